// snell::gpu::Context on both backends. These tests must *run*: a machine
// without a GL context fails them (DESIGN.md sec. 3), it never skips them.
#include <snell/gpu/context.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <cstdlib>
#include <memory>
#include <cstring>
#include <string>
#include <vector>

namespace {

using snell::gpu::Backend;
using snell::gpu::Context;

// Restores an environment variable when the test ends, pass or fail.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    if (value) setenv(name, value, 1);
    else unsetenv(name);
  }
  ~ScopedEnv() {
    if (had_) setenv(name_, old_.c_str(), 1);
    else unsetenv(name_);
  }

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

// Writes out[i] = i * scale + offset: integers and a power-of-two scale, so
// every value is exact in float and the expectation needs no GL at all.
std::vector<float> runAffineKernel(const Context& ctx, float scale, float offset, int count) {
  ctx.makeCurrent();
  const snell::gpu::GlApi& gl = ctx.gl();
  const auto src = snell::gpu::flattenGlslSource(
      "#version 430 core\n"
      "layout(local_size_x = 32) in;\n"
      "layout(std430, binding = 3) writeonly buffer Out { float result[]; };\n"
      "uniform float scale;\n"
      "uniform float offset;\n"
      "uniform int count;\n"
      "void main() {\n"
      "  int i = int(gl_GlobalInvocationID.x);\n"
      "  if (i < count) result[i] = float(i) * scale + offset;\n"
      "}\n",
      "affine.comp", {});
  const auto program = snell::gpu::Program::compute(gl, src);
  snell::gpu::StorageBuffer buffer(gl);
  buffer.allocate(static_cast<std::size_t>(count) * sizeof(float));
  buffer.bindBase(3);
  program.set("scale", scale);
  program.set("offset", offset);
  program.set("count", count);
  program.dispatch(static_cast<GLuint>((count + 31) / 32));
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return buffer.downloadFloats();
}

void expectAffine(const std::vector<float>& got, float scale, float offset, int count) {
  ASSERT_EQ(got.size(), static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const float expected = static_cast<float>(i) * scale + offset;
    ASSERT_EQ(got[static_cast<std::size_t>(i)], expected) << "index " << i;
  }
}

class ContextBackend : public ::testing::TestWithParam<Backend> {};

TEST_P(ContextBackend, CreatesGl43CoreContextAndRunsComputeShader) {
  Context ctx(GetParam());
  EXPECT_EQ(ctx.backend(), GetParam());
  const std::string renderer = ctx.renderer();
  EXPECT_FALSE(renderer.empty());
  // On this project's CI (no GPU) both backends must land on llvmpipe.
  if (std::getenv("SNELL_EXPECT_GPU") == nullptr) {
    EXPECT_NE(renderer.find("llvmpipe"), std::string::npos) << renderer;
  }
  GLint major = 0, minor = 0;
  ctx.gl().GetIntegerv(GL_MAJOR_VERSION, &major);
  ctx.gl().GetIntegerv(GL_MINOR_VERSION, &minor);
  EXPECT_TRUE(major > 4 || (major == 4 && minor >= 3)) << ctx.version();
  EXPECT_NE(ctx.version().find("Core Profile"), std::string::npos) << ctx.version();
  expectAffine(runAffineKernel(ctx, 0.5f, 3.0f, 1000), 0.5f, 3.0f, 1000);
}

INSTANTIATE_TEST_SUITE_P(BothBackends, ContextBackend, ::testing::ValuesIn(snell::gpu::kGlBackends),
                         snell::gpu::BackendParamName());

TEST(Context, BothBackendsCoexistInOneProcess) {
  Context osmesa(Backend::OSMesa);
  Context egl(Backend::EGL);
  // Interleave so each switch goes through makeCurrent in both directions.
  expectAffine(runAffineKernel(osmesa, 2.0f, 1.0f, 300), 2.0f, 1.0f, 300);
  expectAffine(runAffineKernel(egl, 0.25f, -7.0f, 300), 0.25f, -7.0f, 300);
  expectAffine(runAffineKernel(osmesa, -1.0f, 0.0f, 300), -1.0f, 0.0f, 300);
  expectAffine(runAffineKernel(egl, 4.0f, 0.5f, 300), 4.0f, 0.5f, 300);
  // Each context's own string, not the other's or a null one (the symbol-clash symptom).
  osmesa.makeCurrent();
  EXPECT_FALSE(osmesa.version().empty());
  egl.makeCurrent();
  EXPECT_FALSE(egl.version().empty());
}

