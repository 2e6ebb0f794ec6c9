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

}  // namespace

EffectResult runIce(const Gl& g, const Options& o) {
  const gpu::GlApi& gl = g.gl();
  const int W = o.width, H = o.height;
  const lab::Camera cam = camera(vec3(0.0f, 0.7f, 4.3f), vec3(0.0f, 0.0f, 0.0f), 45.0f, o);
  const mat4 clip = clipFromWorld(cam);
  const mat4 worldFromBox = blockTransform();

  const Texture2D envTex = texture(environmentImage(256), Filter::Linear);
  gpu::Texture envGl(gl, envTex);
  Soup block;
  block.box(-kHalf, kHalf, vec3(1.0f), 0.0f, worldFromBox);
  gpu::StorageBuffer blockBuf = g.upload(block);
  std::vector<Soup> crackSoups;
  std::vector<gpu::StorageBuffer> crackBufs;
  for (const Crack& c : cracks()) {
    Soup s;
    auto at = [&](float a, float b) {
      return vec3(worldFromBox * vec4(c.centre + float(kCrackHalf) * (a * c.u + b * c.v), 1.0f));
    };
    const vec3 q[4] = {at(-1, -1), at(1, -1), at(1, 1), at(-1, 1)};
    s.quad(q, vec3(0.0f), 0.0f);
    crackBufs.push_back(g.upload(s));
    crackSoups.push_back(s);
  }

  gpu::Program crack = g.program("gallery_mesh.vert", "gallery_crack.frag");
  gpu::Program ice = g.program("lab_fullscreen.vert", "gallery_ice.frag");
  gpu::Framebuffer sceneFb(gl, W, H, 2, true), frontFb(gl, W, H, 3, true), backFb(gl, W, H, 3, true),
      crackFb(gl, W, H, 4, false), outFb(gl, W, H, 2, false);
  g.setFilter(sceneFb.colorTexture(0), GL_LINEAR);

  // (1) The environment behind the block.
  g.skyPass(sceneFb, clip, cam.position, envGl.id());
  gl.DepthMask(GL_TRUE);
  // (2) Front faces (depth LESS) and back faces (front culled, depth GREATER from 0).
  for (int side = 0; side < 2; ++side) {
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(side == 0 ? GL_LESS : GL_GREATER);
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(side == 0 ? GL_BACK : GL_FRONT);
    g.gbufferPass(side == 0 ? frontFb : backFb, side == 0 ? 1.0f : 0.0f, blockBuf, block.vertexCount(), clip,
                  sceneFb.depthTexture());
  }
  gl.CullFace(GL_BACK);
  gl.Disable(GL_CULL_FACE);
  gl.DepthFunc(GL_LESS);
  // (3) Each crack's depth into its own attachment (2: no crack at the pixel).
  for (int k = 0; k < GALLERY_CRACKS; ++k) crackFb.clearColor(k, vec4(2.0f, 0.0f, 0.0f, 0.0f));
  crackFb.bind();
  gl.Disable(GL_DEPTH_TEST);
  crack.set("clipFromWorld", clip);
  crack.set("clipPlane", vec4(0.0f, 0.0f, 0.0f, 1.0f));
  crack.use();
  for (int k = 0; k < GALLERY_CRACKS; ++k) {
    for (int a = 0; a < GALLERY_CRACKS; ++a) {
      const GLboolean w = a == k ? GL_TRUE : GL_FALSE;
      gl.ColorMaski(GLuint(a), w, w, w, w);
    }
    g.drawSoup(crackBufs[std::size_t(k)], crackSoups[std::size_t(k)].vertexCount());
  }
  for (int a = 0; a < GALLERY_CRACKS; ++a) gl.ColorMaski(GLuint(a), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gpu::checkGl(gl, "ice passes");

  auto icePass = [&](bool withCracks) {
    outFb.bind();
    gl.Disable(GL_DEPTH_TEST);
    ice.set("eye", cam.position);
    ice.set("withCracks", withCracks ? 1 : 0);
    g.bindTextures({frontFb.colorTexture(0), frontFb.colorTexture(1), backFb.colorTexture(0), backFb.colorTexture(1),
                    crackFb.colorTexture(0), crackFb.colorTexture(1), crackFb.colorTexture(2), crackFb.colorTexture(3),
                    envGl.id(), sceneFb.colorTexture(0)});
    ice.use();
    g.fullscreen();
  };
  auto plainPass = [&] { g.plainPass(outFb, sceneFb.colorTexture(0)); };

  const Image fN = frontFb.readColor(0), fW = frontFb.readColor(1), bN = backFb.readColor(0), bW = backFb.readColor(1);
  std::array<Image, GALLERY_CRACKS> cD;
  for (int k = 0; k < GALLERY_CRACKS; ++k) cD[std::size_t(k)] = crackFb.readColor(k);
  std::vector<bool> on(fN.texels.size());
  for (std::size_t i = 0; i < on.size(); ++i) on[i] = fN.texels[i].w != 0.0f;
  auto cpuIce = [&](bool withCracks, Image* bits) {
    Image out(W, H);
    for (std::size_t i = 0; i < on.size(); ++i) {
      if (!on[i]) continue;
      const vec4 cd(cD[0].texels[i].x, cD[1].texels[i].x, cD[2].texels[i].x, cD[3].texels[i].x);
      const GalleryIce r = galleryIce(vec3(fN.texels[i]), vec3(bN.texels[i]), vec3(fW.texels[i]), cam.position,
                                      fW.texels[i].w, bW.texels[i].w, cd, withCracks, envTex);
      out.texels[i] = r.color;
      if (bits) bits->texels[i] = vec4(float(r.cracks), 0.0f, 0.0f, 0.0f);
    }
    return out;
  };

  EffectResult result;
  const std::vector<double> ms =
      g.timeInterleaved({plainPass, [&] { icePass(false); }, [&] { icePass(true); }}, o.timingRepeats);
  // The analytic solid: for each pixel centre, the camera ray against crack plane k (double precision),
  // kept when the hit lies inside the crack square and inside the box.
  const glm::dmat4 worldFromClip = glm::inverse(glm::dmat4(clip));
  const glm::dmat4 boxFromWorld = glm::inverse(glm::dmat4(worldFromBox));
  const auto cs = cracks();
  std::vector<Image> renders;
  for (bool withCracks : {false, true}) {
    icePass(withCracks);
    const Image gpuImage = outFb.readColor(0), gpuBits = outFb.readColor(1);
    Image cpuBits(W, H);
    const gpu::FrameComparison a = compare(gpuImage, cpuIce(withCracks, &cpuBits), on);
    // the environment along the reflected and the refracted ray; depths and cracks from G-buffers
    Row r = makeRow("ice", withCracks ? "with cracks" : "no cracks", 2, ms[withCracks ? 2 : 1], ms[0], a);
    if (withCracks) {
      long kept = 0, analytic = 0, missed = 0, extra = 0, bitsDiffer = 0;
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
          const int gpuMask = on[i] ? int(gpuBits.texels[i].x) : 0;
          bitsDiffer += on[i] && gpuBits.texels[i].x != cpuBits.texels[i].x;
          const glm::dvec2 ndc((x + 0.5) / W * 2.0 - 1.0, (y + 0.5) / H * 2.0 - 1.0);
          const glm::dvec4 far = worldFromClip * glm::dvec4(ndc, 1.0, 1.0);
          const glm::dvec3 eye(cam.position);
          const glm::dvec3 dir = glm::dvec3(far) / far.w - eye;
          // In box coordinates: origin and direction.
          const glm::dvec3 o3 = glm::dvec3(boxFromWorld * glm::dvec4(eye, 1.0));
          const glm::dvec3 d3 = glm::dvec3(boxFromWorld * glm::dvec4(dir, 0.0));
          for (int k = 0; k < GALLERY_CRACKS; ++k) {
            const Crack& c = cs[std::size_t(k)];
            const glm::dvec3 n = glm::cross(glm::dvec3(c.u), glm::dvec3(c.v));
            const double den = glm::dot(n, d3);
            bool inside = false;
            if (den != 0.0) {
              const double t = glm::dot(n, glm::dvec3(c.centre) - o3) / den;
              const glm::dvec3 p = o3 + t * d3;
              // The crack's own coordinates: q = s u + t v (u and v need not be orthogonal).
              const glm::dvec3 q = p - glm::dvec3(c.centre), u(c.u), v(c.v);
              const double uu = glm::dot(u, u), uv = glm::dot(u, v), vv = glm::dot(v, v);
              const double qu = glm::dot(q, u), qv = glm::dot(q, v), det = uu * vv - uv * uv;
              const double s = (qu * vv - qv * uv) / det, w = (qv * uu - qu * uv) / det;
              inside = t > 0.0 && std::abs(s) <= kCrackHalf && std::abs(w) <= kCrackHalf &&
                       std::abs(p.x) <= double(kHalf.x) && std::abs(p.y) <= double(kHalf.y) &&
                       std::abs(p.z) <= double(kHalf.z);
            }
            const bool gpuKept = (gpuMask >> k) & 1;
            kept += gpuKept;
            analytic += inside;
            missed += inside && !gpuKept;
            extra += gpuKept && !inside;
          }
        }
      r.check = "crack pixels kept " + std::to_string(kept) + ", analytic solid " + std::to_string(analytic) + ": " +
                std::to_string(missed) + " missed, " + std::to_string(extra) + " extra; C++ bits differ on " +
                std::to_string(bitsDiffer);
      r.metrics = {{"crack_kept", double(kept)},
                   {"crack_analytic", double(analytic)},
                   {"crack_missed", double(missed)},
                   {"crack_extra", double(extra)},
                   {"crack_bits_cpu_differ", double(bitsDiffer)}};
    } else {
      r.check = "-";
    }
    result.rows.push_back(r);
    renders.push_back(gpuImage);
  }
  savePanel(o, "ice.png", {{&renders[0], "ice block"}, {&renders[1], "with clipped cracks"}},
            "Front/back normal blend (a = 0.33), cubic Fresnel, environment reflection and refraction; four crack "
            "planes clipped by the front-back depth interval.",
            result);
  return result;
}

}  // namespace snell::gallery
