//! Drawing: where vertices from any source enter the geometry pipeline.
//!
//! A draw transforms its vertices to clip space, assembles primitives, clips only those that
//! must be clipped, maps them to window coordinates, culls, sets them up and bins them into
//! the context's [`Scene`]. Nothing is rasterized until a flush point
//! ([`Context::flush_rendering`]): glFlush, glFinish, glReadPixels, clears, glAccum, buffer
//! queries, MakeCurrent.
use super::Context;
use crate::api::enums::*;
use crate::api::types::GLenum;
use crate::context::state::{LinePointState, MAX_LINE_WIDTH, MAX_POINT_SIZE};
use crate::fragment::{DepthTest, FragmentState};
use crate::framebuffer::Rect;
use crate::raster::line::{LineJob, LineVertex};
use crate::raster::point::PointJob;
use crate::raster::triangle::{TriangleJob, WindowVertex};
use crate::raster::{DrawState, Primitive as RasterPrimitive, Scene};
use crate::setup::point::point_rect;
use crate::setup::triangle::GUARD_BAND;
use crate::vertex::assembly::{assemble, Primitive};
use crate::vertex::clip::{ClipPlanes, ClipVertex};
use crate::vertex::Vertex;
use glam::{Mat4, Vec4};

/// The viewport transform: window = ndc · scale + offset (x, y, z).
#[derive(Clone, Copy, Debug)]
struct Viewport {
    scale: [f32; 3],
    offset: [f32; 3],
    /// The y translation of llvmpipe's y-down window space (framebuffer height − offset y),
    /// where lines and points are set up: `y_down = ndc_y · −scale_y + offset_down`.
    offset_down: f32,
}

impl Viewport {
    /// Window coordinates of a clip-space vertex (w > 0), as llvmpipe computes them:
    /// the reciprocal of w first, then a multiply and the scale/offset, in single precision.
    #[inline]
    fn window(&self, v: &ClipVertex) -> WindowVertex {
        let inv_w = 1.0 / v.clip[3];
        let ndc = [v.clip[0] * inv_w, v.clip[1] * inv_w, v.clip[2] * inv_w];
        WindowVertex {
            x: ndc[0] * self.scale[0] + self.offset[0],
            y: ndc[1] * self.scale[1] + self.offset[1],
            z: ndc[2] * self.scale[2] + self.offset[2],
            inv_w,
            color: v.color,
        }
    }

    /// Window coordinates of a line or point vertex in llvmpipe's y-down window space.
    /// Vertices straight from the vertex stage get the multiply-add llvmpipe's generated
    /// code fuses (`fused`); vertices made by clipping get its C clipper's separate
    /// multiply and add. Endpoint pixels depend on the last bit of these coordinates.
    #[inline]
    fn window_down(&self, v: &ClipVertex, fused: bool) -> LineVertex {
        let inv_w = 1.0 / v.clip[3];
        let ndc = [v.clip[0] * inv_w, v.clip[1] * inv_w, v.clip[2] * inv_w];
        let map = |n: f32, scale: f32, offset: f32| if fused { n.mul_add(scale, offset) } else { n * scale + offset };
        LineVertex {
            x: map(ndc[0], self.scale[0], self.offset[0]),
            y_down: map(ndc[1], -self.scale[1], self.offset_down),
            z: map(ndc[2], self.scale[2], self.offset[2]),
            inv_w,
            color: v.color,
        }
    }
}

/// The line stipple of a draw: GL's repeat factor and pattern, and the running counter
/// (in pixel steps along the lines' major axes).
#[derive(Clone, Copy, Debug)]
struct LineStipple {
    factor: i32,
    pattern: u16,
    counter: i32,
}

/// Per-draw constants of the geometry stage.
struct Geometry {
    viewport: Viewport,
    planes: ClipPlanes,
    /// The view volume without guard band: lines are clipped to it, points outside it
    /// are discarded.
    line_planes: ClipPlanes,
    flat: bool,
    cull: Option<GLenum>,
    front_ccw: bool,
    offset: Option<(f32, f32)>,
    depth_bits: u32,
    /// Framebuffer height (for llvmpipe's y-down window space).
    height: i32,
    line_width: f32,
    point_size: f32,
    /// glPolygonMode of front and back faces.
    mode_front: GLenum,
    mode_back: GLenum,
    /// The depth offsets of polygons drawn as lines and as points: (factor, units × 2r),
    /// r the depth buffer's resolution, as Mesa's offset stage applies them.
    offset_line: Option<(f32, f32)>,
    offset_point: Option<(f32, f32)>,
}

