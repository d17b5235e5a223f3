//! Huge pages and prefaulting for large pixel buffers.
//!
//! A fresh buffer's pages are zeroed by the kernel when first touched, and on a machine
//! where a page fault costs about 2 µs that is most of a first frame: 1024 faults for each
//! 4 MiB layer of a 1024×1024 framebuffer. Backed by 2 MiB pages, the same layer takes two
//! faults (measured: 4 MiB first written in 2.0 ms with 4 KiB pages, 0.25–0.6 ms with 2 MiB
//! ones). Linux gives a mapping huge pages, under the default `madvise` policy, only where
//! asked and only for 2 MiB-aligned ranges inside it, so a large buffer is allocated with
//! 2 MiB of slack (never touched) and advised from its first aligned address on.
//!
//! Memory the caller lends (the OSMesa buffer) cannot be placed; its pages outside huge ones
//! are faulted in with one `MADV_POPULATE_WRITE` per range about to be written
//! ([`populate`]): the kernel then maps them in one pass instead of one trap per 4 KiB
//! (4 MiB of 4 KiB pages: 1.4 ms → 0.7–1.0 ms).
//!
//! (Padding a buffer so that glibc serves it from a mapping Linux aligns to 2 MiB does not
//! help: glibc writes its chunk header into the mapping's first page, and the kernel then
//! no longer faults a huge page in around it; `MADV_COLLAPSE` makes it one but took 1–4 ms.)
//!
//! The advice changes how the kernel backs memory, never its contents: the bytes are the
//! same with or without it.

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

/// The base page size the prefault rounds to (where pages are larger the rounding is only
/// finer than needed: the range stays inside pages that are written anyway).
const PAGE: usize = 4096;

/// Faults in, writable, the pages `bytes` lies in, memory about to be written whole: one
/// system call instead of a trap per page. Pages already present are left as they are;
/// contents never change. Ignored where the kernel lacks it (before Linux 5.14).
pub fn populate(bytes: &mut [u8]) {
    if bytes.is_empty() {
        return;
    }
    let start = bytes.as_mut_ptr() as usize;
    let first = start / PAGE * PAGE;
    advise_as(first, start + bytes.len() - first, POPULATE_WRITE);
}

#[cfg(target_os = "linux")]
const POPULATE_WRITE: i32 = libc::MADV_POPULATE_WRITE;
#[cfg(not(target_os = "linux"))]
const POPULATE_WRITE: i32 = 0;

fn advise(address: usize, len: usize) {
    #[cfg(target_os = "linux")]
    advise_as(address, len, libc::MADV_HUGEPAGE);
    #[cfg(not(target_os = "linux"))]
    let _ = (address, len);
}

#[cfg(target_os = "linux")]
fn advise_as(address: usize, len: usize, advice: i32) {
    // SAFETY: [address, address + len) lies inside an allocation this module's caller owns
    // (a Vec's buffer, kept alive by the borrow), the mapped buffer an OSMesa caller lent
    // (`advise_within`), or the pages a borrowed slice lies in (`populate`); MADV_HUGEPAGE
    // only changes how the kernel backs those pages and MADV_POPULATE_WRITE only maps them
    // as a write would, neither changes their contents or validity. A failure (no THP
    // support, a kernel before 5.14) is harmless and ignored: the writes that follow fault
    // the pages in as they always did.
    unsafe {
        libc::madvise(address as *mut libc::c_void, len, advice);
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_as(_address: usize, _len: usize, _advice: i32) {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn populating_keeps_contents() {
        let mut buffer: Vec<u8> = (0..3 * PAGE + 100).map(|i| (i % 251) as u8).collect();
        populate(&mut buffer[10..]);
        assert!(buffer.iter().enumerate().all(|(i, &v)| v == (i % 251) as u8));
        // Fresh pages stay zero.
        let mut fresh = vec![0u8; 64 * PAGE];
        populate(&mut fresh);
        assert!(fresh.iter().all(|&v| v == 0));
    }
}
