//! Pixel rectangles: glBitmap and glDrawPixels (GL 2.1 sections 3.6.4 and 3.7).
//!
//! The client image is read when the command is issued (also when it is compiled into a
//! display list, with the unpack modes of that moment) into owned values: bits for
//! glBitmap, RGBA colors or window depths for glDrawPixels. Executing the command places
//! the image at the current raster position, scaled by the pixel zoom, as one
//! [`PixelRectJob`] of the deferred scene, so its fragments take the same per-fragment path
//! as primitives, in submission order. Nothing is drawn while the raster position is invalid.
//!
//! glCopyPixels reads the source rectangle at execution (after flushing the scene) and
//! draws it as glDrawPixels would. Stencil indices are written to the stencil buffer
//! under the stencil write mask; only the scissor box limits them.
//!
//! glPixelTransfer applies at execution: RGBA and depth scale and bias (then clamped to
//! [0, 1]), and the index shift and offset of stencil indices.
//!
//! GL_MAP_COLOR and GL_MAP_STENCIL look colors and stencil indices up in the glPixelMap
//! tables.
//!
//! GL_DEPTH_STENCIL (EXT_packed_depth_stencil, GL_UNSIGNED_INT_24_8) writes depth and
//! stencil values directly, as Mesa does; glCopyPixels of GL_DEPTH_STENCIL copies through
//! that format (so depth keeps 24 bits). Pixel transfer applies to both parts (GL 2.1
//! section 3.6.4 and EXT_packed_depth_stencil; Mesa 22 ignores it for this format).
//!
//! GL_COLOR_INDEX (RGBA mode): indices shifted and offset, through I_TO_I under
//! GL_MAP_COLOR, then through the I_TO_[RGBA] maps to colors (Mesa 22 matches without
//! shift, offset or GL_MAP_COLOR, which it ignores for this format).
use super::pixel_buffers::ClientBytes;
use super::read_pixels::{check_format_and_type, read_format, unknown_format_error, ReadFormat};
use super::selection::FeedbackVertex;
use super::state::PixelTransfer;
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::pixel::layout::ImageLayout;
use crate::pixel::unpack::{bitmap_bit, index_value};
use crate::pixel::unpack_rect::{unpack_components, unpack_rgba};
use crate::pixel::{ClientFormat, ClientType, PackModes};
use crate::setup::jobs::pixels::{PixelRectJob, PixelSource};
use std::ops::Range;
use std::sync::Arc;

/// Mesa nudges the raster position by this much before flooring it for glBitmap, so that
/// positions a rounding error below an integer land on it.
const BITMAP_EPSILON: f32 = 0.0001;

/// A glDrawPixels image read from client memory.
#[derive(Clone, Debug)]
pub enum DrawImage {
    Colors(Arc<Vec<[f32; 4]>>),
    Depths(Arc<Vec<f32>>),
    Stencil(Arc<Vec<u8>>),
    /// GL_DEPTH_STENCIL (GL_UNSIGNED_INT_24_8): depths in [0, 1] and stencil indices.
    DepthStencil {
        depths: Arc<Vec<f32>>,
        stencil: Arc<Vec<u8>>,
    },
    /// GL_COLOR_INDEX: indices (fractions kept), converted to colors through the
    /// GL_PIXEL_MAP_I_TO_[RGBA] tables at execution.
    ColorIndex(Arc<Vec<f64>>),
}

/// A glDrawPixels command's image and the buffer it needs.
#[derive(Clone, Debug)]
pub struct DrawPixelsData {
    image: DrawImage,
    format: ClientFormat,
}

/// GL_INDEX_SHIFT and GL_INDEX_OFFSET applied to a stencil index, kept to 8 bits.
fn shift_index(value: i64, shift: i32, offset: i32) -> u8 {
    let shifted = if shift >= 0 { value << shift.min(62) } else { value >> (-shift).min(62) };
    shifted.wrapping_add(offset as i64) as u8
}

