//! Semantic analysis of GLSL 1.10 and 1.20: a parsed shader ([`ast`]) → a checked program
//! ([`hir`]) for one stage, or errors in the info log worded as Mesa words them.
//!
//! One pass over the tree in source order, as GLSL's scoping requires (a name is visible
//! from its declaration on): names resolve through a stack of scopes whose outermost holds
//! the stage's built-ins; expressions are typed bottom-up, with GLSL 1.20's implicit int →
//! float conversions inserted as [`ExprKind::Convert`] nodes and constant operands folded
//! at once ([`fold`]), so that an array size or a `const` initializer is a constant exactly
//! when the specification says it is. Overloads resolve by exact match first, then (1.20)
//! by one match through conversions.
//!
//! An error does not end the check: the construct that failed has no type and its parents
//! say nothing more about it (no cascades), and the next statement is checked, so that a log
//! lists what a person needs to fix, as Mesa's does. Expressions nest without bound in the
//! syntax tree (`a+a+...+a` is left-deep), so the checker counts the tree's depth and refuses
//! past [`MAX_DEPTH`]; a left-deep chain it checks in a loop, not by recursion.

use super::ast::{self, ParameterDirection, Storage};
use super::builtins::{self, Access, Limits, Signature};
use super::diagnostics::{InfoLog, Pos};
use super::fold;
use super::hir::*;
use std::collections::HashMap;
use std::sync::Arc;

/// The deepest expression or statement nesting the checker follows: the height of the
/// tree below a function body, which the later passes (the link's walk, the lowering,
/// freeing) follow recursively. Room for the parser's longest chain
/// ([`super::parse::MAX_CHAIN`], 512 operators, which the checker walks in a loop) and
/// 128 levels around it (piglit's `op-selection-*` tests sum 512 terms in one expression).
/// Measured (release build, whole front end: parse, check, link, lowering, freeing), a
/// level of a chain costs about 1 KB of stack and a level of nesting (parentheses, calls,
/// unary operators) 2–4 KB, of which the parser's [`super::parse::MAX_NESTING`] of 256
/// allows at most 256: the worst tree takes about 1.5 MB, within the 2 MB of a thread
/// Rust spawns (and the 8 MB of a main thread).
pub const MAX_DEPTH: usize = 640;

#[derive(Clone)]
enum Symbol {
    Var(VarId),
    Struct(Arc<StructType>),
}

/// A parameter as declared: type, direction, name, `const`.
type ParamDecl = (Type, ParameterDirection, Option<String>, bool);

/// The expression failed to check; its message is in the log.
type R<T> = Option<T>;

struct Checker<'a> {
    version: u32,
    stage: Stage,
    limits: Limits,
    log: &'a mut InfoLog,
    vars: Vec<Variable>,
    functions: Vec<Function>,
    function_names: HashMap<String, Vec<FunctionId>>,
    scopes: Vec<HashMap<String, Symbol>>,
    next_struct_id: u32,
    globals: Vec<(VarId, Option<Expr>)>,
    /// Inside a function: its return type.
    return_type: Option<Type>,
    function_name: String,
    loops: u32,
    depth: usize,
    /// Set when a call of a built-in function with constant arguments is folded: in GLSL
    /// 1.10 such a call is no constant expression (1.10 section 5.10 lists no function
    /// calls; 1.20 adds the built-ins), so a `const` initializer or an array size holding
    /// one is refused there, as Mesa refuses it. Its value is folded in either version.
    folded_builtin_call: bool,
}

/// Checks a parsed shader for `stage`. `None` when the log holds an error.
pub fn check(parsed: &super::Parsed, stage: Stage, limits: &Limits, log: &mut InfoLog) -> Option<Checked> {
    let version = parsed.unit.version;
    let mut c = Checker {
        version,
        stage,
        limits: limits.clone(),
        log,
        vars: Vec::new(),
        functions: Vec::new(),
        function_names: HashMap::new(),
        scopes: vec![HashMap::new()],
        next_struct_id: 0,
        globals: Vec::new(),
        return_type: None,
        function_name: String::new(),
        loops: 0,
        depth: 0,
        folded_builtin_call: false,
    };
    c.declare_builtins();
    c.scopes.push(HashMap::new());
    for item in &parsed.unit.items {
        match item {
            ast::ExternalDeclaration::Function(f) => c.function_definition(f),
            ast::ExternalDeclaration::Declaration(d) => {
                let stmts = c.declaration(d, true);
                for s in stmts {
                    if let Stmt::Declare(v, init) = s {
                        c.globals.push((v, init));
                    }
                }
            }
        }
    }
    c.finish();
    if c.log.has_errors() {
        return None;
    }
    let main =
        c.function_names.get("main").and_then(|ids| ids.iter().copied().find(|&i| c.functions[i].body.is_some()));
    Some(Checked {
        stage,
        version,
        variables: c.vars,
        globals: c.globals,
        functions: c.functions,
        main,
        invariant_all: parsed.invariant_all,
    })
}

fn direction_name(d: ParameterDirection) -> &'static str {
    match d {
        ParameterDirection::In => "in",
        ParameterDirection::Out => "out",
        ParameterDirection::Inout => "inout",
    }
}

fn storage_name(s: Storage) -> &'static str {
    match s {
        Storage::Const => "const",
        Storage::Attribute => "attribute",
        Storage::Varying => "varying",
        Storage::Uniform => "uniform",
    }
}

fn op_name(op: ast::BinaryOp) -> &'static str {
    use ast::BinaryOp::*;
    match op {
        Mul => "*",
        Div => "/",
        Mod => "%",
        Add => "+",
        Sub => "-",
        Shl => "<<",
        Shr => ">>",
        Less => "<",
        Greater => ">",
        LessEqual => "<=",
        GreaterEqual => ">=",
        Equal => "==",
        NotEqual => "!=",
        BitAnd => "&",
        BitXor => "^",
        BitOr => "|",
        And => "&&",
        Xor => "^^",
        Or => "||",
    }
}

fn type_list(types: &[Type]) -> String {
    types.iter().map(|t| t.to_string()).collect::<Vec<_>>().join(", ")
}

impl<'a> Checker<'a> {
    fn error(&mut self, pos: Pos, message: impl Into<String>) {
        self.log.error(pos, message);
    }

    // ------------------------------------------------------------ scopes and names

    fn lookup(&self, name: &str) -> Option<(usize, Symbol)> {
        self.scopes.iter().enumerate().rev().find_map(|(i, s)| s.get(name).map(|sym| (i, sym.clone())))
    }

    fn in_function(&self) -> bool {
        self.return_type.is_some()
    }

    fn declare_builtins(&mut self) {
        let structs = builtins::builtin_structs(&mut self.next_struct_id);
        for s in &structs {
            self.scopes[0].insert(s.name.clone(), Symbol::Struct(s.clone()));
        }
        for b in builtins::variables(self.stage, self.version, &self.limits, &structs) {
            let (storage, read_only) = match b.access {
                Access::In | Access::Uniform => {
                    (if b.access == Access::Uniform { Some(Storage::Uniform) } else { None }, true)
                }
                Access::Out => (None, false),
                Access::Const(_) => (Some(Storage::Const), true),
                Access::Attribute => (Some(Storage::Attribute), true),
                Access::VaryingOut => (Some(Storage::Varying), false),
                Access::VaryingIn => (Some(Storage::Varying), true),
            };
            let constant = builtins::const_value(b.access).map(|v| Constant::Basic(vec![v]));
            let id = self.vars.len();
            self.vars.push(Variable {
                name: b.name.to_string(),
                ty: b.ty,
                kind: VarKind::Builtin,
                storage,
                read_only,
                invariant: false,
                centroid: false,
                constant,
                max_index: None,
                implicit_size: false,
                written: false,
                used: false,
                pos: Pos::default(),
            });
            self.scopes[0].insert(b.name.to_string(), Symbol::Var(id));
        }
    }

    /// Reserved names: `gl_` prefixes are the implementation's; `__` is reserved too (a
    /// warning, as Mesa words it for desktop GLSL).
    fn check_name(&mut self, name: &str, pos: Pos) -> bool {
        if name.starts_with("gl_") {
            self.error(pos, format!("identifier `{name}' uses reserved `gl_' prefix"));
            return false;
        }
        if name.contains("__") {
            self.log.warning(pos, format!("identifier `{name}' uses reserved `__' string"));
        }
        true
    }

