// The ice paper (sec. 3.2-3.3): a block of ice in the environment, refracted
// once about the blend of its front and back normals, reflected about the
// front normal, mixed by the cubic Fresnel term; then four generic crack
// surfaces (large planes through the block) clipped per pixel by the depth
// interval between the front and back faces. The clipping is compared with the
// analytic solid: per pixel and crack, the camera ray's hit on the crack plane
// (double precision) inside the box or not.
#include <array>
#include <glm/gtc/matrix_transform.hpp>

#include "effects.hpp"
#include "lab/image_io.hpp"
#include "textures.hpp"

namespace snell::gallery {

namespace {

const vec3 kHalf(0.8f, 1.1f, 0.65f);

mat4 blockTransform() {
  mat4 m(1.0f);
  m = glm::rotate(m, glm::radians(28.0f), vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(12.0f), vec3(1, 0, 0));
  m = glm::rotate(m, glm::radians(-6.0f), vec3(0, 0, 1));
  return m;
}

// Crack k: a square of half size kCrackHalf through `centre` (box coordinates), spanned by u and v:
// partly inside the block, so the clipping shows at the faces and the square's own edges show inside.
constexpr double kCrackHalf = 0.75;
struct Crack {
  vec3 centre, u, v;
};
std::array<Crack, GALLERY_CRACKS> cracks() {
  return {{{{0.1f, 0.2f, 0.0f}, glm::normalize(vec3(1.0f, 0.3f, 0.2f)), glm::normalize(vec3(-0.1f, 0.4f, 1.0f))},
           {{-0.2f, -0.4f, 0.1f}, glm::normalize(vec3(0.2f, 1.0f, -0.3f)), glm::normalize(vec3(1.0f, 0.0f, 0.6f))},
           {{0.3f, 0.6f, -0.2f}, glm::normalize(vec3(1.0f, -0.5f, 0.0f)), glm::normalize(vec3(0.3f, 0.2f, 1.0f))},
           {{-0.35f, 0.1f, 0.25f}, glm::normalize(vec3(0.0f, 1.0f, 0.2f)), glm::normalize(vec3(0.7f, -0.2f, 0.9f))}}};
}

// The block, turned by `worldFromBox`, as a soup in world space.
Soup iceBlock(const mat4& worldFromBox) {
  Soup block;
  block.box(-kHalf, kHalf, vec3(1.0f), 0.0f, worldFromBox);
  return block;
}

// Each crack's square as a soup in world space (the block's turn applied).
std::vector<Soup> crackSquares(const mat4& worldFromBox) {
  std::vector<Soup> soups;
  for (const Crack& c : cracks()) {
    Soup s;
    auto at = [&](float a, float b) {
      return vec3(worldFromBox * vec4(c.centre + float(kCrackHalf) * (a * c.u + b * c.v), 1.0f));
    };
    const vec3 q[4] = {at(-1, -1), at(1, -1), at(1, 1), at(-1, 1)};
    s.quad(q, vec3(0.0f), 0.0f);
    soups.push_back(s);
  }
  return soups;
}

// One storage buffer per crack: renderCrackDepths draws each into its own attachment.
std::vector<gpu::StorageBuffer> uploadAll(const Gl& g, const std::vector<Soup>& soups) {
  std::vector<gpu::StorageBuffer> buffers;
  for (const Soup& s : soups) buffers.push_back(g.upload(s));
  return buffers;
}

// ---- The stages of one ice run, in order (runIce below). ----

// The block on the GL side, made once (the frame is static): the environment (the C++ side samples the
// same one), the block and the crack squares, the programs and the render targets: the environment
// behind the block, the front and the back faces' G-buffers, one depth attachment per crack and the ice
// pass's output (colour, and the kept cracks' bits).
struct IceGpu {
  const Gl& g;
  const gpu::GlApi& gl;
  const int W, H;
  const lab::Camera cam;
  const mat4 clip;
  const mat4 worldFromBox;
  const Texture2D envTex;
  const gpu::Texture envGl;
  const Soup block;
  const gpu::StorageBuffer blockBuf;
  const std::vector<Soup> crackSoups;
  const std::vector<gpu::StorageBuffer> crackBufs;
  const gpu::Program crack, ice;
  const gpu::Framebuffer sceneFb, frontFb, backFb, crackFb, outFb;

