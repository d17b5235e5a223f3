//! Buffers and pixel formats: the only code that touches raw pixel memory.
//!
//! A [`Framebuffer`] is the set of layers a drawable has (color buffers front/back ×
//! left/right plus aux buffers, depth, stencil, accumulation), stored bottom row first as GL
//! numbers them. It knows formats and rectangles, not GL: the context decides which buffers
//! and which rectangle an operation touches and passes plain values down.

#![deny(unsafe_code)]

pub mod band;
pub mod blit;
pub mod external;
pub mod format;
pub mod hiz;
pub mod layers;
pub mod multisample;
pub mod pages;
pub mod surface;

pub use format::{ColorFormat, DepthStencilFormat};
pub use surface::{AccumBuffer, ColorBuffer, DepthStencilBuffer};

/// Which color buffer of a framebuffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorSlot {
    FrontLeft,
    BackLeft,
    FrontRight,
    BackRight,
    Aux(u8),
    /// GL_COLOR_ATTACHMENTn of a framebuffer object.
    Attachment(u8),
}

/// A half-open pixel rectangle `[x0, x1) × [y0, y1)`, y counted from the bottom row.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Rect {
    pub x0: i32,
    pub y0: i32,
    pub x1: i32,
    pub y1: i32,
}

impl Rect {
    /// The rectangle at (x, y) of size w × h; negative sizes give an empty rectangle.
    pub fn from_xywh(x: i32, y: i32, w: i32, h: i32) -> Rect {
        Rect { x0: x, y0: y, x1: x.saturating_add(w.max(0)), y1: y.saturating_add(h.max(0)) }
    }

    pub fn intersect(self, other: Rect) -> Rect {
        Rect {
            x0: self.x0.max(other.x0),
            y0: self.y0.max(other.y0),
            x1: self.x1.min(other.x1),
            y1: self.y1.min(other.y1),
        }
    }

    pub fn is_empty(self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }

    pub fn width(self) -> usize {
        (self.x1 - self.x0).max(0) as usize
    }

    pub fn height(self) -> usize {
        (self.y1 - self.y0).max(0) as usize
    }
}

/// The shape of a framebuffer: which layers it has and in which formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FramebufferConfig {
    pub color: ColorFormat,
    pub double_buffered: bool,
    pub stereo: bool,
    pub aux_buffers: u8,
    pub depth_stencil: DepthStencilFormat,
    /// Bits per channel of the accumulation buffer (0 or 16).
    pub accum_bits: u32,
}

impl FramebufferConfig {
    /// A single-buffered, mono configuration without aux buffers (what OSMesa gives).
    pub fn single_buffered(color: ColorFormat, depth_stencil: DepthStencilFormat, accum_bits: u32) -> Self {
        FramebufferConfig { color, double_buffered: false, stereo: false, aux_buffers: 0, depth_stencil, accum_bits }
    }

    /// Every color slot this configuration has, front-left first.
    pub fn color_slots(&self) -> Vec<ColorSlot> {
        let mut slots = vec![ColorSlot::FrontLeft];
        if self.double_buffered {
            slots.push(ColorSlot::BackLeft);
        }
        if self.stereo {
            slots.push(ColorSlot::FrontRight);
            if self.double_buffered {
                slots.push(ColorSlot::BackRight);
            }
        }
        slots.extend((0..self.aux_buffers).map(ColorSlot::Aux));
        slots
    }
}

/// Why a framebuffer could not be allocated.
#[derive(Debug, PartialEq, Eq)]
pub struct OutOfMemory;

/// The layers of one drawable.
pub struct Framebuffer {
    config: FramebufferConfig,
    width: usize,
    height: usize,
    color: Vec<(ColorSlot, ColorBuffer)>,
    depth_stencil: DepthStencilBuffer,
    accum: Option<AccumBuffer>,
    /// The multisampled layers, when the framebuffer has more than one sample per pixel
    /// (`multisample.rs`); the layers above then hold the resolved image.
    multisample: Option<multisample::SampleLayers>,
    /// The memory the front-left color is rendered into instead of its own pixels while a
    /// scene renders in place (OSMesa, [`Drawable::render_for_presentation`]): RGBA8 rows
    /// bottom-up without gaps, as the own pixels are. `None` otherwise.
    in_place_front: Option<external::CallerBuffer>,
}

