#pragma once
// RGB pictures for `recode explain`: an 8-bit RGB image (rows from the top, as image files
// and viewers have them), pixel-exact nearest-neighbour upscaling, rectangle outlines, and
// PNG output through stb_image_write.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace recode::explain {

struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;

  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// `colour` scaled towards black by `factor` in [0, 1] (1 keeps it).
[[nodiscard]] Rgb dimmed(Rgb colour, double factor);

// "#rrggbb", for HTML legends.
[[nodiscard]] std::string hexColour(Rgb colour);

class RgbImage {
 public:
  RgbImage() = default;
  // Throws std::invalid_argument unless width and height are at least 1.
  RgbImage(int width, int height, Rgb fill = {});

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  // (x, y) with x to the right and y down from the top row; no bounds check.
  [[nodiscard]] Rgb at(int x, int y) const;
  void set(int x, int y, Rgb colour);
  // Rows from the top, three bytes (R, G, B) per pixel.
  [[nodiscard]] std::span<const std::uint8_t> bytes() const { return data_; }

 private:
  [[nodiscard]] std::size_t offset(int x, int y) const {
    return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                static_cast<std::size_t>(x));
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> data_;
};

// The smallest integer factor that makes the picture at least `minWidth` pixels wide,
// reduced (not below 1) while the larger side would exceed `maxSide`.
[[nodiscard]] int upscaleFactor(int width, int height, int minWidth = 256, int maxSide = 1024);

// Every pixel becomes a factor x factor block of the same colour (no smoothing).
[[nodiscard]] RgbImage upscaled(const RgbImage& image, int factor);

// A half-open rectangle [x0, x1) x [y0, y1) in image pixels (y down).
struct ImageRect {
  int x0 = 0;
  int y0 = 0;
  int x1 = 0;
  int y1 = 0;
};

// Draws a frame `thickness` pixels wide around `rect`, just outside it so the pixels inside
// keep their colours; a side that lies on the image's border is drawn just inside instead
// (so a rectangle covering the whole image still shows). Clipped to the image; nothing for
// an empty rectangle.
void outlineRect(RgbImage& image, const ImageRect& rect, Rgb colour, int thickness);

// Writes `image` as an 8-bit RGB PNG. Throws std::runtime_error naming the file on failure.
void writePng(const std::filesystem::path& path, const RgbImage& image);

}  // namespace recode::explain
