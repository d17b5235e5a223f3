//! The executor: runs a validated program over 16 lanes (one vertex, or one pixel of a 4×4
//! block, per lane) with execution masks.
//!
//! Every register holds 16 words. An instruction computes all 16 lanes (branch-free loops
//! the compiler vectorises) and writes back only the running ones. Control flow keeps one
//! mask per nesting level: an `if` runs each side with the lanes that take it and skips a
//! side no lane takes, so a condition that is uniform over the block branches for real; a
//! loop runs while any lane is still in it; `break`, `continue`, `return` and `discard`
//! take the running lanes out until the end of their loop iteration, their loop, or the
//! program.
//!
//! Texture lookups go to the [`Textures`] of the run (the texture room's samplers, bound per
//! draw) once per block with the coordinates of every lane and the mask of the lanes that
//! want a result, so that a sampler works on whole 2×2 quads (their level of detail) and
//! may specialise per format.
//!
//! A loop runs at most [`MAX_LOOP_ITERATIONS`] iterations per entry; lanes still looping
//! then leave it as if by `break`. GLSL has no bound, but a shader must not hang the
//! process: this is tessera's documented limit (a real GPU's watchdog resets instead).
//!
//! The arithmetic is IEEE single precision rounded once per operation, never contracted
//! into fused multiply-adds, with [`super::math`] for the transcendental functions: the
//! same bits on every CPU and at every SIMD level.
use super::ir::{Axis, BinaryOp, Inst, Lod, Program, Reg, Stmt, UnaryOp};
use super::math;
use crate::gl::float::floor_f32;

/// Lanes per run: a 4×4 block of fragments or 16 vertices.
pub const LANES: usize = 16;
/// Every lane.
pub const ALL_LANES: u16 = 0xffff;
/// The iterations a loop may run per entry (see the module docs).
pub const MAX_LOOP_ITERATIONS: u32 = 1 << 16;

/// One register's, input's or output's value in every lane (f32 as its bits, bool 0 or 1).
pub type Word = [u32; LANES];

/// Runs programs; keeps the registers between runs so that a run allocates nothing.
#[derive(Default)]
pub struct Executor {
    registers: Vec<Word>,
}

/// Where the lanes that stopped running went, for the statements still to come.
#[derive(Default)]
struct Exits {
    /// Lanes that left the innermost loop by `break` (or its iteration bound).
    broke: u16,
    /// Lanes that ended the innermost loop's current iteration by `continue`.
    continued: u16,
    /// Lanes that discarded their fragment.
    discarded: u16,
}

#[inline(always)]
pub(super) fn map1(a: &Word, f: impl Fn(u32) -> u32) -> Word {
    let mut out = [0u32; LANES];
    for i in 0..LANES {
        out[i] = f(a[i]);
    }
    out
}

#[inline(always)]
pub(super) fn map2(a: &Word, b: &Word, f: impl Fn(u32, u32) -> u32) -> Word {
    let mut out = [0u32; LANES];
    for i in 0..LANES {
        out[i] = f(a[i], b[i]);
    }
    out
}

#[inline(always)]
pub(super) fn f(bits: u32) -> f32 {
    f32::from_bits(bits)
}

#[inline(always)]
pub(super) fn fu(value: f32) -> u32 {
    value.to_bits()
}

/// `FMin` on one lane (see [`BinaryOp::FMin`]): `y < x ? y : x`, and `y` when `x` is NaN.
/// Written as selects, never as a library minimum, so that every SIMD level gives the same
/// bits (±0 included).
#[inline(always)]
pub(super) fn fmin_lane(x: u32, y: u32) -> u32 {
    let (a, b) = (f(x), f(y));
    if b < a || a.is_nan() {
        y
    } else {
        x
    }
}

/// `FMax` on one lane: `x < y ? y : x`, and `y` when `x` is NaN.
#[inline(always)]
pub(super) fn fmax_lane(x: u32, y: u32) -> u32 {
    let (a, b) = (f(x), f(y));
    if a < b || a.is_nan() {
        y
    } else {
        x
    }
}

/// f32 → i32 truncating toward zero, saturating, NaN → 0 (Rust's `as`, the same on every
/// CPU).
#[inline(always)]
fn to_i32(v: f32) -> u32 {
    v as i32 as u32
}

