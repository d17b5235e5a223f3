//! Control flow made straight before compiling: [`flatten`] unrolls loops whose trip count
//! is known when the program is compiled and turns `if`s whose arms are pure arithmetic
//! into selects (in fragment programs, not those on uniform conditions: a real branch there
//! runs one arm), then writes straight code's registers once each (`single_writes`), so
//! that typical GLSL fragment programs (a `for` over two lights, a ternary, an
//! `if (diffuse > 0.0)` around a `pow`) reach [`super::lower`] as one straight run of operations:
//! [`super::fast`] then runs them without its control tree, masks per run or recursion,
//! which cost phong 5× the time of its straight-line arithmetic.
//!
//! **Why at the IR, before lowering.** Both passes are rewrites of structured statements
//! whose result is again a valid [`Program`]: the reference [`super::exec`] runs the
//! flattened program to the same bits as the original (the tests check it on random programs
//! and inputs), and [`super::lower`]'s folding, dead code, uniform values and fused
//! operations apply to the straight result unchanged (an unrolled `i < 2` becomes constants
//! it drops; a select on a uniform condition stays a scalar operation).
//!
//! - **Unrolling.** Walking the program with the registers whose value is a known constant in
//!   every running lane (constants, and operations on them computed with the executor's own
//!   lane functions), an `if` on a known condition is replaced by the arm it takes (in the
//!   reference, the other arm runs in no lane). A loop is unrolled by walking copies of its
//!   body so, one per iteration, while every `break` and `continue` of the loop ends up at
//!   the top level of the iteration (every running lane leaves together): a `continue` ends
//!   the copy, a `break`, `return` or `discard` ends the loop. GLSL's
//!   `for (int i = 0; i < n; i++)` with a constant `n` is such a loop. A loop still running
//!   after [`MAX_UNROLLED_ITERATIONS`], or whose copies outgrow [`MAX_UNROLLED_STATEMENTS`],
//!   or that breaks under an unknown condition, stays a loop. Statements after a `break`,
//!   `continue`, `return` or `discard` in the same list run in no lane and are dropped.
//! - **If-conversion.** An `if` whose arms (after their own nested `if`s are converted) are
//!   instructions that only compute registers (no texture lookups, whose sampler sees the
//!   running lanes and, with an implicit level of detail, their quads; no derivatives,
//!   which read other lanes of registers the arms would now write in all of them; no
//!   outputs, `discard`, loops or exits) becomes both arms, each writing fresh registers,
//!   then for every register an arm writes `r = cond ? then's value : else's value` (the
//!   register itself where an arm leaves it). The selects are written in the lanes that ran
//!   the `if`, which is where the original arms wrote; the fresh registers are read by the
//!   selects alone. Arithmetic has no traps, so computing an arm in lanes that do not take it
//!   changes only values nothing reads. Arms larger than [`MAX_CONVERTED_INSTRUCTIONS`] stay
//!   branches (a rare path costs its full price in every lane once converted).
use std::collections::HashMap;

use super::ir::{Const, Inst, Lod, Program, Reg, Stage, Stmt, Type};
use super::lower::{binary_lane, dot_lane, mad_lane, unary_lane};

/// The most iterations of one loop that are unrolled.
pub const MAX_UNROLLED_ITERATIONS: usize = 32;

/// The most statements one loop's unrolled copies may hold (nested unrolled loops count
/// their copies).
pub const MAX_UNROLLED_STATEMENTS: usize = 2048;

/// The most instructions the unrolling of one program may visit (copies of loops nested in
/// loops are walked again for each copy of the outer ones: piglit's `unroll-explosion`, 16
/// loops of 16 nested, would take forever). Past it, loops stay loops.
pub const MAX_UNROLLING_WORK: usize = 1 << 16;

/// The unrolling's state: the registers' types and the work left.
struct Unroller<'a> {
    types: &'a [Type],
    work: usize,
}

