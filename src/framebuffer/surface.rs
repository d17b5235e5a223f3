//! Storage of the individual layers: color, depth/stencil and accumulation buffers.
//!
//! Rows are stored bottom-up with no padding; pixel (x, y) is at `y * width + x`. Every
//! allocation goes through [`alloc_filled`] so that running out of memory is an error value.
use super::format::{
    depth_to_fixed, float_to_unorm, unorm_max, unorm_to_float, unorm_widen_to_u32, ColorFormat, DepthStencilFormat,
};
use super::{OutOfMemory, Rect};

/// A vector of `len` copies of `value`, or [`OutOfMemory`].
fn alloc_filled<T: Clone>(len: usize, value: T) -> Result<Vec<T>, OutOfMemory> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| OutOfMemory)?;
    v.resize(len, value);
    Ok(v)
}

/// Index range of row `y` between `x0` and `x1` in a buffer `width` wide.
#[inline]
fn span(width: usize, y: i32, x0: i32, x1: i32) -> std::ops::Range<usize> {
    let row = y as usize * width;
    row + x0 as usize..row + x1 as usize
}

/// The pixels of a color buffer, typed by format.
#[derive(Clone, Debug)]
pub enum ColorPixels {
    Unorm8(Vec<[u8; 4]>),
    /// r in bits 11..16, g in 5..11, b in 0..5 (GL_UNSIGNED_SHORT_5_6_5).
    Rgb565(Vec<u16>),
    Unorm16(Vec<[u16; 4]>),
    Float32(Vec<[f32; 4]>),
}

/// One color buffer.
#[derive(Clone, Debug)]
pub struct ColorBuffer {
    format: ColorFormat,
    width: usize,
    pixels: ColorPixels,
}

/// Packs RGB (already scaled to 5/6/5 bits) into a 5_6_5 word.
#[inline]
fn pack565(r: u32, g: u32, b: u32) -> u16 {
    ((r << 11) | (g << 5) | b) as u16
}

impl ColorBuffer {
    pub(super) fn new(format: ColorFormat, width: usize, _height: usize, pixels: usize) -> Result<Self, OutOfMemory> {
        // A fresh buffer is black; formats without alpha keep alpha at its maximum.
        let pixels = match format {
            ColorFormat::Unorm8 { alpha } => ColorPixels::Unorm8(alloc_filled(pixels, [0, 0, 0, if alpha { 0 } else { 255 }])?),
            ColorFormat::Rgb565 => ColorPixels::Rgb565(alloc_filled(pixels, 0)?),
            ColorFormat::Unorm16 { alpha } => {
                ColorPixels::Unorm16(alloc_filled(pixels, [0, 0, 0, if alpha { 0 } else { 65535 }])?)
            }
            ColorFormat::Float32 { alpha } => {
                ColorPixels::Float32(alloc_filled(pixels, [0.0, 0.0, 0.0, if alpha { 0.0 } else { 1.0 }])?)
            }
        };
        Ok(ColorBuffer { format, width, pixels })
    }

    pub fn format(&self) -> ColorFormat {
        self.format
    }

    pub fn pixels(&self) -> &ColorPixels {
        &self.pixels
    }

    pub fn pixels_mut(&mut self) -> &mut ColorPixels {
        &mut self.pixels
    }

    /// Clears `rect` (already inside the buffer) to `color`, writing only the channels whose
    /// `mask` entry is true. Fixed-point formats clamp; float formats store `color` as given.
    pub fn clear(&mut self, rect: Rect, color: [f32; 4], mask: [bool; 4]) {
        if rect.is_empty() || !mask.iter().any(|&m| m) {
            return;
        }
        let has_alpha = self.format.has_alpha();
        let mask = [mask[0], mask[1], mask[2], mask[3] && has_alpha];
        let width = self.width;
        match &mut self.pixels {
            ColorPixels::Unorm8(px) => {
                let value = color.map(|c| float_to_unorm(c, 8) as u8);
                fill_masked(px, width, rect, value, mask);
            }
            ColorPixels::Unorm16(px) => {
                let value = color.map(|c| float_to_unorm(c, 16) as u16);
                fill_masked(px, width, rect, value, mask);
            }
            ColorPixels::Float32(px) => fill_masked(px, width, rect, color, mask),
            ColorPixels::Rgb565(px) => {
                let value = pack565(float_to_unorm(color[0], 5), float_to_unorm(color[1], 6), float_to_unorm(color[2], 5));
                let keep: u16 = (if mask[0] { 0 } else { 0xf800 })
                    | (if mask[1] { 0 } else { 0x07e0 })
                    | (if mask[2] { 0 } else { 0x001f });
                for y in rect.y0..rect.y1 {
                    for p in &mut px[span(width, y, rect.x0, rect.x1)] {
                        *p = (*p & keep) | (value & !keep);
                    }
                }
            }
        }
    }

