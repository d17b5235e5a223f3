//! Entry points for clears, write masks, draw/read buffers, scissor, viewport and glAccum.
use super::enums::*;
use super::types::*;
use super::with_context;

#[no_mangle]
pub extern "C" fn glClear(mask: GLbitfield) {
    with_context((), |ctx| ctx.clear(mask))
}

#[no_mangle]
pub extern "C" fn glClearColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) {
    with_context((), |ctx| ctx.clear_color([red, green, blue, alpha]))
}

#[no_mangle]
pub extern "C" fn glClearDepth(depth: GLclampd) {
    with_context((), |ctx| ctx.clear_depth(depth))
}

#[no_mangle]
pub extern "C" fn glClearDepthf(depth: GLfloat) {
    with_context((), |ctx| ctx.clear_depth(depth as f64))
}

#[no_mangle]
pub extern "C" fn glClearStencil(s: GLint) {
    with_context((), |ctx| ctx.clear_stencil(s))
}

#[no_mangle]
pub extern "C" fn glClearAccum(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) {
    with_context((), |ctx| ctx.clear_accum([red, green, blue, alpha]))
}

#[no_mangle]
pub extern "C" fn glClearIndex(c: GLfloat) {
    with_context((), |ctx| ctx.clear_index(c))
}

#[no_mangle]
pub extern "C" fn glColorMask(red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) {
    with_context((), |ctx| ctx.color_mask(None, [red != 0, green != 0, blue != 0, alpha != 0]))
}

#[no_mangle]
pub extern "C" fn glColorMaski(index: GLuint, r: GLboolean, g: GLboolean, b: GLboolean, a: GLboolean) {
    with_context((), |ctx| ctx.color_mask(Some(index), [r != 0, g != 0, b != 0, a != 0]))
}

#[no_mangle]
pub extern "C" fn glColorMaskIndexedEXT(index: GLuint, r: GLboolean, g: GLboolean, b: GLboolean, a: GLboolean) {
    glColorMaski(index, r, g, b, a)
}

#[no_mangle]
pub extern "C" fn glDepthMask(flag: GLboolean) {
    with_context((), |ctx| ctx.depth_mask(flag != 0))
}

#[no_mangle]
pub extern "C" fn glStencilMask(mask: GLuint) {
    with_context((), |ctx| ctx.stencil_mask_active(mask))
}

#[no_mangle]
pub extern "C" fn glStencilMaskSeparate(face: GLenum, mask: GLuint) {
    with_context((), |ctx| ctx.stencil_mask(face, mask))
}

#[no_mangle]
pub extern "C" fn glIndexMask(mask: GLuint) {
    with_context((), |ctx| ctx.index_mask(mask))
}

#[no_mangle]
pub extern "C" fn glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    with_context((), |ctx| ctx.scissor(x, y, width, height))
}

#[no_mangle]
pub extern "C" fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    with_context((), |ctx| ctx.viewport(x, y, width, height))
}

#[no_mangle]
pub extern "C" fn glDepthRange(near_val: GLclampd, far_val: GLclampd) {
    with_context((), |ctx| ctx.depth_range(near_val, far_val))
}

#[no_mangle]
pub extern "C" fn glDepthRangef(near_val: GLfloat, far_val: GLfloat) {
    with_context((), |ctx| ctx.depth_range(near_val as f64, far_val as f64))
}

#[no_mangle]
pub extern "C" fn glDrawBuffer(mode: GLenum) {
    with_context((), |ctx| ctx.draw_buffer(mode))
}

/// # Safety
/// `bufs` must point to `n` GLenums (it is not read when `n` is negative or too large).
#[no_mangle]
pub unsafe extern "C" fn glDrawBuffers(n: GLsizei, bufs: *const GLenum) {
    with_context((), |ctx| {
        if n < 0 || n as usize > crate::context::state::MAX_DRAW_BUFFERS {
            return ctx.error(GL_INVALID_VALUE);
        }
        if bufs.is_null() && n > 0 {
            return ctx.error(GL_INVALID_VALUE);
        }
        let list: &[GLenum] = if n == 0 {
            &[]
        } else {
            // SAFETY: the caller passes `n` enums at `bufs` (checked non-null, n bounded).
            unsafe { std::slice::from_raw_parts(bufs, n as usize) }
        };
        ctx.draw_buffers(list)
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
    with_context((), |ctx| ctx.read_buffer(mode))
}

#[no_mangle]
pub extern "C" fn glAccum(op: GLenum, value: GLfloat) {
    with_context((), |ctx| ctx.accum(op, value))
}

#[no_mangle]
pub extern "C" fn glDepthFunc(func: GLenum) {
    with_context((), |ctx| ctx.depth_func(func))
}
