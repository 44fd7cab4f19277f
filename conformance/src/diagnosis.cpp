#include "recode/conformance/diagnosis.hpp"

#include <algorithm>
#include <cmath>

namespace recode::conformance {

using kit::Variant;

std::string_view toString(Stage s) {
  switch (s) {
    case Stage::Validation:
      return "validation";
    case Stage::Coverage:
      return "coverage";
    case Stage::Facing:
      return "facing";
    case Stage::DepthValue:
      return "depth value";
    case Stage::Quantisation:
      return "quantisation";
    case Stage::DepthTest:
      return "depth test";
    case Stage::Stencil:
      return "stencil";
    case Stage::Clear:
      return "clear";
  }
  return "?";
}

std::string_view contractSection(Stage s) {
  switch (s) {
    case Stage::Validation:
      return "rasterization.md section 2 (vertices and snapping: what a draw may hold)";
    case Stage::Coverage:
      return "rasterization.md section 4 (coverage and the fill rule)";
    case Stage::Facing:
      return "rasterization.md section 3 (triangle setup: area, facing, culling)";
    case Stage::DepthValue:
      return "rasterization.md section 5 (depth: the plane's arithmetic, in its order)";
    case Stage::Quantisation:
      return "rasterization.md section 5 (depth: quantisation to 24 bits, ties to even)";
    case Stage::DepthTest:
      return "rasterization.md section 6 (per-fragment operations: the depth test)";
    case Stage::Stencil:
      return "rasterization.md section 6 (per-fragment operations: stencil test, ops, masks)";
    case Stage::Clear:
      return "rasterization.md section 6 (clears: the scissor and the write masks)";
  }
  return "?";
}

Stage stageOf(Variant v) {
  switch (v) {
    case Variant::TopLeftFill:
    case Variant::EdgeFloat:
      return Stage::Coverage;
    case Variant::QuantiseHalfUp:
    case Variant::QuantiseHalfAway:
    case Variant::QuantiseHalfDown:
    case Variant::QuantiseTruncate:
    case Variant::QuantiseCeil:
    case Variant::QuantiseFloat:
    case Variant::QuantiseExactProduct:
    case Variant::Quantise2To24:
    case Variant::Quantise2To24Truncate:
      return Stage::Quantisation;
    case Variant::IncrWraps:
    case Variant::DecrWraps:
    case Variant::IgnoreValueMask:
      return Stage::Stencil;
    case Variant::StencilClearIgnoresWriteMask:
    case Variant::DepthClearIgnoresWriteMask:
    case Variant::ClearIgnoresScissor:
      return Stage::Clear;
    case Variant::SwappedFacing:
      return Stage::Facing;
    case Variant::StrictLimits:
      return Stage::Validation;
    default:
      return Stage::DepthValue;  // the anchor, slopes, evaluation, fusion and float readings
  }
}

bool apiLatitude(Variant v) {
  switch (stageOf(v)) {
    case Stage::DepthValue:
    case Stage::Quantisation:
    case Stage::Validation:  // the guard band's extent is the implementation's
      return v != Variant::Contract;
    case Stage::Coverage:
      return v == Variant::TopLeftFill;  // any consistent tie rule; float edges are a bug
    default:
      return false;
  }
}

namespace {

std::string latitudeName(Variant v) {
  switch (stageOf(v)) {
    case Stage::Coverage:
      return "the fill rule on ties";
    case Stage::Validation:
      return "the guard band's limits";
    default:
      return "the depth arithmetic and its rounding";
  }
}

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

// The stage from the reference's history alone, when no wrong reading gives the back end's
// values: the first thing in the contract's order that the back end's value can come from.
void stageFromHistory(const PixelHistory& h, PixelExplanation& out) {
  const BadPixel& p = out.pixel;
  std::vector<const TriangleEvent*> fragments, ties, culled, scissored;
  bool anyClear = false;
  for (const HistoryEvent& e : h.events) {
    if (e.clear) {
      anyClear = anyClear || !e.clear->outsideScissor;
      continue;
    }
    if (!e.triangle)
      continue;
    const TriangleEvent& t = *e.triangle;
    if (t.outcome == TriangleOutcome::Fragment)
      fragments.push_back(&t);
    if (decidedByTie(t))
      ties.push_back(&t);
    if (t.outcome == TriangleOutcome::Culled)
      culled.push_back(&t);
    if (t.outcome == TriangleOutcome::OutsideScissor)
      scissored.push_back(&t);
  }
  // A clear the contract keeps from the pixel, or from one of its buffers, whose value the back
  // end has: it cleared outside the scissor or through a write mask.
  // A clear that the scissor keeps from the pixel, whose value the back end has: it cleared
  // outside the scissor.
  for (auto e = h.events.rbegin(); e != h.events.rend(); ++e) {
    if (!e->clear || !e->clear->outsideScissor)
      continue;
    const ClearEvent& c = *e->clear;
    const auto value = static_cast<std::uint8_t>(c.value);
    if (c.depth
            ? p.depthDiffers() && p.gotDepth == c.quantisation.q
            : p.stencilDiffers() &&
                  (p.gotStencil == value ||
                   p.gotStencil == static_cast<std::uint8_t>((value & c.writeMask) |
                                                             (c.stencilBefore & ~c.writeMask)))) {
      out.stage = Stage::Clear;
      out.why = "the clear of command " + std::to_string(e->command) +
                " is outside the scissor here, and the back end has its value";
      return;
    }
  }
  // Only clears after the pixel's last fragment: a fragment after one would have changed what it
  // left, so an equal value there is a coincidence more likely than not.
  for (auto e = h.events.rbegin(); e != h.events.rend(); ++e) {
    if (e->triangle && e->triangle->outcome == TriangleOutcome::Fragment)
      break;
    if (!e->clear)
      continue;
    const ClearEvent& c = *e->clear;
    const auto value = static_cast<std::uint8_t>(c.value);
    const bool depthHere = c.depth && p.depthDiffers() && p.gotDepth == c.quantisation.q;
    const std::string which = "the clear of command " + std::to_string(e->command);
    if (c.depth && c.skipped && depthHere) {
      out.stage = Stage::Clear;
      out.why = which + " runs while the depth write mask is off, and the back end has its value";
      return;
    }
    if (!c.depth && !c.outsideScissor && c.writeMask != 255 && p.stencilDiffers() &&
        p.gotStencil == value) {
      out.stage = Stage::Clear;
      out.why = which +
                " writes through the stencil write mask, and the back end has the "
                "unmasked value";
      return;
    }
  }
  // The event that left the final depth, when it is a clear at a rounding tie.
  const ClearEvent* depthClear = nullptr;
  for (const HistoryEvent& e : h.events) {
    if (e.clear && e.clear->depth && !e.clear->skipped && !e.clear->outsideScissor)
      depthClear = &*e.clear;
    if (e.triangle && e.triangle->depthAfter != e.triangle->depthBefore)
      depthClear = nullptr;
  }
  if (depthClear != nullptr && p.depthDiffers() && std::abs(p.depthUnits()) <= 2) {
    const Quantisation& q = depthClear->quantisation;
    const double frac = q.scaled - std::floor(q.scaled);
    if (q.tie || std::abs(frac - 0.5) < 1e-3) {
      out.stage = Stage::Quantisation;
      out.why = "a depth clear leaves d * 16777215 at " +
                (q.tie ? std::string("a tie") : std::string("almost a tie")) +
                ", which the contract rounds to " + std::to_string(q.q);
      return;
    }
  }
  // The last fragment that wrote the final depth.
  const TriangleEvent* writer = nullptr;
  for (const TriangleEvent* t : fragments) {
    if (t->depthPassed && t->stencilPassed && t->depthWrite && t->depthAfter == h.finalDepth)
      writer = t;
  }
  if (!ties.empty() && (p.stencilDiffers() || fragments.empty() || std::abs(p.depthUnits()) > 2 ||
                        p.gotDepth == 16777215u)) {
    const TriangleEvent& t = *ties.front();
    out.stage = Stage::Coverage;
    out.why = "the sample lies exactly on an edge of " + triangleName(t) + ", which " +
              (t.outcome == TriangleOutcome::Fragment ? "covers it (the edge is inclusive)"
                                                      : "does not cover it (the edge is not "
                                                        "inclusive)") +
              ": the fill rule decides";
    return;
  }
  if (!culled.empty() && (fragments.empty() || p.stencilDiffers())) {
    out.stage = Stage::Facing;
    out.why = triangleName(*culled.front()) + " covers the sample but is culled as " +
              (culled.front()->front ? "front" : "back") + "-facing";
    return;
  }
  if (fragments.empty()) {
    if (!scissored.empty()) {
      out.stage = Stage::Coverage;
      out.why = triangleName(*scissored.front()) +
                " covers the sample but the scissor excludes the pixel";
    } else if (anyClear) {
      out.stage = Stage::Clear;
      out.why = "only clears reach this pixel under the contract";
    } else {
      out.stage = Stage::Coverage;
      out.why = "no triangle covers this sample under the contract and no clear reaches it";
    }
    return;
  }
  if (p.depthDiffers() && writer != nullptr && std::abs(p.depthUnits()) <= 2) {
    const Quantisation& q = writer->quantisation;
    const double frac = q.scaled - std::floor(q.scaled);
    if (q.tie || std::abs(frac - 0.5) < 1e-3) {
      out.stage = Stage::Quantisation;
      out.why = triangleName(*writer) + " leaves z * 16777215 at " +
                (q.tie ? std::string("a tie") : std::string("almost a tie")) +
                ", which the contract rounds to " + std::to_string(q.q);
      return;
    }
    out.stage = Stage::DepthValue;
    out.why = triangleName(*writer) + "'s depth is " + std::to_string(p.depthUnits()) +
              " units off: its plane's arithmetic (order, fusion or precision)";
    return;
  }
  if (p.depthDiffers()) {
    // The back end stopped at another state of the pixel's history: a test went another way.
    for (const TriangleEvent* t : fragments) {
      if (p.gotDepth == t->quantisation.q || p.gotDepth == t->depthBefore) {
        out.stage = Stage::DepthTest;
        out.why = "the back end's depth is one the pixel holds during its history (" +
                  triangleName(*t) + "): a depth test went the other way";
        return;
      }
    }
    out.stage = Stage::DepthValue;
    out.why = "the back end's depth is " + std::to_string(p.depthUnits()) +
              " units off the contract's, and no state of the pixel's history has it";
    return;
  }
  out.stage = Stage::Stencil;
  out.why = "depth agrees; the stencil test, an op or a mask went another way";
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
  if (out.sameAsReading) {
    attributeToReading(out, *out.sameAsReading);
    return out;
  }
  stageFromHistory(out.history, out);
  return out;
}

void attributeToReading(PixelExplanation& e, Variant v) {
  e.sameAsReading = v;
  e.stage = stageOf(v);
  e.why = "the kit's wrong reading " + std::string(kit::variantName(v)) +
          " gives the back end's values here";
  // The history still says which event the stage concerns, for the report's reader.
  PixelExplanation fromHistory = e;
  stageFromHistory(e.history, fromHistory);
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

Requirement requirementOf(const raster::CommandStream& stream, const Answer& expected) {
  Requirement r;
  const auto departs = [](BufferRequirement& b, const std::string& latitude) {
    b.byGraphicsApis = false;
    if (std::find(b.latitudes.begin(), b.latitudes.end(), latitude) == b.latitudes.end())
      b.latitudes.push_back(latitude);
  };
  for (const kit::VariantInfo& v : kit::wrongVariants()) {
    if (!apiLatitude(v.variant))
      continue;
    const std::string name = latitudeName(v.variant);
    ModelBackend model(v.variant);
    const Answer a = model.run(stream);
    if (a.wasRefused() || a.depth != expected.depth)
      departs(r.depth, name);
    if (a.wasRefused() || a.stencil != expected.stencil)
      departs(r.stencil, name);
  }
  return r;
}

}  // namespace recode::conformance
