//! The fixed-function fragment program: a draw's texture environments (every enabled unit,
//! GL_COMBINE and the crossbar included), colour sum and fog (GL 2.1 §3.8.13, 3.9, 3.10)
//! written as a shading-IR program ([`crate::shader::ir`]) from a compact key of the state,
//! as Mesa builds one in `ff_fragment_shader`, so that fixed-function and GLSL fragment
//! shading run on one executor.
//!
//! The program is the one path: the pipeline runs it for every fragment
//! ([`super::shading`]). Its arithmetic is that of the per-pixel code it replaced, kept for
//! the tests only as their reference (`TexEnv::apply`, `fog::fog_factor` and the colour sum
//! in `tests.rs`): the same IEEE operations on the same operands in the same order, and
//! fog's own exponential ([`crate::shader::math::exp`]), so the same bits; the tests run
//! both on random states and inputs.
//!
//! What varies between draws without changing the program's shape is a uniform (each
//! unit's GL_TEXTURE_ENV_COLOR, the fog parameters), so that the cache of programs is
//! keyed by the shape alone ([`FragmentKey`]): which units, their modes and base formats,
//! the combine functions, sources, operands and scales, whether the colour sum is on and
//! clamped, and the fog mode.
//!
//! - Inputs: the primary colour (RGBA), then the varyings the program reads
//!   ([`FixedFragment::inputs`] says which: the secondary colour, the fog coordinate, each
//!   unit's s, t, r, q).
//! - Outputs: the fragment colour (RGBA).
//! - Lookups: one `Sample` per unit, all before the first environment (a crossbar source
//!   reads any unit's texel), at s, t, r divided by q (`projective`), with the implicit
//!   level of detail; the unit's own comparison mode applies (the fixed-function rule: r is
//!   the reference), so the program asks for no comparison.

use super::fog::{Fog, FogMode};
use crate::shader::build::Builder;
use crate::shader::fast::{Bound, Compiled};
use crate::shader::ir::{BinaryOp, Inst, Lod, Program, Reg, Stage, Type, UnaryOp};
use crate::texture::env::{CombineFn, EnvMode, Operand, Source, TexEnv};
use crate::texture::BaseFormat;
use std::collections::HashMap;

/// The most texture units a fixed-function program reads (a crossbar source naming a unit
/// beyond them reads the default texel, as [`crate::texture::Texturing`] does).
pub const MAX_UNITS: usize = crate::gl::limits::MAX_TEXTURE_UNITS;

/// The shape of one enabled unit's environment: its unit number, the varying where its
/// coordinates start, the base format its texture has, and its mode (combine scales as
/// bits).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StageKey {
    pub unit: u8,
    pub slot: u16,
    pub base: BaseFormat,
    pub mode: ModeKey,
}

/// [`EnvMode`] with the combine scales as bits, so that keys hash.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ModeKey {
    Replace,
    Modulate,
    Decal,
    Blend,
    Add,
    Combine {
        rgb: CombineFn,
        alpha: CombineFn,
        src_rgb: [Source; 3],
        op_rgb: [Operand; 3],
        src_alpha: [Source; 3],
        op_alpha: [Operand; 3],
        scale_rgb: u32,
        scale_alpha: u32,
    },
}

impl ModeKey {
    fn of(mode: &EnvMode) -> ModeKey {
        match *mode {
            EnvMode::Replace => ModeKey::Replace,
            EnvMode::Modulate => ModeKey::Modulate,
            EnvMode::Decal => ModeKey::Decal,
            EnvMode::Blend => ModeKey::Blend,
            EnvMode::Add => ModeKey::Add,
            EnvMode::Combine(c) => ModeKey::Combine {
                rgb: c.rgb,
                alpha: c.alpha,
                src_rgb: c.src_rgb,
                op_rgb: c.op_rgb,
                src_alpha: c.src_alpha,
                op_alpha: c.op_alpha,
                scale_rgb: c.scale_rgb.to_bits(),
                scale_alpha: c.scale_alpha.to_bits(),
            },
        }
    }

    /// Whether the environment reads GL_TEXTURE_ENV_COLOR.
    fn reads_constant(&self) -> bool {
        match self {
            ModeKey::Blend => true,
            ModeKey::Combine { rgb, alpha, src_rgb, src_alpha, .. } => {
                let used = |f: &CombineFn| arguments(*f);
                src_rgb[..used(rgb)].contains(&Source::Constant) || src_alpha[..used(alpha)].contains(&Source::Constant)
            }
            _ => false,
        }
    }
}

