// G. Oliveira's refractive texture mapping (2000, Part Two): a flat mesh of
// directional sine waves over a planar map (the pool floor), each vertex's uv
// from the approximate refracted ray (eq. 8) or from Snell's law, interpolated
// by the rasterizer. Both are measured against an independent double-precision
// Snell refraction to the plane, per vertex and per pixel (at the rasterized
// surface point, about the interpolated normal), as a function of the wave
// amplitude; the approximate ray's refraction factor is fitted on the flat mesh.
#include <array>
#include <cmath>
#include <initializer_list>
#include <sstream>

#include "effects.hpp"
#include "lab/figure.hpp"
#include "lab/image_io.hpp"
#include "textures.hpp"

namespace snell::gallery {

namespace {

constexpr float kExtent = 2.0f;  // the mesh spans [-2, 2]^2 at y = 0
constexpr float kDepth = 1.0f;   // the map lies 1 below
constexpr float kEta = 1.0f / 1.333f;
constexpr int kCells = 96;
constexpr int kMapSize = 512;

// The height field: three directional waves (eq. 1 of Part One: sums of sines).
struct Waves {
  float amplitude;
  float time;
  float height(float x, float z, vec3* normal) const {
    const float k[3][2] = {{2.1f, 0.7f}, {-0.9f, 2.6f}, {3.7f, -2.2f}};
    const float w[3] = {1.3f, 1.7f, 2.3f}, a[3] = {1.0f, 0.6f, 0.3f};
    float h = 0.0f, dx = 0.0f, dz = 0.0f;
    for (int i = 0; i < 3; ++i) {
      const float ph = k[i][0] * x + k[i][1] * z + w[i] * time;
      h += amplitude * a[i] * std::sin(ph);
      dx += amplitude * a[i] * k[i][0] * std::cos(ph);
      dz += amplitude * a[i] * k[i][1] * std::cos(ph);
    }
    if (normal) *normal = glm::normalize(vec3(-dx, 1.0f, -dz));
    return h;
  }
};

// Vertices as (position, normal) pairs, each height computed once, and the triangles' corners copied from them.
void mesh(const Waves& waves, std::vector<vec4>& vertices, std::vector<vec4>& triangles) {
  vertices.clear();
  triangles.clear();
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      const float x = -kExtent + 2.0f * kExtent * float(i) / float(kCells);
      const float z = -kExtent + 2.0f * kExtent * float(j) / float(kCells);
      vec3 n;
      const float y = waves.height(x, z, &n);
      vertices.push_back(vec4(x, y, z, 1.0f));
      vertices.push_back(vec4(n, 0.0f));
    }
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i)
      for (const std::pair<int, int>& c : std::initializer_list<std::pair<int, int>>{
               {i, j}, {i, j + 1}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i + 1, j}}) {
        const std::size_t v = 2 * (std::size_t(c.second) * std::size_t(kCells + 1) + std::size_t(c.first));
        triangles.push_back(vertices[v]);
        triangles.push_back(vertices[v + 1]);
      }
}

SnellRefractiveTextureMapParams params(float factor) {
  // x maps to u; z to v with the far edge (z = -2) at v = 1, so the map is upright in the view.
  return snellRefractiveTextureMapParams(vec2(-kExtent, kExtent), vec2(kExtent, -kExtent), 0.0f, kDepth, factor);
}

// Snell's law to the plane in double precision (not the library's function): the uv of the hit.
glm::dvec2 exactUv(glm::dvec3 vertex, glm::dvec3 normal, glm::dvec3 eye) {
  const glm::dvec3 i = glm::normalize(vertex - eye);
  glm::dvec3 n = glm::normalize(normal);
  if (glm::dot(i, n) > 0.0) n = -n;
  const double eta = 1.0 / 1.333, c = -glm::dot(i, n);
  const double k = 1.0 - eta * eta * (1.0 - c * c);
  const glm::dvec3 t = eta * i + (eta * c - std::sqrt(k)) * n;
  const double s = (-double(kDepth) - vertex.y) / t.y;
  const glm::dvec3 p = vertex + s * t;
  const double e = kExtent, u = (p.x + e) / (2.0 * e), v = (e - p.z) / (2.0 * e);
  return glm::clamp(glm::dvec2(u, v), 0.0, 1.0);
}

