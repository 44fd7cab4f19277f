#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

std::vector<Command> countFacingsKeepDepth() {
  return {cmd::DepthFunc{CompareFunc::Always}, cmd::DepthWriteMask{true},
          cmd::StencilFunc{CompareFunc::Always, 0, 0xFF},
          opsFor(Face::Front, StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap),
          opsFor(Face::Back, StencilOp::Keep, StencilOp::Keep, StencilOp::DecrWrap)};
}

cmd::StencilOpsCmd opsFor(Face face, StencilOp sfail, StencilOp dpfail, StencilOp dppass) {
  return cmd::StencilOpsCmd{face, {sfail, dpfail, dppass}};
}

}  // namespace recode::kit::detail