/// The unary operation `op` on every lane of `a`.
pub(super) fn unary(op: UnaryOp, a: &Word) -> Word {
    use UnaryOp::*;
    match op {
        FNeg => map1(a, |x| x ^ 0x8000_0000),
        FAbs => map1(a, |x| x & 0x7fff_ffff),
        FSign => map1(a, |x| {
            let v = f(x);
            if v > 0.0 {
                fu(1.0)
            } else if v < 0.0 {
                fu(-1.0)
            } else {
                x // ±0 and NaN unchanged
            }
        }),
        Floor => map1(a, |x| fu(floor_f32(f(x)))),
        Ceil => map1(a, |x| fu(-floor_f32(-f(x)))),
        Trunc => map1(a, |x| {
            let v = f(x);
            if v.is_nan() || v.abs() >= (1 << 23) as f32 {
                x
            } else {
                fu((v as i32 as f32).copysign(v))
            }
        }),
        Fract => map1(a, |x| fu(f(x) - floor_f32(f(x)))),
        RoundEven => map1(a, |x| {
            let v = f(x);
            if v.is_nan() || v.abs() >= (1 << 23) as f32 {
                return x;
            }
            // Adding and subtracting 2²³ rounds to an integer in the current (nearest-even)
            // rounding mode, exactly, for |v| < 2²³.
            let big = (1 << 23) as f32;
            let r = if v >= 0.0 { (v + big) - big } else { (v - big) + big };
            fu(r.copysign(v))
        }),
        Sqrt => map1(a, |x| fu(f(x).sqrt())),
        Rcp => map1(a, |x| fu(1.0 / f(x))),
        Rsq => map1(a, |x| fu(1.0 / f(x).sqrt())),
        Exp2 => map1(a, |x| fu(math::exp2(f(x)))),
        Exp => map1(a, |x| fu(math::exp(f(x)))),
        Log2 => map1(a, |x| fu(math::log2(f(x)))),
        Sin => map1(a, |x| fu(math::sin(f(x)))),
        Cos => map1(a, |x| fu(math::cos(f(x)))),
        F32ToI32 => map1(a, |x| to_i32(f(x))),
        F32ToU32 => map1(a, |x| f(x) as u32),
        I32ToF32 => map1(a, |x| fu(x as i32 as f32)),
        U32ToF32 => map1(a, |x| fu(x as f32)),
        BoolToF32 => map1(a, |x| fu(x as f32)),
        F32ToBool => map1(a, |x| (f(x) != 0.0) as u32),
        INeg => map1(a, |x| (x as i32).wrapping_neg() as u32),
        IAbs => map1(a, |x| (x as i32).wrapping_abs() as u32),
        INot => map1(a, |x| !x),
        BNot => map1(a, |x| x ^ 1),
        Bitcast => *a,
    }
}

/// The binary operation `op` on every lane of `a` and `b`.
pub(super) fn binary(op: BinaryOp, a: &Word, b: &Word) -> Word {
    use BinaryOp::*;
    let int = |x: u32| x as i32;
    match op {
        FAdd => map2(a, b, |x, y| fu(f(x) + f(y))),
        FSub => map2(a, b, |x, y| fu(f(x) - f(y))),
        FMul => map2(a, b, |x, y| fu(f(x) * f(y))),
        FDiv => map2(a, b, |x, y| fu(f(x) / f(y))),
        FMin => map2(a, b, fmin_lane),
        FMax => map2(a, b, fmax_lane),
        FLt => map2(a, b, |x, y| (f(x) < f(y)) as u32),
        FLe => map2(a, b, |x, y| (f(x) <= f(y)) as u32),
        FEq => map2(a, b, |x, y| (f(x) == f(y)) as u32),
        FNe => map2(a, b, |x, y| (f(x) != f(y)) as u32),
        IAdd => map2(a, b, |x, y| x.wrapping_add(y)),
        ISub => map2(a, b, |x, y| x.wrapping_sub(y)),
        IMul => map2(a, b, |x, y| x.wrapping_mul(y)),
        IDiv => map2(a, b, |x, y| if y == 0 { 0 } else { int(x).wrapping_div(int(y)) as u32 }),
        IRem => map2(a, b, |x, y| if y == 0 { 0 } else { int(x).wrapping_rem(int(y)) as u32 }),
        IMin => map2(a, b, |x, y| int(x).min(int(y)) as u32),
        IMax => map2(a, b, |x, y| int(x).max(int(y)) as u32),
        UDiv => map2(a, b, |x, y| x.checked_div(y).unwrap_or(0)),
        URem => map2(a, b, |x, y| x.checked_rem(y).unwrap_or(0)),
        UMin => map2(a, b, |x, y| x.min(y)),
        UMax => map2(a, b, |x, y| x.max(y)),
        ILt => map2(a, b, |x, y| (int(x) < int(y)) as u32),
        ILe => map2(a, b, |x, y| (int(x) <= int(y)) as u32),
        ULt => map2(a, b, |x, y| (x < y) as u32),
        ULe => map2(a, b, |x, y| (x <= y) as u32),
        IEq | BEq => map2(a, b, |x, y| (x == y) as u32),
        INe => map2(a, b, |x, y| (x != y) as u32),
        And | BAnd => map2(a, b, |x, y| x & y),
        Or | BOr => map2(a, b, |x, y| x | y),
        Xor | BXor => map2(a, b, |x, y| x ^ y),
        Shl => map2(a, b, |x, y| x << (y & 31)),
        AShr => map2(a, b, |x, y| (int(x) >> (y & 31)) as u32),
        LShr => map2(a, b, |x, y| x >> (y & 31)),
    }
}

