// exact_contract32.glsl, the contract's arithmetic in 32-bit words, against the CPU's int64_t
// and double arithmetic, bit for bit: each function of the library runs in a compute shader on
// the vulkan-32 device's logical device (contract32_ops.comp) over millions of operands, random
// over the contract's value ranges (docs/rasterization.md, "Value ranges") and built to be hard:
// ties to even, carries into the next binade, cancellation, signed zeros, the largest deltas,
// the smallest slopes, subnormal floats.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <span>
#include <vector>

#include "compute_harness.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace {

using std::uint32_t;
#include "contract32_ops.comp.h"

using recode::raster::FixedVertex;

// The operation codes of contract32_ops.comp.
enum class Op : uint32_t { MultiplyByInteger, Add, Quantize, FloatToDouble, Depth, Coverage };

struct Operands {
  uint32_t a[4] = {};
  uint32_t b[4] = {};
  uint32_t c[4] = {};
};
static_assert(sizeof(Operands) == 48, "the shader's std430 Operands");
using Result = std::array<uint32_t, 4>;

std::vector<Result> runOnGpu(Op op, const std::vector<Operands>& in) {
  static recode::testing::ComputeHarness harness(k_contract32_ops_comp, 8);
  const uint32_t push[2] = {static_cast<uint32_t>(op), static_cast<uint32_t>(in.size())};
  const std::span<const std::uint8_t> input(reinterpret_cast<const std::uint8_t*>(in.data()),
                                            in.size() * sizeof(Operands));
  const auto bytes =
      harness.run(input, in.size() * sizeof(Result), static_cast<uint32_t>(in.size()),
                  std::span(reinterpret_cast<const std::uint8_t*>(push), sizeof(push)));
  std::vector<Result> out(in.size());
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

void putDouble(uint32_t* words, double d) {
  const auto bits = std::bit_cast<std::uint64_t>(d);
  words[0] = static_cast<uint32_t>(bits);
  words[1] = static_cast<uint32_t>(bits >> 32);
}

std::uint64_t doubleBits(double d) {
  return std::bit_cast<std::uint64_t>(d);
}

double fromBits(std::uint64_t bits) {
  return std::bit_cast<double>(bits);
}

// A double of random sign and 52 random fraction bits with an unbiased exponent in [lo, hi]; a
// quarter of them with the low fraction bits cleared or set, which makes exact products, ties
// and carries frequent.
double randomDouble(std::mt19937_64& rng, int lo, int hi) {
  std::uint64_t fraction = rng() & ((1ull << 52) - 1);
  switch (rng() % 8) {
    case 0:
      fraction &= ~((1ull << (rng() % 52)) - 1);
      break;
    case 1:
      fraction |= (1ull << (rng() % 52)) - 1;
      break;
    default:
      break;
  }
  const auto exponent = static_cast<std::uint64_t>(
      lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1)) + 1023);
  const std::uint64_t sign = (rng() & 1) << 63;
  return fromBits(sign | (exponent << 52) | fraction);
}

// An integer of magnitude below 2^bits, its length uniform so that small ones are common.
std::int32_t randomInteger(std::mt19937_64& rng, int bits) {
  const int length = static_cast<int>(rng() % static_cast<unsigned>(bits + 1));
  const auto magnitude = static_cast<std::int32_t>(rng() & ((1ull << length) - 1));
  return (rng() & 1) ? -magnitude : magnitude;
}

// A float in [0, 1]: uniform, subnormal, 0, 1, or with few significant bits.
float randomDepth(std::mt19937_64& rng) {
  switch (rng() % 8) {
    case 0:
      return std::bit_cast<float>(static_cast<uint32_t>(rng() % 0x800000u));  // subnormal or 0
    case 1:
      return (rng() & 1) ? 1.0f : 0.0f;
    case 2:
      return static_cast<float>(rng() % 17) / 16.0f;
    default:
      return std::bit_cast<float>(static_cast<uint32_t>(rng() % 0x3F800001u));  // [0, 1]
  }
}