/// A stencil index of an integer or float type, kept to the stencil buffer's 8 bits.
fn stencil_index(bytes: &[u8], ty: ClientType, swap: bool) -> u8 {
    index_value(bytes, ty, swap) as i64 as u8
}

impl Context {
    /// The bits of a `width` × `height` bitmap under the unpack modes (`Ok(None)`: NULL or
    /// an empty bitmap); `source` maps the byte span the bitmap occupies to the caller's bytes.
    pub fn unpack_bitmap<'a>(
        &self,
        width: i32,
        height: i32,
        source: impl FnOnce(Range<usize>) -> ClientBytes<'a>,
    ) -> Result<Option<Arc<Vec<bool>>>, GLenum> {
        if width < 0 || height < 0 {
            return Err(GL_INVALID_VALUE);
        }
        let (w, h) = (width as usize, height as usize);
        if w == 0 || h == 0 {
            return Ok(None);
        }
        let modes = PackModes::from(&self.pixel_store.unpack);
        let layout =
            ImageLayout::new(ClientFormat::StencilIndex, ClientType::Bitmap, &modes, w).ok_or(GL_INVALID_VALUE)?;
        let span = layout.span(0..w, 0..h).ok_or(GL_INVALID_VALUE)?;
        let start = span.start;
        let Some(client) = source(span)? else {
            return Ok(None);
        };
        let mut bits = Vec::new();
        bits.try_reserve_exact(w * h).map_err(|_| GL_OUT_OF_MEMORY)?;
        for row in 0..h {
            let row_offset = layout.row_offset(row).ok_or(GL_INVALID_VALUE)?;
            for col in 0..w {
                let bit = layout.bit_index(col);
                let byte = client.get(row_offset + bit / 8 - start).copied().unwrap_or(0);
                bits.push(bitmap_bit(byte, bit, modes.lsb_first));
            }
        }
        Ok(Some(Arc::new(bits)))
    }

    /// glBitmap with its bits already read.
    #[allow(clippy::too_many_arguments)]
    pub fn bitmap(
        &mut self,
        width: i32,
        height: i32,
        origin: [f32; 2],
        advance: [f32; 2],
        bits: &Result<Option<Arc<Vec<bool>>>, GLenum>,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        let bits = match bits {
            Ok(bits) => bits,
            Err(error) => return self.error(*error),
        };
        if !self.state.current.raster.valid {
            return;
        }
        let raster = self.state.current.raster;
        self.feedback_raster(GL_BITMAP_TOKEN);
        if let Some(bits) = bits {
            let x = (raster.window[0] + BITMAP_EPSILON - origin[0]).floor() as f64;
            let y = (raster.window[1] + BITMAP_EPSILON - origin[1]).floor() as f64;
            let source = PixelSource::Bitmap { bits: bits.clone(), color: raster.color };
            self.draw_image([x, y], [1.0, 1.0], width as usize, height as usize, source);
        }
        let window = &mut self.state.current.raster.window;
        window[0] += advance[0];
        window[1] += advance[1];
    }

    /// In feedback mode, reports a pixel command's token and the raster position.
    fn feedback_raster(&mut self, token: GLenum) {
        if self.selection.mode == GL_FEEDBACK {
            let r = self.state.current.raster;
            let vertex = FeedbackVertex { window: r.window, color: r.color, tex: r.tex_coords[0] };
            self.feedback_token(token, None, &[vertex]);
        }
    }

    /// Adds an image at window position `origin` to the scene.
    fn draw_image(&mut self, origin: [f64; 2], zoom: [f64; 2], width: usize, height: usize, source: PixelSource) {
        if !self.rendering() {
            return;
        }
        let raster = self.state.current.raster;
        self.draw_pixel_rect(|needed| PixelRectJob {
            rect: PixelRectJob::window_rect(origin, zoom, width, height),
            origin,
            zoom,
            width,
            height,
            z: raster.window[2],
            varyings: needed
                .iter()
                .map(|a| a.pick(&raster.secondary_color, raster.distance, &raster.tex_coords, 1.0 / raster.window[3]))
                .collect(),
            source,
        });
    }

    /// Reads glDrawPixels' image under the unpack modes, with the argument errors that do
    /// not depend on the framebuffer.
    pub fn unpack_draw_pixels<'a>(
        &self,
        width: i32,
        height: i32,
        format: GLenum,
        ty: GLenum,
        source: impl FnOnce(Range<usize>) -> ClientBytes<'a>,
    ) -> Result<Option<DrawPixelsData>, GLenum> {
        if width < 0 || height < 0 {
            return Err(GL_INVALID_VALUE);
        }
        let read = read_format(format).ok_or_else(|| unknown_format_error(ty))?;
        let client_type = check_format_and_type(read, ty)?;
        // Color indices are laid out as stencil indices (one component, bitmaps allowed).
        let (format, color_index) = match read {
            ReadFormat::Client(format) => (format, false),
            ReadFormat::ColorIndex => (ClientFormat::StencilIndex, true),
        };
        let (w, h) = (width as usize, height as usize);
        if w == 0 || h == 0 {
            return Ok(None);
        }
        let modes = PackModes::from(&self.pixel_store.unpack);
        let layout = ImageLayout::new(format, client_type, &modes, w).ok_or(GL_INVALID_VALUE)?;
        let span = layout.span(0..w, 0..h).ok_or(GL_INVALID_VALUE)?;
        let start = span.start;
        let Some(client) = source(span)? else {
            return Ok(None);
        };
        let pixel_bytes = layout.pixel_bytes();
        let pixel = |col: usize, row: usize| -> Option<&[u8]> {
            let at = layout.pixel_offset(col, row)? - start;
            client.get(at..at + pixel_bytes)
        };
        let count = w.checked_mul(h).ok_or(GL_OUT_OF_MEMORY)?;
        let image = if color_index {
            let mut values = Vec::new();
            values.try_reserve_exact(count).map_err(|_| GL_OUT_OF_MEMORY)?;
            for row in 0..h {
                for col in 0..w {
                    let value = if client_type == ClientType::Bitmap {
                        let at = layout.pixel_offset(col, row).map(|o| o - start);
                        let byte = at.and_then(|o| client.get(o)).copied().unwrap_or(0);
                        let bit = layout.bit_index(col);
                        bitmap_bit(byte, bit, modes.lsb_first) as u8 as f64
                    } else {
                        pixel(col, row).map_or(0.0, |bytes| index_value(bytes, client_type, modes.swap_bytes))
                    };
                    values.push(value);
                }
            }
            return Ok(Some(DrawPixelsData {
                image: DrawImage::ColorIndex(Arc::new(values)),
                format: ClientFormat::Rgba,
            }));
        } else if format == ClientFormat::DepthStencil {
            // GL_UNSIGNED_INT_24_8 (EXT_packed_depth_stencil): depth in the high 24 bits,
            // stencil in the low 8; GL_FLOAT_32_UNSIGNED_INT_24_8_REV (ARB_depth_buffer_float):
            // a float depth, then a word with the stencil index.
            let (mut depths, mut stencil) = (Vec::new(), Vec::new());
            depths.try_reserve_exact(count).map_err(|_| GL_OUT_OF_MEMORY)?;
            stencil.try_reserve_exact(count).map_err(|_| GL_OUT_OF_MEMORY)?;
            for row in 0..h {
                for col in 0..w {
                    if client_type == ClientType::Float32UnsignedInt24_8Rev {
                        let (depth, index) = pixel(col, row)
                            .map_or((0.0, 0), |b| crate::pixel::depth::unpack_depth_stencil_float(b, modes.swap_bytes));
                        depths.push(depth);
                        stencil.push(index);
                        continue;
                    }
                    let word = pixel(col, row).map_or(0, |b| {
                        let word = u32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
                        if modes.swap_bytes {
                            word.swap_bytes()
                        } else {
                            word
                        }
                    });
                    depths.push(((word >> 8) as f64 / 0xff_ffff as f64) as f32);
                    stencil.push(word as u8);
                }
            }
            DrawImage::DepthStencil { depths: Arc::new(depths), stencil: Arc::new(stencil) }
        } else if format == ClientFormat::StencilIndex {
            let mut values = Vec::new();
            values.try_reserve_exact(count).map_err(|_| GL_OUT_OF_MEMORY)?;
            for row in 0..h {
                for col in 0..w {
                    let value = if client_type == ClientType::Bitmap {
                        let at = layout.pixel_offset(col, row).map(|o| o - start);
                        let byte = at.and_then(|o| client.get(o)).copied().unwrap_or(0);
                        let bit = layout.bit_index(col);
                        bitmap_bit(byte, bit, modes.lsb_first) as u8
                    } else {
                        pixel(col, row).map_or(0, |bytes| stencil_index(bytes, client_type, modes.swap_bytes))
                    };
                    values.push(value);
                }
            }
            DrawImage::Stencil(Arc::new(values))
        } else if format == ClientFormat::DepthComponent {
            let mut depths = Vec::new();
            depths.try_reserve_exact(count).map_err(|_| GL_OUT_OF_MEMORY)?;
            for row in 0..h {
                for col in 0..w {
                    let mut d = [0.0f32];
                    if let Some(bytes) = pixel(col, row) {
                        unpack_components(bytes, format, client_type, modes.swap_bytes, &mut d);
                    }
                    // Clamped to [0, 1].
                    depths.push(d[0].clamp(0.0, 1.0));
                }
            }
            DrawImage::Depths(Arc::new(depths))
        } else {
            let mut colors = Vec::new();
            colors.try_reserve_exact(count).map_err(|_| GL_OUT_OF_MEMORY)?;
            for row in 0..h {
                for col in 0..w {
                    let rgba = pixel(col, row)
                        .map(|bytes| unpack_rgba(bytes, format, client_type, modes.swap_bytes))
                        .unwrap_or([0.0, 0.0, 0.0, 1.0]);
                    colors.push(rgba);
                }
            }
            DrawImage::Colors(Arc::new(colors))
        };
        Ok(Some(DrawPixelsData { image, format }))
    }

    /// glDrawPixels with its image already read.
    pub fn draw_pixels(&mut self, width: i32, height: i32, data: &Result<Option<DrawPixelsData>, GLenum>) {
        if !self.check_outside_begin_end() {
            return;
        }
        let data = match data {
            Ok(Some(data)) => data,
            Ok(None) => return,
            Err(error) => return self.error(*error),
        };
        let depth_stencil = self.draw_config().depth_stencil;
        let missing = match data.format {
            ClientFormat::DepthComponent => depth_stencil.depth_bits() == 0,
            ClientFormat::StencilIndex => depth_stencil.stencil_bits() == 0,
            ClientFormat::DepthStencil => depth_stencil.depth_bits() == 0 || depth_stencil.stencil_bits() == 0,
            _ => false,
        };
        if missing {
            return self.error(GL_INVALID_OPERATION);
        }
        let raster = self.state.current.raster;
        if !raster.valid {
            return;
        }
        self.feedback_raster(GL_DRAW_PIXEL_TOKEN);
        let clamp = !self.draw_config().color.is_float();
        let t = self.state.pixel_mode.transfer;
        let identity = t == PixelTransfer::default();
        let source = match &data.image {
            DrawImage::Colors(colors) if clamp || !identity => {
                // The transfer's final conversion clamps to [0, 1]; so do fixed-point buffers.
                // GL_MAP_COLOR looks each clamped component up in its [RGBA]_TO_[RGBA] table.
                let maps = &self.state.pixel_mode.maps;
                let lookup = |i: usize, c: f32| {
                    let table = &maps[6 + i];
                    table[(c * (table.len() - 1) as f32).round() as usize]
                };
                let transfer = |c: &[f32; 4]| {
                    std::array::from_fn(|i| {
                        let c = (c[i] * t.scale[i] + t.bias[i]).clamp(0.0, 1.0);
                        if t.map_color {
                            lookup(i, c)
                        } else {
                            c
                        }
                    })
                };
                PixelSource::Colors(Arc::new(colors.iter().map(transfer).collect()))
            }
            DrawImage::Colors(colors) => PixelSource::Colors(colors.clone()),
            // Depth components become window depths as they are (no depth range mapping).
            DrawImage::Depths(depths) if identity => {
                PixelSource::Depths { depths: depths.clone(), color: raster.color }
            }
            DrawImage::Depths(depths) => {
                let mapped = depths.iter().map(|&d| (d * t.depth_scale + t.depth_bias).clamp(0.0, 1.0)).collect();
                PixelSource::Depths { depths: Arc::new(mapped), color: raster.color }
            }
            DrawImage::Stencil(values) => PixelSource::Stencil {
                values: self.transfer_stencil(values),
                write_mask: self.state.stencil.front.write_mask as u8,
            },
            DrawImage::DepthStencil { depths, stencil } => {
                // As Mesa: the depth and stencil values are written as they are (within the
                // scissor box, under the write masks; no fragment tests, no color).
                let depths = if identity {
                    depths.clone()
                } else {
                    Arc::new(depths.iter().map(|&d| (d * t.depth_scale + t.depth_bias).clamp(0.0, 1.0)).collect())
                };
                PixelSource::DepthStencil {
                    depths,
                    stencil: self.transfer_stencil(stencil),
                    depth_write: self.state.depth.write_mask,
                    stencil_mask: self.state.stencil.front.write_mask as u8,
                }
            }
            DrawImage::ColorIndex(indices) => {
                // GL 2.1 section 3.6.5: GL_INDEX_SHIFT and GL_INDEX_OFFSET, then (RGBA groups
                // being required, as tessera always draws RGBA) the I_TO_[RGBA] lookups, each
                // index masked to its table's size. GL_MAP_COLOR's I_TO_I lookup is only for
                // indices that stay indices, so it does not apply here (nor does Mesa 22).
                let maps = &self.state.pixel_mode.maps;
                let scale = 2f64.powi(t.index_shift.clamp(-62, 62));
                let lookup =
                    |table: &Vec<f32>, index: f64| table[(index.floor() as i64 & (table.len() as i64 - 1)) as usize];
                let to_rgba = |&v: &f64| -> [f32; 4] {
                    let index = v * scale + t.index_offset as f64;
                    std::array::from_fn(|c| lookup(&maps[2 + c], index))
                };
                PixelSource::Colors(Arc::new(indices.iter().map(to_rgba).collect()))
            }
        };
        // The raster position rounded to the nearest pixel corner, as Mesa (and SGI's
        // implementation) do; the specification leaves the sampling of a fractional position open.
        let zoom = self.state.pixel_mode.zoom.map(|z| z as f64);
        let origin = raster.window.map(|c| (c as f64 + 0.5).floor());
        let origin = [origin[0], origin[1]];
        self.draw_image(origin, zoom, width as usize, height as usize, source);
    }
}

