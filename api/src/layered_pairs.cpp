// Pairs with a closed mesh in the collision API: the requests refused, the answer converted.
#include "layered_pairs.hpp"

#include <stdexcept>
#include <string>

namespace recode::detail {

namespace {

std::string describe(const CollisionObject& o) {
  const CollisionGeometry& g = o.geometry();
  if (g.isClosed())
    return "closed mesh '" + g.name() + "'";
  if (g.blockCount() == 1)
    return "convex block '" + g.name() + "'";
  return "compound '" + g.name() + "' of " + std::to_string(g.blockCount()) + " blocks";
}

}  // namespace

bool isLayeredPair(const CollisionObject& a, const CollisionObject& b) {
  return a.geometry().isClosed() || b.geometry().isClosed();
}

void requireLayeredRequest(const CollisionObject& a, const CollisionObject& b,
                           const CollisionRequest& request) {
  const std::string pair = "the pair of " + describe(a) + " and " + describe(b);
  if (request.mode != core::PairMode::Reference)
    throw std::invalid_argument(
        "CollisionRequest::mode " + std::string(core::toString(request.mode)) +
        " applies to pairs of convex blocks: " + pair +
        " has a closed mesh, decided by the layered pair (docs/algorithm.md section 13), which "
        "runs in the reference mode only");
  if (a.geometry().blockCount() > 1 || b.geometry().blockCount() > 1)
    throw std::invalid_argument(
        pair +
        ": the layered pair takes one solid on each side (a convex block or a closed "
        "mesh); collide the compound's blocks one by one, or make it one closed mesh");
}

core::PairResult pairResultOf(const core::LayeredPairResult& layered) {
  core::PairResult p;
  p.collide = layered.collide;
  p.boxesOverlap = layered.boxesOverlap;
  p.mor = layered.mor;
  p.interferingPixels = layered.interferingPixels;
  p.contactRect = layered.contactRect;
  p.contact = layered.contact;
  p.stencilPixelsRead = layered.stencilPixelsRead;
  p.depthPixelsRead = layered.depthPixelsRead;
  p.depthMin = layered.depthMin;
  p.depthMax = layered.depthMax;
  p.timing.totalUs = layered.timing.totalUs;
  return p;
}

}  // namespace recode::detail
