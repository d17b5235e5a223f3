//! Linking: the checked shaders attached to a program ([`super::hir::Checked`], several per
//! stage allowed) → one program interface, or a link error worded like Mesa's.
//!
//! What linking checks, per stage: exactly one `main`; every function called from code
//! reachable from `main` defined in some shader of the stage, once; no static recursion;
//! globals of one name declared with one type in every shader (uniforms across both
//! stages); varyings the fragment shader reads declared by the vertex shader with the same
//! type and written by it; the limits on vertex inputs (16 slots, `gl_Vertex` taking
//! generic 0), uniform components and varying components. A program with one stage is
//! allowed: fixed-function processing supplies the other (compatibility profile).
//!
//! What it makes, a [`Linked`] program interface: the active uniforms as GL reflection
//! lists them (one entry per basic-type leaf: `s.m`, `a[0]` with its array size, `s[1].c`,
//! and the built-in state uniforms the shaders use, with no location), their locations
//! (one per array element) and the layout of their values in one word array (column-major
//! matrices, one word per component: `f32` bits, `i32`, bools 0/1, sampler units), and the
//! active attributes with their locations (glBindAttribLocation's bindings, then Mesa's
//! automatic assignment: larger attributes first, each at the lowest free slots).
//!
//! "Active" is "used by code reachable from `main`". Mesa's optimiser also drops uses whose
//! results are dead (a value stored and overwritten); tessera does not, so such a uniform
//! is active here and not on Mesa. Like Mesa, a top-level array indexed only by constants
//! is active up to its largest index (`gl_LightSource[1]` lists entries 0 and 1).
use super::ast::Storage;
use super::builtins::Limits;
use super::hir::{
    BinaryOp, Checked, Constant, Expr, ExprKind, FunctionId, Scalar, Stage, Stmt, Type, Value, VarId, VarKind,
};
use super::lex::Sampler;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;
use std::sync::Arc;

/// Generic vertex attribute slots (GL_MAX_VERTEX_ATTRIBS).
pub const MAX_VERTEX_ATTRIBS: u32 = Limits::TESSERA.max_vertex_attribs as u32;
/// Uniform components of the vertex and of the fragment stage
/// (GL_MAX_{VERTEX,FRAGMENT}_UNIFORM_COMPONENTS, llvmpipe's values).
pub const MAX_VERTEX_UNIFORM_COMPONENTS: usize = Limits::TESSERA.max_vertex_uniform_components as usize;
pub const MAX_FRAGMENT_UNIFORM_COMPONENTS: usize = Limits::TESSERA.max_fragment_uniform_components as usize;
/// Varying components the fragment shader may read (GL_MAX_VARYING_FLOATS): what the vertex
/// record's slots carry ([`super::varyings`]).
pub const MAX_VARYING_FLOATS: usize = super::varyings::MAX_VARYING_FLOATS;

/// One active uniform as glGetActiveUniform lists it: a scalar, vector, matrix or sampler,
/// or an array of one.
#[derive(Clone, Debug)]
pub struct ActiveUniform {
    /// The listed name: `a[0]` for an array, `s[1].c` for a struct member.
    pub name: String,
    /// The element's type (never an array or struct).
    pub ty: Type,
    /// Array elements (1 for a non-array).
    pub size: u32,
    pub is_array: bool,
    /// The first element's location; `None` for built-in state (`gl_...`).
    pub location: Option<u32>,
    /// The first element's first word in the value array.
    pub offset: usize,
}

impl ActiveUniform {
    /// The name without the `[0]` an array's entry ends with.
    pub fn base_name(&self) -> &str {
        if self.is_array {
            &self.name[..self.name.len() - 3]
        } else {
            &self.name
        }
    }

    /// Words per element.
    pub fn words(&self) -> usize {
        element_words(&self.ty)
    }

    /// The GL type enum (GL_FLOAT_VEC4, GL_SAMPLER_2D...).
    pub fn gl_type(&self) -> GLenum {
        gl_type(&self.ty)
    }
}

/// One active attribute as glGetActiveAttrib lists it.
#[derive(Clone, Debug)]
pub struct ActiveAttribute {
    pub name: String,
    pub ty: Type,
    /// The first generic slot; `None` for a built-in (`gl_Vertex`...).
    pub location: Option<u32>,
}

impl ActiveAttribute {
    pub fn gl_type(&self) -> GLenum {
        gl_type(&self.ty)
    }
}

/// A linked program's interface.
#[derive(Clone, Debug, Default)]
pub struct Linked {
    /// The stages the program replaces.
    pub vertex: bool,
    pub fragment: bool,
    pub uniforms: Vec<ActiveUniform>,
    /// Location → (index into `uniforms`, array element).
    pub locations: Vec<(usize, u32)>,
    /// The uniform values as the link leaves them: zeros, or GLSL 1.20 initializers.
    pub initial_values: Vec<u32>,
    pub attributes: Vec<ActiveAttribute>,
    /// The linked shaders, in attach order.
    pub shaders: Vec<Arc<Checked>>,
}

impl Linked {
    /// The location of a uniform element named as glGetUniformLocation takes it: a leaf's
    /// name, with or without a final `[i]` (`a`, `a[2]`, `s[1].c`, `x[0]` for a non-array).
    /// `gl_` names and anything else are `None`.
    pub fn uniform_location(&self, name: &str) -> Option<u32> {
        if name.starts_with("gl_") {
            return None;
        }
        let (base, index) = split_subscript(name)?;
        self.uniforms.iter().find(|u| u.location.is_some() && u.base_name() == base).and_then(|u| {
            let index = index.unwrap_or(0);
            (index < u.size).then(|| u.location.unwrap_or(0) + index)
        })
    }

    /// The uniform element at `location`: its entry and the first word of its value.
    pub fn at_location(&self, location: u32) -> Option<(&ActiveUniform, usize)> {
        let &(index, element) = self.locations.get(location as usize)?;
        let u = &self.uniforms[index];
        Some((u, u.offset + element as usize * u.words()))
    }

    /// The words of a uniform element by its GL name (`v[3]`, `s[1].c`, `m`): its entry and
    /// first word. Built-in state has no words here.
    pub fn element(&self, name: &str) -> Option<(&ActiveUniform, usize)> {
        self.at_location(self.uniform_location(name)?)
    }

