#pragma once
// Scene-text parsing and error capture for the scene and simulation suites.

#include <string>

#include "core_test_support.hpp"
#include "recode/scene/scene.hpp"

namespace recode::core::test {

// Parses `text` as a scene file called `name`, with mesh paths relative to data/.
inline Scene parseSceneText(const std::string& text, const std::string& name) {
  return parseScene(text, name, dataFile(""));
}

// The message of the SceneError that parsing `text` as `name` throws ("" if it does not throw).
inline std::string sceneErrorOf(const std::string& text, const std::string& name) {
  try {
    (void)parseSceneText(text, name);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace recode::core::test
