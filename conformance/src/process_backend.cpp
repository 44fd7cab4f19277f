#include "recode/conformance/process_backend.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string_view>
#include <thread>
#include <utility>

#include "recode/io/printable.hpp"
#include "recode/raster/golden.hpp"

namespace recode::conformance {

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;

constexpr std::size_t kStderrKept = 4096;
constexpr std::size_t kGreetingLimit = 65536;
constexpr std::size_t kNameLimit = 200;
constexpr std::size_t kQuoted = 200;

std::string errnoText(const char* what) {
  return std::string(what) + ": " + std::strerror(errno);
}

std::string seconds(std::chrono::milliseconds d) {
  const long long ms = d.count();
  return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

// The first bytes of a line, inert in a terminal.
std::string excerpt(std::string_view line) {
  std::string q = io::printable(line.substr(0, kQuoted));
  return line.size() > kQuoted ? q + "..." : q;
}

// Element i of the answer's array `key`, an integer in [0, max]; the JSON path names a bad one.
std::uint32_t integerIn(const json& v, const char* key, std::size_t i, std::uint32_t max) {
  if (v.is_number_unsigned() && v.get<std::uint64_t>() <= max)
    return static_cast<std::uint32_t>(v.get<std::uint64_t>());
  throw BackendError(std::string("answer.") + key + "[" + std::to_string(i) +
                     "]: expected an integer in 0.." + std::to_string(max) + ", got " +
                     excerpt(v.dump()));
}

}  // namespace

// The child's process and the parent's ends of its three pipes.
struct ProcessBackend::Child {
  pid_t pid = -1;
  int in = -1, out = -1, err = -1;  // its stdin (we write), stdout and stderr (we read)
  std::string pending;              // stdout read past the last full line
  std::string stderrTail;           // the last kStderrKept bytes of its stderr
  bool outClosed = false, errClosed = false;
  bool reaped = false;
  int status = 0;

  ~Child() {
    closeFd(in);
    closeFd(out);
    closeFd(err);
  }
  static void closeFd(int& fd) {
    if (fd >= 0)
      ::close(fd);
    fd = -1;
  }

  void keepStderr(const char* data, std::size_t n) {
    stderrTail.append(data, n);
    if (stderrTail.size() > kStderrKept)
      stderrTail.erase(0, stderrTail.size() - kStderrKept);
  }

