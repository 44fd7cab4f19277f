// Writes what the C++ API answers on pairs of the generated suite (verify/oracles/pair_suite),
// for the Python tests to compare against (test_suite_equivalence.py): each pair's two meshes,
// and for each of three requests (the suite's pixel size along z; auto axis at 64 pixels; both
// blocks moved by a random rigid pose, auto at 48 pixels) the pose, the request and the whole
// CollisionResult: verdict, counts, every case map, contact points, box, area and depth. The
// doubles are written with 17 significant digits, so Python reads back the same bits.
//
//   recode_python_suite_expectations OUT.json [COUNT]
#include <cstdio>
#include <exception>
#include <fstream>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "recode/api/collision.hpp"
#include "recode/verify/pair_suite.hpp"

namespace {

using namespace recode;
using Json = nlohmann::json;

Json vectorJson(const Eigen::Vector3d& v) {
  return Json::array({v.x(), v.y(), v.z()});
}

Json meshJson(const core::TriangleMesh& mesh) {
  Json vertices = Json::array(), faces = Json::array();
  for (const Eigen::Vector3d& v : mesh.vertices)
    vertices.push_back(vectorJson(v));
  for (const core::Triangle& t : mesh.triangles)
    faces.push_back(Json::array({t[0], t[1], t[2]}));
  return {{"vertices", vertices}, {"faces", faces}};
}

Json boxJson(const core::Aabb& box) {
  return box.isEmpty() ? Json(nullptr) : Json::array({vectorJson(box.min), vectorJson(box.max)});
}

Json contactJson(const core::ContactRegion& c) {
  Json points = Json::array();
  for (const Eigen::Vector3d& p : c.points)
    points.push_back(vectorJson(p));
  return {{"points", points}, {"box", boxJson(c.box)},   {"pixels", c.pixels},
          {"area", c.area},   {"max_depth", c.maxDepth}, {"collapsed_pixels", c.collapsedPixels}};
}

Json resultJson(const CollisionResult& r) {
  Json contacts = Json::array();
  for (const BlockContact& c : r.contacts) {
    const core::ViewWindow& w = c.frame.window;
    contacts.push_back(
        {{"block_a", c.blockA},
         {"block_b", c.blockB},
         {"frame",
          {{"axis", std::string(core::toString(c.frame.axis))},
           {"window", Json::array({w.umin, w.vmin, w.umax, w.vmax})},
           {"width", c.frame.width},
           {"height", c.frame.height}}},
         {"mor", Json::array({c.pair.mor.x0, c.pair.mor.y0, c.pair.mor.x1, c.pair.mor.y1})},
         {"case_counts", c.pair.caseCounts},
         {"case_map_shape",
          Json::array({c.pair.caseMap.rect.height(), c.pair.caseMap.rect.width()})},
         {"case_map", c.pair.caseMap.data},
         {"interfering_pixels", c.pair.interferingPixels},
         {"contact", contactJson(c.pair.contact)}});
  }
  return {{"collide", r.collide},
          {"interfering_pixels", r.interferingPixels},
          {"box_tests", r.boxTests},
          {"block_pairs_drawn", r.blockPairsDrawn},
          {"contact", contactJson(r.contact)},
          {"contacts", contacts}};
}

Json poseJson(const Eigen::Isometry3d& pose) {
  Json rows = Json::array();
  for (int i = 0; i < 4; ++i)
    rows.push_back(Json::array(
        {pose.matrix()(i, 0), pose.matrix()(i, 1), pose.matrix()(i, 2), pose.matrix()(i, 3)}));
  return rows;
}

Json requestJson(const CollisionRequest& r) {
  const char* axis = r.axis == AxisChoice::Z ? "z" : "auto";
  return {{"pixel_size", r.pixelSize ? Json(*r.pixelSize) : Json(nullptr)},
          {"resolution", r.resolution},
          {"axis", axis}};
}

Json caseJson(const core::TriangleMesh& a, const core::TriangleMesh& b,
              const Eigen::Isometry3d& pose, const CollisionRequest& request) {
  const CollisionObject objectA(CollisionGeometry::single(ConvexBlock::fromMesh(a, "a")), pose);
  const CollisionObject objectB(CollisionGeometry::single(ConvexBlock::fromMesh(b, "b")), pose);
  CollisionResult result;
  collide(objectA, objectB, request, result);
  return {{"pose", poseJson(pose)},
          {"request", requestJson(request)},
          {"expected", resultJson(result)}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: %s OUT.json [COUNT]\n", argv[0]);
    return 2;
  }
  try {
    const int count = argc == 3 ? std::stoi(argv[2]) : 70;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), shift(-2.0, 2.0);
    Json pairs = Json::array();
    for (const verify::SuitePair& p : verify::generatePairSuite({.count = count})) {
      Json cases = Json::array();
      CollisionRequest alongZ;
      alongZ.axis = AxisChoice::Z;
      alongZ.pixelSize = (p.frame.window.umax - p.frame.window.umin) / p.frame.width;
      cases.push_back(caseJson(p.a, p.b, Eigen::Isometry3d::Identity(), alongZ));
      CollisionRequest automatic;
      automatic.resolution = 64;
      cases.push_back(caseJson(p.a, p.b, Eigen::Isometry3d::Identity(), automatic));
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translate(Eigen::Vector3d(shift(random), shift(random), shift(random)));
      pose.rotate(Eigen::AngleAxisd(angle(random), Eigen::Vector3d(1.0, 2.0, 3.0).normalized()));
      CollisionRequest posed;
      posed.resolution = 48;
      cases.push_back(caseJson(p.a, p.b, pose, posed));
      pairs.push_back(
          {{"label", p.label}, {"a", meshJson(p.a)}, {"b", meshJson(p.b)}, {"cases", cases}});
    }
    std::ofstream out(argv[1]);
    out << Json{{"pairs", pairs}}.dump();
    if (!out.flush())
      throw std::runtime_error(std::string("cannot write ") + argv[1]);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 1;
  }
}