/// A lane's pixel in its 2×2 quad: the left column's and the upper row's lane.
#[inline(always)]
pub(super) fn derivative(axis: Axis, a: &Word) -> Word {
    let mut out = [0u32; LANES];
    for (i, o) in out.iter_mut().enumerate() {
        let (first, second) = match axis {
            Axis::X => (i & !1, i | 1),
            Axis::Y => (i & !4, i | 4),
        };
        *o = fu(f(a[second]) - f(a[first]));
    }
    out
}

/// The lanes of a bool word that are true.
#[inline(always)]
pub(super) fn true_lanes(w: &Word) -> u16 {
    let mut mask = 0u16;
    for (i, &v) in w.iter().enumerate() {
        mask |= ((v != 0) as u16) << i;
    }
    mask
}

/// The level of detail of one filtered lookup, per lane where it is given.
#[derive(Clone, Copy, Debug)]
pub enum LodLanes<'a> {
    Implicit,
    Bias(&'a Word),
    Explicit(&'a Word),
}

/// One filtered lookup of a block: the unit, the coordinates of every lane (helper lanes
/// included: the implicit level of detail is a per-quad difference), and the lanes that
/// want a result.
pub struct SampleRequest<'a> {
    pub unit: u8,
    pub n: u8,
    pub coords: &'a [Word; 4],
    pub projective: bool,
    pub lod: LodLanes<'a>,
    pub compare: Option<&'a Word>,
    pub lanes: u16,
}

/// The textures a program's lookups read: the texture room's samplers, bound per draw.
/// Each call fills the lanes of `lanes` (f32 bits; sizes as i32) and may leave the others.
pub trait Textures {
    fn sample(&self, request: &SampleRequest<'_>, out: &mut [Word; 4]);
    fn fetch(&self, unit: u8, n: u8, coords: &[Word; 3], lod: &Word, lanes: u16, out: &mut [Word; 4]);
    fn size(&self, unit: u8, lod: &Word, lanes: u16, out: &mut [Word; 3]);
}

/// For programs without texture lookups (the validator's program has none to ask for):
/// every lookup reads zero.
pub struct NoTextures;

impl Textures for NoTextures {
    fn sample(&self, _: &SampleRequest<'_>, out: &mut [Word; 4]) {
        *out = [[0; LANES]; 4];
    }

    fn fetch(&self, _: u8, _: u8, _: &[Word; 3], _: &Word, _: u16, out: &mut [Word; 4]) {
        *out = [[0; LANES]; 4];
    }

    fn size(&self, _: u8, _: &Word, _: u16, out: &mut [Word; 3]) {
        *out = [[0; LANES]; 3];
    }
}

/// The words of a run: per-lane inputs, uniforms and outputs, indexed by slot, and the
/// textures its lookups read.
pub struct Io<'a> {
    pub inputs: &'a [Word],
    pub uniforms: &'a [u32],
    pub outputs: &'a mut [Word],
    pub textures: &'a dyn Textures,
}

impl Executor {
    pub fn new() -> Executor {
        Executor::default()
    }

    /// Runs `program` (which [`super::validate::validate`] accepted; the slices of `io` as
    /// long as its slot lists) in the lanes of `lanes`; returns the lanes that did not
    /// discard. Registers start at zero in every run.
    pub fn run(&mut self, program: &Program, io: &mut Io<'_>, lanes: u16) -> u16 {
        self.registers.clear();
        self.registers.resize(program.registers.len(), [0; LANES]);
        let mut exits = Exits::default();
        self.block(&program.body, lanes, &mut exits, io);
        lanes & !exits.discarded
    }

    #[inline(always)]
    fn read(&self, r: Reg) -> &Word {
        &self.registers[r.0 as usize]
    }

    #[inline(always)]
    fn write(&mut self, r: Reg, value: Word, exec: u16) {
        let dst = &mut self.registers[r.0 as usize];
        if exec == ALL_LANES {
            *dst = value;
        } else {
            for (i, d) in dst.iter_mut().enumerate() {
                if exec >> i & 1 != 0 {
                    *d = value[i];
                }
            }
        }
    }

