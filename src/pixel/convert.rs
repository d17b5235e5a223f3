//! Scalar conversions of pixel transfers, bit-exact with Mesa 22's.
//!
//! Mesa's glReadPixels converts through `_mesa_format_convert` (`main/format_utils.c`) for
//! color and through `_mesa_pack_depth_span`/`_mesa_pack_stencil_span` (`main/pack.c`) for
//! depth and stencil; the functions here reproduce those formulas, including where they are
//! not the exact rational conversion:
//! - unorm → float is `u · (1/(2ⁿ − 1))` with the reciprocal rounded to f32 first (a product,
//!   not a division: 128 of 8 bits is 0.501960814, not 0.501960784);
//! - float → unorm/snorm scales in single precision and rounds half to even;
//! - unorm → unorm widens by bit replication and narrows as `(u·(2ᵐ−1) + 2ⁿ⁻¹−1) / (2ⁿ−1)`;
//! - depth → fixed-point types truncate (except GL_UNSIGNED_SHORT, which rounds).
//!
//! One deliberate difference: Mesa computes float → 32-bit unorm/snorm as the single-precision
//! product `f · 2³²` (or `f · 2³¹`), which overflows for exactly 1.0 and gives 0 (GL_UNSIGNED_INT)
//! or `i32::MIN` (GL_INT) instead of the maximum. That is a Mesa bug; tessera keeps Mesa's
//! product for every other value and saturates instead of wrapping.

/// The largest value of an n-bit unsigned number (n ≤ 32).
#[inline]
pub const fn unorm_max(bits: u32) -> u32 {
    if bits >= 32 {
        u32::MAX
    } else {
        (1u32 << bits) - 1
    }
}

/// Rounds to the nearest integer, ties to even (as `rintf` in the default rounding mode).
/// Adding 2²³ leaves no fraction bits, so the addition itself rounds; beyond 2²³ every float
/// is an integer already. (`f32::round_ties_even` is a library call without SSE4.1.) NaN
/// stays NaN.
#[inline]
pub fn round_even(value: f32) -> f32 {
    const MAGIC: f32 = 8_388_608.0;
    let magnitude = value.abs();
    if magnitude < MAGIC {
        ((magnitude + MAGIC) - MAGIC).copysign(value)
    } else {
        value
    }
}

/// Mesa's `_mesa_unorm_to_unorm`: replication when widening (the `EXTEND_NORMALIZED_INT`
/// formula), rounding division when narrowing.
#[inline]
pub fn unorm_to_unorm(value: u32, src_bits: u32, dst_bits: u32) -> u32 {
    use std::cmp::Ordering::*;
    match src_bits.cmp(&dst_bits) {
        Less => {
            let factor = unorm_max(dst_bits) / unorm_max(src_bits);
            let rest = dst_bits % src_bits;
            let low = if rest != 0 { value >> (src_bits - rest) } else { 0 };
            value.wrapping_mul(factor).wrapping_add(low)
        }
        Greater => {
            let half = (1u64 << (src_bits - 1)) - 1;
            ((value as u64 * unorm_max(dst_bits) as u64 + half) / unorm_max(src_bits) as u64) as u32
        }
        Equal => value,
    }
}

/// Mesa's `_mesa_unorm_to_float`: `u · (1/(2ⁿ − 1))`, the reciprocal rounded to f32.
#[inline]
pub fn unorm_to_float(value: u32, bits: u32) -> f32 {
    value as f32 * (1.0 / unorm_max(bits) as f32)
}

/// Mesa's `_mesa_float_to_unorm` (n ≤ 32): clamp, scale in f32, round half to even; NaN gives
/// 0. At 32 bits the scale rounds to 2³² and 1.0 would overflow: saturated here (see the
/// module docs).
#[inline]
pub fn float_to_unorm(value: f32, bits: u32) -> u32 {
    if value < 0.0 {
        0
    } else if value > 1.0 {
        unorm_max(bits)
    } else {
        let scaled = round_even(value * unorm_max(bits) as f32);
        // `as` maps NaN to 0 as Mesa's conversion does (its low bits are zero). Below 2³¹ the
        // cheaper signed conversion is exact.
        if bits < 31 {
            scaled as i32 as u32
        } else {
            (scaled as u64).min(unorm_max(bits) as u64) as u32
        }
    }
}

