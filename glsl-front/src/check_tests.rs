//! Tests of semantic analysis: the types it gives expressions, the overloads it chooses,
//! the values it folds, and its messages with their positions.

use super::hir::*;
use super::{compile_shader, InfoLog, Options, Stage};

fn compile(source: &str, stage: Stage) -> Result<Checked, String> {
    let mut log = InfoLog::default();
    compile_shader(source, stage, &Options::default(), &mut log).ok_or_else(|| log.text())
}

fn frag(source: &str) -> Checked {
    compile(source, Stage::Fragment).unwrap_or_else(|log| panic!("{log}"))
}

/// The first error of a fragment (or vertex) shader that must not compile.
fn error(source: &str, stage: Stage) -> String {
    let log = compile(source, stage).expect_err("compile error");
    log.lines().next().unwrap_or_default().to_string()
}

/// The initializer of local variable `name` in `main`.
fn init<'a>(c: &'a Checked, name: &str) -> &'a Expr {
    fn find<'a>(stmts: &'a [Stmt], c: &Checked, name: &str) -> Option<&'a Expr> {
        stmts.iter().find_map(|s| match s {
            Stmt::Declare(v, Some(e)) if c.variables[*v].name == name => Some(e),
            Stmt::Block(b) => find(b, c, name),
            _ => None,
        })
    }
    let main = &c.functions[c.main.expect("main")];
    find(main.body.as_ref().expect("body"), c, name).unwrap_or_else(|| panic!("no `{name}'"))
}

fn floats(e: &Expr) -> Vec<f32> {
    e.constant().unwrap_or_else(|| panic!("not folded: {e:?}")).components().iter().map(|v| v.as_f32()).collect()
}

#[test]
fn expressions_get_glsl_types() {
    let c = frag(
        "#version 120\nuniform mat2x3 m; uniform vec2 v; uniform vec3 w; uniform mat3 n; uniform ivec2 iv;\n\
         void main() {\n\
           vec3 a = m * v;\n  vec2 b = w * m;\n  mat3x2 t = transpose(m);\n  mat2x3 p = n * m;\n\
           vec3 s = 2.0 * w;\n  bvec2 lt = lessThan(iv, ivec2(1));\n  vec2 sw = w.zx;\n  float d = dot(w, w);\n\
           gl_FragColor = vec4(a, b.x) + vec4(s, d) + vec4(t[0], sw) + vec4(p[1], float(lt.x));\n}\n",
    );
    let ty = |n: &str| init(&c, n).ty.to_string();
    assert_eq!(ty("a"), "vec3");
    assert_eq!(ty("b"), "vec2");
    assert_eq!(ty("t"), "mat3x2");
    assert_eq!(ty("p"), "mat2x3");
    assert_eq!(ty("lt"), "bvec2");
    assert_eq!(ty("sw"), "vec2");
    assert_eq!(ty("d"), "float");
    // Linear-algebra products are their own operator; scalar × vector is component-wise.
    assert!(matches!(init(&c, "a").kind, ExprKind::Binary(BinaryOp::MatMul, ..)));
    assert!(matches!(init(&c, "b").kind, ExprKind::Binary(BinaryOp::MatMul, ..)));
    assert!(matches!(init(&c, "s").kind, ExprKind::Binary(BinaryOp::Mul, ..)));
    assert!(matches!(&init(&c, "sw").kind, ExprKind::Swizzle(_, comps) if comps == &[2, 0]));
}

