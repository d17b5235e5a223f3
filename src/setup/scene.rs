//! The scene: a flush interval's draw states and set-up primitives, binned into the 64×64
//! tiles each may touch, waiting for a flush point.
//!
//! A draw call adds its state snapshot ([`Scene::add_state`]) and its primitives
//! ([`Scene::add`], [`Scene::add_narrow`]); each primitive is binned into the tiles its
//! bounding box (or, for lines, its rows' columns) touches, clipped to the draw's scissor
//! box. [`Scene::execute`] hands the bins to the tile workers (`raster`), which call back
//! here to render each bin entry.
//!
//! Only the scene's work is done: a filled triangle that covers a whole tile and writes
//! every pixel of it unconditionally (see [`Scene::overwrites`]) drops that tile's earlier
//! entries, as llvmpipe does. At execution each draw state is compiled once into the lane
//! kernels of `fragment::block` for the framebuffer's formats, and single-sampled filled
//! triangles render through them in 4×4 blocks.

use super::jobs::line::LineJob;
use super::jobs::pixels::PixelRectJob;
use super::jobs::point::PointJob;
use super::jobs::smooth::SmoothJob;
use super::jobs::triangle::TriangleJob;
use crate::fragment::block::BlockPipeline;
use crate::fragment::pipeline::DrawState;
use crate::framebuffer::{ColorFormat, ColorSlot, Framebuffer, Rect};
use crate::raster::{render_tiles, thread_count, TILE_SIZE};
use std::sync::Arc;

/// How many of a scene's most recent draw states a new draw's state is compared with before
/// it is added (see [`Scene::add_state`]).
pub const STATE_CACHE: usize = 4;

/// A primitive ready for rasterization.
pub enum Primitive {
    Triangle(TriangleJob),
    Line(LineJob),
    Point(PointJob),
    /// A smooth (antialiased) line, point or triangle.
    Smooth(SmoothJob),
    /// A pixel rectangle (glBitmap, glDrawPixels).
    Pixels(PixelRectJob),
}

