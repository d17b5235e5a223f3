//! The per-vertex stage of a draw: object coordinates to eye and clip coordinates, the fog
//! coordinate, texture coordinates (texgen), colors clamped and, when lighting is on, the
//! lit colors (the lighting pass dispatched here, evaluated in [`super::lighting`]).
//!
//! Its input is a [`Transform`] that `context` snapshots at the draw: the matrices by value
//! (as Mesa's validated products, computed once per draw) and the lighting state and
//! glMaterial marks by reference, so nothing per light or per vertex is copied.
use super::clip::ClipVertex;
use super::lighting::{Lighting, LightingState, Material, NormalScaling};
use super::texgen::TexGen;
use super::Vertex;
use glam::{Mat4, Vec4};

/// Where the fog coordinate of a vertex comes from (GL_FOG_COORD_SRC and
/// GL_FOG_DISTANCE_MODE_NV).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FogSource {
    /// glFogCoord's value (GL_FOG_COORD).
    Attribute,
    /// The eye distance (GL_EYE_RADIAL_NV).
    Radial,
    /// The signed eye z (GL_EYE_PLANE).
    Plane,
    /// |eye z| (GL_EYE_PLANE_ABSOLUTE_NV, the default).
    PlaneAbsolute,
}

/// The lighting pass of a draw (GL_LIGHTING on).
pub struct LightingInput<'a> {
    pub state: &'a LightingState,
    /// The inverse modelview, column-major.
    pub modelview_inverse: [f32; 16],
    pub normals: NormalScaling,
    /// glMaterial between glBegin and glEnd: from which vertex on each front and back
    /// material applies.
    pub material_marks: &'a [(usize, [Material; 2])],
}

/// What the per-vertex stage of a draw reads.
pub struct Transform<'a> {
    pub modelview: Mat4,
    /// Projection × modelview as Mesa computes it.
    pub model_project: Mat4,
    /// Colors are clamped to [0, 1] (GL_CLAMP_VERTEX_COLOR).
    pub clamp_color: bool,
    /// The fog coordinate's source when GL_FOG is on (`None`: the attribute passes through).
    pub fog: Option<FogSource>,
    pub texgen: TexGen<'a>,
    pub lighting: Option<LightingInput<'a>>,
}

/// Vertices to clip space, with their eye coordinates, fog and texture coordinates, and
/// clamped (or lit) colors.
pub fn transform(t: &Transform, vertices: &[Vertex]) -> Vec<ClipVertex> {
    let (modelview, mvp) = (t.modelview, t.model_project);
    let clamp = t.clamp_color;
    let clamp4 = |c: [f32; 4]| if clamp { c.map(|x| if x > 0.0 { x.min(1.0) } else { 0.0 }) } else { c };
    // The fog coordinate of each vertex, interpolated to the fragments: Mesa's
    // fixed-function vertex program computes the eye distance per vertex too. The fog
    // factor is per fragment whatever GL_FOG_HINT says: Mesa 22 draws identical images
    // under GL_NICEST and GL_FASTEST (capi fragment_ops_fog).
    let fog_coord = |v: &Vertex, eye: Vec4| match t.fog {
        None | Some(FogSource::Attribute) => v.fog_coord,
        Some(FogSource::Radial) => eye.truncate().length(),
        Some(FogSource::Plane) => eye.z,
        Some(FogSource::PlaneAbsolute) => eye.z.abs(),
    };
    let texgen = &t.texgen;
    let mut out: Vec<ClipVertex> = vertices
        .iter()
        .map(|v| {
            let p = Vec4::from_array(v.position);
            let eye = modelview * p;
            ClipVertex {
                clip: (mvp * p).to_array(),
                eye: eye.to_array(),
                color: clamp4(v.color),
                secondary_color: clamp4(v.secondary_color),
                back_colors: [[0.0; 4]; 2],
                tex_coords: if texgen.units.is_empty() { v.tex_coords } else { texgen.tex_coords(v, eye) },
                fog_coord: fog_coord(v, eye),
                edge_flag: v.edge_flag,
            }
        })
        .collect();
    // Lighting is a pass of its own: unlit draws do not see it.
    if let Some(lighting) = &t.lighting {
        light_vertices(lighting, vertices, &mut out, &clamp4);
    }
    out
}

/// Replaces the colors of `out` by the lit colors of `vertices` (GL 2.1 section 2.14.1),
/// the back-face colors too under two-sided lighting.
fn light_vertices(
    input: &LightingInput,
    vertices: &[Vertex],
    out: &mut [ClipVertex],
    clamp4: &dyn Fn([f32; 4]) -> [f32; 4],
) {
    let mut lighting = Lighting::new(input.state, input.modelview_inverse, input.normals);
    // glMaterial between glBegin and glEnd: each mark applies from its vertex on.
    let marks = input.material_marks;
    let mut next_mark = 0;
    for (i, (v, c)) in vertices.iter().zip(out.iter_mut()).enumerate() {
        while next_mark < marks.len() && marks[next_mark].0 <= i {
            lighting.set_materials(&marks[next_mark].1);
            next_mark += 1;
        }
        let lit = lighting.shade(c.eye, v.normal, v.color);
        c.color = clamp4(lit.front);
        c.secondary_color = clamp4(lit.front_secondary);
        c.back_colors = [clamp4(lit.back), clamp4(lit.back_secondary)];
    }
}
