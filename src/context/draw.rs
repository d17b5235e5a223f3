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
use crate::fragment::{DepthTest, FragmentState};
use crate::framebuffer::Rect;
use crate::raster::triangle::{TriangleJob, WindowVertex};
use crate::raster::{DrawState, Primitive as RasterPrimitive, Scene};
use crate::setup::triangle::GUARD_BAND;
use crate::vertex::assembly::{assemble, Primitive, QuadSplit};
use crate::vertex::clip::{ClipPlanes, ClipVertex};
use crate::vertex::Vertex;
use glam::{Mat4, Vec4};

/// The viewport transform: window = ndc · scale + offset (x, y, z).
#[derive(Clone, Copy, Debug)]
struct Viewport {
    scale: [f32; 3],
    offset: [f32; 3],
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
}

/// Per-draw constants of the geometry stage.
struct Geometry {
    viewport: Viewport,
    planes: ClipPlanes,
    flat: bool,
    cull: Option<GLenum>,
    front_ccw: bool,
    offset: Option<(f32, f32)>,
    depth_bits: u32,
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
        // Mesa analyses changed matrices at draw time; their flags decide how products round.
        self.matrices.validate();
        let state = self.draw_state(&mut scene, width, height, float_color, depth_bits);
        let state_index = scene.add_state(state);
        let clip_vertices = self.transform(vertices, float_color);
        let geometry = self.geometry(depth_bits);
        let first_vertex = self.state.lighting.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
        let mut poly = Vec::new();
        let mut scratch = Vec::new();
        let outcodes: Vec<u32> = clip_vertices.iter().map(|v| geometry.planes.outcode(v)).collect();
        let split = if !first_vertex && mode == GL_QUADS && geometry.leaves_view_volume(&clip_vertices) {
            QuadSplit::SecondDiagonal
        } else {
            QuadSplit::FirstDiagonal
        };
        assemble(mode, clip_vertices.len() as u32, first_vertex, split, |primitive| {
            if let Primitive::Triangle { v, provoking, .. } = primitive {
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
        DrawState { fragment: FragmentState { depth, color_masks, clamp_float }, clip }
    }

    /// Vertices to clip space, with their eye coordinates and clamped colors.
    fn transform(&self, vertices: &[Vertex], float_color: bool) -> Vec<ClipVertex> {
        let modelview = self.matrices.modelview();
        let mvp: Mat4 = self.matrices.model_project();
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
    fn geometry(&self, depth_bits: u32) -> Geometry {
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
        Geometry {
            viewport: Viewport {
                scale: [half[0], half[1], ((far - near) * 0.5) as f32],
                offset: [centre[0], centre[1], ((far + near) * 0.5) as f32],
            },
            planes: ClipPlanes {
                guard_x: guard(centre[0], half[0]),
                guard_y: guard(centre[1], half[1]),
                clip_z: !transform.depth_clamp,
                user,
            },
            flat: self.state.lighting.shade_model == GL_FLAT,
            cull: polygon.cull_face.then_some(polygon.cull_face_mode),
            front_ccw: polygon.front_face == GL_CCW,
            offset: polygon.offset_fill.then_some((polygon.offset_factor, polygon.offset_units)),
            depth_bits,
        }
    }
}

impl Geometry {
    /// Whether any vertex lies outside the view volume (not only the guard band) or an
    /// enabled user clip plane: where Mesa's draw module takes its pipeline path.
    fn leaves_view_volume(&self, vertices: &[ClipVertex]) -> bool {
        let view = ClipPlanes { guard_x: 1.0, guard_y: 1.0, clip_z: true, user: self.planes.user.clone() };
        vertices.iter().any(|v| view.outcode(v) != 0)
    }
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
        ctx.matrix_mode(GL_PROJECTION);
        ctx.ortho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0);
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
        ctx.matrix_mode(GL_PROJECTION);
        ctx.load_identity();
        ctx.frustum(-0.5, 0.5, -0.5, 0.5, 0.5, 10.0);
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
}