/// The most instructions the two arms of a converted `if` may hold together.
pub const MAX_CONVERTED_INSTRUCTIONS: usize = 256;

/// `program` with its loops of known trip counts unrolled and its pure `if`s turned into
/// selects (see the module docs): the same outputs, lookups and discards in every lane.
/// `program` must be valid; so is the result.
pub fn flatten(program: &Program) -> Program {
    let mut out = program.clone();
    if !has_control_flow(&program.body) {
        single_writes(&mut out);
        return out;
    }
    let body = std::mem::take(&mut out.body);
    let body =
        unroll_block(&mut Unroller { types: &program.registers, work: MAX_UNROLLING_WORK }, body, &mut Env::new());
    // Fragment programs keep their `if`s on uniform conditions: the fragment pipeline runs
    // [`super::fast`]'s control tree, where such an `if` is one test per block and runs only
    // the arm taken (phong's `p.w == 0.0 ? … : …` per light: converted, every block paid
    // for a positional light's arm at a directional light too). Vertex programs convert
    // them: their bound form ([`super::fast::BoundRun`]) needs one straight run.
    let uniform = match program.stage {
        Stage::Fragment => uniform_registers(out.registers.len(), &body),
        Stage::Vertex => Vec::new(),
    };
    out.body = convert_block(&mut out, body, Some(&uniform));
    single_writes(&mut out);
    out
}

// ---- Single writes -------------------------------------------------------------------

/// The most registers a program may reach by [`single_writes`]' renaming (the executor
/// numbers its words in 16 bits).
const MAX_RENAMED_REGISTERS: usize = 60_000;

/// Straight code (instructions alone, as unrolling and if-conversion leave typical
/// programs) with each pure instruction's register written once: a write of a register
/// written before goes to a fresh register, which the reads after it read, and a read of
/// the destination of a move reads its source instead, when nothing writes that source
/// later. Unrolled iterations reassign the same registers (a light's position, its
/// colours, the loop's results), which kept them out of [`super::lower`]'s uniform
/// prologue and constant folding, and behind chains of moves (phong: 260 of its 506
/// operations were moves of uniform values per block). Every read sees the value it saw
/// before, so the outputs, lookups and bits are the same.
fn single_writes(program: &mut Program) {
    if has_control_flow(&program.body) {
        return;
    }
    let n = program.registers.len();
    // Per original register, its writes still to come, and those that keep its name
    // (texture lookups, derivatives: not renamed).
    let mut remaining = vec![0u32; n];
    let mut in_place = vec![0u32; n];
    for s in &program.body {
        let Stmt::Inst(inst) = s else { unreachable!("straight code") };
        inst.writes().into_iter().for_each(|r| remaining[r.0 as usize] += 1);
        if inst.clone().pure_dst_mut().is_none() {
            inst.writes().into_iter().for_each(|r| in_place[r.0 as usize] += 1);
        }
    }
    let total: usize = remaining.iter().map(|&w| w as usize).sum();
    if n + total > MAX_RENAMED_REGISTERS {
        return;
    }
    // Per original register, its current name; per name, the source it copies.
    let mut name: Vec<Reg> = (0..n as u32).map(Reg).collect();
    let mut written = vec![false; n];
    let mut copies: Vec<Option<Reg>> = vec![None; n];
    let mut computed: HashMap<ArithmeticKey, Reg> = HashMap::new();
    let body = std::mem::take(&mut program.body);
    for s in body {
        let Stmt::Inst(mut inst) = s else { unreachable!("straight code") };
        visit_reads(&mut inst, &mut |r| {
            let current = name[r.0 as usize];
            *r = copies[current.0 as usize].unwrap_or(current);
        });
        if let Some(d) = inst.pure_dst_mut() {
            let original = d.0 as usize;
            remaining[original] -= 1;
            if written[original] {
                let fresh = program.register(program.registers[original]);
                copies.push(None);
                *d = fresh;
            }
            written[original] = true;
            name[original] = *d;
        } else {
            for r in inst.writes() {
                let original = r.0 as usize;
                remaining[original] -= 1;
                in_place[original] -= 1;
                written[original] = true;
                name[original] = r;
                copies[original] = None;
            }
        }
        // A move's destination stands for its source while nothing writes the source again:
        // fresh registers are written once; an original one keeps its value once written
        // (its later pure writes go to fresh ones) unless a lookup writes it in place.
        let stable = |r: Reg| {
            let r = r.0 as usize;
            r >= n || (in_place[r] == 0 && (written[r] || remaining[r] == 0))
        };
        if let Inst::Mov { dst, src } = inst {
            if stable(src) && program.registers[dst.0 as usize] == program.registers[src.0 as usize] {
                copies[dst.0 as usize] = Some(src);
            }
        }
        // An arithmetic instruction on stable registers computed before by the same
        // instruction on the same registers: its destination stands for the earlier one
        // (`p.xyz - position` for a light's direction and again for its distance).
        if let (Some(key), Some(dst)) = (arithmetic_key(&inst), inst.dst()) {
            let mut operands_stable = true;
            visit_reads(&mut inst.clone(), &mut |r| operands_stable &= stable(*r));
            if operands_stable && stable(dst) {
                match computed.get(&key) {
                    Some(&earlier) if program.registers[earlier.0 as usize] == program.registers[dst.0 as usize] => {
                        copies[dst.0 as usize] = Some(earlier)
                    }
                    Some(_) => {}
                    None => {
                        computed.insert(key, dst);
                    }
                }
            }
        }
        program.body.push(Stmt::Inst(inst));
    }
}

