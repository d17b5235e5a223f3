//! Tests of the lowering: small shaders compiled, lowered, run on the reference executor
//! over 16 lanes with per-lane inputs and uniforms, their outputs checked against values
//! computed in Rust.

use super::{lower, Lowered, Word};
use crate::glsl::{compile_shader, InfoLog, Options, Stage};
use crate::shader::exec::{Executor, Io, NoTextures, SampleRequest, Textures, ALL_LANES, LANES};
use crate::shader::ir::{self, Lod};
use std::collections::HashMap;

fn compile(stage: Stage, src: &str) -> crate::glsl::Checked {
    let mut log = InfoLog::default();
    compile_shader(src, stage, &Options::default(), &mut log).unwrap_or_else(|| panic!("{}\n{src}", log.text()))
}

fn lowered(stage: Stage, src: &str) -> Lowered {
    let c = compile(stage, src);
    let l = lower(&[&c]).unwrap_or_else(|e| panic!("{e}\n{src}"));
    // The dump works on every lowered program.
    assert!(!crate::shader::dump::dump(&l.program).is_empty());
    l
}

/// The outputs of one run: by (element name, word index), the 16 lanes as f32 (bools and
/// ints converted), and the lanes that did not discard.
struct Run {
    out: HashMap<(String, u32), [f32; LANES]>,
    alive: u16,
}

impl Run {
    fn get(&self, name: &str, index: u32) -> [f32; LANES] {
        *self
            .out
            .get(&(name.to_string(), index))
            .unwrap_or_else(|| panic!("no output {name}[{index}]: {:?}", self.out.keys()))
    }

    /// Lane 0 of an output element's words.
    fn vec(&self, name: &str, n: u32) -> Vec<f32> {
        (0..n).map(|i| self.get(name, i)[0]).collect()
    }
}

fn to_word(ty: ir::Type, v: f32) -> u32 {
    match ty {
        ir::Type::F32 => v.to_bits(),
        ir::Type::I32 => v as i32 as u32,
        ir::Type::U32 => v as u32,
        ir::Type::Bool => (v != 0.0) as u32,
    }
}

fn from_word(ty: ir::Type, w: u32) -> f32 {
    match ty {
        ir::Type::F32 => f32::from_bits(w),
        ir::Type::I32 => w as i32 as f32,
        ir::Type::U32 => w as f32,
        ir::Type::Bool => w as f32,
    }
}

/// Runs a lowered program: `uniform(word)` and `input(word, lane)` give the values.
fn execute(
    l: &Lowered,
    uniform: &dyn Fn(&Word) -> f32,
    input: &dyn Fn(&Word, usize) -> f32,
    textures: &dyn Textures,
) -> Run {
    let p = &l.program;
    let uniforms: Vec<u32> = l.uniforms.iter().zip(&p.uniforms).map(|(w, &t)| to_word(t, uniform(w))).collect();
    let inputs: Vec<[u32; LANES]> =
        l.inputs.iter().zip(&p.inputs).map(|(w, &t)| std::array::from_fn(|lane| to_word(t, input(w, lane)))).collect();
    let mut outputs = vec![[0u32; LANES]; p.outputs.len()];
    let alive = Executor::new().run(
        p,
        &mut Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures },
        ALL_LANES,
    );
    let out = l
        .outputs
        .iter()
        .zip(&p.outputs)
        .zip(&outputs)
        .map(|((w, &t), v)| ((w.name.clone(), w.index), v.map(|x| from_word(t, x))))
        .collect();
    Run { out, alive }
}

/// A fragment shader run with uniforms by element name and the lane number as the input
/// `lane` (a float varying) in every lane.
fn frag(src: &str, uniforms: &[(&str, &[f32])]) -> Run {
    let l = lowered(Stage::Fragment, src);
    let table: HashMap<&str, &[f32]> = uniforms.iter().copied().collect();
    execute(
        &l,
        &|w| table.get(w.name.as_str()).map_or(0.0, |v| v[w.index as usize]),
        &|w, lane| if w.name == "lane" { lane as f32 } else { 0.0 },
        &NoTextures,
    )
}

const LANE: &str = "#version 120\nvarying float lane;\n";

#[test]
fn arithmetic_vectors_scalars_and_ints() {
    let r = frag(
        &format!(
            "{LANE}uniform vec4 u; uniform int k;
            void main() {{
                vec4 a = u * 2.0 + vec4(1.0, 2.0, 3.0, 4.0) / 4.0 - u.wzyx;
                int i = k * 7 / 2 + -k;
                ivec2 d = ivec2(7, -7) / ivec2(2, 2);
                gl_FragColor = vec4(a.x, float(i), float(d.x), float(d.y)) + vec4(0.0, 0.0, 0.0, a.w);
            }}"
        ),
        &[("u", &[1.0, 2.0, 3.0, 4.0]), ("k", &[3.0])],
    );
    // ints divide truncating toward zero: 21 / 2 = 10, −7 / 2 = −3.
    assert_eq!(r.vec("gl_FragColor", 4), vec![1.0 * 2.0 + 0.25 - 4.0, 7.0, 3.0, -3.0 + 8.0]);
}

#[test]
fn matrices_products_and_constructors() {
    // Non-square: mat2x3 has 2 columns of 3 rows.
    let r = frag(
        "#version 120
        uniform mat2x3 m; uniform vec2 v; uniform vec3 w; uniform mat2 s;
        void main() {
            vec3 mv = m * v;            // 3 rows
            vec2 wm = w * m;            // 2 columns
            mat2 ss = s * s;
            mat3 id = mat3(2.0);
            mat3 big = mat3(mat2(5.0));
            mat2 small = mat2(mat3(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0));
            gl_FragData[0] = vec4(mv, wm.x);
            gl_FragData[1] = vec4(wm.y, ss[0][0], ss[1][0], ss[1][1]);
            gl_FragData[2] = vec4(id[0][0], id[1][0], big[1][1], big[2][2]);
            gl_FragData[3] = vec4(small[0], small[1]);
        }",
        &[
            ("m", &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]),
            ("v", &[10.0, 100.0]),
            ("w", &[1.0, 0.5, 0.25]),
            ("s", &[1.0, 2.0, 3.0, 4.0]),
        ],
    );
    // m columns: (1,2,3), (4,5,6). m*v = 10*(1,2,3) + 100*(4,5,6).
    let mv = [410.0, 520.0, 630.0];
    let wm = [1.0 + 1.0 + 0.75, 4.0 + 2.5 + 1.5];
    // s = [[1,2],[3,4]] columns; s*s column 0 = s*(1,2) = (1+6, 2+8) = (7, 10); column 1 = s*(3,4) = (3+12, 6+16).
    assert_eq!(r.vec("gl_FragData[0]", 4), vec![mv[0], mv[1], mv[2], wm[0]]);
    assert_eq!(r.vec("gl_FragData[1]", 4), vec![wm[1], 7.0, 15.0, 22.0]);
    assert_eq!(r.vec("gl_FragData[2]", 4), vec![2.0, 0.0, 5.0, 1.0]);
    assert_eq!(r.vec("gl_FragData[3]", 4), vec![1.0, 2.0, 4.0, 5.0]);
}

