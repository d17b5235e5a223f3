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
//! GL_EXP and GL_EXP2 use [`crate::shader::math::exp`], tessera's own exponential (not
//! libm's `expf`, an out-of-line call whose last bit depends on the C library): a fixed
//! range reduction and polynomial in double precision, so every machine and SIMD level
//! gives the same bits; the fixed-function fragment program ([`super::program`]) computes
//! fog with the same function.

use super::block::{lanes, F32s};
use crate::shader::math::exp;

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
}
