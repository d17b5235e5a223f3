//! The fragment pipeline of one 4×4 block of a filled triangle, over 16 lanes in
//! structure-of-arrays form: GL's stage order as in [`super::pipeline`], with each
//! per-fragment operation a lane kernel chosen once per draw state ([`BlockPipeline`]).
//!
//! Lane `i` of a block at `(x, y)` is pixel `(x + (i & 3), y + (i >> 2))`; a 16-bit mask
//! says which lanes are live. Depth and colours travel as `[f32; 16]` lanes, stored depth
//! and stencil as `[u32; 16]`, unorm8 colour as `[u16; 16]` per channel ([`kernels`]).
//! The stages: the stencil and depth tests first, before any colour work, whenever nothing
//! before them can discard (depth clamp included); the occlusion count; the colours
//! (texturing, the colour sum and fog: [`block_colors`], the one place colours are
//! computed) only for blocks with a surviving lane; then per colour target its write kernel
//! (blend or logic op, dither, channel masks, the format's store); the common draw (one
//! unorm8 target whose kernel takes packed words, no alpha test or shader, at most linear
//! fog) has a colour loop of its own ([`word_blocks`]). With the alpha test, the
//! colours come first, block by block (after a read-only stencil/depth test that drops
//! blocks none of whose lanes can pass, when a failing fragment changes nothing), then the
//! alpha test and the stencil and depth tests. unorm8 and RGB565 targets blend in exact
//! integers on u16 lanes (`a·b/255` rounded to nearest, the arithmetic of
//! [`super::blend::blend_unorm8`], so the bytes are those of the span path); 16-bit and
//! float targets go through the span path's f32 stages row by row.
//!
//! Texturing, the texture environments, the colour sum and fog are the draw's fragment
//! program, run over the block's lanes ([`super::shading::Shading::run_block`], varyings
//! from [`BlockInputs::varying_lanes`]), the very program the span path runs.
//!
//! **Batches, one copy per SIMD level.** The walk (`raster::blocks`, in the caller's
//! per-level copy) collects a primitive's blocks in a [`Batch`]; [`BlockPipeline::render`]
//! runs each stage over the whole batch as one direct call into that stage's copy for the
//! level (`simd::dispatch::outlined`, the level a constant of the walk's copy): the
//! stencil/depth stage ([`depth_stencil::DepthStencilKernel::run_blocks`], its format and
//! face matched once per batch, the passing blocks kept), then the colour stage over the
//! survivors. So nothing is dispatched per block, every kernel is inlined into its stage,
//! and each stage is compiled once per level, not once per combination of stages (compiling
//! the whole block body into the walk per depth/stencil kind and level cost minutes of LTO
//! time). A triangle's blocks are disjoint, so running a stage over the batch before the
//! next gives each pixel what block-by-block order gives. Blocks move their 32-bit pixels
//! as whole rows in registers ([`load`], [`store`], `simd::dispatch::load_block`) and pack
//! lane masks by movemask (`simd::dispatch::sign_mask16`).
//!
//! Only filled triangles outside the exact accuracy mode take this path
//! (`setup::jobs::triangle`), on multisampled targets through [`samples`] (one sample's
//! plane of a block at a time, the colour once per block) unless the draw uses
//! alpha-to-coverage or depth clamping; lines, points, smooth primitives, pixel
//! rectangles, those multisampled draws and `TESSERA_ACCURACY=exact` keep the span
//! pipeline ([`super::pipeline`]) until they move to blocks.

pub mod depth_stencil;
pub mod kernels;
pub mod samples;

use super::pipeline::{DrawState, Scratch};
use super::shading::LinearFog;
use super::{AlphaTest, FragmentState};
use crate::framebuffer::band::Band;
use crate::framebuffer::band::ColorBand;
use crate::framebuffer::format::float_to_unorm;
use crate::framebuffer::{ColorFormat, DepthStencilFormat};
use crate::simd::dispatch::{outlined, outlined_sse2_for_sse41, sign_mask16, Word32};
use crate::simd::Supported;
use depth_stencil::DepthStencilKernel;
use kernels::TargetKernel;
use std::sync::atomic::Ordering;

/// Lanes per block.
pub const LANES: usize = 16;
pub type F32s = [f32; LANES];
pub type U16s = [u16; LANES];
pub type U32s = [u32; LANES];

/// The lanes `f(0) … f(15)`: a plain fixed-size loop, which LLVM vectorises (unlike
/// `std::array::from_fn` and `<[T; N]>::map`, which it leaves as 16 calls of a closure).
#[inline(always)]
pub fn lanes<T: Copy + Default>(f: impl Fn(usize) -> T) -> [T; LANES] {
    let mut out = [T::default(); LANES];
    for (i, o) in out.iter_mut().enumerate() {
        *o = f(i);
    }
    out
}

/// `f` on every lane of `a`.
#[inline(always)]
pub fn map_lanes<T: Copy, U: Copy + Default>(a: &[T; LANES], f: impl Fn(T) -> U) -> [U; LANES] {
    lanes(|i| f(a[i]))
}

/// Where a block lies in its band: window position, the index of its lane 0 in the band's
/// slices, the distance between its rows there (the band's row length; on a multisampled
/// band its samples' rows too), which lanes are pixels of the band (all but at the
/// framebuffer's right and top edges), and the SIMD level of the copy handling it (a
/// constant there: [`load`] and [`store`] move whole rows with that level's instructions).
#[derive(Clone, Copy, Debug)]
pub struct BlockAt {
    pub x: i32,
    pub y: i32,
    pub base: usize,
    pub width: usize,
    pub valid: u16,
    pub level: Supported,
}

