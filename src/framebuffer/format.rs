//! Pixel formats of the internal buffers and the exact conversions between them.
//!
//! Conversions follow GL's rules for normalized fixed point: float → unorm is
//! `round(clamp(f, 0, 1) · (2ⁿ − 1))` with ties to even (as Mesa's `_mesa_float_to_unorm`),
//! unorm → float is `u / (2ⁿ − 1)`, and widening unorm → unorm replicates bits, which equals
//! the exact rational conversion rounded to nearest.
//!
//! Depth has two encodings ([`DepthEncoding`]), chosen once per buffer: n-bit unsigned
//! normalized integers, and single-precision floats (GL_ARB_depth_buffer_float's
//! GL_DEPTH_COMPONENT32F and GL_DEPTH32F_STENCIL8). A float depth is kept as its IEEE bit
//! pattern in the same u32 plane as 32-bit fixed point. Depth written to a float buffer is
//! clamped to [0, 1] (the extension keeps the depth range clamped) and −0 is stored as +0;
//! for non-negative floats the bit patterns order exactly as the values do, so the depth
//! test, the stencil plane, blits between buffers of one format and every integer path
//! stay as they are, and only the conversions into and out of the plane differ. (A
//! separate `f32` plane would have meant a second copy of every depth loop for the same
//! comparisons.)

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
    /// Single-precision float depth (its bit pattern, see [`DepthEncoding::Float`]) in the
    /// layout of `Depth32`, with an optional separate 8-bit stencil plane.
    Float32 { stencil: bool },
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
            DepthStencilFormat::Depth32 { .. } | DepthStencilFormat::Float32 { .. } => 32,
        }
    }

    pub fn stencil_bits(self) -> u32 {
        match self {
            DepthStencilFormat::Packed24 { stencil: true, .. }
            | DepthStencilFormat::Depth32 { stencil: true }
            | DepthStencilFormat::Float32 { stencil: true } => 8,
            _ => 0,
        }
    }

    /// How depth values are stored (unorm of `depth_bits()` bits, or float).
    #[inline]
    pub fn depth_encoding(self) -> DepthEncoding {
        match self {
            DepthStencilFormat::Float32 { .. } => DepthEncoding::Float,
            f => DepthEncoding::Unorm(f.depth_bits()),
        }
    }

    /// Whether depth is stored as floating point.
    pub fn is_float_depth(self) -> bool {
        matches!(self, DepthStencilFormat::Float32 { .. })
    }
}

/// The encoding of stored depth values: the single place where depth crosses between
/// floats and the integers kept in depth planes. Every writer and reader of depth goes
/// through it, so fixed-point and float buffers share one code path and the choice is
/// made once per buffer (per draw, per read), not per pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthEncoding {
    /// n-bit unsigned normalized (n = 0 for no depth, else 16, 24 or 32).
    Unorm(u32),
    /// The bit pattern of an f32 in [0, 1] (+0 for zero).
    Float,
}

impl DepthEncoding {
    /// A fragment's window-space depth (single precision) as stored: for unorm, the
    /// product in single precision rounded to nearest even as llvmpipe's depth stores
    /// compute it; for float, clamped to [0, 1] with −0 and NaN as +0. NaN becomes 0.
    #[inline(always)]
    pub fn encode_fragment(self, z: f32) -> u32 {
        match self {
            DepthEncoding::Unorm(bits) => fragment_depth_to_fixed(z, bits),
            DepthEncoding::Float => float_depth_bits(z),
        }
    }

    /// A depth value given in double precision (glClearDepth of a whole buffer) as stored.
    #[inline]
    pub fn encode_f64(self, depth: f64) -> u32 {
        match self {
            DepthEncoding::Unorm(bits) => depth_to_fixed(depth, bits),
            DepthEncoding::Float => float_depth_bits(depth as f32),
        }
    }

    /// A depth in single precision (texture texels, client data) as stored: unorm rounds
    /// the exact product to nearest; float keeps the value (clamped to [0, 1]).
    #[inline]
    pub fn encode_f32(self, depth: f32) -> u32 {
        match self {
            DepthEncoding::Unorm(bits) => depth_to_fixed(depth as f64, bits),
            DepthEncoding::Float => float_depth_bits(depth),
        }
    }

