//! OSMesa: contexts that render into memory the caller owns.
//!
//! As Mesa does, tessera writes the caller's buffer at the flush points only, and only when
//! something was drawn since the last one. Rows go bottom-up (`OSMESA_Y_UP`, the default)
//! or top-down, `OSMESA_ROW_LENGTH` pixels apart. Mesa renders into its own framebuffer and
//! copies it; tessera does the same except for RGBA8 buffers with rows bottom-up and no
//! gaps (the usual case): a flush point renders their scene straight into the caller's
//! buffer ([`crate::framebuffer::Drawable::render_for_presentation`], no copy, the own
//! pixels never touched), whose contents are then the image (read back when something
//! else needs it, never after the caller bound another buffer: see
//! capi-tests/osmesa_in_place.c for where this differs from Mesa 22). Other layouts are
//! written by copies and their existing contents are never read.
//!
//! The flush points, as Mesa 22's (checked by capi-tests/osmesa_free_then_destroy.c):
//! glFlush, glFinish, OSMesaMakeCurrent of another context (the old context's buffer) and
//! OSMesaMakeCurrent(NULL, NULL). Binding the same context to another buffer writes
//! nothing: a buffer of the same size takes over the image, which reaches it at the next
//! flush point. glReadPixels and OSMesaGetDepthBuffer complete rendering internally and
//! write nothing. OSMesaGetColorBuffer is a flush point on tessera only (Mesa 22 returns
//! the pointer without writing), so a program reading the pointer sees the image.
//! OSMesaDestroyContext is never one: what was drawn since the last flush point is
//! discarded, since programs like mesa-demos' osdemo free the buffer after their glFinish
//! and then destroy the context. (Mesa 22, destroying a context while another is current,
//! flushes the current one into its still-bound buffer; tessera leaves it for its next
//! flush point.)
//!
//! Audit of caller memory written after the call that handed it over returned:
//! - the OSMesa buffer, here: written only at the flush points above, while bound (also
//!   when a flush point renders in place), and read only while bound to the same address
//!   (bringing an image rendered in place home); it is forgotten (presenter dropped) before
//!   OSMesaDestroyContext releases the context, and a rebind replaces it before anything is
//!   presented;
//! - glSelectBuffer/glFeedbackBuffer arrays: the records are kept inside the context and
//!   copied only inside glRenderMode when it leaves GL_SELECT/GL_FEEDBACK (`api::gl_selection`),
//!   never at a deferred flush nor at destroy;
//! - client vertex and index arrays: read (never written) during the draw call that uses
//!   them (`api::gl_arrays::CallerMemory`); what the deferred scene keeps is tessera's copy;
//! - glReadPixels, glGetTexImage, glGetPolygonStipple, glGetMap, glGet* and the other
//!   queries into client memory: the pending scene is rasterized and the memory written
//!   before the entry point returns; glDrawPixels, glBitmap, glTexImage and friends copy
//!   the caller's pixels before returning;
//! - GLX windows and pixmaps are presented through the X server and XShm segments tessera
//!   owns: no caller memory.
use crate::context::current::{self, SharedContext};
use crate::context::{Context, ContextConfig};
use crate::framebuffer::external::CallerBuffer;
use crate::framebuffer::pages;
use crate::framebuffer::surface::{ColorPixels, DepthStencilPixels};
use crate::framebuffer::{
    ColorFormat, ColorSlot, DepthStencilFormat, Drawable, Framebuffer, FramebufferConfig, OutOfMemory, Present,
};
use crate::gl::enums::*;
use crate::gl::limits::MAX_VIEWPORT_DIM;
use crate::gl::osmesa::{OSMESA_ARGB, OSMESA_BGR, OSMESA_BGRA, OSMESA_RGB_565};
use crate::gl::types::GLenum;
use crate::raster::thread_count;
use crate::winsys::notice;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};

/// Channel layout of the caller's buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelLayout {
    Rgba,
    Bgra,
    Argb,
    Rgb,
    Bgr,
    Rgb565,
}

impl PixelLayout {
    pub fn from_osmesa(format: GLenum) -> Option<PixelLayout> {
        Some(match format {
            GL_RGBA => PixelLayout::Rgba,
            OSMESA_BGRA => PixelLayout::Bgra,
            OSMESA_ARGB => PixelLayout::Argb,
            GL_RGB => PixelLayout::Rgb,
            OSMESA_BGR => PixelLayout::Bgr,
            OSMESA_RGB_565 => PixelLayout::Rgb565,
            _ => return None,
        })
    }

