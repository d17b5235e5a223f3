//! glBlitFramebuffer's arithmetic: which source pixels each destination pixel reads, and the
//! copies of color, depth and stencil between buffers of any size and format.
//!
//! A blit maps the destination rectangle onto the source rectangle axis by axis; either may
//! be inverted (mirroring). The centre of destination pixel `d` maps to the source coordinate
//! `s0 + (d + ½ − d0) · (s1 − s0) / (d1 − d0)`; NEAREST reads the pixel containing it, LINEAR
//! weighs the two pixels whose centres surround it (clamped to the read buffer's edge, as a
//! texture fetch with CLAMP_TO_EDGE). Destination pixels whose centre maps outside the read
//! buffer are not written, with either filter (GL leaves their value undefined; Mesa clips
//! the rectangles to the read buffer, which leaves them unwritten too).
//!
//! The source is read where it lives ([`ColorSource::in_place`], a multisampled layer
//! resolved as it is read); only a blit within one buffer whose rectangles overlap needs a
//! copy of what it reads from before it writes, and that copy holds just the source
//! rectangle (and the one-pixel margin LINEAR may weigh), in the buffer's own format
//! ([`ColorSource::snapshot`]). An unscaled NEAREST blit between unorm8 buffers of one format
//! (MuJoCo's per-frame multisample resolve) copies bytes: the general path's u8 → f32 → u8
//! round trip is the identity (a test checks every value), so the bytes are the same.
use super::layers::{color_buffer, depth_stencil_buffer};
use super::multisample::resolve_color_span;
use super::surface::{ColorPixels, DepthStencilPixels};
use super::{ColorBuffer, ColorFormat, DepthStencilBuffer, OutOfMemory, Rect};
use crate::gl::float::floor_f64;

/// One axis of a blit: source edges `src0`, `src1` and destination edges `dst0`, `dst1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlitAxis {
    pub src0: i32,
    pub src1: i32,
    pub dst0: i32,
    pub dst1: i32,
}

impl BlitAxis {
    /// The destination pixels written, `[min(dst0, dst1), max(dst0, dst1))`.
    pub fn dst_range(&self) -> (i32, i32) {
        (self.dst0.min(self.dst1), self.dst0.max(self.dst1))
    }

    /// Whether source and destination have the same size and direction (a plain copy).
    pub fn is_copy(&self) -> bool {
        wide(self.src1) - wide(self.src0) == wide(self.dst1) - wide(self.dst0)
    }

    /// Whether source and destination have the same size, in either direction.
    pub fn is_unscaled(&self) -> bool {
        (wide(self.src1) - wide(self.src0)).abs() == (wide(self.dst1) - wide(self.dst0)).abs()
    }

    /// The source coordinate of the centre of destination pixel `d`.
    pub fn source_coord(&self, d: i32) -> f64 {
        let scale = (self.src1 - self.src0) as f64 / (self.dst1 - self.dst0) as f64;
        self.src0 as f64 + (d as f64 + 0.5 - self.dst0 as f64) * scale
    }

    /// The source pixel NEAREST reads for destination pixel `d`.
    pub fn nearest(&self, d: i32) -> i32 {
        if self.is_copy() {
            return saturate(wide(d) - wide(self.dst0) + wide(self.src0));
        }
        floor_f64(self.source_coord(d)) as i32
    }

    /// The two source pixels LINEAR weighs for destination pixel `d` and the weight of the
    /// second, both clamped to `[lo, hi)`.
    pub fn linear(&self, d: i32, lo: i32, hi: i32) -> (i32, i32, f32) {
        let s = self.source_coord(d) - 0.5;
        let i = floor_f64(s);
        let weight = (s - i) as f32;
        let i = i as i32;
        (i.clamp(lo, hi - 1), (i + 1).clamp(lo, hi - 1), weight)
    }
}

/// `v` widened, so that sums and differences of any two blit coordinates (any GLint, and
/// the fuzzer finds the extremes) do not overflow.
fn wide(v: i32) -> i64 {
    i64::from(v)
}

/// `v` clamped to the `i32` range: a coordinate beyond it is outside every buffer either way.
fn saturate(v: i64) -> i32 {
    v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

/// The destination pixels of a blit: its rectangle cut by `clip` (bounds and scissor).
pub fn destination(x: BlitAxis, y: BlitAxis, clip: Rect) -> Rect {
    let (x0, x1) = x.dst_range();
    let (y0, y1) = y.dst_range();
    Rect { x0, y0, x1, y1 }.intersect(clip)
}

/// The source pixels a blit may read: its source rectangle widened by one pixel (LINEAR's
/// second texel and clamped neighbours), within the read buffer's `bounds`.
pub fn source_area(x: BlitAxis, y: BlitAxis, bounds: Rect) -> Rect {
    let widen = |a: BlitAxis| (a.src0.min(a.src1).saturating_sub(1), a.src0.max(a.src1).saturating_add(1));
    let ((x0, x1), (y0, y1)) = (widen(x), widen(y));
    Rect { x0, y0, x1, y1 }.intersect(bounds)
}

/// A buffer read where it lives, or a copy owned by the source.
enum Held<'a, T> {
    Borrowed(&'a T),
    Owned(T),
}

impl<T> Held<'_, T> {
    fn get(&self) -> &T {
        match self {
            Held::Borrowed(b) => b,
            Held::Owned(b) => b,
        }
    }
}

