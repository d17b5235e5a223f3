//! Huge pages for large pixel buffers.
//!
//! A fresh buffer's pages are zeroed by the kernel when first touched, and on a machine
//! where a page fault costs about 2 µs that is most of a first frame: 1024 faults for each
//! 4 MiB layer of a 1024×1024 framebuffer. Backed by 2 MiB pages, the same layer takes two
//! faults (measured: 4 MiB first written in 2.0 ms with 4 KiB pages, 0.25–0.6 ms with 2 MiB
//! ones). Linux gives a mapping huge pages, under the default `madvise` policy, only where
//! asked and only for 2 MiB-aligned ranges inside it, so a large buffer is allocated with
//! 2 MiB of slack (never touched) and advised from its first aligned address on.
//!
//! The advice changes how the kernel backs memory tessera owns, never its contents: the
//! bytes are the same with or without it.

// The room denies unsafe code (`framebuffer/mod.rs`); this advice is one of its exceptions.
#![allow(unsafe_code)]

/// The huge-page size (x86-64, and arm64 with 4 KiB base pages).
pub const HUGE_PAGE: usize = 2 << 20;

/// Elements of `T` to allocate beyond a buffer of `bytes` bytes, so that its 2 MiB-aligned
/// interior covers all of it but the first partial huge page: none for buffers below two
/// huge pages (the slack would cost more than it saves).
pub fn slack<T>(bytes: usize) -> usize {
    if bytes < 2 * HUGE_PAGE {
        0
    } else {
        HUGE_PAGE / std::mem::size_of::<T>().max(1)
    }
}

/// Asks the kernel to back the 2 MiB-aligned part of `buffer`'s allocation (its capacity,
/// slack included) with huge pages; does nothing where that is not possible.
pub fn advise_huge_pages<T>(buffer: &mut Vec<T>) {
    let start = buffer.as_mut_ptr() as usize;
    let end = start + buffer.capacity() * std::mem::size_of::<T>();
    let (first, last) = (start.next_multiple_of(HUGE_PAGE), end / HUGE_PAGE * HUGE_PAGE);
    if last > first {
        advise(first, last - first);
    }
}

/// Asks the kernel to back with huge pages each 2 MiB-aligned range that lies wholly
/// inside `[start, start + len)`, memory the caller vouches is mapped and will be written
/// whole (the OSMesa caller's buffer, [`super::external::CallerBuffer`]); nothing below two
/// huge pages.
pub fn advise_within(start: usize, len: usize) {
    if len < 2 * HUGE_PAGE {
        return;
    }
    let (first, last) = (start.next_multiple_of(HUGE_PAGE), start.saturating_add(len) / HUGE_PAGE * HUGE_PAGE);
    if last > first {
        advise(first, last - first);
    }
}

#[cfg(target_os = "linux")]
fn advise(address: usize, len: usize) {
    // SAFETY: [address, address + len) lies inside an allocation this module's caller owns
    // (a Vec's buffer, kept alive by the borrow) or the mapped buffer an OSMesa caller lent
    // (`advise_within`); MADV_HUGEPAGE only changes how the kernel
    // backs those pages, not their contents or validity. A failure (no THP support) is
    // harmless and ignored.
    unsafe {
        libc::madvise(address as *mut libc::c_void, len, libc::MADV_HUGEPAGE);
    }
}

#[cfg(not(target_os = "linux"))]
fn advise(_address: usize, _len: usize) {}