impl Context {
    /// GL_INDEX_SHIFT, GL_INDEX_OFFSET and GL_MAP_STENCIL applied to stencil indices.
    fn transfer_stencil(&self, values: &Arc<Vec<u8>>) -> Arc<Vec<u8>> {
        let t = self.state.pixel_mode.transfer;
        if t.index_shift == 0 && t.index_offset == 0 && !t.map_stencil {
            return values.clone();
        }
        // GL_MAP_STENCIL: the shifted index, masked to the table size, looked up in
        // GL_PIXEL_MAP_S_TO_S.
        let table = &self.state.pixel_mode.maps[1];
        let map = |v: u8| {
            let shifted = shift_index(v as i64, t.index_shift, t.index_offset);
            if t.map_stencil {
                table[shifted as usize & (table.len() - 1)] as i64 as u8
            } else {
                shifted
            }
        };
        Arc::new(values.iter().map(|&v| map(v)).collect())
    }

    /// glCopyPixels: the rectangle at (x, y) of the read buffer (GL_COLOR), the depth buffer
    /// (GL_DEPTH) or the stencil buffer (GL_STENCIL) drawn at the raster position.
    pub fn copy_pixels(&mut self, x: i32, y: i32, width: i32, height: i32, ty: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        let ds = self.read_config().depth_stencil;
        let both = ds.depth_bits() > 0 && ds.stencil_bits() > 0;
        let (format, pixel_bytes) = match ty {
            GL_COLOR => (GL_RGBA, 16),
            GL_DEPTH if ds.depth_bits() > 0 => (GL_DEPTH_COMPONENT, 4),
            GL_STENCIL if ds.stencil_bits() > 0 => (GL_STENCIL_INDEX, 4),
            // EXT_packed_depth_stencil.
            GL_DEPTH_STENCIL if both => (GL_DEPTH_STENCIL, 4),
            GL_DEPTH | GL_STENCIL | GL_DEPTH_STENCIL => return self.error(GL_INVALID_OPERATION),
            _ => return self.error(GL_INVALID_ENUM),
        };
        if !self.state.current.raster.valid {
            return;
        }
        if !self.rendering() {
            return self.feedback_raster(GL_COPY_PIXEL_TOKEN);
        }
        if width == 0 || height == 0 {
            return;
        }
        // Pixels outside the read buffer are undefined in GL; they read as zero, as in Mesa 22
        // (llvmpipe draws zero colors, depths and stencil indices for them: capi
        // pixel_depth_stencil).
        //
        // Memory stays bounded for hostile sizes: at a zoom of ±1 only the source columns and
        // rows whose destination lies in the draw framebuffer are copied (the raster position
        // moves by the whole pixels cut off, so every fragment lands where it would have), and
        // a copy needing more than COPY_LIMIT_BYTES of staging is GL_OUT_OF_MEMORY.
        let (mut x, mut y, mut width, mut height) = (x, y, width, height);
        let raster = self.state.current.raster;
        let zoom = self.state.pixel_mode.zoom;
        // (Without a complete draw framebuffer nothing is cut: the draw reports what is wrong.)
        let draw_size = self.framebuffer_shape(true).map(|(w, h, _)| (w as i64, h as i64));
        let origin = raster.window.map(|c| (c as f64 + 0.5).floor());
        let mut shift = [0f64; 2];
        let limits = draw_size.map(|(w, h)| [w, h]);
        for (axis, (start, size)) in [(&mut x, &mut width), (&mut y, &mut height)].into_iter().enumerate() {
            let z = zoom[axis];
            let Some(limit) = limits.map(|l| l[axis]) else { continue };
            if (z != 1.0 && z != -1.0) || !origin[axis].is_finite() {
                continue;
            }
            // Destination pixel of source offset i: origin + i (zoom 1) or origin - 1 - i (zoom -1).
            let o = origin[axis].clamp(-(1i64 << 40) as f64, (1i64 << 40) as f64) as i64;
            let (first, last) = if z > 0.0 { (-o, limit - 1 - o) } else { (o - limit, o - 1) };
            let first = first.clamp(0, *size as i64);
            let last = last.clamp(-1, *size as i64 - 1);
            if last < first {
                return;
            }
            shift[axis] = first as f64 * z as f64;
            *start = (*start as i64 + first).clamp(i32::MIN as i64, i32::MAX as i64) as i32;
            *size = (last - first + 1) as i32;
        }
        let Some(len) = (width as usize)
            .checked_mul(height as usize)
            .and_then(|n| n.checked_mul(pixel_bytes))
            .filter(|&n| n <= COPY_LIMIT_BYTES)
        else {
            return self.error(GL_OUT_OF_MEMORY);
        };
        let mut bytes = Vec::new();
        if bytes.try_reserve_exact(len).is_err() {
            return self.error(GL_OUT_OF_MEMORY);
        }
        bytes.resize(len, 0);
        // Read as glReadPixels with tightly packed floats (integers for stencil), then
        // unpacked as glDrawPixels with the same layout.
        let tight = crate::context::state::PixelStoreModes { alignment: 1, ..Default::default() };
        let saved = std::mem::replace(&mut self.pixel_store.pack, tight);
        let read_type = match ty {
            GL_STENCIL => GL_UNSIGNED_INT,
            GL_DEPTH_STENCIL => GL_UNSIGNED_INT_24_8,
            _ => GL_FLOAT,
        };
        let earlier = self.take_error();
        self.read_pixels(x, y, width, height, format, read_type, |span| Ok(bytes.get_mut(span)));
        let read_error = self.take_error();
        self.error(earlier);
        self.pixel_store.pack = saved;
        if read_error != GL_NO_ERROR {
            return self.error(read_error);
        }
        let saved = std::mem::replace(&mut self.pixel_store.unpack, tight);
        let data = self.unpack_draw_pixels(width, height, format, read_type, |span| Ok(bytes.get(span)));
        self.pixel_store.unpack = saved;
        drop(bytes);
        let saved_window = self.state.current.raster.window;
        self.state.current.raster.window[0] += shift[0] as f32;
        self.state.current.raster.window[1] += shift[1] as f32;
        self.draw_pixels(width, height, &data);
        self.state.current.raster.window = saved_window;
        if len > crate::setup::Scene::BUDGET_BYTES {
            // A large image is rendered now rather than held until the next flush point.
            self.flush_rendering();
        }
    }
}

