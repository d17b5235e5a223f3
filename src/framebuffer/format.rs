//! Pixel formats of the internal buffers and the exact conversions between them.
//!
//! Conversions follow GL's rules for normalized fixed point: float → unorm is
//! `round(clamp(f, 0, 1) · (2ⁿ − 1))` with ties to even (as Mesa's `_mesa_float_to_unorm`),
//! unorm → float is `u / (2ⁿ − 1)`, and widening unorm → unorm replicates bits, which equals
//! the exact rational conversion rounded to nearest.

/// How a color buffer stores its channels. Every format stores red, green, blue and alpha;
/// formats without alpha bits keep alpha at its maximum, so destination alpha reads 1.0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorFormat {
    /// 8 bits per channel.
    Unorm8 { alpha: bool },
    /// 5/6/5 bits of red/green/blue, no alpha.
    Rgb565,
    /// 16 bits per channel.
    Unorm16 { alpha: bool },
    /// 32-bit float per channel.
    Float32 { alpha: bool },
}

impl ColorFormat {
    /// Bits of red, green, blue, alpha.
    pub fn channel_bits(self) -> [u32; 4] {
        match self {
            ColorFormat::Unorm8 { alpha } => [8, 8, 8, if alpha { 8 } else { 0 }],
            ColorFormat::Rgb565 => [5, 6, 5, 0],
            ColorFormat::Unorm16 { alpha } => [16, 16, 16, if alpha { 16 } else { 0 }],
            ColorFormat::Float32 { alpha } => [32, 32, 32, if alpha { 32 } else { 0 }],
        }
    }

    /// Whether values outside [0, 1] can be stored.
    pub fn is_float(self) -> bool {
        matches!(self, ColorFormat::Float32 { .. })
    }

    pub fn has_alpha(self) -> bool {
        self.channel_bits()[3] > 0
    }
}

/// Depth and stencil storage of a framebuffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthStencilFormat {
    /// No depth, no stencil.
    None,
    /// 16-bit depth, no stencil.
    Depth16,
    /// 24-bit depth in the low bits of a u32, stencil (8 bits) in the high byte; either part
    /// may be absent (`depth`/`stencil` false) while the layout stays the same.
    Packed24 { depth: bool, stencil: bool },
    /// 32-bit depth, with an optional separate 8-bit stencil plane.
    Depth32 { stencil: bool },
}

impl DepthStencilFormat {
    pub fn depth_bits(self) -> u32 {
        match self {
            DepthStencilFormat::None => 0,
            DepthStencilFormat::Depth16 => 16,
            DepthStencilFormat::Packed24 { depth, .. } => {
                if depth {
                    24
                } else {
                    0
                }
            }
            DepthStencilFormat::Depth32 { .. } => 32,
        }
    }

    pub fn stencil_bits(self) -> u32 {
        match self {
            DepthStencilFormat::Packed24 { stencil: true, .. } | DepthStencilFormat::Depth32 { stencil: true } => 8,
            _ => 0,
        }
    }
}

/// The largest value of an n-bit unsigned normalized number.
#[inline]
pub fn unorm_max(bits: u32) -> u32 {
    if bits >= 32 {
        u32::MAX
    } else {
        (1u32 << bits) - 1
    }
}

/// float → n-bit unorm (n ≤ 16): clamp to [0, 1], scale, round half to even. NaN becomes 0.
#[inline]
pub fn float_to_unorm(value: f32, bits: u32) -> u32 {
    let max = unorm_max(bits) as f32;
    let clamped = if value > 0.0 { value.min(1.0) } else { 0.0 };
    if bits <= 16 {
        // The product is below 2¹⁶: adding 2²³ in single precision leaves no fraction bits
        // and rounds to nearest even, exactly as `round_half_even`, without leaving f32
        // (several times fewer instructions in the color-write loops).
        const MAGIC: f32 = (1u32 << 23) as f32;
        (clamped * max + MAGIC).to_bits() - MAGIC.to_bits()
    } else {
        round_half_even(clamped * max)
    }
}

/// Rounds a non-negative single-precision value to the nearest integer, ties to even,
/// exactly as `f32::round_ties_even` but without a rounding instruction, which baseline
/// x86-64 lacks: adding 2⁵² in double precision leaves no fraction bits, and the FPU's
/// default rounding is to nearest even. Exact for every finite `v` in [0, 2⁵²).
#[inline]
pub fn round_half_even(v: f32) -> u32 {
    const MAGIC: f64 = (1u64 << 52) as f64;
    ((v as f64 + MAGIC) - MAGIC) as u32
}

/// float → 16-bit unorm as Mesa's clears of 16-bit buffers compute it: the product in single
/// precision, plus one half, truncated (so a product that rounds to x.5 goes up: 0.3 → 19661,
/// 0.7 → 45875, where [`float_to_unorm`] gives 19660 and 45874).
#[inline]
pub fn float_to_unorm16_half_up(value: f32) -> u16 {
    let clamped = if value > 0.0 { value.min(1.0) } else { 0.0 };
    (clamped * 65535.0 + 0.5) as u16
}

/// n-bit unorm → float, exactly `u / (2ⁿ − 1)` rounded once to f32.
#[inline]
pub fn unorm_to_float(value: u32, bits: u32) -> f32 {
    (value as f64 / unorm_max(bits) as f64) as f32
}

/// Depth in [0, 1] (f64) → n-bit depth value, rounded to nearest with ties to even (as
/// Mesa's clears measure: 0.1 → 0x199a, 0.7 → 0xb332 at 16 bits); NaN becomes 0.
#[inline]
pub fn depth_to_fixed(depth: f64, bits: u32) -> u32 {
    let max = unorm_max(bits) as f64;
    let clamped = if depth > 0.0 { depth.min(1.0) } else { 0.0 };
    (clamped * max).round_ties_even() as u32
}

