//! GLSL fragment shading runs: a block's lanes against the span runs of its rows (the same
//! bits, with derivatives, discards and depths, on framebuffers of both row parities), and
//! the wiring of the fragment's own inputs.
use super::*;
use crate::glsl::{compile_shader, InfoLog, Options, Stage};

#[derive(Debug)]
struct Code(Compiled);

impl ShaderCode for Code {
    fn compiled(&self) -> &Compiled {
        &self.0
    }
}

/// The shading of the fragment shader `source` on a framebuffer `fb_height` rows high:
/// `gl_Color`, `gl_FragCoord` and `gl_FrontFacing` wired to the fragment's own (w: 1 over
/// varying 3), `gl_TexCoord[0]` to varyings 0..4, `gl_FragData[n]` to draw buffer n.
fn shading(source: &str, fb_height: i32) -> GlslShading {
    let mut log = InfoLog::default();
    let checked = compile_shader(source, Stage::Fragment, &Options::default(), &mut log)
        .unwrap_or_else(|| panic!("{}\n{source}", log.text()));
    let lowered = crate::glsl::lower::lower(&[&checked]).unwrap();
    let inputs = lowered
        .inputs
        .iter()
        .map(|w| match w.name.as_str() {
            "gl_Color" => ShaderInput::Primary(w.index as u8),
            "gl_FragCoord" if w.index == 3 => ShaderInput::Reciprocal(3),
            "gl_FragCoord" => ShaderInput::FragCoord(w.index as u8),
            "gl_FrontFacing" => ShaderInput::FrontFacing,
            "gl_TexCoord[0]" => ShaderInput::Varying(w.index as u16),
            _ => ShaderInput::Zero,
        })
        .collect();
    let outputs = lowered
        .outputs
        .iter()
        .map(|w| match w.name.as_str() {
            "gl_FragColor" => ShaderOutput::Color { buffer: 0, channel: w.index as u8 },
            "gl_FragDepth" => ShaderOutput::Depth,
            name => match name.strip_prefix("gl_FragData[").and_then(|n| n.strip_suffix(']')?.parse::<u8>().ok()) {
                Some(buffer) => ShaderOutput::Color { buffer, channel: w.index as u8 },
                None => ShaderOutput::Unused,
            },
        })
        .collect();
    let code = Arc::new(Code(Compiled::new(&lowered.program)));
    let textures = Texturing { stages: Vec::new(), fb_height };
    GlslShading::new(code, &lowered.program, inputs, outputs, Vec::new(), 4, textures)
}

/// A varying that is no plane (so that the quads a derivative takes show).
fn varying(x: f32, y: f32, k: usize) -> f32 {
    x * x * 0.01 + y * 0.3 * k as f32 + (x * y) * 0.001
}

/// The primary colour of a pixel centre.
fn primary(x: f32, y: f32) -> [f32; 4] {
    [x / 16.0, y / 16.0, 0.5, 1.0]
}

const SHADER: &str = "void main() {\n\
    vec4 t = gl_TexCoord[0];\n\
    if (fract(t.x * 3.0) < 0.2) discard;\n\
    gl_FragColor = vec4(dFdx(t.x), dFdy(t.y), gl_Color.r + t.z, gl_FrontFacing ? 1.0 : 0.5);\n\
    gl_FragDepth = gl_FragCoord.z * 0.5 + gl_FragCoord.x / 64.0;\n\
}\n";

