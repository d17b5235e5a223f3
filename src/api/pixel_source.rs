//! Where a pixel command's image is: the caller's memory at the pointer argument, or, while a
//! buffer is bound to the command's pixel pack or unpack target, that buffer with the
//! pointer's value as the offset (`crate::context::pixel_buffers`). An entry point makes one
//! [`UnpackSource`] or [`PackDest`] per call and hands the context a closure over it.
use super::caller_memory;
use crate::context::pixel_buffers::{ClientBytes, ClientBytesMut, PixelBuffer};
use crate::context::Context;
use crate::gl::types::*;
use std::cell::OnceCell;
use std::ops::Range;

/// The image a command reads.
pub(crate) struct UnpackSource {
    pointer: *const u8,
    buffer: Option<PixelBuffer>,
    /// The buffer's bytes of the span the command asked for.
    copy: OnceCell<Vec<u8>>,
}

impl UnpackSource {
    /// The image at `pointer` for a command whose pixel elements are `element` bytes
    /// ([`crate::context::pixel_buffers::element_size`]).
    ///
    /// # Safety
    /// When no buffer is bound to GL_PIXEL_UNPACK_BUFFER, a non-null `pointer` must hold the
    /// image as the unpack parameters describe it (the command's contract), for as long as
    /// this source lives.
    pub unsafe fn new(ctx: &Context, pointer: *const GLvoid, element: usize) -> UnpackSource {
        let buffer = ctx.unpack_buffer(pointer as usize, element);
        UnpackSource { pointer: pointer as *const u8, buffer, copy: OnceCell::new() }
    }

    /// The bytes of `span` (relative to the pointer). A command asks once; a second span
    /// would get the first one's bytes, so it gets an error instead.
    pub fn bytes(&self, span: Range<usize>) -> ClientBytes<'_> {
        let Some(buffer) = &self.buffer else {
            // SAFETY: the context computed `span` from the unpack parameters as the bytes of
            // the image the command reads; by `new`'s contract the caller's memory holds them.
            return Ok(unsafe { caller_memory::bytes(self.pointer, span) });
        };
        if self.copy.get().is_some() {
            return Err(crate::gl::enums::GL_INVALID_OPERATION);
        }
        let copy = buffer.read(span)?;
        Ok(Some(self.copy.get_or_init(|| copy)))
    }
}

/// The image a command writes.
pub(crate) struct PackDest {
    pointer: *mut u8,
    buffer: Option<PixelBuffer>,
    /// The span the whole image occupies when the command writes only part of it (a clipped
    /// glReadPixels): a buffer must hold all of it.
    image: Option<Range<usize>>,
    /// The span the command wrote and the copy of the buffer's bytes it wrote into.
    written: Option<(Range<usize>, Vec<u8>)>,
}

impl PackDest {
    /// The image at `pointer` for a command whose pixel elements are `element` bytes.
    ///
    /// # Safety
    /// When no buffer is bound to GL_PIXEL_PACK_BUFFER, a non-null `pointer` must have room
    /// for the image as the pack parameters describe it (the command's contract), memory
    /// nothing else accesses while this destination lives.
    pub unsafe fn new(ctx: &Context, pointer: *mut GLvoid, element: usize) -> PackDest {
        let buffer = ctx.pack_buffer(pointer as usize, element);
        PackDest { pointer: pointer as *mut u8, buffer, image: None, written: None }
    }

    /// Requires a buffer to hold the whole image `span`, also where the command writes only
    /// part of it.
    pub fn whole_image(self, span: Option<Range<usize>>) -> PackDest {
        PackDest { image: span, ..self }
    }

    /// The bytes of `span` (relative to the pointer) for the command to write.
    pub fn bytes_mut(&mut self, span: Range<usize>) -> ClientBytesMut<'_> {
        let Some(buffer) = &self.buffer else {
            // SAFETY: the context computed `span` from the pack parameters as the bytes of the
            // image the command writes; by `new`'s contract the caller's memory has room for
            // them and nothing else accesses it.
            return Ok(unsafe { caller_memory::bytes_mut(self.pointer, span) });
        };
        if let Some(image) = &self.image {
            buffer.check(image.clone())?;
        }
        let copy = buffer.read(span.clone())?;
        let (_, bytes) = self.written.insert((span, copy));
        Ok(Some(bytes))
    }

    /// Stores what the command wrote into a buffer (the caller's memory was written in place).
    pub fn finish(self) {
        if let (Some(buffer), Some((span, bytes))) = (&self.buffer, &self.written) {
            buffer.write(span.clone(), bytes);
        }
    }
}
