//! Rendering into multisampled bands: per-sample coverage, depth and stencil, one color per
//! pixel.
//!
//! A span here carries one coverage mask per sample (bit `i`: pixel `x0 + i` covers that
//! sample). The fragment color (texturing, color sum, fog) is computed once per pixel, at
//! the pixel centre as llvmpipe does, for the pixels with any covered sample; the multisample
//! fragment operations (GL 2.1 §4.1.3: GL_SAMPLE_COVERAGE, GL_SAMPLE_ALPHA_TO_COVERAGE,
//! GL_SAMPLE_ALPHA_TO_ONE) narrow the masks; then each sample runs the stencil and depth
//! tests with its own depth (interpolated at the sample) and, where it survives, blends and
//! writes the pixel's color into that sample. Each sample of a span is a span of consecutive
//! pixels in its own storage row (`framebuffer::multisample`), so the single-sample
//! fragment operations run unchanged on it.
//!
//! Triangles, lines (their rectangles) and points (their squares) are rasterized per sample
//! ([`walk_sample_spans`]). Primitives without a per-sample rasterization (pixel
//! rectangles, smooth lines, and everything while GL_MULTISAMPLE is disabled,
//! GL 2.1 §3.2.1) reach a multisampled band through the
//! ordinary [`super::shade_span`], which covers every sample of the pixels whose centre is
//! covered ([`shade_span_all_samples`]).
use super::triangle::{stipple_mask, TriangleJob};
use super::{shade_colors, span_mask, write_span_colors, write_span_uniform, Band, DrawState, Scratch, Span};
use crate::fragment::{stencil_depth_test, MAX_SPAN};
use crate::framebuffer::multisample::MAX_SAMPLES;
use crate::framebuffer::Rect;
use crate::setup::multisample::{sample_offsets, SampleOffset};
use std::sync::atomic::Ordering;

/// The multisample state of a draw into a multisampled framebuffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MultisampleState {
    /// Samples per pixel of the target.
    pub samples: u8,
    /// GL_MULTISAMPLE: rasterize per sample and apply the operations below; when false,
    /// primitives are rasterized at pixel centres and cover every sample (§3.2.1).
    pub enabled: bool,
    pub alpha_to_coverage: bool,
    pub alpha_to_one: bool,
    /// The samples GL_SAMPLE_COVERAGE keeps (bit s: sample s); all ones when disabled.
    pub coverage_mask: u8,
}

impl MultisampleState {
    /// Whether a triangle of this draw is rasterized per sample.
    pub fn per_sample(&self) -> bool {
        self.enabled && self.samples > 1
    }
}

/// The sample mask glSampleCoverage(value, invert) gives for `samples` samples: the first
/// ⌊value · samples⌋ samples (value clamped to [0, 1]), complemented when inverted, as
/// Mesa's state tracker computes it. GL leaves which samples to the implementation; a
/// prefix makes `value` 0.5 and its inverse complementary, as §4.1.3 asks.
pub fn sample_coverage_mask(value: f32, invert: bool, samples: usize) -> u8 {
    let all = ((1u32 << samples) - 1) as u8;
    let count = (value.clamp(0.0, 1.0) * samples as f32) as u32;
    let mask = ((1u32 << count) - 1) as u8;
    if invert {
        !mask & all
    } else {
        mask
    }
}

/// The samples alpha-to-coverage keeps for a fragment of alpha `alpha`: sample s iff
/// alpha > s / samples (as llvmpipe; NaN keeps none).
#[inline]
fn alpha_coverage(alpha: f32, samples: usize) -> u8 {
    let step = 1.0 / samples as f32;
    (0..samples).filter(|&s| alpha > step * s as f32).fold(0u8, |m, s| m | 1 << s)
}

/// A span's per-sample coverage: `masks[s]` bit i is pixel i's sample s.
pub type SampleMasks = [u64; MAX_SAMPLES];

