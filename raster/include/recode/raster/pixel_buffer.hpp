#pragma once
// Values over a pixel rectangle: the one type for read-backs, the case map, the parity
// comparer's per-pixel state and the oracles' samples, so that no caller writes the index
// arithmetic by hand. Row-major with rows from the bottom (y = rect.y0) up, as glReadPixels
// and the device interface's read-backs return them.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "recode/raster/device.hpp"
#include "recode/raster/invariants.hpp"
#include "recode/raster/state.hpp"

namespace recode::raster {

template <class T>
struct PixelBuffer {
  PixelRect rect;
  std::vector<T> data;  // rect.area() values; see index()

  PixelBuffer() = default;
  // Every pixel of `r` set to `fill`.
  PixelBuffer(const PixelRect& r, const T& fill)
      : rect(r), data(static_cast<std::size_t>(r.area()), fill) {}
  // Takes values laid out as described above; their count must be r.area().
  PixelBuffer(const PixelRect& r, std::vector<T> values) : rect(r), data(std::move(values)) {
    RECODE_INVARIANT(data.size() == static_cast<std::size_t>(rect.area()),
                     "a pixel buffer holds one value per pixel of its rectangle");
  }

  [[nodiscard]] bool contains(int x, int y) const {
    return x >= rect.x0 && x < rect.x1 && y >= rect.y0 && y < rect.y1;
  }
  // The position of pixel (x, y) in data.
  [[nodiscard]] std::size_t index(int x, int y) const {
    RECODE_INVARIANT(contains(x, y), "a pixel buffer is read inside its rectangle");
    return static_cast<std::size_t>(y - rect.y0) * static_cast<std::size_t>(rect.width()) +
           static_cast<std::size_t>(x - rect.x0);
  }
  [[nodiscard]] T& at(int x, int y) { return data[index(x, y)]; }
  [[nodiscard]] const T& at(int x, int y) const { return data[index(x, y)]; }

  // The values over `r` clipped to this buffer's rectangle, laid out the same way.
  // The rows are found by stepping a pointer by the stride: a pair's MOR is often a few pixels
  // wide and hundreds tall, where working out each row's index cost more than its values.
  [[nodiscard]] std::vector<T> copy(const PixelRect& r) const {
    const PixelRect c = r.intersect(rect);
    std::vector<T> out;
    if (c.empty())
      return out;
    out.reserve(static_cast<std::size_t>(c.area()));
    const auto stride = static_cast<std::size_t>(rect.width());
    const auto width = static_cast<std::size_t>(c.width());
    const T* row = data.data() + index(c.x0, c.y0);
    for (int y = c.y0; y < c.y1; ++y, row += stride)
      out.insert(out.end(), row, row + width);
    return out;
  }
  // Every pixel of `r` clipped to this buffer's rectangle set to `value`. (Stepping a pointer
  // here as copy does measured 3 % faster on a thin MOR but 5-6 % slower on BM_FillPass's
  // whole-framebuffer clears, for reasons the generated loops do not show; left as it was.)
  void fill(const PixelRect& r, const T& value) {
    const PixelRect c = r.intersect(rect);
    for (int y = c.y0; y < c.y1; ++y) {
      const auto row = data.begin() + static_cast<std::ptrdiff_t>(index(c.x0, y));
      std::fill(row, row + c.width(), value);
    }
  }

  friend bool operator==(const PixelBuffer&, const PixelBuffer&) = default;
};

// The device's read-backs with their rectangle: `rect` clamped to the framebuffer, as the
// device interface clamps it.
[[nodiscard]] inline PixelBuffer<std::uint8_t> readStencilBuffer(const DepthStencilDevice& device,
                                                                 const PixelRect& rect) {
  const PixelRect r = rect.intersect({0, 0, device.width(), device.height()});
  return {r, device.readStencil(r)};
}
[[nodiscard]] inline PixelBuffer<std::uint32_t> readDepthBuffer(const DepthStencilDevice& device,
                                                                const PixelRect& rect) {
  const PixelRect r = rect.intersect({0, 0, device.width(), device.height()});
  return {r, device.readDepth(r)};
}

}  // namespace recode::raster
