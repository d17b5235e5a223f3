//! Property tests of the executor: random programs (every exactly rounded operation, nested
//! ifs, loops with break and continue, return, discard, partial lane masks) run over 16
//! lanes and, lane by lane, by a scalar reference that branches for real and computes in
//! f64, rounding to f32 after each operation. For add, sub, mul, div and sqrt of f32
//! operands the f64 result rounded to f32 is the correctly rounded f32 result (53 ≥ 2·24 + 2
//! bits), so the two must agree bit for bit (NaNs only as NaNs: their payloads are the
//! CPU's).
use super::exec::{
    Executor, Io, LodLanes, NoTextures, SampleRequest, Textures, Word, ALL_LANES, LANES, MAX_LOOP_ITERATIONS,
};
use super::fast::{Compiled, Registers, Threaded};
use super::ir::{Axis, BinaryOp, Const, Inst, Lod, Program, Reg, Stage, Stmt, Type, UnaryOp};
use super::validate::validate;

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn chance(&mut self, percent: u64) -> bool {
        self.next() % 100 < percent
    }

    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }

    fn float(&mut self) -> f32 {
        match self.below(8) {
            0 => self.pick(&[0.0, -0.0, 1.0, -1.0, 0.5, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 1e-40, -3e38]),
            1 => self.below(9) as f32 - 4.0,
            2 => f32::from_bits(self.next() as u32),
            _ => (self.next() % 20_000) as f32 / 1000.0 - 10.0,
        }
    }

    fn int(&mut self) -> u32 {
        match self.below(4) {
            0 => self.pick(&[0, 1, u32::MAX, 0x8000_0000, 31, 32]),
            1 => self.next() as u32,
            _ => (self.below(11) as i32 - 5) as u32,
        }
    }
}

// ---- The scalar f64 reference -------------------------------------------------------

fn to_f64(bits: u32) -> f64 {
    f32::from_bits(bits) as f64
}

fn from_f64(v: f64) -> u32 {
    (v as f32).to_bits()
}

/// The reference's value of a unary operation (only the exactly rounded ones).
fn ref_unary(op: UnaryOp, x: u32) -> u32 {
    use UnaryOp::*;
    let v = to_f64(x);
    match op {
        FNeg => x ^ 0x8000_0000,
        FAbs => x & 0x7fff_ffff,
        FSign => {
            if v > 0.0 {
                from_f64(1.0)
            } else if v < 0.0 {
                from_f64(-1.0)
            } else {
                x
            }
        }
        Floor => from_f64(v.floor()),
        Ceil => from_f64(v.ceil()),
        Trunc => from_f64(v.trunc()),
        Fract => from_f64(v - v.floor()),
        RoundEven => from_f64(v.round_ties_even()),
        Sqrt => from_f64(v.sqrt()),
        Rcp => from_f64(1.0 / v),
        Rsq => from_f64(1.0 / (v.sqrt() as f32 as f64)),
        F32ToI32 => v as i32 as u32,
        F32ToU32 => v as u32,
        I32ToF32 => from_f64(x as i32 as f64),
        U32ToF32 => from_f64(x as f64),
        BoolToF32 => from_f64(x as f64),
        F32ToBool => (v != 0.0) as u32,
        INeg => (x as i32).wrapping_neg() as u32,
        IAbs => (x as i32).wrapping_abs() as u32,
        INot => !x,
        BNot => (x == 0) as u32,
        Bitcast => x,
        Exp2 | Exp | Log2 | Sin | Cos => unreachable!("not generated"),
    }
}

fn ref_binary(op: BinaryOp, x: u32, y: u32) -> u32 {
    use BinaryOp::*;
    let (a, b) = (to_f64(x), to_f64(y));
    let (i, j) = (x as i32, y as i32);
    match op {
        FAdd => from_f64(a + b),
        FSub => from_f64(a - b),
        FMul => from_f64(a * b),
        FDiv => from_f64(a / b),
        FMin => {
            if b < a || a.is_nan() {
                y
            } else {
                x
            }
        }
        FMax => {
            if a < b || a.is_nan() {
                y
            } else {
                x
            }
        }
        FLt => (a < b) as u32,
        FLe => (a <= b) as u32,
        FEq => (a == b) as u32,
        FNe => (a != b) as u32,
        IAdd => i.wrapping_add(j) as u32,
        ISub => i.wrapping_sub(j) as u32,
        IMul => i.wrapping_mul(j) as u32,
        IDiv => i.checked_div(j).unwrap_or(if j == 0 { 0 } else { i32::MIN }) as u32,
        IRem => i.checked_rem(j).unwrap_or(0) as u32,
        IMin => i.min(j) as u32,
        IMax => i.max(j) as u32,
        UDiv => x.checked_div(y).unwrap_or(0),
        URem => x.checked_rem(y).unwrap_or(0),
        UMin => x.min(y),
        UMax => x.max(y),
        ILt => (i < j) as u32,
        ILe => (i <= j) as u32,
        ULt => (x < y) as u32,
        ULe => (x <= y) as u32,
        IEq | BEq => (x == y) as u32,
        INe => (x != y) as u32,
        And | BAnd => x & y,
        Or | BOr => x | y,
        Xor | BXor => x ^ y,
        Shl => x.wrapping_shl(y),
        AShr => i.wrapping_shr(y) as u32,
        LShr => x.wrapping_shr(y),
    }
}

enum Flow {
    Next,
    Break,
    Continue,
    Return,
    Discard,
}

struct Lane<'a> {
    regs: Vec<u32>,
    outputs: Vec<u32>,
    inputs: Vec<u32>,
    uniforms: &'a [u32],
}

impl Lane<'_> {
    fn inst(&mut self, inst: &Inst) {
        let r = |l: &Lane, r: Reg| l.regs[r.0 as usize];
        let value = match *inst {
            Inst::Const { value, .. } => value.bits(),
            Inst::Input { slot, .. } => self.inputs[slot as usize],
            Inst::Uniform { slot, .. } => self.uniforms[slot as usize],
            Inst::Mov { src, .. } => r(self, src),
            Inst::Unary { op, a, .. } => ref_unary(op, r(self, a)),
            Inst::Binary { op, a, b, .. } => ref_binary(op, r(self, a), r(self, b)),
            Inst::Mad { a, b, c, .. } => {
                let product = to_f64(from_f64(to_f64(r(self, a)) * to_f64(r(self, b))));
                from_f64(product + to_f64(r(self, c)))
            }
            Inst::Dot { n, a, b, .. } => {
                let mut sum = from_f64(to_f64(r(self, a[0])) * to_f64(r(self, b[0])));
                for k in 1..n as usize {
                    let p = to_f64(from_f64(to_f64(r(self, a[k])) * to_f64(r(self, b[k]))));
                    sum = from_f64(to_f64(sum) + p);
                }
                sum
            }
            Inst::Select { cond, a, b, .. } => {
                if r(self, cond) != 0 {
                    r(self, a)
                } else {
                    r(self, b)
                }
            }
            Inst::Derivative { .. } | Inst::Sample { .. } | Inst::Fetch { .. } | Inst::Size { .. } => {
                unreachable!("not generated")
            }
            Inst::Output { slot, src } => {
                self.outputs[slot as usize] = r(self, src);
                return;
            }
        };
        self.regs[inst.dst().unwrap().0 as usize] = value;
    }

    fn block(&mut self, stmts: &[Stmt]) -> Flow {
        for stmt in stmts {
            let flow = match stmt {
                Stmt::Inst(i) => {
                    self.inst(i);
                    Flow::Next
                }
                Stmt::If { cond, then, otherwise } => {
                    if self.regs[cond.0 as usize] != 0 {
                        self.block(then)
                    } else {
                        self.block(otherwise)
                    }
                }
                Stmt::Loop { body } => {
                    let mut flow = Flow::Next;
                    for _ in 0..MAX_LOOP_ITERATIONS {
                        match self.block(body) {
                            Flow::Next | Flow::Continue => continue,
                            Flow::Break => break,
                            f @ (Flow::Return | Flow::Discard) => {
                                flow = f;
                                break;
                            }
                        }
                    }
                    flow
                }
                Stmt::Break => Flow::Break,
                Stmt::Continue => Flow::Continue,
                Stmt::Return => Flow::Return,
                Stmt::Discard => Flow::Discard,
            };
            if !matches!(flow, Flow::Next) {
                return flow;
            }
        }
        Flow::Next
    }
}

// ---- Random programs ---------------------------------------------------------------

struct Generator {
    rng: Rng,
    program: Program,
    /// Registers the random statements may write, by type.
    pool: [Vec<Reg>; 4],
    loops: usize,
    depth: usize,
    budget: usize,
    /// Also derivatives and texture lookups (which the f64 reference does not model: the
    /// programs with them compare the executors with each other).
    cross_lane: bool,
}

fn type_index(t: Type) -> usize {
    match t {
        Type::F32 => 0,
        Type::I32 => 1,
        Type::U32 => 2,
        Type::Bool => 3,
    }
}

impl Generator {
    fn new(seed: u64, stage: Stage) -> Generator {
        let mut program = Program::new(stage);
        let mut pool: [Vec<Reg>; 4] = Default::default();
        for (t, n) in [(Type::F32, 6), (Type::I32, 3), (Type::U32, 2), (Type::Bool, 3)] {
            for _ in 0..n {
                pool[type_index(t)].push(program.register(t));
            }
        }
        for t in [Type::F32, Type::F32, Type::F32, Type::I32, Type::U32] {
            program.input(t);
        }
        program.uniform(Type::F32);
        program.uniform(Type::I32);
        for t in [Type::F32, Type::F32, Type::F32, Type::I32, Type::Bool] {
            program.output(t);
        }
        Generator { rng: Rng(seed | 1), program, pool, loops: 0, depth: 0, budget: 60, cross_lane: false }
    }

    fn reg(&mut self, t: Type) -> Reg {
        let pool = &self.pool[type_index(t)];
        pool[self.rng.below(pool.len())]
    }