// Snapped vertices as the contract allows them: anywhere in +-2^23, or a small triangle around
// a random point, or a long sliver.
std::array<FixedVertex, 3> randomTriangle(std::mt19937_64& rng) {
  const auto coordinate = [&] {
    return static_cast<std::int64_t>(rng() % (1u << 24) + 1) - (1 << 23);
  };
  std::array<FixedVertex, 3> v;
  const unsigned shape = rng() % 4;
  const std::int64_t cx = coordinate(), cy = coordinate();
  const int spread = shape == 0 ? 24 : static_cast<int>(4 + rng() % 16);
  for (FixedVertex& p : v) {
    if (shape == 0) {
      p.x = coordinate();
      p.y = coordinate();
    } else {
      p.x = std::clamp<std::int64_t>(cx + randomInteger(rng, spread), -(1 << 23), 1 << 23);
      p.y = std::clamp<std::int64_t>(cy + randomInteger(rng, spread), -(1 << 23), 1 << 23);
    }
    if (shape == 3 && (rng() & 1))  // on the pixel-centre grid: samples on edges and vertices
      p.x = (p.x >> 8) * 256 + 128;
    p.z = randomDepth(rng);
  }
  if (rng() % 16 == 0) {  // the extreme corners: the largest differences and products
    v[0].x = -(1 << 23);
    v[1].x = 1 << 23;
    v[2].y = (rng() & 1) ? 1 << 23 : -(1 << 23);
  }
  return v;
}

// A pixel centre of a framebuffer of up to 16384 pixels, near a given fixed-point point half
// of the time.
std::int64_t randomCentre(std::mt19937_64& rng, std::int64_t near) {
  std::int64_t pixel = static_cast<std::int64_t>(rng() % 16384);
  if (rng() & 1)
    pixel = std::clamp<std::int64_t>((near >> 8) + randomInteger(rng, 4), 0, 16383);
  return pixel * 256 + 128;
}

// Compares each result and counts the differences, reporting the first few.
template <typename Expected>
void expectEqual(const char* what, const std::vector<Operands>& in, const std::vector<Result>& out,
                 Expected expected) {
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Result want = expected(in[i]);
    if (want == out[i])
      continue;
    if (++wrong <= 5) {
      UNSCOPED_INFO(what << " operand " << i << ": a " << std::hex << in[i].a[1] << ':'
                         << in[i].a[0] << " b " << in[i].b[1] << ':' << in[i].b[0] << " c "
                         << in[i].c[0] << ',' << in[i].c[1] << " gives " << out[i][1] << ':'
                         << out[i][0] << ' ' << out[i][2] << ' ' << out[i][3] << ", expected "
                         << want[1] << ':' << want[0] << ' ' << want[2] << ' ' << want[3]
                         << std::dec);
    }
  }
  INFO(what << ": " << in.size() << " operands, " << wrong << " different");
  CHECK(wrong == 0);
}

Result doubleResult(double d) {
  const std::uint64_t bits = doubleBits(d);
  return {static_cast<uint32_t>(bits), static_cast<uint32_t>(bits >> 32), 0, 0};
}

}  // namespace

TEST_CASE("multiplyByInteger is the double product, rounded to nearest even", "[vulkan-32]") {
  std::mt19937_64 rng(1);
  std::vector<Operands> in;
  const auto add = [&](double d, std::int32_t k) {
    Operands o;
    putDouble(o.a, d);
    o.b[0] = static_cast<uint32_t>(k);
    in.push_back(o);
  };
  for (int i = 0; i < 2'000'000; ++i) {
    switch (i % 4) {
      case 0:  // a slope and a delta anywhere in the contract's ranges
        add(randomDouble(rng, -198, 25), randomInteger(rng, 24));
        break;
      case 1:  // small integers: products with one or two bits to drop, ties half the time
        add(randomDouble(rng, -198, 25), randomInteger(rng, 4));
        break;
      case 2:  // the quantisation's z * 16777215
        add(std::fabs(randomDouble(rng, -60, -1)), 16777215);
        break;
      default:  // up to the function's own bound, 2^25
        add(randomDouble(rng, -300, 300), randomInteger(rng, 25));
        break;
    }
  }
  for (const double d : {0.0, -0.0, 0x1p25, -0x1p25, 0x1p-198, -0x1p-198, 1.0, 0x1.fffffffffffffp0})
    for (const std::int32_t k :
         {0, 1, -1, 3, (1 << 24) - 1, -(1 << 24), 3 << 22, -(3 << 22), 16777215, (1 << 25) - 1})
      add(d, k);
  const auto out = runOnGpu(Op::MultiplyByInteger, in);
  expectEqual("multiplyByInteger", in, out, [](const Operands& o) {
    const double d = fromBits(o.a[0] | (static_cast<std::uint64_t>(o.a[1]) << 32));
    return doubleResult(d * static_cast<double>(static_cast<std::int32_t>(o.b[0])));
  });
}

