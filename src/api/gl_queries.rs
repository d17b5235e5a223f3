//! Occlusion query entry points (GL 1.5 and ARB_occlusion_query). glBeginQuery and
//! glEndQuery are compiled into display lists; the others always execute.
use super::caller_memory;
use super::{record_or_run, with_context};
use crate::gl::enums::*;
use crate::gl::types::*;

/// # Safety
/// `ids` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenQueries(n: GLsizei, ids: *mut GLuint) {
    with_context((), |ctx| {
        if let Some(names) = ctx.gen_queries(n) {
            // SAFETY: the caller provides room for `n` names at `ids` (or passes NULL).
            unsafe { caller_memory::write_all(ids, names) }
        }
    })
}

/// # Safety
/// `ids` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteQueries(n: GLsizei, ids: *const GLuint) {
    // SAFETY: the caller passes `n` names at `ids`.
    let names = unsafe { caller_memory::read_array(ids, n) };
    with_context((), |ctx| ctx.delete_queries(n, &names))
}

#[no_mangle]
pub extern "C" fn glIsQuery(id: GLuint) -> GLboolean {
    with_context(GL_FALSE, |ctx| if ctx.is_query(id) { GL_TRUE } else { GL_FALSE })
}

#[no_mangle]
pub extern "C" fn glBeginQuery(target: GLenum, id: GLuint) {
    record_or_run(move |ctx| ctx.begin_query(target, id))
}

#[no_mangle]
pub extern "C" fn glEndQuery(target: GLenum) {
    record_or_run(move |ctx| ctx.end_query(target))
}

/// # Safety
/// `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetQueryiv(target: GLenum, pname: GLenum, params: *mut GLint) {
    if let Some(value) = with_context(None, |ctx| ctx.get_query(target, pname)) {
        // SAFETY: the caller provides room for one value (or passes NULL).
        unsafe { caller_memory::write(params, value) }
    }
}

/// # Safety
/// `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetQueryObjectiv(id: GLuint, pname: GLenum, params: *mut GLint) {
    if let Some(value) = with_context(None, |ctx| ctx.get_query_object(id, pname)) {
        // SAFETY: the caller provides room for one value (or passes NULL).
        unsafe { caller_memory::write(params, value.min(i32::MAX as u64) as GLint) }
    }
}

/// # Safety
/// `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetQueryObjectuiv(id: GLuint, pname: GLenum, params: *mut GLuint) {
    if let Some(value) = with_context(None, |ctx| ctx.get_query_object(id, pname)) {
        // SAFETY: the caller provides room for one value (or passes NULL).
        unsafe { caller_memory::write(params, value.min(u32::MAX as u64) as GLuint) }
    }
}

/// # Safety
/// As [`glGenQueries`].
#[no_mangle]
pub unsafe extern "C" fn glGenQueriesARB(n: GLsizei, ids: *mut GLuint) {
    // SAFETY: the same contract as the core function.
    unsafe { glGenQueries(n, ids) }
}

/// # Safety
/// As [`glDeleteQueries`].
#[no_mangle]
pub unsafe extern "C" fn glDeleteQueriesARB(n: GLsizei, ids: *const GLuint) {
    // SAFETY: the same contract as the core function.
    unsafe { glDeleteQueries(n, ids) }
}

#[no_mangle]
pub extern "C" fn glIsQueryARB(id: GLuint) -> GLboolean {
    glIsQuery(id)
}

#[no_mangle]
pub extern "C" fn glBeginQueryARB(target: GLenum, id: GLuint) {
    glBeginQuery(target, id)
}

#[no_mangle]
pub extern "C" fn glEndQueryARB(target: GLenum) {
    glEndQuery(target)
}

/// # Safety
/// As [`glGetQueryiv`].
#[no_mangle]
pub unsafe extern "C" fn glGetQueryivARB(target: GLenum, pname: GLenum, params: *mut GLint) {
    // SAFETY: the same contract as the core function.
    unsafe { glGetQueryiv(target, pname, params) }
}

/// # Safety
/// As [`glGetQueryObjectiv`].
#[no_mangle]
pub unsafe extern "C" fn glGetQueryObjectivARB(id: GLuint, pname: GLenum, params: *mut GLint) {
    // SAFETY: the same contract as the core function.
    unsafe { glGetQueryObjectiv(id, pname, params) }
}

/// # Safety
/// As [`glGetQueryObjectuiv`].
#[no_mangle]
pub unsafe extern "C" fn glGetQueryObjectuivARB(id: GLuint, pname: GLenum, params: *mut GLuint) {
    // SAFETY: the same contract as the core function.
    unsafe { glGetQueryObjectuiv(id, pname, params) }
}
