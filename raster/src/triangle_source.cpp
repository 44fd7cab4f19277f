// Process-unique keys for TriangleSource::contentKey (triangle_source.hpp).
#include "recode/raster/triangle_source.hpp"

#include <atomic>

namespace recode::raster {

std::uint64_t newTriangleSourceKey() {
  // 64 bits do not wrap in any process's life; sources may be made on any thread.
  static std::atomic<std::uint64_t> last{0};
  return last.fetch_add(1, std::memory_order_relaxed) + 1;
}

}  // namespace recode::raster