    /// The location of an active attribute (`None` for built-ins and inactive names).
    pub fn attribute_location(&self, name: &str) -> Option<u32> {
        self.attributes.iter().find(|a| a.name == name).and_then(|a| a.location)
    }
}

/// `a[12]` → (`a`, Some(12)); `s[1].c` → (`s[1].c`, None); malformed final subscripts
/// (`a[01]`, `a[ 1]`, `a[-1]`) → None. (Other malformed names match no leaf.)
fn split_subscript(name: &str) -> Option<(&str, Option<u32>)> {
    let Some(inner) = name.strip_suffix(']') else {
        return (!name.is_empty()).then_some((name, None));
    };
    let open = inner.rfind('[')?;
    let digits = &inner[open + 1..];
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) || (digits.len() > 1 && digits.starts_with('0'))
    {
        return None;
    }
    Some((&inner[..open], Some(digits.parse().ok()?)))
}

/// Words of one element of a leaf type (a sampler holds its unit).
fn element_words(ty: &Type) -> usize {
    match ty {
        Type::Sampler(_) => 1,
        t => t.components(),
    }
}

/// GL's type enum of a scalar, vector, matrix or sampler type.
pub fn gl_type(ty: &Type) -> GLenum {
    match ty {
        Type::Scalar(Scalar::Float) => GL_FLOAT,
        Type::Scalar(Scalar::Int) => GL_INT,
        Type::Scalar(Scalar::Bool) => GL_BOOL,
        Type::Vector(s, n) => {
            let first = match s {
                Scalar::Float => GL_FLOAT_VEC2,
                Scalar::Int => GL_INT_VEC2,
                Scalar::Bool => GL_BOOL_VEC2,
            };
            first + (*n as GLenum - 2)
        }
        Type::Matrix(c, r) => match (c, r) {
            (2, 2) => GL_FLOAT_MAT2,
            (3, 3) => GL_FLOAT_MAT3,
            (4, 4) => GL_FLOAT_MAT4,
            (2, 3) => GL_FLOAT_MAT2x3,
            (2, 4) => GL_FLOAT_MAT2x4,
            (3, 2) => GL_FLOAT_MAT3x2,
            (3, 4) => GL_FLOAT_MAT3x4,
            (4, 2) => GL_FLOAT_MAT4x2,
            _ => GL_FLOAT_MAT4x3,
        },
        Type::Sampler(s) => match s {
            Sampler::S1D => GL_SAMPLER_1D,
            Sampler::S2D => GL_SAMPLER_2D,
            Sampler::S3D => GL_SAMPLER_3D,
            Sampler::Cube => GL_SAMPLER_CUBE,
            Sampler::S1DShadow => GL_SAMPLER_1D_SHADOW,
            Sampler::S2DShadow => GL_SAMPLER_2D_SHADOW,
        },
        _ => 0,
    }
}

/// Whether two types of different shaders are the same (structs: same name and members).
fn same_type(a: &Type, b: &Type) -> bool {
    match (a, b) {
        (Type::Struct(x), Type::Struct(y)) => {
            x.name == y.name
                && x.members.len() == y.members.len()
                && x.members.iter().zip(&y.members).all(|((n, s), (m, t))| n == m && same_type(s, t))
        }
        (Type::Array(x, n), Type::Array(y, m)) => n == m && same_type(x, y),
        _ => a == b,
    }
}

/// The type of a global that two shaders declare, each as (type, whether an array size is
/// implicit: declared unsized and sized by the shader's largest constant index, or not
/// at all). Arrays agree when one size is implicit and no larger than the other (Mesa's
/// `validate_intrastage_arrays`): `float a[]` indexed up to 5 and `float a[6]` are
/// `float[6]`; two implicit sizes make the larger. `Err(Some((declared type, index)))`
/// for an index beyond the declared size, `Err(None)` for types that differ otherwise.
fn merged_type(
    (a, a_implicit): (&Type, bool),
    (b, b_implicit): (&Type, bool),
) -> Result<(Type, bool), Option<(Type, u32)>> {
    if same_type(a, b) {
        return Ok((a.clone(), a_implicit && b_implicit));
    }
    let (Type::Array(ea, na), Type::Array(eb, nb)) = (a, b) else { return Err(None) };
    if !same_type(ea, eb) || !(a_implicit || b_implicit) {
        return Err(None);
    }
    if a_implicit && b_implicit {
        return Ok((Type::Array(ea.clone(), (*na).max(*nb)), true));
    }
    let (sized, n, used) = if a_implicit { (b, nb, na) } else { (a, na, nb) };
    match (n, used) {
        (Some(n), Some(m)) if m > n => Err(Some((sized.clone(), m - 1))),
        _ => Ok((sized.clone(), false)),
    }
}

/// A variable of one shader: (shader index, variable).
type Var = (usize, VarId);
/// A function of one shader.
type Func = (usize, FunctionId);

/// How code reachable from `main` uses a variable.
#[derive(Clone, Copy, Debug, Default)]
struct Use {
    /// The largest constant index into it (top-level arrays).
    max_index: Option<u32>,
    /// Indexed by a non-constant, or used whole.
    whole: bool,
    written: bool,
}

/// The code of one stage reachable from its `main`.
struct Reach<'a> {
    shaders: &'a [Arc<Checked>],
    /// The stage's shaders (indices into `shaders`).
    stage_shaders: Vec<usize>,
    /// Definitions by signature.
    definitions: HashMap<String, Vec<Func>>,
    uses: HashMap<Var, Use>,
    /// Use order of variables (first use first).
    order: Vec<Var>,
    functions: HashSet<Func>,
    errors: Vec<String>,
    /// Whether the walk enters code a constant condition skips (see
    /// [`Expr::constant_bool`]): only the compile's recursion check does, as Mesa's.
    dead_code: bool,
}

fn signature(shader: &Checked, f: FunctionId) -> String {
    let function = &shader.functions[f];
    let params: Vec<String> = function.parameters.iter().map(|p| shader.variables[p.var].ty.to_string()).collect();
    format!("{} {}({})", function.return_type, function.name, params.join(", "))
}

