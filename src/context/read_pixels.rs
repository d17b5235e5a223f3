//! glReadPixels and glPixelStore.
//!
//! glReadPixels validates as Mesa 22 does, in Mesa's order (the specification leaves the
//! order open): inside glBegin/glEnd, then a negative size (GL_INVALID_VALUE), then no depth
//! buffer for depth formats or no stencil buffer for GL_STENCIL_INDEX (GL_INVALID_OPERATION),
//! then the format/type pair (GL_INVALID_ENUM, or GL_INVALID_OPERATION for a packed type of
//! the wrong component count and for GL_UNSIGNED_INT_24_8 with anything but
//! GL_DEPTH_STENCIL), then the read buffer GL_NONE for color formats, GL_DEPTH_STENCIL
//! without a stencil buffer and GL_COLOR_INDEX (no color-index buffers exist), all
//! GL_INVALID_OPERATION. An unknown `format` is
//! GL_INVALID_ENUM at once (GL_INVALID_OPERATION with a packed type, whose rule Mesa checks
//! first): Mesa 22 looks for a stencil buffer first and reports GL_INVALID_OPERATION when
//! there is none, which the specification does not allow.
//!
//! The rectangle is then clipped to the framebuffer; pixels outside it are not written, and
//! the client image keeps its layout (row length, skips) as if nothing had been clipped. The
//! bytes the clipped read touches are computed here, so that the API edge only has to turn
//! the caller's pointer into exactly that slice. The conversions themselves live in
//! [`crate::pixel`].
//!
//! Color values are clamped to [0, 1] when GL_CLAMP_READ_COLOR says so (GL_FIXED_ONLY:
//! only for fixed-point buffers, as the specification and ARB_color_buffer_float define it)
//! or when the type is not a float type. Mesa 22 treats its OSMesa float buffers as
//! fixed-point here and clamps them under GL_FIXED_ONLY; tessera does not.
use super::pixel_buffers::ClientBytesMut;
use super::state::PixelStoreModes;
use super::Context;
use crate::framebuffer::{Framebuffer, Rect};
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::pixel::color::{ColorPlan, ColorScratch};
use crate::pixel::convert::pixel_store_round;
use crate::pixel::depth::{
    pack_depth_row, pack_depth_stencil_float_row, pack_depth_stencil_row, pack_stencil_bitmap_row, pack_stencil_row,
};
use crate::pixel::layout::ImageLayout;
use crate::pixel::{ClientFormat, ClientType, PackModes, PackedType};
use std::ops::Range;

/// A glReadPixels `format`: a client format, or GL_COLOR_INDEX (valid, but never readable
/// from RGBA buffers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ReadFormat {
    Client(ClientFormat),
    ColorIndex,
}

pub(crate) fn read_format(format: GLenum) -> Option<ReadFormat> {
    use ClientFormat::*;
    Some(ReadFormat::Client(match format {
        GL_RGBA => Rgba,
        GL_BGRA => Bgra,
        GL_RGB => Rgb,
        GL_BGR => Bgr,
        GL_RED => Red,
        GL_GREEN => Green,
        GL_BLUE => Blue,
        GL_ALPHA => Alpha,
        GL_LUMINANCE => Luminance,
        GL_LUMINANCE_ALPHA => LuminanceAlpha,
        GL_DEPTH_COMPONENT => DepthComponent,
        GL_STENCIL_INDEX => StencilIndex,
        GL_DEPTH_STENCIL => DepthStencil,
        GL_COLOR_INDEX => return Some(ReadFormat::ColorIndex),
        _ => return None,
    }))
}

/// The error for a `format` no pixel transfer knows, given with `ty`: as in Mesa (whose
/// type rules come before the format's validity; the GL 2.1 spec names both errors and no
/// order), GL_INVALID_OPERATION when `ty` is a packed type, whose format rule excludes every
/// unknown format, else GL_INVALID_ENUM. Shared by glReadPixels, glDrawPixels and the
/// texture image commands.
pub(crate) fn unknown_format_error(ty: GLenum) -> GLenum {
    match client_type(ty) {
        Some(ClientType::Packed(_) | ClientType::UnsignedInt24_8 | ClientType::Float32UnsignedInt24_8Rev) => {
            GL_INVALID_OPERATION
        }
        _ => GL_INVALID_ENUM,
    }
}

