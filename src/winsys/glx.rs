//! GLX on Xlib: contexts that render into X windows, pixmaps and pbuffers.
//!
//! tessera does not speak the GLX protocol. Like Mesa's Xlib driver, it keeps every buffer of a
//! drawable (front/back, left/right, depth, stencil, accumulation) in its own memory and shows
//! the front buffer with XPutImage, through the application's own `Display*`: at
//! glXSwapBuffers (after copying the back buffer to the front one) and at glFlush/glFinish.
//! Reads of the front buffer therefore return exactly what was drawn there. The window's size
//! is queried at glXMakeCurrent and glXSwapBuffers and the buffers follow it.
//!
//! Xlib is loaded at run time (`super::libx11`), the first time a GLX function needs it, so that
//! programs using only OSMesa need no X libraries.
//!
//! Handles given to C (GLXContext, GLXFBConfig) are identifiers looked up in registries here,
//! never dereferenced by tessera, so a stale or forged handle is refused instead of crashing.
// XIDs and visual ids are C `unsigned long`, kept as u64 inside: the casts are no-ops only
// where `unsigned long` is 64 bits.
#![allow(clippy::unnecessary_cast)]
use super::glx_config::{configs_for, FbConfig, VisualDesc};
use super::libx11::Xlib;
use super::xshm::ShmImage;
use crate::context::current::{self, SharedContext};
use crate::context::{Context, ContextConfig};
use crate::framebuffer::surface::ColorPixels;
use crate::framebuffer::{ColorSlot, Drawable, Framebuffer, Present};
use std::cell::RefCell;
use std::collections::HashMap;
use std::ffi::{c_int, c_uint, c_ulong};
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};
use x11_dl::xlib;

/// Xlib, loaded once; `None` when libX11.so.6 is missing.
pub fn xlib() -> Option<&'static Xlib> {
    static XLIB: OnceLock<Option<Xlib>> = OnceLock::new();
    XLIB.get_or_init(Xlib::open).as_ref()
}

/// A `Display*` of the application, kept as an address (only passed back to Xlib).
pub type DisplayAddr = usize;

fn dpy(display: DisplayAddr) -> *mut xlib::Display {
    display as *mut xlib::Display
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

// ---------------------------------------------------------------------------------------------
// Configurations
// ---------------------------------------------------------------------------------------------

/// The configurations of one display (every screen), leaked so that the addresses handed to C
/// as GLXFBConfig stay valid for the life of the process (a few dozen per display).
struct DisplayConfigs {
    configs: &'static [FbConfig],
    /// Every visual of every screen, for visuals equivalent to one with configurations.
    visuals: Vec<VisualDesc>,
}

fn display_configs() -> MutexGuard<'static, HashMap<DisplayAddr, DisplayConfigs>> {
    static CONFIGS: OnceLock<Mutex<HashMap<DisplayAddr, DisplayConfigs>>> = OnceLock::new();
    lock(CONFIGS.get_or_init(|| Mutex::new(HashMap::new())))
}

/// The visuals of every screen of `display`.
fn query_visuals(x: &Xlib, display: DisplayAddr) -> Vec<VisualDesc> {
    let mut visuals = Vec::new();
    // SAFETY: `display` is the application's open Display (GLX contract).
    let screens = unsafe { (x.XScreenCount)(dpy(display)) };
    for screen in 0..screens {
        // SAFETY: XVisualInfo is plain data; a zeroed template with only the screen set is valid.
        let mut template: xlib::XVisualInfo = unsafe { std::mem::zeroed() };
        template.screen = screen;
        let mut count: c_int = 0;
        // SAFETY: valid display, template and count pointers; the result is freed below.
        let list = unsafe { (x.XGetVisualInfo)(dpy(display), xlib::VisualScreenMask, &mut template, &mut count) };
        if list.is_null() {
            continue;
        }
        // SAFETY: Xlib returned `count` entries at `list`.
        let infos = unsafe { std::slice::from_raw_parts(list, count.max(0) as usize) };
        for info in infos {
            visuals.push(VisualDesc {
                screen,
                visual_id: info.visualid as u64,
                class: info.class,
                depth: info.depth,
                masks: [info.red_mask as u64, info.green_mask as u64, info.blue_mask as u64],
            });
        }
        // SAFETY: `list` was allocated by Xlib.
        unsafe { (x.XFree)(list.cast()) };
    }
    visuals
}

