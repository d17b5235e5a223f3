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
//!
//! [`run_with`] also hands the body its level as a constant of the copy, so that the lane
//! helpers at the end, which take it, keep only that level's instructions: [`sign_mask16`]
//! (lane masks to a 16-bit mask by movemask, where LLVM extracts lanes one by one) and
//! [`load_block`]/[`store_block`] (a 4×4 block of 32-bit pixels as four row loads joined in
//! registers: filling a stack array row by row and reading it back as 256-bit vectors
//! stalls on store forwarding, measured as a quarter of the depth kernel's time; and one
//! bounds check per block instead of one per row). [`outlined`]
//! runs a body in a per-level copy that is never inlined into its caller: a batch of blocks'
//! stage compiled once per level and called directly from the walk's copy.
#![allow(unsafe_code)]

use super::{Level, Supported};

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

/// `f(level)` through the wrapper of `level` among `$avx2`, `$sse41` (`target_feature`
/// functions) and `$sse2`: the match of [`run_with`] and [`outlined`], which differ only in
/// the wrappers they call.
macro_rules! call_at_level {
    ($level:expr, $f:ident, $avx2:ident, $sse41:ident, $sse2:ident) => {
        match $level.0 {
            #[cfg(target_arch = "x86_64")]
            Level::Avx2 => {
                // SAFETY: a `Supported` holds only a level the CPU was detected to have
                // (`Supported::new`): here AVX2, and the AVX it implies.
                unsafe {
                    $avx2(
                        #[inline(always)]
                        move || $f(Supported(Level::Avx2)),
                    )
                }
            }
            #[cfg(target_arch = "x86_64")]
            Level::Sse41 => {
                // SAFETY: a `Supported` holds only a level the CPU was detected to have
                // (`Supported::new`): here SSE4.1, and the SSSE3 and SSE3 it implies.
                unsafe {
                    $sse41(
                        #[inline(always)]
                        move || $f(Supported(Level::Sse41)),
                    )
                }
            }
            #[cfg(target_arch = "x86_64")]
            Level::Sse2 => $sse2(
                #[inline(always)]
                move || $f(Supported(Level::Sse2)),
            ),
            #[cfg(not(target_arch = "x86_64"))]
            Level::Portable => $f(Supported(Level::Portable)),
        }
    };
}

/// [`call_at_level!`] without an SSE4.1 copy: that level runs the SSE2 wrapper, given
/// `Supported(Sse2)` (SSE2 is the x86-64 baseline, which every CPU has).
macro_rules! call_at_level_sse2_for_sse41 {
    ($level:expr, $f:ident, $avx2:ident, $sse2:ident) => {
        match $level.0 {
            #[cfg(target_arch = "x86_64")]
            Level::Avx2 => {
                // SAFETY: a `Supported` holds only a level the CPU was detected to have
                // (`Supported::new`): here AVX2, and the AVX it implies.
                unsafe {
                    $avx2(
                        #[inline(always)]
                        move || $f(Supported(Level::Avx2)),
                    )
                }
            }
            #[cfg(target_arch = "x86_64")]
            Level::Sse41 | Level::Sse2 => $sse2(
                #[inline(always)]
                move || $f(Supported(Level::Sse2)),
            ),
            #[cfg(not(target_arch = "x86_64"))]
            Level::Portable => $f(Supported(Level::Portable)),
        }
    };
}

/// Runs `f(level)` compiled for `level`, as [`run`]: `f` receives the level as a constant
/// of its copy (each wrapper passes its own), so the helpers that take it keep only their
/// level's instructions.
#[inline(always)]
pub fn run_with<R>(level: Supported, f: impl FnOnce(Supported) -> R) -> R {
    call_at_level!(level, f, avx2, sse41, sse2)
}

/// Runs `f(level)` compiled for `level` in a copy that is never inlined into the caller
/// (unlike [`run`]'s, which LLVM may inline into a caller compiled for the same level). With
/// `level` a constant (inside a [`run_with`] copy) the call goes straight to the level's
/// copy: one call, no dispatch, and the body compiled once per level however many callers
/// there are.
#[inline(always)]
pub fn outlined<R>(level: Supported, f: impl FnOnce(Supported) -> R) -> R {
    call_at_level!(level, f, avx2_outlined, sse41_outlined, sse2)
}

/// [`run_with`] for a body whose SSE4.1 copy measured no faster than its SSE2 one: the
/// SSE4.1 level runs the SSE2 copy (given `Supported(Sse2)`, which every x86-64 CPU has),
/// so the body is compiled twice, not three times. For the stencil/depth kernels, whose
/// SSE4.1 code ran about 10 % more instructions than SSE2's on the benchmark's scenes
/// (callgrind), and whose third copy cost the libraries tens of kilobytes.
#[inline(always)]
pub fn run_with_sse2_for_sse41<R>(level: Supported, f: impl FnOnce(Supported) -> R) -> R {
    call_at_level_sse2_for_sse41!(level, f, avx2, sse2)
}

/// [`outlined`] with the SSE4.1 level running the SSE2 copy, as
/// [`run_with_sse2_for_sse41`].
#[inline(always)]
pub fn outlined_sse2_for_sse41<R>(level: Supported, f: impl FnOnce(Supported) -> R) -> R {
    call_at_level_sse2_for_sse41!(level, f, avx2_outlined, sse2)
}

