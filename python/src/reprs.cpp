// __repr__ for the module's classes whose binding has none (the others define theirs where they
// are bound): each says what the object holds, in the `<recode.Class ...>` form of the rest.
// Bound after every class (module.cpp), onto the classes by name.
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "bindings.hpp"
#include "recode/api/collision.hpp"
#include "recode/api/geometry.hpp"

namespace recode::python {

namespace {

// A number as Python writes it (repr of a float: the shortest that reads back).
std::string num(double x) {
  return py::repr(py::float_(x)).cast<std::string>();
}

std::string vec(const Eigen::Vector3d& v) {
  return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]";
}

std::string quoted(const std::string& s) {
  return py::repr(py::str(s)).cast<std::string>();
}

// Up to four block names, then how many more.
std::string blockNames(const CollisionGeometry& g) {
  if (g.isClosed())
    return quoted(g.closedMesh()->name());
  std::string out;
  const std::size_t shown = std::min<std::size_t>(g.blockCount(), 4);
  for (std::size_t i = 0; i < shown; ++i) {
    if (i > 0)
      out += ", ";
    out += quoted(g.part(i).block->name());
  }
  if (g.blockCount() > shown)
    out += ", ... (" + std::to_string(g.blockCount() - shown) + " more)";
  return out;
}

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string geometryRepr(const CollisionGeometry& g) {
  if (g.isClosed())
    return "<recode.CollisionGeometry closed mesh " + blockNames(g) + ">";
  return "<recode.CollisionGeometry " + plural(g.blockCount(), "block", "blocks") + ": " +
         blockNames(g) + ">";
}

// The pose as translation and the rotation's angle (degrees) about its axis.
std::string objectRepr(const CollisionObject& o) {
  const Eigen::Isometry3d& pose = o.transform();
  const Eigen::AngleAxisd turn(pose.linear());
  std::string out = "<recode.CollisionObject " + blockNames(o.geometry()) +
                    " at translation=" + vec(pose.translation());
  if (turn.angle() != 0.0)
    out += ", rotated " + num(turn.angle() * 180.0 / std::numbers::pi) + " deg about " +
           vec(turn.axis());
  return out + ">";
}

std::string frameRepr(const core::FrameSpec& f) {
  return "<recode.Frame axis=" + quoted(std::string(core::toString(f.axis))) + " " +
         std::to_string(f.width) + " x " + std::to_string(f.height) + " pixels of " +
         num((f.window.umax - f.window.umin) / f.width) + " over window=(" + num(f.window.umin) +
         ", " + num(f.window.vmin) + ", " + num(f.window.umax) + ", " + num(f.window.vmax) + ")>";
}

std::string contactRepr(const core::ContactRegion& c) {
  if (c.pixels == 0)
    return "<recode.ContactRegion empty>";
  std::string out = "<recode.ContactRegion " + std::to_string(c.pixels) +
                    " pixels, area=" + num(c.area) + ", max_depth=" + num(c.maxDepth);
  if (!c.box.isEmpty())
    out += ", box=[" + vec(c.box.min) + ", " + vec(c.box.max) + "]";
  if (c.normal)
    out += ", normal=" + vec(c.normal->normal) + ", penetration_depth=" + num(c.normal->depth);
  return out + ">";
}

std::string blockContactRepr(const BlockContact& c) {
  const raster::PixelRect& r = c.pair.mor;
  return "<recode.BlockContact blocks " + std::to_string(c.blockA) + ", " +
         std::to_string(c.blockB) + ": " + std::to_string(c.pair.interferingPixels) +
         " interfering pixels, axis " + std::string(core::toString(c.frame.axis)) + ", frame " +
         std::to_string(c.frame.width) + " x " + std::to_string(c.frame.height) + ", mor=(" +
         std::to_string(r.x0) + ", " + std::to_string(r.y0) + ", " + std::to_string(r.x1) + ", " +
         std::to_string(r.y1) + ")>";
}

// Through the Python API (len() and stats), so that whatever the binding wraps the C++ manager
// in, the repr reads it as Python does.
std::string managerRepr(const py::object& self) {
  const py::dict stats = self.attr("stats");
  return "<recode.CollisionManager " + plural(py::len(self), "object", "objects") +
         "; last collide(): " + py::str(stats["candidate_pairs"]).cast<std::string>() +
         " candidate pairs, " + py::str(stats["pairs_in_contact"]).cast<std::string>() +
         " in contact>";
}

template <class Self>
void setRepr(py::module_& m, const char* name, std::string (*repr)(Self)) {
  py::object cls = m.attr(name);
  // Only where the binding has none of its own: a repr bound there wins.
  if (py::hasattr(cls, "__dict__") && cls.attr("__dict__").contains("__repr__"))
    return;
  cls.attr("__repr__") = py::cpp_function(repr, py::name("__repr__"), py::is_method(cls));
}

}  // namespace

void bindReprs(py::module_& m) {
  setRepr(m, "CollisionGeometry", &geometryRepr);
  setRepr(m, "CollisionObject", &objectRepr);
  setRepr(m, "Frame", &frameRepr);
  setRepr(m, "ContactRegion", &contactRepr);
  setRepr(m, "BlockContact", &blockContactRepr);
  setRepr(m, "CollisionManager", &managerRepr);
}

}  // namespace recode::python