#[test]
fn swizzle_writes_and_compound_assignment() {
    let r = frag(
        &format!(
            "{LANE}void main() {{
                vec4 v = vec4(0.0);
                v.zx = vec2(1.0, 2.0);
                v.y += 3.0;
                v.wy *= vec2(2.0, 10.0);
                v.xyz.y -= 1.0;
                gl_FragColor = v + lane;
            }}"
        ),
        &[],
    );
    for lane in 0..16 {
        let l = lane as f32;
        assert_eq!([0, 1, 2, 3].map(|i| r.get("gl_FragColor", i)[lane]), [2.0 + l, 29.0 + l, 1.0 + l, 0.0 + l]);
    }
}

#[test]
fn structs_arrays_and_dynamic_indexing() {
    let r = frag(
        &format!(
            "{LANE}struct S {{ vec2 a; float b[3]; }};
            uniform S s[2];
            uniform float t[4];
            void main() {{
                int i = int(lane) - (int(lane) / 4) * 4;   // lane mod 4
                float local[4];
                for (int k = 0; k < 4; k++) local[k] = float(k * 10);
                local[i] += 1.0;                           // dynamic write
                S copy = s[1];
                copy.b[i - (i / 3) * 3] = 7.0;
                vec4 v = vec4(0.0);
                v[i] = 2.0;                                // dynamic vector component
                mat2 m = mat2(1.0, 2.0, 3.0, 4.0);
                gl_FragData[0] = vec4(t[i], local[i], copy.b[0] + copy.a.y, s[i / 2].b[i / 2 + 1]);
                gl_FragData[1] = vec4(v[3], m[i / 2][1], local[3 - i], copy.b[1]);
            }}"
        ),
        &[
            ("t[0]", &[1.0]),
            ("t[1]", &[2.0]),
            ("t[2]", &[3.0]),
            ("t[3]", &[4.0]),
            ("s[1].a", &[5.0, 6.0]),
            ("s[1].b[0]", &[100.0]),
            ("s[1].b[1]", &[21.0]),
            ("s[1].b[2]", &[22.0]),
            ("s[0].b[1]", &[11.0]),
            ("s[0].b[2]", &[12.0]),
        ],
    );
    for lane in 0..16usize {
        let i = lane % 4;
        let t = [1.0, 2.0, 3.0, 4.0][i];
        let mut local = [0.0, 10.0, 20.0, 30.0];
        local[i] += 1.0;
        let mut b = [100.0, 21.0, 22.0];
        b[i % 3] = 7.0;
        let s_b = [[0.0, 11.0, 12.0], [100.0, 21.0, 22.0]][i / 2][i / 2 + 1];
        let v3 = if i == 3 { 2.0 } else { 0.0 };
        let m = [[1.0, 2.0], [3.0, 4.0]][i / 2][1];
        assert_eq!(
            [0, 1, 2, 3].map(|k| r.get("gl_FragData[0]", k)[lane]),
            [t, local[i], b[0] + 6.0, s_b],
            "lane {lane}"
        );
        assert_eq!([0, 1, 2, 3].map(|k| r.get("gl_FragData[1]", k)[lane]), [v3, m, local[3 - i], b[1]], "lane {lane}");
    }
}

#[test]
fn loops_with_break_and_continue() {
    let r = frag(
        &format!(
            "{LANE}void main() {{
                float sum = 0.0;
                for (int k = 0; k < 10; k++) {{
                    if (float(k) == lane) continue;
                    if (float(k) > lane + 2.0) break;
                    sum += float(k);
                }}
                float w = 0.0; int n = 0;
                while (n < int(lane)) {{ n++; w += 2.0; }}
                int m = 0;
                do {{ m += 3; }} while (m < int(lane));
                gl_FragColor = vec4(sum, w, float(m), float(n));
            }}"
        ),
        &[],
    );
    for lane in 0..16usize {
        let mut sum = 0.0;
        for k in 0..10 {
            if k == lane {
                continue;
            }
            if k as f32 > lane as f32 + 2.0 {
                break;
            }
            sum += k as f32;
        }
        let mut m = 0;
        loop {
            m += 3;
            if m >= lane {
                break;
            }
        }
        assert_eq!(
            [0, 1, 2, 3].map(|i| r.get("gl_FragColor", i)[lane]),
            [sum, 2.0 * lane as f32, m as f32, lane as f32],
            "lane {lane}"
        );
    }
}

#[test]
fn early_returns_from_main_and_functions_under_divergence() {
    let r = frag(
        &format!(
            "{LANE}float f(float x) {{
                for (int k = 0; k < 8; k++) {{
                    if (float(k) >= x) return float(k) * 10.0;
                    for (int j = 0; j < 3; j++) {{ if (j == 1 && x > 12.0) return -1.0; }}
                }}
                if (x > 100.0) return 5.0;
                return 99.0;
            }}
            float g(float x) {{ if (x < 3.0) return 1.0; return 2.0; }}
            void main() {{
                gl_FragColor = vec4(f(lane), g(lane), 0.0, 0.0);
                if (lane > 5.0) return;
                gl_FragColor.z = 3.0;
            }}"
        ),
        &[],
    );
    for lane in 0..16usize {
        let x = lane as f32;
        let f = if x > 12.0 {
            -1.0
        } else if x <= 7.0 {
            x.ceil() * 10.0
        } else {
            99.0
        };
        let g = if x < 3.0 { 1.0 } else { 2.0 };
        let z = if x > 5.0 { 0.0 } else { 3.0 };
        assert_eq!([0, 1, 2].map(|i| r.get("gl_FragColor", i)[lane]), [f, g, z], "lane {lane}");
    }
}

#[test]
fn discard_per_lane() {
    let r = frag(&format!("{LANE}void main() {{ if (lane > 9.0) discard; gl_FragColor = vec4(lane); }}"), &[]);
    assert_eq!(r.alive, 0x03ff);
}

