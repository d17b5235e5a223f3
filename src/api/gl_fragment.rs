//! Entry points for the per-fragment operations' state: alpha test, stencil, blending, logic
//! op and fog (glDepthFunc, glStencilMask and the masks live with the buffers).
use super::caller_memory;
use super::record_or_run;
use crate::context::Context;
use crate::gl::types::*;

#[no_mangle]
pub extern "C" fn glAlphaFunc(func: GLenum, ref_: GLclampf) {
    record_or_run(move |ctx| ctx.alpha_func(func, ref_))
}

#[no_mangle]
pub extern "C" fn glStencilFunc(func: GLenum, ref_: GLint, mask: GLuint) {
    record_or_run(move |ctx| ctx.stencil_func(func, ref_, mask))
}

#[no_mangle]
pub extern "C" fn glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) {
    record_or_run(move |ctx| ctx.stencil_op(fail, zfail, zpass))
}

#[no_mangle]
pub extern "C" fn glStencilFuncSeparate(face: GLenum, func: GLenum, ref_: GLint, mask: GLuint) {
    record_or_run(move |ctx| ctx.stencil_func_separate(face, func, ref_, mask))
}

#[no_mangle]
pub extern "C" fn glStencilOpSeparate(face: GLenum, sfail: GLenum, dpfail: GLenum, dppass: GLenum) {
    record_or_run(move |ctx| ctx.stencil_op_separate(face, sfail, dpfail, dppass))
}

#[no_mangle]
pub extern "C" fn glStencilFuncSeparateATI(frontfunc: GLenum, backfunc: GLenum, ref_: GLint, mask: GLuint) {
    record_or_run(move |ctx| ctx.stencil_func_separate_ati(frontfunc, backfunc, ref_, mask))
}

#[no_mangle]
pub extern "C" fn glActiveStencilFaceEXT(face: GLenum) {
    record_or_run(move |ctx| ctx.active_stencil_face(face))
}

#[no_mangle]
pub extern "C" fn glBlendFunc(sfactor: GLenum, dfactor: GLenum) {
    record_or_run(move |ctx| ctx.blend_func(None, sfactor, dfactor, sfactor, dfactor))
}

#[no_mangle]
pub extern "C" fn glBlendFuncSeparate(
    sfactorRGB: GLenum,
    dfactorRGB: GLenum,
    sfactorAlpha: GLenum,
    dfactorAlpha: GLenum,
) {
    record_or_run(move |ctx| ctx.blend_func(None, sfactorRGB, dfactorRGB, sfactorAlpha, dfactorAlpha))
}

#[no_mangle]
pub extern "C" fn glBlendFuncSeparateEXT(
    sfactorRGB: GLenum,
    dfactorRGB: GLenum,
    sfactorAlpha: GLenum,
    dfactorAlpha: GLenum,
) {
    glBlendFuncSeparate(sfactorRGB, dfactorRGB, sfactorAlpha, dfactorAlpha)
}

#[no_mangle]
pub extern "C" fn glBlendEquation(mode: GLenum) {
    record_or_run(move |ctx| ctx.blend_equation(None, mode, mode))
}

#[no_mangle]
pub extern "C" fn glBlendEquationEXT(mode: GLenum) {
    glBlendEquation(mode)
}

#[no_mangle]
pub extern "C" fn glBlendEquationSeparate(modeRGB: GLenum, modeAlpha: GLenum) {
    record_or_run(move |ctx| ctx.blend_equation(None, modeRGB, modeAlpha))
}

#[no_mangle]
pub extern "C" fn glBlendEquationSeparateEXT(modeRGB: GLenum, modeAlpha: GLenum) {
    glBlendEquationSeparate(modeRGB, modeAlpha)
}

#[no_mangle]
pub extern "C" fn glBlendColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) {
    record_or_run(move |ctx| ctx.blend_color([red, green, blue, alpha]))
}

#[no_mangle]
pub extern "C" fn glBlendColorEXT(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) {
    glBlendColor(red, green, blue, alpha)
}

#[no_mangle]
pub extern "C" fn glBlendFunci(buf: GLuint, src: GLenum, dst: GLenum) {
    record_or_run(move |ctx| ctx.blend_func(Some(buf), src, dst, src, dst))
}

