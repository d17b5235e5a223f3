//! Entry points that are other names of existing ones, added so that an extension tessera
//! advertises has every entry point (GL_ATI_separate_stencil, GL_EXT_texture3D,
//! GL_ARB_texture_compression).
use super::with_context;
use crate::gl::types::*;

/// GL_ATI_separate_stencil's name of glStencilOpSeparate (same arguments and rules).
#[no_mangle]
pub extern "C" fn glStencilOpSeparateATI(face: GLenum, sfail: GLenum, dpfail: GLenum, dppass: GLenum) {
    with_context((), |ctx| ctx.stencil_op_separate(face, sfail, dpfail, dppass))
}

/// GL_EXT_texture3D's name of glTexImage3D (its internal format is a GLenum).
///
/// # Safety
/// As glTexImage3D: `pixels` is NULL or holds the image the unpack state describes.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexImage3DEXT(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    // SAFETY: forwarded contract. An enum above i32::MAX is no internal format either way.
    unsafe {
        super::gl_texture::glTexImage3D(
            target,
            level,
            internalformat as GLint,
            width,
            height,
            depth,
            border,
            format,
            type_,
            pixels,
        )
    }
}

/// GL_EXT_texture3D's name of glTexSubImage3D.
///
/// # Safety
/// As glTexSubImage3D.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexSubImage3DEXT(
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
    // SAFETY: forwarded contract.
    unsafe {
        super::gl_texture::glTexSubImage3D(
            target, level, xoffset, yoffset, zoffset, width, height, depth, format, type_, pixels,
        )
    }
}

/// GL_ARB_texture_compression's names of the compressed-image calls (no compressed format
/// exists: GL_NUM_COMPRESSED_TEXTURE_FORMATS is 0, so they refuse every image as the core
/// ones do).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexImage1DARB(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    width: GLsizei,
    border: GLint,
    imageSize: GLsizei,
    data: *const GLvoid,
) {
    super::gl_texture::glCompressedTexImage1D(target, level, internalformat, width, border, imageSize, data)
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexImage2DARB(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
    imageSize: GLsizei,
    data: *const GLvoid,
) {
    super::gl_texture::glCompressedTexImage2D(target, level, internalformat, width, height, border, imageSize, data)
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexImage3DARB(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    border: GLint,
    imageSize: GLsizei,
    data: *const GLvoid,
) {
    super::gl_texture::glCompressedTexImage3D(
        target,
        level,
        internalformat,
        width,
        height,
        depth,
        border,
        imageSize,
        data,
    )
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexSubImage1DARB(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    width: GLsizei,
    format: GLenum,
    imageSize: GLsizei,
    data: *const GLvoid,
) {
    super::gl_texture::glCompressedTexSubImage1D(target, level, xoffset, width, format, imageSize, data)
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexSubImage2DARB(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    imageSize: GLsizei,
    data: *const GLvoid,
) {
    super::gl_texture::glCompressedTexSubImage2D(
        target, level, xoffset, yoffset, width, height, format, imageSize, data,
    )
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glCompressedTexSubImage3DARB(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    zoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    format: GLenum,
    imageSize: GLsizei,
    data: *const GLvoid,
) {
    super::gl_texture::glCompressedTexSubImage3D(
        target, level, xoffset, yoffset, zoffset, width, height, depth, format, imageSize, data,
    )
}

#[no_mangle]
pub extern "C" fn glGetCompressedTexImageARB(target: GLenum, level: GLint, img: *mut GLvoid) {
    super::gl_texture::glGetCompressedTexImage(target, level, img)
}
