// GL failures: no context, backends that cannot load, compile and
// link errors in included files, incomplete framebuffers, bad arguments to
// the helpers. Each must be a snell::gpu::Error whose text names the GL call
// (or the file and line), thrown where the mistake is made: never a crash, a
// silent black texture, or a GL error left queued to be blamed on a later call.
#include <snell/gpu/context.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>

#include "support/gpu_error_of.hpp"
#include "support/temp_dir.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using snell::gpu::Backend;
using snell::gpu::Context;
using snell::gpu::Error;
using snell::gpu::flattenGlslSource;
using snell::gpu::Program;

using snell_test::gpuErrorOf;

// A POSIX extended regular expression that matches `text` literally.
std::string literal(const std::string& text) {
  std::string re;
  for (char c : text) {
    if (std::string("\\.[](){}*+?^$|").find(c) != std::string::npos) re += '\\';
    re += c;
  }
  return re;
}

// In the child of a death test: create a context, print the error, exit 3.
[[noreturn]] void createContextAndExit(Backend backend) {
  try {
    Context ctx(backend);
  } catch (const Error& e) {
    std::fprintf(stderr, "<<%s>>", e.what());
    std::exit(3);
  }
  std::exit(0);
}

// A directory of libraries that the dynamic loader finds before the system's
// (LD_LIBRARY_PATH). The loader reads that variable once, at process start, so
// the context is created in a child: a gtest death test in the "threadsafe"
// style re-executes this binary, which inherits the environment, and runs the
// test again from the top up to the statement; the directory is made by the
// parent only and handed down in SNELL_TEST_FAKE_GL_DIR.
class FakeGlLibraries {
 public:
  // `contents`: file name -> bytes, or "copy:<path>" for a copy of a real library.
  explicit FakeGlLibraries(const std::vector<std::pair<std::string, std::string>>& contents) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    if (const char* inherited = std::getenv("SNELL_TEST_FAKE_GL_DIR")) {
      dir_ = inherited;
      return;
    }
    temp_ = std::make_unique<snell_test::TempDir>("snell_fake_gl");
    dir_ = temp_->path().string();
    for (const auto& [name, bytes] : contents) {
      if (bytes.rfind("copy:", 0) == 0)
        fs::copy_file(bytes.substr(5), temp_->path() / name);
      else
        temp_->write(name, bytes);
    }
    setenv("SNELL_TEST_FAKE_GL_DIR", dir_.c_str(), 1);
    if (const char* old = std::getenv("LD_LIBRARY_PATH")) oldLibraryPath_ = old, hadLibraryPath_ = true;
    setenv("LD_LIBRARY_PATH", dir_.c_str(), 1);
  }
  ~FakeGlLibraries() {
    if (!temp_) return;
    unsetenv("SNELL_TEST_FAKE_GL_DIR");
    if (hadLibraryPath_) setenv("LD_LIBRARY_PATH", oldLibraryPath_.c_str(), 1);
    else unsetenv("LD_LIBRARY_PATH");
  }
  const std::string& dir() const { return dir_; }

 private:
  std::unique_ptr<snell_test::TempDir> temp_;
  std::string dir_, oldLibraryPath_;
  bool hadLibraryPath_ = false;
};

const std::string kNotElf(256, 'x');  // glibc: "invalid ELF header"

