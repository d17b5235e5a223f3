//! The fixed-function vertex program: what a draw does to a vertex (clip and eye
//! coordinates, colours clamped or lit, texture-coordinate generation and the texture
//! matrices, the fog coordinate), written as a shading-IR program ([`crate::shader::ir`])
//! from a compact key of the state ([`VertexKey`]), as Mesa builds one in `ffvertex_prog.c`,
//! so that fixed-function and GLSL vertex processing run on one executor. The draws run it
//! through [`super::transform::VertexStage`]. (Point size attenuation stays with points
//! until the point path moves onto programs.)
//!
//! The arithmetic is that of Mesa's fixed-function vertex program as llvmpipe runs it, in
//! single precision, because llvmpipe's pictures are the reference: glam's matrix·vector
//! products and dot products for the transform and texgen; for lighting, the program's
//! order with NIR's lowering (DP3 summed from the last component, multiply-adds not fused,
//! `1/√x` as a square root and a division, the attenuation's 1/(1/√x) simplified to √x),
//! and POW as llvmpipe's own exp2/log2 polynomials (the IR's `Exp2` and `Log2`,
//! [`crate::shader::math::exp2`]). The capi test lighting_float compares the results bit for
//! bit as floats; the tests run the programs against the hand-written per-vertex code they
//! replaced ([`reference`], test builds only) on random states and vertices.
//!
//! One deliberate difference: Mesa's program, for a material shininess of zero and a light
//! that is attenuated (local with attenuation, or a spotlight), raises N·H to the power N·L
//! instead of 0 (its dot product fills the exponent's slot); here the specular factor is
//! then 1, as the specification's 0⁰ = 1 says.
//!
//! What varies without changing the program's shape is a uniform ([`VertexUniform`]): the
//! matrices, texgen planes, light positions, half vectors, spot and attenuation constants,
//! and the scene colours and light products that Mesa computes on the CPU
//! ([`super::lighting::Lighting`]). The keys hold
//! the shape: for lighting ([`LightingKey`]) per enabled light whether it is local, a
//! spotlight, attenuated; the light model; the normal scaling; colour-material tracking
//! (whose faces compute their scene colour and light products per vertex from the vertex
//! colour); and whether each face's shininess is zero (the specular factor is then 1, and
//! no half vector is needed).
//!
//! [`LightingProgram`] is lighting alone (inputs: the eye position, the normal, the colour),
//! whose unclamped colours the tests compare more finely than the clamped ones.

use super::lighting::{Lighting, NormalScaling};
use super::texgen::Gen as Generation;
use super::transform::{Binding, FogSource, Transform};
use crate::gl::enums::{GL_AMBIENT, GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_EMISSION, GL_SPECULAR};
use crate::shader::build::Builder;
use crate::shader::fast::Compiled;
use crate::shader::ir::{BinaryOp, Inst, Program, Reg, Stage, Type, UnaryOp};

/// The shape of one enabled light.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LightKey {
    pub local: bool,
    pub spot: bool,
    pub attenuated: bool,
    /// Per face: the light's specular term is zero times a power whose value does not
    /// matter, only whether it is infinite ([`power_unneeded`]): the program raises no power.
    pub no_power: [bool; 2],
}

/// Whether face `f`'s specular term of enabled light `i` can do without its power: the
/// term is `(s·a)·p` with the specular product `p` zero (an untracked face's uniform), so
/// only whether `s·a` is finite counts (∞·0 and NaN·0 are NaN). The base `b` of the power
/// `s = b^shininess` then stands for it (the same selection by N·L): both are +∞ together
/// (a normal whose normalization overflowed), and both are finite otherwise, for the
/// normal (GL_NORMALIZE) and the half vector are unit vectors, up to the rounding of a
/// subnormal squared length (a factor below 1.23 each), so `b ≤ 1.5` and `s ≤ 2^75` with a
/// shininess in (0, 128]; the attenuation `a` (≥ 0, +∞ or NaN) is then at most about
/// 1/k₀ ≤ 2^20 when finite, without a spotlight (whose own power is bounded only as
/// loosely) and with a constant attenuation k₀ ≥ 10⁻⁶ or none, so that `s·a` stays finite.
fn power_unneeded(lighting: &Lighting, i: usize, f: usize) -> bool {
    let (light, face) = (&lighting.lights[i], &lighting.faces[f]);
    let tracked = lighting.tracking.is_some_and(|t| t.face[f]);
    let bounded_attenuation = light.spot.is_none() && light.attenuation.is_none_or(|[k0, _, _]| k0 >= 1e-6);
    matches!(lighting.normals, NormalScaling::Normalize)
        && !tracked
        && face.products[i][2] == [0.0; 3]
        && face.shininess > 0.0
        && face.shininess <= 128.0
        && bounded_attenuation
}

