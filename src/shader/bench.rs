//! Three programs of the kinds the pipeline runs, checked on both compiled executors against
//! the reference, and the benchmark that compares the designs on them (ignored by default:
//! `cargo test --release --lib shader::bench -- --ignored --nocapture`, `TESSERA_SIMD=sse2`
//! for the baseline level).
//!
//! - **phong**: per-pixel lighting: a normal matrix applied to the interpolated normal,
//!   three normalizes, two clamped dot products, a specular power by exp2/log2, colour by
//!   mads, clamped.
//! - **texture**: a texture-matrix transform of (s, t) by mad chains, a lookup, modulate by
//!   the colour, an environment blend and linear fog, clamped.
//! - **control**: a loop over four lights (a uniform count: a real branch), each with a
//!   divergent `if` and a nested divergent `if`, the light direction rotated by a uniform
//!   matrix per iteration (scalar), and a divergent discard after the loop.
use super::exec::{Executor, Io, LodLanes, SampleRequest, Textures, Word, ALL_LANES, LANES};
use super::fast::{Compiled, Registers, Threaded};
use super::ir::{BinaryOp, Const, Inst, Lod, Program, Reg, Stage, Stmt, Type, UnaryOp};
use super::lower::{Node, Op};
use super::validate::validate;
use std::time::Instant;

struct Builder {
    p: Program,
    stack: Vec<Vec<Stmt>>,
}

impl Builder {
    fn new() -> Builder {
        Builder { p: Program::new(Stage::Fragment), stack: vec![Vec::new()] }
    }

    fn emit(&mut self, s: Stmt) {
        self.stack.last_mut().expect("a block").push(s);
    }

    fn reg(&mut self, ty: Type) -> Reg {
        self.p.register(ty)
    }

    fn input(&mut self) -> Reg {
        let slot = self.p.input(Type::F32);
        let dst = self.reg(Type::F32);
        self.emit(Stmt::Inst(Inst::Input { dst, slot }));
        dst
    }

    fn uniform(&mut self, ty: Type) -> Reg {
        let slot = self.p.uniform(ty);
        let dst = self.reg(ty);
        self.emit(Stmt::Inst(Inst::Uniform { dst, slot }));
        dst
    }

    fn konst(&mut self, value: Const) -> Reg {
        let dst = self.reg(value.ty());
        self.emit(Stmt::Inst(Inst::Const { dst, value }));
        dst
    }

    fn set(&mut self, dst: Reg, op: BinaryOp, a: Reg, b: Reg) {
        self.emit(Stmt::Inst(Inst::Binary { op, dst, a, b }));
    }

    fn bin(&mut self, op: BinaryOp, ty: Type, a: Reg, b: Reg) -> Reg {
        let dst = self.reg(ty);
        self.set(dst, op, a, b);
        dst
    }

    fn fb(&mut self, op: BinaryOp, a: Reg, b: Reg) -> Reg {
        self.bin(op, Type::F32, a, b)
    }

    fn un(&mut self, op: UnaryOp, a: Reg) -> Reg {
        let dst = self.reg(Type::F32);
        self.emit(Stmt::Inst(Inst::Unary { op, dst, a }));
        dst
    }

    fn mad_into(&mut self, dst: Reg, a: Reg, b: Reg, c: Reg) {
        self.emit(Stmt::Inst(Inst::Mad { dst, a, b, c }));
    }

    fn mad(&mut self, a: Reg, b: Reg, c: Reg) -> Reg {
        let dst = self.reg(Type::F32);
        self.mad_into(dst, a, b, c);
        dst
    }

    fn dot(&mut self, a: &[Reg], b: &[Reg]) -> Reg {
        let dst = self.reg(Type::F32);
        let (mut ra, mut rb) = ([a[0]; 4], [b[0]; 4]);
        ra[..a.len()].copy_from_slice(a);
        rb[..b.len()].copy_from_slice(b);
        self.emit(Stmt::Inst(Inst::Dot { dst, n: a.len() as u8, a: ra, b: rb }));
        dst
    }