    /// Adds a variable to the innermost scope, refusing a name already declared there.
    fn add_var(&mut self, var: Variable) -> R<VarId> {
        let name = var.name.clone();
        let pos = var.pos;
        let at_global = self.scopes.len() == 2;
        if self.scopes.last().expect("scope").contains_key(&name)
            || (at_global && self.function_names.contains_key(&name))
        {
            self.error(pos, format!("`{name}' redeclared"));
            return None;
        }
        let id = self.vars.len();
        self.vars.push(var);
        self.scopes.last_mut().expect("scope").insert(name, Symbol::Var(id));
        Some(id)
    }

    // ------------------------------------------------------------ types

    /// `e` checked, and whether it is a constant expression of this version: folded to a
    /// constant, and in GLSL 1.10 without a built-in call folded into it
    /// ([`Checker::folded_builtin_call`]).
    fn constant_expr(&mut self, e: &ast::Expr) -> (R<Expr>, bool) {
        let outer = std::mem::take(&mut self.folded_builtin_call);
        let checked = self.expr(e);
        let calls = std::mem::replace(&mut self.folded_builtin_call, outer) && self.version < 120;
        let constant = checked.as_ref().is_some_and(|e| e.constant().is_some()) && !calls;
        (checked, constant)
    }

    fn array_size(&mut self, size: &ast::ArraySize) -> R<Option<u32>> {
        let ast::ArraySize::Sized(e) = size else { return Some(None) };
        let pos = e.pos;
        let (e, constant) = self.constant_expr(e);
        let e = e?;
        if !matches!(e.ty, Type::Scalar(Scalar::Int)) {
            let what = if e.ty.is_scalar() { "integer" } else { "scalar" };
            self.error(pos, format!("array size must be {what} type"));
            return None;
        }
        let (true, Some(Constant::Basic(v))) = (constant, e.constant()) else {
            self.error(pos, "array size must be a constant valued expression");
            return None;
        };
        let n = v[0].as_i32();
        if n <= 0 {
            self.error(pos, "array size must be > 0");
            return None;
        }
        Some(Some(n as u32))
    }

    fn wrap_array(&mut self, base: Type, size: &Option<ast::ArraySize>, pos: Pos) -> R<Type> {
        let Some(size) = size else { return Some(base) };
        if base.is_array() {
            self.error(pos, "arrays of arrays require GLSL 4.30 or GL_ARB_arrays_of_arrays");
            return None;
        }
        let n = self.array_size(size)?;
        Some(Type::Array(Box::new(base), n))
    }

    fn struct_definition(&mut self, def: &ast::StructDefinition) -> R<Arc<StructType>> {
        if self.depth > MAX_DEPTH {
            self.error(def.pos, format!("nesting deeper than {MAX_DEPTH} levels"));
            return None;
        }
        let mut members: Vec<(String, Type)> = Vec::new();
        let mut ok = true;
        for m in &def.members {
            if matches!(m.ty.name, ast::TypeName::Struct(_)) {
                self.error(m.pos, "embedded structure definitions are not allowed");
                ok = false;
                continue;
            }
            self.depth += 1;
            let base = self.type_specifier(&m.ty);
            self.depth -= 1;
            let Some(base) = base else {
                ok = false;
                continue;
            };
            if base == Type::Void {
                self.error(m.pos, "void type in struct member");
                ok = false;
                continue;
            }
            for (name, size, pos) in &m.declarators {
                let Some(ty) = self.wrap_array(base.clone(), size, *pos) else {
                    ok = false;
                    continue;
                };
                if matches!(ty, Type::Array(_, None)) {
                    self.error(*pos, format!("unsized array `{name}' in struct"));
                    ok = false;
                }
                if members.iter().any(|(n, _)| n == name) {
                    self.error(*pos, format!("duplicate field name `{name}' in structure"));
                    ok = false;
                }
                members.push((name.clone(), ty));
            }
        }
        if !ok {
            return None;
        }
        self.next_struct_id += 1;
        let name = def.name.clone().unwrap_or_else(|| format!("#anon_struct_{}", self.next_struct_id));
        let s = Arc::new(StructType { name: name.clone(), members, id: self.next_struct_id });
        if def.name.is_some() {
            if !self.check_name(&name, def.pos) {
                return None;
            }
            if self.scopes.last().expect("scope").contains_key(&name) {
                self.error(def.pos, format!("struct `{name}' previously defined"));
                return None;
            }
            self.scopes.last_mut().expect("scope").insert(name, Symbol::Struct(s.clone()));
        }
        Some(s)
    }

    fn type_name(&mut self, name: &ast::TypeName, pos: Pos) -> R<Type> {
        use ast::TypeName as T;
        Some(match name {
            T::Void => Type::Void,
            T::Float => FLOAT,
            T::Int => INT,
            T::Bool => BOOL,
            T::Vec(n) => Type::Vector(Scalar::Float, *n),
            T::IVec(n) => Type::Vector(Scalar::Int, *n),
            T::BVec(n) => Type::Vector(Scalar::Bool, *n),
            T::Mat(c, r) => Type::Matrix(*c, *r),
            T::Sampler(s) => Type::Sampler(*s),
            T::Struct(def) => Type::Struct(self.struct_definition(def)?),
            T::Named(n) => match self.lookup(n) {
                Some((_, Symbol::Struct(s))) => Type::Struct(s),
                _ => {
                    self.error(pos, format!("`{n}' is not a type"));
                    return None;
                }
            },
        })
    }

    fn type_specifier(&mut self, spec: &ast::TypeSpecifier) -> R<Type> {
        let base = self.type_name(&spec.name, spec.pos)?;
        self.wrap_array(base, &spec.array, spec.pos)
    }

    /// The type of a declarator: the specifier's, with the declarator's array size.
    fn declarator_type(&mut self, base: &Type, size: &Option<ast::ArraySize>, pos: Pos) -> R<Type> {
        self.wrap_array(base.clone(), size, pos)
    }

    // ------------------------------------------------------------ conversions

    /// `e` as type `to`: itself, or (1.20) its int → float conversion. `Err` gives it back.
    fn convert(&self, e: Expr, to: &Type) -> Result<Expr, Expr> {
        if &e.ty == to {
            return Ok(e);
        }
        if self.version >= 120
            && e.ty.base() == Some(Scalar::Int)
            && to.base() == Some(Scalar::Float)
            && e.ty.with_base(Scalar::Float) == *to
        {
            return Ok(self.make_convert(e, Scalar::Float));
        }
        Err(e)
    }

    fn can_convert(&self, from: &Type, to: &Type) -> bool {
        from == to
            || (self.version >= 120
                && from.base() == Some(Scalar::Int)
                && to.base() == Some(Scalar::Float)
                && from.with_base(Scalar::Float) == *to)
    }

    fn make_convert(&self, e: Expr, to: Scalar) -> Expr {
        let ty = e.ty.with_base(to);
        let pos = e.pos;
        if let Some(c) = e.constant().and_then(|c| fold::convert(c, to)) {
            return Expr { ty, kind: ExprKind::Constant(c), pos };
        }
        Expr { ty, kind: ExprKind::Convert(Box::new(e)), pos }
    }

    // ------------------------------------------------------------ expressions

    fn expr(&mut self, e: &ast::Expr) -> R<Expr> {
        if self.depth >= MAX_DEPTH {
            self.error(e.pos, format!("expression nesting deeper than {MAX_DEPTH} levels"));
            return None;
        }
        self.depth += 1;
        let r = self.expr_inner(e);
        self.depth -= 1;
        r
    }

    /// A left-deep chain of binary operators or commas (`a + b + c ...`, as the parser
    /// builds it without nesting) checked from its leftmost operand up, in a loop, so that
    /// the chain costs the checker's stack nothing per operator. The depth counted is
    /// still the tree's, which the later passes walk recursively: each right operand is
    /// checked at its node's depth.
    fn chain(&mut self, top: &ast::Expr) -> R<Expr> {
        use ast::ExprKind as K;
        let base = self.depth;
        let mut spine = vec![top];
        let mut leftmost = top;
        while let K::Binary(_, l, _) | K::Sequence(l, _) = &leftmost.kind {
            if base + spine.len() > MAX_DEPTH {
                self.error(leftmost.pos, format!("expression nesting deeper than {MAX_DEPTH} levels"));
                return None;
            }
            leftmost = l;
            spine.push(l);
        }
        let leaf = spine.pop().expect("the leftmost operand");
        // Inside a node, the depth is the node's own (as `expr` leaves it).
        self.depth = base + spine.len() - 1;
        let mut acc = self.expr(leaf);
        while let Some(node) = spine.pop() {
            self.depth = base + spine.len();
            let (K::Binary(_, _, r) | K::Sequence(_, r)) = &node.kind else { unreachable!("a chain link") };
            let right = self.expr(r);
            acc = match (acc, right, &node.kind) {
                (Some(l), Some(r), K::Binary(op, ..)) => self.binary(*op, l, r, node.pos),
                (Some(a), Some(b), _) => {
                    Some(Expr { ty: b.ty.clone(), kind: ExprKind::Sequence(Box::new(a), Box::new(b)), pos: node.pos })
                }
                _ => None,
            };
        }
        self.depth = base;
        acc
    }