/// Where a color blit reads: a read framebuffer of `width` × `height` pixels whose pixel
/// `(x, y)` is pixel `(x − origin.x, y − origin.y)` of `buffer`, which holds `samples`
/// samples per pixel (storage rows as in [`super::multisample`]; resolved as read).
pub struct ColorSource<'a> {
    width: i32,
    height: i32,
    buffer: Held<'a, ColorBuffer>,
    origin: (i32, i32),
    samples: usize,
}

impl<'a> ColorSource<'a> {
    /// The color buffer of a `width` × `height` read framebuffer (`samples` per pixel), read
    /// in place.
    pub fn in_place(buffer: &'a ColorBuffer, samples: usize, width: usize, height: usize) -> ColorSource<'a> {
        let (width, height) = (width as i32, height as i32);
        ColorSource { width, height, buffer: Held::Borrowed(buffer), origin: (0, 0), samples: samples.max(1) }
    }

    /// A copy of `area` ([`source_area`]) of such a buffer, resolved if multisampled, in the
    /// buffer's own format: for a blit that writes what it reads.
    pub fn snapshot(
        buffer: &ColorBuffer,
        samples: usize,
        width: usize,
        height: usize,
        area: Rect,
    ) -> Result<ColorSource<'static>, OutOfMemory> {
        let (w, h) = (area.width(), area.height());
        let mut copy = color_buffer(buffer.format(), w, h)?;
        let samples = samples.max(1);
        for row in 0..h {
            let (sx, sy) = (area.x0 as usize, area.y0 as usize + row);
            if samples > 1 {
                resolve_color_span(buffer, samples, (sx, sy), &mut copy, (0, row), w);
            } else {
                copy_color_span(buffer, (sx, sy), &mut copy, (0, row), w);
            }
        }
        let (width, height) = (width as i32, height as i32);
        Ok(ColorSource { width, height, buffer: Held::Owned(copy), origin: (area.x0, area.y0), samples: 1 })
    }

    /// Pixels `[x0, x1)` of row `y` as floats into `out` (cleared first); `scratch` holds a
    /// multisampled row's resolve.
    fn read_row_f32(&self, y: i32, x0: i32, x1: i32, out: &mut Vec<[f32; 4]>, scratch: &mut ColorBuffer) {
        out.clear();
        let buffer = self.buffer.get();
        let (bx0, bx1, by) = (x0 - self.origin.0, x1 - self.origin.0, y - self.origin.1);
        if self.samples == 1 {
            buffer.read_row_f32(by, bx0, bx1, out);
        } else {
            let n = (x1 - x0) as usize;
            resolve_color_span(buffer, self.samples, (bx0 as usize, by as usize), scratch, (0, 0), n);
            scratch.read_row_f32(0, 0, n as i32, out);
        }
    }
}

/// Copies `n` pixels from `(sx, sy)` of `src` to `(dx, dy)` of `dst` (same format).
fn copy_color_span(
    src: &ColorBuffer,
    (sx, sy): (usize, usize),
    dst: &mut ColorBuffer,
    (dx, dy): (usize, usize),
    n: usize,
) {
    fn copy<T: Copy>(s: &[T], d: &mut [T], from: usize, to: usize, n: usize) {
        d[to..to + n].copy_from_slice(&s[from..from + n]);
    }
    let (from, to) = (sy * src.width() + sx, dy * dst.width() + dx);
    match (src.pixels(), dst.pixels_mut()) {
        (ColorPixels::Unorm8(s), ColorPixels::Unorm8(d)) => copy(s, d, from, to, n),
        (ColorPixels::Unorm16(s), ColorPixels::Unorm16(d)) => copy(s, d, from, to, n),
        (ColorPixels::Rgb565(s), ColorPixels::Rgb565(d)) => copy(s, d, from, to, n),
        (ColorPixels::Float32(s), ColorPixels::Float32(d)) => copy(s, d, from, to, n),
        _ => {}
    }
}

/// Blits `src` into `dst` over `rect` (from [`destination`]), NEAREST or LINEAR, converting
/// to `dst`'s format (fixed-point formats clamp). Write masks do not apply to blits.
pub fn blit_color(src: &ColorSource, dst: &mut ColorBuffer, x: BlitAxis, y: BlitAxis, rect: Rect, linear: bool) {
    if !linear && x.is_unscaled() && y.is_unscaled() && copy_unorm8(src, dst, x, y, rect) {
        return;
    }
    blit_color_general(src, dst, x, y, rect, linear);
}

