// The STL reader, binary and ASCII. STL stores each triangle's three corners by value; the
// reader welds corners with exactly equal coordinates into one vertex (numbered in order of
// first appearance) and keeps the triangles in file order with their corners in file order.
// docs/geometry.md describes the formats as read here and lists the messages.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "format.hpp"
#include "mesh_io_text.hpp"

namespace recode::core::detail {
namespace {

namespace fs = std::filesystem;

// The bits of a value (std::bit_cast, which the WebAssembly build's libc++ lacks).
template <class To, class From>
To bitsOf(const From& from) {
  static_assert(sizeof(To) == sizeof(From));
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

constexpr std::size_t kBinaryHeaderBytes = 80;
constexpr std::size_t kBinaryPreambleBytes = kBinaryHeaderBytes + 4;  // header, triangle count
constexpr std::size_t kBinaryTriangleBytes = 50;  // normal, 3 corners (12 floats), attribute

// Corners with exactly equal coordinates (==, so -0 and +0 are equal) become one vertex; no
// tolerance, so corners an ulp apart stay two vertices.
class Welder {
 public:
  VertexIndex add(const Eigen::Vector3d& p) {
    // +0.0 turns -0 into +0, so that equal coordinates have equal bits.
    const Key key{bitsOf<std::uint64_t>(p.x() + 0.0), bitsOf<std::uint64_t>(p.y() + 0.0),
                  bitsOf<std::uint64_t>(p.z() + 0.0)};
    const auto [it, inserted] =
        index_.try_emplace(key, static_cast<VertexIndex>(mesh_.vertices.size()));
    if (inserted) {
      mesh_.vertices.push_back(p);
    }
    return it->second;
  }
  void addTriangle(const std::array<Eigen::Vector3d, 3>& corners) {
    mesh_.triangles.push_back({add(corners[0]), add(corners[1]), add(corners[2])});
  }
  TriangleMesh take() { return std::move(mesh_); }

 private:
  struct Key {
    std::uint64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k.x * 0x9E3779B97F4A7C15ULL;
      h = (h ^ (h >> 29) ^ k.y) * 0xBF58476D1CE4E5B9ULL;
      h = (h ^ (h >> 31) ^ k.z) * 0x94D049BB133111EBULL;
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  TriangleMesh mesh_;
  std::unordered_map<Key, VertexIndex, KeyHash> index_;
};

std::uint32_t readLittleEndian32(const char* bytes) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k) {
    value = (value << 8) | static_cast<unsigned char>(bytes[k]);
  }
  return value;
}

// The triangle count a binary header declares, when the file's size is exactly what that
// count needs; nothing otherwise.
std::optional<std::uint32_t> binaryTriangleCount(std::string_view data) {
  if (data.size() < kBinaryPreambleBytes) {
    return std::nullopt;
  }
  const std::uint32_t count = readLittleEndian32(data.data() + kBinaryHeaderBytes);
  if (kBinaryPreambleBytes + std::uint64_t{count} * kBinaryTriangleBytes != data.size()) {
    return std::nullopt;
  }
  return count;
}

TriangleMesh parseBinary(const fs::path& path, std::string_view data, std::uint32_t count) {
  Welder welder;
  for (std::uint32_t t = 0; t < count; ++t) {
    // After the normal (3 floats, ignored): three corners of three little-endian floats.
    const char* record = data.data() + kBinaryPreambleBytes + std::size_t{t} * kBinaryTriangleBytes;
    std::array<Eigen::Vector3d, 3> corners;
    for (int c = 0; c < 3; ++c) {
      for (int axis = 0; axis < 3; ++axis) {
        const std::uint32_t bits = readLittleEndian32(record + 12 + 12 * c + 4 * axis);
        corners[c][axis] = static_cast<double>(bitsOf<float>(bits));
      }
      if (!corners[c].allFinite()) {
        fail(path, "triangle " + std::to_string(t) + " corner " + std::to_string(c) +
                       " has a non-finite coordinate " + formatPoint(corners[c]));
      }
    }
    welder.addTriangle(corners);
  }
  if (count == 0) {
    fail(path, "the file has no faces (empty mesh)");
  }
  return welder.take();
}

// ASCII STL, one statement per line:
//   solid [name]
//     facet normal nx ny nz      (the normal is read as three numbers and ignored)
//       outer loop
//         vertex x y z           (exactly three, finite)
//       endloop
//     endfacet
//   endsolid [name]
// several solids may follow one another. Keywords are lower case.
class AsciiReader {
 public:
  explicit AsciiReader(const fs::path& path) : path_(path) {}