/// Every configuration of `display`.
pub fn configs(display: DisplayAddr) -> &'static [FbConfig] {
    if display == 0 {
        return &[];
    }
    let Some(x) = xlib() else {
        return &[];
    };
    // The first GLX call on a display: Xlib learns the GLX error names (outside the
    // registry's lock, since XInitExtension takes the display's).
    super::glx_error::register_error_names(display);
    let mut all = display_configs();
    all.entry(display)
        .or_insert_with(|| {
            let visuals = query_visuals(x, display);
            DisplayConfigs { configs: Box::leak(configs_for(&visuals).into_boxed_slice()), visuals }
        })
        .configs
}

/// The configuration behind a GLXFBConfig handle (its address), if it is one of ours.
pub fn config_from_handle(handle: usize) -> Option<&'static FbConfig> {
    let all = display_configs();
    all.values().flat_map(|d| d.configs.iter()).find(|c| *c as *const FbConfig as usize == handle)
}

/// The handle given to C for a configuration.
pub fn config_handle(config: &'static FbConfig) -> usize {
    config as *const FbConfig as usize
}

/// Which configuration each visual stands for: the last one chosen for it by glXChooseVisual
/// or glXGetVisualFromFBConfig (several configurations share one X visual).
fn visual_choices() -> MutexGuard<'static, HashMap<(DisplayAddr, u64), &'static FbConfig>> {
    static CHOICES: OnceLock<Mutex<HashMap<(DisplayAddr, u64), &'static FbConfig>>> = OnceLock::new();
    lock(CHOICES.get_or_init(|| Mutex::new(HashMap::new())))
}

/// Records that `config` was handed out as its X visual.
pub fn remember_visual(display: DisplayAddr, config: &'static FbConfig) {
    visual_choices().insert((display, config.visual.visual_id), config);
}

/// The configuration a visual stands for: the one chosen for it, else its most capable one.
pub fn config_for_visual(display: DisplayAddr, visual_id: u64) -> Option<&'static FbConfig> {
    if let Some(c) = visual_choices().get(&(display, visual_id)) {
        return Some(c);
    }
    let all = configs(display);
    let visual = display_configs().get(&display)?.visuals.iter().find(|v| v.visual_id == visual_id).copied()?;
    let on_visual = || all.iter().filter(move |c| c.visual.equivalent(&visual));
    on_visual().find(|c| c.is_default_for_visual()).or_else(|| on_visual().next())
}

/// The X visual of a configuration as a malloc'ed XVisualInfo (from XGetVisualInfo, so
/// XFree releases it); null on failure.
pub fn visual_info(display: DisplayAddr, config: &'static FbConfig) -> *mut xlib::XVisualInfo {
    let Some(x) = xlib() else {
        return std::ptr::null_mut();
    };
    // SAFETY: plain data template.
    let mut template: xlib::XVisualInfo = unsafe { std::mem::zeroed() };
    template.visualid = config.visual.visual_id as xlib::VisualID;
    template.screen = config.visual.screen;
    let mut count = 0;
    // SAFETY: valid display and pointers; the caller frees the result with XFree.
    let info = unsafe {
        (x.XGetVisualInfo)(dpy(display), xlib::VisualIDMask | xlib::VisualScreenMask, &mut template, &mut count)
    };
    if !info.is_null() {
        remember_visual(display, config);
    }
    info
}

// ---------------------------------------------------------------------------------------------
// Presentation
// ---------------------------------------------------------------------------------------------

/// Puts the front-left color buffer into an X window or pixmap with XPutImage.
struct XPresenter {
    display: DisplayAddr,
    target: u64,
    /// The GC, created at the first presentation (0 until then).
    gc: usize,
    visual: usize,
    depth: i32,
    masks: [u64; 3],
    /// The XImage data, reused between presentations (XPutImage path).
    bytes: Vec<u8>,
    /// The MIT-SHM image of the current size, while the server accepts it.
    shm: Option<ShmImage>,
    shm_refused: bool,
}

