//! Per-vertex lighting: the lighting equation of GL 2.1 section 2.14.1, evaluated in eye
//! coordinates, with the per-draw constants computed once.
//!
//! [`Lighting::new`] compiles a draw's lighting state: the enabled lights only, with their
//! normalized directions, half vectors (infinite light and viewer), normalized spot
//! directions and cutoff cosines, and, per face, the scene color (emission + ambient × scene
//! ambient) and the products of material and light colors. [`Lighting::shade`] then does per
//! vertex only what depends on the vertex: the normal's transformation, the directions to
//! local lights, attenuation, the spotlight factor, the diffuse and specular terms.
//!
//! The arithmetic is that of Mesa's fixed-function vertex program (`ffvertex_prog.c`) as
//! llvmpipe runs it, in single precision, because llvmpipe's pictures are the reference:
//! constants that Mesa computes on the CPU (normalized light directions, half vectors, scene
//! colors, light products) use its C expressions; per-vertex values follow the program's
//! order with NIR's lowering (DP3 summed from the last component, multiply-adds not fused,
//! 1/√x and divisions exact, the attenuation's 1/(1/√x) simplified to √x), and POW uses
//! llvmpipe's own exp2/log2 polynomials
//! ([`crate::shader::math::exp2`], the shading IR's). The capi test lighting_float compares the results
//! bit for bit as floats.
//!
//! One deliberate difference: Mesa's program, for a material shininess of zero and a light
//! that is attenuated (local with attenuation, or a spotlight), raises N·H to the power N·L
//! instead of 0 (its dot product fills the exponent's slot); here the specular factor is
//! then 1, as the specification's 0⁰ = 1 says.
//!
//! The GL lighting state ([`LightingState`], [`Light`], [`Material`]) is defined here and
//! stored by `context` as it is: a draw's lighting pass borrows it, so nothing is copied or
//! converted on the way to the per-draw constants.
use crate::gl::enums::*;
use crate::gl::limits::MAX_LIGHTS;
use crate::gl::types::GLenum;
use crate::shader::math::{exp2, log2};

/// One light source (glLight): colors, and position and spot direction in eye coordinates
/// (transformed by the modelview matrix when they were specified).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    /// GL_POSITION in eye coordinates; w = 0 for a directional light.
    pub position: [f32; 4],
    /// GL_SPOT_DIRECTION in eye coordinates.
    pub spot_direction: [f32; 3],
    pub spot_exponent: f32,
    /// Degrees: [0, 90], or 180 (no spotlight).
    pub spot_cutoff: f32,
    /// Constant, linear and quadratic attenuation.
    pub attenuation: [f32; 3],
}

impl Light {
    /// GL's initial values: light 0 is white, the others black (diffuse and specular).
    pub fn initial(index: usize) -> Self {
        let white_if_first = if index == 0 { [1.0; 4] } else { [0.0, 0.0, 0.0, 1.0] };
        Light {
            ambient: [0.0, 0.0, 0.0, 1.0],
            diffuse: white_if_first,
            specular: white_if_first,
            position: [0.0, 0.0, 1.0, 0.0],
            spot_direction: [0.0, 0.0, -1.0],
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            attenuation: [1.0, 0.0, 0.0],
        }
    }
}

/// The material of one face (glMaterial).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    pub emission: [f32; 4],
    pub shininess: f32,
    /// GL_COLOR_INDEXES (ambient, diffuse, specular indexes; color-index lighting only).
    pub color_indexes: [f32; 3],
}

impl Default for Material {
    fn default() -> Self {
        Material {
            ambient: [0.2, 0.2, 0.2, 1.0],
            diffuse: [0.8, 0.8, 0.8, 1.0],
            specular: [0.0, 0.0, 0.0, 1.0],
            emission: [0.0, 0.0, 0.0, 1.0],
            shininess: 0.0,
            color_indexes: [0.0, 1.0, 1.0],
        }
    }
}