impl Framebuffer {
    /// Allocates every layer of `config` at `width` × `height`, zero-filled (color black,
    /// depth 0, stencil 0) as a fresh Mesa renderbuffer is. Allocation failure is reported,
    /// never an abort.
    pub fn new(config: FramebufferConfig, width: usize, height: usize) -> Result<Framebuffer, OutOfMemory> {
        let pixels = width.checked_mul(height).ok_or(OutOfMemory)?;
        let mut color = Vec::new();
        for slot in config.color_slots() {
            color.push((slot, ColorBuffer::new(config.color, width, height, pixels)?));
        }
        let depth_stencil = DepthStencilBuffer::new(config.depth_stencil, width, pixels)?;
        let accum = if config.accum_bits > 0 { Some(AccumBuffer::new(width, pixels)?) } else { None };
        Ok(Framebuffer { config, width, height, color, depth_stencil, accum, multisample: None, in_place_front: None })
    }

    pub fn config(&self) -> &FramebufferConfig {
        &self.config
    }

    pub fn width(&self) -> usize {
        self.width
    }

    pub fn height(&self) -> usize {
        self.height
    }

    /// The whole framebuffer as a rectangle.
    pub fn bounds(&self) -> Rect {
        Rect::from_xywh(0, 0, self.width as i32, self.height as i32)
    }

    pub fn has_slot(&self, slot: ColorSlot) -> bool {
        self.color.iter().any(|(s, _)| *s == slot)
    }

    pub fn color(&self, slot: ColorSlot) -> Option<&ColorBuffer> {
        self.color.iter().find(|(s, _)| *s == slot).map(|(_, b)| b)
    }

    pub fn color_mut(&mut self, slot: ColorSlot) -> Option<&mut ColorBuffer> {
        self.color.iter_mut().find(|(s, _)| *s == slot).map(|(_, b)| b)
    }

    pub fn depth_stencil(&self) -> &DepthStencilBuffer {
        &self.depth_stencil
    }

    pub fn depth_stencil_mut(&mut self) -> &mut DepthStencilBuffer {
        &mut self.depth_stencil
    }

    pub fn accum(&self) -> Option<&AccumBuffer> {
        self.accum.as_ref()
    }

    /// The accumulation buffer together with one color buffer, for glAccum.
    pub fn accum_and_color_mut(&mut self, slot: ColorSlot) -> Option<(&mut AccumBuffer, &mut ColorBuffer)> {
        let accum = self.accum.as_mut()?;
        let color = self.color.iter_mut().find(|(s, _)| *s == slot).map(|(_, b)| b)?;
        Some((accum, color))
    }

    pub fn accum_mut(&mut self) -> Option<&mut AccumBuffer> {
        self.accum.as_mut()
    }

    /// Copies color buffer `from` into `to` (a buffer swap that leaves the back buffer as it
    /// was); does nothing unless both exist.
    pub fn copy_color(&mut self, from: ColorSlot, to: ColorSlot) {
        let find = |slot| self.color.iter().position(|(s, _)| *s == slot);
        let (Some(source), Some(target)) = (find(from), find(to)) else {
            return;
        };
        if source == target {
            return;
        }
        let copy = self.color[source].1.clone();
        self.color[target].1 = copy;
        if let Some(layers) = self.multisample.as_mut() {
            let find = |slot| layers.color.iter().position(|(s, _)| *s == slot);
            if let (Some(source), Some(target)) = (find(from), find(to)) {
                let copy = layers.color[source].1.clone();
                layers.color[target].1 = copy;
            }
        }
    }
}

/// Shows a framebuffer to its consumer: the OSMesa caller's memory, an X window, ...
/// Called at the flush points of the API (glFlush, glFinish, swap) after rendering completed.
pub trait Present: Send {
    fn present(&mut self, framebuffer: &Framebuffer);

    /// Whether presenting is skipped when nothing was drawn since the last presentation.
    /// OSMesa's caller buffer says yes: Mesa writes it only when something was drawn since
    /// the last flush, and a program may free it after its last glFinish (then it must
    /// not be written again). X windows say no: every flush shows the window again.
    fn only_when_drawn(&self) -> bool {
        false
    }

    /// Whether the drawable is drawn into by one context only (an OSMesa buffer's
    /// framebuffer belongs to the context it was bound to; an X window may be current in
    /// several). Only then may a context keep a whole-buffer depth/stencil clear pending
    /// across glFlush and glFinish (`context::draw`): no other context can look at the
    /// buffer in between.
    fn private(&self) -> bool {
        false
    }