/// A band's rows as its blocks see them (a copy, so that the band's layers can be borrowed
/// while blocks are placed). On a multisampled band a grid is one sample's plane
/// ([`Grid::sample`]): its pixel rows `stride` apart in the band's slices (the samples of
/// a pixel row are consecutive storage rows, `framebuffer::multisample`), from `offset`.
#[derive(Clone, Copy, Debug)]
pub struct Grid {
    pub y0: i32,
    pub rows: usize,
    pub width: usize,
    /// The distance between pixel rows in the band's slices (`width · samples`).
    pub stride: usize,
    /// The index of the grid's first pixel in the band's slices (sample `s`: `s · width`).
    pub offset: usize,
    pub level: Supported,
}

impl Grid {
    /// `band`'s rows (sample 0's on a multisampled band), for the copy of level `level`.
    #[inline(always)]
    pub fn new(band: &Band<'_>, level: Supported) -> Self {
        let stride = band.width * band.samples.max(1);
        Grid { y0: band.y0, rows: band.rows, width: band.width, stride, offset: 0, level }
    }

    /// Sample `s`'s plane of a multisampled band's grid.
    #[inline(always)]
    pub fn sample(&self, s: usize) -> Self {
        Grid { offset: s * self.width, ..*self }
    }

    /// The block at window `(x, y)` (inside the band's rows).
    #[inline(always)]
    pub fn at(&self, x: i32, y: i32) -> BlockAt {
        let base = (y - self.y0) as usize * self.stride + self.offset + x as usize;
        let (cols, rows) = (self.width as i32 - x, self.y0 + self.rows as i32 - y);
        let (width, level) = (self.stride, self.level);
        if cols >= 4 && rows >= 4 {
            // All but the blocks at the framebuffer's right and top edges.
            return BlockAt { x, y, base, width, valid: 0xffff, level };
        }
        let col_bits = (1u16 << cols.clamp(0, 4)) - 1;
        let mut valid = 0u16;
        for r in 0..rows.clamp(0, 4) {
            valid |= col_bits << (4 * r);
        }
        BlockAt { x, y, base, width, valid, level }
    }
}

impl BlockAt {
    /// The block at window `(x, y)` (inside `band`'s rows), for the copy of level `level`.
    #[inline]
    pub fn new(band: &Band<'_>, x: i32, y: i32, level: Supported) -> Self {
        Grid::new(band, level).at(x, y)
    }

    /// The index of lane `i` in the band's slices.
    #[inline(always)]
    pub fn index(&self, i: usize) -> usize {
        self.base + (i >> 2) * self.width + (i & 3)
    }
}

/// A pixel type of the band slices blocks read and write: 32-bit pixels (packed depth,
/// unorm8 colour) move as whole blocks in registers, bounds-checked once
/// (`simd::dispatch::load_block`), a partial block stored as a select against the stored
/// pixels; the others row by row and lane by lane.
pub trait Pixel: Copy + Default {
    /// The 16 pixels of a block inside the band (`at.valid` is 0xffff).
    #[inline(always)]
    fn load_inside(px: &[Self], at: &BlockAt) -> [Self; LANES] {
        let mut out = [Self::default(); LANES];
        for r in 0..4 {
            out[4 * r..4 * r + 4].copy_from_slice(&px[at.base + r * at.width..][..4]);
        }
        out
    }

    /// Stores the lanes of `mask` of a block inside the band.
    #[inline(always)]
    fn store_inside(px: &mut [Self], at: &BlockAt, values: &[Self; LANES], mask: u16) {
        for r in 0..4 {
            let row = &mut px[at.base + r * at.width..][..4];
            let bits = mask >> (4 * r);
            if bits & 0xf == 0xf {
                row.copy_from_slice(&values[4 * r..4 * r + 4]);
            } else {
                for (c, cell) in row.iter_mut().enumerate() {
                    if bits & (1 << c) != 0 {
                        *cell = values[4 * r + c];
                    }
                }
            }
        }
    }
}

impl Pixel for u8 {}
impl Pixel for u16 {}

/// 32-bit pixels as words, for [`Pixel`]'s block moves.
pub trait Word: Word32 + Default {
    fn to_word(self) -> u32;
    fn from_word(w: u32) -> Self;
}

impl Word for u32 {
    #[inline(always)]
    fn to_word(self) -> u32 {
        self
    }
    #[inline(always)]
    fn from_word(w: u32) -> Self {
        w
    }
}

impl Word for [u8; 4] {
    #[inline(always)]
    fn to_word(self) -> u32 {
        u32::from_le_bytes(self)
    }
    #[inline(always)]
    fn from_word(w: u32) -> Self {
        w.to_le_bytes()
    }
}

impl Pixel for u32 {
    #[inline(always)]
    fn load_inside(px: &[Self], at: &BlockAt) -> [Self; LANES] {
        load_words(px, at)
    }
    #[inline(always)]
    fn store_inside(px: &mut [Self], at: &BlockAt, values: &[Self; LANES], mask: u16) {
        store_words(px, at, values, mask)
    }
}