#[test]
fn out_and_inout_parameters_with_conversion() {
    let r = frag(
        &format!(
            "{LANE}void f(in float a, out float b, inout vec2 c, out int d) {{
                a += 1.0; b = a * 2.0; c = c.yx + a; d = 3;
            }}
            void main() {{
                float x = lane, y = 0.0; vec2 v = vec2(1.0, 2.0); float conv = 0.0;
                f(x, y, v, conv);   // int out into a float (1.20)
                gl_FragColor = vec4(x + y, v, conv);
            }}"
        ),
        &[],
    );
    for lane in 0..16usize {
        let x = lane as f32;
        assert_eq!(
            [0, 1, 2, 3].map(|i| r.get("gl_FragColor", i)[lane]),
            [x + (x + 1.0) * 2.0, 2.0 + x + 1.0, 1.0 + x + 1.0, 3.0],
            "lane {lane}"
        );
    }
}

#[test]
fn short_circuit_conditional_and_increments_have_their_side_effects_once() {
    let r = frag(
        &format!(
            "{LANE}void main() {{
                int n = 0; int m = 0; int p = 5;
                bool a = lane > 7.0 && (n++ > -1);
                bool b = lane > 7.0 || (m++ > -1);
                float c = lane > 3.0 ? float(p++) : float(--p);
                int q = p++ + ++p;
                gl_FragColor = vec4(float(n), float(m), c, float(q)) + vec4(0.0, 0.0, 0.0, float(a) + float(b) * 100.0);
            }}"
        ),
        &[],
    );
    for lane in 0..16usize {
        let big = lane > 7;
        let n = big as i32;
        let m = (!big) as i32;
        let (c, p) = if lane > 3 { (5.0, 6) } else { (4.0, 4) };
        let q = p + (p + 2);
        let a = big as i32 as f32;
        assert_eq!(
            [0, 1, 2, 3].map(|i| r.get("gl_FragColor", i)[lane]),
            [n as f32, m as f32, c, q as f32 + a + 100.0],
            "lane {lane}"
        );
    }
}

#[test]
fn aggregate_equality() {
    let r = frag(
        &format!(
            "{LANE}struct S {{ vec2 a; int b; }};
            void main() {{
                S x = S(vec2(1.0, lane), 3);
                S y = S(vec2(1.0, 4.0), 3);
                float a[2] = float[2](1.0, lane);
                float b[2] = float[](1.0, 2.0);
                gl_FragColor = vec4(float(x == y), float(x != y), float(a == b), float(mat2(lane) == mat2(1.0)));
            }}"
        ),
        &[],
    );
    for lane in 0..16usize {
        let b = |c: bool| c as i32 as f32;
        assert_eq!(
            [0, 1, 2, 3].map(|i| r.get("gl_FragColor", i)[lane]),
            [b(lane == 4), b(lane != 4), b(lane == 2), b(lane == 1)]
        );
    }
}

/// One float built-in at a few points (per lane: the points), against Rust in f32.
fn unary_builtin(name: &str, points: &[f32]) -> Vec<f32> {
    let src = format!(
        "uniform float p[16]; varying float lane; void main() {{ gl_FragColor = vec4({name}(p[int(lane)])); }}"
    );
    let l = lowered(Stage::Fragment, &src);
    let r = execute(
        &l,
        &|w| {
            let i: usize = w.name.trim_start_matches("p[").trim_end_matches(']').parse().unwrap();
            *points.get(i).unwrap_or(&0.0)
        },
        &|_, lane| lane as f32,
        &NoTextures,
    );
    r.get("gl_FragColor", 0)[..points.len()].to_vec()
}

/// `body` with each numeric literal `n` written `(n + z)` (`(n + iz)` for ints).
fn unfold(body: &str) -> String {
    let chars: Vec<char> = body.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let starts = chars[i].is_ascii_digit() && (i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '_'));
        if !starts {
            out.push(chars[i]);
            i += 1;
            continue;
        }
        let mut j = i;
        while j < chars.len() && (chars[j].is_ascii_digit() || chars[j] == '.') {
            j += 1;
        }
        let lit: String = chars[i..j].iter().collect();
        let zero = if lit.contains('.') { "z" } else { "iz" };
        out.push_str(&format!("({lit} + {zero})"));
        i = j;
    }
    out
}

