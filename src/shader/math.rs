//! tessera's own transcendental functions for programs: 2^x, log2 x, sin x, cos x and eˣ,
//! built from IEEE additions, multiplications, divisions, exact conversions and exact fused
//! multiply-adds (`gl::float::fused_multiply_add`) only, so that they give the same bits on
//! every CPU and at every SIMD level (libm's results differ between libraries and versions,
//! and are calls out of line).
//!
//! `exp2` and `log2`, the shading IR's `Exp2` and `Log2` (and so `pow`), are llvmpipe's
//! (`lp_build_exp2`, `lp_build_log2`: its polynomials, evaluated with fused multiply-adds as
//! on the FMA hardware the reference pictures come from), because pictures are compared
//! with Mesa's: fixed-function lighting (specular powers, spotlights) is bit-exact with
//! llvmpipe, and GLSL's exp2, log2 and pow give llvmpipe's values. `exp2_precise` and
//! `log2_precise` are within about an ulp, for the exact accuracy mode.
//!
//! Maximum errors, measured against f64 over dense samples by [`errors`] (which the tests
//! below assert and BENCHMARKS.md tabulates, `examples/math_errors.rs`):
//!
//! | function | range | bound (tested) | measured |
//! |---|---|---|---|
//! | `exp2` (llvmpipe's) | results above 2⁻¹²⁵ | 3.5 ulp | 3.33 ulp |
//! | `log2` (llvmpipe's) | positive normal f32 | 2 ulp (2⁻²² absolute where \|log₂ x\| < 1) | 1.77 |
//! | pow = `exp2(y·log2 x)` | x in [2⁻⁸, 2⁸], y up to ±128, normal results | 256 ulp (grows with \|y·log₂ x\|) | 190 ulp |
//! | `exp2_precise` | every f32 (0 below −126, +∞ from 128) | 2 ulp | 1.15 ulp |
//! | `log2_precise` | every positive normal or denormal f32 | 1 ulp | 0.50 ulp |
//! | `sin`, `cos` | \|x\| ≤ 10⁵ | 2⁻²³ absolute | 3.0·10⁻⁸ absolute |
//! | `exp` (eˣ) | every f32 (0 below −104, +∞ above 89) | 0.5 ulp + 1.3·10⁻¹² relative | correctly rounded on the tested set |
//!
//! GLSL 1.20 asks for no particular precision; these are within a few ulp of what the GPU
//! drivers that pass conformance give. `exp` is fog's exponential (GL_EXP, GL_EXP2), in
//! double precision inside, so the fixed-function fragment program and the span path give
//! the same bits.
pub mod errors;

use crate::gl::float::{floor_f32, fused_multiply_add};

/// 2^x (see the module docs).
#[inline]
pub fn exp2_precise(x: f32) -> f32 {
    if x.is_nan() {
        return x;
    }
    if x >= 128.0 {
        return f32::INFINITY;
    }
    if x < -126.0 {
        // Flushed: GLSL allows denormal results to be zero.
        return 0.0;
    }
    // x = i + f with f in [−0.5, 0.5]; 2^f = e^(f·ln 2), a Taylor polynomial of degree 7
    // (the first omitted term, (0.3466)^8/8!, is 6·10⁻⁹: under a tenth of an ulp).
    let i = floor_f32(x + 0.5);
    let f = x - i; // exact: x and i are within a factor of two or f is tiny
    let t = f * std::f32::consts::LN_2;
    let p = 1.0
        + t * (1.0
            + t * (0.5
                + t * (1.0 / 6.0 + t * (1.0 / 24.0 + t * (1.0 / 120.0 + t * (1.0 / 720.0 + t * (1.0 / 5040.0)))))));
    // i is in [−126, 128]; 2^i in two factors so that 2^128 (p < 1 there) stays finite.
    let i = i as i32;
    let half = i / 2;
    p * pow2(half) * pow2(i - half)
}

/// 2^i for i in [−126, 127], exactly.
#[inline]
fn pow2(i: i32) -> f32 {
    f32::from_bits(((i + 127) as u32) << 23)
}

