//! Storage of the individual layers: color, depth/stencil and accumulation buffers.
//!
//! Rows are stored bottom-up with no padding; pixel (x, y) is at `y * width + x`. Every
//! allocation goes through [`alloc_filled`] so that running out of memory is an error value.
//! Texture images use the same storage (`crate::texture`): an 8-bit color texture's texels
//! are the pixels of a [`ColorPixels::Unorm8`] buffer and a depth texture is a
//! [`DepthStencilBuffer`], so that a framebuffer object renders into them where they live
//! ([`ColorBuffer::from_pixels`] and [`ColorBuffer::into_pixels`] move the vector).
use super::band::{ColorBand, DepthBand};
use super::format::{
    float_to_unorm, float_to_unorm16_half_up, unorm_to_float, unorm_widen_to_u32, ColorFormat, DepthEncoding,
    DepthStencilFormat,
};
use super::pages;
use super::{OutOfMemory, Rect};

/// A vector of `len` copies of `value`, or [`OutOfMemory`].
///
/// `vec!` asks the allocator for zeroed memory when `value` is all zero bits (the usual
/// case: black, depth 0, stencil 0), and for a large buffer that is fresh pages, which the
/// kernel zeroes when they are first touched: a buffer that the first glClear overwrites is
/// then written once, not twice (a 1024×1024 context wrote 8 MB of zeros before its first
/// clear wrote them again). `vec!` aborts when the allocation fails, so a large buffer is
/// probed first with a fallible reservation (freed at once). Not below [`PROBE_ABOVE`]:
/// glibc serves a block it has just freed from its heap rather than from fresh pages once
/// the freed block was smaller than 32 MiB (its mmap threshold adapts), and must then zero
/// it with memset; a smaller buffer failing to allocate means the process is out of memory
/// anyway.
///
/// A zero-filled buffer of at least two huge pages is allocated with [`pages::slack`] and
/// advised to use huge pages ([`pages`]): its first touch then costs a few faults instead of
/// one per 4 KiB.
fn alloc_filled<T: Clone + PartialEq + Default>(len: usize, value: T) -> Result<Vec<T>, OutOfMemory> {
    let bytes = len.checked_mul(std::mem::size_of::<T>()).ok_or(OutOfMemory)?;
    let slack = if value == T::default() { pages::slack::<T>(bytes) } else { 0 };
    let total = len.checked_add(slack).ok_or(OutOfMemory)?;
    if bytes > PROBE_ABOVE {
        Vec::<T>::new().try_reserve_exact(total).map_err(|_| OutOfMemory)?;
    }
    let mut buffer = vec![value; total];
    if slack > 0 {
        buffer.truncate(len);
        pages::advise_huge_pages(&mut buffer);
    }
    Ok(buffer)
}

