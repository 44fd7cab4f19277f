#pragma once
// What the graphics APIs (Vulkan, OpenGL, WebGPU) allow a native depth/stencil pipeline to leave
// in each pixel of a stream, where this contract fixes one answer. The contract decides five
// things the APIs leave to the implementation:
//
//   - the tie rule: which of two triangles sharing an edge owns a sample exactly on it;
//   - the sub-pixel precision: vertices may be snapped to a grid as coarse as 1/16 pixel;
//   - the depth interpolation: z at a sample is computed to a stated precision only;
//   - the depth conversion: z to 24 bits may round to either of the two nearest values;
//   - the clipping: a triangle reaching beyond the viewport bounds the APIs guarantee may be
//     clipped in single precision, its edges and depth carrying the clip's rounding.
//
// allowedByApis follows the stream with a set of possible states per pixel instead of one:
// a sample whose coverage a freedom can change both is and is not covered, a depth is an
// interval of 24-bit values, and a depth test whose operands' intervals overlap goes both ways,
// so every op, value and later test that depends on it is open too. Everything the APIs fix
// (stencil tests, ops and masks, compare functions, the depth write mask, facing and culling
// of a triangle whose facing no freedom can change, the scissor, clears) is followed exactly.
// The result is sound: every behaviour the freedoms allow, taken as wide as FreedomWidths
// says, ends in one of a pixel's states; it may also hold states no implementation reaches
// (depths are merged into intervals), so "forbidden" is always true and "allowed" may be
// generous. docs/conformance.md cites the clauses and says how wide each freedom is taken.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "recode/kit/variants.hpp"
#include "recode/raster/command_stream.hpp"

namespace recode::conformance {

// Every freedom of the APIs once: X(enumerator, bit, name, the clauses that grant it, rank),
// in the order reports list them; `rank` orders them when one freedom names a choice that
// several opened (the lowest first). The enum and the table are made from the same list.
#define RECODE_CONFORMANCE_FREEDOMS(X)                                                          \
  /* a sample exactly on an edge */                                                             \
  X(TieRule, 1, "the tie rule",                                                                 \
    "a sample on an edge shared by two triangles belongs to exactly one of them, which one is " \
    "the implementation's (Vulkan, Polygon Rasterization; OpenGL 4.5 section 14.6.1; WebGPU, "  \
    "rasterization)",                                                                           \
    4)                                                                                          \
  /* vertices snapped to a coarser grid than the contract's 1/256 pixel */                      \
  X(SubPixelPrecision, 2, "the sub-pixel precision",                                            \
    "vertices are snapped to the implementation's sub-pixel grid, at least 4 bits (Vulkan "     \
    "subPixelPrecisionBits; OpenGL SUBPIXEL_BITS; Direct3D fixes 8)",                           \
    1)                                                                                          \
  /* z at the sample computed to the APIs' precision */                                         \
  X(DepthInterpolation, 4, "the depth interpolation's precision",                               \
    "z at a sample is interpolated from the vertices' depths at the implementation's "          \
    "precision (OpenGL 4.5 section 2.3.4.1: about 1 part in 10^5; Vulkan and WebGPU state no "  \
    "tighter bound)",                                                                           \
    2)                                                                                          \
  /* z to 24 bits: either of the two nearest values */                                          \
  X(DepthConversion, 8, "the rounding of depth to 24 bits",                                     \
    "a float depth converts to 24-bit fixed point as either of the two nearest values "         \
    "(Vulkan, Fixed-Point Data Conversions; OpenGL 4.5 section 2.3.5.2)",                       \
    3)                                                                                          \
  /* a triangle beyond the guaranteed range clipped in single precision */                      \
  X(Clipping, 16, "the clipping of a triangle beyond the viewport bounds",                      \
    "a primitive outside the view volume is clipped to it (or to a guard band) in the "         \
    "implementation's floating point, and the clipped polygon's new vertices and their "        \
    "interpolated depths carry its rounding (OpenGL 4.5 section 13.5; Vulkan, Primitive "       \
    "Clipping, and viewportBoundsRange, at least [-8192, 8191]; WebGPU, rasterization)",        \
    0)

// One freedom of the APIs, as a bit of a FreedomSet.
enum class Freedom : std::uint8_t {
#define RECODE_FREEDOM_ENUMERATOR(e, bit, name, clause, rank) e = bit,
  RECODE_CONFORMANCE_FREEDOMS(RECODE_FREEDOM_ENUMERATOR)
#undef RECODE_FREEDOM_ENUMERATOR
};
// A set of freedoms, as the bits of Freedom.
using FreedomSet = std::uint8_t;

// One freedom's row of the table.
struct FreedomInfo {
  Freedom freedom;
  std::string_view name;    // "the sub-pixel precision"
  std::string_view clause;  // the clauses of the specifications that grant it, in one line
  int rank;                 // which freedom names a choice several opened: the lowest
};

// Every freedom, in the order reports list them.
[[nodiscard]] std::span<const FreedomInfo> allFreedoms();
// The freedom's name, e.g. "the sub-pixel precision".
[[nodiscard]] std::string_view toString(Freedom f);
// The clauses of the specifications that grant the freedom, in one line.
[[nodiscard]] std::string_view apiClause(Freedom f);
// The names of the freedoms in a set, in the table's order.
[[nodiscard]] std::vector<std::string> namesOf(FreedomSet set);
// The freedoms in a set, joined with ", ".
[[nodiscard]] std::string describe(FreedomSet set);

// The freedom a reading of the kit takes (kit/variants.hpp), or nullopt for a reading that
// breaks a rule the APIs fix (stencil ops and masks, clears, the scissor, facing) or the
// contract's validation, which a native pipeline does not have. The other fill rule and edges
// in single precision are the tie rule and the sub-pixel precision; every reading of the
// plane's arithmetic, the depth interpolation; every other rounding, the conversion.
[[nodiscard]] std::optional<Freedom> freedomOf(kit::Variant v);

// How wide each freedom is taken. The defaults are the APIs' own bounds; the tests narrow them
// to show what each one opens.
struct FreedomWidths {
  // The fewest sub-pixel bits an implementation may snap to (Vulkan subPixelPrecisionBits and
  // OpenGL SUBPIXEL_BITS are at least 4). 8 is the contract's grid: no snapping freedom.
  int subPixelBits = 4;
  // Whether a sample exactly on an edge may go either way (any consistent tie rule).
  bool tieRule = true;
  // The relative precision of the interpolated z, as a fraction of the largest |z| of the
  // triangle's vertices (OpenGL: floating-point results accurate to about 1 part in 10^5).
  double depthPrecision = 1e-5;
  // Whether z * (2^24 - 1) may round to either neighbour (else to nearest, ties to even).
  bool depthConversion = true;
  // Whether a triangle with a vertex beyond the viewport bounds every API guarantees
  // (kGuaranteedBounds) may be clipped in single precision: its edges move by the rounding of
  // a float clip of its coordinates, and its depth at a sample is any value between its
  // vertices' (the clipped polygon's fan interpolates depths of points on its edges).
  bool clipping = true;
};

// The window coordinates every API rasterizes without clipping on a frame of `size` pixels (its
// larger side): Vulkan's viewportBoundsRange is at least [-2 s, 2 s - 1] for s its
// maxViewportDimensions, at least 4096 and at least the frame's size, the range a viewport may
// be placed in. A triangle with every vertex within it on both axes is taken as rasterized
// whole; one with a vertex beyond it may be clipped.
struct ViewportBounds {
  double lo = -8192.0, hi = 8191.0;
};
[[nodiscard]] constexpr ViewportBounds guaranteedBounds(int size) {
  const double s = size > 4096 ? static_cast<double>(size) : 4096.0;
  return {-2.0 * s, 2.0 * s - 1.0};
}
// A float clip's rounding, relative to the largest coordinate (pixels) of the triangle: the
// new vertex P0 + t (P1 - P0) after the viewport's transform and its inverse, some ten float
// operations of 2^-24 each, taken as 16, on coordinates summed over both ends of an edge.
inline constexpr double kClipRounding = 32.0 / 16777216.0;

// One possible state of a pixel: a stencil value and the interval of depths that go with it,
// with the freedoms that some path to it took.
struct AllowedState {
  std::uint8_t stencil = 0;
  std::uint32_t depthLo = 0, depthHi = 0;  // 24-bit values, inclusive
  FreedomSet freedoms = 0;
};

// A pixel's possible states after the stream: at most one per stencil value.
struct AllowedPixel {
  std::vector<AllowedState> states;