    fn normalize(&mut self, v: [Reg; 3]) -> [Reg; 3] {
        let l = self.dot(&v, &v);
        let s = self.un(UnaryOp::Rsq, l);
        v.map(|c| self.fb(BinaryOp::FMul, c, s))
    }

    fn clamp(&mut self, x: Reg, lo: Reg, hi: Reg) -> Reg {
        let t = self.fb(BinaryOp::FMax, x, lo);
        self.fb(BinaryOp::FMin, t, hi)
    }

    fn output(&mut self, src: Reg) {
        let slot = self.p.output(Type::F32);
        self.emit(Stmt::Inst(Inst::Output { slot, src }));
    }

    fn begin(&mut self) {
        self.stack.push(Vec::new());
    }

    fn end(&mut self) -> Vec<Stmt> {
        self.stack.pop().expect("a block")
    }

    fn finish(mut self) -> Program {
        self.p.body = self.end();
        validate(&self.p).unwrap_or_else(|e| panic!("{e}\n{}", super::dump::dump(&self.p)));
        self.p
    }
}

fn phong() -> Program {
    use BinaryOp::*;
    let mut b = Builder::new();
    let normal = [0; 3].map(|_| b.input());
    let position = [0; 3].map(|_| b.input());
    let matrix = [0; 9].map(|_| b.uniform(Type::F32));
    let light = [0; 3].map(|_| b.uniform(Type::F32));
    let ambient = [0; 3].map(|_| b.uniform(Type::F32));
    let diffuse = [0; 3].map(|_| b.uniform(Type::F32));
    let specular = [0; 3].map(|_| b.uniform(Type::F32));
    let shininess = b.uniform(Type::F32);
    let zero = b.konst(Const::F32(0.0));
    let one = b.konst(Const::F32(1.0));
    let transformed = [0, 1, 2].map(|row| b.dot(&matrix[row * 3..row * 3 + 3], &normal));
    let n = b.normalize(transformed);
    let eye = position.map(|c| b.un(UnaryOp::FNeg, c));
    let v = b.normalize(eye);
    let half = [0, 1, 2].map(|k| b.fb(FAdd, light[k], v[k]));
    let h = b.normalize(half);
    let ndotl = b.dot(&n, &light);
    let ndotl = b.fb(FMax, ndotl, zero);
    let ndoth = b.dot(&n, &h);
    let ndoth = b.fb(FMax, ndoth, zero);
    let log = b.un(UnaryOp::Log2, ndoth);
    let e = b.fb(FMul, log, shininess);
    let spec = b.un(UnaryOp::Exp2, e);
    for k in 0..3 {
        let c = b.mad(diffuse[k], ndotl, ambient[k]);
        let c = b.mad(specular[k], spec, c);
        let c = b.clamp(c, zero, one);
        b.output(c);
    }
    b.output(one);
    b.finish()
}

fn texture() -> Program {
    use BinaryOp::*;
    let mut b = Builder::new();
    let s = b.input();
    let t = b.input();
    let color = [0; 4].map(|_| b.input());
    let fog_z = b.input();
    let m = [0; 6].map(|_| b.uniform(Type::F32));
    let env = [0; 4].map(|_| b.uniform(Type::F32));
    let fog_color = [0; 3].map(|_| b.uniform(Type::F32));
    let fog_scale = b.uniform(Type::F32);
    let fog_bias = b.uniform(Type::F32);
    let zero = b.konst(Const::F32(0.0));
    let one = b.konst(Const::F32(1.0));
    let s1 = b.mad(m[1], t, m[2]);
    let s2 = b.mad(m[0], s, s1);
    let t1 = b.mad(m[4], t, m[5]);
    let t2 = b.mad(m[3], s, t1);
    let texel = [0; 4].map(|_| b.reg(Type::F32));
    b.emit(Stmt::Inst(Inst::Sample {
        dst: texel,
        unit: 0,
        n: 2,
        coords: [s2, t2, s2, s2],
        projective: false,
        lod: Lod::Implicit,
        compare: None,
    }));
    let fog = b.mad(fog_z, fog_scale, fog_bias);
    let fog = b.clamp(fog, zero, one);
    for k in 0..4 {
        let c = b.fb(FMul, texel[k], color[k]);
        // GL_BLEND-like: c + (env − c)·texel.
        let d = b.fb(FSub, env[k], c);
        let c = b.mad(d, texel[k], c);
        let c = if k < 3 {
            let d = b.fb(FSub, c, fog_color[k]);
            b.mad(d, fog, fog_color[k])
        } else {
            c
        };
        let c = b.clamp(c, zero, one);
        b.output(c);
    }
    b.finish()
}