/// Mesa's `_mesa_float_to_snorm` (n ≤ 32), with the 32-bit overflow at 1.0 saturated.
#[inline]
pub fn float_to_snorm(value: f32, bits: u32) -> i32 {
    let max = unorm_max(bits - 1) as i32;
    if value < -1.0 {
        -max
    } else if value > 1.0 {
        max
    } else {
        let scaled = round_even(value * max as f32) as i64;
        scaled.clamp(i32::MIN as i64, max as i64) as i32
    }
}

/// float → IEEE half (binary16), rounding to nearest even as the F16C instruction Mesa uses.
pub fn float_to_half(value: f32) -> u16 {
    let bits = value.to_bits();
    let sign = ((bits >> 16) & 0x8000) as u16;
    let exponent = ((bits >> 23) & 0xff) as i32;
    let mantissa = bits & 0x7f_ffff;
    if exponent == 0xff {
        // Infinity stays infinity; NaN stays a (quiet) NaN with the payload's top bits.
        let nan = if mantissa != 0 { 0x200 | (mantissa >> 13) as u16 } else { 0 };
        return sign | 0x7c00 | nan;
    }
    let half_exponent = exponent - 127 + 15;
    if half_exponent >= 0x1f {
        return sign | 0x7c00;
    }
    // Significand with the implicit bit, and how far it must shift right to fit 10 bits
    // (more for results that are subnormal in half precision).
    let (significand, shift) = if half_exponent <= 0 {
        if half_exponent < -10 {
            return sign;
        }
        (mantissa | 0x80_0000, (14 - half_exponent) as u32)
    } else {
        (mantissa, 13)
    };
    let kept = significand >> shift;
    let rest = significand & ((1 << shift) - 1);
    let halfway = 1 << (shift - 1);
    let round_up = rest > halfway || (rest == halfway && kept & 1 == 1);
    let base = if half_exponent <= 0 { kept } else { ((half_exponent as u32) << 10) | kept };
    // A carry out of the mantissa correctly bumps the exponent (up to infinity).
    sign | (base + round_up as u32) as u16
}

/// glPixelStoref's float → integer conversion: C's `lroundf` (half away from zero) then the
/// narrowing to `GLint`, as Mesa does. Out-of-range values and NaN give `LONG_MIN` on x86-64,
/// whose low 32 bits are 0.
pub fn pixel_store_round(value: f32) -> i32 {
    let rounded = value.round();
    if !(-9.223_372e18..9.223_372e18).contains(&rounded) {
        0
    } else {
        rounded as i64 as i32
    }
}

/// An n-bit depth value as the float Mesa's depth unpackers give (`_mesa_unpack_float_z_row`):
/// 16 bits in single precision, 24 and 32 bits in double precision.
#[inline]
pub fn depth_to_float(value: u32, bits: u32) -> f32 {
    match bits {
        16 => value as f32 * (1.0 / 65535.0),
        24 => (value as f64 * (1.0 / 16_777_215.0)) as f32,
        _ => (value as f64 * (1.0 / unorm_max(bits) as f64)) as f32,
    }
}

/// Mesa's depth packing macros (`main/macros.h`), applied to depth in [0, 1].
pub mod depth_pack {
    /// `FLOAT_TO_UBYTE`: truncates.
    #[inline]
    pub fn to_u8(d: f32) -> u8 {
        (d * 255.0) as i32 as u8
    }

    /// `FLOAT_TO_BYTE`: `(trunc(255·d) − 1) / 2`, C division.
    #[inline]
    pub fn to_i8(d: f32) -> i8 {
        (((255.0 * d) as i32 - 1) / 2) as i8
    }