    fn inst(&mut self) -> Inst {
        use BinaryOp::*;
        use UnaryOp::*;
        let f = Type::F32;
        if self.cross_lane && self.rng.chance(12) {
            return self.cross_lane_inst();
        }
        match self.rng.below(10) {
            0 => {
                let t = self.rng.pick(&[Type::F32, Type::I32, Type::U32, Type::Bool]);
                let value = match t {
                    Type::F32 => Const::F32(self.rng.float()),
                    Type::I32 => Const::I32(self.rng.int() as i32),
                    Type::U32 => Const::U32(self.rng.int()),
                    Type::Bool => Const::Bool(self.rng.chance(50)),
                };
                Inst::Const { dst: self.reg(t), value }
            }
            1 => {
                let slot = self.rng.below(self.program.inputs.len()) as u16;
                Inst::Input { dst: self.reg(self.program.inputs[slot as usize]), slot }
            }
            2 => {
                let slot = self.rng.below(2) as u16;
                Inst::Uniform { dst: self.reg(self.program.uniforms[slot as usize]), slot }
            }
            3 => {
                let (op, from, to) = self.rng.pick(&[
                    (FNeg, f, f),
                    (FAbs, f, f),
                    (FSign, f, f),
                    (Floor, f, f),
                    (Ceil, f, f),
                    (Trunc, f, f),
                    (Fract, f, f),
                    (RoundEven, f, f),
                    (Sqrt, f, f),
                    (Rcp, f, f),
                    (Rsq, f, f),
                    (F32ToI32, f, Type::I32),
                    (F32ToU32, f, Type::U32),
                    (I32ToF32, Type::I32, f),
                    (U32ToF32, Type::U32, f),
                    (BoolToF32, Type::Bool, f),
                    (F32ToBool, f, Type::Bool),
                    (INeg, Type::I32, Type::I32),
                    (IAbs, Type::I32, Type::I32),
                    (INot, Type::U32, Type::U32),
                    (BNot, Type::Bool, Type::Bool),
                    (Bitcast, Type::I32, Type::U32),
                ]);
                Inst::Unary { op, dst: self.reg(to), a: self.reg(from) }
            }
            4..=6 => {
                let (i, u, b) = (Type::I32, Type::U32, Type::Bool);
                let (op, operand, result) = self.rng.pick(&[
                    (FAdd, f, f),
                    (FSub, f, f),
                    (FMul, f, f),
                    (FDiv, f, f),
                    (FMin, f, f),
                    (FMax, f, f),
                    (FLt, f, b),
                    (FLe, f, b),
                    (FEq, f, b),
                    (FNe, f, b),
                    (IAdd, i, i),
                    (ISub, i, i),
                    (IMul, i, i),
                    (IDiv, i, i),
                    (IRem, i, i),
                    (IMin, i, i),
                    (IMax, i, i),
                    (UDiv, u, u),
                    (URem, u, u),
                    (UMin, u, u),
                    (UMax, u, u),
                    (ILt, i, b),
                    (ILe, i, b),
                    (ULt, u, b),
                    (ULe, u, b),
                    (IEq, i, b),
                    (INe, u, b),
                    (And, i, i),
                    (Or, u, u),
                    (Xor, i, i),
                    (Shl, u, u),
                    (AShr, i, i),
                    (LShr, u, u),
                    (BAnd, b, b),
                    (BOr, b, b),
                    (BXor, b, b),
                    (BEq, b, b),
                ]);
                Inst::Binary { op, dst: self.reg(result), a: self.reg(operand), b: self.reg(operand) }
            }
            7 => Inst::Mad { dst: self.reg(f), a: self.reg(f), b: self.reg(f), c: self.reg(f) },
            8 => {
                let n = 2 + self.rng.below(3) as u8;
                Inst::Dot { dst: self.reg(f), n, a: [0; 4].map(|_| self.reg(f)), b: [0; 4].map(|_| self.reg(f)) }
            }
            _ => {
                let t = self.rng.pick(&[Type::F32, Type::I32, Type::Bool]);
                if self.rng.chance(50) {
                    Inst::Select { dst: self.reg(t), cond: self.reg(Type::Bool), a: self.reg(t), b: self.reg(t) }
                } else {
                    let slot = self.rng.below(self.program.outputs.len()) as u16;
                    Inst::Output { slot, src: self.reg(self.program.outputs[slot as usize]) }
                }
            }
        }
    }

    /// A derivative (fragment programs) or a texture lookup of random registers.
    fn cross_lane_inst(&mut self) -> Inst {
        let f = Type::F32;
        let roll = self.rng.below(4);
        if roll == 0 && self.program.stage == Stage::Fragment {
            let axis = if self.rng.chance(50) { Axis::X } else { Axis::Y };
            return Inst::Derivative { dst: self.reg(f), axis, a: self.reg(f) };
        }
        let unit = self.rng.below(4) as u8;
        if roll == 1 {
            let lod = self.reg(Type::I32);
            return Inst::Size { dst: [0; 3].map(|_| self.reg(Type::I32)), unit, lod };
        }
        if roll == 2 {
            let dst = [0; 4].map(|_| self.reg(f));
            let coords = [0; 3].map(|_| self.reg(Type::I32));
            return Inst::Fetch { dst, unit, n: 2, coords, lod: self.reg(Type::I32) };
        }
        let n = 1 + self.rng.below(3) as u8;
        let lod = match self.rng.below(3) {
            0 if self.program.stage == Stage::Fragment => Lod::Implicit,
            1 if self.program.stage == Stage::Fragment => Lod::Bias(self.reg(f)),
            _ => Lod::Explicit(self.reg(f)),
        };
        let compare = if self.rng.chance(30) { Some(self.reg(f)) } else { None };
        Inst::Sample {
            dst: [0; 4].map(|_| self.reg(f)),
            unit,
            n,
            coords: [0; 4].map(|_| self.reg(f)),
            projective: self.rng.chance(30),
            lod,
            compare,
        }
    }

    fn block(&mut self) -> Vec<Stmt> {
        let mut out = Vec::new();
        let n = 1 + self.rng.below(6);
        for _ in 0..n {
            if self.budget == 0 {
                break;
            }
            self.budget -= 1;
            let roll = self.rng.below(100);
            if roll < 12 && self.depth < 4 {
                self.depth += 1;
                let cond = self.reg(Type::Bool);
                let then = self.block();
                let otherwise = if self.rng.chance(50) { self.block() } else { Vec::new() };
                out.push(Stmt::If { cond, then, otherwise });
                self.depth -= 1;
            } else if roll < 18 && self.depth < 4 {
                out.extend(self.counted_loop());
            } else if roll < 21 && self.loops > 0 {
                let stmt = if self.rng.chance(50) { Stmt::Break } else { Stmt::Continue };
                out.push(Stmt::If { cond: self.reg(Type::Bool), then: vec![stmt], otherwise: vec![] });
            } else if roll < 23 {
                let stmt = if self.program.stage == Stage::Fragment && self.rng.chance(60) {
                    Stmt::Discard
                } else {
                    Stmt::Return
                };
                out.push(Stmt::If { cond: self.reg(Type::Bool), then: vec![stmt], otherwise: vec![] });
            } else {
                out.push(Stmt::Inst(self.inst()));
            }
        }
        out
    }

    /// `counter = 0; loop { counter += 1; if limit < counter { break } … }`: a loop that
    /// ends after at most `limit` iterations whatever its random body does (the counter is
    /// outside the random statements' pool).
    fn counted_loop(&mut self) -> Vec<Stmt> {
        let counter = self.program.register(Type::I32);
        let one = self.program.register(Type::I32);
        let limit = self.program.register(Type::I32);
        let done = self.program.register(Type::Bool);
        let n = self.rng.below(5) as i32;
        self.depth += 1;
        self.loops += 1;
        let mut body = vec![
            Stmt::Inst(Inst::Binary { op: BinaryOp::IAdd, dst: counter, a: counter, b: one }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::ILt, dst: done, a: limit, b: counter }),
            Stmt::If { cond: done, then: vec![Stmt::Break], otherwise: vec![] },
        ];
        body.extend(self.block());
        self.loops -= 1;
        self.depth -= 1;
        vec![
            Stmt::Inst(Inst::Const { dst: counter, value: Const::I32(0) }),
            Stmt::Inst(Inst::Const { dst: one, value: Const::I32(1) }),
            Stmt::Inst(Inst::Const { dst: limit, value: Const::I32(n) }),
            Stmt::Loop { body },
        ]
    }

    fn program(mut self) -> Program {
        let mut body = Vec::new();
        for (slot, reg) in [(0, 0), (1, 1), (2, 2)] {
            body.push(Stmt::Inst(Inst::Input { dst: self.pool[0][reg], slot }));
        }
        body.push(Stmt::Inst(Inst::Input { dst: self.pool[1][0], slot: 3 }));
        body.push(Stmt::Inst(Inst::Input { dst: self.pool[2][0], slot: 4 }));
        body.push(Stmt::Inst(Inst::Binary {
            op: BinaryOp::FLt,
            dst: self.pool[3][0],
            a: self.pool[0][0],
            b: self.pool[0][1],
        }));
        while self.budget > 0 {
            let block = self.block();
            body.extend(block);
        }
        for slot in 0..self.program.outputs.len() as u16 {
            let src = self.reg(self.program.outputs[slot as usize]);
            body.push(Stmt::Inst(Inst::Output { slot, src }));
        }
        self.program.body = body;
        self.program
    }
}

/// A NaN's sign and payload are the CPU's (x86 passes on the first operand's NaN, and the
/// compiler may swap the operands of a commutative operation): every NaN as one.
fn canonical_nan(bits: u32) -> u32 {
    if f32::from_bits(bits).is_nan() {
        f32::NAN.to_bits()
    } else {
        bits
    }
}

/// Outputs with their f32 words' NaNs made one.
fn canonical_outputs(program: &Program, mut outputs: Vec<Word>) -> Vec<Word> {
    for (word, ty) in outputs.iter_mut().zip(&program.outputs) {
        if *ty == Type::F32 {
            *word = word.map(canonical_nan);
        }
    }
    outputs
}

fn same_word(a: u32, b: u32, ty: Type) -> bool {
    a == b || (ty == Type::F32 && f32::from_bits(a).is_nan() && f32::from_bits(b).is_nan())
}

