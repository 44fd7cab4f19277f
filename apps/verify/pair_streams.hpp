#pragma once
// `recode verify [SCENE | --suite] --save-streams DIR`: the command stream RECODE sends for each
// pair verify would check, with the buffers the CPU device leaves, as a golden vector file
// (docs/rasterization.md, section 8), so that a back end can replay the very commands of the
// pair suite (the WebGPU check does) and be compared bit for bit.

#include <cstddef>
#include <filesystem>

#include "recode/pair/pair.hpp"
#include "verify/verify_pairs.hpp"

namespace recode::app {

// Writes DIR/pair-NNN.json (NNN from 000; DIR created if missing) for every pair, the pair drawn
// in its frame with MOR mode `mor`. Returns the number written; throws std::runtime_error naming
// a file that cannot be written.
std::size_t savePairStreams(const VerifyPairs& pairs, core::MorMode mor,
                            const std::filesystem::path& dir);

}  // namespace recode::app
