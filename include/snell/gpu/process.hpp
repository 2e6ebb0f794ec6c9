// Running the tools a runtime needs (glslang, spirv-val, spirv-cross, Deno, Node.js, Chromium) as child
// processes, and the files of their jobs: what every runner that is not a GL context shares.
//
//   snell::gpu::ToolResult t = snell::gpu::runTool("glslangValidator", {"--version"}, "glslang-tools");
//
// runTool starts the program with posix_spawnp (no shell: arguments are passed as they are, nothing is
// expanded), collects its stdout and stderr interleaved and waits for it. A program that cannot be
// started is an Error naming the Debian package that provides it. askServer puts the same question to a
// server that answers like a tool (tools/webgpu/parity_server.ts, tint_server.mjs,
// tools/browser/page_server.mjs).
#pragma once

#include "error.hpp"

#include <poll.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace snell::gpu {

struct ToolResult {
  int exitCode = 0;
  std::string output;  // stdout and stderr, interleaved
};

// Runs `program args...` (no shell) and collects its output. Throws an Error
// naming `package` when the program cannot be started (not installed).
inline ToolResult runTool(const std::string& program, const std::vector<std::string>& args,
                          const std::string& package) {
  int fds[2];
  if (pipe(fds) != 0) throw Error("runTool: pipe() failed: " + std::string(std::strerror(errno)));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  std::vector<std::string> argvStrings;
  argvStrings.push_back(program);
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argvStrings) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  if (rc != 0) {
    close(fds[0]);
    if (rc == ENOENT || rc == EACCES)
      throw Error("'" + program + "' not found or not executable: install the Debian package " + package +
                  " (apt-get install " + package + "), or pass its path");
    throw Error("cannot start '" + program + "': " + std::strerror(rc));
  }
  ToolResult r;
  char buf[4096];
  for (;;) {
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n > 0) {
      r.output.append(buf, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;
    }
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw Error("waitpid for '" + program + "' failed: " + std::strerror(errno));
  }
  if (WIFEXITED(status)) {
    r.exitCode = WEXITSTATUS(status);
    // posix_spawnp may report a failed exec as exit status 127 instead.
    if (r.exitCode == 127 && r.output.empty())
      throw Error("'" + program + "' could not be run (exit 127): install the Debian package " + package +
                  " (apt-get install " + package + "), or pass its path");
  } else {
    r.exitCode = 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  }
  return r;
}

namespace detail {

inline std::uint64_t fnv1a(const std::string& s, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

inline std::string readTextFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeTextFile(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw Error("cannot write " + p.string());
}

inline void writeFloats(const std::filesystem::path& p, const float* data, std::size_t count) {
  std::ofstream out(p, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(count * sizeof(float)));
  if (!out.flush()) throw Error("cannot write " + p.string());
}

inline std::string indent(const std::string& text) {
  std::string out = "    ";
  for (char c : text) {
    out += c;
    if (c == '\n') out += "    ";
  }
  return out;
}

// Asks the server on the Unix socket `socket`: writes `request` and a newline, reads the answer until the
// server closes the connection: "<exit status>\n<output>", what the tool it stands for would exit with and
// print. Throws an Error starting with `who` and naming the socket when the server cannot be reached,
// closes without an answer or gives none within `timeoutSeconds`.
inline ToolResult askServer(const std::filesystem::path& socket, const std::string& request, int timeoutSeconds,
                            const std::string& who) {
  const std::string path = socket.string();
  const auto fail = [&](const std::string& what) { return Error(who + ": " + what); };
  if (request.find('\n') != std::string::npos) throw fail("a request is one line: '" + request + "'");
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  if (path.size() >= sizeof address.sun_path)
    throw fail("the socket path " + path + " is longer than a Unix socket's " +
               std::to_string(sizeof address.sun_path - 1) + " bytes");
  std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw fail("socket() failed: " + std::string(std::strerror(errno)));
  struct Closer {
    int socket;
    ~Closer() { close(socket); }
  } closer{fd};
  if (connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0)
    throw fail("cannot connect to " + path + ": " + std::strerror(errno));
  const std::string line = request + "\n";
  for (std::size_t sent = 0; sent < line.size();) {
    const ssize_t n = send(fd, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw fail("cannot write to " + path + ": " + std::strerror(errno));
    sent += static_cast<std::size_t>(n);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  std::string answer;
  char buf[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd p{fd, POLLIN, 0};
    const int ready = left.count() > 0 ? poll(&p, 1, static_cast<int>(left.count())) : 0;
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) throw fail("poll() on " + path + " failed: " + std::strerror(errno));
    if (ready == 0) throw fail("no answer from " + path + " in " + std::to_string(timeoutSeconds) + " s");
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n > 0) {
      answer.append(buf, static_cast<std::size_t>(n));
    } else if (n == 0) {
      break;
    } else if (errno != EINTR) {
      throw fail("cannot read from " + path + ": " + std::strerror(errno));
    }
  }
  if (answer.empty()) throw fail(path + " closed the connection without an answer (did its server exit?)");
  const std::size_t eol = answer.find('\n');
  if (eol == std::string::npos || eol == 0 || eol > 3 || answer.find_first_not_of("0123456789") != eol)
    throw fail(path + " gave no exit status:\n" + indent(answer));
  ToolResult r;
  r.exitCode = std::stoi(answer.substr(0, eol));
  r.output = answer.substr(eol + 1);
  return r;
}

}  // namespace detail

}  // namespace snell::gpu