#[test]
fn builtin_functions_at_points_and_edges() {
    // Every literal plus a zero input, so that the checker's constant folding leaves the
    // calls to the lowering.
    let frag1 = |body: &str| {
        frag(
            &format!("{LANE}varying float z; void main() {{ int iz = int(z); gl_FragColor = {}; }}", unfold(body)),
            &[],
        )
    };
    let r = frag1("vec4(pow(2.0, 10.0), pow(0.0, 0.0), exp2(3.0), log2(8.0))");
    let v = r.vec("gl_FragColor", 4);
    assert_eq!(v[0], 1024.0);
    assert!(v[1].is_nan(), "pow(0, 0) is exp2(0·log2 0) = NaN in tessera");
    assert_eq!(&v[2..], &[8.0, 3.0]);
    let r = frag1("vec4(normalize(vec3(0.0)), length(vec3(3.0, 4.0, 0.0)))");
    let v = r.vec("gl_FragColor", 4);
    assert!(v[0].is_nan() && v[1].is_nan() && v[2].is_nan(), "normalize(0) is NaN");
    assert_eq!(v[3], 5.0);
    let r = frag1("vec4(1.0 / (lane - lane), -1.0 / (lane - lane), mod(-1.5, 1.0), sign(-3.0))");
    assert_eq!(r.vec("gl_FragColor", 4), vec![f32::INFINITY, f32::NEG_INFINITY, 0.5, -1.0]);
    let r =
        frag1("vec4(float(7 / (int(lane) - int(lane))), clamp(5.0, 0.0, 1.0), mix(2.0, 4.0, 0.25), step(0.5, 0.5))");
    assert_eq!(r.vec("gl_FragColor", 4), vec![0.0, 1.0, 2.5, 1.0], "int division by zero is 0");
    let r = frag1("vec4(smoothstep(0.0, 2.0, 1.0), distance(vec2(0.0), vec2(3.0, 4.0)), dot(vec2(1.0, 2.0), vec2(3.0, 4.0)), fract(-0.25))");
    assert_eq!(r.vec("gl_FragColor", 4), vec![0.5, 5.0, 11.0, 0.75]);
    let r = frag1("vec4(cross(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)), faceforward(1.0, 1.0, 1.0))");
    assert_eq!(r.vec("gl_FragColor", 4), vec![0.0, 0.0, 1.0, -1.0]);
    let r = frag1("vec4(reflect(vec2(1.0, -1.0), vec2(0.0, 1.0)), refract(vec2(0.0, -1.0), vec2(0.0, 1.0), 1.0))");
    assert_eq!(r.vec("gl_FragColor", 4), vec![1.0, 1.0, 0.0, -1.0]);
    let r = frag1("vec4(refract(vec2(0.6, -0.8), vec2(0.0, 1.0), 2.0), float(any(bvec2(false, true))), float(all(not(bvec2(false, true)))))");
    assert_eq!(r.vec("gl_FragColor", 4), vec![0.0, 0.0, 1.0, 0.0], "total internal reflection gives 0");
    let r = frag1("vec4(lessThan(vec2(1.0, 2.0), vec2(2.0)), greaterThanEqual(ivec2(1, 2), ivec2(2)))");
    assert_eq!(r.vec("gl_FragColor", 4), vec![1.0, 0.0, 0.0, 1.0]);
    let r = frag1("vec4(transpose(mat2x3(1.0, 2.0, 3.0, 4.0, 5.0, 6.0))[1], outerProduct(vec2(1.0, 2.0), vec3(3.0, 4.0, 5.0))[2][1], 0.0)");
    // transpose: 3 columns of 2 rows; column 1 = (2, 5). outerProduct: m[j][i] = c[i]·r[j].
    assert_eq!(r.vec("gl_FragColor", 3), vec![2.0, 5.0, 10.0]);
    let r = frag1("vec4(matrixCompMult(mat2(2.0), mat2(3.0))[0], radians(180.0), degrees(3.14159265))");
    assert_eq!(r.vec("gl_FragColor", 4), vec![6.0, 0.0, std::f32::consts::PI, 180.0]);
    // Transcendentals against f64 at a few points.
    let check = |name: &str, pts: &[f32], f: fn(f64) -> f64, tol: f64| {
        let got = unary_builtin(name, pts);
        for (&p, g) in pts.iter().zip(got) {
            let want = f(p as f64);
            assert!((g as f64 - want).abs() <= tol * want.abs().max(1.0), "{name}({p}) = {g}, want {want}");
        }
    };
    let pts = [-1.0, -0.99, -0.5, -0.1, 0.0, 1e-3, 0.3, 0.7, 0.9, 1.0];
    check("asin", &pts, f64::asin, 2e-6);
    check("acos", &pts, f64::acos, 2e-6);
    let wide = [-1e6, -10.0, -1.0, -0.5, 0.0, 0.25, 1.0, 2.0, 100.0];
    check("atan", &wide, f64::atan, 1e-5);
    check("exp", &[-5.0, 0.0, 1.0, 3.5], f64::exp, 1e-6);
    check("log", &[0.1, 1.0, 2.5, 1000.0], f64::ln, 1e-6);
    check("sin", &[-3.0, 0.0, 0.5, 3.0], f64::sin, 1e-6);
    check("tan", &[-1.0, 0.0, 0.5, 1.2], f64::tan, 1e-5);
    check("sqrt", &[0.0, 2.0, 1e6], f64::sqrt, 1e-7);
    check("inversesqrt", &[0.25, 2.0], |x| 1.0 / x.sqrt(), 1e-6);
    let nan = unary_builtin("asin", &[1.5]);
    assert!(nan[0].is_nan(), "asin outside [−1, 1] is NaN");
}

#[test]
fn atan2_quadrants_and_origin() {
    let r = frag(&format!("{LANE}void main() {{ gl_FragColor = vec4(atan(1.0, -1.0), atan(-1.0, -1.0), atan(0.0, 0.0), atan(-2.0, 0.0)); }}"), &[]);
    let v = r.vec("gl_FragColor", 4);
    let want = [(1f64).atan2(-1.0), (-1f64).atan2(-1.0), 0.0, (-2f64).atan2(0.0)];
    for (g, w) in v.iter().zip(want) {
        assert!((*g as f64 - w).abs() < 3e-6, "{v:?} vs {want:?}");
    }
}

#[test]
fn interface_names_words_and_builtin_state() {
    let l = lowered(
        Stage::Vertex,
        "#version 120
        struct L { vec3 c; mat2 m; };
        uniform L lights[3];
        uniform mat3x2 nm;
        attribute vec3 pos;
        varying vec2 uv;
        void main() {
            gl_Position = ftransform() + vec4(gl_LightSource[1].diffuse.x, lights[2].m[1].y, nm[2].x, pos.z);
            uv = lights[0].c.xy;
            gl_TexCoord[2].x = gl_Normal.y;
        }",
    );
    let names: Vec<(String, u32)> = l.uniforms.iter().map(|w| (w.name.clone(), w.index)).collect();
    let has = |list: &[(String, u32)], n: &str, i: u32| list.contains(&(n.to_string(), i));
    assert!(has(&names, "gl_ModelViewProjectionMatrix", 15));
    assert!(has(&names, "gl_LightSource[1].diffuse", 0));
    assert!(!has(&names, "gl_LightSource[1].diffuse", 3), "only the words read");
    assert!(!names.iter().any(|(n, _)| n.starts_with("gl_LightSource[0]")), "unused elements are left out");
    assert!(has(&names, "lights[2].m", 3) && has(&names, "nm", 4) && has(&names, "lights[0].c", 1));
    let inputs: Vec<(String, u32)> = l.inputs.iter().map(|w| (w.name.clone(), w.index)).collect();
    assert!(has(&inputs, "gl_Vertex", 3) && has(&inputs, "pos", 2) && has(&inputs, "gl_Normal", 1));
    assert!(!has(&inputs, "gl_Color", 0));
    let outputs: Vec<(String, u32)> = l.outputs.iter().map(|w| (w.name.clone(), w.index)).collect();
    assert!(has(&outputs, "gl_Position", 3) && has(&outputs, "uv", 1) && has(&outputs, "gl_TexCoord[2]", 3));
    assert!(!has(&outputs, "gl_TexCoord[0]", 0) && !has(&outputs, "gl_FrontColor", 0));
    // Run it: ftransform is the matrix times the vertex.
    let r = execute(
        &l,
        &|w| match w.name.as_str() {
            "gl_ModelViewProjectionMatrix" => {
                [2.0, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 4.0, 0.0, 1.0, 1.0, 1.0, 1.0][w.index as usize]
            }
            "gl_LightSource[1].diffuse" => 0.5,
            _ => 0.0,
        },
        &|w, lane| if w.name == "gl_Vertex" { [lane as f32, 1.0, 1.0, 1.0][w.index as usize] } else { 0.0 },
        &NoTextures,
    );
    for lane in 0..16 {
        assert_eq!(r.get("gl_Position", 0)[lane], 2.0 * lane as f32 + 1.0 + 0.5);
        assert_eq!(r.get("gl_Position", 1)[lane], 4.0);
    }
}