    /// Reads pixels `[x0, x1)` of row `y` as floats (alpha 1.0 for formats without alpha).
    pub fn read_row_f32(&self, y: i32, x0: i32, x1: i32, out: &mut Vec<[f32; 4]>) {
        let range = span(self.width, y, x0, x1);
        match &self.pixels {
            ColorPixels::Unorm8(px) => out.extend(px[range].iter().map(|p| p.map(|c| unorm_to_float(c as u32, 8)))),
            ColorPixels::Unorm16(px) => out.extend(px[range].iter().map(|p| p.map(|c| unorm_to_float(c as u32, 16)))),
            ColorPixels::Float32(px) => out.extend_from_slice(&px[range]),
            ColorPixels::Rgb565(px) => out.extend(px[range].iter().map(|&p| {
                let p = p as u32;
                [unorm_to_float(p >> 11, 5), unorm_to_float((p >> 5) & 63, 6), unorm_to_float(p & 31, 5), 1.0]
            })),
        }
    }

    /// The channel bits of the format (for exact integer readback paths).
    pub fn channel_bits(&self) -> [u32; 4] {
        self.format.channel_bits()
    }

    /// Reads pixels `[x0, x1)` of row `y` as unorm values widened to 32 bits by replication;
    /// `None` for float formats.
    pub fn read_row_unorm32(&self, y: i32, x0: i32, x1: i32, out: &mut Vec<[u32; 4]>) -> Option<()> {
        let range = span(self.width, y, x0, x1);
        match &self.pixels {
            ColorPixels::Unorm8(px) => out.extend(px[range].iter().map(|p| p.map(|c| unorm_widen_to_u32(c as u32, 8)))),
            ColorPixels::Unorm16(px) => out.extend(px[range].iter().map(|p| p.map(|c| unorm_widen_to_u32(c as u32, 16)))),
            ColorPixels::Rgb565(px) => out.extend(px[range].iter().map(|&p| {
                let p = p as u32;
                [unorm_widen_to_u32(p >> 11, 5), unorm_widen_to_u32((p >> 5) & 63, 6), unorm_widen_to_u32(p & 31, 5), u32::MAX]
            })),
            ColorPixels::Float32(_) => return None,
        }
        Some(())
    }

    /// Writes float RGBA into row `y` from `x0`, converting to the format (clamping
    /// fixed-point) and honouring the channel `mask`.
    pub fn write_row_f32(&mut self, y: i32, x0: i32, values: &[[f32; 4]], mask: [bool; 4]) {
        let range = span(self.width, y, x0, x0 + values.len() as i32);
        let mask = [mask[0], mask[1], mask[2], mask[3] && self.format.has_alpha()];
        match &mut self.pixels {
            ColorPixels::Unorm8(px) => {
                for (p, v) in px[range].iter_mut().zip(values) {
                    for c in 0..4 {
                        if mask[c] {
                            p[c] = float_to_unorm(v[c], 8) as u8;
                        }
                    }
                }
            }
            ColorPixels::Unorm16(px) => {
                for (p, v) in px[range].iter_mut().zip(values) {
                    for c in 0..4 {
                        if mask[c] {
                            p[c] = float_to_unorm(v[c], 16) as u16;
                        }
                    }
                }
            }
            ColorPixels::Float32(px) => {
                for (p, v) in px[range].iter_mut().zip(values) {
                    for c in 0..4 {
                        if mask[c] {
                            p[c] = v[c];
                        }
                    }
                }
            }
            ColorPixels::Rgb565(px) => {
                for (p, v) in px[range].iter_mut().zip(values) {
                    let old = *p as u32;
                    let r = if mask[0] { float_to_unorm(v[0], 5) } else { old >> 11 };
                    let g = if mask[1] { float_to_unorm(v[1], 6) } else { (old >> 5) & 63 };
                    let b = if mask[2] { float_to_unorm(v[2], 5) } else { old & 31 };
                    *p = pack565(r, g, b);
                }
            }
        }
    }
}