    pub fn to_osmesa(self) -> GLenum {
        match self {
            PixelLayout::Rgba => GL_RGBA,
            PixelLayout::Bgra => OSMESA_BGRA,
            PixelLayout::Argb => OSMESA_ARGB,
            PixelLayout::Rgb => GL_RGB,
            PixelLayout::Bgr => OSMESA_BGR,
            PixelLayout::Rgb565 => OSMESA_RGB_565,
        }
    }

    /// The format's name in <GL/osmesa.h> (for notices).
    pub fn name(self) -> &'static str {
        match self {
            PixelLayout::Rgba => "OSMESA_RGBA",
            PixelLayout::Bgra => "OSMESA_BGRA",
            PixelLayout::Argb => "OSMESA_ARGB",
            PixelLayout::Rgb => "OSMESA_RGB",
            PixelLayout::Bgr => "OSMESA_BGR",
            PixelLayout::Rgb565 => "OSMESA_RGB_565",
        }
    }

    /// Components per pixel in the caller's buffer.
    fn components(self) -> usize {
        match self {
            PixelLayout::Rgba | PixelLayout::Bgra | PixelLayout::Argb => 4,
            PixelLayout::Rgb | PixelLayout::Bgr => 3,
            PixelLayout::Rgb565 => 1,
        }
    }

    /// For each output component, which RGBA channel it holds.
    fn order(self) -> &'static [usize] {
        match self {
            PixelLayout::Rgba => &[0, 1, 2, 3],
            PixelLayout::Bgra => &[2, 1, 0, 3],
            PixelLayout::Argb => &[3, 0, 1, 2],
            PixelLayout::Rgb => &[0, 1, 2],
            PixelLayout::Bgr => &[2, 1, 0],
            PixelLayout::Rgb565 => &[0],
        }
    }

    /// The internal color format for this layout and GL type; `None` if the pair is invalid.
    pub fn color_format(self, ty: GLenum) -> Option<ColorFormat> {
        let alpha = self.components() == 4;
        match (self, ty) {
            (PixelLayout::Rgb565, GL_UNSIGNED_SHORT_5_6_5) => Some(ColorFormat::Rgb565),
            (PixelLayout::Rgb565, _) => None,
            (_, GL_UNSIGNED_BYTE) => Some(ColorFormat::Unorm8 { alpha }),
            (_, GL_UNSIGNED_SHORT) => Some(ColorFormat::Unorm16 { alpha }),
            (_, GL_FLOAT) => Some(ColorFormat::Float32 { alpha }),
            _ => None,
        }
    }

    /// Bytes per pixel in the caller's buffer for `ty`.
    pub fn bytes_per_pixel(self, ty: GLenum) -> usize {
        let component = match ty {
            GL_UNSIGNED_BYTE => 1,
            GL_UNSIGNED_SHORT | GL_UNSIGNED_SHORT_5_6_5 => 2,
            _ => 4,
        };
        self.components() * component
    }
}

/// A pixel type's name for a notice (its number when it is not one OSMesa knows).
fn type_name(ty: GLenum) -> String {
    match ty {
        GL_UNSIGNED_BYTE => "GL_UNSIGNED_BYTE".into(),
        GL_UNSIGNED_SHORT => "GL_UNSIGNED_SHORT".into(),
        GL_UNSIGNED_SHORT_5_6_5 => "GL_UNSIGNED_SHORT_5_6_5".into(),
        GL_FLOAT => "GL_FLOAT".into(),
        other => format!("0x{other:x}"),
    }
}

/// Depth/stencil/accum sizes requested at creation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Request {
    pub layout: PixelLayout,
    pub depth_bits: i32,
    pub stencil_bits: i32,
    pub accum_bits: i32,
}

impl Request {
    /// The depth/stencil storage for the requested sizes. Like Mesa, any stencil request
    /// gives 8 bits packed with 24-bit depth; unlike Mesa 22 (which gives no depth below 16
    /// bits, 16 bits up to 23 and never 32), tessera gives at least the requested depth.
    fn depth_stencil(&self) -> DepthStencilFormat {
        let (d, s) = (self.depth_bits, self.stencil_bits);
        match (d, s > 0) {
            (0, false) => DepthStencilFormat::None,
            (0, true) => DepthStencilFormat::Packed24 { depth: false, stencil: true },
            (1..=16, false) => DepthStencilFormat::Depth16,
            (1..=24, _) => DepthStencilFormat::Packed24 { depth: true, stencil: s > 0 },
            (_, stencil) => DepthStencilFormat::Depth32 { stencil },
        }
    }