/// log₂ x (see the module docs): NaN below zero, −∞ at zero, +∞ at +∞.
#[inline]
pub fn log2_precise(x: f32) -> f32 {
    if x.is_nan() || x < 0.0 {
        return f32::NAN;
    }
    if x == 0.0 {
        return f32::NEG_INFINITY;
    }
    if x == f32::INFINITY {
        return x;
    }
    // x = m·2^e with m in [√½, √2).
    let (x, bias) = if x < f32::MIN_POSITIVE { (x * (1u32 << 23) as f32, 23) } else { (x, 0) };
    let bits = x.to_bits();
    let mut e = ((bits >> 23) & 0xff) as i32 - 127 - bias;
    let mut m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    if m > std::f32::consts::SQRT_2 {
        m *= 0.5;
        e += 1;
    }
    // log₂ m = 2·atanh(s)/ln 2 with s = (m − 1)/(m + 1), |s| ≤ 0.1716: odd Taylor terms to
    // s¹¹ (the first omitted, s¹³/13, is 6·10⁻¹¹ of s), in f64 so that the sum with e is
    // rounded once.
    let m = m as f64;
    let s = (m - 1.0) / (m + 1.0);
    let s2 = s * s;
    let atanh = s * (1.0 + s2 * (1.0 / 3.0 + s2 * (1.0 / 5.0 + s2 * (1.0 / 7.0 + s2 * (1.0 / 9.0 + s2 / 11.0)))));
    (e as f64 + atanh * (2.0 / std::f64::consts::LN_2)) as f32
}

/// Coefficients of llvmpipe's polynomial for 2^x on [0, 1) (degree 5).
const EXP2_POLYNOMIAL: [f64; 6] =
    [1.0, 0.693153073200169, 0.24015361704437538, 0.055826318053295666, 0.008989340090494664, 0.001877576675191479];

/// Coefficients of llvmpipe's polynomial P(z) with log2(m) = y · P(y²), y = (m − 1)/(m + 1)
/// (degree 4).
const LOG2_POLYNOMIAL: [f64; 5] =
    [2.8853900934330916, 0.9617915504041842, 0.5774403394387364, 0.4033438582513299, 0.40671805249884624];

/// llvmpipe's polynomial evaluation: odd and even terms in x² separately, with fused
/// multiply-adds (its `fmuladd`, fused on the FMA hardware the reference ran on).
fn polynomial(x: f32, coefficients: &[f64]) -> f32 {
    let x2 = x * x;
    let (mut even, mut odd): (Option<f32>, Option<f32>) = (None, None);
    for (i, &c) in coefficients.iter().enumerate().rev() {
        let c = c as f32;
        let slot = if i % 2 == 0 { &mut even } else { &mut odd };
        *slot = Some(slot.map_or(c, |acc| fused_multiply_add(x2, acc, c)));
    }
    match (odd, even) {
        (Some(odd), Some(even)) => fused_multiply_add(odd, x, even),
        (None, Some(even)) => even,
        _ => 0.0,
    }
}

/// log₂ x as llvmpipe computes it (`lp_build_log2`): x = m·2^e with m in [1, 2) from the
/// bits (denormals read as their bits say, as there), log₂ m = y·P(y²) with
/// y = (m − 1)/(m + 1); NaN below 0, −∞ at 0, +∞ at +∞.
pub fn log2(x: f32) -> f32 {
    if x.is_nan() || x < 0.0 {
        return f32::NAN;
    }
    if x == 0.0 {
        return f32::NEG_INFINITY;
    }
    if x == f32::INFINITY {
        return f32::INFINITY;
    }
    let bits = x.to_bits();
    let exponent = (((bits & 0x7f80_0000) >> 23) as i32 - 127) as f32;
    let mantissa = f32::from_bits((bits & 0x007f_ffff) | 1.0f32.to_bits());
    let y = (mantissa - 1.0) / (mantissa + 1.0);
    fused_multiply_add(y, polynomial(y * y, &LOG2_POLYNOMIAL), exponent)
}

/// 2^x as llvmpipe computes it (`lp_build_exp2`): x clamped to [−126.99999, 128],
/// 2^⌊x⌋ from the exponent bits times a polynomial of the fraction; NaN stays NaN.
pub fn exp2(x: f32) -> f32 {
    if x.is_nan() {
        return x;
    }
    let x = x.clamp(-126.99999, 128.0);
    let floor = floor_f32(x);
    let whole = f32::from_bits(((floor as i32 + 127) as u32) << 23);
    whole * polynomial(x - floor, &EXP2_POLYNOMIAL)
}

