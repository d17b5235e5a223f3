//! The checked program: what semantic analysis ([`super::check`]) makes of a syntax tree,
//! for the lowering onto the shading IR. Every expression has its [`Type`], every name is
//! resolved to a [`Variable`] (a shader's own or a built-in) or a function (a shader's own,
//! [`ExprKind::Call`], or a built-in signature, [`ExprKind::Builtin`]), every implicit
//! int → float conversion of GLSL 1.20 is an [`ExprKind::Convert`] node, and constant
//! expressions are folded into [`ExprKind::Constant`].
//!
//! What stays implicit: a scalar operand of a component-wise operator applies to every
//! component of the other operand (`v * 2.0`), as in the IR's operations; linear-algebra
//! products are their own operator, [`BinaryOp::MatMul`], apart from component-wise `*`.

use super::ast::{ParameterDirection, Storage};
use super::diagnostics::Pos;
use super::lex::Sampler;
use std::fmt;
use std::sync::Arc;

/// The scalar kinds of GLSL 1.10/1.20.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scalar {
    Float,
    Int,
    Bool,
}

/// A struct type: two structs are the same type only if they are the same definition.
#[derive(Debug)]
pub struct StructType {
    pub name: String,
    pub members: Vec<(String, Type)>,
    /// Unique per definition in one compile (built-in structs included).
    pub id: u32,
}

impl PartialEq for StructType {
    fn eq(&self, other: &Self) -> bool {
        self.id == other.id
    }
}

/// A GLSL type.
#[derive(Clone, Debug, PartialEq)]
pub enum Type {
    Void,
    Scalar(Scalar),
    /// 2 to 4 components.
    Vector(Scalar, u8),
    /// Columns, rows (2 to 4 each; 1.20 adds the non-square ones).
    Matrix(u8, u8),
    Sampler(Sampler),
    Struct(Arc<StructType>),
    /// An element type and a size; `None` is an array whose size is not known yet (sized
    /// later by its largest constant index, as GLSL 1.10/1.20 permit).
    Array(Box<Type>, Option<u32>),
}

pub const FLOAT: Type = Type::Scalar(Scalar::Float);
pub const INT: Type = Type::Scalar(Scalar::Int);
pub const BOOL: Type = Type::Scalar(Scalar::Bool);

impl Type {
    /// A scalar (`n == 1`) or vector type.
    pub fn vector(base: Scalar, n: u8) -> Type {
        if n == 1 {
            Type::Scalar(base)
        } else {
            Type::Vector(base, n)
        }
    }

    /// The scalar kind of a scalar, vector or matrix.
    pub fn base(&self) -> Option<Scalar> {
        match self {
            Type::Scalar(s) | Type::Vector(s, _) => Some(*s),
            Type::Matrix(..) => Some(Scalar::Float),
            _ => None,
        }
    }

    pub fn is_scalar(&self) -> bool {
        matches!(self, Type::Scalar(_))
    }

    pub fn is_vector(&self) -> bool {
        matches!(self, Type::Vector(..))
    }

    pub fn is_matrix(&self) -> bool {
        matches!(self, Type::Matrix(..))
    }

    pub fn is_array(&self) -> bool {
        matches!(self, Type::Array(..))
    }

    /// A scalar, vector or matrix.
    pub fn is_basic(&self) -> bool {
        self.base().is_some()
    }

    /// A scalar, vector or matrix of float or int.
    pub fn is_numeric(&self) -> bool {
        matches!(self.base(), Some(Scalar::Float | Scalar::Int))
    }

    /// Components of a scalar or vector (1 to 4), rows of a matrix.
    pub fn vector_size(&self) -> u8 {
        match self {
            Type::Vector(_, n) => *n,
            Type::Matrix(_, r) => *r,
            _ => 1,
        }
    }

    /// Scalar components of a scalar, vector or matrix (0 for other types).
    pub fn components(&self) -> usize {
        match self {
            Type::Scalar(_) => 1,
            Type::Vector(_, n) => *n as usize,
            Type::Matrix(c, r) => (*c * *r) as usize,
            _ => 0,
        }
    }

    /// The same shape with another scalar kind (matrices stay float).
    pub fn with_base(&self, base: Scalar) -> Type {
        match self {
            Type::Scalar(_) => Type::Scalar(base),
            Type::Vector(_, n) => Type::Vector(base, *n),
            other => other.clone(),
        }
    }

