#pragma once
// A program run as a child of this process, talked to one line at a time: `/bin/sh -c COMMAND`
// in a process group of its own, its stdin, stdout and stderr as pipes. The plumbing under
// ProcessBackend (process_backend.hpp), which adds the protocol: this file knows nothing of
// JSON or of what a line means.
//
// Nothing the child does can block the caller past a deadline: every wait is a poll with the
// time left, stdout is read into a buffer that stops at the caller's limit, stderr is drained
// whenever the child is waited on (its last 4 KiB kept), and a write to a child that has gone
// fails with EPIPE instead of raising SIGPIPE in this process.

#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace recode::conformance {

// How one exchange with the child ended.
enum class ChildEvent {
  Line,           // a whole line came
  OutputClosed,   // the child closed its stdout (it exited, or crashed) before a whole line
  InputClosed,    // the child closed its stdin before the request was written whole
  TimedOut,       // no whole line before the deadline
  TooLong,        // the line (or what came of it) is longer than the limit
  AnsweredEarly,  // a line came before the request was written whole
};

// What an exchange gave.
struct ChildReply {
  // How it ended.
  ChildEvent event = ChildEvent::Line;
  // Line: the line without its '\n'; OutputClosed: an unfinished line, if one came.
  std::string text;
};

class ChildProcess {
 public:
  using Clock = std::chrono::steady_clock;

  // The bytes of the child's stderr kept for messages.
  static constexpr std::size_t kStderrKept = 4096;

  // Starts `command` with /bin/sh -c. Throws std::system_error when the pipes or the process
  // cannot be made (a command that does not exist is a child that exits with status 127).
  explicit ChildProcess(const std::string& command);
  // Kills the child's process group, if it is still there, and reaps the child.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // Writes `request` and a newline to the child's stdin while waiting, until `deadline`, for
  // the next line of its stdout of at most `limit` bytes; drains its stderr all along. After
  // OutputClosed or InputClosed the child has been waited for (a second at most), so that
  // exitText() can say how it ended. Throws std::system_error when poll fails.
  [[nodiscard]] ChildReply exchange(std::string_view request, std::size_t limit,
                                    Clock::time_point deadline);

  // Closes the child's stdin (the end of requests) and waits up to `grace` for it to exit,
  // draining its output so that a child blocked on a full pipe can; then kills what is left of
  // its process group.
  void finish(std::chrono::milliseconds grace);

  // Kills the child's whole process group (a shell's children too), reaps it and keeps what
  // was left on its stderr.
  void kill();

  // How the child ended: "exited with status 3", "was killed by signal 11 (SIGSEGV)", a
  // shell's report of a signal spelt out, or "closed its stdout" while it still runs.
  [[nodiscard]] std::string exitText() const;

  // The last kStderrKept bytes the child wrote to its stderr.
  [[nodiscard]] const std::string& stderrTail() const { return stderrTail_; }

 private:
  bool drain(int fd, std::string* into, std::size_t limit);
  bool reap(std::chrono::milliseconds grace);
  void keepStderr(const char* data, std::size_t n);

  pid_t pid_ = -1;
  int in_ = -1, out_ = -1, err_ = -1;  // its stdin (we write), stdout and stderr (we read)
  std::string pending_;                // stdout read past the last whole line
  std::string stderrTail_;
  bool outClosed_ = false, errClosed_ = false;
  bool reaped_ = false, killed_ = false;
  int status_ = 0;
};

}  // namespace recode::conformance