  // Whether the APIs leave the pixel's stencil (depth) exactly one value.
  [[nodiscard]] bool stencilFixed() const;
  // Whether the APIs leave the pixel's depth exactly one value.
  [[nodiscard]] bool depthFixed() const;
  // Whether some state holds this stencil value.
  [[nodiscard]] bool allowsStencil(std::uint8_t s) const;
  // Whether some state holds this depth.
  [[nodiscard]] bool allowsDepth(std::uint32_t d) const;
  // Whether some state holds this depth and this stencil value together.
  [[nodiscard]] bool allows(std::uint32_t d, std::uint8_t s) const;
  // The freedoms on the paths to the states that hold (d, s); 0 if none does.
  [[nodiscard]] FreedomSet freedomsFor(std::uint32_t d, std::uint8_t s) const;
  // The smallest and largest depth of any state.
  [[nodiscard]] std::uint32_t depthMin() const;
  // The largest depth of any state.
  [[nodiscard]] std::uint32_t depthMax() const;
};

// A choice a freedom opened at one pixel, for reports: where, which freedom, how far.
struct OpenChoice {
  int command = 0;  // index in the stream
  int draw = 0, triangle = 0;
  Freedom freedom = Freedom::TieRule;
  std::string how;  // e.g. "the sample lies 0.0000077 pixels from edge v0 -> v1"
};

// What the APIs allow in every pixel of a stream (row-major, row 0 at the bottom).
struct AllowedFrame {
  int width = 0, height = 0;
  std::vector<AllowedPixel> pixels;

  // The pixel (x, y).
  [[nodiscard]] const AllowedPixel& at(int x, int y) const;
  // Whether every pixel's stencil is one value: the APIs require the whole stencil buffer.
  [[nodiscard]] bool stencilRequired() const;
  // Whether every pixel's depth is one value.
  [[nodiscard]] bool depthRequired() const;
};

// The states the APIs allow in every pixel of `stream`. Throws std::invalid_argument, naming
// the command, for a stream the contract refuses (section 2).
[[nodiscard]] AllowedFrame allowedByApis(const raster::CommandStream& stream,
                                         const FreedomWidths& widths = {});

// The states of one pixel, with the choices the freedoms opened there in stream order.
[[nodiscard]] AllowedPixel allowedAt(const raster::CommandStream& stream, int x, int y,
                                     std::vector<OpenChoice>* choices,
                                     const FreedomWidths& widths = {});

}  // namespace recode::conformance