/// The fog mode's shape: LINEAR with start = end is its own formula (Mesa's, see
/// [`super::fog`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FogKey {
    Linear,
    LinearDegenerate,
    Exp,
    Exp2,
}

/// Everything that decides the shape of a fixed-function fragment program.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct FragmentKey {
    pub stages: Vec<StageKey>,
    /// The colour sum when on: whether its result is clamped to [0, 1].
    pub color_sum: Option<bool>,
    pub fog: Option<FogKey>,
}

impl FragmentKey {
    /// The key of the units `stages` (unit, first coordinate varying, environment; in unit
    /// order), the colour sum (`Some(clamp)` when on) and `fog`.
    pub fn new<'a>(
        stages: impl IntoIterator<Item = (usize, usize, &'a TexEnv)>,
        color_sum: Option<bool>,
        fog: Option<&Fog>,
    ) -> FragmentKey {
        FragmentKey {
            stages: stages
                .into_iter()
                .map(|(unit, slot, env)| StageKey {
                    unit: unit as u8,
                    slot: slot as u16,
                    base: env.base,
                    mode: ModeKey::of(&env.mode),
                })
                .collect(),
            color_sum,
            fog: fog.map(|f| match f.mode {
                FogMode::Linear if f.start == f.end => FogKey::LinearDegenerate,
                FogMode::Linear => FogKey::Linear,
                FogMode::Exp => FogKey::Exp,
                FogMode::Exp2 => FogKey::Exp2,
            }),
        }
    }

    /// The key of a draw's fragment state.
    pub fn of(state: &super::FragmentState) -> FragmentKey {
        let stages = state.texturing.iter().flat_map(|t| t.stages.iter()).map(|s| (s.unit, s.slot, &s.env));
        FragmentKey::new(stages, state.color_sum.then_some(state.clamp_float), state.fog.as_ref())
    }
}

/// Where an input word of the program comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FragmentInput {
    /// Channel 0..4 of the primary (interpolated or flat) colour.
    Primary(u8),
    /// A varying of the draw (the secondary colour, the fog coordinate, texture coordinates).
    Varying(u16),
}

/// Which state value a uniform word holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FragmentUniform {
    /// Channel `channel` of GL_TEXTURE_ENV_COLOR of the key's stage `stage`.
    EnvColor {
        stage: u8,
        channel: u8,
    },
    FogStart,
    FogEnd,
    FogDensity,
    /// Channel 0..3 of the fog colour.
    FogColor(u8),
}

/// A fragment program ready to run: what the generator made of a key, and its compiled form
/// (the form the pipeline runs; the generated program stays for `TESSERA_DEBUG=programs`
/// and the slot tables).
#[derive(Clone, Debug)]
pub struct CompiledFragment {
    pub fixed: FixedFragment,
    pub compiled: Compiled,
    /// The form the pipeline runs when the program has one (no control flow: every
    /// fixed-function program).
    pub bound: Option<Bound>,
}

impl CompiledFragment {
    /// Generates and compiles the program of `key`.
    pub fn generate(key: &FragmentKey) -> CompiledFragment {
        let fixed = FixedFragment::generate(key);
        let compiled = Compiled::new(&fixed.program);
        let bound = compiled.bind();
        CompiledFragment { fixed, compiled, bound }
    }
}

/// A generated program and what its input and uniform slots hold.
#[derive(Clone, Debug)]
pub struct FixedFragment {
    pub program: Program,
    pub inputs: Vec<FragmentInput>,
    pub uniforms: Vec<FragmentUniform>,
}

