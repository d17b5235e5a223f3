//! The validator: checks a program before it runs, so that the executor can trust it
//! (registers and slots in range, every operand of the type its opcode names, `break` and
//! `continue` only inside a loop, `discard` and derivatives only in fragment programs,
//! nesting no deeper than [`MAX_NESTING`]). Generators and the GLSL front end call it
//! after building a program; an error names the statement by its path.
use super::ir::{BinaryOp, Inst, Lod, Program, Reg, Stage, Stmt, Type, UnaryOp, MAX_SAMPLERS};
use std::fmt;

/// The deepest nesting of ifs and loops a program may have: the executor recurses once per
/// level, and GLSL programs nest far less (this bounds its stack use).
pub const MAX_NESTING: usize = 256;

/// Why a program is not valid, and where: the indices of the statements from the body
/// down (`then` blocks count their statements first, then the `otherwise` block's follow).
#[derive(Clone, Debug, PartialEq)]
pub struct Invalid {
    pub path: Vec<usize>,
    pub reason: String,
}

impl fmt::Display for Invalid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let path: Vec<String> = self.path.iter().map(|i| i.to_string()).collect();
        write!(f, "statement {}: {}", path.join("."), self.reason)
    }
}

/// The operand types and the result type of a unary operation, `None` for operations that
/// accept more than one type (`INot`, `Bitcast`: checked by the caller).
fn unary_signature(op: UnaryOp) -> Option<(Type, Type)> {
    use Type::*;
    use UnaryOp::*;
    Some(match op {
        FNeg | FAbs | FSign | Floor | Ceil | Trunc | Fract | RoundEven | Sqrt | Rcp | Rsq | Exp2 | Exp | Log2 | Sin
        | Cos => (F32, F32),
        F32ToI32 => (F32, I32),
        F32ToU32 => (F32, U32),
        I32ToF32 => (I32, F32),
        U32ToF32 => (U32, F32),
        BoolToF32 => (Bool, F32),
        F32ToBool => (F32, Bool),
        INeg | IAbs => (I32, I32),
        BNot => (Bool, Bool),
        INot | Bitcast => return None,
    })
}

/// The operand type and the result type of a binary operation, `None` for the integer
/// operations that accept i32 or u32 (checked by the caller).
fn binary_signature(op: BinaryOp) -> Option<(Type, Type)> {
    use BinaryOp::*;
    use Type::*;
    Some(match op {
        FAdd | FSub | FMul | FDiv | FMin | FMax => (F32, F32),
        FLt | FLe | FEq | FNe => (F32, Bool),
        IAdd | ISub | IMul | IDiv | IRem | IMin | IMax => (I32, I32),
        UDiv | URem | UMin | UMax => (U32, U32),
        AShr => (I32, I32),
        LShr => (U32, U32),
        ILt | ILe => (I32, Bool),
        ULt | ULe => (U32, Bool),
        BAnd | BOr | BXor | BEq => (Bool, Bool),
        IEq | INe | And | Or | Xor | Shl => return None,
    })
}

struct Checker<'a> {
    program: &'a Program,
    path: Vec<usize>,
}

