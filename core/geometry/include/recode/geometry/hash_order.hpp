#pragma once
// The order in which GCC's libstdc++ lists the keys of a std::unordered_map<std::uint32_t, T>
// (identity hash, maximum load factor 1), kept without the map. The convex hull's face
// triangulation and the cap of a clipped block start each boundary loop at the map's first key,
// and the reference's bits follow from where a loop starts; the native build has always used
// libstdc++'s order. Keeping that order here, on every standard library, gives the same bits
// with libc++ (the WebAssembly build, wasm/) as with libstdc++, without changing a native bit.
// tests/core/geometry/hash_order_test.cpp compares it with libstdc++'s own map.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace recode::core {

class LibstdcxxHashOrder {
 public:
  // Adds a key that is not in the map (as std::unordered_map::operator[] or emplace would).
  void insert(std::uint32_t key);
  // Removes a key that is in the map (as std::unordered_map::erase).
  void erase(std::uint32_t key);
  [[nodiscard]] bool empty() const { return size_ == 0; }
  // The key the map's begin() would point to; the map must not be empty.
  [[nodiscard]] std::uint32_t first() const;

 private:
  static constexpr int kNone = -1;         // no node; an empty bucket
  static constexpr int kBeforeBegin = -2;  // the list head, before the first node

  [[nodiscard]] std::size_t bucketOf(int node) const;
  [[nodiscard]] int nextOf(int before) const;  // the node after `before` (a node or the head)
  void setNext(int before, int node);
  void rehash(std::size_t bucketCount);

  std::vector<std::uint32_t> keys_;  // by node, in insertion order
  std::vector<int> next_;            // by node: the next node in the map's list
  int head_ = kNone;                 // the first node
  std::vector<int> buckets_;         // by bucket: the node before its first node, or kNone
  std::size_t bucketCount_ = 1;
  std::size_t size_ = 0;
  std::size_t nextResize_ = 0;  // more elements than this rehash the map first
};

}  // namespace recode::core
