//! Entry points of the raster position and pixel rectangles: glRasterPos*, glWindowPos*,
//! glBitmap, glDrawPixels, glCopyPixels, glPixelZoom. All are compiled into display lists; glBitmap and
//! glDrawPixels read their image (under the unpack modes) when issued.
use super::caller_memory::read;
use super::pixel_source::{PackDest, UnpackSource};
use super::{record_or_run, with_context};
use crate::context::pixel_buffers::element_size;
use crate::gl::types::*;
use crate::vertex::components::Component;

#[no_mangle]
pub extern "C" fn glRasterPos2s(x: GLshort, y: GLshort) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos2sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glRasterPos2s(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos2i(x: GLint, y: GLint) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos2iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glRasterPos2i(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos2f(x: GLfloat, y: GLfloat) {
    record_or_run(move |ctx| ctx.raster_pos([x, y, 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos2fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glRasterPos2f(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos2d(x: GLdouble, y: GLdouble) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), 0.0, 1.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos2dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glRasterPos2d(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos3s(x: GLshort, y: GLshort, z: GLshort) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), z.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos3sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glRasterPos3s(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos3i(x: GLint, y: GLint, z: GLint) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), z.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos3iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glRasterPos3i(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos3f(x: GLfloat, y: GLfloat, z: GLfloat) {
    record_or_run(move |ctx| ctx.raster_pos([x, y, z, 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos3fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glRasterPos3f(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos3d(x: GLdouble, y: GLdouble, z: GLdouble) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), z.to_f32(), 1.0]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos3dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glRasterPos3d(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), z.to_f32(), w.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos4sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z, w]) = unsafe { read(v) } {
        glRasterPos4s(x, y, z, w)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos4i(x: GLint, y: GLint, z: GLint, w: GLint) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), z.to_f32(), w.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos4iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z, w]) = unsafe { read(v) } {
        glRasterPos4i(x, y, z, w)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
    record_or_run(move |ctx| ctx.raster_pos([x, y, z, w]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos4fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z, w]) = unsafe { read(v) } {
        glRasterPos4f(x, y, z, w)
    }
}

#[no_mangle]
pub extern "C" fn glRasterPos4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
    record_or_run(move |ctx| ctx.raster_pos([x.to_f32(), y.to_f32(), z.to_f32(), w.to_f32()]))
}

/// # Safety
/// `v` must point to 4 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glRasterPos4dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z, w]) = unsafe { read(v) } {
        glRasterPos4d(x, y, z, w)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos2s(x: GLshort, y: GLshort) {
    record_or_run(move |ctx| ctx.window_pos([x.to_f32(), y.to_f32(), 0.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glWindowPos2s(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos2sARB(x: GLshort, y: GLshort) {
    glWindowPos2s(x, y)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2svARB(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos2sv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos2sMESA(x: GLshort, y: GLshort) {
    glWindowPos2s(x, y)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2svMESA(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos2sv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos2i(x: GLint, y: GLint) {
    record_or_run(move |ctx| ctx.window_pos([x.to_f32(), y.to_f32(), 0.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glWindowPos2i(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos2iARB(x: GLint, y: GLint) {
    glWindowPos2i(x, y)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2ivARB(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos2iv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos2iMESA(x: GLint, y: GLint) {
    glWindowPos2i(x, y)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2ivMESA(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos2iv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos2f(x: GLfloat, y: GLfloat) {
    record_or_run(move |ctx| ctx.window_pos([x, y, 0.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glWindowPos2f(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos2fARB(x: GLfloat, y: GLfloat) {
    glWindowPos2f(x, y)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2fvARB(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos2fv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos2fMESA(x: GLfloat, y: GLfloat) {
    glWindowPos2f(x, y)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2fvMESA(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos2fv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos2d(x: GLdouble, y: GLdouble) {
    record_or_run(move |ctx| ctx.window_pos([x.to_f32(), y.to_f32(), 0.0]))
}

/// # Safety
/// `v` must point to 2 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y]) = unsafe { read(v) } {
        glWindowPos2d(x, y)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos2dARB(x: GLdouble, y: GLdouble) {
    glWindowPos2d(x, y)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2dvARB(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos2dv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos2dMESA(x: GLdouble, y: GLdouble) {
    glWindowPos2d(x, y)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2dvMESA(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos2dv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos3s(x: GLshort, y: GLshort, z: GLshort) {
    record_or_run(move |ctx| ctx.window_pos([x.to_f32(), y.to_f32(), z.to_f32()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3sv(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glWindowPos3s(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos3sARB(x: GLshort, y: GLshort, z: GLshort) {
    glWindowPos3s(x, y, z)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3svARB(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos3sv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos3sMESA(x: GLshort, y: GLshort, z: GLshort) {
    glWindowPos3s(x, y, z)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3svMESA(v: *const GLshort) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos3sv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos3i(x: GLint, y: GLint, z: GLint) {
    record_or_run(move |ctx| ctx.window_pos([x.to_f32(), y.to_f32(), z.to_f32()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3iv(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glWindowPos3i(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos3iARB(x: GLint, y: GLint, z: GLint) {
    glWindowPos3i(x, y, z)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3ivARB(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos3iv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos3iMESA(x: GLint, y: GLint, z: GLint) {
    glWindowPos3i(x, y, z)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3ivMESA(v: *const GLint) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos3iv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos3f(x: GLfloat, y: GLfloat, z: GLfloat) {
    record_or_run(move |ctx| ctx.window_pos([x, y, z]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3fv(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glWindowPos3f(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos3fARB(x: GLfloat, y: GLfloat, z: GLfloat) {
    glWindowPos3f(x, y, z)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3fvARB(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos3fv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos3fMESA(x: GLfloat, y: GLfloat, z: GLfloat) {
    glWindowPos3f(x, y, z)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3fvMESA(v: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos3fv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos3d(x: GLdouble, y: GLdouble, z: GLdouble) {
    record_or_run(move |ctx| ctx.window_pos([x.to_f32(), y.to_f32(), z.to_f32()]))
}

/// # Safety
/// `v` must point to 3 values (NULL is ignored).
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3dv(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    if let Some([x, y, z]) = unsafe { read(v) } {
        glWindowPos3d(x, y, z)
    }
}

#[no_mangle]
pub extern "C" fn glWindowPos3dARB(x: GLdouble, y: GLdouble, z: GLdouble) {
    glWindowPos3d(x, y, z)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3dvARB(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos3dv(v) }
}

#[no_mangle]
pub extern "C" fn glWindowPos3dMESA(x: GLdouble, y: GLdouble, z: GLdouble) {
    glWindowPos3d(x, y, z)
}

/// # Safety
/// As the core function.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3dvMESA(v: *const GLdouble) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { glWindowPos3dv(v) }
}

/// # Safety
/// `bitmap` is NULL or points to a `width` × `height` bitmap laid out as the unpack
/// parameters of glPixelStore describe.
#[no_mangle]
pub unsafe extern "C" fn glBitmap(
    width: GLsizei,
    height: GLsizei,
    xorig: GLfloat,
    yorig: GLfloat,
    xmove: GLfloat,
    ymove: GLfloat,
    bitmap: *const GLubyte,
) {
    with_context((), |ctx| {
        // SAFETY: forwarded contract (a bitmap: no element alignment).
        let source = unsafe { UnpackSource::new(ctx, bitmap as *const GLvoid, 0) };
        let bits = ctx.unpack_bitmap(width, height, |span| source.bytes(span));
        ctx.record_or_run(move |ctx| ctx.bitmap(width, height, [xorig, yorig], [xmove, ymove], &bits))
    })
}

/// # Safety
/// `pixels` is NULL or points to a `width` × `height` image of `format`/`type_` laid out as
/// the unpack parameters of glPixelStore describe.
#[no_mangle]
pub unsafe extern "C" fn glDrawPixels(
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    with_context((), |ctx| {
        // SAFETY: forwarded contract.
        let source = unsafe { UnpackSource::new(ctx, pixels, element_size(type_)) };
        let data = ctx.unpack_draw_pixels(width, height, format, type_, |span| source.bytes(span));
        ctx.record_or_run(move |ctx| ctx.draw_pixels(width, height, &data))
    })
}

#[no_mangle]
pub extern "C" fn glPixelZoom(xfactor: GLfloat, yfactor: GLfloat) {
    record_or_run(move |ctx| ctx.pixel_zoom(xfactor, yfactor))
}

#[no_mangle]
pub extern "C" fn glCopyPixels(x: GLint, y: GLint, width: GLsizei, height: GLsizei, type_: GLenum) {
    record_or_run(move |ctx| ctx.copy_pixels(x, y, width, height, type_))
}

#[no_mangle]
pub extern "C" fn glPixelTransferf(pname: GLenum, param: GLfloat) {
    record_or_run(move |ctx| ctx.pixel_transfer(pname, param))
}

#[no_mangle]
pub extern "C" fn glPixelTransferi(pname: GLenum, param: GLint) {
    record_or_run(move |ctx| ctx.pixel_transfer(pname, param as f32))
}

/// A pixel map entry as the caller's memory or a pixel buffer holds it (native byte order).
trait MapEntry: Copy {
    const BYTES: usize;
    fn from_bytes(bytes: &[u8]) -> Self;
    fn to_bytes(self, out: &mut [u8]);
}

macro_rules! map_entry {
    ($($t:ty),*) => {$(
        impl MapEntry for $t {
            const BYTES: usize = std::mem::size_of::<$t>();
            fn from_bytes(bytes: &[u8]) -> Self {
                <$t>::from_ne_bytes(bytes.try_into().expect("one entry's bytes"))
            }
            fn to_bytes(self, out: &mut [u8]) {
                out.copy_from_slice(&self.to_ne_bytes());
            }
        }
    )*};
}
map_entry!(f32, u32, u16);

/// glPixelMap: the `mapsize` values at `values` as floats, from the caller's memory or, while
/// a buffer is bound to GL_PIXEL_UNPACK_BUFFER, from that buffer at the offset `values`
/// gives; then the command runs (or is compiled, with the table read now).
///
/// # Safety
/// When no unpack buffer is bound, a non-null `values` must point to `mapsize` values.
unsafe fn pixel_map<T: MapEntry>(map: GLenum, mapsize: GLsizei, values: *const T, convert: impl Fn(T) -> f32) {
    use crate::context::pixel_rect::MAX_PIXEL_MAP_TABLE;
    with_context((), |ctx| {
        let table = if mapsize <= 0 || mapsize as usize > MAX_PIXEL_MAP_TABLE {
            // Invalid sizes still reach the context (as an empty or oversized table) for the error.
            vec![0.0; mapsize.clamp(0, MAX_PIXEL_MAP_TABLE as GLsizei + 1) as usize]
        } else {
            // SAFETY: forwarded contract (`mapsize` entries of `T::BYTES` bytes each).
            let source = unsafe { UnpackSource::new(ctx, values as *const GLvoid, T::BYTES) };
            match source.bytes(0..mapsize as usize * T::BYTES) {
                Ok(Some(bytes)) => bytes.chunks_exact(T::BYTES).map(|b| convert(T::from_bytes(b))).collect(),
                // NULL: the table of `mapsize` zeros, as before (the context checks the map).
                Ok(None) => vec![0.0; mapsize as usize],
                Err(error) => return ctx.error(error),
            }
        };
        ctx.record_or_run(move |ctx| ctx.pixel_map(map, &table))
    })
}

/// # Safety
/// `values` must point to `mapsize` floats (or be an offset into the unpack buffer).
#[no_mangle]
pub unsafe extern "C" fn glPixelMapfv(map: GLenum, mapsize: GLsizei, values: *const GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { pixel_map(map, mapsize, values, |v| v) }
}

/// # Safety
/// `values` must point to `mapsize` GLuints (or be an offset into the unpack buffer).
#[no_mangle]
pub unsafe extern "C" fn glPixelMapuiv(map: GLenum, mapsize: GLsizei, values: *const GLuint) {
    use crate::context::pixel_rect::pixel_map_from_integer;
    // SAFETY: forwarded contract of this entry point.
    unsafe { pixel_map(map, mapsize, values, |v| pixel_map_from_integer(map, v, 4294967295.0)) }
}

/// # Safety
/// `values` must point to `mapsize` GLushorts (or be an offset into the unpack buffer).
#[no_mangle]
pub unsafe extern "C" fn glPixelMapusv(map: GLenum, mapsize: GLsizei, values: *const GLushort) {
    use crate::context::pixel_rect::pixel_map_from_integer;
    // SAFETY: forwarded contract of this entry point.
    unsafe { pixel_map(map, mapsize, values, |v| pixel_map_from_integer(map, v as u32, 65535.0)) }
}

/// Writes a pixel map table to the caller's array, or, while a buffer is bound to
/// GL_PIXEL_PACK_BUFFER, into that buffer at the offset `values` gives; each entry converted
/// by `convert`.
///
/// # Safety
/// When no pack buffer is bound, `values` must have room for the table
/// (GL_PIXEL_MAP_*_SIZE entries).
unsafe fn write_map<T: MapEntry>(map: GLenum, values: *mut T, convert: impl Fn(f32, bool) -> T) {
    with_context((), |ctx| {
        let Some(table) = ctx.get_pixel_map(map) else { return };
        let color = !matches!(map, crate::gl::enums::GL_PIXEL_MAP_I_TO_I | crate::gl::enums::GL_PIXEL_MAP_S_TO_S);
        // SAFETY: forwarded contract (room for the whole table, or NULL).
        let mut dest = unsafe { PackDest::new(ctx, values as *mut GLvoid, T::BYTES) };
        match dest.bytes_mut(0..table.len() * T::BYTES) {
            Ok(Some(out)) => {
                for (entry, &v) in out.chunks_exact_mut(T::BYTES).zip(&table) {
                    convert(v, color).to_bytes(entry);
                }
            }
            Ok(None) => {}
            Err(error) => ctx.error(error),
        }
        dest.finish();
    })
}

/// # Safety
/// `values` must have room for the table.
#[no_mangle]
pub unsafe extern "C" fn glGetPixelMapfv(map: GLenum, values: *mut GLfloat) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_map(map, values, |v, _| v) }
}

/// # Safety
/// `values` must have room for the table.
#[no_mangle]
pub unsafe extern "C" fn glGetPixelMapuiv(map: GLenum, values: *mut GLuint) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_map(map, values, |v, color| if color { (v as f64 * 4294967295.0) as u32 } else { v as u32 }) }
}

/// # Safety
/// `values` must have room for the table.
#[no_mangle]
pub unsafe extern "C" fn glGetPixelMapusv(map: GLenum, values: *mut GLushort) {
    // SAFETY: forwarded contract of this entry point.
    unsafe { write_map(map, values, |v, color| if color { (v * 65535.0) as u16 } else { v as u16 }) }
}