    /// Frees what the presenter holds in another process (an X server's GC, a shared
    /// segment) while that is still possible; called when its target is destroyed.
    fn release(&mut self) {}

    /// Whether the memory this presenter writes holds pixels in the layout of
    /// `framebuffer`'s front-left color (RGBA8 rows bottom-up without gaps), so that a scene
    /// can render that color there in place ([`Drawable::render_for_presentation`]).
    /// No by default.
    fn lends(&self, _framebuffer: &Framebuffer) -> bool {
        false
    }

    /// The memory [`Present::lends`] says can be rendered into, its pages mapped, until
    /// [`Present::give_back`] returns it; `None` when it cannot.
    fn lend(&mut self, _framebuffer: &Framebuffer) -> Option<external::CallerBuffer> {
        None
    }

    /// Takes back what [`Present::lend`] lent.
    fn give_back(&mut self, _memory: external::CallerBuffer) {}

    /// The address of the caller's memory this presenter writes, if it writes any.
    fn memory(&self) -> Option<usize> {
        None
    }
}

/// A framebuffer together with the way it is presented: what a GL context draws into.
///
/// Where the presenter lends the memory it presents into ([`Present::lends`]: an OSMesa
/// caller's RGBA8 buffer), a flush point's scene renders the front-left color straight
/// into that memory ([`Drawable::render_for_presentation`]) instead of into the
/// framebuffer's own pixels followed by a copy: the first frame of a fresh context then
/// never touches the own pixels' pages. The image then lives in the presenter's memory,
/// and everything else that uses the framebuffer first brings it home
/// ([`Drawable::bring_image_home`], through [`Drawable::framebuffer_to_draw`] and
/// [`Drawable::framebuffer_to_read`]).
pub struct Drawable {
    /// The layers. While the front-left image lives in the presenter's memory its own
    /// pixels are older: read it through [`Drawable::framebuffer_to_read`].
    pub framebuffer: Framebuffer,
    /// How the framebuffer is shown. OSMesa replaces it with [`Drawable::set_presenter`].
    pub presenter: Option<Box<dyn Present>>,
    /// Whether the framebuffer was drawn into since it was last presented.
    drawn: bool,
    /// Whether the depth/stencil pixels were lent to the caller (OSMesaGetDepthBuffer),
    /// who may read them at any flush point from then on.
    depth_stencil_lent: bool,
    /// Whether the presenter's memory holds the current front-left image: it was presented,
    /// or rendered there in place, and nothing was drawn into the own pixels since.
    presenter_holds_image: bool,
    /// Whether the current front-left image lives only in the presenter's memory (a flush
    /// point rendered it there in place): the framebuffer's own front-left pixels are older.
    image_with_presenter: bool,
}

impl Drawable {
    pub fn new(framebuffer: Framebuffer, presenter: Option<Box<dyn Present>>) -> Drawable {
        Drawable {
            framebuffer,
            presenter,
            drawn: false,
            depth_stencil_lent: false,
            presenter_holds_image: false,
            image_with_presenter: false,
        }
    }

    /// The depth/stencil layer, for a caller who keeps its address and reads it after any
    /// later flush point (OSMesaGetDepthBuffer): from now on its clears are never kept
    /// pending past one (see [`Drawable::depth_stencil_lent`]).
    pub fn lend_depth_stencil(&mut self) -> &DepthStencilBuffer {
        self.depth_stencil_lent = true;
        self.framebuffer.depth_stencil()
    }

    /// Whether [`Drawable::lend_depth_stencil`] was called: then glFlush and glFinish
    /// must leave the depth/stencil pixels complete.
    pub fn depth_stencil_lent(&self) -> bool {
        self.depth_stencil_lent
    }

    /// The framebuffer, for drawing into it: the next presentation shows the result.
    pub fn framebuffer_to_draw(&mut self) -> &mut Framebuffer {
        self.bring_image_home();
        self.drawn = true;
        self.presenter_holds_image = false;
        &mut self.framebuffer
    }

    /// The framebuffer with its front-left image home, for reading it (or for changes the
    /// presentation need not show: depth, accumulation).
    pub fn framebuffer_to_read(&mut self) -> &mut Framebuffer {
        self.bring_image_home();
        &mut self.framebuffer
    }