/// The lower clamp of [`exp2`]'s argument.
const EXP2_MIN: f32 = -126.99999;

/// [`EXP2_POLYNOMIAL`] and [`LOG2_POLYNOMIAL`] rounded to f32 as [`polynomial`] rounds them,
/// once at compile time (mapped per call, the arrays were a call out of line each).
const EXP2_F32: [f32; 6] = {
    let c = EXP2_POLYNOMIAL;
    [c[0] as f32, c[1] as f32, c[2] as f32, c[3] as f32, c[4] as f32, c[5] as f32]
};
const LOG2_F32: [f32; 5] = {
    let c = LOG2_POLYNOMIAL;
    [c[0] as f32, c[1] as f32, c[2] as f32, c[3] as f32, c[4] as f32]
};

/// 2²³ + 2²²: added to and taken from an f32 of magnitude under 2²², it rounds it to the
/// nearest integer (ties to even), exactly, with no conversion to an integer (those are
/// saturating calls per lane in Rust, not vector instructions).
const ROUNDER: f32 = 12_582_912.0;

/// [`fused_multiply_add`] of the lane polynomials' operands: the exact product plus `c` in
/// double precision, rounded once more to single precision, with none of the checks of the
/// general function (a sum on a midpoint of the single-precision grid, or under the normal
/// range), because on the arguments [`exp2_lanes`] and [`log2_lanes`] give it those checks
/// never change a bit. Measured over every input the two functions' arithmetic sees (every
/// fraction in [0, 1] for exp2's polynomial, every mantissa and exponent for log2's:
/// `lane_polynomials_need_no_fused_checks`, ignored for its 3·10⁹ cases, run with
/// `--ignored`): 138 sums fall on a midpoint, each exact in double precision (so rounding it
/// to single precision is the fused operation's rounding), and one is zero (+0, as fused);
/// none is subnormal. The checks were half of the polynomials' instructions (a 64-bit
/// compare is three instructions at SSE2).
#[inline(always)]
fn fma_plain(a: f32, b: f32, c: f32) -> f32 {
    (a as f64 * b as f64 + c as f64) as f32
}

/// `polynomial(r, EXP2_POLYNOMIAL)`, its terms in its order, with `fma` for its fused
/// multiply-adds.
#[inline(always)]
fn exp2_lane_polynomial(r: f32, fma: impl Fn(f32, f32, f32) -> f32) -> f32 {
    let c = EXP2_F32;
    let r2 = r * r;
    let odd = fma(r2, c[5], c[3]);
    let even = fma(r2, c[4], c[2]);
    let odd = fma(r2, odd, c[1]);
    let even = fma(r2, even, c[0]);
    fma(odd, r, even)
}

/// `polynomial(y², LOG2_POLYNOMIAL)`, its terms in its order, with `fma` for its fused
/// multiply-adds.
#[inline(always)]
fn log2_lane_polynomial(y: f32, fma: impl Fn(f32, f32, f32) -> f32) -> f32 {
    let c = LOG2_F32;
    let z = y * y;
    let z2 = z * z;
    let even = fma(z2, c[4], c[2]);
    let odd = fma(z2, c[3], c[1]);
    let even = fma(z2, even, c[0]);
    fma(odd, z, even)
}

/// [`log2`] of sixteen lanes of f32 bits, the same bits: the common case branch-free over
/// the lanes (so that it vectorises), then the scalar function for the lanes it does not
/// cover (NaN, negative, +∞). Zero (−∞) is a lane of the common case:
/// `pow(max(dot(n, h), 0.0), e)` takes it in every lane facing away from a light, and the
/// scalar calls for those were 2 % of a Phong shader's instructions.
#[inline(always)]
pub fn log2_lanes(x: &[u32; 16]) -> [u32; 16] {
    let mut out = [0u32; 16];
    let mut slow = [false; 16];
    for i in 0..16 {
        let bits = x[i];
        let v = f32::from_bits(bits);
        let zero = v == 0.0;
        let exponent = (((bits & 0x7f80_0000) >> 23) as i32 - 127) as f32;
        let mantissa = f32::from_bits((bits & 0x007f_ffff) | 1.0f32.to_bits());
        let y = (mantissa - 1.0) / (mantissa + 1.0);
        let value = fma_plain(y, log2_lane_polynomial(y, fma_plain), exponent).to_bits();
        // ±0: −∞ as [`log2`] gives it (the arithmetic above is of the bits 0, and ignored).
        out[i] = if zero { f32::NEG_INFINITY.to_bits() } else { value };
        slow[i] = (v < 0.0) | v.is_nan() | (v == f32::INFINITY);
    }
    for i in 0..16 {
        if slow[i] {
            out[i] = log2(f32::from_bits(x[i])).to_bits();
        }
    }
    out
}

