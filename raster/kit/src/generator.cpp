// The kit's driver: shares the count among the families, draws each vector's candidates until
// one discriminates, and writes the files. The families themselves are in family_*.cpp.
#include "recode/kit/generator.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "family.hpp"
#include "recode/kit/reference_model.hpp"
#include "recode/raster/cpu_device.hpp"

namespace recode::kit {

namespace {

using detail::Candidate;
using detail::Rng;

struct Family {
  FamilyInfo info;
  int weight;  // share of the count
  int cap;     // at most this many vectors
  detail::DrawCandidate draw;
};

constexpr int kNoCap = 1 << 30;

const std::array<Family, 13> kFamilies = {{
    {{"slivers", "sub-pixel slivers at every orientation, edges through sample points"},
     10,
     kNoCap,
     detail::slivers},
    {{"fans", "fans around a vertex on a pixel centre, both windings: every sample once"},
     10,
     kNoCap,
     detail::fans},
    {{"shared_edges", "triangulated grids whose shared edges run through sample points"},
     10,
     kNoCap,
     detail::sharedEdges},
    {{"limits", "vertices at the +-2^23 fixed-point limits (+-32768 pixels), z at 0 and 1"},
     10,
     kNoCap,
     detail::limits},
    {{"depth_ties", "depths whose z * 16777215 is exactly k + 0.5: round half to even"},
     10,
     kNoCap,
     detail::depthTies},
    {{"anchor", "steep planes at a quantisation tie: bits depend on anchor and arithmetic"},
     14,
     kNoCap,
     detail::anchorPlanes},
    {{"stencil_saturation", "INCR at 255, DECR at 0, INCR_WRAP and DECR_WRAP"},
     8,
     kNoCap,
     detail::stencilSaturation},
    {{"masks", "REPLACE under stencil value masks and write masks, masked clears"},
     10,
     kNoCap,
     detail::masksReplace},
    {{"compare_ops", "every stencil compare function x stencil op in each slot x face"},
     12,
     24,
     detail::compareOps},
    {{"culling", "cull none, front and back over both windings"}, 8, kNoCap, detail::culling},
    {{"scissor_clears", "clears inside scissors (partly outside, empty) under write masks"},
     8,
     kNoCap,
     detail::scissorClears},
    {{"wide", "frames 16384 pixels wide or tall, one or two pixels across"},
     2,
     3,
     detail::wideFrames},
    {{"depth_arithmetic",
      "each reading of the depth arithmetic and its rounding, the rarest twice: sloped planes "
      "at ties, steep, near-degenerate and far-anchored slivers"},
     28,
     60,
     detail::depthArithmetic},
}};

constexpr int kAttempts = 400;

// One vector at a time to the family furthest below its share, so that the split follows the
// weights for any count and no family exceeds its cap.
std::vector<int> shareCount(int count) {
  std::vector<int> share(kFamilies.size(), 0);
  for (int n = 0; n < count; ++n) {
    std::size_t best = kFamilies.size();
    for (std::size_t f = 0; f < kFamilies.size(); ++f) {
      if (share[f] >= kFamilies[f].cap)
        continue;
      // share/weight smallest first; compared as cross products to stay in integers.
      if (best == kFamilies.size() ||
          (share[f] + 1) * kFamilies[best].weight < (share[best] + 1) * kFamilies[f].weight) {
        best = f;
      }
    }
    if (best == kFamilies.size())
      break;  // every family at its cap
    ++share[best];
  }
  return share;
}

struct Buffers {
  std::vector<std::uint32_t> depth;
  std::vector<std::uint8_t> stencil;
  friend bool operator==(const Buffers&, const Buffers&) = default;
};

Buffers onCpu(const Candidate& c) {
  raster::CpuDevice dev(c.width, c.height);
  raster::replay(c.commands, dev);
  return {{dev.depthBuffer().begin(), dev.depthBuffer().end()},
          {dev.stencilBuffer().begin(), dev.stencilBuffer().end()}};
}

// The variant's buffers differ from the contract's, or its validation refuses the stream.
bool differs(const Candidate& c, const Buffers& contract, Variant v) {
  ReferenceModel model(c.width, c.height, v);
  try {
    model.run(c.commands);
  } catch (const std::invalid_argument&) {
    return true;
  }
  return Buffers{model.depthBuffer(), model.stencilBuffer()} != contract;
}

// A vector's own random source: the same for (seed, family, index) whatever the count.
Rng vectorRng(std::uint64_t seed, std::size_t family, int index) {
  return Rng(seed * 0x9E3779B97F4A7C15ull + (family + 1) * 0xBF58476D1CE4E5B9ull +
             static_cast<std::uint64_t>(index) * 0x94D049BB133111EBull);
}

KitVector pickVector(std::size_t familyIndex, int index, std::uint64_t seed) {
  const Family& family = kFamilies[familyIndex];
  Rng rng = vectorRng(seed, familyIndex, index);
  const std::string name = std::string(family.info.name) + "_" + std::to_string(index);
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const Candidate c = family.draw(rng, index);
    const Buffers contract = onCpu(c);
    if (differs(c, contract, Variant::Contract))
      throw std::logic_error(name + ": the reference model disagrees with CpuDevice");
    const bool touched = std::any_of(contract.depth.begin(), contract.depth.end(),
                                     [](std::uint32_t d) { return d != raster::kDepthMax; }) ||
                         std::any_of(contract.stencil.begin(), contract.stencil.end(),
                                     [](std::uint8_t s) { return s != 0; });
    const bool discriminates =
        c.targets.empty() || std::any_of(c.targets.begin(), c.targets.end(),
                                         [&](Variant v) { return differs(c, contract, v); });
    if (!touched || !discriminates)
      continue;
    KitVector out{name, std::string(family.info.name), {}, {}};
    std::string caught;
    for (const VariantInfo& v : wrongVariants()) {
      if (differs(c, contract, v.variant)) {
        out.catches.push_back(v.variant);
        caught += (caught.empty() ? "" : ", ") + std::string(v.name);
      }
    }
    out.golden.description = c.description + " Wrong variants it catches: " + caught + ".";
    out.golden.stream = {c.width, c.height, c.commands};
    out.golden.depth = contract.depth;
    out.golden.stencil = contract.stencil;
    return out;
  }
  throw std::logic_error(name + ": no candidate in " + std::to_string(kAttempts) +
                         " discriminates its target variants");
}

}  // namespace

