//! Drawing: what the state machine does at a draw. A draw is validated (a framebuffer to
//! draw into, vertices to draw), its fragment state is compiled into the scene
//! ([`draw_state`]), what vertex processing reads is snapshotted ([`snapshot`]), its vertex
//! program looked up in the share group's cache, and the vertices are handed to the vertex
//! stage ([`crate::vertex`]), which runs the program on them, clips and sets up the
//! primitives and bins them into the context's [`Scene`].
//!
//! This file also keeps the scene's lifecycle: the pending scene is taken for a draw, kept
//! for more draws (or rendered when over its budget), and rendered at a flush point
//! ([`Context::flush_rendering`]): glFlush, glFinish, glReadPixels, clears, glAccum, buffer
//! queries, MakeCurrent. A long array draw into the window is recorded in segments, each
//! beside the render of the one before ([`overlap`]). Selection and feedback modes take
//! their own path ([`select`]).
mod draw_state;
mod overlap;
#[cfg(test)]
pub(crate) mod replay;
mod select;
mod snapshot;
#[cfg(test)]
pub(super) mod tests;

use super::shader_objects::Executable;
use super::{debug, Context};
use crate::framebuffer::{ColorFormat, ColorSlot};
use crate::gl::enums::{GL_FIXED_ONLY, GL_TRUE};
use crate::gl::types::GLenum;
use crate::raster::thread_count;
use crate::setup::jobs::clear::ClearJob;
use crate::setup::{Primitive as RasterPrimitive, Scene};
use crate::vertex::assembly::DrawPart;
use crate::vertex::attribute::Attribute;
use crate::vertex::geometry::Geometry;
use crate::vertex::glsl::{AttributePlace, GlslStage, Input, Output};
use crate::vertex::line::LineStipple;
use crate::vertex::pipeline;
use crate::vertex::transform::StageCache;
use crate::vertex::Vertex;

/// The fewest vertices a draw of independent triangles splits between two threads (see
/// [`split_point`]): below this, starting the helper thread costs more than half the work
/// it takes over.
const SPLIT_MIN_VERTICES: usize = 1536;

/// The fewest vertices a triangle or quad strip splits between two threads: as many as for
/// independent triangles, so a strip splits only when its half is far more work than handing
/// it over. Measured at 192 (LTO build, 2 threads, 1024²): lit_mesh's 128 strips of 258
/// vertices, each split, went from 15 to 30 ms a frame, one hand-off per short strip costing
/// more than the half strip it moved. If the helper is not free in time, the calling thread
/// draws both parts.
const STRIP_SPLIT_MIN_VERTICES: usize = SPLIT_MIN_VERTICES;

/// The fewest render threads with which a draw splits between the calling thread and a
/// helper. With two (a 2-core machine's default) the helper takes a core from the tile
/// workers: measured at 2 threads, 1024², LTO build, small_triangles (100k triangles in one
/// draw) took 43 ms a frame split and 30 ms whole. With more cores the helper is meant to
/// use one that the workers leave idle while the scene records; that is unmeasured here.
const SPLIT_MIN_THREADS: usize = 3;

