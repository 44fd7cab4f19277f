// One pixel's history under the contract, written from docs/rasterization.md (sections 2-6)
// and not from the device or the kit's model: the state is followed command by command, every
// triangle is snapped, set up and tested at the one sample, and the depth plane is evaluated in
// the contract's order with every double operation rounded on its own (this file inherits
// -ffp-contract=off from recode_raster).

#include "recode/conformance/pixel_history.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "contract_arithmetic.hpp"

namespace recode::conformance {

namespace {

using contract::applyOp;
using contract::compare;
using contract::kDepthOne;
using contract::masked;
using contract::roundHalfEven;
using contract::snap;
using raster::CompareFunc;
using raster::StencilOp;
using raster::StencilOps;

// Section 5: q = 0 if z <= 0 (or NaN), 16777215 if z >= 1, else nearbyint(z * 16777215.0).
Quantisation quantise(double z) {
  Quantisation r;
  if (!(z > 0.0)) {
    r.clampedLow = true;
    r.q = 0;
    return r;
  }
  if (z >= 1.0) {
    r.clampedHigh = true;
    r.q = kDepthOne;
    return r;
  }
  r.scaled = z * 16777215.0;
  r.tie = r.scaled - std::floor(r.scaled) == 0.5;
  r.q = static_cast<std::uint32_t>(roundHalfEven(r.scaled));
  return r;
}

const char* compareSymbol(CompareFunc func) {
  switch (func) {
    case CompareFunc::Less:
      return "<";
    case CompareFunc::Equal:
      return "==";
    case CompareFunc::LEqual:
      return "<=";
    case CompareFunc::Greater:
      return ">";
    case CompareFunc::NotEqual:
      return "!=";
    case CompareFunc::GEqual:
      return ">=";
    case CompareFunc::Never:
    case CompareFunc::Always:
      break;
  }
  return "";
}

bool inside(const raster::PixelRect& r, int x, int y) {
  return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
}

std::string commandText(int command) {
  return "command " + std::to_string(command);
}

// Section 5, in exactly the contract's order, each operation rounded on its own.
PlaneTerms planeAt(const TriangleEvent& t, long long xc, long long yc) {
  PlaneTerms p;
  p.z0 = static_cast<double>(t.Z[0]);
  p.dz1 = static_cast<double>(t.Z[1]) - p.z0;
  p.dz2 = static_cast<double>(t.Z[2]) - p.z0;
  p.e1x = static_cast<double>(t.X[1] - t.X[0]);
  p.e1y = static_cast<double>(t.Y[1] - t.Y[0]);
  p.e2x = static_cast<double>(t.X[2] - t.X[0]);
  p.e2y = static_cast<double>(t.Y[2] - t.Y[0]);
  p.a2 = static_cast<double>(t.area2);
  const double xLeft = p.dz1 * p.e2y;
  const double xRight = p.dz2 * p.e1y;
  p.dzdxNumerator = xLeft - xRight;
  p.dzdx = p.dzdxNumerator / p.a2;
  const double yLeft = p.dz2 * p.e1x;
  const double yRight = p.dz1 * p.e2x;
  p.dzdyNumerator = yLeft - yRight;
  p.dzdy = p.dzdyNumerator / p.a2;
  p.sampleDx = static_cast<double>(xc - t.X[0]);
  p.sampleDy = static_cast<double>(yc - t.Y[0]);
  p.tx = p.dzdx * p.sampleDx;
  p.ty = p.dzdy * p.sampleDy;
  p.z0PlusTx = p.z0 + p.tx;
  p.z = p.z0PlusTx + p.ty;
  return p;
}

// Section 6, for a covered sample inside the scissor; `t` holds the before-values.
void fragment(TriangleEvent& t, const raster::RenderState& st) {
  const StencilOps& ops = st.opsFor(t.front);
  t.stencilRef = st.stencilRef;
  t.valueMask = st.stencilValueMask;
  t.writeMask = st.stencilWriteMask;
  t.stencilFunc = std::string(raster::toString(st.stencilFunc));
  t.depthFunc = std::string(raster::toString(st.depthFunc));
  t.depthWrite = st.depthWrite;
  const std::uint8_t s = t.stencilBefore;
  const std::uint32_t d = t.depthBefore;
  std::uint32_t newDepth = d;
  StencilOp op = ops.stencilFail;
  t.stencilPassed =
      compare(st.stencilFunc, static_cast<std::uint32_t>(st.stencilRef & st.stencilValueMask),
              static_cast<std::uint32_t>(s & st.stencilValueMask));
  if (!t.stencilPassed) {
    t.opSlot = "sfail";
  } else {
    t.depthPassed = compare(st.depthFunc, t.quantisation.q, d);
    if (!t.depthPassed) {
      op = ops.depthFail;
      t.opSlot = "dpfail";
    } else {
      op = ops.depthPass;
      t.opSlot = "dppass";
      if (st.depthWrite)
        newDepth = t.quantisation.q;
    }
  }
  t.op = std::string(raster::toString(op));
  t.stencilAfter = masked(applyOp(op, s, st.stencilRef), s, st.stencilWriteMask);
  t.depthAfter = newDepth;
}

// ---- describe() helpers ----

std::string g17(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string hex2(std::uint8_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02x", static_cast<unsigned>(v));
  return buf;
}

std::string num(long long v) {
  return std::to_string(v);
}
std::string num(std::uint32_t v) {
  return std::to_string(v);
}
std::string byte(std::uint8_t v) {
  return std::to_string(static_cast<unsigned>(v));
}

const char* edgeSide(const EdgeAtSample& e) {
  if (e.dy < 0)
    return "left";
  if (e.dy > 0)
    return "right";
  return e.dx > 0 ? "bottom" : "top";
}

std::string edgeName(const EdgeAtSample& e) {
  return std::string(edgeSide(e)) + " edge v" + std::to_string(e.from) + " -> v" +
         std::to_string(e.to);
}

// The edges at the sample whose value is exactly 0 and that are not inclusive.
std::string tieEdges(const TriangleEvent& t) {
  std::string out;
  int count = 0;
  for (const EdgeAtSample& e : t.edges) {
    if (e.value == 0 && !e.inclusive) {
      out += (count == 0 ? "" : " and ") + edgeName(e);
      ++count;
    }
  }
  if (count == 0)
    return "";
  return "E = 0 on its " + out + (count == 1 ? ", which is" : ", which are") +
         " not inclusive (right and top edges do not own the samples on them)";
}

bool hasTie(const TriangleEvent& t) {
  for (const EdgeAtSample& e : t.edges)
    if (e.value == 0 && !e.inclusive)
      return true;
  return false;
}

std::string quantisationText(const Quantisation& q, const std::string& what) {
  if (q.clampedLow)
    return what + " <= 0 -> q = 0";
  if (q.clampedHigh)
    return what + " >= 1 -> q = 16777215";
  std::string out = what + "*16777215 = " + g17(q.scaled);
  if (q.tie)
    out += " tie -> q = " + num(q.q) + " (even)";
  else
    out += " -> q = " + num(q.q);
  return out;
}

std::string scissorText(const raster::PixelRect& r) {
  if (r.x1 <= r.x0 || r.y1 <= r.y0)
    return "the scissor is empty";
  return "the scissor is x in [" + std::to_string(r.x0) + ", " + std::to_string(r.x1) +
         "), y in [" + std::to_string(r.y0) + ", " + std::to_string(r.y1) + ")";
}

std::string testText(const char* what, const std::string& func, CompareFunc f,
                     const std::string& incoming, const std::string& stored, bool passed) {
  std::string out = std::string(what) + " " + func;
  if (f != CompareFunc::Never && f != CompareFunc::Always)
    out += " " + incoming + " " + compareSymbol(f) + " " + stored;
  return out + (passed ? " passes" : " fails");
}

std::string describeClear(const HistoryEvent& ev) {
  const ClearEvent& c = *ev.clear;
  std::string out = commandText(ev.command) + ": ";
  if (c.outsideScissor) {
    return out +
           (c.depth ? "clear_depth " + g17(c.value)
                    : "clear_stencil " + byte(static_cast<std::uint8_t>(c.value))) +
           ": outside the scissor, leaves the pixel as it is\n";
  }
  if (c.depth) {
    out += "clear_depth " + g17(c.value);
    if (c.skipped)
      return out + " skipped: the depth write mask is off (" +
             quantisationText(c.quantisation, "d") + " not written); depth stays " +
             num(c.depthBefore) + "\n";
    return out + ": " + quantisationText(c.quantisation, "d") + "; depth " + num(c.depthBefore) +
           " -> " + num(c.depthAfter) + "\n";
  }
  const auto v = static_cast<std::uint8_t>(c.value);
  out += "clear_stencil " + byte(v);
  if (c.writeMask != 0xFF)
    out += " through write mask " + hex2(c.writeMask) + ": (" + byte(v) + " & " +
           hex2(c.writeMask) + ") | (" + byte(c.stencilBefore) + " & " +
           hex2(static_cast<std::uint8_t>(~c.writeMask)) + ")";
  return out + "; stencil " + byte(c.stencilBefore) + " -> " + byte(c.stencilAfter) + "\n";
}

std::string describeTriangle(const HistoryEvent& ev, int x, int y) {
  const TriangleEvent& t = *ev.triangle;
  std::string out = commandText(t.command) + ", draw " + std::to_string(t.draw) + ", triangle " +
                    std::to_string(t.triangle) + (t.front ? " (front)" : " (back)") + ": ";
  switch (t.outcome) {
    case TriangleOutcome::Fragment: {
      const Quantisation& q = t.quantisation;
      out += "covered; z = " + g17(t.plane.z) + " (z0 + tx = " + g17(t.plane.z0PlusTx) +
             ", ty = " + g17(t.plane.ty) + "), " + quantisationText(q, "z") + "; ";
      out += testText("stencil", t.stencilFunc, *raster::parseCompareFunc(t.stencilFunc),
                      "(" + byte(t.stencilRef) + " & " + hex2(t.valueMask) + " = " +
                          byte(static_cast<std::uint8_t>(t.stencilRef & t.valueMask)) + ")",
                      "(" + byte(t.stencilBefore) + " & " + hex2(t.valueMask) + " = " +
                          byte(static_cast<std::uint8_t>(t.stencilBefore & t.valueMask)) + ")",
                      t.stencilPassed);
      if (t.stencilPassed)
        out += "; " + testText("depth", t.depthFunc, *raster::parseCompareFunc(t.depthFunc),
                               num(q.q), num(t.depthBefore), t.depthPassed);
      else
        out += "; depth test not run";
      out += "; " + t.opSlot + " " + t.op + ": ";
      if (t.writeMask != 0xFF) {
        const std::uint8_t n =
            applyOp(*raster::parseStencilOp(t.op), t.stencilBefore, t.stencilRef);
        out += byte(t.stencilBefore) + " -> " + byte(n) + " through write mask " +
               hex2(t.writeMask) + ": ";
      }
      out += "stencil " + byte(t.stencilBefore) + " -> " + byte(t.stencilAfter);
      if (t.depthAfter != t.depthBefore || (t.depthPassed && t.depthWrite))
        out += ", depth " + num(t.depthBefore) + " -> " + num(t.depthAfter);
      else if (t.depthPassed)
        out += ", depth stays " + num(t.depthBefore) + " (depth write mask off)";
      else
        out += ", depth stays " + num(t.depthBefore);
      break;
    }
    case TriangleOutcome::Culled:
      out += std::string("culled (") + (t.front ? "front" : "back") + "-facing, cull mode " +
             (t.front ? "front" : "back") + ")";
      if (hasTie(t))
        out += "; it would not have covered the sample anyway: " + tieEdges(t);
      else
        out += "; it would cover the sample";
      break;
    case TriangleOutcome::OutsideScissor:
      out += "outside the scissor: " + scissorText(t.scissor);
      if (hasTie(t))
        out += "; it would not have covered the sample anyway: " + tieEdges(t);
      else
        out += "; it covers the sample";
      break;
    case TriangleOutcome::ExcludedByTie:
      out += "excluded by the tie rule: " + tieEdges(t);
      break;
    case TriangleOutcome::Degenerate:
      out += "degenerate (A2 = 0 after snapping): draws nothing";
      break;
  }
  out += "\n";

  // The arithmetic.
  const long long xc = 256LL * x + 128;
  const long long yc = 256LL * y + 128;
  out += "    vertices (24.8 fixed point, submitted order):";
  for (int k = 0; k < 3; ++k)
    out += std::string(k == 0 ? " " : ", ") + "v" + std::to_string(k) + " (" + num(t.X[k]) + ", " +
           num(t.Y[k]) + ", z " + g17(static_cast<double>(t.Z[k])) + ")";
  out += "\n    A2 = (X1 - X0)(Y2 - Y0) - (X2 - X0)(Y1 - Y0) = " + num(t.area2) +
         (t.area2 > 0 ? " > 0: front-facing" : (t.area2 < 0 ? " < 0: back-facing" : "")) + "\n";
  out += "    edges (counter-clockwise), E = dx (Yc - Ya) - dy (Xc - Xa) at (Xc, Yc) = (" +
         num(xc) + ", " + num(yc) + "):\n";
  for (const EdgeAtSample& e : t.edges) {
    out += "      " + edgeName(e) + (e.inclusive ? " (inclusive)" : " (not inclusive)") +
           ": dx = " + num(e.dx) + ", dy = " + num(e.dy) + ", E = " + num(e.value) +
           (e.passes() ? " passes" : " excludes") + "\n";
  }
  if (t.outcome != TriangleOutcome::Fragment)
    return out;
  const PlaneTerms& p = t.plane;
  out += "    z0 = " + g17(p.z0) + ", dz1 = " + g17(p.dz1) + ", dz2 = " + g17(p.dz2) + "\n";
  out += "    e1x = " + g17(p.e1x) + ", e1y = " + g17(p.e1y) + ", e2x = " + g17(p.e2x) +
         ", e2y = " + g17(p.e2y) + ", a2 = " + g17(p.a2) + "\n";
  // The numerators' products, recomputed here with the same rounded operations.
  const double xLeft = p.dz1 * p.e2y;
  const double xRight = p.dz2 * p.e1y;
  const double yLeft = p.dz2 * p.e1x;
  const double yRight = p.dz1 * p.e2x;
  out += "    dzdx = (dz1 e2y - dz2 e1y) / a2 = (" + g17(xLeft) + " - " + g17(xRight) +
         ") / a2 = " + g17(p.dzdxNumerator) + " / a2 = " + g17(p.dzdx) + "\n";
  out += "    dzdy = (dz2 e1x - dz1 e2x) / a2 = (" + g17(yLeft) + " - " + g17(yRight) +
         ") / a2 = " + g17(p.dzdyNumerator) + " / a2 = " + g17(p.dzdy) + "\n";
  out += "    Xc - X0 = " + g17(p.sampleDx) + ", Yc - Y0 = " + g17(p.sampleDy) +
         "; tx = dzdx (Xc - X0) = " + g17(p.tx) + ", ty = dzdy (Yc - Y0) = " + g17(p.ty) + "\n";
  out +=
      "    z = (z0 + tx) + ty = " + g17(p.z0PlusTx) + " + " + g17(p.ty) + " = " + g17(p.z) + "\n";
  return out;
}

}  // namespace

PixelHistory pixelHistory(const raster::CommandStream& stream, int x, int y) {
  const int width = stream.width;
  const int height = stream.height;
  contract::checkFrameSize("pixelHistory", width, height);
  if (x < 0 || x >= width || y < 0 || y >= height)
    throw std::invalid_argument("pixelHistory: pixel (" + std::to_string(x) + ", " +
                                std::to_string(y) + ") lies outside the " + std::to_string(width) +
                                " x " + std::to_string(height) + " frame");

  PixelHistory history;
  history.x = x;
  history.y = y;
  std::uint32_t depth = kDepthOne;  // section 1's initial values
  std::uint8_t stencil = 0;
  // The state as every device follows it (raster::applyToState: the scissor clamped to the
  // frame); what the history explains is what the state does to the pixel.
  raster::RenderState st;
  st.scissor = {0, 0, width, height};
  const long long xc = 256LL * x + 128;  // the sample: the pixel centre in 24.8
  const long long yc = 256LL * y + 128;
  int drawIndex = 0;

  for (std::size_t ci = 0; ci < stream.commands.size(); ++ci) {
    const int command = static_cast<int>(ci);
    const raster::Command& cmd = stream.commands[ci];
    if (raster::applyToState(cmd, st, width, height))
      continue;
    if (const auto* c7 = std::get_if<raster::cmd::ClearDepth>(&cmd)) {
      if (!std::isfinite(c7->value))
        throw std::invalid_argument("pixelHistory: " + commandText(command) +
                                    ": clear_depth value is not finite");
      ClearEvent clear;
      clear.depth = true;
      clear.value = c7->value;
      clear.skipped = !st.depthWrite;
      clear.outsideScissor = !inside(st.scissor, x, y);
      clear.quantisation = quantise(c7->value);
      clear.depthBefore = depth;
      clear.stencilBefore = clear.stencilAfter = stencil;
      if (!clear.skipped && !clear.outsideScissor)
        depth = clear.quantisation.q;
      clear.depthAfter = depth;
      history.events.push_back({command, clear, std::nullopt});
    } else if (const auto* c8 = std::get_if<raster::cmd::ClearStencil>(&cmd)) {
      ClearEvent clear;
      clear.depth = false;
      clear.value = static_cast<double>(c8->value);
      clear.writeMask = st.stencilWriteMask;
      clear.outsideScissor = !inside(st.scissor, x, y);
      clear.depthBefore = clear.depthAfter = depth;
      clear.stencilBefore = stencil;
      if (!clear.outsideScissor)
        stencil = masked(c8->value, stencil, st.stencilWriteMask);
      clear.stencilAfter = stencil;
      history.events.push_back({command, clear, std::nullopt});
    } else if (const auto* draw = std::get_if<raster::cmd::Draw>(&cmd)) {
      contract::validateDraw("pixelHistory", *draw, command);
      const std::size_t triangles = draw->indices.size() / 3;
      for (std::size_t ti = 0; ti < triangles; ++ti) {
        TriangleEvent t;
        t.draw = drawIndex;
        t.triangle = static_cast<int>(ti);
        t.command = command;
        for (std::size_t k = 0; k < 3; ++k) {
          const raster::WindowVertex& v = draw->vertices[draw->indices[3 * ti + k]];
          t.X[k] = snap(v.x);
          t.Y[k] = snap(v.y);
          t.Z[k] = v.z;
        }
        // Section 3.
        t.area2 = (t.X[1] - t.X[0]) * (t.Y[2] - t.Y[0]) - (t.X[2] - t.X[0]) * (t.Y[1] - t.Y[0]);
        if (t.area2 == 0)
          continue;
        t.front = t.area2 > 0;
        // Section 4: counter-clockwise order (v0, v1, v2) if front-facing, else (v0, v2, v1).
        const int order[3] = {0, t.front ? 1 : 2, t.front ? 2 : 1};
        bool reaches = true;
        bool covered = true;
        for (int e = 0; e < 3; ++e) {
          EdgeAtSample& edge = t.edges[e];
          edge.from = order[e];
          edge.to = order[(e + 1) % 3];
          const long long xa = t.X[edge.from];
          const long long ya = t.Y[edge.from];
          edge.dx = t.X[edge.to] - xa;
          edge.dy = t.Y[edge.to] - ya;
          edge.value = edge.dx * (yc - ya) - edge.dy * (xc - xa);
          edge.inclusive = edge.dy < 0 || (edge.dy == 0 && edge.dx > 0);
          if (edge.value < 0)
            reaches = false;
          if (!edge.passes())
            covered = false;
        }
        if (!reaches)
          continue;  // the sample lies outside the triangle: nothing to tell
        t.scissor = st.scissor;
        t.depthBefore = t.depthAfter = depth;
        t.stencilBefore = t.stencilAfter = stencil;
        if (st.culls(t.front)) {
          t.outcome = TriangleOutcome::Culled;
        } else if (!inside(st.scissor, x, y)) {
          t.outcome = TriangleOutcome::OutsideScissor;
        } else if (!covered) {
          t.outcome = TriangleOutcome::ExcludedByTie;
          // The depth it would have had, for a diagnosis that asks what drawing it gives.
          t.plane = planeAt(t, xc, yc);
          t.quantisation = quantise(t.plane.z);
        } else {
          t.outcome = TriangleOutcome::Fragment;
          t.plane = planeAt(t, xc, yc);
          t.quantisation = quantise(t.plane.z);
          fragment(t, st);
          depth = t.depthAfter;
          stencil = t.stencilAfter;
        }
        history.events.push_back({command, std::nullopt, t});
      }
      ++drawIndex;
    }
  }
  history.finalDepth = depth;
  history.finalStencil = stencil;
  return history;
}

std::string describe(const PixelHistory& history) {
  std::string out = "pixel (" + std::to_string(history.x) + ", " + std::to_string(history.y) +
                    "): " + std::to_string(history.events.size()) +
                    (history.events.size() == 1 ? " event" : " events") + "; final depth " +
                    num(history.finalDepth) + ", stencil " + byte(history.finalStencil) + "\n";
  for (const HistoryEvent& ev : history.events) {
    if (ev.clear)
      out += describeClear(ev);
    else if (ev.triangle)
      out += describeTriangle(ev, history.x, history.y);
  }
  return out;
}

}  // namespace recode::conformance
