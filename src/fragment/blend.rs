//! Blending: the fifteen GL blend factors and five equations, with separate RGB and alpha
//! functions, as pure span functions.
//!
//! Two paths: an exact integer path for 8-bit unorm targets, where every product `a·b/255`
//! is rounded to nearest (`t = a·b + 128; (t + (t >> 8)) >> 8`) and the sum or difference
//! saturates to [0, 255], and a single-precision path for 16-bit unorm and float targets.
//! The integer path reproduces llvmpipe byte for byte on a grid of every 17th value for
//! every factor pair and equation (see the module tests). A target without alpha bits reads
//! destination alpha 1: [`Blend::for_target`] rewrites the factors once per draw.

/// A blend factor (GL 2.1 table 4.2); `SrcAlphaSaturate` is `(f, f, f, 1)` with
/// `f = min(As, 1 − Ad)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    ConstantColor,
    OneMinusConstantColor,
    ConstantAlpha,
    OneMinusConstantAlpha,
    SrcAlphaSaturate,
}

impl BlendFactor {
    /// All fifteen factors, in GL's table order.
    pub const ALL: [BlendFactor; 15] = [
        Self::Zero,
        Self::One,
        Self::SrcColor,
        Self::OneMinusSrcColor,
        Self::DstColor,
        Self::OneMinusDstColor,
        Self::SrcAlpha,
        Self::OneMinusSrcAlpha,
        Self::DstAlpha,
        Self::OneMinusDstAlpha,
        Self::ConstantColor,
        Self::OneMinusConstantColor,
        Self::ConstantAlpha,
        Self::OneMinusConstantAlpha,
        Self::SrcAlphaSaturate,
    ];

    /// The factor with destination alpha fixed at 1 (a target without alpha bits).
    fn with_opaque_destination(self) -> Self {
        match self {
            Self::DstAlpha => Self::One,
            Self::OneMinusDstAlpha => Self::Zero,
            // min(As, 1 − 1) = 0 on RGB; the alpha factor of SRC_ALPHA_SATURATE is 1 anyway.
            Self::SrcAlphaSaturate => Self::Zero,
            other => other,
        }
    }
}

/// A blend equation. `Min` and `Max` ignore the factors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlendEquation {
    Add,
    Subtract,
    ReverseSubtract,
    Min,
    Max,
}

impl BlendEquation {
    pub const ALL: [BlendEquation; 5] = [Self::Add, Self::Subtract, Self::ReverseSubtract, Self::Min, Self::Max];
}

/// The factors and equation of one half (RGB or alpha) of the blend function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlendFunc {
    pub src: BlendFactor,
    pub dst: BlendFactor,
    pub equation: BlendEquation,
}

/// The blend state of one draw target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Blend {
    pub rgb: BlendFunc,
    pub alpha: BlendFunc,
}

impl Blend {
    /// The same blend with destination alpha read as 1 when the target has no alpha bits.
    /// `SRC_ALPHA_SATURATE` on the alpha half is 1 whatever the destination, so it stays.
    pub fn for_target(self, has_alpha: bool) -> Self {
        if has_alpha {
            return self;
        }
        let opaque = |f: BlendFunc, keep_saturate: bool| BlendFunc {
            src: if keep_saturate && f.src == BlendFactor::SrcAlphaSaturate {
                f.src
            } else {
                f.src.with_opaque_destination()
            },
            dst: if keep_saturate && f.dst == BlendFactor::SrcAlphaSaturate {
                f.dst
            } else {
                f.dst.with_opaque_destination()
            },
            equation: f.equation,
        };
        Blend { rgb: opaque(self.rgb, false), alpha: opaque(self.alpha, true) }
    }
}

/// `a·b/255` rounded to nearest, exact for all `a, b` in [0, 255].
#[inline(always)]
pub fn mul_unorm8(a: u32, b: u32) -> u32 {
    let t = a * b + 128;
    (t + (t >> 8)) >> 8
}

