// A parity job run by a page in headless Chromium, for the WebGL 2 runtime
// (parity_webgl.hpp) and the WebGPU run in Chromium (parity_webgpu.hpp):
// tools/browser/run_page.mjs, beside the page's own folder of tools/, serves
// the page and the job folder on 127.0.0.1 to one Chromium it starts and
// writes what the page posts back (the results, renderer.txt). Under ctest the
// WebGL 2 runtime asks tools/browser/page_server.mjs instead, which leaves the
// same files: pageJobResults reads a job either way. Source tree only, like
// the runtimes that use it (not installed).
#pragma once

#include "parity_job.hpp"
#include "process.hpp"
#include "include_flattener.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace snell::gpu::detail {

// What a page's run of `job` left, given how its runner (run_page.mjs, or page_server.mjs's answer)
// exited and what it printed, `t`: the `count` cases in job/resultsFile. A failure throws with that
// output, its shader locations mapped to snell's files through `source` if given; `renderer`, if given,
// receives the renderer or adapter string the page reported. `who` names the runtime in errors.
inline std::vector<ParityIO> pageJobResults(const ToolResult& t, const std::filesystem::path& job,
                                            const std::string& resultsFile, std::size_t count, const std::string& who,
                                            const FlatSource* source = nullptr, std::string* renderer = nullptr) {
  if (t.exitCode != 0)
    throw Error(who + " failed on " + job.string() + " (exit " + std::to_string(t.exitCode) + "):\n" +
                indent(source ? mapInfoLog(t.output, *source) : t.output));
  std::vector<ParityIO> out = readParityResults(job / resultsFile, count, who);
  if (renderer) {
    *renderer = readTextFile(job / "renderer.txt");
    while (!renderer->empty() && renderer->back() == '\n') renderer->pop_back();
  }
  return out;
}

// Runs `page` (tools/<runtime>/<page>.js) on `job` with run_page.mjs's `flags`; returns the `count`
// cases the page wrote to job/resultsFile (pageJobResults).
inline std::vector<ParityIO> runChromiumPage(const std::string& node, const std::string& chromium,
                                             const std::filesystem::path& page, const std::filesystem::path& job,
                                             const std::string& resultsFile, std::vector<std::string> flags,
                                             std::size_t count, const std::string& who,
                                             const FlatSource* source = nullptr, std::string* renderer = nullptr) {
  namespace fs = std::filesystem;
  const fs::path script = page.parent_path() / ".." / "browser" / "run_page.mjs";
  if (!fs::exists(script)) throw Error(who + ": the page server is missing: no " + script.string());
  std::error_code ec;
  fs::remove(job / resultsFile, ec);
  std::vector<std::string> args = {script.string(), page.string(), job.string(), resultsFile};
  args.insert(args.end(), flags.begin(), flags.end());
  args.push_back("--chromium=" + chromium);
  return pageJobResults(runTool(node, args, "nodejs"), job, resultsFile, count, who, source, renderer);
}

}  // namespace snell::gpu::detail