/// The unscaled NEAREST blit between unorm8 buffers of one format, byte for byte (a
/// multisampled source averaged as [`super::multisample::resolve_color`] does); `false`
/// (nothing done) for other formats.
fn copy_unorm8(src: &ColorSource, dst: &mut ColorBuffer, x: BlitAxis, y: BlitAxis, rect: Rect) -> bool {
    let format = dst.format();
    let ColorFormat::Unorm8 { alpha } = format else { return false };
    let buffer = src.buffer.get();
    if buffer.format() != format {
        return false;
    }
    let (ColorPixels::Unorm8(input), dst_width) = (buffer.pixels(), dst.width()) else { return false };
    let ColorPixels::Unorm8(output) = dst.pixels_mut() else { return false };
    // Source column of destination column dx: dx + (src0 − dst0), or mirrored
    // (src0 + dst0 − 1) − dx, as `BlitAxis::nearest` computes for an unscaled axis.
    let forward = x.is_copy();
    let (sx_of, lo, hi) = if forward {
        let offset = wide(x.src0) - wide(x.dst0);
        (-offset, saturate(-offset), saturate(wide(src.width) - offset))
    } else {
        let c = wide(x.src0) + wide(x.dst0) - 1;
        (c, saturate(c - wide(src.width) + 1), saturate(c + 1))
    };
    // Within [lo, hi) the source column is within the source's width.
    let sx = |dx: i32| (if forward { wide(dx) - sx_of } else { sx_of - wide(dx) }) as i32;
    let (dx0, dx1) = (rect.x0.max(lo), rect.x1.min(hi));
    if dx0 >= dx1 {
        return true;
    }
    let n = (dx1 - dx0) as usize;
    let (width, samples) = (buffer.width(), src.samples);
    for dy in rect.y0..rect.y1 {
        let sy = y.nearest(dy);
        if sy < 0 || sy >= src.height {
            continue;
        }
        let to = dy as usize * dst_width + dx0 as usize;
        let out = &mut output[to..to + n];
        // Storage index of sample 0 of the source of dx0.
        let first = (sy - src.origin.1) as usize * samples * width + (sx(dx0) - src.origin.0) as usize;
        match (samples, forward, alpha) {
            (1, true, true) => out.copy_from_slice(&input[first..first + n]),
            (1, ..) => {
                for (k, o) in out.iter_mut().enumerate() {
                    let p = input[if forward { first + k } else { first - k }];
                    *o = if alpha { p } else { [p[0], p[1], p[2], o[3]] };
                }
            }
            _ => {
                // The resolve: each channel's rounded average, (sum + count/2) / count, as
                // `average_unorm` computes it (a shift for the power-of-two counts).
                let (half, shift) = (samples as u32 / 2, samples.trailing_zeros());
                let power_of_two = samples.is_power_of_two();
                for (k, o) in out.iter_mut().enumerate() {
                    let i = if forward { first + k } else { first - k };
                    let mut sum = [half; 4];
                    for s in 0..samples {
                        let p = input[i + s * width];
                        for c in 0..4 {
                            sum[c] += p[c] as u32;
                        }
                    }
                    let mut p = [0u8; 4];
                    for c in 0..4 {
                        p[c] = if power_of_two { sum[c] >> shift } else { sum[c] / samples as u32 } as u8;
                    }
                    *o = if alpha { p } else { [p[0], p[1], p[2], o[3]] };
                }
            }
        }
    }
    true
}

/// Any blit: source rows read as floats (each once per run of destination rows that
/// reads it), filtered, written through the destination's conversion.
fn blit_color_general(src: &ColorSource, dst: &mut ColorBuffer, x: BlitAxis, y: BlitAxis, rect: Rect, linear: bool) {
    let area = source_area(x, y, Rect { x0: 0, y0: 0, x1: src.width, y1: src.height });
    if area.is_empty() {
        return;
    }
    let Ok(mut scratch) = color_buffer(src.buffer.get().format(), if src.samples > 1 { area.width() } else { 0 }, 1)
    else {
        return;
    };
    // The source rows held as floats, `(row, pixels from area.x0)`.
    let mut held = [(i32::MIN, Vec::new()), (i32::MIN, Vec::new())];
    let mut row: Vec<[f32; 4]> = Vec::with_capacity(rect.width());
    for dy in rect.y0..rect.y1 {
        row.clear();
        let mut run_start = rect.x0;
        let flush = |row: &mut Vec<[f32; 4]>, start: i32, dst: &mut ColorBuffer| {
            if !row.is_empty() {
                dst.write_row_f32(dy, start, row, [true; 4]);
                row.clear();
            }
        };
        let sy = y.nearest(dy);
        if sy < 0 || sy >= src.height {
            continue;
        }
        let (y0, y1, wy) = y.linear(dy, 0, src.height);
        let (ra, rb) = if linear { (y0, y1) } else { (sy, sy) };
        if held[0].0 != ra {
            if held[1].0 == ra {
                held.swap(0, 1);
            } else {
                src.read_row_f32(ra, area.x0, area.x1, &mut held[0].1, &mut scratch);
                held[0].0 = ra;
            }
        }
        if held[1].0 != rb {
            src.read_row_f32(rb, area.x0, area.x1, &mut held[1].1, &mut scratch);
            held[1].0 = rb;
        }
        let (bottom_row, top_row) = (&held[0].1, &held[1].1);
        let at = |r: &Vec<[f32; 4]>, sx: i32| r[(sx - area.x0) as usize];
        for dx in rect.x0..rect.x1 {
            let sx = x.nearest(dx);
            if sx < 0 || sx >= src.width {
                flush(&mut row, run_start, dst);
                run_start = dx + 1;
                continue;
            }
            if linear {
                let (x0, x1, wx) = x.linear(dx, 0, src.width);
                let lerp = |a: [f32; 4], b: [f32; 4], w: f32| std::array::from_fn(|c| a[c] + (b[c] - a[c]) * w);
                let bottom = lerp(at(bottom_row, x0), at(bottom_row, x1), wx);
                let top = lerp(at(top_row, x0), at(top_row, x1), wx);
                row.push(lerp(bottom, top, wy));
            } else {
                row.push(at(bottom_row, sx));
            }
        }
        flush(&mut row, run_start, dst);
    }
}