/// GL_LIGHTING_BIT: enables, lights, light model, materials, color material, shading.
#[derive(Clone, Debug, PartialEq)]
pub struct LightingState {
    pub enabled: bool,
    pub lights: [bool; MAX_LIGHTS],
    pub color_material: bool,
    /// GL_CLAMP_VERTEX_COLOR.
    pub clamp_vertex_color: GLenum,
    /// glShadeModel: GL_SMOOTH or GL_FLAT.
    pub shade_model: GLenum,
    /// glProvokingVertex: GL_LAST_VERTEX_CONVENTION (GL's default) or GL_FIRST_VERTEX_CONVENTION.
    pub provoking_vertex: GLenum,
    /// The parameters of each light.
    pub light: [Light; MAX_LIGHTS],
    /// GL_LIGHT_MODEL_AMBIENT.
    pub model_ambient: [f32; 4],
    /// GL_LIGHT_MODEL_LOCAL_VIEWER.
    pub local_viewer: bool,
    /// GL_LIGHT_MODEL_TWO_SIDE.
    pub two_side: bool,
    /// GL_LIGHT_MODEL_COLOR_CONTROL: GL_SINGLE_COLOR or GL_SEPARATE_SPECULAR_COLOR.
    pub color_control: GLenum,
    /// Front and back materials.
    pub materials: [Material; 2],
    /// glColorMaterial: GL_FRONT, GL_BACK or GL_FRONT_AND_BACK.
    pub color_material_face: GLenum,
    /// glColorMaterial: GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR or GL_AMBIENT_AND_DIFFUSE.
    pub color_material_mode: GLenum,
}

impl Default for LightingState {
    fn default() -> Self {
        LightingState {
            enabled: false,
            lights: [false; MAX_LIGHTS],
            color_material: false,
            clamp_vertex_color: GL_TRUE as GLenum,
            shade_model: GL_SMOOTH,
            provoking_vertex: GL_LAST_VERTEX_CONVENTION,
            light: std::array::from_fn(Light::initial),
            model_ambient: [0.2, 0.2, 0.2, 1.0],
            local_viewer: false,
            two_side: false,
            color_control: GL_SINGLE_COLOR,
            materials: [Material::default(); 2],
            color_material_face: GL_FRONT_AND_BACK,
            color_material_mode: GL_AMBIENT_AND_DIFFUSE,
        }
    }
}

/// What happens to transformed normals: GL_NORMALIZE, GL_RESCALE_NORMAL (with the factor
/// from the modelview matrix), or nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalScaling {
    None,
    Normalize,
    Rescale(f32),
}

/// The colors lighting gives one vertex: front primary and secondary, and the back ones
/// when two-sided lighting is on (else equal to the front ones).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LitColors {
    pub front: [f32; 4],
    pub front_secondary: [f32; 4],
    pub back: [f32; 4],
    pub back_secondary: [f32; 4],
}

/// A spotlight's constants.
#[derive(Clone, Copy, Debug)]
pub(super) struct Spot {
    /// The normalized spot direction.
    pub(super) direction: [f32; 3],
    pub(super) cos_cutoff: f32,
    pub(super) exponent: f32,
}

/// The constants of one enabled light.
#[derive(Clone, Copy, Debug)]
pub(super) struct LightSetup {
    /// Local lights: the eye-space position; infinite lights: the normalized direction.
    pub(super) position: [f32; 3],
    pub(super) local: bool,
    /// The half vector of an infinite light under an infinite viewer.
    pub(super) half: [f32; 3],
    pub(super) spot: Option<Spot>,
    /// Constant, linear, quadratic attenuation of a local light that has any.
    pub(super) attenuation: Option<[f32; 3]>,
    /// Ambient, diffuse, specular colors of the light (for tracked material products).
    pub(super) colors: [[f32; 4]; 3],
}

/// The constants of one face for a material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct FaceSetup {
    /// Emission + ambient × scene ambient (rgb), and the diffuse alpha.
    pub(super) scene: [f32; 4],
    pub(super) shininess: f32,
    /// Ambient, diffuse, specular products of material and light, per enabled light.
    pub(super) products: [[[f32; 3]; 3]; MAX_LIGHTS],
}

/// Which material parameters the vertex color replaces (GL_COLOR_MATERIAL).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tracking {
    pub face: [bool; 2],
    /// One of GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE.
    pub mode: u32,
}