/// The most staging memory one glCopyPixels may take (GL_OUT_OF_MEMORY above it).
const COPY_LIMIT_BYTES: usize = 1 << 30;

impl Context {
    /// glPixelTransfer.
    pub fn pixel_transfer(&mut self, pname: GLenum, param: f32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let t = &mut self.state.pixel_mode.transfer;
        match pname {
            GL_RED_SCALE => t.scale[0] = param,
            GL_GREEN_SCALE => t.scale[1] = param,
            GL_BLUE_SCALE => t.scale[2] = param,
            GL_ALPHA_SCALE => t.scale[3] = param,
            GL_RED_BIAS => t.bias[0] = param,
            GL_GREEN_BIAS => t.bias[1] = param,
            GL_BLUE_BIAS => t.bias[2] = param,
            GL_ALPHA_BIAS => t.bias[3] = param,
            GL_DEPTH_SCALE => t.depth_scale = param,
            GL_DEPTH_BIAS => t.depth_bias = param,
            GL_INDEX_SHIFT => t.index_shift = param.round() as i32,
            GL_INDEX_OFFSET => t.index_offset = param.round() as i32,
            GL_MAP_COLOR => t.map_color = param != 0.0,
            GL_MAP_STENCIL => t.map_stencil = param != 0.0,
            _ => self.error(GL_INVALID_ENUM),
        }
    }

