//! The executor's front end: turns a validated [`Program`] into [`Code`], the pre-decoded
//! form [`super::fast`] runs. It decides, once per program, what the naive reference
//! ([`super::exec`]) decides again in every block:
//!
//! - **Constant folding.** An instruction at the top level whose operands are registers
//!   written once, earlier at the top level, by constants becomes a constant (computed here
//!   with the executor's own lane functions, so the bits are the same).
//! - **Dead code.** Instructions whose results nothing reads (no output, condition or texture
//!   lookup depends on them) are dropped. Texture lookups are kept: the sampler sees every
//!   request the reference makes.
//! - **Uniform values.** A register is *uniform* when every write to it computes a value
//!   that is the same in every lane (constants, uniforms, operations on uniform registers)
//!   and happens where every running lane runs it: outside any `if` whose condition is not
//!   uniform and outside any loop that lanes can leave at different iterations (a `break`
//!   or `continue` under such an `if`). Lanes that returned or discarded are gone for good,
//!   so they do not make later code divergent. A uniform register is computed once, as a
//!   scalar, and stored broadcast; an `if` on a uniform condition branches for real.
//! - **Unmasked writes.** In code every running lane runs, a write needs no mask: the lanes
//!   that are not running are gone and never read the register again. Registers whose lanes
//!   other lanes may read (derivative operands, texture coordinates: the sampler gets every
//!   lane for its per-quad level of detail) are *pinned*: always written under the mask and
//!   zeroed per run, so their every lane is what the reference holds.
//! - **Fused operations.** `max` then `min` of a single-use value is a clamp, and so is
//!   `lo < a ? min(a, hi) : lo` (colour clamping: a comparison, a minimum and a select of
//!   single-use values, as `shader::build`'s `clamp01` writes it); two single-use
//!   products and their sum (`a·b + c·e`: texture environments, fog) are a `dot2`; a `dot3` of a
//!   vector with itself, its `rsq` and the three products are one normalize; consecutive
//!   dot products with the same right-hand vector are one matrix·vector product. Each fused
//!   operation performs exactly the operations, in the order and with the roundings, of the
//!   instructions it replaces.
//! - **A uniform prologue.** [`split_prologue`] takes out of the top level the scalar
//!   operations that compute a value from uniforms and constants alone into a register
//!   nothing else writes: a caller that runs one program many times with the same uniforms
//!   (a draw's vertex batches) computes them once ([`super::fast::Compiled::prepare`]).
//! - **Compact registers.** Only registers something reads or writes get a word, numbered
//!   densely, and only those a read may reach before any write are zeroed per run. Words are
//!   not shared between registers with disjoint lifetimes: under divergent control flow a
//!   write keeps the other lanes' old value, so a write is not the end of a lifetime, and
//!   the files are small (phong: 73 registers, 64 words, 4 KiB, in L1) — not worth the risk.
use super::ir::{BinaryOp, Const, Inst, Lod, Program, Reg, Stmt, UnaryOp};
use crate::gl::float::floor_f32;

/// A register's index in the run's word file.
pub type R = u16;

/// A pre-decoded operation. Vector operations compute 16 lanes; the `S*` operations compute
/// a uniform value once (reading lane 0 of their operands) and store it in every lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    SConst {
        d: R,
        bits: u32,
    },
    SUniform {
        d: R,
        slot: u16,
    },
    SMov {
        d: R,
        a: R,
    },
    SUnary {
        op: UnaryOp,
        d: R,
        a: R,
    },
    SBinary {
        op: BinaryOp,
        d: R,
        a: R,
        b: R,
    },
    SMad {
        d: R,
        a: R,
        b: R,
        c: R,
    },
    SDot {
        n: u8,
        d: R,
        a: [R; 4],
        b: [R; 4],
    },
    SSelect {
        d: R,
        c: R,
        a: R,
        b: R,
    },

    Const {
        d: R,
        bits: u32,
    },
    Uniform {
        d: R,
        slot: u16,
    },
    Input {
        d: R,
        slot: u16,
    },
    Mov {
        d: R,
        a: R,
    },
    Add {
        d: R,
        a: R,
        b: R,
    },
    Sub {
        d: R,
        a: R,
        b: R,
    },
    Mul {
        d: R,
        a: R,
        b: R,
    },
    Div {
        d: R,
        a: R,
        b: R,
    },
    Min {
        d: R,
        a: R,
        b: R,
    },
    Max {
        d: R,
        a: R,
        b: R,
    },
    Lt {
        d: R,
        a: R,
        b: R,
    },
    Le {
        d: R,
        a: R,
        b: R,
    },
    Sqrt {
        d: R,
        a: R,
    },
    Rsq {
        d: R,
        a: R,
    },
    Unary {
        op: UnaryOp,
        d: R,
        a: R,
    },
    Binary {
        op: BinaryOp,
        d: R,
        a: R,
        b: R,
    },
    Mad {
        d: R,
        a: R,
        b: R,
        c: R,
    },
    Dot2 {
        d: R,
        a: [R; 2],
        b: [R; 2],
    },
    Dot3 {
        d: R,
        a: [R; 3],
        b: [R; 3],
    },
    Dot4 {
        d: R,
        a: [R; 4],
        b: [R; 4],
    },
    Select {
        d: R,
        c: R,
        a: R,
        b: R,
    },
    /// `min(max(a, lo), hi)` as the two instructions compute it.
    Clamp {
        d: R,
        a: R,
        lo: R,
        hi: R,
    },
    /// `lo < a ? min(a, hi) : lo` as the three instructions (a comparison, a minimum and a
    /// select) compute it: GL's clamp of colours to [0, 1], NaN to 0.
    ClampSelect {
        d: R,
        a: R,
        lo: R,
        hi: R,
    },
    /// `s = rsq(dot3(a, a)); d[k] = a[k]·s`.
    Normalize3 {
        d: [R; 3],
        a: [R; 3],
    },
    /// Rows of dot products sharing the vector: [`Wide::MatVec`].
    MatVec(u16),
    Derivative {
        x: bool,
        d: R,
        a: R,
    },
    Output {
        slot: u16,
        a: R,
    },
    /// Texture lookups: [`Wide`].
    Texture(u16),
    /// Up to four consecutive operations of one kind: [`Wide::Group`] ([`super::group`]).
    Group(u16),
    /// `d = ((m0·v0 + m1·v1) + m2·v2) + m3·v3` with uniform `m` (their lane 0 read), as the
    /// multiplication and the three multiply-adds it replaces compute it (each product and
    /// sum rounded, in that order): a row of a uniform matrix times a vector (the vertex
    /// programs' transforms, as glam's `Mat4 * Vec4` computes them).
    MatRow {
        d: R,
        m: [R; 4],
        v: [R; 4],
    },
    /// `Exp2` and `Log2` over the lanes at once ([`super::math::exp2_lanes`]).
    Exp2 {
        d: R,
        a: R,
    },
    Log2 {
        d: R,
        a: R,
    },
    /// `d = exp2(b·log2(a))` as the three operations compute it ([`super::math`]'s lane
    /// functions, the product rounded once): GLSL's `pow`, one dispatch and no stores of
    /// the logarithm and the product.
    Pow {
        d: R,
        a: R,
        b: R,
    },
}