/// [`exp2`] of sixteen lanes of f32 bits, the same bits (as [`log2_lanes`]; the scalar
/// function takes NaN).
#[inline(always)]
pub fn exp2_lanes(x: &[u32; 16]) -> [u32; 16] {
    let mut out = [0u32; 16];
    let mut slow = [false; 16];
    for i in 0..16 {
        let v = f32::from_bits(x[i]);
        slow[i] = v.is_nan();
        // v.clamp(EXP2_MIN, 128.0) and floor_f32 of it (|v| < 2²³, not NaN), branch-free.
        let v = if v < EXP2_MIN { EXP2_MIN } else { v };
        let v = if v > 128.0 { 128.0 } else { v };
        // NaN lanes are the scalar function's: any number keeps the arithmetic in range.
        let v = if v.is_nan() { 0.0 } else { v };
        // ⌊v⌋: v rounded to an integer, less one where that rounded up (the value of
        // `v as i32 as f32` so adjusted, with no conversion: |v| ≤ 128).
        let t = (v + ROUNDER) - ROUNDER;
        let t = if t > v { t - 1.0 } else { t };
        let floor = if t == 0.0 { 0.0f32.copysign(v) } else { t };
        // 2^⌊v⌋ from the bits of ⌊v⌋ + 127 + 2²³, whose low 23 bits are ⌊v⌋ + 127 (0 to 255).
        let biased = floor + (8_388_608.0 + 127.0);
        let whole = f32::from_bits((biased.to_bits() & 0x007f_ffff) << 23);
        out[i] = (whole * exp2_lane_polynomial(v - floor, fma_plain)).to_bits();
    }
    for i in 0..16 {
        if slow[i] {
            out[i] = exp2(f32::from_bits(x[i])).to_bits();
        }
    }
    out
}

/// The reduction of x by multiples of π/2, in f64 (exact enough for |x| ≤ 10⁵: π/2 in two
/// parts, the first with 33 significant bits so that k·part is exact for k < 2²⁰): the
/// remainder in [−π/4, π/4] and the quadrant.
#[inline]
fn reduce(x: f32) -> (f64, i64) {
    const PIO2_HI: f64 = 1.570_796_326_734_125_614_166_259_765_625; // 33 bits of π/2
    const PIO2_LO: f64 = 6.077_100_506_506_192e-11; // π/2 − PIO2_HI
    let x = x as f64;
    let k = crate::gl::float::floor_f64(x * std::f64::consts::FRAC_2_PI + 0.5);
    let r = (x - k * PIO2_HI) - k * PIO2_LO;
    (r, k as i64)
}

/// sin r and cos r for r in [−π/4, π/4], Taylor polynomials to r¹¹ and r¹⁰ in f64.
#[inline]
fn sin_cos_reduced(r: f64) -> (f64, f64) {
    let r2 = r * r;
    let s = r * (1.0 - r2 / 6.0 * (1.0 - r2 / 20.0 * (1.0 - r2 / 42.0 * (1.0 - r2 / 72.0 * (1.0 - r2 / 110.0)))));
    let c = 1.0 - r2 / 2.0 * (1.0 - r2 / 12.0 * (1.0 - r2 / 30.0 * (1.0 - r2 / 56.0 * (1.0 - r2 / 90.0))));
    (s, c)
}

/// sin x of radians (see the module docs); NaN for ±∞ and NaN.
#[inline]
pub fn sin(x: f32) -> f32 {
    if !x.is_finite() {
        return f32::NAN;
    }
    let (r, k) = reduce(x);
    let (s, c) = sin_cos_reduced(r);
    (match k & 3 {
        0 => s,
        1 => c,
        2 => -s,
        _ => -c,
    }) as f32
}