impl<'a> Reach<'a> {
    fn new(shaders: &'a [Arc<Checked>], stage: Stage) -> Self {
        let stage_shaders: Vec<usize> = (0..shaders.len()).filter(|&i| shaders[i].stage == stage).collect();
        let mut definitions: HashMap<String, Vec<Func>> = HashMap::new();
        for &s in &stage_shaders {
            for (f, function) in shaders[s].functions.iter().enumerate() {
                if function.body.is_some() {
                    definitions.entry(signature(&shaders[s], f)).or_default().push((s, f));
                }
            }
        }
        Reach {
            shaders,
            stage_shaders,
            definitions,
            uses: HashMap::new(),
            order: Vec::new(),
            functions: HashSet::new(),
            errors: Vec::new(),
            dead_code: false,
        }
    }

    fn use_var(&mut self, v: Var) -> &mut Use {
        if !self.uses.contains_key(&v) {
            self.order.push(v);
        }
        self.uses.entry(v).or_default()
    }

    /// The definition a call of `f` in shader `s` reaches.
    fn resolve(&mut self, (s, f): Func) -> Option<Func> {
        let function = &self.shaders[s].functions[f];
        if function.body.is_some() {
            return Some((s, f));
        }
        let found = self.definitions.get(&signature(&self.shaders[s], f)).and_then(|d| d.first().copied());
        if found.is_none() {
            let message = format!("unresolved reference to function `{}'\n", function.name);
            if !self.errors.contains(&message) {
                self.errors.push(message);
            }
        }
        found
    }

    /// Walks `main` and everything it calls, recording uses and the functions on cycles of
    /// the call graph. The depth-first walk keeps its own stack rather than the machine's:
    /// a shader may chain thousands of functions, one calling the next, and the caller's
    /// thread may have a small stack.
    fn walk_from(&mut self, main: Func) {
        let mut done: HashSet<Func> = HashSet::new();
        // The functions on the current call path, with their position on it.
        let mut path: Vec<Func> = Vec::new();
        let mut on_path: HashMap<Func, usize> = HashMap::new();
        // Per function on the path: the calls its body makes, and the next one to follow.
        let mut pending: Vec<(Vec<FunctionId>, usize)> = Vec::new();
        let mut recursive: Vec<Func> = Vec::new();
        let mut next = Some(main);
        loop {
            if let Some(f) = next.take() {
                if let Some(&at) = on_path.get(&f) {
                    for &g in &path[at..] {
                        if !recursive.contains(&g) {
                            recursive.push(g);
                        }
                    }
                } else if !done.contains(&f) {
                    on_path.insert(f, path.len());
                    path.push(f);
                    self.functions.insert(f);
                    let shaders = self.shaders;
                    let mut calls = Vec::new();
                    if let Some(body) = &shaders[f.0].functions[f.1].body {
                        for stmt in body {
                            self.stmt(f.0, stmt, &mut calls);
                        }
                    }
                    pending.push((calls, 0));
                }
            }
            let Some((calls, index)) = pending.last_mut() else { break };
            let caller = *path.last().expect("a path entry per pending list");
            if let Some(&call) = calls.get(*index) {
                *index += 1;
                next = self.resolve((caller.0, call));
            } else {
                pending.pop();
                path.pop();
                on_path.remove(&caller);
                done.insert(caller);
            }
        }
        for f in recursive.iter().rev() {
            self.errors.push(format!("function `{}' has static recursion.\n", signature(&self.shaders[f.0], f.1)));
        }
    }

    fn stmt(&mut self, s: usize, stmt: &Stmt, calls: &mut Vec<FunctionId>) {
        match stmt {
            Stmt::Declare(v, init) => {
                self.use_var((s, *v));
                if let Some(e) = init {
                    self.expr(s, e, calls);
                }
            }
            Stmt::Expr(e) => self.expr(s, e, calls),
            Stmt::Block(b) => b.iter().for_each(|st| self.stmt(s, st, calls)),
            Stmt::If { condition, then, otherwise } => {
                let live = if self.dead_code { None } else { condition.constant_bool() };
                self.expr(s, condition, calls);
                if live != Some(false) {
                    self.stmt(s, then, calls);
                }
                if let Some(o) = otherwise.as_ref().filter(|_| live != Some(true)) {
                    self.stmt(s, o, calls);
                }
            }
            Stmt::Loop { init, condition, condition_var, step, body, .. } => {
                init.iter().for_each(|st| self.stmt(s, st, calls));
                if let Some(v) = condition_var {
                    self.use_var((s, *v));
                }
                for e in condition.iter().chain(step.iter()) {
                    self.expr(s, e, calls);
                }
                self.stmt(s, body, calls);
            }
            Stmt::Return(Some(e)) => self.expr(s, e, calls),
            Stmt::Return(None) | Stmt::Break | Stmt::Continue | Stmt::Discard => {}
        }
    }

    /// Marks the variable an assignment target designates as written.
    fn target(&mut self, s: usize, e: &Expr) {
        match &e.kind {
            ExprKind::Variable(v) => self.use_var((s, *v)).written = true,
            ExprKind::Index(b, _) | ExprKind::Field(b, _) | ExprKind::Swizzle(b, _) => self.target(s, b),
            _ => {}
        }
    }

