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

// BlockContact: ([block a, block b, refine level, view axis, width, height], window [umin,
// vmin, umax, vmax], pair).
py::tuple contactState(const BlockContact& c) {
  const core::FrameSpec& f = c.frame;
  const Int64s ints{static_cast<std::int64_t>(c.blockA),
                    static_cast<std::int64_t>(c.blockB),
                    c.refineLevel,
                    static_cast<std::int64_t>(f.axis),
                    f.width,
                    f.height};
  return py::make_tuple(
      stateArray(ints),
      stateArray(Doubles{f.window.umin, f.window.vmin, f.window.umax, f.window.vmax}),
      pairState(c.pair));
}
BlockContact contactFrom(const py::handle& item) {
  const auto t = itemAs<py::tuple>(item, "block contact");
  if (t.size() != 3)
    throw py::value_error(std::string(kType) +
                          ": the pickled state's block contact is not 3 items");
  const Int64s ints = stateValues<std::int64_t>(t[0], 6, kType, "block contact");
  if (ints[0] < 0 || ints[1] < 0 || ints[3] < 0 || ints[3] > 2)
    throw py::value_error(std::string(kType) +
                          ": the pickled state's block contact has a negative block or an "
                          "axis outside 0..2");
  BlockContact c;
  c.blockA = static_cast<std::size_t>(ints[0]);
  c.blockB = static_cast<std::size_t>(ints[1]);
  c.refineLevel = static_cast<int>(ints[2]);
  c.frame.axis = static_cast<core::ViewAxis>(ints[3]);
  c.frame.width = static_cast<int>(ints[4]);
  c.frame.height = static_cast<int>(ints[5]);
  const Doubles w = stateValues<double>(t[1], 4, kType, "frame window");
  c.frame.window = {w[0], w[1], w[2], w[3]};
  c.pair = pairFrom(t[2]);
  return c;
}

}  // namespace

// (format, [collide, interfering pixels, box tests, block pairs drawn, block pairs skipped,
// apart at limit], [collision us, device setup us], contact region, [block contacts]).
py::tuple resultState(const CollisionResult& r) {
  const Int64s counts{r.collide,         r.interferingPixels, r.boxTests,
                      r.blockPairsDrawn, r.blockPairsSkipped, r.apartAtLimit};
  py::list contacts;
  for (const BlockContact& c : r.contacts)
    contacts.append(contactState(c));
  return makeState(stateArray(counts), stateArray(Doubles{r.collisionUs, r.deviceSetupUs}),
                   regionState(r.contact), contacts);
}

CollisionResult resultFromState(const py::tuple& state) {
  checkState(state, kType, 4);
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
  return r;
}

}  // namespace recode::python