    /// `CLAMPED_FLOAT_TO_USHORT`: rounds half to even.
    #[inline]
    pub fn to_u16(d: f32) -> u16 {
        super::round_even(d * 65535.0) as i64 as u16
    }

    /// `FLOAT_TO_SHORT`: `(trunc(65535·d) − 1) / 2`.
    #[inline]
    pub fn to_i16(d: f32) -> i16 {
        (((65535.0 * d) as i32 - 1) / 2) as i16
    }

    /// `FLOAT_TO_UINT`: truncates in double precision.
    #[inline]
    pub fn to_u32(d: f32) -> u32 {
        (d as f64 * 4_294_967_295.0) as u32
    }

    /// `FLOAT_TO_INT`: truncates in double precision.
    #[inline]
    pub fn to_i32(d: f32) -> i32 {
        (2_147_483_647.0 * d as f64) as i32
    }

    /// The depth part of GL_UNSIGNED_INT_24_8 on Mesa's general path: `(GLuint)(d · 0xffffff)`
    /// with a single-precision product.
    #[inline]
    pub fn to_u24(d: f32) -> u32 {
        (d * 16_777_215.0) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unorm_widening_replicates_and_narrowing_rounds() {
        assert_eq!(unorm_to_unorm(128, 8, 16), 32896);
        assert_eq!(unorm_to_unorm(0x80, 8, 32), 0x8080_8080);
        assert_eq!(unorm_to_unorm(255, 8, 32), u32::MAX);
        assert_eq!(unorm_to_unorm(128, 8, 31), 0x4040_4040);
        assert_eq!(unorm_to_unorm(51, 8, 31), 0x1999_9999);
        assert_eq!(unorm_to_unorm(51, 8, 15), 0x1999);
        assert_eq!(unorm_to_unorm(1, 5, 32), 0x0842_1084);
        assert_eq!(unorm_to_unorm(3, 5, 8), 24);
        assert_eq!(unorm_to_unorm(51, 8, 7), 25);
        assert_eq!(unorm_to_unorm(128, 8, 7), 64);
        assert_eq!(unorm_to_unorm(135, 8, 2), 2);
        assert_eq!(unorm_to_unorm(247, 8, 2), 3);
        assert_eq!(unorm_to_unorm(34734, 16, 8), 135);
        assert_eq!(unorm_to_unorm(0xffff, 16, 8), 255);
    }

    #[test]
    fn unorm_to_float_multiplies_by_the_rounded_reciprocal() {
        assert_eq!(unorm_to_float(128, 8).to_bits(), 0x3f00_8081); // 0.501960814
        assert_eq!(unorm_to_float(255, 8), 1.0);
        assert_eq!(unorm_to_float(1, 5).to_bits(), 0x3d04_2108);
        // The exact quotient differs from the product for some values.
        let differ = (0..256u32).filter(|&v| unorm_to_float(v, 8) != (v as f64 / 255.0) as f32).count();
        assert_eq!(differ, 126);
    }

    #[test]
    fn float_to_unorm_and_snorm_match_mesa() {
        assert_eq!(float_to_unorm(0.5, 8), 128);
        assert_eq!(float_to_unorm(-0.0, 8), 0);
        assert_eq!(float_to_unorm(2.0, 16), 65535);
        assert_eq!(float_to_unorm(f32::NAN, 8), 0);
        // Measured on Mesa 22 (GL_RGB float buffer read as GL_UNSIGNED_INT).
        assert_eq!(float_to_unorm(0.2, 32), 0x3333_3340);
        assert_eq!(float_to_unorm(0.6, 32), 0x9999_9a00);
        assert_eq!(float_to_unorm(1.0 / 31.0, 32), 0x0842_1080);
        // Mesa gives 0 here (overflow); tessera saturates.
        assert_eq!(float_to_unorm(1.0, 32), u32::MAX);
        assert_eq!(float_to_snorm(0.5, 32), 0x4000_0000);
        assert_eq!(float_to_snorm(1.0, 32), i32::MAX);
        assert_eq!(float_to_snorm(1.0, 8), 127);
        assert_eq!(float_to_snorm(0.5, 8), 64);
        assert_eq!(float_to_snorm(-2.0, 8), -127);
        assert_eq!(float_to_snorm(-1.0, 16), -32767);
    }

    #[test]
    fn round_even_matches_the_library() {
        for v in [0.5f32, 1.5, 2.5, -2.5, 2.4999998, 8_388_607.5, 8_388_609.0, 1e10, -0.3, 0.0, 65534.5, 3.5e-30] {
            assert_eq!(round_even(v).to_bits(), v.round_ties_even().to_bits(), "{v}");
        }
        assert!(round_even(f32::NAN).is_nan());
    }

    #[test]
    fn half_conversion_rounds_to_nearest_even() {
        assert_eq!(float_to_half(1.0), 0x3c00);
        assert_eq!(float_to_half(0.5), 0x3800);
        assert_eq!(float_to_half(-2.0), 0xc000);
        assert_eq!(float_to_half(0.1), 0x2e66);
        assert_eq!(float_to_half(65504.0), 0x7bff);
        assert_eq!(float_to_half(65520.0), 0x7c00);
        assert_eq!(float_to_half(65519.0), 0x7bff);
        assert_eq!(float_to_half(f32::INFINITY), 0x7c00);
        assert_eq!(float_to_half(f32::NAN) & 0x7e00, 0x7e00);
        assert_eq!(float_to_half(5.960_464_5e-8), 0x0001); // smallest subnormal
        assert_eq!(float_to_half(2.980_232_2e-8), 0x0000); // half of it: ties to even
        assert_eq!(float_to_half(8.940_697e-8), 0x0002); // 1.5 ulp: ties to even
        assert_eq!(float_to_half(6.097_555e-5), 0x03ff); // largest subnormal
        assert_eq!(float_to_half(6.103_515_6e-5), 0x0400); // smallest normal
        assert_eq!(float_to_half(1.0 + 1.0 / 2048.0), 0x3c00); // tie, even stays
        assert_eq!(float_to_half(1.0 + 3.0 / 2048.0), 0x3c02); // tie, odd rounds up
    }

    #[test]
    fn pixel_store_rounding_is_lroundf_narrowed() {
        // Measured on Mesa 22 through glPixelStoref + glGetIntegerv.
        assert_eq!(pixel_store_round(2.5), 3);
        assert_eq!(pixel_store_round(0.49999997), 0);
        assert_eq!(pixel_store_round(-0.4), 0);
        assert_eq!(pixel_store_round(-0.5), -1);
        assert_eq!(pixel_store_round(7.6), 8);
        assert_eq!(pixel_store_round(5e9), 705_032_704);
        assert_eq!(pixel_store_round(3e9), -1_294_967_296);
        assert_eq!(pixel_store_round(1e20), 0);
        assert_eq!(pixel_store_round(f32::NAN), 0);
    }

    #[test]
    fn depth_conversions_match_mesa_measurements() {
        // 24-bit depth 0x19999a (glClearDepth(0.1)) read back on Mesa 22.
        let d = depth_to_float(0x19999a, 24);
        assert_eq!(d.to_bits(), 0x3dcc_ccd1); // 0.100000031
        assert_eq!(depth_pack::to_u8(d), 0x19);
        assert_eq!(depth_pack::to_i8(d), 0x0c);
        assert_eq!(depth_pack::to_u16(d), 0x199a);
        assert_eq!(depth_pack::to_i16(d), 0x0ccc);
        assert_eq!(depth_pack::to_u32(d), 0x1999_9a1f);
        assert_eq!(depth_pack::to_i32(d), 0x0ccc_cd0f);
        assert_eq!(depth_pack::to_u24(d), 0x19999a);
        assert_eq!(float_to_half(d), 0x2e66);
        assert_eq!(depth_pack::to_i8(0.0), 0);
        assert_eq!(depth_pack::to_i16(1.0), 32767);
        assert_eq!(depth_to_float(0xffff, 16), 1.0);
    }
}
