#pragma once
// The colours of every `recode explain` picture, shared by the pictures, legends and JSON.

#include <array>

#include "explain/png_image.hpp"
#include "recode/pair/pair_cases.hpp"

namespace recode::explain {

// One set for every picture so the page reads consistently.
inline constexpr Rgb kEmpty{17, 17, 17};         // nothing here
inline constexpr Rgb kColourA{58, 120, 216};     // block A
inline constexpr Rgb kColourB{214, 69, 69};      // block B
inline constexpr Rgb kColourBoth{155, 64, 192};  // A and B on the same pixel
inline constexpr Rgb kMorOutline{0, 229, 255};   // the MOR rectangle
inline constexpr Rgb kContactOutline{255, 255, 255};
inline constexpr Rgb kZoomOutline{120, 255, 80};   // where the close-up is
inline constexpr Rgb kViewOutline{255, 255, 255};  // the part of the frame the pictures show
inline constexpr Rgb kHatch{70, 78, 88};           // outside the rectangle a step works on
inline constexpr Rgb kNotExamined{43, 43, 43};     // case map outside the MOR
inline constexpr Rgb kDepthZero{27, 59, 111};      // depth exactly 0 (a clear to 0 left it)
inline constexpr Rgb kDepthOne{96, 32, 32};        // depth exactly 1 (a clear to 1 left it)
inline constexpr Rgb kInterfering{255, 210, 63};   // contact picture highlight
inline constexpr Rgb kUnexpected{255, 0, 255};     // a stencil value the encoding never produces
inline constexpr Rgb kNotInterfering{72, 52,
                                     72};  // contact depth at a pixel that does not interfere

// The "what this step changed" pictures: one colour per stencil transition (old -> new), in
// order of how many pixels made it, chosen far apart so that e.g. 3 -> 7 and 2 -> 6 differ.
inline constexpr std::array<Rgb, 10> kChangePalette = {{
    {255, 215, 0},    // gold
    {255, 0, 200},    // magenta
    {0, 200, 255},    // cyan
    {120, 255, 80},   // lime
    {255, 120, 0},    // orange
    {170, 110, 255},  // violet
    {255, 255, 255},  // white
    {0, 110, 255},    // blue
    {255, 80, 80},    // red
    {0, 255, 180},    // aqua
}};

// Stencil values 0..15: the hue is the count in bits 0-1 (grey: A absent, blue: A only so
// far, orange: one face of B at or before Amax, green: both), the lightness the two Amin
// bits (none, bit 2, bit 3, both).
// clang-format off
inline constexpr std::array<Rgb, 16> kStencilPalette = {{
    // count 0          count 1          count 2         count 3
    {17, 17, 17},    {40, 75, 150},   {150, 72, 0},   {35, 115, 40},    // no Amin bit
    {80, 80, 80},    {60, 110, 200},  {195, 98, 0},   {50, 150, 56},    // bit 2
    {122, 122, 122}, {100, 150, 230}, {235, 135, 20}, {85, 195, 90},    // bit 3
    {176, 176, 176}, {160, 200, 245}, {255, 185, 90}, {160, 230, 160},  // bits 2 and 3
}};
// clang-format on

// Cases 0..8; the interfering cases 3-6 in warm colours.
inline constexpr std::array<Rgb, core::kCaseCount> kCasePalette = {{
    {17, 17, 17},     // 0 neither
    {47, 95, 179},    // 1 A only
    {108, 90, 158},   // 2 B behind A
    {255, 210, 63},   // 3
    {255, 140, 26},   // 4
    {230, 57, 70},    // 5
    {255, 95, 162},   // 6
    {138, 159, 208},  // 7 B in front of A
    {42, 157, 143},   // 8 B only
}};

}  // namespace recode::explain
