//! The generated programs against the hand-written per-vertex code they replaced
//! ([`super::reference`]), bit for bit, on random states and vertices, through the
//! reference executor and the pipeline's; and the per-vertex stage the draws run.

use super::reference::{shade, transform};
use super::*;
use crate::gl::enums::{GL_BACK, GL_FRONT, GL_FRONT_AND_BACK, GL_SEPARATE_SPECULAR_COLOR, GL_SINGLE_COLOR};
use crate::shader::exec::{Executor, Io, NoTextures, Word, LANES};
use crate::shader::fast::{Compiled, Registers};
use crate::shader::validate::validate;
use crate::vertex::lighting::{Light, LightingState, Material};
use crate::vertex::texgen::TexCoordUnit;

use crate::shader::build::TestRng as Rng;

/// The cases' values, from the shared test generator.
trait Draws {
    fn color(&mut self) -> [f32; 4];
    fn vec3(&mut self, r: f32) -> [f32; 3];
}

impl Draws for Rng {
    fn color(&mut self) -> [f32; 4] {
        std::array::from_fn(|_| if self.below(8) == 0 { 0.0 } else { self.range(0.0, 1.0) })
    }
    fn vec3(&mut self, r: f32) -> [f32; 3] {
        std::array::from_fn(|_| self.range(-r, r))
    }
}

fn random_light(rng: &mut Rng) -> Light {
    let [x, y, z] = rng.vec3(4.0);
    Light {
        ambient: rng.color(),
        diffuse: rng.color(),
        specular: rng.color(),
        position: [x, y, z, rng.pick(&[0.0, 1.0, 0.5])],
        spot_direction: rng.vec3(1.0),
        spot_exponent: rng.pick(&[0.0, 1.0, 7.5, 128.0]),
        spot_cutoff: if rng.below(2) == 0 { 180.0 } else { rng.range(0.0, 90.0) },
        attenuation: if rng.below(2) == 0 {
            [1.0, 0.0, 0.0]
        } else {
            [rng.range(0.0, 2.0), rng.range(0.0, 1.0), rng.range(0.0, 0.5)]
        },
    }
}

fn random_material(rng: &mut Rng) -> Material {
    Material {
        ambient: rng.color(),
        diffuse: rng.color(),
        specular: rng.color(),
        emission: rng.color(),
        shininess: if rng.below(3) == 0 { 0.0 } else { rng.range(0.0, 128.0) },
        ..Material::default()
    }
}

fn random_lighting(rng: &mut Rng) -> Lighting {
    let state = random_lighting_state(rng);
    let mut inverse_modelview = [0.0f32; 16];
    for (i, m) in inverse_modelview.iter_mut().enumerate() {
        *m = if i % 5 == 0 { rng.range(0.5, 2.0) } else { rng.range(-0.5, 0.5) };
    }
    let normals = match rng.below(3) {
        0 => NormalScaling::None,
        1 => NormalScaling::Normalize,
        _ => NormalScaling::Rescale(rng.range(0.5, 2.0)),
    };
    Lighting::new(&state, inverse_modelview, normals)
}

fn random_lighting_state(rng: &mut Rng) -> LightingState {
    let mut state = LightingState { enabled: true, ..LightingState::default() };
    for i in 0..state.lights.len() {
        state.lights[i] = rng.below(3) == 0;
        state.light[i] = random_light(rng);
    }
    state.color_material = rng.below(2) == 0;
    state.color_material_face = rng.pick(&[GL_FRONT, GL_BACK, GL_FRONT_AND_BACK]);
    state.color_material_mode = rng.pick(&[GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE]);
    state.model_ambient = rng.color();
    state.local_viewer = rng.below(2) == 0;
    state.two_side = rng.below(2) == 0;
    state.color_control = rng.pick(&[GL_SINGLE_COLOR, GL_SEPARATE_SPECULAR_COLOR]);
    state.materials = [random_material(rng), random_material(rng)];
    state
}

/// One vertex per lane: its eye position, normal and colour.
type LitVertex = ([f32; 4], [f32; 3], [f32; 4]);

