//! Entry points for textures: objects, images, parameters, the texture environment and
//! texture coordinate generation. Compressed images are refused (no compressed format is
//! supported or advertised).
use super::caller_memory::{self, read_array};
use super::pixel_source::{PackDest, UnpackSource};
use super::{guard, record_or_run, with_context};
use crate::context::pixel_buffers::{element_size, ClientBytes};
use crate::context::texture::{ImageArgs, Region};
use crate::gl::types::*;
use std::ops::Range;

/// Runs an image command now, or, while a display list is compiled, records it with a copy
/// of the client image read under the unpack state of this moment (GL 2.1 §5.4), which is
/// restored around the command when the list runs. The image is the caller's memory or, while
/// a buffer is bound to GL_PIXEL_UNPACK_BUFFER, that buffer (also when compiled: the list
/// keeps a copy of the buffer's bytes; a refused buffer access is recorded then, as Mesa
/// does, and the list's command reads no image).
///
/// # Safety
/// A non-null `pixels` must hold the image as the unpack parameters describe it (when no
/// unpack buffer is bound).
unsafe fn image_command(
    pixels: *const GLvoid,
    dims: usize,
    format: GLenum,
    ty: GLenum,
    size: [GLsizei; 3],
    run: impl for<'b> Fn(&mut crate::context::Context, &'b dyn Fn(Range<usize>) -> ClientBytes<'b>) + Send + Sync + 'static,
) {
    with_context((), |ctx| {
        // SAFETY: forwarded contract.
        let source = unsafe { UnpackSource::new(ctx, pixels, element_size(ty)) };
        if !ctx.lists.compiling() {
            return run(ctx, &|span| source.bytes(span));
        }
        let unpack = ctx.pixel_store.unpack;
        let copy = match ctx.client_image_span(dims, format, ty, size).map(|span| (span.clone(), source.bytes(span))) {
            Some((span, Ok(bytes))) => bytes.map(|bytes| (span.start, bytes.to_vec())),
            Some((_, Err(error))) => {
                ctx.error(error);
                None
            }
            None => None,
        };
        ctx.record_or_run(move |ctx| {
            let saved = std::mem::replace(&mut ctx.pixel_store.unpack, unpack);
            let read = |span: Range<usize>| {
                let Some((start, bytes)) = copy.as_ref() else { return Ok(None) };
                let (Some(from), Some(to)) = (span.start.checked_sub(*start), span.end.checked_sub(*start)) else {
                    return Ok(None);
                };
                Ok(bytes.get(from..to))
            };
            run(ctx, &read);
            ctx.pixel_store.unpack = saved;
        })
    })
}

/// # Safety
/// `textures` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenTextures(n: GLsizei, textures: *mut GLuint) {
    let names = guard(None, || crate::context::current::with_current(|ctx| ctx.gen_textures(n)).flatten());
    if let Some(names) = names {
        // SAFETY: the caller provides room for `n` names (or passes NULL), and `names` holds `n`.
        unsafe { caller_memory::write_all(textures, names) }
    }
}

/// # Safety
/// `textures` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteTextures(n: GLsizei, textures: *const GLuint) {
    // SAFETY: forwarded contract.
    let names = unsafe { read_array(textures, n) };
    with_context((), |ctx| ctx.delete_textures(n, &names))
}

#[no_mangle]
pub extern "C" fn glBindTexture(target: GLenum, texture: GLuint) {
    record_or_run(move |ctx| ctx.bind_texture(target, texture))
}

#[no_mangle]
pub extern "C" fn glIsTexture(texture: GLuint) -> GLboolean {
    with_context(0, |ctx| ctx.is_texture(texture) as GLboolean)
}

/// # Safety
/// `textures` and `priorities` must point to `n` elements each.
#[no_mangle]
pub unsafe extern "C" fn glPrioritizeTextures(n: GLsizei, textures: *const GLuint, priorities: *const GLclampf) {
    // SAFETY: forwarded contract.
    let (names, values) = unsafe { (read_array(textures, n), read_array(priorities, n)) };
    with_context((), |ctx| ctx.prioritize_textures(n, &names, &values))
}

/// # Safety
/// `textures` must point to `n` names (`residences` is not written: every texture is resident).
#[no_mangle]
pub unsafe extern "C" fn glAreTexturesResident(
    n: GLsizei,
    textures: *const GLuint,
    residences: *mut GLboolean,
) -> GLboolean {
    let _ = residences;
    // SAFETY: forwarded contract.
    let names = unsafe { read_array(textures, n) };
    with_context(0, |ctx| ctx.are_textures_resident(n, &names) as GLboolean)
}

