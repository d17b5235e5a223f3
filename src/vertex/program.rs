//! The fixed-function vertex program: per-vertex lighting (GL 2.1 §2.14.1) written as a
//! shading-IR program ([`crate::shader::ir`]) from a compact key of the lighting state, as
//! Mesa builds one in `ffvertex_prog.c`, so that fixed-function and GLSL vertex processing
//! run on one executor. (Transform, texture-coordinate generation, the fog coordinate and
//! the point size join it as the vertex path moves onto programs.)
//!
//! The program does the arithmetic of [`super::lighting::Lighting::shade`], which follows
//! llvmpipe's run of Mesa's program: the same IEEE operations on the same operands in the
//! same order (DP3 summed from the last component, multiply-adds not fused, `1/√x` as a
//! square root and a division), with the IR's `Exp2` and `Log2` being llvmpipe's
//! approximations ([`crate::shader::math::exp2`]), so the same bits; the tests run both on
//! random states and vertices.
//!
//! What varies without changing the program's shape is a uniform ([`LightingUniform`]):
//! light positions, half vectors, spot and attenuation constants, the normal matrix, and
//! the scene colours and light products that Mesa computes on the CPU. The key
//! ([`LightingKey`]) holds the shape: per enabled light whether it is local, a spotlight,
//! attenuated; the light model; the normal scaling; colour-material tracking (whose faces
//! compute their scene colour and light products per vertex from the vertex colour); and
//! whether each face's shininess is zero (the specular factor is then 1, and no half
//! vector is needed).
//!
//! - Inputs: the eye-space position (x, y, z), the object-space normal, and with colour
//!   material the vertex colour (RGBA).
//! - Outputs: the front primary and secondary colours (RGBA each), and with two-sided
//!   lighting the back ones.

use super::lighting::{Lighting, NormalScaling};
use crate::gl::enums::{GL_AMBIENT, GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_EMISSION, GL_SPECULAR};
use crate::shader::ir::{BinaryOp, Const, Inst, Program, Reg, Stage, Stmt, Type, UnaryOp};
use std::collections::HashMap;

/// The shape of one enabled light.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LightKey {
    pub local: bool,
    pub spot: bool,
    pub attenuated: bool,
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
                .map(|l| LightKey { local: l.local, spot: l.spot.is_some(), attenuated: l.attenuation.is_some() })
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

/// Which input word of the program: eye position, normal, vertex colour components.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightingInput {
    Eye(u8),
    Normal(u8),
    Color(u8),
}

/// Which state value a uniform word holds (`light` counts enabled lights in order, `face`
/// is 0 front and 1 back, `kind` 0 ambient, 1 diffuse, 2 specular, 3 emission).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightingUniform {
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
}

/// A generated lighting program and what its input and uniform slots hold.
#[derive(Clone, Debug)]
pub struct LightingProgram {
    pub program: Program,
    pub inputs: Vec<LightingInput>,
    pub uniforms: Vec<LightingUniform>,
}

