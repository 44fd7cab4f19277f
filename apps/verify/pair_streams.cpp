#include "verify/pair_streams.hpp"

#include <cstdio>
#include <string>
#include <utility>

#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"
#include "recode/verify/exact_parity.hpp"

namespace recode::app {

std::size_t savePairStreams(const VerifyPairs& pairs, core::MorMode mor,
                            const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::size_t written = 0;
  for (const PairToVerify& pair : pairs.pairs) {
    core::PairRequest request;
    request.frame = pair.frame;
    request.mor = mor;
    // Recorded on the CPU device as the exact parity check records it: the commands in order,
    // then the buffers they leave as the expected ones.
    raster::CpuDevice cpu(pair.frame.width, pair.frame.height);
    verify::RecordedPair recorded = verify::recordPair(*pair.a, *pair.b, request, cpu);
    const raster::PixelRect all{0, 0, pair.frame.width, pair.frame.height};
    raster::GoldenVector golden{"recode verify --save-streams: " + pair.label,
                                std::move(recorded.stream), cpu.readDepth(all),
                                cpu.readStencil(all)};
    char name[32];
    std::snprintf(name, sizeof name, "pair-%03zu.json", written);
    raster::writeGolden(dir / name, golden, raster::GoldenLayout::Rows);
    ++written;
  }
  return written;
}

}  // namespace recode::app
