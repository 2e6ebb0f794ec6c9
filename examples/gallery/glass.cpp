// Sousa's glass and heat haze (GPU Gems 2, secs. 19.1-19.3.2): a room with a
// striped wall, tiles and boxes behind two panes, stained glass on the left
// (snellGlass: bump-mapped reflection, refraction tinted by the stain) and
// heat haze on the right (the basic perturbation, drifting upwards), and a
// box in front of both: without the mask its colour leaks into the panes'
// refraction. The leak probe flags S's texels in front of the panes' plane
// (the box and the floor before the panes).
#include "effects.hpp"
#include "lab/image_io.hpp"
#include "textures.hpp"

namespace snell::gallery {

namespace {

Soup room() {
  Soup s;
  const vec3 wall[4] = {{-5.0f, -1.5f, -3.0f}, {5.0f, -1.5f, -3.0f}, {5.0f, 3.5f, -3.0f}, {-5.0f, 3.5f, -3.0f}};
  s.quad(wall, vec3(1.0f), 2.0f);
  const vec3 floorQuad[4] = {{-5.0f, -1.5f, 3.0f}, {5.0f, -1.5f, 3.0f}, {5.0f, -1.5f, -3.0f}, {-5.0f, -1.5f, -3.0f}};
  s.quad(floorQuad, vec3(1.0f), 1.0f);
  s.box({-1.6f, -1.5f, -2.0f}, {-0.8f, -0.2f, -1.2f}, {0.85f, 0.2f, 0.15f});
  s.box({0.6f, -1.5f, -1.9f}, {1.5f, 0.6f, -1.1f}, {0.2f, 0.6f, 0.85f});
  s.box({-0.35f, -1.5f, 0.9f}, {0.35f, 0.1f, 1.5f}, {0.95f, 0.8f, 0.2f});  // in front of the panes
  return s;
}

Soup panes() {
  Soup s;
  const vec3 left[4] = {{-2.0f, -0.7f, 0.0f}, {-0.15f, -0.7f, 0.0f}, {-0.15f, 1.6f, 0.0f}, {-2.0f, 1.6f, 0.0f}};
  const vec3 right[4] = {{0.15f, -0.7f, 0.0f}, {2.0f, -0.7f, 0.0f}, {2.0f, 1.6f, 0.0f}, {0.15f, 1.6f, 0.0f}};
  s.quad(left, vec3(0.0f), GALLERY_PANE_STAINED);
  s.quad(right, vec3(0.0f), GALLERY_PANE_HAZE);
  return s;
}

}  // namespace

EffectResult runGlass(const Gl& g, const Options& o) {
  const gpu::GlApi& gl = g.gl();
  const int W = o.width, H = o.height;
  const lab::Camera cam = camera(vec3(0.0f, 0.55f, 4.6f), vec3(0.0f, 0.35f, 0.0f), 45.0f, o);
  const mat4 clip = clipFromWorld(cam);

  const Texture2D envTex = texture(environmentImage(256), Filter::Linear);
  const Texture2D bumpTex = texture(bumpImage(256), Filter::Linear);
  const Texture2D stainTex = texture(stainImage(256), Filter::Linear);
  gpu::Texture envGl(gl, envTex), bumpGl(gl, bumpTex), stainGl(gl, stainTex);
  const Soup roomSoup = room(), paneSoup = panes();
  gpu::StorageBuffer roomBuf = g.upload(roomSoup), paneBuf = g.upload(paneSoup);

  gpu::Program shade = g.program("gallery_mesh.vert", "gallery_scene.frag");
  gpu::Program pane = g.program("lab_fullscreen.vert", "gallery_pane.frag");
  gpu::Framebuffer sceneFb(gl, W, H, 2, true), gFb(gl, W, H, 3, true), outFb(gl, W, H, 1, false);
  g.setFilter(sceneFb.colorTexture(0), GL_LINEAR);
  g.setFilter(sceneFb.colorTexture(1), GL_LINEAR);

  // (1) S and the probe (in front of the panes' plane z = 0 is what must not leak).
  g.skyPass(sceneFb, clip, cam.position, envGl.id());
  gl.DepthMask(GL_TRUE);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  shade.set("clipFromWorld", clip);
  shade.set("clipPlane", vec4(0.0f, 0.0f, 0.0f, 1.0f));
  shade.set("probePlane", vec4(0.0f, 0.0f, 1.0f, -0.001f));  // in front of the panes' plane z = 0
  shade.use();
  g.drawSoup(roomBuf, roomSoup.vertexCount());
  gpu::checkGl(gl, "glass scene pass");
  // (2) Sousa's mask.
  g.maskPass(paneBuf, paneSoup.vertexCount(), clip);
  // (3) The panes' G-buffer.
  g.gbufferPass(gFb, 1.0f, paneBuf, paneSoup.vertexCount(), clip, sceneFb.depthTexture());
  gpu::checkGl(gl, "glass G-buffer");

  auto panePass = [&](int maskMode, float time, bool probe) {
    outFb.bind();
    gl.Disable(GL_DEPTH_TEST);
    pane.set("eye", cam.position);
    pane.set("time", time);
    pane.set("mask", maskMode);
    pane.set("viewport", vec2(float(W), float(H)));
    g.bindTextures({gFb.colorTexture(0), gFb.colorTexture(1), gFb.colorTexture(2), bumpGl.id(), stainGl.id(),
                    probe ? sceneFb.colorTexture(1) : sceneFb.colorTexture(0), envGl.id()});
    pane.use();
    g.fullscreen();
  };
  auto plainPass = [&] { g.plainPass(outFb, sceneFb.colorTexture(0)); };

  const Image gNormal = gFb.readColor(0), gWorld = gFb.readColor(1), gSurface = gFb.readColor(2);
  const Texture2D sTex = texture(sceneFb.readColor(0), Filter::Linear);
  const Texture2D probeTex = texture(sceneFb.readColor(1), Filter::Linear);
  std::vector<bool> on(gNormal.texels.size()), haze(on.size());
  for (std::size_t i = 0; i < on.size(); ++i) {
    on[i] = gNormal.texels[i].w != 0.0f;
    haze[i] = on[i] && gSurface.texels[i].z == GALLERY_PANE_HAZE;
  }
  auto cpuPane = [&](int maskMode, float time, const Texture2D& sceneColor) {
    Image out(W, H);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
        if (!on[i]) continue;
        const vec4 s = gSurface.texels[i];
        const vec2 uv((float(x) + 0.5f) / float(W), (float(y) + 0.5f) / float(H));
        out.texels[i] = galleryPane(s.z, vec2(s.x, s.y), vec3(gWorld.texels[i]), uv, cam.position, time, maskMode,
                                    bumpTex, stainTex, sceneColor, envTex);
      }
    return out;
  };

