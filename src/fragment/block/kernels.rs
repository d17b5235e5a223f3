//! The per-fragment operations of a block as lane kernels: small free functions over
//! `[T; 16]` that LLVM vectorises, chosen once per draw state as function pointers to
//! monomorphised instances (depth/stencil per storage format, blend per factor and
//! equation, stencil per operation), so that nothing is matched per block or pixel.
//!
//! - Depth and stencil: [`super::depth_stencil`].
//! - Colour targets: a kernel kind chosen once per draw state and matched once per block
//!   and target, inside the block's per-level body (`TargetKernel::run` is inlined there
//!   with every kernel body), so a target costs a jump, not a dispatch of its own.
//! - unorm8 targets: colours converted straight to packed RGBA words; exact integer
//!   blending on u16 lanes (`mul8`), every factor and equation, separate RGB and alpha, the
//!   blend colour; the logic op on the packed words; channel masks as byte masks. The
//!   common factor pairs have their own kernels on the packed words
//!   (GL_SRC_ALPHA or GL_ONE with GL_ONE_MINUS_SRC_ALPHA as 16-bit lanes with `pmullw`,
//!   GL_ONE/GL_ONE as a saturating byte add: `simd::dispatch`'s blend helpers; the first
//!   pair takes interpolated colours as channel lanes, not words, see
//!   [`TargetKernel::run_colors`]), the rest call one function pointer per factor and
//!   channel.
//! - RGB565 targets: the unorm8 blend on the widened destination, dither or truncation to
//!   5/6 bits, the logic op on the packed words, channel masks as bit masks.
//! - 16-bit unorm and float targets: the span path's f32 stages (`super::super::output`),
//!   called on the block's rows.

use super::{lanes, load, map_lanes, store, BlockAt, BlockColors, F32s, U16s, U32s, LANES};
use crate::fragment::blend::{Blend, BlendEquation, BlendFactor};
use crate::fragment::dither::{dither_channel, BAYER4};
use crate::fragment::logic_op::LogicOp;
use crate::fragment::output::{write_target, TargetOps};
use crate::fragment::{write_colors, FragmentState};
use crate::framebuffer::band::ColorBand;
use crate::framebuffer::format::float_to_unorm;
use crate::framebuffer::ColorFormat;
use crate::simd::dispatch::{pack_unorm8, round_even_i32};
use crate::simd::Supported;

// ---------------------------------------------------------------------------------------
// Colour targets.

/// Which write kernel a colour target runs (see [`TargetKernel::run`]).
#[derive(Clone, Copy, Debug)]
enum Kind {
    Unorm8Store,
    Unorm8LogicOp,
    Unorm8BlendSrcAlpha,
    Unorm8BlendAdd,
    Unorm8BlendOneInvSrcAlpha,
    Unorm8Blend,
    Rgb565,
    RowsF32,
}

/// What a colour target's write kernel reads.
pub struct TargetParams {
    mask: [bool; 4],
    /// unorm8: the bytes the channel mask keeps (bit set: keep the stored bit).
    keep8: u32,
    /// RGB565: the bits the channel mask keeps.
    keep565: u16,
    blend: Option<Blend>,
    blend_fns: Option<BlendFns>,
    blend_color: [f32; 4],
    constant8: [u16; 4],
    logic_op: Option<LogicOp>,
    dither: bool,
    clamp_float: bool,
}

/// One colour target's write kernel and the index of its band target.
pub struct TargetKernel {
    pub index: usize,
    kind: Kind,
    params: TargetParams,
}