/// How normals are scaled after the normal matrix.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NormalsKey {
    None,
    Normalize,
    Rescale,
}

/// Everything that decides the shape of a lighting program.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct LightingKey {
    pub lights: Vec<LightKey>,
    pub local_viewer: bool,
    pub two_side: bool,
    pub separate_specular: bool,
    pub normals: NormalsKey,
    /// GL_COLOR_MATERIAL: which faces track the vertex colour, and the parameter.
    pub tracking: Option<([bool; 2], u32)>,
    /// Per face: a shininess of zero.
    pub shininess_zero: [bool; 2],
}

impl LightingKey {
    /// The key of a draw's compiled lighting.
    pub fn of(lighting: &Lighting) -> LightingKey {
        LightingKey {
            lights: lighting
                .lights
                .iter()
                .enumerate()
                .map(|(i, l)| LightKey {
                    local: l.local,
                    spot: l.spot.is_some(),
                    attenuated: l.attenuation.is_some(),
                    no_power: [0, 1].map(|f| (f == 0 || lighting.two_side) && power_unneeded(lighting, i, f)),
                })
                .collect(),
            local_viewer: lighting.local_viewer,
            two_side: lighting.two_side,
            separate_specular: lighting.separate_specular,
            normals: match lighting.normals {
                NormalScaling::None => NormalsKey::None,
                NormalScaling::Normalize => NormalsKey::Normalize,
                NormalScaling::Rescale(_) => NormalsKey::Rescale,
            },
            tracking: lighting.tracking.map(|t| (t.face, t.mode)),
            shininess_zero: lighting.faces.map(|f| f.shininess == 0.0),
        }
    }

    /// Whether a half vector is needed: some lit face has a non-zero shininess.
    fn needs_half(&self) -> bool {
        !self.shininess_zero[0] || (self.two_side && !self.shininess_zero[1])
    }

    fn sides(&self) -> usize {
        if self.two_side {
            2
        } else {
            1
        }
    }
}

/// Which input word of a program: a component of a vertex attribute (or, for the lighting
/// program alone, of the eye-space position).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VertexInput {
    Position(u8),
    Normal(u8),
    Color(u8),
    SecondaryColor(u8),
    TexCoord { unit: u8, k: u8 },
    FogCoord,
    Eye(u8),
}

/// Which state value a uniform word holds (`light` counts enabled lights in order, `face`
/// is 0 front and 1 back, `kind` 0 ambient, 1 diffuse, 2 specular, 3 emission).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VertexUniform {
    /// Element `m[4j + i]` of the inverse modelview for `index = 3j + i`.
    NormalMatrix(u8),
    RescaleFactor,
    /// A local light's eye position or an infinite light's normalized direction.
    Position {
        light: u8,
        k: u8,
    },
    /// An infinite light's half vector under an infinite viewer.
    Half {
        light: u8,
        k: u8,
    },
    SpotDirection {
        light: u8,
        k: u8,
    },
    SpotCutoff {
        light: u8,
    },
    SpotExponent {
        light: u8,
    },
    Attenuation {
        light: u8,
        k: u8,
    },
    LightColor {
        light: u8,
        kind: u8,
        k: u8,
    },
    ModelAmbient(u8),
    Material {
        face: u8,
        kind: u8,
        k: u8,
    },
    /// An untracked face's scene colour and light products (computed on the CPU).
    Scene {
        face: u8,
        k: u8,
    },
    Product {
        face: u8,
        light: u8,
        kind: u8,
        k: u8,
    },
    /// The face's shininess clamped to [−128, 128] (LIT's clamp).
    Shininess {
        face: u8,
    },
    /// Element `4c + r` (column c, row r) of the modelview, of projection × modelview.
    ModelView(u8),
    ModelProject(u8),
    /// Texture-coordinate generation of the key's unit `unit`: component `k` of the object
    /// or eye plane of coordinate `coord`; element `4c + r` of its texture matrix.
    TexGenPlane {
        unit: u8,
        coord: u8,
        k: u8,
    },
    TextureMatrix {
        unit: u8,
        index: u8,
    },
    /// Texgen's normal matrix (the inverse modelview, element `4c + r`) and, for
    /// GL_RESCALE_NORMAL, the length of its third row.
    TexGenInverse(u8),
    TexGenRowLength,
}

/// A generated lighting program and what its input and uniform slots hold.
#[derive(Clone, Debug)]
pub struct LightingProgram {
    pub program: Program,
    pub inputs: Vec<VertexInput>,
    pub uniforms: Vec<VertexUniform>,
}

