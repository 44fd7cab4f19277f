#pragma once
// Helpers for the built-in experiment scenes (private to core): shapes tessellated to a
// triangle budget, tidy numbers, a portable seeded random source, and the JSON they are
// written in.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "recode/geometry/mesh.hpp"

namespace recode::core::detail {

using Json = nlohmann::ordered_json;

// A block: its "shape" object and the mesh the scene reader will make of it.
struct Block {
  Json shape;
  TriangleMesh mesh;
};

// Shapes with segments (and rings) chosen to give about `triangles` triangles.
[[nodiscard]] Block coneBlock(double radius, double height, int triangles);
[[nodiscard]] Block cylinderBlock(double radius, double height, int triangles);
[[nodiscard]] Block ellipsoidBlock(double a, double b, double c, int triangles);
[[nodiscard]] Block sphereBlock(double radius, int triangles);
[[nodiscard]] Block cappedConeBlock(double r0, double r1, double height, int triangles);

// x rounded to `decimals` decimal places (as the nearest double to the decimal), so the
// written JSON reads 0.3, not 0.30000000000000004.
[[nodiscard]] double tidy(double x, int decimals = 6);

// [x, y, z] with each coordinate tidied.
[[nodiscard]] Json vec(double x, double y, double z, int decimals = 6);

// SplitMix64: the same numbers on every platform (the standard distributions are not).
class SceneRandom {
 public:
  explicit SceneRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  // Uniform in [lo, hi), tidied to 4 decimals.
  double uniform(double lo, double hi);

 private:
  std::uint64_t state_;
};

// The scene's JSON text as builtinSceneJson returns it.
[[nodiscard]] std::string sceneText(const Json& scene);

// The makers of the built-in scenes (one file each).
[[nodiscard]] Json makeCombScene(bool rotate, bool offset, int trianglesPerBlock);
[[nodiscard]] Json makeRandomScene(bool conesOnly, int trianglesPerBlock);
[[nodiscard]] Json makeHandGraspScene(int trianglesPerBlock);
[[nodiscard]] Json makeHierarchyNineScene(int trianglesPerBlock);

}  // namespace recode::core::detail