    /// Runs `render` (the scene of a flush point about to present) on the framebuffer,
    /// rendering the front-left color in place into the presenter's memory when the
    /// presenter lends it and that memory has what `render` builds on: the current image
    /// ([`Drawable::presenter_holds_image`]), or nothing because `overwrites` (the scene
    /// starts by clearing every front-left pixel). The memory is written only here, at a
    /// flush point that presents what was drawn, where the copy into it would have written
    /// it anyway. Otherwise `render` draws into the own pixels, as
    /// [`Drawable::framebuffer_to_draw`].
    pub fn render_for_presentation(&mut self, overwrites: bool, render: impl FnOnce(&mut Framebuffer)) {
        let usable = (overwrites || self.presenter_holds_image) && self.framebuffer.samples() == 1;
        let lent = match self.presenter.as_mut() {
            Some(presenter) if usable => presenter.lend(&self.framebuffer),
            _ => None,
        };
        let Some(memory) = lent else {
            return render(self.framebuffer_to_draw());
        };
        self.framebuffer.in_place_front = Some(memory);
        // The memory goes back even when `render` panics (the API edge catches it): a
        // framebuffer that kept it would render into it at any later scene.
        let rendered = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| render(&mut self.framebuffer)));
        if let (Some(presenter), Some(memory)) = (self.presenter.as_mut(), self.framebuffer.in_place_front.take()) {
            presenter.give_back(memory);
        }
        self.drawn = true;
        self.presenter_holds_image = true;
        self.image_with_presenter = true;
        if let Err(panic) = rendered {
            std::panic::resume_unwind(panic);
        }
    }

    /// Copies the front-left image back into the framebuffer's own pixels when it lives
    /// only in the presenter's memory (rendered there in place). The memory is the caller's
    /// and still bound: if the caller changed it since the flush point that wrote it, the
    /// image now shows the change (Mesa 22 keeps its own copy; the classic OSMesa rendered
    /// into the caller's buffer, as this does).
    pub fn bring_image_home(&mut self) {
        if !std::mem::take(&mut self.image_with_presenter) {
            return;
        }
        let Some(presenter) = self.presenter.as_mut() else { return };
        let Some(mut memory) = presenter.lend(&self.framebuffer) else { return };
        let pixels = self.framebuffer.width * self.framebuffer.height;
        let own = self.framebuffer.color_mut(ColorSlot::FrontLeft).map(|b| b.pixels_mut());
        if let (Some(surface::ColorPixels::Unorm8(own)), Some(image)) = (own, memory.unorm8_pixels_mut(pixels)) {
            own[..pixels].copy_from_slice(image);
        }
        presenter.give_back(memory);
    }

    /// Says that what is drawn next replaces every front-left pixel first (a scene that
    /// starts with a whole clear): an image that lives in the presenter's memory need not be
    /// brought home for it.
    pub fn front_image_replaced(&mut self) {
        self.image_with_presenter = false;
    }

    /// Replaces the presenter (OSMesaMakeCurrent of a buffer the framebuffer is kept for,
    /// OSMesaPixelStore). A new presenter into the same memory in the same (lendable) layout
    /// changes nothing. Otherwise an image that lives only in the old presenter's memory is
    /// brought home when the new one writes the same memory (the caller has just vouched
    /// for it again); memory at another address is never read again (the caller need keep
    /// a buffer valid only while it is bound, and may have freed it before binding the
    /// next), so the image becomes what the new memory holds when that can be rendered into
    /// in place (the classic OSMesa's rule), or black.
    pub fn set_presenter(&mut self, presenter: Option<Box<dyn Present>>) {
        let memory = |p: &Option<Box<dyn Present>>| p.as_ref().and_then(|p| p.memory());
        let same_memory = memory(&self.presenter).is_some() && memory(&self.presenter) == memory(&presenter);
        let lends = |p: &Option<Box<dyn Present>>, fb: &Framebuffer| p.as_ref().is_some_and(|p| p.lends(fb));
        let (old_lends, new_lends) = (lends(&self.presenter, &self.framebuffer), lends(&presenter, &self.framebuffer));
        if !(same_memory && old_lends && new_lends) {
            if self.image_with_presenter && same_memory {
                self.bring_image_home();
            } else if self.image_with_presenter && !new_lends {
                self.image_with_presenter = false;
                if presenter.is_some() {
                    let bounds = self.framebuffer.bounds();
                    if let Some(own) = self.framebuffer.color_mut(ColorSlot::FrontLeft) {
                        own.clear(bounds, [0.0; 4], [true; 4]);
                    }
                }
            }
            self.presenter_holds_image = self.image_with_presenter;
        }
        self.presenter = presenter;
    }

    /// Shows the framebuffer through the presenter (unless it skips unchanged images and
    /// nothing was drawn since the last presentation). An image rendered in place is
    /// already where it is shown.
    pub fn present(&mut self) {
        if let Some(presenter) = self.presenter.as_mut() {
            if self.drawn || !presenter.only_when_drawn() {
                if !self.image_with_presenter {
                    presenter.present(&self.framebuffer);
                }
                self.presenter_holds_image = true;
            }
        }
        self.drawn = false;
    }
}

