// CPU/GL parity: replay, compare after every buffer change, and explain what differs.
//
// The reference's fragment depth q follows the contract exactly; llvmpipe's q' is a float
// evaluation of the same plane, |q' - q| <= t for a per-fragment tolerance t (DepthErrorBound
// below). A depth test compares q' with the stored depth d', which differs from the
// reference's d by at most s: the read-back difference before the draw, then updated by each
// fragment of the draw. So GL's test can only come out differently where |q - d| <= t + s:
// such a fragment marks its pixel "near", and there the stencil may differ. The depth never
// may differ by more than s: after a near fragment either side may or may not have written,
// so s grows to max(s, t) + |q - d|. A pixel whose stencil leaves a draw different stays near
// (its later stencil tests start from different values) until the stencils agree again.

#include "recode/verify/gl_parity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "recode/backends/gl_device.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/fragment_stage.hpp"
#include "recode/raster/pipeline.hpp"
#include "recode/raster/pixel_buffer.hpp"

namespace recode::verify {

namespace {

using raster::PixelRect;

std::uint32_t absDiff(std::uint32_t a, std::uint32_t b) {
  return a > b ? a - b : b - a;
}

// A first-order bound, in 24-bit LSB, on how far llvmpipe's float depth for one triangle can be
// from the contract's. llvmpipe (lp_state_setup.c, lp_bld_interp.c) computes in single
// precision, with pixel positions p = window - 0.5 and v0 the first vertex of its setup:
//   det = dx01*dy20 - dx20*dy01,  dzdx = dz01*(dy20/det) - dz20*(dy01/det)  (dzdy alike)
//   a0  = z0 - (dzdx*x0 + dzdy*y0)          the plane's value at the framebuffer origin
//   z   = a0 + dzdx*x + dzdy*y              at each fragment (fused multiply-adds)
// and the origin is the top-left corner: Gallium stores a window-system framebuffer top row
// first, so y runs down from the top (y' = H - y). Far from that origin, on steep planes, the
// terms are much larger than z itself (Mesa's own comment in lp_state_setup.c calls this out).
// With u = 2^-24 (float's unit roundoff, one LSB of a value near 1):
// - each of the six roundings in a0 and z errs by at most u times a partial sum no larger
//   than S = |z0| + |gx|(|x0| + |x|) + |gy|(|y0| + |y|) (g the gradient per pixel): 6 S LSB;
// - the gradient carries the cancellation in det: relative error (k + 6) u with
//   k = (|dx01 dy20| + |dx20 dy01|) / |det|, times Px |x - x0| + Py |y - y0|, where Px, Py
//   are the gradient's terms without cancellation (a0 uses the same gradient, so its error
//   acts from v0 only);
// - both sides round to 24 bits: 1 LSB.
// Each term is taken at its worst over the three choices of v0 (llvmpipe may rotate the
// vertices) and over both y origins (top and bottom), so the bound does not hang on details
// of one Mesa version. Ordinary planes get a few LSB; the steep slivers of faces seen almost
// edge-on get tens, which llvmpipe does use.
class DepthErrorBound {
 public:
  DepthErrorBound(const std::array<raster::FixedVertex, 3>& v, int height) : height_(height) {
    for (int k = 0; k < 3; ++k) {
      x_[k] = static_cast<double>(v[k].x) / raster::kSubpixelOne - 0.5;
      y_[k] = static_cast<double>(v[k].y) / raster::kSubpixelOne - 0.5;
      z_[k] = static_cast<double>(v[k].z);
    }
    for (int r = 0; r < 3; ++r) {
      const int a = r, b = (r + 1) % 3, c = (r + 2) % 3;
      const double dx01 = x_[a] - x_[b], dy01 = y_[a] - y_[b];
      const double dx20 = x_[c] - x_[a], dy20 = y_[c] - y_[a];
      const double dz01 = z_[a] - z_[b], dz20 = z_[c] - z_[a];
      const double e = dx01 * dy20, f = dx20 * dy01, det = std::fabs(e - f);
      const double k = (std::fabs(e) + std::fabs(f)) / det;
      weightX_[r] = (k + 6.0) * (std::fabs(dz01 * dy20) + std::fabs(dz20 * dy01)) / det;
      weightY_[r] = (k + 6.0) * (std::fabs(dz20 * dx01) + std::fabs(dz01 * dx20)) / det;
      // The exact gradient, the same for every rotation.
      gx_ = std::fabs(dz01 * dy20 - dz20 * dy01) / det;
      gy_ = std::fabs(dz20 * dx01 - dz01 * dx20) / det;
    }
  }

