//! The point and line polygon modes (glPolygonMode): polygons decomposed into triangles in
//! Mesa 22's order, clipped as outlines, culled, offset per vertex, and drawn as their edges
//! or vertices.
use super::assembly::DrawPart;
use super::clip::{ClipPlanes, ClipVertex};
use super::cull::{culls, faces_front};
use super::geometry::Geometry;
use super::line::{emit_window_line, LineStipple};
use super::offset::{clamp_offset, depth_resolution};
use super::point::emit_window_point;
use super::triangle::{emit_shaded_triangle, FlatColors};
use crate::framebuffer::format::DepthEncoding;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::setup::jobs::line::LineVertex;
use crate::setup::jobs::triangle::WindowVertex;
use crate::setup::Scene;

/// A triangle of a polygon drawn in GL_POINT or GL_LINE mode: its vertices, which of its
/// edges v0→v1, v1→v2, v2→v0 are edges of the polygon, and whether it is the polygon's
/// first (the line stipple restarts there).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutlineTriangle {
    pub v: [u32; 3],
    pub edges: [bool; 3],
    pub first: bool,
}

/// Decomposes the polygons of `mode` into triangles for the point and line polygon modes,
/// in Mesa 22's order: the vertex order, the order of the outline's edges and where the
/// stipple restarts all follow its primitive decomposition (the provoking vertex stays
/// last, or first under GL_FIRST_VERTEX_CONVENTION; quads split along the diagonal that
/// keeps it a corner of both triangles).
pub fn decompose_outlines(
    mode: GLenum,
    count: u32,
    first_vertex: bool,
    part: DrawPart,
    mut emit: impl FnMut(OutlineTriangle),
) {
    let tri = |v: [u32; 3], edges: [bool; 3], first: bool| OutlineTriangle { v, edges, first };
    const ALL: [bool; 3] = [true; 3];
    match mode {
        GL_TRIANGLES => (0..count / 3).for_each(|i| emit(tri([3 * i, 3 * i + 1, 3 * i + 2], ALL, true))),
        GL_TRIANGLE_STRIP => {
            for i in 0..count.saturating_sub(2) {
                let v = match (i % 2 == 1, first_vertex) {
                    (false, _) => [i, i + 1, i + 2],
                    (true, false) => [i + 1, i, i + 2],
                    (true, true) => [i, i + 2, i + 1],
                };
                emit(tri(v, ALL, true));
            }
        }
        GL_TRIANGLE_FAN => {
            for i in 1..count.saturating_sub(1) {
                emit(tri(if first_vertex { [i, i + 1, 0] } else { [0, i, i + 1] }, ALL, true));
            }
        }
        GL_QUADS => {
            for q in 0..count / 4 {
                let [a, b, c, d] = [0, 1, 2, 3].map(|k| 4 * q + k);
                if first_vertex {
                    // Quads keep their last vertex provoking under either convention.
                    emit(tri([d, a, b], [true, true, false], true));
                    emit(tri([d, b, c], [false, true, true], false));
                } else {
                    emit(tri([a, b, d], [true, false, true], true));
                    emit(tri([b, c, d], [true, true, false], false));
                }
            }
        }
        GL_QUAD_STRIP => {
            for q in 0..count.saturating_sub(2) / 2 {
                // Quad q is a, b, d, c in polygon order.
                let [a, b, c, d] = [0, 1, 2, 3].map(|k| 2 * q + k);
                if first_vertex {
                    emit(tri([d, c, a], [true, true, false], true));
                    emit(tri([d, a, b], [false, true, true], false));
                } else {
                    emit(tri([c, a, d], [true, false, true], true));
                    emit(tri([a, b, d], [true, true, false], false));
                }
            }
        }
        GL_POLYGON if count >= 3 => {
            // A part of a long polygon repeats its first vertex: only the first part has the
            // polygon's first edge (and restarts the stipple), only the last its closing edge.
            for i in 0..count - 2 {
                let last = i + 3 == count && part.last;
                let first = i == 0 && part.first;
                if first_vertex {
                    emit(tri([0, i + 1, i + 2], [first, true, last], first));
                } else {
                    emit(tri([i + 1, i + 2, 0], [true, last, first], first));
                }
            }
        }
        _ => {}
    }
}

