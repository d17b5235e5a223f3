//! Entry points for buffer objects (GL 1.5) and their ARB_vertex_buffer_object aliases.
use super::caller_memory;
use super::{guard, with_context};
use crate::gl::types::*;

/// # Safety
/// `buffers` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenBuffers(n: GLsizei, buffers: *mut GLuint) {
    let names = guard(None, || crate::context::current::with_current(|ctx| ctx.gen_buffers(n)).flatten());
    if let Some(names) = names {
        // SAFETY: the caller provides room for `n` names (or passes NULL), and `names` holds `n`.
        unsafe { caller_memory::write_all(buffers, names) }
    }
}

/// # Safety
/// `buffers` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteBuffers(n: GLsizei, buffers: *const GLuint) {
    // SAFETY: the caller provides `n` names at `buffers`.
    let names = unsafe { caller_memory::read_array(buffers, n) };
    with_context((), |ctx| ctx.delete_buffers(n, &names))
}

#[no_mangle]
pub extern "C" fn glBindBuffer(target: GLenum, buffer: GLuint) {
    with_context((), |ctx| ctx.bind_buffer(target, buffer))
}

#[no_mangle]
pub extern "C" fn glIsBuffer(buffer: GLuint) -> GLboolean {
    with_context(0, |ctx| ctx.is_buffer(buffer) as GLboolean)
}

/// # Safety
/// A non-null `data` must point to `size` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glBufferData(target: GLenum, size: GLsizeiptr, data: *const GLvoid, usage: GLenum) {
    with_context((), |ctx| {
        ctx.buffer_data(target, size, usage, |len| {
            // SAFETY: called with the validated `size`; the caller provides that many bytes.
            unsafe { caller_memory::bytes(data, 0..len) }
        })
    })
}

/// # Safety
/// `data` must point to `size` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glBufferSubData(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *const GLvoid) {
    with_context((), |ctx| {
        ctx.buffer_sub_data(target, offset, size, |len| {
            // SAFETY: called with the validated `size`; the caller provides that many bytes.
            unsafe { caller_memory::bytes(data, 0..len) }
        })
    })
}

/// # Safety
/// `data` must have room for `size` bytes.
#[no_mangle]
pub unsafe extern "C" fn glGetBufferSubData(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *mut GLvoid) {
    with_context((), |ctx| {
        ctx.get_buffer_sub_data(target, offset, size, |len| {
            // SAFETY: called with the validated `size`; the caller provides room for that many
            // bytes, which nothing else accesses during the call.
            unsafe { caller_memory::bytes_mut(data, 0..len) }
        })
    })
}

#[no_mangle]
pub extern "C" fn glMapBuffer(target: GLenum, access: GLenum) -> *mut GLvoid {
    with_context(std::ptr::null_mut(), |ctx| ctx.map_buffer(target, access)) as *mut GLvoid
}

#[no_mangle]
pub extern "C" fn glUnmapBuffer(target: GLenum) -> GLboolean {
    with_context(0, |ctx| ctx.unmap_buffer(target) as GLboolean)
}

/// # Safety
/// `params` must have room for one value (NULL writes nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetBufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    if let Some(value) = with_context(None, |ctx| ctx.get_buffer_parameter(target, pname)) {
        // SAFETY: the caller provides room for one value (or passes NULL).
        unsafe { caller_memory::write(params, value) }
    }
}

/// # Safety
/// `params` must have room for one pointer (NULL writes nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetBufferPointerv(target: GLenum, pname: GLenum, params: *mut *mut GLvoid) {
    if let Some(pointer) = with_context(None, |ctx| ctx.get_buffer_pointer(target, pname)) {
        // SAFETY: the caller provides room for one pointer (or passes NULL).
        unsafe { caller_memory::write(params, pointer as *mut GLvoid) }
    }
}

/// # Safety
/// As [`glGenBuffers`].
#[no_mangle]
pub unsafe extern "C" fn glGenBuffersARB(n: GLsizei, buffers: *mut GLuint) {
    // SAFETY: the same contract as the core function.
    unsafe { glGenBuffers(n, buffers) }
}

/// # Safety
/// As [`glDeleteBuffers`].
#[no_mangle]
pub unsafe extern "C" fn glDeleteBuffersARB(n: GLsizei, buffers: *const GLuint) {
    // SAFETY: the same contract as the core function.
    unsafe { glDeleteBuffers(n, buffers) }
}

#[no_mangle]
pub extern "C" fn glBindBufferARB(target: GLenum, buffer: GLuint) {
    glBindBuffer(target, buffer)
}

#[no_mangle]
pub extern "C" fn glIsBufferARB(buffer: GLuint) -> GLboolean {
    glIsBuffer(buffer)
}

/// # Safety
/// As [`glBufferData`].
#[no_mangle]
pub unsafe extern "C" fn glBufferDataARB(target: GLenum, size: GLsizeiptr, data: *const GLvoid, usage: GLenum) {
    // SAFETY: the same contract as the core function.
    unsafe { glBufferData(target, size, data, usage) }
}

/// # Safety
/// As [`glBufferSubData`].
#[no_mangle]
pub unsafe extern "C" fn glBufferSubDataARB(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *const GLvoid) {
    // SAFETY: the same contract as the core function.
    unsafe { glBufferSubData(target, offset, size, data) }
}

/// # Safety
/// As [`glGetBufferSubData`].
#[no_mangle]
pub unsafe extern "C" fn glGetBufferSubDataARB(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *mut GLvoid) {
    // SAFETY: the same contract as the core function.
    unsafe { glGetBufferSubData(target, offset, size, data) }
}

#[no_mangle]
pub extern "C" fn glMapBufferARB(target: GLenum, access: GLenum) -> *mut GLvoid {
    glMapBuffer(target, access)
}

#[no_mangle]
pub extern "C" fn glUnmapBufferARB(target: GLenum) -> GLboolean {
    glUnmapBuffer(target)
}

/// # Safety
/// As [`glGetBufferParameteriv`].
#[no_mangle]
pub unsafe extern "C" fn glGetBufferParameterivARB(target: GLenum, pname: GLenum, params: *mut GLint) {
    // SAFETY: the same contract as the core function.
    unsafe { glGetBufferParameteriv(target, pname, params) }
}

/// # Safety
/// As [`glGetBufferPointerv`].
#[no_mangle]
pub unsafe extern "C" fn glGetBufferPointervARB(target: GLenum, pname: GLenum, params: *mut *mut GLvoid) {
    // SAFETY: the same contract as the core function.
    unsafe { glGetBufferPointerv(target, pname, params) }
}
