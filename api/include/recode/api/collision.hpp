#pragma once
// RECODE as a collision library, in the request -> result shape of FCL (docs/api.md):
//
//   auto cone = recode::CollisionGeometry::single(recode::ConvexBlock::fromMesh(mesh, "cone"));
//   recode::CollisionObject a(cone), b(cone);
//   b.setTransform(pose);
//   recode::CollisionResult result;
//   if (recode::collide(a, b, recode::CollisionRequest{}, result)) ... result.contact.box ...
//
// collide() descends the two objects' block trees (AABBs, then OBBs) to the block pairs whose
// boxes overlap and runs core::collidePair on each, in a frame it chooses from the two blocks'
// world boxes (chooseFrame below): the same algorithm, passes and contact region as
// `recode pair` and `recode run`, so the same frame gives the same result bit for bit. A pair
// with a closed mesh (ClosedMesh) on either side is decided by core::collideLayered in the same
// frame instead (CollisionResult::layered).

#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "recode/api/device_pool.hpp"
#include "recode/api/geometry.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/layered_pair.hpp"
#include "recode/pair/pair.hpp"
#include "recode/refine/pair_mode.hpp"
#include "recode/sim/hierarchy.hpp"

namespace recode {

// A shape at a pose. Cheap to move; copying copies the posed tree (the shape stays shared).
class CollisionObject {
 public:
  // Throws std::invalid_argument for a null geometry.
  explicit CollisionObject(CollisionGeometryPtr geometry,
                           const Eigen::Isometry3d& transform = Eigen::Isometry3d::Identity());

  // Object -> world. Updates the world boxes of every block at once.
  void setTransform(const Eigen::Isometry3d& transform);
  // The pose: object -> world.
  [[nodiscard]] const Eigen::Isometry3d& transform() const { return transform_; }

  // The shape, shared with other objects.
  [[nodiscard]] const CollisionGeometry& geometry() const { return *geometry_; }
  // The shape's shared pointer, to make another object of the same shape.
  [[nodiscard]] const CollisionGeometryPtr& geometryPtr() const { return geometry_; }
  // The world box of the whole object at its pose.
  [[nodiscard]] const core::Aabb& worldBox() const { return tree_.root().worldAabb; }
  // The posed tree (world AABBs and OBBs per node), as the descent reads it.
  [[nodiscard]] const core::ObjectTree& tree() const { return tree_; }
  // Block i in world coordinates at the current pose.
  [[nodiscard]] core::TriangleMesh worldBlock(std::size_t block) const;