pub(crate) fn client_type(ty: GLenum) -> Option<ClientType> {
    use PackedType::*;
    Some(match ty {
        GL_UNSIGNED_BYTE => ClientType::UnsignedByte,
        GL_BYTE => ClientType::Byte,
        GL_UNSIGNED_SHORT => ClientType::UnsignedShort,
        GL_SHORT => ClientType::Short,
        GL_UNSIGNED_INT => ClientType::UnsignedInt,
        GL_INT => ClientType::Int,
        GL_FLOAT => ClientType::Float,
        GL_HALF_FLOAT => ClientType::HalfFloat,
        GL_BITMAP => ClientType::Bitmap,
        GL_UNSIGNED_INT_24_8 => ClientType::UnsignedInt24_8,
        GL_FLOAT_32_UNSIGNED_INT_24_8_REV => ClientType::Float32UnsignedInt24_8Rev,
        GL_UNSIGNED_BYTE_3_3_2 => ClientType::Packed(UnsignedByte332),
        GL_UNSIGNED_BYTE_2_3_3_REV => ClientType::Packed(UnsignedByte233Rev),
        GL_UNSIGNED_SHORT_5_6_5 => ClientType::Packed(UnsignedShort565),
        GL_UNSIGNED_SHORT_5_6_5_REV => ClientType::Packed(UnsignedShort565Rev),
        GL_UNSIGNED_SHORT_4_4_4_4 => ClientType::Packed(UnsignedShort4444),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => ClientType::Packed(UnsignedShort4444Rev),
        GL_UNSIGNED_SHORT_5_5_5_1 => ClientType::Packed(UnsignedShort5551),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => ClientType::Packed(UnsignedShort1555Rev),
        GL_UNSIGNED_INT_8_8_8_8 => ClientType::Packed(UnsignedInt8888),
        GL_UNSIGNED_INT_8_8_8_8_REV => ClientType::Packed(UnsignedInt8888Rev),
        GL_UNSIGNED_INT_10_10_10_2 => ClientType::Packed(UnsignedInt1010102),
        GL_UNSIGNED_INT_2_10_10_10_REV => ClientType::Packed(UnsignedInt2101010Rev),
        _ => return None,
    })
}

/// The format/type rules of glReadPixels (Mesa's `_mesa_error_check_format_and_type` for
/// desktop GL, restricted to what GL 2.1 and ARB_half_float_pixel define).
pub(crate) fn check_format_and_type(format: ReadFormat, ty: GLenum) -> Result<ClientType, GLenum> {
    use ClientFormat::*;
    if format == ReadFormat::Client(DepthStencil)
        && ty != GL_UNSIGNED_INT_24_8
        && ty != GL_FLOAT_32_UNSIGNED_INT_24_8_REV
    {
        return Err(GL_INVALID_ENUM);
    }
    let ty = client_type(ty).ok_or(GL_INVALID_ENUM)?;
    // Type-specific rules come first, as in Mesa.
    match (ty, format) {
        (ClientType::Bitmap, ReadFormat::ColorIndex | ReadFormat::Client(StencilIndex)) => return Ok(ty),
        (ClientType::Bitmap, _) => return Err(GL_INVALID_ENUM),
        (ClientType::Packed(packed), ReadFormat::Client(f)) if packed.accepts(f) => return Ok(ty),
        (ClientType::Packed(_), _) => return Err(GL_INVALID_OPERATION),
        (ClientType::UnsignedInt24_8 | ClientType::Float32UnsignedInt24_8Rev, ReadFormat::Client(DepthStencil)) => {
            return Ok(ty)
        }
        (ClientType::UnsignedInt24_8 | ClientType::Float32UnsignedInt24_8Rev, _) => return Err(GL_INVALID_OPERATION),
        _ => {}
    }
    // Every remaining type is an array type, which every remaining format accepts.
    Ok(ty)
}

