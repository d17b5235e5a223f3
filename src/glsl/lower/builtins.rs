//! The built-in functions of GLSL 1.20 in the IR's arithmetic: each is a fixed sequence of
//! IR operations (IEEE add, mul, div, sqrt rounded once each, no contraction, and the IR's
//! `Exp2`, `Log2`, `Exp`, `Sin`, `Cos` polynomials), so that every CPU gives the same bits.
//! The formulas, per component:
//!
//! - `radians(x) = x·(π/180)`, `degrees(x) = x·(180/π)` (the factors rounded to f32).
//! - `sin`, `cos`: the IR's; `tan(x) = sin(x)/cos(x)`.
//! - `asin(x) = sign(x)·(π/2 − √(1−|x|)·P(|x|))` and `acos(x) = √(1−|x|)·P(|x|)`
//!   (`π −` that for x < 0), P the degree-7 polynomial of Abramowitz & Stegun 4.4.46
//!   (|error| ≤ 2·10⁻⁸ in exact arithmetic); |x| > 1 gives NaN (√ of a negative).
//! - `atan(y, x)`: t = min(|x|,|y|)/max(|x|,|y|) (0 when both are 0), atan(t) by an odd
//!   degree-11 polynomial, then `π/2 − r` when |y| > |x|, `π − r` when x < 0, negated when
//!   y < 0; `atan(y_over_x)` is the same with x = 1 (error about 5·10⁻⁶ rad, tested ≤ 10⁻⁵).
//! - `pow(x, y) = exp2(y·log2(x))`: pow(0, 0) = exp2(0·−∞) = NaN, pow(x < 0, y) = NaN
//!   (GLSL leaves both undefined). `exp(x)`: the IR's `Exp`; `log(x) = log2(x)·ln 2`;
//!   `exp2`, `log2`, `sqrt`: the IR's; `inversesqrt`: `Rsq`.
//! - `mod(x, y) = x − y·floor(x/y)`; `min`, `max`: the IR's (`y < x ? y : x`);
//!   `clamp(x, a, b) = min(max(x, a), b)`; `mix(x, y, a) = x·(1−a) + y·a` (exact at a = 0
//!   and 1); `step(e, x) = x < e ? 0 : 1`; `smoothstep(e0, e1, x)`: t = clamp((x−e0)/(e1−e0),
//!   0, 1), t·t·(3 − 2t).
//! - `dot`: products summed left to right; `length(x) = √dot(x, x)` (|x| for a float);
//!   `distance(a, b) = length(a − b)`; `normalize(x) = x·rsq(dot(x, x))`: normalize(0) is
//!   0·∞ = NaN in every component (as GLSL's formula gives); `cross` as written in the
//!   spec; `faceforward(N, I, Nref) = dot(Nref, I) < 0 ? N : −N`; `reflect(I, N) =
//!   I − 2·dot(N, I)·N`; `refract`: k = 1 − η²(1 − dot(N, I)²), 0 when k < 0, else
//!   η·I − (η·dot(N, I) + √k)·N.
//! - Division by zero is IEEE's (±∞ or NaN) for floats; the IR's 0 for ints.
//! - `matrixCompMult`, `outerProduct`, `transpose`, the vector relations, `any`, `all`,
//!   `not`: as the spec defines them, component by component.
//! - `dFdx`, `dFdy`: the IR's quad derivatives; `fwidth(p) = |dFdx(p)| + |dFdy(p)|`.
//! - `noise1..4`: 0, as Mesa returns (GL permits any value in [−1, 1] with the noise
//!   properties; no implementation ships real noise).
//! - `ftransform()`: `gl_ModelViewProjectionMatrix · gl_Vertex`, rows as dot products.
//! - Texture lookups: the IR's `Sample` with the sampler's index (see the parent module);
//!   `Proj` forms pass q as the last coordinate and let the sampler divide; vertex shaders'
//!   lookups without `Lod` use level 0 (GLSL: no implicit derivatives there); `shadow*`
//!   pass the reference (r) as the comparison value.