fn control() -> Program {
    use BinaryOp::*;
    let mut b = Builder::new();
    let normal = [0; 3].map(|_| b.input());
    let alpha = b.input();
    let lights = b.uniform(Type::I32);
    let rotation = [0; 9].map(|_| b.uniform(Type::F32));
    let light = [0; 3].map(|_| b.uniform(Type::F32));
    let diffuse = [0; 3].map(|_| b.uniform(Type::F32));
    let highlight = b.uniform(Type::F32);
    let zero = b.konst(Const::F32(0.0));
    let threshold = b.konst(Const::F32(0.9));
    let cut = b.konst(Const::F32(0.05));
    let acc = [0; 3].map(|_| b.konst(Const::F32(0.0)));
    let l = [0; 3].map(|_| b.reg(Type::F32));
    for k in 0..3 {
        b.emit(Stmt::Inst(Inst::Mov { dst: l[k], src: light[k] }));
    }
    let i = b.konst(Const::I32(0));
    let step = b.konst(Const::I32(1));
    let n = b.normalize(normal);
    b.begin();
    {
        b.set(i, IAdd, i, step);
        let done = b.bin(ILt, Type::Bool, lights, i);
        b.emit(Stmt::If { cond: done, then: vec![Stmt::Break], otherwise: vec![] });
        let ndotl = b.dot(&n, &l);
        let lit = b.bin(FLt, Type::Bool, zero, ndotl);
        b.begin();
        {
            for k in 0..3 {
                b.mad_into(acc[k], diffuse[k], ndotl, acc[k]);
            }
            let shiny = b.bin(FLt, Type::Bool, threshold, ndotl);
            b.begin();
            for a in acc {
                b.set(a, FAdd, a, highlight);
            }
            let then = b.end();
            b.emit(Stmt::If { cond: shiny, then, otherwise: vec![] });
        }
        let then = b.end();
        b.emit(Stmt::If { cond: lit, then, otherwise: vec![] });
        let rotated = [0, 1, 2].map(|row| b.dot(&rotation[row * 3..row * 3 + 3], &l));
        for k in 0..3 {
            b.emit(Stmt::Inst(Inst::Mov { dst: l[k], src: rotated[k] }));
        }
    }
    let body = b.end();
    b.emit(Stmt::Loop { body });
    let faint = b.fb(FMul, acc[0], alpha);
    let gone = b.bin(FLt, Type::Bool, faint, cut);
    b.emit(Stmt::If { cond: gone, then: vec![Stmt::Discard], otherwise: vec![] });
    for a in acc {
        b.output(a);
    }
    b.finish()
}

/// A 64×64 texture looked up at the nearest texel, in the requested lanes (a stand-in for
/// the texture room's samplers, at a fixed cost the designs share).
struct Nearest(Vec<[f32; 4]>);

impl Nearest {
    fn new() -> Nearest {
        Nearest((0..64 * 64).map(|i| [(i % 64) as f32 / 63.0, (i / 64) as f32 / 63.0, 0.5, 1.0]).collect())
    }
}

impl Textures for Nearest {
    // Lane i of several words at once.
    #[allow(clippy::needless_range_loop)]
    fn sample(&self, r: &SampleRequest<'_>, out: &mut [Word; 4]) {
        assert!(matches!(r.lod, LodLanes::Implicit));
        for i in 0..LANES {
            let s = f32::from_bits(r.coords[0][i]);
            let t = f32::from_bits(r.coords[1][i]);
            let x = ((s * 64.0) as i32 & 63) as usize;
            let y = ((t * 64.0) as i32 & 63) as usize;
            let texel = self.0[y * 64 + x];
            for c in 0..4 {
                out[c][i] = texel[c].to_bits();
            }
        }
    }