impl FixedFragment {
    /// The program of `key`.
    pub fn generate(key: &FragmentKey) -> FixedFragment {
        let mut g = Gen::new(Stage::Fragment);
        let primary: [Reg; 4] = std::array::from_fn(|k| g.input(FragmentInput::Primary(k as u8)));
        // Every unit's texel first: a crossbar source may read a later unit's.
        let mut texels: HashMap<u8, [Reg; 4]> = HashMap::new();
        for stage in &key.stages {
            let coords = std::array::from_fn(|j| g.input(FragmentInput::Varying(stage.slot + j as u16)));
            let dst = std::array::from_fn(|_| g.register(Type::F32));
            g.emit(Inst::Sample {
                dst,
                unit: stage.unit,
                n: 3,
                coords,
                projective: true,
                lod: Lod::Implicit,
                compare: None,
            });
            texels.insert(stage.unit, dst);
        }
        let zero = g.constant(0.0);
        let mut sources = Sources { previous: primary, primary, constant: [zero; 4], texels };
        for (index, stage) in key.stages.iter().enumerate() {
            sources.constant = if stage.mode.reads_constant() {
                std::array::from_fn(|k| g.uniform(FragmentUniform::EnvColor { stage: index as u8, channel: k as u8 }))
            } else {
                [zero; 4]
            };
            sources.previous = g.environment(stage, &sources);
        }
        let mut color = sources.previous;
        if let Some(clamp) = key.color_sum {
            for (k, c) in color[..3].iter_mut().enumerate() {
                let secondary = g.input(FragmentInput::Varying(k as u16));
                *c = g.binary(BinaryOp::FAdd, *c, secondary);
                if clamp {
                    *c = g.clamp01(*c);
                }
            }
        }
        if let Some(fog) = key.fog {
            let index = if key.color_sum.is_some() { 3 } else { 0 };
            let coordinate = g.input(FragmentInput::Varying(index));
            let factor = g.fog_factor(fog, coordinate);
            let one = g.constant(1.0);
            let remaining = g.binary(BinaryOp::FSub, one, factor);
            for (k, c) in color[..3].iter_mut().enumerate() {
                let fog_color = g.uniform(FragmentUniform::FogColor(k as u8));
                let kept = g.binary(BinaryOp::FMul, factor, *c);
                let added = g.binary(BinaryOp::FMul, remaining, fog_color);
                *c = g.binary(BinaryOp::FAdd, kept, added);
            }
        }
        for c in color {
            let slot = g.program.output(Type::F32);
            g.emit(Inst::Output { slot, src: c });
        }
        let (program, inputs, uniforms) = g.finish();
        FixedFragment { program, inputs, uniforms }
    }

    /// The uniform words of a draw whose units have the environments `envs` (the key's
    /// stages, in order) and whose fog is `fog`.
    pub fn uniform_values(&self, envs: &[&TexEnv], fog: Option<&Fog>) -> Vec<u32> {
        let fog_value = |f: fn(&Fog) -> f32| fog.map_or(0, |fog| f(fog).to_bits());
        self.uniforms
            .iter()
            .map(|u| match *u {
                FragmentUniform::EnvColor { stage, channel } => {
                    envs.get(stage as usize).map_or(0, |e| e.color[channel as usize].to_bits())
                }
                FragmentUniform::FogStart => fog_value(|f| f.start),
                FragmentUniform::FogEnd => fog_value(|f| f.end),
                FragmentUniform::FogDensity => fog_value(|f| f.density),
                FragmentUniform::FogColor(k) => fog.map_or(0, |f| f.color[k as usize].to_bits()),
            })
            .collect()
    }
}

/// How many arguments a combine function reads.
fn arguments(f: CombineFn) -> usize {
    match f {
        CombineFn::Replace => 1,
        CombineFn::Interpolate => 3,
        _ => 2,
    }
}

/// What one unit's environment reads besides its own texel: the previous unit's colour,
/// the primary colour, GL_TEXTURE_ENV_COLOR, and every unit's texel (for the crossbar).
struct Sources {
    previous: [Reg; 4],
    primary: [Reg; 4],
    constant: [Reg; 4],
    texels: HashMap<u8, [Reg; 4]>,
}

/// The program being written (the generator's own operations are below).
type Gen = Builder<FragmentInput, FragmentUniform>;

impl Gen {
    /// `a·b + c·d`, each product and the sum rounded once.
    fn products(&mut self, a: Reg, b: Reg, c: Reg, d: Reg) -> Reg {
        let ab = self.binary(BinaryOp::FMul, a, b);
        let cd = self.binary(BinaryOp::FMul, c, d);
        self.binary(BinaryOp::FAdd, ab, cd)
    }

