//! Immediate-mode entry points: glBegin/glEnd, glVertex, the current vertex attributes
//! (glColor, glSecondaryColor, glNormal, glTexCoord, glMultiTexCoord, glFogCoord, glEdgeFlag,
//! glIndex) and glRect.
//!
//! Each command converts its arguments to floats with the conversions of
//! `vertex::components` (normalized for colors and normals, by value otherwise) and forwards
//! them to the context; the vector (`v`) forms read their array and call the scalar form.
//! Extension aliases (`EXT`, `ARB`) call the core function. The variants differ only in types
//! and counts; they are written out one by one because cbindgen and build.rs read them.
use super::caller_memory::read;
use super::{fast_or_run, record_or_run};
use crate::gl::types::*;
use crate::vertex::components::Component;

#[no_mangle]
pub extern "C" fn glBegin(mode: GLenum) {
    record_or_run(move |ctx| ctx.begin(mode))
}

#[no_mangle]
pub extern "C" fn glEnd() {
    record_or_run(move |ctx| ctx.end())
}

#[no_mangle]
pub extern "C" fn glVertex2s(x: GLshort, y: GLshort) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), 0.0, 1.0))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex2sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glVertex2s(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glVertex2i(x: GLint, y: GLint) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), 0.0, 1.0))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex2iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glVertex2i(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glVertex2f(x: GLfloat, y: GLfloat) {
    fast_or_run(|ctx| ctx.try_vertex(x, y, 0.0, 1.0), move |ctx| ctx.vertex_xyzw(x, y, 0.0, 1.0))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex2fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glVertex2f(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glVertex2d(x: GLdouble, y: GLdouble) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), 0.0, 1.0))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex2dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glVertex2d(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glVertex3s(x: GLshort, y: GLshort, z: GLshort) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), z.to_f32(), 1.0))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex3sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glVertex3s(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glVertex3i(x: GLint, y: GLint, z: GLint) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), z.to_f32(), 1.0))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex3iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glVertex3i(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat) {
    fast_or_run(|ctx| ctx.try_vertex(x, y, z, 1.0), move |ctx| ctx.vertex_xyzw(x, y, z, 1.0))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex3fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glVertex3f(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glVertex3d(x: GLdouble, y: GLdouble, z: GLdouble) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), z.to_f32(), 1.0))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex3dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glVertex3d(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glVertex4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), z.to_f32(), w.to_f32()))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex4sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z, w]) = unsafe { read(v) } {
        glVertex4s(x, y, z, w)
    }
}

#[no_mangle]
pub extern "C" fn glVertex4i(x: GLint, y: GLint, z: GLint, w: GLint) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), z.to_f32(), w.to_f32()))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex4iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z, w]) = unsafe { read(v) } {
        glVertex4i(x, y, z, w)
    }
}

#[no_mangle]
pub extern "C" fn glVertex4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x, y, z, w))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex4fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z, w]) = unsafe { read(v) } {
        glVertex4f(x, y, z, w)
    }
}

#[no_mangle]
pub extern "C" fn glVertex4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
    record_or_run(move |ctx| ctx.vertex_xyzw(x.to_f32(), y.to_f32(), z.to_f32(), w.to_f32()))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertex4dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z, w]) = unsafe { read(v) } {
        glVertex4d(x, y, z, w)
    }
}