#[test]
fn blocks_shade_as_spans_do() {
    let mut discarded = 0u16;
    for fb_height in [16, 15] {
        let s = shading(SHADER, fb_height);
        assert!(s.late_tests() && s.writes_depth());
        for (bx, by) in [(0, 0), (4, 4), (8, 8)] {
            for live in [0xffffu16, 0x8421, 0x0660] {
                let mut scratch = GlslScratch::default();
                let mut colors = [[0.0; LANES]; 4];
                let mut depth = [0.0; LANES];
                let z_of = |x: f32, y: f32| (x + y) / 64.0;
                let kept = s.run_block(&mut scratch, bx, by, live, true, &mut colors, &mut depth, |y0, c, z, v| {
                    for i in 0..LANES {
                        let (x, y) = ((bx + (i & 3) as i32) as f32 + 0.5, (y0 + (i >> 2) as i32) as f32 + 0.5);
                        let p = primary(x, y);
                        for k in 0..4 {
                            c[k][i] = p[k];
                            v[k][i] = varying(x, y, k);
                        }
                        z[i] = z_of(x, y);
                    }
                });
                discarded |= live & !kept;
                assert_eq!(kept & !live, 0);
                for row in 0..4 {
                    let y = by + row;
                    let mut span_colors: Vec<[f32; 4]> =
                        (0..4).map(|c| primary((bx + c) as f32 + 0.5, y as f32 + 0.5)).collect();
                    let mut span_depth: Vec<f32> =
                        (0..4).map(|c| z_of((bx + c) as f32 + 0.5, y as f32 + 0.5)).collect();
                    let span_live = u64::from((live >> (4 * row)) & 0xf);
                    let span_kept = s.run_span(
                        &mut scratch,
                        bx,
                        y,
                        span_live,
                        true,
                        &mut span_colors,
                        &mut span_depth,
                        |dx, dy, out| {
                            let (x, y) = ((bx + dx) as f32 + 0.5, (y + dy) as f32 + 0.5);
                            for (k, o) in out.iter_mut().enumerate() {
                                *o = varying(x, y, k);
                            }
                        },
                    );
                    assert_eq!(span_kept, u64::from((kept >> (4 * row)) & 0xf), "{fb_height} ({bx}, {y})");
                    for c in (0..4).filter(|c| span_kept & (1 << c) != 0) {
                        let lane = 4 * row as usize + c;
                        let block: [f32; 4] = std::array::from_fn(|k| colors[k][lane]);
                        assert_eq!(block.map(f32::to_bits), span_colors[c].map(f32::to_bits), "lane {lane}");
                        assert_eq!(depth[lane].to_bits(), span_depth[c].to_bits());
                        // dFdx of x²·0.01 over a quad of columns (2m, 2m + 1) is 0.01·(2x₀ + 1).
                        let x0 = ((bx as usize + c) & !1) as f32 + 0.5;
                        assert!((block[0] - (0.01 * (2.0 * x0 + 1.0) + 0.001 * (y as f32 + 0.5))).abs() < 1e-4);
                    }
                }
            }
        }
    }
    assert_ne!(discarded, 0, "some lanes discard");
}

#[test]
fn the_fragments_own_inputs_reach_the_shader() {
    let s =
        shading("void main() { gl_FragColor = vec4(gl_FragCoord.xy, gl_FragCoord.w, gl_FrontFacing ? 1.0 : 0.0); }", 8);
    assert!(!s.late_tests());
    for front in [true, false] {
        let mut scratch = GlslScratch::default();
        let mut colors = [[0.0; LANES]; 4];
        let mut depth = [0.0; LANES];
        // Varying 3 (the clip w in a draw) is 4 in lane 0, 2 elsewhere.
        let kept = s.run_block(&mut scratch, 4, 0, 0xffff, front, &mut colors, &mut depth, |_, _, _, v| {
            v[3] = std::array::from_fn(|i| if i == 0 { 4.0 } else { 2.0 });
        });
        assert_eq!(kept, 0xffff);
        assert_eq!(colors[0][6], 6.5, "x of lane 6 (column 2)");
        assert_eq!(colors[1][6], 1.5, "y of lane 6 (row 1)");
        assert_eq!((colors[2][0], colors[2][1]), (0.25, 0.5), "gl_FragCoord.w is 1 over the clip w");
        assert_eq!(colors[3][9], if front { 1.0 } else { 0.0 });
    }
}

