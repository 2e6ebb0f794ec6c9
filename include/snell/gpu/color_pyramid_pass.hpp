// The colour pyramid for rough reads (glsl/snell/shade/color_pyramid.glsl)
// built on the GPU: levels 1, 2, ... of an RGBA32F colour texture, each the
// tent reduce of the one below, one full-screen triangle per level through
// glsl/passes/color_pyramid.frag (installed with the library's GLSL,
// share/snell/glsl). What the rough cone's reads expect in place of
// glGenerateMipmap's box chain (rough_cone.glsl); the result equals
// snell::snellBuildColorPyramid on every level to float rounding
// (tests/gpu/color_pyramid_gpu_test.cpp).
//
//   snell::gpu::ColorPyramidPass pass(gl, "/usr/local/share/snell/glsl");   // or the source tree's glsl/
//   snell::gpu::ColorPyramid pyramid(gl, sceneColorTexture, width, height);  // once
//   pass.build(pyramid);   // after each draw into level 0, before the rough reads
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

// The levels above level 0 of an existing GL_TEXTURE_2D whose level 0 is RGBA32F of width x height (a render
// target's colour, say; it stays the caller's): allocates levels 1 .. down to 1x1 as RGBA32F (replacing what
// they held), a framebuffer for each, and sets the texture to trilinear filtering over the whole chain, clamp
// to edge. Error when the texture's level 0 is not RGBA32F of that size (the chain would be incomplete and
// read as black). The texture must outlive the pyramid; the active unit's 2D binding is restored.
class ColorPyramid {
 public:
  ColorPyramid(const GlApi& gl, GLuint texture, int width, int height) : gl_(&gl), texture_(texture) {
    if (width <= 0 || height <= 0)
      throw Error("ColorPyramid: size " + std::to_string(width) + "x" + std::to_string(height) + " is empty");
    if (texture == 0) throw Error("ColorPyramid: texture 0 is not a texture");
    const detail::BindingRestorer restore(gl);
    gl.BindTexture(GL_TEXTURE_2D, texture);
    GLint format = 0, w0 = 0, h0 = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w0);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h0);
    checkGl(gl, "ColorPyramid: texture " + std::to_string(texture) + " (glBindTexture, level 0's size and format)");
    if (format != GL_RGBA32F || w0 != width || h0 != height)
      throw Error("ColorPyramid: texture " + std::to_string(texture) + "'s level 0 is " + std::to_string(w0) + "x" +
                  std::to_string(h0) + (format == GL_RGBA32F ? " RGBA32F" : " not RGBA32F") + ", not " +
                  std::to_string(width) + "x" + std::to_string(height) + " RGBA32F");
    sizes_.emplace_back(width, height);
    for (int w = width, h = height; w > 1 || h > 1;) {
      w = std::max(1, w / 2);
      h = std::max(1, h / 2);
      gl.TexImage2D(GL_TEXTURE_2D, static_cast<GLint>(sizes_.size()), GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
      sizes_.emplace_back(w, h);
    }
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels() - 1);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    checkGl(gl, "colour pyramid levels (glTexImage2D, " + std::to_string(width) + "x" + std::to_string(height) +
                    " level 0)");
    for (int lod = 1; lod < levels(); ++lod) fbos_.push_back(levelFramebuffer(gl, texture, lod, "colour pyramid"));
  }

  GLuint texture() const { return texture_; }
  int levels() const { return static_cast<int>(sizes_.size()); }
  ivec2 size(int lod) const { return sizes_.at(static_cast<std::size_t>(lod)); }
  // The framebuffer that draws into level lod (1 .. levels() - 1).
  GLuint framebuffer(int lod) const { return fbos_.at(static_cast<std::size_t>(lod - 1)).id(); }

  // One level above level 0, read back (glReadPixels from its framebuffer).
  snell::Image readLevel(int lod) const {
    return readLevelFramebuffer(*gl_, framebuffer(lod), size(lod), "ColorPyramid::readLevel");
  }

 private:
  const GlApi* gl_;
  GLuint texture_;
  std::vector<GlHandle<detail::DeleteFramebuffer>> fbos_;
  std::vector<ivec2> sizes_;
};

class ColorPyramidPass {
 public:
  // The library's pass: passes/fullscreen.vert and passes/color_pyramid.frag of glslDir (snell's glsl/
  // folder, installed as share/snell/glsl), flattened with glslDir on the include path. Error naming the
  // file when one is missing.
  ColorPyramidPass(const GlApi& gl, const std::filesystem::path& glslDir)
      : ColorPyramidPass(gl, flattenGlslFile(glslDir / "passes" / "fullscreen.vert", {glslDir}),
                         flattenGlslFile(glslDir / "passes" / "color_pyramid.frag", {glslDir})) {}

  // A pass of your own shaders: a full-screen vertex stage and a fragment stage with color_pyramid.frag's
  // uniforms.
  ColorPyramidPass(const GlApi& gl, const FlatSource& vertex, const FlatSource& fragment)
      : gl_(&gl), program_(Program::graphics(gl, vertex, fragment)), vao_(gl) {}

  // Fills levels 1 .. of `target` from its level 0, each from the one below. Each draw reads only the level
  // below the one it writes (the texture's base and max level both set to it), so no level is read and
  // written at once. Leaves the whole chain selectable, texture unit 0 active with nothing bound, framebuffer
  // 0 bound, the viewport at the top level, depth test, scissor, culling and blending off, and the pass's
  // program and vertex array bound.
  void build(const ColorPyramid& target) const {
    const GlApi& gl = *gl_;
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    program_.use();
    vao_.bind();
    program_.set("sourceLod", 0);
    program_.setSampler("source", 0);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, target.texture());
    for (int lod = 1; lod < target.levels(); ++lod) {
      gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, lod - 1);
      gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, lod - 1);
      gl.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer(lod));
      gl.Viewport(0, 0, target.size(lod).x, target.size(lod).y);
      gl.DrawArrays(GL_TRIANGLES, 0, 3);
    }
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, target.levels() - 1);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl(gl, "colour pyramid pass");
  }

 private:
  const GlApi* gl_;
  Program program_;
  VertexArray vao_;
};

}  // namespace snell::gpu
