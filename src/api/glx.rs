//! The GLX 1.4 entry points of `<GL/glx.h>` (and the GLX extensions tessera advertises).
//!
//! They forward to `winsys::glx`, which talks to the X server through the application's own
//! `Display*` with a run-time loaded Xlib. Contexts and configurations given to C are
//! identifiers looked up in registries there, never dereferenced, so a NULL, stale or forged
//! handle is refused. Where GLX says a call generates an X protocol error (BadMatch,
//! GLXBadContext, GLXBadDrawable, ...), the application's X error handler receives it
//! (`winsys::glx_error`), besides the call's return value.
//!
//! Arrays returned to the caller (GLXFBConfig lists, XVisualInfo) come from malloc or from
//! Xlib, so the caller frees them with XFree as usual.
//!
//! These prototypes need the X types of `<GL/glx.h>`, so they stay out of `tessera.h`
//! (`cbindgen:ignore` on the module in `api/mod.rs`).
// XIDs and visual ids are C `unsigned long`, kept as u64 inside: the casts are no-ops only
// where `unsigned long` is 64 bits.
#![allow(clippy::unnecessary_cast)]
use super::caller_memory;
use super::guard;
use crate::context::strings;
use crate::gl::glx::*;
use crate::gl::types::*;
use crate::winsys::glx::{self as glx, DisplayAddr, DrawableKind, MakeCurrentError};
use crate::winsys::glx_config::*;
use crate::winsys::glx_error::{self as xerr, request, GlxError};
use crate::winsys::notice;
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

const VENDOR: &CStr = c"tessera project";
const VERSION: &CStr = c"1.4";
/// The GLX extensions whose every entry point and token works.
const EXTENSIONS: &CStr = c"GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address GLX_EXT_swap_control GLX_MESA_swap_control GLX_SGI_swap_control";

fn addr(display: *mut Display) -> DisplayAddr {
    display as DisplayAddr
}

/// Reports a GLX error (X protocol error) about `resource` for the request `minor`.
fn report(display: *mut Display, error: GlxError, resource: u64, minor: u8) {
    xerr::report(addr(display), error, resource, minor);
}

/// Reads a zero-terminated attribute list (pairs unless `singles`, for glXChooseVisual).
///
/// # Safety
/// `list` must be NULL or zero-terminated as the GLX calls require.
unsafe fn attribute_list(list: *const c_int, singles: bool) -> Vec<i32> {
    let step = |attribute| {
        let boolean = singles && matches!(attribute, GLX_USE_GL | GLX_RGBA | GLX_DOUBLEBUFFER | GLX_STEREO);
        // A non-boolean attribute is followed by its value.
        if boolean {
            1
        } else {
            2
        }
    };
    // SAFETY: the list is NULL or terminated by None (0), as the contract says.
    unsafe { caller_memory::read_terminated(list, 0, step) }
}

