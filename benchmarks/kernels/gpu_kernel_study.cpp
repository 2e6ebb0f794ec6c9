// The kernel study on the GPU path (the shaders measured as llvmpipe time
// and instruction ratios): snell's GLSL single sample, normal plane (1 it.),
// CBS-5 and linear march (32 steps, 4 refinements) against the hand-written
// GLSL kernels of gpu_kernels.glsl, on
// the kernel study's rays and buffers (kernel_scene.hpp), one ray per pixel of
// a 512x512 pass (the 20000 rays repeated), on Mesa (OSMesa or EGL); and the
// whole two-interface technique (normal plane, 2 it.) against its kernel, one
// front-face fragment of the same sphere per pixel, with an opaque tilted
// plane behind it as the scene and an equirectangular environment (ShadeScene).
// Prints how many rays each kernel answers with snell's bits, the median pass
// time of every variant (all interleaved in one run, glFinish + steady clock)
// and the ratios. Built and run by gpu_kernel_table.sh; under callgrind the
// per-variant functions drawVariant<V> give instruction counts of the JIT code.
#include <snell/gpu/context.hpp>
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>

#include <snell/optics.hpp>

#include "kernel_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace snell::gpu;

constexpr int kSize = 512;
constexpr int kVariants = 14;
const char* const kNames[kVariants] = {"snell single sample",
                                       "snell normal plane 1 it.",
                                       "snell normal plane 1 it. + far start",
                                       "kernel single sample",
                                       "kernel normal plane 1 it.",
                                       "snell single sample, SNELL_PERSPECTIVE_ONLY",
                                       "snell normal plane 1 it., SNELL_PERSPECTIVE_ONLY",
                                       "snell CBS-5",
                                       "kernel CBS-5",
                                       "snell linear march 32x4",
                                       "kernel linear march 32x4",
                                       "snell single sample, the surface a uniform",
                                       "snell two-interface technique, normal plane 2 it.",
                                       "kernel two-interface technique, normal plane 2 it."};

// The kernel each variant is measured against (-1: a kernel itself), and the
// single sample its ratio is taken to (the same build).
const int kTwin[kVariants] = {3, 4, 4, -1, -1, 3, 4, 8, -1, 10, -1, 3, 13, -1};
const int kSingle[kVariants] = {0, 0, 0, 3, 3, 5, 5, 0, 3, 0, 3, 0, 0, 3};

// The whole technique's inputs: the front-face fragments of the kernel scene's
// sphere (one per texel its front hemisphere covers, view-space position and
// outward normal), the opaque scene behind it (a plane leaning away, GL depth
// cleared to 1, its normals, a checker colour) and the environment.
struct ShadeScene {
  std::vector<kscene::Ray> front;  // o = position, d = normal
  snell::Texture2D depth, normal, color, environment;
};

ShadeScene buildShadeScene(const glm::mat4& P) {
  using namespace glm;
  const int W = kscene::kW;
  ShadeScene sh;
  snell::Image depth(W, W, vec4(1.0f)), normal(W, W, vec4(0.0f)), color(W, W, vec4(0.0f));
  const vec3 c(0.0f, 0.0f, -5.0f), wallNormal = normalize(vec3(0.25f, 0.15f, 1.0f)), wallPoint(0.0f, 0.0f, -8.0f);
  for (int y = 0; y < W; ++y)
    for (int x = 0; x < W; ++x) {
      const vec2 ndc((x + 0.5f) / W * 2 - 1, (y + 0.5f) / W * 2 - 1);
      const vec3 d = normalize(vec3(ndc.x * tan(radians(22.5f)), ndc.y * tan(radians(22.5f)), -1.0f));
      const float b = dot(d, c), disc = b * b - dot(c, c) + 1.0f;
      if (disc >= 0.0f) {
        const vec3 p = d * (b - std::sqrt(disc));
        sh.front.push_back(kscene::Ray{{p.x, p.y, p.z}, {p.x - c.x, p.y - c.y, p.z - c.z}});
      }
      const vec3 q = d * (dot(wallPoint, wallNormal) / dot(d, wallNormal));
      const vec4 clip = P * vec4(q, 1.0f);
      depth.at(x, y) = vec4(clip.z / clip.w * 0.5f + 0.5f);
      normal.at(x, y) = vec4(wallNormal, 0.0f);
      const bool odd = (static_cast<int>(std::floor(2.0f * q.x)) + static_cast<int>(std::floor(2.0f * q.y))) % 2 != 0;
      color.at(x, y) = odd ? vec4(0.9f, 0.8f, 0.3f, 1.0f) : vec4(0.1f, 0.3f, 0.6f, 1.0f);
    }
  snell::Image env(64, 32, vec4(0.0f));
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x)
      env.at(x, y) = vec4((x + 0.5f) / 64.0f, (y + 0.5f) / 32.0f, 0.5f + 0.5f * std::sin(0.4f * static_cast<float>(x)), 1.0f);
  sh.depth = snell::Texture2D(std::move(depth));
  sh.normal = snell::Texture2D(std::move(normal), snell::Filter::Linear);
  sh.color = snell::Texture2D(std::move(color), snell::Filter::Linear);
  sh.environment = snell::Texture2D(std::move(env), snell::Filter::Linear);
  return sh;
}

