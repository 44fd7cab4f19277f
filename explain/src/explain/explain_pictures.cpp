// Turns the recorded buffers into PNG pictures (whole frame and close-ups) with their legends.
#include "explain/explain_pictures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <utility>

#include "explain/explain_format.hpp"
#include "explain/explain_palette.hpp"
#include "explain/explain_rays.hpp"
#include "explain/explain_text.hpp"
#include "recode/pair/pair_cases.hpp"

namespace recode::explain {

using core::PairStep;
using raster::PixelRect;

namespace {

// Outside the rectangle a step works in, buffers are shown at this brightness (and hatched).
constexpr double kOutsideBrightness = 0.35;

Rgb stencilColour(std::uint8_t value) {
  return value < kStencilPalette.size() ? kStencilPalette[value] : kUnexpected;
}

// Grey from depth: near bright, far dark. `nearest`..`farthest` map onto white..black (the
// depths drawn in the step, stretched). Exactly 0 and exactly 1, the two clear values, have
// colours of their own.
Rgb depthColour(std::uint32_t depth, std::uint32_t nearest, std::uint32_t farthest) {
  if (depth == 0)
    return kDepthZero;
  if (depth == raster::kDepthMax)
    return kDepthOne;
  const double span = std::max(1.0, static_cast<double>(farthest) - static_cast<double>(nearest));
  const double nearness = 1.0 - (static_cast<double>(depth) - static_cast<double>(nearest)) / span;
  const auto g = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(nearness, 0.0, 1.0)));
  return {g, g, g};
}

// The depth a step clears to inside its rectangle.
double clearDepthOf(PairStep step) {
  return step == PairStep::LoadAmin || step == PairStep::ContactFar ? 1.0 : 0.0;
}

bool contains(const PixelRect& r, int x, int y) {
  return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
}

// The silhouettes' colour for a coverage value (bit 0: A, bit 1: B).
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

// A picture's file name without ".png": the section number, two digits, then `name`.
std::string fileStem(int sectionNumber, std::string_view name) {
  std::ostringstream s;
  s << std::setw(2) << std::setfill('0') << sectionNumber << '-' << name;
  return s.str();
}

// The whole-frame picture, then the close-up where there is one.
template <class F>
std::vector<Picture> wholeAndCloseUp(const Painter& whole, const std::optional<Painter>& zoom,
                                     F picture) {
  std::vector<Picture> pictures;
  pictures.push_back(picture(whole));
  if (zoom)
    pictures.push_back(picture(*zoom));
  return pictures;
}

}  // namespace

ImageRect Painter::toImage(const PixelRect& r) const {
  return {(r.x0 - region_.x0) * scale_, (region_.y1 - r.y1) * scale_, (r.x1 - region_.x0) * scale_,
          (region_.y1 - r.y0) * scale_};
}

void Painter::outline(RgbImage& image, const PixelRect& r, Rgb colour) const {
  if (!r.empty())
    outlineRect(image, toImage(r), colour, std::clamp(scale_ / 4, 1, 3));
}

void Painter::hatchOutside(RgbImage& image, const PixelRect& active) const {
  const ImageRect a = toImage(active);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const bool inside = !active.empty() && x >= a.x0 && x < a.x1 && y >= a.y0 && y < a.y1;
      if (!inside && (x + y) % 6 == 0)
        image.set(x, y, kHatch);
    }
}

PictureWriter::PictureWriter(std::filesystem::path dir, const PairSetup& setup,
                             const core::PairResult& result,
                             const raster::PixelBuffer<std::uint8_t>& coverage,
                             std::vector<KeptPicture>* kept)
    : dir_(std::move(dir)),
      kept_(kept),
      setup_(setup),
      result_(result),
      coverage_(coverage),
      frame_{0, 0, setup.frame.width, setup.frame.height},
      view_(viewRegion(result.mor, frame_)),
      painter_(view_, kept ? 1 : 512),
      overview_(frame_, kept ? 1 : 160),
      zoom_(kept ? std::nullopt : zoomPainter()) {}

// The MOR with a margin when that is at most half the frame (the rest of the frame is never
// drawn in, so showing it would only shrink what matters), else the whole frame.
PixelRect PictureWriter::viewRegion(const PixelRect& mor, const PixelRect& frame) {
  const PixelRect crop = morWithMargin(mor, frame);
  if (crop.empty() || 2 * crop.area() > frame.area())
    return frame;
  return crop;
}