  void readLine(const std::vector<std::string_view>& tokens, std::size_t line) {
    const std::string_view word = tokens[0];
    switch (stage_) {
      case Stage::Solid:
        expect(word == "solid", line, "'solid'", word);
        stage_ = Stage::Facet;
        return;
      case Stage::Facet:
        if (word == "endsolid") {
          stage_ = Stage::Solid;
          return;
        }
        expect(word == "facet" && tokens.size() > 1 && tokens[1] == "normal", line,
               "'facet normal' or 'endsolid'", word);
        if (tokens.size() != 5) {
          failAt(path_, line,
                 "expected 3 normal coordinates, found " + std::to_string(tokens.size() - 2) +
                     " values");
        }
        for (std::size_t k = 2; k < 5; ++k) {
          if (!parseDouble(tokens[k])) {
            failAt(path_, line, "invalid normal coordinate " + quote(tokens[k]));
          }
        }
        stage_ = Stage::Loop;
        return;
      case Stage::Loop:
        expect(tokens.size() == 2 && word == "outer" && tokens[1] == "loop", line, "'outer loop'",
               word);
        corners_ = 0;
        stage_ = Stage::Vertex;
        return;
      case Stage::Vertex:
        if (word == "endloop") {
          if (corners_ != 3) {
            failAt(path_, line,
                   "facet has " + std::to_string(corners_) +
                       " vertices; an STL facet is a triangle (exactly 3)");
          }
          stage_ = Stage::EndFacet;
          return;
        }
        expect(word == "vertex", line, "'vertex' or 'endloop'", word);
        readVertex(tokens, line);
        return;
      case Stage::EndFacet:
        expect(tokens.size() == 1 && word == "endfacet", line, "'endfacet'", word);
        welder_.addTriangle(triangle_);
        stage_ = Stage::Facet;
        return;
    }
  }

  TriangleMesh finish(std::size_t lineCount) {
    if (stage_ != Stage::Solid) {
      failAt(path_, std::max<std::size_t>(lineCount, 1),
             "unexpected end of file: expected " + std::string(expected()));
    }
    TriangleMesh mesh = welder_.take();
    if (mesh.triangles.empty()) {
      fail(path_, "the file has no faces (empty mesh)");
    }
    return mesh;
  }

 private:
  enum class Stage { Solid, Facet, Loop, Vertex, EndFacet };

  void expect(bool ok, std::size_t line, const char* what, std::string_view found) const {
    if (!ok) {
      failAt(path_, line, std::string("expected ") + what + ", found " + quote(found));
    }
  }

  const char* expected() const {
    switch (stage_) {
      case Stage::Solid:
        return "'solid'";
      case Stage::Facet:
        return "'facet normal' or 'endsolid'";
      case Stage::Loop:
        return "'outer loop'";
      case Stage::Vertex:
        return "'vertex' or 'endloop'";
      case Stage::EndFacet:
        return "'endfacet'";
    }
    return "";
  }

  void readVertex(const std::vector<std::string_view>& tokens, std::size_t line) {
    if (tokens.size() != 4) {
      failAt(path_, line,
             "expected 3 coordinates, found " + std::to_string(tokens.size() - 1) + " values");
    }
    if (corners_ == 3) {
      failAt(path_, line, "facet has more than 3 vertices; an STL facet is a triangle (exactly 3)");
    }
    if (const std::optional<std::string> problem =
            parseCoordinates(tokens, 1, triangle_[corners_])) {
      failAt(path_, line, *problem);
    }
    ++corners_;
  }

  const fs::path& path_;
  Stage stage_ = Stage::Solid;
  std::size_t corners_ = 0;
  std::array<Eigen::Vector3d, 3> triangle_;
  Welder welder_;
};

bool startsWithSolid(std::string_view data) {
  std::size_t k = 0;
  while (k < data.size() && (isBlank(data[k]) || data[k] == '\n' || data[k] == '\r')) {
    ++k;
  }
  return data.substr(k, 5) == "solid";
}

}  // namespace

// A file whose size is exactly what its binary header declares is binary, even when its
// 80-byte header starts with "solid" (as many exporters write it); anything else must be ASCII.
TriangleMesh parseStl(const fs::path& path, std::string_view data) {
  if (const std::optional<std::uint32_t> count = binaryTriangleCount(data)) {
    return parseBinary(path, data, *count);
  }
  // ASCII STL is text: a NUL byte means a binary file whose size does not match its header.
  if (!startsWithSolid(data) ||
      (data.size() >= kBinaryPreambleBytes && data.find('\0') != std::string_view::npos)) {
    if (data.size() < kBinaryPreambleBytes) {
      fail(path, "not an STL file: " + std::to_string(data.size()) +
                     " bytes, too short for a binary STL (at least 84) and not starting with "
                     "'solid' as an ASCII STL does");
    }
    const std::uint32_t declared = readLittleEndian32(data.data() + kBinaryHeaderBytes);
    fail(path,
         "not an STL file: as binary STL its header declares " + std::to_string(declared) +
             " triangles, which take 84 + 50 * " + std::to_string(declared) + " = " +
             std::to_string(kBinaryPreambleBytes + std::uint64_t{declared} * kBinaryTriangleBytes) +
             " bytes, but the file has " + std::to_string(data.size()) +
             " (not an ASCII STL either: " +
             (startsWithSolid(data) ? "it holds NUL bytes" : "it does not start with 'solid'") +
             ")");
  }
  AsciiReader reader(path);
  const std::size_t lineCount = forEachLine(data, [&](std::string_view raw, std::size_t line) {
    const std::vector<std::string_view> tokens = tokenize(raw);
    if (!tokens.empty()) {
      reader.readLine(tokens, line);
    }
  });
  return reader.finish(lineCount);
}

}  // namespace recode::core::detail