    fn config(&self, color: ColorFormat) -> FramebufferConfig {
        FramebufferConfig::single_buffered(color, self.depth_stencil(), if self.accum_bits > 0 { 16 } else { 0 })
    }
}

/// What the caller bound with OSMesaMakeCurrent.
struct Binding {
    /// The caller's buffer address (kept as an address: only the API edge turns it into
    /// a [`CallerBuffer`]).
    address: usize,
    ty: GLenum,
    width: usize,
    height: usize,
    drawable: Arc<Mutex<Drawable>>,
}

/// Writes the front-left color buffer into the caller's memory.
struct CallerPresenter {
    buffer: CallerBuffer,
    layout: PixelLayout,
    ty: GLenum,
    row_length: usize,
    y_up: bool,
    /// Whether a presentation has faulted the buffer's pages in.
    populated: bool,
}

impl Present for CallerPresenter {
    fn only_when_drawn(&self) -> bool {
        true
    }

    fn private(&self) -> bool {
        true
    }

    fn present(&mut self, framebuffer: &Framebuffer) {
        let Some(color) = framebuffer.color(ColorSlot::FrontLeft) else {
            return;
        };
        let (width, height) = (framebuffer.width(), framebuffer.height());
        let bpp = self.layout.bytes_per_pixel(self.ty);
        let stride = self.row_length.max(width) * bpp;
        let (layout, y_up) = (self.layout, self.y_up);
        // The rows the caller's buffer holds (the last one may end after its pixels).
        let Some(rows_bytes) = (height - 1).checked_mul(stride).and_then(|b| b.checked_add(width * bpp)) else {
            return;
        };
        // The first presentation into a buffer faults its pages in (the caller's fresh
        // memory: one fault per 4 KiB outside huge pages); each band asks for its pages in
        // one call instead (`framebuffer::pages::populate`). Later ones find them mapped.
        // Only for rows without gaps: the pages of a wide row length's padding may never be
        // written, so they are not asked for.
        let populate = !self.populated && stride == width * bpp;
        let Some(bytes) = self.buffer.bytes_mut(0, rows_bytes) else {
            return;
        };
        self.populated = true;
        in_bands(bytes, width, height, stride, &|first_row, band| {
            if populate {
                pages::populate(band);
            }
            for (i, row) in band.chunks_mut(stride).enumerate() {
                let dst_row = first_row + i;
                let y = if y_up { dst_row } else { height - 1 - dst_row };
                present_row(layout, color.pixels(), width, y, &mut row[..width * bpp]);
            }
        });
    }

    /// RGBA8 rows bottom-up without gaps, as the framebuffer's own RGBA8 front-left color.
    fn lends(&self, framebuffer: &Framebuffer) -> bool {
        let (width, height) = (framebuffer.width(), framebuffer.height());
        self.layout == PixelLayout::Rgba
            && self.ty == GL_UNSIGNED_BYTE
            && self.y_up
            && self.row_length <= width
            && framebuffer.config().color == (ColorFormat::Unorm8 { alpha: true })
            && width.checked_mul(height).and_then(|p| p.checked_mul(4)).is_some_and(|bytes| bytes <= self.buffer.len())
            && !self.buffer.as_ptr().is_null()
    }

    fn lend(&mut self, framebuffer: &Framebuffer) -> Option<CallerBuffer> {
        if !self.lends(framebuffer) {
            return None;
        }
        // The first use maps the pages as the first presentation would (see `present`).
        if !std::mem::replace(&mut self.populated, true) {
            let (width, height) = (framebuffer.width(), framebuffer.height());
            if let Some(bytes) = self.buffer.bytes_mut(0, width * height * 4) {
                in_bands(bytes, width, height, width * 4, &|_, band| pages::populate(band));
            }
        }
        Some(std::mem::replace(&mut self.buffer, CallerBuffer::empty()))
    }

    fn give_back(&mut self, memory: CallerBuffer) {
        self.buffer = memory;
    }

    fn memory(&self) -> Option<usize> {
        Some(self.buffer.as_ptr() as usize)
    }
}