/// [`super::shade_span`] on a multisampled band for a primitive rasterized at pixel
/// centres: every sample of a covered pixel is covered, at the pixel's depth. Never inlined:
/// it must not change how the single-sample path around its call compiles.
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub fn shade_span_all_samples(
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

/// Runs the fragment operations on one span of a multisampled band (see the module). `z_at(i,
/// s)` is the window depth of pixel i at sample s; `colors` and `varyings` are as for
/// [`super::shade_span`], evaluated at pixel centres.
#[allow(clippy::too_many_arguments)]
pub fn shade_span_samples(
    state: &DrawState,
    band: &mut Band<'_>,
    scratch: &mut Scratch,
    span: Span,
    mut masks: SampleMasks,
    z_at: impl Fn(usize, usize) -> f32,
    colors: impl FnOnce(&mut Vec<[f32; 4]>) -> Option<[f32; 4]>,
    varyings: impl Fn(i32, i32, &mut [f32]),
) {
    let samples = band.samples.min(MAX_SAMPLES);
    let fragment = &state.fragment;
    let ops = state.multisample.filter(|m| m.enabled);
    if let Some(ms) = ops {
        for (s, mask) in masks.iter_mut().enumerate().take(samples) {
            if ms.coverage_mask & (1 << s) == 0 {
                *mask = 0;
            }
        }
    }
    let mut live = masks[..samples].iter().fold(0, |a, &m| a | m);
    if live == 0 {
        return;
    }
    let alpha_to_coverage = ops.is_some_and(|m| m.alpha_to_coverage);
    let mut colors = Some(colors);
    let mut uniform = None;
    if fragment.alpha.is_some() || alpha_to_coverage {
        if let Some(c) = colors.take() {
            uniform = shade_colors(fragment, &span, scratch, live, c, &varyings);
        }
        if alpha_to_coverage {
            let mut keep = [0u64; MAX_SAMPLES];
            let mut bits = live;
            while bits != 0 {
                let i = bits.trailing_zeros() as usize;
                bits &= bits - 1;
                let alpha = uniform.map_or_else(|| scratch.colors[i][3], |c| c[3]);
                let cover = alpha_coverage(alpha, samples);
                for (s, k) in keep.iter_mut().enumerate().take(samples) {
                    if cover & (1 << s) != 0 {
                        *k |= 1 << i;
                    }
                }
            }
            for (m, k) in masks.iter_mut().zip(keep) {
                *m &= k;
            }
        }
        if let Some(alpha) = &fragment.alpha {
            live = match uniform {
                Some(c) if alpha.passes_one(c[3]) => live,
                Some(_) => 0,
                None => alpha.test(&scratch.colors, live),
            };
            for m in &mut masks {
                *m &= live;
            }
        }
    }
    if fragment.depth.is_some() || fragment.stencil.is_some() {
        let face = fragment.stencil.as_ref().map(|s| if span.front_facing { &s.front } else { &s.back });
        for (s, mask) in masks.iter_mut().enumerate().take(samples) {
            if *mask == 0 {
                continue;
            }
            scratch.z.clear();
            if fragment.depth.is_some() {
                scratch.z.extend((0..span.n).map(|i| z_at(i, s)));
            }
            let row_start = band.sample_index(span.y, span.x0, s);
            *mask = stencil_depth_test(
                face,
                fragment.depth.as_ref(),
                &mut band.depth,
                row_start,
                span.n,
                &scratch.z,
                *mask,
            );
        }
    }
    live = masks[..samples].iter().fold(0, |a, &m| a | m);
    if let Some(counter) = &state.samples_passed {
        // GL_SAMPLES_PASSED counts samples on a multisampled target (§4.1.7).
        let passed: u32 = masks[..samples].iter().map(|m| m.count_ones()).sum();
        counter.fetch_add(passed as u64, Ordering::Relaxed);
    }
    if live == 0 {
        return;
    }
    if let Some(c) = colors {
        uniform = shade_colors(fragment, &span, scratch, live, c, &varyings);
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
    if ops.is_some_and(|m| m.alpha_to_one) {
        match uniform.as_mut() {
            Some(c) => c[3] = 1.0,
            None => scratch.colors.iter_mut().for_each(|c| c[3] = 1.0),
        }
    }
    for (s, &mask) in masks.iter().enumerate().take(samples) {
        if mask == 0 {
            continue;
        }
        let sample_span = Span { row_start: band.sample_index(span.y, span.x0, s), ..span };
        match uniform {
            Some(color) => write_span_uniform(fragment, band, &sample_span, color, mask),
            None => write_span_colors(fragment, band, &sample_span, &scratch.colors, mask),
        }
    }
}

/// Walks the rows of `area` for a primitive covering, in row `y`, the pixels
/// `row_span_at(y, sample, x0, x1)` (clipped to `[x0, x1)`) at each of the `offsets`: calls
/// `shade(y, x0, x1, masks)` for runs of at most [`MAX_SPAN`] pixels holding covered samples.
pub fn walk_sample_spans(
    area: Rect,
    offsets: &[SampleOffset],
    row_span_at: impl Fn(i32, &SampleOffset, i32, i32) -> Option<(i32, i32)>,
    mut shade: impl FnMut(i32, i32, i32, SampleMasks),
) {
    if area.is_empty() {
        return;
    }
    for y in area.y0..area.y1 {
        let mut spans = [(0, 0); MAX_SAMPLES];
        let (mut lo, mut hi) = (i32::MAX, i32::MIN);
        for (span, offset) in spans.iter_mut().zip(offsets) {
            if let Some((a, b)) = row_span_at(y, offset, area.x0, area.x1) {
                *span = (a, b);
                lo = lo.min(a);
                hi = hi.max(b);
            }
        }
        let mut x0 = lo;
        while x0 < hi {
            let x1 = (x0 + MAX_SPAN as i32).min(hi);
            let mut masks = [0u64; MAX_SAMPLES];
            for (mask, &(a, b)) in masks.iter_mut().zip(&spans) {
                let (a, b) = (a.max(x0), b.min(x1));
                if a < b {
                    *mask = span_mask((b - a) as usize) << (a - x0);
                }
            }
            shade(y, x0, x1, masks);
            x0 = x1;
        }
    }
}

/// Sample positions relative to the pixel centre, in pixels (GL's y up).
pub fn sample_shifts(offsets: &[SampleOffset]) -> [[f32; 2]; MAX_SAMPLES] {
    std::array::from_fn(|s| offsets.get(s).map_or([0.0; 2], |o| [o.x as f32 / 256.0 - 0.5, o.y as f32 / 256.0 - 0.5]))
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
mod tests {
    use super::*;

    #[test]
    fn sample_coverage_keeps_a_prefix_and_inverts_to_its_complement() {
        assert_eq!(sample_coverage_mask(1.0, false, 4), 0b1111);
        assert_eq!(sample_coverage_mask(0.5, false, 4), 0b0011);
        assert_eq!(sample_coverage_mask(0.5, true, 4), 0b1100);
        assert_eq!(sample_coverage_mask(0.0, false, 8), 0);
        assert_eq!(sample_coverage_mask(0.0, true, 8), 0xff);
        assert_eq!(sample_coverage_mask(0.3, false, 2), 0);
        assert_eq!(sample_coverage_mask(0.9, false, 4), 0b0111);
        assert_eq!(sample_coverage_mask(7.0, false, 2), 0b11);
    }

    #[test]
    fn alpha_to_coverage_covers_sample_s_above_s_over_n() {
        assert_eq!(alpha_coverage(1.0, 4), 0b1111);
        assert_eq!(alpha_coverage(0.0, 4), 0);
        assert_eq!(alpha_coverage(0.25, 4), 0b0001);
        assert_eq!(alpha_coverage(0.26, 4), 0b0011);
        assert_eq!(alpha_coverage(0.5, 8), 0b1111);
        assert_eq!(alpha_coverage(f32::NAN, 8), 0);
    }
}
