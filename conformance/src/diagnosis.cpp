#include "recode/conformance/diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <variant>

#include "contract_arithmetic.hpp"
#include "reading_class.hpp"

namespace recode::conformance {

using kit::Variant;

Stage stageOf(Variant v) {
  return classOf(v).stage;
}

namespace {

std::size_t at(const raster::CommandStream& s, int x, int y) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(s.width) +
         static_cast<std::size_t>(x);
}

// The triangles whose coverage of the sample was decided by a tie: an edge value exactly 0.
bool decidedByTie(const TriangleEvent& t) {
  return t.outcome == TriangleOutcome::ExcludedByTie ||
         (t.outcome == TriangleOutcome::Fragment &&
          std::any_of(std::begin(t.edges), std::end(t.edges),
                      [](const EdgeAtSample& e) { return e.value == 0; }));
}

std::string triangleName(const TriangleEvent& t) {
  return "triangle " + std::to_string(t.triangle) + " of draw " + std::to_string(t.draw) +
         " (command " + std::to_string(t.command) + ")";
}

// A quantisation at, or within 1e-3 of, a rounding tie (z * 16777215 = k + 0.5): where other
// roundings than the contract's part from it, so a depth a unit or two off there is the rounding.
bool nearRoundingTie(const Quantisation& q) {
  return q.tie || std::abs(q.scaled - std::floor(q.scaled) - 0.5) < 1e-3;
}

std::string roundingTieWhy(const std::string& what, const Quantisation& q) {
  return what + " at " + (q.tie ? std::string("a tie") : std::string("almost a tie")) +
         ", which the contract rounds to " + std::to_string(q.q);
}

std::string onEdgeWhy(const TriangleEvent& t) {
  return "the sample lies exactly on an edge of " + triangleName(t) + ", which " +
         (t.outcome == TriangleOutcome::Fragment ? "covers it (the edge is inclusive)"
                                                 : "does not cover it (the edge is not "
                                                   "inclusive)") +
         ": the fill rule decides";
}

// The pixel's depth and stencil just before and just after an event (equal when it changed
// nothing: a clear outside the scissor or under a closed write mask, a triangle without a
// fragment, a fragment whose ops kept both).
struct EventState {
  std::uint32_t depthBefore = 0, depthAfter = 0;
  std::uint8_t stencilBefore = 0, stencilAfter = 0;
  [[nodiscard]] bool changes() const {
    return depthBefore != depthAfter || stencilBefore != stencilAfter;
  }
};

EventState stateOf(const HistoryEvent& e) {
  if (e.clear)
    return {e.clear->depthBefore, e.clear->depthAfter, e.clear->stencilBefore,
            e.clear->stencilAfter};
  if (e.triangle)
    return {e.triangle->depthBefore, e.triangle->depthAfter, e.triangle->stencilBefore,
            e.triangle->stencilAfter};
  return {};
}

// ---- A comparison that went the other way ----
//
// The pixel's history replayed with the stencil and depth tests free to go either way: the
// latest fragment up to which the contract can be followed, and from whose comparison on the
// back end's values can be reached, is where its first wrong event lies. This reads any wrong
// reading of the compare operations, listed in the kit or not, from the history alone.

struct PixelValues {
  std::uint32_t depth = 0;
  std::uint8_t stencil = 0;
  bool operator==(const PixelValues&) const = default;
};

// How a replayed fragment's comparisons go: as the contract runs them, the stencil test's or
// the depth test's outcome the other way (the other test as the contract runs it), or either
// test either way.
enum class Compare { Contract, StencilOther, DepthOther, Free };

// The render state in force at each draw command of the stream, by command index.
using DrawStates = std::map<int, raster::RenderState>;

DrawStates drawStates(const raster::CommandStream& stream) {
  DrawStates out;
  raster::RenderState st = raster::initialRenderState(stream.width, stream.height);
  for (std::size_t ci = 0; ci < stream.commands.size(); ++ci) {
    const raster::Command& cmd = stream.commands[ci];
    if (raster::applyToState(cmd, st, stream.width, stream.height))
      continue;
    if (std::holds_alternative<raster::cmd::Draw>(cmd))
      out[static_cast<int>(ci)] = st;
  }
  return out;
}

// Whether a compare function compares: ALWAYS and NEVER cannot go the other way.
bool compares(raster::CompareFunc f) {
  return f != raster::CompareFunc::Always && f != raster::CompareFunc::Never;
}

// A pixel's states in a replay: too many of them ends it (an answer no replay reaches).
constexpr std::size_t kMaxReplayStates = 4096;
// Histories longer than this are not replayed (the search is quadratic in their length).
constexpr std::size_t kMaxReplayEvents = 256;

void addState(std::vector<PixelValues>& out, PixelValues v) {
  if (std::find(out.begin(), out.end(), v) == out.end())
    out.push_back(v);
}

// The outcomes a comparison may have in a replay: the contract's `result`, its other one, or
// both; none when it is asked to go the other way and cannot.
std::vector<bool> outcomes(bool result, bool canFlip, bool other, bool free) {
  if (other)
    return canFlip ? std::vector<bool>{!result} : std::vector<bool>{};
  if (free && canFlip)
    return {result, !result};
  return {result};
}

// One event of the history applied to every state of `in`, its comparisons as `how` says;
// with `ignoreScissor`, a clear the scissor keeps from the pixel is applied all the same.
std::vector<PixelValues> replay(const HistoryEvent& e, const DrawStates& states, Compare how,
                                const std::vector<PixelValues>& in, bool ignoreScissor = false,
                                bool drawExcluded = false) {
  std::vector<PixelValues> out;
  if (e.clear) {
    const ClearEvent& c = *e.clear;
    const bool reaches = !c.outsideScissor || ignoreScissor;
    for (PixelValues v : in) {
      if (reaches && c.depth && !c.skipped)
        v.depth = c.quantisation.q;
      else if (reaches && !c.depth)
        v.stencil = contract::masked(static_cast<std::uint8_t>(c.value), v.stencil, c.writeMask);
      addState(out, v);
    }
    return out;
  }
  const bool drawn =
      e.triangle && (e.triangle->outcome == TriangleOutcome::Fragment ||
                     (drawExcluded && e.triangle->outcome == TriangleOutcome::ExcludedByTie));
  if (!drawn)
    return in;
  const TriangleEvent& t = *e.triangle;
  const raster::RenderState& st = states.at(t.command);
  const raster::StencilOps& ops = st.opsFor(t.front);
  // A sample on an edge: whether the fragment exists is the fill rule's, not a comparison's.
  const bool flippable = !decidedByTie(t);
  const bool free = how == Compare::Free && flippable;
  for (const PixelValues& v : in) {
    const bool stencilResult = contract::compare(
        st.stencilFunc, static_cast<std::uint32_t>(st.stencilRef & st.stencilValueMask),
        static_cast<std::uint32_t>(v.stencil & st.stencilValueMask));
    for (const bool stencilPass : outcomes(stencilResult, flippable && compares(st.stencilFunc),
                                           how == Compare::StencilOther, free)) {
      if (!stencilPass) {
        if (how == Compare::DepthOther)
          continue;  // the depth test runs only when the stencil test passes
        addState(out, {v.depth, contract::masked(
                                    contract::applyOp(ops.stencilFail, v.stencil, st.stencilRef),
                                    v.stencil, st.stencilWriteMask)});
        continue;
      }
      const bool depthResult = contract::compare(st.depthFunc, t.quantisation.q, v.depth);
      for (const bool depthPass : outcomes(depthResult, flippable && compares(st.depthFunc),
                                           how == Compare::DepthOther, free)) {
        const raster::StencilOp op = depthPass ? ops.depthPass : ops.depthFail;
        addState(out, {depthPass && st.depthWrite ? t.quantisation.q : v.depth,
                       contract::masked(contract::applyOp(op, v.stencil, st.stencilRef), v.stencil,
                                        st.stencilWriteMask)});
      }
    }
  }
  return out;
}

// Where the back end's values first need a comparison to go the other way.
struct ComparisonFlip {
  const TriangleEvent* at = nullptr;  // the fragment; null when no replay reaches the values
  bool stencil = false;               // its stencil test the other way reaches them
  bool depth = false;                 // its depth test the other way reaches them
};

// Whether the values `target` are reached from event k on, event k's comparisons as `how`
// says and every later one free.
bool reaches(const PixelHistory& h, const DrawStates& states, std::size_t k, Compare how,
             PixelValues target) {
  const HistoryEvent& e = h.events[k];
  std::vector<PixelValues> set = {{e.triangle->depthBefore, e.triangle->stencilBefore}};
  set = replay(e, states, how, set);
  for (std::size_t j = k + 1; j < h.events.size() && !set.empty(); ++j) {
    set = replay(h.events[j], states, Compare::Free, set);
    if (set.size() > kMaxReplayStates)
      return false;
  }
  return std::find(set.begin(), set.end(), target) != set.end();
}

// Whether the history replayed from its start, its comparisons as the contract runs them, ends
// in exactly the values `target`, with one change: the triangle `toggled` on an edge left out
// if the contract draws it, drawn if the tie rule excludes it (the back end's fill rule is
// another), or every clear applied outside the scissor too (`clearsIgnoreScissor`: the back
// end cleared outside it).
bool contractReplayReaches(const PixelHistory& h, const DrawStates& states, PixelValues target,
                           const TriangleEvent* toggled, bool clearsIgnoreScissor) {
  if (h.events.empty())
    return false;
  const HistoryEvent& first = h.events.front();
  std::vector<PixelValues> set = {
      first.clear ? PixelValues{first.clear->depthBefore, first.clear->stencilBefore}
                  : PixelValues{first.triangle->depthBefore, first.triangle->stencilBefore}};
  for (const HistoryEvent& e : h.events) {
    const bool isToggled = e.triangle && &*e.triangle == toggled;
    if (isToggled && e.triangle->outcome == TriangleOutcome::Fragment)
      continue;
    set = replay(e, states, Compare::Contract, set, clearsIgnoreScissor, isToggled);
  }
  return set.size() == 1 && set.front() == target;
}

ComparisonFlip firstWrongComparison(const PixelHistory& h, const DrawStates& states,
                                    const BadPixel& p) {
  ComparisonFlip out;
  if (h.events.size() > kMaxReplayEvents)
    return out;
  const PixelValues target{p.gotDepth, p.gotStencil};
  // The latest fragment first: the contract followed for as long as the values allow.
  for (std::size_t k = h.events.size(); k-- > 0;) {
    const HistoryEvent& e = h.events[k];
    if (!e.triangle || e.triangle->outcome != TriangleOutcome::Fragment)
      continue;
    out.stencil = reaches(h, states, k, Compare::StencilOther, target);
    out.depth = reaches(h, states, k, Compare::DepthOther, target);
    if (out.stencil || out.depth) {
      out.at = &*e.triangle;
      return out;
    }
  }
  return out;
}

// What the stage rules read: the bad pixel, its history, and the events of the history that the
// rules name, each found once.
struct Evidence {
  explicit Evidence(const BadPixel& p) : pixel(p) {}
  const BadPixel& pixel;
  std::vector<const TriangleEvent*> fragments, ties, culled, scissored;
  bool anyClear = false;  // a clear reaches the pixel (inside the scissor)
  // The latest event that changes the pixel whose state before it is the back end's, in both
  // buffers: the back end's buffers show no trace of it, as if it (and whatever changes the
  // pixel after it) never ran.
  const HistoryEvent* unseen = nullptr;
  // The latest clear the scissor keeps from the pixel whose value the back end has.
  const HistoryEvent* clearOutsideScissor = nullptr;
  // After the last fragment, the latest clear a write mask changes whose unmasked value the
  // back end has: a depth clear while the depth write mask is off, or a stencil clear through
  // the stencil write mask.
  const HistoryEvent* maskedClear = nullptr;
  const ClearEvent* depthClear = nullptr;  // the clear that leaves the final depth, if one does
  const TriangleEvent* writer = nullptr;   // the last fragment that wrote the final depth
  // The first fragment whose depth, or the depth before it, is the back end's.
  const TriangleEvent* holder = nullptr;
  // The fragment whose stencil or depth comparison first goes the other way, if one does.
  ComparisonFlip flip;
};

Evidence gather(const PixelHistory& h, const BadPixel& p, const DrawStates* states) {
  Evidence ev(p);
  if (states != nullptr)
    ev.flip = firstWrongComparison(h, *states, p);
  // A clear outside the scissor whose value the back end has, with the replay at hand, is
  // taken only where clearing outside the scissor gives the back end's values: elsewhere the
  // value is a coincidence.
  const bool scissorReplays =
      states == nullptr ||
      contractReplayReaches(h, *states, {p.gotDepth, p.gotStencil}, nullptr, true);
  for (const HistoryEvent& e : h.events) {
    const EventState s = stateOf(e);
    if (s.changes() && p.gotDepth == s.depthBefore && p.gotStencil == s.stencilBefore)
      ev.unseen = &e;
    if (e.clear) {
      ev.anyClear = ev.anyClear || !e.clear->outsideScissor;
      if (e.clear->depth && !e.clear->skipped && !e.clear->outsideScissor)
        ev.depthClear = &*e.clear;
      continue;
    }
    if (!e.triangle)
      continue;
    const TriangleEvent& t = *e.triangle;
    if (t.depthAfter != t.depthBefore)
      ev.depthClear = nullptr;
    if (t.outcome == TriangleOutcome::Fragment) {
      ev.fragments.push_back(&t);
      if (t.depthPassed && t.stencilPassed && t.depthWrite && t.depthAfter == h.finalDepth)
        ev.writer = &t;
      if (ev.holder == nullptr && (p.gotDepth == t.quantisation.q || p.gotDepth == t.depthBefore))
        ev.holder = &t;
    }
    if (decidedByTie(t))
      ev.ties.push_back(&t);
    if (t.outcome == TriangleOutcome::Culled)
      ev.culled.push_back(&t);
    if (t.outcome == TriangleOutcome::OutsideScissor)
      ev.scissored.push_back(&t);
  }
  for (auto e = h.events.rbegin();
       scissorReplays && e != h.events.rend() && !ev.clearOutsideScissor; ++e) {
    if (!e->clear || !e->clear->outsideScissor)
      continue;
    const ClearEvent& c = *e->clear;
    const auto value = static_cast<std::uint8_t>(c.value);
    if (c.depth ? p.depthDiffers() && p.gotDepth == c.quantisation.q
                : p.stencilDiffers() &&
                      (p.gotStencil == value ||
                       p.gotStencil == static_cast<std::uint8_t>((value & c.writeMask) |
                                                                 (c.stencilBefore & ~c.writeMask))))
      ev.clearOutsideScissor = &*e;
  }
  // Only clears after the pixel's last fragment: a fragment after one would have changed what it
  // left, so an equal value there is a coincidence more likely than not.
  for (auto e = h.events.rbegin(); e != h.events.rend() && !ev.maskedClear; ++e) {
    if (e->triangle && e->triangle->outcome == TriangleOutcome::Fragment)
      break;
    if (!e->clear)
      continue;
    const ClearEvent& c = *e->clear;
    if (c.depth ? c.skipped && p.depthDiffers() && p.gotDepth == c.quantisation.q
                : !c.outsideScissor && c.writeMask != 255 && p.stencilDiffers() &&
                      p.gotStencil == static_cast<std::uint8_t>(c.value))
      ev.maskedClear = &*e;
  }
  // With the replay at hand, a sample on an edge speaks for the fill rule only where the other
  // owner gives the back end's values: the fragment left out, or the one the tie rule excludes
  // drawn.
  if (states != nullptr)
    std::erase_if(ev.ties, [&](const TriangleEvent* t) {
      return !contractReplayReaches(h, *states, {p.gotDepth, p.gotStencil}, t, false);
    });
  return ev;
}

std::string clearName(const HistoryEvent& e) {
  return "the clear of command " + std::to_string(e.command);
}

// One rule of the stage's reading: when `applies` to the evidence, the stage is `stage` and
// `why` says which event of the history, and how, the back end's values point at.
struct StageRule {
  std::string_view name;
  bool (*applies)(const Evidence&);
  Stage stage;
  std::string (*why)(const Evidence&);
};

// The stage from the reference's history alone, in order, the first rule that applies winning:
// first what leaves no trace of an event (the back end's buffers hold the pixel's values from
// before it), then the clears, then the contract's order from coverage on: the first thing that
// the back end's values can come from.
const StageRule kStageRules[] = {
    // A pixel that holds, in both buffers, its values from just before an event that changes
    // it shows no trace of that event. A back end that drew nothing, or too little, is told
    // which event it missed rather than that a test went the other way, although its untouched
    // pixel holds a depth the pixel also holds during its history. A depth or stencil test that
    // fails by mistake with ops that keep the stencil leaves the same pixel: it reads the same,
    // at the first stage that can leave it.
    {"no trace of a clear",
     [](const Evidence& e) { return e.unseen != nullptr && e.unseen->clear.has_value(); },
     Stage::Clear,
     [](const Evidence& e) {
       return "the back end's buffers show no trace of the " +
              std::string(e.unseen->clear->depth ? "depth" : "stencil") + " clear of command " +
              std::to_string(e.unseen->command) +
              ": its depth and stencil are the values before it";
     }},
    {"no trace of a fragment",
     [](const Evidence& e) { return e.unseen != nullptr && e.unseen->triangle.has_value(); },
     Stage::Coverage,
     [](const Evidence& e) {
       // A fragment on an inclusive edge: the fill rule is the likeliest reason it is missing.
       const TriangleEvent& t = *e.unseen->triangle;
       return "the back end's buffers show no trace of the fragment of " + triangleName(t) +
              (decidedByTie(t) ? ", which covers the sample on an inclusive edge (E = 0): the "
                                 "fill rule decides"
                               : ": its depth and stencil are the values before it");
     }},
    // A clear the contract keeps from the pixel, or from one of its buffers, whose value the
    // back end has: it cleared outside the scissor or through a write mask.
    {"a clear outside the scissor",
     [](const Evidence& e) { return e.clearOutsideScissor != nullptr; }, Stage::Clear,
     [](const Evidence& e) {
       return clearName(*e.clearOutsideScissor) +
              " is outside the scissor here, and the back end has its value";
     }},
    {"a depth clear under the write mask",
     [](const Evidence& e) { return e.maskedClear != nullptr && e.maskedClear->clear->depth; },
     Stage::Clear,
     [](const Evidence& e) {
       return clearName(*e.maskedClear) +
              " runs while the depth write mask is off, and the back end has its value";
     }},
    {"a stencil clear through the write mask",
     [](const Evidence& e) { return e.maskedClear != nullptr && !e.maskedClear->clear->depth; },
     Stage::Clear,
     [](const Evidence& e) {
       return clearName(*e.maskedClear) +
              " writes through the stencil write mask, and the back end has the unmasked value";
     }},
    {"a depth clear at a rounding tie",
     [](const Evidence& e) {
       return e.depthClear != nullptr && e.pixel.depthDiffers() &&
              std::abs(e.pixel.depthUnits()) <= 2 && nearRoundingTie(e.depthClear->quantisation);
     },
     Stage::Quantisation,
     [](const Evidence& e) {
       return roundingTieWhy("a depth clear leaves d * 16777215", e.depthClear->quantisation);
     }},
    // The back end's values follow from the contract up to a fragment whose stencil or depth
    // test goes the other way there (the tests after it either way): whatever reading made it
    // do so, the comparison is the first wrong event. Where either test would do, the stencil
    // test, which runs first. A depth test that leaves a depth the history holds is the later
    // rule's, which says which fragment's depth it is; here only where another rule would
    // otherwise read the pixel (the depth agrees, or an edge or a culled triangle is near).
    {"a stencil test that went the other way",
     [](const Evidence& e) { return e.flip.at != nullptr && e.flip.stencil; }, Stage::Stencil,
     [](const Evidence& e) {
       return "the back end's values follow from the stencil test " + e.flip.at->stencilFunc +
              " of " + triangleName(*e.flip.at) + " going the other way (" +
              (e.flip.at->stencilPassed ? "failing" : "passing") + " where the contract's " +
              (e.flip.at->stencilPassed ? "passes" : "fails") + ")";
     }},
    {"a depth test that went the other way",
     [](const Evidence& e) {
       return e.flip.at != nullptr && e.flip.depth &&
              (!e.pixel.depthDiffers() || !e.ties.empty() || !e.culled.empty());
     },
     Stage::DepthTest,
     [](const Evidence& e) {
       return "the back end's values follow from the depth test " + e.flip.at->depthFunc + " of " +
              triangleName(*e.flip.at) + " going the other way (" +
              (e.flip.at->depthPassed ? "failing" : "passing") + " where the contract's " +
              (e.flip.at->depthPassed ? "passes" : "fails") + ")";
     }},
    {"a sample on an edge",
     [](const Evidence& e) {
       const BadPixel& p = e.pixel;
       return !e.ties.empty() && (p.stencilDiffers() || e.fragments.empty() ||
                                  std::abs(p.depthUnits()) > 2 || p.gotDepth == 16777215u);
     },
     Stage::Coverage, [](const Evidence& e) { return onEdgeWhy(*e.ties.front()); }},
    {"a culled triangle",
     [](const Evidence& e) {
       return !e.culled.empty() && (e.fragments.empty() || e.pixel.stencilDiffers());
     },
     Stage::Facing,
     [](const Evidence& e) {
       return triangleName(*e.culled.front()) + " covers the sample but is culled as " +
              (e.culled.front()->front ? "front" : "back") + "-facing";
     }},
    {"a triangle outside the scissor",
     [](const Evidence& e) { return e.fragments.empty() && !e.scissored.empty(); }, Stage::Coverage,
     [](const Evidence& e) {
       return triangleName(*e.scissored.front()) +
              " covers the sample but the scissor excludes the pixel";
     }},
    {"only clears", [](const Evidence& e) { return e.fragments.empty() && e.anyClear; },
     Stage::Clear,
     [](const Evidence&) {
       return std::string("only clears reach this pixel under the contract");
     }},
    {"nothing reaches the sample", [](const Evidence& e) { return e.fragments.empty(); },
     Stage::Coverage,
     [](const Evidence&) {
       return std::string(
           "no triangle covers this sample under the contract and no clear reaches it");
     }},
    {"a written depth at a rounding tie",
     [](const Evidence& e) {
       return e.pixel.depthDiffers() && e.writer != nullptr &&
              std::abs(e.pixel.depthUnits()) <= 2 && nearRoundingTie(e.writer->quantisation);
     },
     Stage::Quantisation,
     [](const Evidence& e) {
       return roundingTieWhy(triangleName(*e.writer) + " leaves z * 16777215",
                             e.writer->quantisation);
     }},
    {"a written depth units off",
     [](const Evidence& e) {
       return e.pixel.depthDiffers() && e.writer != nullptr && std::abs(e.pixel.depthUnits()) <= 2;
     },
     Stage::DepthValue,
     [](const Evidence& e) {
       return triangleName(*e.writer) + "'s depth is " + std::to_string(e.pixel.depthUnits()) +
              " units off: its plane's arithmetic (order, fusion or precision)";
     }},
    // The back end stopped at another state of the pixel's history: a test went another way.
    {"a depth the history holds",
     [](const Evidence& e) { return e.pixel.depthDiffers() && e.holder != nullptr; },
     Stage::DepthTest,
     [](const Evidence& e) {
       return "the back end's depth is one the pixel holds during its history (" +
              triangleName(*e.holder) + "): a depth test went the other way";
     }},
    {"a depth no state has", [](const Evidence& e) { return e.pixel.depthDiffers(); },
     Stage::DepthValue,
     [](const Evidence& e) {
       return "the back end's depth is " + std::to_string(e.pixel.depthUnits()) +
              " units off the contract's, and no state of the pixel's history has it";
     }},
    {"the stencil alone", [](const Evidence&) { return true; }, Stage::Stencil,
     [](const Evidence&) {
       return std::string("depth agrees; the stencil test, an op or a mask went another way");
     }},
};

// Reads the stage from the history alone (the rules above) into `out`; returns the rule.
// `states`: the render state of each draw, for replays of the comparisons; without them no
// comparison is replayed.
const StageRule& stageFromHistory(const PixelHistory& h, PixelExplanation& out,
                                  const DrawStates* states) {
  const Evidence evidence = gather(h, out.pixel, states);
  for (const StageRule& rule : kStageRules) {
    if (rule.applies(evidence)) {
      out.stage = rule.stage;
      out.why = rule.why(evidence);
      out.rule = rule.name;
      return rule;
    }
  }
  return kStageRules[std::size(kStageRules) - 1];  // unreached: the last rule always applies
}

}  // namespace