impl Context {
    /// Draws `vertices` as primitives of `mode` (GL_POINTS … GL_POLYGON, already validated),
    /// with the current state. Vertex sources (glBegin/glEnd, glDrawArrays, …) call this.
    pub fn draw_vertices(&mut self, mode: GLenum, vertices: &[Vertex]) {
        let Some((width, height, float_color, depth_bits)) = self.with_framebuffer(|fb| {
            (fb.width(), fb.height(), fb.config().color.is_float(), fb.config().depth_stencil.depth_bits())
        }) else {
            return;
        };
        if vertices.is_empty() {
            return;
        }
        let mut scene = match self.scene.take() {
            Some(scene) if scene.size() == (width, height) => scene,
            other => {
                // A resized drawable: render what was recorded for the old size first.
                if let Some(old) = other {
                    self.run_scene(old);
                }
                Scene::new(width, height)
            }
        };
        let state = self.draw_state(&mut scene, width, height, float_color, depth_bits);
        let state_index = scene.add_state(state);
        let clip_vertices = self.transform(vertices, float_color);
        let geometry = self.geometry(depth_bits, height);
        let first_vertex = self.state.lighting.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
        let mut poly = Vec::new();
        let mut scratch = Vec::new();
        let outcodes: Vec<u32> = clip_vertices.iter().map(|v| geometry.planes.outcode(v)).collect();
        let line_outcodes: Vec<u32> = if mode == GL_POINTS || (GL_LINES..=GL_LINE_STRIP).contains(&mode) {
            clip_vertices.iter().map(|v| geometry.line_planes.outcode(v)).collect()
        } else {
            Vec::new()
        };
        let mut stipple = self.line_stipple();
        if geometry.mode_front != GL_FILL || geometry.mode_back != GL_FILL {
            if let Some(planes_outcodes) = outline_outcodes(mode, &geometry, &clip_vertices) {
                let mut outline =
                    Outline { scene: &mut scene, state: state_index, g: &geometry, stipple, first_vertex };
                decompose_outlines(mode, clip_vertices.len() as u32, first_vertex, |t| {
                    let v = t.v.map(|i| &clip_vertices[i as usize]);
                    let codes = t.v.map(|i| planes_outcodes[i as usize]);
                    outline.triangle(v, codes, t, &mut poly, &mut scratch);
                });
                self.scene = Some(scene);
                return;
            }
        }
        assemble(mode, clip_vertices.len() as u32, first_vertex, |primitive| match primitive {
            Primitive::Point(i) => {
                let i = i as usize;
                if line_outcodes[i] == 0 {
                    emit_point(&mut scene, state_index, &geometry, &clip_vertices[i]);
                }
            }
            Primitive::Line { v: [a, b], provoking } => {
                if mode == GL_LINES {
                    // Every independent segment restarts the pattern (GL 2.1 §3.4.2).
                    if let Some(s) = stipple.as_mut() {
                        s.counter = 0;
                    }
                }
                let flat_color = geometry.flat.then(|| clip_vertices[provoking as usize].color);
                let (a, b) = (a as usize, b as usize);
                emit_clip_line(
                    &mut scene,
                    state_index,
                    &geometry,
                    [&clip_vertices[a], &clip_vertices[b]],
                    [line_outcodes[a], line_outcodes[b]],
                    flat_color,
                    stipple.as_mut(),
                );
            }
            Primitive::Triangle { v, provoking, .. } => {
                let [a, b, c] = v.map(|i| i as usize);
                let (oa, ob, oc) = (outcodes[a], outcodes[b], outcodes[c]);
                if oa & ob & oc != 0 {
                    return;
                }
                let flat_color = geometry.flat.then(|| clip_vertices[provoking as usize].color);
                if oa | ob | oc == 0 {
                    let w = [a, b, c].map(|i| geometry.viewport.window(&clip_vertices[i]));
                    emit_triangle(&mut scene, state_index, &geometry, w, flat_color);
                } else {
                    poly.clear();
                    poly.extend([clip_vertices[a], clip_vertices[b], clip_vertices[c]]);
                    geometry.planes.clip_polygon(&mut poly, &mut scratch, oa | ob | oc);
                    if poly.len() < 3 {
                        return;
                    }
                    let w: Vec<WindowVertex> = poly.iter().map(|v| geometry.viewport.window(v)).collect();
                    for i in 1..w.len() - 1 {
                        emit_triangle(&mut scene, state_index, &geometry, [w[0], w[i], w[i + 1]], flat_color);
                    }
                }
            }
        });
        self.scene = Some(scene);
    }

    /// Rasterizes everything recorded so far into the bound framebuffer.
    pub fn flush_rendering(&mut self) {
        if let Some(scene) = self.scene.take() {
            self.run_scene(scene);
        }
    }

    fn run_scene(&mut self, scene: Scene) {
        let _ = self.with_framebuffer(|fb| {
            if scene.size() == (fb.width(), fb.height()) {
                scene.execute(fb);
            }
        });
    }

    /// The fragment state and clip rectangle of a draw.
    fn draw_state(
        &self,
        scene: &mut Scene,
        width: usize,
        height: usize,
        float_color: bool,
        depth_bits: u32,
    ) -> DrawState {
        let depth = (self.state.depth.test && depth_bits > 0)
            .then_some(DepthTest { func: self.state.depth.func, write: self.state.depth.write_mask });
        let mut color_masks = vec![None; scene.target_count()];
        for (slot, index) in self.draw_targets() {
            let target = scene.target_index(slot);
            if color_masks.len() <= target {
                color_masks.resize(target + 1, None);
            }
            color_masks[target] = Some(self.state.color.color_mask[index]);
        }
        let clamp_float = match self.state.color.clamp_fragment_color {
            GL_FIXED_ONLY => !float_color,
            c => c == GL_TRUE as GLenum,
        };
        let clip = self.clip_rect(Rect::from_xywh(0, 0, width as i32, height as i32));
        let polygon_stipple = self.state.polygon.stipple.then_some(self.state.polygon_stipple);
        DrawState { fragment: FragmentState { depth, color_masks, clamp_float }, clip, polygon_stipple }
    }

    /// GL_LINE_STIPPLE's state at the start of a draw, when enabled.
    fn line_stipple(&self) -> Option<LineStipple> {
        let lp = &self.state.line_point;
        lp.line_stipple.then_some(LineStipple {
            factor: lp.line_stipple_factor.clamp(1, 256),
            pattern: lp.line_stipple_pattern,
            counter: 0,
        })
    }