/// The operations too large to keep in an [`Op`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Wide {
    /// `d[i] = dot_n(rows[i], v)` for i < `rows_n`, in order.
    MatVec {
        n: u8,
        rows_n: u8,
        d: [R; 4],
        rows: [[R; 4]; 4],
        v: [R; 4],
    },
    Sample {
        dst: [R; 4],
        unit: u8,
        n: u8,
        coords: [R; 4],
        projective: bool,
        lod: WideLod,
        compare: Option<R>,
    },
    Fetch {
        dst: [R; 4],
        unit: u8,
        n: u8,
        coords: [R; 3],
        lod: R,
    },
    Size {
        dst: [R; 3],
        unit: u8,
        lod: R,
    },
    /// `d[k] = kind(a[k], b[k])` (a select: `c[k] ? a[k] : b[k]`) for k < `n`, in order, each
    /// written before the next reads: the `n` operations it replaces, one dispatch.
    Group {
        kind: GroupKind,
        n: u8,
        d: [R; 4],
        a: [R; 4],
        b: [R; 4],
        c: [R; 4],
    },
}

/// The kind of the operations of a [`Wide::Group`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GroupKind {
    Add,
    Sub,
    Mul,
    Select,
    /// `d[k] = −a[k]` (`b[k]` is `a[k]`): a vector negated, as `-normalize(v)`.
    Neg,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WideLod {
    Implicit,
    Bias(R),
    Explicit(R),
}

/// How an `if` decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Cond {
    /// Per lane: the lanes where the bool register is true.
    Lanes(R),
    /// Uniform: every running lane, or none.
    Uniform(R),
}

/// The control structure over runs of straight-line operations.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// `ops[start..end]`, writing under the execution mask when `masked`.
    Run {
        start: u32,
        end: u32,
        masked: bool,
    },
    If {
        cond: Cond,
        then: Vec<Node>,
        otherwise: Vec<Node>,
    },
    Loop {
        body: Vec<Node>,
    },
    Break,
    Continue,
    Return,
    Discard,
}

/// A program ready to run: its registers, operations and control tree.
#[derive(Clone, Debug)]
pub struct Code {
    /// Words in the run's file.
    pub registers: usize,
    /// The words zeroed at the start of each run.
    pub zeroed: Vec<R>,
    pub ops: Vec<Op>,
    pub wide: Vec<Wide>,
    pub body: Vec<Node>,
}

// ---- Lane functions: the reference's operations on one lane --------------------------

#[inline(always)]
fn f(bits: u32) -> f32 {
    f32::from_bits(bits)
}

#[inline(always)]
fn fu(value: f32) -> u32 {
    value.to_bits()
}

/// One lane of [`super::exec`]'s unary operation (the same formulas).
#[inline(always)]
pub fn unary_lane(op: UnaryOp, x: u32) -> u32 {
    use super::math;
    use UnaryOp::*;
    match op {
        FNeg => x ^ 0x8000_0000,
        FAbs => x & 0x7fff_ffff,
        FSign => {
            let v = f(x);
            if v > 0.0 {
                fu(1.0)
            } else if v < 0.0 {
                fu(-1.0)
            } else {
                x
            }
        }
        Floor => fu(floor_f32(f(x))),
        Ceil => fu(-floor_f32(-f(x))),
        Trunc => {
            let v = f(x);
            if v.is_nan() || v.abs() >= (1 << 23) as f32 {
                x
            } else {
                fu((v as i32 as f32).copysign(v))
            }
        }
        Fract => fu(f(x) - floor_f32(f(x))),
        RoundEven => {
            let v = f(x);
            if v.is_nan() || v.abs() >= (1 << 23) as f32 {
                return x;
            }
            let big = (1 << 23) as f32;
            let r = if v >= 0.0 { (v + big) - big } else { (v - big) + big };
            fu(r.copysign(v))
        }
        Sqrt => fu(f(x).sqrt()),
        Rcp => fu(1.0 / f(x)),
        Rsq => fu(1.0 / f(x).sqrt()),
        Exp2 => fu(math::exp2(f(x))),
        Log2 => fu(math::log2(f(x))),
        Exp => fu(math::exp(f(x))),
        Sin => fu(math::sin(f(x))),
        Cos => fu(math::cos(f(x))),
        F32ToI32 => f(x) as i32 as u32,
        F32ToU32 => f(x) as u32,
        I32ToF32 => fu(x as i32 as f32),
        U32ToF32 => fu(x as f32),
        BoolToF32 => fu(x as f32),
        F32ToBool => (f(x) != 0.0) as u32,
        INeg => (x as i32).wrapping_neg() as u32,
        IAbs => (x as i32).wrapping_abs() as u32,
        INot => !x,
        BNot => x ^ 1,
        Bitcast => x,
    }
}