/// cos x of radians (see the module docs); NaN for ±∞ and NaN.
#[inline]
pub fn cos(x: f32) -> f32 {
    if !x.is_finite() {
        return f32::NAN;
    }
    let (r, k) = reduce(x);
    let (s, c) = sin_cos_reduced(r);
    (match k & 3 {
        0 => c,
        1 => -s,
        2 => -c,
        _ => s,
    }) as f32
}

/// ln 2 and 1/ln 2 in double precision.
const LN_2: f64 = std::f64::consts::LN_2;
const LOG2_E: f64 = std::f64::consts::LOG2_E;

/// 1/k! for k = 0 ..= 12: the Taylor coefficients of eʳ.
const INVERSE_FACTORIALS: [f64; 13] = [
    1.0,
    1.0,
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5040.0,
    1.0 / 40320.0,
    1.0 / 362880.0,
    1.0 / 3628800.0,
    1.0 / 39916800.0,
    1.0 / 479001600.0,
];

/// eˣ in single precision, from IEEE operations only: x = n·ln 2 + r with n = trunc(x/ln 2)
/// (so |r| < ln 2 · (1 + 2⁻⁵⁰)), eʳ by its Taylor polynomial of degree 12 in Horner form,
/// and the power 2ⁿ put into the exponent bits, all in double precision, then one rounding
/// to single precision.
///
/// Error: the polynomial's truncation error is below (ln 2)¹³/13! < 1.2·10⁻¹², and the
/// double-precision reduction and evaluation add a few 10⁻¹⁶, so the double-precision value
/// is within 1.3·10⁻¹² (relative) of eˣ, and the result is eˣ correctly rounded to single
/// precision except where eˣ lies within that distance of a midpoint between two floats:
/// at most 0.5 ulp + 1.3·10⁻¹² relative (`exp_is_within_half_an_ulp` checks it against f64
/// `exp` over [−104, 89]). Below −104 the result is 0 (eˣ < 2⁻¹⁵⁰, which rounds to 0
/// anyway), above 89 it is +∞ (eˣ > f32::MAX), and NaN stays NaN.
#[inline]
pub fn exp(x: f32) -> f32 {
    if x.is_nan() {
        return x;
    }
    if x < -104.0 {
        return 0.0;
    }
    if x > 89.0 {
        return f32::INFINITY;
    }
    let x = x as f64;
    let n = (x * LOG2_E) as i32; // |n| ≤ 151: exact truncation.
    let r = x - n as f64 * LN_2;
    let mut e = INVERSE_FACTORIALS[12];
    for &c in INVERSE_FACTORIALS[..12].iter().rev() {
        e = e * r + c;
    }
    // 2ⁿ is a normal double for |n| ≤ 151: its exponent field alone.
    let scale = f64::from_bits(((1023 + n as i64) as u64) << 52);
    (e * scale) as f32
}

#[cfg(test)]
mod tests {
    use super::errors::*;
    use super::*;

    /// The lane forms against the scalar functions over every 1021st bit pattern and every
    /// 2⁻¹⁶ step of [−130, 130] (where exp2's floor, clamp and 2^⌊x⌋ change): the same bits.
    #[test]
    fn lane_forms_give_the_scalar_bits() {
        let sparse = (0..=u32::MAX / 1021).map(|k| k * 1021);
        let dense = (-130 * 65536..=130 * 65536).map(|k| (k as f32 / 65536.0).to_bits());
        let edges =
            [f32::MIN_POSITIVE, -126.99999, -127.0, 128.0, -0.0, 0.0, f32::INFINITY, f32::NEG_INFINITY, f32::NAN];
        let all: Vec<u32> = sparse.chain(dense).chain(edges.map(f32::to_bits)).collect();
        for chunk in all.chunks(16) {
            let mut x = [0u32; 16];
            x[..chunk.len()].copy_from_slice(chunk);
            let want_exp2 = x.map(|b| exp2(f32::from_bits(b)).to_bits());
            let want_log2 = x.map(|b| log2(f32::from_bits(b)).to_bits());
            assert_eq!(exp2_lanes(&x), want_exp2, "exp2 of {:?}", x.map(f32::from_bits));
            assert_eq!(log2_lanes(&x), want_log2, "log2 of {:?}", x.map(f32::from_bits));
        }
    }

