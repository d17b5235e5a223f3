//! Drawing: where vertices from any source enter the geometry pipeline.
//!
//! A draw transforms its vertices to clip space, assembles primitives, clips only those that
//! must be clipped, maps them to window coordinates, culls, sets them up and bins them into
//! the context's [`Scene`]. Nothing is rasterized until a flush point
//! ([`Context::flush_rendering`]): glFlush, glFinish, glReadPixels, clears, glAccum, buffer
//! queries, MakeCurrent.
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
mod select;

use super::{debug, Context};
use crate::context::state::LinePointState;
use crate::fragment::{DepthTest, FragmentState};
use crate::framebuffer::{ColorFormat, Rect};
use crate::gl::enums::*;
use crate::gl::limits::{MAX_LINE_WIDTH, MAX_POINT_SIZE};
use crate::gl::types::GLenum;
use crate::raster::accuracy::Accuracy;
use crate::raster::line::{LineJob, LineVertex};
use crate::raster::point::PointJob;
use crate::raster::smooth::{SmoothJob, SmoothLine, SmoothPoint, SmoothTriangle};
use crate::raster::triangle::{TriangleJob, WindowVertex};
use crate::raster::{DrawState, Primitive as RasterPrimitive, Scene};
use crate::setup::multisample::SampleQuad;
use crate::setup::point::point_rect;
use crate::setup::triangle::GUARD_BAND;
use crate::vertex::assembly::{assemble, DrawPart, Primitive, QuadSplit};
use crate::vertex::clip::{ClipPlanes, ClipVertex};
use crate::vertex::lighting::{Lighting, NormalScaling};
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
            secondary_color: v.secondary_color,
            tex_coords: v.tex_coords,
            fog_coord: v.fog_coord,
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
            secondary_color: v.secondary_color,
            tex_coords: v.tex_coords,
            fog_coord: v.fog_coord,
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

/// A scalar vertex attribute that a draw's later stages read per fragment: a channel of the
/// secondary color (GL_COLOR_SUM), the fog coordinate (GL_FOG), or a component of a unit's
/// texture coordinates (the unit has a texture target enabled).
///
/// Plain numbers rather than an enum with payloads, so that every byte of a list of them is
/// initialised: valgrind's memcheck (tools/memcheck.sh) flags the optimised code's reads of
/// the payload bytes another variant leaves undefined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Attribute {
    kind: AttributeKind,
    unit: u8,
    component: u8,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AttributeKind {
    SecondaryColor,
    FogCoord,
    TexCoord,
}

impl Attribute {
    pub(crate) const FOG_COORD: Attribute = Attribute { kind: AttributeKind::FogCoord, unit: 0, component: 0 };

    pub(crate) fn secondary_color(component: usize) -> Attribute {
        Attribute { kind: AttributeKind::SecondaryColor, unit: 0, component: component as u8 }
    }

    pub(crate) fn tex_coord(unit: usize, component: usize) -> Attribute {
        Attribute { kind: AttributeKind::TexCoord, unit: unit as u8, component: component as u8 }
    }

    /// This attribute among a vertex's secondary color, fog coordinate and texture coordinates.
    pub(crate) fn pick(self, secondary_color: &[f32; 4], fog_coord: f32, tex_coords: &[[f32; 4]]) -> f32 {
        match self.kind {
            AttributeKind::SecondaryColor => secondary_color[self.component as usize],
            AttributeKind::FogCoord => fog_coord,
            AttributeKind::TexCoord => tex_coords[self.unit as usize][self.component as usize],
        }
    }

    fn of(self, v: &WindowVertex) -> f32 {
        self.pick(&v.secondary_color, v.fog_coord, &v.tex_coords)
    }

    /// The attribute at a line or point vertex.
    fn of_line(self, v: &LineVertex) -> f32 {
        self.pick(&v.secondary_color, v.fog_coord, &v.tex_coords)
    }
}

/// Per-draw constants of the geometry stage.
struct Geometry {
    viewport: Viewport,
    planes: ClipPlanes,
    /// The view volume without guard band: lines are clipped to it, points outside it
    /// are discarded.
    line_planes: ClipPlanes,
    flat: bool,
    /// Two-sided lighting: back-facing polygons take the back colors.
    two_side: bool,
    cull: Option<GLenum>,
    front_ccw: bool,
    offset: Option<(f32, f32)>,
    depth_bits: u32,
    /// The depth buffer stores floats (ARB_depth_buffer_float): polygon offset units are
    /// scaled per primitive, by the exponent of its largest depth.
    float_depth: bool,
    /// Framebuffer height (for llvmpipe's y-down window space).
    height: i32,
    line_width: f32,
    point_size: f32,
    /// GL_POINT_DISTANCE_ATTENUATION's coefficients with GL_POINT_SIZE_MIN/MAX, when they
    /// attenuate (not (1, 0, 0)); `point_size` is used unchanged otherwise.
    point_attenuation: Option<PointAttenuation>,
    /// glPolygonMode of front and back faces.
    mode_front: GLenum,
    mode_back: GLenum,
    /// The depth offsets of polygons drawn as lines and as points: (factor, units × 2r),
    /// r the depth buffer's resolution, as Mesa's offset stage applies them; (factor,
    /// units) on a float depth buffer, whose r depends on the primitive.
    offset_line: Option<(f32, f32)>,
    offset_point: Option<(f32, f32)>,
    /// GL_POLYGON_OFFSET_CLAMP (EXT_polygon_offset_clamp): the bound of every offset.
    offset_clamp: f32,
    /// The attributes interpolated over filled polygons for the stages this draw enables
    /// (none when only color is needed).
    varyings: Vec<Attribute>,
    /// How filled triangles interpolate.
    accuracy: Accuracy,
    /// GL_LINE_SMOOTH, GL_POINT_SMOOTH and GL_POLYGON_SMOOTH: the draw's lines, points or
    /// filled polygons are set up as smooth jobs (coverage in alpha) instead of aliased ones.
    smooth_lines: bool,
    smooth_points: bool,
    smooth_polygons: bool,
    /// Lines and points cover samples (a multisampled target with GL_MULTISAMPLE on; set by
    /// `draw_part` from the draw state).
    per_sample: bool,
}

impl Context {
    /// Draws `vertices` as primitives of `mode` (GL_POINTS … GL_POLYGON, already validated),
    /// with the current state. Vertex sources (glBegin/glEnd, glDrawArrays, …) call this.
    pub fn draw_vertices(&mut self, mode: GLenum, vertices: &[Vertex]) {
        self.draw_part(mode, vertices, DrawPart::WHOLE);
    }

