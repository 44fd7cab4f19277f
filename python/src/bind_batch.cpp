// Batches (docs/api.md#batches): recode.collide_batch (many pairs of objects, at their poses, at
// a pose per object, or at frames of such poses) and recode.collide_poses (one pair at many
// poses), from NumPy arrays, with the results as arrays. The inputs are checked and copied with
// the GIL held; the queries then run without it, each one recode::collide on private copies of
// the objects, so every answer is that of recode.collide on the same pair at the same poses. With
// request.threads other than 1 the queries are spread over oneTBB threads (the pool the C++ API
// decides block pairs on), each with copies of its own. Between queries the calling thread hears
// Ctrl-C and reports progress (query_watch.hpp). BatchResult pickles (pickle_state.hpp).
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "devices.hpp"
#include "pickle_state.hpp"
#include "query_watch.hpp"
#include "recode/api/collision.hpp"

namespace recode::python {

namespace {

constexpr double kQuaternionTolerance = 1e-6;

// The pose of a row x, y, z, qx, qy, qz, qw (a unit quaternion within kQuaternionTolerance).
Eigen::Isometry3d poseFromRow(const double* p, const NameOf& what) {
  const Eigen::Quaterniond q(p[6], p[3], p[4], p[5]);  // Eigen's order: w, x, y, z
  const double norm = q.norm();
  if (std::abs(norm - 1.0) > kQuaternionTolerance) {
    std::ostringstream s;
    s << what() << ": the quaternion (qx, qy, qz, qw) = (" << p[3] << ", " << p[4] << ", " << p[5]
      << ", " << p[6] << ") has norm " << norm << "; it must be a unit quaternion (within "
      << kQuaternionTolerance << ")";
    throw py::value_error(s.str());
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  return pose;
}

// Poses from an array of 4 x 4 matrices (..., 4, 4) or of rows (..., 7): translation x, y, z,
// then the unit quaternion qx, qy, qz, qw (scalar last). `shape` gets the leading dimensions.
struct Poses {
  std::vector<Eigen::Isometry3d> poses;
  std::vector<py::ssize_t> shape;  // the leading dimensions, one pose per entry
};

Poses posesFrom(const py::handle& object, const std::string& what) {
  const RealArray a = realArray(object, what);
  const py::ssize_t n = a.ndim();
  const bool matrices = n >= 3 && a.shape(n - 1) == 4 && a.shape(n - 2) == 4;
  const bool rows = n >= 2 && a.shape(n - 1) == 7;
  if (!matrices && !rows)
    throw py::value_error(what +
                          ": expected 4 x 4 matrices (..., 4, 4) or rows (..., 7) of x, y, "
                          "z, qx, qy, qz, qw, got shape " +
                          shapeText(a));
  Poses out;
  for (py::ssize_t d = 0; d < n - (matrices ? 2 : 1); ++d)
    out.shape.push_back(a.shape(d));
  std::size_t count = 1;
  for (const py::ssize_t s : out.shape)
    count *= static_cast<std::size_t>(s);
  out.poses.resize(count);
  const std::size_t stride = matrices ? 16 : 7;
  for (std::size_t i = 0; i < count; ++i) {
    const double* p = a.data() + i * stride;
    // Named only for an error: a batch may have millions of poses.
    const auto at = [&] { return what + "[" + indexText(out.shape, i) + "]"; };
    for (std::size_t k = 0; k < stride; ++k)
      if (!std::isfinite(p[k]))
        throw py::value_error(at() + " has " + py::str(py::float_(p[k])).cast<std::string>() +
                              ": pose entries must be finite");
    out.poses[i] = matrices ? rigidMotionFrom(p, at) : poseFromRow(p, at);
  }
  return out;
}

// Private copies of the objects (copied with the GIL held).
std::vector<CollisionObject> objectsFrom(const py::sequence& objects, const std::string& what) {
  std::vector<CollisionObject> out;
  out.reserve(py::len(objects));
  for (std::size_t i = 0; i < py::len(objects); ++i) {
    const py::handle item = objects[i];
    if (!py::isinstance<CollisionObject>(item))
      throw py::type_error(what + "[" + std::to_string(i) + "]: expected a CollisionObject, got " +
                           py::str(py::type::of(item)).cast<std::string>());
    out.push_back(item.cast<const CollisionObject&>());
  }
  return out;
}

std::vector<std::array<std::size_t, 2>> pairsFrom(const py::handle& object,
                                                  std::size_t objectCount) {
  const std::vector<std::size_t> indices =
      indexRows(object, "pairs", 2, "a (K, 2) array of indices into objects",
                {"indices into objects", "objects", objectCount});
  std::vector<std::array<std::size_t, 2>> out(indices.size() / 2);
  for (std::size_t k = 0; k < out.size(); ++k)
    out[k] = {indices[2 * k], indices[2 * k + 1]};
  return out;
}

// One query: objects[a] at poseA (null: its own pose) against objects[b] at poseB.
struct Query {
  std::size_t a = 0, b = 0;
  const Eigen::Isometry3d* poseA = nullptr;
  const Eigen::Isometry3d* poseB = nullptr;
};

// One query's answer, as the arrays hold it.
struct Answer {
  bool collide = false;
  long long interferingPixels = 0;
  long long contactPixels = 0;
  std::array<long long, core::kCaseCount> caseCounts{};
  std::array<double, 6> box{};  // min x, y, z, max x, y, z; NaN without a box
  double area = 0.0;
  double maxDepth = 0.0;
  std::array<double, 3> normal{};  // NaN without one
  double penetrationDepth = 0.0;
  long long blockPairsDrawn = 0;
  double collisionUs = 0.0;
  // The layered pair's, for a query with a closed mesh: the volume (NaN for other queries), the
  // containment (-1 for other queries), the layers and the passes (0 for other queries).
  bool layered = false;
  double overlapVolume = 0.0;
  std::int8_t containment = -1;
  std::array<std::int32_t, 2> layers{};
  long long passes = 0;
};

Answer answerOf(const CollisionResult& r) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  Answer out;
  out.collide = r.collide;
  out.interferingPixels = r.interferingPixels;
  out.contactPixels = r.contact.pixels;
  for (const BlockContact& c : r.contacts)
    for (std::size_t k = 0; k < out.caseCounts.size(); ++k)
      out.caseCounts[k] += c.pair.caseCounts[k];
  if (r.contact.box.isEmpty()) {
    out.box.fill(nan);
  } else {
    for (int k = 0; k < 3; ++k) {
      out.box[static_cast<std::size_t>(k)] = r.contact.box.min[k];
      out.box[static_cast<std::size_t>(k) + 3] = r.contact.box.max[k];
    }
  }
  out.area = r.contact.area;
  out.maxDepth = r.contact.maxDepth;
  // The normal of the block contact with the most interfering pixels (the first of equals).
  const BlockContact* best = nullptr;
  for (const BlockContact& c : r.contacts)
    if (c.pair.contact.normal && (!best || c.pair.interferingPixels > best->pair.interferingPixels))
      best = &c;
  out.normal.fill(nan);
  out.penetrationDepth = nan;
  if (best) {
    for (int k = 0; k < 3; ++k)
      out.normal[static_cast<std::size_t>(k)] = best->pair.contact.normal->normal[k];
    out.penetrationDepth = best->pair.contact.normal->depth;
  }
  out.blockPairsDrawn = r.blockPairsDrawn;
  out.collisionUs = r.collisionUs;
  out.layered = r.layered.has_value();
  out.overlapVolume = r.layered ? r.layered->result.overlapVolume : nan;
  if (r.layered) {
    out.containment = static_cast<std::int8_t>(r.layered->result.containment);
    out.layers = {r.layered->result.layersA, r.layered->result.layersB};
    out.passes = r.layered->result.passes;
  }
  return out;
}

void place(CollisionObject& object, const Eigen::Isometry3d* pose) {
  if (pose && pose->matrix() != object.transform().matrix())
    object.setTransform(*pose);
}

// Runs query q on `objects` (private copies, moved to the query's poses).
Answer runQuery(std::vector<CollisionObject>& objects, const std::vector<CollisionObject>& rest,
                const Query& q, std::size_t index, const CollisionRequest& request,
                DevicePool* pool) {
  CollisionObject& a = objects[q.a];
  CollisionObject& b = objects[q.b];
  // An object at its own pose: back to it if an earlier query moved this copy.
  place(a, q.poseA ? q.poseA : &rest[q.a].transform());
  place(b, q.poseB ? q.poseB : &rest[q.b].transform());
  CollisionResult result;
  const auto run = [&](const CollisionObject& other) {
    if (pool)
      collide(a, other, request, result, *pool);
    else
      collide(a, other, request, result);
  };
  try {
    if (q.a == q.b)
      run(CollisionObject(b));  // the same object: a second copy
    else
      run(b);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("query " + std::to_string(index) + " (objects " +
                                std::to_string(q.a) + " and " + std::to_string(q.b) +
                                "): " + e.what());
  }
  return answerOf(result);
}

// Every query in turn on the caller's thread (threads 1, or a device other than cpu, which
// draws from one thread), each taking the device's lock for itself; between queries the watch
// may take the GIL back (query_watch.hpp), so the lock is not held then.
void runInTurn(const std::vector<CollisionObject>& objects, const std::vector<Query>& queries,
               const CollisionRequest& request, SharedPool* shared, QueryWatch& watch,
               std::vector<Answer>& answers) {
  std::vector<CollisionObject> mine = objects;
  for (std::size_t i = 0; i < queries.size() && !watch.stopped(); ++i) {
    if (shared) {
      const std::lock_guard<std::mutex> lock(shared->mutex);
      answers[i] = runQuery(mine, objects, queries[i], i, request, &shared->pool);
    } else {
      answers[i] = runQuery(mine, objects, queries[i], i, request, nullptr);
    }
    watch.queryDone();
    watch.poll();
  }
}

// The queries spread over oneTBB threads, each with copies of the objects of its own; each
// query's block pairs on its thread. They run in chunks, and the caller's thread polls the watch
// between chunks (inside one, it may wait on the other threads rather than run queries itself);
// a chunk grows while it takes under kChunkTime, so Ctrl-C waits for at most about that long
// past the watch's interval.
void runSpread(const std::vector<CollisionObject>& objects, const std::vector<Query>& queries,
               CollisionRequest request, QueryWatch& watch, std::vector<Answer>& answers) {
  constexpr auto kChunkTime = std::chrono::milliseconds(50);
  const int threads = request.threads;
  request.threads = 1;
  const int concurrency = threads > 0 ? std::min(threads, tbb::info::default_concurrency())
                                      : tbb::info::default_concurrency();
  tbb::enumerable_thread_specific<std::vector<CollisionObject>> copies(objects);
  tbb::task_arena arena(concurrency);
  std::size_t chunk = static_cast<std::size_t>(concurrency);
  for (std::size_t begin = 0; begin < queries.size() && !watch.stopped();) {
    const std::size_t end = std::min(queries.size(), begin + chunk);
    const auto start = std::chrono::steady_clock::now();
    arena.execute([&] {
      tbb::parallel_for(std::size_t{begin}, end, [&](std::size_t i) {
        answers[i] = runQuery(copies.local(), objects, queries[i], i, request, nullptr);
        watch.queryDone();
      });
    });
    begin = end;
    if (std::chrono::steady_clock::now() - start < kChunkTime)
      chunk *= 2;
    else if (chunk > static_cast<std::size_t>(concurrency))
      chunk /= 2;
    watch.poll();
  }
}

// Every query without the GIL, Ctrl-C and `progress` heard between queries (query_watch.hpp).
std::vector<Answer> runQueries(const std::vector<CollisionObject>& objects,
                               const std::vector<Query>& queries, const CollisionRequest& request,
                               const std::string& device, const py::object& progress) {
  std::vector<Answer> answers(queries.size());
  SharedPool* shared = device == "cpu" ? nullptr : &devicePool(device);
  QueryWatch watch(progress);
  {
    const py::gil_scoped_release release;
    if (shared || request.threads == 1 || queries.size() < 2)
      runInTurn(objects, queries, request, shared, watch, answers);
    else
      runSpread(objects, queries, request, watch, answers);
  }
  watch.finish();
  return answers;
}

// The answers as arrays, each with the leading shape `shape`.
struct BatchResult {
  py::object collide, interferingPixels, contactPixels, caseCounts, contactBox, contactArea,
      maxDepth, normal, penetrationDepth, blockPairsDrawn, collisionUs, layered, overlapVolume,
      containment, layers, passes;
  std::vector<py::ssize_t> shape;
};

// The arrays in the order a pickled state holds them.
constexpr std::array kColumns = {&BatchResult::collide,          &BatchResult::interferingPixels,
                                 &BatchResult::contactPixels,    &BatchResult::caseCounts,
                                 &BatchResult::contactBox,       &BatchResult::contactArea,
                                 &BatchResult::maxDepth,         &BatchResult::normal,
                                 &BatchResult::penetrationDepth, &BatchResult::blockPairsDrawn,
                                 &BatchResult::collisionUs,      &BatchResult::layered,
                                 &BatchResult::overlapVolume,    &BatchResult::containment,
                                 &BatchResult::layers,           &BatchResult::passes};
constexpr const char* kBatchType = "recode.BatchResult";

// (format, shape, the arrays of kColumns).
py::tuple batchState(const BatchResult& r) {
  py::tuple state(kColumns.size() + 2);
  state[0] = kPickleFormat;
  state[1] = py::cast(r.shape);
  for (std::size_t i = 0; i < kColumns.size(); ++i)
    state[i + 2] = r.*kColumns[i];
  return state;
}
BatchResult batchFromState(const py::tuple& state) {
  checkState(state, kBatchType, kColumns.size() + 1);
  BatchResult r;
  r.shape = stateItem<std::vector<py::ssize_t>>(state[1], kBatchType, "shape");
  for (std::size_t i = 0; i < kColumns.size(); ++i) {
    const py::array column = py::array::ensure(state[i + 2]);
    const auto leading = static_cast<py::ssize_t>(r.shape.size());
    bool fits = column && column.ndim() >= leading;
    for (py::ssize_t d = 0; fits && d < leading; ++d)
      fits = column.shape(d) == r.shape[static_cast<std::size_t>(d)];
    if (!fits)
      throw py::value_error(std::string(kBatchType) + ": the pickled state's array " +
                            std::to_string(i) + " does not have the leading shape " +
                            shapeText(r.shape));
    r.*kColumns[i] = column;
  }
  return r;
}

template <class T, class F>
py::array_t<T> column(const std::vector<Answer>& answers, std::vector<py::ssize_t> shape,
                      std::initializer_list<py::ssize_t> tail, F&& fill) {
  shape.insert(shape.end(), tail.begin(), tail.end());
  py::array_t<T> out(shape);
  T* data = out.mutable_data();
  std::size_t width = 1;
  for (const py::ssize_t t : tail)
    width *= static_cast<std::size_t>(t);
  for (std::size_t i = 0; i < answers.size(); ++i)
    fill(answers[i], data + i * width);
  return out;
}

BatchResult resultOf(const std::vector<Answer>& v, const std::vector<py::ssize_t>& shape) {
  BatchResult r;
  r.shape = shape;
  r.collide = column<bool>(v, shape, {}, [](const Answer& a, bool* o) { *o = a.collide; });
  r.interferingPixels = column<std::int64_t>(
      v, shape, {}, [](const Answer& a, std::int64_t* o) { *o = a.interferingPixels; });
  r.contactPixels = column<std::int64_t>(
      v, shape, {}, [](const Answer& a, std::int64_t* o) { *o = a.contactPixels; });
  r.caseCounts =
      column<std::int64_t>(v, shape, {core::kCaseCount}, [](const Answer& a, std::int64_t* o) {
        std::copy(a.caseCounts.begin(), a.caseCounts.end(), o);
      });
  r.contactBox = column<double>(v, shape, {2, 3}, [](const Answer& a, double* o) {
    std::copy(a.box.begin(), a.box.end(), o);
  });
  r.contactArea = column<double>(v, shape, {}, [](const Answer& a, double* o) { *o = a.area; });
  r.maxDepth = column<double>(v, shape, {}, [](const Answer& a, double* o) { *o = a.maxDepth; });
  r.normal = column<double>(v, shape, {3}, [](const Answer& a, double* o) {
    std::copy(a.normal.begin(), a.normal.end(), o);
  });
  r.penetrationDepth =
      column<double>(v, shape, {}, [](const Answer& a, double* o) { *o = a.penetrationDepth; });
  r.blockPairsDrawn = column<std::int64_t>(
      v, shape, {}, [](const Answer& a, std::int64_t* o) { *o = a.blockPairsDrawn; });
  r.collisionUs =
      column<double>(v, shape, {}, [](const Answer& a, double* o) { *o = a.collisionUs; });
  r.layered = column<bool>(v, shape, {}, [](const Answer& a, bool* o) { *o = a.layered; });
  r.overlapVolume =
      column<double>(v, shape, {}, [](const Answer& a, double* o) { *o = a.overlapVolume; });
  r.containment = column<std::int8_t>(v, shape, {},
                                      [](const Answer& a, std::int8_t* o) { *o = a.containment; });
  r.layers = column<std::int32_t>(v, shape, {2}, [](const Answer& a, std::int32_t* o) {
    std::copy(a.layers.begin(), a.layers.end(), o);
  });
  r.passes =
      column<std::int64_t>(v, shape, {}, [](const Answer& a, std::int64_t* o) { *o = a.passes; });
  return r;
}

BatchResult collideBatch(const py::sequence& objectList, const py::handle& pairArray,
                         const std::optional<py::object>& poseArray,
                         const std::optional<CollisionRequest>& request, const std::string& device,
                         const py::object& progress) {
  const std::vector<CollisionObject> objects = objectsFrom(objectList, "objects");
  const auto pairs = pairsFrom(pairArray, objects.size());
  Poses poses;
  std::size_t frames = 0;  // 0: the objects' own poses
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(pairs.size())};
  if (poseArray && !poseArray->is_none()) {
    poses = posesFrom(*poseArray, "poses");
    const auto m = static_cast<py::ssize_t>(objects.size());
    const bool perObject = poses.shape.size() == 1 && poses.shape[0] == m;
    const bool perFrame = poses.shape.size() == 2 && poses.shape[1] == m;
    if (!perObject && !perFrame)
      throw py::value_error("poses: expected one pose per object, (" + std::to_string(m) +
                            ", 4, 4) or (" + std::to_string(m) + ", 7) for " + std::to_string(m) +
                            " objects, or frames of them, (F, " + std::to_string(m) +
                            ", 4, 4) or (F, " + std::to_string(m) + ", 7); got " +
                            shapeText(poses.shape) + " poses");
    frames = perFrame ? static_cast<std::size_t>(poses.shape[0]) : 1;
    if (perFrame)
      shape.insert(shape.begin(), poses.shape[0]);
  }
  std::vector<Query> queries;
  queries.reserve(std::max<std::size_t>(frames, 1) * pairs.size());
  for (std::size_t f = 0; f < std::max<std::size_t>(frames, 1); ++f)
    for (const auto& p : pairs) {
      Query q{p[0], p[1], nullptr, nullptr};
      if (frames) {
        q.poseA = &poses.poses[f * objects.size() + p[0]];
        q.poseB = &poses.poses[f * objects.size() + p[1]];
      }
      queries.push_back(q);
    }
  return resultOf(
      runQueries(objects, queries, request.value_or(CollisionRequest{}), device, progress), shape);
}

BatchResult collidePoses(const CollisionObject& a, const CollisionObject& b,
                         const std::optional<py::object>& posesA,
                         const std::optional<py::object>& posesB,
                         const std::optional<CollisionRequest>& request, const std::string& device,
                         const py::object& progress) {
  const bool hasA = posesA && !posesA->is_none();
  const bool hasB = posesB && !posesB->is_none();
  if (!hasA && !hasB)
    throw py::value_error("collide_poses: give poses_a, poses_b or both");
  // N poses of one object, (N, 4, 4) or (N, 7); none when not given.
  const auto posesOf = [](const std::optional<py::object>& given, bool has, const char* what) {
    Poses p;
    if (has)
      p = posesFrom(*given, what);
    if (has && p.shape.size() != 1)
      throw py::value_error(std::string(what) + ": expected N poses, (N, 4, 4) or (N, 7); got " +
                            shapeText(p.shape) + " poses");
    return p;
  };
  const Poses pa = posesOf(posesA, hasA, "poses_a");
  const Poses pb = posesOf(posesB, hasB, "poses_b");
  if (hasA && hasB && pa.shape[0] != pb.shape[0])
    throw py::value_error("poses_a and poses_b: expected the same number of poses, got " +
                          std::to_string(pa.shape[0]) + " and " + std::to_string(pb.shape[0]));
  const std::size_t n = hasA ? pa.poses.size() : pb.poses.size();
  const std::vector<CollisionObject> objects{a, b};
  std::vector<Query> queries(n);
  for (std::size_t i = 0; i < n; ++i)
    queries[i] = {0, 1, hasA ? &pa.poses[i] : nullptr, hasB ? &pb.poses[i] : nullptr};
  return resultOf(
      runQueries(objects, queries, request.value_or(CollisionRequest{}), device, progress),
      {static_cast<py::ssize_t>(n)});
}

}  // namespace

