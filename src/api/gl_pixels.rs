//! Entry points for glReadPixels and glPixelStore.
use super::caller_memory;
use super::with_context;
use crate::gl::types::*;

/// # Safety
/// `pixels` must point to client memory laid out as the pack parameters describe for a
/// `width` × `height` image of `format`/`type` (GL's contract for glReadPixels); only the
/// bytes of the pixels inside the framebuffer are written. NULL writes nothing.
#[no_mangle]
pub unsafe extern "C" fn glReadPixels(
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *mut GLvoid,
) {
    with_context((), |ctx| {
        ctx.read_pixels(x, y, width, height, format, type_, |span| {
            // SAFETY: the context computed `span` from the pack parameters as the bytes of
            // the client image that the clipped read writes; by glReadPixels' contract the
            // caller's image holds them, and nothing else accesses that memory during the call.
            unsafe { caller_memory::bytes_mut(pixels, span) }
        })
    })
}

#[no_mangle]
pub extern "C" fn glPixelStorei(pname: GLenum, param: GLint) {
    with_context((), |ctx| ctx.pixel_store(pname, param))
}

#[no_mangle]
pub extern "C" fn glPixelStoref(pname: GLenum, param: GLfloat) {
    with_context((), |ctx| ctx.pixel_store_f(pname, param))
}