impl TargetKernel {
    /// The kernel of target `index` (format `format`, channel mask `mask`) of `fragment`.
    pub fn new(fragment: &FragmentState, index: usize, format: ColorFormat, mask: [bool; 4]) -> Self {
        let blend = fragment.blend.get(index).copied().flatten().filter(|_| fragment.logic_op.is_none());
        let keep8 = (0..4).filter(|&k| !mask[k]).fold(0u32, |m, k| m | 0xff << (8 * k));
        let keep565 = (if mask[0] { 0 } else { 0xf800 })
            | (if mask[1] { 0 } else { 0x07e0 })
            | (if mask[2] { 0 } else { 0x001f });
        let params = TargetParams {
            mask,
            keep8,
            keep565,
            blend,
            blend_fns: blend.map(BlendFns::new),
            blend_color: fragment.blend_color,
            constant8: fragment.blend_color.map(|c| float_to_unorm(c, 8) as u16),
            logic_op: fragment.logic_op,
            dither: fragment.dither,
            clamp_float: fragment.clamp_float,
        };
        use BlendEquation::Add;
        use BlendFactor::{One, OneMinusSrcAlpha, SrcAlpha};
        let kind = match format {
            ColorFormat::Unorm8 { .. } => match (fragment.logic_op, blend) {
                (Some(_), _) => Kind::Unorm8LogicOp,
                (None, None) => Kind::Unorm8Store,
                (None, Some(b)) if b.rgb == b.alpha && b.rgb.equation == Add => match (b.rgb.src, b.rgb.dst) {
                    (SrcAlpha, OneMinusSrcAlpha) => Kind::Unorm8BlendSrcAlpha,
                    (One, One) => Kind::Unorm8BlendAdd,
                    (One, OneMinusSrcAlpha) => Kind::Unorm8BlendOneInvSrcAlpha,
                    _ => Kind::Unorm8Blend,
                },
                (None, Some(_)) => Kind::Unorm8Blend,
            },
            ColorFormat::Rgb565 => Kind::Rgb565,
            ColorFormat::Unorm16 { .. } | ColorFormat::Float32 { .. } => Kind::RowsF32,
        };
        TargetKernel { index, kind, params }
    }

    /// Writes the lanes of `live` of a block's colours into the target. Inlined, with every
    /// kernel body, into its caller, which compiles it per SIMD level
    /// (`super::write_block`): one dispatch per block for the colours and every target, and
    /// one jump on the kind per target.
    #[inline(always)]
    pub fn run(&self, band: &mut ColorBand<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
        let p = &self.params;
        match self.kind {
            Kind::Unorm8Store
            | Kind::Unorm8LogicOp
            | Kind::Unorm8BlendSrcAlpha
            | Kind::Unorm8BlendAdd
            | Kind::Unorm8BlendOneInvSrcAlpha => {
                if let ColorBand::Unorm8(px) = band {
                    self.run_colors(px, at, colors, live)
                }
            }
            Kind::Unorm8Blend => unorm8_blend(p, band, at, colors, live),
            Kind::Rgb565 => rgb565(p, band, at, colors, live),
            Kind::RowsF32 => rows_f32(p, band, at, colors, live),
        }
    }

    /// Whether [`Self::run_words`] is this kernel: a unorm8 target whose kernel works on the
    /// source colours as packed words (no blend, the logic op, or a blend with a packed-word
    /// form).
    pub fn takes_words(&self) -> bool {
        matches!(
            self.kind,
            Kind::Unorm8Store
                | Kind::Unorm8LogicOp
                | Kind::Unorm8BlendSrcAlpha
                | Kind::Unorm8BlendAdd
                | Kind::Unorm8BlendOneInvSrcAlpha
        )
    }

    /// Writes the lanes of `live` of a block's source colours into a unorm8 target: the
    /// kernels of [`Self::takes_words`] (any other kind writes nothing). The blends with
    /// GL_ONE_MINUS_SRC_ALPHA take interpolated colours as channel lanes
    /// (`simd::dispatch::blend_channels_inv_src_alpha8`), the rest as packed words
    /// ([`Self::run_words`]). Inlined into its caller's per-level copy, as [`Self::run`].
    #[inline(always)]
    pub fn run_colors(&self, px: &mut [[u8; 4]], at: &BlockAt, colors: &BlockColors, live: u16) {
        use crate::simd::dispatch::blend_channels_inv_src_alpha8;
        let (p, level) = (&self.params, at.level);
        match (colors, self.kind) {
            (BlockColors::Lanes(l), Kind::Unorm8BlendSrcAlpha) => {
                let dst = load8(px, at);
                let words = blend_channels_inv_src_alpha8::<true>(level, &unorm8_channels(level, l), &dst);
                store8(p, px, at, &words, Some(&dst), live)
            }
            (BlockColors::Lanes(l), Kind::Unorm8BlendOneInvSrcAlpha) => {
                let dst = load8(px, at);
                let words = blend_channels_inv_src_alpha8::<false>(level, &unorm8_channels(level, l), &dst);
                store8(p, px, at, &words, Some(&dst), live)
            }
            _ => self.run_words(px, at, &src_words(level, colors), live),
        }
    }