TEST(Context, TwoContextsOfOneBackendAndDestructionOrder) {
  for (Backend b : snell::gpu::kGlBackends) {
    auto first = std::make_unique<Context>(b);
    Context second(b);
    expectAffine(runAffineKernel(*first, 1.0f, 1.0f, 64), 1.0f, 1.0f, 64);
    first.reset();  // must not tear down `second` (EGL shares one display per process)
    expectAffine(runAffineKernel(second, 3.0f, 0.0f, 64), 3.0f, 0.0f, 64);
  }
}

TEST(Context, MovedContextKeepsWorking) {
  Context a(Backend::Auto);
  const snell::gpu::GlApi* table = &a.gl();
  Context b(std::move(a));
  EXPECT_EQ(&b.gl(), table);  // GlApi references held by resources stay valid
  expectAffine(runAffineKernel(b, 1.0f, 0.0f, 100), 1.0f, 0.0f, 100);
  EXPECT_THROW(a.gl(), snell::gpu::Error);  // NOLINT(bugprone-use-after-move): the moved-from state is defined
}

TEST(Context, AutoFollowsEnvironment) {
  {
    ScopedEnv env("SNELL_GL_BACKEND", "EGL");
    EXPECT_EQ(Context().backend(), Backend::EGL);
  }
  {
    ScopedEnv env("SNELL_GL_BACKEND", "osmesa");
    EXPECT_EQ(Context().backend(), Backend::OSMesa);
  }
  {
    ScopedEnv env("SNELL_GL_BACKEND", nullptr);
    // OSMesa is the default wherever libOSMesa loads (Mesa < 25.1), else EGL.
    const bool haveOsmesa = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL) || dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
    EXPECT_EQ(Context().backend(), haveOsmesa ? Backend::OSMesa : Backend::EGL);
  }
  {
    ScopedEnv env("SNELL_GL_BACKEND", "vulkan");
    try {
      Context ctx;
      FAIL() << "an unknown SNELL_GL_BACKEND must be an error";
    } catch (const snell::gpu::Error& e) {
      EXPECT_NE(std::string(e.what()).find("SNELL_GL_BACKEND"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("osmesa"), std::string::npos) << e.what();
    }
  }
}

TEST(Context, EglDevicePlatformWhenRequested) {
  // SNELL_EGL_DEVICE=1 prefers EGL_EXT_platform_device, falling back to
  // surfaceless; either way a working context must come out.
  ScopedEnv env("SNELL_EGL_DEVICE", "1");
  Context ctx(Backend::EGL);
  expectAffine(runAffineKernel(ctx, 1.0f, 2.0f, 50), 1.0f, 2.0f, 50);
}

TEST(Backend, NamesAndParsing) {
  EXPECT_STREQ(snell::gpu::backendName(Backend::Auto), "auto");
  EXPECT_STREQ(snell::gpu::backendName(Backend::OSMesa), "osmesa");
  EXPECT_STREQ(snell::gpu::backendName(Backend::EGL), "egl");
  EXPECT_EQ(snell::gpu::parseBackend("OSMesa"), Backend::OSMesa);
  EXPECT_EQ(snell::gpu::parseBackend("osmesa"), Backend::OSMesa);
  EXPECT_EQ(snell::gpu::parseBackend("EgL"), Backend::EGL);
  EXPECT_EQ(snell::gpu::parseBackend("AUTO"), Backend::Auto);
  for (const char* bad : {"", "gl", "osmesa ", "vulkan"}) {
    try {
      snell::gpu::parseBackend(bad);
      ADD_FAILURE() << "'" << bad << "' parsed";
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      for (const char* valid : {"auto", "osmesa", "egl"})
        EXPECT_NE(msg.find(valid), std::string::npos) << msg;
    }
  }
}

TEST(GlApi, MissingEntryPointsAreNamed) {
  Context ctx;
  try {
    snell::gpu::GlApi::loadWith([](const char* name) -> void* {
      if (std::strcmp(name, "glDispatchCompute") == 0 || std::strcmp(name, "glReadPixels") == 0) return nullptr;
      return reinterpret_cast<void*>(+[]() {});
    });
    FAIL() << "a missing entry point must throw";
  } catch (const snell::gpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("glDispatchCompute"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("glReadPixels"), std::string::npos) << e.what();
  }
}

TEST(GlApi, CheckGlNamesTheError) {
  Context ctx;
  const snell::gpu::GlApi& gl = ctx.gl();
  snell::gpu::checkGl(gl, "a clean start");
  gl.Enable(0xFFFFu);  // not a capability: GL_INVALID_ENUM
  try {
    snell::gpu::checkGl(gl, "glEnable(0xFFFF)");
    FAIL() << "checkGl must throw after a GL error";
  } catch (const snell::gpu::Error& e) {
    EXPECT_STREQ(e.what(), "GL error 0x0500 (GL_INVALID_ENUM) after glEnable(0xFFFF)");
  }
  snell::gpu::checkGl(gl, "the queue was drained");
}

}  // namespace
