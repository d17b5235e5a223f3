//! Entry points for generic vertex attributes (GL 2.0): glVertexAttrib* in every form,
//! glVertexAttribPointer, glEnable/DisableVertexAttribArray and the glGetVertexAttrib* queries.
use super::caller_memory::{self, read};
use super::{query, record_or_run, with_context};
use crate::gl::types::*;
use crate::vertex::components::Component;

/// Missing components of a glVertexAttrib form: (0, 0, 0, 1).
fn widen<const N: usize>(v: [f32; N]) -> [f32; 4] {
    let mut out = [0.0, 0.0, 0.0, 1.0];
    out[..N].copy_from_slice(&v);
    out
}

#[no_mangle]
pub extern "C" fn glVertexAttrib1s(index: GLuint, x: GLshort) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x.to_f32()])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib1f(index: GLuint, x: GLfloat) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib1d(index: GLuint, x: GLdouble) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x as f32])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib2s(index: GLuint, x: GLshort, y: GLshort) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x.to_f32(), y.to_f32()])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib2f(index: GLuint, x: GLfloat, y: GLfloat) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x, y])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib2d(index: GLuint, x: GLdouble, y: GLdouble) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x as f32, y as f32])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib3s(index: GLuint, x: GLshort, y: GLshort, z: GLshort) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x.to_f32(), y.to_f32(), z.to_f32()])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib3f(index: GLuint, x: GLfloat, y: GLfloat, z: GLfloat) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x, y, z])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib3d(index: GLuint, x: GLdouble, y: GLdouble, z: GLdouble) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x as f32, y as f32, z as f32])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib4s(index: GLuint, x: GLshort, y: GLshort, z: GLshort, w: GLshort) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x.to_f32(), y.to_f32(), z.to_f32(), w.to_f32()])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib4f(index: GLuint, x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x, y, z, w])))
}

#[no_mangle]
pub extern "C" fn glVertexAttrib4d(index: GLuint, x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, widen([x as f32, y as f32, z as f32, w as f32])))
}

/// # Safety
/// `v` must point to 1 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib1sv(index: GLuint, v: *const GLshort) {
    // SAFETY: the caller provides 1 values at `v`.
    if let Some(v) = unsafe { read::<_, 1>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0].to_f32()])))
    }
}

/// # Safety
/// `v` must point to 1 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib1fv(index: GLuint, v: *const GLfloat) {
    // SAFETY: the caller provides 1 values at `v`.
    if let Some(v) = unsafe { read::<_, 1>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0]])))
    }
}

/// # Safety
/// `v` must point to 1 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib1dv(index: GLuint, v: *const GLdouble) {
    // SAFETY: the caller provides 1 values at `v`.
    if let Some(v) = unsafe { read::<_, 1>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0] as f32])))
    }
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib2sv(index: GLuint, v: *const GLshort) {
    // SAFETY: the caller provides 2 values at `v`.
    if let Some(v) = unsafe { read::<_, 2>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0].to_f32(), v[1].to_f32()])))
    }
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib2fv(index: GLuint, v: *const GLfloat) {
    // SAFETY: the caller provides 2 values at `v`.
    if let Some(v) = unsafe { read::<_, 2>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0], v[1]])))
    }
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib2dv(index: GLuint, v: *const GLdouble) {
    // SAFETY: the caller provides 2 values at `v`.
    if let Some(v) = unsafe { read::<_, 2>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0] as f32, v[1] as f32])))
    }
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib3sv(index: GLuint, v: *const GLshort) {
    // SAFETY: the caller provides 3 values at `v`.
    if let Some(v) = unsafe { read::<_, 3>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0].to_f32(), v[1].to_f32(), v[2].to_f32()])))
    }
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib3fv(index: GLuint, v: *const GLfloat) {
    // SAFETY: the caller provides 3 values at `v`.
    if let Some(v) = unsafe { read::<_, 3>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0], v[1], v[2]])))
    }
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib3dv(index: GLuint, v: *const GLdouble) {
    // SAFETY: the caller provides 3 values at `v`.
    if let Some(v) = unsafe { read::<_, 3>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0] as f32, v[1] as f32, v[2] as f32])))
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4sv(index: GLuint, v: *const GLshort) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(index, widen([v[0].to_f32(), v[1].to_f32(), v[2].to_f32(), v[3].to_f32()]))
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4fv(index: GLuint, v: *const GLfloat) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0], v[1], v[2], v[3]])))
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4dv(index: GLuint, v: *const GLdouble) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| ctx.vertex_attrib(index, widen([v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])))
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4bv(index: GLuint, v: *const GLbyte) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(index, widen([v[0].to_f32(), v[1].to_f32(), v[2].to_f32(), v[3].to_f32()]))
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4iv(index: GLuint, v: *const GLint) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(index, widen([v[0].to_f32(), v[1].to_f32(), v[2].to_f32(), v[3].to_f32()]))
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4ubv(index: GLuint, v: *const GLubyte) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(index, widen([v[0].to_f32(), v[1].to_f32(), v[2].to_f32(), v[3].to_f32()]))
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4usv(index: GLuint, v: *const GLushort) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(index, widen([v[0].to_f32(), v[1].to_f32(), v[2].to_f32(), v[3].to_f32()]))
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4uiv(index: GLuint, v: *const GLuint) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(index, widen([v[0].to_f32(), v[1].to_f32(), v[2].to_f32(), v[3].to_f32()]))
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4Nbv(index: GLuint, v: *const GLbyte) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(
                index,
                widen([v[0].normalized(), v[1].normalized(), v[2].normalized(), v[3].normalized()]),
            )
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4Nsv(index: GLuint, v: *const GLshort) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(
                index,
                widen([v[0].normalized(), v[1].normalized(), v[2].normalized(), v[3].normalized()]),
            )
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4Niv(index: GLuint, v: *const GLint) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(
                index,
                widen([v[0].normalized(), v[1].normalized(), v[2].normalized(), v[3].normalized()]),
            )
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4Nubv(index: GLuint, v: *const GLubyte) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(
                index,
                widen([v[0].normalized(), v[1].normalized(), v[2].normalized(), v[3].normalized()]),
            )
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4Nusv(index: GLuint, v: *const GLushort) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(
                index,
                widen([v[0].normalized(), v[1].normalized(), v[2].normalized(), v[3].normalized()]),
            )
        })
    }
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glVertexAttrib4Nuiv(index: GLuint, v: *const GLuint) {
    // SAFETY: the caller provides 4 values at `v`.
    if let Some(v) = unsafe { read::<_, 4>(v) } {
        record_or_run(move |ctx| {
            ctx.vertex_attrib(
                index,
                widen([v[0].normalized(), v[1].normalized(), v[2].normalized(), v[3].normalized()]),
            )
        })
    }
}