impl Pixel for [u8; 4] {
    #[inline(always)]
    fn load_inside(px: &[Self], at: &BlockAt) -> [Self; LANES] {
        load_words(px, at)
    }
    #[inline(always)]
    fn store_inside(px: &mut [Self], at: &BlockAt, values: &[Self; LANES], mask: u16) {
        store_words(px, at, values, mask)
    }
}

#[inline(always)]
fn load_words<T: Word>(px: &[T], at: &BlockAt) -> [T; LANES] {
    crate::simd::dispatch::load_block(at.level, px, at.base, at.width)
}

/// A block of words stored whole: the lanes outside `mask` rewritten with the values just
/// loaded (the band is this worker's alone), which costs a load and a select where per-lane
/// stores cost a branch per lane.
#[inline(always)]
fn store_words<T: Word>(px: &mut [T], at: &BlockAt, values: &[T; LANES], mask: u16) {
    let level = at.level;
    if mask == 0xffff {
        return crate::simd::dispatch::store_block(level, px, at.base, at.width, values);
    }
    let old = crate::simd::dispatch::load_block(level, px, at.base, at.width);
    let m = depth_stencil::expand_mask(mask);
    let merged = lanes(|i| T::from_word((values[i].to_word() & m[i]) | (old[i].to_word() & !m[i])));
    crate::simd::dispatch::store_block(level, px, at.base, at.width, &merged)
}

/// The 16 pixels of a block from a band slice (lanes outside the band read `T::default()`).
#[inline(always)]
pub fn load<T: Pixel>(px: &[T], at: &BlockAt) -> [T; LANES] {
    if at.valid == 0xffff {
        return T::load_inside(px, at);
    }
    let mut out = [T::default(); LANES];
    for (i, o) in out.iter_mut().enumerate() {
        if at.valid & (1 << i) != 0 {
            *o = px[at.index(i)];
        }
    }
    out
}

/// Stores the lanes of `mask` (a subset of the valid lanes) into a band slice.
#[inline(always)]
pub fn store<T: Pixel>(px: &mut [T], at: &BlockAt, values: &[T; LANES], mask: u16) {
    if at.valid == 0xffff {
        return T::store_inside(px, at, values, mask);
    }
    for (i, v) in values.iter().enumerate() {
        if mask & at.valid & (1 << i) != 0 {
            px[at.index(i)] = *v;
        }
    }
}

/// A block's fragment colours: one colour for every lane (flat shading), or four channel lanes.
// Lives on the stack, written in place once per block; boxing the lanes would allocate.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug)]
pub enum BlockColors {
    Uniform([f32; 4]),
    Lanes([F32s; 4]),
}

impl BlockColors {
    /// The four channel lanes.
    #[inline(always)]
    pub fn lanes(&self) -> [F32s; 4] {
        match self {
            BlockColors::Uniform(c) => [[c[0]; LANES], [c[1]; LANES], [c[2]; LANES], [c[3]; LANES]],
            BlockColors::Lanes(l) => *l,
        }
    }
}

/// What a primitive gives the block pipeline: its depth and colours over a block, and its
/// varyings at single pixels.
pub trait BlockInputs {
    /// The window depth of the 16 lanes of the block at `(x, y)`.
    fn z(&self, x: i32, y: i32) -> F32s;
    /// The interpolated (or flat) colours of the block at `(x, y)`, into `out`.
    fn colors(&self, x: i32, y: i32, out: &mut BlockColors);
    /// The varyings of the pixel `dx` columns right of and `dy` rows above `(x, y)`, evaluated
    /// as the span path does from a span starting at `(x, y)`.
    fn varyings(&self, x: i32, y: i32, dx: i32, dy: i32, out: &mut [f32]);
    /// The one colour of every fragment of the primitive when it has one (flat shading):
    /// then [`Self::colors`] is that colour for every block, with no lanes to interpolate.
    fn uniform_color(&self) -> Option<[f32; 4]> {
        None
    }
    /// Varyings `first .. first + out.len()` of the 16 lanes of the block at `(x, y)`, lane
    /// `i` with the bits `varyings(x, y + (i >> 2), i & 3, 0, ..)` gives (0 for a varying
    /// the primitive lacks).
    fn varying_lanes(&self, x: i32, y: i32, first: usize, out: &mut [F32s]);
}

/// A draw state compiled for blocks on one framebuffer: the alpha test, the depth/stencil
/// kernel and each colour target's write kernel, chosen once (see [`kernels`]).
pub struct BlockPipeline {
    alpha: Option<AlphaKernel>,
    /// A GLSL shader that may discard or writes the depth: the colours come before the
    /// tests, as with the alpha test.
    late: bool,
    depth_stencil: Option<DepthStencilKernel>,
    targets: Vec<TargetKernel>,
}

/// The alpha test on lanes (see [`super::alpha`] for the two precisions) as an interval of
/// clamped alpha: a fragment passes when `lo <= c < hi` (or, with `invert`, when not), `c`
/// its alpha clamped to [0, 1] with NaN as 0. Both precisions compare a value that never
/// decreases as `c` grows (the unorm8 conversion, or `c` itself) with the reference, so
/// every function is such an interval, found once per draw state ([`AlphaKernel::new`]);
/// per block that is two float comparisons per lane, with no conversion to unorm8.
#[derive(Clone, Copy, Debug)]
struct AlphaKernel {
    lo: f32,
    hi: f32,
    invert: bool,
}

