//! Evaluator entry points: glMap1/glMap2, glGetMap, glMapGrid, glEvalCoord, glEvalPoint and
//! glEvalMesh (`context::evaluators`).
//!
//! glMap reads its control points here, with the strides, into owned values (so a display
//! list keeps them, as section 5.4 says), but only when the target, orders and strides are
//! valid: otherwise nothing is read and the context reports the error. Every command but
//! glGetMap is compiled into display lists. Double-precision arguments become floats, as
//! Mesa keeps them.
use super::caller_memory::{self, read};
use super::{record_or_run, with_context};
use crate::context::evaluators::readable_map;
use crate::gl::types::*;
use crate::vertex::bezier::Point;

/// The control points of a map at `points`: `orders[0] × orders[1]` points of `components`
/// values, point (i, j) starting `i · strides[0] + j · strides[1]` values in; `None` for
/// NULL or arguments glMap rejects.
///
/// # Safety
/// A non-null `points` must hold every value those strides and orders address.
unsafe fn read_points<T: Copy>(
    target: GLenum,
    dimensions: usize,
    orders: [GLint; 2],
    strides: [GLint; 2],
    points: *const T,
    to_f32: impl Fn(T) -> f32,
) -> Option<Vec<Point>> {
    let components = readable_map(target, dimensions, orders, strides)?;
    if points.is_null() {
        return None;
    }
    let [uorder, vorder] = orders.map(|o| o as usize);
    let [ustride, vstride] = strides.map(|s| s as usize);
    let mut out = Vec::new();
    out.try_reserve_exact(uorder * vorder).ok()?;
    for i in 0..uorder {
        for j in 0..vorder {
            let mut point = [0.0; 4];
            for (c, value) in point.iter_mut().enumerate().take(components) {
                let offset = i * ustride + j * vstride + c;
                // SAFETY: the caller's array holds the values the strides and orders address
                // (GL's contract for glMap).
                *value = to_f32(unsafe { caller_memory::read_at(points, offset) }?);
            }
            out.push(point);
        }
    }
    Some(out)
}

/// # Safety
/// `points` must hold `order` control points `stride` values apart (NULL is an error).
#[no_mangle]
pub unsafe extern "C" fn glMap1f(
    target: GLenum,
    u1: GLfloat,
    u2: GLfloat,
    stride: GLint,
    order: GLint,
    points: *const GLfloat,
) {
    // SAFETY: forwarded contract of this entry point.
    let points = unsafe { read_points(target, 1, [order, 1], [stride, 0], points, |v| v) };
    record_or_run(move |ctx| ctx.map1(target, [u1, u2], stride, order, points.clone()))
}

/// # Safety
/// `points` must hold `order` control points `stride` values apart (NULL is an error).
#[no_mangle]
pub unsafe extern "C" fn glMap1d(
    target: GLenum,
    u1: GLdouble,
    u2: GLdouble,
    stride: GLint,
    order: GLint,
    points: *const GLdouble,
) {
    // SAFETY: forwarded contract of this entry point.
    let points = unsafe { read_points(target, 1, [order, 1], [stride, 0], points, |v| v as f32) };
    let domain = [u1 as f32, u2 as f32];
    record_or_run(move |ctx| ctx.map1(target, domain, stride, order, points.clone()))
}

/// # Safety
/// `points` must hold `uorder × vorder` control points laid out with the strides (NULL is an
/// error).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glMap2f(
    target: GLenum,
    u1: GLfloat,
    u2: GLfloat,
    ustride: GLint,
    uorder: GLint,
    v1: GLfloat,
    v2: GLfloat,
    vstride: GLint,
    vorder: GLint,
    points: *const GLfloat,
) {
    let (orders, strides) = ([uorder, vorder], [ustride, vstride]);
    // SAFETY: forwarded contract of this entry point.
    let points = unsafe { read_points(target, 2, orders, strides, points, |v| v) };
    record_or_run(move |ctx| ctx.map2(target, [u1, u2, v1, v2], strides, orders, points.clone()))
}

/// # Safety
/// `points` must hold `uorder × vorder` control points laid out with the strides (NULL is an
/// error).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glMap2d(
    target: GLenum,
    u1: GLdouble,
    u2: GLdouble,
    ustride: GLint,
    uorder: GLint,
    v1: GLdouble,
    v2: GLdouble,
    vstride: GLint,
    vorder: GLint,
    points: *const GLdouble,
) {
    let (orders, strides) = ([uorder, vorder], [ustride, vstride]);
    // SAFETY: forwarded contract of this entry point.
    let points = unsafe { read_points(target, 2, orders, strides, points, |v| v as f32) };
    let domain = [u1, u2, v1, v2].map(|d| d as f32);
    record_or_run(move |ctx| ctx.map2(target, domain, strides, orders, points.clone()))
}