  // Reads what is there on `fd` without blocking; false at end of file.
  bool drain(int fd, std::string* into, std::size_t limit) {
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
  bool reap(std::chrono::milliseconds grace) {
    const auto deadline = Clock::now() + grace;
    while (!reaped) {
      const pid_t r = ::waitpid(pid, &status, WNOHANG);
      if (r == pid || (r < 0 && errno == ECHILD)) {
        reaped = true;
        break;
      }
      if (Clock::now() >= deadline)
        return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
  }

  // Kills the child's whole process group (a shell's children too) and reaps it.
  void kill() {
    if (pid > 0)
      ::kill(-pid, SIGKILL);
    reap(std::chrono::milliseconds(2000));
  }

  [[nodiscard]] std::string exitText() const {
    if (!reaped)
      return "closed its stdout";
    if (WIFEXITED(status)) {
      const int code = WEXITSTATUS(status);
      std::string text = "exited with status " + std::to_string(code);
      // The shell that runs the command reports a child killed by signal n as 128 + n.
      if (code > 128 && code < 128 + 65) {
        const char* name = sigabbrev_np(code - 128);
        if (name != nullptr)
          text +=
              " (a shell's report of signal " + std::to_string(code - 128) + ", SIG" + name + ")";
      }
      return text;
    }
    if (WIFSIGNALED(status)) {
      const int sig = WTERMSIG(status);
      const char* name = sigabbrev_np(sig);
      return "was killed by signal " + std::to_string(sig) +
             (name != nullptr ? std::string(" (SIG") + name + ")" : std::string());
    }
    return "ended";
  }
};

namespace {

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

int remainingMs(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return left.count() <= 0 ? 0 : static_cast<int>(std::min<long long>(left.count(), 1 << 30));
}

}  // namespace

ProcessBackend::ProcessBackend(std::string command, ProcessOptions options)
    : command_(std::move(command)), options_(options) {
  if (command_.empty())
    throw BackendError("--exec: the command is empty");
  int in[2], out[2], err[2];
  if (::pipe2(in, O_CLOEXEC) != 0)
    throw BackendError(errnoText("pipe"));
  if (::pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]), ::close(in[1]);
    throw BackendError(errnoText("pipe"));
  }
  if (::pipe2(err, O_CLOEXEC) != 0) {
    ::close(in[0]), ::close(in[1]), ::close(out[0]), ::close(out[1]);
    throw BackendError(errnoText("pipe"));
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]})
      ::close(fd);
    throw BackendError(errnoText("fork"));
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
    ::execl("/bin/sh", "sh", "-c", command_.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also here: whichever runs first, the group exists before a kill
  child_ = std::make_unique<Child>();
  child_->pid = pid;
  child_->in = in[1];
  child_->out = out[0];
  child_->err = err[0];
  ::close(in[0]), ::close(out[1]), ::close(err[1]);
  for (int fd : {child_->in, child_->out, child_->err})
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);

  const json hello =
      parsed(exchange(json{{"protocol", kProtocol}}.dump(), kGreetingLimit, "the greeting"),
             "the greeting");
  if (!hello.is_object())
    fail("the greeting: the answer is not a JSON object");
  for (const auto& [key, value] : hello.items()) {
    if (key != "protocol" && key != "name")
      fail("the greeting: unknown key \"" + io::printable(key) + "\" (allowed: protocol, name)");
  }
  if (!hello.contains("protocol") || hello["protocol"] != kProtocol) {
    fail(std::string("the greeting: expected \"protocol\": \"") + kProtocol + "\", got " +
         (hello.contains("protocol") ? excerpt(hello["protocol"].dump()) : "no protocol"));
  }
  if (!hello.contains("name") || !hello["name"].is_string() ||
      hello["name"].get<std::string>().empty() ||
      hello["name"].get<std::string>().size() > kNameLimit) {
    fail("the greeting: \"name\" must be a string of 1.." + std::to_string(kNameLimit) +
         " characters");
  }
  name_ = io::printable(hello["name"].get<std::string>());
}

ProcessBackend::~ProcessBackend() {
  if (!child_)
    return;
  Child::closeFd(child_->in);  // end of requests
  const auto deadline = Clock::now() + options_.exitGrace;
  // Drain its output while it winds down, so that a child blocked on a full pipe can exit.
  while (!child_->reap(std::chrono::milliseconds(0)) && Clock::now() < deadline) {
    pollfd fds[2] = {{child_->out, POLLIN, 0}, {child_->err, POLLIN, 0}};
    const nfds_t n = child_->out >= 0 ? 2 : 0;
    if (n == 0 || ::poll(fds, n, 10) <= 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    std::string discard;
    if (!child_->drain(child_->out, &discard, 1 << 20))
      Child::closeFd(child_->out);
    child_->drain(child_->err, nullptr, 0);
  }
  child_->kill();  // a child still running, or anything it left in its group
}

nlohmann::json ProcessBackend::parsed(const std::string& line, const std::string& what) {
  try {
    return json::parse(line);
  } catch (const json::parse_error&) {
    fail(what + ": answer is not JSON: \"" + excerpt(line) + "\"");
  }
}

[[noreturn]] void ProcessBackend::fail(const std::string& what) {
  child_->kill();
  child_->drain(child_->err, nullptr, 0);
  std::string message = "back end \"" + io::printable(command_) + "\": " + what;
  if (!child_->stderrTail.empty())
    message += "\n  its stderr ended with:\n" + io::printable(child_->stderrTail);
  throw BackendError(message);
}

// Sends one request line and waits for one answer line, pumping stderr all along.
std::string ProcessBackend::exchange(const std::string& request, std::size_t limit,
                                     const std::string& what) {
  Child& c = *child_;
  const auto deadline = Clock::now() + options_.timeout;
  const std::string line = request + "\n";
  std::size_t written = 0;
  for (;;) {
    const std::size_t newline = c.pending.find('\n');
    if (newline != std::string::npos) {
      if (written < line.size())
        fail(what + ": answered before the request was read whole");
      std::string answer = c.pending.substr(0, newline);
      c.pending.erase(0, newline + 1);
      if (answer.size() > limit)
        fail(what + ": answer longer than " + std::to_string(limit) + " bytes");
      return answer;
    }
    if (c.pending.size() > limit)
      fail(what + ": answer longer than " + std::to_string(limit) + " bytes");
    if (c.outClosed) {
      c.reap(std::chrono::milliseconds(1000));
      fail(what + ": the back end " + c.exitText() +
           (c.pending.empty() ? "" : " after an unfinished line: \"" + excerpt(c.pending) + "\""));
    }
    const int wait = remainingMs(deadline);
    if (wait == 0)
      fail(what + ": no answer within " + seconds(options_.timeout));
    pollfd fds[3] = {{c.out, POLLIN, 0},
                     {c.err, c.errClosed ? short{0} : short{POLLIN}, 0},
                     {c.in, written < line.size() ? short{POLLOUT} : short{0}, 0}};
    const int ready = ::poll(fds, 3, wait);
    if (ready < 0) {
      if (errno == EINTR)
        continue;
      fail(errnoText("poll"));
    }
    if (fds[2].revents & (POLLOUT | POLLERR | POLLHUP)) {
      SigpipeBlocked guard;
      const ssize_t n = ::write(c.in, line.data() + written, line.size() - written);
      if (n > 0) {
        written += static_cast<std::size_t>(n);
      } else if (n < 0 && errno == EPIPE) {
        c.reap(std::chrono::milliseconds(1000));
        fail(what + ": the back end " + c.exitText() + " (its stdin is closed)");
      }
    }
    if (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) {
      if (!c.drain(c.err, nullptr, 0))
        c.errClosed = true;
    }
    if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) {
      if (!c.drain(c.out, &c.pending, limit + 1))
        c.outClosed = true;
    }
  }
}

