// Object trees: flattening, rigid OBBs fitted once, per-frame world boxes, and the descent of
// two trees to the leaf pairs whose boxes overlap.
#include "recode/sim/hierarchy.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "posed_vertex_box.hpp"

namespace recode::core {

namespace {

// Boxes are grown by this fraction of their size and position so that a parent's box,
// fitted to its children's corners in other coordinates, still contains them after rounding.
constexpr double kContainmentSlack = 1e-9;

Obb withSlack(const Obb& box) {
  const double scale = box.center.cwiseAbs().maxCoeff() + box.halfExtents.maxCoeff();
  return grown(box, kContainmentSlack * scale);
}

// The fields of a placement that move it, for the message of a pose that is not finite.
std::string motionFields(const Placement& placement) {
  std::string fields = "position, rotation_deg";
  if (placement.motion)
    fields += ", motion";
  if (!placement.keyframes.empty())
    fields += ", keyframes";
  if (placement.joint)
    fields += ", joint";
  return fields;
}

}  // namespace

ObjectTree::ObjectTree(const SceneObject& root) {
  add(root, -1, "");
  // Children come after their parent, so a reverse sweep sees every child before its parent.
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    HierarchyNode& node = nodes_[i];
    for (int c : node.children) {
      const HierarchyNode& child = nodes_[static_cast<std::size_t>(c)];
      if (!child.rigid || child.placement.moves())
        node.rigid = false;
    }
  }
  fitLocalBoxes();
  boundsAt_.assign(nodes_.size(), Eigen::Isometry3d::Identity());
  boundsValid_.assign(nodes_.size(), false);
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    hierarchies_.push_back(std::make_shared<LazyHierarchy>());
  pose(0);
}

int ObjectTree::add(const SceneObject& object, int parent, const std::string& parentPath) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  {
    HierarchyNode& node = nodes_.back();
    node.parent = parent;
    node.path = parent < 0 ? object.name : parentPath + "/" + object.name;
    node.placement = object;  // the Placement part of the scene object
    node.localMesh = object.localMesh;
    node.localExtent = drawableExtent(node.localMesh);
  }
  const std::string path = nodes_.back().path;
  if (object.isLeaf()) {
    if (object.localMesh.triangleCount() == 0)
      throw std::invalid_argument("object node \"" + path + "\" has no triangles");
    triangles_ += object.localMesh.triangleCount();
    leaves_.push_back(index);
    return index;
  }
  for (const SceneObject& child : object.children) {
    const int c = add(child, index, path);
    nodes_[static_cast<std::size_t>(index)].children.push_back(c);
  }
  return index;
}

void ObjectTree::fitLocalBoxes() {
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    HierarchyNode& node = nodes_[i];
    if (node.isLeaf()) {
      node.localObb = withSlack(fitObb(node.localMesh.vertices));
      continue;
    }
    if (!node.rigid)
      continue;
    // The children's boxes in this node's coordinates (their poses are constant).
    std::vector<Eigen::Vector3d> corners;
    for (int c : node.children) {
      const HierarchyNode& child = nodes_[static_cast<std::size_t>(c)];
      for (const Eigen::Vector3d& p :
           child.localObb.transformed(child.placement.poseAt(0)).corners())
        corners.push_back(p);
    }
    node.localObb = withSlack(fitObb(corners));
  }
}

void ObjectTree::setFrame(int frame) {
  for (HierarchyNode& node : nodes_) {
    const Eigen::Isometry3d local = node.placement.poseAt(frame);
    // A scene file's ranges (scene.hpp) keep poses finite; a Placement built in code has no
    // such check, and a NaN pose would silently report no contact, so stop here instead.
    if (!local.matrix().allFinite())
      throw std::domain_error(node.path + ": the pose at frame " + std::to_string(frame) +
                              " is not finite (its " + motionFields(node.placement) +
                              " overflow a double)");
    node.world =
        node.parent < 0 ? local : nodes_[static_cast<std::size_t>(node.parent)].world * local;
  }
}

void ObjectTree::setFrame(int frame, const Eigen::Isometry3d& base) {
  // Kept apart from setFrame(frame) so that a scene's poses stay exactly what they were (no
  // product with an identity that could turn a -0 into +0).
  for (HierarchyNode& node : nodes_) {
    const Eigen::Isometry3d local = node.placement.poseAt(frame);
    const Eigen::Isometry3d& parent =
        node.parent < 0 ? base : nodes_[static_cast<std::size_t>(node.parent)].world;
    node.world = parent * local;
  }
}

void ObjectTree::updateBounds() {
  updateObbs();
  updateAabbs();
}

void ObjectTree::updateObbs() {
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    HierarchyNode& node = nodes_[i];
    if (node.isLeaf() || node.rigid) {
      node.worldObb = node.localObb.transformed(node.world);
      continue;
    }
    Aabb around;
    for (int c : node.children)
      around.extend(nodes_[static_cast<std::size_t>(c)].worldObb.aabb());
    Obb axisBox;
    axisBox.center = around.center();
    axisBox.halfExtents = 0.5 * around.extent();
    node.worldObb = withSlack(axisBox);
  }
}

