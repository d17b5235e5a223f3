//! Entry points for matrices, glActiveTexture and user clip planes.
use super::caller_memory::{self, read};
use super::{record_or_run, with_context};
use crate::gl::types::*;

/// A double matrix converted to float, as every double matrix command does first.
fn to_float(m: [GLdouble; 16]) -> [GLfloat; 16] {
    m.map(|v| v as GLfloat)
}

#[no_mangle]
pub extern "C" fn glMatrixMode(mode: GLenum) {
    record_or_run(move |ctx| ctx.matrix_mode(mode))
}

#[no_mangle]
pub extern "C" fn glActiveTexture(texture: GLenum) {
    record_or_run(move |ctx| ctx.active_texture(texture))
}

#[no_mangle]
pub extern "C" fn glActiveTextureARB(texture: GLenum) {
    glActiveTexture(texture)
}

#[no_mangle]
pub extern "C" fn glPushMatrix() {
    record_or_run(move |ctx| ctx.push_matrix())
}

#[no_mangle]
pub extern "C" fn glPopMatrix() {
    record_or_run(move |ctx| ctx.pop_matrix())
}

#[no_mangle]
pub extern "C" fn glLoadIdentity() {
    record_or_run(move |ctx| ctx.load_identity())
}

/// # Safety
/// `m` is NULL (ignored) or points to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glLoadMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(m) = unsafe { read::<_, 16>(m) } {
        record_or_run(move |ctx| ctx.load_matrix(&m))
    }
}

/// # Safety
/// `m` is NULL (ignored) or points to 16 doubles.
#[no_mangle]
pub unsafe extern "C" fn glLoadMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(m) = unsafe { read::<_, 16>(m) } {
        record_or_run(move |ctx| ctx.load_matrix(&to_float(m)))
    }
}

/// # Safety
/// `m` is NULL (ignored) or points to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glMultMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(m) = unsafe { read::<_, 16>(m) } {
        record_or_run(move |ctx| ctx.mult_matrix(&m))
    }
}

/// # Safety
/// `m` is NULL (ignored) or points to 16 doubles.
#[no_mangle]
pub unsafe extern "C" fn glMultMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(m) = unsafe { read::<_, 16>(m) } {
        record_or_run(move |ctx| ctx.mult_matrix(&to_float(m)))
    }
}

// <GL/gl.h> declares the parameter as an array, `m[16]`; so does tessera.h.
/// cbindgen:ptrs-as-arrays=[[m; 16]]
///
/// # Safety
/// `m` is NULL (ignored) or points to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glLoadTransposeMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(m) = unsafe { read::<_, 16>(m) } {
        record_or_run(move |ctx| ctx.load_transpose_matrix(&m))
    }
}

// <GL/gl.h> declares the parameter as an array, `m[16]`; so does tessera.h.
/// cbindgen:ptrs-as-arrays=[[m; 16]]
///
/// # Safety
/// `m` is NULL (ignored) or points to 16 doubles.
#[no_mangle]
pub unsafe extern "C" fn glLoadTransposeMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(m) = unsafe { read::<_, 16>(m) } {
        record_or_run(move |ctx| ctx.load_transpose_matrix(&to_float(m)))
    }
}

// <GL/gl.h> declares the parameter as an array, `m[16]`; so does tessera.h.
/// cbindgen:ptrs-as-arrays=[[m; 16]]
///
/// # Safety
/// `m` is NULL (ignored) or points to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glMultTransposeMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(m) = unsafe { read::<_, 16>(m) } {
        record_or_run(move |ctx| ctx.mult_transpose_matrix(&m))
    }
}

// <GL/gl.h> declares the parameter as an array, `m[16]`; so does tessera.h.
/// cbindgen:ptrs-as-arrays=[[m; 16]]
///
/// # Safety
/// `m` is NULL (ignored) or points to 16 doubles.
#[no_mangle]
pub unsafe extern "C" fn glMultTransposeMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(m) = unsafe { read::<_, 16>(m) } {
        record_or_run(move |ctx| ctx.mult_transpose_matrix(&to_float(m)))
    }
}

