//! The tiled rasterizer: scenes of binned primitives, rendered band by band by a pool of
//! workers.
//!
//! A draw call appends its primitives (already set up: edges, attribute planes) and a
//! snapshot of its state to the [`Scene`]; each primitive is binned into the 64×64 tiles
//! its bounding box touches. At a flush point the scene runs: the framebuffer is split into
//! bands (rows of tiles), `TESSERA_THREADS` workers (the calling thread included) take bands
//! one at a time, and each band renders its tiles, each tile its bin in submission order.
//! A pixel is only ever touched by the one worker owning its band, in submission order, so
//! the bytes are identical for any number of threads.

pub mod accuracy;
pub mod interpolate;
pub mod line;
pub mod multisample;
pub mod pixels;
pub mod point;
pub mod smooth;
pub mod triangle;

use crate::fragment::output::write_target;
use crate::fragment::{stencil_depth_test, write_colors, write_uniform_color, FragmentState, MAX_SPAN};
use crate::framebuffer::band::Band;
use crate::framebuffer::{ColorSlot, Framebuffer, Rect};
use line::LineJob;
use point::PointJob;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, OnceLock};
use triangle::TriangleJob;

/// Tile side in pixels.
pub const TILE_SIZE: usize = 64;

/// How many of a scene's most recent draw states a new draw's state is compared with before
/// it is added (see [`Scene::add_state`]).
pub const STATE_CACHE: usize = 4;

/// What a draw call's primitives share: the compiled fragment state and the scissor box.
/// Compared whole when a scene caches states ([`Scene::add_state`]).
#[derive(Debug)]
pub struct DrawState {
    pub fragment: FragmentState,
    /// Pixels outside this rectangle (scissor box ∩ framebuffer) are never written.
    pub clip: Rect,
    /// `clip` ∩ the viewport: filled triangles are clipped only to a guard band far
    /// outside the view volume, so the viewport bounds them here instead (points and wide
    /// lines may legitimately reach outside the viewport; they use `clip`).
    pub fill_clip: Rect,
    /// GL_POLYGON_STIPPLE's pattern when enabled (filled polygons only): row `y % 32`
    /// from the bottom of the window, bit `31 − x % 32` for column `x`.
    pub polygon_stipple: Option<[u32; 32]>,
    /// The active occlusion query's counter: fragments passing the depth and stencil tests
    /// are added per span (a sum, so the same for any thread count).
    pub samples_passed: Option<Arc<AtomicU64>>,
    /// The multisample state when the framebuffer is multisampled (`multisample.rs`).
    pub multisample: Option<multisample::MultisampleState>,
}

impl PartialEq for DrawState {
    /// Equal states compile to the same pipeline; two draws count into the same occlusion
    /// query only if they share its counter.
    fn eq(&self, other: &Self) -> bool {
        let same_counter = match (&self.samples_passed, &other.samples_passed) {
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            (None, None) => true,
            _ => false,
        };
        same_counter
            && self.fragment == other.fragment
            && self.clip == other.clip
            && self.fill_clip == other.fill_clip
            && self.polygon_stipple == other.polygon_stipple
            && self.multisample == other.multisample
    }
}

/// A primitive ready for rasterization.
pub enum Primitive {
    Triangle(TriangleJob),
    Line(LineJob),
    Point(PointJob),
    /// A smooth (antialiased) line, point or triangle.
    Smooth(smooth::SmoothJob),
    /// A pixel rectangle (glBitmap, glDrawPixels).
    Pixels(pixels::PixelRectJob),
}

/// Per-worker storage reused across spans.
#[derive(Default)]
pub struct Scratch {
    pub z: Vec<f32>,
    pub colors: Vec<[f32; 4]>,
    /// One fragment's varyings (color sum and fog).
    pub varyings: Vec<f32>,
    /// Texturing: the varyings of a fragment and of its quad's neighbours.
    pub texture: Vec<f32>,
}

/// Where a span lies: window row `y`, columns `x0..x0 + n`, starting at pixel `row_start`
/// of the band, and the facing of the primitive it belongs to (for two-sided stencil).
#[derive(Clone, Copy, Debug)]
pub struct Span {
    pub y: i32,
    pub x0: i32,
    pub n: usize,
    pub row_start: usize,
    pub front_facing: bool,
}