/// Pixels `[x0, x1)` of one row of a color buffer, borrowed in the buffer's own format: the
/// exact values, for readers that convert them once (glReadPixels).
#[derive(Clone, Copy, Debug)]
pub enum ColorRow<'a> {
    Unorm8(&'a [[u8; 4]]),
    /// r in bits 11..16, g in 5..11, b in 0..5.
    Rgb565(&'a [u16]),
    Unorm16(&'a [[u16; 4]]),
    Float32(&'a [[f32; 4]]),
}

impl ColorRow<'_> {
    pub fn len(&self) -> usize {
        match self {
            ColorRow::Unorm8(px) => px.len(),
            ColorRow::Rgb565(px) => px.len(),
            ColorRow::Unorm16(px) => px.len(),
            ColorRow::Float32(px) => px.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

impl ColorBuffer {
    /// Borrows pixels `[x0, x1)` of row `y` (inside the buffer).
    pub fn row(&self, y: i32, x0: i32, x1: i32) -> ColorRow<'_> {
        let range = span(self.width, y, x0, x1);
        match &self.pixels {
            ColorPixels::Unorm8(px) => ColorRow::Unorm8(&px[range]),
            ColorPixels::Rgb565(px) => ColorRow::Rgb565(&px[range]),
            ColorPixels::Unorm16(px) => ColorRow::Unorm16(&px[range]),
            ColorPixels::Float32(px) => ColorRow::Float32(&px[range]),
        }
    }
}

/// Fills `rect` of a 4-channel buffer with `value`, channel-masked.
fn fill_masked<T: Copy>(px: &mut [[T; 4]], width: usize, rect: Rect, value: [T; 4], mask: [bool; 4]) {
    let all = mask.iter().all(|&m| m);
    for y in rect.y0..rect.y1 {
        let row = &mut px[span(width, y, rect.x0, rect.x1)];
        if all {
            row.fill(value);
        } else {
            for p in row {
                for c in 0..4 {
                    if mask[c] {
                        p[c] = value[c];
                    }
                }
            }
        }
    }
}

/// Depth and stencil values, in the layout of [`DepthStencilFormat`].
#[derive(Clone, Debug)]
pub enum DepthStencilPixels {
    None,
    Depth16(Vec<u16>),
    /// depth24 | stencil << 24
    Packed24(Vec<u32>),
    /// 32-bit depth and an optional stencil plane.
    Depth32(Vec<u32>, Option<Vec<u8>>),
}

/// The depth/stencil layer of a framebuffer.
#[derive(Clone, Debug)]
pub struct DepthStencilBuffer {
    format: DepthStencilFormat,
    width: usize,
    pixels: DepthStencilPixels,
}

impl DepthStencilBuffer {
    pub(super) fn new(format: DepthStencilFormat, width: usize, pixels: usize) -> Result<Self, OutOfMemory> {
        let storage = match format {
            DepthStencilFormat::None => DepthStencilPixels::None,
            DepthStencilFormat::Depth16 => DepthStencilPixels::Depth16(alloc_filled(pixels, 0)?),
            DepthStencilFormat::Packed24 { .. } => DepthStencilPixels::Packed24(alloc_filled(pixels, 0)?),
            DepthStencilFormat::Depth32 { stencil } => DepthStencilPixels::Depth32(
                alloc_filled(pixels, 0)?,
                if stencil { Some(alloc_filled(pixels, 0)?) } else { None },
            ),
        };
        Ok(DepthStencilBuffer { format, width, pixels: storage })
    }

    pub fn format(&self) -> DepthStencilFormat {
        self.format
    }

    pub fn depth_bits(&self) -> u32 {
        self.format.depth_bits()
    }

    pub fn stencil_bits(&self) -> u32 {
        self.format.stencil_bits()
    }

    pub fn pixels(&self) -> &DepthStencilPixels {
        &self.pixels
    }

    pub fn pixels_mut(&mut self) -> &mut DepthStencilPixels {
        &mut self.pixels
    }

    /// Clears depth in `rect` to `depth` (in [0, 1]); no-op without depth bits.
    pub fn clear_depth(&mut self, rect: Rect, depth: f64) {
        let bits = self.depth_bits();
        if bits == 0 || rect.is_empty() {
            return;
        }
        let value = depth_to_fixed(depth, bits);
        let width = self.width;
        for y in rect.y0..rect.y1 {
            let r = span(width, y, rect.x0, rect.x1);
            match &mut self.pixels {
                DepthStencilPixels::Depth16(px) => px[r].fill(value as u16),
                DepthStencilPixels::Packed24(px) => {
                    for p in &mut px[r] {
                        *p = (*p & 0xff00_0000) | value;
                    }
                }
                DepthStencilPixels::Depth32(px, _) => px[r].fill(value),
                DepthStencilPixels::None => {}
            }
        }
    }

    /// Clears stencil in `rect` to `value`, changing only the bits set in `write_mask`.
    pub fn clear_stencil(&mut self, rect: Rect, value: u8, write_mask: u8) {
        if self.stencil_bits() == 0 || rect.is_empty() || write_mask == 0 {
            return;
        }
        let width = self.width;
        for y in rect.y0..rect.y1 {
            let r = span(width, y, rect.x0, rect.x1);
            match &mut self.pixels {
                DepthStencilPixels::Packed24(px) => {
                    let keep = !((write_mask as u32) << 24);
                    let set = ((value & write_mask) as u32) << 24;
                    for p in &mut px[r] {
                        *p = (*p & keep) | set;
                    }
                }
                DepthStencilPixels::Depth32(_, Some(st)) => {
                    for s in &mut st[r] {
                        *s = (*s & !write_mask) | (value & write_mask);
                    }
                }
                _ => {}
            }
        }
    }

    /// Reads depth of `[x0, x1)` in row `y` as n-bit fixed point values (n = depth bits).
    pub fn read_depth_row(&self, y: i32, x0: i32, x1: i32, out: &mut Vec<u32>) {
        let r = span(self.width, y, x0, x1);
        match &self.pixels {
            DepthStencilPixels::Depth16(px) => out.extend(px[r].iter().map(|&d| d as u32)),
            DepthStencilPixels::Packed24(px) => out.extend(px[r].iter().map(|&d| d & 0x00ff_ffff)),
            DepthStencilPixels::Depth32(px, _) => out.extend_from_slice(&px[r]),
            DepthStencilPixels::None => {}
        }
    }

    /// Reads stencil of `[x0, x1)` in row `y`.
    pub fn read_stencil_row(&self, y: i32, x0: i32, x1: i32, out: &mut Vec<u8>) {
        let r = span(self.width, y, x0, x1);
        match &self.pixels {
            DepthStencilPixels::Packed24(px) => out.extend(px[r].iter().map(|&d| (d >> 24) as u8)),
            DepthStencilPixels::Depth32(_, Some(st)) => out.extend_from_slice(&st[r]),
            _ => {}
        }
    }

    /// Depth as a float in [0, 1] from an n-bit fixed point value.
    pub fn depth_to_float(&self, value: u32) -> f32 {
        let bits = self.depth_bits();
        (value as f64 / unorm_max(bits) as f64) as f32
    }
}

/// The accumulation buffer: signed 16-bit normalized RGBA, as Mesa stores it.
#[derive(Clone, Debug)]
pub struct AccumBuffer {
    width: usize,
    pixels: Vec<[i16; 4]>,
}

impl AccumBuffer {
    pub(super) fn new(width: usize, pixels: usize) -> Result<Self, OutOfMemory> {
        Ok(AccumBuffer { width, pixels: alloc_filled(pixels, [0; 4])? })
    }

    pub fn width(&self) -> usize {
        self.width
    }

    pub fn pixels(&self) -> &[[i16; 4]] {
        &self.pixels
    }

    pub fn pixels_mut(&mut self) -> &mut [[i16; 4]] {
        &mut self.pixels
    }

    /// Index of pixel (x, y).
    pub fn index(&self, x: i32, y: i32) -> usize {
        y as usize * self.width + x as usize
    }
}
