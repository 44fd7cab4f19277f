// libFuzzer target: bytes through the PLY reader (our header check, then assimp's importer and
// our checks of what it read). assimp itself is not instrumented: a memory error inside it
// shows only if it crashes.
#include "mesh_fuzzer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  recode::fuzz::readMeshText(recode::fuzz::asText(data, size), ".ply");
  return 0;
}