/// # Safety
/// A non-null `pixels` must hold the image as the unpack parameters describe it.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexImage1D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let a = ImageArgs { target, level, internal_format: internalformat, width, height: 1, depth: 1, border };
    // SAFETY: forwarded contract.
    unsafe {
        image_command(pixels, 1, format, type_, [a.width, a.height, a.depth], move |ctx, data| {
            ctx.tex_image(1, a, format, type_, data)
        })
    }
}

/// # Safety
/// A non-null `pixels` must hold the image as the unpack parameters describe it.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let a = ImageArgs { target, level, internal_format: internalformat, width, height, depth: 1, border };
    // SAFETY: forwarded contract.
    unsafe {
        image_command(pixels, 2, format, type_, [a.width, a.height, a.depth], move |ctx, data| {
            ctx.tex_image(2, a, format, type_, data)
        })
    }
}

/// # Safety
/// A non-null `pixels` must hold the image as the unpack parameters describe it.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexImage3D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let a = ImageArgs { target, level, internal_format: internalformat, width, height, depth, border };
    // SAFETY: forwarded contract.
    unsafe {
        image_command(pixels, 3, format, type_, [a.width, a.height, a.depth], move |ctx, data| {
            ctx.tex_image(3, a, format, type_, data)
        })
    }
}

/// # Safety
/// A non-null `pixels` must hold the image as the unpack parameters describe it.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexSubImage1D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    width: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let r = Region { x: xoffset, y: 0, z: 0, width, height: 1, depth: 1 };
    // SAFETY: forwarded contract.
    unsafe {
        image_command(pixels, 1, format, type_, [r.width, r.height, r.depth], move |ctx, data| {
            ctx.tex_sub_image(1, target, level, r, format, type_, data)
        })
    }
}

/// # Safety
/// A non-null `pixels` must hold the image as the unpack parameters describe it.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let r = Region { x: xoffset, y: yoffset, z: 0, width, height, depth: 1 };
    // SAFETY: forwarded contract.
    unsafe {
        image_command(pixels, 2, format, type_, [r.width, r.height, r.depth], move |ctx, data| {
            ctx.tex_sub_image(2, target, level, r, format, type_, data)
        })
    }
}

/// # Safety
/// A non-null `pixels` must hold the image as the unpack parameters describe it.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexSubImage3D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    zoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let r = Region { x: xoffset, y: yoffset, z: zoffset, width, height, depth };
    // SAFETY: forwarded contract.
    unsafe {
        image_command(pixels, 3, format, type_, [r.width, r.height, r.depth], move |ctx, data| {
            ctx.tex_sub_image(3, target, level, r, format, type_, data)
        })
    }
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCopyTexImage1D(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    x: GLint,
    y: GLint,
    width: GLsizei,
    border: GLint,
) {
    let a = ImageArgs { target, level, internal_format: internalformat as GLint, width, height: 1, depth: 1, border };
    record_or_run(move |ctx| ctx.copy_tex_image(1, a, x, y))
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCopyTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
) {
    let a = ImageArgs { target, level, internal_format: internalformat as GLint, width, height, depth: 1, border };
    record_or_run(move |ctx| ctx.copy_tex_image(2, a, x, y))
}

#[no_mangle]
pub extern "C" fn glCopyTexSubImage1D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
) {
    let r = Region { x: xoffset, y: 0, z: 0, width, height: 1, depth: 1 };
    record_or_run(move |ctx| ctx.copy_tex_sub_image(1, target, level, r, x, y))
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCopyTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
) {
    let r = Region { x: xoffset, y: yoffset, z: 0, width, height, depth: 1 };
    record_or_run(move |ctx| ctx.copy_tex_sub_image(2, target, level, r, x, y))
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCopyTexSubImage3D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    zoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
) {
    let r = Region { x: xoffset, y: yoffset, z: zoffset, width, height, depth: 1 };
    record_or_run(move |ctx| ctx.copy_tex_sub_image(3, target, level, r, x, y))
}

/// # Safety
/// A non-null `pixels` must have room for the image as the pack parameters lay it out.
#[no_mangle]
pub unsafe extern "C" fn glGetTexImage(
    target: GLenum,
    level: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *mut GLvoid,
) {
    with_context((), |ctx| {
        // SAFETY: forwarded contract.
        let mut dest = unsafe { PackDest::new(ctx, pixels, element_size(type_)) };
        let out = &mut dest;
        ctx.get_tex_image(target, level, format, type_, move |span| {
            let out = out;
            out.bytes_mut(span)
        });
        dest.finish();
    })
}

#[no_mangle]
pub extern "C" fn glGenerateMipmap(target: GLenum) {
    with_context((), |ctx| ctx.generate_mipmap(target))
}

#[no_mangle]
pub extern "C" fn glGenerateMipmapEXT(target: GLenum) {
    glGenerateMipmap(target)
}

