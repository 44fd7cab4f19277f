#pragma once
// Today's object-space collision libraries, each used the way its users would, as the bench's
// peers (docs/benchmarks.md, "The peers"). They stand where the paper's peers stood:
//   fcl-gjk     FCL 0.7: one fcl::Convex per block, GJK (libccd) -- I-COLLIDE's role
//   fcl-obbrss  FCL 0.7: one OBBRSS BVH triangle mesh per block, contacts on -- RAPID's role
//   bullet      Bullet 3.24: one btConvexHullShape per block, margin 0, a btCollisionWorld's
//               broad and narrow phase -- Q-COLLIDE's role
// Each is built only with RECODE_WITH_PEERS (RECODE_HAVE_PEERS=1); peersBuilt() says so at run
// time, and the factories throw std::runtime_error in a build without them.

#include <memory>
#include <vector>

#include "recode/sim/hierarchy.hpp"
#include "recode/verify/scene_detector.hpp"

namespace recode::verify {

[[nodiscard]] bool peersBuilt();

// Each makes the detector's shapes from every leaf's block (HierarchyNode::localMesh, in
// the leaf's own coordinates; the leaf's world transform places it). Only pairs of leaves of
// different objects are reported.
[[nodiscard]] std::unique_ptr<SceneDetector> makeFclGjkDetector(
    const std::vector<core::ObjectTree>& objects);
[[nodiscard]] std::unique_ptr<SceneDetector> makeFclObbrssDetector(
    const std::vector<core::ObjectTree>& objects);
[[nodiscard]] std::unique_ptr<SceneDetector> makeBulletDetector(
    const std::vector<core::ObjectTree>& objects);

// The exact judge ("cgal"): every leaf pair of different objects whose world AABBs overlap
// (touching counts) is decided by exactlyIntersect (cgal_oracle.hpp). Needs RECODE_HAVE_CGAL;
// throws std::runtime_error otherwise.
[[nodiscard]] std::unique_ptr<SceneDetector> makeExactDetector(
    const std::vector<core::ObjectTree>& objects);

}  // namespace recode::verify
