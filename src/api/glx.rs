//! The GLX 1.4 entry points of `<GL/glx.h>` (and the GLX extensions tessera advertises).
//!
//! They forward to `winsys::glx`, which talks to the X server through the application's own
//! `Display*` with a run-time loaded Xlib. Contexts and configurations given to C are
//! identifiers looked up in registries there, never dereferenced, so a NULL, stale or forged
//! handle is refused. Failures that GLX reports as X protocol errors (BadMatch, BadContext,
//! ...) are reported by the return value only: tessera does not send X errors.
//!
//! Arrays returned to the caller (GLXFBConfig lists, XVisualInfo) come from malloc or from
//! Xlib, so the caller frees them with XFree as usual.
//!
//! These prototypes need the X types of `<GL/glx.h>`, so they stay out of `tessera.h`
//! (`cbindgen:ignore` on the module in `api/mod.rs`).
// XIDs and visual ids are C `unsigned long`, kept as u64 inside: the casts are no-ops only
// where `unsigned long` is 64 bits.
#![allow(clippy::unnecessary_cast)]
use super::guard;
use super::types::*;
use crate::context::strings;
use crate::winsys::glx::{self as glx, DisplayAddr, DrawableKind, MakeCurrentError};
use crate::winsys::glx_config::*;
use std::ffi::{c_char, c_int, c_uint, c_ulong, c_void, CStr};
use x11_dl::xlib::{Display, XVisualInfo};

pub type Bool = c_int;
pub type GLXContext = *mut c_void;
pub type GLXFBConfig = *mut c_void;
pub type GLXDrawable = c_ulong;
pub type GLXextFuncPtr = Option<unsafe extern "C" fn()>;

const TRUE: Bool = 1;
const FALSE: Bool = 0;
const SUCCESS: c_int = 0;
const GLX_BAD_ATTRIBUTE: c_int = 2;
const GLX_BAD_VISUAL: c_int = 4;
const GLX_BAD_CONTEXT: c_int = 5;
const GLX_VENDOR: c_int = 1;
const GLX_VERSION: c_int = 2;
const GLX_EXTENSIONS: c_int = 3;
const GLX_WIDTH: c_int = 0x801D;
const GLX_HEIGHT: c_int = 0x801E;
const GLX_PRESERVED_CONTENTS: c_int = 0x801B;
const GLX_LARGEST_PBUFFER: c_int = 0x801C;
const GLX_PBUFFER_HEIGHT: c_int = 0x8040;
const GLX_PBUFFER_WIDTH: c_int = 0x8041;
const GLX_SHARE_CONTEXT_EXT: c_int = 0x800A;
const GLX_SWAP_INTERVAL_EXT: c_int = 0x20F1;
const GLX_MAX_SWAP_INTERVAL_EXT: c_int = 0x20F2;
const GLX_CONTEXT_MAJOR_VERSION_ARB: c_int = 0x2091;
const GLX_CONTEXT_MINOR_VERSION_ARB: c_int = 0x2092;
const GLX_CONTEXT_FLAGS_ARB: c_int = 0x2094;
const GLX_CONTEXT_PROFILE_MASK_ARB: c_int = 0x9126;
const GLX_CONTEXT_CORE_PROFILE_BIT_ARB: c_int = 1;
const GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB: c_int = 2;
const GLX_CONTEXT_DEBUG_BIT_ARB: c_int = 1;
const GLX_CONTEXT_RESET_NOTIFICATION_STRATEGY_ARB: c_int = 0x8256;
const GLX_NO_RESET_NOTIFICATION_ARB: c_int = 0x8261;

const VENDOR: &CStr = c"tessera project";
const VERSION: &CStr = c"1.4";
/// The GLX extensions whose every entry point and token works.
const EXTENSIONS: &CStr = c"GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address GLX_EXT_swap_control GLX_MESA_swap_control GLX_SGI_swap_control";

fn addr(display: *mut Display) -> DisplayAddr {
    display as DisplayAddr
}

