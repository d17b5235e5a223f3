//! The program form of the shading IR: typed scalar registers, typed operations and
//! structured control flow.
//!
//! A program is in register form, not SSA: a register may be assigned more than once, and
//! an assignment under divergent control flow changes only the lanes that run it. That is
//! what GLSL's mutable variables become after lowering, and it needs no phi nodes to merge
//! the two sides of a branch. Control flow is structured (nested blocks, no gotos), as in
//! GLSL: the executor keeps one execution mask per nesting level, and a condition that is
//! the same in every running lane runs one side only, like a real branch.
//!
//! Every operation names its types in its opcode (`FAdd`, `IAdd`, ...), so the executor
//! never looks at a register's type, and the validator checks each operand against the
//! opcode's signature once. Values are 32-bit words per lane; a bool is 0 or 1.

/// The type of a register, an input, a uniform or an output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Type {
    F32,
    I32,
    U32,
    Bool,
}

impl Type {
    pub fn name(self) -> &'static str {
        match self {
            Type::F32 => "f32",
            Type::I32 => "i32",
            Type::U32 => "u32",
            Type::Bool => "bool",
        }
    }
}

/// A register: an index into [`Program::registers`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Reg(pub u32);

/// A constant of one of the four types.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Const {
    F32(f32),
    I32(i32),
    U32(u32),
    Bool(bool),
}

impl Const {
    pub fn ty(self) -> Type {
        match self {
            Const::F32(_) => Type::F32,
            Const::I32(_) => Type::I32,
            Const::U32(_) => Type::U32,
            Const::Bool(_) => Type::Bool,
        }
    }

    /// The constant's 32-bit word, as a register lane holds it.
    pub fn bits(self) -> u32 {
        match self {
            Const::F32(v) => v.to_bits(),
            Const::I32(v) => v as u32,
            Const::U32(v) => v,
            Const::Bool(v) => v as u32,
        }
    }
}

/// Operations of one operand. The comment after each gives operand → result types and what
/// happens where GLSL leaves the result undefined (tessera defines it, so that every CPU
/// agrees).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UnaryOp {
    /// f32 → f32: −a (sign bit flipped, NaN included).
    FNeg,
    /// f32 → f32: |a| (sign bit cleared).
    FAbs,
    /// f32 → f32: GLSL `sign`: −1, 0 (keeping the sign of zero) or 1; NaN stays NaN.
    FSign,
    /// f32 → f32: exact floor, ceil, truncation, fraction (`a − floor(a)`), and rounding to
    /// nearest with ties to even.
    Floor,
    Ceil,
    Trunc,
    Fract,
    RoundEven,
    /// f32 → f32: IEEE square root; `1/a` and `1/sqrt(a)` as one and two rounded operations.
    Sqrt,
    Rcp,
    Rsq,
    /// f32 → f32: 2^a and log2(a) by [`super::math`]'s polynomials (error documented there).
    Exp2,
    Log2,
    /// f32 → f32: eˣ by [`super::math::exp`] (fog's exponential, 0.5 ulp).
    Exp,
    /// f32 → f32: sin and cos of radians by [`super::math`]'s polynomials.
    Sin,
    Cos,
    /// f32 → i32 / u32: truncation toward zero, saturating at the type's range, NaN → 0.
    F32ToI32,
    F32ToU32,
    /// i32 / u32 / bool → f32: rounded to nearest (bool: 0.0 or 1.0).
    I32ToF32,
    U32ToF32,
    BoolToF32,
    /// f32 → bool: a ≠ 0 (NaN is true, as `a != 0.0`).
    F32ToBool,
    /// i32 → i32: wrapping negation and absolute value (`i32::MIN` stays).
    INeg,
    IAbs,
    /// i32/u32 → i32/u32: bitwise not.
    INot,
    /// bool → bool: logical not.
    BNot,
    /// i32 ↔ u32: the same bits.
    Bitcast,
}

