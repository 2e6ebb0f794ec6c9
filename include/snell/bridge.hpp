// The C++ side of the language bridge (see glsl/snell/prelude.glsl).
// Every C++ entry header includes this first, then includes the GLSL bodies inside
// namespace snell, so the C++ function *is* the shader function compiled by a C++
// compiler. GLSL builtins resolve to GLM, texture hooks to snell::Texture2D.
#pragma once

#define GLM_FORCE_CXX17
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#define SNELL_CXX_BRIDGE 1

// The always-inline attribute (GCC, Clang; empty elsewhere): on Texture2D::size
// and fetchInLevel, which every depth read calls (the DDA's loop otherwise calls
// size out of line: 10 % more instructions per ray, benchmarks/kernels), and in
// SNELL_FN_INLINE (glsl/snell/prelude.glsl).
#if defined(__GNUC__) || defined(__clang__)
#  define SNELL_CXX_ALWAYS_INLINE __attribute__((always_inline))
#else
#  define SNELL_CXX_ALWAYS_INLINE
#endif

namespace snell {

using namespace glm;  // GLSL names (vec3, dot, mix, ...) for the shared bodies

// One mip level of RGBA float texels, row-major from the bottom row (GL's
// glTexImage2D / glReadPixels order: texel (x, y) is at y * width + x).
struct Image {
  int width = 0;
  int height = 0;
  std::vector<vec4> texels;

  Image() = default;
  Image(int w, int h, vec4 fill = vec4(0.0f)) : width(w), height(h) {
    if (w <= 0 || h <= 0) throw std::invalid_argument("snell::Image: size must be positive");
    texels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill);
  }
  vec4& at(int x, int y) { return texels[index(x, y)]; }
  const vec4& at(int x, int y) const { return texels[index(x, y)]; }

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }
};

enum class Filter { Nearest, Linear };        // GL_NEAREST / GL_LINEAR within a level
enum class MipFilter { None, Nearest, Linear };  // no mips / *_MIPMAP_NEAREST / *_MIPMAP_LINEAR

// A texture as GL samples it: clamp-to-edge addressing, texel centres at
// (i + 0.5) / size, nearest or bilinear within a level, explicit-LOD level
// selection as in the OpenGL 4.5 core spec, sec. 8.14.
class Texture2D {
 public:
  Filter magFilter = Filter::Nearest;
  Filter minFilter = Filter::Nearest;
  MipFilter mipFilter = MipFilter::None;

  Texture2D() = default;
  explicit Texture2D(Image base, Filter filter = Filter::Nearest, MipFilter mip = MipFilter::None)
      : magFilter(filter), minFilter(filter), mipFilter(mip) {
    levels_.push_back(std::move(base));
  }