  IceGpu(const Gl& gallery, const Options& o)
      : g(gallery),
        gl(gallery.gl()),
        W(o.width),
        H(o.height),
        cam(camera(vec3(0.0f, 0.7f, 4.3f), vec3(0.0f, 0.0f, 0.0f), 45.0f, o)),
        clip(clipFromWorld(cam)),
        worldFromBox(blockTransform()),
        envTex(texture(environmentImage(256), Filter::Linear)),
        envGl(gl, envTex),
        block(iceBlock(worldFromBox)),
        blockBuf(g.upload(block)),
        crackSoups(crackSquares(worldFromBox)),
        crackBufs(uploadAll(g, crackSoups)),
        crack(g.program("gallery_mesh.vert", "gallery_crack.frag")),
        ice(g.fullScreenProgram("gallery_ice.frag")),
        sceneFb(gl, W, H, 2, true),
        frontFb(gl, W, H, 3, true),
        backFb(gl, W, H, 3, true),
        crackFb(gl, W, H, 4, false),
        outFb(gl, W, H, 2, false) {
    g.setFilter(sceneFb.colorTexture(0), GL_LINEAR);
  }

  // The ice pass into outFb, with or without the cracks.
  void icePass(bool withCracks) const {
    outFb.bind();
    gl.Disable(GL_DEPTH_TEST);
    ice.set("eye", cam.position);
    ice.set("withCracks", withCracks ? 1 : 0);
    g.bindTextures({frontFb.colorTexture(0), frontFb.colorTexture(1), backFb.colorTexture(0), backFb.colorTexture(1),
                    crackFb.colorTexture(0), crackFb.colorTexture(1), crackFb.colorTexture(2), crackFb.colorTexture(3),
                    envGl.id(), sceneFb.colorTexture(0)});
    ice.use();
    g.fullscreen();
  }