/// Normalized-integer form of a color value (as glGet* returns colors).
fn color_to_int(x: f32) -> GLint {
    (x as f64 * 2147483647.0) as GLint
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexLevelParameteriv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLint) {
    if let Some(v) = with_context(None, |ctx| ctx.get_tex_level_parameter(target, level, pname)) {
        // SAFETY: forwarded contract (one value, or NULL).
        unsafe { caller_memory::write(params, v) }
    }
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexLevelParameterfv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLfloat) {
    if let Some(v) = with_context(None, |ctx| ctx.get_tex_level_parameter(target, level, pname)) {
        // SAFETY: forwarded contract (one value, or NULL).
        unsafe { caller_memory::write(params, v as GLfloat) }
    }
}

#[no_mangle]
pub extern "C" fn glTexParameterf(target: GLenum, pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.tex_parameter(target, pname, &[param], false))
}

#[no_mangle]
pub extern "C" fn glTexParameteri(target: GLenum, pname: GLenum, param: GLint) {
    record_or_run(move |ctx| ctx.tex_parameter(target, pname, &[param as f32], true))
}

/// How many values a texture or environment parameter takes.
fn count(pname: GLenum) -> GLsizei {
    use crate::gl::enums::*;
    if pname == GL_TEXTURE_BORDER_COLOR || pname == GL_TEXTURE_ENV_COLOR {
        4
    } else {
        1
    }
}

/// # Safety
/// `params` must point to the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glTexParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract.
    let v = unsafe { read_array(params, count(pname)) };
    record_or_run(move |ctx| ctx.tex_parameter(target, pname, &v, false))
}

/// # Safety
/// `params` must point to the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glTexParameteriv(target: GLenum, pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded contract.
    let v: Vec<f32> = unsafe { read_array(params, count(pname)) }.into_iter().map(|x| x as f32).collect();
    record_or_run(move |ctx| ctx.tex_parameter(target, pname, &v, true))
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
    if let Some((v, _)) = with_context_values(|ctx| ctx.get_tex_parameter(target, pname)) {
        // SAFETY: forwarded contract.
        unsafe { write(params, &v, |x| x) }
    }
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    if let Some((v, normalized)) = with_context_values(|ctx| ctx.get_tex_parameter(target, pname)) {
        let convert = |x: f32| if normalized { color_to_int(x) } else { x.round() as GLint };
        // SAFETY: forwarded contract.
        unsafe { write(params, &v, convert) }
    }
}

fn with_context_values<T: Clone>(f: impl FnOnce(&mut crate::context::Context) -> Option<T>) -> Option<T> {
    guard(None, || crate::context::current::with_current(f).flatten())
}

/// Writes converted `values` to `out` (nothing for NULL).
///
/// # Safety
/// A non-null `out` must have room for `values.len()` elements.
unsafe fn write<S: Copy, T>(out: *mut T, values: &[S], convert: impl Fn(S) -> T) {
    // SAFETY: forwarded contract: room for every value (or NULL).
    unsafe { caller_memory::write_all(out, values.iter().map(|&v| convert(v))) }
}

#[no_mangle]
pub extern "C" fn glTexEnvf(target: GLenum, pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.tex_env(target, pname, &[param], false))
}

#[no_mangle]
pub extern "C" fn glTexEnvi(target: GLenum, pname: GLenum, param: GLint) {
    record_or_run(move |ctx| ctx.tex_env(target, pname, &[param as f32], true))
}

/// # Safety
/// `params` must point to the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glTexEnvfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract.
    let v = unsafe { read_array(params, count(pname)) };
    record_or_run(move |ctx| ctx.tex_env(target, pname, &v, false))
}

/// # Safety
/// `params` must point to the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glTexEnviv(target: GLenum, pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded contract.
    let v: Vec<f32> = unsafe { read_array(params, count(pname)) }.into_iter().map(|x| x as f32).collect();
    record_or_run(move |ctx| ctx.tex_env(target, pname, &v, true))
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
    if let Some((v, _)) = with_context_values(|ctx| ctx.get_tex_env(target, pname)) {
        // SAFETY: forwarded contract.
        unsafe { write(params, &v, |x| x) }
    }
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut GLint) {
    if let Some((v, normalized)) = with_context_values(|ctx| ctx.get_tex_env(target, pname)) {
        let convert = |x: f32| if normalized { color_to_int(x) } else { x.round() as GLint };
        // SAFETY: forwarded contract.
        unsafe { write(params, &v, convert) }
    }
}

#[no_mangle]
pub extern "C" fn glTexGend(coord: GLenum, pname: GLenum, param: GLdouble) {
    record_or_run(move |ctx| ctx.tex_gen(coord, pname, &[param], false))
}