    /// The glGet values of glPixelTransfer's state; `None` for other pnames.
    pub(crate) fn pixel_transfer_values(&self, pname: GLenum) -> Option<Vec<super::get::Value>> {
        use super::get::Value::*;
        let t = &self.state.pixel_mode.transfer;
        Some(vec![match pname {
            GL_RED_SCALE => Float(t.scale[0]),
            GL_GREEN_SCALE => Float(t.scale[1]),
            GL_BLUE_SCALE => Float(t.scale[2]),
            GL_ALPHA_SCALE => Float(t.scale[3]),
            GL_RED_BIAS => Float(t.bias[0]),
            GL_GREEN_BIAS => Float(t.bias[1]),
            GL_BLUE_BIAS => Float(t.bias[2]),
            GL_ALPHA_BIAS => Float(t.bias[3]),
            GL_DEPTH_SCALE => Float(t.depth_scale),
            GL_DEPTH_BIAS => Float(t.depth_bias),
            GL_INDEX_SHIFT => Int(t.index_shift),
            GL_INDEX_OFFSET => Int(t.index_offset),
            GL_MAP_COLOR => Bool(t.map_color),
            GL_MAP_STENCIL => Bool(t.map_stencil),
            _ => return None,
        }])
    }
}

/// GL_MAX_PIXEL_MAP_TABLE (Mesa's value).
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// The table index of a glPixelMap `map` enum, and whether it is indexed by color or
/// stencil indices (GL_PIXEL_MAP_I_TO_*, S_TO_S), whose sizes must be powers of two (GL 2.1;
/// Mesa 22 does not check GL_PIXEL_MAP_I_TO_I).
fn pixel_map_index(map: GLenum) -> Option<(usize, bool)> {
    (GL_PIXEL_MAP_I_TO_I..=GL_PIXEL_MAP_A_TO_A)
        .contains(&map)
        .then(|| ((map - GL_PIXEL_MAP_I_TO_I) as usize, map <= GL_PIXEL_MAP_I_TO_A))
}

