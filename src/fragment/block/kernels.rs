//! The per-fragment operations of a block as lane kernels: small free functions over
//! `[T; 16]` that LLVM vectorises, chosen once per draw state as function pointers to
//! monomorphised instances (depth/stencil per storage format, blend per factor and
//! equation, stencil per operation), so that nothing is matched per block or pixel.
//!
//! - Depth and stencil: [`super::depth_stencil`].
//! - unorm8 targets: exact integer blending on u16 lanes (`mul_unorm8`), every factor and
//!   equation, separate RGB and alpha, the blend colour; the logic op on the packed words;
//!   channel masks as byte masks. The common factor pairs have their own monomorphised
//!   kernels, the rest call one function pointer per factor and channel.
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

// ---------------------------------------------------------------------------------------
// Colour targets.

type WriteFn = fn(&TargetParams, &mut ColorBand<'_>, &BlockAt, &BlockColors, u16);

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
    run: WriteFn,
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
        let run: WriteFn = match format {
            ColorFormat::Unorm8 { .. } => match (fragment.logic_op, blend) {
                (Some(_), _) => unorm8_logic_op,
                (None, None) => unorm8_store,
                (None, Some(b)) if b.rgb == b.alpha && b.rgb.equation == Add => match (b.rgb.src, b.rgb.dst) {
                    (SrcAlpha, OneMinusSrcAlpha) => unorm8_blend_fixed::<6, 7>,
                    (One, One) => unorm8_blend_fixed::<1, 1>,
                    _ => unorm8_blend,
                },
                (None, Some(_)) => unorm8_blend,
            },
            ColorFormat::Rgb565 => rgb565,
            ColorFormat::Unorm16 { .. } | ColorFormat::Float32 { .. } => rows_f32,
        };
        TargetKernel { index, run, params }
    }

    #[inline(always)]
    pub fn run(&self, band: &mut ColorBand<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
        (self.run)(&self.params, band, at, colors, live)
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

/// unorm8, no blend or logic op: convert and store.
fn unorm8_store(p: &TargetParams, band: &mut ColorBand<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
    crate::simd::per_level!({
        let ColorBand::Unorm8(px) = band else { return };
        let words = match colors {
            BlockColors::Uniform(c) => [u32::from_le_bytes(c.map(|v| float_to_unorm(v, 8) as u8)); LANES],
            _ => pack8(&to_unorm8(colors)),
        };
        store8(p, px, at, &words, None, live);
    })
}

/// unorm8 with the logic op on the packed words.
fn unorm8_logic_op(p: &TargetParams, band: &mut ColorBand<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
    crate::simd::per_level!({
        let ColorBand::Unorm8(px) = band else { return };
        let Some(op) = p.logic_op else { return };
        let src = pack8(&to_unorm8(colors));
        let dst = load8(px, at);
        let words = logic_lanes(op, &src, &dst);
        store8(p, px, at, &words, Some(&dst), live);
    })
}

/// `op(s, d)` on every lane, from the truth table (see `logic_op`).
#[inline(always)]
fn logic_lanes(op: LogicOp, src: &U32s, dst: &U32s) -> U32s {
    let t = op as u32;
    let m = [0, 1, 2, 3].map(|b| 0u32.wrapping_sub((t >> b) & 1));
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
fn unorm8_blend(p: &TargetParams, band: &mut ColorBand<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
    crate::simd::per_level!({
        let ColorBand::Unorm8(px) = band else { return };
        let Some(fns) = &p.blend_fns else { return };
        let dst_words = load8(px, at);
        let out = fns.blend(&to_unorm8(colors), &unpack8(&dst_words), &p.constant8);
        store8(p, px, at, &pack8(&out), Some(&dst_words), live);
    })
}

/// unorm8 blending with one factor pair (codes as [`factor8`]) and GL_FUNC_ADD on RGB and
/// alpha alike: everything inlined.
fn unorm8_blend_fixed<const SRC: u8, const DST: u8>(
    p: &TargetParams,
    band: &mut ColorBand<'_>,
    at: &BlockAt,
    colors: &BlockColors,
    live: u16,
) {
    let ColorBand::Unorm8(px) = band else { return };
    // The whole block's arithmetic is compiled once per SIMD level: one dispatch per block.
    crate::simd::per_level!({
        let dst_words = load8(px, at);
        let (s, d) = (to_unorm8(colors), unpack8(&dst_words));
        let c = &p.constant8;
        let out = [
            fixed_channel::<SRC, DST>(0, &s, &d, c),
            fixed_channel::<SRC, DST>(1, &s, &d, c),
            fixed_channel::<SRC, DST>(2, &s, &d, c),
            fixed_channel::<SRC, DST>(3, &s, &d, c),
        ];
        store8(p, px, at, &pack8(&out), Some(&dst_words), live);
    })
}

#[inline(always)]
fn fixed_channel<const SRC: u8, const DST: u8>(k: usize, s: &[U16s; 4], d: &[U16s; 4], c: &[u16; 4]) -> U16s {
    let sf = factor8(SRC, k, s, d, c);
    let df = factor8(DST, k, s, d, c);
    equation8(0, &s[k], &sf, &d[k], &df)
}

/// RGB565: blend on the destination widened to 8 bits (bit replication), dither or
/// truncate to 5/6 bits, logic op on the words, channel masks on the bits.
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
}
