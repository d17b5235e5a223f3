//! Buffer objects (GL 1.5): the table of names and the storage behind them.
//!
//! The whole table is one struct, [`BufferTable`], so that it can later be shared between
//! contexts as a unit. Storage is a `Vec<u8>` that is only replaced (never grown in place) by
//! glBufferData, and never while mapped: the pointer glMapBuffer hands out stays valid until
//! glUnmapBuffer, glBufferData or glDeleteBuffers. While a buffer is mapped the context does
//! not touch its bytes (glBufferSubData and friends are GL_INVALID_OPERATION, draws too), so
//! the caller's writes through the mapped pointer never race with a Rust reference.
use crate::gl::enums::*;
use crate::gl::names::NameTable;
use crate::gl::types::GLenum;

/// The binding points tessera implements: vertex arrays and indices (GL 1.5), the pixel
/// pack and unpack buffers (GL 2.1, ARB_pixel_buffer_object).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BufferTarget {
    Array,
    ElementArray,
    PixelPack,
    PixelUnpack,
}

impl BufferTarget {
    pub fn from_gl(e: GLenum) -> Option<Self> {
        match e {
            GL_ARRAY_BUFFER => Some(Self::Array),
            GL_ELEMENT_ARRAY_BUFFER => Some(Self::ElementArray),
            GL_PIXEL_PACK_BUFFER => Some(Self::PixelPack),
            GL_PIXEL_UNPACK_BUFFER => Some(Self::PixelUnpack),
            _ => None,
        }
    }
}

/// Whether `usage` is one of the nine glBufferData usage hints.
pub fn is_usage(usage: GLenum) -> bool {
    matches!(
        usage,
        GL_STREAM_DRAW
            | GL_STREAM_READ
            | GL_STREAM_COPY
            | GL_STATIC_DRAW
            | GL_STATIC_READ
            | GL_STATIC_COPY
            | GL_DYNAMIC_DRAW
            | GL_DYNAMIC_READ
            | GL_DYNAMIC_COPY
    )
}

/// Whether `access` is a glMapBuffer access.
pub fn is_access(access: GLenum) -> bool {
    matches!(access, GL_READ_ONLY | GL_WRITE_ONLY | GL_READ_WRITE)
}

/// One buffer object.
#[derive(Debug)]
pub struct BufferObject {
    data: Vec<u8>,
    pub usage: GLenum,
    /// GL_BUFFER_ACCESS: the access of the current mapping; GL_READ_WRITE when unmapped (as
    /// Mesa reports it; GL 2.1 only says what glMapBuffer sets).
    pub access: GLenum,
    pub mapped: bool,
}

impl Default for BufferObject {
    fn default() -> Self {
        BufferObject { data: Vec::new(), usage: GL_STATIC_DRAW, access: GL_READ_WRITE, mapped: false }
    }
}

/// The allocation failed (GL_OUT_OF_MEMORY).
#[derive(Debug, PartialEq, Eq)]
pub struct OutOfMemory;

impl BufferObject {
    pub fn size(&self) -> usize {
        self.data.len()
    }

    /// The contents; callers check `mapped` first (see the module docs).
    pub fn data(&self) -> &[u8] {
        &self.data
    }

    /// glBufferData: new storage of `size` bytes, a copy of `contents` when given (exactly
    /// `size` bytes) and zeros otherwise. Allocation failure leaves the buffer as it was.
    /// A mapped buffer is unmapped first, as in Mesa.
    pub fn set_data(&mut self, size: usize, contents: Option<&[u8]>, usage: GLenum) -> Result<(), OutOfMemory> {
        let mut data = Vec::new();
        data.try_reserve_exact(size).map_err(|_| OutOfMemory)?;
        match contents {
            Some(bytes) => data.extend_from_slice(&bytes[..size.min(bytes.len())]),
            None => data.resize(size, 0),
        }
        data.resize(size, 0);
        self.data = data;
        self.usage = usage;
        self.mapped = false;
        self.access = GL_READ_WRITE;
        Ok(())
    }

    /// The bytes `offset..offset + len`, when inside the buffer.
    pub fn range(&self, offset: usize, len: usize) -> Option<&[u8]> {
        self.data.get(offset..offset.checked_add(len)?)
    }

    /// Writable bytes `offset..offset + len`, when inside the buffer.
    pub fn range_mut(&mut self, offset: usize, len: usize) -> Option<&mut [u8]> {
        self.data.get_mut(offset..offset.checked_add(len)?)
    }

    /// glUnmapBuffer: GL_BUFFER_ACCESS returns to GL_READ_WRITE, as in Mesa.
    pub fn unmap(&mut self) {
        self.mapped = false;
        self.access = GL_READ_WRITE;
    }

    /// glMapBuffer: marks the buffer mapped and returns the address of its storage.
    pub fn map(&mut self, access: GLenum) -> *mut u8 {
        self.mapped = true;
        self.access = access;
        self.data.as_mut_ptr()
    }

    /// The address glMapBuffer returned, while mapped (GL_BUFFER_MAP_POINTER).
    pub fn map_pointer(&mut self) -> *mut u8 {
        if self.mapped {
            self.data.as_mut_ptr()
        } else {
            std::ptr::null_mut()
        }
    }
}

/// Every buffer name of a context (later: of a share group).
#[derive(Debug, Default)]
pub struct BufferTable {
    names: NameTable<BufferObject>,
}

