//! The per-level copies of a block and the call that picks one: the only unsafe code of the
//! `simd` room.
//!
//! Each wrapper below is compiled with its level's `target_feature`s and does nothing but
//! call the closure it is given; because [`per_level!`](crate::simd::per_level) marks that
//! closure `#[inline(always)]`, the compiler inlines it into every wrapper, compiling the
//! block once per level. Calling a `target_feature` function from code compiled for the
//! baseline is `unsafe`: the caller promises the CPU has the features. [`run`] takes the
//! level as a [`Supported`], which only `Supported::new` makes, after detecting the level,
//! so a level the CPU lacks can never be run whatever a caller asks for.
#![allow(unsafe_code)]

use super::Supported;

/// Runs `f` compiled for `level` (a level this CPU has: that is what a [`Supported`] is).
/// `f` should be an `#[inline(always)]` closure (as [`per_level!`](crate::simd::per_level)
/// makes it), or its body is compiled once, for the baseline, and only called from here.
/// Each level's copy is a call (SSE2's too), so that the dispatch itself stays small enough
/// to be inlined where a kernel is called.
#[inline(always)]
pub fn run<R>(level: Supported, f: impl FnOnce() -> R) -> R {
    match level.0 {
        #[cfg(target_arch = "x86_64")]
        super::Level::Avx2 => {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have
            // (`Supported::new`): here AVX2, and the AVX it implies.
            unsafe { avx2(f) }
        }
        #[cfg(target_arch = "x86_64")]
        super::Level::Sse41 => {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have
            // (`Supported::new`): here SSE4.1, and the SSSE3 and SSE3 it implies.
            unsafe { sse41(f) }
        }
        #[cfg(target_arch = "x86_64")]
        super::Level::Sse2 => sse2(f),
        #[cfg(not(target_arch = "x86_64"))]
        super::Level::Portable => f(),
    }
}

/// `f` compiled with AVX2 (256-bit integer and float vectors, VEX encodings). Not FMA:
/// results must not depend on the level (see the room's doc).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn avx2<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// `f` compiled with SSE4.1.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "sse4.1")]
fn sse41<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// `f` compiled for the x86-64 baseline the crate is built for, out of line like the others.
#[cfg(target_arch = "x86_64")]
#[inline(never)]
fn sse2<R>(f: impl FnOnce() -> R) -> R {
    f()
}
