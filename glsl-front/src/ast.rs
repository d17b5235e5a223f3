//! The syntax tree of a GLSL 1.10/1.20 shader as the parser builds it: untyped, with the
//! source position of every declaration, statement and expression, for semantic analysis
//! to type, check and lower.
//!
//! It keeps the source's shape where the grammar gives a choice (an array size on the type,
//! `float[3] a`, or on the name, `float a[3]`) so that messages can speak of what was
//! written; semantic analysis folds the forms together.

use super::diagnostics::Pos;
use super::lex::Sampler;

/// A whole shader.
#[derive(Clone, Debug, PartialEq)]
pub struct TranslationUnit {
    pub version: u32,
    pub items: Vec<ExternalDeclaration>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExternalDeclaration {
    Function(FunctionDefinition),
    Declaration(Declaration),
}

/// The basic types and struct types a type specifier names.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeName {
    Void,
    Float,
    Int,
    Bool,
    Vec(u8),
    IVec(u8),
    BVec(u8),
    /// Columns, rows.
    Mat(u8, u8),
    Sampler(Sampler),
    /// A struct defined here.
    Struct(StructDefinition),
    /// A struct type by its name.
    Named(String),
}

/// An array's size as written: `[]` (1.20: sized by its initializer or later use) or `[e]`.
#[derive(Clone, Debug, PartialEq)]
pub enum ArraySize {
    Unsized,
    Sized(Box<Expr>),
}

/// A type specifier: a type name and, from GLSL 1.20 on, an array size after it.
#[derive(Clone, Debug, PartialEq)]
pub struct TypeSpecifier {
    pub name: TypeName,
    pub array: Option<ArraySize>,
    pub pos: Pos,
}

#[derive(Clone, Debug, PartialEq)]
pub struct StructDefinition {
    /// `None` for an anonymous struct (`struct { ... } s;`).
    pub name: Option<String>,
    pub members: Vec<StructMember>,
    pub pos: Pos,
}

/// `type a, b[2];` inside a struct.
#[derive(Clone, Debug, PartialEq)]
pub struct StructMember {
    pub ty: TypeSpecifier,
    pub declarators: Vec<(String, Option<ArraySize>, Pos)>,
    pub pos: Pos,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Storage {
    Const,
    Attribute,
    Varying,
    Uniform,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParameterDirection {
    In,
    Out,
    Inout,
}

/// The qualifiers before a type in a declaration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Qualifiers {
    pub invariant: bool,
    pub centroid: bool,
    pub storage: Option<Storage>,
}

/// Qualifiers and a type specifier.
#[derive(Clone, Debug, PartialEq)]
pub struct FullType {
    pub qualifiers: Qualifiers,
    pub specifier: TypeSpecifier,
    pub pos: Pos,
}

/// One name of a declaration: `a`, `a[3]`, `a = e`, `a[] = e`.
#[derive(Clone, Debug, PartialEq)]
pub struct Declarator {
    pub name: String,
    pub array: Option<ArraySize>,
    pub initializer: Option<Expr>,
    pub pos: Pos,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Declaration {
    /// A function prototype: `vec4 f(float a);`.
    Prototype(FunctionPrototype),
    /// `qualifiers type a, b = e, c[2];` (no declarators: `struct S { ... };` or `float;`).
    Variables { ty: FullType, declarators: Vec<Declarator>, pos: Pos },
    /// `invariant gl_Position, v;` (GLSL 1.20): names declared earlier made invariant.
    Invariant { names: Vec<(String, Pos)>, pos: Pos },
}

#[derive(Clone, Debug, PartialEq)]
pub struct Parameter {
    pub is_const: bool,
    /// As written (`None` is `in`).
    pub direction: Option<ParameterDirection>,
    pub ty: TypeSpecifier,
    pub name: Option<String>,
    pub array: Option<ArraySize>,
    pub pos: Pos,
}

#[derive(Clone, Debug, PartialEq)]
pub struct FunctionPrototype {
    pub return_type: FullType,
    pub name: String,
    pub parameters: Vec<Parameter>,
    pub pos: Pos,
}

#[derive(Clone, Debug, PartialEq)]
pub struct FunctionDefinition {
    pub prototype: FunctionPrototype,
    pub body: Vec<Statement>,
    pub pos: Pos,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    pub kind: StatementKind,
    pub pos: Pos,
}

/// The condition of `if`, `while` and `for`: an expression, or (`while`, `for`) a
/// declaration with an initializer, `while (bool b = f())`.
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    Expr(Expr),
    Declaration { ty: FullType, name: String, initializer: Expr, pos: Pos },
}

#[derive(Clone, Debug, PartialEq)]
pub enum StatementKind {
    Compound(Vec<Statement>),
    Declaration(Declaration),
    /// `e;` or the empty statement `;`.
    Expr(Option<Expr>),
    If {
        condition: Expr,
        then: Box<Statement>,
        otherwise: Option<Box<Statement>>,
    },
    For {
        init: Box<Statement>,
        condition: Option<Condition>,
        step: Option<Expr>,
        body: Box<Statement>,
    },
    While {
        condition: Condition,
        body: Box<Statement>,
    },
    DoWhile {
        body: Box<Statement>,
        condition: Expr,
    },
    Break,
    Continue,
    Return(Option<Expr>),
    Discard,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Plus,
    Minus,
    Not,
    /// `~` (reserved in 1.10 and 1.20: semantic analysis refuses it).
    BitNot,
    PreIncrement,
    PreDecrement,
    PostIncrement,
    PostDecrement,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Mul,
    Div,
    /// `%`, `<<`, `>>`, `&`, `^`, `|`: reserved in 1.10 and 1.20 (parsed, refused by
    /// semantic analysis, as in Mesa, whose grammar is shared with later versions).
    Mod,
    Add,
    Sub,
    Shl,
    Shr,
    Less,
    Greater,
    LessEqual,
    GreaterEqual,
    Equal,
    NotEqual,
    BitAnd,
    BitXor,
    BitOr,
    And,
    Xor,
    Or,
}

/// `=` (`None`) or a compound assignment's operator.
pub type AssignOp = Option<BinaryOp>;

/// What a call calls: a function (or a struct constructor) by name, or a constructor of a
/// basic or array type (`vec4(...)`, `float[3](...)`, 1.20's array constructors).
#[derive(Clone, Debug, PartialEq)]
pub enum Callee {
    Name(String),
    Type(TypeSpecifier),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub pos: Pos,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Ident(String),
    /// An integer literal's 32 bits.
    Int(u32),
    Float(f32),
    Bool(bool),
    Unary(UnaryOp, Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    Assign(AssignOp, Box<Expr>, Box<Expr>),
    Conditional(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `a, b`.
    Sequence(Box<Expr>, Box<Expr>),
    Index(Box<Expr>, Box<Expr>),
    /// Field selection or swizzle: `s.member`, `v.xyz`.
    Field(Box<Expr>, String),
    Call(Callee, Vec<Expr>),
    /// `a.length()` (1.20) and any other method-call shape, for semantic analysis to check.
    Method(Box<Expr>, String, Vec<Expr>),
}
