//! Coverage walking: from a primitive's covered columns per row (at the pixel centres, at
//! each sample position, or as per-pixel coverage values) to spans of at most
//! [`MAX_SPAN`] pixels with their live masks, handed to a shading callback in row order.
//!
//! The walkers know nothing of primitive types: a primitive describes its coverage by a
//! closure (its exact row solve lives in `setup`), and the callback runs the fragment
//! pipeline on each span. Polygon stipple, a coverage mask over window positions, is here
//! too.

use crate::fragment::multisample::SampleMasks;
use crate::fragment::{span_mask, MAX_SPAN};
use crate::framebuffer::multisample::MAX_SAMPLES;
use crate::framebuffer::Rect;

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

/// Walks the rows of `area` for a primitive covering, in row `y`, the pixels
/// `row_span_at(y, offset, x0, x1)` (clipped to `[x0, x1)`) at each of the sample
/// `offsets`: calls `shade(y, x0, x1, masks)` for runs of at most [`MAX_SPAN`] pixels
/// holding covered samples (`masks[s]` bit i: pixel `x0 + i` covers sample s).
pub fn walk_sample_spans<O>(
    area: Rect,
    offsets: &[O],
    row_span_at: impl Fn(i32, &O, i32, i32) -> Option<(i32, i32)>,
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

/// Calls `shade(y, x0, n, live, coverage)` for every piece (at most [`MAX_SPAN`] pixels) of
/// every row of `area` with a covered pixel; `coverage(x, y)` is pixel (x, y)'s coverage
/// (smooth primitives: a fraction of the pixel), `columns(y)` the columns of row `y` that
/// may be covered.
#[inline]
pub fn walk_covered(
    area: Rect,
    columns: impl Fn(i32) -> Option<(i32, i32)>,
    coverage: impl Fn(i32, i32) -> f32,
    mut shade: impl FnMut(i32, i32, usize, u64, &[f32]),
) {
    let mut values = [0.0f32; MAX_SPAN];
    for y in area.y0..area.y1 {
        let Some((first, end)) = columns(y) else { continue };
        let (mut x0, x1) = (first.max(area.x0), end.min(area.x1));
        while x0 < x1 {
            let n = ((x1 - x0) as usize).min(MAX_SPAN);
            let mut live = 0u64;
            for (i, value) in values[..n].iter_mut().enumerate() {
                *value = coverage(x0 + i as i32, y);
                if *value > 0.0 {
                    live |= 1 << i;
                }
            }
            if live != 0 {
                shade(y, x0, n, live, &values[..n]);
            }
            x0 += n as i32;
        }
    }
}

/// The polygon stipple bits of the 64 pixels from `(x0, y)` on: bit `i` for pixel `x0 + i`.
/// The pattern's row `y % 32` holds column `x % 32` in bit `31 − x % 32` (§3.6.2).
#[inline]
pub fn stipple_mask(pattern: &[u32; 32], x0: i32, y: i32) -> u64 {
    let row = pattern[y.rem_euclid(32) as usize];
    // Rotate column x0 into bit 31, then reverse so that it lands in bit 0.
    let bits = row.rotate_left(x0.rem_euclid(32) as u32).reverse_bits() as u64;
    bits | bits << 32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stipple_mask_reads_bit_31_as_the_leftmost_column() {
        let mut pattern = [0u32; 32];
        pattern[3] = 0x8000_0001; // columns 0 and 31 of rows 3, 35, 67, …
        assert_eq!(stipple_mask(&pattern, 0, 3), 1 | 1 << 31 | 1 << 32 | 1 << 63);
        assert_eq!(stipple_mask(&pattern, 31, 35), 1 | 1 << 1 | 1 << 32 | 1 << 33);
        assert_eq!(stipple_mask(&pattern, 5, 4), 0);
        // Negative coordinates wrap like positive ones (x = −1 is column 31).
        assert_eq!(stipple_mask(&pattern, -1, -29) & 3, 3);
    }

    #[test]
    fn spans_are_cut_at_max_span_pixels() {
        let mut seen = Vec::new();
        walk_spans(
            Rect::from_xywh(0, 0, 200, 2),
            |y, _, _| (y == 1).then_some((10, 150)),
            |y, a, b| seen.push((y, a, b)),
        );
        assert_eq!(seen, [(1, 10, 74), (1, 74, 138), (1, 138, 150)]);
    }
}