// A uv error in texels of the map, mean and max (per vertex or per pixel).
struct UvError {
  double mean = 0.0, max = 0.0;
};
// The approximate ray's uv error per vertex of `v` (mesh()'s vertices).
UvError approxError(const std::vector<vec4>& v, vec3 eye, float factor) {
  UvError e;
  const SnellRefractiveTextureMapParams p = params(factor);
  for (std::size_t k = 0; k < v.size(); k += 2) {
    const vec2 a = galleryRtmUv(vec3(v[k]), vec3(v[k + 1]), eye, false, kEta, p);
    const double d =
        glm::length(glm::dvec2(a) - exactUv(glm::dvec3(vec3(v[k])), glm::dvec3(vec3(v[k + 1])), glm::dvec3(eye))) *
        kMapSize;
    e.mean += d;
    e.max = std::max(e.max, d);
  }
  e.mean /= double(v.size() / 2);
  return e;
}

// ---- The stages of one refractive texture mapping run, in order (runRtm below). ----

constexpr float kAmplitude = 0.06f;  // the waves in the pictures, the animation and the timed passes

// The approximate ray's one free parameter, the refraction factor, fitted once so that it best matches
// Snell's law on the flat mesh seen from `eye` (golden-section search on the mean per-vertex error).
float fitRefractionFactor(vec3 eye) {
  std::vector<vec4> flat, flatTriangles;
  mesh({0.0f, 0.0f}, flat, flatTriangles);
  float lo = 0.0f, hi = 3.0f;
  for (int it = 0; it < 40; ++it) {
    const float a = hi - (hi - lo) * 0.618034f, b = lo + (hi - lo) * 0.618034f;
    if (approxError(flat, eye, a).mean < approxError(flat, eye, b).mean)
      hi = b;
    else
      lo = a;
  }
  return 0.5f * (lo + hi);
}

// The wave mesh on the GL side: the floor map (the C++ side samples the same one), the drawing program
// with the eye and the map's plane set once, its render target (colour, uv, world position, normal), the
// plain pass's target, and the mesh's triangles (re-uploaded per amplitude and time) with the buffer the
// vertex shader stores its uvs in.
struct RtmGpu {
  const Gl& g;
  const gpu::GlApi& gl;
  const vec3 eye;
  const SnellRefractiveTextureMapParams rp;
  const Texture2D floorTex;
  const gpu::Texture floorGl;
  const gpu::Program draw;
  const gpu::Framebuffer fb, plainFb;
  std::vector<vec4> vertices, triangles;
  gpu::StorageBuffer tbuf, uvbuf;  // the triangles' corners, the drawn vertices' uvs

  RtmGpu(const Gl& gallery, const Options& o, const lab::Camera& cam, const SnellRefractiveTextureMapParams& mapParams)
      : g(gallery),
        gl(gallery.gl()),
        eye(cam.position),
        rp(mapParams),
        floorTex(texture(floorImage(kMapSize), Filter::Linear)),
        floorGl(gl, floorTex),
        draw(g.program("gallery_rtm.vert", "gallery_rtm.frag")),
        fb(gl, o.width, o.height, 4, true),
        plainFb(gl, o.width, o.height, 1, false),
        tbuf(gl),
        uvbuf(gl) {
    draw.set("eye", eye);
    draw.set("eta", kEta);
    draw.set("extent", vec4(rp.extentMin, rp.extentMax));
    draw.set("planeParams", vec3(rp.restY, rp.depth, rp.refractionFactor));
    draw.set("clipFromWorld", clipFromWorld(cam));
  }

  // The mesh of waves of amplitude `amp` at `time`, its triangles uploaded for drawing.
  void upload(float amp, float time) {
    mesh({amp, time}, vertices, triangles);
    tbuf.upload(triangles);
  }

  // The mesh drawn into fb with the approximate ray or Snell's law per vertex; with `storeUvs`, the
  // vertex shader also stores each drawn vertex's uv in uvbuf.
  void drawPass(bool exact, bool storeUvs = false) {
    for (int a = 0; a < 4; ++a) fb.clearColor(a, vec4(0.0f));
    fb.clearDepth(1.0f);
    fb.bind();
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.Disable(GL_CULL_FACE);
    draw.set("exact", exact ? 1 : 0);
    draw.set("storeUvs", storeUvs ? 1 : 0);
    g.bindTextures({floorGl.id()});
    tbuf.bindBase(0);
    if (uvbuf.size() < triangles.size() / 2 * sizeof(vec4)) uvbuf.allocate(triangles.size() / 2 * sizeof(vec4));
    uvbuf.bindBase(1);
    draw.use();
    g.drawArrays(GLsizei(triangles.size() / 2));
  }

