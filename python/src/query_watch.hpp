#pragma once
// Ctrl-C and progress for a call whose queries run without the GIL (collide_batch,
// collide_poses). Python runs signal handlers only when the main thread holds the GIL, so a call
// that released it for minutes would ignore Ctrl-C. Between queries, the thread that released
// the GIL takes it back briefly, at most once every kPollInterval: PyErr_CheckSignals runs the
// handlers (Ctrl-C's raises KeyboardInterrupt) and `progress(n)` hears of the n queries done since
// its last call. An exception from either stops the call: no query starts after it, the queries
// running finish, and the exception is raised once the call holds the GIL again. Worker threads
// only count the queries they finish and look at the stop flag.

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <exception>
#include <thread>

namespace recode::python {

namespace py = pybind11;

class QueryWatch {
 public:
  // Polls at most this often: Ctrl-C is heard within it (plus the query running), and
  // progress is called at most five times a second.
  static constexpr std::chrono::milliseconds kPollInterval{200};

  // Made with the GIL held, on the thread that will release it. `progress`: None or a callable
  // taking the number of queries done since its last call (tqdm's update); a TypeError otherwise.
  explicit QueryWatch(py::object progress);

  // Any thread, without the GIL: one more query has finished.
  void queryDone() { done_.fetch_add(1, std::memory_order_relaxed); }
  // Any thread: whether to stop starting queries.
  [[nodiscard]] bool stopped() const { return stopped_.load(std::memory_order_acquire); }
  // Any thread, without the GIL, between queries: on the thread that released the GIL, once
  // kPollInterval has passed since the last poll, runs the signal handlers and reports progress.
  void poll();
  // With the GIL held again, after the queries: raises what stopped them, or reports the
  // queries not yet reported.
  void finish();

 private:
  void report();  // with the GIL: progress(done - reported), when both are there

  py::object progress_;
  std::thread::id caller_ = std::this_thread::get_id();
  std::chrono::steady_clock::time_point nextPoll_;
  std::atomic<std::size_t> done_{0};
  std::size_t reported_ = 0;
  std::atomic<bool> stopped_{false};
  std::exception_ptr error_;  // what stopped the queries
};

}  // namespace recode::python
