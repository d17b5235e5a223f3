//! Exact floating-point operations without libm: floor, ceil and rounding to integers, and
//! a fused multiply-add, each built from IEEE additions, multiplications and conversions
//! so that it gives the same bits on every CPU, at every SIMD level, with no call out of
//! line.
//!
//! Why not `f32::floor`, `f64::round` or `f32::mul_add`: on baseline x86-64 (no SSE4.1
//! `roundss`, no FMA) the first two are calls into libm and the last a software `fmaf`
//! routine of a few hundred instructions, and with FMA hardware `mul_add` would be one
//! instruction on some machines and the routine on others. The formulations here rely only
//! on truncating conversion (`as`), which is one instruction everywhere, and on the fact
//! that `x − trunc(x)` is exact for every float.

/// `floor(v)` as an `i32`, with `v` first clamped to ±2³⁰ (NaN gives 0): the pixel bound
/// of a window-space coordinate, far beyond any framebuffer.
#[inline]
pub fn floor_to_i32(v: f32) -> i32 {
    let v = v.clamp(-(1 << 30) as f32, (1 << 30) as f32);
    let t = v as i32;
    // |v| ≥ 2²³ is an integer already (t == v); below, t converts back exactly.
    t - ((t as f32) > v) as i32
}

/// `ceil(v)` as an `i32`, with `v` first clamped to ±2³⁰ (NaN gives 0).
#[inline]
pub fn ceil_to_i32(v: f32) -> i32 {
    let v = v.clamp(-(1 << 30) as f32, (1 << 30) as f32);
    let t = v as i32;
    t + ((t as f32) < v) as i32
}

/// `floor(v)` as an `f32`, exactly `f32::floor` for every input (NaN and ±∞ unchanged;
/// −0 stays −0, a negative fraction above −1 gives −1).
#[inline]
pub fn floor_f32(v: f32) -> f32 {
    // From 2²³ on every float is an integer (and NaN, ±∞ are returned as they are).
    if v.is_nan() || v.abs() >= (1 << 23) as f32 {
        return v;
    }
    let t = v as i32 as f32;
    let f = if t > v { t - 1.0 } else { t };
    // Keep the sign of zero as floor does (−0.0 → −0.0; (−0.5).floor() is −1, not zero).
    if f == 0.0 {
        0.0f32.copysign(v)
    } else {
        f
    }
}

/// `floor(v)` as an `f64`, exactly `f64::floor` for every input.
#[inline]
pub fn floor_f64(v: f64) -> f64 {
    if v.is_nan() || v.abs() >= (1u64 << 52) as f64 {
        return v;
    }
    let t = v as i64 as f64;
    let f = if t > v { t - 1.0 } else { t };
    if f == 0.0 {
        0.0f64.copysign(v)
    } else {
        f
    }
}

/// `ceil(v)` clamped to [−2³⁰, 2³⁰ − ½] and converted to `i32` (NaN gives 0): exactly
/// `v.ceil().clamp(i32::MIN as f64 / 2.0, i32::MAX as f64 / 2.0) as i32`.
#[inline]
pub fn ceil_f64_to_i32(v: f64) -> i32 {
    (-floor_f64(-v)).clamp(i32::MIN as f64 / 2.0, i32::MAX as f64 / 2.0) as i32
}

/// `v.round()` (half away from zero) as an `i64`, for |v| < 2⁶²: the truncation is exact,
/// and so is the fraction `v − trunc(v)`, which then decides the rounding.
#[inline]
pub fn round_half_away_f64(v: f64) -> i64 {
    let t = v as i64;
    let fraction = v - t as f64;
    t + (fraction >= 0.5) as i64 - (fraction <= -0.5) as i64
}