impl LightingProgram {
    /// The program of `key`.
    pub fn generate(key: &LightingKey) -> LightingProgram {
        let mut g = Gen::new(Stage::Vertex);
        let eye: [Reg; 3] = std::array::from_fn(|k| g.input(VertexInput::Eye(k as u8)));
        let normal: [Reg; 3] = std::array::from_fn(|k| g.input(VertexInput::Normal(k as u8)));
        for colors in g.lighting(key, eye, normal) {
            for src in colors {
                let slot = g.program.output(Type::F32);
                g.emit(Inst::Output { slot, src });
            }
        }
        let (program, inputs, uniforms) = g.finish();
        LightingProgram { program, inputs, uniforms }
    }

    /// The uniform words of `lighting` (whose key generated this program).
    pub fn uniform_values(&self, lighting: &Lighting) -> Vec<u32> {
        self.uniforms.iter().map(|u| uniform_value(u, Some(lighting), None).to_bits()).collect()
    }
}

/// How one texture coordinate is generated (glTexGen), its plane a uniform.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum GenerationKey {
    Object,
    Eye,
    Sphere,
    Reflection,
    Normal,
}

/// The shape of one unit's texture-coordinate work: generation per coordinate, and whether
/// a texture matrix other than the identity applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TexUnitKey {
    pub unit: u8,
    pub generation: [Option<GenerationKey>; 4],
    pub needs_normal: bool,
    pub matrix: bool,
}

/// Everything that decides the shape of a fixed-function vertex program.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VertexKey {
    pub clamp_color: bool,
    /// The fog coordinate's source when GL_FOG is on.
    pub fog: Option<FogSource>,
    /// The units whose coordinates are transformed (the others pass through).
    pub texture_units: Vec<TexUnitKey>,
    /// GL_NORMALIZE and GL_RESCALE_NORMAL for texgen's normal.
    pub texgen_normals: (bool, bool),
    pub lighting: Option<LightingKey>,
}

impl VertexKey {
    /// The key of a draw's transform state, lit by `lighting` when lighting is on.
    pub fn of(t: &Transform, lighting: Option<&Lighting>) -> VertexKey {
        VertexKey {
            clamp_color: t.clamp_color,
            fog: t.fog,
            texture_units: t
                .texgen
                .units
                .iter()
                .map(|u| TexUnitKey {
                    unit: u.unit as u8,
                    generation: u.gen.map(|g| {
                        g.map(|g| match g {
                            Generation::Object(_) => GenerationKey::Object,
                            Generation::Eye(_) => GenerationKey::Eye,
                            Generation::Sphere => GenerationKey::Sphere,
                            Generation::Reflection => GenerationKey::Reflection,
                            Generation::Normal => GenerationKey::Normal,
                        })
                    }),
                    needs_normal: u.needs_normal,
                    matrix: u.matrix.is_some(),
                })
                .collect(),
            texgen_normals: (t.texgen.normalize, t.texgen.rescale_normal),
            lighting: lighting.map(LightingKey::of),
        }
    }
}

/// Where a vertex program's outputs go: the clip vertex's fields.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VertexOutput {
    Clip(u8),
    Eye(u8),
    Color(u8),
    SecondaryColor(u8),
    /// The back primary (0) and secondary (1) colours of two-sided lighting.
    BackColor {
        which: u8,
        k: u8,
    },
    TexCoord {
        unit: u8,
        k: u8,
    },
    FogCoord,
}

/// A vertex program ready to run: what the generator made of a key, and its compiled form
/// (the form the pipeline runs; the generated program stays for `TESSERA_DEBUG=programs`
/// and the slot tables).
#[derive(Clone, Debug)]
pub struct CompiledVertex {
    pub generated: VertexProgram,
    pub compiled: Compiled,
    /// Its inputs and outputs in registers, when the compiled form allows it (every
    /// generated program so far: straight-line code).
    pub binding: Option<Binding>,
}

impl CompiledVertex {
    /// Generates and compiles the program of `key`.
    pub fn generate(key: &VertexKey) -> CompiledVertex {
        let generated = VertexProgram::generate(key);
        let compiled = Compiled::new(&generated.program);
        let binding = Binding::of(&generated, &compiled);
        CompiledVertex { generated, compiled, binding }
    }
}

/// A generated vertex program and what its slots hold.
#[derive(Clone, Debug)]
pub struct VertexProgram {
    pub program: Program,
    pub inputs: Vec<VertexInput>,
    pub uniforms: Vec<VertexUniform>,
    pub outputs: Vec<VertexOutput>,
}

