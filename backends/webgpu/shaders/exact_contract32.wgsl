// The rasterization contract's per-fragment arithmetic (docs/rasterization.md, sections 4 and 5)
// in 32-bit words, for WebGPU: backends/exact/shaders/exact_contract32.glsl ported function for
// function (each function names its GLSL twin), with the same representations, the same
// reasoning about which doubles can occur (see the top of the GLSL file), and the same results.
// WGSL has neither 64-bit types nor GLSL's extended-arithmetic built-ins (umulExtended,
// imulExtended, uaddCarry, usubBorrow), so the three helpers that use them there are written
// here with comparisons and 16-bit halves; everything else is a line-for-line translation.
//
// Representations, as in the GLSL file: a 64-bit integer is a vec2<u32> (low word, high word),
// two's complement when signed; a double is its IEEE-754 bit pattern in the same layout.

const kSignBit: u32 = 0x80000000u;
const kHiddenBit: u32 = 0x00100000u;     // bit 52 of a significand, in the high word
const kFractionHigh: u32 = 0x000FFFFFu;  // the high word's 20 fraction bits

// GLSL's findMSB for a u32: the position of the highest set bit, -1 for zero.
fn findMSB(a: u32) -> i32 {
  if (a == 0u) {
    return -1;
  }
  return i32(firstLeadingBit(a));
}

// ---- 64-bit integers as word pairs ----

// GLSL: add64 (uaddCarry's carry is "the low sum wrapped").
fn add64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
  let low = a.x + b.x;
  let carry = select(0u, 1u, low < a.x);
  return vec2<u32>(low, a.y + b.y + carry);
}

// GLSL: sub64 (usubBorrow's borrow is "the low difference wrapped").
fn sub64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
  let borrow = select(0u, 1u, a.x < b.x);
  return vec2<u32>(a.x - b.x, a.y - b.y - borrow);
}

// GLSL: wideProduct. The full 64-bit product of two unsigned words from four 16-bit partial
// products, each below 2^32; the middle column sums three values below 2^16 each, so no sum
// wraps.
fn wideProduct(a: u32, b: u32) -> vec2<u32> {
  let al = a & 0xFFFFu;
  let ah = a >> 16u;
  let bl = b & 0xFFFFu;
  let bh = b >> 16u;
  let ll = al * bl;
  let lh = al * bh;
  let hl = ah * bl;
  let hh = ah * bh;
  let cross = (ll >> 16u) + (lh & 0xFFFFu) + (hl & 0xFFFFu);
  let low = (cross << 16u) | (ll & 0xFFFFu);
  let high = hh + (lh >> 16u) + (hl >> 16u) + (cross >> 16u);
  return vec2<u32>(low, high);
}

// GLSL: signedWideProduct. The unsigned product of the two's-complement words, corrected: a
// negative a stands for a + 2^32 unsigned, which adds b 2^32 to the product (and likewise for b),
// so subtracting those from the high word gives the signed product modulo 2^64.
fn signedWideProduct(a: i32, b: i32) -> vec2<u32> {
  let p = wideProduct(bitcast<u32>(a), bitcast<u32>(b));
  let high = p.y - select(0u, bitcast<u32>(b), a < 0) - select(0u, bitcast<u32>(a), b < 0);
  return vec2<u32>(p.x, high);
}

// GLSL: isZero64.
fn isZero64(a: vec2<u32>) -> bool {
  return (a.x | a.y) == 0u;
}

// GLSL: equal64.
fn equal64(a: vec2<u32>, b: vec2<u32>) -> bool {
  return a.x == b.x && a.y == b.y;
}

// GLSL: less64 (unsigned).
fn less64(a: vec2<u32>, b: vec2<u32>) -> bool {
  return a.y < b.y || (a.y == b.y && a.x < b.x);
}

// GLSL: shiftRight64. Shifts by 0 <= n <= 63; WGSL, like GLSL, leaves a word shifted by 32 or
// more to the implementation, so those cases take the other word.
fn shiftRight64(a: vec2<u32>, n: u32) -> vec2<u32> {
  if (n == 0u) {
    return a;
  }
  if (n >= 32u) {
    return vec2<u32>(a.y >> (n - 32u), 0u);
  }
  return vec2<u32>((a.x >> n) | (a.y << (32u - n)), a.y >> n);
}

// GLSL: shiftLeft64.
fn shiftLeft64(a: vec2<u32>, n: u32) -> vec2<u32> {
  if (n == 0u) {
    return a;
  }
  if (n >= 32u) {
    return vec2<u32>(0u, a.x << (n - 32u));
  }
  return vec2<u32>(a.x << n, (a.y << n) | (a.x >> (32u - n)));
}

// GLSL: highestBit64. The position of the highest set bit, -1 for zero.
fn highestBit64(a: vec2<u32>) -> i32 {
  if (a.y != 0u) {
    return 32 + findMSB(a.y);
  }
  return findMSB(a.x);
}

