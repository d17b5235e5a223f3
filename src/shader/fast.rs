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
//! The arithmetic is [`super::lower`]'s lane functions and the reference's own word
//! functions: IEEE add, sub, mul, div and sqrt rounded once each, never contracted, and
//! [`super::math`]'s polynomials, so every level and every CPU gives the same bytes.
use super::exec::{self, f, fu, map1, map2, Io, LodLanes, SampleRequest, Word, LANES, MAX_LOOP_ITERATIONS};
use super::ir::{Axis, Program};
use super::lower::{
    binary_lane, dot_lane, lower, mad_lane, op_writes, split_prologue, unary_lane, Code, Cond, Node, Op, Wide, WideLod,
    R,
};

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

    #[inline(never)]
    fn texture(&mut self, io: &mut Io<'_>, wide: &Wide) {
        let exec = self.exec;
        match *wide {
            Wide::Sample { dst, unit, n, coords, projective, lod, compare } => {
                let words = coords.map(|r| *self.get(r));
                let lod = match lod {
                    WideLod::Implicit => LodLanes::Implicit,
                    WideLod::Bias(r) => LodLanes::Bias(self.get(r)),
                    WideLod::Explicit(r) => LodLanes::Explicit(self.get(r)),
                };
                let compare = compare.map(|r| self.get(r));
                let request = SampleRequest { unit, n, coords: &words, projective, lod, compare, lanes: exec };
                let mut out = [[0; LANES]; 4];
                io.textures.sample(&request, &mut out);
                for (r, value) in dst.into_iter().zip(&out) {
                    self.put_masked(r, value);
                }
            }
            Wide::Fetch { dst, unit, n, coords, lod } => {
                let words = coords.map(|r| *self.get(r));
                let mut out = [[0; LANES]; 4];
                io.textures.fetch(unit, n, &words, self.get(lod), exec, &mut out);
                for (r, value) in dst.into_iter().zip(&out) {
                    self.put_masked(r, value);
                }
            }
            Wide::Size { dst, unit, lod } => {
                let mut out = [[0; LANES]; 3];
                io.textures.size(unit, self.get(lod), exec, &mut out);
                for (r, value) in dst.into_iter().zip(&out) {
                    self.put_masked(r, value);
                }
            }
            Wide::MatVec { .. } => unreachable!("not a texture lookup"),
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
        #[inline(always)]
        fn step(op: &Op, $st: &mut Registers, $io: &mut Io<'_>, $wide: &[Wide]) {
            match *op {
                $( $pat => $body, )*
            }
        }

        /// An operation of the closure-threaded design.
        #[cfg(test)]
        type Thunk = Box<dyn Fn(&mut Registers, &mut Io<'_>, &[Wide]) + Send + Sync>;

        #[cfg(test)]
        fn thunk(op: Op) -> Thunk {
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
    Op::Min { d, a, b } => st.put(d, map2(st.get(a), st.get(b), |x, y| if f(y) < f(x) { y } else { x })),
    Op::Max { d, a, b } => st.put(d, map2(st.get(a), st.get(b), |x, y| if f(x) < f(y) { y } else { x })),
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
        map3(st.get(a), st.get(lo), st.get(hi), |x, l, h| {
            let t = if f(x) < f(l) { l } else { x };
            if f(h) < f(t) {
                h
            } else {
                t
            }
        }),
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

fn run_tree<S: Straight>(s: &S, code: &Code, st: &mut Registers, io: &mut Io<'_>, lanes: u16) -> u16 {
    st.w.resize(code.registers, [0; LANES]);
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
    code: Code,
    /// The uniform prologue and the rest ([`split_prologue`]), for runs that share
    /// their uniforms ([`Compiled::prepare`]).
    prologue: Vec<Op>,
    rest: Code,
}

struct Interpreter;

impl Straight for Interpreter {
    #[inline(always)]
    fn run(&self, code: &Code, st: &mut Registers, io: &mut Io<'_>, start: u32, end: u32) {
        let ops = &code.ops[start as usize..end as usize];
        let wide = &code.wide[..];
        crate::simd::per_level!({
            for op in ops {
                step(op, st, io, wide);
            }
        })
    }
}

impl Compiled {
    /// Compiles `program`, which [`super::validate::validate`] accepted.
    pub fn new(program: &Program) -> Compiled {
        let code = lower(program);
        let (prologue, rest) = split_prologue(&code);
        Compiled { code, prologue, rest }
    }

    /// The pre-decoded form (for tests and diagnostics).
    pub fn code(&self) -> &Code {
        &self.code
    }

    /// Runs the program in the lanes of `lanes`, as [`exec::Executor::run`] does (the same
    /// outputs, lookups and result); returns the lanes that did not discard.
    pub fn run(&self, registers: &mut Registers, io: &mut Io<'_>, lanes: u16) -> u16 {
        run_tree(&Interpreter, &self.code, registers, io, lanes)
    }

    /// Computes the program's uniform values (its scalar operations on uniforms and
    /// constants alone) into `registers`, for [`Compiled::run_prepared`] calls with the same
    /// `uniforms` and registers: a draw's vertex batches compute them once, not per batch.
    pub fn prepare(&self, registers: &mut Registers, uniforms: &[u32]) {
        registers.w.resize(self.rest.registers, [0; LANES]);
        let mut io = Io { inputs: &[], uniforms, outputs: &mut [], textures: &exec::NoTextures };
        for op in &self.prologue {
            step(op, registers, &mut io, &self.rest.wide);
        }
    }

    /// [`Compiled::run`] after [`Compiled::prepare`] (the same results): `registers` must be
    /// the prepared ones, unused by any other program since, and `io.uniforms` the same.
    pub fn run_prepared(&self, registers: &mut Registers, io: &mut Io<'_>, lanes: u16) -> u16 {
        run_tree(&Interpreter, &self.rest, registers, io, lanes)
    }
}

/// A program without control flow, texture lookups or derivatives whose inputs and outputs
/// are bound to registers ([`Compiled::bind`]): its caller writes the input values straight
/// into the register file and reads the outputs from it, with no staging words and no
/// operations copying them in and out (a draw's vertex batches: [`crate::vertex`]).
#[derive(Clone, Debug)]
pub struct Bound {
    /// Per input slot, the register that holds its value (`None`: nothing reads it).
    pub inputs: Vec<Option<R>>,
    /// Per output slot, the register that holds its value after [`Compiled::run_bound`].
    pub outputs: Vec<R>,
    /// The operations of the program after the prologue, without its inputs and outputs.
    ops: Vec<Op>,
}

impl Registers {
    /// The register file (a bound program's outputs: [`Bound::outputs`]).
    pub fn words(&self) -> &[Word] {
        &self.w
    }

    /// The register file, for a bound program's inputs ([`Bound::inputs`]).
    pub fn words_mut(&mut self) -> &mut [Word] {
        &mut self.w
    }
}

impl Compiled {
    /// The program's inputs and outputs bound to registers, when its code after the
    /// prologue is one unmasked run of operations without texture lookups or derivatives,
    /// every input register is written by its input alone and read after it only (never
    /// zeroed), every output slot is written once, and its register is not written after
    /// that. Then [`Compiled::run_bound`], the inputs written into `inputs`' registers before
    /// and the outputs read from `outputs`' after, gives [`Compiled::run_prepared`]'s
    /// outputs: with one run, every write is unmasked, and an input or output is a copy.
    pub fn bind(&self, input_slots: usize, output_slots: usize) -> Option<Bound> {
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
        Some(Bound { inputs, outputs, ops: kept })
    }

    /// Runs the bound program `bound` ([`Compiled::bind`] of this program) in the lanes of
    /// `lanes`, after [`Compiled::prepare`] with `uniforms` on `registers`, whose input
    /// registers the caller has filled.
    pub fn run_bound(&self, bound: &Bound, registers: &mut Registers, uniforms: &[u32], lanes: u16) {
        let st = registers;
        st.exec = lanes;
        st.mask = lane_mask(lanes);
        st.masked = false;
        let mut io = Io { inputs: &[], uniforms, outputs: &mut [], textures: &exec::NoTextures };
        let (ops, wide) = (&bound.ops[..], &self.rest.wide[..]);
        crate::simd::per_level!({
            for op in ops {
                step(op, st, &mut io, wide);
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
