// The raster stages' invariants (recode/raster/invariants.hpp) fire when broken and stay quiet
// on valid input. Built against recode_raster_checked, the same sources with the checks on in
// every build type. A broken invariant aborts, so each case runs in a child process and the
// parent reads what it printed.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/pipeline.hpp"
#include "recode/raster/pixel_buffer.hpp"
#include "recode/raster/traversal.hpp"
#include "recode/raster/triangle_setup.hpp"

using namespace recode::raster;

namespace {

struct ChildOutcome {
  bool aborted = false;
  int exitCode = -1;
  std::string stderrText;
};

// Runs `body` in a child process with its stderr captured.
ChildOutcome runInChild(const std::function<void()>& body) {
  int fds[2];
  REQUIRE(pipe(fds) == 0);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    close(fds[0]);
    dup2(fds[1], STDERR_FILENO);
    body();
    _exit(0);
  }
  close(fds[1]);
  ChildOutcome out;
  char buffer[512];
  ssize_t n;
  while ((n = read(fds[0], buffer, sizeof buffer)) > 0)
    out.stderrText.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  out.aborted = WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT;
  if (WIFEXITED(status))
    out.exitCode = WEXITSTATUS(status);
  return out;
}

void requireAbortWith(const std::function<void()>& body, const std::string& what) {
  const ChildOutcome out = runInChild(body);
  INFO("child stderr: " << out.stderrText);
  CHECK(out.aborted);
  CHECK(out.stderrText.find("recode: invariant failed: " + what) != std::string::npos);
}

class CountingSink final : public TriangleSink {
 public:
  void beginTriangle(const TriangleSetup&, const std::array<FixedVertex, 3>&) override {}
  void coveredBlock(int, int, std::uint64_t) override { ++blocks; }
  int blocks = 0;
};

TriangleSetup someTriangle() {
  return *setupTriangle({0, 0, 0.5f}, {16 * kSubpixelOne, 0, 0.5f}, {0, 16 * kSubpixelOne, 0.5f});
}

}  // namespace

TEST_CASE("invariants: a clip rectangle outside the framebuffer range aborts traversal") {
  requireAbortWith(
      [] {
        CountingSink sink;
        traverseTriangle(someTriangle(), {-8, 0, 16, 16}, sink);
      },
      "the clip rectangle lies inside the largest framebuffer");
}

TEST_CASE("invariants: a vertex beyond the fixed-point range aborts setup") {
  requireAbortWith(
      [] {
        const std::int64_t far = (std::int64_t{1} << 23) + 1;
        (void)setupTriangle({far, 0, 0.0f}, {0, 256, 0.0f}, {256, 0, 0.0f});
      },
      "snapped vertices lie within the fixed-point range");
}

TEST_CASE("invariants: an index out of range aborts the pipeline") {
  requireAbortWith(
      [] {
        const std::vector<WindowVertex> v = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
        const std::vector<std::uint32_t> i = {0, 1, 7};
        CountingSink sink;
        drawTriangles(initialRenderState(8, 8), v, i, sink);
      },
      "a draw's indices are in range");
}

TEST_CASE("invariants: an unclamped scissor aborts the pipeline") {
  requireAbortWith(
      [] {
        RenderState state = initialRenderState(8, 8);
        state.scissor = {4, 0, 2, 8};  // x1 < x0: never produced by setScissor
        const std::vector<WindowVertex> v = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
        const std::vector<std::uint32_t> i = {0, 1, 2};
        CountingSink sink;
        drawTriangles(state, v, i, sink);
      },
      "the scissor is clamped to the framebuffer");
}

TEST_CASE("invariants: pixel buffers are read inside their rectangle and sized to it") {
  requireAbortWith(
      [] {
        const PixelBuffer<std::uint8_t> b({2, 2, 4, 4}, std::uint8_t{0});
        (void)b.at(4, 2);
      },
      "a pixel buffer is read inside its rectangle");
  requireAbortWith(
      [] {
        (void)PixelBuffer<std::uint8_t>({0, 0, 3, 3}, std::vector<std::uint8_t>(8));
      },
      "a pixel buffer holds one value per pixel of its rectangle");
}

TEST_CASE("invariants: none fires on many valid draws, guard band and scissors included") {
  const ChildOutcome out = runInChild([] {
    CpuDevice device(200, 120);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coordinate(-600.0f, 800.0f);
    std::uniform_real_distribution<float> depth(0.0f, 1.0f);
    std::uniform_int_distribution<int> edge(-50, 250);
    std::vector<WindowVertex> vertices;
    std::vector<std::uint32_t> indices;
    for (std::uint32_t k = 0; k < 3000; ++k) {
      vertices.push_back(
          {snapToSubpixel(coordinate(rng)), snapToSubpixel(coordinate(rng)), depth(rng)});
      indices.push_back(k);
    }
    for (int pass = 0; pass < 20; ++pass) {
      device.setScissor({edge(rng), edge(rng), edge(rng), edge(rng)});
      device.setCullMode(static_cast<CullMode>(pass % 3));
      device.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Incr, StencilOp::Invert});
      device.clearDepth(pass % 2 == 0 ? 1.0 : 0.0);
      device.drawTriangles(vertices, indices);
      (void)readStencilBuffer(device, {edge(rng), edge(rng), edge(rng), edge(rng)});
    }
    if (device.counters().fragments == 0)
      _exit(3);  // the draws must have reached the fragment stage
  });
  INFO("child stderr: " << out.stderrText);
  CHECK_FALSE(out.aborted);
  CHECK(out.exitCode == 0);
}