/// Runs `f(level)` in one out-of-line copy compiled for the SSE2 baseline, whatever the
/// level (given `Supported(Sse2)`): for a body whose wider copies are not worth their size
/// (the span path's conversions and blends: lines, points and pixel rectangles, whose spans
/// are short; its AVX2 copy alone was 96 KB of each library, issue #18's 5 MB limit).
#[inline(always)]
pub fn baseline<R>(f: impl FnOnce(Supported) -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    {
        sse2(
            #[inline(always)]
            move || f(Supported(Level::Sse2)),
        )
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        f(Supported(Level::Portable))
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

/// [`avx2`], never inlined.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline(never)]
fn avx2_outlined<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// [`sse41`], never inlined.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "sse4.1")]
#[inline(never)]
fn sse41_outlined<R>(f: impl FnOnce() -> R) -> R {
    f()
}

// ---------------------------------------------------------------------------------------
// Lane helpers.

/// The sign bits of 16 lanes (lane `i`'s bit 31 as bit `i`): lane masks (all-ones or zero
/// words) packed into a 16-bit mask. LLVM compiles the plain shift-and-OR loop as 16 lane
/// extractions; this is two `vmovmskps` at AVX2, and at SSE2 and SSE4.1 two signed packs to
/// 16 bits, one to 8 bits (which keep each lane's sign) and one `pmovmskb`.
#[inline(always)]
pub fn sign_mask16(level: Supported, m: &[u32; 16]) -> u16 {
    #[cfg(target_arch = "x86_64")]
    {
        if level.0 == Level::Avx2 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2.
            return unsafe { sign_mask16_avx2(m) };
        }
        sign_mask16_sse2(m)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        let mut bits = 0u16;
        for (i, &v) in m.iter().enumerate() {
            bits |= ((v >> 31) as u16) << i;
        }
        bits
    }
}

#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn sign_mask16_sse2(m: &[u32; 16]) -> u16 {
    use std::arch::x86_64::{__m128i, _mm_loadu_si128, _mm_movemask_epi8, _mm_packs_epi16, _mm_packs_epi32};
    let p = m.as_ptr() as *const __m128i;
    // SAFETY: `m` is 16 u32 (64 bytes): the four unaligned 16-byte loads read inside it; SSE2
    // is the x86-64 baseline.
    unsafe {
        let lo = _mm_packs_epi32(_mm_loadu_si128(p), _mm_loadu_si128(p.add(1)));
        let hi = _mm_packs_epi32(_mm_loadu_si128(p.add(2)), _mm_loadu_si128(p.add(3)));
        _mm_movemask_epi8(_mm_packs_epi16(lo, hi)) as u16
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn sign_mask16_avx2(m: &[u32; 16]) -> u16 {
    use std::arch::x86_64::{_mm256_loadu_ps, _mm256_movemask_ps};
    let p = m.as_ptr() as *const f32;
    // SAFETY: `m` is 16 u32 (64 bytes): the two unaligned 32-byte loads read inside it.
    let (lo, hi) = unsafe { (_mm256_loadu_ps(p), _mm256_loadu_ps(p.add(8))) };
    (_mm256_movemask_ps(lo) as u32 | (_mm256_movemask_ps(hi) as u32) << 8) as u16
}

/// The lanes `i` where `(base[0] + steps[0][i]) | (base[1] + steps[1][i]) | (base[2] +
/// steps[2][i])` is not negative (bit `i`): the pixels or sub-blocks of a 4×4 block inside
/// all three edges of a triangle, in 32-bit lanes whose sums the caller knows do not
/// overflow (`raster::blocks`). Written out per level: LLVM left the plain loop as 48
/// scalar adds and ORs with the lanes inserted one by one into vectors for the movemask
/// (the walk of a small triangle's blocks). The adds wrap as the scalar ones do in release
/// builds; without overflow every level gives the exact sums, so the same mask.
#[inline(always)]
pub fn inside_mask16(level: Supported, base: [i32; 3], steps: &[[i32; 16]; 3]) -> u16 {
    #[cfg(target_arch = "x86_64")]
    {
        if level.0 == Level::Avx2 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2.
            return unsafe { inside_mask16_avx2(base, steps) };
        }
        inside_mask16_sse2(base, steps)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        let mut bits = 0u16;
        for i in 0..16 {
            let v = base[0].wrapping_add(steps[0][i])
                | base[1].wrapping_add(steps[1][i])
                | base[2].wrapping_add(steps[2][i]);
            bits |= ((v >= 0) as u16) << i;
        }
        bits
    }
}

#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn inside_mask16_sse2(base: [i32; 3], steps: &[[i32; 16]; 3]) -> u16 {
    use std::arch::x86_64::{
        __m128i, _mm_add_epi32, _mm_loadu_si128, _mm_movemask_epi8, _mm_or_si128, _mm_packs_epi16, _mm_packs_epi32,
        _mm_set1_epi32,
    };
    let p = [0, 1, 2].map(|k| steps[k].as_ptr() as *const __m128i);
    // SAFETY: each row of `steps` is 16 i32 (64 bytes): the unaligned 16-byte loads at
    // quarters 0..4 read inside it; SSE2 is the x86-64 baseline.
    unsafe {
        let b = [_mm_set1_epi32(base[0]), _mm_set1_epi32(base[1]), _mm_set1_epi32(base[2])];
        let quarter = |q: usize| {
            let e0 = _mm_add_epi32(b[0], _mm_loadu_si128(p[0].add(q)));
            let e1 = _mm_add_epi32(b[1], _mm_loadu_si128(p[1].add(q)));
            let e2 = _mm_add_epi32(b[2], _mm_loadu_si128(p[2].add(q)));
            _mm_or_si128(_mm_or_si128(e0, e1), e2)
        };
        // Signed packs keep each lane's sign; the byte movemask gathers them.
        let lo = _mm_packs_epi32(quarter(0), quarter(1));
        let hi = _mm_packs_epi32(quarter(2), quarter(3));
        !(_mm_movemask_epi8(_mm_packs_epi16(lo, hi)) as u16)
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn inside_mask16_avx2(base: [i32; 3], steps: &[[i32; 16]; 3]) -> u16 {
    use std::arch::x86_64::{
        __m256i, _mm256_add_epi32, _mm256_castsi256_ps, _mm256_loadu_si256, _mm256_movemask_ps, _mm256_or_si256,
        _mm256_set1_epi32,
    };
    let b = [_mm256_set1_epi32(base[0]), _mm256_set1_epi32(base[1]), _mm256_set1_epi32(base[2])];
    let p = [0, 1, 2].map(|k| steps[k].as_ptr() as *const __m256i);
    let mut bits = 0u32;
    for h in 0..2 {
        // SAFETY: each row of `steps` is 16 i32 (64 bytes): the unaligned 32-byte loads at
        // halves 0 and 1 read inside it.
        let (s0, s1, s2) = unsafe {
            (_mm256_loadu_si256(p[0].add(h)), _mm256_loadu_si256(p[1].add(h)), _mm256_loadu_si256(p[2].add(h)))
        };
        let v = _mm256_or_si256(
            _mm256_or_si256(_mm256_add_epi32(b[0], s0), _mm256_add_epi32(b[1], s1)),
            _mm256_add_epi32(b[2], s2),
        );
        bits |= (_mm256_movemask_ps(_mm256_castsi256_ps(v)) as u32) << (8 * h);
    }
    !(bits as u16)
}

/// The steps `a·column + b·row` over a 4×4 block's 16 lanes (lane `4·row + column`), in
/// 32-bit lanes whose values the caller knows do not overflow (`raster::blocks`, an edge's
/// steps from a block's corner): the first row `0, a, 2a, 3a` in a vector, each next row it
/// plus `b`. Written as a plain loop of products, LLVM built the lanes one scalar at a time
/// (about 30 instructions an edge, for each small triangle of a run). The adds wrap as the
/// scalar ones do in release builds; without overflow every level gives the exact values.
#[inline(always)]
pub fn edge_steps16(level: Supported, a: i32, b: i32) -> [i32; 16] {
    #[cfg(target_arch = "x86_64")]
    {
        if level.0 == Level::Avx2 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2.
            return unsafe { edge_steps16_avx2(a, b) };
        }
        edge_steps16_sse2(a, b)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        let mut out = [0i32; 16];
        for (i, o) in out.iter_mut().enumerate() {
            *o = a.wrapping_mul((i & 3) as i32).wrapping_add(b.wrapping_mul((i >> 2) as i32));
        }
        out
    }
}

#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn edge_steps16_sse2(a: i32, b: i32) -> [i32; 16] {
    use std::arch::x86_64::{__m128i, _mm_add_epi32, _mm_set1_epi32, _mm_setr_epi32};
    // SAFETY: register operations of SSE2, the x86-64 baseline; four 16-byte vectors are the
    // 64 bytes of 16 i32.
    unsafe {
        let row0 = _mm_setr_epi32(0, a, a.wrapping_add(a), a.wrapping_mul(3));
        let step = _mm_set1_epi32(b);
        let row1 = _mm_add_epi32(row0, step);
        let row2 = _mm_add_epi32(row1, step);
        let row3 = _mm_add_epi32(row2, step);
        std::mem::transmute::<[__m128i; 4], [i32; 16]>([row0, row1, row2, row3])
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn edge_steps16_avx2(a: i32, b: i32) -> [i32; 16] {
    use std::arch::x86_64::{
        __m256i, _mm256_add_epi32, _mm256_broadcastsi128_si256, _mm256_set1_epi32, _mm256_setr_epi32, _mm_setr_epi32,
    };
    // Rows 0 and 1, then rows 2 and 3 (two rows' `b` more).
    let row0 = _mm256_broadcastsi128_si256(_mm_setr_epi32(0, a, a.wrapping_add(a), a.wrapping_mul(3)));
    let low = _mm256_add_epi32(row0, _mm256_setr_epi32(0, 0, 0, 0, b, b, b, b));
    let high = _mm256_add_epi32(low, _mm256_set1_epi32(b.wrapping_add(b)));
    // SAFETY: two 32-byte vectors are the 64 bytes of 16 i32.
    unsafe { std::mem::transmute::<[__m256i; 2], [i32; 16]>([low, high]) }
}

/// Pixel types of 32 bits with no padding and every bit pattern valid, which the row
/// helpers move as plain 32-bit words.
pub trait Word32: Copy + sealed::Sealed {}
impl Word32 for u32 {}
impl Word32 for [u8; 4] {}
mod sealed {
    pub trait Sealed {}
    impl Sealed for u32 {}
    impl Sealed for [u8; 4] {}
}

/// Whether the four rows of 4 pixels from `base`, `width` apart, lie inside a slice of `len`
/// pixels. (`base`, `width` < `len` keep `base + 3·width + 4` from overflowing: a slice has
/// fewer than 2⁶¹ elements of 4 bytes, or 2⁶² of 2.)
#[inline(always)]
fn block_inside(len: usize, base: usize, width: usize) -> bool {
    base < len && width < len && base + 3 * width + 4 <= len
}

/// The 16 pixels of the 4×4 block whose row `r` is `px[base + r·width..][..4]` (lane `4·r + c`
/// is pixel `c` of row `r`), bounds-checked once and joined in registers: at AVX2 two rows
/// per 256-bit vector (a load and an insert), at SSE2 and SSE4.1 one 128-bit load per row.
/// Panics if a row lies outside `px`.
#[inline(always)]
pub fn load_block<T: Word32>(level: Supported, px: &[T], base: usize, width: usize) -> [T; 16] {
    assert!(block_inside(px.len(), base, width), "a block's rows lie inside its slice");
    #[cfg(target_arch = "x86_64")]
    {
        let p = px[base..].as_ptr();
        if level.0 == Level::Avx2 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2;
            // the four rows lie inside `px` (checked above).
            return unsafe { load_block_avx2(p, width) };
        }
        use std::arch::x86_64::{__m128i, _mm_loadu_si128};
        // SAFETY: rows `r` (0..4) are the 16 bytes at `p + r·width` pixels, inside `px`
        // (checked above), of 32-bit words (`Word32`: no padding, every bit pattern valid);
        // SSE2 is the baseline.
        let row = |r: usize| unsafe { _mm_loadu_si128(p.add(r * width) as *const __m128i) };
        let v = [row(0), row(1), row(2), row(3)];
        // SAFETY: four 16-byte vectors are the 64 bytes of 16 words of 32 bits (`Word32`).
        unsafe { std::mem::transmute_copy::<[__m128i; 4], [T; 16]>(&v) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        let mut lanes = [px[base]; 16];
        for (i, l) in lanes.iter_mut().enumerate() {
            *l = px[base + (i >> 2) * width + (i & 3)];
        }
        lanes
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn load_block_avx2<T: Word32>(p: *const T, width: usize) -> [T; 16] {
    use std::arch::x86_64::{__m128i, __m256i, _mm256_castsi128_si256, _mm256_inserti128_si256, _mm_loadu_si128};
    // SAFETY: the caller checked that the rows (16 bytes at `p + r·width` pixels) are
    // readable, 32-bit words (`Word32`).
    let row = |r: usize| unsafe { _mm_loadu_si128(p.add(r * width) as *const __m128i) };
    let lo = _mm256_inserti128_si256::<1>(_mm256_castsi128_si256(row(0)), row(1));
    let hi = _mm256_inserti128_si256::<1>(_mm256_castsi128_si256(row(2)), row(3));
    // SAFETY: two 32-byte vectors are the 64 bytes of 16 words of 32 bits (`Word32`).
    unsafe { std::mem::transmute_copy::<[__m256i; 2], [T; 16]>(&[lo, hi]) }
}

/// Stores the 16 lanes of a 4×4 block into its rows ([`load_block`]'s inverse), split from
/// registers. Panics if a row lies outside `px`.
#[inline(always)]
pub fn store_block<T: Word32>(level: Supported, px: &mut [T], base: usize, width: usize, values: &[T; 16]) {
    assert!(block_inside(px.len(), base, width), "a block's rows lie inside its slice");
    #[cfg(target_arch = "x86_64")]
    {
        let p = px[base..].as_mut_ptr();
        if level.0 == Level::Avx2 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2;
            // the four rows lie inside `px` (checked above).
            return unsafe { store_block_avx2(p, width, values) };
        }
        use std::arch::x86_64::{__m128i, _mm_loadu_si128, _mm_storeu_si128};
        let v = values.as_ptr() as *const __m128i;
        for r in 0..4 {
            // SAFETY: `values` is 64 bytes, read as four 16-byte vectors; row `r` is the 16
            // bytes at `p + r·width` pixels, inside `px` (checked above), of 32-bit words
            // (`Word32`), written whole; SSE2 is the baseline.
            unsafe { _mm_storeu_si128(p.add(r * width) as *mut __m128i, _mm_loadu_si128(v.add(r))) }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        for (i, v) in values.iter().enumerate() {
            px[base + (i >> 2) * width + (i & 3)] = *v;
        }
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn store_block_avx2<T: Word32>(p: *mut T, width: usize, values: &[T; 16]) {
    use std::arch::x86_64::{
        __m128i, __m256i, _mm256_castsi256_si128, _mm256_extracti128_si256, _mm256_loadu_si256, _mm_storeu_si128,
    };
    let v = values.as_ptr() as *const __m256i;
    // SAFETY: `values` is 64 bytes, read as two 32-byte vectors.
    let (lo, hi) = unsafe { (_mm256_loadu_si256(v), _mm256_loadu_si256(v.add(1))) };
    let halves = [
        _mm256_castsi256_si128(lo),
        _mm256_extracti128_si256::<1>(lo),
        _mm256_castsi256_si128(hi),
        _mm256_extracti128_si256::<1>(hi),
    ];
    for (r, half) in halves.into_iter().enumerate() {
        // SAFETY: the caller checked that row `r` (16 bytes at `p + r·width` pixels, 32-bit
        // words) lies inside its slice; written whole.
        unsafe { _mm_storeu_si128(p.add(r * width) as *mut __m128i, half) }
    }
}

/// Each lane rounded to the nearest integer, ties to even, as an i32 (lanes of magnitude below
/// 2³¹): `cvtps2dq`, which rounds by the MXCSR mode, and Rust requires the default environment
/// (round to nearest even), so every level gives the same integers. Plain Rust has no
/// round-to-nearest conversion (`as` truncates; `round_ties_even` is a libm call at SSE2).
#[inline(always)]
pub fn round_even_i32(level: Supported, x: &[f32; 16]) -> [i32; 16] {
    #[cfg(target_arch = "x86_64")]
    {
        if level.0 == Level::Avx2 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2.
            return unsafe { round_even_i32_avx2(x) };
        }
        use std::arch::x86_64::{__m128i, _mm_cvtps_epi32, _mm_loadu_ps};
        let p = x.as_ptr();
        // SAFETY: `x` is 64 bytes, read as four 16-byte vectors; SSE2 is the baseline.
        let row = |k: usize| unsafe { _mm_cvtps_epi32(_mm_loadu_ps(p.add(4 * k))) };
        let v = [row(0), row(1), row(2), row(3)];
        // SAFETY: four 16-byte vectors are the 64 bytes of 16 i32.
        unsafe { std::mem::transmute::<[__m128i; 4], [i32; 16]>(v) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        let mut out = [0i32; 16];
        for (o, &v) in out.iter_mut().zip(x) {
            *o = v.round_ties_even() as i32;
        }
        out
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn round_even_i32_avx2(x: &[f32; 16]) -> [i32; 16] {
    use std::arch::x86_64::{__m256i, _mm256_cvtps_epi32, _mm256_loadu_ps};
    let p = x.as_ptr();
    // SAFETY: `x` is 64 bytes, read as two 32-byte vectors.
    let (lo, hi) = unsafe { (_mm256_loadu_ps(p), _mm256_loadu_ps(p.add(8))) };
    // SAFETY: two 32-byte vectors are the 64 bytes of 16 i32.
    unsafe { std::mem::transmute::<[__m256i; 2], [i32; 16]>([_mm256_cvtps_epi32(lo), _mm256_cvtps_epi32(hi)]) }
}

/// `mul8(x, y) = t + (t >> 8) >> 8` with `t = x·y + 128` (`x·y/255` rounded to nearest,
/// exact for bytes) on 16-bit lanes holding bytes: the product and `t` fit in 16 bits
/// (`255·255 + 128 < 2¹⁶`), and `(t + (t >> 8)) >> 8` is the high half of `t·257` (with
/// `t = 256q + r`, `t·257/2¹⁶ = q + (r + q + r/256)/256`, and `r + q + r/256` reaches the
/// next multiple of 256 only where `r + q` does, `r < 256`): `pmullw`, `paddw`, `pmulhuw`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn mul8_epi16(x: std::arch::x86_64::__m128i, y: std::arch::x86_64::__m128i) -> std::arch::x86_64::__m128i {
    use std::arch::x86_64::{_mm_add_epi16, _mm_mulhi_epu16, _mm_mullo_epi16, _mm_set1_epi16};
    // SAFETY: register operations of SSE2, the x86-64 baseline.
    unsafe { _mm_mulhi_epu16(_mm_add_epi16(_mm_mullo_epi16(x, y), _mm_set1_epi16(128)), _mm_set1_epi16(257)) }
}

/// [`mul8_epi16`] on 256-bit vectors.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn mul8_epi16_avx2(x: std::arch::x86_64::__m256i, y: std::arch::x86_64::__m256i) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::{_mm256_add_epi16, _mm256_mulhi_epu16, _mm256_mullo_epi16, _mm256_set1_epi16};
    _mm256_mulhi_epu16(_mm256_add_epi16(_mm256_mullo_epi16(x, y), _mm256_set1_epi16(128)), _mm256_set1_epi16(257))
}

/// unorm8 RGBA words (byte `k`: channel `k`) blended by `GL_FUNC_ADD` with destination
/// factor `GL_ONE_MINUS_SRC_ALPHA` on every channel and source factor `GL_SRC_ALPHA`
/// (`SRC_ALPHA`) or `GL_ONE`: `min(mul8(s, f) + mul8(d, 255 − a), 255)` per byte, `a` the
/// source alpha, `f` it or 255 (`mul8(s, 255) = s`), the integer blend of
/// `fragment::blend::blend_unorm8` byte for byte. On 16-bit lanes, a row of four pixels per
/// 128-bit vector (two per 256-bit one at AVX2): bytes widened by unpacking, each pixel's
/// alpha spread over its channels by two word shuffles, [`mul8_epi16`], and the bytes packed
/// back with unsigned saturation (the clamp; with `GL_SRC_ALPHA` the sum is at most
/// `mul8(255, a) + mul8(255, 255 − a) = 255`). Integer arithmetic: the same words at every
/// level.
#[inline(always)]
pub fn blend_inv_src_alpha8<const SRC_ALPHA: bool>(level: Supported, src: &[u32; 16], dst: &[u32; 16]) -> [u32; 16] {
    #[cfg(target_arch = "x86_64")]
    {
        if level.0 == Level::Avx2 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2.
            return unsafe { blend_inv_src_alpha8_avx2::<SRC_ALPHA>(src, dst) };
        }
        use std::arch::x86_64::{
            __m128i, _mm_add_epi16, _mm_loadu_si128, _mm_packus_epi16, _mm_set1_epi16, _mm_setzero_si128,
            _mm_shufflehi_epi16, _mm_shufflelo_epi16, _mm_unpackhi_epi8, _mm_unpacklo_epi8, _mm_xor_si128,
        };
        let (s, d) = (src.as_ptr() as *const __m128i, dst.as_ptr() as *const __m128i);
        // Two pixels' channels as 16-bit lanes: each alpha (lanes 3 and 7) spread over its pixel.
        // SAFETY (the register operations here): SSE2 is the x86-64 baseline.
        let half = |s: __m128i, d: __m128i| unsafe {
            let a = _mm_shufflehi_epi16::<0xff>(_mm_shufflelo_epi16::<0xff>(s));
            let ia = _mm_xor_si128(a, _mm_set1_epi16(0xff));
            let sf = if SRC_ALPHA { mul8_epi16(s, a) } else { s };
            _mm_add_epi16(sf, mul8_epi16(d, ia))
        };
        // SAFETY: `src` and `dst` are 64 bytes each, read as four 16-byte vectors; SSE2 is
        // the baseline.
        let row = |r: usize| unsafe {
            let (s, d) = (_mm_loadu_si128(s.add(r)), _mm_loadu_si128(d.add(r)));
            let zero = _mm_setzero_si128();
            let lo = half(_mm_unpacklo_epi8(s, zero), _mm_unpacklo_epi8(d, zero));
            let hi = half(_mm_unpackhi_epi8(s, zero), _mm_unpackhi_epi8(d, zero));
            _mm_packus_epi16(lo, hi)
        };
        let v = [row(0), row(1), row(2), row(3)];
        // SAFETY: four 16-byte vectors are the 64 bytes of 16 u32.
        unsafe { std::mem::transmute::<[__m128i; 4], [u32; 16]>(v) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        let mul8 = |x: u32, y: u32| {
            let t = x * y + 128;
            (t + (t >> 8)) >> 8
        };
        let mut out = [0u32; 16];
        for (o, (&s, &d)) in out.iter_mut().zip(src.iter().zip(dst)) {
            let a = s >> 24;
            for k in 0..4 {
                let (sc, dc) = ((s >> (8 * k)) & 0xff, (d >> (8 * k)) & 0xff);
                let sf = if SRC_ALPHA { mul8(sc, a) } else { sc };
                *o |= (sf + mul8(dc, 255 - a)).min(255) << (8 * k);
            }
        }
        out
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn blend_inv_src_alpha8_avx2<const SRC_ALPHA: bool>(src: &[u32; 16], dst: &[u32; 16]) -> [u32; 16] {
    use std::arch::x86_64::{
        __m256i, _mm256_add_epi16, _mm256_loadu_si256, _mm256_packus_epi16, _mm256_set1_epi16, _mm256_setzero_si256,
        _mm256_shufflehi_epi16, _mm256_shufflelo_epi16, _mm256_unpackhi_epi8, _mm256_unpacklo_epi8, _mm256_xor_si256,
    };
    let (s, d) = (src.as_ptr() as *const __m256i, dst.as_ptr() as *const __m256i);
    // Unpacking and packing both work within 128-bit halves: each half is
    // `blend_inv_src_alpha8`'s SSE2 row.
    let half = |s: __m256i, d: __m256i| {
        let a = _mm256_shufflehi_epi16::<0xff>(_mm256_shufflelo_epi16::<0xff>(s));
        let ia = _mm256_xor_si256(a, _mm256_set1_epi16(0xff));
        let sf = if SRC_ALPHA { mul8_epi16_avx2(s, a) } else { s };
        _mm256_add_epi16(sf, mul8_epi16_avx2(d, ia))
    };
    let rows = |r: usize| {
        // SAFETY: `src` and `dst` are 64 bytes each, read as two 32-byte vectors.
        let (s, d) = unsafe { (_mm256_loadu_si256(s.add(r)), _mm256_loadu_si256(d.add(r))) };
        let zero = _mm256_setzero_si256();
        let lo = half(_mm256_unpacklo_epi8(s, zero), _mm256_unpacklo_epi8(d, zero));
        let hi = half(_mm256_unpackhi_epi8(s, zero), _mm256_unpackhi_epi8(d, zero));
        _mm256_packus_epi16(lo, hi)
    };
    // SAFETY: two 32-byte vectors are the 64 bytes of 16 u32.
    unsafe { std::mem::transmute::<[__m256i; 2], [u32; 16]>([rows(0), rows(1)]) }
}

/// `min(a + b, 255)` on every byte of 16 words (GL_ONE, GL_ONE blending of unorm8 words):
/// one unsigned saturating byte add (`paddusb`) per vector.
#[inline(always)]
pub fn add_saturate8(level: Supported, a: &[u32; 16], b: &[u32; 16]) -> [u32; 16] {
    #[cfg(target_arch = "x86_64")]
    {
        if level.0 == Level::Avx2 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2.
            return unsafe { add_saturate8_avx2(a, b) };
        }
        use std::arch::x86_64::{__m128i, _mm_adds_epu8, _mm_loadu_si128};
        let (pa, pb) = (a.as_ptr() as *const __m128i, b.as_ptr() as *const __m128i);
        // SAFETY: `a` and `b` are 64 bytes each, read as four 16-byte vectors; SSE2 is the
        // baseline.
        let row = |r: usize| unsafe { _mm_adds_epu8(_mm_loadu_si128(pa.add(r)), _mm_loadu_si128(pb.add(r))) };
        let v = [row(0), row(1), row(2), row(3)];
        // SAFETY: four 16-byte vectors are the 64 bytes of 16 u32.
        unsafe { std::mem::transmute::<[__m128i; 4], [u32; 16]>(v) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        let mut out = [0u32; 16];
        for (o, (&x, &y)) in out.iter_mut().zip(a.iter().zip(b)) {
            *o = u32::from_le_bytes(std::array::from_fn(|k| x.to_le_bytes()[k].saturating_add(y.to_le_bytes()[k])));
        }
        out
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn add_saturate8_avx2(a: &[u32; 16], b: &[u32; 16]) -> [u32; 16] {
    use std::arch::x86_64::{__m256i, _mm256_adds_epu8, _mm256_loadu_si256};
    let (pa, pb) = (a.as_ptr() as *const __m256i, b.as_ptr() as *const __m256i);
    // SAFETY: `a` and `b` are 64 bytes each, read as two 32-byte vectors.
    let row = |r: usize| unsafe { _mm256_adds_epu8(_mm256_loadu_si256(pa.add(r)), _mm256_loadu_si256(pb.add(r))) };
    // SAFETY: two 32-byte vectors are the 64 bytes of 16 u32.
    unsafe { std::mem::transmute::<[__m256i; 2], [u32; 16]>([row(0), row(1)]) }
}

/// Four channel lanes of integers packed into RGBA words (byte `k`: channel `k`), each
/// channel clamped to [0, 255] on the way (unsigned saturation: negative values, and the
/// `i32::MIN` a conversion gives NaN, become 0): a unorm8 conversion's last step. Per row of
/// four pixels, two signed packs to 16 bits (red with green, blue with alpha) and one
/// unsigned pack to bytes give the row in channel order (`r0..3 g0..3 b0..3 a0..3`); SSE4.1
/// and AVX2 transpose that to pixels with one byte shuffle (four shuffles a row), SSE2 with
/// four unpacks (seven). Shuffles share one or two ports, and the blends after this use
/// them too: shifting each channel into place and OR-ing them takes no shuffle but a clamp
/// per channel more. AVX2 does two rows per 256-bit vector (packs and shuffles work within
/// 128-bit halves). Integer operations: the same words at every level.
#[inline(always)]
pub fn pack_unorm8(level: Supported, c: &[[i32; 16]; 4]) -> [u32; 16] {
    #[cfg(target_arch = "x86_64")]
    {
        match level.0 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2.
            Level::Avx2 => return unsafe { pack_unorm8_avx2(c) },
            // SAFETY: as above: SSE4.1, which implies SSSE3.
            Level::Sse41 => return unsafe { pack_unorm8_ssse3(c) },
            _ => {}
        }
        use std::arch::x86_64::{
            __m128i, _mm_loadu_si128, _mm_packs_epi32, _mm_packus_epi16, _mm_srli_si128, _mm_unpacklo_epi16,
            _mm_unpacklo_epi8,
        };
        let p = c.each_ref().map(|k| k.as_ptr() as *const __m128i);
        // SAFETY: each channel is 64 bytes, read as four 16-byte vectors; SSE2 is the baseline.
        let row = |r: usize| unsafe {
            let ch = |k: usize| _mm_loadu_si128(p[k].add(r));
            // `r0..3 b0..3 g0..3 a0..3`, then `r g r g … b a b a …`, then `r g b a …`.
            let x = _mm_packus_epi16(_mm_packs_epi32(ch(0), ch(2)), _mm_packs_epi32(ch(1), ch(3)));
            let t = _mm_unpacklo_epi8(x, _mm_srli_si128::<8>(x));
            _mm_unpacklo_epi16(t, _mm_srli_si128::<8>(t))
        };
        let v = [row(0), row(1), row(2), row(3)];
        // SAFETY: four 16-byte vectors are the 64 bytes of 16 u32.
        unsafe { std::mem::transmute::<[__m128i; 4], [u32; 16]>(v) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = level;
        let mut out = [0u32; 16];
        for (i, o) in out.iter_mut().enumerate() {
            *o = (0..4).fold(0, |w, k| w | (c[k][i].clamp(0, 255) as u32) << (8 * k));
        }
        out
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "ssse3")]
#[inline]
unsafe fn pack_unorm8_ssse3(c: &[[i32; 16]; 4]) -> [u32; 16] {
    use std::arch::x86_64::{__m128i, _mm_loadu_si128, _mm_packs_epi32, _mm_packus_epi16, _mm_shuffle_epi8};
    let p = c.each_ref().map(|k| k.as_ptr() as *const __m128i);
    // SAFETY: 16 bytes read from a 16-byte array.
    let transpose = unsafe { _mm_loadu_si128(TRANSPOSE4X4.as_ptr() as *const __m128i) };
    let row = |r: usize| {
        // SAFETY: each channel is 64 bytes, read as four 16-byte vectors.
        let ch = |k: usize| unsafe { _mm_loadu_si128(p[k].add(r)) };
        let x = _mm_packus_epi16(_mm_packs_epi32(ch(0), ch(1)), _mm_packs_epi32(ch(2), ch(3)));
        _mm_shuffle_epi8(x, transpose)
    };
    // SAFETY: four 16-byte vectors are the 64 bytes of 16 u32.
    unsafe { std::mem::transmute::<[__m128i; 4], [u32; 16]>([row(0), row(1), row(2), row(3)]) }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn pack_unorm8_avx2(c: &[[i32; 16]; 4]) -> [u32; 16] {
    use std::arch::x86_64::{
        __m128i, __m256i, _mm256_broadcastsi128_si256, _mm256_loadu_si256, _mm256_packs_epi32, _mm256_packus_epi16,
        _mm256_shuffle_epi8, _mm_loadu_si128,
    };
    let p = c.each_ref().map(|k| k.as_ptr() as *const __m256i);
    // SAFETY: 16 bytes read from a 16-byte array.
    let transpose = _mm256_broadcastsi128_si256(unsafe { _mm_loadu_si128(TRANSPOSE4X4.as_ptr() as *const __m128i) });
    let rows = |r: usize| {
        // SAFETY: each channel is 64 bytes, read as two 32-byte vectors.
        let ch = |k: usize| unsafe { _mm256_loadu_si256(p[k].add(r)) };
        let x = _mm256_packus_epi16(_mm256_packs_epi32(ch(0), ch(1)), _mm256_packs_epi32(ch(2), ch(3)));
        _mm256_shuffle_epi8(x, transpose)
    };
    // SAFETY: two 32-byte vectors are the 64 bytes of 16 u32.
    unsafe { std::mem::transmute::<[__m256i; 2], [u32; 16]>([rows(0), rows(1)]) }
}

/// [`blend_inv_src_alpha8`] of source colours given as four channel lanes of integers
/// (unorm8 values before packing: each at most 255; negative values, and the `i32::MIN` a
/// conversion gives NaN, count as 0), as `blend_inv_src_alpha8(pack_unorm8(c), dst)` gives
/// byte for byte. At SSE4.1 and AVX2 the blend runs on the channels as they come, a row of
/// four pixels as two vectors of 16-bit lanes (red with green, blue with alpha: two signed
/// packs), with the destination row transposed to that order (one byte shuffle) and the
/// result transposed back (another): eight shuffles a row, where packing the source into
/// words and blending them pixel by pixel takes sixteen (seven to pack; two unpacks per
/// operand, four alpha spreads and a pack to blend), and shuffles are the blend's
/// bottleneck (they share one or two ports; the multiplies and adds have more). SSE2,
/// without the byte shuffle, packs and blends the words.
#[inline(always)]
pub fn blend_channels_inv_src_alpha8<const SRC_ALPHA: bool>(
    level: Supported,
    c: &[[i32; 16]; 4],
    dst: &[u32; 16],
) -> [u32; 16] {
    #[cfg(target_arch = "x86_64")]
    {
        match level.0 {
            // SAFETY: a `Supported` holds only a level the CPU was detected to have: AVX2.
            Level::Avx2 => return unsafe { blend_channels_inv_src_alpha8_avx2::<SRC_ALPHA>(c, dst) },
            // SAFETY: as above: SSE4.1, which implies SSSE3.
            Level::Sse41 => return unsafe { blend_channels_inv_src_alpha8_ssse3::<SRC_ALPHA>(c, dst) },
            _ => {}
        }
    }
    blend_inv_src_alpha8::<SRC_ALPHA>(level, &pack_unorm8(level, c), dst)
}

/// The byte shuffle that transposes a row of four RGBA pixels (`r0 g0 b0 a0 r1 …`) to
/// channel order (`r0 r1 r2 r3 g0 …`) and back: a 4×4 transpose is its own inverse.
#[cfg(target_arch = "x86_64")]
const TRANSPOSE4X4: [i8; 16] = [0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15];

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "ssse3")]
#[inline]
unsafe fn blend_channels_inv_src_alpha8_ssse3<const SRC_ALPHA: bool>(c: &[[i32; 16]; 4], dst: &[u32; 16]) -> [u32; 16] {
    use std::arch::x86_64::{
        __m128i, _mm_add_epi16, _mm_loadu_si128, _mm_max_epi16, _mm_packs_epi32, _mm_packus_epi16, _mm_set1_epi16,
        _mm_setzero_si128, _mm_shuffle_epi8, _mm_unpackhi_epi64, _mm_unpackhi_epi8, _mm_unpacklo_epi8, _mm_xor_si128,
    };
    let p = c.each_ref().map(|k| k.as_ptr() as *const __m128i);
    let d = dst.as_ptr() as *const __m128i;
    // SAFETY: 16 bytes read from a 16-byte array.
    let transpose = unsafe { _mm_loadu_si128(TRANSPOSE4X4.as_ptr() as *const __m128i) };
    let zero = _mm_setzero_si128();
    let row = |r: usize| {
        // SAFETY: each channel is 64 bytes and `dst` 64 bytes, read as four 16-byte vectors.
        let (ch, dst) = unsafe { (|k: usize| _mm_loadu_si128(p[k].add(r)), _mm_loadu_si128(d.add(r))) };
        // Red and green, blue and alpha of the four pixels as 16-bit lanes in [0, 255].
        let rg = _mm_max_epi16(_mm_packs_epi32(ch(0), ch(1)), zero);
        let ba = _mm_max_epi16(_mm_packs_epi32(ch(2), ch(3)), zero);
        let a = _mm_unpackhi_epi64(ba, ba);
        let ia = _mm_xor_si128(a, _mm_set1_epi16(0xff));
        let dst = _mm_shuffle_epi8(dst, transpose);
        let blend = |s: __m128i, d: __m128i| {
            let sf = if SRC_ALPHA { mul8_epi16(s, a) } else { s };
            _mm_add_epi16(sf, mul8_epi16(d, ia))
        };
        let out = _mm_packus_epi16(blend(rg, _mm_unpacklo_epi8(dst, zero)), blend(ba, _mm_unpackhi_epi8(dst, zero)));
        _mm_shuffle_epi8(out, transpose)
    };
    // SAFETY: four 16-byte vectors are the 64 bytes of 16 u32.
    unsafe { std::mem::transmute::<[__m128i; 4], [u32; 16]>([row(0), row(1), row(2), row(3)]) }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn blend_channels_inv_src_alpha8_avx2<const SRC_ALPHA: bool>(c: &[[i32; 16]; 4], dst: &[u32; 16]) -> [u32; 16] {
    use std::arch::x86_64::{
        __m128i, __m256i, _mm256_add_epi16, _mm256_broadcastsi128_si256, _mm256_loadu_si256, _mm256_max_epi16,
        _mm256_packs_epi32, _mm256_packus_epi16, _mm256_set1_epi16, _mm256_setzero_si256, _mm256_shuffle_epi8,
        _mm256_unpackhi_epi64, _mm256_unpackhi_epi8, _mm256_unpacklo_epi8, _mm256_xor_si256, _mm_loadu_si128,
    };
    let p = c.each_ref().map(|k| k.as_ptr() as *const __m256i);
    let d = dst.as_ptr() as *const __m256i;
    // Packs, unpacks and byte shuffles work within 128-bit halves, and each half holds one
    // row of four pixels (channel lanes 0–3 and 4–7 of the 8): each half is the SSSE3 row.
    // SAFETY: 16 bytes read from a 16-byte array.
    let transpose = _mm256_broadcastsi128_si256(unsafe { _mm_loadu_si128(TRANSPOSE4X4.as_ptr() as *const __m128i) });
    let zero = _mm256_setzero_si256();
    let rows = |r: usize| {
        // SAFETY: each channel is 64 bytes and `dst` 64 bytes, read as two 32-byte vectors.
        let (ch, dst) = unsafe { (|k: usize| _mm256_loadu_si256(p[k].add(r)), _mm256_loadu_si256(d.add(r))) };
        let rg = _mm256_max_epi16(_mm256_packs_epi32(ch(0), ch(1)), zero);
        let ba = _mm256_max_epi16(_mm256_packs_epi32(ch(2), ch(3)), zero);
        let a = _mm256_unpackhi_epi64(ba, ba);
        let ia = _mm256_xor_si256(a, _mm256_set1_epi16(0xff));
        let dst = _mm256_shuffle_epi8(dst, transpose);
        let blend = |s: __m256i, d: __m256i| {
            let sf = if SRC_ALPHA { mul8_epi16_avx2(s, a) } else { s };
            _mm256_add_epi16(sf, mul8_epi16_avx2(d, ia))
        };
        let out =
            _mm256_packus_epi16(blend(rg, _mm256_unpacklo_epi8(dst, zero)), blend(ba, _mm256_unpackhi_epi8(dst, zero)));
        _mm256_shuffle_epi8(out, transpose)
    };
    // SAFETY: two 32-byte vectors are the 64 bytes of 16 u32.
    unsafe { std::mem::transmute::<[__m256i; 2], [u32; 16]>([rows(0), rows(1)]) }
}
