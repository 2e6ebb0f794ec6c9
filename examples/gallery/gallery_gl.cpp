#include "gallery_gl.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <snell/gpu/include_flattener.hpp>

namespace snell::gallery {

void Soup::vertex(vec3 p, vec3 n, vec3 colour, float material, vec2 uv) {
  data.push_back(vec4(p, material));
  data.push_back(vec4(n, uv.x));
  data.push_back(vec4(colour, uv.y));
}

void Soup::quad(const vec3 (&c)[4], vec3 colour, float material) {
  const vec3 n = glm::normalize(glm::cross(c[1] - c[0], c[3] - c[0]));
  const vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i : {0, 1, 2, 0, 2, 3}) vertex(c[i], n, colour, material, uv[i]);
}

void Soup::box(vec3 lo, vec3 hi, vec3 colour, float material, const mat4& worldFromBox) {
  auto at = [&](float x, float y, float z) { return vec3(worldFromBox * vec4(x, y, z, 1.0f)); };
  const vec3 a = lo, b = hi;
  const vec3 faces[6][4] = {
      {at(b.x, a.y, a.z), at(b.x, b.y, a.z), at(b.x, b.y, b.z), at(b.x, a.y, b.z)},  // +x
      {at(a.x, a.y, b.z), at(a.x, b.y, b.z), at(a.x, b.y, a.z), at(a.x, a.y, a.z)},  // -x
      {at(a.x, b.y, b.z), at(b.x, b.y, b.z), at(b.x, b.y, a.z), at(a.x, b.y, a.z)},  // +y
      {at(a.x, a.y, a.z), at(b.x, a.y, a.z), at(b.x, a.y, b.z), at(a.x, a.y, b.z)},  // -y
      {at(a.x, a.y, b.z), at(b.x, a.y, b.z), at(b.x, b.y, b.z), at(a.x, b.y, b.z)},  // +z
      {at(b.x, a.y, a.z), at(a.x, a.y, a.z), at(a.x, b.y, a.z), at(b.x, b.y, a.z)},  // -z
  };
  for (const auto& f : faces) quad(f, colour, material);
}

Gl::Gl(const std::string& backend, const Options& options)
    : ctx_(gpu::parseBackend(backend)),
      vao_(ctx_.gl()),
      labGlsl_(options.labGlsl),
      snellGlsl_(options.snellGlsl),
      plain_(fullScreenProgram("gallery_plain.frag")),
      sky_(fullScreenProgram("gallery_sky.frag")),
      mask_(program("gallery_mesh.vert", "gallery_mask.frag")),
      gbuffer_(program("gallery_mesh.vert", "gallery_gbuffer.frag")) {}

std::string Gl::description() const {
  return std::string(gpu::backendName(ctx_.backend())) + ", " + ctx_.renderer() + ", OpenGL " + ctx_.version();
}

gpu::Program Gl::program(const std::string& vs, const std::string& fs) const {
  return gpu::Program::graphics(gl(), gpu::flattenGlslFile(labGlsl_ / vs, {snellGlsl_, labGlsl_}),
                                gpu::flattenGlslFile(labGlsl_ / fs, {snellGlsl_, labGlsl_}));
}

gpu::Program Gl::fullScreenProgram(const std::string& fs) const {
  return gpu::Program::graphics(gl(), gpu::flattenGlslFile(snellGlsl_ / "passes" / "fullscreen.vert", {snellGlsl_}),
                                gpu::flattenGlslFile(labGlsl_ / fs, {snellGlsl_, labGlsl_}));
}

gpu::StorageBuffer Gl::upload(const Soup& soup) const { return gpu::StorageBuffer(gl(), soup.data); }

void Gl::drawSoup(const gpu::StorageBuffer& buffer, int vertexCount) const {
  buffer.bindBase(0);
  drawArrays(vertexCount);
}

void Gl::fullscreen() const { drawArrays(3); }

void Gl::drawArrays(GLsizei count) const {
  vao_.bind();
  gl().DrawArrays(GL_TRIANGLES, 0, count);
}