// snell's surface as the uniform kSurface (variant 11), built once by the C++
// mirror. A field the variant does not read has no location (-1): GL ignores it.
void setSurface(const GlApi& gl, GLuint id, const snell::SnellDepthSurface& s) {
  auto loc = [&](const char* field) { return gl.GetUniformLocation(id, (std::string("kSurface.") + field).c_str()); };
  gl.ProgramUniformMatrix4fv(id, loc("clipFromView"), 1, GL_FALSE, &s.clipFromView[0][0]);
  gl.ProgramUniform1f(id, loc("zNear"), s.zNear);
  gl.ProgramUniform1f(id, loc("zFar"), s.zFar);
  gl.ProgramUniform1i(id, loc("convention"), s.convention);
  gl.ProgramUniform1f(id, loc("emptyDepth"), s.emptyDepth);
  gl.ProgramUniform1i(id, loc("lod"), s.lod);
  gl.ProgramUniform1i(id, loc("depthFilter"), s.depthFilter);
  gl.ProgramUniform1i(id, loc("closed"), s.closed ? 1 : 0);
  gl.ProgramUniform1i(id, loc("perspective"), s.perspective ? 1 : 0);
  gl.ProgramUniform1f(id, loc("perspectiveDet"), s.perspectiveDet);
  gl.ProgramUniform1i(id, loc("linearizable"), s.linearizable ? 1 : 0);
  gl.ProgramUniform1i(id, loc("depthReversed"), s.depthReversed ? 1 : 0);
  gl.ProgramUniform1f(id, loc("nearOverFar"), s.nearOverFar);
  gl.ProgramUniform1f(id, loc("depthFarBelow"), s.depthFarBelow);
  gl.ProgramUniform1f(id, loc("depthFarLimit"), s.depthFarLimit);
  checkGl(gl, "uniform kSurface");
}

struct Study {
  Context ctx;
  const GlApi& gl;
  kscene::Scene sc;
  ShadeScene sh;  // filled in frontPositions' initializer: it needs sc.P, which depth's initializer builds
  Texture depth, normal, pyramid, origins, dirs, frontPositions, frontNormals, sceneDepth, sceneNormal, sceneColor,
      environment;
  Framebuffer fb;
  VertexArray vao;
  std::vector<Program> programs;

