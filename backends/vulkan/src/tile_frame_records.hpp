#pragma once
// The compute device's frame on the host (tile_frame.hpp): what the devices recorded since the
// last submission, the records the stages read, made from it once a submission (each
// framebuffer's commands cut into epochs, tile_frame_epochs.hpp, and numbered in command order),
// and where each region of the frame's work buffer lies. It calls no Vulkan function (it names
// Vulkan's handle and size types only), so that it is tested on the CPU
// (tests/backends/vulkan/tile_frame_records_test.cpp).

#include <vulkan/vulkan_core.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "recode/raster/state.hpp"
#include "tile_frame_budgets.hpp"
#include "tile_frame_epochs.hpp"
#include "tile_frame_layout.hpp"

namespace recode::backends::detail {

// Where a draw's window vertices come from: a buffer of them (by address), or a posed mesh whose
// object-space vertices the vertex stage takes to the window with `transform` (23 doubles:
// tile_vertex.comp). Draws of one content key (not 0) in one frame share one vertex job.
struct TileVertices {
  VkDeviceAddress window = 0;  // three floats a vertex; 0 for a posed mesh
  VkDeviceAddress local = 0;   // three doubles a vertex
  std::uint32_t vertexCount = 0;
  std::array<double, kTileTransformDoubles> transform{};
  std::uint64_t contentKey = 0;
};

// A posed block whose world box the box stage makes.
struct TileBoxRequest {
  VkDeviceAddress local = 0;
  std::uint32_t vertexCount = 0;
  std::array<double, kTilePoseDoubles> pose{};
};

// What the devices recorded since the last submission.
struct TileRecorded {
  struct Target {
    bool live = false;
    VkDeviceAddress pixels = 0;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
  };
  // A command as recorded: what the shaders read, and what the host still needs.
  struct Pending {
    TileCommand command;
    raster::PixelRect rect;
    // A draw's sources: window vertices by address, or a vertex job's (vertexJob >= 0).
    VkDeviceAddress vertices = 0;
    int vertexJob = -1;
    VkDeviceAddress indices = 0;
    // A read's destination.
    VkBuffer destination = VK_NULL_HANDLE;
    VkDeviceSize destinationOffset = 0;
  };
  struct BoxBatch {
    std::vector<TileBoxRequest> blocks;
    VkBuffer destination = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
  };
  std::vector<Target> targets;
  std::vector<std::vector<Pending>> commands;  // by target
  std::vector<TileVertices> vertexJobs;
  std::vector<BoxBatch> boxBatches;
  // The draw to copy back after the frame: its target and its index in the target's commands.
  std::optional<std::pair<std::uint32_t, std::size_t>> captured;