void bindBatch(py::module_& m) {
  // BatchResult.containment's codes, by index (core::Containment's order).
  py::list containment;
  for (int c = 0; c <= static_cast<int>(core::Containment::Same); ++c)
    containment.append(std::string(core::toString(static_cast<core::Containment>(c))));
  m.attr("CONTAINMENT") = py::tuple(containment);
  py::class_<BatchResult>(
      m, "BatchResult",
      "The answers of collide_batch or collide_poses as arrays, one entry per query (leading "
      "shape `shape`): what recode.collide returns for the same pair at the same poses.")
      .def(py::pickle(&batchState, &batchFromState))
      .def_readonly("collide", &BatchResult::collide, "bool: the verdicts.")
      .def_readonly("interfering_pixels", &BatchResult::interferingPixels, "int64.")
      .def_readonly("contact_pixels", &BatchResult::contactPixels, "int64: result.contact.pixels.")
      .def_readonly("case_counts", &BatchResult::caseCounts,
                    "int64 (..., 9): cases 0-8 summed over the block pairs in contact.")
      .def_readonly("contact_box", &BatchResult::contactBox,
                    "float64 (..., 2, 3): [[min], [max]] of result.contact.box; NaN without one.")
      .def_readonly("contact_area", &BatchResult::contactArea, "float64: result.contact.area.")
      .def_readonly("max_depth", &BatchResult::maxDepth, "float64: result.contact.max_depth.")
      .def_readonly("normal", &BatchResult::normal,
                    "float64 (..., 3): with request.normal, the contact normal of the block "
                    "contact with the most interfering pixels (the first of equals); else NaN.")
      .def_readonly("penetration_depth", &BatchResult::penetrationDepth,
                    "float64: that block contact's penetration depth; NaN without a normal.")
      .def_readonly("block_pairs_drawn", &BatchResult::blockPairsDrawn, "int64.")
      .def_readonly("collision_us", &BatchResult::collisionUs,
                    "float64: each query's own time inside the C++ API, microseconds.")
      .def_readonly("layered", &BatchResult::layered,
                    "bool: a closed mesh took part, so the layered pair decided the query.")
      .def_readonly("overlap_volume", &BatchResult::overlapVolume,
                    "float64: the layered pair's estimate of the intersection's volume; NaN "
                    "where no closed mesh took part.")
      .def_readonly("containment", &BatchResult::containment,
                    "int8: the layered pair's containment as an index into recode.CONTAINMENT "
                    "(0 none, 1 a_inside_b, 2 b_inside_a, 3 same); -1 where no closed mesh took "
                    "part.")
      .def_readonly("layers", &BatchResult::layers,
                    "int32 (..., 2): the layered pair's most entries of A and of B at one pixel; "
                    "0 where no closed mesh took part.")
      .def_readonly("passes", &BatchResult::passes,
                    "int64: the layered pair's passes; 0 where no closed mesh took part.")
      .def_property_readonly("shape",
                             [](const BatchResult& r) {
                               py::tuple t(r.shape.size());
                               for (std::size_t i = 0; i < r.shape.size(); ++i)
                                 t[i] = r.shape[i];
                               return t;
                             })
      .def("__len__", [](const BatchResult& r) { return r.shape.empty() ? 0 : r.shape.front(); })
      .def("__repr__", [](const BatchResult& r) {
        const auto c = r.collide.cast<py::array_t<bool>>();
        std::size_t hits = 0;
        for (py::ssize_t i = 0; i < c.size(); ++i)
          hits += c.data()[i] ? 1 : 0;
        return "<recode.BatchResult shape=" + shapeText(r.shape) +
               " collide=" + std::to_string(hits) + " of " + std::to_string(c.size()) + ">";
      });

  m.def("collide_batch", &collideBatch, py::arg("objects"), py::arg("pairs"),
        py::arg("poses") = py::none(), py::kw_only(), py::arg("request") = py::none(),
        py::arg("device") = "cpu", py::arg("progress") = py::none(),
        "Collides objects[pairs[k, 0]] with objects[pairs[k, 1]] for every row k of pairs "
        "(K, 2): at the objects' own poses; at `poses`, one per object, (M, 4, 4) or (M, 7) "
        "rows x, y, z, qx, qy, qz, qw (results (K,)); or at frames of them, (F, M, 4, 4) or "
        "(F, M, 7) (results (F, K)). Runs without the GIL; request.threads other than 1 "
        "spreads the queries over that many threads (0: all). Ctrl-C stops it (KeyboardInterrupt "
        "within a fraction of a second); `progress(n)`, e.g. a tqdm bar's update, is called on "
        "this thread at most five times a second with the queries done since its last call. "
        "Returns a BatchResult.");
  m.def("collide_poses", &collidePoses, py::arg("a"), py::arg("b"), py::arg("poses_a") = py::none(),
        py::arg("poses_b") = py::none(), py::kw_only(), py::arg("request") = py::none(),
        py::arg("device") = "cpu", py::arg("progress") = py::none(),
        "Collides a with b at N poses: poses_a and/or poses_b (N, 4, 4) or (N, 7) rows x, y, z, "
        "qx, qy, qz, qw; an object without poses stays at its own. Ctrl-C and `progress` as in "
        "collide_batch. Returns a BatchResult of N queries.");
}

}  // namespace recode::python
