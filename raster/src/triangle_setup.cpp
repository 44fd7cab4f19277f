#include "recode/raster/triangle_setup.hpp"

#include "triangle_setup_steps.hpp"

namespace recode::raster {

std::optional<TriangleCoverage> setupCoverage(const FixedVertex& v0, const FixedVertex& v1,
                                              const FixedVertex& v2) {
  // One named result on every path, so that it is built in the caller's storage.
  std::optional<TriangleCoverage> t(std::in_place);
  if (detail::coverageInto(v0, v1, v2, *t) == 0)
    t.reset();
  return t;
}

std::optional<TriangleSetup> setupTriangle(const FixedVertex& v0, const FixedVertex& v1,
                                           const FixedVertex& v2) {
  // One named result on every path, so that it is built in the caller's storage.
  std::optional<TriangleSetup> setup(std::in_place);
  if (!setupTriangleInto(v0, v1, v2, *setup))
    setup.reset();
  return setup;
}

bool setupTriangleInto(const FixedVertex& v0, const FixedVertex& v1, const FixedVertex& v2,
                       TriangleSetup& t) {
  return detail::setupInto(v0, v1, v2, t);
}

}  // namespace recode::raster
