//! Writing programs: a [`Builder`] that the fixed-function generators (and the GLSL front
//! end after them) use to emit instructions into a straight-line body, with each input
//! word, uniform word and constant read into a register once, however often it is named.
//!
//! Inputs and uniforms are named by the generator's own keys (`I`, `U`: where a word comes
//! from), so that a generated program carries the list of what its slots hold.

use super::ir::{BinaryOp, Const, Inst, Program, Reg, Stage, Stmt, Type, UnaryOp};
use std::collections::HashMap;
use std::hash::Hash;

/// A program being written (see the module).
pub struct Builder<I, U> {
    pub program: Program,
    body: Vec<Stmt>,
    /// What each input slot holds, in slot order.
    pub inputs: Vec<I>,
    /// What each uniform slot holds, in slot order.
    pub uniforms: Vec<U>,
    input_regs: HashMap<I, Reg>,
    uniform_regs: HashMap<U, Reg>,
    constants: HashMap<u32, Reg>,
}

impl<I: Copy + Eq + Hash, U: Copy + Eq + Hash> Builder<I, U> {
    pub fn new(stage: Stage) -> Self {
        Builder {
            program: Program::new(stage),
            body: Vec::new(),
            inputs: Vec::new(),
            uniforms: Vec::new(),
            input_regs: HashMap::new(),
            uniform_regs: HashMap::new(),
            constants: HashMap::new(),
        }
    }

    /// The finished program (its body the instructions emitted), and what its input and
    /// uniform slots hold.
    pub fn finish(self) -> (Program, Vec<I>, Vec<U>) {
        let Builder { mut program, body, inputs, uniforms, .. } = self;
        program.body = body;
        (program, inputs, uniforms)
    }

    pub fn emit(&mut self, inst: Inst) {
        self.body.push(Stmt::Inst(inst));
    }

    pub fn register(&mut self, ty: Type) -> Reg {
        self.program.register(ty)
    }

    /// The f32 input word `source`, read once.
    pub fn input(&mut self, source: I) -> Reg {
        if let Some(&r) = self.input_regs.get(&source) {
            return r;
        }
        let slot = self.program.input(Type::F32);
        self.inputs.push(source);
        let dst = self.register(Type::F32);
        self.emit(Inst::Input { dst, slot });
        self.input_regs.insert(source, dst);
        dst
    }

    /// The f32 uniform word `value`, read once.
    pub fn uniform(&mut self, value: U) -> Reg {
        if let Some(&r) = self.uniform_regs.get(&value) {
            return r;
        }
        let slot = self.program.uniform(Type::F32);
        self.uniforms.push(value);
        let dst = self.register(Type::F32);
        self.emit(Inst::Uniform { dst, slot });
        self.uniform_regs.insert(value, dst);
        dst
    }

    /// The f32 constant `value` (by its bits: −0 and 0 are two constants).
    pub fn constant(&mut self, value: f32) -> Reg {
        if let Some(&r) = self.constants.get(&value.to_bits()) {
            return r;
        }
        let dst = self.register(Type::F32);
        self.emit(Inst::Const { dst, value: Const::F32(value) });
        self.constants.insert(value.to_bits(), dst);
        dst
    }

    /// An f32 operation, or an f32 comparison (a bool register).
    pub fn binary(&mut self, op: BinaryOp, a: Reg, b: Reg) -> Reg {
        let ty = if matches!(op, BinaryOp::FLt | BinaryOp::FLe | BinaryOp::FEq | BinaryOp::FNe) {
            Type::Bool
        } else {
            Type::F32
        };
        let dst = self.register(ty);
        self.emit(Inst::Binary { op, dst, a, b });
        dst
    }

    /// An f32 → f32 operation.
    pub fn unary(&mut self, op: UnaryOp, a: Reg) -> Reg {
        let dst = self.register(Type::F32);
        self.emit(Inst::Unary { op, dst, a });
        dst
    }

    /// `cond ? a : b` on f32 values.
    pub fn select(&mut self, cond: Reg, a: Reg, b: Reg) -> Reg {
        let dst = self.register(Type::F32);
        self.emit(Inst::Select { dst, cond, a, b });
        dst
    }

    /// `a·b + c`, two roundings.
    pub fn mad(&mut self, a: Reg, b: Reg, c: Reg) -> Reg {
        let dst = self.register(Type::F32);
        self.emit(Inst::Mad { dst, a, b, c });
        dst
    }

    /// `a[0]·b[0] + a[1]·b[1] + a[2]·b[2]` summed left to right.
    pub fn dot3(&mut self, a: [Reg; 3], b: [Reg; 3]) -> Reg {
        let dst = self.register(Type::F32);
        self.emit(Inst::Dot { dst, n: 3, a: [a[0], a[1], a[2], a[0]], b: [b[0], b[1], b[2], b[0]] });
        dst
    }

    /// `1 − x`.
    pub fn one_minus(&mut self, x: Reg) -> Reg {
        let one = self.constant(1.0);
        self.binary(BinaryOp::FSub, one, x)
    }

    /// `x > 0 ? min(x, 1) : 0` (NaN gives 0): GL's clamp of colours to [0, 1].
    pub fn clamp01(&mut self, x: Reg) -> Reg {
        let (zero, one) = (self.constant(0.0), self.constant(1.0));
        let positive = self.binary(BinaryOp::FLt, zero, x);
        // FMin(x, 1) is `1 < x ? 1 : x`: min(x, 1) for every x > 0.
        let at_most_one = self.binary(BinaryOp::FMin, x, one);
        self.select(positive, at_most_one, zero)
    }
}

/// The random tests' generator (the generators' tests name it from here).
#[cfg(test)]
pub use crate::gl::test_rng::TestRng;
