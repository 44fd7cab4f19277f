#pragma once
// The stages of the contract at which a back end's answer can first depart, each listed once:
// its name in reports and baselines, the section of docs/rasterization.md that states its rule,
// the graphics APIs' clause for a native pipeline that departs there, and its colour in the HTML
// report's error masks. The enum and the table are made from the same list, so a stage cannot
// be added without all four.

#include <span>
#include <string_view>

namespace recode::conformance {

// X(enumerator, name, contract section, the APIs' clause, mask colour), in report order.
#define RECODE_CONFORMANCE_STAGES(X)                                                             \
  /* the back end refused a valid stream */                                                      \
  X(Validation, "validation",                                                                    \
    "rasterization.md section 2 (vertices and snapping: what a draw may hold)",                  \
    "a native pipeline has no validation of its own: every vector of the kit is a valid stream", \
    "#7f7f7f")                                                                                   \
  /* which samples a triangle covers: edges and the fill rule */                                 \
  X(Coverage, "coverage", "rasterization.md section 4 (coverage and the fill rule)",             \
    "a sample farther from every edge than snapping reaches is inside or outside on every "      \
    "allowed grid (Vulkan, Basic Polygon Rasterization; OpenGL 4.5 section 14.6.1)",             \
    "#d62728")                                                                                   \
  /* front or back, culling */                                                                   \
  X(Facing, "facing", "rasterization.md section 3 (triangle setup: area, facing, culling)",      \
    "facing and culling follow the sign of the polygon's area (Vulkan, Basic Polygon "           \
    "Rasterization and Culling; OpenGL 4.5 sections 14.6.1 and 14.6.2)",                         \
    "#9467bd")                                                                                   \
  /* the plane's arithmetic */                                                                   \
  X(DepthValue, "depth value",                                                                   \
    "rasterization.md section 5 (depth: the plane's arithmetic, in its order)", kDepthClause,    \
    "#1f77b4")                                                                                   \
  /* z to 24 bits */                                                                             \
  X(Quantisation, "quantisation",                                                                \
    "rasterization.md section 5 (depth: quantisation to 24 bits, ties to even)", kDepthClause,   \
    "#17becf")                                                                                   \
  /* which fragment's depth won */                                                               \
  X(DepthTest, "depth test",                                                                     \
    "rasterization.md section 6 (per-fragment operations: the depth test)",                      \
    "the depth test compares the fragment's depth with the stored one by the depth function "    \
    "and writes it through the depth write mask (Vulkan, Depth Test; OpenGL 4.5 section "        \
    "17.3.6; WebGPU, depth test)",                                                               \
    "#ff7f0e")                                                                                   \
  /* the stencil test, ops and masks */                                                          \
  X(Stencil, "stencil",                                                                          \
    "rasterization.md section 6 (per-fragment operations: stencil test, ops, masks)",            \
    "the stencil test compares (ref & mask) with (stencil & mask) and applies the op of its "    \
    "outcome through the write mask (Vulkan, Stencil Test; OpenGL 4.5 section 17.3.5; WebGPU, "  \
    "stencil test)",                                                                             \
    "#2ca02c")                                                                                   \
  /* clears: the scissor and the write masks */                                                  \
  X(Clear, "clear", "rasterization.md section 6 (clears: the scissor and the write masks)",      \
    "a clear writes only inside the scissor and through the write masks (OpenGL 4.5 sections "   \
    "17.4.2 and 17.4.3; in Vulkan and WebGPU a draw that does what the contract's clear does)",  \
    "#8c564b")

enum class Stage {
#define RECODE_STAGE_ENUMERATOR(e, name, section, clause, colour) e,
  RECODE_CONFORMANCE_STAGES(RECODE_STAGE_ENUMERATOR)
#undef RECODE_STAGE_ENUMERATOR
};

// One stage's row of the table.
struct StageInfo {
  Stage stage;
  std::string_view name;       // "coverage", "depth value", ... as reports and baselines spell it
  std::string_view section;    // "rasterization.md section 4 (coverage and the fill rule)"
  std::string_view apiClause;  // what the graphics APIs fix there, with the clauses
  std::string_view colour;     // the HTML error mask's colour, "#d62728"
};

// Every stage, in the enum's order.
[[nodiscard]] std::span<const StageInfo> allStages();
// The stage's row.
[[nodiscard]] const StageInfo& infoOf(Stage s);

// The stage's name, e.g. "coverage".
[[nodiscard]] std::string_view toString(Stage s);
// The contract section that states the stage's rule, e.g. "rasterization.md section 4
// (coverage and the fill rule)".
[[nodiscard]] std::string_view contractSection(Stage s);

}  // namespace recode::conformance
