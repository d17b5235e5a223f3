//! Fog: the draw's fog parameters ([`Fog`]), from which the fixed-function fragment program
//! ([`super::program`]) is generated; the program computes the factor f of the three GL
//! modes and the blend `f·Cf + (1 − f)·Cfog` on RGB, in single precision, as the rules
//! below say. [`fog_factor`] writes the factor out directly: the tests' reference only.
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
//! gives the same bits; the fragment program computes fog with that function.

#[cfg(test)]
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

#[cfg(test)]
fn clamp01(x: f32) -> f32 {
    if x > 0.0 {
        x.min(1.0)
    } else {
        0.0
    }
}

/// The fog factor for coordinate `c`, clamped to [0, 1]: **the tests' reference only**, the
/// arithmetic the generated program must reproduce bit for bit.
#[cfg(test)]
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
}