/// Fills channels `lo..hi` of `out[i]` (i < n) with `factor` evaluated for unorm8 colors.
#[inline(always)] // into the per-level copies of write_target (crate::simd)
fn factor_unorm8(
    factor: BlendFactor,
    src: &[[u8; 4]],
    dst: &[[u8; 4]],
    constant: [u8; 4],
    channels: std::ops::Range<usize>,
    out: &mut [[u8; 4]],
) {
    let n = out.len();
    macro_rules! each {
        (|$s:ident, $d:ident, $k:ident| $e:expr) => {
            if channels == (0..4) {
                // A fixed-length inner loop (a variable range became a memset call per pixel).
                for ((o, $s), $d) in out.iter_mut().zip(&src[..n]).zip(&dst[..n]) {
                    for $k in 0..4 {
                        o[$k] = $e;
                    }
                }
            } else {
                for ((o, $s), $d) in out.iter_mut().zip(&src[..n]).zip(&dst[..n]) {
                    for $k in channels.clone() {
                        o[$k] = $e;
                    }
                }
            }
        };
    }
    match factor {
        BlendFactor::Zero => each!(|_s, _d, k| 0),
        BlendFactor::One => each!(|_s, _d, k| 255),
        BlendFactor::SrcColor => each!(|s, _d, k| s[k]),
        BlendFactor::OneMinusSrcColor => each!(|s, _d, k| 255 - s[k]),
        BlendFactor::DstColor => each!(|_s, d, k| d[k]),
        BlendFactor::OneMinusDstColor => each!(|_s, d, k| 255 - d[k]),
        BlendFactor::SrcAlpha => each!(|s, _d, k| s[3]),
        BlendFactor::OneMinusSrcAlpha => each!(|s, _d, k| 255 - s[3]),
        BlendFactor::DstAlpha => each!(|_s, d, k| d[3]),
        BlendFactor::OneMinusDstAlpha => each!(|_s, d, k| 255 - d[3]),
        BlendFactor::ConstantColor => each!(|_s, _d, k| constant[k]),
        BlendFactor::OneMinusConstantColor => each!(|_s, _d, k| 255 - constant[k]),
        BlendFactor::ConstantAlpha => each!(|_s, _d, k| constant[3]),
        BlendFactor::OneMinusConstantAlpha => each!(|_s, _d, k| 255 - constant[3]),
        BlendFactor::SrcAlphaSaturate => each!(|s, d, k| if k == 3 { 255 } else { s[3].min(255 - d[3]) }),
    }
}

/// Combines source and destination with their factors on channels `lo..hi`, writing to `out`.
#[inline(always)] // into the per-level copies of write_target (crate::simd)
fn equation_unorm8(
    equation: BlendEquation,
    src: &[[u8; 4]],
    dst: &[[u8; 4]],
    sf: &[[u8; 4]],
    df: &[[u8; 4]],
    channels: std::ops::Range<usize>,
    out: &mut [[u8; 4]],
) {
    let n = out.len();
    macro_rules! each {
        (|$s:ident, $d:ident| $e:expr) => {
            if channels == (0..4) {
                // All four channels: fixed-length inner loops without bounds checks, which
                // the compiler unrolls (the same arithmetic as below).
                let lanes = out.iter_mut().zip(src).zip(dst).zip(sf).zip(df);
                for ((((o, s), d), a), b) in lanes {
                    for k in 0..4 {
                        let $s = mul_unorm8(s[k] as u32, a[k] as u32);
                        let $d = mul_unorm8(d[k] as u32, b[k] as u32);
                        o[k] = $e as u8;
                    }
                }
            } else {
                for i in 0..n {
                    for k in channels.clone() {
                        let $s = mul_unorm8(src[i][k] as u32, sf[i][k] as u32);
                        let $d = mul_unorm8(dst[i][k] as u32, df[i][k] as u32);
                        out[i][k] = $e as u8;
                    }
                }
            }
        };
    }
    match equation {
        BlendEquation::Add => each!(|s, d| (s + d).min(255)),
        BlendEquation::Subtract => each!(|s, d| s.saturating_sub(d)),
        BlendEquation::ReverseSubtract => each!(|s, d| d.saturating_sub(s)),
        BlendEquation::Min => (0..n).for_each(|i| channels.clone().for_each(|k| out[i][k] = src[i][k].min(dst[i][k]))),
        BlendEquation::Max => (0..n).for_each(|i| channels.clone().for_each(|k| out[i][k] = src[i][k].max(dst[i][k]))),
    }
}

