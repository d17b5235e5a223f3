//! The one wrapper around caller-owned pixel memory (the OSMesa buffer).
//!
//! The caller promises, by the OSMesa contract, that the buffer handed to OSMesaMakeCurrent
//! holds `row_length × height` pixels of the format and type it named and stays valid while
//! bound. [`CallerBuffer`] records that extent once and then only lets safe code write whole
//! rows inside it.

// The room denies unsafe code (`framebuffer/mod.rs`); this wrapper is its one exception.
#![allow(unsafe_code)]

/// A byte range of memory owned by the C caller.
pub struct CallerBuffer {
    ptr: *mut u8,
    len: usize,
}

// SAFETY: the buffer is plain memory the caller lent to the context; tessera writes it only
// from the thread holding the context's lock, and the OSMesa contract forbids the caller from
// using it concurrently with rendering.
unsafe impl Send for CallerBuffer {}

impl CallerBuffer {
    /// Wraps `len` bytes at `ptr`.
    ///
    /// # Safety
    /// `ptr` must be valid for writes of `len` bytes for as long as this value is used.
    pub unsafe fn new(ptr: *mut u8, len: usize) -> CallerBuffer {
        CallerBuffer { ptr, len }
    }

    /// No memory: what a presenter holds while it lends its buffer (`Present::lend`).
    pub fn empty() -> CallerBuffer {
        CallerBuffer { ptr: std::ptr::null_mut(), len: 0 }
    }

    /// The address, as the caller gave it.
    pub fn as_ptr(&self) -> *mut u8 {
        self.ptr
    }

    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Asks the kernel to back the huge-page-aligned interior of the buffer with huge pages
    /// (`super::pages`): the first write of a fresh 1024×1024 RGBA buffer then costs about
    /// 500 page faults instead of 1024. Only for a buffer written whole (rows without gaps
    /// between them), so that no page is backed that tessera would not have touched; the
    /// advice changes how the kernel backs the caller's pages, never their contents.
    pub fn advise_huge_pages(&self) {
        if !self.ptr.is_null() {
            super::pages::advise_within(self.ptr as usize, self.len);
        }
    }

    /// The bytes `[offset, offset + count)` as a mutable slice; `None` when outside.
    pub fn bytes_mut(&mut self, offset: usize, count: usize) -> Option<&mut [u8]> {
        let end = offset.checked_add(count)?;
        if end > self.len || self.ptr.is_null() {
            return None;
        }
        // SAFETY: [offset, end) lies inside the `len` bytes the constructor's contract makes
        // valid for writes, and `&mut self` makes this the only live view.
        Some(unsafe { std::slice::from_raw_parts_mut(self.ptr.add(offset), count) })
    }

    /// The first `count` pixels of RGBA8 memory; `None` when the buffer holds fewer.
    pub fn unorm8_pixels_mut(&mut self, count: usize) -> Option<&mut [[u8; 4]]> {
        let bytes = self.bytes_mut(0, count.checked_mul(4)?)?;
        Some(bytes.as_chunks_mut::<4>().0)
    }
}

#[cfg(test)]
impl CallerBuffer {
    /// The memory of a test's vector, which must neither move nor be dropped while the
    /// value is used.
    pub fn of_test_vec(memory: &mut [u8]) -> CallerBuffer {
        // SAFETY: the slice is valid for writes of its length; the test keeps it alive and
        // in place while the value is used (the contract above).
        unsafe { CallerBuffer::new(memory.as_mut_ptr(), memory.len()) }
    }
}
