// Sousa's water (GPU Gems 2, sec. 19.3.1): a pool with pillars standing out
// of the water, a box floating above it and one under it. Passes: the opaque
// scene S (sky, tiles, boxes) with the leak probe, Sousa's mask (the water
// writes alpha 0 into S), the planar reflection (the scene mirrored through
// the water plane, clipped to what lies above it), the water's G-buffer, and
// the water pass with each mask. The probe pass runs the same water function
// on a texture that is 1 where S shows a point above the water and 0 elsewhere,
// with every other colour zero: a water pixel whose result is not zero shows
// something the water cannot refract (the leak the chapter describes).
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

}  // namespace

EffectResult runWater(const Gl& g, const Options& o) {
  const gpu::GlApi& gl = g.gl();
  const int W = o.width, H = o.height;
  const lab::Camera cam = camera(vec3(0.0f, 2.4f, 7.5f), vec3(0.0f, -0.4f, 0.0f), 50.0f, o);
  const mat4 clip = clipFromWorld(cam);
  const mat4 mirror = glm::scale(mat4(1.0f), vec3(1.0f, -1.0f, 1.0f));  // through the water plane y = 0
  const mat4 clipMirror = clip * mirror;

  const Texture2D envTex = texture(environmentImage(256), Filter::Linear);
  const Texture2D bumpTex = texture(bumpImage(256), Filter::Linear);
  const Texture2D black = texture(Image(1, 1), Filter::Nearest);
  gpu::Texture envGl(gl, envTex), bumpGl(gl, bumpTex), blackGl(gl, black);
  const Soup sceneSoup = waterScene(), surfaceSoup = waterSurface();
  gpu::StorageBuffer scene = g.upload(sceneSoup), surface = g.upload(surfaceSoup);
  const int sceneCount = sceneSoup.vertexCount(), surfaceCount = surfaceSoup.vertexCount();

  gpu::Program shade = g.program("gallery_mesh.vert", "gallery_scene.frag");
  gpu::Program water = g.program("lab_fullscreen.vert", "gallery_water.frag");

  gpu::Framebuffer sceneFb(gl, W, H, 2, true), reflFb(gl, W, H, 2, true), gFb(gl, W, H, 3, true),
      outFb(gl, W, H, 1, false);
  g.setFilter(sceneFb.colorTexture(0), GL_LINEAR);
  g.setFilter(sceneFb.colorTexture(1), GL_LINEAR);
  g.setFilter(reflFb.colorTexture(0), GL_LINEAR);

  auto drawScene = [&](const gpu::Framebuffer& fb, const mat4& clipM, vec3 eye, bool clipBelow) {
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
  };
  // (1) S and the probe; (2) Sousa's mask into both alphas.
  drawScene(sceneFb, clip, cam.position, false);
  g.maskPass(surface, surfaceCount, clip);
  // (3) The planar reflection: the mirrored scene above the plane, from the mirrored eye.
  drawScene(reflFb, clipMirror, vec3(mirror * vec4(cam.position, 1.0f)), true);
  // (4) The water's G-buffer, hidden by the opaque scene.
  g.gbufferPass(gFb, 1.0f, surface, surfaceCount, clip, sceneFb.depthTexture());
  gpu::checkGl(gl, "water scene passes");

  // (5) The water pass.
  auto waterPass = [&](int maskMode, float time, bool probe) {
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
  };
  auto plainPass = [&] { g.plainPass(outFb, sceneFb.colorTexture(0)); };

  // The read-back buffers, as the C++ side reads them.
  const Image gNormal = gFb.readColor(0), gWorld = gFb.readColor(1);
  const Texture2D sTex = texture(sceneFb.readColor(0), Filter::Linear);
  const Texture2D depthTex = texture(sceneFb.readDepth(), Filter::Nearest);
  const Texture2D reflTex = texture(reflFb.readColor(0), Filter::Linear);
  const Image probeImage = sceneFb.readColor(1);
  std::vector<bool> on(gNormal.texels.size());
  for (std::size_t i = 0; i < on.size(); ++i) on[i] = gNormal.texels[i].w != 0.0f;

  auto cpuWater = [&](int maskMode, float time, const Texture2D& sceneColor, const Texture2D& reflection, bool probe) {
    Image out(W, H);
    SnellWaterParams p = snellWaterParams();
    if (probe) {
      p.waterColor = p.deepColor = vec3(0.0f);
      p.deepDistance = 1e30f;
    }
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
        if (!on[i]) continue;
        const vec4 gw = gWorld.texels[i];
        const vec2 uv((float(x) + 0.5f) / float(W), (float(y) + 0.5f) / float(H));
        out.texels[i] = galleryWater(vec3(gw), gw.w, uv, cam.position, time, maskMode, bumpTex, sceneColor, depthTex,
                                     reflection, p);
      }
    return out;
  };

  EffectResult result;
  std::vector<Image> renders;
  const std::vector<double> ms =
      g.timeInterleaved({plainPass, [&] { waterPass(0, 0.0f, false); }, [&] { waterPass(1, 0.0f, false); },
                         [&] { waterPass(2, 0.0f, false); }},
                        o.timingRepeats);
  const int fetches[3] = {6, 7,
                          7};  // 4 bump layers, S once (off) or twice, the reflection; the depth mask reads depth + S
  std::vector<std::string> leakText;
  for (int m = 0; m < 3; ++m) {
    waterPass(m, 0.0f, false);
    const Image gpuImage = outFb.readColor(0);
    const gpu::FrameComparison a = compare(gpuImage, cpuWater(m, 0.0f, sTex, reflTex, false), on);
    // Leaks, with S read bilinearly (the pictures) and by nearest texel.
    long leaks[2] = {0, 0};
    Image leakView = gpuImage;
    for (int f = 0; f < 2; ++f) {
      g.setFilter(sceneFb.colorTexture(1), f == 0 ? GL_LINEAR : GL_NEAREST);
      waterPass(m, 0.0f, true);
      const Image probeOut = outFb.readColor(0);
      for (std::size_t i = 0; i < on.size(); ++i)
        if (on[i] && probeOut.texels[i].x > 0.0f) {
          ++leaks[f];
          if (f == 0) leakView.texels[i] = vec4(1.0f, 0.0f, 1.0f, 1.0f);
        }
    }
    g.setFilter(sceneFb.colorTexture(1), GL_LINEAR);
    // The probe on the C++ side too: the leak count must not depend on the build.
    const Image cpuProbe = cpuWater(m, 0.0f, texture(probeImage, Filter::Linear), black, true);
    long cpuLeaks = 0;
    for (std::size_t i = 0; i < on.size(); ++i) cpuLeaks += on[i] && cpuProbe.texels[i].x > 0.0f;
    Row r = makeRow("Sousa water", kMaskNames[m], fetches[m], ms[std::size_t(m) + 1], ms[0], a);
    r.check = "leaking pixels: " + std::to_string(leaks[0]) + " (S bilinear; C++ " + std::to_string(cpuLeaks) + "), " +
              std::to_string(leaks[1]) + " (S nearest)";
    r.metrics = {{"leaks_bilinear", double(leaks[0])},
                 {"leaks_nearest", double(leaks[1])},
                 {"leaks_cpu_bilinear", double(cpuLeaks)}};
    result.rows.push_back(r);
    renders.push_back(gpuImage);
    renders.push_back(leakView);
  }
  savePanel(o, "water_masks.png", {{&renders[0], "mask off"}, {&renders[2], "alpha mask"}, {&renders[4], "depth mask"}},
            "Sousa's water over a pool: the occluders' colours leak into the refraction without a mask.", result);
  savePanel(o, "water_leaks.png",
            {{&renders[1], "mask off: leaks"}, {&renders[3], "alpha mask: leaks"}, {&renders[5], "depth mask: leaks"}},
            "Magenta: water pixels whose refraction shows a point above the water (the leak probe, S bilinear).",
            result);
  // The animation: the bump layers drift.
  std::vector<Image> frames;
  for (int f = 0; f < o.frames; ++f) {
    waterPass(1, 0.5f * float(f), false);
    frames.push_back(outFb.readColor(0));
  }
  saveAnimation(o, "water", frames, result);
  result.findings.push_back(
      "Water: leak probe = the same water function on a texture that is 1 where S shows a "
      "point above the water plane; every other colour zero.");
  gpu::checkGl(gl, "water passes");
  return result;
}

}  // namespace snell::gallery
