#pragma once
// The one exception type for bad mesh input: unreadable or malformed files (mesh_io.hpp) and
// meshes that are not valid convex blocks (validate.hpp).

#include <stdexcept>
#include <string>

namespace recode::core {

// Thrown for every problem with mesh input. The message names where the problem is
// ("<path>:<line>: ", "<path>: " or "<sourceName>: ") followed by what is wrong.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace recode::core
