//! Framebuffer objects and renderbuffers (ARB/EXT_framebuffer_object, EXT_framebuffer_blit):
//! the objects, their bindings, completeness, queries, and what draws and reads go to.
//!
//! **Where attached images live, and rendering in place.** A renderbuffer owns a
//! framebuffer-format buffer (a [`ColorBuffer`] or [`DepthStencilBuffer`], the same types a
//! window's framebuffer is made of). A texture keeps its images in the texture store in the
//! same storage (`crate::texture`: RGBA8 texels are the pixels of an 8-bit unorm color
//! buffer, a depth image is a [`DepthStencilBuffer`] of its format, which the sampler
//! decodes per fetch). Whenever the context needs the bound framebuffer object as a
//! [`Framebuffer`] (to execute the recorded scene, clear, read, blit),
//! [`Context::with_object_framebuffer`] assembles one by *moving* each attached image in:
//! a renderbuffer's storage, or a texture image's texel vector (the image leaves the shared
//! texture table meanwhile), and moves them back afterwards. No pixel is copied or converted
//! per scene, draw or bind, so rendering into a texture costs what rendering into a
//! renderbuffer costs and gives the same values. The rasterizer is unchanged: the scene
//! executes on a `Framebuffer` split into bands as for a window, so tiles still own pixels
//! and results do not depend on the thread count. Recorded draws run when the draw binding
//! or an attachment changes (a flush point), so the texture store is current whenever the
//! texture is next sampled, read or specified.
//!
//! What still copies, only where it must: a layer of a 3D texture (a slice of one texel
//! vector) is copied into a framebuffer-sized buffer and written back after rendering; a
//! texture image still shared when it is lent (GL's undefined feedback loop of sampling a
//! texture while rendering into it, or another context's recorded draws) is cloned, so that
//! the holder keeps sampling the texels it recorded; and color formats of fewer than 8 bits
//! per channel (GL_RGBA4, GL_RGB5_A1, GL_R3_G3_B2, ...) are rendered as 8-bit and quantized
//! to their bits in place after each scene that wrote them (a table lookup per texel), as
//! the texture store keeps every image of them quantized.
//!
//! **Formats** (storage, reported sizes): RGB/RGBA(8) and the smaller unorm formats as
//! 8-bit unorm, RGB(A)12/16 as 16-bit unorm, RGB(A)16F/32F as f32 (16F keeps f32 precision),
//! DEPTH_COMPONENT16/24/32 and 32F as 16/24/32-bit depth (32F as 32-bit unorm: depth is
//! clamped to [0, 1] anyway), STENCIL_INDEX* as 8-bit stencil, DEPTH24_STENCIL8 packed.
//! Textures are renderable when their base format is RGB, RGBA or depth, without border;
//! formats of fewer than 8 bits per channel are quantized when the rendered image is stored.
//!
//! **Combinations reported GL_FRAMEBUFFER_UNSUPPORTED** (allowed by the specification, and
//! what Mesa's Gallium drivers also reject): depth and stencil in two different images,
//! attached images of different sizes, one image attached at two color points, textures of
//! other base formats or with a border, and renderbuffers of the alpha, luminance and
//! intensity formats (accepted by glRenderbufferStorage).
//!
//! **Multisample renderbuffers**: glRenderbufferStorageMultisample allocates the smallest
//! supported count of at least the requested one (1 → 2; 2, 4 or 8, `framebuffer::
//! multisample`), which GL_RENDERBUFFER_SAMPLES reports; the storage holds every sample
//! (sample rows), and a framebuffer object of multisampled attachments is assembled into a
//! multisampled [`Framebuffer`] ([`Framebuffer::from_sample_layers`]) without resolved
//! layers: reading it needs a glBlitFramebuffer resolve, as the specification says.
use super::state::ScissorState;
use super::texture::TARGETS;
use super::Context;
use crate::framebuffer::blit::{self, BlitAxis, ColorSource, DepthStencilSource};
use crate::framebuffer::layers::{color_buffer, depth_stencil_buffer};
use crate::framebuffer::multisample::supported_samples;
use crate::framebuffer::surface::ColorPixels;
use crate::framebuffer::{
    ColorBuffer, ColorFormat, ColorSlot, DepthStencilBuffer, DepthStencilFormat, Framebuffer, FramebufferConfig,
    OutOfMemory, Rect,
};
use crate::gl::enums::*;
use crate::gl::limits::MAX_DRAW_BUFFERS;
use crate::gl::names::{NameTable, OutOfNames};
use crate::gl::types::GLenum;
use crate::texture::{BaseFormat, TexImage, Texels};
use std::sync::Arc;

/// GL_MAX_COLOR_ATTACHMENTS.
pub const MAX_COLOR_ATTACHMENTS: usize = 8;
/// GL_MAX_RENDERBUFFER_SIZE.
pub const MAX_RENDERBUFFER_SIZE: i32 = 16384;
/// GL_MAX_SAMPLES: the counts glRenderbufferStorageMultisample accepts.
pub const MAX_SAMPLES: i32 = 8;

/// Index of the depth and stencil attachment points after the color ones.
const DEPTH: usize = MAX_COLOR_ATTACHMENTS;
const STENCIL: usize = MAX_COLOR_ATTACHMENTS + 1;
const POINTS: usize = MAX_COLOR_ATTACHMENTS + 2;

/// What is attached at one attachment point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attachment {
    Renderbuffer(u32),
    /// A texture image: object, index into [`TARGETS`], cube face, mipmap level, 3D layer.
    Texture {
        name: u32,
        target: usize,
        face: usize,
        level: usize,
        layer: usize,
    },
}

/// A framebuffer object: its attachments and its draw/read buffer state.
#[derive(Clone, Debug)]
pub struct FramebufferObject {
    attachments: [Option<Attachment>; POINTS],
    draw_buffers: [GLenum; MAX_DRAW_BUFFERS],
    read_buffer: GLenum,
}

impl FramebufferObject {
    fn new() -> Self {
        let mut draw_buffers = [GL_NONE; MAX_DRAW_BUFFERS];
        draw_buffers[0] = GL_COLOR_ATTACHMENT0;
        FramebufferObject { attachments: [None; POINTS], draw_buffers, read_buffer: GL_COLOR_ATTACHMENT0 }
    }
}

/// A renderbuffer's pixels.
#[derive(Debug, Default)]
pub enum RenderbufferStorage {
    #[default]
    None,
    Color(ColorBuffer),
    DepthStencil(DepthStencilBuffer),
}

/// A renderbuffer object.
#[derive(Debug)]
pub struct Renderbuffer {
    pub internal_format: GLenum,
    pub width: usize,
    pub height: usize,
    /// The sample count requested by glRenderbufferStorageMultisample.
    pub requested_samples: i32,
    /// The samples per pixel of the storage (1: single-sampled).
    pub samples: usize,
    pub format: Option<Renderable>,
    storage: RenderbufferStorage,
}

/// The storage format of a renderable internal format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Renderable {
    Color(ColorFormat),
    DepthStencil(DepthStencilFormat),
}

impl Renderable {
    fn depth_bits(self) -> u32 {
        match self {
            Renderable::DepthStencil(f) => f.depth_bits(),
            Renderable::Color(_) => 0,
        }
    }

    fn stencil_bits(self) -> u32 {
        match self {
            Renderable::DepthStencil(f) => f.stencil_bits(),
            Renderable::Color(_) => 0,
        }
    }
}

/// The storage of a renderbuffer internal format; `None` when not renderable.
pub fn renderbuffer_format(internal_format: GLenum) -> Option<Renderable> {
    use ColorFormat::*;
    use DepthStencilFormat::{Depth16, Depth32, Packed24};
    Some(match internal_format {
        GL_RGB | GL_RGB8 | GL_R3_G3_B2 | GL_RGB4 | GL_RGB5 | GL_RGB10 => Renderable::Color(Unorm8 { alpha: false }),
        GL_RGBA | GL_RGBA8 | GL_RGBA2 | GL_RGBA4 | GL_RGB5_A1 | GL_RGB10_A2 => {
            Renderable::Color(Unorm8 { alpha: true })
        }
        GL_RGB12 | GL_RGB16 => Renderable::Color(Unorm16 { alpha: false }),
        GL_RGBA12 | GL_RGBA16 => Renderable::Color(Unorm16 { alpha: true }),
        GL_RGB16F | GL_RGB32F => Renderable::Color(Float32 { alpha: false }),
        GL_RGBA16F | GL_RGBA32F => Renderable::Color(Float32 { alpha: true }),
        GL_DEPTH_COMPONENT16 => Renderable::DepthStencil(Depth16),
        GL_DEPTH_COMPONENT | GL_DEPTH_COMPONENT24 => Renderable::DepthStencil(Packed24 { depth: true, stencil: false }),
        GL_DEPTH_COMPONENT32 => Renderable::DepthStencil(Depth32 { stencil: false }),
        // ARB_depth_buffer_float: depth stored as floats.
        GL_DEPTH_COMPONENT32F => Renderable::DepthStencil(DepthStencilFormat::Float32 { stencil: false }),
        GL_DEPTH32F_STENCIL8 => Renderable::DepthStencil(DepthStencilFormat::Float32 { stencil: true }),
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 => Renderable::DepthStencil(Packed24 { depth: true, stencil: true }),
        // Accepted (ARB_framebuffer_object makes them color-renderable in the compatibility
        // profile) but stored as RGBA8 and reported GL_FRAMEBUFFER_UNSUPPORTED when attached.
        GL_ALPHA
        | GL_ALPHA4
        | GL_ALPHA8
        | GL_ALPHA12
        | GL_ALPHA16
        | GL_LUMINANCE
        | GL_LUMINANCE4
        | GL_LUMINANCE8
        | GL_LUMINANCE12
        | GL_LUMINANCE16
        | GL_LUMINANCE_ALPHA
        | GL_LUMINANCE4_ALPHA4
        | GL_LUMINANCE6_ALPHA2
        | GL_LUMINANCE8_ALPHA8
        | GL_LUMINANCE12_ALPHA4
        | GL_LUMINANCE12_ALPHA12
        | GL_LUMINANCE16_ALPHA16
        | GL_INTENSITY
        | GL_INTENSITY4
        | GL_INTENSITY8
        | GL_INTENSITY12
        | GL_INTENSITY16 => Renderable::Color(Unorm8 { alpha: true }),
        GL_STENCIL_INDEX | GL_STENCIL_INDEX1 | GL_STENCIL_INDEX4 | GL_STENCIL_INDEX8 | GL_STENCIL_INDEX16 => {
            Renderable::DepthStencil(Packed24 { depth: false, stencil: true })
        }
        _ => return None,
    })
}

