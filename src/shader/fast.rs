//! The executor the pipeline runs: [`Compiled`], an interpreter of fused lane operations
//! over a file of 16-lane words, running the pre-decoded [`Code`] that [`super::lower`]
//! makes from a program once (constants folded, dead code dropped, uniform values scalar,
//! uniform branches taken for real, writes unmasked where every running lane runs them,
//! clamp / normalize / matrix·vector fused). It gives the same bits as the reference
//! [`super::exec`], the semantics' definition, on every program (the tests run both).
//!
//! **Why an interpreter.** Three designs were open: (a) this interpreter, (b) a
//! closure-threaded program (`Threaded`, in test builds: the same front end, a `Vec` of boxed closures,
//! one per fused operation; kept for the comparison and its tests), (c) an x86-64 code
//! generator. Measured on the three programs of `bench.rs` (callgrind instructions per
//! 16-lane block; release build without LTO; AVX2 unless said):
//!
//! | program (statements → ops) | reference | (a) AVX2 | (a) SSE2 | (b) closures |
//! |---|---|---|---|---|
//! | phong (77 → 60) | 12 709 | 3 377 | 4 182 | 4 507 |
//! | texture (62 → 57, with a lookup) | 11 432 | 3 673 | 4 333 | 4 578 |
//! | control (66 → 55, a loop of 4, divergent ifs, a discard) | 21 380 | 9 822 | 10 865 | 11 079 |
//!
//! Wall clock, ns per block (each design in its own process, best of 3×5 rounds of 100 000
//! blocks, AMD EPYC virtual machine, 2 cores loaded ~5× over, so ±15 %), AVX2 / SSE2:
//! phong 2 172 / 2 086 reference, 704 / 639 (a), 720 / 625 (b); texture 1 612 / 1 482,
//! 581 / 532, 762 / 600; control 4 023 / 3 177, 1 317 / 983, 1 730 / 1 162. Most of the gain
//! over the reference is the front end's (uniform values computed once, fused operations,
//! no masks where no lane can be skipped, lane loops without per-lane calls); between (a)
//! and (b) the interpreter runs 10–25 % fewer instructions (a `match` on a 16-byte record
//! costs no more than an indirect call through a closure, and its loop is compiled once per SIMD
//! level with [`crate::simd::per_level!`], where a boxed closure is compiled once, for the
//! SSE2 baseline) and is as fast or up to 25 % faster on the clock. The per-level copies
//! save 10–19 % of the instructions at AVX2 but no measurable time on this machine (its
//! AVX2 may split 256-bit operations); they cost nothing per block, so they stay. The
//! interpreter's code is one `Vec<Op>`, cheap to build (the front end costs 130–160
//! thousand instructions per program, ≈ 30 µs: a cold first frame pays that
//! per program, far under its 1 ms) and to cache. A code generator would remove the
//! remaining dispatch and the stores between operations, but brings an assembler, executable
//! memory and its unsafe code, per-level encodings and a second implementation of every
//! operation to keep bit-identical; not worth it while the reference's
//! transcendental functions (scalar, per lane: ≈ 930 of phong's 3 377 instructions) are the
//! larger cost left.
//!
//! **A GLSL program.** `tools/bench/bench.c`'s `phong_shader` (per-pixel Blinn-Phong, its
//! loop over two lights unrolled, the built-in light state indexed by the loop counter),
//! per 16-lane fragment block (callgrind instructions under `GlslShading::run`, 256², one
//! thread, release build without LTO, AVX2):
//!
//! | | operations (with prologue) | interpreter | of which exp2 / log2 | whole run with inputs |
//! |---|---|---|---|---|
//! | unrolled as is | 506 (260 scalar moves) | 14 940 | 2 800 | 16 410 |
//! | [`super::flatten`]'s single writes and common instructions, vector exp2 without conversions | 205 | 7 370 | 1 900 | 8 500 |
//! | [`super::group`]'s groups (a `vec4`'s adds, subs, muls, selects: one dispatch each four) | 205 (≈ 126 per block → 66) | 6 090 (6 630 before) | | |
//!
//! (The last row: the interpreter's own instructions and its callees per call, 256², release
//! build without LTO, AVX2, callgrind, not under `GlslShading::run`: the build had no symbols;
//! the whole process ran 3.2 % fewer instructions; at 1024², 2 threads, on a loaded machine,
//! phong's best of 6 frames went from 150 to 142 ms, llvmpipe's 56.) A group's loop reads
//! its registers from the file's first [`FILE`] words as an array, by a byte: without that,
//! and with the file reached through `self` (the compiler reloaded its pointer and length
//! after every store), groups saved 1.5 %, not 8 %.
//!
//! GLSL's `pow` (log2, a product, exp2) is one operation, [`Op::Pow`], and
//! [`super::math::log2_lanes`] takes zero in its vector path (a light's specular power at
//! the lanes facing away from it: scalar calls before, ≈ 2 % of phong's instructions).
//! Together (`tools/bench/bench.c`'s `phong_shader`, 256², one thread, release build without
//! LTO, AVX2, callgrind): the whole process 1 227 → 1 161 million instructions (≈ 17 560 →
//! 16 610 per shaded block), the same bytes at SSE2 and AVX2.
//! Their polynomials' fused multiply-adds are then plain double-precision sums, without
//! the general emulation's midpoint and subnormal checks (`math::fma_plain`: exhaustively the
//! same bits on every input they see): 256², one thread, release build without LTO, 65 536
//! blocks, the whole process 1 114 → 1 065 million instructions at AVX2 (−752 per block;
//! pow's exp2 and log2 were ≈ 1 350 per block in the LTO build), 1 335 → 1 263 million at
//! SSE2 (−1 096: a 64-bit compare is three instructions there), the same bytes.
//! Tried and dropped: every operation reading a fixed-size file through register numbers
//! masked to it (4096 words, no bounds checks; a larger program would not link): each
//! operand's compare and branch (26.7 million instructions on phong at 256²) became an `and`
//! (30.9 million), no fewer instructions; and piglit's `glsl-fs-uniform-array-6` has 10 239
//! registers. A byte index (256 words) would make the mask free but needs words reused
//! between register lifetimes first (14 of piglit's 1 237 GLSL 1.10/1.20 shaders have more
//! than 256 registers, 4 more than 1 024).
//!
//! The unrolled iterations reassigned the same registers (the light's position, products,
//! results), so their uniform values stayed in the per-block run as moves instead of the
//! prologue; written once, they are computed once per draw. What is left per block is ~150
//! vector operations at ≈ 37 instructions each (dispatch, operand reads with bounds checks,
//! the unmasked store) and the two pow's exp2 and log2; a positional light's arm computed
//! for the directional light too (the GLSL ternary is a select) is another ~10 operations.
//!
//! **Specialised per draw** ([`super::specialize`], [`Compiled::specialize`]: the fragment
//! pipeline's form): a select on a uniform condition is a copy of its arm, what the uniforms
//! decide is computed once per draw, copies and dead arms are gone, and `-v`'s negations are
//! a group. Phong with `bench.c`'s lights (0 directional, 1 positional): 68 dispatches per
//! block → 53 (light 0's positional arm, its attenuation's product by 1, light 1's selects).
//! Callgrind, `phong_shader` at 256², one thread, LTO profiling build (AVX2), per shaded
//! block (65 536 runs):
//!
//! | | interpreter (`run_tree`) | `GlslShading::run` | whole block (`execute_on`) | process |
//! |---|---|---|---|---|
//! | before | 6 821 | 7 054 | 9 180 | 862.6 M |
//! | specialised | 5 786 | 6 017 | 8 142 | 795.6 M |
//!
//! (exp2 and log2 of the two `pow`s are ≈ 1 350 of the interpreter's, unchanged.) Wall
//! clock at 1024², `TESSERA_THREADS=2`, 3 frames × 3 alternated runs on a loaded 2-core
//! machine, best (median) ms: phong 108 (121) → 95 (106), llvmpipe 56 (66): 0.51× → 0.59×
//! of llvmpipe; `textured_shader` 42.6 → 43.1, llvmpipe 86.8 (≈ 2.0×, unchanged: nothing
//! to specialise). The library grew 31.5 KB (4 794 536 → 4 826 048 bytes stripped).
//!
//! The arithmetic is [`super::lower`]'s lane functions and the reference's own word
//! functions: IEEE add, sub, mul, div and sqrt rounded once each, never contracted, and
//! [`super::math`]'s polynomials, so every level and every CPU gives the same bytes.
use super::exec::{self, f, fu, map1, map2, Io, LodLanes, SampleRequest, Word, LANES, MAX_LOOP_ITERATIONS};
use super::ir::{Axis, Program};
use super::lower::{
    binary_lane, dot_lane, lower, mad_lane, op_writes, split_prologue, unary_lane, Code, Cond, GroupKind, Node, Op,
    Wide, WideLod, R,
};
use std::sync::{Arc, Mutex};

