// The compute device's posed draws (TriangleSource::posedMesh): the vertex stage of
// docs/rasterization.md section 2.1 run on the device must give the window vertices of
// raster::vertexStage bit for bit, so a posed draw writes what drawing allTriangles() on the CPU
// device writes; a block's object-space mesh stays on the device while the block lives and no
// longer. Runs on whatever Vulkan driver the loader finds (lavapipe here).

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "compute_device_test_support.hpp"
#include "recode/backends/vulkan_compute_device.hpp"
#include "recode/kit/vertex_stage_vectors.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/posed_boxes.hpp"
#include "recode/raster/triangle_source.hpp"
#include "recode/raster/vertex_stage.hpp"

using namespace recode;
using backends::VulkanComputeDevice;
using raster::CompareFunc;
using raster::Face;
using raster::PixelRect;
using raster::StencilOp;
using raster::VertexTransform;
using raster::WindowVertex;
using test::countingState;
using test::expectSameBuffers;

namespace {

// A block's object-space mesh, as a PairBlock's ObjectSpaceMesh holds it.
struct LocalMesh {
  std::vector<double> xyz;
  std::vector<std::uint32_t> indices;
  std::uint64_t key = raster::newTriangleSourceKey();
};

// A posed block: the mesh, one pose and view, and allTriangles() made by the reference's vertex
// stage. Every vertex must map inside the window's range (the promise posedMesh makes).
class PosedSource final : public raster::TriangleSource {
 public:
  PosedSource(std::shared_ptr<const LocalMesh> mesh, const VertexTransform& transform)
      : mesh_(std::move(mesh)), transform_(transform) {
    for (std::size_t i = 0; i + 2 < mesh_->xyz.size(); i += 3) {
      const std::array<double, 3> p{mesh_->xyz[i], mesh_->xyz[i + 1], mesh_->xyz[i + 2]};
      const raster::WindowPosition w =
          raster::mapToWindow(transform.window, raster::poseVertex(transform.pose, p));
      REQUIRE(raster::drawablePosition(w));
      windows_.push_back(raster::snapPosition(w));
    }
  }
  [[nodiscard]] raster::TriangleDraw allTriangles() const override {
    return {windows_, mesh_->indices};
  }
  [[nodiscard]] std::uint64_t contentKey() const override { return key_; }
  [[nodiscard]] std::optional<raster::PosedMesh> posedMesh() const override {
    return raster::PosedMesh{mesh_->xyz, mesh_->indices, transform_, mesh_->key, mesh_};
  }
  [[nodiscard]] const std::vector<WindowVertex>& windows() const { return windows_; }

 private:
  std::shared_ptr<const LocalMesh> mesh_;
  VertexTransform transform_;
  std::vector<WindowVertex> windows_;
  std::uint64_t key_ = raster::newTriangleSourceKey();
};

// `triangles` random triangles in the box [-1, 1]^3, each its own three vertices.
std::shared_ptr<LocalMesh> randomMesh(std::mt19937& rng, int triangles) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto mesh = std::make_shared<LocalMesh>();
  for (int t = 0; t < 3 * triangles; ++t) {
    mesh->xyz.insert(mesh->xyz.end(), {u(rng), u(rng), u(rng)});
    mesh->indices.push_back(static_cast<std::uint32_t>(t));
  }
  return mesh;
}

// A random rotation (a unit quaternion's matrix, row by row) and translation.
raster::Pose randomPose(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  double q[4] = {n(rng), n(rng), n(rng), n(rng)};
  const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q)
    c /= len;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  raster::Pose pose;
  pose.linear = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                 2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                 2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
  std::uniform_real_distribution<double> t(-0.3, 0.3);
  pose.translation = {t(rng), t(rng), t(rng)};
  return pose;
}