TEST(GlFailure, BackendsThatCannotLoadListEveryReason) {
  const FakeGlLibraries fake({{"libOSMesa.so.8", kNotElf}, {"libOSMesa.so", kNotElf},
                              {"libEGL.so.1", kNotElf}, {"libEGL.so", kNotElf}});
  const std::string& d = fake.dir();
  const std::string osmesa = "OSMesa backend: cannot load libOSMesa.so.8 or libOSMesa.so (" + d +
                             "/libOSMesa.so.8: invalid ELF header; " + d +
                             "/libOSMesa.so: invalid ELF header); install libosmesa6 (Debian/Ubuntu) or set "
                             "SNELL_GL_BACKEND=egl";
  const std::string egl = "EGL backend: cannot load libEGL.so.1 or libEGL.so (" + d +
                          "/libEGL.so.1: invalid ELF header; " + d +
                          "/libEGL.so: invalid ELF header); install libegl1 and libegl-mesa0 (Debian/Ubuntu) or set "
                          "SNELL_GL_BACKEND=osmesa";
  EXPECT_EXIT(createContextAndExit(Backend::OSMesa), ::testing::ExitedWithCode(3), literal("<<" + osmesa + ">>"));
  EXPECT_EXIT(createContextAndExit(Backend::EGL), ::testing::ExitedWithCode(3), literal("<<" + egl + ">>"));
  EXPECT_EXIT(createContextAndExit(Backend::Auto), ::testing::ExitedWithCode(3),
              literal("<<no GL context: tried OSMesa, then EGL.\n  " + osmesa + "\n  " + egl + ">>"));
}

TEST(GlFailure, ALibraryWithoutTheEntryPointsIsNamed) {
  // A real shared library under the OSMesa names: it loads, but is not Mesa.
  const FakeGlLibraries fake({{"libOSMesa.so.8", "copy:/lib/x86_64-linux-gnu/libm.so.6"},
                              {"libOSMesa.so", "copy:/lib/x86_64-linux-gnu/libm.so.6"}});
  EXPECT_EXIT(createContextAndExit(Backend::OSMesa), ::testing::ExitedWithCode(3),
              literal("<<OSMesa backend: libOSMesa.so.8 has no symbol OSMesaCreateContextAttribs; the library is too "
                      "old or not the Mesa one>>"));
}

TEST(GlFailure, UnknownBackendNameIsAnError) {
  const char* old = std::getenv("SNELL_GL_BACKEND");
  const std::string saved = old ? old : "";
  setenv("SNELL_GL_BACKEND", "nonsense", 1);
  const std::string msg = gpuErrorOf([] { Context ctx; });
  if (old) setenv("SNELL_GL_BACKEND", saved.c_str(), 1);
  else unsetenv("SNELL_GL_BACKEND");
  EXPECT_EQ(msg, "SNELL_GL_BACKEND: unknown GL backend 'nonsense'; valid names: auto, osmesa, egl");
}

// Every helper creates its GL object first and checks the name it got: with
// no context current Mesa's dispatch stubs do nothing and hand back 0.
TEST(GlFailure, HelpersWithoutACurrentContextSaySo) {
  snell::gpu::GlApi gl;
  {
    const Context ctx(Backend::OSMesa);
    gl = ctx.gl();
  }  // destroyed and released: nothing is current on this thread
  const auto cs = flattenGlslSource("#version 430 core\nlayout(local_size_x = 1) in;\nvoid main() {}\n", "x.comp", {});
  EXPECT_EQ(gpuErrorOf([&] { Program::compute(gl, cs); }), "glCreateShader(compute) failed; is a context current?");
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::StorageBuffer b(gl); }), "glGenBuffers failed; is a context current?");
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Texture t(gl, snell::Texture2D(snell::Image(2, 2))); }),
            "glGenTextures failed; is a context current?");
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Framebuffer f(gl, 4, 4); }), "glGenFramebuffers failed; is a context current?");
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::VertexArray v(gl); }), "glGenVertexArrays failed; is a context current?");
}

// The driver's log is rewritten to the files the flattener spliced together:
// a typo in an include of the fragment shader is reported at that include.
TEST(GlFailure, CompileErrorInAnIncludeNamesItsFileAndLine) {
  const snell_test::TempDir dir("snell_gl_failure");
  const fs::path lib = dir.write("lib/tint.glsl", "vec4 tint(vec4 c) {\n  return c * strength;\n}\n");
  const fs::path frag = dir.write("shade.frag",
                                  "#version 450 core\n#include \"lib/tint.glsl\"\nout vec4 colour;\n"
                                  "void main() { colour = tint(vec4(1.0)); }\n");
  const fs::path vert = dir.write("full.vert", "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n");
  const Context ctx;
  const std::string msg = gpuErrorOf([&] {
    Program::graphics(ctx.gl(), snell::gpu::flattenGlslFile(vert, {}), snell::gpu::flattenGlslFile(frag, {}));
  });
  const std::string head = "fragment shader " + frag.string() + " failed to compile:\n";
  ASSERT_EQ(msg.rfind(head, 0), 0u) << msg;
  // Mesa: "<file>:2(21): error: `strength' undeclared": the include's path and line, nothing of "0:" or "1:".
  EXPECT_EQ(msg.find(lib.lexically_normal().string() + ":2("), head.size()) << msg;
  EXPECT_NE(msg.find("`strength' undeclared"), std::string::npos) << msg;
}