/// Reads a zero-terminated attribute list (pairs unless `singles`, for glXChooseVisual).
///
/// # Safety
/// `list` must be NULL or zero-terminated as the GLX calls require.
unsafe fn attribute_list(list: *const c_int, singles: bool) -> Vec<i32> {
    let mut out = Vec::new();
    if list.is_null() {
        return out;
    }
    let mut i = 0;
    loop {
        // SAFETY: the list is terminated by None (0); we stop there.
        let attribute = unsafe { *list.add(i) };
        if attribute == 0 {
            break;
        }
        out.push(attribute);
        let boolean = singles && matches!(attribute, GLX_USE_GL | GLX_RGBA | GLX_DOUBLEBUFFER | GLX_STEREO);
        if !boolean {
            // SAFETY: a non-boolean attribute is followed by its value.
            out.push(unsafe { *list.add(i + 1) });
            i += 1;
        }
        i += 1;
    }
    out
}

/// A malloc'ed array of configuration handles (freed by the caller with XFree).
///
/// # Safety
/// `count` must be NULL or writable.
unsafe fn config_array(configs: &[&'static FbConfig], count: *mut c_int) -> *mut GLXFBConfig {
    if !count.is_null() {
        // SAFETY: checked non-null; the caller's out-parameter.
        unsafe { *count = 0 };
    }
    if configs.is_empty() {
        return std::ptr::null_mut();
    }
    // SAFETY: plain malloc; checked for NULL below.
    let array = unsafe { libc::malloc(std::mem::size_of_val(configs)) } as *mut GLXFBConfig;
    if array.is_null() {
        return array;
    }
    for (i, c) in configs.iter().enumerate() {
        // SAFETY: `array` holds `configs.len()` pointers.
        unsafe { *array.add(i) = glx::config_handle(c) as GLXFBConfig };
    }
    if !count.is_null() {
        // SAFETY: checked non-null.
        unsafe { *count = configs.len() as c_int };
    }
    array
}

fn config_of(display: *mut Display, config: GLXFBConfig) -> Option<&'static FbConfig> {
    let _ = glx::configs(addr(display));
    glx::config_from_handle(config as usize)
}

/// The configuration a caller's XVisualInfo stands for.
///
/// # Safety
/// `vis` must be NULL or point to an XVisualInfo.
unsafe fn config_of_visual(display: *mut Display, vis: *const XVisualInfo) -> Option<&'static FbConfig> {
    if vis.is_null() || display.is_null() {
        return None;
    }
    // SAFETY: checked non-null; the caller passes an XVisualInfo.
    let visual_id = unsafe { (*vis).visualid } as u64;
    glx::config_for_visual(addr(display), visual_id)
}

fn set<T>(out: *mut T, value: T) {
    if !out.is_null() {
        // SAFETY: non-null out-parameter of the caller.
        unsafe { *out = value };
    }
}

/// # Safety
/// `errorBase`/`eventBase` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryExtension(dpy: *mut Display, errorBase: *mut c_int, eventBase: *mut c_int) -> Bool {
    guard(FALSE, || {
        if dpy.is_null() || glx::xlib().is_none() {
            return FALSE;
        }
        // tessera renders without the server's GLX; its codes are given when it has one.
        let (_, event, error) = glx::server_extension(addr(dpy), c"GLX").unwrap_or((0, 0, 0));
        set(errorBase, error);
        set(eventBase, event);
        TRUE
    })
}

/// # Safety
/// `major`/`minor` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryVersion(dpy: *mut Display, major: *mut c_int, minor: *mut c_int) -> Bool {
    guard(FALSE, || {
        if dpy.is_null() {
            return FALSE;
        }
        set(major, 1);
        set(minor, 4);
        TRUE
    })
}

#[no_mangle]
pub extern "C" fn glXQueryExtensionsString(dpy: *mut Display, screen: c_int) -> *const c_char {
    guard(std::ptr::null(), || {
        let _ = (dpy, screen);
        EXTENSIONS.as_ptr()
    })
}

