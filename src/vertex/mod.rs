//! Vertex processing: the vertices a draw call delivers (immediate mode, client arrays,
//! buffer objects), their transformation to clip space, primitive assembly and clipping.
//!
//! Every source of vertices produces the same [`Vertex`] records, so everything after
//! vertex input has one path.

pub mod arrays;
pub mod bezier;
pub mod buffer_objects;
pub mod components;
pub mod immediate;
pub mod lighting;

use crate::gl::limits::MAX_TEXTURE_UNITS;

/// One vertex as a draw call delivers it: object-space position and every attribute the
/// fixed-function pipeline may use (unused ones keep the current values).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    /// Object coordinates (x, y, z, w).
    pub position: [f32; 4],
    pub color: [f32; 4],
    pub secondary_color: [f32; 4],
    pub normal: [f32; 3],
    pub tex_coords: [[f32; 4]; MAX_TEXTURE_UNITS],
    pub fog_coord: f32,
    /// Whether edges starting at this vertex are boundary edges (glEdgeFlag).
    pub edge_flag: bool,
}

pub mod assembly;
pub mod clip;