/// Textures that answer each lookup with its own request: unit, coordinates, LOD kind,
/// comparison value.
struct Echo;

impl Textures for Echo {
    fn sample(&self, q: &SampleRequest<'_>, out: &mut [[u32; LANES]; 4]) {
        let lod = match q.lod {
            crate::shader::exec::LodLanes::Implicit => 0.0,
            crate::shader::exec::LodLanes::Bias(b) => 100.0 + f32::from_bits(b[0]),
            crate::shader::exec::LodLanes::Explicit(e) => 200.0 + f32::from_bits(e[0]),
        };
        let last = if q.projective { f32::from_bits(q.coords[q.n as usize][0]) } else { -1.0 };
        let cmp = q.compare.map_or(-1.0, |c| f32::from_bits(c[0]));
        let first = f32::from_bits(q.coords[0][0]);
        *out = [q.unit as f32 * 1000.0 + first, lod, last, cmp].map(|v| [v.to_bits(); LANES]);
    }

    fn fetch(&self, _: u8, _: u8, _: &[[u32; LANES]; 3], _: &[u32; LANES], _: u16, out: &mut [[u32; LANES]; 4]) {
        *out = [[0; LANES]; 4];
    }

    fn size(&self, _: u8, _: &[u32; LANES], _: u16, out: &mut [[u32; LANES]; 3]) {
        *out = [[0; LANES]; 3];
    }
}

#[test]
fn texture_lookups_name_their_sampler_uniforms() {
    let l = lowered(
        Stage::Fragment,
        "uniform sampler2D a; uniform sampler2DShadow sh[2]; uniform samplerCube c;
        vec4 look(sampler2D s, vec2 p) { return texture2D(s, p, 1.5); }
        void main() {
            gl_FragData[0] = look(a, vec2(0.25, 0.5));
            gl_FragData[1] = shadow2DProj(sh[1], vec4(3.0, 4.0, 0.75, 2.0));
            gl_FragData[2] = texture2DProj(a, vec4(5.0, 6.0, 7.0, 8.0));
            gl_FragData[3] = textureCube(c, vec3(9.0));
        }",
    );
    let names: Vec<&str> = l.samplers.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["a", "sh[1]", "c"]);
    assert!(l.uniforms.is_empty(), "samplers take no uniform words: {:?}", l.uniforms);
    let r = execute(&l, &|_| 0.0, &|_, _| 0.0, &Echo);
    assert_eq!(r.vec("gl_FragData[0]", 4), vec![0.25, 101.5, -1.0, -1.0]);
    assert_eq!(r.vec("gl_FragData[1]", 4), vec![1003.0, 0.0, 2.0, 0.75]);
    assert_eq!(r.vec("gl_FragData[2]", 4), vec![5.0, 0.0, 8.0, -1.0]);
    assert_eq!(r.vec("gl_FragData[3]", 4), vec![2009.0, 0.0, -1.0, -1.0]);
    // Vertex lookups use level 0 unless they give one.
    let v = lowered(
        Stage::Vertex,
        "uniform sampler2D t; void main() { gl_Position = texture2D(t, vec2(0.0)) + texture2DLod(t, vec2(0.0), 3.0); }",
    );
    let lods: Vec<Lod> = format!("{:?}", v.program.body).matches("Explicit").map(|_| Lod::Implicit).collect();
    assert_eq!(lods.len(), 2);
}

#[test]
fn several_units_and_recursion() {
    let a = compile(Stage::Fragment, "float helper(float x); void main() { gl_FragColor = vec4(helper(2.0)); }");
    let b = compile(Stage::Fragment, "float helper(float x) { return x * 3.0; }");
    let l = lower(&[&a, &b]).expect("lowers");
    let r = execute(&l, &|_| 0.0, &|_, _| 0.0, &NoTextures);
    assert_eq!(r.get("gl_FragColor", 0)[0], 6.0);
    assert!(lower(&[&a]).unwrap_err().contains("no definition"));
    let rec = compile(Stage::Fragment, "float f(float x); float f(float x) { return x > 0.0 ? f(x - 1.0) : 0.0; } void main() { gl_FragColor = vec4(f(2.0)); }");
    assert!(lower(&[&rec]).unwrap_err().contains("recursive"));
}

#[test]
fn derivatives_and_fragment_inputs() {
    let l = lowered(
        Stage::Fragment,
        "void main() { gl_FragColor = vec4(dFdx(gl_FragCoord.x * 2.0), dFdy(gl_FragCoord.y * gl_FragCoord.y), fwidth(gl_FragCoord.x), float(gl_FrontFacing)); }",
    );
    let r = execute(
        &l,
        &|_| 0.0,
        &|w, lane| match (w.name.as_str(), w.index) {
            ("gl_FragCoord", 0) => (lane & 3) as f32 + 0.5,
            ("gl_FragCoord", 1) => (lane >> 2) as f32 + 0.5,
            ("gl_FrontFacing", _) => 1.0,
            _ => 0.0,
        },
        &NoTextures,
    );
    assert_eq!(r.get("gl_FragColor", 0), [2.0; LANES]);
    // Rows 0,1 form quads: (1.5² − 0.5²) = 2; rows 2,3: 3.5² − 2.5² = 6.
    assert_eq!(r.get("gl_FragColor", 1)[0], 2.0);
    assert_eq!(r.get("gl_FragColor", 1)[15], 6.0);
    assert_eq!(r.get("gl_FragColor", 2), [1.0; LANES]);
    assert_eq!(r.get("gl_FragColor", 3), [1.0; LANES]);
}

#[test]
fn dynamic_index_into_a_swizzle_reads_and_writes_one_component() {
    let r = frag(
        &format!(
            "{LANE}void main() {{
                int i = int(lane) - (int(lane) / 4) * 4;
                gl_FragColor = vec4(1.0, 2.0, 3.0, 4.0);
                gl_FragColor.wzyx[i] = 9.0;
                gl_FragData[0].x = 0.0;
            }}"
        )
        .replace("gl_FragData[0].x = 0.0;", ""),
        &[],
    );
    for lane in 0..16usize {
        let mut want = [1.0, 2.0, 3.0, 4.0];
        want[3 - lane % 4] = 9.0;
        assert_eq!([0, 1, 2, 3].map(|k| r.get("gl_FragColor", k)[lane]), want, "lane {lane}");
    }
}