    fn constant(ty: Type, c: Constant, pos: Pos) -> Expr {
        Expr { ty, kind: ExprKind::Constant(c), pos }
    }

    fn expr_inner(&mut self, e: &ast::Expr) -> R<Expr> {
        use ast::ExprKind as K;
        let pos = e.pos;
        match &e.kind {
            K::Int(v) => Some(Self::constant(INT, Constant::Basic(vec![Value::I(*v as i32)]), pos)),
            K::Float(v) => Some(Self::constant(FLOAT, Constant::Basic(vec![Value::F(*v)]), pos)),
            K::Bool(v) => Some(Self::constant(BOOL, Constant::Basic(vec![Value::B(*v)]), pos)),
            K::Ident(name) => self.identifier(name, pos),
            K::Unary(op, operand) => self.unary(*op, operand, pos),
            K::Binary(..) | K::Sequence(..) => self.chain(e),
            K::Assign(op, target, value) => self.assign(*op, target, value, pos),
            K::Conditional(c, a, b) => {
                let (c, a, b) = (self.expr(c), self.expr(a), self.expr(b));
                let (c, a, b) = (c?, a?, b?);
                if c.ty != BOOL {
                    self.error(c.pos, "?: condition must be scalar boolean");
                    return None;
                }
                let (a, b) = match (self.convert(a.clone(), &b.ty), self.convert(b.clone(), &a.ty)) {
                    (Ok(a2), _) if a2.ty == b.ty => (a2, b),
                    (_, Ok(b2)) => (a, b2),
                    _ => {
                        self.error(pos, "second and third operands of ?: operator must have identical types");
                        return None;
                    }
                };
                if self.version < 120 && a.ty.is_array() {
                    self.error(pos, "second and third operands of ?: operator cannot be arrays in GLSL 1.10");
                    return None;
                }
                let ty = a.ty.clone();
                if let Some(Constant::Basic(v)) = c.constant() {
                    if let (Some(_), Some(_)) = (a.constant(), b.constant()) {
                        return Some(if v[0].as_bool() { a } else { b });
                    }
                }
                Some(Expr { ty, kind: ExprKind::Conditional(Box::new(c), Box::new(a), Box::new(b)), pos })
            }
            K::Index(base, index) => {
                let (base, index) = (self.expr(base), self.expr(index));
                self.index(base?, index?, pos)
            }
            K::Field(base, name) => {
                let base = self.expr(base)?;
                self.field(base, name, pos)
            }
            K::Call(callee, args) => self.call(callee, args, pos),
            K::Method(base, name, args) => {
                let base = self.expr(base)?;
                if name != "length" || !args.is_empty() {
                    self.error(pos, format!("unknown method: `{name}'"));
                    return None;
                }
                match &base.ty {
                    Type::Array(_, Some(n)) if self.version >= 120 => {
                        Some(Self::constant(INT, Constant::Basic(vec![Value::I(*n as i32)]), pos))
                    }
                    Type::Array(_, None) => {
                        self.error(pos, "length called on unsized array");
                        None
                    }
                    Type::Array(..) => {
                        self.error(pos, "length() requires GLSL 1.20");
                        None
                    }
                    other => {
                        self.error(pos, format!("length method called on non-array type `{other}'"));
                        None
                    }
                }
            }
        }
    }

    fn identifier(&mut self, name: &str, pos: Pos) -> R<Expr> {
        match self.lookup(name) {
            Some((_, Symbol::Var(id))) => {
                let v = &mut self.vars[id];
                v.used = true;
                if let Some(c) = &v.constant {
                    return Some(Self::constant(v.ty.clone(), c.clone(), pos));
                }
                Some(Expr { ty: v.ty.clone(), kind: ExprKind::Variable(id), pos })
            }
            Some((_, Symbol::Struct(_))) => {
                self.error(pos, format!("`{name}' is a type, not a variable"));
                None
            }
            None => {
                self.error(pos, format!("`{name}' undeclared"));
                None
            }
        }
    }

    fn unary(&mut self, op: ast::UnaryOp, operand: &ast::Expr, pos: Pos) -> R<Expr> {
        use ast::UnaryOp as U;
        let e = self.expr(operand)?;
        let (hop, sym) = match op {
            U::Plus => {
                if !e.ty.is_numeric() {
                    self.error(pos, "operand of unary + must be numeric");
                    return None;
                }
                return Some(e);
            }
            U::Minus => (UnaryOp::Neg, "-"),
            U::Not => (UnaryOp::Not, "!"),
            U::BitNot => {
                self.error(pos, format!("operator '~' is reserved in GLSL {}", self.version_name()));
                return None;
            }
            U::PreIncrement => (UnaryOp::PreIncrement, "++"),
            U::PreDecrement => (UnaryOp::PreDecrement, "--"),
            U::PostIncrement => (UnaryOp::PostIncrement, "++"),
            U::PostDecrement => (UnaryOp::PostDecrement, "--"),
        };
        match hop {
            UnaryOp::Neg => {
                if !e.ty.is_numeric() {
                    self.error(pos, "operand of unary - must be numeric");
                    return None;
                }
            }
            UnaryOp::Not => {
                if e.ty != BOOL {
                    self.error(pos, "operand of `!' must be scalar boolean");
                    return None;
                }
            }
            _ => {
                if !e.ty.is_numeric() {
                    self.error(pos, format!("operand of `{sym}' must be numeric"));
                    return None;
                }
                self.lvalue(operand, &e, sym)?;
            }
        }
        let ty = e.ty.clone();
        if matches!(hop, UnaryOp::Neg | UnaryOp::Not) {
            if let Some(c) = e.constant().and_then(|c| fold::unary(hop, c)) {
                return Some(Self::constant(ty, c, pos));
            }
        }
        Some(Expr { ty, kind: ExprKind::Unary(hop, Box::new(e)), pos })
    }