impl VertexProgram {
    /// The program of `key`.
    pub fn generate(key: &VertexKey) -> VertexProgram {
        let mut g = Gen::new(Stage::Vertex);
        let mut outputs = Vec::new();
        let mut out = |g: &mut Gen, what: VertexOutput, src: Reg| {
            let slot = g.program.output(Type::F32);
            g.emit(Inst::Output { slot, src });
            outputs.push(what);
        };
        let position: [Reg; 4] = std::array::from_fn(|k| g.input(VertexInput::Position(k as u8)));
        let clip = g.matrix_times(VertexUniform::ModelProject, position);
        let eye = g.matrix_times(VertexUniform::ModelView, position);
        for k in 0..4u8 {
            out(&mut g, VertexOutput::Clip(k), clip[k as usize]);
        }
        for k in 0..4u8 {
            out(&mut g, VertexOutput::Eye(k), eye[k as usize]);
        }
        let colors: Vec<[Reg; 4]> = match &key.lighting {
            Some(lighting) => {
                let normal = std::array::from_fn(|k| g.input(VertexInput::Normal(k as u8)));
                g.lighting(lighting, [eye[0], eye[1], eye[2]], normal)
            }
            None => vec![
                std::array::from_fn(|k| g.input(VertexInput::Color(k as u8))),
                std::array::from_fn(|k| g.input(VertexInput::SecondaryColor(k as u8))),
            ],
        };
        for (index, color) in colors.iter().enumerate() {
            for (k, &c) in color.iter().enumerate() {
                let c = if key.clamp_color { g.clamp01(c) } else { c };
                let k = k as u8;
                let what = match index {
                    0 => VertexOutput::Color(k),
                    1 => VertexOutput::SecondaryColor(k),
                    which => VertexOutput::BackColor { which: which as u8 - 2, k },
                };
                out(&mut g, what, c);
            }
        }
        for (index, unit) in key.texture_units.iter().enumerate() {
            let coords = g.tex_coords(key, index as u8, unit, position, eye);
            for (k, c) in coords.into_iter().enumerate() {
                out(&mut g, VertexOutput::TexCoord { unit: unit.unit, k: k as u8 }, c);
            }
        }
        let fog = match key.fog {
            None | Some(FogSource::Attribute) => g.input(VertexInput::FogCoord),
            Some(FogSource::Radial) => {
                let length2 = g.dot3([eye[0], eye[1], eye[2]], [eye[0], eye[1], eye[2]]);
                g.unary(UnaryOp::Sqrt, length2)
            }
            Some(FogSource::Plane) => eye[2],
            Some(FogSource::PlaneAbsolute) => g.unary(UnaryOp::FAbs, eye[2]),
        };
        out(&mut g, VertexOutput::FogCoord, fog);
        let (program, inputs, uniforms) = g.finish();
        VertexProgram { program, inputs, uniforms, outputs }
    }

    /// The uniform words of a draw's transform state `t` and compiled `lighting`.
    pub fn uniform_values(&self, t: &Transform, lighting: Option<&Lighting>) -> Vec<u32> {
        self.uniforms.iter().map(|u| uniform_value(u, lighting, Some(t)).to_bits()).collect()
    }
}

/// The value of uniform `u` from a draw's compiled lighting and its transform state.
fn uniform_value(u: &VertexUniform, lighting: Option<&Lighting>, transform: Option<&Transform>) -> f32 {
    if let Some(value) = lighting.and_then(|l| lighting_value(u, l)) {
        return value;
    }
    let Some(t) = transform else { return 0.0 };
    let column_major = |m: &glam::Mat4, index: u8| m.col(index as usize / 4)[index as usize % 4];
    let unit = |unit: u8| &t.texgen.units[unit as usize];
    match *u {
        VertexUniform::ModelView(index) => column_major(&t.modelview, index),
        VertexUniform::ModelProject(index) => column_major(&t.model_project, index),
        VertexUniform::TexGenPlane { unit: n, coord, k } => match unit(n).gen[coord as usize] {
            Some(Generation::Object(p) | Generation::Eye(p)) => p[k as usize],
            _ => 0.0,
        },
        VertexUniform::TextureMatrix { unit: n, index } => unit(n).matrix.map_or(0.0, |m| column_major(&m, index)),
        VertexUniform::TexGenInverse(index) => column_major(&t.texgen.modelview_inverse, index),
        VertexUniform::TexGenRowLength => {
            let inv = &t.texgen.modelview_inverse;
            glam::Vec3::new(inv.col(0).z, inv.col(1).z, inv.col(2).z).length()
        }
        _ => 0.0,
    }
}

