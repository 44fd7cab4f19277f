#include "recode/raster/device_checks.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "recode/raster/state.hpp"

namespace recode::raster {

namespace {

void checkVertex(const WindowVertex& v, std::uint32_t index) {
  const auto bad = [&](const char* what) {
    throw std::invalid_argument("drawTriangles: vertex " + std::to_string(index) + " (" +
                                std::to_string(v.x) + ", " + std::to_string(v.y) + ", " +
                                std::to_string(v.z) + ") " + what);
  };
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    bad("is not finite");
  if (std::fabs(v.x) > kMaxWindowCoordinate || std::fabs(v.y) > kMaxWindowCoordinate)
    bad("lies beyond the +-32768 pixel range of 24.8 fixed point");
  if (v.z < 0.0f || v.z > 1.0f)
    bad("has depth outside [0, 1]");
}

}  // namespace

void checkFramebufferSize(int width, int height) {
  if (width < 1 || height < 1 || width > kMaxFramebufferSize || height > kMaxFramebufferSize) {
    throw std::invalid_argument("framebuffer size " + std::to_string(width) + "x" +
                                std::to_string(height) + " is outside 1.." +
                                std::to_string(kMaxFramebufferSize) + " in each dimension");
  }
}

namespace {

void checkIndexCount(std::size_t count) {
  if (count % 3 != 0) {
    throw std::invalid_argument("drawTriangles: index count " + std::to_string(count) +
                                " is not a multiple of 3");
  }
}

void checkIndex(std::size_t vertexCount, std::uint32_t index, std::size_t position) {
  if (index >= vertexCount) {
    throw std::invalid_argument("drawTriangles: index " + std::to_string(index) + " at position " +
                                std::to_string(position) + " is out of range (" +
                                std::to_string(vertexCount) + " vertices)");
  }
}

}  // namespace

void checkIndices(std::size_t vertexCount, std::span<const std::uint32_t> indices) {
  checkIndexCount(indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k)
    checkIndex(vertexCount, indices[k], k);
}

void checkDraw(std::span<const WindowVertex> vertices, std::span<const std::uint32_t> indices) {
  // Index by index, so that the first bad index or vertex is the one named.
  checkIndexCount(indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k) {
    checkIndex(vertices.size(), indices[k], k);
    checkVertex(vertices[indices[k]], indices[k]);
  }
}

void checkCompareFunc(CompareFunc func, const char* what) {
  if (static_cast<int>(func) > static_cast<int>(CompareFunc::Always))
    throw std::invalid_argument(std::string(what) + ": unknown compare function " +
                                std::to_string(static_cast<int>(func)));
}

void checkStencilOps(const StencilOps& ops) {
  for (const StencilOp op : {ops.stencilFail, ops.depthFail, ops.depthPass})
    if (static_cast<int>(op) > static_cast<int>(StencilOp::Invert))
      throw std::invalid_argument("setStencilOps: unknown stencil op " +
                                  std::to_string(static_cast<int>(op)));
}

void checkFace(Face face) {
  if (static_cast<int>(face) > static_cast<int>(Face::Both))
    throw std::invalid_argument("setStencilOps: unknown face " +
                                std::to_string(static_cast<int>(face)));
}

void checkCullMode(CullMode mode) {
  if (static_cast<int>(mode) > static_cast<int>(CullMode::Back))
    throw std::invalid_argument("setCullMode: unknown cull mode " +
                                std::to_string(static_cast<int>(mode)));
}

}  // namespace recode::raster
