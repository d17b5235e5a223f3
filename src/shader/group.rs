//! Groups of lane operations: [`group`] rewrites each run of [`Code`] so that up to four
//! consecutive operations of one kind (add, subtract, multiply, select, negate: a `vec4`'s
//! components, as the GLSL front end writes them one after another) are one [`Op::Group`],
//! which [`super::fast`]'s interpreter dispatches once and runs as a loop over its
//! components.
//!
//! **Why.** After [`super::flatten`] and [`super::lower`], phong's fragment program runs
//! ~126 vector operations per block, 36 multiplications, 32 additions and 16 selects of
//! them in fours (a light's colour products and sums, the specular `if` converted to
//! selects); each dispatch costs about 8 instructions and each operation's store about 5
//! more, out of some 33 for a multiplication. A group pays them once.
//!
//! **Same bits.** A group runs its operations in their order, each writing its register
//! before the next reads its operands, with the interpreter's own lane functions: exactly
//! the sequence it replaces, whatever the registers (an operation may read what an earlier
//! one of the group wrote). Only consecutive operations of one run are grouped, so the
//! masks and the control tree are unchanged. Only registers below [`FILE`] are grouped (the
//! interpreter reads a group's registers from a fixed array, without bounds checks). Which
//! paths use it: [`super::fast::Compiled`]'s
//! runs of the control tree; not the bound forms, whose own fusions look for single
//! operations ([`super::fast::Compiled::bind`], [`super::fast::Compiled::bind_run`]).
use super::fast::FILE;
use super::ir::UnaryOp;
use super::lower::{Code, GroupKind, Node, Op, Wide, R};

/// The most operations of a group.
const MAX_GROUP: usize = 4;

/// An operation's place in a group: its kind and operands (`c` for a select's condition).
fn member(op: &Op) -> Option<(GroupKind, R, R, R, R)> {
    Some(match *op {
        Op::Add { d, a, b } => (GroupKind::Add, d, a, b, 0),
        Op::Sub { d, a, b } => (GroupKind::Sub, d, a, b, 0),
        Op::Mul { d, a, b } => (GroupKind::Mul, d, a, b, 0),
        Op::Select { d, c, a, b } => (GroupKind::Select, d, a, b, c),
        Op::Unary { op: UnaryOp::FNeg, d, a } => (GroupKind::Neg, d, a, a, 0),
        _ => return None,
    })
}

/// `code` with its consecutive operations of one kind grouped (see the module docs).
pub fn group(code: &Code) -> Code {
    let mut ops = Vec::with_capacity(code.ops.len());
    let mut wide = code.wide.clone();
    let body = nodes(code, &code.body, &mut ops, &mut wide);
    Code { registers: code.registers, zeroed: code.zeroed.clone(), ops, wide, body }
}

fn nodes(code: &Code, list: &[Node], ops: &mut Vec<Op>, wide: &mut Vec<Wide>) -> Vec<Node> {
    list.iter()
        .map(|node| match node {
            &Node::Run { start, end, masked } => {
                let begin = ops.len() as u32;
                run(&code.ops[start as usize..end as usize], ops, wide);
                Node::Run { start: begin, end: ops.len() as u32, masked }
            }
            Node::If { cond, then, otherwise } => Node::If {
                cond: *cond,
                then: nodes(code, then, ops, wide),
                otherwise: nodes(code, otherwise, ops, wide),
            },
            Node::Loop { body } => Node::Loop { body: nodes(code, body, ops, wide) },
            other => other.clone(),
        })
        .collect()
}

/// Appends the run `run` to `ops`, grouped.
fn run(run: &[Op], ops: &mut Vec<Op>, wide: &mut Vec<Wide>) {
    let mut k = 0;
    while k < run.len() {
        let Some((kind, ..)) = member(&run[k]) else {
            ops.push(run[k]);
            k += 1;
            continue;
        };
        // Registers below [`FILE`] only: the interpreter indexes a group's by a byte.
        let small = |r: R| (r as usize) < FILE;
        let n = run[k..]
            .iter()
            .take(MAX_GROUP)
            .take_while(|op| {
                member(op).is_some_and(|(kind2, d, a, b, c)| kind2 == kind && [d, a, b, c].into_iter().all(small))
            })
            .count();
        // The wide index is 16 bits: past it, the operations stay single.
        if n < 2 || wide.len() > u16::MAX as usize {
            ops.push(run[k]);
            k += 1;
            continue;
        }
        let (mut d, mut a, mut b, mut c) = ([0; 4], [0; 4], [0; 4], [0; 4]);
        for (j, op) in run[k..k + n].iter().enumerate() {
            let (_, dj, aj, bj, cj) = member(op).expect("a member of the group");
            (d[j], a[j], b[j], c[j]) = (dj, aj, bj, cj);
        }
        ops.push(Op::Group(wide.len() as u16));
        wide.push(Wide::Group { kind, n: n as u8, d, a, b, c });
        k += n;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_consecutive_operations_of_one_kind_and_keeps_the_rest() {
        let ops = vec![
            Op::Mul { d: 1, a: 0, b: 0 },
            Op::Mul { d: 2, a: 1, b: 0 },
            Op::Add { d: 3, a: 2, b: 1 },
            Op::Mul { d: 4, a: 3, b: 3 },
            Op::Mul { d: 5, a: 4, b: 3 },
            Op::Mul { d: 6, a: 5, b: 3 },
            Op::Mul { d: 7, a: 6, b: 3 },
            Op::Mul { d: 8, a: 7, b: 3 },
            Op::Select { d: 9, c: 1, a: 2, b: 3 },
            Op::Select { d: 10, c: 1, a: 3, b: 2 },
        ];
        let code = Code {
            registers: 11,
            zeroed: vec![],
            ops: ops.clone(),
            wide: vec![],
            body: vec![Node::Run { start: 0, end: 2, masked: false }, Node::Run { start: 2, end: 10, masked: true }],
        };
        let grouped = group(&code);
        // Two multiplications (the first run); an addition alone; four multiplications (at
        // most four), one alone; two selects.
        assert_eq!(grouped.ops.len(), 5, "{:?}", grouped.ops);
        assert_eq!(grouped.ops[1], Op::Add { d: 3, a: 2, b: 1 });
        assert_eq!(grouped.ops[3], Op::Mul { d: 8, a: 7, b: 3 });
        assert_eq!(
            grouped.body,
            vec![Node::Run { start: 0, end: 1, masked: false }, Node::Run { start: 1, end: 5, masked: true }]
        );
        assert_eq!(
            grouped.wide[1],
            Wide::Group { kind: GroupKind::Mul, n: 4, d: [4, 5, 6, 7], a: [3, 4, 5, 6], b: [3; 4], c: [0; 4] }
        );
        assert_eq!(
            grouped.wide[2],
            Wide::Group {
                kind: GroupKind::Select,
                n: 2,
                d: [9, 10, 0, 0],
                a: [2, 3, 0, 0],
                b: [3, 2, 0, 0],
                c: [1, 1, 0, 0]
            }
        );
    }
}
