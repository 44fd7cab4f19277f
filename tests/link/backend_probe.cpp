// What a back-end author writes first: two generated cones tip to tip, RECODE on the CPU
// reference device, the verdict. Built by a project that has only raster, geometry and pair.
#include <cstdio>

#include "recode/geometry/generators.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"

int main() {
  using namespace recode;
  core::TriangleMesh a = core::makeCone(1.0, 2.0, 16);
  core::TriangleMesh b = core::makeCone(1.0, 2.0, 16);
  // a points up from z = -1.9 to 0.1, b down from z = 1.9 to -0.1: the tips overlap by 0.2.
  a = core::transformed(a, Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, -1.9)));
  Eigen::Isometry3d flip = Eigen::Isometry3d::Identity();
  flip.linear() = Eigen::AngleAxisd(3.14159265358979323846, Eigen::Vector3d::UnitX()).matrix();
  flip.translation() = Eigen::Vector3d(0.0, 0.0, 1.9);
  b = core::transformed(b, flip);

  core::ViewSpec view;
  view.axis = core::ViewAxis::X;
  core::Aabb bounds = core::boundingBox(a);
  bounds.extend(core::boundingBox(b));
  core::PairRequest request;
  request.frame = core::resolveFrame(view, bounds, {128, std::nullopt, std::nullopt});
  raster::CpuDevice device(request.frame.width, request.frame.height);
  const core::PairResult result = core::collidePair(device, a, b, request);
  std::printf("collide: %s, interfering pixels: %lld\n", result.collide ? "yes" : "no",
              result.interferingPixels);
  return result.collide && result.interferingPixels > 0 ? 0 : 1;
}