/// A draw's compiled lighting.
#[derive(Clone, Debug)]
pub struct Lighting {
    pub(super) lights: Vec<LightSetup>,
    pub(super) model_ambient: [f32; 4],
    pub(super) local_viewer: bool,
    pub(super) two_side: bool,
    pub(super) separate_specular: bool,
    /// The inverse modelview (column-major): normals go through its transpose.
    pub(super) inverse_modelview: [f32; 16],
    pub(super) normals: NormalScaling,
    pub(super) materials: [Material; 2],
    pub(super) faces: [FaceSetup; 2],
    pub(super) tracking: Option<Tracking>,
    /// The vertex color `tracked_faces` were made from (GL_COLOR_MATERIAL), if any yet.
    /// (NaN until a color is tracked: NaN equals nothing, so the first color recomputes; a
    /// plain array rather than an `Option`, whose comparison valgrind reports as a read of
    /// its uninitialised payload.)
    tracked_color: [f32; 4],
    tracked_faces: [FaceSetup; 2],
}

/// The program's DP3 as llvmpipe runs it: NIR lowers the reduction from the last
/// component, (z·z' + y·y') + x·x' (measured bit for bit in capi lighting_float).
fn dot3(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[2] * b[2] + a[1] * b[1] + a[0] * b[0]
}

fn scale3(v: [f32; 3], s: f32) -> [f32; 3] {
    [v[0] * s, v[1] * s, v[2] * s]
}

/// Mesa's `NORMALIZE_3FV` (CPU-side constants): unchanged when the length is zero.
fn normalize_cpu(v: [f32; 3]) -> [f32; 3] {
    let len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if len2 != 0.0 {
        scale3(v, 1.0 / len2.sqrt())
    } else {
        v
    }
}

/// The program's normalization: v · (1/√(v·v)).
fn normalize(v: [f32; 3]) -> [f32; 3] {
    scale3(v, 1.0 / dot3(v, v).sqrt())
}

/// `a · b + c` per channel: a multiply and an add, as llvmpipe runs the program's
/// multiply-adds (its NIR options lower `ffma`).
fn mad3(a: f32, b: [f32; 3], c: [f32; 3]) -> [f32; 3] {
    [a * b[0] + c[0], a * b[1] + c[1], a * b[2] + c[2]]
}

impl LightSetup {
    fn new(l: &Light) -> Self {
        let p = [l.position[0], l.position[1], l.position[2]];
        let local = l.position[3] != 0.0;
        let direction = normalize_cpu(p);
        let half = {
            let h = normalize_cpu(direction);
            normalize_cpu([h[0], h[1], h[2] + 1.0])
        };
        let spot = (l.spot_cutoff != 180.0).then(|| Spot {
            direction: normalize_cpu(l.spot_direction),
            cos_cutoff: (l.spot_cutoff as f64 * std::f64::consts::PI / 180.0).cos() as f32,
            exponent: l.spot_exponent,
        });
        let attenuated = l.attenuation != [1.0, 0.0, 0.0];
        LightSetup {
            position: if local { p } else { direction },
            local,
            half,
            spot,
            attenuation: (local && attenuated).then_some(l.attenuation),
            colors: [l.ambient, l.diffuse, l.specular],
        }
    }
}

/// The scene color and light products of `m` (a multiply and an add per channel, whether
/// Mesa computes them on the CPU or, for tracked materials, in the program).
fn face_setup(m: &Material, model_ambient: [f32; 4], lights: &[LightSetup]) -> FaceSetup {
    let scene_channel = |i: usize| model_ambient[i] * m.ambient[i] + m.emission[i];
    let mut products = [[[0.0; 3]; 3]; MAX_LIGHTS];
    for (product, light) in products.iter_mut().zip(lights) {
        for (k, material) in [m.ambient, m.diffuse, m.specular].iter().enumerate() {
            product[k] = std::array::from_fn(|i| light.colors[k][i] * material[i]);
        }
    }
    FaceSetup {
        scene: [scene_channel(0), scene_channel(1), scene_channel(2), m.diffuse[3]],
        shininess: m.shininess,
        products,
    }
}