impl AlphaKernel {
    fn new(test: &AlphaTest) -> Self {
        use crate::gl::CompareFunc as C;
        let clamp = |x: f32| if x > 0.0 { x.min(1.0) } else { 0.0 };
        // The compared value of a clamped alpha, and the reference's.
        let value = |c: f32| if test.unorm8 { float_to_unorm(c, 8) } else { c.to_bits() };
        let reference = if test.unorm8 {
            super::alpha::reference_unorm8(test.reference) as u32
        } else {
            clamp(test.reference).to_bits()
        };
        // The least clamped alpha whose value reaches `v` (+∞ when none does): a binary
        // search over the bit patterns of [0, 1], which order as their values.
        let first = |v: u32| -> f32 {
            if value(1.0) < v {
                return f32::INFINITY;
            }
            let (mut below, mut at) = (0u32, 1f32.to_bits());
            if value(0.0) >= v {
                return 0.0;
            }
            // value(bits below) < v <= value(bits at)
            while at - below > 1 {
                let mid = below + (at - below) / 2;
                if value(f32::from_bits(mid)) >= v {
                    at = mid;
                } else {
                    below = mid;
                }
            }
            f32::from_bits(at)
        };
        let (r, r1) = (first(reference), first(reference + 1));
        let inf = f32::INFINITY;
        let (lo, hi, invert) = match test.func {
            C::Never => (inf, inf, false),
            C::Less => (0.0, r, false),
            C::LessEqual => (0.0, r1, false),
            C::Equal => (r, r1, false),
            C::NotEqual => (r, r1, true),
            C::Greater => (r1, inf, false),
            C::GreaterEqual => (r, inf, false),
            C::Always => (0.0, inf, false),
        };
        AlphaKernel { lo, hi, invert }
    }

    #[inline(always)]
    fn test(&self, level: Supported, alpha: &F32s, live: u16) -> u16 {
        let flip = if self.invert { !0u32 } else { 0 };
        let pass: U32s = lanes(|i| {
            let a = alpha[i];
            let a = if a > 0.0 { a } else { 0.0 };
            let c = if a < 1.0 { a } else { 1.0 };
            let inside = if (c >= self.lo) & (c < self.hi) { !0u32 } else { 0 };
            inside ^ flip
        });
        sign_mask16(level, &pass) & live
    }
}

impl BlockPipeline {
    /// The depth test by which hierarchical z may skip regions of a triangle of this draw
    /// ([`DepthStencilKernel::hiz_reject`]); none when a shader writes the depth.
    pub fn hiz_reject(&self, fragment: &FragmentState) -> Option<crate::framebuffer::hiz::DepthReject> {
        let shader_depth = fragment.glsl.as_ref().is_some_and(|g| g.writes_depth());
        self.depth_stencil.as_ref().and_then(|k| k.hiz_reject()).filter(|_| !shader_depth)
    }

    /// Compiles `fragment` for a single-sampled framebuffer whose band colour targets have
    /// `formats` (in the band's order) and whose depth/stencil layer is `depth_format`.
    pub fn compile(fragment: &FragmentState, formats: &[ColorFormat], depth_format: DepthStencilFormat) -> Self {
        // A target whose channels are all masked (glColorMask(0, 0, 0, 0): the stencil
        // passes of shadow volumes, depth pre-passes) gets no kernel: nothing it could do
        // changes a bit, and without a target the block stage skips the colours entirely.
        let targets = formats
            .iter()
            .zip(&fragment.color_masks)
            .enumerate()
            .filter(|(_, (_, mask))| mask.is_some_and(|m| m.contains(&true)))
            .filter_map(|(index, (format, mask))| Some(TargetKernel::new(fragment, index, *format, (*mask)?)))
            .collect();
        BlockPipeline {
            alpha: fragment.alpha.as_ref().map(AlphaKernel::new),
            late: fragment.late_tests(),
            depth_stencil: DepthStencilKernel::new(fragment, depth_format),
            targets,
        }
    }
}

impl BlockPipeline {
    /// The constant fill of a primitive whose every fragment has colour `color` (flat
    /// shading), drawn with `state`: the index of the one colour target and the pixel value
    /// to store at each covered pixel, when the pipeline writes that value there
    /// unconditionally. That holds when nothing can drop or change a fragment (no alpha,
    /// stencil or depth test and no depth write, no fragment program: texturing, colour sum
    /// and fog are one, no occlusion count) and the target's kernel stores a constant colour
    /// ([`TargetKernel::constant_pixel`]: no blend, logic op, channel mask or dither that
    /// changes the value). The primitive's covered pixels may then be written as whole
    /// rectangles (`setup::jobs::triangle`) with the bytes [`Self::render`] writes.
    pub fn constant_fill(&self, state: &DrawState, color: [f32; 4]) -> Option<(usize, [u8; 4])> {
        let unconditional = self.alpha.is_none()
            && self.depth_stencil.is_none()
            && state.samples_passed.is_none()
            && state.fragment.shading.is_none()
            && state.fragment.glsl.is_none();
        match self.targets.as_slice() {
            [target] if unconditional => Some((target.index, target.constant_pixel(color)?)),
            _ => None,
        }
    }
}

