#include "query_watch.hpp"

#include <string>
#include <utility>

namespace recode::python {

QueryWatch::QueryWatch(py::object progress)
    : progress_(std::move(progress)), nextPoll_(std::chrono::steady_clock::now() + kPollInterval) {
  if (!progress_.is_none() && !PyCallable_Check(progress_.ptr()))
    throw py::type_error(
        "progress: expected a callable taking the number of queries done since "
        "its last call (e.g. a tqdm bar's update), got " +
        py::str(py::type::of(progress_)).cast<std::string>());
}

void QueryWatch::poll() {
  if (std::this_thread::get_id() != caller_ || stopped())
    return;
  const auto now = std::chrono::steady_clock::now();
  if (now < nextPoll_)
    return;
  nextPoll_ = now + kPollInterval;
  const py::gil_scoped_acquire gil;
  try {
    if (PyErr_CheckSignals() != 0)
      throw py::error_already_set();
    report();
  } catch (...) {
    error_ = std::current_exception();
    stopped_.store(true, std::memory_order_release);
  }
}

void QueryWatch::finish() {
  if (error_)
    std::rethrow_exception(error_);
  report();
}

void QueryWatch::report() {
  const std::size_t done = done_.load(std::memory_order_relaxed);
  if (progress_.is_none() || done == reported_)
    return;
  const std::size_t n = done - reported_;
  reported_ = done;
  progress_(n);
}

}  // namespace recode::python