    /// Whether the type contains a sampler (which only uniforms and parameters may hold).
    pub fn contains_sampler(&self) -> bool {
        match self {
            Type::Sampler(_) => true,
            Type::Array(e, _) => e.contains_sampler(),
            Type::Struct(s) => s.members.iter().any(|(_, t)| t.contains_sampler()),
            _ => false,
        }
    }

    pub fn contains_array(&self) -> bool {
        match self {
            Type::Array(..) => true,
            Type::Struct(s) => s.members.iter().any(|(_, t)| t.contains_array()),
            _ => false,
        }
    }

    /// Whether the type is made only of float scalars, vectors and matrices (what attributes
    /// and varyings may be).
    pub fn is_float_based(&self) -> bool {
        match self {
            Type::Array(e, _) => e.is_float_based(),
            t => t.base() == Some(Scalar::Float),
        }
    }
}

impl fmt::Display for Type {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let scalar = |s: Scalar| match s {
            Scalar::Float => "float",
            Scalar::Int => "int",
            Scalar::Bool => "bool",
        };
        match self {
            Type::Void => write!(f, "void"),
            Type::Scalar(s) => write!(f, "{}", scalar(*s)),
            Type::Vector(s, n) => {
                let p = match s {
                    Scalar::Float => "",
                    Scalar::Int => "i",
                    Scalar::Bool => "b",
                };
                write!(f, "{p}vec{n}")
            }
            Type::Matrix(c, r) if c == r => write!(f, "mat{c}"),
            Type::Matrix(c, r) => write!(f, "mat{c}x{r}"),
            Type::Sampler(s) => write!(f, "{}", s.name()),
            Type::Struct(s) => write!(f, "{}", s.name),
            Type::Array(e, Some(n)) => write!(f, "{e}[{n}]"),
            Type::Array(e, None) => write!(f, "{e}[]"),
        }
    }
}

/// One scalar component of a constant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    F(f32),
    I(i32),
    B(bool),
}

impl Value {
    pub fn as_f32(self) -> f32 {
        match self {
            Value::F(f) => f,
            Value::I(i) => i as f32,
            Value::B(b) => b as u8 as f32,
        }
    }

    pub fn as_i32(self) -> i32 {
        match self {
            // GLSL's float → int conversion truncates towards zero (saturating in Rust).
            Value::F(f) => f as i32,
            Value::I(i) => i,
            Value::B(b) => b as i32,
        }
    }

    pub fn as_bool(self) -> bool {
        match self {
            Value::F(f) => f != 0.0,
            Value::I(i) => i != 0,
            Value::B(b) => b,
        }
    }

    pub fn convert(self, to: Scalar) -> Value {
        match to {
            Scalar::Float => Value::F(self.as_f32()),
            Scalar::Int => Value::I(self.as_i32()),
            Scalar::Bool => Value::B(self.as_bool()),
        }
    }
}

/// A constant's value: the components of a scalar, vector or matrix (column-major), or the
/// elements or members of an array or struct.
#[derive(Clone, Debug, PartialEq)]
pub enum Constant {
    Basic(Vec<Value>),
    Composite(Vec<Constant>),
}

impl Constant {
    pub fn components(&self) -> &[Value] {
        match self {
            Constant::Basic(v) => v,
            Constant::Composite(_) => &[],
        }
    }
}

pub type VarId = usize;
pub type FunctionId = usize;

/// Where a variable lives and who may write it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarKind {
    /// A built-in variable, constant or uniform of the stage.
    Builtin,
    Global,
    Local,
    Parameter(ParameterDirection),
}