#[inline(always)]
fn map3(a: &Word, b: &Word, c: &Word, op: impl Fn(u32, u32, u32) -> u32) -> Word {
    let mut out = [0u32; LANES];
    for i in 0..LANES {
        out[i] = op(a[i], b[i], c[i]);
    }
    out
}

/// Lane `i`'s bit of a lane mask.
pub const LANE_BITS: Word = [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384, 32768];

/// The lanes of `exec` as a word of all-ones and zeros (a broadcast, an and and a compare
/// per vector: the shifts by each lane's index stayed scalar).
#[inline(always)]
pub fn lane_mask(exec: u16) -> Word {
    let mut mask = [0u32; LANES];
    for (m, bit) in mask.iter_mut().zip(LANE_BITS) {
        *m = if exec as u32 & bit != 0 { !0 } else { 0 };
    }
    mask
}

/// The register file of runs, kept between runs so that a run allocates nothing.
#[derive(Default)]
pub struct Registers {
    w: Vec<Word>,
    /// The running lanes of the current run of operations, as a bit mask and as a word.
    exec: u16,
    mask: Word,
    /// Whether the current run writes under the mask.
    masked: bool,
}

impl Registers {
    pub fn new() -> Registers {
        Registers::default()
    }

    /// Register `r`'s word (a [`Bound`] or [`BoundRun`] program's input or output).
    #[inline(always)]
    pub fn word(&mut self, r: R) -> &mut Word {
        &mut self.w[r as usize]
    }

    #[inline(always)]
    fn get(&self, r: R) -> &Word {
        &self.w[r as usize]
    }

    /// Lane 0 of a uniform register.
    #[inline(always)]
    fn s(&self, r: R) -> u32 {
        self.w[r as usize][0]
    }

    #[inline(always)]
    fn bcast(&mut self, d: R, v: u32) {
        self.w[d as usize] = [v; LANES];
    }

    #[inline(always)]
    fn put(&mut self, d: R, v: Word) {
        let mask = self.mask;
        let dst = &mut self.w[d as usize];
        if !self.masked {
            *dst = v;
        } else {
            for i in 0..LANES {
                dst[i] = (v[i] & mask[i]) | (dst[i] & !mask[i]);
            }
        }
    }

    /// A texture lookup's result: always under the mask, as the reference writes it.
    #[inline(always)]
    fn put_masked(&mut self, d: R, v: &Word) {
        let mask = self.mask;
        let dst = &mut self.w[d as usize];
        for i in 0..LANES {
            dst[i] = (v[i] & mask[i]) | (dst[i] & !mask[i]);
        }
    }

    /// A texture lookup of the running lanes: out of line, so that the interpreter's
    /// `match` stays small in its per-level copies, but compiled once per SIMD level itself
    /// (one more dispatch per lookup), so that its copies of coordinates and masked stores of
    /// results, a few 16-lane words each, run at the machine's level and not at SSE2's.
    #[inline(never)]
    fn texture(&mut self, io: &mut Io<'_>, wide: &Wide) {
        crate::simd::per_level!(self.texture_body(io, wide))
    }

    /// [`Registers::texture`]'s body. Plain loops over the words, not `array::map` or
    /// iterator zips: without LTO those stayed calls, and cost more than the copies.
    #[inline(always)]
    // The lookup's words and its destinations are indexed alike.
    #[allow(clippy::needless_range_loop)]
    fn texture_body(&mut self, io: &mut Io<'_>, wide: &Wide) {
        let exec = self.exec;
        match *wide {
            Wide::Sample { dst, unit, n, coords, projective, lod, compare } => {
                let mut words = [[0; LANES]; 4];
                for k in 0..4 {
                    words[k] = *self.get(coords[k]);
                }
                let lod = match lod {
                    WideLod::Implicit => LodLanes::Implicit,
                    WideLod::Bias(r) => LodLanes::Bias(self.get(r)),
                    WideLod::Explicit(r) => LodLanes::Explicit(self.get(r)),
                };
                let compare = compare.map(|r| self.get(r));
                let request = SampleRequest { unit, n, coords: &words, projective, lod, compare, lanes: exec };
                let mut out = [[0; LANES]; 4];
                io.textures.sample(&request, &mut out);
                for k in 0..4 {
                    self.put_masked(dst[k], &out[k]);
                }
            }
            Wide::Fetch { dst, unit, n, coords, lod } => {
                let mut words = [[0; LANES]; 3];
                for k in 0..3 {
                    words[k] = *self.get(coords[k]);
                }
                let mut out = [[0; LANES]; 4];
                io.textures.fetch(unit, n, &words, self.get(lod), exec, &mut out);
                for k in 0..4 {
                    self.put_masked(dst[k], &out[k]);
                }
            }
            Wide::Size { dst, unit, lod } => {
                let mut out = [[0; LANES]; 3];
                io.textures.size(unit, self.get(lod), exec, &mut out);
                for k in 0..3 {
                    self.put_masked(dst[k], &out[k]);
                }
            }
            Wide::MatVec { .. } | Wide::Group { .. } => unreachable!("not a texture lookup"),
        }
    }

    #[inline(always)]
    fn mat_vec(&mut self, wide: &Wide) {
        let Wide::MatVec { n, rows_n, d, rows, v } = *wide else { unreachable!("a matrix·vector product") };
        for row in 0..rows_n as usize {
            let r = rows[row];
            let value = match n {
                2 => dot2(self.get(r[0]), self.get(r[1]), self.get(v[0]), self.get(v[1])),
                3 => {
                    dot3(self.get(r[0]), self.get(r[1]), self.get(r[2]), self.get(v[0]), self.get(v[1]), self.get(v[2]))
                }
                _ => dot4(
                    [self.get(r[0]), self.get(r[1]), self.get(r[2]), self.get(r[3])],
                    [self.get(v[0]), self.get(v[1]), self.get(v[2]), self.get(v[3])],
                ),
            };
            self.put(d[row], value);
        }
    }

    /// A [`Wide::Group`]: its operations in order, one loop per kind. The file's first
    /// [`FILE`] words as a local array, indexed by a byte ([`super::group`] groups registers
    /// below [`FILE`] only), and the mask flag read once: through `self`, every store made
    /// the compiler reload the file's pointer and length and the flag, and each read and
    /// write had its bounds check (a group cost about what its operations did one by one).
    #[inline(always)]
    fn group(&mut self, wide: &Wide) {
        let Wide::Group { kind, n, d, a, b, c } = wide else { unreachable!("a group of operations") };
        let n = usize::from(*n).min(4);
        let Registers { w, mask, masked, .. } = self;
        let masked = *masked;
        let w: &mut [Word; FILE] = (&mut w[..FILE]).try_into().expect("a file of at least FILE words");
        let at = |r: R| usize::from(r as u8);
        match kind {
            GroupKind::Add => {
                for k in 0..n {
                    let v = map2(&w[at(a[k])], &w[at(b[k])], |x, y| fu(f(x) + f(y)));
                    put_word(&mut w[at(d[k])], &v, mask, masked);
                }
            }
            GroupKind::Sub => {
                for k in 0..n {
                    let v = map2(&w[at(a[k])], &w[at(b[k])], |x, y| fu(f(x) - f(y)));
                    put_word(&mut w[at(d[k])], &v, mask, masked);
                }
            }
            GroupKind::Mul => {
                for k in 0..n {
                    let v = map2(&w[at(a[k])], &w[at(b[k])], |x, y| fu(f(x) * f(y)));
                    put_word(&mut w[at(d[k])], &v, mask, masked);
                }
            }
            GroupKind::Neg => {
                for k in 0..n {
                    let v = map1(&w[at(a[k])], |x| x ^ 0x8000_0000);
                    put_word(&mut w[at(d[k])], &v, mask, masked);
                }
            }
            GroupKind::Select => {
                for k in 0..n {
                    let v = map3(&w[at(c[k])], &w[at(a[k])], &w[at(b[k])], |c, x, y| if c != 0 { x } else { y });
                    put_word(&mut w[at(d[k])], &v, mask, masked);
                }
            }
        }
    }
}