impl LightingProgram {
    /// The program of `key`.
    pub fn generate(key: &LightingKey) -> LightingProgram {
        let mut g = Gen::new();
        let eye: [Reg; 3] = std::array::from_fn(|k| g.input(LightingInput::Eye(k as u8)));
        let normal: [Reg; 3] = std::array::from_fn(|k| g.input(LightingInput::Normal(k as u8)));
        let n = g.eye_normal(key, normal);
        let needs_half = key.needs_half();
        let faces: Vec<Face> = (0..key.sides()).map(|f| g.face(key, f)).collect();
        let eye_dir = (key.local_viewer && needs_half).then(|| g.normalize(eye));
        let zero = g.constant(0.0);
        let mut primary: Vec<[Reg; 3]> = faces.iter().map(|f| [f.scene[0], f.scene[1], f.scene[2]]).collect();
        let mut secondary = vec![[zero; 3]; key.sides()];
        for (index, light) in key.lights.iter().enumerate() {
            let l = index as u8;
            let position: [Reg; 3] =
                std::array::from_fn(|k| g.uniform(LightingUniform::Position { light: l, k: k as u8 }));
            let (vp, local) = if light.local {
                let d: [Reg; 3] = std::array::from_fn(|k| g.binary(BinaryOp::FSub, position[k], eye[k]));
                let d2 = g.dot3(d, d);
                let root = g.unary(UnaryOp::Sqrt, d2);
                let inv = g.unary(UnaryOp::Rcp, root);
                (d.map(|x| g.binary(BinaryOp::FMul, x, inv)), Some((inv, d2)))
            } else {
                (position, None)
            };
            let spot = light.spot.then(|| {
                let direction =
                    std::array::from_fn(|k| g.uniform(LightingUniform::SpotDirection { light: l, k: k as u8 }));
                let away = vp.map(|x| g.unary(UnaryOp::FNeg, x));
                let cos = g.dot3(away, direction);
                let cutoff = g.uniform(LightingUniform::SpotCutoff { light: l });
                let exponent = g.uniform(LightingUniform::SpotExponent { light: l });
                let inside = g.binary(BinaryOp::FLt, cutoff, cos);
                let power = g.pow(cos, exponent);
                g.select(inside, power, zero)
            });
            let distance = match (light.attenuated, local) {
                (true, Some((inv, d2))) => {
                    // (1/d · d, d, d²) with d = √x: the terms NIR leaves of Mesa's program.
                    let d = g.unary(UnaryOp::Sqrt, d2);
                    let first = g.binary(BinaryOp::FMul, inv, d);
                    let k = std::array::from_fn(|k| g.uniform(LightingUniform::Attenuation { light: l, k: k as u8 }));
                    let sum = g.dot3(k, [first, d, d2]);
                    Some(g.unary(UnaryOp::Rcp, sum))
                }
                _ => None,
            };
            let attenuation = match (distance, spot) {
                (Some(d), Some(s)) => Some(g.binary(BinaryOp::FMul, d, s)),
                (d, s) => d.or(s),
            };
            let half = if !needs_half {
                None
            } else if let Some(e) = eye_dir {
                let toward: [Reg; 3] = std::array::from_fn(|k| g.binary(BinaryOp::FSub, vp[k], e[k]));
                Some(g.normalize(toward))
            } else if !light.local {
                Some(std::array::from_fn(|k| g.uniform(LightingUniform::Half { light: l, k: k as u8 })))
            } else {
                let one = g.constant(1.0);
                let z = g.binary(BinaryOp::FAdd, vp[2], one);
                Some(g.normalize([vp[0], vp[1], z]))
            };
            let n_dot_l = g.dot3(n, vp);
            let n_dot_h = half.map(|h| g.dot3(n, h));
            for (f, face) in faces.iter().enumerate() {
                let signed = |g: &mut Gen, x: Reg| {
                    if f == 0 {
                        x
                    } else {
                        let minus_one = g.constant(-1.0);
                        g.binary(BinaryOp::FMul, minus_one, x)
                    }
                };
                let ndl = signed(&mut g, n_dot_l);
                let mut diffuse = g.positive_part(ndl);
                let lit = g.binary(BinaryOp::FLt, zero, ndl);
                let mut specular = if key.shininess_zero[f] {
                    let one = g.constant(1.0);
                    g.select(lit, one, zero)
                } else {
                    let ndh = n_dot_h.expect("a non-zero shininess needs the half vector");
                    let ndh = signed(&mut g, ndh);
                    let base = g.positive_part(ndh);
                    let shininess = g.uniform(LightingUniform::Shininess { face: f as u8 });
                    let power = g.pow(base, shininess);
                    g.select(lit, power, zero)
                };
                let [ambient, diffuse_product, specular_product] = face.products[index];
                let mut color = primary[f];
                if let Some(a) = attenuation {
                    diffuse = g.binary(BinaryOp::FMul, diffuse, a);
                    specular = g.binary(BinaryOp::FMul, specular, a);
                    color = std::array::from_fn(|k| g.mad(a, ambient[k], color[k]));
                } else {
                    color = std::array::from_fn(|k| g.binary(BinaryOp::FAdd, ambient[k], color[k]));
                }
                color = std::array::from_fn(|k| g.mad(diffuse, diffuse_product[k], color[k]));
                if key.separate_specular {
                    secondary[f] = std::array::from_fn(|k| g.mad(specular, specular_product[k], secondary[f][k]));
                } else {
                    color = std::array::from_fn(|k| g.mad(specular, specular_product[k], color[k]));
                }
                primary[f] = color;
            }
        }
        let one = g.constant(1.0);
        for (f, face) in faces.iter().enumerate() {
            let [r, gr, b] = primary[f];
            let [sr, sg, sb] = secondary[f];
            for src in [r, gr, b, face.scene[3], sr, sg, sb, one] {
                let slot = g.program.output(Type::F32);
                g.emit(Inst::Output { slot, src });
            }
        }
        let Gen { mut program, body, inputs, uniforms, .. } = g;
        program.body = body;
        LightingProgram { program, inputs, uniforms }
    }

