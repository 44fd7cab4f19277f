#include "explain_command.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pair_setup.hpp"
#include "png_image.hpp"
#include "recode/core/frame.hpp"
#include "recode/core/pair.hpp"
#include "recode/core/pair_cases.hpp"
#include "recode/core/view.hpp"
#include "recode/raster/cpu_device.hpp"

namespace recode::app {

namespace {

namespace fs = std::filesystem;
using core::PairStep;
using raster::PixelRect;

// Every step is kept as a full-frame copy of both buffers, so the frame is limited to keep
// that (and one picture pixel per framebuffer pixel) reasonable.
constexpr int kMaxExplainSide = 2048;

struct ExplainOptions {
  std::string scene;  // empty: the built-in pair
  std::string out;
  std::string mor = "min";
  std::string resolution;
  bool boxTest = true;
};

// ---------------------------------------------------------------------------------------
// Colours. One set for every picture so the page reads consistently.

constexpr Rgb kEmpty{17, 17, 17};         // nothing here
constexpr Rgb kColourA{58, 120, 216};     // block A
constexpr Rgb kColourB{214, 69, 69};      // block B
constexpr Rgb kColourBoth{155, 64, 192};  // A and B on the same pixel
constexpr Rgb kMorOutline{0, 229, 255};   // the MOR rectangle
constexpr Rgb kContactOutline{255, 255, 255};
constexpr Rgb kHatch{70, 78, 88};          // outside the rectangle a step works on
constexpr Rgb kNotExamined{43, 43, 43};    // case map outside the MOR
constexpr Rgb kDepthZero{27, 59, 111};     // depth exactly 0 (a clear to 0 left it)
constexpr Rgb kInterfering{255, 210, 63};  // contact picture highlight
constexpr Rgb kUnexpected{255, 0, 255};    // a stencil value the encoding never produces

// Stencil values 0..15: the hue is the count in bits 0-1 (grey: A absent, blue: A only so
// far, orange: one face of B at or before Amax, green: both), the lightness the two Amin
// bits (none, bit 2, bit 3, both).
// clang-format off
constexpr std::array<Rgb, 16> kStencilPalette = {{
    // count 0          count 1          count 2         count 3
    {17, 17, 17},    {40, 75, 150},   {150, 72, 0},   {35, 115, 40},    // no Amin bit
    {80, 80, 80},    {60, 110, 200},  {195, 98, 0},   {50, 150, 56},    // bit 2
    {122, 122, 122}, {100, 150, 230}, {235, 135, 20}, {85, 195, 90},    // bit 3
    {176, 176, 176}, {160, 200, 245}, {255, 185, 90}, {160, 230, 160},  // bits 2 and 3
}};
// clang-format on

// Cases 0..8; the interfering cases 3-6 in warm colours.
constexpr std::array<Rgb, core::kCaseCount> kCasePalette = {{
    {17, 17, 17},     // 0 neither
    {47, 95, 179},    // 1 A only
    {108, 90, 158},   // 2 B behind A
    {255, 210, 63},   // 3
    {255, 140, 26},   // 4
    {230, 57, 70},    // 5
    {255, 95, 162},   // 6
    {138, 159, 208},  // 7 B in front of A
    {42, 157, 143},   // 8 B only
}};

Rgb stencilColour(std::uint8_t value) {
  return value < kStencilPalette.size() ? kStencilPalette[value] : kUnexpected;
}

// Grey from depth: near bright, far dark. `nearest`..`farthest` map onto white..black (the
// whole range normally; a close-up stretches its own range). Exactly 0 has its own colour.
Rgb depthColour(std::uint32_t depth, std::uint32_t nearest = 0,
                std::uint32_t farthest = raster::kDepthMax) {
  if (depth == 0)
    return kDepthZero;
  const double span = std::max(1.0, static_cast<double>(farthest) - static_cast<double>(nearest));
  const double nearness = 1.0 - (static_cast<double>(depth) - static_cast<double>(nearest)) / span;
  const auto g = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(nearness, 0.0, 1.0)));
  return {g, g, g};
}

// ---------------------------------------------------------------------------------------
// Recording the buffers after each step.

struct Snapshot {
  PairStep step;
  std::vector<std::uint8_t> stencil;  // whole frame, bottom row first
  std::vector<std::uint32_t> depth;
};

class Recorder final : public core::PairObserver {
 public:
  void afterStep(PairStep step, raster::DepthStencilDevice& device) override {
    const PixelRect all{0, 0, device.width(), device.height()};
    snapshots.push_back({step, device.readStencil(all), device.readDepth(all)});
  }
  std::vector<Snapshot> snapshots;
};

// ---------------------------------------------------------------------------------------
// Pictures of the frame.

// Paints a region of the frame (the whole frame, or a zoom on part of it), each framebuffer
// pixel as a scale x scale block, the frame's top row at the top.
class Painter {
 public:
  // The smallest whole magnification that makes the picture at least `minWidth` wide
  // (1024 at most on its longer side, where that leaves a magnification of at least 1).
  Painter(const PixelRect& region, int minWidth)
      : region_(region), scale_(upscaleFactor(region.width(), region.height(), minWidth, 1024)) {}
  [[nodiscard]] const PixelRect& region() const { return region_; }
  [[nodiscard]] int scale() const { return scale_; }
  [[nodiscard]] int pictureWidth() const { return region_.width() * scale_; }
  [[nodiscard]] int pictureHeight() const { return region_.height() * scale_; }