/// One lane of [`super::exec`]'s binary operation (the same formulas).
#[inline(always)]
pub fn binary_lane(op: BinaryOp, x: u32, y: u32) -> u32 {
    use BinaryOp::*;
    let int = |x: u32| x as i32;
    match op {
        FAdd => fu(f(x) + f(y)),
        FSub => fu(f(x) - f(y)),
        FMul => fu(f(x) * f(y)),
        FDiv => fu(f(x) / f(y)),
        FMin => super::exec::fmin_lane(x, y),
        FMax => super::exec::fmax_lane(x, y),
        FLt => (f(x) < f(y)) as u32,
        FLe => (f(x) <= f(y)) as u32,
        FEq => (f(x) == f(y)) as u32,
        FNe => (f(x) != f(y)) as u32,
        IAdd => x.wrapping_add(y),
        ISub => x.wrapping_sub(y),
        IMul => x.wrapping_mul(y),
        IDiv => {
            if y == 0 {
                0
            } else {
                int(x).wrapping_div(int(y)) as u32
            }
        }
        IRem => {
            if y == 0 {
                0
            } else {
                int(x).wrapping_rem(int(y)) as u32
            }
        }
        IMin => int(x).min(int(y)) as u32,
        IMax => int(x).max(int(y)) as u32,
        UDiv => x.checked_div(y).unwrap_or(0),
        URem => x.checked_rem(y).unwrap_or(0),
        UMin => x.min(y),
        UMax => x.max(y),
        ILt => (int(x) < int(y)) as u32,
        ILe => (int(x) <= int(y)) as u32,
        ULt => (x < y) as u32,
        ULe => (x <= y) as u32,
        IEq | BEq => (x == y) as u32,
        INe => (x != y) as u32,
        And | BAnd => x & y,
        Or | BOr => x | y,
        Xor | BXor => x ^ y,
        Shl => x << (y & 31),
        AShr => (int(x) >> (y & 31)) as u32,
        LShr => x >> (y & 31),
    }
}

/// `a·b + c` with two roundings.
#[inline(always)]
pub fn mad_lane(a: u32, b: u32, c: u32) -> u32 {
    fu(f(a) * f(b) + f(c))
}

/// The dot product of the first `n` pairs, left to right, as the reference sums it.
#[inline(always)]
pub fn dot_lane(n: usize, a: &[u32; 4], b: &[u32; 4]) -> u32 {
    let mut sum = f(a[0]) * f(b[0]);
    for k in 1..n {
        sum += f(a[k]) * f(b[k]);
    }
    fu(sum)
}

// ---- Analysis over the IR ----------------------------------------------------------

/// A short list of registers, without allocating (an instruction reads at most eight).
#[derive(Clone, Copy)]
struct List {
    regs: [Reg; 8],
    n: usize,
}

impl List {
    fn of(regs: &[Reg]) -> List {
        let mut list = List { regs: [Reg(0); 8], n: regs.len() };
        list.regs[..regs.len()].copy_from_slice(regs);
        list
    }

    fn push(&mut self, r: Reg) {
        self.regs[self.n] = r;
        self.n += 1;
    }

    fn iter(&self) -> impl Iterator<Item = Reg> + '_ {
        self.regs[..self.n].iter().copied()
    }
}

/// The registers an instruction reads.
fn reads(inst: &Inst) -> List {
    match *inst {
        Inst::Const { .. } | Inst::Input { .. } | Inst::Uniform { .. } => List::of(&[]),
        Inst::Mov { src, .. } => List::of(&[src]),
        Inst::Unary { a, .. } | Inst::Derivative { a, .. } => List::of(&[a]),
        Inst::Binary { a, b, .. } => List::of(&[a, b]),
        Inst::Mad { a, b, c, .. } => List::of(&[a, b, c]),
        Inst::Dot { n, a, b, .. } => {
            let mut list = List::of(&a[..n as usize]);
            b[..n as usize].iter().for_each(|&r| list.push(r));
            list
        }
        Inst::Select { cond, a, b, .. } => List::of(&[cond, a, b]),
        Inst::Output { src, .. } => List::of(&[src]),
        Inst::Sample { coords, lod, compare, .. } => {
            let mut list = List::of(&coords);
            if let Lod::Bias(r) | Lod::Explicit(r) = lod {
                list.push(r);
            }
            compare.into_iter().for_each(|r| list.push(r));
            list
        }
        Inst::Fetch { coords, lod, .. } => {
            let mut list = List::of(&coords);
            list.push(lod);
            list
        }
        Inst::Size { lod, .. } => List::of(&[lod]),
    }
}

/// The registers an instruction writes ([`Inst::writes`] without allocating).
fn writes(inst: &Inst) -> List {
    match *inst {
        Inst::Sample { dst, .. } | Inst::Fetch { dst, .. } => List::of(&dst),
        Inst::Size { dst, .. } => List::of(&dst),
        _ => List::of(inst.dst().as_slice()),
    }
}

/// Registers whose every lane another lane may read: derivative operands and everything a
/// texture lookup hands the sampler.
fn is_cross_lane(inst: &Inst) -> bool {
    matches!(inst, Inst::Derivative { .. } | Inst::Sample { .. } | Inst::Fetch { .. } | Inst::Size { .. })
}

fn is_texture(inst: &Inst) -> bool {
    matches!(inst, Inst::Sample { .. } | Inst::Fetch { .. } | Inst::Size { .. })
}

fn for_each_inst(stmts: &[Stmt], visit: &mut impl FnMut(&Inst)) {
    for stmt in stmts {
        match stmt {
            Stmt::Inst(i) => visit(i),
            Stmt::If { then, otherwise, .. } => {
                for_each_inst(then, visit);
                for_each_inst(otherwise, visit);
            }
            Stmt::Loop { body } => for_each_inst(body, visit),
            _ => {}
        }
    }
}