    fn inst(&mut self, inst: &Inst, exec: u16, io: &mut Io<'_>) {
        let value = match *inst {
            Inst::Const { value, .. } => [value.bits(); LANES],
            Inst::Input { slot, .. } => io.inputs[slot as usize],
            Inst::Uniform { slot, .. } => [io.uniforms[slot as usize]; LANES],
            Inst::Mov { src, .. } => *self.read(src),
            Inst::Unary { op, a, .. } => unary(op, self.read(a)),
            Inst::Binary { op, a, b, .. } => binary(op, self.read(a), self.read(b)),
            Inst::Mad { a, b, c, .. } => {
                let (a, b, c) = (self.read(a), self.read(b), self.read(c));
                std::array::from_fn(|i| fu(f(a[i]) * f(b[i]) + f(c[i])))
            }
            Inst::Dot { n, a, b, .. } => {
                let mut sum = map2(self.read(a[0]), self.read(b[0]), |x, y| fu(f(x) * f(y)));
                for k in 1..n as usize {
                    let (x, y) = (self.read(a[k]), self.read(b[k]));
                    for i in 0..LANES {
                        sum[i] = fu(f(sum[i]) + f(x[i]) * f(y[i]));
                    }
                }
                sum
            }
            Inst::Select { cond, a, b, .. } => {
                let (c, a, b) = (self.read(cond), self.read(a), self.read(b));
                std::array::from_fn(|i| if c[i] != 0 { a[i] } else { b[i] })
            }
            Inst::Derivative { axis, a, .. } => derivative(axis, self.read(a)),
            Inst::Sample { dst, unit, n, coords, projective, lod, compare } => {
                let words = coords.map(|r| *self.read(r));
                let lod = match lod {
                    Lod::Implicit => LodLanes::Implicit,
                    Lod::Bias(r) => LodLanes::Bias(self.read(r)),
                    Lod::Explicit(r) => LodLanes::Explicit(self.read(r)),
                };
                let compare = compare.map(|r| self.read(r));
                let request = SampleRequest { unit, n, coords: &words, projective, lod, compare, lanes: exec };
                let mut out = [[0; LANES]; 4];
                io.textures.sample(&request, &mut out);
                for (r, value) in dst.into_iter().zip(out) {
                    self.write(r, value, exec);
                }
                return;
            }
            Inst::Fetch { dst, unit, n, coords, lod } => {
                let words = coords.map(|r| *self.read(r));
                let mut out = [[0; LANES]; 4];
                io.textures.fetch(unit, n, &words, self.read(lod), exec, &mut out);
                for (r, value) in dst.into_iter().zip(out) {
                    self.write(r, value, exec);
                }
                return;
            }
            Inst::Size { dst, unit, lod } => {
                let mut out = [[0; LANES]; 3];
                io.textures.size(unit, self.read(lod), exec, &mut out);
                for (r, value) in dst.into_iter().zip(out) {
                    self.write(r, value, exec);
                }
                return;
            }
            Inst::Output { slot, src } => {
                let value = *self.read(src);
                let out = &mut io.outputs[slot as usize];
                for (i, o) in out.iter_mut().enumerate() {
                    if exec >> i & 1 != 0 {
                        *o = value[i];
                    }
                }
                return;
            }
        };
        if let Some(dst) = inst.dst() {
            self.write(dst, value, exec);
        }
    }

    /// Runs `stmts` in the lanes of `exec`; returns the lanes still running at the end.
    fn block(&mut self, stmts: &[Stmt], mut exec: u16, exits: &mut Exits, io: &mut Io<'_>) -> u16 {
        for stmt in stmts {
            if exec == 0 {
                break;
            }
            match stmt {
                Stmt::Inst(inst) => self.inst(inst, exec, io),
                Stmt::If { cond, then, otherwise } => {
                    let taken = exec & true_lanes(self.read(*cond));
                    let not_taken = exec & !taken;
                    let mut after = 0;
                    if taken != 0 {
                        after |= self.block(then, taken, exits, io);
                    }
                    if not_taken != 0 {
                        after |= self.block(otherwise, not_taken, exits, io);
                    }
                    exec = after;
                }
                Stmt::Loop { body } => {
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
                        looping = self.block(body, looping, exits, io) | exits.continued;
                    }
                    exec = exits.broke;
                    (exits.broke, exits.continued) = outer;
                }
                Stmt::Break => {
                    exits.broke |= exec;
                    exec = 0;
                }
                Stmt::Continue => {
                    exits.continued |= exec;
                    exec = 0;
                }
                Stmt::Return => exec = 0,
                Stmt::Discard => {
                    exits.discarded |= exec;
                    exec = 0;
                }
            }
        }
        exec
    }
}
