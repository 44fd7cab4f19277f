// The compute device's records as the shaders lay them out, read from their SPIR-V: every record
// of tile_common.glsl (and the push constants) has, in each stage that binds it, the field
// offsets and array stride of its host mirror (backends/vulkan/src/tile_frame_layout.hpp,
// vulkan_compute_pipelines.hpp). The offsets are the compiler's own std430 decisions, so a field
// added, moved, renamed or widened on one side only fails here. Vulkan-free.

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "tile_frame_layout.hpp"
#include "vulkan_compute_pipelines.hpp"

namespace {
using std::uint32_t;  // glslangValidator --vn writes `const uint32_t k_<name>[] = {...};`
#include "tile_box.comp.h"
#include "tile_raster.comp.h"
#include "tile_resolve.comp.h"
#include "tile_scan.comp.h"
#include "tile_scan_serial.comp.h"
#include "tile_scatter.comp.h"
#include "tile_setup.comp.h"
#include "tile_sort.comp.h"
#include "tile_vertex.comp.h"
}  // namespace

using namespace recode::backends::detail;

namespace {

constexpr std::uint32_t kMagic = 0x07230203;
constexpr std::uint32_t kOpName = 5;
constexpr std::uint32_t kOpMemberName = 6;
constexpr std::uint32_t kOpTypeRuntimeArray = 29;
constexpr std::uint32_t kOpDecorate = 71;
constexpr std::uint32_t kOpMemberDecorate = 72;
constexpr std::uint32_t kDecorationArrayStride = 6;
constexpr std::uint32_t kDecorationOffset = 35;

// A struct type as a module lays it out: each member's byte offset by name, and the stride of a
// runtime array of it (0 when the module has none).
struct Layout {
  std::map<std::string, std::uint32_t> offsets;
  std::uint32_t stride = 0;
};

// The literal string at words[at...] (nul-terminated, four bytes a word, low byte first).
std::string literal(std::span<const std::uint32_t> words, std::size_t at) {
  std::string s;
  for (std::size_t i = at; i < words.size(); ++i) {
    for (int b = 0; b < 4; ++b) {
      const char c = static_cast<char>((words[i] >> (8 * b)) & 0xFFu);
      if (c == '\0')
        return s;
      s.push_back(c);
    }
  }
  return s;
}

// Every laid-out struct named `name` in a module (a struct copied into a function's variable is
// a type of its own without offsets: left out). Instructions follow the 5-word header, each word
// count in the high half of its first word and opcode in the low half.
std::vector<Layout> layoutsNamed(std::span<const std::uint32_t> words, const std::string& name) {
  REQUIRE(words.size() > 5);
  REQUIRE(words[0] == kMagic);
  std::set<std::uint32_t> named;
  std::map<std::uint32_t, std::map<std::uint32_t, std::string>> memberNames;
  std::map<std::uint32_t, std::map<std::uint32_t, std::uint32_t>> memberOffsets;
  std::map<std::uint32_t, std::uint32_t> strides;        // array type -> ArrayStride
  std::map<std::uint32_t, std::uint32_t> runtimeArrays;  // array type -> element type
  for (std::size_t i = 5; i < words.size();) {
    const std::uint32_t count = words[i] >> 16;
    const std::uint32_t opcode = words[i] & 0xFFFFu;
    if (count == 0 || i + count > words.size())
      FAIL("malformed SPIR-V at word " << i);
    const std::span<const std::uint32_t> op = words.subspan(i, count);
    if (opcode == kOpName && literal(op, 2) == name)
      named.insert(op[1]);
    else if (opcode == kOpMemberName)
      memberNames[op[1]][op[2]] = literal(op, 3);
    else if (opcode == kOpMemberDecorate && op[3] == kDecorationOffset)
      memberOffsets[op[1]][op[2]] = op[4];
    else if (opcode == kOpDecorate && op[2] == kDecorationArrayStride)
      strides[op[1]] = op[3];
    else if (opcode == kOpTypeRuntimeArray)
      runtimeArrays[op[1]] = op[2];
    i += count;
  }
  std::vector<Layout> found;
  for (const std::uint32_t id : named) {
    if (memberOffsets.count(id) == 0)
      continue;
    Layout l;
    for (const auto& [member, offset] : memberOffsets[id])
      l.offsets[memberNames[id][member]] = offset;
    for (const auto& [array, element] : runtimeArrays)
      if (element == id)
        l.stride = strides[array];
    found.push_back(l);
  }
  return found;
}

// "name offset" a field, in offset order, for a readable difference.
std::string describe(const std::map<std::string, std::uint32_t>& fields) {
  std::map<std::uint32_t, std::string> byOffset;
  for (const auto& [name, offset] : fields)
    byOffset[offset] += (byOffset[offset].empty() ? "" : "|") + name;
  std::string s;
  for (const auto& [offset, names] : byOffset)
    s += names + " " + std::to_string(offset) + ", ";
  return s;
}

struct Stage {
  const char* name;
  std::span<const std::uint32_t> words;
};
const Stage kStages[] = {
    {"tile_box", k_tile_box_comp},
    {"tile_vertex", k_tile_vertex_comp},
    {"tile_setup", k_tile_setup_comp},
    {"tile_scan", k_tile_scan_comp},
    {"tile_scan_serial", k_tile_scan_serial_comp},
    {"tile_scatter", k_tile_scatter_comp},
    {"tile_sort", k_tile_sort_comp},
    {"tile_raster", k_tile_raster_comp},
    {"tile_resolve", k_tile_resolve_comp},
};

// Checks that every stage that lays out `glslName` gives it the host's `fields` and, bound as an
// array, a stride of `hostSize`; returns the stages that do.
std::set<std::string> checkRecord(const std::string& glslName,
                                  const std::map<std::string, std::uint32_t>& fields,
                                  std::size_t hostSize) {
  std::set<std::string> stages;
  for (const Stage& stage : kStages) {
    for (const Layout& l : layoutsNamed(stage.words, glslName)) {
      INFO(stage.name << "'s " << glslName);
      CHECK(describe(l.offsets) == describe(fields));
      if (l.stride != 0)
        CHECK(l.stride == hostSize);
      stages.insert(stage.name);
    }
  }
  return stages;
}

template <class T, class M>
std::uint32_t at(M T::*member) {
  // offsetof by member pointer: the byte distance in a value-initialised T.
  const T value{};
  return static_cast<std::uint32_t>(reinterpret_cast<const char*>(&(value.*member)) -
                                    reinterpret_cast<const char*>(&value));
}

}  // namespace