/// What an arithmetic instruction computes, its destination left out: its operation and
/// the registers it reads, compared exactly; `None` for the others (constants are
/// [`super::lower`]'s to fold). A key of plain values rather than the instruction's text:
/// formatting every instruction was two fifths of flattening a fixed-function program.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum ArithmeticKey {
    Unary(super::ir::UnaryOp, Reg),
    Binary(super::ir::BinaryOp, Reg, Reg),
    Mad(Reg, Reg, Reg),
    Dot(u8, [Reg; 4], [Reg; 4]),
    Select(Reg, Reg, Reg),
}

fn arithmetic_key(inst: &Inst) -> Option<ArithmeticKey> {
    Some(match *inst {
        Inst::Unary { op, a, .. } => ArithmeticKey::Unary(op, a),
        Inst::Binary { op, a, b, .. } => ArithmeticKey::Binary(op, a, b),
        Inst::Mad { a, b, c, .. } => ArithmeticKey::Mad(a, b, c),
        Inst::Dot { n, a, b, .. } => ArithmeticKey::Dot(n, a, b),
        Inst::Select { cond, a, b, .. } => ArithmeticKey::Select(cond, a, b),
        _ => return None,
    })
}

/// Shows every register `inst` reads to `visit`, which may rename it.
fn visit_reads(inst: &mut Inst, visit: &mut dyn FnMut(&mut Reg)) {
    match inst {
        Inst::Const { .. } | Inst::Input { .. } | Inst::Uniform { .. } => {}
        Inst::Mov { src: a, .. } | Inst::Unary { a, .. } | Inst::Derivative { a, .. } | Inst::Output { src: a, .. } => {
            visit(a)
        }
        Inst::Binary { a, b, .. } => {
            visit(a);
            visit(b);
        }
        Inst::Mad { a, b, c, .. } => {
            visit(a);
            visit(b);
            visit(c);
        }
        Inst::Dot { n, a, b, .. } => {
            for k in 0..*n as usize {
                visit(&mut a[k]);
                visit(&mut b[k]);
            }
        }
        Inst::Select { cond, a, b, .. } => {
            visit(cond);
            visit(a);
            visit(b);
        }
        Inst::Sample { coords, lod, compare, .. } => {
            coords.iter_mut().for_each(&mut *visit);
            if let Lod::Bias(r) | Lod::Explicit(r) = lod {
                visit(r);
            }
            if let Some(r) = compare {
                visit(r);
            }
        }
        Inst::Fetch { coords, lod, .. } => {
            coords.iter_mut().for_each(&mut *visit);
            visit(lod);
        }
        Inst::Size { lod, .. } => visit(lod),
    }
}