/// Sets material parameter `pname` (GL_AMBIENT … GL_COLOR_INDEXES, already validated; `p`
/// holds enough values) of `m`.
pub fn set_material_parameter(m: &mut Material, pname: u32, p: &[f32]) {
    use crate::gl::enums::*;
    let vec4 = |p: &[f32]| [p[0], p[1], p[2], p[3]];
    match pname {
        GL_AMBIENT => m.ambient = vec4(p),
        GL_DIFFUSE => m.diffuse = vec4(p),
        GL_SPECULAR => m.specular = vec4(p),
        GL_EMISSION => m.emission = vec4(p),
        GL_AMBIENT_AND_DIFFUSE => (m.ambient, m.diffuse) = (vec4(p), vec4(p)),
        GL_SHININESS => m.shininess = p[0],
        GL_COLOR_INDEXES => m.color_indexes = [p[0], p[1], p[2]],
        _ => {}
    }
}

/// The program's POW as llvmpipe evaluates it: 2^(log2(x) · y), and 0 for x = 0. Matching
/// its approximations keeps specular highlights and spotlights bit-exact.
fn pow(x: f32, y: f32) -> f32 {
    if x == 0.0 {
        0.0
    } else {
        exp2(log2(x) * y)
    }
}

/// max(x, 0) as one comparison and select: x when x > 0, else +0 (NaN and −0 included), the
/// same operation as the lighting program's ([`super::program`]).
fn positive_part(x: f32) -> f32 {
    if x > 0.0 {
        x
    } else {
        0.0
    }
}

/// The diffuse and specular factors of one light for one face (GL's LIT): max(N·L, 0),
/// and (N·H)^shininess where N·L > 0.
fn lit(n_dot_l: f32, n_dot_h: f32, shininess: f32) -> (f32, f32) {
    let diffuse = positive_part(n_dot_l);
    let specular = if n_dot_l > 0.0 {
        if shininess == 0.0 {
            1.0
        } else {
            pow(positive_part(n_dot_h), shininess.clamp(-128.0, 128.0))
        }
    } else {
        0.0
    };
    (diffuse, specular)
}

impl Lighting {
    /// Compiles `state` for a draw: `inverse_modelview` transforms normals (by its
    /// transpose), `normals` is GL_NORMALIZE / GL_RESCALE_NORMAL.
    pub fn new(state: &LightingState, inverse_modelview: [f32; 16], normals: NormalScaling) -> Self {
        let lights: Vec<LightSetup> =
            (0..MAX_LIGHTS).filter(|&i| state.lights[i]).map(|i| LightSetup::new(&state.light[i])).collect();
        let tracking = state.color_material.then_some(Tracking {
            face: match state.color_material_face {
                GL_FRONT => [true, false],
                GL_BACK => [false, true],
                _ => [true, true],
            },
            mode: state.color_material_mode,
        });
        let faces = state.materials.map(|m| face_setup(&m, state.model_ambient, &lights));
        Lighting {
            lights,
            model_ambient: state.model_ambient,
            local_viewer: state.local_viewer,
            two_side: state.two_side,
            separate_specular: state.color_control == GL_SEPARATE_SPECULAR_COLOR,
            inverse_modelview,
            normals,
            materials: state.materials,
            faces,
            tracking,
            tracked_color: [f32::NAN; 4],
            tracked_faces: faces,
        }
    }

    /// Whether back faces get colors of their own.
    pub fn two_side(&self) -> bool {
        self.two_side
    }

    /// Whether the specular term goes to the secondary color.
    pub fn separate_specular(&self) -> bool {
        self.separate_specular
    }

    /// Replaces the materials (glMaterial between glBegin and glEnd).
    pub fn set_materials(&mut self, materials: &[Material; 2]) {
        self.materials = *materials;
        self.faces = materials.map(|m| face_setup(&m, self.model_ambient, &self.lights));
        self.tracked_color = [f32::NAN; 4];
    }

    /// Under GL_COLOR_MATERIAL, makes `tracked_faces` the face constants of the materials
    /// with the tracked parameters replaced by `color`, recomputed only when the color
    /// changes from one vertex to the next.
    fn track(&mut self, color: [f32; 4]) {
        let Some(tracking) = self.tracking else { return };
        if self.tracked_color != color {
            for f in 0..2 {
                self.tracked_faces[f] = if tracking.face[f] {
                    let mut m = self.materials[f];
                    set_material_parameter(&mut m, tracking.mode, &color);
                    face_setup(&m, self.model_ambient, &self.lights)
                } else {
                    self.faces[f]
                };
            }
            self.tracked_color = color;
        }
    }

