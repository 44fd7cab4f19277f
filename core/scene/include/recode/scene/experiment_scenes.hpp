#pragma once
// The paper's experiment scenes, built in so that `recode run NAME` needs no files, and so
// that every algorithm (RECODE here, the peers in `recode bench`) runs the same motion. Each
// is made as scene JSON text and read by parseScene, so a built-in and the file
// `recode run NAME --write-scene FILE` writes are the same scene by construction; the
// defaults are in data/scenes/NAME.json, and a test holds those files equal to the built-ins.
// docs/scenes.md ("Built-in scenes") describes each one.
//
// Every scene is parameterised by the triangles per block (each convex block is tessellated
// to about that many triangles) and uses fixed seeds: the same name and triangle budget give
// the same scene on every machine.

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "recode/scene/scene.hpp"

namespace recode::core {

struct BuiltinSceneInfo {
  std::string_view name;
  std::string_view summary;
  int defaultTrianglesPerBlock;
};

// The built-in experiment scenes, in the order `recode run --list` shows them.
[[nodiscard]] std::span<const BuiltinSceneInfo> builtinExperimentScenes();

// The entry with this name, or nullptr.
[[nodiscard]] const BuiltinSceneInfo* findBuiltinExperimentScene(std::string_view name);

// Smallest and largest triangles per block accepted.
inline constexpr int kMinTrianglesPerBlock = 16;
inline constexpr int kMaxTrianglesPerBlock = 100000;

// The scene as JSON text (2-space indented, newline at the end). Throws std::invalid_argument
// for an unknown name (the message lists the built-ins) or a triangle budget outside
// kMinTrianglesPerBlock..kMaxTrianglesPerBlock.
[[nodiscard]] std::string builtinSceneJson(std::string_view name,
                                           std::optional<int> trianglesPerBlock = std::nullopt);

// The scene itself: parseScene(builtinSceneJson(name, ...)), named "built-in NAME".
[[nodiscard]] Scene builtinExperimentScene(std::string_view name,
                                           std::optional<int> trianglesPerBlock = std::nullopt);

}  // namespace recode::core
