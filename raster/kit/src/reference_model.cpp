#include "reference_model.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace recode::test {

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

ReferenceModel::ReferenceModel(int width, int height)
    : w_(width),
      h_(height),
      depth_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 16777215u),
      stencil_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0),
      sx1_(width),
      sy1_(height) {}

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
            if (!depthWrite_)
              return;
            for (int y = sy0_; y < sy1_; ++y)
              for (int x = sx0_; x < sx1_; ++x)
                depth_[idx(x, y)] = modelQuantize(v.value);
          } else if constexpr (std::is_same_v<T, cmd::ClearStencil>) {
            for (int y = sy0_; y < sy1_; ++y)
              for (int x = sx0_; x < sx1_; ++x) {
                std::uint8_t& s = stencil_[idx(x, y)];
                s = static_cast<std::uint8_t>((v.value & writeMask_) | (s & (255u - writeMask_)));
              }
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

void ReferenceModel::draw(const cmd::Draw& d) {
  for (std::size_t t = 0; t + 2 < d.indices.size(); t += 3) {
    long long X[3], Y[3];
    double Z[3];
    for (int k = 0; k < 3; ++k) {
      const WindowVertex& v = d.vertices[d.indices[t + static_cast<std::size_t>(k)]];
      X[k] = static_cast<long long>(std::nearbyint(static_cast<double>(v.x) * 256.0));
      Y[k] = static_cast<long long>(std::nearbyint(static_cast<double>(v.y) * 256.0));
      Z[k] = static_cast<double>(v.z);
    }
    const long long area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    if (area == 0)
      continue;
    const bool front = area > 0;
    if ((cull_ == 1 && front) || (cull_ == 2 && !front))
      continue;
    // Counter-clockwise order for the inside test.
    const int order[3] = {0, front ? 1 : 2, front ? 2 : 1};
    // Depth plane in the submitted order, as the contract spells it out.
    const double dz1 = Z[1] - Z[0], dz2 = Z[2] - Z[0];
    const double ex1 = static_cast<double>(X[1] - X[0]), ey1 = static_cast<double>(Y[1] - Y[0]);
    const double ex2 = static_cast<double>(X[2] - X[0]), ey2 = static_cast<double>(Y[2] - Y[0]);
    const double a2 = static_cast<double>(area);
    const double dzdx = (dz1 * ey2 - dz2 * ey1) / a2;
    const double dzdy = (dz2 * ex1 - dz1 * ex2) / a2;
    for (int y = sy0_; y < sy1_; ++y) {
      for (int x = sx0_; x < sx1_; ++x) {
        const long long px = 256LL * x + 128, py = 256LL * y + 128;
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
          const int a = order[k], b = order[(k + 1) % 3];
          const long long cross = (X[b] - X[a]) * (py - Y[a]) - (Y[b] - Y[a]) * (px - X[a]);
          const bool leftEdge = Y[b] < Y[a];
          const bool bottomEdge = Y[b] == Y[a] && X[b] > X[a];
          inside = cross > 0 || (cross == 0 && (leftEdge || bottomEdge));
        }
        if (!inside)
          continue;
        const double z =
            (Z[0] + dzdx * static_cast<double>(px - X[0])) + dzdy * static_cast<double>(py - Y[0]);
        fragment(x, y, front, modelQuantize(z));
      }
    }
  }
}

void ReferenceModel::fragment(int x, int y, bool front, std::uint32_t z) {
  std::uint8_t& s = stencil_[idx(x, y)];
  std::uint32_t& d = depth_[idx(x, y)];
  const int* ops = front ? opsFront_ : opsBack_;
  int op;
  if (!modelCompare(stencilFunc_, ref_ & valueMask_, s & valueMask_)) {
    op = ops[0];
  } else if (!modelCompare(depthFunc_, z, d)) {
    op = ops[1];
  } else {
    op = ops[2];
    if (depthWrite_)
      d = z;
  }
  const unsigned next = modelStencilOp(op, s, ref_);
  s = static_cast<std::uint8_t>((next & writeMask_) | (s & (255u - writeMask_)));
}

}  // namespace recode::test
