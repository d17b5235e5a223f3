//! The buffer object commands (GL 1.5 and ARB_vertex_buffer_object): glGenBuffers,
//! glBindBuffer, glBufferData, glBufferSubData, glGetBufferSubData, glMapBuffer,
//! glUnmapBuffer, glGetBufferParameteriv, glGetBufferPointerv, glIsBuffer, glDeleteBuffers;
//! on the vertex array and index targets and on the pixel pack and unpack targets (GL 2.1,
//! ARB_pixel_buffer_object: what the pixel commands do with them is `super::super::pixel_buffers`).
//!
//! Errors come in Mesa 22's order: the target (GL_INVALID_ENUM), the bound buffer
//! (GL_INVALID_OPERATION when none), then the arguments, then the mapping.
//!
//! Deliberate differences from Mesa 22: the targets of later versions (uniform, texture,
//! copy buffers...) are GL_INVALID_ENUM; a failed glBufferData (GL_OUT_OF_MEMORY) keeps the
//! old contents, where Mesa leaves an empty buffer.
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::{GLenum, GLint};
use crate::vertex::buffer_objects::{is_access, is_usage, BufferObject, BufferTarget};

impl Context {
    /// The name bound to `target`.
    fn binding(&self, target: BufferTarget) -> u32 {
        match target {
            BufferTarget::Array => self.vertex_input.arrays.array_buffer,
            BufferTarget::ElementArray => self.vertex_input.arrays.element_array_buffer,
            BufferTarget::PixelPack => self.pixel_store.pack_buffer,
            BufferTarget::PixelUnpack => self.pixel_store.unpack_buffer,
        }
    }

