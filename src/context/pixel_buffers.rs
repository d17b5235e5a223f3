//! Pixel buffer objects (GL 2.1 §3.6 and §4.3.5, ARB_pixel_buffer_object): while a buffer is
//! bound to GL_PIXEL_UNPACK_BUFFER, the pointer argument of a command that reads an image
//! (glTexImage*, glTexSubImage*, glDrawPixels, glBitmap, glPolygonStipple, glPixelMap*) is an
//! offset into that buffer; while one is bound to GL_PIXEL_PACK_BUFFER, so is the pointer of a
//! command that writes one (glReadPixels, glGetTexImage, glGetPolygonStipple,
//! glGetPixelMap*).
//!
//! The pixel commands do not know where their image is: each takes a closure that turns the
//! byte span its image occupies (relative to the pointer) into bytes ([`ClientBytes`],
//! [`ClientBytesMut`]), and the entry point makes that closure over the caller's memory or
//! over a [`PixelBuffer`]. The buffer access is checked when the command asks for the bytes,
//! so after the command's own argument checks, in Mesa 22's order: GL_INVALID_OPERATION
//! when the span passes the end of the buffer (a buffer of no storage has no span), when the
//! offset is not a multiple of the size of the type's element (bitmaps excepted), or while
//! the buffer is mapped; the command then changes nothing. A glReadPixels clipped by the
//! window needs room for its whole image (`Context::read_image_span`), as GL 2.1 §4.3.2
//! writes every pixel; one wholly outside the window writes nothing and is not checked.
//!
//! An unpack reads a copy of its span, taken while the (shared) buffer table is locked for
//! just that copy: the command runs with the context borrowed and may take other locks. A
//! pack writes into a copy of its span that goes back into the buffer once the command has
//! returned, so the bytes of the span the command does not write (pixels outside the
//! framebuffer, row padding) keep their contents.
use super::share::Shared;
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::vertex::buffer_objects::{BufferObject, BufferTable};
use std::ops::Range;

/// The client bytes of an image span read by a pixel command: `Ok(None)` for a NULL pointer
/// to the caller's memory (nothing to read), `Err(error)` for an access the command must
/// refuse: it records `error` and changes nothing.
pub type ClientBytes<'a> = Result<Option<&'a [u8]>, GLenum>;

/// The client bytes of an image span written by a pixel command, as [`ClientBytes`].
pub type ClientBytesMut<'a> = Result<Option<&'a mut [u8]>, GLenum>;

/// The size of the element of the pixel type `ty`, to which a pixel buffer offset must be
/// aligned (0 for GL_BITMAP and for a type the command will refuse: no alignment rule).
pub fn element_size(ty: GLenum) -> usize {
    super::read_pixels::client_type(ty).map_or(0, |t| t.element_bytes())
}

/// A pixel command's access to the buffer bound to its pack or unpack target, at the offset
/// its pointer argument gives.
#[derive(Debug)]
pub struct PixelBuffer {
    table: Shared<BufferTable>,
    name: u32,
    offset: usize,
    /// The element size the offset must be a multiple of (0: none).
    element: usize,
}

impl Context {
    /// The unpack buffer a command with pointer argument `pointer` (its address as a number)
    /// and elements of `element` bytes reads from; `None` when no buffer is bound to
    /// GL_PIXEL_UNPACK_BUFFER (the pointer is the caller's memory).
    pub fn unpack_buffer(&self, pointer: usize, element: usize) -> Option<PixelBuffer> {
        self.pixel_buffer(self.pixel_store.unpack_buffer, pointer, element)
    }

    /// The pack buffer a command writes into, as [`Context::unpack_buffer`].
    pub fn pack_buffer(&self, pointer: usize, element: usize) -> Option<PixelBuffer> {
        self.pixel_buffer(self.pixel_store.pack_buffer, pointer, element)
    }

    fn pixel_buffer(&self, name: u32, pointer: usize, element: usize) -> Option<PixelBuffer> {
        (name != 0).then(|| PixelBuffer { table: self.buffers.clone(), name, offset: pointer, element })
    }
}

impl PixelBuffer {
    /// The bytes of `span` (relative to the offset) in `buffer`, when the access is allowed.
    fn range(&self, buffer: Option<&BufferObject>, span: &Range<usize>) -> Result<Range<usize>, GLenum> {
        let buffer = buffer.ok_or(GL_INVALID_OPERATION)?;
        let start = self.offset.checked_add(span.start).ok_or(GL_INVALID_OPERATION)?;
        let end = self.offset.checked_add(span.end).ok_or(GL_INVALID_OPERATION)?;
        let misaligned = self.element > 1 && !self.offset.is_multiple_of(self.element);
        if buffer.mapped || buffer.size() == 0 || end > buffer.size() || misaligned {
            return Err(GL_INVALID_OPERATION);
        }
        Ok(start..end)
    }

    /// Whether the command may access `span` (relative to the offset) of the buffer.
    pub fn check(&self, span: Range<usize>) -> Result<(), GLenum> {
        self.range(self.table.lock().get(self.name), &span).map(|_| ())
    }

    /// A copy of the bytes of `span` (relative to the offset).
    pub fn read(&self, span: Range<usize>) -> Result<Vec<u8>, GLenum> {
        let table = self.table.lock();
        let buffer = table.get(self.name);
        let range = self.range(buffer, &span)?;
        let bytes = &buffer.expect("checked by range").data()[range];
        let mut copy = Vec::new();
        copy.try_reserve_exact(bytes.len()).map_err(|_| GL_OUT_OF_MEMORY)?;
        copy.extend_from_slice(bytes);
        Ok(copy)
    }