#[test]
fn an_out_argument_indexed_by_a_variable_the_call_changes_writes_the_element_of_the_call() {
    // GLSL 1.20 section 6.1.1: `a[i]`'s place is fixed when the call starts; the call
    // writing `i` (an earlier inout argument, copied back first) does not move it.
    let r = frag(
        &format!(
            "{LANE}uniform int u;
            void f(inout int i, inout float x) {{ i = 0; x = x + 10.0; }}
            void g(inout int i, out int x) {{ x = 4; i = 3; }}
            float bump(inout int i) {{ i = 2; return 5.0; }}
            void h(out float x, in float y) {{ x = y; }}
            void main() {{
                float a[4] = float[](1.0, 2.0, 3.0, lane);
                int i = u;
                f(i, a[i]);               // a[1] += 10, not a[0]
                vec4 v = vec4(0.0);
                int j = u;
                g(j, v[j]);               // int out into v[1], converted
                int k = u;
                h(a[k], bump(k));         // a[1] = 5: k changes in a later argument
                gl_FragColor = vec4(a[0] + a[2], a[1], v.y + v.w, float(i + j + k));
            }}"
        ),
        &[("u", &[1.0])],
    );
    for lane in 0..16usize {
        assert_eq!([0, 1, 2, 3].map(|c| r.get("gl_FragColor", c)[lane]), [4.0, 5.0, 4.0, 5.0], "lane {lane}");
    }
}

#[test]
fn a_value_is_taken_before_later_side_effects_change_it() {
    let r = frag(
        &format!(
            "{LANE}float g;
            float bump() {{ g += 10.0; return 1.0; }}
            void main() {{
                vec4 v = vec4(1.0, 2.0, 3.0, 4.0);
                v = v.wzyx;                   // the value is the target's own registers
                v.xy = v.yx;
                g = lane;
                float s = g + bump();         // g read before bump() changes it
                gl_FragColor = vec4(v.xyz, s + g);
            }}"
        ),
        &[],
    );
    for lane in 0..16usize {
        let l = lane as f32;
        assert_eq!([0, 1, 2, 3].map(|k| r.get("gl_FragColor", k)[lane]), [3.0, 4.0, 2.0, l + 1.0 + l + 10.0]);
    }
}

#[test]
fn exponential_inlining_is_an_error_not_a_hang() {
    let mut src = String::from("void f0() { gl_FragColor = exp(gl_FragColor); }\n");
    for i in 1..30 {
        src.push_str(&format!("void f{i}() {{ f{}(); f{}(); }}\n", i - 1, i - 1));
    }
    src.push_str("void main() { f29(); }\n");
    let c = compile(Stage::Fragment, &src);
    let start = std::time::Instant::now();
    let e = lower(&[&c]).unwrap_err();
    assert!(e.contains("registers after inlining"), "{e}");
    assert!(start.elapsed().as_secs() < 20);
}

/// A miniature `shader_runner` for piglit's simplest GLSL 1.10/1.20 execution tests: the
/// vertex shader runs on the four corners of each `draw rect` (default GL state: identity
/// matrices, no other attributes read), its outputs are interpolated over the rectangle's
/// two triangles, and the fragment program runs on the reference executor in 4×4 blocks
/// over an RGBA8 window; the `probe` lines compare within piglit's tolerance for 8-bit
/// channels (3/2⁸). A test using anything else (textures, `ortho`, built-in state other
/// than the matrices, other attributes, extra requirements) is skipped.
mod runner {
    use super::*;

    const TOLERANCE: f32 = 3.0 / 256.0;

    pub enum Outcome {
        Pass,
        Fail(String),
        Skip(#[allow(dead_code)] String),
    }

    struct Program {
        vs: Option<Lowered>,
        fs: Lowered,
    }

    fn identity_state(w: &Word) -> Option<f32> {
        let matrix = [
            "gl_ModelViewMatrix",
            "gl_ProjectionMatrix",
            "gl_ModelViewProjectionMatrix",
            "gl_ModelViewMatrixInverse",
            "gl_ProjectionMatrixInverse",
            "gl_ModelViewProjectionMatrixInverse",
            "gl_ModelViewMatrixTranspose",
            "gl_ModelViewProjectionMatrixTranspose",
            "gl_ProjectionMatrixTranspose",
        ];
        if matrix.contains(&w.name.as_str()) {
            return Some(if w.index.is_multiple_of(5) { 1.0 } else { 0.0 });
        }
        if w.name == "gl_NormalMatrix" {
            return Some(if w.index.is_multiple_of(4) { 1.0 } else { 0.0 });
        }
        None
    }

    fn uniform_value(values: &HashMap<String, Vec<f32>>, w: &Word) -> Result<f32, String> {
        if w.name.starts_with("gl_") {
            return identity_state(w).ok_or_else(|| format!("built-in state {}", w.name));
        }
        let v = values.get(&w.name).or_else(|| w.name.strip_suffix("[0]").and_then(|n| values.get(n)));
        Ok(v.and_then(|v| v.get(w.index as usize).copied()).unwrap_or(0.0))
    }