/// What one glReadPixels call reads, after validation and clipping.
struct ReadJob {
    format: ClientFormat,
    ty: ClientType,
    modes: PackModes,
    layout: ImageLayout,
    /// The clipped rectangle in window coordinates.
    rect: Rect,
    /// Column and row of the clipped rectangle's first pixel in the client image.
    first_col: usize,
    first_row: usize,
    /// The bytes touched, relative to the client pointer.
    span: Range<usize>,
    clamp_read_color: GLenum,
}

impl From<&PixelStoreModes> for PackModes {
    fn from(m: &PixelStoreModes) -> PackModes {
        PackModes {
            swap_bytes: m.swap_bytes,
            lsb_first: m.lsb_first,
            row_length: m.row_length.max(0) as usize,
            skip_rows: m.skip_rows.max(0) as usize,
            skip_pixels: m.skip_pixels.max(0) as usize,
            alignment: m.alignment.max(1) as usize,
        }
    }
}

/// One glPixelStore parameter, for either direction.
#[derive(Clone, Copy)]
enum StoreParam {
    SwapBytes,
    LsbFirst,
    RowLength,
    ImageHeight,
    SkipRows,
    SkipPixels,
    SkipImages,
    Alignment,
}

fn store_param(pname: GLenum) -> Option<(bool, StoreParam)> {
    use StoreParam::*;
    Some(match pname {
        GL_PACK_SWAP_BYTES => (true, SwapBytes),
        GL_PACK_LSB_FIRST => (true, LsbFirst),
        GL_PACK_ROW_LENGTH => (true, RowLength),
        GL_PACK_IMAGE_HEIGHT => (true, ImageHeight),
        GL_PACK_SKIP_ROWS => (true, SkipRows),
        GL_PACK_SKIP_PIXELS => (true, SkipPixels),
        GL_PACK_SKIP_IMAGES => (true, SkipImages),
        GL_PACK_ALIGNMENT => (true, Alignment),
        GL_UNPACK_SWAP_BYTES => (false, SwapBytes),
        GL_UNPACK_LSB_FIRST => (false, LsbFirst),
        GL_UNPACK_ROW_LENGTH => (false, RowLength),
        GL_UNPACK_IMAGE_HEIGHT => (false, ImageHeight),
        GL_UNPACK_SKIP_ROWS => (false, SkipRows),
        GL_UNPACK_SKIP_PIXELS => (false, SkipPixels),
        GL_UNPACK_SKIP_IMAGES => (false, SkipImages),
        GL_UNPACK_ALIGNMENT => (false, Alignment),
        _ => return None,
    })
}

impl Context {
    /// glPixelStorei: booleans are nonzero; lengths and skips must not be negative
    /// (GL_INVALID_VALUE), the alignment must be 1, 2, 4 or 8 (GL_INVALID_VALUE).
    pub fn pixel_store(&mut self, pname: GLenum, param: i32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some((pack, which)) = store_param(pname) else {
            return self.error(GL_INVALID_ENUM);
        };
        let valid = match which {
            StoreParam::SwapBytes | StoreParam::LsbFirst => true,
            StoreParam::Alignment => matches!(param, 1 | 2 | 4 | 8),
            _ => param >= 0,
        };
        if !valid {
            return self.error(GL_INVALID_VALUE);
        }
        let modes = if pack { &mut self.pixel_store.pack } else { &mut self.pixel_store.unpack };
        match which {
            StoreParam::SwapBytes => modes.swap_bytes = param != 0,
            StoreParam::LsbFirst => modes.lsb_first = param != 0,
            StoreParam::RowLength => modes.row_length = param,
            StoreParam::ImageHeight => modes.image_height = param,
            StoreParam::SkipRows => modes.skip_rows = param,
            StoreParam::SkipPixels => modes.skip_pixels = param,
            StoreParam::SkipImages => modes.skip_images = param,
            StoreParam::Alignment => modes.alignment = param,
        }
    }

