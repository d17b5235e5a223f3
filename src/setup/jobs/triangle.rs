//! Filled triangles: the job a set-up triangle becomes (its edges and attribute planes),
//! and how it renders inside one tile: its exact row spans (at pixel centres, or at each
//! sample position on a multisampled target) walked by `raster`, each span handed with its
//! depth, colors and varyings to the fragment pipeline.
//!
//! Attribute planes are anchored at the triangle's first vertex (not the window origin), so
//! their precision does not depend on where the triangle lies. Colors are interpolated
//! perspective-correctly (planes of c/w and 1/w), window z linearly; when all three w are
//! equal the divide is skipped, which changes nothing but time. The accuracy mode
//! ([`Accuracy`]) may instead interpolate affinely (fast) or compute every attribute from
//! f64 barycentric coordinates at each pixel (exact).
//!
//! On a single-sampled target (outside the exact mode) a triangle renders in 4×4 blocks:
//! the tile is walked hierarchically on its integer edge functions
//! (`raster::blocks`) and each block runs the lane pipeline (`fragment::block`), with
//! depth, colours and varyings evaluated per lane from the same planes and the same
//! arithmetic as the span path ([`TriangleJob::render_blocks`]). On a multisampled
//! target the walk covers every pixel with a possibly covered sample and each block gets
//! its exact per-sample masks (`raster::samples`), its depth per sample from the same
//! plane at the sample positions ([`TriangleJob::render_sample_blocks`]); draws with
//! alpha-to-coverage or depth clamping, and the exact mode, keep the span path.
use crate::fragment::block::samples::{SampleBatch, SampleInputs};
use crate::fragment::block::{lanes, Batch, BlockColors, BlockInputs, BlockPipeline, F32s, Run, BATCH};
use crate::fragment::pipeline::{shade_span, shade_span_samples, DrawState, Scratch, Span};
use crate::fragment::{multisample::SampleMasks, span_mask};
use crate::framebuffer::band::Band;
use crate::framebuffer::hiz::{visible_parts, DepthPlane, REGION};
use crate::framebuffer::multisample::MAX_SAMPLES;
use crate::framebuffer::Rect;
use crate::glsl::varyings::VARYING_SLOTS;
use crate::raster::blocks::{walk_blocks, walk_blocks_filling, PixelEdge};
use crate::raster::samples::SampleEdges;
use crate::raster::walk::{stipple_mask, walk_sample_spans, walk_spans};
use crate::setup::accuracy::Accuracy;
use crate::setup::multisample::{sample_offsets, sample_shifts, SampleOffset};
use crate::setup::plane::{self, Plane};
use crate::setup::triangle::{TriangleSetup, ONE};

/// How a triangle's color varies over it (planes around its anchor).
pub type Shading = plane::Shading<Plane>;

/// A triangle's extra attributes (planes around its anchor).
pub type Varyings = plane::Varyings<Plane>;

/// A set-up triangle with everything its fragments need.
#[derive(Clone, Debug)]
pub struct TriangleJob {
    pub setup: TriangleSetup,
    /// The anchor of the planes: the first (counter-clockwise) vertex, in pixels.
    pub anchor: [f32; 2],
    pub z: Plane,
    pub shading: Shading,
    pub varyings: Varyings,
    /// Whether the triangle faces front (it selects the stencil face); set by the caller,
    /// true from [`TriangleJob::new`].
    pub front_facing: bool,
    /// The exact accuracy mode's inputs; when present they replace the planes.
    exact: Option<Box<ExactAttributes>>,
}

/// Which triangles may render inside one area of a single-sampled band as part of a run
/// ([`TriangleJob::render_run`]) with one draw state and its compiled pipeline: those that
/// [`TriangleJob::render_blocks`] would walk block by block through the pipeline. Not in
/// the exact accuracy mode, nor a constant fill (written as rows), nor a triangle
/// hierarchical z may skip regions of (one larger than a region in the area).
///
/// Made once per state and area, the state's part of the decision taken then (whether
/// hierarchical z may reject, whether a stipple is on): the tile workers ask it of every
/// triangle of a run, and a run of small triangles has hundreds.
#[derive(Clone, Copy)]
pub struct RunRules<'a> {
    state: &'a DrawState,
    pipeline: &'a BlockPipeline,
    area: Rect,
    /// Whether hierarchical z may reject regions of the state's triangles.
    hiz: bool,
}

impl<'a> RunRules<'a> {
    /// The rules of triangles drawn with `state` through `pipeline` into `area`.
    #[inline(always)]
    pub fn new(state: &'a DrawState, pipeline: &'a BlockPipeline, area: Rect) -> Self {
        let hiz = pipeline.hiz_reject(&state.fragment).is_some();
        RunRules { state, pipeline, area, hiz }
    }

    /// The area the run renders into.
    #[inline(always)]
    pub fn area(&self) -> Rect {
        self.area
    }

    /// Whether `job` may render as part of a run.
    #[inline(always)]
    pub fn admit(&self, job: &TriangleJob) -> bool {
        if job.exact.is_some() {
            return false;
        }
        if self.hiz {
            let part = self.area.intersect(job.bounds());
            if part.x1 - part.x0 >= REGION && part.y1 - part.y0 >= REGION {
                return false;
            }
        }
        self.state.polygon_stipple.is_some()
            || job.uniform_color().is_none_or(|c| self.pipeline.constant_fill(self.state, c).is_none())
    }
}

/// What the exact accuracy mode interpolates: the vertices (pixels, counter-clockwise) and
/// their attributes in f64.
#[derive(Clone, Debug)]
struct ExactAttributes {
    p: [[f64; 2]; 3],
    /// Twice the signed area, (p1 − p0) × (p2 − p0) (positive).
    area: f64,
    z: [f64; 3],
    inv_w: [f64; 3],
    /// `None` when flat: the planes' [`Shading::Flat`] color is used.
    colors: Option<[[f64; 4]; 3]>,
    varyings: Vec<[f64; 3]>,
}

impl ExactAttributes {
    /// The barycentric coordinates of pixel centre (x, y) and their perspective weights
    /// λᵢ/wᵢ normalised to sum to one.
    #[inline]
    fn weights(&self, x: i32, y: i32) -> ([f64; 3], [f64; 3]) {
        let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
        let cross = |a: [f64; 2], b: [f64; 2]| a[0] * b[1] - a[1] * b[0];
        let rel = |q: [f64; 2]| [q[0] - px, q[1] - py];
        let (r0, r1, r2) = (rel(self.p[0]), rel(self.p[1]), rel(self.p[2]));
        let l = [cross(r1, r2) / self.area, cross(r2, r0) / self.area, cross(r0, r1) / self.area];
        let persp = [l[0] * self.inv_w[0], l[1] * self.inv_w[1], l[2] * self.inv_w[2]];
        let sum = persp[0] + persp[1] + persp[2];
        (l, persp.map(|q| q / sum))
    }
}