impl XPresenter {
    fn new(display: DisplayAddr, target: u64, kind: DrawableKind, config: &FbConfig) -> Option<XPresenter> {
        let x = xlib()?;
        if kind == DrawableKind::Window {
            // A window's own visual, which may be any visual equivalent to the config's.
            // SAFETY: plain data filled by XGetWindowAttributes.
            let mut attributes: xlib::XWindowAttributes = unsafe { std::mem::zeroed() };
            // SAFETY: valid display and out-pointer.
            let ok = unsafe { (x.XGetWindowAttributes)(dpy(display), target as c_ulong, &mut attributes) };
            if ok != 0 && !attributes.visual.is_null() {
                // SAFETY: Xlib's Visual of a live window.
                let v = unsafe { &*attributes.visual };
                return Some(XPresenter {
                    display,
                    target,
                    gc: 0,
                    visual: attributes.visual as usize,
                    depth: attributes.depth,
                    masks: [v.red_mask as u64, v.green_mask as u64, v.blue_mask as u64],
                    bytes: Vec::new(),
                    shm: None,
                    shm_refused: false,
                });
            }
        }
        // SAFETY: plain data template.
        let mut template: xlib::XVisualInfo = unsafe { std::mem::zeroed() };
        template.visualid = config.visual.visual_id as xlib::VisualID;
        template.screen = config.visual.screen;
        let mut count = 0;
        // SAFETY: valid display and pointers; freed below.
        let info = unsafe {
            (x.XGetVisualInfo)(dpy(display), xlib::VisualIDMask | xlib::VisualScreenMask, &mut template, &mut count)
        };
        if info.is_null() {
            return None;
        }
        // SAFETY: non-null result of XGetVisualInfo with at least one entry.
        let visual = unsafe { (*info).visual } as usize;
        // SAFETY: allocated by Xlib.
        unsafe { (x.XFree)(info.cast()) };
        Some(XPresenter {
            display,
            target,
            gc: 0,
            visual,
            depth: config.visual.depth,
            masks: config.visual.masks,
            bytes: Vec::new(),
            shm: None,
            shm_refused: false,
        })
    }
}

/// Packs one RGBA8 pixel into an X pixel value of the visual's masks.
fn pack_pixel(p: [u8; 4], masks: &[u64; 3]) -> u32 {
    let mut value = 0u32;
    for (c, &mask) in masks.iter().enumerate() {
        let shift = mask.trailing_zeros();
        let bits = mask.count_ones();
        value |= ((p[c] as u32) >> (8 - bits.min(8))) << shift;
    }
    value
}

/// Writes `pixels` (GL rows, bottom-up) into an X image's bytes (top-down rows of
/// `bytes_per_line`), packing each pixel for `masks` in the image's byte order.
fn fill_image(
    out: &mut [u8],
    layout: (usize, i32, i32),
    pixels: &[[u8; 4]],
    width: usize,
    height: usize,
    masks: &[u64; 3],
) {
    let (bytes_per_line, bits_per_pixel, byte_order) = layout;
    let n = ((bits_per_pixel / 8).max(1) as usize).min(4);
    for y in 0..height {
        let src = &pixels[(height - 1 - y) * width..(height - y) * width];
        let row = &mut out[y * bytes_per_line..(y + 1) * bytes_per_line];
        for (dst, &p) in row.chunks_exact_mut(n).zip(src) {
            let value = pack_pixel(p, masks);
            if byte_order == xlib::MSBFirst {
                dst.copy_from_slice(&value.to_be_bytes()[4 - n..]);
            } else {
                dst.copy_from_slice(&value.to_le_bytes()[..n]);
            }
        }
    }
}

impl XPresenter {
    /// MIT-SHM presentation; false when the server does not take it (XPutImage then).
    fn present_shm(&mut self, x: &Xlib, pixels: &[[u8; 4]], width: usize, height: usize) -> bool {
        if self.shm_refused {
            return false;
        }
        let display = dpy(self.display);
        if self.shm.as_ref().map(|s| (s.width, s.height)) != Some((width, height)) {
            if let Some(mut old) = self.shm.take() {
                old.detach(display);
            }
            self.shm = ShmImage::new(x, display, self.visual as *mut xlib::Visual, self.depth, width, height);
            self.shm_refused = self.shm.is_none();
        }
        let Some(shm) = self.shm.as_mut() else {
            return false;
        };
        let (bytes_per_line, bits_per_pixel, byte_order) = shm.layout();
        fill_image(shm.bytes_mut(), (bytes_per_line, bits_per_pixel, byte_order), pixels, width, height, &self.masks);
        shm.put(x, display, self.target as c_ulong, self.gc as xlib::GC);
        true
    }

