//! The values of GLSL's built-in state uniforms (GLSL 1.20 section 7.5: `gl_ModelViewMatrix`
//! and the other matrices with their inverses and transposes, `gl_NormalMatrix`,
//! `gl_DepthRange`, `gl_ClipPlane`, `gl_Point`, the materials, `gl_LightSource`, the light
//! model and light products, `gl_TextureEnvColor`, the texgen planes and `gl_Fog`) from the
//! context's current state, word by word as a lowered program names them
//! ([`crate::glsl::lower::Word`]).
//!
//! A program's words are resolved once, when it is linked or bound
//! ([`BuiltinUniform::resolve`]: the GL name parsed into what it reads), and read at each
//! draw through a [`BuiltinValues`], which computes what several words share (the analysed
//! matrices, the modelview-projection product and its inverse) once per draw on first use.
//! The draws read them through `Context::stage_uniforms` (`super::shader_objects`); the
//! tests read single words through `Context::builtin_uniform_word`.
//!
//! The values are Mesa 22's (`prog_statevars.c` and the built-in uniform table of its GLSL
//! front end), checked against llvmpipe by `capi-tests/glsl_builtin_state.c`:
//! - the matrices are the ones fixed function uses: the tops of the stacks, the inverses Mesa
//!   keeps with them (its algorithm per matrix type; a singular matrix has the identity as
//!   inverse), and for `gl_ModelViewProjectionMatrix` the same product the fixed-function
//!   vertex path uses, so that `ftransform()` agrees with it bit for bit;
//! - `gl_NormalMatrix` is the upper 3×3 of the inverse modelview, transposed;
//!   `gl_NormalScale` GL_RESCALE_NORMAL's factor (1/|third row of the inverse|, 1 for a
//!   length-preserving modelview);
//! - a light's position and spot direction are the eye-space values glLight stored; its
//!   half vector is normalize(normalize(position.xyz) + (0, 0, 1)) with w = 1 (for every
//!   light whose position was set, as Mesa computes it then; zero before), spotCosCutoff
//!   is Mesa's single-precision cosf of spotCutoff · π/180, 0 for 90 and 180;
//! - a light product is light color × material color with the material's alpha;
//!   sceneColor is emission + ambient × the light model's ambient, with the diffuse alpha;
//! - `gl_Fog.scale` is 1/(end − start) (infinite when they are equal, as on Mesa 22), the fog
//!   color clamped when fragment colors are ([`Context::fragment_clamping`]);
//! - `gl_DepthRange` is near and far as floats and far − near in single precision;
//! - texture units beyond tessera's four (`gl_TextureMatrix[7]`, `gl_EyePlaneS[5]`) read
//!   those units' initial state: the identity, the initial planes.
use super::matrix::{Matrix, StackId};
use super::Context;
use crate::gl::limits::{MAX_CLIP_PLANES, MAX_LIGHTS, MAX_TEXTURE_COORDS, MAX_TEXTURE_UNITS};
use std::cell::OnceCell;

/// Elements of the arrays GLSL sizes by gl_MaxTextureCoords (the texture matrices and the
/// texgen planes), as [`crate::glsl::builtins::Limits`] declares them.
const TEXTURE_COORD_SETS: u32 = MAX_TEXTURE_COORDS as u32;

/// Which 4×4 matrix a matrix uniform reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MatrixSource {
    ModelView,
    Projection,
    ModelViewProjection,
    /// gl_TextureMatrix[unit] (any unit below gl_MaxTextureCoords).
    Texture(u8),
}

/// Which form of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MatrixForm {
    Plain,
    Inverse,
    Transpose,
    InverseTranspose,
}

/// A member of gl_MaterialParameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MaterialMember {
    Emission,
    Ambient,
    Diffuse,
    Specular,
    Shininess,
}

/// A member of gl_LightSourceParameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightMember {
    Ambient,
    Diffuse,
    Specular,
    Position,
    HalfVector,
    SpotDirection,
    SpotExponent,
    SpotCutoff,
    SpotCosCutoff,
    ConstantAttenuation,
    LinearAttenuation,
    QuadraticAttenuation,
}

/// A member of gl_LightProducts: the ambient, diffuse or specular product.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProductMember {
    Ambient,
    Diffuse,
    Specular,
}

/// A member of gl_FogParameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FogMember {
    Color,
    Density,
    Start,
    End,
    Scale,
}

/// A member of gl_PointParameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointMember {
    Size,
    SizeMin,
    SizeMax,
    FadeThresholdSize,
    DistanceConstantAttenuation,
    DistanceLinearAttenuation,
    DistanceQuadraticAttenuation,
}

/// A member of gl_DepthRangeParameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthRangeMember {
    Near,
    Far,
    Diff,
}

/// One word of a built-in state uniform, resolved from its GL name: what to read, without
/// names. `word` is the word within the element (matrices column-major, vectors by
/// component); faces are 0 (front) and 1 (back).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BuiltinUniform {
    Matrix {
        source: MatrixSource,
        form: MatrixForm,
        word: u8,
    },
    NormalMatrix {
        word: u8,
    },
    NormalScale,
    DepthRange(DepthRangeMember),
    ClipPlane {
        plane: u8,
        word: u8,
    },
    Point(PointMember),
    Material {
        face: u8,
        member: MaterialMember,
        word: u8,
    },
    Light {
        light: u8,
        member: LightMember,
        word: u8,
    },
    LightModelAmbient {
        word: u8,
    },
    SceneColor {
        face: u8,
        word: u8,
    },
    LightProduct {
        face: u8,
        light: u8,
        member: ProductMember,
        word: u8,
    },
    TextureEnvColor {
        unit: u8,
        word: u8,
    },
    /// gl_EyePlaneS..Q (`eye`) or gl_ObjectPlaneS..Q; `coord` 0..4 is S, T, R, Q.
    TexGenPlane {
        eye: bool,
        coord: u8,
        unit: u8,
        word: u8,
    },
    Fog {
        member: FogMember,
        word: u8,
    },
}

