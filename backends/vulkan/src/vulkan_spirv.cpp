#include "vulkan_spirv.hpp"

namespace recode::backends::detail {

namespace {
// glslangValidator --vn writes each module as `const uint32_t k_<stage>[] = {...};`.
using std::uint32_t;
#include "clear_vk.frag.h"
#include "clear_vk.vert.h"
#include "exact32_vk.frag.h"
#include "exact32_vk.vert.h"
#include "exact_vk.frag.h"
#include "exact_vk.vert.h"
#include "native_vk.vert.h"
#include "summary_vk.comp.h"
}  // namespace

SpirvModules spirvModules(ShaderArithmetic arithmetic) {
  if (arithmetic == ShaderArithmetic::Emulated32)
    return {k_exact32_vk_vert, k_exact32_vk_frag, k_clear_vk_vert,
            k_clear_vk_frag,   k_summary_vk_comp, k_native_vk_vert};
  return {k_exact_vk_vert, k_exact_vk_frag,   k_clear_vk_vert,
          k_clear_vk_frag, k_summary_vk_comp, k_native_vk_vert};
}

}  // namespace recode::backends::detail