#[test]
fn random_programs_match_the_scalar_f64_reference_lane_by_lane() {
    let mut rng = Rng(0x5eed_1234_abcd_9876);
    let mut executor = Executor::new();
    let mut registers = Registers::new();
    let mut discards = 0;
    let mut loops_run = 0;
    for case in 0..3000u64 {
        let stage = if case % 2 == 0 { Stage::Fragment } else { Stage::Vertex };
        let program = Generator::new(rng.next(), stage).program();
        validate(&program).unwrap_or_else(|e| panic!("case {case}: {e}\n{}", super::dump::dump(&program)));
        loops_run += program.body.iter().filter(|s| matches!(s, Stmt::Loop { .. })).count();
        let inputs: Vec<Word> = program
            .inputs
            .iter()
            .map(|t| std::array::from_fn(|_| if *t == Type::F32 { rng.float().to_bits() } else { rng.int() }))
            .collect();
        let uniforms = [rng.float().to_bits(), rng.int()];
        let mut outputs = vec![[0u32; LANES]; program.outputs.len()];
        let lanes = if rng.chance(70) { ALL_LANES } else { rng.next() as u16 };
        let alive = executor.run(
            &program,
            &mut Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &NoTextures },
            lanes,
        );
        // The compiled executors give the reference executor's bits in every lane.
        let (compiled, threaded) = (Compiled::new(&program), Threaded::new(&program));
        let specialized = compiled.specialize(&uniforms);
        for which in 0..6 {
            let mut fast_outputs = vec![[0u32; LANES]; program.outputs.len()];
            let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut fast_outputs, textures: &NoTextures };
            let fast_alive = match which {
                0 => compiled.run(&mut registers, &mut io, lanes),
                1 => threaded.run(&mut registers, &mut io, lanes),
                // The uniform prologue once, then the rest (twice: the prologue's registers
                // survive a run).
                2 => {
                    compiled.prepare(&mut registers, &uniforms);
                    compiled.run_prepared(&mut registers, &mut io, lanes)
                }
                3 => compiled.run_prepared(&mut registers, &mut io, lanes),
                // Specialised on the uniforms, the same (twice, too).
                4 => {
                    compiled.prepare_specialized(&specialized, &mut registers);
                    compiled.run_specialized(&specialized, &mut registers, &mut io, lanes)
                }
                _ => compiled.run_specialized(&specialized, &mut registers, &mut io, lanes),
            };
            assert_eq!(fast_alive, alive, "case {case} ({which}): discards differ\n{}", super::dump::dump(&program));
            assert_eq!(
                canonical_outputs(&program, fast_outputs),
                canonical_outputs(&program, outputs.clone()),
                "case {case} ({which}): outputs differ\n{}\n{:#?}",
                super::dump::dump(&program),
                compiled.code()
            );
        }
        for lane in 0..LANES {
            if lanes >> lane & 1 == 0 {
                assert!(outputs.iter().all(|o| o[lane] == 0), "case {case}: lane {lane} was not running");
                assert_eq!(alive >> lane & 1, 0);
                continue;
            }
            let mut reference = Lane {
                regs: vec![0; program.registers.len()],
                outputs: vec![0; program.outputs.len()],
                inputs: inputs.iter().map(|w| w[lane]).collect(),
                uniforms: &uniforms,
            };
            let discarded = matches!(reference.block(&program.body), Flow::Discard);
            discards += discarded as usize;
            assert_eq!(
                alive >> lane & 1 == 0,
                discarded,
                "case {case}, lane {lane}: discard differs\n{}",
                super::dump::dump(&program)
            );
            for (slot, ty) in program.outputs.iter().enumerate() {
                let (got, want) = (outputs[slot][lane], reference.outputs[slot]);
                assert!(
                    same_word(got, want, *ty),
                    "case {case}, lane {lane}, output {slot}: {got:#x} vs reference {want:#x}\n{}",
                    super::dump::dump(&program)
                );
            }
        }
    }
    // The generator exercised what it is for.
    assert!(discards > 1000 && loops_run > 1000, "discards {discards}, loops {loops_run}");
}

#[test]
fn a_loop_that_never_ends_stops_at_the_iteration_bound() {
    let mut p = Program::new(Stage::Fragment);
    let count = p.register(Type::I32);
    let one = p.register(Type::I32);
    p.output(Type::I32);
    p.body = vec![
        Stmt::Inst(Inst::Const { dst: one, value: Const::I32(1) }),
        Stmt::Loop { body: vec![Stmt::Inst(Inst::Binary { op: BinaryOp::IAdd, dst: count, a: count, b: one })] },
        Stmt::Inst(Inst::Output { slot: 0, src: count }),
    ];
    validate(&p).unwrap();
    let mut out = vec![[0u32; LANES]];
    let alive = Executor::new().run(
        &p,
        &mut Io { inputs: &[], uniforms: &[], outputs: &mut out, textures: &NoTextures },
        ALL_LANES,
    );
    assert_eq!(alive, ALL_LANES);
    assert_eq!(out[0], [MAX_LOOP_ITERATIONS; LANES]);
    // The compiled executors stop there too (the counter is uniform there: scalar).
    for which in 0..2 {
        let mut fast = vec![[0u32; LANES]];
        let mut io = Io { inputs: &[], uniforms: &[], outputs: &mut fast, textures: &NoTextures };
        let alive = if which == 0 {
            Compiled::new(&p).run(&mut Registers::new(), &mut io, 0x0ff0)
        } else {
            Threaded::new(&p).run(&mut Registers::new(), &mut io, 0x0ff0)
        };
        assert_eq!(alive, 0x0ff0);
        let expected: Word = std::array::from_fn(|i| if 0x0ff0 >> i & 1 != 0 { MAX_LOOP_ITERATIONS } else { 0 });
        assert_eq!(fast[0], expected);
    }
}

#[test]
fn derivatives_are_the_differences_across_each_quad() {
    let mut p = Program::new(Stage::Fragment);
    let x = p.register(Type::F32);
    let dx = p.register(Type::F32);
    let dy = p.register(Type::F32);
    p.input(Type::F32);
    p.output(Type::F32);
    p.output(Type::F32);
    p.body = vec![
        Stmt::Inst(Inst::Input { dst: x, slot: 0 }),
        Stmt::Inst(Inst::Derivative { dst: dx, axis: Axis::X, a: x }),
        Stmt::Inst(Inst::Derivative { dst: dy, axis: Axis::Y, a: x }),
        Stmt::Inst(Inst::Output { slot: 0, src: dx }),
        Stmt::Inst(Inst::Output { slot: 1, src: dy }),
    ];
    validate(&p).unwrap();
    // x² + 10·y² over the block: per quad, the right pixel minus the left on the lane's own
    // row, the lower pixel minus the upper in the lane's own column.
    let value = |c: usize, r: usize| (c * c + 10 * r * r) as f32;
    let input: Word = std::array::from_fn(|i| value(i & 3, i >> 2).to_bits());
    // The reference, the interpreter and the closures.
    for which in 0..3 {
        let mut out = vec![[0u32; LANES]; 2];
        let mut io = Io { inputs: &[input], uniforms: &[], outputs: &mut out, textures: &NoTextures };
        match which {
            0 => Executor::new().run(&p, &mut io, ALL_LANES),
            1 => Compiled::new(&p).run(&mut Registers::new(), &mut io, ALL_LANES),
            _ => Threaded::new(&p).run(&mut Registers::new(), &mut io, ALL_LANES),
        };
        for (i, (dx, dy)) in out[0].iter().zip(&out[1]).enumerate() {
            let (c, r) = (i & 3, i >> 2);
            let (c0, r0) = (c & !1, r & !1);
            assert_eq!(f32::from_bits(*dx), value(c0 + 1, r) - value(c0, r), "ddx at lane {i} ({which})");
            assert_eq!(f32::from_bits(*dy), value(c, r0 + 1) - value(c, r0), "ddy at lane {i} ({which})");
        }
    }
}

/// A texture whose texel at (s, t) is (s + t, s·t, unit, λ or −1) and which records what it
/// was asked.
struct Probe(std::cell::RefCell<Vec<(u8, u16, bool)>>);

impl Textures for Probe {
    fn sample(&self, r: &SampleRequest<'_>, out: &mut [Word; 4]) {
        self.0.borrow_mut().push((r.unit, r.lanes, r.projective));
        let lod = match r.lod {
            LodLanes::Explicit(w) => Some(w),
            _ => None,
        };
        for i in 0..LANES {
            let (s, t) = (f32::from_bits(r.coords[0][i]), f32::from_bits(r.coords[1][i]));
            out[0][i] = (s + t).to_bits();
            out[1][i] = (s * t).to_bits();
            out[2][i] = (r.unit as f32).to_bits();
            out[3][i] = lod.map_or((-1.0f32).to_bits(), |w| w[i]);
        }
    }

    fn fetch(&self, unit: u8, _: u8, coords: &[Word; 3], _: &Word, lanes: u16, out: &mut [Word; 4]) {
        self.0.borrow_mut().push((unit, lanes, false));
        out[0] = coords[0].map(|c| (c as i32 as f32).to_bits());
    }

    fn size(&self, unit: u8, lod: &Word, lanes: u16, out: &mut [Word; 3]) {
        self.0.borrow_mut().push((unit, lanes, false));
        out[0] = lod.map(|l| 64 >> l);
    }
}

