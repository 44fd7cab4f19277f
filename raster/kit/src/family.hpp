#pragma once
// What a family of the conformance kit is (generator.hpp), and the helpers the families share:
// a deterministic random source and vertices written in 24.8 fixed point.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "recode/kit/variants.hpp"
#include "recode/raster/command_stream.hpp"

namespace recode::kit::detail {

// Random numbers that are the same on every platform: std::mt19937_64 is specified bit for
// bit, the standard distributions are not, so the ranges are made here.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  // An integer in [lo, hi].
  long long uniform(long long lo, long long hi) {
    const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
    return lo + static_cast<long long>(engine_() % span);
  }
  bool chance(int percent) { return uniform(0, 99) < percent; }
  // A float depth in [0, 1] on a grid of 2^-20, so that it is exactly a float.
  float depth() { return static_cast<float>(uniform(0, 1 << 20)) / static_cast<float>(1 << 20); }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[static_cast<std::size_t>(uniform(0, static_cast<long long>(v.size()) - 1))];
  }

 private:
  std::mt19937_64 engine_;
};

// A proposed vector; the generator keeps it when one of `targets` gets its bits wrong.
struct Candidate {
  std::string description;
  int width = 16, height = 16;
  std::vector<raster::Command> commands;
  std::vector<Variant> targets;
};

// Draws the family's candidate for vector `index` (the index chooses which case or target).
using DrawCandidate = Candidate (*)(Rng& rng, int index);

// The 24.8 fixed-point vertex (X, Y) with depth z; |X|, |Y| <= 2^23 stay exact in float.
inline raster::WindowVertex fixedVertex(long long X, long long Y, float z) {
  return {static_cast<float>(X) / 256.0f, static_cast<float>(Y) / 256.0f, z};
}
// The fixed-point centre of pixel column or row i.
inline long long centre(long long i) {
  return 256 * i + 128;
}
inline constexpr long long kLimit = 1LL << 23;  // |X|, |Y| <= 2^23: +-32768 pixels

// Stencil counts fragments (INCR_WRAP on front faces, DECR_WRAP on back faces: 1 and 255 for
// one fragment) and depth keeps the last fragment's bits (ALWAYS, writes on).
std::vector<raster::Command> countFacingsKeepDepth();
// The ops of one face, in GL's order.
raster::cmd::StencilOpsCmd opsFor(raster::Face face, raster::StencilOp sfail,
                                  raster::StencilOp dpfail, raster::StencilOp dppass);

// A triangle covering a width x height frame whose plane, evaluated as the contract says, lands
// exactly on quantisation ties (z * 16777215 = k + 0.5) at many samples; it varies along y if
// alongY, else along x; anchored at z0 = 0.5 if halfAnchor, else at z0 = 0
// (family_tie_plane.cpp gives the construction).
raster::cmd::Draw tiePlane(Rng& rng, int width, int height, bool alongY, bool halfAnchor);

// A triangle covering a width x height frame through a plane sloped along both axes whose
// exact value is a quantisation tie at every sample, k even or odd, its three depths distinct
// (family_sloped_tie_plane.cpp gives the construction).
raster::cmd::Draw slopedTiePlane(Rng& rng, int width, int height);

// Adds a steep sliver through sample points of the w x h frame at a tie, near one or at random
// depths, its vertices near or far, submitted from any vertex (family_steep_slivers.cpp).
void addSteepSliver(Rng& rng, int w, int h, raster::cmd::Draw& d);

// The families (one file each).
Candidate slivers(Rng& rng, int index);
Candidate fans(Rng& rng, int index);
Candidate sharedEdges(Rng& rng, int index);
Candidate limits(Rng& rng, int index);
Candidate depthTies(Rng& rng, int index);
Candidate anchorPlanes(Rng& rng, int index);
Candidate stencilSaturation(Rng& rng, int index);
Candidate masksReplace(Rng& rng, int index);
Candidate compareOps(Rng& rng, int index);
Candidate culling(Rng& rng, int index);
Candidate scissorClears(Rng& rng, int index);
Candidate wideFrames(Rng& rng, int index);
Candidate depthArithmetic(Rng& rng, int index);

}  // namespace recode::kit::detail