    fn expr(&mut self, s: usize, e: &Expr, calls: &mut Vec<FunctionId>) {
        match &e.kind {
            ExprKind::Constant(_) => {}
            ExprKind::Variable(v) => self.use_var((s, *v)).whole = true,
            ExprKind::Index(base, index) => {
                if let ExprKind::Variable(v) = base.kind {
                    let constant = index.constant().and_then(|c| c.components().first().copied());
                    let u = self.use_var((s, v));
                    match constant {
                        Some(Value::I(i)) if i >= 0 => {
                            u.max_index = Some(u.max_index.map_or(i as u32, |m| m.max(i as u32)))
                        }
                        _ => u.whole = true,
                    }
                } else {
                    self.expr(s, base, calls);
                }
                self.expr(s, index, calls);
            }
            ExprKind::Unary(op, a) => {
                use super::hir::UnaryOp::*;
                if matches!(op, PreIncrement | PreDecrement | PostIncrement | PostDecrement) {
                    self.target(s, a);
                }
                self.expr(s, a, calls);
            }
            ExprKind::Assign(_, target, value) => {
                self.target(s, target);
                self.expr(s, target, calls);
                self.expr(s, value, calls);
            }
            ExprKind::Binary(op @ (BinaryOp::And | BinaryOp::Or), a, b) if !self.dead_code => {
                // `false && f()`: the second operand is dead code (as in the lowering).
                self.expr(s, a, calls);
                if a.constant_bool() != Some(*op == BinaryOp::Or) {
                    self.expr(s, b, calls);
                }
            }
            ExprKind::Binary(_, a, b) | ExprKind::Sequence(a, b) => {
                self.expr(s, a, calls);
                self.expr(s, b, calls);
            }
            ExprKind::Conditional(a, b, c) => {
                let live = if self.dead_code { None } else { a.constant_bool() };
                self.expr(s, a, calls);
                if live != Some(false) {
                    self.expr(s, b, calls);
                }
                if live != Some(true) {
                    self.expr(s, c, calls);
                }
            }
            ExprKind::Field(a, _) | ExprKind::Swizzle(a, _) | ExprKind::Convert(a) => self.expr(s, a, calls),
            ExprKind::Construct(args) => args.iter().for_each(|a| self.expr(s, a, calls)),
            ExprKind::Call(f, args) => {
                let function = &self.shaders[s].functions[*f];
                for (a, p) in args.iter().zip(&function.parameters) {
                    if p.direction != super::ast::ParameterDirection::In {
                        self.target(s, a);
                    }
                    self.expr(s, a, calls);
                }
                calls.push(*f);
            }
            ExprKind::Builtin(name, args) => {
                if *name == "ftransform" {
                    // ftransform() reads the vertex and the modelview-projection matrix.
                    for builtin in ["gl_Vertex", "gl_ModelViewProjectionMatrix"] {
                        if let Some(v) = self.shaders[s].variables.iter().position(|v| v.name == builtin) {
                            self.use_var((s, v)).whole = true;
                        }
                    }
                }
                args.iter().for_each(|a| self.expr(s, a, calls));
            }
        }
    }
}

/// The signatures (`float f(float)`) of the functions of one shader that call themselves,
/// directly or not, in definition order: GLSL has no recursion, and Mesa refuses it when
/// compiling a shader (recursion through several shaders is a link error).
pub fn recursive_functions(shader: &Arc<Checked>) -> Vec<String> {
    let shaders = std::slice::from_ref(shader);
    let mut reach = Reach::new(shaders, shader.stage);
    reach.dead_code = true;
    let callees: Vec<Vec<FunctionId>> = shader
        .functions
        .iter()
        .map(|f| {
            let mut calls = Vec::new();
            for stmt in f.body.iter().flatten() {
                reach.stmt(0, stmt, &mut calls);
            }
            calls
        })
        .collect();
    let on_cycle = functions_on_cycles(&callees);
    (0..shader.functions.len()).filter(|&f| on_cycle[f]).map(|f| signature(shader, f)).collect()
}

/// Per function of a call graph (`callees[f]`: the functions `f` calls), whether it lies on
/// a cycle: it calls itself, or shares a strongly connected component with another
/// function. Tarjan's algorithm with its own stack, so linear in the graph and safe on
/// chains of any length.
fn functions_on_cycles(callees: &[Vec<FunctionId>]) -> Vec<bool> {
    const UNSEEN: usize = usize::MAX;
    let n = callees.len();
    let mut index = vec![UNSEEN; n];
    let mut low = vec![0; n];
    let mut on_stack = vec![false; n];
    let mut stack: Vec<FunctionId> = Vec::new();
    let mut on_cycle = vec![false; n];
    let mut counter = 0;
    for root in 0..n {
        if index[root] != UNSEEN {
            continue;
        }
        // The depth-first path: a function and the next of its callees to look at.
        let mut walk: Vec<(FunctionId, usize)> = vec![(root, 0)];
        index[root] = counter;
        low[root] = counter;
        counter += 1;
        stack.push(root);
        on_stack[root] = true;
        while let Some(&mut (f, ref mut next)) = walk.last_mut() {
            if let Some(&g) = callees[f].get(*next) {
                *next += 1;
                if g == f {
                    on_cycle[f] = true;
                } else if index[g] == UNSEEN {
                    index[g] = counter;
                    low[g] = counter;
                    counter += 1;
                    stack.push(g);
                    on_stack[g] = true;
                    walk.push((g, 0));
                } else if on_stack[g] {
                    low[f] = low[f].min(index[g]);
                }
                continue;
            }
            walk.pop();
            if let Some(&(caller, _)) = walk.last() {
                low[caller] = low[caller].min(low[f]);
            }
            if low[f] == index[f] {
                let mut component = Vec::new();
                loop {
                    let g = stack.pop().expect("the component's functions are on the stack");
                    on_stack[g] = false;
                    component.push(g);
                    if g == f {
                        break;
                    }
                }
                if component.len() > 1 {
                    component.iter().for_each(|&g| on_cycle[g] = true);
                }
            }
        }
    }
    on_cycle
}

/// One global of the program, merged over the shaders that declare it.
struct Global {
    name: String,
    ty: Type,
    builtin: bool,
    usage: Use,
    initializer: Option<Constant>,
}

