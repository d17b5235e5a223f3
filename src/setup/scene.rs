//! The scene: a flush interval's draw states and set-up primitives, binned into the 64×64
//! tiles each may touch, waiting for a flush point.
//!
//! A draw call adds its state snapshot ([`Scene::add_state`]) and its primitives
//! ([`Scene::add`], [`Scene::add_narrow`]); each primitive is binned into the tiles its
//! bounding box (for lines, its rows' columns; for triangles, the tiles of the box its
//! edges reach) touches, clipped to the draw's scissor box. [`Scene::execute`] hands the bins to the tile workers (`raster`), which call back
//! here to render each bin entry.
//!
//! Only the scene's work is done: a filled triangle that covers a whole tile and writes
//! every pixel of it unconditionally (see [`Scene::overwrites`]) drops that tile's earlier
//! entries, as llvmpipe does. At execution each draw state is compiled once into the lane
//! kernels of `fragment::block` for the framebuffer's formats, and single-sampled filled
//! triangles render through them in 4×4 blocks.

use super::jobs::clear::ClearJob;
use super::jobs::line::LineJob;
use super::jobs::pixels::PixelRectJob;
use super::jobs::point::PointJob;
use super::jobs::smooth::SmoothJob;
use super::jobs::triangle::{RunRules, TriangleJob};
use super::triangle::TriangleSetup;
use crate::fragment::block::{Batch, BlockPipeline};
use crate::fragment::pipeline::{DrawState, Scratch};
use crate::fragment::DepthTest;
use crate::framebuffer::band::Band;
use crate::framebuffer::{ColorFormat, ColorSlot, Framebuffer, Rect};
use crate::gl::CompareFunc;
use crate::raster::{render_tiles, thread_count, TILE_SIZE};
use std::mem::ManuallyDrop;
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
    /// A clear (glClear): no draw state ([`CLEAR_STATE`] stands in for its index).
    Clear(ClearJob),
}

/// The draw-state index recorded beside a clear, which has none.
const CLEAR_STATE: u32 = u32::MAX;

/// Recorded rendering waiting for a flush point.
pub struct Scene {
    width: usize,
    height: usize,
    tiles_x: usize,
    /// The color buffers the scene writes, in the order of every draw's color masks.
    targets: Vec<ColorSlot>,
    states: Vec<Arc<DrawState>>,
    /// The primitives and the index of each one's draw state.
    primitives: Store,
    /// Per draw state, [`Scene::overwrites`].
    overwriting: Vec<bool>,
    /// Per tile (row-major), indices into `primitives` in submission order.
    bins: Vec<Vec<u32>>,
    /// How many indices the bins hold in all.
    binned: usize,
    /// A deferred part ([`Scene::deferred_part`]): in order, what binning each primitive
    /// [`Scene::add`] is given needs (its index in the part's store, its state, its
    /// clipped bounds and, for a triangle, the edges binning tests), computed on the
    /// recording thread, for the primitives that [`Scene::append`] bins (those that may
    /// drop tiles' entries, and all after them; the part bins the others into its own
    /// `bins`, with indices into its own store).
    deferred: Option<Vec<Deferred>>,
    /// Emptied bins of the last deferred part, lent to the next one.
    spare_bins: Vec<Vec<u32>>,
    /// The index of `states[0]`: 0, but in a deferred part, which holds only the scene's
    /// last [`STATE_CACHE`] states (the ones a draw's state may be).
    state_base: usize,
}

/// What [`Scene::append`] needs to bin a primitive of a deferred part: its index in the
/// part's store, its draw state, its clipped bounds and its pixel edges when binning reads
/// them (see [`Scene::add`]).
type Deferred = (u32, u32, Rect, Option<PixelEdges>);

/// How many primitives one chunk of a [`Store`] holds (a power of two). Small enough that
/// the unused end of a chunk a deferred part leaves behind costs little: a long draw comes
/// in parts of a few thousand vertices, each split in two (with 4096, small_triangles took
/// a fresh chunk per part and freed the excess each scene: 3700 more page faults a frame).
const CHUNK: usize = 1 << 9;

/// A scene's primitives and the draw state of each, in chunks of [`CHUNK`]: primitive `i` is
/// entry `i % CHUNK` of chunk `i / CHUNK`. Chunks make a deferred part's primitives part of
/// the scene without moving them ([`Store::append`] appends the part's chunks, leaving the
/// rest of the scene's last chunk unused: indices need not be dense), where one vector
/// copied every job of the part (on small_triangles, 34 MB a frame on the recording thread)
/// into freshly allocated memory; and the chunks of a rendered scene are kept, emptied, for
/// the next one (see [`Scene::clear`]), so recording writes into memory already mapped.
#[derive(Default)]
struct Store {
    chunks: Vec<Chunk>,
    /// Emptied chunks, their storage kept for reuse.
    spare: Vec<Chunk>,
    /// How many primitives the chunks hold.
    len: usize,
}

/// Up to [`CHUNK`] primitives and their draw states (a clear's is [`CLEAR_STATE`]), apart:
/// pushing a primitive with its state as one pair copied the job once more (callgrind).
///
/// The primitives are dropped by hand ([`Chunk::clear`]), and only when one of them owns
/// memory (`owning`): most triangles own none, and dropping them one by one read every
/// job of the scene again, from memory long out of the caches (small_triangles: 5 % of
/// its time in `perf`, against 0.6 % of its instructions).
struct Chunk {
    primitives: Vec<ManuallyDrop<Primitive>>,
    states: Vec<u32>,
    /// Whether a primitive of the chunk may own memory ([`Primitive::owns_memory`]).
    owning: bool,
}

impl Chunk {
    fn new() -> Chunk {
        Chunk { primitives: Vec::with_capacity(CHUNK), states: Vec::with_capacity(CHUNK), owning: false }
    }

    #[inline(always)]
    fn push(&mut self, primitive: Primitive, state: u32) {
        self.owning |= primitive.owns_memory();
        self.primitives.push(ManuallyDrop::new(primitive));
        self.states.push(state);
    }

    /// Empties the chunk, dropping its primitives when one may own memory.
    fn clear(&mut self) {
        if self.owning {
            self.primitives.drain(..).for_each(|p| drop(ManuallyDrop::into_inner(p)));
        } else {
            self.primitives.clear();
        }
        self.states.clear();
        self.owning = false;
    }
}

impl Drop for Chunk {
    fn drop(&mut self) {
        self.clear();
    }
}

