//! The stencil and depth tests of a block as one lane kernel per depth/stencil storage
//! format, chosen once per draw state ([`DepthStencilKernel`]), and the comparison helpers
//! the alpha, stencil and depth tests share.
//!
//! - Comparisons (alpha, depth, stencil) are GL's three-bit encoding: bit 0 passes when the
//!   fragment is less, bit 1 when equal, bit 2 when greater (`GL_NEVER` 0 … `GL_ALWAYS` 7).
//! - Depth: every [`DepthBand`] format, stored values as u32 lanes, the fragment depth
//!   encoded as the span path's `DepthEncoding::encode_fragment` (bit for bit: a unit test
//!   runs both over the steps, edges and NaN); the stencil test, its operations (two-sided)
//!   and the depth write in GL's order (`super::super::stencil`).
//! - Inside the kernel the live lanes are lane masks (all-ones or zero words), converted
//!   from and to 16-bit masks once per block, so that every stage is a plain loop LLVM
//!   vectorises; the stencil operations are matched once per block and inlined, so that
//!   they run in the kernel's copy for the SIMD level (an out-of-line call would be SSE2
//!   code). The stored block is loaded once and stored back whole (4 row stores) with the
//!   loaded values in the lanes nothing changed, only when the draw can write depth or
//!   stencil. Packed 24/8 words keep the stencil as `w >> 24` on u32 lanes: one shift out
//!   and one shift back in, where u8 lanes would need pack and unpack shuffles.

use super::{lanes, load, map_lanes, store, BlockAt, BlockEntry, F32s, Grid, U32s, LANES};
use crate::fragment::stencil::{StencilFace, StencilOp};
use crate::fragment::FragmentState;
use crate::framebuffer::band::DepthBand;
use crate::framebuffer::format::DepthEncoding;
use crate::framebuffer::hiz::DepthReject;
use crate::framebuffer::DepthStencilFormat;
use crate::gl::CompareFunc;
use crate::simd::dispatch::sign_mask16;
use crate::simd::Supported;

/// GL's comparison bits of `func` (see the module).
pub fn compare_bits(func: CompareFunc) -> u8 {
    match func {
        CompareFunc::Never => 0,
        CompareFunc::Less => 1,
        CompareFunc::Equal => 2,
        CompareFunc::LessEqual => 3,
        CompareFunc::Greater => 4,
        CompareFunc::NotEqual => 5,
        CompareFunc::GreaterEqual => 6,
        CompareFunc::Always => 7,
    }
}

/// A condition as a lane mask word: all ones where it holds.
#[inline(always)]
fn all(c: bool) -> u32 {
    if c {
        !0
    } else {
        0
    }
}

/// The bits of a 16-bit lane mask as lane mask words: each lane's bit tested against a
/// constant (an AND and a compare per vector).
#[inline(always)]
pub fn expand_mask(bits: u16) -> U32s {
    if bits == 0xffff {
        // Most blocks are whole.
        return [!0; LANES];
    }
    let bits = u32::from(bits);
    lanes(|i| all(bits & BIT[i] == BIT[i]))
}

/// Each lane's bit (`1 << i`).
const BIT: U32s = {
    let mut b = [0u32; LANES];
    let mut i = 0;
    while i < LANES {
        b[i] = 1 << i;
        i += 1;
    }
    b
};

/// The lanes where `a func b` holds, as lane mask words: one plain comparison loop per
/// function (the function is the draw's: the branch goes the same way every block). `T`
/// is `i32` for values below 2³¹ (unorm depth up to 24 bits, float depth bits, stencil),
/// whose signed comparisons SSE2 has, `u32` for 32-bit unorm depth.
#[inline(always)]
pub fn compare_mask<T: Copy + PartialOrd>(func: u8, a: &[T; LANES], b: &[T; LANES]) -> U32s {
    match func {
        0 => [0; LANES],
        1 => lanes(|i| all(a[i] < b[i])),
        2 => lanes(|i| all(a[i] == b[i])),
        3 => lanes(|i| all(a[i] <= b[i])),
        4 => lanes(|i| all(a[i] > b[i])),
        5 => lanes(|i| all(a[i] != b[i])),
        6 => lanes(|i| all(a[i] >= b[i])),
        _ => [!0; LANES],
    }
}

/// `a & b` on lane masks.
#[inline(always)]
fn and(a: &U32s, b: &U32s) -> U32s {
    lanes(|i| a[i] & b[i])
}

/// `a & !b` on lane masks.
#[inline(always)]
fn and_not(a: &U32s, b: &U32s) -> U32s {
    lanes(|i| a[i] & !b[i])
}

/// `new` where `mask`, else `old`.
#[inline(always)]
fn select(mask: &U32s, new: &U32s, old: &U32s) -> U32s {
    lanes(|i| (new[i] & mask[i]) | (old[i] & !mask[i]))
}

// ---------------------------------------------------------------------------------------
// Stencil and depth.

/// The stencil operations' codes (0: KEEP, which changes nothing).
fn stencil_op_code(op: StencilOp) -> u8 {
    match op {
        StencilOp::Keep => 0,
        StencilOp::Zero => 1,
        StencilOp::Replace => 2,
        StencilOp::Incr => 3,
        StencilOp::Decr => 4,
        StencilOp::IncrWrap => 5,
        StencilOp::DecrWrap => 6,
        StencilOp::Invert => 7,
    }
}

/// Stencil operation `OP` on the lanes of `which` (lane masks), through the write mask.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // an index loop on purpose: see the comment inside
fn stencil_op_lanes<const OP: u8>(values: &mut U32s, reference: u32, which: &U32s, write_mask: u32) {
    // An index loop: a `zip` can stay a call in a large per-level copy.
    for i in 0..LANES {
        let (v, m) = (&mut values[i], which[i]);
        let new = match OP {
            1 => 0,
            2 => reference,
            3 => (*v + 1).min(255),
            4 => v.saturating_sub(1),
            5 => (*v + 1) & 255,
            6 => v.wrapping_sub(1) & 255,
            7 => !*v & 255,
            _ => *v,
        };
        let new = (*v & !write_mask) | (new & write_mask);
        *v = (new & m) | (*v & !m);
    }
}