/// Writes `v` to `dst`, under `mask` when `masked`.
#[inline(always)]
fn put_word(dst: &mut Word, v: &Word, mask: &Word, masked: bool) {
    if !masked {
        *dst = *v;
    } else {
        for i in 0..LANES {
            dst[i] = (v[i] & mask[i]) | (dst[i] & !mask[i]);
        }
    }
}

// Plain loops, not `array::from_fn` or `map`: those stay calls per lane without LTO.
#[inline(always)]
fn dot2(a0: &Word, a1: &Word, b0: &Word, b1: &Word) -> Word {
    let mut out = [0u32; LANES];
    for i in 0..LANES {
        out[i] = fu(f(a0[i]) * f(b0[i]) + f(a1[i]) * f(b1[i]));
    }
    out
}

#[inline(always)]
fn dot3(a0: &Word, a1: &Word, a2: &Word, b0: &Word, b1: &Word, b2: &Word) -> Word {
    let mut out = [0u32; LANES];
    for i in 0..LANES {
        out[i] = fu(f(a0[i]) * f(b0[i]) + f(a1[i]) * f(b1[i]) + f(a2[i]) * f(b2[i]));
    }
    out
}

#[inline(always)]
fn dot4(a: [&Word; 4], b: [&Word; 4]) -> Word {
    let mut out = [0u32; LANES];
    for i in 0..LANES {
        out[i] =
            fu(f(a[0][i]) * f(b[0][i]) + f(a[1][i]) * f(b[1][i]) + f(a[2][i]) * f(b[2][i]) + f(a[3][i]) * f(b[3][i]));
    }
    out
}

/// One function per operation, written once: `step` (the interpreter's `match`) and
/// `thunk` (the closure-threaded design's closure per operation) are both made from it.
macro_rules! operations {
    (|$st:ident, $io:ident, $wide:ident| { $( $pat:pat => $body:expr, )* }) => {
        /// One operation; `GROUPS`: whether the caller's code holds groups (only
        /// [`Interpreter`]'s: the copies of the bound forms and the prologue, which never see
        /// one, then carry no [`Registers::group`]: library size).
        #[inline(always)]
        fn step<const GROUPS: bool>(op: &Op, $st: &mut Registers, $io: &mut Io<'_>, $wide: &[Wide]) {
            match *op {
                $( $pat => $body, )*
            }
        }

        /// An operation of the closure-threaded design.
        #[cfg(test)]
        type Thunk = Box<dyn Fn(&mut Registers, &mut Io<'_>, &[Wide]) + Send + Sync>;

        #[cfg(test)]
        fn thunk(op: Op) -> Thunk {
            const GROUPS: bool = true;
            match op {
                $( $pat => Box::new(move |$st: &mut Registers, $io: &mut Io<'_>, $wide: &[Wide]| {
                    let _ = (&$io, &$wide);
                    $body
                }), )*
            }
        }
    };
}

operations!(|st, io, wide| {
    Op::SConst { d, bits } => st.bcast(d, bits),
    Op::SUniform { d, slot } => st.bcast(d, io.uniforms[slot as usize]),
    Op::SMov { d, a } => st.bcast(d, st.s(a)),
    Op::SUnary { op, d, a } => st.bcast(d, unary_lane(op, st.s(a))),
    Op::SBinary { op, d, a, b } => st.bcast(d, binary_lane(op, st.s(a), st.s(b))),
    Op::SMad { d, a, b, c } => st.bcast(d, mad_lane(st.s(a), st.s(b), st.s(c))),
    Op::SDot { n, d, a, b } => {
        let (mut x, mut y) = ([0; 4], [0; 4]);
        for k in 0..n as usize {
            x[k] = st.s(a[k]);
            y[k] = st.s(b[k]);
        }
        st.bcast(d, dot_lane(n as usize, &x, &y))
    },
    Op::SSelect { d, c, a, b } => st.bcast(d, if st.s(c) != 0 { st.s(a) } else { st.s(b) }),
    Op::Const { d, bits } => st.put(d, [bits; LANES]),
    Op::Uniform { d, slot } => st.put(d, [io.uniforms[slot as usize]; LANES]),
    Op::Input { d, slot } => st.put(d, io.inputs[slot as usize]),
    Op::Mov { d, a } => st.put(d, *st.get(a)),
    Op::Add { d, a, b } => st.put(d, map2(st.get(a), st.get(b), |x, y| fu(f(x) + f(y)))),
    Op::Sub { d, a, b } => st.put(d, map2(st.get(a), st.get(b), |x, y| fu(f(x) - f(y)))),
    Op::Mul { d, a, b } => st.put(d, map2(st.get(a), st.get(b), |x, y| fu(f(x) * f(y)))),
    Op::Div { d, a, b } => st.put(d, map2(st.get(a), st.get(b), |x, y| fu(f(x) / f(y)))),
    Op::Min { d, a, b } => st.put(d, map2(st.get(a), st.get(b), exec::fmin_lane)),
    Op::Max { d, a, b } => st.put(d, map2(st.get(a), st.get(b), exec::fmax_lane)),
    Op::Lt { d, a, b } => st.put(d, map2(st.get(a), st.get(b), |x, y| (f(x) < f(y)) as u32)),
    Op::Le { d, a, b } => st.put(d, map2(st.get(a), st.get(b), |x, y| (f(x) <= f(y)) as u32)),
    Op::Sqrt { d, a } => st.put(d, map1(st.get(a), |x| fu(f(x).sqrt()))),
    Op::Rsq { d, a } => st.put(d, map1(st.get(a), |x| fu(1.0 / f(x).sqrt()))),
    Op::Unary { op, d, a } => st.put(d, exec::unary(op, st.get(a))),
    Op::Binary { op, d, a, b } => st.put(d, exec::binary(op, st.get(a), st.get(b))),
    Op::Mad { d, a, b, c } => st.put(d, map3(st.get(a), st.get(b), st.get(c), |x, y, z| fu(f(x) * f(y) + f(z)))),
    Op::Dot2 { d, a, b } => st.put(d, dot2(st.get(a[0]), st.get(a[1]), st.get(b[0]), st.get(b[1]))),
    Op::Dot3 { d, a, b } => {
        st.put(d, dot3(st.get(a[0]), st.get(a[1]), st.get(a[2]), st.get(b[0]), st.get(b[1]), st.get(b[2])))
    },
    Op::Dot4 { d, a, b } => st.put(
        d,
        dot4([st.get(a[0]), st.get(a[1]), st.get(a[2]), st.get(a[3])], [st.get(b[0]), st.get(b[1]), st.get(b[2]), st.get(b[3])]),
    ),
    Op::Select { d, c, a, b } => st.put(d, map3(st.get(c), st.get(a), st.get(b), |c, x, y| if c != 0 { x } else { y })),
    Op::Clamp { d, a, lo, hi } => st.put(
        d,
        map3(st.get(a), st.get(lo), st.get(hi), |x, l, h| exec::fmin_lane(exec::fmax_lane(x, l), h)),
    ),
    Op::ClampSelect { d, a, lo, hi } => st.put(
        d,
        map3(st.get(a), st.get(lo), st.get(hi), |x, l, h| {
            if f(l) < f(x) {
                if f(h) < f(x) {
                    h
                } else {
                    x
                }
            } else {
                l
            }
        }),
    ),
    Op::Normalize3 { d, a } => {
        let v = [*st.get(a[0]), *st.get(a[1]), *st.get(a[2])];
        let s = map1(&dot3(&v[0], &v[1], &v[2], &v[0], &v[1], &v[2]), |x| fu(1.0 / f(x).sqrt()));
        for k in 0..3 {
            st.put(d[k], map2(&v[k], &s, |x, y| fu(f(x) * f(y))));
        }
    },
    Op::MatVec(i) => st.mat_vec(&wide[i as usize]),
    Op::Derivative { x, d, a } => st.put(d, exec::derivative(if x { Axis::X } else { Axis::Y }, st.get(a))),
    Op::Output { slot, a } => {
        let value = *st.get(a);
        let out = &mut io.outputs[slot as usize];
        // Every lane running (a full batch of vertices or a covered block): no blend.
        if st.exec == exec::ALL_LANES {
            *out = value;
        } else {
            let mask = st.mask;
            for i in 0..LANES {
                out[i] = (value[i] & mask[i]) | (out[i] & !mask[i]);
            }
        }
    },
    Op::Texture(i) => st.texture(io, &wide[i as usize]),
    Op::Group(i) => {
        if GROUPS {
            st.group(&wide[i as usize])
        } else {
            unreachable!("a group outside the interpreter's code")
        }
    },
    Op::MatRow { d, m, v } => {
        let [m0, m1, m2, m3] = m.map(|r| f(st.s(r)));
        let (v0, v1, v2, v3) = (st.get(v[0]), st.get(v[1]), st.get(v[2]), st.get(v[3]));
        let mut out = [0u32; LANES];
        for i in 0..LANES {
            let t = m0 * f(v0[i]);
            let t = m1 * f(v1[i]) + t;
            let t = m2 * f(v2[i]) + t;
            out[i] = fu(m3 * f(v3[i]) + t);
        }
        st.put(d, out)
    },
    Op::Exp2 { d, a } => st.put(d, super::math::exp2_lanes(st.get(a))),
    Op::Log2 { d, a } => st.put(d, super::math::log2_lanes(st.get(a))),
    Op::Pow { d, a, b } => {
        let l = super::math::log2_lanes(st.get(a));
        let m = map2(st.get(b), &l, |y, l| fu(f(y) * f(l)));
        st.put(d, super::math::exp2_lanes(&m))
    },
});