/// Runs `work(first_row, band)` on bands of whole rows (`stride` bytes apart; the last may
/// be shorter) of `bytes`, which holds `height` rows of `width` pixels. A large image is written by the
/// shared worker threads too: the first write of a fresh caller buffer is mostly page
/// faults (one per 4 KiB), which then happen on every core at once.
fn in_bands(bytes: &mut [u8], width: usize, height: usize, stride: usize, work: &(dyn Fn(usize, &mut [u8]) + Sync)) {
    let threads = if width * height >= PARALLEL_PRESENT_PIXELS { thread_count() } else { 1 };
    if threads <= 1 {
        return work(0, bytes);
    }
    let band_rows = height.div_ceil(threads * 4).max(1);
    let queue = Mutex::new(bytes.chunks_mut(band_rows * stride).enumerate());
    crate::pool::run(threads - 1, &|| loop {
        let Some((index, band)) = queue.lock().unwrap_or_else(|p| p.into_inner()).next() else {
            break;
        };
        work(index * band_rows, band);
    });
}

/// Images from this many pixels on are written into the caller's buffer by all the worker
/// threads (below it, waking them costs more than the copy).
const PARALLEL_PRESENT_PIXELS: usize = 256 * 1024;

/// Writes row `y` of the image (`width` pixels of `pixels`) into `dst`, in the caller's
/// layout.
fn present_row(layout: PixelLayout, pixels: &ColorPixels, width: usize, y: usize, dst: &mut [u8]) {
    let order = layout.order();
    let src = y * width..(y + 1) * width;
    match pixels {
        // RGBA bytes are stored in the caller's order: one copy per row.
        ColorPixels::Unorm8(px) if order == [0, 1, 2, 3] => dst.copy_from_slice(px[src].as_flattened()),
        ColorPixels::Unorm8(px) => {
            for (out, p) in dst.chunks_exact_mut(order.len()).zip(&px[src]) {
                for (o, &c) in out.iter_mut().zip(order) {
                    *o = p[c];
                }
            }
        }
        ColorPixels::Unorm16(px) => {
            for (out, p) in dst.chunks_exact_mut(order.len() * 2).zip(&px[src]) {
                for (o, &c) in out.chunks_exact_mut(2).zip(order) {
                    o.copy_from_slice(&p[c].to_ne_bytes());
                }
            }
        }
        ColorPixels::Float32(px) => {
            for (out, p) in dst.chunks_exact_mut(order.len() * 4).zip(&px[src]) {
                for (o, &c) in out.chunks_exact_mut(4).zip(order) {
                    o.copy_from_slice(&p[c].to_ne_bytes());
                }
            }
        }
        ColorPixels::Rgb565(px) => {
            for (out, p) in dst.chunks_exact_mut(2).zip(&px[src]) {
                out.copy_from_slice(&p.to_ne_bytes());
            }
        }
    }
}

/// An OSMesa context: a GL context plus what OSMesa needs to bind caller memory to it.
pub struct OsMesaContext {
    pub shared: Arc<SharedContext>,
    pub request: Request,
    binding: Mutex<Option<Binding>>,
    /// OSMESA_ROW_LENGTH and OSMESA_Y_UP (they apply to the current context).
    store: Mutex<(usize, bool)>,
}

/// Why OSMesaMakeCurrent failed.
#[derive(Debug, PartialEq, Eq)]
pub enum BindFailure {
    BadArguments,
    OutOfMemory,
    CurrentElsewhere,
}

