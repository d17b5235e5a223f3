//! The fragment pipeline of one 4×4 block of a filled triangle, over 16 lanes in
//! structure-of-arrays form: GL's stage order as in [`super::pipeline`], with each
//! per-fragment operation a lane kernel chosen once per draw state ([`BlockPipeline`]).
//!
//! Lane `i` of a block at `(x, y)` is pixel `(x + (i & 3), y + (i >> 2))`; a 16-bit mask
//! says which lanes are live. Depth and colours travel as `[f32; 16]` lanes, stored depth
//! and stencil as `[u32; 16]`, unorm8 colour as `[u16; 16]` per channel ([`kernels`]).
//! The stages: colours (and texturing) first only when the alpha test needs alpha; the
//! alpha test; the stencil and depth tests (early, before any colour work, whenever
//! nothing before them can discard; depth clamp included); the occlusion count; colours,
//! texturing, the colour sum and fog only for blocks with a surviving lane; then per colour
//! target its write kernel (blend or logic op, dither, channel masks, the format's store).
//! unorm8 and RGB565 targets blend in exact integers on u16 lanes (`a·b/255` rounded to
//! nearest, the arithmetic of [`super::blend::blend_unorm8`], so the bytes are those of the
//! span path); 16-bit and float targets go through the span path's f32 stages row by row.
//!
//! Texturing and fog keep the span path's code and results: they are called on the
//! block's rows in array-of-structures form (`crate::texture::Texturing::texture_span`,
//! [`super::FragmentState::sum_and_fog`]).
//!
//! Only single-sampled filled triangles outside the exact accuracy mode take this path
//! (`setup::jobs::triangle`); lines, points, smooth primitives, pixel rectangles,
//! multisampled targets and `TESSERA_ACCURACY=exact` keep the span pipeline
//! ([`super::pipeline`]) until they move to blocks.

pub mod kernels;

use super::pipeline::{DrawState, Scratch};
use super::{AlphaTest, FragmentState};
use crate::framebuffer::band::Band;
use crate::framebuffer::{ColorFormat, DepthStencilFormat};
use kernels::{compare_bits, compare_lanes_small, DepthStencilKernel, TargetKernel};
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
/// slices, the band's row length, and which lanes are pixels of the band (all but at the
/// framebuffer's right and top edges).
#[derive(Clone, Copy, Debug)]
pub struct BlockAt {
    pub x: i32,
    pub y: i32,
    pub base: usize,
    pub width: usize,
    pub valid: u16,
}

impl BlockAt {
    /// The block at window `(x, y)` (inside `band`'s rows).
    #[inline]
    pub fn new(band: &Band<'_>, x: i32, y: i32) -> Self {
        let base = (y - band.y0) as usize * band.width + x as usize;
        let (cols, rows) = (band.width as i32 - x, band.y0 + band.rows as i32 - y);
        if cols >= 4 && rows >= 4 {
            // All but the blocks at the framebuffer's right and top edges.
            return BlockAt { x, y, base, width: band.width, valid: 0xffff };
        }
        let col_bits = (1u16 << cols.clamp(0, 4)) - 1;
        let mut valid = 0u16;
        for r in 0..rows.clamp(0, 4) {
            valid |= col_bits << (4 * r);
        }
        BlockAt { x, y, base, width: band.width, valid }
    }

    /// The index of lane `i` in the band's slices.
    #[inline(always)]
    pub fn index(&self, i: usize) -> usize {
        self.base + (i >> 2) * self.width + (i & 3)
    }
}

/// The 16 pixels of a block from a band slice (lanes outside the band read `T::default()`).
#[inline(always)]
pub fn load<T: Copy + Default>(px: &[T], at: &BlockAt) -> [T; LANES] {
    let mut out = [T::default(); LANES];
    if at.valid == 0xffff {
        for r in 0..4 {
            out[4 * r..4 * r + 4].copy_from_slice(&px[at.base + r * at.width..][..4]);
        }
    } else {
        for (i, o) in out.iter_mut().enumerate() {
            if at.valid & (1 << i) != 0 {
                *o = px[at.index(i)];
            }
        }
    }
    out
}