  // The bound at the sample of pixel (x, y), in LSB (not rounded).
  [[nodiscard]] double at(int x, int y) const {
    const double px = x, py = y;  // the sample (x + 0.5, y + 0.5) in p coordinates
    // The same sample measured from the top: y' = H - (y + 0.5), minus 0.5.
    const double pyTop = static_cast<double>(height_) - 1.0 - py;
    double rounding = 0.0, gradient = 0.0;
    for (int r = 0; r < 3; ++r) {
      const double yTop = static_cast<double>(height_) - 1.0 - y_[r];
      const double ySpan =
          std::max(std::fabs(y_[r]) + std::fabs(py), std::fabs(yTop) + std::fabs(pyTop));
      const double s = std::fabs(z_[r]) + gx_ * (std::fabs(x_[r]) + std::fabs(px)) + gy_ * ySpan;
      rounding = std::max(rounding, 6.0 * s);
      gradient = std::max(
          gradient, weightX_[r] * std::fabs(px - x_[r]) + weightY_[r] * std::fabs(py - y_[r]));
    }
    return 1.0 + rounding + gradient;
  }

 private:
  int height_;
  double x_[3] = {}, y_[3] = {}, z_[3] = {};
  double weightX_[3] = {}, weightY_[3] = {};
  double gx_ = 0.0, gy_ = 0.0;
};

// What is known at one pixel of the compared region: the reference's values, and how far the
// candidate's may be from them.
struct PixelKnowledge {
  std::uint32_t depth = 0;  // the reference's
  std::uint8_t stencil = 0;
  // Bound on |candidate depth - reference depth|: the read-back difference, or the tolerance
  // of the fragment that wrote the depth since.
  std::uint32_t depthSlack = 0;
  bool near = false;     // a test here may have gone the other way
  bool written = false;  // depthSlack is a fragment's tolerance from this draw
};
using RegionState = raster::PixelBuffer<PixelKnowledge>;

// A read-back of the region, checked before it is trusted: the candidate is the device under
// test, so a wrong size is its fault, reported, not an invariant of ours.
template <class T>
raster::PixelBuffer<T> checkedReadBack(std::vector<T> values, const PixelRect& region) {
  if (values.size() != static_cast<std::size_t>(region.area()))
    throw std::runtime_error("GL parity: a device returned a read-back of the wrong size");
  return {region, std::move(values)};
}

// Re-runs each triangle's fragments on the reference's values with the contract's arithmetic
// and marks the pixels whose depth test was within reach of GL's rounding.
class NearDecisionSink final : public raster::TriangleSink {
 public:
  NearDecisionSink(const raster::RenderState& state, const GlParityOptions& options, int height,
                   RegionState& region)
      : state_(state), options_(options), height_(height), r_(region) {}

  void beginTriangle(const raster::TriangleSetup& triangle,
                     const std::array<raster::FixedVertex, 3>& snapped) override {
    tri_ = &triangle;
    ops_ = &state_.opsFor(triangle.frontFacing);
    bound_.reset();
    if (options_.planeErrorBound)
      bound_.emplace(snapped, height_);
  }

