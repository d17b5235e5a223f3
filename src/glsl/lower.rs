//! Lowering: the checked GLSL of one stage ([`super::hir`], one or more compilation units)
//! onto the shading IR of [`crate::shader::ir`], with the interface the draw path needs to
//! wire the program: what each uniform, input and output word is, by GL name, and which
//! sampler uniform each texture lookup reads.
//!
//! **Values.** Every GLSL value is a list of scalar registers, its *leaves*, in GLSL's
//! order: struct members in declaration order, array elements in index order, matrices
//! column by column. A sampler leaf is no register but a compile-time index into
//! [`Lowered::samplers`] (functions are inlined, so every lookup knows its sampler
//! statically), or, for an element of a sampler array chosen by a non-constant index (which
//! GLSL 1.10/1.20 do not allow and Mesa compiles), a tag naming the index register and the
//! candidates: the lookup then samples each candidate and selects per lane.
//!
//! **Variables.** Shader globals and built-ins are shared across the units of a stage by
//! name; locals and parameters belong to their unit. A variable's leaves get registers on
//! first use, so a uniform array of which one element is read costs one element's words.
//! Uniform and input words and every constant are read in a prologue at the top of the
//! program (in every lane), so that a register first named inside a branch holds its value
//! everywhere. Output variables are written by `Output` instructions in an epilogue, after
//! the body (main's `return` is lowered as a jump there, not as the IR's `Return`).
//!
//! **Interface.** "Used" means named by the program after inlining, except in code a
//! constant condition skips (`if (false)`, `true ? a : b`, `false && f()`), which is not
//! lowered at all, as Mesa's compiler drops it before the link. A uniform or input word is
//! listed when the program reads it (`gl_LightSource[0].diffuse.x` lists word 0 of
//! `gl_LightSource[0].diffuse` only); an
//! output *basic-type element* (`v[3]`, `s.c`, `gl_TexCoord[1]`) is listed, every word of
//! it, when the shader names any part of it. A dynamically indexed array counts as naming
//! all its elements. A listed output word that the shader never writes holds
//! 0.0 (registers start at zero): `gl_FragColor.rgb = c` lists `gl_FragColor` 0..4 and its
//! alpha is 0. Outputs the shader never names are not listed: the draw path decides what
//! they hold (GL leaves them undefined).
//!
//! **Samplers.** An IR lookup's `unit` is an index into [`Lowered::samplers`], the sampler
//! uniform elements by GL name in order of first use; at bind time the draw path reads each
//! one's uniform value (the texture image unit) and binds that unit's texture under the
//! index.
//!
//! **Control flow.** An inlined function whose `return` is not its last statement runs in a
//! one-iteration IR loop that its `return` breaks out of; a `return` inside the function's
//! own loops sets a flag, breaks, and each enclosing loop of the function breaks again when
//! the flag is set. A `for` loop's step runs at the top of every iteration after the first
//! (so that `continue` reaches it); a `do ... while` tests its condition there too.
//! `&&`, `||` and `?:` whose second operand has side effects are IR ifs; without side
//! effects they evaluate both operands and select. Dynamic indexing is a chain of selects
//! (reads) or of selected writes, over the array's elements; an index outside the array
//! reads element 0 and writes nothing (GLSL leaves it undefined).
//!
//! The arithmetic of each built-in function is in [`builtins`], with its formula.

mod builtins;
#[cfg(test)]
mod tests;

use super::ast::{ParameterDirection, Storage};
use super::hir::{self, Checked, Constant, Expr, ExprKind, Scalar, Type, Value, VarKind};
use super::lex::Sampler;
use crate::shader::ir::{self, BinaryOp as B, Const, Inst, Program, Reg, Stmt, UnaryOp as U};
use std::collections::HashMap;

/// One word of the interface: the GL name of the basic-type element it belongs to, as
/// `glGetUniformLocation` accepts it for that element (`m`, `v[3]`, `s[1].c`,
/// `gl_LightSource[0].diffuse`), and the word's index within the element (matrices
/// column-major).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Word {
    pub name: String,
    pub index: u32,
}

/// A sampler uniform element the program's lookups read (see the module docs).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SamplerUse {
    pub name: String,
    pub kind: Sampler,
}

/// A lowered stage: its program and what its slots hold.
#[derive(Clone, Debug)]
pub struct Lowered {
    pub program: Program,
    /// Per uniform slot.
    pub uniforms: Vec<Word>,
    /// Per input slot.
    pub inputs: Vec<Word>,
    /// Per output slot.
    pub outputs: Vec<Word>,
    /// The lookups' `unit` indexes this list.
    pub samplers: Vec<SamplerUse>,
}

/// The register index that tags a sampler leaf (`SAMPLER_TAG + index into samplers`).
const SAMPLER_TAG: u32 = 0xffff_0000;

/// The tag of a sampler chosen from an array by a non-constant index:
/// `DYNAMIC_SAMPLER_TAG + index into Lowerer::dynamic_samplers` (above every plain sampler
/// tag, so every test for a sampler leaf, `r.0 >= SAMPLER_TAG`, holds for it too).
const DYNAMIC_SAMPLER_TAG: u32 = SAMPLER_TAG + 0x8000;

/// The most registers a lowered program may have: every call is inlined, and a shader that
/// calls a function twice in each of n nested functions would grow as 2ⁿ (the executor
/// keeps 64 bytes per register).
const MAX_REGISTERS: usize = 1 << 18;

/// The size of an unsized built-in array nobody indexed by a constant (`gl_TexCoord`).
const TEX_COORDS: u32 = 8;

/// One leaf's kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Leaf {
    Scalar(ir::Type),
    Sampler,
}

fn ir_type(s: Scalar) -> ir::Type {
    match s {
        Scalar::Float => ir::Type::F32,
        Scalar::Int => ir::Type::I32,
        Scalar::Bool => ir::Type::Bool,
    }
}

fn array_len(n: Option<u32>) -> u32 {
    n.unwrap_or(TEX_COORDS)
}

/// The leaves of a type, in order.
fn leaves(ty: &Type, out: &mut Vec<Leaf>) {
    match ty {
        Type::Void => {}
        Type::Scalar(_) | Type::Vector(..) | Type::Matrix(..) => {
            let t = ir_type(ty.base().expect("basic"));
            out.extend(std::iter::repeat_n(Leaf::Scalar(t), ty.components()));
        }
        Type::Sampler(_) => out.push(Leaf::Sampler),
        Type::Struct(s) => s.members.iter().for_each(|(_, t)| leaves(t, out)),
        Type::Array(e, n) => {
            for _ in 0..array_len(*n) {
                leaves(e, out);
            }
        }
    }
}

fn leaf_count(ty: &Type) -> usize {
    match ty {
        Type::Void => 0,
        Type::Sampler(_) => 1,
        Type::Struct(s) => s.members.iter().map(|(_, t)| leaf_count(t)).sum(),
        Type::Array(e, n) => leaf_count(e) * array_len(*n) as usize,
        t => t.components(),
    }
}

/// The basic-type (or sampler) elements of a type with their GL names and leaf ranges.
fn elements(ty: &Type, name: String, base: usize, out: &mut Vec<(String, usize, usize, Type)>) {
    match ty {
        Type::Struct(s) => {
            let mut at = base;
            for (m, t) in &s.members {
                elements(t, format!("{name}.{m}"), at, out);
                at += leaf_count(t);
            }
        }
        Type::Array(e, n) => {
            let size = leaf_count(e);
            for i in 0..array_len(*n) as usize {
                elements(e, format!("{name}[{i}]"), base + i * size, out);
            }
        }
        t => out.push((name, base, leaf_count(t), t.clone())),
    }
}

