#include "recode/conformance/reduce.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace recode::conformance {

namespace {

using raster::Command;
using raster::CommandStream;
namespace cmd = raster::cmd;

// Among the passing candidates of the last round, the twin is the one that changes fewest
// elements (one coordinate, one triangle, one command); of equal size, a moved value before a
// part taken away, since it shows more sharply what the failure needs. The order of the kinds.
enum class StepKind { Coordinate, Depth, State, Frame, Vertices, Triangles, Commands };

struct Step {
  StepKind kind = StepKind::Commands;
  long long units = 1;  // elements moved or removed
  std::string what;     // for the twin's description
};

bool smallerStep(const Step& a, const Step& b) {
  return std::pair(a.units, static_cast<int>(a.kind)) <
         std::pair(b.units, static_cast<int>(b.kind));
}

std::string opName(const Command& c) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, cmd::Scissor>)
          return "scissor";
        else if constexpr (std::is_same_v<T, cmd::ClearDepth>)
          return "clear_depth";
        else if constexpr (std::is_same_v<T, cmd::ClearStencil>)
          return "clear_stencil";
        else if constexpr (std::is_same_v<T, cmd::DepthFunc>)
          return "depth_func";
        else if constexpr (std::is_same_v<T, cmd::DepthWriteMask>)
          return "depth_write_mask";
        else if constexpr (std::is_same_v<T, cmd::StencilFunc>)
          return "stencil_func";
        else if constexpr (std::is_same_v<T, cmd::StencilOpsCmd>)
          return "stencil_ops";
        else if constexpr (std::is_same_v<T, cmd::StencilWriteMask>)
          return "stencil_write_mask";
        else if constexpr (std::is_same_v<T, cmd::Cull>)
          return "cull";
        else
          return "draw";
      },
      c);
}

std::string commandName(const CommandStream& s, std::size_t i) {
  return "command " + std::to_string(i) + " (" + opName(s.commands[i]) + ")";
}

std::string rangeName(const char* what, std::size_t begin, std::size_t end) {
  return end - begin == 1
             ? std::string(what) + " " + std::to_string(begin)
             : std::string(what) + "s " + std::to_string(begin) + " to " + std::to_string(end - 1);
}

// Enough digits to tell floats apart, and none more: 3 reads better than 3.000000.
std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  return buffer;
}