  void coveredBlock(int blockX, int blockY, std::uint64_t mask) override {
    const bool depthDecides = state_.depthFunc != raster::CompareFunc::Always &&
                              state_.depthFunc != raster::CompareFunc::Never;
    while (mask != 0) {
      const int bit = __builtin_ctzll(mask);
      mask &= mask - 1;
      const int x = blockX + (bit & (raster::kBlockSize - 1));
      const int y = blockY + bit / raster::kBlockSize;
      PixelKnowledge& p = r_.at(x, y);
      const std::uint32_t q = raster::quantizeDepth(
          tri_->depth.at(raster::pixelCentreFixed(x), raster::pixelCentreFixed(y)));
      const std::uint32_t tolerance = toleranceAt(x, y);
      const std::uint32_t d = p.depth;
      const bool stencilPasses = raster::stencilTestPasses(state_, p.stencil);
      const bool writes =
          stencilPasses && state_.depthWrite && raster::compare(state_.depthFunc, q, d);
      // The candidate's outcome may differ when its stencil may already differ (a pixel left
      // "near" by an earlier draw) or when the depth test was decided within reach.
      const std::uint32_t margin = absDiff(q, d);
      const bool depthNear =
          depthDecides && static_cast<std::uint64_t>(margin) <=
                              static_cast<std::uint64_t>(tolerance) + p.depthSlack;
      if (p.near || (stencilPasses && depthNear)) {
        p.near = true;
        p.written = false;
        // Either side may or may not write: the candidate keeps d' (within s of d) or writes
        // q' (within t of q), the reference keeps d or writes q.
        if (state_.depthWrite) {
          p.depthSlack = std::min(raster::kDepthMax, std::max(p.depthSlack, tolerance) + margin);
        }
      } else if (writes) {
        p.depthSlack = tolerance;  // the candidate wrote its own depth for this fragment
        p.written = true;
      }
      raster::applyFragment(state_, *ops_, q, p.depth, p.stencil);
    }
  }

 private:
  [[nodiscard]] std::uint32_t toleranceAt(int x, int y) const {
    const std::uint32_t floor = options_.depthTolerance;
    if (!bound_)
      return floor;
    const double b = std::ceil(bound_->at(x, y));
    return b >= static_cast<double>(raster::kDepthMax)
               ? raster::kDepthMax
               : std::max(floor, static_cast<std::uint32_t>(b));
  }

  const raster::RenderState& state_;
  const GlParityOptions& options_;
  int height_;
  RegionState& r_;
  const raster::TriangleSetup* tri_ = nullptr;
  const raster::StencilOps* ops_ = nullptr;
  std::optional<DepthErrorBound> bound_;  // when options_.planeErrorBound
};

class Comparer {
 public:
  Comparer(raster::DepthStencilDevice& reference, raster::DepthStencilDevice& candidate,
           const PixelRect& region, const GlParityOptions& options)
      : reference_(reference),
        candidate_(candidate),
        options_(options),
        state_(region, PixelKnowledge{}) {
    gl_ = raster::initialRenderState(reference.width(), reference.height());
  }

  // Follows the state commands so that draws can be re-evaluated.
  void track(const raster::Command& command) {
    (void)raster::applyToState(command, gl_, reference_.width(), reference_.height());
  }

  // Marks the pixels where this draw's depth tests were near, from the reference's values
  // before the draw: the draw runs through the same pipeline as the CPU device's, clipped to
  // the compared region. Call only for a draw the reference has accepted (a valid draw).
  void analyseDraw(const raster::cmd::Draw& draw) {
    raster::RenderState clipped = gl_;
    clipped.scissor = gl_.scissor.intersect(state_.rect);
    if (clipped.scissor.empty())
      return;
    NearDecisionSink sink(clipped, options_, reference_.height(), state_);
    raster::drawTriangles(clipped, draw.vertices, draw.indices, sink);
  }

  // Reads both devices over the region and classifies every pixel.
  void compare(int command, GlParityReport& report) {
    const PixelRect& r = state_.rect;
    ++report.comparisons;
    if (r.empty())
      return;
    const auto depth = checkedReadBack(candidate_.readDepth(r), r);
    const auto stencil = checkedReadBack(candidate_.readStencil(r), r);
    const auto refDepth = checkedReadBack(reference_.readDepth(r), r);
    const auto refStencil = checkedReadBack(reference_.readStencil(r), r);
    GlParityCounts& c = report.counts;
    for (int y = r.y0; y < r.y1; ++y) {
      for (int x = r.x0; x < r.x1; ++x) {
        PixelKnowledge& p = state_.at(x, y);
        const std::uint32_t dd = absDiff(refDepth.at(x, y), depth.at(x, y));
        const std::uint32_t allowed = std::max(options_.depthTolerance, p.depthSlack);
        const bool stencilEqual = refStencil.at(x, y) == stencil.at(x, y);
        ++c.pixels;
        bool keepNear = false;
        if (stencilEqual && dd == 0) {
          ++c.identical;
        } else if (dd <= allowed && (stencilEqual || p.near)) {
          ++c.depthTies;
          if (!stencilEqual) {
            ++report.stencilTies;
            keepNear = true;  // later tests here start from different stencil values
          } else if (dd > options_.depthTolerance) {
            ++report.wideDepthTies;
          }
          if (stencilEqual)
            report.maxDepthDifference = std::max(report.maxDepthDifference, dd);
          if (stencilEqual && p.written) {
            report.maxToleranceFraction =
                std::max(report.maxToleranceFraction,
                         static_cast<double>(dd) / static_cast<double>(allowed));
          }
        } else {
          ++c.unexplained;
          if (static_cast<int>(report.examples.size()) < options_.maxExamples) {
            report.examples.push_back({command, x, y, refStencil.at(x, y), stencil.at(x, y),
                                       refDepth.at(x, y), depth.at(x, y)});
          }
        }
        p.near = keepNear;
        p.written = false;
        p.depthSlack = dd;
        p.depth = refDepth.at(x, y);
        p.stencil = refStencil.at(x, y);
      }
    }
  }

