// The gallery's GL plumbing on one context: programs from the gallery's and
// the library's GLSL, world-space triangle soups pulled by gl_VertexID, the
// full-screen triangle, texture binding and interleaved wall-clock timing
// (glFinish on both sides: timer queries mean nothing on llvmpipe).
#pragma once
#include <functional>
#include <initializer_list>
#include <snell/gpu/context.hpp>
#include <snell/gpu/frame_compare.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>
#include <string>
#include <vector>

#include "gallery.hpp"
#include "lab/camera.hpp"

namespace snell::gallery {

// Triangles in world space, three vec4 per vertex (gallery_mesh.vert):
// position + material, normal + u, colour + v.
struct Soup {
  std::vector<vec4> data;
  void vertex(vec3 p, vec3 n, vec3 colour, float material, vec2 uv);
  // Corners counter-clockwise seen from the side the normal points to; uv (0,0) (1,0) (1,1) (0,1).
  void quad(const vec3 (&c)[4], vec3 colour, float material);
  // An axis-aligned box, or one turned by `worldFromBox` (a rigid transform) when given.
  void box(vec3 lo, vec3 hi, vec3 colour, float material = 0.0f, const mat4& worldFromBox = mat4(1.0f));
  int vertexCount() const { return static_cast<int>(data.size() / 3); }
};

class Gl {
 public:
  Gl(const std::string& backend, const Options& options);
  const gpu::GlApi& gl() const { return ctx_.gl(); }
  std::string description() const;

  // vs/fs: file names under examples/glsl (the library's glsl/ is on the include path too).
  gpu::Program program(const std::string& vs, const std::string& fs) const;
  // `fs` over the whole viewport, with the library's full-screen vertex stage (glsl/passes/fullscreen.vert).
  gpu::Program fullScreenProgram(const std::string& fs) const;

  // A soup's storage buffer (binding 0 for gallery_mesh.vert).
  gpu::StorageBuffer upload(const Soup& soup) const;
  void drawSoup(const gpu::StorageBuffer& buffer, int vertexCount) const;
  void fullscreen() const;
  // glDrawArrays(GL_TRIANGLES, 0, count) with the gallery's vertex array bound (vertex pulling).
  void drawArrays(GLsizei count) const;
  // Clears `target` (colours 0, depth 1) and draws the environment behind everything along each pixel's
  // world ray (gallery_sky.frag), depth untouched; leaves depth testing, depth writes and culling off.
  void skyPass(const gpu::Framebuffer& target, const mat4& clipFromWorld, vec3 eye, GLuint environment) const;
  // Sousa's refraction mask: the soup (a refracting surface) writes alpha 0 into attachments 0 and 1 of the
  // bound scene framebuffer where it is visible (depth-tested, no depth writes, colours masked off).
  void maskPass(const gpu::StorageBuffer& soup, int vertexCount, const mat4& clipFromWorld) const;
  // A refracting surface's G-buffer (gallery_gbuffer.frag) into `target`: cleared to 0 and to `clearDepth`,
  // hidden where `occluderDepth` lies in front. Depth test and culling are the caller's.
  void gbufferPass(const gpu::Framebuffer& target, float clearDepth, const gpu::StorageBuffer& soup, int vertexCount,
                   const mat4& clipFromWorld, GLuint occluderDepth) const;
  // The cost yardstick: one bilinear read of `texture` per pixel of `target` (gallery_plain.frag).
  void plainPass(const gpu::Framebuffer& target, GLuint texture) const;
  // Binds texture names to units 0, 1, ...
  void bindTextures(std::initializer_list<GLuint> textures) const;
  void setFilter(GLuint texture, GLint filter) const;

  // After one untimed round, `rounds` rounds of `passes`: glFinish, steady clock, pass, glFinish per pass.
  // Returns each pass's median over the rounds, in ms, the passes interleaved.
  std::vector<double> timeInterleaved(const std::vector<std::function<void()>>& passes, int rounds) const;

 private:
  gpu::Context ctx_;
  gpu::VertexArray vao_;
  std::filesystem::path labGlsl_, snellGlsl_;
  gpu::Program plain_, sky_, mask_, gbuffer_;
};

// A camera at `eye` looking at `target` with a vertical field of view in degrees, at the options' size.
lab::Camera camera(vec3 eye, vec3 target, float fovYDegrees, const Options& options);
mat4 clipFromWorld(const lab::Camera& camera);

// A texture of one Image with the filter both sides read it with.
Texture2D texture(Image image, Filter filter);
// The whole-frame comparison (snell/gpu/frame_compare.hpp) over the pixels where `on` is set.
gpu::FrameComparison compare(const Image& gpuImage, const Image& cpuImage, const std::vector<bool>& on);

}  // namespace snell::gallery
