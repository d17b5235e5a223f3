//! Entry points for capabilities, errors, queries, hints, attribute stacks and flushing.
use super::caller_memory;
use super::{guard, record_or_run, with_context};
use crate::gl::types::*;

#[no_mangle]
pub extern "C" fn glEnable(cap: GLenum) {
    record_or_run(move |ctx| ctx.set_capability(cap, true))
}

#[no_mangle]
pub extern "C" fn glDisable(cap: GLenum) {
    record_or_run(move |ctx| ctx.set_capability(cap, false))
}

#[no_mangle]
pub extern "C" fn glIsEnabled(cap: GLenum) -> GLboolean {
    with_context(0, |ctx| ctx.is_enabled(cap))
}

#[no_mangle]
pub extern "C" fn glEnablei(target: GLenum, index: GLuint) {
    record_or_run(move |ctx| ctx.set_capability_indexed(target, index, true))
}

#[no_mangle]
pub extern "C" fn glDisablei(target: GLenum, index: GLuint) {
    record_or_run(move |ctx| ctx.set_capability_indexed(target, index, false))
}

#[no_mangle]
pub extern "C" fn glIsEnabledi(target: GLenum, index: GLuint) -> GLboolean {
    with_context(0, |ctx| ctx.is_enabled_indexed(target, index))
}

#[no_mangle]
pub extern "C" fn glEnableIndexedEXT(target: GLenum, index: GLuint) {
    glEnablei(target, index)
}

#[no_mangle]
pub extern "C" fn glDisableIndexedEXT(target: GLenum, index: GLuint) {
    glDisablei(target, index)
}

#[no_mangle]
pub extern "C" fn glIsEnabledIndexedEXT(target: GLenum, index: GLuint) -> GLboolean {
    glIsEnabledi(target, index)
}

#[no_mangle]
pub extern "C" fn glGetError() -> GLenum {
    // Between glBegin and glEnd glGetError is itself GL_INVALID_OPERATION (and returns 0).
    with_context(0, |ctx| if ctx.check_outside_begin_end() { ctx.take_error() } else { 0 })
}

#[no_mangle]
pub extern "C" fn glGetString(name: GLenum) -> *const GLubyte {
    let s = with_context(None, |ctx| ctx.get_string(name));
    s.map_or(std::ptr::null(), |s| s.as_ptr())
}

#[no_mangle]
pub extern "C" fn glHint(target: GLenum, mode: GLenum) {
    record_or_run(move |ctx| ctx.hint(target, mode))
}

#[no_mangle]
pub extern "C" fn glClampColor(target: GLenum, clamp: GLenum) {
    record_or_run(move |ctx| ctx.clamp_color(target, clamp))
}

#[no_mangle]
pub extern "C" fn glClampColorARB(target: GLenum, clamp: GLenum) {
    glClampColor(target, clamp)
}

#[no_mangle]
pub extern "C" fn glFlush() {
    with_context((), |ctx| {
        if ctx.check_outside_begin_end() {
            ctx.flush()
        }
    })
}

#[no_mangle]
pub extern "C" fn glFinish() {
    with_context((), |ctx| {
        if ctx.check_outside_begin_end() {
            ctx.finish()
        }
    })
}

#[no_mangle]
pub extern "C" fn glPushAttrib(mask: GLbitfield) {
    record_or_run(move |ctx| ctx.push_attrib(mask))
}

#[no_mangle]
pub extern "C" fn glPopAttrib() {
    record_or_run(move |ctx| ctx.pop_attrib())
}

#[no_mangle]
pub extern "C" fn glPushClientAttrib(mask: GLbitfield) {
    with_context((), |ctx| ctx.push_client_attrib(mask))
}

#[no_mangle]
pub extern "C" fn glPopClientAttrib() {
    with_context((), |ctx| ctx.pop_client_attrib())
}

/// # Safety
/// `data` must have room for the values `pname` returns.
#[no_mangle]
pub unsafe extern "C" fn glGetBooleanv(pname: GLenum, data: *mut GLboolean) {
    let values = with_context_vec(|ctx| ctx.get_booleans(pname));
    // SAFETY: forwarded contract of this entry point.
    unsafe { caller_memory::write_all(data, values) }
}

/// # Safety
/// `data` must have room for the values `pname` returns.
#[no_mangle]
pub unsafe extern "C" fn glGetIntegerv(pname: GLenum, data: *mut GLint) {
    let values = with_context_vec(|ctx| ctx.get_integers(pname));
    // SAFETY: forwarded contract of this entry point.
    unsafe { caller_memory::write_all(data, values) }
}

/// # Safety
/// `data` must have room for the values `pname` returns.
#[no_mangle]
pub unsafe extern "C" fn glGetFloatv(pname: GLenum, data: *mut GLfloat) {
    let values = with_context_vec(|ctx| ctx.get_floats(pname));
    // SAFETY: forwarded contract of this entry point.
    unsafe { caller_memory::write_all(data, values) }
}

/// # Safety
/// `data` must have room for the values `pname` returns.
#[no_mangle]
pub unsafe extern "C" fn glGetDoublev(pname: GLenum, data: *mut GLdouble) {
    let values = with_context_vec(|ctx| ctx.get_doubles(pname));
    // SAFETY: forwarded contract of this entry point.
    unsafe { caller_memory::write_all(data, values) }
}

/// Runs a query returning a vector; empty when there is no context or the query failed.
fn with_context_vec<T>(f: impl FnOnce(&mut crate::context::Context) -> Option<Vec<T>>) -> Vec<T> {
    guard(Vec::new(), || crate::context::current::with_current(f).flatten().unwrap_or_default())
}