#[test]
fn implicit_conversions_only_in_120() {
    let c = frag("#version 120\nuniform int i;\nvoid main() { float f = i; float g = 1; vec2 v = ivec2(i) + vec2(1.0); gl_FragColor = vec4(f, g, v); }\n");
    assert!(matches!(&init(&c, "f").kind, ExprKind::Convert(e) if e.ty == INT));
    assert_eq!(init(&c, "f").ty, FLOAT);
    // A constant converts at compile time.
    assert_eq!(init(&c, "g").kind, ExprKind::Constant(Constant::Basic(vec![Value::F(1.0)])));
    assert!(
        matches!(&init(&c, "v").kind, ExprKind::Binary(BinaryOp::Add, l, _) if matches!(l.kind, ExprKind::Convert(_)))
    );
    assert_eq!(
        error("uniform int i;\nvoid main() {\n  float f = i;\n}\n", Stage::Fragment),
        "0:3(8): error: initializer of type `int' cannot be assigned to variable of type `float'"
    );
    assert_eq!(
        error("void main() {\n  gl_FragColor = vec4(1.0) * 2;\n}\n", Stage::Fragment),
        "0:2(27): error: could not implicitly convert operands to arithmetic operator `*'"
    );
    // No conversion between arrays, even in 1.20.
    assert!(compile("#version 120\nvoid main() { float a[2] = int[2](1, 2); }\n", Stage::Fragment).is_err());
}

#[test]
fn overloads_choose_exact_then_converted() {
    let c = frag(
        "#version 120\nfloat f(float x) { return 1.0; }\nfloat f(int x) { return 2.0; }\nfloat g(float x) { return x; }\n\
         uniform vec3 w;\nvoid main() { float a = f(1); float b = f(1.0); float c = g(1); vec3 m = max(w, 1.0); vec3 n = max(w, w);\n\
         gl_FragColor = vec4(a, b, c, m.x + n.x); }\n",
    );
    let callee = |n: &str| match &init(&c, n).kind {
        ExprKind::Call(f, args) => (c.variables[c.functions[*f].parameters[0].var].ty.clone(), args[0].ty.clone()),
        other => panic!("{other:?}"),
    };
    assert_eq!(callee("a"), (INT, INT));
    assert_eq!(callee("b"), (FLOAT, FLOAT));
    // Through the int → float conversion, which is explicit in the result.
    assert_eq!(callee("c"), (FLOAT, FLOAT));
    assert!(matches!(&init(&c, "c").kind, ExprKind::Call(_, args) if args[0].constant().is_some()));
    let builtin_args = |n: &str| match &init(&c, n).kind {
        ExprKind::Builtin(name, args) => (name.to_string(), args.iter().map(|a| a.ty.to_string()).collect::<Vec<_>>()),
        other => panic!("{other:?}"),
    };
    assert_eq!(builtin_args("m"), ("max".into(), vec!["vec3".into(), "float".into()]));
    assert_eq!(builtin_args("n"), ("max".into(), vec!["vec3".into(), "vec3".into()]));
    assert_eq!(
        error(
            "#version 120\nvoid h(float a, int b) {}\nvoid h(int a, float b) {}\nvoid main() {\n  h(1, 1);\n}\n",
            Stage::Fragment
        ),
        "0:5(2): error: call to `h(int, int)' is ambiguous"
    );
    assert_eq!(
        error("void main() {\n  gl_FragColor = vec4(sin(1, 2));\n}\n", Stage::Fragment),
        "0:2(22): error: no matching function for call to `sin(int, int)'"
    );
}

#[test]
fn integer_min_max_clamp_abs_sign_in_110_as_mesa() {
    let c = frag(
        "uniform int u;\nvoid main() { int a = min(u, 4); ivec2 b = max(ivec2(u), 2); ivec3 k = clamp(ivec3(u), 0, 9);\n\
         int s = sign(u) + abs(u);\n  int f = min(7, 3) + max(-2, 1) + clamp(12, 0, 5) + abs(-3) + sign(-7);\n\
         ivec2 g = clamp(ivec2(-5, 5), ivec2(-1), ivec2(1));\n  gl_FragColor = vec4(float(a + b.x + k.y + s + f + g.y)); }\n",
    );
    let builtin_ty = |n: &str| match &init(&c, n).kind {
        ExprKind::Builtin(name, args) => (name.to_string(), init(&c, n).ty.to_string(), args[1].ty.to_string()),
        other => panic!("{other:?}"),
    };
    assert_eq!(builtin_ty("a"), ("min".into(), "int".into(), "int".into()));
    assert_eq!(builtin_ty("b"), ("max".into(), "ivec2".into(), "int".into()));
    assert_eq!(builtin_ty("k"), ("clamp".into(), "ivec3".into(), "int".into()));
    // Folded as integers: 3 + 1 + 5 + 3 − 1 (no `const` initializers: in 1.10 a built-in
    // call is no constant expression, though its value is folded).
    assert!(
        compile("void main() { const int f = min(7, 3); gl_FragColor = vec4(float(f)); }\n", Stage::Fragment).is_err()
    );
    assert_eq!(init(&c, "f").constant().unwrap().components(), [Value::I(11)]);
    assert_eq!(init(&c, "g").constant().unwrap().components(), [Value::I(-1), Value::I(1)]);
    // Still no implicit int-to-float conversion in 1.10, nor mixed overloads.
    assert_eq!(
        error("uniform float f;\nvoid main() {\n  float m = min(f, 4);\n}\n", Stage::Fragment),
        "0:3(12): error: no matching function for call to `min(float, int)'"
    );
    assert!(compile("uniform int u;\nvoid main() { float m = min(u, 4); }\n", Stage::Fragment).is_err());
    assert!(compile("uniform int u;\nvoid main() { int m = mod(u, 4); }\n", Stage::Fragment).is_err());
}

