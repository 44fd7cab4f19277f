// Pixel histories (conformance/pixel_history.hpp): computed from the stream alone, they must end
// where the reference device ends on every golden vector, chain from event to event, and tell
// the contract's story: section 4's worked example, quantisation ties, culling, the scissor.

#include "recode/conformance/pixel_history.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"

using namespace recode;
using conformance::describe;
using conformance::PixelHistory;
using conformance::pixelHistory;
using conformance::TriangleOutcome;

namespace {

const std::filesystem::path kGolden = std::filesystem::path(RECODE_DATA_DIR) / "golden";

std::vector<std::filesystem::path> goldenFiles() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kGolden))
    if (entry.path().extension() == ".json")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The pixels of a frame to check: all of a small frame; of a larger one, every pixel whose
// expected value differs from the initial one (at most 200 of them, evenly spread) and about
// 100 more evenly spread over the frame.
std::vector<std::pair<int, int>> pixelsToCheck(const raster::GoldenVector& g) {
  const int w = g.stream.width;
  const int h = g.stream.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::set<std::size_t> chosen;
  if (n <= 4096) {
    for (std::size_t i = 0; i < n; ++i)
      chosen.insert(i);
  } else {
    std::vector<std::size_t> changed;
    for (std::size_t i = 0; i < n; ++i)
      if (g.depth[i] != 16777215u || g.stencil[i] != 0)
        changed.push_back(i);
    const std::size_t step = changed.size() / 200 + 1;
    for (std::size_t k = 0; k < changed.size(); k += step)
      chosen.insert(changed[k]);
    const std::size_t spread = n / 100 + 1;
    for (std::size_t i = 0; i < n; i += spread)
      chosen.insert(i);
    chosen.insert(n - 1);
  }
  std::vector<std::pair<int, int>> out;
  for (const std::size_t i : chosen)
    out.emplace_back(static_cast<int>(i % static_cast<std::size_t>(w)),
                     static_cast<int>(i / static_cast<std::size_t>(w)));
  return out;
}

// The before/after values of one event, whichever kind.
struct Values {
  std::uint32_t depthBefore, depthAfter;
  std::uint8_t stencilBefore, stencilAfter;
};
Values valuesOf(const conformance::HistoryEvent& e) {
  if (e.clear)
    return {e.clear->depthBefore, e.clear->depthAfter, e.clear->stencilBefore,
            e.clear->stencilAfter};
  return {e.triangle->depthBefore, e.triangle->depthAfter, e.triangle->stencilBefore,
          e.triangle->stencilAfter};
}

// Empty when the history chains from the initial values to its final ones, else the problem.
std::string chainProblem(const PixelHistory& h) {
  std::uint32_t d = 16777215u;
  std::uint8_t s = 0;
  for (std::size_t k = 0; k < h.events.size(); ++k) {
    const conformance::HistoryEvent& e = h.events[k];
    if (e.clear.has_value() == e.triangle.has_value())
      return "event " + std::to_string(k) + " is not exactly one of a clear and a triangle";
    const Values v = valuesOf(e);
    if (v.depthBefore != d || v.stencilBefore != s)
      return "event " + std::to_string(k) + " does not start where the previous one ended";
    if (e.triangle && e.triangle->outcome != TriangleOutcome::Fragment &&
        (v.depthAfter != v.depthBefore || v.stencilAfter != v.stencilBefore))
      return "event " + std::to_string(k) + " changes the pixel without a fragment";
    d = v.depthAfter;
    s = v.stencilAfter;
  }
  if (d != h.finalDepth || s != h.finalStencil)
    return "the last event does not end at the final values";
  return "";
}

raster::WindowVertex vertex(float x, float y, float z) {
  return {x, y, z};
}

raster::cmd::Draw drawOf(std::vector<raster::WindowVertex> vertices,
                         std::vector<std::uint32_t> indices) {
  raster::cmd::Draw d;
  d.vertices = std::move(vertices);
  d.indices = std::move(indices);
  return d;
}

// An incrementing stencil so that every fragment shows.
raster::cmd::StencilOpsCmd incrementOnPass() {
  raster::cmd::StencilOpsCmd ops;
  ops.face = raster::Face::Both;
  ops.ops.depthPass = raster::StencilOp::Incr;
  return ops;
}

std::vector<const conformance::TriangleEvent*> trianglesOf(const PixelHistory& h) {
  std::vector<const conformance::TriangleEvent*> out;
  for (const auto& e : h.events)
    if (e.triangle)
      out.push_back(&*e.triangle);
  return out;
}

}  // namespace

