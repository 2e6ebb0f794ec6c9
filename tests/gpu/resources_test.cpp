// Round trips through the GPU resources: what goes up must come back bit for
// bit, in snell's layout (bottom row first, all mip levels, std430 vec4).
#include <snell/gpu/context.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using snell::gpu::Context;
using snell::gpu::Error;
using snell::gpu::flattenGlslSource;
using snell::gpu::Program;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Texel value that encodes where it came from, exact in float.
glm::vec4 tag(int x, int y, int lod) {
  return glm::vec4(static_cast<float>(x), static_cast<float>(y), static_cast<float>(lod),
                   static_cast<float>(x + 16 * y + 256 * lod) * 0.25f);
}

snell::Texture2D taggedTexture(int w, int h) {
  snell::Texture2D tex(snell::Image(w, h), snell::Filter::Linear, snell::MipFilter::Linear);
  tex.generateMipmaps();
  for (int lod = 0; lod < tex.levelCount(); ++lod) {
    snell::Image& img = tex.level(lod);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) img.at(x, y) = tag(x, y, lod);
  }
  return tex;
}

TEST(Resources, StorageBufferRoundTripKeepsEveryBit) {
  Context ctx;
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<glm::vec4> data = {
      {0.0f, -0.0f, 1.0f, -1.0f},
      {inf, -inf, std::numeric_limits<float>::quiet_NaN(), 1e-44f},  // NaN and a denormal survive a plain copy
      {3.4028235e38f, 1.17549435e-38f, 0.1f, 12345.678f}};
  snell::gpu::StorageBuffer buffer(ctx.gl(), data);
  EXPECT_EQ(buffer.size(), data.size() * sizeof(glm::vec4));
  const std::vector<glm::vec4> back = buffer.downloadVec4();
  ASSERT_EQ(back.size(), data.size());
  for (std::size_t i = 0; i < data.size(); ++i)
    for (int k = 0; k < 4; ++k) EXPECT_TRUE(sameBits(back[i][k], data[i][k])) << i << "," << k;

  // Through a shader: out[i] = in[i] * 2 + 1, exact for these values.
  const std::vector<float> in = {0.0f, 1.5f, -3.0f, 1024.0f, 0.25f};
  snell::gpu::StorageBuffer src(ctx.gl()), dst(ctx.gl());
  src.upload(in);
  dst.allocate(in.size() * sizeof(float));
  src.bindBase(0);
  dst.bindBase(1);
  const Program p = Program::compute(ctx.gl(), flattenGlslSource(R"(#version 430 core
layout(local_size_x = 8) in;
layout(std430, binding = 0) readonly buffer In { float a[]; };
layout(std430, binding = 1) writeonly buffer Out { float b[]; };
void main() { uint i = gl_GlobalInvocationID.x; if (i < uint(a.length())) b[i] = a[i] * 2.0 + 1.0; }
)", "double.comp", {}));
  p.dispatch(1);
  ctx.gl().MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<float> out = dst.downloadFloats();
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) EXPECT_EQ(out[i], in[i] * 2.0f + 1.0f) << i;

  EXPECT_THROW(dst.download(nullptr, 4, out.size() * sizeof(float)), Error);  // past the end
}