  [[nodiscard]] bool empty() const;
};

// The frame's records as the stages read them, target by target, each target's commands cut
// into epochs, numbered in command order.
struct TileFrameRecords {
  std::vector<TileTarget> targets;
  std::vector<TileCommand> commands;
  std::vector<TileEpoch> epochs;
  std::vector<TileDrawSource> draws;
  std::vector<TileResolveRange> resolveRanges;
  std::vector<std::uint32_t> laterEpochs;  // the ranges' later epochs
  std::vector<TileVertexJob> vertexJobs;   // placed in the work buffer by placeVertexJobs
  std::vector<double> transforms;          // kTileTransformDoubles a vertex job
  std::vector<TileBoxJob> boxJobs;
  std::vector<double> poses;  // kTilePoseDoubles a box job
  // A read's words in the read arena and where they go after the frame.
  struct ReadCopy {
    VkBuffer destination = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    std::uint32_t firstWord = 0;
    std::uint32_t words = 0;
  };
  std::vector<ReadCopy> readCopies;
  std::uint32_t triangles = 0;
  std::uint32_t jobs = 0;
  std::uint32_t finals = 0;  // jobs of epochs that leave their pixels to the resolve stage
  std::uint32_t arenaWords = 0;
  std::uint32_t resolvePixels = 0;
  // Entries the jobs' lists hold in all: for each draw, 4 a triangle, 2 a job of its epoch and
  // 4,096. A job whose list would pass the end draws each of its draws from every triangle
  // instead (tile_raster.comp), so this bounds memory, not results.
  std::uint64_t listCapacity = 0;
  // What bounds the stages' loops (tile_frame_budgets.hpp): the rounds the raster and sort
  // stages may need for the longest job, and the most blocks a triangle's candidates may reach.
  std::uint32_t rasterRounds = 1;
  std::uint32_t sortRounds = 1;
  std::uint64_t largestGrid = 0;
  std::uint32_t windowVertices = 0;        // the vertex jobs' vertices, in all
  std::vector<std::uint32_t> windowFirst;  // vertex job k's first window vertex
  std::vector<int> drawVertexJob;          // each draw's vertex job, or -1 (window vertices given)
  // The captured draw's record and its epoch's.
  std::optional<std::pair<std::uint32_t, std::uint32_t>> captured;
};

// Jobs whose pixels a frame may keep for the resolve stage (64 words each: 64 MiB in all).
inline constexpr std::uint64_t kTileMostFinalJobs = std::uint64_t{1} << 18;
// Entries the jobs' lists may hold in all (2^27: 512 MiB).
inline constexpr std::uint64_t kTileMostListEntries = std::uint64_t{1} << 27;

// The records of everything `recorded` holds, within `budgets` (the vertex jobs are left to
// placeVertexJobs, once the work buffer's address is known).
[[nodiscard]] TileFrameRecords tileFrameRecords(const TileRecorded& recorded,
                                                const TileLoopBudgets& budgets);

// `epochs` (one target's), or, when the epochs that meet another would keep more jobs than the
// frame has left of kTileMostFinalJobs (`finals` kept so far), one epoch of all the commands that
// starts from the framebuffer and stores its own pixels: the same results, its blocks' commands
// run one after another instead of side by side, and no pixel kept for the resolve stage. The
// same when more epochs meet another than a resolve invocation may compare (`mostLater` later
// epochs: a CPU driver's loop limit, tile_frame_budgets.hpp).
[[nodiscard]] std::vector<EpochSpan> withinFinalBudget(std::vector<EpochSpan> epochs,
                                                       std::uint64_t finals,
                                                       std::uint32_t mostLater);

// Where the frame's regions lie in its work buffer, each from a multiple of kTileBindAlignment,
// one after another in this order, and each at least a word (every region is bound for every
// stage, and a binding's range may not be empty).
struct TileWorkLayout {
  explicit TileWorkLayout(const TileFrameRecords& r);
  // Entries the jobs' lists hold in all (TileFrameRecords::listCapacity, at most
  // kTileMostListEntries).
  std::uint32_t entryCapacity;
  VkDeviceSize triangleBytes;  // from 0
  VkDeviceSize jobBytes;       // each of the counts, offsets and cursors
  VkDeviceSize binEntriesAt = 0;
  VkDeviceSize offsetsAt = 0;
  VkDeviceSize cursorsAt = 0;
  VkDeviceSize listsAt = 0;
  VkDeviceSize finalsAt = 0;
  VkDeviceSize windowsAt = 0;
  VkDeviceSize arenaAt = 0;
  VkDeviceSize boxesAt = 0;
  VkDeviceSize progressAt = 0;
  VkDeviceSize sortProgressAt = 0;
  VkDeviceSize countersAt = 0;
  VkDeviceSize rasterArgsAt = 0;
  VkDeviceSize sortArgsAt = 0;
  VkDeviceSize carryAt = 0;  // up to here zeroed each frame
  VkDeviceSize bytes = 0;
};

// The posed draws' vertex jobs, their window vertices made by the vertex stage into the work
// buffer (at `workAddress`), and the draws that take them pointed there.
void placeVertexJobs(TileFrameRecords& r, const std::vector<TileVertices>& vertexJobs,
                     const TileWorkLayout& layout, VkDeviceAddress workAddress);

}  // namespace recode::backends::detail