/// The value of a lighting uniform (`None` for the others).
fn lighting_value(u: &VertexUniform, lighting: &Lighting) -> Option<f32> {
    let m = &lighting.inverse_modelview;
    let light = |l: u8| &lighting.lights[l as usize];
    Some(match *u {
        VertexUniform::NormalMatrix(index) => m[4 * (index as usize / 3) + index as usize % 3],
        VertexUniform::RescaleFactor => match lighting.normals {
            NormalScaling::Rescale(s) => s,
            _ => 1.0,
        },
        VertexUniform::Position { light: l, k } => light(l).position[k as usize],
        VertexUniform::Half { light: l, k } => light(l).half[k as usize],
        VertexUniform::SpotDirection { light: l, k } => light(l).spot.map_or(0.0, |s| s.direction[k as usize]),
        VertexUniform::SpotCutoff { light: l } => light(l).spot.map_or(0.0, |s| s.cos_cutoff),
        VertexUniform::SpotExponent { light: l } => light(l).spot.map_or(0.0, |s| s.exponent),
        VertexUniform::Attenuation { light: l, k } => light(l).attenuation.map_or(0.0, |a| a[k as usize]),
        VertexUniform::LightColor { light: l, kind, k } => light(l).colors[kind as usize][k as usize],
        VertexUniform::ModelAmbient(k) => lighting.model_ambient[k as usize],
        VertexUniform::Material { face, kind, k } => {
            let material = &lighting.materials[face as usize];
            [material.ambient, material.diffuse, material.specular, material.emission][kind as usize][k as usize]
        }
        VertexUniform::Scene { face, k } => lighting.faces[face as usize].scene[k as usize],
        VertexUniform::Product { face, light, kind, k } => {
            lighting.faces[face as usize].products[light as usize][kind as usize][k as usize]
        }
        VertexUniform::Shininess { face } => lighting.faces[face as usize].shininess.clamp(-128.0, 128.0),
        _ => return None,
    })
}

/// One face's scene colour and, per light, its ambient, diffuse and specular products:
/// uniforms, or computed from the vertex colour when the face tracks it.
struct Face {
    scene: [Reg; 4],
    products: Vec<[[Reg; 3]; 3]>,
}

/// The program being written (the generator's own operations are below).
type Gen = Builder<VertexInput, VertexUniform>;

impl Gen {
    /// The program's DP3 as llvmpipe runs it: (z·z' + y·y') + x·x'.
    fn dp3(&mut self, a: [Reg; 3], b: [Reg; 3]) -> Reg {
        let dst = self.program.register(Type::F32);
        self.emit(Inst::Dot { dst, n: 3, a: [a[2], a[1], a[0], a[0]], b: [b[2], b[1], b[0], b[0]] });
        dst
    }

    /// v · (1/√(v·v)).
    fn normalize(&mut self, v: [Reg; 3]) -> [Reg; 3] {
        let length2 = self.dp3(v, v);
        let inverse = self.unary(UnaryOp::Rsq, length2);
        self.scaled(v, inverse)
    }

    /// `v · s`, the components multiplied in the order of [`Gen::dp3`]'s operands (z, y,
    /// x): after `dp3(v, v)` and its `Rsq`, the executor's one normalize operation
    /// ([`crate::shader::lower::Op::Normalize3`]; `Rsq` is the square root and the division
    /// of NIR's lowering, the same two roundings as `Sqrt` then `Rcp`).
    fn scaled(&mut self, v: [Reg; 3], s: Reg) -> [Reg; 3] {
        let z = self.binary(BinaryOp::FMul, v[2], s);
        let y = self.binary(BinaryOp::FMul, v[1], s);
        let x = self.binary(BinaryOp::FMul, v[0], s);
        [x, y, z]
    }

    /// x when x > 0, else +0 (LIT's max(x, 0), NaN giving 0).
    fn positive_part(&mut self, x: Reg) -> Reg {
        let zero = self.constant(0.0);
        let positive = self.binary(BinaryOp::FLt, zero, x);
        self.select(positive, x, zero)
    }

    /// POW as llvmpipe evaluates it: 2^(log₂ x · y), and 0 for x = 0.
    fn pow(&mut self, x: Reg, y: Reg) -> Reg {
        let zero = self.constant(0.0);
        let log = self.unary(UnaryOp::Log2, x);
        let product = self.binary(BinaryOp::FMul, log, y);
        let power = self.unary(UnaryOp::Exp2, product);
        let is_zero = self.binary(BinaryOp::FEq, x, zero);
        self.select(is_zero, zero, power)
    }