  // Appends the next mip level; it must be half the previous size (floor, min 1).
  void addLevel(Image level) {
    if (levels_.empty()) throw std::logic_error("snell::Texture2D::addLevel: no base level");
    const Image& prev = levels_.back();
    if (level.width != std::max(1, prev.width / 2) || level.height != std::max(1, prev.height / 2))
      throw std::invalid_argument("snell::Texture2D::addLevel: level size must halve the previous one");
    levels_.push_back(std::move(level));
  }
  // Box-filters level 0 down to 1x1, replacing any existing mip levels (what
  // glGenerateMipmap does for power-of-two sizes).
  void generateMipmaps() {
    if (levels_.empty()) throw std::logic_error("snell::Texture2D::generateMipmaps: no base level");
    levels_.resize(1);
    while (levels_.back().width > 1 || levels_.back().height > 1) {
      const Image& p = levels_.back();
      Image n(std::max(1, p.width / 2), std::max(1, p.height / 2));
      for (int y = 0; y < n.height; ++y)
        for (int x = 0; x < n.width; ++x) {
          vec4 sum(0.0f);
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx)
              sum += p.at(std::min(2 * x + dx, p.width - 1), std::min(2 * y + dy, p.height - 1));
          n.at(x, y) = sum * 0.25f;
        }
      levels_.push_back(std::move(n));
    }
  }

  int levelCount() const { return static_cast<int>(levels_.size()); }
  const Image& level(int lod) const { return levels_.at(static_cast<std::size_t>(lod)); }
  Image& level(int lod) { return levels_.at(static_cast<std::size_t>(lod)); }

  // textureSize: zero for a missing level, as GL does.
  // (The unsigned comparisons test both bounds at once: a negative int is huge.
  // Image's constructor keeps width and height positive; a default Image's
  // zero size makes every texel out of range.)
  SNELL_CXX_ALWAYS_INLINE ivec2 size(int lod) const {
    if (static_cast<unsigned>(lod) >= levels_.size()) return ivec2(0);
    const Image& l = levels_[static_cast<std::size_t>(lod)];
    return ivec2(l.width, l.height);
  }

  // texelFetch. GL leaves out-of-range fetches undefined; here they return 0
  // (what robust-access drivers return), so a bug shows as "invalid", not a crash.
  vec4 fetch(ivec2 px, int lod) const {
    if (static_cast<unsigned>(lod) >= levels_.size()) return vec4(0.0f);
    const Image& l = levels_[static_cast<std::size_t>(lod)];
    if (static_cast<unsigned>(px.x) >= static_cast<unsigned>(l.width) ||
        static_cast<unsigned>(px.y) >= static_cast<unsigned>(l.height))
      return vec4(0.0f);
    return l.at(px.x, px.y);
  }

  // texelFetch of a texel the caller has already placed inside level lod
  // (0 <= lod < levelCount(), 0 <= px < size(lod)): fetch without its tests.
  // SNELL_TEXEL_FETCH_IN_LEVEL (glsl/snell/prelude.glsl).
  SNELL_CXX_ALWAYS_INLINE const vec4& fetchInLevel(ivec2 px, int lod) const {
    return levels_[static_cast<std::size_t>(lod)].at(px.x, px.y);
  }

  // textureLod with this texture's filter state (GL 4.5 sec. 8.14.2-8.14.3).
  vec4 sampleLod(vec2 uv, float lod) const {
    if (levels_.empty()) return vec4(0.0f);
    const int q = levelCount() - 1;
    // c: the magnification/minification switch-over point (sec. 8.14.2). Mesa
    // 22.3 llvmpipe uses c = 0 for every filter pair; this follows the spec.
    const bool cHalf = magFilter == Filter::Linear && minFilter == Filter::Nearest &&
                       mipFilter != MipFilter::None;
    const float c = cHalf ? 0.5f : 0.0f;
    if (!(lod > c)) return filterLevel(0, uv, magFilter);  // also catches NaN lod
    switch (mipFilter) {
      case MipFilter::None:
        return filterLevel(0, uv, minFilter);
      case MipFilter::Nearest: {
        // The spec's ceil(lod + 0.5) - 1 takes the lower level at exact
        // half-integer lods; llvmpipe rounds those up.
        // lod >= q + 0.5 (also +inf, 1e30) selects level q: decided before the
        // cast, which is undefined behaviour for values beyond int's range.
        int d = lod <= 0.5f ? 0
                : lod >= static_cast<float>(q) + 0.5f ? q
                                                       : static_cast<int>(std::ceil(lod + 0.5f)) - 1;
        return filterLevel(std::min(d, q), uv, minFilter);
      }
      case MipFilter::Linear:
      default: {
        const float l = std::min(lod, static_cast<float>(q));
        const int d1 = std::min(static_cast<int>(std::floor(l)), q);
        const int d2 = std::min(d1 + 1, q);
        const float f = l - std::floor(l);
        const vec4 a = filterLevel(d1, uv, minFilter);
        if (d2 == d1 || f == 0.0f) return a;
        return a * (1.0f - f) + filterLevel(d2, uv, minFilter) * f;
      }
    }
  }

 private:
  std::vector<Image> levels_;

  static int clampi(int v, int hi) { return std::max(0, std::min(v, hi)); }
  // std::floor, exactly (the sign of zero included), without the library call
  // that x86-64 needs before SSE4.1 (309 of a plane ray's 2,316
  // instructions): for |v| < 2^31 the integer part converts exactly.
  static float floorExact(float v) {
#if defined(__SSE4_1__)
    return std::floor(v);  // one roundss
#else
    if (!(std::fabs(v) < 2147483648.0f)) return std::floor(v);  // NaN, +-inf, huge
    const float t = static_cast<float>(static_cast<int>(v));
    return t > v ? t - 1.0f : (v == 0.0f ? v : t);
#endif
  }
  // Float to int without UB for NaN/huge values (clamp-to-edge makes them
  // edges); `floored` is floorExact(v).
  static int toIndex(float v, float floored) {
    if (!(v > -1e9f)) return -1000000000;
    if (v > 1e9f) return 1000000000;
    return static_cast<int>(floored);
  }

  vec4 filterLevel(int lod, vec2 uv, Filter f) const {
    const Image& l = levels_[static_cast<std::size_t>(lod)];
    const float u = uv.x * static_cast<float>(l.width);
    const float v = uv.y * static_cast<float>(l.height);
    if (f == Filter::Nearest)
      return l.at(clampi(toIndex(u, floorExact(u)), l.width - 1), clampi(toIndex(v, floorExact(v)), l.height - 1));
    // One floor per axis serves both the texel index and the weight.
    const float us = u - 0.5f, vs = v - 0.5f;
    const float fu = floorExact(us), fv = floorExact(vs);
    const int i0 = toIndex(us, fu), j0 = toIndex(vs, fv);
    const float a = std::isfinite(us) ? us - fu : 0.0f;
    const float b = std::isfinite(vs) ? vs - fv : 0.0f;
    const int x0 = clampi(i0, l.width - 1), x1 = clampi(i0 + 1, l.width - 1);
    const int y0 = clampi(j0, l.height - 1), y1 = clampi(j0 + 1, l.height - 1);
    return (1.0f - a) * (1.0f - b) * l.at(x0, y0) + a * (1.0f - b) * l.at(x1, y0) +
           (1.0f - a) * b * l.at(x0, y1) + a * b * l.at(x1, y1);
  }
};

}  // namespace snell

#define SNELL_TEX2D const ::snell::Texture2D&
#define SNELL_TEXEL_FETCH(tex, px, lod) ((tex).fetch(px, lod))
#define SNELL_TEXEL_FETCH_IN_LEVEL(tex, px, lod) ((tex).fetchInLevel(px, lod))
#define SNELL_SAMPLE_LOD(tex, uv, lod) ((tex).sampleLod(uv, lod))
#define SNELL_TEXTURE_SIZE(tex, lod) ((tex).size(lod))
