//! The reference the generated vertex programs are tested against, **not a runtime path**
//! (it is built for the tests only): the hand-written per-vertex code that the draws ran
//! before the fixed-function vertex program replaced it — the transform, texgen, the fog
//! coordinate, colour clamping and [`shade`], the lighting equation as llvmpipe evaluates
//! Mesa's program.
//!
//! Why this code and not a scalar f64 evaluation: what the programs must reproduce is
//! llvmpipe's single-precision bits (the capi tests compare lit colours bit for bit), which
//! depend on the order and rounding of every operation; an f64 evaluation could only bound
//! the error, and would not catch a generator that sums a dot product in the wrong order.
//! This code was checked against llvmpipe that way (capi lighting_float) for as long as it
//! was the runtime path, and it is written independently of the generator (plain Rust
//! arithmetic, glam's operators), so the two agreeing bit for bit is a real test.
use crate::gl::limits::MAX_TEXTURE_UNITS;
use crate::shader::math::{exp2, log2};
use crate::vertex::clip::FixedClipVertex as ClipVertex;
use crate::vertex::lighting::{face_setup, scale3, set_material_parameter, FaceSetup, Lighting, NormalScaling};
use crate::vertex::texgen::{Gen, TexGen};
use crate::vertex::transform::{FogSource, LightingInput, Transform};
use crate::vertex::Vertex;
use glam::{Mat4, Vec3, Vec4};

/// The program's DP3 as llvmpipe runs it: NIR lowers the reduction from the last
/// component, (z·z' + y·y') + x·x' (measured bit for bit in capi lighting_float).
fn dot3(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[2] * b[2] + a[1] * b[1] + a[0] * b[0]
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
                tex_coords: if texgen.units.is_empty() { v.tex_coords } else { tex_coords(texgen, v, eye) },
                fog_coord: fog_coord(v, eye),
                point_size: 0.0,
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
        let lit = shade(&lighting, c.eye, v.normal, v.color);
        c.color = clamp4(lit.front);
        c.secondary_color = clamp4(lit.front_secondary);
        c.back_colors = [clamp4(lit.back), clamp4(lit.back_secondary)];
    }
}

/// Applies texgen and the texture matrix of every enabled unit to a vertex's texture
/// coordinates (object coordinates `v`, eye coordinates `eye`).
fn tex_coords(texgen: &TexGen, v: &Vertex, eye: Vec4) -> [[f32; 4]; MAX_TEXTURE_UNITS] {
    let mut out = v.tex_coords;
    for u in texgen.units {
        let mut tc = v.tex_coords[u.unit];
        if u.gen.iter().any(|g| g.is_some()) {
            let normal = if u.needs_normal {
                texgen_eye_normal(&texgen.modelview_inverse, v.normal, texgen.normalize, texgen.rescale_normal)
            } else {
                Vec3::Z
            };
            let unit_eye = {
                let p = eye.truncate();
                let len = p.length();
                if len > 0.0 {
                    p / len
                } else {
                    p
                }
            };
            let reflect = unit_eye - 2.0 * normal * normal.dot(unit_eye);
            for (c, g) in u.gen.iter().enumerate() {
                let Some(g) = g else { continue };
                tc[c] = match *g {
                    Gen::Object(p) => (0..4).map(|i| p[i] * v.position[i]).sum(),
                    Gen::Eye(p) => (0..4).map(|i| p[i] * eye[i]).sum(),
                    Gen::Sphere => {
                        let m = 2.0
                            * (reflect.x * reflect.x + reflect.y * reflect.y + (reflect.z + 1.0) * (reflect.z + 1.0))
                                .sqrt();
                        let r = if c == 0 { reflect.x } else { reflect.y };
                        if m > 0.0 {
                            r / m + 0.5
                        } else {
                            0.5
                        }
                    }
                    Gen::Reflection => reflect[c],
                    Gen::Normal => normal[c],
                };
            }
        }
        if let Some(m) = &u.matrix {
            tc = (*m * Vec4::from_array(tc)).to_array();
        }
        out[u.unit] = tc;
    }
    out
}

