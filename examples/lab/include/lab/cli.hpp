// The command-line exit codes snell-lab and snell-gallery share: --help and
// --version exit 0, a usage error exits 2 with CLI11's message after the
// program's name, as every other error of the programs (CLI11_PARSE would
// return CLI11's own codes, 105 or 109, and print the message bare).
#pragma once
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

namespace snell::lab {

// Parses the command line. Returns -1 to go on, or the code to exit with;
// onUsageError runs after CLI11's message (snell-lab adds suggestions).
template <class OnUsageError>
int parseCommandLine(CLI::App& app, int argc, char** argv, OnUsageError onUsageError) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const std::string name = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "snell";
    std::fprintf(stderr, "%s: %s\nRun with --help for more information.\n", name.c_str(), e.what());
    onUsageError();
    return 2;
  }
  return -1;
}

inline int parseCommandLine(CLI::App& app, int argc, char** argv) {
  return parseCommandLine(app, argc, argv, [] {});
}

}  // namespace snell::lab
