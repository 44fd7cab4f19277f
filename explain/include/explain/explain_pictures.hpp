#pragma once
// Turns the recorded buffers into PNG pictures (whole frame and close-ups) with their legends.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "explain/explain_recorder.hpp"
#include "explain/png_image.hpp"
#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/state.hpp"

namespace recode::explain {

struct LegendEntry {
  Rgb colour;
  std::string label;      // HTML
  long long pixels = -1;  // < 0: not shown
};

struct Picture {
  std::string file;
  std::string kind;          // silhouettes, depth, stencil, cases, contact
  bool zoom = false;         // a close-up of part of the frame
  raster::PixelRect region;  // the part of the frame shown
  int scale = 1;             // picture pixels per framebuffer pixel, each way
  int width = 0;             // picture size
  int height = 0;
  std::string caption;  // HTML
  std::vector<LegendEntry> legend;
  bool depthLegend = false;
  double depthNear = 0.0;  // the depths shown white and black
  double depthFar = 1.0;
  double depthClear = 0.0;  // the value the step cleared depth to (0 or 1)
};

// Paints a region of the frame (the whole frame, or a zoom on part of it), each framebuffer
// pixel as a scale x scale block, the frame's top row at the top.
class Painter {
 public:
  // The smallest whole magnification that makes the picture at least `minWidth` wide
  // (1024 at most on its longer side, where that leaves a magnification of at least 1).
  Painter(const raster::PixelRect& region, int minWidth)
      : region_(region), scale_(upscaleFactor(region.width(), region.height(), minWidth, 1024)) {}
  [[nodiscard]] const raster::PixelRect& region() const { return region_; }
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

  [[nodiscard]] ImageRect toImage(const raster::PixelRect& r) const;
  void outline(RgbImage& image, const raster::PixelRect& r, Rgb colour) const;
  // Diagonal hatching over everything outside `active`: the step did not touch it.
  void hatchOutside(RgbImage& image, const raster::PixelRect& active) const;

 private:
  raster::PixelRect region_;
  int scale_;
};

// A picture kept in memory instead of written as a PNG file: the interactive page (wasm/)
// draws it on a canvas, enlarged by the browser.
struct KeptPicture {
  std::string file;  // the name the page refers to it by (as Picture::file)
  RgbImage image;
};

// Writes the pictures of one run into `dir` and describes each for the page. Each function
// writes the whole-frame picture and then, where there is one, its close-up of where both
// blocks are; `section` numbers the files. setup, result and coverage must outlive it.
// With `kept`, the pictures go there instead, one picture pixel per framebuffer pixel and
// without close-ups (the page enlarges them on screen, so a close-up would repeat them).
class PictureWriter {
 public:
  PictureWriter(std::filesystem::path dir, const PairSetup& setup, const core::PairResult& result,
                const raster::PixelBuffer<std::uint8_t>& coverage,
                std::vector<KeptPicture>* kept = nullptr);

  // The whole frame, and picture pixels per framebuffer pixel in the whole-frame pictures.
  [[nodiscard]] const raster::PixelRect& frame() const { return frame_; }
  // The part of the frame the pictures show: the MOR with a margin, or the whole frame.
  [[nodiscard]] const raster::PixelRect& view() const { return view_; }
  [[nodiscard]] int scale() const { return painter_.scale(); }

  // The whole frame, small, with the part shown framed (when that is not the whole frame),
  // then the coverage of A and B over the part shown, with the MOR.
  [[nodiscard]] std::vector<Picture> silhouettes(int section);
  [[nodiscard]] std::vector<Picture> depth(const StepSnapshot& snap, int section);
  [[nodiscard]] std::vector<Picture> stencil(const StepSnapshot& snap, int section);
  // The pixels whose stencil this step changed, one colour per transition (the close-up
  // where there is one, else the whole frame); nothing when the step changed no pixel.
  [[nodiscard]] std::vector<Picture> changes(const StepSnapshot& snap,
                                             const raster::PixelBuffer<std::uint8_t>& before,
                                             int section);
  // The case of every MOR pixel.
  [[nodiscard]] std::vector<Picture> cases(int section);
  // The interfering pixels over the dimmed silhouettes.
  [[nodiscard]] std::vector<Picture> contact(int section);

 private:
  [[nodiscard]] const raster::PixelRect& mor() const { return result_.mor; }
  [[nodiscard]] static raster::PixelRect viewRegion(const raster::PixelRect& mor,
                                                    const raster::PixelRect& frame);
  [[nodiscard]] std::optional<Painter> zoomPainter() const;
  [[nodiscard]] bool isZoom(const Painter& painter) const { return zoom_ && &painter == &*zoom_; }
  Picture makePicture(const Painter& painter, const std::string& stem, std::string kind,
                      const RgbImage& image);
  [[nodiscard]] raster::PixelRect activeRect(core::PairStep step) const;
  template <class F>
  [[nodiscard]] RgbImage bufferImage(const Painter& painter, const raster::PixelRect& active,
                                     F colourAt) const;
  Picture depthPicture(const Painter& painter, const StepSnapshot& snap, int number);
  Picture stencilPicture(const Painter& painter, const StepSnapshot& snap, int number);
  [[nodiscard]] int caseAt(int x, int y) const;
  Picture casePicture(const Painter& painter, int number);
  Picture contactPicture(const Painter& painter, int number);

  std::filesystem::path dir_;
  std::vector<KeptPicture>* kept_;
  const PairSetup& setup_;
  const core::PairResult& result_;
  const raster::PixelBuffer<std::uint8_t>& coverage_;
  raster::PixelRect frame_;
  raster::PixelRect view_;
  Painter painter_;   // the part shown
  Painter overview_;  // the whole frame, small
  std::optional<Painter> zoom_;
};

}  // namespace recode::explain
