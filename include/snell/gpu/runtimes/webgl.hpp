// The WebGL 2 runtime: the case file flattened into an ES 3.00 fragment shader, as an engine would paste it,
// run in headless Chromium's WebGL 2 (ANGLE on SwiftShader on the test machines; parity_webgl.hpp). The way
// three.js, Babylon.js and PlayCanvas get snell. Source tree only: it runs tools/webgl and tools/browser.
#pragma once

#include "../parity_webgl.hpp"
#include "../runtime.hpp"

#include <string>
#include <vector>

namespace snell::gpu {

class WebGlRuntime final : public Runtime {
 public:
  explicit WebGlRuntime(const RuntimeSetup& setup) : setup_(setup) {
    tools_.toolsDir = setup.sourceDir / "tools" / "webgl";
    tools_.node = setup.node;
    tools_.chromium = setup.chromium;
  }
  std::string name() const override { return "webgl2"; }
  std::string describe() const override { return "ES 3.00 fragment shader in headless Chromium's WebGL 2"; }
  std::string needs() const override { return "Debian chromium and nodejs"; }
  // SwiftShader, like most GPUs, flushes denormal floats.
  bool flushesDenormals() const override { return true; }
  std::vector<ParityIO> run(const RuntimeCase& c, const std::vector<ParityIO>& inputs) override {
    return runParityWebGl(tools_, c.includeDirs, c.caseFile, c.entry, inputs, c.textures, setup_.workDir / "webgl",
                          c.entrySource, &renderer_);
  }
  std::string renderer() override { return renderer_.empty() ? "(known after its first run)" : renderer_; }

 private:
  RuntimeSetup setup_;
  WebGlTools tools_;
  std::string renderer_;
};

}  // namespace snell::gpu
