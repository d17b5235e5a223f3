//! The last per-fragment stages of one color target: blending or the logic op, dither, and
//! the write with the channel mask.
//!
//! Each format has its own path, chosen once per span: 8-bit targets blend with the exact
//! integer path and apply logic ops to the bytes; RGB565 targets read their destination
//! widened to 8 bits (bit replication), blend in 8 bits, reduce to 5/6 bits (truncating,
//! or dithered), and apply logic ops to the packed words; 16-bit and float targets blend
//! in single precision (clamped for the fixed-point 16-bit ones), 16-bit ones apply logic
//! ops to each channel, and float targets ignore the logic op (ARB_color_buffer_float).
//! Dither comes after blending and before the logic op (GL 2.1 §4.1.8–4.1.10).
use super::blend::{blend_f32, blend_unorm8, Blend};
use super::dither::dither_rgb565;
use super::logic_op::{logic_op_u16, logic_op_unorm8, LogicOp};
use super::{span_mask, write_colors, MAX_SPAN};
use crate::framebuffer::band::ColorBand;
use crate::framebuffer::format::float_to_unorm;

/// What one target does to a span's colors beyond the plain write.
#[derive(Clone, Copy, Debug)]
pub struct TargetOps<'a> {
    pub blend: Option<&'a Blend>,
    pub logic_op: Option<LogicOp>,
    /// Dither (only RGB565 targets are dithered).
    pub dither: bool,
    pub blend_color: [f32; 4],
    pub mask: [bool; 4],
    pub clamp_float: bool,
}

/// Blends (or logic-ops), dithers and writes `colors[i]` for every bit `i` of `live` to the
/// pixels of `target` from `row_start`, which is window pixel (`x0`, `y`).
pub fn write_target(
    target: &mut ColorBand<'_>,
    row_start: usize,
    x0: i32,
    y: i32,
    colors: &[[f32; 4]],
    live: u64,
    ops: &TargetOps<'_>,
) {
    // One copy, SSE2's, at every level (`crate::simd::dispatch::baseline`): this span path
    // is the rare one (lines, points, pixel rectangles and float targets), its spans are
    // short, and its SSE4.1 and AVX2 copies were 120 KB and 96 KB of each library.
    crate::simd::dispatch::baseline(
        #[inline(always)]
        |_| {
            let n = colors.len().min(MAX_SPAN);
            let colors = &colors[..n];
            let mask = ops.mask;
            match target {
                ColorBand::Unorm8(px) => {
                    let px = &mut px[row_start..row_start + n];
                    let mut src = [[0u8; 4]; MAX_SPAN];
                    to_unorm8(colors, &mut src);
                    let mut out = [[0u8; 4]; MAX_SPAN];
                    out[..n].copy_from_slice(px);
                    if let Some(op) = ops.logic_op {
                        logic_op_unorm8(op, &src[..n], &mut out[..n], live);
                    } else if let Some(blend) = ops.blend {
                        blend_unorm8(blend, constant_unorm8(ops.blend_color), &src[..n], &mut out[..n], live);
                    } else {
                        out[..n].copy_from_slice(&src[..n]);
                    }
                    if mask == [true; 4] && live == span_mask(n) {
                        px.copy_from_slice(&out[..n]);
                    } else {
                        for_live(live, n, |i| (0..4).filter(|&k| mask[k]).for_each(|k| px[i][k] = out[i][k]));
                    }
                }
                ColorBand::Rgb565(px) => {
                    let px = &mut px[row_start..row_start + n];
                    let mut color = [[0u8; 4]; MAX_SPAN];
                    to_unorm8(colors, &mut color);
                    if let (Some(blend), None) = (ops.blend, ops.logic_op) {
                        let mut dst = [[0u8; 4]; MAX_SPAN];
                        for (d, &w) in dst.iter_mut().zip(px.iter()) {
                            *d = widen_565(w);
                        }
                        blend_unorm8(blend, constant_unorm8(ops.blend_color), &color[..n], &mut dst[..n], live);
                        color = dst;
                    }
                    let mut words = [0u16; MAX_SPAN];
                    if ops.dither {
                        dither_rgb565(x0 as u32, y as u32, &color[..n], &mut words[..n]);
                    } else {
                        for (w, c) in words.iter_mut().zip(&color[..n]) {
                            *w = ((c[0] as u16 >> 3) << 11) | ((c[1] as u16 >> 2) << 5) | (c[2] as u16 >> 3);
                        }
                    }
                    if let Some(op) = ops.logic_op {
                        let mut dst = [0u16; MAX_SPAN];
                        dst[..n].copy_from_slice(px);
                        logic_op_u16(op, &words[..n], &mut dst[..n], live);
                        words = dst;
                    }
                    let keep: u16 = (if mask[0] { 0 } else { 0xf800 })
                        | (if mask[1] { 0 } else { 0x07e0 })
                        | (if mask[2] { 0 } else { 0x001f });
                    for_live(live, n, |i| px[i] = (px[i] & keep) | (words[i] & !keep));
                }
                ColorBand::Unorm16(px) => {
                    let px = &mut px[row_start..row_start + n];
                    let mut out = [[0u16; 4]; MAX_SPAN];
                    if let Some(op) = ops.logic_op {
                        let mut src = [0u16; 4 * MAX_SPAN];
                        let mut dst = [0u16; 4 * MAX_SPAN];
                        for i in 0..n {
                            for k in 0..4 {
                                src[4 * i + k] = float_to_unorm(colors[i][k], 16) as u16;
                                dst[4 * i + k] = px[i][k];
                            }
                        }
                        // Each pixel's four channels are live together.
                        for (i, o) in out[..n].iter_mut().enumerate() {
                            let word_live = if live & (1 << i) != 0 { 0xf } else { 0 };
                            let (s, d) = (&src[4 * i..4 * i + 4], &mut dst[4 * i..4 * i + 4]);
                            logic_op_u16(op, s, d, word_live);
                            o.copy_from_slice(d);
                        }
                    } else if let Some(blend) = ops.blend {
                        let mut dst = [[0f32; 4]; MAX_SPAN];
                        for (d, p) in dst.iter_mut().zip(px.iter()) {
                            *d = p.map(|v| v as f32 / 65535.0);
                        }
                        blend_f32(blend, ops.blend_color, colors, &mut dst[..n], live, true);
                        for (o, d) in out.iter_mut().zip(&dst[..n]) {
                            *o = d.map(|x| float_to_unorm(x, 16) as u16);
                        }
                    } else {
                        return write_colors(target, row_start, colors, live, mask, ops.clamp_float);
                    }
                    for_live(live, n, |i| (0..4).filter(|&k| mask[k]).for_each(|k| px[i][k] = out[i][k]));
                }
                ColorBand::Float32(px) => {
                    // Logic ops do not apply to float buffers.
                    let Some(blend) = ops.blend else {
                        return write_colors(target, row_start, colors, live, mask, ops.clamp_float);
                    };
                    let px = &mut px[row_start..row_start + n];
                    let mut src = [[0f32; 4]; MAX_SPAN];
                    for (s, c) in src.iter_mut().zip(colors) {
                        *s = if ops.clamp_float { c.map(|x| if x > 0.0 { x.min(1.0) } else { 0.0 }) } else { *c };
                    }
                    let mut dst = [[0f32; 4]; MAX_SPAN];
                    dst[..n].copy_from_slice(px);
                    blend_f32(blend, ops.blend_color, &src[..n], &mut dst[..n], live, false);
                    for_live(live, n, |i| (0..4).filter(|&k| mask[k]).for_each(|k| px[i][k] = dst[i][k]));
                }
            }
        },
    )
}

