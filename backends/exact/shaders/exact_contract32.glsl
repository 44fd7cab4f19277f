// The rasterization contract's per-fragment arithmetic (docs/rasterization.md, sections 4 and 5)
// in 32-bit words only, for GPUs without 64-bit integers or doubles (most mobile Vulkan GPUs,
// Metal, WebGPU): no double, no int64 type anywhere, so the SPIR-V declares neither the Float64
// nor the Int64 capability. The results are the bits of exact_contract.glsl's, which the CPU
// reference computes in int64_t and double.
//
// Written to be ported line for line to WGSL or MSL: only uint/int arithmetic, bit operations,
// findMSB and the four extended-arithmetic built-ins umulExtended, imulExtended, uaddCarry and
// usubBorrow, each used only inside the three helpers below (wideProduct, signedWideProduct,
// add64/sub64), which a language without them (WGSL) writes once with 16-bit halves.
//
// Representations:
// - a 64-bit integer is a uvec2 (low word, high word), two's complement when signed;
// - a double is its IEEE-754 bit pattern in the same uvec2 layout (GLSL's unpackDouble2x32,
//   a little-endian memcpy on the CPU).
//
// What the soft double needs to handle, and why nothing else can occur. The contract evaluates
// z = (z0 + tx) + ty with tx = dzdx (Xc - X0), ty = dzdy (Yc - Y0), then RN(z 16777215):
// - z0 is a float in [0, 1]: 0 or a multiple of 2^-149 in [2^-149, 1], so a normal double.
// - The slopes come set up from the CPU: dzdx = RN(N / a2) with a2 a nonzero integer below 2^49
//   and N = RN(RN(dz1 e2y) - RN(dz2 e1y)), where |dz| <= 1 and the e are integers of at most
//   2^24, so |N| <= 2^25. Every dz is a float difference rounded to double: a multiple of
//   2^-149 (rounding a multiple of 2^-149 to a grid of powers of two at least as coarse keeps
//   it one), and so are the products and N. So a slope is 0 or in [2^-198, 2^25].
// - The deltas Xc - X0 are integers below 2^24 in magnitude (section 2), so tx, ty are 0 or in
//   [2^-198, 2^49]; every operand and every exact sum is a multiple of 2^-250 (a double of at
//   least 2^-198 is a multiple of 2^-250), so a nonzero sum is at least 2^-250, and at most
//   2^51.
// So every operand and every result is zero or a normal double between 2^-250 and 2^51: no
// subnormal, infinity or NaN ever reaches these functions, and none can be produced (the
// smallest normal double is 2^-1022). They assume that and do not check it.

const uint kSignBit = 0x80000000u;
const uint kHiddenBit = 0x00100000u;     // bit 52 of a significand, in the high word
const uint kFractionHigh = 0x000FFFFFu;  // the high word's 20 fraction bits

// ---- 64-bit integers as word pairs ----

uvec2 add64(uvec2 a, uvec2 b) {
  uint carry;
  uint low = uaddCarry(a.x, b.x, carry);
  return uvec2(low, a.y + b.y + carry);
}

uvec2 sub64(uvec2 a, uvec2 b) {
  uint borrow;
  uint low = usubBorrow(a.x, b.x, borrow);
  return uvec2(low, a.y - b.y - borrow);
}

// The full 64-bit product of two unsigned words.
uvec2 wideProduct(uint a, uint b) {
  uint high, low;
  umulExtended(a, b, high, low);
  return uvec2(low, high);
}

// The full 64-bit two's-complement product of two signed words.
uvec2 signedWideProduct(int a, int b) {
  int high, low;
  imulExtended(a, b, high, low);
  return uvec2(uint(low), uint(high));
}

bool isZero64(uvec2 a) {
  return (a.x | a.y) == 0u;
}

bool equal64(uvec2 a, uvec2 b) {
  return a.x == b.x && a.y == b.y;
}

bool less64(uvec2 a, uvec2 b) {  // unsigned
  return a.y < b.y || (a.y == b.y && a.x < b.x);
}

// Shifts by 0 <= n <= 63: GLSL (and WGSL, MSL) leave a word shifted by 32 or more undefined.
uvec2 shiftRight64(uvec2 a, uint n) {
  if (n == 0u)
    return a;
  if (n >= 32u)
    return uvec2(a.y >> (n - 32u), 0u);
  return uvec2((a.x >> n) | (a.y << (32u - n)), a.y >> n);
}

uvec2 shiftLeft64(uvec2 a, uint n) {
  if (n == 0u)
    return a;
  if (n >= 32u)
    return uvec2(0u, a.x << (n - 32u));
  return uvec2(a.x << n, (a.y << n) | (a.x >> (32u - n)));
}

// The position of the highest set bit, -1 for zero.
int highestBit64(uvec2 a) {
  return a.y != 0u ? 32 + findMSB(a.y) : findMSB(a.x);
}

