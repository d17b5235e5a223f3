//! Fog: the fog factor f of the three GL modes and the blend `f·Cf + (1 − f)·Cfog` on RGB,
//! in single precision, over a span ([`apply_fog`]) or a block's 16 lanes ([`fog_lanes`],
//! the same operations, so the same bits).
//!
//! The fog coordinate `c` is whatever the draw's coordinate source gives (the eye distance
//! `|z_eye|` or the interpolated fog coordinate, not made absolute). LINEAR with
//! `start == end`, a division by zero the spec leaves undefined, follows Mesa 22 (llvmpipe
//! and softpipe agree): f = clamp(c − end, 0, 1), measured with start = end = 0.5, 0.3, 0,
//! −0.2 and 2 for both coordinate sources (e.g. end 0.5: c = 0.6 → f = 0.1, c = 1.0 → 0.5,
//! c ≤ 0.5 → full fog color).
//!
//! GL_EXP and GL_EXP2 use [`exp`], tessera's own exponential (not libm's `expf`, an
//! out-of-line call whose last bit depends on the C library): a fixed range reduction and
//! polynomial in double precision, so every machine and SIMD level gives the same bits.

use super::block::{lanes, F32s};

/// The fog equation (glFog GL_FOG_MODE).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FogMode {
    Linear,
    Exp,
    Exp2,
}

/// The fog parameters of a draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    pub mode: FogMode,
    pub start: f32,
    pub end: f32,
    pub density: f32,
    /// The fog color, clamped to [0, 1] by the context.
    pub color: [f32; 4],
}