    /// The inputs of [`exp2_lanes`] whose polynomial has a double-precision sum on a
    /// midpoint of the single-precision grid (found by `lane_polynomials_need_no_fused_checks`;
    /// the fraction 1 comes from tiny negative inputs).
    const EXP2_MIDPOINT_INPUTS: [u32; 10] = [
        0x3e200000, 0x3e438000, 0x3e780000, 0x3e825000, 0x3ea19000, 0x3ed7bf80, 0x3f2c0b60, 0x3f380000, 0x3f7e26c4,
        0xb2800000, // −2⁻²⁶: its fraction v − ⌊v⌋ rounds to 1
    ];

    /// The same for [`log2_lanes`] (its last multiply-add, the exponent's sum).
    const LOG2_MIDPOINT_INPUTS: [u32; 127] = [
        0x3f08e46b, 0x3f111111, 0x3f945ae8, 0x3e981181, 0x40181181, 0x3f1bb4a4, 0x3da01201, 0x3e201201, 0x40a01201,
        0x41201201, 0x3f21fb78, 0x3ba49249, 0x3c249249, 0x3ca49249, 0x3d249249, 0x41a49249, 0x42249249, 0x42a49249,
        0x43249249, 0x3f2be0c2, 0x3f34daca, 0x3f3a2e19, 0x3fbb13b1, 0x3f3d0f01, 0x3fcc0ed4, 0x3f5122b7, 0x3f5316b1,
        0x3ed55555, 0x40555555, 0x3f57bd33, 0x3fd9e652, 0x3fd9e653, 0x3de15a74, 0x3e615a74, 0x40e15a74, 0x41615a74,
        0x3f61b5fe, 0x3f61b5ff, 0x3f642c85, 0x3f642c86, 0x3f68f4a1, 0x3f68f4a2, 0x3f6b05fc, 0x3f6b7538, 0x3f6bd613,
        0x3f6c16c1, 0x3f713787, 0x3f7158d1, 0x3f7158d2, 0x3f724288, 0x3ff2e5fa, 0x3ff2e5fb, 0x3f73ada5, 0x3f754223,
        0x3f756cac, 0x3f7602a6, 0x3f7602a7, 0x3ef706f5, 0x407706f5, 0x3f7854e4, 0x3f7a57a8, 0x3f7aaaba, 0x3f7aaabb,
        0x3f7b1840, 0x3f7beb39, 0x3f7cbab1, 0x3f7db5c2, 0x3f7db5c3, 0x3f7e179c, 0x3f7e2255, 0x3f7e4881, 0x3f7edb21,
        0x3f7edb22, 0x3f7edb23, 0x3f7ee75d, 0x3f7ee75e, 0x3f7eefc1, 0x3f7eefc2, 0x3f7f7631, 0x3f7f7632, 0x3f7f79d7,
        0x3f7f860b, 0x3f7f9e6c, 0x3f7fb6d0, 0x3f7fc708, 0x3f7fe202, 0x3f7fe203, 0x3f7feb01, 0x3f7ff1c0, 0x3f7ff520,
        0x3f7ff6e2, 0x3f7ff6e3, 0x3f7ff7a8, 0x3f7ffbe0, 0x3f7ffcf7, 0x3f7ffe83, 0x3f7ffef8, 0x3f7fff75, 0x3f7fff76,
        0x3f7fff77, 0x3f7fffa3, 0x3f7fffac, 0x3f7fffbd, 0x3f7fffbe, 0x3f7fffbf, 0x3f7fffd4, 0x3f7fffdd, 0x3f7fffde,
        0x3f7fffe1, 0x3f7fffe2, 0x3f7fffe3, 0x3f7ffff8, 0x3ffffff9, 0x3ffffffa, 0x3efffffb, 0x407ffffb, 0x3ffffffc,
        0x3bfffffd, 0x3c7ffffd, 0x3cfffffd, 0x3d7ffffd, 0x41fffffd, 0x427ffffd, 0x42fffffd, 0x437ffffd, 0x3ffffffe,
        0x3fffffff,
    ];