fn glx_string(name: c_int) -> *const c_char {
    match name {
        GLX_VENDOR => VENDOR.as_ptr(),
        GLX_VERSION => VERSION.as_ptr(),
        GLX_EXTENSIONS => EXTENSIONS.as_ptr(),
        _ => std::ptr::null(),
    }
}

#[no_mangle]
pub extern "C" fn glXGetClientString(dpy: *mut Display, name: c_int) -> *const c_char {
    guard(std::ptr::null(), || {
        let _ = dpy;
        glx_string(name)
    })
}

#[no_mangle]
pub extern "C" fn glXQueryServerString(dpy: *mut Display, screen: c_int, name: c_int) -> *const c_char {
    guard(std::ptr::null(), || {
        let _ = (dpy, screen);
        glx_string(name)
    })
}

/// # Safety
/// `attribList` must be NULL or a None-terminated glXChooseVisual attribute list.
#[no_mangle]
pub unsafe extern "C" fn glXChooseVisual(dpy: *mut Display, screen: c_int, attribList: *mut c_int) -> *mut XVisualInfo {
    // SAFETY: forwarded contract.
    let list = unsafe { attribute_list(attribList, true) };
    guard(std::ptr::null_mut(), || {
        if dpy.is_null() {
            return std::ptr::null_mut();
        }
        let Ok(criteria) = Criteria::visual(&list) else {
            return std::ptr::null_mut();
        };
        match criteria.choose(glx::configs(addr(dpy)), screen).first() {
            Some(config) => glx::visual_info(addr(dpy), config),
            None => std::ptr::null_mut(),
        }
    })
}

/// # Safety
/// `vis` must be NULL or an XVisualInfo; `value` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetConfig(
    dpy: *mut Display,
    vis: *mut XVisualInfo,
    attrib: c_int,
    value: *mut c_int,
) -> c_int {
    // SAFETY: forwarded contract.
    let config = guard(None, || unsafe { config_of_visual(dpy, vis) });
    let Some(config) = config else {
        if attrib == GLX_USE_GL {
            set(value, 0);
            return SUCCESS;
        }
        return GLX_BAD_VISUAL;
    };
    match config.attrib(attrib) {
        Some(v) => {
            set(value, v);
            SUCCESS
        }
        None => GLX_BAD_ATTRIBUTE,
    }
}

fn context_handle(handle: Option<usize>) -> GLXContext {
    handle.map_or(std::ptr::null_mut(), |h| h as GLXContext)
}

/// # Safety
/// `vis` must be NULL or an XVisualInfo.
#[no_mangle]
pub unsafe extern "C" fn glXCreateContext(
    dpy: *mut Display,
    vis: *mut XVisualInfo,
    shareList: GLXContext,
    direct: Bool,
) -> GLXContext {
    let _ = direct;
    // SAFETY: forwarded contract.
    let config = guard(None, || unsafe { config_of_visual(dpy, vis) });
    let Some(config) = config else {
        return std::ptr::null_mut();
    };
    guard(std::ptr::null_mut(), || context_handle(glx::create_context(addr(dpy), config, shareList as usize)))
}

#[no_mangle]
pub extern "C" fn glXCreateNewContext(
    dpy: *mut Display,
    config: GLXFBConfig,
    renderType: c_int,
    shareList: GLXContext,
    direct: Bool,
) -> GLXContext {
    let _ = direct;
    guard(std::ptr::null_mut(), || {
        let Some(config) = config_of(dpy, config) else {
            return std::ptr::null_mut();
        };
        if renderType != GLX_RGBA_TYPE {
            return std::ptr::null_mut();
        }
        context_handle(glx::create_context(addr(dpy), config, shareList as usize))
    })
}

