// Every file of glsl/snell compiles on a real GL driver (Mesa llvmpipe), through
// snell's own include flattener, as GLSL 330 core (fragment), 450 core
// (compute) and 310 es (compute), on both backends. glslangValidator checks the
// same offline (tests/compile); this catches what only the driver rejects.
#include <gtest/gtest.h>

#include <snell/gpu/context.hpp>
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/program.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace {
namespace fs = std::filesystem;
using snell::gpu::Backend;

const fs::path kGlsl = fs::path(SNELL_SOURCE_DIR) / "glsl";

std::vector<std::string> glslFiles() {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(kGlsl / "snell"))
    if (e.path().extension() == ".glsl") files.push_back(fs::relative(e.path(), kGlsl).generic_string());
  return files;
}

struct Mode {
  const char* name;
  snell::gpu::Stage stage;
  const char* header;
  const char* main;
};

const Mode kModes[] = {
    {"330 core", snell::gpu::Stage::Fragment, "#version 330 core\n", "out vec4 snellColor;\nvoid main() { snellColor = vec4(0.0); }\n"},
    {"450 core", snell::gpu::Stage::Compute, "#version 450 core\n", "layout(local_size_x = 1) in;\nvoid main() {}\n"},
    {"310 es", snell::gpu::Stage::Compute,
     "#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n",
     "layout(local_size_x = 1) in;\nvoid main() {}\n"},
};

void compileAll(Backend backend) {
  snell::gpu::Context ctx(backend);
  const std::vector<std::string> files = glslFiles();
  ASSERT_GT(files.size(), 5u);
  for (const std::string& f : files) {
    for (const Mode& m : kModes) {
      const std::string source = std::string(m.header) + "#include \"" + f + "\"\n" + m.main;
      try {
        const snell::gpu::FlatSource flat = snell::gpu::flattenGlslSource(source, "wrapper(" + f + ")", {kGlsl});
        snell::gpu::Shader shader(ctx.gl(), m.stage, flat);
      } catch (const std::exception& e) {
        ADD_FAILURE() << f << " as GLSL " << m.name << " on " << snell::gpu::backendName(backend) << ":\n" << e.what();
      }
    }
  }
}

class MesaCompile : public ::testing::TestWithParam<Backend> {};
TEST_P(MesaCompile, EveryGlslFile) { compileAll(GetParam()); }
INSTANTIATE_TEST_SUITE_P(Backends, MesaCompile, ::testing::ValuesIn(snell::gpu::kGlBackends),
                         snell::gpu::BackendParamName());

}  // namespace