    /// The uniform words of `lighting` (whose key generated this program).
    pub fn uniform_values(&self, lighting: &Lighting) -> Vec<u32> {
        let m = &lighting.inverse_modelview;
        self.uniforms
            .iter()
            .map(|u| {
                let light = |l: u8| &lighting.lights[l as usize];
                let value = match *u {
                    LightingUniform::NormalMatrix(index) => m[4 * (index as usize / 3) + index as usize % 3],
                    LightingUniform::RescaleFactor => match lighting.normals {
                        NormalScaling::Rescale(s) => s,
                        _ => 1.0,
                    },
                    LightingUniform::Position { light: l, k } => light(l).position[k as usize],
                    LightingUniform::Half { light: l, k } => light(l).half[k as usize],
                    LightingUniform::SpotDirection { light: l, k } => {
                        light(l).spot.map_or(0.0, |s| s.direction[k as usize])
                    }
                    LightingUniform::SpotCutoff { light: l } => light(l).spot.map_or(0.0, |s| s.cos_cutoff),
                    LightingUniform::SpotExponent { light: l } => light(l).spot.map_or(0.0, |s| s.exponent),
                    LightingUniform::Attenuation { light: l, k } => light(l).attenuation.map_or(0.0, |a| a[k as usize]),
                    LightingUniform::LightColor { light: l, kind, k } => light(l).colors[kind as usize][k as usize],
                    LightingUniform::ModelAmbient(k) => lighting.model_ambient[k as usize],
                    LightingUniform::Material { face, kind, k } => {
                        let material = &lighting.materials[face as usize];
                        [material.ambient, material.diffuse, material.specular, material.emission][kind as usize]
                            [k as usize]
                    }
                    LightingUniform::Scene { face, k } => lighting.faces[face as usize].scene[k as usize],
                    LightingUniform::Product { face, light, kind, k } => {
                        lighting.faces[face as usize].products[light as usize][kind as usize][k as usize]
                    }
                    LightingUniform::Shininess { face } => lighting.faces[face as usize].shininess.clamp(-128.0, 128.0),
                };
                value.to_bits()
            })
            .collect()
    }
}

/// One face's scene colour and, per light, its ambient, diffuse and specular products:
/// uniforms, or computed from the vertex colour when the face tracks it.
struct Face {
    scene: [Reg; 4],
    products: Vec<[[Reg; 3]; 3]>,
}

/// The program being written, with its inputs, uniforms and constants each read once.
struct Gen {
    program: Program,
    body: Vec<Stmt>,
    inputs: Vec<LightingInput>,
    uniforms: Vec<LightingUniform>,
    input_regs: HashMap<LightingInput, Reg>,
    uniform_regs: HashMap<LightingUniform, Reg>,
    constants: HashMap<u32, Reg>,
}

impl Gen {
    fn new() -> Gen {
        Gen {
            program: Program::new(Stage::Vertex),
            body: Vec::new(),
            inputs: Vec::new(),
            uniforms: Vec::new(),
            input_regs: HashMap::new(),
            uniform_regs: HashMap::new(),
            constants: HashMap::new(),
        }
    }

    fn emit(&mut self, inst: Inst) {
        self.body.push(Stmt::Inst(inst));
    }

    fn input(&mut self, source: LightingInput) -> Reg {
        if let Some(&r) = self.input_regs.get(&source) {
            return r;
        }
        let slot = self.program.input(Type::F32);
        self.inputs.push(source);
        let dst = self.program.register(Type::F32);
        self.emit(Inst::Input { dst, slot });
        self.input_regs.insert(source, dst);
        dst
    }

    fn uniform(&mut self, value: LightingUniform) -> Reg {
        if let Some(&r) = self.uniform_regs.get(&value) {
            return r;
        }
        let slot = self.program.uniform(Type::F32);
        self.uniforms.push(value);
        let dst = self.program.register(Type::F32);
        self.emit(Inst::Uniform { dst, slot });
        self.uniform_regs.insert(value, dst);
        dst
    }