/// The window-space inputs of one vertex, with the `N` varying slots of the clip-space
/// record it comes from (`crate::vertex::clip::ClipVertex`: all of them after a GLSL vertex
/// program, the texture units' after fixed-function processing).
#[derive(Clone, Copy, Debug)]
pub struct WindowVertex<const N: usize = VARYING_SLOTS> {
    pub x: f32,
    pub y: f32,
    pub z: f32,
    pub inv_w: f32,
    pub color: [f32; 4],
    /// The attributes later stages may read; [`TriangleJob::new`] interpolates the ones a
    /// draw asks for.
    pub secondary_color: [f32; 4],
    pub tex_coords: [[f32; 4]; N],
    pub fog_coord: f32,
}

impl TriangleJob {
    /// Sets up a triangle; `None` when it covers no pixel centre (zero area).
    /// `flat` is the flat-shading color, if flat shaded. `depth_offset` is added to z.
    /// `varyings` holds, for each extra attribute the draw needs, its value at the three
    /// vertices (in the order of `v`).
    pub fn new(
        v: [WindowVertex; 3],
        flat: Option<[f32; 4]>,
        depth_offset: f32,
        varyings: &[[f32; 3]],
    ) -> Option<TriangleJob> {
        Self::with_accuracy(Accuracy::Conformant, &v, flat, depth_offset, varyings)
    }

    /// As [`TriangleJob::new`], interpolating as `accuracy` says.
    pub fn with_accuracy<const N: usize>(
        accuracy: Accuracy,
        v: &[WindowVertex<N>; 3],
        flat: Option<[f32; 4]>,
        depth_offset: f32,
        varyings: &[[f32; 3]],
    ) -> Option<TriangleJob> {
        let setup = TriangleSetup::new(v.map(|p| [p.x, p.y]))?;
        Some(Self::with_setup(setup, accuracy, v, flat, depth_offset, varyings))
    }

    /// As [`TriangleJob::with_accuracy`] for a triangle already set up (`setup`, from the
    /// positions of `v`): its planes, made only once the caller knows the triangle may
    /// cover something (see `Scene::add_triangle`).
    #[inline]
    pub fn with_setup<const N: usize>(
        setup: TriangleSetup,
        accuracy: Accuracy,
        v: &[WindowVertex<N>; 3],
        flat: Option<[f32; 4]>,
        depth_offset: f32,
        varyings: &[[f32; 3]],
    ) -> TriangleJob {
        Self::with_setup_by(setup, accuracy, v, flat, depth_offset, varyings.len(), |k| varyings[k])
    }

    /// As [`TriangleJob::with_setup`] with the values of varying `k` (`k < count`) at the
    /// three vertices given by `varying(k)`: the caller reads them straight from its
    /// vertices, with no table of them made (and zeroed) per triangle.
    #[inline(always)]
    pub fn with_setup_by<const N: usize>(
        setup: TriangleSetup,
        accuracy: Accuracy,
        v: &[WindowVertex<N>; 3],
        flat: Option<[f32; 4]>,
        depth_offset: f32,
        count: usize,
        varying: impl Fn(usize) -> [f32; 3],
    ) -> TriangleJob {
        // Attribute values in the setup's (counter-clockwise) vertex order.
        let order = if setup.was_clockwise { [0, 2, 1] } else { [0, 1, 2] };
        let v = order.map(|i| &v[i]);
        let fixed = setup.vertices;
        let px = |i: usize| [fixed[i][0] as f64 / ONE as f64, fixed[i][1] as f64 / ONE as f64];
        let (p0, p1, p2) = (px(0), px(1), px(2));
        let d1 = [p1[0] - p0[0], p1[1] - p0[1]];
        let d2 = [p2[0] - p0[0], p2[1] - p0[1]];
        let plane = |values: [f32; 3]| Plane::through(d1, d2, values);
        let z_values = [v[0].z, v[1].z, v[2].z];
        let fast = accuracy == Accuracy::Fast;
        // Depth's plane and the colour's made together (see `Plane::through_all`).
        let (mut z, shading) = match flat {
            Some(color) => (plane(z_values), Shading::Flat(color)),
            None if v[0].color == v[1].color && v[1].color == v[2].color => {
                (plane(z_values), Shading::Flat(v[0].color))
            }
            // The fast mode interpolates affinely even where w varies (no divide per
            // fragment); the conformant mode only where it is exact (all w equal).
            None if fast || (v[0].inv_w == v[1].inv_w && v[1].inv_w == v[2].inv_w) => {
                let channel = |c: usize| [v[0].color[c], v[1].color[c], v[2].color[c]];
                let [z, r, g, b, a] =
                    Plane::through_all(d1, d2, [z_values, channel(0), channel(1), channel(2), channel(3)]);
                (z, Shading::Affine([r, g, b, a]))
            }
            None => {
                let over_w = |c: usize| [0, 1, 2].map(|i| v[i].color[c] * v[i].inv_w);
                let inv_w = [v[0].inv_w, v[1].inv_w, v[2].inv_w];
                let [z, r, g, b, a, q] =
                    Plane::through_all(d1, d2, [z_values, over_w(0), over_w(1), over_w(2), over_w(3), inv_w]);
                (z, Shading::Perspective { color_over_w: [r, g, b, a], inv_w: q })
            }
        };
        z.a0 += depth_offset;
        let inv_w = [v[0].inv_w, v[1].inv_w, v[2].inv_w];
        let exact = (accuracy == Accuracy::Exact).then(|| {
            let f = |a: [f32; 3]| a.map(|x| x as f64);
            Box::new(ExactAttributes {
                p: [p0, p1, p2],
                area: d1[0] * d2[1] - d2[0] * d1[1],
                z: [v[0].z, v[1].z, v[2].z].map(|z| z as f64 + depth_offset as f64),
                inv_w: f(inv_w),
                colors: match shading {
                    Shading::Flat(_) => None,
                    _ => Some(v.map(|q| q.color.map(|c| c as f64))),
                },
                varyings: (0..count).map(|k| f(varying(k))).map(|a| order.map(|i| a[i])).collect(),
            })
        });
        let varyings = if count == 0 {
            Varyings::default()
        } else if fast {
            Varyings::affine((0..count).map(|k| {
                let a = varying(k);
                plane(order.map(|i| a[i]))
            }))
        } else {
            let over_w = (0..count).map(|k| {
                let a = varying(k);
                let a = order.map(|i| a[i]);
                plane([a[0] * inv_w[0], a[1] * inv_w[1], a[2] * inv_w[2]])
            });
            Varyings::new(over_w, plane(inv_w))
        };
        TriangleJob { setup, anchor: [p0[0] as f32, p0[1] as f32], z, shading, varyings, front_facing: true, exact }
    }

    /// Whether dropping the job frees memory (the scene drops only the jobs that do:
    /// `setup::scene`). Every field that may own memory is named here.
    #[inline(always)]
    pub fn owns_memory(&self) -> bool {
        self.exact.is_some() || self.varyings.on_heap()
    }

    /// The pixel rectangle that may contain covered centres.
    pub fn bounds(&self) -> Rect {
        let s = &self.setup;
        Rect { x0: s.min_x, y0: s.min_y, x1: s.max_x.saturating_add(1), y1: s.max_y.saturating_add(1) }
    }