    /// The inputs whose lane polynomials have a double-precision sum on a midpoint of the
    /// single-precision grid (the case where rounding twice can differ from rounding once):
    /// [`exp2_lanes`] and [`log2_lanes`] give the scalar functions' bits there too.
    #[test]
    fn lane_forms_agree_where_sums_fall_on_midpoints() {
        for inputs in [&EXP2_MIDPOINT_INPUTS[..], &LOG2_MIDPOINT_INPUTS[..]] {
            for chunk in inputs.chunks(16) {
                let mut x = [1.0f32.to_bits(); 16];
                x[..chunk.len()].copy_from_slice(chunk);
                assert_eq!(exp2_lanes(&x), x.map(|b| exp2(f32::from_bits(b)).to_bits()));
                assert_eq!(log2_lanes(&x), x.map(|b| log2(f32::from_bits(b)).to_bits()));
            }
        }
    }

    /// [`fma_plain`]'s claim, over every argument the lane polynomials see: every fraction
    /// in [0, 1] for exp2's, every mantissa for log2's and with it every exponent for its last
    /// multiply-add, the plain double-precision sums give the fused results' bits; and the
    /// midpoint cases are the ones listed above. About 3·10⁹ cases (a minute at `--release`):
    /// `cargo test --release --lib lane_polynomials_need_no_fused_checks -- --ignored`.
    #[test]
    #[ignore]
    fn lane_polynomials_need_no_fused_checks() {
        let on_midpoint =
            |a: f32, b: f32, c: f32| (a as f64 * b as f64 + c as f64).to_bits() & 0x1fff_ffff == 0x1000_0000;
        let mut exp2_midpoints = vec![];
        for bits in 0..=1.0f32.to_bits() {
            let r = f32::from_bits(bits);
            let plain = exp2_lane_polynomial(r, fma_plain);
            assert_eq!(plain.to_bits(), exp2_lane_polynomial(r, fused_multiply_add).to_bits(), "exp2 at {r:e}");
            let hit = std::cell::Cell::new(false);
            exp2_lane_polynomial(r, |a, b, c| {
                hit.set(hit.get() | on_midpoint(a, b, c));
                fma_plain(a, b, c)
            });
            if hit.get() {
                exp2_midpoints.push(bits);
            }
        }
        let mut log2_midpoints = vec![];
        for mantissa_bits in 0..1u32 << 23 {
            let mantissa = f32::from_bits(mantissa_bits | 1.0f32.to_bits());
            let y = (mantissa - 1.0) / (mantissa + 1.0);
            let p = log2_lane_polynomial(y, fma_plain);
            assert_eq!(p.to_bits(), log2_lane_polynomial(y, fused_multiply_add).to_bits(), "log2 at {mantissa:e}");
            let hit = std::cell::Cell::new(false);
            log2_lane_polynomial(y, |a, b, c| {
                hit.set(hit.get() | on_midpoint(a, b, c));
                fma_plain(a, b, c)
            });
            assert!(!hit.get(), "log2's polynomial at {mantissa:e} is not in the list");
            for exponent in -127..=127 {
                let e = exponent as f32;
                assert_eq!(
                    fma_plain(y, p, e).to_bits(),
                    fused_multiply_add(y, p, e).to_bits(),
                    "log2 at {mantissa:e}·2^{e}"
                );
                if on_midpoint(y, p, e) {
                    log2_midpoints.push((((exponent + 127) as u32) << 23) | mantissa_bits);
                }
            }
        }
        let mut listed = EXP2_MIDPOINT_INPUTS.to_vec();
        *listed.last_mut().unwrap() = 1.0f32.to_bits();
        assert_eq!(exp2_midpoints, listed);
        assert_eq!(log2_midpoints, LOG2_MIDPOINT_INPUTS);
    }

    /// llvmpipe's approximations: their measured error (the bounds a little above it), the
    /// edges, and the points where they are exact.
    #[test]
    fn mesa_exp2_and_log2_errors() {
        let worst = exp2_worst();
        eprintln!("llvmpipe exp2: worst {worst:.3} ulp");
        assert!(worst <= 3.5, "exp2: {worst} ulp");
        assert_eq!(exp2(0.0), 1.0);
        assert_eq!(exp2(3.0), 8.0);
        assert!(exp2(f32::NAN).is_nan());
        let worst = log2_worst();
        eprintln!("llvmpipe log2: worst {worst:.3} ulp (absolute 2^-23 below 1 in magnitude)");
        assert!(worst <= 2.0, "log2: {worst}");
        assert_eq!(log2(1.0), 0.0);
        assert_eq!(log2(0.0), f32::NEG_INFINITY);
        assert!(log2(-1.0).is_nan() && log2(f32::NAN).is_nan());
        assert_eq!(log2(f32::INFINITY), f32::INFINITY);
    }

