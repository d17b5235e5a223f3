//! Per-sample coverage of a filled triangle's 4×4 blocks on a multisampled target: for
//! each block the walk ([`super::blocks`]) finds, one 16-bit mask per sample (bit `i`:
//! pixel `(x + (i & 3), y + (i >> 2))` covers that sample).
//!
//! A sample at `(ox, oy)` (1/256 pixel from the pixel's lower-left corner) is covered when
//! every edge function, moved from the pixel centre to the sample, is non-negative:
//! `E_s(x, y) = E(x, y) + (a/256)·(ox − 128) + (b/256)·(oy − 128)`, `E` the setup's pixel
//! edge (centre, fill-rule bias and all; `a` and `b` are multiples of 256). That is the test
//! `TriangleSetup::row_span_at` solves per row for the span path, so both give the same
//! samples. The walk itself runs unchanged on the *widened* edges (each edge moved to the
//! sample where it is largest), whose pixels are every pixel with a sample that may be
//! covered; each block it emits then gets its exact per-sample masks here, with a shortcut
//! for blocks every sample of which lies inside all three edges (the inside of a large
//! triangle: no per-sample work). Values are i64 (exact within the guard band, as the
//! setup's edges). Kept apart from the walker (which is the single-sample path's and knows
//! nothing of samples); `#[inline(always)]` like it, so it compiles into the caller's copy
//! per SIMD level.

use super::blocks::PixelEdge;

/// The most samples per pixel ([`crate::framebuffer::multisample::MAX_SAMPLES`]).
const MAX: usize = crate::framebuffer::multisample::MAX_SAMPLES;

/// A triangle's three edges at each sample position of its target.
#[derive(Clone, Copy, Debug)]
pub struct SampleEdges {
    edges: [PixelEdge; 3],
    /// Each edge's move from the pixel centre to sample `s`.
    shifts: [[i64; MAX]; 3],
    samples: usize,
    /// Each edge's smallest value over a 4×4 block relative to its corner, plus its
    /// smallest shift: a block whose corner value plus this is ≥ 0 on every edge has every
    /// sample of every pixel inside.
    inside: [i64; 3],
    /// Each edge's steps `a·column + b·row` over the 16 lanes.
    steps: [[i64; 16]; 3],
}

impl SampleEdges {
    /// The pixel `edges` (`TriangleSetup::pixel_edges`) at the sample `offsets` (1/256
    /// pixel from the lower-left corner, at most 8).
    pub fn new(edges: &[PixelEdge; 3], offsets: impl IntoIterator<Item = [i64; 2]>) -> Self {
        let mut shifts = [[0i64; MAX]; 3];
        let mut samples = 0;
        for (s, [ox, oy]) in offsets.into_iter().take(MAX).enumerate() {
            for (k, e) in edges.iter().enumerate() {
                shifts[k][s] = (e.a >> 8) * (ox - 128) + (e.b >> 8) * (oy - 128);
            }
            samples = s + 1;
        }
        let inside = std::array::from_fn(|k| {
            let e = &edges[k];
            let least = shifts[k][..samples].iter().copied().min().unwrap_or(0);
            3 * (e.a.min(0) + e.b.min(0)) + least
        });
        let steps = std::array::from_fn(|k| {
            let e = &edges[k];
            std::array::from_fn(|i| e.a * (i & 3) as i64 + e.b * (i >> 2) as i64)
        });
        SampleEdges { edges: *edges, shifts, samples, inside, steps }
    }

    /// The edges moved to the sample where each is largest: a pixel is inside all three
    /// when any of its samples may be covered (the walk's edges).
    pub fn widened(&self) -> [PixelEdge; 3] {
        std::array::from_fn(|k| {
            let most = self.shifts[k][..self.samples].iter().copied().max().unwrap_or(0);
            PixelEdge { c: self.edges[k].c + most, ..self.edges[k] }
        })
    }

    /// The per-sample masks of the block at `(x, y)` within `pixels` (the pixels the walk
    /// of the widened edges emitted, cut to its area and stipple); samples past the
    /// target's count are 0.
    #[inline(always)]
    pub fn masks(&self, x: i32, y: i32, pixels: u16) -> [u16; MAX] {
        let corner: [i64; 3] = std::array::from_fn(|k| {
            let e = &self.edges[k];
            e.c + e.a * x as i64 + e.b * y as i64
        });
        let mut out = [0u16; MAX];
        if (0..3).all(|k| corner[k] + self.inside[k] >= 0) {
            out[..self.samples].fill(pixels);
            return out;
        }
        for (s, o) in out.iter_mut().enumerate().take(self.samples) {
            let mut outside = 0u16;
            for ((c, shifts), steps) in corner.iter().zip(&self.shifts).zip(&self.steps) {
                let base = c + shifts[s];
                for (i, step) in steps.iter().enumerate() {
                    outside |= (((base + step) as u64 >> 63) as u16) << i;
                }
            }
            *o = pixels & !outside;
        }
        out
    }
}