/// GLX_ARB_create_context(_profile): compatibility contexts of the versions that work. A
/// core profile is only meaningful from 3.2, which tessera does not reach; below 3.2 the
/// profile mask is ignored as the extension says.
///
/// # Safety
/// `attribList` must be NULL or a None-terminated attribute/value list.
#[no_mangle]
pub unsafe extern "C" fn glXCreateContextAttribsARB(
    dpy: *mut Display,
    config: GLXFBConfig,
    share_context: GLXContext,
    direct: Bool,
    attribList: *const c_int,
) -> GLXContext {
    let _ = direct;
    // SAFETY: forwarded contract.
    let list = unsafe { attribute_list(attribList, false) };
    guard(std::ptr::null_mut(), || {
        let Some(config) = config_of(dpy, config) else {
            return std::ptr::null_mut();
        };
        let (mut major, mut minor, mut flags, mut profile) = (1, 0, 0, GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB);
        for pair in list.chunks(2) {
            let value = pair.get(1).copied().unwrap_or(0);
            match pair[0] {
                GLX_CONTEXT_MAJOR_VERSION_ARB => major = value,
                GLX_CONTEXT_MINOR_VERSION_ARB => minor = value,
                GLX_CONTEXT_FLAGS_ARB => flags = value,
                GLX_CONTEXT_PROFILE_MASK_ARB => profile = value,
                GLX_RENDER_TYPE if value == GLX_RGBA_TYPE => {}
                GLX_CONTEXT_RESET_NOTIFICATION_STRATEGY_ARB if value == GLX_NO_RESET_NOTIFICATION_ARB => {}
                _ => return std::ptr::null_mut(),
            }
        }
        // Only the debug flag may be given (forward-compatible needs 3.0, robustness is
        // not advertised); the debug flag changes nothing.
        if flags & !GLX_CONTEXT_DEBUG_BIT_ARB != 0 {
            return std::ptr::null_mut();
        }
        let profile_valid =
            profile == GLX_CONTEXT_CORE_PROFILE_BIT_ARB || profile == GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB;
        if (major, minor) >= (3, 2) && !profile_valid {
            return std::ptr::null_mut();
        }
        if !strings::supports_version(major, minor) {
            return std::ptr::null_mut();
        }
        context_handle(glx::create_context(addr(dpy), config, share_context as usize))
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyContext(dpy: *mut Display, ctx: GLXContext) {
    let _ = dpy;
    guard((), || glx::destroy_context(ctx as usize))
}

fn make_current(dpy: *mut Display, draw: GLXDrawable, read: GLXDrawable, ctx: GLXContext) -> Bool {
    guard(FALSE, || match glx::make_current(addr(dpy), draw as u64, read as u64, ctx as usize) {
        Ok(()) => TRUE,
        Err(MakeCurrentError::BadContext | MakeCurrentError::BadMatch) => FALSE,
        Err(MakeCurrentError::BadDrawable | MakeCurrentError::BadAccess) => FALSE,
    })
}

#[no_mangle]
pub extern "C" fn glXMakeCurrent(dpy: *mut Display, drawable: GLXDrawable, ctx: GLXContext) -> Bool {
    make_current(dpy, drawable, drawable, ctx)
}

#[no_mangle]
pub extern "C" fn glXMakeContextCurrent(
    dpy: *mut Display,
    draw: GLXDrawable,
    read: GLXDrawable,
    ctx: GLXContext,
) -> Bool {
    make_current(dpy, draw, read, ctx)
}

#[no_mangle]
pub extern "C" fn glXGetCurrentContext() -> GLXContext {
    guard(std::ptr::null_mut(), || glx::current_binding().context as GLXContext)
}

#[no_mangle]
pub extern "C" fn glXGetCurrentDrawable() -> GLXDrawable {
    guard(0, || glx::current_binding().draw as GLXDrawable)
}

#[no_mangle]
pub extern "C" fn glXGetCurrentReadDrawable() -> GLXDrawable {
    guard(0, || glx::current_binding().read as GLXDrawable)
}

#[no_mangle]
pub extern "C" fn glXGetCurrentDisplay() -> *mut Display {
    guard(std::ptr::null_mut(), || glx::current_binding().display as *mut Display)
}

#[no_mangle]
pub extern "C" fn glXIsDirect(dpy: *mut Display, ctx: GLXContext) -> Bool {
    let _ = dpy;
    guard(FALSE, || glx::lookup_context(ctx as usize).is_some() as Bool)
}

#[no_mangle]
pub extern "C" fn glXCopyContext(dpy: *mut Display, src: GLXContext, dst: GLXContext, mask: c_ulong) {
    let _ = dpy;
    guard((), || {
        if let (Some(s), Some(d)) = (glx::lookup_context(src as usize), glx::lookup_context(dst as usize)) {
            glx::copy_context(&s, &d, mask as u32);
        }
    })
}

/// # Safety
/// `attribList` must be NULL or a None-terminated list; `nitems` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXChooseFBConfig(
    dpy: *mut Display,
    screen: c_int,
    attribList: *const c_int,
    nitems: *mut c_int,
) -> *mut GLXFBConfig {
    // SAFETY: forwarded contract.
    let list = unsafe { attribute_list(attribList, false) };
    set(nitems, 0);
    guard(std::ptr::null_mut(), || {
        if dpy.is_null() {
            return std::ptr::null_mut();
        }
        let Ok(criteria) = Criteria::fbconfig(&list) else {
            return std::ptr::null_mut();
        };
        let chosen = criteria.choose(glx::configs(addr(dpy)), screen);
        // SAFETY: forwarded contract on `nitems`.
        unsafe { config_array(&chosen, nitems) }
    })
}

/// # Safety
/// `nelements` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetFBConfigs(dpy: *mut Display, screen: c_int, nelements: *mut c_int) -> *mut GLXFBConfig {
    set(nelements, 0);
    guard(std::ptr::null_mut(), || {
        if dpy.is_null() {
            return std::ptr::null_mut();
        }
        let on_screen: Vec<&'static FbConfig> =
            glx::configs(addr(dpy)).iter().filter(|c| c.visual.screen == screen).collect();
        // SAFETY: forwarded contract on `nelements`.
        unsafe { config_array(&on_screen, nelements) }
    })
}

/// # Safety
/// `value` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetFBConfigAttrib(
    dpy: *mut Display,
    config: GLXFBConfig,
    attribute: c_int,
    value: *mut c_int,
) -> c_int {
    let Some(config) = guard(None, || config_of(dpy, config)) else {
        return GLX_BAD_ATTRIBUTE;
    };
    match config.attrib(attribute) {
        Some(v) => {
            set(value, v);
            SUCCESS
        }
        None => GLX_BAD_ATTRIBUTE,
    }
}

