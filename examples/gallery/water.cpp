// Sousa's water (GPU Gems 2, sec. 19.3.1): a pool with pillars standing out
// of the water, a box floating above it and one under it. Passes: the opaque
// scene S (sky, tiles, boxes) with the leak probe, Sousa's mask (the water
// writes alpha 0 into S), the planar reflection (the scene mirrored through
// the water plane, clipped to what lies above it), the water's G-buffer, and
// the water pass with each mask. The probe pass runs the same water function
// on a texture that is 1 where S shows a point above the water and 0 elsewhere,
// with every other colour zero: a water pixel whose result is not zero shows
// something the water cannot refract (the leak the chapter describes).
#include <array>
#include <glm/gtc/matrix_transform.hpp>

#include "effects.hpp"
#include "lab/image_io.hpp"
#include "textures.hpp"

namespace snell::gallery {

namespace {

constexpr float kPoolFloor = -1.2f;

Soup waterScene() {
  Soup s;
  const float e = 14.0f;
  const vec3 floorQuad[4] = {{-e, kPoolFloor, e}, {e, kPoolFloor, e}, {e, kPoolFloor, -e}, {-e, kPoolFloor, -e}};
  s.quad(floorQuad, vec3(1.0f), 1.0f);
  s.box({-2.6f, kPoolFloor, -1.5f}, {-1.9f, 1.4f, -0.8f}, {0.8f, 0.2f, 0.15f});  // pillars through the surface
  s.box({1.5f, kPoolFloor, -3.0f}, {2.3f, 0.9f, -2.2f}, {0.9f, 0.75f, 0.2f});
  s.box({0.3f, kPoolFloor, 1.6f}, {0.9f, 0.7f, 2.2f}, {0.2f, 0.7f, 0.3f});      // near the camera: an occluder
  s.box({-0.8f, kPoolFloor, -0.5f}, {0.4f, -0.7f, 0.6f}, {0.95f, 0.5f, 0.1f});  // under water
  s.box({2.4f, 0.15f, 0.4f}, {3.2f, 0.65f, 1.2f}, {0.55f, 0.3f, 0.8f});         // above water
  return s;
}

Soup waterSurface() {
  Soup s;
  const float e = 14.0f;
  const vec3 q[4] = {{-e, 0.0f, e}, {e, 0.0f, e}, {e, 0.0f, -e}, {-e, 0.0f, -e}};
  s.quad(q, vec3(0.0f), 0.0f);
  return s;
}

const char* kMaskNames[3] = {"mask off", "alpha mask", "depth mask"};
// Texture reads per water pixel, by mask: 4 bump layers, S once (off) or twice, the reflection; the
// depth mask reads depth + S.
const int kFetches[3] = {6, 7, 7};

// ---- The stages of one water run, in order (runWater below). ----

// The pool on the GL side, made once (the frame is static): the environment and bump textures (the
// C++ side samples the same ones), the scene and the water surface, the programs and the render
// targets: S with the probe, the reflection, the water's G-buffer and the water pass's output.
struct WaterGpu {
  const Gl& g;
  const gpu::GlApi& gl;
  const int W, H;
  const lab::Camera cam;
  const mat4 clip;
  const mat4 mirror;  // through the water plane y = 0
  const mat4 clipMirror;
  const Texture2D envTex, bumpTex, black;
  const gpu::Texture envGl, bumpGl, blackGl;
  const Soup sceneSoup, surfaceSoup;
  const gpu::StorageBuffer scene, surface;
  const int sceneCount, surfaceCount;
  const gpu::Program shade, water;
  const gpu::Framebuffer sceneFb, reflFb, gFb, outFb;