    /// A stored value as a float in [0, 1]: `u / (2ⁿ − 1)` rounded once, or the float itself.
    #[inline]
    pub fn decode(self, stored: u32) -> f32 {
        match self {
            DepthEncoding::Unorm(bits) => unorm_to_float(stored, bits),
            DepthEncoding::Float => f32::from_bits(stored),
        }
    }

    /// The depth a stored value of this encoding has after storing it in `target`
    /// (blits, copies between buffers): the bits unchanged when the encodings agree.
    #[inline]
    pub fn convert_to(self, stored: u32, target: DepthEncoding) -> u32 {
        if self == target {
            stored
        } else {
            target.encode_f32(self.decode(stored))
        }
    }
}

/// A depth as a float depth buffer stores it: clamped to [0, 1], NaN and −0 as +0, as
/// its bit pattern (which orders as the values do).
#[inline(always)]
pub fn float_depth_bits(z: f32) -> u32 {
    // `z > 0.0` is false for NaN, −0 and +0, which all store as +0.
    if z > 0.0 {
        z.min(1.0).to_bits()
    } else {
        0
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
    // Below 2³²: adding 2⁵² leaves no fraction bits and rounds to nearest even, as
    // `round_ties_even` does without its libm call on baseline x86-64.
    const MAGIC: f64 = (1u64 << 52) as f64;
    ((clamped * max + MAGIC) - MAGIC) as u32
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
    fn float_depth_bit_patterns_order_as_the_values() {
        let enc = DepthEncoding::Float;
        // A walk over [0, 1] at a stride, plus the neighbours of 0 and 1.
        let mut values: Vec<f32> = (0..=1.0f32.to_bits()).step_by(9973).map(f32::from_bits).collect();
        values.extend([0.0, f32::from_bits(1), f32::MIN_POSITIVE, 1.0 - f32::EPSILON / 2.0, 1.0]);
        values.sort_by(f32::total_cmp);
        for pair in values.windows(2) {
            let (a, b) = (enc.encode_fragment(pair[0]), enc.encode_fragment(pair[1]));
            assert_eq!(pair[0].partial_cmp(&pair[1]), a.partial_cmp(&b), "{} vs {}", pair[0], pair[1]);
            assert_eq!(enc.decode(a), pair[0], "float depth is stored exactly");
        }
    }

    #[test]
    fn float_depth_clamps_and_drops_negative_zero() {
        let enc = DepthEncoding::Float;
        assert_eq!(enc.encode_fragment(-0.0), 0, "−0 stores as +0, so −0 == +0 in the depth test");
        assert_eq!(enc.encode_fragment(-0.0), enc.encode_fragment(0.0));
        assert_eq!(enc.encode_fragment(-1e-30), 0);
        assert_eq!(enc.encode_fragment(f32::NAN), 0);
        assert_eq!(enc.encode_fragment(1.5), 1.0f32.to_bits());
        assert_eq!(enc.encode_fragment(f32::INFINITY), 1.0f32.to_bits());
        assert_eq!(enc.encode_f64(0.1), 0.1f32.to_bits());
        assert_eq!(enc.decode(enc.encode_f32(1e-7)), 1e-7, "small depths are kept exactly");
        // Depths 1e-8 apart near 0 (reversed Z, far away) stay apart in float, not in 24 bits.
        assert!(enc.encode_fragment(1e-8) < enc.encode_fragment(2e-8));
        assert_eq!(fragment_depth_to_fixed(1e-8, 24), fragment_depth_to_fixed(2e-8, 24));
    }

    #[test]
    fn converting_between_encodings_goes_through_the_value() {
        let (fixed, float) = (DepthEncoding::Unorm(24), DepthEncoding::Float);
        assert_eq!(fixed.convert_to(0xff_ffff, float), 1.0f32.to_bits());
        assert_eq!(float.convert_to(0.5f32.to_bits(), fixed), 0x80_0000);
        assert_eq!(float.convert_to(0x1234_5678, float), 0x1234_5678, "same encoding: bits unchanged");
        assert_eq!(DepthStencilFormat::Float32 { stencil: true }.depth_encoding(), float);
        assert_eq!(DepthStencilFormat::Depth32 { stencil: false }.depth_encoding(), DepthEncoding::Unorm(32));
    }

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
