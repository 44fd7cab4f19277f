#include "recode/conformance/process_backend.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "child_process.hpp"
#include "recode/io/printable.hpp"
#include "recode/raster/golden.hpp"

namespace recode::conformance {

namespace {

using nlohmann::json;

constexpr std::size_t kGreetingLimit = 65536;
constexpr std::size_t kNameLimit = 200;
constexpr std::size_t kQuoted = 200;

std::string seconds(std::chrono::milliseconds d) {
  const long long ms = d.count();
  return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

// The first bytes of a line, inert in a terminal.
std::string excerpt(std::string_view line) {
  std::string q = io::printable(line.substr(0, kQuoted));
  return line.size() > kQuoted ? q + "..." : q;
}

// A value of an answer that breaks the protocol's rules: the JSON path and the rule.
struct BadValue {
  std::string what;
};

// Element i of the answer's array `key`, an integer in [0, max]; the JSON path names a bad one.
std::uint32_t integerIn(const json& v, const char* key, std::size_t i, std::uint32_t max) {
  if (v.is_number_unsigned() && v.get<std::uint64_t>() <= max)
    return static_cast<std::uint32_t>(v.get<std::uint64_t>());
  throw BadValue{std::string("answer.") + key + "[" + std::to_string(i) +
                 "]: expected an integer in 0.." + std::to_string(max) + ", got " +
                 excerpt(v.dump())};
}

}  // namespace

ProcessBackend::ProcessBackend(std::string command, ProcessOptions options)
    : command_(std::move(command)), options_(options) {
  if (command_.empty())
    throw std::invalid_argument("the back end's command is empty");
  child_ = std::make_unique<ChildProcess>(command_);

  const json hello =
      parsed(exchange(json{{"protocol", kProtocol}}.dump(), kGreetingLimit, "the greeting"),
             "the greeting");
  const auto malformed = [this](const std::string& what) { fail(BackendFailure::Malformed, what); };
  if (!hello.is_object())
    malformed("the greeting: the answer is not a JSON object");
  for (const auto& [key, value] : hello.items()) {
    if (key != "protocol" && key != "name")
      malformed("the greeting: unknown key \"" + io::printable(key) +
                "\" (allowed: protocol, name)");
  }
  if (!hello.contains("protocol") || hello["protocol"] != kProtocol) {
    malformed(std::string("the greeting: expected \"protocol\": \"") + kProtocol + "\", got " +
              (hello.contains("protocol") ? excerpt(hello["protocol"].dump()) : "no protocol"));
  }
  if (!hello.contains("name") || !hello["name"].is_string() ||
      hello["name"].get<std::string>().empty() ||
      hello["name"].get<std::string>().size() > kNameLimit) {
    malformed("the greeting: \"name\" must be a string of 1.." + std::to_string(kNameLimit) +
              " characters");
  }
  name_ = io::printable(hello["name"].get<std::string>());
}

ProcessBackend::~ProcessBackend() {
  if (child_)
    child_->finish(options_.exitGrace);
}

nlohmann::json ProcessBackend::parsed(const std::string& line, const std::string& what) {
  try {
    return json::parse(line);
  } catch (const json::parse_error&) {
    fail(BackendFailure::Malformed, what + ": answer is not JSON: \"" + excerpt(line) + "\"");
  }
}

[[noreturn]] void ProcessBackend::fail(BackendFailure kind, const std::string& what) {
  child_->kill();
  std::string message = "back end \"" + io::printable(command_) + "\": " + what;
  if (!child_->stderrTail().empty())
    message += "\n  its stderr ended with:\n" + io::printable(child_->stderrTail());
  throw BackendError(kind, message);
}

// Sends one request line and waits for one answer line; what the child did instead, named.
std::string ProcessBackend::exchange(const std::string& request, std::size_t limit,
                                     const std::string& what) {
  ChildReply reply =
      child_->exchange(request, limit, ChildProcess::Clock::now() + options_.timeout);
  switch (reply.event) {
    case ChildEvent::Line:
      return std::move(reply.text);
    case ChildEvent::AnsweredEarly:
      fail(BackendFailure::Malformed, what + ": answered before the request was read whole");
    case ChildEvent::TooLong:
      fail(BackendFailure::Flooded,
           what + ": answer longer than " + std::to_string(limit) + " bytes");
    case ChildEvent::TimedOut:
      fail(BackendFailure::TimedOut, what + ": no answer within " + seconds(options_.timeout));
    case ChildEvent::OutputClosed:
      fail(BackendFailure::Crashed,
           what + ": the back end " + child_->exitText() +
               (reply.text.empty() ? ""
                                   : " after an unfinished line: \"" + excerpt(reply.text) + "\""));
    case ChildEvent::InputClosed:
      fail(BackendFailure::Crashed,
           what + ": the back end " + child_->exitText() + " (its stdin is closed)");
  }
  fail(BackendFailure::Malformed, what + ": no answer");
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
  const auto malformed = [&](const std::string& rule) {
    fail(BackendFailure::Malformed, what + ": " + rule);
  };
  if (!a.is_object())
    malformed("the answer is not a JSON object");
  const bool refused = a.contains("refused");
  for (const auto& [key, value] : a.items()) {
    const bool allowed =
        key == "id" || (refused ? key == "refused" : key == "depth" || key == "stencil");
    if (!allowed) {
      malformed("answer." + io::printable(key) + ": unknown key (allowed: " +
                (refused ? "id, refused" : "id, depth, stencil") + ")");
    }
  }
  if (!a.contains("id") || !a["id"].is_number_integer() || a["id"].get<long long>() != id) {
    malformed("answer.id: expected " + std::to_string(id) + ", got " +
              (a.contains("id") ? excerpt(a["id"].dump()) : "none"));
  }
  Answer out;
  if (refused) {
    if (!a["refused"].is_string() || a["refused"].get<std::string>().empty())
      malformed("answer.refused: expected a non-empty string saying why");
    out.refused = io::printable(a["refused"].get<std::string>());
    return out;
  }
  for (const char* key : {"depth", "stencil"}) {
    if (!a.contains(key))
      malformed(std::string("answer.") + key +
                ": missing (an answer has depth and stencil, or refused)");
    if (!a[key].is_array() || a[key].size() != pixels) {
      malformed(
          std::string("answer.") + key +
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
  } catch (const BadValue& e) {
    malformed(e.what);
  }
  return out;
}

}  // namespace recode::conformance