// A view along world axis `axis` whose window [-2.1, 2.3] x [-1.9, 2.2] covers the posed mesh
// on a width x height frame, and whose depth range [-2.5, 2.5] holds it.
raster::WindowMapping viewAlong(int axis, int width, int height) {
  raster::WindowMapping m;
  m.axes = {(axis + 1) % 3, (axis + 2) % 3, axis};
  m.umin = -2.1;
  m.urange = 2.3 - -2.1;
  m.width = width;
  m.vmin = -1.9;
  m.vrange = 2.2 - -1.9;
  m.height = height;
  m.depthMax = 2.5;
  m.depthRange = 2.5 - -2.5;
  return m;
}

std::uint32_t bitsOf(float f) {
  std::uint32_t b = 0;
  std::memcpy(&b, &f, sizeof b);
  return b;
}

std::uint64_t bitsOf(double d) {
  std::uint64_t b = 0;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

}  // namespace

TEST_CASE("a posed draw writes what the window vertices of the reference's vertex stage write",
          "[vulkan-compute]") {
  std::mt19937 rng(50);
  constexpr int kWidth = 96, kHeight = 80;
  VulkanComputeDevice device(kWidth, kHeight);
  raster::CpuDevice reference(kWidth, kHeight);
  countingState(device);
  countingState(reference);
  // Along each axis, three poses of two meshes, with the scissor and culling changing between
  // draws: each draw's stencil counts show every fragment of it.
  for (int axis = 0; axis < 3; ++axis) {
    const std::shared_ptr<LocalMesh> meshes[2] = {randomMesh(rng, 60), randomMesh(rng, 25)};
    for (int round = 0; round < 3; ++round) {
      const PixelRect scissor = round == 1 ? PixelRect{5, 3, 71, 77} : PixelRect{0, 0, 96, 80};
      const raster::CullMode cull = round == 2 ? raster::CullMode::Back : raster::CullMode::None;
      for (const auto& mesh : meshes) {
        const PosedSource source(mesh, {randomPose(rng), viewAlong(axis, kWidth, kHeight)});
        for (raster::DepthStencilDevice* d :
             {static_cast<raster::DepthStencilDevice*>(&device),
              static_cast<raster::DepthStencilDevice*>(&reference)}) {
          d->setScissor(scissor);
          d->setCullMode(cull);
          d->drawMesh(source);
        }
      }
    }
  }
  expectSameBuffers(device, reference);
  const VulkanComputeDevice::MeshCounters counters = device.meshCounters();
  CHECK(counters.posedDraws == 18);
  CHECK(counters.uploads == 6);  // each mesh once, whatever its poses
}