/// The basic-type element holding leaf `i` of a value of type `ty` named `name`: its GL
/// name, its first leaf, and the leaf's kind (what [`elements`] and [`leaves`] list, for
/// one leaf).
fn element_of(ty: &Type, name: String, i: usize) -> (String, usize, Leaf) {
    match ty {
        Type::Struct(s) => {
            let mut at = 0;
            for (m, t) in &s.members {
                let n = leaf_count(t);
                if i < at + n {
                    let (name, base, kind) = element_of(t, format!("{name}.{m}"), i - at);
                    return (name, at + base, kind);
                }
                at += n;
            }
            unreachable!("leaf {i} beyond the struct's {at} leaves")
        }
        Type::Array(e, _) => {
            let size = leaf_count(e).max(1);
            let k = i / size;
            let (name, base, kind) = element_of(e, format!("{name}[{k}]"), i % size);
            (name, k * size + base, kind)
        }
        Type::Sampler(_) => (name, 0, Leaf::Sampler),
        t => (name, 0, Leaf::Scalar(ir_type(t.base().expect("basic")))),
    }
}

/// Where a variable's words come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Class {
    Uniform,
    Input,
    Output,
    /// Globals, locals, parameters, constants.
    Private,
}

/// A variable's identity across units: globals and built-ins by name.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Key {
    Global(String),
    Local(usize, hir::VarId),
}

struct VarState {
    ty: Type,
    class: Class,
    /// Per leaf: its register once used.
    regs: Vec<Option<Reg>>,
    /// The folded value of a constant variable.
    constant: Option<Constant>,
}

/// Where an lvalue or an indexed rvalue lives: leaves `base..base + len` of a variable or a
/// temporary, further chosen by dynamic indices and a swizzle.
#[derive(Clone, Debug)]
struct Place {
    root: Root,
    base: usize,
    ty: Type,
    /// Per dynamic index: the i32 register, the stride in leaves and the element count.
    dynamic: Vec<(Reg, usize, usize)>,
    /// Components of the vector at the place (after the dynamic indices).
    swizzle: Option<Vec<u8>>,
    /// A dynamic index into the swizzle's components (`v.wzyx[i]`).
    pick: Option<Reg>,
}

#[derive(Clone, Debug)]
enum Root {
    Var(Key),
    Temp(Vec<Reg>),
}

/// The function being inlined.
struct Frame {
    unit: usize,
    function: hir::FunctionId,
    /// The return value's registers.
    ret: Vec<Reg>,
    /// Whether the body runs in a loop that `return` breaks.
    wrapped: bool,
    /// The flag a `return` inside the function's own loops sets.
    returned: Option<Reg>,
    /// Loops of this function around the current statement.
    loops: usize,
}

struct Lowerer<'a> {
    units: &'a [&'a Checked],
    stage: ir::Stage,
    program: Program,
    prologue: Vec<Stmt>,
    body: Vec<Stmt>,
    vars: HashMap<Key, VarState>,
    constants: HashMap<(ir::Type, u32), Reg>,
    uniforms: Vec<Word>,
    inputs: Vec<Word>,
    samplers: Vec<SamplerUse>,
    /// Samplers chosen by a non-constant index (GLSL 1.10/1.20 allow only constant indices
    /// of sampler arrays; Mesa accepts others, piglit's max-samplers indexes by a loop
    /// counter): the index register and the candidate sampler tags, element by element.
    dynamic_samplers: Vec<(Reg, Vec<Reg>)>,
    /// Output variables in order of first use.
    output_vars: Vec<Key>,
    frames: Vec<Frame>,
}

type R<T> = Result<T, String>;

/// Lowers one stage from its compilation units (see the module docs). Errors: no `main`, a
/// function called but defined nowhere, recursion, and the constructs the lowering does not
/// support (each with a message).
pub fn lower(units: &[&Checked]) -> Result<Lowered, String> {
    let first = units.first().ok_or("no shader to lower")?;
    let stage = match first.stage {
        hir::Stage::Vertex => ir::Stage::Vertex,
        hir::Stage::Fragment => ir::Stage::Fragment,
    };
    let mains: Vec<(usize, usize)> = units
        .iter()
        .enumerate()
        .filter_map(|(u, c)| c.main.filter(|&m| c.functions[m].body.is_some()).map(|m| (u, m)))
        .collect();
    let &[(unit, main)] = mains.as_slice() else {
        return Err(if mains.is_empty() { "no definition of `main'".into() } else { "`main' is defined twice".into() });
    };
    let mut l = Lowerer {
        units,
        stage,
        program: Program::new(stage),
        prologue: Vec::new(),
        body: Vec::new(),
        vars: HashMap::new(),
        constants: HashMap::new(),
        uniforms: Vec::new(),
        inputs: Vec::new(),
        samplers: Vec::new(),
        dynamic_samplers: Vec::new(),
        output_vars: Vec::new(),
        frames: Vec::new(),
    };
    // Global initializers, unit by unit, then main.
    for (u, c) in units.iter().enumerate() {
        for (id, init) in &c.globals {
            if let Some(init) = init {
                let v = &c.variables[*id];
                // A folded constant needs no code; a uniform's initializer is its value
                // at link time, which the API side sets (the program only reads it).
                if (v.storage == Some(Storage::Const) && v.constant.is_some()) || v.storage == Some(Storage::Uniform) {
                    continue;
                }
                l.frames.push(Frame {
                    unit: u,
                    function: usize::MAX,
                    ret: vec![],
                    wrapped: false,
                    returned: None,
                    loops: 0,
                });
                let v = l.expr(init)?;
                let key = l.key(u, *id);
                let place = l.var_place(u, *id, key);
                l.write(&place, &v)?;
                l.frames.pop();
            }
        }
    }
    l.inline(unit, main, Vec::new())?;
    // The epilogue: every used output word.
    let mut outputs = Vec::new();
    for key in l.output_vars.clone() {
        let state = &l.vars[&key];
        let name = match &key {
            Key::Global(n) => n.clone(),
            Key::Local(..) => unreachable!("outputs are globals"),
        };
        let mut elems = Vec::new();
        elements(&state.ty.clone(), name, 0, &mut elems);
        for (name, base, len, _) in elems {
            if (base..base + len).any(|i| l.vars[&key].regs[i].is_some()) {
                for i in 0..len {
                    let src = l.leaf(&key, base + i)?;
                    let ty = l.program.registers[src.0 as usize];
                    let slot = l.program.output(ty);
                    l.body.push(Stmt::Inst(Inst::Output { slot, src }));
                    outputs.push(Word { name: name.clone(), index: i as u32 });
                }
            }
        }
    }
    let mut body = std::mem::take(&mut l.prologue);
    body.append(&mut l.body);
    l.program.body = body;
    if l.samplers.len() > ir::MAX_SAMPLERS {
        return Err(format!("too many samplers ({})", l.samplers.len()));
    }
    crate::shader::validate::validate(&l.program).map_err(|e| format!("lowered program is not valid: {e}"))?;
    Ok(Lowered { program: l.program, uniforms: l.uniforms, inputs: l.inputs, outputs, samplers: l.samplers })
}

impl<'a> Lowerer<'a> {
    // ------------------------------------------------------------ registers and emission

    fn reg(&mut self, ty: ir::Type) -> Reg {
        self.program.register(ty)
    }

    /// New registers for every scalar leaf of `ty`; `sampler_error` when it holds a sampler
    /// (samplers are not values a register can hold).
    fn fresh_registers(&mut self, ty: &Type, sampler_error: &str) -> R<Vec<Reg>> {
        let mut kinds = Vec::new();
        leaves(ty, &mut kinds);
        kinds
            .iter()
            .map(|k| match k {
                Leaf::Scalar(t) => Ok(self.reg(*t)),
                Leaf::Sampler => Err(sampler_error.to_string()),
            })
            .collect()
    }

