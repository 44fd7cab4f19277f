// libFuzzer target: scene JSON text through the scene reader (the JSON layer, every schema
// section, shapes and generators; mesh references resolve under a folder that does not exist).
// Scenes are held to 2^12 triangles, so that each input costs milliseconds: the budget's own
// refusal is part of what is fuzzed, and the default limit differs only in its value.
#include "fuzz_support.hpp"
#include "recode/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  recode::fuzz::expectCleanErrors([&] {
    (void)recode::core::parseScene(recode::fuzz::asText(data, size), "fuzz.json",
                                   "/nonexistent-recode-fuzz",
                                   recode::core::SceneReadLimits{std::size_t{1} << 12});
  });
  return 0;
}