fn has_control_flow(stmts: &[Stmt]) -> bool {
    stmts.iter().any(|s| !matches!(s, Stmt::Inst(_)))
}

// ---- Unrolling ----------------------------------------------------------------------

/// The registers whose value is the same known word in every running lane.
type Env = HashMap<Reg, u32>;

/// Records what `inst` writes in `env`.
fn eval(inst: &Inst, env: &mut Env) {
    match (inst.dst(), value(inst, env)) {
        (Some(d), Some(v)) => {
            env.insert(d, v);
        }
        _ => {
            for r in inst.writes() {
                env.remove(&r);
            }
        }
    }
}

/// The word `inst` computes, if `env` knows its operands.
fn value(inst: &Inst, env: &Env) -> Option<u32> {
    let known = |r: &Reg| env.get(r).copied();
    match *inst {
        Inst::Const { value, .. } => Some(value.bits()),
        Inst::Mov { src, .. } => known(&src),
        Inst::Unary { op, a, .. } => known(&a).map(|x| unary_lane(op, x)),
        Inst::Binary { op, a, b, .. } => match (known(&a), known(&b)) {
            (Some(x), Some(y)) => Some(binary_lane(op, x, y)),
            _ => None,
        },
        Inst::Mad { a, b, c, .. } => match (known(&a), known(&b), known(&c)) {
            (Some(x), Some(y), Some(z)) => Some(mad_lane(x, y, z)),
            _ => None,
        },
        Inst::Dot { n, a, b, .. } => {
            let (mut x, mut y) = ([0; 4], [0; 4]);
            let mut all = true;
            for k in 0..n as usize {
                match (known(&a[k]), known(&b[k])) {
                    (Some(p), Some(q)) => (x[k], y[k]) = (p, q),
                    _ => all = false,
                }
            }
            all.then(|| dot_lane(n as usize, &x, &y))
        }
        Inst::Select { cond, a, b, .. } => match known(&cond) {
            Some(c) => known(if c != 0 { &a } else { &b }),
            None => None,
        },
        _ => None,
    }
}

/// `inst` with what `env` knows put in: an operation on known values becomes its constant
/// (computed with the executor's lane functions: the same bits), a select on a known
/// condition a move (an unrolled loop's `gl_LightSource[i]` is a chain of those).
fn simplify(types: &[Type], inst: Inst, env: &Env) -> Inst {
    let known = |r: &Reg| env.contains_key(r);
    let folds = match &inst {
        Inst::Mov { src, .. } => known(src),
        Inst::Unary { a, .. } => known(a),
        Inst::Binary { a, b, .. } => known(a) && known(b),
        Inst::Mad { a, b, c, .. } => known(a) && known(b) && known(c),
        Inst::Dot { n, a, b, .. } => (0..*n as usize).all(|k| known(&a[k]) && known(&b[k])),
        Inst::Select { cond, a, b, .. } => known(cond) && known(a) && known(b),
        _ => false,
    };
    if folds {
        let dst = inst.dst().expect("an operation writes a register");
        let bits = value(&inst, env).expect("known operands");
        let value = match types[dst.0 as usize] {
            Type::F32 => Const::F32(f32::from_bits(bits)),
            Type::I32 => Const::I32(bits as i32),
            Type::U32 => Const::U32(bits),
            Type::Bool => Const::Bool(bits != 0),
        };
        return Inst::Const { dst, value };
    }
    match inst {
        Inst::Select { dst, cond, a, b } if known(&cond) => Inst::Mov { dst, src: if env[&cond] != 0 { a } else { b } },
        other => other,
    }
}