TEST_CASE(
    "the device's vertex stage rounds as the reference's: snap ties, signed zeros, float "
    "ties and denormal depths",
    "[vulkan-compute]") {
  // A window of 256 world units onto 256 pixels: x = u exactly, so
  // coordinates k/256 + 1/512 sit halfway between two snapped positions. Depth z = -d exactly
  // (depthMax 0, range 1): halfway between two floats, or below the smallest normal float.
  raster::WindowMapping m;
  m.umin = 0.0;
  m.urange = 256.0;
  m.width = 256.0;
  m.vmin = 0.0;
  m.vrange = 256.0;
  m.height = 256.0;
  m.depthMax = 0.0;
  m.depthRange = 1.0;
  const double tie = 1.0 / 512.0;
  const double floatTie = 0.75 + std::ldexp(1.0, -25);  // halfway between two floats near 0.75
  const double floatTieOdd = 0.75 + 3 * std::ldexp(1.0, -25);
  struct Case {
    double x, y, z;
  };
  const Case cases[] = {
      {10.0 + tie, 20.0 + 3 * tie, floatTie},  // ties to even: down, up
      {-0.0, -0.0, 0.5},                       // signed zeros (with the -0 translation)
      {-tie, tie, floatTieOdd},                // tiny values that snap to -0 and +0
      {100.0, 50.0, 1e-40},                    // a float denormal
      {200.0, 100.0, 3e-46},                   // below every float: 0
      {-300.0 - tie, 250.5, 1e-300},           // a double far below float
  };
  auto mesh = std::make_shared<LocalMesh>();
  // Each case the first vertex of a large triangle whose other corners are fixed, so that the
  // set-up stage shows its snapped position and its z (DrawStages).
  for (const Case& c : cases) {
    const auto first = static_cast<std::uint32_t>(mesh->xyz.size() / 3);
    mesh->xyz.insert(mesh->xyz.end(), {c.x, c.y, -c.z});
    mesh->xyz.insert(mesh->xyz.end(), {255.0, 3.0, -0.5});
    mesh->xyz.insert(mesh->xyz.end(), {128.0, 255.0, -0.25});
    mesh->indices.insert(mesh->indices.end(), {first, first + 1, first + 2});
  }
  // The identity with a -0 translation: a sum with any +0 term is +0, so only then do the
  // signed zeros of case 1 reach the window.
  raster::Pose pose;
  pose.translation = {-0.0, -0.0, -0.0};
  const PosedSource source(mesh, {pose, m});
  VulkanComputeDevice device(256, 256);
  device.keepDrawStages();
  device.drawMesh(source);
  const VulkanComputeDevice::DrawStages stages = device.lastDrawStages();
  REQUIRE(stages.triangles.size() == std::size(cases));
  // Stage 0's own output, signed zeros included.
  REQUIRE(stages.windowVertices.size() == source.windows().size());
  for (std::size_t k = 0; k < source.windows().size(); ++k) {
    INFO("vertex " << k);
    CHECK(bitsOf(stages.windowVertices[k].x) == bitsOf(source.windows()[k].x));
    CHECK(bitsOf(stages.windowVertices[k].y) == bitsOf(source.windows()[k].y));
    CHECK(bitsOf(stages.windowVertices[k].z) == bitsOf(source.windows()[k].z));
  }
  for (std::size_t k = 0; k < std::size(cases); ++k) {
    INFO("case " << k);
    const WindowVertex& expected = source.windows()[3 * k];
    const VulkanComputeDevice::SetUpTriangle& got = stages.triangles[k];
    REQUIRE_FALSE(got.candidates.empty());
    CHECK(got.fixed[0] == raster::snapToFixed(expected.x));
    CHECK(got.fixed[1] == raster::snapToFixed(expected.y));
    CHECK(bitsOf(got.z0) == bitsOf(expected.z));
  }
  // And the values themselves, so that the cases test what they say.
  CHECK(source.windows()[0].x == 10.0f);
  CHECK(source.windows()[0].y == static_cast<float>(20.0 + 4 * tie));
  CHECK(bitsOf(source.windows()[0].z) == bitsOf(0.75f));
  CHECK(std::signbit(source.windows()[3].x));
  CHECK(std::signbit(source.windows()[3].y));
  CHECK(std::signbit(source.windows()[6].x));
  CHECK(bitsOf(source.windows()[6].z) == bitsOf(static_cast<float>(0.75 + std::ldexp(1.0, -23))));
  CHECK(std::fpclassify(source.windows()[9].z) == FP_SUBNORMAL);
  CHECK(source.windows()[12].z == 0.0f);
  // The buffers, too.
  raster::CpuDevice reference(256, 256);
  reference.drawMesh(source);
  expectSameBuffers(device, reference);
}

