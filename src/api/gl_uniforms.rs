//! Entry points for GLSL uniforms (GL 2.0/2.1): glUniform*, glUniformMatrix* (the 2.1
//! non-square forms included) and glGetUniform*. Setting a uniform is compiled into display
//! lists (GL 2.1 section 5.4 excludes only object creation and queries), so each setter
//! copies the caller's values before [`record_or_run`].
use super::caller_memory;
use super::{query, record_or_run, with_context};
use crate::context::shader_objects::UniformForm;
use crate::gl::types::*;

/// Reads the caller's `count` elements of `form` at `value` as words, no more than the
/// uniform at `location` can take (a wrong count is refused by the context without them).
///
/// # Safety
/// A non-null `value` must point to `count` elements of `form`'s components.
unsafe fn read_words<T: Copy>(
    location: GLint,
    count: GLsizei,
    form: UniformForm,
    value: *const T,
    bits: fn(T) -> u32,
) -> Vec<u32> {
    let elements = with_context(0, |ctx| ctx.uniform_room(location)).min(usize::try_from(count).unwrap_or(0));
    // SAFETY: the caller provides `count` elements; at most that many are read.
    let values = unsafe { caller_memory::read_vec(value, elements * form.components()) }.unwrap_or_default();
    values.into_iter().map(bits).collect()
}

fn float_bits(f: GLfloat) -> u32 {
    f.to_bits()
}

fn int_bits(i: GLint) -> u32 {
    i as u32
}

#[no_mangle]
pub extern "C" fn glUniform1f(location: GLint, v0: GLfloat) {
    record_or_run(move |ctx| ctx.set_uniform(location, 1, UniformForm::Float(1), &[v0.to_bits()]))
}

#[no_mangle]
pub extern "C" fn glUniform1i(location: GLint, v0: GLint) {
    record_or_run(move |ctx| ctx.set_uniform(location, 1, UniformForm::Int(1), &[v0 as u32]))
}

#[no_mangle]
pub extern "C" fn glUniform2f(location: GLint, v0: GLfloat, v1: GLfloat) {
    record_or_run(move |ctx| ctx.set_uniform(location, 1, UniformForm::Float(2), &[v0.to_bits(), v1.to_bits()]))
}

#[no_mangle]
pub extern "C" fn glUniform2i(location: GLint, v0: GLint, v1: GLint) {
    record_or_run(move |ctx| ctx.set_uniform(location, 1, UniformForm::Int(2), &[v0 as u32, v1 as u32]))
}

#[no_mangle]
pub extern "C" fn glUniform3f(location: GLint, v0: GLfloat, v1: GLfloat, v2: GLfloat) {
    record_or_run(move |ctx| {
        ctx.set_uniform(location, 1, UniformForm::Float(3), &[v0.to_bits(), v1.to_bits(), v2.to_bits()])
    })
}

#[no_mangle]
pub extern "C" fn glUniform3i(location: GLint, v0: GLint, v1: GLint, v2: GLint) {
    record_or_run(move |ctx| ctx.set_uniform(location, 1, UniformForm::Int(3), &[v0 as u32, v1 as u32, v2 as u32]))
}

#[no_mangle]
pub extern "C" fn glUniform4f(location: GLint, v0: GLfloat, v1: GLfloat, v2: GLfloat, v3: GLfloat) {
    record_or_run(move |ctx| {
        ctx.set_uniform(location, 1, UniformForm::Float(4), &[v0.to_bits(), v1.to_bits(), v2.to_bits(), v3.to_bits()])
    })
}

#[no_mangle]
pub extern "C" fn glUniform4i(location: GLint, v0: GLint, v1: GLint, v2: GLint, v3: GLint) {
    record_or_run(move |ctx| {
        ctx.set_uniform(location, 1, UniformForm::Int(4), &[v0 as u32, v1 as u32, v2 as u32, v3 as u32])
    })
}

/// # Safety
/// A non-null `value` must point to `count` × 1 values.
#[no_mangle]
pub unsafe extern "C" fn glUniform1fv(location: GLint, count: GLsizei, value: *const GLfloat) {
    let form = UniformForm::Float(1);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 1 values.
#[no_mangle]
pub unsafe extern "C" fn glUniform1iv(location: GLint, count: GLsizei, value: *const GLint) {
    let form = UniformForm::Int(1);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, int_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 2 values.
#[no_mangle]
pub unsafe extern "C" fn glUniform2fv(location: GLint, count: GLsizei, value: *const GLfloat) {
    let form = UniformForm::Float(2);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 2 values.
#[no_mangle]
pub unsafe extern "C" fn glUniform2iv(location: GLint, count: GLsizei, value: *const GLint) {
    let form = UniformForm::Int(2);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, int_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 3 values.
#[no_mangle]
pub unsafe extern "C" fn glUniform3fv(location: GLint, count: GLsizei, value: *const GLfloat) {
    let form = UniformForm::Float(3);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 3 values.
#[no_mangle]
pub unsafe extern "C" fn glUniform3iv(location: GLint, count: GLsizei, value: *const GLint) {
    let form = UniformForm::Int(3);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, int_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 4 values.
#[no_mangle]
pub unsafe extern "C" fn glUniform4fv(location: GLint, count: GLsizei, value: *const GLfloat) {
    let form = UniformForm::Float(4);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 4 values.
#[no_mangle]
pub unsafe extern "C" fn glUniform4iv(location: GLint, count: GLsizei, value: *const GLint) {
    let form = UniformForm::Int(4);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, int_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 4 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix2fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(2, 2, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 9 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix3fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(3, 3, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 16 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix4fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(4, 4, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 6 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix2x3fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(2, 3, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 6 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix3x2fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(3, 2, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 8 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix2x4fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(2, 4, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 8 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix4x2fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(4, 2, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 12 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix3x4fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(3, 4, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// A non-null `value` must point to `count` × 12 values.
#[no_mangle]
pub unsafe extern "C" fn glUniformMatrix4x3fv(
    location: GLint,
    count: GLsizei,
    transpose: GLboolean,
    value: *const GLfloat,
) {
    let form = UniformForm::Matrix(4, 3, transpose != 0);
    // SAFETY: as this function's contract.
    let values = unsafe { read_words(location, count, form, value, float_bits) };
    record_or_run(move |ctx| ctx.set_uniform(location, count, form, &values))
}

/// # Safety
/// `params` must have room for the uniform element's components (NULL writes nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetUniformfv(program: GLuint, location: GLint, params: *mut GLfloat) {
    let Some(words) = query(|ctx| ctx.get_uniform(program, location, true)) else { return };
    // SAFETY: the caller provides room for the element's components (or passes NULL).
    unsafe { caller_memory::write_all(params, words.into_iter().map(f32::from_bits)) }
}

/// # Safety
/// `params` must have room for the uniform element's components (NULL writes nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetUniformiv(program: GLuint, location: GLint, params: *mut GLint) {
    let Some(words) = query(|ctx| ctx.get_uniform(program, location, false)) else { return };
    // SAFETY: the caller provides room for the element's components (or passes NULL).
    unsafe { caller_memory::write_all(params, words.into_iter().map(|w| w as i32)) }
}