/// Operations of two operands of one type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BinaryOp {
    /// f32 × f32 → f32, each rounded once. `FMin`/`FMax` are GLSL's `b < a ? b : a` and
    /// `a < b ? b : a` (equal operands, ±0 included: `a`), and with one NaN operand the
    /// other one, as Mesa's min and max (GLSL leaves NaN undefined; piglit's
    /// `*-nan-builtin-min/max` want the number); NaN when both are.
    FAdd,
    FSub,
    FMul,
    FDiv,
    FMin,
    FMax,
    /// f32 × f32 → bool: IEEE comparisons (false with a NaN, but `FNe` true).
    FLt,
    FLe,
    FEq,
    FNe,
    /// i32 × i32 → i32, wrapping; division and remainder by zero give 0, `i32::MIN / −1`
    /// wraps to `i32::MIN` (GLSL leaves both undefined).
    IAdd,
    ISub,
    IMul,
    IDiv,
    IRem,
    IMin,
    IMax,
    /// u32 × u32 → u32, wrapping; division and remainder by zero give 0.
    UDiv,
    URem,
    UMin,
    UMax,
    /// i32 × i32 → bool and u32 × u32 → bool.
    ILt,
    ILe,
    ULt,
    ULe,
    /// Same-type integer equality (i32 or u32) → bool.
    IEq,
    INe,
    /// Bitwise (i32 or u32, operands of one type).
    And,
    Or,
    Xor,
    /// Shifts by the low five bits of b: left (i32 or u32, b of the same type), right
    /// arithmetic (i32 × i32) and right logical (u32 × u32).
    Shl,
    AShr,
    LShr,
    /// bool × bool → bool.
    BAnd,
    BOr,
    BXor,
    BEq,
}

/// The axis of a screen-space derivative.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    X,
    Y,
}

/// The most texture image units a program may name (the GL limit a context reports is at
/// most this).
pub const MAX_SAMPLERS: usize = 32;

/// How a filtered lookup chooses its level of detail.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Lod {
    /// From the coordinates' derivatives over each 2×2 quad (fragment programs).
    Implicit,
    /// The implicit level plus an f32 bias (fragment programs).
    Bias(Reg),
    /// The f32 level of detail λ itself.
    Explicit(Reg),
}

/// One operation. `dst` is always written (in the running lanes only).
#[derive(Clone, Debug, PartialEq)]
pub enum Inst {
    Const {
        dst: Reg,
        value: Const,
    },
    /// A per-lane input word: a vertex attribute component or a varying component.
    Input {
        dst: Reg,
        slot: u16,
    },
    /// A uniform word, the same in every lane.
    Uniform {
        dst: Reg,
        slot: u16,
    },
    Mov {
        dst: Reg,
        src: Reg,
    },
    Unary {
        op: UnaryOp,
        dst: Reg,
        a: Reg,
    },
    Binary {
        op: BinaryOp,
        dst: Reg,
        a: Reg,
        b: Reg,
    },
    /// f32: `a·b + c`, two roundings (never fused).
    Mad {
        dst: Reg,
        a: Reg,
        b: Reg,
        c: Reg,
    },
    /// f32: `a[0]·b[0] + a[1]·b[1] + …` over the first `n` (2 to 4) pairs, summed left to
    /// right, every product and sum rounded once.
    Dot {
        dst: Reg,
        n: u8,
        a: [Reg; 4],
        b: [Reg; 4],
    },
    /// `cond ? a : b` per lane (`cond` bool; `a`, `b` and `dst` of one type).
    Select {
        dst: Reg,
        cond: Reg,
        a: Reg,
        b: Reg,
    },
    /// Fragment programs: the derivative of an f32 within each lane's 2×2 quad, along the
    /// lane's own row (right minus left pixel) or column (lower minus upper pixel).
    Derivative {
        dst: Reg,
        axis: Axis,
        a: Reg,
    },
    /// Writes `src` to an output word (in the running lanes).
    Output {
        slot: u16,
        src: Reg,
    },
    /// A filtered lookup of texture unit `unit` at the f32 coordinates `coords[..n]` (1 to 3,
    /// as the unit's target needs: s; s, t; s, t, r or a cube direction): RGBA into `dst`.
    /// `projective`: `coords[n]` is q, and the sampler divides the others by it, with its
    /// own rounding (the fixed-function and `texture*Proj` rules). `compare`: the depth
    /// reference of a shadow lookup. The sampler applies the unit's own filters, wraps,
    /// border, depth mode and comparison: the program only asks.
    Sample {
        dst: [Reg; 4],
        unit: u8,
        n: u8,
        coords: [Reg; 4],
        projective: bool,
        lod: Lod,
        compare: Option<Reg>,
    },
    /// One texel of level `lod` (i32) at the i32 coordinates `coords[..n]`, unfiltered;
    /// outside the level: zero.
    Fetch {
        dst: [Reg; 4],
        unit: u8,
        n: u8,
        coords: [Reg; 3],
        lod: Reg,
    },
    /// The i32 width, height and depth of level `lod` (i32) of the unit's texture.
    Size {
        dst: [Reg; 3],
        unit: u8,
        lod: Reg,
    },
}

