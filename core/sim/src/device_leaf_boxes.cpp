#include "device_leaf_boxes.hpp"

#include <memory>
#include <utility>

#include "posed_vertex_box.hpp"

namespace recode::core::detail {

void reduceLeafBoxes(std::vector<ObjectTree>& objects, const std::vector<std::size_t>& which,
                     raster::DepthStencilDevice& device, raster::PosedBoxReducer& reducer) {
  struct Leaf {
    std::size_t object;
    int node;
    std::shared_ptr<const ObjectSpaceMesh> mesh;  // held until the boxes are back
  };
  std::vector<Leaf> leaves;
  std::vector<raster::PosedMesh> meshes;
  for (const std::size_t o : which) {
    const ObjectTree& tree = objects[o];
    for (const int leaf : tree.leaves()) {
      if (!tree.leafBoxStale(leaf))
        continue;
      const HierarchyNode& node = tree.nodes()[static_cast<std::size_t>(leaf)];
      std::shared_ptr<const ObjectSpaceMesh> mesh = tree.objectSpaceMesh(leaf);
      raster::PosedMesh posed{mesh->xyz, mesh->indices, {}, mesh->key, mesh};
      posed.transform.pose = rasterPose(node.world.linear(), node.world.translation());
      meshes.push_back(std::move(posed));
      leaves.push_back({o, leaf, std::move(mesh)});
    }
  }
  if (leaves.empty())
    return;
  raster::PendingRead<raster::PosedBox> read = reducer.posedBoxesLater(meshes);
  device.finish();
  const std::vector<raster::PosedBox> boxes = read.take();
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    ObjectTree& tree = objects[leaves[i].object];
    const HierarchyNode& node = tree.nodes()[static_cast<std::size_t>(leaves[i].node)];
    Aabb box;
    if (boxes[i].orderMatters) {
      box = posedVertexBoxScalar(node.localMesh.vertices, node.world.linear(),
                                 node.world.translation());
    } else {
      box.min = {boxes[i].min[0], boxes[i].min[1], boxes[i].min[2]};
      box.max = {boxes[i].max[0], boxes[i].max[1], boxes[i].max[2]};
    }
    tree.setLeafBox(leaves[i].node, box);
  }
}

void keepLeafMeshes(const std::vector<ObjectTree>& objects, raster::DepthStencilDevice& device,
                    raster::PosedBoxReducer& reducer) {
  std::vector<std::shared_ptr<const ObjectSpaceMesh>> held;
  std::vector<raster::PosedMesh> meshes;
  for (const ObjectTree& tree : objects) {
    for (const int leaf : tree.leaves()) {
      held.push_back(tree.objectSpaceMesh(leaf));
      const ObjectSpaceMesh& mesh = *held.back();
      meshes.push_back({mesh.xyz, mesh.indices, {}, mesh.key, held.back()});
    }
  }
  if (meshes.empty())
    return;
  raster::PendingRead<raster::PosedBox> read = reducer.posedBoxesLater(meshes);
  device.finish();
  (void)read.take();
}

}  // namespace recode::core::detail