TEST_CASE("addDoubles is the double sum, rounded to nearest even", "[vulkan-32]") {
  std::mt19937_64 rng(2);
  std::vector<Operands> in;
  const auto add = [&](double a, double b) {
    Operands o;
    putDouble(o.a, a);
    putDouble(o.b, b);
    in.push_back(o);
  };
  for (int i = 0; i < 2'000'000; ++i) {
    const double a = randomDouble(rng, -250, 51);
    const int ea = std::ilogb(a);
    switch (i % 5) {
      case 0: {  // exponents 0 to 70 apart, either order, either sign
        const int eb = ea - static_cast<int>(rng() % 71);
        const double b = randomDouble(rng, eb, eb);
        (rng() & 1) ? add(a, b) : add(b, a);
        break;
      }
      case 1: {  // cancellation: minus a within a few hundred ulps, the leading bits lost
        const auto delta = static_cast<std::int64_t>(rng() % 512) - 256;
        const double b = -fromBits(doubleBits(a) + static_cast<std::uint64_t>(delta));
        add(a, b);
        break;
      }
      case 2: {  // exactly half an ulp of a, or just above or below it: ties and near-ties
        const double half = std::ldexp(1.0, ea - 53) * ((rng() & 1) ? 1.0 : 3.0);
        const double nudge =
            (rng() % 3 == 0) ? std::ldexp(1.0, ea - 53 - static_cast<int>(rng() % 60)) : 0.0;
        const double b = std::copysign(half, (rng() & 1) ? 1.0 : -1.0) + nudge;
        add(a, b);
        break;
      }
      case 3: {  // the contract's sums: a float z0 plus a product, then a second product
        const double z0 = static_cast<double>(randomDepth(rng));
        const double tx = randomDouble(rng, -198, 25) * static_cast<double>(randomInteger(rng, 24));
        add(z0, tx);
        break;
      }
      default: {  // exponents one apart, opposite signs: the largest renormalising shifts
        const double b = -randomDouble(rng, ea - 1, ea);
        add(a, std::copysign(b, -a));
        break;
      }
    }
  }
  for (const double a : {0.0, -0.0, 1.0, -1.0, 0x1p-250, 0x1p51})
    for (const double b : {0.0, -0.0, 1.0, -1.0, 0x1p-250, -0x1p51, 0x1p-54, -0x1p-53})
      add(a, b);
  const auto out = runOnGpu(Op::Add, in);
  expectEqual("addDoubles", in, out, [](const Operands& o) {
    const double a = fromBits(o.a[0] | (static_cast<std::uint64_t>(o.a[1]) << 32));
    const double b = fromBits(o.b[0] | (static_cast<std::uint64_t>(o.b[1]) << 32));
    return doubleResult(a + b);
  });
}

TEST_CASE("quantizeDepth32 is raster::quantizeDepth", "[vulkan-32]") {
  std::mt19937_64 rng(3);
  std::vector<Operands> in;
  const auto add = [&](double z) {
    Operands o;
    putDouble(o.a, z);
    in.push_back(o);
  };
  for (int i = 0; i < 1'000'000; ++i) {
    if (i % 2 == 0) {
      add(std::fabs(randomDouble(rng, -64, 0)));
      continue;
    }
    // Around the exact halfway points (k + 0.5) / (2^24 - 1), a few ulps either side: the
    // product rounds onto k + 0.5 for some, and round half to even decides.
    const double k = static_cast<double>(rng() % 16777215);
    const double tie = (k + 0.5) / 16777215.0;
    add(fromBits(doubleBits(tie) + rng() % 7 - 3));
  }
  for (const double z : {0.0, -0.0, 1.0, 0x1.fffffffffffffp-1, 0x1p-250, -0x1p-250, 0x1p51, -1.0,
                         0.5 / 16777215.0, 1.5 / 16777215.0, 0x1p-25, 0x1p-24})
    add(z);
  const auto out = runOnGpu(Op::Quantize, in);
  expectEqual("quantizeDepth32", in, out, [](const Operands& o) {
    const double z = fromBits(o.a[0] | (static_cast<std::uint64_t>(o.a[1]) << 32));
    return Result{recode::raster::quantizeDepth(z), 0, 0, 0};
  });
}

TEST_CASE("doubleFromFloatBits widens every finite float exactly", "[vulkan-32]") {
  std::mt19937_64 rng(4);
  std::vector<Operands> in;
  for (int i = 0; i < 500'000; ++i) {
    Operands o;
    auto bits = static_cast<uint32_t>(rng());
    if (i % 4 == 0)
      bits &= 0x807FFFFFu;  // subnormal (or zero), either sign
    if (((bits >> 23) & 0xFFu) == 0xFFu)
      bits &= 0xBFFFFFFFu;  // no infinity or NaN: the contract's z is finite
    o.a[0] = bits;
    in.push_back(o);
  }
  for (const uint32_t bits : {0u, 0x80000000u, 1u, 0x7FFFFFu, 0x800000u, 0x3F800000u})
    in.push_back(Operands{{bits}});
  const auto out = runOnGpu(Op::FloatToDouble, in);
  expectEqual("doubleFromFloatBits", in, out, [](const Operands& o) {
    return doubleResult(static_cast<double>(std::bit_cast<float>(o.a[0])));
  });
}