    fn ty_of(&self, r: Reg) -> ir::Type {
        self.program.registers[r.0 as usize]
    }

    fn emit(&mut self, inst: Inst) {
        self.body.push(Stmt::Inst(inst));
    }

    /// A constant's register, read once in the prologue.
    fn konst(&mut self, c: Const) -> Reg {
        let key = (c.ty(), c.bits());
        if let Some(&r) = self.constants.get(&key) {
            return r;
        }
        let dst = self.reg(c.ty());
        self.prologue.push(Stmt::Inst(Inst::Const { dst, value: c }));
        self.constants.insert(key, dst);
        dst
    }

    fn f(&mut self, v: f32) -> Reg {
        self.konst(Const::F32(v))
    }

    fn un(&mut self, op: U, a: Reg) -> Reg {
        let ty = match op {
            U::F32ToI32 => ir::Type::I32,
            U::F32ToU32 => ir::Type::U32,
            U::I32ToF32 | U::U32ToF32 | U::BoolToF32 => ir::Type::F32,
            U::F32ToBool => ir::Type::Bool,
            U::INot | U::Bitcast => self.ty_of(a),
            U::INeg | U::IAbs => ir::Type::I32,
            U::BNot => ir::Type::Bool,
            _ => ir::Type::F32,
        };
        let dst = self.reg(ty);
        self.emit(Inst::Unary { op, dst, a });
        dst
    }

    fn bin(&mut self, op: B, a: Reg, b: Reg) -> Reg {
        use B::*;
        let ty = match op {
            FLt | FLe | FEq | FNe | ILt | ILe | ULt | ULe | IEq | INe | BAnd | BOr | BXor | BEq => ir::Type::Bool,
            FAdd | FSub | FMul | FDiv | FMin | FMax => ir::Type::F32,
            _ => self.ty_of(a),
        };
        let dst = self.reg(ty);
        self.emit(Inst::Binary { op, dst, a, b });
        dst
    }

    fn select(&mut self, cond: Reg, a: Reg, b: Reg) -> Reg {
        if a == b {
            return a;
        }
        let dst = self.reg(self.ty_of(a));
        self.emit(Inst::Select { dst, cond, a, b });
        dst
    }

    fn mov(&mut self, dst: Reg, src: Reg) {
        if dst != src {
            self.emit(Inst::Mov { dst, src });
        }
    }

    /// A fresh copy of a value (sampler leaves stay tags).
    fn copy(&mut self, v: &[Reg]) -> Vec<Reg> {
        v.iter()
            .map(|&r| {
                if r.0 >= SAMPLER_TAG {
                    r
                } else {
                    let dst = self.reg(self.ty_of(r));
                    self.emit(Inst::Mov { dst, src: r });
                    dst
                }
            })
            .collect()
    }

    /// Runs `f` with its statements collected into their own block.
    fn nested(&mut self, f: impl FnOnce(&mut Self) -> R<()>) -> R<Vec<Stmt>> {
        let outer = std::mem::take(&mut self.body);
        let result = f(self);
        let inner = std::mem::replace(&mut self.body, outer);
        result.map(|()| inner)
    }

    // ------------------------------------------------------------ variables

    fn unit(&self) -> usize {
        self.frames.last().map_or(0, |f| f.unit)
    }

    fn key(&self, unit: usize, id: hir::VarId) -> Key {
        let v = &self.units[unit].variables[id];
        match v.kind {
            VarKind::Builtin | VarKind::Global => Key::Global(v.name.clone()),
            VarKind::Local | VarKind::Parameter(_) => Key::Local(unit, id),
        }
    }

    fn class_of(&self, v: &hir::Variable) -> Class {
        let vertex = self.stage == ir::Stage::Vertex;
        match (v.storage, v.kind) {
            (Some(Storage::Uniform), _) => Class::Uniform,
            (Some(Storage::Attribute), _) => Class::Input,
            (Some(Storage::Varying), _) => {
                if vertex {
                    Class::Output
                } else {
                    Class::Input
                }
            }
            (None, VarKind::Builtin) => {
                if v.read_only {
                    Class::Input
                } else {
                    Class::Output
                }
            }
            _ => Class::Private,
        }
    }

    /// The state of a variable, created on first use.
    fn ensure_var(&mut self, unit: usize, id: hir::VarId, key: &Key) {
        if self.vars.contains_key(key) {
            return;
        }
        let v = &self.units[unit].variables[id];
        let mut ty = v.ty.clone();
        // An array one unit declares unsized may be sized in another, implicitly or not:
        // the largest wins (the link refused an index beyond a declared size).
        let global = matches!(v.kind, VarKind::Builtin | VarKind::Global);
        let size_open = v.implicit_size || matches!(ty, Type::Array(_, None));
        if let (Type::Array(e, _), true) = (&ty, global && size_open) {
            let n = self
                .units
                .iter()
                .flat_map(|c| c.variables.iter())
                .filter(|w| w.name == v.name && matches!(w.kind, VarKind::Builtin | VarKind::Global))
                .filter_map(|w| match &w.ty {
                    Type::Array(_, n) => *n,
                    _ => None,
                })
                .max();
            ty = Type::Array(e.clone(), Some(n.unwrap_or(TEX_COORDS)));
        }
        let class = self.class_of(v);
        let constant = if v.storage == Some(Storage::Const) { v.constant.clone() } else { None };
        let n = leaf_count(&ty);
        if class == Class::Output {
            self.output_vars.push(key.clone());
        }
        self.vars.insert(key.clone(), VarState { ty, class, regs: vec![None; n], constant });
    }

    /// Leaf `i` of a variable: its register (or sampler tag), created on first use.
    fn leaf(&mut self, key: &Key, i: usize) -> R<Reg> {
        let state = &self.vars[key];
        if let Some(r) = state.regs[i] {
            return Ok(r);
        }
        let class = state.class;
        let ty = state.ty.clone();
        let constant = state.constant.clone();
        let name = match key {
            Key::Global(n) => n.clone(),
            Key::Local(..) => String::new(),
        };
        // Straight to the leaf's element, not through a list of all of them: a dynamically
        // indexed array names every leaf, and a list per leaf would be quadratic.
        let (elem_name, elem_base, leaf_kind) = element_of(&ty, name, i);
        let r = match leaf_kind {
            Leaf::Sampler => {
                if class != Class::Uniform {
                    return Err("a sampler that is not a uniform".into());
                }
                let kind = sampler_kind(&ty, i).ok_or("sampler kind")?;
                let index = match self.samplers.iter().position(|s| s.name == elem_name) {
                    Some(p) => p,
                    None => {
                        self.samplers.push(SamplerUse { name: elem_name, kind });
                        self.samplers.len() - 1
                    }
                };
                Reg(SAMPLER_TAG + index as u32)
            }
            Leaf::Scalar(t) => {
                if let Some(c) = &constant {
                    let mut values = Vec::new();
                    flatten_constant(c, &mut values);
                    let v = *values.get(i).ok_or("constant of the wrong size")?;
                    let c = convert_value(v, t);
                    // A constant variable's leaf is a register of its own, as it may be
                    // indexed dynamically like any array.
                    self.konst(c)
                } else {
                    let dst = self.reg(t);
                    match class {
                        Class::Uniform => {
                            let slot = self.program.uniform(t);
                            self.prologue.push(Stmt::Inst(Inst::Uniform { dst, slot }));
                            self.uniforms.push(Word { name: elem_name, index: (i - elem_base) as u32 });
                        }
                        Class::Input => {
                            let slot = self.program.input(t);
                            self.prologue.push(Stmt::Inst(Inst::Input { dst, slot }));
                            self.inputs.push(Word { name: elem_name, index: (i - elem_base) as u32 });
                        }
                        Class::Output | Class::Private => {}
                    }
                    dst
                }
            }
        };
        self.vars.get_mut(key).expect("variable").regs[i] = Some(r);
        Ok(r)
    }