/// The values both of two environments know alike.
fn intersect(a: Env, b: &Env) -> Env {
    a.into_iter().filter(|(r, v)| b.get(r) == Some(v)).collect()
}

/// Whether a statement ends the list it is in for every lane that runs it.
fn is_exit(s: &Stmt) -> bool {
    matches!(s, Stmt::Break | Stmt::Continue | Stmt::Return | Stmt::Discard)
}

/// Unrolls the loops of `stmts` and takes the `if`s on known conditions; `env` is updated
/// to after them.
fn unroll_block(cx: &mut Unroller, stmts: Vec<Stmt>, env: &mut Env) -> Vec<Stmt> {
    let mut out = Vec::with_capacity(stmts.len());
    for s in stmts {
        match s {
            Stmt::Inst(inst) => {
                cx.work = cx.work.saturating_sub(1);
                let inst = simplify(cx.types, inst, env);
                eval(&inst, env);
                out.push(Stmt::Inst(inst));
            }
            Stmt::If { cond, then, otherwise } => match env.get(&cond) {
                Some(&c) => {
                    let arm = unroll_block(cx, if c != 0 { then } else { otherwise }, env);
                    let exits = arm.last().is_some_and(is_exit);
                    out.extend(arm);
                    if exits {
                        return out;
                    }
                }
                None => {
                    let mut other = env.clone();
                    let then = unroll_block(cx, then, env);
                    let otherwise = unroll_block(cx, otherwise, &mut other);
                    // A side that left (its list ends in an exit) has no lanes after the if.
                    let then_exits = then.last().is_some_and(is_exit);
                    let otherwise_exits = otherwise.last().is_some_and(is_exit);
                    *env = match (then_exits, otherwise_exits) {
                        (true, false) => other,
                        (false, true) => std::mem::take(env),
                        _ => intersect(std::mem::take(env), &other),
                    };
                    out.push(Stmt::If { cond, then, otherwise });
                }
            },
            Stmt::Loop { body } => {
                let exits = unroll_loop(cx, body, env, &mut out);
                if exits {
                    return out;
                }
            }
            exit => {
                out.push(exit);
                return out;
            }
        }
    }
    out
}

/// Whether `stmts` hold a `break` or `continue` of their loop other than at their top level.
fn nested_loop_exit(stmts: &[Stmt]) -> bool {
    fn inside(stmts: &[Stmt]) -> bool {
        stmts.iter().any(|s| match s {
            Stmt::Break | Stmt::Continue => true,
            Stmt::If { then, otherwise, .. } => inside(then) || inside(otherwise),
            _ => false,
        })
    }
    stmts.iter().any(|s| match s {
        Stmt::If { then, otherwise, .. } => inside(then) || inside(otherwise),
        _ => false,
    })
}

fn count(stmts: &[Stmt]) -> usize {
    stmts
        .iter()
        .map(|s| match s {
            Stmt::If { then, otherwise, .. } => 1 + count(then) + count(otherwise),
            Stmt::Loop { body } => 1 + count(body),
            _ => 1,
        })
        .sum()
}

fn kill_writes(stmts: &[Stmt], env: &mut Env) {
    for s in stmts {
        match s {
            Stmt::Inst(inst) => {
                for r in inst.writes() {
                    env.remove(&r);
                }
            }
            Stmt::If { then, otherwise, .. } => {
                kill_writes(then, env);
                kill_writes(otherwise, env);
            }
            Stmt::Loop { body } => kill_writes(body, env),
            _ => {}
        }
    }
}