    /// pow through llvmpipe's exp2 and log2: the error a lighting exponent of up to 128 can
    /// reach (|y·log₂ x| up to 1024 magnifies log2's absolute error), and exact powers of two.
    #[test]
    fn pow_error_stays_within_its_bound() {
        let worst = pow_worst();
        eprintln!("pow: worst {worst:.3} ulp");
        assert!(worst <= POW_ULPS, "pow: {worst} ulp");
        assert_eq!(exp2(2.0 * log2(8.0)), 64.0);
    }

    #[test]
    fn exp2_precise_is_within_two_ulp() {
        let worst = exp2_precise_worst();
        eprintln!("exp2: worst {worst:.3} ulp");
        assert!(worst <= 2.0, "exp2: {worst} ulp");
        for x in samples(1e-8, 127.9, 997).map(|x| -x).filter(|&x| (x as f64).exp2() < f32::MIN_POSITIVE as f64) {
            assert_eq!(exp2_precise(x), 0.0, "2^{x} is flushed to zero");
        }
        assert_eq!(exp2_precise(0.0), 1.0);
        for i in -126..128 {
            assert_eq!(exp2_precise(i as f32), (i as f64).exp2() as f32, "2^{i} is exact");
        }
        assert_eq!(exp2_precise(128.0), f32::INFINITY);
        assert_eq!(exp2_precise(-200.0), 0.0);
        assert!(exp2_precise(f32::NAN).is_nan());
        assert_eq!(exp2_precise(f32::NEG_INFINITY), 0.0);
    }

    #[test]
    fn log2_precise_is_within_one_ulp() {
        let worst = log2_precise_worst();
        eprintln!("log2: worst {worst:.3} ulp");
        assert!(worst <= 1.0, "log2: {worst} ulp");
        for i in -149..128 {
            assert_eq!(log2_precise((i as f64).exp2() as f32), i as f32, "log2 of 2^{i} is exact");
        }
        assert_eq!(log2_precise(0.0), f32::NEG_INFINITY);
        assert!(log2_precise(-1.0).is_nan() && log2_precise(f32::NAN).is_nan());
        assert_eq!(log2_precise(f32::INFINITY), f32::INFINITY);
    }

    #[test]
    fn sin_and_cos_are_within_an_ulp_of_one_absolute() {
        let worst = sin_cos_worst();
        eprintln!("sin/cos: worst {worst:e} absolute");
        assert!(worst <= 2f64.powi(-23), "sin/cos: {worst:e} absolute");
        assert_eq!(sin(0.0), 0.0);
        assert_eq!(cos(0.0), 1.0);
        assert!(sin(f32::INFINITY).is_nan() && cos(f32::NAN).is_nan());
    }

    /// The documented bound: within 0.5 ulp (+ 1.3·10⁻¹² relative) of eˣ computed in double
    /// precision over every input the fog factors can use (and beyond), correctly rounded on
    /// those and on the ends of the range.
    #[test]
    fn exp_is_within_half_an_ulp() {
        let worst = exp_worst();
        assert!(worst <= 0.5 + 1e-6, "worst error {worst} ulp");
        for x in [0.0, -0.0, -1e-30, 1e-30, -103.97, -87.5, -87.3, 88.7, -1.0, -0.5, -f32::MIN_POSITIVE] {
            assert_eq!(exp(x), (x as f64).exp() as f32, "exp({x:e}) is e^x rounded to nearest");
        }
        assert!(exp(f32::NAN).is_nan());
        assert_eq!((exp(-105.0), exp(90.0), exp(0.0)), (0.0, f32::INFINITY, 1.0));
    }

    /// The table BENCHMARKS.md prints lists every function with a bound its measurement meets.
    #[test]
    fn the_error_table_lists_every_function_within_its_bound() {
        let rows = measure_all();
        assert_eq!(rows.len(), 7);
        for r in &rows {
            assert!(r.worst <= r.bound, "{}: {} above {}", r.function, r.worst, r.bound);
        }
        let table = markdown_table(&rows);
        assert_eq!(table.lines().count(), 2 + rows.len());
        assert!(table.contains("| pow = exp2(y·log2 x) |"));
    }
}