#[test]
fn constant_expressions_fold() {
    let c = frag(
        "#version 120\nconst float k = 2.0;\nvoid main() {\n\
           const float x = sin(0.0) + k * 3.0;\n  const ivec2 d = ivec2(7, -7) / 2;\n\
           const mat2 m = mat2(1.0, 2.0, 3.0, 4.0) * mat2(2.0);\n  const vec2 mv = mat2(1.0, 2.0, 3.0, 4.0) * vec2(1.0, 1.0);\n\
           float a[int(3.7) + 1];\n  const int len = a.length();\n  const vec4 s = vec4(1, 2, 3, 4).wzyx;\n\
           const float arr[3] = float[](1.0, 2.0, 3.0);\n  const float e = arr[2] + max(1.0, 2.0);\n\
           const mat3 big = mat3(mat2(5.0));\n  const bool b = all(equal(vec2(1.0), vec2(1.0))) && !(1 > 2);\n\
           gl_FragColor = vec4(x, float(d.y), m[1][0], mv.y + float(len) + s.x + e + big[2][2]);\n}\n",
    );
    assert_eq!(floats(init(&c, "x")), [6.0]);
    // Integer division truncates towards zero.
    assert_eq!(init(&c, "d").constant().unwrap().components(), [Value::I(3), Value::I(-3)]);
    assert_eq!(floats(init(&c, "m")), [2.0, 4.0, 6.0, 8.0]);
    // Column-major: (1 3; 2 4) × (1, 1) = (4, 6).
    assert_eq!(floats(init(&c, "mv")), [4.0, 6.0]);
    assert_eq!(init(&c, "len").constant().unwrap().components(), [Value::I(4)]);
    assert_eq!(floats(init(&c, "s")), [4.0, 3.0, 2.0, 1.0]);
    assert_eq!(floats(init(&c, "e")), [5.0]);
    // A matrix from a smaller one: the rest from the identity.
    assert_eq!(floats(init(&c, "big")), [5.0, 0.0, 0.0, 0.0, 5.0, 0.0, 0.0, 0.0, 1.0]);
    assert_eq!(init(&c, "b").constant().unwrap().components(), [Value::B(true)]);
    let a = c.variables.iter().find(|v| v.name == "a").unwrap();
    assert_eq!(a.ty.to_string(), "float[4]");
    assert_eq!(
        error("uniform int n;\nvoid main() {\n  float a[n];\n}\n", Stage::Fragment),
        "0:3(10): error: array size must be a constant valued expression"
    );
    assert_eq!(
        error("void main() {\n  float a[2 - 2];\n}\n", Stage::Fragment),
        "0:2(12): error: array size must be > 0"
    );
    assert_eq!(
        error("uniform float u;\nvoid main() {\n  const float c = u;\n}\n", Stage::Fragment),
        "0:3(14): error: initializer of const variable `c' must be a constant expression"
    );
}