/// Stores the lanes of `mask` (a subset of the valid lanes) into a band slice.
#[inline(always)]
pub fn store<T: Copy>(px: &mut [T], at: &BlockAt, values: &[T; LANES], mask: u16) {
    if at.valid == 0xffff {
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
    } else {
        for (i, v) in values.iter().enumerate() {
            if mask & at.valid & (1 << i) != 0 {
                px[at.index(i)] = *v;
            }
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

    /// The colours of row `r` (lanes 4r..4r+4) as pixels.
    #[inline(always)]
    fn row(&self, r: usize) -> [[f32; 4]; 4] {
        match self {
            BlockColors::Uniform(c) => [*c; 4],
            BlockColors::Lanes(l) => std::array::from_fn(|c| std::array::from_fn(|k| l[k][4 * r + c])),
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
}

/// A draw state compiled for blocks on one framebuffer: the alpha test, the depth/stencil
/// kernel and each colour target's write kernel, chosen once (see [`kernels`]).
pub struct BlockPipeline {
    alpha: Option<AlphaKernel>,
    depth_stencil: Option<DepthStencilKernel>,
    targets: Vec<TargetKernel>,
}

/// The alpha test on lanes (see [`super::alpha`] for the two precisions).
#[derive(Clone, Copy, Debug)]
struct AlphaKernel {
    func: u8,
    unorm8: bool,
    reference8: u32,
    reference: f32,
}

impl AlphaKernel {
    fn new(test: &AlphaTest) -> Self {
        let clamp = |x: f32| if x > 0.0 { x.min(1.0) } else { 0.0 };
        AlphaKernel {
            func: compare_bits(test.func),
            unorm8: test.unorm8,
            reference8: super::alpha::reference_unorm8(test.reference) as u32,
            reference: clamp(test.reference),
        }
    }

    #[inline]
    fn test(&self, alpha: &F32s, live: u16) -> u16 {
        if self.unorm8 {
            let a: U32s = map_lanes(&kernels::unorm8_lanes(alpha), u32::from);
            compare_lanes_small(self.func, &a, &[self.reference8; LANES]) & live
        } else {
            // Clamped to [0, 1] (NaN as 0): the bit patterns of non-negative floats order
            // as their values.
            let a: U32s = lanes(|i| if alpha[i] > 0.0 { alpha[i].min(1.0).to_bits() } else { 0 });
            compare_lanes_small(self.func, &a, &[self.reference.to_bits(); LANES]) & live
        }
    }
}

impl BlockPipeline {
    /// Compiles `fragment` for a single-sampled framebuffer whose band colour targets have
    /// `formats` (in the band's order) and whose depth/stencil layer is `depth_format`.
    pub fn compile(fragment: &FragmentState, formats: &[ColorFormat], depth_format: DepthStencilFormat) -> Self {
        let targets = formats
            .iter()
            .zip(&fragment.color_masks)
            .enumerate()
            .filter_map(|(index, (format, mask))| Some(TargetKernel::new(fragment, index, *format, (*mask)?)))
            .collect();
        BlockPipeline {
            alpha: fragment.alpha.as_ref().map(AlphaKernel::new),
            depth_stencil: DepthStencilKernel::new(fragment, depth_format),
            targets,
        }
    }
}

/// Runs the fragment pipeline (see the module) on the lanes of `mask` of the block at
/// `(x, y)` of a primitive facing front or back (`front_facing`, for two-sided stencil).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn shade_block(
    pipeline: &BlockPipeline,
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    x: i32,
    y: i32,
    mask: u16,
    front_facing: bool,
    inputs: &impl BlockInputs,
) {
    let fragment = &state.fragment;
    let at = BlockAt::new(band, x, y);
    let mut live = mask;
    let mut colors = BlockColors::Uniform([0.0; 4]);
    if let Some(alpha) = &pipeline.alpha {
        shade_colors(fragment, scratch, &at, live, inputs, &mut colors);
        live = match &colors {
            BlockColors::Uniform(c) => alpha.test(&[c[3]; LANES], live),
            BlockColors::Lanes(l) => alpha.test(&l[3], live),
        };
        if live == 0 {
            return;
        }
    }
    if let Some(kernel) = &pipeline.depth_stencil {
        live = kernel.run(&mut band.depth, &at, live, front_facing, || inputs.z(x, y));
        if live == 0 {
            return;
        }
    }
    if let Some(counter) = &state.samples_passed {
        counter.fetch_add(live.count_ones() as u64, Ordering::Relaxed);
    }
    if pipeline.alpha.is_none() {
        shade_colors(fragment, scratch, &at, live, inputs, &mut colors);
    }
    if fragment.needs_varyings() {
        // The colour sum and fog of the span path, once over the block's 16 fragments
        // (fragment i is lane i; its varyings are those of its row's span).
        let mut pixels = [[0f32; 4]; LANES];
        let l = colors.lanes();
        for (i, p) in pixels.iter_mut().enumerate() {
            *p = [l[0][i], l[1][i], l[2][i], l[3][i]];
        }
        let fog_slot = usize::from(fragment.color_sum) * 3;
        scratch.varyings.resize(fog_slot + 1, 0.0);
        fragment.sum_and_fog(&mut pixels, live as u64, &mut scratch.varyings, |i, out| {
            inputs.varyings(x, y + (i >> 2) as i32, (i & 3) as i32, 0, out)
        });
        let mut lanes = [[0f32; LANES]; 4];
        for (i, p) in pixels.iter().enumerate() {
            for k in 0..4 {
                lanes[k][i] = p[k];
            }
        }
        colors = BlockColors::Lanes(lanes);
    }
    for target in &pipeline.targets {
        target.run(&mut band.colors[target.index].pixels, &at, &colors, live);
    }
}

/// The colours of a block's fragments before the tests: interpolated (or flat), textured
/// when the draw textures (row by row through the span path's texturing).
#[inline]
fn shade_colors(
    fragment: &FragmentState,
    scratch: &mut Scratch,
    at: &BlockAt,
    live: u16,
    inputs: &impl BlockInputs,
    colors: &mut BlockColors,
) {
    inputs.colors(at.x, at.y, colors);
    let Some(texturing) = &fragment.texturing else {
        return;
    };
    let mut lanes = colors.lanes();
    for r in 0..4 {
        let row_live = (live >> (4 * r)) as u64 & 0xf;
        if row_live == 0 {
            continue;
        }
        let mut row = colors.row(r);
        let y = at.y + r as i32;
        texturing.texture_span(&mut row, row_live, at.x, y, &mut scratch.texture, |dx, dy, out| {
            inputs.varyings(at.x, y, dx, dy, out)
        });
        for (c, pixel) in row.iter().enumerate() {
            for k in 0..4 {
                lanes[k][4 * r + c] = pixel[k];
            }
        }
    }
    *colors = BlockColors::Lanes(lanes);
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
        };
        let at = BlockAt::new(&band, 4, 0);
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
}