/// Replaces top-level instructions computable from constants by constants.
fn fold_constants(program: &Program, body: Vec<Stmt>) -> Vec<Stmt> {
    let mut defs = vec![0u32; program.registers.len()];
    for_each_inst(&body, &mut |i| {
        for r in writes(i).iter() {
            defs[r.0 as usize] += 1;
        }
    });
    let mut known: Vec<Option<u32>> = vec![None; program.registers.len()];
    body.into_iter()
        .map(|stmt| {
            let Stmt::Inst(inst) = &stmt else { return stmt };
            let Some(dst) = inst.dst() else { return stmt };
            let k = |r: Reg| known[r.0 as usize];
            let value = match *inst {
                Inst::Const { value, .. } => Some(value.bits()),
                Inst::Mov { src, .. } => k(src),
                Inst::Unary { op, a, .. } => k(a).map(|a| unary_lane(op, a)),
                Inst::Binary { op, a, b, .. } => k(a).zip(k(b)).map(|(a, b)| binary_lane(op, a, b)),
                Inst::Mad { a, b, c, .. } => match (k(a), k(b), k(c)) {
                    (Some(a), Some(b), Some(c)) => Some(mad_lane(a, b, c)),
                    _ => None,
                },
                Inst::Dot { n, a, b, .. } => {
                    let n = n as usize;
                    let (a, b) = (a.map(k), b.map(k));
                    (a[..n].iter().all(Option::is_some) && b[..n].iter().all(Option::is_some))
                        .then(|| dot_lane(n, &a.map(|v| v.unwrap_or(0)), &b.map(|v| v.unwrap_or(0))))
                }
                Inst::Select { cond, a, b, .. } => match (k(cond), k(a), k(b)) {
                    (Some(c), Some(a), Some(b)) => Some(if c != 0 { a } else { b }),
                    _ => None,
                },
                _ => None,
            };
            match value {
                Some(bits) => {
                    if defs[dst.0 as usize] == 1 {
                        known[dst.0 as usize] = Some(bits);
                    }
                    // The register's type names the constant's type; the bits are the value.
                    Stmt::Inst(Inst::Const { dst, value: Const::U32(bits) })
                }
                None => stmt,
            }
        })
        .collect()
}

/// Drops instructions whose results nothing needs (see the module docs).
fn remove_dead(registers: usize, body: Vec<Stmt>) -> Vec<Stmt> {
    let mut useful = vec![false; registers];
    // Backwards, so that straight-line code settles in one pass (loops may need more).
    fn walk(stmts: &[Stmt], useful: &mut [bool], changed: &mut bool) {
        fn mark(r: Reg, useful: &mut [bool], changed: &mut bool) {
            if !useful[r.0 as usize] {
                useful[r.0 as usize] = true;
                *changed = true;
            }
        }
        for s in stmts.iter().rev() {
            match s {
                Stmt::If { cond, then, otherwise } => {
                    mark(*cond, useful, changed);
                    walk(then, useful, changed);
                    walk(otherwise, useful, changed);
                }
                Stmt::Loop { body } => walk(body, useful, changed),
                Stmt::Inst(i) => {
                    let needed = matches!(i, Inst::Output { .. })
                        || is_texture(i)
                        || writes(i).iter().any(|r| useful[r.0 as usize]);
                    if needed {
                        for r in reads(i).iter() {
                            mark(r, useful, changed);
                        }
                    }
                }
                _ => {}
            }
        }
    }
    loop {
        let mut changed = false;
        walk(&body, &mut useful, &mut changed);
        if !changed {
            break;
        }
    }
    fn filter(stmts: Vec<Stmt>, useful: &[bool]) -> Vec<Stmt> {
        stmts
            .into_iter()
            .filter_map(|s| match s {
                Stmt::Inst(i) => {
                    let keep = matches!(i, Inst::Output { .. })
                        || is_texture(&i)
                        || writes(&i).iter().any(|r| useful[r.0 as usize]);
                    keep.then_some(Stmt::Inst(i))
                }
                Stmt::If { cond, then, otherwise } => {
                    Some(Stmt::If { cond, then: filter(then, useful), otherwise: filter(otherwise, useful) })
                }
                Stmt::Loop { body } => Some(Stmt::Loop { body: filter(body, useful) }),
                other => Some(other),
            })
            .collect()
    }
    filter(body, &useful)
}

/// Whether a `break` or `continue` of this loop (not of a loop inside it) sits under an
/// `if` whose condition is not uniform.
fn divergent_exit(stmts: &[Stmt], uniform: &[bool], under_divergent_if: bool) -> bool {
    stmts.iter().any(|s| match s {
        Stmt::Break | Stmt::Continue => under_divergent_if,
        Stmt::If { cond, then, otherwise } => {
            let d = under_divergent_if || !uniform[cond.0 as usize];
            divergent_exit(then, uniform, d) || divergent_exit(otherwise, uniform, d)
        }
        _ => false,
    })
}

/// The uniform registers (see the module docs): the largest set consistent with the rules.
fn uniform_registers(registers: usize, pinned: &[bool], body: &[Stmt]) -> Vec<bool> {
    let mut uniform: Vec<bool> = pinned.iter().map(|p| !p).collect();
    uniform.resize(registers, true);
    fn walk(stmts: &[Stmt], divergent: bool, uniform: &mut Vec<bool>, changed: &mut bool) {
        for s in stmts {
            match s {
                Stmt::Inst(i) => {
                    let value_uniform = match i {
                        Inst::Const { .. } | Inst::Uniform { .. } => true,
                        Inst::Mov { .. }
                        | Inst::Unary { .. }
                        | Inst::Binary { .. }
                        | Inst::Mad { .. }
                        | Inst::Dot { .. }
                        | Inst::Select { .. } => reads(i).iter().all(|r| uniform[r.0 as usize]),
                        _ => false,
                    };
                    if divergent || !value_uniform {
                        for r in writes(i).iter() {
                            if uniform[r.0 as usize] {
                                uniform[r.0 as usize] = false;
                                *changed = true;
                            }
                        }
                    }
                }
                Stmt::If { cond, then, otherwise } => {
                    let d = divergent || !uniform[cond.0 as usize];
                    walk(then, d, uniform, changed);
                    walk(otherwise, d, uniform, changed);
                }
                Stmt::Loop { body } => {
                    let d = divergent || divergent_exit(body, uniform, false);
                    walk(body, d, uniform, changed);
                }
                _ => {}
            }
        }
    }
    loop {
        let mut changed = false;
        walk(body, false, &mut uniform, &mut changed);
        if !changed {
            return uniform;
        }
    }
}