TEST_CASE("pixel histories end where the reference device ends, on every golden vector",
          "[pixel_history]") {
  int files = 0;
  long long pixels = 0;
  long long events = 0;
  long long fragments = 0;
  std::vector<std::string> failures;
  for (const auto& path : goldenFiles()) {
    ++files;
    const raster::GoldenVector g = raster::readGolden(path);
    raster::CpuDevice dev(g.stream.width, g.stream.height);
    raster::replay(g.stream.commands, dev);
    const auto depth = dev.depthBuffer();
    const auto stencil = dev.stencilBuffer();
    for (const auto& [x, y] : pixelsToCheck(g)) {
      ++pixels;
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(g.stream.width) +
                            static_cast<std::size_t>(x);
      const PixelHistory h = pixelHistory(g.stream, x, y);
      events += static_cast<long long>(h.events.size());
      for (const auto* t : trianglesOf(h))
        fragments += t->outcome == TriangleOutcome::Fragment ? 1 : 0;
      std::string problem;
      if (h.finalDepth != depth[i] || h.finalStencil != stencil[i])
        problem = "final depth " + std::to_string(h.finalDepth) + " stencil " +
                  std::to_string(h.finalStencil) + ", the device has " + std::to_string(depth[i]) +
                  " and " + std::to_string(stencil[i]);
      else
        problem = chainProblem(h);
      if (problem.empty() && describe(h).rfind("pixel (", 0) != 0)
        problem = "describe() does not start with the pixel";
      if (!problem.empty() && failures.size() < 10)
        failures.push_back(path.filename().string() + " (" + std::to_string(x) + ", " +
                           std::to_string(y) + "): " + problem + "\n" + describe(h));
    }
  }
  INFO(files << " vectors, " << pixels << " pixels, " << events << " events, " << fragments
             << " fragments");
  CHECK(files >= 307);
  CHECK(fragments > 0);
  for (const std::string& f : failures)  // the first 10, each with its history
    FAIL_CHECK(f);
  CHECK(failures.empty());
}