#[test]
fn each_draw_buffer_takes_its_frag_data() {
    assert!(!shading("void main() { gl_FragColor = vec4(1.0); }", 8).writes_data());
    assert!(!shading("void main() { gl_FragData[0] = vec4(1.0); }", 8).writes_data());
    let s = shading(
        "void main() {\n\
             gl_FragData[0] = vec4(0.25);\n\
             if (gl_FragCoord.x > 5.0) discard;\n\
             gl_FragData[2] = vec4(gl_FragCoord.x, gl_TexCoord[0].x, 0.5, 1.0);\n\
         }\n",
        8,
    )
    // The band's targets: draw buffers 2, 0 and 1.
    .with_target_buffers(vec![2, 0, 1]);
    assert!(s.writes_data() && s.late_tests());
    let mut scratch = GlslScratch::default();
    let mut colors = vec![[0.0; 4]; 6];
    let mut depth = vec![0.0; 6];
    let kept = s.run_span(&mut scratch, 1, 3, 0b111110, true, &mut colors, &mut depth, |dx, _, out| {
        out[0] = dx as f32 * 0.125;
    });
    // Columns 1..7, the first not live; x + ½ > 5 discards columns 5 and 6.
    assert_eq!(kept, 0b001110);
    let buffer2 = s.target_colors(&scratch, 0, &colors);
    let buffer0 = s.target_colors(&scratch, 1, &colors);
    let buffer1 = s.target_colors(&scratch, 2, &colors);
    for i in (0..6).filter(|i| kept & (1 << i) != 0) {
        assert_eq!(buffer0[i], [0.25; 4]);
        assert_eq!(buffer2[i], [(1 + i) as f32 + 0.5, i as f32 * 0.125, 0.5, 1.0], "pixel {i}");
        // Buffer 1 is not written: it takes buffer 0's colour.
        assert_eq!(buffer1[i], [0.25; 4]);
    }
}

/// `tools/bench`'s phong fragment shader: a loop over two lights, ternaries on the light's
/// `w`, an `if` around `pow`.
const PHONG: &str = "varying vec3 normal;\n\
varying vec3 position;\n\
void main() {\n\
    vec3 n = normalize(normal);\n\
    vec3 eye = -normalize(position);\n\
    vec4 color = gl_FrontLightModelProduct.sceneColor;\n\
    for (int i = 0; i < 2; i++) {\n\
        vec4 p = gl_LightSource[i].position;\n\
        vec3 l = p.w == 0.0 ? normalize(p.xyz) : normalize(p.xyz - position);\n\
        float attenuation = p.w == 0.0 ? 1.0\n\
            : 1.0 / (gl_LightSource[i].constantAttenuation\n\
                     + gl_LightSource[i].linearAttenuation * length(p.xyz - position));\n\
        float diffuse = max(dot(n, l), 0.0);\n\
        color += attenuation * (gl_FrontLightProduct[i].ambient + gl_FrontLightProduct[i].diffuse * diffuse);\n\
        if (diffuse > 0.0) {\n\
            float h = max(dot(n, normalize(l + eye)), 0.0);\n\
            color += attenuation * gl_FrontLightProduct[i].specular * pow(h, gl_FrontMaterial.shininess);\n\
        }\n\
    }\n\
    gl_FragColor = clamp(color, 0.0, 1.0);\n\
}\n";

#[test]
fn a_loop_over_lights_with_ternaries_and_an_if_runs_as_straight_code() {
    let shading = shading(PHONG, 16);
    let code = shading.code.compiled().code();
    assert!(
        matches!(code.body.as_slice(), [crate::shader::lower::Node::Run { masked: false, .. }]),
        "not one unmasked run: {:?}",
        code.body
    );
    eprintln!("phong: {} operations, {} registers", code.ops.len(), code.registers);
}