// ---- Lowering ----------------------------------------------------------------------

struct Lowering {
    map: Vec<Option<R>>,
    registers: usize,
    uniform: Vec<bool>,
    pinned: Vec<bool>,
    uses: Vec<u32>,
    ops: Vec<Op>,
    wide: Vec<Wide>,
}

impl Lowering {
    fn r(&mut self, reg: Reg) -> R {
        let slot = &mut self.map[reg.0 as usize];
        *slot.get_or_insert_with(|| {
            self.registers += 1;
            (self.registers - 1) as R
        })
    }

    fn uniform(&self, reg: Reg) -> bool {
        self.uniform[reg.0 as usize]
    }

    /// The operation for one instruction.
    fn op(&mut self, inst: &Inst) -> Op {
        let scalar = inst.dst().is_some_and(|d| self.uniform(d));
        match *inst {
            Inst::Const { dst, value } => {
                let d = self.r(dst);
                if scalar {
                    Op::SConst { d, bits: value.bits() }
                } else {
                    Op::Const { d, bits: value.bits() }
                }
            }
            Inst::Uniform { dst, slot } => {
                let d = self.r(dst);
                if scalar {
                    Op::SUniform { d, slot }
                } else {
                    Op::Uniform { d, slot }
                }
            }
            Inst::Input { dst, slot } => Op::Input { d: self.r(dst), slot },
            Inst::Mov { dst, src } => {
                let (d, a) = (self.r(dst), self.r(src));
                if scalar {
                    Op::SMov { d, a }
                } else {
                    Op::Mov { d, a }
                }
            }
            Inst::Unary { op, dst, a } => {
                let (d, a) = (self.r(dst), self.r(a));
                match op {
                    _ if scalar => Op::SUnary { op, d, a },
                    UnaryOp::Sqrt => Op::Sqrt { d, a },
                    UnaryOp::Rsq => Op::Rsq { d, a },
                    UnaryOp::Exp2 => Op::Exp2 { d, a },
                    UnaryOp::Log2 => Op::Log2 { d, a },
                    _ => Op::Unary { op, d, a },
                }
            }
            Inst::Binary { op, dst, a, b } => {
                let (d, a, b) = (self.r(dst), self.r(a), self.r(b));
                match op {
                    _ if scalar => Op::SBinary { op, d, a, b },
                    BinaryOp::FAdd => Op::Add { d, a, b },
                    BinaryOp::FSub => Op::Sub { d, a, b },
                    BinaryOp::FMul => Op::Mul { d, a, b },
                    BinaryOp::FDiv => Op::Div { d, a, b },
                    BinaryOp::FMin => Op::Min { d, a, b },
                    BinaryOp::FMax => Op::Max { d, a, b },
                    BinaryOp::FLt => Op::Lt { d, a, b },
                    BinaryOp::FLe => Op::Le { d, a, b },
                    _ => Op::Binary { op, d, a, b },
                }
            }
            Inst::Mad { dst, a, b, c } => {
                let (d, a, b, c) = (self.r(dst), self.r(a), self.r(b), self.r(c));
                if scalar {
                    Op::SMad { d, a, b, c }
                } else {
                    Op::Mad { d, a, b, c }
                }
            }
            Inst::Dot { dst, n, a, b } => {
                let d = self.r(dst);
                let mut ra = [0; 4];
                let mut rb = [0; 4];
                for k in 0..n as usize {
                    ra[k] = self.r(a[k]);
                    rb[k] = self.r(b[k]);
                }
                match n {
                    _ if scalar => Op::SDot { n, d, a: ra, b: rb },
                    2 => Op::Dot2 { d, a: [ra[0], ra[1]], b: [rb[0], rb[1]] },
                    3 => Op::Dot3 { d, a: [ra[0], ra[1], ra[2]], b: [rb[0], rb[1], rb[2]] },
                    _ => Op::Dot4 { d, a: ra, b: rb },
                }
            }
            Inst::Select { dst, cond, a, b } => {
                let (d, c, a, b) = (self.r(dst), self.r(cond), self.r(a), self.r(b));
                if scalar {
                    Op::SSelect { d, c, a, b }
                } else {
                    Op::Select { d, c, a, b }
                }
            }
            Inst::Derivative { dst, axis, a } => {
                Op::Derivative { x: axis == super::ir::Axis::X, d: self.r(dst), a: self.r(a) }
            }
            Inst::Output { slot, src } => Op::Output { slot, a: self.r(src) },
            Inst::Sample { dst, unit, n, coords, projective, lod, compare } => {
                let lod = match lod {
                    Lod::Implicit => WideLod::Implicit,
                    Lod::Bias(r) => WideLod::Bias(self.r(r)),
                    Lod::Explicit(r) => WideLod::Explicit(self.r(r)),
                };
                let wide = Wide::Sample {
                    dst: dst.map(|r| self.r(r)),
                    unit,
                    n,
                    coords: coords.map(|r| self.r(r)),
                    projective,
                    lod,
                    compare: compare.map(|r| self.r(r)),
                };
                self.wide(wide)
            }
            Inst::Fetch { dst, unit, n, coords, lod } => {
                let wide = Wide::Fetch {
                    dst: dst.map(|r| self.r(r)),
                    unit,
                    n,
                    coords: coords.map(|r| self.r(r)),
                    lod: self.r(lod),
                };
                self.wide(wide)
            }
            Inst::Size { dst, unit, lod } => {
                let wide = Wide::Size { dst: dst.map(|r| self.r(r)), unit, lod: self.r(lod) };
                self.wide(wide)
            }
        }
    }

    fn wide(&mut self, wide: Wide) -> Op {
        self.wide.push(wide);
        Op::Texture(self.wide.len() as u16 - 1)
    }