#[test]
fn texture_lookups_ask_the_sampler_with_the_running_lanes_and_write_only_those() {
    let mut p = Program::new(Stage::Fragment);
    let s = p.register(Type::F32);
    let t = p.register(Type::F32);
    let lod = p.register(Type::F32);
    let texel: [Reg; 4] = std::array::from_fn(|_| p.register(Type::F32));
    let take = p.register(Type::Bool);
    let ilod = p.register(Type::I32);
    let size: [Reg; 3] = std::array::from_fn(|_| p.register(Type::I32));
    for _ in 0..2 {
        p.input(Type::F32);
    }
    for _ in 0..5 {
        p.output(Type::F32);
    }
    p.output(Type::I32);
    let sample = |unit, lod| Inst::Sample {
        dst: texel,
        unit,
        n: 2,
        coords: [s, t, s, s],
        projective: false,
        lod,
        compare: None,
    };
    p.body = vec![
        Stmt::Inst(Inst::Input { dst: s, slot: 0 }),
        Stmt::Inst(Inst::Input { dst: t, slot: 1 }),
        Stmt::Inst(Inst::Const { dst: lod, value: Const::F32(2.5) }),
        Stmt::Inst(sample(3, Lod::Implicit)),
        // Lanes whose s is below 2 look up again with an explicit level on unit 1.
        Stmt::Inst(Inst::Const { dst: texel[3], value: Const::F32(2.0) }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FLt, dst: take, a: s, b: texel[3] }),
        Stmt::Inst(sample(3, Lod::Implicit)),
        Stmt::If { cond: take, then: vec![Stmt::Inst(sample(1, Lod::Explicit(lod)))], otherwise: vec![] },
        Stmt::Inst(Inst::Const { dst: ilod, value: Const::I32(2) }),
        Stmt::Inst(Inst::Size { dst: size, unit: 0, lod: ilod }),
        Stmt::Inst(Inst::Output { slot: 0, src: texel[0] }),
        Stmt::Inst(Inst::Output { slot: 1, src: texel[1] }),
        Stmt::Inst(Inst::Output { slot: 2, src: texel[2] }),
        Stmt::Inst(Inst::Output { slot: 3, src: texel[3] }),
        Stmt::Inst(Inst::Output { slot: 5, src: size[0] }),
    ];
    validate(&p).unwrap();
    let inputs: [Word; 2] = [std::array::from_fn(|i| (i as f32 * 0.25).to_bits()), [1.5f32.to_bits(); LANES]];
    let lanes = 0x7fff;
    // The reference, the interpreter and the closures.
    for which in 0..3 {
        let mut out = vec![[0u32; LANES]; 6];
        let probe = Probe(Default::default());
        let mut io = Io { inputs: &inputs, uniforms: &[], outputs: &mut out, textures: &probe };
        match which {
            0 => Executor::new().run(&p, &mut io, lanes),
            1 => Compiled::new(&p).run(&mut Registers::new(), &mut io, lanes),
            _ => Threaded::new(&p).run(&mut Registers::new(), &mut io, lanes),
        };
        // s = i/4 < 2 for lanes 0..8.
        assert_eq!(*probe.0.borrow(), vec![(3, lanes, false), (3, lanes, false), (1, 0xff, false), (0, lanes, false)]);
        for (i, size) in out[5].iter().enumerate().take(15) {
            let s = i as f32 * 0.25;
            let texel = [out[0][i], out[1][i], out[2][i], out[3][i]].map(f32::from_bits);
            let (unit, lod) = if i < 8 { (1.0, 2.5) } else { (3.0, -1.0) };
            assert_eq!(texel, [s + 1.5, s * 1.5, unit, lod], "lane {i}");
            assert_eq!(*size, 16, "size of level 2 at lane {i}");
        }
        assert_eq!(out.iter().map(|o| o[15]).collect::<Vec<_>>(), vec![0; 6], "lane 15 was not running");
    }
}

/// A texture that records every request whole (all 16 lanes of every operand word) and
/// answers with a function of each lane's coordinates, in every lane.
#[derive(Default)]
struct Recorder(std::cell::RefCell<Vec<Vec<u32>>>);

impl Textures for Recorder {
    // Lane i of several words at once.
    #[allow(clippy::needless_range_loop)]
    fn sample(&self, r: &SampleRequest<'_>, out: &mut [Word; 4]) {
        let mut log = vec![0, r.unit as u32, r.n as u32, r.projective as u32, r.lanes as u32];
        r.coords.iter().for_each(|w| log.extend(w));
        match r.lod {
            LodLanes::Implicit => log.push(7),
            LodLanes::Bias(w) | LodLanes::Explicit(w) => log.extend(w),
        }
        r.compare.into_iter().for_each(|w| log.extend(w));
        self.0.borrow_mut().push(log);
        for i in 0..LANES {
            let (s, t) = (f32::from_bits(r.coords[0][i]), f32::from_bits(r.coords[1][i]));
            out[0][i] = (s + t).to_bits();
            out[1][i] = (s * t).to_bits();
            out[2][i] = (s - r.unit as f32).to_bits();
            out[3][i] = ((f32::from_bits(r.coords[2][i]) < f32::from_bits(r.coords[3][i])) as u32 as f32).to_bits();
        }
    }

    fn fetch(&self, unit: u8, n: u8, coords: &[Word; 3], lod: &Word, lanes: u16, out: &mut [Word; 4]) {
        let mut log = vec![1, unit as u32, n as u32, lanes as u32];
        coords.iter().chain([lod]).for_each(|w| log.extend(w));
        self.0.borrow_mut().push(log);
        for i in 0..LANES {
            out[0][i] = (coords[0][i] as i32 as f32).to_bits();
            out[1][i] = ((coords[1][i] as i32).wrapping_mul(3) as f32).to_bits();
            out[2][i] = (lod[i] as i32 as f32).to_bits();
        }
    }

    fn size(&self, unit: u8, lod: &Word, lanes: u16, out: &mut [Word; 3]) {
        let mut log = vec![2, unit as u32, lanes as u32];
        log.extend(lod);
        self.0.borrow_mut().push(log);
        for i in 0..LANES {
            out[0][i] = 64u32.wrapping_shr(lod[i]);
            out[1][i] = lod[i].wrapping_add(unit as u32);
            out[2][i] = 5;
        }
    }
}

#[test]
fn compiled_executors_match_the_reference_with_derivatives_and_texture_lookups() {
    let mut rng = Rng(0xc0ff_ee12_3456_789a);
    let mut executor = Executor::new();
    let mut registers = Registers::new();
    let mut requests = 0;
    for case in 0..3000u64 {
        let stage = if case % 3 == 0 { Stage::Vertex } else { Stage::Fragment };
        let mut generator = Generator::new(rng.next(), stage);
        generator.cross_lane = true;
        let program = generator.program();
        validate(&program).unwrap_or_else(|e| panic!("case {case}: {e}\n{}", super::dump::dump(&program)));
        let inputs: Vec<Word> = program
            .inputs
            .iter()
            .map(|t| std::array::from_fn(|_| if *t == Type::F32 { rng.float().to_bits() } else { rng.int() }))
            .collect();
        let uniforms = [rng.float().to_bits(), rng.int()];
        let lanes = if rng.chance(60) { ALL_LANES } else { rng.next() as u16 };
        let run = |which: usize, registers: &mut Registers, executor: &mut Executor| {
            let textures = Recorder::default();
            let mut outputs = vec![[0u32; LANES]; program.outputs.len()];
            let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &textures };
            let alive = match which {
                0 => executor.run(&program, &mut io, lanes),
                1 => Compiled::new(&program).run(registers, &mut io, lanes),
                2 => Threaded::new(&program).run(registers, &mut io, lanes),
                // Specialised on the uniforms.
                _ => {
                    let compiled = Compiled::new(&program);
                    let specialized = compiled.specialize(&uniforms);
                    compiled.prepare_specialized(&specialized, registers);
                    compiled.run_specialized(&specialized, registers, &mut io, lanes)
                }
            };
            // Requests compared with every NaN as one (see `canonical_nan`).
            let log: Vec<Vec<u32>> =
                textures.0.into_inner().into_iter().map(|r| r.into_iter().map(canonical_nan).collect()).collect();
            (alive, canonical_outputs(&program, outputs), log)
        };
        let reference = run(0, &mut registers, &mut executor);
        requests += reference.2.len();
        for which in 1..4 {
            let got = run(which, &mut registers, &mut executor);
            assert!(got == reference, "case {case} ({which}) differs\n{}", super::dump::dump(&program));
        }
    }
    assert!(requests > 3000, "only {requests} texture requests");
}

#[test]
fn the_colour_clamp_is_fused_and_keeps_its_bits() {
    // `0 < x ? min(x, 1) : 0` as the fixed-function generators write it: one operation,
    // the three instructions' bits on NaN, ±0, ±∞, denormals and values around 0 and 1,
    // with every lane running and with a partial mask.
    let mut p = Program::new(Stage::Fragment);
    let [x, zero, one] = [0; 3].map(|_| p.register(Type::F32));
    let positive = p.register(Type::Bool);
    let [at_most_one, clamped] = [0; 2].map(|_| p.register(Type::F32));
    p.input(Type::F32);
    p.output(Type::F32);
    p.body = vec![
        Stmt::Inst(Inst::Input { dst: x, slot: 0 }),
        Stmt::Inst(Inst::Const { dst: zero, value: Const::F32(0.0) }),
        Stmt::Inst(Inst::Const { dst: one, value: Const::F32(1.0) }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FLt, dst: positive, a: zero, b: x }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FMin, dst: at_most_one, a: x, b: one }),
        Stmt::Inst(Inst::Select { dst: clamped, cond: positive, a: at_most_one, b: zero }),
        Stmt::Inst(Inst::Output { slot: 0, src: clamped }),
    ];
    validate(&p).unwrap();
    let compiled = Compiled::new(&p);
    let fused = compiled.code().ops.iter().filter(|o| matches!(o, super::lower::Op::ClampSelect { .. })).count();
    assert_eq!(fused, 1, "{:#?}", compiled.code());
    let values = [
        f32::NAN,
        -f32::NAN,
        0.0,
        -0.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        1e-45,
        -1e-45,
        0.5,
        1.0,
        f32::from_bits(1f32.to_bits() + 1),
        f32::from_bits(1f32.to_bits() - 1),
        -0.25,
        2.0,
        1e30,
        0.999,
    ];
    let input: Word = std::array::from_fn(|i| values[i].to_bits());
    for lanes in [ALL_LANES, 0x5a5a] {
        let mut want = vec![[0u32; LANES]];
        Executor::new().run(
            &p,
            &mut Io { inputs: &[input], uniforms: &[], outputs: &mut want, textures: &NoTextures },
            lanes,
        );
        for i in (0..LANES).filter(|i| lanes >> i & 1 != 0) {
            let v = values[i];
            let expected = if v > 0.0 { v.min(1.0) } else { 0.0 };
            assert_eq!(want[0][i], expected.to_bits(), "the reference, lane {i}");
        }
        for which in 0..2 {
            let mut got = vec![[0u32; LANES]];
            let mut io = Io { inputs: &[input], uniforms: &[], outputs: &mut got, textures: &NoTextures };
            if which == 0 {
                compiled.run(&mut Registers::new(), &mut io, lanes);
            } else {
                Threaded::new(&p).run(&mut Registers::new(), &mut io, lanes);
            }
            assert_eq!(got, want, "design {which}, lanes {lanes:#x}");
        }
    }
}