std::vector<BadPixel> badPixels(const raster::CommandStream& stream, const Answer& expected,
                                const Answer& got, std::size_t limit, long long* count) {
  std::vector<BadPixel> out;
  long long n = 0;
  if (!got.wasRefused()) {
    for (int y = 0; y < stream.height; ++y) {
      for (int x = 0; x < stream.width; ++x) {
        const std::size_t i = at(stream, x, y);
        if (expected.depth[i] == got.depth[i] && expected.stencil[i] == got.stencil[i])
          continue;
        ++n;
        if (out.size() < limit) {
          out.push_back(
              {x, y, expected.depth[i], got.depth[i], expected.stencil[i], got.stencil[i]});
        }
      }
    }
  }
  if (count != nullptr)
    *count = n;
  return out;
}

std::vector<ReadingAnswer> readingAnswers(const raster::CommandStream& stream) {
  std::vector<ReadingAnswer> out;
  for (const kit::VariantInfo& v : kit::wrongVariants()) {
    ModelBackend model(v.variant);
    out.push_back({v.variant, model.run(stream)});
  }
  return out;
}

PixelExplanation explainPixel(const raster::CommandStream& stream, const BadPixel& pixel,
                              const std::vector<ReadingAnswer>& readings) {
  PixelExplanation out;
  out.pixel = pixel;
  out.history = pixelHistory(stream, pixel.x, pixel.y);
  const std::size_t i = at(stream, pixel.x, pixel.y);
  for (const ReadingAnswer& r : readings) {
    if (!r.answer.wasRefused() && r.answer.depth[i] == pixel.gotDepth &&
        r.answer.stencil[i] == pixel.gotStencil) {
      out.sameAsReading = r.variant;
      break;
    }
  }
  const DrawStates states = drawStates(stream);
  stageFromHistory(out.history, out, &states);
  // The stage is the history's even where one of the kit's readings gives the back end's values
  // at the pixel: a back end that is not that reading may give them too, for another reason. A
  // run that behaves like the reading on every vector has every pixel attributed to it
  // (attributeToReading).
  if (out.sameAsReading)
    out.why += " (so does the kit's wrong reading " +
               std::string(kit::variantName(*out.sameAsReading)) + ")";
  return out;
}

void attributeToReading(PixelExplanation& e, Variant v) {
  e.sameAsReading = v;
  e.stage = stageOf(v);
  e.why = "the kit's wrong reading " + std::string(kit::variantName(v)) +
          " gives the back end's values here";
  // The history still says which event the stage concerns, for the report's reader.
  PixelExplanation fromHistory = e;
  stageFromHistory(e.history, fromHistory, nullptr);
  e.rule = fromHistory.rule;
  if (fromHistory.stage == e.stage)
    e.why += ": " + fromHistory.why;
}

Stage failingStage(const raster::CommandStream& stream, const Answer& expected, const Answer& got,
                   const std::vector<ReadingAnswer>& readings) {
  if (got.wasRefused())
    return Stage::Validation;
  const std::vector<BadPixel> first = badPixels(stream, expected, got, 1);
  if (first.empty())
    return Stage::Validation;  // not failing: the caller's mistake, named harmlessly
  return explainPixel(stream, first.front(), readings).stage;
}

}  // namespace recode::conformance
