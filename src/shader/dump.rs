//! The text form of a program, for people: what `TESSERA_DEBUG=programs` prints when a
//! program is built, and what the tests show when a program misbehaves. One statement per
//! line, registers as `r<n>`, nested blocks indented.
//!
//! ```text
//! fragment program: 3 registers, inputs [f32], uniforms [f32], outputs [f32]
//!   r0 = input 0            ; f32
//!   r1 = fmul r0, r0        ; f32
//!   if r2 {
//!     discard
//!   }
//!   output 0 = r1
//! ```
use super::ir::{Axis, Const, Inst, Lod, Program, Reg, Stage, Stmt, Type};
use std::fmt::{self, Write};

fn types(list: &[Type]) -> String {
    let names: Vec<&str> = list.iter().map(|t| t.name()).collect();
    format!("[{}]", names.join(" "))
}

fn constant(c: Const) -> String {
    match c {
        // The bits too, so that -0.0, NaN payloads and denormals are visible.
        Const::F32(v) => format!("{v:?} (0x{:08x})", v.to_bits()),
        Const::I32(v) => format!("{v}i"),
        Const::U32(v) => format!("{v}u"),
        Const::Bool(v) => format!("{v}"),
    }
}

/// Registers as `r1 r2 r3`.
fn regs(list: &[Reg]) -> String {
    list.iter().map(|r| format!("r{}", r.0)).collect::<Vec<_>>().join(" ")
}

fn lower<T: fmt::Debug>(op: T) -> String {
    format!("{op:?}").to_lowercase()
}

fn inst(out: &mut String, inst: &Inst) -> fmt::Result {
    match inst {
        Inst::Const { dst, value } => write!(out, "r{} = {}", dst.0, constant(*value)),
        Inst::Input { dst, slot } => write!(out, "r{} = input {slot}", dst.0),
        Inst::Uniform { dst, slot } => write!(out, "r{} = uniform {slot}", dst.0),
        Inst::Mov { dst, src } => write!(out, "r{} = r{}", dst.0, src.0),
        Inst::Unary { op, dst, a } => write!(out, "r{} = {} r{}", dst.0, lower(op), a.0),
        Inst::Binary { op, dst, a, b } => write!(out, "r{} = {} r{}, r{}", dst.0, lower(op), a.0, b.0),
        Inst::Mad { dst, a, b, c } => write!(out, "r{} = mad r{}, r{}, r{}", dst.0, a.0, b.0, c.0),
        Inst::Dot { dst, n, a, b } => {
            write!(out, "r{} = dot{n} ({}), ({})", dst.0, regs(&a[..*n as usize]), regs(&b[..*n as usize]))
        }
        Inst::Select { dst, cond, a, b } => write!(out, "r{} = select r{}, r{}, r{}", dst.0, cond.0, a.0, b.0),
        Inst::Derivative { dst, axis, a } => {
            let name = match axis {
                Axis::X => "ddx",
                Axis::Y => "ddy",
            };
            write!(out, "r{} = {name} r{}", dst.0, a.0)
        }
        Inst::Output { slot, src } => write!(out, "output {slot} = r{}", src.0),
        Inst::Sample { dst, unit, n, coords, projective, lod, compare } => {
            let used = *n as usize + *projective as usize;
            write!(
                out,
                "{} = sample{} unit {unit} ({})",
                regs(dst),
                if *projective { "proj" } else { "" },
                regs(&coords[..used])
            )?;
            match lod {
                Lod::Implicit => {}
                Lod::Bias(r) => write!(out, " bias r{}", r.0)?,
                Lod::Explicit(r) => write!(out, " lod r{}", r.0)?,
            }
            match compare {
                Some(r) => write!(out, " compare r{}", r.0),
                None => Ok(()),
            }
        }
        Inst::Fetch { dst, unit, n, coords, lod } => {
            write!(out, "{} = fetch unit {unit} ({}) lod r{}", regs(dst), regs(&coords[..*n as usize]), lod.0)
        }
        Inst::Size { dst, unit, lod } => write!(out, "{} = size unit {unit} lod r{}", regs(dst), lod.0),
    }
}

fn block(out: &mut String, program: &Program, stmts: &[Stmt], depth: usize) -> fmt::Result {
    let pad = "  ".repeat(depth + 1);
    for stmt in stmts {
        out.push_str(&pad);
        match stmt {
            Stmt::Inst(i) => {
                let start = out.len();
                inst(out, i)?;
                if let Some(&dst) = i.writes().first() {
                    let width = out.len() - start;
                    let ty = program.registers.get(dst.0 as usize).map_or("?", |t| t.name());
                    write!(out, "{:1$}; {ty}", "", 24usize.saturating_sub(width).max(1))?;
                }
            }
            Stmt::If { cond, then, otherwise } => {
                writeln!(out, "if r{} {{", cond.0)?;
                block(out, program, then, depth + 1)?;
                if !otherwise.is_empty() {
                    writeln!(out, "{pad}}} else {{")?;
                    block(out, program, otherwise, depth + 1)?;
                }
                out.push_str(&pad);
                out.push('}');
            }
            Stmt::Loop { body } => {
                writeln!(out, "loop {{")?;
                block(out, program, body, depth + 1)?;
                out.push_str(&pad);
                out.push('}');
            }
            Stmt::Break => out.push_str("break"),
            Stmt::Continue => out.push_str("continue"),
            Stmt::Return => out.push_str("return"),
            Stmt::Discard => out.push_str("discard"),
        }
        out.push('\n');
    }
    Ok(())
}

/// The text form of `program` (see the module docs).
pub fn dump(program: &Program) -> String {
    let stage = match program.stage {
        Stage::Vertex => "vertex",
        Stage::Fragment => "fragment",
    };
    let mut out = format!(
        "{stage} program: {} registers, inputs {}, uniforms {}, outputs {}\n",
        program.registers.len(),
        types(&program.inputs),
        types(&program.uniforms),
        types(&program.outputs)
    );
    // Writing into a String cannot fail.
    let _ = block(&mut out, program, &program.body, 0);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shader::ir::{BinaryOp, Inst, Type};

    #[test]
    fn a_program_reads_as_its_statements() {
        let mut p = Program::new(Stage::Fragment);
        let x = p.register(Type::F32);
        let y = p.register(Type::F32);
        let b = p.register(Type::Bool);
        p.input(Type::F32);
        p.output(Type::F32);
        p.body = vec![
            Stmt::Inst(Inst::Input { dst: x, slot: 0 }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FMul, dst: y, a: x, b: x }),
            Stmt::Inst(Inst::Const { dst: x, value: Const::F32(-0.0) }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FLt, dst: b, a: y, b: x }),
            Stmt::If { cond: b, then: vec![Stmt::Discard], otherwise: vec![Stmt::Return] },
            Stmt::Loop { body: vec![Stmt::Break] },
            Stmt::Inst(Inst::Output { slot: 0, src: y }),
        ];
        let text = dump(&p);
        let expected = "fragment program: 3 registers, inputs [f32], uniforms [], outputs [f32]
  r0 = input 0            ; f32
  r1 = fmul r0, r0        ; f32
  r0 = -0.0 (0x80000000)  ; f32
  r2 = flt r1, r0         ; bool
  if r2 {
    discard
  } else {
    return
  }
  loop {
    break
  }
  output 0 = r1
";
        assert_eq!(text, expected);
    }
}
