//! The caller's memory: every read and write through a pointer a GL, OSMesa or GLX caller
//! passed goes through this module, so the entry points themselves only name what they read.
//!
//! One alignment policy: tessera never assumes a caller's pointer is aligned for its type
//! (C code hands out `GLfloat*` into byte buffers and packed structs). Typed values are read
//! with `read_unaligned` and written with `write_unaligned`, element by element, and come back
//! as owned values (arrays and vectors), never as borrowed typed slices. Slices of caller
//! memory are formed only of bytes (`u8`, alignment 1): pixel images, client arrays, buffer
//! data. So a misaligned but otherwise valid pointer is never undefined behaviour here.
//!
//! NULL is handled here too: a read of NULL gives `None` (or nothing), a write to NULL does
//! nothing. What the caller must still guarantee — that a non-null pointer designates as many
//! readable or writable elements as the command's arguments say — is the GL contract of each
//! entry point, stated in its `# Safety` section; these functions forward it.
use crate::gl::types::*;
use crate::vertex::arrays::ClientMemory;
use std::ffi::{c_char, CStr};
use std::ops::Range;

/// `N` consecutive values at `p`; `None` for NULL.
///
/// # Safety
/// A non-null `p` must point to `N` readable values of `T`.
pub(crate) unsafe fn read<T: Copy, const N: usize>(p: *const T) -> Option<[T; N]> {
    if p.is_null() {
        return None;
    }
    // SAFETY: non-null and N readable values by the contract; read_unaligned needs no alignment.
    Some(unsafe { std::ptr::read_unaligned(p as *const [T; N]) })
}

/// The value `index` elements after `p` (for strided arrays); `None` for NULL.
///
/// # Safety
/// A non-null `p` must have a readable value of `T` `index` elements in.
pub(crate) unsafe fn read_at<T: Copy>(p: *const T, index: usize) -> Option<T> {
    if p.is_null() {
        return None;
    }
    // SAFETY: readable by the contract; read_unaligned needs no alignment.
    Some(unsafe { p.wrapping_add(index).read_unaligned() })
}

/// `count` consecutive values at `p`; `None` for NULL.
///
/// # Safety
/// A non-null `p` must point to `count` readable values of `T`.
pub(crate) unsafe fn read_vec<T: Copy>(p: *const T, count: usize) -> Option<Vec<T>> {
    if p.is_null() {
        return None;
    }
    // SAFETY: element i < count is readable by the contract; read_unaligned needs no alignment.
    Some((0..count).map(|i| unsafe { p.add(i).read_unaligned() }).collect())
}

/// The values of a C array of `count` elements; empty for NULL or a count below 1 (the
/// context reports a negative count itself).
///
/// # Safety
/// A non-null `p` must point to `count` readable values of `T` when `count` is positive.
pub(crate) unsafe fn read_array<T: Copy>(p: *const T, count: GLsizei) -> Vec<T> {
    if count <= 0 {
        return Vec::new();
    }
    // SAFETY: forwarded contract.
    unsafe { read_vec(p, count as usize) }.unwrap_or_default()
}

/// The values of a list ended by `end` (GLX and OSMesa attribute lists), read `step` at a
/// time: each step's first value is tested for `end`, the step's values are kept. Empty for
/// NULL.
///
/// # Safety
/// A non-null `p` must point to a list whose steps are readable up to the one starting
/// with `end`.
pub(crate) unsafe fn read_terminated<T: Copy + PartialEq>(p: *const T, end: T, step: impl Fn(T) -> usize) -> Vec<T> {
    let mut values = Vec::new();
    if p.is_null() {
        return values;
    }
    let mut i = 0;
    loop {
        // SAFETY: the list is readable up to its terminator, which ends the loop.
        let first = unsafe { p.add(i).read_unaligned() };
        if first == end {
            return values;
        }
        let n = step(first).max(1);
        // SAFETY: a step that does not start with the terminator is readable whole.
        values.extend((0..n).map(|k| unsafe { p.add(i + k).read_unaligned() }));
        i += n;
    }
}

/// Writes `value` at `p`; nothing for NULL.
///
/// # Safety
/// A non-null `p` must be valid for a write of one `T`.
pub(crate) unsafe fn write<T>(p: *mut T, value: T) {
    if !p.is_null() {
        // SAFETY: non-null and writable by the contract; write_unaligned needs no alignment.
        unsafe { p.write_unaligned(value) }
    }
}

/// Writes `values` at consecutive places from `p`; nothing for NULL.
///
/// # Safety
/// A non-null `p` must be valid for writes of as many `T` as `values` yields.
pub(crate) unsafe fn write_all<T>(p: *mut T, values: impl IntoIterator<Item = T>) {
    if p.is_null() {
        return;
    }
    for (i, value) in values.into_iter().enumerate() {
        // SAFETY: element i is writable by the contract; write_unaligned needs no alignment.
        unsafe { p.add(i).write_unaligned(value) }
    }
}

