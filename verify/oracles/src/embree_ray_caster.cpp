#include "embree_ray_caster.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace recode::verify::detail {

namespace {

// Rays start this far outside the depth range [0, 1] so that no face lies behind the origin.
constexpr float kFrontOrigin = -1.0f;
constexpr float kBackOrigin = 2.0f;
// Pixels per rtcIntersect1M call (two rays each): big enough to amortise the call, small
// enough that the ray buffer (80 bytes a ray) stays in cache. The call gets all entry rays,
// then all exit rays: a stream whose neighbours share a direction ran about 1.6 times faster
// (CPU time) than one alternating entry and exit rays (docs/verification.md).
constexpr std::size_t kChunkPixels = 2048;

void onEmbreeError(void* user, RTCError code, const char* message) {
  auto* last = static_cast<std::string*>(user);
  *last = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
          (message ? message : "(no message)");
}

// Scene and geometry handles released on every path out.
struct SceneHandle {
  RTCScene scene = nullptr;
  ~SceneHandle() {
    if (scene)
      rtcReleaseScene(scene);
  }
};

// The device's own vertices: snapped x and y, float depth.
void copyBlock(const WindowBlock& block, float* vertices, std::uint32_t* indices) {
  for (std::size_t i = 0; i < block.x.size(); ++i) {
    vertices[3 * i] = block.x[i];
    vertices[3 * i + 1] = block.y[i];
    vertices[3 * i + 2] = block.zf[i];
  }
  for (std::size_t t = 0; t < block.triangles.size(); ++t)
    std::memcpy(indices + 3 * t, block.triangles[t].data(), 3 * sizeof(std::uint32_t));
}

// One chunk's rays, all entry rays first and then all exit rays (kChunkPixels says why): for
// each pixel a ray through its centre from in front of depth 0 toward +z, and one from behind
// depth 1 toward -z.
void aimRays(std::span<const PixelXY> pixels, std::vector<RTCRayHit>& rays) {
  const std::size_t count = pixels.size();
  rays.resize(2 * count);
  for (std::size_t k = 0; k < count; ++k) {
    const PixelXY& p = pixels[k];
    const float cx = static_cast<float>(p.x) + 0.5f, cy = static_cast<float>(p.y) + 0.5f;
    for (std::size_t side = 0; side < 2; ++side) {
      RTCRayHit& r = rays[side * count + k];
      r.ray.org_x = cx;
      r.ray.org_y = cy;
      r.ray.org_z = side == 0 ? kFrontOrigin : kBackOrigin;
      r.ray.dir_x = 0.0f;
      r.ray.dir_y = 0.0f;
      r.ray.dir_z = side == 0 ? 1.0f : -1.0f;
      r.ray.tnear = 0.0f;
      r.ray.tfar = std::numeric_limits<float>::infinity();
      r.ray.time = 0.0f;
      r.ray.mask = 0xFFFFFFFFu;
      r.ray.id = 0;
      r.ray.flags = 0;
      r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      r.hit.primID = RTC_INVALID_GEOMETRY_ID;
      r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
  }
}

// The triangle each of a chunk's `count` pixels was entered and left by, laid out as aimRays
// laid the rays out; a ray that met nothing leaves its kNoHit in place.
void recordHits(const std::vector<RTCRayHit>& rays, std::size_t count, std::int32_t* entry,
                std::int32_t* exit) {
  for (std::size_t k = 0; k < count; ++k) {
    const RTCHit& front = rays[k].hit;
    const RTCHit& back = rays[count + k].hit;
    if (front.geomID != RTC_INVALID_GEOMETRY_ID)
      entry[k] = static_cast<std::int32_t>(front.primID);
    if (back.geomID != RTC_INVALID_GEOMETRY_ID)
      exit[k] = static_cast<std::int32_t>(back.primID);
  }
}

}  // namespace

RayCaster::RayCaster() {
  device_ = rtcNewDevice(nullptr);
  if (!device_) {
    throw std::runtime_error("Embree: rtcNewDevice failed (error " +
                             std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  }
  rtcSetDeviceErrorFunction(device_, onEmbreeError, &lastError_);
}

RayCaster::~RayCaster() {
  if (device_)
    rtcReleaseDevice(device_);
}

void RayCaster::throwIfFailed(const char* what) {
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE || !lastError_.empty()) {
    std::string message = std::string("Embree: ") + what + " failed: " + lastError_;
    lastError_.clear();
    throw std::runtime_error(message);
  }
}

void RayCaster::buildScene(RTCScene scene, const WindowBlock& block) {
  // Robust mode makes the triangle test watertight, so a ray through a shared edge is not lost.
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  throwIfFailed("rtcNewGeometry");
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), block.x.size()));
  auto* indices = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(std::uint32_t), block.triangles.size()));
  if (!vertices || !indices) {
    rtcReleaseGeometry(geometry);
    throwIfFailed("rtcSetNewGeometryBuffer");
    throw std::runtime_error("Embree: rtcSetNewGeometryBuffer returned no buffer");
  }
  copyBlock(block, vertices, indices);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  throwIfFailed("building the scene");
}

long long RayCaster::cast(const WindowBlock& block, std::span<const PixelXY> pixels,
                          std::vector<std::int32_t>& entry, std::vector<std::int32_t>& exit) {
  entry.assign(pixels.size(), kNoHit);
  exit.assign(pixels.size(), kNoHit);
  if (pixels.empty() || block.triangles.empty())
    return 0;

  SceneHandle handle;
  handle.scene = rtcNewScene(device_);
  throwIfFailed("rtcNewScene");
  buildScene(handle.scene, block);

  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  // Neighbouring rays are parallel and a fraction of a pixel apart: as coherent as rays get.
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;

  long long rays = 0;
  for (std::size_t first = 0; first < pixels.size(); first += kChunkPixels) {
    const std::size_t count = std::min(kChunkPixels, pixels.size() - first);
    aimRays(pixels.subspan(first, count), rays_);
    rtcIntersect1M(handle.scene, &context, rays_.data(), static_cast<unsigned int>(2 * count),
                   sizeof(RTCRayHit));
    rays += static_cast<long long>(2 * count);
    recordHits(rays_, count, entry.data() + first, exit.data() + first);
  }
  throwIfFailed("rtcIntersect1M");
  return rays;
}

}  // namespace recode::verify::detail