#[derive(Clone, Debug)]
pub struct Variable {
    pub name: String,
    /// An unsized array's size is filled in after the whole shader is checked, from its
    /// largest constant index.
    pub ty: Type,
    pub kind: VarKind,
    /// `const`, `attribute`, `varying`, `uniform` as declared (built-ins: as the spec
    /// declares them: `gl_Color` is an attribute in a vertex shader and a varying in a
    /// fragment shader; `gl_FragColor` has none).
    pub storage: Option<Storage>,
    pub read_only: bool,
    pub invariant: bool,
    pub centroid: bool,
    /// A `const` variable's folded value.
    pub constant: Option<Constant>,
    /// The largest constant index used on an array, for sizing unsized arrays.
    pub max_index: Option<u32>,
    /// Whether `ty` is an array declared without a size that the shader sized by its
    /// largest constant index: another shader of the program may declare it larger (GLSL
    /// 1.10 section 4.1.9).
    pub implicit_size: bool,
    /// Whether the shader ever writes the variable (`gl_FragColor`, `gl_FragData`...).
    pub written: bool,
    /// Whether the shader reads or writes it at all.
    pub used: bool,
    pub pos: Pos,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    /// Logical `!` of a bool.
    Not,
    PreIncrement,
    PreDecrement,
    PostIncrement,
    PostDecrement,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    /// Component-wise (a scalar operand applies to every component).
    Add,
    Sub,
    Mul,
    Div,
    /// The linear-algebra product: matrix × matrix, matrix × vector, vector × matrix.
    MatMul,
    Less,
    Greater,
    LessEqual,
    GreaterEqual,
    /// Whole-value comparisons (vectors, matrices, arrays, structs) giving one bool.
    Equal,
    NotEqual,
    And,
    Or,
    Xor,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub ty: Type,
    pub kind: ExprKind,
    pub pos: Pos,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Constant(Constant),
    Variable(VarId),
    Unary(UnaryOp, Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    /// `target = value` or `target op= value` (`value` converted to the target's kind).
    Assign(Option<BinaryOp>, Box<Expr>, Box<Expr>),
    Conditional(Box<Expr>, Box<Expr>, Box<Expr>),
    Sequence(Box<Expr>, Box<Expr>),
    /// An array element, a vector component or a matrix column.
    Index(Box<Expr>, Box<Expr>),
    /// A struct member by its index.
    Field(Box<Expr>, usize),
    /// Vector components by index (0..4), 1 to 4 of them.
    Swizzle(Box<Expr>, Vec<u8>),
    /// The operand converted component-wise to this expression's type's scalar kind.
    Convert(Box<Expr>),
    /// A constructor of this expression's type. Arguments are as written (GLSL's rules take
    /// their components in order, splat a single scalar, put it on a matrix's diagonal, or
    /// copy a matrix into a matrix of another size).
    Construct(Vec<Expr>),
    /// A call of one of the shader's functions.
    Call(FunctionId, Vec<Expr>),
    /// A call of a built-in function, by name, with arguments converted to its parameters.
    Builtin(&'static str, Vec<Expr>),
}

impl Expr {
    pub fn constant(&self) -> Option<&Constant> {
        match &self.kind {
            ExprKind::Constant(c) => Some(c),
            _ => None,
        }
    }

    /// The value of a constant bool condition (`if (false)`, a folded `sqrt(1.0) != 1.0`):
    /// the branch it rules out is dead code, which the link and the lowering skip as Mesa's
    /// compiler drops it (a call there to a function defined nowhere is no link error).
    pub fn constant_bool(&self) -> Option<bool> {
        match self.constant()?.components() {
            [Value::B(b)] => Some(*b),
            _ => None,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// A local variable and its initializer.
    Declare(VarId, Option<Expr>),
    Expr(Expr),
    Block(Vec<Stmt>),
    If {
        condition: Expr,
        then: Box<Stmt>,
        otherwise: Option<Box<Stmt>>,
    },
    /// `for`, `while` (no init or step) and `do ... while` (`test_first` false). A
    /// condition that declares a variable has it in `condition_var`, initialized to
    /// `condition` on each test.
    Loop {
        init: Vec<Stmt>,
        condition: Option<Expr>,
        condition_var: Option<VarId>,
        step: Option<Expr>,
        body: Box<Stmt>,
        test_first: bool,
    },
    Break,
    Continue,
    Return(Option<Expr>),
    Discard,
}

#[derive(Clone, Debug)]
pub struct Parameter {
    pub var: VarId,
    pub direction: ParameterDirection,
}

#[derive(Clone, Debug)]
pub struct Function {
    pub name: String,
    pub return_type: Type,
    pub parameters: Vec<Parameter>,
    /// `None` for a prototype never defined in this shader (another shader of the program
    /// may define it).
    pub body: Option<Vec<Stmt>>,
    pub pos: Pos,
}

/// The shader stage a source is compiled for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    Vertex,
    Fragment,
}

/// A checked shader.
#[derive(Clone, Debug)]
pub struct Checked {
    pub stage: Stage,
    pub version: u32,
    /// Every variable: the built-ins the shader uses, globals, parameters and locals.
    pub variables: Vec<Variable>,
    /// The shader's global variables in declaration order, with their initializers.
    pub globals: Vec<(VarId, Option<Expr>)>,
    pub functions: Vec<Function>,
    pub main: Option<FunctionId>,
    /// `#pragma STDGL invariant(all)`.
    pub invariant_all: bool,
}
