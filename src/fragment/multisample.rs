//! The multisample fragment operations and the per-sample coverage the fragment pipeline
//! runs on for a multisampled target: per-sample coverage, depth and stencil, one color per
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
//! fragment operations run unchanged on it. The stage order is the one driver of
//! [`super::pipeline`]; this module supplies its [`Footprint`].

use super::pipeline::{Footprint, Span};
use crate::framebuffer::band::Band;
use crate::framebuffer::multisample::MAX_SAMPLES;

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

/// The [`Footprint`] of a span on a multisampled band: its per-sample masks, narrowed by
/// the draw's multisample operations when GL_MULTISAMPLE is on.
pub struct SampleCoverage {
    masks: SampleMasks,
    samples: usize,
    /// The multisample operations, when enabled.
    ops: Option<MultisampleState>,
}

impl SampleCoverage {
    /// The coverage `masks` of a band of `samples` samples, GL_SAMPLE_COVERAGE's mask applied.
    #[inline]
    pub fn new(mut masks: SampleMasks, samples: usize, state: Option<MultisampleState>) -> Self {
        let samples = samples.min(MAX_SAMPLES);
        let ops = state.filter(|m| m.enabled);
        if let Some(ms) = ops {
            for (s, mask) in masks.iter_mut().enumerate().take(samples) {
                if ms.coverage_mask & (1 << s) == 0 {
                    *mask = 0;
                }
            }
        }
        SampleCoverage { masks, samples, ops }
    }
}

impl Footprint for SampleCoverage {
    const MULTISAMPLE: bool = true;

    #[inline]
    fn live(&self) -> u64 {
        self.masks[..self.samples].iter().fold(0, |a, &m| a | m)
    }

    #[inline]
    fn alpha_to_coverage(&self) -> bool {
        self.ops.is_some_and(|m| m.alpha_to_coverage)
    }

    fn narrow_by_alpha(&mut self, live: u64, alpha: impl Fn(usize) -> f32) {
        let mut keep = [0u64; MAX_SAMPLES];
        let mut bits = live;
        while bits != 0 {
            let i = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            let cover = alpha_coverage(alpha(i), self.samples);
            for (s, k) in keep.iter_mut().enumerate().take(self.samples) {
                if cover & (1 << s) != 0 {
                    *k |= 1 << i;
                }
            }
        }
        for (m, k) in self.masks.iter_mut().zip(keep) {
            *m &= k;
        }
    }

    #[inline]
    fn keep(&mut self, live: u64) {
        for m in &mut self.masks {
            *m &= live;
        }
    }

    #[inline]
    fn each_sample(
        &mut self,
        band: &mut Band<'_>,
        span: &Span,
        mut test: impl FnMut(&mut Band<'_>, usize, &Span, &mut u64),
    ) {
        for (s, mask) in self.masks.iter_mut().enumerate().take(self.samples) {
            if *mask == 0 {
                continue;
            }
            let at = Span { row_start: band.sample_index(span.y, span.x0, s), ..*span };
            test(band, s, &at, mask);
        }
    }

    #[inline]
    fn passed(&self, _: u64) -> u64 {
        self.masks[..self.samples].iter().map(|m| m.count_ones() as u64).sum()
    }

    #[inline]
    fn alpha_to_one(&self) -> bool {
        self.ops.is_some_and(|m| m.alpha_to_one)
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