/// The size above which [`alloc_filled`] probes the allocation before making it.
const PROBE_ABOVE: usize = 64 << 20;

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
            ColorFormat::Unorm8 { alpha } => {
                ColorPixels::Unorm8(alloc_filled(pixels, [0, 0, 0, if alpha { 0 } else { 255 }])?)
            }
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

    /// A color buffer made of `pixels` (moved, not copied), `width` pixels per row: a texture
    /// image rendered in place. `pixels` must be of `format`'s type.
    pub fn from_pixels(format: ColorFormat, width: usize, pixels: ColorPixels) -> ColorBuffer {
        debug_assert!(matches!(
            (format, &pixels),
            (ColorFormat::Unorm8 { .. }, ColorPixels::Unorm8(_))
                | (ColorFormat::Rgb565, ColorPixels::Rgb565(_))
                | (ColorFormat::Unorm16 { .. }, ColorPixels::Unorm16(_))
                | (ColorFormat::Float32 { .. }, ColorPixels::Float32(_))
        ));
        ColorBuffer { format, width, pixels }
    }

    /// The pixels, moved out of the buffer.
    pub fn into_pixels(self) -> ColorPixels {
        self.pixels
    }

    pub fn format(&self) -> ColorFormat {
        self.format
    }

    /// Pixels per row.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Rows in the buffer.
    pub fn height(&self) -> usize {
        let len = match &self.pixels {
            ColorPixels::Unorm8(px) => px.len(),
            ColorPixels::Rgb565(px) => px.len(),
            ColorPixels::Unorm16(px) => px.len(),
            ColorPixels::Float32(px) => px.len(),
        };
        len.checked_div(self.width).unwrap_or(0)
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
        let whole_buffer =
            rect == Rect::from_xywh(0, 0, self.width as i32, self.height() as i32) && mask.iter().all(|&m| m);
        let mut pixels = match &mut self.pixels {
            ColorPixels::Unorm8(px) => ColorBand::Unorm8(px),
            ColorPixels::Rgb565(px) => ColorBand::Rgb565(px),
            ColorPixels::Unorm16(px) => ColorBand::Unorm16(px),
            ColorPixels::Float32(px) => ColorBand::Float32(px),
        };
        clear_color_band(&mut pixels, self.format, self.width, 0, rect, color, mask, whole_buffer);
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
            ColorPixels::Unorm16(px) => {
                out.extend(px[range].iter().map(|p| p.map(|c| unorm_widen_to_u32(c as u32, 16))))
            }
            ColorPixels::Rgb565(px) => out.extend(px[range].iter().map(|&p| {
                let p = p as u32;
                [
                    unorm_widen_to_u32(p >> 11, 5),
                    unorm_widen_to_u32((p >> 5) & 63, 6),
                    unorm_widen_to_u32(p & 31, 5),
                    u32::MAX,
                ]
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
/// Clears `rect` of a color band (rows from `y0` on, `width` pixels each) to `color`,
/// writing only the channels whose `mask` entry is true: the one encoding of a color clear,
/// whether [`ColorBuffer::clear`] runs it at once or a tile worker runs a clear recorded in
/// the scene. `whole_buffer` (a clear of every pixel and channel) picks llvmpipe's packing
/// of a whole-buffer clear over that of a drawn (scissored or masked) one.
#[allow(clippy::too_many_arguments)]
pub fn clear_color_band(
    pixels: &mut ColorBand<'_>,
    format: ColorFormat,
    width: usize,
    y0: i32,
    rect: Rect,
    color: [f32; 4],
    mask: [bool; 4],
    whole_buffer: bool,
) {
    if rect.is_empty() || !mask.iter().any(|&m| m) {
        return;
    }
    let mask = [mask[0], mask[1], mask[2], mask[3] && format.has_alpha()];
    let rect = Rect { y0: rect.y0 - y0, y1: rect.y1 - y0, ..rect };
    match pixels {
        ColorBand::Unorm8(px) => {
            let value = color.map(|c| float_to_unorm(c, 8) as u8);
            fill_masked(px, width, rect, value, mask);
        }
        ColorBand::Unorm16(px) => {
            // llvmpipe packs a whole-buffer clear with half-up rounding and draws a partial
            // (scissored or masked) clear as a quad whose stores round ties to even; both
            // are "nearest", and matching the reference bit for bit decides which tie wins.
            let value = if whole_buffer {
                color.map(float_to_unorm16_half_up)
            } else {
                color.map(|c| float_to_unorm(c, 16) as u16)
            };
            fill_masked(px, width, rect, value, mask);
        }
        ColorBand::Float32(px) => fill_masked(px, width, rect, color, mask),
        ColorBand::Rgb565(px) => {
            // A partial clear is drawn by llvmpipe, whose 5/6-bit stores take the top bits
            // of the 8-bit conversion (0.992 green: 253 >> 2 = 63, not round(62.496)).
            let value = if whole_buffer {
                pack565(float_to_unorm(color[0], 5), float_to_unorm(color[1], 6), float_to_unorm(color[2], 5))
            } else {
                let c8 = color.map(|c| float_to_unorm(c, 8));
                pack565(c8[0] >> 3, c8[1] >> 2, c8[2] >> 3)
            };
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

/// The stored value a depth clear to `depth` writes in `format`, for a clear of the whole
/// buffer or of a part of it.
pub fn depth_clear_value(format: DepthStencilFormat, whole_buffer: bool, depth: f64) -> u32 {
    // llvmpipe packs a whole-buffer clear from the double-precision depth, and draws a
    // partial (scissored) clear as a quad at NDC depth 2d − 1, which the viewport maps
    // back in single precision before the fragment depth store: 0.1 clears a 16-bit
    // buffer to 0x199a, a scissored part of it to 0x1999 (matches Mesa on 4082 samples).
    let encoding = format.depth_encoding();
    if whole_buffer {
        encoding.encode_f64(depth)
    } else {
        let ndc = depth as f32 * 2.0 - 1.0;
        encoding.encode_fragment(ndc * 0.5 + 0.5)
    }
}

/// Clears `rect` of a depth/stencil band (rows from `y0` on, `width` pixels each): depth to
/// `depth` when given, stencil to `stencil.0` under write mask `stencil.1` when given; the
/// same stores as [`DepthStencilBuffer::clear_depth_and_stencil`] (a tile worker runs this
/// for a clear recorded in the scene).
#[allow(clippy::too_many_arguments)]
pub fn clear_depth_band(
    pixels: &mut DepthBand<'_>,
    format: DepthStencilFormat,
    width: usize,
    y0: i32,
    rect: Rect,
    depth: Option<f64>,
    stencil: Option<(u8, u8)>,
    whole_buffer: bool,
) {
    if rect.is_empty() {
        return;
    }
    // Compiled per SIMD level: a depth-only clear of a depth/stencil buffer keeps each
    // pixel's stencil byte (a load, and, or and store per pixel), which runs 8 pixels per
    // instruction at AVX2 and 4 at the SSE2 baseline (MuJoCo clears a 4096² one per frame).
    crate::simd::per_level!(clear_depth_band_body(pixels, format, width, y0, rect, depth, stencil, whole_buffer))
}

/// [`clear_depth_band`]'s body, inlined into each level's copy.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn clear_depth_band_body(
    pixels: &mut DepthBand<'_>,
    format: DepthStencilFormat,
    width: usize,
    y0: i32,
    rect: Rect,
    depth: Option<f64>,
    stencil: Option<(u8, u8)>,
    whole_buffer: bool,
) {
    let depth = depth.filter(|_| format.depth_bits() > 0).map(|d| depth_clear_value(format, whole_buffer, d));
    let stencil = stencil.filter(|&(_, mask)| format.stencil_bits() > 0 && mask != 0);
    let rect = Rect { y0: rect.y0 - y0, y1: rect.y1 - y0, ..rect };
    let rows = rect.y0..rect.y1;
    match pixels {
        DepthBand::None => {}
        DepthBand::Depth16(px) => {
            if let Some(value) = depth {
                rows.for_each(|y| px[span(width, y, rect.x0, rect.x1)].fill(value as u16));
            }
        }
        DepthBand::Packed24(px) => {
            for y in rows {
                let row = &mut px[span(width, y, rect.x0, rect.x1)];
                match (depth, stencil) {
                    (Some(d), Some((s, 0xff))) => row.fill(d | (s as u32) << 24),
                    (d, s) => {
                        let (keep_depth, set_depth) = d.map_or((0x00ff_ffff, 0), |d| (0, d));
                        let (keep_stencil, set_stencil) = s.map_or((0xff00_0000, 0), |(v, m)| {
                            (!((m as u32) << 24) & 0xff00_0000, ((v & m) as u32) << 24)
                        });
                        for p in row {
                            *p = (*p & (keep_depth | keep_stencil)) | set_depth | set_stencil;
                        }
                    }
                }
            }
        }
        DepthBand::Depth32(px, st) | DepthBand::Float32(px, st) => {
            for y in rows {
                let r = span(width, y, rect.x0, rect.x1);
                if let Some(value) = depth {
                    px[r.clone()].fill(value);
                }
                if let (Some((value, mask)), Some(st)) = (stencil, st.as_deref_mut()) {
                    for s in &mut st[r] {
                        *s = (*s & !mask) | (value & mask);
                    }
                }
            }
        }
    }
}

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
#[derive(Clone, Debug, PartialEq, Default)]
pub enum DepthStencilPixels {
    #[default]
    None,
    Depth16(Vec<u16>),
    /// depth24 | stencil << 24
    Packed24(Vec<u32>),
    /// 32-bit depth (fixed point, or float bit patterns in a `Float32` buffer) and an
    /// optional stencil plane.
    Depth32(Vec<u32>, Option<Vec<u8>>),
}

/// The depth/stencil layer of a framebuffer (or the texels of a depth texture). The default
/// buffer is empty (no depth, no stencil, no pixels): what is left behind when a texture's
/// buffer is moved into a framebuffer.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthStencilBuffer {
    format: DepthStencilFormat,
    width: usize,
    pixels: DepthStencilPixels,
}

impl Default for DepthStencilBuffer {
    fn default() -> Self {
        DepthStencilBuffer { format: DepthStencilFormat::None, width: 0, pixels: DepthStencilPixels::None }
    }
}

impl DepthStencilBuffer {
    pub(super) fn new(format: DepthStencilFormat, width: usize, pixels: usize) -> Result<Self, OutOfMemory> {
        let storage = match format {
            DepthStencilFormat::None => DepthStencilPixels::None,
            DepthStencilFormat::Depth16 => DepthStencilPixels::Depth16(alloc_filled(pixels, 0)?),
            DepthStencilFormat::Packed24 { .. } => DepthStencilPixels::Packed24(alloc_filled(pixels, 0)?),
            DepthStencilFormat::Depth32 { stencil } | DepthStencilFormat::Float32 { stencil } => {
                DepthStencilPixels::Depth32(
                    alloc_filled(pixels, 0)?,
                    if stencil { Some(alloc_filled(pixels, 0)?) } else { None },
                )
            }
        };
        Ok(DepthStencilBuffer { format, width, pixels: storage })
    }

    pub fn format(&self) -> DepthStencilFormat {
        self.format
    }

    /// Pixels per row.
    pub fn width(&self) -> usize {
        self.width
    }

    pub fn depth_bits(&self) -> u32 {
        self.format.depth_bits()
    }

    pub fn stencil_bits(&self) -> u32 {
        self.format.stencil_bits()
    }

    #[inline]
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
        let value = self.depth_clear_value(rect, depth);
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

    /// The stored value a depth clear of `rect` to `depth` writes.
    fn depth_clear_value(&self, rect: Rect, depth: f64) -> u32 {
        let rows = self.len().checked_div(self.width).unwrap_or(0);
        let whole_buffer = rect == Rect::from_xywh(0, 0, self.width as i32, rows as i32);
        depth_clear_value(self.format, whole_buffer, depth)
    }

    /// Clears depth and stencil in `rect` together: the same as [`Self::clear_depth`] then
    /// [`Self::clear_stencil`]. Packed 24/8 with every stencil bit written is one store per
    /// pixel, with no read: the two read-modify-write passes read a fresh buffer's pages
    /// before writing them, which costs the kernel two page faults per page instead of one.
    pub fn clear_depth_and_stencil(&mut self, rect: Rect, depth: f64, stencil: u8, write_mask: u8) {
        let whole_word = matches!(self.pixels, DepthStencilPixels::Packed24(_))
            && self.depth_bits() == 24
            && self.stencil_bits() == 8
            && write_mask == 0xff;
        if !whole_word || rect.is_empty() {
            self.clear_depth(rect, depth);
            self.clear_stencil(rect, stencil, write_mask);
            return;
        }
        let value = self.depth_clear_value(rect, depth) | (stencil as u32) << 24;
        let width = self.width;
        if let DepthStencilPixels::Packed24(px) = &mut self.pixels {
            for y in rect.y0..rect.y1 {
                px[span(width, y, rect.x0, rect.x1)].fill(value);
            }
        }
    }

    /// Pixels in the buffer.
    pub fn len(&self) -> usize {
        match &self.pixels {
            DepthStencilPixels::None => 0,
            DepthStencilPixels::Depth16(px) => px.len(),
            DepthStencilPixels::Packed24(px) => px.len(),
            DepthStencilPixels::Depth32(px, _) => px.len(),
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

    /// Whether the buffer has no pixels.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The stored depth of pixel `i` (see [`Self::depth_encoding`]; 0 without depth).
    #[inline]
    pub fn depth_value(&self, i: usize) -> u32 {
        match &self.pixels {
            DepthStencilPixels::Depth16(px) => px[i] as u32,
            DepthStencilPixels::Packed24(px) => px[i] & 0x00ff_ffff,
            DepthStencilPixels::Depth32(px, _) => px[i],
            DepthStencilPixels::None => 0,
        }
    }

    /// Sets the stored depth of pixel `i`, keeping its stencil index.
    #[inline]
    pub fn set_depth_value(&mut self, i: usize, value: u32) {
        match &mut self.pixels {
            DepthStencilPixels::Depth16(px) => px[i] = value as u16,
            DepthStencilPixels::Packed24(px) => px[i] = (px[i] & 0xff00_0000) | (value & 0x00ff_ffff),
            DepthStencilPixels::Depth32(px, _) => px[i] = value,
            DepthStencilPixels::None => {}
        }
    }

    /// The stencil index of pixel `i` (0 without stencil).
    #[inline]
    pub fn stencil_value(&self, i: usize) -> u8 {
        match &self.pixels {
            DepthStencilPixels::Packed24(px) if self.stencil_bits() > 0 => (px[i] >> 24) as u8,
            DepthStencilPixels::Depth32(_, Some(st)) => st[i],
            _ => 0,
        }
    }

    /// Sets the stencil index of pixel `i` (nothing without stencil).
    #[inline]
    pub fn set_stencil_value(&mut self, i: usize, index: u8) {
        let stencil = self.stencil_bits() > 0;
        match &mut self.pixels {
            DepthStencilPixels::Packed24(px) if stencil => px[i] = (px[i] & 0x00ff_ffff) | (index as u32) << 24,
            DepthStencilPixels::Depth32(_, Some(st)) => st[i] = index,
            _ => {}
        }
    }

    /// Reads depth of `[x0, x1)` in row `y` as stored (see [`Self::depth_encoding`]).
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

    /// Depth as a float in [0, 1] from a stored value.
    pub fn depth_to_float(&self, value: u32) -> f32 {
        self.format.depth_encoding().decode(value)
    }

    /// How the values [`Self::read_depth_row`] returns encode depth.
    #[inline]
    pub fn depth_encoding(&self) -> DepthEncoding {
        self.format.depth_encoding()
    }
}

/// The accumulation buffer: signed 16-bit normalized RGBA, as Mesa stores it.
///
/// The arithmetic reproduces Mesa 22's glAccum (`main/accum.c` on the CPU) bit for bit, because
/// tessera must give the same pictures; it was measured against llvmpipe OSMesa for every
/// operation, value range and color format (see `capi-tests/accum.c`):
/// - values are stored as `i16` with 1.0 ↔ 32767; float → `i16` truncates toward zero through a
///   32-bit integer and keeps the low 16 bits (x86-64's `cvttss2si` + C's narrowing), so values
///   beyond ±1 wrap around instead of saturating, and so do sums (`wrapping_add`). The GL
///   specification leaves results outside [-1, 1] undefined; Mesa's wrap is what programs see.
/// - color channels are read as Mesa's format unpackers do: `c · (1/(2ⁿ − 1))` in f32 (a
///   multiplication by the rounded reciprocal, not a division).
/// - GL_RETURN writes `acc · (value / 32767)` packed as Mesa's format packers do: 8-bit
///   channels round to nearest (even), 16-bit and 5/6-bit channels add 0.5 and truncate, float
///   channels store the value unclamped.
#[derive(Clone, Debug)]
pub struct AccumBuffer {
    width: usize,
    pixels: Vec<[i16; 4]>,
}

/// float → accumulation value: truncation through i32 (NaN and out-of-range give `i32::MIN`,
/// as `cvttss2si` does), then the low 16 bits.
#[inline]
pub fn accum_from_f32(value: f32) -> i16 {
    // Rust's `as` saturates: NaN gives 0 and values below the range i32::MIN, whose low half
    // is 0 as with cvttss2si; only values above the range need the explicit 0.
    let wide = value as i32;
    if value >= 2147483648.0 {
        0
    } else {
        wide as i16
    }
}

/// Magnitude below which [`accum_from_small_f32`] is exact.
const SMALL_LIMIT: f32 = 4194304.0; // 2²²

/// [`accum_from_f32`] for |value| < 2²², without the saturating conversion that LLVM does
/// not vectorize on baseline x86-64: adding 1.5 · 2²³ rounds to nearest into the low mantissa
/// bits, and a rounding away from zero is then undone. (Checked equal to [`accum_from_f32`]
/// for every such f32.)
#[inline]
fn accum_from_small_f32(value: f32) -> i16 {
    const MAGIC: f32 = 12582912.0;
    let biased = value + MAGIC;
    let rounded = (biased.to_bits() as i32).wrapping_sub(MAGIC.to_bits() as i32);
    let rounded_away = (biased - MAGIC).abs() > value.abs();
    let toward_zero = if value < 0.0 { 1 } else { -1 };
    (if rounded_away { rounded + toward_zero } else { rounded }) as i16
}

/// Stores `convert(src)` into `acc` (GL_LOAD) or adds it, wrapping (GL_ACCUM).
#[inline]
fn combine_channels<T: Copy, const ACCUMULATE: bool>(acc: &mut [i16], src: &[T], convert: impl Fn(T) -> i16) {
    for (a, &c) in acc.iter_mut().zip(src) {
        let new = convert(c);
        *a = if ACCUMULATE { a.wrapping_add(new) } else { new };
    }
}

/// glClearAccum's value (in [-1, 1]) as stored: Mesa's `FLOAT_TO_SHORT`,
/// `(trunc(65535 · c) − 1) / 2` with C's division (toward zero).
#[inline]
pub fn accum_clear_value(value: f32) -> i16 {
    let scaled = if value.is_nan() { 0 } else { (65535.0 * value.clamp(-1.0, 1.0)) as i32 };
    ((scaled - 1) / 2) as i16
}

/// Mesa's float → n-bit unorm packing for 16-bit and 5/6-bit channels (`util_iround` of the
/// clamped value times 2ⁿ − 1, which adds 0.5 and truncates); NaN gives 0.
#[inline]
fn pack_unorm_half_up(value: f32, max: f32) -> u32 {
    let clamped = if value > 0.0 { value.min(1.0) } else { 0.0 };
    (clamped * max + 0.5) as u32
}

/// Mesa's float → 8-bit unorm packing (`float_to_ubyte`): 0 for NaN and values ≤ 0, 255 from
/// 1 up, else the low byte of the mantissa of `f · 255/256 + 32768`, which is `f · 255` rounded
/// to nearest even (without a rounding instruction, which x86-64's baseline lacks).
#[inline]
fn pack_unorm8(value: f32) -> u8 {
    let rounded = (value * (255.0 / 256.0) + 32768.0).to_bits() as u8;
    if value >= 1.0 {
        255
    } else if value > 0.0 {
        rounded
    } else {
        0
    }
}

/// Mesa's n-bit unorm → float unpacking: a multiplication by the f32 reciprocal of 2ⁿ − 1.
#[inline]
fn unpack_unorm(value: u32, reciprocal: f32) -> f32 {
    value as f32 * reciprocal
}

const RECIP_255: f32 = 1.0 / 255.0;
const RECIP_65535: f32 = 1.0 / 65535.0;
const RECIP_31: f32 = 1.0 / 31.0;
const RECIP_63: f32 = 1.0 / 63.0;

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

    /// Sets every pixel of `rect` (already inside the buffer) to `value`.
    pub fn fill(&mut self, rect: Rect, value: [i16; 4]) {
        for y in rect.y0..rect.y1 {
            self.pixels[span(self.width, y, rect.x0, rect.x1)].fill(value);
        }
    }

    /// GL_ADD: adds `value · 32767` (truncated) to every channel of `rect`, wrapping.
    pub fn add(&mut self, rect: Rect, value: f32) {
        let increment = accum_from_f32(value * 32767.0);
        self.for_each_channel(rect, |acc| *acc = acc.wrapping_add(increment));
    }

    /// GL_MULT: multiplies every channel of `rect` by `value`, truncating.
    pub fn multiply(&mut self, rect: Rect, value: f32) {
        // |acc · value| ≤ 32768 · |value|.
        if value.abs() < SMALL_LIMIT / 32768.0 {
            self.for_each_channel(rect, |acc| *acc = accum_from_small_f32(*acc as f32 * value));
        } else {
            self.for_each_channel(rect, |acc| *acc = accum_from_f32(*acc as f32 * value));
        }
    }

    fn for_each_channel(&mut self, rect: Rect, mut f: impl FnMut(&mut i16)) {
        for y in rect.y0..rect.y1 {
            for pixel in &mut self.pixels[span(self.width, y, rect.x0, rect.x1)] {
                pixel.iter_mut().for_each(&mut f);
            }
        }
    }

    /// GL_LOAD (`accumulate` false) or GL_ACCUM (true) over `rect`: the color buffer's pixels
    /// times `value`, stored or added. `color` has the accumulation buffer's width.
    ///
    /// Formats without alpha store alpha at its maximum, which reads as exactly 1.0 as Mesa's
    /// unpackers give (the accumulated alpha of such buffers is never visible anyway).
    pub fn load_from(&mut self, color: &ColorBuffer, rect: Rect, value: f32, accumulate: bool) {
        if accumulate {
            self.load::<true>(color, rect, value);
        } else {
            self.load::<false>(color, rect, value);
        }
    }

    fn load<const ACCUMULATE: bool>(&mut self, color: &ColorBuffer, rect: Rect, value: f32) {
        let scale = value * 32767.0;
        match &color.pixels {
            ColorPixels::Unorm8(px) => {
                // 256 possible inputs: convert each once.
                let table: [i16; 256] =
                    std::array::from_fn(|c| accum_from_f32(unpack_unorm(c as u32, RECIP_255) * scale));
                self.load_channels::<_, ACCUMULATE>(px, rect, |c| table[c as usize]);
            }
            ColorPixels::Unorm16(px) => {
                // Unpacked colors are in [0, 1].
                if scale.abs() < SMALL_LIMIT {
                    self.load_channels::<_, ACCUMULATE>(px, rect, |c| {
                        accum_from_small_f32(unpack_unorm(c as u32, RECIP_65535) * scale)
                    })
                } else {
                    self.load_channels::<_, ACCUMULATE>(px, rect, |c| {
                        accum_from_f32(unpack_unorm(c as u32, RECIP_65535) * scale)
                    })
                }
            }
            ColorPixels::Float32(px) => {
                for y in rect.y0..rect.y1 {
                    let range = span(self.width, y, rect.x0, rect.x1);
                    let colors = px[range.clone()].as_flattened();
                    let acc = self.pixels[range].as_flattened_mut();
                    // Float colors are unbounded: decide per row (NaN takes the general path).
                    let small = colors.iter().fold(true, |ok, &c| ok & ((c * scale).abs() < SMALL_LIMIT));
                    if small {
                        combine_channels::<_, ACCUMULATE>(acc, colors, |c| accum_from_small_f32(c * scale));
                    } else {
                        combine_channels::<_, ACCUMULATE>(acc, colors, |c| accum_from_f32(c * scale));
                    }
                }
            }
            ColorPixels::Rgb565(px) => {
                let opaque = accum_from_f32(scale);
                for y in rect.y0..rect.y1 {
                    let range = span(self.width, y, rect.x0, rect.x1);
                    for (acc, &p) in self.pixels[range.clone()].iter_mut().zip(&px[range]) {
                        let p = p as u32;
                        let new = [
                            accum_from_f32(unpack_unorm(p >> 11, RECIP_31) * scale),
                            accum_from_f32(unpack_unorm((p >> 5) & 63, RECIP_63) * scale),
                            accum_from_f32(unpack_unorm(p & 31, RECIP_31) * scale),
                            opaque,
                        ];
                        for (a, n) in acc.iter_mut().zip(new) {
                            *a = if ACCUMULATE { a.wrapping_add(n) } else { n };
                        }
                    }
                }
            }
        }
    }

    /// The channels of `rect` of a 4-channel color buffer, each converted by `convert`, stored
    /// into or added to the accumulation buffer.
    fn load_channels<T: Copy, const ACCUMULATE: bool>(
        &mut self,
        px: &[[T; 4]],
        rect: Rect,
        convert: impl Fn(T) -> i16,
    ) {
        for y in rect.y0..rect.y1 {
            let range = span(self.width, y, rect.x0, rect.x1);
            let colors = px[range.clone()].as_flattened();
            combine_channels::<_, ACCUMULATE>(self.pixels[range].as_flattened_mut(), colors, &convert);
        }
    }

    /// GL_RETURN over `rect`: writes `acc · value` into `color`, only the channels whose `mask`
    /// entry is true. `color` has the accumulation buffer's width.
    pub fn return_to(&self, color: &mut ColorBuffer, rect: Rect, value: f32, mask: [bool; 4]) {
        let scale = value / 32767.0;
        let mask = [mask[0], mask[1], mask[2], mask[3] && color.format.has_alpha()];
        match &mut color.pixels {
            ColorPixels::Unorm8(px) => self.return_channels(px, rect, mask, |a| pack_unorm8(a as f32 * scale)),
            ColorPixels::Unorm16(px) => {
                self.return_channels(px, rect, mask, |a| pack_unorm_half_up(a as f32 * scale, 65535.0) as u16)
            }
            ColorPixels::Float32(px) => self.return_channels(px, rect, mask, |a| a as f32 * scale),
            ColorPixels::Rgb565(px) => {
                let keep: u16 = (if mask[0] { 0 } else { 0xf800 })
                    | (if mask[1] { 0 } else { 0x07e0 })
                    | (if mask[2] { 0 } else { 0x001f });
                for y in rect.y0..rect.y1 {
                    let range = span(self.width, y, rect.x0, rect.x1);
                    for (p, acc) in px[range.clone()].iter_mut().zip(&self.pixels[range]) {
                        let r = pack_unorm_half_up(acc[0] as f32 * scale, 31.0);
                        let g = pack_unorm_half_up(acc[1] as f32 * scale, 63.0);
                        let b = pack_unorm_half_up(acc[2] as f32 * scale, 31.0);
                        *p = (*p & keep) | (pack565(r, g, b) & !keep);
                    }
                }
            }
        }
    }

    /// Writes `convert(acc)` into the channels of `rect` of a 4-channel color buffer whose
    /// `mask` entry is true.
    fn return_channels<T: Copy>(&self, px: &mut [[T; 4]], rect: Rect, mask: [bool; 4], convert: impl Fn(i16) -> T) {
        let all = mask == [true; 4];
        for y in rect.y0..rect.y1 {
            let range = span(self.width, y, rect.x0, rect.x1);
            let accum = &self.pixels[range.clone()];
            if all {
                let dst = px[range].as_flattened_mut();
                for (p, &a) in dst.iter_mut().zip(accum.as_flattened()) {
                    *p = convert(a);
                }
            } else {
                for (p, a) in px[range].iter_mut().zip(accum) {
                    for c in 0..4 {
                        if mask[c] {
                            p[c] = convert(a[c]);
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod accum_tests {
    //! Expected values were computed with Mesa 22's C expressions (and checked against
    //! llvmpipe OSMesa); they pin the rounding, truncation and wrap-around of every step.
    use super::*;

    fn whole(width: i32, height: i32) -> Rect {
        Rect::from_xywh(0, 0, width, height)
    }

    fn accum_with(values: &[[i16; 4]]) -> AccumBuffer {
        let mut accum = AccumBuffer::new(values.len(), values.len()).unwrap();
        accum.pixels_mut().copy_from_slice(values);
        accum
    }

    #[test]
    fn float_to_accum_truncates_and_wraps_like_x86_mesa() {
        assert_eq!(accum_from_f32(0.99), 0);
        assert_eq!(accum_from_f32(1.9), 1);
        assert_eq!(accum_from_f32(-1.9), -1);
        assert_eq!(accum_from_f32(32767.9), 32767);
        assert_eq!(accum_from_f32(32768.0), -32768);
        assert_eq!(accum_from_f32(-32769.0), 32767);
        assert_eq!(accum_from_f32(98301.0), 32765);
        assert_eq!(accum_from_f32(2147483520.0), -128);
        // Outside the i32 range, cvttss2si gives i32::MIN, whose low half is 0.
        assert_eq!(accum_from_f32(2147483648.0), 0);
        assert_eq!(accum_from_f32(-1e10), 0);
        assert_eq!(accum_from_f32(f32::NAN), 0);
        assert_eq!(accum_from_f32(f32::INFINITY), 0);
    }

    #[test]
    fn small_conversion_equals_the_general_one() {
        // Every 13th f32 below 2²² in magnitude, plus the halves and the edges.
        let mut bits = 0u32;
        while bits < SMALL_LIMIT.to_bits() {
            for v in [f32::from_bits(bits), -f32::from_bits(bits)] {
                assert_eq!(accum_from_small_f32(v), accum_from_f32(v), "{v:e}");
            }
            bits += 13;
        }
        for n in -70000..70000 {
            let v = n as f32 + 0.5;
            assert_eq!(accum_from_small_f32(v), accum_from_f32(v), "{v}");
        }
        let below_limit = f32::from_bits(SMALL_LIMIT.to_bits() - 1);
        for v in [0.0, -0.0, 0.99999994, -0.99999994, 32767.5, -32768.5, below_limit, -below_limit] {
            assert_eq!(accum_from_small_f32(v), accum_from_f32(v), "{v}");
        }
    }

    #[test]
    fn clear_value_is_mesas_float_to_short() {
        assert_eq!(accum_clear_value(1.0), 32767);
        assert_eq!(accum_clear_value(-1.0), -32768);
        assert_eq!(accum_clear_value(0.0), 0);
        assert_eq!(accum_clear_value(0.5), 16383);
        assert_eq!(accum_clear_value(-0.5), -16384);
        assert_eq!(accum_clear_value(0.25), 8191);
        assert_eq!(accum_clear_value(1e-5), 0);
    }

    #[test]
    fn fill_add_and_multiply_stay_inside_the_rect() {
        let mut accum = AccumBuffer::new(3, 6).unwrap();
        accum.fill(whole(3, 2), [20000, 1000, -12345, 30000]);
        let inner = Rect::from_xywh(1, 1, 2, 1);
        accum.add(inner, 0.5);
        assert_eq!(accum.pixels()[4], [-29153, 17383, 4038, -19153]);
        accum.fill(whole(3, 2), [20000, 1000, -12345, 30000]);
        accum.multiply(inner, 0.3);
        assert_eq!(accum.pixels()[5][1], 300);
        accum.fill(inner, [1000, -12345, 30000, 7]);
        accum.multiply(inner, 1.7);
        assert_eq!(accum.pixels()[4], [1700, -20986, -14536, 11]);
        accum.multiply(inner, f32::NAN);
        assert_eq!(accum.pixels()[4], [0; 4]);
        // Outside the rectangle nothing changed.
        assert_eq!(accum.pixels()[0], [20000, 1000, -12345, 30000]);
        assert_eq!(accum.pixels()[3], [20000, 1000, -12345, 30000]);
        // Increments below one step truncate to nothing.
        accum.add(whole(3, 2), 1e-5);
        assert_eq!(accum.pixels()[0], [20000, 1000, -12345, 30000]);
    }

    #[test]
    fn maximum_channels_unpack_to_exactly_one() {
        // Formats without alpha rely on this: their stored alpha is the maximum.
        assert_eq!(unpack_unorm(255, RECIP_255), 1.0);
        assert_eq!(unpack_unorm(65535, RECIP_65535), 1.0);
    }

    #[test]
    fn load_and_accum_unpack_with_mesas_reciprocals() {
        let mut color = ColorBuffer::new(ColorFormat::Unorm8 { alpha: true }, 2, 1, 2).unwrap();
        if let ColorPixels::Unorm8(px) = color.pixels_mut() {
            px[0] = [128, 0, 255, 254];
            px[1] = [1, 2, 3, 4];
        }
        let mut accum = AccumBuffer::new(2, 2).unwrap();
        accum.load_from(&color, whole(1, 1), 1.0, false);
        assert_eq!(accum.pixels()[0], [16447, 0, 32767, 32638]);
        assert_eq!(accum.pixels()[1], [0; 4], "outside the rectangle");
        accum.load_from(&color, whole(1, 1), 1.0, true);
        assert_eq!(accum.pixels()[0], [-32642, 0, -2, -260]);
        // x · (1/255) rounds differently from x / 255 here: -32515 (Mesa) instead of -32516.
        accum.load_from(&color, whole(1, 1), 33151.0 / 32767.0, false);
        assert_eq!(accum.pixels()[0][3], -32515);

        let mut color16 = ColorBuffer::new(ColorFormat::Unorm16 { alpha: false }, 1, 1, 1).unwrap();
        if let ColorPixels::Unorm16(px) = color16.pixels_mut() {
            px[0] = [257, 40000, 514, 65535];
        }
        let mut accum = AccumBuffer::new(1, 1).unwrap();
        accum.load_from(&color16, whole(1, 1), 510.0 / 32767.0, false);
        // 257 · (1/65535) gives 1 where 257 / 65535 would give 2; alpha reads as 1.0.
        assert_eq!(accum.pixels()[0], [1, 311, 3, 510]);

        let mut color565 = ColorBuffer::new(ColorFormat::Rgb565, 1, 1, 1).unwrap();
        if let ColorPixels::Rgb565(px) = color565.pixels_mut() {
            px[0] = pack565(31, 40, 0);
        }
        accum.load_from(&color565, whole(1, 1), 1.0, false);
        assert_eq!(accum.pixels()[0], [32767, 20804, 0, 32767]);

        let mut colorf = ColorBuffer::new(ColorFormat::Float32 { alpha: true }, 1, 1, 1).unwrap();
        if let ColorPixels::Float32(px) = colorf.pixels_mut() {
            px[0] = [3.0, -1.11, 1e6, f32::NAN];
        }
        accum.load_from(&colorf, whole(1, 1), 1.0, false);
        assert_eq!(accum.pixels()[0], [32765, 29165, 0, 0]);
    }

    #[test]
    fn return_packs_like_mesa_per_format() {
        let accum = accum_with(&[[16447, 32742, -32768, 16457], [16000, 16000, 16000, 16000]]);
        let rect = whole(2, 1);

        let mut c8 = ColorBuffer::new(ColorFormat::Unorm8 { alpha: true }, 2, 1, 2).unwrap();
        accum.return_to(&mut c8, rect, 1.0, [true; 4]);
        let ColorPixels::Unorm8(px) = c8.pixels() else { unreachable!() };
        assert_eq!(px[0], [128, 255, 0, 128]);

        let mut c16 = ColorBuffer::new(ColorFormat::Unorm16 { alpha: true }, 2, 1, 2).unwrap();
        accum.return_to(&mut c16, rect, 0.5, [true; 4]);
        let ColorPixels::Unorm16(px) = c16.pixels() else { unreachable!() };
        // 32742.5 rounds up (Mesa adds 0.5 and truncates), not to even.
        assert_eq!(px[0][1], 32743);
        accum.return_to(&mut c16, rect, 1.0, [true; 4]);
        let ColorPixels::Unorm16(px) = c16.pixels() else { unreachable!() };
        assert_eq!(px[0][3], 32915);

        let mut cf = ColorBuffer::new(ColorFormat::Float32 { alpha: true }, 2, 1, 2).unwrap();
        accum.return_to(&mut cf, rect, 3.0, [true; 4]);
        let ColorPixels::Float32(px) = cf.pixels() else { unreachable!() };
        assert_eq!(px[0][2], -32768.0 * (3.0 / 32767.0));
        assert_eq!(px[1][0], 16000.0 * (3.0 / 32767.0));
        assert!(px[1][0] > 1.0, "float buffers are not clamped");

        let mut c565 = ColorBuffer::new(ColorFormat::Rgb565, 2, 1, 2).unwrap();
        accum.return_to(&mut c565, rect, 1.0, [true; 4]);
        let ColorPixels::Rgb565(px) = c565.pixels() else { unreachable!() };
        assert_eq!(px[1], pack565(15, 31, 15));
    }

    #[test]
    fn return_honours_the_channel_mask() {
        let accum = accum_with(&[[32767, 32767, 32767, 32767]]);
        let mut c8 = ColorBuffer::new(ColorFormat::Unorm8 { alpha: true }, 1, 1, 1).unwrap();
        c8.clear(whole(1, 1), [0.2, 0.4, 0.6, 0.8], [true; 4]);
        accum.return_to(&mut c8, whole(1, 1), 1.0, [false, true, false, true]);
        let ColorPixels::Unorm8(px) = c8.pixels() else { unreachable!() };
        assert_eq!(px[0], [51, 255, 153, 255]);

        let mut c565 = ColorBuffer::new(ColorFormat::Rgb565, 1, 1, 1).unwrap();
        accum.return_to(&mut c565, whole(1, 1), 1.0, [true, false, true, true]);
        let ColorPixels::Rgb565(px) = c565.pixels() else { unreachable!() };
        assert_eq!(px[0], pack565(31, 0, 31));
    }

    /// Mesa's float_to_ubyte trick equals clamping and rounding `f · 255` to nearest even
    /// (checked here against [`float_to_unorm`], an independent formulation).
    #[test]
    fn unorm8_packing_rounds_to_nearest_even() {
        // Every 61st float of [0, 1] plus the ties and the edges.
        let mut bits = 0u32;
        while bits <= 1.0f32.to_bits() {
            let f = f32::from_bits(bits);
            assert_eq!(pack_unorm8(f), float_to_unorm(f, 8) as u8, "{f:e}");
            bits += 61;
        }
        for n in 0..255 {
            let tie = (n as f32 + 0.5) / 255.0;
            assert_eq!(pack_unorm8(tie), float_to_unorm(tie, 8) as u8, "{tie:e}");
        }
        for f in [-1.0, 1.5, f32::NAN, f32::INFINITY, -0.0, 1.0] {
            assert_eq!(pack_unorm8(f), float_to_unorm(f, 8) as u8);
        }
    }
}

#[cfg(test)]
mod color_tests {
    use super::*;

    #[test]
    fn partial_clears_convert_as_llvmpipe_draws_them() {
        // Values measured on Mesa 22 llvmpipe (capi-tests/clear_conversions.c sweeps them all).
        let mut rgb = ColorBuffer::new(ColorFormat::Rgb565, 4, 4, 16).unwrap();
        rgb.clear(Rect::from_xywh(0, 0, 4, 4), [0.008, 0.992, 0.004, 1.0], [true; 4]);
        let ColorPixels::Rgb565(px) = rgb.pixels() else { unreachable!() };
        assert_eq!(px[0] & 0x07e0, 62 << 5);
        rgb.clear(Rect::from_xywh(0, 0, 2, 2), [0.008, 0.992, 0.004, 1.0], [true; 4]);
        let ColorPixels::Rgb565(px) = rgb.pixels() else { unreachable!() };
        assert_eq!(px[0] & 0x07e0, 63 << 5);

        let mut depth = DepthStencilBuffer::new(DepthStencilFormat::Depth16, 4, 16).unwrap();
        depth.clear_depth(Rect::from_xywh(0, 0, 4, 4), 0.1);
        let mut row = Vec::new();
        depth.read_depth_row(0, 0, 1, &mut row);
        depth.clear_depth(Rect::from_xywh(0, 0, 2, 2), 0.1);
        depth.read_depth_row(0, 0, 1, &mut row);
        assert_eq!(row, vec![0x199a, 0x1999]);
    }

    #[test]
    fn float_depth_clears_store_the_float_and_keep_stencil() {
        let mut ds = DepthStencilBuffer::new(DepthStencilFormat::Float32 { stencil: true }, 4, 16).unwrap();
        ds.clear_stencil(Rect::from_xywh(0, 0, 4, 4), 0x5a, 0xff);
        ds.clear_depth(Rect::from_xywh(0, 0, 4, 4), 0.1);
        let mut row = Vec::new();
        ds.read_depth_row(0, 0, 1, &mut row);
        assert_eq!(row, vec![0.1f32.to_bits()], "a whole clear stores 0.1f itself");
        assert_eq!(ds.depth_to_float(row[0]), 0.1);
        ds.clear_depth(Rect::from_xywh(0, 0, 2, 2), 2.0);
        ds.clear_depth(Rect::from_xywh(2, 0, 2, 2), -1.0);
        row.clear();
        ds.read_depth_row(0, 0, 4, &mut row);
        assert_eq!(row, vec![1.0f32.to_bits(), 1.0f32.to_bits(), 0, 0], "clears clamp to [0, 1]");
        let mut stencil = Vec::new();
        ds.read_stencil_row(0, 0, 4, &mut stencil);
        assert_eq!(stencil, vec![0x5a; 4]);
    }

    #[test]
    fn a_joint_depth_and_stencil_clear_stores_what_the_two_clears_store() {
        let packed = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let cases = [
            (Rect::from_xywh(0, 0, 4, 4), 0.1, 0x5a, 0xff),
            (Rect::from_xywh(1, 1, 2, 3), 0.7, 0x3c, 0xff),
            (Rect::from_xywh(0, 0, 4, 4), 0.3, 0xa5, 0x0f),
        ];
        for (rect, depth, stencil, mask) in cases {
            let mut joint = DepthStencilBuffer::new(packed, 4, 16).unwrap();
            let mut apart = DepthStencilBuffer::new(packed, 4, 16).unwrap();
            // Different earlier contents per pixel, so that a clear outside `rect` or of
            // masked bits would show.
            for ds in [&mut joint, &mut apart] {
                for i in 0..4 {
                    ds.clear_depth(Rect::from_xywh(i, 0, 1, 4), 0.2 * i as f64);
                    ds.clear_stencil(Rect::from_xywh(0, i, 4, 1), 0x11 * i as u8, 0xff);
                }
            }
            joint.clear_depth_and_stencil(rect, depth, stencil, mask);
            apart.clear_depth(rect, depth);
            apart.clear_stencil(rect, stencil, mask);
            let (DepthStencilPixels::Packed24(a), DepthStencilPixels::Packed24(b)) = (joint.pixels(), apart.pixels())
            else {
                unreachable!()
            };
            assert_eq!(a, b, "{rect:?}");
            // Pixel (1, 1) is inside every rectangle.
            assert_eq!(a[5] & 0x00ff_ffff, apart.depth_clear_value(rect, depth));
            if mask == 0xff {
                assert_eq!(a[5] >> 24, stencil as u32);
            }
        }
    }

    #[test]
    fn sixteen_bit_clears_break_ties_like_llvmpipe() {
        // 0.3 · 65535 rounds to 19660.5 in single precision: whole-buffer clears give 19661,
        // partial (scissored or masked) ones 19660, as measured on Mesa 22 llvmpipe.
        let format = ColorFormat::Unorm16 { alpha: true };
        let mut buffer = ColorBuffer::new(format, 4, 4, 16).unwrap();
        buffer.clear(Rect::from_xywh(0, 0, 4, 4), [0.3; 4], [true; 4]);
        let ColorPixels::Unorm16(px) = buffer.pixels() else { unreachable!() };
        assert_eq!(px[0], [19661; 4]);
        buffer.clear(Rect::from_xywh(0, 0, 2, 2), [0.3; 4], [true; 4]);
        buffer.clear(Rect::from_xywh(0, 0, 4, 4), [0.3; 4], [true, false, true, true]);
        let ColorPixels::Unorm16(px) = buffer.pixels() else { unreachable!() };
        assert_eq!(px[0], [19660; 4]);
        assert_eq!(px[15], [19660, 19661, 19660, 19660]);
    }
}