// A host struct laid out as std140 (vec3 + float pairs) reaches the shader
// field by field through UniformBuffer, and requireUniformBlock rejects a
// missing block, another size and another binding.
TEST(Resources, UniformBufferCarriesAStd140HostStruct) {
  Context ctx;
  struct Host {
    glm::mat4 m;
    glm::vec3 a;
    float b;
    glm::vec3 c;
    int d;
  };
  static_assert(sizeof(Host) == 96, "std140: mat4 64, vec3 at 64, float at 76, vec3 at 80, int at 92");
  Host h{};
  h.m = glm::mat4(2.0f);
  h.m[3] = glm::vec4(1.0f, 2.0f, 3.0f, 1.0f);
  h.a = glm::vec3(0.5f, -1.5f, 8.0f);
  h.b = 7.25f;
  h.c = glm::vec3(-3.0f, 4.0f, 1e-3f);
  h.d = -42;
  snell::gpu::UniformBuffer ubo(ctx.gl(), &h, sizeof h);
  snell::gpu::StorageBuffer out(ctx.gl());
  out.allocate(4 * sizeof(glm::vec4));
  const Program p = Program::compute(ctx.gl(), flattenGlslSource(R"(#version 450 core
layout(local_size_x = 1) in;
struct Host { mat4 m; vec3 a; float b; vec3 c; int d; };
layout(std140, binding = 2) uniform HostBlock { Host h; };
layout(std430, binding = 1) writeonly buffer Out { vec4 o[]; };
void main() {
  o[0] = h.m * vec4(1.0, 1.0, 1.0, 1.0);
  o[1] = vec4(h.a, h.b);
  o[2] = vec4(h.c, float(h.d));
  o[3] = vec4(0.0);
}
)", "ubo.comp", {}));
  p.requireUniformBlock("HostBlock", 2, sizeof h);
  EXPECT_THROW(p.requireUniformBlock("Missing", 2, sizeof h), Error);
  EXPECT_THROW(p.requireUniformBlock("HostBlock", 2, sizeof h + 16), Error);
  EXPECT_THROW(p.requireUniformBlock("HostBlock", 1, sizeof h), Error);
  ubo.bindBase(2);
  out.bindBase(1);
  p.dispatch(1);
  ctx.gl().MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::vec4> o = out.downloadVec4();
  EXPECT_EQ(o[0], glm::vec4(3.0f, 4.0f, 5.0f, 1.0f));  // 2 I with column 3 = (1, 2, 3, 1), times (1, 1, 1, 1)
  EXPECT_EQ(o[1], glm::vec4(0.5f, -1.5f, 8.0f, 7.25f));
  EXPECT_EQ(o[2], glm::vec4(-3.0f, 4.0f, 1e-3f, -42.0f));
}

TEST(Resources, TextureRoundTripAllMipLevels) {
  Context ctx;
  const snell::Texture2D tex = taggedTexture(8, 4);  // 8x4, 4x2, 2x1, 1x1
  ASSERT_EQ(tex.levelCount(), 4);
  const snell::gpu::Texture gpuTex(ctx.gl(), tex);
  EXPECT_EQ(gpuTex.levelCount(), 4);

  // One invocation per (x, y, lod) slot of an 8x4x4 grid; slots outside a level write sizes only.
  const Program p = Program::compute(ctx.gl(), flattenGlslSource(R"(#version 450 core
layout(local_size_x = 8, local_size_y = 4, local_size_z = 1) in;
layout(std430, binding = 0) writeonly buffer Out { vec4 texel[]; };
layout(std430, binding = 1) writeonly buffer Sizes { ivec4 size[]; };
uniform sampler2D tex;
void main() {
  ivec3 g = ivec3(gl_GlobalInvocationID);
  ivec2 s = textureSize(tex, g.z);
  uint slot = uint(g.x + 8 * g.y + 32 * g.z);
  if (g.x == 0 && g.y == 0) size[g.z] = ivec4(s, 0, 0);
  texel[slot] = (g.x < s.x && g.y < s.y) ? texelFetch(tex, g.xy, g.z) : vec4(-1.0);
}
)", "fetch.comp", {}));
  snell::gpu::StorageBuffer texels(ctx.gl()), sizes(ctx.gl());
  texels.allocate(8 * 4 * 4 * sizeof(glm::vec4));
  sizes.allocate(4 * sizeof(glm::ivec4));
  texels.bindBase(0);
  sizes.bindBase(1);
  gpuTex.bind(2);
  p.setSampler("tex", 2);
  p.dispatch(1, 1, 4);
  ctx.gl().MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

  std::vector<glm::ivec4> gotSizes(4);
  sizes.download(gotSizes.data(), gotSizes.size() * sizeof(glm::ivec4));
  const std::vector<glm::vec4> got = texels.downloadVec4();
  for (int lod = 0; lod < 4; ++lod) {
    EXPECT_EQ(gotSizes[static_cast<std::size_t>(lod)].x, tex.size(lod).x) << "lod " << lod;
    EXPECT_EQ(gotSizes[static_cast<std::size_t>(lod)].y, tex.size(lod).y) << "lod " << lod;
    for (int y = 0; y < tex.size(lod).y; ++y)
      for (int x = 0; x < tex.size(lod).x; ++x) {
        const glm::vec4 g = got[static_cast<std::size_t>(x + 8 * y + 32 * lod)];
        const glm::vec4 e = tex.fetch(glm::ivec2(x, y), lod);
        EXPECT_EQ(g, e) << "lod " << lod << " texel " << x << "," << y;
      }
  }
}

TEST(Resources, CreatingATextureKeepsEarlierBindings) {
  Context ctx;
  const snell::Texture2D a(snell::Image(2, 2, glm::vec4(1.0f, 2.0f, 3.0f, 4.0f)));
  const snell::Texture2D b(snell::Image(2, 2, glm::vec4(5.0f, 6.0f, 7.0f, 8.0f)));
  const snell::gpu::Texture ga(ctx.gl(), a);
  ga.bind(0);
  const snell::gpu::Texture gb(ctx.gl(), b);  // uploads through unit 0, must not unbind `ga`
  gb.bind(1);
  const snell::gpu::Framebuffer unused(ctx.gl(), 2, 2);  // its attachments too
  const Program p = Program::compute(ctx.gl(), flattenGlslSource(R"(#version 450 core
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Out { vec4 o[]; };
uniform sampler2D ta;
uniform sampler2D tb;
void main() { o[0] = texelFetch(ta, ivec2(1, 1), 0); o[1] = texelFetch(tb, ivec2(0, 1), 0); }
)", "two.comp", {}));
  p.setSampler("ta", 0);
  p.setSampler("tb", 1);
  snell::gpu::StorageBuffer out(ctx.gl());
  out.allocate(2 * sizeof(glm::vec4));
  out.bindBase(0);
  p.dispatch(1);
  ctx.gl().MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::vec4> o = out.downloadVec4();
  EXPECT_EQ(o[0], glm::vec4(1.0f, 2.0f, 3.0f, 4.0f));
  EXPECT_EQ(o[1], glm::vec4(5.0f, 6.0f, 7.0f, 8.0f));
}

TEST(Resources, TextureMirrorsFilterState) {
  Context ctx;
  // Linear/mip-linear at points where every weight is 0, 0.5 or 1, so GL's
  // fixed-point filter weights cannot differ from the CPU view.
  const snell::Texture2D tex = taggedTexture(8, 4);
  const snell::gpu::Texture gpuTex(ctx.gl(), tex);
  const std::vector<glm::vec4> queries = {
      {0.5f / 8.0f, 0.5f / 4.0f, 0.0f, 0.0f},  // texel centre, level 0
      {0.25f, 0.5f, 0.0f, 0.0f},               // between texel centres
      {0.25f, 0.5f, 1.0f, 0.0f},               // level 1
      {0.25f, 0.5f, 1.5f, 0.0f},               // halfway between levels 1 and 2
      {-3.0f, 7.0f, 0.0f, 0.0f},               // clamp-to-edge
      {0.5f, 0.5f, 9.0f, 0.0f},                // lod past the last level
  };
  snell::gpu::StorageBuffer q(ctx.gl(), queries), r(ctx.gl());
  r.allocate(queries.size() * sizeof(glm::vec4));
  q.bindBase(0);
  r.bindBase(1);
  gpuTex.bind(0);
  const Program p = Program::compute(ctx.gl(), flattenGlslSource(R"(#version 450 core
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Q { vec4 q[]; };
layout(std430, binding = 1) writeonly buffer R { vec4 r[]; };
uniform sampler2D tex;
void main() { uint i = gl_GlobalInvocationID.x; r[i] = textureLod(tex, q[i].xy, q[i].z); }
)", "sample.comp", {}));
  p.setSampler("tex", 0);
  p.dispatch(static_cast<GLuint>(queries.size()));
  ctx.gl().MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::vec4> got = r.downloadVec4();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const glm::vec4 e = tex.sampleLod(glm::vec2(queries[i].x, queries[i].y), queries[i].z);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[i][k], e[k], 1e-5f) << "query " << i << " channel " << k;
  }
  EXPECT_EQ(snell::gpu::glMinFilter(snell::Filter::Nearest, snell::MipFilter::Linear), GL_NEAREST_MIPMAP_LINEAR);
  EXPECT_EQ(snell::gpu::glMinFilter(snell::Filter::Linear, snell::MipFilter::Nearest), GL_LINEAR_MIPMAP_NEAREST);
  EXPECT_EQ(snell::gpu::glMinFilter(snell::Filter::Linear, snell::MipFilter::None), GL_LINEAR);
  EXPECT_EQ(snell::gpu::glMagFilter(snell::Filter::Nearest), GL_NEAREST);
}

TEST(Resources, FramebufferClearAndRenderReadBack) {
  Context ctx;
  const snell::gpu::GlApi& gl = ctx.gl();
  const int w = 7, h = 5;  // odd sizes catch row-stride mistakes
  const snell::gpu::Framebuffer fb(gl, w, h, 2, true);

  const glm::vec4 clear(0.25f, -1.5f, 1e6f, 3.0f);  // float target: no clamping, no quantization
  fb.clearColor(0, clear);
  fb.clearColor(1, glm::vec4(0.0f));
  fb.clearDepth(0.375f);
  const snell::Image img = fb.readColor(0);
  ASSERT_EQ(img.width, w);
  ASSERT_EQ(img.height, h);
  for (const glm::vec4& t : img.texels) ASSERT_EQ(t, clear);
  for (const glm::vec4& t : fb.readDepth().texels) ASSERT_EQ(t.x, 0.375f);

  // A full-screen triangle writing gl_FragCoord to attachment 1: pixel (x, y)
  // must hold (x + 0.5, y + 0.5) at img.at(x, y), i.e. bottom row first.
  const std::filesystem::path fullscreen = std::filesystem::path(SNELL_SOURCE_DIR) / "glsl" / "passes" / "fullscreen.vert";
  const Program p = Program::graphics(gl, snell::gpu::flattenGlslFile(fullscreen, {}), flattenGlslSource(R"(#version 450 core
layout(location = 0) out vec4 colour;
layout(location = 1) out vec4 coord;
uniform vec4 tint;
void main() { colour = tint; coord = vec4(gl_FragCoord.xy, gl_FragCoord.z, 1.0); }
)", "coord.frag", {}));
  const snell::gpu::VertexArray vao(gl);
  fb.bind();
  vao.bind();
  p.use();
  p.set("tint", glm::vec4(1.0f, 2.0f, 3.0f, 4.0f));
  gl.Disable(GL_DEPTH_TEST);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  snell::gpu::checkGl(gl, "full-screen draw");
  const snell::Image coords = fb.readColor(1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      EXPECT_EQ(coords.at(x, y).x, static_cast<float>(x) + 0.5f) << x << "," << y;
      EXPECT_EQ(coords.at(x, y).y, static_cast<float>(y) + 0.5f) << x << "," << y;
    }
  EXPECT_EQ(fb.readColor(0).at(3, 2), glm::vec4(1.0f, 2.0f, 3.0f, 4.0f));
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);

  EXPECT_THROW(fb.readColor(2), Error);
}

TEST(Resources, IncompleteFramebufferNamesTheStatus) {
  Context ctx;
  try {
    snell::gpu::Framebuffer fb(ctx.gl(), 4, 4, 0, false);  // nothing attached
    FAIL() << "an incomplete framebuffer must throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"), std::string::npos)
        << e.what();
  }
}

