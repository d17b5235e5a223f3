//! The geometry of selection and feedback modes: which primitives of a draw survive
//! clipping (to the view volume and the user planes) and culling, and the window depths of
//! what remains, handed to the hit record, or reported as feedback tokens
//! (`context::selection`). Nothing is rasterized. Transformation, clipping, facing and the
//! viewport transform are `crate::vertex`'s, on the same snapshot a rendered draw takes.
use super::super::Context;
use crate::context::raster_pos::ShaderOutputs;
use crate::context::selection::FeedbackVertex;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::vertex::assembly::{assemble, Primitive, QuadSplit};
use crate::vertex::clip::ClipVertex;
use crate::vertex::cull::{culls, faces_front};
use crate::vertex::geometry::Geometry;
use crate::vertex::Vertex;

impl Context {
    /// glRenderMode(GL_SELECT)'s draw: updates the hit flag and depth range.
    pub(super) fn select_vertices(&mut self, mode: GLenum, vertices: &[Vertex]) {
        let feedback = self.selection.mode == GL_FEEDBACK;
        if vertices.is_empty() || !(feedback || self.selection.mode == GL_SELECT) {
            return;
        }
        let (depth_bits, height) = self
            .framebuffer_shape(true)
            .map(|(_, height, config)| (config.depth_stencil.depth_bits(), height))
            .unwrap_or((24, 1));
        self.matrices.validate();
        let executable = self.program_in_use.executable().cloned().filter(|e| e.vertex_program.is_some());
        let clip_vertices = match &executable {
            // A GLSL vertex shader's outputs, the current color and texture coordinates for
            // those it does not write (Mesa 22's feedback stage).
            Some(executable) => {
                let stage = self.vertex_shader_stage(executable, self.draw_config().color.is_float());
                let rows = &self.vertex_input.generic_rows;
                let mut out = stage.run(vertices, rows, &self.state.current.generic, <[ClipVertex]>::to_vec);
                let written = ShaderOutputs::of(executable);
                let current = &self.state.current;
                for v in &mut out {
                    if !written.color {
                        v.color = current.color;
                    }
                    if !written.tex_coords[0] {
                        v.tex_coords[0] = current.tex_coords[0];
                    }
                }
                out
            }
            None => self.transform_units(vertices, true, &self.tex_coord_units()),
        };
        let g = self.geometry(depth_bits, height);
        let planes = &g.line_planes;
        let outcodes: Vec<u32> = clip_vertices.iter().map(|v| planes.outcode(v)).collect();
        let first_vertex = self.state.lighting.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
        // The primitives that remain: a token and its clipped vertices.
        let mut kept: Vec<(GLenum, Vec<ClipVertex>)> = Vec::new();
        let (mut poly, mut scratch) = (Vec::new(), Vec::new());
        assemble(
            mode,
            clip_vertices.len() as u32,
            first_vertex,
            QuadSplit::SecondDiagonal,
            |primitive| match primitive {
                Primitive::Point(i) => {
                    if outcodes[i as usize] == 0 {
                        kept.push((GL_POINT_TOKEN, vec![clip_vertices[i as usize]]));
                    }
                }
                Primitive::Line { v: [a, b], .. } => {
                    let (a, b) = (a as usize, b as usize);
                    // GL 2.1 section 5.3 marks a segment that restarts the stipple with
                    // GL_LINE_RESET_TOKEN; Mesa 22 reports every segment as GL_LINE_TOKEN, and
                    // programs (piglit's rendermode-feedback) expect that.
                    let token = GL_LINE_TOKEN;
                    if let Some((ca, cb)) =
                        planes.clip_line(&clip_vertices[a], &clip_vertices[b], outcodes[a] | outcodes[b])
                    {
                        kept.push((token, vec![ca, cb]));
                    }
                }
                Primitive::Triangle { v, provoking, .. } => {
                    // Mesa's order: each triangle rotated so that its provoking vertex comes last
                    // (first under the first-vertex convention); a clipped triangle's polygon as a
                    // fan around its first vertex, placed the same way.
                    let mut v = v;
                    while v[if first_vertex { 0 } else { 2 }] != provoking {
                        v.rotate_left(1);
                    }
                    let [a, b, c] = v.map(|i| i as usize);
                    if outcodes[a] & outcodes[b] & outcodes[c] != 0 || culled(&g, [a, b, c].map(|i| &clip_vertices[i]))
                    {
                        return;
                    }
                    let mask = outcodes[a] | outcodes[b] | outcodes[c];
                    if mask == 0 {
                        kept.push((GL_POLYGON_TOKEN, vec![clip_vertices[a], clip_vertices[b], clip_vertices[c]]));
                        return;
                    }
                    poly.clear();
                    poly.extend([clip_vertices[a], clip_vertices[b], clip_vertices[c]]);
                    planes.clip_polygon(&mut poly, &mut scratch, mask);
                    for i in 1..poly.len().saturating_sub(1) {
                        let fan = if first_vertex {
                            [poly[0], poly[i], poly[i + 1]]
                        } else {
                            [poly[i], poly[i + 1], poly[0]]
                        };
                        kept.push((GL_POLYGON_TOKEN, fan.to_vec()));
                    }
                }
            },
        );
        for (token, clipped) in kept {
            if feedback {
                let vertices: Vec<FeedbackVertex> = clipped
                    .iter()
                    .map(|v| {
                        let w = g.viewport.window(v);
                        FeedbackVertex { window: [w.x, w.y, w.z, v.clip[3]], color: v.color, tex: v.tex_coords[0] }
                    })
                    .collect();
                let count = (token == GL_POLYGON_TOKEN).then_some(vertices.len());
                self.feedback_token(token, count, &vertices);
            } else {
                for v in &clipped {
                    self.selection.hit(g.viewport.window(v).z);
                }
            }
        }
    }
}

/// Whether culling removes the triangle `v` (facing from its window-space area). A
/// triangle of zero area is reported like any other unless culling is enabled, which then
/// removes it whatever face it culls, as Mesa's selection and feedback do (piglit's
/// rendermode-feedback draws three collinear vertices); one whose area is not a number
/// is always removed.
fn culled(g: &Geometry, v: [&ClipVertex; 3]) -> bool {
    let w = v.map(|c| g.viewport.window(c));
    let det = (w[0].x - w[2].x) * (w[1].y - w[2].y) - (w[0].y - w[2].y) * (w[1].x - w[2].x);
    if !det.is_finite() {
        return true;
    }
    if det == 0.0 {
        return g.cull.is_some();
    }
    culls(g.cull, faces_front(g.front_ccw, det))
}
