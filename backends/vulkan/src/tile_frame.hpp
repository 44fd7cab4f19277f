#pragma once
// The vulkan-compute device's frame: everything the devices of the 64-bit context record between
// two submissions, kept on the host as a job list and run, just before the submission, as a fixed
// sequence of at most nine dispatches whatever it holds (docs/backends.md, "A frame is one job
// list"), and on a driver with a loop limit the sort's and raster's further rounds, each an
// indirect dispatch that runs only when a job of the round before stopped at its budget
// (tile_frame_budgets.hpp):
//
//   boxes    posed blocks' world boxes (one workgroup a block)
//   vertex   every posed draw's window vertices (one invocation a vertex)
//   set-up   every triangle of every draw (one invocation a triangle)
//   binning  each triangle counted into the jobs it may cover a centre of, the counts' prefix
//            sum, each triangle listed in those jobs, each job's list sorted: command order
//   raster   every job at once: an 8x8 block of one epoch, its commands in order on its pixels
//   resolve  each pixel's final value from the last epoch that touched it
//
// An epoch is a run of one framebuffer's commands that depends on nothing recorded before it:
// it starts with a depth clear and a stencil clear (all bits) of one rectangle, and every later
// command of it lies inside that rectangle; a framebuffer's commands before its first such epoch
// (or that reach outside their epoch's rectangle) form an epoch that starts from the framebuffer
// as the last submission left it. So a frame's pair tests, each of which clears its MOR first,
// are epochs of their own and run side by side, however many share a framebuffer.
//
// Reads (read-backs, the summaries' copies and kept depths) are commands too: the raster stage
// writes them into a read arena at their place in the command order, and a copy takes them to
// their destination after the frame. Not thread-safe on its own: every call is made under the
// recorder's lock (CommandRecorder::hold), which the hook runs under too.

#include <vulkan/vulkan_core.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "recode/raster/render_state_device.hpp"
#include "tile_frame_layout.hpp"
#include "tile_frame_records.hpp"
#include "vulkan_context.hpp"

namespace recode::backends::detail {

class CommandRecorder;
class TilePipelines;

// What the stages made of one draw, copied back for tests (VulkanComputeDevice::DrawStages):
// its set-up triangles, its epoch's grid and each job's list, in frame numbering.
struct TileDrawCapture {
  std::vector<TileSetUpTriangle> triangles;
  std::int32_t gridOrigin[2] = {0, 0};
  std::uint32_t gridWidth = 0;
  std::uint32_t gridHeight = 0;
  std::uint32_t firstTriangle = 0;
  std::vector<std::vector<std::uint32_t>> jobLists;  // frame triangle indices, in list order
  std::vector<bool> overflowed;
  std::vector<float> windowVertices;  // a posed draw's: three floats a vertex
};

class TileFrame {
 public:
  TileFrame(VulkanContext& context, CommandRecorder& recorder, const TilePipelines& pipelines);
  ~TileFrame();
  TileFrame(const TileFrame&) = delete;
  TileFrame& operator=(const TileFrame&) = delete;

  // A framebuffer (a word a pixel, rows from the bottom) the frame may draw into; its id for
  // the calls below. Release it after the recording that used it has run.
  [[nodiscard]] std::uint32_t addTarget(VkBuffer framebuffer, int width, int height);
  void removeTarget(std::uint32_t target);

  // Commands, in the order they are to take effect on their target. `scissor` and `rect` lie
  // inside the target and are not empty.
  void clearDepth(std::uint32_t target, const raster::PixelRect& scissor, std::uint32_t q);
  void clearStencil(std::uint32_t target, const raster::PixelRect& scissor, std::uint8_t value,
                    std::uint8_t writeMask);
  void draw(std::uint32_t target, const raster::RenderState& state, const TileVertices& vertices,
            VkDeviceAddress indices, std::uint32_t triangles);
  // The rectangle's pixels in `form` (rows from the bottom; stencil bytes packed four a word, the
  // last word padded with zeros) copied to `destination` from `offset` after the frame.
  void read(std::uint32_t target, const raster::PixelRect& rect, TileReadForm form,
            VkBuffer destination, VkDeviceSize offset);
  // Posed blocks' world boxes (eight doubles each: min, max, the order-matters flag, 0) copied to
  // `destination` from `offset` after the box stage.
  using BoxRequest = TileBoxRequest;
  void boxes(const std::vector<BoxRequest>& blocks, VkBuffer destination, VkDeviceSize offset);
  // The last draw recorded on `target` is copied back after the frame and handed to `sink`.
  void captureLastDraw(std::uint32_t target, std::function<void(TileDrawCapture)> sink);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The frame of the 64-bit context's recorder, made on first use and never destroyed (as the
// context and the recorder).
[[nodiscard]] TileFrame& tileFrame();

}  // namespace recode::backends::detail