    /// Vertices to clip space, with their eye coordinates and clamped colors.
    fn transform(&self, vertices: &[Vertex], float_color: bool) -> Vec<ClipVertex> {
        let modelview = self.matrices.modelview();
        let mvp: Mat4 = self.matrices.projection() * modelview;
        let clamp = match self.state.lighting.clamp_vertex_color {
            GL_FIXED_ONLY => !float_color,
            c => c == GL_TRUE as GLenum,
        };
        let clamp4 = |c: [f32; 4]| if clamp { c.map(|x| if x > 0.0 { x.min(1.0) } else { 0.0 }) } else { c };
        vertices
            .iter()
            .map(|v| {
                let p = Vec4::from_array(v.position);
                ClipVertex {
                    clip: (mvp * p).to_array(),
                    eye: (modelview * p).to_array(),
                    color: clamp4(v.color),
                    secondary_color: clamp4(v.secondary_color),
                    tex_coords: v.tex_coords,
                    fog_coord: v.fog_coord,
                    edge_flag: v.edge_flag,
                }
            })
            .collect()
    }

    /// The per-draw geometry constants.
    fn geometry(&self, depth_bits: u32, height: usize) -> Geometry {
        let [x, y, w, h] = self.state.viewport.rect;
        let [near, far] = self.state.viewport.depth_range;
        let half = [w as f32 * 0.5, h as f32 * 0.5];
        let centre = [x as f32 + half[0], y as f32 + half[1]];
        // The guard band in NDC: as far out as keeps window coordinates within GUARD_BAND.
        let guard = |c: f32, h: f32| if h > 0.0 { ((GUARD_BAND * 0.5 - c.abs()) / h).max(1.0) } else { 1.0 };
        let transform = &self.state.transform;
        let user = (0..transform.clip_planes.len())
            .filter(|&i| transform.clip_planes[i])
            .map(|i| transform.clip_plane_equations[i].map(|c| c as f32))
            .collect();
        let polygon = &self.state.polygon;
        let planes = ClipPlanes {
            guard_x: guard(centre[0], half[0]),
            guard_y: guard(centre[1], half[1]),
            clip_z: !transform.depth_clamp,
            user,
        };
        let lp = &self.state.line_point;
        // Mesa's offset stage scales units by twice the depth buffer's resolution.
        let units_scale = if depth_bits > 0 { (2.0 / ((1u64 << depth_bits) - 1) as f64) as f32 } else { 0.0 };
        Geometry {
            viewport: Viewport {
                scale: [half[0], half[1], ((far - near) * 0.5) as f32],
                offset: [centre[0], centre[1], ((far + near) * 0.5) as f32],
                offset_down: height as f32 - centre[1],
            },
            line_planes: ClipPlanes { guard_x: 1.0, guard_y: 1.0, ..planes.clone() },
            planes,
            height: height as i32,
            line_width: lp.line_width.min(MAX_LINE_WIDTH),
            point_size: point_size(lp),
            // A culled face's mode does not matter; Mesa gives it the other face's, which
            // decides whether quads are split as filled quads or as outlines.
            mode_front: if polygon.cull_face && polygon.cull_face_mode == GL_FRONT {
                polygon.mode_back
            } else {
                polygon.mode_front
            },
            mode_back: if polygon.cull_face && polygon.cull_face_mode == GL_BACK {
                polygon.mode_front
            } else {
                polygon.mode_back
            },
            offset_line: polygon.offset_line.then_some((polygon.offset_factor, polygon.offset_units * units_scale)),
            offset_point: polygon.offset_point.then_some((polygon.offset_factor, polygon.offset_units * units_scale)),
            flat: self.state.lighting.shade_model == GL_FLAT,
            cull: polygon.cull_face.then_some(polygon.cull_face_mode),
            front_ccw: polygon.front_face == GL_CCW,
            offset: polygon.offset_fill.then_some((polygon.offset_factor, polygon.offset_units)),
            depth_bits,
        }
    }
}

/// The size points are drawn with: glPointSize clamped to GL_POINT_SIZE_MIN/MAX (the
/// minimum winning when they cross, as in Mesa) and to the implementation's range.
/// Distance attenuation (GL_POINT_DISTANCE_ATTENUATION) is not applied yet.
fn point_size(lp: &LinePointState) -> f32 {
    let size = lp.point_size;
    let size = if size < lp.point_size_min {
        lp.point_size_min
    } else if size > lp.point_size_max {
        lp.point_size_max
    } else {
        size
    };
    size.min(MAX_POINT_SIZE)
}

/// A triangle of a polygon drawn in GL_POINT or GL_LINE mode: its vertices, which of its
/// edges v0→v1, v1→v2, v2→v0 are edges of the polygon, and whether it is the polygon's
/// first (the line stipple restarts there).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct OutlineTriangle {
    v: [u32; 3],
    edges: [bool; 3],
    first: bool,
}

/// Decomposes the polygons of `mode` into triangles for the point and line polygon modes,
/// in Mesa 22's order: the vertex order, the order of the outline's edges and where the
/// stipple restarts all follow its primitive decomposition (the provoking vertex stays
/// last, or first under GL_FIRST_VERTEX_CONVENTION; quads split along the diagonal that
/// keeps it a corner of both triangles).
fn decompose_outlines(mode: GLenum, count: u32, first_vertex: bool, mut emit: impl FnMut(OutlineTriangle)) {
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
            for i in 0..count - 2 {
                let last = i + 3 == count;
                if first_vertex {
                    emit(tri([0, i + 1, i + 2], [i == 0, true, last], i == 0));
                } else {
                    emit(tri([i + 1, i + 2, 0], [true, last, i == 0], i == 0));
                }
            }
        }
        _ => {}
    }
}