/// The point and line polygon modes: triangles of polygons are clipped to the view volume
/// (edges made by clipping are not polygon edges), culled, offset, and then drawn in their
/// face's mode as their polygon edges or vertices, following Mesa 22's pipeline (clip,
/// cull, offset, flat shading, unfilled, stipple).
pub struct Outline<'a> {
    pub scene: &'a mut Scene,
    pub state: u32,
    pub g: &'a Geometry,
    pub stipple: Option<LineStipple>,
}

impl Outline<'_> {
    /// One triangle of the decomposition, `codes` its vertices' outcodes.
    pub fn triangle<const N: usize>(
        &mut self,
        v: [&ClipVertex<N>; 3],
        codes: [u32; 3],
        t: OutlineTriangle,
        poly: &mut Vec<ClipVertex<N>>,
        scratch: &mut Vec<ClipVertex<N>>,
    ) {
        if codes[0] & codes[1] & codes[2] != 0 {
            return;
        }
        // An edge is drawn when the decomposition and the edge flag of its first vertex say so.
        let edges = std::array::from_fn(|i| t.edges[i] && v[i].edge_flag);
        let flat = self.g.flat.then(|| FlatColors::of(v[if self.g.first_vertex { 0 } else { 2 }]));
        let corner = |c: &ClipVertex<N>, fused: bool| {
            (self.g.viewport.window_down(c, fused), self.g.viewport.window(c), c.back_colors, self.g.point_size_of(c))
        };
        if codes[0] | codes[1] | codes[2] == 0 {
            let w = v.map(|c| corner(c, true));
            self.draw(w, edges, t.first, flat);
            return;
        }
        poly.clear();
        poly.extend((0..3).map(|i| ClipVertex { edge_flag: edges[i], ..*v[i] }));
        if !clip_outline(&self.g.line_planes, poly, scratch, codes[0] | codes[1] | codes[2]) {
            return;
        }
        let n = poly.len();
        if n < 3 {
            return;
        }
        // Vertices made by clipping get Mesa's C clipper's window mapping.
        let w: Vec<_> = poly.iter().map(|c| corner(c, v.iter().any(|o| o.clip == c.clip))).collect();
        let flags: Vec<bool> = poly.iter().map(|c| c.edge_flag).collect();
        // Mesa re-emits a clipped polygon as a fan around its first vertex, keeping the
        // provoking vertex first or last.
        for i in 2..n {
            let start = i == 2 && flags[0];
            let middle = flags[i - 1];
            let end = i == n - 1 && flags[i];
            if self.g.first_vertex {
                self.draw([w[0], w[i - 1], w[i]], [start, middle, end], i == 2, flat);
            } else {
                self.draw([w[i - 1], w[i], w[0]], [middle, end, start], i == 2, flat);
            }
        }
    }

    /// Culls, offsets and draws one (clipped) triangle in its face's mode; `w` holds each
    /// corner in y-down and in GL window coordinates.
    fn draw<const N: usize>(&mut self, w: [Corner<N>; 3], edges: [bool; 3], first: bool, flat: Option<FlatColors>) {
        let g = self.g;
        let mut l = w.map(|c| c.0);
        let (ex, ey, ez) = (l[0].x - l[2].x, l[0].y_down - l[2].y_down, l[0].z - l[2].z);
        let (fx, fy, fz) = (l[1].x - l[2].x, l[1].y_down - l[2].y_down, l[1].z - l[2].z);
        let det = ex * fy - ey * fx;
        if det == 0.0 || !det.is_finite() {
            return;
        }
        // y-down flips the orientation: counter-clockwise in GL has det < 0 here.
        let front = faces_front(g.front_ccw, -det);
        if culls(g.cull, front) {
            return;
        }
        let mode = if front { g.mode_front } else { g.mode_back };
        let offset = match mode {
            GL_LINE => g.offset_line,
            GL_POINT => g.offset_point,
            _ => {
                if let Some(s) = self.stipple.as_mut() {
                    s.counter = 0;
                }
                emit_shaded_triangle(self.scene, self.state, g, &w.map(|c| c.1), w.map(|c| c.2), flat);
                return;
            }
        };
        if let Some((factor, units)) = offset {
            // Mesa's offset stage: the larger depth slope of the triangle, applied per vertex.
            let inv_det = 1.0 / det;
            let dzdx = ((ey * fz - ez * fy) * inv_det).abs();
            let dzdy = ((ez * fx - ex * fz) * inv_det).abs();
            // On a float depth buffer r depends on the primitive (unorm units came scaled).
            let units = match g.depth {
                DepthEncoding::Float => units * depth_resolution(g.depth, l.iter().map(|c| c.z)),
                DepthEncoding::Unorm(_) => units,
            };
            let z_offset = clamp_offset(units + dzdx.max(dzdy) * factor, g.offset_clamp);
            for c in &mut l {
                c.z = (c.z + z_offset).clamp(0.0, 1.0);
            }
        }
        let use_back = g.two_side && !front;
        if use_back {
            for (c, corner) in l.iter_mut().zip(&w) {
                (c.color, c.secondary_color) = (corner.2[0], corner.2[1]);
            }
        }
        let flat = flat.map(|f| if use_back { f.back } else { f.front });
        if let Some([color, secondary]) = flat {
            for c in &mut l {
                (c.color, c.secondary_color) = (color, secondary);
            }
        }
        let flat = flat.map(|f| f[0]);
        if mode == GL_LINE {
            if first {
                if let Some(s) = self.stipple.as_mut() {
                    s.counter = 0;
                }
            }
            // Mesa draws the edge into v0 first: v2→v0, v0→v1, v1→v2.
            for k in [2, 0, 1] {
                if edges[k] {
                    emit_window_line(self.scene, self.state, g, l[k], l[(k + 1) % 3], flat, self.stipple.as_mut());
                }
            }
        } else {
            for k in 0..3 {
                if edges[k] {
                    if let Some(s) = self.stipple.as_mut() {
                        s.counter = 0;
                    }
                    emit_window_point(self.scene, self.state, g, &l[k], w[k].3);
                }
            }
        }
    }
}