  static snell::Texture2D rayTexture(const std::vector<kscene::Ray>& rays, bool origin) {
    const int w = 200, h = (static_cast<int>(rays.size()) + w - 1) / w;
    snell::Image img(w, h, glm::vec4(0.0f));
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const float* v = origin ? rays[i].o : rays[i].d;
      img.at(static_cast<int>(i) % w, static_cast<int>(i) / w) = glm::vec4(v[0], v[1], v[2], 0.0f);
    }
    return snell::Texture2D(std::move(img));
  }
  static kscene::Scene& built(kscene::Scene& s) {
    kscene::build(s, true, false);
    return s;
  }

  explicit Study(Backend backend)
      : ctx(backend),
        gl((ctx.makeCurrent(), ctx.gl())),
        depth(gl, built(sc).depth),
        normal(gl, sc.normal),
        pyramid(gl, sc.pyramid),
        origins(gl, rayTexture(sc.rays, true)),
        dirs(gl, rayTexture(sc.rays, false)),
        frontPositions(gl, rayTexture((sh = buildShadeScene(sc.P)).front, true)),
        frontNormals(gl, rayTexture(sh.front, false)),
        sceneDepth(gl, sh.depth),
        sceneNormal(gl, sh.normal),
        sceneColor(gl, sh.color),
        environment(gl, sh.environment),
        fb(gl, kSize, kSize, 2, false),
        vao(gl) {
    const std::vector<std::filesystem::path> paths = {SNELL_GLSL_DIR, SNELL_KERNELS_DIR};
    const FlatSource vs = flattenGlslFile(std::filesystem::path(SNELL_GLSL_DIR) / "passes" / "fullscreen.vert", {});
    for (int v = 0; v < kVariants; ++v) {
      const std::string src = "#version 450 core\n#extension GL_GOOGLE_include_directive : require\n#define VARIANT " +
                              std::to_string(v) + "\n#include \"gpu_kernel_pass.glsl\"\n";
      programs.push_back(Program::graphics(gl, vs, flattenGlslSource(src, "gpu_kernel_pass.frag", paths)));
      const GLuint id = programs.back().id();
      const kern::Camera& k = sc.cam;
      auto loc = [&](const char* name) { return gl.GetUniformLocation(id, name); };
      const glm::vec4 cam(k.a, k.b, k.det, k.zNear);
      gl.ProgramUniform4fv(id, loc("kCam"), 1, &cam[0]);
      gl.ProgramUniform1f(id, loc("kNearOverFar"), k.nearOverFar);
      gl.ProgramUniformMatrix4fv(id, loc("kClipFromView"), 1, GL_FALSE, &sc.P[0][0]);
      const glm::vec2 range(sc.surface.zNear, sc.surface.zFar);
      gl.ProgramUniform2fv(id, loc("kClipRange"), 1, &range[0]);
      setSurface(gl, id, sc.surface);
      gl.ProgramUniform1i(id, loc("kRayCount"), static_cast<int>(sc.rays.size()));
      gl.ProgramUniform1f(id, loc("kEta"), snell::snellIorToEta(1.0f, 1.5f));
      gl.ProgramUniform1i(id, loc("kFrontCount"), static_cast<int>(sh.front.size()));
      gl.ProgramUniform1i(id, loc("kPyramidTop"), sc.pyramid.levelCount() - 1);
      const glm::vec3 absorption(0.15f, 0.05f, 0.1f);
      gl.ProgramUniform3fv(id, loc("kAbsorption"), 1, &absorption[0]);
      checkGl(gl, "uniforms of variant " + std::to_string(v));
    }
    depth.bind(0);
    normal.bind(1);
    pyramid.bind(2);
    origins.bind(3);
    dirs.bind(4);
    frontPositions.bind(5);
    frontNormals.bind(6);
    sceneDepth.bind(7);
    sceneNormal.bind(8);
    sceneColor.bind(9);
    environment.bind(10);
  }

  void draw(int v) {
    fb.bind();
    gl.Viewport(0, 0, kSize, kSize);
    vao.bind();
    programs[static_cast<std::size_t>(v)].use();
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.Finish();
  }
};