// a >> n rounded to nearest, ties to even, for 1 <= n <= 63: the contract's rounding of every
// operation, applied to an exact integer result.
uvec2 shiftRightRoundEven(uvec2 a, uint n) {
  uvec2 kept = shiftRight64(a, n);
  uvec2 dropped = sub64(a, shiftLeft64(kept, n));
  uvec2 halfway = shiftLeft64(uvec2(1u, 0u), n - 1u);
  bool up = less64(halfway, dropped) || (equal64(dropped, halfway) && (kept.x & 1u) != 0u);
  return up ? add64(kept, uvec2(1u, 0u)) : kept;
}

// ---- doubles as bit patterns (zero or normal: see the top of the file) ----

uint doubleSign(uvec2 d) {
  return d.y & kSignBit;
}

uint doubleExponent(uvec2 d) {  // biased: the value is significand 2^(exponent - 1075)
  return (d.y >> 20) & 0x7FFu;
}

uvec2 doubleSignificand(uvec2 d) {  // 53 bits, the hidden bit included
  return uvec2(d.x, (d.y & kFractionHigh) | kHiddenBit);
}

bool doubleIsZero(uvec2 d) {
  return d.x == 0u && (d.y & ~kSignBit) == 0u;
}

// A double from a 53-bit significand m (2^52 <= m < 2^53, or 2^53 after a rounding carry) and
// its biased exponent.
uvec2 makeDouble(uint sign, uint exponent, uvec2 m) {
  if (m.y == (kHiddenBit << 1)) {  // rounded up to 2^53: 2^52 one exponent higher
    m = shiftRight64(m, 1u);
    exponent += 1u;
  }
  return uvec2(m.x, sign | (exponent << 20) | (m.y & kFractionHigh));
}

// (double) f for the bits f of a finite float: exact. A subnormal float (z may be as small as
// 2^-149) is a normal double.
uvec2 doubleFromFloatBits(uint f) {
  uint sign = f & kSignBit;
  uint exponent = (f >> 23) & 0xFFu;
  uint fraction = f & 0x7FFFFFu;
  if (exponent == 0u) {
    if (fraction == 0u)
      return uvec2(0u, sign);
    int top = findMSB(fraction);  // the value is 1.xxx 2^(top - 149)
    fraction = (fraction << uint(23 - top)) & 0x7FFFFFu;
    exponent = uint(top - 149 + 1023);
  } else {
    exponent = exponent - 127u + 1023u;
  }
  return uvec2(fraction << 29, sign | (exponent << 20) | (fraction >> 3));
}

// RN(d k) for an integer |k| < 2^25: the contract's dzdx * (double)(Xc - X0) and
// z * 16777215.0 ((double) k is exact, so multiplying by the integer itself gives the same
// rounded product). The exact product m |k| < 2^78 takes three words; it is shifted right by
// the s <= 25 bits beyond 53 and rounded.
uvec2 multiplyByInteger(uvec2 d, int k) {
  uint sign = doubleSign(d) ^ (k < 0 ? kSignBit : 0u);
  uint magnitude = uint(abs(k));
  if (magnitude == 0u || doubleIsZero(d))
    return uvec2(0u, sign);
  uvec2 m = doubleSignificand(d);
  uvec2 low = wideProduct(m.x, magnitude);   // bits 0..63
  uvec2 high = wideProduct(m.y, magnitude);  // bits 32..77
  uvec2 middle = add64(uvec2(low.y, 0u), high);
  uint w0 = low.x, w1 = middle.x, w2 = middle.y;  // the product, w2 < 2^14
  int top = w2 != 0u ? 64 + findMSB(w2) : highestBit64(uvec2(w0, w1));
  uint s = uint(top - 52);
  uint exponent = doubleExponent(d) + s;
  if (s == 0u)
    return makeDouble(sign, exponent, uvec2(w0, w1));
  // Keep one bit more than the significand, and whether anything below it is set: the bits
  // dropped are all in w0 (s <= 25), so a sticky bit stands for them exactly.
  uint t = s - 1u;
  uvec2 kept = t == 0u ? uvec2(w0, w1)
                       : uvec2((w0 >> t) | (w1 << (32u - t)), (w1 >> t) | (w2 << (32u - t)));
  uint sticky = (w0 & ((1u << t) - 1u)) != 0u ? 1u : 0u;
  // kept has 54 bits; with the sticky bit below them two bits of rounding information remain
  // (round bit, sticky), all that ties-to-even needs.
  uvec2 jammed = add64(shiftLeft64(kept, 1u), uvec2(sticky, 0u));
  return makeDouble(sign, exponent, shiftRightRoundEven(jammed, 2u));
}

