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
use super::surface::DepthStencilPixels;
use super::{ColorBuffer, DepthStencilBuffer, Rect};
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
        self.src1 - self.src0 == self.dst1 - self.dst0
    }

    /// The source coordinate of the centre of destination pixel `d`.
    pub fn source_coord(&self, d: i32) -> f64 {
        let scale = (self.src1 - self.src0) as f64 / (self.dst1 - self.dst0) as f64;
        self.src0 as f64 + (d as f64 + 0.5 - self.dst0 as f64) * scale
    }

    /// The source pixel NEAREST reads for destination pixel `d`.
    pub fn nearest(&self, d: i32) -> i32 {
        if self.is_copy() {
            return d - self.dst0 + self.src0;
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

/// The destination pixels of a blit: its rectangle cut by `clip` (bounds and scissor).
pub fn destination(x: BlitAxis, y: BlitAxis, clip: Rect) -> Rect {
    let (x0, x1) = x.dst_range();
    let (y0, y1) = y.dst_range();
    Rect { x0, y0, x1, y1 }.intersect(clip)
}

/// The color pixels of a read buffer as floats (a snapshot, so that a blit within one
/// buffer reads the values from before it).
pub struct ColorSource {
    width: i32,
    height: i32,
    pixels: Vec<[f32; 4]>,
}

impl ColorSource {
    /// Reads the whole `buffer` (`width` × `height`).
    pub fn read(buffer: &ColorBuffer, width: usize, height: usize) -> ColorSource {
        let mut pixels = Vec::with_capacity(width * height);
        for y in 0..height as i32 {
            buffer.read_row_f32(y, 0, width as i32, &mut pixels);
        }
        ColorSource { width: width as i32, height: height as i32, pixels }
    }

    fn at(&self, x: i32, y: i32) -> [f32; 4] {
        self.pixels[(y * self.width + x) as usize]
    }
}

/// Blits `src` into `dst` over `rect` (from [`destination`]), NEAREST or LINEAR, converting
/// to `dst`'s format (fixed-point formats clamp). Write masks do not apply to blits.
pub fn blit_color(src: &ColorSource, dst: &mut ColorBuffer, x: BlitAxis, y: BlitAxis, rect: Rect, linear: bool) {
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
                let bottom = lerp(src.at(x0, y0), src.at(x1, y0), wx);
                let top = lerp(src.at(x0, y1), src.at(x1, y1), wx);
                row.push(lerp(bottom, top, wy));
            } else {
                row.push(src.at(sx, sy));
            }
        }
        flush(&mut row, run_start, dst);
    }
}

/// The depth and stencil values of a read buffer (a snapshot, as [`ColorSource`]).
pub struct DepthStencilSource {
    width: i32,
    height: i32,
    depth: Vec<u32>,
    stencil: Vec<u8>,
}

impl DepthStencilSource {
    pub fn read(buffer: &DepthStencilBuffer, width: usize, height: usize) -> DepthStencilSource {
        let (mut depth, mut stencil) = (Vec::new(), Vec::new());
        for y in 0..height as i32 {
            buffer.read_depth_row(y, 0, width as i32, &mut depth);
            buffer.read_stencil_row(y, 0, width as i32, &mut stencil);
        }
        DepthStencilSource { width: width as i32, height: height as i32, depth, stencil }
    }
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
    let depth = depth && !src.depth.is_empty();
    let stencil = stencil && !src.stencil.is_empty();
    for dy in rect.y0..rect.y1 {
        let sy = y.nearest(dy);
        if sy < 0 || sy >= src.height {
            continue;
        }
        for dx in rect.x0..rect.x1 {
            let sx = x.nearest(dx);
            if sx < 0 || sx >= src.width {
                continue;
            }
            let from = (sy * src.width + sx) as usize;
            let to = dy as usize * dst_width + dx as usize;
            match dst.pixels_mut() {
                DepthStencilPixels::None => {}
                DepthStencilPixels::Depth16(px) => {
                    if depth {
                        px[to] = src.depth[from] as u16;
                    }
                }
                DepthStencilPixels::Packed24(px) => {
                    if depth {
                        px[to] = (px[to] & 0xff00_0000) | src.depth[from];
                    }
                    if stencil {
                        px[to] = (px[to] & 0x00ff_ffff) | (src.stencil[from] as u32) << 24;
                    }
                }
                DepthStencilPixels::Depth32(px, st) => {
                    if depth {
                        px[to] = src.depth[from];
                    }
                    if let (true, Some(st)) = (stencil, st) {
                        st[to] = src.stencil[from];
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::layers::color_buffer;
    use crate::framebuffer::surface::ColorPixels;
    use crate::framebuffer::ColorFormat;

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
        let source = ColorSource::read(&src, 2, 1);
        let mut dst = color_buffer(ColorFormat::Unorm8 { alpha: true }, 4, 1).unwrap();
        // Source columns −1..3 onto 0..4: the first and last have no source pixel.
        let x = axis(-1, 3, 0, 4);
        blit_color(&source, &mut dst, x, axis(0, 1, 0, 1), Rect::from_xywh(0, 0, 4, 1), false);
        let ColorPixels::Unorm8(px) = dst.pixels() else { unreachable!() };
        assert_eq!(px, &[[0, 0, 0, 0], [255, 128, 0, 255], [0, 64, 255, 128], [0, 0, 0, 0]]);
    }
}
