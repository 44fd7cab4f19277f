#pragma once
// The device commands of RECODE's passes (docs/algorithm.md, "The passes"), private to
// collidePair: one function per pass, each setting every piece of state its draws depend on.

#include <cstdint>

#include "recode/pair/pair_cases.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/triangle_source.hpp"

namespace recode::core::detail {

// The command sequence of docs/algorithm.md ("The passes"). Each function sets every piece
// of state its draws depend on, so the sequence does not rely on what the device held before.
class PassRunner {
 public:
  // Each block is drawn with drawMesh: the stream is drawTriangles of the whole block, and a
  // device may draw only what meets its scissor (raster/triangle_source.hpp).
  PassRunner(raster::DepthStencilDevice& device, const raster::TriangleSource& a,
             const raster::TriangleSource& b)
      : dev_(device), a_(a), b_(b) {}

  // RenderSetZ(A, GEQUAL): depth cleared to 0 then raised to the farthest face of A, so the
  // depth buffer holds Amax; stencil cleared to 0 and set to 1 wherever A is drawn. All of
  // A's faces are drawn (the paper draws the back faces): the maximum over both is Amax even
  // where rounding puts a silhouette pixel's front face a step behind its back face.
  void setZ(const raster::PixelRect& mor) {
    dev_.setScissor(mor);
    dev_.setDepthWriteMask(true);
    dev_.setStencilWriteMask(0xFF);
    dev_.clearDepth(0.0);
    dev_.clearStencil(0);
    dev_.setCullMode(raster::CullMode::None);
    dev_.setDepthFunc(raster::CompareFunc::GEqual);
    dev_.setStencilFunc(raster::CompareFunc::Always, 1, 0xFF);
    dev_.setStencilOps(raster::Face::Both, {raster::StencilOp::Keep, raster::StencilOp::Keep,
                                            raster::StencilOp::Replace});
    dev_.drawMesh(a_);
  }

  // RenderTestZ(B, LEQUAL): where A is present (1 <= count), every face of B at or in front
  // of Amax increments the count; depth is only tested, never written.
  void testZ() {
    dev_.setDepthWriteMask(false);
    dev_.setDepthFunc(raster::CompareFunc::LEqual);
    dev_.setStencilFunc(raster::CompareFunc::LEqual, 1, kCountBits);
    dev_.setStencilOps(raster::Face::Both,
                       {raster::StencilOp::Keep, raster::StencilOp::Keep, raster::StencilOp::Incr});
    dev_.setStencilWriteMask(kCountBits);
    dev_.setCullMode(raster::CullMode::None);
    dev_.drawMesh(b_);
  }

  // Depth cleared to 1 and lowered to A's nearest face: the depth buffer holds Amin. The
  // stencil write mask is 0 so the count survives.
  void loadAmin() {
    dev_.setStencilWriteMask(0);
    dev_.setDepthWriteMask(true);
    dev_.clearDepth(1.0);
    dev_.setDepthFunc(raster::CompareFunc::LEqual);
    dev_.setStencilFunc(raster::CompareFunc::Always, 0, 0xFF);
    dev_.setStencilOps(raster::Face::Both,
                       {raster::StencilOp::Keep, raster::StencilOp::Keep, raster::StencilOp::Keep});
    dev_.setCullMode(raster::CullMode::None);
    dev_.drawMesh(a_);
  }

  // One of B's two faces (front: cull back faces; back: cull front faces) against Amin with
  // GEQUAL. Where A is present the bit is flipped when the face is at or behind Amin; where
  // A is absent the stencil test fails and the bit is flipped anyway, recording B's
  // coverage. A convex block has one face of each orientation per pixel, so one flip sets
  // the bit from 0.
  void testAmin(raster::CullMode culled, std::uint8_t bit) {
    dev_.setDepthWriteMask(false);
    dev_.setDepthFunc(raster::CompareFunc::GEqual);
    dev_.setStencilFunc(raster::CompareFunc::LEqual, 1, kCountBits);
    dev_.setStencilOps(raster::Face::Both, {raster::StencilOp::Invert, raster::StencilOp::Keep,
                                            raster::StencilOp::Invert});
    dev_.setStencilWriteMask(bit);
    dev_.setCullMode(culled);
    dev_.drawMesh(b_);
  }

  // Depth over `rect` becomes, for the faces facing the viewer (near end: cull back, GEQUAL
  // from 0) the later of A's and B's near ends, or for the faces facing away (far end: cull
  // front, LEQUAL from 1) the earlier of their far ends: the two ends of the overlap interval.
  void overlapEnd(const raster::PixelRect& rect, bool nearEnd) {
    dev_.setScissor(rect);
    dev_.setStencilWriteMask(0);
    dev_.setDepthWriteMask(true);
    dev_.clearDepth(nearEnd ? 0.0 : 1.0);
    dev_.setCullMode(nearEnd ? raster::CullMode::Back : raster::CullMode::Front);
    dev_.setDepthFunc(nearEnd ? raster::CompareFunc::GEqual : raster::CompareFunc::LEqual);
    dev_.setStencilFunc(raster::CompareFunc::Always, 0, 0xFF);
    dev_.setStencilOps(raster::Face::Both,
                       {raster::StencilOp::Keep, raster::StencilOp::Keep, raster::StencilOp::Keep});
    dev_.drawMesh(a_);
    dev_.drawMesh(b_);
  }

 private:
  raster::DepthStencilDevice& dev_;
  const raster::TriangleSource& a_;
  const raster::TriangleSource& b_;
};

}  // namespace recode::core::detail
