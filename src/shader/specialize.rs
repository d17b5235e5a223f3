//! Per-draw specialisation of a program on its uniform values: [`specialize`] takes the
//! prepared form of a program ([`super::lower::split_prologue`]: the uniform prologue and
//! the rest) and the draw's uniform words, and returns the words the program's uniform
//! values leave in the register file and the rest with every operation those values
//! decide done once, here, instead of per block.
//!
//! **Why.** A GLSL program often selects on a uniform: phong's `p.w == 0.0 ? normalize(p.xyz)
//! : normalize(p.xyz - position)` per light, a ternary the front end makes a `select` of both
//! arms (a directional light's positional arm — a subtraction, a normalize, a length, a
//! division — ran per block for nothing, and the directional arm's products of uniforms were
//! vector operations because the select made them per block). The condition is known once
//! the draw's uniforms are: the select becomes a copy of its arm, the copy disappears, and
//! what the other arm computed is dead.
//!
//! **What it does**, on the top-level unmasked runs of the rest (where every operation runs
//! exactly once per block, in every running lane), to registers written once and read only
//! after their write (not zeroed per run):
//! - an operation of the lanes whose operands are all known values is computed here — by
//!   the interpreter itself, over broadcast words, so with its very bits — and its result
//!   becomes a known value;
//! - a select on a known condition becomes a copy of the arm it takes;
//! - a product by a known 1.0 of a value an arithmetic operation computed becomes a copy
//!   (x·1 is x exactly, NaN included: an arithmetic result is never a signalling NaN);
//! - a copy of a register written once is replaced by that register in every read;
//! - then the operations whose results nothing reads are dropped (texture lookups and
//!   outputs stay).
//!
//! Each step keeps every value any remaining operation reads, so the specialised code gives
//! the bits of the code it came from in every lane (the tests run both on random programs).
use super::lower::{op_writes, Code, Cond, Node, Op, Wide, R};

/// The result of [`specialize`]: the known words and the code left to run per block.
#[derive(Clone, Debug)]
pub struct Specialized {
    /// Each known register and its word: written once per draw into the register file, in
    /// place of the prologue.
    pub known: Vec<(R, [u32; 16])>,
    /// The rest, specialised (not grouped: its caller groups it).
    pub code: Code,
}

/// How [`specialize`] runs operations: `evaluate(ops, file, uniforms, wide)`.
pub type Evaluate<'a> = dyn FnMut(&[Op], &mut super::fast::Registers, &[u32], &[Wide]) + 'a;

/// Whether `op` computes its results from its operands alone, lane by lane: with known
/// operands, its results are known (and nothing else notices it ran or not).
fn lane_wise(op: &Op) -> bool {
    !matches!(op, Op::Input { .. } | Op::Output { .. } | Op::Texture(_) | Op::Derivative { .. } | Op::Group(_))
}

/// Whether `op`'s result is an arithmetic operation's, never a signalling NaN: a product of
/// it by 1.0 is itself.
fn arithmetic(op: &Op) -> bool {
    matches!(
        op,
        Op::Add { .. }
            | Op::Sub { .. }
            | Op::Mul { .. }
            | Op::Div { .. }
            | Op::Mad { .. }
            | Op::Dot2 { .. }
            | Op::Dot3 { .. }
            | Op::Dot4 { .. }
            | Op::Sqrt { .. }
            | Op::Rsq { .. }
            | Op::MatRow { .. }
            | Op::Pow { .. }
    )
}

/// The registers a condition of the control tree reads, counted into `reads`.
fn count_conditions(nodes: &[Node], reads: &mut [u32]) {
    for node in nodes {
        match node {
            Node::If { cond: Cond::Lanes(r) | Cond::Uniform(r), then, otherwise } => {
                reads[*r as usize] += 1;
                count_conditions(then, reads);
                count_conditions(otherwise, reads);
            }
            Node::Loop { body } => count_conditions(body, reads),
            _ => {}
        }
    }
}

fn rename_conditions(nodes: &mut [Node], alias: &[R]) {
    for node in nodes {
        match node {
            Node::If { cond: Cond::Lanes(r) | Cond::Uniform(r), then, otherwise } => {
                *r = alias[*r as usize];
                rename_conditions(then, alias);
                rename_conditions(otherwise, alias);
            }
            Node::Loop { body } => rename_conditions(body, alias),
            _ => {}
        }
    }
}

/// The control tree over the kept operations (`count_before[k]`: how many operations before
/// operation k are kept).
fn rebuild(nodes: &[Node], count_before: &[u32]) -> Vec<Node> {
    let mut out = Vec::with_capacity(nodes.len());
    for node in nodes {
        match node {
            &Node::Run { start, end, masked } => {
                let (start, end) = (count_before[start as usize], count_before[end as usize]);
                if start < end {
                    out.push(Node::Run { start, end, masked });
                }
            }
            Node::If { cond, then, otherwise } => out.push(Node::If {
                cond: *cond,
                then: rebuild(then, count_before),
                otherwise: rebuild(otherwise, count_before),
            }),
            Node::Loop { body } => out.push(Node::Loop { body: rebuild(body, count_before) }),
            other => out.push(other.clone()),
        }
    }
    out
}