/// Blends the unorm8 source colors `src` (pixel i of the span) into `dst` for every bit of
/// `live`; `constant` is the blend color converted to unorm8. Channel masks are applied by
/// the caller's write, not here.
#[inline(always)] // into the per-level copies of write_target (crate::simd)
pub fn blend_unorm8(blend: &Blend, constant: [u8; 4], src: &[[u8; 4]], dst: &mut [[u8; 4]], live: u64) {
    let n = src.len().min(dst.len()).min(super::MAX_SPAN);
    let mut sf = [[0u8; 4]; super::MAX_SPAN];
    let mut df = [[0u8; 4]; super::MAX_SPAN];
    let mut out = [[0u8; 4]; super::MAX_SPAN];
    let (src, d) = (&src[..n], &dst[..n]);
    if blend.rgb == blend.alpha {
        factor_unorm8(blend.rgb.src, src, d, constant, 0..4, &mut sf[..n]);
        factor_unorm8(blend.rgb.dst, src, d, constant, 0..4, &mut df[..n]);
        equation_unorm8(blend.rgb.equation, src, d, &sf[..n], &df[..n], 0..4, &mut out[..n]);
    } else {
        factor_unorm8(blend.rgb.src, src, d, constant, 0..3, &mut sf[..n]);
        factor_unorm8(blend.rgb.dst, src, d, constant, 0..3, &mut df[..n]);
        factor_unorm8(blend.alpha.src, src, d, constant, 3..4, &mut sf[..n]);
        factor_unorm8(blend.alpha.dst, src, d, constant, 3..4, &mut df[..n]);
        equation_unorm8(blend.rgb.equation, src, d, &sf[..n], &df[..n], 0..3, &mut out[..n]);
        equation_unorm8(blend.alpha.equation, src, d, &sf[..n], &df[..n], 3..4, &mut out[..n]);
    }
    for (i, (cell, v)) in dst[..n].iter_mut().zip(&out[..n]).enumerate() {
        if live & (1 << i) != 0 {
            *cell = *v;
        }
    }
}

/// Fills channels `channels` of `out[i]` with `factor` evaluated in single precision.
fn factor_f32(
    factor: BlendFactor,
    src: &[[f32; 4]],
    dst: &[[f32; 4]],
    c: [f32; 4],
    channels: std::ops::Range<usize>,
    out: &mut [[f32; 4]],
) {
    macro_rules! each {
        (|$s:ident, $d:ident, $k:ident| $e:expr) => {
            for ((o, $s), $d) in out.iter_mut().zip(src).zip(dst) {
                for $k in channels.clone() {
                    o[$k] = $e;
                }
            }
        };
    }
    match factor {
        BlendFactor::Zero => each!(|_s, _d, k| 0.0),
        BlendFactor::One => each!(|_s, _d, k| 1.0),
        BlendFactor::SrcColor => each!(|s, _d, k| s[k]),
        BlendFactor::OneMinusSrcColor => each!(|s, _d, k| 1.0 - s[k]),
        BlendFactor::DstColor => each!(|_s, d, k| d[k]),
        BlendFactor::OneMinusDstColor => each!(|_s, d, k| 1.0 - d[k]),
        BlendFactor::SrcAlpha => each!(|s, _d, k| s[3]),
        BlendFactor::OneMinusSrcAlpha => each!(|s, _d, k| 1.0 - s[3]),
        BlendFactor::DstAlpha => each!(|_s, d, k| d[3]),
        BlendFactor::OneMinusDstAlpha => each!(|_s, d, k| 1.0 - d[3]),
        BlendFactor::ConstantColor => each!(|_s, _d, k| c[k]),
        BlendFactor::OneMinusConstantColor => each!(|_s, _d, k| 1.0 - c[k]),
        BlendFactor::ConstantAlpha => each!(|_s, _d, k| c[3]),
        BlendFactor::OneMinusConstantAlpha => each!(|_s, _d, k| 1.0 - c[3]),
        BlendFactor::SrcAlphaSaturate => each!(|s, d, k| if k == 3 { 1.0 } else { s[3].min(1.0 - d[3]) }),
    }
}

/// Combines source and destination with their factors on `channels` in single precision.
fn equation_f32(
    equation: BlendEquation,
    src: &[[f32; 4]],
    dst: &[[f32; 4]],
    sf: &[[f32; 4]],
    df: &[[f32; 4]],
    channels: std::ops::Range<usize>,
    out: &mut [[f32; 4]],
) {
    macro_rules! each {
        (|$s:ident, $d:ident, $i:ident, $k:ident| $e:expr) => {
            for $i in 0..out.len() {
                for $k in channels.clone() {
                    let $s = src[$i][$k] * sf[$i][$k];
                    let $d = dst[$i][$k] * df[$i][$k];
                    out[$i][$k] = $e;
                }
            }
        };
    }
    match equation {
        BlendEquation::Add => each!(|s, d, i, k| s + d),
        BlendEquation::Subtract => each!(|s, d, i, k| s - d),
        BlendEquation::ReverseSubtract => each!(|s, d, i, k| d - s),
        BlendEquation::Min => each!(|_s, _d, i, k| src[i][k].min(dst[i][k])),
        BlendEquation::Max => each!(|_s, _d, i, k| src[i][k].max(dst[i][k])),
    }
}

