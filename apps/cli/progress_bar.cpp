#include "cli/progress_bar.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace recode::app {

namespace {
constexpr int kWidth = 40;
constexpr auto kDelay = std::chrono::seconds(1);
constexpr auto kInterval = std::chrono::milliseconds(100);
}  // namespace

ProgressBar::ProgressBar(int total)
    : total_(total), enabled_(total > 1 && isatty(STDERR_FILENO) == 1), start_(Clock::now()) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::update(int done) {
  if (!enabled_)
    return;
  const Clock::time_point now = Clock::now();
  if (now - start_ < kDelay || (drawn_ && now - lastDraw_ < kInterval))
    return;
  lastDraw_ = now;
  drawn_ = true;
  const int filled = total_ > 0 ? done * kWidth / total_ : 0;
  const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                          std::string(static_cast<std::size_t>(kWidth - filled), '.');
  std::fprintf(stderr, "\rrecode run: frame %d/%d [%s] %3d%%", done, total_, bar.c_str(),
               total_ > 0 ? done * 100 / total_ : 0);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (!drawn_)
    return;
  std::fprintf(stderr, "\r%*s\r", kWidth + 40, "");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace recode::app