/// Links `shaders` (each compiled; attach order) with glBindAttribLocation's `bindings`.
/// `Err` holds the info log.
pub fn link(shaders: &[Arc<Checked>], bindings: &[(String, u32)]) -> Result<Linked, String> {
    let mut log = String::new();
    let error = |log: &mut String, message: &str| {
        log.push_str("error: ");
        log.push_str(message);
    };
    let mut reaches = Vec::new();
    for stage in [Stage::Vertex, Stage::Fragment] {
        let mut reach = Reach::new(shaders, stage);
        if reach.stage_shaders.is_empty() {
            continue;
        }
        let mains: Vec<Func> = reach.definitions.get("void main()").cloned().unwrap_or_default();
        match mains.len() {
            0 => {
                let name = if stage == Stage::Vertex { "vertex" } else { "fragment" };
                error(&mut log, &format!("{name} shader lacks `main'\n"));
                return Err(log);
            }
            1 => {}
            _ => {
                error(&mut log, "function `main' is multiply defined\n");
                return Err(log);
            }
        }
        for (_, definitions) in reach.definitions.iter() {
            if definitions.len() > 1 {
                let (s, f) = definitions[0];
                error(&mut log, &format!("function `{}' is multiply defined\n", shaders[s].functions[f].name));
                return Err(log);
            }
        }
        reach.walk_from(mains[0]);
        // As Mesa, a prototype called by a function that main never reaches must be
        // defined too.
        // One walker for all of them (what it records is ignored): a new one per function
        // would index every definition again, quadratic in the number of functions.
        let mut ignored = Reach::new(shaders, stage);
        for &sh in &reach.stage_shaders.clone() {
            for f in 0..shaders[sh].functions.len() {
                if shaders[sh].functions[f].body.is_some() && !reach.functions.contains(&(sh, f)) {
                    let mut calls = Vec::new();
                    for stmt in shaders[sh].functions[f].body.iter().flatten() {
                        ignored.stmt(sh, stmt, &mut calls);
                    }
                    for call in calls {
                        reach.resolve((sh, call));
                    }
                }
            }
        }
        if !reach.errors.is_empty() {
            for e in &reach.errors {
                error(&mut log, e);
            }
            return Err(log);
        }
        reaches.push((stage, reach));
    }

    // Globals of one name agree in type: uniforms across the program, others per stage.
    // An array one shader declares without a size (sized by its largest constant index)
    // takes the size another declares, or the largest of the implicit sizes.
    let mut seen: HashMap<(bool, Option<Stage>, String), (Type, bool)> = HashMap::new();
    for shader in shaders {
        for &(v, _) in &shader.globals {
            let var = &shader.variables[v];
            if var.kind != VarKind::Global || var.storage == Some(Storage::Const) {
                continue;
            }
            let uniform = var.storage == Some(Storage::Uniform);
            let key = (uniform, (!uniform).then_some(shader.stage), var.name.clone());
            let implicit = var.implicit_size || matches!(var.ty, Type::Array(_, None));
            let Some((ty, seen_implicit)) = seen.get_mut(&key) else {
                seen.insert(key, (var.ty.clone(), implicit));
                continue;
            };
            let mode = match var.storage {
                Some(Storage::Uniform) => "uniform",
                Some(Storage::Varying) if shader.stage == Stage::Vertex => "shader output",
                Some(Storage::Varying | Storage::Attribute) => "shader input",
                _ => "global variable",
            };
            match merged_type((ty, *seen_implicit), (&var.ty, implicit)) {
                Ok((merged, merged_implicit)) => (*ty, *seen_implicit) = (merged, merged_implicit),
                Err(Some((sized, index))) => {
                    error(
                        &mut log,
                        &format!(
                            "{mode} `{}' declared as type `{sized}' but outermost dimension has an index of `{index}'\n",
                            var.name
                        ),
                    );
                    return Err(log);
                }
                Err(None) => {
                    error(&mut log, &format!("{mode} `{}' declared as type `{}' and type `{ty}'\n", var.name, var.ty));
                    return Err(log);
                }
            }
        }
    }

    let reach_of = |stage: Stage| reaches.iter().find(|(s, _)| *s == stage).map(|(_, r)| r);
    // Varyings the fragment shader reads: declared and written by the vertex shader.
    if let (Some(vertex), Some(fragment)) = (reach_of(Stage::Vertex), reach_of(Stage::Fragment)) {
        let mut components = 0;
        for &(s, v) in &fragment.order {
            let var = &shaders[s].variables[v];
            if var.kind != VarKind::Global || var.storage != Some(Storage::Varying) {
                continue;
            }
            components += leaf_components(&var.ty);
            let declared = vertex.stage_shaders.iter().find_map(|&vs| {
                shaders[vs]
                    .variables
                    .iter()
                    .position(|o| {
                        o.kind == VarKind::Global && o.storage == Some(Storage::Varying) && o.name == var.name
                    })
                    .map(|o| (vs, o))
            });
            if let Some((vs, o)) = declared {
                let out = &shaders[vs].variables[o];
                if !same_type(&out.ty, &var.ty) {
                    error(
                        &mut log,
                        &format!(
                            "vertex shader output `{}' declared as type `{}', but fragment shader input declared as type `{}'\n",
                            var.name, out.ty, var.ty
                        ),
                    );
                    return Err(log);
                }
            }
            let written = vertex.order.iter().any(|&(vs, o)| {
                let out = &shaders[vs].variables[o];
                out.kind == VarKind::Global && out.name == var.name && vertex.uses[&(vs, o)].written
            });
            if !written {
                // Mesa reports it once per component, each followed by a lone ".".
                for _ in 0..leaf_components(&var.ty).max(1) {
                    error(&mut log, &format!("fragment shader varying {} not written by vertex shader\n.", var.name));
                }
            }
        }
        if !log.is_empty() {
            return Err(log);
        }
        if components > MAX_VARYING_FLOATS {
            error(
                &mut log,
                &format!("fragment shader uses too many input components ({components} > {MAX_VARYING_FLOATS})\n"),
            );
            return Err(log);
        }
    }

    // Active uniforms: per stage, the built-in state it uses, then its own in declaration
    // order; a uniform both stages use is listed once.
    let mut globals: Vec<Global> = Vec::new();
    for (stage, reach) in &reaches {
        let mut stage_components = 0;
        let mut builtins: Vec<Var> = Vec::new();
        let mut own: Vec<Var> = Vec::new();
        for &(s, v) in &reach.order {
            let var = &shaders[s].variables[v];
            if var.storage != Some(Storage::Uniform) {
                continue;
            }
            match var.kind {
                VarKind::Builtin => builtins.push((s, v)),
                VarKind::Global => own.push((s, v)),
                _ => {}
            }
        }
        // As Mesa, a uniform declared with an initializer is active even where no code
        // reads it (its value may matter to the other stage or to the application).
        for &s in &reach.stage_shaders {
            for (v, init) in &shaders[s].globals {
                let var = &shaders[s].variables[*v];
                if init.is_some() && var.storage == Some(Storage::Uniform) && !own.contains(&(s, *v)) {
                    own.push((s, *v));
                }
            }
        }
        // Declaration order for the shader's own uniforms.
        own.sort_by_key(|&(s, v)| (s, shaders[s].globals.iter().position(|g| g.0 == v)));
        builtins.sort();
        for (s, v) in builtins.into_iter().chain(own) {
            let var = &shaders[s].variables[v];
            let usage = reach.uses.get(&(s, v)).copied().unwrap_or(Use { whole: true, ..Use::default() });
            if var.kind == VarKind::Global {
                stage_components += leaf_components(&var.ty);
            }
            let initializer = shaders[s]
                .globals
                .iter()
                .find(|g| g.0 == v)
                .and_then(|g| g.1.as_ref())
                .and_then(|e| e.constant().cloned());
            if let Some(g) = globals.iter_mut().find(|g| g.name == var.name) {
                g.usage.whole |= usage.whole;
                g.usage.max_index = g.usage.max_index.max(usage.max_index);
                // The initializer may be in the other stage's declaration only.
                if g.initializer.is_none() {
                    g.initializer = initializer;
                }
                continue;
            }
            // The size of an array declared unsized may come from another declaration.
            let ty = seen.get(&(true, None, var.name.clone())).map_or(&var.ty, |(t, _)| t).clone();
            globals.push(Global {
                name: var.name.clone(),
                ty,
                builtin: var.kind == VarKind::Builtin,
                usage,
                initializer,
            });
        }
        let (name, budget) = match stage {
            Stage::Vertex => ("vertex", MAX_VERTEX_UNIFORM_COMPONENTS),
            Stage::Fragment => ("fragment", MAX_FRAGMENT_UNIFORM_COMPONENTS),
        };
        if stage_components > budget {
            error(&mut log, &format!("Too many {name} shader default uniform block components\n"));
            return Err(log);
        }
    }
    let mut linked = Linked {
        vertex: reach_of(Stage::Vertex).is_some(),
        fragment: reach_of(Stage::Fragment).is_some(),
        shaders: shaders.to_vec(),
        ..Linked::default()
    };
    for g in &globals {
        // A top-level array used only with constant indices is active up to the largest.
        let ty = match (&g.ty, g.usage.max_index) {
            (Type::Array(e, Some(n)), Some(max)) if !g.usage.whole => Type::Array(e.clone(), Some((max + 1).min(*n))),
            (t, _) => t.clone(),
        };
        let mut values = Vec::new();
        if let Some(c) = &g.initializer {
            flatten_constant(c, &mut values);
        }
        let mut taken = 0;
        add_leaves(&mut linked, g.name.clone(), &ty, g.builtin, &values, &mut taken);
    }

    linked.attributes = attributes(shaders, reach_of(Stage::Vertex), bindings, &mut log)?;
    Ok(linked)
}