    fn var_place(&mut self, unit: usize, id: hir::VarId, key: Key) -> Place {
        self.ensure_var(unit, id, &key);
        let ty = self.vars[&key].ty.clone();
        Place { root: Root::Var(key), base: 0, ty, dynamic: Vec::new(), swizzle: None, pick: None }
    }

    /// Gives a local (a declaration, a parameter) fresh registers.
    fn fresh_local(&mut self, unit: usize, id: hir::VarId) -> Key {
        let key = self.key(unit, id);
        self.vars.remove(&key);
        self.ensure_var(unit, id, &key);
        key
    }

    // ------------------------------------------------------------ places

    fn place(&mut self, e: &Expr) -> R<Place> {
        match &e.kind {
            ExprKind::Variable(id) => {
                let unit = self.unit();
                let key = self.key(unit, *id);
                Ok(self.var_place(unit, *id, key))
            }
            ExprKind::Field(inner, m) => {
                let mut p = self.place(inner)?;
                if p.swizzle.is_some() {
                    return Err("a member of a swizzle".into());
                }
                let Type::Struct(s) = &p.ty else { return Err("a member of a non-struct".into()) };
                let offset: usize = s.members[..*m].iter().map(|(_, t)| leaf_count(t)).sum();
                p.ty = s.members[*m].1.clone();
                p.base += offset;
                Ok(p)
            }
            ExprKind::Index(inner, index) => {
                let mut p = self.place(inner)?;
                let (elem, count) = match &p.ty {
                    Type::Array(e, n) => ((**e).clone(), array_len(*n) as usize),
                    Type::Matrix(c, r) => (Type::Vector(Scalar::Float, *r), *c as usize),
                    Type::Vector(s, n) => (Type::Scalar(*s), *n as usize),
                    t => return Err(format!("indexing a {t}")),
                };
                let stride = leaf_count(&elem);
                let constant = index.constant().map(|c| c.components()[0].as_i32());
                if let Some(sw) = &mut p.swizzle {
                    if constant.is_none() && p.pick.is_none() {
                        p.pick = Some(self.expr(index)?[0]);
                        p.ty = elem;
                        return Ok(p);
                    }
                    let Some(k) = constant else {
                        // A dynamic component of a swizzle: index the swizzled value.
                        let v = self.read(&p)?;
                        let i = self.expr(index)?[0];
                        return Ok(Place {
                            root: Root::Temp(v),
                            base: 0,
                            ty: p.ty,
                            dynamic: vec![(i, 1, count)],
                            swizzle: None,
                            pick: None,
                        }
                        .retyped(elem));
                    };
                    let c = *sw.get(k.max(0) as usize).ok_or("swizzle index out of range")?;
                    *sw = vec![c];
                    p.ty = elem;
                    return Ok(p);
                }
                match constant {
                    Some(k) => {
                        let k = if k < 0 || k as usize >= count { 0 } else { k as usize };
                        p.base += k * stride;
                    }
                    None => {
                        let i = self.expr(index)?[0];
                        p.dynamic.push((i, stride, count));
                    }
                }
                p.ty = elem;
                Ok(p)
            }
            ExprKind::Swizzle(inner, comps) => {
                let mut p = self.place(inner)?;
                p.swizzle = Some(match &p.swizzle {
                    Some(outer) => comps.iter().map(|&c| outer[c as usize]).collect(),
                    None => comps.clone(),
                });
                p.ty = e.ty.clone();
                Ok(p)
            }
            _ => {
                let v = self.expr(e)?;
                Ok(Place {
                    root: Root::Temp(v),
                    base: 0,
                    ty: e.ty.clone(),
                    dynamic: Vec::new(),
                    swizzle: None,
                    pick: None,
                })
            }
        }
    }

    /// The leaves at a place without dynamic indices (`base` already resolved).
    fn static_leaves(&mut self, root: &Root, base: usize, len: usize, swizzle: &Option<Vec<u8>>) -> R<Vec<Reg>> {
        let indices: Vec<usize> = match swizzle {
            Some(sw) => sw.iter().map(|&c| base + c as usize).collect(),
            None => (base..base + len).collect(),
        };
        indices
            .into_iter()
            .map(|i| match root {
                Root::Var(key) => self.leaf(key, i),
                Root::Temp(v) => v.get(i).copied().ok_or_else(|| "index outside a value".to_string()),
            })
            .collect()
    }

    /// The place with its dynamic indices copied into registers of their own, so that it
    /// stays where it is when the variables of the index expressions change later.
    fn frozen(&mut self, mut p: Place) -> Place {
        for d in &mut p.dynamic {
            d.0 = self.copy(&[d.0])[0];
        }
        if let Some(pick) = p.pick {
            p.pick = Some(self.copy(&[pick])[0]);
        }
        p
    }

    fn read(&mut self, p: &Place) -> R<Vec<Reg>> {
        let len = if p.swizzle.is_some() { 0 } else { leaf_count(&p.ty) };
        let v = self.read_at(&p.root, p.base, len, &p.dynamic, &p.swizzle)?;
        let Some(index) = p.pick else { return Ok(v) };
        let mut result = v[0];
        for (k, &r) in v.iter().enumerate().skip(1) {
            let kc = self.konst(Const::I32(k as i32));
            let cond = self.bin(B::IEq, index, kc);
            result = self.select(cond, r, result);
        }
        Ok(vec![result])
    }

    fn read_at(
        &mut self,
        root: &Root,
        base: usize,
        len: usize,
        dynamic: &[(Reg, usize, usize)],
        swizzle: &Option<Vec<u8>>,
    ) -> R<Vec<Reg>> {
        let Some(&(index, stride, count)) = dynamic.first() else {
            return self.static_leaves(root, base, len, swizzle);
        };
        let mut result = self.read_at(root, base, len, &dynamic[1..], swizzle)?;
        if result.iter().any(|r| r.0 >= SAMPLER_TAG) {
            return self.dynamic_sampler_leaves(
                index,
                result,
                |l, k| l.read_at(root, base + k * stride, len, &dynamic[1..], swizzle),
                count,
            );
        }
        for k in 1..count {
            let v = self.read_at(root, base + k * stride, len, &dynamic[1..], swizzle)?;
            let kc = self.konst(Const::I32(k as i32));
            let cond = self.bin(B::IEq, index, kc);
            result = v.iter().zip(&result).map(|(&a, &b)| self.select(cond, a, b)).collect();
        }
        Ok(result)
    }

    /// The leaves of element `index` of an array whose element 0 is `first` and element k
    /// what `element(k)` reads, when its elements hold samplers: each sampler leaf becomes
    /// a dynamic sampler tag naming the candidates (the lookup selects among them per lane,
    /// element 0 for an index out of range, as other reads are). Arrays of such elements
    /// indexed again (no GLSL 1.20 type has them) are refused.
    fn dynamic_sampler_leaves(
        &mut self,
        index: Reg,
        first: Vec<Reg>,
        mut element: impl FnMut(&mut Self, usize) -> R<Vec<Reg>>,
        count: usize,
    ) -> R<Vec<Reg>> {
        let mut elements = vec![first];
        for k in 1..count {
            elements.push(element(self, k)?);
        }
        if elements.iter().flatten().any(|r| r.0 >= DYNAMIC_SAMPLER_TAG) {
            return Err("a sampler array indexed twice by non-constant expressions".into());
        }
        let mut result = Vec::with_capacity(elements[0].len());
        for j in 0..elements[0].len() {
            if elements[0][j].0 >= SAMPLER_TAG {
                let candidates: Vec<Reg> = elements.iter().map(|e| e[j]).collect();
                self.dynamic_samplers.push((index, candidates));
                result.push(Reg(DYNAMIC_SAMPLER_TAG + (self.dynamic_samplers.len() - 1) as u32));
            } else {
                let mut r = elements[0][j];
                for (k, e) in elements.iter().enumerate().skip(1) {
                    let kc = self.konst(Const::I32(k as i32));
                    let cond = self.bin(B::IEq, index, kc);
                    r = self.select(cond, e[j], r);
                }
                result.push(r);
            }
        }
        Ok(result)
    }