/// `FMin` / `FMax` with a NaN operand give the other operand (Mesa's min and max; piglit
/// `*-nan-builtin-min/max`), equal operands (±0) the first, on the reference, the compiled
/// executor (its `Min`, `Max` and the fused `Clamp` of `max` then `min`) and the closures,
/// the same bits (run at each `TESSERA_SIMD` level).
#[test]
fn min_and_max_with_a_nan_operand_give_the_other_operand() {
    let mut p = Program::new(Stage::Fragment);
    let [x, y, lo, hi, mn, mx, t, clamped] = [0; 8].map(|_| p.register(Type::F32));
    for _ in 0..4 {
        p.input(Type::F32);
    }
    for _ in 0..3 {
        p.output(Type::F32);
    }
    p.body = vec![
        Stmt::Inst(Inst::Input { dst: x, slot: 0 }),
        Stmt::Inst(Inst::Input { dst: y, slot: 1 }),
        Stmt::Inst(Inst::Input { dst: lo, slot: 2 }),
        Stmt::Inst(Inst::Input { dst: hi, slot: 3 }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FMin, dst: mn, a: x, b: y }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FMax, dst: mx, a: x, b: y }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FMax, dst: t, a: x, b: lo }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FMin, dst: clamped, a: t, b: hi }),
        Stmt::Inst(Inst::Output { slot: 0, src: mn }),
        Stmt::Inst(Inst::Output { slot: 1, src: mx }),
        Stmt::Inst(Inst::Output { slot: 2, src: clamped }),
    ];
    validate(&p).unwrap();
    let compiled = Compiled::new(&p);
    let fused = compiled.code().ops.iter().filter(|o| matches!(o, super::lower::Op::Clamp { .. })).count();
    assert_eq!(fused, 1, "{:#?}", compiled.code());
    let values = [f32::NAN, 1.5, -2.0, 0.0, -0.0, f32::INFINITY, f32::NEG_INFINITY, -f32::NAN];
    let min = |a: f32, b: f32| if a.is_nan() || b < a { b } else { a };
    let max = |a: f32, b: f32| if a.is_nan() || a < b { b } else { a };
    // Every pair of values for x and y, and as the clamp's bounds.
    let pairs: Vec<(f32, f32)> = values.iter().flat_map(|&a| values.iter().map(move |&b| (a, b))).collect();
    for block in pairs.chunks(LANES) {
        let lane = |k: usize| block[k % block.len()];
        let word = |g: &dyn Fn(usize) -> f32| -> Word { std::array::from_fn(|k| g(k).to_bits()) };
        let inputs = [word(&|k| lane(k).0), word(&|k| lane(k).1), word(&|k| lane(k).1), word(&|k| lane(k).0)];
        let mut want = vec![[0u32; LANES]; 3];
        let io = &mut Io { inputs: &inputs, uniforms: &[], outputs: &mut want, textures: &NoTextures };
        Executor::new().run(&p, io, ALL_LANES);
        for (k, words) in (0..LANES).map(|k| (k, want.iter().map(|w| w[k]).collect::<Vec<u32>>())) {
            let (a, b) = lane(k);
            let expected = [min(a, b), max(a, b), min(max(a, b), a)].map(f32::to_bits);
            assert_eq!(words, expected, "min({a}, {b}), max({a}, {b}), clamp({a}, {b}, {a})");
        }
        assert!(min(f32::NAN, 1.5) == 1.5 && max(1.5, f32::NAN) == 1.5);
        for which in 0..2 {
            let mut got = vec![[0u32; LANES]; 3];
            let mut io = Io { inputs: &inputs, uniforms: &[], outputs: &mut got, textures: &NoTextures };
            if which == 0 {
                compiled.run(&mut Registers::new(), &mut io, ALL_LANES);
            } else {
                Threaded::new(&p).run(&mut Registers::new(), &mut io, ALL_LANES);
            }
            assert_eq!(got, want, "design {which}");
        }
    }
}

#[test]
fn two_products_and_their_sum_are_a_dot2_with_their_bits() {
    // `a·b + c·e` (texture environments, fog): one dot2, each product and the sum rounded
    // once as the three instructions round them (NaN as any NaN, as everywhere: LLVM may
    // commute an addition, so a NaN's sign is not a promise); the sum written the other
    // way round (`u + t`) is left as it is.
    for swapped in [false, true] {
        let mut p = Program::new(Stage::Fragment);
        let regs: Vec<Reg> = (0..7).map(|_| p.register(Type::F32)).collect();
        let (t, u, d) = (regs[4], regs[5], regs[6]);
        let mut body: Vec<Stmt> = (0..4)
            .map(|k| {
                p.input(Type::F32);
                Stmt::Inst(Inst::Input { dst: regs[k], slot: k as u16 })
            })
            .collect();
        p.output(Type::F32);
        let (first, second) = if swapped { (u, t) } else { (t, u) };
        body.extend([
            Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst: t, a: regs[0], b: regs[1] }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst: u, a: regs[2], b: regs[3] }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FAdd, dst: d, a: first, b: second }),
            Stmt::Inst(Inst::Output { slot: 0, src: d }),
        ]);
        p.body = body;
        validate(&p).unwrap();
        let compiled = Compiled::new(&p);
        let fused = compiled.code().ops.iter().filter(|o| matches!(o, super::lower::Op::Dot2 { .. })).count();
        assert_eq!(fused, usize::from(!swapped), "{:#?}", compiled.code());
        let mut rng = Rng(0xd072_0000_1111 + swapped as u64);
        let specials = [f32::NAN, -f32::NAN, 0.0, -0.0, f32::INFINITY, 1e-45, 3.0e38, 0.1];
        let inputs: Vec<Word> = (0..4)
            .map(|_| {
                std::array::from_fn(|i| {
                    if i < 8 { specials[(i + rng.next() as usize) % 8] } else { rng.float() }.to_bits()
                })
            })
            .collect();
        for lanes in [ALL_LANES, 0x3c3c] {
            let mut want = vec![[0u32; LANES]];
            Executor::new().run(
                &p,
                &mut Io { inputs: &inputs, uniforms: &[], outputs: &mut want, textures: &NoTextures },
                lanes,
            );
            let mut got = vec![[0u32; LANES]];
            let mut io = Io { inputs: &inputs, uniforms: &[], outputs: &mut got, textures: &NoTextures };
            compiled.run(&mut Registers::new(), &mut io, lanes);
            for i in 0..LANES {
                assert!(same_word(got[0][i], want[0][i], Type::F32), "lanes {lanes:#x}, lane {i}");
            }
            assert!(want[0].iter().any(|&w| !f32::from_bits(w).is_nan() && w != 0), "finite sums compared");
        }
    }
}

/// Runs `program`'s bound form ([`Compiled::bind`]) as the fragment pipeline does: the
/// uniform prologue once, each input written into its register in every lane, each output
/// read from its register. `None` if the program has no bound form.
fn run_bound(program: &Program, inputs: &[Word], uniforms: &[u32], lanes: u16) -> Option<Vec<Word>> {
    let bound = Compiled::new(program).bind()?;
    let mut registers = Registers::new();
    bound.prepare(&mut registers, uniforms);
    let mut outputs = Vec::new();
    // Twice: the prepared registers survive a run.
    for _ in 0..2 {
        for (slot, word) in inputs.iter().enumerate() {
            if let Some(r) = bound.input(&mut registers, slot) {
                *r = *word;
            }
        }
        let mut io = Io { inputs: &[], uniforms, outputs: &mut [], textures: &NoTextures };
        bound.run(&mut registers, &mut io, lanes);
        outputs = (0..program.outputs.len())
            .map(|slot| bound.output(&registers, slot).copied().unwrap_or([0; LANES]))
            .collect();
    }
    Some(outputs)
}

#[test]
fn bound_straight_programs_match_the_reference_in_the_running_lanes() {
    // The random programs' top-level instructions alone (no control flow): the bound form
    // gives the reference's bits in every running lane.
    let mut rng = Rng(0xb0b0_7777_1234_5678);
    let mut executor = Executor::new();
    let mut bound = 0;
    for case in 0..3000u64 {
        let stage = if case % 2 == 0 { Stage::Fragment } else { Stage::Vertex };
        let mut program = Generator::new(rng.next(), stage).program();
        program.body.retain(|s| matches!(s, Stmt::Inst(_)));
        validate(&program).unwrap_or_else(|e| panic!("case {case}: {e}\n{}", super::dump::dump(&program)));
        let inputs: Vec<Word> = program
            .inputs
            .iter()
            .map(|t| std::array::from_fn(|_| if *t == Type::F32 { rng.float().to_bits() } else { rng.int() }))
            .collect();
        let uniforms = [rng.float().to_bits(), rng.int()];
        let mut want = vec![[0u32; LANES]; program.outputs.len()];
        let lanes = if rng.chance(60) { ALL_LANES } else { rng.next() as u16 };
        executor.run(
            &program,
            &mut Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut want, textures: &NoTextures },
            lanes,
        );
        let Some(got) = run_bound(&program, &inputs, &uniforms, lanes) else { continue };
        bound += 1;
        for (slot, ty) in program.outputs.iter().enumerate() {
            for lane in (0..LANES).filter(|l| lanes >> l & 1 != 0) {
                assert!(
                    same_word(got[slot][lane], want[slot][lane], *ty),
                    "case {case}, lane {lane}, output {slot}: {:#x} vs {:#x}\n{}",
                    got[slot][lane],
                    want[slot][lane],
                    super::dump::dump(&program)
                );
            }
        }
    }
    assert!(bound > 200, "only {bound} programs bound");
}

/// Lanes of special values (NaN, ±0, ±∞, denormals, values around 0 and 1) and random ones.
fn special_word(rng: &mut Rng) -> Word {
    let specials = [f32::NAN, -0.0, 0.0, f32::INFINITY, f32::NEG_INFINITY, 1e-45, -1e-40, 1.0, 0.5, 3.0e38, -2.0];
    std::array::from_fn(|i| {
        if i < 8 { specials[(i + rng.next() as usize) % specials.len()] } else { rng.float() }.to_bits()
    })
}

#[test]
fn the_fused_fragment_patterns_keep_their_bits() {
    // Linear fog (its ramp and the three channels' blend) and a modulate with the colour
    // clamp, as the fixed-function generator writes them: fused in the bound form, and the
    // reference's bits in the running lanes on special values, with every lane running and
    // with partial masks. With 300 live registers before them (a sum of 300 inputs, output
    // last), their registers lie past the 256 a fused operation can index: not fused, and
    // the same bits.
    for padding in [0, 300] {
        fused_fragment_patterns(padding);
    }
}