/// The input words a generated lighting program reads, from one vertex per lane.
fn lighting_inputs(generated: &LightingProgram, vertices: &[LitVertex]) -> Vec<Word> {
    generated
        .inputs
        .iter()
        .map(|source| {
            std::array::from_fn(|lane| {
                let (eye, normal, color) = &vertices[lane];
                match *source {
                    VertexInput::Eye(k) => eye[k as usize],
                    VertexInput::Normal(k) => normal[k as usize],
                    VertexInput::Color(k) => color[k as usize],
                    other => unreachable!("the lighting program reads no {other:?}"),
                }
                .to_bits()
            })
        })
        .collect()
}

#[test]
fn generated_programs_give_the_bits_of_shade() {
    let mut rng = Rng(0xddc0_ffee_1234_5677);
    let mut executor = Executor::new();
    for case in 0..2000 {
        let lighting = random_lighting(&mut rng);
        let key = LightingKey::of(&lighting);
        let generated = LightingProgram::generate(&key);
        validate(&generated.program).unwrap_or_else(|e| panic!("case {case}: {e:?}"));
        let uniforms = generated.uniform_values(&lighting);
        let vertices: Vec<LitVertex> = (0..LANES)
            .map(|_| {
                let [x, y, z] = rng.vec3(5.0);
                ([x, y, z, 1.0], if rng.below(16) == 0 { [0.0; 3] } else { rng.vec3(1.0) }, rng.color())
            })
            .collect();
        let inputs = lighting_inputs(&generated, &vertices);
        let mut outputs = vec![[0u32; LANES]; generated.program.outputs.len()];
        let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &NoTextures };
        executor.run(&generated.program, &mut io, 0xffff);
        for (lane, (eye, normal, color)) in vertices.iter().enumerate() {
            let lit = shade(&lighting, *eye, *normal, *color);
            let mut want = vec![lit.front, lit.front_secondary];
            if key.two_side {
                want.extend([lit.back, lit.back_secondary]);
            }
            let want: Vec<u32> = want.iter().flatten().map(|v| v.to_bits()).collect();
            let got: Vec<u32> = outputs.iter().map(|o| o[lane]).collect();
            assert_eq!(got, want, "case {case} lane {lane}: {key:?}");
        }
    }
}

#[test]
fn the_key_holds_the_shape_and_the_uniforms_the_values() {
    let mut rng = Rng(99);
    let mut state = LightingState { enabled: true, ..LightingState::default() };
    state.lights[0] = true;
    state.lights[3] = true;
    state.light[3] = Light { position: [1.0, 2.0, 3.0, 1.0], ..Light::initial(3) };
    let a = Lighting::new(&state, [1.0; 16], NormalScaling::None);
    state.light[3].diffuse = rng.color();
    state.light[0].position = [0.0, 1.0, 0.0, 0.0];
    let b = Lighting::new(&state, [2.0; 16], NormalScaling::None);
    assert_eq!(LightingKey::of(&a), LightingKey::of(&b), "colours, directions and matrices are uniforms");
    let key = LightingKey::of(&a);
    assert_eq!(
        key.lights,
        [
            LightKey { local: false, spot: false, attenuated: false, no_power: [false; 2] },
            LightKey { local: true, spot: false, attenuated: false, no_power: [false; 2] }
        ]
    );
    state.materials[0].shininess = 5.0;
    assert_ne!(LightingKey::of(&Lighting::new(&state, [1.0; 16], NormalScaling::None)), key, "shininess 0 or not");
    let generated = LightingProgram::generate(&key);
    assert_eq!(generated.program.outputs.len(), 8, "front primary and secondary only");
    assert!(!generated.inputs.contains(&VertexInput::Color(0)), "no colour material, no colour input");
    let values = generated.uniform_values(&b);
    let position = generated.uniforms.iter().position(|u| *u == VertexUniform::Position { light: 1, k: 2 });
    assert_eq!(values[position.expect("a local light's position")], 3.0f32.to_bits());
}

fn random_matrix(rng: &mut Rng) -> glam::Mat4 {
    glam::Mat4::from_cols_array(&std::array::from_fn(|i| {
        if i % 5 == 0 {
            rng.range(0.5, 2.0)
        } else {
            rng.range(-1.0, 1.0)
        }
    }))
}

