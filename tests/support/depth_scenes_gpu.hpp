// Renders a snell_test::DepthScene on the GL driver: a full-screen triangle whose
// fragment shader (tests/support/depth_scenes.frag) evaluates the same analytic
// surface per pixel in float and writes gl_FragDepth and the normal, into a
// DEPTH_COMPONENT32F + RGBA32F framebuffer cleared to the scene's emptyDepth.
// The result is a real GL depth buffer of the scene (for the GPU-vs-CPU test).
#pragma once

#include <snell/gpu/context.hpp>
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>

#include <filesystem>
#include <string>

#include "depth_scenes.hpp"

namespace snell_test {

struct GpuSceneBuffers {
  snell::Image depth;    // depth in x
  snell::Image normals;  // normal xyz, w = 1 where covered
};

inline GpuSceneBuffers renderDepthSceneGpu(const snell::gpu::Context& ctx, const DepthScene& sc) {
  using namespace snell::gpu;
  ctx.makeCurrent();
  const GlApi& gl = ctx.gl();
  const std::filesystem::path dir = std::filesystem::path(SNELL_SOURCE_DIR) / "tests" / "support";
  const std::filesystem::path fullscreen = std::filesystem::path(SNELL_SOURCE_DIR) / "glsl" / "passes" / "fullscreen.vert";
  const Program program =
      Program::graphics(gl, flattenGlslFile(fullscreen, {}), flattenGlslFile(dir / "depth_scenes.frag", {dir}));
  Framebuffer fb(gl, sc.width, sc.height, 1, true);
  fb.clearColor(0, glm::vec4(0.0f));
  fb.clearDepth(sc.emptyDepth);
  fb.bind();
  auto setIf = [&](const std::string& name, auto v) {
    if (program.hasUniform(name)) program.set(name, v);
  };
  setIf("sceneKind", sc.kind);
  for (int i = 0; i < 4; ++i) setIf("sceneParams[" + std::to_string(i) + "]", sc.params[i]);
  setIf("tanHalf", glm::vec2(float(sc.tanHalfX), float(sc.tanHalfY)));
  setIf("viewport", glm::vec2(float(sc.width), float(sc.height)));
  setIf("zNear", sc.zNear);
  setIf("zFar", sc.zFar);
  setIf("convention", sc.convention);
  VertexArray vao(gl);
  vao.bind();
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_ALWAYS);
  gl.DepthMask(GL_TRUE);
  program.use();
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.Disable(GL_DEPTH_TEST);
  checkGl(gl, "renderDepthSceneGpu draw");
  GpuSceneBuffers out;
  out.depth = fb.readDepth();
  out.normals = fb.readColor(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  return out;
}

}  // namespace snell_test
