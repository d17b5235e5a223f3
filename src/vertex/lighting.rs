//! Per-vertex lighting's state and per-draw constants: the GL lighting state as the context
//! stores it, and [`Lighting`], a draw's lighting compiled into the values the generated
//! vertex program reads as uniforms ([`super::program`], which evaluates the lighting
//! equation of GL 2.1 section 2.14.1 in eye coordinates, per vertex).
//!
//! [`Lighting::new`] compiles a draw's lighting state: the enabled lights only, with their
//! normalized directions, half vectors (infinite light and viewer), normalized spot
//! directions and cutoff cosines, and, per face, the scene color (emission + ambient × scene
//! ambient) and the products of material and light colors. These are the constants Mesa
//! computes on the CPU for its fixed-function vertex program (`ffvertex_prog.c`), with its C
//! expressions, in single precision, because llvmpipe's pictures are the reference; the
//! per-vertex arithmetic (and the one deliberate difference from Mesa, a zero shininess) is
//! described with the program.
//!
//! The GL lighting state ([`LightingState`], [`Light`], [`Material`]) is defined here and
//! stored by `context` as it is: a draw's lighting pass borrows it, so nothing is copied or
//! converted on the way to the per-draw constants.
use crate::gl::enums::*;
use crate::gl::limits::MAX_LIGHTS;
use crate::gl::types::GLenum;

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
}

pub(super) fn scale3(v: [f32; 3], s: f32) -> [f32; 3] {
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
pub(super) fn face_setup(m: &Material, model_ambient: [f32; 4], lights: &[LightSetup]) -> FaceSetup {
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
    }
}