    fn write(&mut self, p: &Place, v: &[Reg]) -> R<()> {
        let len = if p.swizzle.is_some() { 0 } else { leaf_count(&p.ty) };
        if let Some(index) = p.pick {
            // The whole swizzle, with the picked component replaced.
            let whole = Place { pick: None, ..p.clone() };
            let cur = self.read(&whole)?;
            let mut new = Vec::new();
            for (k, &c) in cur.iter().enumerate() {
                let kc = self.konst(Const::I32(k as i32));
                let cond = self.bin(B::IEq, index, kc);
                new.push(self.select(cond, v[0], c));
            }
            return self.write(&whole, &new);
        }
        self.write_at(&p.root, p.base, len, &p.dynamic, &p.swizzle, v, None)
    }

    /// Writes `v` at a place; under `cond` (a bool register) only where it is true.
    #[allow(clippy::too_many_arguments)]
    fn write_at(
        &mut self,
        root: &Root,
        base: usize,
        len: usize,
        dynamic: &[(Reg, usize, usize)],
        swizzle: &Option<Vec<u8>>,
        v: &[Reg],
        cond: Option<Reg>,
    ) -> R<()> {
        if let Some(&(index, stride, count)) = dynamic.first() {
            for k in 0..count {
                let kc = self.konst(Const::I32(k as i32));
                let here = self.bin(B::IEq, index, kc);
                let c = match cond {
                    Some(c) => self.bin(B::BAnd, c, here),
                    None => here,
                };
                self.write_at(root, base + k * stride, len, &dynamic[1..], swizzle, v, Some(c))?;
            }
            return Ok(());
        }
        let Root::Var(key) = root else { return Err("assignment to a value that is not a variable".into()) };
        let targets = self.static_leaves(root, base, len, swizzle)?;
        // `v = v.wzyx`: the value is made of the target's own registers.
        let copied;
        let v = if v.iter().any(|r| targets.contains(r) && r.0 < SAMPLER_TAG) {
            copied = self.copy(v);
            &copied[..]
        } else {
            v
        };
        if targets.len() != v.len() {
            return Err(format!("assignment of {} words to {}", v.len(), targets.len()));
        }
        let _ = key;
        for (&t, &s) in targets.iter().zip(v) {
            if t.0 >= SAMPLER_TAG || s.0 >= SAMPLER_TAG {
                if t != s {
                    return Err("assignment of a sampler".into());
                }
                continue;
            }
            match cond {
                Some(c) => {
                    let dst = t;
                    self.emit(Inst::Select { dst, cond: c, a: s, b: t });
                }
                None => self.mov(t, s),
            }
        }
        Ok(())
    }

    // ------------------------------------------------------------ functions

    /// Finds the definition of a function (perhaps in another unit).
    fn definition(&self, unit: usize, f: hir::FunctionId) -> R<(usize, hir::FunctionId)> {
        let func = &self.units[unit].functions[f];
        if func.body.is_some() {
            return Ok((unit, f));
        }
        let sig = |u: usize, g: &hir::Function| -> Vec<String> {
            g.parameters.iter().map(|p| self.units[u].variables[p.var].ty.to_string()).collect()
        };
        let wanted = sig(unit, func);
        for (u, c) in self.units.iter().enumerate() {
            for (g, gf) in c.functions.iter().enumerate() {
                if gf.body.is_some() && gf.name == func.name && sig(u, gf) == wanted {
                    return Ok((u, g));
                }
            }
        }
        Err(format!("function `{}' has no definition", func.name))
    }

    /// Inlines a call; `args` are the arguments' values (in) or places (out, inout).
    fn inline(&mut self, unit: usize, f: hir::FunctionId, args: Vec<Arg>) -> R<Vec<Reg>> {
        let (unit, f) = self.definition(unit, f)?;
        if self.frames.iter().any(|fr| fr.unit == unit && fr.function == f) {
            return Err(format!("function `{}' is recursive", self.units[unit].functions[f].name));
        }
        if self.frames.len() > 64 {
            return Err("calls nest too deeply".into());
        }
        if self.program.registers.len() > MAX_REGISTERS {
            return Err(format!("the program has more than {MAX_REGISTERS} registers after inlining"));
        }
        let func = &self.units[unit].functions[f];
        let body = func.body.as_ref().expect("definition");
        let ret = self.fresh_registers(&func.return_type, "a function returning a sampler")?;
        // Parameters.
        let params = func.parameters.clone();
        let mut writeback = Vec::new();
        for (p, arg) in params.iter().zip(args) {
            let key = self.fresh_local(unit, p.var);
            let pty = self.units[unit].variables[p.var].ty.clone();
            let n = leaf_count(&pty);
            let value = match arg {
                Arg::Value(v) => Some(v),
                Arg::Place { place, ty, value } => {
                    writeback.push((key.clone(), place, ty, pty.clone()));
                    value
                }
            };
            if let Some(v) = value {
                if v.len() != n {
                    return Err("argument of the wrong size".into());
                }
                let regs = self.copy(&v);
                self.vars.get_mut(&key).expect("parameter").regs = regs.into_iter().map(Some).collect();
            }
        }
        let wrapped = needs_wrap(body);
        self.frames.push(Frame { unit, function: f, ret: ret.clone(), wrapped, returned: None, loops: 0 });
        let result = self.nested(|l| {
            for s in body {
                l.stmt(s)?;
            }
            Ok(())
        });
        let frame = self.frames.pop().expect("frame");
        let mut inner = result?;
        if let Some(flag) = frame.returned {
            let f = self.konst(Const::Bool(false));
            self.mov(flag, f);
        }
        if wrapped {
            inner.push(Stmt::Break);
            self.body.push(Stmt::Loop { body: inner });
        } else {
            self.body.append(&mut inner);
        }
        // Copy out.
        for (key, place, argty, pty) in writeback {
            let n = leaf_count(&pty);
            let v: Vec<Reg> = (0..n).map(|i| self.leaf(&key, i)).collect::<R<_>>()?;
            let v = match (argty.base(), pty.base()) {
                (Some(to), Some(from)) if to != from => self.convert(&v, from, to),
                _ => v,
            };
            self.write(&place, &v)?;
        }
        Ok(ret)
    }

    // ------------------------------------------------------------ statements

    fn frame(&mut self) -> &mut Frame {
        self.frames.last_mut().expect("in a function")
    }