    /// Writes the lanes of `live` of a block's source colours, converted to packed unorm8
    /// words (`src`), into a unorm8 target: the kernels of [`Self::takes_words`] (any other
    /// kind writes nothing). Inlined into its caller's per-level copy, as [`Self::run`].
    #[inline(always)]
    pub fn run_words(&self, px: &mut [[u8; 4]], at: &BlockAt, src: &U32s, live: u16) {
        use crate::simd::dispatch::{add_saturate8, blend_inv_src_alpha8};
        let p = &self.params;
        match self.kind {
            Kind::Unorm8Store => store8(p, px, at, src, None, live),
            Kind::Unorm8LogicOp => {
                if let Some(op) = p.logic_op {
                    let dst = load8(px, at);
                    store8(p, px, at, &logic_lanes(op, src, &dst), Some(&dst), live);
                }
            }
            // GL_SRC_ALPHA or GL_ONE, GL_ONE_MINUS_SRC_ALPHA and GL_FUNC_ADD on RGB and alpha
            // alike, on the packed words as 16-bit lanes (`pmullw`/`pmulhuw`, four pixels per
            // 128-bit vector, the span path's rounding of `mul8` byte for byte).
            Kind::Unorm8BlendSrcAlpha => {
                let dst = load8(px, at);
                store8(p, px, at, &blend_inv_src_alpha8::<true>(at.level, src, &dst), Some(&dst), live);
            }
            Kind::Unorm8BlendOneInvSrcAlpha => {
                let dst = load8(px, at);
                store8(p, px, at, &blend_inv_src_alpha8::<false>(at.level, src, &dst), Some(&dst), live);
            }
            // GL_ONE, GL_ONE and GL_FUNC_ADD on RGB and alpha alike: `mul8(x, 255)` is `x`, so
            // the blend is `min(s + d, 255)` per byte, a saturating byte add.
            Kind::Unorm8BlendAdd => {
                let dst = load8(px, at);
                store8(p, px, at, &add_saturate8(at.level, src, &dst), Some(&dst), live);
            }
            _ => {}
        }
    }
}

impl TargetKernel {
    /// The one pixel value this kernel stores for every fragment of colour `color`, when it
    /// stores it unconditionally: a unorm8 target with every channel written and no blend or
    /// logic op (dither changes nothing on unorm8 targets). The word is [`src_words`]'s, so a
    /// constant fill of it writes the bytes this kernel writes. `None` for any other kernel.
    pub fn constant_pixel(&self, color: [f32; 4]) -> Option<[u8; 4]> {
        match (self.kind, self.params.keep8) {
            (Kind::Unorm8Store, 0) => {
                Some(src_words(crate::simd::current(), &BlockColors::Uniform(color))[0].to_le_bytes())
            }
            _ => None,
        }
    }
}

/// `float_to_unorm(x, 8)` on lanes, branch-free so that it vectorises: the clamp as two
/// selects (NaN and −0 give 0, +∞ gives 1, as there), then the same single-precision
/// product and round-to-nearest-even by adding 2²³.
#[inline(always)]
pub fn unorm8_lanes(x: &F32s) -> U16s {
    const MAGIC: f32 = (1u32 << 23) as f32;
    lanes(|i| {
        let v = x[i];
        let v = if v > 0.0 { v } else { 0.0 };
        let v = if v < 1.0 { v } else { 1.0 };
        ((v * 255.0 + MAGIC).to_bits() - MAGIC.to_bits()) as u16
    })
}