/// Components of a varying or uniform (arrays: all elements; samplers: none).
fn leaf_components(ty: &Type) -> usize {
    match ty {
        Type::Array(e, n) => leaf_components(e) * n.unwrap_or(1) as usize,
        Type::Struct(s) => s.members.iter().map(|(_, t)| leaf_components(t)).sum(),
        t => t.components(),
    }
}

/// A constant's scalar components in leaf order.
fn flatten_constant(c: &Constant, out: &mut Vec<Value>) {
    match c {
        Constant::Basic(v) => out.extend_from_slice(v),
        Constant::Composite(parts) => parts.iter().for_each(|p| flatten_constant(p, out)),
    }
}

/// One word of a uniform value.
pub fn word(v: Value) -> u32 {
    match v {
        Value::F(f) => f.to_bits(),
        Value::I(i) => i as u32,
        Value::B(b) => b as u32,
    }
}

/// Adds the leaves of a uniform of type `ty` called `name`, with the initializer's
/// components `values` (consumed from `taken`).
fn add_leaves(linked: &mut Linked, name: String, ty: &Type, builtin: bool, values: &[Value], taken: &mut usize) {
    let (element, size, is_array) = match ty {
        Type::Array(e, n) if !matches!(**e, Type::Struct(_)) => ((**e).clone(), n.unwrap_or(1), true),
        Type::Array(e, n) => {
            for i in 0..n.unwrap_or(1) {
                add_leaves(linked, format!("{name}[{i}]"), e, builtin, values, taken);
            }
            return;
        }
        Type::Struct(s) => {
            for (member, t) in &s.members {
                add_leaves(linked, format!("{name}.{member}"), t, builtin, values, taken);
            }
            return;
        }
        t => (t.clone(), 1, false),
    };
    let words = element_words(&element) * size as usize;
    let location = (!builtin).then_some(linked.locations.len() as u32);
    let offset = linked.initial_values.len();
    let index = linked.uniforms.len();
    if !builtin {
        for e in 0..size {
            linked.locations.push((index, e));
        }
        for i in 0..words {
            let v = values.get(*taken + i).map_or(0, |&v| word(v));
            linked.initial_values.push(v);
        }
    }
    *taken += words;
    let name = if is_array { format!("{name}[0]") } else { name };
    linked.uniforms.push(ActiveUniform { name, ty: element, size, is_array, location, offset });
}

/// Generic slots of an attribute type (a matrix takes one per column).
fn slots(ty: &Type) -> u32 {
    match ty {
        Type::Matrix(c, _) => *c as u32,
        _ => 1,
    }
}

