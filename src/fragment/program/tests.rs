//! The generated programs against the per-pixel code they stand for, bit for bit, on
//! random states and inputs, through the reference executor.

use super::*;
use crate::fragment::FragmentState;
use crate::shader::exec::{Executor, Io, SampleRequest, Textures, Word, LANES};
use crate::shader::fast::{Compiled, Registers};
use crate::shader::validate::validate;
use crate::texture::env::Combine;

use crate::shader::build::TestRng as Rng;

/// The cases' values, from the shared test generator.
trait Draws {
    fn value(&mut self) -> f32;
}

impl Draws for Rng {
    /// A colour-like value: mostly in [−0.25, 1.25], sometimes exactly 0, ½ or 1, rarely NaN.
    fn value(&mut self) -> f32 {
        match self.below(16) {
            0 => 0.0,
            1 => 1.0,
            2 => 0.5,
            3 if self.below(8) == 0 => f32::NAN,
            _ => (self.below(1 << 20) as f32 / (1 << 20) as f32) * 1.5 - 0.25,
        }
    }
}

/// The texel the probe returns for unit `unit` at raw coordinates `coords` (s, t, r, q
/// before projection): a value the test can recompute, so that a lookup reading the wrong
/// unit or the wrong varyings gives another texel.
fn texel(unit: u8, coords: [u32; 4]) -> [f32; 4] {
    let mut h = 0x9e37_79b9_7f4a_7c15u64 ^ unit as u64;
    for c in coords {
        h = (h ^ c as u64).wrapping_mul(0x0100_0000_01b3);
    }
    std::array::from_fn(|k| {
        let bits = (h >> (16 * k)) as u16;
        match bits % 11 {
            0 => 0.0,
            1 => 1.0,
            _ => bits as f32 / 65535.0 * 1.2 - 0.1,
        }
    })
}

/// Textures for the generated programs: checks each request is the fixed-function one.
struct Probe;

impl Textures for Probe {
    fn sample(&self, r: &SampleRequest<'_>, out: &mut [Word; 4]) {
        assert!(r.projective && r.n == 3 && r.compare.is_none(), "a fixed-function lookup");
        assert!(matches!(r.lod, crate::shader::exec::LodLanes::Implicit));
        for lane in (0..LANES).filter(|l| r.lanes >> l & 1 != 0) {
            let t = texel(r.unit, [0, 1, 2, 3].map(|j| r.coords[j][lane]));
            for (channel, value) in out.iter_mut().zip(t) {
                channel[lane] = value.to_bits();
            }
        }
    }

    fn fetch(&self, _: u8, _: u8, _: &[Word; 3], _: &Word, _: u16, _: &mut [Word; 4]) {
        unreachable!("fixed-function programs do not fetch")
    }

    fn size(&self, _: u8, _: &Word, _: u16, _: &mut [Word; 3]) {
        unreachable!("fixed-function programs do not ask sizes")
    }
}

const BASES: [BaseFormat; 6] = [
    BaseFormat::Alpha,
    BaseFormat::Luminance,
    BaseFormat::LuminanceAlpha,
    BaseFormat::Intensity,
    BaseFormat::Rgb,
    BaseFormat::Rgba,
];

fn random_combine(rng: &mut Rng) -> Combine {
    use CombineFn::*;
    let sources = [
        Source::Texture,
        Source::TextureUnit(0),
        Source::TextureUnit(1),
        Source::TextureUnit(2),
        Source::TextureUnit(3),
        Source::TextureUnit(MAX_UNITS),
        Source::Constant,
        Source::PrimaryColor,
        Source::Previous,
    ];
    let operand =
        |rng: &mut Rng, alpha_only: bool| Operand { alpha: alpha_only || rng.below(3) == 0, invert: rng.below(2) == 0 };
    Combine {
        rgb: rng.pick(&[Replace, Modulate, Add, AddSigned, Interpolate, Subtract, Dot3Rgb, Dot3Rgba]),
        alpha: rng.pick(&[Replace, Modulate, Add, AddSigned, Interpolate, Subtract]),
        src_rgb: std::array::from_fn(|_| rng.pick(&sources)),
        op_rgb: std::array::from_fn(|_| operand(rng, false)),
        src_alpha: std::array::from_fn(|_| rng.pick(&sources)),
        op_alpha: std::array::from_fn(|_| operand(rng, true)),
        scale_rgb: rng.pick(&[1.0, 2.0, 4.0]),
        scale_alpha: rng.pick(&[1.0, 2.0, 4.0]),
    }
}

