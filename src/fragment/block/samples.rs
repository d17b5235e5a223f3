//! The block pipeline on a multisampled target: 4×4 blocks with one coverage mask per
//! sample, the stencil and depth tests and writes per sample over lanes, the colour
//! computed once per pixel (the fragment program once per block, at pixel centres, as the
//! span path and llvmpipe do) and written to each covered sample.
//!
//! **Lanes: one sample of 16 pixels.** A multisampled layer stores sample `s` of pixel row
//! `y` as storage row `y·S + s` (`framebuffer::multisample`), so sample `s` of a 4×4 block
//! is 4 runs of 4 consecutive pixels `S` rows apart: the very shape of a single-sampled
//! block with a longer row stride ([`Grid::sample`]). Lane `i` of a block is therefore
//! pixel `i` of one sample, and per block the pipeline runs each sample as a block of its
//! own: the depth/stencil kernels and the colour target kernels of the single-sample path
//! run unchanged on it (whole-row loads and stores, 16 depth comparisons per vector pass),
//! with the sample's depth lanes (the depth plane at the sample positions) and coverage
//! mask. The other layout that keeps rows whole, the 4 samples × 4 pixels of one pixel row
//! (consecutive storage rows), would need the pixel colours shuffled into lanes per sample
//! and a depth plane evaluated at a different point pattern per lane; with a sample per
//! block the colour lanes computed once are the lanes of every sample's write.
//!
//! Stage order (GL 2.1 §4.1 with §4.1.3's multisample operations), as the span path's
//! driver (`super::super::pipeline::shade` with its `SampleCoverage` footprint): the
//! walk's per-sample masks narrowed by GL_SAMPLE_COVERAGE (`setup`); per sample the stencil
//! and depth tests over the whole batch (one format match per sample and batch: a batch's
//! blocks and a block's samples are disjoint pixels, so the order gives each sample what
//! block-by-block order gives); GL_SAMPLES_PASSED counting passing samples; the colours of
//! the blocks with a passing sample; alpha-to-one; then per sample the target writes
//! (blend, logic op, dither at the pixel's position, masks).
//!
//! With the alpha test the colours come first, block by block (after a read-only
//! per-sample stencil/depth test that drops blocks none of whose samples can pass, when a
//! failing fragment changes nothing): the alpha test removes a failing pixel's every
//! sample, then the per-sample tests run. Draws with alpha-to-coverage and with depth
//! clamping (which the multisampled span path has never applied) are not compiled for this
//! path: `setup` keeps them on the span path.

use super::{block_colors, BlockColors, BlockEntry, BlockInputs, BlockPipeline, F32s, Grid, BATCH};
use crate::fragment::pipeline::{DrawState, Scratch};
use crate::framebuffer::band::Band;
use crate::framebuffer::multisample::MAX_SAMPLES;
use crate::simd::dispatch::{outlined, outlined_sse2_for_sse41};
use crate::simd::Supported;
use std::sync::atomic::Ordering;

/// What a primitive gives the multisampled block pipeline beyond [`BlockInputs`]: its
/// depth at each sample position.
pub trait SampleInputs: BlockInputs {
    /// The primitive's inputs at pixel centres (the colours), the type the single-sample
    /// pipeline's stages are compiled for, so that the colour writes share their copies.
    type Pixels: BlockInputs;
    fn pixels(&self) -> &Self::Pixels;

    /// The window depth of sample `sample` of the 16 pixels of the block at `(x, y)`.
    fn sample_z(&self, x: i32, y: i32, sample: usize) -> F32s;
}

/// A block with covered samples: window position, the pixels with any covered sample, and
/// each sample's covered pixels.
#[derive(Clone, Copy, Debug, Default)]
pub struct SampleEntry {
    pub x: i32,
    pub y: i32,
    pub mask: u16,
    pub samples: [u16; MAX_SAMPLES],
}

/// A batch of a primitive's blocks with their sample masks (see [`super::Batch`]).
pub struct SampleBatch {
    entries: [SampleEntry; BATCH],
    len: usize,
}