fn random_units(rng: &mut Rng) -> Vec<TexCoordUnit> {
    use crate::vertex::texgen::Gen as G;
    let mut units = Vec::new();
    for unit in 0..crate::gl::limits::MAX_TEXTURE_UNITS {
        if rng.below(2) == 0 {
            continue;
        }
        let gen: [Option<G>; 4] = std::array::from_fn(|c| match rng.below(7) {
            0 | 1 => None,
            2 => Some(G::Object(std::array::from_fn(|_| rng.range(-1.0, 1.0)))),
            3 => Some(G::Eye(std::array::from_fn(|_| rng.range(-1.0, 1.0)))),
            4 if c < 2 => Some(G::Sphere),
            5 if c < 3 => Some(G::Reflection),
            6 if c < 3 => Some(G::Normal),
            _ => None,
        });
        let needs_normal = gen.iter().any(|g| matches!(g, Some(G::Sphere | G::Reflection | G::Normal)));
        let matrix = (rng.below(2) == 0).then(|| random_matrix(rng));
        units.push(TexCoordUnit { unit, gen, needs_normal, matrix });
    }
    units
}

#[test]
fn generated_vertex_programs_give_the_bits_of_transform() {
    use crate::vertex::transform::LightingInput as Lit;
    use crate::vertex::Vertex;
    let mut rng = Rng(0x005e_ed0f_7a4e_0001);
    let mut executor = Executor::new();
    for case in 0..1500 {
        let lighting_state = LightingState { enabled: true, ..random_lighting_state(&mut rng) };
        let inverse = random_matrix(&mut rng);
        let normals = match rng.below(3) {
            0 => NormalScaling::None,
            1 => NormalScaling::Normalize,
            _ => NormalScaling::Rescale(rng.range(0.5, 2.0)),
        };
        let units = random_units(&mut rng);
        let lit = rng.below(2) == 0;
        let t = Transform {
            modelview: random_matrix(&mut rng),
            model_project: random_matrix(&mut rng),
            clamp_color: rng.below(2) == 0,
            fog: [
                None,
                Some(FogSource::Attribute),
                Some(FogSource::Radial),
                Some(FogSource::Plane),
                Some(FogSource::PlaneAbsolute),
            ][rng.below(5)],
            texgen: crate::vertex::texgen::TexGen {
                units: &units,
                modelview_inverse: inverse,
                normalize: rng.below(2) == 0,
                rescale_normal: rng.below(2) == 0,
            },
            lighting: lit.then(|| Lit {
                state: &lighting_state,
                modelview_inverse: inverse.to_cols_array(),
                normals,
                material_marks: &[],
            }),
        };
        let lighting = lit.then(|| Lighting::new(&lighting_state, inverse.to_cols_array(), normals));
        let key = VertexKey::of(&t, lighting.as_ref());
        let generated = VertexProgram::generate(&key);
        validate(&generated.program).unwrap_or_else(|e| panic!("case {case}: {e:?}"));
        let uniforms = generated.uniform_values(&t, lighting.as_ref());
        let vertices: Vec<Vertex> = (0..LANES)
            .map(|_| {
                let [x, y, z] = rng.vec3(5.0);
                Vertex {
                    position: [x, y, z, rng.pick(&[1.0, 0.5, 2.0])],
                    color: std::array::from_fn(|_| rng.range(-0.5, 1.5)),
                    secondary_color: std::array::from_fn(|_| rng.range(-0.5, 1.5)),
                    tex_coords: std::array::from_fn(|_| std::array::from_fn(|_| rng.range(-2.0, 2.0))),
                    normal: if rng.below(16) == 0 { [0.0; 3] } else { rng.vec3(1.0) },
                    fog_coord: rng.range(-1.0, 4.0),
                    edge_flag: true,
                    generic: crate::vertex::generic::CURRENT,
                }
            })
            .collect();
        let want = transform(&t, &vertices);
        let inputs: Vec<Word> = generated
            .inputs
            .iter()
            .map(|source| {
                std::array::from_fn(|lane| {
                    let v = &vertices[lane];
                    match *source {
                        VertexInput::Position(k) => v.position[k as usize],
                        VertexInput::Normal(k) => v.normal[k as usize],
                        VertexInput::Color(k) => v.color[k as usize],
                        VertexInput::SecondaryColor(k) => v.secondary_color[k as usize],
                        VertexInput::TexCoord { unit, k } => v.tex_coords[unit as usize][k as usize],
                        VertexInput::FogCoord => v.fog_coord,
                        VertexInput::Eye(_) => unreachable!("the eye position is computed"),
                    }
                    .to_bits()
                })
            })
            .collect();
        let mut outputs = vec![[0u32; LANES]; generated.program.outputs.len()];
        let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &NoTextures };
        executor.run(&generated.program, &mut io, 0xffff);
        // The pipeline's executor gives the reference's bits.
        let mut fast_outputs = vec![[0u32; LANES]; generated.program.outputs.len()];
        let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut fast_outputs, textures: &NoTextures };
        Compiled::new(&generated.program).run(&mut Registers::new(), &mut io, 0xffff);
        assert_eq!(fast_outputs, outputs, "case {case}: the interpreter");
        for (lane, w) in want.iter().enumerate() {
            for (slot, what) in generated.outputs.iter().enumerate() {
                let expected = match *what {
                    VertexOutput::Clip(k) => w.clip[k as usize],
                    VertexOutput::Eye(k) => w.eye[k as usize],
                    VertexOutput::Color(k) => w.color[k as usize],
                    VertexOutput::SecondaryColor(k) => w.secondary_color[k as usize],
                    VertexOutput::BackColor { which, k } => w.back_colors[which as usize][k as usize],
                    VertexOutput::TexCoord { unit, k } => w.tex_coords[unit as usize][k as usize],
                    VertexOutput::FogCoord => w.fog_coord,
                };
                assert_eq!(outputs[slot][lane], expected.to_bits(), "case {case} lane {lane} {what:?}: {key:?}");
            }
        }
    }
}