/// Appends loop `body` to `out`, unrolled if it can be (see the module docs); returns
/// whether every lane has left the program after it (an unrolled `return` or `discard`).
fn unroll_loop(cx: &mut Unroller, body: Vec<Stmt>, env: &mut Env, out: &mut Vec<Stmt>) -> bool {
    let mut copies = Vec::new();
    let mut state = env.clone();
    let iterations = if cx.work == 0 { 0 } else { MAX_UNROLLED_ITERATIONS };
    for _ in 0..iterations {
        let copy = unroll_block(cx, body.clone(), &mut state);
        if nested_loop_exit(&copy) {
            break;
        }
        let last = copy.last().cloned();
        copies.extend(copy.into_iter().filter(|s| !matches!(s, Stmt::Break | Stmt::Continue)));
        if count(&copies) > MAX_UNROLLED_STATEMENTS {
            break;
        }
        match last {
            Some(Stmt::Break) => {
                *env = state;
                out.extend(copies);
                return false;
            }
            Some(Stmt::Return | Stmt::Discard) => {
                out.extend(copies);
                return true;
            }
            _ => {}
        }
    }
    // Kept as a loop: its body sees any iteration's values.
    kill_writes(&body, env);
    let body = unroll_block(cx, body, &mut env.clone());
    out.push(Stmt::Loop { body });
    false
}

// ---- If-conversion -------------------------------------------------------------------

/// Whether an instruction only computes its register from registers, inputs and uniforms.
fn is_pure(inst: &Inst) -> bool {
    matches!(
        inst,
        Inst::Const { .. }
            | Inst::Input { .. }
            | Inst::Uniform { .. }
            | Inst::Mov { .. }
            | Inst::Unary { .. }
            | Inst::Binary { .. }
            | Inst::Mad { .. }
            | Inst::Dot { .. }
            | Inst::Select { .. }
    )
}

fn pure_arm(stmts: &[Stmt]) -> bool {
    stmts.iter().all(|s| matches!(s, Stmt::Inst(i) if is_pure(i)))
}

/// `inst` (pure) with its operands renamed by `names`, each operand shown to `seen` first.
fn rename_reads(inst: &mut Inst, names: &HashMap<Reg, Reg>, seen: &mut dyn FnMut(Reg)) {
    let mut name = |r: &mut Reg| {
        seen(*r);
        if let Some(&n) = names.get(r) {
            *r = n;
        }
    };
    match inst {
        Inst::Mov { src, .. } => name(src),
        Inst::Unary { a, .. } => name(a),
        Inst::Binary { a, b, .. } => {
            name(a);
            name(b);
        }
        Inst::Mad { a, b, c, .. } => {
            name(a);
            name(b);
            name(c);
        }
        Inst::Dot { n, a, b, .. } => {
            for k in 0..*n as usize {
                name(&mut a[k]);
                name(&mut b[k]);
            }
        }
        Inst::Select { cond, a, b, .. } => {
            name(cond);
            name(a);
            name(b);
        }
        _ => {}
    }
}

fn set_dst(inst: &mut Inst, to: Reg) {
    *inst.pure_dst_mut().expect("a pure instruction") = to;
}

/// An arm's instructions writing fresh registers, appended to `out`; returns the final
/// name of each register the arm writes, in the order of first writes.
fn rename_arm(program: &mut Program, arm: Vec<Stmt>, out: &mut Vec<Stmt>) -> Vec<(Reg, Reg)> {
    let mut names = HashMap::new();
    let mut order = Vec::new();
    for s in arm {
        let Stmt::Inst(mut inst) = s else { unreachable!("a pure arm") };
        rename_reads(&mut inst, &names, &mut |_| {});
        let dst = inst.dst().expect("a pure instruction writes a register");
        let fresh = program.register(program.registers[dst.0 as usize]);
        set_dst(&mut inst, fresh);
        if names.insert(dst, fresh).is_none() {
            order.push(dst);
        }
        out.push(Stmt::Inst(inst));
    }
    order.into_iter().map(|r| (r, names[&r])).collect()
}

