#include "explain/png_image.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "output/atomic_file.hpp"

namespace recode::explain {

Rgb dimmed(Rgb colour, double factor) {
  const auto scale = [factor](std::uint8_t c) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(factor, 0.0, 1.0) * c));
  };
  return {scale(colour.r), scale(colour.g), scale(colour.b)};
}

std::string hexColour(Rgb colour) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", colour.r, colour.g, colour.b);
  return text;
}

RgbImage::RgbImage(int width, int height, Rgb fill) : width_(width), height_(height) {
  if (width < 1 || height < 1)
    throw std::invalid_argument("RgbImage: size " + std::to_string(width) + "x" +
                                std::to_string(height) + " is not at least 1x1");
  data_.resize(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t i = 0; i < data_.size(); i += 3) {
    data_[i] = fill.r;
    data_[i + 1] = fill.g;
    data_[i + 2] = fill.b;
  }
}

Rgb RgbImage::at(int x, int y) const {
  const std::size_t i = offset(x, y);
  return {data_[i], data_[i + 1], data_[i + 2]};
}

void RgbImage::set(int x, int y, Rgb colour) {
  const std::size_t i = offset(x, y);
  data_[i] = colour.r;
  data_[i + 1] = colour.g;
  data_[i + 2] = colour.b;
}

int upscaleFactor(int width, int height, int minWidth, int maxSide) {
  if (width < 1 || height < 1)
    throw std::invalid_argument("upscaleFactor: empty picture");
  int factor = std::max(1, (minWidth + width - 1) / width);
  const int side = std::max(width, height);
  while (factor > 1 && static_cast<long long>(side) * factor > maxSide)
    --factor;
  return factor;
}

RgbImage upscaled(const RgbImage& image, int factor) {
  if (factor < 1)
    throw std::invalid_argument("upscaled: factor " + std::to_string(factor) + " below 1");
  if (factor == 1)
    return image;
  RgbImage out(image.width() * factor, image.height() * factor);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x)
      out.set(x, y, image.at(x / factor, y / factor));
  return out;
}

namespace {

void fillClipped(RgbImage& image, int x0, int y0, int x1, int y1, Rgb colour) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width());
  y1 = std::min(y1, image.height());
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      image.set(x, y, colour);
}

}  // namespace

void outlineRect(RgbImage& image, const ImageRect& rect, Rgb colour, int thickness) {
  if (rect.x1 <= rect.x0 || rect.y1 <= rect.y0 || thickness < 1)
    return;
  const int t = thickness;
  // Each side's band: outside the rectangle unless that side touches the image border.
  const int left = rect.x0 <= 0 ? rect.x0 : rect.x0 - t;
  const int right = rect.x1 >= image.width() ? rect.x1 - t : rect.x1;
  const int top = rect.y0 <= 0 ? rect.y0 : rect.y0 - t;
  const int bottom = rect.y1 >= image.height() ? rect.y1 - t : rect.y1;
  const int outerX0 = std::min(left, rect.x0), outerX1 = std::max(right + t, rect.x1);
  const int outerY0 = std::min(top, rect.y0), outerY1 = std::max(bottom + t, rect.y1);
  fillClipped(image, outerX0, top, outerX1, top + t, colour);
  fillClipped(image, outerX0, bottom, outerX1, bottom + t, colour);
  fillClipped(image, left, outerY0, left + t, outerY1, colour);
  fillClipped(image, right, outerY0, right + t, outerY1, colour);
}

void writePng(const std::filesystem::path& path, const RgbImage& image) {
  if (image.width() < 1 || image.height() < 1)
    throw std::runtime_error(path.string() + ": cannot write an empty picture");
  // Encoded in memory, then written whole (atomic_file.hpp).
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &png, image.width(), image.height(), 3, image.bytes().data(),
                             3 * image.width()) == 0)
    throw std::runtime_error(path.string() + ": cannot encode the PNG picture");
  output::writeFileAtomically(path, png);
}

}  // namespace recode::explain