/// A block's colours converted to unorm8 (the span path's `float_to_unorm`) and packed into
/// RGBA words (byte k: channel k), straight from the f32 lanes, in the copy for `level`.
/// Each channel is capped at 1 (`1 < v ? 1 : v`, one `minps` that keeps NaN), scaled and
/// rounded to nearest even by one conversion (`simd::dispatch::round_even_i32`), and the
/// packing clamps below by unsigned saturation (`simd::dispatch::pack_unorm8`): a negative
/// value rounds to a negative integer or 0, NaN and −∞ convert to `i32::MIN`, all of which
/// saturate to 0, as `float_to_unorm` clamps them; in [0, 1] the product lies in [0, 255],
/// where that conversion is the integer `float_to_unorm` gets by adding 2²³. So no `maxps`
/// per channel, and no shifts and ORs to pack.
#[inline(always)]
pub fn src_words(level: Supported, colors: &BlockColors) -> U32s {
    match colors {
        BlockColors::Uniform(c) => {
            let b = |k: usize| float_to_unorm(c[k], 8);
            [b(0) | b(1) << 8 | b(2) << 16 | b(3) << 24; LANES]
        }
        BlockColors::Lanes(l) => lane_words(level, l),
    }
}

/// [`src_words`] of four channel lanes.
#[inline(always)]
fn lane_words(level: Supported, l: &[F32s; 4]) -> U32s {
    pack_unorm8(level, &unorm8_channels(level, l))
}

/// Four channel lanes capped at 1, scaled and rounded to integers: unorm8 values once
/// negative ones are taken as 0 (see [`src_words`]).
#[inline(always)]
fn unorm8_channels(level: Supported, l: &[F32s; 4]) -> [[i32; LANES]; 4] {
    let scaled = |x: &F32s| {
        let capped = lanes(|i| {
            let v = x[i];
            let v = if 1.0 < v { 1.0 } else { v };
            v * 255.0
        });
        round_even_i32(level, &capped)
    };
    [scaled(&l[0]), scaled(&l[1]), scaled(&l[2]), scaled(&l[3])]
}

/// A block's colours as unorm8 channel lanes (the span path's `float_to_unorm`).
#[inline(always)]
fn to_unorm8(colors: &BlockColors) -> [U16s; 4] {
    match colors {
        BlockColors::Uniform(c) => {
            let v = |k: usize| [float_to_unorm(c[k], 8) as u16; LANES];
            [v(0), v(1), v(2), v(3)]
        }
        BlockColors::Lanes(l) => [unorm8_lanes(&l[0]), unorm8_lanes(&l[1]), unorm8_lanes(&l[2]), unorm8_lanes(&l[3])],
    }
}

/// Packs unorm8 channel lanes into RGBA words (byte k: channel k).
#[inline(always)]
fn pack8(c: &[U16s; 4]) -> U32s {
    lanes(|i| c[0][i] as u32 | (c[1][i] as u32) << 8 | (c[2][i] as u32) << 16 | (c[3][i] as u32) << 24)
}

/// Unpacks RGBA words into unorm8 channel lanes.
#[inline(always)]
fn unpack8(w: &U32s) -> [U16s; 4] {
    let channel = |k: usize| map_lanes(w, |v| ((v >> (8 * k)) & 0xff) as u16);
    [channel(0), channel(1), channel(2), channel(3)]
}

/// Loads a unorm8 target's block as packed words.
#[inline(always)]
fn load8(px: &[[u8; 4]], at: &BlockAt) -> U32s {
    map_lanes(&load(px, at), u32::from_le_bytes)
}

/// Stores packed words through the channel mask into the lanes of `live`.
#[inline(always)]
fn store8(p: &TargetParams, px: &mut [[u8; 4]], at: &BlockAt, words: &U32s, old: Option<&U32s>, live: u16) {
    let words = match (p.keep8, old) {
        (0, _) => *words,
        (keep, Some(old)) => lanes(|i| (old[i] & keep) | (words[i] & !keep)),
        (keep, None) => {
            let old = load8(px, at);
            lanes(|i| (old[i] & keep) | (words[i] & !keep))
        }
    };
    store(px, at, &map_lanes(&words, u32::to_le_bytes), live);
}

/// `op(s, d)` on every lane, from the truth table (see `logic_op`).
#[inline(always)]
fn logic_lanes(op: LogicOp, src: &U32s, dst: &U32s) -> U32s {
    let t = op as u32;
    let m = |b: u32| 0u32.wrapping_sub((t >> b) & 1);
    let m = [m(0), m(1), m(2), m(3)];
    lanes(|i| {
        let (s, d) = (src[i], dst[i]);
        (s & d & m[0]) | (s & !d & m[1]) | (!s & d & m[2]) | (!s & !d & m[3])
    })
}