/// Calls `f(i)` for every bit `i < n` of `live`.
#[inline(always)]
fn for_live(live: u64, n: usize, mut f: impl FnMut(usize)) {
    let mut bits = live & span_mask(n);
    while bits != 0 {
        f(bits.trailing_zeros() as usize);
        bits &= bits - 1;
    }
}

#[inline(always)] // into the per-level copies of write_target (crate::simd)
fn to_unorm8(colors: &[[f32; 4]], out: &mut [[u8; 4]; MAX_SPAN]) {
    for (o, c) in out.iter_mut().zip(colors) {
        *o = c.map(|x| float_to_unorm(x, 8) as u8);
    }
}

fn constant_unorm8(c: [f32; 4]) -> [u8; 4] {
    c.map(|x| float_to_unorm(x, 8) as u8)
}

/// An RGB565 word widened to 8-bit channels by bit replication, alpha 255.
#[inline]
fn widen_565(w: u16) -> [u8; 4] {
    let (r, g, b) = ((w >> 11) as u8, ((w >> 5) & 0x3f) as u8, (w & 0x1f) as u8);
    [(r << 3) | (r >> 2), (g << 2) | (g >> 4), (b << 3) | (b >> 2), 255]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fragment::blend::{BlendEquation, BlendFactor, BlendFunc};

    fn ops(blend: Option<&Blend>, logic_op: Option<LogicOp>, dither: bool) -> TargetOps<'_> {
        TargetOps { blend, logic_op, dither, blend_color: [0.0; 4], mask: [true; 4], clamp_float: true }
    }

    const HALF: Blend = Blend {
        rgb: BlendFunc { src: BlendFactor::SrcAlpha, dst: BlendFactor::OneMinusSrcAlpha, equation: BlendEquation::Add },
        alpha: BlendFunc { src: BlendFactor::One, dst: BlendFactor::Zero, equation: BlendEquation::Add },
    };

    #[test]
    fn unorm8_blend_reads_the_destination_and_honours_live_and_mask() {
        let mut px = [[200u8, 100, 0, 255]; 3];
        let src = [[0.0, 0.0, 1.0, 0.5]; 3];
        let mut o = ops(Some(&HALF), None, false);
        o.mask = [true, true, true, false];
        write_target(&mut ColorBand::Unorm8(&mut px), 0, 0, 0, &src, 0b101, &o);
        // 128/255 of source: 200·127/255 = 99.6 → 100, 100·127/255 → 50, 255·128/255 = 128.
        assert_eq!(px, [[100, 50, 128, 255], [200, 100, 0, 255], [100, 50, 128, 255]]);
    }

    #[test]
    fn logic_op_replaces_blending() {
        let mut px = [[0x0fu8, 0xf0, 0xff, 0x00]];
        let src = [[1.0, 1.0, 0.0, 1.0]];
        write_target(&mut ColorBand::Unorm8(&mut px), 0, 0, 0, &src, 1, &ops(Some(&HALF), Some(LogicOp::Xor), false));
        assert_eq!(px, [[0xf0, 0x0f, 0xff, 0xff]]);
    }

    #[test]
    fn rgb565_dithers_after_blending_and_before_the_logic_op() {
        // 132 on every channel at (0, 1): the pattern of dither.rs's test, green 33, 32, 33, 33.
        let v = 132.0 / 255.0;
        let mut px = [0u16; 4];
        write_target(&mut ColorBand::Rgb565(&mut px), 0, 0, 1, &[[v, v, v, 1.0]; 4], 0b1111, &ops(None, None, true));
        let w = |r: u16, g: u16, b: u16| r << 11 | g << 5 | b;
        assert_eq!(px, [w(16, 33, 16), w(16, 32, 16), w(16, 33, 16), w(16, 33, 16)]);
        let mut px = [0xffffu16; 2];
        let o = ops(None, Some(LogicOp::Xor), true);
        write_target(&mut ColorBand::Rgb565(&mut px), 0, 0, 1, &[[v, v, v, 1.0]; 2], 0b11, &o);
        assert_eq!(px, [!w(16, 33, 16), !w(16, 32, 16)]);
        // Blending reads the widened destination: white · (1 − 1/2) + black · 1/2.
        let mut px = [0xffffu16];
        write_target(
            &mut ColorBand::Rgb565(&mut px),
            0,
            0,
            0,
            &[[0.0, 0.0, 0.0, 0.5]],
            1,
            &ops(Some(&HALF), None, false),
        );
        // 255·127/255 = 127: 127 >> 3 = 15, 127 >> 2 = 31.
        assert_eq!(px, [w(15, 31, 15)]);
    }

    #[test]
    fn float_targets_blend_unclamped_and_ignore_logic_ops() {
        let mut px = [[2.0f32, 0.5, 0.0, 1.0]];
        let add = Blend {
            rgb: BlendFunc { src: BlendFactor::One, dst: BlendFactor::One, equation: BlendEquation::Add },
            alpha: BlendFunc { src: BlendFactor::One, dst: BlendFactor::One, equation: BlendEquation::Add },
        };
        let mut o = ops(Some(&add), Some(LogicOp::Clear), false);
        o.clamp_float = false;
        o.logic_op = None;
        write_target(&mut ColorBand::Float32(&mut px), 0, 0, 0, &[[1.5, 0.25, 0.0, 1.0]], 1, &o);
        assert_eq!(px, [[3.5, 0.75, 0.0, 2.0]]);
        let o = ops(None, Some(LogicOp::Clear), false);
        write_target(&mut ColorBand::Float32(&mut px), 0, 0, 0, &[[0.5, 0.5, 0.5, 0.5]], 1, &o);
        assert_eq!(px, [[0.5; 4]]);
    }

    #[test]
    fn unorm16_logic_op_per_channel() {
        let mut px = [[0xffffu16, 0, 0x1234, 0xffff], [7, 7, 7, 7]];
        let o = ops(None, Some(LogicOp::Xor), false);
        write_target(&mut ColorBand::Unorm16(&mut px), 0, 0, 0, &[[1.0, 1.0, 0.0, 0.0]; 2], 0b01, &o);
        assert_eq!(px, [[0, 0xffff, 0x1234, 0xffff], [7, 7, 7, 7]]);
    }
}
