// The fragment stage over a block (block_fragments.hpp): the SIMD version against the
// one-pixel-at-a-time version, byte for byte on both buffers, on every Highway target this
// build runs here, over random states (every compare function and stencil op, random masks
// and references), random stored values, random depth planes anywhere in the guard band whose
// depths lie around and beyond [0, 1] (NaN, infinities, exact 0 and 1, the rounding midpoints),
// and coverage masks with partial rows, full rows and pairs of rows (the vectors take the rows
// of at least a few pixels, masked where partial). The
// one-pixel version is applyFragment() itself, which the reference-model tests hold to the
// contract.

#include <sys/mman.h>
#include <unistd.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "recode/raster/block_coverage.hpp"
#include "recode/raster/block_fragments.hpp"
#include "recode/raster/fixed_point.hpp"

namespace {

using namespace recode::raster;

constexpr int kStride = 11;  // a buffer wider than the block, so rows are not contiguous

double randomDepth(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> unit(-0.2, 1.2);
  std::uniform_int_distribution<std::uint32_t> level(0, kDepthMax);
  switch (kind(rng)) {
    case 0:
      return std::numeric_limits<double>::quiet_NaN();
    case 1:
      return kind(rng) < 5 ? std::numeric_limits<double>::infinity()
                           : -std::numeric_limits<double>::infinity();
    case 2:
      return kind(rng) < 5 ? 0.0 : 1.0;
    case 3:  // a rounding midpoint: half a depth step above a level
      return (level(rng) + 0.5) / static_cast<double>(kDepthMax);
    default:
      return unit(rng);
  }
}

// A plane's slope per sub-pixel step: flat (so the depths are exactly the special values above),
// small enough to cross a few depth steps per pixel, steep enough to clamp, or not finite.
double randomSlope(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> small(-1e-7, 1e-7), steep(-1e-2, 1e-2);
  switch (kind(rng)) {
    case 0:
    case 1:
    case 2:
      return 0.0;
    case 3:
      return steep(rng);
    case 4:
      return kind(rng) < 5 ? std::numeric_limits<double>::infinity()
                           : std::numeric_limits<double>::quiet_NaN();
    default:
      return small(rng);
  }
}

StencilOp randomOp(std::mt19937_64& rng) {
  return static_cast<StencilOp>(std::uniform_int_distribution<int>(0, 7)(rng));
}

}  // namespace