    /// Lowers a statement list; `divergent`: lanes that are still running may skip it.
    fn block(&mut self, stmts: &[Stmt], divergent: bool) -> Vec<Node> {
        let mut nodes = Vec::new();
        let mut i = 0;
        while i < stmts.len() {
            match &stmts[i] {
                Stmt::Inst(_) => {
                    // A run of straight-line instructions; in uniform code, writes to pinned
                    // registers go to runs of their own, under the mask.
                    let start = i;
                    while i < stmts.len() && matches!(stmts[i], Stmt::Inst(_)) {
                        i += 1;
                    }
                    let insts: Vec<&Inst> = stmts[start..i]
                        .iter()
                        .map(|s| if let Stmt::Inst(x) = s { x } else { unreachable!() })
                        .collect();
                    let mut k = 0;
                    while k < insts.len() {
                        let pinned = |x: &Inst| writes(x).iter().any(|r| self.pinned[r.0 as usize]);
                        let masked = divergent || pinned(insts[k]);
                        let first = k;
                        while k < insts.len() && (divergent || pinned(insts[k]) == masked) {
                            k += 1;
                        }
                        let begin = self.ops.len() as u32;
                        self.straight(&insts[first..k]);
                        nodes.push(Node::Run { start: begin, end: self.ops.len() as u32, masked });
                    }
                    continue;
                }
                Stmt::If { cond, then, otherwise } => {
                    let inner = divergent || !self.uniform(*cond);
                    let c = self.r(*cond);
                    let cond = if self.uniform(*cond) { Cond::Uniform(c) } else { Cond::Lanes(c) };
                    let then = self.block(then, inner);
                    let otherwise = self.block(otherwise, inner);
                    nodes.push(Node::If { cond, then, otherwise });
                }
                Stmt::Loop { body } => {
                    let inner = divergent || divergent_exit(body, &self.uniform, false);
                    let body = self.block(body, inner);
                    nodes.push(Node::Loop { body });
                }
                Stmt::Break => nodes.push(Node::Break),
                Stmt::Continue => nodes.push(Node::Continue),
                Stmt::Return => nodes.push(Node::Return),
                Stmt::Discard => nodes.push(Node::Discard),
            }
            i += 1;
        }
        nodes
    }

    /// A single-use register that fusion may leave unwritten.
    fn temporary(&self, reg: Reg, uses: u32) -> bool {
        self.uses[reg.0 as usize] == uses && !self.pinned[reg.0 as usize] && !self.uniform(reg)
    }

