//! Entry points for client vertex arrays and the draws that read them: glXxxPointer,
//! glEnable/DisableClientState, glClientActiveTexture, glInterleavedArrays, glGetPointerv,
//! glArrayElement, glDrawArrays, glDrawElements, glDrawRangeElements, glMultiDrawArrays and
//! glMultiDrawElements, with their EXT/ARB aliases (EXT_vertex_array's pointer commands take
//! a count that GL 1.1 dropped; it is ignored).
//!
//! Array pointers are recorded as addresses. Client memory is read only through
//! [`CallerMemory`], for the byte ranges the context computed from the draw's indices.
use super::caller_memory::{self, read_array, CallerMemory};
use super::with_context;
use crate::gl::types::*;

#[no_mangle]
pub extern "C" fn glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context((), |ctx| ctx.vertex_pointer(size, type_, stride, ptr as usize))
}

#[no_mangle]
pub extern "C" fn glNormalPointer(type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context((), |ctx| ctx.normal_pointer(type_, stride, ptr as usize))
}

#[no_mangle]
pub extern "C" fn glColorPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context((), |ctx| ctx.color_pointer(size, type_, stride, ptr as usize))
}

#[no_mangle]
pub extern "C" fn glSecondaryColorPointer(size: GLint, type_: GLenum, stride: GLsizei, pointer: *const GLvoid) {
    with_context((), |ctx| ctx.secondary_color_pointer(size, type_, stride, pointer as usize))
}

#[no_mangle]
pub extern "C" fn glSecondaryColorPointerEXT(size: GLint, type_: GLenum, stride: GLsizei, pointer: *const GLvoid) {
    glSecondaryColorPointer(size, type_, stride, pointer)
}

#[no_mangle]
pub extern "C" fn glFogCoordPointer(type_: GLenum, stride: GLsizei, pointer: *const GLvoid) {
    with_context((), |ctx| ctx.fog_coord_pointer(type_, stride, pointer as usize))
}

#[no_mangle]
pub extern "C" fn glFogCoordPointerEXT(type_: GLenum, stride: GLsizei, pointer: *const GLvoid) {
    glFogCoordPointer(type_, stride, pointer)
}

#[no_mangle]
pub extern "C" fn glIndexPointer(type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context((), |ctx| ctx.index_pointer(type_, stride, ptr as usize))
}

#[no_mangle]
pub extern "C" fn glEdgeFlagPointer(stride: GLsizei, ptr: *const GLvoid) {
    with_context((), |ctx| ctx.edge_flag_pointer(stride, ptr as usize))
}

#[no_mangle]
pub extern "C" fn glTexCoordPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context((), |ctx| ctx.tex_coord_pointer(size, type_, stride, ptr as usize))
}

#[no_mangle]
pub extern "C" fn glVertexPointerEXT(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    _count: GLsizei,
    pointer: *const GLvoid,
) {
    glVertexPointer(size, type_, stride, pointer)
}

#[no_mangle]
pub extern "C" fn glNormalPointerEXT(type_: GLenum, stride: GLsizei, _count: GLsizei, pointer: *const GLvoid) {
    glNormalPointer(type_, stride, pointer)
}

#[no_mangle]
pub extern "C" fn glColorPointerEXT(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    _count: GLsizei,
    pointer: *const GLvoid,
) {
    glColorPointer(size, type_, stride, pointer)
}

#[no_mangle]
pub extern "C" fn glIndexPointerEXT(type_: GLenum, stride: GLsizei, _count: GLsizei, pointer: *const GLvoid) {
    glIndexPointer(type_, stride, pointer)
}

#[no_mangle]
pub extern "C" fn glEdgeFlagPointerEXT(stride: GLsizei, _count: GLsizei, pointer: *const GLboolean) {
    glEdgeFlagPointer(stride, pointer as *const GLvoid)
}

#[no_mangle]
pub extern "C" fn glTexCoordPointerEXT(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    _count: GLsizei,
    pointer: *const GLvoid,
) {
    glTexCoordPointer(size, type_, stride, pointer)
}

#[no_mangle]
pub extern "C" fn glEnableClientState(cap: GLenum) {
    with_context((), |ctx| ctx.enable_client_state(cap, true))
}

#[no_mangle]
pub extern "C" fn glDisableClientState(cap: GLenum) {
    with_context((), |ctx| ctx.enable_client_state(cap, false))
}

#[no_mangle]
pub extern "C" fn glClientActiveTexture(texture: GLenum) {
    with_context((), |ctx| ctx.client_active_texture(texture))
}

