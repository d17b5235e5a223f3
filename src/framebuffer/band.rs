//! Bands: disjoint horizontal strips of a framebuffer that rasterizer workers own.
//!
//! A band is one row of tiles (`TILE_SIZE` rows of pixels) of every layer a scene writes:
//! the selected color buffers and the depth/stencil buffer. Bands borrow disjoint slices of
//! the buffers, so worker threads can render different bands at the same time with no
//! locking and no unsafe code; each pixel belongs to exactly one band, which is what makes
//! results identical for any number of threads.
use super::hiz::HiZ;
use super::surface::{ColorPixels, DepthStencilPixels};
use super::{ColorFormat, ColorSlot, DepthStencilFormat, Framebuffer, Rect};

/// The pixels of one color buffer inside a band (rows bottom-up, `width` pixels each).
pub enum ColorBand<'a> {
    Unorm8(&'a mut [[u8; 4]]),
    Rgb565(&'a mut [u16]),
    Unorm16(&'a mut [[u16; 4]]),
    Float32(&'a mut [[f32; 4]]),
}

/// The depth/stencil pixels inside a band.
pub enum DepthBand<'a> {
    None,
    Depth16(&'a mut [u16]),
    Packed24(&'a mut [u32]),
    Depth32(&'a mut [u32], Option<&'a mut [u8]>),
    /// Float depth as bit patterns ([`super::format::DepthEncoding::Float`]), stencil plane.
    Float32(&'a mut [u32], Option<&'a mut [u8]>),
}

/// One color target of a band: the buffer's pixels and its format.
pub struct ColorTarget<'a> {
    pub slot: ColorSlot,
    pub format: ColorFormat,
    pub pixels: ColorBand<'a>,
}

/// A strip of rows `[y0, y0 + rows)` of every layer a scene writes. On a multisampled
/// framebuffer the slices hold every sample of those rows (`multisample.rs`: storage row
/// `(y − y0)·samples + s` is sample `s` of pixel row `y`).
pub struct Band<'a> {
    pub y0: i32,
    pub rows: usize,
    pub width: usize,
    /// Samples per pixel (1: single-sampled).
    pub samples: usize,
    pub colors: Vec<ColorTarget<'a>>,
    pub depth: DepthBand<'a>,
    pub depth_format: DepthStencilFormat,
    /// The depth summary of hierarchical z, kept while the band renders a scene
    /// ([`super::hiz`]): start with `HiZ::default()`.
    pub hiz: HiZ,
}

impl Band<'_> {
    /// The index of sample `sample` of pixel (x, y) (inside the band) in its slices.
    #[inline]
    pub fn sample_index(&self, y: i32, x: i32, sample: usize) -> usize {
        ((y - self.y0) as usize * self.samples + sample) * self.width + x as usize
    }
}

/// Constant fills of a unorm8 colour target of a single-sampled band: the pixels a flat,
/// unconditionally stored primitive covers (`setup::jobs::triangle`), written as rows of
/// one value instead of through the block pipeline's lanes.
impl Band<'_> {
    /// Writes `pixel` to every pixel of `rect` (inside the band) of colour target `target`;
    /// nothing unless that target is unorm8.
    #[inline(always)]
    pub fn fill_unorm8(&mut self, target: usize, rect: Rect, pixel: [u8; 4]) {
        let (width, y0) = (self.width, self.y0);
        let ColorBand::Unorm8(px) = &mut self.colors[target].pixels else { return };
        let (x0, x1) = (rect.x0 as usize, rect.x1 as usize);
        // Eight pixels (32 bytes) per copy, which the compiler makes whole-register stores.
        let wide = [pixel; 8];
        for y in rect.y0..rect.y1 {
            let row = (y - y0) as usize * width;
            let (chunks, rest) = px[row + x0..row + x1].as_chunks_mut::<8>();
            for chunk in chunks {
                *chunk = wide;
            }
            for p in rest {
                *p = pixel;
            }
        }
    }

    /// Writes `pixel` to the pixels `mask` of the 4×4 block at `(x, y)` (bit `i`: pixel
    /// `(x + i % 4, y + i / 4)`, each inside the band) of colour target `target`; nothing
    /// unless that target is unorm8.
    #[inline(always)]
    pub fn fill_block_unorm8(&mut self, target: usize, x: i32, y: i32, mask: u16, pixel: [u8; 4]) {
        let (width, y0) = (self.width, self.y0);
        let ColorBand::Unorm8(px) = &mut self.colors[target].pixels else { return };
        let base = (y - y0) as usize * width + x as usize;
        for row in 0..4 {
            let bits = (mask >> (4 * row)) & 0xf;
            if bits == 0xf {
                let (quad, _) = px[base + row * width..base + row * width + 4].as_chunks_mut::<4>();
                quad[0] = [pixel; 4];
            } else {
                for c in 0..4 {
                    if bits & (1 << c) != 0 {
                        px[base + row * width + c] = pixel;
                    }
                }
            }
        }
    }
}