/// Recorded rendering waiting for a flush point.
pub struct Scene {
    width: usize,
    height: usize,
    tiles_x: usize,
    /// The color buffers the scene writes, in the order of every draw's color masks.
    targets: Vec<ColorSlot>,
    states: Vec<Arc<DrawState>>,
    /// The primitives, and apart (so that adding one copies the job once, straight into
    /// place) the index of each one's draw state.
    primitives: Vec<Primitive>,
    primitive_states: Vec<u32>,
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
            primitive_states: Vec::new(),
            bins: vec![Vec::new(); tiles_x * tiles_y],
            binned: 0,
        }
    }

    /// The recorded primitives a scene may hold before the context renders it (whatever
    /// the thread count, so the same commands flush at the same points): a long draw then
    /// needs this much memory for its primitives, not memory in proportion to its length.
    /// The context checks after every part of a draw (every draw of any length is delivered
    /// in parts of at most `BATCH_VERTICES` + 2 vertices, display-list replays included),
    /// so a scene passes the budget by at most one part's primitives.
    pub const BUDGET_BYTES: usize = 64 << 20;

    /// About how much memory the recorded primitives and their bin entries take.
    pub fn recorded_bytes(&self) -> usize {
        self.primitives.len() * (std::mem::size_of::<Primitive>() + std::mem::size_of::<u32>())
            + self.binned * std::mem::size_of::<u32>()
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
    #[inline]
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
        let t = TILE_SIZE as i32;
        let (rows, columns) = ((r.y0 / t)..=((r.y1 - 1) / t), (r.x0 / t)..=((r.x1 - 1) / t));
        let opaque = match &primitive {
            Primitive::Triangle(job) if self.overwrites(drawn) => Some(job.setup.clone()),
            _ => None,
        };
        self.primitives.push(primitive);
        self.primitive_states.push(state);
        self.binned += rows.clone().count() * columns.clone().count();
        let bounds = Rect::from_xywh(0, 0, self.width as i32, self.height as i32);
        for ty in rows {
            for tx in columns.clone() {
                let bin = ty as usize * self.tiles_x + tx as usize;
                if let Some(setup) = &opaque {
                    // The part of the tile the triangle may write (inside the scissor box
                    // and viewport); covering its corners, the (convex) triangle writes all
                    // of it.
                    let tile = Rect::from_xywh(tx * t, ty * t, t, t).intersect(bounds);
                    let region = tile.intersect(clip);
                    let corners = [
                        (region.x0, region.y0),
                        (region.x1 - 1, region.y0),
                        (region.x0, region.y1 - 1),
                        (region.x1 - 1, region.y1 - 1),
                    ];
                    // A region reaching outside the triangle's box (a small triangle's always
                    // does) cannot be covered: no corner tests.
                    let inside = region.intersect(r) == region;
                    if inside
                        && corners.iter().all(|&(x, y)| setup.covers(x, y))
                        && self.droppable(bin, drawn, tile, region)
                    {
                        self.binned -= self.bins[bin].len();
                        self.bins[bin].clear();
                    }
                }
                self.bins[bin].push(index);
            }
        }
    }

    /// Whether a filled triangle drawn with `state` writes every pixel it covers
    /// unconditionally, replacing whatever the scene drew there before: single-sampled, no
    /// alpha or stencil test, no depth test or one that always passes, no blending, logic
    /// op or stipple, every colour channel of every target of the scene written.
    fn overwrites(&self, state: &DrawState) -> bool {
        let f = &state.fragment;
        state.multisample.is_none()
            && state.polygon_stipple.is_none()
            && f.alpha.is_none()
            && f.stencil.is_none()
            && f.logic_op.is_none()
            && f.depth.is_none_or(|d| d.func == crate::gl::CompareFunc::Always)
            && f.blend.iter().all(|b| b.is_none())
            && f.color_masks.len() == self.targets.len()
            && f.color_masks.iter().all(|m| *m == Some([true; 4]))
    }

    /// Whether the entries of tile `bin` (the pixels `tile`) leave nothing that a triangle
    /// overwriting the part `region` of the tile with `state` would not replace: each wrote
    /// only inside `region` (its clip rectangle's part of the tile; a scissored draw
    /// overwrites what earlier draws under the same scissor box wrote), no stencil changes,
    /// no occlusion query counting them, no pixel rectangle (which may write depth or stencil
    /// directly), and depth written only if `state` writes depth too.
    fn droppable(&self, bin: usize, state: &DrawState, tile: Rect, region: Rect) -> bool {
        let writes_depth = state.fragment.depth.is_some_and(|d| d.write);
        self.bins[bin].iter().all(|&i| {
            let primitive = &self.primitives[i as usize];
            let s = &self.states[self.primitive_states[i as usize] as usize];
            let clip = if matches!(primitive, Primitive::Triangle(_)) { s.fill_clip } else { s.clip };
            !matches!(primitive, Primitive::Pixels(_))
                && (region == tile || tile.intersect(clip).intersect(region) == tile.intersect(clip))
                && s.samples_passed.is_none()
                && s.fragment.stencil.is_none()
                && (writes_depth || s.fragment.depth.is_none_or(|d| !d.write))
        })
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
            self.primitives.push(primitive);
            self.primitive_states.push(state);
        }
    }

    /// Renders the scene into `framebuffer` (which must have the scene's size) on
    /// `thread_count()` threads.
    pub fn execute(self, framebuffer: &mut Framebuffer) {
        self.execute_on(framebuffer, thread_count());
    }

    /// Renders the scene on up to `threads` threads (the caller's included): the tile
    /// workers render each tile's bin in submission order, each entry by its job.
    pub fn execute_on(self, framebuffer: &mut Framebuffer, threads: usize) {
        if self.primitives.is_empty() {
            return;
        }
        // Each draw state compiled once into lane kernels for this framebuffer's formats (the
        // band's colour targets are the scene's targets the framebuffer has, in order).
        let single_sampled = framebuffer.samples() == 1;
        let formats: Vec<ColorFormat> =
            self.targets.iter().filter_map(|&slot| framebuffer.color(slot).map(|b| b.format())).collect();
        let depth_format = framebuffer.depth_stencil().format();
        let pipelines: Vec<Option<BlockPipeline>> = self
            .states
            .iter()
            .map(|s| {
                (single_sampled && s.multisample.is_none())
                    .then(|| BlockPipeline::compile(&s.fragment, &formats, depth_format))
            })
            .collect();
        render_tiles(framebuffer, &self.targets, self.tiles_x, &self.bins, threads, |index, tile, band, scratch| {
            let primitive = &self.primitives[index as usize];
            let state_index = self.primitive_states[index as usize] as usize;
            let state = &self.states[state_index];
            let area = tile.intersect(state.clip);
            match primitive {
                Primitive::Triangle(job) if band.samples == 1 && pipelines[state_index].is_some() => {
                    let pipeline = pipelines[state_index].as_ref().expect("compiled above");
                    job.render_blocks(state, pipeline, tile.intersect(state.fill_clip), band, scratch)
                }
                Primitive::Triangle(job) if state.multisample.is_some_and(|m| m.per_sample()) => {
                    job.render_samples(state, tile.intersect(state.fill_clip), band, scratch)
                }
                Primitive::Triangle(job) => job.render(state, tile.intersect(state.fill_clip), band, scratch),
                Primitive::Line(job) if job.per_sample() => job.render_samples(state, area, band, scratch),
                Primitive::Line(job) => job.render(state, area, band, scratch),
                Primitive::Point(job) if job.sample_square.is_some() => job.render_samples(state, area, band, scratch),
                Primitive::Point(job) => job.render(state, area, band, scratch),
                Primitive::Smooth(job) => job.render(state, area, band, scratch),
                Primitive::Pixels(job) => job.render(state, area, band, scratch),
            }
        });
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fragment::{AlphaTest, DepthTest, FragmentState};
    use crate::gl::CompareFunc;

    fn state(alpha: bool) -> DrawState {
        let depth = Some(DepthTest { func: CompareFunc::Less, write: true });
        let mut fragment = FragmentState::plain(depth, vec![Some([true; 4])], false);
        fragment.alpha = alpha.then_some(AlphaTest { func: CompareFunc::Always, reference: 0.0, unorm8: true });
        let clip = Rect::from_xywh(0, 0, 4, 1);
        DrawState { fragment, clip, fill_clip: clip, polygon_stipple: None, samples_passed: None, multisample: None }
    }

    /// A state with no test, blend or mask (it overwrites), clipped to `clip`.
    fn opaque(clip: Rect) -> DrawState {
        let fragment = FragmentState::plain(None, vec![Some([true; 4])], false);
        DrawState { fragment, clip, fill_clip: clip, polygon_stipple: None, samples_passed: None, multisample: None }
    }

    /// A triangle covering the whole window of side `size` (bounds: the window).
    fn cover(size: f32) -> TriangleJob {
        use crate::gl::limits::MAX_TEXTURE_UNITS;
        use crate::setup::jobs::triangle::WindowVertex;
        let v = |x: f32, y: f32| WindowVertex {
            x,
            y,
            z: 0.5,
            inv_w: 1.0,
            color: [1.0; 4],
            secondary_color: [0.0; 4],
            tex_coords: [[0.0; 4]; MAX_TEXTURE_UNITS],
            fog_coord: 0.0,
        };
        TriangleJob::new([v(-1.0, -1.0), v(3.0 * size, -1.0), v(-1.0, 3.0 * size)], None, 0.0, &[]).unwrap()
    }

    #[test]
    fn a_scissored_opaque_triangle_drops_what_the_same_scissor_box_drew_before() {
        // 128×128: four tiles; a scissor box one pixel inside the window touches all four
        // but covers none of them whole.
        let window = Rect::from_xywh(0, 0, 128, 128);
        let scissor = Rect::from_xywh(1, 1, 126, 126);
        let mut scene = Scene::new(128, 128);
        scene.target_index(ColorSlot::FrontLeft);
        let (inner, _) = scene.add_state(opaque(scissor));
        let (whole, _) = scene.add_state(opaque(window));
        let bins = |scene: &Scene| scene.bins.clone();
        scene.add(inner, window, Primitive::Triangle(cover(128.0)));
        scene.add(inner, window, Primitive::Triangle(cover(128.0)));
        // The second replaces the first in every tile, though it covers none of them whole.
        assert_eq!(bins(&scene), vec![vec![1]; 4]);
        scene.add(whole, window, Primitive::Triangle(cover(128.0)));
        assert_eq!(bins(&scene), vec![vec![2]; 4]);
        // The unscissored triangle wrote outside the box: it stays, in every tile.
        scene.add(inner, window, Primitive::Triangle(cover(128.0)));
        scene.add(inner, window, Primitive::Triangle(cover(128.0)));
        assert_eq!(bins(&scene), vec![vec![2, 3, 4]; 4]);
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