/// Every bit of a clip-space vertex (NaN payloads included).
fn clip_bits(c: &crate::vertex::clip::FixedClipVertex) -> Vec<u32> {
    let mut bits: Vec<u32> = [c.clip, c.eye, c.color, c.secondary_color, c.back_colors[0], c.back_colors[1]]
        .iter()
        .chain(&c.tex_coords)
        .flatten()
        .map(|x| x.to_bits())
        .collect();
    bits.extend([c.fog_coord.to_bits(), c.edge_flag as u32]);
    bits
}

#[test]
fn the_vertex_stage_gives_the_reference_s_vertices_across_batches_and_material_runs() {
    use crate::vertex::transform::{LightingInput as Lit, VertexStage};
    use crate::vertex::Vertex;
    use std::sync::Arc;
    let mut rng = Rng(0x0057_a9e0_0000_0042);
    for case in 0..200 {
        let mut lighting_state = LightingState { enabled: true, ..random_lighting_state(&mut rng) };
        // Shininess zero or not changes the program's shape from one run to the next.
        lighting_state.materials[0].shininess = rng.pick(&[0.0, 10.0]);
        let inverse = random_matrix(&mut rng);
        let units = random_units(&mut rng);
        let count = rng.pick(&[1, 15, 16, 17, 40, 64]);
        let lit = rng.below(4) != 0;
        // glMaterial marks: a first one at vertex 0 (the materials at glBegin), then a few.
        let mut marks: Vec<(usize, [Material; 2])> = Vec::new();
        if lit && rng.below(2) == 0 {
            let mut at = 0;
            while at < count + 3 {
                let mut materials = [random_material(&mut rng), random_material(&mut rng)];
                materials[0].shininess = rng.pick(&[0.0, 10.0]);
                marks.push((at, materials));
                at += rng.pick(&[0, 1, 5, 16, 23]);
            }
        }
        let t = Transform {
            modelview: random_matrix(&mut rng),
            model_project: random_matrix(&mut rng),
            clamp_color: rng.below(2) == 0,
            fog: [None, Some(FogSource::Radial), Some(FogSource::PlaneAbsolute)][rng.below(3)],
            texgen: crate::vertex::texgen::TexGen {
                units: &units,
                modelview_inverse: inverse,
                normalize: rng.below(2) == 0,
                rescale_normal: false,
            },
            lighting: lit.then(|| Lit {
                state: &lighting_state,
                modelview_inverse: inverse.to_cols_array(),
                normals: NormalScaling::Normalize,
                material_marks: &marks,
            }),
        };
        let vertices: Vec<Vertex> = (0..count)
            .map(|_| {
                let [x, y, z] = rng.vec3(5.0);
                Vertex {
                    position: [x, y, z, 1.0],
                    color: rng.color(),
                    secondary_color: std::array::from_fn(|_| rng.range(-0.5, 1.5)),
                    tex_coords: std::array::from_fn(|_| std::array::from_fn(|_| rng.range(-2.0, 2.0))),
                    normal: rng.vec3(1.0),
                    fog_coord: rng.range(-1.0, 4.0),
                    edge_flag: rng.below(2) == 0,
                    generic: crate::vertex::generic::CURRENT,
                }
            })
            .collect();
        let want: Vec<Vec<u32>> = transform(&t, &vertices).iter().map(clip_bits).collect();
        let mut lookups = 0;
        let stage = VertexStage::new(&t, count, |key| {
            lookups += 1;
            Arc::new(CompiledVertex::generate(key))
        });
        let runs = 1 + marks.iter().filter(|m| m.0 > 0 && m.0 < count).count();
        assert!(lookups <= runs, "case {case}: a lookup per run of vertices at most, not per batch");
        let got: Vec<Vec<u32>> = stage.run(&vertices, 0, |c| c.iter().map(clip_bits).collect());
        assert_eq!(
            got,
            want,
            "case {case}: {count} vertices, marks at {:?}",
            marks.iter().map(|m| m.0).collect::<Vec<_>>()
        );
        // The staged path (programs whose inputs and outputs are not bound to registers)
        // gives the same vertices; every generated program binds.
        let staged = VertexStage::new(&t, count, |key| {
            let mut compiled = CompiledVertex::generate(key);
            assert!(compiled.binding.is_some(), "case {case}: a generated program binds");
            compiled.binding = None;
            Arc::new(compiled)
        });
        let got: Vec<Vec<u32>> = staged.run(&vertices, 0, |c| c.iter().map(clip_bits).collect());
        assert_eq!(got, want, "case {case}: the staged path");
        // A later part of the draw (a draw split between threads) counts marks from the
        // draw's first vertex.
        let split = count / 2;
        let tail: Vec<Vec<u32>> = stage.run(&vertices[split..], split, |c| c.iter().map(clip_bits).collect());
        assert_eq!(tail, want[split..], "case {case}: the part from vertex {split}");
    }
}