    /// Plain XPutImage presentation.
    fn present_put(&mut self, x: &Xlib, pixels: &[[u8; 4]], width: usize, height: usize) {
        let display = dpy(self.display);
        // SAFETY: XCreateImage only allocates the XImage header (no data: null) for the
        // display's format of this visual and depth.
        let image = unsafe {
            (x.XCreateImage)(
                display,
                self.visual as *mut xlib::Visual,
                self.depth as c_uint,
                xlib::ZPixmap,
                0,
                std::ptr::null_mut(),
                width as c_uint,
                height as c_uint,
                32,
                0,
            )
        };
        if image.is_null() {
            return;
        }
        // SAFETY: `image` is a valid XImage header just created.
        let (bytes_per_line, bits_per_pixel) =
            unsafe { ((*image).bytes_per_line.max(0) as usize, (*image).bits_per_pixel) };
        self.bytes.clear();
        self.bytes.resize(bytes_per_line * height, 0);
        fill_image(
            &mut self.bytes,
            (bytes_per_line, bits_per_pixel, xlib::LSBFirst),
            pixels,
            width,
            height,
            &self.masks,
        );
        // SAFETY: the data pointer lives in `self.bytes` (bytes_per_line × height bytes, the
        // layout XCreateImage computed) for the duration of XPutImage; it is detached before
        // the header is freed so that Xlib never frees our memory.
        unsafe {
            (*image).data = self.bytes.as_mut_ptr().cast();
            (*image).byte_order = xlib::LSBFirst;
            (x.XPutImage)(
                display,
                self.target as c_ulong,
                self.gc as xlib::GC,
                image,
                0,
                0,
                0,
                0,
                width as c_uint,
                height as c_uint,
            );
            (*image).data = std::ptr::null_mut();
            (x.XFree)(image.cast());
            (x.XFlush)(display);
        }
    }
}

impl Present for XPresenter {
    fn release(&mut self) {
        let Some(x) = xlib() else {
            return;
        };
        if let Some(mut shm) = self.shm.take() {
            shm.detach(dpy(self.display));
        }
        if self.gc != 0 {
            // SAFETY: the GC this presenter created on the (still open) display.
            unsafe { (x.XFreeGC)(dpy(self.display), self.gc as xlib::GC) };
            self.gc = 0;
        }
    }