/// The active attributes and their locations.
fn attributes(
    shaders: &[Arc<Checked>],
    vertex: Option<&Reach>,
    bindings: &[(String, u32)],
    log: &mut String,
) -> Result<Vec<ActiveAttribute>, String> {
    let Some(vertex) = vertex else { return Ok(Vec::new()) };
    let mut builtins = Vec::new();
    let mut own: Vec<(usize, Var)> = Vec::new();
    for &(s, v) in &vertex.order {
        let var = &shaders[s].variables[v];
        if var.storage != Some(Storage::Attribute) {
            continue;
        }
        if var.kind == VarKind::Builtin {
            builtins.push((s, v));
        } else if !own.iter().any(|&(_, (os, ov))| shaders[os].variables[ov].name == var.name) {
            own.push((shaders[s].globals.iter().position(|g| g.0 == v).unwrap_or(0) + s * 1_000_000, (s, v)));
        }
    }
    builtins.sort();
    own.sort_by_key(|o| o.0);
    let mut list: Vec<ActiveAttribute> = Vec::new();
    let uses_vertex = builtins.iter().any(|&(s, v)| shaders[s].variables[v].name == "gl_Vertex");
    for (s, v) in builtins {
        let var = &shaders[s].variables[v];
        list.push(ActiveAttribute { name: var.name.clone(), ty: var.ty.clone(), location: None });
    }
    let first_own = list.len();
    for (_, (s, v)) in own {
        let var = &shaders[s].variables[v];
        list.push(ActiveAttribute { name: var.name.clone(), ty: var.ty.clone(), location: None });
    }
    // The count Mesa checks first leaves gl_Vertex out; taking generic 0 from the rest
    // fails later, as a placement.
    let needed: u32 = list[first_own..].iter().map(|a| slots(&a.ty)).sum::<u32>();
    if needed > MAX_VERTEX_ATTRIBS {
        log.push_str(&format!("error: too many vertex shader inputs (max {MAX_VERTEX_ATTRIBS})"));
        return Err(std::mem::take(log));
    }
    // Bound attributes first, then generic 0 for gl_Vertex, then the rest: most slots first.
    let mut used = [false; MAX_VERTEX_ATTRIBS as usize];
    if uses_vertex {
        used[0] = true;
    }
    for a in &mut list[first_own..] {
        if let Some(&(_, index)) = bindings.iter().rev().find(|(n, _)| *n == a.name) {
            let n = slots(&a.ty);
            if index + n > MAX_VERTEX_ATTRIBS {
                let _ = write!(
                    log,
                    "error: insufficient contiguous locations available for vertex shader input `{}'",
                    a.name
                );
                return Err(std::mem::take(log));
            }
            (index..index + n).for_each(|i| used[i as usize] = true);
            a.location = Some(index);
        }
    }
    let mut order: Vec<usize> = (first_own..list.len()).filter(|&i| list[i].location.is_none()).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(slots(&list[i].ty)));
    for i in order {
        let n = slots(&list[i].ty) as usize;
        let start = (0..=used.len() - n).find(|&st| used[st..st + n].iter().all(|u| !u));
        let Some(start) = start else {
            let _ = write!(
                log,
                "error: insufficient contiguous locations available for vertex shader input `{}'",
                list[i].name
            );
            return Err(std::mem::take(log));
        };
        used[start..start + n].iter_mut().for_each(|u| *u = true);
        list[i].location = Some(start as u32);
    }
    Ok(list)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glsl::{compile_shader, InfoLog, Options};

    fn compiled(stage: Stage, source: &str) -> Arc<Checked> {
        let mut log = InfoLog::default();
        let checked = compile_shader(source, stage, &Options::default(), &mut log);
        Arc::new(checked.unwrap_or_else(|| panic!("{}", log.text())))
    }

    fn vertex(source: &str) -> Arc<Checked> {
        compiled(Stage::Vertex, source)
    }

    fn fragment(source: &str) -> Arc<Checked> {
        compiled(Stage::Fragment, source)
    }

    #[test]
    fn uniform_leaves_locations_and_words() {
        let v = vertex(
            "#version 120\nstruct S { float a; vec3 b[2]; };\nuniform S s[2];\nuniform mat2x3 m;\n\
             uniform float unused;\nuniform vec2 init = vec2(3.0, 4.0);\n\
             void main() { gl_Position = vec4(s[1].b[1], s[0].a) + vec4(m[1], 1.0) + init.xyxy; }",
        );
        let linked = link(&[v], &[]).unwrap();
        let names: Vec<_> = linked.uniforms.iter().map(|u| (u.name.as_str(), u.size, u.location)).collect();
        assert_eq!(
            names,
            [
                ("s[0].a", 1, Some(0)),
                ("s[0].b[0]", 2, Some(1)),
                ("s[1].a", 1, Some(3)),
                ("s[1].b[0]", 2, Some(4)),
                ("m", 1, Some(6)),
                ("init", 1, Some(7)),
            ]
        );
        assert_eq!(linked.uniform_location("s[1].b"), Some(4));
        assert_eq!(linked.uniform_location("s[1].b[1]"), Some(5));
        assert_eq!(linked.uniform_location("s[1].b[2]"), None);
        assert_eq!(linked.uniform_location("m[0]"), Some(6), "[0] names a non-array too");
        assert_eq!(linked.uniform_location("s[1].b[01]"), None);
        assert_eq!(linked.uniform_location("unused"), None);
        // Words: 1 + 6 + 1 + 6 (the structs), 6 for the matrix, then the initializer.
        let (u, first) = linked.element("s[1].b[1]").unwrap();
        assert_eq!((u.gl_type(), first), (GL_FLOAT_VEC3, 7 + 1 + 3));
        let (_, first) = linked.element("init").unwrap();
        assert_eq!(&linked.initial_values[first..first + 2], &[3.0f32.to_bits(), 4.0f32.to_bits()]);
    }

    #[test]
    fn constant_indices_shrink_top_level_arrays_and_builtins_have_no_location() {
        let v = vertex(
            "uniform float a[8]; uniform float d[8];\n\
             void main() { gl_Position = vec4(a[2] + d[int(gl_Vertex.x)]) + gl_LightSource[1].diffuse; }",
        );
        let linked = link(&[v], &[]).unwrap();
        let find = |n: &str| linked.uniforms.iter().find(|u| u.name == n).unwrap();
        assert_eq!(find("a[0]").size, 3);
        assert_eq!(find("d[0]").size, 8);
        assert_eq!(find("gl_LightSource[1].diffuse").location, None);
        assert!(linked.uniforms.iter().all(|u| !u.name.starts_with("gl_LightSource[2]")));
        assert_eq!(linked.uniform_location("gl_LightSource[1].diffuse"), None);
    }

    #[test]
    fn attributes_bound_then_largest_first_with_gl_vertex_on_zero() {
        let v = vertex(
            "attribute vec4 a; attribute mat3 m; attribute vec2 b; attribute float unused;\n\
             void main() { gl_Position = gl_Vertex + a + vec4(m[0], b.x); }",
        );
        let linked = link(std::slice::from_ref(&v), &[]).unwrap();
        let at = |l: &Linked, n: &str| l.attribute_location(n);
        assert_eq!((at(&linked, "m"), at(&linked, "a"), at(&linked, "b")), (Some(1), Some(4), Some(5)));
        assert_eq!(at(&linked, "gl_Vertex"), None);
        assert_eq!(at(&linked, "unused"), None);
        let linked = link(&[v], &[("b".into(), 1), ("a".into(), 9)]).unwrap();
        assert_eq!((at(&linked, "m"), at(&linked, "a"), at(&linked, "b")), (Some(2), Some(9), Some(1)));
    }

    #[test]
    fn link_errors_are_worded_as_mesa_words_them() {
        let error = |shaders: &[Arc<Checked>]| link(shaders, &[]).unwrap_err();
        assert_eq!(error(&[vertex("void f() {}")]), "error: vertex shader lacks `main'\n");
        let main = "void main() { gl_Position = vec4(0.0); }";
        assert_eq!(error(&[vertex(main), vertex(main)]), "error: function `main' is multiply defined\n");
        assert_eq!(error(&[vertex("void f(); void main() { f(); }")]), "error: unresolved reference to function `f'\n");
        assert_eq!(
            error(&[
                vertex("uniform float u;\nvoid main() { gl_Position = vec4(u); }"),
                fragment("uniform int u; void main() { gl_FragColor = vec4(u); }")
            ]),
            "error: uniform `u' declared as type `int' and type `float'\n"
        );
        assert_eq!(
            error(&[
                vertex("void main() { gl_Position = vec4(0.0); }"),
                fragment("varying vec2 c; void main() { gl_FragColor = c.xyxy; }")
            ]),
            "error: fragment shader varying c not written by vertex shader\n.".repeat(2)
        );
        assert_eq!(
            error(&[vertex("void g(); void f() { g(); } void main() { f(); }"), vertex("void f(); void g() { f(); }")]),
            "error: function `void g()' has static recursion.\nerror: function `void f()' has static recursion.\n"
        );
        // Prototype resolved in another shader of the stage; a fragment shader alone links.
        assert!(link(
            &[vertex("void f(); void main() { f(); }"), vertex("void f() { gl_Position = vec4(1.0); }")],
            &[]
        )
        .is_ok());
        assert!(link(&[fragment("void main() { gl_FragColor = gl_Color; }")], &[]).is_ok());
    }

    /// GLSL 1.10 section 4.1.9: an array declared without a size takes the size another
    /// shader of the stage declares, if its own constant indices fit (piglit
    /// glsl-fs-implicit-array-size-01); two implicit sizes make the larger.
    #[test]
    fn an_unsized_array_links_with_a_sized_declaration_that_holds_its_indices() {
        let main = "float a[]; void f(); void main() { f(); gl_FragColor = vec4(a[1]); }";
        let ok = |other: &str| link(&[fragment(main), fragment(other)], &[]);
        assert!(ok("float a[]; void f() { a[5] = 0.0; }").is_ok());
        assert!(ok("float a[6]; void f() { a[5] = 0.0; }").is_ok());
        assert!(ok("float a[2]; void f() {}").is_ok());
        assert_eq!(
            ok("float a[1]; void f() {}").unwrap_err(),
            "error: global variable `a' declared as type `float[1]' but outermost dimension has an index of `1'\n"
        );
        assert_eq!(
            ok("int a[]; void f() { a[5] = 0; }").unwrap_err(),
            "error: global variable `a' declared as type `int[6]' and type `float[2]'\n"
        );
        // Two declared sizes must agree.
        let sized = |n: u32| fragment(&format!("float a[{n}]; void main() {{ gl_FragColor = vec4(a[0]); }}"));
        let other = fragment("float a[3]; void f() {}");
        assert!(link(&[sized(2), other], &[]).unwrap_err().contains("declared as type `float[3]' and type `float[2]'"));
        // The uniform of an unsized declaration is as large as the sized one.
        let u = link(
            &[
                fragment("uniform float u[]; void f(); void main() { f(); gl_FragColor = vec4(u[1]); }"),
                fragment("uniform float u[4]; void f() { gl_FragColor += vec4(u[3]); }"),
            ],
            &[],
        )
        .unwrap();
        assert_eq!(u.uniforms.iter().find(|x| x.name == "u[0]").map(|x| x.size), Some(4));
    }

    /// As Mesa's compiler, which drops code a constant condition skips before the link:
    /// a call there to a function defined nowhere links; the same call in live code, or
    /// behind a condition that is not constant, does not.
    #[test]
    fn calls_in_code_a_constant_condition_skips_need_no_definition() {
        let linked = |body: &str| {
            let f = fragment(&format!("#version 120\nvoid bad(); uniform float u;\nvoid main() {{ {body} }}"));
            link(&[f], &[])
        };
        for dead in [
            "if (false) bad(); gl_FragColor = vec4(1.0);",
            "if (sqrt(1.0) != 1.0) bad(); else if (exp2(1.0) == 2.0) gl_FragColor = vec4(u); else bad();",
            "gl_FragColor = vec4(true ? 1.0 : (bad(), 2.0));",
            "if (false && (bad(), true)) gl_FragColor = vec4(1.0);",
            "if (true || (bad(), true)) gl_FragColor = vec4(1.0);",
        ] {
            assert!(linked(dead).is_ok(), "{dead}");
        }
        for live in [
            "bad();",
            "if (u > 0.0) bad();",
            "if (true) bad();",
            "if (false) {} else bad();",
            "gl_FragColor = vec4(false ? 1.0 : (bad(), 2.0));",
            "if (true && (bad(), true)) gl_FragColor = vec4(1.0);",
        ] {
            assert_eq!(linked(live).unwrap_err(), "error: unresolved reference to function `bad'\n", "{live}");
        }
        // A uniform named only in dead code is not active (as Mesa).
        let l = linked("if (false) gl_FragColor = vec4(u); gl_FragColor = vec4(1.0);").unwrap();
        assert_eq!(l.uniform_location("u"), None);
    }

    #[test]
    fn recursion_within_one_shader_is_found_in_definition_order() {
        let v = vertex("float f(float x) { return f(x); } void h() {} void main() { h(); }");
        assert_eq!(recursive_functions(&v), ["float f(float)"]);
    }

    /// A chain of functions, each calling the one before: the walks keep their own stacks,
    /// so a long chain links on a thread with a small stack (the caller's thread may have
    /// one), and a cycle at the far end of the chain is still found.
    #[test]
    fn long_call_chains_link_on_a_small_stack() {
        const LENGTH: usize = 4000;
        let chain = |closing: &str| {
            let mut source = format!("float f0(float x) {{ {closing} }}\n");
            for i in 1..LENGTH {
                source += &format!("float f{i}(float x) {{ return f{}(x) + 1.0; }}\n", i - 1);
            }
            source + &format!("void main() {{ gl_FragColor = vec4(f{}(1.0)); }}\n", LENGTH - 1)
        };
        let plain = fragment(&chain("return x;"));
        let prototype = format!("float f{}(float x);\n", LENGTH - 1);
        let cyclic = fragment(&(prototype + &chain(&format!("return f{}(x);", LENGTH - 1))));
        let outcome = std::thread::Builder::new()
            .stack_size(64 * 1024)
            .spawn(move || {
                let linked = link(&[plain], &[]).is_ok();
                let recursive = recursive_functions(&cyclic).len();
                (linked, recursive)
            })
            .expect("thread")
            .join()
            .expect("no stack overflow");
        assert_eq!(outcome, (true, LENGTH));
    }
}