std::vector<Picture> PictureWriter::silhouettes(int section) {
  std::vector<Picture> pictures;
  const auto colourAt = [&](int x, int y) { return coverageColour(coverage_.at(x, y)); };
  if (view_ != frame_) {
    // The whole frame, small, with the part the other pictures show framed.
    RgbImage overview = overview_.paint(colourAt);
    overview_.outline(overview, view_, kViewOutline);
    Picture o = makePicture(overview_, fileStem(section, "frame"), "overview", overview);
    o.caption =
        "The whole frame, small: the other pictures show only the part in the white "
        "frame, the MOR and a margin (nothing outside the MOR is ever drawn).";
    o.legend = {{kViewOutline, "the part shown in the other pictures", -1}};
    pictures.push_back(std::move(o));
  }
  RgbImage image = painter_.paint(colourAt);
  painter_.outline(image, mor(), kMorOutline);
  if (zoom_)
    painter_.outline(image, zoom_->region(), kZoomOutline);
  std::array<long long, 4> counts{};
  for (std::uint8_t c : coverage_.data)
    ++counts[c & 3u];
  Picture p = makePicture(painter_, fileStem(section, "silhouettes"), "silhouettes", image);
  p.caption = "Coverage of A and B; cyan: the MOR (pixel counts over the whole frame).";
  p.legend = {{kColourA, "A only (" + escapeHtml(setup_.nameA) + ")", counts[1]},
              {kColourB, "B only (" + escapeHtml(setup_.nameB) + ")", counts[2]},
              {kColourBoth, "both A and B", counts[3]},
              {kEmpty, "neither", counts[0]},
              {kMorOutline, "MOR outline", -1}};
  if (zoom_)
    p.legend.push_back({kZoomOutline, "the close-up shown beside later pictures", -1});
  pictures.push_back(std::move(p));
  return pictures;
}

std::vector<Picture> PictureWriter::depth(const StepSnapshot& snap, int section) {
  return wholeAndCloseUp(painter_, zoom_,
                         [&](const Painter& p) { return depthPicture(p, snap, section); });
}

std::vector<Picture> PictureWriter::stencil(const StepSnapshot& snap, int section) {
  return wholeAndCloseUp(painter_, zoom_,
                         [&](const Painter& p) { return stencilPicture(p, snap, section); });
}

std::vector<Picture> PictureWriter::changes(const StepSnapshot& snap,
                                            const raster::PixelBuffer<std::uint8_t>& before,
                                            int section) {
  const PixelRect active = activeRect(snap.step);
  // The transitions, most pixels first.
  std::map<std::pair<int, int>, long long> counts;
  for (int y = active.y0; y < active.y1; ++y)
    for (int x = active.x0; x < active.x1; ++x)
      if (before.at(x, y) != snap.stencil.at(x, y))
        ++counts[{before.at(x, y), snap.stencil.at(x, y)}];
  if (counts.empty())
    return {};
  std::vector<std::pair<std::pair<int, int>, long long>> order(counts.begin(), counts.end());
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& l, const auto& r) { return l.second > r.second; });
  std::map<std::pair<int, int>, Rgb> colour;
  for (std::size_t i = 0; i < order.size(); ++i)
    colour[order[i].first] = i < kChangePalette.size() ? kChangePalette[i] : kUnexpected;
  const Painter& painter = zoom_ ? *zoom_ : painter_;
  const RgbImage image = bufferImage(painter, active, [&](int x, int y) {
    const int from = before.at(x, y), to = snap.stencil.at(x, y);
    if (from == to)
      return dimmed(stencilColour(static_cast<std::uint8_t>(to)), 0.3);
    return colour.at({from, to});
  });
  const bool zoom = isZoom(painter);
  Picture p = makePicture(painter,
                          fileStem(section, std::string(core::toString(snap.step)) +
                                                (zoom ? "-changes-zoom" : "-changes")),
                          "changes", image);
  p.caption =
      "The stencil bits this step changed: one colour per change (old value &rarr; new "
      "value), unchanged pixels dimmed.";
  for (const auto& [change, n] : order) {
    std::ostringstream label;
    label << "<code>" << change.first << " &rarr; " << change.second << "</code> (";
    for (int bit = 3; bit >= 0; --bit)
      label << ((change.first >> bit) & 1);
    label << " &rarr; ";
    for (int bit = 3; bit >= 0; --bit)
      label << ((change.second >> bit) & 1);
    label << "): " << stencilMeaning(static_cast<std::uint8_t>(change.second), snap.step);
    p.legend.push_back({colour.at(change), label.str(), n});
  }
  p.legend.push_back({dimmed(kStencilPalette[1], 0.3), "dimmed: unchanged by this step", -1});
  std::vector<Picture> pictures;
  pictures.push_back(std::move(p));
  return pictures;
}