  // colourAt(x, y) in GL pixel coordinates (y up).
  template <class F>
  [[nodiscard]] RgbImage paint(F colourAt) const {
    RgbImage image(region_.width(), region_.height());
    for (int y = region_.y0; y < region_.y1; ++y)
      for (int x = region_.x0; x < region_.x1; ++x)
        image.set(x - region_.x0, region_.y1 - 1 - y, colourAt(x, y));
    return upscaled(image, scale_);
  }

  [[nodiscard]] ImageRect toImage(const PixelRect& r) const {
    return {(r.x0 - region_.x0) * scale_, (region_.y1 - r.y1) * scale_,
            (r.x1 - region_.x0) * scale_, (region_.y1 - r.y0) * scale_};
  }

  void outline(RgbImage& image, const PixelRect& r, Rgb colour) const {
    if (!r.empty())
      outlineRect(image, toImage(r), colour, std::clamp(scale_ / 4, 1, 3));
  }

  // Diagonal hatching over everything outside `active`: the step did not touch it.
  void hatchOutside(RgbImage& image, const PixelRect& active) const {
    const ImageRect a = toImage(active);
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const bool inside = !active.empty() && x >= a.x0 && x < a.x1 && y >= a.y0 && y < a.y1;
        if (!inside && (x + y) % 6 == 0)
          image.set(x, y, kHatch);
      }
  }

 private:
  PixelRect region_;
  int scale_;
};

std::size_t pixelIndex(int x, int y, int width) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
         static_cast<std::size_t>(x);
}

bool contains(const PixelRect& r, int x, int y) {
  return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
}

// Coverage of A (bit 0) and B (bit 1) over the whole frame, drawn through the device
// interface on a device of its own: depth test ALWAYS, no depth writes, each block setting
// its own stencil bit.
std::vector<std::uint8_t> silhouettes(const PairSetup& setup, double depthMin, double depthMax) {
  const core::FrameSpec& f = setup.frame;
  const core::OrthoView view(f.axis, f.window, f.width, f.height, depthMin, depthMax);
  raster::CpuDevice device(f.width, f.height);
  device.setScissor({0, 0, f.width, f.height});
  device.setStencilWriteMask(0xFF);
  device.clearStencil(0);
  device.setDepthWriteMask(false);
  device.setDepthFunc(raster::CompareFunc::Always);
  device.setCullMode(raster::CullMode::None);
  device.setStencilOps(raster::Face::Both, {raster::StencilOp::Keep, raster::StencilOp::Keep,
                                            raster::StencilOp::Replace});
  const auto draw = [&](const core::TriangleMesh& mesh, std::uint8_t bit) {
    device.setStencilFunc(raster::CompareFunc::Always, bit, 0xFF);
    device.setStencilWriteMask(bit);
    const auto vertices = view.toWindow(mesh);
    const auto indices = core::triangleIndices(mesh);
    device.drawTriangles(vertices, indices);
  };
  draw(setup.a, 1);
  draw(setup.b, 2);
  return device.readStencil({0, 0, f.width, f.height});
}

Rgb coverageColour(std::uint8_t coverage) {
  switch (coverage & 3) {
    case 1:
      return kColourA;
    case 2:
      return kColourB;
    case 3:
      return kColourBoth;
    default:
      return kEmpty;
  }
}

// ---------------------------------------------------------------------------------------
// Text.

std::string escapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s << std::setprecision(6) << v;
  return s.str();
}

std::string rectText(const PixelRect& r) {
  std::ostringstream s;
  s << "[" << r.x0 << ", " << r.y0 << ", " << r.x1 << ", " << r.y1 << ")";
  return s.str();
}

std::string pointText(const Eigen::Vector3d& p) {
  return "(" + formatNumber(p.x()) + ", " + formatNumber(p.y()) + ", " + formatNumber(p.z()) + ")";
}

std::string_view axisName(core::ViewAxis axis) {
  switch (axis) {
    case core::ViewAxis::X:
      return "x";
    case core::ViewAxis::Y:
      return "y";
    case core::ViewAxis::Z:
      return "z";
  }
  return "?";
}

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

// What a stencil value means once `step` has run.
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

struct LegendEntry {
  Rgb colour;
  std::string label;      // HTML
  long long pixels = -1;  // < 0: not shown
};

struct Picture {
  std::string file;
  std::string kind;   // silhouettes, depth, stencil, cases, contact
  bool zoom = false;  // a close-up of part of the frame
  PixelRect region;   // the part of the frame shown
  int scale = 1;      // picture pixels per framebuffer pixel, each way
  int width = 0;      // picture size
  int height = 0;
  std::string caption;  // HTML
  std::vector<LegendEntry> legend;
  bool depthLegend = false;
  double depthNear = 0.0;  // the depths shown white and black
  double depthFar = 1.0;
};