    fn fetch(&self, _: u8, _: u8, _: &[Word; 3], _: &Word, _: u16, _: &mut [Word; 4]) {
        unreachable!()
    }

    fn size(&self, _: u8, _: &Word, _: u16, _: &mut [Word; 3]) {
        unreachable!()
    }
}

/// Inputs of `blocks` blocks and the uniforms of `program`, plausible for its kind.
fn data(program: &Program, blocks: usize, seed: u64) -> (Vec<Vec<Word>>, Vec<u32>) {
    let mut x = seed | 1;
    let mut rand = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 40) as f32 / (1u64 << 24) as f32 // [0, 1)
    };
    let inputs = (0..blocks)
        .map(|_| program.inputs.iter().map(|_| std::array::from_fn(|_| (rand() * 2.0 - 0.5).to_bits())).collect())
        .collect();
    let uniforms = program
        .uniforms
        .iter()
        .map(|t| match t {
            Type::I32 => 4,
            _ => (rand() * 1.5 - 0.25).to_bits(),
        })
        .collect();
    (inputs, uniforms)
}

fn ops(program: &Program) -> Vec<Op> {
    Compiled::new(program).code().ops.clone()
}

fn uniform_ifs(nodes: &[Node]) -> usize {
    nodes
        .iter()
        .map(|n| match n {
            Node::If { cond, then, otherwise } => {
                matches!(cond, super::lower::Cond::Uniform(_)) as usize + uniform_ifs(then) + uniform_ifs(otherwise)
            }
            Node::Loop { body } => uniform_ifs(body),
            _ => 0,
        })
        .sum()
}

#[test]
fn the_sample_programs_are_fused_and_match_the_reference() {
    let phong_ops = ops(&phong());
    let count = |ops: &[Op], f: fn(&Op) -> bool| ops.iter().filter(|o| f(o)).count();
    assert_eq!(count(&phong_ops, |o| matches!(o, Op::Normalize3 { .. })), 3, "{phong_ops:#?}");
    assert_eq!(count(&phong_ops, |o| matches!(o, Op::Clamp { .. })), 3);
    assert_eq!(count(&phong_ops, |o| matches!(o, Op::MatVec(_))), 1);
    // Every uniform read and the constants are scalar.
    assert_eq!(count(&phong_ops, |o| matches!(o, Op::SUniform { .. })), 22);
    let texture_ops = ops(&texture());
    assert_eq!(count(&texture_ops, |o| matches!(o, Op::Clamp { .. })), 5);
    let control = control();
    let code = Compiled::new(&control).code().clone();
    // The light count's test is uniform, and the rotation of the light is scalar.
    assert_eq!(uniform_ifs(&code.body), 1, "{code:#?}");
    assert!(count(&code.ops, |o| matches!(o, Op::SDot { .. })) == 3);

    let textures = Nearest::new();
    let mut executor = Executor::new();
    let mut registers = Registers::new();
    for program in [phong(), texture(), control] {
        let (compiled, threaded) = (Compiled::new(&program), Threaded::new(&program));
        let (inputs, mut uniforms) = data(&program, 200, 7);
        for (block, inputs) in inputs.iter().enumerate() {
            if block % 50 == 49 {
                uniforms = data(&program, 1, block as u64).1;
            }
            let lanes = if block % 3 == 0 { (block as u16).wrapping_mul(0x9e37) | 1 } else { ALL_LANES };
            let mut results = Vec::new();
            for which in 0..3 {
                let mut outputs = vec![[0u32; LANES]; program.outputs.len()];
                let mut io = Io { inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &textures };
                let alive = match which {
                    0 => executor.run(&program, &mut io, lanes),
                    1 => compiled.run(&mut registers, &mut io, lanes),
                    _ => threaded.run(&mut registers, &mut io, lanes),
                };
                results.push((alive, outputs));
            }
            assert_eq!(results[1], results[0], "block {block}\n{}", super::dump::dump(&program));
            assert_eq!(results[2], results[0], "block {block}");
        }
    }
}