/// A block the walk found: window position (multiples of 4), covered lanes, and which
/// primitive of the batch's sources it is of ([`BlockSource`]; 0 for a batch of one
/// primitive).
#[derive(Clone, Copy, Debug, Default)]
pub struct BlockEntry {
    pub x: i32,
    pub y: i32,
    pub mask: u16,
    pub source: u8,
}

/// The primitives whose blocks a batch holds: one primitive (any [`BlockInputs`]), or a run
/// of them (`setup::jobs::triangle`'s runs of small triangles in a tile, one batch for
/// many triangles), block `b` being of primitive `b.source`.
pub trait BlockSource {
    type Inputs: BlockInputs;
    /// The primitive of blocks with source `source`.
    fn of(&self, source: u8) -> &Self::Inputs;
}

impl<T: BlockInputs> BlockSource for T {
    type Inputs = T;
    #[inline(always)]
    fn of(&self, _: u8) -> &T {
        self
    }
}

/// The primitives of one batch as the renderers hand them to the stages: block source `s`
/// is `of[s]`, the first `len` set (the rest repeat the first and are never read). A single
/// primitive is a run of one ([`Run::one`]): the stages are compiled for `Run<T>` alone, not
/// a second time for `T` (a copy of every colour stage per SIMD level, about 200 KB of each
/// library: issue #18's 5 MB limit), so every renderer of `T` passes a `Run`.
pub struct Run<'a, T> {
    pub of: [&'a T; BATCH],
    pub len: usize,
}

impl<'a, T> Run<'a, T> {
    /// `primitive` alone (every block of the batch is of source 0).
    #[inline(always)]
    pub fn one(primitive: &'a T) -> Self {
        Run { of: [primitive; BATCH], len: 1 }
    }
}

impl<T: BlockInputs> BlockSource for Run<'_, T> {
    type Inputs = T;
    #[inline(always)]
    fn of(&self, source: u8) -> &T {
        self.of[source as usize % BATCH]
    }
}

/// Blocks in a batch: the walk's blocks are collected this many at a time, so that each
/// stage runs as one call per batch rather than one per block.
pub const BATCH: usize = 32;

/// A batch of blocks in walk order, of one primitive or of a run of them ([`BlockSource`]).
/// The stages may run over the whole batch one after the other: each stage handles the
/// blocks in order and reads and writes only its own buffers (the tests depth and stencil,
/// the colour stage the colour targets), so every pixel sees each of its fragments' tests
/// and writes in submission order, as block by block, also where blocks of several
/// primitives of a run overlap.
pub struct Batch {
    entries: [BlockEntry; BATCH],
    len: usize,
}

impl Default for Batch {
    fn default() -> Self {
        Batch { entries: [BlockEntry::default(); BATCH], len: 0 }
    }
}

impl Batch {
    /// Adds a block; true when the batch is then full.
    #[inline(always)]
    pub fn push(&mut self, x: i32, y: i32, mask: u16) -> bool {
        self.push_from(0, x, y, mask)
    }

    /// Adds a block of the batch's primitive `source` ([`BlockSource`]); true when the
    /// batch is then full.
    #[inline(always)]
    pub fn push_from(&mut self, source: u8, x: i32, y: i32, mask: u16) -> bool {
        // `len < BATCH` always holds here: a full batch is rendered (emptied) at once.
        let slot = self.len.min(BATCH - 1);
        self.entries[slot] = BlockEntry { x, y, mask, source };
        self.len = slot + 1;
        self.len == BATCH
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl BlockPipeline {
    /// Runs the fragment pipeline (see the module) on the blocks of `batch` of a primitive
    /// facing front or back (`front_facing`, for two-sided stencil), and empties it. Called
    /// from the walk's copy for SIMD level `level` (a constant there): each stage is one
    /// direct call per batch into its copy for the level (`simd::dispatch::outlined`),
    /// compiled once per level: the stencil/depth tests of every block, then the colours
    /// and target writes of the blocks with a surviving lane; with the alpha test, the
    /// colours, the alpha test and the tests block by block.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub fn render<I: BlockSource>(
        &self,
        level: Supported,
        state: &DrawState,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
        inputs: &I,
        front_facing: bool,
        batch: &mut Batch,
    ) {
        let len = std::mem::take(&mut batch.len);
        let blocks = &mut batch.entries[..len];
        if blocks.is_empty() {
            return;
        }
        let grid = Grid::new(band, level);
        if self.alpha.is_some() || self.late {
            // Colours first: kept per block for the target writes (the enum's flat variant
            // makes the buffer cheap to set up).
            let mut shaded = [BlockColors::Uniform([0.0; 4]); BATCH];
            let survivors = outlined(
                level,
                #[inline(always)]
                |level| {
                    let grid = Grid { level, ..grid };
                    alpha_blocks(self, state, band, scratch, grid, inputs, front_facing, blocks, &mut shaded)
                },
            );
            if survivors > 0 && !self.targets.is_empty() {
                let (blocks, shaded) = (&blocks[..survivors], Some(&shaded[..survivors]));
                self.color_stage(level, state, band, scratch, grid, inputs, blocks, shaded, front_facing);
            }
            return;
        }
        // Whether anything reads the lanes that pass: the occlusion count or a colour target.
        let counted = state.samples_passed.is_some() || !self.targets.is_empty();
        // SSE4.1's copy of the tests ran more instructions than SSE2's (simd::dispatch).
        let survivors = match &self.depth_stencil {
            Some(kernel) => outlined_sse2_for_sse41(
                level,
                #[inline(always)]
                |level| {
                    let grid = Grid { level, ..grid };
                    kernel.run_blocks(
                        &mut band.depth,
                        grid,
                        front_facing,
                        blocks,
                        counted,
                        #[inline(always)]
                        |b| inputs.of(b.source).z(b.x, b.y),
                    )
                },
            ),
            None => blocks.len(),
        };
        let blocks = &blocks[..survivors];
        if let Some(counter) = &state.samples_passed {
            let passed: u32 = blocks.iter().map(|b| b.mask.count_ones()).sum();
            counter.fetch_add(u64::from(passed), Ordering::Relaxed);
        }
        // Without a colour target to write (depth-only passes, all channels masked) the
        // colours are never needed.
        if !blocks.is_empty() && !self.targets.is_empty() {
            self.color_stage(level, state, band, scratch, grid, inputs, blocks, None, front_facing);
        }
    }

    /// The colour stage ([`color_blocks`]), one copy per level (one closure) for both orders
    /// of [`Self::render`] (colours kept by the alpha test, or computed here) and for the
    /// multisampled blocks (`samples`), not a copy of every target kernel each: a second
    /// copy for the early-test order ran about 1 % fewer instructions on the blend, depth
    /// and stencil scenes (callgrind) and cost each library 196 KB.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn color_stage<I: BlockSource>(
        &self,
        level: Supported,
        state: &DrawState,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
        grid: Grid,
        inputs: &I,
        blocks: &[BlockEntry],
        shaded: Option<&[BlockColors]>,
        front_facing: bool,
    ) {
        outlined(
            level,
            #[inline(always)]
            |level| {
                let grid = Grid { level, ..grid };
                color_blocks(self, &state.fragment, band, scratch, grid, inputs, blocks, shaded, front_facing)
            },
        );
    }
}