TEST_CASE(
    "block fragments: SIMD rows and the compiled one-pixel kernels give the general one-pixel "
    "version's bytes on every target",
    "[raster][simd]") {
  std::vector<std::string> targets;
  forEachSimdTarget([&](const char* name) {
    targets.emplace_back(name);
    std::mt19937_64 rng(1124);
    std::uniform_int_distribution<int> byte(0, 255), func(0, 7), coin(0, 1);
    std::uniform_int_distribution<std::uint32_t> storedDepth(0, kDepthMax);
    // Vertex positions anywhere in the guard band, blocks anywhere in the largest framebuffer.
    std::uniform_int_distribution<std::int64_t> position(-(std::int64_t{32768} << 8),
                                                         std::int64_t{32768} << 8);
    std::uniform_int_distribution<int> pixel(0, kMaxFramebufferSize / 8 - 1);
    long long fullRows = 0, fullRowPairs = 0, denseBlocksWithPartialRows = 0, sparseBlocks = 0;
    std::vector<int> compiledKernelTrials(detail::kCompiledFragmentKernels);
    std::uniform_int_distribution<int> compiledOrNot(-detail::kCompiledFragmentKernels,
                                                     detail::kCompiledFragmentKernels - 1);
    for (int trial = 0; trial < 6000; ++trial) {
      RenderState state = initialRenderState(16, 16);
      state.depthFunc = static_cast<CompareFunc>(func(rng));
      state.stencilFunc = static_cast<CompareFunc>(func(rng));
      StencilOps ops{randomOp(rng), randomOp(rng), randomOp(rng)};
      // Half the trials take the functions and ops of a kernel compiled for them.
      if (const int k = compiledOrNot(rng); k >= 0) {
        const detail::FragmentFuncs& funcs = detail::kCompiledFragmentFuncs[k];
        state.stencilFunc = funcs.stencilFunc;
        state.depthFunc = funcs.depthFunc;
        ops = funcs.ops;
      }
      const int kernel = detail::compiledFragmentKernel(state, ops);
      if (kernel >= 0)
        ++compiledKernelTrials[static_cast<std::size_t>(kernel)];
      state.depthWrite = coin(rng) == 1;
      state.stencilRef = static_cast<std::uint8_t>(byte(rng));
      state.stencilValueMask = static_cast<std::uint8_t>(coin(rng) ? 0xFF : byte(rng));
      state.stencilWriteMask = static_cast<std::uint8_t>(coin(rng) ? 0xFF : byte(rng));

      DepthPlane plane;
      plane.x0 = position(rng);
      plane.y0 = position(rng);
      plane.z0 = randomDepth(rng);
      plane.dzdx = randomSlope(rng);
      plane.dzdy = randomSlope(rng);
      BlockFragments block;
      block.state = &state;
      block.ops = &ops;
      block.plane = &plane;
      block.kernel = kernel;
      block.x = pixel(rng) * 8;
      block.y = pixel(rng) * 8;
      std::vector<std::uint32_t> depth(8 * kStride);
      std::vector<std::uint8_t> stencil(8 * kStride);
      for (std::size_t i = 0; i < depth.size(); ++i) {
        // Some stored depths equal to the incoming one, so Equal and the ties are reached.
        const int c = static_cast<int>(i % kStride % 8), r = static_cast<int>(i / kStride);
        depth[i] = coin(rng) ? storedDepth(rng) : quantizeDepth(block.depthAt(c, r));
        stencil[i] = static_cast<std::uint8_t>(coin(rng) ? byte(rng) : state.stencilRef);
      }
      std::uint64_t mask = 0;
      if (trial % 4 == 0) {
        // A sparse block, a small triangle's: the one-pixel kernels, not the vectors.
        for (int i = 0; i < 64; ++i)
          mask |= std::uint64_t{byte(rng) < 32} << i;
      } else {
        for (int r = 0; r < 8; ++r) {
          const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
          const std::uint64_t bits = kind == 0 ? 0 : kind == 1 ? 0xFF : byte(rng);
          fullRows += bits == 0xFF;
          fullRowPairs += r > 0 && bits == 0xFF && ((mask >> (8 * r - 8)) & 0xFF) == 0xFF;
          mask |= bits << (8 * r);
        }
      }
      sparseBlocks += __builtin_popcountll(mask) < detail::kMinSimdBlockPixels;
      // A block dense enough for the vectors whose partial rows go through them masked.
      bool partialRow = false;
      for (int r = 0; r < 8; ++r) {
        const int pixels = __builtin_popcountll((mask >> (8 * r)) & 0xFF);
        partialRow = partialRow || (pixels >= 3 && pixels < 8);
      }
      denseBlocksWithPartialRows +=
          partialRow && __builtin_popcountll(mask) >= detail::kMinSimdBlockPixels;

      std::vector<std::uint32_t> depthSimd = depth;
      std::vector<std::uint8_t> stencilSimd = stencil;
      block.stride = kStride;
      block.wholeColumns = true;  // the rows are 11 wide
      block.depth = depth.data();
      block.stencil = stencil.data();
      const int appliedScalar = applyBlockFragmentsScalar(block, mask);
      block.depth = depthSimd.data();
      block.stencil = stencilSimd.data();
      const int appliedSimd = applyBlockFragments(block, mask);
      INFO("target " << name << ", trial " << trial);
      REQUIRE(appliedSimd == appliedScalar);
      REQUIRE(appliedScalar == __builtin_popcountll(mask));
      REQUIRE(depthSimd == depth);
      REQUIRE(stencilSimd == stencil);
    }
    // The SIMD rows were exercised, single and in pairs, not only the scalar fallback.
    CHECK(fullRows > 4000);
    CHECK(fullRowPairs > 1000);
    CHECK(denseBlocksWithPartialRows > 1000);
    CHECK(sparseBlocks > 1000);
    // Each compiled kernel, not only the general one.
    for (const int trials : compiledKernelTrials)
      CHECK(trials > 400);
  });
  CHECK(!targets.empty());
}