fn fused_fragment_patterns(padding: usize) {
    let mut p = Program::new(Stage::Fragment);
    let f32s = |p: &mut Program, n: usize| (0..n).map(|_| p.register(Type::F32)).collect::<Vec<Reg>>();
    let mut body = Vec::new();
    let mut sum = None;
    for k in 0..padding {
        let r = p.register(Type::F32);
        p.input(Type::F32);
        body.push(Stmt::Inst(Inst::Input { dst: r, slot: k as u16 }));
        sum = Some(match sum {
            None => r,
            Some(a) => {
                let d = p.register(Type::F32);
                body.push(Stmt::Inst(Inst::Binary { op: BinaryOp::FAdd, dst: d, a, b: r }));
                d
            }
        });
    }
    let color = f32s(&mut p, 4);
    let texel = f32s(&mut p, 4);
    let [coord, end, start, zero, one, t, span, u, factor, rest] = f32s(&mut p, 10).try_into().unwrap();
    let fog_color = f32s(&mut p, 3);
    let products = f32s(&mut p, 4);
    let clamped = f32s(&mut p, 4);
    for (k, &r) in color.iter().chain(&texel).chain([&coord]).enumerate() {
        p.input(Type::F32);
        body.push(Stmt::Inst(Inst::Input { dst: r, slot: (padding + k) as u16 }));
    }
    for (k, &r) in [end, start].iter().chain(&fog_color).enumerate() {
        p.uniform(Type::F32);
        body.push(Stmt::Inst(Inst::Uniform { dst: r, slot: k as u16 }));
    }
    body.push(Stmt::Inst(Inst::Const { dst: zero, value: Const::F32(0.0) }));
    body.push(Stmt::Inst(Inst::Const { dst: one, value: Const::F32(1.0) }));
    // Modulate: four products, then four clamps.
    for k in 0..4 {
        body.push(Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst: products[k], a: color[k], b: texel[k] }));
    }
    for k in 0..4 {
        let (positive, at_most_one) = (p.register(Type::Bool), p.register(Type::F32));
        body.extend([
            Stmt::Inst(Inst::Binary { op: BinaryOp::FLt, dst: positive, a: zero, b: products[k] }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FMin, dst: at_most_one, a: products[k], b: one }),
            Stmt::Inst(Inst::Select { dst: clamped[k], cond: positive, a: at_most_one, b: zero }),
        ]);
    }
    // Fog: (end − c) / (end − start), clamped; the blend of each channel.
    let (positive, at_most_one) = (p.register(Type::Bool), p.register(Type::F32));
    body.extend([
        Stmt::Inst(Inst::Binary { op: BinaryOp::FSub, dst: t, a: end, b: coord }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FSub, dst: span, a: end, b: start }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FDiv, dst: u, a: t, b: span }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FLt, dst: positive, a: zero, b: u }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FMin, dst: at_most_one, a: u, b: one }),
        Stmt::Inst(Inst::Select { dst: factor, cond: positive, a: at_most_one, b: zero }),
        Stmt::Inst(Inst::Binary { op: BinaryOp::FSub, dst: rest, a: one, b: factor }),
    ]);
    let mut fogged = Vec::new();
    for k in 0..3 {
        let [kept, added, sum] = [0; 3].map(|_| p.register(Type::F32));
        body.extend([
            Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst: kept, a: factor, b: clamped[k] }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst: added, a: rest, b: fog_color[k] }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FAdd, dst: sum, a: kept, b: added }),
        ]);
        fogged.push(sum);
    }
    fogged.push(clamped[3]);
    fogged.extend(sum);
    let outputs = fogged.len();
    for (slot, &r) in fogged.iter().enumerate() {
        p.output(Type::F32);
        body.push(Stmt::Inst(Inst::Output { slot: slot as u16, src: r }));
    }
    p.body = body;
    validate(&p).unwrap();
    let bound = Compiled::new(&p).bind().expect("a straight program binds");
    let fused = if padding < 200 { [4, 1, 1] } else { [0, 0, 0] };
    assert_eq!(bound.fused(), fused, "MulClamp, Ramp, Mix3 in {bound:#?}");
    let mut rng = Rng(0xf0f0_1234);
    let mut compared = 0;
    for case in 0..200 {
        let inputs: Vec<Word> = (0..padding + 9).map(|_| special_word(&mut rng)).collect();
        let uniforms: Vec<u32> = match case % 4 {
            // A degenerate span (division by zero) and special parameters, then plain ones.
            0 => vec![0.5f32.to_bits(), 0.5f32.to_bits(), 0.2f32.to_bits(), f32::NAN.to_bits(), 1.0f32.to_bits()],
            1 => special_word(&mut rng)[..5].to_vec(),
            _ => (0..5).map(|_| rng.float().to_bits()).collect(),
        };
        for lanes in [ALL_LANES, 0x5a5a, 0x0001, rng.next() as u16] {
            let mut want = vec![[0u32; LANES]; outputs];
            Executor::new().run(
                &p,
                &mut Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut want, textures: &NoTextures },
                lanes,
            );
            let got = run_bound(&p, &inputs, &uniforms, lanes).unwrap();
            for slot in 0..outputs {
                for lane in (0..LANES).filter(|l| lanes >> l & 1 != 0) {
                    assert!(
                        same_word(got[slot][lane], want[slot][lane], Type::F32),
                        "case {case}, lanes {lanes:#x}, output {slot}, lane {lane}: {:#x} vs {:#x}",
                        got[slot][lane],
                        want[slot][lane]
                    );
                    compared += !f32::from_bits(want[slot][lane]).is_nan() as usize;
                }
            }
        }
    }
    assert!(compared > 5000, "only {compared} numbers compared");
}

#[test]
fn a_uniform_matrix_row_times_a_vector_is_one_operation_with_its_bits() {
    // `m0·v0`, then `m1·v1 + t`, `m2·v2 + t`, `m3·v3 + t` with uniform m (the vertex
    // programs' transforms): one MatRow, each product and sum rounded as the four
    // instructions round them, on NaN, ±∞, ±0, denormals and overflowing products, with
    // every lane running and with a partial mask, through run, prepare + run_prepared and
    // bind_run + run_bound_run.
    let mut p = Program::new(Stage::Vertex);
    let v: Vec<Reg> = (0..4).map(|_| p.register(Type::F32)).collect();
    let m: Vec<Reg> = (0..4).map(|_| p.register(Type::F32)).collect();
    let t: Vec<Reg> = (0..4).map(|_| p.register(Type::F32)).collect();
    let mut body = Vec::new();
    for k in 0..4 {
        p.input(Type::F32);
        p.uniform(Type::F32);
        body.push(Stmt::Inst(Inst::Input { dst: v[k], slot: k as u16 }));
        body.push(Stmt::Inst(Inst::Uniform { dst: m[k], slot: k as u16 }));
    }
    p.output(Type::F32);
    body.push(Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst: t[0], a: m[0], b: v[0] }));
    for k in 1..4 {
        body.push(Stmt::Inst(Inst::Mad { dst: t[k], a: m[k], b: v[k], c: t[k - 1] }));
    }
    body.push(Stmt::Inst(Inst::Output { slot: 0, src: t[3] }));
    p.body = body;
    validate(&p).unwrap();
    let compiled = Compiled::new(&p);
    let fused = compiled.code().ops.iter().filter(|o| matches!(o, super::lower::Op::MatRow { .. })).count();
    assert_eq!(fused, 1, "{:#?}", compiled.code());
    let specials = [f32::NAN, -f32::NAN, 0.0, -0.0, f32::INFINITY, f32::NEG_INFINITY, 1e-45, 3.0e38, -2.5e-39, 0.1];
    let mut rng = Rng(0x3a7_0000_2222);
    for round in 0..40 {
        let value =
            |rng: &mut Rng| if rng.chance(30) { specials[rng.below(specials.len())] } else { rng.float() }.to_bits();
        let inputs: Vec<Word> = (0..4).map(|_| std::array::from_fn(|_| value(&mut rng))).collect();
        let uniforms: Vec<u32> = (0..4).map(|_| value(&mut rng)).collect();
        for lanes in [ALL_LANES, 0x0ff0, 0x0001] {
            let mut want = vec![[0u32; LANES]];
            Executor::new().run(
                &p,
                &mut Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut want, textures: &NoTextures },
                lanes,
            );
            let check = |got: &[Word], how: &str| {
                for i in (0..LANES).filter(|i| lanes >> i & 1 != 0) {
                    assert!(
                        same_word(got[0][i], want[0][i], Type::F32),
                        "round {round}, {how}, lanes {lanes:#x}, lane {i}"
                    );
                }
            };
            let mut got = vec![[0u32; LANES]];
            let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut got, textures: &NoTextures };
            compiled.run(&mut Registers::new(), &mut io, lanes);
            check(&got, "run");
            let mut registers = Registers::new();
            compiled.prepare(&mut registers, &uniforms);
            let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut got, textures: &NoTextures };
            compiled.run_prepared(&mut registers, &mut io, lanes);
            check(&got, "run_prepared");
            let bound = compiled.bind_run(4, 1).expect("straight-line code binds");
            let mut registers = Registers::new();
            compiled.prepare(&mut registers, &uniforms);
            for (slot, r) in bound.inputs.iter().enumerate() {
                registers.words_mut()[r.expect("every input is read") as usize] = inputs[slot];
            }
            compiled.run_bound_run(&bound, &mut registers, &uniforms, lanes);
            check(&[registers.words()[bound.outputs[0] as usize]], "run_bound_run");
        }
    }
}