/// A corner of an outlined triangle: in llvmpipe's y-down window space, in GL window
/// coordinates, its back-face colors and its point size (GL_POINT polygon mode).
type Corner<const N: usize> = (LineVertex<N>, WindowVertex<N>, [[f32; 4]; 2], f32);

/// Clips the polygon `poly` (each vertex's `edge_flag` telling whether the edge it starts
/// is drawn) against the planes in `mask` as Mesa's clipper does for polygons it draws as
/// outlines: plane by plane, each new vertex interpolated from the end of the cut edge
/// nearer to the plane, edges along a view-volume plane not drawn. `false` when a
/// distance is NaN (the polygon is dropped).
pub fn clip_outline<const N: usize>(
    planes: &ClipPlanes,
    poly: &mut Vec<ClipVertex<N>>,
    scratch: &mut Vec<ClipVertex<N>>,
    mask: u32,
) -> bool {
    let user_planes = planes.count() - planes.user.len();
    for plane in 0..planes.count() {
        if mask & (1 << plane) == 0 || poly.len() < 3 {
            continue;
        }
        scratch.clear();
        let n = poly.len();
        let mut prev = poly[0];
        let mut d_prev = planes.distance(plane, &prev);
        for i in 1..=n {
            let cur = poly[i % n];
            let d = planes.distance(plane, &cur);
            if d.is_nan() || d_prev.is_nan() {
                return false;
            }
            if d_prev >= 0.0 {
                scratch.push(prev);
            }
            if (d_prev >= 0.0) == (d < 0.0) {
                // Interpolate from the end nearer to the plane (the inside one on a tie),
                // so that both directions of an edge give the same vertex.
                let denom = d - d_prev;
                let (from, to, t) = if d < 0.0 {
                    if -d < d_prev {
                        (&cur, &prev, d / denom)
                    } else {
                        (&prev, &cur, -d_prev / denom)
                    }
                } else if -d_prev < d {
                    (&prev, &cur, -d_prev / denom)
                } else {
                    (&cur, &prev, d / denom)
                };
                let mix = |p: [f32; 4], q: [f32; 4]| std::array::from_fn(|k| p[k] + t * (q[k] - p[k]));
                // Leaving the volume: the new edge runs along the plane, drawn only for user
                // clip planes (as NVIDIA does, which Mesa copies). Coming back: the new
                // vertex starts the rest of the cut edge.
                let edge_flag = if d < 0.0 { plane >= user_planes } else { prev.edge_flag };
                scratch.push(ClipVertex {
                    clip: mix(from.clip, to.clip),
                    color: mix(from.color, to.color),
                    secondary_color: mix(from.secondary_color, to.secondary_color),
                    back_colors: [0, 1].map(|k| mix(from.back_colors[k], to.back_colors[k])),
                    tex_coords: std::array::from_fn(|u| mix(from.tex_coords[u], to.tex_coords[u])),
                    fog_coord: from.fog_coord + t * (to.fog_coord - from.fog_coord),
                    edge_flag,
                    ..cur
                });
            }
            prev = cur;
            d_prev = d;
        }
        std::mem::swap(poly, scratch);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outline_decomposition_keeps_the_provoking_vertex_and_the_outline() {
        let collect = |mode, count, first| {
            let mut out = Vec::new();
            decompose_outlines(mode, count, first, DrawPart::WHOLE, |t| out.push(t));
            out
        };
        let t = |v: [u32; 3], edges: [bool; 3], first: bool| OutlineTriangle { v, edges, first };
        // Quads split along the diagonal that keeps the last vertex a corner of both halves.
        assert_eq!(
            collect(GL_QUADS, 4, false),
            [t([0, 1, 3], [true, false, true], true), t([1, 2, 3], [true, true, false], false)]
        );
        assert_eq!(
            collect(GL_QUADS, 4, true),
            [t([3, 0, 1], [true, true, false], true), t([3, 1, 2], [false, true, true], false)]
        );
        // A polygon's outline is its edges in order, around vertex 0.
        assert_eq!(
            collect(GL_POLYGON, 5, false),
            [
                t([1, 2, 0], [true, false, true], true),
                t([2, 3, 0], [true, false, false], false),
                t([3, 4, 0], [true, true, false], false),
            ]
        );
        let outline = |tris: &[OutlineTriangle]| {
            let mut edges: Vec<(u32, u32)> = tris
                .iter()
                .flat_map(|t| (0..3).filter(move |&k| t.edges[k]).map(move |k| (t.v[k], t.v[(k + 1) % 3])))
                .map(|(a, b)| (a.min(b), a.max(b)))
                .collect();
            edges.sort_unstable();
            edges
        };
        for first in [false, true] {
            // A polygon's outline is each of its edges once.
            assert_eq!(outline(&collect(GL_POLYGON, 6, first)), [(0, 1), (0, 5), (1, 2), (2, 3), (3, 4), (4, 5)]);
            // Each quad of a strip is outlined without its diagonals.
            for quad in collect(GL_QUAD_STRIP, 8, first).chunks(2) {
                let a = quad.iter().flat_map(|t| t.v).min().unwrap();
                assert_eq!(outline(quad), [(a, a + 1), (a, a + 2), (a + 1, a + 3), (a + 2, a + 3)]);
            }
        }
    }
}