    /// Lowers straight-line instructions, fusing the patterns of the module docs.
    fn straight(&mut self, insts: &[&Inst]) {
        use BinaryOp::{FMax, FMin, FMul};
        let mut k = 0;
        while k < insts.len() {
            let rest = &insts[k..];
            // A row of a uniform matrix times a vector: t0 = m0·v0; t1 = m1·v1 + t0;
            // t2 = m2·v2 + t1; d = m3·v3 + t2.
            if let [Inst::Binary { op: FMul, dst: t0, a: m0, b: v0 }, Inst::Mad { dst: t1, a: m1, b: v1, c: c1 }, Inst::Mad { dst: t2, a: m2, b: v2, c: c2 }, Inst::Mad { dst, a: m3, b: v3, c: c3 }, ..] =
                rest
            {
                let (m, v, t) = ([*m0, *m1, *m2, *m3], [*v0, *v1, *v2, *v3], [*t0, *t1, *t2]);
                if c1 == t0
                    && c2 == t1
                    && c3 == t2
                    && t0 != t1
                    && t1 != t2
                    && t0 != t2
                    && m.iter().all(|&r| self.uniform(r) && !t.contains(&r))
                    && v.iter().all(|r| !t.contains(r))
                    && t.iter().all(|&r| self.temporary(r, 1))
                    && !t.contains(dst)
                    && !self.uniform(*dst)
                {
                    let op = Op::MatRow { d: self.r(*dst), m: m.map(|r| self.r(r)), v: v.map(|r| self.r(r)) };
                    self.ops.push(op);
                    k += 4;
                    continue;
                }
            }
            // Power, as the GLSL front end writes `pow`: l = log2 a; m = b·l; d = exp2 m.
            if let [Inst::Unary { op: UnaryOp::Log2, dst: l, a }, Inst::Binary { op: FMul, dst: m, a: b, b: l2 }, Inst::Unary { op: UnaryOp::Exp2, dst, a: m2 }, ..] =
                rest
            {
                if l == l2
                    && m == m2
                    && l != m
                    && a != l
                    && b != l
                    && self.temporary(*l, 1)
                    && self.temporary(*m, 1)
                    && !self.uniform(*dst)
                {
                    let op = Op::Pow { d: self.r(*dst), a: self.r(*a), b: self.r(*b) };
                    self.ops.push(op);
                    k += 3;
                    continue;
                }
            }
            // Clamp: t = max(a, lo); d = min(t, hi).
            if let [Inst::Binary { op: FMax, dst: t, a, b: lo }, Inst::Binary { op: FMin, dst, a: t2, b: hi }, ..] =
                rest
            {
                if t == t2 && hi != t && self.temporary(*t, 1) && !self.uniform(*dst) {
                    let op = Op::Clamp { d: self.r(*dst), a: self.r(*a), lo: self.r(*lo), hi: self.r(*hi) };
                    self.ops.push(op);
                    k += 2;
                    continue;
                }
            }
            // Two products summed: t = a·b; u = c·e; d = t + u, each rounded once, is dot2.
            if let [Inst::Binary { op: FMul, dst: t, a: a0, b: b0 }, Inst::Binary { op: FMul, dst: u, a: a1, b: b1 }, Inst::Binary { op: BinaryOp::FAdd, dst, a: t2, b: u2 }, ..] =
                rest
            {
                if t == t2 && u == u2 && t != u && self.temporary(*t, 1) && self.temporary(*u, 1) && !self.uniform(*dst)
                {
                    let op = Op::Dot2 { d: self.r(*dst), a: [self.r(*a0), self.r(*a1)], b: [self.r(*b0), self.r(*b1)] };
                    self.ops.push(op);
                    k += 3;
                    continue;
                }
            }
            // Select clamp: p = lo < x; m = min(x, hi); d = p ? m : lo.
            if let [Inst::Binary { op: BinaryOp::FLt, dst: p, a: lo, b: x }, Inst::Binary { op: FMin, dst: m, a: x2, b: hi }, Inst::Select { dst, cond, a: m2, b: lo2 }, ..] =
                rest
            {
                if p == cond
                    && m == m2
                    && x == x2
                    && lo == lo2
                    && p != m
                    && self.temporary(*p, 1)
                    && self.temporary(*m, 1)
                    && !self.uniform(*dst)
                {
                    let op = Op::ClampSelect { d: self.r(*dst), a: self.r(*x), lo: self.r(*lo), hi: self.r(*hi) };
                    self.ops.push(op);
                    k += 3;
                    continue;
                }
            }
            // Normalize: l = dot3(v, v); s = rsq l; d0 = v0·s; d1 = v1·s; d2 = v2·s.
            if let [Inst::Dot { dst: l, n: 3, a: v, b: v2 }, Inst::Unary { op: UnaryOp::Rsq, dst: s, a: l2 }, Inst::Binary { op: FMul, dst: d0, a: m0, b: s0 }, Inst::Binary { op: FMul, dst: d1, a: m1, b: s1 }, Inst::Binary { op: FMul, dst: d2, a: m2, b: s2 }, ..] =
                rest
            {
                let d = [*d0, *d1, *d2];
                if v[..3] == v2[..3]
                    && l == l2
                    && [s0, s1, s2] == [s; 3]
                    && [*m0, *m1, *m2] == v[..3]
                    && l != s
                    && self.temporary(*l, 1)
                    && self.temporary(*s, 3)
                    && !d.contains(s)
                    && !d.contains(l)
                    && d[0] != v[1]
                    && d[0] != v[2]
                    && d[1] != v[2]
                    && d.iter().all(|r| !self.uniform(*r))
                {
                    let op = Op::Normalize3 { d: d.map(|r| self.r(r)), a: [v[0], v[1], v[2]].map(|r| self.r(r)) };
                    self.ops.push(op);
                    k += 5;
                    continue;
                }
            }
            // Matrix·vector: consecutive dots of one size sharing the right-hand vector,
            // none writing a register a later one reads.
            if let Inst::Dot { n, b, .. } = rest[0] {
                let mut rows = 1;
                let mut written: Vec<Reg> = Vec::new();
                while rows < 4 && rows < rest.len() {
                    let Inst::Dot { n: n2, b: b2, a: a2, dst: d2 } = rest[rows] else { break };
                    let prev = rest[rows - 1].dst().expect("a dot writes");
                    written.push(prev);
                    let reads_written = a2[..*n as usize].iter().chain(&b2[..*n as usize]).any(|r| written.contains(r));
                    if n2 != n || b2[..*n as usize] != b[..*n as usize] || reads_written || self.uniform(*d2) {
                        break;
                    }
                    rows += 1;
                }
                if rows >= 2 && !self.uniform(rest[0].dst().expect("a dot writes")) {
                    let mut d = [0; 4];
                    let mut m = [[0; 4]; 4];
                    let mut vv = [0; 4];
                    for (row, inst) in rest[..rows].iter().enumerate() {
                        let Inst::Dot { dst, a, .. } = inst else { unreachable!() };
                        d[row] = self.r(*dst);
                        for c in 0..*n as usize {
                            m[row][c] = self.r(a[c]);
                        }
                    }
                    for c in 0..*n as usize {
                        vv[c] = self.r(b[c]);
                    }
                    self.wide.push(Wide::MatVec { n: *n, rows_n: rows as u8, d, rows: m, v: vv });
                    self.ops.push(Op::MatVec(self.wide.len() as u16 - 1));
                    k += rows;
                    continue;
                }
            }
            let op = self.op(rest[0]);
            self.ops.push(op);
            k += 1;
        }
    }
}

/// Which registers a read may reach before any write to them (those are zeroed per run):
/// a register counts as written after a top-level, unmasked write.
fn zeroed(body: &[Stmt], registers: usize, pinned: &[bool]) -> Vec<bool> {
    let mut written = vec![false; registers];
    let mut zero = pinned.to_vec();
    fn reads_in(stmts: &[Stmt], written: &[bool], zero: &mut [bool]) {
        for s in stmts {
            match s {
                Stmt::Inst(i) => {
                    for r in reads(i).iter() {
                        zero[r.0 as usize] |= !written[r.0 as usize];
                    }
                }
                Stmt::If { cond, then, otherwise } => {
                    zero[cond.0 as usize] |= !written[cond.0 as usize];
                    reads_in(then, written, zero);
                    reads_in(otherwise, written, zero);
                }
                Stmt::Loop { body } => reads_in(body, written, zero),
                _ => {}
            }
        }
    }
    for s in body {
        reads_in(std::slice::from_ref(s), &written, &mut zero);
        if let Stmt::Inst(i) = s {
            if !is_texture(i) {
                for r in writes(i).iter() {
                    written[r.0 as usize] = true;
                }
            }
        }
    }
    zero
}

/// Compiles a validated program (see the module docs).
pub fn lower(program: &Program) -> Code {
    let n = program.registers.len();
    let body = fold_constants(program, program.body.clone());
    let body = remove_dead(n, body);
    let mut pinned = vec![false; n];
    let mut uses = vec![0u32; n];
    for_each_inst(&body, &mut |i| {
        for r in reads(i).iter() {
            uses[r.0 as usize] += 1;
            if is_cross_lane(i) {
                pinned[r.0 as usize] = true;
            }
        }
    });
    fn cond_uses(stmts: &[Stmt], uses: &mut [u32]) {
        for s in stmts {
            match s {
                Stmt::If { cond, then, otherwise } => {
                    uses[cond.0 as usize] += 1;
                    cond_uses(then, uses);
                    cond_uses(otherwise, uses);
                }
                Stmt::Loop { body } => cond_uses(body, uses),
                _ => {}
            }
        }
    }
    cond_uses(&body, &mut uses);
    let uniform = uniform_registers(n, &pinned, &body);
    let zero = zeroed(&body, n, &pinned);
    let mut lowering =
        Lowering { map: vec![None; n], registers: 0, uniform, pinned, uses, ops: Vec::new(), wide: Vec::new() };
    let nodes = lowering.block(&body, false);
    let zeroed = (0..n).filter(|&r| zero[r]).filter_map(|r| lowering.map[r]).collect();
    Code { registers: lowering.registers, zeroed, ops: lowering.ops, wide: lowering.wide, body: nodes }
}

