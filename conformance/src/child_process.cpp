#include "child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>
#include <thread>

namespace recode::conformance {

namespace {

using Clock = ChildProcess::Clock;

[[noreturn]] void throwErrno(const char* what) {
  throw std::system_error(errno, std::generic_category(), what);
}

void closeFd(int& fd) {
  if (fd >= 0)
    ::close(fd);
  fd = -1;
}

int remainingMs(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return left.count() <= 0 ? 0 : static_cast<int>(std::min<long long>(left.count(), 1 << 30));
}

// Writing to a child that has gone raises SIGPIPE, which would end this process: it is
// blocked around each write and a pending one consumed, so the write fails with EPIPE instead,
// without changing the process's signal disposition.
class SigpipeBlocked {
 public:
  SigpipeBlocked() {
    sigset_t pipe;
    sigemptyset(&pipe);
    sigaddset(&pipe, SIGPIPE);
    sigset_t pending;
    sigpending(&pending);
    wasPending_ = sigismember(&pending, SIGPIPE) == 1;
    pthread_sigmask(SIG_BLOCK, &pipe, &old_);
  }
  ~SigpipeBlocked() {
    if (!wasPending_) {
      sigset_t pipe;
      sigemptyset(&pipe);
      sigaddset(&pipe, SIGPIPE);
      const timespec zero{0, 0};
      while (sigtimedwait(&pipe, nullptr, &zero) == SIGPIPE) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlocked(const SigpipeBlocked&) = delete;
  SigpipeBlocked& operator=(const SigpipeBlocked&) = delete;

 private:
  sigset_t old_{};
  bool wasPending_ = false;
};

}  // namespace

ChildProcess::ChildProcess(const std::string& command) {
  int in[2], out[2], err[2];
  if (::pipe2(in, O_CLOEXEC) != 0)
    throwErrno("pipe");
  if (::pipe2(out, O_CLOEXEC) != 0) {
    const int e = errno;
    ::close(in[0]), ::close(in[1]);
    errno = e;
    throwErrno("pipe");
  }
  if (::pipe2(err, O_CLOEXEC) != 0) {
    const int e = errno;
    ::close(in[0]), ::close(in[1]), ::close(out[0]), ::close(out[1]);
    errno = e;
    throwErrno("pipe");
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]})
      ::close(fd);
    errno = e;
    throwErrno("fork");
  }
  if (pid == 0) {
    // The child: its own process group (so that a kill reaches everything it starts), the
    // pipes as its standard streams, SIGPIPE back to its default. Only async-signal-safe calls.
    ::setpgid(0, 0);
    ::dup2(in[0], 0);
    ::dup2(out[1], 1);
    ::dup2(err[1], 2);
    ::signal(SIGPIPE, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also here: whichever runs first, the group exists before a kill
  pid_ = pid;
  in_ = in[1];
  out_ = out[0];
  err_ = err[0];
  ::close(in[0]), ::close(out[1]), ::close(err[1]);
  for (int fd : {in_, out_, err_})
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
}

ChildProcess::~ChildProcess() {
  kill();
  closeFd(in_);
  closeFd(out_);
  closeFd(err_);
}

void ChildProcess::keepStderr(const char* data, std::size_t n) {
  stderrTail_.append(data, n);
  if (stderrTail_.size() > kStderrKept)
    stderrTail_.erase(0, stderrTail_.size() - kStderrKept);
}

// Reads what is there on `fd` without blocking, into `into` (stdout) or the kept tail of
// stderr (null); false at end of file. Stops once `into` holds more than `limit` bytes.
bool ChildProcess::drain(int fd, std::string* into, std::size_t limit) {
  if (fd < 0)
    return false;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      if (into != nullptr) {
        into->append(buffer, static_cast<std::size_t>(n));
        if (into->size() > limit)
          return true;  // the caller refuses the flood
      } else {
        keepStderr(buffer, static_cast<std::size_t>(n));
      }
      continue;
    }
    if (n == 0)
      return false;
    if (errno == EINTR)
      continue;
    return true;  // EAGAIN: nothing more for now
  }
}