/// Where the lanes that stopped running went (as in the reference).
#[derive(Default)]
struct Exits {
    broke: u16,
    continued: u16,
    discarded: u16,
}

/// How a run of straight-line operations is executed: the one difference between the two
/// designs.
trait Straight {
    fn run(&self, code: &Code, st: &mut Registers, io: &mut Io<'_>, start: u32, end: u32);
}

/// Runs the control tree (the reference's masks, over pre-decoded runs).
fn nodes<S: Straight>(
    s: &S,
    code: &Code,
    st: &mut Registers,
    list: &[Node],
    mut exec: u16,
    exits: &mut Exits,
    io: &mut Io<'_>,
) -> u16 {
    for node in list {
        if exec == 0 {
            break;
        }
        match node {
            Node::Run { start, end, masked } => {
                st.exec = exec;
                st.mask = lane_mask(exec);
                st.masked = *masked;
                s.run(code, st, io, *start, *end);
            }
            Node::If { cond, then, otherwise } => {
                let taken = match *cond {
                    Cond::Lanes(r) => exec & exec::true_lanes(st.get(r)),
                    Cond::Uniform(r) => {
                        if st.s(r) != 0 {
                            exec
                        } else {
                            0
                        }
                    }
                };
                let not_taken = exec & !taken;
                let mut after = 0;
                if taken != 0 {
                    after |= nodes(s, code, st, then, taken, exits, io);
                }
                if not_taken != 0 {
                    after |= nodes(s, code, st, otherwise, not_taken, exits, io);
                }
                exec = after;
            }
            Node::Loop { body } => {
                let outer = (exits.broke, exits.continued);
                exits.broke = 0;
                let mut looping = exec;
                let mut iterations = 0;
                while looping != 0 {
                    if iterations == MAX_LOOP_ITERATIONS {
                        exits.broke |= looping;
                        break;
                    }
                    iterations += 1;
                    exits.continued = 0;
                    looping = nodes(s, code, st, body, looping, exits, io) | exits.continued;
                }
                exec = exits.broke;
                (exits.broke, exits.continued) = outer;
            }
            Node::Break => {
                exits.broke |= exec;
                exec = 0;
            }
            Node::Continue => {
                exits.continued |= exec;
                exec = 0;
            }
            Node::Return => exec = 0,
            Node::Discard => {
                exits.discarded |= exec;
                exec = 0;
            }
        }
    }
    exec
}

/// Runs a prologue (the uniform values, once per draw or batch of draws) at the baseline:
/// one copy of the interpreter's `match` for [`Compiled::prepare`] and [`Bound::prepare`].
#[inline(never)]
fn run_prologue(prologue: &[Op], registers: &mut Registers, uniforms: &[u32], wide: &[Wide]) {
    let mut io = Io { inputs: &[], uniforms, outputs: &mut [], textures: &exec::NoTextures };
    for op in prologue {
        step::<false>(op, registers, &mut io, wide);
    }
}

fn run_tree<S: Straight>(s: &S, code: &Code, st: &mut Registers, io: &mut Io<'_>, lanes: u16) -> u16 {
    // At least [`FILE`] words: a group's ([`Registers::group`]).
    st.w.resize(code.registers.max(FILE), [0; LANES]);
    for &r in &code.zeroed {
        st.w[r as usize] = [0; LANES];
    }
    let mut exits = Exits::default();
    nodes(s, code, st, &code.body, lanes, &mut exits, io);
    lanes & !exits.discarded
}

/// A compiled program: the interpreter of fused lane operations (see the module docs).
#[derive(Clone, Debug)]
pub struct Compiled {
    /// The last specialisation ([`Compiled::specialize`]) and the uniforms it was made for.
    specialized: LastSpecialization,
    code: Code,
    /// The uniform prologue and the rest ([`split_prologue`]), for runs that share
    /// their uniforms ([`Compiled::prepare`]).
    prologue: Vec<Op>,
    rest: Code,
    /// `code` and `rest` as the control tree runs them: grouped ([`super::group`]; the
    /// bound forms are made from `rest`, whose single operations their fusions look for).
    run_code: Code,
    run_rest: Code,
}

/// A program specialised on a draw's uniform values ([`Compiled::specialize`]).
#[derive(Debug)]
pub struct Specialization {
    /// The registers whose values the uniforms decide, and those values.
    known: Vec<(R, Word)>,
    /// The code left per block, grouped.
    run: Code,
}

impl Specialization {
    /// The code run per block (for tests and diagnostics).
    pub fn run_code(&self) -> &Code {
        &self.run
    }
}

/// [`Compiled`]'s last specialisation: shared by the program's clones, empty in a clone.
#[derive(Default, Debug)]
#[allow(clippy::type_complexity)]
struct LastSpecialization(Mutex<Option<(Vec<u32>, Arc<Specialization>)>>);

impl Clone for LastSpecialization {
    fn clone(&self) -> Self {
        LastSpecialization::default()
    }
}

struct Interpreter;

impl Straight for Interpreter {
    #[inline(always)]
    fn run(&self, code: &Code, st: &mut Registers, io: &mut Io<'_>, start: u32, end: u32) {
        let ops = &code.ops[start as usize..end as usize];
        let wide = &code.wide[..];
        // No SSE4.1 copy (that level runs SSE2's): each copy of the op loop is about 17 KB of
        // each library, and issue #18's 5 MB limit is close.
        crate::simd::per_level!(sse2_for_sse41, |_level| {
            for op in ops {
                step::<true>(op, st, io, wide);
            }
        })
    }
}

impl Compiled {
    /// Compiles `program`, which [`super::validate::validate`] accepted.
    pub fn new(program: &Program) -> Compiled {
        let code = lower(&super::flatten::flatten(program));
        let (prologue, rest) = split_prologue(&code);
        let (run_code, run_rest) = (super::group::group(&code), super::group::group(&rest));
        Compiled { specialized: LastSpecialization::default(), code, prologue, rest, run_code, run_rest }
    }

