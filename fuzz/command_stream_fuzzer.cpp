// libFuzzer target: golden-vector and command-stream JSON through both readers.
#include "fuzz_support.hpp"
#include "recode/raster/golden.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = recode::fuzz::asText(data, size);
  recode::fuzz::expectCleanErrors([&] { (void)recode::raster::goldenFromJson(text, "fuzz.json"); });
  recode::fuzz::expectCleanErrors(
      [&] { (void)recode::raster::commandStreamFromJson(text, "fuzz.json"); });
  return 0;
}