#[no_mangle]
pub extern "C" fn glBlendFunciARB(buf: GLuint, src: GLenum, dst: GLenum) {
    glBlendFunci(buf, src, dst)
}

#[no_mangle]
pub extern "C" fn glBlendFuncSeparatei(
    buf: GLuint,
    srcRGB: GLenum,
    dstRGB: GLenum,
    srcAlpha: GLenum,
    dstAlpha: GLenum,
) {
    record_or_run(move |ctx| ctx.blend_func(Some(buf), srcRGB, dstRGB, srcAlpha, dstAlpha))
}

#[no_mangle]
pub extern "C" fn glBlendFuncSeparateiARB(
    buf: GLuint,
    srcRGB: GLenum,
    dstRGB: GLenum,
    srcAlpha: GLenum,
    dstAlpha: GLenum,
) {
    glBlendFuncSeparatei(buf, srcRGB, dstRGB, srcAlpha, dstAlpha)
}

#[no_mangle]
pub extern "C" fn glBlendEquationi(buf: GLuint, mode: GLenum) {
    record_or_run(move |ctx| ctx.blend_equation(Some(buf), mode, mode))
}

#[no_mangle]
pub extern "C" fn glBlendEquationiARB(buf: GLuint, mode: GLenum) {
    glBlendEquationi(buf, mode)
}

#[no_mangle]
pub extern "C" fn glBlendEquationSeparatei(buf: GLuint, modeRGB: GLenum, modeAlpha: GLenum) {
    record_or_run(move |ctx| ctx.blend_equation(Some(buf), modeRGB, modeAlpha))
}

#[no_mangle]
pub extern "C" fn glBlendEquationSeparateiARB(buf: GLuint, modeRGB: GLenum, modeAlpha: GLenum) {
    glBlendEquationSeparatei(buf, modeRGB, modeAlpha)
}

#[no_mangle]
pub extern "C" fn glLogicOp(opcode: GLenum) {
    record_or_run(move |ctx| ctx.logic_op(opcode))
}

#[no_mangle]
pub extern "C" fn glFogf(pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.fog(pname, [param, 0.0, 0.0, 0.0]))
}

#[no_mangle]
pub extern "C" fn glFogi(pname: GLenum, param: GLint) {
    record_or_run(move |ctx| ctx.fog(pname, [param as GLfloat, 0.0, 0.0, 0.0]))
}

/// The number of values glFog*v reads for `pname`: four for the color, else one.
fn fog_param_count(pname: GLenum) -> usize {
    if pname == crate::gl::enums::GL_FOG_COLOR {
        4
    } else {
        1
    }
}

/// Reads the values of a glFog*v call into an array padded with zeros; `None` for a null
/// pointer (the call is then ignored).
///
/// # Safety
/// `params` is null or points to `fog_param_count(pname)` readable values.
unsafe fn read_fog_params<T: Copy + Default>(pname: GLenum, params: *const T) -> Option<[T; 4]> {
    let mut values = [T::default(); 4];
    let count = fog_param_count(pname).min(4);
    // SAFETY: the caller guarantees `fog_param_count(pname)` readable values (or NULL).
    let read = unsafe { caller_memory::read_vec(params, count) }?;
    values[..count].copy_from_slice(&read);
    Some(values)
}

/// # Safety
/// `params` points to four floats for GL_FOG_COLOR, one otherwise.
#[no_mangle]
pub unsafe extern "C" fn glFogfv(pname: GLenum, params: *const GLfloat) {
    // SAFETY: the GL contract of glFogfv, passed on to our caller.
    if let Some(values) = unsafe { read_fog_params(pname, params) } {
        record_or_run(move |ctx| ctx.fog(pname, values))
    }
}

/// # Safety
/// `params` points to four integers for GL_FOG_COLOR, one otherwise.
#[no_mangle]
pub unsafe extern "C" fn glFogiv(pname: GLenum, params: *const GLint) {
    // SAFETY: the GL contract of glFogiv, passed on to our caller.
    if let Some(values) = unsafe { read_fog_params(pname, params) } {
        record_or_run(move |ctx: &mut Context| ctx.fog_integers(pname, values))
    }
}