    /// glPixelStoref: the value is rounded as Mesa does (`lroundf`, then narrowed to GLint:
    /// 2.5 → 3, 0.49999997 → 0, NaN → 0), then as glPixelStorei.
    pub fn pixel_store_f(&mut self, pname: GLenum, param: f32) {
        self.pixel_store(pname, pixel_store_round(param));
    }

    /// glReadPixels from the current read buffer (or the depth/stencil buffer). `dest` turns
    /// the byte span the read touches (relative to the client pointer) into the client
    /// memory; it is called only when at least one pixel is written, and a `None` answer
    /// (a NULL pointer) skips the write.
    #[allow(clippy::too_many_arguments)]
    pub fn read_pixels<'a>(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: GLenum,
        ty: GLenum,
        dest: impl FnOnce(Range<usize>) -> ClientBytesMut<'a>,
    ) {
        let Some(job) = self.validate_read(x, y, width, height, format, ty) else {
            return;
        };
        // Rendering recorded so far completes before the read (a flush point).
        self.flush_rendering();
        let out = match dest(job.span.clone()) {
            Ok(Some(out)) => out,
            Ok(None) => return,
            Err(error) => return self.error(error),
        };
        let slot = self.current_read_slot();
        let _ = self.with_read_framebuffer(|fb| read_into(fb, slot, &job, out));
    }

    /// The bytes of a whole `width` × `height` glReadPixels image of `format`/`ty` under the
    /// pack state, before clipping: what a pixel pack buffer must hold, since GL 2.1 §4.3.2
    /// writes every pixel of the image (undefined values outside the window). Deliberate
    /// difference: Mesa 22 checks less and writes the rows of such a read past the end of the
    /// buffer (capi pixel_buffer_objects). `None` when the arguments are invalid (the command
    /// reports that) or the image is empty.
    pub fn read_image_span(&self, width: i32, height: i32, format: GLenum, ty: GLenum) -> Option<Range<usize>> {
        if width <= 0 || height <= 0 {
            return None;
        }
        let client_format = match read_format(format)? {
            ReadFormat::Client(f) => f,
            ReadFormat::ColorIndex => ClientFormat::StencilIndex,
        };
        let client_ty = check_format_and_type(ReadFormat::Client(client_format), ty).ok()?;
        let modes = PackModes::from(&self.pixel_store.pack);
        let (w, h) = (width as usize, height as usize);
        ImageLayout::new(client_format, client_ty, &modes, w)?.span(0..w, 0..h)
    }

    /// Checks a glReadPixels call (recording the error) and works out its clipped rectangle
    /// and client layout; `None` when invalid, when nothing is inside the framebuffer or when
    /// no framebuffer is bound.
    fn validate_read(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: GLenum,
        ty: GLenum,
    ) -> Option<ReadJob> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if width < 0 || height < 0 {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        if !self.check_framebuffer_complete(false) || !self.check_read_single_sampled() {
            return None;
        }
        let Some(read_format) = read_format(format) else {
            self.error(unknown_format_error(ty));
            return None;
        };
        let layers = self.read_config().depth_stencil;
        let (depth_bits, stencil_bits) = (layers.depth_bits(), layers.stencil_bits());
        let layer_missing = match read_format {
            ReadFormat::Client(ClientFormat::DepthComponent | ClientFormat::DepthStencil) => depth_bits == 0,
            // Mesa looks GL_COLOR_INDEX up as a stencil format here; it fails later anyway.
            ReadFormat::Client(ClientFormat::StencilIndex) | ReadFormat::ColorIndex => stencil_bits == 0,
            _ => false,
        };
        if layer_missing {
            self.error(GL_INVALID_OPERATION);
            return None;
        }
        let client_ty = match check_format_and_type(read_format, ty) {
            Ok(t) => t,
            Err(e) => {
                self.error(e);
                return None;
            }
        };
        let client_format = match read_format {
            ReadFormat::Client(ClientFormat::DepthStencil) if stencil_bits == 0 => None,
            ReadFormat::Client(f) if f.is_color() && self.current_read_slot().is_none() => None,
            ReadFormat::Client(f) => Some(f),
            ReadFormat::ColorIndex => None,
        };
        let Some(client_format) = client_format else {
            self.error(GL_INVALID_OPERATION);
            return None;
        };
        let bounds = self.framebuffer_shape(false).map(|(w, h, _)| Rect::from_xywh(0, 0, w as i32, h as i32))?;
        let rect = clip(x, y, width, height, bounds);
        if rect.is_empty() {
            return None;
        }
        let modes = PackModes::from(&self.pixel_store.pack);
        let (first_col, first_row) = ((rect.x0 as i64 - x as i64) as usize, (rect.y0 as i64 - y as i64) as usize);
        let layout = ImageLayout::new(client_format, client_ty, &modes, width as usize);
        let span =
            layout.and_then(|l| l.span(first_col..first_col + rect.width(), first_row..first_row + rect.height()));
        let (Some(layout), Some(span)) = (layout, span) else {
            // The layout addresses memory beyond the address space: no client buffer can
            // hold it.
            self.error(GL_INVALID_VALUE);
            return None;
        };
        Some(ReadJob {
            format: client_format,
            ty: client_ty,
            modes,
            layout,
            rect,
            first_col,
            first_row,
            span,
            clamp_read_color: self.state.color.clamp_read_color,
        })
    }
}

