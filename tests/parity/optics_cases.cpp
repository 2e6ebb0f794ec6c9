// Registrations of the optics/ parity cases (see parity_registry.hpp).
#include <snell/optics.hpp>

#include "parity_registry.hpp"

namespace parity_optics {
using namespace snell;
using snell::gpu::SnellParityOut;
#include "cases/optics.glsl"
}  // namespace parity_optics

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;

ParityIO run(SnellParityOut (*entry)(glm::vec4, glm::vec4, glm::vec4, glm::vec4), const ParityIO& in) {
  return snell::gpu::toParityIO(entry(in.v[0], in.v[1], in.v[2], in.v[3]));
}

std::vector<ParityIO> safeNormalizeInputs() {
  InputGen g(11);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    glm::vec3 x = g.unitVector() * std::exp(g.uniform(-40.0f, 40.0f));
    if (g.chance(0.1f)) x = g.hostileVector();
    in.v[0] = glm::vec4(x, 0.0f);
    v.push_back(in);
  }
  return v;
}

// Edge cases: grazing angles, TIR on both sides of the critical angle, eta = 1,
// normals facing away, unnormalized and hostile vectors, all three policies.
std::vector<ParityIO> refractInputs() {
  InputGen g(12);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    glm::vec3 n = g.unitVector();
    glm::vec3 d = g.unitVector();
    if (g.chance(0.2f)) d = glm::normalize(d - n * glm::dot(d, n) + n * g.uniform(-1e-3f, 1e-3f));  // grazing
    float eta = g.chance(0.5f) ? 1.0f / g.uniform(1.0f, 2.5f) : g.uniform(1.0f, 2.5f);
    if (g.chance(0.05f)) eta = 1.0f;
    if (g.chance(0.1f)) d *= g.uniform(0.01f, 100.0f);
    if (g.chance(0.03f)) d = g.hostileVector();
    if (g.chance(0.03f)) n = g.hostileVector();
    if (g.chance(0.03f)) eta = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(d, eta);
    in.v[1] = glm::vec4(n, static_cast<float>(g.integer(0, 2)));
    v.push_back(in);
  }
  return v;
}
}  // namespace

SNELL_PARITY_CASE({"snellSafeNormalize", "optics.glsl", "caseSnellSafeNormalize", safeNormalizeInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellSafeNormalize, in); }, 0, 3,
                   {1e-6f, 1e-6f}});
SNELL_PARITY_CASE({"snellRefract", "optics.glsl", "caseSnellRefract", refractInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellRefract, in); }, 0x30, 6,
                   {1e-5f, 1e-5f}});