  // The cost yardstick: the floor map read once per pixel.
  void plainPass() const { g.plainPass(plainFb, floorGl.id()); }
};

// The cost columns: the plain pass and the mesh drawn with each variant, interleaved.
std::vector<double> timeRtm(RtmGpu& w, int repeats) {
  return w.g.timeInterleaved({[&] { w.plainPass(); }, [&] { w.drawPass(false); }, [&] { w.drawPass(true); }},
                             repeats);
}

// Per vertex, each variant: the uvs the drawing vertex shader computed (it stores them by gl_VertexID)
// against C++, the largest difference in texels of the map.
std::array<double, 2> compareVertexUvs(RtmGpu& w) {
  const std::size_t corners = w.triangles.size() / 2;
  std::array<double, 2> vertexMax = {0.0, 0.0};
  for (bool exact : {false, true}) {
    w.uvbuf.allocate(corners * sizeof(vec4));
    w.drawPass(exact, true);
    w.gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<vec4> gpuUv = w.uvbuf.downloadVec4();
    for (std::size_t k = 0; k < corners; ++k) {
      const vec2 c = galleryRtmUv(vec3(w.triangles[2 * k]), vec3(w.triangles[2 * k + 1]), w.eye, exact, kEta, w.rp);
      vertexMax[exact] = std::max(vertexMax[exact], double(glm::length(c - vec2(gpuUv[k]))) * kMapSize);
    }
  }
  return vertexMax;
}

// One variant's row: the drawn frame against C++ sampling the map at the rasterized uvs; its render and
// its uv image go to `renders` and `uvs` for the picture.
Row measureVariant(RtmGpu& w, bool exact, float factor, const std::vector<double>& ms,
                   const std::array<double, 2>& vertexMax, std::vector<Image>& renders, std::vector<Image>& uvs) {
  w.drawPass(exact);
  const Image gpuImage = w.fb.readColor(0), uvImage = w.fb.readColor(1);
  Image cpuImage(gpuImage.width, gpuImage.height);
  std::vector<bool> on(gpuImage.texels.size());
  for (std::size_t i = 0; i < on.size(); ++i) {
    on[i] = uvImage.texels[i].w != 0.0f;
    if (on[i]) cpuImage.texels[i] = vec4(vec3(w.floorTex.sampleLod(vec2(uvImage.texels[i]), 0.0f)), 1.0f);
  }
  const gpu::FrameComparison a = compare(gpuImage, cpuImage, on);
  Row r = makeRow("refractive texture mapping",
                  exact ? "Snell's law per vertex" : "approximate ray per vertex (factor " + fixed(factor, 3) + ")",
                  1, ms[exact ? 2 : 1], ms[0], a);
  r.check = "per-vertex uv, GPU vs C++: " + fixed(vertexMax[exact ? 1 : 0], 4) + " texels max";
  r.metrics = {{"vertex_uv_gpu_cpu_max_texels", vertexMax[exact ? 1 : 0]}, {"refraction_factor", factor}};
  renders.push_back(gpuImage);
  uvs.push_back(uvImage);
  return r;
}

// The picture: both variants and the difference of their uv images, in texels of the 512 x 512 map.
void saveRtmPanel(const Options& o, const std::vector<Image>& renders, const std::vector<Image>& uvs,
                  EffectResult& result) {
  Image diff(o.width, o.height);
  for (std::size_t i = 0; i < diff.texels.size(); ++i)
    if (uvs[0].texels[i].w != 0.0f && uvs[1].texels[i].w != 0.0f)
      diff.texels[i] = vec4(
          lab::heatColor(glm::length(vec2(uvs[0].texels[i]) - vec2(uvs[1].texels[i])) * float(kMapSize) / 16.0f), 1.0f);
  savePanel(o, "rtm.png", {{&renders[0], "approximate ray"}, {&renders[1], "Snell's law"}, {&diff, "uv difference"}},
            "A sine-wave water mesh over the pool floor; uv difference black 0 to white 16 texels of the 512 map.",
            result);
}

