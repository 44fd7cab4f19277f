#pragma once
// The device commands of the layered pair (docs/algorithm.md, "Closed meshes: the layered
// pair"), private to collideLayered: one function per pass, each setting every piece of state
// its draw depends on. Only the contract's operations: the stencil counts fragments with INCR,
// and the stencil test EQUAL picks out the k-th of them while the depth test is ALWAYS.

#include <cstdint>

#include "recode/raster/device.hpp"
#include "recode/raster/triangle_source.hpp"

namespace recode::core::detail {

// Which fragments of a closed mesh a pass draws: the front-facing ones, where a view ray
// enters the mesh, or the back-facing ones, where it leaves.
enum class Facing { Entries, Exits };

class LayerPassRunner {
 public:
  explicit LayerPassRunner(raster::DepthStencilDevice& device) : dev_(device) {}

  // The stencil over `rect` becomes the number of the mesh's fragments of one facing at each
  // pixel (INCR saturates at 255). Depth is neither tested nor written.
  void countFragments(const raster::TriangleSource& mesh, Facing facing,
                      const raster::PixelRect& rect) {
    startPass(facing, rect);
    dev_.setDepthWriteMask(false);
    dev_.setStencilFunc(raster::CompareFunc::Always, 0, 0xFF);
    dev_.setStencilOps(raster::Face::Both,
                       {raster::StencilOp::Keep, raster::StencilOp::Keep, raster::StencilOp::Incr});
    dev_.drawMesh(mesh);
  }

  // The depth over `rect` becomes the depth of each pixel's k-th fragment of one facing (k >= 1)
  // in the order the contract draws them (the mesh's triangle order), where the pixel has k or
  // more. Every fragment increments the stencil from 0, whether its stencil test passes or not;
  // the test EQUAL k - 1 passes for the k-th alone, and with the depth test ALWAYS only that one
  // writes its depth. Pixels with fewer fragments keep the clear value, 1.
  void captureLayer(const raster::TriangleSource& mesh, Facing facing, int k,
                    const raster::PixelRect& rect) {
    startPass(facing, rect);
    dev_.setDepthWriteMask(true);
    dev_.clearDepth(1.0);
    dev_.setStencilFunc(raster::CompareFunc::Equal, static_cast<std::uint8_t>(k - 1), 0xFF);
    dev_.setStencilOps(raster::Face::Both,
                       {raster::StencilOp::Incr, raster::StencilOp::Incr, raster::StencilOp::Incr});
    dev_.drawMesh(mesh);
  }

 private:
  // The state both passes share: the scissor, the stencil cleared to 0 under a full write mask,
  // the depth test ALWAYS, and the other facing culled.
  void startPass(Facing facing, const raster::PixelRect& rect) {
    dev_.setScissor(rect);
    dev_.setStencilWriteMask(0xFF);
    dev_.clearStencil(0);
    dev_.setDepthFunc(raster::CompareFunc::Always);
    dev_.setCullMode(facing == Facing::Entries ? raster::CullMode::Back : raster::CullMode::Front);
  }

  raster::DepthStencilDevice& dev_;
};

}  // namespace recode::core::detail