/// Stencil operation `op` (a [`stencil_op_code`]) on the lanes of `which`: matched once
/// per block, each arm a vectorised loop compiled into the kernel's copy per SIMD level.
#[inline(always)]
fn stencil_op(op: u8, values: &mut U32s, reference: u32, which: &U32s, write_mask: u32) {
    match op {
        1 => stencil_op_lanes::<1>(values, reference, which, write_mask),
        2 => stencil_op_lanes::<2>(values, reference, which, write_mask),
        3 => stencil_op_lanes::<3>(values, reference, which, write_mask),
        4 => stencil_op_lanes::<4>(values, reference, which, write_mask),
        5 => stencil_op_lanes::<5>(values, reference, which, write_mask),
        6 => stencil_op_lanes::<6>(values, reference, which, write_mask),
        7 => stencil_op_lanes::<7>(values, reference, which, write_mask),
        _ => {}
    }
}

/// One face of the stencil state on lanes; an operation that changes nothing (KEEP, or an
/// empty write mask) is code 0.
#[derive(Clone, Copy)]
struct FaceKernel {
    func: u8,
    reference: u32,
    value_mask: u32,
    write_mask: u32,
    sfail: u8,
    zfail: u8,
    zpass: u8,
}

impl FaceKernel {
    fn new(face: &StencilFace) -> Self {
        let op = |op| if face.write_mask == 0 { 0 } else { stencil_op_code(op) };
        FaceKernel {
            func: compare_bits(face.func),
            reference: face.reference as u32,
            value_mask: face.value_mask as u32,
            write_mask: face.write_mask as u32,
            sfail: op(face.sfail),
            zfail: op(face.zfail),
            zpass: op(face.zpass),
        }
    }

    /// Whether any operation can change stored values.
    fn writes(&self) -> bool {
        self.sfail != 0 || self.zfail != 0 || self.zpass != 0
    }

    #[inline(always)]
    fn apply(&self, op: u8, values: &mut U32s, which: &U32s) {
        stencil_op(op, values, self.reference, which, self.write_mask)
    }
}

/// A stencil operation on packed 24/8 words (stencil in bits 24–31), through the write
/// mask, as `((w & and) + add) ^ xor`: every operation but the saturating INCR and DECR, the
/// wrapping ones only with the full write mask (the add's carry out of bit 31 is the wrap).
/// Applied to the lanes of a lane mask `m` as `((w & (and | !m)) + (add & m)) ^ (xor & m)`:
/// four vector operations on the words, with no shift of the stencil out and back.
#[derive(Clone, Copy, Debug, PartialEq)]
struct WordOp {
    and: u32,
    add: u32,
    xor: u32,
    /// Whether the operation can change a word (not KEEP): a flag tested per block, where
    /// comparing the three words with KEEP's cost seven instructions per operation.
    changes: bool,
}

impl WordOp {
    const KEEP: WordOp = WordOp { and: !0, add: 0, xor: 0, changes: false };

    fn of(op: StencilOp, reference: u8, write_mask: u8) -> Option<WordOp> {
        let wm = u32::from(write_mask) << 24;
        let full = write_mask == 0xff;
        let changing = WordOp { changes: true, ..WordOp::KEEP };
        Some(match op {
            _ if write_mask == 0 => WordOp::KEEP,
            StencilOp::Keep => WordOp::KEEP,
            StencilOp::Zero => WordOp { and: !wm, ..changing },
            StencilOp::Replace => WordOp { and: !wm, add: (u32::from(reference) << 24) & wm, ..changing },
            StencilOp::Invert => WordOp { xor: wm, ..changing },
            StencilOp::IncrWrap if full => WordOp { add: 1 << 24, ..changing },
            StencilOp::DecrWrap if full => WordOp { add: 0xff00_0000, ..changing },
            _ => return None,
        })
    }

    /// Applies the operation to the lanes of `which` (lane masks); KEEP skips the work.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // an index loop vectorises where a `zip` may stay a call
    fn apply(&self, words: &mut U32s, which: &U32s) {
        if !self.changes {
            return;
        }
        for i in 0..LANES {
            let m = which[i];
            words[i] = (words[i] & (self.and | !m)).wrapping_add(self.add & m) ^ (self.xor & m);
        }
    }
}

/// A stencil face whose three operations all have the packed-word form ([`WordOp`]).
#[derive(Clone, Copy)]
struct WordFace {
    func: u8,
    reference: u32,
    value_mask: u32,
    sfail: WordOp,
    zfail: WordOp,
    zpass: WordOp,
}

impl WordFace {
    /// No stencil test: every fragment passes it and nothing changes the stencil bits, so
    /// the depth test alone runs in the packed-word form (the depth write replacing the
    /// low 24 bits, with no shift of the stencil out and back in).
    const NONE: WordFace = WordFace {
        func: 7,
        reference: 0,
        value_mask: 0,
        sfail: WordOp::KEEP,
        zfail: WordOp::KEEP,
        zpass: WordOp::KEEP,
    };

    fn new(face: &StencilFace) -> Option<Self> {
        let op = |op| WordOp::of(op, face.reference, face.write_mask);
        Some(WordFace {
            func: compare_bits(face.func),
            reference: face.reference as u32,
            value_mask: face.value_mask as u32,
            sfail: op(face.sfail)?,
            zfail: op(face.zfail)?,
            zpass: op(face.zpass)?,
        })
    }
}

