//! The generated lighting programs against `Lighting::shade`, bit for bit, on random
//! lighting states and vertices, through the reference executor.

use super::*;
use crate::gl::enums::{GL_BACK, GL_FRONT, GL_FRONT_AND_BACK, GL_SEPARATE_SPECULAR_COLOR, GL_SINGLE_COLOR};
use crate::shader::exec::{Executor, Io, NoTextures, Word, LANES};
use crate::shader::validate::validate;
use crate::vertex::lighting::{Light, LightingState, Material};

/// A small xorshift generator: the same cases on every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }

    /// Uniform in [lo, hi), on a grid of 2⁻²⁰ of the range.
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * (self.below(1 << 20) as f32 / (1 << 20) as f32)
    }

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

#[test]
fn generated_programs_give_the_bits_of_shade() {
    let mut rng = Rng(0xddc0_ffee_1234_5677);
    let mut executor = Executor::new();
    for case in 0..2000 {
        let mut lighting = random_lighting(&mut rng);
        let key = LightingKey::of(&lighting);
        let generated = LightingProgram::generate(&key);
        validate(&generated.program).unwrap_or_else(|e| panic!("case {case}: {e:?}"));
        let uniforms = generated.uniform_values(&lighting);
        let vertices: Vec<([f32; 4], [f32; 3], [f32; 4])> = (0..LANES)
            .map(|_| {
                let [x, y, z] = rng.vec3(5.0);
                ([x, y, z, 1.0], if rng.below(16) == 0 { [0.0; 3] } else { rng.vec3(1.0) }, rng.color())
            })
            .collect();
        let inputs: Vec<Word> = generated
            .inputs
            .iter()
            .map(|source| {
                std::array::from_fn(|lane| {
                    let (eye, normal, color) = &vertices[lane];
                    match *source {
                        LightingInput::Eye(k) => eye[k as usize],
                        LightingInput::Normal(k) => normal[k as usize],
                        LightingInput::Color(k) => color[k as usize],
                    }
                    .to_bits()
                })
            })
            .collect();
        let mut outputs = vec![[0u32; LANES]; generated.program.outputs.len()];
        let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &NoTextures };
        executor.run(&generated.program, &mut io, 0xffff);
        for (lane, (eye, normal, color)) in vertices.iter().enumerate() {
            let lit = lighting.shade(*eye, *normal, *color);
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
            LightKey { local: false, spot: false, attenuated: false },
            LightKey { local: true, spot: false, attenuated: false }
        ]
    );
    state.materials[0].shininess = 5.0;
    assert_ne!(LightingKey::of(&Lighting::new(&state, [1.0; 16], NormalScaling::None)), key, "shininess 0 or not");
    let generated = LightingProgram::generate(&key);
    assert_eq!(generated.program.outputs.len(), 8, "front primary and secondary only");
    assert!(!generated.inputs.contains(&LightingInput::Color(0)), "no colour material, no colour input");
    let values = generated.uniform_values(&b);
    let position = generated.uniforms.iter().position(|u| *u == LightingUniform::Position { light: 1, k: 2 });
    assert_eq!(values[position.expect("a local light's position")], 3.0f32.to_bits());
}