Answer ProcessBackend::run(const raster::CommandStream& stream) {
  const long long id = nextId_++;
  const json doc = json::parse(raster::commandStreamToJson(stream));
  const json request = {{"id", id},
                        {"width", stream.width},
                        {"height", stream.height},
                        {"commands", doc["commands"]}};
  const std::size_t pixels =
      static_cast<std::size_t>(stream.width) * static_cast<std::size_t>(stream.height);
  const std::size_t limit = 16 * pixels + 65536;
  const std::string what = "request " + std::to_string(id);
  const json a = parsed(exchange(request.dump(), limit, what), what);
  if (!a.is_object())
    fail(what + ": the answer is not a JSON object");
  const bool refused = a.contains("refused");
  for (const auto& [key, value] : a.items()) {
    const bool allowed =
        key == "id" || (refused ? key == "refused" : key == "depth" || key == "stencil");
    if (!allowed) {
      fail(what + ": answer." + io::printable(key) +
           ": unknown key (allowed: " + (refused ? "id, refused" : "id, depth, stencil") + ")");
    }
  }
  if (!a.contains("id") || !a["id"].is_number_integer() || a["id"].get<long long>() != id) {
    fail(what + ": answer.id: expected " + std::to_string(id) + ", got " +
         (a.contains("id") ? excerpt(a["id"].dump()) : "none"));
  }
  Answer out;
  if (refused) {
    if (!a["refused"].is_string() || a["refused"].get<std::string>().empty())
      fail(what + ": answer.refused: expected a non-empty string saying why");
    out.refused = io::printable(a["refused"].get<std::string>());
    return out;
  }
  for (const char* key : {"depth", "stencil"}) {
    if (!a.contains(key))
      fail(what + ": answer." + key + ": missing (an answer has depth and stencil, or refused)");
    if (!a[key].is_array() || a[key].size() != pixels) {
      fail(
          what + ": answer." + key +
          ": expected an array of width x height = " + std::to_string(pixels) + " integers, got " +
          (a[key].is_array() ? std::to_string(a[key].size()) + " values" : excerpt(a[key].dump())));
    }
  }
  out.depth.resize(pixels);
  out.stencil.resize(pixels);
  const json& depth = a["depth"];
  const json& stencil = a["stencil"];
  try {
    for (std::size_t i = 0; i < pixels; ++i) {
      out.depth[i] = integerIn(depth[i], "depth", i, 16777215u);
      out.stencil[i] = static_cast<std::uint8_t>(integerIn(stencil[i], "stencil", i, 255u));
    }
  } catch (const BackendError& e) {
    fail(what + ": " + e.what());
  }
  return out;
}

}  // namespace recode::conformance