    fn present(&mut self, framebuffer: &Framebuffer) {
        let Some(x) = xlib() else {
            return;
        };
        let Some(color) = framebuffer.color(ColorSlot::FrontLeft) else {
            return;
        };
        let ColorPixels::Unorm8(pixels) = color.pixels() else {
            return;
        };
        let (width, height) = (framebuffer.width(), framebuffer.height());
        if width == 0 || height == 0 {
            return;
        }
        if self.gc == 0 {
            // SAFETY: valid display and drawable; no GC values passed.
            self.gc =
                unsafe { (x.XCreateGC)(dpy(self.display), self.target as c_ulong, 0, std::ptr::null_mut()) } as usize;
        }
        if !self.present_shm(x, pixels, width, height) {
            self.present_put(x, pixels, width, height);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Drawables
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawableKind {
    /// An X window (through glXCreateWindow or used directly).
    Window,
    /// An X pixmap (glXCreatePixmap / glXCreateGLXPixmap).
    Pixmap,
    /// A pbuffer: tessera's buffers only; its XID is a 1×1 pixmap reserved for the name.
    Pbuffer,
}

/// A GLX drawable: an X drawable plus tessera's buffers for it.
pub struct GlxDrawable {
    pub display: DisplayAddr,
    pub xid: u64,
    pub kind: DrawableKind,
    /// Whether the application created it (glXCreateWindow, ...) rather than binding a plain
    /// window; an implicit drawable takes the configuration of the context bound to it.
    pub explicit: bool,
    pub config: Mutex<&'static FbConfig>,
    pub surface: Arc<Mutex<Drawable>>,
    /// glXSelectEvent's mask (GLX_PBUFFER_CLOBBER_MASK): kept for glXGetSelectedEvent; tessera's
    /// buffers are never clobbered, so no such event is ever sent.
    pub event_mask: std::sync::atomic::AtomicU64,
}

/// The GLX drawables by display and XID.
type DrawableTable = HashMap<(DisplayAddr, u64), Arc<GlxDrawable>>;

fn drawables() -> MutexGuard<'static, DrawableTable> {
    static DRAWABLES: OnceLock<Mutex<DrawableTable>> = OnceLock::new();
    lock(DRAWABLES.get_or_init(|| Mutex::new(HashMap::new())))
}

/// The size of an X drawable (XGetGeometry).
fn x_size(display: DisplayAddr, xid: u64) -> Option<(usize, usize)> {
    let x = xlib()?;
    let (mut root, mut px, mut py, mut w, mut h, mut border, mut depth) = (0, 0, 0, 0, 0, 0, 0);
    // SAFETY: valid display; all out-pointers are locals.
    let ok = unsafe {
        (x.XGetGeometry)(
            dpy(display),
            xid as c_ulong,
            &mut root,
            &mut px,
            &mut py,
            &mut w,
            &mut h,
            &mut border,
            &mut depth,
        )
    };
    (ok != 0).then_some((w as usize, h as usize))
}

impl GlxDrawable {
    fn new(
        display: DisplayAddr,
        xid: u64,
        kind: DrawableKind,
        explicit: bool,
        config: &'static FbConfig,
        size: (usize, usize),
    ) -> Option<Arc<GlxDrawable>> {
        let (w, h) = (size.0.max(1), size.1.max(1));
        let framebuffer = Framebuffer::with_samples(config.framebuffer_config(), w, h, config.sample_count()).ok()?;
        let presenter: Option<Box<dyn Present>> = match kind {
            DrawableKind::Pbuffer => None,
            _ => XPresenter::new(display, xid, kind, config).map(|p| Box::new(p) as Box<dyn Present>),
        };
        Some(Arc::new(GlxDrawable {
            display,
            xid,
            kind,
            explicit,
            config: Mutex::new(config),
            surface: Arc::new(Mutex::new(Drawable::new(framebuffer, presenter))),
            event_mask: Default::default(),
        }))
    }

    pub fn config(&self) -> &'static FbConfig {
        *lock(&self.config)
    }

    /// Follows the X drawable's size: reallocates the buffers when it changed (contents are
    /// lost, as on any resize). Pending rendering must have been flushed.
    fn follow_size(&self) {
        if self.kind == DrawableKind::Pbuffer {
            return;
        }
        let Some((w, h)) = x_size(self.display, self.xid) else {
            return;
        };
        let (w, h) = (w.max(1), h.max(1));
        let mut surface = lock(&self.surface);
        if (surface.framebuffer.width(), surface.framebuffer.height()) != (w, h) {
            let samples = surface.framebuffer.samples();
            if let Ok(framebuffer) = Framebuffer::with_samples(*surface.framebuffer.config(), w, h, samples) {
                surface.framebuffer = framebuffer;
            }
        }
    }

    /// Gives an implicit drawable the configuration of a context with another one.
    fn adopt(&self, config: &'static FbConfig) -> bool {
        let mut current = lock(&self.config);
        if current.framebuffer_config() == config.framebuffer_config() && current.samples == config.samples {
            return true;
        }
        if self.explicit {
            return false;
        }
        let mut surface = lock(&self.surface);
        let (w, h) = (surface.framebuffer.width(), surface.framebuffer.height());
        match Framebuffer::with_samples(config.framebuffer_config(), w, h, config.sample_count()) {
            Ok(framebuffer) => {
                surface.framebuffer = framebuffer;
                *current = config;
                true
            }
            Err(_) => false,
        }
    }

    /// The drawable's size (GLX_WIDTH / GLX_HEIGHT).
    pub fn size(&self) -> (usize, usize) {
        let surface = lock(&self.surface);
        (surface.framebuffer.width(), surface.framebuffer.height())
    }
}

/// The registered drawable `xid` of `display`.
pub fn lookup_drawable(display: DisplayAddr, xid: u64) -> Option<Arc<GlxDrawable>> {
    drawables().get(&(display, xid)).cloned()
}

/// glXCreateWindow / glXCreatePixmap / glXCreateGLXPixmap: registers the X drawable. Returns
/// false if it is already a GLX drawable or cannot be allocated.
pub fn create_drawable(display: DisplayAddr, xid: u64, kind: DrawableKind, config: &'static FbConfig) -> bool {
    if xid == 0 || lookup_drawable(display, xid).is_some() {
        return false;
    }
    let Some(size) = x_size(display, xid) else {
        return false;
    };
    let Some(drawable) = GlxDrawable::new(display, xid, kind, true, config, size) else {
        return false;
    };
    drawables().insert((display, xid), drawable);
    true
}

/// glXCreatePbuffer: a drawable with tessera's buffers only; its name is a 1×1 pixmap.
pub fn create_pbuffer(display: DisplayAddr, config: &'static FbConfig, width: usize, height: usize) -> u64 {
    let Some(x) = xlib() else {
        return 0;
    };
    // SAFETY: valid display; the pixmap only reserves an XID and is freed with the pbuffer.
    let xid = unsafe {
        let root = (x.XRootWindow)(dpy(display), config.visual.screen);
        (x.XCreatePixmap)(dpy(display), root, 1, 1, config.visual.depth as c_uint)
    } as u64;
    if xid == 0 {
        return 0;
    }
    match GlxDrawable::new(display, xid, DrawableKind::Pbuffer, true, config, (width, height)) {
        Some(d) => {
            drawables().insert((display, xid), d);
            xid
        }
        None => {
            // SAFETY: the pixmap created above.
            unsafe { (x.XFreePixmap)(dpy(display), xid as c_ulong) };
            0
        }
    }
}

/// glXDestroyWindow / Pixmap / Pbuffer: forgets the drawable (a context still bound to it
/// keeps its buffers until it is unbound).
pub fn destroy_drawable(display: DisplayAddr, xid: u64, kind: DrawableKind) {
    let removed = {
        let mut all = drawables();
        match all.get(&(display, xid)) {
            Some(d) if d.kind == kind => all.remove(&(display, xid)),
            _ => None,
        }
    };
    if let Some(d) = &removed {
        // The X drawable goes away: free the presenter's X resources now, and present no
        // more (a context still bound to it keeps rendering into tessera's buffers).
        let presenter = lock(&d.surface).presenter.take();
        if let Some(mut presenter) = presenter {
            presenter.release();
        }
    }
    if let (Some(d), Some(x)) = (removed, xlib()) {
        if d.kind == DrawableKind::Pbuffer {
            // SAFETY: the name pixmap created by create_pbuffer.
            unsafe { (x.XFreePixmap)(dpy(display), xid as c_ulong) };
        }
    }
}

/// The drawable for `xid`, registering a plain X window bound for the first time: BadMatch
/// when it cannot take the context's configuration, BadDrawable when it is no drawable
/// (or its buffers cannot be allocated).
fn drawable_for_binding(
    display: DisplayAddr,
    xid: u64,
    config: &'static FbConfig,
) -> Result<Arc<GlxDrawable>, MakeCurrentError> {
    if let Some(d) = lookup_drawable(display, xid) {
        return if d.adopt(config) { Ok(d) } else { Err(MakeCurrentError::BadMatch) };
    }
    let size = x_size(display, xid).ok_or(MakeCurrentError::BadDrawable)?;
    let drawable = GlxDrawable::new(display, xid, DrawableKind::Window, false, config, size)
        .ok_or(MakeCurrentError::BadDrawable)?;
    drawables().insert((display, xid), drawable.clone());
    Ok(drawable)
}

// ---------------------------------------------------------------------------------------------
// Contexts
// ---------------------------------------------------------------------------------------------

/// A GLX context.
pub struct GlxContext {
    pub shared: Arc<SharedContext>,
    pub config: &'static FbConfig,
    pub display: DisplayAddr,
    pub share: usize,
}

fn contexts() -> MutexGuard<'static, HashMap<usize, Arc<GlxContext>>> {
    static CONTEXTS: OnceLock<Mutex<HashMap<usize, Arc<GlxContext>>>> = OnceLock::new();
    lock(CONTEXTS.get_or_init(|| Mutex::new(HashMap::new())))
}