/// Outcodes against the view volume for the polygon modes, or `None` when `mode` draws no
/// polygons.
fn outline_outcodes(mode: GLenum, g: &Geometry, vertices: &[ClipVertex]) -> Option<Vec<u32>> {
    (GL_TRIANGLES..=GL_POLYGON).contains(&mode).then(|| vertices.iter().map(|v| g.line_planes.outcode(v)).collect())
}

/// The point and line polygon modes: triangles of polygons are clipped to the view volume
/// (edges made by clipping are not polygon edges), culled, offset, and then drawn in their
/// face's mode as their polygon edges or vertices, following Mesa 22's pipeline (clip,
/// cull, offset, flat shading, unfilled, stipple).
struct Outline<'a> {
    scene: &'a mut Scene,
    state: u32,
    g: &'a Geometry,
    stipple: Option<LineStipple>,
    first_vertex: bool,
}

impl Outline<'_> {
    /// One triangle of the decomposition, `codes` its vertices' outcodes.
    fn triangle(
        &mut self,
        v: [&ClipVertex; 3],
        codes: [u32; 3],
        t: OutlineTriangle,
        poly: &mut Vec<ClipVertex>,
        scratch: &mut Vec<ClipVertex>,
    ) {
        if codes[0] & codes[1] & codes[2] != 0 {
            return;
        }
        // An edge is drawn when the decomposition and the edge flag of its first vertex say so.
        let edges = std::array::from_fn(|i| t.edges[i] && v[i].edge_flag);
        let flat = self.g.flat.then(|| v[if self.first_vertex { 0 } else { 2 }].color);
        let corner = |c: &ClipVertex, fused: bool| (self.g.viewport.window_down(c, fused), self.g.viewport.window(c));
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
            if self.first_vertex {
                self.draw([w[0], w[i - 1], w[i]], [start, middle, end], i == 2, flat);
            } else {
                self.draw([w[i - 1], w[i], w[0]], [middle, end, start], i == 2, flat);
            }
        }
    }

    /// Culls, offsets and draws one (clipped) triangle in its face's mode; `w` holds each
    /// corner in y-down and in GL window coordinates.
    fn draw(&mut self, w: [(LineVertex, WindowVertex); 3], edges: [bool; 3], first: bool, flat: Option<[f32; 4]>) {
        let g = self.g;
        let mut l = w.map(|c| c.0);
        let (ex, ey, ez) = (l[0].x - l[2].x, l[0].y_down - l[2].y_down, l[0].z - l[2].z);
        let (fx, fy, fz) = (l[1].x - l[2].x, l[1].y_down - l[2].y_down, l[1].z - l[2].z);
        let det = ex * fy - ey * fx;
        if det == 0.0 || !det.is_finite() {
            return;
        }
        // y-down flips the orientation: counter-clockwise in GL has det < 0 here.
        let front = (det < 0.0) == g.front_ccw;
        match g.cull {
            Some(GL_FRONT_AND_BACK) => return,
            Some(GL_FRONT) if front => return,
            Some(GL_BACK) if !front => return,
            _ => {}
        }
        let mode = if front { g.mode_front } else { g.mode_back };
        let offset = match mode {
            GL_LINE => g.offset_line,
            GL_POINT => g.offset_point,
            _ => {
                if let Some(s) = self.stipple.as_mut() {
                    s.counter = 0;
                }
                emit_triangle(self.scene, self.state, g, w.map(|c| c.1), flat);
                return;
            }
        };
        if let Some((factor, units)) = offset {
            // Mesa's offset stage: the larger depth slope of the triangle, applied per vertex.
            let inv_det = 1.0 / det;
            let dzdx = ((ey * fz - ez * fy) * inv_det).abs();
            let dzdy = ((ez * fx - ex * fz) * inv_det).abs();
            let z_offset = units + dzdx.max(dzdy) * factor;
            for c in &mut l {
                c.z = (c.z + z_offset).clamp(0.0, 1.0);
            }
        }
        if let Some(color) = flat {
            for c in &mut l {
                c.color = color;
            }
        }
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
                    emit_window_point(self.scene, self.state, g, &l[k]);
                }
            }
        }
    }
}