TEST_CASE("a posed mesh stays on the device while its block lives, and goes with it",
          "[vulkan-compute]") {
  std::mt19937 rng(51);
  VulkanComputeDevice device(64, 64);
  raster::CpuDevice reference(64, 64);
  countingState(device);
  countingState(reference);
  std::shared_ptr<LocalMesh> a = randomMesh(rng, 40);
  std::shared_ptr<LocalMesh> b = randomMesh(rng, 40);
  {
    // Two poses of one mesh: one upload; each draw its own vertices.
    const PosedSource first(a, {randomPose(rng), viewAlong(2, 64, 64)});
    const PosedSource second(a, {randomPose(rng), viewAlong(2, 64, 64)});
    for (const PosedSource* s : {&first, &second, &first}) {
      device.drawMesh(*s);
      reference.drawMesh(*s);
    }
    CHECK(device.meshCounters().uploads == 1);
    CHECK(device.meshCounters().residentMeshes == 1);
    const PosedSource other(b, {randomPose(rng), viewAlong(1, 64, 64)});
    device.drawMesh(other);
    reference.drawMesh(other);
    CHECK(device.meshCounters().residentMeshes == 2);
  }
  expectSameBuffers(device, reference);
  // The sources are gone but the meshes live (a and b hold them): still kept.
  device.finish();
  CHECK(device.meshCounters().residentMeshes == 2);
  a.reset();
  device.finish();
  CHECK(device.meshCounters().residentMeshes == 1);
  b.reset();
  device.finish();
  CHECK(device.meshCounters().residentMeshes == 0);
}

TEST_CASE("the device's vertex stage gives every vertex of the kit's vertex-stage vectors",
          "[vulkan-compute]") {
  // Each vector as one posed block (its vertices three a triangle, the last repeated to fill a
  // triangle): the window vertices the device's stage 0 made (DrawStages) against the vector's
  // expected bits, and the buffers against the CPU device drawing the expected vertices.
  const std::vector<kit::VertexStageVector> vectors = kit::vertexStageVectors();
  REQUIRE(vectors.size() >= 20);
  VulkanComputeDevice device(64, 48);
  device.keepDrawStages();
  long long vertices = 0;
  for (const kit::VertexStageVector& v : vectors) {
    INFO("vector " << v.name);
    auto mesh = std::make_shared<LocalMesh>();
    for (const std::array<double, 3>& p : v.local)
      mesh->xyz.insert(mesh->xyz.end(), p.begin(), p.end());
    for (std::size_t k = 0; k < v.local.size(); k += 3)
      for (std::size_t j = 0; j < 3; ++j)
        mesh->indices.push_back(static_cast<std::uint32_t>(std::min(k + j, v.local.size() - 1)));
    const PosedSource source(mesh, v.transform);
    device.drawMesh(source);
    const VulkanComputeDevice::DrawStages stages = device.lastDrawStages();
    REQUIRE(stages.windowVertices.size() == v.expected.size());
    for (std::size_t k = 0; k < v.expected.size(); ++k) {
      INFO("vertex " << k);
      const WindowVertex& got = stages.windowVertices[k];
      CHECK(bitsOf(got.x) == bitsOf(v.expected[k].x));
      CHECK(bitsOf(got.y) == bitsOf(v.expected[k].y));
      CHECK(bitsOf(got.z) == bitsOf(v.expected[k].z));
      ++vertices;
    }
    raster::CpuDevice reference(64, 48);
    reference.drawTriangles(v.expected, mesh->indices);
    VulkanComputeDevice fresh(64, 48);
    fresh.drawMesh(source);
    expectSameBuffers(fresh, reference);
  }
  CHECK(vertices >= 200);
}

namespace {

// The box of `mesh` at `pose` in any order of comparisons, and whether an extreme is a zero or
// a coordinate NaN (what the device must flag).
raster::PosedBox referenceBox(const LocalMesh& mesh, const raster::Pose& pose) {
  raster::PosedBox box;
  box.min.fill(std::numeric_limits<double>::infinity());
  box.max.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i + 2 < mesh.xyz.size(); i += 3) {
    const std::array<double, 3> w =
        raster::poseVertex(pose, {mesh.xyz[i], mesh.xyz[i + 1], mesh.xyz[i + 2]});
    for (std::size_t k = 0; k < 3; ++k) {
      if (std::isnan(w[k])) {
        box.orderMatters = true;
        continue;
      }
      box.min[k] = std::min(box.min[k], w[k]);
      box.max[k] = std::max(box.max[k], w[k]);
    }
  }
  for (std::size_t k = 0; k < 3; ++k)
    box.orderMatters = box.orderMatters || box.min[k] == 0.0 || box.max[k] == 0.0;
  return box;
}