// GLSL: shiftRightRoundEven. a >> n rounded to nearest, ties to even, for 1 <= n <= 63.
fn shiftRightRoundEven(a: vec2<u32>, n: u32) -> vec2<u32> {
  let kept = shiftRight64(a, n);
  let dropped = sub64(a, shiftLeft64(kept, n));
  let halfway = shiftLeft64(vec2<u32>(1u, 0u), n - 1u);
  let up = less64(halfway, dropped) || (equal64(dropped, halfway) && (kept.x & 1u) != 0u);
  if (up) {
    return add64(kept, vec2<u32>(1u, 0u));
  }
  return kept;
}

// ---- doubles as bit patterns (zero or normal: see the top of the GLSL file) ----

// GLSL: doubleSign.
fn doubleSign(d: vec2<u32>) -> u32 {
  return d.y & kSignBit;
}

// GLSL: doubleExponent. Biased: the value is significand 2^(exponent - 1075).
fn doubleExponent(d: vec2<u32>) -> u32 {
  return (d.y >> 20u) & 0x7FFu;
}

// GLSL: doubleSignificand. 53 bits, the hidden bit included.
fn doubleSignificand(d: vec2<u32>) -> vec2<u32> {
  return vec2<u32>(d.x, (d.y & kFractionHigh) | kHiddenBit);
}

// GLSL: doubleIsZero.
fn doubleIsZero(d: vec2<u32>) -> bool {
  return d.x == 0u && (d.y & ~kSignBit) == 0u;
}

// GLSL: makeDouble. A double from a 53-bit significand m (2^52 <= m < 2^53, or 2^53 after a
// rounding carry) and its biased exponent.
fn makeDouble(sign: u32, exponentIn: u32, mIn: vec2<u32>) -> vec2<u32> {
  var m = mIn;
  var exponent = exponentIn;
  if (m.y == (kHiddenBit << 1u)) {  // rounded up to 2^53: 2^52 one exponent higher
    m = shiftRight64(m, 1u);
    exponent += 1u;
  }
  return vec2<u32>(m.x, sign | (exponent << 20u) | (m.y & kFractionHigh));
}

// GLSL: doubleFromFloatBits. (double) f for the bits f of a finite float: exact; a subnormal
// float is a normal double.
fn doubleFromFloatBits(f: u32) -> vec2<u32> {
  let sign = f & kSignBit;
  var exponent = (f >> 23u) & 0xFFu;
  var fraction = f & 0x7FFFFFu;
  if (exponent == 0u) {
    if (fraction == 0u) {
      return vec2<u32>(0u, sign);
    }
    let top = findMSB(fraction);  // the value is 1.xxx 2^(top - 149)
    fraction = (fraction << u32(23 - top)) & 0x7FFFFFu;
    exponent = u32(top - 149 + 1023);
  } else {
    exponent = exponent - 127u + 1023u;
  }
  return vec2<u32>(fraction << 29u, sign | (exponent << 20u) | (fraction >> 3u));
}

// GLSL: multiplyByInteger. RN(d k) for an integer |k| < 2^25; the exact product m |k| < 2^78
// takes three words and is shifted right by the s <= 25 bits beyond 53 and rounded.
fn multiplyByInteger(d: vec2<u32>, k: i32) -> vec2<u32> {
  let sign = doubleSign(d) ^ select(0u, kSignBit, k < 0);
  let magnitude = u32(abs(k));
  if (magnitude == 0u || doubleIsZero(d)) {
    return vec2<u32>(0u, sign);
  }
  let m = doubleSignificand(d);
  let low = wideProduct(m.x, magnitude);   // bits 0..63
  let high = wideProduct(m.y, magnitude);  // bits 32..77
  let middle = add64(vec2<u32>(low.y, 0u), high);
  let w0 = low.x;
  let w1 = middle.x;
  let w2 = middle.y;  // the product, w2 < 2^14
  var top: i32;
  if (w2 != 0u) {
    top = 64 + findMSB(w2);
  } else {
    top = highestBit64(vec2<u32>(w0, w1));
  }
  let s = u32(top - 52);
  let exponent = doubleExponent(d) + s;
  if (s == 0u) {
    return makeDouble(sign, exponent, vec2<u32>(w0, w1));
  }
  // Keep one bit more than the significand, and whether anything below it is set: the bits
  // dropped are all in w0 (s <= 25), so a sticky bit stands for them exactly.
  let t = s - 1u;
  var kept = vec2<u32>(w0, w1);
  if (t != 0u) {
    kept = vec2<u32>((w0 >> t) | (w1 << (32u - t)), (w1 >> t) | (w2 << (32u - t)));
  }
  let sticky = select(0u, 1u, (w0 & ((1u << t) - 1u)) != 0u);
  let jammed = add64(shiftLeft64(kept, 1u), vec2<u32>(sticky, 0u));
  return makeDouble(sign, exponent, shiftRightRoundEven(jammed, 2u));
}