#[no_mangle]
pub extern "C" fn glXGetVisualFromFBConfig(dpy: *mut Display, config: GLXFBConfig) -> *mut XVisualInfo {
    guard(std::ptr::null_mut(), || match config_of(dpy, config) {
        Some(c) => glx::visual_info(addr(dpy), c),
        None => std::ptr::null_mut(),
    })
}

fn create_drawable(dpy: *mut Display, config: GLXFBConfig, xid: c_ulong, kind: DrawableKind) -> c_ulong {
    guard(0, || {
        let Some(config) = config_of(dpy, config) else {
            return 0;
        };
        if glx::create_drawable(addr(dpy), xid as u64, kind, config) {
            xid
        } else {
            0
        }
    })
}

/// The GLXWindow is the X window's own XID (as in Mesa's Xlib driver).
#[no_mangle]
pub extern "C" fn glXCreateWindow(
    dpy: *mut Display,
    config: GLXFBConfig,
    win: c_ulong,
    attribList: *const c_int,
) -> c_ulong {
    let _ = attribList;
    create_drawable(dpy, config, win, DrawableKind::Window)
}

#[no_mangle]
pub extern "C" fn glXDestroyWindow(dpy: *mut Display, win: c_ulong) {
    guard((), || glx::destroy_drawable(addr(dpy), win as u64, DrawableKind::Window))
}

