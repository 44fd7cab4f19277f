// libFuzzer target: OFF text through the OFF reader.
#include "mesh_fuzzer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  recode::fuzz::readMeshText(recode::fuzz::asText(data, size), ".off");
  return 0;
}