// The animation, with the approximate ray: the waves travel, 0.4 s per frame.
void animateRtm(RtmGpu& w, const Options& o, EffectResult& result) {
  std::vector<Image> frames;
  for (int f = 0; f < o.frames; ++f) {
    w.upload(kAmplitude, 0.4f * float(f));
    w.drawPass(false);
    frames.push_back(w.fb.readColor(0));
  }
  saveAnimation(o, "rtm", frames, result);
}

// One variant against Snell's law per pixel: the interpolated uv against the exact refraction at the
// rasterized surface point about the interpolated normal, texels of the map.
UvError pixelError(RtmGpu& w, bool exact) {
  w.drawPass(exact);
  const Image uv = w.fb.readColor(1), world = w.fb.readColor(2), normal = w.fb.readColor(3);
  UvError e;
  long n = 0;
  for (std::size_t i = 0; i < uv.texels.size(); ++i) {
    if (uv.texels[i].w == 0.0f) continue;
    const double d = glm::length(glm::dvec2(vec2(uv.texels[i])) - exactUv(glm::dvec3(vec3(world.texels[i])),
                                                                          glm::dvec3(vec3(normal.texels[i])),
                                                                          glm::dvec3(w.eye))) *
                     kMapSize;
    e.mean += d;
    e.max = std::max(e.max, d);
    ++n;
  }
  e.mean /= double(std::max(1L, n));
  return e;
}

// Both variants against Snell's law as the waves grow, per vertex and per pixel: the findings' table,
// and its means as metrics of the rows (the approximate ray's first, Snell's law's last).
std::string amplitudeSweep(RtmGpu& w, float factor, std::vector<Row>& rows) {
  std::ostringstream t;
  t << "Refractive texture mapping against Snell's law to the floor plane in double precision (not the library's "
       "function), uv error in texels of the "
    << kMapSize << "x" << kMapSize << " map, mean / max; eye at (0, 3, 3.2), floor " << kDepth
    << " below the rest plane, eta 1/1.333, refraction factor " << fixed(factor, 3)
    << " (fitted on the flat mesh). Per vertex: the approximate ray at each vertex. Per pixel: the interpolated uv "
       "against the exact refraction at the rasterized surface point about the interpolated normal.\n\n"
       "| wave amplitude | approximate, per vertex | approximate, per pixel | Snell per vertex, per pixel |\n"
       "|---|---|---|---|\n";
  for (float amp : {0.0f, 0.02f, 0.04f, 0.06f, 0.1f, 0.15f}) {
    w.upload(amp, 0.0f);
    const UvError v = approxError(w.vertices, w.eye, factor);
    const UvError pa = pixelError(w, false), pe = pixelError(w, true);
    t << "| " << fixed(amp, 2) << " | " << fixed(v.mean, 2) << " / " << fixed(v.max, 2) << " | " << fixed(pa.mean, 2)
      << " / " << fixed(pa.max, 2) << " | " << fixed(pe.mean, 2) << " / " << fixed(pe.max, 2) << " |\n";
    rows.front().metrics["approx_error_mean_texels_a" + fixed(amp, 2)] = v.mean;
    rows.front().metrics["approx_pixel_error_mean_texels_a" + fixed(amp, 2)] = pa.mean;
    rows.back().metrics["snell_vertex_pixel_error_mean_texels_a" + fixed(amp, 2)] = pe.mean;
  }
  return t.str();
}

}  // namespace

EffectResult runRtm(const Gl& g, const Options& o) {
  const lab::Camera cam = camera(vec3(0.0f, 3.0f, 3.2f), vec3(0.0f, -0.6f, -0.2f), 50.0f, o);
  const float factor = fitRefractionFactor(cam.position);
  RtmGpu w(g, o, cam, params(factor));
  w.upload(kAmplitude, 0.0f);
  EffectResult result;
  const std::vector<double> ms = timeRtm(w, o.timingRepeats);
  const std::array<double, 2> vertexMax = compareVertexUvs(w);
  std::vector<Image> renders, uvs;  // per variant, its render and its uv image
  for (bool exact : {false, true}) result.rows.push_back(measureVariant(w, exact, factor, ms, vertexMax, renders, uvs));
  saveRtmPanel(o, renders, uvs, result);
  animateRtm(w, o, result);
  result.findings.push_back(amplitudeSweep(w, factor, result.rows));
  return result;
}

}  // namespace snell::gallery
