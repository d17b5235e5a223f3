//! Entry points of framebuffer and renderbuffer objects (ARB_framebuffer_object, with the
//! EXT_framebuffer_object, EXT_framebuffer_blit and EXT_framebuffer_multisample names).
use super::caller_memory::{self, read_array};
use super::{guard, with_context};
use crate::gl::types::*;

/// # Safety
/// `framebuffers` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenFramebuffers(n: GLsizei, framebuffers: *mut GLuint) {
    let names = guard(None, || crate::context::current::with_current(|ctx| ctx.gen_fbo_names(n, false)).flatten());
    // SAFETY: forwarded from the caller's contract.
    unsafe { caller_memory::write_all(framebuffers, names.unwrap_or_default()) }
}

/// # Safety
/// As glGenFramebuffers.
#[no_mangle]
pub unsafe extern "C" fn glGenFramebuffersEXT(n: GLsizei, framebuffers: *mut GLuint) {
    // SAFETY: same contract.
    unsafe { glGenFramebuffers(n, framebuffers) }
}

/// # Safety
/// `framebuffers` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteFramebuffers(n: GLsizei, framebuffers: *const GLuint) {
    // SAFETY: forwarded from the caller's contract.
    let names = unsafe { read_array(framebuffers, n) };
    with_context((), |ctx| ctx.delete_framebuffers(n, &names))
}

/// # Safety
/// As glDeleteFramebuffers.
#[no_mangle]
pub unsafe extern "C" fn glDeleteFramebuffersEXT(n: GLsizei, framebuffers: *const GLuint) {
    // SAFETY: same contract.
    unsafe { glDeleteFramebuffers(n, framebuffers) }
}

#[no_mangle]
pub extern "C" fn glBindFramebuffer(target: GLenum, framebuffer: GLuint) {
    with_context((), |ctx| ctx.bind_framebuffer(target, framebuffer))
}

#[no_mangle]
pub extern "C" fn glBindFramebufferEXT(target: GLenum, framebuffer: GLuint) {
    glBindFramebuffer(target, framebuffer)
}

#[no_mangle]
pub extern "C" fn glIsFramebuffer(framebuffer: GLuint) -> GLboolean {
    with_context(0, |ctx| ctx.is_framebuffer(framebuffer) as GLboolean)
}

#[no_mangle]
pub extern "C" fn glIsFramebufferEXT(framebuffer: GLuint) -> GLboolean {
    glIsFramebuffer(framebuffer)
}

#[no_mangle]
pub extern "C" fn glCheckFramebufferStatus(target: GLenum) -> GLenum {
    with_context(0, |ctx| ctx.check_framebuffer_status(target))
}

#[no_mangle]
pub extern "C" fn glCheckFramebufferStatusEXT(target: GLenum) -> GLenum {
    glCheckFramebufferStatus(target)
}

#[no_mangle]
pub extern "C" fn glFramebufferTexture1D(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
) {
    with_context((), |ctx| ctx.framebuffer_texture(1, target, attachment, textarget, texture, level, 0))
}

#[no_mangle]
pub extern "C" fn glFramebufferTexture1DEXT(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
) {
    glFramebufferTexture1D(target, attachment, textarget, texture, level)
}

#[no_mangle]
pub extern "C" fn glFramebufferTexture2D(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
) {
    with_context((), |ctx| ctx.framebuffer_texture(2, target, attachment, textarget, texture, level, 0))
}

#[no_mangle]
pub extern "C" fn glFramebufferTexture2DEXT(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
) {
    glFramebufferTexture2D(target, attachment, textarget, texture, level)
}

#[no_mangle]
pub extern "C" fn glFramebufferTexture3D(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
    zoffset: GLint,
) {
    with_context((), |ctx| ctx.framebuffer_texture(3, target, attachment, textarget, texture, level, zoffset))
}

#[no_mangle]
pub extern "C" fn glFramebufferTexture3DEXT(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
    zoffset: GLint,
) {
    glFramebufferTexture3D(target, attachment, textarget, texture, level, zoffset)
}

#[no_mangle]
pub extern "C" fn glFramebufferTextureLayer(
    target: GLenum,
    attachment: GLenum,
    texture: GLuint,
    level: GLint,
    layer: GLint,
) {
    with_context((), |ctx| ctx.framebuffer_texture(0, target, attachment, 0, texture, level, layer))
}

#[no_mangle]
pub extern "C" fn glFramebufferRenderbuffer(
    target: GLenum,
    attachment: GLenum,
    renderbuffertarget: GLenum,
    renderbuffer: GLuint,
) {
    with_context((), |ctx| ctx.framebuffer_renderbuffer(target, attachment, renderbuffertarget, renderbuffer))
}

#[no_mangle]
pub extern "C" fn glFramebufferRenderbufferEXT(
    target: GLenum,
    attachment: GLenum,
    renderbuffertarget: GLenum,
    renderbuffer: GLuint,
) {
    glFramebufferRenderbuffer(target, attachment, renderbuffertarget, renderbuffer)
}

/// # Safety
/// `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetFramebufferAttachmentParameteriv(
    target: GLenum,
    attachment: GLenum,
    pname: GLenum,
    params: *mut GLint,
) {
    let value = with_context(None, |ctx| ctx.get_framebuffer_attachment_parameter(target, attachment, pname));
    if let Some(v) = value {
        // SAFETY: the caller provides room for one value (or passes NULL).
        unsafe { caller_memory::write(params, v) }
    }
}