/// Writes glGetMap's answer, each value converted by `convert`.
///
/// # Safety
/// `v` must have room for the values the query returns.
unsafe fn write_map<T>(target: GLenum, query: GLenum, v: *mut T, convert: impl Fn(crate::context::get::Value) -> T) {
    with_context((), |ctx| {
        let Some(values) = ctx.get_map(target, query) else {
            return;
        };
        // SAFETY: the caller provides room for the query's values (or passes NULL).
        unsafe { caller_memory::write_all(v, values.iter().map(|&value| convert(value))) }
    })
}

/// # Safety
/// `v` must have room for the values the query returns.
#[no_mangle]
pub unsafe extern "C" fn glGetMapfv(target: GLenum, query: GLenum, v: *mut GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_map(target, query, v, |value| value.to_float()) }
}

/// # Safety
/// `v` must have room for the values the query returns.
#[no_mangle]
pub unsafe extern "C" fn glGetMapdv(target: GLenum, query: GLenum, v: *mut GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_map(target, query, v, |value| value.to_double()) }
}

/// # Safety
/// `v` must have room for the values the query returns.
#[no_mangle]
pub unsafe extern "C" fn glGetMapiv(target: GLenum, query: GLenum, v: *mut GLint) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_map(target, query, v, |value| value.to_integer()) }
}

#[no_mangle]
pub extern "C" fn glMapGrid1f(un: GLint, u1: GLfloat, u2: GLfloat) {
    record_or_run(move |ctx| ctx.map_grid1(un, [u1, u2]))
}

#[no_mangle]
pub extern "C" fn glMapGrid1d(un: GLint, u1: GLdouble, u2: GLdouble) {
    glMapGrid1f(un, u1 as f32, u2 as f32)
}

#[no_mangle]
pub extern "C" fn glMapGrid2f(un: GLint, u1: GLfloat, u2: GLfloat, vn: GLint, v1: GLfloat, v2: GLfloat) {
    record_or_run(move |ctx| ctx.map_grid2([un, vn], [u1, u2, v1, v2]))
}

#[no_mangle]
pub extern "C" fn glMapGrid2d(un: GLint, u1: GLdouble, u2: GLdouble, vn: GLint, v1: GLdouble, v2: GLdouble) {
    glMapGrid2f(un, u1 as f32, u2 as f32, vn, v1 as f32, v2 as f32)
}

#[no_mangle]
pub extern "C" fn glEvalCoord1f(u: GLfloat) {
    record_or_run(move |ctx| ctx.eval_coord1(u))
}

#[no_mangle]
pub extern "C" fn glEvalCoord1d(u: GLdouble) {
    glEvalCoord1f(u as f32)
}

/// # Safety
/// `u` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glEvalCoord1fv(u: *const GLfloat) {
    // SAFETY: the caller provides one readable value (or NULL).
    if let Some([a]) = unsafe { read(u) } {
        glEvalCoord1f(a)
    }
}

/// # Safety
/// `u` must point to 1 value (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glEvalCoord1dv(u: *const GLdouble) {
    // SAFETY: the caller provides one readable value (or NULL).
    if let Some([a]) = unsafe { read(u) } {
        glEvalCoord1d(a)
    }
}

#[no_mangle]
pub extern "C" fn glEvalCoord2f(u: GLfloat, v: GLfloat) {
    record_or_run(move |ctx| ctx.eval_coord2([u, v]))
}

#[no_mangle]
pub extern "C" fn glEvalCoord2d(u: GLdouble, v: GLdouble) {
    glEvalCoord2f(u as f32, v as f32)
}

/// # Safety
/// `u` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glEvalCoord2fv(u: *const GLfloat) {
    // SAFETY: the caller provides two readable values (or NULL).
    if let Some([a, b]) = unsafe { read(u) } {
        glEvalCoord2f(a, b)
    }
}

/// # Safety
/// `u` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glEvalCoord2dv(u: *const GLdouble) {
    // SAFETY: the caller provides two readable values (or NULL).
    if let Some([a, b]) = unsafe { read(u) } {
        glEvalCoord2d(a, b)
    }
}

#[no_mangle]
pub extern "C" fn glEvalPoint1(i: GLint) {
    record_or_run(move |ctx| ctx.eval_point1(i))
}

#[no_mangle]
pub extern "C" fn glEvalPoint2(i: GLint, j: GLint) {
    record_or_run(move |ctx| ctx.eval_point2(i, j))
}

#[no_mangle]
pub extern "C" fn glEvalMesh1(mode: GLenum, i1: GLint, i2: GLint) {
    record_or_run(move |ctx| ctx.eval_mesh1(mode, i1, i2))
}

#[no_mangle]
pub extern "C" fn glEvalMesh2(mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint) {
    record_or_run(move |ctx| ctx.eval_mesh2(mode, [i1, i2], [j1, j2]))
}