    fn version_name(&self) -> &'static str {
        if self.version >= 120 {
            "1.20"
        } else {
            "1.10"
        }
    }

    /// Brings the operands of an arithmetic or relational operator to one scalar kind.
    fn unify(&mut self, l: Expr, r: Expr, op: &str, pos: Pos) -> R<(Expr, Expr)> {
        if l.ty.base() == r.ty.base() {
            return Some((l, r));
        }
        if self.version >= 120 {
            let lb = l.ty.base();
            let rb = r.ty.base();
            if lb == Some(Scalar::Int) && rb == Some(Scalar::Float) {
                return Some((self.make_convert(l, Scalar::Float), r));
            }
            if lb == Some(Scalar::Float) && rb == Some(Scalar::Int) {
                return Some((l, self.make_convert(r, Scalar::Float)));
            }
        }
        self.error(pos, format!("could not implicitly convert operands to arithmetic operator `{op}'"));
        None
    }

    /// The type of an arithmetic operation on `l` and `r` (already of one scalar kind), and
    /// whether `*` is the linear-algebra product.
    fn arithmetic_type(&mut self, op: ast::BinaryOp, l: &Type, r: &Type, pos: Pos) -> R<(Type, bool)> {
        let mul = op == ast::BinaryOp::Mul;
        let (lt, rt) = (l, r);
        match (lt, rt) {
            (Type::Scalar(_), _) => Some((rt.clone(), false)),
            (_, Type::Scalar(_)) => Some((lt.clone(), false)),
            (Type::Vector(_, a), Type::Vector(_, b)) => {
                if a != b {
                    self.error(pos, "vector size mismatch for arithmetic operator");
                    return None;
                }
                Some((lt.clone(), false))
            }
            (Type::Matrix(c, r), Type::Vector(_, n)) if mul => {
                if c != n {
                    self.error(pos, "size mismatch for matrix multiplication");
                    return None;
                }
                Some((Type::Vector(Scalar::Float, *r), true))
            }
            (Type::Vector(_, n), Type::Matrix(c, r)) if mul => {
                if r != n {
                    self.error(pos, "size mismatch for matrix multiplication");
                    return None;
                }
                Some((Type::Vector(Scalar::Float, *c), true))
            }
            (Type::Matrix(c1, r1), Type::Matrix(c2, r2)) if mul => {
                if c1 != r2 {
                    self.error(pos, "size mismatch for matrix multiplication");
                    return None;
                }
                Some((Type::Matrix(*c2, *r1), true))
            }
            (Type::Matrix(..), Type::Matrix(..)) if lt == rt => Some((lt.clone(), false)),
            _ => {
                self.error(pos, format!("type mismatch: `{lt}' and `{rt}' for operator `{}'", op_name(op)));
                None
            }
        }
    }

    fn binary(&mut self, op: ast::BinaryOp, l: Expr, r: Expr, pos: Pos) -> R<Expr> {
        use ast::BinaryOp as B;
        let name = op_name(op);
        let (hop, ty, l, r) = match op {
            B::Mod | B::Shl | B::Shr | B::BitAnd | B::BitXor | B::BitOr => {
                self.error(pos, format!("operator '{name}' is reserved in GLSL {}", self.version_name()));
                return None;
            }
            B::Add | B::Sub | B::Mul | B::Div => {
                if !l.ty.is_numeric() || !r.ty.is_numeric() {
                    self.error(pos, "operands to arithmetic operators must be numeric");
                    return None;
                }
                let (l, r) = self.unify(l, r, name, pos)?;
                let (ty, matmul) = self.arithmetic_type(op, &l.ty, &r.ty, pos)?;
                let hop = match op {
                    B::Add => BinaryOp::Add,
                    B::Sub => BinaryOp::Sub,
                    B::Mul if matmul => BinaryOp::MatMul,
                    B::Mul => BinaryOp::Mul,
                    _ => BinaryOp::Div,
                };
                (hop, ty, l, r)
            }
            B::Less | B::Greater | B::LessEqual | B::GreaterEqual => {
                if !l.ty.is_scalar() || !r.ty.is_scalar() || !l.ty.is_numeric() || !r.ty.is_numeric() {
                    self.error(pos, "operands to relational operators must be scalar and numeric");
                    return None;
                }
                let (l, r) = self.unify(l, r, name, pos)?;
                let hop = match op {
                    B::Less => BinaryOp::Less,
                    B::Greater => BinaryOp::Greater,
                    B::LessEqual => BinaryOp::LessEqual,
                    _ => BinaryOp::GreaterEqual,
                };
                (hop, BOOL, l, r)
            }
            B::Equal | B::NotEqual => {
                let (l, r) = match (self.convert(l.clone(), &r.ty), self.convert(r.clone(), &l.ty)) {
                    (Ok(l2), _) if l2.ty == r.ty => (l2, r),
                    (_, Ok(r2)) => (l, r2),
                    _ => {
                        self.error(pos, format!("operands of `{name}' must have the same type"));
                        return None;
                    }
                };
                if l.ty.contains_sampler() || l.ty == Type::Void {
                    self.error(pos, format!("operands of `{name}' cannot be of type `{}'", l.ty));
                    return None;
                }
                if self.version < 120 && l.ty.contains_array() {
                    self.error(pos, format!("array comparison with `{name}' requires GLSL 1.20"));
                    return None;
                }
                (if op == B::Equal { BinaryOp::Equal } else { BinaryOp::NotEqual }, BOOL, l, r)
            }
            B::And | B::Or | B::Xor => {
                if l.ty != BOOL {
                    self.error(l.pos, format!("LHS of `{name}' must be scalar boolean"));
                    return None;
                }
                if r.ty != BOOL {
                    self.error(r.pos, format!("RHS of `{name}' must be scalar boolean"));
                    return None;
                }
                let hop = match op {
                    B::And => BinaryOp::And,
                    B::Or => BinaryOp::Or,
                    _ => BinaryOp::Xor,
                };
                (hop, BOOL, l, r)
            }
        };
        if let (Some(a), Some(b)) = (l.constant(), r.constant()) {
            if let Some(c) = fold::binary(hop, &l.ty, a, &r.ty, b) {
                return Some(Self::constant(ty, c, pos));
            }
        }
        Some(Expr { ty, kind: ExprKind::Binary(hop, Box::new(l), Box::new(r)), pos })
    }

    /// Checks that `ast` (checked as `e`) may be written, and marks its variable written.
    fn lvalue(&mut self, ast: &ast::Expr, e: &Expr, what: &str) -> R<()> {
        use ast::ExprKind as K;
        match &ast.kind {
            K::Ident(name) => {
                let Some((_, Symbol::Var(id))) = self.lookup(name) else {
                    self.error(ast.pos, format!("non-lvalue in {what}"));
                    return None;
                };
                let v = &self.vars[id];
                if v.read_only {
                    let kind = match v.storage {
                        Some(s) => storage_name(s),
                        None => "read-only",
                    };
                    let msg = format!("assignment to {kind} variable `{name}'");
                    self.error(ast.pos, msg);
                    return None;
                }
                let _ = e;
                self.vars[id].written = true;
                Some(())
            }
            K::Index(base, _) => {
                let ExprKind::Index(hb, _) = &e.kind else {
                    self.error(ast.pos, format!("non-lvalue in {what}"));
                    return None;
                };
                self.lvalue(base, hb, what)
            }
            K::Field(base, name) => match &e.kind {
                ExprKind::Swizzle(hb, comps) => {
                    let mut seen = [false; 4];
                    for &c in comps {
                        if std::mem::replace(&mut seen[c as usize], true) {
                            self.error(
                                ast.pos,
                                format!("invalid swizzle / mask `{name}' in {what}: repeated component"),
                            );
                            return None;
                        }
                    }
                    self.lvalue(base, hb, what)
                }
                ExprKind::Field(hb, _) => self.lvalue(base, hb, what),
                _ => {
                    self.error(ast.pos, format!("non-lvalue in {what}"));
                    None
                }
            },
            _ => {
                self.error(ast.pos, format!("non-lvalue in {what}"));
                None
            }
        }
    }

    fn assign(&mut self, op: ast::AssignOp, target: &ast::Expr, value: &ast::Expr, pos: Pos) -> R<Expr> {
        let t = self.expr(target);
        let v = self.expr(value);
        let (t, v) = (t?, v?);
        self.lvalue(target, &t, "assignment")?;
        let ty = t.ty.clone();
        if let Type::Array(_, n) = &ty {
            if self.version < 120 {
                self.error(pos, "assignment to arrays requires GLSL 1.20");
                return None;
            }
            if n.is_none() {
                self.error(pos, "assignment to an unsized array");
                return None;
            }
        }
        let (hop, v) = match op {
            None => match self.convert(v, &ty) {
                Ok(v) => (None, v),
                Err(v) => {
                    self.error(pos, format!("type mismatch in assignment: `{}' = `{}'", ty, v.ty));
                    return None;
                }
            },
            Some(op) => {
                let tc = t.clone();
                let r = self.binary(op, tc, v, pos)?;
                if r.ty != ty {
                    self.error(pos, format!("type mismatch in assignment: `{}' {}= `{}'", ty, op_name(op), r.ty));
                    return None;
                }
                let (hop, rhs) = match r.kind {
                    ExprKind::Binary(hop, _, rhs) => (hop, *rhs),
                    _ => return None,
                };
                (Some(hop), rhs)
            }
        };
        Some(Expr { ty, kind: ExprKind::Assign(hop, Box::new(t), Box::new(v)), pos })
    }

    fn index(&mut self, base: Expr, index: Expr, pos: Pos) -> R<Expr> {
        let (elem, bound): (Type, Option<u32>) = match &base.ty {
            Type::Array(e, n) => ((**e).clone(), *n),
            Type::Vector(s, n) => (Type::Scalar(*s), Some(*n as u32)),
            Type::Matrix(c, r) => (Type::Vector(Scalar::Float, *r), Some(*c as u32)),
            _ => {
                self.error(pos, "cannot dereference non-array / non-matrix / non-vector");
                return None;
            }
        };
        if index.ty != INT {
            let what = if index.ty.is_scalar() { "integer" } else { "scalar" };
            self.error(index.pos, format!("array index must be {what}"));
            return None;
        }
        let var = match &base.kind {
            ExprKind::Variable(id) => Some(*id),
            _ => None,
        };
        if let Some(Constant::Basic(v)) = index.constant() {
            let i = v[0].as_i32();
            if i < 0 {
                self.error(index.pos, format!("array index must be >= 0 (got {i})"));
                return None;
            }
            if let Some(n) = bound {
                if i as u32 >= n {
                    self.error(index.pos, format!("array index must be < {n}"));
                    return None;
                }
            } else if let Some(id) = var {
                let limit = self.implicit_limit(id);
                if limit.is_some_and(|l| i as u32 >= l) {
                    self.error(
                        index.pos,
                        format!("array index must be < {} (the size of `{}')", limit.unwrap_or(0), self.vars[id].name),
                    );
                    return None;
                }
                let m = &mut self.vars[id].max_index;
                *m = Some(m.map_or(i as u32, |m| m.max(i as u32)));
            }
            if let Some(c) = base.constant().and_then(|c| fold::index(&base.ty, c, i as usize)) {
                return Some(Self::constant(elem, c, pos));
            }
        } else if bound.is_none() {
            match var {
                Some(id) if self.vars[id].kind == VarKind::Builtin => {}
                _ => {
                    self.error(pos, "unsized array index must be constant");
                    return None;
                }
            }
        }
        Some(Expr { ty: elem, kind: ExprKind::Index(Box::new(base), Box::new(index)), pos })
    }

    /// The largest size an unsized array may reach (`gl_TexCoord`: `gl_MaxTextureCoords`).
    fn implicit_limit(&self, id: VarId) -> Option<u32> {
        (self.vars[id].name == "gl_TexCoord").then_some(self.limits.max_texture_coords as u32)
    }

    fn field(&mut self, base: Expr, name: &str, pos: Pos) -> R<Expr> {
        match &base.ty {
            Type::Struct(s) => {
                let Some(i) = s.members.iter().position(|(n, _)| n == name) else {
                    self.error(pos, format!("no field `{name}' in structure `{}'", s.name));
                    return None;
                };
                let ty = s.members[i].1.clone();
                if let Some(c) = base.constant().and_then(|c| fold::field(c, i)) {
                    return Some(Self::constant(ty, c, pos));
                }
                Some(Expr { ty, kind: ExprKind::Field(Box::new(base), i), pos })
            }
            Type::Vector(s, n) => {
                let (s, n) = (*s, *n);
                let sets = ["xyzw", "rgba", "stpq"];
                let set = name.chars().next().and_then(|c| sets.iter().find(|set| set.contains(c)));
                let comps: Option<Vec<u8>> =
                    set.and_then(|set| name.chars().map(|c| set.find(c).map(|i| i as u8).filter(|&i| i < n)).collect());
                let Some(comps) = comps.filter(|c| !c.is_empty() && c.len() <= 4) else {
                    self.error(pos, format!("invalid swizzle / mask `{name}'"));
                    return None;
                };
                let ty = Type::vector(s, comps.len() as u8);
                if let Some(c) = base.constant().and_then(|c| fold::swizzle(c, &comps)) {
                    return Some(Self::constant(ty, c, pos));
                }
                Some(Expr { ty, kind: ExprKind::Swizzle(Box::new(base), comps), pos })
            }
            other => {
                let msg = if other.is_scalar() {
                    format!("invalid swizzle / mask `{name}'")
                } else {
                    format!("cannot access field `{name}' of non-structure / non-vector")
                };
                self.error(pos, msg);
                None
            }
        }
    }

    // ------------------------------------------------------------ calls and constructors

    fn call(&mut self, callee: &ast::Callee, args: &[ast::Expr], pos: Pos) -> R<Expr> {
        let mut checked = Vec::with_capacity(args.len());
        let mut ok = true;
        for a in args {
            match self.expr(a) {
                Some(e) => checked.push(e),
                None => ok = false,
            }
        }
        if !ok {
            return None;
        }
        // `f(void)`-style empty calls parse as no arguments.
        match callee {
            ast::Callee::Type(spec) => {
                let ty = match &spec.array {
                    Some(ast::ArraySize::Unsized) => {
                        let base = self.type_name(&spec.name, spec.pos)?;
                        Type::Array(Box::new(base), Some(checked.len() as u32))
                    }
                    _ => self.type_specifier(spec)?,
                };
                self.construct(ty, checked, pos)
            }
            ast::Callee::Name(name) => match self.lookup(name) {
                Some((_, Symbol::Struct(s))) => self.construct(Type::Struct(s), checked, pos),
                Some((_, Symbol::Var(_)))
                    if !self.function_names.contains_key(name.as_str()) || self.lookup_is_local_var(name) =>
                {
                    self.error(pos, format!("`{name}' is not a function"));
                    None
                }
                _ => self.function_call(name, args, checked, pos),
            },
        }
    }

    fn lookup_is_local_var(&self, name: &str) -> bool {
        matches!(self.lookup(name), Some((i, Symbol::Var(_))) if i >= 2)
    }

    fn construct(&mut self, ty: Type, args: Vec<Expr>, pos: Pos) -> R<Expr> {
        let fold_it = |ty: Type, args: Vec<Expr>| {
            let consts: Option<Vec<&Constant>> = args.iter().map(|a| a.constant()).collect();
            let types: Vec<Type> = args.iter().map(|a| a.ty.clone()).collect();
            if let Some(c) = consts.and_then(|cs| fold::construct(&ty, &types, &cs)) {
                return Expr { ty, kind: ExprKind::Constant(c), pos };
            }
            Expr { ty, kind: ExprKind::Construct(args), pos }
        };
        match &ty {
            Type::Array(elem, n) => {
                if self.version < 120 {
                    self.error(pos, "array constructors require GLSL 1.20");
                    return None;
                }
                let n = n.unwrap_or(0) as usize;
                if args.len() != n {
                    self.error(pos, format!("array constructor must have {n} parameters, not {}", args.len()));
                    return None;
                }
                let mut out = Vec::with_capacity(n);
                for (i, a) in args.into_iter().enumerate() {
                    match self.convert(a, elem) {
                        Ok(a) => out.push(a),
                        Err(a) => {
                            self.error(
                                a.pos,
                                format!("array constructor argument {} has type `{}', not `{elem}'", i + 1, a.ty),
                            );
                            return None;
                        }
                    }
                }
                Some(fold_it(ty, out))
            }
            Type::Struct(s) => {
                if args.len() != s.members.len() {
                    self.error(pos, format!("wrong number of arguments to constructor of `{}'", s.name));
                    return None;
                }
                let mut out = Vec::with_capacity(args.len());
                for (a, (member, mty)) in args.into_iter().zip(&s.members) {
                    match self.convert(a, mty) {
                        Ok(a) => out.push(a),
                        Err(a) => {
                            self.error(
                                a.pos,
                                format!(
                                    "constructor argument for `{}.{member}' has type `{}', not `{mty}'",
                                    s.name, a.ty
                                ),
                            );
                            return None;
                        }
                    }
                }
                Some(fold_it(ty.clone(), out))
            }
            t if t.is_basic() => {
                if args.is_empty() {
                    self.error(pos, format!("too few components to construct `{ty}'"));
                    return None;
                }
                for a in &args {
                    if !a.ty.is_basic() {
                        self.error(a.pos, format!("cannot construct `{ty}' from a non-numeric data type"));
                        return None;
                    }
                }
                let need = ty.components();
                if ty.is_matrix() && args.iter().any(|a| a.ty.is_matrix()) {
                    if args.len() > 1 {
                        self.error(pos, "for matrix-from-matrix constructors, only one argument may be given");
                        return None;
                    }
                    if self.version < 120 {
                        self.error(pos, "matrix-from-matrix constructors require GLSL 1.20");
                        return None;
                    }
                    return Some(fold_it(ty, args));
                }
                if args.len() == 1 && args[0].ty.is_scalar() {
                    return Some(fold_it(ty, args));
                }
                let mut have = 0;
                for a in &args {
                    if have >= need {
                        self.error(pos, format!("too many parameters to `{ty}' constructor"));
                        return None;
                    }
                    have += a.ty.components();
                }
                if have < need {
                    self.error(pos, format!("too few components to construct `{ty}'"));
                    return None;
                }
                Some(fold_it(ty, args))
            }
            _ => {
                self.error(pos, format!("cannot construct `{ty}'"));
                None
            }
        }
    }

    fn function_call(&mut self, name: &str, ast_args: &[ast::Expr], args: Vec<Expr>, pos: Pos) -> R<Expr> {
        let arg_types: Vec<Type> = args.iter().map(|a| a.ty.clone()).collect();
        let user: Vec<FunctionId> = self.function_names.get(name).cloned().unwrap_or_default();
        // User functions first (exact, then through conversions), then the built-ins, which a
        // shader's own function of the same name hides in GLSL 1.20.
        let user_match = |c: &Checker, exact: bool| -> Vec<FunctionId> {
            user.iter()
                .copied()
                .filter(|&f| {
                    let ps = &c.functions[f].parameters;
                    ps.len() == arg_types.len()
                        && ps.iter().zip(&arg_types).all(|(p, a)| {
                            let pt = &c.vars[p.var].ty;
                            pt == a
                                || (!exact
                                    && match p.direction {
                                        ParameterDirection::In => c.can_convert(a, pt),
                                        ParameterDirection::Out => c.can_convert(pt, a),
                                        ParameterDirection::Inout => false,
                                    })
                        })
                })
                .collect()
        };
        let builtins_visible = self.version < 120 || user.is_empty();
        let sigs: Vec<&'static Signature> = if builtins_visible {
            builtins::functions()
                .get(name)
                .map(|v| {
                    v.iter()
                        .filter(|s| s.version <= self.version && s.stage.is_none_or(|st| st == self.stage))
                        .collect()
                })
                .unwrap_or_default()
        } else {
            Vec::new()
        };
        let builtin_match = |c: &Checker, exact: bool| -> Vec<&'static Signature> {
            sigs.iter()
                .copied()
                .filter(|s| {
                    s.params.len() == arg_types.len()
                        && s.params.iter().zip(&arg_types).all(|(p, a)| p == a || (!exact && c.can_convert(a, p)))
                })
                .collect()
        };
        if user.is_empty() && sigs.is_empty() {
            let exists = builtins::functions().contains_key(name);
            if exists {
                self.error(
                    pos,
                    format!(
                        "no matching function for call to `{name}({})' in this shader stage or version",
                        type_list(&arg_types)
                    ),
                );
            } else {
                self.error(pos, format!("no function with name '{name}'"));
            }
            return None;
        }
        for exact in [true, false] {
            let u = user_match(self, exact);
            // A shader's own function replaces a built-in of the same parameters.
            let b: Vec<&Signature> = builtin_match(self, exact)
                .into_iter()
                .filter(|s| {
                    !u.iter()
                        .any(|&f| self.functions[f].parameters.iter().map(|p| &self.vars[p.var].ty).eq(s.params.iter()))
                })
                .collect();
            if u.len() + b.len() > 1 {
                self.error(pos, format!("call to `{name}({})' is ambiguous", type_list(&arg_types)));
                return None;
            }
            if let Some(&f) = u.first() {
                let params = self.functions[f].parameters.clone();
                let mut out = Vec::with_capacity(args.len());
                for ((a, p), ast_arg) in args.into_iter().zip(&params).zip(ast_args) {
                    let pt = self.vars[p.var].ty.clone();
                    if p.direction != ParameterDirection::In {
                        let what =
                            format!("function parameter `{} {}'", direction_name(p.direction), self.vars[p.var].name);
                        self.lvalue(ast_arg, &a, &what)?;
                        // An `out` argument of another type (1.20) receives the parameter's
                        // value converted on return; it stays the lvalue here.
                        out.push(a);
                    } else {
                        out.push(self.convert(a, &pt).ok()?);
                    }
                }
                let ty = self.functions[f].return_type.clone();
                return Some(Expr { ty, kind: ExprKind::Call(f, out), pos });
            }
            if let Some(&s) = b.first() {
                let out: Vec<Expr> =
                    args.into_iter().zip(&s.params).filter_map(|(a, p)| self.convert(a, p).ok()).collect();
                let consts: Option<Vec<&Constant>> = out.iter().map(|a| a.constant()).collect();
                if let Some(c) = consts.and_then(|cs| fold::builtin(s.name, &s.ret, &s.params, &cs)) {
                    self.folded_builtin_call = true;
                    return Some(Self::constant(s.ret.clone(), c, pos));
                }
                return Some(Expr { ty: s.ret.clone(), kind: ExprKind::Builtin(s.name, out), pos });
            }
            if self.version < 120 {
                break;
            }
        }
        self.error(pos, format!("no matching function for call to `{name}({})'", type_list(&arg_types)));
        None
    }

    // ------------------------------------------------------------ declarations

    /// A declaration at global scope (`global`) or in a function: the variables it
    /// declares, as statements.
    fn declaration(&mut self, d: &ast::Declaration, global: bool) -> Vec<Stmt> {
        match d {
            ast::Declaration::Prototype(p) => {
                if !global {
                    self.error(p.pos, "function declarations are only allowed at global scope");
                    return Vec::new();
                }
                self.function_prototype(p, false);
                Vec::new()
            }
            ast::Declaration::Invariant { names, pos } => {
                if !global {
                    self.error(*pos, "`invariant' redeclaration is only allowed at global scope");
                    return Vec::new();
                }
                for (name, npos) in names {
                    match self.lookup(name) {
                        Some((_, Symbol::Var(id))) => {
                            let v = &self.vars[id];
                            let output_like = match self.stage {
                                Stage::Vertex => {
                                    (v.storage == Some(Storage::Varying) && !v.read_only)
                                        || matches!(v.name.as_str(), "gl_Position" | "gl_PointSize" | "gl_ClipVertex")
                                }
                                Stage::Fragment => v.storage == Some(Storage::Varying),
                            };
                            if !output_like {
                                self.error(
                                    *npos,
                                    format!(
                                        "`{name}' cannot be marked invariant; interfaces between shader stages only"
                                    ),
                                );
                            } else if v.used && v.kind != VarKind::Builtin {
                                self.error(*npos, format!("`{name}' cannot be marked invariant after its use"));
                            } else {
                                self.vars[id].invariant = true;
                            }
                        }
                        _ => self.error(*npos, format!("undeclared variable `{name}' cannot be marked invariant")),
                    }
                }
                Vec::new()
            }
            ast::Declaration::Variables { ty, declarators, pos } => self.variables(ty, declarators, *pos, global),
        }
    }

    fn variables(
        &mut self,
        full: &ast::FullType,
        declarators: &[ast::Declarator],
        pos: Pos,
        global: bool,
    ) -> Vec<Stmt> {
        let q = full.qualifiers;
        let Some(base) = self.type_specifier(&full.specifier) else { return Vec::new() };
        if declarators.is_empty() {
            if (q.storage.is_some() || q.invariant || q.centroid) && !matches!(base, Type::Struct(_)) {
                self.log.warning(pos, "empty declaration with qualifiers");
            }
            return Vec::new();
        }
        if !self.qualifiers_allowed(q, global, &base, pos) {
            return Vec::new();
        }
        let mut out = Vec::new();
        for d in declarators {
            let Some(ty) = self.declarator_type(&base, &d.array, d.pos) else { continue };
            if let Some(s) = self.declare_variable(q, ty, d, global) {
                out.push(s);
            }
        }
        out
    }

    fn qualifiers_allowed(&mut self, q: ast::Qualifiers, global: bool, base: &Type, pos: Pos) -> bool {
        if let Some(s) = q.storage {
            if !global && s != Storage::Const {
                self.error(pos, format!("`{}' variables may only be declared at global scope", storage_name(s)));
                return false;
            }
            if s == Storage::Attribute && self.stage == Stage::Fragment {
                self.error(pos, "`attribute' variables may not be declared in a fragment shader");
                return false;
            }
        }
        if q.centroid && q.storage != Some(Storage::Varying) {
            self.error(pos, "`centroid' may only qualify varying variables");
            return false;
        }
        if q.invariant && q.storage != Some(Storage::Varying) {
            self.error(pos, "`invariant' may only qualify varying variables");
            return false;
        }
        if *base == Type::Void {
            self.error(pos, "variables may not be of type `void'");
            return false;
        }
        true
    }

    fn declare_variable(&mut self, q: ast::Qualifiers, ty: Type, d: &ast::Declarator, global: bool) -> R<Stmt> {
        let pos = d.pos;
        let name = &d.name;
        let storage = q.storage;
        // Redeclaring a built-in: only gl_TexCoord, with a size (and its own qualifier).
        if name.starts_with("gl_") {
            if name == "gl_TexCoord" && global && storage == Some(Storage::Varying) {
                if let (Type::Array(e, Some(n)), Some((_, Symbol::Var(id)))) = (&ty, self.lookup(name)) {
                    if **e != Type::Vector(Scalar::Float, 4) {
                        self.error(pos, format!("`gl_TexCoord' redeclared as `{ty}', not an array of vec4"));
                        return None;
                    }
                    if self.vars[id].max_index.is_some_and(|m| m >= *n) || *n as i32 > self.limits.max_texture_coords {
                        self.error(
                            pos,
                            format!("`gl_TexCoord' redeclared with size {n}, too small or above gl_MaxTextureCoords"),
                        );
                        return None;
                    }
                    self.vars[id].ty = ty;
                    return None;
                }
            }
            self.check_name(name, pos);
            return None;
        }
        self.check_name(name, pos);
        match storage {
            Some(Storage::Attribute)
                if !matches!(ty, Type::Scalar(Scalar::Float) | Type::Vector(Scalar::Float, _) | Type::Matrix(..)) =>
            {
                self.error(pos, format!("vertex shader input / attribute cannot have type `{ty}'"));
                return None;
            }
            Some(Storage::Varying) if !ty.is_float_based() => {
                self.error(
                    pos,
                    format!("varying variables must be of type float, vec, mat or arrays of these, not `{ty}'"),
                );
                return None;
            }
            _ => {}
        }
        if ty.contains_sampler() && storage != Some(Storage::Uniform) {
            self.error(pos, format!("sampler variable `{name}' must be declared uniform"));
            return None;
        }
        let mut failed = false;
        let mut init_constant = false;
        let init = match &d.initializer {
            None => None,
            Some(e) => {
                if matches!(storage, Some(Storage::Attribute | Storage::Varying)) {
                    self.error(
                        pos,
                        format!("cannot initialize {} variable `{name}'", storage_name(storage.expect("storage"))),
                    );
                    failed = true;
                }
                if storage == Some(Storage::Uniform) && self.version < 120 {
                    self.error(pos, "uniform initializers require GLSL 1.20");
                    failed = true;
                }
                let (e, constant) = self.constant_expr(e);
                failed |= e.is_none();
                init_constant = constant;
                e
            }
        };
        // An unsized array takes its initializer's size (1.20).
        let ty = match (&ty, &init) {
            (Type::Array(e, None), Some(i)) => match &i.ty {
                Type::Array(ie, Some(n)) if ie == e => Type::Array(e.clone(), Some(*n)),
                _ => ty,
            },
            _ => ty,
        };
        let init = match init {
            None => None,
            Some(i) => match self.convert(i, &ty) {
                Ok(i) => Some(i),
                Err(i) => {
                    self.error(
                        pos,
                        format!("initializer of type `{}' cannot be assigned to variable of type `{ty}'", i.ty),
                    );
                    failed = true;
                    None
                }
            },
        };
        // An unsized array redeclared with a size in the same scope.
        if let Some(Symbol::Var(id)) = self.scopes.last().and_then(|s| s.get(name.as_str())).cloned() {
            let old = &self.vars[id];
            if let (Type::Array(oe, None), Type::Array(ne, Some(n))) = (&old.ty, &ty) {
                if oe == ne && old.storage == storage && storage != Some(Storage::Const) {
                    if let Some(m) = old.max_index.filter(|m| m >= n) {
                        self.error(pos, format!("array `{name}' redeclared with size {n}, but accessed at index {m}"));
                        return None;
                    }
                    self.vars[id].ty = ty;
                    return init.map(|i| Stmt::Declare(id, Some(i)));
                }
            }
        }
        let mut constant = None;
        if storage == Some(Storage::Const) && !failed {
            match &init {
                None => {
                    self.error(pos, format!("const declaration of `{name}' must be initialized"));
                }
                Some(i) => match i.constant().filter(|_| init_constant) {
                    Some(c) => constant = Some(c.clone()),
                    None => {
                        self.error(
                            pos,
                            format!("initializer of const variable `{name}' must be a constant expression"),
                        );
                    }
                },
            }
        }
        if storage == Some(Storage::Uniform) && init.as_ref().is_some_and(|i| i.constant().is_none()) {
            self.error(pos, format!("initializer of uniform variable `{name}' must be a constant expression"));
        }
        let read_only = match storage {
            Some(Storage::Const | Storage::Uniform | Storage::Attribute) => true,
            Some(Storage::Varying) => self.stage == Stage::Fragment,
            None => false,
        };
        let var = Variable {
            name: name.clone(),
            ty,
            kind: if global { VarKind::Global } else { VarKind::Local },
            storage,
            read_only,
            invariant: q.invariant,
            centroid: q.centroid,
            constant,
            max_index: None,
            implicit_size: false,
            written: false,
            used: false,
            pos,
        };
        let id = self.add_var(var)?;
        Some(Stmt::Declare(id, init))
    }

    // ------------------------------------------------------------ functions

    fn parameter(&mut self, p: &ast::Parameter, define: bool) -> R<(Type, ParameterDirection, Option<String>)> {
        let direction = p.direction.unwrap_or(ParameterDirection::In);
        if p.is_const && direction != ParameterDirection::In {
            self.error(p.pos, format!("const parameter cannot be `{}'", direction_name(direction)));
            return None;
        }
        let base = self.type_specifier(&p.ty)?;
        let ty = self.declarator_type(&base, &p.array, p.pos)?;
        if ty == Type::Void {
            if p.name.is_some() {
                self.error(p.pos, "parameter of type `void'");
                return None;
            }
            return Some((ty, direction, None));
        }
        if matches!(ty, Type::Array(_, None)) {
            self.error(p.pos, "function parameters must be sized arrays");
            return None;
        }
        if ty.is_array() && direction != ParameterDirection::In && self.version < 120 {
            self.error(p.pos, format!("`{}' array parameters require GLSL 1.20", direction_name(direction)));
            return None;
        }
        if ty.contains_sampler() && direction != ParameterDirection::In {
            self.error(p.pos, format!("sampler parameters cannot be `{}'", direction_name(direction)));
            return None;
        }
        if let Some(n) = &p.name {
            if define || n.starts_with("gl_") {
                self.check_name(n, p.pos);
            }
        }
        Some((ty, direction, p.name.clone()))
    }

    /// Declares (or finds) the function a prototype names; `define` when a body follows.
    /// Returns the function and its parameters' types, directions and names.
    fn function_prototype(&mut self, p: &ast::FunctionPrototype, define: bool) -> R<(FunctionId, Vec<ParamDecl>)> {
        let q = p.return_type.qualifiers;
        if q.storage.is_some() || q.invariant || q.centroid {
            self.error(p.pos, format!("function `{}' return type has qualifiers", p.name));
            return None;
        }
        let ret = self.type_specifier(&p.return_type.specifier)?;
        if matches!(ret, Type::Array(_, None)) {
            self.error(p.pos, format!("function `{}' return type array must be sized", p.name));
            return None;
        }
        if ret.contains_sampler() {
            self.error(p.pos, format!("function `{}' return type can't contain a sampler", p.name));
            return None;
        }
        let mut params = Vec::new();
        for par in &p.parameters {
            let (ty, dir, name) = self.parameter(par, define)?;
            params.push((ty, dir, name, par.is_const));
        }
        if params.len() == 1 && params[0].0 == Type::Void {
            params.clear();
        } else if params.iter().any(|p| p.0 == Type::Void) {
            self.error(p.pos, "`void' parameter must be the only parameter");
            return None;
        }
        if p.name.starts_with("gl_") {
            self.check_name(&p.name, p.pos);
            return None;
        }
        if p.name == "main" {
            if ret != Type::Void {
                self.error(p.pos, "main() must return void");
                return None;
            }
            if !params.is_empty() {
                self.error(p.pos, "main() must not take any parameters");
                return None;
            }
        }
        if let Some((_, Symbol::Var(_) | Symbol::Struct(_))) = self.scopes[1].get(&p.name).map(|s| (1, s.clone())) {
            self.error(p.pos, format!("function name `{}' conflicts with a variable or type", p.name));
            return None;
        }
        // A known signature: the same parameter types.
        let existing = self.function_names.get(&p.name).cloned().unwrap_or_default();
        for f in existing {
            let same = self.functions[f].parameters.len() == params.len()
                && self.functions[f].parameters.iter().zip(&params).all(|(a, b)| self.vars[a.var].ty == b.0);
            if !same {
                continue;
            }
            if self.functions[f].return_type != ret {
                self.error(p.pos, format!("function `{}' return type doesn't match prototype", p.name));
                return None;
            }
            if self.functions[f].parameters.iter().zip(&params).any(|(a, b)| a.direction != b.1) {
                self.error(p.pos, format!("function `{}' parameter qualifiers don't match prototype", p.name));
                return None;
            }
            if define && self.functions[f].body.is_some() {
                self.error(p.pos, format!("function `{}' redefined", p.name));
                return None;
            }
            return Some((f, params));
        }
        if self.version < 120 && matches!(ret, Type::Array(..)) {
            self.error(p.pos, "functions returning arrays require GLSL 1.20");
            return None;
        }
        // The parameters as variables (the definition's names replace a prototype's).
        let mut hparams = Vec::new();
        for (ty, dir, name, is_const) in &params {
            let id = self.vars.len();
            self.vars.push(Variable {
                name: name.clone().unwrap_or_default(),
                ty: ty.clone(),
                kind: VarKind::Parameter(*dir),
                storage: if *is_const { Some(Storage::Const) } else { None },
                read_only: *is_const,
                invariant: false,
                centroid: false,
                constant: None,
                max_index: None,
                implicit_size: false,
                written: false,
                used: false,
                pos: p.pos,
            });
            hparams.push(Parameter { var: id, direction: *dir });
        }
        let f = self.functions.len();
        self.functions.push(Function {
            name: p.name.clone(),
            return_type: ret,
            parameters: hparams,
            body: None,
            pos: p.pos,
        });
        self.function_names.entry(p.name.clone()).or_default().push(f);
        Some((f, params))
    }

    fn function_definition(&mut self, def: &ast::FunctionDefinition) {
        let Some((f, params)) = self.function_prototype(&def.prototype, true) else { return };
        // The parameters and the body's outermost statements share one scope.
        self.scopes.push(HashMap::new());
        let mut param_vars = Vec::new();
        for (i, (ty, dir, name, is_const)) in params.into_iter().enumerate() {
            let var = Variable {
                name: name.clone().unwrap_or_default(),
                ty,
                kind: VarKind::Parameter(dir),
                storage: if is_const { Some(Storage::Const) } else { None },
                read_only: is_const,
                invariant: false,
                centroid: false,
                constant: None,
                max_index: None,
                implicit_size: false,
                written: false,
                used: false,
                pos: def.prototype.parameters[i].pos,
            };
            let id = if name.is_some() {
                match self.add_var(var) {
                    Some(id) => id,
                    None => continue,
                }
            } else {
                self.vars.push(var);
                self.vars.len() - 1
            };
            param_vars.push(Parameter { var: id, direction: dir });
        }
        if param_vars.len() == self.functions[f].parameters.len() {
            self.functions[f].parameters = param_vars;
        }
        self.return_type = Some(self.functions[f].return_type.clone());
        self.function_name = def.prototype.name.clone();
        let body = self.statements(&def.body);
        self.return_type = None;
        self.scopes.pop();
        self.functions[f].body = Some(body);
    }

    // ------------------------------------------------------------ statements

    fn statements(&mut self, list: &[ast::Statement]) -> Vec<Stmt> {
        let mut out = Vec::with_capacity(list.len());
        for s in list {
            self.statement_into(s, &mut out);
        }
        out
    }

    fn statement_into(&mut self, s: &ast::Statement, out: &mut Vec<Stmt>) {
        if let ast::StatementKind::Declaration(d) = &s.kind {
            out.extend(self.declaration(d, false));
        } else if let Some(s) = self.statement(s) {
            out.push(s);
        }
    }

    /// A statement that is its own scope when it is a compound one.
    fn scoped(&mut self, s: &ast::Statement) -> Stmt {
        self.scopes.push(HashMap::new());
        let mut out = Vec::new();
        self.statement_into(s, &mut out);
        self.scopes.pop();
        if out.len() == 1 {
            out.pop().expect("one")
        } else {
            Stmt::Block(out)
        }
    }

    fn bool_condition(&mut self, e: &ast::Expr, what: &str) -> R<Expr> {
        let c = self.expr(e)?;
        if c.ty != BOOL {
            self.error(c.pos, format!("{what} condition must be scalar boolean"));
            return None;
        }
        Some(c)
    }

    fn condition(&mut self, c: &ast::Condition, what: &str) -> (R<Expr>, Option<VarId>) {
        match c {
            ast::Condition::Expr(e) => (self.bool_condition(e, what), None),
            ast::Condition::Declaration { ty, name, initializer, pos } => {
                let Some(t) = self.type_specifier(&ty.specifier) else { return (None, None) };
                if t != BOOL {
                    self.error(*pos, format!("{what} condition must be scalar boolean"));
                    return (None, None);
                }
                let Some(init) = self.expr(initializer) else { return (None, None) };
                if init.ty != BOOL {
                    self.error(init.pos, format!("{what} condition must be scalar boolean"));
                    return (None, None);
                }
                let var = Variable {
                    name: name.clone(),
                    ty: BOOL,
                    kind: VarKind::Local,
                    storage: None,
                    read_only: false,
                    invariant: false,
                    centroid: false,
                    constant: None,
                    max_index: None,
                    implicit_size: false,
                    written: false,
                    used: false,
                    pos: *pos,
                };
                let id = self.add_var(var);
                (Some(init), id)
            }
        }
    }

    fn statement(&mut self, s: &ast::Statement) -> Option<Stmt> {
        if self.depth >= MAX_DEPTH {
            self.error(s.pos, format!("statement nesting deeper than {MAX_DEPTH} levels"));
            return None;
        }
        self.depth += 1;
        let r = self.statement_inner(s);
        self.depth -= 1;
        r
    }

    fn statement_inner(&mut self, s: &ast::Statement) -> Option<Stmt> {
        use ast::StatementKind as K;
        let pos = s.pos;
        match &s.kind {
            K::Compound(list) => {
                self.scopes.push(HashMap::new());
                let body = self.statements(list);
                self.scopes.pop();
                Some(Stmt::Block(body))
            }
            K::Declaration(d) => Some(Stmt::Block(self.declaration(d, false))),
            K::Expr(None) => None,
            K::Expr(Some(e)) => Some(Stmt::Expr(self.expr(e)?)),
            K::If { condition, then, otherwise } => {
                let c = self.bool_condition(condition, "if-statement");
                let then = self.scoped(then);
                let otherwise = otherwise.as_ref().map(|o| Box::new(self.scoped(o)));
                Some(Stmt::If { condition: c?, then: Box::new(then), otherwise })
            }
            K::For { init, condition, step, body } => {
                self.scopes.push(HashMap::new());
                let mut init_out = Vec::new();
                self.statement_into(init, &mut init_out);
                let (c, cv) = match condition {
                    Some(c) => {
                        let (c, v) = self.condition(c, "loop");
                        (c.map(Some), v)
                    }
                    None => (Some(None), None),
                };
                let step = step.as_ref().map(|e| self.expr(e));
                self.loops += 1;
                let body = self.scoped(body);
                self.loops -= 1;
                self.scopes.pop();
                let step = match step {
                    Some(s) => Some(s?),
                    None => None,
                };
                Some(Stmt::Loop {
                    init: init_out,
                    condition: c?,
                    condition_var: cv,
                    step,
                    body: Box::new(body),
                    test_first: true,
                })
            }
            K::While { condition, body } => {
                self.scopes.push(HashMap::new());
                let (c, cv) = self.condition(condition, "loop");
                self.loops += 1;
                let body = self.scoped(body);
                self.loops -= 1;
                self.scopes.pop();
                Some(Stmt::Loop {
                    init: Vec::new(),
                    condition: Some(c?),
                    condition_var: cv,
                    step: None,
                    body: Box::new(body),
                    test_first: true,
                })
            }
            K::DoWhile { body, condition } => {
                self.loops += 1;
                let body = self.scoped(body);
                self.loops -= 1;
                let c = self.bool_condition(condition, "loop")?;
                Some(Stmt::Loop {
                    init: Vec::new(),
                    condition: Some(c),
                    condition_var: None,
                    step: None,
                    body: Box::new(body),
                    test_first: false,
                })
            }
            K::Break | K::Continue => {
                let word = if matches!(s.kind, K::Break) { "break" } else { "continue" };
                if self.loops == 0 {
                    self.error(pos, format!("{word} may only appear in a loop"));
                    return None;
                }
                Some(if word == "break" { Stmt::Break } else { Stmt::Continue })
            }
            K::Return(value) => {
                let ret = self.return_type.clone().unwrap_or(Type::Void);
                let fname = self.function_name.clone();
                match value {
                    None => {
                        if ret != Type::Void {
                            self.error(pos, format!("`return' with no value, in function {fname} returning non-void"));
                            return None;
                        }
                        Some(Stmt::Return(None))
                    }
                    Some(e) => {
                        let e = self.expr(e)?;
                        if ret == Type::Void {
                            self.error(pos, format!("`return` with a value, in function {fname} returning void"));
                            return None;
                        }
                        match self.convert(e, &ret) {
                            Ok(e) => Some(Stmt::Return(Some(e))),
                            Err(e) => {
                                self.error(
                                    pos,
                                    format!("`return' with wrong type {}, in function `{fname}' returning {ret}", e.ty),
                                );
                                None
                            }
                        }
                    }
                }
            }
            K::Discard => {
                if self.stage != Stage::Fragment {
                    self.error(pos, "discard may only appear in a fragment shader");
                    return None;
                }
                Some(Stmt::Discard)
            }
        }
    }

    // ------------------------------------------------------------ whole-shader rules

    fn finish(&mut self) {
        // Unsized arrays take the size of their largest constant index.
        for v in &mut self.vars {
            if let Type::Array(e, None) = &v.ty {
                if let Some(m) = v.max_index {
                    v.ty = Type::Array(e.clone(), Some(m + 1));
                    v.implicit_size = true;
                }
            }
        }
        if self.stage == Stage::Fragment {
            let written = |c: &Checker, name: &str| {
                c.vars.iter().any(|v| v.kind == VarKind::Builtin && v.name == name && v.written)
            };
            if written(self, "gl_FragColor") && written(self, "gl_FragData") {
                self.error(Pos::new(0, 0, 0), "fragment shader writes to both `gl_FragColor' and `gl_FragData'");
            }
        }
        let _ = self.in_function();
    }
}