    /// One unit's environment ([`TexEnv::apply`]): its output colour from the previous
    /// unit's `previous`.
    fn environment(&mut self, stage: &StageKey, sources: &Sources) -> [Reg; 4] {
        let Sources { previous, constant, texels, .. } = sources;
        let (previous, constant) = (*previous, *constant);
        let t = texels[&stage.unit];
        let cf = previous;
        let cc = constant;
        let base = stage.base;
        let has_color = !matches!(base, BaseFormat::Alpha);
        let has_alpha =
            matches!(base, BaseFormat::Alpha | BaseFormat::LuminanceAlpha | BaseFormat::Intensity | BaseFormat::Rgba);
        let mut rgb = cf;
        let alpha;
        match stage.mode {
            ModeKey::Replace => {
                if has_color {
                    rgb[..3].copy_from_slice(&t[..3]);
                }
                alpha = if has_alpha { t[3] } else { cf[3] };
            }
            ModeKey::Modulate => {
                if has_color {
                    for k in 0..3 {
                        rgb[k] = self.binary(BinaryOp::FMul, cf[k], t[k]);
                    }
                }
                alpha = if has_alpha { self.binary(BinaryOp::FMul, cf[3], t[3]) } else { cf[3] };
            }
            ModeKey::Decal => {
                match base {
                    BaseFormat::Rgb => rgb[..3].copy_from_slice(&t[..3]),
                    BaseFormat::Rgba => {
                        let remaining = self.one_minus(t[3]);
                        for k in 0..3 {
                            rgb[k] = self.products(cf[k], remaining, t[k], t[3]);
                        }
                    }
                    // Undefined for other formats: the fragment passes unchanged.
                    _ => {}
                }
                alpha = cf[3];
            }
            ModeKey::Blend => {
                if has_color {
                    for k in 0..3 {
                        let remaining = self.one_minus(t[k]);
                        rgb[k] = self.products(cf[k], remaining, cc[k], t[k]);
                    }
                }
                alpha = match base {
                    BaseFormat::Intensity => {
                        let remaining = self.one_minus(t[3]);
                        self.products(cf[3], remaining, cc[3], t[3])
                    }
                    _ if has_alpha => self.binary(BinaryOp::FMul, cf[3], t[3]),
                    _ => cf[3],
                };
            }
            ModeKey::Add => {
                if has_color {
                    for k in 0..3 {
                        rgb[k] = self.binary(BinaryOp::FAdd, cf[k], t[k]);
                    }
                }
                alpha = match base {
                    BaseFormat::Intensity => self.binary(BinaryOp::FAdd, cf[3], t[3]),
                    _ if has_alpha => self.binary(BinaryOp::FMul, cf[3], t[3]),
                    _ => cf[3],
                };
            }
            ModeKey::Combine { .. } => return self.combine(stage, sources),
        }
        [self.clamp01(rgb[0]), self.clamp01(rgb[1]), self.clamp01(rgb[2]), self.clamp01(alpha)]
    }