/// The registers an operation writes (at most four).
pub(super) fn op_writes(op: &Op, wide: &[Wide]) -> ([R; 4], usize) {
    let one = |d: R| ([d, 0, 0, 0], 1);
    match *op {
        Op::SConst { d, .. }
        | Op::SUniform { d, .. }
        | Op::SMov { d, .. }
        | Op::SUnary { d, .. }
        | Op::SBinary { d, .. }
        | Op::SMad { d, .. }
        | Op::SDot { d, .. }
        | Op::SSelect { d, .. }
        | Op::Const { d, .. }
        | Op::Uniform { d, .. }
        | Op::Input { d, .. }
        | Op::Mov { d, .. }
        | Op::Add { d, .. }
        | Op::Sub { d, .. }
        | Op::Mul { d, .. }
        | Op::Div { d, .. }
        | Op::Min { d, .. }
        | Op::Max { d, .. }
        | Op::Lt { d, .. }
        | Op::Le { d, .. }
        | Op::Sqrt { d, .. }
        | Op::Rsq { d, .. }
        | Op::Unary { d, .. }
        | Op::Binary { d, .. }
        | Op::Mad { d, .. }
        | Op::Dot2 { d, .. }
        | Op::Dot3 { d, .. }
        | Op::Dot4 { d, .. }
        | Op::Select { d, .. }
        | Op::Clamp { d, .. }
        | Op::ClampSelect { d, .. }
        | Op::Derivative { d, .. }
        | Op::MatRow { d, .. }
        | Op::Exp2 { d, .. }
        | Op::Log2 { d, .. }
        | Op::Pow { d, .. } => one(d),
        Op::Normalize3 { d, .. } => ([d[0], d[1], d[2], 0], 3),
        Op::Output { .. } => ([0; 4], 0),
        Op::MatVec(i) | Op::Texture(i) | Op::Group(i) => match wide[i as usize] {
            Wide::MatVec { rows_n, d, .. } => (d, rows_n as usize),
            Wide::Sample { dst, .. } | Wide::Fetch { dst, .. } => (dst, 4),
            Wide::Size { dst, .. } => ([dst[0], dst[1], dst[2], 0], 3),
            Wide::Group { n, d, .. } => (d, n as usize),
        },
    }
}

/// Splits `code` into its uniform prologue and the rest (see the module docs): the scalar
/// operations of top-level, unmasked runs whose operands the prologue computes and whose
/// register nothing else writes and no run zeroes. Running the prologue, then the rest,
/// gives `code`'s results; the rest may run many times after one prologue, as long as the
/// uniforms and the register file stay the same.
pub fn split_prologue(code: &Code) -> (Vec<Op>, Code) {
    let n = code.registers;
    let mut written = vec![0u32; n];
    for op in &code.ops {
        let (d, count) = op_writes(op, &code.wide);
        for &r in &d[..count] {
            written[r as usize] += 1;
        }
    }
    let mut movable = vec![true; n];
    for &r in &code.zeroed {
        movable[r as usize] = false;
    }
    for (r, &w) in written.iter().enumerate() {
        movable[r] &= w == 1;
    }
    struct Split<'a> {
        code: &'a Code,
        movable: Vec<bool>,
        hoisted: Vec<bool>,
        prologue: Vec<Op>,
        ops: Vec<Op>,
    }
    impl Split<'_> {
        fn hoistable(&self, op: &Op) -> Option<R> {
            let h = |r: R| self.hoisted[r as usize];
            let (d, operands) = match *op {
                Op::SConst { d, .. } | Op::SUniform { d, .. } => (d, true),
                Op::SMov { d, a } | Op::SUnary { d, a, .. } => (d, h(a)),
                Op::SBinary { d, a, b, .. } => (d, h(a) && h(b)),
                Op::SMad { d, a, b, c } | Op::SSelect { d, c, a, b } => (d, h(a) && h(b) && h(c)),
                Op::SDot { n, d, a, b } => (d, a[..n as usize].iter().chain(&b[..n as usize]).all(|&r| h(r))),
                _ => return None,
            };
            (operands && self.movable[d as usize]).then_some(d)
        }

        fn nodes(&mut self, nodes: &[Node], top: bool) -> Vec<Node> {
            let mut out = Vec::new();
            for node in nodes {
                match node {
                    &Node::Run { start, end, masked } => {
                        let begin = self.ops.len() as u32;
                        for op in &self.code.ops[start as usize..end as usize] {
                            match self.hoistable(op).filter(|_| top && !masked) {
                                Some(d) => {
                                    self.hoisted[d as usize] = true;
                                    self.prologue.push(*op);
                                }
                                None => self.ops.push(*op),
                            }
                        }
                        let end = self.ops.len() as u32;
                        if begin < end {
                            out.push(Node::Run { start: begin, end, masked });
                        }
                    }
                    Node::If { cond, then, otherwise } => {
                        let (then, otherwise) = (self.nodes(then, false), self.nodes(otherwise, false));
                        out.push(Node::If { cond: *cond, then, otherwise });
                    }
                    Node::Loop { body } => {
                        let body = self.nodes(body, false);
                        out.push(Node::Loop { body });
                    }
                    other => out.push(other.clone()),
                }
            }
            out
        }
    }
    let mut split =
        Split { code, movable, hoisted: vec![false; n], prologue: Vec::new(), ops: Vec::with_capacity(code.ops.len()) };
    let body = split.nodes(&code.body, true);
    let rest = Code { registers: n, zeroed: code.zeroed.clone(), ops: split.ops, wide: code.wide.clone(), body };
    (split.prologue, rest)
}
