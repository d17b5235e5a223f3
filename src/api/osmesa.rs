//! The OSMesa entry points of Mesa's `<GL/osmesa.h>`.
//!
//! Handles given to C are identifiers looked up in the registry of `winsys::osmesa`, never
//! dereferenced, so a NULL, stale or foreign handle is refused instead of crashing.
use super::caller_memory;
use super::guard;
use crate::context::strings;
use crate::framebuffer::external::CallerBuffer;
use crate::gl::enums::*;
use crate::gl::types::*;
use crate::winsys::notice;
use crate::winsys::osmesa::{self as osm, BindFailure, PixelLayout, Request};
use std::ffi::{c_char, c_int, c_uint, c_void};

use crate::gl::osmesa::*;

fn handle_of(ctx: OSMesaContext) -> usize {
    ctx as usize
}

fn to_c(handle: Option<usize>) -> OSMesaContext {
    handle.map_or(std::ptr::null_mut(), |h| h as OSMesaContext)
}

fn share_handle(sharelist: OSMesaContext) -> Option<usize> {
    (!sharelist.is_null()).then(|| handle_of(sharelist))
}

/// The OSMesa formats tessera provides, as a refusal notice names them.
const FORMATS: &str = "OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR and OSMESA_RGB_565";

/// OSMesaCreateContext(Ext/Attribs) after their own checks; `entry` names the entry point
/// in a refusal notice.
fn create(
    entry: &str,
    format: GLenum,
    depth: GLint,
    stencil: GLint,
    accum: GLint,
    sharelist: OSMesaContext,
) -> OSMesaContext {
    guard(std::ptr::null_mut(), || {
        let Some(layout) = PixelLayout::from_osmesa(format) else {
            notice::once("osmesa-format", || {
                format!("{entry} asked for pixel format {}; tessera provides {FORMATS}", osmesa_format_name(format))
            });
            return std::ptr::null_mut();
        };
        if depth < 0 || stencil < 0 || accum < 0 {
            notice::once("osmesa-buffer-sizes", || {
                format!(
                    "{entry} asked for {depth} depth, {stencil} stencil and {accum} accumulation bits; \
                     tessera provides any size from 0 (depth up to 32 bits, stencil 8, accumulation 16 per channel)"
                )
            });
            return std::ptr::null_mut();
        }
        let request = Request { layout, depth_bits: depth, stencil_bits: stencil, accum_bits: accum };
        to_c(osm::create(request, share_handle(sharelist)))
    })
}

/// The name of a format tessera does not provide, for a notice (its number when OSMesa has
/// no name for it).
fn osmesa_format_name(format: GLenum) -> String {
    match format {
        OSMESA_COLOR_INDEX => "OSMESA_COLOR_INDEX".into(),
        other => format!("0x{other:x}"),
    }
}

#[no_mangle]
pub extern "C" fn OSMesaCreateContext(format: GLenum, sharelist: OSMesaContext) -> OSMesaContext {
    create("OSMesaCreateContext", format, 24, 8, 0, sharelist)
}

#[no_mangle]
pub extern "C" fn OSMesaCreateContextExt(
    format: GLenum,
    depthBits: GLint,
    stencilBits: GLint,
    accumBits: GLint,
    sharelist: OSMesaContext,
) -> OSMesaContext {
    create("OSMesaCreateContextExt", format, depthBits, stencilBits, accumBits, sharelist)
}

