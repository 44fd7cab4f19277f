#pragma once
// A back end under test, as the conformance suite sees it: a command stream in, both buffers
// out. Three kinds: a DepthStencilDevice made in this process (DeviceBackend), a program in any
// language that speaks the line protocol of docs/conformance.md (ProcessBackend,
// process_backend.hpp), and the kit's reference model run with one of its wrong readings
// (ModelBackend), which the suite uses to name what a failing back end behaves like.

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "recode/kit/variants.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/device.hpp"

namespace recode::conformance {

// A back end's answer to one stream: its whole buffers (row-major, bottom row first, as
// DepthStencilDevice::readDepth returns them), or why it refused the stream.
struct Answer {
  std::vector<std::uint32_t> depth;
  std::vector<std::uint8_t> stencil;
  std::string refused;  // non-empty: the back end's validation refused the stream

  [[nodiscard]] bool wasRefused() const { return !refused.empty(); }
  friend bool operator==(const Answer&, const Answer&) = default;
};

// How a back end broke its side of the protocol, for the reports that CI reads (JUnit's error
// type, the JSON's "error_kind").
enum class BackendFailure {
  Crashed,    // it exited, or was killed by a signal, before it answered
  TimedOut,   // no answer within the timeout
  Flooded,    // an answer longer than its bound
  Malformed,  // an answer that is not JSON or breaks the protocol's rules
};
// "crashed", "timed out", "flooded", "malformed".
[[nodiscard]] std::string_view toString(BackendFailure f);

// The back end broke its side of the protocol (crashed, hung, flooded, answered garbage): an
// error of the run, not a failing vector.
class BackendError : public std::runtime_error {
 public:
  // `what`: the message, naming what the back end did.
  BackendError(BackendFailure kind, const std::string& what)
      : std::runtime_error(what), kind_(kind) {}
  // How it broke.
  [[nodiscard]] BackendFailure kind() const { return kind_; }

 private:
  BackendFailure kind_;
};

class Backend {
 public:
  virtual ~Backend() = default;
  // What the report calls it.
  [[nodiscard]] virtual std::string name() const = 0;
  // Runs `stream` on a fresh framebuffer of its size. Throws BackendError when the back end
  // cannot answer.
  [[nodiscard]] virtual Answer run(const raster::CommandStream& stream) = 0;
};

// Makes a fresh device of the given size (width, height in 1..16384).
using DeviceFactory =
    std::function<std::unique_ptr<raster::DepthStencilDevice>(int width, int height)>;

// A device of this process. A std::invalid_argument from the device while it replays the
// stream is its refusal; any other exception propagates.
class DeviceBackend final : public Backend {
 public:
  DeviceBackend(std::string name, DeviceFactory factory);
  [[nodiscard]] std::string name() const override { return name_; }
  [[nodiscard]] Answer run(const raster::CommandStream& stream) override;

 private:
  std::string name_;
  DeviceFactory factory_;
};

// The kit's independent reference model (kit/reference_model.hpp) with one reading of the
// contract: Variant::Contract, or a wrong one.
class ModelBackend final : public Backend {
 public:
  explicit ModelBackend(kit::Variant variant);
  [[nodiscard]] std::string name() const override;
  [[nodiscard]] Answer run(const raster::CommandStream& stream) override;

 private:
  kit::Variant variant_;
};

// The reference's own answer (raster::CpuDevice): what every vector's expected buffers are.
[[nodiscard]] Answer referenceAnswer(const raster::CommandStream& stream);

}  // namespace recode::conformance