/// glXCreateContext & co. after argument checks: registers a context and returns its handle.
/// `share` must be 0 or a live context, whose display lists, texture and buffer objects the
/// new context shares (context::share).
pub fn create_context(display: DisplayAddr, config: &'static FbConfig, share: usize) -> Option<usize> {
    let share_source = match share {
        0 => None,
        handle => Some(lookup_context(handle)?),
    };
    // The worker threads start now rather than at the first scene (`crate::pool::prestart`).
    crate::pool::prestart(crate::raster::thread_count() - 1);
    let mut context = Context::new(ContextConfig { visual: config.framebuffer_config() });
    if let Some(source) = share_source {
        context.join_share_group(source.shared.share_group());
    }
    let glx = Arc::new(GlxContext { shared: SharedContext::new(context), config, display, share });
    let handle = Arc::as_ptr(&glx) as usize;
    contexts().insert(handle, glx);
    Some(handle)
}

pub fn lookup_context(handle: usize) -> Option<Arc<GlxContext>> {
    contexts().get(&handle).cloned()
}

/// glXDestroyContext: unregisters; a context current on some thread stays usable there
/// until it is released (GLX: destruction is deferred while current).
pub fn destroy_context(handle: usize) {
    contexts().remove(&handle);
}

/// What this thread has current through GLX.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CurrentBinding {
    pub context: usize,
    pub draw: u64,
    pub read: u64,
    pub display: DisplayAddr,
}