    /// Lighting (see the module): the front primary and secondary colours, and the back
    /// ones with two-sided lighting, from the eye-space position `eye` and the object-space
    /// `normal` (the vertex colour is read as an input when a face tracks it).
    fn lighting(&mut self, key: &LightingKey, eye: [Reg; 3], normal: [Reg; 3]) -> Vec<[Reg; 4]> {
        let n = self.eye_normal(key, normal);
        let needs_half = key.needs_half();
        let faces: Vec<Face> = (0..key.sides()).map(|f| self.face(key, f)).collect();
        let eye_dir = (key.local_viewer && needs_half).then(|| self.normalize(eye));
        let zero = self.constant(0.0);
        let mut primary: Vec<[Reg; 3]> = faces.iter().map(|f| [f.scene[0], f.scene[1], f.scene[2]]).collect();
        let mut secondary = vec![[zero; 3]; key.sides()];
        for (index, light) in key.lights.iter().enumerate() {
            let l = index as u8;
            let position: [Reg; 3] =
                std::array::from_fn(|k| self.uniform(VertexUniform::Position { light: l, k: k as u8 }));
            let (vp, local) = if light.local {
                let d: [Reg; 3] = std::array::from_fn(|k| self.binary(BinaryOp::FSub, position[k], eye[k]));
                let d2 = self.dp3(d, d);
                let inv = self.unary(UnaryOp::Rsq, d2);
                (self.scaled(d, inv), Some((inv, d2)))
            } else {
                (position, None)
            };
            let spot = light.spot.then(|| {
                let direction =
                    std::array::from_fn(|k| self.uniform(VertexUniform::SpotDirection { light: l, k: k as u8 }));
                let away = vp.map(|x| self.unary(UnaryOp::FNeg, x));
                let cos = self.dp3(away, direction);
                let cutoff = self.uniform(VertexUniform::SpotCutoff { light: l });
                let exponent = self.uniform(VertexUniform::SpotExponent { light: l });
                let inside = self.binary(BinaryOp::FLt, cutoff, cos);
                let power = self.pow(cos, exponent);
                self.select(inside, power, zero)
            });
            let distance = match (light.attenuated, local) {
                (true, Some((inv, d2))) => {
                    // (1/d · d, d, d²) with d = √x: the terms NIR leaves of Mesa's program.
                    let d = self.unary(UnaryOp::Sqrt, d2);
                    let first = self.binary(BinaryOp::FMul, inv, d);
                    let k = std::array::from_fn(|k| self.uniform(VertexUniform::Attenuation { light: l, k: k as u8 }));
                    let sum = self.dp3(k, [first, d, d2]);
                    Some(self.unary(UnaryOp::Rcp, sum))
                }
                _ => None,
            };
            let attenuation = match (distance, spot) {
                (Some(d), Some(s)) => Some(self.binary(BinaryOp::FMul, d, s)),
                (d, s) => d.or(s),
            };
            let half = if !needs_half {
                None
            } else if let Some(e) = eye_dir {
                let toward: [Reg; 3] = std::array::from_fn(|k| self.binary(BinaryOp::FSub, vp[k], e[k]));
                Some(self.normalize(toward))
            } else if !light.local {
                Some(std::array::from_fn(|k| self.uniform(VertexUniform::Half { light: l, k: k as u8 })))
            } else {
                let one = self.constant(1.0);
                let z = self.binary(BinaryOp::FAdd, vp[2], one);
                Some(self.normalize([vp[0], vp[1], z]))
            };
            let n_dot_l = self.dp3(n, vp);
            let n_dot_h = half.map(|h| self.dp3(n, h));
            for (f, face) in faces.iter().enumerate() {
                let signed = |g: &mut Gen, x: Reg| {
                    if f == 0 {
                        x
                    } else {
                        let minus_one = g.constant(-1.0);
                        g.binary(BinaryOp::FMul, minus_one, x)
                    }
                };
                let ndl = signed(self, n_dot_l);
                let mut diffuse = self.positive_part(ndl);
                let lit = self.binary(BinaryOp::FLt, zero, ndl);
                let mut specular = if key.shininess_zero[f] {
                    let one = self.constant(1.0);
                    self.select(lit, one, zero)
                } else {
                    let ndh = n_dot_h.expect("a non-zero shininess needs the half vector");
                    let ndh = signed(self, ndh);
                    let base = self.positive_part(ndh);
                    if light.no_power[f] {
                        self.select(lit, base, zero)
                    } else {
                        let shininess = self.uniform(VertexUniform::Shininess { face: f as u8 });
                        let power = self.pow(base, shininess);
                        self.select(lit, power, zero)
                    }
                };
                let [ambient, diffuse_product, specular_product] = face.products[index];
                let mut color = primary[f];
                if let Some(a) = attenuation {
                    diffuse = self.binary(BinaryOp::FMul, diffuse, a);
                    specular = self.binary(BinaryOp::FMul, specular, a);
                    color = std::array::from_fn(|k| self.mad(a, ambient[k], color[k]));
                } else {
                    color = std::array::from_fn(|k| self.binary(BinaryOp::FAdd, ambient[k], color[k]));
                }
                color = std::array::from_fn(|k| self.mad(diffuse, diffuse_product[k], color[k]));
                if key.separate_specular {
                    secondary[f] = std::array::from_fn(|k| self.mad(specular, specular_product[k], secondary[f][k]));
                } else {
                    color = std::array::from_fn(|k| self.mad(specular, specular_product[k], color[k]));
                }
                primary[f] = color;
            }
        }
        let one = self.constant(1.0);
        faces
            .iter()
            .enumerate()
            .flat_map(|(f, face)| {
                let ([r, g, b], [sr, sg, sb]) = (primary[f], secondary[f]);
                [[r, g, b, face.scene[3]], [sr, sg, sb, one]]
            })
            .collect()
    }