#[test]
fn the_transforms_run_as_fused_matrix_rows_and_the_program_binds() {
    // The clip and eye transforms are one MatRow per row (the executor's fused form, which
    // the generator's instruction order must keep reachable), and the program binds its
    // inputs and outputs to registers.
    use crate::shader::lower::Op;
    let t = Transform {
        modelview: glam::Mat4::IDENTITY,
        model_project: glam::Mat4::IDENTITY,
        clamp_color: true,
        fog: None,
        texgen: crate::vertex::texgen::TexGen {
            units: &[],
            modelview_inverse: glam::Mat4::IDENTITY,
            normalize: false,
            rescale_normal: false,
        },
        lighting: None,
    };
    let compiled = CompiledVertex::generate(&VertexKey::of(&t, None));
    let rows = compiled.compiled.code().ops.iter().filter(|o| matches!(o, Op::MatRow { .. })).count();
    assert_eq!(rows, 8, "{:#?}", compiled.compiled.code());
    assert!(compiled.binding.is_some());
}

#[test]
fn a_draw_reuses_the_last_stage_only_when_its_unlit_state_is_the_same_bit_for_bit() {
    // StageCache: the stage of the draw before is reused only when the program's key and
    // every uniform value would be the same; any change (a matrix, even 0.0 to -0.0, a
    // texgen plane, the clamp) makes a new one, and a lit stage is never reused.
    use crate::vertex::texgen::{Gen, TexGen};
    use crate::vertex::transform::{LightingInput as Lit, StageCache, VertexStage};
    use crate::vertex::Vertex;
    use glam::Mat4;
    use std::sync::Arc;
    let plain = [TexCoordUnit {
        unit: 0,
        gen: [Some(Gen::Object([1.0, 0.0, 0.0, 0.0])), None, None, None],
        needs_normal: false,
        matrix: None,
    }];
    let moved_plane =
        [TexCoordUnit { gen: [Some(Gen::Object([0.0, 1.0, 0.0, 0.0])), None, None, None], ..plain[0].clone() }];
    let lighting_state = LightingState::default();
    let state = |modelview: Mat4, clamp_color: bool, units: &'static [TexCoordUnit]| (modelview, clamp_color, units);
    let transform = |(modelview, clamp_color, units): (Mat4, bool, &'static [TexCoordUnit]), lit: bool| Transform {
        modelview,
        model_project: modelview,
        clamp_color,
        fog: None,
        texgen: TexGen { units, modelview_inverse: Mat4::IDENTITY, normalize: false, rescale_normal: false },
        lighting: lit.then(|| Lit {
            state: &lighting_state,
            modelview_inverse: Mat4::IDENTITY.to_cols_array(),
            normals: NormalScaling::None,
            material_marks: &[],
        }),
    };
    let plain: &'static [TexCoordUnit] = Box::leak(Box::new(plain));
    let moved_plane: &'static [TexCoordUnit] = Box::leak(Box::new(moved_plane));
    let vertex = Vertex {
        position: [0.25, -0.5, 0.75, 1.0],
        color: [2.0, 0.5, 0.25, 1.0],
        secondary_color: [0.0; 4],
        tex_coords: [[0.5, 0.25, 0.0, 1.0]; crate::gl::limits::MAX_TEXTURE_UNITS],
        normal: [0.0, 0.0, 1.0],
        fog_coord: 0.0,
        edge_flag: true,
        generic: crate::vertex::generic::CURRENT,
    };
    let negative_zero =
        Mat4::from_cols_array(&[1.0, -0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
    let translated = Mat4::from_translation(glam::Vec3::new(0.5, 0.0, 0.0));
    let base = state(Mat4::IDENTITY, true, plain);
    // (state, lit, reused)
    let draws = [
        (base, false, false),
        (base, false, true),
        (state(translated, true, plain), false, false),
        (state(translated, true, plain), false, true),
        (state(negative_zero, true, plain), false, false),
        (base, false, false),
        (state(Mat4::IDENTITY, false, plain), false, false),
        (state(Mat4::IDENTITY, false, moved_plane), false, false),
        (state(Mat4::IDENTITY, false, moved_plane), false, true),
        (state(Mat4::IDENTITY, false, moved_plane), true, false),
        (state(Mat4::IDENTITY, false, moved_plane), true, false),
        (state(Mat4::IDENTITY, false, moved_plane), false, false),
    ];
    let mut cache: Option<Box<StageCache>> = None;
    for (i, &(s, lit, reused)) in draws.iter().enumerate() {
        let t = transform(s, lit);
        let mut lookups = 0;
        let stage = StageCache::reuse_or_new(cache.take(), &t, 1, |key| {
            lookups += 1;
            Arc::new(CompiledVertex::generate(key))
        });
        assert_eq!(lookups == 0, reused, "draw {i}: reused");
        let got: Vec<Vec<u32>> = stage.stage().run(&[vertex], 0, |c| c.iter().map(clip_bits).collect());
        let fresh = VertexStage::new(&t, 1, |key| Arc::new(CompiledVertex::generate(key)));
        let want: Vec<Vec<u32>> = fresh.run(&[vertex], 0, |c| c.iter().map(clip_bits).collect());
        assert_eq!(got, want, "draw {i}: the same vertex as a stage made afresh");
        cache = Some(stage);
    }
}

#[test]
fn the_direct_transform_gives_the_program_s_vertices_bit_for_bit() {
    // An unlit draw without texture units whose fog coordinate passes through runs its
    // program's arithmetic written out (`transform::Direct`): the same records, bit for
    // bit, as the program through the executor, on random matrices (special values among
    // their elements) and vertices with NaN, infinities, signed zeros and colours outside
    // [0, 1]; a state it does not cover (texgen, fog from the eye, lighting) runs the program.
    use crate::vertex::transform::{LightingInput as Lit, VertexStage};
    use crate::vertex::Vertex;
    use std::sync::Arc;
    let mut rng = Rng(0x00d1_2ec7_0000_0007);
    let special = [0.0, -0.0, 1.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e30, -3e-39, 0.5];
    let value = |rng: &mut Rng, r: f32| if rng.below(6) == 0 { rng.pick(&special) } else { rng.range(-r, r) };
    let lighting_state = LightingState::default();
    let no_units: [TexCoordUnit; 0] = [];
    for case in 0..300 {
        let mut matrix = random_matrix(&mut rng).to_cols_array();
        for m in &mut matrix {
            if rng.below(8) == 0 {
                *m = value(&mut rng, 2.0);
            }
        }
        let units = if case % 10 == 9 { random_units(&mut rng) } else { Vec::new() };
        let fog = [None, Some(FogSource::Attribute), Some(FogSource::Radial), Some(FogSource::Plane)][rng.below(4)];
        let lit = case % 10 == 8;
        let t = Transform {
            modelview: random_matrix(&mut rng),
            model_project: glam::Mat4::from_cols_array(&matrix),
            clamp_color: rng.below(2) == 0,
            fog,
            texgen: crate::vertex::texgen::TexGen {
                units: if units.is_empty() { &no_units } else { &units },
                modelview_inverse: glam::Mat4::IDENTITY,
                normalize: false,
                rescale_normal: false,
            },
            lighting: lit.then(|| Lit {
                state: &lighting_state,
                modelview_inverse: glam::Mat4::IDENTITY.to_cols_array(),
                normals: NormalScaling::None,
                material_marks: &[],
            }),
        };
        let count = rng.pick(&[1, 3, 16, 17, 50]);
        let vertices: Vec<Vertex> = (0..count)
            .map(|_| Vertex {
                position: std::array::from_fn(|_| value(&mut rng, 5.0)),
                color: std::array::from_fn(|_| value(&mut rng, 1.5)),
                secondary_color: std::array::from_fn(|_| value(&mut rng, 1.5)),
                tex_coords: std::array::from_fn(|_| std::array::from_fn(|_| rng.range(-2.0, 2.0))),
                normal: rng.vec3(1.0),
                fog_coord: value(&mut rng, 4.0),
                edge_flag: rng.below(2) == 0,
                generic: crate::vertex::generic::CURRENT,
            })
            .collect();
        let stage = VertexStage::new(&t, count, |key| Arc::new(CompiledVertex::generate(key)));
        let direct = !lit && units.is_empty() && matches!(fog, None | Some(FogSource::Attribute));
        assert_eq!(stage.runs_directly(), direct, "case {case}: the direct form exactly where it applies");
        let got: Vec<Vec<u32>> = stage.run(&vertices, 0, |c| c.iter().map(clip_bits).collect());
        let programmed = VertexStage::new(&t, count, |key| Arc::new(CompiledVertex::generate(key))).through_programs();
        let want: Vec<Vec<u32>> = programmed.run(&vertices, 0, |c| c.iter().map(clip_bits).collect());
        assert_eq!(got, want, "case {case}");
    }
}

#[test]
fn normalizations_are_one_executor_operation_each() {
    // The eye normal (GL_NORMALIZE), a local light's direction and its half vector are
    // written as dp3, Rsq and the products in the dot's order, which the executor fuses:
    // three normalize operations where the generic form was twelve dispatches.
    use crate::shader::lower::Op;
    let light = |local| LightKey { local, spot: false, attenuated: false, no_power: [false; 2] };
    let key = VertexKey {
        clamp_color: true,
        fog: None,
        texture_units: Vec::new(),
        texgen_normals: (false, false),
        lighting: Some(LightingKey {
            lights: vec![light(false), light(true)],
            local_viewer: false,
            two_side: false,
            separate_specular: false,
            normals: NormalsKey::Normalize,
            tracking: None,
            shininess_zero: [false, false],
        }),
    };
    let compiled = CompiledVertex::generate(&key).compiled;
    let ops = &compiled.prepared_code().ops;
    let normalizations = ops.iter().filter(|op| matches!(op, Op::Normalize3 { .. })).count();
    assert_eq!(normalizations, 3, "{ops:?}");
    assert!(!ops.iter().any(|op| matches!(op, Op::Sqrt { .. })), "no square root left but the fused ones");
}

#[test]
fn a_light_without_specular_light_raises_no_power_and_gives_the_same_bits() {
    // Lights whose specular product is zero skip the power (`power_unneeded`): the colours
    // must be the bits of the program that raises it and of the reference, for the normals
    // where the power is infinite (a tiny normal whose normalization overflows), NaN normals,
    // zero ones, and a vertex at a light's position (infinite or NaN attenuation).
    let mut rng = Rng(0x5eed_0f11_6475);
    let mut executor = Executor::new();
    let mut skipped = 0;
    for case in 0..600 {
        let mut state = random_lighting_state(&mut rng);
        for light in state.light.iter_mut() {
            if rng.below(2) == 0 {
                light.specular = [0.0, 0.0, 0.0, rng.range(0.0, 1.0)];
            }
            if rng.below(2) == 0 {
                light.spot_cutoff = 180.0;
            }
            light.attenuation[0] = rng.pick(&[0.0, 1e-7, 1e-6, 0.5, 1.0]);
        }
        state.color_material = rng.below(4) == 0;
        let normals = if rng.below(8) == 0 { NormalScaling::None } else { NormalScaling::Normalize };
        let mut inverse_modelview = [0.0f32; 16];
        for (i, m) in inverse_modelview.iter_mut().enumerate() {
            *m = if i % 5 == 0 { rng.range(0.5, 2.0) } else { rng.range(-0.5, 0.5) };
        }
        let lighting = Lighting::new(&state, inverse_modelview, normals);
        let key = LightingKey::of(&lighting);
        let without = LightingKey {
            lights: key.lights.iter().map(|l| LightKey { no_power: [false; 2], ..*l }).collect(),
            ..key.clone()
        };
        let skips = key.lights.iter().flat_map(|l| l.no_power).filter(|&s| s).count();
        skipped += skips;
        let special = [[1e-24, -2e-24, 3e-24], [1e-22, 0.0, 0.0], [0.0; 3], [f32::NAN, 0.0, 1.0], [1e30, 1e30, 0.0]];
        let local = lighting.lights.iter().find(|l| l.local).map(|l| l.position);
        let vertices: Vec<LitVertex> = (0..LANES)
            .map(|lane| {
                let [x, y, z] = match local {
                    Some(p) if lane == 0 => p,
                    _ => rng.vec3(5.0),
                };
                let normal = if lane > 0 && lane <= special.len() { special[lane - 1] } else { rng.vec3(1.0) };
                ([x, y, z, 1.0], normal, rng.color())
            })
            .collect();
        let mut run = |key: &LightingKey| {
            let generated = LightingProgram::generate(key);
            let uniforms = generated.uniform_values(&lighting);
            let inputs = lighting_inputs(&generated, &vertices);
            let mut outputs = vec![[0u32; LANES]; generated.program.outputs.len()];
            let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &NoTextures };
            executor.run(&generated.program, &mut io, 0xffff);
            let exp2s = generated
                .program
                .body
                .iter()
                .filter(|s| matches!(s, crate::shader::ir::Stmt::Inst(Inst::Unary { op: UnaryOp::Exp2, .. })))
                .count();
            (outputs, exp2s)
        };
        let ((got, exp2s), (want, all_exp2s)) = (run(&key), run(&without));
        assert_eq!(got, want, "case {case}: {key:?}");
        assert_eq!(exp2s + skips, all_exp2s, "case {case}: one power fewer per skipped term");
        for (lane, (eye, normal, color)) in vertices.iter().enumerate() {
            let lit = shade(&lighting, *eye, *normal, *color);
            let mut reference = vec![lit.front, lit.front_secondary];
            if key.two_side {
                reference.extend([lit.back, lit.back_secondary]);
            }
            let reference: Vec<u32> = reference.iter().flatten().map(|v| v.to_bits()).collect();
            let lane_bits: Vec<u32> = got.iter().map(|o| o[lane]).collect();
            assert_eq!(lane_bits, reference, "case {case} lane {lane}: {key:?}");
        }
    }
    assert!(skipped > 200, "the cases skip powers ({skipped})");
}