  EffectResult result;
  const std::vector<double> ms = g.timeInterleaved(
      {plainPass, [&] { panePass(GALLERY_MASK_OFF, 0.0f, false); }, [&] { panePass(GALLERY_MASK_ALPHA, 0.0f, false); }},
      o.timingRepeats);
  std::vector<Image> renders;
  for (int m : {GALLERY_MASK_OFF, GALLERY_MASK_ALPHA}) {
    panePass(m, 0.0f, false);
    const Image gpuImage = outFb.readColor(0);
    const gpu::FrameComparison a = compare(gpuImage, cpuPane(m, 0.0f, sTex), on);
    // Leaks on the haze pane (the stained glass always masks; its result mixes in the environment):
    // the probe through the same pass, with S read bilinearly (the pictures) and by nearest texel.
    long leaks[2] = {0, 0}, cpuLeaks = 0;
    for (int f = 0; f < 2; ++f) {
      g.setFilter(sceneFb.colorTexture(1), f == 0 ? GL_LINEAR : GL_NEAREST);
      panePass(m, 0.0f, true);
      const Image probeGpu = outFb.readColor(0);
      for (std::size_t i = 0; i < on.size(); ++i) leaks[f] += haze[i] && probeGpu.texels[i].x > 0.0f;
    }
    g.setFilter(sceneFb.colorTexture(1), GL_LINEAR);
    const Image probeCpu = cpuPane(m, 0.0f, probeTex);
    for (std::size_t i = 0; i < on.size(); ++i) cpuLeaks += haze[i] && probeCpu.texels[i].x > 0.0f;
    // haze: bump + S (+ S unperturbed); stained glass: 5 (bump, stain, S twice, env)
    Row r = makeRow("Sousa glass + heat haze",
                    m == GALLERY_MASK_OFF ? "haze without mask" : "haze, alpha mask (+ stained glass: 5 fetches)",
                    m == GALLERY_MASK_OFF ? 2 : 3, ms[m == GALLERY_MASK_OFF ? 1 : 2], ms[0], a);
    r.check = "haze pixels leaking: " + std::to_string(leaks[0]) + " (S bilinear; C++ " + std::to_string(cpuLeaks) +
              "), " + std::to_string(leaks[1]) + " (S nearest)";
    r.metrics = {{"leaks_bilinear", double(leaks[0])},
                 {"leaks_nearest", double(leaks[1])},
                 {"leaks_cpu_bilinear", double(cpuLeaks)}};
    result.rows.push_back(r);
    renders.push_back(gpuImage);
  }
  const Image sceneView = sceneFb.readColor(0);
  savePanel(
      o, "glass.png", {{&sceneView, "scene S"}, {&renders[0], "haze without mask"}, {&renders[1], "alpha mask"}},
      "Left pane: stained glass (snellGlass). Right pane: heat haze (snellPerturbSample / snellRefractionMasked); "
      "the yellow box in front leaks into it without the mask.",
      result);
  std::vector<Image> frames;
  for (int f = 0; f < o.frames; ++f) {
    panePass(GALLERY_MASK_ALPHA, 0.5f * float(f), false);
    frames.push_back(outFb.readColor(0));
  }
  saveAnimation(o, "glass", frames, result);
  gpu::checkGl(gl, "glass passes");
  return result;
}

}  // namespace snell::gallery