    pub fn run(text: &str) -> Outcome {
        let requires_120 = text.lines().any(|l| l.split_whitespace().collect::<Vec<_>>() == ["GLSL", ">=", "1.20"]);
        let mut sections: Vec<(String, String)> = Vec::new();
        for line in text.lines() {
            if line.starts_with('[') {
                sections.push((line.trim().to_string(), String::new()));
            } else if let Some((_, body)) = sections.last_mut() {
                body.push_str(line);
                body.push('\n');
            }
        }
        let (mut width, mut height) = (250usize, 250usize);
        let mut vs_src = None;
        let mut fs_src = None;
        let mut test = None;
        for (name, body) in &sections {
            match name.as_str() {
                "[require]" => {
                    for l in body.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')) {
                        let w: Vec<&str> = l.split_whitespace().collect();
                        match w.as_slice() {
                            ["GLSL", ">=", "1.10" | "1.20"] | ["GL", ">=", _] | ["rlimit", _] => {}
                            ["SIZE", a, b] => {
                                (width, height) = (a.parse().unwrap_or(250), b.parse().unwrap_or(250));
                            }
                            _ => return Outcome::Skip(format!("requires {l}")),
                        }
                    }
                }
                "[vertex shader passthrough]" => vs_src = Some(None),
                "[vertex shader]" => vs_src = Some(Some(body.clone())),
                "[fragment shader]" => fs_src = Some(body.clone()),
                "[test]" => test = Some(body.clone()),
                other => return Outcome::Skip(format!("section {other}")),
            }
        }
        let (Some(fs_src), Some(test)) = (fs_src, test) else { return Outcome::Skip("no fragment shader".into()) };
        let initializer = |s: &str| s.lines().any(|l| l.trim_start().starts_with("uniform") && l.contains('='));
        if initializer(&fs_src) || vs_src.clone().flatten().is_some_and(|s| initializer(&s)) {
            return Outcome::Skip("uniform initializers (the link sets them)".into());
        }
        let prepare = |s: &str| {
            let has_version = s.lines().any(|l| l.trim_start().starts_with("#version"));
            if requires_120 && !has_version {
                format!("#version 120\n{s}")
            } else {
                s.to_string()
            }
        };
        let build = |stage: Stage, s: &str| -> Result<Lowered, String> {
            let mut log = InfoLog::default();
            let c = compile_shader(&prepare(s), stage, &Options::default(), &mut log).ok_or(log.text())?;
            lower(&[&c])
        };
        let fs = match build(Stage::Fragment, &fs_src) {
            Ok(l) => l,
            Err(e) => return Outcome::Skip(format!("fragment shader: {e}")),
        };
        let vs = match vs_src.flatten() {
            Some(s) => match build(Stage::Vertex, &s) {
                Ok(l) => Some(l),
                Err(e) => return Outcome::Skip(format!("vertex shader: {e}")),
            },
            None => None,
        };
        if !fs.samplers.is_empty() || vs.as_ref().is_some_and(|v| !v.samplers.is_empty()) {
            return Outcome::Skip("textures".into());
        }
        let program = Program { vs, fs };
        let mut uniforms: HashMap<String, Vec<f32>> = HashMap::new();
        let mut clear = [0.0f32; 4];
        let mut fb = vec![[0u8; 4]; width * height];
        for line in test.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')) {
            let clean = line.replace(['(', ')', ','], " ");
            let w: Vec<&str> = clean.split_whitespace().collect();
            let nums = |s: &[&str]| -> Option<Vec<f32>> { s.iter().map(|x| x.parse::<f32>().ok()).collect() };
            match w.as_slice() {
                ["uniform", _ty, name, values @ ..] => match nums(values) {
                    Some(v) => {
                        uniforms.insert(name.to_string(), v);
                    }
                    None => return Outcome::Skip(format!("uniform line {line}")),
                },
                ["clear", "color", c @ ..] => match nums(c) {
                    Some(c) if c.len() == 4 => clear = [c[0], c[1], c[2], c[3]],
                    _ => return Outcome::Skip(line.to_string()),
                },
                ["clear"] => fb.fill(clear.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8)),
                ["draw", "rect", r @ ..] => match nums(r) {
                    Some(r) if r.len() == 4 && (r[2] < 0.0 || r[3] < 0.0) => {
                        return Outcome::Skip("a back-facing rectangle".into());
                    }
                    Some(r) if r.len() == 4 => {
                        if let Err(e) = draw(&program, &uniforms, [r[0], r[1], r[2], r[3]], width, height, &mut fb) {
                            return Outcome::Skip(e);
                        }
                    }
                    _ => return Outcome::Skip(line.to_string()),
                },
                _ if (w.first() == Some(&"probe") || w.starts_with(&["relative", "probe"]))
                    && w.len() > 2
                    && matches!(w[if w[0] == "relative" { 2 } else { 1 }], "rgb" | "rgba" | "all") =>
                {
                    let relative = w[0] == "relative";
                    let at = if relative { 2 } else { 1 };
                    let (kind, rest) = (&w[at], &w[at + 1..]);
                    let (all, rest): (bool, &[&str]) = if *kind == "all" { (true, &rest[1..]) } else { (false, rest) };
                    let channels = if *kind == "all" {
                        if w.contains(&"rgba") {
                            4
                        } else {
                            3
                        }
                    } else if *kind == "rgba" {
                        4
                    } else {
                        3
                    };
                    let Some(v) = nums(rest) else { return Outcome::Skip(line.to_string()) };
                    let (x0, y0, expected) = if all {
                        (None, None, v)
                    } else {
                        if v.len() < 2 {
                            return Outcome::Skip(line.to_string());
                        }
                        let (x, y) = if relative {
                            ((v[0] * width as f32) as usize, (v[1] * height as f32) as usize)
                        } else {
                            (v[0] as usize, v[1] as usize)
                        };
                        (Some(x), Some(y), v[2..].to_vec())
                    };
                    if expected.len() != channels {
                        return Outcome::Skip(line.to_string());
                    }
                    let pixels: Vec<(usize, usize)> = match (x0, y0) {
                        (Some(x), Some(y)) => vec![(x.min(width - 1), y.min(height - 1))],
                        _ => (0..height).flat_map(|y| (0..width).map(move |x| (x, y))).collect(),
                    };
                    for (x, y) in pixels {
                        let p = fb[y * width + x];
                        for c in 0..channels {
                            let got = p[c] as f32 / 255.0;
                            if (got - expected[c]).abs() > TOLERANCE {
                                return Outcome::Fail(format!("{line}: pixel ({x}, {y}) is {p:?}"));
                            }
                        }
                    }
                }
                _ => return Outcome::Skip(format!("command {line}")),
            }
        }
        Outcome::Pass
    }

    #[allow(clippy::needless_range_loop)] // lanes index several per-lane arrays
    /// Draws the rectangle (x, y, w, h in clip space, as `piglit_draw_rect`'s strip).
    fn draw(
        p: &Program,
        uniforms: &HashMap<String, Vec<f32>>,
        r: [f32; 4],
        width: usize,
        height: usize,
        fb: &mut [[u8; 4]],
    ) -> Result<(), String> {
        let corners = [[r[0], r[1]], [r[0] + r[2], r[1]], [r[0], r[1] + r[3]], [r[0] + r[2], r[1] + r[3]]];
        // Vertex outputs per corner by (name, index); the passthrough shader gives the position.
        let mut varyings: HashMap<(String, u32), [f32; 4]> = HashMap::new();
        match &p.vs {
            None => {
                for i in 0..4u32 {
                    let v = [0, 1, 2, 3].map(|c| [corners[c][0], corners[c][1], 0.0, 1.0][i as usize]);
                    varyings.insert(("gl_Position".into(), i), v);
                }
            }
            Some(vs) => {
                let uv: Vec<f32> = vs.uniforms.iter().map(|w| uniform_value(uniforms, w)).collect::<Result<_, _>>()?;
                for w in &vs.inputs {
                    if w.name != "gl_Vertex" {
                        return Err(format!("attribute {}", w.name));
                    }
                }
                let run = execute(
                    vs,
                    &|w| uv[vs.uniforms.iter().position(|x| x == w).expect("word")],
                    &|w, lane| {
                        let c = corners[lane.min(3)];
                        [c[0], c[1], 0.0, 1.0][w.index as usize]
                    },
                    &NoTextures,
                );
                for (k, v) in run.out {
                    varyings.insert(k, [v[0], v[1], v[2], v[3]]);
                }
            }
        }
        for i in 0..4 {
            let w = varyings.get(&("gl_Position".to_string(), 3)).map_or(1.0, |v| v[i]);
            let pos: Vec<f32> =
                (0..2).map(|k| varyings.get(&("gl_Position".to_string(), k)).map_or(0.0, |v| v[i])).collect();
            if w != 1.0 || pos[0] != corners[i][0] || pos[1] != corners[i][1] {
                return Err("a vertex shader that moves the rectangle".into());
            }
        }
        let fs = &p.fs;
        let fu: Vec<f32> = fs.uniforms.iter().map(|w| uniform_value(uniforms, w)).collect::<Result<_, _>>()?;
        // Each fragment input: the vertex output it reads.
        let mut sources = Vec::new();
        for w in &fs.inputs {
            let from = match w.name.as_str() {
                "gl_FragCoord" | "gl_FrontFacing" => None,
                "gl_Color" => Some(("gl_FrontColor".to_string(), w.index)),
                "gl_SecondaryColor" => Some(("gl_FrontSecondaryColor".to_string(), w.index)),
                n if n.starts_with("gl_") && !n.starts_with("gl_TexCoord") && n != "gl_FogFragCoord" => {
                    return Err(format!("input {n}"));
                }
                n => Some((n.to_string(), w.index)),
            };
            sources.push(from);
        }
        let (x0, x1) = ((r[0] + 1.0) * 0.5 * width as f32, (r[0] + r[2] + 1.0) * 0.5 * width as f32);
        let (y0, y1) = ((r[1] + 1.0) * 0.5 * height as f32, (r[1] + r[3] + 1.0) * 0.5 * height as f32);
        let inputs: Vec<[u32; LANES]> = vec![[0; LANES]; fs.inputs.len()];
        let mut inputs = inputs;
        let mut executor = Executor::new();
        for by in (0..height).step_by(4) {
            for bx in (0..width).step_by(4) {
                let mut mask = 0u16;
                for lane in 0..LANES {
                    let (x, y) = (bx + (lane & 3), by + (lane >> 2));
                    let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
                    let inside = x < width && y < height && cx >= x0 && cx < x1 && cy >= y0 && cy < y1;
                    mask |= (inside as u16) << lane;
                    let u = (cx - x0) / (x1 - x0);
                    let v = (cy - y0) / (y1 - y0);
                    let interp = |a: [f32; 4]| {
                        if u + v <= 1.0 {
                            a[0] + u * (a[1] - a[0]) + v * (a[2] - a[0])
                        } else {
                            a[3] + (1.0 - u) * (a[2] - a[3]) + (1.0 - v) * (a[1] - a[3])
                        }
                    };
                    for (k, (w, src)) in fs.inputs.iter().zip(&sources).enumerate() {
                        let value = match src {
                            None if w.name == "gl_FrontFacing" => 1.0,
                            None => match w.index {
                                0 => cx,
                                1 => cy,
                                2 => {
                                    0.5 * interp(
                                        varyings.get(&("gl_Position".to_string(), 2)).copied().unwrap_or([0.0; 4]),
                                    ) + 0.5
                                }
                                _ => 1.0,
                            },
                            Some(key) => interp(varyings.get(key).copied().unwrap_or([0.0; 4])),
                        };
                        inputs[k][lane] = to_word(fs.program.inputs[k], value);
                    }
                }
                if mask == 0 {
                    continue;
                }
                let uw: Vec<u32> =
                    fs.uniforms.iter().zip(&fu).zip(&fs.program.uniforms).map(|((_, &v), &t)| to_word(t, v)).collect();
                let mut outputs = vec![[0u32; LANES]; fs.program.outputs.len()];
                let alive = executor.run(
                    &fs.program,
                    &mut Io { inputs: &inputs, uniforms: &uw, outputs: &mut outputs, textures: &NoTextures },
                    ALL_LANES,
                ) & mask;
                let color_name =
                    if fs.outputs.iter().any(|w| w.name == "gl_FragColor") { "gl_FragColor" } else { "gl_FragData[0]" };
                for lane in 0..LANES {
                    if alive >> lane & 1 == 0 {
                        continue;
                    }
                    let (x, y) = (bx + (lane & 3), by + (lane >> 2));
                    let mut px = [0u8; 4];
                    for c in 0..4 {
                        let v = fs
                            .outputs
                            .iter()
                            .position(|w| w.name == color_name && w.index == c as u32)
                            .map_or(0.0, |k| f32::from_bits(outputs[k][lane]));
                        // GL's clamp then the unorm8 conversion (NaN → 0).
                        let v = if v > 0.0 { v.min(1.0) } else { 0.0 };
                        px[c] = (v * 255.0).round() as u8;
                    }
                    fb[y * width + x] = px;
                }
            }
        }
        Ok(())
    }
}