void Gl::skyPass(const gpu::Framebuffer& target, const mat4& clip, vec3 eye, GLuint environment) const {
  for (int a = 0; a < 2; ++a) target.clearColor(a, vec4(0.0f));
  target.clearDepth(1.0f);
  target.bind();
  gl().Disable(GL_CULL_FACE);
  gl().Disable(GL_DEPTH_TEST);
  gl().DepthMask(GL_FALSE);
  sky_.set("worldFromClip", glm::inverse(clip));
  sky_.set("eye", eye);
  sky_.set("viewport", vec2(float(target.width()), float(target.height())));
  bindTextures({environment});
  sky_.use();
  fullscreen();
}

void Gl::maskPass(const gpu::StorageBuffer& soup, int vertexCount, const mat4& clip) const {
  gl().ColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  gl().ColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  gl().DepthMask(GL_FALSE);
  mask_.set("clipFromWorld", clip);
  mask_.set("clipPlane", vec4(0.0f, 0.0f, 0.0f, 1.0f));
  mask_.use();
  drawSoup(soup, vertexCount);
  gl().ColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl().ColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl().DepthMask(GL_TRUE);
}

void Gl::gbufferPass(const gpu::Framebuffer& target, float clearDepth, const gpu::StorageBuffer& soup, int vertexCount,
                     const mat4& clip, GLuint occluderDepth) const {
  for (int a = 0; a < 3; ++a) target.clearColor(a, vec4(0.0f));
  target.clearDepth(clearDepth);
  target.bind();
  gbuffer_.set("clipFromWorld", clip);
  gbuffer_.set("clipPlane", vec4(0.0f, 0.0f, 0.0f, 1.0f));
  bindTextures({occluderDepth});
  gbuffer_.use();
  drawSoup(soup, vertexCount);
}

void Gl::plainPass(const gpu::Framebuffer& target, GLuint texture) const {
  target.bind();
  gl().Disable(GL_DEPTH_TEST);
  plain_.set("viewport", vec2(float(target.width()), float(target.height())));
  bindTextures({texture});
  plain_.use();
  fullscreen();
}

void Gl::bindTextures(std::initializer_list<GLuint> textures) const {
  GLenum unit = 0;
  for (GLuint t : textures) {
    gl().ActiveTexture(GL_TEXTURE0 + unit++);
    gl().BindTexture(GL_TEXTURE_2D, t);
  }
  gl().ActiveTexture(GL_TEXTURE0);
}

void Gl::setFilter(GLuint texture, GLint filter) const {
  gl().BindTexture(GL_TEXTURE_2D, texture);
  gl().TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  gl().TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  gl().BindTexture(GL_TEXTURE_2D, 0);
}

std::vector<double> Gl::timeInterleaved(const std::vector<std::function<void()>>& passes, int rounds) const {
  std::vector<std::vector<double>> ms(passes.size());
  // One untimed round first: llvmpipe compiles a program's shaders at its first draw.
  for (const auto& pass : passes) pass();
  for (int r = 0; r < std::max(1, rounds); ++r)
    for (std::size_t i = 0; i < passes.size(); ++i) {
      gl().Finish();
      const auto t0 = std::chrono::steady_clock::now();
      passes[i]();
      gl().Finish();
      ms[i].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
  std::vector<double> median;
  for (auto& m : ms) {
    std::sort(m.begin(), m.end());
    median.push_back(m[m.size() / 2]);
  }
  gpu::checkGl(gl(), "timed passes");
  return median;
}

lab::Camera camera(vec3 eye, vec3 target, float fovYDegrees, const Options& options) {
  lab::Camera c;
  c.position = eye;
  c.target = target;
  c.fovYDegrees = fovYDegrees;
  c.width = options.width;
  c.height = options.height;
  return c;
}

mat4 clipFromWorld(const lab::Camera& camera) { return camera.clipFromView() * camera.viewFromWorld(); }

Texture2D texture(Image image, Filter filter) { return Texture2D(std::move(image), filter); }

gpu::FrameComparison compare(const Image& gpuImage, const Image& cpuImage, const std::vector<bool>& on) {
  const std::size_t w = std::size_t(gpuImage.width);
  return gpu::compareFrames(gpuImage, cpuImage,
                            [&](int x, int y) { return on.at(std::size_t(y) * w + std::size_t(x)); });
}

}  // namespace snell::gallery