#[no_mangle]
pub extern "C" fn glTexGenf(coord: GLenum, pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.tex_gen(coord, pname, &[param as f64], false))
}

#[no_mangle]
pub extern "C" fn glTexGeni(coord: GLenum, pname: GLenum, param: GLint) {
    record_or_run(move |ctx| ctx.tex_gen(coord, pname, &[param as f64], false))
}

/// Values a texgen parameter takes.
fn gen_count(pname: GLenum) -> GLsizei {
    if pname == crate::gl::enums::GL_TEXTURE_GEN_MODE {
        1
    } else {
        4
    }
}

/// # Safety
/// `params` must point to the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glTexGendv(coord: GLenum, pname: GLenum, params: *const GLdouble) {
    // SAFETY: forwarded contract.
    let v = unsafe { read_array(params, gen_count(pname)) };
    record_or_run(move |ctx| ctx.tex_gen(coord, pname, &v, true))
}

/// # Safety
/// `params` must point to the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glTexGenfv(coord: GLenum, pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded contract.
    let v: Vec<f64> = unsafe { read_array(params, gen_count(pname)) }.into_iter().map(|x| x as f64).collect();
    record_or_run(move |ctx| ctx.tex_gen(coord, pname, &v, true))
}

/// # Safety
/// `params` must point to the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glTexGeniv(coord: GLenum, pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded contract.
    let v: Vec<f64> = unsafe { read_array(params, gen_count(pname)) }.into_iter().map(|x| x as f64).collect();
    record_or_run(move |ctx| ctx.tex_gen(coord, pname, &v, true))
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexGendv(coord: GLenum, pname: GLenum, params: *mut GLdouble) {
    if let Some(v) = with_context_values(|ctx| ctx.get_tex_gen(coord, pname)) {
        // SAFETY: forwarded contract.
        unsafe { write(params, &v, |x| x) }
    }
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexGenfv(coord: GLenum, pname: GLenum, params: *mut GLfloat) {
    if let Some(v) = with_context_values(|ctx| ctx.get_tex_gen(coord, pname)) {
        // SAFETY: forwarded contract.
        unsafe { write(params, &v, |x| x as GLfloat) }
    }
}

/// # Safety
/// `params` must have room for the values of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexGeniv(coord: GLenum, pname: GLenum, params: *mut GLint) {
    if let Some(v) = with_context_values(|ctx| ctx.get_tex_gen(coord, pname)) {
        // SAFETY: forwarded contract.
        unsafe { write(params, &v, |x| x.round() as GLint) }
    }
}

/// Refuses a compressed image: no compressed internal format is supported.
fn refuse_compressed() {
    with_context((), |ctx| {
        if ctx.check_outside_begin_end() {
            ctx.error(crate::gl::enums::GL_INVALID_ENUM)
        }
    })
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexImage1D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _border: GLint,
    _imageSize: GLsizei,
    _data: *const GLvoid,
) {
    refuse_compressed()
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexImage2D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _height: GLsizei,
    _border: GLint,
    _imageSize: GLsizei,
    _data: *const GLvoid,
) {
    refuse_compressed()
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexImage3D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _height: GLsizei,
    _depth: GLsizei,
    _border: GLint,
    _imageSize: GLsizei,
    _data: *const GLvoid,
) {
    refuse_compressed()
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexSubImage1D(
    _target: GLenum,
    _level: GLint,
    _xoffset: GLint,
    _width: GLsizei,
    _format: GLenum,
    _imageSize: GLsizei,
    _data: *const GLvoid,
) {
    refuse_compressed()
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexSubImage2D(
    _target: GLenum,
    _level: GLint,
    _xoffset: GLint,
    _yoffset: GLint,
    _width: GLsizei,
    _height: GLsizei,
    _format: GLenum,
    _imageSize: GLsizei,
    _data: *const GLvoid,
) {
    refuse_compressed()
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexSubImage3D(
    _target: GLenum,
    _level: GLint,
    _xoffset: GLint,
    _yoffset: GLint,
    _zoffset: GLint,
    _width: GLsizei,
    _height: GLsizei,
    _depth: GLsizei,
    _format: GLenum,
    _imageSize: GLsizei,
    _data: *const GLvoid,
) {
    refuse_compressed()
}

/// No image is ever compressed: GL_INVALID_OPERATION.
#[no_mangle]
pub extern "C" fn glGetCompressedTexImage(_target: GLenum, _level: GLint, _img: *mut GLvoid) {
    with_context((), |ctx| {
        if ctx.check_outside_begin_end() {
            ctx.error(crate::gl::enums::GL_INVALID_OPERATION)
        }
    })
}