/// # Safety
/// `attribList` must be NULL or a zero-terminated list of attribute/value pairs.
#[no_mangle]
pub unsafe extern "C" fn OSMesaCreateContextAttribs(
    attribList: *const c_int,
    sharelist: OSMesaContext,
) -> OSMesaContext {
    let mut format = OSMESA_RGBA;
    // <GL/osmesa.h>: depth, stencil and accum bits default to 0 here (unlike OSMesaCreateContext).
    let (mut depth, mut stencil, mut accum) = (0, 0, 0);
    let mut profile = OSMESA_COMPAT_PROFILE;
    let (mut major, mut minor) = (1, 0);
    if !attribList.is_null() {
        let mut i = 0;
        // SAFETY: the list is zero-terminated; we read pairs until the terminator.
        while let Some(attr) = (unsafe { caller_memory::read_at(attribList, i) }).filter(|&a| a != 0) {
            // SAFETY: a non-terminator attribute is followed by its value.
            let value = unsafe { caller_memory::read_at(attribList, i + 1) }.unwrap_or_default();
            match attr {
                a if a == OSMESA_FORMAT => format = value as GLenum,
                OSMESA_DEPTH_BITS => depth = value,
                OSMESA_STENCIL_BITS => stencil = value,
                OSMESA_ACCUM_BITS => accum = value,
                OSMESA_PROFILE => profile = value,
                OSMESA_CONTEXT_MAJOR_VERSION => major = value,
                OSMESA_CONTEXT_MINOR_VERSION => minor = value,
                _ => {
                    notice::once("osmesa-attribute", || {
                        format!(
                            "OSMesaCreateContextAttribs was given attribute 0x{attr:x}, which tessera does not know; \
                             it knows OSMESA_FORMAT, OSMESA_DEPTH_BITS, OSMESA_STENCIL_BITS, OSMESA_ACCUM_BITS, \
                             OSMESA_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION and OSMESA_CONTEXT_MINOR_VERSION"
                        )
                    });
                    return std::ptr::null_mut();
                }
            }
            i += 2;
        }
    }
    // Core profiles need shaders, which tessera does not have.
    if profile != OSMESA_COMPAT_PROFILE || !strings::supports_version(major, minor) {
        notice::once("osmesa-version", || {
            let asked = match profile {
                OSMESA_CORE_PROFILE => "core profile".to_string(),
                OSMESA_COMPAT_PROFILE => "compatibility profile".to_string(),
                other => format!("profile 0x{other:x}"),
            };
            format!(
                "OSMesaCreateContextAttribs asked for OpenGL {major}.{minor} {asked}; tessera provides {}",
                strings::provided_description()
            )
        });
        return std::ptr::null_mut();
    }
    create("OSMesaCreateContextAttribs", format, depth, stencil, accum, sharelist)
}

#[no_mangle]
pub extern "C" fn OSMesaDestroyContext(ctx: OSMesaContext) {
    guard((), || osm::destroy(handle_of(ctx)))
}

/// # Safety
/// `buffer` must be NULL or hold `width × height` pixels of `type` in the context's format
/// (`OSMESA_ROW_LENGTH × height` once a row length is set), valid while the context is bound.
#[no_mangle]
pub unsafe extern "C" fn OSMesaMakeCurrent(
    ctx: OSMesaContext,
    buffer: *mut c_void,
    type_: GLenum,
    width: GLsizei,
    height: GLsizei,
) -> GLboolean {
    guard(GL_FALSE, || {
        if ctx.is_null() && buffer.is_null() {
            osm::release_current();
            return GL_TRUE;
        }
        let Some(context) = osm::lookup(handle_of(ctx)) else {
            return GL_FALSE;
        };
        if buffer.is_null() || width < 1 || height < 1 {
            return GL_FALSE;
        }
        let bytes = context.required_bytes(type_, width as usize, height as usize);
        // SAFETY: by the OSMesa contract the caller's buffer holds width × height pixels of
        // `type_` (row_length × height once a row length is set) and outlives the binding.
        let caller = unsafe { CallerBuffer::new(buffer.cast(), bytes) };
        match context.make_current(caller, type_, width, height) {
            Ok(()) => GL_TRUE,
            Err(BindFailure::BadArguments | BindFailure::OutOfMemory | BindFailure::CurrentElsewhere) => GL_FALSE,
        }
    })
}

#[no_mangle]
pub extern "C" fn OSMesaGetCurrentContext() -> OSMesaContext {
    guard(std::ptr::null_mut(), || to_c(osm::current_handle()))
}

#[no_mangle]
pub extern "C" fn OSMesaPixelStore(pname: GLint, value: GLint) {
    guard((), || {
        let Some(context) = osm::current_context() else {
            return;
        };
        // SAFETY: by the OSMesa contract, a caller that sets a row length provides a buffer of
        // row_length × height pixels; the wrapper is rebuilt with that extent.
        let wrap = |ptr: *mut u8, len: usize| unsafe { CallerBuffer::new(ptr, len) };
        match pname {
            OSMESA_ROW_LENGTH if value >= 0 => context.pixel_store(Some(value as usize), None, wrap),
            OSMESA_Y_UP => context.pixel_store(None, Some(value != 0), wrap),
            OSMESA_ROW_LENGTH => record_error(GL_INVALID_VALUE),
            _ => record_error(GL_INVALID_ENUM),
        }
    })
}

/// Records a GL error on the current context (OSMesa reports its errors that way).
fn record_error(error: GLenum) {
    crate::context::current::with_current(|ctx| ctx.error(error));
}

