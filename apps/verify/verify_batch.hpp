#pragma once
// `recode verify --gl-exact` and `--vulkan` also run every pair of the input as one batch
// (core::collidePairs, one device per frame size) on that device: the path `recode run`, the
// bench and the collision API take, where a frame's pair tests are recorded and run at once.
// Each batched result must be the CPU reference's result for the pair, field for field
// (core::firstDifference; timing aside).

#include <string>
#include <vector>

#include "recode/pair/pair.hpp"
#include "recode/sim/simulation.hpp"

namespace recode::app {

struct BatchCheck {
  long long pairs = 0;
  long long different = 0;     // pairs whose batched result is not the reference's
  std::string firstDifferent;  // "label: field: a vs b" of the first, if any
  long long submissions = 0;   // the device's, for the whole batch
  long long readbackBytes = 0;
  double seconds = 0.0;
  [[nodiscard]] bool passed() const { return different == 0; }
};

// One pair of the batch: its label, blocks, request and the CPU reference's result.
struct BatchPair {
  const std::string* label = nullptr;
  const core::TriangleMesh* a = nullptr;
  const core::TriangleMesh* b = nullptr;
  core::PairRequest request;
  const core::PairResult* reference = nullptr;
};

// Runs the pairs as one batch on devices made by `factory` and compares.
[[nodiscard]] BatchCheck checkBatch(const std::vector<BatchPair>& pairs,
                                    const core::DeviceFactory& factory);

}  // namespace recode::app
