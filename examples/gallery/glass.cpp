// Sousa's glass and heat haze (GPU Gems 2, secs. 19.1-19.3.2): a room with a
// striped wall, tiles and boxes behind two panes, stained glass on the left
// (snellGlass: bump-mapped reflection, refraction tinted by the stain) and
// heat haze on the right (the basic perturbation, drifting upwards), and a
// box in front of both: without the mask its colour leaks into the panes'
// refraction. The leak probe flags S's texels in front of the panes' plane
// (the box and the floor before the panes).
#include <array>

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

// ---- The stages of one glass run, in order (runGlass below). ----

// The room on the GL side, made once (the frame is static): the environment, bump and stain textures
// (the C++ side samples the same ones), the room and the panes, the programs and the render targets:
// S with the probe, the panes' G-buffer and the pane pass's output.
struct GlassGpu {
  const Gl& g;
  const gpu::GlApi& gl;
  const int W, H;
  const lab::Camera cam;
  const mat4 clip;
  const Texture2D envTex, bumpTex, stainTex;
  const gpu::Texture envGl, bumpGl, stainGl;
  const Soup roomSoup, paneSoup;
  const gpu::StorageBuffer roomBuf, paneBuf;
  const gpu::Program shade, pane;
  const gpu::Framebuffer sceneFb, gFb, outFb;

  GlassGpu(const Gl& gallery, const Options& o)
      : g(gallery),
        gl(gallery.gl()),
        W(o.width),
        H(o.height),
        cam(camera(vec3(0.0f, 0.55f, 4.6f), vec3(0.0f, 0.35f, 0.0f), 45.0f, o)),
        clip(clipFromWorld(cam)),
        envTex(texture(environmentImage(256), Filter::Linear)),
        bumpTex(texture(bumpImage(256), Filter::Linear)),
        stainTex(texture(stainImage(256), Filter::Linear)),
        envGl(gl, envTex),
        bumpGl(gl, bumpTex),
        stainGl(gl, stainTex),
        roomSoup(room()),
        paneSoup(panes()),
        roomBuf(g.upload(roomSoup)),
        paneBuf(g.upload(paneSoup)),
        shade(g.program("gallery_mesh.vert", "gallery_scene.frag")),
        pane(g.fullScreenProgram("gallery_pane.frag")),
        sceneFb(gl, W, H, 2, true),
        gFb(gl, W, H, 3, true),
        outFb(gl, W, H, 1, false) {
    g.setFilter(sceneFb.colorTexture(0), GL_LINEAR);
    g.setFilter(sceneFb.colorTexture(1), GL_LINEAR);
  }

  // Both panes into outFb with one mask at `time`; with `probe`, reading the probe instead of S.
  void panePass(int maskMode, float time, bool probe) const {
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
  }

  // The cost yardstick: S read once per pixel.
  void plainPass() const { g.plainPass(outFb, sceneFb.colorTexture(0)); }
};

// Everything the pane pass reads, before it runs: S and the probe (what lies in front of the panes'
// plane z = 0 must not leak), Sousa's mask, and the panes' G-buffer.
void renderGlassInputs(const GlassGpu& w) {
  const gpu::GlApi& gl = w.gl;
  w.g.skyPass(w.sceneFb, w.clip, w.cam.position, w.envGl.id());
  gl.DepthMask(GL_TRUE);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  w.shade.set("clipFromWorld", w.clip);
  w.shade.set("clipPlane", vec4(0.0f, 0.0f, 0.0f, 1.0f));
  w.shade.set("probePlane", vec4(0.0f, 0.0f, 1.0f, -0.001f));  // in front of the panes' plane z = 0
  w.shade.use();
  w.g.drawSoup(w.roomBuf, w.roomSoup.vertexCount());
  gpu::checkGl(gl, "glass scene pass");
  w.g.maskPass(w.paneBuf, w.paneSoup.vertexCount(), w.clip);
  w.g.gbufferPass(w.gFb, 1.0f, w.paneBuf, w.paneSoup.vertexCount(), w.clip, w.sceneFb.depthTexture());
  gpu::checkGl(gl, "glass G-buffer");
}

// The read-back buffers, as the C++ side reads them; `on` marks the pane pixels, `haze` those of the
// haze pane (where the leaks are counted).
struct GlassBuffers {
  Image gNormal, gWorld, gSurface;
  Texture2D sTex, probeTex;
  std::vector<bool> on, haze;
};

GlassBuffers readGlassBuffers(const GlassGpu& w) {
  GlassBuffers b{w.gFb.readColor(0),
                 w.gFb.readColor(1),
                 w.gFb.readColor(2),
                 texture(w.sceneFb.readColor(0), Filter::Linear),
                 texture(w.sceneFb.readColor(1), Filter::Linear),
                 {},
                 {}};
  b.on.resize(b.gNormal.texels.size());
  b.haze.resize(b.on.size());
  for (std::size_t i = 0; i < b.on.size(); ++i) {
    b.on[i] = b.gNormal.texels[i].w != 0.0f;
    b.haze[i] = b.on[i] && b.gSurface.texels[i].z == GALLERY_PANE_HAZE;
  }
  return b;
}

// The pane pass again in C++ (the same galleryPane) at every pane pixel, on the read-back buffers, with
// `sceneColor` as S (S itself, or the probe).
Image shadePanesOnCpu(const GlassGpu& w, const GlassBuffers& b, int maskMode, float time,
                      const Texture2D& sceneColor) {
  const int W = w.W, H = w.H;
  Image out(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
      if (!b.on[i]) continue;
      const vec4 s = b.gSurface.texels[i];
      const vec2 uv((float(x) + 0.5f) / float(W), (float(y) + 0.5f) / float(H));
      out.texels[i] = galleryPane(s.z, vec2(s.x, s.y), vec3(b.gWorld.texels[i]), uv, w.cam.position, time, maskMode,
                                  w.bumpTex, w.stainTex, sceneColor, w.envTex);
    }
  return out;
}

