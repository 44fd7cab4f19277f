#pragma once
// Shared helpers for the pair-algorithm suites: run collidePair on a fresh CpuDevice, build
// blocks placed exactly (no trigonometry in the placement), look up a pixel's case.

#include <Eigen/Geometry>
#include <cstdint>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"

namespace recode::test {

inline core::PairResult runPair(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                const core::FrameSpec& frame,
                                core::MorMode mor = core::MorMode::Min, bool contact = true,
                                bool boxTest = true) {
  raster::CpuDevice device(frame.width, frame.height);
  core::PairRequest request;
  request.frame = frame;
  request.mor = mor;
  request.contact = contact;
  request.boxTest = boxTest;
  return core::collidePair(device, a, b, request);
}

inline core::FrameSpec frameZ(double umin, double vmin, double umax, double vmax, int w, int h) {
  core::FrameSpec f;
  f.axis = core::ViewAxis::Z;
  f.window = {umin, vmin, umax, vmax};
  f.width = w;
  f.height = h;
  return f;
}

// An axis-aligned box with the given corners.
inline core::TriangleMesh boxBetween(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = 0.5 * (lo + hi);
  return core::transformed(core::makeBox(0.5 * (hi - lo)), t);
}

inline core::TriangleMesh moved(const core::TriangleMesh& m, const Eigen::Vector3d& offset) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = offset;
  return core::transformed(m, t);
}

// Turned upside down about the x axis (y -> -y, z -> -z, exactly), then moved.
inline core::TriangleMesh flippedAndMoved(const core::TriangleMesh& m,
                                          const Eigen::Vector3d& offset) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  t.translation() = offset;
  return core::transformed(m, t);
}

// The case of pixel (x, y); -1 when it lies outside the MOR.
inline int caseAt(const core::PairResult& r, int x, int y) {
  return r.caseMap.contains(x, y) ? r.caseMap.at(x, y) : -1;
}

}  // namespace recode::test
