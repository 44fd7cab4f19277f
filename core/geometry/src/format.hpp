#pragma once
// Internal helpers for building error messages (not installed, not public API).

#include <string>

#include <Eigen/Core>

#include "recode/io/double_text.hpp"

namespace recode::core::detail {

// Shortest text that reads back as the same double ("0.1", "-2", "1e-300", "nan", "inf").
inline std::string formatDouble(double value) {
  return io::shortestText(value);
}

// "(x, y, z)" with formatDouble for each coordinate.
inline std::string formatPoint(const Eigen::Vector3d& p) {
  std::string text;
  text += '(';
  text += formatDouble(p.x());
  text += ", ";
  text += formatDouble(p.y());
  text += ", ";
  text += formatDouble(p.z());
  text += ')';
  return text;
}

}  // namespace recode::core::detail
