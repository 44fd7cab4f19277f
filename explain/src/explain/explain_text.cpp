// What the explain page says, for a student who has not read the paper (HTML fragments).
#include "explain/explain_text.hpp"

#include <array>
#include <sstream>

#include "explain/explain_format.hpp"
#include "explain/explain_palette.hpp"
#include "recode/pair/pair_cases.hpp"
#include "recode/raster/state.hpp"

namespace recode::explain {

namespace {

using core::PairStep;

// The condition of each case in terms of the two depth intervals.
constexpr std::array<std::string_view, core::kCaseCount> kCaseCondition = {
    "no block on this ray",
    "only A on this ray",
    "A<sub>max</sub> &lt; B<sub>min</sub>",
    "A<sub>min</sub> &le; B<sub>min</sub> &le; A<sub>max</sub> &lt; B<sub>max</sub>",
    "B<sub>min</sub> &lt; A<sub>min</sub>, A<sub>max</sub> &lt; B<sub>max</sub>",
    "A<sub>min</sub> &le; B<sub>min</sub>, B<sub>max</sub> &le; A<sub>max</sub>",
    "B<sub>min</sub> &lt; A<sub>min</sub> &le; B<sub>max</sub> &le; A<sub>max</sub>",
    "B<sub>max</sub> &lt; A<sub>min</sub>",
    "only B on this ray",
};

// The stencil values (bits 0-3) that decode to each case, e.g. "3, 7".
std::string stencilValuesOfCase(int pixelCase) {
  std::string out;
  for (int v = 0; v < 16; ++v) {
    if (core::caseFromStencil(static_cast<std::uint8_t>(v)) != pixelCase)
      continue;
    if (!out.empty())
      out += ", ";
    out += std::to_string(v);
  }
  return out;
}

int stepOrder(PairStep step) {
  return static_cast<int>(step);
}

}  // namespace

std::string stencilMeaning(std::uint8_t value, PairStep step) {
  if (value > core::kUsedStencilBits)
    return "unexpected: the pair algorithm uses only bits 0-3";
  const int count = value & core::kCountBits;
  const bool front = (value & core::kFrontBehindAminBit) != 0;
  const bool back = (value & core::kBackBehindAminBit) != 0;
  std::string text;
  if (step == PairStep::SetZ) {
    text = count == 0 ? "A does not cover the pixel" : "A covers the pixel";
  } else {
    static constexpr std::array<std::string_view, 4> kCount = {
        "count 0: A absent",
        "count 1: A here, no face of B at or in front of A<sub>max</sub>",
        "count 2: A here, one face of B at or in front of A<sub>max</sub>",
        "count 3: A here, both faces of B at or in front of A<sub>max</sub>",
    };
    text = kCount[static_cast<std::size_t>(count)];
  }
  if (front)
    text += count == 0 ? "; bit 2: B's front face here (A absent)"
                       : "; bit 2: B's front face at or behind A<sub>min</sub>";
  if (back)
    text += count == 0 ? "; bit 3: B's back face here (A absent)"
                       : "; bit 3: B's back face at or behind A<sub>min</sub>";
  if (stepOrder(step) >= stepOrder(PairStep::TestAminBack)) {
    const int c = core::caseFromStencil(value);
    text += " &rarr; case " + std::to_string(c) + " (" + std::string(core::caseName(c)) + ")";
  }
  return text;
}

StepWords stepWords(PairStep step) {
  switch (step) {
    case PairStep::SetZ:
      return {"1 SetZ",
              "depth cleared to 0 and stencil to 0 over the MOR; every fragment of A passes "
              "GEQUAL and REPLACEs the stencil with 1. So: 1 where A covers the pixel, 0 where "
              "it does not (or outside the MOR: the scissor keeps every pass away and the "
              "stencil stays 0). The depth buffer ends holding Amax."};
    case PairStep::TestZ:
      return {"2 TestZ",
              "only where A is present (stencil test 1 \u2264 count), each face of B at or in "
              "front of Amax (LEQUAL) INCRements the count in bits 0-1. So the count becomes 1 "
              "+ the number of B\u2019s two boundaries at or before Amax; where A is absent "
              "nothing changes."};
    case PairStep::LoadAmin:
      return {"3 Load Amin",
              "A is drawn again into depth cleared to 1, leaving Amin in the depth buffer; the "
              "stencil write mask is 0, so the stencil does not change at all."};
    case PairStep::TestAminFront:
      return {"4 B front vs Amin",
              "only B\u2019s front face is drawn. Where A is present it INVERTs bit 2 (value 4) "
              "when that face is at or behind Amin (GEQUAL); where A is absent the stencil test "
              "fails and sfail INVERTs bit 2 anyway, so bit 2 then says that B covers the "
              "pixel. No face of B: nothing changes."};
    case PairStep::TestAminBack:
      return {"5 B back vs Amin",
              "the same for B\u2019s back face and bit 3 (value 8): INVERT when it is at or "
              "behind Amin where A is present, always where A is absent and B covers the "
              "pixel."};
    case PairStep::ReadStencil:
      return {"6 Read stencil",
              "the read-back decodes the stencil (the stencil encoding): count 0 gives case 0 "
              "without bits 2-3, else 8; count 1 gives 1 without them, else 2; count 2 gives 3 "
              "with both bits, else 4; count 3 gives 5 with both, 6 with one, 7 with neither. A "
              "pixel outside the MOR is not read back: not examined."};
    case PairStep::ContactNear:
      return {"7 Contact near",
              "only over the interfering pixels' rectangle: depth cleared to 0, the front "
              "faces of A and B drawn with GEQUAL, leaving max(Amin, Bmin); the stencil is "
              "kept."};
    case PairStep::ContactFar:
      return {"8 Contact far",
              "over the same rectangle: depth cleared to 1, the back faces of A and B drawn "
              "with LEQUAL, leaving min(Amax, Bmax); the stencil is kept."};
  }
  return {"?", ""};
}

std::span<const std::string_view> stepOperands(PairStep step) {
  static constexpr std::array<std::string_view, 1> kSetZ = {"a_covers"};
  static constexpr std::array<std::string_view, 3> kTestZ = {"a_back", "b_front", "b_back"};
  static constexpr std::array<std::string_view, 2> kFront = {"a_front", "b_front"};
  static constexpr std::array<std::string_view, 2> kBack = {"a_front", "b_back"};
  switch (step) {
    case PairStep::SetZ:
      return kSetZ;
    case PairStep::TestZ:
      return kTestZ;
    case PairStep::TestAminFront:
      return kFront;
    case PairStep::TestAminBack:
      return kBack;
    case PairStep::LoadAmin:     // write mask 0
    case PairStep::ReadStencil:  // reads the stencil only
    case PairStep::ContactNear:  // the stencil is kept
    case PairStep::ContactFar:
      break;
  }
  return {};
}

std::string stepTitle(PairStep step) {
  const auto titled = [step](std::string_view what) {
    return std::string(stepWords(step).name) + ": " + std::string(what);
  };
  switch (step) {
    case PairStep::SetZ:
      return titled("RenderSetZ(A, &ge;), the far side of A into the depth buffer");
    case PairStep::TestZ:
      return titled("RenderTestZ(B, &le;), count B's faces in front of A's far side");
    case PairStep::LoadAmin:
      return titled("load the near side of A into the depth buffer");
    case PairStep::TestAminFront:
      return titled("is B's front face at or behind A's near side? (stencil bit 2)");
    case PairStep::TestAminBack:
      return titled("is B's back face at or behind A's near side? (stencil bit 3)");
    case PairStep::ReadStencil:
      return titled("read back the stencil and classify every pixel");
    case PairStep::ContactNear:
      return titled("the near end of the overlap, max(A<sub>min</sub>, B<sub>min</sub>)");
    case PairStep::ContactFar:
      return titled("the far end of the overlap, min(A<sub>max</sub>, B<sub>max</sub>)");
  }
  return "?";
}

std::string originText(PairStep step) {
  const auto paper = [](std::string_view why) {
    return "<p class=\"origin\"><span class=\"paper\">from the paper</span>" + std::string(why) +
           "</p>";
  };
  const auto ours = [](std::string_view why) {
    return "<p class=\"origin\"><span class=\"ours\">added here</span>" + std::string(why) + "</p>";
  };
  switch (step) {
    case PairStep::SetZ:
      return paper(
          "RenderSetZ is the paper's first pass; drawing all of A's faces rather than only its "
          "back faces is ours: the same A<sub>max</sub> on a convex block, and right at "
          "silhouette pixels where rounding puts a front face a step behind a back face.");
    case PairStep::TestZ:
      return paper("RenderTestZ and the count 0-3 in the stencil's low bits are the paper's.");
    case PairStep::LoadAmin:
      return ours(
          "The count alone leaves cases together (1 with 2, 3 with 4, 5 with 6 and 7); the paper "
          "mentions a second rendering without spelling it out, and this is ours: A's near side "
          "for the two tests that follow.");
    case PairStep::TestAminFront:
    case PairStep::TestAminBack:
      return ours(
          "One stencil bit per face of B, written through face culling and a write mask with a "
          "single reference value: this project's way of separating the cases the count "
          "leaves together.");
    case PairStep::ReadStencil:
      return paper(
          "One stencil read-back over the MOR decides the verdict, as in the paper; decoding "
          "the count together with bits 2 and 3 into nine cases is ours.");
    case PairStep::ContactNear:
    case PairStep::ContactFar:
      return ours(
          "The verdict needs only the stencil; these two depth passes are this project's way "
          "of measuring the contact region.");
  }
  return "";
}

std::string stateText(const raster::RenderState& st, double clearDepth) {
  const auto hex = [](unsigned v) {
    std::ostringstream o;
    o << "0x" << std::hex << std::uppercase << (v < 16 ? "0" : "") << v;
    return o.str();
  };
  const auto ops = [](const raster::StencilOps& o) {
    return std::string(raster::toString(o.stencilFail)) + " / " +
           std::string(raster::toString(o.depthFail)) + " / " +
           std::string(raster::toString(o.depthPass));
  };
  std::ostringstream t;
  t << "<p class=\"state\"><a href=\"#device-state-terms\"><b>Device state</b></a> (read from "
       "the device after the step): scissor "
    << rectText(st.scissor);
  if (clearDepth >= 0.0)
    t << ", depth cleared to " << formatNumber(clearDepth);
  t << "; depth test <code>" << raster::toString(st.depthFunc) << "</code>, depth writes "
    << (st.depthWrite ? "on" : "off") << "; stencil test <code>" << raster::toString(st.stencilFunc)
    << "</code> (ref " << int{st.stencilRef} << ", mask " << hex(st.stencilValueMask)
    << "), ops sfail / dpfail / dppass <code>" << ops(st.frontOps) << "</code>";
  if (st.frontOps != st.backOps)
    t << " (front), <code>" << ops(st.backOps) << "</code> (back)";
  t << ", stencil write mask " << hex(st.stencilWriteMask) << "; culling <code>"
    << raster::toString(st.cull) << "</code>.</p>";
  return t.str();
}

// A declarative table, one paragraph per step: long, but each case reads on its own.
std::string stepText(PairStep step) {
  switch (step) {
    case PairStep::SetZ:
      return "<p>Inside the MOR the depth buffer is cleared to 0 (the nearest possible value) "
             "and the stencil to 0. Then every triangle of A is drawn with the depth test "
             "<code>GEQUAL</code> and depth writes on: a fragment replaces the stored depth "
             "only if it is at or behind it, so each pixel ends with the farthest point of A "
             "on its ray, A<sub>max</sub>, where the ray leaves A. Every fragment of A also "
             "writes 1 into the stencil (<code>REPLACE</code>): &ldquo;A is here&rdquo;.</p>"
             "<p>Why the far side: anything of B that lies in front of A<sub>max</sub> may be "
             "inside A, anything behind it cannot be. MOR pixels A does not cover keep the "
             "cleared depth 0 (dark blue).</p>";
    case PairStep::TestZ:
      return "<p>Depth writes are now off: the depth buffer only answers the question "
             "&ldquo;is this fragment at or in front of A<sub>max</sub>?&rdquo; (<code>LEQUAL"
             "</code>). Every triangle of B is drawn; where A is present (the stencil test "
             "<code>1 &le; stencil</code> passes) each fragment of B that passes the depth "
             "test increments the stencil (<code>INCR</code>).</p>"
             "<p>B is convex, so a ray meets its surface exactly twice: entering at "
             "B<sub>min</sub> through a front face and leaving at B<sub>max</sub> through a "
             "back face. The stencil therefore ends at 1 + 0, 1 or 2. A count of 2 means "
             "B<sub>min</sub> &le; A<sub>max</sub> &lt; B<sub>max</sub>: A<sub>max</sub> lies "
             "inside B's interval, so the blocks certainly overlap there (cases 3 and 4). A "
             "count of 3 means all of B is at or in front of A<sub>max</sub>: B may overlap A "
             "(cases 5, 6) or lie entirely in front of it (case 7). The count cannot tell "
             "these apart, which is what the next three steps are for.</p>";
    case PairStep::LoadAmin:
      return "<p>The stencil write mask is set to 0 so the count survives. The depth buffer "
             "is cleared to 1 (the farthest value) and A is drawn again with <code>LEQUAL"
             "</code> and depth writes on: each pixel keeps the nearest point of A, "
             "A<sub>min</sub>, where the ray enters A. MOR pixels A does not cover keep 1 "
             "(dark red).</p>"
             "<p>With A's near side in the depth buffer the next two steps can ask where B's "
             "two faces lie relative to it.</p>";
    case PairStep::TestAminFront:
      return "<p>Only B's front faces are drawn (back faces culled): on a convex block they "
             "are exactly the surface at B<sub>min</sub>. The depth test is <code>GEQUAL"
             "</code> against A<sub>min</sub>, depth writes off, and the stencil write mask "
             "lets only bit 2 (value 4) change: where B's front face is at or behind "
             "A<sub>min</sub> the bit is inverted from 0 to 1.</p>"
             "<p>Where A is absent the stencil test (<code>1 &le; count</code>) fails and "
             "its fail operation inverts the bit too: this records B's coverage outside A, "
             "which the count could not see (case 8).</p>";
    case PairStep::TestAminBack:
      return "<p>The same test for B's back faces (front faces culled), the surface at "
             "B<sub>max</sub>, into bit 3 (value 8): set where B<sub>max</sub> &ge; "
             "A<sub>min</sub>, or where B covers a pixel A does not.</p>"
             "<p>Now every pixel's stencil holds the count and two bits, which together "
             "separate all nine cases: for example count 3 with neither bit means B ends in "
             "front of A's near side (case 7, no contact), count 3 with both bits means B "
             "lies inside A's interval (case 5).</p>";
    case PairStep::ReadStencil:
      return "<p>The stencil over the MOR is read back: this is the only read-back needed "
             "for the verdict, and the reason the MOR should be small (reading pixels back "
             "was the slow part on the paper's hardware). Each pixel's value is decoded "
             "into one of the nine cases below. The blocks collide if and only if some pixel "
             "is in case 3, 4, 5 or 6: there the two depth intervals share at least one "
             "point, so the ray passes through a point inside both blocks (touching "
             "counts).</p>";
    case PairStep::ContactNear:
      return "<p>Only when some pixel interferes: over the bounding rectangle of the "
             "interfering pixels (white frame) depth is cleared to 0 and the front faces of "
             "both A and B are drawn with <code>GEQUAL</code>, so each pixel keeps the later "
             "of the two entries, max(A<sub>min</sub>, B<sub>min</sub>): the near end of the "
             "overlap interval.</p>";
    case PairStep::ContactFar:
      return "<p>Depth over the same rectangle is cleared to 1 and the back faces of both "
             "blocks are drawn with <code>LEQUAL</code>: each pixel keeps the earlier of the "
             "two exits, min(A<sub>max</sub>, B<sub>max</sub>), the far end of the overlap. "
             "Together with the previous picture this is, at every interfering pixel, the "
             "stretch of the view ray that lies inside both blocks.</p>";
  }
  return "";
}

std::string silhouettesText(const core::PairResult& result, core::MorMode mor, bool boxTest,
                            const raster::PixelRect& frame) {
  std::ostringstream t;
  t << "<p>Both blocks drawn flat, seen along the view axis. Each framebuffer pixel is one "
       "ray parallel to the axis; a convex block meets such a ray in a single stretch "
       "[min, max] of depth, entering through a front face and leaving through a back face, "
       "and the blocks interfere exactly where these stretches overlap on some ray. Where "
       "only one block (or neither) covers a pixel they cannot touch there.</p>"
       "<p>The <b>MOR</b> (minimum overlapping region, cyan frame) is the pixel rectangle "
       "the algorithm works in. ";
  switch (mor) {
    case core::MorMode::Min:
      t << "In mode <code>min</code> it is where the projections of the two blocks' "
           "bounding boxes overlap: outside it at most one block is present.";
      break;
    case core::MorMode::Max:
      t << "In mode <code>max</code> it is the rectangle around both blocks' projected "
           "boxes: larger than necessary, as in the paper's comparison (Table 1).";
      break;
    case core::MorMode::Full:
      t << "In mode <code>full</code> it is the whole frame: the slowest choice, as in the "
           "paper's comparison (Table 1).";
      break;
  }
  t << " Every later pass is limited to it with the scissor rectangle, and only its pixels "
       "are read back.</p>";
  if (!result.mor.empty())
    t << "<p>MOR " << rectText(result.mor)
      << " (x from the left, y from the bottom, half-open): " << result.mor.width() << " &times; "
      << result.mor.height() << " = " << result.mor.area() << " of the frame's " << frame.area()
      << " pixels.</p>";
  if (!result.boxesOverlap) {
    t << "<p><b>The boxes do not overlap</b> (their projections share no pixel centre, or "
         "their depth ranges do not meet), so the blocks cannot collide. ";
    if (boxTest)
      t << "Nothing is drawn: the algorithm stops here (run with <code>--no-box-test</code> "
           "to see the passes anyway).</p>";
    else if (result.mor.empty())
      t << "The passes were asked for (<code>--no-box-test</code>) but the MOR is empty, so "
           "there is nothing to draw.</p>";
    else
      t << "Normally the algorithm would stop here; <code>--no-box-test</code> runs the "
           "passes anyway, to show the cases of blocks that do not touch.</p>";
  }
  return t.str();
}

std::string caseTableHtml(const core::PairResult& result) {
  std::ostringstream t;
  t << "<table><tr><th></th><th>case</th><th>on the view ray</th><th>condition</th>"
       "<th>stencil values</th><th>interferes</th><th>pixels in the MOR</th></tr>";
  for (int c = 0; c < core::kCaseCount; ++c) {
    const auto i = static_cast<std::size_t>(c);
    t << "<tr" << (core::isInterfering(c) ? " class=\"hit\"" : "") << "><td>"
      << swatch(kCasePalette[i]) << "</td><td>" << c << "</td><td>" << escapeHtml(core::caseName(c))
      << "</td><td>" << kCaseCondition[i] << "</td><td>" << stencilValuesOfCase(c) << "</td><td>"
      << (core::isInterfering(c) ? "yes" : "no") << "</td><td>" << result.caseCounts[i]
      << "</td></tr>";
  }
  t << "</table><p>Reading the table: the count (bits 0-1) says how many of B's faces are "
       "at or in front of A<sub>max</sub>; bit 2 (value 4) and bit 3 (value 8) say whether "
       "B's front and back faces are at or behind A<sub>min</sub>. Count 2 is always "
       "contact (case 4 if B's front face is in front of A<sub>min</sub>, else 3). Count 3 "
       "is contact only if B's back face reaches A<sub>min</sub> (cases 5 and 6), else B "
       "is wholly in front of A (case 7). Count 1 with a bit set is B wholly behind A (case "
       "2); count 0 with a bit set is B alone (case 8).</p>";
  return t.str();
}

std::string caseDefinitionsHtml() {
  std::ostringstream t;
  t << "<table id=\"case-definitions\"><tr><th>case</th><th>on the view ray</th>"
       "<th>condition</th><th>stencil values</th><th>interferes</th></tr>";
  for (int c = 0; c < core::kCaseCount; ++c) {
    const auto i = static_cast<std::size_t>(c);
    t << "<tr id=\"term-case-" << c << "\"" << (core::isInterfering(c) ? " class=\"hit\"" : "")
      << "><td>" << c << "</td><td>" << escapeHtml(core::caseName(c)) << "</td><td>"
      << kCaseCondition[i] << "</td><td>" << stencilValuesOfCase(c) << "</td><td>"
      << (core::isInterfering(c) ? "yes" : "no") << "</td></tr>";
  }
  t << "</table>";
  return t.str();
}

std::string contactText(const core::ContactRegion& c) {
  std::ostringstream t;
  t << "<p>Each interfering pixel (yellow) is a ray segment inside both blocks: unprojecting "
       "its centre at the two depths of the previous steps gives two world points. Together "
       "they outline where the blocks overlap. The area is the number of interfering pixels "
       "times the area of one pixel; the greatest depth is the longest such segment, how "
       "deep the blocks overlap along the view axis.</p><table>"
    << "<tr><td>interfering pixels</td><td>" << c.pixels << "</td></tr>"
    << "<tr><td>area (world units&sup2;)</td><td>" << formatNumber(c.area) << "</td></tr>";
  if (!c.box.isEmpty())
    t << "<tr><td>box</td><td>" << pointText(c.box.min) << " &ndash; " << pointText(c.box.max)
      << "</td></tr>";
  t << "<tr><td>greatest overlap depth (world units)</td><td>" << formatNumber(c.maxDepth)
    << "</td></tr><tr><td>contact points</td><td>" << c.points.size()
    << " (one per interfering pixel, halfway along its overlap)</td></tr>";
  if (c.collapsedPixels > 0)
    t << "<tr><td>pixels touching within depth rounding</td><td>" << c.collapsedPixels
      << "</td></tr>";
  t << "</table>";
  return t.str();
}

std::string verdictHtml(const core::PairResult& result) {
  std::ostringstream t;
  t << "<p class=\"verdict " << (result.collide ? "yes\">The blocks collide" : "no\">No collision")
    << "</p><p>";
  if (result.mor.empty())
    t << "The bounding boxes do not overlap: decided without drawing anything.";
  else
    t << result.interferingPixels << " of the MOR's " << result.mor.area()
      << " pixels interfere (cases 3-6: the ray passes through a point inside both blocks). "
         "Contact area "
      << formatNumber(result.contact.area) << " world units&sup2;, greatest overlap depth "
      << formatNumber(result.contact.maxDepth) << " world units.";
  t << "</p>";
  return t.str();
}

}  // namespace recode::explain