/// Runs the per-fragment operations on the fragments of `live` of one span, in GL order:
/// texturing, alpha test, stencil and depth tests, then for each color target blending or
/// the logic op, dither and the masked write. `z_at(i)` is pixel i's window depth; `colors`
/// fills `scratch.colors` with the span's colors, or returns the one color of a flat span;
/// `varyings(dx, dy, out)` gives the varyings of the pixel `dx` columns right of the span's
/// first and `dy` rows above it, read for texturing (which also reads the pixel's 2×2 quad
/// neighbours), the color sum and fog. The color sum and fog finish the colors after the
/// tests (they change no alpha, so the alpha test may run first). Colors (and texturing)
/// are computed before the tests only when the alpha test needs them; an untextured draw
/// does no texture work at all.
#[inline]
// The per-primitive inputs are separate closures so that each primitive's are inlined.
#[allow(clippy::too_many_arguments)]
pub fn shade_span(
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    span: Span,
    live: u64,
    z_at: impl Fn(usize) -> f32,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: impl Fn(i32, i32, &mut [f32]),
) {
    shade_covered_span(state, band, scratch, span, live, z_at, colors, varyings, FullCoverage);
}

/// How much of each pixel of a span a primitive covers, multiplied into the fragments'
/// alpha after texturing (GL 2.1 §3.12): [`FullCoverage`] for aliased primitives (no work
/// at all: the choice is made per primitive type, at compile time), a slice of per-pixel
/// coverages for smooth ones ([`smooth`]).
pub trait Coverage {
    /// Applies the coverage to the span's colors: `uniform` is the one color of a uniform
    /// span (then `colors` is not filled yet); returns the uniform color that remains.
    fn apply(&self, colors: &mut Vec<[f32; 4]>, uniform: Option<[f32; 4]>, n: usize) -> Option<[f32; 4]>;
}

/// Every pixel fully covered: aliased primitives.
#[derive(Clone, Copy, Debug)]
pub struct FullCoverage;

impl Coverage for FullCoverage {
    #[inline(always)]
    fn apply(&self, _: &mut Vec<[f32; 4]>, uniform: Option<[f32; 4]>, _: usize) -> Option<[f32; 4]> {
        uniform
    }
}

impl Coverage for &[f32] {
    #[inline]
    fn apply(&self, colors: &mut Vec<[f32; 4]>, uniform: Option<[f32; 4]>, n: usize) -> Option<[f32; 4]> {
        if let Some(color) = uniform {
            colors.clear();
            colors.resize(n, color);
        }
        for (color, coverage) in colors.iter_mut().zip(self.iter()) {
            color[3] *= coverage;
        }
        None
    }
}

/// [`shade_span`] with the primitive's `coverage` multiplied into the alpha of its
/// fragments.
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn shade_covered_span(
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    span: Span,
    mut live: u64,
    z_at: impl Fn(usize) -> f32,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: impl Fn(i32, i32, &mut [f32]),
    coverage: impl Coverage,
) {
    if band.samples > 1 {
        return multisample::shade_span_all_samples(state, band, scratch, span, live, z_at, colors, varyings);
    }
    let fragment = &state.fragment;
    let mut colors = Some(colors);
    let mut uniform = None;
    if let Some(alpha) = &fragment.alpha {
        if let Some(c) = colors.take() {
            uniform = shade_colors(fragment, &span, scratch, live, c, &varyings);
            uniform = coverage.apply(&mut scratch.colors, uniform, span.n);
        }
        live = match uniform {
            Some(c) if alpha.passes_one(c[3]) => live,
            Some(_) => 0,
            None => alpha.test(&scratch.colors, live),
        };
        if live == 0 {
            return;
        }
    }
    if fragment.depth.is_some() || fragment.stencil.is_some() {
        scratch.z.clear();
        if fragment.depth.is_some() {
            scratch.z.extend((0..span.n).map(&z_at));
            if let Some([min, max]) = fragment.depth_clamp {
                for z in &mut scratch.z {
                    *z = z.clamp(min, max);
                }
            }
        }
        let face = fragment.stencil.as_ref().map(|s| if span.front_facing { &s.front } else { &s.back });
        live = stencil_depth_test(
            face,
            fragment.depth.as_ref(),
            &mut band.depth,
            span.row_start,
            span.n,
            &scratch.z,
            live,
        );
        if live == 0 {
            return;
        }
    }
    if let Some(counter) = &state.samples_passed {
        counter.fetch_add(live.count_ones() as u64, Ordering::Relaxed);
    }
    if let Some(c) = colors {
        uniform = shade_colors(fragment, &span, scratch, live, c, &varyings);
        uniform = coverage.apply(&mut scratch.colors, uniform, span.n);
    }
    if fragment.needs_varyings() {
        if let Some(color) = uniform.take() {
            scratch.colors.clear();
            scratch.colors.resize(span.n, color);
        }
        let fog_slot = usize::from(fragment.color_sum) * 3;
        scratch.varyings.resize(fog_slot + 1, 0.0);
        fragment.sum_and_fog(&mut scratch.colors, live, &mut scratch.varyings, |i, out| varyings(i as i32, 0, out));
    }
    match uniform {
        Some(color) => write_span_uniform(fragment, band, &span, color, live),
        None => write_span_colors(fragment, band, &span, &scratch.colors, live),
    }
}

