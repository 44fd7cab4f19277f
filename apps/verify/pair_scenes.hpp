#pragma once
// `recode verify [SCENE | --suite] --save-scenes DIR`: each pair verify would check (a scene's
// block pairs, or the generated suite's) as a scene file that `recode pair` reads (its two
// blocks as OFF meshes beside it, the pair's frame as the scene's view), so that another build
// of the reference (the WebAssembly module, a user's own) can be run on the very same pairs.

#include <cstddef>
#include <filesystem>

#include "verify/verify_pairs.hpp"

namespace recode::app {

// Writes pair-NNN.json, pair-NNN-a.off and pair-NNN-b.off (NNN from 000) for every pair into
// `dir` (created if missing), coordinates in the shortest text that reads back as the same
// double. Returns the number of scenes written; throws std::runtime_error naming a file that
// cannot be written.
std::size_t savePairScenes(const VerifyPairs& pairs, const std::filesystem::path& dir);

}  // namespace recode::app
