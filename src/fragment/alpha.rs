//! The alpha test: the eight compare functions of fragment alpha against the reference, on a
//! span, producing a live mask.
//!
//! Precision follows llvmpipe (and GL 2.1 §4.1.4, which converts the reference to fixed
//! point): for a draw whose first color target is 8-bit unorm, both the fragment alpha and
//! the reference are converted to 8 bits (clamp, scale by 255, round half to even, as color
//! stores do) and compared as integers. Measured on Mesa 22.3.6 llvmpipe with GEQUAL/EQUAL
//! at references and alphas `(k + ½)/255`: ref `125.5/255` lets alpha 126/255 pass and
//! `126.5/255` lets 126/255 pass; alpha `126.5/255` equals ref 126/255, `127.5/255` equals
//! 128/255. (softpipe compares in float instead: alpha 126/255 fails `≥ 126.5/255`.) For
//! float and 16-bit targets the comparison is in single precision on clamped values.

use super::{passes, MAX_SPAN};
use crate::framebuffer::format::float_to_unorm;
use crate::gl::CompareFunc;

/// The reference converted for [`alpha_test_unorm8`].
#[inline]
pub fn reference_unorm8(reference: f32) -> u8 {
    float_to_unorm(reference, 8) as u8
}

/// Tests 8-bit alphas against an 8-bit reference; returns the fragments of `live` that pass.
pub fn alpha_test_unorm8(func: CompareFunc, reference: u8, alphas: &[u8], live: u64) -> u64 {
    let mut pass = 0u64;
    for (i, &a) in alphas.iter().enumerate().take(MAX_SPAN) {
        if passes(func, a as u32, reference as u32) {
            pass |= 1 << i;
        }
    }
    pass & live
}

/// Tests single-precision alphas against the reference, both clamped to [0, 1] (NaN alpha
/// counts as 0); returns the fragments of `live` that pass.
pub fn alpha_test_f32(func: CompareFunc, reference: f32, alphas: &[f32], live: u64) -> u64 {
    let clamp = |x: f32| if x > 0.0 { x.min(1.0) } else { 0.0 };
    let r = clamp(reference);
    let mut pass = 0u64;
    for (i, &a) in alphas.iter().enumerate().take(MAX_SPAN) {
        let a = clamp(a);
        let ok = match func {
            CompareFunc::Never => false,
            CompareFunc::Less => a < r,
            CompareFunc::Equal => a == r,
            CompareFunc::LessEqual => a <= r,
            CompareFunc::Greater => a > r,
            CompareFunc::NotEqual => a != r,
            CompareFunc::GreaterEqual => a >= r,
            CompareFunc::Always => true,
        };
        pass |= (ok as u64) << i;
    }
    pass & live
}

#[cfg(test)]
mod tests {
    use super::*;
    use CompareFunc as C;

    const TABLE: [(C, u64); 8] = [
        (C::Never, 0b000),
        (C::Less, 0b001),
        (C::Equal, 0b010),
        (C::LessEqual, 0b011),
        (C::Greater, 0b100),
        (C::NotEqual, 0b101),
        (C::GreaterEqual, 0b110),
        (C::Always, 0b111),
    ];

    #[test]
    fn every_function_unorm8() {
        for (func, want) in TABLE {
            assert_eq!(alpha_test_unorm8(func, 128, &[127, 128, 129], 0b111), want, "{func:?}");
            assert_eq!(alpha_test_unorm8(func, 128, &[127, 128, 129], 0b010), want & 0b010);
        }
    }

    #[test]
    fn every_function_f32() {
        for (func, want) in TABLE {
            assert_eq!(alpha_test_f32(func, 0.5, &[0.25, 0.5, 0.75], 0b111), want, "{func:?}");
        }
        // Out-of-range alphas and references are clamped.
        assert_eq!(alpha_test_f32(C::Equal, 2.0, &[1.5, 1.0, f32::NAN], 0b111), 0b011);
        assert_eq!(alpha_test_f32(C::Equal, -1.0, &[f32::NAN, -3.0, 0.1], 0b111), 0b011);
    }

    #[test]
    fn unorm8_reference_rounds_half_to_even_as_llvmpipe() {
        assert_eq!(reference_unorm8(125.5 / 255.0), 126);
        assert_eq!(reference_unorm8(126.5 / 255.0), 126);
        assert_eq!(reference_unorm8(0.5), 128);
        assert_eq!(reference_unorm8(-0.5), 0);
        assert_eq!(reference_unorm8(7.0), 255);
        // A fragment alpha of 0.5 (127.5 → 128) passes GEQUAL 128/255, which a float compare
        // (0.5 ≥ 0.50196) would reject.
        let a = float_to_unorm(0.5, 8) as u8;
        assert_eq!(alpha_test_unorm8(C::GreaterEqual, reference_unorm8(128.0 / 255.0), &[a], 1), 1);
        assert_eq!(alpha_test_f32(C::GreaterEqual, 128.0 / 255.0, &[0.5], 1), 0);
    }
}