/// Where the vertices of a draw split between the calling thread and a helper, if they
/// do: filled triangles, enough of them, and at least [`SPLIT_MIN_THREADS`] threads to render with; as the
/// end of the calling thread's part and the start of the helper's.
///
/// Independent triangles split between two triangles, so each part assembles the same
/// triangles. The calling thread takes 7/16 of them: besides its part it has fetched every
/// vertex (callgrind on small_triangles, LTO build: fetching is about 150 instructions a
/// triangle, transforming, setting up and binning one about 1500 since the unlit transform
/// runs directly, so the calling thread's share `p` with `150 + 1500·p = 1500·(1 − p)` is
/// about 0.45; with the executor's transform, 3/8 was the balance).
///
/// Strips (GL_TRIANGLE_STRIP, GL_QUAD_STRIP) split in half at an even vertex, the two
/// vertices there in both parts: the second part's triangles are then the draw's, in order,
/// with the same winding parity, quads and provoking vertices (GL_QUADS are not split: how
/// a quad is cut depends on all of the draw's vertices, `vertex::pipeline`).
fn split_point(mode: GLenum, geometry: &Geometry, vertices: usize, threads: usize) -> Option<(usize, usize)> {
    use crate::gl::enums::{GL_FILL, GL_QUAD_STRIP, GL_TRIANGLES, GL_TRIANGLE_STRIP};
    let filled = geometry.mode_front == GL_FILL && geometry.mode_back == GL_FILL;
    if !filled || threads < SPLIT_MIN_THREADS {
        return None;
    }
    match mode {
        GL_TRIANGLES if vertices >= SPLIT_MIN_VERTICES => {
            let split = vertices / 3 * 7 / 16 * 3;
            Some((split, split))
        }
        GL_TRIANGLE_STRIP | GL_QUAD_STRIP if vertices >= STRIP_SPLIT_MIN_VERTICES => {
            let split = vertices / 4 * 2;
            Some((split + 2, split))
        }
        _ => None,
    }
}

/// The vertices of a segment of a long draw whose recording overlaps with rendering the
/// segment before it ([`Context::record_in_segments`]): 8 batches of `BATCH_VERTICES`
/// (small_triangles, 100 000 triangles at 1024², is recorded in 13 segments).
const OVERLAP_SEGMENT_VERTICES: usize = 8 * crate::context::vertex_input::BATCH_VERTICES;

#[cfg(test)]
thread_local! {
    /// Whether long draws overlap their recording with rendering (tests turn it off to
    /// compare the bytes).
    pub(crate) static OVERLAP_ENABLED: std::cell::Cell<bool> = const { std::cell::Cell::new(true) };
}

/// Whether long draws overlap their recording with rendering: always, but a test may turn
/// it off ([`OVERLAP_ENABLED`]) to compare the bytes. (Measured on a quiet 2-core machine,
/// LTO, 1024², 2 threads, small_triangles: 35.9 ms a frame recorded whole, 27.6 ms with
/// the overlap; llvmpipe 36.3 ms.)
fn overlap_enabled() -> bool {
    #[cfg(test)]
    return OVERLAP_ENABLED.with(|on| on.get());
    #[cfg(not(test))]
    true
}