/// piglit's GLSL 1.10/1.20 execution tests that the mini runner can run (see [`runner`]).
/// Skips without piglit, except under CI.
#[test]
fn piglit_shader_runner_subset() {
    let Some(files) = crate::glsl::tests::piglit_shader_tests(&["glsl-1.10/execution", "glsl-1.20/execution"]) else {
        return;
    };
    let root = std::path::Path::new(crate::glsl::tests::PIGLIT_SPEC);
    let (mut pass, mut fail, mut skip) = (0, Vec::new(), 0);
    for f in &files {
        let Ok(text) = std::fs::read_to_string(f) else { continue };
        if text.contains("#extension") {
            skip += 1;
            continue;
        }
        match runner::run(&text) {
            runner::Outcome::Pass => pass += 1,
            runner::Outcome::Fail(e) => fail.push(format!("{}: {e}\n", f.strip_prefix(root).unwrap_or(f).display())),
            runner::Outcome::Skip(_) => skip += 1,
        }
    }
    println!("mini shader_runner: {pass} pass, {} fail, {skip} skipped\n{}", fail.len(), fail.join(""));
    // The failures the runner knows: GL_CLAMP_VERTEX_COLOR is draw-path state this runner
    // does not model; llvmpipe flushes denormal products to zero and tessera's executor
    // keeps them (2⁻¹⁴⁹ is not 0 here).
    let known = ["glsl-clamp-vertex-color.shader_test", "fs-underflow-mul-compare-zero.shader_test"];
    let unknown: Vec<&String> = fail.iter().filter(|f| !known.iter().any(|k| f.contains(k))).collect();
    assert!(unknown.is_empty(), "{unknown:?}");
    assert!(pass >= 400, "only {pass} pass");
}