impl Checker<'_> {
    fn fail<T>(&self, reason: String) -> Result<T, Invalid> {
        Err(Invalid { path: self.path.clone(), reason })
    }

    fn reg(&self, r: Reg) -> Result<Type, Invalid> {
        match self.program.registers.get(r.0 as usize) {
            Some(&ty) => Ok(ty),
            None => self.fail(format!("register r{} does not exist", r.0)),
        }
    }

    fn expect(&self, r: Reg, ty: Type) -> Result<(), Invalid> {
        let actual = self.reg(r)?;
        if actual != ty {
            return self.fail(format!("r{} is {}, expected {}", r.0, actual.name(), ty.name()));
        }
        Ok(())
    }

    fn integer(&self, r: Reg) -> Result<Type, Invalid> {
        let ty = self.reg(r)?;
        if !matches!(ty, Type::I32 | Type::U32) {
            return self.fail(format!("r{} is {}, expected an integer", r.0, ty.name()));
        }
        Ok(ty)
    }

    fn slot(&self, slots: &[Type], slot: u16, what: &str) -> Result<Type, Invalid> {
        match slots.get(slot as usize) {
            Some(&ty) => Ok(ty),
            None => self.fail(format!("{what} {slot} does not exist ({} declared)", slots.len())),
        }
    }

    fn unit(&self, unit: u8) -> Result<(), Invalid> {
        if unit as usize >= MAX_SAMPLERS {
            return self.fail(format!("texture unit {unit} (at most {MAX_SAMPLERS})"));
        }
        Ok(())
    }

    fn components(&self, n: u8, most: u8) -> Result<(), Invalid> {
        if !(1..=most).contains(&n) {
            return self.fail(format!("{n} coordinates (1 to {most})"));
        }
        Ok(())
    }

    fn inst(&self, inst: &Inst) -> Result<(), Invalid> {
        match *inst {
            Inst::Const { dst, value } => self.expect(dst, value.ty()),
            Inst::Input { dst, slot } => self.expect(dst, self.slot(&self.program.inputs, slot, "input")?),
            Inst::Uniform { dst, slot } => self.expect(dst, self.slot(&self.program.uniforms, slot, "uniform")?),
            Inst::Output { slot, src } => self.expect(src, self.slot(&self.program.outputs, slot, "output")?),
            Inst::Mov { dst, src } => self.expect(dst, self.reg(src)?),
            Inst::Unary { op, dst, a } => match unary_signature(op) {
                Some((operand, result)) => {
                    self.expect(a, operand)?;
                    self.expect(dst, result)
                }
                None if op == UnaryOp::INot => self.expect(dst, self.integer(a)?),
                None => {
                    let from = self.integer(a)?;
                    self.expect(dst, if from == Type::I32 { Type::U32 } else { Type::I32 })
                }
            },
            Inst::Binary { op, dst, a, b } => match binary_signature(op) {
                Some((operand, result)) => {
                    self.expect(a, operand)?;
                    self.expect(b, operand)?;
                    self.expect(dst, result)
                }
                None => {
                    let ty = self.integer(a)?;
                    self.expect(b, ty)?;
                    let result = if matches!(op, BinaryOp::IEq | BinaryOp::INe) { Type::Bool } else { ty };
                    self.expect(dst, result)
                }
            },
            Inst::Mad { dst, a, b, c } => {
                for r in [dst, a, b, c] {
                    self.expect(r, Type::F32)?;
                }
                Ok(())
            }
            Inst::Dot { dst, n, a, b } => {
                if !(2..=4).contains(&n) {
                    return self.fail(format!("dot of {n} components"));
                }
                self.expect(dst, Type::F32)?;
                for i in 0..n as usize {
                    self.expect(a[i], Type::F32)?;
                    self.expect(b[i], Type::F32)?;
                }
                Ok(())
            }
            Inst::Select { dst, cond, a, b } => {
                self.expect(cond, Type::Bool)?;
                let ty = self.reg(a)?;
                self.expect(b, ty)?;
                self.expect(dst, ty)
            }
            Inst::Sample { dst, unit, n, coords, projective, lod, compare } => {
                self.unit(unit)?;
                self.components(n, 3)?;
                let used = n as usize + projective as usize;
                for r in dst.into_iter().chain(coords[..used].iter().copied()).chain(compare) {
                    self.expect(r, Type::F32)?;
                }
                match lod {
                    Lod::Implicit | Lod::Bias(_) if self.program.stage != Stage::Fragment => {
                        self.fail("an implicit level of detail outside a fragment program".into())
                    }
                    Lod::Implicit => Ok(()),
                    Lod::Bias(r) | Lod::Explicit(r) => self.expect(r, Type::F32),
                }
            }
            Inst::Fetch { dst, unit, n, coords, lod } => {
                self.unit(unit)?;
                self.components(n, 3)?;
                for r in dst {
                    self.expect(r, Type::F32)?;
                }
                for &r in coords[..n as usize].iter().chain([&lod]) {
                    self.expect(r, Type::I32)?;
                }
                Ok(())
            }
            Inst::Size { dst, unit, lod } => {
                self.unit(unit)?;
                for r in dst.into_iter().chain([lod]) {
                    self.expect(r, Type::I32)?;
                }
                Ok(())
            }
            Inst::Derivative { dst, a, .. } => {
                if self.program.stage != Stage::Fragment {
                    return self.fail("a derivative outside a fragment program".into());
                }
                self.expect(a, Type::F32)?;
                self.expect(dst, Type::F32)
            }
        }
    }

    fn block(&mut self, stmts: &[Stmt], loops: usize, depth: usize, first_index: usize) -> Result<(), Invalid> {
        if depth > MAX_NESTING {
            return self.fail(format!("nested deeper than {MAX_NESTING} levels"));
        }
        for (i, stmt) in stmts.iter().enumerate() {
            self.path.push(first_index + i);
            match stmt {
                Stmt::Inst(inst) => self.inst(inst)?,
                Stmt::If { cond, then, otherwise } => {
                    self.expect(*cond, Type::Bool)?;
                    self.block(then, loops, depth + 1, 0)?;
                    self.block(otherwise, loops, depth + 1, then.len())?;
                }
                Stmt::Loop { body } => self.block(body, loops + 1, depth + 1, 0)?,
                Stmt::Break | Stmt::Continue if loops == 0 => {
                    return self.fail(format!("{stmt:?} outside a loop").to_lowercase());
                }
                Stmt::Discard if self.program.stage != Stage::Fragment => {
                    return self.fail("discard outside a fragment program".into());
                }
                Stmt::Break | Stmt::Continue | Stmt::Return | Stmt::Discard => {}
            }
            self.path.pop();
        }
        Ok(())
    }
}

