#pragma once
// The state of the depth/stencil machine: its plain types and RenderState, everything a draw
// or a clear depends on, as one value. Shared by every device, the pipeline (pipeline.hpp),
// which reads it and never changes it, and the command-stream format. Names follow OpenGL's
// so that a back end maps them one to one.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string_view>

namespace recode::raster {

// Framebuffer limits. 16384 matches common GL MAX_VIEWPORT_DIMS; vertices may lie outside
// the framebuffer (a guard band) up to kMaxWindowCoordinate pixels from the origin, which
// keeps 24.8 fixed point and float snapping exact and the 64-bit edge functions far from
// overflow (|products| < 2^49).
inline constexpr int kMaxFramebufferSize = 16384;
inline constexpr float kMaxWindowCoordinate = 32768.0f;

inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelOne = 1 << kSubpixelBits;      // 256 sub-pixel steps per pixel
inline constexpr std::uint32_t kDepthMax = (1u << 24) - 1u;  // 24-bit unorm depth

enum class CompareFunc : std::uint8_t {
  Never,
  Less,
  Equal,
  LEqual,
  Greater,
  NotEqual,
  GEqual,
  Always
};

enum class StencilOp : std::uint8_t { Keep, Zero, Replace, Incr, IncrWrap, Decr, DecrWrap, Invert };

enum class Face : std::uint8_t { Front, Back, Both };

enum class CullMode : std::uint8_t { None, Front, Back };

struct StencilOps {
  StencilOp stencilFail = StencilOp::Keep;
  StencilOp depthFail = StencilOp::Keep;
  StencilOp depthPass = StencilOp::Keep;

  friend bool operator==(const StencilOps&, const StencilOps&) = default;
};

// A half-open pixel rectangle [x0, x1) x [y0, y1) in GL window coordinates (y up).
struct PixelRect {
  int x0 = 0;
  int y0 = 0;
  int x1 = 0;
  int y1 = 0;

  [[nodiscard]] int width() const { return x1 > x0 ? x1 - x0 : 0; }
  [[nodiscard]] int height() const { return y1 > y0 ? y1 - y0 : 0; }
  [[nodiscard]] bool empty() const { return width() == 0 || height() == 0; }
  [[nodiscard]] long long area() const {
    return static_cast<long long>(width()) * static_cast<long long>(height());
  }
  // Inline: the traversal clips every triangle's bounds with it.
  [[nodiscard]] PixelRect intersect(const PixelRect& o) const {
    PixelRect r{std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
    r.x1 = std::max(r.x1, r.x0);
    r.y1 = std::max(r.y1, r.y0);
    return r;
  }

  friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

// Everything a draw or a clear depends on, with GL's defaults. The scissor is kept clamped to
// the framebuffer (setScissor), so the stages after it never see a pixel outside.
struct RenderState {
  PixelRect scissor;
  CompareFunc depthFunc = CompareFunc::Less;
  bool depthWrite = true;
  CompareFunc stencilFunc = CompareFunc::Always;
  std::uint8_t stencilRef = 0;
  std::uint8_t stencilValueMask = 0xFF;
  std::uint8_t stencilWriteMask = 0xFF;
  StencilOps frontOps;
  StencilOps backOps;
  CullMode cull = CullMode::None;

  // The ops for a triangle of this facing (GL's glStencilOpSeparate).
  [[nodiscard]] const StencilOps& opsFor(bool frontFacing) const {
    return frontFacing ? frontOps : backOps;
  }
  // Whether a triangle of this facing is discarded before rasterization.
  [[nodiscard]] bool culls(bool frontFacing) const {
    return (cull == CullMode::Front && frontFacing) || (cull == CullMode::Back && !frontFacing);
  }
  // The state changes of the device interface whose meaning is more than an assignment: ops for
  // Front, Back or Both faces; the scissor clamped to a width x height framebuffer.
  void setStencilOps(Face face, const StencilOps& ops);
  void setScissor(const PixelRect& rect, int width, int height);
};

// GL's initial state for a width x height framebuffer (the scissor is the whole of it).
[[nodiscard]] RenderState initialRenderState(int width, int height);

// Names as they appear in the golden-vector files and in messages ("LEQUAL", "INCR_WRAP",
// "front", ...). Parsing is case-sensitive and returns nullopt for an unknown name.
[[nodiscard]] std::string_view toString(CompareFunc f);
[[nodiscard]] std::string_view toString(StencilOp op);
[[nodiscard]] std::string_view toString(Face face);
[[nodiscard]] std::string_view toString(CullMode mode);
[[nodiscard]] std::optional<CompareFunc> parseCompareFunc(std::string_view s);
[[nodiscard]] std::optional<StencilOp> parseStencilOp(std::string_view s);
[[nodiscard]] std::optional<Face> parseFace(std::string_view s);
[[nodiscard]] std::optional<CullMode> parseCullMode(std::string_view s);

}  // namespace recode::raster