thread_local! {
    /// The binding and the address of its SharedContext.
    static CURRENT: RefCell<(CurrentBinding, usize)> = RefCell::new((CurrentBinding::default(), 0));
}

/// This thread's GLX binding, if its current GL context is still the GLX one (an OSMesa
/// context made current later replaces it).
pub fn current_binding() -> CurrentBinding {
    let (binding, shared) = CURRENT.try_with(|c| *c.borrow()).unwrap_or_default();
    // Compared by address: the registry may already have dropped a destroyed context that
    // is still current here.
    let still = current::current().is_some_and(|s| Arc::as_ptr(&s) as usize == shared);
    if binding.context != 0 && still {
        binding
    } else {
        CurrentBinding::default()
    }
}

fn set_binding(binding: CurrentBinding, shared: usize) {
    let _ = CURRENT.try_with(|c| *c.borrow_mut() = (binding, shared));
}

/// Why glXMakeCurrent failed (the GLX error it stands for).
#[derive(Debug, PartialEq, Eq)]
pub enum MakeCurrentError {
    BadContext,
    BadMatch,
    BadDrawable,
    BadAccess,
}

/// Completes the rendering of this thread's current context.
fn flush_current_rendering() {
    current::with_current(|gl| gl.flush_rendering());
}

/// Releases this thread's current GLX context (if `except` is not it) from its drawable: its
/// rendering is completed into tessera's buffers but not shown, because the window may
/// already be destroyed (programs commonly destroy the window, then unbind at exit).
fn release_current_glx(except: Option<&Arc<SharedContext>>) {
    if current_binding().context == 0 {
        return;
    }
    if let Some(shared) = current::current() {
        if !except.is_some_and(|e| Arc::ptr_eq(e, &shared)) {
            current::with_current(|gl| gl.bind_drawable(None));
        }
    }
}