// RN(a + b), IEEE-754 addition rounded to nearest even. The operands are aligned in 64-bit
// words with the significands' leading bit at bit 62 (10 guard bits below, one carry bit above);
// bits shifted out of the smaller operand are kept as a sticky bit at bit 0. That bit lies at
// least 8 places below the rounding position, so it decides only "above or below the exact
// half", never a tie, and a tie is decided by exact bits. A large cancellation (leading bit
// below 61) only happens when the exponents differ by 0 or 1, when nothing was shifted out: the
// left shift that renormalises it is exact.
uvec2 addDoubles(uvec2 a, uvec2 b) {
  if (doubleIsZero(b))
    return doubleIsZero(a) ? uvec2(0u, a.y & b.y & kSignBit) : a;  // -0 + -0 = -0, else +0
  if (doubleIsZero(a))
    return b;
  if (less64(uvec2(a.x, a.y & ~kSignBit), uvec2(b.x, b.y & ~kSignBit))) {
    uvec2 swap = a;
    a = b;
    b = swap;
  }
  uint exponent = doubleExponent(a);
  uint shift = exponent - doubleExponent(b);
  uvec2 ma = shiftLeft64(doubleSignificand(a), 10u);
  uvec2 mb = shiftLeft64(doubleSignificand(b), 10u);
  if (shift >= 64u) {
    mb = uvec2(1u, 0u);  // b is below every bit kept: sticky alone
  } else if (shift > 0u) {
    uvec2 kept = shiftRight64(mb, shift);
    bool lost = !equal64(shiftLeft64(kept, shift), mb);
    mb = uvec2(kept.x | (lost ? 1u : 0u), kept.y);
  }
  bool subtract = doubleSign(a) != doubleSign(b);
  uvec2 sum = subtract ? sub64(ma, mb) : add64(ma, mb);
  if (isZero64(sum))
    return uvec2(0u);  // exact cancellation: +0 when rounding to nearest
  int top = highestBit64(sum);
  if (top == 63) {  // a carry: one place right, the dropped bit kept as sticky
    sum = uvec2((sum.x >> 1) | (sum.y << 31) | (sum.x & 1u), sum.y >> 1);
  } else if (top < 62) {
    sum = shiftLeft64(sum, uint(62 - top));
  }
  uint resultExponent = uint(int(exponent) + top - 62);
  return makeDouble(doubleSign(a), resultExponent, shiftRightRoundEven(sum, 10u));
}

// ---- the contract ----

// The plane at a centre: (z0 + tx) + ty, each product and sum rounded on its own (section 5).
// z0 and the slopes (dzdx, dzdy) are doubles' bits; v0 and the centre are 24.8 fixed point.
uvec2 depthAt32(uvec2 z0, uvec4 slopes, ivec2 v0, ivec2 centre) {
  uvec2 tx = multiplyByInteger(slopes.xy, centre.x - v0.x);
  uvec2 ty = multiplyByInteger(slopes.zw, centre.y - v0.y);
  return addDoubles(addDoubles(z0, tx), ty);
}

// Clamp and quantise to the 24-bit q: 0 for z <= 0, 2^24 - 1 for z >= 1, else
// roundEven(RN(z 16777215)). For 0 < z < 1 the scaled value is below 2^24, so its significand's
// binary point lies at least 29 places up; below 2^-11 it rounds to 0.
uint quantizeDepth32(uvec2 z) {
  if (doubleIsZero(z) || doubleSign(z) != 0u)
    return 0u;
  if (doubleExponent(z) >= 1023u)
    return 16777215u;
  uvec2 scaled = multiplyByInteger(z, 16777215);
  uint fractionBits = 1075u - doubleExponent(scaled);
  if (fractionBits >= 64u)
    return 0u;
  return shiftRightRoundEven(doubleSignificand(scaled), fractionBits).x;
}

// Does directed edge a -> b of a counter-clockwise triangle cover the centre? E > 0, or E = 0
// on an inclusive (left or bottom) edge (section 4). E = dx (Yc - Ya) - dy (Xc - Xa) needs up
// to 50 bits: each factor fits a word (|dx|, |dy| <= 2^24, a centre minus a vertex below
// 1.5 2^23), each product is a full 64-bit word pair, and their difference (below 2^49 in
// magnitude) cannot wrap.
bool edgeCovers32(ivec2 a, ivec2 b, ivec2 centre) {
  int dx = b.x - a.x;
  int dy = b.y - a.y;
  uvec2 e = sub64(signedWideProduct(dx, centre.y - a.y), signedWideProduct(dy, centre.x - a.x));
  bool zero = isZero64(e);
  bool positive = int(e.y) > 0 || (e.y == 0u && !zero);
  bool inclusive = dy < 0 || (dy == 0 && dx > 0);
  return positive || (zero && inclusive);
}

// Coverage of the triangle (v0, v1, v2) in submitted order, of the facing given (the CPU's exact
// sign of the area): the edges run counter-clockwise, (v0, v1, v2) when front-facing and
// (v0, v2, v1) when back-facing.
bool triangleCovers32(ivec2 v0, ivec2 v1, ivec2 v2, bool frontFacing, ivec2 centre) {
  ivec2 p1 = frontFacing ? v1 : v2;
  ivec2 p2 = frontFacing ? v2 : v1;
  return edgeCovers32(v0, p1, centre) && edgeCovers32(p1, p2, centre) &&
         edgeCovers32(p2, v0, centre);
}

// The fixed-point position of the centre of the pixel whose window coordinates are fragCoord
// (i + 0.5, j + 0.5): (256 i + 128, 256 j + 128), at most 2^22 + 128.
ivec2 pixelCentreFixed32(vec2 fragCoord) {
  return ivec2(floor(fragCoord)) * 256 + 128;
}