  WaterGpu(const Gl& gallery, const Options& o)
      : g(gallery),
        gl(gallery.gl()),
        W(o.width),
        H(o.height),
        cam(camera(vec3(0.0f, 2.4f, 7.5f), vec3(0.0f, -0.4f, 0.0f), 50.0f, o)),
        clip(clipFromWorld(cam)),
        mirror(glm::scale(mat4(1.0f), vec3(1.0f, -1.0f, 1.0f))),
        clipMirror(clip * mirror),
        envTex(texture(environmentImage(256), Filter::Linear)),
        bumpTex(texture(bumpImage(256), Filter::Linear)),
        black(texture(Image(1, 1), Filter::Nearest)),
        envGl(gl, envTex),
        bumpGl(gl, bumpTex),
        blackGl(gl, black),
        sceneSoup(waterScene()),
        surfaceSoup(waterSurface()),
        scene(g.upload(sceneSoup)),
        surface(g.upload(surfaceSoup)),
        sceneCount(sceneSoup.vertexCount()),
        surfaceCount(surfaceSoup.vertexCount()),
        shade(g.program("gallery_mesh.vert", "gallery_scene.frag")),
        water(g.fullScreenProgram("gallery_water.frag")),
        sceneFb(gl, W, H, 2, true),
        reflFb(gl, W, H, 2, true),
        gFb(gl, W, H, 3, true),
        outFb(gl, W, H, 1, false) {
    g.setFilter(sceneFb.colorTexture(0), GL_LINEAR);
    g.setFilter(sceneFb.colorTexture(1), GL_LINEAR);
    g.setFilter(reflFb.colorTexture(0), GL_LINEAR);
  }

  // The opaque scene and the probe into `fb` through `clipM` from `eye`; with `clipBelow`, only what
  // lies above the water plane (the reflection's half).
  void drawScene(const gpu::Framebuffer& fb, const mat4& clipM, vec3 eye, bool clipBelow) const {
    g.skyPass(fb, clipM, eye, envGl.id());
    gl.DepthMask(GL_TRUE);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    shade.set("clipFromWorld", clipM);
    shade.set("clipPlane", clipBelow ? vec4(0.0f, 1.0f, 0.0f, 0.0f) : vec4(0.0f, 0.0f, 0.0f, 1.0f));
    shade.set("probePlane", vec4(0.0f, 1.0f, 0.0f, -0.001f));  // above the water plane y = 0
    if (clipBelow) gl.Enable(GL_CLIP_DISTANCE0);
    shade.use();
    g.drawSoup(scene, sceneCount);
    gl.Disable(GL_CLIP_DISTANCE0);
  }

  // The water pass into outFb with one mask at `time`; with `probe`, on the probe texture with every
  // other colour zero (the leak probe).
  void waterPass(int maskMode, float time, bool probe) const {
    outFb.bind();
    gl.Disable(GL_DEPTH_TEST);
    SnellWaterParams p = snellWaterParams();
    water.set("eye", cam.position);
    water.set("time", time);
    water.set("mask", maskMode);
    water.set("viewport", vec2(float(W), float(H)));
    water.set("waterColor", probe ? vec3(0.0f) : p.waterColor);
    water.set("deepColor", probe ? vec3(0.0f) : p.deepColor);
    water.set("deepDistance", probe ? 1e30f : p.deepDistance);
    g.bindTextures({gFb.colorTexture(0), gFb.colorTexture(1), bumpGl.id(),
                    probe ? sceneFb.colorTexture(1) : sceneFb.colorTexture(0), sceneFb.depthTexture(),
                    probe ? blackGl.id() : reflFb.colorTexture(0)});
    water.use();
    g.fullscreen();
  }