/// The part of the rectangle (x, y, width, height) inside `bounds`, computed without
/// overflow.
fn clip(x: i32, y: i32, width: i32, height: i32, bounds: Rect) -> Rect {
    let x1 = (x as i64 + width as i64).min(bounds.x1 as i64) as i32;
    let y1 = (y as i64 + height as i64).min(bounds.y1 as i64) as i32;
    Rect { x0: x.max(bounds.x0), y0: y.max(bounds.y0), x1, y1 }
}

/// Packs the job's pixels from `fb` into `out` (the job's span of client memory).
fn read_into(fb: &Framebuffer, slot: Option<crate::framebuffer::ColorSlot>, job: &ReadJob, out: &mut [u8]) {
    let rect = job.rect;
    let base = job.span.start;
    let cols = rect.width();
    // Where row `j` of the clipped rectangle starts in `out`.
    let row_start = |j: usize| job.layout.pixel_offset(job.first_col, job.first_row + j).map(|o| o - base);
    let swap = job.modes.swap_bytes;
    match job.format {
        ClientFormat::DepthComponent | ClientFormat::StencilIndex | ClientFormat::DepthStencil => {
            let ds = fb.depth_stencil();
            let encoding = ds.depth_encoding();
            let (mut depth, mut stencil) = (Vec::with_capacity(cols), Vec::with_capacity(cols));
            for (j, y) in (rect.y0..rect.y1).enumerate() {
                let Some(start) = row_start(j) else { return };
                depth.clear();
                stencil.clear();
                if job.format != ClientFormat::StencilIndex {
                    ds.read_depth_row(y, rect.x0, rect.x1, &mut depth);
                }
                if job.format != ClientFormat::DepthComponent {
                    ds.read_stencil_row(y, rect.x0, rect.x1, &mut stencil);
                }
                let row_bytes = cols * job.layout.pixel_bytes();
                match (job.format, job.ty) {
                    (ClientFormat::StencilIndex, ClientType::Bitmap) => {
                        let first_bit = job.layout.bit_index(job.first_col);
                        let len = (first_bit % 8 + cols).div_ceil(8);
                        if let Some(o) = out.get_mut(start..start + len) {
                            pack_stencil_bitmap_row(&stencil, first_bit % 8, job.modes.lsb_first, o);
                        }
                    }
                    (ClientFormat::StencilIndex, ty) => {
                        if let Some(o) = out.get_mut(start..start + row_bytes) {
                            pack_stencil_row(&stencil, ty, swap, o);
                        }
                    }
                    (ClientFormat::DepthComponent, ty) => {
                        if let Some(o) = out.get_mut(start..start + row_bytes) {
                            pack_depth_row(&depth, encoding, ty, swap, o);
                        }
                    }
                    (_, ClientType::Float32UnsignedInt24_8Rev) => {
                        if let Some(o) = out.get_mut(start..start + row_bytes) {
                            pack_depth_stencil_float_row(&depth, encoding, &stencil, swap, o);
                        }
                    }
                    _ => {
                        if let Some(o) = out.get_mut(start..start + row_bytes) {
                            pack_depth_stencil_row(&depth, encoding, &stencil, swap, o);
                        }
                    }
                }
            }
        }
        _ => {
            let Some(buffer) = slot.and_then(|s| fb.color(s)) else { return };
            let source = buffer.format();
            let clamp_read = match job.clamp_read_color {
                GL_FIXED_ONLY => !source.is_float(),
                mode => mode != GL_FALSE as GLenum,
            };
            let clamp = clamp_read || !job.ty.is_float();
            let Some(plan) = ColorPlan::new(source, job.format, job.ty, clamp, swap) else { return };
            let row_bytes = cols * plan.pixel_bytes();
            let mut scratch = ColorScratch::default();
            for (j, y) in (rect.y0..rect.y1).enumerate() {
                let Some(start) = row_start(j) else { return };
                if let Some(o) = out.get_mut(start..start + row_bytes) {
                    plan.pack_row(buffer.row(y, rect.x0, rect.x1), o, &mut scratch);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};

    fn context(color: ColorFormat, depth_stencil: DepthStencilFormat, w: usize, h: usize) -> Context {
        Context::with_test_drawable(FramebufferConfig::single_buffered(color, depth_stencil, 0), w, h).0
    }

    fn read(ctx: &mut Context, rect: [i32; 4], format: GLenum, ty: GLenum, buffer: &mut [u8]) -> GLenum {
        ctx.read_pixels(rect[0], rect[1], rect[2], rect[3], format, ty, |span| Ok(buffer.get_mut(span)));
        ctx.take_error()
    }

    const RGBA8: ColorFormat = ColorFormat::Unorm8 { alpha: true };
    const D24S8: DepthStencilFormat = DepthStencilFormat::Packed24 { depth: true, stencil: true };

    #[test]
    fn errors_come_in_mesa_order() {
        let mut ctx = context(RGBA8, DepthStencilFormat::None, 4, 4);
        let mut buf = [0u8; 256];
        assert_eq!(read(&mut ctx, [0, 0, -1, 1], 0x1234, 0x1234, &mut buf), GL_INVALID_VALUE);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], 0x1234, GL_UNSIGNED_BYTE, &mut buf), GL_INVALID_ENUM);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_DEPTH_COMPONENT, 0x1234, &mut buf), GL_INVALID_OPERATION);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut buf), GL_INVALID_OPERATION);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_RGBA, 0x1234, &mut buf), GL_INVALID_ENUM);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, &mut buf), GL_INVALID_OPERATION);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_BGR, GL_UNSIGNED_SHORT_5_6_5, &mut buf), GL_INVALID_OPERATION);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, &mut buf), GL_INVALID_OPERATION);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_RGBA, GL_UNSIGNED_INT_24_8, &mut buf), GL_INVALID_OPERATION);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_RGBA, GL_BITMAP, &mut buf), GL_INVALID_ENUM);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_RGBA, GL_HALF_FLOAT, &mut buf), GL_NO_ERROR);
        ctx.read_buffer(GL_NONE);
        assert_eq!(read(&mut ctx, [0, 0, 0, 1], GL_RGBA, GL_UNSIGNED_BYTE, &mut buf), GL_INVALID_OPERATION);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_RGBA, 0x1234, &mut buf), GL_INVALID_ENUM);
        ctx.inside_begin_end = true;
        assert_eq!(read(&mut ctx, [0, 0, -1, 1], GL_RGBA, GL_UNSIGNED_BYTE, &mut buf), GL_INVALID_OPERATION);

        let mut ctx = context(RGBA8, D24S8, 4, 4);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_COLOR_INDEX, GL_UNSIGNED_BYTE, &mut buf), GL_INVALID_OPERATION);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_COLOR_INDEX, 0x1234, &mut buf), GL_INVALID_ENUM);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, &mut buf), GL_INVALID_ENUM);
        assert_eq!(
            read(&mut ctx, [0, 0, 1, 1], GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, &mut buf),
            GL_INVALID_OPERATION
        );
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_DEPTH_COMPONENT, GL_BITMAP, &mut buf), GL_INVALID_ENUM);
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &mut buf), GL_NO_ERROR);
        let mut ctx = context(RGBA8, DepthStencilFormat::Packed24 { depth: true, stencil: false }, 4, 4);
        assert_eq!(
            read(&mut ctx, [0, 0, 1, 1], GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &mut buf),
            GL_INVALID_OPERATION
        );
        assert_eq!(read(&mut ctx, [0, 0, 1, 1], GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, &mut buf), GL_INVALID_ENUM);
    }

    #[test]
    fn out_of_window_pixels_are_untouched() {
        let mut ctx = context(RGBA8, D24S8, 4, 3);
        ctx.clear_color([1.0, 0.0, 0.5, 1.0]);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.pixel_store(GL_PACK_ALIGNMENT, 1);
        // A 6×5 read from (-1, -1): only the 4×3 window part is written.
        let mut buf = [0xeeu8; 6 * 5 * 3];
        assert_eq!(read(&mut ctx, [-1, -1, 6, 5], GL_RGB, GL_UNSIGNED_BYTE, &mut buf), GL_NO_ERROR);
        for row in 0..5 {
            for col in 0..6 {
                let px = &buf[(row * 6 + col) * 3..][..3];
                let inside = (1..5).contains(&col) && (1..4).contains(&row);
                assert_eq!(px, if inside { [255, 0, 128] } else { [0xee; 3] }, "row {row} col {col}");
            }
        }
        // Entirely outside: the destination is not even asked for.
        ctx.read_pixels(10, 10, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, |_| panic!("nothing to write"));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn pack_modes_place_rows() {
        let mut ctx = context(RGBA8, D24S8, 4, 4);
        ctx.clear_stencil(7);
        ctx.clear(GL_STENCIL_BUFFER_BIT);
        ctx.pixel_store(GL_PACK_ROW_LENGTH, 5);
        ctx.pixel_store(GL_PACK_SKIP_ROWS, 1);
        ctx.pixel_store(GL_PACK_SKIP_PIXELS, 2);
        ctx.pixel_store(GL_PACK_ALIGNMENT, 8);
        let mut buf = [0u8; 64];
        let mut asked = None;
        ctx.read_pixels(1, 1, 2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, |span| {
            asked = Some(span.clone());
            Ok(buf.get_mut(span))
        });
        // Rows 8 bytes apart (5 rounded up to 8), first row after one skipped row.
        assert_eq!(asked, Some(10..20));
        assert_eq!(&buf[..20], &[0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 7, 7, 0, 0, 0, 0, 0, 0, 7, 7]);
    }

    #[test]
    fn pixel_store_validates() {
        let mut ctx = context(RGBA8, D24S8, 1, 1);
        ctx.pixel_store(GL_PACK_ALIGNMENT, 3);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.pixel_store(GL_UNPACK_SKIP_IMAGES, -1);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.pixel_store(0x8758, 1); // GL_PACK_INVERT_MESA: not supported
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.pixel_store_f(GL_PACK_ALIGNMENT, 7.6);
        ctx.pixel_store_f(GL_PACK_ROW_LENGTH, 2.5);
        ctx.pixel_store(GL_UNPACK_SWAP_BYTES, -7);
        ctx.pixel_store_f(GL_UNPACK_LSB_FIRST, 0.4);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert_eq!(ctx.pixel_store.pack.alignment, 8);
        assert_eq!(ctx.pixel_store.pack.row_length, 3);
        assert!(ctx.pixel_store.unpack.swap_bytes);
        assert!(!ctx.pixel_store.unpack.lsb_first);
        ctx.inside_begin_end = true;
        ctx.pixel_store(GL_PACK_ALIGNMENT, 1);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.pixel_store.pack.alignment, 8);
    }
}
