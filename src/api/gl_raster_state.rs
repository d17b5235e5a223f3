//! Entry points for the rasterization state: shading, faces, polygon modes and offset, lines,
//! points and the polygon stipple.
use super::caller_memory;
use super::pixel_source::{PackDest, UnpackSource};
use super::{record_or_run, with_context};
use crate::context::Context;
use crate::gl::types::*;

#[no_mangle]
pub extern "C" fn glShadeModel(mode: GLenum) {
    record_or_run(move |ctx| ctx.shade_model(mode))
}

#[no_mangle]
pub extern "C" fn glProvokingVertex(mode: GLenum) {
    record_or_run(move |ctx| ctx.provoking_vertex(mode))
}

#[no_mangle]
pub extern "C" fn glProvokingVertexEXT(mode: GLenum) {
    glProvokingVertex(mode)
}

#[no_mangle]
pub extern "C" fn glFrontFace(mode: GLenum) {
    record_or_run(move |ctx| ctx.front_face(mode))
}

#[no_mangle]
pub extern "C" fn glCullFace(mode: GLenum) {
    record_or_run(move |ctx| ctx.cull_face(mode))
}

#[no_mangle]
pub extern "C" fn glPolygonMode(face: GLenum, mode: GLenum) {
    record_or_run(move |ctx| ctx.polygon_mode(face, mode))
}

#[no_mangle]
pub extern "C" fn glPolygonOffset(factor: GLfloat, units: GLfloat) {
    record_or_run(move |ctx| ctx.polygon_offset(factor, units, 0.0))
}

#[no_mangle]
pub extern "C" fn glPolygonOffsetClamp(factor: GLfloat, units: GLfloat, clamp: GLfloat) {
    record_or_run(move |ctx| ctx.polygon_offset(factor, units, clamp))
}

#[no_mangle]
pub extern "C" fn glPolygonOffsetClampEXT(factor: GLfloat, units: GLfloat, clamp: GLfloat) {
    glPolygonOffsetClamp(factor, units, clamp)
}

#[no_mangle]
pub extern "C" fn glSampleCoverage(value: GLclampf, invert: GLboolean) {
    record_or_run(move |ctx| ctx.sample_coverage(value, invert != 0))
}

#[no_mangle]
pub extern "C" fn glSampleCoverageARB(value: GLclampf, invert: GLboolean) {
    glSampleCoverage(value, invert)
}

#[no_mangle]
pub extern "C" fn glLineWidth(width: GLfloat) {
    record_or_run(move |ctx| ctx.line_width(width))
}

#[no_mangle]
pub extern "C" fn glLineStipple(factor: GLint, pattern: GLushort) {
    record_or_run(move |ctx| ctx.line_stipple(factor, pattern))
}

#[no_mangle]
pub extern "C" fn glPointSize(size: GLfloat) {
    record_or_run(move |ctx| ctx.point_size(size))
}

#[no_mangle]
pub extern "C" fn glPointParameterf(pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.point_parameter(pname, [param, 0.0, 0.0]))
}

#[no_mangle]
pub extern "C" fn glPointParameteri(pname: GLenum, param: GLint) {
    glPointParameterf(pname, param as GLfloat)
}

/// The values a glPointParameter*v pointer holds for `pname`, as floats; `None` for NULL.
///
/// # Safety
/// `params` is NULL or points to as many values as `pname` takes.
unsafe fn read_point_params<T: Copy + Into<f64>>(pname: GLenum, params: *const T) -> Option<[GLfloat; 3]> {
    let count = Context::point_parameter_count(pname).min(3);
    // SAFETY: the caller passes a pointer to `count` values (GL's contract for `pname`) or NULL.
    let read = unsafe { caller_memory::read_vec(params, count) }?;
    let mut values = [0.0; 3];
    for (value, v) in values.iter_mut().zip(read) {
        *value = v.into() as GLfloat;
    }
    Some(values)
}

/// # Safety
/// `params` is NULL (ignored) or points to 3 floats for GL_POINT_DISTANCE_ATTENUATION, else 1.
#[no_mangle]
pub unsafe extern "C" fn glPointParameterfv(pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(values) = unsafe { read_point_params(pname, params) } {
        record_or_run(move |ctx| ctx.point_parameter(pname, values))
    }
}

/// # Safety
/// `params` is NULL (ignored) or points to 3 integers for GL_POINT_DISTANCE_ATTENUATION, else 1.
#[no_mangle]
pub unsafe extern "C" fn glPointParameteriv(pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(values) = unsafe { read_point_params(pname, params) } {
        record_or_run(move |ctx| ctx.point_parameter(pname, values))
    }
}

#[no_mangle]
pub extern "C" fn glPointParameterfARB(pname: GLenum, param: GLfloat) {
    glPointParameterf(pname, param)
}

#[no_mangle]
pub extern "C" fn glPointParameterfEXT(pname: GLenum, param: GLfloat) {
    glPointParameterf(pname, param)
}

/// # Safety
/// As glPointParameterfv.
#[no_mangle]
pub unsafe extern "C" fn glPointParameterfvARB(pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glPointParameterfv(pname, params) }
}

/// # Safety
/// As glPointParameterfv.
#[no_mangle]
pub unsafe extern "C" fn glPointParameterfvEXT(pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glPointParameterfv(pname, params) }
}

/// # Safety
/// `mask` is NULL (ignored) or points to a 32×32 bitmap laid out as the unpack parameters of
/// glPixelStore describe.
#[no_mangle]
pub unsafe extern "C" fn glPolygonStipple(mask: *const GLubyte) {
    with_context((), |ctx| {
        // SAFETY: forwarded contract (a bitmap: no element alignment).
        let source = unsafe { UnpackSource::new(ctx, mask as *const GLvoid, 0) };
        let pattern = ctx.unpack_polygon_stipple(|span| source.bytes(span));
        ctx.record_or_run(move |ctx| ctx.set_polygon_stipple(pattern))
    })
}

/// # Safety
/// `mask` is NULL (nothing written) or points to room for a 32×32 bitmap laid out as the pack
/// parameters of glPixelStore describe; only the bits of the bitmap are written.
#[no_mangle]
pub unsafe extern "C" fn glGetPolygonStipple(mask: *mut GLubyte) {
    with_context((), |ctx| {
        // SAFETY: forwarded contract (a bitmap: no element alignment).
        let mut dest = unsafe { PackDest::new(ctx, mask as *mut GLvoid, 0) };
        let out = &mut dest;
        ctx.get_polygon_stipple(move |span| {
            let out = out;
            out.bytes_mut(span)
        });
        dest.finish();
    })
}
