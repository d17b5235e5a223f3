//! Pixel rectangles (glBitmap, glDrawPixels): the job such an image becomes (placed at the
//! raster position and scaled by the pixel zoom), and how it renders inside one tile: its
//! fragments go through the same fragment pipeline as primitives (one depth, one set of
//! varyings for the whole rectangle); stencil and depth/stencil images are written
//! straight to the buffer.
//!
//! Window pixel (x, y) takes image pixel (⌊(x + ½ − x_r) / zoom_x⌋, ⌊(y + ½ − y_r) / zoom_y⌋)
//! when that lies inside the image: the fragments are the pixels whose centres lie in the
//! zoomed image's rectangle (left and bottom edges included), which also handles negative
//! zooms (the image then extends left of or below the raster position).
use crate::fragment::pipeline::{shade_span, DrawState, Scratch, Span};
use crate::fragment::MAX_SPAN;
use crate::framebuffer::band::{Band, DepthBand};
use crate::framebuffer::format::DepthEncoding::{Float, Unorm};
use crate::framebuffer::Rect;
use crate::gl::float::ceil_f64_to_i32;
use std::sync::Arc;

/// What a pixel rectangle's fragments hold.
#[derive(Clone, Debug)]
pub enum PixelSource {
    /// glBitmap: a fragment of `color` where a bit is set (`bits[row * width + col]`).
    Bitmap { bits: Arc<Vec<bool>>, color: [f32; 4] },
    /// glDrawPixels of colors: one color per image pixel, rows bottom-up.
    Colors(Arc<Vec<[f32; 4]>>),
    /// glDrawPixels of depths: one window depth per image pixel, fragments of `color`.
    Depths { depths: Arc<Vec<f32>>, color: [f32; 4] },
    /// glDrawPixels of stencil indices: written straight to the stencil buffer under
    /// `write_mask` (only the scissor box limits them; no fragment tests apply).
    Stencil { values: Arc<Vec<u8>>, write_mask: u8 },
    /// glDrawPixels of GL_DEPTH_STENCIL: depths (when `depth_write`) and stencil indices
    /// (under `stencil_mask`) written straight to the buffer, as Mesa does (only the scissor
    /// box limits them; no fragment tests, no color).
    DepthStencil { depths: Arc<Vec<f32>>, stencil: Arc<Vec<u8>>, depth_write: bool, stencil_mask: u8 },
}

/// A pixel rectangle ready for rasterization.
#[derive(Clone, Debug)]
pub struct PixelRectJob {
    /// The window pixels it may cover.
    pub rect: Rect,
    /// Lower-left corner of the image in window coordinates (x_r, y_r).
    pub origin: [f64; 2],
    pub zoom: [f64; 2],
    pub width: usize,
    pub height: usize,
    pub z: f32,
    pub varyings: Vec<f32>,
    pub source: PixelSource,
}

/// The image column (or row) window column `x` takes, if any.
#[inline]
fn image_index(x: i32, origin: f64, zoom: f64, size: usize) -> Option<usize> {
    // For q ≥ 0 truncation is floor, and floor(q) ∈ [0, size) ⇔ q ∈ [0, size) (no libm
    // call per pixel).
    let q = (x as f64 + 0.5 - origin) / zoom;
    (q >= 0.0 && q < size as f64).then_some(q as usize)
}

/// The half-open range of window columns whose centres lie in [`origin`, `origin` + zoom·size)
/// (or the mirrored range for a negative zoom).
pub fn covered_columns(origin: f64, zoom: f64, size: usize) -> (i32, i32) {
    let end = origin + zoom * size as f64;
    let (lo, hi) = if zoom >= 0.0 { (origin, end) } else { (end, origin) };
    (ceil_f64_to_i32(lo - 0.5), ceil_f64_to_i32(hi - 0.5))
}

impl PixelRectJob {
    /// The window rectangle the zoomed image covers.
    pub fn window_rect(origin: [f64; 2], zoom: [f64; 2], width: usize, height: usize) -> Rect {
        let (x0, x1) = covered_columns(origin[0], zoom[0], width);
        let (y0, y1) = covered_columns(origin[1], zoom[1], height);
        Rect { x0, y0, x1, y1 }
    }

    pub fn bounds(&self) -> Rect {
        self.rect
    }

