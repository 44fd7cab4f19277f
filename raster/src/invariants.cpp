#include "recode/raster/invariants.hpp"

#include <cstdio>
#include <cstdlib>

namespace recode::raster {

void invariantFailed(const char* condition, const char* what, const char* file, int line) {
  std::fprintf(stderr, "recode: invariant failed: %s (%s) at %s:%d\n", what, condition, file, line);
  std::fflush(stderr);
  std::abort();
}

}  // namespace recode::raster
