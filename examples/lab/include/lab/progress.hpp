// A progress line on stderr (off with --quiet). On a terminal, one bar
// redrawn in place; otherwise (a log, CI, a pipe) a plain line every 10%, so
// a long run still shows it is alive. Thread-safe advance(); the percentage
// shown never goes backwards, and finish() ends at 100% only when all the
// work was done.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace snell::lab {

class ProgressBar {
 public:
  enum class Style { Auto, Terminal, Lines };  // Auto: Terminal when `out` is a terminal
  // enabled: false draws nothing.
  ProgressBar(std::string label, long total, bool enabled, std::FILE* out = stderr, Style style = Style::Auto);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void advance(long n = 1);
  void finish();
  bool active() const { return active_; }

 private:
  std::string label_;
  long total_;
  bool active_;
  bool terminal_;
  std::FILE* out_;
  bool finished_ = false;
  std::atomic<long> done_{0};
  std::mutex mutex_;
  int lastPercent_ = -1;
  std::chrono::steady_clock::time_point start_;
  void drawLocked();
  int percentDone() const;  // of the work advanced so far, 0..100
};

}  // namespace snell::lab
