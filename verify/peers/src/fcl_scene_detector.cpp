// The FCL peers' common frame: pose, broad phase, narrow phase (fcl_scene_detector.hpp).
#include "fcl_scene_detector.hpp"

#include <chrono>
#include <utility>

namespace recode::verify {

namespace {

// What the broad phase's callback needs; FCL passes it through as void*.
struct CallbackState {
  const fcl::CollisionRequestd* request = nullptr;
  std::vector<LeafPairId> pairs;
};

const LeafRef& leafOf(const fcl::CollisionObjectd* shape) {
  return *static_cast<const LeafRef*>(shape->getUserData());
}

// Called by the broad phase for each pair of shapes whose AABBs overlap. Returns false: never
// stop early, every colliding pair is wanted.
bool collideCandidate(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data) {
  const LeafRef& leafA = leafOf(a);
  const LeafRef& leafB = leafOf(b);
  // Blocks of one object are one body: no narrow phase for them, as in RECODE.
  if (leafA.object == leafB.object)
    return false;
  auto& state = *static_cast<CallbackState*>(data);
  fcl::CollisionResultd result;
  fcl::collide(a, b, *state.request, result);
  if (result.isCollision())
    state.pairs.push_back(orderedPair(leafA, leafB));
  return false;
}

}  // namespace

FclSceneDetector::FclSceneDetector(std::string name, const std::vector<core::ObjectTree>& objects,
                                   const GeometryMaker& makeGeometry,
                                   fcl::CollisionRequestd request)
    : name_(std::move(name)), leaves_(objects), request_(request) {
  std::vector<fcl::CollisionObjectd*> registered;
  for (const LeafRef& leaf : leaves_.all()) {
    const core::HierarchyNode& node = SceneLeaves::node(objects, leaf);
    auto shape = std::make_unique<fcl::CollisionObjectd>(makeGeometry(node.localMesh), node.world);
    // The LeafRef lives in leaves_, which never changes after construction.
    shape->setUserData(const_cast<LeafRef*>(&leaf));
    registered.push_back(shape.get());
    shapes_.push_back(std::move(shape));
  }
  manager_.registerObjects(registered);
  manager_.setup();
}

Detection FclSceneDetector::detect(const std::vector<core::ObjectTree>& objects, int /*frame*/) {
  leaves_.checkSameShape(objects);
  CallbackState state;
  state.request = &request_;

  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < shapes_.size(); ++i) {
    shapes_[i]->setTransform(SceneLeaves::node(objects, leaves_[static_cast<int>(i)]).world);
    shapes_[i]->computeAABB();
  }
  manager_.update();
  manager_.collide(&state, collideCandidate);
  return finishDetection(std::move(state.pairs), start);
}

}  // namespace recode::verify