#[test]
fn exp2_and_log2_over_lanes_give_the_scalar_functions_bits() {
    // The executor's lane forms of Exp2 and Log2 against the scalar polynomials, on
    // NaN, ±∞, ±0, denormals, negative values, the clamps of exp2 and random values, with
    // every lane running and with a partial mask.
    let specials = [
        f32::NAN,
        -f32::NAN,
        0.0,
        -0.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        1e-45,
        -1e-45,
        1.1e-38,
        -126.99999,
        -127.0,
        -200.0,
        128.0,
        127.99,
        300.0,
        -0.5,
        1.0,
        0.5,
        2.0,
        -3.25,
    ];
    let mut p = Program::new(Stage::Vertex);
    let [x, e, l] = [0; 3].map(|_| p.register(Type::F32));
    p.input(Type::F32);
    p.output(Type::F32);
    p.output(Type::F32);
    p.body = vec![
        Stmt::Inst(Inst::Input { dst: x, slot: 0 }),
        Stmt::Inst(Inst::Unary { op: UnaryOp::Exp2, dst: e, a: x }),
        Stmt::Inst(Inst::Unary { op: UnaryOp::Log2, dst: l, a: x }),
        Stmt::Inst(Inst::Output { slot: 0, src: e }),
        Stmt::Inst(Inst::Output { slot: 1, src: l }),
    ];
    validate(&p).unwrap();
    let compiled = Compiled::new(&p);
    let ops = &compiled.code().ops;
    assert!(ops.iter().any(|o| matches!(o, super::lower::Op::Exp2 { .. })), "{ops:?}");
    assert!(ops.iter().any(|o| matches!(o, super::lower::Op::Log2 { .. })), "{ops:?}");
    let mut rng = Rng(0xe2_0000_3333);
    for round in 0..2000 {
        let input: Word = std::array::from_fn(|_| match rng.below(4) {
            0 => specials[rng.below(specials.len())].to_bits(),
            1 => rng.next() as u32,
            _ => rng.float().to_bits(),
        });
        let lanes = if round % 2 == 0 { ALL_LANES } else { 0x9c3f };
        let mut got = vec![[0u32; LANES]; 2];
        let mut io = Io { inputs: &[input], uniforms: &[], outputs: &mut got, textures: &NoTextures };
        compiled.run(&mut Registers::new(), &mut io, lanes);
        for i in (0..LANES).filter(|i| lanes >> i & 1 != 0) {
            let v = f32::from_bits(input[i]);
            assert_eq!(got[0][i], super::math::exp2(v).to_bits(), "exp2 of {v:e} ({:#x})", input[i]);
            assert_eq!(got[1][i], super::math::log2(v).to_bits(), "log2 of {v:e} ({:#x})", input[i]);
        }
        assert_eq!(super::math::exp2_lanes(&input), input.map(|b| super::math::exp2(f32::from_bits(b)).to_bits()));
        assert_eq!(super::math::log2_lanes(&input), input.map(|b| super::math::log2(f32::from_bits(b)).to_bits()));
    }
}

/// GLSL's `pow` (log2, the exponent times it, exp2) is one fused operation, with the bits
/// of the three (the reference's): zeros, negative and NaN bases, ±∞ and huge exponents,
/// the exponent read before the logarithm is written (a base that is its own exponent).
#[test]
fn pow_is_one_operation_with_the_bits_of_its_three() {
    let specials =
        [0.0, -0.0, 1.0, 2.0, 0.5, -1.5, 1e-40, 3e38, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 128.0, -130.0];
    for same in [false, true] {
        let mut p = Program::new(Stage::Fragment);
        let [x, y, l, m, d] = [0; 5].map(|_| p.register(Type::F32));
        p.input(Type::F32);
        p.input(Type::F32);
        p.output(Type::F32);
        let y = if same { x } else { y };
        p.body = vec![
            Stmt::Inst(Inst::Input { dst: x, slot: 0 }),
            Stmt::Inst(Inst::Input { dst: y, slot: 1 }),
            Stmt::Inst(Inst::Unary { op: UnaryOp::Log2, dst: l, a: x }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst: m, a: y, b: l }),
            Stmt::Inst(Inst::Unary { op: UnaryOp::Exp2, dst: d, a: m }),
            Stmt::Inst(Inst::Output { slot: 0, src: d }),
        ];
        validate(&p).unwrap();
        let compiled = Compiled::new(&p);
        let ops = &compiled.code().ops;
        assert!(ops.iter().any(|o| matches!(o, super::lower::Op::Pow { .. })), "{ops:?}");
        assert!(!ops.iter().any(|o| matches!(o, super::lower::Op::Exp2 { .. })), "{ops:?}");
        let mut rng = Rng(0x90_0000_7777);
        for round in 0..500 {
            let mut value = || match rng.below(3) {
                0 => specials[rng.below(specials.len())].to_bits(),
                1 => rng.next() as u32,
                _ => rng.float().to_bits(),
            };
            let inputs: [Word; 2] = [std::array::from_fn(|_| value()), std::array::from_fn(|_| value())];
            let lanes = if round % 2 == 0 { ALL_LANES } else { 0x9c3f };
            let (mut want, mut got) = (vec![[0u32; LANES]; 1], vec![[0u32; LANES]; 1]);
            let mut io = Io { inputs: &inputs, uniforms: &[], outputs: &mut want, textures: &NoTextures };
            Executor::new().run(&p, &mut io, lanes);
            let mut io = Io { inputs: &inputs, uniforms: &[], outputs: &mut got, textures: &NoTextures };
            compiled.run(&mut Registers::new(), &mut io, lanes);
            assert_eq!(got, want, "pow of {:?} and {:?}", inputs[0].map(f32::from_bits), inputs[1].map(f32::from_bits));
        }
    }
}

// ---- Flattening (`super::flatten`) ---------------------------------------------------

/// Counts the `if`s and loops of a body.
fn control_statements(stmts: &[Stmt]) -> (usize, usize) {
    stmts.iter().fold((0, 0), |(ifs, loops), s| match s {
        Stmt::If { then, otherwise, .. } => {
            let (a, b) = control_statements(then);
            let (c, d) = control_statements(otherwise);
            (ifs + 1 + a + c, loops + b + d)
        }
        Stmt::Loop { body } => {
            let (a, b) = control_statements(body);
            (ifs + a, loops + 1 + b)
        }
        _ => (ifs, loops),
    })
}

#[test]
fn flattened_programs_give_the_reference_bits_lookups_and_discards() {
    use super::flatten::flatten;
    let mut rng = Rng(0xf1a7_7e40_5eed_0001);
    let mut executor = Executor::new();
    let (mut unrolled, mut converted, mut straight, mut discards) = (0, 0, 0, 0);
    for case in 0..4000u64 {
        let stage = if case % 3 == 0 { Stage::Vertex } else { Stage::Fragment };
        let mut generator = Generator::new(rng.next(), stage);
        generator.cross_lane = case % 2 == 0;
        let program = generator.program();
        let flat = flatten(&program);
        validate(&flat).unwrap_or_else(|e| panic!("case {case}: {e}\n{}", super::dump::dump(&flat)));
        let (ifs, loops) = control_statements(&program.body);
        let (flat_ifs, flat_loops) = control_statements(&flat.body);
        unrolled += loops - flat_loops;
        converted += ifs.saturating_sub(flat_ifs);
        straight += usize::from(flat_ifs + flat_loops == 0 && ifs + loops > 0);
        // NaN, infinities, signed zeros and denormals in the inputs and the uniform.
        let inputs: Vec<Word> = program
            .inputs
            .iter()
            .map(|t| if *t == Type::F32 { special_word(&mut rng) } else { std::array::from_fn(|_| rng.int()) })
            .collect();
        let uniforms = [rng.float().to_bits(), rng.int()];
        let lanes = if rng.chance(60) { ALL_LANES } else { rng.next() as u16 };
        let mut run = |p: &Program| {
            let textures = Recorder::default();
            let mut outputs = vec![[0u32; LANES]; p.outputs.len()];
            let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &textures };
            let alive = executor.run(p, &mut io, lanes);
            (alive, outputs, textures.0.into_inner())
        };
        // Bit for bit, NaN payloads included: the same operations on the same values.
        let reference = run(&program);
        let got = run(&flat);
        discards += usize::from(reference.0 != lanes);
        assert!(
            got == reference,
            "case {case} differs\n{}\nflattened:\n{}",
            super::dump::dump(&program),
            super::dump::dump(&flat)
        );
    }
    assert!(unrolled > 1000, "only {unrolled} loops unrolled");
    assert!(converted > 1000, "only {converted} ifs converted");
    assert!(straight > 80, "only {straight} programs made straight");
    assert!(discards > 200, "only {discards} runs with discards");
}

/// A GLSL `for (int i = 0; i < 2; i++)` as the front end lowers it (an `again` flag guarding
/// the step, the test then `break`), around `if (d > 0.0) s += exp2(log2(d) * e)`.
fn glsl_style_loop() -> Program {
    let mut p = Program::new(Stage::Fragment);
    let (f, i32t, b) = (Type::F32, Type::I32, Type::Bool);
    let slot_x = p.input(f);
    let slot_e = p.uniform(f);
    let out = p.output(f);
    let [x, e, s, d, l, t] = [0; 6].map(|_| p.register(f));
    let [i, one, two] = [0; 3].map(|_| p.register(i32t));
    let [again, yes, no, more, positive] = [0; 5].map(|_| p.register(b));
    let zero = p.register(f);
    let inst = Stmt::Inst;
    let body = vec![
        Stmt::If {
            cond: again,
            then: vec![inst(Inst::Binary { op: BinaryOp::IAdd, dst: i, a: i, b: one })],
            otherwise: vec![],
        },
        inst(Inst::Mov { dst: again, src: yes }),
        inst(Inst::Binary { op: BinaryOp::ILt, dst: more, a: i, b: two }),
        Stmt::If { cond: more, then: vec![], otherwise: vec![Stmt::Break] },
        inst(Inst::Binary { op: BinaryOp::FSub, dst: d, a: x, b: s }),
        inst(Inst::Binary { op: BinaryOp::FLt, dst: positive, a: zero, b: d }),
        Stmt::If {
            cond: positive,
            then: vec![
                inst(Inst::Unary { op: UnaryOp::Log2, dst: l, a: d }),
                inst(Inst::Binary { op: BinaryOp::FMul, dst: l, a: l, b: e }),
                inst(Inst::Unary { op: UnaryOp::Exp2, dst: t, a: l }),
                inst(Inst::Binary { op: BinaryOp::FAdd, dst: s, a: s, b: t }),
            ],
            otherwise: vec![inst(Inst::Binary { op: BinaryOp::FMul, dst: s, a: s, b: d })],
        },
    ];
    p.body = vec![
        inst(Inst::Input { dst: x, slot: slot_x }),
        inst(Inst::Uniform { dst: e, slot: slot_e }),
        inst(Inst::Const { dst: s, value: Const::F32(0.25) }),
        inst(Inst::Const { dst: zero, value: Const::F32(0.0) }),
        inst(Inst::Const { dst: i, value: Const::I32(0) }),
        inst(Inst::Const { dst: one, value: Const::I32(1) }),
        inst(Inst::Const { dst: two, value: Const::I32(2) }),
        inst(Inst::Const { dst: yes, value: Const::Bool(true) }),
        inst(Inst::Const { dst: no, value: Const::Bool(false) }),
        inst(Inst::Mov { dst: again, src: no }),
        Stmt::Loop { body },
        inst(Inst::Output { slot: out, src: s }),
    ];
    p
}

