//! Entry points for GLSL shader and program objects (GL 2.0).
use super::caller_memory;
use super::{guard, query, record_or_run, with_context};
use crate::context::{current, Context};
use crate::gl::enums::{GL_INVALID_OPERATION, GL_INVALID_VALUE};
use crate::gl::types::*;

/// Writes `text` into the caller's `buffer` of `buffer_size` bytes as GL's string queries do
/// (at most `buffer_size - 1` bytes and a NUL) and its length without the NUL to `length`.
///
/// # Safety
/// A non-null `buffer` must have room for `buffer_size` bytes; a non-null `length` for one
/// value.
unsafe fn write_string(text: &str, buffer_size: GLsizei, length: *mut GLsizei, buffer: *mut GLchar) {
    let size = usize::try_from(buffer_size).unwrap_or(0);
    let (count, bytes) = crate::context::shader_objects::copy_out(text, if buffer.is_null() { 0 } else { size });
    // SAFETY: the caller provides room for `buffer_size` bytes, and `bytes` holds at most that.
    unsafe { caller_memory::write_all(buffer as *mut u8, bytes) };
    // SAFETY: the caller provides room for one value (or passes NULL).
    unsafe { caller_memory::write(length, count as GLsizei) };
}

#[no_mangle]
pub extern "C" fn glCreateShader(shaderType: GLenum) -> GLuint {
    with_context(0, |ctx| ctx.create_shader(shaderType))
}

#[no_mangle]
pub extern "C" fn glCreateProgram() -> GLuint {
    with_context(0, |ctx| ctx.create_program())
}

/// # Safety
/// `string` must point to `count` pointers, each (when `length` is NULL or its entry is
/// negative) to a NUL-terminated string or else to `length[i]` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glShaderSource(
    shader: GLuint,
    count: GLsizei,
    string: *const *const GLchar,
    length: *const GLint,
) {
    // The name first, as Mesa checks it: a call on a name that is no shader raises its
    // error without reading the strings (piglit's shadersource-errors passes garbage there).
    if !with_context(false, |ctx| ctx.shader_source_text(shader).is_some()) {
        return;
    }
    if count < 0 || string.is_null() {
        return with_context((), |ctx| ctx.shader_source(shader, Err(GL_INVALID_VALUE)));
    }
    // SAFETY: the caller provides `count` pointers at `string`.
    let pointers = unsafe { caller_memory::read_array(string, count) };
    let lengths = if length.is_null() {
        vec![-1; pointers.len()]
    } else {
        // SAFETY: a non-null `length` points to `count` values.
        unsafe { caller_memory::read_array(length, count) }
    };
    let mut pieces = Ok(Vec::with_capacity(pointers.len()));
    for (&pointer, &len) in pointers.iter().zip(&lengths) {
        let piece = if len < 0 {
            // SAFETY: a piece without a length is NUL-terminated by the contract.
            unsafe { caller_memory::c_str(pointer) }.map(|s| s.to_bytes().to_vec())
        } else {
            // SAFETY: a piece with a length has that many readable bytes by the contract.
            unsafe { caller_memory::bytes(pointer, 0..len as usize) }.map(<[u8]>::to_vec)
        };
        match (piece, pieces.as_mut()) {
            (Some(piece), Ok(list)) => list.push(piece),
            _ => pieces = Err(GL_INVALID_OPERATION),
        }
    }
    with_context((), |ctx| ctx.shader_source(shader, pieces))
}

#[no_mangle]
pub extern "C" fn glCompileShader(shader: GLuint) {
    with_context((), |ctx| ctx.compile_shader(shader))
}

#[no_mangle]
pub extern "C" fn glDeleteShader(shader: GLuint) {
    with_context((), |ctx| ctx.delete_shader(shader))
}

#[no_mangle]
pub extern "C" fn glDeleteProgram(program: GLuint) {
    with_context((), |ctx| ctx.delete_program(program))
}

#[no_mangle]
pub extern "C" fn glIsShader(shader: GLuint) -> GLboolean {
    with_context(0, |ctx| ctx.is_shader(shader) as GLboolean)
}

