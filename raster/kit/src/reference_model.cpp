#include "recode/kit/reference_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "model_plane.hpp"
#include "model_quantise.hpp"

namespace recode::kit {

using namespace recode::raster;

bool modelCompare(int func, unsigned incoming, unsigned stored) {
  const bool lt = incoming<stored, eq = incoming == stored, gt = incoming> stored;
  const bool table[8] = {false, lt, eq, lt || eq, gt, !eq, gt || eq, true};
  return table[func];
}

unsigned modelStencilOp(int op, unsigned s, unsigned ref) {
  switch (op) {
    case 0:
      return s;
    case 1:
      return 0;
    case 2:
      return ref;
    case 3:
      return s < 255 ? s + 1 : 255;
    case 4:
      return (s + 1) % 256;
    case 5:
      return s > 0 ? s - 1 : 0;
    case 6:
      return (s + 255) % 256;
    default:
      return 255 - s;
  }
}

std::uint32_t modelQuantize(double z) {
  if (std::isnan(z) || z <= 0.0)
    return 0;
  if (z >= 1.0)
    return 16777215u;
  return static_cast<std::uint32_t>(std::nearbyint(z * 16777215.0));
}

ReferenceModel::ReferenceModel(int width, int height, Variant variant)
    : w_(width),
      h_(height),
      variant_(variant),
      depth_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 16777215u),
      stencil_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0),
      sx1_(width),
      sy1_(height) {}

std::uint32_t ReferenceModel::quantize(double z) const {
  const detail::Rounding r = detail::rounding(variant_);
  return r == detail::Rounding::NearestEven ? modelQuantize(z) : detail::quantiseWith(r, z);
}

unsigned ReferenceModel::stencilOp(int op, unsigned s) const {
  if (variant_ == Variant::IncrWraps && op == 3)
    return (s + 1) % 256;
  if (variant_ == Variant::DecrWraps && op == 5)
    return (s + 255) % 256;
  return modelStencilOp(op, s, ref_);
}

void ReferenceModel::clearDepth(double value) {
  if (!depthWrite_ && variant_ != Variant::DepthClearIgnoresWriteMask)
    return;
  const bool whole = variant_ == Variant::ClearIgnoresScissor;
  for (int y = whole ? 0 : sy0_; y < (whole ? h_ : sy1_); ++y)
    for (int x = whole ? 0 : sx0_; x < (whole ? w_ : sx1_); ++x)
      depth_[idx(x, y)] = quantize(value);
}

void ReferenceModel::clearStencil(unsigned value) {
  const bool whole = variant_ == Variant::ClearIgnoresScissor;
  const unsigned mask = variant_ == Variant::StencilClearIgnoresWriteMask ? 255u : writeMask_;
  for (int y = whole ? 0 : sy0_; y < (whole ? h_ : sy1_); ++y)
    for (int x = whole ? 0 : sx0_; x < (whole ? w_ : sx1_); ++x) {
      std::uint8_t& s = stencil_[idx(x, y)];
      s = static_cast<std::uint8_t>((value & mask) | (s & (255u - mask)));
    }
}

void ReferenceModel::run(const std::vector<Command>& commands) {
  for (const Command& c : commands) {
    std::visit(
        [this](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, cmd::Scissor>) {
            sx0_ = std::clamp(v.rect.x0, 0, w_);
            sy0_ = std::clamp(v.rect.y0, 0, h_);
            sx1_ = std::clamp(v.rect.x1, sx0_, w_);
            sy1_ = std::clamp(v.rect.y1, sy0_, h_);
          } else if constexpr (std::is_same_v<T, cmd::ClearDepth>) {
            clearDepth(v.value);
          } else if constexpr (std::is_same_v<T, cmd::ClearStencil>) {
            clearStencil(v.value);
          } else if constexpr (std::is_same_v<T, cmd::DepthFunc>) {
            depthFunc_ = static_cast<int>(v.func);
          } else if constexpr (std::is_same_v<T, cmd::DepthWriteMask>) {
            depthWrite_ = v.write;
          } else if constexpr (std::is_same_v<T, cmd::StencilFunc>) {
            stencilFunc_ = static_cast<int>(v.func);
            ref_ = v.ref;
            valueMask_ = v.valueMask;
          } else if constexpr (std::is_same_v<T, cmd::StencilOpsCmd>) {
            const int ops[3] = {static_cast<int>(v.ops.stencilFail),
                                static_cast<int>(v.ops.depthFail),
                                static_cast<int>(v.ops.depthPass)};
            if (v.face != Face::Back)
              std::copy(ops, ops + 3, opsFront_);
            if (v.face != Face::Front)
              std::copy(ops, ops + 3, opsBack_);
          } else if constexpr (std::is_same_v<T, cmd::StencilWriteMask>) {
            writeMask_ = v.mask;
          } else if constexpr (std::is_same_v<T, cmd::Cull>) {
            cull_ = static_cast<int>(v.mode);
          } else {
            draw(v);
          }
        },
        c);
  }
}