/// The GLXPixmap is the X pixmap's own XID.
#[no_mangle]
pub extern "C" fn glXCreatePixmap(
    dpy: *mut Display,
    config: GLXFBConfig,
    pixmap: c_ulong,
    attribList: *const c_int,
) -> c_ulong {
    let _ = attribList;
    create_drawable(dpy, config, pixmap, DrawableKind::Pixmap)
}

#[no_mangle]
pub extern "C" fn glXDestroyPixmap(dpy: *mut Display, pixmap: c_ulong) {
    guard((), || glx::destroy_drawable(addr(dpy), pixmap as u64, DrawableKind::Pixmap))
}

/// # Safety
/// `visual` must be NULL or an XVisualInfo.
#[no_mangle]
pub unsafe extern "C" fn glXCreateGLXPixmap(dpy: *mut Display, visual: *mut XVisualInfo, pixmap: c_ulong) -> c_ulong {
    // SAFETY: forwarded contract.
    let config = guard(None, || unsafe { config_of_visual(dpy, visual) });
    let Some(config) = config else {
        return 0;
    };
    guard(0, || if glx::create_drawable(addr(dpy), pixmap as u64, DrawableKind::Pixmap, config) { pixmap } else { 0 })
}

#[no_mangle]
pub extern "C" fn glXDestroyGLXPixmap(dpy: *mut Display, pixmap: c_ulong) {
    guard((), || glx::destroy_drawable(addr(dpy), pixmap as u64, DrawableKind::Pixmap))
}

/// # Safety
/// `attribList` must be NULL or a None-terminated attribute/value list.
#[no_mangle]
pub unsafe extern "C" fn glXCreatePbuffer(dpy: *mut Display, config: GLXFBConfig, attribList: *const c_int) -> c_ulong {
    // SAFETY: forwarded contract.
    let list = unsafe { attribute_list(attribList, false) };
    guard(0, || {
        let Some(config) = config_of(dpy, config) else {
            return 0;
        };
        let (mut width, mut height) = (0, 0);
        for pair in list.chunks(2) {
            let value = pair.get(1).copied().unwrap_or(0);
            match pair[0] {
                GLX_PBUFFER_WIDTH => width = value,
                GLX_PBUFFER_HEIGHT => height = value,
                GLX_PRESERVED_CONTENTS | GLX_LARGEST_PBUFFER => {}
                _ => return 0,
            }
        }
        let max = crate::context::state::MAX_VIEWPORT_DIM;
        if !(0..=max).contains(&width) || !(0..=max).contains(&height) {
            return 0;
        }
        glx::create_pbuffer(addr(dpy), config, width as usize, height as usize) as c_ulong
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyPbuffer(dpy: *mut Display, pbuf: c_ulong) {
    guard((), || glx::destroy_drawable(addr(dpy), pbuf as u64, DrawableKind::Pbuffer))
}

/// # Safety
/// `value` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryDrawable(dpy: *mut Display, draw: GLXDrawable, attribute: c_int, value: *mut c_uint) {
    guard((), || {
        let Some(drawable) = glx::lookup_drawable(addr(dpy), draw as u64) else {
            return;
        };
        let (w, h) = drawable.size();
        let v = match attribute {
            GLX_WIDTH => w as c_uint,
            GLX_HEIGHT => h as c_uint,
            GLX_PRESERVED_CONTENTS => 1,
            GLX_LARGEST_PBUFFER => 0,
            GLX_FBCONFIG_ID => drawable.config().id as c_uint,
            GLX_SWAP_INTERVAL_EXT => 0,
            GLX_MAX_SWAP_INTERVAL_EXT => 1,
            _ => return,
        };
        set(value, v);
    })
}

/// # Safety
/// `value` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryContext(
    dpy: *mut Display,
    ctx: GLXContext,
    attribute: c_int,
    value: *mut c_int,
) -> c_int {
    let _ = dpy;
    let Some(context) = guard(None, || glx::lookup_context(ctx as usize)) else {
        return GLX_BAD_CONTEXT;
    };
    let v = match attribute {
        GLX_FBCONFIG_ID => context.config.id,
        GLX_RENDER_TYPE => GLX_RGBA_TYPE,
        GLX_SCREEN => context.config.visual.screen,
        GLX_VISUAL_ID => context.config.visual.visual_id as c_int,
        GLX_SHARE_CONTEXT_EXT => context.share as c_int,
        _ => return GLX_BAD_ATTRIBUTE,
    };
    set(value, v);
    SUCCESS
}

/// GLX events (pbuffer clobber, swap complete) are never generated: the mask is accepted.
#[no_mangle]
pub extern "C" fn glXSelectEvent(dpy: *mut Display, draw: GLXDrawable, event_mask: c_ulong) {
    guard((), || {
        if let Some(d) = glx::lookup_drawable(addr(dpy), draw as u64) {
            d.event_mask.store(event_mask as u64, std::sync::atomic::Ordering::Relaxed);
        }
    })
}

/// # Safety
/// `event_mask` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetSelectedEvent(dpy: *mut Display, draw: GLXDrawable, event_mask: *mut c_ulong) {
    guard((), || {
        let mask = glx::lookup_drawable(addr(dpy), draw as u64)
            .map_or(0, |d| d.event_mask.load(std::sync::atomic::Ordering::Relaxed));
        set(event_mask, mask as c_ulong);
    })
}

