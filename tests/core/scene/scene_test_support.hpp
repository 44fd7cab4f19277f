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

// Parses a scene called "s.json"; the message of the error it throws ("" if none).
inline Scene parse(const std::string& text) {
  return parseSceneText(text, "s.json");
}
inline std::string errorOf(const std::string& text) {
  return sceneErrorOf(text, "s.json");
}

// A scene with one object whose members are `objectBody` (JSON members, without braces).
inline std::string oneObject(const std::string& objectBody) {
  return R"({"objects": [{)" + objectBody + "}]}";
}

// A scene with one object of the given shape (the shape object's members, without braces).
inline std::string oneShape(const std::string& shapeBody) {
  return oneObject(R"("shape": {)" + shapeBody + "}");
}

}  // namespace recode::core::test