struct Section {
  std::string id;
  std::string step;   // the PairStep's name, or "" for sections that are not a step
  std::string title;  // HTML
  std::string text;   // HTML paragraphs
  std::vector<Picture> pictures;
};

// The explanation of each step, for a student who has not read the paper.
std::string stepTitle(PairStep step) {
  switch (step) {
    case PairStep::SetZ:
      return "RenderSetZ(A, &ge;): the far side of A into the depth buffer";
    case PairStep::TestZ:
      return "RenderTestZ(B, &le;): count B's faces in front of A's far side";
    case PairStep::LoadAmin:
      return "Load the near side of A into the depth buffer";
    case PairStep::TestAminFront:
      return "Is B's front face at or behind A's near side? (stencil bit 2)";
    case PairStep::TestAminBack:
      return "Is B's back face at or behind A's near side? (stencil bit 3)";
    case PairStep::ReadStencil:
      return "Read back the stencil and classify every pixel";
    case PairStep::ContactNear:
      return "Contact: the near end of the overlap, max(A<sub>min</sub>, B<sub>min</sub>)";
    case PairStep::ContactFar:
      return "Contact: the far end of the overlap, min(A<sub>max</sub>, B<sub>max</sub>)";
  }
  return "?";
}

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
             "(black).</p>"
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

// Which buffers a step is about (a buffer that changed is pictured as well).
bool stepWritesDepth(PairStep s) {
  return s == PairStep::SetZ || s == PairStep::LoadAmin || s == PairStep::ContactNear ||
         s == PairStep::ContactFar;
}
bool stepWritesStencil(PairStep s) {
  return s == PairStep::SetZ || s == PairStep::TestZ || s == PairStep::TestAminFront ||
         s == PairStep::TestAminBack;
}

std::string fileStem(int sectionNumber, std::string_view name) {
  std::ostringstream s;
  s << std::setw(2) << std::setfill('0') << sectionNumber << '-' << name;
  return s.str();
}

// ---------------------------------------------------------------------------------------
// The run.

core::MorMode parseMor(const std::string& text) {
  if (text == "min")
    return core::MorMode::Min;
  if (text == "max")
    return core::MorMode::Max;
  return core::MorMode::Full;
}

fs::path prepareOutDir(const std::string& out) {
  const fs::path dir(out);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw std::runtime_error("--out " + out + ": cannot create the directory: " + ec.message());
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error("--out " + out + ": exists and is not a directory");
  return dir;
}

nlohmann::json colourJson(Rgb c) {
  return nlohmann::json::array({c.r, c.g, c.b});
}

// Outside the rectangle a step works in, buffers are shown at this brightness (and hatched).
constexpr double kOutsideBrightness = 0.35;

class Explainer {
 public:
  Explainer(const ExplainOptions& options, PairSetup setup)
      : options_(options),
        setup_(std::move(setup)),
        frame_{0, 0, setup_.frame.width, setup_.frame.height},
        painter_(frame_, 512),
        dir_(prepareOutDir(options.out)) {}

  int run() {
    const core::FrameSpec& f = setup_.frame;
    core::PairRequest request;
    request.frame = f;
    request.mor = parseMor(options_.mor);
    request.contact = true;
    request.boxTest = options_.boxTest;
    raster::CpuDevice device(f.width, f.height);
    Recorder recorder;
    result_ = core::collidePair(device, setup_.a, setup_.b, request, &recorder);

    const auto range =
        core::pairDepthRange(f.axis, core::boundingBox(setup_.a), core::boundingBox(setup_.b));
    coverage_ = silhouettes(setup_, range[0], range[1]);
    zoom_ = zoomPainter();

    addSilhouettes();
    std::vector<std::uint8_t> prevStencil(coverage_.size(), 0);
    std::vector<std::uint32_t> prevDepth(coverage_.size(), raster::kDepthMax);
    for (const Snapshot& snap : recorder.snapshots) {
      addStep(snap, prevStencil, prevDepth);
      prevStencil = snap.stencil;
      prevDepth = snap.depth;
    }
    if (result_.collide)
      addContact();
    writeHtml();
    writeJson();

    std::size_t pictures = 0;
    for (const Section& s : sections_)
      pictures += s.pictures.size();
    std::cout << "recode explain: " << setup_.nameA << " and " << setup_.nameB << ", " << f.width
              << "x" << f.height << " pixels along " << axisName(f.axis) << ", MOR " << options_.mor
              << ": " << (result_.collide ? "collide" : "no collision") << " ("
              << result_.interferingPixels << " interfering pixels)\n"
              << "  wrote " << pictures << (pictures == 1 ? " picture" : " pictures")
              << ", index.html and explain.json to " << dir_.string() << '\n';
    return 0;
  }

 private:
  [[nodiscard]] const PixelRect& mor() const { return result_.mor; }
  [[nodiscard]] int frameWidth() const { return setup_.frame.width; }

