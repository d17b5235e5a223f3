//! Constant folding: the values of GLSL's constant expressions (array sizes, `const`
//! initializers, constant indices), computed at compile time over [`Constant`]s.
//!
//! Each function returns `None` when it cannot fold (an integer division by zero, a
//! built-in that is no constant function, such as the texture lookups): the expression then
//! stays as it is and is not a constant expression. Folding runs at compile time only, so
//! it may use the standard library's transcendental functions.

use super::hir::{BinaryOp, Constant, Scalar, Type, UnaryOp, Value};

fn basic(c: &Constant) -> Option<&[Value]> {
    match c {
        Constant::Basic(v) => Some(v),
        Constant::Composite(_) => None,
    }
}

/// `op c` for a constant of type `ty`.
pub fn unary(op: UnaryOp, c: &Constant) -> Option<Constant> {
    let v = basic(c)?;
    let out = v
        .iter()
        .map(|&x| match (op, x) {
            (UnaryOp::Neg, Value::F(f)) => Some(Value::F(-f)),
            (UnaryOp::Neg, Value::I(i)) => Some(Value::I(i.wrapping_neg())),
            (UnaryOp::Not, Value::B(b)) => Some(Value::B(!b)),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    Some(Constant::Basic(out))
}

fn arith(op: BinaryOp, a: Value, b: Value) -> Option<Value> {
    Some(match (a, b) {
        (Value::F(x), Value::F(y)) => Value::F(match op {
            BinaryOp::Add => x + y,
            BinaryOp::Sub => x - y,
            BinaryOp::Mul => x * y,
            BinaryOp::Div => x / y,
            _ => return None,
        }),
        (Value::I(x), Value::I(y)) => Value::I(match op {
            BinaryOp::Add => x.wrapping_add(y),
            BinaryOp::Sub => x.wrapping_sub(y),
            BinaryOp::Mul => x.wrapping_mul(y),
            BinaryOp::Div if y == 0 => return None,
            BinaryOp::Div => x.wrapping_div(y),
            _ => return None,
        }),
        _ => return None,
    })
}

fn compare(op: BinaryOp, a: Value, b: Value) -> Option<bool> {
    let (x, y) = match (a, b) {
        (Value::F(x), Value::F(y)) => (x, y),
        (Value::I(x), Value::I(y)) => {
            return Some(match op {
                BinaryOp::Less => x < y,
                BinaryOp::Greater => x > y,
                BinaryOp::LessEqual => x <= y,
                BinaryOp::GreaterEqual => x >= y,
                _ => return None,
            })
        }
        _ => return None,
    };
    Some(match op {
        BinaryOp::Less => x < y,
        BinaryOp::Greater => x > y,
        BinaryOp::LessEqual => x <= y,
        BinaryOp::GreaterEqual => x >= y,
        _ => return None,
    })
}

/// `l op r`, where `lt`/`rt` are the operand types (after conversion to one scalar kind).
pub fn binary(op: BinaryOp, lt: &Type, l: &Constant, rt: &Type, r: &Constant) -> Option<Constant> {
    match op {
        BinaryOp::Equal | BinaryOp::NotEqual => {
            let eq = l == r;
            return Some(Constant::Basic(vec![Value::B(eq == (op == BinaryOp::Equal))]));
        }
        BinaryOp::And | BinaryOp::Or | BinaryOp::Xor => {
            let (a, b) = (basic(l)?.first()?.as_bool(), basic(r)?.first()?.as_bool());
            let v = match op {
                BinaryOp::And => a && b,
                BinaryOp::Or => a || b,
                _ => a != b,
            };
            return Some(Constant::Basic(vec![Value::B(v)]));
        }
        _ => {}
    }
    let (a, b) = (basic(l)?, basic(r)?);
    match op {
        BinaryOp::Less | BinaryOp::Greater | BinaryOp::LessEqual | BinaryOp::GreaterEqual => {
            Some(Constant::Basic(vec![Value::B(compare(op, *a.first()?, *b.first()?)?)]))
        }
        BinaryOp::MatMul => {
            let f = |v: &[Value]| v.iter().map(|x| x.as_f32()).collect::<Vec<f32>>();
            let (a, b) = (f(a), f(b));
            let out: Vec<f32> = match (lt, rt) {
                (Type::Matrix(c1, r1), Type::Matrix(c2, _)) => {
                    let (c1, r1, c2) = (*c1 as usize, *r1 as usize, *c2 as usize);
                    let mut out = vec![0.0; c2 * r1];
                    for j in 0..c2 {
                        for i in 0..r1 {
                            let mut s = 0.0;
                            for k in 0..c1 {
                                s += a[k * r1 + i] * b[j * c1 + k];
                            }
                            out[j * r1 + i] = s;
                        }
                    }
                    out
                }
                (Type::Matrix(c, r), _) => {
                    let (c, r) = (*c as usize, *r as usize);
                    (0..r).map(|i| (0..c).fold(0.0, |s, k| s + a[k * r + i] * b[k])).collect()
                }
                (_, Type::Matrix(c, r)) => {
                    let (c, r) = (*c as usize, *r as usize);
                    (0..c).map(|j| (0..r).fold(0.0, |s, k| s + a[k] * b[j * r + k])).collect()
                }
                _ => return None,
            };
            Some(Constant::Basic(out.into_iter().map(Value::F).collect()))
        }
        _ => {
            // Component-wise, a scalar applying to every component of the other side.
            let n = a.len().max(b.len());
            let pick = |v: &[Value], i: usize| if v.len() == 1 { v[0] } else { v[i] };
            if (a.len() != 1 && a.len() != n) || (b.len() != 1 && b.len() != n) {
                return None;
            }
            let out = (0..n).map(|i| arith(op, pick(a, i), pick(b, i))).collect::<Option<Vec<_>>>()?;
            Some(Constant::Basic(out))
        }
    }
}

/// Converts every component to `to`.
pub fn convert(c: &Constant, to: Scalar) -> Option<Constant> {
    Some(Constant::Basic(basic(c)?.iter().map(|v| v.convert(to)).collect()))
}

/// A constructor of `ty` from constant arguments of types `arg_types`.
pub fn construct(ty: &Type, arg_types: &[Type], args: &[&Constant]) -> Option<Constant> {
    match ty {
        Type::Array(..) | Type::Struct(_) => Some(Constant::Composite(args.iter().map(|c| (*c).clone()).collect())),
        Type::Matrix(c, r) => {
            let (c, r) = (*c as usize, *r as usize);
            let first = basic(args[0])?;
            if args.len() == 1 && first.len() == 1 {
                // A scalar on the diagonal.
                let d = first[0].as_f32();
                let out = (0..c * r).map(|i| Value::F(if i % r == i / r { d } else { 0.0 })).collect();
                return Some(Constant::Basic(out));
            }
            if let [Type::Matrix(sc, sr)] = arg_types {
                // A matrix from a matrix: the overlap copied, the rest of the identity.
                let (sc, sr) = (*sc as usize, *sr as usize);
                let out = (0..c * r)
                    .map(|i| {
                        let (col, row) = (i / r, i % r);
                        Value::F(if col < sc && row < sr {
                            first[col * sr + row].as_f32()
                        } else if col == row {
                            1.0
                        } else {
                            0.0
                        })
                    })
                    .collect();
                return Some(Constant::Basic(out));
            }
            let all: Vec<Value> = args.iter().filter_map(|a| basic(a)).flatten().copied().collect();
            Some(Constant::Basic(all.into_iter().take(c * r).map(|v| v.convert(Scalar::Float)).collect()))
        }
        _ => {
            let base = ty.base()?;
            let n = ty.components();
            let first = basic(args[0])?;
            if args.len() == 1 && first.len() == 1 {
                return Some(Constant::Basic(vec![first[0].convert(base); n]));
            }
            let all: Vec<Value> = args.iter().filter_map(|a| basic(a)).flatten().copied().collect();
            if all.len() < n {
                return None;
            }
            Some(Constant::Basic(all.into_iter().take(n).map(|v| v.convert(base)).collect()))
        }
    }
}

pub fn swizzle(c: &Constant, components: &[u8]) -> Option<Constant> {
    let v = basic(c)?;
    Some(Constant::Basic(components.iter().map(|&i| v.get(i as usize).copied()).collect::<Option<_>>()?))
}

/// Element `index` of an array, vector (a component) or matrix (a column of `rows`).
pub fn index(ty: &Type, c: &Constant, index: usize) -> Option<Constant> {
    match (ty, c) {
        (_, Constant::Composite(items)) => items.get(index).cloned(),
        (Type::Matrix(_, r), Constant::Basic(v)) => {
            let r = *r as usize;
            Some(Constant::Basic(v.get(index * r..index * r + r)?.to_vec()))
        }
        (_, Constant::Basic(v)) => Some(Constant::Basic(vec![*v.get(index)?])),
    }
}

pub fn field(c: &Constant, member: usize) -> Option<Constant> {
    match c {
        Constant::Composite(items) => items.get(member).cloned(),
        Constant::Basic(_) => None,
    }
}

/// The integer `abs`, `sign`, `min`, `max` and `clamp` of constant arguments (`n`
/// components; a scalar argument applies to every component).
fn integer_builtin(name: &str, n: usize, vals: &[&[Value]]) -> Option<Constant> {
    let at = |i: usize, k: usize| -> Option<i32> {
        let v = vals.get(i)?;
        match if v.len() == 1 { v[0] } else { *v.get(k)? } {
            Value::I(x) => Some(x),
            _ => None,
        }
    };
    let each = |g: &dyn Fn(usize) -> Option<i32>| -> Option<Constant> {
        Some(Constant::Basic((0..n).map(|k| g(k).map(Value::I)).collect::<Option<_>>()?))
    };
    match name {
        "abs" => each(&|k| Some(at(0, k)?.wrapping_abs())),
        "sign" => each(&|k| Some(at(0, k)?.signum())),
        "min" => each(&|k| Some(at(0, k)?.min(at(1, k)?))),
        "max" => each(&|k| Some(at(0, k)?.max(at(1, k)?))),
        "clamp" => each(&|k| Some(at(0, k)?.max(at(1, k)?).min(at(2, k)?))),
        _ => None,
    }
}

/// A built-in function of constant arguments, if it is one GLSL folds (not the texture
/// lookups, noise, derivatives or `ftransform`). `ret` is the signature's return type.
/// `min` as the executor's `FMin`: `y < x ? y : x`, and `y` when `x` is NaN.
fn fmin(x: f32, y: f32) -> f32 {
    if y < x || x.is_nan() {
        y
    } else {
        x
    }
}

/// `max` as the executor's `FMax`: `x < y ? y : x`, and `y` when `x` is NaN.
fn fmax(x: f32, y: f32) -> f32 {
    if x < y || x.is_nan() {
        y
    } else {
        x
    }
}

pub fn builtin(name: &str, ret: &Type, arg_types: &[Type], args: &[&Constant]) -> Option<Constant> {
    let vals: Vec<&[Value]> = args.iter().map(|c| basic(c)).collect::<Option<_>>()?;
    if ret.base() == Some(Scalar::Int) {
        return integer_builtin(name, ret.components().max(1), &vals);
    }
    let f = |i: usize| vals[i].iter().map(|v| v.as_f32()).collect::<Vec<f32>>();
    let floats = |v: Vec<f32>| Some(Constant::Basic(v.into_iter().map(Value::F).collect()));
    let bools = |v: Vec<bool>| Some(Constant::Basic(v.into_iter().map(Value::B).collect()));
    let n = ret.components().max(1);
    // Argument `i`'s component `k`, a scalar argument applying to every component.
    let at = |i: usize, k: usize| {
        let v = vals[i];
        if v.len() == 1 {
            v[0].as_f32()
        } else {
            v[k].as_f32()
        }
    };
    let map1 = |g: &dyn Fn(f32) -> f32| floats((0..n).map(|k| g(at(0, k))).collect());
    let map2 = |g: &dyn Fn(f32, f32) -> f32| floats((0..n).map(|k| g(at(0, k), at(1, k))).collect());
    let map3 = |g: &dyn Fn(f32, f32, f32) -> f32| floats((0..n).map(|k| g(at(0, k), at(1, k), at(2, k))).collect());
    let dot = |a: &[f32], b: &[f32]| a.iter().zip(b).fold(0.0f32, |s, (x, y)| s + x * y);
    let cmp = |g: &dyn Fn(Value, Value) -> bool| bools(vals[0].iter().zip(vals[1]).map(|(a, b)| g(*a, *b)).collect());
    let lt = |a: Value, b: Value| match (a, b) {
        (Value::I(x), Value::I(y)) => x < y,
        _ => a.as_f32() < b.as_f32(),
    };
    match name {
        "radians" => map1(&|x| x * (std::f32::consts::PI / 180.0)),
        "degrees" => map1(&|x| x * (180.0 / std::f32::consts::PI)),
        "sin" => map1(&f32::sin),
        "cos" => map1(&f32::cos),
        "tan" => map1(&f32::tan),
        "asin" => map1(&f32::asin),
        "acos" => map1(&f32::acos),
        "atan" if args.len() == 2 => map2(&f32::atan2),
        "atan" => map1(&f32::atan),
        "pow" => map2(&f32::powf),
        "exp" => map1(&f32::exp),
        "log" => map1(&f32::ln),
        "exp2" => map1(&f32::exp2),
        "log2" => map1(&f32::log2),
        "sqrt" => map1(&f32::sqrt),
        "inversesqrt" => map1(&|x| 1.0 / x.sqrt()),
        "abs" => map1(&f32::abs),
        "sign" => map1(&|x| {
            if x > 0.0 {
                1.0
            } else if x < 0.0 {
                -1.0
            } else {
                0.0
            }
        }),
        "floor" => map1(&f32::floor),
        "ceil" => map1(&f32::ceil),
        "fract" => map1(&|x| x - x.floor()),
        "mod" => map2(&|x, y| x - y * (x / y).floor()),
        // As the executor's FMin / FMax: a NaN operand gives the other one.
        "min" => map2(&fmin),
        "max" => map2(&fmax),
        "clamp" => map3(&|x, lo, hi| fmin(fmax(x, lo), hi)),
        "mix" => map3(&|x, y, a| x * (1.0 - a) + y * a),
        "step" => map2(&|edge, x| if x < edge { 0.0 } else { 1.0 }),
        "smoothstep" => map3(&|e0, e1, x| {
            let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
            t * t * (3.0 - 2.0 * t)
        }),
        "length" => floats(vec![dot(&f(0), &f(0)).sqrt()]),
        "distance" => {
            let d: Vec<f32> = f(0).iter().zip(f(1)).map(|(a, b)| a - b).collect();
            floats(vec![dot(&d, &d).sqrt()])
        }
        "dot" => floats(vec![dot(&f(0), &f(1))]),
        "cross" => {
            let (a, b) = (f(0), f(1));
            floats(vec![a[1] * b[2] - b[1] * a[2], a[2] * b[0] - b[2] * a[0], a[0] * b[1] - b[0] * a[1]])
        }
        "normalize" => {
            let a = f(0);
            let l = dot(&a, &a).sqrt();
            floats(a.iter().map(|x| x / l).collect())
        }
        "faceforward" => {
            let (nn, i, nref) = (f(0), f(1), f(2));
            let s = if dot(&nref, &i) < 0.0 { 1.0 } else { -1.0 };
            floats(nn.iter().map(|x| x * s).collect())
        }
        "reflect" => {
            let (i, nn) = (f(0), f(1));
            let d = 2.0 * dot(&nn, &i);
            floats(i.iter().zip(&nn).map(|(a, b)| a - d * b).collect())
        }
        "refract" => {
            let (i, nn, eta) = (f(0), f(1), f(2)[0]);
            let d = dot(&nn, &i);
            let k = 1.0 - eta * eta * (1.0 - d * d);
            if k < 0.0 {
                floats(vec![0.0; i.len()])
            } else {
                floats(i.iter().zip(&nn).map(|(a, b)| eta * a - (eta * d + k.sqrt()) * b).collect())
            }
        }
        "lessThan" => cmp(&lt),
        "lessThanEqual" => cmp(&|a, b| !lt(b, a)),
        "greaterThan" => cmp(&|a, b| lt(b, a)),
        "greaterThanEqual" => cmp(&|a, b| !lt(a, b)),
        "equal" => cmp(&|a, b| a == b),
        "notEqual" => cmp(&|a, b| a != b),
        "any" => bools(vec![vals[0].iter().any(|v| v.as_bool())]),
        "all" => bools(vec![vals[0].iter().all(|v| v.as_bool())]),
        "not" => bools(vals[0].iter().map(|v| !v.as_bool()).collect()),
        // A constant has no derivative.
        "dFdx" | "dFdy" | "fwidth" => floats(vec![0.0; n]),
        "matrixCompMult" => map2(&|x, y| x * y),
        "outerProduct" => {
            let (c, r) = (f(0), f(1));
            floats(r.iter().flat_map(|y| c.iter().map(move |x| x * y)).collect())
        }
        "transpose" => {
            let (Type::Matrix(c, r), m) = (&arg_types[0], f(0)) else { return None };
            let (c, r) = (*c as usize, *r as usize);
            floats((0..c * r).map(|i| m[(i % c) * r + i / c]).collect())
        }
        _ => None,
    }
}
