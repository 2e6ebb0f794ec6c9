// A one-line progress bar on stderr, drawn only when stderr is a terminal and
// not disabled (--quiet). Thread-safe advance().
#pragma once
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace snell::lab {

class ProgressBar {
 public:
  // enabled: false forces it off; true still requires stderr to be a terminal.
  ProgressBar(std::string label, long total, bool enabled);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void advance(long n = 1);
  void finish();
  bool active() const { return active_; }
  static bool stderrIsTerminal();

 private:
  std::string label_;
  long total_;
  bool active_;
  bool finished_ = false;
  std::atomic<long> done_{0};
  std::mutex mutex_;
  int lastPercent_ = -1;
  std::chrono::steady_clock::time_point start_;
  void draw(long done);
};

}  // namespace snell::lab