std::vector<Picture> PictureWriter::cases(int section) {
  return wholeAndCloseUp(painter_, zoom_,
                         [&](const Painter& p) { return casePicture(p, section); });
}

std::vector<Picture> PictureWriter::contact(int section) {
  return wholeAndCloseUp(painter_, zoom_,
                         [&](const Painter& p) { return contactPicture(p, section); });
}

// A close-up of where both blocks cover the frame (the only place where they can touch)
// when that is a small part of the frame: the pixels' bounding rectangle with a margin,
// magnified at least twice as much as the whole-frame pictures.
std::optional<Painter> PictureWriter::zoomPainter() const {
  if (result_.mor.empty())
    return std::nullopt;
  PixelRect c{frame_.x1, frame_.y1, frame_.x0, frame_.y0};
  for (int y = 0; y < frame_.y1; ++y)
    for (int x = 0; x < frame_.x1; ++x)
      if ((coverage_.at(x, y) & 3u) == 3u)
        c = {std::min(c.x0, x), std::min(c.y0, y), std::max(c.x1, x + 1), std::max(c.y1, y + 1)};
  if (c.empty())
    return std::nullopt;
  const int margin = std::max(2, std::max(c.width(), c.height()) / 4);
  const PixelRect region =
      PixelRect{c.x0 - margin, c.y0 - margin, c.x1 + margin, c.y1 + margin}.intersect(frame_);
  Painter zoom(region, 384);
  if (2 * region.width() > view_.width() && 2 * region.height() > view_.height())
    return std::nullopt;
  if (zoom.scale() < 2 * painter_.scale())
    return std::nullopt;
  return zoom;
}

Picture PictureWriter::makePicture(const Painter& painter, const std::string& stem,
                                   std::string kind, const RgbImage& image) {
  Picture p;
  p.file = stem + ".png";
  if (kept_)
    kept_->push_back({p.file, image});
  else
    writePng(dir_ / p.file, image);
  p.kind = std::move(kind);
  p.zoom = isZoom(painter);
  p.region = painter.region();
  p.scale = painter.scale();
  p.width = image.width();
  p.height = image.height();
  return p;
}

// The rectangle a step draws in (its scissor).
PixelRect PictureWriter::activeRect(PairStep step) const {
  return step == PairStep::ContactNear || step == PairStep::ContactFar ? result_.contactRect
                                                                       : result_.mor;
}

// colourAt inside `active`, dimmed outside it, hatched outside it, the MOR (and `active`
// if it differs) outlined.
template <class F>
RgbImage PictureWriter::bufferImage(const Painter& painter, const PixelRect& active,
                                    F colourAt) const {
  RgbImage image = painter.paint([&](int x, int y) {
    const Rgb c = colourAt(x, y);
    return contains(active, x, y) ? c : dimmed(c, kOutsideBrightness);
  });
  painter.hatchOutside(image, active);
  painter.outline(image, mor(), kMorOutline);
  if (active != mor())
    painter.outline(image, active, kContactOutline);
  if (zoom_ && !isZoom(painter))
    painter.outline(image, zoom_->region(), kZoomOutline);
  return image;
}