impl Primitive {
    /// Whether dropping the primitive frees memory: a triangle's only with the exact mode's
    /// inputs or its varyings' planes on the heap ([`TriangleJob::owns_memory`]); any other
    /// kind is taken to.
    #[inline(always)]
    fn owns_memory(&self) -> bool {
        match self {
            Primitive::Triangle(job) => job.owns_memory(),
            _ => true,
        }
    }
}

impl Store {
    /// The index the next [`Store::push`] gives.
    #[inline(always)]
    fn next_index(&self) -> u32 {
        match self.chunks.last() {
            Some(c) if c.primitives.len() < CHUNK => ((self.chunks.len() - 1) * CHUNK + c.primitives.len()) as u32,
            _ => (self.chunks.len() * CHUNK) as u32,
        }
    }

    /// Adds `primitive`, drawn with `state`; its index.
    #[inline(always)]
    fn push(&mut self, primitive: Primitive, state: u32) -> u32 {
        self.len += 1;
        let k = self.chunks.len();
        if let Some(chunk) = self.chunks.last_mut().filter(|c| c.primitives.len() < CHUNK) {
            let index = (k - 1) * CHUNK + chunk.primitives.len();
            chunk.push(primitive, state);
            return index as u32;
        }
        let mut chunk = self.spare.pop().unwrap_or_else(Chunk::new);
        chunk.push(primitive, state);
        self.chunks.push(chunk);
        (k * CHUNK) as u32
    }

    /// Primitive `index` and its draw state.
    #[inline(always)]
    fn get(&self, index: u32) -> (&Primitive, u32) {
        let (chunk, i) = (&self.chunks[index as usize / CHUNK], index as usize % CHUNK);
        (&*chunk.primitives[i], chunk.states[i])
    }

    /// Appends the chunks of `other`, and takes its spare ones: the index in this store of
    /// `other`'s primitive `i` is `i` plus the returned offset.
    fn append(&mut self, other: Store) -> u32 {
        let offset = (self.chunks.len() * CHUNK) as u32;
        self.chunks.extend(other.chunks);
        self.spare.extend(other.spare);
        self.len += other.len;
        offset
    }

    /// Up to `n` spare chunks, for a deferred part to record into.
    fn lend(&mut self, n: usize) -> Store {
        let spare = self.spare.split_off(self.spare.len().saturating_sub(n));
        Store { chunks: Vec::new(), spare, len: 0 }
    }

    /// Empties the store, keeping the storage of at most `kept` chunks.
    fn clear(&mut self, kept: usize) {
        for mut chunk in self.chunks.drain(..) {
            chunk.clear();
            self.spare.push(chunk);
        }
        self.spare.truncate(kept);
        self.len = 0;
    }
}

/// Whether what an entry wrote in `tile` inside its rectangle `clip` lies within `region`
/// (the part of the tile a later triangle overwrites).
#[inline]
fn writes_within(tile: Rect, clip: Rect, region: Rect) -> bool {
    let written = tile.intersect(clip);
    region == tile || written.intersect(region) == written
}

/// The most pixels of a triangle's clipped box whose centres [`Scene::add_triangle`] tests one
/// by one (a box of a triangle about a pixel in size has 1 to 4).
const SMALL_BOX: usize = 4;

/// A triangle's edge functions over pixel centres (`TriangleSetup::pixel_edges`): pixel
/// (x, y) is covered exactly when every `c + a·x + b·y ≥ 0`.
type PixelEdges = [[i64; 3]; 3];

/// Whether binning a filled triangle rasterized at pixel centres whose clipped box `r`
/// spans the tiles `span` reads its pixel edges: to test the tiles of a box reaching
/// over more than one, or for the tile drop of an `overwriting` state under the clip
/// rectangle `fill_clip` (in a `framebuffer` of that rectangle), which within one tile
/// needs a box holding all of the tile's part the triangle may write (see
/// `Scene::drop_covered_tile`): never a small triangle's.
#[inline(always)]
fn edges_needed(span: [i32; 4], r: Rect, overwriting: bool, fill_clip: Rect, framebuffer: Rect) -> bool {
    let [tx0, ty0, tx1, ty1] = span;
    if tx0 != tx1 || ty0 != ty1 {
        return true;
    }
    let t = TILE_SIZE as i32;
    overwriting && {
        let region = Rect::from_xywh(tx0 * t, ty0 * t, t, t).intersect(framebuffer).intersect(fill_clip);
        region.intersect(r) == region
    }
}

/// The first and last tile columns and rows of the non-empty rectangle `r` inside the
/// framebuffer: `[x0, y0, x1, y1]`, inclusive (shifts: the coordinates are not negative).
#[inline(always)]
fn tile_span(r: Rect) -> [i32; 4] {
    const SHIFT: u32 = TILE_SIZE.trailing_zeros();
    const _: () = assert!(TILE_SIZE == 1 << SHIFT);
    debug_assert!(r.x0 >= 0 && r.y0 >= 0 && !r.is_empty());
    [r.x0 >> SHIFT, r.y0 >> SHIFT, (r.x1 - 1) >> SHIFT, (r.y1 - 1) >> SHIFT]
}

/// Whether pixel (x, y)'s centre is covered (`TriangleSetup::covers`, on the pixel edges).
#[inline]
fn covers(edges: &PixelEdges, x: i32, y: i32) -> bool {
    edges.iter().all(|&[c, a, b]| c + a * x as i64 + b * y as i64 >= 0)
}