    /// Renders the part of the rectangle inside `area` (within the band) into `band`.
    pub fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.rect);
        if area.is_empty() {
            return;
        }
        let mut columns = [0usize; MAX_SPAN];
        for y in area.y0..area.y1 {
            let Some(row) = image_index(y, self.origin[1], self.zoom[1], self.height) else {
                continue;
            };
            let mut x0 = area.x0;
            while x0 < area.x1 {
                let x1 = (x0 + MAX_SPAN as i32).min(area.x1);
                let n = (x1 - x0) as usize;
                let mut live = 0u64;
                for (k, column) in columns[..n].iter_mut().enumerate() {
                    let Some(col) = image_index(x0 + k as i32, self.origin[0], self.zoom[0], self.width) else {
                        continue;
                    };
                    *column = row * self.width + col;
                    let on = match &self.source {
                        PixelSource::Bitmap { bits, .. } => bits[*column],
                        _ => true,
                    };
                    live |= (on as u64) << k;
                }
                if let PixelSource::Stencil { values, write_mask } = &self.source {
                    let row_start = (y - band.y0) as usize * band.width + x0 as usize;
                    write_stencil(band, row_start, &columns[..n], live, values, *write_mask);
                } else if let PixelSource::DepthStencil { depths, stencil, depth_write, stencil_mask } = &self.source {
                    let row_start = (y - band.y0) as usize * band.width + x0 as usize;
                    if *depth_write {
                        write_depth(band, row_start, &columns[..n], live, depths);
                    }
                    write_stencil(band, row_start, &columns[..n], live, stencil, *stencil_mask);
                } else if live != 0 {
                    let row_start = (y - band.y0) as usize * band.width + x0 as usize;
                    let span = Span { y, x0, n, row_start, front_facing: true };
                    let columns = &columns;
                    shade_span(
                        state,
                        band,
                        scratch,
                        span,
                        live,
                        |k| match &self.source {
                            PixelSource::Depths { depths, .. } => depths[columns[k]],
                            _ => self.z,
                        },
                        |out| match &self.source {
                            PixelSource::Bitmap { color, .. } | PixelSource::Depths { color, .. } => Some(*color),
                            PixelSource::Stencil { .. } | PixelSource::DepthStencil { .. } => None,
                            PixelSource::Colors(colors) => {
                                out.extend(
                                    (0..n).map(|k| if live >> k & 1 != 0 { colors[columns[k]] } else { [0.0; 4] }),
                                );
                                None
                            }
                        },
                        |_, _, out| out.iter_mut().zip(&self.varyings).for_each(|(o, &v)| *o = v),
                    );
                }
                x0 = x1;
            }
        }
    }
}

/// Writes the window depth `depths[columns[k]]` to the depth of pixel `row_start + k` for
/// each live `k`, converted as fragment depths are.
fn write_depth(band: &mut Band<'_>, row_start: usize, columns: &[usize], live: u64, depths: &[f32]) {
    for (k, &column) in columns.iter().enumerate() {
        if live >> k & 1 == 0 {
            continue;
        }
        let z = depths[column];
        let at = row_start + k;
        match &mut band.depth {
            DepthBand::Depth16(px) => px[at] = Unorm(16).encode_fragment(z) as u16,
            DepthBand::Packed24(px) => px[at] = (px[at] & 0xff00_0000) | Unorm(24).encode_fragment(z),
            DepthBand::Depth32(px, _) => px[at] = Unorm(32).encode_fragment(z),
            DepthBand::Float32(px, _) => px[at] = Float.encode_fragment(z),
            DepthBand::None => return,
        }
    }
}

/// Writes `values[columns[k]]` to the stencil of pixel `row_start + k` for each live `k`.
fn write_stencil(band: &mut Band<'_>, row_start: usize, columns: &[usize], live: u64, values: &[u8], write_mask: u8) {
    let mask = write_mask as u32;
    for (k, &column) in columns.iter().enumerate() {
        if live >> k & 1 == 0 {
            continue;
        }
        let v = values[column] as u32;
        match &mut band.depth {
            DepthBand::Packed24(px) => {
                let old = px[row_start + k];
                let stencil = ((old >> 24) & !mask) | (v & mask);
                px[row_start + k] = (old & 0x00ff_ffff) | stencil << 24;
            }
            DepthBand::Depth32(_, Some(s)) | DepthBand::Float32(_, Some(s)) => {
                let old = s[row_start + k] as u32;
                s[row_start + k] = ((old & !mask) | (v & mask)) as u8;
            }
            _ => return,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zoomed_images_cover_the_pixel_centres_inside() {
        assert_eq!(covered_columns(10.0, 1.0, 4), (10, 14));
        assert_eq!(covered_columns(10.5, 1.0, 4), (10, 14), "centre 10.5 lies on the left edge");
        assert_eq!(covered_columns(10.6, 1.0, 4), (11, 15));
        assert_eq!(covered_columns(10.0, 2.5, 2), (10, 15));
        assert_eq!(covered_columns(10.0, -1.0, 3), (7, 10));
        assert_eq!(image_index(10, 10.0, 2.5, 2), Some(0));
        assert_eq!(image_index(12, 10.0, 2.5, 2), Some(1), "12.5 − 10 = 2.5 starts pixel 1");
        assert_eq!(image_index(9, 10.0, -1.0, 3), Some(0));
        assert_eq!(image_index(7, 10.0, -1.0, 3), Some(2));
        assert_eq!(image_index(10, 10.0, -1.0, 3), None);
    }
}