/// A GL element name split into its variable, array index and member:
/// `gl_LightSource[2].diffuse` is (`gl_LightSource`, Some(2), Some(`diffuse`)).
fn split_name(name: &str) -> Option<(&str, Option<u32>, Option<&str>)> {
    let base_end = name.find(['[', '.']).unwrap_or(name.len());
    let (base, mut rest) = name.split_at(base_end);
    let mut index = None;
    if let Some(after) = rest.strip_prefix('[') {
        let close = after.find(']')?;
        let digits = &after[..close];
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        index = Some(digits.parse().ok()?);
        rest = &after[close + 1..];
    }
    let member = match rest {
        "" => None,
        _ => Some(rest.strip_prefix('.')?),
    };
    Some((base, index, member))
}

/// `Some(word as u8)` when `word < len`.
fn word_below(word: u32, len: u32) -> Option<u8> {
    (word < len).then_some(word as u8)
}

/// `Some(i as u8)` for an array index below `len`.
fn element_below(index: Option<u32>, len: u32) -> Option<u8> {
    index.filter(|&i| i < len).map(|i| i as u8)
}

/// A matrix variable's name without `gl_` split into its stem and form:
/// `ModelViewMatrixInverse` is (`ModelView`, Inverse); `None` for no matrix name.
fn matrix_name(base: &str) -> Option<(&str, MatrixForm)> {
    let (rest, form) = [
        ("InverseTranspose", MatrixForm::InverseTranspose),
        ("Inverse", MatrixForm::Inverse),
        ("Transpose", MatrixForm::Transpose),
    ]
    .into_iter()
    .find_map(|(suffix, form)| base.strip_suffix(suffix).map(|rest| (rest, form)))
    .unwrap_or((base, MatrixForm::Plain));
    Some((rest.strip_suffix("Matrix")?, form))
}

impl BuiltinUniform {
    /// Word `index` of the built-in uniform element `name` (`gl_ModelViewMatrix`,
    /// `gl_TextureMatrix[1]`, `gl_LightSource[0].diffuse`; as [`crate::glsl::lower::Word`]
    /// names it); `None` for a name or word that is no built-in state.
    pub fn resolve(name: &str, index: u32) -> Option<BuiltinUniform> {
        use BuiltinUniform as B;
        let (base, element, member) = split_name(name)?;
        let base = base.strip_prefix("gl_")?;
        let vec4 = || word_below(index, 4);
        let scalar = || (index == 0).then_some(0u8);
        // Plain variables and structs take no index; arrays need one.
        let no_element = || element.is_none().then_some(());
        if let Some((stem, form)) = matrix_name(base) {
            if member.is_some() {
                return None;
            }
            let source = match stem {
                "ModelView" => MatrixSource::ModelView,
                "Projection" => MatrixSource::Projection,
                "ModelViewProjection" => MatrixSource::ModelViewProjection,
                "Texture" => MatrixSource::Texture(element_below(element, TEXTURE_COORD_SETS)?),
                "Normal" if form == MatrixForm::Plain => {
                    no_element()?;
                    return Some(B::NormalMatrix { word: word_below(index, 9)? });
                }
                _ => return None,
            };
            if !matches!(source, MatrixSource::Texture(_)) {
                no_element()?;
            }
            return Some(B::Matrix { source, form, word: word_below(index, 16)? });
        }
        let face = |prefix: &str| match prefix {
            "Front" => Some(0u8),
            "Back" => Some(1u8),
            _ => None,
        };
        Some(match (base, member) {
            ("NormalScale", None) => {
                no_element()?;
                scalar()?;
                B::NormalScale
            }
            ("DepthRange", Some(m)) => {
                no_element()?;
                scalar()?;
                B::DepthRange(match m {
                    "near" => DepthRangeMember::Near,
                    "far" => DepthRangeMember::Far,
                    "diff" => DepthRangeMember::Diff,
                    _ => return None,
                })
            }
            ("ClipPlane", None) => {
                B::ClipPlane { plane: element_below(element, MAX_CLIP_PLANES as u32)?, word: vec4()? }
            }
            ("Point", Some(m)) => {
                no_element()?;
                scalar()?;
                B::Point(match m {
                    "size" => PointMember::Size,
                    "sizeMin" => PointMember::SizeMin,
                    "sizeMax" => PointMember::SizeMax,
                    "fadeThresholdSize" => PointMember::FadeThresholdSize,
                    "distanceConstantAttenuation" => PointMember::DistanceConstantAttenuation,
                    "distanceLinearAttenuation" => PointMember::DistanceLinearAttenuation,
                    "distanceQuadraticAttenuation" => PointMember::DistanceQuadraticAttenuation,
                    _ => return None,
                })
            }
            ("LightSource", Some(m)) => {
                let light = element_below(element, MAX_LIGHTS as u32)?;
                let (member, len) = match m {
                    "ambient" => (LightMember::Ambient, 4),
                    "diffuse" => (LightMember::Diffuse, 4),
                    "specular" => (LightMember::Specular, 4),
                    "position" => (LightMember::Position, 4),
                    "halfVector" => (LightMember::HalfVector, 4),
                    "spotDirection" => (LightMember::SpotDirection, 3),
                    "spotExponent" => (LightMember::SpotExponent, 1),
                    "spotCutoff" => (LightMember::SpotCutoff, 1),
                    "spotCosCutoff" => (LightMember::SpotCosCutoff, 1),
                    "constantAttenuation" => (LightMember::ConstantAttenuation, 1),
                    "linearAttenuation" => (LightMember::LinearAttenuation, 1),
                    "quadraticAttenuation" => (LightMember::QuadraticAttenuation, 1),
                    _ => return None,
                };
                B::Light { light, member, word: word_below(index, len)? }
            }
            ("LightModel", Some("ambient")) => {
                no_element()?;
                B::LightModelAmbient { word: vec4()? }
            }
            ("TextureEnvColor", None) => {
                B::TextureEnvColor { unit: element_below(element, MAX_TEXTURE_UNITS as u32)?, word: vec4()? }
            }
            ("Fog", Some(m)) => {
                no_element()?;
                let (member, word) = match m {
                    "color" => (FogMember::Color, vec4()?),
                    "density" => (FogMember::Density, scalar()?),
                    "start" => (FogMember::Start, scalar()?),
                    "end" => (FogMember::End, scalar()?),
                    "scale" => (FogMember::Scale, scalar()?),
                    _ => return None,
                };
                B::Fog { member, word }
            }
            (base, m) => {
                if let Some(rest) = base.strip_suffix("Material") {
                    no_element()?;
                    let (member, word) = match m? {
                        "emission" => (MaterialMember::Emission, vec4()?),
                        "ambient" => (MaterialMember::Ambient, vec4()?),
                        "diffuse" => (MaterialMember::Diffuse, vec4()?),
                        "specular" => (MaterialMember::Specular, vec4()?),
                        "shininess" => (MaterialMember::Shininess, scalar()?),
                        _ => return None,
                    };
                    B::Material { face: face(rest)?, member, word }
                } else if let Some(rest) = base.strip_suffix("LightModelProduct") {
                    no_element()?;
                    (m? == "sceneColor").then_some(())?;
                    B::SceneColor { face: face(rest)?, word: vec4()? }
                } else if let Some(rest) = base.strip_suffix("LightProduct") {
                    let member = match m? {
                        "ambient" => ProductMember::Ambient,
                        "diffuse" => ProductMember::Diffuse,
                        "specular" => ProductMember::Specular,
                        _ => return None,
                    };
                    let light = element_below(element, MAX_LIGHTS as u32)?;
                    B::LightProduct { face: face(rest)?, light, member, word: vec4()? }
                } else if let Some(coord) = base.strip_prefix("EyePlane").or(base.strip_prefix("ObjectPlane")) {
                    if m.is_some() {
                        return None;
                    }
                    let coord = match coord {
                        "S" => 0,
                        "T" => 1,
                        "R" => 2,
                        "Q" => 3,
                        _ => return None,
                    };
                    let unit = element_below(element, TEXTURE_COORD_SETS)?;
                    B::TexGenPlane { eye: base.starts_with("Eye"), coord, unit, word: vec4()? }
                } else {
                    return None;
                }
            }
        })
    }
}