/// Window-space depth of a fragment (single precision, in [0, 1]) → n-bit depth value:
/// the product in single precision, rounded to nearest with ties to even, as llvmpipe's
/// depth stores compute it. NaN becomes 0.
#[inline]
pub fn fragment_depth_to_fixed(z: f32, bits: u32) -> u32 {
    let clamped = if z > 0.0 { z.min(1.0) } else { 0.0 };
    round_half_even(clamped * unorm_max(bits) as f32)
}

/// Widens an n-bit unorm value to 32 bits by bit replication (exact rounding of the ratio).
#[inline]
pub fn unorm_widen_to_u32(value: u32, bits: u32) -> u32 {
    match bits {
        0 => 0,
        32 => value,
        _ => {
            let mut out: u64 = 0;
            let mut filled = 0;
            while filled < 32 {
                out = (out << bits) | value as u64;
                filled += bits;
            }
            (out >> (filled - 32)) as u32
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn single_precision_rounding_equals_the_double_precision_route() {
        // Every f32 in [0, 1] at a stride, plus the neighbours of every tie (k + ½)/max.
        let reference = |v: f32, bits: u32| {
            let max = unorm_max(bits) as f32;
            round_half_even(if v > 0.0 { v.min(1.0) } else { 0.0 } * max)
        };
        for bits in [1, 5, 6, 8, 10, 16] {
            for i in (0..=1.0f32.to_bits()).step_by(997) {
                let v = f32::from_bits(i);
                assert_eq!(float_to_unorm(v, bits), reference(v, bits), "{v} at {bits} bits");
            }
            let max = unorm_max(bits);
            for k in 0..max.min(70_000) {
                let tie = ((k as f64 + 0.5) / max as f64) as f32;
                for v in [f32::from_bits(tie.to_bits() - 1), tie, f32::from_bits(tie.to_bits() + 1)] {
                    assert_eq!(float_to_unorm(v, bits), reference(v, bits), "{v} at {bits} bits");
                }
            }
        }
    }

    #[test]
    fn float_to_unorm_rounds_to_nearest_and_clamps() {
        assert_eq!(float_to_unorm(0.5, 8), 128);
        assert_eq!(float_to_unorm(0.002, 8), 1);
        assert_eq!(float_to_unorm(0.998, 8), 254);
        assert_eq!(float_to_unorm(-1.0, 8), 0);
        assert_eq!(float_to_unorm(2.0, 8), 255);
        assert_eq!(float_to_unorm(f32::NAN, 8), 0);
        assert_eq!(float_to_unorm(1.0, 5), 31);
        assert_eq!(float_to_unorm(1.0, 16), 65535);
    }

    #[test]
    fn depth_conversion_matches_mesa_measurements() {
        // Values read back from Mesa 22.3.6 after glClearDepth.
        assert_eq!(depth_to_fixed(0.1, 16), 0x199a);
        assert_eq!(depth_to_fixed(0.7, 16), 0xb332);
        assert_eq!(depth_to_fixed(0.1, 24), 0x19999a);
        assert_eq!(depth_to_fixed(0.7, 24), 0xb33332);
        assert_eq!(depth_to_fixed(0.99999, 24), 0xffff57);
        assert_eq!(depth_to_fixed(1.0, 24), 0xffffff);
    }

    #[test]
    fn sixteen_bit_clears_round_half_up_in_single_precision() {
        // Values measured on Mesa 22 after glClearColor(v) of a GL_UNSIGNED_SHORT buffer.
        assert_eq!(float_to_unorm16_half_up(600.0 / 2000.0), 19661);
        assert_eq!(float_to_unorm16_half_up(1043.0 / 2000.0), 34177);
        assert_eq!(float_to_unorm16_half_up(0.7), 45875);
        assert_eq!(float_to_unorm16_half_up(1.0), 65535);
        assert_eq!(float_to_unorm16_half_up(-0.5), 0);
        assert_eq!(float_to_unorm16_half_up(f32::NAN), 0);
    }

    #[test]
    fn fragment_depth_rounds_the_single_precision_product_to_even() {
        assert_eq!(fragment_depth_to_fixed(0.5, 16), 0x8000);
        assert_eq!(fragment_depth_to_fixed(1.0, 24), 0xff_ffff);
        assert_eq!(fragment_depth_to_fixed(-1.0, 24), 0);
        assert_eq!(fragment_depth_to_fixed(f32::NAN, 16), 0);
        // 0.1f · 65535 = 6553.5 exactly in single precision: ties go to the even 6554.
        assert_eq!(fragment_depth_to_fixed(0.1, 16), 0x199a);
    }

    #[test]
    fn magic_rounding_equals_round_ties_even() {
        for i in 0..=(1u32 << 20) {
            let v = i as f32 / 4096.0;
            assert_eq!(round_half_even(v), v.round_ties_even() as u32, "{v}");
        }
        for v in [0.5f32, 1.5, 2.5, 254.5, 255.0, 16777215.0, 4294967040.0] {
            assert_eq!(round_half_even(v), v.round_ties_even() as u32, "{v}");
        }
    }

    #[test]
    fn widening_replicates_bits() {
        assert_eq!(unorm_widen_to_u32(0x199a, 16), 0x199a199a);
        assert_eq!(unorm_widen_to_u32(0x19999a, 24), 0x19999a19);
        assert_eq!(unorm_widen_to_u32(0xff, 8), 0xffff_ffff);
        assert_eq!(unorm_widen_to_u32(0x80, 8), 0x8080_8080);
    }
}