/// Nanoseconds per block of the best of `rounds` rounds of `blocks` blocks each.
fn time(rounds: usize, blocks: usize, mut run: impl FnMut(usize)) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..rounds {
        let start = Instant::now();
        for i in 0..blocks {
            run(i);
        }
        best = best.min(start.elapsed().as_nanos() as f64 / blocks as f64);
    }
    best
}

#[test]
#[ignore = "a benchmark: run with --ignored --nocapture in a release build"]
fn bench_the_executor_designs() {
    let textures = Nearest::new();
    eprintln!("level {}", crate::simd::describe());
    eprintln!("program   stmts  ops regs | naive ns  interp ns  closures ns | compile µs (interp, closures)");
    let only = std::env::var("BENCH_PROGRAM").ok();
    for (name, program) in [("phong", phong()), ("texture", texture()), ("control", control())] {
        if only.as_deref().is_some_and(|o| o != name) {
            continue;
        }
        fn stmts(s: &[Stmt]) -> usize {
            s.iter()
                .map(|s| match s {
                    Stmt::If { then, otherwise, .. } => 1 + stmts(then) + stmts(otherwise),
                    Stmt::Loop { body } => 1 + stmts(body),
                    _ => 1,
                })
                .sum()
        }
        let (inputs, uniforms) = data(&program, 64, 11);
        let mut outputs = vec![[0u32; LANES]; program.outputs.len()];
        let mut executor = Executor::new();
        let mut registers = Registers::new();
        let (compiled, threaded) = (Compiled::new(&program), Threaded::new(&program));
        // BENCH_BLOCKS: fewer blocks for callgrind.
        let blocks = std::env::var("BENCH_BLOCKS").ok().and_then(|v| v.parse().ok()).unwrap_or(100_000);
        let compiles = (blocks / 50).max(10);
        let compile_interp = time(5, compiles, |_| drop(std::hint::black_box(Compiled::new(&program)))) / 1000.0;
        let compile_closures = time(5, compiles, |_| drop(std::hint::black_box(Threaded::new(&program)))) / 1000.0;
        let io_of = |i: usize| (i % inputs.len(), i);
        let mut naive = |i: usize| {
            let (k, _) = io_of(i);
            let mut io = Io { inputs: &inputs[k], uniforms: &uniforms, outputs: &mut outputs, textures: &textures };
            std::hint::black_box(executor.run(&program, &mut io, ALL_LANES));
        };
        // BENCH_DESIGN=naive|interp|closures: time only that one (for `perf stat`).
        let design = std::env::var("BENCH_DESIGN").ok();
        let wanted = |d: &str| design.as_deref().is_none_or(|w| w == d);
        let t_naive = if wanted("naive") { time(5, blocks, &mut naive) } else { 0.0 };
        let mut outputs = vec![[0u32; LANES]; program.outputs.len()];
        let t_interp = if !wanted("interp") {
            0.0
        } else {
            time(5, blocks, |i| {
                let k = i % inputs.len();
                let mut io = Io { inputs: &inputs[k], uniforms: &uniforms, outputs: &mut outputs, textures: &textures };
                std::hint::black_box(compiled.run(&mut registers, &mut io, ALL_LANES));
            })
        };
        let t_closures = if !wanted("closures") {
            0.0
        } else {
            time(5, blocks, |i| {
                let k = i % inputs.len();
                let mut io = Io { inputs: &inputs[k], uniforms: &uniforms, outputs: &mut outputs, textures: &textures };
                std::hint::black_box(threaded.run(&mut registers, &mut io, ALL_LANES));
            })
        };
        eprintln!(
            "{name:<9} {:>5} {:>4} {:>2}→{:<2}| {t_naive:>8.0} {t_interp:>10.0} {t_closures:>12.0} | {compile_interp:.1}, {compile_closures:.1}",
            stmts(&program.body),
            compiled.code().ops.len(),
            program.registers.len(),
            compiled.code().registers,
        );
    }
}