/// The target writes of blocks whose tests are done (`mask`: the surviving lanes), with
/// their colours (`shaded`, when the alpha test computed them, else computed here),
/// compiled once per SIMD level.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn color_blocks<I: BlockSource>(
    pipeline: &BlockPipeline,
    fragment: &FragmentState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    grid: Grid,
    inputs: &I,
    blocks: &[BlockEntry],
    shaded: Option<&[BlockColors]>,
    front_facing: bool,
) {
    // The common case has a loop of its own: one unorm8 target taking packed words, no
    // alpha test or shader, and no fragment program or linear fog alone.
    if let (None, None, [target]) = (shaded, &fragment.glsl, pipeline.targets.as_slice()) {
        let fog = fragment.shading.as_ref().map(|s| s.linear_fog());
        if let (true, ColorBand::Unorm8(px)) = (target.takes_words(), &mut band.colors[target.index].pixels) {
            match fog {
                None => return word_blocks(target, None, px, grid, inputs, blocks),
                Some(Some(fog)) => return word_blocks(target, Some(fog), px, grid, inputs, blocks),
                Some(None) => {}
            }
        }
    }
    let mut local = BlockColors::Uniform([0.0; 4]);
    for (i, b) in blocks.iter().enumerate() {
        let at = grid.at(b.x, b.y);
        let colors = match shaded {
            Some(shaded) => &shaded[i],
            None => {
                // Nothing discards here (a shader that may runs before the tests).
                block_colors(fragment, scratch, &at, b.mask, front_facing, inputs.of(b.source), &mut local);
                &local
            }
        };
        write_targets(pipeline, band, &at, colors, b.mask);
    }
}

/// [`color_blocks`] for one unorm8 target whose kernel takes the colours as packed words
/// ([`TargetKernel::run_colors`]), without an alpha test or shader, with linear fog alone
/// (`fog`) or no fragment program: per block the primitive's colours, the fog written out
/// ([`LinearFog::apply_body`], inlined) and the target's kernel,
/// in one small loop whose lanes stay in registers (the general loop, which serves every
/// kind, kept them on the stack and reloaded its state from there: about 70 instructions a
/// block of bookkeeping, callgrind).
#[inline(always)]
fn word_blocks<I: BlockSource>(
    target: &TargetKernel,
    fog: Option<&LinearFog>,
    px: &mut [[u8; 4]],
    grid: Grid,
    inputs: &I,
    blocks: &[BlockEntry],
) {
    for b in blocks {
        let at = grid.at(b.x, b.y);
        let inputs = inputs.of(b.source);
        let mut colors = BlockColors::Uniform([0.0; 4]);
        match inputs.uniform_color() {
            Some(c) => colors = BlockColors::Uniform(c),
            None => inputs.colors(at.x, at.y, &mut colors),
        }
        if let Some(fog) = fog {
            let mut lanes = colors.lanes();
            let mut coordinate = [[0.0; LANES]];
            inputs.varying_lanes(at.x, at.y, 0, &mut coordinate);
            fog.apply_body(&coordinate[0], &mut lanes);
            colors = BlockColors::Lanes(lanes);
        }
        target.run_colors(px, &at, &colors, b.mask);
    }
}

