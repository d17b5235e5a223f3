//! Entry points for lights, the light model, materials and color material.
use super::caller_memory::{read_vec, write_all};
use super::{guard, record_or_run};
use crate::context::lighting::{
    int_params_to_float, light_model_param_count, light_param_count, material_param_count, values_to_integers,
};
use crate::context::Context;
use crate::gl::types::*;

#[no_mangle]
pub extern "C" fn glLightf(light: GLenum, pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.light_scalar(light, pname, param))
}

#[no_mangle]
pub extern "C" fn glLighti(light: GLenum, pname: GLenum, param: GLint) {
    record_or_run(move |ctx| ctx.light_scalar(light, pname, param as GLfloat))
}

/// # Safety
/// `params` is NULL (ignored) or points to as many floats as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(p) = unsafe { read_vec(params, light_param_count(pname)) } {
        record_or_run(move |ctx| ctx.light(light, pname, &p))
    }
}

/// # Safety
/// `params` is NULL (ignored) or points to as many integers as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glLightiv(light: GLenum, pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(p) = unsafe { read_vec(params, light_param_count(pname)) } {
        record_or_run(move |ctx| ctx.light(light, pname, &int_params_to_float(pname, &p)))
    }
}

/// # Safety
/// `params` is NULL or has room for as many floats as `pname` returns.
#[no_mangle]
pub unsafe extern "C" fn glGetLightfv(light: GLenum, pname: GLenum, params: *mut GLfloat) {
    let values = query(|ctx| ctx.get_light(light, pname).iter().map(|v| v.to_float()).collect());
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_all(params, values) }
}

/// # Safety
/// `params` is NULL or has room for as many integers as `pname` returns.
#[no_mangle]
pub unsafe extern "C" fn glGetLightiv(light: GLenum, pname: GLenum, params: *mut GLint) {
    let values = query(|ctx| values_to_integers(&ctx.get_light(light, pname), false));
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_all(params, values) }
}

#[no_mangle]
pub extern "C" fn glLightModelf(pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.light_model_scalar(pname, param))
}

#[no_mangle]
pub extern "C" fn glLightModeli(pname: GLenum, param: GLint) {
    record_or_run(move |ctx| ctx.light_model_scalar(pname, param as GLfloat))
}

/// # Safety
/// `params` is NULL (ignored) or points to as many floats as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glLightModelfv(pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(p) = unsafe { read_vec(params, light_model_param_count(pname)) } {
        record_or_run(move |ctx| ctx.light_model(pname, &p))
    }
}

/// # Safety
/// `params` is NULL (ignored) or points to as many integers as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glLightModeliv(pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(p) = unsafe { read_vec(params, light_model_param_count(pname)) } {
        record_or_run(move |ctx| ctx.light_model(pname, &int_params_to_float(pname, &p)))
    }
}

#[no_mangle]
pub extern "C" fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.material_scalar(face, pname, param))
}

#[no_mangle]
pub extern "C" fn glMateriali(face: GLenum, pname: GLenum, param: GLint) {
    record_or_run(move |ctx| ctx.material_scalar(face, pname, param as GLfloat))
}

/// # Safety
/// `params` is NULL (ignored) or points to as many floats as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(p) = unsafe { read_vec(params, material_param_count(pname)) } {
        record_or_run(move |ctx| ctx.material(face, pname, &p))
    }
}

/// # Safety
/// `params` is NULL (ignored) or points to as many integers as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glMaterialiv(face: GLenum, pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some(p) = unsafe { read_vec(params, material_param_count(pname)) } {
        record_or_run(move |ctx| ctx.material(face, pname, &int_params_to_float(pname, &p)))
    }
}

/// # Safety
/// `params` is NULL or has room for as many floats as `pname` returns.
#[no_mangle]
pub unsafe extern "C" fn glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat) {
    let values = query(|ctx| ctx.get_material(face, pname).iter().map(|v| v.to_float()).collect());
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_all(params, values) }
}

/// # Safety
/// `params` is NULL or has room for as many integers as `pname` returns.
#[no_mangle]
pub unsafe extern "C" fn glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut GLint) {
    let values = query(|ctx| values_to_integers(&ctx.get_material(face, pname), true));
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_all(params, values) }
}

#[no_mangle]
pub extern "C" fn glColorMaterial(face: GLenum, mode: GLenum) {
    record_or_run(move |ctx| ctx.color_material(face, mode))
}

/// Runs a query returning a vector; empty when there is no context.
fn query<T>(f: impl FnOnce(&mut Context) -> Vec<T>) -> Vec<T> {
    guard(Vec::new(), || crate::context::current::with_current(f).unwrap_or_default())
}
