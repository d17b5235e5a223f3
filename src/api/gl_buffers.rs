//! Entry points for clears, write masks, draw/read buffers, scissor, viewport and glAccum.
use super::caller_memory;
use super::record_or_run;
use crate::gl::enums::*;
use crate::gl::types::*;

#[no_mangle]
pub extern "C" fn glClear(mask: GLbitfield) {
    record_or_run(move |ctx| ctx.clear(mask))
}

#[no_mangle]
pub extern "C" fn glClearColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) {
    record_or_run(move |ctx| ctx.clear_color([red, green, blue, alpha]))
}

#[no_mangle]
pub extern "C" fn glClearDepth(depth: GLclampd) {
    record_or_run(move |ctx| ctx.clear_depth(depth))
}

#[no_mangle]
pub extern "C" fn glClearDepthf(depth: GLfloat) {
    record_or_run(move |ctx| ctx.clear_depth(depth as f64))
}

#[no_mangle]
pub extern "C" fn glClearStencil(s: GLint) {
    record_or_run(move |ctx| ctx.clear_stencil(s))
}

#[no_mangle]
pub extern "C" fn glClearAccum(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) {
    record_or_run(move |ctx| ctx.clear_accum([red, green, blue, alpha]))
}

#[no_mangle]
pub extern "C" fn glClearIndex(c: GLfloat) {
    record_or_run(move |ctx| ctx.clear_index(c))
}

#[no_mangle]
pub extern "C" fn glColorMask(red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) {
    record_or_run(move |ctx| ctx.color_mask(None, [red != 0, green != 0, blue != 0, alpha != 0]))
}

#[no_mangle]
pub extern "C" fn glColorMaski(index: GLuint, r: GLboolean, g: GLboolean, b: GLboolean, a: GLboolean) {
    record_or_run(move |ctx| ctx.color_mask(Some(index), [r != 0, g != 0, b != 0, a != 0]))
}

#[no_mangle]
pub extern "C" fn glColorMaskIndexedEXT(index: GLuint, r: GLboolean, g: GLboolean, b: GLboolean, a: GLboolean) {
    glColorMaski(index, r, g, b, a)
}

#[no_mangle]
pub extern "C" fn glDepthMask(flag: GLboolean) {
    record_or_run(move |ctx| ctx.depth_mask(flag != 0))
}

#[no_mangle]
pub extern "C" fn glStencilMask(mask: GLuint) {
    record_or_run(move |ctx| ctx.stencil_mask_active(mask))
}

#[no_mangle]
pub extern "C" fn glStencilMaskSeparate(face: GLenum, mask: GLuint) {
    record_or_run(move |ctx| ctx.stencil_mask(face, mask))
}

#[no_mangle]
pub extern "C" fn glIndexMask(mask: GLuint) {
    record_or_run(move |ctx| ctx.index_mask(mask))
}

#[no_mangle]
pub extern "C" fn glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    record_or_run(move |ctx| ctx.scissor(x, y, width, height))
}

#[no_mangle]
pub extern "C" fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    record_or_run(move |ctx| ctx.viewport(x, y, width, height))
}

#[no_mangle]
pub extern "C" fn glDepthRange(near_val: GLclampd, far_val: GLclampd) {
    record_or_run(move |ctx| ctx.depth_range(near_val, far_val))
}

#[no_mangle]
pub extern "C" fn glDepthRangef(near_val: GLfloat, far_val: GLfloat) {
    record_or_run(move |ctx| ctx.depth_range(near_val as f64, far_val as f64))
}

#[no_mangle]
pub extern "C" fn glDrawBuffer(mode: GLenum) {
    record_or_run(move |ctx| ctx.draw_buffer(mode))
}

/// # Safety
/// `bufs` must point to `n` GLenums (it is not read when `n` is negative or too large).
#[no_mangle]
pub unsafe extern "C" fn glDrawBuffers(n: GLsizei, bufs: *const GLenum) {
    let list: Option<Vec<GLenum>> = if n < 0 || n as usize > crate::gl::limits::MAX_DRAW_BUFFERS {
        None
    } else if n == 0 {
        Some(Vec::new())
    } else if bufs.is_null() {
        None
    } else {
        // SAFETY: the caller passes `n` enums at `bufs` (checked non-null, n bounded).
        unsafe { caller_memory::read_vec(bufs, n as usize) }
    };
    record_or_run(move |ctx| match &list {
        Some(list) => ctx.draw_buffers(list),
        None => ctx.error(GL_INVALID_VALUE),
    })
}

/// # Safety
/// As [`glDrawBuffers`].
#[no_mangle]
pub unsafe extern "C" fn glDrawBuffersARB(n: GLsizei, bufs: *const GLenum) {
    // SAFETY: same contract as glDrawBuffers.
    unsafe { glDrawBuffers(n, bufs) }
}

#[no_mangle]
pub extern "C" fn glReadBuffer(mode: GLenum) {
    record_or_run(move |ctx| ctx.read_buffer(mode))
}

#[no_mangle]
pub extern "C" fn glAccum(op: GLenum, value: GLfloat) {
    record_or_run(move |ctx| ctx.accum(op, value))
}

#[no_mangle]
pub extern "C" fn glDepthFunc(func: GLenum) {
    record_or_run(move |ctx| ctx.depth_func(func))
}