    /// A 4×4 uniform matrix (elements `which(4c + r)`) times `v`, as glam's `Mat4 * Vec4`
    /// computes it: ((c0·x + c1·y) + c2·z) + c3·w per row, every product and sum rounded.
    fn matrix_times(&mut self, which: impl Fn(u8) -> VertexUniform, v: [Reg; 4]) -> [Reg; 4] {
        std::array::from_fn(|r| {
            // The row's uniforms first, then its four operations in a row: the executor
            // fuses them into one ([`crate::shader::lower::Op::MatRow`]).
            let row: [Reg; 4] = std::array::from_fn(|c| self.uniform(which(4 * c as u8 + r as u8)));
            let mut sum = None;
            for (&m, &x) in row.iter().zip(&v) {
                sum = Some(match sum {
                    None => self.binary(BinaryOp::FMul, m, x),
                    Some(s) => self.mad(m, x, s),
                });
            }
            sum.expect("four columns")
        })
    }

    /// `v / length` where `length > 0`, else `v` unchanged.
    fn divided_if_positive(&mut self, v: [Reg; 3], length: Reg) -> [Reg; 3] {
        let zero = self.constant(0.0);
        let positive = self.binary(BinaryOp::FLt, zero, length);
        v.map(|x| {
            let q = self.binary(BinaryOp::FDiv, x, length);
            self.select(positive, q, x)
        })
    }

    /// The texture coordinates of the key's unit `index` (GL 2.1 §2.11.4):
    /// generated coordinates, then the texture matrix.
    fn tex_coords(
        &mut self,
        key: &VertexKey,
        index: u8,
        unit: &TexUnitKey,
        position: [Reg; 4],
        eye: [Reg; 4],
    ) -> [Reg; 4] {
        let mut tc: [Reg; 4] =
            std::array::from_fn(|k| self.input(VertexInput::TexCoord { unit: unit.unit, k: k as u8 }));
        if unit.generation.iter().any(Option::is_some) {
            let normal = if unit.needs_normal {
                self.texgen_normal(key)
            } else {
                let (zero, one) = (self.constant(0.0), self.constant(1.0));
                [zero, zero, one]
            };
            let needs_reflection =
                unit.generation.iter().any(|g| matches!(g, Some(GenerationKey::Sphere | GenerationKey::Reflection)));
            let reflection = needs_reflection.then(|| {
                let p = [eye[0], eye[1], eye[2]];
                let length2 = self.dot3(p, p);
                let length = self.unary(UnaryOp::Sqrt, length2);
                let unit_eye = self.divided_if_positive(p, length);
                // unit_eye − (2·normal)·(normal · unit_eye), as glam evaluates it.
                let d = self.dot3(normal, unit_eye);
                let two = self.constant(2.0);
                std::array::from_fn(|k| {
                    let twice = self.binary(BinaryOp::FMul, two, normal[k]);
                    let scaled = self.binary(BinaryOp::FMul, twice, d);
                    self.binary(BinaryOp::FSub, unit_eye[k], scaled)
                })
            });
            for (c, generation) in unit.generation.iter().enumerate() {
                let Some(generation) = generation else { continue };
                tc[c] = match generation {
                    GenerationKey::Object | GenerationKey::Eye => {
                        let source = if *generation == GenerationKey::Object { position } else { eye };
                        let plane: [Reg; 4] = std::array::from_fn(|k| {
                            self.uniform(VertexUniform::TexGenPlane { unit: index, coord: c as u8, k: k as u8 })
                        });
                        let dst = self.program.register(Type::F32);
                        self.emit(Inst::Dot { dst, n: 4, a: plane, b: source });
                        dst
                    }
                    GenerationKey::Sphere => {
                        let r: [Reg; 3] = reflection.expect("computed for sphere maps");
                        let one = self.constant(1.0);
                        let z = self.binary(BinaryOp::FAdd, r[2], one);
                        let xx = self.binary(BinaryOp::FMul, r[0], r[0]);
                        let xy = self.mad(r[1], r[1], xx);
                        let sum = self.mad(z, z, xy);
                        let root = self.unary(UnaryOp::Sqrt, sum);
                        let two = self.constant(2.0);
                        let m = self.binary(BinaryOp::FMul, two, root);
                        let component = if c == 0 { r[0] } else { r[1] };
                        let half = self.constant(0.5);
                        let q = self.binary(BinaryOp::FDiv, component, m);
                        let value = self.binary(BinaryOp::FAdd, q, half);
                        let zero = self.constant(0.0);
                        let positive = self.binary(BinaryOp::FLt, zero, m);
                        self.select(positive, value, half)
                    }
                    GenerationKey::Reflection => reflection.expect("computed for reflection maps")[c.min(2)],
                    GenerationKey::Normal => normal[c.min(2)],
                };
            }
        }
        if unit.matrix {
            tc = self.matrix_times(|i| VertexUniform::TextureMatrix { unit: index, index: i }, tc);
        }
        tc
    }

