#pragma once
// The conformance kit's generator: adversarial golden vectors (recode-golden-1,
// docs/rasterization.md section 8), in families that each aim at a part of the contract a back
// end is likely to get wrong. Every candidate is drawn from its family's random source and kept
// only when one of the family's wrong variants (variants.hpp) produces other bits than the
// contract, so each vector is known to catch something. Expected buffers come from
// raster::CpuDevice; the generator also checks that the reference model agrees with them.
//
// Deterministic: the same count and seed give the same vectors, byte for byte, on every run.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "recode/kit/variants.hpp"
#include "recode/raster/golden.hpp"

namespace recode::kit {

struct FamilyInfo {
  std::string_view name;    // file names are <name>_<index>.json
  std::string_view checks;  // one line: what the family aims at
};

// The families in generation order.
[[nodiscard]] std::span<const FamilyInfo> kitFamilies();

struct KitVector {
  std::string name;    // <family>_<index>
  std::string family;  // the family's name
  raster::GoldenVector golden;
  std::vector<Variant> catches;  // the wrong variants whose bits differ from the contract's
};

// `count` vectors (at least 1) spread over the families in proportion to their weights, each
// family's share capped where its cases run out (the compare x op x face grid: 24 vectors; the
// depth readings: 60, each once and the 15 rarest twice) or its files are large (the 16384-pixel
// frames: 3). Throws std::invalid_argument for count < 1
// and std::logic_error if a family finds no discriminating candidate or the reference model
// disagrees with CpuDevice (a bug here, never bad input).
[[nodiscard]] std::vector<KitVector> generateKit(int count, std::uint64_t seed);

// Random stream `index` of `seed` for differential testing (`recode conform --random`): the
// families in turn (all but `wide`, whose 16384-pixel frames would dominate a run), each
// candidate drawn as the kit draws it but kept whatever it catches; expected buffers from
// raster::CpuDevice. `catches` is left empty. The same (seed, index) gives the same stream.
// With `family` (a family's name, e.g. "limits"), every stream is drawn from that family:
// stream `index` is then the one the families in turn give as their stream index * F + f (F
// families, f its place), named "random-<seed>-<family>-<index>". Throws std::invalid_argument
// for an unknown family or "wide".
[[nodiscard]] KitVector randomKitStream(std::uint64_t seed, int index,
                                        std::string_view family = {});

// Writes each vector as DIR/<name>.json (GoldenLayout::Rows), creating DIR, after removing the
// files of an earlier kit there (<family>_<digits>.json of the families above; nothing else).
// The vectors are written into DIR/.recode-kit-staging and moved in once all are written, so a
// failed write leaves the earlier kit untouched. Returns the paths written.
std::vector<std::filesystem::path> writeKit(const std::vector<KitVector>& kit,
                                            const std::filesystem::path& dir);

}  // namespace recode::kit
