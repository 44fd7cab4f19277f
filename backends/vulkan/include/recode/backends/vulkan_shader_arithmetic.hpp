#pragma once
// The two kinds of exact Vulkan device: the same contract (docs/rasterization.md) and the same
// bits, in the shader arithmetic a GPU has. A device of each kind has its own logical device,
// pipelines and recording, so both can be used in one process.

namespace recode::backends {

enum class ShaderArithmetic {
  // Doubles and 64-bit integers in the shaders (exact_contract.glsl): needs shaderFloat64 and
  // shaderInt64, which desktop GPUs and lavapipe have.
  Native64,
  // 32-bit words only (exact_contract32.glsl): the 64-bit edge functions as word pairs and the
  // depth plane's double operations by a small soft double. Requests neither feature, so it runs
  // on the GPUs that lack them (most mobile GPUs; the arithmetic Metal and WebGPU offer).
  Emulated32,
};

inline constexpr int kShaderArithmeticCount = 2;

[[nodiscard]] constexpr int indexOf(ShaderArithmetic arithmetic) {
  return arithmetic == ShaderArithmetic::Native64 ? 0 : 1;
}

}  // namespace recode::backends