/// The colors of a span's fragments before the tests: the interpolated (or flat) colors,
/// textured when the draw textures (then never uniform).
#[inline]
fn shade_colors(
    fragment: &FragmentState,
    span: &Span,
    scratch: &mut Scratch,
    live: u64,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: &impl Fn(i32, i32, &mut [f32]),
) -> Option<[f32; 4]> {
    scratch.colors.clear();
    let uniform = colors(&mut scratch.colors);
    let Some(texturing) = &fragment.texturing else {
        return uniform;
    };
    if let Some(color) = uniform {
        scratch.colors.resize(span.n, color);
    }
    texturing.texture_span(&mut scratch.colors, live, span.x0, span.y, &mut scratch.texture, varyings);
    None
}

/// Writes a shaded span (`colors[i]` for every bit `i` of `live`) to every color target the
/// draw writes, blending, logic-opping and dithering where the draw says so.
#[inline]
pub fn write_span_colors(fragment: &FragmentState, band: &mut Band<'_>, span: &Span, colors: &[[f32; 4]], live: u64) {
    for (index, (target, mask)) in band.colors.iter_mut().zip(&fragment.color_masks).enumerate() {
        let Some(mask) = *mask else { continue };
        if fragment.target_has_ops(index) {
            let ops = fragment.target_ops(index, mask);
            write_target(&mut target.pixels, span.row_start, span.x0, span.y, colors, live, &ops);
        } else {
            write_colors(&mut target.pixels, span.row_start, colors, live, mask, fragment.clamp_float);
        }
    }
}

/// Calls `shade(y, x0, x1)` for every covered span of `area`, row by row, in pieces of at
/// most [`MAX_SPAN`] pixels; `row_span(y, x0, x1)` gives a row's covered pixels within
/// `[x0, x1)`.
#[inline]
pub fn walk_spans(
    area: Rect,
    row_span: impl Fn(i32, i32, i32) -> Option<(i32, i32)>,
    mut shade: impl FnMut(i32, i32, i32),
) {
    for y in area.y0..area.y1 {
        let Some((x0, x1)) = row_span(y, area.x0, area.x1) else {
            continue;
        };
        let mut start = x0;
        while start < x1 {
            let end = (start + MAX_SPAN as i32).min(x1);
            shade(y, start, end);
            start = end;
        }
    }
}

/// The live-fragment mask of an `n`-pixel span (bit i: pixel i), n ≤ 64.
#[inline]
pub fn span_mask(n: usize) -> u64 {
    if n >= 64 {
        !0
    } else {
        (1u64 << n) - 1
    }
}

/// As [`write_span_colors`] for a span of one color (flat shading).
#[inline]
pub fn write_span_uniform(fragment: &FragmentState, band: &mut Band<'_>, span: &Span, color: [f32; 4], live: u64) {
    let n = span.n;
    let mut expanded = None;
    for (index, (target, mask)) in band.colors.iter_mut().zip(&fragment.color_masks).enumerate() {
        let Some(mask) = *mask else { continue };
        if fragment.target_has_ops(index) {
            let colors: &[[f32; 4]; MAX_SPAN] = expanded.get_or_insert([color; MAX_SPAN]);
            let ops = fragment.target_ops(index, mask);
            write_target(&mut target.pixels, span.row_start, span.x0, span.y, &colors[..n], live, &ops);
        } else {
            write_uniform_color(&mut target.pixels, span.row_start, n, color, live, mask, fragment.clamp_float);
        }
    }
}

