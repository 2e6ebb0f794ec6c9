#include "lab/progress.hpp"

#include <algorithm>
#include <unistd.h>

namespace snell::lab {

ProgressBar::ProgressBar(std::string label, long total, bool enabled, std::FILE* out, Style style)
    : label_(std::move(label)),
      total_(total > 0 ? total : 1),
      active_(enabled && out != nullptr),
      terminal_(style == Style::Terminal || (style == Style::Auto && out && isatty(fileno(out)) == 1)),
      out_(out),
      start_(std::chrono::steady_clock::now()) {
  if (active_) {
    std::lock_guard<std::mutex> lock(mutex_);
    drawLocked();
  }
}

ProgressBar::~ProgressBar() { finish(); }

int ProgressBar::percentDone() const { return static_cast<int>(100 * std::min(done_.load(), total_) / total_); }

void ProgressBar::advance(long n) {
  done_.fetch_add(n);
  if (!active_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  drawLocked();
}

void ProgressBar::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!active_ || finished_) return;
  drawLocked();
  finished_ = true;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    std::fputc('\n', out_);
  } else if (lastPercent_ == 100) {
    std::fprintf(out_, "%s: done in %.1fs\n", label_.c_str(), s);
  } else {
    std::fprintf(out_, "%s: stopped at %d%% after %.1fs\n", label_.c_str(), percentDone(), s);
  }
  std::fflush(out_);
}

// Under mutex_: done_ is read here, so a thread that advanced earlier but
// drew later cannot draw an older count over a newer one.
void ProgressBar::drawLocked() {
  if (finished_) return;
  const int percent = percentDone();
  const int step = terminal_ ? 1 : 10;
  if (percent <= lastPercent_ || (percent / step == lastPercent_ / step && lastPercent_ >= 0 && percent != 100)) return;
  lastPercent_ = percent;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(kWidth - filled), '.');
    std::fprintf(out_, "\r%s [%s] %3d%% %.1fs", label_.c_str(), bar.c_str(), percent, s);
  } else {
    std::fprintf(out_, "%s: %d%% (%.1fs)\n", label_.c_str(), percent, s);
  }
  std::fflush(out_);
}

}  // namespace snell::lab