/// The eye-space normal of a vertex: the normal transformed by the inverse transpose of the
/// modelview's upper 3×3, then normalized (GL_NORMALIZE) or rescaled (GL_RESCALE_NORMAL).
fn texgen_eye_normal(modelview_inverse: &Mat4, normal: [f32; 3], normalize: bool, rescale: bool) -> Vec3 {
    let inv = modelview_inverse;
    let n = Vec3::from_array(normal);
    // n' = n · M⁻¹ (a row vector times the inverse): n dotted with the columns of M⁻¹.
    let cols = [inv.col(0).truncate(), inv.col(1).truncate(), inv.col(2).truncate()];
    let mut e = Vec3::new(n.dot(cols[0]), n.dot(cols[1]), n.dot(cols[2]));
    if normalize {
        let len = e.length();
        if len > 0.0 {
            e /= len;
        }
    } else if rescale {
        let row = Vec3::new(cols[0].z, cols[1].z, cols[2].z);
        let len = row.length();
        if len > 0.0 {
            e /= len;
        }
    }
    e
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

/// The program's normalization: v · (1/√(v·v)).
fn normalize(v: [f32; 3]) -> [f32; 3] {
    scale3(v, 1.0 / dot3(v, v).sqrt())
}

/// `a · b + c` per channel: a multiply and an add, as llvmpipe runs the program's
/// multiply-adds (its NIR options lower `ffma`).
fn mad3(a: f32, b: [f32; 3], c: [f32; 3]) -> [f32; 3] {
    [a * b[0] + c[0], a * b[1] + c[1], a * b[2] + c[2]]
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

/// The eye-space normal of an object-space `normal`, normalized or rescaled as enabled.
pub fn eye_normal(lighting: &Lighting, normal: [f32; 3]) -> [f32; 3] {
    let m = &lighting.inverse_modelview;
    // Component j is column j of the inverse (row j of its transpose) · normal.
    let n = [0, 1, 2].map(|j| dot3([m[4 * j], m[4 * j + 1], m[4 * j + 2]], normal));
    match lighting.normals {
        NormalScaling::None => n,
        NormalScaling::Normalize => normalize(n),
        NormalScaling::Rescale(s) => scale3(n, s),
    }
}

/// The lit colors of a vertex at `eye` (eye coordinates) with object-space `normal` and
/// vertex color `color` (used by GL_COLOR_MATERIAL). Not clamped.
pub fn shade(lighting: &Lighting, eye: [f32; 4], normal: [f32; 3], color: [f32; 4]) -> LitColors {
    let tracked = tracked_faces(lighting, color);
    let faces = tracked.as_ref().unwrap_or(&lighting.faces);
    let n = eye_normal(lighting, normal);
    let eye3 = [eye[0], eye[1], eye[2]];
    let sides = if lighting.two_side { 2 } else { 1 };
    let mut primary = [[0.0f32; 3]; 2];
    let mut secondary = [[0.0f32; 3]; 2];
    for f in 0..sides {
        primary[f] = [faces[f].scene[0], faces[f].scene[1], faces[f].scene[2]];
    }
    let needs_half = faces[0].shininess != 0.0 || (lighting.two_side && faces[1].shininess != 0.0);
    let eye_dir = (lighting.local_viewer && needs_half).then(|| normalize(eye3));
    for (index, light) in lighting.lights.iter().enumerate() {
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
            if lighting.separate_specular {
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
    if lighting.two_side {
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

/// Under GL_COLOR_MATERIAL, the face constants of the materials with the tracked
/// parameters replaced by `color` (the runtime path computes them in the program).
fn tracked_faces(lighting: &Lighting, color: [f32; 4]) -> Option<[FaceSetup; 2]> {
    let tracking = lighting.tracking?;
    Some(std::array::from_fn(|f| {
        if tracking.face[f] {
            let mut m = lighting.materials[f];
            set_material_parameter(&mut m, tracking.mode, &color);
            face_setup(&m, lighting.model_ambient, &lighting.lights)
        } else {
            lighting.faces[f]
        }
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::enums::*;
    use crate::vertex::lighting::{LightingState, Material};

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
        let l = Lighting::new(&state(), IDENTITY, NormalScaling::None);
        let c = shade(&l, [0.0, 0.0, -5.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        // 0.2 · 0.2 scene ambient + 0.8 diffuse (light 0 is white, at +z).
        assert!(close(c.front, [0.84, 0.84, 0.84, 1.0]), "{:?}", c.front);
        // Facing away: ambient only.
        let c = shade(&l, [0.0, 0.0, -5.0, 1.0], [0.0, 0.0, -1.0], [1.0; 4]);
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
        let l = Lighting::new(&s, IDENTITY, NormalScaling::None);
        // The vertex 2 below the light (at the eye): L = +z, distance 2, attenuation
        // 1/(1 + 1) = 0.5, spot cos = 1. Local viewer: V = +z, H = +z; N·L = N·H = 1.
        let c = shade(&l, [0.0, 0.0, -2.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        assert!(close(c.front, [0.25, 0.25, 0.35, 0.25]), "{:?}", c.front);
        assert!(close(c.front_secondary, [0.5, 0.5, 0.5, 1.0]), "{:?}", c.front_secondary);
        // Tilted normal (60° from L): N·L = 0.5, H = L so N·H = 0.5, specular 0.25.
        let c = shade(&l, [0.0, 0.0, -2.0, 1.0], [0.75f32.sqrt(), 0.0, 0.5], [1.0; 4]);
        assert!(close(c.front, [0.125, 0.125, 0.225, 0.25]), "{:?}", c.front);
        assert!(close(c.front_secondary, [0.125, 0.125, 0.125, 1.0]), "{:?}", c.front_secondary);
        // Outside the 45° cone: nothing from the light.
        let c = shade(&l, [3.0, 0.0, -2.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
        assert!(close(c.front, [0.0, 0.0, 0.1, 0.25]), "{:?}", c.front);
        // Spot exponent: 30° off axis, cos² = 0.75 inside the cone.
        let x = 2.0 * (30.0f32).to_radians().tan();
        let c = shade(&l, [x, 0.0, -2.0, 1.0], [0.0, 0.0, 1.0], [1.0; 4]);
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
        let l = Lighting::new(&s, IDENTITY, NormalScaling::None);
        let c = shade(&l, [0.0, 0.0, -1.0, 1.0], [0.0, 0.0, -1.0], [1.0; 4]);
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
        assert_eq!(eye_normal(&l, [0.0, 0.0, 1.0]), [0.0, 0.0, 0.5]);
        let l = Lighting::new(&state(), inverse, NormalScaling::Normalize);
        assert_eq!(eye_normal(&l, [0.0, 0.0, 3.0]), [0.0, 0.0, 1.0]);
        let l = Lighting::new(&state(), inverse, NormalScaling::Rescale(2.0));
        assert_eq!(eye_normal(&l, [0.0, 0.0, 1.0]), [0.0, 0.0, 1.0]);
        // Non-uniform scale(1, 2, 1): the normal (1, 1, 0) becomes (1, 0.5, 0).
        let mut inverse = IDENTITY;
        inverse[5] = 0.5;
        let l = Lighting::new(&state(), inverse, NormalScaling::None);
        assert_eq!(eye_normal(&l, [1.0, 1.0, 0.0]), [1.0, 0.5, 0.0]);
    }

    #[test]
    fn color_material_replaces_the_tracked_parameters() {
        let mut s = state();
        s.color_material = true;
        s.color_material_mode = GL_DIFFUSE;
        s.color_material_face = GL_FRONT;
        s.model_ambient = [0.0; 4];
        let l = Lighting::new(&s, IDENTITY, NormalScaling::None);
        let c = shade(&l, [0.0, 0.0, -1.0, 1.0], [0.0, 0.0, 1.0], [1.0, 0.5, 0.0, 0.75]);
        assert!(close(c.front, [1.0, 0.5, 0.0, 0.75]), "{:?}", c.front);
        s.color_material_mode = GL_EMISSION;
        let l = Lighting::new(&s, IDENTITY, NormalScaling::None);
        let c = shade(&l, [0.0, 0.0, -1.0, 1.0], [0.0, 0.0, -1.0], [0.25, 0.5, 0.0, 0.75]);
        assert!(close(c.front, [0.25, 0.5, 0.0, 1.0]), "{:?}", c.front);
    }
}