/// # Safety
/// `value` must be NULL or point to a GLint.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetIntegerv(pname: GLint, value: *mut GLint) {
    let result = guard(None, || {
        let context = osm::current_context();
        let (width, height, ty) = context.as_ref().map_or((0, 0, 0), |c| c.bound_size());
        let (row_length, y_up) = context.as_ref().map_or((0, true), |c| c.row_length_and_y_up());
        Some(match pname {
            OSMESA_WIDTH => width as GLint,
            OSMESA_HEIGHT => height as GLint,
            OSMESA_FORMAT => context.as_ref().map_or(0, |c| c.request.layout.to_osmesa() as GLint),
            OSMESA_TYPE => ty as GLint,
            OSMESA_ROW_LENGTH => row_length as GLint,
            OSMESA_Y_UP => y_up as GLint,
            OSMESA_MAX_WIDTH | OSMESA_MAX_HEIGHT => crate::gl::limits::MAX_VIEWPORT_DIM,
            _ => {
                record_error(GL_INVALID_ENUM);
                return None;
            }
        })
    });
    if let Some(v) = result {
        // SAFETY: the caller passes a GLint to fill, or NULL.
        unsafe { caller_memory::write(value, v) }
    }
}

/// Writes `v` through `p` when `p` is not NULL.
///
/// # Safety
/// `p` must be NULL or valid for a write of `T`.
unsafe fn out<T>(p: *mut T, v: T) {
    // SAFETY: NULL or valid for writes by the function's contract.
    unsafe { caller_memory::write(p, v) }
}

/// # Safety
/// Each out-pointer must be NULL or valid for a write.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetDepthBuffer(
    c: OSMesaContext,
    width: *mut GLint,
    height: *mut GLint,
    bytesPerValue: *mut GLint,
    buffer: *mut *mut c_void,
) -> GLboolean {
    let found = guard(None, || osm::lookup(handle_of(c)).and_then(|ctx| ctx.depth_buffer()));
    let (w, h, bpv, address) = found.unwrap_or((0, 0, 0, 0));
    // SAFETY: each pointer is NULL or valid, per this function's contract.
    unsafe {
        out(width, w as GLint);
        out(height, h as GLint);
        out(bytesPerValue, bpv as GLint);
        out(buffer, address as *mut c_void);
    }
    found.is_some() as GLboolean
}

/// # Safety
/// Each out-pointer must be NULL or valid for a write.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetColorBuffer(
    c: OSMesaContext,
    width: *mut GLint,
    height: *mut GLint,
    format: *mut GLint,
    buffer: *mut *mut c_void,
) -> GLboolean {
    let found = guard(None, || {
        let ctx = osm::lookup(handle_of(c))?;
        let (address, w, h) = ctx.color_buffer()?;
        Some((w, h, ctx.request.layout.to_osmesa(), address))
    });
    let (w, h, f, address) = found.unwrap_or((0, 0, 0, 0));
    // SAFETY: each pointer is NULL or valid, per this function's contract.
    unsafe {
        out(width, w as GLint);
        out(height, h as GLint);
        out(format, f as GLint);
        out(buffer, address as *mut c_void);
    }
    found.is_some() as GLboolean
}

/// # Safety
/// `funcName` must be NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetProcAddress(funcName: *const c_char) -> OSMESAproc {
    // SAFETY: NULL or NUL-terminated by the contract.
    let name = unsafe { caller_memory::c_str(funcName) }?;
    guard(None, || super::procs::lookup(name.to_bytes()))
}

#[no_mangle]
pub extern "C" fn OSMesaColorClamp(enable: GLboolean) {
    let clamp = if enable != 0 { GL_TRUE as GLenum } else { GL_FIXED_ONLY };
    super::with_context((), |ctx| ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, clamp))
}

/// Mesa's post-processing filters (gallium's pp_* passes) are not implemented: the call is
/// refused honestly with a message, and rendering is unaffected.
///
/// # Safety
/// `filter` must be NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn OSMesaPostprocess(osmesa: OSMesaContext, filter: *const c_char, enable_value: c_uint) {
    let _ = (osmesa, enable_value);
    guard((), || {
        // SAFETY: NULL or NUL-terminated by the contract.
        let name = match unsafe { caller_memory::c_str(filter) } {
            None => String::from("(null)"),
            Some(name) => name.to_string_lossy().into_owned(),
        };
        eprintln!("tessera: OSMesaPostprocess filter '{name}' is not supported; rendering is unchanged");
    })
}