/// The compiled depth and stencil state.
pub struct DepthStencilParams {
    /// Comparison bits and depth write.
    depth: Option<(u8, bool)>,
    clamp: Option<[f32; 2]>,
    /// Front and back faces.
    stencil: Option<[FaceKernel; 2]>,
    /// Whether the stencil values can change (else they are not stored back).
    stencil_writes: bool,
    /// Front and back faces in the packed-word form, when both have it (packed 24/8 only;
    /// [`WordFace::NONE`] without the stencil test).
    word_faces: Option<[WordFace; 2]>,
}

type DepthStencilFn = fn(&DepthStencilParams, &mut DepthBand<'_>, &BlockAt, &F32s, u16, bool) -> u16;

/// The stencil and depth tests of a draw on one depth/stencil format.
pub struct DepthStencilKernel {
    run: DepthStencilFn,
    /// The same tests without storing anything (see [`DepthStencilKernel::test`]).
    test: DepthStencilFn,
    params: DepthStencilParams,
    /// Whether a fragment failing the stencil or depth test changes nothing stored
    /// (no stencil test, or KEEP on stencil and depth failure on both faces).
    failures_keep: bool,
}

const D16: u8 = 0;
const PACKED24: u8 = 1;
const D32: u8 = 2;
const F32: u8 = 3;

impl DepthStencilKernel {
    /// `None` when the draw has neither test (or the framebuffer no depth/stencil layer).
    pub fn new(fragment: &FragmentState, format: DepthStencilFormat) -> Option<Self> {
        let stencil = fragment.stencil.filter(|_| format.stencil_bits() > 0);
        if fragment.depth.is_none() && stencil.is_none() {
            return None;
        }
        let (run, test): (DepthStencilFn, DepthStencilFn) = match format {
            DepthStencilFormat::None => return None,
            DepthStencilFormat::Depth16 => (depth_stencil::<D16, true>, depth_stencil::<D16, false>),
            DepthStencilFormat::Packed24 { .. } => (depth_stencil::<PACKED24, true>, depth_stencil::<PACKED24, false>),
            DepthStencilFormat::Depth32 { .. } => (depth_stencil::<D32, true>, depth_stencil::<D32, false>),
            DepthStencilFormat::Float32 { .. } => (depth_stencil::<F32, true>, depth_stencil::<F32, false>),
        };
        let faces = stencil.map(|s| [FaceKernel::new(&s.front), FaceKernel::new(&s.back)]);
        let params = DepthStencilParams {
            depth: fragment.depth.map(|d| (compare_bits(d.func), d.write)),
            clamp: fragment.depth_clamp,
            stencil_writes: faces.is_some_and(|f| f[0].writes() || f[1].writes()),
            stencil: faces,
            word_faces: match (format, stencil) {
                (DepthStencilFormat::Packed24 { .. }, Some(s)) => {
                    WordFace::new(&s.front).zip(WordFace::new(&s.back)).map(|(f, b)| [f, b])
                }
                (DepthStencilFormat::Packed24 { .. }, None) => Some([WordFace::NONE; 2]),
                _ => None,
            },
        };
        let failures_keep = faces.is_none_or(|f| f.iter().all(|f| f.sfail == 0 && f.zfail == 0));
        Some(DepthStencilKernel { run, test, params, failures_keep })
    }

    /// Whether a block whose lanes all fail [`Self::test`] can be dropped before the alpha
    /// test (before its colours are computed): its fragments then change nothing whatever
    /// their alpha, since failing the stencil or depth test leaves everything as it was.
    pub fn culls_before_alpha(&self) -> bool {
        self.failures_keep
    }

    /// The depth test hierarchical z may reject whole regions for (`framebuffer::hiz`):
    /// GL_LESS or GL_LEQUAL, when a failing fragment changes nothing.
    pub fn hiz_reject(&self) -> Option<DepthReject> {
        match self.params.depth {
            Some((func @ (1 | 3), _)) if self.failures_keep => {
                Some(DepthReject { equal_passes: func == 3, clamp: self.params.clamp })
            }
            _ => None,
        }
    }

    /// The lanes of `live` that pass the stencil and depth tests, without storing anything
    /// (the early test of a draw with the alpha test, see [`Self::culls_before_alpha`]).
    #[inline]
    pub fn test(
        &self,
        band: &mut DepthBand<'_>,
        at: &BlockAt,
        live: u16,
        front_facing: bool,
        z: impl FnOnce() -> F32s,
    ) -> u16 {
        let lanes = self.depth_lanes(z);
        (self.test)(&self.params, band, at, &lanes, live, front_facing)
    }

    /// Runs the tests on the lanes of `live`; `z()` gives the fragments' window depth (read
    /// only when the depth test is on). Returns the lanes that pass.
    #[inline]
    pub fn run(
        &self,
        band: &mut DepthBand<'_>,
        at: &BlockAt,
        live: u16,
        front_facing: bool,
        z: impl FnOnce() -> F32s,
    ) -> u16 {
        let lanes = self.depth_lanes(z);
        (self.run)(&self.params, band, at, &lanes, live, front_facing)
    }

    /// The window depth of block `b` (`z_at(b)`), as
    /// [`Self::depth_lanes`].
    #[inline(always)]
    fn block_depth(&self, b: &BlockEntry, z_at: &impl Fn(&BlockEntry) -> F32s) -> F32s {
        self.depth_lanes(
            #[inline(always)]
            || z_at(b),
        )
    }

    /// The fragments' window depth, depth-clamped (zeros without the depth test).
    #[inline(always)]
    fn depth_lanes(&self, z: impl FnOnce() -> F32s) -> F32s {
        let mut lanes = [0f32; LANES];
        if self.params.depth.is_some() {
            lanes = z();
            if let Some([lo, hi]) = self.params.clamp {
                for z in &mut lanes {
                    *z = z.clamp(lo, hi);
                }
            }
        }
        lanes
    }
}

/// `DepthEncoding::encode_fragment` on lanes, branch-free: the clamp as selects (NaN and
/// −0 give 0), then for unorm the same single-precision product rounded to nearest even
/// through f64 (`format::round_half_even`), for float the clamped value's bits.
#[inline(always)]
fn encode_depth(level: Supported, encoding: DepthEncoding, z: &F32s) -> U32s {
    let clamped = lanes(|i| {
        let v = z[i];
        let v = if v > 0.0 { v } else { 0.0 };
        if v < 1.0 {
            v
        } else {
            1.0
        }
    });
    match encoding {
        DepthEncoding::Unorm(bits) if bits <= 24 => {
            // The product is at most 2²⁴ − 1: rounded to nearest even by one conversion
            // (`simd::dispatch::round_even_i32`), the f64 rounding's result (below 2²⁴ every
            // f32 is exact in f64, and its nearest integer is the same).
            let max = crate::framebuffer::format::unorm_max(bits) as f32;
            let p = lanes(|i| clamped[i] * max);
            map_lanes(&crate::simd::dispatch::round_even_i32(level, &p), |v| v as u32)
        }
        DepthEncoding::Unorm(bits) => {
            const MAGIC: f64 = (1u64 << 52) as f64;
            let max = crate::framebuffer::format::unorm_max(bits) as f32;
            lanes(|i| (((clamped[i] * max) as f64 + MAGIC) - MAGIC) as u32)
        }
        DepthEncoding::Float => map_lanes(&clamped, f32::to_bits),
    }
}

/// The stencil test, the depth test and the stencil operations in GL's order (see
/// [`crate::fragment::stencil_depth_test`]) on lane masks: `stencil` is updated in place,
/// the result is the passing lanes and the depth values to store (the stored ones where
/// nothing is written). `SIGNED`: the stored depth values are below 2³¹.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn tests<const SIGNED: bool>(
    level: Supported,
    p: &DepthStencilParams,
    face: Option<&FaceKernel>,
    encoding: DepthEncoding,
    z: &F32s,
    stored: &U32s,
    stencil: &mut U32s,
    live: &U32s,
) -> (U32s, U32s) {
    let mut passing = *live;
    if let Some(face) = face {
        let reference = [(face.reference & face.value_mask) as i32; LANES];
        let masked = map_lanes(stencil, |v| (v & face.value_mask) as i32);
        passing = and(&compare_mask(face.func, &reference, &masked), live);
        face.apply(face.sfail, stencil, &and_not(live, &passing));
    }
    let mut depth = *stored;
    if let Some((func, write)) = p.depth {
        let fragment = encode_depth(level, encoding, z);
        let pass = if SIGNED {
            let f = map_lanes(&fragment, |v| v as i32);
            let s = map_lanes(stored, |v| v as i32);
            compare_mask(func, &f, &s)
        } else {
            compare_mask(func, &fragment, stored)
        };
        let pass = and(&pass, &passing);
        if write {
            depth = select(&pass, &fragment, stored);
        }
        if let Some(face) = face {
            face.apply(face.zfail, stencil, &and_not(&passing, &pass));
        }
        passing = pass;
    }
    if let Some(face) = face {
        face.apply(face.zpass, stencil, &passing);
    }
    (passing, depth)
}