    /// The program specialised on the uniform words `uniforms` ([`super::specialize`]):
    /// for [`Compiled::prepare_specialized`] and [`Compiled::run_specialized`]. The last one
    /// made is kept: a frame's draws with the same uniforms make it once.
    pub fn specialize(&self, uniforms: &[u32]) -> Arc<Specialization> {
        let mut last = self.specialized.0.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((words, made)) = last.as_ref() {
            if words[..] == *uniforms {
                return made.clone();
            }
        }
        // Words the uniforms lack read 0 (as nowhere in a real draw: its words cover the slots).
        let slots = self.prologue.iter().chain(&self.rest.ops).fold(0, |n, op| match *op {
            Op::SUniform { slot, .. } | Op::Uniform { slot, .. } => n.max(slot as usize + 1),
            _ => n,
        });
        let mut words = uniforms.to_vec();
        words.resize(words.len().max(slots), 0);
        let made = super::specialize::specialize(&self.prologue, &self.rest, &words, &mut run_prologue);
        let made = Arc::new(Specialization { known: made.known, run: super::group::group(&made.code) });
        *last = Some((uniforms.to_vec(), made.clone()));
        made
    }

    /// Writes the uniform values of `specialization` (of this program) into `registers`:
    /// [`Compiled::prepare`] for [`Compiled::run_specialized`].
    pub fn prepare_specialized(&self, specialization: &Specialization, registers: &mut Registers) {
        registers.w.resize(self.rest.registers.max(FILE), [0; LANES]);
        for (r, word) in &specialization.known {
            registers.w[*r as usize] = *word;
        }
    }

    /// [`Compiled::run_prepared`] of the specialised program (the same results): `registers`
    /// prepared by [`Compiled::prepare_specialized`] with `specialization`, made for
    /// `io.uniforms`, and unused by any other program since.
    pub fn run_specialized(
        &self,
        specialization: &Specialization,
        registers: &mut Registers,
        io: &mut Io<'_>,
        lanes: u16,
    ) -> u16 {
        run_tree(&Interpreter, &specialization.run, registers, io, lanes)
    }

    /// The pre-decoded form (for tests and diagnostics).
    pub fn code(&self) -> &Code {
        &self.code
    }

    /// The pre-decoded form after the prologue, as [`Compiled::run_prepared`] runs it,
    /// grouped (for tests and diagnostics).
    pub fn prepared_code(&self) -> &Code {
        &self.run_rest
    }

    /// The pre-decoded form as [`Compiled::run`] runs it, grouped (for tests and diagnostics).
    pub fn run_code(&self) -> &Code {
        &self.run_code
    }

    /// Runs the program in the lanes of `lanes`, as [`exec::Executor::run`] does (the same
    /// outputs, lookups and result); returns the lanes that did not discard. Never inlined:
    /// its runs have their own per-level copies, which every caller's per-level body would
    /// otherwise copy again.
    #[inline(never)]
    pub fn run(&self, registers: &mut Registers, io: &mut Io<'_>, lanes: u16) -> u16 {
        run_tree(&Interpreter, &self.run_code, registers, io, lanes)
    }

    /// Computes the program's uniform values (its scalar operations on uniforms and
    /// constants alone) into `registers`, for [`Compiled::run_prepared`] calls with the same
    /// `uniforms` and registers: a draw's vertex batches compute them once, not per batch.
    pub fn prepare(&self, registers: &mut Registers, uniforms: &[u32]) {
        registers.w.resize(self.rest.registers.max(FILE), [0; LANES]);
        run_prologue(&self.prologue, registers, uniforms, &self.rest.wide);
    }

    /// [`Compiled::run`] after [`Compiled::prepare`] (the same results): `registers` must be
    /// the prepared ones, unused by any other program since, and `io.uniforms` the same.
    pub fn run_prepared(&self, registers: &mut Registers, io: &mut Io<'_>, lanes: u16) -> u16 {
        run_tree(&Interpreter, &self.run_rest, registers, io, lanes)
    }
}

/// A program without control flow, texture lookups or derivatives whose inputs and outputs
/// are bound to registers, run as one unmasked run of operations (the vertex stage's form;
/// [`Bound`] is the fragment pipeline's, more general one: masked runs and texture lookups,
/// with its own fused operations; the two are to become one) ([`Compiled::bind_run`]): its caller writes the input values straight
/// into the register file and reads the outputs from it, with no staging words and no
/// operations copying them in and out (a draw's vertex batches: [`crate::vertex`]).
#[derive(Clone, Debug)]
pub struct BoundRun {
    /// Per input slot, the register that holds its value (`None`: nothing reads it).
    pub inputs: Vec<Option<R>>,
    /// Per output slot, the register that holds its value after [`Compiled::run_bound_run`].
    pub outputs: Vec<R>,
    /// The operations of the program after the prologue, without its inputs and outputs.
    ops: Vec<Op>,
}

impl Registers {
    /// The register file (a bound program's outputs: [`BoundRun::outputs`]).
    pub fn words(&self) -> &[Word] {
        &self.w
    }

    /// Makes the file `n` words long.
    pub(super) fn words_resize(&mut self, n: usize) {
        self.w.resize(n, [0; LANES]);
    }

    /// The register file, for a bound program's inputs ([`BoundRun::inputs`]).
    pub fn words_mut(&mut self) -> &mut [Word] {
        &mut self.w
    }
}

impl Compiled {
    /// The program's inputs and outputs bound to registers, when its code after the
    /// prologue is one unmasked run of operations without texture lookups or derivatives,
    /// every input register is written by its input alone and read after it only (never
    /// zeroed), every output slot is written once, and its register is not written after
    /// that. Then [`Compiled::run_bound_run`], the inputs written into `inputs`' registers before
    /// and the outputs read from `outputs`' after, gives [`Compiled::run_prepared`]'s
    /// outputs: with one run, every write is unmasked, and an input or output is a copy.
    pub fn bind_run(&self, input_slots: usize, output_slots: usize) -> Option<BoundRun> {
        let rest = &self.rest;
        let ops = match rest.body.as_slice() {
            [] => &[][..],
            [Node::Run { start, end, masked: false }] => &rest.ops[*start as usize..*end as usize],
            _ => return None,
        };
        if !rest.zeroed.is_empty() {
            return None;
        }
        let mut writes = vec![0u32; rest.registers];
        for op in ops {
            let (d, n) = op_writes(op, &rest.wide);
            for &r in &d[..n] {
                writes[r as usize] += 1;
            }
        }
        let mut inputs = vec![None; input_slots];
        let mut outputs = vec![None; output_slots];
        let mut kept = Vec::with_capacity(ops.len());
        for (i, op) in ops.iter().enumerate() {
            match *op {
                Op::Input { d, slot } => {
                    let input = inputs.get_mut(slot as usize)?;
                    if writes[d as usize] != 1 || input.is_some() {
                        return None;
                    }
                    *input = Some(d);
                }
                Op::Output { slot, a } => {
                    let written_later = ops[i + 1..].iter().any(|later| {
                        let (d, n) = op_writes(later, &rest.wide);
                        d[..n].contains(&a)
                    });
                    let output = outputs.get_mut(slot as usize)?;
                    if written_later || output.is_some() {
                        return None;
                    }
                    *output = Some(a);
                }
                Op::Texture(_) | Op::Derivative { .. } => return None,
                other => kept.push(other),
            }
        }
        let outputs = outputs.into_iter().collect::<Option<Vec<R>>>()?;
        Some(BoundRun { inputs, outputs, ops: kept })
    }

    /// Runs the bound program `bound` ([`Compiled::bind_run`] of this program) in the lanes of
    /// `lanes`, after [`Compiled::prepare`] with `uniforms` on `registers`, whose input
    /// registers the caller has filled.
    pub fn run_bound_run(&self, bound: &BoundRun, registers: &mut Registers, uniforms: &[u32], lanes: u16) {
        let st = registers;
        st.exec = lanes;
        st.mask = lane_mask(lanes);
        st.masked = false;
        let mut io = Io { inputs: &[], uniforms, outputs: &mut [], textures: &exec::NoTextures };
        let (ops, wide) = (&bound.ops[..], &self.rest.wide[..]);
        // No SSE4.1 copy, as `Interpreter::run`.
        crate::simd::per_level!(sse2_for_sse41, |_level| {
            for op in ops {
                step::<false>(op, st, &mut io, wide);
            }
        })
    }
}

/// The closure-threaded design, kept for the comparison of the module docs (and built for
/// the tests only): the same front end, one boxed closure per operation.
#[cfg(test)]
pub struct Threaded {
    code: Code,
    thunks: Vec<Thunk>,
}

#[cfg(test)]
impl Straight for Vec<Thunk> {
    #[inline(always)]
    fn run(&self, code: &Code, st: &mut Registers, io: &mut Io<'_>, start: u32, end: u32) {
        for t in &self[start as usize..end as usize] {
            t(st, io, &code.wide);
        }
    }
}

#[cfg(test)]
impl Threaded {
    pub fn new(program: &Program) -> Threaded {
        let code = lower(program);
        let thunks = code.ops.iter().map(|&op| thunk(op)).collect();
        Threaded { code, thunks }
    }

