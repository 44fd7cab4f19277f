// libFuzzer target: Wavefront OBJ text through the OBJ reader (line checks, tinyobjloader,
// face triangulation).
#include "mesh_fuzzer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  recode::fuzz::readMeshText(recode::fuzz::asText(data, size), ".obj");
  return 0;
}
