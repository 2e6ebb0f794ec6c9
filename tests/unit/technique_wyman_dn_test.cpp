// include/snell/wyman_dn.hpp: d_N per vertex of a UV sphere equals the chord
// along -N (the diameter, 2R) within tessellation error; open meshes miss.
#include <gtest/gtest.h>

#include <snell/wyman_dn.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <vector>

namespace {

struct Mesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;
};

// A UV sphere (rings x segments), normals = exact radial directions.
Mesh uvSphere(glm::vec3 c, float r, int rings, int segments) {
  Mesh m;
  for (int i = 0; i <= rings; ++i) {
    const double th = M_PI * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double ph = 2.0 * M_PI * j / segments;
      const glm::vec3 n(float(std::sin(th) * std::cos(ph)), float(std::cos(th)), float(std::sin(th) * std::sin(ph)));
      m.positions.push_back(c + r * n);
      m.normals.push_back(n);
    }
  }
  auto id = [&](int i, int j) { return std::uint32_t(i * segments + (j % segments)); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      m.indices.insert(m.indices.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.indices.insert(m.indices.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

TEST(TechniqueWymanDn, SphereChordIsTheDiameter) {
  const float r = 1.7f;
  const Mesh m = uvSphere(glm::vec3(0.3f, -0.2f, 2.0f), r, 48, 96);
  const std::vector<float> dn = snell::computeWymanDn(m.positions, m.normals, m.indices);
  ASSERT_EQ(dn.size(), m.positions.size());
  // Tessellation: a flat triangle lies inside the sphere by at most r (1 - cos(half angle)).
  const double sag = double(r) * (1.0 - std::cos(M_PI / 48.0));
  double maxErr = 0.0;
  for (size_t v = 0; v < dn.size(); ++v) {
    const double e = std::fabs(double(dn[v]) - 2.0 * double(r));
    maxErr = std::max(maxErr, e);
  }
  std::printf("[wyman_dn] %zu vertices, max |dN - 2R| = %.5f (sagitta bound %.5f)\n", dn.size(), maxErr, 2.0 * sag);
  EXPECT_LT(maxErr, 2.0 * sag + 1e-4);
}

TEST(TechniqueWymanDn, BruteForceAgreesOnACoarseSphereAndOpenMeshesMiss) {
  const Mesh m = uvSphere(glm::vec3(0.0f), 1.0f, 6, 9);
  const std::vector<float> dn = snell::computeWymanDn(m.positions, m.normals, m.indices);
  for (float d : dn) {
    EXPECT_GT(d, 1.6f);
    EXPECT_LE(d, 2.0f + 1e-5f);
  }
  // A single triangle: nothing behind any vertex.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, n(3, glm::vec3(0, 0, 1));
  const std::vector<float> open = snell::computeWymanDn(p, n, {0, 1, 2}, -1.0f);
  for (float d : open) EXPECT_EQ(d, -1.0f);
  EXPECT_THROW(snell::computeWymanDn(p, n, {0, 1, 7}), std::invalid_argument);
}

// The BVH's top levels built on several threads make the same tree: every
// d_N bit for bit what one thread gives, and the sphere chord still holds.
TEST(TechniqueWymanDn, ParallelBvhBuildGivesTheSameDn) {
  const Mesh m = uvSphere(glm::vec3(0.1f, 0.4f, -1.0f), 1.3f, 40, 80);
  std::vector<float> one(m.positions.size()), many(m.positions.size());
  const snell::wyman_detail::Baker serial(m.positions, m.normals, m.indices, 1e-7, 1);
  serial.bake(0, one.size(), -1.0f, one.data());
  for (int threads : {2, 3, 8}) {
    const snell::wyman_detail::Baker parallel(m.positions, m.normals, m.indices, 1e-7, threads);
    parallel.bake(0, many.size(), -1.0f, many.data());
    for (std::size_t v = 0; v < one.size(); ++v) {
      ASSERT_EQ(std::memcmp(&one[v], &many[v], sizeof(float)), 0) << threads << " threads, vertex " << v;
      EXPECT_NEAR(many[v], 2.6f, 2.0 * 1.3 * (1.0 - std::cos(M_PI / 40.0)) + 1e-4);
    }
  }
}

}  // namespace