std::string count(long long n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

struct Shape {
  int draws = 0, triangles = 0;
};

Shape shapeOf(const CommandStream& s) {
  Shape out;
  for (const Command& c : s.commands) {
    if (const auto* d = std::get_if<cmd::Draw>(&c)) {
      ++out.draws;
      out.triangles += static_cast<int>(d->indices.size() / 3);
    }
  }
  return out;
}

std::string describe(const FailureSignature& s) {
  if (s.refused)
    return "is refused by the back end (stage " + std::string(toString(s.stage)) + ")";
  const std::string buffers = s.depth && s.stencil ? "depth and stencil"
                              : s.depth            ? "depth"
                                                   : "stencil";
  return "fails at pixel (" + std::to_string(s.x) + ", " + std::to_string(s.y) + "): " + buffers +
         ", stage " + std::string(toString(s.stage));
}

// Depths move only towards simpler floats, so that the rounds reach a fixpoint: 0 and 1, then
// 0.5, then fewer significant mantissa bits.
int depthRank(float z) {
  if (z == 0.0f)
    return 0;
  if (z == 1.0f)
    return 1;
  if (z == 0.5f)
    return 2;
  const std::uint32_t mantissa = std::bit_cast<std::uint32_t>(z) & 0x7FFFFFu;
  return 3 + (mantissa == 0 ? 0 : 23 - std::countr_zero(mantissa));
}

// z rounded to `bits` significant mantissa bits (to nearest, ties away): adding half an ulp of
// the shorter mantissa to the representation carries into the exponent where it must.
float withMantissaBits(float z, int bits) {
  const int drop = 23 - bits;
  const std::uint32_t half = 1u << (drop - 1);
  const std::uint32_t mask = ~((1u << drop) - 1u);
  const float r = std::bit_cast<float>((std::bit_cast<std::uint32_t>(z) + half) & mask);
  return std::min(r, 1.0f);
}

// A coordinate's simplicity: the trailing zero bits of its 24.8 fixed-point value, whole
// pixels (8 or more) all alike.
int coordinateLevel(long long fixed) {
  if (fixed == 0)
    return 8;
  return std::min(std::countr_zero(static_cast<std::uint64_t>(fixed < 0 ? -fixed : fixed)), 8);
}

long long floorDiv(long long a, long long b) {
  const long long q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

// The candidates for a coordinate of fixed-point value `fixed`, simplest first: the nearest
// whole pixel and the other one beside it, the nearest pixel centre, then the nearest multiple
// of 64, 32, ..., 2 sub-pixel steps. Every one is simpler than `fixed` (coordinateLevel), and
// within |X| <= 2^23 when `fixed` is, since 2^23 is a whole pixel.
std::vector<long long> simplerCoordinates(long long fixed) {
  std::vector<long long> out;
  const auto add = [&](long long v) {
    if (v != fixed && std::find(out.begin(), out.end(), v) == out.end())
      out.push_back(v);
  };
  const int level = coordinateLevel(fixed);
  if (level >= 8)
    return out;
  const long long below = floorDiv(fixed, 256) * 256;
  const long long above = below + 256;
  if (fixed - below <= above - fixed) {
    add(below);
    add(above);
  } else {
    add(above);
    add(below);
  }
  if (level < 7)
    add(below + 128);
  for (int b = 6; b > level; --b) {
    const long long step = 1LL << b;
    add(floorDiv(fixed + step / 2, step) * step);
  }
  return out;
}

// The values a state command's field moves to, simplest (the default) first; a field already
// at one of them moves only to those before it, so no two steps undo each other.
template <class V>
std::vector<V> simplerValues(const V& current, std::vector<V> simplest) {
  const auto at = std::find(simplest.begin(), simplest.end(), current);
  simplest.erase(at, simplest.end());
  return simplest;
}

enum class Verdict { SameFailure, Passes, OtherwiseFails };

class Reducer {
 public:
  Reducer(const CommandStream& stream, Backend& backend, const ReduceOptions& options)
      : current_(stream), backend_(backend), options_(options) {
    Answer expected;
    try {
      expected = referenceAnswer(stream);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("reduce: the stream is not valid: ") + e.what());
    }
    ++runs_;
    const std::optional<FailureSignature> s = signatureOf(stream, expected, backend_.run(stream));
    if (!s)
      throw std::invalid_argument("reduce: " + backend_.name() +
                                  " passes the stream: there is no failure to reduce");
    signature_ = *s;
  }

  void run() {
    // Each step that is taken makes the stream strictly smaller or simpler (fewer commands,
    // triangles, vertices or pixels, simpler values), so the rounds end even without a budget.
    while (budgetLeft()) {
      bool changed = false;
      // The frame first: every later run is on fewer pixels.
      if (shrinkFrame())
        changed = true;
      if (dropCommands())
        changed = true;
      if (dropTriangles())
        changed = true;
      if (compactVertices())
        changed = true;
      if (simplifyState())
        changed = true;
      if (simplifyCoordinates())
        changed = true;
      if (simplifyDepths())
        changed = true;
      if (!changed)
        break;
    }
  }

  [[nodiscard]] const FailureSignature& signature() const { return signature_; }
  [[nodiscard]] const CommandStream& minimal() const { return current_; }
  [[nodiscard]] long long runs() const { return runs_; }
  [[nodiscard]] const std::optional<std::pair<CommandStream, Step>>& twin() const { return twin_; }

 private:
  [[nodiscard]] bool budgetLeft() const { return runs_ < options_.maxBackendRuns; }

  Verdict judge(const CommandStream& candidate) {
    Answer expected;
    try {
      expected = referenceAnswer(candidate);
    } catch (const std::invalid_argument&) {
      // The steps keep streams valid; should one not be, it is no vector to commit.
      return Verdict::OtherwiseFails;
    }
    ++runs_;
    const std::optional<FailureSignature> s =
        signatureOf(candidate, expected, backend_.run(candidate));
    if (!s)
      return Verdict::Passes;
    return *s == signature_ ? Verdict::SameFailure : Verdict::OtherwiseFails;
  }

  // Takes the candidate when it fails the same way. A passing one is remembered as the twin
  // unless a smaller step already passed; any candidate taken forgets it, since it was one step
  // from a stream that is no longer the current one.
  bool attempt(CommandStream candidate, Step step) {
    if (!budgetLeft())
      return false;
    switch (judge(candidate)) {
      case Verdict::SameFailure:
        current_ = std::move(candidate);
        twin_.reset();
        return true;
      case Verdict::Passes:
        if (!twin_ || smallerStep(step, twin_->second))
          twin_.emplace(std::move(candidate), std::move(step));
        return false;
      case Verdict::OtherwiseFails:
        return false;
    }
    return false;
  }

  // The failing pixel is the first in scan order, so no pixel of a lower row, nor any to its
  // left in its row, differs: a frame ending at it keeps it first. A refusal has no pixel.
  bool shrinkFrame() {
    const int w = signature_.refused ? 1 : signature_.x + 1;
    const int h = signature_.refused ? 1 : signature_.y + 1;
    const std::pair<int, int> sizes[] = {{w, h}, {w, current_.height}, {current_.width, h}};
    for (const auto& [tw, th] : sizes) {
      if (tw > current_.width || th > current_.height ||
          (tw == current_.width && th == current_.height))
        continue;
      CommandStream c = current_;
      c.width = tw;
      c.height = th;
      if (attempt(std::move(c), {StepKind::Frame, 1,
                                 "the frame shrunk to " + std::to_string(tw) + " x " +
                                     std::to_string(th) + " pixels"}))
        return true;
    }
    return false;
  }

  // Chunks of half the commands, then quarters, down to one at a time (ddmin's complements).
  bool dropCommands() {
    bool changed = false;
    for (std::size_t chunk = std::max<std::size_t>(current_.commands.size() / 2, 1);; chunk /= 2) {
      for (std::size_t begin = 0; begin < current_.commands.size() && budgetLeft();) {
        const std::size_t end = std::min(begin + chunk, current_.commands.size());
        CommandStream c = current_;
        c.commands.erase(c.commands.begin() + static_cast<std::ptrdiff_t>(begin),
                         c.commands.begin() + static_cast<std::ptrdiff_t>(end));
        const std::string what = end - begin == 1 ? commandName(current_, begin) + " removed"
                                                  : rangeName("command", begin, end) + " removed";
        if (attempt(std::move(c), {StepKind::Commands, static_cast<long long>(end - begin), what}))
          changed = true;  // the same begin now names the commands after the removed ones
        else
          begin = end;
      }
      if (chunk <= 1)
        break;
    }
    return changed;
  }

  // Likewise within each draw; a draw whose last triangles go is dropped as a whole.
  bool dropTriangles() {
    bool changed = false;
    for (std::size_t ci = 0; ci < current_.commands.size() && budgetLeft();) {
      if (!std::holds_alternative<cmd::Draw>(current_.commands[ci])) {
        ++ci;
        continue;
      }
      const auto triangles = [&] {
        return std::get<cmd::Draw>(current_.commands[ci]).indices.size() / 3;
      };
      bool drawGone = false;
      for (std::size_t chunk = std::max<std::size_t>(triangles() / 2, 1); !drawGone; chunk /= 2) {
        for (std::size_t begin = 0; begin < triangles() && budgetLeft();) {
          const std::size_t end = std::min(begin + chunk, triangles());
          const bool whole = begin == 0 && end == triangles();
          CommandStream c = current_;
          Step step;
          if (whole) {
            c.commands.erase(c.commands.begin() + static_cast<std::ptrdiff_t>(ci));
            step = {StepKind::Commands, 1, commandName(current_, ci) + " removed"};
          } else {
            auto& indices = std::get<cmd::Draw>(c.commands[ci]).indices;
            indices.erase(indices.begin() + static_cast<std::ptrdiff_t>(3 * begin),
                          indices.begin() + static_cast<std::ptrdiff_t>(3 * end));
            step = {StepKind::Triangles, static_cast<long long>(end - begin),
                    rangeName("triangle", begin, end) + " of " + commandName(current_, ci) +
                        " removed"};
          }
          if (attempt(std::move(c), std::move(step))) {
            changed = true;
            if (whole) {
              drawGone = true;
              break;
            }
          } else {
            begin = end;
          }
        }
        if (chunk <= 1)
          break;
      }
      if (!drawGone)
        ++ci;
    }
    return changed;
  }

  // Vertices no index names: the contract never reads them, but a back end might.
  bool compactVertices() {
    bool changed = false;
    for (std::size_t ci = 0; ci < current_.commands.size() && budgetLeft(); ++ci) {
      const auto* draw = std::get_if<cmd::Draw>(&current_.commands[ci]);
      if (draw == nullptr)
        continue;
      std::vector<std::uint32_t> renumbered(draw->vertices.size(), 0);
      std::vector<bool> used(draw->vertices.size(), false);
      for (const std::uint32_t i : draw->indices)
        used[i] = true;
      cmd::Draw compact;
      for (std::size_t v = 0; v < draw->vertices.size(); ++v) {
        if (!used[v])
          continue;
        renumbered[v] = static_cast<std::uint32_t>(compact.vertices.size());
        compact.vertices.push_back(draw->vertices[v]);
      }
      const std::size_t removed = draw->vertices.size() - compact.vertices.size();
      if (removed == 0)
        continue;
      for (const std::uint32_t i : draw->indices)
        compact.indices.push_back(renumbered[i]);
      CommandStream c = current_;
      const std::string what = std::to_string(removed) + (removed == 1 ? " vertex" : " vertices") +
                               " that no index names removed from " + commandName(current_, ci);
      c.commands[ci] = std::move(compact);
      if (attempt(std::move(c), {StepKind::Vertices, static_cast<long long>(removed), what}))
        changed = true;
    }
    return changed;
  }

  // One field of command `ci` (of type T) moved to the first of `values` that still fails.
  template <class T, class V, class Field>
  bool moveField(std::size_t ci, const std::vector<V>& simplest, Field field, const char* name) {
    for (const V& v : simplerValues(field(std::get<T>(current_.commands[ci])), simplest)) {
      CommandStream c = current_;
      field(std::get<T>(c.commands[ci])) = v;
      if (attempt(std::move(c), {StepKind::State, 1,
                                 std::string(name) + " of " + commandName(current_, ci) +
                                     " set to its simplest value"}))
        return true;
    }
    return false;
  }

  bool simplifyState() {
    using raster::CompareFunc;
    using raster::StencilOp;
    bool changed = false;
    for (std::size_t ci = 0; ci < current_.commands.size() && budgetLeft(); ++ci) {
      const Command& c = current_.commands[ci];
      bool moved = false;
      if (std::holds_alternative<cmd::Scissor>(c)) {
        const raster::PixelRect whole{0, 0, current_.width, current_.height};
        // The clamped rectangle is what every device uses; its numbers are the frame's.
        const raster::PixelRect clamped = std::get<cmd::Scissor>(c).rect.intersect(whole);
        std::vector<raster::PixelRect> values{whole};
        if (clamped.empty())
          values.push_back({0, 0, 0, 0});
        if (std::find(values.begin(), values.end(), clamped) == values.end())
          values.push_back(clamped);
        moved = moveField<cmd::Scissor>(
            ci, values, [](cmd::Scissor& s) -> raster::PixelRect& { return s.rect; }, "the rect");
      } else if (std::holds_alternative<cmd::ClearDepth>(c)) {
        moved = moveField<cmd::ClearDepth>(
            ci, std::vector<double>{1.0, 0.0, 0.5},
            [](cmd::ClearDepth& s) -> double& { return s.value; }, "the value");
      } else if (std::holds_alternative<cmd::ClearStencil>(c)) {
        moved = moveField<cmd::ClearStencil>(
            ci, std::vector<std::uint8_t>{0},
            [](cmd::ClearStencil& s) -> std::uint8_t& { return s.value; }, "the value");
      } else if (std::holds_alternative<cmd::DepthFunc>(c)) {
        moved = moveField<cmd::DepthFunc>(
            ci, std::vector<CompareFunc>{CompareFunc::Less},
            [](cmd::DepthFunc& s) -> CompareFunc& { return s.func; }, "the func");
      } else if (std::holds_alternative<cmd::DepthWriteMask>(c)) {
        moved = moveField<cmd::DepthWriteMask>(
            ci, std::vector<bool>{true}, [](cmd::DepthWriteMask& s) -> bool& { return s.write; },
            "the mask");
      } else if (std::holds_alternative<cmd::StencilFunc>(c)) {
        moved =
            moveField<cmd::StencilFunc>(
                ci, std::vector<CompareFunc>{CompareFunc::Always},
                [](cmd::StencilFunc& s) -> CompareFunc& { return s.func; }, "the func") ||
            moveField<cmd::StencilFunc>(
                ci, std::vector<std::uint8_t>{0},
                [](cmd::StencilFunc& s) -> std::uint8_t& { return s.ref; }, "the ref") ||
            moveField<cmd::StencilFunc>(
                ci, std::vector<std::uint8_t>{0xFF},
                [](cmd::StencilFunc& s) -> std::uint8_t& { return s.valueMask; }, "the value mask");
      } else if (std::holds_alternative<cmd::StencilOpsCmd>(c)) {
        const std::vector<StencilOp> keep{StencilOp::Keep};
        moved = moveField<cmd::StencilOpsCmd>(
                    ci, std::vector<raster::Face>{raster::Face::Both},
                    [](cmd::StencilOpsCmd& s) -> raster::Face& { return s.face; }, "the face") ||
                moveField<cmd::StencilOpsCmd>(
                    ci, keep, [](cmd::StencilOpsCmd& s) -> StencilOp& { return s.ops.stencilFail; },
                    "sfail") ||
                moveField<cmd::StencilOpsCmd>(
                    ci, keep, [](cmd::StencilOpsCmd& s) -> StencilOp& { return s.ops.depthFail; },
                    "dpfail") ||
                moveField<cmd::StencilOpsCmd>(
                    ci, keep, [](cmd::StencilOpsCmd& s) -> StencilOp& { return s.ops.depthPass; },
                    "dppass");
      } else if (std::holds_alternative<cmd::StencilWriteMask>(c)) {
        moved = moveField<cmd::StencilWriteMask>(
            ci, std::vector<std::uint8_t>{0xFF},
            [](cmd::StencilWriteMask& s) -> std::uint8_t& { return s.mask; }, "the mask");
      } else if (std::holds_alternative<cmd::Cull>(c)) {
        moved = moveField<cmd::Cull>(
            ci, std::vector<raster::CullMode>{raster::CullMode::None},
            [](cmd::Cull& s) -> raster::CullMode& { return s.mode; }, "the mode");
      }
      if (moved)
        changed = true;
    }
    return changed;
  }

  bool simplifyCoordinates() {
    bool changed = false;
    for (std::size_t ci = 0; ci < current_.commands.size() && budgetLeft(); ++ci) {
      if (!std::holds_alternative<cmd::Draw>(current_.commands[ci]))
        continue;
      const std::size_t count = std::get<cmd::Draw>(current_.commands[ci]).vertices.size();
      for (std::size_t v = 0; v < count && budgetLeft(); ++v) {
        for (const int axis : {0, 1}) {
          const auto coordinate = [axis, v, ci](CommandStream& s) -> float& {
            raster::WindowVertex& w = std::get<cmd::Draw>(s.commands[ci]).vertices[v];
            return axis == 0 ? w.x : w.y;
          };
          const float now = coordinate(current_);
          // Inputs keep to the 1/256 grid (section 2); one that does not is snapped first.
          const long long fixed = std::llround(std::nearbyint(static_cast<double>(now) * 256.0));
          std::vector<long long> values = simplerCoordinates(fixed);
          if (static_cast<double>(fixed) != static_cast<double>(now) * 256.0)
            values.push_back(fixed);
          for (const long long x : values) {
            CommandStream c = current_;
            const float moved = static_cast<float>(static_cast<double>(x) / 256.0);
            coordinate(c) = moved;
            const std::string what = std::string(axis == 0 ? "x" : "y") + " of vertex " +
                                     std::to_string(v) + " of " + commandName(current_, ci) +
                                     " moved from " + number(now) + " to " + number(moved);
            if (attempt(std::move(c), {StepKind::Coordinate, 1, what})) {
              changed = true;
              break;
            }
          }
        }
      }
    }
    return changed;
  }

  bool simplifyDepths() {
    bool changed = false;
    for (std::size_t ci = 0; ci < current_.commands.size() && budgetLeft(); ++ci) {
      if (!std::holds_alternative<cmd::Draw>(current_.commands[ci]))
        continue;
      const std::size_t count = std::get<cmd::Draw>(current_.commands[ci]).vertices.size();
      for (std::size_t v = 0; v < count && budgetLeft(); ++v) {
        const auto depth = [v, ci](CommandStream& s) -> float& {
          return std::get<cmd::Draw>(s.commands[ci]).vertices[v].z;
        };
        const float now = depth(current_);
        const int rank = depthRank(now);
        std::vector<float> values;
        const auto add = [&](float z) {
          if (depthRank(z) < rank && std::find(values.begin(), values.end(), z) == values.end())
            values.push_back(z);
        };
        add(0.0f);
        add(1.0f);
        add(0.5f);
        if (now > 0.0f && now < 1.0f) {
          for (int bits = 0; bits < 23; ++bits)
            add(withMantissaBits(now, bits));
        }
        for (const float z : values) {
          CommandStream c = current_;
          depth(c) = z;
          const std::string what = "z of vertex " + std::to_string(v) + " of " +
                                   commandName(current_, ci) + " moved from " + number(now) +
                                   " to " + number(z);
          if (attempt(std::move(c), {StepKind::Depth, 1, what})) {
            changed = true;
            break;
          }
        }
      }
    }
    return changed;
  }

  CommandStream current_;
  Backend& backend_;
  const ReduceOptions& options_;
  FailureSignature signature_;
  long long runs_ = 0;
  std::optional<std::pair<CommandStream, Step>> twin_;
};

raster::GoldenVector goldenOf(const CommandStream& s, std::string description) {
  Answer a = referenceAnswer(s);
  return {std::move(description), s, std::move(a.depth), std::move(a.stencil)};
}

}  // namespace