    /// Renders the part of the triangle inside `area` (within the band) into `band`.
    pub fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.bounds());
        if area.is_empty() {
            return;
        }
        walk_spans(
            area,
            |y, x0, x1| self.setup.row_span(y, x0, x1),
            |y, x0, x1| self.shade_span(state, band, y, x0, x1, scratch),
        );
    }

    /// Renders the part of the triangle inside `area` (within the band) into a
    /// single-sampled `band` in 4×4 blocks through the compiled lane `pipeline`, collected
    /// in `batch` (empty, and left empty: the tile worker's, made once per band rather than
    /// once per triangle); the exact accuracy mode renders spans instead
    /// ([`TriangleJob::render`]).
    pub fn render_blocks(
        &self,
        state: &DrawState,
        pipeline: &BlockPipeline,
        area: Rect,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
        batch: &mut Batch,
    ) {
        if self.exact.is_some() {
            return self.render(state, area, band, scratch);
        }
        let area = area.intersect(self.bounds());
        if area.is_empty() {
            return;
        }
        let edges = self.setup.pixel_edges().map(PixelEdge::from_array);
        // A flat triangle whose fragments all store one value (`BlockPipeline::constant_fill`)
        // is written as that value: the rectangles it covers whole as rows, its edge blocks
        // through their masks, with no per-block pipeline work.
        let fill = self.uniform_color().and_then(|c| pipeline.constant_fill(state, c));
        // One copy of this walk, not one per SIMD level: its work is the stores of the fill
        // (a copy per level made the libraries 146 KB larger), and the lanes' signs are the
        // same at every level.
        if let (Some((target, pixel)), None) = (fill, state.polygon_stipple.as_ref()) {
            let band = std::cell::RefCell::new(band);
            return walk_blocks_filling(
                crate::simd::current(),
                area,
                &edges,
                None,
                |x, y, mask| band.borrow_mut().fill_block_unorm8(target, x, y, mask, pixel),
                Some(|rect| band.borrow_mut().fill_unorm8(target, rect, pixel)),
            );
        }
        // The walk compiled once per SIMD level (one dispatch per triangle and tile); its
        // blocks collected in batches, each batch's stages one direct call per stage into
        // their copies for the level (`BlockPipeline::render`). No SSE4.1 copy of the walk
        // (that level runs SSE2's: issue #18's 5 MB limit).
        // Hierarchical z (`framebuffer::hiz`): the regions where every fragment fails the
        // depth test are not walked. Not for triangles smaller than a region in this tile,
        // whose tests would cost more than they save.
        let big = area.x1 - area.x0 >= REGION && area.y1 - area.y0 >= REGION;
        let rejected = match pipeline.hiz_reject(&state.fragment).filter(|_| big) {
            Some(test) => {
                let z = DepthPlane { a0: self.z.a0, dadx: self.z.dadx, dady: self.z.dady, anchor: self.anchor };
                band.hiz_rejected(area, &z, test)
            }
            None => 0,
        };
        // The stages see the triangle as a run of one (`fragment::block::Run`: they are
        // compiled for runs only).
        let one = Run::one(self);
        crate::simd::per_level!(sse2_for_sse41, |level| {
            let front_facing = self.front_facing;
            for &part in visible_parts(area, rejected).as_slice() {
                walk_blocks(
                    level,
                    part,
                    &edges,
                    state.polygon_stipple.as_ref(),
                    #[inline(always)]
                    |x, y, mask| {
                        if batch.push(x, y, mask) {
                            pipeline.render(level, state, band, scratch, &one, front_facing, batch);
                        }
                    },
                );
            }
            pipeline.render(level, state, band, scratch, &one, front_facing, batch);
        });
    }

    /// Renders the parts inside `area` (within the single-sampled band) of a run of
    /// consecutive triangles of one draw state and facing, each of which its
    /// [`RunRules`] admit, as [`TriangleJob::render_blocks`] renders them one after
    /// the other: their blocks walked into one `batch` (empty, and left empty), each block
    /// tagged with its triangle, and the pipeline run per full batch. The stages' set-up
    /// (the level's dispatch, the stage calls) is paid per batch, not per triangle: a
    /// small triangle has two or three blocks. Blocks of different triangles may overlap;
    /// the stages keep their order (see `fragment::block::Batch`).
    #[allow(clippy::too_many_arguments)]
    pub fn render_run<'a>(
        state: &DrawState,
        pipeline: &BlockPipeline,
        area: Rect,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
        batch: &mut Batch,
        jobs: impl Iterator<Item = &'a TriangleJob> + Clone,
    ) {
        let Some(first) = jobs.clone().next() else { return };
        let front_facing = first.front_facing;
        let stipple = state.polygon_stipple.as_ref();
        let mut run = Run { of: [first; BATCH], len: 0 };
        crate::simd::per_level!(sse2_for_sse41, |level| {
            for job in jobs.clone() {
                let part = area.intersect(job.bounds());
                if part.is_empty() {
                    continue;
                }
                let edges = job.setup.pixel_edges().map(PixelEdge::from_array);
                // The job's source in the run, once it has a block in the batch.
                let mut source = None;
                walk_blocks(
                    level,
                    part,
                    &edges,
                    stipple,
                    #[inline(always)]
                    |x, y, mask| {
                        let s = match source {
                            Some(s) => s,
                            None => {
                                let s = run.len;
                                run.of[s.min(BATCH - 1)] = job;
                                run.len = s + 1;
                                source = Some(s);
                                s
                            }
                        };
                        if batch.push_from(s as u8, x, y, mask) {
                            pipeline.render(level, state, band, scratch, &run, front_facing, batch);
                            run.len = 0;
                            source = None;
                        }
                    },
                );
            }
            pipeline.render(level, state, band, scratch, &run, front_facing, batch);
        });
    }

    /// Renders the part of the triangle inside `area` (within the band) into a
    /// multisampled `band` in 4×4 blocks through the compiled lane `pipeline`
    /// (`fragment::block::samples`): per sample at the standard positions while
    /// GL_MULTISAMPLE is on (the walk on the edges widened to every sample, each block's
    /// sample masks exact: `raster::samples`), else at pixel centres with every sample of a
    /// covered pixel covered at the pixel's depth (§3.2.1), as the span path
    /// ([`TriangleJob::render_samples`], [`TriangleJob::render`]), which the exact accuracy
    /// mode keeps.
    pub fn render_sample_blocks(
        &self,
        state: &DrawState,
        pipeline: &BlockPipeline,
        area: Rect,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
    ) {
        let ms = state.multisample.filter(|m| m.enabled);
        let per_sample = ms.is_some_and(|m| m.per_sample());
        if self.exact.is_some() {
            return if per_sample {
                self.render_samples(state, area, band, scratch)
            } else {
                self.render(state, area, band, scratch)
            };
        }
        let samples = band.samples.min(MAX_SAMPLES);
        let offsets = sample_offsets(band.samples);
        let pixel_edges = self.setup.pixel_edges().map(PixelEdge::from_array);
        let sample_edges = per_sample.then(|| SampleEdges::new(&pixel_edges, offsets.iter().map(|o| [o.x, o.y])));
        let (area, edges) = match &sample_edges {
            Some(e) => (area.intersect(self.sample_bounds()), e.widened()),
            None => (area.intersect(self.bounds()), pixel_edges),
        };
        if area.is_empty() {
            return;
        }
        // GL_SAMPLE_COVERAGE's samples (all when the multisample operations are off).
        let coverage = ms.map_or(0xff, |m| m.coverage_mask);
        let mut keep = [0u16; MAX_SAMPLES];
        for (s, k) in keep.iter_mut().enumerate().take(samples) {
            *k = if coverage & (1 << s) != 0 { 0xffff } else { 0 };
        }
        let inputs = SampleDepth { job: self, shifts: per_sample.then(|| sample_shifts(offsets)) };
        // The walk and the stages below it without SSE4.1 copies (that level runs SSE2's):
        // they cost each library about 70 KB for CPUs with SSE4.1 and no AVX2, and no
        // benchmark scene is multisampled.
        crate::simd::per_level!(sse2_for_sse41, |level| {
            let mut batch = SampleBatch::default();
            let front_facing = self.front_facing;
            walk_blocks(
                level,
                area,
                &edges,
                state.polygon_stipple.as_ref(),
                #[inline(always)]
                |x, y, mask| {
                    let mut masks = match &sample_edges {
                        Some(e) => e.masks(x, y, mask),
                        None => [mask; MAX_SAMPLES],
                    };
                    let mut any = 0;
                    for (m, k) in masks.iter_mut().zip(keep) {
                        *m &= k;
                        any |= *m;
                    }
                    if any != 0 && batch.push(x, y, masks) {
                        pipeline.render_samples(level, state, band, scratch, &inputs, front_facing, &mut batch);
                    }
                },
            );
            pipeline.render_samples(level, state, band, scratch, &inputs, front_facing, &mut batch);
        });
    }

    /// The planes' offsets of a block's columns and rows (pixel centres relative to the
    /// anchor, computed as the span path computes a span's first pixel).
    /// Plain loops rather than `std::array::from_fn` (which LLVM may leave as calls).
    #[inline(always)]
    fn block_offsets(&self, x: i32, y: i32) -> Offsets {
        let (mut dx, mut dy) = ([0f32; 4], [0f32; 4]);
        for (c, d) in dx.iter_mut().enumerate() {
            *d = (x + c as i32) as f32 + 0.5 - self.anchor[0];
        }
        for (r, d) in dy.iter_mut().enumerate() {
            *d = (y + r as i32) as f32 + 0.5 - self.anchor[1];
        }
        Offsets { dx, dy }
    }

    fn shade_span(&self, state: &DrawState, band: &mut Band<'_>, y: i32, x0: i32, x1: i32, scratch: &mut Scratch) {
        let n = (x1 - x0) as usize;
        let dy = y as f32 + 0.5 - self.anchor[1];
        let dx0 = x0 as f32 + 0.5 - self.anchor[0];
        let row_start = (y - band.y0) as usize * band.width + x0 as usize;
        let mut live = span_mask(n);
        if let Some(pattern) = &state.polygon_stipple {
            live &= stipple_mask(pattern, x0, y);
            if live == 0 {
                return;
            }
        }
        let span = Span { y, x0, n, row_start, front_facing: self.front_facing };
        if let Some(exact) = &self.exact {
            let flat = match self.shading {
                Shading::Flat(c) => Some(c),
                _ => None,
            };
            shade_span(
                state,
                band,
                scratch,
                span,
                live,
                |i| {
                    let (l, _) = exact.weights(x0 + i as i32, y);
                    (l[0] * exact.z[0] + l[1] * exact.z[1] + l[2] * exact.z[2]) as f32
                },
                |colors| {
                    let Some(vertex_colors) = &exact.colors else {
                        return flat;
                    };
                    colors.extend((0..n).map(|i| {
                        let (_, q) = exact.weights(x0 + i as i32, y);
                        std::array::from_fn(|c| {
                            (q[0] * vertex_colors[0][c] + q[1] * vertex_colors[1][c] + q[2] * vertex_colors[2][c])
                                as f32
                        })
                    }));
                    flat
                },
                |i, j, out| {
                    let (_, q) = exact.weights(x0 + i, y + j);
                    for (o, a) in out.iter_mut().zip(&exact.varyings) {
                        *o = (q[0] * a[0] + q[1] * a[1] + q[2] * a[2]) as f32;
                    }
                },
            );
            return;
        }
        shade_span(
            state,
            band,
            scratch,
            span,
            live,
            |i| self.z.at(dx0 + i as f32, dy),
            |colors| self.shading.span_colors(dx0, dy, n, colors),
            |i, j, out| self.varyings.at(dx0 + i as f32, dy + j as f32, out),
        );
    }
}