    /// The name of the buffer bound to `target`, after the checks every command makes:
    /// outside glBegin/glEnd, a known target, a buffer bound.
    fn bound_name(&mut self, target: GLenum) -> Option<u32> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let Some(target) = BufferTarget::from_gl(target) else {
            self.error(GL_INVALID_ENUM);
            return None;
        };
        let name = self.binding(target);
        if self.buffers.lock().get(name).is_none() {
            self.error(GL_INVALID_OPERATION);
            return None;
        }
        Some(name)
    }

    /// Runs `f` on the buffer bound to `target`, after the checks of
    /// [`Context::bound_name`], with the (shared) buffer table locked; records the error `f`
    /// returns. `None` when an error was recorded.
    fn with_bound_buffer<R>(
        &mut self,
        target: GLenum,
        f: impl FnOnce(&mut BufferObject) -> Result<R, GLenum>,
    ) -> Option<R> {
        let name = self.bound_name(target)?;
        let result = f(self.buffers.lock().get_mut(name)?);
        result.map_err(|error| self.error(error)).ok()
    }

    /// glGenBuffers: `None` when an error was recorded.
    pub fn gen_buffers(&mut self, n: i32) -> Option<Vec<u32>> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if n < 0 {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        let names = self.buffers.lock().generate(n as usize);
        if names.is_err() {
            self.error(GL_OUT_OF_MEMORY);
        }
        names.ok()
    }

    /// glDeleteBuffers of `names` (the first `n` of the caller's array). Bindings of the
    /// deleted buffers in this context return to 0: the four binding points and every array
    /// (which then draws nothing: its pointer was an offset into the deleted buffer).
    pub fn delete_buffers(&mut self, n: i32, names: &[u32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if n < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        for &name in names {
            if !self.buffers.lock().delete(name) {
                continue;
            }
            for binding in [&mut self.pixel_store.pack_buffer, &mut self.pixel_store.unpack_buffer] {
                if *binding == name {
                    *binding = 0;
                }
            }
            let arrays = &mut self.vertex_input.arrays;
            if arrays.array_buffer == name {
                arrays.array_buffer = 0;
            }
            if arrays.element_array_buffer == name {
                arrays.element_array_buffer = 0;
            }
            for array in arrays.all_mut().filter(|a| a.buffer == name) {
                array.buffer = 0;
                array.orphaned = true;
            }
        }
    }

    /// glBindBuffer: binding a name the first time creates its buffer.
    pub fn bind_buffer(&mut self, target: GLenum, name: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(target) = BufferTarget::from_gl(target) else {
            return self.error(GL_INVALID_ENUM);
        };
        self.buffers.lock().create_on_bind(name);
        let arrays = &mut self.vertex_input.arrays;
        match target {
            BufferTarget::Array => arrays.array_buffer = name,
            BufferTarget::ElementArray => arrays.element_array_buffer = name,
            BufferTarget::PixelPack => self.pixel_store.pack_buffer = name,
            BufferTarget::PixelUnpack => self.pixel_store.unpack_buffer = name,
        }
    }

    /// glIsBuffer: true for names whose buffer exists (bound at least once).
    pub fn is_buffer(&mut self, name: u32) -> bool {
        self.check_outside_begin_end() && self.buffers.lock().is_buffer(name)
    }

    /// glBufferData. `contents` gives the caller's `size` bytes (`None`: no data pointer, the
    /// buffer is zero-filled).
    pub fn buffer_data<'a>(
        &mut self,
        target: GLenum,
        size: isize,
        usage: GLenum,
        contents: impl FnOnce(usize) -> Option<&'a [u8]>,
    ) {
        self.with_bound_buffer(target, |buffer| {
            if size < 0 {
                Err(GL_INVALID_VALUE)
            } else if !is_usage(usage) {
                Err(GL_INVALID_ENUM)
            } else {
                buffer.set_data(size as usize, contents(size as usize), usage).map_err(|_| GL_OUT_OF_MEMORY)
            }
        });
    }

    /// The checks of glBufferSubData and glGetBufferSubData: runs `f` on the buffer and the
    /// byte range when they pass.
    fn with_buffer_range(
        &mut self,
        target: GLenum,
        offset: isize,
        size: isize,
        f: impl FnOnce(&mut BufferObject, usize, usize),
    ) {
        self.with_bound_buffer(target, |buffer| {
            let end = (offset >= 0 && size >= 0).then(|| (offset as usize).checked_add(size as usize)).flatten();
            match end {
                Some(end) if end <= buffer.size() && !buffer.mapped => {
                    f(buffer, offset as usize, size as usize);
                    Ok(())
                }
                Some(end) if end <= buffer.size() => Err(GL_INVALID_OPERATION),
                _ => Err(GL_INVALID_VALUE),
            }
        });
    }

    /// glBufferSubData: `contents` gives the caller's `size` bytes.
    pub fn buffer_sub_data<'a>(
        &mut self,
        target: GLenum,
        offset: isize,
        size: isize,
        contents: impl FnOnce(usize) -> Option<&'a [u8]>,
    ) {
        self.with_buffer_range(target, offset, size, |buffer, offset, size| {
            if let (Some(source), Some(destination)) = (contents(size), buffer.range_mut(offset, size)) {
                let n = destination.len().min(source.len());
                destination[..n].copy_from_slice(&source[..n]);
            }
        });
    }

    /// glGetBufferSubData: `destination` gives the caller's `size` bytes to write.
    pub fn get_buffer_sub_data<'a>(
        &mut self,
        target: GLenum,
        offset: isize,
        size: isize,
        destination: impl FnOnce(usize) -> Option<&'a mut [u8]>,
    ) {
        self.with_buffer_range(target, offset, size, |buffer, offset, size| {
            if let (Some(destination), Some(source)) = (destination(size), buffer.range(offset, size)) {
                let n = destination.len().min(source.len());
                destination[..n].copy_from_slice(&source[..n]);
            }
        });
    }

    /// glMapBuffer: the address of the buffer's storage, valid until it is unmapped; null
    /// when an error was recorded. Like Mesa, an empty buffer cannot be mapped
    /// (GL_INVALID_OPERATION).
    pub fn map_buffer(&mut self, target: GLenum, access: GLenum) -> *mut u8 {
        if !self.check_outside_begin_end() {
            return std::ptr::null_mut();
        }
        if BufferTarget::from_gl(target).is_none() || !is_access(access) {
            self.error(GL_INVALID_ENUM);
            return std::ptr::null_mut();
        }
        let pointer = self.with_bound_buffer(target, |buffer| {
            if buffer.mapped || buffer.size() == 0 {
                Err(GL_INVALID_OPERATION)
            } else {
                Ok(buffer.map(access))
            }
        });
        pointer.unwrap_or(std::ptr::null_mut())
    }

    /// glUnmapBuffer: true unless an error was recorded (the contents never become corrupt
    /// in a software implementation).
    pub fn unmap_buffer(&mut self, target: GLenum) -> bool {
        let unmapped = self.with_bound_buffer(target, |buffer| {
            if !buffer.mapped {
                return Err(GL_INVALID_OPERATION);
            }
            buffer.unmap();
            Ok(true)
        });
        unmapped.unwrap_or(false)
    }

    /// glGetBufferParameteriv: `None` when an error was recorded.
    pub fn get_buffer_parameter(&mut self, target: GLenum, pname: GLenum) -> Option<GLint> {
        self.with_bound_buffer(target, |buffer| match pname {
            GL_BUFFER_SIZE => Ok(buffer.size().min(i32::MAX as usize) as GLint),
            GL_BUFFER_USAGE => Ok(buffer.usage as GLint),
            GL_BUFFER_ACCESS => Ok(buffer.access as GLint),
            GL_BUFFER_MAPPED => Ok(buffer.mapped as GLint),
            _ => Err(GL_INVALID_ENUM),
        })
    }

    /// glGetBufferPointerv (GL_BUFFER_MAP_POINTER): null while unmapped; `None` when an error
    /// was recorded. The pname is checked before the binding, as in Mesa.
    pub fn get_buffer_pointer(&mut self, target: GLenum, pname: GLenum) -> Option<*mut u8> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if BufferTarget::from_gl(target).is_none() || pname != GL_BUFFER_MAP_POINTER {
            self.error(GL_INVALID_ENUM);
            return None;
        }
        self.with_bound_buffer(target, |buffer| Ok(buffer.map_pointer()))
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_support::*;
    use super::*;

    fn bound_context() -> (Context, u32) {
        let mut ctx = context();
        let name = ctx.gen_buffers(1).unwrap()[0];
        ctx.bind_buffer(GL_ARRAY_BUFFER, name);
        (ctx, name)
    }

    #[test]
    fn data_round_trips_and_sub_data_ranges() {
        let (mut ctx, _) = bound_context();
        let data: Vec<u8> = (0..16).map(|i| i * 3 + 1).collect();
        ctx.buffer_data(GL_ARRAY_BUFFER, 16, GL_STATIC_DRAW, |n| Some(&data[..n]));
        ctx.buffer_sub_data(GL_ARRAY_BUFFER, 2, 3, |_| Some(b"xyz"));
        let mut out = [0xeeu8; 17];
        ctx.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 16, |n| Some(&mut out[..n]));
        assert_eq!(out, [1, 4, b'x', b'y', b'z', 16, 19, 22, 25, 28, 31, 34, 37, 40, 43, 46, 0xee]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        // Ranges: negative, beyond the end; an empty range at the end is fine.
        for (offset, size, error) in [
            (-1, 1, GL_INVALID_VALUE),
            (0, -1, GL_INVALID_VALUE),
            (14, 3, GL_INVALID_VALUE),
            (16, 0, GL_NO_ERROR),
            (17, 0, GL_INVALID_VALUE),
        ] {
            ctx.buffer_sub_data(GL_ARRAY_BUFFER, offset, size, |_| Some(b"abc"));
            assert_eq!(ctx.take_error(), error, "sub data {offset} {size}");
            ctx.get_buffer_sub_data(GL_ARRAY_BUFFER, offset, size, |n| Some(&mut out[..n]));
            assert_eq!(ctx.take_error(), error, "get sub data {offset} {size}");
        }
        assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), Some(16));
        assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), Some(GL_STATIC_DRAW as i32));
    }

    #[test]
    fn buffer_data_errors_in_mesas_order() {
        let mut ctx = context();
        ctx.buffer_data(GL_TEXTURE_2D, 4, GL_STATIC_DRAW, |_| None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.buffer_data(GL_ARRAY_BUFFER, -1, 0x1234, |_| None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION, "no buffer bound comes first");
        ctx.bind_buffer(GL_ARRAY_BUFFER, 3);
        ctx.buffer_data(GL_ARRAY_BUFFER, -1, 0x1234, |_| None);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.buffer_data(GL_ARRAY_BUFFER, 8, 0x1234, |_| None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.buffer_data(GL_ARRAY_BUFFER, isize::MAX, GL_STREAM_DRAW, |_| None);
        assert_eq!(ctx.take_error(), GL_OUT_OF_MEMORY);
        assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), Some(0));
        ctx.buffer_data(GL_ARRAY_BUFFER, 5, GL_DYNAMIC_COPY, |_| None);
        assert_eq!(ctx.buffers.lock().get(3).unwrap().data(), [0; 5]);
        assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_USAGE), Some(GL_DYNAMIC_COPY as i32));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn mapping_rules() {
        let (mut ctx, name) = bound_context();
        assert!(ctx.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY).is_null());
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION, "an empty buffer cannot be mapped");
        ctx.buffer_data(GL_ARRAY_BUFFER, 4, GL_STATIC_DRAW, |_| Some(b"abcd"));
        assert!(ctx.map_buffer(GL_ARRAY_BUFFER, 0x1234).is_null());
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        let p = ctx.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
        assert!(!p.is_null());
        assert_eq!(ctx.get_buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER), Some(p));
        assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), Some(1));
        assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), Some(GL_WRITE_ONLY as i32));
        assert!(ctx.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY).is_null());
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        // While mapped: sub data is an error after the range checks.
        ctx.buffer_sub_data(GL_ARRAY_BUFFER, 0, 9, |_| None);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 1, |_| None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert!(ctx.unmap_buffer(GL_ARRAY_BUFFER));
        assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), Some(GL_READ_WRITE as i32));
        assert!(!ctx.unmap_buffer(GL_ARRAY_BUFFER));
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.get_buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER), Some(std::ptr::null_mut()));
        // glBufferData unmaps.
        ctx.map_buffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
        ctx.buffer_data(GL_ARRAY_BUFFER, 2, GL_STREAM_DRAW, |_| None);
        assert!(!ctx.buffers.lock().get(name).unwrap().mapped);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn parameter_and_pointer_query_errors() {
        let mut ctx = context();
        assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, 0x1234), None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION, "the binding is checked before the pname");
        assert_eq!(ctx.get_buffer_pointer(GL_ARRAY_BUFFER, 0x1234), None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM, "the pname is checked before the binding");
        assert_eq!(ctx.get_buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER), None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 9);
        assert_eq!(ctx.get_buffer_parameter(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_ACCESS), Some(GL_READ_WRITE as i32));
        assert_eq!(ctx.get_buffer_parameter(GL_ELEMENT_ARRAY_BUFFER, 0x1234), None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.get_buffer_parameter(GL_PIXEL_UNPACK_BUFFER, GL_BUFFER_SIZE), None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION, "a pixel target with no buffer bound");
        assert_eq!(ctx.get_buffer_parameter(GL_PIXEL_UNPACK_BUFFER + 1, GL_BUFFER_SIZE), None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn names_bindings_and_deletion() {
        let mut ctx = context();
        assert_eq!(ctx.gen_buffers(-1), None);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        let names = ctx.gen_buffers(3).unwrap();
        assert_eq!(names, [1, 2, 3]);
        assert!(!ctx.is_buffer(1));
        ctx.bind_buffer(GL_ARRAY_BUFFER, 1);
        assert!(ctx.is_buffer(1));
        ctx.bind_buffer(0x1234, 2);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 1);
        ctx.vertex_pointer(2, GL_FLOAT, 8, 16);
        ctx.client_active_texture(GL_TEXTURE1);
        ctx.tex_coord_pointer(2, GL_FLOAT, 0, 4);
        ctx.bind_buffer(GL_ARRAY_BUFFER, 0);
        ctx.color_pointer(4, GL_UNSIGNED_BYTE, 0, 0x1000);
        ctx.delete_buffers(-1, &[]);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.delete_buffers(3, &[0, 12345, 1]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let a = &ctx.vertex_input.arrays;
        assert_eq!((a.array_buffer, a.element_array_buffer), (0, 0));
        assert_eq!((a.vertex.buffer, a.vertex.orphaned, a.vertex.pointer), (0, true, 16));
        assert!(a.tex_coords[1].orphaned);
        assert!(!a.color.orphaned);
        assert!(!ctx.is_buffer(1));
        // A new pointer specification clears the orphan mark.
        ctx.vertex_pointer(2, GL_FLOAT, 8, 0x2000);
        assert!(!ctx.vertex_input.arrays.vertex.orphaned);
        ctx.inside_begin_end = true;
        assert!(!ctx.is_buffer(2));
        assert_eq!(ctx.gen_buffers(1), None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
    }
}