/// `a·b/255` rounded to nearest on lanes (exact for a, b ≤ 255; no u16 overflow).
#[inline(always)]
fn mul8(a: &U16s, b: &U16s) -> U16s {
    lanes(|i| {
        let t = a[i] * b[i] + 128;
        (t + (t >> 8)) >> 8
    })
}

/// A blend factor on channel `k` of unorm8 lanes (the factor codes are
/// `BlendFactor::ALL`'s indices).
#[inline(always)]
fn factor8(f: u8, k: usize, s: &[U16s; 4], d: &[U16s; 4], c: &[u16; 4]) -> U16s {
    let inv = |v: &U16s| map_lanes(v, |x| 255 - x);
    match f {
        0 => [0; LANES],
        1 => [255; LANES],
        2 => s[k],
        3 => inv(&s[k]),
        4 => d[k],
        5 => inv(&d[k]),
        6 => s[3],
        7 => inv(&s[3]),
        8 => d[3],
        9 => inv(&d[3]),
        10 => [c[k]; LANES],
        11 => [255 - c[k]; LANES],
        12 => [c[3]; LANES],
        13 => [255 - c[3]; LANES],
        _ if k == 3 => [255; LANES],
        _ => lanes(|i| s[3][i].min(255 - d[3][i])),
    }
}

/// A blend equation on unorm8 lanes (codes: `BlendEquation::ALL`'s indices).
#[inline(always)]
fn equation8(e: u8, s: &U16s, sf: &U16s, d: &U16s, df: &U16s) -> U16s {
    match e {
        3 => lanes(|i| s[i].min(d[i])),
        4 => lanes(|i| s[i].max(d[i])),
        _ => {
            let (a, b) = (mul8(s, sf), mul8(d, df));
            match e {
                0 => lanes(|i| (a[i] + b[i]).min(255)),
                1 => lanes(|i| a[i].saturating_sub(b[i])),
                _ => lanes(|i| b[i].saturating_sub(a[i])),
            }
        }
    }
}

type FactorFn = fn(usize, &[U16s; 4], &[U16s; 4], &[u16; 4]) -> U16s;
type EquationFn = fn(&U16s, &U16s, &U16s, &U16s) -> U16s;

fn factor_fn<const F: u8>(k: usize, s: &[U16s; 4], d: &[U16s; 4], c: &[u16; 4]) -> U16s {
    factor8(F, k, s, d, c)
}

fn equation_fn<const E: u8>(s: &U16s, sf: &U16s, d: &U16s, df: &U16s) -> U16s {
    equation8(E, s, sf, d, df)
}

const FACTORS: [FactorFn; 15] = [
    factor_fn::<0>,
    factor_fn::<1>,
    factor_fn::<2>,
    factor_fn::<3>,
    factor_fn::<4>,
    factor_fn::<5>,
    factor_fn::<6>,
    factor_fn::<7>,
    factor_fn::<8>,
    factor_fn::<9>,
    factor_fn::<10>,
    factor_fn::<11>,
    factor_fn::<12>,
    factor_fn::<13>,
    factor_fn::<14>,
];

const EQUATIONS: [EquationFn; 5] =
    [equation_fn::<0>, equation_fn::<1>, equation_fn::<2>, equation_fn::<3>, equation_fn::<4>];

/// A blend's factor and equation functions per channel (RGB, RGB, RGB, alpha).
#[derive(Clone, Copy)]
struct BlendFns {
    src: [FactorFn; 4],
    dst: [FactorFn; 4],
    equation: [EquationFn; 4],
}

impl BlendFns {
    fn new(blend: Blend) -> Self {
        let f = |x: BlendFactor| FACTORS[BlendFactor::ALL.iter().position(|&y| y == x).unwrap_or(0)];
        let e = |x: BlendEquation| EQUATIONS[BlendEquation::ALL.iter().position(|&y| y == x).unwrap_or(0)];
        let (src_rgb, src_a) = (f(blend.rgb.src), f(blend.alpha.src));
        let (dst_rgb, dst_a) = (f(blend.rgb.dst), f(blend.alpha.dst));
        let (eq_rgb, eq_a) = (e(blend.rgb.equation), e(blend.alpha.equation));
        BlendFns {
            src: [src_rgb, src_rgb, src_rgb, src_a],
            dst: [dst_rgb, dst_rgb, dst_rgb, dst_a],
            equation: [eq_rgb, eq_rgb, eq_rgb, eq_a],
        }
    }