    /// As [`Context::draw_vertices`] for one part of a long connected primitive (see
    /// [`DrawPart`]): the line stipple continues from the previous part, and only the first
    /// and last parts of a polygon draw its first and closing outline edges. Parts are
    /// delivered only while rendering (selection and feedback take primitives whole).
    pub fn draw_part(&mut self, mode: GLenum, vertices: &[Vertex], part: DrawPart) {
        if !self.rendering() {
            return self.select_vertices(mode, vertices);
        }
        let Some((width, height, color_format, depth_bits, stencil_bits)) = self.target_format() else {
            return;
        };
        if vertices.is_empty() {
            return;
        }
        let float_color = color_format.is_float();
        let mut scene = self.take_scene(width, height);
        // Mesa analyses changed matrices at draw time; their flags decide how products round.
        self.matrices.validate();
        let state = self.draw_state(&mut scene, width, height, color_format, depth_bits, stencil_bits);
        let description = debug::enabled("pipeline").then(|| {
            let r = state.clip;
            let stipple = if state.polygon_stipple.is_some() { "polygon stipple → " } else { "" };
            format!("pixels [{}, {}) x [{}, {}) → {stipple}{}", r.x0, r.x1, r.y0, r.y1, state.fragment)
        });
        let per_sample = state.multisample.is_some_and(|m| m.per_sample());
        let (state_index, cached) = scene.add_state(state);
        if let Some(stages) = description {
            let how = if cached { "cached" } else { "compiled" };
            let name = debug::mode_name(mode);
            eprintln!("tessera pipeline: {name} ({} vertices), state {state_index} {how}: {stages}", vertices.len());
        }
        let clip_vertices = self.transform(vertices, float_color);
        let geometry = Geometry { per_sample, ..self.geometry(depth_bits, height) };
        let first_vertex = self.state.lighting.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
        let mut poly = Vec::new();
        let mut scratch = Vec::new();
        let polygons = (GL_TRIANGLES..=GL_POLYGON).contains(&mode);
        let outlines = polygons && (geometry.mode_front != GL_FILL || geometry.mode_back != GL_FILL);
        // Filled polygons are clipped to the guard band; points, lines and outlines to the
        // view volume.
        let planes = if polygons && !outlines { &geometry.planes } else { &geometry.line_planes };
        let outcodes: Vec<u32> = clip_vertices.iter().map(|v| planes.outcode(v)).collect();
        let mut stipple = self.active_line_stipple();
        if let (false, Some(s)) = (part.first, stipple.as_mut()) {
            s.counter = self.vertex_input.stipple_counter;
        }
        if outlines {
            let mut outline = Outline { scene: &mut scene, state: state_index, g: &geometry, stipple, first_vertex };
            decompose_outlines(mode, clip_vertices.len() as u32, first_vertex, part, |t| {
                let v = t.v.map(|i| &clip_vertices[i as usize]);
                let codes = t.v.map(|i| outcodes[i as usize]);
                outline.triangle(v, codes, t, &mut poly, &mut scratch);
            });
            let stipple = outline.stipple;
            self.end_part(scene, stipple, part);
            return;
        }
        let split = if !first_vertex && mode == GL_QUADS && geometry.leaves_view_volume(&clip_vertices) {
            QuadSplit::SecondDiagonal
        } else {
            QuadSplit::FirstDiagonal
        };
        assemble(mode, clip_vertices.len() as u32, first_vertex, split, |primitive| match primitive {
            Primitive::Point(i) => {
                let i = i as usize;
                if outcodes[i] == 0 {
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
                let provoking = &clip_vertices[provoking as usize];
                let flat_color = geometry.flat.then_some(provoking.color);
                let (a, b) = (a as usize, b as usize);
                let codes = [outcodes[a], outcodes[b]];
                if geometry.flat {
                    // Flat shading covers the secondary color too (the lit specular term).
                    let secondary_color = provoking.secondary_color;
                    let ea = ClipVertex { secondary_color, ..clip_vertices[a] };
                    let eb = ClipVertex { secondary_color, ..clip_vertices[b] };
                    emit_clip_line(&mut scene, state_index, &geometry, [&ea, &eb], codes, flat_color, stipple.as_mut());
                } else {
                    let ends = [&clip_vertices[a], &clip_vertices[b]];
                    emit_clip_line(&mut scene, state_index, &geometry, ends, codes, flat_color, stipple.as_mut());
                }
            }
            Primitive::Triangle { v, provoking, .. } => {
                let [a, b, c] = v.map(|i| i as usize);
                let (oa, ob, oc) = (outcodes[a], outcodes[b], outcodes[c]);
                if oa & ob & oc != 0 {
                    return;
                }
                let flat = geometry.flat.then(|| FlatColors::of(&clip_vertices[provoking as usize]));
                if oa | ob | oc == 0 {
                    let (va, vb, vc) = (&clip_vertices[a], &clip_vertices[b], &clip_vertices[c]);
                    let viewport = &geometry.viewport;
                    let w = [viewport.window(va), viewport.window(vb), viewport.window(vc)];
                    let back = [va.back_colors, vb.back_colors, vc.back_colors];
                    emit_shaded_triangle(&mut scene, state_index, &geometry, w, back, flat);
                } else {
                    poly.clear();
                    poly.extend([clip_vertices[a], clip_vertices[b], clip_vertices[c]]);
                    geometry.planes.clip_polygon(&mut poly, &mut scratch, oa | ob | oc);
                    if poly.len() < 3 {
                        return;
                    }
                    let w: Vec<WindowVertex> = poly.iter().map(|v| geometry.viewport.window(v)).collect();
                    for i in 1..w.len() - 1 {
                        let back = [poly[0].back_colors, poly[i].back_colors, poly[i + 1].back_colors];
                        emit_shaded_triangle(&mut scene, state_index, &geometry, [w[0], w[i], w[i + 1]], back, flat);
                    }
                }
            }
        });
        self.end_part(scene, stipple, part);
    }

    /// After a draw (or a part of one): keeps the line stipple counter for the next part, and
    /// keeps the scene for more draws, or renders it when it has grown past
    /// [`Scene::BUDGET_BYTES`] so that memory stays bounded however much is drawn between
    /// flush points. Rendering part of the recorded primitives early changes no pixel: each
    /// pixel still sees every primitive in submission order.
    fn end_part(&mut self, scene: Scene, stipple: Option<LineStipple>, part: DrawPart) {
        if let (false, Some(s)) = (part.last, stipple) {
            self.vertex_input.stipple_counter = s.counter;
        }
        self.keep_scene(scene);
    }

    /// Puts `scene` back as the pending scene, or renders it when it is over its budget.
    fn keep_scene(&mut self, scene: Scene) {
        if scene.recorded_bytes() > Scene::BUDGET_BYTES {
            self.run_scene(scene);
        } else {
            self.scene = Some(scene);
        }
    }

    /// Adds a pixel rectangle to the scene under the current state; `make` builds it from the
    /// varyings the draw's stages read (none when only color is needed).
    pub(super) fn draw_pixel_rect(&mut self, make: impl FnOnce(&[Attribute]) -> crate::raster::pixels::PixelRectJob) {
        let Some((width, height, color_format, depth_bits, stencil_bits)) = self.target_format() else {
            return;
        };
        let mut scene = self.take_scene(width, height);
        let state = self.draw_state(&mut scene, width, height, color_format, depth_bits, stencil_bits);
        let (state_index, _) = scene.add_state(state);
        let job = make(&self.varyings_needed());
        scene.add(state_index, job.bounds(), RasterPrimitive::Pixels(job));
        self.keep_scene(scene);
    }

    /// The bound framebuffer's size, color format and depth/stencil bits; `None` (with
    /// GL_INVALID_FRAMEBUFFER_OPERATION for an incomplete framebuffer object) when there is
    /// nothing to draw into.
    fn target_format(&mut self) -> Option<(usize, usize, ColorFormat, u32, u32)> {
        if !self.check_framebuffer_complete(true) {
            return None;
        }
        let (width, height, config) = self.framebuffer_shape(true)?;
        let ds = config.depth_stencil;
        Some((width, height, config.color, ds.depth_bits(), ds.stencil_bits()))
    }

    /// The scene to record into for a `width` × `height` framebuffer: the pending one, or a
    /// new one after rendering what was recorded for a drawable that has since been resized.
    fn take_scene(&mut self, width: usize, height: usize) -> Scene {
        match self.scene.take() {
            Some(scene) if scene.size() == (width, height) => scene,
            other => {
                if let Some(old) = other {
                    self.run_scene(old);
                }
                Scene::new(width, height)
            }
        }
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

    /// The attributes beyond color that the enabled per-fragment stages read: the secondary
    /// color for the color sum, the fog coordinate for fog, and the texture coordinates of
    /// every unit with a texture target enabled. Nothing else is interpolated.
    pub(super) fn varyings_needed(&self) -> Vec<Attribute> {
        let mut needed = Vec::new();
        if self.color_sum_active() {
            needed.extend((0..3).map(Attribute::secondary_color));
        }
        if self.state.fog.enabled {
            needed.push(Attribute::FOG_COORD);
        }
        for (unit, _) in self.enabled_texture_units() {
            needed.extend((0..4).map(|c| Attribute::tex_coord(unit, c)));
        }
        needed
    }

    /// Whether the color sum adds the secondary color: GL_COLOR_SUM without lighting; with
    /// lighting, GL_SEPARATE_SPECULAR_COLOR (the secondary color is then the specular term;
    /// under GL_SINGLE_COLOR it is zero and adding it changes nothing).
    pub(super) fn color_sum_active(&self) -> bool {
        if self.state.lighting.enabled {
            self.state.lighting.color_control == GL_SEPARATE_SPECULAR_COLOR
        } else {
            self.state.fog.color_sum
        }
    }

    /// The fragment state and clip rectangle of a draw.
    fn draw_state(
        &self,
        scene: &mut Scene,
        width: usize,
        height: usize,
        color_format: ColorFormat,
        depth_bits: u32,
        stencil_bits: u32,
    ) -> DrawState {
        let float_color = color_format.is_float();
        let depth = (self.state.depth.test && depth_bits > 0)
            .then_some(DepthTest { func: self.state.depth.func, write: self.state.depth.write_mask });
        let mut color_masks = vec![None; scene.target_count()];
        let mut buffer_of = vec![None; scene.target_count()];
        for (slot, index) in self.draw_targets() {
            let target = scene.target_index(slot);
            if color_masks.len() <= target {
                color_masks.resize(target + 1, None);
                buffer_of.resize(target + 1, None);
            }
            color_masks[target] = Some(self.write_mask(slot, index));
            buffer_of[target] = Some(index);
        }
        let clamp_float = match self.state.color.clamp_fragment_color {
            GL_FIXED_ONLY => !float_color,
            c => c == GL_TRUE as GLenum,
        };
        let clip = self.clip_rect(Rect::from_xywh(0, 0, width as i32, height as i32));
        let [vx, vy, vw, vh] = self.state.viewport.rect;
        let fill_clip = clip.intersect(Rect::from_xywh(vx, vy, vw, vh));
        let polygon_stipple = self.state.polygon.stipple.then_some(self.state.polygon_stipple);
        let mut fragment = FragmentState::plain(depth, color_masks, clamp_float);
        if self.state.transform.depth_clamp {
            // ARB_depth_clamp: near/far clipping is off (`geometry`), and fragment depths
            // are clamped to the depth range instead.
            let [near, far] = self.state.viewport.depth_range.map(|d| d as f32);
            fragment.depth_clamp = Some([near.min(far), near.max(far)]);
        }
        self.compile_fragment_ops(&mut fragment, &buffer_of, color_format, stencil_bits);
        if self.accuracy == Accuracy::Fast {
            fragment.dither = false;
        }
        // Texture coordinates follow the secondary color and the fog coordinate among the
        // varyings (`varyings_needed`).
        let first_slot = 3 * usize::from(self.color_sum_active()) + usize::from(self.state.fog.enabled);
        fragment.texturing = self.compile_texturing(first_slot, height as i32).map(std::sync::Arc::new);
        let samples_passed = self.queries.active_counter();
        let multisample = self.multisample_state(self.framebuffer_samples());
        DrawState { fragment, clip, fill_clip, polygon_stipple, samples_passed, multisample }
    }

    /// GL_LINE_STIPPLE's state at the start of a draw, when enabled.
    fn active_line_stipple(&self) -> Option<LineStipple> {
        let lp = &self.state.line_point;
        lp.line_stipple.then_some(LineStipple {
            factor: lp.line_stipple_factor.clamp(1, 256),
            pattern: lp.line_stipple_pattern,
            counter: 0,
        })
    }

    /// Vertices to clip space, with their eye coordinates and clamped colors.
    fn transform(&self, vertices: &[Vertex], float_color: bool) -> Vec<ClipVertex> {
        self.transform_units(vertices, float_color, &self.tex_coord_units())
    }

    /// As [`Context::transform`], with texgen and the texture matrices applied to the
    /// coordinates of `tex_units` (glRasterPos: every unit).
    pub(super) fn transform_units(
        &self,
        vertices: &[Vertex],
        float_color: bool,
        tex_units: &[super::texture_env::TexCoordUnit],
    ) -> Vec<ClipVertex> {
        let modelview = self.matrices.modelview();
        let mvp: Mat4 = self.matrices.model_project();
        let clamp = match self.state.lighting.clamp_vertex_color {
            GL_FIXED_ONLY => !float_color,
            c => c == GL_TRUE as GLenum,
        };
        let clamp4 = |c: [f32; 4]| if clamp { c.map(|x| if x > 0.0 { x.min(1.0) } else { 0.0 }) } else { c };
        // The fog coordinate of each vertex, interpolated to the fragments: Mesa's
        // fixed-function vertex program computes the eye distance per vertex too. The fog
        // factor is per fragment whatever GL_FOG_HINT says: Mesa 22 draws identical images
        // under GL_NICEST and GL_FASTEST (capi fragment_ops_fog).
        let fog = &self.state.fog;
        let fog_coord = |v: &Vertex, eye: Vec4| match (fog.coord_src, fog.distance_mode) {
            (GL_FOG_COORD, _) => v.fog_coord,
            (_, GL_EYE_RADIAL_NV) => eye.truncate().length(),
            (_, GL_EYE_PLANE) => eye.z,
            _ => eye.z.abs(),
        };
        let mut out: Vec<ClipVertex> = vertices
            .iter()
            .map(|v| {
                let p = Vec4::from_array(v.position);
                let eye = modelview * p;
                ClipVertex {
                    clip: (mvp * p).to_array(),
                    eye: eye.to_array(),
                    color: clamp4(v.color),
                    secondary_color: clamp4(v.secondary_color),
                    back_colors: [[0.0; 4]; 2],
                    tex_coords: if tex_units.is_empty() {
                        v.tex_coords
                    } else {
                        self.vertex_tex_coords(v, eye, tex_units)
                    },
                    fog_coord: if fog.enabled { fog_coord(v, eye) } else { v.fog_coord },
                    edge_flag: v.edge_flag,
                }
            })
            .collect();
        // Lighting is a pass of its own: unlit draws do not see it.
        if self.state.lighting.enabled {
            self.light_vertices(vertices, &mut out, &clamp4);
        }
        out
    }

    /// Replaces the colors of `out` by the lit colors of `vertices` (GL 2.1 section 2.14.1),
    /// the back-face colors too under two-sided lighting.
    fn light_vertices(&self, vertices: &[Vertex], out: &mut [ClipVertex], clamp4: &dyn Fn([f32; 4]) -> [f32; 4]) {
        let transform = &self.state.transform;
        let normals = if transform.normalize {
            NormalScaling::Normalize
        } else if transform.rescale_normal {
            NormalScaling::Rescale(self.matrices.normal_rescale())
        } else {
            NormalScaling::None
        };
        let inverse = self.matrices.modelview_inverse().to_cols_array();
        let mut lighting = Lighting::new(&self.state.lighting, inverse, normals);
        // glMaterial between glBegin and glEnd: each mark applies from its vertex on.
        let marks = &self.vertex_input.material_marks;
        let mut next_mark = 0;
        for (i, (v, c)) in vertices.iter().zip(out.iter_mut()).enumerate() {
            while next_mark < marks.len() && marks[next_mark].0 <= i {
                lighting.set_materials(&marks[next_mark].1);
                next_mark += 1;
            }
            let lit = lighting.shade(c.eye, v.normal, v.color);
            c.color = clamp4(lit.front);
            c.secondary_color = clamp4(lit.front_secondary);
            c.back_colors = [clamp4(lit.back), clamp4(lit.back_secondary)];
        }
    }

    /// The per-draw geometry constants.
    fn geometry(&self, depth_bits: u32, height: usize) -> Geometry {
        let [x, y, w, h] = self.state.viewport.rect;
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
            zero_to_one: self.clip_zero_to_one(),
            user,
        };
        let lp = &self.state.line_point;
        // Mesa's offset stage scales units by twice the depth buffer's resolution.
        let (depth_scale, depth_offset) = self.depth_transform();
        let float_depth = self.draw_config().depth_stencil.is_float_depth();
        let units_scale = if float_depth {
            1.0
        } else if depth_bits > 0 {
            (2.0 / ((1u64 << depth_bits) - 1) as f64) as f32
        } else {
            0.0
        };
        Geometry {
            accuracy: self.accuracy,
            smooth_lines: lp.line_smooth,
            smooth_points: lp.point_smooth,
            smooth_polygons: polygon.smooth,
            per_sample: false,
            varyings: self.varyings_needed(),
            // glClipControl decides the depth mapping and the sign of y (ARB_clip_control).
            viewport: Viewport {
                scale: [half[0], half[1] * self.viewport_y_sign(), depth_scale as f32],
                offset: [centre[0], centre[1], depth_offset as f32],
                offset_down: height as f32 - centre[1],
            },
            line_planes: ClipPlanes { guard_x: 1.0, guard_y: 1.0, ..planes.clone() },
            planes,
            height: height as i32,
            line_width: lp.line_width.min(MAX_LINE_WIDTH),
            point_size: point_size(lp),
            point_attenuation: (lp.point_distance_attenuation != [1.0, 0.0, 0.0]).then_some(PointAttenuation {
                size: lp.point_size,
                coefficients: lp.point_distance_attenuation,
                min: lp.point_size_min,
                max: lp.point_size_max,
            }),
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
            two_side: self.state.lighting.enabled && self.state.lighting.two_side,
            cull: polygon.cull_face.then_some(polygon.cull_face_mode),
            // GL_UPPER_LEFT mirrors y, and with it every polygon's window winding: the facing
            // rule is mirrored too (ARB_clip_control), as Mesa flips front_ccw.
            front_ccw: (polygon.front_face == GL_CCW) != (self.viewport_y_sign() < 0.0),
            offset: polygon.offset_fill.then_some((polygon.offset_factor, polygon.offset_units)),
            offset_clamp: polygon.offset_clamp,
            depth_bits,
            float_depth,
        }
    }
}

impl Geometry {
    /// Whether any vertex lies outside the view volume (not only the guard band) or an
    /// enabled user clip plane: where Mesa's draw module takes its pipeline path.
    fn leaves_view_volume(&self, vertices: &[ClipVertex]) -> bool {
        vertices.iter().any(|v| self.line_planes.outcode(v) != 0)
    }
}

/// The size points are drawn with without distance attenuation: glPointSize clamped to
/// GL_POINT_SIZE_MIN/MAX (the minimum winning when they cross, as in Mesa) and to the
/// implementation's range.
fn point_size(lp: &LinePointState) -> f32 {
    clamp_point_size(lp.point_size, lp.point_size_min, lp.point_size_max)
}

/// `size` clamped to [min, max] (min winning when they cross; NaN gives min) and to the
/// implementation's range.
fn clamp_point_size(size: f32, min: f32, max: f32) -> f32 {
    let size = if size.is_nan() || size < min {
        min
    } else if size > max {
        max
    } else {
        size
    };
    size.min(MAX_POINT_SIZE)
}

/// Point parameters' distance attenuation (GL 1.4, GL 2.1 §3.4): the derived size
/// `size · 1/√(a + b·d + c·d²)` clamped to GL_POINT_SIZE_MIN/MAX. As Mesa's fixed-function
/// vertex program, d is |z| of the eye coordinates (the spec's distance to the eye,
/// approximated along the view axis; the same on the view axis) and the square root is of
/// the absolute value. Without multisampling the derived size is the point's width (the
/// fade threshold applies to multisampled points only).
#[derive(Clone, Copy, Debug)]
struct PointAttenuation {
    size: f32,
    coefficients: [f32; 3],
    min: f32,
    max: f32,
}

impl PointAttenuation {
    fn size_at(&self, eye: [f32; 4]) -> f32 {
        let d = eye[2].abs();
        let [a, b, c] = self.coefficients;
        let factor = d.mul_add(c, b).mul_add(d, a);
        clamp_point_size(self.size / factor.abs().sqrt(), self.min, self.max)
    }
}

impl Geometry {
    /// The width of a point whose vertex has eye coordinates `eye`.
    fn point_size_at(&self, eye: [f32; 4]) -> f32 {
        self.point_attenuation.map_or(self.point_size, |a| a.size_at(eye))
    }
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
fn decompose_outlines(
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
        let flat = self.g.flat.then(|| FlatColors::of(v[if self.first_vertex { 0 } else { 2 }]));
        let corner = |c: &ClipVertex, fused: bool| {
            (
                self.g.viewport.window_down(c, fused),
                self.g.viewport.window(c),
                c.back_colors,
                self.g.point_size_at(c.eye),
            )
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
            if self.first_vertex {
                self.draw([w[0], w[i - 1], w[i]], [start, middle, end], i == 2, flat);
            } else {
                self.draw([w[i - 1], w[i], w[0]], [middle, end, start], i == 2, flat);
            }
        }
    }