/// Per register, whether its value is the same in every running lane wherever it is read:
/// every write of it is a pure instruction at the top level (run by every lane still
/// running; lanes that left by `discard` or `return` are gone for good) whose operands are
/// such registers (a constant or a uniform has none). A register nothing writes reads zero.
fn uniform_registers(registers: usize, body: &[Stmt]) -> Vec<bool> {
    fn nested_writes(stmts: &[Stmt], uniform: &mut [bool]) {
        for s in stmts {
            match s {
                Stmt::Inst(inst) => inst.writes().into_iter().for_each(|r| uniform[r.0 as usize] = false),
                Stmt::If { then, otherwise, .. } => {
                    nested_writes(then, uniform);
                    nested_writes(otherwise, uniform);
                }
                Stmt::Loop { body } => nested_writes(body, uniform),
                _ => {}
            }
        }
    }
    let mut uniform = vec![true; registers];
    for s in body {
        match s {
            Stmt::Inst(inst) if !is_pure(inst) || matches!(inst, Inst::Input { .. }) => {
                inst.writes().into_iter().for_each(|r| uniform[r.0 as usize] = false)
            }
            Stmt::If { then, otherwise, .. } => {
                nested_writes(then, &mut uniform);
                nested_writes(otherwise, &mut uniform);
            }
            Stmt::Loop { body } => nested_writes(body, &mut uniform),
            _ => {}
        }
    }
    // A write of a value computed from a register that is not uniform: to a fixed point.
    let mut changed = true;
    while changed {
        changed = false;
        for s in body {
            let Stmt::Inst(inst) = s else { continue };
            let Some(d) = inst.dst() else { continue };
            if uniform[d.0 as usize] && is_pure(inst) {
                let mut reads_varying = false;
                rename_reads(&mut inst.clone(), &HashMap::new(), &mut |r| reads_varying |= !uniform[r.0 as usize]);
                if reads_varying {
                    uniform[d.0 as usize] = false;
                    changed = true;
                }
            }
        }
    }
    uniform
}

/// Converts the pure `if`s of `stmts` into selects; `uniform` (at the top level: the
/// [`uniform_registers`], empty for none) keeps those on uniform conditions as `if`s.
fn convert_block(program: &mut Program, stmts: Vec<Stmt>, uniform: Option<&[bool]>) -> Vec<Stmt> {
    let mut out = Vec::with_capacity(stmts.len());
    for s in stmts {
        match s {
            Stmt::If { cond, then, otherwise } => {
                let then = convert_block(program, then, None);
                let otherwise = convert_block(program, otherwise, None);
                let uniform_condition = uniform.is_some_and(|u| u.get(cond.0 as usize) == Some(&true));
                if !uniform_condition
                    && pure_arm(&then)
                    && pure_arm(&otherwise)
                    && then.len() + otherwise.len() <= MAX_CONVERTED_INSTRUCTIONS
                {
                    let then_names = rename_arm(program, then, &mut out);
                    let otherwise_names = rename_arm(program, otherwise, &mut out);
                    let mut written: Vec<Reg> = then_names.iter().chain(&otherwise_names).map(|&(r, _)| r).collect();
                    written.sort();
                    written.dedup();
                    // The condition's own select last: the others read its old value.
                    if let Some(k) = written.iter().position(|&r| r == cond) {
                        let c = written.remove(k);
                        written.push(c);
                    }
                    let find = |names: &[(Reg, Reg)], r: Reg| names.iter().find(|n| n.0 == r).map_or(r, |n| n.1);
                    for r in written {
                        let (a, b) = (find(&then_names, r), find(&otherwise_names, r));
                        out.push(Stmt::Inst(Inst::Select { dst: r, cond, a, b }));
                    }
                } else {
                    out.push(Stmt::If { cond, then, otherwise });
                }
            }
            Stmt::Loop { body } => out.push(Stmt::Loop { body: convert_block(program, body, None) }),
            other => out.push(other),
        }
    }
    out
}