namespace {

// A 24.8 coordinate on a sub-pixel variant's coarser grid (the contract's 8 bits otherwise).
long long toSubPixelGrid(long long v, Variant variant) {
  switch (variant) {
    case Variant::SubPixel4Nearest:
      return 16 * static_cast<long long>(std::nearbyint(static_cast<double>(v) / 16.0));
    case Variant::SubPixel4Floor:
      return 16 * static_cast<long long>(std::floor(static_cast<double>(v) / 16.0));
    case Variant::SubPixel4Ceil:
      return 16 * static_cast<long long>(std::ceil(static_cast<double>(v) / 16.0));
    case Variant::SubPixel4HalfUp:
      return 16 * static_cast<long long>(std::floor(static_cast<double>(v) / 16.0 + 0.5));
    case Variant::SubPixel6Nearest:
      return 4 * static_cast<long long>(std::nearbyint(static_cast<double>(v) / 4.0));
    default:
      return v;
  }
}

}  // namespace

void ReferenceModel::draw(const cmd::Draw& d) {
  if (variant_ == Variant::StrictLimits) {
    for (std::uint32_t i : d.indices) {
      const WindowVertex& v = d.vertices[i];
      if (std::fabs(v.x) >= 32768.0f || std::fabs(v.y) >= 32768.0f || v.z <= 0.0f || v.z >= 1.0f)
        throw std::invalid_argument("strict_limits: a vertex at the limits of its range");
    }
  }
  for (std::size_t t = 0; t + 2 < d.indices.size(); t += 3) {
    Triangle tri;
    for (int k = 0; k < 3; ++k) {
      const WindowVertex& v = d.vertices[d.indices[t + static_cast<std::size_t>(k)]];
      tri.X[k] = toSubPixelGrid(
          static_cast<long long>(std::nearbyint(static_cast<double>(v.x) * 256.0)), variant_);
      tri.Y[k] = toSubPixelGrid(
          static_cast<long long>(std::nearbyint(static_cast<double>(v.y) * 256.0)), variant_);
      tri.Z[k] = v.z;
    }
    drawTriangle(tri);
  }
}

bool ReferenceModel::covers(const Triangle& t, const int order[3], long long px,
                            long long py) const {
  for (int k = 0; k < 3; ++k) {
    const int a = order[k], b = order[(k + 1) % 3];
    const long long dx = t.X[b] - t.X[a], dy = t.Y[b] - t.Y[a];
    long long sign;
    if (variant_ == Variant::EdgeFloat) {
      const float e = static_cast<float>(dx) * static_cast<float>(py - t.Y[a]) -
                      static_cast<float>(dy) * static_cast<float>(px - t.X[a]);
      sign = e > 0.0f ? 1 : (e < 0.0f ? -1 : 0);
    } else {
      sign = dx * (py - t.Y[a]) - dy * (px - t.X[a]);
    }
    const bool leftEdge = dy < 0;
    // Horizontal edges: the contract's bottom edges run right; a top-left rule's top edges
    // run left.
    const bool horizontalOwner = dy == 0 && (variant_ == Variant::TopLeftFill ? dx < 0 : dx > 0);
    if (!(sign > 0 || (sign == 0 && (leftEdge || horizontalOwner))))
      return false;
  }
  return true;
}

void ReferenceModel::drawTriangle(const Triangle& t) {
  const long long area =
      (t.X[1] - t.X[0]) * (t.Y[2] - t.Y[0]) - (t.X[2] - t.X[0]) * (t.Y[1] - t.Y[0]);
  if (area == 0)
    return;
  const bool ccw = area > 0;
  const bool front = variant_ == Variant::SwappedFacing ? !ccw : ccw;
  if ((cull_ == 1 && front) || (cull_ == 2 && !front))
    return;
  // Counter-clockwise order for the inside test; the depth plane keeps the submitted order.
  const int order[3] = {0, ccw ? 1 : 2, ccw ? 2 : 1};
  detail::ModelPlane plane(t.X, t.Y, t.Z, order, variant_);
  for (int y = sy0_; y < sy1_; ++y) {
    for (int x = sx0_; x < sx1_; ++x) {
      if (covers(t, order, 256LL * x + 128, 256LL * y + 128))
        fragment(x, y, front, quantize(plane.at(x, y)));
    }
  }
}

void ReferenceModel::fragment(int x, int y, bool front, std::uint32_t z) {
  std::uint8_t& s = stencil_[idx(x, y)];
  std::uint32_t& d = depth_[idx(x, y)];
  const int* ops = front ? opsFront_ : opsBack_;
  const unsigned mask = variant_ == Variant::IgnoreValueMask ? 255u : valueMask_;
  int op;
  if (!modelCompare(stencilFunc_, ref_ & mask, s & mask)) {
    op = ops[0];
  } else if (!modelCompare(depthFunc_, z, d)) {
    op = ops[1];
  } else {
    op = ops[2];
    if (depthWrite_)
      d = z;
  }
  const unsigned next = stencilOp(op, s);
  s = static_cast<std::uint8_t>((next & writeMask_) | (s & (255u - writeMask_)));
}

}  // namespace recode::kit