/// Splits `slice` into chunks of `chunk` elements (the last may be shorter).
fn split<T>(slice: &mut [T], chunk: usize) -> Vec<&mut [T]> {
    slice.chunks_mut(chunk.max(1)).collect()
}

impl Framebuffer {
    /// Splits the color buffers in `slots` (each at most once) and the depth/stencil buffer
    /// into bands of `band_rows` rows.
    pub fn bands(&mut self, band_rows: usize, slots: &[ColorSlot]) -> Vec<Band<'_>> {
        let width = self.width;
        let height = self.height;
        let samples = self.samples();
        let chunk = width * band_rows * samples;
        let count = height.div_ceil(band_rows.max(1));
        let mut bands: Vec<Band<'_>> = (0..count)
            .map(|i| Band {
                y0: (i * band_rows) as i32,
                rows: band_rows.min(height - i * band_rows),
                width,
                samples,
                colors: Vec::new(),
                depth: DepthBand::None,
                depth_format: self.config.depth_stencil,
                hiz: HiZ::default(),
            })
            .collect();
        // Split every selected buffer, then hand the pieces to the bands in `slots` order.
        let mut split_buffers: Vec<(ColorSlot, ColorFormat, Vec<ColorBand<'_>>)> = Vec::new();
        // A multisampled framebuffer renders into its samples (resolved after the scene).
        let (color_layers, depth_layer, mut in_place_front) = match self.multisample.as_mut() {
            Some(layers) => (&mut layers.color, &mut layers.depth_stencil, None),
            None => (&mut self.color, &mut self.depth_stencil, self.in_place_front.as_mut()),
        };
        for (slot, buffer) in color_layers.iter_mut().filter(|(s, _)| slots.contains(s)) {
            let format = buffer.format();
            // The front-left image rendered in place, in the memory it is presented from.
            let in_place = match (*slot, format) {
                (ColorSlot::FrontLeft, ColorFormat::Unorm8 { alpha: true }) => {
                    in_place_front.take().and_then(|b| b.unorm8_pixels_mut(width * height))
                }
                _ => None,
            };
            if let Some(px) = in_place {
                split_buffers.push((*slot, format, split(px, chunk).into_iter().map(ColorBand::Unorm8).collect()));
                continue;
            }
            let pieces: Vec<ColorBand<'_>> = match buffer.pixels_mut() {
                ColorPixels::Unorm8(px) => split(px, chunk).into_iter().map(ColorBand::Unorm8).collect(),
                ColorPixels::Rgb565(px) => split(px, chunk).into_iter().map(ColorBand::Rgb565).collect(),
                ColorPixels::Unorm16(px) => split(px, chunk).into_iter().map(ColorBand::Unorm16).collect(),
                ColorPixels::Float32(px) => split(px, chunk).into_iter().map(ColorBand::Float32).collect(),
            };
            split_buffers.push((*slot, format, pieces));
        }
        for slot in slots {
            let Some(i) = split_buffers.iter().position(|(s, _, _)| s == slot) else {
                continue;
            };
            let (slot, format, pieces) = split_buffers.swap_remove(i);
            for (band, pixels) in bands.iter_mut().zip(pieces) {
                band.colors.push(ColorTarget { slot, format, pixels });
            }
        }
        let float_depth = depth_layer.format().is_float_depth();
        let depth_pieces: Vec<DepthBand<'_>> = match depth_layer.pixels_mut() {
            DepthStencilPixels::None => Vec::new(),
            DepthStencilPixels::Depth16(px) => split(px, chunk).into_iter().map(DepthBand::Depth16).collect(),
            DepthStencilPixels::Packed24(px) => split(px, chunk).into_iter().map(DepthBand::Packed24).collect(),
            DepthStencilPixels::Depth32(px, stencil) => {
                let mut stencil_pieces = stencil.as_mut().map(|s| split(s, chunk).into_iter());
                split(px, chunk)
                    .into_iter()
                    .map(|d| {
                        let stencil = stencil_pieces.as_mut().and_then(|s| s.next());
                        if float_depth {
                            DepthBand::Float32(d, stencil)
                        } else {
                            DepthBand::Depth32(d, stencil)
                        }
                    })
                    .collect()
            }
        };
        for (band, depth) in bands.iter_mut().zip(depth_pieces) {
            band.depth = depth;
        }
        bands
    }
}
