#pragma once
// The collision API's pairs with a closed mesh (docs/api.md, "Closed meshes"): which requests
// the layered pair can answer, and how its answer enters the API's result.

#include "recode/api/collision.hpp"

namespace recode::detail {

// Whether a and b are decided by the layered pair: either is a closed mesh.
[[nodiscard]] bool isLayeredPair(const CollisionObject& a, const CollisionObject& b);

// Throws std::invalid_argument, naming the objects and the rule, for what the layered pair
// cannot answer: a mode other than Reference (adaptive, conservative and skip-apart are built
// on RECODE's passes over convex blocks) and a compound of several blocks against a closed mesh
// (the layered pair takes one solid on each side).
void requireLayeredRequest(const CollisionObject& a, const CollisionObject& b,
                           const CollisionRequest& request);

// The fields of a layered answer that a core::PairResult has: verdict, MOR, pixels, contact
// region, pixels read, depth range and total time; no case counts, no case map.
[[nodiscard]] core::PairResult pairResultOf(const core::LayeredPairResult& layered);

}  // namespace recode::detail