/// `a·b + c` rounded once to single precision: exactly `f32::mul_add` (IEEE fusedMultiplyAdd)
/// for every input, without an FMA instruction or libm's `fmaf`.
///
/// The product of two floats is exact in double precision (24 + 24 significant bits ≤ 53).
/// The sum `p + c` is not, and rounding it to f64 and then to f32 may round twice the wrong
/// way — but only when the f64 sum lands exactly on a midpoint between two floats: every such
/// midpoint is itself a double, so an exact sum on one side of it cannot round in f64 to the
/// other side. Where the f64 sum is not a midpoint of the single-precision grid (the common
/// case, a bit test: for results of normal magnitude the 29 bits below a float's last bit are
/// not 1000…0) its conversion is the correctly rounded result. Otherwise, and for results
/// of subnormal magnitude (whose grid is coarser), the sum is rounded to f64 *to odd*: its exact error is recovered by Knuth's TwoSum,
/// and when it is non-zero and the rounded sum's last significand bit is even, the sum is
/// moved one ulp towards the error, which makes that bit odd. A value rounded to odd at
/// precision p and then to nearest at precision q ≤ p − 2 is the value rounded to nearest
/// at q directly (Boldo and Melquiond, "When double rounding is odd", 2005), and 53 ≥ 24 + 2.
/// The f64 sum can neither overflow nor lose bits to subnormals for f32 inputs (|p| < 2²⁵⁶,
/// and every non-zero p or c is above 2⁻³⁰⁰); infinities and NaN propagate as in the fused
/// operation (an infinite or NaN sum is returned as it is), and signed zeros follow the same
/// IEEE rules as the fused operation's.
#[inline(always)]
pub fn fused_multiply_add(a: f32, b: f32, c: f32) -> f32 {
    let p = a as f64 * b as f64;
    let s = p + c as f64;
    // Not a midpoint of the single-precision grid, and |s| ≥ 2⁻¹²⁶ (or ∞; NaN fails it).
    if s.to_bits() & 0x1fff_ffff != 0x1000_0000 && s.abs() >= f32::MIN_POSITIVE as f64 {
        return s as f32;
    }
    rounded_to_odd_sum(p, c as f64, s)
}