 private:
  CollisionGeometryPtr geometry_;
  core::ObjectTree tree_;
  Eigen::Isometry3d transform_;
};

// The view axis: one of the world axes, or Auto: the axis along which the box where the two
// blocks' world AABBs overlap is thinnest (ties go to z, then x, then y). Looking across the
// thin side of the overlap puts its two larger sides on the image plane, so the most pixels
// fall on the region where the blocks can meet.
enum class AxisChoice { X, Y, Z, Auto };

// With a resolution, the most pixels across both blocks' boxes: a tiny overlap (tips meeting)
// would otherwise ask for a frame of millions of pixels a side.
inline constexpr double kMaxResolutionFrameSide = 2048.0;

// What collide() measures and how finely: the request half of the request -> result shape.
struct CollisionRequest {
  // Square pixels of this size, in world units. Without it, the pixel size is the longer side
  // of the overlap box on the image plane divided by `resolution` (the union of the two boxes'
  // when the overlap is flat on the image plane), but never finer than the longer side of the
  // union over kMaxResolutionFrameSide pixels.
  std::optional<double> pixelSize;
  int resolution = 256;                    // 1..16384, used without pixelSize
  core::MorMode mor = core::MorMode::Min;  // the rectangle the passes run over (core::MorMode)
  AxisChoice axis = AxisChoice::Auto;      // the view axis (AxisChoice)
  bool contact = true;                     // the two depth passes that measure the contact region
  // With `contact`: each block contact's pair.contact.normal, the contact normal and penetration
  // depth (core::PairRequest::normal). The merged CollisionResult::contact carries none.
  bool normal = false;
  // How each block pair is decided (docs/algorithm.md, "Beyond the paper"): Reference, the
  // paper's algorithm in the chosen frame; Adaptive, refined on finer frames where a finer grid
  // could change the answer (a contact's `pair` and `frame` are those of the run that saw it);
  // Conservative, both blocks grown by a pixel across and 4 depth steps along the view, so no
  // contact is missed (the `pair` is that of the grown blocks).
  core::PairMode mode = core::PairMode::Reference;
  // Threads the block pairs of a call may be decided on when they are drawn on CPU devices (a
  // DevicePool without a factory; oneTBB, as `recode run --threads`): 1, the default, decides
  // them in turn on the caller's thread; 0 on every hardware thread; N on at most N. The results
  // are the same whatever the count; only times differ. A pool with a factory (a GPU device)
  // draws on the caller's thread.
  int threads = 1;
};

// One pair of blocks whose pixels interfere.
struct BlockContact {
  std::size_t blockA = 0;  // block index in the first object's geometry
  std::size_t blockB = 0;  // and in the second's
  core::FrameSpec frame;   // the frame it was drawn in
  core::PairResult pair;   // collidePair's result (its case map kept)
  // Adaptive mode: the refinement level the contact was seen at (0: the chosen frame).
  int refineLevel = 0;
  // Decided by the layered pair (a closed mesh took part): `pair` then holds its verdict,
  // MOR, pixels, contact region and times, and no case counts or case map (those are RECODE's
  // passes'); CollisionResult::layered has the rest.
  bool layered = false;
};

// What the layered pair found for two objects of which one or both are closed meshes.
struct LayeredPair {
  core::FrameSpec frame;           // the frame it was drawn in (width 0: the boxes missed)
  core::LayeredPairResult result;  // core::collideLayered's result (per-pixel overlap kept)
};

// What collide() found for two objects: the verdict, the contact region over all their block
// pairs, each block pair in contact, and the cost.
struct CollisionResult {
  bool collide = false;             // some pair of blocks interferes
  long long interferingPixels = 0;  // summed over the block pairs
  // The union over the block pairs: all points, the box around their boxes, the summed area
  // and pixels, the greatest depth. Empty without contact (or with request.contact off: then
  // only pixels and area are known).
  core::ContactRegion contact;
  std::vector<BlockContact> contacts;  // the block pairs in contact, by (blockA, blockB)
  long long boxTests = 0;              // node pairs whose boxes the descent tested
  long long blockPairsDrawn = 0;       // block pairs given to collidePair
  long long blockPairsSkipped = 0;     // skip-apart mode: block pairs proven apart, not drawn
  double collisionUs = 0.0;            // the whole call, device making left out
  double deviceSetupUs = 0.0;          // making devices for sizes not seen before
  // Adaptive mode: block pairs left apart_at_limit (a contact could not be ruled out within the
  // refinement limits; they are not contacts).
  long long apartAtLimit = 0;
  // Set whenever either object is a closed mesh: the layered pair's overlap volume,
  // containment, layers, passes and per-pixel overlap (docs/algorithm.md section 13). When the
  // objects' boxes do not meet, nothing is drawn and it holds an empty result (no frame).
  std::optional<LayeredPair> layered;

  // Back to a default result (collide() clears the result it is given).
  void clear() { *this = CollisionResult{}; }
};

// The frame a pair of blocks with these world boxes is drawn in: the axis and pixel size the
// request gives (see above), then core::granularPairFrame, the frame `recode run` draws a
// leaf pair in. Throws std::invalid_argument for a resolution outside 1..16384 or a frame over
// 16384 pixels a side (the message of core::frameFromPixelSize).
[[nodiscard]] core::FrameSpec chooseFrame(const core::Aabb& a, const core::Aabb& b,
                                          const CollisionRequest& request);

// Collides two objects: fills `result` (cleared first) and returns result.collide. Draws on
// raster::CpuDevices kept per thread. Throws std::invalid_argument as chooseFrame and
// core::collidePair do, and, for a pair with a closed mesh, as core::collideLayered does, for a
// mode other than Reference (the other modes are RECODE's passes') and for a closed mesh
// against a compound of several blocks (the layered pair takes one solid on each side).
bool collide(const CollisionObject& a, const CollisionObject& b, const CollisionRequest& request,
             CollisionResult& result);
// The same, drawing on the pool's devices (the seam for a device of your own).
bool collide(const CollisionObject& a, const CollisionObject& b, const CollisionRequest& request,
             CollisionResult& result, DevicePool& devices);

}  // namespace recode