    /// The eye-space normal of an object-space `normal`, normalized or rescaled as enabled.
    pub fn eye_normal(&self, normal: [f32; 3]) -> [f32; 3] {
        let m = &self.inverse_modelview;
        // Component j is column j of the inverse (row j of its transpose) · normal.
        let n = [0, 1, 2].map(|j| dot3([m[4 * j], m[4 * j + 1], m[4 * j + 2]], normal));
        match self.normals {
            NormalScaling::None => n,
            NormalScaling::Normalize => normalize(n),
            NormalScaling::Rescale(s) => scale3(n, s),
        }
    }

    /// The lit colors of a vertex at `eye` (eye coordinates) with object-space `normal` and
    /// vertex color `color` (used by GL_COLOR_MATERIAL). Not clamped.
    pub fn shade(&mut self, eye: [f32; 4], normal: [f32; 3], color: [f32; 4]) -> LitColors {
        self.track(color);
        let faces = if self.tracking.is_some() { &self.tracked_faces } else { &self.faces };
        let n = self.eye_normal(normal);
        let eye3 = [eye[0], eye[1], eye[2]];
        let sides = if self.two_side { 2 } else { 1 };
        let mut primary = [[0.0f32; 3]; 2];
        let mut secondary = [[0.0f32; 3]; 2];
        for f in 0..sides {
            primary[f] = [faces[f].scene[0], faces[f].scene[1], faces[f].scene[2]];
        }
        let needs_half = faces[0].shininess != 0.0 || (self.two_side && faces[1].shininess != 0.0);
        let eye_dir = (self.local_viewer && needs_half).then(|| normalize(eye3));
        for (index, light) in self.lights.iter().enumerate() {
            let (vp, inv_dist) = if light.local {
                let d = [light.position[0] - eye3[0], light.position[1] - eye3[1], light.position[2] - eye3[2]];
                let d2 = dot3(d, d);
                let inv = 1.0 / d2.sqrt();
                (scale3(d, inv), Some((inv, d2)))
            } else {
                (light.position, None)
            };
            let spot = light.spot.map(|s| {
                let cos = dot3([-vp[0], -vp[1], -vp[2]], s.direction);
                if s.cos_cutoff < cos {
                    pow(cos, s.exponent)
                } else {
                    0.0
                }
            });
            let distance = match (light.attenuation, inv_dist) {
                (Some(k), Some((inv, d2))) => {
                    // Mesa 22's program builds (1, d, d²) from 1/d as (1/d · d, d, d · d);
                    // NIR's algebraic rules turn its d = 1/(1/√x) into √x and d · d into x.
                    // The first term is then 1/√x · √x, not always exactly 1.
                    let d = d2.sqrt();
                    Some(1.0 / dot3(k, [inv * d, d, d2]))
                }
                _ => None,
            };
            let attenuation = match (distance, spot) {
                (Some(d), Some(s)) => Some(d * s),
                (d, s) => d.or(s),
            };
            let half = if !needs_half {
                [0.0; 3]
            } else if let Some(e) = eye_dir {
                normalize([vp[0] - e[0], vp[1] - e[1], vp[2] - e[2]])
            } else if !light.local {
                light.half
            } else {
                normalize([vp[0], vp[1], vp[2] + 1.0])
            };
            let n_dot_l = dot3(n, vp);
            let n_dot_h = dot3(n, half);
            for f in 0..sides {
                let sign = if f == 0 { 1.0 } else { -1.0 };
                let (mut diffuse, mut specular) = lit(sign * n_dot_l, sign * n_dot_h, faces[f].shininess);
                let [ambient_p, diffuse_p, specular_p] = faces[f].products[index];
                let mut col = primary[f];
                if let Some(a) = attenuation {
                    diffuse *= a;
                    specular *= a;
                    col = mad3(a, ambient_p, col);
                } else {
                    col = [ambient_p[0] + col[0], ambient_p[1] + col[1], ambient_p[2] + col[2]];
                }
                col = mad3(diffuse, diffuse_p, col);
                if self.separate_specular {
                    secondary[f] = mad3(specular, specular_p, secondary[f]);
                } else {
                    col = mad3(specular, specular_p, col);
                }
                primary[f] = col;
            }
        }
        let rgba = |c: [f32; 3], a: f32| [c[0], c[1], c[2], a];
        let front = rgba(primary[0], faces[0].scene[3]);
        let front_secondary = rgba(secondary[0], 1.0);
        if self.two_side {
            LitColors {
                front,
                front_secondary,
                back: rgba(primary[1], faces[1].scene[3]),
                back_secondary: rgba(secondary[1], 1.0),
            }
        } else {
            LitColors { front, front_secondary, back: front, back_secondary: front_secondary }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::enums::{GL_DIFFUSE, GL_EMISSION};

    const IDENTITY: [f32; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];

    fn state() -> LightingState {
        let mut s = LightingState { enabled: true, ..Default::default() };
        s.lights[0] = true;
        s
    }

    fn close(a: [f32; 4], b: [f32; 4]) -> bool {
        a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-6)
    }

    #[test]
    fn default_light_on_a_facing_normal_is_ambient_plus_diffuse() {
        let mut l = Lighting::new(&state(), IDENTITY, NormalScaling::None);
        let c = l.shade([0.0, 0.0, -5.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        // 0.2 · 0.2 scene ambient + 0.8 diffuse (light 0 is white, at +z).
        assert!(close(c.front, [0.84, 0.84, 0.84, 1.0]), "{:?}", c.front);
        // Facing away: ambient only.
        let c = l.shade([0.0, 0.0, -5.0, 1.0], [0.0, 0.0, -1.0], [1.0; 4]);
        assert!(close(c.front, [0.04, 0.04, 0.04, 1.0]), "{:?}", c.front);
    }

    #[test]
    fn attenuation_spotlight_and_specular_on_known_values() {
        let mut s = state();
        s.materials[0] = Material {
            ambient: [0.0, 0.0, 0.0, 1.0],
            diffuse: [0.5, 0.5, 0.5, 0.25],
            specular: [1.0, 1.0, 1.0, 1.0],
            emission: [0.0, 0.0, 0.1, 1.0],
            shininess: 2.0,
            ..Default::default()
        };
        s.model_ambient = [0.0; 4];
        s.color_control = GL_SEPARATE_SPECULAR_COLOR;
        s.light[0].position = [0.0, 0.0, 0.0, 1.0];
        s.light[0].attenuation = [1.0, 0.5, 0.0];
        s.light[0].spot_cutoff = 45.0;
        s.light[0].spot_exponent = 2.0;
        s.local_viewer = true;
        let mut l = Lighting::new(&s, IDENTITY, NormalScaling::None);
        // The vertex 2 below the light (at the eye): L = +z, distance 2, attenuation
        // 1/(1 + 1) = 0.5, spot cos = 1. Local viewer: V = +z, H = +z; N·L = N·H = 1.
        let c = l.shade([0.0, 0.0, -2.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        assert!(close(c.front, [0.25, 0.25, 0.35, 0.25]), "{:?}", c.front);
        assert!(close(c.front_secondary, [0.5, 0.5, 0.5, 1.0]), "{:?}", c.front_secondary);
        // Tilted normal (60° from L): N·L = 0.5, H = L so N·H = 0.5, specular 0.25.
        let c = l.shade([0.0, 0.0, -2.0, 1.0], [0.75f32.sqrt(), 0.0, 0.5], [1.0; 4]);
        assert!(close(c.front, [0.125, 0.125, 0.225, 0.25]), "{:?}", c.front);
        assert!(close(c.front_secondary, [0.125, 0.125, 0.125, 1.0]), "{:?}", c.front_secondary);
        // Outside the 45° cone: nothing from the light.
        let c = l.shade([3.0, 0.0, -2.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        assert!(close(c.front, [0.0, 0.0, 0.1, 0.25]), "{:?}", c.front);
        // Spot exponent: 30° off axis, cos² = 0.75 inside the cone.
        let x = 2.0 * (30.0f32).to_radians().tan();
        let c = l.shade([x, 0.0, -2.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        let dist = (x * x + 4.0).sqrt();
        let expect = 0.75 / (1.0 + 0.5 * dist) * (2.0 / dist) * 0.5;
        assert!((c.front[0] - expect).abs() < 1e-6, "{} vs {expect}", c.front[0]);
    }

    #[test]
    fn two_sided_back_faces_use_the_back_material_and_negated_normal() {
        let mut s = state();
        s.two_side = true;
        s.materials[1].diffuse = [0.0, 1.0, 0.0, 0.5];
        s.materials[1].ambient = [0.0; 4];
        let mut l = Lighting::new(&s, IDENTITY, NormalScaling::None);
        let c = l.shade([0.0, 0.0, -1.0, 1.0], [0.0, 0.0, -1.0], [1.0; 4]);
        assert!(close(c.back, [0.0, 1.0, 0.0, 0.5]), "{:?}", c.back);
        assert!(close(c.front, [0.04, 0.04, 0.04, 1.0]), "{:?}", c.front);
    }

    #[test]
    fn pow_is_llvmpipe_s_approximation() {
        assert_eq!(pow(0.0, 5.0), 0.0);
        assert_eq!(pow(1.0, 37.0), 1.0);
        assert_eq!(pow(0.3, 0.0), 1.0);
        assert_eq!(pow(2.0, 3.0), 8.0);
        for (x, y) in [(0.5f32, 13.0f32), (0.9, 128.0), (0.123, 2.5), (0.99, 0.3)] {
            let (got, exact) = (pow(x, y), x.powf(y));
            assert!(((got - exact) / exact).abs() < 1e-5, "{x}^{y}: {got} vs {exact}");
        }
        // Not powf: the polynomials round differently somewhere in [0.5, 1).
        assert!((0..1000).any(|i| {
            let x = 0.5 + i as f32 / 2000.0;
            pow(x, 20.0) != x.powf(20.0)
        }));
        assert!(pow(-0.5, 2.0).is_nan());
    }

    #[test]
    fn normals_follow_the_inverse_transpose_and_scaling() {
        // Modelview scale(2, 2, 2): the inverse halves normals.
        let mut inverse = IDENTITY;
        (inverse[0], inverse[5], inverse[10]) = (0.5, 0.5, 0.5);
        let l = Lighting::new(&state(), inverse, NormalScaling::None);
        assert_eq!(l.eye_normal([0.0, 0.0, 1.0]), [0.0, 0.0, 0.5]);
        let l = Lighting::new(&state(), inverse, NormalScaling::Normalize);
        assert_eq!(l.eye_normal([0.0, 0.0, 3.0]), [0.0, 0.0, 1.0]);
        let l = Lighting::new(&state(), inverse, NormalScaling::Rescale(2.0));
        assert_eq!(l.eye_normal([0.0, 0.0, 1.0]), [0.0, 0.0, 1.0]);
        // Non-uniform scale(1, 2, 1): the normal (1, 1, 0) becomes (1, 0.5, 0).
        let mut inverse = IDENTITY;
        inverse[5] = 0.5;
        let l = Lighting::new(&state(), inverse, NormalScaling::None);
        assert_eq!(l.eye_normal([1.0, 1.0, 0.0]), [1.0, 0.5, 0.0]);
    }

    #[test]
    fn color_material_replaces_the_tracked_parameters() {
        let mut s = state();
        s.color_material = true;
        s.color_material_mode = GL_DIFFUSE;
        s.color_material_face = GL_FRONT;
        s.model_ambient = [0.0; 4];
        let mut l = Lighting::new(&s, IDENTITY, NormalScaling::None);
        let c = l.shade([0.0, 0.0, -1.0, 1.0], [0.0, 0.0, 1.0], [1.0, 0.5, 0.0, 0.75]);
        assert!(close(c.front, [1.0, 0.5, 0.0, 0.75]), "{:?}", c.front);
        s.color_material_mode = GL_EMISSION;
        let mut l = Lighting::new(&s, IDENTITY, NormalScaling::None);
        let c = l.shade([0.0, 0.0, -1.0, 1.0], [0.0, 0.0, -1.0], [0.25, 0.5, 0.0, 0.75]);
        assert!(close(c.front, [0.25, 0.5, 0.0, 1.0]), "{:?}", c.front);
    }
}