/// The stencil and depth tests on one format: the block's stored values loaded as lanes
/// once, [`tests`], and the block stored back whole (lanes that neither test changed
/// keep the values just loaded) only when the draw can change them and `STORE`. Called
/// through a function pointer, block by block: the alpha-test path (and the tests), whose
/// blocks pay for their colours and the alpha test before these tests. One copy, at the
/// baseline level: the AVX2 copies of the eight instances were 34 KB of each library
/// (issue #18's 5 MB limit), for a path no benchmark scene takes; the batched stage
/// ([`DepthStencilKernel::run_blocks`]) keeps its per-level copies.
fn depth_stencil<const FMT: u8, const STORE: bool>(
    p: &DepthStencilParams,
    band: &mut DepthBand<'_>,
    at: &BlockAt,
    z: &F32s,
    live: u16,
    front_facing: bool,
) -> u16 {
    crate::simd::dispatch::baseline(
        #[inline(always)]
        |level| {
            let at = BlockAt { level, ..*at };
            let face = p.stencil.as_ref().map(|f| &f[usize::from(!front_facing)]);
            match band {
                DepthBand::Depth16(px) if FMT == D16 => depth16::<STORE>(p, px, &at, z, live),
                DepthBand::Packed24(px) if FMT == PACKED24 => packed24::<STORE>(p, face, px, &at, z, live),
                DepthBand::Depth32(px, s) if FMT == D32 => depth32::<STORE, false>(p, face, px, s, &at, z, live),
                DepthBand::Float32(px, s) if FMT == F32 => depth32::<STORE, true>(p, face, px, s, &at, z, live),
                _ => live,
            }
        },
    )
}