    /// Texgen's eye-space normal: the normal dotted with
    /// the inverse modelview's columns, then divided by its length (GL_NORMALIZE) or by
    /// the length of the matrix's third row (GL_RESCALE_NORMAL) when that is positive.
    fn texgen_normal(&mut self, key: &VertexKey) -> [Reg; 3] {
        let n: [Reg; 3] = std::array::from_fn(|k| self.input(VertexInput::Normal(k as u8)));
        let e = [0u8, 1, 2].map(|j| {
            let column = [0u8, 1, 2].map(|i| self.uniform(VertexUniform::TexGenInverse(4 * j + i)));
            self.dot3(n, column)
        });
        match key.texgen_normals {
            (true, _) => {
                let length2 = self.dot3(e, e);
                let length = self.unary(UnaryOp::Sqrt, length2);
                self.divided_if_positive(e, length)
            }
            (false, true) => {
                let length = self.uniform(VertexUniform::TexGenRowLength);
                self.divided_if_positive(e, length)
            }
            _ => e,
        }
    }

    /// The eye-space normal: the transpose of the inverse modelview times the normal, then
    /// normalized or rescaled.
    fn eye_normal(&mut self, key: &LightingKey, normal: [Reg; 3]) -> [Reg; 3] {
        let n = [0u8, 1, 2].map(|j| {
            let column = [0u8, 1, 2].map(|i| self.uniform(VertexUniform::NormalMatrix(3 * j + i)));
            self.dp3(column, normal)
        });
        match key.normals {
            NormalsKey::None => n,
            NormalsKey::Normalize => self.normalize(n),
            NormalsKey::Rescale => {
                let s = self.uniform(VertexUniform::RescaleFactor);
                n.map(|x| self.binary(BinaryOp::FMul, x, s))
            }
        }
    }

    /// Face `f`'s constants: uniforms, or under colour material the material with the
    /// tracked parameters replaced by the vertex colour (Mesa's `face_setup` per vertex: the
    /// scene colour `model ambient · ambient + emission` and the products `light · material`).
    fn face(&mut self, key: &LightingKey, f: usize) -> Face {
        let face = f as u8;
        let tracked = key.tracking.filter(|(faces, _)| faces[f]).map(|(_, mode)| mode);
        let Some(mode) = tracked else {
            return Face {
                scene: std::array::from_fn(|k| self.uniform(VertexUniform::Scene { face, k: k as u8 })),
                products: (0..key.lights.len() as u8)
                    .map(|light| {
                        std::array::from_fn(|kind| {
                            std::array::from_fn(|k| {
                                self.uniform(VertexUniform::Product { face, light, kind: kind as u8, k: k as u8 })
                            })
                        })
                    })
                    .collect(),
            };
        };
        let replaced = |kind: u32| match mode {
            GL_AMBIENT_AND_DIFFUSE => kind == GL_AMBIENT || kind == GL_DIFFUSE,
            m => m == kind,
        };
        let color: [Reg; 4] = std::array::from_fn(|k| self.input(VertexInput::Color(k as u8)));
        let material: [[Reg; 4]; 4] = [GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION].map(|name| {
            if replaced(name) {
                color
            } else {
                let kind = match name {
                    GL_AMBIENT => 0,
                    GL_DIFFUSE => 1,
                    GL_SPECULAR => 2,
                    _ => 3,
                };
                std::array::from_fn(|k| self.uniform(VertexUniform::Material { face, kind, k: k as u8 }))
            }
        });
        let [ambient, diffuse, specular, emission] = material;
        let scene = std::array::from_fn(|k| {
            if k == 3 {
                diffuse[3]
            } else {
                let model = self.uniform(VertexUniform::ModelAmbient(k as u8));
                self.mad(model, ambient[k], emission[k])
            }
        });
        let products = (0..key.lights.len() as u8)
            .map(|light| {
                std::array::from_fn(|kind| {
                    let m = [ambient, diffuse, specular][kind];
                    std::array::from_fn(|k| {
                        let c = self.uniform(VertexUniform::LightColor { light, kind: kind as u8, k: k as u8 });
                        self.binary(BinaryOp::FMul, c, m[k])
                    })
                })
            })
            .collect();
        Face { scene, products }
    }
}

#[cfg(test)]
pub(crate) mod reference;
#[cfg(test)]
mod tests;