    pub fn run(&self, registers: &mut Registers, io: &mut Io<'_>, lanes: u16) -> u16 {
        run_tree(&self.thunks, &self.code, registers, io, lanes)
    }
}

/// A program without control flow bound for a caller that runs it on many blocks with the
/// same uniforms and hands its inputs and takes its outputs in place: the fragment pipeline
/// ([`crate::fragment`]'s shading). [`Compiled::bind`] makes it from the prepared form
/// ([`split_prologue`]): the `Input` operations are gone (the caller writes each input's
/// register, [`Bound::input`]), and so are the `Output` operations (the caller reads each
/// output's register, [`Bound::output`]); the runs are a flat list, executed without the
/// control tree.
///
/// The results in the running lanes are [`Compiled::run`]'s. An input's register holds the
/// caller's value in every lane, where the reference has it only in the running lanes (and
/// zero or an older value elsewhere), and an output's register holds the value in the
/// running lanes (the caller keeps those); so a caller must run every lane a running lane's
/// result may read across lanes (a derivative's or an implicit-LOD lookup's 2×2 quad) — the
/// fragment pipeline runs whole quads.
#[derive(Clone, Debug)]
pub struct Bound {
    /// The uniform prologue ([`Compiled::prepare`]'s).
    prologue: Vec<Op>,
    /// The runs: (first op, end, masked).
    runs: Vec<(u32, u32, bool)>,
    ops: Vec<BOp>,
    wide: Vec<Wide>,
    registers: usize,
    /// The words zeroed per run (less the inputs').
    zeroed: Vec<R>,
    /// Each input slot's register (`None`: the program does not read it).
    inputs: Vec<Option<R>>,
    /// Each output slot's register (`None`: the program does not write it).
    outputs: Vec<Option<R>>,
    /// Whether a run reads the lane mask (a masked run, a texture lookup).
    needs_mask: bool,
}

impl Compiled {
    /// The bound form of the program (see [`Bound`]), if it has no control flow, reads each
    /// input once into a register nothing else writes, and writes each output once from a
    /// register nothing writes after.
    pub fn bind(&self) -> Option<Bound> {
        let rest = &self.rest;
        let mut written = vec![0u32; rest.registers];
        for op in &rest.ops {
            let (d, count) = op_writes(op, &rest.wide);
            for &r in &d[..count] {
                written[r as usize] += 1;
            }
        }
        let mut inputs: Vec<Option<R>> = Vec::new();
        let mut outputs: Vec<Option<R>> = Vec::new();
        let mut ops = Vec::with_capacity(rest.ops.len());
        let mut runs: Vec<(u32, u32, bool)> = Vec::new();
        let mut last_write = vec![0usize; rest.registers];
        for (k, op) in rest.ops.iter().enumerate() {
            let (d, count) = op_writes(op, &rest.wide);
            for &r in &d[..count] {
                last_write[r as usize] = k;
            }
        }
        for node in &rest.body {
            let &Node::Run { start, end, masked } = node else { return None };
            let begin = ops.len() as u32;
            for (k, op) in rest.ops[start as usize..end as usize].iter().enumerate() {
                let k = start as usize + k;
                match *op {
                    Op::Input { d, slot } => {
                        let slot = slot as usize;
                        if written[d as usize] != 1 {
                            return None;
                        }
                        if inputs.len() <= slot {
                            inputs.resize(slot + 1, None);
                        }
                        if inputs[slot].replace(d).is_some() {
                            return None;
                        }
                    }
                    Op::Output { slot, a } => {
                        let slot = slot as usize;
                        if last_write[a as usize] > k && written[a as usize] > 0 {
                            return None;
                        }
                        if outputs.len() <= slot {
                            outputs.resize(slot + 1, None);
                        }
                        if outputs[slot].replace(a).is_some() {
                            return None;
                        }
                    }
                    _ => ops.push(*op),
                }
            }
            let end = ops.len() as u32;
            match runs.last_mut() {
                _ if begin == end => {}
                Some(last) if last.2 == masked && last.1 == begin => last.1 = end,
                _ => runs.push((begin, end, masked)),
            }
        }
        // An input read before its `Input` (a zeroed register) keeps the general path.
        let input_regs: Vec<R> = inputs.iter().flatten().copied().collect();
        let zeroed: Vec<R> = rest.zeroed.iter().copied().filter(|r| !input_regs.contains(r)).collect();
        if rest.zeroed.iter().any(|r| input_regs.contains(r)) {
            // Only pinned inputs (texture coordinates) are zeroed and written before any
            // read; any other zeroed input may be read before its write.
            for &r in input_regs.iter().filter(|r| rest.zeroed.contains(r)) {
                let first_read = rest.ops.iter().position(|op| op_reads(op, &rest.wide).contains(&r));
                let write = rest.ops.iter().position(|op| matches!(*op, Op::Input { d, .. } if d == r));
                if first_read.is_some_and(|read| write.is_none_or(|w| read < w)) {
                    return None;
                }
            }
        }
        let outputs_read: Vec<R> = outputs.iter().flatten().copied().collect();
        let (ops, runs) = fuse(&ops, &runs, &rest.wide, &outputs_read);
        let needs_mask = runs.iter().any(|r| r.2) || ops.iter().any(|op| matches!(op, BOp::Op(Op::Texture(_))));
        Some(Bound {
            needs_mask,
            prologue: self.prologue.clone(),
            runs,
            ops,
            wide: rest.wide.clone(),
            registers: rest.registers,
            zeroed,
            inputs,
            outputs,
        })
    }
}

/// One matcher of the registers an operation reads (through `wide` for the wide
/// operations), in a fixed order, for both forms: [`op_reads`] lists them and
/// [`reads_mut`] lets a pass rewrite them in place (`mut` as the last argument).
macro_rules! visit_reads {
    ($op:expr, $wide:expr, $f:expr $(, $m:tt)?) => {{
        let f = $f;
        match $op {
            Op::SConst { .. } | Op::SUniform { .. } | Op::Const { .. } | Op::Uniform { .. } | Op::Input { .. } => {}
            Op::SMov { a, .. }
            | Op::SUnary { a, .. }
            | Op::Mov { a, .. }
            | Op::Sqrt { a, .. }
            | Op::Rsq { a, .. }
            | Op::Unary { a, .. }
            | Op::Derivative { a, .. }
            | Op::Exp2 { a, .. }
            | Op::Log2 { a, .. }
            | Op::Output { a, .. } => f(a),
            Op::SBinary { a, b, .. }
            | Op::Add { a, b, .. }
            | Op::Sub { a, b, .. }
            | Op::Mul { a, b, .. }
            | Op::Div { a, b, .. }
            | Op::Min { a, b, .. }
            | Op::Max { a, b, .. }
            | Op::Lt { a, b, .. }
            | Op::Le { a, b, .. }
            | Op::Binary { a, b, .. }
            | Op::Pow { a, b, .. } => {
                f(a);
                f(b);
            }
            Op::SMad { a, b, c, .. } | Op::Mad { a, b, c, .. } | Op::SSelect { c, a, b, .. } | Op::Select { c, a, b, .. } => {
                f(a);
                f(b);
                f(c);
            }
            Op::Clamp { a, lo, hi, .. } | Op::ClampSelect { a, lo, hi, .. } => {
                f(a);
                f(lo);
                f(hi);
            }
            Op::SDot { n, a, b, .. } => {
                let n = *n as usize;
                for r in &$($m)? a[..n] {
                    f(r);
                }
                for r in &$($m)? b[..n] {
                    f(r);
                }
            }
            Op::Dot2 { a, b, .. } => {
                for r in &$($m)? a[..] {
                    f(r);
                }
                for r in &$($m)? b[..] {
                    f(r);
                }
            }
            Op::Dot3 { a, b, .. } => {
                for r in &$($m)? a[..] {
                    f(r);
                }
                for r in &$($m)? b[..] {
                    f(r);
                }
            }
            Op::Dot4 { a, b, .. } => {
                for r in &$($m)? a[..] {
                    f(r);
                }
                for r in &$($m)? b[..] {
                    f(r);
                }
            }
            Op::Normalize3 { a, .. } => {
                for r in &$($m)? a[..] {
                    f(r);
                }
            }
            Op::MatRow { m, v, .. } => {
                for r in &$($m)? m[..] {
                    f(r);
                }
                for r in &$($m)? v[..] {
                    f(r);
                }
            }
            Op::MatVec(i) | Op::Texture(i) | Op::Group(i) => match &$($m)? $wide[*i as usize] {
                Wide::Group { kind, n, a, b, c, .. } => {
                    let n = *n as usize;
                    for r in &$($m)? a[..n] {
                        f(r);
                    }
                    for r in &$($m)? b[..n] {
                        f(r);
                    }
                    if *kind == GroupKind::Select {
                        for r in &$($m)? c[..n] {
                            f(r);
                        }
                    }
                }
                Wide::MatVec { n, rows_n, rows, v, .. } => {
                    let n = *n as usize;
                    for row in &$($m)? rows[..*rows_n as usize] {
                        for r in &$($m)? row[..n] {
                            f(r);
                        }
                    }
                    for r in &$($m)? v[..n] {
                        f(r);
                    }
                }
                Wide::Sample { coords, lod, compare, .. } => {
                    for r in &$($m)? coords[..] {
                        f(r);
                    }
                    if let WideLod::Bias(r) | WideLod::Explicit(r) = lod {
                        f(r);
                    }
                    if let Some(r) = compare {
                        f(r);
                    }
                }
                Wide::Fetch { coords, lod, .. } => {
                    for r in &$($m)? coords[..] {
                        f(r);
                    }
                    f(lod);
                }
                Wide::Size { lod, .. } => f(lod),
            },
        }
    }};
}

/// The registers an operation reads (for [`Compiled::bind`]'s checks).
fn op_reads(op: &Op, wide: &[Wide]) -> Vec<R> {
    let mut list = Vec::new();
    visit_reads!(op, wide, &mut |r: &R| list.push(*r));
    list
}

/// Calls `f` on each register `op` reads (through `wide` for the wide operations), to
/// rewrite it in place.
pub(super) fn reads_mut(op: &mut Op, wide: &mut [Wide], f: &mut dyn FnMut(&mut R)) {
    visit_reads!(op, wide, f, mut)
}

impl Bound {
    /// Computes the uniform values into `registers` ([`Compiled::prepare`]): once for
    /// [`Bound::run`]s with the same uniforms and registers.
    pub fn prepare(&self, registers: &mut Registers, uniforms: &[u32]) {
        // At least a [`View`]'s words.
        registers.w.resize(self.registers.max(FILE), [0; LANES]);
        run_prologue(&self.prologue, registers, uniforms, &self.wide);
    }