impl OsMesaContext {
    fn lock_binding(&self) -> MutexGuard<'_, Option<Binding>> {
        self.binding.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn store(&self) -> (usize, bool) {
        *self.store.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// OSMesaMakeCurrent with a non-null buffer, already wrapped by the API edge.
    /// A framebuffer of the same size and type is kept (its contents survive), as in Mesa.
    pub fn make_current(
        self: &Arc<Self>,
        buffer: CallerBuffer,
        ty: GLenum,
        width: i32,
        height: i32,
    ) -> Result<(), BindFailure> {
        if width < 1 || height < 1 || width > MAX_VIEWPORT_DIM || height > MAX_VIEWPORT_DIM {
            return Err(BindFailure::BadArguments);
        }
        let Some(color) = self.request.layout.color_format(ty) else {
            notice::once("osmesa-type", || {
                format!(
                    "OSMesaMakeCurrent asked for type {} with format {}; tessera provides {}",
                    type_name(ty),
                    self.request.layout.name(),
                    if self.request.layout == PixelLayout::Rgb565 {
                        "GL_UNSIGNED_SHORT_5_6_5 with OSMESA_RGB_565"
                    } else {
                        "GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and GL_FLOAT with this format"
                    }
                )
            });
            return Err(BindFailure::BadArguments);
        };
        if let Some(owner) = self.shared.bound_thread() {
            if owner != std::thread::current().id() {
                return Err(BindFailure::CurrentElsewhere);
            }
        }
        let (width, height) = (width as usize, height as usize);
        let (row_length, y_up) = self.store();
        let presenter_address = buffer.as_ptr() as usize;
        if row_length <= width {
            buffer.advise_huge_pages();
        }
        let presenter =
            Box::new(CallerPresenter { buffer, layout: self.request.layout, ty, row_length, y_up, populated: false });
        let mut binding = self.lock_binding();
        let reuse = binding.as_ref().filter(|b| b.ty == ty && b.width == width && b.height == height);
        let drawable = match reuse {
            Some(b) => {
                b.drawable.lock().unwrap_or_else(|p| p.into_inner()).set_presenter(Some(presenter));
                b.drawable.clone()
            }
            None => {
                let framebuffer = Framebuffer::new(self.request.config(color), width, height)
                    .map_err(|OutOfMemory| BindFailure::OutOfMemory)?;
                // The old framebuffer goes; an image of it that lives in the old buffer is
                // never read (the caller may have freed that buffer already).
                if let Some(old) = binding.as_ref() {
                    old.drawable.lock().unwrap_or_else(|p| p.into_inner()).set_presenter(None);
                }
                Arc::new(Mutex::new(Drawable::new(framebuffer, Some(presenter))))
            }
        };
        *binding = Some(Binding { address: presenter_address, ty, width, height, drawable: drawable.clone() });
        drop(binding);
        current::make_current(Some(self.shared.clone())).map_err(|_| BindFailure::CurrentElsewhere)?;
        self.shared.with_gl(|gl| gl.bind_drawable(Some(drawable)));
        Ok(())
    }

    /// OSMesaPixelStore on this (current) context. `wrap` describes the caller's buffer
    /// for the new row length: the API edge owns that promise.
    pub fn pixel_store(
        &self,
        row_length: Option<usize>,
        y_up: Option<bool>,
        wrap: impl FnOnce(*mut u8, usize) -> CallerBuffer,
    ) {
        let (row_length, y_up) = {
            let mut store = self.store.lock().unwrap_or_else(|p| p.into_inner());
            if let Some(r) = row_length {
                store.0 = r;
            }
            if let Some(y) = y_up {
                store.1 = y;
            }
            *store
        };
        if let Some(b) = self.lock_binding().as_ref() {
            let bytes = row_length.max(b.width) * b.height * self.request.layout.bytes_per_pixel(b.ty);
            let presenter = CallerPresenter {
                buffer: wrap(b.address as *mut u8, bytes),
                layout: self.request.layout,
                ty: b.ty,
                row_length,
                y_up,
                populated: false,
            };
            b.drawable.lock().unwrap_or_else(|p| p.into_inner()).set_presenter(Some(Box::new(presenter)));
        }
    }

    /// The bytes the caller's buffer must hold for `width` × `height` of `ty` under the
    /// current row length.
    pub fn required_bytes(&self, ty: GLenum, width: usize, height: usize) -> usize {
        self.store().0.max(width) * height * self.request.layout.bytes_per_pixel(ty)
    }

    /// OSMesaGetIntegerv values of the bound buffer: (width, height, type); zeros if unbound.
    pub fn bound_size(&self) -> (usize, usize, GLenum) {
        self.lock_binding().as_ref().map_or((0, 0, 0), |b| (b.width, b.height, b.ty))
    }

    /// OSMESA_ROW_LENGTH and OSMESA_Y_UP as set.
    pub fn row_length_and_y_up(&self) -> (usize, bool) {
        self.store()
    }

    /// The caller's buffer address and size, after flushing rendering into it (as glFlush).
    pub fn color_buffer(&self) -> Option<(usize, usize, usize)> {
        self.shared.with_gl(|gl| gl.flush());
        let binding = self.lock_binding();
        let b = binding.as_ref()?;
        b.drawable.lock().unwrap_or_else(|p| p.into_inner()).present();
        Some((b.address, b.width, b.height))
    }

    /// The internal depth buffer: (width, height, bytes per value, address), after flushing.
    /// `None` without depth bits.
    pub fn depth_buffer(&self) -> Option<(usize, usize, usize, usize)> {
        self.shared.with_gl(|gl| gl.flush_rendering());
        let binding = self.lock_binding();
        let b = binding.as_ref()?;
        let mut drawable = b.drawable.lock().unwrap_or_else(|p| p.into_inner());
        let ds = drawable.lend_depth_stencil();
        if ds.depth_bits() == 0 {
            return None;
        }
        let (bpv, address) = match ds.pixels() {
            DepthStencilPixels::Depth16(px) => (2, px.as_ptr() as usize),
            DepthStencilPixels::Packed24(px) => (4, px.as_ptr() as usize),
            DepthStencilPixels::Depth32(px, _) => (4, px.as_ptr() as usize),
            DepthStencilPixels::None => return None,
        };
        Some((b.width, b.height, bpv, address))
    }

    /// Forgets the caller's buffer: nothing is written into it from now on, whatever was
    /// drawn since the last flush point (OSMesaDestroyContext).
    fn forget_buffer(&self) {
        if let Some(b) = self.lock_binding().take() {
            b.drawable.lock().unwrap_or_else(|p| p.into_inner()).set_presenter(None);
        }
    }
}

/// The live OSMesa contexts, by the handle given to C. A handle is only an identifier:
/// it is looked up here, never dereferenced, so a stale or forged handle is harmless.
fn registry() -> MutexGuard<'static, HashMap<usize, Arc<OsMesaContext>>> {
    static REGISTRY: OnceLock<Mutex<HashMap<usize, Arc<OsMesaContext>>>> = OnceLock::new();
    REGISTRY.get_or_init(|| Mutex::new(HashMap::new())).lock().unwrap_or_else(|p| p.into_inner())
}