  // A close-up of where both blocks cover the frame (the only place where they can touch)
  // when that is a small part of the frame: the pixels' bounding rectangle with a margin,
  // magnified at least twice as much as the whole-frame pictures.
  [[nodiscard]] std::optional<Painter> zoomPainter() const {
    if (result_.mor.empty())
      return std::nullopt;
    const int w = frameWidth();
    PixelRect c{frame_.x1, frame_.y1, frame_.x0, frame_.y0};
    for (int y = 0; y < frame_.y1; ++y)
      for (int x = 0; x < frame_.x1; ++x)
        if ((coverage_[pixelIndex(x, y, w)] & 3u) == 3u)
          c = {std::min(c.x0, x), std::min(c.y0, y), std::max(c.x1, x + 1), std::max(c.y1, y + 1)};
    if (c.empty())
      return std::nullopt;
    const int margin = std::max(2, std::max(c.width(), c.height()) / 4);
    const PixelRect region =
        PixelRect{c.x0 - margin, c.y0 - margin, c.x1 + margin, c.y1 + margin}.intersect(frame_);
    Painter zoom(region, 384);
    if (2 * region.width() > frame_.width() && 2 * region.height() > frame_.height())
      return std::nullopt;
    if (zoom.scale() < 2 * painter_.scale())
      return std::nullopt;
    return zoom;
  }

  Picture makePicture(const Painter& painter, const std::string& stem, std::string kind,
                      const RgbImage& image) {
    Picture p;
    p.file = stem + ".png";
    writePng(dir_ / p.file, image);
    p.kind = std::move(kind);
    p.zoom = painter.region() != frame_;
    p.region = painter.region();
    p.scale = painter.scale();
    p.width = image.width();
    p.height = image.height();
    return p;
  }