    /// GL_COMBINE (the span path's `combine`).
    fn combine(&mut self, stage: &StageKey, sources: &Sources) -> [Reg; 4] {
        let &Sources { previous, primary, constant, ref texels } = sources;
        let ModeKey::Combine { rgb, alpha, src_rgb, op_rgb, src_alpha, op_alpha, scale_rgb, scale_alpha } = stage.mode
        else {
            unreachable!("combine of a classic mode")
        };
        let default_texel = [self.constant(0.0), self.constant(0.0), self.constant(0.0), self.constant(1.0)];
        let source = |s: Source| -> [Reg; 4] {
            match s {
                Source::Texture => texels[&stage.unit],
                Source::TextureUnit(n) => {
                    u8::try_from(n).ok().and_then(|n| texels.get(&n)).copied().unwrap_or(default_texel)
                }
                Source::Constant => constant,
                Source::PrimaryColor => primary,
                Source::Previous => previous,
            }
        };
        let mut rgb_args = Vec::new();
        for i in 0..arguments(rgb) {
            let c = source(src_rgb[i]);
            let v = if op_rgb[i].alpha { [c[3]; 3] } else { [c[0], c[1], c[2]] };
            rgb_args.push(if op_rgb[i].invert { v.map(|x| self.one_minus(x)) } else { v });
        }
        let a = &rgb_args;
        let half = self.constant(0.5);
        let color: [Reg; 3] = match rgb {
            CombineFn::Replace => a[0],
            CombineFn::Modulate => per_channel(self, &|g, k| g.binary(BinaryOp::FMul, a[0][k], a[1][k])),
            CombineFn::Add => per_channel(self, &|g, k| g.binary(BinaryOp::FAdd, a[0][k], a[1][k])),
            CombineFn::AddSigned => per_channel(self, &|g, k| {
                let sum = g.binary(BinaryOp::FAdd, a[0][k], a[1][k]);
                g.binary(BinaryOp::FSub, sum, half)
            }),
            CombineFn::Interpolate => per_channel(self, &|g, k| {
                let remaining = g.one_minus(a[2][k]);
                g.products(a[0][k], a[2][k], a[1][k], remaining)
            }),
            CombineFn::Subtract => per_channel(self, &|g, k| g.binary(BinaryOp::FSub, a[0][k], a[1][k])),
            CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => {
                // 4·Σ (a0 − ½)(a1 − ½), summed from the first product (the span path starts
                // its sum at zero: the same value but for the sign of a zero, which the
                // clamp below makes 0 either way).
                let x: [Reg; 3] = std::array::from_fn(|k| self.binary(BinaryOp::FSub, a[0][k], half));
                let y: [Reg; 3] = std::array::from_fn(|k| self.binary(BinaryOp::FSub, a[1][k], half));
                let sum = self.register(Type::F32);
                self.emit(Inst::Dot { dst: sum, n: 3, a: [x[0], x[1], x[2], x[0]], b: [y[0], y[1], y[2], y[0]] });
                let four = self.constant(4.0);
                let d = self.binary(BinaryOp::FMul, four, sum);
                [d; 3]
            }
        };
        let scale_rgb = self.constant(f32::from_bits(scale_rgb));
        let scale_alpha = self.constant(f32::from_bits(scale_alpha));
        if rgb == CombineFn::Dot3Rgba {
            // The dot product goes to alpha too, scaled by GL_ALPHA_SCALE (as Mesa does).
            let scaled = self.binary(BinaryOp::FMul, color[0], scale_rgb);
            let c = self.clamp01(scaled);
            let scaled_alpha = self.binary(BinaryOp::FMul, color[0], scale_alpha);
            return [c, c, c, self.clamp01(scaled_alpha)];
        }
        let color = color.map(|x| {
            let scaled = self.binary(BinaryOp::FMul, x, scale_rgb);
            self.clamp01(scaled)
        });
        let mut b = Vec::new();
        for i in 0..arguments(alpha) {
            let v = source(src_alpha[i])[3];
            b.push(if op_alpha[i].invert { self.one_minus(v) } else { v });
        }
        let value = match alpha {
            CombineFn::Replace => b[0],
            CombineFn::Modulate => self.binary(BinaryOp::FMul, b[0], b[1]),
            CombineFn::Add => self.binary(BinaryOp::FAdd, b[0], b[1]),
            CombineFn::AddSigned => {
                let sum = self.binary(BinaryOp::FAdd, b[0], b[1]);
                self.binary(BinaryOp::FSub, sum, half)
            }
            CombineFn::Interpolate => {
                let remaining = self.one_minus(b[2]);
                self.products(b[0], b[2], b[1], remaining)
            }
            CombineFn::Subtract => self.binary(BinaryOp::FSub, b[0], b[1]),
            // Not valid for alpha (the context refuses them).
            CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => b[0],
        };
        let scaled = self.binary(BinaryOp::FMul, value, scale_alpha);
        [color[0], color[1], color[2], self.clamp01(scaled)]
    }

    /// The fog factor of `c`, clamped to [0, 1] ([`super::fog::fog_factor`]).
    fn fog_factor(&mut self, fog: FogKey, c: Reg) -> Reg {
        let end = self.uniform(FragmentUniform::FogEnd);
        let value = match fog {
            FogKey::LinearDegenerate => self.binary(BinaryOp::FSub, c, end),
            FogKey::Linear => {
                let start = self.uniform(FragmentUniform::FogStart);
                let distance = self.binary(BinaryOp::FSub, end, c);
                let span = self.binary(BinaryOp::FSub, end, start);
                self.binary(BinaryOp::FDiv, distance, span)
            }
            FogKey::Exp => {
                let density = self.uniform(FragmentUniform::FogDensity);
                let negated = self.unary(UnaryOp::FNeg, density);
                let x = self.binary(BinaryOp::FMul, negated, c);
                self.unary(UnaryOp::Exp, x)
            }
            FogKey::Exp2 => {
                let density = self.uniform(FragmentUniform::FogDensity);
                let dc = self.binary(BinaryOp::FMul, density, c);
                let square = self.binary(BinaryOp::FMul, dc, dc);
                let x = self.unary(UnaryOp::FNeg, square);
                self.unary(UnaryOp::Exp, x)
            }
        };
        self.clamp01(value)
    }
}

/// `f` for channels 0, 1 and 2.
fn per_channel(g: &mut Gen, f: &dyn Fn(&mut Gen, usize) -> Reg) -> [Reg; 3] {
    [f(g, 0), f(g, 1), f(g, 2)]
}

#[cfg(test)]
mod tests;