// One function per variant, so callgrind can attribute a pass's instructions.
template <int V>
__attribute__((noinline)) double drawVariant(Study& s) {
  const auto t0 = std::chrono::steady_clock::now();
  s.draw(V);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double drawTimed(Study& s, int v) {
  switch (v) {
    case 0: return drawVariant<0>(s);
    case 1: return drawVariant<1>(s);
    case 2: return drawVariant<2>(s);
    case 3: return drawVariant<3>(s);
    case 4: return drawVariant<4>(s);
    case 5: return drawVariant<5>(s);
    case 6: return drawVariant<6>(s);
    case 7: return drawVariant<7>(s);
    case 8: return drawVariant<8>(s);
    case 9: return drawVariant<9>(s);
    case 10: return drawVariant<10>(s);
    case 11: return drawVariant<11>(s);
    case 12: return drawVariant<12>(s);
    default: return drawVariant<13>(s);
  }
}

struct Readback {
  snell::Image position, hit;
};

// How many of the first `rays` pixels (one per ray or fragment) hold the same bits in both.
int identical(const Readback& a, const Readback& b, int rays, float& maxPositionDiff) {
  int same = 0;
  maxPositionDiff = 0.0f;
  for (int i = 0; i < rays; ++i) {
    const int x = i % kSize, y = i / kSize;
    const glm::vec4 pa = a.position.at(x, y), pb = b.position.at(x, y), ha = a.hit.at(x, y), hb = b.hit.at(x, y);
    if (std::memcmp(&pa, &pb, sizeof pa) == 0 && std::memcmp(&ha, &hb, sizeof ha) == 0) ++same;
    for (int c = 0; c < 3; ++c) maxPositionDiff = std::max(maxPositionDiff, std::abs(pa[c] - pb[c]));
  }
  return same;
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
  const std::string backendName = argc > 2 ? argv[2] : "auto";
  try {
    Study s(parseBackend(backendName));
    std::printf("%s, %s, OpenGL %s; %dx%d pass, %zu rays repeated\n", backendName.c_str(), s.ctx.renderer().c_str(),
                s.ctx.version().c_str(), kSize, kSize, s.sc.rays.size());
    std::vector<Readback> out;
    for (int v = 0; v < kVariants; ++v) {  // also JIT-compiles each program: not timed
      s.draw(v);
      out.push_back({s.fb.readColor(0), s.fb.readColor(1)});
    }
    // gpu_kernel_table.sh reads these lines for its instruction table.
    for (int v = 0; v < kVariants; ++v)
      std::printf("variant %d single %d twin %d: %s\n", v, kSingle[v], kTwin[v], kNames[v]);
    const int rays = static_cast<int>(s.sc.rays.size()), fragments = static_cast<int>(s.sh.front.size());
    bool allSame = true;
    for (const auto& [kernel, snellV] :
         {std::pair<int, int>{3, 0}, {4, 1}, {3, 5}, {4, 6}, {8, 7}, {10, 9}, {3, 11}, {13, 12}}) {
      float diff = 0.0f;
      const int n = kernel == 13 ? fragments : rays;
      const int same = identical(out[static_cast<std::size_t>(kernel)], out[static_cast<std::size_t>(snellV)], n, diff);
      std::printf("%s vs %s: %d/%d %s with identical bits (%s); max |%s diff| %.3g\n", kNames[kernel],
                  kNames[snellV], same, n, kernel == 13 ? "fragments" : "rays",
                  kernel == 13 ? "colour, path length, Fresnel, fetches, back hit, fallback"
                               : "position, uv, valid, fetches",
                  kernel == 13 ? "colour" : "position", static_cast<double>(diff));
      allSame = allSame && same == n;
    }
    // Like kernel_table.sh: a kernel that does not give snell's bits measures something else.
    if (!allSame) {
      std::fprintf(stderr, "gpu_kernel_study: a kernel does not reproduce snell's output bits\n");
      return 1;
    }
    if (std::getenv("GPU_KERNEL_NO_TIMING")) return 0;
    std::vector<std::vector<double>> ms(kVariants);
    for (int r = 0; r < rounds; ++r)
      for (int v = 0; v < kVariants; ++v) ms[static_cast<std::size_t>(v)].push_back(drawTimed(s, v));
    std::vector<double> median(kVariants);
    for (int v = 0; v < kVariants; ++v) {
      auto& t = ms[static_cast<std::size_t>(v)];
      std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
      median[static_cast<std::size_t>(v)] = t[t.size() / 2];
    }
    std::printf("| variant | median pass (ms) | over its single sample | over the kernel |\n|---|---:|---:|---:|\n");
    for (int v = 0; v < kVariants; ++v) {
      const double single = median[static_cast<std::size_t>(kSingle[v])];
      const int twin = kTwin[v];
      std::printf("| %s | %.2f | %.2fx | %s |\n", kNames[v], median[static_cast<std::size_t>(v)],
                  median[static_cast<std::size_t>(v)] / single,
                  twin < 0 ? "" : (std::to_string(median[static_cast<std::size_t>(v)] / median[static_cast<std::size_t>(twin)]).substr(0, 4) + "x").c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gpu_kernel_study: %s\n", e.what());
    return 1;
  }
  return 0;
}