#[no_mangle]
pub extern "C" fn glXSwapBuffers(dpy: *mut Display, drawable: GLXDrawable) {
    guard((), || glx::swap_buffers(addr(dpy), drawable as u64))
}

#[no_mangle]
pub extern "C" fn glXWaitGL() {
    guard((), glx::wait_gl)
}

#[no_mangle]
pub extern "C" fn glXWaitX() {
    guard((), glx::wait_x)
}

/// Compiles display lists `listBase .. listBase + count` that draw the glyphs `first ..
/// first + count` of the X font `font` with glBitmap (and advance the raster position), as
/// GLX 1.4 §3.3.10 says. Needs a current context (on the context's display).
#[no_mangle]
pub extern "C" fn glXUseXFont(font: c_ulong, first: c_int, count: c_int, listBase: c_int) {
    use super::enums::*;
    use super::gl_lists::{glEndList, glNewList};
    use super::gl_pixel_rect::glBitmap;
    use super::gl_pixels::glPixelStorei;
    use super::gl_state::glGetIntegerv;
    guard((), || {
        let display = glXGetCurrentDisplay();
        let Some(glyphs) = crate::winsys::xfont::glyphs(display as usize, font as u64, first, count) else {
            return;
        };
        // glBitmap reads with the unpack state: tightly packed rows, most significant bit
        // first, restored afterwards.
        const UNPACK: [u32; 6] = [
            GL_UNPACK_SWAP_BYTES,
            GL_UNPACK_LSB_FIRST,
            GL_UNPACK_ROW_LENGTH,
            GL_UNPACK_SKIP_ROWS,
            GL_UNPACK_SKIP_PIXELS,
            GL_UNPACK_ALIGNMENT,
        ];
        let saved = UNPACK.map(|p| {
            let mut v = 0;
            // SAFETY: one GLint.
            unsafe { glGetIntegerv(p, &mut v) };
            v
        });
        for (p, v) in UNPACK.iter().zip([0, 0, 0, 0, 0, 1]) {
            glPixelStorei(*p, v);
        }
        for (i, g) in glyphs.iter().enumerate() {
            glNewList((listBase + i as c_int) as u32, GL_COMPILE);
            let bits = if g.bits.is_empty() { std::ptr::null() } else { g.bits.as_ptr() };
            // SAFETY: `bits` holds `height` rows of whole bytes for `width` bits (or is NULL
            // for an empty glyph).
            unsafe { glBitmap(g.width, g.height, g.x_origin, g.y_origin, g.x_move, 0.0, bits) };
            glEndList();
        }
        for (p, v) in UNPACK.iter().zip(saved) {
            glPixelStorei(*p, v);
        }
    })
}