    /// How many of each fused operation the bound form holds: [`BOp::MulClamp`],
    /// [`BOp::Ramp`], [`BOp::Mix3`] (for tests and diagnostics).
    pub fn fused(&self) -> [usize; 3] {
        let count = |f: fn(&BOp) -> bool| self.ops.iter().filter(|op| f(op)).count();
        [
            count(|op| matches!(op, BOp::MulClamp { .. })),
            count(|op| matches!(op, BOp::Ramp { .. })),
            count(|op| matches!(op, BOp::Mix3 { .. })),
        ]
    }

    /// Whether the program reads input `slot`.
    pub fn reads_input(&self, slot: usize) -> bool {
        matches!(self.inputs.get(slot), Some(Some(_)))
    }

    /// The register of input `slot` (`None`: not read).
    pub fn input_register(&self, slot: usize) -> Option<R> {
        self.inputs.get(slot).copied().flatten()
    }

    /// The register holding output `slot` after a run (`None`: not written).
    pub fn output_register(&self, slot: usize) -> Option<R> {
        self.outputs.get(slot).copied().flatten()
    }

    /// Whether an operation of the run reads register `r` (not counting outputs).
    pub fn reads_register(&self, r: R) -> bool {
        self.ops.iter().any(|op| match op {
            BOp::Op(op) => op_reads(op, &self.wide).contains(&r),
            BOp::MulClamp { a, b, lo, hi, .. } => [*a, *b, *lo, *hi].contains(&r),
            BOp::Mix3 { f, g, a, b, .. } => [*f, *g].iter().chain(a).chain(b).any(|&x| x == r),
            BOp::Ramp { c, e, s, lo, hi, one, f, .. } => [*c, *e, *s, *lo, *hi, *one, *f].contains(&r),
        })
    }

    /// The register of input `slot`, to write before a run (`None`: not read).
    #[inline(always)]
    pub fn input<'r>(&self, registers: &'r mut Registers, slot: usize) -> Option<&'r mut Word> {
        match self.inputs.get(slot) {
            Some(&Some(r)) => Some(&mut registers.w[r as usize]),
            _ => None,
        }
    }

    /// The register holding output `slot` after a run (in its running lanes).
    #[inline(always)]
    pub fn output<'r>(&self, registers: &'r Registers, slot: usize) -> Option<&'r Word> {
        match self.outputs.get(slot) {
            Some(&Some(r)) => Some(&registers.w[r as usize]),
            _ => None,
        }
    }

    /// Runs the program in the lanes `lanes` of `registers` (prepared by
    /// [`Bound::prepare`], inputs written); `io`'s inputs and outputs are not used. One copy
    /// per SIMD level. The fragment pipeline calls [`Bound::run_inline`] from its shading
    /// copy, which is itself one per level (inlined into each of the pipeline's per-level
    /// bodies instead, the interpreter's match made the libraries 1.5 MB larger).
    pub fn run(&self, registers: &mut Registers, io: &mut Io<'_>, lanes: u16) {
        crate::simd::per_level!(self.run_inline(registers, io, lanes))
    }

    /// [`Bound::run`] inlined into a caller that is itself compiled once per SIMD level
    /// (the fragment pipeline's one shading copy per level): no second dispatch per block.
    #[inline(always)]
    pub fn run_inline(&self, registers: &mut Registers, io: &mut Io<'_>, lanes: u16) {
        for &r in &self.zeroed {
            registers.w[r as usize] = [0; LANES];
        }
        registers.exec = lanes;
        if self.needs_mask {
            registers.mask = lane_mask(lanes);
        }
        let wide = &self.wide[..];
        for &(start, end, masked) in &self.runs {
            registers.masked = masked;
            for op in &self.ops[start as usize..end as usize] {
                match op {
                    BOp::Op(op) => step::<false>(op, registers, io, wide),
                    BOp::MulClamp { d, a, b, lo, hi } => {
                        let mut st = registers.view();
                        let (a, b, lo, hi) = (st.get(*a), st.get(*b), st.get(*lo), st.get(*hi));
                        let mut v = [0u32; LANES];
                        for i in 0..LANES {
                            v[i] = clamp_select_lane(fu(f(a[i]) * f(b[i])), lo[i], hi[i]);
                        }
                        st.put(*d, &v);
                    }
                    BOp::Mix3 { d, f: x, g: y, a, b } => {
                        let mut st = registers.view();
                        for k in 0..3 {
                            let v = dot2(st.get(*x), st.get(*y), st.get(a[k]), st.get(b[k]));
                            st.put(d[k], &v);
                        }
                    }
                    BOp::Ramp { f: fr, g, c, e, s, lo, hi, one } => {
                        let mut st = registers.view();
                        let (c, e, s, lo, hi) = (st.get(*c), st.get(*e), st.get(*s), st.get(*lo), st.get(*hi));
                        let mut v = [0u32; LANES];
                        for i in 0..LANES {
                            v[i] = clamp_select_lane(fu((f(e[i]) - f(c[i])) / f(s[i])), lo[i], hi[i]);
                        }
                        let w = map2(st.get(*one), &v, |x, y| fu(f(x) - f(y)));
                        st.put(*fr, &v);
                        st.put(*g, &w);
                    }
                }
            }
        }
    }
}