TEST_CASE("pixel history: section 4's worked example on fill_square", "[pixel_history]") {
  // fill_square draws T1 = (2.5,2.5) (6.5,2.5) (6.5,6.5) as triangle 0 and T2 = (2.5,2.5)
  // (6.5,6.5) (2.5,6.5) as triangle 1, depth ALWAYS without writes, stencil INCR_WRAP on pass.
  const raster::GoldenVector g = raster::readGolden(kGolden / "fill_square.json");
  REQUIRE(g.stream.width == 10);
  REQUIRE(g.stream.height == 10);

  SECTION("(6, 3) lies on T1's right edge: excluded by the tie rule, not drawn") {
    const PixelHistory h = pixelHistory(g.stream, 6, 3);
    const auto ts = trianglesOf(h);
    REQUIRE(ts.size() == 1);
    CHECK(ts[0]->triangle == 0);
    CHECK(ts[0]->draw == 0);
    CHECK(ts[0]->command == 4);
    CHECK(ts[0]->front);
    CHECK(ts[0]->outcome == TriangleOutcome::ExcludedByTie);
    // The right edge (1664,640) -> (1664,1664) is T1's v1 -> v2, its second edge.
    CHECK(ts[0]->edges[1].from == 1);
    CHECK(ts[0]->edges[1].to == 2);
    CHECK(ts[0]->edges[1].dx == 0);
    CHECK(ts[0]->edges[1].dy == 1024);
    CHECK(ts[0]->edges[1].value == 0);
    CHECK_FALSE(ts[0]->edges[1].inclusive);
    CHECK(ts[0]->edges[0].value > 0);
    CHECK(ts[0]->edges[2].value > 0);
    CHECK(h.finalStencil == 0);
    const std::string text = describe(h);
    INFO(text);
    CHECK(text.find("command 4, draw 0, triangle 0 (front): excluded by the tie rule") !=
          std::string::npos);
    CHECK(text.find("right edge v1 -> v2, which is not inclusive") != std::string::npos);
  }

  SECTION("(2, 2), a corner: T1 draws it, T2 has it on its exclusive diagonal") {
    const PixelHistory h = pixelHistory(g.stream, 2, 2);
    const auto ts = trianglesOf(h);
    REQUIRE(ts.size() == 2);
    CHECK(ts[0]->triangle == 0);
    CHECK(ts[0]->outcome == TriangleOutcome::Fragment);
    // E = 0 on T1's bottom and diagonal, both inclusive.
    CHECK(ts[0]->edges[0].value == 0);
    CHECK(ts[0]->edges[0].inclusive);
    CHECK(ts[0]->edges[2].value == 0);
    CHECK(ts[0]->edges[2].inclusive);
    CHECK(ts[0]->opSlot == "dppass");
    CHECK(ts[0]->op == "INCR_WRAP");
    CHECK(ts[0]->stencilBefore == 0);
    CHECK(ts[0]->stencilAfter == 1);
    CHECK(ts[0]->depthAfter == 16777215u);  // the depth write mask is off
    CHECK(ts[0]->quantisation.tie);         // z = 0.5: 8388607.5 -> 8388608
    CHECK(ts[0]->quantisation.q == 8388608u);
    CHECK(ts[1]->triangle == 1);
    CHECK(ts[1]->outcome == TriangleOutcome::ExcludedByTie);
    // T2's diagonal (640,640) -> (1664,1664) is its v0 -> v1, dy > 0: a right edge.
    CHECK(ts[1]->edges[0].from == 0);
    CHECK(ts[1]->edges[0].to == 1);
    CHECK(ts[1]->edges[0].value == 0);
    CHECK_FALSE(ts[1]->edges[0].inclusive);
    CHECK(h.finalStencil == 1);
    const std::string text = describe(h);
    INFO(text);
    CHECK(text.find("command 4, draw 0, triangle 0 (front): covered; z = 0.5 (z0 + tx = 0.5, ty = "
                    "0), z*16777215 = 8388607.5 tie -> q = 8388608 (even); stencil ALWAYS passes; "
                    "depth ALWAYS passes; dppass INCR_WRAP: stencil 0 -> 1, depth stays 16777215 "
                    "(depth write mask off)") != std::string::npos);
  }

  SECTION("(4, 4) on the diagonal: one fragment, from T1") {
    const PixelHistory h = pixelHistory(g.stream, 4, 4);
    const auto ts = trianglesOf(h);
    REQUIRE(ts.size() == 2);
    CHECK(ts[0]->triangle == 0);
    CHECK(ts[0]->outcome == TriangleOutcome::Fragment);
    CHECK(ts[1]->triangle == 1);
    CHECK(ts[1]->outcome == TriangleOutcome::ExcludedByTie);
    CHECK(h.finalStencil == 1);
  }

  SECTION("(3, 6) lies on T2's top edge: not drawn") {
    const PixelHistory h = pixelHistory(g.stream, 3, 6);
    const auto ts = trianglesOf(h);
    REQUIRE(ts.size() == 1);
    CHECK(ts[0]->triangle == 1);
    CHECK(ts[0]->outcome == TriangleOutcome::ExcludedByTie);
    CHECK(ts[0]->edges[1].dy == 0);
    CHECK(ts[0]->edges[1].dx < 0);
    CHECK_FALSE(ts[0]->edges[1].inclusive);
    CHECK(describe(h).find("top edge v1 -> v2, which is not inclusive") != std::string::npos);
  }

  SECTION("16 fragments in all, one on each pixel of [2, 5]^2") {
    int fragments = 0;
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 10; ++x) {
        int here = 0;
        const PixelHistory h = pixelHistory(g.stream, x, y);  // outlives the pointers into it
        for (const auto* t : trianglesOf(h))
          here += t->outcome == TriangleOutcome::Fragment ? 1 : 0;
        const bool inSquare = x >= 2 && x <= 5 && y >= 2 && y <= 5;
        CHECK(here == (inSquare ? 1 : 0));
        fragments += here;
      }
    CHECK(fragments == 16);
  }
}