/// Where a depth/stencil blit reads (as [`ColorSource`]; a multisampled layer reads sample 0,
/// as its resolve does).
pub struct DepthStencilSource<'a> {
    width: i32,
    height: i32,
    buffer: Held<'a, DepthStencilBuffer>,
    origin: (i32, i32),
    samples: usize,
}

impl<'a> DepthStencilSource<'a> {
    /// The depth/stencil buffer of a `width` × `height` read framebuffer, read in place.
    pub fn in_place(buffer: &'a DepthStencilBuffer, samples: usize, width: usize, height: usize) -> Self {
        let (width, height) = (width as i32, height as i32);
        DepthStencilSource { width, height, buffer: Held::Borrowed(buffer), origin: (0, 0), samples: samples.max(1) }
    }

    /// A copy of `area` ([`source_area`]) of such a buffer (sample 0 if multisampled).
    pub fn snapshot(
        buffer: &DepthStencilBuffer,
        samples: usize,
        width: usize,
        height: usize,
        area: Rect,
    ) -> Result<DepthStencilSource<'static>, OutOfMemory> {
        let (w, h) = (area.width(), area.height());
        let mut copy = depth_stencil_buffer(buffer.format(), w, h)?;
        let samples = samples.max(1);
        for row in 0..h {
            let from = (area.y0 as usize + row) * samples * buffer.width() + area.x0 as usize;
            copy_depth_stencil_span(buffer, from, &mut copy, row * w, w, (true, true));
        }
        let (width, height) = (width as i32, height as i32);
        Ok(DepthStencilSource { width, height, buffer: Held::Owned(copy), origin: (area.x0, area.y0), samples: 1 })
    }
}

/// Copies depth (`depth`) and/or stencil (`stencil`) of `n` pixels from index `from` of
/// `src` to index `to` of `dst`, as the per-pixel blit writes them; `false` when the
/// formats differ.
fn copy_depth_stencil_span(
    src: &DepthStencilBuffer,
    from: usize,
    dst: &mut DepthStencilBuffer,
    to: usize,
    n: usize,
    (depth, stencil): (bool, bool),
) -> bool {
    let (s, d) = (from..from + n, to..to + n);
    match (src.pixels(), dst.pixels_mut()) {
        (DepthStencilPixels::None, DepthStencilPixels::None) => {}
        (DepthStencilPixels::Depth16(a), DepthStencilPixels::Depth16(b)) => {
            if depth {
                b[d].copy_from_slice(&a[s]);
            }
        }
        (DepthStencilPixels::Packed24(a), DepthStencilPixels::Packed24(b)) => {
            // The parts of the packed word copied: depth in the low 24 bits, stencil above.
            let keep = match (depth, stencil) {
                (true, true) => {
                    b[d].copy_from_slice(&a[s]);
                    return true;
                }
                (true, false) => 0xff00_0000,
                (false, true) => 0x00ff_ffff,
                (false, false) => return true,
            };
            for (b, &a) in b[d].iter_mut().zip(&a[s]) {
                *b = (*b & keep) | (a & !keep);
            }
        }
        (DepthStencilPixels::Depth32(a, sa), DepthStencilPixels::Depth32(b, sb)) => {
            if depth {
                b[d.clone()].copy_from_slice(&a[s.clone()]);
            }
            if let (true, Some(sa), Some(sb)) = (stencil, sa, sb) {
                sb[d].copy_from_slice(&sa[s]);
            }
        }
        _ => return false,
    }
    true
}

