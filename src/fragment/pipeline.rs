//! The fragment pipeline of one covered span, from coverage to the framebuffer write, in
//! GL's stage order, written once for every primitive and for both single-sampled and
//! multisampled targets.
//!
//! The stages (GL 2.1 chapter 4.1, with texturing, the color sum and fog of §3.8–§3.11 in
//! front): the fragment colors (the draw's fragment program: texturing, the color sum and
//! fog, [`super::shading`]), the primitive's coverage for smooth primitives,
//! alpha-to-coverage, the alpha test, the stencil and depth tests, the occlusion query
//! count, alpha-to-one, then per color target blending or the logic op, dither and the
//! masked write. Colors are computed before the tests only when a stage before them needs
//! alpha (fog and the color sum change no alpha, so running them before the alpha test
//! changes nothing); a draw without a program does no shading work.
//!
//! What differs between a single-sampled and a multisampled target is only where a span's
//! coverage and depth live: one live mask per span ([`PixelMask`]) or one per sample
//! ([`SampleCoverage`](super::multisample::SampleCoverage)). The driver, [`shade`], is
//! generic over that [`Footprint`], so each target kind gets its own monomorphised copy and
//! nothing is decided per pixel; the single-sampled copy compiles as if the multisample
//! stages did not exist.

use super::multisample::{MultisampleState, SampleCoverage, SampleMasks};
use super::output::write_target;
use super::{stencil_depth_test, write_colors, write_uniform_color, FragmentState, MAX_SPAN};
use crate::framebuffer::band::Band;
use crate::framebuffer::multisample::MAX_SAMPLES;
use crate::framebuffer::Rect;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// What a draw call's primitives share: the compiled fragment state, the scissor box and
/// the rest of the state snapshot every stage below the draw reads. Compared whole when a
/// scene caches states (`setup::Scene::add_state`). It lives here, in the lowest room
/// that reads it; setup and raster read its clip rectangles and stipple.
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
    pub multisample: Option<MultisampleState>,
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