/// `tools/bench/bench.c`'s Phong shader ([`PHONG`]) runs its colour arithmetic (a `vec4` per light's
/// products and sums, the converted specular `if`'s selects) as groups of four operations:
/// one dispatch each instead of four.
#[test]
fn phong_runs_its_colour_arithmetic_in_groups() {
    let source = PHONG;
    let mut log = InfoLog::default();
    let checked = compile_shader(source, Stage::Fragment, &Options::default(), &mut log).unwrap();
    let lowered = crate::glsl::lower::lower(&[&checked]).unwrap();
    let compiled = Compiled::new(&lowered.program);
    let single = compiled.code().ops.len();
    let run = compiled.run_code();
    let groups = run.ops.iter().filter(|op| matches!(op, crate::shader::lower::Op::Group(_))).count();
    // 8 groups of four products, 6 of four sums, 2 of four selects and 4 of three
    // (subtractions, sums, the lights' selects).
    assert!(groups >= 18, "{groups} groups");
    assert!(run.ops.len() + 50 <= single, "{} operations, {single} single", run.ops.len());
}

/// [`PHONG`] specialised on a directional light 0 and a positional light 1 (bench.c's):
/// light 0's positional arm and its selects are gone, light 1's selects are copies, and the
/// blocks' colours keep their bits.
#[test]
fn phong_specialised_on_its_lights_runs_fewer_operations_with_the_same_bits() {
    use crate::shader::exec::LANES;
    let mut log = InfoLog::default();
    let checked = compile_shader(PHONG, Stage::Fragment, &Options::default(), &mut log).unwrap();
    let lowered = crate::glsl::lower::lower(&[&checked]).unwrap();
    let compiled = Compiled::new(&lowered.program);
    let slot = |name: &str, index: u32| {
        lowered
            .uniforms
            .iter()
            .position(|w| w.name == name && w.index == index)
            .unwrap_or_else(|| panic!("{name}[{index}] in {:?}", lowered.uniforms))
    };
    // Colours and factors in (0, 1].
    let mut uniforms: Vec<u32> =
        (0..lowered.uniforms.len()).map(|i| (((i * 37) % 64 + 1) as f32 / 64.0).to_bits()).collect();
    uniforms[slot("gl_LightSource[0].position", 3)] = 0f32.to_bits();
    uniforms[slot("gl_LightSource[1].position", 3)] = 1f32.to_bits();
    uniforms[slot("gl_FrontMaterial.shininess", 0)] = 24f32.to_bits();
    let specialized = compiled.specialize(&uniforms);
    let (before, after) = (compiled.prepared_code().ops.len(), specialized.run_code().ops.len());
    assert!(after + 10 <= before, "{after} operations per block, {before} unspecialised");
    let mut rng = 0x1234_5678_9abc_def0u64;
    let mut float = || {
        rng = rng.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((rng >> 40) as f32 / (1u64 << 24) as f32) * 2.0 - 1.0
    };
    let (mut plain, mut special) = (Registers::new(), Registers::new());
    compiled.prepare(&mut plain, &uniforms);
    compiled.prepare_specialized(&specialized, &mut special);
    for block in 0..64 {
        let inputs: Vec<Word> = (0..6).map(|_| std::array::from_fn(|_| float().to_bits())).collect();
        let lanes = if block % 2 == 0 { !0 } else { (block * 0x9e37) as u16 | 1 };
        let run = |registers: &mut Registers, specialised: bool| {
            let mut outputs = vec![[0u32; LANES]; 4];
            let textures = crate::shader::exec::NoTextures;
            let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &textures };
            let kept = if specialised {
                compiled.run_specialized(&specialized, registers, &mut io, lanes)
            } else {
                compiled.run_prepared(registers, &mut io, lanes)
            };
            (kept, outputs)
        };
        assert_eq!(run(&mut special, true), run(&mut plain, false), "block {block}");
    }
}