/// # Safety
/// As glGetFramebufferAttachmentParameteriv.
#[no_mangle]
pub unsafe extern "C" fn glGetFramebufferAttachmentParameterivEXT(
    target: GLenum,
    attachment: GLenum,
    pname: GLenum,
    params: *mut GLint,
) {
    // SAFETY: same contract.
    unsafe { glGetFramebufferAttachmentParameteriv(target, attachment, pname, params) }
}

/// # Safety
/// `renderbuffers` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenRenderbuffers(n: GLsizei, renderbuffers: *mut GLuint) {
    let names = guard(None, || crate::context::current::with_current(|ctx| ctx.gen_fbo_names(n, true)).flatten());
    // SAFETY: forwarded from the caller's contract.
    unsafe { caller_memory::write_all(renderbuffers, names.unwrap_or_default()) }
}

/// # Safety
/// As glGenRenderbuffers.
#[no_mangle]
pub unsafe extern "C" fn glGenRenderbuffersEXT(n: GLsizei, renderbuffers: *mut GLuint) {
    // SAFETY: same contract.
    unsafe { glGenRenderbuffers(n, renderbuffers) }
}

/// # Safety
/// `renderbuffers` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteRenderbuffers(n: GLsizei, renderbuffers: *const GLuint) {
    // SAFETY: forwarded from the caller's contract.
    let names = unsafe { read_array(renderbuffers, n) };
    with_context((), |ctx| ctx.delete_renderbuffers(n, &names))
}

/// # Safety
/// As glDeleteRenderbuffers.
#[no_mangle]
pub unsafe extern "C" fn glDeleteRenderbuffersEXT(n: GLsizei, renderbuffers: *const GLuint) {
    // SAFETY: same contract.
    unsafe { glDeleteRenderbuffers(n, renderbuffers) }
}

#[no_mangle]
pub extern "C" fn glBindRenderbuffer(target: GLenum, renderbuffer: GLuint) {
    with_context((), |ctx| ctx.bind_renderbuffer(target, renderbuffer))
}

#[no_mangle]
pub extern "C" fn glBindRenderbufferEXT(target: GLenum, renderbuffer: GLuint) {
    glBindRenderbuffer(target, renderbuffer)
}

#[no_mangle]
pub extern "C" fn glIsRenderbuffer(renderbuffer: GLuint) -> GLboolean {
    with_context(0, |ctx| ctx.is_renderbuffer(renderbuffer) as GLboolean)
}

#[no_mangle]
pub extern "C" fn glIsRenderbufferEXT(renderbuffer: GLuint) -> GLboolean {
    glIsRenderbuffer(renderbuffer)
}

#[no_mangle]
pub extern "C" fn glRenderbufferStorage(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei) {
    with_context((), |ctx| ctx.renderbuffer_storage(target, 0, internalformat, width, height))
}

#[no_mangle]
pub extern "C" fn glRenderbufferStorageEXT(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei) {
    glRenderbufferStorage(target, internalformat, width, height)
}

#[no_mangle]
pub extern "C" fn glRenderbufferStorageMultisample(
    target: GLenum,
    samples: GLsizei,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
) {
    with_context((), |ctx| ctx.renderbuffer_storage(target, samples, internalformat, width, height))
}

#[no_mangle]
pub extern "C" fn glRenderbufferStorageMultisampleEXT(
    target: GLenum,
    samples: GLsizei,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
) {
    glRenderbufferStorageMultisample(target, samples, internalformat, width, height)
}

/// # Safety
/// `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetRenderbufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    let value = with_context(None, |ctx| ctx.get_renderbuffer_parameter(target, pname));
    if let Some(v) = value {
        // SAFETY: the caller provides room for one value (or passes NULL).
        unsafe { caller_memory::write(params, v) }
    }
}

/// # Safety
/// As glGetRenderbufferParameteriv.
#[no_mangle]
pub unsafe extern "C" fn glGetRenderbufferParameterivEXT(target: GLenum, pname: GLenum, params: *mut GLint) {
    // SAFETY: same contract.
    unsafe { glGetRenderbufferParameteriv(target, pname, params) }
}

#[allow(clippy::too_many_arguments)]
#[no_mangle]
pub extern "C" fn glBlitFramebuffer(
    src_x0: GLint,
    src_y0: GLint,
    src_x1: GLint,
    src_y1: GLint,
    dst_x0: GLint,
    dst_y0: GLint,
    dst_x1: GLint,
    dst_y1: GLint,
    mask: GLbitfield,
    filter: GLenum,
) {
    with_context((), |ctx| {
        ctx.blit_framebuffer([src_x0, src_y0, src_x1, src_y1], [dst_x0, dst_y0, dst_x1, dst_y1], mask, filter)
    })
}

#[allow(clippy::too_many_arguments)]
#[no_mangle]
pub extern "C" fn glBlitFramebufferEXT(
    src_x0: GLint,
    src_y0: GLint,
    src_x1: GLint,
    src_y1: GLint,
    dst_x0: GLint,
    dst_y0: GLint,
    dst_x1: GLint,
    dst_y1: GLint,
    mask: GLbitfield,
    filter: GLenum,
) {
    glBlitFramebuffer(src_x0, src_y0, src_x1, src_y1, dst_x0, dst_y0, dst_x1, dst_y1, mask, filter)
}
