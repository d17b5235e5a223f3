//! The geometry of selection mode: which primitives of a draw survive clipping (to the view
//! volume and the user planes) and culling, and the window depths of what remains, handed to
//! the hit record (`context::selection`). Nothing is rasterized.
use super::{Context, Geometry};
use crate::api::enums::*;
use crate::api::types::GLenum;
use crate::vertex::assembly::{assemble, Primitive, QuadSplit};
use crate::vertex::clip::ClipVertex;
use crate::vertex::Vertex;

impl Context {
    /// glRenderMode(GL_SELECT)'s draw: updates the hit flag and depth range.
    pub(super) fn select_vertices(&mut self, mode: GLenum, vertices: &[Vertex]) {
        if self.selection.mode != GL_SELECT || vertices.is_empty() {
            return;
        }
        let (depth_bits, height) =
            self.with_framebuffer(|fb| (fb.config().depth_stencil.depth_bits(), fb.height())).unwrap_or((24, 1));
        self.matrices.validate();
        let clip_vertices = self.transform(vertices, true);
        let g = self.geometry(depth_bits, height);
        let planes = &g.line_planes;
        let outcodes: Vec<u32> = clip_vertices.iter().map(|v| planes.outcode(v)).collect();
        let first_vertex = self.state.lighting.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
        let mut depths: Vec<f32> = Vec::new();
        let (mut poly, mut scratch) = (Vec::new(), Vec::new());
        let window_z = |v: &ClipVertex| g.viewport.window(v).z;
        assemble(
            mode,
            clip_vertices.len() as u32,
            first_vertex,
            QuadSplit::FirstDiagonal,
            |primitive| match primitive {
                Primitive::Point(i) => {
                    if outcodes[i as usize] == 0 {
                        depths.push(window_z(&clip_vertices[i as usize]));
                    }
                }
                Primitive::Line { v: [a, b], .. } => {
                    let (a, b) = (a as usize, b as usize);
                    if let Some((ca, cb)) =
                        planes.clip_line(&clip_vertices[a], &clip_vertices[b], outcodes[a] | outcodes[b])
                    {
                        depths.extend([window_z(&ca), window_z(&cb)]);
                    }
                }
                Primitive::Triangle { v, .. } => {
                    let [a, b, c] = v.map(|i| i as usize);
                    if outcodes[a] & outcodes[b] & outcodes[c] != 0 || culled(&g, [a, b, c].map(|i| &clip_vertices[i]))
                    {
                        return;
                    }
                    poly.clear();
                    poly.extend([clip_vertices[a], clip_vertices[b], clip_vertices[c]]);
                    planes.clip_polygon(&mut poly, &mut scratch, outcodes[a] | outcodes[b] | outcodes[c]);
                    if poly.len() >= 3 {
                        depths.extend(poly.iter().map(window_z));
                    }
                }
            },
        );
        for z in depths {
            self.selection.hit(z);
        }
    }
}

/// Whether culling removes the triangle `v` (facing from its window-space area; a triangle
/// of zero area is removed too, as the rasterizer does).
fn culled(g: &Geometry, v: [&ClipVertex; 3]) -> bool {
    let w = v.map(|c| g.viewport.window(c));
    let det = (w[0].x - w[2].x) * (w[1].y - w[2].y) - (w[0].y - w[2].y) * (w[1].x - w[2].x);
    if det == 0.0 || !det.is_finite() {
        return true;
    }
    let front = (det > 0.0) == g.front_ccw;
    match g.cull {
        Some(GL_FRONT_AND_BACK) => true,
        Some(GL_FRONT) => front,
        Some(GL_BACK) => !front,
        _ => false,
    }
}