/// glXMakeContextCurrent (glXMakeCurrent: draw == read). Rendering goes to `draw`; pixels
/// are read (glReadPixels, glCopyPixels, glCopyTexImage) from `read`.
pub fn make_current(display: DisplayAddr, draw: u64, read: u64, context: usize) -> Result<(), MakeCurrentError> {
    if context == 0 {
        if draw != 0 || read != 0 {
            return Err(MakeCurrentError::BadMatch);
        }
        release_current_glx(None);
        let _ = current::make_current(None);
        set_binding(CurrentBinding::default(), 0);
        return Ok(());
    }
    let glx = lookup_context(context).ok_or(MakeCurrentError::BadContext)?;
    if draw == 0 || read == 0 {
        return Err(MakeCurrentError::BadMatch);
    }
    // Refused before anything changes: the calling thread keeps its current context.
    if glx.shared.bound_thread().is_some_and(|t| t != std::thread::current().id()) {
        return Err(MakeCurrentError::BadAccess);
    }
    let drawable = drawable_for_binding(display, draw, glx.config)?;
    let read_drawable = if read != draw { drawable_for_binding(display, read, glx.config)? } else { drawable.clone() };
    flush_current_rendering();
    drawable.follow_size();
    read_drawable.follow_size();
    release_current_glx(Some(&glx.shared));
    current::make_current(Some(glx.shared.clone())).map_err(|_| MakeCurrentError::BadAccess)?;
    current::with_current(|context| {
        context.bind_drawable(Some(drawable.surface.clone()));
        context.bind_read_drawable(Some(read_drawable.surface.clone()));
    });
    set_binding(CurrentBinding { context, draw, read, display }, Arc::as_ptr(&glx.shared) as usize);
    Ok(())
}

/// glXSwapBuffers: completes the current context's rendering into `xid`, copies back to front
/// and shows it, then follows the window's size for the next frame.
pub fn swap_buffers(display: DisplayAddr, xid: u64) {
    let Some(drawable) = lookup_drawable(display, xid) else {
        return;
    };
    flush_current_rendering();
    {
        let mut surface = lock(&drawable.surface);
        let fb = &mut surface.framebuffer;
        if fb.config().double_buffered {
            fb.copy_color(ColorSlot::BackLeft, ColorSlot::FrontLeft);
            fb.copy_color(ColorSlot::BackRight, ColorSlot::FrontRight);
        }
        surface.present();
    }
    drawable.follow_size();
}

/// glXWaitGL: completes rendering and shows the front buffer.
pub fn wait_gl() {
    current::with_current(|gl| gl.finish());
}

/// glXWaitX: waits until the X server processed the application's requests.
pub fn wait_x() {
    let binding = current_binding();
    if let (Some(x), true) = (xlib(), binding.display != 0) {
        // SAFETY: the display of the current binding, open while it is current.
        unsafe { (x.XSync)(dpy(binding.display), 0) };
    }
}

/// Whether the server has the MIT-SHM or GLX extension, ... : XQueryExtension.
pub fn server_extension(display: DisplayAddr, name: &std::ffi::CStr) -> Option<(i32, i32, i32)> {
    let x = xlib()?;
    let (mut opcode, mut event, mut error) = (0, 0, 0);
    // SAFETY: valid display and NUL-terminated name.
    let present = unsafe { (x.XQueryExtension)(dpy(display), name.as_ptr(), &mut opcode, &mut event, &mut error) };
    (present != 0).then_some((opcode, event, error))
}

/// glXCopyContext: copies the attribute groups of `mask` from `source` to `target`.
pub fn copy_context(source: &GlxContext, target: &GlxContext, mask: u32) -> bool {
    // A destination current on some thread (this one included), or a source current on
    // another thread, cannot be reached: BadAccess.
    if target.shared.bound_thread().is_some() {
        return false;
    }
    current::with_two(&source.shared, &target.shared, |src, dst| dst.copy_attribs_from(src, mask)).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixels_pack_into_the_visual_masks() {
        let rgb = [0xff0000, 0xff00, 0xff];
        assert_eq!(pack_pixel([0x12, 0x34, 0x56, 0x78], &rgb), 0x123456);
        let bgr = [0xff, 0xff00, 0xff0000];
        assert_eq!(pack_pixel([0x12, 0x34, 0x56, 0x78], &bgr), 0x563412);
        let rgb565 = [0xf800, 0x7e0, 0x1f];
        assert_eq!(pack_pixel([0xff, 0xff, 0xff, 0], &rgb565), 0xffff);
        assert_eq!(pack_pixel([0x80, 0x40, 0x08, 0], &rgb565), (0x10 << 11) | (0x10 << 5) | 0x01);
    }
}