#[inline(always)]
fn clamp01(x: f32) -> f32 {
    if x > 0.0 {
        x.min(1.0)
    } else {
        0.0
    }
}

/// Blends in single precision, for 16-bit unorm and float targets. `fixed_point` selects
/// GL's clamping for fixed-point buffers: source, destination and constant are clamped to
/// [0, 1] before blending and the result after (GL 2.1 with ARB_color_buffer_float §4.1.8);
/// float buffers blend unclamped. The result is written to `dst` for every bit of `live`.
pub fn blend_f32(
    blend: &Blend,
    constant: [f32; 4],
    src: &[[f32; 4]],
    dst: &mut [[f32; 4]],
    live: u64,
    fixed_point: bool,
) {
    const N: usize = super::MAX_SPAN;
    let n = src.len().min(dst.len()).min(N);
    let c = if fixed_point { constant.map(clamp01) } else { constant };
    let (mut s, mut d) = ([[0f32; 4]; N], [[0f32; 4]; N]);
    s[..n].copy_from_slice(&src[..n]);
    d[..n].copy_from_slice(&dst[..n]);
    if fixed_point {
        s[..n].iter_mut().chain(d[..n].iter_mut()).for_each(|p| *p = p.map(clamp01));
    }
    let (s, d) = (&s[..n], &d[..n]);
    let (mut sf, mut df, mut out) = ([[0f32; 4]; N], [[0f32; 4]; N], [[0f32; 4]; N]);
    for (f, channels) in [(blend.rgb, 0..3), (blend.alpha, 3..4)] {
        factor_f32(f.src, s, d, c, channels.clone(), &mut sf[..n]);
        factor_f32(f.dst, s, d, c, channels.clone(), &mut df[..n]);
        equation_f32(f.equation, s, d, &sf[..n], &df[..n], channels, &mut out[..n]);
    }
    for (i, (cell, v)) in dst[..n].iter_mut().zip(&out[..n]).enumerate() {
        if live & (1 << i) != 0 {
            *cell = if fixed_point { v.map(clamp01) } else { *v };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use BlendEquation as E;
    use BlendFactor as F;

    fn func(src: F, dst: F, equation: E) -> BlendFunc {
        BlendFunc { src, dst, equation }
    }

    fn same(src: F, dst: F, equation: E) -> Blend {
        Blend { rgb: func(src, dst, equation), alpha: func(src, dst, equation) }
    }

    fn one(blend: &Blend, constant: [u8; 4], s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
        let mut dst = [d];
        blend_unorm8(blend, constant, &[s], &mut dst, 1);
        dst[0]
    }

    #[test]
    fn mul_unorm8_is_rounded_exactly_for_all_pairs() {
        for a in 0..=255u32 {
            for b in 0..=255u32 {
                let exact = ((a * b) as f64 / 255.0).round() as u32;
                assert_eq!(mul_unorm8(a, b), exact, "{a}·{b}");
            }
        }
    }

    #[test]
    fn every_factor_on_one_pixel() {
        let s = [200, 100, 50, 128];
        let d = [10, 240, 128, 64];
        let c = [51, 102, 153, 204];
        let expect: [(F, [u8; 4]); 15] = [
            (F::Zero, [0, 0, 0, 0]),
            (F::One, [200, 100, 50, 128]),
            (F::SrcColor, [157, 39, 10, 64]),
            (F::OneMinusSrcColor, [43, 61, 40, 64]),
            (F::DstColor, [8, 94, 25, 32]),
            (F::OneMinusDstColor, [192, 6, 25, 96]),
            (F::SrcAlpha, [100, 50, 25, 64]),
            (F::OneMinusSrcAlpha, [100, 50, 25, 64]),
            (F::DstAlpha, [50, 25, 13, 32]),
            (F::OneMinusDstAlpha, [150, 75, 37, 96]),
            (F::ConstantColor, [40, 40, 30, 102]),
            (F::OneMinusConstantColor, [160, 60, 20, 26]),
            (F::ConstantAlpha, [160, 80, 40, 102]),
            (F::OneMinusConstantAlpha, [40, 20, 10, 26]),
            // f = min(128, 255 − 64) = 128 on RGB, 1 on alpha.
            (F::SrcAlphaSaturate, [100, 50, 25, 128]),
        ];
        for (f, e) in expect {
            assert_eq!(one(&same(f, F::Zero, E::Add), c, s, d), e, "src {f:?}");
        }
    }

    #[test]
    fn equations_saturate_and_min_max_ignore_factors() {
        let s = [200, 100, 50, 128];
        let d = [100, 200, 50, 255];
        assert_eq!(one(&same(F::One, F::One, E::Add), [0; 4], s, d), [255, 255, 100, 255]);
        assert_eq!(one(&same(F::One, F::One, E::Subtract), [0; 4], s, d), [100, 0, 0, 0]);
        assert_eq!(one(&same(F::One, F::One, E::ReverseSubtract), [0; 4], s, d), [0, 100, 0, 127]);
        assert_eq!(one(&same(F::Zero, F::Zero, E::Min), [0; 4], s, d), [100, 100, 50, 128]);
        assert_eq!(one(&same(F::Zero, F::Zero, E::Max), [0; 4], s, d), [200, 200, 50, 255]);
        // The classic over operator: 200·128/255 + 100·127/255 = 100.39 + 49.80 → 100 + 50.
        assert_eq!(one(&same(F::SrcAlpha, F::OneMinusSrcAlpha, E::Add), [0; 4], s, d)[0], 150);
    }

    #[test]
    fn separate_rgb_and_alpha_functions() {
        let b = Blend { rgb: func(F::One, F::One, E::Add), alpha: func(F::Zero, F::One, E::ReverseSubtract) };
        assert_eq!(one(&b, [0; 4], [10, 20, 30, 40], [1, 2, 3, 50]), [11, 22, 33, 50]);
        let b = Blend { rgb: func(F::Zero, F::One, E::Max), alpha: func(F::One, F::Zero, E::Add) };
        assert_eq!(one(&b, [0; 4], [10, 20, 30, 40], [1, 200, 3, 50]), [10, 200, 30, 40]);
    }

    #[test]
    fn live_mask_leaves_dead_pixels() {
        let b = same(F::One, F::One, E::Add);
        let mut dst = [[1, 1, 1, 1]; 3];
        blend_unorm8(&b, [0; 4], &[[5; 4]; 3], &mut dst, 0b101);
        assert_eq!(dst, [[6; 4], [1; 4], [6; 4]]);
    }

    #[test]
    fn target_without_alpha_reads_destination_alpha_one() {
        let b = Blend {
            rgb: func(F::DstAlpha, F::SrcAlphaSaturate, E::Add),
            alpha: func(F::OneMinusDstAlpha, F::SrcAlphaSaturate, E::Add),
        }
        .for_target(false);
        assert_eq!(b.rgb, func(F::One, F::Zero, E::Add));
        assert_eq!(b.alpha, func(F::Zero, F::SrcAlphaSaturate, E::Add));
        assert_eq!(same(F::DstAlpha, F::One, E::Add).for_target(true), same(F::DstAlpha, F::One, E::Add));
    }

    #[test]
    fn float_path_clamps_only_fixed_point() {
        let b = same(F::One, F::One, E::Add);
        let mut dst = [[0.75f32, -1.0, 2.0, 0.5]];
        blend_f32(&b, [0.0; 4], &[[0.5, 0.25, 0.0, 0.25]], &mut dst, 1, false);
        assert_eq!(dst[0], [1.25, -0.75, 2.0, 0.75]);
        let mut dst = [[0.75f32, -1.0, 2.0, 0.5]];
        blend_f32(&b, [0.0; 4], &[[0.5, 0.25, 0.0, 0.25]], &mut dst, 1, true);
        assert_eq!(dst[0], [1.0, 0.25, 1.0, 0.75]);
        let b = same(F::ConstantColor, F::SrcAlphaSaturate, E::Subtract);
        let mut dst = [[0.5f32, 0.5, 0.5, 0.75]];
        blend_f32(&b, [0.5, 2.0, -1.0, 0.5], &[[1.0, 0.5, 0.5, 0.5]], &mut dst, 1, false);
        // RGB: s·c − d·min(0.5, 0.25); alpha: 0.5·0.5 − 0.75·1.
        assert_eq!(dst[0], [0.375, 0.875, -0.625, -0.5]);
    }
}