    fn stmt(&mut self, s: &hir::Stmt) -> R<()> {
        match s {
            hir::Stmt::Declare(id, init) => {
                let unit = self.unit();
                let v = &self.units[unit].variables[*id];
                if v.storage == Some(Storage::Const) && v.constant.is_some() {
                    self.fresh_local(unit, *id);
                    return Ok(());
                }
                let value = init.as_ref().map(|e| self.expr(e)).transpose()?;
                let key = self.fresh_local(unit, *id);
                if let Some(value) = value {
                    let ty = self.vars[&key].ty.clone();
                    let place = Place { root: Root::Var(key), base: 0, ty, dynamic: vec![], swizzle: None, pick: None };
                    self.write(&place, &value)?;
                }
            }
            hir::Stmt::Expr(e) => {
                self.expr(e)?;
            }
            hir::Stmt::Block(list) => {
                for s in list {
                    self.stmt(s)?;
                }
            }
            hir::Stmt::If { condition, then, otherwise } => {
                match condition.constant_bool() {
                    Some(true) => return self.stmt(then),
                    Some(false) => return otherwise.as_ref().map_or(Ok(()), |o| self.stmt(o)),
                    None => {}
                }
                let c = self.expr(condition)?[0];
                let then = self.nested(|l| l.stmt(then))?;
                let otherwise = match otherwise {
                    Some(o) => self.nested(|l| l.stmt(o))?,
                    None => Vec::new(),
                };
                self.body.push(Stmt::If { cond: c, then, otherwise });
            }
            hir::Stmt::Loop { init, condition, condition_var, step, body, test_first } => {
                for s in init {
                    self.stmt(s)?;
                }
                // `again`: false on the first iteration (the step and a do-while's test
                // run from the second on).
                let needs_again = step.is_some() || (!test_first && condition.is_some());
                let again = if needs_again {
                    let r = self.reg(ir::Type::Bool);
                    let f = self.konst(Const::Bool(false));
                    self.mov(r, f);
                    Some(r)
                } else {
                    None
                };
                self.frame().loops += 1;
                let result = self.nested(|l| {
                    let test = |l: &mut Self| -> R<()> {
                        if let Some(c) = condition {
                            let v = l.expr(c)?[0];
                            if let Some(var) = condition_var {
                                let unit = l.unit();
                                let key = l.fresh_local(unit, *var);
                                let r = l.leaf(&key, 0)?;
                                l.mov(r, v);
                            }
                            l.body.push(Stmt::If { cond: v, then: vec![], otherwise: vec![Stmt::Break] });
                        }
                        Ok(())
                    };
                    if let Some(again) = again {
                        let top = l.nested(|l| {
                            if let Some(step) = step {
                                l.expr(step)?;
                            }
                            if !test_first {
                                test(l)?;
                            }
                            Ok(())
                        })?;
                        l.body.push(Stmt::If { cond: again, then: top, otherwise: vec![] });
                        let t = l.konst(Const::Bool(true));
                        l.mov(again, t);
                    }
                    if *test_first {
                        test(l)?;
                    }
                    l.stmt(body)
                });
                self.frame().loops -= 1;
                let inner = result?;
                self.body.push(Stmt::Loop { body: inner });
                // A return from inside the loop leaves the enclosing loops too.
                if let Some(flag) = self.frame().returned {
                    if self.frame().loops > 0 || self.frame().wrapped {
                        self.body.push(Stmt::If { cond: flag, then: vec![Stmt::Break], otherwise: vec![] });
                    }
                }
            }
            hir::Stmt::Break => self.body.push(Stmt::Break),
            hir::Stmt::Continue => self.body.push(Stmt::Continue),
            hir::Stmt::Discard => self.body.push(Stmt::Discard),
            hir::Stmt::Return(value) => {
                if let Some(e) = value {
                    let v = self.expr(e)?;
                    let ret = self.frame().ret.clone();
                    for (&d, &s) in ret.iter().zip(&v) {
                        self.mov(d, s);
                    }
                }
                let frame = self.frames.last().expect("frame");
                if !frame.wrapped {
                    // The last statement of an unwrapped function: nothing to skip.
                    return Ok(());
                }
                if frame.loops > 0 {
                    let flag = match frame.returned {
                        Some(f) => f,
                        None => {
                            let r = self.reg(ir::Type::Bool);
                            // Cleared before the body (see `inline`).
                            self.frame().returned = Some(r);
                            r
                        }
                    };
                    let t = self.konst(Const::Bool(true));
                    self.mov(flag, t);
                }
                self.body.push(Stmt::Break);
            }
        }
        Ok(())
    }

    // ------------------------------------------------------------ expressions

    fn expr(&mut self, e: &Expr) -> R<Vec<Reg>> {
        match &e.kind {
            ExprKind::Constant(c) => {
                let mut values = Vec::new();
                flatten_constant(c, &mut values);
                let mut kinds = Vec::new();
                leaves(&e.ty, &mut kinds);
                if kinds.len() != values.len() {
                    return Err("a constant of the wrong size".into());
                }
                Ok(values
                    .into_iter()
                    .zip(kinds)
                    .map(|(v, k)| match k {
                        Leaf::Scalar(t) => self.konst(convert_value(v, t)),
                        Leaf::Sampler => unreachable!("sampler constant"),
                    })
                    .collect())
            }
            ExprKind::Variable(_) | ExprKind::Index(..) | ExprKind::Field(..) | ExprKind::Swizzle(..) => {
                let p = self.place(e)?;
                self.read(&p)
            }
            ExprKind::Unary(op, a) => self.unary(*op, a, &e.ty),
            ExprKind::Binary(op, a, b) => match op {
                hir::BinaryOp::And | hir::BinaryOp::Or => self.logical(*op, a, b),
                _ => {
                    let v = self.operands(&[a, b])?;
                    self.binary(*op, &v[0], &a.ty, &v[1], &b.ty, &e.ty)
                }
            },
            ExprKind::Assign(op, target, value) => {
                let place = self.place(target)?;
                let v = self.expr(value)?;
                let v = match op {
                    Some(op) => {
                        let cur = self.read(&place)?;
                        self.binary(*op, &cur, &target.ty, &v, &value.ty, &target.ty)?
                    }
                    None => v,
                };
                self.write(&place, &v)?;
                Ok(v)
            }
            ExprKind::Conditional(c, a, b) => {
                match c.constant_bool() {
                    Some(true) => return self.expr(a),
                    Some(false) => return self.expr(b),
                    None => {}
                }
                let c = self.expr(c)?[0];
                if !side_effects(a) && !side_effects(b) {
                    let va = self.expr(a)?;
                    let vb = self.expr(b)?;
                    if va.iter().chain(&vb).any(|r| r.0 >= SAMPLER_TAG) {
                        return Err("a conditional choosing a sampler".into());
                    }
                    return Ok(va.iter().zip(&vb).map(|(&x, &y)| self.select(c, x, y)).collect());
                }
                let result = self.fresh_registers(&e.ty, "a conditional choosing a sampler")?;
                let branch = |l: &mut Self, x: &Expr| -> R<Vec<Stmt>> {
                    l.nested(|l| {
                        let v = l.expr(x)?;
                        for (&d, &s) in result.iter().zip(&v) {
                            l.mov(d, s);
                        }
                        Ok(())
                    })
                };
                let then = branch(self, a)?;
                let otherwise = branch(self, b)?;
                self.body.push(Stmt::If { cond: c, then, otherwise });
                Ok(result)
            }
            ExprKind::Sequence(a, b) => {
                self.expr(a)?;
                self.expr(b)
            }
            ExprKind::Convert(a) => {
                let v = self.expr(a)?;
                let (from, to) = (a.ty.base().ok_or("conversion")?, e.ty.base().ok_or("conversion")?);
                Ok(self.convert(&v, from, to))
            }
            ExprKind::Construct(args) => self.construct(&e.ty, args),
            ExprKind::Call(f, args) => {
                let unit = self.unit();
                let (du, df) = self.definition(unit, *f)?;
                let params = self.units[du].functions[df].parameters.clone();
                // GLSL 1.20 section 6.1.1: arguments are evaluated left to right once, at
                // the call: an out argument's place (its index values included) is fixed
                // then, and an inout's value read then, whatever the call or a later
                // argument does to the variables they name (`f(i, a[i])` writing `i`).
                let mut values = Vec::new();
                for (k, (a, p)) in args.iter().zip(&params).enumerate() {
                    let later_effects = args[k + 1..].iter().any(side_effects);
                    if p.direction == ParameterDirection::In {
                        let v = self.expr(a)?;
                        values.push(Arg::Value(if later_effects { self.copy(&v) } else { v }));
                    } else {
                        let place = self.place(a)?;
                        let place = self.frozen(place);
                        let value = match p.direction {
                            ParameterDirection::Inout => {
                                let v = self.read(&place)?;
                                Some(if later_effects { self.copy(&v) } else { v })
                            }
                            _ => None,
                        };
                        values.push(Arg::Place { place, ty: a.ty.clone(), value });
                    }
                }
                self.inline(unit, *f, values)
            }
            ExprKind::Builtin(name, args) => {
                let values = self.operands(&args.iter().collect::<Vec<_>>())?;
                let types: Vec<Type> = args.iter().map(|a| a.ty.clone()).collect();
                self.builtin(name, &values, &types, &e.ty)
            }
        }
    }