impl DepthStencilKernel {
    /// Runs the tests on every block of `blocks` (`mask`: its covered lanes; `z(x, y)`: the
    /// window depth of the block at `(x, y)`), keeping in `blocks`, in order, those with a
    /// passing lane, their masks the passing lanes; returns how many. Without `survivors`
    /// (no colour target to write and no occlusion query: nothing reads the passing lanes)
    /// a kernel may skip that and return 0. The format and the stencil face are matched
    /// once for all of them; compiled into the caller's copy for `grid.level` (the block
    /// stage's batch call).
    #[inline(always)]
    pub fn run_blocks(
        &self,
        band: &mut DepthBand<'_>,
        grid: Grid,
        front_facing: bool,
        blocks: &mut [BlockEntry],
        survivors: bool,
        z_at: impl Fn(&BlockEntry) -> F32s,
    ) -> usize {
        let p = &self.params;
        let face = p.stencil.as_ref().map(|f| &f[usize::from(!front_facing)]);
        // Every closure here is inlined into the caller's copy for the level (one that
        // were not would be baseline code).
        match band {
            DepthBand::Depth16(px) => keep(
                blocks,
                #[inline(always)]
                |b| depth16::<true>(p, px, &grid.at(b.x, b.y), &self.block_depth(b, &z_at), b.mask),
            ),
            DepthBand::Packed24(px) => match &p.word_faces {
                Some(faces) => {
                    let face = &faces[usize::from(!front_facing)];
                    if !survivors {
                        // The stencil passes of shadow volumes: only the stored words count
                        // (no lane mask packed, no block kept).
                        for b in blocks.iter() {
                            packed24_words(p, face, px, &grid.at(b.x, b.y), &self.block_depth(b, &z_at), b.mask);
                        }
                        return 0;
                    }
                    keep(
                        blocks,
                        #[inline(always)]
                        |b| packed24_words(p, face, px, &grid.at(b.x, b.y), &self.block_depth(b, &z_at), b.mask),
                    )
                }
                None => keep(
                    blocks,
                    #[inline(always)]
                    |b| packed24::<true>(p, face, px, &grid.at(b.x, b.y), &self.block_depth(b, &z_at), b.mask),
                ),
            },
            DepthBand::Depth32(px, s) => keep(
                blocks,
                #[inline(always)]
                |b| depth32::<true, false>(p, face, px, s, &grid.at(b.x, b.y), &self.block_depth(b, &z_at), b.mask),
            ),
            DepthBand::Float32(px, s) => keep(
                blocks,
                #[inline(always)]
                |b| depth32::<true, true>(p, face, px, s, &grid.at(b.x, b.y), &self.block_depth(b, &z_at), b.mask),
            ),
            DepthBand::None => blocks.len(),
        }
    }
}

/// Replaces each block's mask by `test(block)`, keeping (in order, at the front) the blocks
/// with a lane left; returns how many.
#[inline(always)]
fn keep(blocks: &mut [BlockEntry], mut test: impl FnMut(&BlockEntry) -> u16) -> usize {
    // (Each caller's `test` is one closure, called here once: inlined.)
    let mut kept = 0;
    for i in 0..blocks.len() {
        let mut b = blocks[i];
        b.mask = test(&b);
        blocks[kept] = b;
        kept += usize::from(b.mask != 0);
    }
    kept
}

/// 16-bit depth (no stencil).
#[inline(always)]
fn depth16<const STORE: bool>(p: &DepthStencilParams, px: &mut [u16], at: &BlockAt, z: &F32s, live: u16) -> u16 {
    let stored = map_lanes(&load(px, at), u32::from);
    let mut stencil = [0; LANES];
    let (pass, depth) =
        tests::<true>(at.level, p, None, DepthEncoding::Unorm(16), z, &stored, &mut stencil, &expand_mask(live));
    let bits = sign_mask16(at.level, &pass);
    if STORE && p.depth.is_some_and(|(_, write)| write) && bits != 0 {
        store(px, at, &map_lanes(&depth, |v| v as u16), 0xffff);
    }
    bits
}

/// Packed 24-bit depth and 8-bit stencil (`face`: the stencil test's, if on).
#[inline(always)]
#[allow(clippy::needless_range_loop)] // index loops vectorise where a `zip` may stay a call
fn packed24<const STORE: bool>(
    p: &DepthStencilParams,
    face: Option<&FaceKernel>,
    px: &mut [u32],
    at: &BlockAt,
    z: &F32s,
    live: u16,
) -> u16 {
    let words = load(px, at);
    let stored = map_lanes(&words, |w| w & 0x00ff_ffff);
    let mut stencil = map_lanes(&words, |w| w >> 24);
    let (pass, depth) =
        tests::<true>(at.level, p, face, DepthEncoding::Unorm(24), z, &stored, &mut stencil, &expand_mask(live));
    let bits = sign_mask16(at.level, &pass);
    let depth_writes = STORE && p.depth.is_some_and(|(_, write)| write);
    let stencil_writes = STORE && face.is_some() && p.stencil_writes;
    if (depth_writes && bits != 0) || stencil_writes {
        let new = lanes(|i| depth[i] | stencil[i] << 24);
        // Stored only when a word changed: the stencil passes of shadow volumes change
        // few blocks (z-fail: only where the volume is behind the scene), and a block
        // left alone costs no store and dirties no cache line.
        let mut changed = 0;
        for i in 0..LANES {
            changed |= new[i] ^ words[i];
        }
        if changed != 0 {
            store(px, at, &new, 0xffff);
        }
    }
    bits
}

/// Packed 24-bit depth and 8-bit stencil with the stencil test on and every operation of
/// the face in the packed-word form ([`WordOp`]): the stencil passes of shadow volumes
/// (INCR_WRAP/DECR_WRAP on depth failure) and the stencil-masked passes after them. The
/// operations change the loaded words in place, the depth write replaces their low 24 bits,
/// and the block is stored only when a word changed. The same words as [`packed24`].
#[inline(always)]
#[allow(clippy::needless_range_loop)] // an index loop vectorises where a `zip` may stay a call
fn packed24_words(p: &DepthStencilParams, face: &WordFace, px: &mut [u32], at: &BlockAt, z: &F32s, live: u16) -> u16 {
    let words = load(px, at);
    let live = expand_mask(live);
    let mut new = words;
    let mut passing = live;
    if face.func != 7 {
        let reference = [(face.reference & face.value_mask) as i32; LANES];
        let masked = map_lanes(&words, |w| ((w >> 24) & face.value_mask) as i32);
        passing = and(&compare_mask(face.func, &reference, &masked), &live);
        face.sfail.apply(&mut new, &and_not(&live, &passing));
    }
    if let Some((func, write)) = p.depth {
        let fragment = encode_depth(at.level, DepthEncoding::Unorm(24), z);
        let f = map_lanes(&fragment, |v| v as i32);
        let stored = map_lanes(&words, |w| (w & 0x00ff_ffff) as i32);
        let pass = and(&compare_mask(func, &f, &stored), &passing);
        face.zfail.apply(&mut new, &and_not(&passing, &pass));
        if write {
            new = select(&pass, &lanes(|i| (new[i] & 0xff00_0000) | fragment[i]), &new);
        }
        passing = pass;
    }
    face.zpass.apply(&mut new, &passing);
    let mut changed = 0;
    for i in 0..LANES {
        changed |= new[i] ^ words[i];
    }
    if changed != 0 {
        store(px, at, &new, 0xffff);
    }
    sign_mask16(at.level, &passing)
}