/// Whether attaching a renderbuffer of `internal_format` can give a complete framebuffer
/// (not the luminance, alpha and intensity formats, which are accepted but not rendered).
fn renderbuffer_supported(internal_format: GLenum) -> bool {
    let rgba8 =
        matches!(renderbuffer_format(internal_format), Some(Renderable::Color(ColorFormat::Unorm8 { alpha: true })));
    !rgba8 || matches!(internal_format, GL_RGBA | GL_RGBA8 | GL_RGBA2 | GL_RGBA4 | GL_RGB5_A1 | GL_RGB10_A2)
}

/// The framebuffer and renderbuffer objects of a context and their bindings.
#[derive(Debug)]
pub struct FramebufferObjects {
    framebuffers: NameTable<FramebufferObject>,
    renderbuffers: NameTable<Renderbuffer>,
    /// GL_DRAW_FRAMEBUFFER_BINDING and GL_READ_FRAMEBUFFER_BINDING (0: the window's).
    pub draw: u32,
    pub read: u32,
    /// GL_RENDERBUFFER_BINDING.
    pub renderbuffer: u32,
    /// The window framebuffer's draw and read buffers while an object is bound (the
    /// context's state holds those of the bound framebuffers).
    window_draw_buffers: [GLenum; MAX_DRAW_BUFFERS],
    window_read_buffer: GLenum,
}

impl FramebufferObjects {
    /// No objects; `window_buffer` is the window's initial draw/read buffer.
    pub fn new(window_buffer: GLenum) -> Self {
        let mut window_draw_buffers = [GL_NONE; MAX_DRAW_BUFFERS];
        window_draw_buffers[0] = window_buffer;
        FramebufferObjects {
            framebuffers: NameTable::default(),
            renderbuffers: NameTable::default(),
            draw: 0,
            read: 0,
            renderbuffer: 0,
            window_draw_buffers,
            window_read_buffer: window_buffer,
        }
    }
}

/// The attachment point an enum names: `Ok(index)`, or the error it gives.
fn attachment_point(attachment: GLenum) -> Result<usize, GLenum> {
    match attachment {
        GL_DEPTH_ATTACHMENT => Ok(DEPTH),
        GL_STENCIL_ATTACHMENT => Ok(STENCIL),
        a if (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + MAX_COLOR_ATTACHMENTS as GLenum).contains(&a) => {
            Ok((a - GL_COLOR_ATTACHMENT0) as usize)
        }
        // Color attachments beyond the maximum exist as enums: GL_INVALID_OPERATION (Mesa).
        a if (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + 32).contains(&a) => Err(GL_INVALID_OPERATION),
        _ => Err(GL_INVALID_ENUM),
    }
}

/// The slot of a framebuffer object's draw or read buffer enum: `Some(None)` for GL_NONE,
/// `None` when the enum names no attachment.
pub fn attachment_slot(buffer: GLenum) -> Option<Option<ColorSlot>> {
    match buffer {
        GL_NONE => Some(None),
        b if (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + MAX_COLOR_ATTACHMENTS as GLenum).contains(&b) => {
            Some(Some(ColorSlot::Attachment((b - GL_COLOR_ATTACHMENT0) as u8)))
        }
        _ => None,
    }
}

/// GL_RENDERBUFFER_SAMPLES / GL_SAMPLES of storage with `samples` samples per pixel.
fn reported_samples(samples: usize) -> i32 {
    if samples > 1 {
        samples as i32
    } else {
        0
    }
}

/// What completeness and assembly need to know about one attached image.
#[derive(Clone, Copy, Debug, PartialEq)]
struct ImageInfo {
    width: usize,
    height: usize,
    format: Renderable,
    samples: i32,
    /// Texture images that cannot be rendered into (other formats, borders).
    supported: bool,
}

/// Which of the completeness rules fails first, as glCheckFramebufferStatus reports it.
/// `images` holds the attachment points' images (`None`: nothing attached; `Some(None)`:
/// attached but not attachment-complete).
fn completeness(
    images: &[Option<Option<ImageInfo>>; POINTS],
    attachments: &[Option<Attachment>; POINTS],
    draw_buffers: &[GLenum],
    read_buffer: GLenum,
) -> GLenum {
    let mut any = false;
    for (point, image) in images.iter().enumerate() {
        let Some(image) = image else { continue };
        any = true;
        let Some(info) = image else {
            return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
        };
        let fits = match (point, info.format) {
            (DEPTH, f) => f.depth_bits() > 0,
            (STENCIL, f) => f.stencil_bits() > 0,
            (_, Renderable::Color(_)) => true,
            _ => false,
        };
        if !fits || info.width == 0 || info.height == 0 {
            return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
        }
    }
    if !any {
        return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
    }
    for &buffer in draw_buffers {
        if let Some(Some(ColorSlot::Attachment(i))) = attachment_slot(buffer) {
            if images[i as usize].is_none() {
                return GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER;
            }
        }
    }
    if let Some(Some(ColorSlot::Attachment(i))) = attachment_slot(read_buffer) {
        if images[i as usize].is_none() {
            return GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER;
        }
    }
    let infos: Vec<ImageInfo> = images.iter().flatten().flatten().copied().collect();
    if infos.iter().any(|i| i.samples != infos[0].samples) {
        return GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE;
    }
    let same_size = infos.iter().all(|i| (i.width, i.height) == (infos[0].width, infos[0].height));
    let separate_depth_stencil = matches!((attachments[DEPTH], attachments[STENCIL]), (Some(d), Some(s)) if d != s);
    let colors: Vec<Attachment> = attachments[..MAX_COLOR_ATTACHMENTS].iter().flatten().copied().collect();
    let repeated_color = colors.iter().enumerate().any(|(i, a)| colors[..i].contains(a));
    if !same_size || separate_depth_stencil || repeated_color || infos.iter().any(|i| !i.supported) {
        return GL_FRAMEBUFFER_UNSUPPORTED;
    }
    GL_FRAMEBUFFER_COMPLETE
}

/// How an attached texture image was lent to an assembled framebuffer
/// ([`Context::lend_texture`]); `bits`: the bits per channel its format stores.
enum Lent {
    /// The whole image: `shell` is the image without its texels (moved into the
    /// framebuffer). `shared` is the table's `Arc` when something else held it too (the
    /// texels were then cloned).
    Whole { shell: TexImage, shared: Option<Arc<TexImage>>, bits: [u32; 4] },
    /// A copy of one layer of a 3D image.
    Layer { bits: [u32; 4] },
}

impl Lent {
    fn bits(&self) -> [u32; 4] {
        match self {
            Lent::Whole { bits, .. } | Lent::Layer { bits } => *bits,
        }
    }
}

/// Quantizes rendered 8-bit texels to the `bits` per channel of their format (GL_RGB5_A1,
/// GL_RGBA4, GL_R3_G3_B2, GL_RGB10_A2's alpha, ...), as the texture store keeps every image
/// of such formats; nothing to do for 8-bit formats. Channels of 0 bits keep their value
/// (alpha 1 of formats without alpha).
fn quantize_texels(texels: &mut [[u8; 4]], bits: [u32; 4]) {
    if bits.iter().all(|&b| b == 0 || b >= 8) {
        return;
    }
    let tables: [[u8; 256]; 4] = std::array::from_fn(|c| {
        std::array::from_fn(|v| match bits[c] {
            1..=7 => crate::texture::quantize_to_u8(v as f32 / 255.0, bits[c]),
            _ => v as u8,
        })
    });
    for t in texels {
        *t = std::array::from_fn(|c| tables[c][t[c] as usize]);
    }
}

impl Context {
    // ---- Object names ----------------------------------------------------------------

    /// glGenFramebuffers / glGenRenderbuffers.
    pub fn gen_fbo_names(&mut self, n: i32, renderbuffers: bool) -> Option<Vec<u32>> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if n < 0 {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        let names = if renderbuffers {
            self.fbo.renderbuffers.generate(n as usize)
        } else {
            self.fbo.framebuffers.generate(n as usize)
        };
        match names {
            Ok(names) => Some(names),
            Err(OutOfNames) => {
                self.error(GL_OUT_OF_MEMORY);
                None
            }
        }
    }

    /// glIsFramebuffer.
    pub fn is_framebuffer(&mut self, name: u32) -> bool {
        self.check_outside_begin_end() && name != 0 && self.fbo.framebuffers.is_object(name)
    }

    /// glIsRenderbuffer.
    pub fn is_renderbuffer(&mut self, name: u32) -> bool {
        self.check_outside_begin_end() && name != 0 && self.fbo.renderbuffers.is_object(name)
    }

    /// glBindFramebuffer: `target` GL_FRAMEBUFFER binds both, GL_DRAW_/READ_FRAMEBUFFER one.
    /// Each framebuffer has its own draw and read buffers, swapped into the context state.
    pub fn bind_framebuffer(&mut self, target: GLenum, name: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let (draw, read) = match target {
            GL_FRAMEBUFFER => (true, true),
            GL_DRAW_FRAMEBUFFER => (true, false),
            GL_READ_FRAMEBUFFER => (false, true),
            _ => return self.error(GL_INVALID_ENUM),
        };
        self.fbo.framebuffers.get_or_create(name, FramebufferObject::new);
        if draw && self.fbo.draw != name {
            // What was recorded belongs to the old draw framebuffer.
            self.flush_rendering();
            let current = self.state.color.draw_buffers;
            match self.fbo.framebuffers.get_mut(self.fbo.draw) {
                Some(old) => old.draw_buffers = current,
                None => self.fbo.window_draw_buffers = current,
            }
            self.state.color.draw_buffers = match self.fbo.framebuffers.get(name) {
                Some(new) => new.draw_buffers,
                None => self.fbo.window_draw_buffers,
            };
            self.fbo.draw = name;
        }
        if read && self.fbo.read != name {
            let current = self.state.pixel_mode.read_buffer;
            match self.fbo.framebuffers.get_mut(self.fbo.read) {
                Some(old) => old.read_buffer = current,
                None => self.fbo.window_read_buffer = current,
            }
            self.state.pixel_mode.read_buffer = match self.fbo.framebuffers.get(name) {
                Some(new) => new.read_buffer,
                None => self.fbo.window_read_buffer,
            };
            self.fbo.read = name;
        }
    }

