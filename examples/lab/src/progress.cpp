#include "lab/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace snell::lab {

bool ProgressBar::stderrIsTerminal() { return isatty(STDERR_FILENO) == 1; }

ProgressBar::ProgressBar(std::string label, long total, bool enabled)
    : label_(std::move(label)), total_(total > 0 ? total : 1), active_(enabled && stderrIsTerminal()),
      start_(std::chrono::steady_clock::now()) {
  if (active_) draw(0);
}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance(long n) {
  const long done = done_.fetch_add(n) + n;
  if (active_) draw(done);
}

void ProgressBar::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!active_ || finished_) return;
  finished_ = true;
  std::fputc('\n', stderr);
  std::fflush(stderr);
}

void ProgressBar::draw(long done) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  const int percent = static_cast<int>(100 * std::min(done, total_) / total_);
  if (percent == lastPercent_) return;
  lastPercent_ = percent;
  constexpr int kWidth = 40;
  const int filled = percent * kWidth / 100;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kWidth - filled), '.');
  std::fprintf(stderr, "\r%s [%s] %3d%% %.1fs", label_.c_str(), bar.c_str(), percent, s);
  std::fflush(stderr);
}

}  // namespace snell::lab
