//! The GLSL 1.10/1.20 parser: recursive descent over the grammar of chapter 9 of the
//! specifications, with precedence climbing for binary operators, building [`ast`] nodes
//! with their source positions.
//!
//! Written by hand (not generated) so that messages and positions are ours: a syntax error
//! reads `syntax error, unexpected X, expecting Y` at the offending token, as Mesa's
//! parser words it, and, as in Mesa, the first syntax error ends the parse. The parser
//! keeps the struct names in scope because the grammar needs them: `S x;` declares, `s x;`
//! is an error, `S(1.0)` constructs. Nesting (parentheses, unary operators, statements) has
//! a ceiling, [`MAX_NESTING`], and so do the chains that grow a tree to the left
//! ([`MAX_CHAIN`]), so that a pathological shader is an error, not a stack overflow.
//!
//! Version gating: the 1.20 keywords (`invariant`, `centroid`, `mat2x3`...) are keywords
//! only in 1.20 shaders (the lexer's business); the 1.20 syntax (array types on the type
//! specifier, array constructors, unsized array initializers) is refused in 1.10 shaders
//! here. Semantic rules (types, declared names, where a qualifier may appear, the reserved
//! operators `%`, `<<`, `&`...) are left to semantic analysis.

use super::ast::*;
use super::diagnostics::{InfoLog, Pos};
use super::lex::{Keyword, Token, TokenKind};
use std::collections::HashMap;

/// The deepest nesting of parentheses, unary operators and statements the parser accepts.
pub const MAX_NESTING: usize = 256;

/// The most operators a left-growing chain (`a + b + c ...`, `a, b, c ...`, `a[0].x.y ...`)
/// may hold: each adds a level to the tree that semantic analysis walks and that is freed
/// recursively, so an unbounded chain (10⁵ terms) would overflow the caller's stack.
pub const MAX_CHAIN: usize = 512;

/// The struct types of the built-in uniform state (GLSL 1.10/1.20 section 7.5), which a
/// shader may name (`vec4 f(gl_LightSourceParameters l)`).
pub const BUILTIN_STRUCTS: [&str; 8] = [
    "gl_DepthRangeParameters",
    "gl_PointParameters",
    "gl_MaterialParameters",
    "gl_LightSourceParameters",
    "gl_LightModelParameters",
    "gl_LightModelProducts",
    "gl_LightProducts",
    "gl_FogParameters",
];

/// A parse failed; the message is in the log.
#[derive(Debug)]
pub struct Failed;

type PResult<T> = Result<T, Failed>;

pub struct Parser<'a> {
    tokens: &'a [Token],
    at: usize,
    version: u32,
    log: &'a mut InfoLog,
    /// Names declared in each open scope, innermost last: true for a struct type name.
    scopes: Vec<HashMap<String, bool>>,
    depth: usize,
}

/// Parses a preprocessed shader's tokens (ending with [`TokenKind::End`]).
pub fn parse(tokens: &[Token], version: u32, log: &mut InfoLog) -> PResult<TranslationUnit> {
    // The built-in uniform state's struct types are type names from the start.
    let builtins = BUILTIN_STRUCTS.iter().map(|n| (n.to_string(), true)).collect();
    let mut p = Parser { tokens, at: 0, version, log, scopes: vec![builtins], depth: 0 };
    let mut items = Vec::new();
    while p.peek() != &TokenKind::End {
        if p.eat_punct(";") {
            continue; // a stray `;` at global scope, accepted as Mesa does
        }
        items.push(p.external_declaration()?);
    }
    Ok(TranslationUnit { version, items })
}

fn describe(kind: &TokenKind) -> String {
    match kind {
        TokenKind::Ident(name) => format!("IDENTIFIER `{name}'"),
        TokenKind::Keyword(_) => "keyword".into(),
        TokenKind::Int(_) => "INTCONSTANT".into(),
        TokenKind::Float(_) => "FLOATCONSTANT".into(),
        TokenKind::Punct(p) => format!("'{p}'"),
        TokenKind::Invalid(_) => "invalid token".into(),
        TokenKind::End => "end of file".into(),
    }
}