#[no_mangle]
pub extern "C" fn glIsProgram(program: GLuint) -> GLboolean {
    with_context(0, |ctx| ctx.is_program(program) as GLboolean)
}

#[no_mangle]
pub extern "C" fn glAttachShader(program: GLuint, shader: GLuint) {
    with_context((), |ctx| ctx.attach_shader(program, shader))
}

#[no_mangle]
pub extern "C" fn glDetachShader(program: GLuint, shader: GLuint) {
    with_context((), |ctx| ctx.detach_shader(program, shader))
}

/// # Safety
/// A non-null `shaders` must have room for `maxCount` names; a non-null `count` for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetAttachedShaders(
    program: GLuint,
    maxCount: GLsizei,
    count: *mut GLsizei,
    shaders: *mut GLuint,
) {
    let Some(names) = query(|ctx| ctx.attached_shaders(program, maxCount)) else { return };
    let written = names.len() as GLsizei;
    // SAFETY: the caller provides room for `maxCount` names; `names` holds at most that many.
    unsafe { caller_memory::write_all(shaders, names) };
    // SAFETY: the caller provides room for one value (or passes NULL).
    unsafe { caller_memory::write(count, written) };
}

/// # Safety
/// `params` must have room for one value (NULL writes nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetShaderiv(shader: GLuint, pname: GLenum, params: *mut GLint) {
    if let Some(value) = with_context(None, |ctx| ctx.get_shader(shader, pname)) {
        // SAFETY: the caller provides room for one value (or passes NULL).
        unsafe { caller_memory::write(params, value) }
    }
}

/// # Safety
/// `params` must have room for one value (NULL writes nothing).
#[no_mangle]
pub unsafe extern "C" fn glGetProgramiv(program: GLuint, pname: GLenum, params: *mut GLint) {
    if let Some(value) = with_context(None, |ctx| ctx.get_program(program, pname)) {
        // SAFETY: the caller provides room for one value (or passes NULL).
        unsafe { caller_memory::write(params, value) }
    }
}

/// Runs a string query of an object, or records GL_INVALID_VALUE for a negative buffer size
/// (after the object's own checks, as Mesa orders them).
fn string_query(buffer_size: GLsizei, text_of: impl FnOnce(&mut Context) -> Option<String>) -> Option<String> {
    guard(None, || {
        current::with_current(|ctx| {
            let text = text_of(ctx)?;
            if buffer_size < 0 {
                ctx.error(GL_INVALID_VALUE);
                return None;
            }
            Some(text)
        })
        .flatten()
    })
}

/// # Safety
/// A non-null `infoLog` must have room for `bufSize` bytes; a non-null `length` for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetShaderInfoLog(
    shader: GLuint,
    bufSize: GLsizei,
    length: *mut GLsizei,
    infoLog: *mut GLchar,
) {
    if let Some(text) = string_query(bufSize, |ctx| ctx.shader_info_log(shader)) {
        // SAFETY: as this function's contract.
        unsafe { write_string(&text, bufSize, length, infoLog) }
    }
}

/// # Safety
/// A non-null `infoLog` must have room for `bufSize` bytes; a non-null `length` for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetProgramInfoLog(
    program: GLuint,
    bufSize: GLsizei,
    length: *mut GLsizei,
    infoLog: *mut GLchar,
) {
    if let Some(text) = string_query(bufSize, |ctx| ctx.program_info_log(program)) {
        // SAFETY: as this function's contract.
        unsafe { write_string(&text, bufSize, length, infoLog) }
    }
}

/// # Safety
/// A non-null `source` must have room for `bufSize` bytes; a non-null `length` for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetShaderSource(
    shader: GLuint,
    bufSize: GLsizei,
    length: *mut GLsizei,
    source: *mut GLchar,
) {
    if let Some(text) = string_query(bufSize, |ctx| ctx.shader_source_text(shader)) {
        // SAFETY: as this function's contract.
        unsafe { write_string(&text, bufSize, length, source) }
    }
}