/// How many words of the register file a [`Bound`] run's fused operations see as an array
/// ([`View`]); [`fuse`] fuses only operations whose registers are below it.
pub(super) const FILE: usize = 256;

/// The first [`FILE`] words of a register file as an array, with the run's mask: a
/// register number below [`FILE`] indexes it with no bounds check (a fused operation's
/// five to fifteen checked reads and writes were a third of a fog program's run).
struct View<'a> {
    w: &'a mut [Word; FILE],
    mask: &'a Word,
    masked: bool,
}

impl View<'_> {
    #[inline(always)]
    fn get(&self, r: R) -> &Word {
        &self.w[usize::from(r as u8)]
    }

    #[inline(always)]
    fn put(&mut self, d: R, v: &Word) {
        let dst = &mut self.w[usize::from(d as u8)];
        if !self.masked {
            *dst = *v;
        } else {
            for i in 0..LANES {
                dst[i] = (v[i] & self.mask[i]) | (dst[i] & !self.mask[i]);
            }
        }
    }
}

impl Registers {
    /// The file as a [`View`] (at least [`FILE`] words: [`Bound::prepare`] makes it so).
    #[inline(always)]
    fn view(&mut self) -> View<'_> {
        let Registers { w, mask, masked, .. } = self;
        let w: &mut [Word; FILE] = (&mut w[..FILE]).try_into().expect("a prepared register file");
        View { w, mask, masked: *masked }
    }
}

/// `l < x ? min(x, h) : l` as [`Op::ClampSelect`] computes it.
#[inline(always)]
fn clamp_select_lane(x: u32, l: u32, h: u32) -> u32 {
    if f(l) < f(x) {
        if f(h) < f(x) {
            h
        } else {
            x
        }
    } else {
        l
    }
}

/// An operation of a [`Bound`] program: the executor's, or a fused operation for a hot
/// pattern of the fixed-function fragment programs ([`fuse`]). Each performs exactly the
/// operations, in the order and with the roundings, of the operations it replaces, whose
/// intermediate registers nothing else reads.
#[derive(Clone, Copy, Debug, PartialEq)]
enum BOp {
    Op(Op),
    /// `t = a·b; d = clamp_select(t, lo, hi)`: a texture environment's product and GL's
    /// clamp of the colour.
    MulClamp {
        d: R,
        a: R,
        b: R,
        lo: R,
        hi: R,
    },
    /// `d[k] = dot2((f, g), (a[k], b[k]))` for k = 0, 1, 2 in order: fog's blend of three
    /// channels (and any three products sharing their weights).
    Mix3 {
        d: [R; 3],
        f: R,
        g: R,
        a: [R; 3],
        b: [R; 3],
    },
    /// `t = e − c; u = t / s; f = clamp_select(u, lo, hi); g = one − f`: linear fog's factor
    /// and its complement.
    Ramp {
        f: R,
        g: R,
        c: R,
        e: R,
        s: R,
        lo: R,
        hi: R,
        one: R,
    },
}

/// The registers a [`BOp`] writes.
fn bop_writes(op: &BOp, wide: &[Wide]) -> Vec<R> {
    match *op {
        BOp::Op(ref op) => {
            let (w, n) = op_writes(op, wide);
            w[..n].to_vec()
        }
        BOp::MulClamp { d, .. } => vec![d],
        BOp::Mix3 { d, .. } => d.to_vec(),
        BOp::Ramp { f, g, .. } => vec![f, g],
    }
}

/// Fuses the hot patterns of `ops` (run by run: `runs` are (start, end, masked)) into
/// [`BOp`]s. `outputs` are registers the caller reads after the run. An intermediate is
/// elided only if the fused operation is its one read.
fn fuse(ops: &[Op], runs: &[(u32, u32, bool)], wide: &[Wide], outputs: &[R]) -> (Vec<BOp>, Vec<(u32, u32, bool)>) {
    let registers = ops
        .iter()
        .flat_map(|op| {
            let (d, n) = op_writes(op, wide);
            d.into_iter().take(n).chain(op_reads(op, wide))
        })
        .chain(outputs.iter().copied())
        .map(|r| r as usize + 1)
        .max()
        .unwrap_or(0);
    let mut reads = vec![0u32; registers];
    for op in ops {
        for r in op_reads(op, wide) {
            reads[r as usize] += 1;
        }
    }
    for &r in outputs {
        reads[r as usize] += 1;
    }
    let temporary = |r: R| reads[r as usize] == 1;
    // A fused operation indexes a [`View`]: its registers must be below [`FILE`].
    let small = |rs: &[R]| rs.iter().all(|&r| (r as usize) < FILE);
    let mut out = Vec::with_capacity(ops.len());
    let mut out_runs = Vec::with_capacity(runs.len());
    for &(start, end, masked) in runs {
        let begin = out.len() as u32;
        let mut run = ops[start as usize..end as usize].iter().map(|&op| Some(BOp::Op(op))).collect::<Vec<_>>();
        // A product whose one read is a later clamp moves to the clamp (the operations
        // between write neither its operands nor its result).
        for j in 0..run.len() {
            let Some(BOp::Op(Op::ClampSelect { d, a: t, lo, hi })) = run[j] else { continue };
            if !temporary(t) || t == lo || t == hi {
                continue;
            }
            let writer = (0..j).rev().find(|&i| run[i].is_some_and(|op| bop_writes(&op, wide).contains(&t)));
            let Some(i) = writer else { continue };
            let Some(BOp::Op(Op::Mul { d: t2, a, b })) = run[i] else { continue };
            let clobbered =
                run[i + 1..j].iter().flatten().any(|op| bop_writes(op, wide).iter().any(|r| [a, b, t].contains(r)));
            if t2 == t && !clobbered && small(&[d, a, b, lo, hi]) {
                run[i] = None;
                run[j] = Some(BOp::MulClamp { d, a, b, lo, hi });
            }
        }
        let run: Vec<BOp> = run.into_iter().flatten().collect();
        let run = &run[..];
        let mut k = 0;
        while k < run.len() {
            let rest = &run[k..];
            if let [BOp::Op(Op::Sub { d: t, a: e, b: c }), BOp::Op(Op::Div { d: u, a: t2, b: s }), BOp::Op(Op::ClampSelect { d: fr, a: u2, lo, hi }), BOp::Op(Op::Sub { d: g, a: one, b: f2 }), ..] =
                *rest
            {
                if t == t2
                    && u == u2
                    && f2 == fr
                    && t != u
                    && temporary(t)
                    && temporary(u)
                    && ![e, c, s].contains(&t)
                    && ![lo, hi].contains(&u)
                    && one != fr
                    && small(&[fr, g, c, e, s, lo, hi, one])
                {
                    out.push(BOp::Ramp { f: fr, g, c, e, s, lo, hi, one });
                    k += 4;
                    continue;
                }
            }
            if let [BOp::Op(Op::Dot2 { d: d0, a: w0, b: b0 }), BOp::Op(Op::Dot2 { d: d1, a: w1, b: b1 }), BOp::Op(Op::Dot2 { d: d2, a: w2, b: b2 }), ..] =
                *rest
            {
                // Each write before the next's reads, as in sequence: no later operand is an
                // earlier result.
                let later = |d: R, w: [R; 2], b: [R; 2]| w.contains(&d) || b.contains(&d);
                let registers = [d0, d1, d2, w0[0], w0[1], b0[0], b0[1], b1[0], b1[1], b2[0], b2[1]];
                if w0 == w1
                    && w1 == w2
                    && !later(d0, w1, b1)
                    && !later(d0, w2, b2)
                    && !later(d1, w2, b2)
                    && small(&registers)
                {
                    out.push(BOp::Mix3 {
                        d: [d0, d1, d2],
                        f: w0[0],
                        g: w0[1],
                        a: [b0[0], b1[0], b2[0]],
                        b: [b0[1], b1[1], b2[1]],
                    });
                    k += 3;
                    continue;
                }
            }
            out.push(rest[0]);
            k += 1;
        }
        out_runs.push((begin, out.len() as u32, masked));
    }
    (out, out_runs)
}