/// Checks `program` (see the module docs).
pub fn validate(program: &Program) -> Result<(), Invalid> {
    if program.registers.len() > u32::MAX as usize
        || program.inputs.len() > u16::MAX as usize
        || program.uniforms.len() > u16::MAX as usize
        || program.outputs.len() > u16::MAX as usize
    {
        return Err(Invalid { path: Vec::new(), reason: "too many registers or slots".into() });
    }
    Checker { program, path: Vec::new() }.block(&program.body, 0, 0, 0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shader::ir::Const;

    fn program() -> (Program, Reg, Reg) {
        let mut p = Program::new(Stage::Vertex);
        let f = p.register(Type::F32);
        let b = p.register(Type::Bool);
        p.input(Type::F32);
        p.output(Type::F32);
        (p, f, b)
    }

    #[test]
    fn a_well_typed_program_passes() {
        let (mut p, f, b) = program();
        p.body = vec![
            Stmt::Inst(Inst::Input { dst: f, slot: 0 }),
            Stmt::Inst(Inst::Binary { op: BinaryOp::FLt, dst: b, a: f, b: f }),
            Stmt::Loop { body: vec![Stmt::If { cond: b, then: vec![Stmt::Break], otherwise: vec![Stmt::Continue] }] },
            Stmt::Inst(Inst::Output { slot: 0, src: f }),
        ];
        assert_eq!(validate(&p), Ok(()));
    }

    #[test]
    fn mistakes_are_found_with_their_place() {
        let (mut p, f, b) = program();
        p.body = vec![Stmt::If {
            cond: b,
            then: vec![],
            otherwise: vec![Stmt::Inst(Inst::Binary { op: BinaryOp::FAdd, dst: b, a: f, b: f })],
        }];
        let err = validate(&p).unwrap_err();
        assert_eq!(err.path, vec![0, 0]);
        assert!(err.reason.contains("expected f32"), "{err}");

        let cases: Vec<(Vec<Stmt>, &str)> = vec![
            (vec![Stmt::Break], "outside a loop"),
            (vec![Stmt::Discard], "discard outside"),
            (vec![Stmt::Inst(Inst::Derivative { dst: f, axis: crate::shader::ir::Axis::X, a: f })], "derivative"),
            (vec![Stmt::Inst(Inst::Input { dst: f, slot: 1 })], "input 1 does not exist"),
            (vec![Stmt::Inst(Inst::Const { dst: Reg(9), value: Const::F32(1.0) })], "r9 does not exist"),
            (vec![Stmt::Inst(Inst::Const { dst: f, value: Const::I32(1) })], "expected i32"),
            (vec![Stmt::If { cond: f, then: vec![], otherwise: vec![] }], "expected bool"),
            (vec![Stmt::Inst(Inst::Unary { op: UnaryOp::INot, dst: f, a: f })], "expected an integer"),
            (
                vec![Stmt::Inst(Inst::Sample {
                    dst: [f; 4],
                    unit: 0,
                    n: 2,
                    coords: [f; 4],
                    projective: false,
                    lod: Lod::Implicit,
                    compare: None,
                })],
                "implicit level of detail outside",
            ),
            (
                vec![Stmt::Inst(Inst::Sample {
                    dst: [f; 4],
                    unit: 40,
                    n: 2,
                    coords: [f; 4],
                    projective: false,
                    lod: Lod::Explicit(f),
                    compare: None,
                })],
                "texture unit 40",
            ),
            (vec![Stmt::Inst(Inst::Fetch { dst: [f; 4], unit: 0, n: 2, coords: [f; 3], lod: f })], "expected i32"),
        ];
        for (body, reason) in cases {
            p.body = body;
            let err = validate(&p).unwrap_err();
            assert!(err.reason.contains(reason), "{err} should mention {reason:?}");
        }
    }

    #[test]
    fn nesting_is_bounded() {
        let (mut p, _, b) = program();
        let mut body = vec![];
        for _ in 0..=MAX_NESTING {
            body = vec![Stmt::If { cond: b, then: body, otherwise: vec![] }];
        }
        p.body = body;
        assert!(validate(&p).unwrap_err().reason.contains("nested deeper"));
    }
}