/// A malloc'ed array of configuration handles (freed by the caller with XFree).
///
/// # Safety
/// `count` must be NULL or writable.
unsafe fn config_array(configs: &[&'static FbConfig], count: *mut c_int) -> *mut GLXFBConfig {
    // SAFETY: the caller's out-parameter, or NULL.
    unsafe { caller_memory::write(count, 0) };
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
    // SAFETY: the caller's out-parameter, or NULL.
    unsafe { caller_memory::write(count, configs.len() as c_int) };
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
    if display.is_null() {
        return None;
    }
    // SAFETY: the caller passes an XVisualInfo, or NULL.
    let visual_id = unsafe { caller_memory::read_at(vis, 0) }?.visualid as u64;
    glx::config_for_visual(addr(display), visual_id)
}

fn set<T>(out: *mut T, value: T) {
    // SAFETY: an out-parameter of the caller, or NULL (the contracts of the GLX calls that
    // use this).
    unsafe { caller_memory::write(out, value) }
}

/// # Safety
/// `errorBase`/`eventBase` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryExtension(dpy: *mut Display, errorBase: *mut c_int, eventBase: *mut c_int) -> Bool {
    guard(FALSE, || {
        if dpy.is_null() || glx::xlib().is_none() {
            return FALSE;
        }
        // tessera renders without the server's GLX; its codes are given when it has one,
        // and its error names are registered with Xlib for the errors tessera reports.
        let (_, event, error) = glx::server_extension(addr(dpy), c"GLX").unwrap_or((0, 0, 0));
        xerr::register_error_names(addr(dpy));
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
        let criteria = match Criteria::visual(&list) {
            Ok(criteria) => criteria,
            Err(bad) => {
                refuse_criteria("glXChooseVisual", bad);
                return std::ptr::null_mut();
            }
        };
        match criteria.choose(glx::configs(addr(dpy)), screen).first() {
            Some(config) => glx::visual_info(addr(dpy), config),
            None => {
                refuse_unmatched("glXChooseVisual", &list, true, screen);
                std::ptr::null_mut()
            }
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
        // SAFETY: forwarded contract.
        let visual = unsafe { describe_visual(vis) };
        guard((), || {
            refuse_visual("glXCreateContext", visual);
            report(dpy, xerr::BAD_VALUE, 0, request::CREATE_CONTEXT)
        });
        return std::ptr::null_mut();
    };
    guard(std::ptr::null_mut(), || new_context(dpy, config, shareList, request::CREATE_CONTEXT))
}

/// Creates a context sharing with `share` (GLXBadContext when it is not a context).
fn new_context(dpy: *mut Display, config: &'static FbConfig, share: GLXContext, minor: u8) -> GLXContext {
    if !share.is_null() && glx::lookup_context(share as usize).is_none() {
        notice::once("glx-share-context", || {
            format!("a GLX context was to share objects with {share:p}, which is not a live tessera context")
        });
        report(dpy, xerr::GLX_BAD_CONTEXT, share as u64, minor);
        return std::ptr::null_mut();
    }
    let handle = glx::create_context(addr(dpy), config, share as usize);
    if handle.is_none() {
        report(dpy, xerr::BAD_ALLOC, 0, minor);
    }
    context_handle(handle)
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
            refuse_config("glXCreateNewContext", config);
            report(dpy, xerr::GLX_BAD_FBCONFIG, config as u64, request::CREATE_NEW_CONTEXT);
            return std::ptr::null_mut();
        };
        if renderType != GLX_RGBA_TYPE {
            notice::once("glx-color-index", || {
                format!("glXCreateNewContext asked for render type {renderType:#x}; tessera renders RGBA only (GLX_RGBA_TYPE)")
            });
            // Color index is a valid type no configuration supports: BadMatch.
            let error = if renderType == GLX_COLOR_INDEX_TYPE { xerr::BAD_MATCH } else { xerr::BAD_VALUE };
            report(dpy, error, 0, request::CREATE_NEW_CONTEXT);
            return std::ptr::null_mut();
        }
        new_context(dpy, config, shareList, request::CREATE_NEW_CONTEXT)
    })
}

/// What a glXCreateContextAttribsARB call asked for, for the refusal notices: e.g.
/// "OpenGL 3.3 core profile, forward-compatible".
fn describe_attribs(major: i32, minor: i32, profile: Option<c_int>, flags: c_int) -> String {
    let mut text = format!("OpenGL {major}.{minor}");
    match profile {
        Some(GLX_CONTEXT_CORE_PROFILE_BIT_ARB) => text.push_str(" core profile"),
        Some(GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB) => text.push_str(" compatibility profile"),
        Some(other) => text.push_str(&format!(" profile mask {other:#x}")),
        None => {}
    }
    let named = [
        (GLX_CONTEXT_DEBUG_BIT_ARB, "debug"),
        (GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB, "forward-compatible"),
        (GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB, "robust access"),
    ];
    for (bit, name) in named {
        if flags & bit != 0 {
            text.push_str(", ");
            text.push_str(name);
        }
    }
    let unknown = flags & !named.iter().fold(0, |m, (bit, _)| m | bit);
    if unknown != 0 {
        text.push_str(&format!(", flags {unknown:#x}"));
    }
    text
}