/// The rare case of [`fused_multiply_add`]: `p + c` (whose f64 rounding is `s`) rounded to
/// odd in double precision, then to nearest in single precision. Out of line, so that the
/// common case stays a handful of instructions wherever it is inlined.
#[cold]
#[inline(never)]
fn rounded_to_odd_sum(p: f64, c: f64, s: f64) -> f32 {
    if !s.is_finite() {
        return s as f32;
    }
    // TwoSum: p + c == s + error exactly.
    let b_virtual = s - p;
    let error = (p - (s - b_virtual)) + (c - b_virtual);
    let bits = s.to_bits();
    let odd = if error != 0.0 && bits & 1 == 0 {
        // s ≠ 0 here (s == 0 means p == −c exactly). Growing the magnitude is bits + 1.
        f64::from_bits(if (error > 0.0) == (s > 0.0) { bits + 1 } else { bits - 1 })
    } else {
        s
    };
    odd as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tiny deterministic generator (xorshift).
    fn next(seed: &mut u64) -> u64 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        *seed
    }

    /// Floats of every magnitude and sign, and some special values.
    fn floats(seed: &mut u64, n: usize) -> Vec<f32> {
        let mut v: Vec<f32> = (0..n).map(|_| f32::from_bits(next(seed) as u32)).filter(|f| !f.is_nan()).collect();
        v.extend([0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 1e-40, -1e-40, f32::INFINITY, f32::NEG_INFINITY]);
        v.extend([8388607.5, -8388607.5, 8388608.0, 0.49999997, -0.49999997, 1.0 - f32::EPSILON / 2.0]);
        v
    }

    #[test]
    fn floor_and_ceil_match_libm() {
        let mut seed = 0x2545f4914f6cdd1d;
        for v in floats(&mut seed, 20000) {
            assert_eq!(floor_f32(v).to_bits(), v.floor().to_bits(), "floor({v:e})");
            let clamp = |f: f32| f.clamp(-(1 << 30) as f32, (1 << 30) as f32) as i32;
            assert_eq!(floor_to_i32(v), clamp(v.floor()), "floor({v:e})");
            assert_eq!(ceil_to_i32(v), clamp(v.ceil()), "ceil({v:e})");
            let w = v as f64 * 1.000000001;
            assert_eq!(floor_f64(w).to_bits(), w.floor().to_bits(), "floor({w:e})");
            let clamp64 = |f: f64| f.clamp(i32::MIN as f64 / 2.0, i32::MAX as f64 / 2.0) as i32;
            assert_eq!(ceil_f64_to_i32(w), clamp64(w.ceil()), "ceil({w:e})");
        }
        assert!(floor_f32(f32::NAN).is_nan());
        assert_eq!((floor_to_i32(f32::NAN), ceil_to_i32(f32::NAN)), (0, 0));
        // Small numbers, with fractions, where most coordinates are.
        for i in -5000..5000 {
            let v = i as f32 / 64.0 + 0.001;
            assert_eq!(floor_f32(v), v.floor());
            assert_eq!((floor_to_i32(v), ceil_to_i32(v)), (v.floor() as i32, v.ceil() as i32));
        }
    }

    #[test]
    fn round_half_away_matches_libm() {
        let mut seed = 0x9e3779b97f4a7c15;
        for _ in 0..20000 {
            // Window coordinates times 256, as triangle setup snaps them (|v| ≤ 2³⁰).
            let v = (next(&mut seed) as i64 >> 33) as f64 / (1u64 << (next(&mut seed) % 24)) as f64;
            assert_eq!(round_half_away_f64(v), v.round() as i64, "{v}");
        }
        for v in [0.5, -0.5, 1.5, -1.5, 2.5, 0.49999999999999994, -0.49999999999999994, 0.0, -0.0, 1e9 + 0.5] {
            assert_eq!(round_half_away_f64(v), v.round() as i64, "{v}");
        }
    }

    #[test]
    fn fused_multiply_add_is_exactly_mul_add() {
        let mut seed = 0x853c49e6748fea9b;
        let check = |a: f32, b: f32, c: f32| {
            let (got, want) = (fused_multiply_add(a, b, c), a.mul_add(b, c));
            assert!(got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()), "fma({a:e}, {b:e}, {c:e})");
        };
        // Random bits: every magnitude, specials included.
        for _ in 0..200000 {
            let [a, b, c] = [0; 3].map(|_| f32::from_bits(next(&mut seed) as u32));
            check(a, b, c);
        }
        // Operands of close magnitudes, where the product and the addend cancel and where
        // double rounding would go wrong.
        for _ in 0..200000 {
            let a = f32::from_bits(0x3f00_0000 | (next(&mut seed) as u32 & 0x00ff_ffff));
            let b = f32::from_bits(0x3f00_0000 | (next(&mut seed) as u32 & 0x00ff_ffff));
            let exponent = 0x3e00_0000 + ((next(&mut seed) as u32 % 4) << 23);
            let sign = (next(&mut seed) as u32 & 1) << 31;
            let c = f32::from_bits(sign | exponent | (next(&mut seed) as u32 & 0x007f_ffff));
            check(a, b, c);
            // c just off the product's f32 midpoints.
            let p = a * b;
            let half_ulp = f32::from_bits(p.to_bits() & 0x7f80_0000) * f32::EPSILON / 2.0;
            check(a, b, half_ulp);
            check(a, b, -half_ulp);
            check(a, b, half_ulp * 1.0000001);
        }
        // Line planes: pixel coordinates times gradients, plus an anchor value.
        for _ in 0..100000 {
            let px = (next(&mut seed) % 4096) as f32;
            let d = f32::from_bits(next(&mut seed) as u32 & 0x3fff_ffff) - 1.0;
            let a0 = (next(&mut seed) % 1_000_000) as f32 / 997.0;
            check(d, px, a0);
            check(-d, px, a0);
        }
        for (a, b, c) in [(0.0, 1.0, -0.0), (-0.0, 1.0, 0.0), (-0.0, 1.0, -0.0), (f32::INFINITY, 0.0, 1.0)] {
            check(a, b, c);
        }
    }
}
