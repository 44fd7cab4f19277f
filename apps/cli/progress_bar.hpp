#pragma once
// A progress bar on stderr for long runs: drawn only when stderr is a terminal (so logs and
// pipes stay clean), only once the run has taken a second, at most ten times a second, and
// erased when done.

#include <chrono>

namespace recode::app {

class ProgressBar {
 public:
  explicit ProgressBar(int total);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // `done` of `total` steps are finished.
  void update(int done);
  // Erases the bar (if one was drawn).
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  int total_;
  bool enabled_;
  bool drawn_ = false;
  Clock::time_point start_;
  Clock::time_point lastDraw_;
};

}  // namespace recode::app