impl Default for SampleBatch {
    fn default() -> Self {
        SampleBatch { entries: [SampleEntry::default(); BATCH], len: 0 }
    }
}

impl SampleBatch {
    /// Adds a block (`samples`: each sample's covered pixels); true when the batch is then
    /// full.
    #[inline(always)]
    pub fn push(&mut self, x: i32, y: i32, samples: [u16; MAX_SAMPLES]) -> bool {
        let mask = samples.iter().fold(0, |a, &m| a | m);
        let slot = self.len.min(BATCH - 1);
        self.entries[slot] = SampleEntry { x, y, mask, samples };
        self.len = slot + 1;
        self.len == BATCH
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl BlockPipeline {
    /// Whether a draw state runs on the multisampled block path (see the module): without
    /// alpha-to-coverage and depth clamping.
    pub fn takes_samples(state: &DrawState) -> bool {
        // GLSL shaders take the span path there (it has the facing and runs a shader
        // that discards or writes the depth before the tests).
        state.fragment.depth_clamp.is_none()
            && state.fragment.glsl.is_none()
            && !state.multisample.is_some_and(|m| m.enabled && m.alpha_to_coverage)
    }

    /// Runs the multisampled pipeline (see the module) on the blocks of `batch` of a
    /// primitive facing front or back, on a band of `band.samples` samples, and empties it.
    /// Called from the walk's copy for SIMD level `level`, each stage one direct call per
    /// batch into its copy for the level, as [`BlockPipeline::render`].
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub fn render_samples<I: SampleInputs>(
        &self,
        level: Supported,
        state: &DrawState,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
        inputs: &I,
        front_facing: bool,
        batch: &mut SampleBatch,
    ) {
        let len = std::mem::take(&mut batch.len);
        let blocks = &mut batch.entries[..len];
        if blocks.is_empty() {
            return;
        }
        // The batch's stages in one copy per level, called from both of the walk's calls
        // (a direct call per batch: the level is a constant of the walk's copy), each stage
        // a direct call from it, rather than their glue inlined into each call of the walk.
        outlined(
            level,
            #[inline(always)]
            |level| self.sample_stages(level, state, band, scratch, inputs, front_facing, blocks),
        );
    }

    /// [`Self::render_samples`]'s stages on the non-empty `blocks` of a batch.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn sample_stages<I: SampleInputs>(
        &self,
        level: Supported,
        state: &DrawState,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
        inputs: &I,
        front_facing: bool,
        blocks: &mut [SampleEntry],
    ) {
        let samples = band.samples.min(MAX_SAMPLES);
        let grid = Grid::new(band, level);
        let alpha_to_one = state.multisample.is_some_and(|m| m.enabled && m.alpha_to_one);
        // Colours first with the alpha test, kept per block for the target writes (as
        // `render`); one copy of the target writes per level serves both orders.
        if self.alpha.is_some() {
            let mut shaded = [BlockColors::Uniform([0.0; 4]); BATCH];
            let survivors = outlined(
                level,
                #[inline(always)]
                |level| {
                    let grid = Grid { level, ..grid };
                    alpha_sample_blocks(self, state, band, scratch, grid, inputs, front_facing, blocks, &mut shaded)
                },
            );
            if survivors > 0 && !self.targets.is_empty() {
                let blocks = &blocks[..survivors];
                self.write_sample_blocks(
                    level,
                    state,
                    band,
                    scratch,
                    grid,
                    inputs,
                    blocks,
                    &mut shaded,
                    true,
                    alpha_to_one,
                );
            }
            return;
        }
        if let Some(kernel) = &self.depth_stencil {
            // As `render`'s tests: SSE4.1's copy measured slower than SSE2's.
            outlined_sse2_for_sse41(
                level,
                #[inline(always)]
                |level| {
                    let grid = Grid { level, ..grid };
                    for s in 0..samples {
                        // The blocks covering sample s, tested as single-sample blocks of
                        // its plane; the survivors (a subsequence, in order) merged back.
                        let mut plane = [BlockEntry::default(); BATCH];
                        let mut n = 0;
                        for b in blocks.iter().filter(|b| b.samples[s] != 0) {
                            plane[n.min(BATCH - 1)] = BlockEntry { x: b.x, y: b.y, mask: b.samples[s], source: 0 };
                            n += 1;
                        }
                        if n == 0 {
                            continue;
                        }
                        let kept = kernel.run_blocks(
                            &mut band.depth,
                            grid.sample(s),
                            front_facing,
                            &mut plane[..n],
                            true,
                            #[inline(always)]
                            |b| inputs.sample_z(b.x, b.y, s),
                        );
                        let mut j = 0;
                        for b in blocks.iter_mut().filter(|b| b.samples[s] != 0) {
                            let p = plane[j.min(BATCH - 1)];
                            if j < kept && p.x == b.x && p.y == b.y {
                                b.samples[s] = p.mask;
                                j += 1;
                            } else {
                                b.samples[s] = 0;
                            }
                        }
                    }
                },
            );
        }
        // The blocks with a passing sample, their masks the pixels with one.
        let mut kept = 0;
        let mut passed = 0u32;
        for i in 0..blocks.len() {
            let b = blocks[i];
            let mask = b.samples[..samples].iter().fold(0, |a, &m| a | m);
            passed += b.samples[..samples].iter().map(|m| m.count_ones()).sum::<u32>();
            blocks[kept] = SampleEntry { mask, ..b };
            kept += usize::from(mask != 0);
        }
        if let Some(counter) = &state.samples_passed {
            // GL_SAMPLES_PASSED counts samples on a multisampled target (§4.1.7).
            counter.fetch_add(u64::from(passed), Ordering::Relaxed);
        }
        if kept == 0 || self.targets.is_empty() {
            return;
        }
        let mut shaded = [BlockColors::Uniform([0.0; 4]); BATCH];
        let blocks = &blocks[..kept];
        self.write_sample_blocks(level, state, band, scratch, grid, inputs, blocks, &mut shaded, false, alpha_to_one);
    }

    /// The colours (unless kept in `shaded`, one per block) and the target writes of
    /// `blocks`, for both orders of [`Self::render_samples`]: the colours once per block
    /// (one small stage per level), then per sample the single-sample pipeline's colour
    /// stage (`color_stage`) with the colours kept, on the sample's plane of the blocks.
    /// That stage's copies (every target kernel, about 60 KB per level) thus serve both
    /// paths; a sample's writes are one call per batch, and the samples are disjoint
    /// pixels, so writing sample by sample gives the bytes of block by block.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn write_sample_blocks<I: SampleInputs>(
        &self,
        level: Supported,
        state: &DrawState,
        band: &mut Band<'_>,
        scratch: &mut Scratch,
        grid: Grid,
        inputs: &I,
        blocks: &[SampleEntry],
        shaded: &mut [BlockColors; BATCH],
        kept: bool,
        alpha_to_one: bool,
    ) {
        let pixels = inputs.pixels();
        // The colour stage's copies are those of the single-sample pipeline's runs.
        let run = super::Run::one(pixels);
        let n = blocks.len().min(BATCH);
        let blocks = &blocks[..n];
        if !kept {
            let fragment = &state.fragment;
            outlined(
                level,
                #[inline(always)]
                |level| {
                    let grid = Grid { level, ..grid };
                    for (b, colors) in blocks.iter().zip(shaded.iter_mut()) {
                        block_colors(fragment, scratch, &grid.at(b.x, b.y), b.mask, true, pixels, colors);
                    }
                },
            );
        }
        if alpha_to_one {
            for colors in &mut shaded[..n] {
                match colors {
                    BlockColors::Uniform(c) => c[3] = 1.0,
                    BlockColors::Lanes(l) => l[3] = [1.0; super::LANES],
                }
            }
        }
        let samples = band.samples.min(MAX_SAMPLES);
        let mut plane = [BlockEntry::default(); BATCH];
        for s in 0..samples {
            let mut m = 0;
            for b in blocks.iter().filter(|b| b.samples[s] != 0) {
                plane[m.min(BATCH - 1)] = BlockEntry { x: b.x, y: b.y, mask: b.samples[s], source: 0 };
                m += 1;
            }
            if m == 0 {
                continue;
            }
            let grid = grid.sample(s);
            if m == n {
                self.color_stage(level, state, band, scratch, grid, &run, &plane[..m], Some(&shaded[..m]), true);
            } else {
                // Some blocks lack sample s (edge blocks): the others' colours, in order.
                let mut colors = [BlockColors::Uniform([0.0; 4]); BATCH];
                let mut j = 0;
                for (b, c) in blocks.iter().zip(shaded.iter()) {
                    if b.samples[s] != 0 {
                        colors[j.min(BATCH - 1)] = *c;
                        j += 1;
                    }
                }
                self.color_stage(level, state, band, scratch, grid, &run, &plane[..m], Some(&colors[..m]), true);
            }
        }
    }
}

