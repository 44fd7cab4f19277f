// CollisionObject, CollisionRequest, CollisionResult and collide() (recode/api/collision.hpp).
// Results are the C++ structs themselves; their vectors reach Python as read-only NumPy views
// whose base keeps the result alive, so reading a large case map or point list copies nothing.
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "devices.hpp"
#include "pickle_state.hpp"
#include "recode/api/collision.hpp"
#include "recode/refine/pair_mode.hpp"
#include "result_state.hpp"

namespace recode::python {

namespace {

using ObjectHolder = std::shared_ptr<CollisionObject>;

// A shape argument: a CollisionGeometry, a ConvexBlock taken as a geometry of one block, or a
// ClosedMesh taken as a closed mesh's geometry.
CollisionGeometryPtr shapeFrom(const py::handle& shape) {
  if (py::isinstance<ConvexBlock>(shape))
    return CollisionGeometry::single(shape.cast<std::shared_ptr<ConvexBlock>>());
  if (py::isinstance<ClosedMesh>(shape))
    return CollisionGeometry::closed(shape.cast<std::shared_ptr<ClosedMesh>>());
  if (py::isinstance<CollisionGeometry>(shape))
    return shape.cast<std::shared_ptr<CollisionGeometry>>();
  throw py::type_error(
      "shape: expected a ConvexBlock or a CollisionGeometry (or a ClosedMesh), got " +
      py::str(py::type::of(shape)).cast<std::string>());
}

py::object boxOf(const core::Aabb& box) {
  if (box.isEmpty())
    return py::none();
  py::array_t<double> out({2, 3});
  auto w = out.mutable_unchecked<2>();
  for (int k = 0; k < 3; ++k) {
    w(0, k) = box.min[k];
    w(1, k) = box.max[k];
  }
  return out;
}

py::array_t<long long> countsOf(const std::array<long long, core::kCaseCount>& counts) {
  py::array_t<long long> out(core::kCaseCount);
  std::copy(counts.begin(), counts.end(), out.mutable_data());
  return out;
}

py::tuple rectOf(const raster::PixelRect& r) {
  return py::make_tuple(r.x0, r.y0, r.x1, r.y1);
}

std::string morName(core::MorMode mode) {
  return std::string(core::toString(mode));
}
core::MorMode morFrom(const std::string& name) {
  if (const auto mode = core::parseMorMode(name))
    return *mode;
  throw py::value_error("mor: '" + name + "' is not a MOR mode (min, max or full)");
}

std::string axisName(AxisChoice axis) {
  switch (axis) {
    case AxisChoice::X:
      return "x";
    case AxisChoice::Y:
      return "y";
    case AxisChoice::Z:
      return "z";
    case AxisChoice::Auto:
      break;
  }
  return "auto";
}
AxisChoice axisFrom(const std::string& name) {
  if (name == "x")
    return AxisChoice::X;
  if (name == "y")
    return AxisChoice::Y;
  if (name == "z")
    return AxisChoice::Z;
  if (name == "auto")
    return AxisChoice::Auto;
  throw py::value_error("axis: '" + name + "' is not a view axis (x, y, z or auto)");
}

core::PairMode modeFrom(const std::string& name) {
  if (const auto mode = core::parsePairMode(name))
    return *mode;
  throw py::value_error("mode: '" + name +
                        "' is not a pair mode (reference, adaptive, conservative or skip-apart)");
}

std::optional<double> pixelSizeFrom(const std::optional<double>& size) {
  if (size && !(std::isfinite(*size) && *size > 0.0))
    throw py::value_error("pixel_size: " + py::str(py::float_(*size)).cast<std::string>() +
                          " is not a positive finite number of world units");
  return size;
}

int resolutionFrom(int resolution) {
  if (resolution < 1 || resolution > raster::kMaxFramebufferSize)
    throw py::value_error("resolution: " + std::to_string(resolution) + " is outside 1.." +
                          std::to_string(raster::kMaxFramebufferSize));
  return resolution;
}

int threadsFrom(int threads) {
  if (threads < 0)
    throw py::value_error("threads is " + std::to_string(threads) +
                          ": give 1 (the caller's thread), 0 (every hardware thread) or a count");
  return threads;
}

std::string repr(const CollisionRequest& r) {
  return "CollisionRequest(pixel_size=" +
         (r.pixelSize ? py::str(py::float_(*r.pixelSize)).cast<std::string>() : "None") +
         ", resolution=" + std::to_string(r.resolution) + ", mor='" + morName(r.mor) + "', axis='" +
         axisName(r.axis) + "', contact=" + (r.contact ? "True" : "False") +
         ", normal=" + (r.normal ? "True" : "False") + ", mode='" +
         std::string(core::toString(r.mode)) + "', threads=" + std::to_string(r.threads) + ")";
}

// The case map of the result's one block pair in contact; None without contact.
py::object singleCaseMap(const py::object& self) {
  const auto& result = self.cast<const CollisionResult&>();
  if (result.contacts.empty())
    return py::none();
  if (result.contacts.size() > 1)
    throw py::value_error(std::to_string(result.contacts.size()) +
                          " block pairs are in contact, each with its own case map and frame: "
                          "read result.contacts[i].case_map");
  const py::object first =
      py::cast(&result.contacts.front(), py::return_value_policy::reference_internal, self);
  return first.attr("case_map");
}

std::shared_ptr<CollisionObject> objectFrom(const py::handle& shape,
                                            const std::optional<py::object>& pose,
                                            const std::optional<py::object>& rotation,
                                            const std::optional<py::object>& translation) {
  return std::make_shared<CollisionObject>(shapeFrom(shape),
                                           poseFromArguments(pose, rotation, translation));
}

void setTransform(CollisionObject& o, const std::optional<py::object>& pose,
                  const std::optional<py::object>& rotation,
                  const std::optional<py::object>& translation) {
  o.setTransform(poseFromArguments(pose, rotation, translation));
}

CollisionRequest requestFrom(std::optional<double> pixelSize, int resolution,
                             const std::string& mor, const std::string& axis, bool contact,
                             bool normal, const std::string& mode, int threads) {
  CollisionRequest r;
  r.pixelSize = pixelSizeFrom(pixelSize);
  r.resolution = resolutionFrom(resolution);
  r.mor = morFrom(mor);
  r.axis = axisFrom(axis);
  r.contact = contact;
  r.normal = normal;
  r.mode = modeFrom(mode);
  r.threads = threadsFrom(threads);
  return r;
}

// The result's block contacts, each a view kept alive by the result.
py::list contactsOf(const py::object& self) {
  py::list list;
  for (const BlockContact& c : self.cast<const CollisionResult&>().contacts)
    list.append(py::cast(&c, py::return_value_policy::reference_internal, self));
  return list;
}

py::array_t<long long> caseCountsOf(const CollisionResult& r) {
  std::array<long long, core::kCaseCount> sum{};
  for (const BlockContact& c : r.contacts)
    for (std::size_t k = 0; k < sum.size(); ++k)
      sum[k] += c.pair.caseCounts[k];
  return countsOf(sum);
}

// recode.collide: copies of the two objects and the request, made with the GIL held; the query
// then runs without it, and another thread may move a or b meanwhile (docs/api.md#threads).
CollisionResult collideObjects(const CollisionObject& a, const CollisionObject& b,
                               const std::optional<CollisionRequest>& request,
                               const std::string& device) {
  const CollisionObject copyA = a;
  const CollisionObject copyB = b;
  const CollisionRequest r = request.value_or(CollisionRequest{});
  SharedPool* shared = device == "cpu" ? nullptr : &devicePool(device);
  CollisionResult result;
  py::gil_scoped_release release;
  if (!shared) {
    collide(copyA, copyB, r, result);
  } else {
    const std::lock_guard<std::mutex> lock(shared->mutex);
    collide(copyA, copyB, r, result, shared->pool);
  }
  return result;
}

constexpr const char* kObjectType = "recode.CollisionObject";
constexpr const char* kRequestType = "recode.CollisionRequest";

// (format, geometry, pose 4 x 4): the geometry pickles itself (shared shapes stay shared within
// one pickle).
py::tuple objectState(const CollisionObject& o) {
  return makeState(std::const_pointer_cast<CollisionGeometry>(o.geometryPtr()),
                   matrixOf(o.transform()));
}
std::shared_ptr<CollisionObject> objectFromState(const py::tuple& state) {
  checkState(state, kObjectType, 2);
  auto geometry = stateItem<std::shared_ptr<CollisionGeometry>>(state[1], kObjectType, "geometry");
  return std::make_shared<CollisionObject>(std::move(geometry), poseFrom(state[2]));
}

// (format, pixel size or None, resolution, mor, axis, contact, normal, mode, threads): the
// constructor's arguments, checked by it again.
py::tuple requestState(const CollisionRequest& r) {
  return makeState(r.pixelSize, r.resolution, morName(r.mor), axisName(r.axis), r.contact, r.normal,
                   std::string(core::toString(r.mode)), r.threads);
}
CollisionRequest requestFromState(const py::tuple& state) {
  checkState(state, kRequestType, 8);
  return requestFrom(stateItem<std::optional<double>>(state[1], kRequestType, "pixel size"),
                     stateItem<int>(state[2], kRequestType, "resolution"),
                     stateItem<std::string>(state[3], kRequestType, "mor"),
                     stateItem<std::string>(state[4], kRequestType, "axis"),
                     stateItem<bool>(state[5], kRequestType, "contact"),
                     stateItem<bool>(state[6], kRequestType, "normal"),
                     stateItem<std::string>(state[7], kRequestType, "mode"),
                     stateItem<int>(state[8], kRequestType, "threads"));
}

void bindObject(py::module_& m) {
  py::class_<CollisionObject, ObjectHolder>(
      m, "CollisionObject",
      "A shape at a pose (object -> world). Poses are 4 x 4 matrices [[R, t], [0, 0, 0, 1]] or "
      "rotation (3 x 3) and translation (3,) keywords.")
      .def(py::init(&objectFrom), py::arg("shape"), py::arg("pose") = py::none(), py::kw_only(),
           py::arg("rotation") = py::none(), py::arg("translation") = py::none())
      .def("set_transform", &setTransform, py::arg("pose") = py::none(), py::kw_only(),
           py::arg("rotation") = py::none(), py::arg("translation") = py::none(),
           "Moves the object (its world boxes follow).")
      .def_property_readonly(
          "transform", [](const CollisionObject& o) { return matrixOf(o.transform()); },
          "The pose, 4 x 4 (a copy).")
      .def_property_readonly("geometry",
                             [](const CollisionObject& o) {
                               return std::const_pointer_cast<CollisionGeometry>(o.geometryPtr());
                             })
      .def_property_readonly(
          "world_box", [](const CollisionObject& o) { return boxOf(o.worldBox()); },
          "[[min x, y, z], [max x, y, z]] of the object at its pose.")
      .def(py::pickle(&objectState, &objectFromState));
}

void bindRequest(py::module_& m) {
  py::class_<CollisionRequest>(m, "CollisionRequest",
                               "What collide() measures and how finely (docs/api.md).")
      .def(py::init(&requestFrom), py::kw_only(), py::arg("pixel_size") = py::none(),
           py::arg("resolution") = 256, py::arg("mor") = "min", py::arg("axis") = "auto",
           py::arg("contact") = true, py::arg("normal") = false, py::arg("mode") = "reference",
           py::arg("threads") = 1)
      .def_property(
          "pixel_size", [](const CollisionRequest& r) { return r.pixelSize; },
          [](CollisionRequest& r, std::optional<double> s) { r.pixelSize = pixelSizeFrom(s); },
          "Square pixels of this size in world units; None: use resolution.")
      .def_property(
          "resolution", [](const CollisionRequest& r) { return r.resolution; },
          [](CollisionRequest& r, int n) { r.resolution = resolutionFrom(n); },
          "Pixels along the longer side of the blocks' overlap box (without pixel_size).")
      .def_property(
          "mor", [](const CollisionRequest& r) { return morName(r.mor); },
          [](CollisionRequest& r, const std::string& s) { r.mor = morFrom(s); },
          "'min' (default), 'max' or 'full'.")
      .def_property(
          "axis", [](const CollisionRequest& r) { return axisName(r.axis); },
          [](CollisionRequest& r, const std::string& s) { r.axis = axisFrom(s); },
          "'x', 'y', 'z' or 'auto' (the overlap box's thinnest side).")
      .def_readwrite("contact", &CollisionRequest::contact,
                     "Measure the contact region (points, box, depth).")
      .def_readwrite("normal", &CollisionRequest::normal,
                     "With contact: each block contact's contact.normal and "
                     "contact.penetration_depth.")
      .def_property(
          "mode", [](const CollisionRequest& r) { return std::string(core::toString(r.mode)); },
          [](CollisionRequest& r, const std::string& s) { r.mode = modeFrom(s); },
          "'reference' (default, the paper's algorithm), 'adaptive', 'conservative' or "
          "'skip-apart' (the reference's answer; block pairs proven apart are not drawn).")
      .def_property(
          "threads", [](const CollisionRequest& r) { return r.threads; },
          [](CollisionRequest& r, int n) { r.threads = threadsFrom(n); },
          "Threads a call's block pairs may be decided on, on the CPU device: 1 (default) the "
          "caller's, 0 every hardware thread, N at most N; the results are the same.")
      .def(py::pickle(&requestState, &requestFromState))
      .def("__repr__", &repr);
}

void bindFrame(py::module_& m) {
  py::class_<core::FrameSpec>(m, "Frame", "The frame a block pair was drawn in.")
      .def_property_readonly(
          "axis", [](const core::FrameSpec& f) { return std::string(core::toString(f.axis)); })
      .def_property_readonly(
          "window",
          [](const core::FrameSpec& f) {
            return py::make_tuple(f.window.umin, f.window.vmin, f.window.umax, f.window.vmax);
          },
          "(umin, vmin, umax, vmax) in world units on the image plane.")
      .def_readonly("width", &core::FrameSpec::width)
      .def_readonly("height", &core::FrameSpec::height)
      .def_property_readonly("pixel_size", [](const core::FrameSpec& f) {
        return (f.window.umax - f.window.umin) / f.width;
      });
}

void bindContactRegion(py::module_& m) {
  py::class_<core::ContactRegion>(m, "ContactRegion")
      .def_property_readonly(
          "points",
          [](const py::object& self) {
            return pointsView(self.cast<const core::ContactRegion&>().points, self);
          },
          "(n, 3) float64, one world point per interfering pixel (read-only).")
      .def_property_readonly(
          "box", [](const core::ContactRegion& c) { return boxOf(c.box); },
          "[[min], [max]] of the overlap intervals' ends, or None.")
      .def_readonly("pixels", &core::ContactRegion::pixels)
      .def_readonly("area", &core::ContactRegion::area, "World units squared.")
      .def_readonly("max_depth", &core::ContactRegion::maxDepth,
                    "Longest overlap along the view axis, world units.")
      .def_readonly("collapsed_pixels", &core::ContactRegion::collapsedPixels)
      .def_property_readonly(
          "normal",
          [](const core::ContactRegion& c) -> py::object {
            if (!c.normal)
              return py::none();
            py::array_t<double> out(3);
            std::copy(c.normal->normal.data(), c.normal->normal.data() + 3, out.mutable_data());
            return out;
          },
          "Unit contact normal from block A towards block B, float64 (3,); None unless the "
          "request asked for normals (a block contact's only, never the merged region's).")
      .def_property_readonly(
          "penetration_depth",
          [](const core::ContactRegion& c) -> std::optional<double> {
            if (!c.normal)
              return std::nullopt;
            return c.normal->depth;
          },
          "The overlap's width along normal, world units; None with normal.");
}

void bindBlockContact(py::module_& m) {
  py::class_<BlockContact>(m, "BlockContact", "One pair of blocks whose pixels interfere.")
      .def_readonly("block_a", &BlockContact::blockA)
      .def_readonly("block_b", &BlockContact::blockB)
      .def_readonly("frame", &BlockContact::frame)
      .def_readonly("layered", &BlockContact::layered,
                    "Decided by the layered pair (a closed mesh took part): no cases, an empty "
                    "case map; see CollisionResult.layered.")
      .def_property_readonly(
          "case_counts", [](const BlockContact& c) { return countsOf(c.pair.caseCounts); },
          "Pixels of each case 0-8 inside the MOR, int64 (9,); zeros for a layered contact.")
      .def_property_readonly(
          "case_map",
          [](const py::object& self) {
            const auto& map = self.cast<const BlockContact&>().pair.caseMap;
            return gridView(map.data, map.rect.height(), map.rect.width(), self);
          },
          "uint8 (rows, columns) over the MOR, read-only: case_map[y - mor[1], x - mor[0]], "
          "row 0 the bottom row; empty, (0, 0), for a layered contact.")
      .def_property_readonly(
          "mor", [](const BlockContact& c) { return rectOf(c.pair.mor); },
          "(x0, y0, x1, y1) in pixels, half-open, y from the bottom.")
      .def_property_readonly("interfering_pixels",
                             [](const BlockContact& c) { return c.pair.interferingPixels; })
      .def_property_readonly(
          "contact",
          [](const BlockContact& c) -> const core::ContactRegion& { return c.pair.contact; },
          py::return_value_policy::reference_internal)
      .def_readonly("refine_level", &BlockContact::refineLevel,
                    "Adaptive mode: the refinement level the contact was seen at (0: the "
                    "chosen frame).")
      .def_property_readonly(
          "timing_us", [](const BlockContact& c) { return c.pair.timing.totalUs; },
          "Wall time of the pair algorithm, microseconds.");
}

void bindLayered(py::module_& m) {
  py::class_<LayeredPair>(m, "LayeredResult",
                          "What the layered pair found for two objects of which one or both are "
                          "closed meshes (docs/algorithm.md section 13).")
      .def_readonly("frame", &LayeredPair::frame,
                    "The frame it was drawn in (width 0 when the boxes did not meet).")
      .def_property_readonly("collide", [](const LayeredPair& l) { return l.result.collide; })
      .def_property_readonly("interfering_pixels",
                             [](const LayeredPair& l) { return l.result.interferingPixels; })
      .def_property_readonly(
          "overlap_volume", [](const LayeredPair& l) { return l.result.overlapVolume; },
          "Estimated volume of A and B's intersection, world units cubed.")
      .def_property_readonly(
          "containment",
          [](const LayeredPair& l) { return std::string(core::toString(l.result.containment)); },
          "'none', 'a_inside_b', 'b_inside_a' or 'same'.")
      .def_property_readonly(
          "layers",
          [](const LayeredPair& l) { return py::make_tuple(l.result.layersA, l.result.layersB); },
          "(A, B): the most entries of each mesh at one MOR pixel.")
      .def_property_readonly(
          "passes", [](const LayeredPair& l) { return l.result.passes; },
          "Depth/stencil passes drawn: 4 + 2 (layers A + layers B), 0 when nothing was drawn.")
      .def_property_readonly(
          "mor", [](const LayeredPair& l) { return rectOf(l.result.mor); },
          "(x0, y0, x1, y1) in pixels, half-open, y from the bottom.")
      .def_property_readonly(
          "overlap_steps",
          [](const py::object& self) {
            const auto& map = self.cast<const LayeredPair&>().result.overlapSteps;
            return gridView(map.data, map.rect.height(), map.rect.width(), self);
          },
          "uint32 (rows, columns) over the MOR, read-only: each pixel's overlap length in depth "
          "steps, [y - mor[1], x - mor[0]], row 0 the bottom row.")
      .def_property_readonly(
          "interferes",
          [](const py::object& self) {
            const auto& map = self.cast<const LayeredPair&>().result.interferes;
            return gridView(map.data, map.rect.height(), map.rect.width(), self);
          },
          "uint8 (rows, columns) over the MOR, read-only: 1 where the pixel interferes.")
      .def_property_readonly(
          "contact",
          [](const LayeredPair& l) -> const core::ContactRegion& { return l.result.contact; },
          py::return_value_policy::reference_internal)
      .def_property_readonly(
          "timing_us", [](const LayeredPair& l) { return l.result.timing.totalUs; },
          "Wall time of the layered pair, microseconds.")
      .def("__repr__", [](const LayeredPair& l) {
        const core::LayeredPairResult& r = l.result;
        return "<recode.LayeredResult collide=" + std::string(r.collide ? "True" : "False") +
               " overlap_volume=" + py::repr(py::float_(r.overlapVolume)).cast<std::string>() +
               " containment='" + std::string(core::toString(r.containment)) + "' layers=(" +
               std::to_string(r.layersA) + ", " + std::to_string(r.layersB) +
               ") passes=" + std::to_string(r.passes) + ">";
      });
}

void bindResult(py::module_& m) {
  py::class_<CollisionResult>(m, "CollisionResult")
      .def(py::pickle(&resultState, &resultFromState))
      .def_readonly("collide", &CollisionResult::collide)
      .def("__bool__", [](const CollisionResult& r) { return r.collide; })
      .def_readonly("interfering_pixels", &CollisionResult::interferingPixels)
      .def_readonly("contact", &CollisionResult::contact,
                    "The union over the block pairs in contact.")
      .def_property_readonly("contacts", &contactsOf,
                             "The block pairs in contact, by (block_a, block_b).")
      .def_property_readonly("case_counts", &caseCountsOf,
                             "Cases 0-8 summed over the block pairs in contact, int64 (9,).")
      .def_property_readonly("case_map", &singleCaseMap,
                             "The case map of the one block pair in contact (None without "
                             "contact; ValueError with several: see contacts).")
      .def_property_readonly(
          "layered",
          [](const py::object& self) -> py::object {
            const auto& r = self.cast<const CollisionResult&>();
            if (!r.layered)
              return py::none();
            return py::cast(&*r.layered, py::return_value_policy::reference_internal, self);
          },
          "A LayeredResult when a closed mesh took part (overlap volume, containment, layers, "
          "passes, per-pixel overlap); None for convex blocks.")
      .def_readonly("box_tests", &CollisionResult::boxTests)
      .def_readonly("block_pairs_drawn", &CollisionResult::blockPairsDrawn)
      .def_readonly("block_pairs_skipped", &CollisionResult::blockPairsSkipped,
                    "Skip-apart mode: block pairs proven apart, not drawn.")
      .def_readonly("collision_us", &CollisionResult::collisionUs,
                    "The whole call, microseconds, device making left out.")
      .def_readonly("device_setup_us", &CollisionResult::deviceSetupUs)
      .def_readonly("apart_at_limit", &CollisionResult::apartAtLimit,
                    "Adaptive mode: block pairs a contact could not be ruled out for within the "
                    "refinement limits (not contacts).")
      .def("__repr__", [](const CollisionResult& r) {
        return "<recode.CollisionResult collide=" + std::string(r.collide ? "True" : "False") +
               " interfering_pixels=" + std::to_string(r.interferingPixels) +
               " block_pairs=" + std::to_string(r.contacts.size()) + ">";
      });
}

}  // namespace

void bindCollision(py::module_& m) {
  bindObject(m);
  bindRequest(m);
  bindFrame(m);
  bindContactRegion(m);
  bindBlockContact(m);
  bindLayered(m);
  bindResult(m);
  m.def("collide", &collideObjects, py::arg("a"), py::arg("b"), py::arg("request") = py::none(),
        py::kw_only(), py::arg("device") = "cpu",
        "Collides two objects at their current poses; returns a CollisionResult (true when they "
        "collide). device: a name of recode.devices() (an exact one gives the cpu device's "
        "result, timing aside). Runs without the GIL, on copies of a and b.");
}

}  // namespace recode::python