// The cost columns: the plain pass and the pane pass without and with the mask, interleaved.
std::vector<double> timeGlass(const GlassGpu& w, int repeats) {
  return w.g.timeInterleaved({[&] { w.plainPass(); }, [&] { w.panePass(GALLERY_MASK_OFF, 0.0f, false); },
                              [&] { w.panePass(GALLERY_MASK_ALPHA, 0.0f, false); }},
                             repeats);
}

// Leaks are counted on the haze pane only: the stained glass always masks, and its result mixes in the
// environment. The probe through the same pass, with S read bilinearly (the pictures) and by nearest texel.
std::array<long, 2> countGpuLeaks(const GlassGpu& w, const GlassBuffers& b, int maskMode) {
  std::array<long, 2> leaks = {0, 0};
  for (int f = 0; f < 2; ++f) {
    w.g.setFilter(w.sceneFb.colorTexture(1), f == 0 ? GL_LINEAR : GL_NEAREST);
    w.panePass(maskMode, 0.0f, true);
    const Image probeGpu = w.outFb.readColor(0);
    for (std::size_t i = 0; i < b.on.size(); ++i) leaks[std::size_t(f)] += b.haze[i] && probeGpu.texels[i].x > 0.0f;
  }
  w.g.setFilter(w.sceneFb.colorTexture(1), GL_LINEAR);
  return leaks;
}

// The probe on the C++ side too (S bilinear): the leak count must not depend on the build.
long countCpuLeaks(const GlassGpu& w, const GlassBuffers& b, int maskMode) {
  const Image probeCpu = shadePanesOnCpu(w, b, maskMode, 0.0f, b.probeTex);
  long cpuLeaks = 0;
  for (std::size_t i = 0; i < b.on.size(); ++i) cpuLeaks += b.haze[i] && probeCpu.texels[i].x > 0.0f;
  return cpuLeaks;
}

// One mask's row: the pane pass against C++ and the haze pane's leaks on both builds; its render goes
// to `renders` for the picture.
Row measureMask(const GlassGpu& w, const GlassBuffers& b, int m, const std::vector<double>& ms,
                std::vector<Image>& renders) {
  w.panePass(m, 0.0f, false);
  const Image gpuImage = w.outFb.readColor(0);
  const gpu::FrameComparison a = compare(gpuImage, shadePanesOnCpu(w, b, m, 0.0f, b.sTex), b.on);
  const std::array<long, 2> leaks = countGpuLeaks(w, b, m);
  const long cpuLeaks = countCpuLeaks(w, b, m);
  // haze: bump + S (+ S unperturbed); stained glass: 5 (bump, stain, S twice, env)
  Row r = makeRow("Sousa glass + heat haze",
                  m == GALLERY_MASK_OFF ? "haze without mask" : "haze, alpha mask (+ stained glass: 5 fetches)",
                  m == GALLERY_MASK_OFF ? 2 : 3, ms[m == GALLERY_MASK_OFF ? 1 : 2], ms[0], a);
  r.check = "haze pixels leaking: " + std::to_string(leaks[0]) + " (S bilinear; C++ " + std::to_string(cpuLeaks) +
            "), " + std::to_string(leaks[1]) + " (S nearest)";
  r.metrics = {{"leaks_bilinear", double(leaks[0])},
               {"leaks_nearest", double(leaks[1])},
               {"leaks_cpu_bilinear", double(cpuLeaks)}};
  renders.push_back(gpuImage);
  return r;
}

// The picture: S alone, then both panes without and with the mask (renders as measureMask left them);
// the caption says "panel" for a part of the figure and "pane" for a sheet of glass in the scene.
void saveGlassPanel(const GlassGpu& w, const Options& o, const std::vector<Image>& renders, EffectResult& result) {
  const Image sceneView = w.sceneFb.readColor(0);
  savePanel(
      o, "glass.png", {{&sceneView, "scene S"}, {&renders[0], "haze without mask"}, {&renders[1], "alpha mask"}},
      "Panels, left to right: S, the scene the panes refract (no panes drawn); both panes, the haze without the "
      "mask; both panes with Sousa's alpha mask. Left pane: stained glass (snellGlass, always masked). Right pane: "
      "heat haze (snellPerturbSample without the mask, snellRefractionMasked with it); the yellow box in front leaks "
      "into it without the mask.",
      result);
}

// The animation, with the mask: the haze drifts upwards, half a second per frame.
void animateGlass(const GlassGpu& w, const Options& o, EffectResult& result) {
  std::vector<Image> frames;
  for (int f = 0; f < o.frames; ++f) {
    w.panePass(GALLERY_MASK_ALPHA, 0.5f * float(f), false);
    frames.push_back(w.outFb.readColor(0));
  }
  saveAnimation(o, "glass", frames, result);
}

}  // namespace

EffectResult runGlass(const Gl& g, const Options& o) {
  const GlassGpu w(g, o);
  renderGlassInputs(w);
  const GlassBuffers b = readGlassBuffers(w);
  EffectResult result;
  const std::vector<double> ms = timeGlass(w, o.timingRepeats);
  std::vector<Image> renders;  // per mask, its render
  for (int m : {GALLERY_MASK_OFF, GALLERY_MASK_ALPHA}) result.rows.push_back(measureMask(w, b, m, ms, renders));
  saveGlassPanel(w, o, renders, result);
  animateGlass(w, o, result);
  gpu::checkGl(w.gl, "glass passes");
  return result;
}

}  // namespace snell::gallery