  void addSilhouettes() {
    const int w = frameWidth();
    RgbImage image = painter_.paint(
        [&](int x, int y) { return coverageColour(coverage_[pixelIndex(x, y, w)]); });
    painter_.outline(image, mor(), kMorOutline);
    std::array<long long, 4> counts{};
    for (std::uint8_t c : coverage_)
      ++counts[c & 3u];

    Section s;
    s.id = "silhouettes";
    s.title = "The two blocks and the MOR";
    std::ostringstream t;
    t << "<p>Both blocks drawn flat, seen along the view axis. Each framebuffer pixel is one "
         "ray parallel to the axis; a convex block meets such a ray in a single stretch "
         "[min, max] of depth, entering through a front face and leaving through a back face, "
         "and the blocks interfere exactly where these stretches overlap on some ray. Where "
         "only one block (or neither) covers a pixel they cannot touch there.</p>"
         "<p>The <b>MOR</b> (minimum overlapping region, cyan frame) is the pixel rectangle "
         "the algorithm works in. ";
    switch (parseMor(options_.mor)) {
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
    if (!result_.mor.empty())
      t << "<p>MOR " << rectText(mor())
        << " (x from the left, y from the bottom, half-open): " << mor().width() << " &times; "
        << mor().height() << " = " << mor().area() << " of the frame's " << frame_.area()
        << " pixels.</p>";
    if (!result_.boxesOverlap) {
      t << "<p><b>The boxes do not overlap</b> (their projections share no pixel centre, or "
           "their depth ranges do not meet), so the blocks cannot collide. ";
      if (options_.boxTest)
        t << "Nothing is drawn: the algorithm stops here (run with <code>--no-box-test</code> "
             "to see the passes anyway).</p>";
      else if (result_.mor.empty())
        t << "The passes were asked for (<code>--no-box-test</code>) but the MOR is empty, so "
             "there is nothing to draw.</p>";
      else
        t << "Normally the algorithm would stop here; <code>--no-box-test</code> runs the "
             "passes anyway, to show the cases of blocks that do not touch.</p>";
    }
    s.text = t.str();
    Picture p = makePicture(painter_, fileStem(1, "silhouettes"), "silhouettes", image);
    p.caption = "Coverage of A and B over the whole frame; cyan: the MOR.";
    p.legend = {{kColourA, "A only (" + escapeHtml(setup_.nameA) + ")", counts[1]},
                {kColourB, "B only (" + escapeHtml(setup_.nameB) + ")", counts[2]},
                {kColourBoth, "both A and B", counts[3]},
                {kEmpty, "neither", counts[0]},
                {kMorOutline, "MOR outline", -1}};
    s.pictures.push_back(std::move(p));
    sections_.push_back(std::move(s));
  }

  // The rectangle a step draws in (its scissor).
  [[nodiscard]] PixelRect activeRect(PairStep step) const {
    return step == PairStep::ContactNear || step == PairStep::ContactFar ? result_.contactRect
                                                                         : result_.mor;
  }

  // colourAt inside `active`, dimmed outside it, hatched outside it, the MOR (and `active`
  // if it differs) outlined.
  template <class F>
  [[nodiscard]] RgbImage bufferImage(const Painter& painter, const PixelRect& active,
                                     F colourAt) const {
    RgbImage image = painter.paint([&](int x, int y) {
      const Rgb c = colourAt(x, y);
      return contains(active, x, y) ? c : dimmed(c, kOutsideBrightness);
    });
    painter.hatchOutside(image, active);
    painter.outline(image, mor(), kMorOutline);
    if (active != mor())
      painter.outline(image, active, kContactOutline);
    return image;
  }

  Picture depthPicture(const Painter& painter, const Snapshot& snap, int number) {
    const int w = frameWidth();
    const PixelRect active = activeRect(snap.step);
    const bool zoom = painter.region() != frame_;
    // A close-up stretches the grey levels over the depths inside the step's rectangle
    // (leaving out the clear values 0 and 1), so small differences show.
    std::uint32_t nearest = 0, farthest = raster::kDepthMax;
    if (zoom) {
      std::uint32_t lo = raster::kDepthMax, hi = 0;
      const PixelRect shown = active.intersect(painter.region());
      for (int y = shown.y0; y < shown.y1; ++y)
        for (int x = shown.x0; x < shown.x1; ++x) {
          const std::uint32_t d = snap.depth[pixelIndex(x, y, w)];
          if (d != 0 && d != raster::kDepthMax) {
            lo = std::min(lo, d);
            hi = std::max(hi, d);
          }
        }
      if (lo <= hi) {
        nearest = lo;
        farthest = hi;
      }
    }
    const RgbImage image = bufferImage(painter, active, [&](int x, int y) {
      return depthColour(snap.depth[pixelIndex(x, y, w)], nearest, farthest);
    });
    Picture p = makePicture(painter,
                            fileStem(number, std::string(core::toString(snap.step)) +
                                                 (zoom ? "-depth-zoom" : "-depth")),
                            "depth", image);
    p.caption = zoom ? "Close-up of where both blocks are, grey levels stretched over the depths "
                       "drawn there in this step."
                     : "Depth buffer after this step: near is bright, far is dark.";
    const double scale = 1.0 / static_cast<double>(raster::kDepthMax);
    p.depthNear = nearest * scale;
    p.depthFar = farthest * scale;
    p.depthLegend = true;
    return p;
  }

  Picture stencilPicture(const Painter& painter, const Snapshot& snap, int number) {
    const int w = frameWidth();
    const PixelRect active = activeRect(snap.step);
    const RgbImage image = bufferImage(painter, active, [&](int x, int y) {
      return stencilColour(snap.stencil[pixelIndex(x, y, w)]);
    });
    const bool zoom = painter.region() != frame_;
    if (zoom) {
      Picture p = makePicture(
          painter, fileStem(number, std::string(core::toString(snap.step)) + "-stencil-zoom"),
          "stencil", image);
      p.caption = "Close-up of where both blocks are; colours as in the picture beside it.";
      return p;
    }
    std::array<long long, 256> counts{};
    for (int y = active.y0; y < active.y1; ++y)
      for (int x = active.x0; x < active.x1; ++x)
        ++counts[snap.stencil[pixelIndex(x, y, w)]];
    Picture p =
        makePicture(painter, fileStem(number, std::string(core::toString(snap.step)) + "-stencil"),
                    "stencil", image);
    p.caption = "Stencil buffer after this step (pixel counts inside the MOR).";
    for (int v = 0; v < 256; ++v) {
      if (counts[static_cast<std::size_t>(v)] == 0)
        continue;
      const auto value = static_cast<std::uint8_t>(v);
      std::ostringstream label;
      label << "<code>" << v << "</code> (binary <code>";
      for (int bit = 3; bit >= 0; --bit)
        label << ((v >> bit) & 1);
      label << "</code>): " << stencilMeaning(value, snap.step);
      p.legend.push_back({stencilColour(value), label.str(), counts[static_cast<std::size_t>(v)]});
    }
    p.legend.push_back({kHatch, "hatched, dimmed: outside the MOR, never drawn or read", -1});
    return p;
  }

  [[nodiscard]] int caseAt(int x, int y) const {
    const PixelRect& m = mor();
    if (!contains(m, x, y))
      return -1;
    return result_.caseMap[pixelIndex(x - m.x0, y - m.y0, m.width())];
  }

  Picture casePicture(const Painter& painter, int number) {
    RgbImage image = painter.paint([&](int x, int y) {
      const int c = caseAt(x, y);
      if (c < 0)
        return kNotExamined;
      return c < core::kCaseCount ? kCasePalette[static_cast<std::size_t>(c)] : kUnexpected;
    });
    painter.hatchOutside(image, mor());
    painter.outline(image, mor(), kMorOutline);
    const bool zoom = painter.region() != frame_;
    if (zoom)
      painter.outline(image, result_.contactRect, kContactOutline);
    Picture p =
        makePicture(painter, fileStem(number, zoom ? "cases-zoom" : "cases"), "cases", image);
    p.caption = zoom ? "Close-up of where both blocks are (white frame: the interfering pixels' "
                       "rectangle)."
                     : "The case of every MOR pixel; warm colours interfere.";
    for (int c = 0; c < core::kCaseCount; ++c) {
      const auto i = static_cast<std::size_t>(c);
      if (zoom && result_.caseCounts[i] == 0)
        continue;
      std::string label = "case " + std::to_string(c) + ": " + std::string(core::caseName(c));
      if (core::isInterfering(c))
        label += " <b>(interferes)</b>";
      p.legend.push_back({kCasePalette[i], label, zoom ? -1 : result_.caseCounts[i]});
    }
    p.legend.push_back({kNotExamined, "hatched: outside the MOR, not examined", -1});
    return p;
  }

  void addStep(const Snapshot& snap, const std::vector<std::uint8_t>& prevStencil,
               const std::vector<std::uint32_t>& prevDepth) {
    const int number = static_cast<int>(sections_.size()) + 1;
    Section s;
    s.id = std::string(core::toString(snap.step));
    s.step = s.id;
    s.title = stepTitle(snap.step);
    s.text = stepText(snap.step);
    if (snap.step == PairStep::ReadStencil) {
      s.text += caseTableHtml();
      s.pictures.push_back(casePicture(painter_, number));
      if (zoom_)
        s.pictures.push_back(casePicture(*zoom_, number));
    } else {
      if (stepWritesDepth(snap.step) || snap.depth != prevDepth) {
        s.pictures.push_back(depthPicture(painter_, snap, number));
        if (zoom_)
          s.pictures.push_back(depthPicture(*zoom_, snap, number));
      }
      if (stepWritesStencil(snap.step) || snap.stencil != prevStencil) {
        s.pictures.push_back(stencilPicture(painter_, snap, number));
        if (zoom_)
          s.pictures.push_back(stencilPicture(*zoom_, snap, number));
      }
    }
    sections_.push_back(std::move(s));
  }

  [[nodiscard]] std::string caseTableHtml() const {
    std::ostringstream t;
    t << "<table><tr><th></th><th>case</th><th>on the view ray</th><th>condition</th>"
         "<th>stencil values</th><th>interferes</th><th>pixels in the MOR</th></tr>";
    for (int c = 0; c < core::kCaseCount; ++c) {
      const auto i = static_cast<std::size_t>(c);
      t << "<tr" << (core::isInterfering(c) ? " class=\"hit\"" : "") << "><td>"
        << swatch(kCasePalette[i]) << "</td><td>" << c << "</td><td>"
        << escapeHtml(core::caseName(c)) << "</td><td>" << kCaseCondition[i] << "</td><td>"
        << stencilValuesOfCase(c) << "</td><td>" << (core::isInterfering(c) ? "yes" : "no")
        << "</td><td>" << result_.caseCounts[i] << "</td></tr>";
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

  Picture contactPicture(const Painter& painter, int number) {
    const int w = frameWidth();
    RgbImage image = painter.paint([&](int x, int y) {
      if (core::isInterfering(caseAt(x, y)))
        return kInterfering;
      return dimmed(coverageColour(coverage_[pixelIndex(x, y, w)]), 0.4);
    });
    painter.outline(image, mor(), kMorOutline);
    painter.outline(image, result_.contactRect, kContactOutline);
    const bool zoom = painter.region() != frame_;
    Picture p =
        makePicture(painter, fileStem(number, zoom ? "contact-zoom" : "contact"), "contact", image);
    p.caption = zoom ? "Close-up of the contact region."
                     : "Interfering pixels over the dimmed silhouettes.";
    p.legend = {{kInterfering, "interfering pixel (cases 3-6)", result_.contact.pixels},
                {dimmed(kColourA, 0.4), "A", -1},
                {dimmed(kColourB, 0.4), "B", -1},
                {dimmed(kColourBoth, 0.4), "A and B, not interfering", -1},
                {kContactOutline, "bounding rectangle of the interfering pixels", -1},
                {kMorOutline, "MOR", -1}};
    return p;
  }

  void addContact() {
    const core::ContactRegion& c = result_.contact;
    const int number = static_cast<int>(sections_.size()) + 1;
    Section s;
    s.id = "contact";
    s.title = "The contact region";
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
    s.text = t.str();
    s.pictures.push_back(contactPicture(painter_, number));
    if (zoom_)
      s.pictures.push_back(contactPicture(*zoom_, number));
    sections_.push_back(std::move(s));
  }

  static std::string swatch(Rgb c) {
    return "<span class=\"sw\" style=\"background:" + hexColour(c) + "\"></span>";
  }

  [[nodiscard]] std::string verdictHtml() const {
    std::ostringstream t;
    t << "<p class=\"verdict "
      << (result_.collide ? "yes\">The blocks collide" : "no\">No collision") << "</p><p>";
    if (result_.mor.empty())
      t << "The bounding boxes do not overlap: decided without drawing anything.";
    else
      t << result_.interferingPixels << " of the MOR's " << mor().area()
        << " pixels interfere (cases 3-6). Contact area " << formatNumber(result_.contact.area)
        << " world units&sup2;, greatest overlap depth " << formatNumber(result_.contact.maxDepth)
        << " world units.";
    t << "</p>";
    return t.str();
  }

  void writeHtml() const {
    const core::FrameSpec& f = setup_.frame;
    const std::string source = escapeHtml(setup_.source);
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
         "<title>RECODE step by step</title><style>\n"
         "body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;"
         "line-height:1.45;color:#222}\n"
         "section{border-top:1px solid #ccc;margin-top:2em;padding-top:.5em}\n"
         "figure{display:inline-block;vertical-align:top;margin:.5em 1.5em .5em 0}\n"
         "img{image-rendering:pixelated;max-width:100%;height:auto;border:1px solid #888}\n"
         "figcaption{font-size:.9em;color:#444;max-width:520px}\n"
         ".sw{display:inline-block;width:1.1em;height:1.1em;border:1px solid #555;"
         "vertical-align:middle;margin-right:.4em}\n"
         ".grad{display:inline-block;width:12em;height:1.1em;border:1px solid #555;"
         "vertical-align:middle;background:linear-gradient(to right,#ffffff,#000000)}\n"
         "ul.legend{list-style:none;padding-left:0;font-size:.9em}\n"
         "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #bbb;"
         "padding:.2em .5em;text-align:left}tr.hit{background:#fff3d6}\n"
         ".verdict{font-size:1.3em;font-weight:bold}.verdict.yes{color:#b3261e}"
         ".verdict.no{color:#1e6b2e}\ncode{background:#f2f2f2;padding:0 .2em}\n"
         "</style></head><body>\n";
    h << "<h1>RECODE step by step</h1>\n<p>Block A: <b>" << escapeHtml(setup_.nameA)
      << "</b>, block B: <b>" << escapeHtml(setup_.nameB) << "</b>, from " << source << ". View "
      << "along the " << axisName(f.axis) << " axis, " << f.width << " &times; " << f.height
      << " pixels, MOR mode <code>" << escapeHtml(options_.mor) << "</code>.</p>\n"
      << verdictHtml() << '\n';
    h << "<h2>How RECODE works, and how to read the pictures</h2>\n"
         "<p>RECODE (REndered COllision DEtection, Baciu, Wong and Sun 1999) decides whether "
         "two convex blocks A and B touch by <i>drawing</i> them, as a graphics card would, "
         "instead of intersecting their triangles in 3-D. A graphics card keeps two numbers "
         "for every pixel besides its colour: the <b>depth</b> (how far along the view "
         "direction the drawn surface is, 0 nearest to the viewer, 1 farthest, stored as a "
         "24-bit integer) and the <b>stencil</b> (an 8-bit counter). When a triangle is "
         "drawn, each pixel it covers produces a <i>fragment</i> with its own depth. The "
         "<b>depth test</b> compares it with the stored depth (e.g. <code>LEQUAL</code>: pass "
         "if the fragment is at or in front of what is stored) and, if depth writes are on, "
         "a passing fragment stores its depth. The <b>stencil test</b> compares the stored "
         "stencil with a reference value, and the <b>stencil operations</b> say what to do "
         "with the stencil when the stencil test fails, when the depth test fails, or when "
         "both pass (keep, replace, increment, invert a bit...).</p>\n"
         "<p>RECODE chooses these tests so that after a few passes each pixel's stencil "
         "tells how the two blocks' depth intervals along that pixel's ray are arranged. "
         "Reading the stencil back then gives the verdict and the contact region. Here every "
         "pass runs on the reference CPU depth/stencil machine, exactly as a GPU back end "
         "would run it.</p>\n"
         "<p>Pictures: each framebuffer pixel is shown as a "
      << painter_.scale() << " &times; " << painter_.scale()
      << " block (close-ups magnify more), the top of the picture is the top of the frame. "
         "The cyan frame is the MOR; dimmed, hatched pixels are outside the rectangle a step "
         "works in (the step does not touch them). Depth pictures show near as bright and far "
         "as dark. Notation: A<sub>min</sub> and A<sub>max</sub> are the depths where a "
         "pixel's ray enters and leaves A, likewise B<sub>min</sub>, B<sub>max</sub>.</p>\n";
    for (const Section& s : sections_) {
      h << "<section id=\"" << s.id << "\"><h2>" << s.title << "</h2>\n" << s.text << '\n';
      for (const Picture& p : s.pictures) {
        h << "<figure><img src=\"" << p.file << "\" width=\"" << p.width << "\" height=\""
          << p.height << "\" alt=\"" << p.kind << (p.zoom ? " close-up" : "") << "\"><figcaption>"
          << p.caption << "<ul class=\"legend\">";
        if (p.depthLegend)
          h << "<li>near (" << formatNumber(p.depthNear) << ") <span class=\"grad\"></span> far ("
            << formatNumber(p.depthFar) << ")</li><li>" << swatch(kDepthZero)
            << "exactly 0: a clear to 0 left it (nothing drawn here)</li><li>" << swatch(kHatch)
            << "hatched, dimmed: outside the rectangle this step draws in</li>";
        for (const LegendEntry& e : p.legend) {
          h << "<li>" << swatch(e.colour) << e.label;
          if (e.pixels >= 0)
            h << " &mdash; " << e.pixels << " px";
          h << "</li>";
        }
        h << "</ul></figcaption></figure>\n";
      }
      h << "</section>\n";
    }
    h << "<section id=\"verdict\"><h2>Verdict</h2>" << verdictHtml() << "</section>\n"
      << "</body></html>\n";
    writeText(dir_ / "index.html", h.str());
  }

  void writeJson() const {
    nlohmann::json j;
    const core::FrameSpec& f = setup_.frame;
    const auto rect = [](const PixelRect& r) {
      return nlohmann::json::array({r.x0, r.y0, r.x1, r.y1});
    };
    j["source"] = setup_.source;
    j["objects"] = {setup_.nameA, setup_.nameB};
    j["axis"] = axisName(f.axis);
    j["width"] = f.width;
    j["height"] = f.height;
    j["scale"] = painter_.scale();
    j["mor_mode"] = options_.mor;
    j["collide"] = result_.collide;
    j["boxes_overlap"] = result_.boxesOverlap;
    j["mor"] = rect(result_.mor);
    j["contact_rect"] = rect(result_.contactRect);
    nlohmann::json counts = nlohmann::json::object();
    for (int c = 0; c < core::kCaseCount; ++c)
      counts[std::to_string(c)] = result_.caseCounts[static_cast<std::size_t>(c)];
    j["case_counts"] = counts;
    j["interfering_pixels"] = result_.interferingPixels;
    nlohmann::json contact;
    contact["pixels"] = result_.contact.pixels;
    contact["area"] = result_.contact.area;
    contact["max_depth"] = result_.contact.maxDepth;
    if (!result_.contact.box.isEmpty()) {
      const auto& b = result_.contact.box;
      contact["box"] = {{b.min.x(), b.min.y(), b.min.z()}, {b.max.x(), b.max.y(), b.max.z()}};
    }
    j["contact"] = contact;
    nlohmann::json palettes;
    nlohmann::json cases = nlohmann::json::object();
    for (int c = 0; c < core::kCaseCount; ++c)
      cases[std::to_string(c)] = colourJson(kCasePalette[static_cast<std::size_t>(c)]);
    palettes["cases"] = cases;
    nlohmann::json stencil = nlohmann::json::object();
    for (std::size_t v = 0; v < kStencilPalette.size(); ++v)
      stencil[std::to_string(v)] = colourJson(kStencilPalette[v]);
    palettes["stencil"] = stencil;
    palettes["silhouettes"] = {{"a", colourJson(kColourA)},
                               {"b", colourJson(kColourB)},
                               {"both", colourJson(kColourBoth)},
                               {"neither", colourJson(kEmpty)}};
    palettes["interfering"] = colourJson(kInterfering);
    j["palettes"] = palettes;
    nlohmann::json sections = nlohmann::json::array();
    nlohmann::json pictures = nlohmann::json::array();
    for (const Section& s : sections_) {
      nlohmann::json files = nlohmann::json::array();
      for (const Picture& p : s.pictures) {
        files.push_back(p.file);
        pictures.push_back({{"file", p.file},
                            {"kind", p.kind},
                            {"section", s.id},
                            {"zoom", p.zoom},
                            {"region", rect(p.region)},
                            {"scale", p.scale},
                            {"width", p.width},
                            {"height", p.height}});
      }
      sections.push_back({{"id", s.id}, {"step", s.step}, {"files", files}});
    }
    j["sections"] = sections;
    j["pictures"] = pictures;
    writeText(dir_ / "explain.json", j.dump(2) + "\n");
  }

  static void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    if (!out)
      throw std::runtime_error(path.string() + ": cannot open for writing");
    out << text;
    if (!out)
      throw std::runtime_error(path.string() + ": write failed");
  }

  ExplainOptions options_;
  PairSetup setup_;
  PixelRect frame_;
  Painter painter_;
  std::optional<Painter> zoom_;
  fs::path dir_;
  core::PairResult result_;
  std::vector<std::uint8_t> coverage_;
  std::vector<Section> sections_;
};

int runExplain(const ExplainOptions& options) {
  const core::FrameOverrides overrides =
      options.resolution.empty() ? core::FrameOverrides{} : parseResolution(options.resolution);
  PairSetup setup = loadPairSetup(
      options.scene.empty() ? std::nullopt : std::optional<std::string>(options.scene), overrides);
  const core::FrameSpec& f = setup.frame;
  if (f.width > kMaxExplainSide || f.height > kMaxExplainSide)
    throw std::invalid_argument("the frame is " + std::to_string(f.width) + "x" +
                                std::to_string(f.height) + "; recode explain draws at most " +
                                std::to_string(kMaxExplainSide) +
                                " pixels a side (use --resolution)");
  Explainer explainer(options, std::move(setup));
  return explainer.run();
}

}  // namespace

void addExplainCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<ExplainOptions>();
  CLI::App* cmd = app.add_subcommand(
      "explain",
      "Run RECODE on one pair and write a picture of the buffers after every step, with an "
      "index.html that explains each step");
  cmd->add_option("scene", opts->scene,
                  "scene file (JSON, docs/scenes.md; its first two objects are A and B); omit "
                  "for the built-in pair")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", opts->out,
                  "directory for the pictures, index.html and explain.json "
                  "(created if missing)")
      ->required();
  cmd->add_option("--mor", opts->mor, "minimum overlapping region: min, max or full")
      ->check(CLI::IsMember({"min", "max", "full"}))
      ->capture_default_str();
  cmd->add_option("--resolution", opts->resolution,
                  "W or WxH pixels (W alone: square pixels); overrides the scene; at most " +
                      std::to_string(kMaxExplainSide) + " a side");
  cmd->add_flag("!--no-box-test", opts->boxTest,
                "run the passes even when the blocks' boxes are apart (shows cases 1, 2, 7, 8)");
  cmd->callback([opts, &exitCode]() { exitCode = runExplain(*opts); });
}

}  // namespace recode::app