    fn constant(&mut self, value: f32) -> Reg {
        if let Some(&r) = self.constants.get(&value.to_bits()) {
            return r;
        }
        let dst = self.program.register(Type::F32);
        self.emit(Inst::Const { dst, value: Const::F32(value) });
        self.constants.insert(value.to_bits(), dst);
        dst
    }

    fn binary(&mut self, op: BinaryOp, a: Reg, b: Reg) -> Reg {
        let ty = if matches!(op, BinaryOp::FLt | BinaryOp::FLe | BinaryOp::FEq | BinaryOp::FNe) {
            Type::Bool
        } else {
            Type::F32
        };
        let dst = self.program.register(ty);
        self.emit(Inst::Binary { op, dst, a, b });
        dst
    }

    fn unary(&mut self, op: UnaryOp, a: Reg) -> Reg {
        let dst = self.program.register(Type::F32);
        self.emit(Inst::Unary { op, dst, a });
        dst
    }

    fn select(&mut self, cond: Reg, a: Reg, b: Reg) -> Reg {
        let dst = self.program.register(Type::F32);
        self.emit(Inst::Select { dst, cond, a, b });
        dst
    }

    /// `a·b + c`, two roundings.
    fn mad(&mut self, a: Reg, b: Reg, c: Reg) -> Reg {
        let dst = self.program.register(Type::F32);
        self.emit(Inst::Mad { dst, a, b, c });
        dst
    }

    /// The program's DP3 as llvmpipe runs it: (z·z' + y·y') + x·x'.
    fn dot3(&mut self, a: [Reg; 3], b: [Reg; 3]) -> Reg {
        let dst = self.program.register(Type::F32);
        self.emit(Inst::Dot { dst, n: 3, a: [a[2], a[1], a[0], a[0]], b: [b[2], b[1], b[0], b[0]] });
        dst
    }

    /// v · (1/√(v·v)).
    fn normalize(&mut self, v: [Reg; 3]) -> [Reg; 3] {
        let length2 = self.dot3(v, v);
        let length = self.unary(UnaryOp::Sqrt, length2);
        let inverse = self.unary(UnaryOp::Rcp, length);
        v.map(|x| self.binary(BinaryOp::FMul, x, inverse))
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

    /// The eye-space normal: the transpose of the inverse modelview times the normal, then
    /// normalized or rescaled.
    fn eye_normal(&mut self, key: &LightingKey, normal: [Reg; 3]) -> [Reg; 3] {
        let n = [0u8, 1, 2].map(|j| {
            let column = [0u8, 1, 2].map(|i| self.uniform(LightingUniform::NormalMatrix(3 * j + i)));
            self.dot3(column, normal)
        });
        match key.normals {
            NormalsKey::None => n,
            NormalsKey::Normalize => self.normalize(n),
            NormalsKey::Rescale => {
                let s = self.uniform(LightingUniform::RescaleFactor);
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
                scene: std::array::from_fn(|k| self.uniform(LightingUniform::Scene { face, k: k as u8 })),
                products: (0..key.lights.len() as u8)
                    .map(|light| {
                        std::array::from_fn(|kind| {
                            std::array::from_fn(|k| {
                                self.uniform(LightingUniform::Product { face, light, kind: kind as u8, k: k as u8 })
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
        let color: [Reg; 4] = std::array::from_fn(|k| self.input(LightingInput::Color(k as u8)));
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
                std::array::from_fn(|k| self.uniform(LightingUniform::Material { face, kind, k: k as u8 }))
            }
        });
        let [ambient, diffuse, specular, emission] = material;
        let scene = std::array::from_fn(|k| {
            if k == 3 {
                diffuse[3]
            } else {
                let model = self.uniform(LightingUniform::ModelAmbient(k as u8));
                self.mad(model, ambient[k], emission[k])
            }
        });
        let products = (0..key.lights.len() as u8)
            .map(|light| {
                std::array::from_fn(|kind| {
                    let m = [ambient, diffuse, specular][kind];
                    std::array::from_fn(|k| {
                        let c = self.uniform(LightingUniform::LightColor { light, kind: kind as u8, k: k as u8 });
                        self.binary(BinaryOp::FMul, c, m[k])
                    })
                })
            })
            .collect();
        Face { scene, products }
    }
}

#[cfg(test)]
mod tests;