#[no_mangle]
pub extern "C" fn glLinkProgram(program: GLuint) {
    with_context((), |ctx| ctx.link_program(program))
}

#[no_mangle]
pub extern "C" fn glValidateProgram(program: GLuint) {
    with_context((), |ctx| ctx.validate_program(program))
}

/// Compiled into display lists (GL 2.1 section 5.4 lists the shader commands that are not).
#[no_mangle]
pub extern "C" fn glUseProgram(program: GLuint) {
    record_or_run(move |ctx| ctx.use_program(program))
}

/// # Safety
/// `name` must be a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn glBindAttribLocation(program: GLuint, index: GLuint, name: *const GLchar) {
    // SAFETY: NUL-terminated by the contract.
    let name = unsafe { caller_memory::c_str(name) }.map(|s| s.to_bytes().to_vec()).unwrap_or_default();
    with_context((), |ctx| ctx.bind_attrib_location(program, index, &name))
}

/// The caller's NUL-terminated name (`None` for NULL).
///
/// # Safety
/// A non-null `name` must be a NUL-terminated string.
unsafe fn name_of(name: *const GLchar) -> Option<String> {
    // SAFETY: NUL-terminated by the contract.
    unsafe { caller_memory::c_str(name) }.map(|s| s.to_string_lossy().into_owned())
}

/// # Safety
/// `name` must be a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn glGetAttribLocation(program: GLuint, name: *const GLchar) -> GLint {
    // SAFETY: as this function's contract.
    let name = unsafe { name_of(name) }.unwrap_or_default();
    with_context(-1, |ctx| ctx.attrib_location(program, &name))
}

/// # Safety
/// `name` must be a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn glGetUniformLocation(program: GLuint, name: *const GLchar) -> GLint {
    // SAFETY: as this function's contract.
    let name = unsafe { name_of(name) }.unwrap_or_default();
    with_context(-1, |ctx| ctx.uniform_location(program, &name))
}

/// glGetActiveUniform and glGetActiveAttrib: writes an entry's name, size and type (nothing
/// for `None`, a refused call).
///
/// # Safety
/// A non-null `name` must have room for `buffer_size` bytes; `length`, `size` and `kind`
/// for one value each (or be NULL).
unsafe fn write_active(
    entry: Option<(String, GLint, GLenum)>,
    buffer_size: GLsizei,
    length: *mut GLsizei,
    size: *mut GLint,
    kind: *mut GLenum,
    name: *mut GLchar,
) {
    let Some((text, count, ty)) = entry else { return };
    // SAFETY: as this function's contract.
    unsafe { write_string(&text, buffer_size, length, name) };
    // SAFETY: the caller provides room for one value each (or passes NULL).
    unsafe {
        caller_memory::write(size, count);
        caller_memory::write(kind, ty);
    }
}

/// # Safety
/// A non-null `name` must have room for `bufSize` bytes; `length`, `size` and `type_` for
/// one value each (or be NULL).
#[no_mangle]
pub unsafe extern "C" fn glGetActiveUniform(
    program: GLuint,
    index: GLuint,
    bufSize: GLsizei,
    length: *mut GLsizei,
    size: *mut GLint,
    type_: *mut GLenum,
    name: *mut GLchar,
) {
    let entry = query(|ctx| ctx.active_variable(program, index, bufSize, true));
    // SAFETY: as this function's contract.
    unsafe { write_active(entry, bufSize, length, size, type_, name) }
}

/// # Safety
/// A non-null `name` must have room for `bufSize` bytes; `length`, `size` and `type_` for
/// one value each (or be NULL).
#[no_mangle]
pub unsafe extern "C" fn glGetActiveAttrib(
    program: GLuint,
    index: GLuint,
    bufSize: GLsizei,
    length: *mut GLsizei,
    size: *mut GLint,
    type_: *mut GLenum,
    name: *mut GLchar,
) {
    let entry = query(|ctx| ctx.active_variable(program, index, bufSize, false));
    // SAFETY: as this function's contract.
    unsafe { write_active(entry, bufSize, length, size, type_, name) }
}