TEST_CASE("depthAt32 and quantizeDepth32 give the CPU plane's bits on set-up triangles",
          "[vulkan-32]") {
  std::mt19937_64 rng(5);
  std::vector<Operands> in;
  std::vector<recode::raster::DepthPlane> planes;
  while (in.size() < 2'000'000) {
    const auto v = randomTriangle(rng);
    const auto setup = recode::raster::setupTriangle(v[0], v[1], v[2]);
    if (!setup)
      continue;
    for (int s = 0; s < 4; ++s) {
      Operands o;
      o.a[0] = std::bit_cast<uint32_t>(v[0].z);
      o.a[1] = static_cast<uint32_t>(v[0].x);
      o.a[2] = static_cast<uint32_t>(v[0].y);
      putDouble(o.b, setup->depth.dzdx);
      putDouble(o.b + 2, setup->depth.dzdy);
      o.c[0] = static_cast<uint32_t>(randomCentre(rng, v[s % 3].x));
      o.c[1] = static_cast<uint32_t>(randomCentre(rng, v[s % 3].y));
      in.push_back(o);
      planes.push_back(setup->depth);
    }
  }
  const auto out = runOnGpu(Op::Depth, in);
  std::size_t i = 0;
  expectEqual("depthAt32", in, out, [&](const Operands& o) {
    const recode::raster::DepthPlane& plane = planes[i++];
    const double z = plane.at(static_cast<std::int32_t>(o.c[0]), static_cast<std::int32_t>(o.c[1]));
    Result r = doubleResult(z);
    r[2] = recode::raster::quantizeDepth(z);
    return r;
  });
}

TEST_CASE("triangleCovers32 and edgeCovers32 are the contract's 64-bit coverage", "[vulkan-32]") {
  std::mt19937_64 rng(6);
  std::vector<Operands> in;
  std::vector<bool> covered;
  while (in.size() < 1'000'000) {
    const auto v = randomTriangle(rng);
    const auto coverage = recode::raster::setupCoverage(v[0], v[1], v[2]);
    if (!coverage)
      continue;  // zero area: no proxy is drawn
    for (int s = 0; s < 4; ++s) {
      Operands o;
      for (int k = 0; k < 2; ++k) {
        o.a[2 * k] = static_cast<uint32_t>(v[k].x);
        o.a[2 * k + 1] = static_cast<uint32_t>(v[k].y);
      }
      o.b[0] = static_cast<uint32_t>(v[2].x);
      o.b[1] = static_cast<uint32_t>(v[2].y);
      o.b[2] = coverage->frontFacing ? 1u : 0u;
      const std::int64_t cx = randomCentre(rng, v[s % 3].x);
      const std::int64_t cy = randomCentre(rng, v[s % 3].y);
      o.c[0] = static_cast<uint32_t>(cx);
      o.c[1] = static_cast<uint32_t>(cy);
      in.push_back(o);
      bool inside = true;
      for (const auto& e : coverage->edges)
        inside = inside && e.at(cx, cy) >= 0;
      covered.push_back(inside);
    }
  }
  const auto out = runOnGpu(Op::Coverage, in);
  std::size_t i = 0;
  expectEqual("triangleCovers32", in, out, [&](const Operands& o) {
    const auto word = [](uint32_t w) {
      return static_cast<std::int64_t>(static_cast<std::int32_t>(w));
    };
    // Edge v0 -> v1 on its own, the contract's formula (section 4).
    const std::int64_t dx = word(o.a[2]) - word(o.a[0]);
    const std::int64_t dy = word(o.a[3]) - word(o.a[1]);
    const std::int64_t e = dx * (word(o.c[1]) - word(o.a[1])) - dy * (word(o.c[0]) - word(o.a[0]));
    const bool inclusive = dy < 0 || (dy == 0 && dx > 0);
    const bool edge = e > 0 || (e == 0 && inclusive);
    return Result{covered[i++] ? 1u : 0u, static_cast<uint32_t>(e),
                  static_cast<uint32_t>(static_cast<std::uint64_t>(e) >> 32), edge ? 1u : 0u};
  });
}