/// The pipeline up to the target writes with the alpha test, block by block, compiled once
/// per SIMD level: the colours, the alpha test, the stencil and depth tests (after a
/// read-only test that drops blocks none of whose lanes can pass, when a failing fragment
/// changes nothing) and the occlusion count. Keeps in `blocks`, in order, the blocks with a
/// surviving lane (their masks those lanes) and their colours in `shaded`; returns how many.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn alpha_blocks<I: BlockSource>(
    pipeline: &BlockPipeline,
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    grid: Grid,
    inputs: &I,
    front_facing: bool,
    blocks: &mut [BlockEntry],
    shaded: &mut [BlockColors; BATCH],
) -> usize {
    let fragment = &state.fragment;
    // A shader's own depths: then no test can run before it.
    let shader_depth = fragment.glsl.as_ref().filter(|g| g.writes_depth()).is_some();
    let mut kept = 0;
    for i in 0..blocks.len() {
        let b = blocks[i];
        let inputs = inputs.of(b.source);
        let (x, y) = (b.x, b.y);
        let at = grid.at(x, y);
        let mut live = b.mask;
        // A block none of whose lanes can pass changes nothing whatever its alpha, so it
        // needs no colours.
        if let Some(kernel) = pipeline.depth_stencil.as_ref().filter(|k| k.culls_before_alpha() && !shader_depth) {
            if kernel.test(&mut band.depth, &at, live, front_facing, || inputs.z(x, y)) == 0 {
                continue;
            }
        }
        let colors = &mut shaded[kept.min(BATCH - 1)];
        live = block_colors(fragment, scratch, &at, live, front_facing, inputs, colors);
        if let Some(alpha) = &pipeline.alpha {
            live = match colors {
                BlockColors::Uniform(c) => alpha.test(grid.level, &[c[3]; LANES], live),
                BlockColors::Lanes(l) => alpha.test(grid.level, &l[3], live),
            };
        }
        if live == 0 {
            continue;
        }
        if let Some(kernel) = &pipeline.depth_stencil {
            let depth = scratch.block_depth;
            live =
                kernel.run(
                    &mut band.depth,
                    &at,
                    live,
                    front_facing,
                    || {
                        if shader_depth {
                            depth
                        } else {
                            inputs.z(x, y)
                        }
                    },
                );
            if live == 0 {
                continue;
            }
        }
        if let Some(counter) = &state.samples_passed {
            counter.fetch_add(live.count_ones() as u64, Ordering::Relaxed);
        }
        blocks[kept] = BlockEntry { mask: live, ..b };
        kept += 1;
    }
    kept
}

/// Every colour target's write kernel on the lanes of `live`. One target (nearly every
/// draw) is no loop: in a loop LLVM hoists the mask work of every kernel kind's rare paths
/// out of it (over 100 instructions per block, measured), to run whichever kind runs.
#[inline(always)]
fn write_targets(pipeline: &BlockPipeline, band: &mut Band<'_>, at: &BlockAt, colors: &BlockColors, live: u16) {
    match pipeline.targets.as_slice() {
        [target] => target.run(&mut band.colors[target.index].pixels, at, colors, live),
        targets => {
            for target in targets {
                target.run(&mut band.colors[target.index].pixels, at, colors, live);
            }
        }
    }
}

/// The fragment colours of a block (the lanes of `live` are the ones that count): the
/// primitive's interpolated (or flat) colours, then the draw's fragment program (texturing,
/// colour sum, fog: [`crate::fragment::shading`]) over the block's lanes when it has one.
/// The one place the block path computes colours: its inputs are the block's position and
/// live lanes and the primitive's planes, its output the 16 colour lanes. Returns the lanes
/// of `live` that survive: a GLSL shader ([`glsl_block_colors`]) may discard.
#[inline(always)]
fn block_colors(
    fragment: &FragmentState,
    scratch: &mut Scratch,
    at: &BlockAt,
    live: u16,
    front_facing: bool,
    inputs: &impl BlockInputs,
    colors: &mut BlockColors,
) -> u16 {
    if let Some(glsl) = &fragment.glsl {
        return glsl_block_colors(glsl, scratch, at, live, front_facing, inputs, colors);
    }
    match inputs.uniform_color() {
        Some(c) => *colors = BlockColors::Uniform(c),
        None => inputs.colors(at.x, at.y, colors),
    }
    let Some(shading) = &fragment.shading else {
        return live;
    };
    // The program writes its colours in place: the interpolated lanes are not copied out
    // and back (a flat colour becomes lanes first).
    if let BlockColors::Uniform(_) = colors {
        *colors = BlockColors::Lanes(colors.lanes());
    }
    let BlockColors::Lanes(lanes) = colors else { return live };
    let texturing = fragment.texturing.as_deref();
    // The closure inlined (LLVM left it a call per varying run and pass, with the planes'
    // setup behind it, in each per-level body).
    shading.run_block(
        at.level,
        &mut scratch.shading,
        texturing,
        at.y,
        live,
        lanes,
        #[inline(always)]
        |y, first, out| inputs.varying_lanes(at.x, y, first, out),
    );
    live
}

