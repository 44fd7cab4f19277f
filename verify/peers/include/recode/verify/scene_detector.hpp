#pragma once
// The bench's view of a collision detector (`recode bench`, docs/benchmarks.md). Every
// algorithm -- RECODE on the CPU or the GL device, the FCL and Bullet peers, and CGAL as the
// exact judge -- is made from the same object trees, is handed them posed at each frame, and
// answers with the leaf pairs it finds colliding. So all of them follow one motion path, and
// their answers can be compared pair by pair. No FCL, Bullet or CGAL type appears here.

#include <compare>
#include <string>
#include <vector>

#include "recode/sim/hierarchy.hpp"

namespace recode::verify {

// A pair of convex blocks (leaves) of two different objects.
struct LeafPairId {
  int objectA = 0;  // index into the scene's objects; objectA < objectB
  int leafA = 0;    // node index of a leaf in objectA's tree (ObjectTree::nodes())
  int objectB = 0;
  int leafB = 0;
  friend auto operator<=>(const LeafPairId&, const LeafPairId&) = default;
};

struct Detection {
  std::vector<LeafPairId> pairs;  // the colliding leaf pairs, sorted, without repeats
  double collisionUs = 0.0;       // the detector's own work for the frame, see detect()
};

class SceneDetector {
 public:
  virtual ~SceneDetector() = default;
  SceneDetector() = default;
  SceneDetector(const SceneDetector&) = delete;
  SceneDetector& operator=(const SceneDetector&) = delete;

  // The column name in the bench's CSV and plots, e.g. "recode-cpu", "fcl-gjk", "bullet".
  [[nodiscard]] virtual std::string name() const = 0;

  // The colliding leaf pairs at frame `frame`. `objects` are the trees the detector was made
  // from (same order, same nodes), each already at that frame (ObjectTree::setFrame: every
  // node's world transform is current; updateBounds may not have been called). collisionUs
  // is what a user of the detector pays per frame: handing it the new transforms, its broad
  // phase and its narrow phase; posing the trees is not included. A detector that owns its
  // own trees (RECODE's Simulation) may pose those instead, outside its timer.
  [[nodiscard]] virtual Detection detect(const std::vector<core::ObjectTree>& objects,
                                         int frame) = 0;
};

}  // namespace recode::verify
