#pragma once
// A back end in another process and any language, driven over the line protocol
// recode-conform-1 (docs/conformance.md): JSON requests on its stdin, JSON answers on its
// stdout, one object per line. POSIX only.
//
// Nothing the child does can crash or hang the caller: every wait is bounded by the timeout, an
// answer longer than its bound is refused before it is parsed, stderr is drained as it comes
// (its last 4 KiB kept for messages), and a child that breaks the protocol is killed with its
// whole process group and reported as a BackendError naming what it did and how it broke
// (BackendFailure: crashed, timed out, flooded, malformed). The child's plumbing is
// src/child_process.hpp; this class is the protocol on top of it.

#include <chrono>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "recode/conformance/backend.hpp"

namespace recode::conformance {

// The protocol's name, which the greeting exchanges.
inline constexpr const char* kProtocol = "recode-conform-1";

// The bounds on a back end's time.
struct ProcessOptions {
  std::chrono::milliseconds timeout{60000};   // per message: the greeting, each answer
  std::chrono::milliseconds exitGrace{5000};  // after stdin is closed, before the kill
};

// The child's plumbing (src/child_process.hpp), private to the library.
class ChildProcess;

class ProcessBackend final : public Backend {
 public:
  // Starts `command` with /bin/sh -c and exchanges the greeting. Throws std::invalid_argument
  // for an empty command, std::system_error when no process can be made, and BackendError when
  // the back end does not greet as the protocol says, in time.
  explicit ProcessBackend(std::string command, ProcessOptions options = {});
  ~ProcessBackend() override;
  ProcessBackend(const ProcessBackend&) = delete;
  ProcessBackend& operator=(const ProcessBackend&) = delete;

  // The name the back end gave in its greeting.
  [[nodiscard]] std::string name() const override { return name_; }
  // Sends the stream as one request and checks the answer against the protocol's rules. Throws
  // BackendError, with its kind, when the back end breaks them, crashes or does not answer in
  // time; the back end has then been killed.
  [[nodiscard]] Answer run(const raster::CommandStream& stream) override;

  // The command as it was given.
  [[nodiscard]] const std::string& command() const { return command_; }

 private:
  // Sends a request line and returns the answer line (at most `limit` bytes).
  [[nodiscard]] std::string exchange(const std::string& request, std::size_t limit,
                                     const std::string& what);
  [[nodiscard]] nlohmann::json parsed(const std::string& line, const std::string& what);
  // Kills the child and throws BackendError of `kind` with `what` and the end of its stderr.
  [[noreturn]] void fail(BackendFailure kind, const std::string& what);
  std::string command_;
  ProcessOptions options_;
  std::string name_;
  long long nextId_ = 1;
  std::unique_ptr<ChildProcess> child_;
};

}  // namespace recode::conformance