#[no_mangle]
pub extern "C" fn glColor3b(red: GLbyte, green: GLbyte, blue: GLbyte) {
    record_or_run(move |ctx| ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor3bv(v: *const GLbyte) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glColor3b(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glColor3s(red: GLshort, green: GLshort, blue: GLshort) {
    record_or_run(move |ctx| ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor3sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glColor3s(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glColor3i(red: GLint, green: GLint, blue: GLint) {
    record_or_run(move |ctx| ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor3iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glColor3i(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glColor3f(red: GLfloat, green: GLfloat, blue: GLfloat) {
    let color = [red.normalized(), green.normalized(), blue.normalized(), 1.0];
    fast_or_run(|ctx| ctx.try_set_color(color), move |ctx| ctx.set_color(color))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor3fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glColor3f(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glColor3d(red: GLdouble, green: GLdouble, blue: GLdouble) {
    record_or_run(move |ctx| ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor3dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glColor3d(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glColor3ub(red: GLubyte, green: GLubyte, blue: GLubyte) {
    let color = [red.normalized(), green.normalized(), blue.normalized(), 1.0];
    fast_or_run(|ctx| ctx.try_set_color(color), move |ctx| ctx.set_color(color))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor3ubv(v: *const GLubyte) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glColor3ub(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glColor3us(red: GLushort, green: GLushort, blue: GLushort) {
    record_or_run(move |ctx| ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor3usv(v: *const GLushort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glColor3us(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glColor3ui(red: GLuint, green: GLuint, blue: GLuint) {
    record_or_run(move |ctx| ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor3uiv(v: *const GLuint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glColor3ui(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glColor4b(red: GLbyte, green: GLbyte, blue: GLbyte, alpha: GLbyte) {
    record_or_run(move |ctx| {
        ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), alpha.normalized()])
    })
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor4bv(v: *const GLbyte) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue, alpha]) = unsafe { read(v) } {
        glColor4b(red, green, blue, alpha)
    }
}

#[no_mangle]
pub extern "C" fn glColor4s(red: GLshort, green: GLshort, blue: GLshort, alpha: GLshort) {
    record_or_run(move |ctx| {
        ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), alpha.normalized()])
    })
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor4sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue, alpha]) = unsafe { read(v) } {
        glColor4s(red, green, blue, alpha)
    }
}

#[no_mangle]
pub extern "C" fn glColor4i(red: GLint, green: GLint, blue: GLint, alpha: GLint) {
    record_or_run(move |ctx| {
        ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), alpha.normalized()])
    })
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor4iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue, alpha]) = unsafe { read(v) } {
        glColor4i(red, green, blue, alpha)
    }
}

#[no_mangle]
pub extern "C" fn glColor4f(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) {
    let color = [red.normalized(), green.normalized(), blue.normalized(), alpha.normalized()];
    fast_or_run(|ctx| ctx.try_set_color(color), move |ctx| ctx.set_color(color))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor4fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue, alpha]) = unsafe { read(v) } {
        glColor4f(red, green, blue, alpha)
    }
}

#[no_mangle]
pub extern "C" fn glColor4d(red: GLdouble, green: GLdouble, blue: GLdouble, alpha: GLdouble) {
    record_or_run(move |ctx| {
        ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), alpha.normalized()])
    })
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor4dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue, alpha]) = unsafe { read(v) } {
        glColor4d(red, green, blue, alpha)
    }
}

#[no_mangle]
pub extern "C" fn glColor4ub(red: GLubyte, green: GLubyte, blue: GLubyte, alpha: GLubyte) {
    let color = [red.normalized(), green.normalized(), blue.normalized(), alpha.normalized()];
    fast_or_run(|ctx| ctx.try_set_color(color), move |ctx| ctx.set_color(color))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor4ubv(v: *const GLubyte) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue, alpha]) = unsafe { read(v) } {
        glColor4ub(red, green, blue, alpha)
    }
}

#[no_mangle]
pub extern "C" fn glColor4us(red: GLushort, green: GLushort, blue: GLushort, alpha: GLushort) {
    record_or_run(move |ctx| {
        ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), alpha.normalized()])
    })
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor4usv(v: *const GLushort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue, alpha]) = unsafe { read(v) } {
        glColor4us(red, green, blue, alpha)
    }
}