namespace {

// `bytes` bytes that end where an inaccessible page begins: a read or write past them faults.
class BufferBeforeGuardPage {
 public:
  explicit BufferBeforeGuardPage(std::size_t bytes)
      : page_(static_cast<std::size_t>(sysconf(_SC_PAGESIZE))) {
    base_ = mmap(nullptr, 2 * page_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    REQUIRE(base_ != MAP_FAILED);
    REQUIRE(mprotect(static_cast<char*>(base_) + page_, page_, PROT_NONE) == 0);
    data_ = static_cast<char*>(base_) + page_ - bytes;
  }
  ~BufferBeforeGuardPage() { munmap(base_, 2 * page_); }
  BufferBeforeGuardPage(const BufferBeforeGuardPage&) = delete;
  BufferBeforeGuardPage& operator=(const BufferBeforeGuardPage&) = delete;
  template <class T>
  T* as() const {
    return reinterpret_cast<T*>(data_);
  }

 private:
  std::size_t page_;
  void* base_ = nullptr;
  char* data_ = nullptr;
};

}  // namespace

TEST_CASE("block fragments: a block at the right edge of a buffer touches only the buffer",
          "[raster][simd]") {
  // A buffer 5 pixels wide and 8 rows high ending at a guard page, and a block at its left edge
  // whose 3 last columns lie beyond each row: on the last row, beyond the buffer. Partial rows
  // of 5 pixels are dense enough for the vectors, which must not take them here (a vector
  // would read all 8 columns and fault).
  constexpr int kWidth = 5;
  std::vector<std::string> targets;
  forEachSimdTarget([&](const char* name) {
    targets.emplace_back(name);
    RenderState state = initialRenderState(kWidth, 8);
    state.depthFunc = CompareFunc::LEqual;
    state.stencilFunc = CompareFunc::Always;
    const StencilOps ops{StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap};
    DepthPlane plane;
    plane.z0 = 0.25;
    plane.dzdx = 1e-4;
    plane.dzdy = 2e-4;
    BufferBeforeGuardPage depthSimd(8 * kWidth * sizeof(std::uint32_t));
    BufferBeforeGuardPage stencilSimd(8 * kWidth);
    std::vector<std::uint32_t> depth(8 * kWidth, kDepthMax);
    std::vector<std::uint8_t> stencil(8 * kWidth, 0);
    std::copy(depth.begin(), depth.end(), depthSimd.as<std::uint32_t>());
    std::copy(stencil.begin(), stencil.end(), stencilSimd.as<std::uint8_t>());
    BlockFragments block;
    block.state = &state;
    block.ops = &ops;
    block.plane = &plane;
    block.stride = kWidth;
    block.wholeColumns = false;
    const std::uint64_t mask = 0x1F1F1F1F1F1F1F1FULL;  // columns 0-4 of every row
    block.depth = depth.data();
    block.stencil = stencil.data();
    applyBlockFragmentsScalar(block, mask);
    block.depth = depthSimd.as<std::uint32_t>();
    block.stencil = stencilSimd.as<std::uint8_t>();
    INFO("target " << name);
    CHECK(applyBlockFragments(block, mask) == 40);
    CHECK(std::equal(depth.begin(), depth.end(), depthSimd.as<std::uint32_t>()));
    CHECK(std::equal(stencil.begin(), stencil.end(), stencilSimd.as<std::uint8_t>()));
    CHECK(stencil[0] == 1);  // the fragments were applied
  });
  CHECK(!targets.empty());
}