    /// Operands evaluated left to right; a value that a later operand's side effects could
    /// change (it is a variable's own registers) is copied first.
    fn operands(&mut self, list: &[&Expr]) -> R<Vec<Vec<Reg>>> {
        let mut out = Vec::with_capacity(list.len());
        for (i, e) in list.iter().enumerate() {
            let v = self.expr(e)?;
            let later = list[i + 1..].iter().any(|x| side_effects(x));
            out.push(if later { self.copy(&v) } else { v });
        }
        Ok(out)
    }

    fn unary(&mut self, op: hir::UnaryOp, a: &Expr, ty: &Type) -> R<Vec<Reg>> {
        use hir::UnaryOp::*;
        let base = ty.base().ok_or("unary operator on a non-basic type")?;
        match op {
            Neg => {
                let v = self.expr(a)?;
                let op = if base == Scalar::Float { U::FNeg } else { U::INeg };
                Ok(v.iter().map(|&r| self.un(op, r)).collect())
            }
            Not => {
                let v = self.expr(a)?;
                Ok(v.iter().map(|&r| self.un(U::BNot, r)).collect())
            }
            PreIncrement | PreDecrement | PostIncrement | PostDecrement => {
                let place = self.place(a)?;
                let old = self.read(&place)?;
                let old = self.copy(&old);
                let (one, add, sub) = if base == Scalar::Float {
                    (self.f(1.0), B::FAdd, B::FSub)
                } else {
                    (self.konst(Const::I32(1)), B::IAdd, B::ISub)
                };
                let pre = matches!(op, PreIncrement | PreDecrement);
                let op = if matches!(op, PreIncrement | PostIncrement) { add } else { sub };
                let new: Vec<Reg> = old.iter().map(|&r| self.bin(op, r, one)).collect();
                self.write(&place, &new)?;
                Ok(if pre { new } else { old })
            }
        }
    }

    /// `&&` and `||`: an IR if when the second operand has side effects.
    fn logical(&mut self, op: hir::BinaryOp, a: &Expr, b: &Expr) -> R<Vec<Reg>> {
        // A constant first operand that decides the result: the second is dead code.
        match (op, a.constant_bool()) {
            (hir::BinaryOp::And, Some(false)) | (hir::BinaryOp::Or, Some(true)) => return self.expr(a),
            (_, Some(_)) => return self.expr(b),
            _ => {}
        }
        let va = self.expr(a)?[0];
        if !side_effects(b) {
            let vb = self.expr(b)?[0];
            let bop = if op == hir::BinaryOp::And { B::BAnd } else { B::BOr };
            return Ok(vec![self.bin(bop, va, vb)]);
        }
        let result = self.reg(ir::Type::Bool);
        self.mov(result, va);
        let rhs = self.nested(|l| {
            let vb = l.expr(b)?[0];
            l.mov(result, vb);
            Ok(())
        })?;
        let (then, otherwise) = if op == hir::BinaryOp::And { (rhs, vec![]) } else { (vec![], rhs) };
        self.body.push(Stmt::If { cond: va, then, otherwise });
        Ok(vec![result])
    }

    /// Converts every leaf from one scalar kind to another.
    fn convert(&mut self, v: &[Reg], from: Scalar, to: Scalar) -> Vec<Reg> {
        v.iter().map(|&r| self.convert1(r, from, to)).collect()
    }

    fn convert1(&mut self, r: Reg, from: Scalar, to: Scalar) -> Reg {
        use Scalar::*;
        match (from, to) {
            (a, b) if a == b => r,
            (Int, Float) => self.un(U::I32ToF32, r),
            (Bool, Float) => self.un(U::BoolToF32, r),
            (Float, Int) => self.un(U::F32ToI32, r),
            (Bool, Int) => {
                let (one, zero) = (self.konst(Const::I32(1)), self.konst(Const::I32(0)));
                self.select(r, one, zero)
            }
            (Float, Bool) => self.un(U::F32ToBool, r),
            (Int, Bool) => {
                let zero = self.konst(Const::I32(0));
                self.bin(B::INe, r, zero)
            }
            _ => unreachable!(),
        }
    }

    /// A binary operator on lowered operands.
    fn binary(&mut self, op: hir::BinaryOp, a: &[Reg], at: &Type, b: &[Reg], bt: &Type, _result: &Type) -> R<Vec<Reg>> {
        use hir::BinaryOp::*;
        let base = at.base().or(bt.base());
        let float = base == Some(Scalar::Float);
        match op {
            Add | Sub | Mul | Div => {
                let iop = match (op, float) {
                    (Add, true) => B::FAdd,
                    (Sub, true) => B::FSub,
                    (Mul, true) => B::FMul,
                    (Div, true) => B::FDiv,
                    (Add, false) => B::IAdd,
                    (Sub, false) => B::ISub,
                    (Mul, false) => B::IMul,
                    _ => B::IDiv,
                };
                let n = a.len().max(b.len());
                Ok((0..n)
                    .map(|i| {
                        let x = if a.len() == 1 { a[0] } else { a[i] };
                        let y = if b.len() == 1 { b[0] } else { b[i] };
                        self.bin(iop, x, y)
                    })
                    .collect())
            }
            MatMul => self.matmul(a, at, b, bt),
            Less | Greater | LessEqual | GreaterEqual => {
                let (x, y) = if matches!(op, Greater | GreaterEqual) { (b[0], a[0]) } else { (a[0], b[0]) };
                let o = match (op, float) {
                    (Less | Greater, true) => B::FLt,
                    (_, true) => B::FLe,
                    (Less | Greater, false) => B::ILt,
                    _ => B::ILe,
                };
                Ok(vec![self.bin(o, x, y)])
            }
            Equal | NotEqual => {
                let eq = self.equal(a, b)?;
                Ok(vec![if op == NotEqual { self.un(U::BNot, eq) } else { eq }])
            }
            And => Ok(vec![self.bin(B::BAnd, a[0], b[0])]),
            Or => Ok(vec![self.bin(B::BOr, a[0], b[0])]),
            Xor => Ok(vec![self.bin(B::BXor, a[0], b[0])]),
        }
    }

    /// Whether two values are equal in every leaf (one bool).
    fn equal(&mut self, a: &[Reg], b: &[Reg]) -> R<Reg> {
        let mut all: Option<Reg> = None;
        for (&x, &y) in a.iter().zip(b) {
            if x.0 >= SAMPLER_TAG || y.0 >= SAMPLER_TAG {
                return Err("comparison of samplers".into());
            }
            let e = self.eq1(x, y);
            all = Some(match all {
                Some(p) => self.bin(B::BAnd, p, e),
                None => e,
            });
        }
        Ok(all.unwrap_or_else(|| self.konst(Const::Bool(true))))
    }

    fn eq1(&mut self, x: Reg, y: Reg) -> Reg {
        match self.ty_of(x) {
            ir::Type::F32 => self.bin(B::FEq, x, y),
            ir::Type::Bool => self.bin(B::BEq, x, y),
            _ => self.bin(B::IEq, x, y),
        }
    }