#[test]
fn a_glsl_for_loop_of_two_with_a_pure_if_becomes_straight_code_with_the_same_bits() {
    let program = glsl_style_loop();
    validate(&program).unwrap();
    let flat = super::flatten::flatten(&program);
    validate(&flat).unwrap();
    assert!(flat.body.iter().all(|s| matches!(s, Stmt::Inst(_))), "not straight:\n{}", super::dump::dump(&flat));
    // Each register written once: the iterations' copies write fresh ones.
    let mut writes = vec![0; flat.registers.len()];
    for s in &flat.body {
        let Stmt::Inst(i) = s else { unreachable!() };
        i.writes().into_iter().for_each(|r| writes[r.0 as usize] += 1);
    }
    assert!(writes.iter().all(|&w| w <= 1), "registers written twice:\n{}", super::dump::dump(&flat));
    let mut rng = Rng(0x0123_4567_89ab_cdef);
    let mut executor = Executor::new();
    let mut registers = Registers::new();
    for _ in 0..200 {
        let inputs = [special_word(&mut rng)];
        let uniforms = [rng.float().to_bits()];
        let lanes = if rng.chance(50) { ALL_LANES } else { rng.next() as u16 };
        let mut reference = vec![[0u32; LANES]];
        executor.run(
            &program,
            &mut Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut reference, textures: &NoTextures },
            lanes,
        );
        for p in [&program, &flat] {
            let mut outputs = vec![[0u32; LANES]];
            executor.run(
                p,
                &mut Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &NoTextures },
                lanes,
            );
            assert_eq!(outputs, reference);
        }
        // The compiled form runs one straight run of operations, with the same bits.
        let compiled = Compiled::new(&program);
        let mut outputs = vec![[0u32; LANES]];
        compiled.run(
            &mut registers,
            &mut Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &NoTextures },
            lanes,
        );
        assert_eq!(outputs, reference);
    }
}

#[test]
fn loops_that_break_under_unknown_conditions_or_run_long_stay_loops() {
    let mut program = glsl_style_loop();
    // The trip count from an input: not known when compiling.
    let Stmt::Inst(Inst::Const { dst: i, .. }) = program.body[4] else { panic!("the counter") };
    program.body[4] = Stmt::Inst(Inst::Input { dst: i, slot: program.inputs.len() as u16 });
    program.inputs.push(Type::I32);
    validate(&program).unwrap();
    let (_, loops) = control_statements(&super::flatten::flatten(&program).body);
    assert_eq!(loops, 1);
    // A known trip count above the bound.
    let mut program = glsl_style_loop();
    let Stmt::Inst(Inst::Const { dst: two, .. }) = program.body[6] else { panic!("the limit") };
    let limit = super::flatten::MAX_UNROLLED_ITERATIONS as i32 + 1;
    program.body[6] = Stmt::Inst(Inst::Const { dst: two, value: Const::I32(limit) });
    let (_, loops) = control_statements(&super::flatten::flatten(&program).body);
    assert_eq!(loops, 1);
}

/// piglit's `unroll-explosion`: loops of 16 iterations nested deep. Unrolling each copy of
/// each loop again would never end; the work bound keeps flattening quick.
#[test]
fn deeply_nested_counted_loops_flatten_quickly() {
    let mut p = Program::new(Stage::Fragment);
    let x = p.register(Type::F32);
    let slot = p.input(Type::F32);
    let out = p.output(Type::F32);
    let (one, sixteen) = (p.register(Type::I32), p.register(Type::I32));
    let mut body = vec![Stmt::Inst(Inst::Unary { op: UnaryOp::Exp, dst: x, a: x })];
    for _ in 0..14 {
        let (i, more) = (p.register(Type::I32), p.register(Type::Bool));
        let mut inner = vec![
            Stmt::Inst(Inst::Binary { op: BinaryOp::ILt, dst: more, a: i, b: sixteen }),
            Stmt::If { cond: more, then: vec![], otherwise: vec![Stmt::Break] },
            Stmt::Inst(Inst::Binary { op: BinaryOp::IAdd, dst: i, a: i, b: one }),
        ];
        inner.extend(body);
        // The counter starts again at every iteration of the enclosing loop.
        body = vec![Stmt::Inst(Inst::Const { dst: i, value: Const::I32(0) }), Stmt::Loop { body: inner }];
    }
    p.body = vec![
        Stmt::Inst(Inst::Input { dst: x, slot }),
        Stmt::Inst(Inst::Const { dst: one, value: Const::I32(1) }),
        Stmt::Inst(Inst::Const { dst: sixteen, value: Const::I32(16) }),
    ];
    p.body.extend(body);
    p.body.push(Stmt::Inst(Inst::Output { slot: out, src: x }));
    if validate(&p).is_err() {
        return; // deeper than the validator allows: nothing to flatten
    }
    let start = std::time::Instant::now();
    let flat = super::flatten::flatten(&p);
    validate(&flat).unwrap();
    assert!(start.elapsed().as_secs() < 5, "flattening took {:?}", start.elapsed());
    assert!(control_statements(&flat.body).1 > 0, "the nest stays loops");
}

/// A light's `p.w == 0.0 ? normalize(p.xyz) : normalize(p.xyz - position)` as the front end
/// lowers it (one component here): a condition on a uniform, pure arms.
fn uniform_ternary(stage: Stage) -> Program {
    let mut p = Program::new(stage);
    let (f, b) = (Type::F32, Type::Bool);
    let slot_x = p.input(f);
    let slot_w = p.uniform(f);
    let out = p.output(f);
    let [x, w, zero, t, r] = [0; 5].map(|_| p.register(f));
    let directional = p.register(b);
    let inst = Stmt::Inst;
    p.body = vec![
        inst(Inst::Input { dst: x, slot: slot_x }),
        inst(Inst::Uniform { dst: w, slot: slot_w }),
        inst(Inst::Const { dst: zero, value: Const::F32(0.0) }),
        inst(Inst::Binary { op: BinaryOp::FEq, dst: directional, a: w, b: zero }),
        Stmt::If {
            cond: directional,
            then: vec![inst(Inst::Mov { dst: r, src: w })],
            otherwise: vec![
                inst(Inst::Binary { op: BinaryOp::FSub, dst: t, a: w, b: x }),
                inst(Inst::Unary { op: UnaryOp::Sqrt, dst: r, a: t }),
            ],
        },
        inst(Inst::Output { slot: out, src: r }),
    ];
    p
}

#[test]
fn fragment_programs_keep_ifs_on_uniform_conditions_and_vertex_programs_convert_them() {
    let fragment = uniform_ternary(Stage::Fragment);
    validate(&fragment).unwrap();
    let flat = super::flatten::flatten(&fragment);
    assert_eq!(control_statements(&flat.body), (1, 0), "{}", super::dump::dump(&flat));
    let vertex = uniform_ternary(Stage::Vertex);
    let flat = super::flatten::flatten(&vertex);
    assert_eq!(control_statements(&flat.body), (0, 0), "{}", super::dump::dump(&flat));
    // The fragment program's `if` compiles to a uniform branch: each block runs one arm,
    // with the reference's bits.
    let compiled = Compiled::new(&fragment);
    let mut executor = Executor::new();
    let mut registers = Registers::new();
    let mut rng = Rng(0x5eed_1f1f_0000_0001);
    for w in [0.0f32, 2.0, -0.0] {
        let inputs = [special_word(&mut rng)];
        let uniforms = [w.to_bits()];
        let mut reference = vec![[0u32; LANES]];
        let io = |outputs| Io { inputs: &inputs, uniforms: &uniforms, outputs, textures: &NoTextures };
        executor.run(&fragment, &mut io(&mut reference), ALL_LANES);
        let mut outputs = vec![[0u32; LANES]];
        compiled.run(&mut registers, &mut io(&mut outputs), 0x0ff0);
        let mask = super::fast::lane_mask(0x0ff0);
        for i in 0..LANES {
            assert_eq!(outputs[0][i] & mask[i], reference[0][i] & mask[i], "w = {w}");
        }
    }
    assert!(
        compiled
            .code()
            .body
            .iter()
            .any(|n| matches!(n, super::lower::Node::If { cond: super::lower::Cond::Uniform(_), .. })),
        "{:?}",
        compiled.code().body
    );
}

#[test]
fn flattening_reads_an_arithmetic_result_computed_twice_from_its_first_computation() {
    let mut p = Program::new(Stage::Fragment);
    let (x, y) = (p.register(Type::F32), p.register(Type::F32));
    let (first, again, swapped) = (p.register(Type::F32), p.register(Type::F32), p.register(Type::F32));
    let (square, mixed) = (p.register(Type::F32), p.register(Type::F32));
    let (slot_x, slot_y) = (p.input(Type::F32), p.input(Type::F32));
    let (out_square, out_mixed) = (p.output(Type::F32), p.output(Type::F32));
    let sub = |dst, a, b| Stmt::Inst(Inst::Binary { op: BinaryOp::FSub, dst, a, b });
    let mul = |dst, a, b| Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst, a, b });
    p.body = vec![
        Stmt::Inst(Inst::Input { dst: x, slot: slot_x }),
        Stmt::Inst(Inst::Input { dst: y, slot: slot_y }),
        sub(first, x, y),
        sub(again, x, y),
        sub(swapped, y, x),
        mul(square, first, again),
        mul(mixed, first, swapped),
        Stmt::Inst(Inst::Output { slot: out_square, src: square }),
        Stmt::Inst(Inst::Output { slot: out_mixed, src: mixed }),
    ];
    validate(&p).unwrap();
    let flat = super::flatten::flatten(&p);
    let products: Vec<(Reg, Reg)> = flat
        .body
        .iter()
        .filter_map(|s| match s {
            Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, a, b, .. }) => Some((*a, *b)),
            _ => None,
        })
        .collect();
    // `x - y` twice is one value; `y - x` is another.
    assert_eq!(products, vec![(first, first), (first, swapped)], "{}", super::dump::dump(&flat));
}