fn binary_op(p: &str) -> Option<(u8, BinaryOp)> {
    use BinaryOp::*;
    Some(match p {
        "||" => (1, Or),
        "^^" => (2, Xor),
        "&&" => (3, And),
        "|" => (4, BitOr),
        "^" => (5, BitXor),
        "&" => (6, BitAnd),
        "==" => (7, Equal),
        "!=" => (7, NotEqual),
        "<" => (8, Less),
        ">" => (8, Greater),
        "<=" => (8, LessEqual),
        ">=" => (8, GreaterEqual),
        "<<" => (9, Shl),
        ">>" => (9, Shr),
        "+" => (10, Add),
        "-" => (10, Sub),
        "*" => (11, Mul),
        "/" => (11, Div),
        "%" => (11, Mod),
        _ => return None,
    })
}

fn assign_op(p: &str) -> Option<AssignOp> {
    use BinaryOp::*;
    Some(match p {
        "=" => None,
        "*=" => Some(Mul),
        "/=" => Some(Div),
        "%=" => Some(Mod),
        "+=" => Some(Add),
        "-=" => Some(Sub),
        "<<=" => Some(Shl),
        ">>=" => Some(Shr),
        "&=" => Some(BitAnd),
        "^=" => Some(BitXor),
        "|=" => Some(BitOr),
        _ => return None,
    })
}

fn basic_type(k: Keyword) -> Option<TypeName> {
    Some(match k {
        Keyword::Void => TypeName::Void,
        Keyword::Float => TypeName::Float,
        Keyword::Int => TypeName::Int,
        Keyword::Bool => TypeName::Bool,
        Keyword::Vec(n) => TypeName::Vec(n),
        Keyword::IVec(n) => TypeName::IVec(n),
        Keyword::BVec(n) => TypeName::BVec(n),
        Keyword::Mat(c, r) => TypeName::Mat(c, r),
        Keyword::Sampler(s) => TypeName::Sampler(s),
        _ => return None,
    })
}

fn is_qualifier(k: &TokenKind) -> bool {
    matches!(
        k,
        TokenKind::Keyword(
            Keyword::Const
                | Keyword::Attribute
                | Keyword::Uniform
                | Keyword::Varying
                | Keyword::Centroid
                | Keyword::Invariant
        )
    )
}