/// NEAREST blit of depth (`depth`) and/or stencil (`stencil`) between buffers of the same
/// format; `dst` is `dst_width` pixels wide.
pub fn blit_depth_stencil(
    src: &DepthStencilSource,
    dst: &mut DepthStencilBuffer,
    dst_width: usize,
    x: BlitAxis,
    y: BlitAxis,
    rect: Rect,
    (depth, stencil): (bool, bool),
) {
    let buffer = src.buffer.get();
    // What the source holds: depth unless it has no buffer, stencil in a packed or separate
    // stencil plane (the packed word's top byte is copied as it stands).
    let has_depth = !matches!(buffer.pixels(), DepthStencilPixels::None);
    let has_stencil =
        matches!(buffer.pixels(), DepthStencilPixels::Packed24(_) | DepthStencilPixels::Depth32(_, Some(_)));
    let depth = depth && has_depth;
    let stencil = stencil && has_stencil;
    let (width, samples) = (buffer.width(), src.samples);
    let index = |sx: i32, sy: i32| (sy - src.origin.1) as usize * samples * width + (sx - src.origin.0) as usize;
    let raw_stencil = |i: usize| match buffer.pixels() {
        DepthStencilPixels::Packed24(px) => (px[i] >> 24) as u8,
        DepthStencilPixels::Depth32(_, Some(st)) => st[i],
        _ => 0,
    };
    // An unscaled, unmirrored blit copies runs of whole rows where the formats allow.
    let rows = x.is_copy() && y.is_copy();
    let shift = wide(x.dst0) - wide(x.src0);
    let (lo, hi) = (saturate(shift), saturate(shift + wide(src.width)));
    for dy in rect.y0..rect.y1 {
        let sy = y.nearest(dy);
        if sy < 0 || sy >= src.height {
            continue;
        }
        if rows {
            let (dx0, dx1) = (rect.x0.max(lo), rect.x1.min(hi));
            if dx0 >= dx1 {
                continue;
            }
            let to = dy as usize * dst_width + dx0 as usize;
            let n = (dx1 - dx0) as usize;
            if copy_depth_stencil_span(buffer, index(dx0 - lo, sy), dst, to, n, (depth, stencil)) {
                continue;
            }
        }
        for dx in rect.x0..rect.x1 {
            let sx = x.nearest(dx);
            if sx < 0 || sx >= src.width {
                continue;
            }
            let from = index(sx, sy);
            let to = dy as usize * dst_width + dx as usize;
            match dst.pixels_mut() {
                DepthStencilPixels::None => {}
                DepthStencilPixels::Depth16(px) => {
                    if depth {
                        px[to] = buffer.depth_value(from) as u16;
                    }
                }
                DepthStencilPixels::Packed24(px) => {
                    if depth {
                        px[to] = (px[to] & 0xff00_0000) | buffer.depth_value(from);
                    }
                    if stencil {
                        px[to] = (px[to] & 0x00ff_ffff) | (raw_stencil(from) as u32) << 24;
                    }
                }
                DepthStencilPixels::Depth32(px, st) => {
                    if depth {
                        px[to] = buffer.depth_value(from);
                    }
                    if let (true, Some(st)) = (stencil, st) {
                        st[to] = raw_stencil(from);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::format::{float_to_unorm, unorm_to_float};
    use crate::framebuffer::DepthStencilFormat;

    fn axis(src0: i32, src1: i32, dst0: i32, dst1: i32) -> BlitAxis {
        BlitAxis { src0, src1, dst0, dst1 }
    }

    #[test]
    fn nearest_copies_scales_and_mirrors() {
        let copy = axis(2, 6, 10, 14);
        assert_eq!((10..14).map(|d| copy.nearest(d)).collect::<Vec<_>>(), [2, 3, 4, 5]);
        let double = axis(0, 2, 0, 4);
        assert_eq!((0..4).map(|d| double.nearest(d)).collect::<Vec<_>>(), [0, 0, 1, 1]);
        let half = axis(0, 4, 0, 2);
        assert_eq!((0..2).map(|d| half.nearest(d)).collect::<Vec<_>>(), [1, 3]);
        let mirrored = axis(0, 4, 4, 0);
        assert_eq!(mirrored.dst_range(), (0, 4));
        assert_eq!((0..4).map(|d| mirrored.nearest(d)).collect::<Vec<_>>(), [3, 2, 1, 0]);
        // Inverting both rectangles is no mirror.
        let both = axis(4, 0, 4, 0);
        assert_eq!((0..4).map(|d| both.nearest(d)).collect::<Vec<_>>(), [0, 1, 2, 3]);
    }

    #[test]
    fn linear_weighs_the_two_nearest_centres_and_clamps_at_the_edge() {
        let double = axis(0, 2, 0, 4);
        assert_eq!(double.linear(0, 0, 2), (0, 0, 0.75));
        assert_eq!(double.linear(1, 0, 2), (0, 1, 0.25));
        assert_eq!(double.linear(2, 0, 2), (0, 1, 0.75));
        assert_eq!(double.linear(3, 0, 2), (1, 1, 0.25));
        assert_eq!(axis(0, 4, 0, 4).linear(2, 0, 4), (2, 3, 0.0));
    }

    #[test]
    fn destination_is_cut_by_the_clip_rectangle() {
        let r = destination(axis(0, 8, 8, -2), axis(0, 1, 0, 1), Rect::from_xywh(0, 0, 4, 4));
        assert_eq!(r, Rect { x0: 0, y0: 0, x1: 4, y1: 1 });
    }

    #[test]
    fn color_blits_convert_formats_and_skip_pixels_without_source() {
        let mut src = color_buffer(ColorFormat::Float32 { alpha: true }, 2, 1).unwrap();
        src.write_row_f32(0, 0, &[[2.0, 0.5, -1.0, 1.0], [0.0, 0.25, 1.0, 0.5]], [true; 4]);
        let source = ColorSource::in_place(&src, 1, 2, 1);
        let mut dst = color_buffer(ColorFormat::Unorm8 { alpha: true }, 4, 1).unwrap();
        // Source columns −1..3 onto 0..4: the first and last have no source pixel.
        let x = axis(-1, 3, 0, 4);
        blit_color(&source, &mut dst, x, axis(0, 1, 0, 1), Rect::from_xywh(0, 0, 4, 1), false);
        let ColorPixels::Unorm8(px) = dst.pixels() else { unreachable!() };
        assert_eq!(px, &[[0, 0, 0, 0], [255, 128, 0, 255], [0, 64, 255, 128], [0, 0, 0, 0]]);
    }
    use crate::gl::test_rng::TestRng as Rng;

    /// A `width` × `rows` buffer of `format` filled with random values.
    fn random_buffer(rng: &mut Rng, format: ColorFormat, width: usize, rows: usize) -> ColorBuffer {
        let mut buffer = color_buffer(format, width, rows).unwrap();
        match buffer.pixels_mut() {
            ColorPixels::Unorm8(px) => px.iter_mut().for_each(|p| *p = (rng.next() as u32).to_le_bytes()),
            ColorPixels::Unorm16(px) => px.iter_mut().for_each(|p| *p = [0, 1, 2, 3].map(|_| rng.next() as u16)),
            ColorPixels::Rgb565(px) => px.iter_mut().for_each(|p| *p = rng.next() as u16),
            ColorPixels::Float32(px) => {
                px.iter_mut().for_each(|p| *p = [0, 1, 2, 3].map(|_| (rng.next() % 1000) as f32 / 400.0 - 0.5))
            }
        }
        buffer
    }

    fn unorm8(buffer: &ColorBuffer) -> Vec<[u8; 4]> {
        let ColorPixels::Unorm8(px) = buffer.pixels() else { unreachable!() };
        px.clone()
    }

    /// The blit as it was first written: the whole read buffer as floats (resolved first if
    /// multisampled), every pixel filtered and written through `write_row_f32`.
    fn reference_blit(
        src: &ColorBuffer,
        samples: usize,
        dst: &mut ColorBuffer,
        x: BlitAxis,
        y: BlitAxis,
        rect: Rect,
        linear: bool,
    ) {
        let (w, h) = (src.width() as i32, (src.height() / samples) as i32);
        let mut resolved = color_buffer(src.format(), w as usize, h as usize).unwrap();
        for row in 0..h as usize {
            if samples > 1 {
                resolve_color_span(src, samples, (0, row), &mut resolved, (0, row), w as usize);
            } else {
                copy_color_span(src, (0, row), &mut resolved, (0, row), w as usize);
            }
        }
        let mut all = Vec::new();
        for row in 0..h {
            resolved.read_row_f32(row, 0, w, &mut all);
        }
        let at = |sx: i32, sy: i32| all[(sy * w + sx) as usize];
        for dy in rect.y0..rect.y1 {
            let sy = y.nearest(dy);
            if sy < 0 || sy >= h {
                continue;
            }
            let (y0, y1, wy) = y.linear(dy, 0, h);
            for dx in rect.x0..rect.x1 {
                let sx = x.nearest(dx);
                if sx < 0 || sx >= w {
                    continue;
                }
                let value = if linear {
                    let (x0, x1, wx) = x.linear(dx, 0, w);
                    let lerp = |a: [f32; 4], b: [f32; 4], t: f32| std::array::from_fn(|c| a[c] + (b[c] - a[c]) * t);
                    lerp(lerp(at(x0, y0), at(x1, y0), wx), lerp(at(x0, y1), at(x1, y1), wx), wy)
                } else {
                    at(sx, sy)
                };
                dst.write_row_f32(dy, dx, &[value], [true; 4]);
            }
        }
    }

    /// Random source and destination edges on one axis of a buffer `size` wide: partly
    /// outside the buffer at times, unscaled (`unscaled`) or of any size, either direction.
    fn random_axis(rng: &mut Rng, size: i32, unscaled: bool) -> BlitAxis {
        let n = rng.between(1, size + 3);
        let m = if unscaled { n } else { rng.between(1, 2 * size) };
        let (s0, d0) = (rng.between(-3, size), rng.between(-3, size));
        let (mut a, mut b) = (axis(s0, s0 + n, d0, d0 + m), rng.next() % 4);
        if b & 1 != 0 {
            (a.src0, a.src1) = (a.src1, a.src0);
        }
        b >>= 1;
        if b & 1 != 0 {
            (a.dst0, a.dst1) = (a.dst1, a.dst0);
        }
        a
    }

    #[test]
    fn unorm8_round_trips_exactly_through_the_float_path() {
        // The byte copy of the unscaled unorm8 blit stands for read_row_f32 then
        // write_row_f32: that is the identity on every byte value.
        for v in 0..=255u32 {
            assert_eq!(float_to_unorm(unorm_to_float(v, 8), 8), v);
        }
        let format = ColorFormat::Unorm8 { alpha: true };
        let mut buffer = color_buffer(format, 256, 1).unwrap();
        let ColorPixels::Unorm8(px) = buffer.pixels_mut() else { unreachable!() };
        px.iter_mut().enumerate().for_each(|(i, p)| *p = [i as u8, 255 - i as u8, (i * 7) as u8, (i * 13) as u8]);
        let before = unorm8(&buffer);
        let mut row = Vec::new();
        buffer.read_row_f32(0, 0, 256, &mut row);
        buffer.write_row_f32(0, 0, &row, [true; 4]);
        assert_eq!(unorm8(&buffer), before);
    }

    #[test]
    fn unorm8_copies_and_resolves_give_the_float_paths_bytes() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for round in 0..600 {
            let alpha = round % 3 != 0;
            let format = ColorFormat::Unorm8 { alpha };
            let samples = [1, 2, 4, 8][round % 4];
            let (w, h) = (rng.between(1, 13), rng.between(1, 11));
            let src = random_buffer(&mut rng, format, w as usize, h as usize * samples);
            let (dw, dh) = (rng.between(1, 13) as usize, rng.between(1, 11) as usize);
            let dst = random_buffer(&mut rng, format, dw, dh);
            let (x, y) = (random_axis(&mut rng, w, true), random_axis(&mut rng, h, true));
            let clip = Rect::from_xywh(rng.between(0, 3), rng.between(0, 3), dw as i32, dh as i32);
            let rect = destination(x, y, clip.intersect(Rect::from_xywh(0, 0, dw as i32, dh as i32)));
            if rect.is_empty() {
                continue;
            }
            let source = ColorSource::in_place(&src, samples, w as usize, h as usize);
            let (mut fast, mut general, mut reference) = (dst.clone(), dst.clone(), dst.clone());
            assert!(copy_unorm8(&source, &mut fast, x, y, rect));
            blit_color_general(&source, &mut general, x, y, rect, false);
            reference_blit(&src, samples, &mut reference, x, y, rect, false);
            assert_eq!(unorm8(&general), unorm8(&reference), "round {round}: {x:?} {y:?} {rect:?}");
            assert_eq!(unorm8(&fast), unorm8(&reference), "round {round}: {x:?} {y:?} {rect:?}");
            // A snapshot of the source area reads the same pixels.
            let area = source_area(x, y, Rect::from_xywh(0, 0, w, h));
            let snapshot = ColorSource::snapshot(&src, samples, w as usize, h as usize, area).unwrap();
            let mut copied = dst.clone();
            blit_color(&snapshot, &mut copied, x, y, rect, false);
            assert_eq!(unorm8(&copied), unorm8(&reference), "round {round}");
        }
    }

    #[test]
    fn the_float_path_reads_in_place_and_from_snapshots_as_from_a_whole_copy() {
        let mut rng = Rng(0x0123_4567_89ab_cdef);
        let formats = [
            ColorFormat::Unorm8 { alpha: true },
            ColorFormat::Unorm16 { alpha: false },
            ColorFormat::Rgb565,
            ColorFormat::Float32 { alpha: true },
        ];
        for round in 0..400 {
            let (sf, df) = (formats[round % 4], formats[(round / 4) % 4]);
            let samples = if round % 5 == 0 { 4 } else { 1 };
            let linear = round % 2 == 1;
            let (w, h) = (rng.between(1, 11), rng.between(1, 9));
            let src = random_buffer(&mut rng, sf, w as usize, h as usize * samples);
            let (dw, dh) = (rng.between(1, 14) as usize, rng.between(1, 12) as usize);
            let dst = random_buffer(&mut rng, df, dw, dh);
            let unscaled = round % 3 == 0;
            let (x, y) = (random_axis(&mut rng, w, unscaled), random_axis(&mut rng, h, unscaled));
            let rect = destination(x, y, Rect::from_xywh(0, 0, dw as i32, dh as i32));
            let mut reference = dst.clone();
            reference_blit(&src, samples, &mut reference, x, y, rect, linear);
            let mut in_place = dst.clone();
            blit_color(
                &ColorSource::in_place(&src, samples, w as usize, h as usize),
                &mut in_place,
                x,
                y,
                rect,
                linear,
            );
            let area = source_area(x, y, Rect::from_xywh(0, 0, w, h));
            let snapshot = ColorSource::snapshot(&src, samples, w as usize, h as usize, area).unwrap();
            let mut copied = dst.clone();
            blit_color(&snapshot, &mut copied, x, y, rect, linear);
            let bytes = |b: &ColorBuffer| format!("{:?}", b.pixels());
            assert_eq!(bytes(&in_place), bytes(&reference), "round {round}: {x:?} {y:?}");
            assert_eq!(bytes(&copied), bytes(&reference), "round {round}: {x:?} {y:?}");
        }
    }

    #[test]
    fn an_overlapping_blit_within_one_buffer_reads_the_pixels_from_before_it() {
        let mut rng = Rng(42);
        for round in 0..300 {
            let format = ColorFormat::Unorm8 { alpha: round % 2 == 0 };
            let (w, h) = (rng.between(2, 12), rng.between(2, 10));
            let original = random_buffer(&mut rng, format, w as usize, h as usize);
            let unscaled = round % 2 == 0;
            let (x, y) = (random_axis(&mut rng, w, unscaled), random_axis(&mut rng, h, unscaled));
            let linear = round % 3 == 0;
            let bounds = Rect::from_xywh(0, 0, w, h);
            let rect = destination(x, y, bounds);
            let mut reference = original.clone();
            reference_blit(&original, 1, &mut reference, x, y, rect, linear);
            let mut buffer = original.clone();
            let snapshot =
                ColorSource::snapshot(&buffer, 1, w as usize, h as usize, source_area(x, y, bounds)).unwrap();
            blit_color(&snapshot, &mut buffer, x, y, rect, linear);
            assert_eq!(unorm8(&buffer), unorm8(&reference), "round {round}: {x:?} {y:?}");
        }
    }

    #[test]
    fn depth_stencil_row_copies_match_the_per_pixel_blit() {
        let mut rng = Rng(7);
        let formats = [
            DepthStencilFormat::Packed24 { depth: true, stencil: true },
            DepthStencilFormat::Depth16,
            DepthStencilFormat::Depth32 { stencil: true },
        ];
        for round in 0..300 {
            let format = formats[round % 3];
            let samples = [1, 4][(round / 3) % 2];
            let want = [(true, true), (true, false), (false, true)][(round / 6) % 3];
            let (w, h) = (rng.between(1, 10), rng.between(1, 9));
            let random = |rng: &mut Rng, width: usize, rows: usize| {
                let mut b = depth_stencil_buffer(format, width, rows).unwrap();
                for i in 0..width * rows {
                    b.set_depth_value(i, rng.next() as u32 & 0xffff);
                    b.set_stencil_value(i, rng.next() as u8);
                }
                b
            };
            let src = random(&mut rng, w as usize, h as usize * samples);
            let (dw, dh) = (rng.between(1, 12) as usize, rng.between(1, 10) as usize);
            let dst = random(&mut rng, dw, dh);
            let (x, y) = (random_axis(&mut rng, w, true), random_axis(&mut rng, h, true));
            let rect = destination(x, y, Rect::from_xywh(0, 0, dw as i32, dh as i32));
            // The reference: pixel by pixel from sample 0.
            let mut reference = dst.clone();
            for dy in rect.y0..rect.y1 {
                for dx in rect.x0..rect.x1 {
                    let (sx, sy) = (x.nearest(dx), y.nearest(dy));
                    if sx < 0 || sx >= w || sy < 0 || sy >= h {
                        continue;
                    }
                    let (from, to) =
                        ((sy as usize * samples) * w as usize + sx as usize, dy as usize * dw + dx as usize);
                    if want.0 {
                        reference.set_depth_value(to, src.depth_value(from));
                    }
                    if want.1 {
                        reference.set_stencil_value(to, src.stencil_value(from));
                    }
                }
            }
            let mut in_place = dst.clone();
            let source = DepthStencilSource::in_place(&src, samples, w as usize, h as usize);
            blit_depth_stencil(&source, &mut in_place, dw, x, y, rect, want);
            let area = source_area(x, y, Rect::from_xywh(0, 0, w, h));
            let snapshot = DepthStencilSource::snapshot(&src, samples, w as usize, h as usize, area).unwrap();
            let mut copied = dst.clone();
            blit_depth_stencil(&snapshot, &mut copied, dw, x, y, rect, want);
            let all = |b: &DepthStencilBuffer| {
                (0..dw * dh).map(|i| (b.depth_value(i), b.stencil_value(i))).collect::<Vec<_>>()
            };
            assert_eq!(all(&in_place), all(&reference), "round {round}: {x:?} {y:?} {want:?}");
            assert_eq!(all(&copied), all(&reference), "round {round}");
        }
    }
}