    #[inline(always)]
    fn blend(&self, s: &[U16s; 4], d: &[U16s; 4], c: &[u16; 4]) -> [U16s; 4] {
        let channel = |k: usize| {
            let sf = (self.src[k])(k, s, d, c);
            let df = (self.dst[k])(k, s, d, c);
            (self.equation[k])(&s[k], &sf, &d[k], &df)
        };
        [channel(0), channel(1), channel(2), channel(3)]
    }
}

/// unorm8 blending with any factors and equations.
#[inline(always)]
fn unorm8_blend(p: &TargetParams, band: &mut ColorBand<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
    let ColorBand::Unorm8(px) = band else { return };
    let Some(fns) = &p.blend_fns else { return };
    let dst_words = load8(px, at);
    let out = fns.blend(&to_unorm8(colors), &unpack8(&dst_words), &p.constant8);
    store8(p, px, at, &pack8(&out), Some(&dst_words), live);
}

/// RGB565: blend on the destination widened to 8 bits (bit replication), dither or
/// truncate to 5/6 bits, logic op on the words, channel masks on the bits.
#[inline(always)]
fn rgb565(p: &TargetParams, band: &mut ColorBand<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
    let ColorBand::Rgb565(px) = band else { return };
    let dst = load(px, at);
    let mut color = to_unorm8(colors);
    if let (Some(fns), None) = (&p.blend_fns, p.logic_op) {
        let widened: [U16s; 4] = [
            map_lanes(&dst, |w| {
                let r = w >> 11;
                (r << 3) | (r >> 2)
            }),
            map_lanes(&dst, |w| {
                let g = (w >> 5) & 0x3f;
                (g << 2) | (g >> 4)
            }),
            map_lanes(&dst, |w| {
                let b = w & 0x1f;
                (b << 3) | (b >> 2)
            }),
            [255; LANES],
        ];
        color = fns.blend(&color, &widened, &p.constant8);
    }
    let mut words: U16s = if p.dither {
        let row_of = |i: usize| &BAYER4[((at.y as u32 + (i >> 2) as u32) & 3) as usize];
        lanes(|i| {
            let m = row_of(i)[((at.x as u32 + (i & 3) as u32) & 3) as usize];
            let r = dither_channel(color[0][i] as u8, 5, m);
            let g = dither_channel(color[1][i] as u8, 6, m);
            let b = dither_channel(color[2][i] as u8, 5, m);
            (r << 11 | g << 5 | b) as u16
        })
    } else {
        lanes(|i| ((color[0][i] >> 3) << 11) | ((color[1][i] >> 2) << 5) | (color[2][i] >> 3))
    };
    if let Some(op) = p.logic_op {
        let out = logic_lanes(op, &map_lanes(&words, u32::from), &map_lanes(&dst, u32::from));
        words = map_lanes(&out, |w| w as u16);
    }
    let keep = p.keep565;
    let words: U16s = lanes(|i| (dst[i] & keep) | (words[i] & !keep));
    store(px, at, &words, live);
}