/// OSMesaCreateContextExt / Attribs after argument checks: registers a new context and
/// returns its handle.
pub fn create(request: Request, share: Option<usize>) -> Option<usize> {
    if request.depth_bits < 0 || request.stencil_bits < 0 || request.accum_bits < 0 {
        return None;
    }
    // The share context's display lists, texture and buffer objects become this context's
    // too (context::share).
    let share = match share {
        Some(handle) => Some(lookup(handle)?),
        None => None,
    };
    // The worker threads start now, while the context is built and bound, rather than at
    // its first scene (`crate::pool::prestart`).
    crate::pool::prestart(thread_count() - 1);
    // The color format is decided by the type given at MakeCurrent; RGBA8 until then.
    let placeholder = request.layout.color_format(GL_UNSIGNED_BYTE).unwrap_or(ColorFormat::Rgb565);
    let mut context = Context::new(ContextConfig { visual: request.config(placeholder) });
    if let Some(share) = share {
        context.join_share_group(share.shared.share_group());
    }
    let osmesa = Arc::new(OsMesaContext {
        shared: SharedContext::new(context),
        request,
        binding: Mutex::new(None),
        store: Mutex::new((0, true)),
    });
    let handle = Arc::as_ptr(&osmesa) as usize;
    registry().insert(handle, osmesa);
    Some(handle)
}

/// The context behind a handle.
pub fn lookup(handle: usize) -> Option<Arc<OsMesaContext>> {
    registry().get(&handle).cloned()
}

/// The handle of the OSMesa context current on this thread.
pub fn current_handle() -> Option<usize> {
    let shared = current::current()?;
    registry().iter().find(|(_, c)| Arc::ptr_eq(&c.shared, &shared)).map(|(h, _)| *h)
}

/// The OSMesa context current on this thread.
pub fn current_context() -> Option<Arc<OsMesaContext>> {
    lookup(current_handle()?)
}

/// OSMesaDestroyContext: unregisters; releases it first if it is current on this thread.
/// Like Mesa, it never writes the caller's buffer: what was drawn since the last flush
/// point is discarded (osdemo frees its buffer after its glFinish, then destroys the
/// context). The buffer is forgotten before the release, whose flush would present.
pub fn destroy(handle: usize) {
    let Some(context) = registry().remove(&handle) else {
        return;
    };
    context.forget_buffer();
    if current::current().is_some_and(|c| Arc::ptr_eq(&c, &context.shared)) {
        let _ = current::make_current(None);
    }
    context.shared.with_gl(|gl| gl.bind_drawable(None));
}

/// OSMesaMakeCurrent(NULL, NULL, ...): releases the current context.
pub fn release_current() {
    let _ = current::make_current(None);
}