/// How glPixelMapuiv/usv values become table entries: color maps are normalized (`max` is
/// 2³²−1 or 2¹⁶−1), index maps keep their values.
pub fn pixel_map_from_integer(map: GLenum, value: u32, max: f64) -> f32 {
    match pixel_map_index(map) {
        Some((i, _)) if i >= 2 && map != GL_PIXEL_MAP_S_TO_S => (value as f64 / max) as f32,
        _ => value as f32,
    }
}

impl Context {
    /// glPixelMap with the values as floats (already normalized for the integer forms).
    pub fn pixel_map(&mut self, map: GLenum, values: &[f32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some((index, power_of_two)) = pixel_map_index(map) else {
            return self.error(GL_INVALID_ENUM);
        };
        let size = values.len();
        if !(1..=MAX_PIXEL_MAP_TABLE).contains(&size) || (power_of_two && !size.is_power_of_two()) {
            return self.error(GL_INVALID_VALUE);
        }
        // Color maps (I_TO_[RGBA], [RGBA]_TO_[RGBA]) hold values clamped to [0, 1].
        let clamp = index >= 2;
        let table = values.iter().map(|&v| if clamp { v.clamp(0.0, 1.0) } else { v }).collect();
        self.state.pixel_mode.maps[index] = table;
    }

    /// glGetPixelMap: the table of `map` (`None` with GL_INVALID_ENUM for another enum).
    pub fn get_pixel_map(&mut self, map: GLenum) -> Option<Vec<f32>> {
        if !self.check_outside_begin_end() {
            return None;
        }
        match pixel_map_index(map) {
            Some((index, _)) => Some(self.state.pixel_mode.maps[index].clone()),
            None => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// The glGet values of the pixel map sizes; `None` for other pnames.
    pub(crate) fn pixel_map_values(&self, pname: GLenum) -> Option<Vec<super::get::Value>> {
        use super::get::Value::Int;
        if pname == GL_MAX_PIXEL_MAP_TABLE {
            return Some(vec![Int(MAX_PIXEL_MAP_TABLE as i32)]);
        }
        let index = (GL_PIXEL_MAP_I_TO_I_SIZE..=GL_PIXEL_MAP_A_TO_A_SIZE)
            .contains(&pname)
            .then(|| (pname - GL_PIXEL_MAP_I_TO_I_SIZE) as usize)?;
        Some(vec![Int(self.state.pixel_mode.maps[index].len() as i32)])
    }
}