/// Whether the triangle of `edges` may cover a pixel of the non-empty rectangle `part`:
/// no edge is negative at all of its pixels (each edge's largest value over them is at a
/// corner). Within the guard band no value overflows (see `TriangleSetup::pixel_edges`).
#[inline]
fn reaches(edges: &PixelEdges, part: Rect) -> bool {
    let (x0, x1, y0, y1) = (part.x0 as i64, part.x1 as i64 - 1, part.y0 as i64, part.y1 as i64 - 1);
    edges.iter().all(|&[c, a, b]| c + (a * x0).max(a * x1) + (b * y0).max(b * y1) >= 0)
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
            primitives: Store::default(),
            overwriting: Vec::new(),
            bins: vec![Vec::new(); tiles_x * tiles_y],
            binned: 0,
            deferred: None,
            spare_bins: Vec::new(),
            state_base: 0,
        }
    }

    /// An empty part of this scene that another thread may record filled triangles into
    /// (through [`Scene::add`]) while this scene records the draw's earlier primitives:
    /// [`Scene::append`] makes what it is given part of this scene afterwards, in order,
    /// exactly as if it had been added here (the bins, the tiles an opaque triangle drops
    /// and so the bytes are the same): the part bins what it can on its own thread (see
    /// `deferred`) and keeps the rest for `append` to bin. Only [`Scene::add`] may be used on it. It
    /// records into this scene's spare storage, enough for `capacity` primitives if it has
    /// that much.
    pub fn deferred_part(&mut self, capacity: usize) -> Scene {
        debug_assert!(self.deferred.is_none());
        let recent = self.states.len().saturating_sub(STATE_CACHE);
        Scene {
            width: self.width,
            height: self.height,
            tiles_x: self.tiles_x,
            targets: Vec::new(),
            states: self.states[recent..].to_vec(),
            primitives: self.primitives.lend(capacity.div_ceil(CHUNK)),
            overwriting: self.overwriting[recent..].to_vec(),
            binned: 0,
            bins: self.lend_bins(),
            deferred: Some(Vec::new()),
            spare_bins: Vec::new(),
            state_base: recent,
        }
    }

    /// Bins the primitives recorded into `part` (from [`Scene::deferred_part`]) after
    /// everything recorded here so far.
    pub fn append(&mut self, part: Scene) {
        let Some(deferred) = part.deferred else { return };
        debug_assert!(self.deferred.is_none() && deferred.len() <= part.primitives.len);
        // The part's chunks become the scene's (no job moves), then each primitive is binned
        // in order, as [`Scene::add`] bins it.
        let offset = self.primitives.append(part.primitives);
        let mut bins = part.bins;
        if part.binned > 0 {
            // What the part binned itself comes first, in order.
            for (bin, entries) in self.bins.iter_mut().zip(&mut bins) {
                bin.extend(entries.iter().map(|&i| i + offset));
                entries.clear();
            }
            self.binned += part.binned;
        }
        self.spare_bins = bins;
        for (index, state, r, edges) in deferred {
            let opaque = edges.as_ref().filter(|_| self.overwriting[state as usize] && self.writes_every_target(state));
            self.bin(index + offset, state, r, tile_span(r), edges.as_ref(), opaque);
        }
    }

    /// Empty bins for a deferred part: the ones the last part gave back, kept for reuse.
    fn lend_bins(&mut self) -> Vec<Vec<u32>> {
        let mut bins = std::mem::take(&mut self.spare_bins);
        bins.resize_with(self.bins.len(), Vec::new);
        bins
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
        self.primitives.len * (std::mem::size_of::<Primitive>() + std::mem::size_of::<u32>())
            + self.binned * std::mem::size_of::<u32>()
    }

    pub fn is_empty(&self) -> bool {
        self.primitives.len == 0
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
        self.overwriting.push(Self::overwrites(&state));
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
        // The primitive is read where it lies and moved once, into the store (taking a
        // triangle's job out of it to bin and wrapping it again cost two more copies).
        let (r, edges) = match &primitive {
            Primitive::Triangle(job) => self.triangle_binning(state, bounds, job),
            _ => (bounds.intersect(self.draw_state(state).0.clip), None),
        };
        if r.is_empty() {
            return;
        }
        self.record(state, r, edges, primitive);
    }

    /// Bins a filled triangle set up as `setup` under draw state `state`, its job made by
    /// `job` from the setup, unless it covers no pixel inside its clip rectangle where it
    /// is rasterized at pixel centres: its box there is empty, or is at most [`SMALL_BOX`]
    /// pixels none of whose centres it covers (a triangle smaller than a pixel mostly covers
    /// none). Such a triangle costs its edges only, not its planes nor a bin entry; one that
    /// passes may still cover nothing (the walk then finds no block). A triangle rasterized
    /// per sample (multisampling) may cover samples of pixels whose centre it misses: it is
    /// binned as [`Scene::add`] bins it.
    #[inline(always)]
    pub fn add_triangle(&mut self, state: u32, setup: TriangleSetup, job: impl FnOnce(TriangleSetup) -> TriangleJob) {
        let (drawn, overwriting) = self.draw_state(state);
        if drawn.multisample.is_some_and(|m| m.per_sample()) {
            let job = job(setup);
            return self.add(state, job.bounds(), Primitive::Triangle(job));
        }
        let fill_clip = drawn.fill_clip;
        let (x1, y1) = (setup.max_x.saturating_add(1), setup.max_y.saturating_add(1));
        let r = Rect { x0: setup.min_x, y0: setup.min_y, x1, y1 }.intersect(fill_clip);
        if r.is_empty() {
            return;
        }
        if r.width() * r.height() <= SMALL_BOX && !(r.y0..r.y1).any(|y| (r.x0..r.x1).any(|x| setup.covers(x, y))) {
            return;
        }
        let framebuffer = Rect::from_xywh(0, 0, self.width as i32, self.height as i32);
        let edges = edges_needed(tile_span(r), r, overwriting, fill_clip, framebuffer).then(|| setup.pixel_edges());
        self.record(state, r, edges, Primitive::Triangle(job(setup)));
    }

    /// Where a filled triangle `job` with bounds `bounds` is binned: its bounds within its
    /// clip rectangle, and its pixel edges when binning reads them ([`edges_needed`]).
    #[inline(always)]
    fn triangle_binning(&self, state: u32, bounds: Rect, job: &TriangleJob) -> (Rect, Option<PixelEdges>) {
        let (drawn, overwriting) = self.draw_state(state);
        // Rasterized per sample, a triangle may cover samples of pixels whose centre it misses.
        let per_sample = drawn.multisample.is_some_and(|m| m.per_sample());
        let bounds = if per_sample { job.sample_bounds() } else { bounds };
        let fill_clip = drawn.fill_clip;
        let r = bounds.intersect(fill_clip);
        if r.is_empty() {
            return (r, None);
        }
        let framebuffer = Rect::from_xywh(0, 0, self.width as i32, self.height as i32);
        let edges = (!per_sample && edges_needed(tile_span(r), r, overwriting, fill_clip, framebuffer))
            .then(|| job.setup.pixel_edges());
        (r, edges)
    }

    /// Stores `primitive` (drawn with `state`, its bounds within its clip rectangle `r`, not
    /// empty) and bins it, or in a deferred part keeps what [`Scene::append`] bins it with.
    #[inline(always)]
    fn record(&mut self, state: u32, r: Rect, edges: Option<PixelEdges>, primitive: Primitive) {
        let index = self.primitives.push(primitive, state);
        if self.deferred.is_some() {
            // A primitive that cannot drop a tile's entries (of a state that never
            // overwrites, or not a triangle with pixel edges, or whose box holds no tile's
            // whole part: a small triangle) has the same bin entries (after the part's
            // earlier ones, all binned here) when they are made here, on the part's thread.
            // From the first that may drop entries on, binning waits for [`Scene::append`].
            let may_drop = edges.is_some() && self.draw_state(state).1 && self.holds_a_tile(state, r);
            let deferred = self.deferred.as_mut().expect("a deferred part");
            if deferred.is_empty() && !may_drop {
                return self.bin(index, state, r, tile_span(r), edges.as_ref(), None);
            }
            return deferred.push((index, state, r, edges));
        }
        let opaque = edges.as_ref().filter(|_| self.overwriting[state as usize] && self.writes_every_target(state));
        self.bin(index, state, r, tile_span(r), edges.as_ref(), opaque);
    }

    /// Whether the box `r` (not empty) of a primitive of draw state `state` holds the whole
    /// part of one of its tiles that the state may write (inside its fill clip rectangle):
    /// without, the primitive cannot drop a tile's entries (see
    /// [`Scene::drop_covered_tile`]).
    fn holds_a_tile(&self, state: u32, r: Rect) -> bool {
        let t = TILE_SIZE as i32;
        let framebuffer = Rect::from_xywh(0, 0, self.width as i32, self.height as i32);
        let clip = self.draw_state(state).0.fill_clip.intersect(framebuffer);
        let [tx0, ty0, tx1, ty1] = tile_span(r);
        (ty0..=ty1).any(|ty| {
            (tx0..=tx1).any(|tx| {
                let region = Rect::from_xywh(tx * t, ty * t, t, t).intersect(clip);
                !region.is_empty() && region.intersect(r) == region
            })
        })
    }

    /// Draw state `state` and whether it overwrites (a deferred part holds only the
    /// scene's last few states, from `state_base` on).
    #[inline]
    fn draw_state(&self, state: u32) -> (&DrawState, bool) {
        let i = state as usize - self.state_base;
        (&self.states[i], self.overwriting[i])
    }

    /// Bins primitive `index` into the tiles of `r` (its bounds within its clip rectangle,
    /// not empty), which spans the tiles `span` ([`tile_span`]); `edges` are the pixel
    /// edges of a filled triangle when it is tested against tiles or may drop them (see
    /// [`edges_needed`]); `opaque` the same edges when the triangle may drop what the tiles
    /// hold ([`Scene::drop_covered_tile`]).
    ///
    /// A triangle is binned only into the tiles its edges reach: a tile of its box where
    /// one edge is negative at every pixel the box holds there has none of its pixels (a
    /// long thin triangle's box has many such tiles), so the tile workers never visit it
    /// for this triangle. Which tiles those are does not depend on the thread count.
    #[inline(always)]
    fn bin(
        &mut self,
        index: u32,
        state: u32,
        r: Rect,
        span: [i32; 4],
        edges: Option<&PixelEdges>,
        opaque: Option<&PixelEdges>,
    ) {
        let t = TILE_SIZE as i32;
        let [tx0, ty0, tx1, ty1] = span;
        if tx0 == tx1 && ty0 == ty1 {
            // One tile (small triangles): no tile test.
            return self.bin_tile(index, state, r, tx0, ty0, opaque);
        }
        for ty in ty0..=ty1 {
            for tx in tx0..=tx1 {
                if let Some(edges) = edges {
                    if !reaches(edges, Rect::from_xywh(tx * t, ty * t, t, t).intersect(r)) {
                        continue;
                    }
                }
                self.bin_tile(index, state, r, tx, ty, opaque);
            }
        }
    }

    /// Bins primitive `index` into tile `(tx, ty)`, after the tile drop of an opaque
    /// triangle (`opaque`: its edges) whose binned box is `r`.
    #[inline(always)]
    fn bin_tile(&mut self, index: u32, state: u32, r: Rect, tx: i32, ty: i32, opaque: Option<&PixelEdges>) {
        let t = TILE_SIZE as i32;
        let bin = ty as usize * self.tiles_x + tx as usize;
        if let Some(edges) = opaque {
            self.drop_covered_tile(bin, tx * t, ty * t, r, edges, state);
        }
        self.bins[bin].push(index);
        self.binned += 1;
    }

    /// Empties tile `bin` (origin `(x, y)`), but for the clears it does not overwrite, when
    /// the opaque triangle of pixel edges `edges`, whose binned box is `r`, writes all of the tile's part
    /// inside its clip rectangle (scissor box and viewport) and nothing binned there before
    /// must survive it.
    #[inline]
    fn drop_covered_tile(&mut self, bin: usize, x: i32, y: i32, r: Rect, edges: &PixelEdges, state: u32) {
        let t = TILE_SIZE as i32;
        let tile = Rect::from_xywh(x, y, t, t).intersect(Rect::from_xywh(0, 0, self.width as i32, self.height as i32));
        // The part of the tile the triangle may write; covering its corners, the (convex)
        // triangle writes all of it. A region reaching outside the triangle's box (a small
        // triangle's always does) cannot be covered: no corner tests.
        let region = tile.intersect(self.states[state as usize].fill_clip);
        if region.is_empty() || region.intersect(r) != region {
            return;
        }
        let corners = [
            (region.x0, region.y0),
            (region.x1 - 1, region.y0),
            (region.x0, region.y1 - 1),
            (region.x1 - 1, region.y1 - 1),
        ];
        if corners.iter().all(|&(x, y)| covers(edges, x, y))
            && self.droppable(bin, &self.states[state as usize], tile, region)
        {
            // Clears stay where the triangle does not overwrite them: a depth/stencil clear
            // (the triangle writes neither), and a colour clear reaching outside the region
            // (its pixels there must stay cleared; inside, the triangle paints over it).
            let (primitives, entries) = (&self.primitives, &mut self.bins[bin]);
            let before = entries.len();
            entries.retain(|&i| match primitives.get(i).0 {
                Primitive::Clear(c) => c.depth_stencil_only() || !writes_within(tile, c.rect, region),
                _ => false,
            });
            self.binned -= before - entries.len();
        }
    }

    /// Whether state `state`'s color masks cover every target of the scene so far (the part
    /// of [`Scene::overwrites`] that changes as later draws add targets).
    #[inline]
    fn writes_every_target(&self, state: u32) -> bool {
        self.states[state as usize].fragment.color_masks.len() == self.targets.len()
    }

    /// Whether a filled triangle drawn with `state` writes every pixel it covers
    /// unconditionally, replacing whatever the scene drew there before: single-sampled, no
    /// alpha or stencil test, no depth test or one that always passes, no blending, logic
    /// op or stipple, every colour channel of its color masks written. (Whether those masks
    /// cover every target of the scene is checked per primitive: a later draw may add one.)
    /// Computed once per state, when it is added ([`Scene::add_state`]).
    fn overwrites(state: &DrawState) -> bool {
        let f = &state.fragment;
        state.multisample.is_none()
            && state.polygon_stipple.is_none()
            && f.alpha.is_none()
            // A GLSL shader that may discard leaves some pixels as they were.
            && !f.late_tests()
            && f.stencil.is_none()
            && f.logic_op.is_none()
            && f.depth.is_none_or(|d| d.func == crate::gl::CompareFunc::Always)
            && f.blend.iter().all(|b| b.is_none())
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
        // Whether what an entry wrote inside `clip` lies within the region overwritten.
        let within = |clip: Rect| writes_within(tile, clip, region);
        self.bins[bin].iter().all(|&i| {
            let (primitive, state) = self.primitives.get(i);
            if let Primitive::Clear(c) = primitive {
                // A depth/stencil clear is kept, and so is a colour clear where the triangle
                // does not overwrite it (see `drop_covered_tile`).
                return c.depth_stencil_only() || (c.depth.is_none() && c.stencil.is_none());
            }
            let s = &self.states[state as usize];
            let clip = if matches!(primitive, Primitive::Triangle(_)) { s.fill_clip } else { s.clip };
            !matches!(primitive, Primitive::Pixels(_))
                && within(clip)
                && s.samples_passed.is_none()
                && s.fragment.stencil.is_none()
                && (writes_depth || s.fragment.depth.is_none_or(|d| !d.write))
        })
    }

    /// Bins a clear into every tile its rectangle touches; its color buffers become targets
    /// of the scene.
    pub fn add_clear(&mut self, job: ClearJob) {
        let r = job.rect.intersect(Rect::from_xywh(0, 0, self.width as i32, self.height as i32));
        if r.is_empty() || (job.colors.is_empty() && job.depth.is_none() && job.stencil.is_none()) {
            return;
        }
        for c in &job.colors {
            self.target_index(c.slot);
        }
        let index = self.primitives.push(Primitive::Clear(job), CLEAR_STATE);
        let t = TILE_SIZE as i32;
        for ty in (r.y0 / t)..=((r.y1 - 1) / t) {
            for tx in (r.x0 / t)..=((r.x1 - 1) / t) {
                self.bins[ty as usize * self.tiles_x + tx as usize].push(index);
                self.binned += 1;
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
        debug_assert!(self.deferred.is_none(), "a deferred part records filled triangles only");
        let clip = self.states[state as usize].clip;
        let r = bounds.intersect(clip);
        if r.is_empty() {
            return;
        }
        let index = self.primitives.next_index();
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
            self.primitives.push(primitive, state);
        }
    }

    /// Renders the scene into `framebuffer` (which must have the scene's size) on
    /// `thread_count()` threads.
    pub fn execute(&self, framebuffer: &mut Framebuffer) {
        self.execute_on(framebuffer, thread_count());
    }

    /// Renders the scene on up to `threads` threads (the caller's included): the tile
    /// workers render each tile's bin in submission order, each entry by its job.
    pub fn execute_on(&self, framebuffer: &mut Framebuffer, threads: usize) {
        if self.is_empty() {
            return;
        }
        // Each draw state compiled once into lane kernels for this framebuffer's formats (the
        // band's colour targets are the scene's targets the framebuffer has, in order).
        let single_sampled = framebuffer.samples() == 1;
        // (A multisampled framebuffer's bands are its sample layers: their formats.)
        let formats: Vec<ColorFormat> =
            self.targets.iter().filter_map(|&slot| framebuffer.band_color_format(slot)).collect();
        let depth_format = framebuffer.band_depth_stencil_format();
        // Multisampled: the states the sample block path takes (`fragment::block::samples`).
        let pipelines: Vec<Option<BlockPipeline>> = self
            .states
            .iter()
            .map(|s| {
                // (A GLSL shader's gl_FragData[n] reach their draw buffers on the span path.)
                let blocks = match s.multisample {
                    _ if s.fragment.glsl.as_ref().is_some_and(|g| g.writes_data()) => false,
                    None => single_sampled,
                    Some(_) => !single_sampled && BlockPipeline::takes_samples(s),
                };
                blocks.then(|| BlockPipeline::compile(&s.fragment, &formats, depth_format))
            })
            .collect();
        // One batch of blocks per band, handed to each triangle empty (`TriangleJob::render_blocks`).
        let render_one = |index, tile: Rect, band: &mut Band<'_>, scratch: &mut Scratch, batch: &mut Batch| {
            let (primitive, state_index) = self.primitives.get(index);
            if let Primitive::Clear(job) = primitive {
                return job.render(tile, band);
            }
            let state_index = state_index as usize;
            let state = &self.states[state_index];
            let area = tile.intersect(state.clip);
            match primitive {
                Primitive::Triangle(job) if band.samples == 1 && pipelines[state_index].is_some() => {
                    let pipeline = pipelines[state_index].as_ref().expect("compiled above");
                    job.render_blocks(state, pipeline, tile.intersect(state.fill_clip), band, scratch, batch)
                }
                Primitive::Triangle(job) if pipelines[state_index].is_some() => {
                    let pipeline = pipelines[state_index].as_ref().expect("compiled above");
                    job.render_sample_blocks(state, pipeline, tile.intersect(state.fill_clip), band, scratch)
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
                Primitive::Clear(_) => unreachable!("rendered above"),
            }
            // Hierarchical z (`framebuffer::hiz`) learns where the job may have written depth:
            // through a test that keeps only nearer or equal depths, or anything (pixel
            // rectangles: glDrawPixels of depth).
            let only_nearer = match primitive {
                Primitive::Pixels(_) => Some(false),
                _ => Self::depth_written_only_nearer(state),
            };
            if let Some(only_nearer) = only_nearer {
                let written = match primitive {
                    Primitive::Triangle(job) => tile.intersect(state.fill_clip).intersect(job.bounds()),
                    _ => area,
                };
                band.hiz_written(written, only_nearer);
            }
        };
        // A tile's bin in order, its runs of consecutive triangles that render through the
        // same block pipeline in one batch (`TriangleJob::render_run`: small triangles,
        // whose per-triangle set-up of the stages cost as much as their blocks), every
        // other entry on its own.
        let render = |bin: &[u32], tile: Rect, band: &mut Band<'_>, scratch: &mut Scratch, batch: &mut Batch| {
            let single_sampled = band.samples == 1;
            // The first triangle of a run: its state's rules, if they admit it.
            let run_head = |index: u32| {
                let (primitive, state_index) = self.primitives.get(index);
                let Primitive::Triangle(job) = primitive else { return None };
                let state = &self.states[state_index as usize];
                let pipeline = pipelines[state_index as usize].as_ref().filter(|_| single_sampled)?;
                let rules = RunRules::new(state, pipeline, tile.intersect(state.fill_clip));
                rules.admit(job).then_some((job, state_index, state, pipeline, rules))
            };
            let mut i = 0;
            while i < bin.len() {
                let Some((first, state_index, state, pipeline, rules)) = run_head(bin[i]) else {
                    render_one(bin[i], tile, band, scratch, batch);
                    i += 1;
                    continue;
                };
                // The triangles after it of the same state and facing that the same rules
                // admit (the entry that ends the run is looked at again as a run's head).
                let mut end = i + 1;
                while end < bin.len() {
                    match self.primitives.get(bin[end]) {
                        (Primitive::Triangle(job), s)
                            if s == state_index && job.front_facing == first.front_facing && rules.admit(job) =>
                        {
                            end += 1
                        }
                        _ => break,
                    }
                }
                if end == i + 1 {
                    render_one(bin[i], tile, band, scratch, batch);
                    i += 1;
                    continue;
                }
                let area = rules.area();
                let run = &bin[i..end];
                let job = |index: u32| match self.primitives.get(index).0 {
                    Primitive::Triangle(job) => job,
                    _ => unreachable!("a run holds triangles"),
                };
                TriangleJob::render_run(state, pipeline, area, band, scratch, batch, run.iter().map(|&k| job(k)));
                if let Some(only_nearer) = Self::depth_written_only_nearer(state) {
                    band.hiz_written_within(area, run.iter().map(|&k| area.intersect(job(k).bounds())), only_nearer);
                }
                i = end;
            }
        };
        render_tiles(framebuffer, &self.targets, self.tiles_x, &self.bins, threads, render);
        if framebuffer.samples() > 1 {
            framebuffer.resolve(&self.targets, self.drawn_area());
        }
    }

    /// Whether a primitive drawn with `state` may write depth only through a test that keeps
    /// nearer or equal depths (what hierarchical z learns, `framebuffer::hiz`); `None` when
    /// it writes no depth.
    fn depth_written_only_nearer(state: &DrawState) -> Option<bool> {
        match state.fragment.depth {
            Some(DepthTest { func, write: true }) => Some(matches!(
                func,
                CompareFunc::Less | CompareFunc::LessEqual | CompareFunc::Equal | CompareFunc::Never
            )),
            _ => None,
        }
    }

    /// Empties the scene for the next flush interval, keeping the storage of its primitives
    /// and bins up to about [`Scene::BUDGET_BYTES`]: the next scene then records into
    /// memory already mapped instead of a fresh allocation the kernel faults in page by page
    /// (on small_triangles at 1024² that is 14 000 page faults a frame), and what stays
    /// allocated between scenes is bounded by the budget a scene may reach anyway.
    pub fn clear(&mut self) {
        // Twice a full budget's chunks: deferred parts leave chunks partly used.
        let kept_chunks =
            2 * (Self::BUDGET_BYTES / (CHUNK * (std::mem::size_of::<Primitive>() + std::mem::size_of::<u32>())) + 1);
        self.targets.clear();
        self.states.clear();
        self.overwriting.clear();
        self.primitives.clear(kept_chunks);
        // The bins' entries count against the budget too: a tile keeps at most its share.
        let kept_entries = Self::BUDGET_BYTES / std::mem::size_of::<u32>() / self.bins.len().max(1);
        for bin in &mut self.bins {
            bin.clear();
            bin.shrink_to(kept_entries);
        }
        for bin in &mut self.spare_bins {
            bin.shrink_to(kept_entries);
        }
        self.binned = 0;
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
    use crate::fragment::multisample::MultisampleState;
    use crate::fragment::{AlphaTest, DepthTest, FragmentState};
    use crate::gl::CompareFunc;
    use crate::setup::triangle::TriangleSetup;

    fn state(alpha: bool) -> DrawState {
        let depth = Some(DepthTest { func: CompareFunc::Less, write: true });
        let mut fragment = FragmentState::plain(depth, vec![Some([true; 4])], false);
        fragment.alpha = alpha.then_some(AlphaTest { func: CompareFunc::Always, reference: 0.0, unorm8: true });
        let clip = Rect::from_xywh(0, 0, 4, 1);
        DrawState { fragment, clip, fill_clip: clip, polygon_stipple: None, samples_passed: None, multisample: None }
    }

    /// A triangle job through three window points, one color.
    fn triangle(points: [[f32; 2]; 3]) -> Primitive {
        use crate::setup::jobs::triangle::WindowVertex;
        let v = points.map(|[x, y]| WindowVertex {
            x,
            y,
            z: 0.5,
            inv_w: 1.0,
            color: [1.0, 0.5, 0.25, 1.0],
            secondary_color: [0.0; 4],
            tex_coords: [[0.0; 4]; crate::glsl::varyings::VARYING_SLOTS],
            fog_coord: 0.0,
        });
        Primitive::Triangle(TriangleJob::new(v, None, 0.0, &[]).expect("not degenerate"))
    }

    /// What a scene has binned: per tile, the setups of its entries in order.
    fn binned(scene: &Scene) -> Vec<Vec<TriangleSetup>> {
        let setup = |i: &u32| match scene.primitives.get(*i).0 {
            Primitive::Triangle(job) => job.setup.clone(),
            _ => unreachable!("triangles only"),
        };
        scene.bins.iter().map(|bin| bin.iter().map(setup).collect()).collect()
    }

    #[test]
    fn a_deferred_part_appended_bins_as_if_added_in_place() {
        // Opaque state (no depth test): a triangle covering a whole tile drops what the tile
        // held, also when the covering triangle comes from the deferred part.
        let opaque = || {
            let mut s = state(false);
            s.fragment.depth = None;
            s.clip = Rect::from_xywh(0, 0, 200, 130);
            s.fill_clip = s.clip;
            s
        };
        let triangles: Vec<[[f32; 2]; 3]> = vec![
            [[1.0, 1.0], [150.0, 2.5], [140.0, 120.0]],
            [[70.0, 3.0], [90.0, 60.0], [60.0, 50.0]],
            [[-10.0, -10.0], [300.0, -10.0], [-10.0, 300.0]],
            [[5.0, 70.0], [190.0, 66.0], [100.0, 129.0]],
            [[130.0, 10.0], [199.0, 10.0], [160.0, 40.0]],
        ];
        // Also under a depth-tested state, which never drops entries: the part bins its
        // triangles itself, and append merges its bins. A second part, appended after the
        // first, records into the bins the first gave back.
        let tested = || DrawState { fragment: state(false).fragment, ..opaque() };
        for (make, opaque_state) in [(&opaque as &dyn Fn() -> DrawState, true), (&tested, false)] {
            let add = |scene: &mut Scene, t: [[f32; 2]; 3]| {
                let p = triangle(t);
                let bounds = match &p {
                    Primitive::Triangle(job) => job.bounds(),
                    _ => unreachable!(),
                };
                scene.add(0, bounds, p);
            };
            for split in 0..=triangles.len() {
                let mut whole = Scene::new(200, 130);
                let mut parted = Scene::new(200, 130);
                for scene in [&mut whole, &mut parted] {
                    scene.target_index(ColorSlot::FrontLeft);
                    assert_eq!(scene.add_state(make()), (0, false));
                }
                for _ in 0..2 {
                    triangles.iter().for_each(|&t| add(&mut whole, t));
                }
                let mut later = parted.deferred_part(4);
                for (i, &t) in triangles.iter().enumerate() {
                    add(if i < split { &mut parted } else { &mut later }, t);
                }
                // The part bins what it is given itself up to the first triangle that may
                // drop a tile's entries: under the opaque state the third, the only one
                // whose box holds a whole tile's part.
                let binned_apart = later.binned;
                let bins_none = split == triangles.len() || (opaque_state && split == 2);
                assert_eq!(binned_apart == 0, bins_none, "split {split}");
                parted.append(later);
                let mut again = parted.deferred_part(4);
                triangles.iter().for_each(|&t| add(&mut again, t));
                parted.append(again);
                assert_eq!(binned(&parted), binned(&whole), "split after {split} triangles");
                assert_eq!((parted.binned, parted.primitives.len), (whole.binned, whole.primitives.len));
            }
        }
        // The big triangle (x + y < 290) drops what the first two left in every tile it
        // covers whole; tile (2, 1), pixels x 128..192, y 64..128, it does not (its far
        // corner's centre sums to 319) and keeps the first triangle before it. Tile (3, 2),
        // pixels x 192..200, y 128..130, is in its box but beyond its edge: not binned.
        let whole = {
            let mut s = Scene::new(200, 130);
            s.target_index(ColorSlot::FrontLeft);
            s.add_state(opaque());
            for &t in &triangles[..3] {
                let p = triangle(t);
                let bounds = match &p {
                    Primitive::Triangle(job) => job.bounds(),
                    _ => unreachable!(),
                };
                s.add(0, bounds, p);
            }
            s
        };
        let mut expected = vec![vec![2]; 12];
        expected[6] = vec![0, 2];
        expected[11] = vec![];
        assert_eq!(whole.bins, expected);
    }

    #[test]
    fn triangles_covering_no_pixel_centre_are_dropped_before_their_job_is_made() {
        // `add_triangle` makes (and records) a triangle's job only if it may cover a pixel
        // centre inside its clip rectangle; rasterized per sample, even a triangle between
        // centres may cover samples, and is recorded.
        let add = |scene: &mut Scene, state: u32, points: [[f32; 2]; 3]| {
            let mut made = false;
            let setup = TriangleSetup::new(points).expect("not degenerate");
            scene.add_triangle(state, setup, |_| {
                made = true;
                match triangle(points) {
                    Primitive::Triangle(job) => job,
                    _ => unreachable!(),
                }
            });
            made
        };
        let mut scene = Scene::new(16, 16);
        scene.target_index(ColorSlot::FrontLeft);
        let (plain, _) = scene.add_state(opaque(Rect::from_xywh(0, 0, 8, 8)));
        let between = [[0.6, 0.6], [1.4, 0.6], [0.6, 1.4]]; // its box has no pixel
        let beside = [[0.2, 0.45], [0.55, 0.8], [0.2, 0.8]]; // one pixel's box, centre outside
        let outside = [[10.2, 10.2], [11.9, 10.2], [10.2, 11.9]]; // beyond the clip rectangle
        for points in [between, beside, outside] {
            assert!(!add(&mut scene, plain, points), "{points:?}");
        }
        assert!(scene.is_empty() && scene.binned == 0);
        assert!(add(&mut scene, plain, [[0.2, 0.2], [0.9, 0.2], [0.2, 0.9]]));
        assert_eq!((scene.primitives.len, scene.binned), (1, 1));
        let multisample = MultisampleState {
            samples: 4,
            enabled: true,
            alpha_to_coverage: false,
            alpha_to_one: false,
            coverage_mask: 0xf,
        };
        let (per_sample, _) =
            scene.add_state(DrawState { multisample: Some(multisample), ..opaque(Rect::from_xywh(0, 0, 8, 8)) });
        assert!(add(&mut scene, per_sample, beside));
        assert_eq!(scene.primitives.len, 2);
    }

    /// A state with no test, blend or mask (it overwrites), clipped to `clip`.
    fn opaque(clip: Rect) -> DrawState {
        let fragment = FragmentState::plain(None, vec![Some([true; 4])], false);
        DrawState { fragment, clip, fill_clip: clip, polygon_stipple: None, samples_passed: None, multisample: None }
    }

    /// A triangle covering the whole window of side `size` (bounds: the window).
    fn cover(size: f32) -> TriangleJob {
        use crate::setup::jobs::triangle::WindowVertex;
        let v = |x: f32, y: f32| WindowVertex {
            x,
            y,
            z: 0.5,
            inv_w: 1.0,
            color: [1.0; 4],
            secondary_color: [0.0; 4],
            tex_coords: [[0.0; 4]; crate::glsl::varyings::VARYING_SLOTS],
            fog_coord: 0.0,
        };
        TriangleJob::new([v(-1.0, -1.0), v(3.0 * size, -1.0), v(-1.0, 3.0 * size)], None, 0.0, &[]).unwrap()
    }

    #[test]
    fn a_scissored_opaque_triangle_drops_a_colour_clear_only_inside_its_box() {
        use crate::setup::jobs::clear::{ClearJob, ColorClear};
        let window = Rect::from_xywh(0, 0, 128, 128);
        let clear = |rect: Rect, colour: bool, depth: bool| ClearJob {
            rect,
            whole: rect == window,
            colors: if colour {
                vec![ColorClear { slot: ColorSlot::FrontLeft, color: [0.0; 4], mask: [true; 4] }]
            } else {
                vec![]
            },
            depth: depth.then_some(1.0),
            stencil: None,
        };
        let scissor = Rect::from_xywh(1, 1, 126, 126);
        let mut scene = Scene::new(128, 128);
        scene.target_index(ColorSlot::FrontLeft);
        let (inner, _) = scene.add_state(opaque(scissor));
        // A whole-window colour clear wrote outside the box: scissored triangles keep it
        // (the one-pixel frame must stay cleared) while dropping what the box held before
        // them; the depth clear always stays.
        scene.add_clear(clear(window, true, false));
        scene.add_clear(clear(window, false, true));
        scene.add(inner, window, Primitive::Triangle(cover(128.0)));
        assert_eq!(scene.bins, vec![vec![0, 1, 2]; 4]);
        // A second scissored triangle replaces the first and keeps both clears.
        scene.add(inner, window, Primitive::Triangle(cover(128.0)));
        assert_eq!(scene.bins, vec![vec![0, 1, 3]; 4]);
        // A colour clear inside the box is overwritten where the triangle writes.
        let mut scene = Scene::new(128, 128);
        scene.target_index(ColorSlot::FrontLeft);
        let (inner, _) = scene.add_state(opaque(scissor));
        scene.add_clear(clear(scissor, true, false));
        scene.add_clear(clear(window, false, true));
        scene.add(inner, window, Primitive::Triangle(cover(128.0)));
        assert_eq!(scene.bins, vec![vec![1, 2]; 4]);
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
    fn triangles_are_binned_into_exactly_the_tiles_their_edges_reach() {
        // Random triangles over a 300 × 260 scene (5 × 5 tiles), thin slivers among them:
        // every tile holding a covered pixel has the triangle binned (none is lost), and a
        // sliver crossing the window is binned into far fewer tiles than its box holds.
        let window = Rect::from_xywh(0, 0, 300, 260);
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut unit = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f32 / (1u64 << 53) as f32
        };
        for round in 0..60 {
            let mut scene = Scene::new(300, 260);
            scene.target_index(ColorSlot::FrontLeft);
            let (s, _) = scene.add_state(state_clipped(window));
            let points: [[f32; 2]; 3] = if round % 2 == 0 {
                let (y0, y1) = (unit() * 260.0, unit() * 260.0);
                [[-5.0, y0], [305.0, y1], [305.0, y1 + 0.7]]
            } else {
                [0, 1, 2].map(|_| [unit() * 340.0 - 20.0, unit() * 300.0 - 20.0])
            };
            let p = triangle(points);
            let Primitive::Triangle(job) = &p else { unreachable!() };
            let (setup, bounds) = (job.setup.clone(), job.bounds());
            scene.add(s, bounds, p);
            let r = bounds.intersect(window);
            let mut in_box = 0;
            for (bin, entries) in scene.bins.iter().enumerate() {
                let (tx, ty) = ((bin % 5) as i32 * 64, (bin / 5) as i32 * 64);
                let tile = Rect::from_xywh(tx, ty, 64, 64).intersect(r);
                in_box += !tile.is_empty() as usize;
                let covered = (tile.y0..tile.y1).any(|y| (tile.x0..tile.x1).any(|x| setup.covers(x, y)));
                assert!(!covered || entries == &[0], "round {round}: tile {bin} lost");
                assert!(entries.is_empty() || !tile.is_empty(), "round {round}: tile {bin} outside the box");
            }
            if round % 2 == 0 && in_box >= 15 {
                assert!(scene.binned * 2 < in_box, "round {round}: {} of {in_box} tiles", scene.binned);
            }
        }
    }

    /// A plain state (depth-tested, so nothing is dropped) clipped to `clip`.
    fn state_clipped(clip: Rect) -> DrawState {
        DrawState { clip, fill_clip: clip, ..state(false) }
    }

    #[test]
    fn the_store_keeps_every_primitive_and_state_across_chunks_and_appends() {
        use crate::setup::jobs::clear::ClearJob;
        let clear = |k: usize| {
            let rect = Rect::from_xywh(k as i32, 0, 1, 1);
            Primitive::Clear(ClearJob { rect, whole: false, colors: vec![], depth: Some(1.0), stencil: None })
        };
        let x_of = |store: &Store, i: u32| match store.get(i) {
            (Primitive::Clear(c), state) => (c.rect.x0 as usize, state),
            _ => unreachable!("clears only"),
        };
        let mut store = Store::default();
        let first: Vec<u32> = (0..CHUNK + 5).map(|k| store.push(clear(k), k as u32)).collect();
        assert_eq!(first, (0..CHUNK as u32 + 5).collect::<Vec<_>>(), "dense within a store");
        // A part recorded apart, in one spare chunk lent by the store once it has one.
        store.clear(4);
        assert_eq!((store.len, store.spare.len()), (0, 2));
        let first: Vec<u32> = (0..7).map(|k| store.push(clear(k), k as u32)).collect();
        let mut part = store.lend(1);
        assert_eq!(part.spare.len(), 1);
        let local: Vec<u32> = (0..CHUNK + 3).map(|k| part.push(clear(1000 + k), 7)).collect();
        let offset = store.append(part);
        assert_eq!(offset as usize, CHUNK, "the part starts at the store's next chunk");
        let later = store.push(clear(99), 8);
        assert_eq!(store.len, 7 + CHUNK + 3 + 1);
        for (k, &i) in first.iter().enumerate() {
            assert_eq!(x_of(&store, i), (k, k as u32));
        }
        for (k, &i) in local.iter().enumerate() {
            assert_eq!(x_of(&store, i + offset), (1000 + k, 7));
        }
        assert_eq!(later as usize, 2 * CHUNK + 3, "after the part's last primitive");
        assert_eq!(x_of(&store, later), (99, 8));
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