impl Inst {
    /// The register a pure instruction (one that computes a register from registers, inputs
    /// and uniforms alone) writes, to rename it; `None` for the others.
    pub fn pure_dst_mut(&mut self) -> Option<&mut Reg> {
        match self {
            Inst::Const { dst, .. }
            | Inst::Input { dst, .. }
            | Inst::Uniform { dst, .. }
            | Inst::Mov { dst, .. }
            | Inst::Unary { dst, .. }
            | Inst::Binary { dst, .. }
            | Inst::Mad { dst, .. }
            | Inst::Dot { dst, .. }
            | Inst::Select { dst, .. } => Some(dst),
            _ => None,
        }
    }

    /// The register the instruction writes, if any.
    pub fn dst(&self) -> Option<Reg> {
        match *self {
            Inst::Const { dst, .. }
            | Inst::Input { dst, .. }
            | Inst::Uniform { dst, .. }
            | Inst::Mov { dst, .. }
            | Inst::Unary { dst, .. }
            | Inst::Binary { dst, .. }
            | Inst::Mad { dst, .. }
            | Inst::Dot { dst, .. }
            | Inst::Select { dst, .. }
            | Inst::Derivative { dst, .. } => Some(dst),
            Inst::Output { .. } | Inst::Sample { .. } | Inst::Fetch { .. } | Inst::Size { .. } => None,
        }
    }

    /// The registers the instruction writes: its `dst`, or the components of a texture
    /// lookup.
    pub fn writes(&self) -> Vec<Reg> {
        match self {
            Inst::Sample { dst, .. } | Inst::Fetch { dst, .. } => dst.to_vec(),
            Inst::Size { dst, .. } => dst.to_vec(),
            _ => self.dst().into_iter().collect(),
        }
    }
}

/// A statement of structured control flow.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    Inst(Inst),
    /// Runs `then` in the lanes where the bool `cond` is true, `otherwise` in the others.
    If {
        cond: Reg,
        then: Vec<Stmt>,
        otherwise: Vec<Stmt>,
    },
    /// Runs `body` until every lane has left by `Break` (or `Return`, `Discard`), or the
    /// iteration bound of the executor is reached.
    Loop {
        body: Vec<Stmt>,
    },
    /// Leaves the innermost loop (in the running lanes).
    Break,
    /// Ends the innermost loop's current iteration (in the running lanes).
    Continue,
    /// Ends the program (in the running lanes), keeping what they have written.
    Return,
    /// Fragment programs: ends the program and discards the fragment (in the running lanes).
    Discard,
}

/// The stage a program runs in: vertex programs see one vertex per lane, fragment programs
/// one pixel of a 4×4 block per lane (lane `i` at column `i & 3`, row `i >> 2`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    Vertex,
    Fragment,
}

/// A program: its registers' types, the types of its input, uniform and output words, and
/// its body.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub stage: Stage,
    pub registers: Vec<Type>,
    pub inputs: Vec<Type>,
    pub uniforms: Vec<Type>,
    pub outputs: Vec<Type>,
    pub body: Vec<Stmt>,
}

impl Program {
    pub fn new(stage: Stage) -> Program {
        Program {
            stage,
            registers: Vec::new(),
            inputs: Vec::new(),
            uniforms: Vec::new(),
            outputs: Vec::new(),
            body: Vec::new(),
        }
    }

    /// A new register of type `ty`.
    pub fn register(&mut self, ty: Type) -> Reg {
        self.registers.push(ty);
        Reg(self.registers.len() as u32 - 1)
    }

    /// A new input word of type `ty`; its slot.
    pub fn input(&mut self, ty: Type) -> u16 {
        self.inputs.push(ty);
        self.inputs.len() as u16 - 1
    }

    /// A new uniform word of type `ty`; its slot.
    pub fn uniform(&mut self, ty: Type) -> u16 {
        self.uniforms.push(ty);
        self.uniforms.len() as u16 - 1
    }

    /// A new output word of type `ty`; its slot.
    pub fn output(&mut self, ty: Type) -> u16 {
        self.outputs.push(ty);
        self.outputs.len() as u16 - 1
    }
}