/// [`block_colors`] with a GLSL fragment shader: its colours, its depths in
/// `scratch.block_depth`; returns the lanes of `live` that did not discard. Not inlined:
/// one copy serves every SIMD level's block body (the shader's interpreter has its own).
#[inline(never)]
fn glsl_block_colors(
    glsl: &super::glsl_shading::GlslShading,
    scratch: &mut Scratch,
    at: &BlockAt,
    live: u16,
    front_facing: bool,
    inputs: &impl BlockInputs,
    colors: &mut BlockColors,
) -> u16 {
    let mut lanes = [[0.0; LANES]; 4];
    let mut depth = [0.0; LANES];
    let kept = glsl.run_block(
        &mut scratch.glsl,
        at.x,
        at.y,
        live,
        front_facing,
        &mut lanes,
        &mut depth,
        |y0, primary, z, varyings| {
            let mut c = BlockColors::Uniform([0.0; 4]);
            match inputs.uniform_color() {
                Some(u) => c = BlockColors::Uniform(u),
                None => inputs.colors(at.x, y0, &mut c),
            }
            *primary = c.lanes();
            *z = inputs.z(at.x, y0);
            if !varyings.is_empty() {
                inputs.varying_lanes(at.x, y0, 0, varyings);
            }
        },
    );
    *colors = BlockColors::Lanes(lanes);
    scratch.block_depth = depth;
    kept
}

/// Test values around every unorm8 step: each step `k/255`, the half-way points between
/// steps and the floats a few ulps either side of them (ties round to even), and the float
/// just below 1.
#[cfg(test)]
pub(crate) fn unorm8_steps_and_ties() -> Vec<f32> {
    let mut values = Vec::new();
    for k in 0..=256u32 {
        let x = (k as f32 - 0.5) / 255.0;
        for d in -3..=3i32 {
            values.push(f32::from_bits((x.abs().to_bits() as i32 + d) as u32).copysign(x));
        }
        values.push(k as f32 / 255.0);
    }
    values.push(f32::from_bits(1f32.to_bits() - 1));
    values
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::band::{ColorBand, ColorTarget, DepthBand};
    use crate::framebuffer::ColorSlot;

    #[test]
    fn blocks_at_the_framebuffer_edge_touch_only_their_pixels() {
        // A 6×3 band: the block at (4, 0) has 2 columns and 3 rows inside.
        let mut colors = [[0u8; 4]; 18];
        let band = Band {
            y0: 0,
            rows: 3,
            width: 6,
            samples: 1,
            colors: vec![ColorTarget {
                slot: ColorSlot::FrontLeft,
                format: ColorFormat::Unorm8 { alpha: true },
                pixels: ColorBand::Unorm8(&mut colors),
            }],
            depth: DepthBand::None,
            depth_format: DepthStencilFormat::None,
            hiz: Default::default(),
        };
        let at = BlockAt::new(&band, 4, 0, crate::simd::current());
        assert_eq!(at.valid, 0b0000_0011_0011_0011);
        drop(band);
        let mut px = [7u32; 18];
        let values: U32s = std::array::from_fn(|i| i as u32);
        assert_eq!(load(&px, &at)[5], 7);
        assert_eq!(load(&px, &at)[2], 0, "outside the band");
        store(&mut px, &at, &values, at.valid);
        assert_eq!(px[4..6], [0, 1]);
        assert_eq!(px[10..12], [4, 5]);
        assert_eq!(px[16..18], [8, 9]);
        assert_eq!(px[0..4], [7; 4]);
    }

    #[test]
    fn fully_masked_targets_get_no_kernel() {
        // glColorMask(0, 0, 0, 0) (a shadow volume's stencil pass): no target, so the block
        // stage never computes colours; one channel written keeps its kernel.
        let formats = [ColorFormat::Unorm8 { alpha: true }, ColorFormat::Unorm8 { alpha: true }];
        let masks = |a, b| FragmentState::plain(None, vec![a, b], false);
        let compiled = |f: &FragmentState| BlockPipeline::compile(f, &formats, DepthStencilFormat::None);
        let indices = |p: &BlockPipeline| p.targets.iter().map(|t| t.index).collect::<Vec<_>>();
        assert!(compiled(&masks(Some([false; 4]), None)).targets.is_empty());
        assert_eq!(indices(&compiled(&masks(Some([false; 4]), Some([false, false, false, true])))), [1]);
        assert_eq!(indices(&compiled(&masks(Some([true; 4]), Some([false; 4])))), [0]);
    }

    #[test]
    fn the_lane_alpha_test_is_the_span_alpha_test() {
        use crate::gl::CompareFunc as C;
        // Alphas at and around every unorm8 step and the references, the edges and NaN.
        let mut alphas = vec![0.0, -0.0, 1.0, 2.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e-30, 1e-45];
        alphas.extend(unorm8_steps_and_ties());
        let references = [0.0, 1.0, 0.5, 0.1, 0.75, 125.5 / 255.0, 126.5 / 255.0, -0.5, 1.5, f32::NAN, 1e-40];
        for func in [C::Never, C::Less, C::Equal, C::LessEqual, C::Greater, C::NotEqual, C::GreaterEqual, C::Always] {
            for &reference in &references {
                for unorm8 in [false, true] {
                    let test = AlphaTest { func, reference, unorm8 };
                    let kernel = AlphaKernel::new(&test);
                    for chunk in alphas.chunks(LANES) {
                        let mut lanes = [0.5f32; LANES];
                        lanes[..chunk.len()].copy_from_slice(chunk);
                        let pixels: Vec<[f32; 4]> = lanes.iter().map(|&a| [0.0, 0.0, 0.0, a]).collect();
                        let want = test.test(&pixels, 0xffff) as u16;
                        let level = crate::simd::current();
                        assert_eq!(kernel.test(level, &lanes, 0xffff), want, "{test:?} {chunk:?}");
                        assert_eq!(kernel.test(level, &lanes, 0x5a5a), want & 0x5a5a);
                    }
                }
            }
        }
    }
}