    /// Stores `bytes`, what a pack command wrote into the copy [`PixelBuffer::read`] gave it
    /// for `span`. The span was checked then; a buffer that lost it since (nothing else runs
    /// on this context in between, but another context of the share group may respecify
    /// it) receives nothing.
    pub fn write(&self, span: Range<usize>, bytes: &[u8]) {
        let mut table = self.table.lock();
        let Ok(range) = self.range(table.get(self.name), &span) else {
            return;
        };
        if let Some(target) = table.get_mut(self.name).and_then(|b| b.range_mut(range.start, range.len())) {
            target.copy_from_slice(bytes);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::vertex_input::test_support::context;

    #[test]
    fn accesses_are_checked_against_size_alignment_and_mapping() {
        let mut ctx = context();
        assert!(ctx.unpack_buffer(0, 1).is_none() && ctx.pack_buffer(0, 1).is_none());
        ctx.bind_buffer(GL_PIXEL_UNPACK_BUFFER, 5);
        let empty = ctx.unpack_buffer(0, 1).unwrap();
        assert_eq!(empty.read(0..0), Err(GL_INVALID_OPERATION), "a buffer without storage");
        ctx.buffer_data(GL_PIXEL_UNPACK_BUFFER, 8, GL_STREAM_DRAW, |_| Some(b"abcdefgh"));
        assert!(ctx.pack_buffer(0, 1).is_none(), "the pack target is separate");
        assert_eq!(ctx.unpack_buffer(2, 1).unwrap().read(1..4), Ok(b"def".to_vec()));
        assert_eq!(ctx.unpack_buffer(2, 2).unwrap().read(0..6), Ok(b"cdefgh".to_vec()));
        assert_eq!(ctx.unpack_buffer(2, 2).unwrap().read(0..7), Err(GL_INVALID_OPERATION), "past the end");
        assert_eq!(ctx.unpack_buffer(2, 2).unwrap().check(0..6), Ok(()));
        assert_eq!(ctx.unpack_buffer(2, 2).unwrap().check(5..7), Err(GL_INVALID_OPERATION));
        assert_eq!(ctx.unpack_buffer(3, 2).unwrap().read(0..2), Err(GL_INVALID_OPERATION), "misaligned");
        assert_eq!(ctx.unpack_buffer(3, 0).unwrap().read(0..2), Ok(b"de".to_vec()), "bitmaps: no alignment");
        assert_eq!(ctx.unpack_buffer(usize::MAX, 1).unwrap().read(1..2), Err(GL_INVALID_OPERATION), "wraps");
        ctx.map_buffer(GL_PIXEL_UNPACK_BUFFER, GL_READ_ONLY);
        assert_eq!(ctx.unpack_buffer(0, 1).unwrap().read(0..1), Err(GL_INVALID_OPERATION), "mapped");
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn a_pack_writes_its_span_back() {
        let mut ctx = context();
        ctx.bind_buffer(GL_PIXEL_PACK_BUFFER, 2);
        ctx.buffer_data(GL_PIXEL_PACK_BUFFER, 6, GL_STREAM_READ, |_| Some(b"ABCDEF"));
        let access = ctx.pack_buffer(1, 1).unwrap();
        let mut copy = access.read(1..3).unwrap();
        assert_eq!(copy, b"CD");
        copy.copy_from_slice(b"xy");
        access.write(1..3, &copy);
        assert_eq!(ctx.buffers.lock().get(2).unwrap().data(), b"ABxyEF");
        // Respecified smaller in between: nothing is written.
        ctx.buffer_data(GL_PIXEL_PACK_BUFFER, 2, GL_STREAM_READ, |_| Some(b"ab"));
        access.write(1..3, b"zz");
        assert_eq!(ctx.buffers.lock().get(2).unwrap().data(), b"ab");
    }

    #[test]
    fn bindings_are_queried_saved_with_the_pixel_store_and_dropped_with_the_buffer() {
        use crate::context::get::Value;
        let mut ctx = context();
        ctx.bind_buffer(GL_PIXEL_PACK_BUFFER, 3);
        ctx.bind_buffer(GL_PIXEL_UNPACK_BUFFER, 4);
        assert_eq!(ctx.vertex_input_values(GL_PIXEL_PACK_BUFFER_BINDING), Some(vec![Value::Int(3)]));
        assert_eq!(ctx.vertex_input_values(GL_PIXEL_UNPACK_BUFFER_BINDING), Some(vec![Value::Int(4)]));
        ctx.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT);
        ctx.bind_buffer(GL_PIXEL_PACK_BUFFER, 0);
        ctx.delete_buffers(1, &[4]);
        assert_eq!(ctx.pixel_store.unpack_buffer, 0, "deleting a bound buffer unbinds it");
        ctx.pop_client_attrib();
        assert_eq!((ctx.pixel_store.pack_buffer, ctx.pixel_store.unpack_buffer), (3, 4));
        assert!(ctx.buffers.lock().is_buffer(4), "restored as glBindBuffer binds: a new buffer");
        ctx.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        ctx.bind_buffer(GL_PIXEL_PACK_BUFFER, 7);
        ctx.pop_client_attrib();
        assert_eq!(ctx.pixel_store.pack_buffer, 7, "not part of the vertex array group");
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }
}