/// The planes' offsets of a block's four columns (`dx`) and four rows (`dy`).
#[derive(Clone, Copy)]
struct Offsets {
    dx: [f32; 4],
    dy: [f32; 4],
}

/// A plane over a block's lanes: `a0 + dadx·dx + dady·dy` per lane, as [`Plane::at`]
/// evaluates it (`(a0 + dadx·dx) + dady·dy`, two roundings of each product and sum), with
/// the terms shared by a column or a row computed once: `a0 + dadx·dx` per column,
/// `dady·dy` per row, one add per lane. The same operations on the same operands, so the
/// same bits as the span path's.
#[inline(always)]
fn plane_lanes(p: &Plane, o: &Offsets) -> F32s {
    let (mut cols, mut rows) = ([0f32; 4], [0f32; 4]);
    for (col, dx) in cols.iter_mut().zip(o.dx) {
        *col = p.a0 + p.dadx * dx;
    }
    for (row, dy) in rows.iter_mut().zip(o.dy) {
        *row = p.dady * dy;
    }
    lanes(|i| cols[i & 3] + rows[i >> 2])
}

/// A plane over a block's lanes times `w` per lane.
#[inline(always)]
fn times_lanes(p: &Plane, o: &Offsets, w: &F32s) -> F32s {
    let v = plane_lanes(p, o);
    lanes(|i| v[i] * w[i])
}

impl BlockInputs for TriangleJob {
    #[inline(always)]
    fn z(&self, x: i32, y: i32) -> F32s {
        plane_lanes(&self.z, &self.block_offsets(x, y))
    }