void ObjectTree::updateAabbs() {
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    HierarchyNode& node = nodes_[i];
    if (node.isLeaf()) {
      if (!boundsValid_[i] || boundsAt_[i].matrix() != node.world.matrix()) {
        // The same arithmetic as transformed(), so the box is exactly worldMesh()'s box.
        node.worldAabb = detail::posedVertexBox(node.localMesh.vertices, node.world.linear(),
                                                node.world.translation());
        boundsAt_[i] = node.world;
        boundsValid_[i] = true;
      }
      continue;
    }
    Aabb box;
    for (int c : node.children)
      box.extend(nodes_[static_cast<std::size_t>(c)].worldAabb);
    node.worldAabb = box;
  }
}

bool ObjectTree::leafBoxStale(int node) const {
  const auto i = static_cast<std::size_t>(node);
  const HierarchyNode& n = nodes_.at(i);
  return n.isLeaf() && (!boundsValid_[i] || boundsAt_[i].matrix() != n.world.matrix());
}

void ObjectTree::setLeafBox(int node, const Aabb& box) {
  const auto i = static_cast<std::size_t>(node);
  HierarchyNode& n = nodes_.at(i);
  if (!n.isLeaf())
    throw std::invalid_argument("setLeafBox: node " + std::to_string(node) + " is not a leaf");
  n.worldAabb = box;
  boundsAt_[i] = n.world;
  boundsValid_[i] = true;
}

const Aabb* ObjectTree::currentLeafBox(int node) const {
  const auto i = static_cast<std::size_t>(node);
  const HierarchyNode& n = nodes_.at(i);
  // Bit for bit: a box made at a pose with +0 where this one has -0 may differ in a zero's sign.
  if (!n.isLeaf() || !boundsValid_[i] ||
      std::memcmp(boundsAt_[i].matrix().data(), n.world.matrix().data(), sizeof(double) * 16) != 0)
    return nullptr;
  return &n.worldAabb;
}

Aabb ObjectTree::boxAroundObb() const {
  // The root's OBB holds every vertex up to the rounding of the fits and the transforms, which
  // is far below a relative 1e-9 of the box's world coordinates.
  Aabb box = root().worldObb.aabb();
  const double margin = 1e-9 * (box.center().cwiseAbs().maxCoeff() + 0.5 * box.extent().maxCoeff());
  box.min.array() -= margin;
  box.max.array() += margin;
  return box;
}

TriangleMesh ObjectTree::worldMesh(int node) const {
  const HierarchyNode& n = nodes_.at(static_cast<std::size_t>(node));
  return transformed(n.localMesh, n.world);
}

std::shared_ptr<const TriangleBvh> ObjectTree::triangleHierarchy(int node) const {
  const HierarchyNode& n = nodes_.at(static_cast<std::size_t>(node));
  LazyHierarchy& lazy = *hierarchies_[static_cast<std::size_t>(node)];
  std::call_once(lazy.built,
                 [&] { lazy.hierarchy = std::make_shared<const TriangleBvh>(n.localMesh); });
  return lazy.hierarchy;
}

std::shared_ptr<const ObjectSpaceMesh> ObjectTree::objectSpaceMesh(int node) const {
  const HierarchyNode& n = nodes_.at(static_cast<std::size_t>(node));
  LazyHierarchy& lazy = *hierarchies_[static_cast<std::size_t>(node)];
  std::call_once(lazy.flattened,
                 [&] { lazy.objectSpace = std::make_shared<const ObjectSpaceMesh>(n.localMesh); });
  return lazy.objectSpace;
}

bool nodeBoxesOverlap(const HierarchyNode& a, const HierarchyNode& b) {
  return aabbsOverlap(a.worldAabb, b.worldAabb) && obbsOverlap(a.worldObb, b.worldObb);
}

long long descendPair(const ObjectTree& a, const ObjectTree& b, std::vector<LeafPair>& out,
                      std::size_t maxLeafPairs) {
  const std::size_t first = out.size();
  long long tests = 0;
  std::vector<std::pair<int, int>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const HierarchyNode& na = a.nodes()[static_cast<std::size_t>(i)];
    const HierarchyNode& nb = b.nodes()[static_cast<std::size_t>(j)];
    ++tests;
    if (!nodeBoxesOverlap(na, nb))
      continue;
    if (na.isLeaf() && nb.isLeaf()) {
      out.push_back({i, j});
      if (out.size() - first >= maxLeafPairs)
        return tests;
      continue;
    }
    // Split the node that is not a leaf; of two inner nodes the one with the larger box.
    const bool splitA =
        !na.isLeaf() && (nb.isLeaf() || na.worldAabb.diagonal() >= nb.worldAabb.diagonal());
    if (splitA) {
      for (int c : na.children)
        stack.emplace_back(c, j);
    } else {
      for (int c : nb.children)
        stack.emplace_back(i, c);
    }
  }
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
            [](const LeafPair& x, const LeafPair& y) {
              return std::pair(x.leafA, x.leafB) < std::pair(y.leafA, y.leafB);
            });
  return tests;
}

}  // namespace recode::core
