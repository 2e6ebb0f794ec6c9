// The lab's progress line: without a terminal it still reports
// (plain lines every 10%), with one it redraws in place; from many threads
// the percentage shown never goes backwards, and it ends at 100% exactly when
// all the work was done.
#include "lab/progress.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <regex>
#include <string>
#include <thread>
#include <vector>

using snell::lab::ProgressBar;

namespace {

// What `style` writes while 8 threads advance it `total` times in all.
std::string run(ProgressBar::Style style, long total, long advanced) {
  std::FILE* f = std::tmpfile();
  EXPECT_NE(f, nullptr);
  {
    ProgressBar bar("work", total, true, f, style);
    std::vector<std::thread> threads;
    for (int t = 0; t < 8; ++t)
      threads.emplace_back([&, t] {
        for (long i = t; i < advanced; i += 8) bar.advance();
      });
    for (std::thread& t : threads) t.join();
  }
  std::rewind(f);
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) out.append(buf, n);
  std::fclose(f);
  return out;
}

std::vector<int> percents(const std::string& out, const std::regex& re) {
  std::vector<int> p;
  for (auto it = std::sregex_iterator(out.begin(), out.end(), re); it != std::sregex_iterator(); ++it)
    p.push_back(std::stoi((*it)[1]));
  return p;
}

}  // namespace

TEST(LabProgress, WithoutATerminalItPrintsLinesThatNeverGoBack) {
  for (int rep = 0; rep < 20; ++rep) {
    const std::string out = run(ProgressBar::Style::Lines, 1000, 1000);
    const std::vector<int> p = percents(out, std::regex("work: (\\d+)% \\("));
    ASSERT_FALSE(p.empty()) << out;
    EXPECT_EQ(p.front(), 0);
    EXPECT_EQ(p.back(), 100) << out;
    for (std::size_t i = 1; i < p.size(); ++i) EXPECT_GT(p[i], p[i - 1]) << out;
    EXPECT_LE(p.size(), 12u) << out;  // 0, 10, ..., 100: a log is not flooded
    EXPECT_NE(out.find("work: done in "), std::string::npos) << out;
    EXPECT_EQ(out.find('\r'), std::string::npos);
  }
}

TEST(LabProgress, OnATerminalItRedrawsAndNeverGoesBack) {
  for (int rep = 0; rep < 20; ++rep) {
    const std::string out = run(ProgressBar::Style::Terminal, 997, 997);
    const std::vector<int> p = percents(out, std::regex("\\] +(\\d+)% "));
    ASSERT_FALSE(p.empty());
    for (std::size_t i = 1; i < p.size(); ++i) EXPECT_GT(p[i], p[i - 1]) << out;
    EXPECT_EQ(p.back(), 100);
    EXPECT_EQ(out.back(), '\n');
  }
}

TEST(LabProgress, WorkLeftUndoneSaysWhereItStopped) {
  const std::string out = run(ProgressBar::Style::Lines, 100, 37);
  EXPECT_NE(out.find("work: stopped at 37% after "), std::string::npos) << out;
  EXPECT_EQ(out.find("100%"), std::string::npos) << out;
  EXPECT_EQ(run(ProgressBar::Style::Lines, 100, 100).find("stopped"), std::string::npos);
}