    /// Culls, offsets and draws one (clipped) triangle in its face's mode; `w` holds each
    /// corner in y-down and in GL window coordinates.
    fn draw(&mut self, w: [Corner; 3], edges: [bool; 3], first: bool, flat: Option<FlatColors>) {
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
                emit_shaded_triangle(self.scene, self.state, g, w.map(|c| c.1), w.map(|c| c.2), flat);
                return;
            }
        };
        if let Some((factor, units)) = offset {
            // Mesa's offset stage: the larger depth slope of the triangle, applied per vertex.
            let inv_det = 1.0 / det;
            let dzdx = ((ey * fz - ez * fy) * inv_det).abs();
            let dzdy = ((ez * fx - ex * fz) * inv_det).abs();
            let units = if g.float_depth { units * float_depth_resolution(l.iter().map(|c| c.z)) } else { units };
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
type Corner = (LineVertex, WindowVertex, [[f32; 4]; 2], f32);

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

/// The colors of a flat-shaded primitive: its provoking vertex's front primary and
/// secondary colors, and its back ones.
#[derive(Clone, Copy, Debug)]
struct FlatColors {
    front: [[f32; 4]; 2],
    back: [[f32; 4]; 2],
}

impl FlatColors {
    fn of(v: &ClipVertex) -> Self {
        FlatColors { front: [v.color, v.secondary_color], back: v.back_colors }
    }
}

/// Whether a window-space triangle faces front (GL_FRONT_FACE).
fn faces_front(g: &Geometry, w: &[WindowVertex; 3]) -> bool {
    let area2 = (w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[2].x - w[0].x) * (w[1].y - w[0].y);
    (area2 > 0.0) == g.front_ccw
}

/// Emits a filled triangle with the colors of its facing: the back colors `back` of its
/// corners when it faces back under two-sided lighting, and the provoking vertex's colors
/// (primary and secondary) under flat shading.
fn emit_shaded_triangle(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    mut w: [WindowVertex; 3],
    back: [[[f32; 4]; 2]; 3],
    flat: Option<FlatColors>,
) {
    let use_back = g.two_side && !faces_front(g, &w);
    if use_back {
        for (c, b) in w.iter_mut().zip(back) {
            (c.color, c.secondary_color) = (b[0], b[1]);
        }
    }
    let flat = flat.map(|f| if use_back { f.back } else { f.front });
    if let Some([_, secondary]) = flat {
        for c in &mut w {
            c.secondary_color = secondary;
        }
    }
    emit_triangle(scene, state, g, w, flat.map(|f| f[0]));
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
    let offset =
        g.offset.map_or(0.0, |(factor, units)| clamp_offset(polygon_offset(&w, factor, units, g), g.offset_clamp));
    let varyings: Vec<[f32; 3]> = g.varyings.iter().map(|a| w.map(|v| a.of(&v))).collect();
    if g.smooth_polygons {
        if let Some(job) = SmoothTriangle::new(w, flat, offset, &varyings, front) {
            let job = SmoothJob::Triangle(Box::new(job));
            scene.add(state, job.bounds(), RasterPrimitive::Smooth(job));
        }
        return;
    }
    if let Some(mut job) = TriangleJob::with_accuracy(g.accuracy, w, flat, offset, &varyings) {
        job.front_facing = front;
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

/// `from + t · (to − from)` for the clip position and attributes of a clipped line end.
fn lerp_clip(from: &ClipVertex, to: &ClipVertex, t: f32) -> ClipVertex {
    let mix = |a: [f32; 4], b: [f32; 4]| std::array::from_fn(|i| a[i] + t * (b[i] - a[i]));
    ClipVertex {
        clip: mix(from.clip, to.clip),
        color: mix(from.color, to.color),
        secondary_color: mix(from.secondary_color, to.secondary_color),
        tex_coords: std::array::from_fn(|u| mix(from.tex_coords[u], to.tex_coords[u])),
        fog_coord: from.fog_coord + t * (to.fog_coord - from.fog_coord),
        ..*from
    }
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
    // Smooth lines count their stipple along their true (Euclidean) length, as Mesa's
    // draw module does for them.
    let (dx, dy) = ((a.x - b.x).abs(), (a.y_down - b.y_down).abs());
    let length = if g.smooth_lines { (dx * dx + dy * dy).sqrt() } else { dx.max(dy) };
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
            secondary_color: std::array::from_fn(|i| mix(a.secondary_color[i], b.secondary_color[i])),
            tex_coords: std::array::from_fn(|u| std::array::from_fn(|i| mix(a.tex_coords[u][i], b.tex_coords[u][i]))),
            fog_coord: mix(a.fog_coord, b.fog_coord),
        }
    };
    let start = if t0 > 0.0 { at(t0) } else { *a };
    let end = if t1 < 1.0 { at(t1) } else { *b };
    emit_line_job(scene, state, g, &start, &end, flat);
}

fn emit_line_job(scene: &mut Scene, state: u32, g: &Geometry, a: &LineVertex, b: &LineVertex, flat: Option<[f32; 4]>) {
    let varyings: Vec<[f32; 2]> = g.varyings.iter().map(|v| [v.of_line(a), v.of_line(b)]).collect();
    if g.smooth_lines {
        if let Some(job) = SmoothLine::new(a, b, g.line_width, g.height, flat, &varyings) {
            let job = SmoothJob::Line(Box::new(job));
            scene.add(state, job.bounds(), RasterPrimitive::Smooth(job));
        }
        return;
    }
    if g.per_sample {
        // The rectangle of the unrounded width, as llvmpipe draws it on a multisampled target
        // (widths below 1 draw as 1 there, Mesa's minimum line width).
        let up = |v: &LineVertex| [v.x, g.height as f32 - v.y_down];
        let quad = SampleQuad::line(up(a), up(b), g.line_width.max(1.0));
        if let Some(job) = quad.and_then(|quad| LineJob::covering_samples(a, b, g.height, flat, &varyings, quad)) {
            scene.add(state, job.bounds(), RasterPrimitive::Line(job));
        }
        return;
    }
    if let Some(job) = LineJob::new(a, b, g.line_width, g.height, flat, &varyings) {
        let (bounds, setup) = (job.bounds(), job.setup().clone());
        scene.add_narrow(state, bounds, RasterPrimitive::Line(job), |y0, y1| setup.columns(y0, y1));
    }
}

/// Emits a point whose vertex is inside the view volume.
fn emit_point(scene: &mut Scene, state: u32, g: &Geometry, v: &ClipVertex) {
    let w = g.viewport.window_down(v, true);
    emit_window_point(scene, state, g, &w, g.point_size_at(v.eye));
}

fn emit_window_point(scene: &mut Scene, state: u32, g: &Geometry, w: &LineVertex, size: f32) {
    // llvmpipe interpolates point colors perspective-correctly too: (c/w)·w.
    let color = if w.inv_w == 1.0 { w.color } else { w.color.map(|c| c * w.inv_w * (1.0 / w.inv_w)) };
    let varyings = g.varyings.iter().map(|v| v.of_line(w)).collect();
    if g.per_sample {
        // The square of the unrounded size, as llvmpipe draws it on a multisampled target
        // (sizes below 1 draw as 1 there, as for aliased points); GL_POINT_SMOOTH changes
        // nothing there (measured on Mesa 22.3; GL 2.1 §3.3.3 would make it a circle).
        if let Some(square) = SampleQuad::point([w.x, g.height as f32 - w.y_down], size.max(1.0)) {
            let (x0, y0, x1, y1) = square.pixel_box();
            let rect = Rect { x0, y0, x1, y1 };
            let sample_square = Some(Box::new(square));
            scene.add(state, rect, RasterPrimitive::Point(PointJob { rect, z: w.z, color, varyings, sample_square }));
        }
        return;
    }
    if g.smooth_points {
        if let Some(job) = SmoothPoint::new(w, size, g.height, color, varyings) {
            let job = SmoothJob::Point(Box::new(job));
            scene.add(state, job.bounds(), RasterPrimitive::Smooth(job));
        }
        return;
    }
    let rect = point_rect(w.x, w.y_down, size, g.height);
    let point = PointJob { rect, z: w.z, color, varyings, sample_square: None };
    scene.add(state, rect, RasterPrimitive::Point(point));
}

/// A polygon offset bounded by GL_POLYGON_OFFSET_CLAMP as EXT_polygon_offset_clamp says:
/// at most `clamp` when it is positive, at least `clamp` when negative, unbounded when it
/// is 0 (or NaN).
fn clamp_offset(offset: f32, clamp: f32) -> f32 {
    if clamp > 0.0 {
        offset.min(clamp)
    } else if clamp < 0.0 {
        offset.max(clamp)
    } else {
        offset
    }
}

/// The smallest resolvable difference r of a float depth buffer for a primitive whose
/// depths are `z` (GL 3.0 §3.6.5, ARB_depth_buffer_float): 2^(e − 23), e the exponent of
/// the largest |z|. Computed on the bit pattern as Mesa's offset stage does, including its
/// clamp to 0 when e − 23 falls below the smallest exponent (llvmpipe's triangle setup
/// omits that clamp and scales by a huge negative number for depths below 2⁻¹⁰³, which
/// no program relies on).
fn float_depth_resolution(z: impl Iterator<Item = f32>) -> f32 {
    let max = z.fold(0.0f32, |m, z| m.max(z.abs()));
    let exponent = (max.to_bits() & (0xff << 23)) as i32;
    f32::from_bits((exponent - (23 << 23)).max(0) as u32)
}

/// glPolygonOffset's depth offset for a triangle: factor × max depth slope + units × r,
/// where r is the smallest resolvable difference of the depth buffer.
fn polygon_offset(w: &[WindowVertex; 3], factor: f32, units: f32, g: &Geometry) -> f32 {
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
    let r = if g.float_depth {
        float_depth_resolution(w.iter().map(|v| v.z))
    } else if g.depth_bits > 0 {
        1.0 / ((1u64 << g.depth_bits) - 1) as f32
    } else {
        0.0
    };
    factor * slope + units * r
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, Drawable, FramebufferConfig};
    use crate::gl::CompareFunc;
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

    /// A vertex at (x, y, z) of `color` with default attributes (shared by the context's
    /// draw tests).
    pub(in crate::context) fn vertex(x: f32, y: f32, z: f32, color: [f32; 4]) -> Vertex {
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

    fn slot_pixel(ctx: &mut Context, d: &Arc<Mutex<Drawable>>, slot: ColorSlot, x: i32, y: i32) -> [u8; 4] {
        ctx.flush_rendering();
        let mut row = Vec::new();
        d.lock().unwrap().framebuffer.color(slot).unwrap().read_row_f32(y, x, x + 1, &mut row);
        row[0].map(|c| (c * 255.0).round() as u8)
    }

    fn square(ctx: &mut Context, x0: f32, y0: f32, x1: f32, y1: f32, color: [f32; 4]) {
        let v = |x, y| vertex(x, y, 0.0, color);
        ctx.draw_vertices(GL_QUADS, &[v(x0, y0), v(x1, y0), v(x1, y1), v(x0, y1)]);
    }

    #[test]
    fn each_draw_buffer_blends_with_its_own_state() {
        let visual = FramebufferConfig {
            aux_buffers: 2,
            ..FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, DepthStencilFormat::None, 0)
        };
        let (mut ctx, d) = Context::with_test_drawable(visual, 4, 4);
        ctx.matrix_mode(GL_PROJECTION);
        ctx.ortho(0.0, 4.0, 0.0, 4.0, -1.0, 1.0);
        ctx.draw_buffers(&[GL_FRONT_LEFT, GL_AUX0, GL_AUX0 + 1]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.clear_color([0.5; 4]);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        // Buffer 0 adds, buffer 1 modulates (glBlendFunci), buffer 2 does not blend.
        ctx.set_capability_indexed(GL_BLEND, 0, true);
        ctx.set_capability_indexed(GL_BLEND, 1, true);
        ctx.blend_func(Some(0), GL_ONE, GL_ONE, GL_ONE, GL_ONE);
        ctx.blend_func(Some(1), GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_SRC_COLOR);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let mut scene = Scene::new(4, 4);
        let state = ctx.draw_state(&mut scene, 4, 4, ColorFormat::Unorm8 { alpha: true }, 0, 0);
        assert!(state.fragment.blend[0].is_some() && state.fragment.blend[1].is_some());
        assert_eq!(state.fragment.blend[2], None, "a buffer with blending off has no blend stage");
        square(&mut ctx, 0.0, 0.0, 4.0, 4.0, [0.25, 0.5, 0.75, 0.5]);
        // The source is (64, 128, 191, 128) in 8 bits, the destination 128.
        assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::FrontLeft, 1, 1), [192, 255, 255, 255]);
        assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::Aux(0), 1, 1), [32, 64, 96, 64]);
        assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::Aux(1), 1, 1), [64, 128, 191, 128]);
        // The logic op replaces blending on every buffer.
        ctx.set_capability(GL_COLOR_LOGIC_OP, true);
        ctx.logic_op(GL_XOR);
        square(&mut ctx, 0.0, 0.0, 4.0, 4.0, [1.0, 0.0, 1.0, 0.0]);
        assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::FrontLeft, 1, 1), [63, 255, 0, 255]);
        assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::Aux(0), 1, 1), [223, 64, 159, 64]);
        assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::Aux(1), 1, 1), [191, 128, 64, 128]);
    }

    #[test]
    fn disabled_stages_are_absent_from_the_compiled_state() {
        let (mut ctx, _d) = context(4, 4);
        let mut scene = Scene::new(4, 4);
        let compile = |ctx: &Context, scene: &mut Scene, format, stencil_bits| {
            ctx.draw_state(scene, 4, 4, format, 24, stencil_bits).fragment
        };
        let rgba8 = ColorFormat::Unorm8 { alpha: true };
        let f = compile(&ctx, &mut scene, rgba8, 8);
        assert_eq!((f.alpha, f.stencil, f.logic_op, f.dither), (None, None, None, false));
        assert!(f.blend.iter().all(|b| b.is_none()));
        // GL_DITHER is on by default but only RGB565 targets dither.
        assert!(compile(&ctx, &mut scene, ColorFormat::Rgb565, 8).dither);
        ctx.set_capability(GL_STENCIL_TEST, true);
        ctx.set_capability(GL_ALPHA_TEST, true);
        ctx.set_capability(GL_BLEND, true);
        ctx.set_capability(GL_COLOR_LOGIC_OP, true);
        let f = compile(&ctx, &mut scene, rgba8, 8);
        assert!(f.alpha.is_some() && f.stencil.is_some() && f.logic_op.is_some());
        assert!(f.blend.iter().all(|b| b.is_none()), "the logic op replaces blending");
        assert_eq!(compile(&ctx, &mut scene, rgba8, 0).stencil, None, "no stencil bits, no stencil test");
        // Float buffers blend: the logic op does not apply to them.
        let f = compile(&ctx, &mut scene, ColorFormat::Float32 { alpha: true }, 8);
        assert!(f.logic_op.is_none() && f.blend.iter().all(|b| b.is_some()));
    }

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

    /// Horizontal, vertical, diagonal, shallow and steep lines; pixel-centre, integer and
    /// fractional endpoints; both directions of one steep segment (its centre tie goes
    /// differently each way).
    #[test]
    fn width_1_lines_follow_the_diamond_exit_rule_as_llvmpipe() {
        let script = "
            size 16 16; color 1 1 1 1; clear 0 0 0 0; begin lines; v 1.5 1.5; v 6.5 1.5; v 6.5 3.5
            v 1.5 3.5; v 8 1; v 14 1; v 1.5 5.5; v 1.5 10.5; v 3.5 10.5; v 3.5 5.5; end; lit axis_aligned
            clear 0 0 0 0; begin lines; v 1.5 1.5; v 6.5 6.5; v 12.5 1.5; v 7.5 6.5; v 1.25 8.75
            v 14.75 11.25; v 14.75 13.25; v 1.25 15.75; end; lit diagonal_and_shallow; clear 0 0 0 0
            begin lines; v 2.2 0.7; v 4.9 14.3; v 13.8 14.6; v 10.1 1.2; v 7.5 2.5; v 8.5 4.5; end
            lit steep_fractional; clear 0 0 0 0; begin lines; v 10.5 2.5; v 9.5 12.5; v 9.5 12.5; v 10.5 2.5
            end; lit both_directions_of_a_tie";
        let mesa = concat!(
            "axis_aligned: 8,0 9,0 10,0 11,0 12,0 13,0 1,1 2,1 3,1 4,1 5,1 2,3 3,3 4,3 5,3 6,3 1,5 \
             1,6 3,6 1,7 3,7 1,8 3,8 1,9 3,9 3,10\n",
            "diagonal_and_shallow: 1,1 12,1 2,2 11,2 3,3 10,3 4,4 9,4 5,5 8,5 1,8 2,8 3,9 4,9 5,9 6,9 \
             7,9 8,10 9,10 10,10 11,10 12,10 13,11 14,11 11,13 12,13 13,13 14,13 5,14 6,14 7,14 8,14 \
             9,14 10,14 1,15 2,15 3,15 4,15\n",
            "steep_fractional: 2,1 10,1 2,2 7,2 10,2 2,3 7,3 10,3 2,4 11,4 3,5 11,5 3,6 11,6 3,7 11,7 \
             3,8 12,8 3,9 12,9 4,10 12,10 4,11 12,11 4,12 13,12 4,13 13,13 13,14\n",
            "both_directions_of_a_tie: 10,2 10,3 10,4 10,5 10,6 9,7 10,7 9,8 9,9 9,10 9,11 9,12\n",
        );
        assert_eq!(replay(script), mesa);
    }

    /// Each segment draws its start pixel and not its end pixel.
    #[test]
    fn strips_and_loops_draw_shared_vertices_once() {
        let script = "
            size 16 16; color 1 1 1 1; clear 0 0 0 0; begin line_strip; v 1.5 1.5; v 8.5 1.5; v 8.5 8.5
            v 1.7 14.2; end; lit strip; clear 0 0 0 0; begin line_loop; v 2.5 2.5; v 12.5 3.5; v 7.5 12.5
            end; lit loop";
        let mesa = concat!(
            "strip: 1,1 2,1 3,1 4,1 5,1 6,1 7,1 8,1 8,2 8,3 8,4 8,5 8,6 8,7 8,8 7,9 6,10 4,11 5,11 \
             3,12 2,13\n",
            "loop: 2,2 3,2 4,2 5,2 6,2 7,2 2,3 8,3 9,3 10,3 11,3 12,3 3,4 11,4 3,5 11,5 4,6 10,6 4,7 \
             10,7 5,8 9,8 5,9 9,9 6,10 8,10 6,11 8,11 7,12\n",
        );
        assert_eq!(replay(script), mesa);
    }

    /// x-major lines get round(width) rows per column, y-major lines round(width) columns per
    /// row; 2.5 rounds up.
    #[test]
    fn wide_lines_are_widened_across_their_minor_axis() {
        let script = "
            size 16 16; color 1 1 1 1; clear 0 0 0 0; linewidth 2; begin lines; v 1.5 2.5; v 12.5 4.5
            v 13.5 6.5; v 11.5 14.5; end; lit width2; clear 0 0 0 0; linewidth 2.5; begin lines; v 1.25 3.3
            v 14.75 8.6; end; lit width2_5_is_3; clear 0 0 0 0; linewidth 4; begin lines; v 7.4 1.2
            v 8.6 13.9; end; lit width4_ymajor";
        let mesa = concat!(
            "width2: 1,2 2,2 3,2 4,2 5,2 6,2 1,3 2,3 3,3 4,3 5,3 6,3 7,3 8,3 9,3 10,3 11,3 7,4 8,4 \
             9,4 10,4 11,4 12,6 13,6 12,7 13,7 12,8 13,8 12,9 13,9 11,10 12,10 11,11 12,11 11,12 \
             12,12 11,13 12,13\n",
            "width2_5_is_3: 1,2 2,2 1,3 2,3 3,3 4,3 5,3 1,4 2,4 3,4 4,4 5,4 6,4 7,4 3,5 4,5 5,5 6,5 \
             7,5 8,5 9,5 10,5 6,6 7,6 8,6 9,6 10,6 11,6 12,6 8,7 9,7 10,7 11,7 12,7 13,7 11,8 12,8 \
             13,8 13,9\n",
            "width4_ymajor: 5,1 6,1 7,1 8,1 6,2 7,2 8,2 9,2 6,3 7,3 8,3 9,3 6,4 7,4 8,4 9,4 6,5 7,5 \
             8,5 9,5 6,6 7,6 8,6 9,6 6,7 7,7 8,7 9,7 6,8 7,8 8,8 9,8 6,9 7,9 8,9 9,9 6,10 7,10 8,10 \
             9,10 6,11 7,11 8,11 9,11 6,12 7,12 8,12 9,12 7,13 8,13 9,13 10,13\n",
        );
        assert_eq!(replay(script), mesa);
    }

    /// GL_LINES restarts the pattern for every segment; strips and loops continue it, by whole
    /// pixel steps per segment (Mesa 22); the factor repeats each bit.
    #[test]
    fn line_stipple_restarts_per_segment_of_gl_lines_only() {
        let script = "
            size 24 8; color 1 1 1 1; enable line_stipple; stipple 1 0f0f; clear 0 0 0 0; begin lines
            v 0.5 1.5; v 10.5 1.5; v 0.5 3.5; v 20.5 3.5; end; lit lines_restart; clear 0 0 0 0
            begin line_strip; v 0.5 1.5; v 6.25 1.5; v 20.5 1.5; end; lit strip_continues_by_whole_steps
            clear 0 0 0 0; stipple 3 00ff; begin line_loop; v 1.5 1.5; v 20.5 1.5; v 20.5 6.5; v 1.5 6.5
            end; lit loop_factor3";
        let mesa = concat!(
            "lines_restart: 0,1 1,1 2,1 3,1 8,1 9,1 0,3 1,3 2,3 3,3 8,3 9,3 10,3 11,3 16,3 17,3 18,3 \
             19,3\n",
            "strip_continues_by_whole_steps: 0,1 1,1 2,1 3,1 8,1 9,1 10,1 11,1 16,1 17,1 18,1 19,1\n",
            "loop_factor3: 1,1 2,1 3,1 4,1 5,1 6,1 7,1 8,1 9,1 10,1 11,1 12,1 13,1 14,1 15,1 16,1 \
             17,1 18,1 19,1 20,1 20,2 20,3 20,4 20,5\n",
        );
        assert_eq!(replay(script), mesa);
    }

    /// Odd sizes centre on the pixel containing the point, even sizes on the nearest corner;
    /// sizes round at halves down and clamp to GL_POINT_SIZE_MIN/MAX; a point whose centre is
    /// outside the view volume is discarded, a wide one inside it draws past the viewport.
    #[test]
    fn points_cover_squares_of_their_rounded_size() {
        let script = "
            size 24 24; color 1 1 1 1; clear 0 0 0 0; pointsize 1; begin points; v 2.5 2.5; v 4.0 2.0
            v 6.99 2.01; end; pointsize 2; begin points; v 2.5 6.5; v 6.2 6.7; end; pointsize 3
            begin points; v 12.5 6.5; v 17.0 6.0; end; pointsize 2.5; begin points; v 4.5 12.5; end
            pointsize 1.5; begin points; v 10.5 12.5; end; lit sizes; clear 0 0 0 0; pointsize 10
            pointminmax 2 4; begin points; v 5.5 5.5; end; pointsize 1; begin points; v 15.5 15.5; end
            pointminmax 0 255; lit clamped_to_min_max; clear 0 0 0 0; viewport 4 4 16 16
            ortho 0 16 0 16 -1 1; pointsize 5; begin points; v 0.5 0.5; v -0.5 8.5; v 15.9 15.9; end
            lit centre_in_view_decides";
        let mesa = concat!(
            "sizes: 2,2 4,2 6,2 11,5 12,5 13,5 16,5 17,5 18,5 2,6 3,6 5,6 6,6 11,6 12,6 13,6 16,6 \
             17,6 18,6 2,7 3,7 5,7 6,7 11,7 12,7 13,7 16,7 17,7 18,7 4,12 5,12 10,12 4,13 5,13\n",
            "clamped_to_min_max: 4,4 5,4 6,4 7,4 4,5 5,5 6,5 7,5 4,6 5,6 6,6 7,6 4,7 5,7 6,7 7,7 \
             15,15 16,15 15,16 16,16\n",
            "centre_in_view_decides: 2,2 3,2 4,2 5,2 6,2 2,3 3,3 4,3 5,3 6,3 2,4 3,4 4,4 5,4 6,4 2,5 \
             3,5 4,5 5,5 6,5 2,6 3,6 4,6 5,6 6,6 17,17 18,17 19,17 20,17 21,17 17,18 18,18 19,18 \
             20,18 21,18 17,19 18,19 19,19 20,19 21,19 17,20 18,20 19,20 20,20 21,20 17,21 18,21 \
             19,21 20,21 21,21\n",
        );
        assert_eq!(replay(script), mesa);
    }

    /// Smooth color and window z along a line; flat color from the last or the first vertex.
    #[test]
    fn lines_interpolate_color_and_depth_and_flat_shade_from_the_provoking_vertex() {
        let script = "
            size 16 8; enable depth_test; clear 0 0 0 0; begin lines; color 1 0 0 1; v 1.5 1.5 -0.5
            color 0 0 1 1; v 14.5 5.5 0.5; end; dump smooth; depth smooth_z; shade flat; clear 0 0 0 0
            begin line_strip; color 1 0 0 1; v 1.5 1.5; color 0 1 0 1; v 8.5 1.5; color 0 0 1 1; v 8.5 6.5
            end; dump flat_last; provoking first; clear 0 0 0 0; begin line_strip; color 1 0 0 1; v 1.5 1.5
            color 0 1 0 1; v 8.5 1.5; color 0 0 1 1; v 8.5 6.5; end; dump flat_first";
        let mesa = concat!(
            "smooth: 1,1=ff0000ff 2,1=eb0014ff 3,2=d80027ff 4,2=c4003bff 5,2=b1004eff 6,3=9d0062ff \
             7,3=890076ff 8,3=760089ff 9,3=62009dff 10,4=4e00b1ff 11,4=3b00c4ff 12,4=2700d8ff \
             13,5=1400ebff\n",
            "smooth_z: 1,1=bfffff 2,1=b62762 3,2=ac4ec4 4,2=a27627 5,2=989d89 6,3=8ec4eb 7,3=84ec4e \
             8,3=7b13b0 9,3=713b13 10,4=676276 11,4=5d89d8 12,4=53b13a 13,5=49d89c\n",
            "flat_last: 1,1=00ff00ff 2,1=00ff00ff 3,1=00ff00ff 4,1=00ff00ff 5,1=00ff00ff 6,1=00ff00ff \
             7,1=00ff00ff 8,1=0000ffff 8,2=0000ffff 8,3=0000ffff 8,4=0000ffff 8,5=0000ffff\n",
            "flat_first: 1,1=ff0000ff 2,1=ff0000ff 3,1=ff0000ff 4,1=ff0000ff 5,1=ff0000ff \
             6,1=ff0000ff 7,1=ff0000ff 8,1=00ff00ff 8,2=00ff00ff 8,3=00ff00ff 8,4=00ff00ff \
             8,5=00ff00ff\n",
        );
        assert_eq!(replay(script), mesa);
    }

    /// Only boundary edges (no quad diagonal, glEdgeFlag honoured), per-face modes and culling,
    /// and clipped polygons: edges made by clipping are not drawn, vertices made by it are.
    #[test]
    fn polygon_modes_draw_polygon_edges_and_vertices() {
        let script = "
            size 16 16; color 1 1 1 1; polymode front_and_back line; clear 0 0 0 0; begin quads; v 2.5 2.5
            v 12.5 2.5; v 12.5 12.5; v 2.5 12.5; end; lit quad_outline_no_diagonal; clear 0 0 0 0
            begin polygon; v 2.3 1.7; edge 0; v 13.2 3.1; edge 1; v 11.6 13.4; v 3.1 10.2; end
            lit polygon_edge_flag; polymode front point; polymode back line; clear 0 0 0 0; begin triangles
            v 2.5 2.5; v 7.5 2.5; v 2.5 7.5; v 9.5 9.5; v 9.5 14.5; v 14.5 9.5; end
            lit front_points_back_lines; enable cull_face; cullface front; clear 0 0 0 0; begin triangles
            v 2.5 2.5; v 7.5 2.5; v 2.5 7.5; v 9.5 9.5; v 9.5 14.5; v 14.5 9.5; end; lit front_culled
            disable cull_face; polymode front_and_back line; clear 0 0 0 0; begin triangles; v -6.5 4.5
            v 12.5 6.5; v 4.5 14.5; end; lit clip_edges_not_drawn; polymode front_and_back point
            clear 0 0 0 0; begin triangles; v -6.5 4.5; v 12.5 6.5; v 4.5 14.5; end
            lit clip_vertices_are_points";
        let mesa = concat!(
            "quad_outline_no_diagonal: 2,2 3,2 4,2 5,2 6,2 7,2 8,2 9,2 10,2 11,2 12,2 2,3 12,3 2,4 \
             12,4 2,5 12,5 2,6 12,6 2,7 12,7 2,8 12,8 2,9 12,9 2,10 12,10 2,11 12,11 2,12 3,12 4,12 \
             5,12 6,12 7,12 8,12 9,12 10,12 11,12 12,12\n",
            "polygon_edge_flag: 2,1 3,1 4,1 2,2 5,2 6,2 7,2 8,2 9,2 10,2 11,2 2,3 12,3 2,4 2,5 2,6 \
             2,7 2,8 3,9 3,10 4,10 5,11 6,11 7,11 8,12 9,12 10,12 11,13\n",
            "front_points_back_lines: 2,2 7,2 2,7 9,9 10,9 11,9 12,9 13,9 14,9 9,10 13,10 9,11 12,11 \
             9,12 11,12 9,13 10,13 9,14\n",
            "front_culled: 9,9 10,9 11,9 12,9 13,9 14,9 9,10 13,10 9,11 12,11 9,12 11,12 9,13 10,13 \
             9,14\n",
            "clip_edges_not_drawn: 0,5 1,5 2,5 3,5 4,5 5,5 6,5 7,5 8,6 9,6 10,6 11,6 12,6 11,7 10,8 \
             9,9 0,10 8,10 1,11 7,11 2,12 6,12 3,13 5,13 4,14\n",
            "clip_vertices_are_points: 0,5 12,6 4,14\n",
        );
        assert_eq!(replay(script), mesa);
    }

    #[test]
    fn offset_clamp_bounds_the_offset_on_its_own_side_only() {
        assert_eq!(clamp_offset(0.3, 0.1), 0.1);
        assert_eq!(clamp_offset(0.05, 0.1), 0.05);
        assert_eq!(clamp_offset(-0.3, 0.1), -0.3);
        assert_eq!(clamp_offset(-0.3, -0.1), -0.1);
        assert_eq!(clamp_offset(0.3, -0.1), 0.3);
        assert_eq!(clamp_offset(0.3, 0.0), 0.3);
        assert_eq!(clamp_offset(-0.3, f32::NAN), -0.3);
    }

    /// GL_POLYGON_OFFSET_LINE with factor 1 and units 2, against no offset.
    #[test]
    fn polygon_offset_line_moves_outline_depth() {
        let script = "
            size 16 16; color 1 1 1 1; enable depth_test; depthfunc always; polymode front_and_back line
            enable offset_line; offset 1 2; clear 0 0 0 0; begin triangles; v 2.5 2.5 0.2; v 13.5 3.5 -0.3
            v 6.5 13.5 0.4; end; depth offset_line; disable offset_line; clear 0 0 0 0; begin triangles
            v 2.5 2.5 0.2; v 13.5 3.5 -0.3; v 6.5 13.5 0.4; end; depth no_offset";
        let mesa = concat!(
            "offset_line: 2,2=6ca2ce 3,2=727442 4,2=7845b6 5,2=7e172a 6,2=83e89f 7,2=89ba13 \
             2,3=6a4f06 8,3=8f8b87 9,3=955cfc 10,3=9b2e70 11,3=a0ffe4 12,3=a6d159 13,3=aca2cd \
             3,4=67fb3e 12,4=a3ad0b 3,5=65a776 12,5=9ab748 3,6=6353ae 11,6=91c185 4,7=60ffe6 \
             10,7=88cbc3 4,8=5eac1d 10,8=7fd601 5,9=5c5855 9,9=76e03e 5,10=5a048d 8,10=6dea7c \
             5,11=57b0c5 7,11=64f4ba 6,12=555cfd 7,12=5bfef7 6,13=530934\n",
            "no_offset: 2,2=666666 3,2=6c37da 4,2=72094e 5,2=77dac3 6,2=7dac38 7,2=837dab 2,3=64129e \
             8,3=894f1f 9,3=8f2094 10,3=94f208 11,3=9ac37c 12,3=a094f1 13,3=a66665 3,4=61bed6 \
             12,4=9d70a3 3,5=5f6b0e 12,5=947ae0 3,6=5d1746 11,6=8b851d 4,7=5ac37d 10,7=828f5b \
             4,8=586fb5 10,8=799999 5,9=561bed 9,9=70a3d6 5,10=53c824 8,10=67ae14 5,11=51745c \
             7,11=5eb852 6,12=4f2094 7,12=55c28f 6,13=4ccccc\n",
        );
        assert_eq!(replay(script), mesa);
    }

    /// Row y % 32 from the bottom, bit 31 − x % 32; outlines are not stippled.
    #[test]
    fn polygon_stipple_is_anchored_at_the_window_origin() {
        let script = "
            size 40 37; color 1 1 1 1; clear 0 0 0 0
            pstipple 80000001 00000000 00000000 80000001 00000000 0000ffff 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000
            enable polygon_stipple; begin triangles; v 1.3 2.7; v 39 5; v 20 36; end; lit filled
            polymode front_and_back line; clear 0 0 0 0; begin triangles; v 1.3 2.7; v 39 5; v 20 36; end
            lit outline_not_stippled";
        let mesa = concat!(
            "filled: 16,5 17,5 18,5 19,5 20,5 21,5 22,5 23,5 24,5 25,5 26,5 27,5 28,5 29,5 30,5 31,5 \
             31,6 32,6 31,9 32,9 31,12 32,12 31,15 32,15\n",
            "outline_not_stippled: 1,2 2,2 3,2 4,2 5,2 1,3 6,3 7,3 8,3 9,3 10,3 11,3 12,3 13,3 14,3 \
             15,3 16,3 17,3 18,3 19,3 20,3 21,3 22,3 2,4 23,4 24,4 25,4 26,4 27,4 28,4 29,4 30,4 31,4 \
             32,4 33,4 34,4 35,4 36,4 37,4 38,4 2,5 38,5 3,6 38,6 3,7 37,7 4,8 36,8 5,9 36,9 5,10 \
             35,10 6,11 35,11 6,12 34,12 7,13 33,13 7,14 33,14 8,15 32,15 9,16 31,16 9,17 31,17 10,18 \
             30,18 10,19 30,19 11,20 29,20 11,21 28,21 12,22 28,22 12,23 27,23 13,24 27,24 14,25 \
             26,25 14,26 25,26 15,27 25,27 15,28 24,28 16,29 23,29 16,30 23,30 17,31 22,31 18,32 \
             22,32 18,33 21,33 19,34 20,34 19,35 20,35\n",
        );
        assert_eq!(replay(script), mesa);
    }

    /// A quad in GL_LINE mode is stippled as one strip of four edges, in Mesa's edge order.
    #[test]
    fn outline_edges_continue_the_line_stipple() {
        let script = "
            size 16 16; color 1 1 1 1; polymode front_and_back line; enable line_stipple; stipple 1 3333
            clear 0 0 0 0; begin quads; v 1.5 1.5; v 14.5 1.5; v 14.5 14.5; v 1.5 14.5; end
            lit quad_edges_continue_the_pattern";
        let mesa = "quad_edges_continue_the_pattern: 1,1 4,1 5,1 8,1 9,1 12,1 13,1 1,2 14,3 14,4 1,5 1,6 \
             14,7 14,8 1,9 1,10 14,11 14,12 1,13 1,14 4,14 5,14 8,14 9,14 12,14 13,14\n";
        assert_eq!(replay(script), mesa);
    }

    #[test]
    fn lines_points_and_outlines_are_identical_for_any_thread_count() {
        let render = |threads: usize| {
            let (mut ctx, d) = context(300, 200);
            ctx.state.depth.test = true;
            ctx.clear(GL_DEPTH_BUFFER_BIT);
            let mut seed = 777u32;
            let mut rnd = || {
                seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
                (seed >> 8) as f32 / (1 << 24) as f32
            };
            let mut vertices = Vec::new();
            for _ in 0..120 {
                let c = [rnd(), rnd(), rnd(), 1.0];
                vertices.push(vertex(rnd() * 340.0 - 20.0, rnd() * 240.0 - 20.0, rnd() * 2.0 - 1.0, c));
            }
            ctx.state.line_point.line_width = 3.0;
            ctx.draw_vertices(GL_LINE_STRIP, &vertices);
            ctx.state.line_point.line_stipple = true;
            ctx.state.line_point.line_stipple_pattern = 0x3f3f;
            ctx.state.line_point.line_width = 1.0;
            ctx.draw_vertices(GL_LINES, &vertices);
            ctx.state.line_point.point_size = 9.0;
            ctx.draw_vertices(GL_POINTS, &vertices);
            ctx.state.polygon.mode_front = GL_LINE;
            ctx.state.polygon.mode_back = GL_POINT;
            ctx.draw_vertices(GL_TRIANGLES, &vertices);
            let scene = ctx.scene.take().unwrap();
            scene.execute_on(&mut d.lock().unwrap().framebuffer, threads);
            pixels(&mut ctx, &d)
        };
        let one = render(1);
        assert!(one.iter().filter(|p| p[3] != 0).count() > 5000);
        for threads in [2, 4, 7] {
            assert!(one == render(threads), "{threads} threads differ");
        }
    }

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

    /// Long connected primitives are delivered in parts (glBegin/glEnd and array draws) and
    /// the scene is rendered when over budget; the pixels are those of the primitive drawn
    /// whole: strip order, fans' and polygons' first vertex, provoking vertices, a polygon's
    /// outline and the line stipple all continue across parts.
    #[test]
    fn long_primitives_in_parts_draw_the_same_pixels_as_whole() {
        use crate::context::vertex_input::test_support::{floats, FakeMemory};
        use crate::context::vertex_input::BATCH_VERTICES;
        let count = 2 * BATCH_VERTICES + 7;
        let spiral: Vec<Vertex> = (0..count)
            .map(|i| {
                let t = i as f32 / count as f32;
                let angle = t * 9.0 * std::f32::consts::TAU;
                let r = 6.0 + 38.0 * t + if i % 2 == 1 { 4.0 } else { 0.0 };
                let color = [t, 1.0 - t, if i % 7 < 3 { 1.0 } else { 0.2 }, 1.0];
                vertex(48.0 + r * angle.cos(), 48.0 + r * angle.sin(), 0.0, color)
            })
            .collect();
        let mut memory = FakeMemory::default();
        let positions: Vec<f32> = spiral.iter().flat_map(|v| v.position).collect();
        let colors: Vec<f32> = spiral.iter().flat_map(|v| v.color).collect();
        let positions = memory.add(0x1000_0000, floats(&positions));
        let colors = memory.add(0x2000_0000, floats(&colors));
        let modes = [GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUAD_STRIP, GL_POLYGON];
        for mode in modes {
            for (flat, first_vertex, outline) in [(false, false, false), (true, false, true), (true, true, false)] {
                let setup = |ctx: &mut Context| {
                    ctx.shade_model(if flat { GL_FLAT } else { GL_SMOOTH });
                    ctx.provoking_vertex(if first_vertex {
                        GL_FIRST_VERTEX_CONVENTION
                    } else {
                        GL_LAST_VERTEX_CONVENTION
                    });
                    ctx.polygon_mode(GL_FRONT_AND_BACK, if outline { GL_LINE } else { GL_FILL });
                    ctx.line_stipple(1, 0x0f3b);
                    ctx.set_capability(GL_LINE_STIPPLE, true);
                };
                let (mut whole, d) = context(96, 96);
                setup(&mut whole);
                whole.draw_vertices(mode, &spiral);
                let expected = pixels(&mut whole, &d);
                let (mut ctx, d) = context(96, 96);
                setup(&mut ctx);
                ctx.begin(mode);
                for v in &spiral {
                    ctx.set_color(v.color);
                    ctx.vertex(v.position);
                }
                ctx.end();
                assert!(ctx.vertex_input.delivered.len() >= 3, "mode {mode:#x}: delivered in parts");
                assert!(pixels(&mut ctx, &d) == expected, "mode {mode:#x} flat {flat} outline {outline}: glBegin");
                let (mut ctx, d) = context(96, 96);
                setup(&mut ctx);
                ctx.vertex_pointer(4, GL_FLOAT, 0, positions);
                ctx.color_pointer(4, GL_FLOAT, 0, colors);
                ctx.enable_client_state(GL_VERTEX_ARRAY, true);
                ctx.enable_client_state(GL_COLOR_ARRAY, true);
                ctx.draw_arrays(mode, 0, count as i32, &memory);
                assert!(ctx.vertex_input.delivered.len() >= 3, "mode {mode:#x}: delivered in parts");
                assert!(pixels(&mut ctx, &d) == expected, "mode {mode:#x} flat {flat} outline {outline}: arrays");
                assert_eq!(ctx.take_error(), GL_NO_ERROR);
            }
        }
    }

    #[test]
    fn a_scene_over_its_budget_is_rendered_at_the_next_draw() {
        let (mut ctx, d) = context(64, 64);
        let per_square = 2 * std::mem::size_of::<(u32, RasterPrimitive)>() + 2 * 4;
        let squares = Scene::BUDGET_BYTES / per_square + 2;
        for i in 0..squares {
            let c = (i % 256) as f32 / 255.0;
            square(&mut ctx, 0.0, 0.0, 64.0, 64.0, [c, 1.0 - c, 0.5, 1.0]);
            let recorded = ctx.scene.as_ref().map_or(0, |s| s.recorded_bytes());
            assert!(recorded <= Scene::BUDGET_BYTES, "square {i}: {recorded} bytes recorded");
        }
        let last = ((squares - 1) % 256) as f32 / 255.0;
        let expected = [(last * 255.0).round() as u8, ((1.0 - last) * 255.0).round() as u8, 128, 255];
        assert!(pixels(&mut ctx, &d).iter().all(|&p| p == expected));
    }

    #[test]
    fn point_size_clamps_like_mesa() {
        let mut lp =
            LinePointState { point_size: 10.0, point_size_min: 2.0, point_size_max: 4.0, ..Default::default() };
        assert_eq!(point_size(&lp), 4.0);
        lp.point_size = 1.0;
        assert_eq!(point_size(&lp), 2.0);
        // Crossed limits: the minimum wins below it, the maximum above.
        (lp.point_size_min, lp.point_size_max) = (6.0, 4.0);
        assert_eq!(point_size(&lp), 6.0);
        lp.point_size = 9.0;
        assert_eq!(point_size(&lp), 4.0);
        lp = LinePointState { point_size: 300.0, ..Default::default() };
        assert_eq!(point_size(&lp), MAX_POINT_SIZE);
    }

    /// Replays a probe script: the command language of `tools/gl-probe.c`, which runs the
    /// same script on Mesa (size, clear, viewport, ortho, frustum, linewidth, pointsize, pointminmax, stipple,
    /// pstipple, enable, disable, shade, provoking, polymode, cullface, frontface,
    /// depthfunc, offset, begin, color, edge, v, end, lit, dump, depth; one command per line
    /// or separated by `;`), printing the same lines, so that a script's output on Mesa and
    /// on tessera can be diffed. `lit` lists the pixels that differ from the clear color.
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
        for line in script.split(['\n', ';']) {
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
                    ctx.matrix_mode(GL_PROJECTION);
                    ctx.load_identity();
                    if cmd == "ortho" {
                        ctx.ortho(l, r, b, t, n, fa);
                    } else {
                        ctx.frustum(l, r, b, t, n, fa);
                    }
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
}
