#pragma once
// The output of `recode pair` for a pair with a closed mesh (docs/cli.md, "Closed meshes"): the
// layered pair's JSON object and report.

#include <nlohmann/json.hpp>
#include <ostream>

#include "pair/pair_setup.hpp"
#include "recode/pair/layered_pair.hpp"

namespace recode::explain {

// The object printed by `recode pair --json` when either object is a closed mesh.
[[nodiscard]] nlohmann::ordered_json layeredResultToJson(const PairSetup& setup,
                                                         const core::PairRequest& request,
                                                         const core::LayeredPairResult& result);

// The human-readable report; `picture` adds a character picture of the MOR's interference.
void printLayeredReport(std::ostream& out, const PairSetup& setup, const core::PairRequest& request,
                        const core::LayeredPairResult& result, bool picture);

}  // namespace recode::explain
