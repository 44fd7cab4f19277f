// CollisionManager (recode/api/manager.hpp). Python's manager holds the CollisionObjects Python
// added (shared), so moving an object in Python moves it in the manager; the C++ manager inside
// holds copies of them, moved to the Python objects' poses at the start of each query with the
// GIL held, so that the query runs without the GIL while Python threads move the objects.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <map>
#include <memory>
#include <mutex>
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

// The lock of a manager, taken without the GIL held (a thread waiting for it lets the others
// run), and held with the GIL back once taken.
std::unique_lock<std::mutex> lockWithoutGil(std::mutex& mutex) {
  py::gil_scoped_release release;
  return std::unique_lock<std::mutex>(mutex);
}

// An object as Python added it, and the manager's copy of it, which a query reads without the
// GIL: the copy follows the Python object's pose at the start of each query.
struct Held {
  std::shared_ptr<CollisionObject> shared;
  std::shared_ptr<CollisionObject> copy;
};

// The Python CollisionManager: the C++ manager over copies, and the lock its calls take turns
// on (a query holds it without the GIL; the manager's broad phase, devices and stats are its).
struct PyManager {
  explicit PyManager(const std::string& device) : manager(deviceFactory(device)) {}

  // The Python object of id; a KeyError with the C++ message for an id not held.
  CollisionObject& shared(ObjectId id) {
    byId([&]() -> CollisionObject& { return manager.object(id); });
    return *held.at(id).shared;
  }
  // Moves every copy to its Python object's current pose (with the GIL and the lock held).
  void followPoses() {
    for (auto& [id, h] : held)
      if (h.copy->transform().matrix() != h.shared->transform().matrix())
        h.copy->setTransform(h.shared->transform());
  }

  std::mutex mutex;
  CollisionManager manager;
  std::map<ObjectId, Held> held;
};

ObjectId addObject(PyManager& pm, std::shared_ptr<CollisionObject> object) {
  const auto lock = lockWithoutGil(pm.mutex);
  auto copy = object ? std::make_shared<CollisionObject>(*object) : nullptr;
  const ObjectId id = pm.manager.add(copy);  // the C++ message for None
  pm.held.emplace(id, Held{std::move(object), std::move(copy)});
  return id;
}

void removeObject(PyManager& pm, ObjectId id) {
  const auto lock = lockWithoutGil(pm.mutex);
  byId([&] { pm.manager.remove(id); });
  pm.held.erase(id);
}

void updateObject(PyManager& pm, ObjectId id, const std::optional<py::object>& pose,
                  const std::optional<py::object>& rotation,
                  const std::optional<py::object>& translation) {
  const Eigen::Isometry3d p = poseFromArguments(pose, rotation, translation);
  const auto lock = lockWithoutGil(pm.mutex);
  pm.shared(id).setTransform(p);
}

std::shared_ptr<CollisionObject> objectOf(PyManager& pm, ObjectId id) {
  const auto lock = lockWithoutGil(pm.mutex);
  pm.shared(id);  // a KeyError for an id not held
  return pm.held.at(id).shared;
}

std::size_t sizeOf(PyManager& pm) {
  const auto lock = lockWithoutGil(pm.mutex);
  return pm.manager.size();
}

using ContactCallback = std::function<void(ObjectId, ObjectId, const CollisionResult&)>;

// Every pair in contact, as a list of ObjectContact, or handed to `callback` (None returned).
py::object collideAll(PyManager& pm, const std::optional<CollisionRequest>& request,
                      const std::optional<ContactCallback>& callback) {
  const CollisionRequest r = request.value_or(CollisionRequest{});
  std::vector<ObjectContact> contacts;
  {
    const auto lock = lockWithoutGil(pm.mutex);
    pm.followPoses();  // with the GIL: reads the Python objects' poses
    py::gil_scoped_release release;
    if (callback) {
      pm.manager.collide(r, [&](ObjectId a, ObjectId b, const CollisionResult& result) {
        contacts.push_back({a, b, result});
      });
    } else {
      contacts = pm.manager.collide(r);
    }
  }
  // The lock is free again, so a callback may call the manager.
  if (callback) {
    for (const ObjectContact& c : contacts)
      (*callback)(c.a, c.b, c.result);
    return py::none();
  }
  py::list out;
  for (ObjectContact& c : contacts)
    out.append(py::cast(std::move(c)));
  return out;
}

py::dict statsOf(PyManager& pm) {
  const auto lock = lockWithoutGil(pm.mutex);
  py::dict d;
  d["candidate_pairs"] = pm.manager.stats().candidatePairs;
  d["pairs_in_contact"] = pm.manager.stats().pairsInContact;
  return d;
}

void bindObjectContact(py::module_& m) {
  py::class_<ObjectContact>(m, "ObjectContact", "One pair of objects in contact, a < b.")
      .def_readonly("a", &ObjectContact::a)
      .def_readonly("b", &ObjectContact::b)
      .def_readonly("result", &ObjectContact::result)
      .def("__repr__", [](const ObjectContact& c) {
        return "<recode.ObjectContact " + std::to_string(c.a) + ", " + std::to_string(c.b) + ": " +
               std::to_string(c.result.interferingPixels) + " interfering pixels>";
      });
}

void bindCollisionManager(py::module_& m) {
  py::class_<PyManager>(
      m, "CollisionManager",
      "Many objects: sort and sweep on their world boxes, then collide() on each candidate pair. "
      "May be shared between threads: its calls take turns, and a query runs without the GIL.")
      .def(py::init([](const std::string& device) { return std::make_unique<PyManager>(device); }),
           py::kw_only(), py::arg("device") = "cpu",
           "device: a name of recode.devices(), the device every pair is drawn on.")
      .def("add", &addObject, py::arg("object"),
           "Adds an object (shared: moving it moves it here); returns its id. Ids are never "
           "reused.")
      .def("remove", &removeObject, py::arg("id"))
      .def("update", &updateObject, py::arg("id"), py::arg("pose") = py::none(), py::kw_only(),
           py::arg("rotation") = py::none(), py::arg("translation") = py::none(),
           "Moves object `id` (the same as object(id).set_transform(...)).")
      .def("object", &objectOf, py::arg("id"), "The object added as `id` (the same Python object).")
      .def("__len__", &sizeOf)
      .def("collide", &collideAll, py::arg("request") = py::none(),
           py::arg("callback") = py::none(),
           "Every pair in contact at the objects' current poses, as a list of ObjectContact "
           "ordered by (a, b); with `callback`, calls callback(a, b, result) for each instead and "
           "returns None. Runs without the GIL, on the manager's copies of the objects moved to "
           "their poses at the call; request.threads decides the block pairs on that many "
           "oneTBB threads, as the C++ manager does.")
      .def_property_readonly(
          "stats", &statsOf,
          "Of the last collide(): candidate_pairs (boxes overlap), pairs_in_contact.");
}

}  // namespace

void bindManager(py::module_& m) {
  bindObjectContact(m);
  bindCollisionManager(m);
}

}  // namespace recode::python
