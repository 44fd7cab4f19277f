// libFuzzer target: bytes through the STL reader (binary by size, else ASCII; exact welding).
#include "mesh_fuzzer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  recode::fuzz::readMeshText(recode::fuzz::asText(data, size), ".stl");
  return 0;
}
