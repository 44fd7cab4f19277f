#include "recode/geometry/hash_order.hpp"

#include <array>
#include <stdexcept>
#include <utility>

namespace recode::core {

namespace {

// libstdc++'s bucket counts as a map grows one key at a time: at the first key, and whenever a
// key would make the elements outnumber the buckets (load factor 1), the next of these.
constexpr std::array<std::size_t, 19> kBucketCounts = {
    13,    29,    59,    127,    257,    541,    1109,    2357,    5087,   10273,
    20753, 42043, 85229, 172933, 351061, 712697, 1447153, 2938679, 5967347};

std::size_t nextBucketCount(std::size_t current) {
  for (const std::size_t count : kBucketCounts)
    if (count > current)
      return count;
  throw std::length_error("LibstdcxxHashOrder: more than 5967347 keys");
}

}  // namespace

std::size_t LibstdcxxHashOrder::bucketOf(int node) const {
  return keys_[static_cast<std::size_t>(node)] % bucketCount_;  // std::hash: the key itself
}

int LibstdcxxHashOrder::nextOf(int before) const {
  return before == kBeforeBegin ? head_ : next_[static_cast<std::size_t>(before)];
}

void LibstdcxxHashOrder::setNext(int before, int node) {
  if (before == kBeforeBegin)
    head_ = node;
  else
    next_[static_cast<std::size_t>(before)] = node;
}

// As _Hashtable::_M_rehash_aux for unique keys: the list is walked in order and each node put
// at the front of the list when its new bucket is empty, else at the front of its bucket.
void LibstdcxxHashOrder::rehash(std::size_t bucketCount) {
  std::vector<int> buckets(bucketCount, kNone);
  int node = head_;
  head_ = kNone;
  std::size_t beginBucket = 0;
  bucketCount_ = bucketCount;
  while (node != kNone) {
    const int following = next_[static_cast<std::size_t>(node)];
    const std::size_t bucket = bucketOf(node);
    if (buckets[bucket] == kNone) {
      next_[static_cast<std::size_t>(node)] = head_;
      head_ = node;
      buckets[bucket] = kBeforeBegin;
      if (next_[static_cast<std::size_t>(node)] != kNone)
        buckets[beginBucket] = node;
      beginBucket = bucket;
    } else {
      const int before = buckets[bucket];
      next_[static_cast<std::size_t>(node)] = nextOf(before);
      setNext(before, node);
    }
    node = following;
  }
  buckets_ = std::move(buckets);
  nextResize_ = bucketCount;
}

// As _M_insert_unique_node: rehash if needed, then _M_insert_bucket_begin.
void LibstdcxxHashOrder::insert(std::uint32_t key) {
  if (size_ + 1 > nextResize_)  // the first key makes 13 buckets, later ones the next count
    rehash(nextBucketCount(bucketCount_));
  const int node = static_cast<int>(keys_.size());
  keys_.push_back(key);
  next_.push_back(kNone);
  const std::size_t bucket = bucketOf(node);
  if (buckets_[bucket] != kNone) {
    const int before = buckets_[bucket];
    next_[static_cast<std::size_t>(node)] = nextOf(before);
    setNext(before, node);
  } else {
    next_[static_cast<std::size_t>(node)] = head_;
    head_ = node;
    if (next_[static_cast<std::size_t>(node)] != kNone)
      buckets_[bucketOf(next_[static_cast<std::size_t>(node)])] = node;
    buckets_[bucket] = kBeforeBegin;
  }
  ++size_;
}

// As _M_erase for unique keys: the node is unlinked, and the buckets that pointed at it or
// began with it are mended (_M_remove_bucket_begin).
void LibstdcxxHashOrder::erase(std::uint32_t key) {
  int before = kBeforeBegin;
  int node = head_;
  while (node != kNone && keys_[static_cast<std::size_t>(node)] != key) {
    before = node;
    node = next_[static_cast<std::size_t>(node)];
  }
  if (node == kNone)
    throw std::logic_error("LibstdcxxHashOrder::erase: the key is not in the map");
  const std::size_t bucket = bucketOf(node);
  const int following = next_[static_cast<std::size_t>(node)];
  if (before == buckets_[bucket]) {
    const std::size_t followingBucket = following == kNone ? 0 : bucketOf(following);
    if (following == kNone || followingBucket != bucket) {
      if (following != kNone)
        buckets_[followingBucket] = buckets_[bucket];
      buckets_[bucket] = kNone;
    }
  } else if (following != kNone) {
    const std::size_t followingBucket = bucketOf(following);
    if (followingBucket != bucket)
      buckets_[followingBucket] = before;
  }
  setNext(before, following);
  --size_;
}

std::uint32_t LibstdcxxHashOrder::first() const {
  if (head_ == kNone)
    throw std::logic_error("LibstdcxxHashOrder::first: the map is empty");
  return keys_[static_cast<std::size_t>(head_)];
}

}  // namespace recode::core