#[no_mangle]
pub extern "C" fn glVertexAttrib4Nub(index: GLuint, x: GLubyte, y: GLubyte, z: GLubyte, w: GLubyte) {
    record_or_run(move |ctx| ctx.vertex_attrib(index, [x.normalized(), y.normalized(), z.normalized(), w.normalized()]))
}

#[no_mangle]
pub extern "C" fn glVertexAttribPointer(
    index: GLuint,
    size: GLint,
    type_: GLenum,
    normalized: GLboolean,
    stride: GLsizei,
    pointer: *const GLvoid,
) {
    with_context((), |ctx| ctx.vertex_attrib_pointer(index, size, type_, normalized != 0, stride, pointer as usize))
}

#[no_mangle]
pub extern "C" fn glEnableVertexAttribArray(index: GLuint) {
    with_context((), |ctx| ctx.enable_vertex_attrib_array(index, true))
}

#[no_mangle]
pub extern "C" fn glDisableVertexAttribArray(index: GLuint) {
    with_context((), |ctx| ctx.enable_vertex_attrib_array(index, false))
}

/// # Safety
/// `params` must have room for 4 values for GL_CURRENT_VERTEX_ATTRIB, else 1 (NULL writes
/// nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetVertexAttribfv(index: GLuint, pname: GLenum, params: *mut GLfloat) {
    if let Some(value) = query(|ctx| ctx.get_vertex_attrib(index, pname)) {
        // SAFETY: the caller provides room for the values `pname` has.
        unsafe { caller_memory::write_all(params, value.floats().into_iter().map(|v| v as f32)) }
    }
}

/// # Safety
/// As [`glGetVertexAttribfv`].
#[no_mangle]
pub unsafe extern "C" fn glGetVertexAttribdv(index: GLuint, pname: GLenum, params: *mut GLdouble) {
    if let Some(value) = query(|ctx| ctx.get_vertex_attrib(index, pname)) {
        // SAFETY: the caller provides room for the values `pname` has.
        unsafe { caller_memory::write_all(params, value.floats()) }
    }
}

/// # Safety
/// As [`glGetVertexAttribfv`].
#[no_mangle]
pub unsafe extern "C" fn glGetVertexAttribiv(index: GLuint, pname: GLenum, params: *mut GLint) {
    if let Some(value) = query(|ctx| ctx.get_vertex_attrib(index, pname)) {
        // SAFETY: the caller provides room for the values `pname` has.
        unsafe { caller_memory::write_all(params, value.integers()) }
    }
}

/// # Safety
/// `pointer` must have room for one pointer (NULL writes nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetVertexAttribPointerv(index: GLuint, pname: GLenum, pointer: *mut *mut GLvoid) {
    let address = query(|ctx| ctx.get_vertex_attrib_pointer(index, pname));
    if let Some(address) = address {
        // SAFETY: the caller provides room for one pointer (or passes NULL).
        unsafe { caller_memory::write(pointer, address as *mut GLvoid) }
    }
}