    #[inline(always)]
    fn colors(&self, x: i32, y: i32, out: &mut BlockColors) {
        if let Shading::Flat(c) = &self.shading {
            *out = BlockColors::Uniform(*c);
            return;
        }
        let o = self.block_offsets(x, y);
        *out = match &self.shading {
            Shading::Flat(c) => BlockColors::Uniform(*c),
            Shading::Affine([r, g, b, a]) => {
                BlockColors::Lanes([plane_lanes(r, &o), plane_lanes(g, &o), plane_lanes(b, &o), plane_lanes(a, &o)])
            }
            Shading::Perspective { color_over_w, inv_w } => {
                let q = plane_lanes(inv_w, &o);
                let w: F32s = lanes(|i| 1.0 / q[i]);
                let [r, g, b, a] = color_over_w;
                BlockColors::Lanes([
                    times_lanes(r, &o, &w),
                    times_lanes(g, &o, &w),
                    times_lanes(b, &o, &w),
                    times_lanes(a, &o, &w),
                ])
            }
        };
    }

    #[inline]
    fn varyings(&self, x: i32, y: i32, dx: i32, dy: i32, out: &mut [f32]) {
        let dx0 = x as f32 + 0.5 - self.anchor[0];
        let dy0 = y as f32 + 0.5 - self.anchor[1];
        self.varyings.at(dx0 + dx as f32, dy0 + dy as f32, out);
    }

    #[inline(always)]
    fn uniform_color(&self) -> Option<[f32; 4]> {
        match &self.shading {
            Shading::Flat(c) => Some(*c),
            _ => None,
        }
    }

    #[inline(always)]
    fn varying_lanes(&self, x: i32, y: i32, first: usize, out: &mut [F32s]) {
        // The points `varyings(x, y + row, column, 0, ..)` evaluates, in its operations.
        let dx0 = x as f32 + 0.5 - self.anchor[0];
        let px: F32s = lanes(|i| dx0 + (i & 3) as f32);
        let py: F32s = lanes(|i| (y + (i >> 2) as i32) as f32 + 0.5 - self.anchor[1] + 0.0);
        self.varyings.lanes_at(&px, &py, first, out);
    }
}

/// A triangle as the multisampled block pipeline reads it: its block inputs, and its depth
/// at each sample position (`shifts`: from the pixel centre, in pixels; `None` while
/// GL_MULTISAMPLE is off, when every sample takes the centre's depth).
struct SampleDepth<'a> {
    job: &'a TriangleJob,
    shifts: Option<[[f32; 2]; MAX_SAMPLES]>,
}

impl BlockInputs for SampleDepth<'_> {
    #[inline(always)]
    fn z(&self, x: i32, y: i32) -> F32s {
        self.job.z(x, y)
    }
    #[inline(always)]
    fn colors(&self, x: i32, y: i32, out: &mut BlockColors) {
        self.job.colors(x, y, out)
    }
    #[inline]
    fn varyings(&self, x: i32, y: i32, dx: i32, dy: i32, out: &mut [f32]) {
        self.job.varyings(x, y, dx, dy, out)
    }
    #[inline(always)]
    fn uniform_color(&self) -> Option<[f32; 4]> {
        self.job.uniform_color()
    }
    #[inline(always)]
    fn varying_lanes(&self, x: i32, y: i32, first: usize, out: &mut [F32s]) {
        self.job.varying_lanes(x, y, first, out)
    }
}

impl SampleInputs for SampleDepth<'_> {
    type Pixels = TriangleJob;
    #[inline(always)]
    fn pixels(&self) -> &TriangleJob {
        self.job
    }

    /// The depth plane at the sample: the pixel centres' offsets plus the sample's shift,
    /// the operations of the span path's `z.at(dx0 + i + shift_x, dy + shift_y)` (the
    /// offsets are exact, as for [`TriangleJob::block_offsets`]).
    #[inline(always)]
    fn sample_z(&self, x: i32, y: i32, sample: usize) -> F32s {
        let Some(shifts) = &self.shifts else {
            return self.job.z(x, y);
        };
        let [sx, sy] = shifts[sample];
        let mut o = self.job.block_offsets(x, y);
        for d in &mut o.dx {
            *d += sx;
        }
        for d in &mut o.dy {
            *d += sy;
        }
        plane_lanes(&self.job.z, &o)
    }
}

impl TriangleJob {
    /// The pixel rectangle that may contain covered samples: every pixel the triangle's
    /// bounding box touches.
    pub fn sample_bounds(&self) -> Rect {
        let (x0, y0, x1, y1) = self.setup.pixel_box();
        Rect { x0, y0, x1, y1 }
    }

    /// Renders the part of the triangle inside `area` into a multisampled band, sample by
    /// sample at the standard positions of `samples` samples, with the fill rule of pixel
    /// centres applied to each sample.
    pub fn render_samples(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let offsets = sample_offsets(band.samples);
        walk_sample_spans(
            area.intersect(self.sample_bounds()),
            offsets,
            |y, o, x0, x1| self.setup.row_span_at(y, o.x, o.y, x0, x1),
            |y, x0, x1, masks| self.shade_samples(state, band, scratch, y, x0, x1, masks, offsets),
        );
    }

    #[allow(clippy::too_many_arguments)]
    fn shade_samples(
        &self,
        state: &DrawState,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
        y: i32,
        x0: i32,
        x1: i32,
        mut masks: SampleMasks,
        offsets: &[SampleOffset],
    ) {
        let n = (x1 - x0) as usize;
        if let Some(pattern) = &state.polygon_stipple {
            let stipple = stipple_mask(pattern, x0, y);
            masks.iter_mut().for_each(|m| *m &= stipple);
        }
        let dy = y as f32 + 0.5 - self.anchor[1];
        let dx0 = x0 as f32 + 0.5 - self.anchor[0];
        let shifts = sample_shifts(offsets);
        let span = Span { y, x0, n, row_start: band.sample_index(y, x0, 0), front_facing: self.front_facing };
        shade_span_samples(
            state,
            band,
            scratch,
            span,
            masks,
            |i, s| self.z.at(dx0 + i as f32 + shifts[s][0], dy + shifts[s][1]),
            |colors| self.shading.span_colors(dx0, dy, n, colors),
            |i, j, out| self.varyings.at(dx0 + i as f32, dy + j as f32, out),
        );
    }
}

#[cfg(test)]
mod varying_tests {
    use super::*;

    fn vertex(x: f32, y: f32, w: f32) -> WindowVertex {
        WindowVertex {
            x,
            y,
            z: 0.5,
            inv_w: 1.0 / w,
            color: [1.0; 4],
            secondary_color: [0.0; 4],
            tex_coords: [[0.0; 4]; VARYING_SLOTS],
            fog_coord: 0.0,
        }
    }