#[inline(always)]
fn clamp01(x: f32) -> f32 {
    if x > 0.0 {
        x.min(1.0)
    } else {
        0.0
    }
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

/// The fog factor for coordinate `c`, clamped to [0, 1].
#[inline]
pub fn fog_factor(fog: &Fog, c: f32) -> f32 {
    match fog.mode {
        FogMode::Linear if fog.start == fog.end => clamp01(c - fog.end),
        FogMode::Linear => clamp01((fog.end - c) / (fog.end - fog.start)),
        FogMode::Exp => clamp01(exp(-fog.density * c)),
        FogMode::Exp2 => {
            let dc = fog.density * c;
            clamp01(exp(-(dc * dc)))
        }
    }
}

/// Fogs the RGB of `colors[i]` for every bit of `live` with coordinate `coords[i]`; alpha is
/// unchanged. The mode is matched once per span.
pub fn apply_fog(fog: &Fog, coords: &[f32], colors: &mut [[f32; 4]], live: u64) {
    let mut factors = [0f32; super::MAX_SPAN];
    let n = coords.len().min(colors.len()).min(super::MAX_SPAN);
    match fog.mode {
        FogMode::Linear if fog.start == fog.end => {
            factors[..n].iter_mut().zip(coords).for_each(|(f, &c)| *f = clamp01(c - fog.end))
        }
        // Divides like fog_factor rather than multiplying by the reciprocal, for identical results.
        FogMode::Linear => {
            factors[..n].iter_mut().zip(coords).for_each(|(f, &c)| *f = clamp01((fog.end - c) / (fog.end - fog.start)))
        }
        _ => factors[..n].iter_mut().zip(coords).for_each(|(f, &c)| *f = fog_factor(fog, c)),
    }
    for (i, (col, &f)) in colors[..n].iter_mut().zip(&factors[..n]).enumerate() {
        if live & (1 << i) != 0 {
            for (x, &fog_c) in col[..3].iter_mut().zip(&fog.color[..3]) {
                *x = f * *x + (1.0 - f) * fog_c;
            }
        }
    }
}

/// [`apply_fog`] on the 16 lanes of a block: the fog factors of `coords` and the blend of
/// the RGB lanes, every lane (the caller keeps only the live ones). The same operations in
/// the same order as the span version, so the same bits; LINEAR is branch-free so that it
/// vectorises, EXP and EXP2 take [`fog_factor`] lane by lane.
#[inline(always)]
pub fn fog_lanes(fog: &Fog, coords: &F32s, colors: &mut [F32s; 4]) {
    let factors: F32s = match fog.mode {
        FogMode::Linear if fog.start == fog.end => lanes(|i| clamp01_lane(coords[i] - fog.end)),
        FogMode::Linear => {
            let span = fog.end - fog.start;
            lanes(|i| clamp01_lane((fog.end - coords[i]) / span))
        }
        _ => lanes(|i| fog_factor(fog, coords[i])),
    };
    for (channel, &fog_c) in colors[..3].iter_mut().zip(&fog.color[..3]) {
        *channel = lanes(|i| factors[i] * channel[i] + (1.0 - factors[i]) * fog_c);
    }
}

/// [`clamp01`] as two selects (NaN and −0 give 0, as there), which vectorise.
#[inline(always)]
pub fn clamp01_lane(x: f32) -> f32 {
    let x = if x > 0.0 { x } else { 0.0 };
    if x < 1.0 {
        x
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fog(mode: FogMode, start: f32, end: f32, density: f32) -> Fog {
        Fog { mode, start, end, density, color: [0.0, 0.0, 1.0, 1.0] }
    }

    #[test]
    fn linear_factor_and_clamping() {
        let f = fog(FogMode::Linear, 0.2, 0.8, 1.0);
        assert_eq!(fog_factor(&f, 0.5), 0.5);
        assert_eq!(fog_factor(&f, 0.2), 1.0);
        assert_eq!(fog_factor(&f, 0.0), 1.0);
        assert_eq!(fog_factor(&f, 0.8), 0.0);
        assert_eq!(fog_factor(&f, 5.0), 0.0);
        // Reversed start and end: (0.2 − 0.5)/(0.2 − 0.8) = 0.5, and c = 0 → 0 (clamped).
        let r = fog(FogMode::Linear, 0.8, 0.2, 1.0);
        assert_eq!(fog_factor(&r, 0.5), 0.5);
        assert_eq!(fog_factor(&r, 0.0), 0.0);
    }

    #[test]
    fn linear_with_start_equal_to_end_follows_mesa() {
        let f = fog(FogMode::Linear, 0.5, 0.5, 1.0);
        assert_eq!(fog_factor(&f, 1.0), 0.5);
        assert_eq!(fog_factor(&f, 0.25), 0.0);
        assert_eq!(fog_factor(&f, 0.5), 0.0);
        assert_eq!(fog_factor(&f, 3.0), 1.0);
        let z = fog(FogMode::Linear, -0.2, -0.2, 1.0);
        assert_eq!(fog_factor(&z, 0.3), 0.5);
    }

    #[test]
    fn exp_and_exp2_factors() {
        let e = fog(FogMode::Exp, 0.0, 1.0, 1.7);
        assert_eq!(fog_factor(&e, 0.0), 1.0);
        assert_eq!(fog_factor(&e, 0.4), exp(-0.68));
        assert_eq!(fog_factor(&e, 0.4), (-0.68f64).exp() as f32);
        // Mesa writes red 129 for this fragment: 0.50662 · 255 = 129.19.
        assert_eq!(crate::framebuffer::format::float_to_unorm(fog_factor(&e, 0.4), 8), 129);
        assert_eq!(fog_factor(&e, -1.0), 1.0, "clamped");
        let e2 = fog(FogMode::Exp2, 0.0, 1.0, 1.7);
        let dc = 1.7f32 * 0.5;
        assert_eq!(fog_factor(&e2, 0.5), (-(dc * dc) as f64).exp() as f32);
        assert_eq!(crate::framebuffer::format::float_to_unorm(fog_factor(&e2, 0.5), 8), 124);
    }

    #[test]
    fn blend_changes_rgb_only_on_live_fragments() {
        let f = fog(FogMode::Linear, 0.0, 1.0, 1.0);
        let mut colors = [[1.0, 0.5, 0.0, 0.25], [1.0, 0.5, 0.0, 0.25]];
        apply_fog(&f, &[0.75, 0.75], &mut colors, 0b01);
        assert_eq!(colors[0], [0.25, 0.125, 0.75, 0.25]);
        assert_eq!(colors[1], [1.0, 0.5, 0.0, 0.25]);
        let mut c = [[1.0, 0.0, 0.0, 1.0]];
        apply_fog(&fog(FogMode::Exp, 0.0, 0.0, 1.7), &[0.4], &mut c, 1);
        let f = exp(-0.68);
        assert_eq!(c[0], [f, 0.0, 1.0 - f, 1.0]);
    }

    #[test]
    fn lanes_give_the_bits_of_the_span_fog() {
        // Coordinates inside, at and beyond both ends, negative, NaN and infinite, for every
        // mode (with LINEAR's start == end case): lane for lane the span's bits.
        let coords: [f32; 16] =
            [0.0, -0.0, 0.25, 0.5, 0.999, 1.0, 1.5, -0.3, f32::NAN, f32::INFINITY, 0.1, 0.7, 2.0, 3.5, 0.33, 1e-8];
        let colors: [[f32; 4]; 16] = std::array::from_fn(|i| [i as f32 / 15.0, 1.0 - i as f32 / 15.0, 0.3, 0.5]);
        for f in [
            fog(FogMode::Linear, 0.2, 0.8, 1.0),
            fog(FogMode::Linear, 1.0, -0.5, 1.0),
            fog(FogMode::Linear, 0.5, 0.5, 1.0),
            fog(FogMode::Exp, 0.0, 1.0, 1.7),
            fog(FogMode::Exp2, 0.0, 1.0, 0.9),
        ] {
            let mut want = colors;
            apply_fog(&f, &coords, &mut want, 0xffff);
            let mut got: [F32s; 4] = std::array::from_fn(|k| colors.map(|c| c[k]));
            fog_lanes(&f, &coords, &mut got);
            for (i, w) in want.iter().enumerate() {
                assert_eq!(w.map(f32::to_bits), [0, 1, 2, 3].map(|k| got[k][i].to_bits()), "{f:?} lane {i}");
            }
        }
    }

    /// The documented bound: within 0.5 ulp + 1.3·10⁻¹² (relative) of eˣ computed in double
    /// precision, over every input the fog factors can use (and beyond), in steps of about
    /// 2⁻¹² plus every float of [−1, 0) in a stride, with the ends of the range.
    #[test]
    fn exp_is_within_half_an_ulp() {
        let mut inputs: Vec<f32> = (-104 * 4096..=89 * 4096).map(|i| i as f32 / 4096.0 + 1.0e-4).collect();
        inputs.extend((0..(1u32 << 23)).step_by(61).map(|m| -f32::from_bits(0x3f00_0000 | m)));
        inputs.extend([0.0, -0.0, -1e-30, 1e-30, -103.97, -87.5, -87.3, 88.7, -1.0, -0.5, -f32::MIN_POSITIVE]);
        let mut worst = 0.0f64;
        let mut rounded_differently = 0;
        for x in inputs {
            let got = exp(x) as f64;
            let want = (x as f64).exp();
            let nearest = want as f32;
            if nearest.is_infinite() {
                assert_eq!(got, f64::INFINITY, "exp({x:e}) overflows");
                continue;
            }
            // The spacing of floats around the result (subnormals: 2⁻¹⁴⁹).
            let ulp = (f32::from_bits(nearest.to_bits() + 1) as f64 - nearest as f64)
                .max(f64::from_bits(0x36a0_0000_0000_0000));
            let error = (got - want).abs() / ulp;
            worst = worst.max(error);
            assert!(error <= 0.5 + 1.3e-12 * want / ulp + 1e-9, "exp({x:e}) = {got:e}, e^x = {want:e}");
            rounded_differently += (got as f32 != nearest) as u32;
        }
        assert!(worst <= 0.5 + 1e-6, "worst error {worst} ulp");
        assert_eq!(rounded_differently, 0, "results other than e^x rounded to nearest");
        assert!(exp(f32::NAN).is_nan());
        assert_eq!((exp(-105.0), exp(90.0), exp(0.0)), (0.0, f32::INFINITY, 1.0));
    }
}