#[cfg(test)]
mod in_place_tests {
    //! Rendering in place into a presenter's memory ([`Drawable::render_for_presentation`]).
    use super::*;
    use crate::framebuffer::band::ColorBand;
    use crate::framebuffer::surface::ColorPixels;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Arc;

    const W: usize = 8;
    const H: usize = 6;

    /// A presenter into test memory (RGBA8 rows bottom-up), lending it when `lends`.
    struct Memory {
        buffer: external::CallerBuffer,
        lends: bool,
        copies: Arc<AtomicUsize>,
    }

    impl Present for Memory {
        fn present(&mut self, framebuffer: &Framebuffer) {
            self.copies.fetch_add(1, Ordering::SeqCst);
            let Some(ColorPixels::Unorm8(px)) = framebuffer.color(ColorSlot::FrontLeft).map(|b| b.pixels()) else {
                return;
            };
            self.buffer.unorm8_pixels_mut(W * H).unwrap().copy_from_slice(&px[..W * H]);
        }

        fn only_when_drawn(&self) -> bool {
            true
        }

        fn lends(&self, _framebuffer: &Framebuffer) -> bool {
            self.lends
        }

        fn lend(&mut self, framebuffer: &Framebuffer) -> Option<external::CallerBuffer> {
            self.lends(framebuffer).then(|| std::mem::replace(&mut self.buffer, external::CallerBuffer::empty()))
        }

        fn give_back(&mut self, memory: external::CallerBuffer) {
            self.buffer = memory;
        }

        fn memory(&self) -> Option<usize> {
            Some(self.buffer.as_ptr() as usize)
        }
    }

