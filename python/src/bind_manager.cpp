// CollisionManager (recode/api/manager.hpp). The manager holds the same CollisionObjects as
// Python does (shared), so moving an object in Python moves it in the manager.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "devices.hpp"
#include "recode/api/manager.hpp"

namespace recode::python {

namespace {

// An id not in the manager is a KeyError (ids are keys, not positions), with the C++ message.
template <class F>
auto byId(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::out_of_range& e) {
    throw py::key_error(e.what());
  }
}

}  // namespace

void bindManager(py::module_& m) {
  py::class_<ObjectContact>(m, "ObjectContact", "One pair of objects in contact, a < b.")
      .def_readonly("a", &ObjectContact::a)
      .def_readonly("b", &ObjectContact::b)
      .def_readonly("result", &ObjectContact::result)
      .def("__repr__", [](const ObjectContact& c) {
        return "<recode.ObjectContact " + std::to_string(c.a) + ", " + std::to_string(c.b) + ": " +
               std::to_string(c.result.interferingPixels) + " interfering pixels>";
      });

  py::class_<CollisionManager>(
      m, "CollisionManager",
      "Many objects: sort and sweep on their world boxes, then collide() on each candidate pair.")
      .def(py::init([](const std::string& device) {
             return std::make_unique<CollisionManager>(deviceFactory(device));
           }),
           py::kw_only(), py::arg("device") = "cpu",
           "device: a name of recode.devices(), the device every pair is drawn on.")
      .def("add", &CollisionManager::add, py::arg("object"),
           "Adds an object (shared: moving it moves it here); returns its id. Ids are never "
           "reused.")
      .def(
          "remove", [](CollisionManager& cm, ObjectId id) { byId([&] { cm.remove(id); }); },
          py::arg("id"))
      .def(
          "update",
          [](CollisionManager& cm, ObjectId id, std::optional<py::object> pose,
             std::optional<py::object> rotation, std::optional<py::object> translation) {
            const Eigen::Isometry3d p = poseFromArguments(pose, rotation, translation);
            byId([&] { cm.update(id, p); });
          },
          py::arg("id"), py::arg("pose") = py::none(), py::kw_only(),
          py::arg("rotation") = py::none(), py::arg("translation") = py::none(),
          "Moves object `id` (the same as object(id).set_transform(...)).")
      .def(
          "object",
          [](CollisionManager& cm, ObjectId id) {
            // The manager's shared pointer, so Python gets the object it added.
            CollisionObject& o = byId([&]() -> CollisionObject& { return cm.object(id); });
            return py::cast(&o, py::return_value_policy::reference);
          },
          py::arg("id"))
      .def("__len__", &CollisionManager::size)
      .def(
          "collide",
          [](CollisionManager& cm, const std::optional<CollisionRequest>& request,
             const std::optional<std::function<void(ObjectId, ObjectId, const CollisionResult&)>>&
                 callback) -> py::object {
            const CollisionRequest r = request.value_or(CollisionRequest{});
            if (callback) {
              cm.collide(r, *callback);
              return py::none();
            }
            py::list out;
            for (ObjectContact& c : cm.collide(r))
              out.append(py::cast(std::move(c)));
            return out;
          },
          py::arg("request") = py::none(), py::arg("callback") = py::none(),
          "Every pair in contact at the objects' current poses, as a list of ObjectContact "
          "ordered by (a, b); with `callback`, calls callback(a, b, result) for each instead and "
          "returns None.")
      .def_property_readonly(
          "stats",
          [](const CollisionManager& cm) {
            py::dict d;
            d["candidate_pairs"] = cm.stats().candidatePairs;
            d["pairs_in_contact"] = cm.stats().pairsInContact;
            return d;
          },
          "Of the last collide(): candidate_pairs (boxes overlap), pairs_in_contact.");
}

}  // namespace recode::python