    /// glDeleteFramebuffers: bound objects are unbound first (the window's framebuffer
    /// becomes bound).
    pub fn delete_framebuffers(&mut self, n: i32, names: &[u32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if n < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        for &name in names {
            if name == 0 {
                continue;
            }
            if self.fbo.draw == name {
                self.bind_framebuffer(GL_DRAW_FRAMEBUFFER, 0);
            }
            if self.fbo.read == name {
                self.bind_framebuffer(GL_READ_FRAMEBUFFER, 0);
            }
            self.fbo.framebuffers.delete(name);
        }
    }

    /// glBindRenderbuffer.
    pub fn bind_renderbuffer(&mut self, target: GLenum, name: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if target != GL_RENDERBUFFER {
            return self.error(GL_INVALID_ENUM);
        }
        self.fbo.renderbuffers.get_or_create(name, || Renderbuffer {
            internal_format: GL_RGBA,
            width: 0,
            height: 0,
            requested_samples: 0,
            samples: 1,
            format: None,
            storage: RenderbufferStorage::None,
        });
        self.fbo.renderbuffer = name;
    }

    /// glDeleteRenderbuffers: a deleted renderbuffer is unbound and detached from the
    /// framebuffer objects (here from every one, not only the bound ones).
    pub fn delete_renderbuffers(&mut self, n: i32, names: &[u32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if n < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        for &name in names {
            if name == 0 {
                continue;
            }
            if !self.fbo.renderbuffers.is_object(name) {
                // A reserved name is only freed.
                self.fbo.renderbuffers.delete(name);
            } else {
                self.detach_everywhere(Attachment::Renderbuffer(name));
                self.fbo.renderbuffers.delete(name);
                if self.fbo.renderbuffer == name {
                    self.fbo.renderbuffer = 0;
                }
            }
        }
    }

    /// Completes the draws recorded into a framebuffer object before a texture image is read
    /// or specified: they may write texture images (which are current only after a flush).
    pub(super) fn flush_into_textures(&mut self) {
        if self.fbo.draw != 0 {
            self.flush_rendering();
        }
    }

    /// Detaches every image of texture `name` (it is being deleted).
    pub(super) fn detach_texture(&mut self, name: u32) {
        let attached = |a: &Attachment| matches!(a, Attachment::Texture { name: n, .. } if *n == name);
        let any = self.fbo.framebuffers.values().any(|f| f.attachments.iter().flatten().any(attached));
        if any {
            self.flush_rendering();
            for f in self.fbo.framebuffers.values_mut() {
                for a in &mut f.attachments {
                    if a.as_ref().is_some_and(attached) {
                        *a = None;
                    }
                }
            }
        }
    }

    fn detach_everywhere(&mut self, attachment: Attachment) {
        self.flush_rendering();
        for f in self.fbo.framebuffers.values_mut() {
            for a in &mut f.attachments {
                if *a == Some(attachment) {
                    *a = None;
                }
            }
        }
    }

    // ---- Renderbuffer storage -----------------------------------------------------------

    /// glRenderbufferStorage(Multisample): (re)allocates the bound renderbuffer's storage.
    pub fn renderbuffer_storage(&mut self, target: GLenum, samples: i32, internal_format: GLenum, w: i32, h: i32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if target != GL_RENDERBUFFER {
            return self.error(GL_INVALID_ENUM);
        }
        let Some(format) = renderbuffer_format(internal_format) else {
            return self.error(GL_INVALID_ENUM);
        };
        if w < 0 || h < 0 || w > MAX_RENDERBUFFER_SIZE || h > MAX_RENDERBUFFER_SIZE {
            return self.error(GL_INVALID_VALUE);
        }
        if !(0..=MAX_SAMPLES).contains(&samples) {
            return self.error(GL_INVALID_VALUE);
        }
        let name = self.fbo.renderbuffer;
        if name == 0 {
            return self.error(GL_INVALID_OPERATION);
        }
        // Draws recorded into the old storage complete first.
        self.flush_rendering();
        let (w, h) = (w as usize, h as usize);
        let sample_count = supported_samples(samples as usize).unwrap_or(1);
        // Multisampled storage: `sample_count` storage rows per pixel row.
        let rows = h * sample_count;
        let storage = match format {
            Renderable::Color(f) => color_buffer(f, w, rows).map(RenderbufferStorage::Color),
            Renderable::DepthStencil(f) => depth_stencil_buffer(f, w, rows).map(RenderbufferStorage::DepthStencil),
        };
        let Ok(storage) = storage else {
            return self.error(GL_OUT_OF_MEMORY);
        };
        if let Some(rb) = self.fbo.renderbuffers.get_mut(name) {
            *rb = Renderbuffer {
                internal_format,
                width: w,
                height: h,
                requested_samples: samples,
                samples: sample_count,
                format: Some(format),
                storage,
            };
        }
    }

    /// glGetRenderbufferParameteriv.
    pub fn get_renderbuffer_parameter(&mut self, target: GLenum, pname: GLenum) -> Option<i32> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if target != GL_RENDERBUFFER {
            self.error(GL_INVALID_ENUM);
            return None;
        }
        let Some(rb) = self.fbo.renderbuffers.get(self.fbo.renderbuffer) else {
            self.error(GL_INVALID_OPERATION);
            return None;
        };
        let bits = rb.format.map(renderable_sizes).unwrap_or([0; 6]);
        Some(match pname {
            GL_RENDERBUFFER_WIDTH => rb.width as i32,
            GL_RENDERBUFFER_HEIGHT => rb.height as i32,
            GL_RENDERBUFFER_INTERNAL_FORMAT => rb.internal_format as i32,
            GL_RENDERBUFFER_SAMPLES => reported_samples(rb.samples),
            GL_RENDERBUFFER_RED_SIZE => bits[0],
            GL_RENDERBUFFER_GREEN_SIZE => bits[1],
            GL_RENDERBUFFER_BLUE_SIZE => bits[2],
            GL_RENDERBUFFER_ALPHA_SIZE => bits[3],
            GL_RENDERBUFFER_DEPTH_SIZE => bits[4],
            GL_RENDERBUFFER_STENCIL_SIZE => bits[5],
            _ => {
                self.error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    // ---- Attachments --------------------------------------------------------------------

    /// The bound object of a framebuffer target, for attachment commands: `Err(error)`.
    fn attach_target(&self, target: GLenum) -> Result<u32, GLenum> {
        let name = match target {
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER => self.fbo.draw,
            GL_READ_FRAMEBUFFER => self.fbo.read,
            _ => return Err(GL_INVALID_ENUM),
        };
        if name == 0 {
            Err(GL_INVALID_OPERATION)
        } else {
            Ok(name)
        }
    }

    /// Sets attachment `point` (GL_DEPTH_STENCIL_ATTACHMENT: both) of the object bound to
    /// `target`.
    fn set_attachment(&mut self, fbo: u32, attachment: GLenum, value: Option<Attachment>) {
        if fbo == self.fbo.draw {
            self.flush_rendering();
        }
        let Some(object) = self.fbo.framebuffers.get_mut(fbo) else { return };
        if attachment == GL_DEPTH_STENCIL_ATTACHMENT {
            object.attachments[DEPTH] = value;
            object.attachments[STENCIL] = value;
        } else if let Ok(point) = attachment_point(attachment) {
            object.attachments[point] = value;
        }
    }

    /// Validates the target and attachment of an attachment command; the object name.
    fn check_attachment_command(&mut self, target: GLenum, attachment: GLenum) -> Option<u32> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let fbo = match self.attach_target(target) {
            Ok(f) => f,
            Err(GL_INVALID_ENUM) => {
                self.error(GL_INVALID_ENUM);
                return None;
            }
            Err(e) => {
                // The attachment enum is checked before the binding (as Mesa).
                if attachment != GL_DEPTH_STENCIL_ATTACHMENT {
                    if let Err(e2) = attachment_point(attachment) {
                        self.error(e2);
                        return None;
                    }
                }
                self.error(e);
                return None;
            }
        };
        if attachment != GL_DEPTH_STENCIL_ATTACHMENT {
            if let Err(e) = attachment_point(attachment) {
                self.error(e);
                return None;
            }
        }
        Some(fbo)
    }

    /// glFramebufferRenderbuffer.
    pub fn framebuffer_renderbuffer(&mut self, target: GLenum, attachment: GLenum, rb_target: GLenum, rb: u32) {
        let Some(fbo) = self.check_attachment_command(target, attachment) else { return };
        if rb_target != GL_RENDERBUFFER {
            return self.error(GL_INVALID_ENUM);
        }
        if rb != 0 && !self.fbo.renderbuffers.is_object(rb) {
            return self.error(GL_INVALID_OPERATION);
        }
        self.set_attachment(fbo, attachment, (rb != 0).then_some(Attachment::Renderbuffer(rb)));
    }

    /// glFramebufferTexture1D/2D/3D (`dims`) and glFramebufferTextureLayer (`dims` 0, target
    /// taken from the texture).
    #[allow(clippy::too_many_arguments)]
    pub fn framebuffer_texture(
        &mut self,
        dims: usize,
        target: GLenum,
        attachment: GLenum,
        tex_target: GLenum,
        texture: u32,
        level: i32,
        layer: i32,
    ) {
        let Some(fbo) = self.check_attachment_command(target, attachment) else { return };
        if texture == 0 {
            // Detaching: the texture target is still checked (as Mesa) except for Layer.
            if dims != 0 && tex_target_of(dims, tex_target).is_none() {
                return self.error(GL_INVALID_ENUM);
            }
            return self.set_attachment(fbo, attachment, None);
        }
        let Some(object_target) = self.textures.lock().object(texture).map(|o| o.target) else {
            return self.error(GL_INVALID_OPERATION);
        };
        let (t, face) = if dims == 0 {
            match object_target {
                GL_TEXTURE_3D => (2, 0),
                _ => return self.error(GL_INVALID_OPERATION),
            }
        } else {
            let Some((t, face)) = tex_target_of(dims, tex_target) else {
                // A texture target of another dimensionality is GL_INVALID_OPERATION (Mesa).
                let any_dims = (1..=3).any(|d| tex_target_of(d, tex_target).is_some());
                return self.error(if any_dims { GL_INVALID_OPERATION } else { GL_INVALID_ENUM });
            };
            if TARGETS[t] != object_target {
                return self.error(GL_INVALID_OPERATION);
            }
            (t, face)
        };
        let max_size = match t {
            2 => super::texture::MAX_3D_TEXTURE_SIZE,
            3 => super::texture::MAX_CUBE_MAP_TEXTURE_SIZE,
            _ => super::texture::MAX_TEXTURE_SIZE,
        };
        let max_level = usize::BITS - max_size.leading_zeros() - 1;
        if level < 0 || level as u32 > max_level {
            return self.error(GL_INVALID_VALUE);
        }
        if t == 2 && (layer < 0 || layer as usize >= super::texture::MAX_3D_TEXTURE_SIZE) {
            return self.error(GL_INVALID_VALUE);
        }
        let layer = if t == 2 { layer as usize } else { 0 };
        let value = Attachment::Texture { name: texture, target: t, face, level: level as usize, layer };
        self.set_attachment(fbo, attachment, Some(value));
    }

    /// glGetFramebufferAttachmentParameteriv.
    pub fn get_framebuffer_attachment_parameter(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        pname: GLenum,
    ) -> Option<i32> {
        let window = match target {
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER => self.fbo.draw == 0,
            GL_READ_FRAMEBUFFER => self.fbo.read == 0,
            _ => false,
        };
        if window && self.check_outside_begin_end() {
            return self.window_attachment_parameter(attachment, pname);
        }
        let fbo = self.check_attachment_command(target, attachment)?;
        let object = &self.fbo.framebuffers[&fbo];
        let point = if attachment == GL_DEPTH_STENCIL_ATTACHMENT {
            if object.attachments[DEPTH] != object.attachments[STENCIL] {
                self.error(GL_INVALID_OPERATION);
                return None;
            }
            DEPTH
        } else {
            attachment_point(attachment).ok()?
        };
        let attached = object.attachments[point];
        let format = self.image_info(attached).flatten().map(|i| i.format);
        let sizes = format.map(renderable_sizes).unwrap_or([0; 6]);
        let value = match (pname, attached) {
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, None) => GL_NONE as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attachment::Renderbuffer(_))) => GL_RENDERBUFFER as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attachment::Texture { .. })) => GL_TEXTURE as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, None) => 0,
            (
                GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                Some(Attachment::Renderbuffer(n) | Attachment::Texture { name: n, .. }),
            ) => n as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, Some(Attachment::Texture { level, .. })) => level as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, Some(Attachment::Texture { target, face, .. })) => {
                if target == 3 {
                    (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face as GLenum) as i32
                } else {
                    0
                }
            }
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, Some(Attachment::Texture { layer, .. })) => layer as i32,
            (
                GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE
                | GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                Some(_),
            ) => sizes[(pname - GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE) as usize],
            // Depth and stencil of one image may differ in type: no single answer (as Mesa).
            (GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, Some(_)) if attachment == GL_DEPTH_STENCIL_ATTACHMENT => {
                self.error(GL_INVALID_OPERATION);
                return None;
            }
            (GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, Some(_)) => match format {
                // A float depth format answers GL_FLOAT for its stencil too (Mesa: the
                // datatype of the whole Z32F_S8 format).
                Some(Renderable::Color(ColorFormat::Float32 { .. }))
                | Some(Renderable::DepthStencil(DepthStencilFormat::Float32 { .. })) => GL_FLOAT as i32,
                _ => GL_UNSIGNED_NORMALIZED as i32,
            },
            (GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, Some(_)) => GL_LINEAR as i32,
            _ => {
                self.error(if attached.is_none() { GL_INVALID_OPERATION } else { GL_INVALID_ENUM });
                return None;
            }
        };
        Some(value)
    }

    /// glGetFramebufferAttachmentParameteriv on the window's framebuffer (GL 3.0 section
    /// 6.1.13): its buffers are of type GL_FRAMEBUFFER_DEFAULT.
    fn window_attachment_parameter(&mut self, attachment: GLenum, pname: GLenum) -> Option<i32> {
        let visual = self.config.visual;
        let present = match attachment {
            GL_DEPTH => visual.depth_stencil.depth_bits() > 0,
            GL_STENCIL => visual.depth_stencil.stencil_bits() > 0,
            GL_FRONT_LEFT | GL_FRONT_RIGHT | GL_BACK_LEFT | GL_BACK_RIGHT | GL_AUX0 | GL_AUX1 | GL_AUX2 | GL_AUX3 => {
                super::buffers::slots_of(&visual, attachment).is_some_and(|s| !s.is_empty())
            }
            _ => {
                self.error(GL_INVALID_ENUM);
                return None;
            }
        };
        let [r, g, b, a] = visual.color.channel_bits().map(|b| b as i32);
        let color = !matches!(attachment, GL_DEPTH | GL_STENCIL);
        let size = |c: i32| if color { c } else { 0 };
        let value = match pname {
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE => (if present { GL_FRAMEBUFFER_DEFAULT } else { GL_NONE }) as i32,
            _ if !present => {
                self.error(GL_INVALID_OPERATION);
                return None;
            }
            GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE => size(r),
            GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE => size(g),
            GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE => size(b),
            GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE => size(a),
            GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => {
                if attachment == GL_DEPTH {
                    visual.depth_stencil.depth_bits() as i32
                } else {
                    0
                }
            }
            GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => {
                if attachment == GL_STENCIL {
                    visual.depth_stencil.stencil_bits() as i32
                } else {
                    0
                }
            }
            GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE => {
                if (color && visual.color.is_float()) || (!color && visual.depth_stencil.is_float_depth()) {
                    GL_FLOAT as i32
                } else {
                    GL_UNSIGNED_NORMALIZED as i32
                }
            }
            GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING => GL_LINEAR as i32,
            _ => {
                self.error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(value)
    }

    // ---- Completeness -------------------------------------------------------------------

    /// The attached image's size and format: `None` when nothing is attached, `Some(None)`
    /// when the image does not exist.
    fn image_info(&self, attachment: Option<Attachment>) -> Option<Option<ImageInfo>> {
        Some(match attachment? {
            Attachment::Renderbuffer(name) => self.fbo.renderbuffers.get(name).and_then(|rb| {
                let samples = reported_samples(rb.samples);
                Some(ImageInfo {
                    width: rb.width,
                    height: rb.height,
                    format: rb.format?,
                    samples,
                    supported: renderbuffer_supported(rb.internal_format),
                })
            }),
            Attachment::Texture { name, target, face, level, layer } => {
                self.textures.lock().object(name).and_then(|o| o.level(face, level)).and_then(|l| {
                    l.image.as_ref()?;
                    if target == 2 && layer >= l.depth {
                        return None;
                    }
                    let base = l.info.base;
                    let (format, supported) = if base == BaseFormat::Depth {
                        (Renderable::DepthStencil(l.info.depth_format()), true)
                    } else {
                        let alpha = l.info.bits[3] > 0;
                        let rgb = matches!(base, BaseFormat::Rgb | BaseFormat::Rgba);
                        (Renderable::Color(ColorFormat::Unorm8 { alpha }), rgb)
                    };
                    Some(ImageInfo {
                        width: l.width,
                        height: l.height,
                        format,
                        samples: 0,
                        supported: supported && l.border == 0,
                    })
                })
            }
        })
    }

    /// The completeness status of framebuffer object `name` (0: the window's, complete).
    fn framebuffer_status(&self, name: u32) -> GLenum {
        let Some(object) = self.fbo.framebuffers.get(name) else {
            return GL_FRAMEBUFFER_COMPLETE;
        };
        let images: [Option<Option<ImageInfo>>; POINTS] =
            std::array::from_fn(|i| self.image_info(object.attachments[i]));
        // The bound framebuffers' buffer state is in the context state.
        let draw_buffers = if name == self.fbo.draw { self.state.color.draw_buffers } else { object.draw_buffers };
        let read_buffer = if name == self.fbo.read { self.state.pixel_mode.read_buffer } else { object.read_buffer };
        completeness(&images, &object.attachments, &draw_buffers, read_buffer)
    }

    /// glCheckFramebufferStatus.
    pub fn check_framebuffer_status(&mut self, target: GLenum) -> GLenum {
        if !self.check_outside_begin_end() {
            return 0;
        }
        let name = match target {
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER => self.fbo.draw,
            GL_READ_FRAMEBUFFER => self.fbo.read,
            _ => {
                self.error(GL_INVALID_ENUM);
                return 0;
            }
        };
        self.framebuffer_status(name)
    }

    /// Whether the draw (`draw`) or read framebuffer is complete; records
    /// GL_INVALID_FRAMEBUFFER_OPERATION when not (drawing, reading and copying commands).
    pub fn check_framebuffer_complete(&mut self, draw: bool) -> bool {
        let name = if draw { self.fbo.draw } else { self.fbo.read };
        if self.framebuffer_status(name) == GL_FRAMEBUFFER_COMPLETE {
            true
        } else {
            self.error(GL_INVALID_FRAMEBUFFER_OPERATION);
            false
        }
    }

    // ---- What draws and reads go to -----------------------------------------------------

    /// The shape of the draw framebuffer (the window's configuration when none is bound).
    pub fn draw_config(&self) -> FramebufferConfig {
        self.object_config(self.fbo.draw, &self.state.color.draw_buffers)
    }

    /// The shape of the read framebuffer.
    pub fn read_config(&self) -> FramebufferConfig {
        self.object_config(self.fbo.read, &[self.state.pixel_mode.read_buffer])
    }

    /// The configuration of object `name`: its depth/stencil layers and as color format
    /// the format of the first attached image among `buffers`, else of any color image.
    fn object_config(&self, name: u32, buffers: &[GLenum]) -> FramebufferConfig {
        let Some(object) = self.fbo.framebuffers.get(name) else {
            return self.config.visual;
        };
        let color_of = |point: usize| match self.image_info(object.attachments[point]) {
            Some(Some(ImageInfo { format: Renderable::Color(f), .. })) => Some(f),
            _ => None,
        };
        let by_buffer = buffers.iter().find_map(|&b| match attachment_slot(b) {
            Some(Some(ColorSlot::Attachment(i))) => color_of(i as usize),
            _ => None,
        });
        // Fragment colors are clamped unless a draw buffer is a float one (GL_FIXED_ONLY).
        let float_buffer = buffers.iter().find_map(|&b| match attachment_slot(b) {
            Some(Some(ColorSlot::Attachment(i))) => color_of(i as usize).filter(|f| f.is_float()),
            _ => None,
        });
        let color = float_buffer
            .or(by_buffer)
            .or_else(|| (0..MAX_COLOR_ATTACHMENTS).find_map(color_of))
            .unwrap_or(ColorFormat::Unorm8 { alpha: true });
        FramebufferConfig {
            color,
            double_buffered: false,
            stereo: false,
            aux_buffers: 0,
            depth_stencil: self.object_depth_stencil(object),
            accum_bits: 0,
        }
    }

    fn object_depth_stencil(&self, object: &FramebufferObject) -> DepthStencilFormat {
        let format = |point: usize| match self.image_info(object.attachments[point]) {
            Some(Some(ImageInfo { format: Renderable::DepthStencil(f), .. })) => Some(f),
            _ => None,
        };
        match (format(DEPTH), format(STENCIL)) {
            (Some(f), _) | (None, Some(f)) => f,
            (None, None) => DepthStencilFormat::None,
        }
    }

    /// The channel write mask of draw buffer `index` writing `slot`: glColorMask's, without
    /// alpha for an attachment whose format has none (its alpha stays 1, which is what
    /// blending then reads as destination alpha).
    pub fn write_mask(&self, slot: ColorSlot, index: usize) -> [bool; 4] {
        let mut mask = self.state.color.color_mask[index];
        if let (ColorSlot::Attachment(i), Some(object)) = (slot, self.fbo.framebuffers.get(self.fbo.draw)) {
            if let Some(Some(ImageInfo { format: Renderable::Color(f), .. })) =
                self.image_info(object.attachments[i as usize])
            {
                mask[3] &= f.has_alpha();
            }
        }
        mask
    }

    /// The color slots a draw buffer enum names in the draw framebuffer (existing ones only);
    /// `None` if the enum is not a buffer name there.
    pub fn draw_slots(&self, buffer: GLenum) -> Option<Vec<ColorSlot>> {
        if self.fbo.draw == 0 {
            return super::buffers::slots_of(&self.config.visual, buffer);
        }
        let object = &self.fbo.framebuffers[&self.fbo.draw];
        Some(match attachment_slot(buffer)? {
            Some(ColorSlot::Attachment(i)) if object.attachments[i as usize].is_some() => {
                vec![ColorSlot::Attachment(i)]
            }
            _ => vec![],
        })
    }

    /// The slot the read buffer enum selects in the read framebuffer.
    pub fn read_slot_of(&self, buffer: GLenum) -> Option<ColorSlot> {
        if self.fbo.read == 0 {
            return super::buffers::read_slot(&self.config.visual, buffer);
        }
        let object = &self.fbo.framebuffers[&self.fbo.read];
        match attachment_slot(buffer)? {
            Some(ColorSlot::Attachment(i)) if object.attachments[i as usize].is_some() => {
                Some(ColorSlot::Attachment(i))
            }
            _ => None,
        }
    }

    /// The size and shape of the draw (`draw`) or read framebuffer, without assembling an
    /// object's images; `None` without a drawable or for an incomplete object.
    pub fn framebuffer_shape(&self, draw: bool) -> Option<(usize, usize, FramebufferConfig)> {
        let name = if draw { self.fbo.draw } else { self.fbo.read };
        if name == 0 {
            return self.window_shape(!draw);
        }
        if self.framebuffer_status(name) != GL_FRAMEBUFFER_COMPLETE {
            return None;
        }
        let object = self.fbo.framebuffers.get(name)?;
        let first = object.attachments.iter().flatten().next().copied();
        let info = self.image_info(first).flatten()?;
        let config = if draw { self.draw_config() } else { self.read_config() };
        Some((info.width, info.height, config))
    }

    /// Samples per pixel of the read framebuffer (1: single-sampled).
    pub fn read_samples(&self) -> usize {
        self.samples_of(self.fbo.read)
    }

    /// Samples per pixel of framebuffer object `name` (0: the window's) without assembling it.
    pub(super) fn samples_of(&self, name: u32) -> usize {
        if let (0, Some((_, samples))) = (name, self.window_pinned) {
            return samples;
        }
        if name == 0 {
            let window = self.drawable().map(|d| d.lock().unwrap_or_else(|p| p.into_inner()).framebuffer.samples());
            return window.unwrap_or(1);
        }
        let Some(object) = self.fbo.framebuffers.get(name) else { return 1 };
        let first = object.attachments.iter().flatten().next().copied();
        match self.image_info(first) {
            Some(Some(info)) => (info.samples as usize).max(1),
            _ => 1,
        }
    }

    /// Runs `f` on the draw framebuffer (an object's, assembled, or the window's).
    pub fn with_framebuffer<R>(&mut self, f: impl FnOnce(&mut Framebuffer) -> R) -> Option<R> {
        match self.fbo.draw {
            0 => self.draw_into_window_framebuffer(f),
            name => self.with_object_framebuffer(name, true, f),
        }
    }

    /// Runs `f` on the read framebuffer; what `f` changes is not kept for texture images.
    pub fn with_read_framebuffer<R>(&mut self, f: impl FnOnce(&mut Framebuffer) -> R) -> Option<R> {
        match self.fbo.read {
            0 => self.with_window_read_framebuffer(f),
            name => self.with_object_framebuffer(name, false, f),
        }
    }

    /// Assembles framebuffer object `name` from its attached images, runs `f` on it and
    /// puts the images back; `None` when the object is not complete or a layer of a 3D
    /// texture cannot be copied (out of memory). Renderbuffer storage and texture images are
    /// moved in and out (see the module documentation); only a layer of a 3D texture is
    /// copied, and written back when `write` is set.
    pub fn with_object_framebuffer<R>(
        &mut self,
        name: u32,
        write: bool,
        f: impl FnOnce(&mut Framebuffer) -> R,
    ) -> Option<R> {
        let (mut framebuffer, object, lent) = self.assemble_object_framebuffer(name)?;
        let result = f(&mut framebuffer);
        self.disassemble_object_framebuffer(framebuffer, &object, lent, write);
        Some(result)
    }

    /// The first half of [`Context::with_object_framebuffer`]: framebuffer object `name`
    /// assembled from its images, which [`Context::disassemble_object_framebuffer`] puts back.
    fn assemble_object_framebuffer(
        &mut self,
        name: u32,
    ) -> Option<(Framebuffer, FramebufferObject, Vec<Option<Lent>>)> {
        if self.framebuffer_status(name) != GL_FRAMEBUFFER_COMPLETE {
            return None;
        }
        let object = self.fbo.framebuffers.get(name)?.clone();
        // The color format draws compile for: that of the draw buffers (or the read buffer).
        let config = if name == self.fbo.draw { self.draw_config() } else { self.read_config() };
        let first = object.attachments.iter().flatten().next().copied();
        let info = self.image_info(first).flatten()?;
        let (width, height) = (info.width, info.height);
        let mut lent: Vec<Option<Lent>> = (0..POINTS).map(|_| None).collect();
        let mut colors = Vec::new();
        for (i, attachment) in object.attachments[..MAX_COLOR_ATTACHMENTS].iter().enumerate() {
            let Some(attachment) = *attachment else { continue };
            let buffer = match attachment {
                Attachment::Renderbuffer(rb) => match self.take_storage(rb) {
                    RenderbufferStorage::Color(b) => Some(b),
                    _ => None,
                },
                Attachment::Texture { .. } => self.lend_texture(attachment, width, height).and_then(|(texels, l)| {
                    let alpha = l.bits()[3] > 0;
                    match texels {
                        Texels::Rgba8(px) => {
                            lent[i] = Some(l);
                            let format = ColorFormat::Unorm8 { alpha };
                            Some(ColorBuffer::from_pixels(format, width, ColorPixels::Unorm8(px)))
                        }
                        other => {
                            self.give_back_texture(attachment, other, l, false);
                            None
                        }
                    }
                }),
            };
            match buffer {
                Some(b) => colors.push((ColorSlot::Attachment(i as u8), b)),
                None => {
                    self.return_layers(&object, colors, None, lent, false);
                    self.error(GL_OUT_OF_MEMORY);
                    return None;
                }
            }
        }
        let depth_stencil = match object.attachments[DEPTH].or(object.attachments[STENCIL]) {
            None => None,
            Some(Attachment::Renderbuffer(rb)) => match self.take_storage(rb) {
                RenderbufferStorage::DepthStencil(b) => Some(b),
                _ => None,
            },
            Some(texture) => {
                let buffer = self.lend_texture(texture, width, height).and_then(|(texels, l)| match texels {
                    Texels::Depth(buffer) => {
                        lent[DEPTH] = Some(l);
                        Some(buffer)
                    }
                    other => {
                        self.give_back_texture(texture, other, l, false);
                        None
                    }
                });
                if buffer.is_none() {
                    self.return_layers(&object, colors, None, lent, false);
                    self.error(GL_OUT_OF_MEMORY);
                    return None;
                }
                buffer
            }
        };
        let framebuffer = match info.samples {
            0 => Framebuffer::from_layers(config, width, height, colors, depth_stencil),
            n => Framebuffer::from_sample_layers(config, width, height, n as usize, colors, depth_stencil),
        };
        Some((framebuffer, object, lent))
    }

    /// Puts back the images of a framebuffer from [`Context::assemble_object_framebuffer`]
    /// (written back, for copied layers, when `write` is set).
    fn disassemble_object_framebuffer(
        &mut self,
        framebuffer: Framebuffer,
        object: &FramebufferObject,
        lent: Vec<Option<Lent>>,
        write: bool,
    ) {
        let (colors, depth_stencil) = framebuffer.into_layers();
        self.return_layers(object, colors, Some(depth_stencil), lent, write);
    }

    fn take_storage(&mut self, rb: u32) -> RenderbufferStorage {
        self.fbo.renderbuffers.get_mut(rb).map(|r| std::mem::take(&mut r.storage)).unwrap_or_default()
    }

    /// Puts the layers of an assembled framebuffer back where they came from (`lent` says
    /// how each texture image was lent): renderbuffer storage and whole texture images
    /// always (they were moved), copied 3D layers only after a `write`.
    fn return_layers(
        &mut self,
        object: &FramebufferObject,
        colors: Vec<(ColorSlot, ColorBuffer)>,
        depth_stencil: Option<DepthStencilBuffer>,
        mut lent: Vec<Option<Lent>>,
        write: bool,
    ) {
        for (slot, buffer) in colors {
            let ColorSlot::Attachment(i) = slot else { continue };
            match object.attachments[i as usize] {
                Some(Attachment::Renderbuffer(rb)) => {
                    if let Some(r) = self.fbo.renderbuffers.get_mut(rb) {
                        r.storage = RenderbufferStorage::Color(buffer);
                    }
                }
                Some(texture) => {
                    if let (Some(l), ColorPixels::Unorm8(px)) = (lent[i as usize].take(), buffer.into_pixels()) {
                        self.give_back_texture(texture, Texels::Rgba8(px), l, write);
                    }
                }
                None => {}
            }
        }
        let Some(depth_stencil) = depth_stencil else { return };
        match object.attachments[DEPTH].or(object.attachments[STENCIL]) {
            Some(Attachment::Renderbuffer(rb)) => {
                if let Some(r) = self.fbo.renderbuffers.get_mut(rb) {
                    r.storage = RenderbufferStorage::DepthStencil(depth_stencil);
                }
            }
            Some(texture) => {
                if let Some(l) = lent[DEPTH].take() {
                    self.give_back_texture(texture, Texels::Depth(depth_stencil), l, write);
                }
            }
            None => {}
        }
    }

    /// Lends the texels of an attached texture image to a `width` × `height` framebuffer.
    /// A whole image (every 1D and 2D image, a cube face) is taken out of the texture table
    /// and its texel vector moved; the table holds no image for the level until
    /// [`Context::give_back_texture`] (another context sharing the table then sees an
    /// incomplete texture rather than one being drawn). If something else still holds the
    /// image (a recorded draw of another context, or of the scene being rendered: GL's
    /// undefined feedback loop), the texels are cloned, so that holder keeps sampling what it
    /// recorded. A layer of a 3D image is copied.
    fn lend_texture(&self, attachment: Attachment, width: usize, height: usize) -> Option<(Texels, Lent)> {
        let Attachment::Texture { name, face, level, layer, .. } = attachment else { return None };
        let mut table = self.textures.lock();
        let lv = table.object_mut(name)?.faces.get_mut(face)?.get_mut(level)?.as_mut()?;
        let bits = lv.info.bits;
        let image = lv.image.as_ref()?;
        if (image.width, image.height, image.depth, image.border) == (width, height, 1, 0) {
            let (mut shell, shared) = match Arc::try_unwrap(lv.image.take()?) {
                Ok(image) => (image, None),
                Err(shared) => ((*shared).clone(), Some(shared)),
            };
            let texels = std::mem::replace(&mut shell.texels, Texels::Rgba8(Vec::new()));
            return Some((texels, Lent::Whole { shell, shared, bits }));
        }
        let area = width.checked_mul(height)?;
        let range = layer.checked_mul(area)?..(layer + 1).checked_mul(area)?;
        let texels = match &image.texels {
            Texels::Rgba8(t) => {
                let slice = t.get(range)?;
                let mut copy = Vec::new();
                copy.try_reserve_exact(area).ok()?;
                copy.extend_from_slice(slice);
                Texels::Rgba8(copy)
            }
            Texels::Depth(d) => {
                if d.len() < range.end {
                    return None;
                }
                let mut copy = depth_stencil_buffer(d.format(), width, height).ok()?;
                for (k, i) in range.enumerate() {
                    copy.set_depth_value(k, d.depth_value(i));
                    copy.set_stencil_value(k, d.stencil_value(i));
                }
                Texels::Depth(copy)
            }
        };
        Some((texels, Lent::Layer { bits }))
    }

    /// Gives back what [`Context::lend_texture`] lent, holding `texels` as the framebuffer
    /// left them. A whole image returns to the table (unless the level was specified anew
    /// meanwhile by another context sharing the table: then what was drawn is dropped); a
    /// copied layer is written back after a `write`. After a write, texels of a format of
    /// fewer than 8 bits per channel are quantized to its bits, as the texture store keeps
    /// every image of such formats (the one conversion left, a pass over the image that only
    /// those formats pay).
    fn give_back_texture(&mut self, attachment: Attachment, mut texels: Texels, lent: Lent, write: bool) {
        let Attachment::Texture { name, face, level, layer, .. } = attachment else { return };
        if write {
            if let Texels::Rgba8(px) = &mut texels {
                quantize_texels(px, lent.bits());
            }
        }
        match lent {
            Lent::Whole { mut shell, shared, .. } => {
                let image = match shared {
                    // Nothing was written: the image the table held goes back as it was.
                    Some(original) if !write => original,
                    _ => {
                        shell.texels = texels;
                        Arc::new(shell)
                    }
                };
                let mut table = self.textures.lock();
                let slot = table.object_mut(name).and_then(|o| o.faces.get_mut(face)?.get_mut(level)?.as_mut());
                if let Some(lv) = slot {
                    if lv.image.is_none() {
                        lv.image = Some(image);
                    }
                }
            }
            Lent::Layer { .. } if write => {
                self.with_texture_image_mut(attachment, |image| {
                    let area = image.width * image.height;
                    let range = layer * area..(layer + 1) * area;
                    match (&mut image.texels, &texels) {
                        (Texels::Rgba8(t), Texels::Rgba8(px)) => {
                            if let Some(slice) = t.get_mut(range) {
                                slice.copy_from_slice(&px[..area.min(px.len())]);
                            }
                        }
                        (Texels::Depth(d), Texels::Depth(copy)) if d.len() >= range.end && copy.len() >= area => {
                            for (k, i) in range.enumerate() {
                                d.set_depth_value(i, copy.depth_value(k));
                                d.set_stencil_value(i, copy.stencil_value(k));
                            }
                        }
                        _ => {}
                    }
                });
            }
            Lent::Layer { .. } => {}
        }
    }

    /// Runs `f` on the texture image level an attachment names, for writing (copy on
    /// write); the shared texture table is locked meanwhile.
    fn with_texture_image_mut<R>(&mut self, attachment: Attachment, f: impl FnOnce(&mut TexImage) -> R) -> Option<R> {
        let Attachment::Texture { name, face, level, .. } = attachment else { return None };
        let mut table = self.textures.lock();
        let level = table.object_mut(name)?.faces.get_mut(face)?.get_mut(level)?.as_mut()?;
        level.image.as_mut().map(Arc::make_mut).map(f)
    }

    // ---- Blits --------------------------------------------------------------------------

    /// glBlitFramebuffer.
    #[allow(clippy::too_many_arguments)]
    pub fn blit_framebuffer(&mut self, src: [i32; 4], dst: [i32; 4], mask: u32, filter: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        let known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
        if mask & !known != 0 {
            return self.error(GL_INVALID_VALUE);
        }
        if filter != GL_NEAREST && filter != GL_LINEAR {
            return self.error(GL_INVALID_ENUM);
        }
        let depth_stencil_bits = GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
        if filter == GL_LINEAR && mask & depth_stencil_bits != 0 {
            return self.error(GL_INVALID_OPERATION);
        }
        if !self.check_framebuffer_complete(true) || !self.check_framebuffer_complete(false) {
            return;
        }
        let (read, draw) = (self.read_config(), self.draw_config());
        let (rds, dds) = (read.depth_stencil, draw.depth_stencil);
        // Depth/stencil blits need the same format in both (when both have the buffer): the
        // same bits and the same type, so float and fixed-point depth do not blit into each
        // other (GL_INVALID_OPERATION, as Mesa checks the formats' datatypes too).
        let differ = rds.depth_bits() != dds.depth_bits()
            || rds.stencil_bits() != dds.stencil_bits()
            || rds.is_float_depth() != dds.is_float_depth();
        let depth_mismatch = mask & GL_DEPTH_BUFFER_BIT != 0 && rds.depth_bits() > 0 && dds.depth_bits() > 0 && differ;
        let stencil_mismatch =
            mask & GL_STENCIL_BUFFER_BIT != 0 && rds.stencil_bits() > 0 && dds.stencil_bits() > 0 && differ;
        if depth_mismatch || stencil_mismatch {
            return self.error(GL_INVALID_OPERATION);
        }
        // Multisampled framebuffers: a multisampled read framebuffer is resolved into the
        // draw one, which must then be single-sampled, with rectangles of the same size and
        // (for color) the same format (ARB_framebuffer_object, glBlitFramebuffer).
        let (read_samples, draw_samples) = (self.read_samples(), self.framebuffer_samples());
        let size = |r: [i32; 4]| (i64::from(r[2]) - i64::from(r[0]), i64::from(r[3]) - i64::from(r[1]));
        let same_size = size(src) == size(dst);
        let same_color = read.color == draw.color;
        if draw_samples > 1 || (read_samples > 1 && (!same_size || (mask & GL_COLOR_BUFFER_BIT != 0 && !same_color))) {
            return self.error(GL_INVALID_OPERATION);
        }
        if mask == 0 {
            return;
        }
        // Rendering recorded so far completes first (both framebuffers may be involved).
        self.flush_rendering();
        let read_slot = self.current_read_slot();
        let want =
            (mask & GL_COLOR_BUFFER_BIT != 0, mask & GL_DEPTH_BUFFER_BIT != 0, mask & GL_STENCIL_BUFFER_BIT != 0);
        let x = BlitAxis { src0: src[0], src1: src[2], dst0: dst[0], dst1: dst[2] };
        let y = BlitAxis { src0: src[1], src1: src[3], dst0: dst[1], dst1: dst[3] };
        if x.src0 == x.src1 || y.src0 == y.src1 || x.dst0 == x.dst1 || y.dst0 == y.dst1 {
            return;
        }
        let job = BlitJob {
            targets: self.draw_targets().into_iter().map(|(s, _)| s).collect(),
            read_slot,
            want,
            x,
            y,
            linear: filter == GL_LINEAR,
            scissor: self.state.scissor.clone(),
        };
        let (read_name, draw_name) = (self.fbo.read, self.fbo.draw);
        // A read framebuffer apart from the draw one is read where it lives (a multisampled
        // one resolved as it is read) while the draw framebuffer is written: no copy.
        if read_name != 0 && read_name != draw_name && !self.share_an_image(read_name, draw_name) {
            let Some((read_fb, object, lent)) = self.assemble_object_framebuffer(read_name) else { return };
            let _ = self.with_framebuffer(|fb| job.run(fb, &blit_sources_in_place(&read_fb, job.read_slot, want)));
            self.disassemble_object_framebuffer(read_fb, &object, lent, false);
            return;
        }
        if read_name == 0 && draw_name != 0 {
            if let Some(drawable) = self.read_drawable.clone().or_else(|| self.drawable.clone()) {
                let mut guard = drawable.lock().unwrap_or_else(|p| p.into_inner());
                let read_fb = &*guard.framebuffer_to_read();
                let _ = self.with_framebuffer(|fb| job.run(fb, &blit_sources_in_place(read_fb, job.read_slot, want)));
            }
            return;
        }
        // One framebuffer read and written (or two window drawables): a copy of the source
        // rectangle, which the blit may overwrite, in the buffers' own format.
        let sources = self.with_read_framebuffer(|fb| {
            let area = blit::source_area(x, y, fb.bounds());
            blit_sources_snapshot(fb, read_slot, want, area)
        });
        let Some(sources) = sources else { return };
        let Ok(sources) = sources else {
            return self.error(GL_OUT_OF_MEMORY);
        };
        let _ = self.with_framebuffer(|fb| job.run(fb, &sources));
    }

    /// Whether framebuffer objects `a` and `b` have an image (a renderbuffer or any image of
    /// a texture) attached to both (never for the window's, 0).
    fn share_an_image(&self, a: u32, b: u32) -> bool {
        let (Some(a), Some(b)) = (self.fbo.framebuffers.get(a), self.fbo.framebuffers.get(b)) else { return false };
        let same = |p: &Attachment, q: &Attachment| match (p, q) {
            (Attachment::Renderbuffer(p), Attachment::Renderbuffer(q)) => p == q,
            (Attachment::Texture { name: p, .. }, Attachment::Texture { name: q, .. }) => p == q,
            _ => false,
        };
        a.attachments.iter().flatten().any(|p| b.attachments.iter().flatten().any(|q| same(p, q)))
    }
}

/// A validated glBlitFramebuffer, ready to run on the draw framebuffer.
struct BlitJob {
    targets: Vec<ColorSlot>,
    read_slot: Option<ColorSlot>,
    /// Color, depth, stencil.
    want: (bool, bool, bool),
    x: BlitAxis,
    y: BlitAxis,
    linear: bool,
    scissor: ScissorState,
}

/// What a blit reads: color and depth/stencil, each when asked for and present.
type BlitSources<'a> = (Option<ColorSource<'a>>, Option<DepthStencilSource<'a>>);

impl BlitJob {
    /// Blits `sources` into the draw framebuffer `fb`.
    fn run(&self, fb: &mut Framebuffer, (color, depth_stencil): &BlitSources) {
        let (x, y) = (self.x, self.y);
        let rect = blit::destination(x, y, self.scissor.clip(fb.bounds()));
        if rect.is_empty() {
            return;
        }
        if let Some(color) = color {
            for slot in &self.targets {
                if let Some(buffer) = fb.color_mut(*slot) {
                    blit::blit_color(color, buffer, x, y, rect, self.linear);
                }
            }
        }
        if let Some(source) = depth_stencil {
            let width = fb.width();
            let (_, depth, stencil) = self.want;
            blit::blit_depth_stencil(source, fb.depth_stencil_mut(), width, x, y, rect, (depth, stencil));
        }
    }
}

/// The color (from `slot`) and depth/stencil buffers of `read` a blit reads, `want`ed as
/// (color, depth, stencil), read in place.
fn blit_sources_in_place<'a>(
    read: &'a Framebuffer,
    slot: Option<ColorSlot>,
    want: (bool, bool, bool),
) -> BlitSources<'a> {
    let (w, h) = (read.width(), read.height());
    let color = match slot.filter(|_| want.0) {
        None => None,
        Some(slot) => match read.color_samples(slot) {
            Some((samples, count)) => Some(ColorSource::in_place(samples, count, w, h)),
            None => read.color(slot).map(|b| ColorSource::in_place(b, 1, w, h)),
        },
    };
    let depth_stencil = (want.1 || want.2).then(|| match read.depth_stencil_samples() {
        Some((samples, count)) => DepthStencilSource::in_place(samples, count, w, h),
        None => DepthStencilSource::in_place(read.depth_stencil(), 1, w, h),
    });
    (color, depth_stencil)
}