/// Clips the polygon `poly` (each vertex's `edge_flag` telling whether the edge it starts
/// is drawn) against the planes in `mask` as Mesa's clipper does for polygons it draws as
/// outlines: plane by plane, each new vertex interpolated from the end of the cut edge
/// nearer to the plane, edges along a view-volume plane not drawn. `false` when a
/// distance is NaN (the polygon is dropped).
fn clip_outline(planes: &ClipPlanes, poly: &mut Vec<ClipVertex>, scratch: &mut Vec<ClipVertex>, mask: u32) -> bool {
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

/// Culls, offsets, sets up and bins one window-space triangle.
fn emit_triangle(scene: &mut Scene, state: u32, g: &Geometry, w: [WindowVertex; 3], flat: Option<[f32; 4]>) {
    let area2 = (w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[2].x - w[0].x) * (w[1].y - w[0].y);
    if !area2.is_finite() {
        return;
    }
    let front = (area2 > 0.0) == g.front_ccw;
    match g.cull {
        Some(GL_FRONT_AND_BACK) => return,
        Some(GL_FRONT) if front => return,
        Some(GL_BACK) if !front => return,
        _ => {}
    }
    let offset = g.offset.map_or(0.0, |(factor, units)| polygon_offset(&w, factor, units, g.depth_bits));
    if let Some(job) = TriangleJob::new(w, flat, offset) {
        let bounds = job.bounds();
        scene.add(state, bounds, RasterPrimitive::Triangle(job));
    }
}

/// Clips a line to the view volume the way Mesa's clipper does (both ends moved from the
/// original endpoints, by the largest cut of any plane), maps it to window space and emits
/// it. `outcodes` are against `g.line_planes`.
fn emit_clip_line(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    ends: [&ClipVertex; 2],
    outcodes: [u32; 2],
    flat: Option<[f32; 4]>,
    stipple: Option<&mut LineStipple>,
) {
    let [a, b] = ends;
    if outcodes[0] & outcodes[1] != 0 {
        return;
    }
    let (wa, wb) = if outcodes[0] | outcodes[1] == 0 {
        (g.viewport.window_down(a, true), g.viewport.window_down(b, true))
    } else {
        let planes = &g.line_planes;
        let (mut t0, mut t1) = (0.0f32, 0.0f32);
        let mut mask = outcodes[0] | outcodes[1];
        while mask != 0 {
            let plane = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            let (da, db) = (planes.distance(plane, a), planes.distance(plane, b));
            if !da.is_finite() || !db.is_finite() {
                return;
            }
            if db < 0.0 {
                t1 = t1.max(db / (db - da));
            }
            if da < 0.0 {
                t0 = t0.max(da / (da - db));
            }
            if t0 + t1 >= 1.0 {
                return;
            }
        }
        let wa = if outcodes[0] != 0 {
            g.viewport.window_down(&lerp_clip(a, b, t0), false)
        } else {
            g.viewport.window_down(a, true)
        };
        let wb = if outcodes[1] != 0 {
            g.viewport.window_down(&lerp_clip(b, a, t1), false)
        } else {
            g.viewport.window_down(b, true)
        };
        (wa, wb)
    };
    emit_window_line(scene, state, g, wa, wb, flat, stipple);
}

/// `from + t · (to − from)` for the clip position and color of a clipped line end.
fn lerp_clip(from: &ClipVertex, to: &ClipVertex, t: f32) -> ClipVertex {
    let mix = |a: [f32; 4], b: [f32; 4]| std::array::from_fn(|i| a[i] + t * (b[i] - a[i]));
    ClipVertex { clip: mix(from.clip, to.clip), color: mix(from.color, to.color), ..*from }
}

/// Emits a window-space line, cut into its stippled dashes when stippled.
fn emit_window_line(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    a: LineVertex,
    b: LineVertex,
    flat: Option<[f32; 4]>,
    stipple: Option<&mut LineStipple>,
) {
    let Some(stipple) = stipple else {
        emit_line_job(scene, state, g, &a, &b, flat);
        return;
    };
    // llvmpipe's stipple: the line is cut into dashes, one pixel step along the major axis
    // per stipple bit, each dash drawn as a line of its own.
    let length = (a.x - b.x).abs().max((a.y_down - b.y_down).abs());
    let steps = if length.is_finite() { length.ceil() as i32 } else { 0 };
    let base = stipple.counter;
    let bit = |i: i32| stipple.pattern >> (((base + i) / stipple.factor) & 15) & 1 != 0;
    let mut dash_start = None;
    for i in 0..steps {
        match (dash_start, bit(i)) {
            (None, true) => dash_start = Some(i),
            (Some(start), false) => {
                emit_dash(scene, state, g, &a, &b, start as f32 / length, i as f32 / length, flat);
                dash_start = None;
            }
            _ => {}
        }
    }
    if let Some(start) = dash_start {
        if (start as f32) < length {
            emit_dash(scene, state, g, &a, &b, start as f32 / length, 1.0, flat);
        }
    }
    // The counter advances by whole steps: a strip's next segment continues where this
    // one's last (partial) step ended, as in Mesa 22.
    stipple.counter = stipple.counter.wrapping_add(steps);
}

/// Emits the part of `a`–`b` between parameters `t0` and `t1`, every attribute
/// interpolated linearly in window space as llvmpipe's stipple stage does.
#[allow(clippy::too_many_arguments)]
fn emit_dash(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    a: &LineVertex,
    b: &LineVertex,
    t0: f32,
    t1: f32,
    flat: Option<[f32; 4]>,
) {
    let at = |t: f32| {
        let mix = |p: f32, q: f32| p + t * (q - p);
        LineVertex {
            x: mix(a.x, b.x),
            y_down: mix(a.y_down, b.y_down),
            z: mix(a.z, b.z),
            inv_w: mix(a.inv_w, b.inv_w),
            color: std::array::from_fn(|i| mix(a.color[i], b.color[i])),
        }
    };
    let start = if t0 > 0.0 { at(t0) } else { *a };
    let end = if t1 < 1.0 { at(t1) } else { *b };
    emit_line_job(scene, state, g, &start, &end, flat);
}

fn emit_line_job(scene: &mut Scene, state: u32, g: &Geometry, a: &LineVertex, b: &LineVertex, flat: Option<[f32; 4]>) {
    if let Some(job) = LineJob::new(a, b, g.line_width, g.height, flat) {
        let bounds = job.bounds();
        scene.add(state, bounds, RasterPrimitive::Line(job));
    }
}

/// Emits a point whose vertex is inside the view volume.
fn emit_point(scene: &mut Scene, state: u32, g: &Geometry, v: &ClipVertex) {
    let w = g.viewport.window_down(v, true);
    emit_window_point(scene, state, g, &w);
}

fn emit_window_point(scene: &mut Scene, state: u32, g: &Geometry, w: &LineVertex) {
    let rect = point_rect(w.x, w.y_down, g.point_size, g.height);
    // llvmpipe interpolates point colors perspective-correctly too: (c/w)·w.
    let color = if w.inv_w == 1.0 { w.color } else { w.color.map(|c| c * w.inv_w * (1.0 / w.inv_w)) };
    scene.add(state, rect, RasterPrimitive::Point(PointJob { rect, z: w.z, color }));
}

/// glPolygonOffset's depth offset for a triangle: factor × max depth slope + units × r,
/// where r is the smallest resolvable difference of the depth buffer.
fn polygon_offset(w: &[WindowVertex; 3], factor: f32, units: f32, depth_bits: u32) -> f32 {
    let (x1, y1, z1) = (w[1].x - w[0].x, w[1].y - w[0].y, w[1].z - w[0].z);
    let (x2, y2, z2) = (w[2].x - w[0].x, w[2].y - w[0].y, w[2].z - w[0].z);
    let det = x1 * y2 - x2 * y1;
    let slope = if det != 0.0 {
        let dzdx = (z1 * y2 - z2 * y1) / det;
        let dzdy = (x1 * z2 - x2 * z1) / det;
        dzdx.abs().max(dzdy.abs())
    } else {
        0.0
    };
    let r = if depth_bits > 0 { 1.0 / ((1u64 << depth_bits) - 1) as f32 } else { 0.0 };
    factor * slope + units * r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::state::CompareFunc;
    use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, Drawable, FramebufferConfig};
    use std::sync::{Arc, Mutex};

    fn context(w: usize, h: usize) -> (Context, Arc<Mutex<Drawable>>) {
        let visual = FramebufferConfig::single_buffered(
            ColorFormat::Unorm8 { alpha: true },
            DepthStencilFormat::Packed24 { depth: true, stencil: true },
            0,
        );
        let (mut ctx, d) = Context::with_test_drawable(visual, w, h);
        // glOrtho(0, w, 0, h, -1, 1): object coordinates are window coordinates.
        ctx.matrices.projection = vec![Mat4::orthographic_rh_gl(0.0, w as f32, 0.0, h as f32, -1.0, 1.0)];
        (ctx, d)
    }

    fn vertex(x: f32, y: f32, z: f32, color: [f32; 4]) -> Vertex {
        Vertex {
            position: [x, y, z, 1.0],
            color,
            secondary_color: [0.0; 4],
            normal: [0.0, 0.0, 1.0],
            tex_coords: [[0.0; 4]; 4],
            fog_coord: 0.0,
            edge_flag: true,
        }
    }

    fn pixels(ctx: &mut Context, d: &Arc<Mutex<Drawable>>) -> Vec<[u8; 4]> {
        ctx.flush_rendering();
        let guard = d.lock().unwrap();
        let fb = &guard.framebuffer;
        let mut out = Vec::new();
        for y in 0..fb.height() as i32 {
            let mut row = Vec::new();
            fb.color(ColorSlot::FrontLeft).unwrap().read_row_f32(y, 0, fb.width() as i32, &mut row);
            out.extend(row.iter().map(|c| c.map(|x| (x * 255.0).round() as u8)));
        }
        out
    }

    const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
    const GREEN: [f32; 4] = [0.0, 1.0, 0.0, 1.0];

    #[test]
    fn a_triangle_covers_exactly_the_centres_inside_it() {
        let (mut ctx, d) = context(8, 8);
        ctx.draw_vertices(
            GL_TRIANGLES,
            &[vertex(0.5, 0.5, 0.0, RED), vertex(4.5, 0.5, 0.0, RED), vertex(4.5, 4.5, 0.0, RED)],
        );
        let px = pixels(&mut ctx, &d);
        let lit: Vec<(usize, usize)> = (0..64).filter(|i| px[*i][0] == 255).map(|i| (i % 8, i / 8)).collect();
        // Mesa 22 llvmpipe: rows y0: x0..3, y1: x1..3, y2: x2..3, y3: x3.
        assert_eq!(lit, vec![(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1), (2, 2), (3, 2), (3, 3)]);
    }

    #[test]
    fn depth_test_keeps_the_nearer_surface_in_any_order() {
        for order in [0, 1] {
            let (mut ctx, d) = context(16, 16);
            ctx.state.depth.test = true;
            ctx.clear(GL_DEPTH_BUFFER_BIT);
            let quad = |z: f32, c: [f32; 4]| {
                [vertex(0.0, 0.0, z, c), vertex(16.0, 0.0, z, c), vertex(16.0, 16.0, z, c), vertex(0.0, 16.0, z, c)]
            };
            // glOrtho maps z = 0.5 nearer than z = -0.5 (eye z is negated).
            let (near, far) = (quad(0.5, GREEN), quad(-0.5, RED));
            let draws = if order == 0 { [near, far] } else { [far, near] };
            for q in &draws {
                ctx.draw_vertices(GL_QUADS, q);
            }
            assert!(pixels(&mut ctx, &d).iter().all(|p| *p == [0, 255, 0, 255]), "order {order}");
        }
    }

    #[test]
    fn equal_depth_passes_on_redrawn_geometry() {
        let (mut ctx, d) = context(32, 32);
        ctx.state.depth.test = true;
        ctx.clear(GL_DEPTH_BUFFER_BIT);
        let tri = |c| [vertex(1.3, 2.1, -0.31, c), vertex(30.2, 5.7, 0.77, c), vertex(11.9, 29.4, 0.12, c)];
        ctx.draw_vertices(GL_TRIANGLES, &tri(RED));
        ctx.state.depth.func = CompareFunc::Equal;
        ctx.draw_vertices(GL_TRIANGLES, &tri(GREEN));
        let px = pixels(&mut ctx, &d);
        assert!(px.iter().any(|p| p[1] == 255));
        assert!(px.iter().all(|p| p[0] == 0), "every redrawn pixel passes GL_EQUAL");
    }

    #[test]
    fn geometry_behind_the_eye_is_clipped_not_wrapped() {
        let (mut ctx, d) = context(16, 16);
        ctx.matrices.projection = vec![Mat4::perspective_rh_gl(1.2, 1.0, 0.5, 10.0)];
        // A triangle from in front of the camera to behind it (eye z > 0).
        ctx.draw_vertices(
            GL_TRIANGLES,
            &[vertex(-1.0, -1.0, -2.0, RED), vertex(1.0, -1.0, -2.0, RED), vertex(0.0, -1.0, 3.0, RED)],
        );
        let px = pixels(&mut ctx, &d);
        let lit = px.iter().filter(|p| p[0] == 255).count();
        assert!(lit > 0 && lit < 16 * 16 / 2, "{lit} pixels");
        // Only the lower half of the view can see a floor below the eye.
        assert!(px[8 * 16..].iter().all(|p| p[0] == 0));
    }

    #[test]
    fn results_are_identical_for_any_thread_count() {
        let render = |threads: usize| {
            let (mut ctx, d) = context(200, 150);
            ctx.state.depth.test = true;
            ctx.clear(GL_DEPTH_BUFFER_BIT);
            let mut seed = 12345u32;
            let mut rnd = || {
                seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
                (seed >> 8) as f32 / (1 << 24) as f32
            };
            let mut vertices = Vec::new();
            for _ in 0..300 {
                let c = [rnd(), rnd(), rnd(), 1.0];
                vertices.push(vertex(rnd() * 220.0 - 10.0, rnd() * 170.0 - 10.0, rnd() * 2.0 - 1.0, c));
            }
            ctx.draw_vertices(GL_TRIANGLES, &vertices);
            let scene = ctx.scene.take().unwrap();
            scene.execute_on(&mut d.lock().unwrap().framebuffer, threads);
            pixels(&mut ctx, &d)
        };
        let one = render(1);
        for threads in [2, 4, 7] {
            assert!(one == render(threads), "{threads} threads differ");
        }
    }

    /// Replays a probe script: the command language of the C probe used to measure Mesa
    /// (size, clear, viewport, ortho, frustum, linewidth, pointsize, pointminmax, stipple,
    /// pstipple, enable, disable, shade, provoking, polymode, cullface, frontface,
    /// depthfunc, offset, begin, color, edge, v, end, lit, dump, depth), printing the same
    /// lines, so that a script's output on Mesa and on tessera can be diffed.
    pub(crate) fn replay(script: &str) -> String {
        let mut out = String::new();
        let mut ctx_drawable: Option<(Context, Arc<Mutex<Drawable>>)> = None;
        let mut size = (0usize, 0usize);
        let mut clear = [0.0f32; 4];
        let mut mode = 0;
        let mut vertices = Vec::new();
        let mut color = [1.0f32; 4];
        let mut edge = true;
        let name = |n: &str| -> GLenum {
            match n {
                "points" => GL_POINTS,
                "lines" => GL_LINES,
                "line_strip" => GL_LINE_STRIP,
                "line_loop" => GL_LINE_LOOP,
                "triangles" => GL_TRIANGLES,
                "triangle_strip" => GL_TRIANGLE_STRIP,
                "triangle_fan" => GL_TRIANGLE_FAN,
                "quads" => GL_QUADS,
                "quad_strip" => GL_QUAD_STRIP,
                "polygon" => GL_POLYGON,
                "point" => GL_POINT,
                "line" => GL_LINE,
                "fill" => GL_FILL,
                "front" => GL_FRONT,
                "back" => GL_BACK,
                "front_and_back" => GL_FRONT_AND_BACK,
                "flat" => GL_FLAT,
                "smooth" => GL_SMOOTH,
                "cw" => GL_CW,
                "ccw" => GL_CCW,
                "first" => GL_FIRST_VERTEX_CONVENTION,
                "last" => GL_LAST_VERTEX_CONVENTION,
                _ => panic!("unknown name {n}"),
            }
        };
        for line in script.lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            let Some(&cmd) = words.first() else { continue };
            if cmd.starts_with('#') {
                continue;
            }
            let f = |i: usize| words[i].parse::<f64>().unwrap();
            if cmd == "size" {
                size = (words[1].parse().unwrap(), words[2].parse().unwrap());
                ctx_drawable = Some(context(size.0, size.1));
                continue;
            }
            let (ctx, d) = ctx_drawable.as_mut().expect("size first");
            let st = &mut ctx.state;
            match cmd {
                "clear" => {
                    clear = [f(1) as f32, f(2) as f32, f(3) as f32, f(4) as f32];
                    st.color.clear_color = clear;
                    st.depth.clear = 1.0;
                    ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                }
                "cleardepth" => {
                    st.depth.clear = f(1);
                    ctx.clear(GL_DEPTH_BUFFER_BIT);
                }
                "ortho" | "frustum" => {
                    let (l, r, b, t, n, fa) = (f(1), f(2), f(3), f(4), f(5), f(6));
                    // In single precision, as Mesa's glOrtho and glFrustum compute them.
                    let [l, r, b, t, n, fa] = [l, r, b, t, n, fa].map(|v| v as f32);
                    #[rustfmt::skip]
                    let m = if cmd == "ortho" {
                        Mat4::from_cols_array(&[
                            2.0 / (r - l), 0.0, 0.0, 0.0,
                            0.0, 2.0 / (t - b), 0.0, 0.0,
                            0.0, 0.0, -2.0 / (fa - n), 0.0,
                            -(r + l) / (r - l), -(t + b) / (t - b), -(fa + n) / (fa - n), 1.0,
                        ])
                    } else {
                        Mat4::from_cols_array(&[
                            2.0 * n / (r - l), 0.0, 0.0, 0.0,
                            0.0, 2.0 * n / (t - b), 0.0, 0.0,
                            (r + l) / (r - l), (t + b) / (t - b), -(fa + n) / (fa - n), -1.0,
                            0.0, 0.0, -(2.0 * fa * n) / (fa - n), 0.0,
                        ])
                    };
                    ctx.matrices.projection = vec![m];
                }
                "viewport" => st.viewport.rect = [1, 2, 3, 4].map(|i| words[i].parse().unwrap()),
                "scissorbox" => st.scissor.rect = [1, 2, 3, 4].map(|i| words[i].parse().unwrap()),
                "linewidth" => st.line_point.line_width = f(1) as f32,
                "pointsize" => st.line_point.point_size = f(1) as f32,
                "pointminmax" => {
                    st.line_point.point_size_min = f(1) as f32;
                    st.line_point.point_size_max = f(2) as f32;
                }
                "stipple" => {
                    st.line_point.line_stipple_factor = words[1].parse().unwrap();
                    st.line_point.line_stipple_pattern = u16::from_str_radix(words[2], 16).unwrap();
                }
                "pstipple" => {
                    for i in 0..32 {
                        st.polygon_stipple[i] = u32::from_str_radix(words[1 + i], 16).unwrap();
                    }
                }
                "enable" | "disable" => {
                    let on = cmd == "enable";
                    match words[1] {
                        "line_stipple" => st.line_point.line_stipple = on,
                        "polygon_stipple" => st.polygon.stipple = on,
                        "depth_test" => st.depth.test = on,
                        "cull_face" => st.polygon.cull_face = on,
                        "offset_fill" => st.polygon.offset_fill = on,
                        "offset_line" => st.polygon.offset_line = on,
                        "offset_point" => st.polygon.offset_point = on,
                        "scissor" => st.scissor.test = on,
                        w => panic!("unknown capability {w}"),
                    }
                }
                "shade" => st.lighting.shade_model = name(words[1]),
                "provoking" => st.lighting.provoking_vertex = name(words[1]),
                "polymode" => {
                    let m = name(words[2]);
                    match name(words[1]) {
                        GL_FRONT => st.polygon.mode_front = m,
                        GL_BACK => st.polygon.mode_back = m,
                        _ => {
                            st.polygon.mode_front = m;
                            st.polygon.mode_back = m;
                        }
                    }
                }
                "cullface" => st.polygon.cull_face_mode = name(words[1]),
                "frontface" => st.polygon.front_face = name(words[1]),
                "depthfunc" => {
                    st.depth.func = match words[1] {
                        "less" => CompareFunc::Less,
                        "lequal" => CompareFunc::LessEqual,
                        "equal" => CompareFunc::Equal,
                        "always" => CompareFunc::Always,
                        w => panic!("unknown depth func {w}"),
                    }
                }
                "offset" => {
                    st.polygon.offset_factor = f(1) as f32;
                    st.polygon.offset_units = f(2) as f32;
                }
                "begin" => {
                    mode = name(words[1]);
                    vertices.clear();
                }
                "color" => color = [f(1) as f32, f(2) as f32, f(3) as f32, f(4) as f32],
                "edge" => edge = words[1] != "0",
                "v" => {
                    let p = [
                        f(1) as f32,
                        f(2) as f32,
                        words.get(3).map_or(0.0, |_| f(3) as f32),
                        words.get(4).map_or(1.0, |_| f(4) as f32),
                    ];
                    let mut v = vertex(p[0], p[1], p[2], color);
                    v.position[3] = p[3];
                    v.edge_flag = edge;
                    vertices.push(v);
                }
                "end" => ctx.draw_vertices(mode, &vertices),
                "lit" | "dump" => {
                    let px = pixels(ctx, d);
                    let cc = clear.map(|c| (c * 255.0 + 0.5) as u8);
                    out.push_str(&format!("{}:", words[1]));
                    for (i, p) in px.iter().enumerate() {
                        if *p != cc {
                            let (x, y) = (i % size.0, i / size.0);
                            if cmd == "lit" {
                                out.push_str(&format!(" {x},{y}"));
                            } else {
                                out.push_str(&format!(" {x},{y}={:02x}{:02x}{:02x}{:02x}", p[0], p[1], p[2], p[3]));
                            }
                        }
                    }
                    out.push('\n');
                }
                "depth" => {
                    ctx.flush_rendering();
                    let guard = d.lock().unwrap();
                    let fb = &guard.framebuffer;
                    out.push_str(&format!("{}:", words[1]));
                    for y in 0..fb.height() as i32 {
                        let mut row = Vec::new();
                        fb.depth_stencil().read_depth_row(y, 0, fb.width() as i32, &mut row);
                        for (x, z) in row.iter().enumerate() {
                            if *z != 0x00ff_ffff {
                                out.push_str(&format!(" {x},{y}={z:06x}"));
                            }
                        }
                    }
                    out.push('\n');
                }
                w => panic!("unknown command {w}"),
            }
        }
        out
    }

    /// Prints the replay of the script named by TESSERA_PROBE_SCRIPT (a tool for comparing
    /// with Mesa, not a test): `cargo test replay_probe_script -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn replay_probe_script() {
        let path = std::env::var("TESSERA_PROBE_SCRIPT").expect("TESSERA_PROBE_SCRIPT");
        let script = std::fs::read_to_string(path).unwrap();
        print!("{}", replay(&script));
    }
}
