//! Texture coordinates of a vertex (glTexGen, then the texture matrix, GL 2.1 §2.11.4):
//! per-draw compiled generation modes, evaluated per vertex.
use super::Vertex;
use crate::gl::limits::MAX_TEXTURE_UNITS;
use glam::{Mat4, Vec3, Vec4};

/// Texture coordinate generation of one coordinate, compiled.
#[derive(Clone, Copy, Debug)]
pub enum Gen {
    Object([f32; 4]),
    Eye([f32; 4]),
    Sphere,
    Reflection,
    Normal,
}

/// Per-draw texture coordinate work of one enabled unit.
#[derive(Clone, Debug)]
pub struct TexCoordUnit {
    pub unit: usize,
    pub gen: [Option<Gen>; 4],
    /// Whether a coordinate is generated from the eye-space normal.
    pub needs_normal: bool,
    /// The texture matrix, unless the identity.
    pub matrix: Option<Mat4>,
}

/// The texture coordinate work of a draw: the units whose coordinates are transformed, and
/// what their generation modes read.
pub struct TexGen<'a> {
    pub units: &'a [TexCoordUnit],
    /// The inverse modelview (read only when a unit `needs_normal`).
    pub modelview_inverse: Mat4,
    /// GL_NORMALIZE and GL_RESCALE_NORMAL.
    pub normalize: bool,
    pub rescale_normal: bool,
}

impl TexGen<'_> {
    /// Applies texgen and the texture matrix of every enabled unit to a vertex's texture
    /// coordinates (object coordinates `v`, eye coordinates `eye`).
    #[inline]
    pub fn tex_coords(&self, v: &Vertex, eye: Vec4) -> [[f32; 4]; MAX_TEXTURE_UNITS] {
        let mut out = v.tex_coords;
        for u in self.units {
            let mut tc = v.tex_coords[u.unit];
            if u.gen.iter().any(|g| g.is_some()) {
                let normal = if u.needs_normal {
                    eye_normal(&self.modelview_inverse, v.normal, self.normalize, self.rescale_normal)
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
                                * (reflect.x * reflect.x
                                    + reflect.y * reflect.y
                                    + (reflect.z + 1.0) * (reflect.z + 1.0))
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
}

/// The eye-space normal of a vertex: the normal transformed by the inverse transpose of the
/// modelview's upper 3×3, then normalized (GL_NORMALIZE) or rescaled (GL_RESCALE_NORMAL).
pub fn eye_normal(modelview_inverse: &Mat4, normal: [f32; 3], normalize: bool, rescale: bool) -> Vec3 {
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