/// Recorded rendering waiting for a flush point.
pub struct Scene {
    width: usize,
    height: usize,
    tiles_x: usize,
    /// The color buffers the scene writes, in the order of every draw's color masks.
    targets: Vec<ColorSlot>,
    states: Vec<Arc<DrawState>>,
    primitives: Vec<(u32, Primitive)>,
    /// Per tile (row-major), indices into `primitives` in submission order.
    bins: Vec<Vec<u32>>,
    /// How many indices the bins hold in all.
    binned: usize,
}

impl Scene {
    /// An empty scene for a `width` × `height` framebuffer.
    pub fn new(width: usize, height: usize) -> Scene {
        let tiles_x = width.div_ceil(TILE_SIZE);
        let tiles_y = height.div_ceil(TILE_SIZE);
        Scene {
            width,
            height,
            tiles_x,
            targets: Vec::new(),
            states: Vec::new(),
            primitives: Vec::new(),
            bins: vec![Vec::new(); tiles_x * tiles_y],
            binned: 0,
        }
    }

    /// The recorded primitives a scene may hold before the context renders it (whatever
    /// the thread count, so the same commands flush at the same points): a long draw then
    /// needs this much memory for its primitives, not memory in proportion to its length.
    pub const BUDGET_BYTES: usize = 64 << 20;

    /// About how much memory the recorded primitives and their bin entries take.
    pub fn recorded_bytes(&self) -> usize {
        self.primitives.len() * std::mem::size_of::<(u32, Primitive)>() + self.binned * std::mem::size_of::<u32>()
    }

    pub fn is_empty(&self) -> bool {
        self.primitives.is_empty()
    }

    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// The index of `slot` among the scene's color targets, adding it if new.
    pub fn target_index(&mut self, slot: ColorSlot) -> usize {
        if let Some(i) = self.targets.iter().position(|&s| s == slot) {
            return i;
        }
        self.targets.push(slot);
        self.targets.len() - 1
    }

    /// How many color targets the scene has so far.
    pub fn target_count(&self) -> usize {
        self.targets.len()
    }

    /// Adds a draw's state; primitives added afterwards refer to it. A state equal to one of
    /// the last [`STATE_CACHE`] states is not added again: its index is returned, with
    /// `true` for "cached" (a loop of glBegin/glEnd pairs with unchanged state shares one
    /// compiled state).
    pub fn add_state(&mut self, state: DrawState) -> (u32, bool) {
        let recent = self.states.len().saturating_sub(STATE_CACHE);
        if let Some(i) = self.states[recent..].iter().rposition(|s| **s == state) {
            return ((recent + i) as u32, true);
        }
        self.states.push(Arc::new(state));
        ((self.states.len() - 1) as u32, false)
    }

    /// How many distinct draw states the scene holds.
    pub fn state_count(&self) -> usize {
        self.states.len()
    }

    /// Bins a primitive covering at most the pixel rectangle `bounds` (inclusive min,
    /// exclusive max), under draw state `state`.
    pub fn add(&mut self, state: u32, bounds: Rect, primitive: Primitive) {
        let drawn = &self.states[state as usize];
        let clip = if matches!(primitive, Primitive::Triangle(_)) { drawn.fill_clip } else { drawn.clip };
        // Rasterized per sample, a triangle may cover samples of pixels whose centre it misses.
        let bounds = match &primitive {
            Primitive::Triangle(job) if drawn.multisample.is_some_and(|m| m.per_sample()) => job.sample_bounds(),
            _ => bounds,
        };
        let r = bounds.intersect(clip);
        if r.is_empty() {
            return;
        }
        let index = self.primitives.len() as u32;
        self.primitives.push((state, primitive));
        let t = TILE_SIZE as i32;
        let (rows, columns) = ((r.y0 / t)..=((r.y1 - 1) / t), (r.x0 / t)..=((r.x1 - 1) / t));
        self.binned += rows.clone().count() * columns.clone().count();
        for ty in rows {
            for tx in columns.clone() {
                self.bins[ty as usize * self.tiles_x + tx as usize].push(index);
            }
        }
    }