/// Per-worker storage reused across spans.
#[derive(Default)]
pub struct Scratch {
    pub z: Vec<f32>,
    pub colors: Vec<[f32; 4]>,
    /// The fragment program's registers and lanes.
    pub shading: super::shading::ShadingScratch,
    /// A GLSL fragment shader's registers and lanes, and the depths it gives a span.
    pub glsl: super::glsl_shading::GlslScratch,
    pub depth: Vec<f32>,
    /// The depths a GLSL shader gave the block shaded last.
    pub block_depth: super::block::F32s,
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

/// How much of each pixel of a span a primitive covers, multiplied into the fragments'
/// alpha after texturing (GL 2.1 §3.12): [`FullCoverage`] for aliased primitives (no work
/// at all: the choice is made per primitive type, at compile time), a slice of per-pixel
/// coverages for smooth ones.
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

/// Where a span's coverage and depth live: the one thing the driver [`shade`] is
/// parameterised by. Bit `i` of a mask is pixel `x0 + i` of the span.
pub trait Footprint {
    /// Whether this is the multisampled footprint (a compile-time constant, so the
    /// single-sampled driver has no multisample code in it).
    const MULTISAMPLE: bool;
    /// The pixels with anything covered.
    fn live(&self) -> u64;
    /// Whether alpha-to-coverage narrows the coverage (then alpha is needed before the tests).
    fn alpha_to_coverage(&self) -> bool;
    /// Alpha-to-coverage: narrows each pixel of `live` to the samples its alpha keeps.
    fn narrow_by_alpha(&mut self, live: u64, alpha: impl Fn(usize) -> f32);
    /// Keeps only the pixels of `live` (after the alpha test).
    fn keep(&mut self, live: u64);
    /// Calls `test(band, sample, sample_span, mask)` for each covered sample's mask, where
    /// `sample_span` is `span` placed in that sample's storage (its `row_start`).
    fn each_sample(
        &mut self,
        band: &mut Band<'_>,
        span: &Span,
        test: impl FnMut(&mut Band<'_>, usize, &Span, &mut u64),
    );
    /// How many samples (GL_SAMPLES_PASSED's unit) of `live` pass.
    fn passed(&self, live: u64) -> u64;
    /// Whether alpha-to-one sets the fragments' alpha to one before blending.
    fn alpha_to_one(&self) -> bool;
}

/// A single-sampled span's coverage: one bit per pixel.
#[derive(Clone, Copy, Debug)]
pub struct PixelMask(pub u64);

impl Footprint for PixelMask {
    const MULTISAMPLE: bool = false;
    #[inline(always)]
    fn live(&self) -> u64 {
        self.0
    }
    #[inline(always)]
    fn alpha_to_coverage(&self) -> bool {
        false
    }
    #[inline(always)]
    fn narrow_by_alpha(&mut self, _: u64, _: impl Fn(usize) -> f32) {}
    #[inline(always)]
    fn keep(&mut self, live: u64) {
        self.0 = live;
    }
    #[inline(always)]
    fn each_sample(
        &mut self,
        band: &mut Band<'_>,
        span: &Span,
        mut test: impl FnMut(&mut Band<'_>, usize, &Span, &mut u64),
    ) {
        test(band, 0, span, &mut self.0);
    }
    #[inline(always)]
    fn passed(&self, live: u64) -> u64 {
        live.count_ones() as u64
    }
    #[inline(always)]
    fn alpha_to_one(&self) -> bool {
        false
    }
}

/// Runs the fragment pipeline (see the module) on the fragments of `live` of one span of an
/// aliased primitive. `z_at(i)` is pixel i's window depth; `colors` fills `scratch.colors`
/// with the span's colors, or returns the one color of a flat span; `varyings(dx, dy, out)`
/// gives the varyings of the pixel `dx` columns right of the span's first and `dy` rows
/// above it, read for texturing (which also reads the pixel's 2×2 quad neighbours), the
/// color sum and fog.
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

/// [`shade_span`] with the primitive's `coverage` multiplied into the alpha of its
/// fragments. On a multisampled band (a primitive rasterized at pixel centres: pixel
/// rectangles, smooth primitives, anything while GL_MULTISAMPLE is off, §3.2.1) every
/// sample of a covered pixel is covered, at the pixel's depth.
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn shade_covered_span(
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    span: Span,
    live: u64,
    z_at: impl Fn(usize) -> f32,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: impl Fn(i32, i32, &mut [f32]),
    coverage: impl Coverage,
) {
    if band.samples > 1 {
        return shade_span_all_samples(state, band, scratch, span, live, z_at, colors, varyings);
    }
    shade(state, band, scratch, span, PixelMask(live), |i, _| z_at(i), colors, varyings, coverage);
}

/// [`shade_covered_span`] on a multisampled band: every sample of a covered pixel. Never
/// inlined: it must not change how the single-sample path around its call compiles. (The
/// primitive's smooth coverage is not applied here: a multisampled target has always
/// ignored it, as before this driver was shared.)
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn shade_span_all_samples(
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    span: Span,
    live: u64,
    z_at: impl Fn(usize) -> f32,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: impl Fn(i32, i32, &mut [f32]),
) {
    let masks = [live; MAX_SAMPLES];
    shade_span_samples(state, band, scratch, span, masks, |i, _| z_at(i), colors, varyings);
}

/// Runs the fragment pipeline on one span of a multisampled band rasterized per sample:
/// `masks[s]` bit i is pixel i's sample s, `z_at(i, s)` the window depth of pixel i at
/// sample s; `colors` and `varyings` are as for [`shade_span`], evaluated at pixel centres
/// (once per pixel, as llvmpipe does).
#[allow(clippy::too_many_arguments)]
pub fn shade_span_samples(
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    span: Span,
    masks: SampleMasks,
    z_at: impl Fn(usize, usize) -> f32,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: impl Fn(i32, i32, &mut [f32]),
) {
    let footprint = SampleCoverage::new(masks, band.samples, state.multisample);
    shade(state, band, scratch, span, footprint, z_at, colors, varyings, FullCoverage);
}

/// The fragment pipeline, in GL's order (see the module), over any [`Footprint`].
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn shade<F: Footprint>(
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    span: Span,
    mut footprint: F,
    z_at: impl Fn(usize, usize) -> f32,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: impl Fn(i32, i32, &mut [f32]),
    coverage: impl Coverage,
) {
    let fragment = &state.fragment;
    let mut live = footprint.live();
    // Single-sampled callers never pass an empty span; GL_SAMPLE_COVERAGE may empty one.
    if F::MULTISAMPLE && live == 0 {
        return;
    }
    let mut colors = Some(colors);
    let mut uniform = None;
    let alpha_to_coverage = footprint.alpha_to_coverage();
    // A GLSL shader that may discard or writes the depth runs before the tests.
    let late = fragment.late_tests();
    let shader_depth = late && fragment.glsl.as_ref().is_some_and(|g| g.writes_depth());
    if fragment.alpha.is_some() || alpha_to_coverage || late {
        if let Some(c) = colors.take() {
            let kept;
            (uniform, kept) = shade_colors(fragment, &span, scratch, live, c, &varyings, &z_at);
            uniform = coverage.apply(&mut scratch.colors, uniform, span.n);
            if kept != live {
                live = kept;
                footprint.keep(live);
                if live == 0 {
                    return;
                }
            }
        }
        if alpha_to_coverage {
            let colors = &scratch.colors;
            footprint.narrow_by_alpha(live, |i| uniform.map_or_else(|| colors[i][3], |c| c[3]));
            live = footprint.live();
            if live == 0 {
                return;
            }
        }
        if let Some(alpha) = &fragment.alpha {
            live = match uniform {
                Some(c) if alpha.passes_one(c[3]) => live,
                Some(_) => 0,
                None => alpha.test(&scratch.colors, live),
            };
            footprint.keep(live);
            if live == 0 {
                return;
            }
        }
    }
    if fragment.depth.is_some() || fragment.stencil.is_some() {
        let face = fragment.stencil.as_ref().map(|s| if span.front_facing { &s.front } else { &s.back });
        footprint.each_sample(band, &span, |band, s, at, mask| {
            scratch.z.clear();
            if fragment.depth.is_some() && shader_depth {
                scratch.z.extend_from_slice(&scratch.depth[..span.n]);
            } else if fragment.depth.is_some() {
                scratch.z.extend((0..span.n).map(|i| z_at(i, s)));
                // The multisampled path has never clamped (kept as it was; see the report
                // of the stages restructuring).
                if let (Some([min, max]), false) = (fragment.depth_clamp, F::MULTISAMPLE) {
                    for z in &mut scratch.z {
                        *z = z.clamp(min, max);
                    }
                }
            }
            *mask = stencil_depth_test(
                face,
                fragment.depth.as_ref(),
                &mut band.depth,
                at.row_start,
                span.n,
                &scratch.z,
                *mask,
            );
        });
        live = footprint.live();
        if live == 0 {
            return;
        }
    }
    if let Some(counter) = &state.samples_passed {
        // GL_SAMPLES_PASSED counts samples on a multisampled target (§4.1.7).
        counter.fetch_add(footprint.passed(live), Ordering::Relaxed);
    }
    if let Some(c) = colors {
        (uniform, _) = shade_colors(fragment, &span, scratch, live, c, &varyings, &z_at);
        uniform = coverage.apply(&mut scratch.colors, uniform, span.n);
    }
    if footprint.alpha_to_one() {
        match uniform.as_mut() {
            Some(c) => c[3] = 1.0,
            None => scratch.colors.iter_mut().for_each(|c| c[3] = 1.0),
        }
    }
    let colors = &scratch.colors;
    if let Some(glsl) = fragment.glsl.as_deref().filter(|g| g.writes_data()) {
        let data = &scratch.glsl;
        footprint.each_sample(band, &span, |band, _, at, mask| {
            write_span_data(fragment, glsl, data, band, at, colors, *mask)
        });
        return;
    }
    footprint.each_sample(band, &span, |band, _, at, mask| match uniform {
        Some(color) => write_span_uniform(fragment, band, at, color, *mask),
        None => write_span_colors(fragment, band, at, colors, *mask),
    });
}

/// As [`write_span_colors`] for a GLSL shader that writes `gl_FragData[n]`: each colour
/// target takes the colours of its draw buffer ([`GlslShading::target_colors`]).
///
/// [`GlslShading::target_colors`]: super::glsl_shading::GlslShading::target_colors
#[inline(never)]
fn write_span_data(
    fragment: &FragmentState,
    glsl: &super::glsl_shading::GlslShading,
    data: &super::glsl_shading::GlslScratch,
    band: &mut Band<'_>,
    span: &Span,
    colors: &[[f32; 4]],
    live: u64,
) {
    for (index, (target, mask)) in band.colors.iter_mut().zip(&fragment.color_masks).enumerate() {
        let Some(mask) = *mask else { continue };
        let colors = glsl.target_colors(data, index, colors);
        if fragment.target_has_ops(index) {
            let ops = fragment.target_ops(index, mask);
            write_target(&mut target.pixels, span.row_start, span.x0, span.y, colors, live, &ops);
        } else {
            write_colors(&mut target.pixels, span.row_start, colors, live, mask, fragment.clamp_float);
        }
    }
}

/// The colors of a span's fragments: the interpolated (or flat) colors, then the draw's
/// fragment program (texturing, color sum, fog: [`super::shading::Shading::run_span`]) when
/// it has one (then never uniform), or the GLSL fragment shader in use
/// ([`super::glsl_shading::GlslShading::run_span`]: its depths then in `scratch.depth`).
/// Returns the colours' uniform colour and the fragments of `live` that survive (a shader
/// may discard). Always inlined, as [`write_span_colors`].
#[inline(always)]
fn shade_colors(
    fragment: &FragmentState,
    span: &Span,
    scratch: &mut Scratch,
    live: u64,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: &impl Fn(i32, i32, &mut [f32]),
    z_at: &impl Fn(usize, usize) -> f32,
) -> (Option<[f32; 4]>, u64) {
    scratch.colors.clear();
    let uniform = colors(&mut scratch.colors);
    if let Some(glsl) = &fragment.glsl {
        return (None, shade_glsl(glsl, span, scratch, live, uniform, varyings, z_at));
    }
    let Some(shading) = &fragment.shading else {
        return (uniform, live);
    };
    if let Some(color) = uniform {
        scratch.colors.resize(span.n, color);
    }
    let texturing = fragment.texturing.as_deref();
    shading.run_span(&mut scratch.shading, texturing, span.x0, span.y, live, &mut scratch.colors, varyings);
    (None, live)
}

/// [`shade_colors`] with a GLSL fragment shader: its colours in `scratch.colors`, its
/// depths in `scratch.depth`; returns the fragments of `live` that did not discard.
#[inline(never)]
fn shade_glsl(
    glsl: &super::glsl_shading::GlslShading,
    span: &Span,
    scratch: &mut Scratch,
    live: u64,
    uniform: Option<[f32; 4]>,
    varyings: &impl Fn(i32, i32, &mut [f32]),
    z_at: &impl Fn(usize, usize) -> f32,
) -> u64 {
    if let Some(color) = uniform {
        scratch.colors.resize(span.n, color);
    }
    scratch.depth.clear();
    scratch.depth.extend((0..span.n).map(|i| z_at(i, 0)));
    let Scratch { glsl: glsl_scratch, colors, depth, .. } = scratch;
    glsl.run_span(glsl_scratch, span.x0, span.y, live, span.front_facing, colors, depth, varyings)
}

/// Writes a shaded span (`colors[i]` for every bit `i` of `live`) to every color target the
/// draw writes, blending, logic-opping and dithering where the draw says so.
// Always inlined into the driver, as it was before the driver was shared between the
// single- and multisampled paths (two call sites made LLVM outline it: 2–7% more instructions).
#[inline(always)]
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

/// As [`write_span_colors`] for a span of one color (flat shading).
// Always inlined into the driver, as it was before the driver was shared between the
// single- and multisampled paths (two call sites made LLVM outline it: 2–7% more instructions).
#[inline(always)]
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fragment::{span_mask, AlphaTest, DepthTest};
    use crate::framebuffer::band::{ColorBand, ColorTarget, DepthBand};
    use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat};
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
            hiz: Default::default(),
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
}