Picture PictureWriter::depthPicture(const Painter& painter, const StepSnapshot& snap, int number) {
  const PixelRect active = activeRect(snap.step);
  const bool zoom = isZoom(painter);
  // The grey levels stretch over the depths inside the step's rectangle (leaving out the
  // clear values 0 and 1, which have colours of their own), so small differences show.
  std::uint32_t nearest = 0, farthest = raster::kDepthMax;
  {
    std::uint32_t lo = raster::kDepthMax, hi = 0;
    const PixelRect shown = active.intersect(painter.region());
    for (int y = shown.y0; y < shown.y1; ++y)
      for (int x = shown.x0; x < shown.x1; ++x) {
        const std::uint32_t d = snap.depth.at(x, y);
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
  // The contact passes measure the overlap only where the blocks interfere; elsewhere in
  // their rectangle the depth they leave means nothing and is masked.
  const bool contactStep = snap.step == PairStep::ContactNear || snap.step == PairStep::ContactFar;
  const RgbImage image = bufferImage(painter, active, [&](int x, int y) {
    if (contactStep && contains(active, x, y) && !core::isInterfering(caseAt(x, y)))
      return kNotInterfering;
    return depthColour(snap.depth.at(x, y), nearest, farthest);
  });
  Picture p = makePicture(
      painter,
      fileStem(number, std::string(core::toString(snap.step)) + (zoom ? "-depth-zoom" : "-depth")),
      "depth", image);
  p.caption = zoom ? "Close-up of where both blocks are." : "Depth buffer after this step.";
  p.caption +=
      " Grey levels are stretched over the depths drawn in the step's rectangle (near "
      "bright, far dark), not over the whole range 0-1.";
  p.depthClear = clearDepthOf(snap.step);
  if (contactStep)
    p.legend.push_back({kNotInterfering,
                        "in the rectangle but not interfering: masked, the depth here is no "
                        "part of the contact region",
                        -1});
  const double scale = 1.0 / static_cast<double>(raster::kDepthMax);
  p.depthNear = nearest * scale;
  p.depthFar = farthest * scale;
  p.depthLegend = true;
  return p;
}

Picture PictureWriter::stencilPicture(const Painter& painter, const StepSnapshot& snap,
                                      int number) {
  const PixelRect active = activeRect(snap.step);
  const RgbImage image = bufferImage(
      painter, active, [&](int x, int y) { return stencilColour(snap.stencil.at(x, y)); });
  const bool zoom = isZoom(painter);
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
      ++counts[snap.stencil.at(x, y)];
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

int PictureWriter::caseAt(int x, int y) const {
  const PixelRect& m = mor();
  if (!contains(m, x, y))
    return -1;
  return result_.caseMap.at(x, y);
}

Picture PictureWriter::casePicture(const Painter& painter, int number) {
  RgbImage image = painter.paint([&](int x, int y) {
    const int c = caseAt(x, y);
    if (c < 0)
      return kNotExamined;
    return c < core::kCaseCount ? kCasePalette[static_cast<std::size_t>(c)] : kUnexpected;
  });
  painter.hatchOutside(image, mor());
  painter.outline(image, mor(), kMorOutline);
  const bool zoom = isZoom(painter);
  if (zoom)
    painter.outline(image, result_.contactRect, kContactOutline);
  Picture p = makePicture(painter, fileStem(number, zoom ? "cases-zoom" : "cases"), "cases", image);
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

Picture PictureWriter::contactPicture(const Painter& painter, int number) {
  RgbImage image = painter.paint([&](int x, int y) {
    if (core::isInterfering(caseAt(x, y)))
      return kInterfering;
    return dimmed(coverageColour(coverage_.at(x, y)), 0.4);
  });
  painter.outline(image, mor(), kMorOutline);
  painter.outline(image, result_.contactRect, kContactOutline);
  const bool zoom = isZoom(painter);
  Picture p =
      makePicture(painter, fileStem(number, zoom ? "contact-zoom" : "contact"), "contact", image);
  p.caption =
      zoom ? "Close-up of the contact region." : "Interfering pixels over the dimmed silhouettes.";
  p.legend = {{kInterfering, "interfering pixel (cases 3-6)", result_.contact.pixels},
              {dimmed(kColourA, 0.4), "A", -1},
              {dimmed(kColourB, 0.4), "B", -1},
              {dimmed(kColourBoth, 0.4), "A and B, not interfering", -1},
              {kContactOutline, "bounding rectangle of the interfering pixels", -1},
              {kMorOutline, "MOR", -1}};
  return p;
}

}  // namespace recode::explain
