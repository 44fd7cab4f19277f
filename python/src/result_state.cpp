#include "result_state.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "pickle_state.hpp"

namespace recode::python {

namespace {

constexpr const char* kType = "recode.CollisionResult";

using Int64s = std::vector<std::int64_t>;
using Doubles = std::vector<double>;

template <class T>
T itemAs(const py::handle& item, const char* what) {
  return stateItem<T>(item, kType, what);
}

py::array_t<std::int32_t> rectState(const raster::PixelRect& r) {
  return stateArray(std::vector<std::int32_t>{r.x0, r.y0, r.x1, r.y1});
}
raster::PixelRect rectFrom(const py::handle& state, const char* what) {
  const auto v = stateValues<std::int32_t>(state, 4, kType, what);
  return {v[0], v[1], v[2], v[3]};
}

// ContactRegion: (points (n, 3), box [min, max] (6,), [pixels, collapsed pixels], [area, max
// depth], None or [normal x, y, z, depth]).
py::tuple regionState(const core::ContactRegion& c) {
  const Doubles box{c.box.min.x(), c.box.min.y(), c.box.min.z(),
                    c.box.max.x(), c.box.max.y(), c.box.max.z()};
  const py::object normal =
      c.normal ? py::object(stateArray(Doubles{c.normal->normal.x(), c.normal->normal.y(),
                                               c.normal->normal.z(), c.normal->depth}))
               : py::none();
  return py::make_tuple(pointsState(c.points), stateArray(box),
                        stateArray(Int64s{c.pixels, c.collapsedPixels}),
                        stateArray(Doubles{c.area, c.maxDepth}), normal);
}
core::ContactRegion regionFrom(const py::handle& item) {
  const auto t = itemAs<py::tuple>(item, "contact region");
  if (t.size() != 5)
    throw py::value_error(std::string(kType) +
                          ": the pickled state's contact region is not 5 "
                          "items");
  core::ContactRegion c;
  c.points = pointsFromState(t[0], kType, "contact points");
  const Doubles box = stateValues<double>(t[1], 6, kType, "contact box");
  c.box.min = Eigen::Vector3d(box[0], box[1], box[2]);
  c.box.max = Eigen::Vector3d(box[3], box[4], box[5]);
  const Int64s counts = stateValues<std::int64_t>(t[2], 2, kType, "contact pixels");
  c.pixels = counts[0];
  c.collapsedPixels = counts[1];
  const Doubles sizes = stateValues<double>(t[3], 2, kType, "contact area");
  c.area = sizes[0];
  c.maxDepth = sizes[1];
  if (!t[4].is_none()) {
    const Doubles n = stateValues<double>(t[4], 4, kType, "contact normal");
    c.normal = core::ContactNormal{Eigen::Vector3d(n[0], n[1], n[2]), n[3]};
  }
  return c;
}

// PairResult: ([collide, boxes overlap, interfering pixels, stencil pixels read, depth pixels
// read], mor, contact rectangle, case counts (9,), (case map rectangle, case map values),
// contact region, [depth min, depth max], [step times..., classify, total]).
py::tuple pairState(const core::PairResult& p) {
  const Int64s flags{p.collide, p.boxesOverlap, p.interferingPixels, p.stencilPixelsRead,
                     p.depthPixelsRead};
  Doubles timing(p.timing.stepUs.begin(), p.timing.stepUs.end());
  timing.push_back(p.timing.classifyUs);
  timing.push_back(p.timing.totalUs);
  const py::tuple caseMap = py::make_tuple(rectState(p.caseMap.rect), stateArray(p.caseMap.data));
  return py::make_tuple(stateArray(flags), rectState(p.mor), rectState(p.contactRect),
                        stateArray(Int64s(p.caseCounts.begin(), p.caseCounts.end())), caseMap,
                        regionState(p.contact), stateArray(Doubles{p.depthMin, p.depthMax}),
                        stateArray(timing));
}
core::PairResult pairFrom(const py::handle& item) {
  const auto t = itemAs<py::tuple>(item, "block pair");
  if (t.size() != 8)
    throw py::value_error(std::string(kType) + ": the pickled state's block pair is not 8 items");
  core::PairResult p;
  const Int64s flags = stateValues<std::int64_t>(t[0], 5, kType, "block pair counts");
  p.collide = flags[0] != 0;
  p.boxesOverlap = flags[1] != 0;
  p.interferingPixels = flags[2];
  p.stencilPixelsRead = flags[3];
  p.depthPixelsRead = flags[4];
  p.mor = rectFrom(t[1], "MOR");
  p.contactRect = rectFrom(t[2], "contact rectangle");
  const Int64s cases = stateValues<std::int64_t>(t[3], core::kCaseCount, kType, "case counts");
  std::copy(cases.begin(), cases.end(), p.caseCounts.begin());
  const auto caseMap = itemAs<py::tuple>(t[4], "case map");
  if (caseMap.size() != 2)
    throw py::value_error(std::string(kType) + ": the pickled state's case map is not 2 items");
  const raster::PixelRect rect = rectFrom(caseMap[0], "case map rectangle");
  const auto area = static_cast<std::size_t>(rect.area());
  p.caseMap = raster::PixelBuffer<std::uint8_t>(
      rect, stateValues<std::uint8_t>(caseMap[1], area, kType, "case map"));
  p.contact = regionFrom(t[5]);
  const Doubles depth = stateValues<double>(t[6], 2, kType, "depth range");
  p.depthMin = depth[0];
  p.depthMax = depth[1];
  const Doubles timing = stateValues<double>(t[7], core::kPairStepCount + 2, kType, "step times");
  std::copy(timing.begin(), timing.begin() + core::kPairStepCount, p.timing.stepUs.begin());
  p.timing.classifyUs = timing[core::kPairStepCount];
  p.timing.totalUs = timing[core::kPairStepCount + 1];
  return p;
}

// A per-pixel buffer: (rectangle, values).
template <class T>
py::tuple bufferState(const raster::PixelBuffer<T>& b) {
  return py::make_tuple(rectState(b.rect), stateArray(b.data));
}
template <class T>
raster::PixelBuffer<T> bufferFrom(const py::handle& item, const char* what) {
  const auto t = itemAs<py::tuple>(item, what);
  if (t.size() != 2)
    throw py::value_error(std::string(kType) + ": the pickled state's " + what + " is not 2 items");
  const raster::PixelRect rect = rectFrom(t[0], what);
  return raster::PixelBuffer<T>(
      rect, stateValues<T>(t[1], static_cast<std::size_t>(rect.area()), kType, what));
}

// LayeredPairResult: ([collide, boxes overlap, interfering pixels, containment, layers A, layers
// B, passes, stencil pixels read, depth pixels read], mor, contact rectangle, overlap steps,
// interferes, contact region, [overlap volume, depth min, depth max], [step times..., total]).
py::tuple layeredState(const core::LayeredPairResult& r) {
  const Int64s ints{r.collide,
                    r.boxesOverlap,
                    r.interferingPixels,
                    static_cast<std::int64_t>(r.containment),
                    r.layersA,
                    r.layersB,
                    r.passes,
                    r.stencilPixelsRead,
                    r.depthPixelsRead};
  Doubles timing(r.timing.stepUs.begin(), r.timing.stepUs.end());
  timing.push_back(r.timing.totalUs);
  return py::make_tuple(
      stateArray(ints), rectState(r.mor), rectState(r.contactRect), bufferState(r.overlapSteps),
      bufferState(r.interferes), regionState(r.contact),
      stateArray(Doubles{r.overlapVolume, r.depthMin, r.depthMax}), stateArray(timing));
}
core::LayeredPairResult layeredFrom(const py::handle& item) {
  const auto t = itemAs<py::tuple>(item, "layered result");
  if (t.size() != 8)
    throw py::value_error(std::string(kType) +
                          ": the pickled state's layered result is not 8 items");
  const Int64s ints = stateValues<std::int64_t>(t[0], 9, kType, "layered counts");
  if (ints[3] < 0 || ints[3] > static_cast<std::int64_t>(core::Containment::Same))
    throw py::value_error(std::string(kType) + ": the pickled state's containment is outside 0..3");
  core::LayeredPairResult r;
  r.collide = ints[0] != 0;
  r.boxesOverlap = ints[1] != 0;
  r.interferingPixels = ints[2];
  r.containment = static_cast<core::Containment>(ints[3]);
  r.layersA = static_cast<int>(ints[4]);
  r.layersB = static_cast<int>(ints[5]);
  r.passes = static_cast<int>(ints[6]);
  r.stencilPixelsRead = ints[7];
  r.depthPixelsRead = ints[8];
  r.mor = rectFrom(t[1], "layered MOR");
  r.contactRect = rectFrom(t[2], "layered contact rectangle");
  r.overlapSteps = bufferFrom<std::uint32_t>(t[3], "overlap steps");
  r.interferes = bufferFrom<std::uint8_t>(t[4], "interferes");
  r.contact = regionFrom(t[5]);
  const Doubles sizes = stateValues<double>(t[6], 3, kType, "overlap volume and depth range");
  r.overlapVolume = sizes[0];
  r.depthMin = sizes[1];
  r.depthMax = sizes[2];
  const Doubles timing =
      stateValues<double>(t[7], core::kLayerStepCount + 1, kType, "layered step times");
  std::copy(timing.begin(), timing.begin() + core::kLayerStepCount, r.timing.stepUs.begin());
  r.timing.totalUs = timing[core::kLayerStepCount];
  return r;
}

// FrameSpec: ([view axis, width, height], window [umin, vmin, umax, vmax]).
py::tuple frameState(const core::FrameSpec& f) {
  return py::make_tuple(
      stateArray(Int64s{static_cast<std::int64_t>(f.axis), f.width, f.height}),
      stateArray(Doubles{f.window.umin, f.window.vmin, f.window.umax, f.window.vmax}));
}
core::FrameSpec frameFrom(const py::handle& item) {
  const auto t = itemAs<py::tuple>(item, "frame");
  if (t.size() != 2)
    throw py::value_error(std::string(kType) + ": the pickled state's frame is not 2 items");
  const Int64s ints = stateValues<std::int64_t>(t[0], 3, kType, "frame");
  if (ints[0] < 0 || ints[0] > 2)
    throw py::value_error(std::string(kType) +
                          ": the pickled state's frame has an axis outside 0..2");
  core::FrameSpec f;
  f.axis = static_cast<core::ViewAxis>(ints[0]);
  f.width = static_cast<int>(ints[1]);
  f.height = static_cast<int>(ints[2]);
  const Doubles w = stateValues<double>(t[1], 4, kType, "frame window");
  f.window = {w[0], w[1], w[2], w[3]};
  return f;
}

// BlockContact: ([block a, block b, refine level, layered], frame, pair).
py::tuple contactState(const BlockContact& c) {
  const Int64s ints{static_cast<std::int64_t>(c.blockA), static_cast<std::int64_t>(c.blockB),
                    c.refineLevel, c.layered};
  return py::make_tuple(stateArray(ints), frameState(c.frame), pairState(c.pair));
}
BlockContact contactFrom(const py::handle& item) {
  const auto t = itemAs<py::tuple>(item, "block contact");
  if (t.size() != 3)
    throw py::value_error(std::string(kType) +
                          ": the pickled state's block contact is not 3 items");
  const Int64s ints = stateValues<std::int64_t>(t[0], 4, kType, "block contact");
  if (ints[0] < 0 || ints[1] < 0)
    throw py::value_error(std::string(kType) +
                          ": the pickled state's block contact has a negative block");
  BlockContact c;
  c.blockA = static_cast<std::size_t>(ints[0]);
  c.blockB = static_cast<std::size_t>(ints[1]);
  c.refineLevel = static_cast<int>(ints[2]);
  c.layered = ints[3] != 0;
  c.frame = frameFrom(t[1]);
  c.pair = pairFrom(t[2]);
  return c;
}

}  // namespace

// (format, [collide, interfering pixels, box tests, block pairs drawn, block pairs skipped,
// apart at limit], [collision us, device setup us], contact region, [block contacts], None or
// (frame, layered result)).
py::tuple resultState(const CollisionResult& r) {
  const Int64s counts{r.collide,         r.interferingPixels, r.boxTests,
                      r.blockPairsDrawn, r.blockPairsSkipped, r.apartAtLimit};
  py::list contacts;
  for (const BlockContact& c : r.contacts)
    contacts.append(contactState(c));
  const py::object layered = r.layered ? py::object(py::make_tuple(frameState(r.layered->frame),
                                                                   layeredState(r.layered->result)))
                                       : py::none();
  return makeState(stateArray(counts), stateArray(Doubles{r.collisionUs, r.deviceSetupUs}),
                   regionState(r.contact), contacts, layered);
}

CollisionResult resultFromState(const py::tuple& state) {
  checkState(state, kType, 5);
  CollisionResult r;
  const Int64s counts = stateValues<std::int64_t>(state[1], 6, kType, "counts");
  r.collide = counts[0] != 0;
  r.interferingPixels = counts[1];
  r.boxTests = counts[2];
  r.blockPairsDrawn = counts[3];
  r.blockPairsSkipped = counts[4];
  r.apartAtLimit = counts[5];
  const Doubles times = stateValues<double>(state[2], 2, kType, "times");
  r.collisionUs = times[0];
  r.deviceSetupUs = times[1];
  r.contact = regionFrom(state[3]);
  for (const py::handle c : itemAs<py::list>(state[4], "block contacts"))
    r.contacts.push_back(contactFrom(c));
  if (!state[5].is_none()) {
    const auto layered = itemAs<py::tuple>(state[5], "layered pair");
    if (layered.size() != 2)
      throw py::value_error(std::string(kType) +
                            ": the pickled state's layered pair is not 2 items");
    r.layered = LayeredPair{frameFrom(layered[0]), layeredFrom(layered[1])};
  }
  return r;
}

}  // namespace recode::python
