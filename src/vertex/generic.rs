//! The generic vertex attributes (glVertexAttrib, glVertexAttribPointer) of a draw's
//! vertices, kept beside the [`Vertex`] records rather than in them: only GLSL vertex
//! programs read them, and a record carrying sixteen more vectors would make every
//! fixed-function draw copy them.
//!
//! A vertex names its values by [`Vertex::generic`]: a row of [`GenericRows`] (all the
//! attributes, one vector each), or [`CURRENT`], the context's current values at the draw.
//! Rows are made only when the values differ per vertex: in glBegin/glEnd once
//! glVertexAttrib changes them there (a row per change between two glVertex calls), and in
//! an array draw with a GLSL vertex program that reads generic attributes (a row per
//! vertex). Fixed-function draws make none, and their vertices say [`CURRENT`] at no cost
//! (the index fills the record's padding).
use super::Vertex;
use crate::gl::limits::{MAX_TEXTURE_COORDS, MAX_TEXTURE_UNITS, MAX_VERTEX_ATTRIBS};

/// [`Vertex::generic`] of a vertex whose generic attributes are the current values.
pub const CURRENT: u32 = u32::MAX;

/// The slots of a row: the generic attributes, then the texture coordinate sets past the
/// fixed-function units (GL_MAX_TEXTURE_UNITS up to GL_MAX_TEXTURE_COORDS). Only a GLSL
/// vertex shader reads those sets (`gl_MultiTexCoord4..7`), so they travel here, beside the
/// records, rather than in [`Vertex::tex_coords`].
pub const SLOTS: usize = MAX_VERTEX_ATTRIBS + MAX_TEXTURE_COORDS - MAX_TEXTURE_UNITS;

/// The slot of texture coordinate set `set` (GL_MAX_TEXTURE_UNITS <= set <
/// GL_MAX_TEXTURE_COORDS).
#[inline]
pub const fn tex_coord_slot(set: usize) -> usize {
    MAX_VERTEX_ATTRIBS + set - MAX_TEXTURE_UNITS
}

/// The generic attributes of one vertex (attribute 0, the position, is in the vertex) and
/// its texture coordinate sets past the fixed-function units ([`SLOTS`]).
pub type GenericValues = [[f32; 4]; SLOTS];

/// The rows vertices of a draw name.
#[derive(Clone, Debug, Default)]
pub struct GenericRows {
    pub rows: Vec<GenericValues>,
}

impl GenericRows {
    /// The generic attributes of `vertex`, `current` being the current values.
    #[inline]
    pub fn of<'a>(&'a self, vertex: &Vertex, current: &'a GenericValues) -> &'a GenericValues {
        self.rows.get(vertex.generic as usize).unwrap_or(current)
    }

    /// Appends `values`; returns its row's index.
    pub fn push(&mut self, values: GenericValues) -> u32 {
        self.rows.push(values);
        (self.rows.len() - 1) as u32
    }

    pub fn clear(&mut self) {
        self.rows.clear();
    }
}