/// 32-bit unorm (`FLOAT` false) or float depth with an optional separate stencil plane.
#[inline(always)]
fn depth32<const STORE: bool, const FLOAT: bool>(
    p: &DepthStencilParams,
    face: Option<&FaceKernel>,
    px: &mut [u32],
    s: &mut Option<&mut [u8]>,
    at: &BlockAt,
    z: &F32s,
    live: u16,
) -> u16 {
    let stored = load(px, at);
    let mut stencil = match (&s, face.is_some()) {
        (Some(s), true) => map_lanes(&load(s, at), u32::from),
        _ => [0; LANES],
    };
    let live = expand_mask(live);
    let (pass, depth) = if FLOAT {
        tests::<true>(at.level, p, face, DepthEncoding::Float, z, &stored, &mut stencil, &live)
    } else {
        tests::<false>(at.level, p, face, DepthEncoding::Unorm(32), z, &stored, &mut stencil, &live)
    };
    let bits = sign_mask16(at.level, &pass);
    if STORE && p.depth.is_some_and(|(_, write)| write) && bits != 0 {
        store(px, at, &depth, 0xffff);
    }
    if let (Some(s), true) = (s, STORE && face.is_some() && p.stencil_writes) {
        store(s, at, &map_lanes(&stencil, |v| v as u8), 0xffff);
    }
    bits
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compare_bits_follow_every_function() {
        let f: U32s = std::array::from_fn(|i| (i % 3) as u32);
        let s = [1u32; LANES];
        for func in CompareFunc::ALL {
            let want = (0..LANES).filter(|&i| crate::fragment::passes(func, f[i], s[i])).fold(0u16, |m, i| m | 1 << i);
            assert_eq!(
                sign_mask16(crate::simd::current(), &compare_mask(compare_bits(func), &f, &s)),
                want,
                "{func:?}"
            );
        }
    }

    #[test]
    fn lane_depth_encoding_is_encode_fragment_bit_for_bit() {
        // Every encoding on values around each representable step of 16 and 24 bits near
        // the ends and at spread points, the edges (0, −0, 1, just below 1, above 1, tiny,
        // denormal, ±∞) and NaN.
        let mut z = vec![0.0, -0.0, 1.0, f32::from_bits(1f32.to_bits() - 1), 1.5, -1.0, 1e-30, 1e-45, 1e-38];
        z.extend([f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 0.5, 0.25, 1.0 / 3.0, 0.1, 0.7]);
        for bits in [16u32, 24] {
            let max = ((1u64 << bits) - 1) as f64;
            for k in (0..64).chain((1u64 << bits) - 64..1 << bits).chain((0..4096).map(|i| i * 4099 % (1 << bits))) {
                // The half-way points between steps, a few ulps either side.
                let x = ((k as f64 + 0.5) / max) as f32;
                for d in -4..=4i32 {
                    z.push(f32::from_bits((x.to_bits() as i32 + d) as u32));
                }
                z.push((k as f64 / max) as f32);
            }
        }
        for step in 0..20_000u32 {
            z.push(f32::from_bits(0x3f80_0000 - step * 97));
        }
        for encoding in
            [DepthEncoding::Unorm(16), DepthEncoding::Unorm(24), DepthEncoding::Unorm(32), DepthEncoding::Float]
        {
            for chunk in z.chunks(LANES) {
                let mut lanes = [0f32; LANES];
                lanes[..chunk.len()].copy_from_slice(chunk);
                for level in crate::simd::Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
                    let got = crate::simd::dispatch::run_with(level, |l| encode_depth(l, encoding, &lanes));
                    for i in 0..LANES {
                        assert_eq!(got[i], encoding.encode_fragment(lanes[i]), "{encoding:?} {:e} {level:?}", lanes[i]);
                    }
                }
            }
        }
    }

    /// A small deterministic generator for the kernel tests.
    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self) -> u32 {
            self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (self.0 >> 33) as u32
        }
    }

    #[test]
    fn the_block_kernel_is_the_span_path_on_every_format_and_state() {
        use crate::fragment::{stencil_depth_test, DepthTest, StencilTest};
        use StencilOp::*;
        let ops = [Keep, Zero, Replace, Incr, Decr, IncrWrap, DecrWrap, Invert];
        let funcs = CompareFunc::ALL;
        let formats = [
            DepthStencilFormat::Depth16,
            DepthStencilFormat::Packed24 { depth: true, stencil: true },
            DepthStencilFormat::Depth32 { stencil: true },
            DepthStencilFormat::Float32 { stencil: true },
        ];
        let at = BlockAt { x: 0, y: 0, base: 0, width: 4, valid: 0xffff, level: crate::simd::current() };
        let mut rng = Lcg(7);
        for round in 0..3000 {
            let format = formats[round % 4];
            let encoding = format.depth_encoding();
            let face = |rng: &mut Lcg| StencilFace {
                func: funcs[rng.next() as usize % 8],
                reference: [0, 1, 7, 128, 255][rng.next() as usize % 5],
                value_mask: [0xff, 0x0f, 0][rng.next() as usize % 3],
                write_mask: [0xff, 0xf0, 0][rng.next() as usize % 3],
                sfail: ops[rng.next() as usize % 8],
                zfail: ops[rng.next() as usize % 8],
                zpass: ops[rng.next() as usize % 8],
            };
            let stencil =
                (!rng.next().is_multiple_of(3)).then(|| StencilTest { front: face(&mut rng), back: face(&mut rng) });
            let depth = (!rng.next().is_multiple_of(4))
                .then(|| DepthTest { func: funcs[rng.next() as usize % 8], write: !rng.next().is_multiple_of(3) });
            if depth.is_none() && stencil.is_none() {
                continue;
            }
            let mut fragment = FragmentState::plain(depth, vec![], false);
            fragment.stencil = stencil;
            fragment.depth_clamp = rng.next().is_multiple_of(5).then_some([0.25, 0.75]);
            let Some(kernel) = DepthStencilKernel::new(&fragment, format) else {
                // Depth16 has no stencil: a stencil-only state compiles no kernel.
                assert!(fragment.depth.is_none() && format.stencil_bits() == 0);
                continue;
            };
            // Fragment depths near the stored ones (equal encodings included), the edges.
            let stored_z: Vec<f32> = (0..16).map(|_| [0.0, 1.0, 0.5, 0.25][rng.next() as usize % 4]).collect();
            let z: F32s = std::array::from_fn(|i| match rng.next() % 6 {
                0 => stored_z[i],
                1 => f32::from_bits(stored_z[i].to_bits().wrapping_add(rng.next() % 3)),
                2 => -0.5,
                3 => f32::NAN,
                _ => (rng.next() % 1000) as f32 / 999.0,
            });
            let depth_values: Vec<u32> = stored_z.iter().map(|&v| encoding.encode_fragment(v)).collect();
            let stencil_values: Vec<u8> = (0..16).map(|_| [0, 1, 255, 128, 7][rng.next() as usize % 5]).collect();
            let live = rng.next() as u16 | ((rng.next() % 2) as u16 * 0xffff);
            let front_facing = rng.next().is_multiple_of(2);
            // Three copies: the block kernel, its read-only test, and the span path.
            let mut d16: [Vec<u16>; 3] = std::array::from_fn(|_| depth_values.iter().map(|&v| v as u16).collect());
            let mut d32: [Vec<u32>; 3] = std::array::from_fn(|_| depth_values.clone());
            let mut packed: [Vec<u32>; 3] = std::array::from_fn(|_| {
                depth_values.iter().zip(&stencil_values).map(|(&d, &s)| d | (s as u32) << 24).collect()
            });
            let mut s8: [Vec<u8>; 3] = std::array::from_fn(|_| stencil_values.clone());
            let mut results = [0u16; 3];
            let [d16a, d16b, d16c] = &mut d16;
            let [d32a, d32b, d32c] = &mut d32;
            let [pa, pb, pc] = &mut packed;
            let [sa, sb, sc] = &mut s8;
            let mut bands: Vec<DepthBand<'_>> = match format {
                DepthStencilFormat::Depth16 => {
                    vec![DepthBand::Depth16(d16a), DepthBand::Depth16(d16b), DepthBand::Depth16(d16c)]
                }
                DepthStencilFormat::Packed24 { .. } => {
                    vec![DepthBand::Packed24(pa), DepthBand::Packed24(pb), DepthBand::Packed24(pc)]
                }
                DepthStencilFormat::Depth32 { .. } => vec![
                    DepthBand::Depth32(d32a, Some(sa)),
                    DepthBand::Depth32(d32b, Some(sb)),
                    DepthBand::Depth32(d32c, Some(sc)),
                ],
                _ => vec![
                    DepthBand::Float32(d32a, Some(sa)),
                    DepthBand::Float32(d32b, Some(sb)),
                    DepthBand::Float32(d32c, Some(sc)),
                ],
            };
            results[0] = kernel.run(&mut bands[0], &at, live, front_facing, || z);
            results[1] = kernel.test(&mut bands[1], &at, live, front_facing, || z);
            // The span path, row by row, with the depth clamp applied by its caller.
            let face =
                fragment
                    .stencil
                    .filter(|_| format.stencil_bits() > 0)
                    .map(|s| if front_facing { s.front } else { s.back });
            for r in 0..4 {
                let zr: Vec<f32> = z[4 * r..4 * r + 4]
                    .iter()
                    .map(|&v| fragment.depth_clamp.map_or(v, |[lo, hi]| v.clamp(lo, hi)))
                    .collect();
                let row_live = (live >> (4 * r)) as u64 & 0xf;
                let pass =
                    stencil_depth_test(face.as_ref(), fragment.depth.as_ref(), &mut bands[2], 4 * r, 4, &zr, row_live);
                results[2] |= (pass as u16) << (4 * r);
            }
            drop(bands);
            let what = format!("{format:?} {fragment:?} live {live:#x} front {front_facing} z {z:?}");
            assert_eq!(results[0], results[2], "passing lanes: {what}");
            assert_eq!(results[1], results[2], "read-only test: {what}");
            assert_eq!(
                (&d16[0], &d32[0], &packed[0], &s8[0]),
                (&d16[2], &d32[2], &packed[2], &s8[2]),
                "stored: {what}"
            );
            let untouched = (depth_values.clone(), stencil_values.clone());
            assert_eq!(d32[1].len(), 16);
            if !matches!(format, DepthStencilFormat::Depth16 | DepthStencilFormat::Packed24 { .. }) {
                assert_eq!((&d32[1], &s8[1]), (&untouched.0, &untouched.1), "the test stores nothing: {what}");
            }
            assert_eq!(
                packed[1],
                depth_values.iter().zip(&stencil_values).map(|(&d, &s)| d | (s as u32) << 24).collect::<Vec<_>>()
            );
            assert_eq!(d16[1], depth_values.iter().map(|&v| v as u16).collect::<Vec<_>>());
            // Culling before the alpha test is offered exactly when failing changes nothing.
            let keeps = |f: &StencilFace| f.write_mask == 0 || (f.sfail == Keep && f.zfail == Keep);
            let want = fragment
                .stencil
                .filter(|_| format.stencil_bits() > 0)
                .is_none_or(|s| keeps(&s.front) && keeps(&s.back));
            assert_eq!(kernel.culls_before_alpha(), want, "{what}");
        }
    }

    #[test]
    fn the_packed_word_stencil_kernel_is_the_lane_kernel() {
        // Packed 24/8 with the stencil test: the batched stage (the packed-word kernel when
        // both faces have the word form) against the block-by-block lane kernel, itself the
        // span path (the test above), over every operation, write masks full, partial and
        // empty, every function, depth on or off, with or without its write.
        use crate::fragment::{DepthTest, StencilTest};
        use StencilOp::*;
        let ops = [Keep, Zero, Replace, Incr, Decr, IncrWrap, DecrWrap, Invert];
        let format = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let mut rng = Lcg(11);
        let mut word_form = 0;
        for _ in 0..20_000 {
            let face = |rng: &mut Lcg| StencilFace {
                func: CompareFunc::ALL[rng.next() as usize % 8],
                reference: [0, 1, 7, 128, 255][rng.next() as usize % 5],
                value_mask: [0xff, 0x0f, 0][rng.next() as usize % 3],
                write_mask: [0xff, 0xff, 0xf0, 0][rng.next() as usize % 4],
                sfail: ops[rng.next() as usize % 8],
                zfail: ops[rng.next() as usize % 8],
                zpass: ops[rng.next() as usize % 8],
            };
            let depth = (!rng.next().is_multiple_of(4)).then(|| DepthTest {
                func: CompareFunc::ALL[rng.next() as usize % 8],
                write: rng.next().is_multiple_of(2),
            });
            let mut fragment = FragmentState::plain(depth, vec![], false);
            // Without the stencil test too (the depth test alone in the word form).
            let stencil = StencilTest { front: face(&mut rng), back: face(&mut rng) };
            fragment.stencil = (!rng.next().is_multiple_of(5)).then_some(stencil);
            if fragment.stencil.is_none() && fragment.depth.is_none() {
                continue;
            }
            let kernel = DepthStencilKernel::new(&fragment, format).unwrap();
            word_form += usize::from(kernel.params.word_faces.is_some());
            let stored: Vec<u32> = (0..16)
                .map(|_| {
                    let d = [0, 0x00ff_ffff, 0x0080_0000, rng.next() & 0x00ff_ffff][rng.next() as usize % 4];
                    d | [0u32, 1, 255, 128, 7][rng.next() as usize % 5] << 24
                })
                .collect();
            let z: F32s = std::array::from_fn(|i| match rng.next() % 4 {
                0 => (stored[i] & 0x00ff_ffff) as f32 / 16_777_215.0,
                1 => f32::NAN,
                _ => (rng.next() % 1000) as f32 / 999.0,
            });
            let live = rng.next() as u16 | ((rng.next() % 2) as u16 * 0xffff);
            let front_facing = rng.next().is_multiple_of(2);
            let level = crate::simd::current();
            let at = BlockAt { x: 0, y: 0, base: 0, width: 4, valid: 0xffff, level };
            let grid = Grid { y0: 0, rows: 4, width: 4, stride: 4, offset: 0, level };
            let (mut lane, mut batched) = (stored.clone(), stored.clone());
            let want = kernel.run(&mut DepthBand::Packed24(&mut lane), &at, live, front_facing, || z);
            let mut blocks = [BlockEntry { x: 0, y: 0, mask: live, source: 0 }];
            let kept = crate::simd::dispatch::run_with(level, |l| {
                let grid = Grid { level: l, ..grid };
                kernel.run_blocks(&mut DepthBand::Packed24(&mut batched), grid, front_facing, &mut blocks, true, |_| z)
            });
            let what = format!("{fragment:?} live {live:#x} front {front_facing}");
            assert_eq!((kept, blocks[0].mask), (usize::from(want != 0), want), "{what}");
            assert_eq!(batched, lane, "{what}");
            // Without survivors asked for (no colour target, no occlusion query): the same
            // words stored.
            let mut unkept = stored.clone();
            let mut blocks = [BlockEntry { x: 0, y: 0, mask: live, source: 0 }];
            crate::simd::dispatch::run_with(level, |l| {
                let grid = Grid { level: l, ..grid };
                kernel.run_blocks(&mut DepthBand::Packed24(&mut unkept), grid, front_facing, &mut blocks, false, |_| z)
            });
            assert_eq!(unkept, lane, "{what} without survivors");
        }
        assert!(word_form > 2000, "{word_form} states took the packed-word kernel");
    }

    #[test]
    fn lane_masks_round_trip_every_16_bit_mask() {
        for bits in 0..=u16::MAX {
            let m = expand_mask(bits);
            assert!(m.iter().all(|&v| v == 0 || v == !0));
            assert_eq!(sign_mask16(crate::simd::current(), &m), bits);
        }
    }

    #[test]
    fn stencil_ops_wrap_and_saturate_through_the_write_mask() {
        let op = |op: StencilOp, v: &mut U32s, reference: u32, which: u16, write_mask: u32| {
            stencil_op(stencil_op_code(op), v, reference, &expand_mask(which), write_mask)
        };
        let mut v: U32s = [0; LANES];
        v[1] = 255;
        op(StencilOp::DecrWrap, &mut v, 0, 0b01, 0xff);
        op(StencilOp::Incr, &mut v, 0, 0b10, 0xff);
        assert_eq!(v[..2], [255, 255]);
        op(StencilOp::IncrWrap, &mut v, 0, 0b11, 0x0f);
        assert_eq!(v[..2], [0xf0, 0xf0]);
        op(StencilOp::Replace, &mut v, 0x3c, 0b01, 0xff);
        op(StencilOp::Invert, &mut v, 0, 0b10, 0xff);
        assert_eq!(v[..3], [0x3c, 0x0f, 0]);
        op(StencilOp::Keep, &mut v, 0x77, 0xffff, 0xff);
        assert_eq!(v[..3], [0x3c, 0x0f, 0]);
    }
}