TEST(GlFailure, LinkErrorNamesBothStagesAndFiles) {
  const Context ctx;
  const std::string msg = gpuErrorOf([&] {
    Program::graphics(ctx.gl(),
                      flattenGlslSource("#version 450 core\nout vec3 v;\nvoid main() { v = vec3(1.0); gl_Position = "
                                        "vec4(0.0); }\n",
                                        "a.vert", {}),
                      flattenGlslSource("#version 450 core\nin vec4 v;\nout vec4 c;\nvoid main() { c = v; }\n",
                                        "b.frag", {}));
  });
  const std::string head = "program (vertex a.vert, fragment b.frag) failed to link:\n";
  ASSERT_EQ(msg.rfind(head, 0), 0u) << msg;
  EXPECT_NE(msg.find("`v'"), std::string::npos) << msg;  // Mesa names the mismatched variable
}

// A framebuffer whose attachment cannot be rendered to: the status and the GL call are named.
TEST(GlFailure, IncompleteFramebufferNamesTheCallAndStatus) {
  const Context ctx;
  const snell::gpu::GlApi& gl = ctx.gl();
  auto attachAndCheck = [&](GLint internalFormat, GLenum format, int size) {
    GLuint fbo = 0, tex = 0;
    gl.GenFramebuffers(1, &fbo);
    gl.GenTextures(1, &tex);
    const snell::gpu::GlHandle<snell::gpu::detail::DeleteFramebuffer> fboHandle(gl, fbo);
    const snell::gpu::GlHandle<snell::gpu::detail::DeleteTexture> texHandle(gl, tex);
    gl.BindTexture(GL_TEXTURE_2D, tex);
    gl.TexImage2D(GL_TEXTURE_2D, 0, internalFormat, size, size, 0, format, GL_FLOAT, nullptr);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    snell::gpu::checkGl(gl, "test framebuffer setup");
    const std::string msg = gpuErrorOf([&] { snell::gpu::checkFramebufferComplete(gl, "my target"); });
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return msg;
  };
  const std::string incomplete =
      "my target: glCheckFramebufferStatus returned GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (an attachment has a zero "
      "size or a format that cannot be rendered to)";
  EXPECT_EQ(attachAndCheck(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, 4), incomplete);  // depth as a colour target
  EXPECT_EQ(attachAndCheck(GL_RGBA32F, GL_RGBA, 0), incomplete);                       // a 0 x 0 image
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Framebuffer fb(gl, 4, 4, 0, false); }),
            "snell::gpu::Framebuffer 4x4: glCheckFramebufferStatus returned "
            "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT");
  snell::gpu::checkGl(gl, "nothing left queued");
}