impl Parser<'_> {
    fn peek(&self) -> &TokenKind {
        self.peek_at(0)
    }

    fn peek_at(&self, n: usize) -> &TokenKind {
        let i = (self.at + n).min(self.tokens.len() - 1);
        &self.tokens[i].kind
    }

    fn pos(&self) -> Pos {
        self.tokens[self.at.min(self.tokens.len() - 1)].pos
    }

    fn bump(&mut self) -> &Token {
        let i = self.at.min(self.tokens.len() - 1);
        if self.at < self.tokens.len() - 1 {
            self.at += 1;
        }
        &self.tokens[i]
    }

    fn is_punct(&self, p: &str) -> bool {
        matches!(self.peek(), TokenKind::Punct(q) if *q == p)
    }

    fn eat_punct(&mut self, p: &str) -> bool {
        let yes = self.is_punct(p);
        if yes {
            self.bump();
        }
        yes
    }

    fn expect_punct(&mut self, p: &str) -> PResult<Pos> {
        let pos = self.pos();
        if self.eat_punct(p) {
            Ok(pos)
        } else {
            Err(self.unexpected(&format!("'{p}'")))
        }
    }

    fn is_keyword(&self, k: Keyword) -> bool {
        self.peek() == &TokenKind::Keyword(k)
    }

    fn eat_keyword(&mut self, k: Keyword) -> bool {
        let yes = self.is_keyword(k);
        if yes {
            self.bump();
        }
        yes
    }

    /// Reports the current token as unexpected (or the lexer's complaint about it).
    fn unexpected(&mut self, expecting: &str) -> Failed {
        let t = &self.tokens[self.at.min(self.tokens.len() - 1)];
        let message = match &t.kind {
            TokenKind::Invalid(message) => message.clone(),
            TokenKind::Keyword(_) => {
                format!("syntax error, unexpected `{}', expecting {expecting}", self.spelling())
            }
            kind => format!("syntax error, unexpected {}, expecting {expecting}", describe(kind)),
        };
        self.log.error(t.pos, message);
        Failed
    }

    /// The current keyword's spelling, for messages.
    fn spelling(&self) -> String {
        match self.peek() {
            TokenKind::Keyword(k) => keyword_spelling(*k),
            other => describe(other),
        }
    }

    fn error<T>(&mut self, pos: Pos, message: impl Into<String>) -> PResult<T> {
        self.log.error(pos, message);
        Err(Failed)
    }

    fn requires_120(&mut self, pos: Pos, what: &str) -> PResult<()> {
        if self.version < 120 {
            return self.error(pos, format!("{what} require GLSL 1.20"));
        }
        Ok(())
    }

    fn enter(&mut self) -> PResult<()> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            let pos = self.pos();
            return self.error(pos, format!("nesting deeper than {MAX_NESTING} levels"));
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// Counts one more operator of a left-growing chain: an error past [`MAX_CHAIN`].
    fn lengthen(&mut self, chain: &mut usize) -> PResult<()> {
        *chain += 1;
        if *chain > MAX_CHAIN {
            let pos = self.pos();
            return self.error(pos, format!("expression of more than {MAX_CHAIN} operators in a row"));
        }
        Ok(())
    }

    fn declare(&mut self, name: &str, is_type: bool) {
        self.scopes.last_mut().expect("the global scope").insert(name.to_string(), is_type);
    }

    fn is_type_name(&self, name: &str) -> bool {
        self.scopes.iter().rev().find_map(|s| s.get(name)).copied().unwrap_or(false)
    }

    /// The token `n` ahead starts a type specifier.
    fn is_type_start_at(&self, n: usize) -> bool {
        match self.peek_at(n) {
            TokenKind::Keyword(Keyword::Struct) => true,
            TokenKind::Keyword(k) => basic_type(*k).is_some(),
            TokenKind::Ident(name) => self.is_type_name(name),
            _ => false,
        }
    }

    fn external_declaration(&mut self) -> PResult<ExternalDeclaration> {
        self.declaration(true)
    }

    /// A declaration, or at global scope (`global`) a function definition.
    fn declaration(&mut self, global: bool) -> PResult<ExternalDeclaration> {
        let pos = self.pos();
        // `invariant name, ...;`: the re-declaration form (1.20).
        if self.is_keyword(Keyword::Invariant) {
            if let TokenKind::Ident(name) = self.peek_at(1) {
                if !self.is_type_name(name) {
                    self.bump();
                    let mut names = Vec::new();
                    loop {
                        let npos = self.pos();
                        match self.peek().clone() {
                            TokenKind::Ident(name) => {
                                self.bump();
                                names.push((name, npos));
                            }
                            _ => return Err(self.unexpected("IDENTIFIER")),
                        }
                        if !self.eat_punct(",") {
                            break;
                        }
                    }
                    self.expect_punct(";")?;
                    return Ok(ExternalDeclaration::Declaration(Declaration::Invariant { names, pos }));
                }
            }
        }
        let ty = self.fully_specified_type()?;
        if let (TokenKind::Ident(name), TokenKind::Punct("(")) = (self.peek().clone(), self.peek_at(1)) {
            let prototype = self.function_prototype(ty, name)?;
            if global && self.is_punct("{") {
                self.scopes.push(HashMap::new());
                for p in &prototype.parameters {
                    if let Some(name) = &p.name {
                        self.scopes.last_mut().expect("pushed").insert(name.clone(), false);
                    }
                }
                self.expect_punct("{")?;
                let body = self.statements_until_brace();
                self.scopes.pop();
                let body = body?;
                return Ok(ExternalDeclaration::Function(FunctionDefinition { prototype, body, pos }));
            }
            self.expect_punct(";")?;
            return Ok(ExternalDeclaration::Declaration(Declaration::Prototype(prototype)));
        }
        let declarators = self.declarators()?;
        self.expect_punct(";")?;
        Ok(ExternalDeclaration::Declaration(Declaration::Variables { ty, declarators, pos }))
    }

    /// `name [size] [= init], ...` up to (not including) the `;`; empty before a `;`.
    fn declarators(&mut self) -> PResult<Vec<Declarator>> {
        let mut list = Vec::new();
        if self.is_punct(";") {
            return Ok(list);
        }
        loop {
            let pos = self.pos();
            let name = match self.peek().clone() {
                TokenKind::Ident(name) => {
                    self.bump();
                    name
                }
                _ => return Err(self.unexpected("IDENTIFIER")),
            };
            let array = self.array_suffix(true)?;
            let initializer = if self.eat_punct("=") {
                if array.is_some() {
                    self.requires_120(pos, "array initializers")?;
                }
                Some(self.assignment()?)
            } else {
                None
            };
            if matches!(array, Some(ArraySize::Unsized)) && initializer.is_none() && self.version >= 120 {
                // `float a[];` is 1.10's unsized array declaration, kept in 1.20.
            }
            self.declare(&name, false);
            list.push(Declarator { name, array, initializer, pos });
            if !self.eat_punct(",") {
                return Ok(list);
            }
        }
    }

    /// `[` `]` or `[` constant-expression `]` after a name (`unsized_ok`) or a type.
    fn array_suffix(&mut self, unsized_ok: bool) -> PResult<Option<ArraySize>> {
        if !self.eat_punct("[") {
            return Ok(None);
        }
        if unsized_ok && self.eat_punct("]") {
            return Ok(Some(ArraySize::Unsized));
        }
        let size = self.conditional()?;
        self.expect_punct("]")?;
        Ok(Some(ArraySize::Sized(Box::new(size))))
    }

    fn qualifiers(&mut self) -> PResult<Qualifiers> {
        let mut q = Qualifiers { invariant: self.eat_keyword(Keyword::Invariant), ..Qualifiers::default() };
        q.centroid = self.eat_keyword(Keyword::Centroid);
        let storage = match self.peek() {
            TokenKind::Keyword(Keyword::Const) => Some(Storage::Const),
            TokenKind::Keyword(Keyword::Attribute) => Some(Storage::Attribute),
            TokenKind::Keyword(Keyword::Uniform) => Some(Storage::Uniform),
            TokenKind::Keyword(Keyword::Varying) => Some(Storage::Varying),
            _ => None,
        };
        // GLSL 1.20's grammar: `invariant` and `centroid` qualify `varying` only.
        if (q.invariant || q.centroid) && storage != Some(Storage::Varying) {
            return Err(self.unexpected("`varying'"));
        }
        if storage.is_some() {
            self.bump();
        }
        q.storage = storage;
        Ok(q)
    }

    fn fully_specified_type(&mut self) -> PResult<FullType> {
        let pos = self.pos();
        let qualifiers = self.qualifiers()?;
        let specifier = self.type_specifier()?;
        Ok(FullType { qualifiers, specifier, pos })
    }

    fn type_specifier(&mut self) -> PResult<TypeSpecifier> {
        let pos = self.pos();
        let name = match self.peek().clone() {
            TokenKind::Keyword(Keyword::Struct) => TypeName::Struct(self.struct_specifier()?),
            TokenKind::Keyword(k) if basic_type(k).is_some() => {
                self.bump();
                basic_type(k).expect("checked")
            }
            TokenKind::Ident(name) if self.is_type_name(&name) => {
                self.bump();
                TypeName::Named(name)
            }
            _ => return Err(self.unexpected("a type")),
        };
        let array = if self.is_punct("[") {
            let at = self.pos();
            self.requires_120(at, "array types on the type specifier")?;
            self.array_suffix(true)?
        } else {
            None
        };
        Ok(TypeSpecifier { name, array, pos })
    }

    fn struct_specifier(&mut self) -> PResult<StructDefinition> {
        let pos = self.pos();
        self.bump(); // struct
        let name = match self.peek().clone() {
            TokenKind::Ident(name) => {
                self.bump();
                Some(name)
            }
            _ => None,
        };
        self.expect_punct("{")?;
        let mut members = Vec::new();
        loop {
            let mpos = self.pos();
            let ty = self.type_specifier()?;
            let mut declarators = Vec::new();
            loop {
                let dpos = self.pos();
                let member = match self.peek().clone() {
                    TokenKind::Ident(n) => {
                        self.bump();
                        n
                    }
                    _ => return Err(self.unexpected("IDENTIFIER")),
                };
                let array = self.array_suffix(false)?;
                declarators.push((member, array, dpos));
                if !self.eat_punct(",") {
                    break;
                }
            }
            self.expect_punct(";")?;
            members.push(StructMember { ty, declarators, pos: mpos });
            if self.eat_punct("}") {
                break;
            }
        }
        if let Some(n) = &name {
            self.declare(n, true);
        }
        Ok(StructDefinition { name, members, pos })
    }

    fn function_prototype(&mut self, return_type: FullType, name: String) -> PResult<FunctionPrototype> {
        let pos = self.pos();
        self.bump(); // the name
        self.bump(); // (
        self.declare(&name, false);
        let mut parameters = Vec::new();
        if self.is_keyword(Keyword::Void) && self.peek_at(1) == &TokenKind::Punct(")") {
            self.bump();
        }
        if !self.eat_punct(")") {
            loop {
                parameters.push(self.parameter()?);
                if self.eat_punct(")") {
                    break;
                }
                if !self.eat_punct(",") {
                    return Err(self.unexpected("',' or ')'"));
                }
            }
        }
        Ok(FunctionPrototype { return_type, name, parameters, pos })
    }

    fn parameter(&mut self) -> PResult<Parameter> {
        let pos = self.pos();
        let is_const = self.eat_keyword(Keyword::Const);
        let direction = match self.peek() {
            TokenKind::Keyword(Keyword::In) => Some(ParameterDirection::In),
            TokenKind::Keyword(Keyword::Out) => Some(ParameterDirection::Out),
            TokenKind::Keyword(Keyword::Inout) => Some(ParameterDirection::Inout),
            _ => None,
        };
        if direction.is_some() {
            self.bump();
        }
        let ty = self.type_specifier()?;
        let (name, array) = match self.peek().clone() {
            TokenKind::Ident(n) => {
                self.bump();
                (Some(n), self.array_suffix(false)?)
            }
            _ => (None, None),
        };
        Ok(Parameter { is_const, direction, ty, name, array, pos })
    }

    /// Statements up to and including the closing `}`.
    fn statements_until_brace(&mut self) -> PResult<Vec<Statement>> {
        let mut list = Vec::new();
        while !self.eat_punct("}") {
            if self.peek() == &TokenKind::End {
                return Err(self.unexpected("'}'"));
            }
            list.push(self.statement()?);
        }
        Ok(list)
    }

    /// A statement in a scope of its own (the bodies of `if`, loops).
    fn scoped_statement(&mut self) -> PResult<Statement> {
        self.scopes.push(HashMap::new());
        let s = self.statement();
        self.scopes.pop();
        s
    }

    fn statement(&mut self) -> PResult<Statement> {
        self.enter()?;
        let s = self.statement_inner();
        self.leave();
        s
    }

    fn statement_inner(&mut self) -> PResult<Statement> {
        let pos = self.pos();
        let kind = match self.peek().clone() {
            TokenKind::Punct("{") => {
                self.bump();
                self.scopes.push(HashMap::new());
                let body = self.statements_until_brace();
                self.scopes.pop();
                StatementKind::Compound(body?)
            }
            TokenKind::Punct(";") => {
                self.bump();
                StatementKind::Expr(None)
            }
            TokenKind::Keyword(Keyword::If) => {
                self.bump();
                self.expect_punct("(")?;
                let condition = self.expression()?;
                self.expect_punct(")")?;
                let then = Box::new(self.scoped_statement()?);
                let otherwise =
                    if self.eat_keyword(Keyword::Else) { Some(Box::new(self.scoped_statement()?)) } else { None };
                StatementKind::If { condition, then, otherwise }
            }
            TokenKind::Keyword(Keyword::While) => {
                self.bump();
                self.expect_punct("(")?;
                self.scopes.push(HashMap::new());
                let result = (|| {
                    let condition = self.condition()?;
                    self.expect_punct(")")?;
                    let body = Box::new(self.statement()?);
                    Ok(StatementKind::While { condition, body })
                })();
                self.scopes.pop();
                result?
            }
            TokenKind::Keyword(Keyword::Do) => {
                self.bump();
                let body = Box::new(self.scoped_statement()?);
                if !self.eat_keyword(Keyword::While) {
                    return Err(self.unexpected("`while'"));
                }
                self.expect_punct("(")?;
                let condition = self.expression()?;
                self.expect_punct(")")?;
                self.expect_punct(";")?;
                StatementKind::DoWhile { body, condition }
            }
            TokenKind::Keyword(Keyword::For) => {
                self.bump();
                self.expect_punct("(")?;
                self.scopes.push(HashMap::new());
                let result = (|| {
                    let init = Box::new(self.simple_statement()?);
                    let condition = if self.is_punct(";") { None } else { Some(self.condition()?) };
                    self.expect_punct(";")?;
                    let step = if self.is_punct(")") { None } else { Some(self.expression()?) };
                    self.expect_punct(")")?;
                    let body = Box::new(self.statement()?);
                    Ok(StatementKind::For { init, condition, step, body })
                })();
                self.scopes.pop();
                result?
            }
            TokenKind::Keyword(k @ (Keyword::Break | Keyword::Continue | Keyword::Discard)) => {
                self.bump();
                self.expect_punct(";")?;
                match k {
                    Keyword::Break => StatementKind::Break,
                    Keyword::Continue => StatementKind::Continue,
                    _ => StatementKind::Discard,
                }
            }
            TokenKind::Keyword(Keyword::Return) => {
                self.bump();
                let value = if self.is_punct(";") { None } else { Some(self.expression()?) };
                self.expect_punct(";")?;
                StatementKind::Return(value)
            }
            _ => return self.simple_statement(),
        };
        Ok(Statement { kind, pos })
    }

    /// Whether the tokens ahead begin a declaration rather than an expression: a qualifier,
    /// `struct`, or a type not followed by `(` (a constructor), also after `[...]`.
    fn is_declaration_start(&self) -> bool {
        let k = self.peek();
        if is_qualifier(k) || matches!(k, TokenKind::Keyword(Keyword::Struct)) {
            return true;
        }
        if !self.is_type_start_at(0) {
            return false;
        }
        let mut n = 1;
        if self.peek_at(n) == &TokenKind::Punct("[") {
            let mut depth = 0usize;
            loop {
                match self.peek_at(n) {
                    TokenKind::Punct("[") => depth += 1,
                    TokenKind::Punct("]") => {
                        depth -= 1;
                        if depth == 0 {
                            n += 1;
                            break;
                        }
                    }
                    TokenKind::End => return true,
                    _ => {}
                }
                n += 1;
            }
        }
        self.peek_at(n) != &TokenKind::Punct("(")
    }

    /// A declaration or expression statement.
    fn simple_statement(&mut self) -> PResult<Statement> {
        let pos = self.pos();
        if self.eat_punct(";") {
            return Ok(Statement { kind: StatementKind::Expr(None), pos });
        }
        if self.is_declaration_start() {
            return match self.declaration(false)? {
                ExternalDeclaration::Declaration(d) => Ok(Statement { kind: StatementKind::Declaration(d), pos }),
                ExternalDeclaration::Function(_) => unreachable!("definitions only at global scope"),
            };
        }
        let e = self.expression()?;
        self.expect_punct(";")?;
        Ok(Statement { kind: StatementKind::Expr(Some(e)), pos })
    }

    /// A loop condition: an expression, or `type name = initializer`.
    fn condition(&mut self) -> PResult<Condition> {
        if !self.is_declaration_start() {
            return Ok(Condition::Expr(self.expression()?));
        }
        let pos = self.pos();
        let ty = self.fully_specified_type()?;
        let name = match self.peek().clone() {
            TokenKind::Ident(n) => {
                self.bump();
                n
            }
            _ => return Err(self.unexpected("IDENTIFIER")),
        };
        self.expect_punct("=")?;
        let initializer = self.assignment()?;
        self.declare(&name, false);
        Ok(Condition::Declaration { ty, name, initializer, pos })
    }

    /// `expression`: assignments separated by commas.
    pub fn expression(&mut self) -> PResult<Expr> {
        let mut e = self.assignment()?;
        let mut chain = 0;
        while self.is_punct(",") {
            self.lengthen(&mut chain)?;
            let pos = self.pos();
            self.bump();
            let right = self.assignment()?;
            e = Expr { kind: ExprKind::Sequence(Box::new(e), Box::new(right)), pos };
        }
        Ok(e)
    }

    fn assignment(&mut self) -> PResult<Expr> {
        let start = self.at;
        let (left, unary_shaped) = self.conditional_shaped()?;
        let op = match self.peek() {
            TokenKind::Punct(p) => assign_op(p),
            _ => None,
        };
        let Some(op) = op else { return Ok(left) };
        if !unary_shaped {
            // The grammar takes a unary expression on the left of `=`: `a + b = c` is a
            // syntax error at the `=`.
            let _ = start;
            return Err(self.unexpected("';'"));
        }
        let pos = self.pos();
        self.bump();
        self.enter()?;
        let right = self.assignment();
        self.leave();
        Ok(Expr { kind: ExprKind::Assign(op, Box::new(left), Box::new(right?)), pos })
    }

    fn conditional(&mut self) -> PResult<Expr> {
        Ok(self.conditional_shaped()?.0)
    }

    /// A conditional expression, and whether it is a unary expression in the grammar's sense.
    fn conditional_shaped(&mut self) -> PResult<(Expr, bool)> {
        let (cond, shaped) = self.binary(0)?;
        if !self.is_punct("?") {
            return Ok((cond, shaped));
        }
        let pos = self.pos();
        self.bump();
        self.enter()?;
        let result = (|| {
            let then = self.expression()?;
            self.expect_punct(":")?;
            let otherwise = self.assignment()?;
            Ok((then, otherwise))
        })();
        self.leave();
        let (then, otherwise) = result?;
        Ok((Expr { kind: ExprKind::Conditional(Box::new(cond), Box::new(then), Box::new(otherwise)), pos }, false))
    }

    /// Precedence climbing over the binary operators binding tighter than `min`.
    fn binary(&mut self, min: u8) -> PResult<(Expr, bool)> {
        let mut left = self.unary()?;
        let mut shaped = true;
        let mut chain = 0;
        while let Some((prec, op)) = match self.peek() {
            TokenKind::Punct(p) => binary_op(p).filter(|(prec, _)| *prec > min),
            _ => None,
        } {
            self.lengthen(&mut chain)?;
            let pos = self.pos();
            self.bump();
            let (right, _) = self.binary(prec)?;
            left = Expr { kind: ExprKind::Binary(op, Box::new(left), Box::new(right)), pos };
            shaped = false;
        }
        Ok((left, shaped))
    }

    fn unary(&mut self) -> PResult<Expr> {
        let pos = self.pos();
        let op = match self.peek() {
            TokenKind::Punct("++") => Some(UnaryOp::PreIncrement),
            TokenKind::Punct("--") => Some(UnaryOp::PreDecrement),
            TokenKind::Punct("+") => Some(UnaryOp::Plus),
            TokenKind::Punct("-") => Some(UnaryOp::Minus),
            TokenKind::Punct("!") => Some(UnaryOp::Not),
            TokenKind::Punct("~") => Some(UnaryOp::BitNot),
            _ => None,
        };
        let Some(op) = op else { return self.postfix() };
        self.bump();
        self.enter()?;
        let operand = self.unary();
        self.leave();
        Ok(Expr { kind: ExprKind::Unary(op, Box::new(operand?)), pos })
    }

    fn postfix(&mut self) -> PResult<Expr> {
        let mut e = self.primary()?;
        let mut chain = 0;
        loop {
            self.lengthen(&mut chain)?;
            let pos = self.pos();
            if self.eat_punct("[") {
                self.enter()?;
                let index = self.expression();
                self.leave();
                let index = index?;
                self.expect_punct("]")?;
                e = Expr { kind: ExprKind::Index(Box::new(e), Box::new(index)), pos };
            } else if self.eat_punct(".") {
                let name = match self.peek().clone() {
                    TokenKind::Ident(n) => {
                        self.bump();
                        n
                    }
                    _ => return Err(self.unexpected("IDENTIFIER")),
                };
                if self.is_punct("(") {
                    let args = self.arguments()?;
                    e = Expr { kind: ExprKind::Method(Box::new(e), name, args), pos };
                } else {
                    e = Expr { kind: ExprKind::Field(Box::new(e), name), pos };
                }
            } else if self.eat_punct("++") {
                e = Expr { kind: ExprKind::Unary(UnaryOp::PostIncrement, Box::new(e)), pos };
            } else if self.eat_punct("--") {
                e = Expr { kind: ExprKind::Unary(UnaryOp::PostDecrement, Box::new(e)), pos };
            } else {
                return Ok(e);
            }
        }
    }

    /// `( )`, `( void )` or `( a, b, ... )`.
    fn arguments(&mut self) -> PResult<Vec<Expr>> {
        self.expect_punct("(")?;
        let mut args = Vec::new();
        if self.is_keyword(Keyword::Void) && self.peek_at(1) == &TokenKind::Punct(")") {
            self.bump();
        }
        if self.eat_punct(")") {
            return Ok(args);
        }
        self.enter()?;
        let result = (|| loop {
            args.push(self.assignment()?);
            if self.eat_punct(")") {
                return Ok(());
            }
            if !self.eat_punct(",") {
                return Err(self.unexpected("',' or ')'"));
            }
        })();
        self.leave();
        result?;
        Ok(args)
    }

    fn primary(&mut self) -> PResult<Expr> {
        let pos = self.pos();
        let kind = match self.peek().clone() {
            TokenKind::Int(v) => {
                self.bump();
                ExprKind::Int(v)
            }
            TokenKind::Float(v) => {
                self.bump();
                ExprKind::Float(v)
            }
            TokenKind::Keyword(Keyword::True) => {
                self.bump();
                ExprKind::Bool(true)
            }
            TokenKind::Keyword(Keyword::False) => {
                self.bump();
                ExprKind::Bool(false)
            }
            TokenKind::Punct("(") => {
                self.bump();
                self.enter()?;
                let e = self.expression();
                self.leave();
                let e = e?;
                self.expect_punct(")")?;
                return Ok(e);
            }
            TokenKind::Ident(name) if !self.is_type_name(&name) => {
                self.bump();
                if self.is_punct("(") {
                    ExprKind::Call(Callee::Name(name), self.arguments()?)
                } else {
                    ExprKind::Ident(name)
                }
            }
            _ if self.is_type_start_at(0) && !self.is_keyword(Keyword::Struct) => {
                // A constructor: `vec4(...)`, `S(...)`, `float[3](...)`.
                let ty = self.type_specifier()?;
                if !self.is_punct("(") {
                    return Err(self.unexpected("'('"));
                }
                let args = self.arguments()?;
                match ty {
                    TypeSpecifier { name: TypeName::Named(n), array: None, .. } => {
                        ExprKind::Call(Callee::Name(n), args)
                    }
                    ty => ExprKind::Call(Callee::Type(ty), args),
                }
            }
            _ => return Err(self.unexpected("an expression")),
        };
        Ok(Expr { kind, pos })
    }
}

fn keyword_spelling(k: Keyword) -> String {
    use Keyword::*;
    match k {
        Attribute => "attribute".into(),
        Const => "const".into(),
        Uniform => "uniform".into(),
        Varying => "varying".into(),
        Centroid => "centroid".into(),
        Invariant => "invariant".into(),
        Break => "break".into(),
        Continue => "continue".into(),
        Do => "do".into(),
        For => "for".into(),
        While => "while".into(),
        If => "if".into(),
        Else => "else".into(),
        In => "in".into(),
        Out => "out".into(),
        Inout => "inout".into(),
        Void => "void".into(),
        Float => "float".into(),
        Int => "int".into(),
        Bool => "bool".into(),
        True => "true".into(),
        False => "false".into(),
        Discard => "discard".into(),
        Return => "return".into(),
        Struct => "struct".into(),
        Vec(n) => format!("vec{n}"),
        IVec(n) => format!("ivec{n}"),
        BVec(n) => format!("bvec{n}"),
        Mat(c, r) if c == r => format!("mat{c}"),
        Mat(c, r) => format!("mat{c}x{r}"),
        Sampler(s) => s.name().into(),
    }
}