// Waits for the child's exit for at most `grace`; true when it has exited.
bool ChildProcess::reap(std::chrono::milliseconds grace) {
  const auto deadline = Clock::now() + grace;
  while (!reaped_ && pid_ > 0) {
    const pid_t r = ::waitpid(pid_, &status_, WNOHANG);
    if (r == pid_ || (r < 0 && errno == ECHILD)) {
      reaped_ = true;
      break;
    }
    if (Clock::now() >= deadline)
      return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

void ChildProcess::kill() {
  if (pid_ > 0 && !killed_)
    ::kill(-pid_, SIGKILL);
  killed_ = true;
  reap(std::chrono::milliseconds(2000));
  if (!errClosed_ && !drain(err_, nullptr, 0))
    errClosed_ = true;
}

void ChildProcess::finish(std::chrono::milliseconds grace) {
  closeFd(in_);  // end of requests
  const auto deadline = Clock::now() + grace;
  // Drain its output while it winds down, so that a child blocked on a full pipe can exit.
  while (!reap(std::chrono::milliseconds(0)) && Clock::now() < deadline) {
    pollfd fds[2] = {{out_, POLLIN, 0}, {err_, POLLIN, 0}};
    const nfds_t n = out_ >= 0 ? 2 : 0;
    if (n == 0 || ::poll(fds, n, 10) <= 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    std::string discard;
    if (!drain(out_, &discard, 1 << 20))
      closeFd(out_);
    drain(err_, nullptr, 0);
  }
  kill();  // a child still running, or anything it left in its group
}

ChildReply ChildProcess::exchange(std::string_view request, std::size_t limit,
                                  Clock::time_point deadline) {
  const std::string line = std::string(request) + "\n";
  std::size_t written = 0;
  for (;;) {
    const std::size_t newline = pending_.find('\n');
    if (newline != std::string::npos) {
      if (written < line.size())
        return {ChildEvent::AnsweredEarly, {}};
      std::string answer = pending_.substr(0, newline);
      pending_.erase(0, newline + 1);
      if (answer.size() > limit)
        return {ChildEvent::TooLong, {}};
      return {ChildEvent::Line, std::move(answer)};
    }
    if (pending_.size() > limit)
      return {ChildEvent::TooLong, {}};
    if (outClosed_) {
      reap(std::chrono::milliseconds(1000));
      return {ChildEvent::OutputClosed, pending_};
    }
    const int wait = remainingMs(deadline);
    if (wait == 0)
      return {ChildEvent::TimedOut, {}};
    pollfd fds[3] = {{out_, POLLIN, 0},
                     {err_, errClosed_ ? short{0} : short{POLLIN}, 0},
                     {in_, written < line.size() ? short{POLLOUT} : short{0}, 0}};
    const int ready = ::poll(fds, 3, wait);
    if (ready < 0) {
      if (errno == EINTR)
        continue;
      throwErrno("poll");
    }
    if (fds[2].revents & (POLLOUT | POLLERR | POLLHUP)) {
      SigpipeBlocked guard;
      const ssize_t n = ::write(in_, line.data() + written, line.size() - written);
      if (n > 0) {
        written += static_cast<std::size_t>(n);
      } else if (n < 0 && errno == EPIPE) {
        reap(std::chrono::milliseconds(1000));
        return {ChildEvent::InputClosed, {}};
      }
    }
    if (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) {
      if (!drain(err_, nullptr, 0))
        errClosed_ = true;
    }
    if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) {
      if (!drain(out_, &pending_, limit + 1))
        outClosed_ = true;
    }
  }
}

std::string ChildProcess::exitText() const {
  if (!reaped_)
    return "closed its stdout";
  if (WIFEXITED(status_)) {
    const int code = WEXITSTATUS(status_);
    std::string text = "exited with status " + std::to_string(code);
    // The shell that runs the command reports a child killed by signal n as 128 + n.
    if (code > 128 && code < 128 + 65) {
      const char* name = sigabbrev_np(code - 128);
      if (name != nullptr)
        text += " (a shell's report of signal " + std::to_string(code - 128) + ", SIG" + name + ")";
    }
    return text;
  }
  if (WIFSIGNALED(status_)) {
    const int sig = WTERMSIG(status_);
    const char* name = sigabbrev_np(sig);
    return "was killed by signal " + std::to_string(sig) +
           (name != nullptr ? std::string(" (SIG") + name + ")" : std::string());
  }
  return "ended";
}

}  // namespace recode::conformance