TEST_CASE("the set-up triangle's host mirror has the shaders' layout, in every stage of it",
          "[tile-layout]") {
  using T = TileSetUpTriangle;
  const std::map<std::string, std::uint32_t> fields = {
      {"x0", at(&T::x0)},       {"y0", at(&T::y0)},
      {"x1", at(&T::x1)},       {"y1", at(&T::y1)},
      {"x2", at(&T::x2)},       {"y2", at(&T::y2)},
      {"front", at(&T::front)}, {"candidates", at(&T::candidates)},
      {"z0", at(&T::z0)},       {"dzdx", at(&T::dzdx)},
      {"dzdy", at(&T::dzdy)},
  };
  const std::set<std::string> stages = checkRecord("SetUpTriangle", fields, sizeof(T));
  CHECK(stages == std::set<std::string>{"tile_setup", "tile_scatter", "tile_raster"});
}

TEST_CASE("the frame's other records and push constants have their host mirrors' layout",
          "[tile-layout]") {
  {
    using T = TileTarget;
    CHECK_FALSE(
        checkRecord(
            "Target",
            {{"pixels", at(&T::pixels)}, {"width", at(&T::width)}, {"height", at(&T::height)}},
            sizeof(T))
            .empty());
  }
  {
    using T = TileCommand;
    CHECK_FALSE(checkRecord("Command",
                            {{"rect", at(&T::rect)},
                             {"kind", at(&T::kind)},
                             {"target", at(&T::target)},
                             {"tests", at(&T::tests)},
                             {"stencil", at(&T::stencil)},
                             {"ops", at(&T::ops)},
                             {"first", at(&T::first)},
                             {"count", at(&T::count)},
                             {"value", at(&T::value)},
                             {"clearMask", at(&T::clearMask)},
                             {"readForm", at(&T::readForm)},
                             {"arenaWord", at(&T::arenaWord)},
                             {"pad", at(&T::pad)}},
                            sizeof(T))
                    .empty());
  }
  {
    using T = TileEpoch;
    CHECK_FALSE(checkRecord("Epoch",
                            {{"footprint", at(&T::footprint)},
                             {"gridOrigin", at(&T::gridOrigin)},
                             {"gridWidth", at(&T::gridWidth)},
                             {"gridHeight", at(&T::gridHeight)},
                             {"target", at(&T::target)},
                             {"firstJob", at(&T::firstJob)},
                             {"firstCommand", at(&T::firstCommand)},
                             {"commandEnd", at(&T::commandEnd)},
                             {"flags", at(&T::flags)},
                             {"firstFinal", at(&T::firstFinal)},
                             {"pad1", at(&T::pad)},
                             {"pad2", at(&T::pad) + 4}},
                            sizeof(T))
                    .empty());
  }
  {
    using T = TileDrawSource;
    CHECK_FALSE(checkRecord("DrawSource",
                            {{"vertices", at(&T::vertices)},
                             {"indices", at(&T::indices)},
                             {"firstTriangle", at(&T::firstTriangle)},
                             {"triangleCount", at(&T::triangleCount)},
                             {"command", at(&T::command)},
                             {"epoch", at(&T::epoch)}},
                            sizeof(T))
                    .empty());
  }
  {
    using T = TileVertexJob;
    CHECK_FALSE(checkRecord("VertexJob",
                            {{"local", at(&T::local)},
                             {"windows", at(&T::windows)},
                             {"firstVertex", at(&T::firstVertex)},
                             {"vertexCount", at(&T::vertexCount)},
                             {"transform", at(&T::transform)},
                             {"pad", at(&T::pad)}},
                            sizeof(T))
                    .empty());
  }
  {
    using T = TileResolveRange;
    CHECK_FALSE(checkRecord("ResolveRange",
                            {{"rect", at(&T::rect)},
                             {"target", at(&T::target)},
                             {"epoch", at(&T::epoch)},
                             {"firstLater", at(&T::firstLater)},
                             {"laterCount", at(&T::laterCount)},
                             {"firstPixel", at(&T::firstPixel)},
                             {"pad0", at(&T::pad)},
                             {"pad1", at(&T::pad) + 4},
                             {"pad2", at(&T::pad) + 8}},
                            sizeof(T))
                    .empty());
  }
  {
    using T = TileBoxJob;
    CHECK_FALSE(checkRecord("BoxJob",
                            {{"local", at(&T::local)},
                             {"vertexCount", at(&T::vertexCount)},
                             {"pose", at(&T::pose)}},
                            sizeof(T))
                    .empty());
  }
  {
    using T = TileFrameConstants;
    CHECK_FALSE(checkRecord("Frame",
                            {{"vertexCount", at(&T::vertexCount)},
                             {"vertexJobs", at(&T::vertexJobs)},
                             {"triangleCount", at(&T::triangleCount)},
                             {"drawCount", at(&T::drawCount)},
                             {"jobCount", at(&T::jobCount)},
                             {"epochCount", at(&T::epochCount)},
                             {"entryCapacity", at(&T::entryCapacity)},
                             {"resolvePixels", at(&T::resolvePixels)},
                             {"resolveRanges", at(&T::resolveRanges)},
                             {"boxJobs", at(&T::boxJobs)},
                             {"binPass", at(&T::binPass)},
                             {"rasterBudget", at(&T::rasterBudget)},
                             {"sortBudget", at(&T::sortBudget)},
                             {"scatterBlocks", at(&T::scatterBlocks)},
                             {"scatterChunks", at(&T::scatterChunks)},
                             {"round", at(&T::round)},
                             {"roundGroupsX", at(&T::roundGroupsX)},
                             {"roundGroupsY", at(&T::roundGroupsY)}},
                            sizeof(T))
                    .empty());
  }
}