 private:
  raster::DepthStencilDevice& reference_;
  raster::DepthStencilDevice& candidate_;
  const GlParityOptions& options_;
  RegionState state_;
  raster::RenderState gl_;  // the stream's state so far (GL's defaults to start)
};

void checkSize(const raster::DepthStencilDevice& device, const raster::CommandStream& stream,
               const char* which) {
  if (device.width() != stream.width || device.height() != stream.height) {
    throw std::invalid_argument(std::string("GL parity: the ") + which + " device is " +
                                std::to_string(device.width()) + "x" +
                                std::to_string(device.height()) + " but the stream is " +
                                std::to_string(stream.width) + "x" + std::to_string(stream.height));
  }
}

}  // namespace

GlParityReport compareStreamOnDevices(const raster::CommandStream& stream,
                                      raster::DepthStencilDevice& reference,
                                      raster::DepthStencilDevice& candidate,
                                      const GlParityOptions& options) {
  checkSize(reference, stream, "reference");
  checkSize(candidate, stream, "candidate");
  const PixelRect frame{0, 0, stream.width, stream.height};
  PixelRect region = options.region ? options.region->intersect(frame) : frame;
  if (region.empty())
    region = {};

  GlParityReport report;
  Comparer comparer(reference, candidate, region, options);
  comparer.compare(-1, report);  // the fresh state: depth 1, stencil 0 on both
  for (std::size_t k = 0; k < stream.commands.size(); ++k) {
    const std::vector<raster::Command> one{stream.commands[k]};
    // The reference validates a draw before the analysis reads its indices; the analysis
    // starts from the reference's read-back before the draw, which the comparer keeps.
    raster::replay(one, reference);
    comparer.track(one.front());
    if (const auto* draw = std::get_if<raster::cmd::Draw>(&one.front()))
      comparer.analyseDraw(*draw);
    raster::replay(one, candidate);
    if (raster::changesBuffers(one.front()))
      comparer.compare(static_cast<int>(k), report);
  }
  return report;
}

GlParityReport compareStreamOnGl(const raster::CommandStream& stream,
                                 const GlParityOptions& options) {
  raster::CpuDevice reference(stream.width, stream.height);
  backends::GlDevice candidate(stream.width, stream.height, options.platform);
  GlParityReport report = compareStreamOnDevices(stream, reference, candidate, options);
  report.renderer = candidate.renderer();
  return report;
}

GlParityReport compareOnGl(const core::TriangleMesh& a, const core::TriangleMesh& b,
                           const core::PairRequest& request, const GlParityOptions& options) {
  raster::CpuDevice cpu(request.frame.width, request.frame.height);
  raster::RecordingDevice recorder(cpu);
  const core::PairResult result = core::collidePair(recorder, a, b, request);
  // An empty MOR (boxes apart) compares no pixel: skip starting a GL context (milliseconds
  // each, which dominated scenes of many distant pairs).
  if (result.mor.empty())
    return {};
  GlParityOptions pairOptions = options;
  pairOptions.region = result.mor;
  return compareStreamOnGl(recorder.stream(), pairOptions);
}

}  // namespace recode::verify