// GLSL: addDoubles. RN(a + b), aligned with the leading bit at bit 62 and a sticky bit at bit 0
// (the GLSL file says why that rounds exactly).
fn addDoubles(aIn: vec2<u32>, bIn: vec2<u32>) -> vec2<u32> {
  var a = aIn;
  var b = bIn;
  if (doubleIsZero(b)) {
    if (doubleIsZero(a)) {
      return vec2<u32>(0u, a.y & b.y & kSignBit);  // -0 + -0 = -0, else +0
    }
    return a;
  }
  if (doubleIsZero(a)) {
    return b;
  }
  if (less64(vec2<u32>(a.x, a.y & ~kSignBit), vec2<u32>(b.x, b.y & ~kSignBit))) {
    let swap = a;
    a = b;
    b = swap;
  }
  let exponent = doubleExponent(a);
  let shift = exponent - doubleExponent(b);
  let ma = shiftLeft64(doubleSignificand(a), 10u);
  var mb = shiftLeft64(doubleSignificand(b), 10u);
  if (shift >= 64u) {
    mb = vec2<u32>(1u, 0u);  // b is below every bit kept: sticky alone
  } else if (shift > 0u) {
    let kept = shiftRight64(mb, shift);
    let lost = !equal64(shiftLeft64(kept, shift), mb);
    mb = vec2<u32>(kept.x | select(0u, 1u, lost), kept.y);
  }
  let subtract = doubleSign(a) != doubleSign(b);
  var sum: vec2<u32>;
  if (subtract) {
    sum = sub64(ma, mb);
  } else {
    sum = add64(ma, mb);
  }
  if (isZero64(sum)) {
    return vec2<u32>(0u, 0u);  // exact cancellation: +0 when rounding to nearest
  }
  let top = highestBit64(sum);
  if (top == 63) {  // a carry: one place right, the dropped bit kept as sticky
    sum = vec2<u32>((sum.x >> 1u) | (sum.y << 31u) | (sum.x & 1u), sum.y >> 1u);
  } else if (top < 62) {
    sum = shiftLeft64(sum, u32(62 - top));
  }
  let resultExponent = u32(i32(exponent) + top - 62);
  return makeDouble(doubleSign(a), resultExponent, shiftRightRoundEven(sum, 10u));
}

// ---- the contract ----

// GLSL: depthAt32. The plane at a centre: (z0 + tx) + ty, each product and sum rounded on its
// own (section 5). z0 and the slopes (dzdx, dzdy) are doubles' bits; v0 and the centre are 24.8
// fixed point.
fn depthAt32(z0: vec2<u32>, slopes: vec4<u32>, v0: vec2<i32>, centre: vec2<i32>) -> vec2<u32> {
  let tx = multiplyByInteger(slopes.xy, centre.x - v0.x);
  let ty = multiplyByInteger(slopes.zw, centre.y - v0.y);
  return addDoubles(addDoubles(z0, tx), ty);
}

// GLSL: quantizeDepth32. Clamp and quantise to the 24-bit q: 0 for z <= 0, 2^24 - 1 for
// z >= 1, else roundEven(RN(z 16777215)).
fn quantizeDepth32(z: vec2<u32>) -> u32 {
  if (doubleIsZero(z) || doubleSign(z) != 0u) {
    return 0u;
  }
  if (doubleExponent(z) >= 1023u) {
    return 16777215u;
  }
  let scaled = multiplyByInteger(z, 16777215);
  let fractionBits = 1075u - doubleExponent(scaled);
  if (fractionBits >= 64u) {
    return 0u;
  }
  return shiftRightRoundEven(doubleSignificand(scaled), fractionBits).x;
}

// GLSL: edgeCovers32. Does directed edge a -> b of a counter-clockwise triangle cover the
// centre? E > 0, or E = 0 on an inclusive (left or bottom) edge (section 4).
fn edgeCovers32(a: vec2<i32>, b: vec2<i32>, centre: vec2<i32>) -> bool {
  let dx = b.x - a.x;
  let dy = b.y - a.y;
  let e = sub64(signedWideProduct(dx, centre.y - a.y), signedWideProduct(dy, centre.x - a.x));
  let zero = isZero64(e);
  let positive = bitcast<i32>(e.y) > 0 || (e.y == 0u && !zero);
  let inclusive = dy < 0 || (dy == 0 && dx > 0);
  return positive || (zero && inclusive);
}

// GLSL: triangleCovers32. Coverage of (v0, v1, v2) in submitted order, of the facing given:
// the edges run counter-clockwise, (v0, v1, v2) when front-facing and (v0, v2, v1) when not.
fn triangleCovers32(v0: vec2<i32>, v1: vec2<i32>, v2: vec2<i32>, frontFacing: bool,
                    centre: vec2<i32>) -> bool {
  let p1 = select(v2, v1, frontFacing);
  let p2 = select(v1, v2, frontFacing);
  return edgeCovers32(v0, p1, centre) && edgeCovers32(p1, p2, centre) &&
         edgeCovers32(p2, v0, centre);
}

// GLSL: pixelCentreFixed32. The fixed-point centre of the pixel whose window coordinates are
// fragCoord (i + 0.5, j + 0.5): (256 i + 128, 256 j + 128).
fn pixelCentreFixed32(fragCoord: vec2<f32>) -> vec2<i32> {
  return vec2<i32>(floor(fragCoord)) * 256 + 128;
}
