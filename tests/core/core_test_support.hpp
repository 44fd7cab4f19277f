#pragma once
// Helpers shared by the core test suites (geometry and up).

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <utility>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/mesh_error.hpp"

namespace recode::core::test {

// A fresh directory under the system temp directory, removed with its contents on
// destruction. Unique per process and per instance, so parallel ctest runs do not collide.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    path_ = std::filesystem::temp_directory_path() /
            ("recode_core_tests_" + std::to_string(stamp) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  // Writes `contents` byte for byte to a file in the directory and returns its path.
  [[nodiscard]] std::filesystem::path write(const std::string& name,
                                            const std::string& contents) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream out(file, std::ios::binary);
    out << contents;
    return file;
  }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Runs f, which must throw MeshError, and returns the message ("" if it did not throw;
// the caller's message checks then fail).
inline std::string meshErrorMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

// Number of distinct undirected edges.
inline std::size_t countEdges(const TriangleMesh& mesh) {
  std::set<std::pair<VertexIndex, VertexIndex>> edges;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const VertexIndex a = t[static_cast<std::size_t>(k)];
      const VertexIndex b = t[static_cast<std::size_t>((k + 1) % 3)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return edges.size();
}

// Path of a file under data/ in the source tree.
inline std::filesystem::path dataFile(const std::string& relative) {
  return std::filesystem::path(RECODE_DATA_DIR) / relative;
}

}  // namespace recode::core::test