    /// `Σ a[k]·b[k]` summed left to right (a plain product for one pair).
    fn dot(&mut self, a: &[Reg], b: &[Reg]) -> Reg {
        if a.len() == 1 {
            return self.bin(B::FMul, a[0], b[0]);
        }
        let dst = self.reg(ir::Type::F32);
        let pad = |v: &[Reg]| [v[0], v[1], *v.get(2).unwrap_or(&v[0]), *v.get(3).unwrap_or(&v[0])];
        self.emit(Inst::Dot { dst, n: a.len() as u8, a: pad(a), b: pad(b) });
        dst
    }

    /// The linear-algebra product.
    fn matmul(&mut self, a: &[Reg], at: &Type, b: &[Reg], bt: &Type) -> R<Vec<Reg>> {
        let col = |m: &[Reg], rows: usize, j: usize| m[j * rows..(j + 1) * rows].to_vec();
        let row =
            |m: &[Reg], cols: usize, rows: usize, i: usize| (0..cols).map(|k| m[k * rows + i]).collect::<Vec<_>>();
        match (at, bt) {
            (Type::Matrix(c1, r1), Type::Matrix(c2, _)) => {
                let (c1, r1, c2) = (*c1 as usize, *r1 as usize, *c2 as usize);
                let mut out = Vec::new();
                for j in 0..c2 {
                    let bc = col(b, c1, j);
                    for i in 0..r1 {
                        let ar = row(a, c1, r1, i);
                        out.push(self.dot(&ar, &bc));
                    }
                }
                Ok(out)
            }
            (Type::Matrix(c, r), Type::Vector(..)) => {
                let (c, r) = (*c as usize, *r as usize);
                Ok((0..r)
                    .map(|i| {
                        let ar = row(a, c, r, i);
                        self.dot(&ar, b)
                    })
                    .collect())
            }
            (Type::Vector(..), Type::Matrix(c, r)) => {
                let (c, r) = (*c as usize, *r as usize);
                Ok((0..c)
                    .map(|j| {
                        let bc = col(b, r, j);
                        self.dot(a, &bc)
                    })
                    .collect())
            }
            _ => Err(format!("a product of {at} and {bt}")),
        }
    }

    /// Constructors: scalars, vectors and matrices from components, a scalar splat or a
    /// matrix's diagonal, a matrix from a matrix; structs and arrays from their parts.
    fn construct(&mut self, ty: &Type, args: &[Expr]) -> R<Vec<Reg>> {
        let values = self.operands(&args.iter().collect::<Vec<_>>())?;
        match ty {
            Type::Struct(_) | Type::Array(..) => {
                let mut out = Vec::new();
                let mut kinds = Vec::new();
                leaves(ty, &mut kinds);
                for (v, a) in values.iter().zip(args) {
                    out.extend_from_slice(v);
                    let _ = a;
                }
                if out.len() != kinds.len() {
                    return Err(format!("constructor of {ty} from {} words", out.len()));
                }
                Ok(out)
            }
            _ => {
                let to = ty.base().ok_or("constructor of a non-basic type")?;
                let n = ty.components();
                // The arguments' components converted to the target kind.
                let mut comps = Vec::new();
                for (v, a) in values.iter().zip(args) {
                    let from = a.ty.base().ok_or("constructor argument")?;
                    comps.extend(self.convert(v, from, to));
                }
                if let (Type::Matrix(c, r), [arg]) = (ty, args) {
                    let (c, r) = (*c as usize, *r as usize);
                    let zero = self.f(0.0);
                    let one = self.f(1.0);
                    if arg.ty.is_scalar() {
                        let d = comps[0];
                        return Ok((0..c * r).map(|k| if k / r == k % r { d } else { zero }).collect());
                    }
                    if let Type::Matrix(ac, ar) = arg.ty {
                        let (ac, ar) = (ac as usize, ar as usize);
                        return Ok((0..c * r)
                            .map(|k| {
                                let (j, i) = (k / r, k % r);
                                if j < ac && i < ar {
                                    comps[j * ar + i]
                                } else if i == j {
                                    one
                                } else {
                                    zero
                                }
                            })
                            .collect());
                    }
                }
                if comps.len() == 1 && n > 1 {
                    return Ok(vec![comps[0]; n]);
                }
                if comps.len() < n {
                    return Err(format!("constructor of {ty} from {} components", comps.len()));
                }
                comps.truncate(n);
                Ok(comps)
            }
        }
    }
}

/// An argument of an inlined call.
enum Arg {
    Value(Vec<Reg>),
    /// An out or inout argument: its place (indices frozen at the call), its type, and for
    /// an inout the value read at the call.
    Place {
        place: Place,
        ty: Type,
        value: Option<Vec<Reg>>,
    },
}

impl Place {
    fn retyped(mut self, ty: Type) -> Place {
        self.ty = ty;
        self
    }
}

/// Whether a function body needs the loop `return` breaks: a `return` anywhere but as its
/// last top-level statement.
fn needs_wrap(body: &[hir::Stmt]) -> bool {
    fn any_return(s: &hir::Stmt) -> bool {
        match s {
            hir::Stmt::Return(_) => true,
            hir::Stmt::Block(l) => l.iter().any(any_return),
            hir::Stmt::If { then, otherwise, .. } => any_return(then) || otherwise.as_deref().is_some_and(any_return),
            hir::Stmt::Loop { body, .. } => any_return(body),
            _ => false,
        }
    }
    match body.split_last() {
        Some((hir::Stmt::Return(_), rest)) => rest.iter().any(any_return),
        Some(_) => body.iter().any(any_return),
        None => false,
    }
}

/// Whether evaluating an expression may write anything (an assignment, `++`, a call of the
/// shader's own functions).
fn side_effects(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Constant(_) | ExprKind::Variable(_) => false,
        ExprKind::Assign(..) | ExprKind::Call(..) => true,
        ExprKind::Unary(op, a) => !matches!(op, hir::UnaryOp::Neg | hir::UnaryOp::Not) || side_effects(a),
        ExprKind::Binary(_, a, b) | ExprKind::Sequence(a, b) | ExprKind::Index(a, b) => {
            side_effects(a) || side_effects(b)
        }
        ExprKind::Conditional(a, b, c) => side_effects(a) || side_effects(b) || side_effects(c),
        ExprKind::Field(a, _) | ExprKind::Swizzle(a, _) | ExprKind::Convert(a) => side_effects(a),
        ExprKind::Construct(args) | ExprKind::Builtin(_, args) => args.iter().any(side_effects),
    }
}

fn flatten_constant(c: &Constant, out: &mut Vec<Value>) {
    match c {
        Constant::Basic(v) => out.extend_from_slice(v),
        Constant::Composite(list) => list.iter().for_each(|c| flatten_constant(c, out)),
    }
}

fn convert_value(v: Value, t: ir::Type) -> Const {
    match t {
        ir::Type::F32 => Const::F32(v.as_f32()),
        ir::Type::I32 => Const::I32(v.as_i32()),
        ir::Type::U32 => Const::U32(v.as_i32() as u32),
        ir::Type::Bool => Const::Bool(v.as_bool()),
    }
}

/// The sampler type of leaf `i` of a type.
fn sampler_kind(ty: &Type, i: usize) -> Option<Sampler> {
    match ty {
        Type::Sampler(s) => (i == 0).then_some(*s),
        Type::Array(e, _) => sampler_kind(e, i % leaf_count(e).max(1)),
        Type::Struct(s) => {
            let mut at = 0;
            for (_, t) in &s.members {
                let n = leaf_count(t);
                if i < at + n {
                    return sampler_kind(t, i - at);
                }
                at += n;
            }
            None
        }
        _ => None,
    }
}