#[test]
fn stage_rules_for_built_ins() {
    assert!(compile("void main() { gl_Position = ftransform(); gl_TexCoord[3] = gl_MultiTexCoord0; }", Stage::Vertex)
        .is_ok());
    assert!(compile("void main() { gl_FragColor = vec4(dFdx(gl_FragCoord.x)); }", Stage::Fragment).is_ok());
    assert_eq!(
        error("void main() {\n  gl_Position = vec4(dFdx(1.0));\n}\n", Stage::Vertex),
        "0:2(21): error: no matching function for call to `dFdx(float)' in this shader stage or version"
    );
    assert!(compile("void main() { gl_FragColor = ftransform(); }", Stage::Fragment).is_err());
    assert!(compile(
        "uniform sampler2D s; void main() { gl_FragColor = texture2DLod(s, vec2(0.0), 1.0); }",
        Stage::Fragment
    )
    .is_err());
    assert!(compile(
        "uniform sampler2D s; void main() { gl_Position = texture2DLod(s, vec2(0.0), 1.0); }",
        Stage::Vertex
    )
    .is_ok());
    assert_eq!(
        error("void main() {\n  gl_FragColor = gl_Vertex;\n}\n", Stage::Fragment),
        "0:2(17): error: `gl_Vertex' undeclared"
    );
    assert_eq!(
        error("void main() {\n  discard;\n}\n", Stage::Vertex),
        "0:2(2): error: discard may only appear in a fragment shader"
    );
    assert_eq!(
        error("void main() {\n  gl_Color = vec4(1.0);\n}\n", Stage::Fragment),
        "0:2(2): error: assignment to varying variable `gl_Color'"
    );
    // gl_PointCoord is 1.20's; the uniform state has its struct types.
    assert!(compile("void main() { gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }", Stage::Fragment).is_err());
    let c = frag("#version 120\nvoid main() { vec3 d = gl_LightSource[gl_MaxLights - 1].spotDirection; float f = gl_Fog.density; gl_FragColor = vec4(d, f); }\n");
    assert_eq!(init(&c, "d").ty.to_string(), "vec3");
}

#[test]
fn statements_and_declarations_are_checked() {
    assert_eq!(
        error("void main() {\n  break;\n}\n", Stage::Fragment),
        "0:2(2): error: break may only appear in a loop"
    );
    assert_eq!(
        error("float f() {\n  return;\n}\nvoid main() {}\n", Stage::Fragment),
        "0:2(2): error: `return' with no value, in function f returning non-void"
    );
    assert_eq!(
        error("void main() {\n  if (1) {}\n}\n", Stage::Fragment),
        "0:2(6): error: if-statement condition must be scalar boolean"
    );
    assert_eq!(error("void main() {\n  float a;\n  int a;\n}\n", Stage::Fragment), "0:3(6): error: `a' redeclared");
    assert_eq!(
        error("attribute vec4 a;\nvoid main() {}\n", Stage::Fragment),
        "0:1(1): error: `attribute' variables may not be declared in a fragment shader"
    );
    assert_eq!(
        error("void main() {\n  vec2 v = vec2(1.0).xz;\n}\n", Stage::Fragment),
        "0:2(20): error: invalid swizzle / mask `xz'"
    );
    assert_eq!(
        error("void main() {\n  vec4 v;\n  v.xx = vec2(1.0);\n}\n", Stage::Fragment).split(':').nth(2).unwrap().trim(),
        "error"
    );
    assert_eq!(
        error("void main() {\n  vec3 v = vec3(1.0, 2.0, 3.0, 4.0);\n}\n", Stage::Fragment),
        "0:2(11): error: too many parameters to `vec3' constructor"
    );
    // Shadowing in an inner scope is allowed; a name is visible from its declaration on.
    assert!(compile("void main() { float a = 1.0; { int a = 2; } gl_FragColor = vec4(a); }", Stage::Fragment).is_ok());
}

#[test]
fn pathological_nesting_is_an_error() {
    let mut src = String::from("void main() { float a = 1.0; gl_FragColor = vec4(a");
    for _ in 0..5000 {
        src.push_str(" + a");
    }
    src.push_str("); }\n");
    let log = compile(&src, Stage::Fragment).expect_err("refused");
    // The parser refuses the chain before the checker walks it (`parse::MAX_CHAIN`).
    assert!(log.contains("operators in a row"), "{log}");
}