/// Mesa's `NORMALIZE_3FV`: v · (1/√|v|²), unchanged when the length is zero.
fn normalize3(v: [f32; 3]) -> [f32; 3] {
    let len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if len2 == 0.0 {
        return v;
    }
    let inv = 1.0 / len2.sqrt();
    v.map(|c| c * inv)
}

/// A light's half vector for an infinite viewer, as Mesa computes it at glLight(GL_POSITION):
/// normalize(normalize(position.xyz) + (0, 0, 1)), w = 1. Mesa computes it only when a
/// glLight changes the position, so a light still at its initial position (0, 0, 1, 0) has
/// the initial (0, 0, 0, 0). (A position changed and then set back to the initial one has
/// the computed vector on Mesa; tessera keeps no history and answers zero then too.)
fn half_vector(position: [f32; 4]) -> [f32; 4] {
    const INITIAL_POSITION: [f32; 4] = [0.0, 0.0, 1.0, 0.0];
    if position.map(f32::to_bits) == INITIAL_POSITION.map(f32::to_bits) {
        return [0.0; 4];
    }
    let p = normalize3([position[0], position[1], position[2]]);
    let h = normalize3([p[0], p[1], p[2] + 1.0]);
    [h[0], h[1], h[2], 1.0]
}

/// Mesa's `cosf(cutoff · π/180)`: the angle in double precision rounded to a float, its
/// single-precision cosine, negative results (90° and 180°) as 0. (llvmpipe reads 0.49999997
/// for 60°.)
fn spot_cos_cutoff(cutoff: f32) -> f32 {
    let angle = (cutoff as f64 * std::f64::consts::PI / 180.0) as f32;
    angle.cos().max(0.0)
}

/// The built-in state of one draw, read word by word: what several words share is computed
/// on first use and kept for the draw. Build one per draw (after the draw validated the
/// matrices) with [`Context::builtin_values`]; it borrows the context, so state cannot
/// change under it.
pub struct BuiltinValues<'a> {
    ctx: &'a Context,
    /// Analysed copies of the modelview, projection, modelview-projection and texture
    /// matrices (tops of the stacks are analysed already after the draw's validation; a
    /// copy is analysed when one is not).
    matrices: [OnceCell<Matrix>; 3 + MAX_TEXTURE_COORDS],
}

impl Context {
    /// The built-in state values of the current state (see [`BuiltinValues`]).
    pub fn builtin_values(&self) -> BuiltinValues<'_> {
        BuiltinValues { ctx: self, matrices: Default::default() }
    }

    /// Word `index` of the built-in uniform element `name` (`gl_ModelViewMatrix`,
    /// `gl_LightSource[0].diffuse`; matrices column-major) as the current state gives it;
    /// `None` for a name that is no built-in state uniform. Resolves the name and computes
    /// shared values each call: for many words, resolve once ([`BuiltinUniform::resolve`])
    /// and read through one [`BuiltinValues`] per draw (as the draws do). For the tests.
    #[cfg(test)]
    pub fn builtin_uniform_word(&self, name: &str, index: u32) -> Option<u32> {
        let uniform = BuiltinUniform::resolve(name, index)?;
        Some(self.builtin_values().word(&uniform))
    }
}

fn analysed(mut m: Matrix) -> Matrix {
    if m.is_dirty() {
        m.analyse();
    }
    m
}