fn random_env(rng: &mut Rng) -> TexEnv {
    let mode = match rng.below(7) {
        0 => EnvMode::Replace,
        1 => EnvMode::Modulate,
        2 => EnvMode::Decal,
        3 => EnvMode::Blend,
        4 => EnvMode::Add,
        _ => EnvMode::Combine(random_combine(rng)),
    };
    TexEnv { mode, base: rng.pick(&BASES), color: std::array::from_fn(|_| rng.value()) }
}

/// One random draw state: units (with their environments and coordinate slots), colour
/// sum and fog as the fragment state holds them.
struct Case {
    units: Vec<(usize, usize, TexEnv)>,
    state: FragmentState,
    varyings: usize,
}

fn random_case(rng: &mut Rng) -> Case {
    let mut state = FragmentState::plain(None, Vec::new(), rng.below(2) == 0);
    state.color_sum = rng.below(2) == 0;
    state.fog = match rng.below(5) {
        0 => None,
        k => {
            let start = rng.pick(&[0.0, 0.25, 0.5, -1.0]);
            Some(Fog {
                mode: [FogMode::Linear, FogMode::Linear, FogMode::Exp, FogMode::Exp2][k - 1],
                start,
                end: if rng.below(4) == 0 { start } else { rng.pick(&[1.0, 0.75, 2.5]) },
                density: rng.pick(&[0.0, 0.5, 1.0, 3.0]),
                color: std::array::from_fn(|_| rng.value().clamp(0.0, 1.0)),
            })
        }
    };
    // Varyings: the secondary colour (0..3) with the colour sum, the fog coordinate, then
    // four per unit.
    let first = if state.color_sum { 3 } else { 0 } + usize::from(state.fog.is_some());
    let mut units = Vec::new();
    for unit in 0..MAX_UNITS {
        if rng.below(2) == 0 {
            units.push((unit, first + 4 * units.len(), random_env(rng)));
        }
    }
    let varyings = first + 4 * units.len();
    Case { units, state, varyings }
}

/// The per-pixel code's colour of one fragment (the tests' reference, written out
/// directly: [`TexEnv::apply`] and [`super::super::fog::fog_factor`] are compiled for the
/// tests only): every unit's environment in order, then the colour sum (clamped when
/// fragment colours are) and fog, `f·C + (1 − f)·Cfog` on RGB. The colour sum precedes fog
/// (GL 2.1 §3.10, §3.11).
fn reference(case: &Case, primary: [f32; 4], varyings: &[f32]) -> [f32; 4] {
    let mut texels = [[0.0, 0.0, 0.0, 1.0]; MAX_UNITS];
    for (unit, slot, _) in &case.units {
        texels[*unit] = texel(*unit as u8, std::array::from_fn(|j| varyings[slot + j].to_bits()));
    }
    let mut color = primary;
    for (unit, _, env) in &case.units {
        color = env.apply(*unit, color, primary, &texels);
    }
    let state = &case.state;
    if state.color_sum {
        for (c, &s) in color[..3].iter_mut().zip(&varyings[..3]) {
            *c += s;
            if state.clamp_float {
                *c = if *c > 0.0 { c.min(1.0) } else { 0.0 };
            }
        }
    }
    if let Some(fog) = &state.fog {
        let coordinate = varyings[if state.color_sum { 3 } else { 0 }];
        let f = super::super::fog::fog_factor(fog, coordinate);
        for (x, &fog_c) in color[..3].iter_mut().zip(&fog.color[..3]) {
            *x = f * *x + (1.0 - f) * fog_c;
        }
    }
    color
}