TEST_CASE("pixel history: depth quantisation ties round half to even", "[pixel_history]") {
  SECTION("a plane at z = 0.5: 8388607.5 rounds up to the even 8388608") {
    raster::CommandStream s;
    s.width = 4;
    s.height = 4;
    s.commands.push_back(
        drawOf({vertex(-1.0f, -1.0f, 0.5f), vertex(9.0f, -1.0f, 0.5f), vertex(-1.0f, 9.0f, 0.5f)},
               {0, 1, 2}));
    const PixelHistory h = pixelHistory(s, 1, 1);
    const auto ts = trianglesOf(h);
    REQUIRE(ts.size() == 1);
    REQUIRE(ts[0]->outcome == TriangleOutcome::Fragment);
    CHECK(ts[0]->plane.z == 0.5);
    CHECK(ts[0]->quantisation.scaled == 8388607.5);
    CHECK(ts[0]->quantisation.tie);
    CHECK(ts[0]->quantisation.q == 8388608u);
    CHECK(ts[0]->depthPassed);
    CHECK(h.finalDepth == 8388608u);
  }

  SECTION("a depth clear whose d * 16777215 is a tie") {
    // 0.5 * 16777215 = 8388607.5: k odd, rounds up to 8388608.
    raster::CommandStream s;
    s.width = 2;
    s.height = 2;
    s.commands.push_back(raster::cmd::ClearDepth{0.5});
    const PixelHistory h = pixelHistory(s, 0, 0);
    REQUIRE(h.events.size() == 1);
    REQUIRE(h.events[0].clear);
    CHECK(h.events[0].clear->quantisation.tie);
    CHECK(h.events[0].clear->quantisation.q == 8388608u);
    CHECK(h.finalDepth == 8388608u);
  }

  SECTION("the kit's depth_ties vectors: ties with k even keep k, with k odd go up") {
    int evenKept = 0;
    int oddRaised = 0;
    for (const auto& path : goldenFiles()) {
      if (path.filename().string().rfind("depth_ties_", 0) != 0)
        continue;
      const raster::GoldenVector g = raster::readGolden(path);
      for (int y = 0; y < g.stream.height; ++y)
        for (int x = 0; x < g.stream.width; ++x) {
          const PixelHistory h = pixelHistory(g.stream, x, y);
          for (const auto& e : h.events) {
            const conformance::Quantisation* q = nullptr;
            if (e.triangle && e.triangle->outcome == TriangleOutcome::Fragment)
              q = &e.triangle->quantisation;
            else if (e.clear && e.clear->depth)
              q = &e.clear->quantisation;
            if (q == nullptr || !q->tie)
              continue;
            const double k = std::floor(q->scaled);
            INFO(path.filename().string() << " (" << x << ", " << y << ")");
            CHECK(q->scaled == k + 0.5);
            CHECK(q->q % 2 == 0);
            if (static_cast<double>(q->q) == k)
              ++evenKept;
            else if (static_cast<double>(q->q) == k + 1.0)
              ++oddRaised;
            else
              FAIL("a tie rounded to neither neighbour");
          }
        }
    }
    CHECK(evenKept > 0);
    CHECK(oddRaised > 0);
  }
}