/// # Safety
/// `procName` must be NULL or NUL-terminated.
#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddress(procName: *const GLubyte) -> GLXextFuncPtr {
    if procName.is_null() {
        return None;
    }
    // SAFETY: non-null and NUL-terminated by the contract.
    let name = unsafe { CStr::from_ptr(procName.cast()) };
    guard(None, || super::procs::lookup(name.to_bytes()))
}

/// # Safety
/// `procName` must be NULL or NUL-terminated.
#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddressARB(procName: *const GLubyte) -> GLXextFuncPtr {
    // SAFETY: forwarded contract.
    unsafe { glXGetProcAddress(procName) }
}

/// Swap intervals: tessera presents immediately; the calls succeed and change nothing.
#[no_mangle]
pub extern "C" fn glXSwapIntervalEXT(dpy: *mut Display, drawable: GLXDrawable, interval: c_int) {
    guard((), || {
        let _ = (dpy, drawable, interval);
    })
}

#[no_mangle]
pub extern "C" fn glXSwapIntervalMESA(interval: c_uint) -> c_int {
    guard(0, || {
        let _ = interval;
        0
    })
}

#[no_mangle]
pub extern "C" fn glXGetSwapIntervalMESA() -> c_int {
    guard(0, || 0)
}

#[no_mangle]
pub extern "C" fn glXSwapIntervalSGI(interval: c_int) -> c_int {
    guard(0, || {
        // GLX_SGI_swap_control: a non-positive interval is GLX_BAD_VALUE (6).
        if interval <= 0 {
            6
        } else {
            0
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn attribute_lists_are_read_up_to_none() {
        let pairs = [GLX_DOUBLEBUFFER, 1, GLX_DEPTH_SIZE, 24, 0, 99];
        // SAFETY: a None-terminated list.
        assert_eq!(unsafe { attribute_list(pairs.as_ptr(), false) }, vec![GLX_DOUBLEBUFFER, 1, GLX_DEPTH_SIZE, 24]);
        let singles = [GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 1, 0];
        // SAFETY: a None-terminated list.
        assert_eq!(
            unsafe { attribute_list(singles.as_ptr(), true) },
            vec![GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 1]
        );
        // SAFETY: NULL is allowed.
        assert!(unsafe { attribute_list(std::ptr::null(), false) }.is_empty());
    }

    #[test]
    fn glx_calls_without_a_display_fail_cleanly() {
        assert!(glXGetCurrentContext().is_null());
        assert_eq!(glXGetCurrentDrawable(), 0);
        let mut n = 7;
        // SAFETY: NULL display and a writable count.
        assert!(unsafe { glXChooseFBConfig(std::ptr::null_mut(), 0, std::ptr::null(), &mut n) }.is_null());
        assert_eq!(n, 0);
        assert_eq!(glXMakeCurrent(std::ptr::null_mut(), 0, std::ptr::null_mut()), TRUE);
        assert_eq!(glXMakeCurrent(std::ptr::null_mut(), 5, 0x1234 as GLXContext), FALSE);
        // SAFETY: a NUL-terminated name.
        assert!(unsafe { glXGetProcAddress(c"glClear".as_ptr().cast()) }.is_some());
        // SAFETY: a NUL-terminated name.
        assert!(unsafe { glXGetProcAddressARB(c"glXCreateContextAttribsARB".as_ptr().cast()) }.is_some());
        // SAFETY: a NUL-terminated name.
        assert!(unsafe { glXGetProcAddress(c"glNoSuchFunction".as_ptr().cast()) }.is_none());
    }
}