    #[test]
    fn varyings_are_perspective_correct() {
        let v = [vertex(1.0, 1.0, 1.0), vertex(60.0, 4.0, 8.0), vertex(10.0, 50.0, 2.5)];
        let attribute = [0.0f32, 1.0, 0.25];
        for order in [[0, 1, 2], [0, 2, 1], [2, 1, 0]] {
            let job = TriangleJob::new(order.map(|i| v[i]), None, 0.0, &[order.map(|i| attribute[i])]).unwrap();
            assert_eq!(job.varyings.len(), 1);
            for (px, py) in [(20, 10), (12, 30), (40, 9)] {
                // Screen-space barycentrics at the pixel centre, then the perspective-correct
                // value Σ λᵢ aᵢ/wᵢ / Σ λᵢ /wᵢ.
                let (x, y) = (px as f64 + 0.5, py as f64 + 0.5);
                let p = v.map(|q| (q.x as f64, q.y as f64));
                let area =
                    |a: (f64, f64), b: (f64, f64), c: (f64, f64)| (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1);
                let total = area(p[0], p[1], p[2]);
                let l = [
                    area((x, y), p[1], p[2]) / total,
                    area(p[0], (x, y), p[2]) / total,
                    area(p[0], p[1], (x, y)) / total,
                ];
                let num: f64 = (0..3).map(|i| l[i] * attribute[i] as f64 * v[i].inv_w as f64).sum();
                let den: f64 = (0..3).map(|i| l[i] * v[i].inv_w as f64).sum();
                let mut out = [0.0f32];
                job.varyings.at(x as f32 - job.anchor[0], y as f32 - job.anchor[1], &mut out);
                assert!((out[0] as f64 - num / den).abs() < 1e-5, "{order:?} ({px},{py}): {} vs {}", out[0], num / den);
            }
        }
    }

    #[test]
    fn draws_without_varyings_carry_none() {
        let v = [vertex(1.0, 1.0, 1.0), vertex(60.0, 4.0, 8.0), vertex(10.0, 50.0, 2.5)];
        assert!(TriangleJob::new(v, None, 0.0, &[]).unwrap().varyings.is_empty());
    }
}

#[cfg(test)]
mod block_walk_tests {
    use super::*;
    use crate::raster::blocks::{walk_blocks, PixelEdge};
    use crate::setup::triangle::GUARD_BAND;

    /// A tiny deterministic generator (xorshift) in [0, 1).
    fn unit(seed: &mut u64) -> f32 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        ((*seed >> 11) as f64 / (1u64 << 53) as f64) as f32
    }

    /// Walks `area` in blocks and compares every pixel of it (and of the blocks around it)
    /// with the per-pixel reference test.
    fn assert_blocks_match(t: &TriangleSetup, area: Rect) {
        let edges = t.pixel_edges().map(PixelEdge::from_array);
        let (w, h) = (area.width(), area.height());
        let mut seen = vec![false; w * h];
        walk_blocks(crate::simd::current(), area, &edges, None, |x, y, mask| {
            assert!(x % 4 == 0 && y % 4 == 0, "block origin ({x},{y})");
            for i in 0..16 {
                if mask & (1 << i) != 0 {
                    let (px, py) = (x + (i & 3), y + (i >> 2));
                    assert!(px >= area.x0 && px < area.x1 && py >= area.y0 && py < area.y1, "({px},{py}) outside");
                    let cell = &mut seen[(py - area.y0) as usize * w + (px - area.x0) as usize];
                    assert!(!*cell, "({px},{py}) twice");
                    *cell = true;
                }
            }
        });
        for y in 0..h {
            for x in 0..w {
                let (px, py) = (area.x0 + x as i32, area.y0 + y as i32);
                let span = t.row_span(py, area.x0, area.x1).is_some_and(|(a, b)| a <= px && px < b);
                assert_eq!(seen[y * w + x], t.covers(px, py), "pixel ({px},{py}) of {:?}", t.vertices);
                assert_eq!(span, t.covers(px, py));
            }
        }
    }

    #[test]
    fn blocks_cover_exactly_the_pixels_of_the_edge_test() {
        let mut seed = 0x2545_f491_4f6c_dd1d;
        for round in 0..3000 {
            // Small, tile-sized and huge triangles (vertices near the guard band), some
            // with vertices on pixel centres and edges through them (the fill rule).
            let range = match round % 4 {
                0 => 20.0,
                1 => 150.0,
                2 => 2.0 * GUARD_BAND,
                _ => 4000.0,
            };
            let mut v =
                [0, 1, 2].map(|_| [unit(&mut seed) * range - range / 3.0, unit(&mut seed) * range - range / 3.0]);
            if round % 5 == 0 {
                v = v.map(|p| p.map(|c| (c.clamp(-GUARD_BAND, GUARD_BAND) as i32) as f32 + 0.5));
            }
            let v = v.map(|p| p.map(|c| c.clamp(-GUARD_BAND, GUARD_BAND)));
            let Some(t) = TriangleSetup::new(v) else { continue };
            // A tile-sized area somewhere in a 16384-wide framebuffer, not aligned.
            let x0 = (unit(&mut seed) * 200.0) as i32 + if round % 3 == 0 { 16000 } else { 0 };
            let y0 = (unit(&mut seed) * 200.0) as i32;
            let area =
                Rect::from_xywh(x0, y0, 1 + (unit(&mut seed) * 90.0) as i32, 1 + (unit(&mut seed) * 90.0) as i32);
            assert_blocks_match(&t, area);
        }
    }

    #[test]
    fn shared_edges_through_centres_are_walked_once() {
        let quad = [[0.5, 0.5], [40.5, 0.5], [40.5, 33.5], [0.5, 33.5]];
        let a = TriangleSetup::new([quad[0], quad[1], quad[2]]).unwrap();
        let b = TriangleSetup::new([quad[0], quad[2], quad[3]]).unwrap();
        let mut hits = vec![0u8; 64 * 64];
        for t in [&a, &b] {
            walk_blocks(
                crate::simd::current(),
                Rect::from_xywh(0, 0, 64, 64),
                &t.pixel_edges().map(PixelEdge::from_array),
                None,
                |x, y, m| {
                    for i in 0..16 {
                        if m & (1 << i) != 0 {
                            hits[((y + (i >> 2)) * 64 + x + (i & 3)) as usize] += 1;
                        }
                    }
                },
            );
        }
        for y in 0..64 {
            for x in 0..64 {
                let inside = x < 40 && y < 33;
                assert_eq!(hits[y * 64 + x], inside as u8, "({x},{y})");
            }
        }
    }
}

