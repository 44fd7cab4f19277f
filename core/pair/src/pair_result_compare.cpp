// firstDifference: two pair results compared field by field, timing aside.
#include "recode/pair/pair_result_compare.hpp"

#include <cstddef>
#include <cstring>
#include <sstream>

namespace recode::core {

namespace {

// Doubles are compared by their bits: +0 and -0 differ, and a NaN equals itself.
bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool sameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return sameBits(a.x(), b.x()) && sameBits(a.y(), b.y()) && sameBits(a.z(), b.z());
}

std::string show(const raster::PixelRect& r) {
  std::ostringstream s;
  s << "[" << r.x0 << "," << r.y0 << ")-[" << r.x1 << "," << r.y1 << ")";
  return s.str();
}

std::string show(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return s.str();
}

template <class T>
std::string differs(const char* field, const T& a, const T& b) {
  std::ostringstream s;
  s.precision(17);
  s << field << ": " << a << " vs " << b;
  return s.str();
}

std::optional<std::string> compareCases(const PairResult& a, const PairResult& b) {
  for (std::size_t c = 0; c < a.caseCounts.size(); ++c)
    if (a.caseCounts[c] != b.caseCounts[c])
      return differs(("caseCounts[" + std::to_string(c) + "]").c_str(), a.caseCounts[c],
                     b.caseCounts[c]);
  if (a.caseMap.rect != b.caseMap.rect)
    return "caseMap.rect: " + show(a.caseMap.rect) + " vs " + show(b.caseMap.rect);
  for (std::size_t i = 0; i < a.caseMap.data.size() && i < b.caseMap.data.size(); ++i)
    if (a.caseMap.data[i] != b.caseMap.data[i])
      return differs(("caseMap.data[" + std::to_string(i) + "]").c_str(), int{a.caseMap.data[i]},
                     int{b.caseMap.data[i]});
  if (a.caseMap.data.size() != b.caseMap.data.size())
    return differs("caseMap.data.size()", a.caseMap.data.size(), b.caseMap.data.size());
  return std::nullopt;
}

std::optional<std::string> compareContact(const ContactRegion& a, const ContactRegion& b) {
  if (a.points.size() != b.points.size())
    return differs("contact.points.size()", a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if (!sameBits(a.points[i], b.points[i]))
      return "contact.points[" + std::to_string(i) + "]: " + show(a.points[i]) + " vs " +
             show(b.points[i]);
  if (!sameBits(a.box.min, b.box.min) || !sameBits(a.box.max, b.box.max))
    return "contact.box: " + show(a.box.min) + "-" + show(a.box.max) + " vs " + show(b.box.min) +
           "-" + show(b.box.max);
  if (a.pixels != b.pixels)
    return differs("contact.pixels", a.pixels, b.pixels);
  if (!sameBits(a.area, b.area))
    return differs("contact.area", a.area, b.area);
  if (!sameBits(a.maxDepth, b.maxDepth))
    return differs("contact.maxDepth", a.maxDepth, b.maxDepth);
  if (a.collapsedPixels != b.collapsedPixels)
    return differs("contact.collapsedPixels", a.collapsedPixels, b.collapsedPixels);
  if (a.normal.has_value() != b.normal.has_value())
    return differs("contact.normal.has_value()", a.normal.has_value(), b.normal.has_value());
  if (a.normal && (!sameBits(a.normal->normal, b.normal->normal) ||
                   !sameBits(a.normal->depth, b.normal->depth)))
    return "contact.normal: " + show(a.normal->normal) + " depth " +
           std::to_string(a.normal->depth) + " vs " + show(b.normal->normal) + " depth " +
           std::to_string(b.normal->depth);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> firstDifference(const PairResult& a, const PairResult& b) {
  if (a.collide != b.collide)
    return differs("collide", a.collide, b.collide);
  if (a.boxesOverlap != b.boxesOverlap)
    return differs("boxesOverlap", a.boxesOverlap, b.boxesOverlap);
  if (a.mor != b.mor)
    return "mor: " + show(a.mor) + " vs " + show(b.mor);
  if (a.interferingPixels != b.interferingPixels)
    return differs("interferingPixels", a.interferingPixels, b.interferingPixels);
  if (auto d = compareCases(a, b))
    return d;
  if (a.contactRect != b.contactRect)
    return "contactRect: " + show(a.contactRect) + " vs " + show(b.contactRect);
  if (auto d = compareContact(a.contact, b.contact))
    return d;
  if (a.stencilPixelsRead != b.stencilPixelsRead)
    return differs("stencilPixelsRead", a.stencilPixelsRead, b.stencilPixelsRead);
  if (a.depthPixelsRead != b.depthPixelsRead)
    return differs("depthPixelsRead", a.depthPixelsRead, b.depthPixelsRead);
  if (!sameBits(a.depthMin, b.depthMin))
    return differs("depthMin", a.depthMin, b.depthMin);
  if (!sameBits(a.depthMax, b.depthMax))
    return differs("depthMax", a.depthMax, b.depthMax);
  return std::nullopt;
}

}  // namespace recode::core