impl BuiltinValues<'_> {
    /// The analysed matrix `source`; texture units tessera does not have read the identity.
    fn matrix(&self, source: MatrixSource) -> Option<&Matrix> {
        let stacks = &self.ctx.matrices;
        let (slot, id) = match source {
            MatrixSource::ModelView => (0, StackId::Modelview),
            MatrixSource::Projection => (1, StackId::Projection),
            MatrixSource::ModelViewProjection => {
                return Some(self.matrices[2].get_or_init(|| analysed(stacks.model_project_matrix())));
            }
            MatrixSource::Texture(unit) if (unit as usize) < MAX_TEXTURE_COORDS => {
                (3 + unit as usize, StackId::Texture(unit as usize))
            }
            MatrixSource::Texture(_) => return None,
        };
        Some(self.matrices[slot].get_or_init(|| analysed(stacks.top(id))))
    }

    /// The value of one resolved word, as the bits of a float.
    pub fn word(&self, uniform: &BuiltinUniform) -> u32 {
        self.value(uniform).to_bits()
    }

    /// The value of one resolved word.
    pub fn value(&self, uniform: &BuiltinUniform) -> f32 {
        use BuiltinUniform as B;
        let s = &self.ctx.state;
        let lighting = &s.lighting;
        // glMaterial between glBegin and glEnd gives vertices their materials, which only
        // fixed-function lighting reads: a shader's gl_FrontMaterial and its products keep
        // the materials of glBegin until glEnd (as Mesa; piglit gl-2.0-shader-materials).
        let materials = self.ctx.begin_materials.as_ref().unwrap_or(&lighting.materials);
        match *uniform {
            B::Matrix { source, form, word } => {
                let word = word as usize;
                // Element (row, col) of a column-major matrix is at col·4 + row; a transpose
                // reads (col, row).
                let transposed = (word % 4) * 4 + word / 4;
                let Some(m) = self.matrix(source) else {
                    // The identity (a unit tessera does not have), in every form.
                    return if word.is_multiple_of(5) { 1.0 } else { 0.0 };
                };
                match form {
                    MatrixForm::Plain => m.elements()[word],
                    MatrixForm::Transpose => m.elements()[transposed],
                    MatrixForm::Inverse => m.inverse()[word],
                    MatrixForm::InverseTranspose => m.inverse()[transposed],
                }
            }
            B::NormalMatrix { word } => {
                // Column c of the normal matrix is row c of the inverse modelview.
                let (col, row) = (word as usize / 3, word as usize % 3);
                let inverse = self.matrix(MatrixSource::ModelView).map_or(&[0.0; 16], Matrix::inverse);
                inverse[row * 4 + col]
            }
            B::NormalScale => self.matrix(MatrixSource::ModelView).map_or(1.0, Matrix::normal_rescale),
            B::DepthRange(member) => {
                let [near, far] = s.viewport.depth_range.map(|d| d as f32);
                match member {
                    DepthRangeMember::Near => near,
                    DepthRangeMember::Far => far,
                    DepthRangeMember::Diff => far - near,
                }
            }
            B::ClipPlane { plane, word } => s.transform.clip_plane_equations[plane as usize][word as usize] as f32,
            B::Point(member) => {
                let lp = &s.line_point;
                match member {
                    PointMember::Size => lp.point_size,
                    PointMember::SizeMin => lp.point_size_min,
                    PointMember::SizeMax => lp.point_size_max,
                    PointMember::FadeThresholdSize => lp.point_fade_threshold,
                    PointMember::DistanceConstantAttenuation => lp.point_distance_attenuation[0],
                    PointMember::DistanceLinearAttenuation => lp.point_distance_attenuation[1],
                    PointMember::DistanceQuadraticAttenuation => lp.point_distance_attenuation[2],
                }
            }
            B::Material { face, member, word } => {
                let m = &materials[face as usize];
                let w = word as usize;
                match member {
                    MaterialMember::Emission => m.emission[w],
                    MaterialMember::Ambient => m.ambient[w],
                    MaterialMember::Diffuse => m.diffuse[w],
                    MaterialMember::Specular => m.specular[w],
                    MaterialMember::Shininess => m.shininess,
                }
            }
            B::Light { light, member, word } => {
                let l = &lighting.light[light as usize];
                let w = word as usize;
                match member {
                    LightMember::Ambient => l.ambient[w],
                    LightMember::Diffuse => l.diffuse[w],
                    LightMember::Specular => l.specular[w],
                    LightMember::Position => l.position[w],
                    LightMember::HalfVector => half_vector(l.position)[w],
                    LightMember::SpotDirection => l.spot_direction[w],
                    LightMember::SpotExponent => l.spot_exponent,
                    LightMember::SpotCutoff => l.spot_cutoff,
                    LightMember::SpotCosCutoff => spot_cos_cutoff(l.spot_cutoff),
                    LightMember::ConstantAttenuation => l.attenuation[0],
                    LightMember::LinearAttenuation => l.attenuation[1],
                    LightMember::QuadraticAttenuation => l.attenuation[2],
                }
            }
            B::LightModelAmbient { word } => lighting.model_ambient[word as usize],
            B::SceneColor { face, word } => {
                let m = &materials[face as usize];
                let w = word as usize;
                if w == 3 {
                    m.diffuse[3]
                } else {
                    lighting.model_ambient[w] * m.ambient[w] + m.emission[w]
                }
            }
            B::LightProduct { face, light, member, word } => {
                let m = &materials[face as usize];
                let l = &lighting.light[light as usize];
                let (light_color, material_color) = match member {
                    ProductMember::Ambient => (l.ambient, m.ambient),
                    ProductMember::Diffuse => (l.diffuse, m.diffuse),
                    ProductMember::Specular => (l.specular, m.specular),
                };
                let w = word as usize;
                if w == 3 {
                    material_color[3]
                } else {
                    light_color[w] * material_color[w]
                }
            }
            B::TextureEnvColor { unit, word } => s.texture.unit_state[unit as usize].env.color[word as usize],
            B::TexGenPlane { eye, coord, unit, word } => {
                let Some(unit_state) = s.texture.unit_state.get(unit as usize) else {
                    // The initial planes of a unit tessera does not have: S = (1, 0, 0, 0),
                    // T = (0, 1, 0, 0), R = Q = 0.
                    return if coord < 2 && coord == word { 1.0 } else { 0.0 };
                };
                let gen = &unit_state.gen[coord as usize];
                let plane = if eye { gen.eye_plane } else { gen.object_plane };
                plane[word as usize] as f32
            }
            B::Fog { member, word } => {
                let fog = &s.fog;
                match member {
                    FogMember::Color => {
                        let c = fog.color[word as usize];
                        if self.ctx.fragment_clamping() {
                            c.clamp(0.0, 1.0)
                        } else {
                            c
                        }
                    }
                    FogMember::Density => fog.density,
                    FogMember::Start => fog.start,
                    FogMember::End => fog.end,
                    FogMember::Scale => 1.0 / (fog.end - fog.start),
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::ContextConfig;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};
    use crate::gl::enums::*;
    use crate::glsl::builtins::{builtin_structs, variables, Access};
    use crate::glsl::hir::Type;
    use crate::glsl::{Limits, Stage};

    fn context() -> Context {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, depth_stencil, 0);
        Context::new(ContextConfig { visual })
    }

    fn word(ctx: &Context, name: &str, index: u32) -> f32 {
        f32::from_bits(ctx.builtin_uniform_word(name, index).unwrap_or_else(|| panic!("{name} word {index}")))
    }

    fn words<const N: usize>(ctx: &Context, name: &str) -> [f32; N] {
        std::array::from_fn(|i| word(ctx, name, i as u32))
    }

    /// The inverse of a column-major 4×4 matrix, in double precision (cofactors).
    fn inverse_f64(m: &[f32; 16]) -> [f64; 16] {
        let a = glam::DMat4::from_cols_array(&m.map(f64::from));
        assert!(a.determinant().abs() > 1e-9, "test matrix is singular");
        a.inverse().to_cols_array()
    }

    fn assert_close(got: &[f32], want: &[f64], tolerance: f64, what: &str) {
        for (i, (&g, &w)) in got.iter().zip(want).enumerate() {
            assert!((g as f64 - w).abs() <= tolerance * w.abs().max(1.0), "{what} word {i}: {g} != {w}");
        }
    }

    /// Every element name and word count of a built-in uniform of type `ty`.
    fn elements(name: &str, ty: &Type, out: &mut Vec<(String, u32)>) {
        match ty {
            Type::Scalar(_) => out.push((name.to_string(), 1)),
            Type::Vector(_, n) => out.push((name.to_string(), *n as u32)),
            Type::Matrix(c, r) => out.push((name.to_string(), (*c * *r) as u32)),
            Type::Array(element, Some(n)) => {
                for i in 0..*n {
                    elements(&format!("{name}[{i}]"), element, out);
                }
            }
            Type::Struct(s) => {
                for (member, t) in &s.members {
                    elements(&format!("{name}.{member}"), t, out);
                }
            }
            other => panic!("{name}: unexpected built-in uniform type {other:?}"),
        }
    }

    #[test]
    fn every_declared_builtin_uniform_word_resolves_and_no_word_past_its_end() {
        let mut next_id = 0;
        let structs = builtin_structs(&mut next_id);
        let mut all = Vec::new();
        for stage in [Stage::Vertex, Stage::Fragment] {
            for v in variables(stage, 120, &Limits::default(), &structs) {
                if v.access == Access::Uniform {
                    elements(v.name, &v.ty, &mut all);
                }
            }
        }
        assert!(all.len() > 300, "{} elements", all.len());
        let ctx = context();
        for (name, count) in &all {
            for i in 0..*count {
                assert!(BuiltinUniform::resolve(name, i).is_some(), "{name} word {i}");
                assert!(ctx.builtin_uniform_word(name, i).is_some(), "{name} word {i}");
            }
            assert_eq!(BuiltinUniform::resolve(name, *count), None, "{name} word {count}");
        }
    }

    #[test]
    fn names_that_are_no_builtin_state_do_not_resolve() {
        for name in [
            "gl_ModelViewMatrixInverseInverse",
            "gl_NormalMatrixInverse",
            "gl_TextureMatrix",
            "gl_TextureMatrix[8]",
            "gl_ModelViewMatrix[0]",
            "gl_LightSource[8].diffuse",
            "gl_LightSource.diffuse",
            "gl_LightSource[0].colour",
            "gl_LightSource[0]",
            "gl_LightSource[x].diffuse",
            "gl_LightSource[0]diffuse",
            "gl_ClipPlane[6]",
            "gl_TextureEnvColor[4]",
            "gl_EyePlaneU[0]",
            "gl_SideMaterial.ambient",
            "gl_FrontLightModelProduct.ambient",
            "gl_Fog",
            "gl_Fog.colour",
            "gl_FogCoord",
            "ModelViewMatrix",
            "u",
            "",
        ] {
            assert_eq!(BuiltinUniform::resolve(name, 0), None, "{name}");
        }
        assert_eq!(BuiltinUniform::resolve("gl_LightSource[0].spotDirection", 3), None);
        assert_eq!(BuiltinUniform::resolve("gl_Fog.density", 1), None);
        assert_eq!(
            BuiltinUniform::resolve("gl_TextureMatrixInverseTranspose[3]", 14),
            Some(BuiltinUniform::Matrix {
                source: MatrixSource::Texture(3),
                form: MatrixForm::InverseTranspose,
                word: 14
            })
        );
        assert_eq!(
            BuiltinUniform::resolve("gl_BackLightProduct[7].specular", 2),
            Some(BuiltinUniform::LightProduct { face: 1, light: 7, member: ProductMember::Specular, word: 2 })
        );
    }

    /// A modelview of a rotation, a translation and a non-uniform scale; a perspective
    /// projection; a projective texture matrix on unit 0 and a singular one on unit 1.
    fn matrices_context() -> Context {
        let mut ctx = context();
        ctx.matrix_mode(GL_MODELVIEW);
        ctx.translate(0.5, -1.25, 2.0);
        ctx.rotate(33.0, 0.3, 1.0, -0.2);
        ctx.scale(1.5, 0.75, 2.5);
        ctx.matrix_mode(GL_PROJECTION);
        ctx.frustum(-1.0, 1.5, -0.75, 1.25, 0.5, 20.0);
        ctx.matrix_mode(GL_TEXTURE);
        ctx.load_matrix(&[1.0, 0.5, 0.0, 0.25, 0.125, 2.0, 0.3, 0.0, -0.5, 0.0, 1.5, 0.1, 3.0, -2.0, 1.0, 1.0]);
        ctx.active_texture(GL_TEXTURE1);
        ctx.scale(2.0, 0.0, 1.0);
        ctx.active_texture(GL_TEXTURE0);
        ctx.matrix_mode(GL_MODELVIEW);
        ctx.matrices.validate();
        ctx
    }

    #[test]
    fn matrices_their_inverses_and_transposes() {
        let ctx = matrices_context();
        let cases = [
            ("ModelView", ctx.matrix_elements(StackId::Modelview)),
            ("Projection", ctx.matrix_elements(StackId::Projection)),
            ("ModelViewProjection", ctx.matrices.model_project().to_cols_array()),
            ("Texture", ctx.matrix_elements(StackId::Texture(0))),
        ];
        for (stem, m) in cases {
            let index = if stem == "Texture" { "[0]" } else { "" };
            let plain: [f32; 16] = words(&ctx, &format!("gl_{stem}Matrix{index}"));
            let transpose: [f32; 16] = words(&ctx, &format!("gl_{stem}MatrixTranspose{index}"));
            let inverse: [f32; 16] = words(&ctx, &format!("gl_{stem}MatrixInverse{index}"));
            let inverse_transpose: [f32; 16] = words(&ctx, &format!("gl_{stem}MatrixInverseTranspose{index}"));
            // The matrix fixed function uses, bit for bit (the MVP product included: the
            // invariance of ftransform()).
            assert_eq!(plain.map(f32::to_bits), m.map(f32::to_bits), "{stem}");
            for col in 0..4 {
                for row in 0..4 {
                    assert_eq!(transpose[col * 4 + row], m[row * 4 + col], "{stem} transpose");
                    assert_eq!(inverse_transpose[col * 4 + row], inverse[row * 4 + col], "{stem} inverse transpose");
                }
            }
            assert_close(&inverse, &inverse_f64(&m), 1e-5, &format!("{stem} inverse"));
        }
        // The MVP is P · M.
        let p = glam::DMat4::from_cols_array(&ctx.matrix_elements(StackId::Projection).map(f64::from));
        let m = glam::DMat4::from_cols_array(&ctx.matrix_elements(StackId::Modelview).map(f64::from));
        let mvp: [f32; 16] = words(&ctx, "gl_ModelViewProjectionMatrix");
        assert_close(&mvp, &(p * m).to_cols_array(), 1e-6, "P·M");
    }

    #[test]
    fn a_singular_matrix_has_the_identity_as_inverse_as_on_mesa() {
        let ctx = matrices_context();
        let identity = glam::Mat4::IDENTITY.to_cols_array();
        for name in ["gl_TextureMatrixInverse[1]", "gl_TextureMatrixInverseTranspose[1]"] {
            assert_eq!(words::<16>(&ctx, name), identity, "{name}");
        }
        assert_eq!(word(&ctx, "gl_TextureMatrix[1]", 5), 0.0);
        // Units without fixed-function state (4..8) read the identity in every form.
        for name in ["gl_TextureMatrix[6]", "gl_TextureMatrixInverse[7]", "gl_TextureMatrixTranspose[4]"] {
            assert_eq!(words::<16>(&ctx, name), identity, "{name}");
        }
    }

    #[test]
    fn a_matrix_changed_since_the_last_validation_is_read_as_it_is_now() {
        let mut ctx = matrices_context();
        ctx.matrix_mode(GL_PROJECTION);
        ctx.load_identity();
        ctx.scale(2.0, 4.0, 8.0);
        let inverse: [f32; 16] = words(&ctx, "gl_ProjectionMatrixInverse");
        assert_eq!([inverse[0], inverse[5], inverse[10], inverse[15]], [0.5, 0.25, 0.125, 1.0]);
    }

    #[test]
    fn normal_matrix_and_normal_scale() {
        let ctx = matrices_context();
        let m = ctx.matrix_elements(StackId::Modelview);
        // transpose(inverse(upper 3×3)), independently in double precision.
        let upper =
            glam::DMat3::from_cols_array(&[m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]].map(f64::from));
        let want = upper.inverse().transpose().to_cols_array();
        let normal: [f32; 9] = words(&ctx, "gl_NormalMatrix");
        assert_close(&normal, &want, 1e-5, "gl_NormalMatrix");
        // The rescale factor is 1/|third row of the inverse|: 1/|(upper⁻¹ row 2)|.
        let inv = upper.inverse();
        let row2 = glam::DVec3::new(inv.x_axis.z, inv.y_axis.z, inv.z_axis.z);
        assert_close(&[word(&ctx, "gl_NormalScale", 0)], &[1.0 / row2.length()], 1e-6, "gl_NormalScale");

        let mut rigid = context();
        rigid.rotate(40.0, 1.0, 2.0, 3.0);
        rigid.translate(1.0, 2.0, 3.0);
        rigid.matrices.validate();
        assert_eq!(word(&rigid, "gl_NormalScale", 0), 1.0, "length preserving");
        let mut scaled = context();
        scaled.scale(1.0, 1.0, 4.0);
        scaled.matrices.validate();
        assert_eq!(word(&scaled, "gl_NormalScale", 0), 4.0);
    }

    #[test]
    fn lights_materials_and_their_products() {
        let mut ctx = context();
        ctx.translate(0.0, 0.0, -2.0);
        ctx.light(GL_LIGHT3, GL_POSITION, &[1.0, 2.0, 0.0, 1.0]);
        ctx.light(GL_LIGHT3, GL_SPOT_DIRECTION, &[0.0, 3.0, 4.0]);
        ctx.light(GL_LIGHT3, GL_SPOT_CUTOFF, &[60.0]);
        ctx.light(GL_LIGHT3, GL_SPOT_EXPONENT, &[7.0]);
        ctx.light(GL_LIGHT3, GL_AMBIENT, &[0.1, 0.2, 0.3, 0.4]);
        ctx.light(GL_LIGHT3, GL_DIFFUSE, &[0.5, 0.6, 0.7, 0.8]);
        ctx.light(GL_LIGHT3, GL_SPECULAR, &[0.9, 1.0, 1.5, 0.25]);
        ctx.light(GL_LIGHT3, GL_CONSTANT_ATTENUATION, &[2.0]);
        ctx.light(GL_LIGHT3, GL_LINEAR_ATTENUATION, &[0.5]);
        ctx.light(GL_LIGHT3, GL_QUADRATIC_ATTENUATION, &[0.25]);
        ctx.material(GL_BACK, GL_AMBIENT, &[0.3, 0.4, 0.5, 0.6]);
        ctx.material(GL_BACK, GL_DIFFUSE, &[0.25, 0.5, 0.75, 0.125]);
        ctx.material(GL_BACK, GL_SPECULAR, &[1.0, 0.5, 0.25, 0.375]);
        ctx.material(GL_BACK, GL_EMISSION, &[0.01, 0.02, 0.03, 0.04]);
        ctx.material(GL_BACK, GL_SHININESS, &[33.0]);
        ctx.light_model(GL_LIGHT_MODEL_AMBIENT, &[0.5, 0.25, 0.125, 0.0625]);

        let light = |member: &str| format!("gl_LightSource[3].{member}");
        assert_eq!(words::<4>(&ctx, &light("ambient")), [0.1, 0.2, 0.3, 0.4]);
        assert_eq!(words::<4>(&ctx, &light("specular")), [0.9, 1.0, 1.5, 0.25]);
        // Eye space: the position moved by the modelview, the direction not (w = 0 for it).
        assert_eq!(words::<4>(&ctx, &light("position")), [1.0, 2.0, -2.0, 1.0]);
        assert_eq!(words::<3>(&ctx, &light("spotDirection")), [0.0, 3.0, 4.0]);
        // normalize(normalize((1, 2, -2)) + (0, 0, 1)) = (1, 2, 1)/√6.
        let s6 = 6f64.sqrt();
        assert_close(&words::<4>(&ctx, &light("halfVector")), &[1.0 / s6, 2.0 / s6, 1.0 / s6, 1.0], 1e-6, "half");
        assert_eq!(word(&ctx, &light("spotExponent"), 0), 7.0);
        assert_eq!(word(&ctx, &light("spotCutoff"), 0), 60.0);
        assert_eq!(word(&ctx, &light("spotCosCutoff"), 0), 0.49999997, "cos 60° as llvmpipe has it");
        assert_eq!(
            [light("constantAttenuation"), light("linearAttenuation"), light("quadraticAttenuation")]
                .map(|n| word(&ctx, &n, 0)),
            [2.0, 0.5, 0.25]
        );
        // An untouched light: cutoff 180 has cosine 0 (Mesa clamps the −1), its half
        // vector was never computed; light 1 is black.
        assert_eq!(word(&ctx, "gl_LightSource[1].spotCutoff", 0), 180.0);
        assert_eq!(word(&ctx, "gl_LightSource[1].spotCosCutoff", 0), 0.0);
        assert_eq!(words::<4>(&ctx, "gl_LightSource[1].halfVector"), [0.0; 4]);
        // Single precision as on llvmpipe: cos 60° is 0.49999997, cos 90° (−4.4e-8) is 0.
        ctx.light(GL_LIGHT1, GL_SPOT_CUTOFF, &[90.0]);
        assert_eq!(word(&ctx, "gl_LightSource[1].spotCosCutoff", 0), 0.0);
        ctx.light(GL_LIGHT1, GL_SPOT_CUTOFF, &[89.9]);
        assert_eq!(word(&ctx, "gl_LightSource[1].spotCosCutoff", 0).to_bits(), 0x3ae4c281, "llvmpipe's value");
        ctx.light(GL_LIGHT1, GL_POSITION, &[0.0, 0.0, 3.0, 0.0]);
        assert_eq!(words::<4>(&ctx, "gl_LightSource[1].halfVector"), [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(words::<4>(&ctx, "gl_LightSource[1].diffuse"), [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(words::<4>(&ctx, "gl_LightSource[0].diffuse"), [1.0; 4]);

        assert_eq!(words::<4>(&ctx, "gl_BackMaterial.diffuse"), [0.25, 0.5, 0.75, 0.125]);
        assert_eq!(word(&ctx, "gl_BackMaterial.shininess", 0), 33.0);
        assert_eq!(words::<4>(&ctx, "gl_FrontMaterial.diffuse"), [0.8, 0.8, 0.8, 1.0], "front untouched");
        assert_eq!(words::<4>(&ctx, "gl_LightModel.ambient"), [0.5, 0.25, 0.125, 0.0625]);
        // Emission + ambient × model ambient; alpha from the diffuse material.
        let scene = [0.01f32 + 0.3 * 0.5, 0.02 + 0.4 * 0.25, 0.03 + 0.5 * 0.125, 0.125];
        assert_eq!(words::<4>(&ctx, "gl_BackLightModelProduct.sceneColor"), scene);
        // Light × material; alpha the material's.
        assert_eq!(words::<4>(&ctx, "gl_BackLightProduct[3].diffuse"), [0.5f32 * 0.25, 0.6 * 0.5, 0.7 * 0.75, 0.125]);
        assert_eq!(words::<4>(&ctx, "gl_BackLightProduct[3].specular"), [0.9f32 * 1.0, 1.0 * 0.5, 1.5 * 0.25, 0.375]);
        assert_eq!(words::<4>(&ctx, "gl_BackLightProduct[3].ambient"), [0.1f32 * 0.3, 0.2 * 0.4, 0.3 * 0.5, 0.6]);
        assert_eq!(words::<4>(&ctx, "gl_FrontLightProduct[0].ambient"), [0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn planes_texture_environment_fog_points_and_depth_range() {
        let mut ctx = context();
        ctx.translate(0.0, 0.0, -2.0);
        ctx.clip_plane(GL_CLIP_PLANE4, [0.0, 0.0, 1.0, 0.0]);
        ctx.active_texture(GL_TEXTURE2);
        ctx.tex_gen(GL_R, GL_EYE_PLANE, &[0.0, 0.0, 1.0, 0.5], true);
        ctx.tex_gen(GL_Q, GL_OBJECT_PLANE, &[1.0, 2.0, 3.0, 4.0], true);
        ctx.tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.25, 0.5, 0.75, 1.0], false);
        // z' = z − 2 turns z = 0 into z' = −2 and so the planes' eye form gains z's w term.
        assert_eq!(words::<4>(&ctx, "gl_ClipPlane[4]"), [0.0, 0.0, 1.0, 2.0]);
        assert_eq!(words::<4>(&ctx, "gl_EyePlaneR[2]"), [0.0, 0.0, 1.0, 2.5]);
        assert_eq!(words::<4>(&ctx, "gl_ObjectPlaneQ[2]"), [1.0, 2.0, 3.0, 4.0]);
        assert_eq!(words::<4>(&ctx, "gl_TextureEnvColor[2]"), [0.25, 0.5, 0.75, 1.0]);
        assert_eq!(words::<4>(&ctx, "gl_TextureEnvColor[1]"), [0.0; 4]);
        // Initial planes, also of units tessera does not have.
        for unit in [0, 5] {
            assert_eq!(words::<4>(&ctx, &format!("gl_EyePlaneS[{unit}]")), [1.0, 0.0, 0.0, 0.0]);
            assert_eq!(words::<4>(&ctx, &format!("gl_ObjectPlaneT[{unit}]")), [0.0, 1.0, 0.0, 0.0]);
            assert_eq!(words::<4>(&ctx, &format!("gl_EyePlaneQ[{unit}]")), [0.0; 4]);
        }

        ctx.fog(GL_FOG_COLOR, [1.5, -0.25, 0.5, 2.0]);
        ctx.fog(GL_FOG_DENSITY, [0.75, 0.0, 0.0, 0.0]);
        ctx.fog(GL_FOG_START, [1.5, 0.0, 0.0, 0.0]);
        ctx.fog(GL_FOG_END, [5.5, 0.0, 0.0, 0.0]);
        // A fixed-point color buffer under GL_FIXED_ONLY: the fog color is clamped.
        assert_eq!(words::<4>(&ctx, "gl_Fog.color"), [1.0, 0.0, 0.5, 1.0]);
        ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE as crate::gl::types::GLenum);
        assert_eq!(words::<4>(&ctx, "gl_Fog.color"), [1.5, -0.25, 0.5, 2.0]);
        let fog = ["density", "start", "end", "scale"].map(|m| word(&ctx, &format!("gl_Fog.{m}"), 0));
        assert_eq!(fog, [0.75, 1.5, 5.5, 0.25]);
        ctx.fog(GL_FOG_END, [1.5, 0.0, 0.0, 0.0]);
        assert_eq!(word(&ctx, "gl_Fog.scale", 0), f32::INFINITY, "Mesa 22 divides by zero too");

        ctx.point_size(3.5);
        ctx.point_parameter(GL_POINT_SIZE_MIN, [1.25, 0.0, 0.0]);
        ctx.point_parameter(GL_POINT_SIZE_MAX, [40.0, 0.0, 0.0]);
        ctx.point_parameter(GL_POINT_FADE_THRESHOLD_SIZE, [2.5, 0.0, 0.0]);
        ctx.point_parameter(GL_POINT_DISTANCE_ATTENUATION, [1.0, 0.125, 0.0625]);
        let point = [
            "size",
            "sizeMin",
            "sizeMax",
            "fadeThresholdSize",
            "distanceConstantAttenuation",
            "distanceLinearAttenuation",
            "distanceQuadraticAttenuation",
        ]
        .map(|m| word(&ctx, &format!("gl_Point.{m}"), 0));
        assert_eq!(point, [3.5, 1.25, 40.0, 2.5, 1.0, 0.125, 0.0625]);

        ctx.depth_range(0.1, 0.7);
        let range = ["near", "far", "diff"].map(|m| word(&ctx, &format!("gl_DepthRange.{m}"), 0));
        // Single precision throughout, as Mesa 22 keeps the range.
        assert_eq!(range, [0.1f32, 0.7, 0.7f32 - 0.1f32]);
    }

    #[test]
    fn one_draws_values_share_the_analysed_matrices() {
        let ctx = matrices_context();
        let values = ctx.builtin_values();
        let w = BuiltinUniform::resolve("gl_ModelViewProjectionMatrixInverse", 5).unwrap();
        let first = values.word(&w);
        assert!(values.matrices[2].get().is_some(), "computed on first use");
        assert_eq!(values.word(&w), first);
        assert!(values.matrices[1].get().is_none(), "the projection was not needed");
        assert_eq!(ctx.builtin_uniform_word("gl_ModelViewProjectionMatrixInverse", 5), Some(first));
    }
}