TEST_CASE("pixel history: culling, the scissor, clears and the frame", "[pixel_history]") {
  // A clockwise (back-facing) and a counter-clockwise (front-facing) triangle over the frame.
  const raster::cmd::Draw ccw =
      drawOf({vertex(-1.0f, -1.0f, 0.25f), vertex(9.0f, -1.0f, 0.25f), vertex(-1.0f, 9.0f, 0.25f)},
             {0, 1, 2});
  const raster::cmd::Draw cw =
      drawOf({vertex(-1.0f, -1.0f, 0.75f), vertex(9.0f, -1.0f, 0.75f), vertex(-1.0f, 9.0f, 0.75f)},
             {0, 2, 1});

  SECTION("culled triangles") {
    raster::CommandStream s;
    s.width = 8;
    s.height = 8;
    s.commands.push_back(incrementOnPass());
    s.commands.push_back(raster::cmd::Cull{raster::CullMode::Back});
    s.commands.push_back(cw);
    s.commands.push_back(ccw);
    s.commands.push_back(raster::cmd::Cull{raster::CullMode::Front});
    s.commands.push_back(ccw);
    s.commands.push_back(cw);
    const PixelHistory h = pixelHistory(s, 2, 2);
    const auto ts = trianglesOf(h);
    REQUIRE(ts.size() == 4);
    CHECK(ts[0]->outcome == TriangleOutcome::Culled);
    CHECK_FALSE(ts[0]->front);
    CHECK(ts[0]->draw == 0);
    CHECK(ts[1]->outcome == TriangleOutcome::Fragment);
    CHECK(ts[1]->front);
    CHECK(ts[1]->draw == 1);
    CHECK(ts[2]->outcome == TriangleOutcome::Culled);
    CHECK(ts[2]->front);
    CHECK(ts[2]->command == 5);
    CHECK(ts[3]->outcome == TriangleOutcome::Fragment);  // 0.75 is not LESS than 0.25
    CHECK_FALSE(ts[3]->front);
    CHECK_FALSE(ts[3]->depthPassed);
    CHECK(ts[3]->opSlot == "dpfail");
    CHECK(h.finalStencil == 1);
    CHECK(h.finalDepth == 4194304u);  // 0.25 * 16777215 = 4194303.75
    CHECK(chainProblem(h).empty());
    const std::string text = describe(h);
    INFO(text);
    CHECK(text.find("command 2, draw 0, triangle 0 (back): culled") != std::string::npos);
    CHECK(text.find("command 5, draw 2, triangle 0 (front): culled") != std::string::npos);
    CHECK(text.find("depth LESS 12582911 < 4194304 fails") != std::string::npos);
  }

  SECTION("the scissor: clamped to the frame, excluding covering triangles and clears") {
    raster::CommandStream s;
    s.width = 8;
    s.height = 8;
    s.commands.push_back(incrementOnPass());
    s.commands.push_back(raster::cmd::Scissor{{-5, -5, 3, 3}});
    s.commands.push_back(raster::cmd::ClearStencil{7});
    s.commands.push_back(ccw);
    s.commands.push_back(raster::cmd::Scissor{{6, 6, 2, 2}});  // inverted: empty
    s.commands.push_back(raster::cmd::ClearDepth{0.0});
    s.commands.push_back(ccw);

    const PixelHistory in = pixelHistory(s, 2, 2);
    REQUIRE(in.events.size() == 4);
    REQUIRE(in.events[0].clear);
    CHECK_FALSE(in.events[0].clear->outsideScissor);
    CHECK(in.events[0].clear->stencilAfter == 7);
    REQUIRE(in.events[1].triangle);
    CHECK(in.events[1].triangle->outcome == TriangleOutcome::Fragment);
    CHECK(in.events[1].triangle->stencilAfter == 8);
    // The depth clear under the empty scissor is recorded, and leaves the pixel as it is.
    REQUIRE(in.events[2].clear);
    CHECK(in.events[2].clear->outsideScissor);
    CHECK(in.events[2].clear->depthAfter == in.events[2].clear->depthBefore);
    REQUIRE(in.events[3].triangle);
    CHECK(in.events[3].triangle->outcome == TriangleOutcome::OutsideScissor);
    CHECK(in.events[3].triangle->scissor.x0 == in.events[3].triangle->scissor.x1);
    CHECK(in.finalStencil == 8);
    CHECK(chainProblem(in).empty());

    const PixelHistory out = pixelHistory(s, 3, 2);
    const auto ts = trianglesOf(out);
    REQUIRE(out.events.size() == 4);  // neither clear reaches it: both are marked so
    for (const conformance::HistoryEvent& e : out.events) {
      if (e.clear)
        CHECK(e.clear->outsideScissor);
    }
    REQUIRE(ts.size() == 2);
    CHECK(ts[0]->outcome == TriangleOutcome::OutsideScissor);
    CHECK(ts[0]->scissor == raster::PixelRect{0, 0, 3, 3});
    CHECK(ts[1]->outcome == TriangleOutcome::OutsideScissor);
    CHECK(out.finalStencil == 0);
    CHECK(out.finalDepth == 16777215u);
    const std::string text = describe(out);
    INFO(text);
    CHECK(text.find("outside the scissor: the scissor is x in [0, 3), y in [0, 3)") !=
          std::string::npos);
    CHECK(text.find("outside the scissor: the scissor is empty") != std::string::npos);
  }

  SECTION("clears honour the write masks") {
    raster::CommandStream s;
    s.width = 2;
    s.height = 2;
    s.commands.push_back(raster::cmd::ClearStencil{0xF0});
    s.commands.push_back(raster::cmd::StencilWriteMask{0x0F});
    s.commands.push_back(raster::cmd::ClearStencil{0x3C});
    s.commands.push_back(raster::cmd::DepthWriteMask{false});
    s.commands.push_back(raster::cmd::ClearDepth{0.0});
    const PixelHistory h = pixelHistory(s, 1, 1);
    REQUIRE(h.events.size() == 3);
    CHECK(h.events[1].clear->stencilBefore == 0xF0);
    CHECK(h.events[1].clear->stencilAfter == 0xFC);
    CHECK(h.events[2].clear->skipped);
    CHECK(h.events[2].clear->quantisation.q == 0);
    CHECK(h.finalStencil == 0xFC);
    CHECK(h.finalDepth == 16777215u);
    CHECK(chainProblem(h).empty());
  }

  SECTION("pixels outside the frame are refused") {
    raster::CommandStream s;
    s.width = 8;
    s.height = 4;
    s.commands.push_back(ccw);
    CHECK_THROWS_AS(pixelHistory(s, -1, 0), std::invalid_argument);
    CHECK_THROWS_AS(pixelHistory(s, 0, -1), std::invalid_argument);
    CHECK_THROWS_AS(pixelHistory(s, 8, 0), std::invalid_argument);
    CHECK_THROWS_AS(pixelHistory(s, 0, 4), std::invalid_argument);
    CHECK_NOTHROW(pixelHistory(s, 7, 3));
  }
}