/// The pipeline up to the target writes with the alpha test, block by block, compiled once
/// per SIMD level (the span path's order): the colours of the pixels with a covered
/// sample, the alpha test (a failing pixel loses every sample), then per sample the
/// stencil and depth tests, and the occlusion count. When a failing fragment changes
/// nothing, a read-only test first drops blocks none of whose samples can pass (no colours
/// computed for them). Keeps in `blocks`, in order, the blocks with a surviving sample
/// (their masks the pixels with one) and their colours in `shaded`; returns how many.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn alpha_sample_blocks<I: SampleInputs>(
    pipeline: &BlockPipeline,
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    grid: Grid,
    inputs: &I,
    front_facing: bool,
    blocks: &mut [SampleEntry],
    shaded: &mut [BlockColors; BATCH],
) -> usize {
    let Some(alpha) = &pipeline.alpha else { return 0 };
    let samples = band.samples.min(MAX_SAMPLES);
    let fragment = &state.fragment;
    let mut kept = 0;
    let mut passed = 0u32;
    for i in 0..blocks.len() {
        let mut b = blocks[i];
        let (x, y) = (b.x, b.y);
        if let Some(kernel) = pipeline.depth_stencil.as_ref().filter(|k| k.culls_before_alpha()) {
            let mut any = 0;
            for s in (0..samples).filter(|&s| b.samples[s] != 0) {
                let at = grid.sample(s).at(x, y);
                any |= kernel.test(&mut band.depth, &at, b.samples[s], front_facing, || inputs.sample_z(x, y, s));
                if any != 0 {
                    break;
                }
            }
            if any == 0 {
                continue;
            }
        }
        let at = grid.at(x, y);
        let colors = &mut shaded[kept.min(BATCH - 1)];
        block_colors(fragment, scratch, &at, b.mask, true, inputs, colors);
        let live = match colors {
            BlockColors::Uniform(c) => alpha.test(grid.level, &[c[3]; super::LANES], b.mask),
            BlockColors::Lanes(l) => alpha.test(grid.level, &l[3], b.mask),
        };
        if live == 0 {
            continue;
        }
        let mut mask = 0;
        for s in 0..samples {
            let mut m = b.samples[s] & live;
            if m != 0 {
                if let Some(kernel) = &pipeline.depth_stencil {
                    let at = grid.sample(s).at(x, y);
                    m = kernel.run(&mut band.depth, &at, m, front_facing, || inputs.sample_z(x, y, s));
                }
            }
            b.samples[s] = m;
            mask |= m;
            passed += m.count_ones();
        }
        if mask == 0 {
            continue;
        }
        blocks[kept] = SampleEntry { mask, ..b };
        kept += 1;
    }
    if let Some(counter) = &state.samples_passed {
        counter.fetch_add(u64::from(passed), Ordering::Relaxed);
    }
    kept
}