#[cfg(test)]
mod sample_block_tests {
    use super::*;
    use crate::fragment::blend::{Blend, BlendEquation, BlendFactor, BlendFunc};
    use crate::fragment::multisample::MultisampleState;
    use crate::fragment::stencil::{StencilFace, StencilOp};
    use crate::fragment::{AlphaTest, DepthTest, FragmentState, StencilTest};
    use crate::framebuffer::band::{ColorBand, ColorTarget, DepthBand};
    use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat};
    use crate::gl::CompareFunc;
    use crate::glsl::varyings::VARYING_SLOTS;
    use crate::raster::blocks::walk_blocks;
    use crate::setup::triangle::TriangleSetup;
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::Arc;

    /// A tiny deterministic generator (xorshift).
    struct Rng(u64);
    impl Rng {
        fn bits(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn unit(&mut self) -> f32 {
            ((self.bits() >> 11) as f64 / (1u64 << 53) as f64) as f32
        }
        fn below(&mut self, n: u64) -> u64 {
            self.bits() % n
        }
    }

    #[test]
    fn block_sample_masks_are_the_span_walk_samples() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for round in 0..1500 {
            let range = [6.0, 30.0, 120.0][round % 3];
            let mut v = [0, 1, 2].map(|_| [rng.unit() * range, rng.unit() * range]);
            if round % 4 == 0 {
                // On sample positions and pixel edges: the fill rule decides.
                v = v.map(|p| p.map(|c| (c * 4.0) as i32 as f32 / 4.0));
            }
            let Some(t) = TriangleSetup::new(v) else { continue };
            let (bx0, by0, bx1, by1) = t.pixel_box();
            let area = Rect { x0: bx0.max(0), y0: by0.max(0), x1: bx1.min(200), y1: by1.min(200) };
            for samples in [2, 4, 8] {
                let offsets = sample_offsets(samples);
                let edges = t.pixel_edges().map(PixelEdge::from_array);
                let se = SampleEdges::new(&edges, offsets.iter().map(|o| [o.x, o.y]));
                let w = 200usize;
                let mut got = vec![0u8; w * w];
                walk_blocks(crate::simd::current(), area, &se.widened(), None, |x, y, mask| {
                    let masks = se.masks(x, y, mask);
                    assert!(masks[samples..].iter().all(|&m| m == 0));
                    for (s, m) in masks.iter().enumerate() {
                        assert_eq!(m & !mask, 0);
                        for i in 0..16 {
                            if m & (1 << i) != 0 {
                                got[(y as usize + i / 4) * w + x as usize + i % 4] |= 1 << s;
                            }
                        }
                    }
                });
                for py in area.y0..area.y1 {
                    let mut want = vec![0u8; w];
                    for (s, o) in offsets.iter().enumerate() {
                        if let Some((a, b)) = t.row_span_at(py, o.x, o.y, area.x0, area.x1) {
                            for cell in &mut want[a as usize..b as usize] {
                                *cell |= 1 << s;
                            }
                        }
                    }
                    for px in area.x0..area.x1 {
                        assert_eq!(
                            got[py as usize * w + px as usize],
                            want[px as usize],
                            "{v:?} {samples} ({px},{py})"
                        );
                    }
                }
            }
        }
    }

    fn vertex(rng: &mut Rng, size: f32) -> WindowVertex {
        WindowVertex {
            x: rng.unit() * (size + 20.0) - 10.0,
            y: rng.unit() * (size + 20.0) - 10.0,
            z: rng.unit() * 1.2 - 0.1,
            inv_w: 0.3 + rng.unit() * 2.0,
            color: [rng.unit(), rng.unit(), rng.unit(), rng.unit()],
            secondary_color: [0.0; 4],
            tex_coords: [[0.0; 4]; VARYING_SLOTS],
            fog_coord: 0.0,
        }
    }

    fn face(rng: &mut Rng) -> StencilFace {
        use StencilOp::*;
        let ops = [Keep, Zero, Replace, Incr, Decr, IncrWrap, DecrWrap, Invert];
        let op = |rng: &mut Rng| ops[rng.below(8) as usize];
        StencilFace {
            func: CompareFunc::ALL[rng.below(8) as usize],
            reference: rng.below(6) as u8,
            value_mask: [0xff, 0x7, 0xfe][rng.below(3) as usize],
            write_mask: [0xff, 0x3, 0][rng.below(3) as usize],
            sfail: op(rng),
            zfail: op(rng),
            zpass: op(rng),
        }
    }

    /// A random draw state of the kinds the sample block path takes.
    fn random_state(rng: &mut Rng, samples: usize, size: i32, stencil: bool) -> DrawState {
        let depth = (rng.below(5) != 0)
            .then(|| DepthTest { func: CompareFunc::ALL[rng.below(8) as usize], write: rng.below(3) != 0 });
        let mask = match rng.below(4) {
            0 => [true, false, true, false],
            _ => [true; 4],
        };
        let mut fragment = FragmentState::plain(depth, vec![Some(mask)], false);
        if stencil && rng.below(2) == 0 {
            fragment.stencil = Some(StencilTest { front: face(rng), back: face(rng) });
        }
        if rng.below(3) == 0 {
            let func = CompareFunc::ALL[rng.below(8) as usize];
            fragment.alpha = Some(AlphaTest { func, reference: rng.unit(), unorm8: rng.below(2) == 0 });
        }
        if rng.below(3) == 0 {
            let func = BlendFunc {
                src: BlendFactor::SrcAlpha,
                dst: BlendFactor::OneMinusSrcAlpha,
                equation: BlendEquation::ALL[rng.below(5) as usize],
            };
            fragment.blend = vec![Some(Blend { rgb: func, alpha: func })];
        }
        let all = ((1u32 << samples) - 1) as u8;
        let multisample = MultisampleState {
            samples: samples as u8,
            enabled: rng.below(4) != 0,
            alpha_to_coverage: false,
            alpha_to_one: rng.below(4) == 0,
            coverage_mask: if rng.below(3) == 0 { rng.below(256) as u8 & all } else { all },
        };
        let clip = if rng.below(3) == 0 {
            Rect::from_xywh(3, 5, size - 9, size - 7)
        } else {
            Rect::from_xywh(0, 0, size, size)
        };
        let polygon_stipple =
            (rng.below(6) == 0).then(|| std::array::from_fn(|i| 0x5a5a_f00f_u32.rotate_left(i as u32 * 3)));
        DrawState {
            fragment,
            clip,
            fill_clip: clip,
            polygon_stipple,
            samples_passed: Some(Arc::new(AtomicU64::new(0))),
            multisample: Some(multisample),
        }
    }

    #[test]
    fn flat_triangles_write_through_constant_fills_what_spans_write() {
        // Flat triangles over two tiles' areas, single-sampled, under states of which some
        // take the constant fill (no test, mask or blend; scissored or not, stippled or not)
        // and some must not (a channel mask, blending, a depth test, an alpha test, an
        // occlusion count): the block path writes the span path's bytes either way, and
        // the fill is taken where it may be.
        let size = 150i32;
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let mut filled = 0;
        for round in 0..300 {
            let n = (size * size) as usize;
            let mut colors = [vec![[7u8, 9, 11, 13]; n], vec![[7u8, 9, 11, 13]; n]];
            let mut depth = [vec![0x0080_0000u32; n], vec![0x0080_0000u32; n]];
            let [c0, c1] = &mut colors;
            let [d0, d1] = &mut depth;
            let mut bands: Vec<Band<'_>> = [(c0, d0), (c1, d1)]
                .into_iter()
                .map(|(c, d)| Band {
                    y0: 0,
                    rows: size as usize,
                    width: size as usize,
                    samples: 1,
                    colors: vec![ColorTarget {
                        slot: ColorSlot::FrontLeft,
                        format: ColorFormat::Unorm8 { alpha: true },
                        pixels: ColorBand::Unorm8(c),
                    }],
                    depth: DepthBand::Packed24(d),
                    depth_format: DepthStencilFormat::Packed24 { depth: true, stencil: true },
                    hiz: Default::default(),
                })
                .collect();
            let kind = round % 8;
            let mask = if kind == 5 { [true, true, false, true] } else { [true; 4] };
            let depth_test = (kind == 6).then_some(DepthTest { func: CompareFunc::Less, write: true });
            let mut fragment = FragmentState::plain(depth_test, vec![Some(mask)], false);
            if kind == 7 {
                let func = BlendFunc {
                    src: BlendFactor::SrcAlpha,
                    dst: BlendFactor::OneMinusSrcAlpha,
                    equation: BlendEquation::ALL[0],
                };
                fragment.blend = vec![Some(Blend { rgb: func, alpha: func })];
            }
            if kind == 4 {
                fragment.alpha = Some(AlphaTest { func: CompareFunc::Greater, reference: 0.5, unorm8: false });
            }
            let clip = if kind == 1 {
                Rect::from_xywh(13, 7, size - 31, size - 20)
            } else {
                Rect::from_xywh(0, 0, size, size)
            };
            let state = DrawState {
                fragment,
                clip,
                fill_clip: clip,
                polygon_stipple: (kind == 2).then(|| std::array::from_fn(|i| 0x5a5a_f00f_u32.rotate_left(i as u32))),
                samples_passed: (kind == 3).then(|| Arc::new(AtomicU64::new(0))),
                multisample: None,
            };
            let format = DepthStencilFormat::Packed24 { depth: true, stencil: true };
            let pipeline = BlockPipeline::compile(&state.fragment, &[ColorFormat::Unorm8 { alpha: true }], format);
            let may_fill = kind <= 2;
            let mut scratch = Scratch::default();
            let mut batch = Batch::default();
            for _ in 0..4 {
                let v = [0, 1, 2].map(|_| vertex(&mut rng, size as f32));
                let c = [rng.unit(), rng.unit() * 1.2 - 0.1, rng.unit(), rng.unit()];
                let Some(job) = TriangleJob::new(v, Some(c), 0.0, &[]) else { continue };
                let fills = pipeline.constant_fill(&state, c).is_some();
                // (The stippled state's pipeline fills; its triangle does not take the fill.)
                assert_eq!(fills, may_fill, "round {round}: kind {kind}");
                filled += usize::from(fills && kind != 2);
                for area in [Rect::from_xywh(0, 0, size, 64), Rect::from_xywh(0, 64, size, size - 64)] {
                    let area = area.intersect(state.fill_clip);
                    job.render_blocks(&state, &pipeline, area, &mut bands[0], &mut scratch, &mut batch);
                    job.render(&state, area, &mut bands[1], &mut scratch);
                }
            }
            drop(bands);
            assert!(colors[0] == colors[1], "round {round}: colours differ (kind {kind})");
            assert!(depth[0] == depth[1], "round {round}: depth differs (kind {kind})");
        }
        assert!(filled > 100, "{filled}");
    }

    #[test]
    fn multisampled_blocks_write_what_sample_spans_write() {
        let size = 70i32;
        let mut rng = Rng(0x2545_f491_4f6c_dd1d);
        for round in 0..600 {
            let samples = [2, 4, 8][round % 3];
            let format = [
                DepthStencilFormat::Packed24 { depth: true, stencil: true },
                DepthStencilFormat::Depth16,
                DepthStencilFormat::Float32 { stencil: true },
            ][(round / 3) % 3];
            let stencil = format.stencil_bits() > 0;
            let n = (size * size) as usize * samples;
            let mut colors = [vec![[7u8, 9, 11, 13]; n], vec![[7u8, 9, 11, 13]; n]];
            let mut depth32 = [vec![0u32; n], vec![0u32; n]];
            let mut depth16 = [vec![0u16; n], vec![0u16; n]];
            let mut stencil8 = [vec![0u8; n], vec![0u8; n]];
            // Stored depth and stencil varying per sample.
            for i in 0..n {
                let (d, s) = (rng.bits() as u32, rng.below(6) as u8);
                for k in 0..2 {
                    depth32[k][i] = match format {
                        DepthStencilFormat::Packed24 { .. } => (d & 0x00ff_ffff) | (u32::from(s) << 24),
                        _ => ((d % 1001) as f32 / 1000.0).to_bits(),
                    };
                    depth16[k][i] = d as u16;
                    stencil8[k][i] = s;
                }
            }
            let [c0, c1] = &mut colors;
            let [d0, d1] = &mut depth32;
            let [h0, h1] = &mut depth16;
            let [s0, s1] = &mut stencil8;
            let mut bands: Vec<Band<'_>> = [(c0, d0, h0, s0), (c1, d1, h1, s1)]
                .into_iter()
                .map(|(c, d, h, s)| Band {
                    y0: 0,
                    rows: size as usize,
                    width: size as usize,
                    samples,
                    colors: vec![ColorTarget {
                        slot: ColorSlot::FrontLeft,
                        format: ColorFormat::Unorm8 { alpha: true },
                        pixels: ColorBand::Unorm8(c),
                    }],
                    depth: match format {
                        DepthStencilFormat::Packed24 { .. } => DepthBand::Packed24(d),
                        DepthStencilFormat::Depth16 => DepthBand::Depth16(h),
                        _ => DepthBand::Float32(d, Some(s)),
                    },
                    depth_format: format,
                    hiz: Default::default(),
                })
                .collect();
            let state = random_state(&mut rng, samples, size, stencil);
            let pipeline = BlockPipeline::compile(&state.fragment, &[ColorFormat::Unorm8 { alpha: true }], format);
            let counter = state.samples_passed.clone().unwrap();
            let (mut block_count, mut span_count) = (0, 0);
            let mut scratch = Scratch::default();
            for _ in 0..6 {
                let v = [0, 1, 2].map(|_| vertex(&mut rng, size as f32));
                let flat = (rng.below(4) == 0).then_some([0.25, 0.5, 0.75, 0.4]);
                let Some(mut job) = TriangleJob::new(v, flat, 0.0, &[]) else { continue };
                job.front_facing = rng.below(2) == 0;
                // Two tiles' worth of areas, as the scene hands them.
                for area in [Rect::from_xywh(0, 0, size, 32), Rect::from_xywh(0, 32, size, size - 32)] {
                    let area = area.intersect(state.fill_clip);
                    counter.store(0, Ordering::Relaxed);
                    job.render_sample_blocks(&state, &pipeline, area, &mut bands[0], &mut scratch);
                    block_count += counter.load(Ordering::Relaxed);
                    counter.store(0, Ordering::Relaxed);
                    if state.multisample.unwrap().per_sample() {
                        job.render_samples(&state, area, &mut bands[1], &mut scratch);
                    } else {
                        job.render(&state, area, &mut bands[1], &mut scratch);
                    }
                    span_count += counter.load(Ordering::Relaxed);
                }
            }
            drop(bands);
            assert_eq!(block_count, span_count, "round {round}: samples passed");
            assert!(colors[0] == colors[1], "round {round}: colours differ ({samples} samples, {format:?})");
            assert!(depth32[0] == depth32[1] && depth16[0] == depth16[1], "round {round}: depth differs");
            assert!(stencil8[0] == stencil8[1], "round {round}: stencil differs");
        }
    }
}