/// 16-bit unorm and float targets: the span path's f32 stages on each row of the block.
#[inline(always)]
fn rows_f32(p: &TargetParams, band: &mut ColorBand<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
    let ops = TargetOps {
        blend: p.blend.as_ref(),
        logic_op: p.logic_op,
        dither: p.dither,
        blend_color: p.blend_color,
        mask: p.mask,
        clamp_float: p.clamp_float,
    };
    let has_ops = p.dither || p.logic_op.is_some() || p.blend.is_some();
    for r in 0..4 {
        let row_live = (live >> (4 * r)) & 0xf & (at.valid >> (4 * r));
        if row_live == 0 {
            continue;
        }
        // The row's pixels inside the band, from its first column.
        let n = ((at.valid >> (4 * r)) & 0xf).count_ones() as usize;
        let row: [[f32; 4]; 4] = std::array::from_fn(|c| match colors {
            BlockColors::Uniform(v) => *v,
            BlockColors::Lanes(l) => [l[0][4 * r + c], l[1][4 * r + c], l[2][4 * r + c], l[3][4 * r + c]],
        });
        let start = at.base + r * at.width;
        let y = at.y + r as i32;
        if has_ops {
            write_target(band, start, at.x, y, &row[..n], row_live as u64, &ops);
        } else {
            write_colors(band, start, &row[..n], row_live as u64, p.mask, p.clamp_float);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fragment::blend::{blend_unorm8, BlendFunc};

    #[test]
    fn packed_source_words_are_float_to_unorm_at_every_level() {
        // Every step's value and the half-way points between steps a few ulps either side
        // (ties round to even), the ends, values outside [0, 1], ±∞ and NaN, in every channel.
        let mut values = vec![0.0, -0.0, 1.0, 2.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e-45];
        values.extend(crate::fragment::block::unorm8_steps_and_ties());
        for level in crate::simd::Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
            for (n, chunk) in values.chunks(LANES).enumerate() {
                let mut lane_values = [0.25f32; LANES];
                lane_values[..chunk.len()].copy_from_slice(chunk);
                // Channel k reads the values rotated by k lanes, so each channel sees each value.
                let channels: [F32s; 4] =
                    std::array::from_fn(|k| std::array::from_fn(|i| lane_values[(i + k) % LANES]));
                let got = crate::simd::dispatch::run_with(level, |l| src_words(l, &BlockColors::Lanes(channels)));
                for i in 0..LANES {
                    let want = (0..4).fold(0, |w, k| w | float_to_unorm(channels[k][i], 8) << (8 * k));
                    assert_eq!(got[i], want, "chunk {n} lane {i} {level:?}");
                }
            }
        }
    }

    #[test]
    fn lane_blending_equals_the_span_blend_for_every_factor_and_equation() {
        // Every factor pair and equation on 16 lanes of assorted values, separate RGB and
        // alpha functions: byte for byte the span path's integer blend.
        let src: [[u8; 4]; LANES] =
            std::array::from_fn(|i| [(i * 17) as u8, 255 - (i * 13) as u8, (i * 7 + 3) as u8, (i * 16) as u8]);
        let dst: [[u8; 4]; LANES] = std::array::from_fn(|i| [(i * 5) as u8, (i * 29) as u8, 200, 255 - (i * 11) as u8]);
        let constant = [51u8, 102, 153, 204];
        let lanes = |p: &[[u8; 4]; LANES]| -> [U16s; 4] { std::array::from_fn(|k| p.map(|c| c[k] as u16)) };
        for (n, &src_f) in BlendFactor::ALL.iter().enumerate() {
            for &dst_f in &BlendFactor::ALL {
                for &equation in &BlendEquation::ALL {
                    let alpha_f = BlendFactor::ALL[(n + 5) % 15];
                    let blend = Blend {
                        rgb: BlendFunc { src: src_f, dst: dst_f, equation },
                        alpha: BlendFunc { src: alpha_f, dst: dst_f, equation: BlendEquation::ALL[n % 5] },
                    };
                    let mut want = dst;
                    blend_unorm8(&blend, constant, &src, &mut want, 0xffff);
                    let got = BlendFns::new(blend).blend(&lanes(&src), &lanes(&dst), &constant.map(u16::from));
                    for i in 0..LANES {
                        assert_eq!([0, 1, 2, 3].map(|k| got[k][i] as u8), want[i], "{blend:?} lane {i}");
                    }
                }
            }
        }
    }

    #[test]
    fn word_blend_helpers_equal_the_span_blend_for_every_source_destination_and_alpha() {
        // simd::dispatch's 16-bit-lane blends (GL_SRC_ALPHA or GL_ONE with
        // GL_ONE_MINUS_SRC_ALPHA) and saturating add (GL_ONE, GL_ONE) at every level, over
        // every (source, destination, alpha) byte triple: 48 source channels a call.
        use crate::simd::dispatch::{add_saturate8, blend_inv_src_alpha8};
        let func = |src, dst| BlendFunc { src, dst, equation: BlendEquation::Add };
        let blend = |f| Blend { rgb: f, alpha: f };
        let src_alpha = blend(func(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha));
        let one = blend(func(BlendFactor::One, BlendFactor::OneMinusSrcAlpha));
        let add = blend(func(BlendFactor::One, BlendFactor::One));
        let words = |p: &[[u8; 4]; LANES]| p.map(u32::from_le_bytes);
        for level in crate::simd::Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
            for a in 0..=255u8 {
                for d in 0..=255u8 {
                    let dst = [[d, d, d, d]; LANES];
                    for s0 in (0..256).step_by(48) {
                        let src: [[u8; 4]; LANES] = std::array::from_fn(|i| {
                            let c = |k: usize| (s0 + 3 * i + k) as u8;
                            [c(0), c(1), c(2), a]
                        });
                        let (s, dw) = (words(&src), words(&dst));
                        let got = crate::simd::dispatch::run_with(level, |l| {
                            [
                                blend_inv_src_alpha8::<true>(l, &s, &dw),
                                blend_inv_src_alpha8::<false>(l, &s, &dw),
                                add_saturate8(l, &s, &dw),
                            ]
                        });
                        for (got, b) in got.iter().zip([src_alpha, one, add]) {
                            let mut want = dst;
                            blend_unorm8(&b, [0; 4], &src, &mut want, 0xffff);
                            assert_eq!(*got, words(&want), "{b:?} a {a} d {d} s0 {s0} {level:?}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn word_blends_equal_the_span_blend_for_every_source_alpha_and_destination() {
        // The packed-word kernels (GL_SRC_ALPHA/GL_ONE_MINUS_SRC_ALPHA, GL_ONE/GL_ONE) and the
        // generic one (GL_ONE/GL_ONE_MINUS_SRC_ALPHA) against the span path's integer blend,
        // every source value and alpha with destinations in steps of 3, through a channel
        // mask and a partial live mask.
        let pairs = [(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha), (BlendFactor::One, BlendFactor::One)];
        let pairs = pairs.into_iter().chain([(BlendFactor::One, BlendFactor::OneMinusSrcAlpha)]);
        for (src_f, dst_f) in pairs {
            for mask in [[true; 4], [true, false, true, true]] {
                let func = BlendFunc { src: src_f, dst: dst_f, equation: BlendEquation::Add };
                let blend = Blend { rgb: func, alpha: func };
                let mut state = FragmentState::plain(None, vec![Some(mask)], false);
                state.blend = vec![Some(blend)];
                let kernel = TargetKernel::new(&state, 0, ColorFormat::Unorm8 { alpha: true }, mask);
                let at = BlockAt { x: 0, y: 0, base: 0, width: 4, valid: 0xffff, level: crate::simd::current() };
                let live = 0xfeff;
                for a in 0..=255u32 {
                    for d in (0..=255u32).step_by(3) {
                        for s0 in (0..256u32).step_by(16) {
                            let src: [[u8; 4]; LANES] = std::array::from_fn(|i| {
                                let s = s0 + i as u32;
                                [s as u8, (255 - s) as u8, (s ^ d) as u8, a as u8]
                            });
                            let dst: [[u8; 4]; LANES] = std::array::from_fn(|i| {
                                [d as u8, (d + 7 * i as u32) as u8, (255 - d) as u8, (d ^ a) as u8]
                            });
                            let colors = BlockColors::Lanes(std::array::from_fn(|k| src.map(|c| c[k] as f32 / 255.0)));
                            assert!(src
                                .iter()
                                .all(|c| c.iter().all(|&v| float_to_unorm(v as f32 / 255.0, 8) == v as u32)));
                            let mut want = dst;
                            let mut blended = dst;
                            blend_unorm8(&blend, [0; 4], &src, &mut blended, 0xffff);
                            for i in 0..LANES {
                                if live & (1 << i) != 0 {
                                    for k in 0..4 {
                                        if mask[k] {
                                            want[i][k] = blended[i][k];
                                        }
                                    }
                                }
                            }
                            let mut got = dst;
                            kernel.run(&mut ColorBand::Unorm8(&mut got), &at, &colors, live);
                            assert_eq!(got, want, "{src_f:?} {dst_f:?} a {a} d {d} s0 {s0}");
                        }
                    }
                }
            }
        }
    }
}
