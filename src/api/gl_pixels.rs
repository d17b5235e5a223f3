//! Entry points for glReadPixels and glPixelStore.
use super::pixel_source::PackDest;
use super::with_context;
use crate::context::pixel_buffers::element_size;
use crate::gl::types::*;

/// # Safety
/// Unless a buffer is bound to GL_PIXEL_PACK_BUFFER (then `pixels` is an offset into it),
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
        // SAFETY: forwarded contract.
        let mut dest = unsafe { PackDest::new(ctx, pixels, element_size(type_)) }
            .whole_image(ctx.read_image_span(width, height, format, type_));
        let out = &mut dest;
        ctx.read_pixels(x, y, width, height, format, type_, move |span| {
            let out = out;
            out.bytes_mut(span)
        });
        dest.finish();
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