use super::{Leaf, Lowerer, DYNAMIC_SAMPLER_TAG, R, SAMPLER_TAG};
use crate::glsl::hir::{Scalar, Type};
use crate::glsl::lex::Sampler;
use crate::shader::ir::{self, Axis, BinaryOp as B, Const, Inst, Lod, Reg, Stmt, UnaryOp as U};

const PI: f32 = std::f32::consts::PI;
const HALF_PI: f32 = std::f32::consts::FRAC_PI_2;

/// Abramowitz & Stegun 4.4.46: acos(x) ≈ √(1−x)·Σ aₖxᵏ on [0, 1].
#[allow(clippy::approx_constant)] // A&S's a₀, which is π/2 to its 10 digits
const ACOS: [f32; 8] = [
    1.570_796_3,
    -0.214_598_8,
    0.088_978_99,
    -0.050_174_3,
    0.030_891_88,
    -0.017_088_126,
    0.006_670_09,
    -0.001_262_491_1,
];

/// atan(t) ≈ t·Σ bₖt²ᵏ on [0, 1] (the classic degree-11 odd fit).
const ATAN: [f32; 6] = [0.999_995_6, -0.332_994_6, 0.195_635_93, -0.121_239_07, 0.057_477_314, -0.013_480_47];

impl Lowerer<'_> {
    /// Per component of up to three operands (a one-component operand applies to all).
    fn each(&mut self, args: &[&[Reg]], mut f: impl FnMut(&mut Self, &[Reg]) -> Reg) -> Vec<Reg> {
        let n = args.iter().map(|a| a.len()).max().unwrap_or(0);
        (0..n)
            .map(|i| {
                let ops: Vec<Reg> = args.iter().map(|a| if a.len() == 1 { a[0] } else { a[i] }).collect();
                f(self, &ops)
            })
            .collect()
    }

    /// Σ cₖxᵏ by Horner's rule (a multiply and an add, each rounded).
    fn poly(&mut self, x: Reg, c: &[f32]) -> Reg {
        let mut acc = self.f(c[c.len() - 1]);
        for &k in c[..c.len() - 1].iter().rev() {
            let kc = self.f(k);
            let m = self.bin(B::FMul, acc, x);
            acc = self.bin(B::FAdd, m, kc);
        }
        acc
    }

    fn fconst_mul(&mut self, x: Reg, k: f32) -> Reg {
        let kc = self.f(k);
        self.bin(B::FMul, x, kc)
    }

    /// acos |x| by Abramowitz and Stegun 4.4.46: √(1 − |x|)·p(|x|), the part acos and asin
    /// share.
    fn acos_of_magnitude(&mut self, x: Reg) -> Reg {
        let ax = self.un(U::FAbs, x);
        let one = self.f(1.0);
        let d = self.bin(B::FSub, one, ax);
        let s = self.un(U::Sqrt, d);
        let p = self.poly(ax, &ACOS);
        self.bin(B::FMul, s, p)
    }

    fn acos1(&mut self, x: Reg) -> Reg {
        let r = self.acos_of_magnitude(x);
        let pi = self.f(PI);
        let flipped = self.bin(B::FSub, pi, r);
        let zero = self.f(0.0);
        let neg = self.bin(B::FLt, x, zero);
        self.select(neg, flipped, r)
    }

    fn asin1(&mut self, x: Reg) -> Reg {
        let r = self.acos_of_magnitude(x);
        let hp = self.f(HALF_PI);
        let a = self.bin(B::FSub, hp, r);
        let zero = self.f(0.0);
        let neg = self.bin(B::FLt, x, zero);
        let na = self.un(U::FNeg, a);
        self.select(neg, na, a)
    }

    fn atan2_1(&mut self, y: Reg, x: Reg) -> Reg {
        let ax = self.un(U::FAbs, x);
        let ay = self.un(U::FAbs, y);
        let hi = self.bin(B::FMax, ax, ay);
        let lo = self.bin(B::FMin, ax, ay);
        let q = self.bin(B::FDiv, lo, hi);
        let zero = self.f(0.0);
        let both_zero = self.bin(B::FEq, hi, zero);
        let t = self.select(both_zero, zero, q);
        let t2 = self.bin(B::FMul, t, t);
        let p = self.poly(t2, &ATAN);
        let r = self.bin(B::FMul, p, t);
        let hp = self.f(HALF_PI);
        let steep = self.bin(B::FLt, ax, ay);
        let r2 = self.bin(B::FSub, hp, r);
        let r = self.select(steep, r2, r);
        let pi = self.f(PI);
        let left = self.bin(B::FLt, x, zero);
        let r3 = self.bin(B::FSub, pi, r);
        let r = self.select(left, r3, r);
        let below = self.bin(B::FLt, y, zero);
        let nr = self.un(U::FNeg, r);
        self.select(below, nr, r)
    }

    fn pow1(&mut self, x: Reg, y: Reg) -> Reg {
        let l = self.un(U::Log2, x);
        let m = self.bin(B::FMul, y, l);
        self.un(U::Exp2, m)
    }

    fn min_max_clamp(&mut self, x: Reg, a: Reg, b: Reg, float: bool) -> Reg {
        let (mx, mn) = if float { (B::FMax, B::FMin) } else { (B::IMax, B::IMin) };
        let t = self.bin(mx, x, a);
        self.bin(mn, t, b)
    }

    /// The samplers a lookup's sampler argument may be: one, or for an array element chosen
    /// by a non-constant index, the index register and every element's sampler.
    fn sampler_choice(&self, v: &[Reg]) -> R<(Option<Reg>, Vec<u8>)> {
        let unit = |r: Reg| -> R<u8> { u8::try_from(r.0 - SAMPLER_TAG).map_err(|_| "too many samplers".to_string()) };
        match v.first() {
            Some(r) if r.0 >= DYNAMIC_SAMPLER_TAG => {
                let (index, candidates) = &self.dynamic_samplers[(r.0 - DYNAMIC_SAMPLER_TAG) as usize];
                Ok((Some(*index), candidates.iter().map(|&c| unit(c)).collect::<R<_>>()?))
            }
            Some(&r) if r.0 >= SAMPLER_TAG => Ok((None, vec![unit(r)?])),
            _ => Err("a texture lookup without a sampler uniform".into()),
        }
    }

    /// A built-in function call on lowered arguments.
    pub(super) fn builtin(&mut self, name: &str, a: &[Vec<Reg>], types: &[Type], ret: &Type) -> R<Vec<Reg>> {
        let float = types.first().and_then(|t| t.base()) == Some(Scalar::Float);
        let arg = |i: usize| -> &[Reg] { &a[i] };
        Ok(match name {
            "radians" => self.each(&[arg(0)], |l, o| l.fconst_mul(o[0], PI / 180.0)),
            "degrees" => self.each(&[arg(0)], |l, o| l.fconst_mul(o[0], 180.0 / PI)),
            "sin" => self.each(&[arg(0)], |l, o| l.un(U::Sin, o[0])),
            "cos" => self.each(&[arg(0)], |l, o| l.un(U::Cos, o[0])),
            "tan" => self.each(&[arg(0)], |l, o| {
                let s = l.un(U::Sin, o[0]);
                let c = l.un(U::Cos, o[0]);
                l.bin(B::FDiv, s, c)
            }),
            "asin" => self.each(&[arg(0)], |l, o| l.asin1(o[0])),
            "acos" => self.each(&[arg(0)], |l, o| l.acos1(o[0])),
            "atan" if a.len() == 2 => self.each(&[arg(0), arg(1)], |l, o| l.atan2_1(o[0], o[1])),
            "atan" => self.each(&[arg(0)], |l, o| {
                let one = l.f(1.0);
                l.atan2_1(o[0], one)
            }),
            "pow" => self.each(&[arg(0), arg(1)], |l, o| l.pow1(o[0], o[1])),
            "exp" => self.each(&[arg(0)], |l, o| l.un(U::Exp, o[0])),
            "log" => self.each(&[arg(0)], |l, o| {
                let lg = l.un(U::Log2, o[0]);
                l.fconst_mul(lg, std::f32::consts::LN_2)
            }),
            "exp2" => self.each(&[arg(0)], |l, o| l.un(U::Exp2, o[0])),
            "log2" => self.each(&[arg(0)], |l, o| l.un(U::Log2, o[0])),
            "sqrt" => self.each(&[arg(0)], |l, o| l.un(U::Sqrt, o[0])),
            "inversesqrt" => self.each(&[arg(0)], |l, o| l.un(U::Rsq, o[0])),
            "abs" => self.each(&[arg(0)], |l, o| l.un(if float { U::FAbs } else { U::IAbs }, o[0])),
            "sign" if float => self.each(&[arg(0)], |l, o| l.un(U::FSign, o[0])),
            // The integer sign is x clamped to [-1, 1].
            "sign" => self.each(&[arg(0)], |l, o| {
                let (lo, hi) = (l.konst(Const::I32(-1)), l.konst(Const::I32(1)));
                l.min_max_clamp(o[0], lo, hi, false)
            }),
            "floor" => self.each(&[arg(0)], |l, o| l.un(U::Floor, o[0])),
            "ceil" => self.each(&[arg(0)], |l, o| l.un(U::Ceil, o[0])),
            "fract" => self.each(&[arg(0)], |l, o| l.un(U::Fract, o[0])),
            "mod" => self.each(&[arg(0), arg(1)], |l, o| {
                let q = l.bin(B::FDiv, o[0], o[1]);
                let fl = l.un(U::Floor, q);
                let m = l.bin(B::FMul, o[1], fl);
                l.bin(B::FSub, o[0], m)
            }),
            "min" => self.each(&[arg(0), arg(1)], |l, o| l.bin(if float { B::FMin } else { B::IMin }, o[0], o[1])),
            "max" => self.each(&[arg(0), arg(1)], |l, o| l.bin(if float { B::FMax } else { B::IMax }, o[0], o[1])),
            "clamp" => self.each(&[arg(0), arg(1), arg(2)], |l, o| l.min_max_clamp(o[0], o[1], o[2], float)),
            "mix" => self.each(&[arg(0), arg(1), arg(2)], |l, o| {
                let one = l.f(1.0);
                let inv = l.bin(B::FSub, one, o[2]);
                let x = l.bin(B::FMul, o[0], inv);
                let y = l.bin(B::FMul, o[1], o[2]);
                l.bin(B::FAdd, x, y)
            }),
            "step" => self.each(&[arg(0), arg(1)], |l, o| {
                let below = l.bin(B::FLt, o[1], o[0]);
                let (zero, one) = (l.f(0.0), l.f(1.0));
                l.select(below, zero, one)
            }),
            "smoothstep" => self.each(&[arg(0), arg(1), arg(2)], |l, o| {
                let num = l.bin(B::FSub, o[2], o[0]);
                let den = l.bin(B::FSub, o[1], o[0]);
                let q = l.bin(B::FDiv, num, den);
                let (zero, one) = (l.f(0.0), l.f(1.0));
                let t = l.min_max_clamp(q, zero, one, true);
                let two_t = l.fconst_mul(t, 2.0);
                let three = l.f(3.0);
                let k = l.bin(B::FSub, three, two_t);
                let tt = l.bin(B::FMul, t, t);
                l.bin(B::FMul, tt, k)
            }),
            "length" => vec![self.length(arg(0))],
            "distance" => {
                let d: Vec<Reg> = self.each(&[arg(0), arg(1)], |l, o| l.bin(B::FSub, o[0], o[1]));
                vec![self.length(&d)]
            }
            "dot" => vec![self.dot(arg(0), arg(1))],
            "cross" => {
                let (x, y) = (arg(0).to_vec(), arg(1).to_vec());
                let c = |l: &mut Self, i: usize, j: usize| {
                    let p = l.bin(B::FMul, x[i], y[j]);
                    let q = l.bin(B::FMul, y[i], x[j]);
                    l.bin(B::FSub, p, q)
                };
                vec![c(self, 1, 2), c(self, 2, 0), c(self, 0, 1)]
            }
            "normalize" => {
                let x = arg(0).to_vec();
                let d = self.dot(&x, &x);
                let r = self.un(U::Rsq, d);
                self.each(&[&x, &[r]], |l, o| l.bin(B::FMul, o[0], o[1]))
            }
            "ftransform" => {
                let m = self.builtin_value("gl_ModelViewProjectionMatrix")?;
                let v = self.builtin_value("gl_Vertex")?;
                self.matmul(&m, &Type::Matrix(4, 4), &v, &Type::Vector(Scalar::Float, 4))?
            }
            "faceforward" => {
                let (n, i, nref) = (arg(0).to_vec(), arg(1).to_vec(), arg(2).to_vec());
                let d = self.dot(&nref, &i);
                let zero = self.f(0.0);
                let front = self.bin(B::FLt, d, zero);
                self.each(&[&n], |l, o| {
                    let neg = l.un(U::FNeg, o[0]);
                    l.select(front, o[0], neg)
                })
            }
            "reflect" => {
                let (i, n) = (arg(0).to_vec(), arg(1).to_vec());
                let d = self.dot(&n, &i);
                let d2 = self.fconst_mul(d, 2.0);
                self.each(&[&i, &n], |l, o| {
                    let m = l.bin(B::FMul, d2, o[1]);
                    l.bin(B::FSub, o[0], m)
                })
            }
            "refract" => {
                let (i, n, eta) = (arg(0).to_vec(), arg(1).to_vec(), arg(2)[0]);
                let d = self.dot(&n, &i);
                let one = self.f(1.0);
                let dd = self.bin(B::FMul, d, d);
                let t = self.bin(B::FSub, one, dd);
                let ee = self.bin(B::FMul, eta, eta);
                let et = self.bin(B::FMul, ee, t);
                let k = self.bin(B::FSub, one, et);
                let zero = self.f(0.0);
                let total = self.bin(B::FLt, k, zero);
                let sk = self.un(U::Sqrt, k);
                let ed = self.bin(B::FMul, eta, d);
                let f = self.bin(B::FAdd, ed, sk);
                self.each(&[&i, &n], |l, o| {
                    let a = l.bin(B::FMul, eta, o[0]);
                    let b = l.bin(B::FMul, f, o[1]);
                    let r = l.bin(B::FSub, a, b);
                    l.select(total, zero, r)
                })
            }
            "matrixCompMult" => self.each(&[arg(0), arg(1)], |l, o| l.bin(B::FMul, o[0], o[1])),
            "outerProduct" => {
                let (c, r) = (arg(0).to_vec(), arg(1).to_vec());
                let mut out = Vec::new();
                for &rj in &r {
                    for &ci in &c {
                        out.push(self.bin(B::FMul, ci, rj));
                    }
                }
                out
            }
            "transpose" => {
                let Type::Matrix(c, r) = types[0] else { return Err("transpose of a non-matrix".into()) };
                let (c, r) = (c as usize, r as usize);
                let m = arg(0);
                // Result: r columns of c rows; element (j, i) = m[i][j].
                (0..r * c).map(|k| m[(k % c) * r + k / c]).collect()
            }
            "lessThan" | "lessThanEqual" | "greaterThan" | "greaterThanEqual" => {
                let f = types[0].base() == Some(Scalar::Float);
                let (op, swap) = match (name, f) {
                    ("lessThan", true) => (B::FLt, false),
                    ("lessThanEqual", true) => (B::FLe, false),
                    ("greaterThan", true) => (B::FLt, true),
                    (_, true) => (B::FLe, true),
                    ("lessThan", false) => (B::ILt, false),
                    ("lessThanEqual", false) => (B::ILe, false),
                    ("greaterThan", false) => (B::ILt, true),
                    _ => (B::ILe, true),
                };
                self.each(&[arg(0), arg(1)], |l, o| if swap { l.bin(op, o[1], o[0]) } else { l.bin(op, o[0], o[1]) })
            }
            "equal" | "notEqual" => self.each(&[arg(0), arg(1)], |l, o| {
                let e = l.eq1(o[0], o[1]);
                if name == "notEqual" {
                    l.un(U::BNot, e)
                } else {
                    e
                }
            }),
            "any" | "all" => {
                let op = if name == "any" { B::BOr } else { B::BAnd };
                let v = arg(0).to_vec();
                let mut acc = v[0];
                for &x in &v[1..] {
                    acc = self.bin(op, acc, x);
                }
                vec![acc]
            }
            "not" => self.each(&[arg(0)], |l, o| l.un(U::BNot, o[0])),
            "dFdx" | "dFdy" => {
                let axis = if name == "dFdx" { Axis::X } else { Axis::Y };
                self.each(&[arg(0)], |l, o| l.derivative(axis, o[0]))
            }
            "fwidth" => self.each(&[arg(0)], |l, o| {
                let x = l.derivative(Axis::X, o[0]);
                let y = l.derivative(Axis::Y, o[0]);
                let ax = l.un(U::FAbs, x);
                let ay = l.un(U::FAbs, y);
                l.bin(B::FAdd, ax, ay)
            }),
            "noise1" | "noise2" | "noise3" | "noise4" => {
                let zero = self.f(0.0);
                vec![zero; ret.components()]
            }
            _ if name.starts_with("texture") || name.starts_with("shadow") => self.lookup(name, a, types)?,
            _ => return Err(format!("built-in function `{name}' is not supported")),
        })
    }

    fn length(&mut self, x: &[Reg]) -> Reg {
        if x.len() == 1 {
            return self.un(U::FAbs, x[0]);
        }
        let d = self.dot(x, x);
        self.un(U::Sqrt, d)
    }

    fn derivative(&mut self, axis: Axis, a: Reg) -> Reg {
        let dst = self.reg(ir::Type::F32);
        self.emit(Inst::Derivative { dst, axis, a });
        dst
    }

    /// The value of a built-in variable by name (for `ftransform`).
    fn builtin_value(&mut self, name: &str) -> R<Vec<Reg>> {
        let unit = self.unit();
        let id = self.units[unit]
            .variables
            .iter()
            .position(|v| v.name == name)
            .ok_or_else(|| format!("built-in `{name}' is not declared"))?;
        let key = self.key(unit, id);
        let place = self.var_place(unit, id, key);
        self.read(&place)
    }

    /// `texture*`, `shadow*` (plain, `Proj`, `Lod`, bias).
    fn lookup(&mut self, name: &str, a: &[Vec<Reg>], types: &[Type]) -> R<Vec<Reg>> {
        let (index, units) = self.sampler_choice(&a[0])?;
        let Type::Sampler(kind) = types[0] else { return Err("lookup without a sampler".into()) };
        let proj = name.contains("Proj");
        let explicit = name.ends_with("Lod");
        let c = &a[1];
        let n: usize = match kind {
            Sampler::S1D | Sampler::S1DShadow => 1,
            Sampler::S2D | Sampler::S2DShadow => 2,
            Sampler::S3D | Sampler::Cube => 3,
        };
        let shadow = matches!(kind, Sampler::S1DShadow | Sampler::S2DShadow);
        let mut coords: Vec<Reg> = c[..n].to_vec();
        if proj {
            // q is the last component of the coordinate vector.
            coords.push(*c.last().expect("coordinates"));
        }
        let compare = shadow.then(|| c[2]);
        let zero = self.f(0.0);
        while coords.len() < 4 {
            coords.push(zero);
        }
        let lod = if explicit {
            Lod::Explicit(a[2][0])
        } else if a.len() == 3 {
            if self.stage == ir::Stage::Vertex {
                return Err("a bias in a vertex shader".into());
            }
            Lod::Bias(a[2][0])
        } else if self.stage == ir::Stage::Vertex {
            Lod::Explicit(zero)
        } else {
            Lod::Implicit
        };
        let mut result: Option<[Reg; 4]> = None;
        // One lookup per candidate sampler, the index choosing among their results per lane
        // (element 0 where it is out of range).
        for (k, &unit) in units.iter().enumerate() {
            let dst = [0; 4].map(|_| self.reg(ir::Type::F32));
            self.body.push(Stmt::Inst(Inst::Sample {
                dst,
                unit,
                n: n as u8,
                coords: [coords[0], coords[1], coords[2], coords[3]],
                projective: proj,
                lod,
                compare,
            }));
            result = Some(match (result, index) {
                (Some(previous), Some(index)) => {
                    let kc = self.konst(Const::I32(k as i32));
                    let cond = self.bin(B::IEq, index, kc);
                    [0, 1, 2, 3].map(|c| self.select(cond, dst[c], previous[c]))
                }
                _ => dst,
            });
        }
        let _ = Leaf::Sampler;
        Ok(result.ok_or("a sampler array of no elements")?.to_vec())
    }
}
