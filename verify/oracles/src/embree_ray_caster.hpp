#pragma once
// Ray casts along the depth axis through pixel centres with Embree's stream API: which
// triangle of a block a ray from the viewer meets first (the entry) and which a ray from
// behind meets first (the exit). Internal to the Embree oracle; the only file that talks to
// Embree.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include "embree_window_block.hpp"

namespace recode::verify::detail {

struct PixelXY {
  int x = 0;
  int y = 0;
};

inline constexpr std::int32_t kNoHit = -1;

class RayCaster {
 public:
  RayCaster();  // throws std::runtime_error if Embree cannot start
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // For every pixel, the index of the triangle hit first by a ray from in front of depth 0
  // toward depth 1 (entry) and by one from behind depth 1 toward depth 0 (exit), or kNoHit.
  // Returns the number of rays cast.
  long long cast(const WindowBlock& block, std::span<const PixelXY> pixels,
                 std::vector<std::int32_t>& entry, std::vector<std::int32_t>& exit);

 private:
  void throwIfFailed(const char* what);
  // Fills an empty scene with the block's triangles and commits it; throws on Embree errors.
  void buildScene(RTCScene scene, const WindowBlock& block);

  RTCDevice device_ = nullptr;
  std::string lastError_;
  std::vector<RTCRayHit> rays_;
};

}  // namespace recode::verify::detail