    /// Bins a primitive covering at most `bounds`, but only into the tiles of each tile row
    /// that `columns` (the half-open pixel columns it may cover within a half-open range
    /// of rows) names: long thin primitives (lines) cross few of their bounding box's tiles.
    pub fn add_narrow(
        &mut self,
        state: u32,
        bounds: Rect,
        primitive: Primitive,
        columns: impl Fn(i32, i32) -> Option<(i32, i32)>,
    ) {
        let clip = self.states[state as usize].clip;
        let r = bounds.intersect(clip);
        if r.is_empty() {
            return;
        }
        let index = self.primitives.len() as u32;
        let t = TILE_SIZE as i32;
        let mut binned = false;
        for ty in (r.y0 / t)..=((r.y1 - 1) / t) {
            let Some((x0, x1)) = columns(r.y0.max(ty * t), r.y1.min(ty * t + t)) else {
                continue;
            };
            let (x0, x1) = (x0.max(r.x0), x1.min(r.x1));
            if x0 >= x1 {
                continue;
            }
            for tx in (x0 / t)..=((x1 - 1) / t) {
                self.bins[ty as usize * self.tiles_x + tx as usize].push(index);
                self.binned += 1;
                binned = true;
            }
        }
        if binned {
            self.primitives.push((state, primitive));
        }
    }

    /// Renders the scene into `framebuffer` (which must have the scene's size) on
    /// `thread_count()` threads.
    pub fn execute(self, framebuffer: &mut Framebuffer) {
        self.execute_on(framebuffer, thread_count());
    }

    /// Renders the scene on up to `threads` threads (the caller's included).
    pub fn execute_on(self, framebuffer: &mut Framebuffer, threads: usize) {
        if self.primitives.is_empty() {
            return;
        }
        let bands = framebuffer.bands(TILE_SIZE, &self.targets);
        let scene = &self;
        run_parallel(bands, threads, |band| scene.render_band(band));
        if framebuffer.samples() > 1 {
            framebuffer.resolve(&self.targets, self.drawn_area());
        }
    }

    /// The smallest rectangle holding every tile with something binned into it.
    fn drawn_area(&self) -> Rect {
        let mut area = Rect { x0: i32::MAX, y0: i32::MAX, x1: i32::MIN, y1: i32::MIN };
        for (i, _) in self.bins.iter().enumerate().filter(|(_, b)| !b.is_empty()) {
            let t = TILE_SIZE as i32;
            let (tx, ty) = ((i % self.tiles_x) as i32, (i / self.tiles_x) as i32);
            area.x0 = area.x0.min(tx * t);
            area.y0 = area.y0.min(ty * t);
            area.x1 = area.x1.max(tx * t + t);
            area.y1 = area.y1.max(ty * t + t);
        }
        area
    }

    /// Renders every tile of one band, each tile's primitives in submission order.
    fn render_band(&self, mut band: Band<'_>) {
        let ty = band.y0 as usize / TILE_SIZE;
        let mut scratch = Scratch::default();
        for tx in 0..self.tiles_x {
            let tile = Rect::from_xywh((tx * TILE_SIZE) as i32, band.y0, TILE_SIZE as i32, band.rows as i32)
                .intersect(Rect::from_xywh(0, 0, self.width as i32, self.height as i32));
            for &index in &self.bins[ty * self.tiles_x + tx] {
                let (state, primitive) = &self.primitives[index as usize];
                let state = &self.states[*state as usize];
                let area = tile.intersect(state.clip);
                match primitive {
                    Primitive::Triangle(job) if state.multisample.is_some_and(|m| m.per_sample()) => {
                        job.render_samples(state, tile.intersect(state.fill_clip), &mut band, &mut scratch)
                    }
                    Primitive::Triangle(job) => {
                        job.render(state, tile.intersect(state.fill_clip), &mut band, &mut scratch)
                    }
                    Primitive::Line(job) if job.per_sample() => {
                        job.render_samples(state, area, &mut band, &mut scratch)
                    }
                    Primitive::Line(job) => job.render(state, area, &mut band, &mut scratch),
                    Primitive::Point(job) if job.sample_square.is_some() => {
                        job.render_samples(state, area, &mut band, &mut scratch)
                    }
                    Primitive::Point(job) => job.render(state, area, &mut band, &mut scratch),
                    Primitive::Smooth(job) => job.render(state, area, &mut band, &mut scratch),
                    Primitive::Pixels(job) => job.render(state, area, &mut band, &mut scratch),
                }
            }
        }
    }
}