impl BufferTable {
    /// glGenBuffers: `n` unused names, reserved (see [`NameTable`]: like Mesa, names continue
    /// after the largest name ever used). A count the memory cannot hold is [`OutOfMemory`],
    /// not an abort.
    pub fn generate(&mut self, n: usize) -> Result<Vec<u32>, OutOfMemory> {
        self.names.generate(n).map_err(|_| OutOfMemory)
    }

    /// glBindBuffer's object creation: any nonzero name becomes an object at its first bind.
    pub fn create_on_bind(&mut self, name: u32) {
        self.names.get_or_create(name, BufferObject::default);
    }

    /// glIsBuffer.
    pub fn is_buffer(&self, name: u32) -> bool {
        self.names.is_object(name)
    }

    /// Frees `name` (and its storage); false when it was not a name in use.
    pub fn delete(&mut self, name: u32) -> bool {
        let used = self.names.is_used(name);
        self.names.delete(name);
        used
    }

    pub fn get(&self, name: u32) -> Option<&BufferObject> {
        self.names.get(name)
    }

    pub fn get_mut(&mut self, name: u32) -> Option<&mut BufferObject> {
        self.names.get_mut(name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_continue_after_the_largest_ever_used_like_mesa() {
        let mut table = BufferTable::default();
        assert_eq!(table.generate(3), Ok(vec![1, 2, 3]));
        assert!(!table.is_buffer(1), "a generated name is no object before its first bind");
        table.create_on_bind(77);
        assert!(table.is_buffer(77));
        assert!(table.delete(1) && table.delete(2));
        assert!(!table.delete(2) && !table.delete(0) && !table.delete(12345));
        assert_eq!(table.generate(2), Ok(vec![78, 79]));
        assert!(table.delete(3) && table.delete(77) && table.delete(78) && table.delete(79));
        assert_eq!(table.generate(1), Ok(vec![80]));
        assert_eq!(table.generate(0), Ok(vec![]));
        assert_eq!(table.generate(usize::MAX / 2), Err(OutOfMemory));
        table.create_on_bind(u32::MAX);
        assert_eq!(table.generate(2), Ok(vec![1, 2]));
    }

    #[test]
    fn bind_creates_reserved_and_unknown_names_once() {
        let mut table = BufferTable::default();
        let [a] = table.generate(1).unwrap()[..] else { panic!() };
        table.create_on_bind(a);
        table.get_mut(a).unwrap().set_data(4, Some(b"abcd"), GL_DYNAMIC_DRAW).unwrap();
        table.create_on_bind(a);
        assert_eq!(table.get(a).unwrap().data(), b"abcd");
        table.create_on_bind(0);
        assert!(!table.is_buffer(0));
    }

    #[test]
    fn data_ranges_and_mapping() {
        let mut buffer = BufferObject::default();
        assert_eq!(
            (buffer.size(), buffer.usage, buffer.access, buffer.mapped),
            (0, GL_STATIC_DRAW, GL_READ_WRITE, false)
        );
        buffer.set_data(6, Some(b"abcdef"), GL_STREAM_READ).unwrap();
        assert_eq!(buffer.range(2, 3), Some(&b"cde"[..]));
        assert_eq!(buffer.range(6, 0), Some(&b""[..]));
        assert_eq!(buffer.range(5, 2), None);
        assert_eq!(buffer.range(usize::MAX, 2), None);
        buffer.range_mut(0, 1).unwrap()[0] = b'X';
        assert!(buffer.map_pointer().is_null());
        let p = buffer.map(GL_WRITE_ONLY);
        assert_eq!((buffer.mapped, buffer.access, buffer.map_pointer()), (true, GL_WRITE_ONLY, p));
        // glBufferData unmaps and zero-fills without contents.
        buffer.set_data(3, None, GL_STATIC_COPY).unwrap();
        assert_eq!((buffer.data(), buffer.mapped, buffer.access), (&[0u8; 3][..], false, GL_READ_WRITE));
    }

    #[test]
    fn impossible_allocations_fail_and_keep_the_old_storage() {
        let mut buffer = BufferObject::default();
        buffer.set_data(2, Some(b"ok"), GL_STATIC_DRAW).unwrap();
        assert_eq!(buffer.set_data(usize::MAX / 2, None, GL_STREAM_DRAW), Err(OutOfMemory));
        assert_eq!((buffer.data(), buffer.usage), (&b"ok"[..], GL_STATIC_DRAW));
    }

    #[test]
    fn targets_usages_and_accesses() {
        assert_eq!(BufferTarget::from_gl(GL_ARRAY_BUFFER), Some(BufferTarget::Array));
        assert_eq!(BufferTarget::from_gl(GL_ELEMENT_ARRAY_BUFFER), Some(BufferTarget::ElementArray));
        assert_eq!(BufferTarget::from_gl(GL_PIXEL_PACK_BUFFER), Some(BufferTarget::PixelPack));
        assert_eq!(BufferTarget::from_gl(GL_PIXEL_UNPACK_BUFFER), Some(BufferTarget::PixelUnpack));
        assert_eq!(BufferTarget::from_gl(GL_PIXEL_UNPACK_BUFFER + 1), None);
        assert!(is_usage(GL_DYNAMIC_COPY) && is_usage(GL_STREAM_DRAW) && !is_usage(GL_STREAM_DRAW + 3));
        assert!(is_access(GL_READ_ONLY) && is_access(GL_READ_WRITE) && !is_access(GL_READ_WRITE + 1));
    }
}