TEST(Program, ErrorsNameStageFileAndUniform) {
  Context ctx;
  const snell::gpu::GlApi& gl = ctx.gl();
  try {
    snell::gpu::Shader s(gl, snell::gpu::Stage::Fragment,
                         flattenGlslSource("#version 450 core\nout vec4 c;\nvoid main() { c = vec4(oops); }\n",
                                           "broken.frag", {}));
    FAIL() << "a compile error must throw";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("fragment shader broken.frag failed to compile"), std::string::npos) << msg;
    EXPECT_NE(msg.find("broken.frag:3("), std::string::npos) << msg;
  }
  try {  // declared, never defined: only the linker sees it
    Program::compute(gl, flattenGlslSource(
                             "#version 450 core\nlayout(local_size_x = 1) in;\nvoid helper();\nvoid main() { helper(); }\n",
                             "unlinked.comp", {}));
    FAIL() << "a link error must throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("failed to link"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("unlinked.comp"), std::string::npos) << e.what();
  }
  const Program p = Program::compute(gl, flattenGlslSource(R"(#version 450 core
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Out { vec4 o[]; };
uniform mat4 m; uniform vec3 v3; uniform vec2 v2; uniform ivec2 i2; uniform float f; uniform int n;
void main() { o[0] = m * vec4(v3, 1.0); o[1] = vec4(v2, vec2(i2)); o[2] = vec4(f, float(n), 0.0, 0.0); }
)", "uniforms.comp", {}));
  glm::mat4 m(1.0f);
  m[3] = glm::vec4(10.0f, 20.0f, 30.0f, 1.0f);  // translation: column-major must survive
  p.set("m", m);
  p.set("v3", glm::vec3(1.0f, 2.0f, 3.0f));
  p.set("v2", glm::vec2(-1.0f, -2.0f));
  p.set("i2", glm::ivec2(7, -8));
  p.set("f", 0.5f);
  p.set("n", 42);
  EXPECT_FALSE(p.hasUniform("missing"));
  EXPECT_THROW(p.set("missing", 1.0f), Error);
  snell::gpu::StorageBuffer out(gl);
  out.allocate(3 * sizeof(glm::vec4));
  out.bindBase(0);
  p.dispatch(1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::vec4> o = out.downloadVec4();
  EXPECT_EQ(o[0], glm::vec4(11.0f, 22.0f, 33.0f, 1.0f));
  EXPECT_EQ(o[1], glm::vec4(-1.0f, -2.0f, 7.0f, -8.0f));
  EXPECT_EQ(o[2], glm::vec4(0.5f, 42.0f, 0.0f, 0.0f));
}

}  // namespace
