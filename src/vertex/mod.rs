//! Vertex processing: everything between the vertices a draw delivers and the primitives
//! set up for rasterization — vertex input (immediate mode, client arrays, buffer objects),
//! transformation, lighting, texgen and the fog coordinate, primitive assembly, clipping,
//! the polygon modes, line stipple, culling, polygon offset, point size and the viewport
//! transform.
//!
//! This room works on typed inputs, never on the context: `context` validates a draw,
//! snapshots what the vertex stage reads into a [`transform::Transform`] (matrices by value,
//! lighting state by reference) and a [`geometry::Geometry`] (the per-draw constants of
//! everything after transformation), and hands them over with the vertices and the scene to
//! bin into. The lighting state types are defined here ([`lighting`]) and stored by the
//! context as they are, so the lighting pass borrows them instead of copying a light set per
//! draw; everything else the snapshot holds is a handful of words computed once per draw.
//! Nothing here imports `context`, `api` or `winsys`.
//!
//! Every source of vertices produces the same [`Vertex`] records (generic attributes, which
//! only GLSL vertex shaders read, beside them: [`generic`]), so everything after vertex
//! input has one path: [`transform`] (or a GLSL vertex shader, [`glsl`]) makes clip-space
//! vertices, and
//! [`pipeline::draw`] assembles and clips them ([`assembly`], [`clip`]) and hands each
//! primitive to its setup: [`triangle`] (with [`cull`] and [`offset`]), [`line`], [`point`]
//! or, in the point and line polygon modes, [`outline`]; all of them map to window space
//! through [`viewport`].
//!
//! Points, lines and polygons drawn in GL_POINT or GL_LINE mode follow Mesa 22's llvmpipe
//! exactly (it is what programs are compared against), which pins down details GL leaves
//! open: they are clipped to the view volume (points by their centre), in llvmpipe's y-down
//! window space with its rounding (a fused multiply-add where its generated code has one);
//! line stipple cuts lines into dashes, one pixel step along the major axis per pattern
//! bit; polygon outlines come from Mesa's primitive decomposition, clipper (new vertices
//! interpolated from the end nearer the plane), culling, polygon offset (per vertex, units
//! scaled by twice the depth resolution) and edge order; quads keep their last vertex
//! provoking under either convention, as Mesa's (GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION
//! false). Known deviations, where Mesa contradicts the GL specification: a strip whose
//! first segment is clipped away entirely keeps the stipple counter of the previous draw in
//! Mesa (here it restarts); Mesa turns a 3-vertex triangle fan into GL_TRIANGLES, changing
//! its provoking vertex under GL_FIRST_VERTEX_CONVENTION (here it stays the second vertex);
//! and when front and back faces have different modes, Mesa applies the polygon offset of
//! the first triangle's mode to the whole draw (here each triangle gets its own mode's).
#![deny(unsafe_code)]

pub mod arrays;
pub mod assembly;
pub mod attribute;
pub mod bezier;
pub mod buffer_objects;
pub mod clip;
pub mod components;
pub mod cull;
pub mod generic;
pub mod geometry;
pub mod glsl;
pub mod immediate;
pub mod lighting;
pub mod line;
pub mod offset;
pub mod outline;
pub mod pipeline;
pub mod point;
pub mod program;
pub mod texgen;
pub mod transform;
pub mod triangle;
pub mod viewport;

use crate::gl::limits::MAX_TEXTURE_UNITS;

/// One vertex as a draw call delivers it: object-space position and every attribute the
/// fixed-function pipeline may use (unused ones keep the current values).
///
/// The layout is fixed, with every four-float attribute on a 16-byte boundary: the compiler's
/// own layout put the texture coordinates at byte 76, and immediate mode's copy of a vertex
/// then read 16-byte pieces that straddled two earlier stores, a store-forwarding stall that
/// was a third of a glVertex call.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(16))]
pub struct Vertex {
    /// Object coordinates (x, y, z, w).
    pub position: [f32; 4],
    pub color: [f32; 4],
    pub secondary_color: [f32; 4],
    pub tex_coords: [[f32; 4]; MAX_TEXTURE_UNITS],
    pub normal: [f32; 3],
    pub fog_coord: f32,
    /// Whether edges starting at this vertex are boundary edges (glEdgeFlag).
    pub edge_flag: bool,
    /// Where the vertex's generic attributes are, for GLSL vertex programs that read them:
    /// a row of the draw's [`generic::GenericRows`], or [`generic::CURRENT`] (the current
    /// values at the draw). It fills the record's padding: fixed-function draws pay nothing.
    pub generic: u32,
}

// The generic row index lives in the padding after the edge flag.
const _: () = assert!(std::mem::size_of::<Vertex>() == 144);