/// The bytes `span` of the caller's buffer at `p`; `None` for NULL.
///
/// # Safety
/// A non-null `p` must designate at least `span.end` readable bytes, unchanged while the
/// returned slice lives (the call).
pub(crate) unsafe fn bytes<'a, V>(p: *const V, span: Range<usize>) -> Option<&'a [u8]> {
    if p.is_null() || span.start > span.end {
        return None;
    }
    // SAFETY: readable by the contract; bytes have alignment 1.
    Some(unsafe { std::slice::from_raw_parts((p as *const u8).add(span.start), span.len()) })
}

/// The bytes `span` of the caller's buffer at `p`, writable; `None` for NULL.
///
/// # Safety
/// A non-null `p` must designate at least `span.end` writable bytes that nothing else
/// accesses while the returned slice lives (the call).
pub(crate) unsafe fn bytes_mut<'a, V>(p: *mut V, span: Range<usize>) -> Option<&'a mut [u8]> {
    if p.is_null() || span.start > span.end {
        return None;
    }
    // SAFETY: writable and unaliased by the contract; bytes have alignment 1.
    Some(unsafe { std::slice::from_raw_parts_mut((p as *mut u8).add(span.start), span.len()) })
}

/// The NUL-terminated string at `p`; `None` for NULL.
///
/// # Safety
/// A non-null `p` must point to a NUL-terminated string, unchanged during the call.
pub(crate) unsafe fn c_str<'a>(p: *const c_char) -> Option<&'a CStr> {
    if p.is_null() {
        return None;
    }
    // SAFETY: non-null and NUL-terminated by the contract.
    Some(unsafe { CStr::from_ptr(p) })
}

/// The caller's memory, as GL's contract for client arrays and index arrays promises it:
/// the context reads through it the byte ranges it computed from a draw's arguments.
pub(crate) struct CallerMemory;

impl ClientMemory for CallerMemory {
    fn bytes(&self, address: usize, len: usize) -> Option<&[u8]> {
        if address == 0 || address.checked_add(len)? > isize::MAX as usize {
            return None;
        }
        if len == 0 {
            return Some(&[]);
        }
        // SAFETY: the context asks for the bytes of the elements (or indices) a draw uses,
        // computed from the pointer the caller gave and the draw's arguments (vertex_input's
        // `byte_extent`). GL requires the caller to provide those elements in one array it
        // owns, unchanged while the command runs; the slice lives only during the call.
        unsafe { bytes(address as *const u8, 0..len) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn misaligned_values_are_read_and_written_whole() {
        let mut storage = [0u8; 64];
        // A GLfloat pointer one byte into the buffer: misaligned for f32.
        let p = storage.as_mut_ptr().wrapping_add(1) as *mut GLfloat;
        // SAFETY: 63 writable bytes from p hold the 12 floats written here.
        unsafe { write_all(p, [1.5f32, -2.0, 3.25]) };
        // SAFETY: as above, three floats were written.
        assert_eq!(unsafe { read::<_, 3>(p) }, Some([1.5, -2.0, 3.25]));
        // SAFETY: as above.
        assert_eq!(unsafe { read_vec(p as *const GLfloat, 2) }, Some(vec![1.5, -2.0]));
        // SAFETY: as above.
        unsafe { write(p.wrapping_add(1), 7.0) };
        // SAFETY: as above.
        assert_eq!(unsafe { read_array(p as *const GLfloat, 3) }, vec![1.5, 7.0, 3.25]);
    }

    #[test]
    fn null_reads_nothing_and_null_writes_nothing() {
        let null: *const GLint = std::ptr::null();
        // SAFETY: NULL is allowed everywhere.
        unsafe {
            assert_eq!(read::<_, 4>(null), None);
            assert_eq!(read_vec(null, 4), None);
            assert!(read_array(null, 4).is_empty());
            assert!(read_terminated(null, 0, |_| 2).is_empty());
            assert!(bytes(null, 0..4).is_none());
            assert!(c_str(std::ptr::null()).is_none());
            write(std::ptr::null_mut::<GLint>(), 1);
            write_all(std::ptr::null_mut::<GLint>(), [1, 2]);
        }
        let values = [1, 2];
        // SAFETY: two readable values; a count below 1 reads none.
        assert!(unsafe { read_array(values.as_ptr(), -1) }.is_empty());
    }

    #[test]
    fn terminated_lists_stop_at_the_terminator_of_a_step() {
        // Pairs, except the key 5 which stands alone; 0 ends the list.
        let list = [8, 0, 5, 9, 1, 0, 77];
        // SAFETY: the list is readable up to its terminator.
        let values = unsafe { read_terminated(list.as_ptr(), 0, |key| if key == 5 { 1 } else { 2 }) };
        assert_eq!(values, vec![8, 0, 5, 9, 1]);
    }
}