TEST(GlFailure, FramebufferSizesAreChecked) {
  const Context ctx;
  const snell::gpu::GlApi& gl = ctx.gl();
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Framebuffer fb(gl, 0, 4); }),
            "snell::gpu::Framebuffer: size 0x4; both must be positive");
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Framebuffer fb(gl, 8, -2); }),
            "snell::gpu::Framebuffer: size 8x-2; both must be positive");
  // Past GL_MAX_TEXTURE_SIZE: the attachment's glTexImage2D fails; it was
  // reported as an incomplete framebuffer, with GL_INVALID_VALUE left queued.
  GLint maxSize = 0;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  const int tooWide = maxSize + 1;
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Framebuffer fb(gl, tooWide, 4); }),
            "GL error 0x0501 (GL_INVALID_VALUE) after glTexImage2D(GL_RGBA32F, " + std::to_string(tooWide) +
                "x4) for a snell::gpu::Framebuffer attachment");
  snell::gpu::checkGl(gl, "nothing left queued");
  const snell::gpu::Framebuffer fb(gl, 4, 4, 1, false);
  EXPECT_EQ(gpuErrorOf([&] { fb.clearColor(1, glm::vec4(1.0f)); }),
            "snell::gpu::Framebuffer::clearColor: no colour attachment 1");
  EXPECT_EQ(gpuErrorOf([&] { fb.readDepth(); }),
            "snell::gpu::Framebuffer::readDepth: the framebuffer has no depth attachment");
}

// A GL error right after the call that caused it, with that call's name.
TEST(GlFailure, BadArgumentsAreReportedAtTheirGlCall) {
  const Context ctx;
  const snell::gpu::GlApi& gl = ctx.gl();
  GLint maxSize = 0, maxBindings = 0, maxUnits = 0;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  gl.GetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &maxBindings);
  gl.GetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &maxUnits);

  // Texture sizes: 0 x 0 is legal GL (an incomplete texture that samples as
  // black), a size that disagrees with the texels would make GL read past them.
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Texture t(gl, snell::Texture2D(snell::Image())); }),
            "snell::gpu::Texture: level 0 is 0x0; sizes must be positive");
  snell::Image lying(2, 2);
  lying.height = 3;
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Texture t(gl, snell::Texture2D(lying)); }),
            "snell::gpu::Texture: level 0 is 2x3 but holds 4 texels");
  const snell::Image wide(maxSize + 1, 1);
  EXPECT_EQ(gpuErrorOf([&] { snell::gpu::Texture t(gl, snell::Texture2D(wide)); }),
            "GL error 0x0501 (GL_INVALID_VALUE) after glTexImage2D(level 0, " + std::to_string(maxSize + 1) +
                "x1, GL_RGBA32F) in snell::gpu::Texture");

  const snell::gpu::Texture tex(gl, snell::Texture2D(snell::Image(2, 2)));
  EXPECT_EQ(gpuErrorOf([&] { tex.bind(maxUnits); }),
            "GL error 0x0500 (GL_INVALID_ENUM) after glActiveTexture(GL_TEXTURE0 + " + std::to_string(maxUnits) + ")");
  snell::gpu::StorageBuffer buffer(gl);
  buffer.allocate(16);
  EXPECT_EQ(gpuErrorOf([&] { buffer.bindBase(static_cast<GLuint>(maxBindings)); }),
            "GL error 0x0501 (GL_INVALID_VALUE) after glBindBufferBase(GL_SHADER_STORAGE_BUFFER, " +
                std::to_string(maxBindings) + ")");

  // A value of the wrong type for a uniform: GL_INVALID_OPERATION at the set,
  // where before it surfaced at the next dispatch as a glDispatchCompute error.
  const Program p = Program::compute(gl, flattenGlslSource(R"(#version 450 core
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Out { float o[]; };
uniform int count;
uniform vec3 axis;
void main() { o[0] = float(count) + axis.x; }
)", "types.comp", {}));
  EXPECT_EQ(gpuErrorOf([&] { p.set("count", 1.5f); }),
            "GL error 0x0502 (GL_INVALID_OPERATION) after glProgramUniform1f for uniform 'count'");
  EXPECT_EQ(gpuErrorOf([&] { p.set("axis", glm::vec2(1.0f)); }),
            "GL error 0x0502 (GL_INVALID_OPERATION) after glProgramUniform2fv for uniform 'axis'");
  p.set("count", 2);
  p.set("axis", glm::vec3(0.5f));
  buffer.bindBase(0);
  p.dispatch(1);  // nothing stale left to blame on it
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  EXPECT_EQ(buffer.downloadFloats()[0], 2.5f);
}

}  // namespace