/// The number of rasterizer threads: `TESSERA_THREADS`, or the number of cores.
pub fn thread_count() -> usize {
    static COUNT: OnceLock<usize> = OnceLock::new();
    *COUNT.get_or_init(|| {
        std::env::var("TESSERA_THREADS")
            .ok()
            .and_then(|v| v.trim().parse::<usize>().ok())
            .filter(|&n| n >= 1)
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
            .min(256)
    })
}

/// Runs `work` on every item, on up to `threads` threads (the caller's included).
fn run_parallel<T: Send>(items: Vec<T>, threads: usize, work: impl Fn(T) + Sync) {
    let threads = threads.min(items.len());
    if threads <= 1 {
        items.into_iter().for_each(work);
        return;
    }
    let queue = Mutex::new(items.into_iter());
    let next = || queue.lock().unwrap_or_else(|p| p.into_inner()).next();
    let worker = || {
        while let Some(item) = next() {
            work(item);
        }
    };
    std::thread::scope(|s| {
        for _ in 1..threads {
            s.spawn(worker);
        }
        worker();
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fragment::{AlphaTest, DepthTest};
    use crate::framebuffer::band::{ColorBand, ColorTarget, DepthBand};
    use crate::framebuffer::{ColorFormat, DepthStencilFormat};
    use crate::gl::CompareFunc;
    use std::cell::Cell;

    fn state(alpha: bool) -> DrawState {
        let depth = Some(DepthTest { func: CompareFunc::Less, write: true });
        let mut fragment = FragmentState::plain(depth, vec![Some([true; 4])], false);
        fragment.alpha = alpha.then_some(AlphaTest { func: CompareFunc::Always, reference: 0.0, unorm8: true });
        let clip = Rect::from_xywh(0, 0, 4, 1);
        DrawState { fragment, clip, fill_clip: clip, polygon_stipple: None, samples_passed: None, multisample: None }
    }

    /// Runs one 4-pixel span at depth 0.5 over stored depths `stored`; returns how often the
    /// span's colors were computed and the color buffer afterwards.
    fn run_span(state: &DrawState, stored: [u16; 4]) -> (usize, [[u8; 4]; 4]) {
        let mut colors = [[0u8; 4]; 4];
        let mut depth = stored;
        let mut band = Band {
            y0: 0,
            rows: 1,
            width: 4,
            samples: 1,
            colors: vec![ColorTarget {
                slot: ColorSlot::FrontLeft,
                format: ColorFormat::Unorm8 { alpha: true },
                pixels: ColorBand::Unorm8(&mut colors),
            }],
            depth: DepthBand::Depth16(&mut depth),
            depth_format: DepthStencilFormat::Depth16,
        };
        let computed = Cell::new(0);
        let span = Span { y: 0, x0: 0, n: 4, row_start: 0, front_facing: true };
        shade_span(
            state,
            &mut band,
            &mut Scratch::default(),
            span,
            span_mask(4),
            |_| 0.5,
            |out| {
                computed.set(computed.get() + 1);
                out.extend([[1.0, 0.0, 0.0, 1.0]; 4]);
                None
            },
            |_, _, _| {},
        );
        drop(band);
        (computed.get(), colors)
    }

    #[test]
    fn depth_runs_before_shading_unless_the_alpha_test_comes_first() {
        // Early: a span that loses the depth test everywhere is never shaded.
        assert_eq!(run_span(&state(false), [0; 4]).0, 0);
        let (computed, colors) = run_span(&state(false), [0, 0xffff, 0, 0xffff]);
        assert_eq!(computed, 1);
        assert_eq!(colors, [[0; 4], [255, 0, 0, 255], [0; 4], [255, 0, 0, 255]]);
        // Late: the alpha test needs the colors before the depth test can run.
        assert_eq!(run_span(&state(true), [0; 4]).0, 1);
    }

    #[test]
    fn equal_states_share_one_entry_of_the_scene() {
        let mut scene = Scene::new(4, 1);
        assert_eq!(scene.add_state(state(false)), (0, false));
        assert_eq!(scene.add_state(state(true)), (1, false));
        assert_eq!(scene.add_state(state(false)), (0, true));
        assert_eq!(scene.state_count(), 2);
    }
}