#[cfg(test)]
thread_local! {
    /// The most bytes a scene of this thread has recorded when a draw (or part) ended: what
    /// the tests of bounded memory read.
    pub(crate) static PEAK_SCENE_BYTES: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
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
        let executable = self.program_in_use.executable().cloned();
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
        if state.fragment.depth.is_some() || state.fragment.stencil.is_some() {
            self.bring_carried_clear(&mut scene);
        }
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
        if let Some(executable) = executable.filter(|e| e.vertex_program.is_some()) {
            // A GLSL vertex shader replaces the fixed-function per-vertex stage.
            let mut geometry = Geometry { per_sample, ..self.geometry(depth_bits, height) };
            let lp = &self.state.line_point;
            geometry.two_side = lp.vertex_program_two_side;
            geometry.point_attenuation = None;
            geometry.program_point_size =
                lp.vertex_program_point_size.then_some([lp.point_size_min, lp.point_size_max]);
            let stage = self.vertex_shader_stage(&executable, float_color);
            let mut stipple = self.active_line_stipple();
            if let (false, Some(s)) = (part.first, stipple.as_mut()) {
                s.counter = self.vertex_input.stipple_counter;
            }
            let rows = std::mem::take(&mut self.vertex_input.generic_rows);
            let stipple = stage.run(vertices, &rows, &self.state.current.generic, |clip_vertices| {
                pipeline::draw(&mut scene, state_index, &geometry, mode, clip_vertices, part, stipple)
            });
            self.vertex_input.generic_rows = rows;
            return self.end_part(scene, stipple, part);
        }
        let units = self.tex_coord_units();
        let previous = self.stage_cache.take();
        let input = self.transform_input(float_color, &units);
        let programs = &self.programs;
        let stage = StageCache::reuse_or_new(previous, &input, vertices.len(), |key| programs.lock().vertex(key));
        let vertex_stage = stage.stage();
        let geometry = Geometry { per_sample, ..self.geometry(depth_bits, height) };
        let mut stipple = self.active_line_stipple();
        if let (false, Some(s)) = (part.first, stipple.as_mut()) {
            s.counter = self.vertex_input.stipple_counter;
        }
        // Tests split wherever split_point allows it, whatever the machine's thread count, so
        // the split's bytes are checked on every machine.
        let threads = if cfg!(test) { thread_count().max(SPLIT_MIN_THREADS) } else { thread_count() };
        let stipple = match split_point(mode, &geometry, vertices.len(), threads) {
            // The later triangles transformed, clipped and set up on a helper thread into a
            // deferred part of the scene, binned after the earlier ones: the tile workers
            // are idle while a scene records, and the scene is the same.
            Some((first_end, second_start)) => {
                let (first, second) = (&vertices[..first_end], &vertices[second_start..]);
                // Room for the part's triangles (a strip has about one a vertex).
                let triangles = if mode == crate::gl::enums::GL_TRIANGLES { second.len() / 3 } else { second.len() };
                let mut later = scene.deferred_part(triangles);
                let [own, helper] = &mut self.vertex_scratch;
                let ((), stipple) = crate::pool::join(
                    || {
                        vertex_stage.run_in(helper, second, second_start, |clip_vertices| {
                            pipeline::draw(&mut later, state_index, &geometry, mode, clip_vertices, part, None)
                        });
                    },
                    || {
                        vertex_stage.run_in(own, first, 0, |clip_vertices| {
                            pipeline::draw(&mut scene, state_index, &geometry, mode, clip_vertices, part, stipple)
                        })
                    },
                );
                scene.append(later);
                stipple
            }
            None => vertex_stage.run_in(&mut self.vertex_scratch[0], vertices, 0, |clip_vertices| {
                pipeline::draw(&mut scene, state_index, &geometry, mode, clip_vertices, part, stipple)
            }),
        };
        self.stage_cache = Some(stage);
        self.end_part(scene, stipple, part);
    }

    /// The GLSL vertex stage of a draw with `executable` (which has a vertex shader) into a
    /// float (`float_color`) or fixed-point colour buffer: its interface wired, its uniform
    /// words filled (user uniforms from the program's values, built-in state from
    /// [`Context::stage_uniforms`]), once per draw.
    pub(crate) fn vertex_shader_stage<'e>(&self, executable: &'e Executable, float_color: bool) -> GlslStage<'e> {
        let program = executable.vertex_program.as_ref().expect("a vertex shader");
        let lowered = &program.lowered;
        let interface = &executable.interface;
        let attribute = |name: &str| {
            let a = interface.attributes.iter().find(|a| a.name == name)?;
            let column_rows = match a.ty {
                crate::glsl::hir::Type::Matrix(_, rows) => u32::from(rows),
                _ => 4,
            };
            Some(AttributePlace { location: a.location?, column_rows })
        };
        let inputs = lowered.inputs.iter().map(|w| Input::of(w, attribute)).collect();
        let outputs = lowered
            .outputs
            .iter()
            .map(|w| Output::of(w, |name, index| executable.varyings.index_of(name, index)))
            .collect();
        let uniforms = self.stage_uniforms(program);
        let clamp_color = match self.state.lighting.clamp_vertex_color {
            GL_FIXED_ONLY => !float_color,
            c => c == GL_TRUE as GLenum,
        };
        let two_side = self.state.line_point.vertex_program_two_side;
        GlslStage::new(&program.compiled, inputs, outputs, uniforms, clamp_color, two_side)
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
        #[cfg(test)]
        PEAK_SCENE_BYTES.with(|peak| peak.set(peak.get().max(scene.recorded_bytes())));
        if scene.recorded_bytes() > Scene::BUDGET_BYTES {
            self.run_scene(scene);
        } else {
            self.scene = Some(scene);
        }
    }

    /// Adds a pixel rectangle to the scene under the current state; `make` builds it from the
    /// varyings the draw's stages read (none when only color is needed).
    pub(super) fn draw_pixel_rect(
        &mut self,
        make: impl FnOnce(&[Attribute]) -> crate::setup::jobs::pixels::PixelRectJob,
    ) {
        let Some((width, height, color_format, depth_bits, stencil_bits)) = self.target_format() else {
            return;
        };
        let mut scene = self.take_scene(width, height);
        // A pixel rectangle may write depth or stencil (glDrawPixels of either).
        self.bring_carried_clear(&mut scene);
        let state = self.draw_state(&mut scene, width, height, color_format, depth_bits, stencil_bits);
        let (state_index, _) = scene.add_state(state);
        let job = make(&self.varyings_needed());
        scene.add(state_index, job.bounds(), RasterPrimitive::Pixels(job));
        self.keep_scene(scene);
    }

    /// Records a clear in the scene (see `setup::jobs::clear`): each tile's worker applies it
    /// in order with the draws around it.
    pub(super) fn record_clear(&mut self, job: crate::setup::jobs::clear::ClearJob) {
        let Some((width, height, ..)) = self.target_format() else {
            return;
        };
        let mut scene = self.take_scene(width, height);
        if !job.depth_stencil_only() {
            if scene.is_empty() {
                self.scene_overwrites_front =
                    job.whole && job.colors.iter().any(|c| c.slot == ColorSlot::FrontLeft && c.mask == [true; 4]);
            }
            scene.add_clear(job);
        } else if let Some(job) = self.carry_clear(job) {
            // A partial depth/stencil clear: after the carried whole one.
            self.bring_carried_clear(&mut scene);
            scene.add_clear(job);
        }
        self.keep_scene(scene);
    }

    /// Keeps a depth/stencil clear out of the scenes when it sets every depth and stencil
    /// value of a single-sampled window framebuffer that only this context draws into
    /// ([`crate::framebuffer::Present::private`], an OSMesa buffer) and whose depth the
    /// caller has not been given (OSMesaGetDepthBuffer): it replaces whatever
    /// was carried before (it overwrites all of it) and waits until a draw tests depth or
    /// stencil, a pixel rectangle or a partial clear is recorded (then it is binned first,
    /// in submission order), or something reads the framebuffer ([`Context::flush_rendering`],
    /// which every reader calls, bins it). glFlush and glFinish leave it carried: nothing
    /// can see depth or stencil until one of those happens. A first frame that clears
    /// depth and draws without the depth test then never touches the depth buffer's pages
    /// (at 1024² that is 4 MiB of fresh pages the kernel would fault in and zero).
    /// Returns the job when it cannot be carried.
    fn carry_clear(&mut self, job: ClearJob) -> Option<ClearJob> {
        let private = self.fbo.draw == 0
            && self.drawable().is_some_and(|d| {
                let guard = d.lock().unwrap_or_else(|p| p.into_inner());
                guard.presenter.as_ref().is_some_and(|p| p.private())
                    && !guard.depth_stencil_lent()
                    && guard.framebuffer.samples() == 1
            });
        let format = self.config.visual.depth_stencil;
        let covers = job.whole
            && (format.depth_bits() == 0 || job.depth.is_some())
            && (format.stencil_bits() == 0 || matches!(job.stencil, Some((_, 0xff))));
        if private && covers && job.depth_stencil_only() {
            self.carried_clear = Some(job);
            None
        } else {
            Some(job)
        }
    }

    /// Bins the carried clear (if any) into `scene`, before what is recorded next.
    fn bring_carried_clear(&mut self, scene: &mut Scene) {
        if let Some(job) = self.carried_clear.take() {
            scene.add_clear(job);
        }
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
                match self.spare_scene.take() {
                    Some(spare) if spare.size() == (width, height) => spare,
                    _ => Scene::new(width, height),
                }
            }
        }
    }

    /// Rasterizes everything recorded so far into the bound framebuffer, the carried
    /// depth/stencil clear ([`Context::carry_clear`]) included: what any reader of the
    /// framebuffer calls first.
    pub fn flush_rendering(&mut self) {
        if self.carried_clear.is_some() {
            match self.target_format() {
                Some((width, height, ..)) => {
                    let mut scene = self.take_scene(width, height);
                    self.bring_carried_clear(&mut scene);
                    self.scene = Some(scene);
                }
                None => self.carried_clear = None,
            }
        }
        if let Some(scene) = self.scene.take() {
            self.run_scene(scene);
        }
    }

    /// Rasterizes what the scene recorded for a flush point that presents the window's
    /// drawable right after (glFlush, glFinish, another context made current), leaving a
    /// carried clear carried (see [`Context::carry_clear`]). Into the window, the front-left
    /// color is rendered in place into the memory it is presented in where the drawable
    /// allows it ([`crate::framebuffer::Drawable::render_for_presentation`]: an OSMesa
    /// caller's RGBA8 buffer), saving the copy and the own pixels' first touch.
    pub(super) fn flush_for_presentation(&mut self) {
        let Some(mut scene) = self.scene.take() else { return };
        // The fallbacks go through run_scene, which reads scene_overwrites_front itself.
        let window = self.drawable.clone().filter(|_| self.fbo.draw == 0);
        let Some(drawable) = window else { return self.run_scene(scene) };
        let mut guard = drawable.lock().unwrap_or_else(|p| p.into_inner());
        if scene.size() != (guard.framebuffer.width(), guard.framebuffer.height()) {
            drop(guard);
            return self.run_scene(scene);
        }
        let overwrites = std::mem::take(&mut self.scene_overwrites_front);
        guard.render_for_presentation(overwrites, |fb| scene.execute(fb));
        drop(guard);
        scene.clear();
        self.spare_scene = Some(scene);
    }

    /// The vertices of each segment a long draw of `count` vertices into the window is
    /// recorded in when the segments overlap with rendering (see
    /// [`Context::record_in_segments`]); `None` when it is recorded whole: one render
    /// thread (nothing to overlap with), a framebuffer object (its images are assembled on
    /// the context's thread), selection or feedback, or a draw too short to split.
    pub(in crate::context) fn overlap_segment(&self, count: usize) -> Option<usize> {
        let segment = OVERLAP_SEGMENT_VERTICES;
        // Tests overlap on every machine, so the overlap's bytes are checked everywhere.
        let threads = if cfg!(test) { thread_count().max(2) } else { thread_count() };
        let overlaps = threads >= 2
            && count >= 2 * segment
            && self.fbo.draw == 0
            && self.drawable.is_some()
            && self.rendering()
            && overlap_enabled();
        overlaps.then_some(segment)
    }

    /// Rasterizes `scene` into the bound framebuffer, then keeps it, emptied, for the next
    /// draws to record into ([`Scene::clear`] says what it keeps).
    fn run_scene(&mut self, mut scene: Scene) {
        if std::mem::take(&mut self.scene_overwrites_front) && self.fbo.draw == 0 {
            // No need to bring home an image the scene replaces whole.
            if let Some(drawable) = &self.drawable {
                drawable.lock().unwrap_or_else(|p| p.into_inner()).front_image_replaced();
            }
        }
        let _ = self.with_framebuffer(|fb| {
            if scene.size() == (fb.width(), fb.height()) {
                scene.execute(fb);
            }
        });
        scene.clear();
        self.spare_scene = Some(scene);
    }
}