/// Specialises `rest` (after `prologue`, [`super::lower::split_prologue`]'s) on `uniforms`
/// (see the module docs). `evaluate(ops, file, wide)` runs `ops` on the words `file` as the
/// interpreter does, every lane running, unmasked.
pub fn specialize(prologue: &[Op], rest: &Code, uniforms: &[u32], evaluate: &mut Evaluate<'_>) -> Specialized {
    let n = rest.registers;
    let mut writes = vec![0u32; n];
    for op in prologue.iter().chain(&rest.ops) {
        let (d, count) = op_writes(op, &rest.wide);
        for &r in &d[..count] {
            writes[r as usize] += 1;
        }
    }
    let mut zeroed = vec![false; n];
    for &r in &rest.zeroed {
        zeroed[r as usize] = true;
    }
    // Written once, and every read after the write.
    let single = |r: R| writes[r as usize] == 1 && !zeroed[r as usize];
    let mut file = super::fast::Registers::new();
    file.words_resize(n.max(super::fast::FILE));
    evaluate(prologue, &mut file, uniforms, &rest.wide);
    let mut known = vec![false; n];
    for op in prologue {
        let (d, count) = op_writes(op, &rest.wide);
        for &r in &d[..count] {
            known[r as usize] = true;
        }
    }
    // The operation that writes each register written once.
    let mut definition: Vec<Option<Op>> = vec![None; n];
    for op in &rest.ops {
        let (d, count) = op_writes(op, &rest.wide);
        for &r in &d[..count] {
            if single(r) {
                definition[r as usize] = Some(*op);
            }
        }
    }
    let mut ops: Vec<Option<Op>> = rest.ops.iter().map(|&op| Some(op)).collect();
    let mut wide = rest.wide.clone();
    let one = [1f32.to_bits(); 16];
    for node in &rest.body {
        let &Node::Run { start, end, masked: false } = node else { continue };
        for slot in &mut ops[start as usize..end as usize] {
            let Some(mut op) = *slot else { continue };
            let is_known = |r: R, known: &[bool]| known[r as usize];
            match op {
                Op::Select { d, c, a, b } if is_known(c, &known) => {
                    let taken = if file.words()[c as usize][0] != 0 { a } else { b };
                    op = Op::Mov { d, a: taken };
                }
                Op::Mul { d, a, b } => {
                    for (x, y) in [(a, b), (b, a)] {
                        let by_one = is_known(y, &known) && file.words()[y as usize] == one;
                        if by_one
                            && !is_known(x, &known)
                            && single(x)
                            && definition[x as usize].is_some_and(|o| arithmetic(&o))
                        {
                            op = Op::Mov { d, a: x };
                            break;
                        }
                    }
                }
                _ => {}
            }
            let (d, count) = op_writes(&op, &wide);
            let mut operands_known = true;
            super::fast::reads_mut(&mut op, &mut wide, &mut |r| operands_known &= known[*r as usize]);
            if lane_wise(&op) && operands_known && d[..count].iter().all(|&r| single(r)) {
                evaluate(std::slice::from_ref(&op), &mut file, uniforms, &wide);
                for &r in &d[..count] {
                    known[r as usize] = true;
                }
                *slot = None;
            } else {
                *slot = Some(op);
            }
        }
    }
    // Copies of registers written once: their reads read the original.
    let mut alias: Vec<R> = (0..n as R).collect();
    for node in &rest.body {
        let &Node::Run { start, end, masked: false } = node else { continue };
        for slot in &mut ops[start as usize..end as usize] {
            if let Some(Op::Mov { d, a }) = *slot {
                if single(d) && single(a) && !known[a as usize] {
                    alias[d as usize] = alias[a as usize];
                    *slot = None;
                }
            }
        }
    }
    for op in ops.iter_mut().flatten() {
        super::fast::reads_mut(op, &mut wide, &mut |r| *r = alias[*r as usize]);
    }
    let mut body = rest.body.clone();
    rename_conditions(&mut body, &alias);
    // Dead operations, until none is left.
    loop {
        let mut reads = vec![0u32; n];
        count_conditions(&body, &mut reads);
        for op in ops.iter_mut().flatten() {
            super::fast::reads_mut(op, &mut wide, &mut |r| reads[*r as usize] += 1);
        }
        let mut changed = false;
        for slot in &mut ops {
            let Some(op) = slot else { continue };
            let (d, count) = op_writes(op, &wide);
            let pure = lane_wise(op) || matches!(op, Op::Input { .. } | Op::Derivative { .. });
            if pure && count > 0 && d[..count].iter().all(|&r| reads[r as usize] == 0) {
                *slot = None;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    let mut count_before = Vec::with_capacity(ops.len() + 1);
    let mut new_ops = Vec::with_capacity(ops.len());
    for slot in &ops {
        count_before.push(new_ops.len() as u32);
        if let Some(op) = slot {
            new_ops.push(*op);
        }
    }
    count_before.push(new_ops.len() as u32);
    let body = rebuild(&body, &count_before);
    let known_words = (0..n).filter(|&r| known[r]).map(|r| (r as R, file.words()[r])).collect();
    Specialized {
        known: known_words,
        code: Code { registers: n, zeroed: rest.zeroed.clone(), ops: new_ops, wide, body },
    }
}
