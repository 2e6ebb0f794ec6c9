// Parity of the texture hooks (SNELL_SAMPLE_LOD, SNELL_TEXEL_FETCH,
// SNELL_TEXTURE_SIZE): GL's sampler against snell::Texture2D.
#include <snell/bridge.hpp>

#include "parity_case.hpp"

namespace parity_hooks {
using namespace snell;
Texture2D parityTexNearest, parityTexLinear, parityTexTrilinear, parityTexMipNearest, parityTexMagLinear;
#include "cases/hooks.glsl"
}  // namespace parity_hooks

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;
using namespace parity_hooks;

// A non-power-of-two texture with random texels and explicitly built levels
// (37x29 down to 1x1), so no driver-specific mip generation is involved.
void buildTextures() {
  InputGen g(5);
  auto level = [&](int w, int h) {
    snell::Image img(w, h);
    for (glm::vec4& t : img.texels) t = glm::vec4(g.uniform(-2, 2), g.uniform(0, 1), g.uniform(0, 100), g.uniform(-1, 1));
    return img;
  };
  snell::Texture2D base(level(37, 29));
  for (int w = 37, h = 29; w > 1 || h > 1;) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    base.addLevel(level(w, h));
  }
  auto with = [&](snell::Filter mag, snell::Filter min, snell::MipFilter mip) {
    snell::Texture2D t = base;
    t.magFilter = mag;
    t.minFilter = min;
    t.mipFilter = mip;
    return t;
  };
  using F = snell::Filter;
  using M = snell::MipFilter;
  parityTexNearest = with(F::Nearest, F::Nearest, M::None);
  parityTexLinear = with(F::Linear, F::Linear, M::None);
  parityTexTrilinear = with(F::Linear, F::Linear, M::Linear);
  parityTexMipNearest = with(F::Nearest, F::Nearest, M::Nearest);
  parityTexMagLinear = with(F::Linear, F::Nearest, M::Nearest);
}

// uv over [-0.25, 1.25] (clamp-to-edge), texel centres and edges exactly, lods
// beyond both ends of the chain, texel fetches over every level.
std::vector<ParityIO> hookInputs() {
  InputGen g(6);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    float u = g.uniform(-0.25f, 1.25f), w = g.uniform(-0.25f, 1.25f);
    if (g.chance(0.2f)) {  // exactly on a texel centre or edge of level 0
      u = (static_cast<float>(g.integer(0, 37)) + (g.chance(0.5f) ? 0.5f : 0.0f)) / 37.0f;
      w = (static_cast<float>(g.integer(0, 29)) + (g.chance(0.5f) ? 0.5f : 0.0f)) / 29.0f;
    }
    float lod = g.uniform(-1.0f, 7.0f);
    // Integer lods: trilinear level boundaries. Exact half-integers are left out:
    // there *_MIPMAP_NEAREST ties, which the spec breaks down, llvmpipe up.
    if (g.chance(0.2f)) lod = static_cast<float>(g.integer(-1, 7));
    const int level = g.integer(0, 5);
    const glm::ivec2 size = parityTexMipNearest.size(level);
    in.v[0] = glm::vec4(u, w, lod, 0.0f);
    in.v[1] = glm::vec4(static_cast<float>(g.integer(0, size.x - 1)), static_cast<float>(g.integer(0, size.y - 1)),
                        static_cast<float>(level), 0.0f);
    v.push_back(in);
  }
  return v;
}

// As hookInputs, with lod moved out of (0, 0.5] and uv off texel edges: there llvmpipe ignores the
// spec's c = 0.5 switch-over for this filter pair (snell::Texture2D follows the spec).
std::vector<ParityIO> magLinearInputs() {
  std::vector<ParityIO> v = hookInputs();
  for (ParityIO& in : v) {
    if (in.v[0].z > 0.0f && in.v[0].z <= 0.5f) in.v[0].z += 0.5f;
    // Off exact texel edges of the coarser levels (u = 0.5 is one at level 1):
    // nearest filtering there depends on the GPU's sub-texel precision.
    in.v[0].x += 1e-4f;
    in.v[0].y += 1e-4f;
  }
  return v;
}

std::vector<snell::gpu::ParityTexture> allTextures() {
  return {{"parityTexNearest", &parityTexNearest},
          {"parityTexLinear", &parityTexLinear},
          {"parityTexTrilinear", &parityTexTrilinear},
          {"parityTexMipNearest", &parityTexMipNearest},
          {"parityTexMagLinear", &parityTexMagLinear}};
}
}  // namespace

namespace parity_hooks {
#define SNELL_PARITY_FILE "hooks.glsl"
using snell_parity::CaseExtras;

// Nearest reads and fetches select texels: exact. Filtered reads: llvmpipe
// computes bilinear weights in reduced fixed-point precision, hence the tolerance.
SNELL_PARITY_CASE(SNELL_TEXEL_FETCH_and_SIZE, hookInputs,
                  (vec2, uv, 0)(float, lod, 2)(ivec2, texel, 4)(int, level, 6),
                  (vec4, nearest, 0, exact)(vec4, fetched, 4, exact)(ivec2, size, 8, exact),
                  CaseExtras().sampling(allTextures(), buildTextures),
                  nearest = SNELL_SAMPLE_LOD(parityTexNearest, uv, lod);
                  fetched = SNELL_TEXEL_FETCH(parityTexMipNearest, texel, level);
                  size = SNELL_TEXTURE_SIZE(parityTexMipNearest, level);)

SNELL_PARITY_CASE(SNELL_SAMPLE_LOD, hookInputs,
                  (vec2, uv, 0)(float, lod, 2),
                  (vec4, bilinear, 0, within(1e-4f, 1e-4f)),
                  CaseExtras().sampling(allTextures(), buildTextures),
                  bilinear = SNELL_SAMPLE_LOD(parityTexLinear, uv, lod);)

SNELL_PARITY_CASE(SNELL_SAMPLE_LOD_mipmaps, hookInputs,
                  (vec2, uv, 0)(float, lod, 2),
                  (vec4, trilinear, 0, within(1e-4f, 1e-4f))(vec4, mipNearest, 4, exact),
                  CaseExtras().sampling(allTextures(), buildTextures),
                  trilinear = SNELL_SAMPLE_LOD(parityTexTrilinear, uv, lod);
                  mipNearest = SNELL_SAMPLE_LOD(parityTexMipNearest, uv, lod);)

// mag LINEAR with min NEAREST_MIPMAP_*: the spec switches to minification at
// lod c = 0.5, llvmpipe at 0; the inputs avoid lod in (0, 0.5] (see bridge.hpp).
SNELL_PARITY_CASE(SNELL_SAMPLE_LOD_mag_linear, magLinearInputs,
                  (vec2, uv, 0)(float, lod, 2),
                  (vec4, filtered, 0, within(1e-4f, 1e-4f)),
                  CaseExtras().sampling(allTextures(), buildTextures),
                  filtered = SNELL_SAMPLE_LOD(parityTexMagLinear, uv, lod);)
}  // namespace parity_hooks