  // The cost yardstick: the environment pass read once per pixel.
  void plainPass() const { g.plainPass(outFb, sceneFb.colorTexture(0)); }
};

// The block's two interfaces: the environment behind it, then the front faces (depth LESS) and the back
// faces (front culled, depth GREATER from 0), each into its own G-buffer.
void renderBlockFaces(const IceGpu& w) {
  const gpu::GlApi& gl = w.gl;
  w.g.skyPass(w.sceneFb, w.clip, w.cam.position, w.envGl.id());
  gl.DepthMask(GL_TRUE);
  for (int side = 0; side < 2; ++side) {
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(side == 0 ? GL_LESS : GL_GREATER);
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(side == 0 ? GL_BACK : GL_FRONT);
    w.g.gbufferPass(side == 0 ? w.frontFb : w.backFb, side == 0 ? 1.0f : 0.0f, w.blockBuf, w.block.vertexCount(),
                    w.clip, w.sceneFb.depthTexture());
  }
  gl.CullFace(GL_BACK);
  gl.Disable(GL_CULL_FACE);
  gl.DepthFunc(GL_LESS);
}

// Each crack's depth into its own attachment (2: no crack at the pixel), unclipped: the ice pass clips
// them per pixel against the front-back depth interval.
void renderCrackDepths(const IceGpu& w) {
  const gpu::GlApi& gl = w.gl;
  for (int k = 0; k < GALLERY_CRACKS; ++k) w.crackFb.clearColor(k, vec4(2.0f, 0.0f, 0.0f, 0.0f));
  w.crackFb.bind();
  gl.Disable(GL_DEPTH_TEST);
  w.crack.set("clipFromWorld", w.clip);
  w.crack.set("clipPlane", vec4(0.0f, 0.0f, 0.0f, 1.0f));
  w.crack.use();
  for (int k = 0; k < GALLERY_CRACKS; ++k) {
    for (int a = 0; a < GALLERY_CRACKS; ++a) {
      const GLboolean write = a == k ? GL_TRUE : GL_FALSE;
      gl.ColorMaski(GLuint(a), write, write, write, write);
    }
    w.g.drawSoup(w.crackBufs[std::size_t(k)], w.crackSoups[std::size_t(k)].vertexCount());
  }
  for (int a = 0; a < GALLERY_CRACKS; ++a) gl.ColorMaski(GLuint(a), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gpu::checkGl(gl, "ice passes");
}

// The read-back buffers, as the C++ side reads them: front and back normals and world positions (depth
// in w), each crack's depth; `on` marks the block's pixels.
struct IceBuffers {
  Image fN, fW, bN, bW;
  std::array<Image, GALLERY_CRACKS> cD;
  std::vector<bool> on;
};

IceBuffers readIceBuffers(const IceGpu& w) {
  IceBuffers b{w.frontFb.readColor(0), w.frontFb.readColor(1), w.backFb.readColor(0), w.backFb.readColor(1), {}, {}};
  for (int k = 0; k < GALLERY_CRACKS; ++k) b.cD[std::size_t(k)] = w.crackFb.readColor(k);
  b.on.resize(b.fN.texels.size());
  for (std::size_t i = 0; i < b.on.size(); ++i) b.on[i] = b.fN.texels[i].w != 0.0f;
  return b;
}

// The ice pass again in C++ (the same galleryIce) at every block pixel, on the read-back buffers; with
// `bits`, the kept cracks' bits there too.
Image shadeIceOnCpu(const IceGpu& w, const IceBuffers& b, bool withCracks, Image* bits) {
  Image out(w.W, w.H);
  for (std::size_t i = 0; i < b.on.size(); ++i) {
    if (!b.on[i]) continue;
    const vec4 cd(b.cD[0].texels[i].x, b.cD[1].texels[i].x, b.cD[2].texels[i].x, b.cD[3].texels[i].x);
    const GalleryIce r = galleryIce(vec3(b.fN.texels[i]), vec3(b.bN.texels[i]), vec3(b.fW.texels[i]), w.cam.position,
                                    b.fW.texels[i].w, b.bW.texels[i].w, cd, withCracks, w.envTex);
    out.texels[i] = r.color;
    if (bits) bits->texels[i] = vec4(float(r.cracks), 0.0f, 0.0f, 0.0f);
  }
  return out;
}

// The cost columns: the plain pass and the ice pass without and with the cracks, interleaved.
std::vector<double> timeIce(const IceGpu& w, int repeats) {
  return w.g.timeInterleaved({[&] { w.plainPass(); }, [&] { w.icePass(false); }, [&] { w.icePass(true); }}, repeats);
}

// The analytic solid for one crack: does the camera ray o3 + t d3 (box coordinates, t > 0) meet the crack
// plane inside the crack's square and inside the box? In double precision, independent of the GL side.
bool analyticCrackHit(const Crack& c, const glm::dvec3& o3, const glm::dvec3& d3) {
  const glm::dvec3 n = glm::cross(glm::dvec3(c.u), glm::dvec3(c.v));
  const double den = glm::dot(n, d3);
  if (den == 0.0) return false;
  const double t = glm::dot(n, glm::dvec3(c.centre) - o3) / den;
  const glm::dvec3 p = o3 + t * d3;
  // The crack's own coordinates: q = s u + t v (u and v need not be orthogonal).
  const glm::dvec3 q = p - glm::dvec3(c.centre), u(c.u), v(c.v);
  const double uu = glm::dot(u, u), uv = glm::dot(u, v), vv = glm::dot(v, v);
  const double qu = glm::dot(q, u), qv = glm::dot(q, v), det = uu * vv - uv * uv;
  const double s = (qu * vv - qv * uv) / det, w = (qv * uu - qu * uv) / det;
  return t > 0.0 && std::abs(s) <= kCrackHalf && std::abs(w) <= kCrackHalf && std::abs(p.x) <= double(kHalf.x) &&
         std::abs(p.y) <= double(kHalf.y) && std::abs(p.z) <= double(kHalf.z);
}

// The clipping's own check: per pixel and crack, the GPU's kept bit against the analytic solid along the
// camera ray through the pixel centre; and the C++ bits against the GPU's.
struct CrackCounts {
  long kept = 0, analytic = 0, missed = 0, extra = 0, bitsDiffer = 0;
};

CrackCounts compareCracks(const IceGpu& w, const IceBuffers& b, const Image& gpuBits, const Image& cpuBits) {
  const int W = w.W, H = w.H;
  const glm::dmat4 worldFromClip = glm::inverse(glm::dmat4(w.clip));
  const glm::dmat4 boxFromWorld = glm::inverse(glm::dmat4(w.worldFromBox));
  const auto cs = cracks();
  CrackCounts n;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
      const int gpuMask = b.on[i] ? int(gpuBits.texels[i].x) : 0;
      n.bitsDiffer += b.on[i] && gpuBits.texels[i].x != cpuBits.texels[i].x;
      const glm::dvec2 ndc((x + 0.5) / W * 2.0 - 1.0, (y + 0.5) / H * 2.0 - 1.0);
      const glm::dvec4 far = worldFromClip * glm::dvec4(ndc, 1.0, 1.0);
      const glm::dvec3 eye(w.cam.position);
      const glm::dvec3 dir = glm::dvec3(far) / far.w - eye;
      // In box coordinates: origin and direction.
      const glm::dvec3 o3 = glm::dvec3(boxFromWorld * glm::dvec4(eye, 1.0));
      const glm::dvec3 d3 = glm::dvec3(boxFromWorld * glm::dvec4(dir, 0.0));
      for (int k = 0; k < GALLERY_CRACKS; ++k) {
        const bool inside = analyticCrackHit(cs[std::size_t(k)], o3, d3);
        const bool gpuKept = (gpuMask >> k) & 1;
        n.kept += gpuKept;
        n.analytic += inside;
        n.missed += inside && !gpuKept;
        n.extra += gpuKept && !inside;
      }
    }
  return n;
}

// One variant's row: the ice pass against C++, and with the cracks their clipping against the analytic
// solid; its render goes to `renders` for the picture.
Row measureVariant(const IceGpu& w, const IceBuffers& b, bool withCracks, const std::vector<double>& ms,
                   std::vector<Image>& renders) {
  w.icePass(withCracks);
  const Image gpuImage = w.outFb.readColor(0), gpuBits = w.outFb.readColor(1);
  Image cpuBits(w.W, w.H);
  const gpu::FrameComparison a = compare(gpuImage, shadeIceOnCpu(w, b, withCracks, &cpuBits), b.on);
  // the environment along the reflected and the refracted ray; depths and cracks from G-buffers
  Row r = makeRow("ice", withCracks ? "with cracks" : "no cracks", 2, ms[withCracks ? 2 : 1], ms[0], a);
  if (withCracks) {
    const CrackCounts n = compareCracks(w, b, gpuBits, cpuBits);
    r.check = "crack pixels kept " + std::to_string(n.kept) + ", analytic solid " + std::to_string(n.analytic) + ": " +
              std::to_string(n.missed) + " missed, " + std::to_string(n.extra) + " extra; C++ bits differ on " +
              std::to_string(n.bitsDiffer);
    r.metrics = {{"crack_kept", double(n.kept)},
                 {"crack_analytic", double(n.analytic)},
                 {"crack_missed", double(n.missed)},
                 {"crack_extra", double(n.extra)},
                 {"crack_bits_cpu_differ", double(n.bitsDiffer)}};
  } else {
    r.check = "-";
  }
  renders.push_back(gpuImage);
  return r;
}

// The picture: the block without and with the clipped cracks.
void saveIcePanel(const Options& o, const std::vector<Image>& renders, EffectResult& result) {
  savePanel(o, "ice.png", {{&renders[0], "ice block"}, {&renders[1], "with clipped cracks"}},
            "Front/back normal blend (a = 0.33), cubic Fresnel, environment reflection and refraction; four crack "
            "planes clipped by the front-back depth interval.",
            result);
}

}  // namespace

EffectResult runIce(const Gl& g, const Options& o) {
  const IceGpu w(g, o);
  renderBlockFaces(w);
  renderCrackDepths(w);
  const IceBuffers b = readIceBuffers(w);
  EffectResult result;
  const std::vector<double> ms = timeIce(w, o.timingRepeats);
  std::vector<Image> renders;  // per variant, its render
  for (bool withCracks : {false, true}) result.rows.push_back(measureVariant(w, b, withCracks, ms, renders));
  saveIcePanel(o, renders, result);
  return result;
}

}  // namespace snell::gallery