  // The cost yardstick: S read once per pixel.
  void plainPass() const { g.plainPass(outFb, sceneFb.colorTexture(0)); }
};

// Everything the water pass reads, before it runs: S and the probe, Sousa's mask into both alphas,
// the planar reflection (the mirrored scene above the plane, from the mirrored eye), and the water's
// G-buffer, hidden by the opaque scene.
void renderWaterInputs(const WaterGpu& w) {
  w.drawScene(w.sceneFb, w.clip, w.cam.position, false);
  w.g.maskPass(w.surface, w.surfaceCount, w.clip);
  w.drawScene(w.reflFb, w.clipMirror, vec3(w.mirror * vec4(w.cam.position, 1.0f)), true);
  w.g.gbufferPass(w.gFb, 1.0f, w.surface, w.surfaceCount, w.clip, w.sceneFb.depthTexture());
  gpu::checkGl(w.gl, "water scene passes");
}

// The read-back buffers, as the C++ side reads them; `on` marks the water pixels.
struct WaterBuffers {
  Image gNormal, gWorld;
  Texture2D sTex, depthTex, reflTex;
  Image probeImage;
  std::vector<bool> on;
};

WaterBuffers readWaterBuffers(const WaterGpu& w) {
  WaterBuffers b{w.gFb.readColor(0),
                 w.gFb.readColor(1),
                 texture(w.sceneFb.readColor(0), Filter::Linear),
                 texture(w.sceneFb.readDepth(), Filter::Nearest),
                 texture(w.reflFb.readColor(0), Filter::Linear),
                 w.sceneFb.readColor(1),
                 {}};
  b.on.resize(b.gNormal.texels.size());
  for (std::size_t i = 0; i < b.on.size(); ++i) b.on[i] = b.gNormal.texels[i].w != 0.0f;
  return b;
}

// The water pass again in C++ (the same galleryWater) at every water pixel, on the read-back buffers;
// with `probe`, every colour but `sceneColor`'s zero, as the GPU's probe pass.
Image shadeWaterOnCpu(const WaterGpu& w, const WaterBuffers& b, int maskMode, float time,
                      const Texture2D& sceneColor, const Texture2D& reflection, bool probe) {
  const int W = w.W, H = w.H;
  Image out(W, H);
  SnellWaterParams p = snellWaterParams();
  if (probe) {
    p.waterColor = p.deepColor = vec3(0.0f);
    p.deepDistance = 1e30f;
  }
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
      if (!b.on[i]) continue;
      const vec4 gw = b.gWorld.texels[i];
      const vec2 uv((float(x) + 0.5f) / float(W), (float(y) + 0.5f) / float(H));
      out.texels[i] = galleryWater(vec3(gw), gw.w, uv, w.cam.position, time, maskMode, w.bumpTex, sceneColor,
                                   b.depthTex, reflection, p);
    }
  return out;
}

// The cost columns: the plain pass and the water pass with each mask, interleaved.
std::vector<double> timeWater(const WaterGpu& w, int repeats) {
  return w.g.timeInterleaved({[&] { w.plainPass(); }, [&] { w.waterPass(0, 0.0f, false); },
                              [&] { w.waterPass(1, 0.0f, false); }, [&] { w.waterPass(2, 0.0f, false); }},
                             repeats);
}

// The leaks one mask lets through on the GPU, with S read bilinearly (the pictures) and by nearest
// texel: the bilinear ones are painted magenta on `leakView`.
std::array<long, 2> countGpuLeaks(const WaterGpu& w, const WaterBuffers& b, int maskMode, Image& leakView) {
  std::array<long, 2> leaks = {0, 0};
  for (int f = 0; f < 2; ++f) {
    w.g.setFilter(w.sceneFb.colorTexture(1), f == 0 ? GL_LINEAR : GL_NEAREST);
    w.waterPass(maskMode, 0.0f, true);
    const Image probeOut = w.outFb.readColor(0);
    for (std::size_t i = 0; i < b.on.size(); ++i)
      if (b.on[i] && probeOut.texels[i].x > 0.0f) {
        ++leaks[std::size_t(f)];
        if (f == 0) leakView.texels[i] = vec4(1.0f, 0.0f, 1.0f, 1.0f);
      }
  }
  w.g.setFilter(w.sceneFb.colorTexture(1), GL_LINEAR);
  return leaks;
}

// The probe on the C++ side too (S bilinear): the leak count must not depend on the build.
long countCpuLeaks(const WaterGpu& w, const WaterBuffers& b, int maskMode) {
  const Image cpuProbe = shadeWaterOnCpu(w, b, maskMode, 0.0f, texture(b.probeImage, Filter::Linear), w.black, true);
  long cpuLeaks = 0;
  for (std::size_t i = 0; i < b.on.size(); ++i) cpuLeaks += b.on[i] && cpuProbe.texels[i].x > 0.0f;
  return cpuLeaks;
}

// One mask's row: the water pass against C++ and its leaks on both builds; its render and its leak
// view go to `renders` for the pictures.
Row measureMask(const WaterGpu& w, const WaterBuffers& b, int m, const std::vector<double>& ms,
                std::vector<Image>& renders) {
  w.waterPass(m, 0.0f, false);
  const Image gpuImage = w.outFb.readColor(0);
  const gpu::FrameComparison a = compare(gpuImage, shadeWaterOnCpu(w, b, m, 0.0f, b.sTex, b.reflTex, false), b.on);
  Image leakView = gpuImage;
  const std::array<long, 2> leaks = countGpuLeaks(w, b, m, leakView);
  const long cpuLeaks = countCpuLeaks(w, b, m);
  Row r = makeRow("Sousa water", kMaskNames[m], kFetches[m], ms[std::size_t(m) + 1], ms[0], a);
  r.check = "leaking pixels: " + std::to_string(leaks[0]) + " (S bilinear; C++ " + std::to_string(cpuLeaks) + "), " +
            std::to_string(leaks[1]) + " (S nearest)";
  r.metrics = {{"leaks_bilinear", double(leaks[0])},
               {"leaks_nearest", double(leaks[1])},
               {"leaks_cpu_bilinear", double(cpuLeaks)}};
  renders.push_back(gpuImage);
  renders.push_back(leakView);
  return r;
}

// The pictures: the three masks side by side, then their leaks (renders as measureMask left them).
void saveWaterPanels(const Options& o, const std::vector<Image>& renders, EffectResult& result) {
  savePanel(o, "water_masks.png", {{&renders[0], "mask off"}, {&renders[2], "alpha mask"}, {&renders[4], "depth mask"}},
            "Sousa's water over a pool: the occluders' colours leak into the refraction without a mask.", result);
  savePanel(o, "water_leaks.png",
            {{&renders[1], "mask off: leaks"}, {&renders[3], "alpha mask: leaks"}, {&renders[5], "depth mask: leaks"}},
            "Magenta: water pixels whose refraction shows a point above the water (the leak probe, S bilinear).",
            result);
}

// The animation, with the alpha mask: the bump layers drift, half a second per frame.
void animateWater(const WaterGpu& w, const Options& o, EffectResult& result) {
  std::vector<Image> frames;
  for (int f = 0; f < o.frames; ++f) {
    w.waterPass(1, 0.5f * float(f), false);
    frames.push_back(w.outFb.readColor(0));
  }
  saveAnimation(o, "water", frames, result);
}

}  // namespace

EffectResult runWater(const Gl& g, const Options& o) {
  const WaterGpu w(g, o);
  renderWaterInputs(w);
  const WaterBuffers b = readWaterBuffers(w);
  EffectResult result;
  const std::vector<double> ms = timeWater(w, o.timingRepeats);
  std::vector<Image> renders;  // per mask: its render, then its leak view
  for (int m = 0; m < 3; ++m) result.rows.push_back(measureMask(w, b, m, ms, renders));
  saveWaterPanels(o, renders, result);
  animateWater(w, o, result);
  result.findings.push_back(
      "Water: leak probe = the same water function on a texture that is 1 where S shows a "
      "point above the water plane; every other colour zero.");
  gpu::checkGl(w.gl, "water passes");
  return result;
}

}  // namespace snell::gallery