std::span<const FamilyInfo> kitFamilies() {
  static const std::vector<FamilyInfo> infos = [] {
    std::vector<FamilyInfo> v;
    for (const Family& f : kFamilies)
      v.push_back(f.info);
    return v;
  }();
  return infos;
}

std::vector<KitVector> generateKit(int count, std::uint64_t seed) {
  if (count < 1)
    throw std::invalid_argument("the kit needs a count of at least 1, got " +
                                std::to_string(count));
  const std::vector<int> share = shareCount(count);
  std::vector<KitVector> kit;
  for (std::size_t f = 0; f < kFamilies.size(); ++f) {
    for (int i = 0; i < share[f]; ++i)
      kit.push_back(pickVector(f, i, seed));
  }
  return kit;
}

KitVector randomKitStream(std::uint64_t seed, int index, std::string_view family) {
  if (index < 0)
    throw std::invalid_argument("a random stream's index is at least 0, got " +
                                std::to_string(index));
  std::vector<std::size_t> families;
  std::string names;
  for (std::size_t f = 0; f < kFamilies.size(); ++f) {
    if (kFamilies[f].info.name == "wide")
      continue;
    names += (names.empty() ? "" : ", ") + std::string(kFamilies[f].info.name);
    if (family.empty() || kFamilies[f].info.name == family)
      families.push_back(f);
  }
  if (families.empty())
    throw std::invalid_argument("random streams: unknown family \"" + std::string(family) +
                                "\" (families: " + names + ")");
  const std::size_t f = families[static_cast<std::size_t>(index) % families.size()];
  const int round = index / static_cast<int>(families.size());
  // Another stream of random numbers than the kit's own vectors of the same seed.
  Rng rng = vectorRng(~seed, f, round);
  const Candidate c = kFamilies[f].draw(rng, round);
  const Buffers contract = onCpu(c);
  KitVector out{"random-" + std::to_string(seed) + "-" +
                    (family.empty() ? "" : std::string(family) + "-") + std::to_string(index),
                std::string(kFamilies[f].info.name),
                {},
                {}};
  out.golden.description = "Random stream " + std::to_string(index) + " of seed " +
                           std::to_string(seed) + " (family " + out.family + "): " + c.description;
  out.golden.stream = {c.width, c.height, c.commands};
  out.golden.depth = contract.depth;
  out.golden.stencil = contract.stencil;
  return out;
}

namespace {

bool isKitFile(const std::filesystem::path& p) {
  if (p.extension() != ".json")
    return false;
  const std::string stem = p.stem().string();
  for (const Family& f : kFamilies) {
    const std::string prefix = std::string(f.info.name) + "_";
    if (stem.size() > prefix.size() && stem.compare(0, prefix.size(), prefix) == 0 &&
        std::all_of(stem.begin() + static_cast<std::ptrdiff_t>(prefix.size()), stem.end(),
                    [](char c) { return c >= '0' && c <= '9'; })) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<std::filesystem::path> writeKit(const std::vector<KitVector>& kit,
                                            const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  // Every vector is written into a staging folder beside its target first: a write that fails
  // (a full disk) leaves the earlier kit as it was and no partial files.
  const fs::path staging = dir / ".recode-kit-staging";
  fs::remove_all(staging);
  fs::create_directory(staging);
  try {
    for (const KitVector& v : kit)
      raster::writeGolden(staging / (v.name + ".json"), v.golden, raster::GoldenLayout::Rows);
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw;
  }
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && isKitFile(entry.path()))
      fs::remove(entry.path());
  }
  std::vector<fs::path> written;
  for (const KitVector& v : kit) {
    written.push_back(dir / (v.name + ".json"));
    fs::rename(staging / (v.name + ".json"), written.back());
  }
  fs::remove(staging);
  return written;
}

}  // namespace recode::kit