std::optional<FailureSignature> signatureOf(const raster::CommandStream& stream,
                                            const Answer& expected, const Answer& got) {
  if (expected.wasRefused() || got.wasRefused()) {
    if (expected.wasRefused() == got.wasRefused())
      return std::nullopt;
    FailureSignature s;
    s.refused = got.wasRefused();
    s.stage = Stage::Validation;
    return s;
  }
  if (expected == got)
    return std::nullopt;
  const auto pixels =
      static_cast<std::size_t>(stream.width) * static_cast<std::size_t>(stream.height);
  if (expected.depth.size() != pixels || expected.stencil.size() != pixels ||
      got.depth.size() != pixels || got.stencil.size() != pixels)
    throw std::invalid_argument("signatureOf: an answer's buffers are not the stream's size");
  const std::vector<BadPixel> first = badPixels(stream, expected, got, 1);
  FailureSignature s;
  s.x = first.front().x;
  s.y = first.front().y;
  s.depth = first.front().depthDiffers();
  s.stencil = first.front().stencilDiffers();
  s.stage = failingStage(stream, expected, got, {});
  return s;
}

Reduction reduce(const raster::CommandStream& stream, Backend& backend,
                 const ReduceOptions& options) {
  Reducer reducer(stream, backend, options);
  reducer.run();

  const Shape before = shapeOf(stream);
  Reduction out;
  out.signature = reducer.signature();
  out.backendRuns = reducer.runs();
  const Shape after = shapeOf(reducer.minimal());
  out.draws = after.draws;
  out.triangles = after.triangles;
  const std::string name = backend.name();
  const std::string failure = describe(out.signature);
  out.minimal =
      goldenOf(reducer.minimal(),
               "Reduced by delta debugging from a stream of " +
                   count(static_cast<long long>(stream.commands.size()), "command") + " (" +
                   count(before.draws, "draw") + ", " + count(before.triangles, "triangle") +
                   ") on " + std::to_string(stream.width) + " x " + std::to_string(stream.height) +
                   " pixels that " + name + " fails, to " + count(after.draws, "draw") + " and " +
                   count(after.triangles, "triangle") + " in " + count(out.backendRuns, "run") +
                   " of the back end; it still " + failure + ".");
  if (const auto& twin = reducer.twin()) {
    out.passingTwin = goldenOf(twin->first,
                               "Passing twin of a vector reduced by delta debugging, one "
                               "step from it (" +
                                   twin->second.what + "): " + name +
                                   " passes it, while the reduced vector " + failure + ".");
  }
  return out;
}

}  // namespace recode::conformance