#[no_mangle]
pub extern "C" fn glColor4ui(red: GLuint, green: GLuint, blue: GLuint, alpha: GLuint) {
    record_or_run(move |ctx| {
        ctx.set_color([red.normalized(), green.normalized(), blue.normalized(), alpha.normalized()])
    })
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glColor4uiv(v: *const GLuint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue, alpha]) = unsafe { read(v) } {
        glColor4ui(red, green, blue, alpha)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3b(red: GLbyte, green: GLbyte, blue: GLbyte) {
    record_or_run(move |ctx| ctx.set_secondary_color([red.normalized(), green.normalized(), blue.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3bv(v: *const GLbyte) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glSecondaryColor3b(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3s(red: GLshort, green: GLshort, blue: GLshort) {
    record_or_run(move |ctx| ctx.set_secondary_color([red.normalized(), green.normalized(), blue.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glSecondaryColor3s(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3i(red: GLint, green: GLint, blue: GLint) {
    record_or_run(move |ctx| ctx.set_secondary_color([red.normalized(), green.normalized(), blue.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glSecondaryColor3i(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3f(red: GLfloat, green: GLfloat, blue: GLfloat) {
    record_or_run(move |ctx| ctx.set_secondary_color([red.normalized(), green.normalized(), blue.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glSecondaryColor3f(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3d(red: GLdouble, green: GLdouble, blue: GLdouble) {
    record_or_run(move |ctx| ctx.set_secondary_color([red.normalized(), green.normalized(), blue.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glSecondaryColor3d(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3ub(red: GLubyte, green: GLubyte, blue: GLubyte) {
    record_or_run(move |ctx| ctx.set_secondary_color([red.normalized(), green.normalized(), blue.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3ubv(v: *const GLubyte) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glSecondaryColor3ub(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3us(red: GLushort, green: GLushort, blue: GLushort) {
    record_or_run(move |ctx| ctx.set_secondary_color([red.normalized(), green.normalized(), blue.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3usv(v: *const GLushort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glSecondaryColor3us(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3ui(red: GLuint, green: GLuint, blue: GLuint) {
    record_or_run(move |ctx| ctx.set_secondary_color([red.normalized(), green.normalized(), blue.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3uiv(v: *const GLuint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([red, green, blue]) = unsafe { read(v) } {
        glSecondaryColor3ui(red, green, blue)
    }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3bEXT(red: GLbyte, green: GLbyte, blue: GLbyte) {
    glSecondaryColor3b(red, green, blue)
}

/// # Safety
/// As [`glSecondaryColor3bv`].
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3bvEXT(v: *const GLbyte) {
    // SAFETY: the same contract as the core function.
    unsafe { glSecondaryColor3bv(v) }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3sEXT(red: GLshort, green: GLshort, blue: GLshort) {
    glSecondaryColor3s(red, green, blue)
}

/// # Safety
/// As [`glSecondaryColor3sv`].
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3svEXT(v: *const GLshort) {
    // SAFETY: the same contract as the core function.
    unsafe { glSecondaryColor3sv(v) }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3iEXT(red: GLint, green: GLint, blue: GLint) {
    glSecondaryColor3i(red, green, blue)
}

/// # Safety
/// As [`glSecondaryColor3iv`].
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3ivEXT(v: *const GLint) {
    // SAFETY: the same contract as the core function.
    unsafe { glSecondaryColor3iv(v) }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3fEXT(red: GLfloat, green: GLfloat, blue: GLfloat) {
    glSecondaryColor3f(red, green, blue)
}

/// # Safety
/// As [`glSecondaryColor3fv`].
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3fvEXT(v: *const GLfloat) {
    // SAFETY: the same contract as the core function.
    unsafe { glSecondaryColor3fv(v) }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3dEXT(red: GLdouble, green: GLdouble, blue: GLdouble) {
    glSecondaryColor3d(red, green, blue)
}

/// # Safety
/// As [`glSecondaryColor3dv`].
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3dvEXT(v: *const GLdouble) {
    // SAFETY: the same contract as the core function.
    unsafe { glSecondaryColor3dv(v) }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3ubEXT(red: GLubyte, green: GLubyte, blue: GLubyte) {
    glSecondaryColor3ub(red, green, blue)
}

/// # Safety
/// As [`glSecondaryColor3ubv`].
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3ubvEXT(v: *const GLubyte) {
    // SAFETY: the same contract as the core function.
    unsafe { glSecondaryColor3ubv(v) }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3usEXT(red: GLushort, green: GLushort, blue: GLushort) {
    glSecondaryColor3us(red, green, blue)
}

/// # Safety
/// As [`glSecondaryColor3usv`].
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3usvEXT(v: *const GLushort) {
    // SAFETY: the same contract as the core function.
    unsafe { glSecondaryColor3usv(v) }
}

#[no_mangle]
pub extern "C" fn glSecondaryColor3uiEXT(red: GLuint, green: GLuint, blue: GLuint) {
    glSecondaryColor3ui(red, green, blue)
}

/// # Safety
/// As [`glSecondaryColor3uiv`].
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3uivEXT(v: *const GLuint) {
    // SAFETY: the same contract as the core function.
    unsafe { glSecondaryColor3uiv(v) }
}

#[no_mangle]
pub extern "C" fn glNormal3b(nx: GLbyte, ny: GLbyte, nz: GLbyte) {
    record_or_run(move |ctx| ctx.set_normal([nx.normalized(), ny.normalized(), nz.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glNormal3bv(v: *const GLbyte) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([nx, ny, nz]) = unsafe { read(v) } {
        glNormal3b(nx, ny, nz)
    }
}

#[no_mangle]
pub extern "C" fn glNormal3s(nx: GLshort, ny: GLshort, nz: GLshort) {
    record_or_run(move |ctx| ctx.set_normal([nx.normalized(), ny.normalized(), nz.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glNormal3sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([nx, ny, nz]) = unsafe { read(v) } {
        glNormal3s(nx, ny, nz)
    }
}

#[no_mangle]
pub extern "C" fn glNormal3i(nx: GLint, ny: GLint, nz: GLint) {
    record_or_run(move |ctx| ctx.set_normal([nx.normalized(), ny.normalized(), nz.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glNormal3iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([nx, ny, nz]) = unsafe { read(v) } {
        glNormal3i(nx, ny, nz)
    }
}

#[no_mangle]
pub extern "C" fn glNormal3f(nx: GLfloat, ny: GLfloat, nz: GLfloat) {
    let normal = [nx.normalized(), ny.normalized(), nz.normalized()];
    fast_or_run(|ctx| ctx.try_set_normal(normal), move |ctx| ctx.set_normal(normal))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glNormal3fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([nx, ny, nz]) = unsafe { read(v) } {
        glNormal3f(nx, ny, nz)
    }
}

#[no_mangle]
pub extern "C" fn glNormal3d(nx: GLdouble, ny: GLdouble, nz: GLdouble) {
    record_or_run(move |ctx| ctx.set_normal([nx.normalized(), ny.normalized(), nz.normalized()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glNormal3dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([nx, ny, nz]) = unsafe { read(v) } {
        glNormal3d(nx, ny, nz)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord1s(s: GLshort) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), 0.0, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord1sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s]) = unsafe { read(v) } {
        glTexCoord1s(s)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord1i(s: GLint) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), 0.0, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord1iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s]) = unsafe { read(v) } {
        glTexCoord1i(s)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord1f(s: GLfloat) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s, 0.0, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord1fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s]) = unsafe { read(v) } {
        glTexCoord1f(s)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord1d(s: GLdouble) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), 0.0, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord1dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s]) = unsafe { read(v) } {
        glTexCoord1d(s)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord2s(s: GLshort, t: GLshort) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord2sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t]) = unsafe { read(v) } {
        glTexCoord2s(s, t)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord2i(s: GLint, t: GLint) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord2iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t]) = unsafe { read(v) } {
        glTexCoord2i(s, t)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord2f(s: GLfloat, t: GLfloat) {
    fast_or_run(|ctx| ctx.try_set_tex_coords0([s, t, 0.0, 1.0]), move |ctx| ctx.set_tex_coords(0, [s, t, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord2fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t]) = unsafe { read(v) } {
        glTexCoord2f(s, t)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord2d(s: GLdouble, t: GLdouble) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord2dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t]) = unsafe { read(v) } {
        glTexCoord2d(s, t)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord3s(s: GLshort, t: GLshort, r: GLshort) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), r.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord3sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r]) = unsafe { read(v) } {
        glTexCoord3s(s, t, r)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord3i(s: GLint, t: GLint, r: GLint) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), r.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord3iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r]) = unsafe { read(v) } {
        glTexCoord3i(s, t, r)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord3f(s: GLfloat, t: GLfloat, r: GLfloat) {
    fast_or_run(|ctx| ctx.try_set_tex_coords0([s, t, r, 1.0]), move |ctx| ctx.set_tex_coords(0, [s, t, r, 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord3fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r]) = unsafe { read(v) } {
        glTexCoord3f(s, t, r)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord3d(s: GLdouble, t: GLdouble, r: GLdouble) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), r.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord3dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r]) = unsafe { read(v) } {
        glTexCoord3d(s, t, r)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord4s(s: GLshort, t: GLshort, r: GLshort, q: GLshort) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), r.to_f32(), q.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord4sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r, q]) = unsafe { read(v) } {
        glTexCoord4s(s, t, r, q)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord4i(s: GLint, t: GLint, r: GLint, q: GLint) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), r.to_f32(), q.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord4iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r, q]) = unsafe { read(v) } {
        glTexCoord4i(s, t, r, q)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s, t, r, q]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord4fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r, q]) = unsafe { read(v) } {
        glTexCoord4f(s, t, r, q)
    }
}

#[no_mangle]
pub extern "C" fn glTexCoord4d(s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) {
    record_or_run(move |ctx| ctx.set_tex_coords(0, [s.to_f32(), t.to_f32(), r.to_f32(), q.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glTexCoord4dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r, q]) = unsafe { read(v) } {
        glTexCoord4d(s, t, r, q)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord1s(target: GLenum, s: GLshort) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), 0.0, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1sv(target: GLenum, v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s]) = unsafe { read(v) } {
        glMultiTexCoord1s(target, s)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord1i(target: GLenum, s: GLint) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), 0.0, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1iv(target: GLenum, v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s]) = unsafe { read(v) } {
        glMultiTexCoord1i(target, s)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord1f(target: GLenum, s: GLfloat) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s, 0.0, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1fv(target: GLenum, v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s]) = unsafe { read(v) } {
        glMultiTexCoord1f(target, s)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord1d(target: GLenum, s: GLdouble) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), 0.0, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1dv(target: GLenum, v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s]) = unsafe { read(v) } {
        glMultiTexCoord1d(target, s)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord2s(target: GLenum, s: GLshort, t: GLshort) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2sv(target: GLenum, v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t]) = unsafe { read(v) } {
        glMultiTexCoord2s(target, s, t)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord2i(target: GLenum, s: GLint, t: GLint) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2iv(target: GLenum, v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t]) = unsafe { read(v) } {
        glMultiTexCoord2i(target, s, t)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord2f(target: GLenum, s: GLfloat, t: GLfloat) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s, t, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2fv(target: GLenum, v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t]) = unsafe { read(v) } {
        glMultiTexCoord2f(target, s, t)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord2d(target: GLenum, s: GLdouble, t: GLdouble) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2dv(target: GLenum, v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t]) = unsafe { read(v) } {
        glMultiTexCoord2d(target, s, t)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord3s(target: GLenum, s: GLshort, t: GLshort, r: GLshort) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), r.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3sv(target: GLenum, v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r]) = unsafe { read(v) } {
        glMultiTexCoord3s(target, s, t, r)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord3i(target: GLenum, s: GLint, t: GLint, r: GLint) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), r.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3iv(target: GLenum, v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r]) = unsafe { read(v) } {
        glMultiTexCoord3i(target, s, t, r)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord3f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s, t, r, 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3fv(target: GLenum, v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r]) = unsafe { read(v) } {
        glMultiTexCoord3f(target, s, t, r)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord3d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), r.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3dv(target: GLenum, v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r]) = unsafe { read(v) } {
        glMultiTexCoord3d(target, s, t, r)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4s(target: GLenum, s: GLshort, t: GLshort, r: GLshort, q: GLshort) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), r.to_f32(), q.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4sv(target: GLenum, v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r, q]) = unsafe { read(v) } {
        glMultiTexCoord4s(target, s, t, r, q)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4i(target: GLenum, s: GLint, t: GLint, r: GLint, q: GLint) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), r.to_f32(), q.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4iv(target: GLenum, v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r, q]) = unsafe { read(v) } {
        glMultiTexCoord4i(target, s, t, r, q)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s, t, r, q]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4fv(target: GLenum, v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r, q]) = unsafe { read(v) } {
        glMultiTexCoord4f(target, s, t, r, q)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) {
    record_or_run(move |ctx| ctx.multi_tex_coord(target, [s.to_f32(), t.to_f32(), r.to_f32(), q.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4dv(target: GLenum, v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([s, t, r, q]) = unsafe { read(v) } {
        glMultiTexCoord4d(target, s, t, r, q)
    }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord1sARB(target: GLenum, s: GLshort) {
    glMultiTexCoord1s(target, s)
}

/// # Safety
/// As [`glMultiTexCoord1sv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1svARB(target: GLenum, v: *const GLshort) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord1sv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord1iARB(target: GLenum, s: GLint) {
    glMultiTexCoord1i(target, s)
}

/// # Safety
/// As [`glMultiTexCoord1iv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1ivARB(target: GLenum, v: *const GLint) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord1iv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord1fARB(target: GLenum, s: GLfloat) {
    glMultiTexCoord1f(target, s)
}

/// # Safety
/// As [`glMultiTexCoord1fv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1fvARB(target: GLenum, v: *const GLfloat) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord1fv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord1dARB(target: GLenum, s: GLdouble) {
    glMultiTexCoord1d(target, s)
}

/// # Safety
/// As [`glMultiTexCoord1dv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1dvARB(target: GLenum, v: *const GLdouble) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord1dv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord2sARB(target: GLenum, s: GLshort, t: GLshort) {
    glMultiTexCoord2s(target, s, t)
}

/// # Safety
/// As [`glMultiTexCoord2sv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2svARB(target: GLenum, v: *const GLshort) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord2sv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord2iARB(target: GLenum, s: GLint, t: GLint) {
    glMultiTexCoord2i(target, s, t)
}

/// # Safety
/// As [`glMultiTexCoord2iv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2ivARB(target: GLenum, v: *const GLint) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord2iv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord2fARB(target: GLenum, s: GLfloat, t: GLfloat) {
    glMultiTexCoord2f(target, s, t)
}

/// # Safety
/// As [`glMultiTexCoord2fv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2fvARB(target: GLenum, v: *const GLfloat) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord2fv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord2dARB(target: GLenum, s: GLdouble, t: GLdouble) {
    glMultiTexCoord2d(target, s, t)
}

/// # Safety
/// As [`glMultiTexCoord2dv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2dvARB(target: GLenum, v: *const GLdouble) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord2dv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord3sARB(target: GLenum, s: GLshort, t: GLshort, r: GLshort) {
    glMultiTexCoord3s(target, s, t, r)
}

/// # Safety
/// As [`glMultiTexCoord3sv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3svARB(target: GLenum, v: *const GLshort) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord3sv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord3iARB(target: GLenum, s: GLint, t: GLint, r: GLint) {
    glMultiTexCoord3i(target, s, t, r)
}

/// # Safety
/// As [`glMultiTexCoord3iv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3ivARB(target: GLenum, v: *const GLint) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord3iv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord3fARB(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat) {
    glMultiTexCoord3f(target, s, t, r)
}

/// # Safety
/// As [`glMultiTexCoord3fv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3fvARB(target: GLenum, v: *const GLfloat) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord3fv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord3dARB(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble) {
    glMultiTexCoord3d(target, s, t, r)
}

/// # Safety
/// As [`glMultiTexCoord3dv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3dvARB(target: GLenum, v: *const GLdouble) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord3dv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4sARB(target: GLenum, s: GLshort, t: GLshort, r: GLshort, q: GLshort) {
    glMultiTexCoord4s(target, s, t, r, q)
}

/// # Safety
/// As [`glMultiTexCoord4sv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4svARB(target: GLenum, v: *const GLshort) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord4sv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4iARB(target: GLenum, s: GLint, t: GLint, r: GLint, q: GLint) {
    glMultiTexCoord4i(target, s, t, r, q)
}

/// # Safety
/// As [`glMultiTexCoord4iv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4ivARB(target: GLenum, v: *const GLint) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord4iv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4fARB(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) {
    glMultiTexCoord4f(target, s, t, r, q)
}

/// # Safety
/// As [`glMultiTexCoord4fv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4fvARB(target: GLenum, v: *const GLfloat) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord4fv(target, v) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4dARB(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) {
    glMultiTexCoord4d(target, s, t, r, q)
}

/// # Safety
/// As [`glMultiTexCoord4dv`].
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4dvARB(target: GLenum, v: *const GLdouble) {
    // SAFETY: the same contract as the core function.
    unsafe { glMultiTexCoord4dv(target, v) }
}

#[no_mangle]
pub extern "C" fn glFogCoordf(coord: GLfloat) {
    record_or_run(move |ctx| ctx.set_fog_coord(coord))
}

/// # Safety
/// `coord` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glFogCoordfv(coord: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([coord]) = unsafe { read(coord) } {
        glFogCoordf(coord)
    }
}

#[no_mangle]
pub extern "C" fn glFogCoordd(coord: GLdouble) {
    record_or_run(move |ctx| ctx.set_fog_coord(coord.to_f32()))
}

/// # Safety
/// `coord` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glFogCoorddv(coord: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([coord]) = unsafe { read(coord) } {
        glFogCoordd(coord)
    }
}

#[no_mangle]
pub extern "C" fn glFogCoordfEXT(coord: GLfloat) {
    glFogCoordf(coord)
}

/// # Safety
/// As [`glFogCoordfv`].
#[no_mangle]
pub unsafe extern "C" fn glFogCoordfvEXT(coord: *const GLfloat) {
    // SAFETY: the same contract as the core function.
    unsafe { glFogCoordfv(coord) }
}

#[no_mangle]
pub extern "C" fn glFogCoorddEXT(coord: GLdouble) {
    glFogCoordd(coord)
}

/// # Safety
/// As [`glFogCoorddv`].
#[no_mangle]
pub unsafe extern "C" fn glFogCoorddvEXT(coord: *const GLdouble) {
    // SAFETY: the same contract as the core function.
    unsafe { glFogCoorddv(coord) }
}

#[no_mangle]
pub extern "C" fn glEdgeFlag(flag: GLboolean) {
    record_or_run(move |ctx| ctx.set_edge_flag(flag != 0))
}

/// # Safety
/// `flag` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glEdgeFlagv(flag: *const GLboolean) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([flag]) = unsafe { read(flag) } {
        glEdgeFlag(flag)
    }
}

#[no_mangle]
pub extern "C" fn glIndexs(c: GLshort) {
    record_or_run(move |ctx| ctx.set_index(c.to_f32()))
}

/// # Safety
/// `c` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glIndexsv(c: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([c]) = unsafe { read(c) } {
        glIndexs(c)
    }
}

#[no_mangle]
pub extern "C" fn glIndexi(c: GLint) {
    record_or_run(move |ctx| ctx.set_index(c.to_f32()))
}

/// # Safety
/// `c` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glIndexiv(c: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([c]) = unsafe { read(c) } {
        glIndexi(c)
    }
}

#[no_mangle]
pub extern "C" fn glIndexf(c: GLfloat) {
    record_or_run(move |ctx| ctx.set_index(c))
}

/// # Safety
/// `c` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glIndexfv(c: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([c]) = unsafe { read(c) } {
        glIndexf(c)
    }
}

#[no_mangle]
pub extern "C" fn glIndexd(c: GLdouble) {
    record_or_run(move |ctx| ctx.set_index(c.to_f32()))
}

/// # Safety
/// `c` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glIndexdv(c: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([c]) = unsafe { read(c) } {
        glIndexd(c)
    }
}

#[no_mangle]
pub extern "C" fn glIndexub(c: GLubyte) {
    record_or_run(move |ctx| ctx.set_index(c.to_f32()))
}

/// # Safety
/// `c` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glIndexubv(c: *const GLubyte) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([c]) = unsafe { read(c) } {
        glIndexub(c)
    }
}

#[no_mangle]
pub extern "C" fn glRects(x1: GLshort, y1: GLshort, x2: GLshort, y2: GLshort) {
    record_or_run(move |ctx| ctx.rect([x1.to_f32(), y1.to_f32()], [x2.to_f32(), y2.to_f32()]))
}

/// # Safety
/// `v1` and `v2` must each point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRectsv(v1: *const GLshort, v2: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let (Some([x1, y1]), Some([x2, y2])) = unsafe { (read(v1), read(v2)) } {
        glRects(x1, y1, x2, y2)
    }
}

#[no_mangle]
pub extern "C" fn glRecti(x1: GLint, y1: GLint, x2: GLint, y2: GLint) {
    record_or_run(move |ctx| ctx.rect([x1.to_f32(), y1.to_f32()], [x2.to_f32(), y2.to_f32()]))
}

/// # Safety
/// `v1` and `v2` must each point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRectiv(v1: *const GLint, v2: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let (Some([x1, y1]), Some([x2, y2])) = unsafe { (read(v1), read(v2)) } {
        glRecti(x1, y1, x2, y2)
    }
}

#[no_mangle]
pub extern "C" fn glRectf(x1: GLfloat, y1: GLfloat, x2: GLfloat, y2: GLfloat) {
    record_or_run(move |ctx| ctx.rect([x1, y1], [x2, y2]))
}

/// # Safety
/// `v1` and `v2` must each point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRectfv(v1: *const GLfloat, v2: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let (Some([x1, y1]), Some([x2, y2])) = unsafe { (read(v1), read(v2)) } {
        glRectf(x1, y1, x2, y2)
    }
}

#[no_mangle]
pub extern "C" fn glRectd(x1: GLdouble, y1: GLdouble, x2: GLdouble, y2: GLdouble) {
    record_or_run(move |ctx| ctx.rect([x1.to_f32(), y1.to_f32()], [x2.to_f32(), y2.to_f32()]))
}

/// # Safety
/// `v1` and `v2` must each point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRectdv(v1: *const GLdouble, v2: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let (Some([x1, y1]), Some([x2, y2])) = unsafe { (read(v1), read(v2)) } {
        glRectd(x1, y1, x2, y2)
    }
}