#[test]
fn generated_programs_give_the_bits_of_the_per_pixel_code() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let mut executor = Executor::new();
    for case_index in 0..3000 {
        let case = random_case(&mut rng);
        let key = FragmentKey::new(
            case.units.iter().map(|(u, s, e)| (*u, *s, e)),
            case.state.color_sum.then_some(case.state.clamp_float),
            case.state.fog.as_ref(),
        );
        let fixed = FixedFragment::generate(&key);
        validate(&fixed.program).unwrap_or_else(|e| panic!("case {case_index}: {e:?}"));
        let envs: Vec<&TexEnv> = case.units.iter().map(|(_, _, e)| e).collect();
        let uniforms = fixed.uniform_values(&envs, case.state.fog.as_ref());
        let primary: [[f32; 4]; LANES] = std::array::from_fn(|_| std::array::from_fn(|_| rng.value()));
        let varyings: Vec<Vec<f32>> = (0..LANES).map(|_| (0..case.varyings).map(|_| rng.value()).collect()).collect();
        let inputs: Vec<Word> = fixed
            .inputs
            .iter()
            .map(|source| {
                std::array::from_fn(|lane| match *source {
                    FragmentInput::Primary(k) => primary[lane][k as usize].to_bits(),
                    FragmentInput::Varying(v) => varyings[lane][v as usize].to_bits(),
                })
            })
            .collect();
        let mut outputs = vec![[0u32; LANES]; 4];
        let lanes = rng.next() as u16 | 1;
        let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut outputs, textures: &Probe };
        assert_eq!(executor.run(&fixed.program, &mut io, lanes), lanes, "nothing discards");
        // The pipeline's executor gives the reference's results (NaN as any NaN).
        let mut fast_outputs = vec![[0u32; LANES]; 4];
        let mut io = Io { inputs: &inputs, uniforms: &uniforms, outputs: &mut fast_outputs, textures: &Probe };
        assert_eq!(Compiled::new(&fixed.program).run(&mut Registers::new(), &mut io, lanes), lanes);
        for lane in (0..LANES).filter(|l| lanes >> l & 1 != 0) {
            for k in 0..4 {
                let (a, b) = (f32::from_bits(fast_outputs[k][lane]), f32::from_bits(outputs[k][lane]));
                assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()), "case {case_index}: the interpreter");
            }
        }
        for lane in (0..LANES).filter(|l| lanes >> l & 1 != 0) {
            let want = reference(&case, primary[lane], &varyings[lane]).map(f32::to_bits);
            let got: [u32; 4] = std::array::from_fn(|k| outputs[k][lane]);
            assert_eq!(got, want, "case {case_index} lane {lane}: {key:?}");
        }
    }
}

#[test]
fn the_key_holds_the_shape_and_the_uniforms_the_values() {
    let env = |color: [f32; 4]| TexEnv { mode: EnvMode::Blend, base: BaseFormat::Rgb, color };
    let (a, b) = (env([0.25; 4]), env([0.75; 4]));
    let fog = |start: f32, end: f32| Fog { mode: FogMode::Linear, start, end, density: 1.0, color: [0.5; 4] };
    let key_a = FragmentKey::new([(1, 4, &a)], None, Some(&fog(0.0, 1.0)));
    let key_b = FragmentKey::new([(1, 4, &b)], None, Some(&fog(0.5, 2.0)));
    assert_eq!(key_a, key_b, "colours and fog distances are uniforms");
    assert_ne!(key_a, FragmentKey::new([(1, 4, &a)], None, Some(&fog(1.0, 1.0))), "LINEAR with start = end");
    assert_ne!(key_a, FragmentKey::new([(2, 4, &a)], None, Some(&fog(0.0, 1.0))), "another unit");
    assert_ne!(key_a, FragmentKey::new([(1, 4, &a)], Some(true), Some(&fog(0.0, 1.0))), "colour sum");
    let fixed = FixedFragment::generate(&key_a);
    let values = fixed.uniform_values(&[&b], Some(&fog(0.5, 2.0)));
    let env_color = fixed.uniforms.iter().position(|u| *u == FragmentUniform::EnvColor { stage: 0, channel: 2 });
    assert_eq!(values[env_color.expect("BLEND reads the constant")], 0.75f32.to_bits());
    let start = fixed.uniforms.iter().position(|u| *u == FragmentUniform::FogStart).expect("LINEAR reads start");
    assert_eq!(values[start], 0.5f32.to_bits());
    // MODULATE reads no constant: no uniform for it.
    let modulate = TexEnv { mode: EnvMode::Modulate, ..a };
    let plain = FixedFragment::generate(&FragmentKey::new([(0, 0, &modulate)], None, None));
    assert!(plain.uniforms.is_empty());
    assert_eq!(plain.inputs.len(), 4 + 4, "the primary colour and one unit's s, t, r, q");
    let lookups =
        plain.program.body.iter().filter(|s| matches!(s, crate::shader::ir::Stmt::Inst(Inst::Sample { .. }))).count();
    assert_eq!(lookups, 1);
}