/// Prints the one-line notice of a refused glXCreateContextAttribsARB (once per `reason`).
fn refuse_attribs(reason: &str, asked: &str, why: &str) {
    notice::once(reason, || {
        format!(
            "glXCreateContextAttribsARB asked for {asked}; tessera provides {}{why}",
            strings::provided_description()
        )
    });
}

/// GLX_ARB_create_context(_profile): compatibility contexts of the versions that work. A
/// core profile is only meaningful from 3.2, which tessera does not reach; below 3.2 the
/// profile mask is ignored as the extension says. A refusal reports its X error and prints
/// one notice line naming what was asked and what tessera provides.
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
    const MINOR: u8 = request::CREATE_CONTEXT_ATTRIBS_ARB;
    guard(std::ptr::null_mut(), || {
        let Some(config) = config_of(dpy, config) else {
            refuse_config("glXCreateContextAttribsARB", config);
            report(dpy, xerr::GLX_BAD_FBCONFIG, config as u64, MINOR);
            return std::ptr::null_mut();
        };
        let (mut major, mut minor, mut flags, mut profile) = (1, 0, 0, None);
        for pair in list.chunks(2) {
            let value = pair.get(1).copied().unwrap_or(0);
            match pair[0] {
                GLX_CONTEXT_MAJOR_VERSION_ARB => major = value,
                GLX_CONTEXT_MINOR_VERSION_ARB => minor = value,
                GLX_CONTEXT_FLAGS_ARB => flags = value,
                GLX_CONTEXT_PROFILE_MASK_ARB => profile = Some(value),
                GLX_RENDER_TYPE if value == GLX_RGBA_TYPE => {}
                GLX_CONTEXT_RESET_NOTIFICATION_STRATEGY_ARB if value == GLX_NO_RESET_NOTIFICATION_ARB => {}
                GLX_RENDER_TYPE => {
                    notice::once("glx-color-index", || {
                        "glXCreateContextAttribsARB asked for a color-index context; tessera renders RGBA only"
                            .to_string()
                    });
                    report(dpy, xerr::BAD_MATCH, 0, MINOR);
                    return std::ptr::null_mut();
                }
                other => {
                    notice::once("glx-context-attribute", || {
                        format!(
                            "glXCreateContextAttribsARB was given attribute {other:#x} = {value:#x}, which tessera \
                             does not support (it takes the version, profile, flags and render type)"
                        )
                    });
                    report(dpy, xerr::BAD_VALUE, 0, MINOR);
                    return std::ptr::null_mut();
                }
            }
        }
        let asked = || describe_attribs(major, minor, profile, flags);
        // GLX_ARB_create_context: an unknown flag is BadValue; the forward-compatible flag
        // below 3.0 and the robust-access flag (not advertised) are BadMatch; the debug flag
        // changes nothing.
        const KNOWN_FLAGS: c_int =
            GLX_CONTEXT_DEBUG_BIT_ARB | GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB | GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB;
        if flags & !KNOWN_FLAGS != 0 {
            refuse_attribs("glx-context-flags", &asked(), " and knows no such flag");
            report(dpy, xerr::BAD_VALUE, 0, MINOR);
            return std::ptr::null_mut();
        }
        let supported = strings::supports_version(major, minor);
        if flags & !GLX_CONTEXT_DEBUG_BIT_ARB != 0 {
            let why = if supported { ", without forward-compatible or robust-access contexts" } else { "" };
            refuse_attribs("glx-context-flags", &asked(), why);
            report(dpy, xerr::BAD_MATCH, 0, MINOR);
            return std::ptr::null_mut();
        }
        let profile_mask = profile.unwrap_or(GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB);
        let profile_valid = profile_mask == GLX_CONTEXT_CORE_PROFILE_BIT_ARB
            || profile_mask == GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB;
        if (major, minor) >= (3, 2) && !profile_valid {
            refuse_attribs("glx-context-profile", &asked(), "");
            report(dpy, GlxError::Glx(GLX_BAD_PROFILE_ARB), 0, MINOR);
            return std::ptr::null_mut();
        }
        if !supported {
            // A version no configuration provides: GLXBadFBConfig (as Mesa; BadMatch for
            // versions that do not exist at all).
            let exists = (major == 1 && (0..=5).contains(&minor))
                || (major == 2 && (0..=1).contains(&minor))
                || (major == 3 && (0..=3).contains(&minor))
                || (major == 4 && (0..=6).contains(&minor));
            refuse_attribs("glx-context-version", &asked(), "");
            let error = if exists { xerr::GLX_BAD_FBCONFIG } else { xerr::BAD_MATCH };
            report(dpy, error, 0, MINOR);
            return std::ptr::null_mut();
        }
        new_context(dpy, config, share_context, MINOR)
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyContext(dpy: *mut Display, ctx: GLXContext) {
    guard((), || {
        if glx::lookup_context(ctx as usize).is_none() {
            return report(dpy, xerr::GLX_BAD_CONTEXT, ctx as u64, request::DESTROY_CONTEXT);
        }
        glx::destroy_context(ctx as usize)
    })
}

fn make_current(dpy: *mut Display, draw: GLXDrawable, read: GLXDrawable, ctx: GLXContext, minor: u8) -> Bool {
    guard(FALSE, || {
        let (error, resource) = match glx::make_current(addr(dpy), draw as u64, read as u64, ctx as usize) {
            Ok(()) => return TRUE,
            Err(MakeCurrentError::BadContext) => (xerr::GLX_BAD_CONTEXT, ctx as u64),
            Err(MakeCurrentError::BadMatch) => (xerr::BAD_MATCH, 0),
            Err(MakeCurrentError::BadDrawable) => (xerr::GLX_BAD_DRAWABLE, draw as u64),
            Err(MakeCurrentError::BadAccess) => (xerr::BAD_ACCESS, ctx as u64),
        };
        refuse_make_current(dpy, draw, read, ctx, minor, error);
        report(dpy, error, resource, minor);
        FALSE
    })
}

#[no_mangle]
pub extern "C" fn glXMakeCurrent(dpy: *mut Display, drawable: GLXDrawable, ctx: GLXContext) -> Bool {
    make_current(dpy, drawable, drawable, ctx, request::MAKE_CURRENT)
}

#[no_mangle]
pub extern "C" fn glXMakeContextCurrent(
    dpy: *mut Display,
    draw: GLXDrawable,
    read: GLXDrawable,
    ctx: GLXContext,
) -> Bool {
    make_current(dpy, draw, read, ctx, request::MAKE_CONTEXT_CURRENT)
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
    guard((), || {
        let minor = request::COPY_CONTEXT;
        let (Some(s), Some(d)) = (glx::lookup_context(src as usize), glx::lookup_context(dst as usize)) else {
            let bad = if glx::lookup_context(src as usize).is_none() { src } else { dst };
            return report(dpy, xerr::GLX_BAD_CONTEXT, bad as u64, minor);
        };
        if !glx::copy_context(&s, &d, mask as u32) {
            // The same context, or a destination current to some thread.
            let error = if src == dst { xerr::BAD_MATCH } else { xerr::BAD_ACCESS };
            report(dpy, error, dst as u64, minor);
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
        let criteria = match Criteria::fbconfig(&list) {
            Ok(criteria) => criteria,
            Err(bad) => {
                refuse_criteria("glXChooseFBConfig", bad);
                return std::ptr::null_mut();
            }
        };
        let chosen = criteria.choose(glx::configs(addr(dpy)), screen);
        if chosen.is_empty() {
            refuse_unmatched("glXChooseFBConfig", &list, false, screen);
        }
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
    let minor = if kind == DrawableKind::Window { request::CREATE_WINDOW } else { request::CREATE_PIXMAP };
    guard(0, || {
        let Some(config) = config_of(dpy, config) else {
            report(dpy, xerr::GLX_BAD_FBCONFIG, config as u64, minor);
            return 0;
        };
        if glx::create_drawable(addr(dpy), xid as u64, kind, config) {
            xid
        } else {
            // Already a GLX drawable (BadAlloc, GLX 1.4 §3.3.4), or no X drawable at all
            // (XGetGeometry has reported that already), or out of memory.
            report(dpy, xerr::BAD_ALLOC, xid as u64, minor);
            0
        }
    })
}

/// Destroys the GLX drawable `xid` of `kind`; `error` when it is none of that kind.
fn destroy_drawable(dpy: *mut Display, xid: c_ulong, kind: DrawableKind, error: GlxError, minor: u8) {
    guard((), || {
        if glx::lookup_drawable(addr(dpy), xid as u64).is_none_or(|d| d.kind != kind || !d.explicit) {
            return report(dpy, error, xid as u64, minor);
        }
        glx::destroy_drawable(addr(dpy), xid as u64, kind)
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
    destroy_drawable(dpy, win, DrawableKind::Window, xerr::GLX_BAD_WINDOW, request::DESTROY_WINDOW)
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
    destroy_drawable(dpy, pixmap, DrawableKind::Pixmap, xerr::GLX_BAD_PIXMAP, request::DESTROY_PIXMAP)
}

/// # Safety
/// `visual` must be NULL or an XVisualInfo.
#[no_mangle]
pub unsafe extern "C" fn glXCreateGLXPixmap(dpy: *mut Display, visual: *mut XVisualInfo, pixmap: c_ulong) -> c_ulong {
    // SAFETY: forwarded contract.
    let config = guard(None, || unsafe { config_of_visual(dpy, visual) });
    let Some(config) = config else {
        guard((), || report(dpy, xerr::BAD_VALUE, 0, request::CREATE_GLX_PIXMAP));
        return 0;
    };
    guard(0, || {
        if glx::create_drawable(addr(dpy), pixmap as u64, DrawableKind::Pixmap, config) {
            pixmap
        } else {
            report(dpy, xerr::BAD_ALLOC, pixmap as u64, request::CREATE_GLX_PIXMAP);
            0
        }
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyGLXPixmap(dpy: *mut Display, pixmap: c_ulong) {
    destroy_drawable(dpy, pixmap, DrawableKind::Pixmap, xerr::GLX_BAD_PIXMAP, request::DESTROY_GLX_PIXMAP)
}

/// # Safety
/// `attribList` must be NULL or a None-terminated attribute/value list.
#[no_mangle]
pub unsafe extern "C" fn glXCreatePbuffer(dpy: *mut Display, config: GLXFBConfig, attribList: *const c_int) -> c_ulong {
    // SAFETY: forwarded contract.
    let list = unsafe { attribute_list(attribList, false) };
    const MINOR: u8 = request::CREATE_PBUFFER;
    guard(0, || {
        let Some(config) = config_of(dpy, config) else {
            report(dpy, xerr::GLX_BAD_FBCONFIG, config as u64, MINOR);
            return 0;
        };
        let (mut width, mut height) = (0, 0);
        for pair in list.chunks(2) {
            let value = pair.get(1).copied().unwrap_or(0);
            match pair[0] {
                GLX_PBUFFER_WIDTH => width = value,
                GLX_PBUFFER_HEIGHT => height = value,
                // Other attributes are ignored, as Mesa does (GLX 1.4 names no error for them).
                _ => {}
            }
        }
        let max = crate::gl::limits::MAX_VIEWPORT_DIM;
        if !(0..=max).contains(&width) || !(0..=max).contains(&height) {
            report(dpy, xerr::BAD_ALLOC, 0, MINOR);
            return 0;
        }
        let pbuffer = glx::create_pbuffer(addr(dpy), config, width as usize, height as usize) as c_ulong;
        if pbuffer == 0 {
            report(dpy, xerr::BAD_ALLOC, 0, MINOR);
        }
        pbuffer
    })
}

#[no_mangle]
pub extern "C" fn glXDestroyPbuffer(dpy: *mut Display, pbuf: c_ulong) {
    destroy_drawable(dpy, pbuf, DrawableKind::Pbuffer, xerr::GLX_BAD_PBUFFER, request::DESTROY_PBUFFER)
}

/// # Safety
/// `value` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXQueryDrawable(dpy: *mut Display, draw: GLXDrawable, attribute: c_int, value: *mut c_uint) {
    guard((), || {
        let Some(drawable) = glx::lookup_drawable(addr(dpy), draw as u64) else {
            return report(dpy, xerr::GLX_BAD_DRAWABLE, draw as u64, request::GET_DRAWABLE_ATTRIBUTES);
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
    guard((), || match glx::lookup_drawable(addr(dpy), draw as u64) {
        Some(d) => d.event_mask.store(event_mask as u64, std::sync::atomic::Ordering::Relaxed),
        None => report(dpy, xerr::GLX_BAD_DRAWABLE, draw as u64, request::CHANGE_DRAWABLE_ATTRIBUTES),
    })
}

/// # Safety
/// `event_mask` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetSelectedEvent(dpy: *mut Display, draw: GLXDrawable, event_mask: *mut c_ulong) {
    guard((), || {
        let drawable = glx::lookup_drawable(addr(dpy), draw as u64);
        if drawable.is_none() {
            report(dpy, xerr::GLX_BAD_DRAWABLE, draw as u64, request::GET_DRAWABLE_ATTRIBUTES);
        }
        let mask = drawable.map_or(0, |d| d.event_mask.load(std::sync::atomic::Ordering::Relaxed));
        set(event_mask, mask as c_ulong);
    })
}

#[no_mangle]
pub extern "C" fn glXSwapBuffers(dpy: *mut Display, drawable: GLXDrawable) {
    guard((), || {
        if glx::lookup_drawable(addr(dpy), drawable as u64).is_none() {
            return report(dpy, xerr::GLX_BAD_DRAWABLE, drawable as u64, request::SWAP_BUFFERS);
        }
        glx::swap_buffers(addr(dpy), drawable as u64)
    })
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
    use super::gl_lists::{glEndList, glNewList};
    use super::gl_pixel_rect::glBitmap;
    use super::gl_pixels::glPixelStorei;
    use super::gl_state::glGetIntegerv;
    use crate::gl::enums::*;
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
    // SAFETY: NULL or NUL-terminated by the contract.
    let name = unsafe { caller_memory::c_str(procName.cast()) }?;
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

// ---------------------------------------------------------------------------------------------
// Refusal notices (winsys::notice): one line on stderr saying what was asked and what tessera
// provides, once per reason per process, silenced by TESSERA_QUIET=1.
// ---------------------------------------------------------------------------------------------

/// A GLXFBConfig handle that is none of tessera's.
fn refuse_config(call: &str, handle: GLXFBConfig) {
    notice::once("glx-fbconfig", || {
        format!(
            "{call} was given GLXFBConfig {handle:p}, which is not one of tessera's configurations \
             (those of glXChooseFBConfig or glXGetFBConfigs)"
        )
    });
}

/// What a caller's XVisualInfo is, for messages: "visual 0x21 (depth 24, class 4)".
///
/// # Safety
/// `vis` must be NULL or point to an XVisualInfo.
unsafe fn describe_visual(vis: *const XVisualInfo) -> String {
    // SAFETY: the caller passes an XVisualInfo, or NULL.
    let Some(v) = (unsafe { caller_memory::read_at(vis, 0) }) else {
        return "no visual (NULL)".to_string();
    };
    format!("visual {:#x} (depth {}, class {})", v.visualid, v.depth, v.class)
}

/// A visual without configurations.
fn refuse_visual(call: &str, visual: String) {
    notice::once("glx-visual", || {
        format!(
            "{call} was given {visual}, which has no tessera configuration; tessera renders on \
             TrueColor and DirectColor visuals with 8-bit red, green and blue (see glXChooseVisual)"
        )
    });
}

/// An attribute list glXChooseVisual / glXChooseFBConfig does not accept.
fn refuse_criteria(call: &str, bad: BadAttribute) {
    notice::once("glx-choose-attribute", || match bad {
        BadAttribute::ColorIndex => {
            format!("{call} asked for a color-index visual (no GLX_RGBA); tessera renders RGBA only")
        }
        BadAttribute::Unknown(a) => format!("{call} was given attribute {a:#x}, which GLX does not define for it"),
    });
}

/// GLX attribute names, for messages.
fn attribute_name(attribute: c_int) -> Option<&'static str> {
    Some(match attribute {
        GLX_USE_GL => "GLX_USE_GL",
        GLX_BUFFER_SIZE => "GLX_BUFFER_SIZE",
        GLX_LEVEL => "GLX_LEVEL",
        GLX_RGBA => "GLX_RGBA",
        GLX_DOUBLEBUFFER => "GLX_DOUBLEBUFFER",
        GLX_STEREO => "GLX_STEREO",
        GLX_AUX_BUFFERS => "GLX_AUX_BUFFERS",
        GLX_RED_SIZE => "GLX_RED_SIZE",
        GLX_GREEN_SIZE => "GLX_GREEN_SIZE",
        GLX_BLUE_SIZE => "GLX_BLUE_SIZE",
        GLX_ALPHA_SIZE => "GLX_ALPHA_SIZE",
        GLX_DEPTH_SIZE => "GLX_DEPTH_SIZE",
        GLX_STENCIL_SIZE => "GLX_STENCIL_SIZE",
        GLX_ACCUM_RED_SIZE => "GLX_ACCUM_RED_SIZE",
        GLX_ACCUM_GREEN_SIZE => "GLX_ACCUM_GREEN_SIZE",
        GLX_ACCUM_BLUE_SIZE => "GLX_ACCUM_BLUE_SIZE",
        GLX_ACCUM_ALPHA_SIZE => "GLX_ACCUM_ALPHA_SIZE",
        GLX_CONFIG_CAVEAT => "GLX_CONFIG_CAVEAT",
        GLX_X_VISUAL_TYPE => "GLX_X_VISUAL_TYPE",
        GLX_TRANSPARENT_TYPE => "GLX_TRANSPARENT_TYPE",
        GLX_DRAWABLE_TYPE => "GLX_DRAWABLE_TYPE",
        GLX_RENDER_TYPE => "GLX_RENDER_TYPE",
        GLX_X_RENDERABLE => "GLX_X_RENDERABLE",
        GLX_FBCONFIG_ID => "GLX_FBCONFIG_ID",
        GLX_SAMPLE_BUFFERS => "GLX_SAMPLE_BUFFERS",
        GLX_SAMPLES => "GLX_SAMPLES",
        _ => return None,
    })
}

/// An attribute list no configuration satisfies: the list as asked, and what tessera's
/// configurations offer at most.
fn refuse_unmatched(call: &str, list: &[i32], singles: bool, screen: c_int) {
    notice::once("glx-choose-none", || {
        let mut asked = Vec::new();
        let mut i = 0;
        while i < list.len() {
            let a = list[i];
            let name = attribute_name(a).map_or_else(|| format!("{a:#x}"), str::to_string);
            let boolean = singles && matches!(a, GLX_USE_GL | GLX_RGBA | GLX_DOUBLEBUFFER | GLX_STEREO);
            match list.get(i + 1) {
                Some(v) if !boolean => {
                    asked.push(format!("{name} {v}"));
                    i += 1;
                }
                _ => asked.push(name),
            }
            i += 1;
        }
        format!(
            "{call} found no configuration on screen {screen} for [{}]; tessera's configurations have \
             8-bit red, green, blue (alpha 0 or 8), depth 0/16/24, stencil 0/8, accumulation 0/16, \
             0/2/4/8 samples, stereo, no auxiliary buffers, level 0, on TrueColor/DirectColor visuals \
             of 8-bit channels",
            asked.join(", ")
        )
    });
}

/// A refused glXMakeCurrent / glXMakeContextCurrent.
fn refuse_make_current(
    dpy: *mut Display,
    draw: GLXDrawable,
    read: GLXDrawable,
    ctx: GLXContext,
    minor: u8,
    error: GlxError,
) {
    let call = if minor == request::MAKE_CURRENT { "glXMakeCurrent" } else { "glXMakeContextCurrent" };
    let (reason, message) = if error == xerr::GLX_BAD_CONTEXT {
        ("glx-make-current-context", format!("{call} was given {ctx:p}, which is not a live tessera GLX context"))
    } else if error == xerr::BAD_ACCESS {
        (
            "glx-make-current-thread",
            format!(
                "{call}: context {ctx:p} is current in another thread; a context is current in one thread at a time"
            ),
        )
    } else if error == xerr::GLX_BAD_DRAWABLE {
        (
            "glx-make-current-drawable",
            format!("{call} was given drawable {draw:#x}, which is no window, GLX pixmap or pbuffer of this display"),
        )
    } else if ctx.is_null() {
        (
            "glx-make-current-match",
            format!("{call} was given drawable {draw:#x} without a context (None needs no context and no drawable)"),
        )
    } else if draw == 0 || read == 0 {
        ("glx-make-current-match", format!("{call} was given context {ctx:p} without a drawable; tessera needs a window, pixmap or pbuffer to make a context current"))
    } else {
        let context_config = glx::lookup_context(ctx as usize).map_or(0, |c| c.config.id);
        let drawable_config =
            |xid: GLXDrawable| glx::lookup_drawable(addr(dpy), xid as u64).map_or(0, |d| d.config().id);
        let (d, r) = (drawable_config(draw), drawable_config(read));
        let culprit = if d != context_config { (draw, d) } else { (read, r) };
        (
            "glx-make-current-match",
            format!(
                "{call}: drawable {:#x} was created for GLXFBConfig id {}, the context for id {context_config}, \
                 and their buffers differ; create both from the same configuration",
                culprit.0, culprit.1
            ),
        )
    };
    notice::once(reason, || message);
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
    fn refused_context_requests_are_described() {
        let core = Some(GLX_CONTEXT_CORE_PROFILE_BIT_ARB);
        assert_eq!(describe_attribs(3, 3, core, 0), "OpenGL 3.3 core profile");
        assert_eq!(
            describe_attribs(3, 2, core, GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB | GLX_CONTEXT_DEBUG_BIT_ARB),
            "OpenGL 3.2 core profile, debug, forward-compatible"
        );
        assert_eq!(describe_attribs(2, 1, None, 0x40), "OpenGL 2.1, flags 0x40");
        assert_eq!(
            describe_attribs(1, 0, Some(GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB), GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB),
            "OpenGL 1.0 compatibility profile, robust access"
        );
        assert_eq!(describe_attribs(3, 2, Some(0x40), 0), "OpenGL 3.2 profile mask 0x40");
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