/// As [`blit_sources_in_place`], copying the pixels of `area` (a multisampled color buffer
/// resolved).
fn blit_sources_snapshot(
    read: &Framebuffer,
    slot: Option<ColorSlot>,
    want: (bool, bool, bool),
    area: Rect,
) -> Result<BlitSources<'static>, OutOfMemory> {
    let (w, h) = (read.width(), read.height());
    let color = match slot.filter(|_| want.0) {
        None => None,
        Some(slot) => match read.color_samples(slot) {
            Some((samples, count)) => Some(ColorSource::snapshot(samples, count, w, h, area)?),
            None => read.color(slot).map(|b| ColorSource::snapshot(b, 1, w, h, area)).transpose()?,
        },
    };
    let depth_stencil = match (want.1 || want.2, read.depth_stencil_samples()) {
        (false, _) => None,
        (true, Some((samples, count))) => Some(DepthStencilSource::snapshot(samples, count, w, h, area)?),
        (true, None) => Some(DepthStencilSource::snapshot(read.depth_stencil(), 1, w, h, area)?),
    };
    Ok((color, depth_stencil))
}

/// The (target index, face) of a glFramebufferTexture{dims}D texture target.
fn tex_target_of(dims: usize, target: GLenum) -> Option<(usize, usize)> {
    match (dims, target) {
        (1, GL_TEXTURE_1D) => Some((0, 0)),
        (2, GL_TEXTURE_2D) => Some((1, 0)),
        (2, GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) => {
            Some((3, (target - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize))
        }
        (3, GL_TEXTURE_3D) => Some((2, 0)),
        _ => None,
    }
}

/// Bits of red, green, blue, alpha, depth, stencil of a renderable format.
fn renderable_sizes(format: Renderable) -> [i32; 6] {
    match format {
        Renderable::Color(f) => {
            let [r, g, b, a] = f.channel_bits().map(|b| b as i32);
            [r, g, b, a, 0, 0]
        }
        Renderable::DepthStencil(f) => [0, 0, 0, 0, f.depth_bits() as i32, f.stencil_bits() as i32],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(format: Renderable, size: usize) -> Option<Option<ImageInfo>> {
        Some(Some(ImageInfo { width: size, height: size, format, samples: 0, supported: true }))
    }

    const RGBA8: Renderable = Renderable::Color(ColorFormat::Unorm8 { alpha: true });
    const D24S8: Renderable = Renderable::DepthStencil(DepthStencilFormat::Packed24 { depth: true, stencil: true });
    const S8: Renderable = Renderable::DepthStencil(DepthStencilFormat::Packed24 { depth: false, stencil: true });

    fn status(images: [Option<Option<ImageInfo>>; POINTS], attachments: [Option<Attachment>; POINTS]) -> GLenum {
        let mut draw = [GL_NONE; MAX_DRAW_BUFFERS];
        draw[0] = GL_COLOR_ATTACHMENT0;
        completeness(&images, &attachments, &draw, GL_COLOR_ATTACHMENT0)
    }

    fn rb(n: u32) -> Option<Attachment> {
        Some(Attachment::Renderbuffer(n))
    }

    #[test]
    fn completeness_follows_the_rules_in_order() {
        let none: [Option<Option<ImageInfo>>; POINTS] = Default::default();
        assert_eq!(status(none, [None; POINTS]), GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT);

        let mut images = none;
        let mut att = [None; POINTS];
        images[0] = image(RGBA8, 4);
        att[0] = rb(1);
        assert_eq!(status(images, att), GL_FRAMEBUFFER_COMPLETE);

        // A color format at the depth point; an image without storage; a zero-size image.
        let mut bad = images;
        bad[DEPTH] = image(RGBA8, 4);
        assert_eq!(status(bad, att), GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
        bad[DEPTH] = Some(None);
        assert_eq!(status(bad, att), GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
        bad[DEPTH] = image(D24S8, 0);
        assert_eq!(status(bad, att), GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
        // Stencil-only at the depth point.
        bad[DEPTH] = image(S8, 4);
        assert_eq!(status(bad, att), GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT);

        // Draw buffer 0 names an empty point.
        let mut only_depth = none;
        only_depth[DEPTH] = image(D24S8, 4);
        let mut att_d = [None; POINTS];
        att_d[DEPTH] = rb(2);
        assert_eq!(status(only_depth, att_d), GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER);
        let no_buffers = [GL_NONE; MAX_DRAW_BUFFERS];
        assert_eq!(
            completeness(&only_depth, &att_d, &no_buffers, GL_COLOR_ATTACHMENT0),
            GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER
        );
        assert_eq!(completeness(&only_depth, &att_d, &no_buffers, GL_NONE), GL_FRAMEBUFFER_COMPLETE);
    }

    #[test]
    fn unsupported_combinations() {
        let mut images: [Option<Option<ImageInfo>>; POINTS] = Default::default();
        let mut att = [None; POINTS];
        images[0] = image(RGBA8, 4);
        att[0] = rb(1);
        // Sizes differ.
        images[1] = image(RGBA8, 8);
        att[1] = rb(2);
        assert_eq!(status(images, att), GL_FRAMEBUFFER_UNSUPPORTED);
        // One renderbuffer at two color points.
        images[1] = image(RGBA8, 4);
        att[1] = rb(1);
        assert_eq!(status(images, att), GL_FRAMEBUFFER_UNSUPPORTED);
        att[1] = rb(2);
        assert_eq!(status(images, att), GL_FRAMEBUFFER_COMPLETE);
        // Depth and stencil from different renderbuffers, or from one.
        images[DEPTH] = image(D24S8, 4);
        images[STENCIL] = image(D24S8, 4);
        att[DEPTH] = rb(3);
        att[STENCIL] = rb(4);
        assert_eq!(status(images, att), GL_FRAMEBUFFER_UNSUPPORTED);
        att[STENCIL] = rb(3);
        assert_eq!(status(images, att), GL_FRAMEBUFFER_COMPLETE);
        // Sample counts differ.
        images[1] = Some(Some(ImageInfo { samples: 4, ..images[0].unwrap().unwrap() }));
        assert_eq!(status(images, att), GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE);
    }

    fn context() -> Context {
        let visual = FramebufferConfig::single_buffered(
            ColorFormat::Unorm8 { alpha: true },
            DepthStencilFormat::Packed24 { depth: true, stencil: true },
            0,
        );
        Context::with_test_drawable(visual, 4, 4).0
    }

    #[test]
    fn each_framebuffer_keeps_its_draw_and_read_buffers() {
        let mut ctx = context();
        let fb = ctx.gen_fbo_names(1, false).unwrap()[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        assert_eq!(ctx.state.color.draw_buffers[0], GL_COLOR_ATTACHMENT0);
        ctx.draw_buffers(&[GL_COLOR_ATTACHMENT2, GL_NONE, GL_COLOR_ATTACHMENT5]);
        ctx.read_buffer(GL_COLOR_ATTACHMENT7);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        // No image attached at all.
        assert_eq!(ctx.check_framebuffer_status(GL_FRAMEBUFFER), GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT);
        ctx.bind_framebuffer(GL_FRAMEBUFFER, 0);
        assert_eq!(ctx.state.color.draw_buffers[0], GL_FRONT);
        assert_eq!(ctx.state.pixel_mode.read_buffer, GL_FRONT);
        ctx.bind_framebuffer(GL_DRAW_FRAMEBUFFER, fb);
        assert_eq!(ctx.state.color.draw_buffers[..3], [GL_COLOR_ATTACHMENT2, GL_NONE, GL_COLOR_ATTACHMENT5]);
        assert_eq!(ctx.state.pixel_mode.read_buffer, GL_FRONT, "the read binding did not change");
        ctx.bind_framebuffer(GL_READ_FRAMEBUFFER, fb);
        assert_eq!(ctx.state.pixel_mode.read_buffer, GL_COLOR_ATTACHMENT7);

        // A color renderbuffer at attachment 2 only: draw buffer 2 (COLOR_ATTACHMENT5) and the
        // read buffer are incomplete in turn.
        let rb = ctx.gen_fbo_names(1, true).unwrap()[0];
        ctx.bind_renderbuffer(GL_RENDERBUFFER, rb);
        ctx.renderbuffer_storage(GL_RENDERBUFFER, 0, GL_RGBA8, 4, 4);
        ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_RENDERBUFFER, rb);
        assert_eq!(ctx.check_framebuffer_status(GL_DRAW_FRAMEBUFFER), GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER);
        ctx.draw_buffers(&[GL_COLOR_ATTACHMENT2]);
        assert_eq!(ctx.check_framebuffer_status(GL_DRAW_FRAMEBUFFER), GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER);
        ctx.read_buffer(GL_COLOR_ATTACHMENT2);
        assert_eq!(ctx.check_framebuffer_status(GL_FRAMEBUFFER), GL_FRAMEBUFFER_COMPLETE);
        assert_eq!(ctx.draw_config().accum_bits, 0);
        assert_eq!(ctx.draw_config().depth_stencil, DepthStencilFormat::None);

        // A clear reaches the renderbuffer and nothing else.
        ctx.state.color.clear_color = [1.0, 0.5, 0.0, 1.0];
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.flush_rendering();
        let read = ctx.with_read_framebuffer(|fb| {
            let mut row = Vec::new();
            fb.color(ColorSlot::Attachment(2)).unwrap().read_row_f32(3, 0, 1, &mut row);
            row[0]
        });
        assert_eq!(read, Some([1.0, 128.0 / 255.0, 0.0, 1.0]));

        // Deleting the bound object binds the window's framebuffer and its buffers again.
        ctx.delete_framebuffers(1, &[fb]);
        assert_eq!((ctx.fbo.draw, ctx.fbo.read), (0, 0));
        assert_eq!(ctx.state.color.draw_buffers[0], GL_FRONT);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    /// A texture image of `internal_format` (4 × 4) attached at `attachment` of a new bound
    /// framebuffer object; the texture's name.
    fn attached_texture(ctx: &mut Context, internal_format: GLenum, attachment: GLenum) -> u32 {
        let tex = ctx.gen_textures(1).unwrap()[0];
        ctx.bind_texture(GL_TEXTURE_2D, tex);
        let (format, ty) = if attachment == GL_COLOR_ATTACHMENT0 {
            (GL_RGBA, GL_UNSIGNED_BYTE)
        } else {
            (GL_DEPTH_COMPONENT, GL_FLOAT)
        };
        let args = super::super::texture::ImageArgs {
            target: GL_TEXTURE_2D,
            level: 0,
            internal_format: internal_format as i32,
            width: 4,
            height: 4,
            depth: 1,
            border: 0,
        };
        ctx.tex_image(2, args, format, ty, |_| Ok(None));
        ctx.framebuffer_texture(2, GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, tex, 0, 0);
        tex
    }

    /// The level 0 image of texture `name`.
    fn level0(ctx: &Context, name: u32) -> Arc<TexImage> {
        ctx.textures.lock().object(name).unwrap().level(0, 0).unwrap().image.clone().unwrap()
    }

    /// Where the texels of an image are: the same address after rendering means rendered in
    /// place.
    fn texel_address(image: &TexImage) -> usize {
        match &image.texels {
            Texels::Rgba8(t) => t.as_ptr() as usize,
            Texels::Depth(d) => match d.pixels() {
                crate::framebuffer::surface::DepthStencilPixels::Packed24(px) => px.as_ptr() as usize,
                _ => 0,
            },
        }
    }

    #[test]
    fn attached_texture_images_are_rendered_in_place() {
        let mut ctx = context();
        let fb = ctx.gen_fbo_names(1, false).unwrap()[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        let color = attached_texture(&mut ctx, GL_RGBA8, GL_COLOR_ATTACHMENT0);
        let depth = attached_texture(&mut ctx, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL_ATTACHMENT);
        assert_eq!(ctx.check_framebuffer_status(GL_FRAMEBUFFER), GL_FRAMEBUFFER_COMPLETE);
        let addresses = |ctx: &Context| (texel_address(&level0(ctx, color)), texel_address(&level0(ctx, depth)));
        let before = addresses(&ctx);
        ctx.state.color.clear_color = [1.0, 0.5, 0.0, 1.0];
        ctx.state.depth.clear = 0.25;
        ctx.state.stencil.clear = 7;
        ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        ctx.flush_rendering();
        let _ = ctx.with_read_framebuffer(|_| ());
        assert_eq!(addresses(&ctx), before, "drawing and reading moved the texels, copying none");
        // The framebuffer's layers are the texture's texel vectors themselves.
        let layers = ctx.with_framebuffer(|fb| {
            let ColorPixels::Unorm8(px) = fb.color(ColorSlot::Attachment(0)).unwrap().pixels() else { return (0, 0) };
            let crate::framebuffer::surface::DepthStencilPixels::Packed24(ds) = fb.depth_stencil().pixels() else {
                return (0, 0);
            };
            (px.as_ptr() as usize, ds.as_ptr() as usize)
        });
        assert_eq!(layers, Some(before));
        let (c, d) = (level0(&ctx, color), level0(&ctx, depth));
        assert_eq!(c.texels, Texels::Rgba8(vec![[255, 128, 0, 255]; 16]));
        assert_eq!((d.depth_f32(5), d.stencil(5)), (crate::pixel::convert::depth_to_float(0x40_0000, 24), 7));
        drop((c, d));

        // Something that still holds the image (a draw recorded in another context) keeps the
        // texels it holds; the table gets the drawn ones.
        let held = level0(&ctx, color);
        ctx.state.color.clear_color = [0.0, 0.0, 1.0, 1.0];
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.flush_rendering();
        assert_eq!(held.texels, Texels::Rgba8(vec![[255, 128, 0, 255]; 16]));
        assert_eq!(level0(&ctx, color).texels, Texels::Rgba8(vec![[0, 0, 255, 255]; 16]));
        // A read while the image is held gives the table its image back unchanged.
        let held = level0(&ctx, color);
        let _ = ctx.with_read_framebuffer(|_| ());
        assert!(Arc::ptr_eq(&held, &level0(&ctx, color)));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn rendered_texels_of_small_formats_are_quantized() {
        let mut ctx = context();
        let fb = ctx.gen_fbo_names(1, false).unwrap()[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        let tex = attached_texture(&mut ctx, GL_RGBA4, GL_COLOR_ATTACHMENT0);
        // 0.6 is 153 in 8 bits and 9 (0x99) in 4; 0.2 is 51 and 3 (0x33).
        ctx.state.color.clear_color = [0.6, 0.2, 1.0, 0.0];
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.flush_rendering();
        assert_eq!(level0(&ctx, tex).texels, Texels::Rgba8(vec![[0x99, 0x33, 0xff, 0]; 16]));
        ctx.state.color.clear_color = [0.5, 0.5, 0.5, 0.5];
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.flush_rendering();
        // 0.5 → 128 → 128/255 · 15 = 7.53 → 8 (0x88).
        assert_eq!(level0(&ctx, tex).texels, Texels::Rgba8(vec![[0x88; 4]; 16]));
        let mut texels = vec![[0u8, 17, 128, 255]];
        quantize_texels(&mut texels, [8, 4, 1, 0]);
        assert_eq!(texels, vec![[0, 17, 255, 255]]);
    }

    #[test]
    fn a_layer_of_a_3d_texture_is_copied_in_and_out() {
        let mut ctx = context();
        let fb = ctx.gen_fbo_names(1, false).unwrap()[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        let tex = ctx.gen_textures(1).unwrap()[0];
        ctx.bind_texture(GL_TEXTURE_3D, tex);
        let args = super::super::texture::ImageArgs {
            target: GL_TEXTURE_3D,
            level: 0,
            internal_format: GL_RGBA8 as i32,
            width: 2,
            height: 2,
            depth: 3,
            border: 0,
        };
        ctx.tex_image(3, args, GL_RGBA, GL_UNSIGNED_BYTE, |_| Ok(None));
        ctx.framebuffer_texture(3, GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, tex, 0, 1);
        assert_eq!(ctx.check_framebuffer_status(GL_FRAMEBUFFER), GL_FRAMEBUFFER_COMPLETE);
        ctx.state.color.clear_color = [1.0, 1.0, 1.0, 1.0];
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.flush_rendering();
        let mut expected = vec![[0u8; 4]; 12];
        expected[4..8].fill([255; 4]);
        assert_eq!(level0(&ctx, tex).texels, Texels::Rgba8(expected));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn renderbuffer_formats_store_what_they_name() {
        assert_eq!(renderbuffer_format(GL_RGBA8), Some(RGBA8));
        assert_eq!(renderbuffer_format(GL_DEPTH24_STENCIL8), Some(D24S8));
        assert_eq!(renderbuffer_format(GL_STENCIL_INDEX8), Some(S8));
        assert_eq!(renderbuffer_format(GL_RGBA16F).map(renderable_sizes), Some([32, 32, 32, 32, 0, 0]),);
        assert_eq!(renderbuffer_format(GL_DEPTH_COMPONENT16).map(renderable_sizes), Some([0, 0, 0, 0, 16, 0]));
        assert!(renderbuffer_format(GL_LUMINANCE8).is_some() && !renderbuffer_supported(GL_LUMINANCE8));
        assert!(renderbuffer_supported(GL_RGBA8) && renderbuffer_supported(GL_DEPTH24_STENCIL8));
        assert_eq!(renderbuffer_format(GL_COLOR_INDEX), None);
    }
}