    fn drawable(memory: &mut [u8], lends: bool) -> (Drawable, Arc<AtomicUsize>) {
        let config =
            FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, DepthStencilFormat::None, 0);
        let framebuffer = Framebuffer::new(config, W, H).unwrap();
        let copies = Arc::new(AtomicUsize::new(0));
        let presenter = Memory { buffer: external::CallerBuffer::of_test_vec(memory), lends, copies: copies.clone() };
        (Drawable::new(framebuffer, Some(Box::new(presenter))), copies)
    }

    /// Fills the rows `[y0, y1)` of the front-left color, as a scene's band workers write.
    fn fill_rows(framebuffer: &mut Framebuffer, y0: usize, y1: usize, pixel: [u8; 4]) {
        for mut band in framebuffer.bands(1, &[ColorSlot::FrontLeft]) {
            let y = band.y0 as usize;
            if let ColorBand::Unorm8(px) = &mut band.colors[0].pixels {
                if (y0..y1).contains(&y) {
                    px.fill(pixel);
                }
            }
        }
    }

    fn own_pixels(drawable: &Drawable) -> Vec<[u8; 4]> {
        let Some(ColorPixels::Unorm8(px)) = drawable.framebuffer.color(ColorSlot::FrontLeft).map(|b| b.pixels()) else {
            unreachable!()
        };
        px[..W * H].to_vec()
    }

    fn pixel_rows(memory: &[u8]) -> Vec<[u8; 4]> {
        memory.as_chunks::<4>().0.to_vec()
    }

    #[test]
    fn a_scene_that_overwrites_renders_in_place_and_is_not_copied() {
        let mut memory = vec![0xEE; W * H * 4];
        let (mut drawable, copies) = drawable(&mut memory, true);
        drawable.render_for_presentation(true, |fb| fill_rows(fb, 0, H, [1, 2, 3, 4]));
        drawable.present();
        assert_eq!(copies.load(Ordering::SeqCst), 0, "presented by a copy");
        assert_eq!(own_pixels(&drawable), vec![[0; 4]; W * H], "the own pixels were touched");
        // Every other use brings the image home.
        let _ = drawable.framebuffer_to_read();
        assert_eq!(own_pixels(&drawable), vec![[1, 2, 3, 4]; W * H]);
        drop(drawable);
        assert_eq!(pixel_rows(&memory), vec![[1, 2, 3, 4]; W * H]);
    }

    #[test]
    fn a_scene_that_builds_on_an_image_the_memory_lacks_renders_into_the_own_pixels() {
        let mut memory = vec![0xEE; W * H * 4];
        let (mut drawable, copies) = drawable(&mut memory, true);
        drawable.render_for_presentation(false, |fb| fill_rows(fb, 0, 2, [9; 4]));
        assert_eq!(copies.load(Ordering::SeqCst), 0);
        drawable.present();
        assert_eq!(copies.load(Ordering::SeqCst), 1, "not presented by a copy");
        // The memory now holds the image: the next frame builds on it in place.
        drawable.render_for_presentation(false, |fb| fill_rows(fb, 4, 5, [7; 4]));
        drawable.present();
        assert_eq!(copies.load(Ordering::SeqCst), 1);
        drop(drawable);
        let rows = pixel_rows(&memory);
        assert_eq!(rows[0], [9; 4]);
        assert_eq!(rows[2 * W], [0; 4], "the fresh image is black, whatever the memory held");
        assert_eq!(rows[4 * W], [7; 4]);
    }

    #[test]
    fn the_memory_goes_back_when_rendering_panics() {
        let mut memory = vec![0xEE; W * H * 4];
        let (mut drawable, _) = drawable(&mut memory, true);
        let panicked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drawable.render_for_presentation(true, |_| panic!("injected"))
        }));
        assert!(panicked.is_err());
        assert!(drawable.framebuffer.in_place_front.is_none(), "the framebuffer kept the memory");
        // The presenter has it back: it lends it again.
        drawable.render_for_presentation(true, |fb| fill_rows(fb, 0, H, [2; 4]));
        drop(drawable);
        assert_eq!(pixel_rows(&memory), vec![[2; 4]; W * H]);
    }

    #[test]
    fn a_presenter_that_does_not_lend_is_presented_by_copies() {
        let mut memory = vec![0xEE; W * H * 4];
        let (mut drawable, copies) = drawable(&mut memory, false);
        drawable.render_for_presentation(true, |fb| fill_rows(fb, 0, H, [5; 4]));
        assert_eq!(own_pixels(&drawable), vec![[5; 4]; W * H]);
        drawable.present();
        assert_eq!(copies.load(Ordering::SeqCst), 1);
    }

    #[test]
    fn other_memory_is_never_read_once_the_presenter_is_replaced() {
        let (mut first, mut second) = (vec![0xEE; W * H * 4], vec![0x55; W * H * 4]);
        let (mut drawable, _) = drawable(&mut first, true);
        drawable.render_for_presentation(true, |fb| fill_rows(fb, 0, H, [1; 4]));
        drawable.present();
        let copies = Arc::new(AtomicUsize::new(0));
        let buffer = external::CallerBuffer::of_test_vec(&mut second);
        drawable.set_presenter(Some(Box::new(Memory { buffer, lends: true, copies })));
        // The old memory changes (as freed memory would): the image is the new memory's.
        first.fill(0x99);
        let _ = drawable.framebuffer_to_read();
        assert_eq!(own_pixels(&drawable), vec![[0x55; 4]; W * H]);
    }

    #[test]
    fn the_same_memory_in_a_layout_not_rendered_into_brings_the_image_home() {
        let mut memory = vec![0xEE; W * H * 4];
        let (mut drawable, copies) = drawable(&mut memory, true);
        drawable.render_for_presentation(true, |fb| fill_rows(fb, 0, H, [3; 4]));
        drawable.present();
        let buffer = external::CallerBuffer::of_test_vec(&mut memory);
        drawable.set_presenter(Some(Box::new(Memory { buffer, lends: false, copies: copies.clone() })));
        assert_eq!(own_pixels(&drawable), vec![[3; 4]; W * H]);
        // The next frame draws into the own pixels and is copied.
        drawable.render_for_presentation(false, |fb| fill_rows(fb, 0, 1, [4; 4]));
        drawable.present();
        assert_eq!(copies.load(Ordering::SeqCst), 1);
    }
}