raster::PosedMesh posedOf(const std::shared_ptr<LocalMesh>& mesh, const raster::Pose& pose) {
  raster::PosedMesh posed{mesh->xyz, mesh->indices, {}, mesh->key, mesh};
  posed.transform.pose = pose;
  return posed;
}

}  // namespace

TEST_CASE("posed blocks' boxes reduced on the device are the reference's, zeros flagged",
          "[vulkan-compute]") {
  std::mt19937 rng(53);
  std::vector<std::shared_ptr<LocalMesh>> meshes;
  std::vector<raster::Pose> poses;
  // Random blocks of 1 to 3,000 triangles (a workgroup's stride and its tree both matter).
  for (const int triangles : {1, 7, 21, 22, 300, 3000}) {
    meshes.push_back(randomMesh(rng, triangles));
    poses.push_back(randomPose(rng));
  }
  // An infinite translation: infinite extremes are ordinary ones.
  meshes.push_back(randomMesh(rng, 5));
  poses.emplace_back();
  poses.back().translation[0] = std::numeric_limits<double>::infinity();
  // A block without vertices: +inf and -inf, unflagged.
  meshes.push_back(std::make_shared<LocalMesh>());
  poses.emplace_back();
  // x = 5, -0, +0 at the identity with a -0 translation (each product with a negative y or z is
  // -0, so the zeros keep their signs): a reduction in another order than the host's keeps the
  // other zero, so the box must be flagged.
  auto zeros = std::make_shared<LocalMesh>();
  zeros->xyz = {5.0, -1.0, -1.0, -0.0, -1.0, -1.0, 0.0, -1.0, -1.0};
  zeros->indices = {0, 1, 2};
  meshes.push_back(zeros);
  raster::Pose negativeZero;
  negativeZero.translation = {-0.0, -0.0, -0.0};
  poses.push_back(negativeZero);
  // A NaN coordinate: flagged.
  meshes.push_back(randomMesh(rng, 4));
  meshes.back()->xyz[7] = std::numeric_limits<double>::quiet_NaN();
  poses.push_back(randomPose(rng));

  std::vector<raster::PosedMesh> posed;
  for (std::size_t i = 0; i < meshes.size(); ++i)
    posed.push_back(posedOf(meshes[i], poses[i]));
  VulkanComputeDevice device(8, 8);
  raster::PendingRead<raster::PosedBox> read = device.posedBoxesLater(posed);
  device.finish();
  const std::vector<raster::PosedBox> boxes = read.take();
  REQUIRE(boxes.size() == meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    INFO("block " << i);
    const raster::PosedBox expected = referenceBox(*meshes[i], poses[i]);
    CHECK(boxes[i].orderMatters == expected.orderMatters);
    if (expected.orderMatters)
      continue;
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(bitsOf(boxes[i].min[k]) == bitsOf(expected.min[k]));
      CHECK(bitsOf(boxes[i].max[k]) == bitsOf(expected.max[k]));
    }
  }
  CHECK(boxes[8].orderMatters);  // the zeros
  CHECK(boxes[9].orderMatters);  // the NaN
  CHECK_FALSE(boxes[6].orderMatters);
  CHECK(boxes[6].min[0] == std::numeric_limits<double>::infinity());
  CHECK_FALSE(boxes[7].orderMatters);
  CHECK(boxes[7].min[0] == std::numeric_limits<double>::infinity());
  // The meshes are kept as posed draws keep them: drawing one uploads nothing more.
  CHECK(device.meshCounters().uploads == static_cast<long long>(meshes.size()));
  const PosedSource source(meshes[4], {poses[4], viewAlong(2, 8, 8)});
  device.drawMesh(source);
  CHECK(device.meshCounters().uploads == static_cast<long long>(meshes.size()));
}
