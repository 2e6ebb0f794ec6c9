// The depth min/max pyramid (glsl/snell/intersect/depth_pyramid.glsl) built on
// the GPU: the reusable pass behind snell-lab's back-face and scene pyramids
// and the GL-vs-C++ pyramid test. One RGBA32F texture with its full mip chain;
// level 0 from a depth texture (snellDepthPyramidBase), each next level the 2x2
// reduction of the one before (snellDepthMinMaxReduce), one full-screen
// triangle per level through glsl/passes/depth_pyramid.frag (installed with
// the library's GLSL, share/snell/glsl), or a shader of your own with its
// uniforms. The result equals snell::snellBuildDepthPyramid bit for bit on
// every level (tests/gpu/depth_pyramid_gpu_test.cpp).
//
//   snell::gpu::DepthPyramidPass pass(gl, "/usr/local/share/snell/glsl");   // or the source tree's glsl/
//   snell::gpu::DepthPyramid pyramid(gl, width, height);
//   pass.build(pyramid, depthTexture, zNear, zFar, SNELL_DEPTH_GL, 0.0f);   // then bind pyramid.texture()
#pragma once
#include "error.hpp"
#include "include_flattener.hpp"
#include "program.hpp"
#include "resources.hpp"

#include <snell/bridge.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace snell::gpu {

// The pyramid's storage: every level of a GL_RGBA32F texture (sampled nearest
// within and between levels, clamp to edge) and one framebuffer per level.
class DepthPyramid {
 public:
  DepthPyramid(const GlApi& gl, int width, int height) : gl_(&gl) {
    if (width <= 0 || height <= 0)
      throw Error("DepthPyramid: size " + std::to_string(width) + "x" + std::to_string(height) + " is empty");
    GLuint id = 0;
    gl.GenTextures(1, &id);
    texture_ = GlHandle<detail::DeleteTexture>(gl, id);
    gl.BindTexture(GL_TEXTURE_2D, id);
    for (int w = width, h = height;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
      gl.TexImage2D(GL_TEXTURE_2D, static_cast<GLint>(sizes_.size()), GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
      sizes_.emplace_back(w, h);
      if (w == 1 && h == 1) break;
    }
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels() - 1);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    for (int lod = 0; lod < levels(); ++lod) fbos_.push_back(levelFramebuffer(gl, id, lod, "depth pyramid"));
    checkGl(gl, "depth pyramid allocation");
  }

  GLuint texture() const { return texture_.id(); }
  int levels() const { return static_cast<int>(sizes_.size()); }
  ivec2 size(int lod) const { return sizes_.at(static_cast<std::size_t>(lod)); }
  GLuint framebuffer(int lod) const { return fbos_.at(static_cast<std::size_t>(lod)).id(); }

  // One level, read back (glReadPixels from its framebuffer).
  snell::Image readLevel(int lod) const {
    return readLevelFramebuffer(*gl_, framebuffer(lod), size(lod), "DepthPyramid::readLevel");
  }

 private:
  const GlApi* gl_;
  GlHandle<detail::DeleteTexture> texture_;
  std::vector<GlHandle<detail::DeleteFramebuffer>> fbos_;
  std::vector<ivec2> sizes_;
};

class DepthPyramidPass {
 public:
  // The library's pass: passes/fullscreen.vert and passes/depth_pyramid.frag of
  // glslDir (snell's glsl/ folder, installed as share/snell/glsl), flattened
  // with glslDir on the include path. Error naming the file when one is missing.
  DepthPyramidPass(const GlApi& gl, const std::filesystem::path& glslDir)
      : DepthPyramidPass(gl, flattenGlslFile(glslDir / "passes" / "fullscreen.vert", {glslDir}),
                         flattenGlslFile(glslDir / "passes" / "depth_pyramid.frag", {glslDir})) {}

  // A pass of your own shaders: a full-screen vertex stage and a fragment
  // stage with depth_pyramid.frag's uniforms (for other depth hooks, say).
  DepthPyramidPass(const GlApi& gl, const FlatSource& vertex, const FlatSource& fragment)
      : gl_(&gl), program_(Program::graphics(gl, vertex, fragment)), vao_(gl) {}

  // Fills every level of `target` from depthTexture (level 0's size), whose texels are window depths in
  // `convention` with emptyDepth meaning "no surface". Leaves texture unit 0 unbound, depth test off.
  void build(const DepthPyramid& target, GLuint depthTexture, float zNear, float zFar, int convention,
             float emptyDepth) const {
    build(target, depthTexture, zNear, zFar, convention, emptyDepth, ivec4(0, 0, target.size(0)));
  }

  // The same, rewriting only what `region` (level-0 texels x in [region.x, region.z), y in [region.y,
  // region.w), clamped to the buffer) reduces into on every level: the texels of level L+1 whose children
  // (snellDepthMinMaxReduce's 2x2, 3 at an odd edge) include one rewritten on level L. The rest of every
  // level keeps what the last build left there, so the result is the whole build's when the depth texture
  // changed only inside `region` since then: an object's own buffers, drawn with a scissor around its
  // screen rectangle (and the rectangle it had in the previous frame). An empty region rewrites nothing.
  void build(const DepthPyramid& target, GLuint depthTexture, float zNear, float zFar, int convention,
             float emptyDepth, ivec4 region) const {
    const GlApi& gl = *gl_;
    region = ivec4(glm::max(ivec2(region.x, region.y), ivec2(0)), glm::min(ivec2(region.z, region.w), target.size(0)));
    if (region.z <= region.x || region.w <= region.y) return;
    gl.Enable(GL_SCISSOR_TEST);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_CULL_FACE);
    program_.use();
    vao_.bind();
    program_.set("zNear", zNear);
    program_.set("zFar", zFar);
    program_.set("convention", convention);
    program_.set("emptyDepth", emptyDepth);
    program_.set("sourceLod", 0);
    program_.setSampler("source", 0);
    gl.ActiveTexture(GL_TEXTURE0);
    for (int lod = 0; lod < target.levels(); ++lod) {
      gl.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer(lod));
      gl.Viewport(0, 0, target.size(lod).x, target.size(lod).y);
      if (lod > 0) region = parentRegion(region, target.size(lod));
      gl.Scissor(region.x, region.y, region.z - region.x, region.w - region.y);
      if (lod == 0) {
        gl.BindTexture(GL_TEXTURE_2D, depthTexture);
        program_.set("baseLevel", 1);
      } else {
        // Read level lod - 1 only: no feedback loop with the level being written.
        gl.BindTexture(GL_TEXTURE_2D, target.texture());
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, lod - 1);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, lod - 1);
        program_.set("baseLevel", 0);
      }
      gl.DrawArrays(GL_TRIANGLES, 0, 3);
    }
    gl.BindTexture(GL_TEXTURE_2D, target.texture());
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, target.levels() - 1);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.Disable(GL_SCISSOR_TEST);
    checkGl(gl, "depth pyramid pass");
  }

  // The texels of a level of `size` whose children include one of `child` (the level below's rewritten
  // texels): columns floor(x / 2) .. ceil(x1 / 2) - 1, the last column also for the odd edge's third child.
  static ivec4 parentRegion(ivec4 child, ivec2 size) {
    const ivec2 lo = glm::min(ivec2(child.x, child.y) / 2, size - 1);
    const ivec2 hi = glm::clamp((ivec2(child.z, child.w) + 1) / 2, lo + 1, size);
    return ivec4(lo, hi);
  }

 private:
  const GlApi* gl_;
  Program program_;
  VertexArray vao_;
};

}  // namespace snell::gpu
