//! Texture coordinates of a vertex (glTexGen, then the texture matrix, GL 2.1 §2.11.4): a
//! draw's generation modes, planes and texture matrices as `context` snapshots them, from
//! which the vertex program's key and uniforms are made ([`super::program`] evaluates them
//! per vertex).
use glam::Mat4;

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
