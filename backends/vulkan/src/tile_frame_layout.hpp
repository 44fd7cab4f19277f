#pragma once
// The frame's records as the host writes them: the mirror of tile_common.glsl's structs (std430,
// every field a 32-bit word, addresses as two words, low first). Field names and order are the
// shader's; the sizes are checked here, and every field's offset against the stages' SPIR-V by
// tests/backends/vulkan/tile_frame_layout_test.cpp.

#include <cstddef>
#include <cstdint>

#include "recode/raster/state.hpp"

namespace recode::backends::detail {

// Doubles of a vertex job's transform (tile_vertex.comp) and of a box job's pose (tile_box.comp).
inline constexpr std::uint32_t kTileTransformDoubles = 23;
inline constexpr std::uint32_t kTilePoseDoubles = 12;

// Strides of the work buffer's regions, in bytes: a window vertex (three floats), a box job's
// box (eight doubles: min, max, the order-matters flag, 0), a job's 64 pixel words (JobFinal,
// Carry), a raster job's and a sort job's progress record (tile_raster.comp's uvec4,
// tile_sort.comp's uvec2) and a round's indirect dispatch (VkDispatchIndirectCommand).
inline constexpr std::uint64_t kTileWindowVertexBytes = 12;
inline constexpr std::uint64_t kTileBoxBytes = 64;
inline constexpr std::uint64_t kTileJobPixelBytes = 256;
inline constexpr std::uint64_t kTileRasterProgressBytes = 16;
inline constexpr std::uint64_t kTileSortProgressBytes = 8;
inline constexpr std::uint64_t kTileRoundArgsBytes = 12;

// Where a region the stages bind may start: the largest minStorageBufferOffsetAlignment the
// specification allows, so no device needs asking.
inline constexpr std::uint64_t kTileBindAlignment = 256;
inline constexpr std::uint64_t tileAligned(std::uint64_t bytes) {
  return (bytes + kTileBindAlignment - 1) / kTileBindAlignment * kTileBindAlignment;
}

// A rectangle as the records hold it: x0, y0, x1, y1.
inline void putRect(const raster::PixelRect& r, std::int32_t (&out)[4]) {
  out[0] = r.x0;
  out[1] = r.y0;
  out[2] = r.x1;
  out[3] = r.y1;
}
inline raster::PixelRect rectOf(const std::int32_t (&words)[4]) {
  return {words[0], words[1], words[2], words[3]};
}

// Command kinds and read forms (tile_common.glsl's kDraw..., kRead...).
enum class TileCommandKind : std::uint32_t { Draw = 0, ClearDepth = 1, ClearStencil = 2, Read = 3 };
enum class TileReadForm : std::uint32_t { DepthWords = 0, StencilBytes = 1, DepthFloats = 2 };
// The frame's counters (tile_common.glsl's kCounter...): what the stages did, which the host
// compares with what it asked for.
enum TileCounter : std::uint32_t {
  kTileCounterRasterColumns = 0,  // job columns the raster stage ran to their end
  kTileCounterSortedJobs = 1,     // jobs whose lists the sort stage left in order
  kTileCounterScatterShort = 2,   // scatter invocations whose loop ended early
  kTileCounterResolveShort = 3,   // resolve invocations whose loop ended early
};
inline constexpr std::uint32_t kTileCounters = 4;
// Epoch flags.
inline constexpr std::uint32_t kTileEpochLoads = 1;
inline constexpr std::uint32_t kTileEpochStores = 2;

// A set-up triangle (tile_common.glsl's SetUpTriangle, which the set-up stage writes and the
// binning and raster stages read; the host reads it back for tests). The offsets asserted below
// are std430's for the shader's fields.
struct TileSetUpTriangle {
  std::int32_t x0 = 0;  // the snapped vertices (24.8 fixed point)
  std::int32_t y0 = 0;
  std::int32_t x1 = 0;
  std::int32_t y1 = 0;
  std::int32_t x2 = 0;
  std::int32_t y2 = 0;
  std::uint32_t front = 0;                    // 1 front-facing, 0 back-facing
  std::int32_t candidates[4] = {0, 0, 0, 0};  // x0, y0, x1, y1, half-open (empty: draws nothing)
  std::uint32_t z0 = 0;                       // z0's float bits
  std::uint32_t dzdx[2] = {0, 0};             // the slopes' double bits, low word first
  std::uint32_t dzdy[2] = {0, 0};
};
static_assert(sizeof(TileSetUpTriangle) == 64);
static_assert(offsetof(TileSetUpTriangle, front) == 24);
static_assert(offsetof(TileSetUpTriangle, candidates) == 28);
static_assert(offsetof(TileSetUpTriangle, z0) == 44);
static_assert(offsetof(TileSetUpTriangle, dzdx) == 48);  // a uvec2: 8-aligned in std430
static_assert(offsetof(TileSetUpTriangle, dzdy) == 56);

struct TileAddress {
  std::uint32_t low = 0;
  std::uint32_t high = 0;
  static TileAddress of(std::uint64_t address) {
    return {static_cast<std::uint32_t>(address), static_cast<std::uint32_t>(address >> 32)};
  }
};

struct TileTarget {
  TileAddress pixels;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};
static_assert(sizeof(TileTarget) == 16);

// A draw's state packed into three words (tile_common.glsl's decoders read them back): `tests`
// the depth func (bits 0-2), depth write (3), stencil func (4-6) and cull mode (7-8); `stencil`
// the reference (bits 0-7), value mask (8-15) and write mask (16-23); `ops` the front face's
// stencil-fail, depth-fail and depth-pass ops (three bits each), then the back face's from bit 9.
inline constexpr std::uint32_t kTileDepthWriteBit = 1u << 3;
inline constexpr std::uint32_t kTileStencilFuncShift = 4;
inline constexpr std::uint32_t kTileCullShift = 7;
inline constexpr std::uint32_t kTileValueMaskShift = 8;
inline constexpr std::uint32_t kTileWriteMaskShift = 16;
inline constexpr std::uint32_t kTileDepthFailShift = 3;
inline constexpr std::uint32_t kTileDepthPassShift = 6;
inline constexpr std::uint32_t kTileBackOpsShift = 9;

struct TileCommand {
  std::int32_t rect[4] = {0, 0, 0, 0};
  TileCommandKind kind = TileCommandKind::Draw;
  std::uint32_t target = 0;
  std::uint32_t tests = 0;                           // a draw's: see above
  std::uint32_t stencil = 0;                         // a draw's: see above
  std::uint32_t ops = 0;                             // a draw's: see above
  std::uint32_t first = 0;                           // a draw's first triangle in the frame
  std::uint32_t count = 0;                           // a draw's triangles
  std::uint32_t value = 0;                           // a clear's value: q, or the stencil byte
  std::uint32_t clearMask = 0;                       // a stencil clear's write mask
  TileReadForm readForm = TileReadForm::DepthWords;  // a read's form
  std::uint32_t arenaWord = 0;                       // a read's first word in the read arena
  std::uint32_t pad = 0;
};
static_assert(sizeof(TileCommand) == 64);

struct TileEpoch {
  std::int32_t footprint[4] = {0, 0, 0, 0};
  std::int32_t gridOrigin[2] = {0, 0};
  std::uint32_t gridWidth = 0;
  std::uint32_t gridHeight = 0;
  std::uint32_t target = 0;
  std::uint32_t firstJob = 0;
  std::uint32_t firstCommand = 0;
  std::uint32_t commandEnd = 0;
  std::uint32_t flags = 0;
  std::uint32_t firstFinal = 0;
  std::uint32_t pad[2] = {0, 0};
};
static_assert(sizeof(TileEpoch) == 64);

struct TileDrawSource {
  TileAddress vertices;
  TileAddress indices;
  std::uint32_t firstTriangle = 0;
  std::uint32_t triangleCount = 0;
  std::uint32_t command = 0;
  std::uint32_t epoch = 0;
};
static_assert(sizeof(TileDrawSource) == 32);

struct TileVertexJob {
  TileAddress local;
  TileAddress windows;
  std::uint32_t firstVertex = 0;
  std::uint32_t vertexCount = 0;
  std::uint32_t transform = 0;
  std::uint32_t pad = 0;
};
static_assert(sizeof(TileVertexJob) == 32);

struct TileResolveRange {
  std::int32_t rect[4] = {0, 0, 0, 0};
  std::uint32_t target = 0;
  std::uint32_t epoch = 0;
  std::uint32_t firstLater = 0;
  std::uint32_t laterCount = 0;
  std::uint32_t firstPixel = 0;
  std::uint32_t pad[3] = {0, 0, 0};
};
static_assert(sizeof(TileResolveRange) == 48);

struct TileBoxJob {
  TileAddress local;
  std::uint32_t vertexCount = 0;
  std::uint32_t pose = 0;
};
static_assert(sizeof(TileBoxJob) == 16);

}  // namespace recode::backends::detail
