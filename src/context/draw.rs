//! Drawing: where vertices from any source enter the geometry pipeline.
use super::Context;
use crate::api::types::GLenum;
use crate::vertex::Vertex;

impl Context {
    /// Draws `vertices` as primitives of `mode` (GL_POINTS … GL_POLYGON, already validated),
    /// with the current state. Vertex sources (glBegin/glEnd, glDrawArrays, …) call this.
    pub fn draw_vertices(&mut self, _mode: GLenum, _vertices: &[Vertex]) {
        // The geometry pipeline (transform, clip, setup, binning, tiles) lands here.
    }
}