/// # Safety
/// As glLoadTransposeMatrixf.
#[no_mangle]
pub unsafe extern "C" fn glLoadTransposeMatrixfARB(m: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glLoadTransposeMatrixf(m) }
}

/// # Safety
/// As glLoadTransposeMatrixd.
#[no_mangle]
pub unsafe extern "C" fn glLoadTransposeMatrixdARB(m: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glLoadTransposeMatrixd(m) }
}

/// # Safety
/// As glMultTransposeMatrixf.
#[no_mangle]
pub unsafe extern "C" fn glMultTransposeMatrixfARB(m: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glMultTransposeMatrixf(m) }
}

/// # Safety
/// As glMultTransposeMatrixd.
#[no_mangle]
pub unsafe extern "C" fn glMultTransposeMatrixdARB(m: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glMultTransposeMatrixd(m) }
}

#[no_mangle]
pub extern "C" fn glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) {
    record_or_run(move |ctx| ctx.rotate(angle, x, y, z))
}

#[no_mangle]
pub extern "C" fn glRotated(angle: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) {
    glRotatef(angle as GLfloat, x as GLfloat, y as GLfloat, z as GLfloat)
}

#[no_mangle]
pub extern "C" fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat) {
    record_or_run(move |ctx| ctx.scale(x, y, z))
}

#[no_mangle]
pub extern "C" fn glScaled(x: GLdouble, y: GLdouble, z: GLdouble) {
    glScalef(x as GLfloat, y as GLfloat, z as GLfloat)
}

#[no_mangle]
pub extern "C" fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) {
    record_or_run(move |ctx| ctx.translate(x, y, z))
}

#[no_mangle]
pub extern "C" fn glTranslated(x: GLdouble, y: GLdouble, z: GLdouble) {
    glTranslatef(x as GLfloat, y as GLfloat, z as GLfloat)
}

#[no_mangle]
pub extern "C" fn glFrustum(
    left: GLdouble,
    right: GLdouble,
    bottom: GLdouble,
    top: GLdouble,
    near_val: GLdouble,
    far_val: GLdouble,
) {
    record_or_run(move |ctx| ctx.frustum(left, right, bottom, top, near_val, far_val))
}

#[no_mangle]
pub extern "C" fn glOrtho(
    left: GLdouble,
    right: GLdouble,
    bottom: GLdouble,
    top: GLdouble,
    near_val: GLdouble,
    far_val: GLdouble,
) {
    record_or_run(move |ctx| ctx.ortho(left, right, bottom, top, near_val, far_val))
}

/// glClipControl (ARB_clip_control, GL 4.5); compiled into display lists, as in Mesa.
#[no_mangle]
pub extern "C" fn glClipControl(origin: GLenum, depth: GLenum) {
    record_or_run(move |ctx| ctx.clip_control(origin, depth))
}

/// # Safety
/// `equation` is NULL (ignored) or points to 4 doubles.
#[no_mangle]
pub unsafe extern "C" fn glClipPlane(plane: GLenum, equation: *const GLdouble) {
    // SAFETY: GL's contract: a plane equation is 4 doubles.
    let Some(equation) = (unsafe { read::<_, 4>(equation) }) else {
        return;
    };
    record_or_run(move |ctx| ctx.clip_plane(plane, equation))
}

/// # Safety
/// `equation` is NULL (nothing written) or points to room for 4 doubles.
#[no_mangle]
pub unsafe extern "C" fn glGetClipPlane(plane: GLenum, equation: *mut GLdouble) {
    let Some(values) = with_context(None, |ctx| ctx.get_clip_plane(plane)) else {
        return;
    };
    // SAFETY: GL's contract: the caller provides room for 4 doubles (or passes NULL).
    unsafe { caller_memory::write_all(equation, values) }
}