#[no_mangle]
pub extern "C" fn glClientActiveTextureARB(texture: GLenum) {
    glClientActiveTexture(texture)
}

#[no_mangle]
pub extern "C" fn glInterleavedArrays(format: GLenum, stride: GLsizei, pointer: *const GLvoid) {
    with_context((), |ctx| ctx.interleaved_arrays(format, stride, pointer as usize))
}

/// # Safety
/// `params` must have room for one pointer (NULL writes nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetPointerv(pname: GLenum, params: *mut *mut GLvoid) {
    if let Some(pointer) = with_context(None, |ctx| ctx.get_pointer(pname)) {
        // SAFETY: the caller provides room for one pointer at `params` (or passes NULL).
        unsafe { caller_memory::write(params, pointer as *mut GLvoid) }
    }
}

/// # Safety
/// As [`glGetPointerv`].
#[no_mangle]
pub unsafe extern "C" fn glGetPointervEXT(pname: GLenum, params: *mut *mut GLvoid) {
    // SAFETY: the same contract as the core function.
    unsafe { glGetPointerv(pname, params) }
}

#[no_mangle]
pub extern "C" fn glArrayElement(i: GLint) {
    with_context((), |ctx| ctx.array_element_or_compile(i, &CallerMemory))
}

#[no_mangle]
pub extern "C" fn glArrayElementEXT(i: GLint) {
    glArrayElement(i)
}

#[no_mangle]
pub extern "C" fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei) {
    with_context((), |ctx| ctx.draw_or_compile(|ctx| ctx.draw_arrays(mode, first, count, &CallerMemory)))
}

#[no_mangle]
pub extern "C" fn glDrawArraysEXT(mode: GLenum, first: GLint, count: GLsizei) {
    glDrawArrays(mode, first, count)
}

#[no_mangle]
pub extern "C" fn glDrawElements(mode: GLenum, count: GLsizei, type_: GLenum, indices: *const GLvoid) {
    with_context((), |ctx| {
        ctx.draw_or_compile(|ctx| ctx.draw_elements(mode, count, type_, indices as usize, &CallerMemory))
    })
}

#[no_mangle]
pub extern "C" fn glDrawRangeElements(
    mode: GLenum,
    start: GLuint,
    end: GLuint,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
) {
    with_context((), |ctx| {
        ctx.draw_or_compile(|ctx| {
            ctx.draw_range_elements(mode, start, end, count, type_, indices as usize, &CallerMemory)
        })
    })
}

#[no_mangle]
pub extern "C" fn glDrawRangeElementsEXT(
    mode: GLenum,
    start: GLuint,
    end: GLuint,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
) {
    glDrawRangeElements(mode, start, end, count, type_, indices)
}

/// # Safety
/// `first` and `count` must point to `drawcount` values each.
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawArrays(
    mode: GLenum,
    first: *const GLint,
    count: *const GLsizei,
    drawcount: GLsizei,
) {
    // SAFETY: the caller provides `drawcount` values in each array.
    let (firsts, counts) = unsafe { (read_array(first, drawcount), read_array(count, drawcount)) };
    with_context((), |ctx| {
        ctx.draw_or_compile(|ctx| ctx.multi_draw_arrays(mode, &firsts, &counts, drawcount, &CallerMemory))
    })
}

/// # Safety
/// As [`glMultiDrawArrays`].
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawArraysEXT(
    mode: GLenum,
    first: *const GLint,
    count: *const GLsizei,
    primcount: GLsizei,
) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiDrawArrays(mode, first, count, primcount) }
}

/// # Safety
/// `count` and `indices` must point to `drawcount` values each.
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawElements(
    mode: GLenum,
    count: *const GLsizei,
    type_: GLenum,
    indices: *const *const GLvoid,
    drawcount: GLsizei,
) {
    // SAFETY: the caller provides `drawcount` values in each array.
    let (counts, pointers) = unsafe { (read_array(count, drawcount), read_array(indices, drawcount)) };
    // Addresses (or element buffer offsets), so the context never holds caller pointers.
    let addresses: Vec<usize> = pointers.iter().map(|&p| p as usize).collect();
    with_context((), |ctx| {
        ctx.draw_or_compile(|ctx| ctx.multi_draw_elements(mode, &counts, type_, &addresses, drawcount, &CallerMemory))
    })
}

/// # Safety
/// As [`glMultiDrawElements`].
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawElementsEXT(
    mode: GLenum,
    count: *const GLsizei,
    type_: GLenum,
    indices: *const *const GLvoid,
    primcount: GLsizei,
) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiDrawElements(mode, count, type_, indices, primcount) }
}
