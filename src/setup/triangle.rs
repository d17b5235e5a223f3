//! Triangle setup in 24.8 fixed point and exact row spans.
//!
//! A vertex snaps to the nearest 1/256 pixel. For an edge from `a` to `b` the edge function
//! at point `p` is `E(p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x)`; after orienting
//! the triangle counter-clockwise every interior point has `E > 0` for all three edges.
//! A centre exactly on an edge belongs to the triangle only if the edge is a left edge or a
//! bottom edge (lowest y, window coordinates growing upwards). That is the top-left rule of
//! a y-down framebuffer seen through GL's y-up window coordinates, and what Mesa's llvmpipe
//! does (measured: a triangle with an edge on pixel centres of row 0 covers row 0). It makes
//! triangles sharing an edge cover every pixel exactly once.

use super::fixed::{div_ceil, div_floor};
use crate::gl::float::round_half_away_f64;

/// Subpixel bits of window coordinates.
pub const SUBPIXEL_BITS: u32 = 8;
/// One pixel in fixed point.
pub const ONE: i64 = 1 << SUBPIXEL_BITS;
const HALF: i64 = ONE / 2;

/// Largest |coordinate| in pixels that setup accepts; larger primitives are clipped before
/// setup (the guard band). With 8 subpixel bits coordinates stay below 2^31 in fixed point
/// and every edge-function product below 2^63.
pub const GUARD_BAND: f32 = (1 << 22) as f32;

/// Snaps a window coordinate to fixed point (round to nearest, half away from zero; the
/// product is exact, and |v| ≤ [`GUARD_BAND`] keeps it below 2³¹).
#[inline]
pub fn to_fixed(v: f32) -> i64 {
    round_half_away_f64(v as f64 * ONE as f64)
}

/// [`to_fixed`] of a coordinate within the guard band (|v| ≤ [`GUARD_BAND`]), in single
/// precision: `v·256` is exact (a power of two, below 2³¹), so are its truncation and the
/// fraction left, which then decides the rounding as [`to_fixed`]'s does, with the same
/// result; without the conversions to and from double precision.
#[inline(always)]
fn snap(v: f32) -> i64 {
    let x = v * ONE as f32;
    let t = x as i32;
    let fraction = x - t as f32;
    (t + (fraction >= 0.5) as i32 - (fraction <= -0.5) as i32) as i64
}

/// The edge from `p` to `q` of a counter-clockwise triangle over pixel centres: `[c, a, b]`
/// with pixel (x, y) inside exactly when `c + a·x + b·y ≥ 0` (see
/// [`TriangleSetup::pixel_edges`]).
///
/// Over fixed-point points the edge function is `E(p) = dx·(p.y − py) − dy·(p.x − px)`
/// (`d = q − p`), positive inside; a point exactly on the edge is inside only on a left or
/// bottom edge (see the module docs). At the centre of pixel (x, y), `(256·x + 128,
/// 256·y + 128)`, that is `E ≥ bias` with `bias` 0 for those edges and 1 otherwise; the
/// centre's half pixel and the bias are folded into `c`.
#[inline(always)]
fn pixel_edge(p: [i64; 2], q: [i64; 2]) -> [i64; 3] {
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    // E(x, y) = a·x + b·y + c over fixed-point coordinates.
    let (a, b, c) = (-dy, dx, dy * p[0] - dx * p[1]);
    // Counter-clockwise with y up: a left edge goes down (dy < 0); a bottom edge is
    // horizontal and goes right (dy == 0, dx > 0).
    let owns_centres = dy < 0 || (dy == 0 && dx > 0);
    let bias = (!owns_centres) as i64;
    [a * HALF + b * HALF + c - bias, a * ONE, b * ONE]
}

/// A set-up triangle: its three edges and its pixel bounding box.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TriangleSetup {
    /// The edges over pixel centres, `[c, a, b]` ([`TriangleSetup::pixel_edges`]), kept in
    /// the form the block walker reads, so that rendering the triangle in a tile computes
    /// nothing of them; the row solves read the same values.
    pixel: [[i64; 3]; 3],
    /// Fixed-point vertices, counter-clockwise (within the guard band they fit in i32:
    /// |v| ≤ 2³⁰; halving their size keeps a triangle's job smaller, and the scene moves
    /// every job through memory).
    pub vertices: [[i32; 2]; 3],
    /// Whether the input was clockwise (reordered to counter-clockwise).
    pub was_clockwise: bool,
    /// Inclusive pixel bounds that may contain covered centres.
    pub min_x: i32,
    pub max_x: i32,
    pub min_y: i32,
    pub max_y: i32,
}

impl TriangleSetup {
    /// Sets up a triangle from window coordinates (within the guard band). Returns `None`
    /// for a degenerate (zero-area) triangle, which covers no pixel, and for one outside the
    /// guard band or with a non-finite coordinate: clipping keeps coordinates inside it
    /// unless the viewport itself lies far outside (glViewport accepts any origin), where
    /// nothing can reach a framebuffer (at most 16384 pixels wide).
    ///
    /// Inlined: it runs for every filled triangle, and as a call its 120-byte result went
    /// through memory and the caller's checks of it.
    #[inline(always)]
    pub fn new(window: [[f32; 2]; 3]) -> Option<TriangleSetup> {
        let [a, b, c] = window.map(Self::snapped);
        Self::from_snapped([a?, b?, c?])
    }

    /// A vertex's window coordinates snapped as [`TriangleSetup::new`] snaps them, `None`
    /// outside the guard band: for the callers that snap each vertex of a strip once and
    /// set up its triangles with [`TriangleSetup::from_snapped`] (the same setups).
    #[inline(always)]
    pub fn snapped(p: [f32; 2]) -> Option<[i64; 2]> {
        (p[0].abs() <= GUARD_BAND && p[1].abs() <= GUARD_BAND).then(|| [snap(p[0]), snap(p[1])])
    }

    /// [`TriangleSetup::new`] from its vertices snapped ([`TriangleSetup::snapped`]).
    #[inline(always)]
    pub fn from_snapped(mut v: [[i64; 2]; 3]) -> Option<TriangleSetup> {
        let area2 = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1]);
        if area2 == 0 {
            return None;
        }
        let was_clockwise = area2 < 0;
        if was_clockwise {
            v.swap(1, 2);
        }
        let pixel = [pixel_edge(v[0], v[1]), pixel_edge(v[1], v[2]), pixel_edge(v[2], v[0])];
        let xs = v.map(|p| p[0]);
        let ys = v.map(|p| p[1]);
        // Pixel x is covered only if its centre x·256+128 lies within [min, max]. Divisions
        // by ONE (a power of two) rounding down are arithmetic shifts, and up, shifts of the
        // negation: `div_floor`/`div_ceil` by ONE, without their division.
        const _: () = assert!(ONE == 1 << SUBPIXEL_BITS);
        let pixel_lo = |m: i64| -((HALF - m) >> SUBPIXEL_BITS) as i32;
        let pixel_hi = |m: i64| ((m - HALF) >> SUBPIXEL_BITS) as i32;
        Some(TriangleSetup {
            pixel,
            vertices: v.map(|p| p.map(|c| c as i32)),
            was_clockwise,
            min_x: pixel_lo(*xs.iter().min().unwrap()),
            max_x: pixel_hi(*xs.iter().max().unwrap()),
            min_y: pixel_lo(*ys.iter().min().unwrap()),
            max_y: pixel_hi(*ys.iter().max().unwrap()),
        })
    }

    /// Whether pixel (x, y)'s centre is covered (reference test, one pixel at a time).
    #[inline]
    pub fn covers(&self, x: i32, y: i32) -> bool {
        self.pixel.iter().all(|&[c, a, b]| c + a * x as i64 + b * y as i64 >= 0)
    }

    /// The covered pixels of row `y` as a half-open range `[x0, x1)` clamped to
    /// `[clip_x0, clip_x1)`, solved exactly from the edge equations; `None` if empty.
    pub fn row_span(&self, y: i32, clip_x0: i32, clip_x1: i32) -> Option<(i32, i32)> {
        let mut lo = clip_x0.max(self.min_x) as i64;
        let mut hi = clip_x1.min(self.max_x + 1) as i64; // exclusive
        for &[c, k, b] in &self.pixel {
            // Inside: c + k·x + b·y ≥ 0  ⇔  k·x ≥ −(c + b·y).
            let rhs = -(c + b * y as i64);
            if k > 0 {
                lo = lo.max(div_ceil(rhs, k));
            } else if k < 0 {
                hi = hi.min(div_floor(rhs, k) + 1);
            } else if rhs > 0 {
                return None;
            }
            if lo >= hi {
                return None;
            }
        }
        Some((lo as i32, hi as i32))
    }

    /// The three edge functions over pixel centres, for the hierarchical block walker
    /// (`raster::blocks`): pixel (x, y) is covered exactly when every
    /// `c + a·x + b·y ≥ 0`, the same test as [`TriangleSetup::covers`] with the centre's
    /// half pixel and the fill rule's bias folded into `c`. Within the guard band every value
    /// at a pixel of a framebuffer (x, y < 2¹⁵) stays below 2⁶³ (see [`GUARD_BAND`]).
    #[inline(always)]
    pub fn pixel_edges(&self) -> [[i64; 3]; 3] {
        self.pixel
    }

    /// The pixel box that may hold covered samples anywhere in a pixel (inclusive min,
    /// exclusive max): `(x0, y0, x1, y1)`.
    pub fn pixel_box(&self) -> (i32, i32, i32, i32) {
        let xs = self.vertices.map(|p| p[0] as i64);
        let ys = self.vertices.map(|p| p[1] as i64);
        let lo = |m: i64| div_floor(m, ONE) as i32;
        let hi = |m: i64| div_floor(m, ONE) as i32 + 1;
        let (min, max) = (|a: [i64; 3]| a[0].min(a[1]).min(a[2]), |a: [i64; 3]| a[0].max(a[1]).max(a[2]));
        (lo(min(xs)), lo(min(ys)), hi(max(xs)), hi(max(ys)))
    }

    /// As [`TriangleSetup::row_span`] for the sample at `(offset_x, offset_y)` (in 1/256
    /// pixel from each pixel's lower-left corner) instead of the centre: the pixels of row
    /// `y` whose sample is covered.
    #[inline]
    pub fn row_span_at(&self, y: i32, offset_x: i64, offset_y: i64, clip_x0: i32, clip_x1: i32) -> Option<(i32, i32)> {
        let (x0, _, x1, _) = self.pixel_box();
        let (lo, hi) = (clip_x0.max(x0) as i64, clip_x1.min(x1) as i64);
        self.solve_row(y as i64 * ONE + offset_y, offset_x, lo, hi)
    }

    /// The pixels `x` in `[lo, hi)` whose point `(x·256 + offset_x, py)` (fixed point) is
    /// inside, solved exactly from the edge equations: [`TriangleSetup::row_span`]'s
    /// computation for any point of the pixel. (`row_span` keeps its own copy with the centre
    /// as constants: sharing this function cost the single-sample path 9 % more
    /// instructions in callgrind on the small-triangle benchmark.)
    #[inline]
    fn solve_row(&self, py: i64, offset_x: i64, mut lo: i64, mut hi: i64) -> Option<(i32, i32)> {
        for &[pc, k, pb] in &self.pixel {
            // The edge over fixed-point points, `a·x + b·y + c ≥ bias` (see `pixel_edge`):
            // `a` and `b` are the pixel edge's divided by ONE (exact: multiples of it), and
            // `c − bias` its `c` without the centre's half pixel.
            let (a, b) = (k >> SUBPIXEL_BITS, pb >> SUBPIXEL_BITS);
            let c_minus_bias = pc - a * HALF - b * HALF;
            // Inside: a·(256·x + ox) + b·py + c ≥ bias  ⇔  256·a·x ≥ bias − a·ox − b·py − c.
            let rhs = -c_minus_bias - a * offset_x - b * py;
            if k > 0 {
                lo = lo.max(div_ceil(rhs, k));
            } else if k < 0 {
                hi = hi.min(div_floor(rhs, k) + 1);
            } else if rhs > 0 {
                return None;
            }
            if lo >= hi {
                return None;
            }
        }
        Some((lo as i32, hi as i32))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pixel in the bounding box: span membership equals the per-pixel test.
    fn assert_spans_match_pixels(t: &TriangleSetup) {
        for y in t.min_y - 1..=t.max_y + 1 {
            let span = t.row_span(y, i32::MIN / 2, i32::MAX / 2);
            for x in t.min_x - 1..=t.max_x + 1 {
                let in_span = span.is_some_and(|(a, b)| a <= x && x < b);
                assert_eq!(in_span, t.covers(x, y), "pixel ({x},{y})");
            }
        }
    }

    /// A tiny deterministic generator (xorshift) for coordinates.
    fn coords(seed: &mut u64, range: f32) -> f32 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        ((*seed >> 11) as f64 / (1u64 << 53) as f64) as f32 * range
    }

    #[test]
    fn spans_equal_the_per_pixel_test() {
        let mut seed = 0x9e3779b97f4a7c15;
        for _ in 0..300 {
            let v = [0, 1, 2].map(|_| [coords(&mut seed, 40.0) - 5.0, coords(&mut seed, 40.0) - 5.0]);
            if let Some(t) = TriangleSetup::new(v) {
                assert_spans_match_pixels(&t);
            }
        }
    }

    #[test]
    fn sample_rows_at_the_centre_are_the_centre_rows() {
        // The row solve at any sample offset, taken at the centre, gives `row_span`'s spans;
        // and a sample a little right of the centre is inside exactly where the edge
        // functions over fixed-point points say.
        let mut seed = 0x51f1_5eed_0bad_cafe;
        for _ in 0..300 {
            let v = [0, 1, 2].map(|_| [coords(&mut seed, 40.0) - 5.0, coords(&mut seed, 40.0) - 5.0]);
            let Some(t) = TriangleSetup::new(v) else { continue };
            for y in t.min_y - 1..=t.max_y + 1 {
                assert_eq!(t.row_span_at(y, HALF, HALF, -100, 100), t.row_span(y, -100, 100));
                let span = t.row_span_at(y, HALF + 37, HALF, -100, 100);
                for x in -10..50 {
                    let (px, py) = (x as i64 * ONE + HALF + 37, y as i64 * ONE + HALF);
                    let inside = (0..3).all(|i| {
                        let (p, q) = (t.vertices[i].map(i64::from), t.vertices[(i + 1) % 3].map(i64::from));
                        let e = (q[0] - p[0]) * (py - p[1]) - (q[1] - p[1]) * (px - p[0]);
                        let owns = q[1] < p[1] || (q[1] == p[1] && q[0] > p[0]);
                        e > 0 || (e == 0 && owns)
                    });
                    assert_eq!(span.is_some_and(|(a, b)| a <= x && x < b), inside, "({x}, {y})");
                }
            }
        }
    }

    #[test]
    fn shared_edges_cover_each_pixel_exactly_once() {
        // A fan around an interior point: every pixel of the enclosing square is covered by
        // exactly one of the triangles, even with centres exactly on shared edges.
        let centre = [8.5, 8.5];
        let ring = [[0.0, 0.0], [16.0, 0.0], [16.0, 16.0], [0.0, 16.0]];
        let mut hits = vec![0u8; 16 * 16];
        for i in 0..4 {
            let t = TriangleSetup::new([centre, ring[i], ring[(i + 1) % 4]]).unwrap();
            for y in 0..16 {
                if let Some((a, b)) = t.row_span(y, 0, 16) {
                    for x in a..b {
                        hits[(y * 16 + x) as usize] += 1;
                    }
                }
            }
        }
        assert!(hits.iter().all(|&h| h == 1), "{hits:?}");
    }

    #[test]
    fn fill_rule_on_a_square_through_pixel_centres() {
        // Two triangles forming the square [0.5, 4.5]² whose edges run through pixel centres:
        // it covers exactly 16 pixels, owning the centres on its left and bottom edges.
        let quad = [[0.5, 0.5], [4.5, 0.5], [4.5, 4.5], [0.5, 4.5]];
        let a = TriangleSetup::new([quad[0], quad[1], quad[2]]).unwrap();
        let b = TriangleSetup::new([quad[0], quad[2], quad[3]]).unwrap();
        let mut covered = Vec::new();
        for y in -1..6 {
            for x in -1..6 {
                let n = a.covers(x, y) as u8 + b.covers(x, y) as u8;
                assert!(n <= 1);
                if n == 1 {
                    covered.push((x, y));
                }
            }
        }
        // The left edge (x = 0.5) and the bottom edge (y = 0.5) are in; right and top out.
        let expected: Vec<_> = (0..4).flat_map(|y| (0..4).map(move |x| (x, y))).collect();
        covered.sort_by_key(|&(x, y)| (y, x));
        assert_eq!(covered, expected);
    }

    #[test]
    fn matches_llvmpipe_on_edges_through_centres() {
        // Mesa 22 llvmpipe draws this triangle as rows y0: x0..3, y1: x1..3, y2: x2..3, y3: x3.
        let t = TriangleSetup::new([[0.5, 0.5], [4.5, 0.5], [4.5, 4.5]]).unwrap();
        let spans: Vec<_> = (0..6).map(|y| t.row_span(y, 0, 8)).collect();
        assert_eq!(spans, vec![Some((0, 4)), Some((1, 4)), Some((2, 4)), Some((3, 4)), None, None]);
    }

    #[test]
    fn orientation_and_translation_do_not_change_coverage() {
        let v = [[1.3, 2.7], [13.9, 4.1], [6.2, 11.6]];
        let t = TriangleSetup::new(v).unwrap();
        let reversed = TriangleSetup::new([v[0], v[2], v[1]]).unwrap();
        let rotated = TriangleSetup::new([v[1], v[2], v[0]]).unwrap();
        let moved = TriangleSetup::new(v.map(|p| [p[0] + 7.0, p[1] - 3.0])).unwrap();
        for y in 0..16 {
            for x in 0..16 {
                assert_eq!(t.covers(x, y), reversed.covers(x, y));
                assert_eq!(t.covers(x, y), rotated.covers(x, y));
                assert_eq!(t.covers(x, y), moved.covers(x + 7, y - 3));
            }
        }
    }

    #[test]
    fn snapping_in_single_precision_equals_to_fixed() {
        // Halves of 1/256 (the rounding ties), their neighbours, random values of every
        // magnitude, and the guard band's ends.
        let mut seed = 0x1234_5678_9abc_def1;
        let mut values = vec![0.0, -0.0, GUARD_BAND, -GUARD_BAND, 0.5 / 256.0, -0.5 / 256.0, 1.5 / 256.0];
        for k in 0..2000 {
            let magnitude = (1u32 << (k % 23)) as f32;
            let v = (coords(&mut seed, 2.0) - 1.0) * magnitude;
            let tie = ((v * 256.0) as i32) as f32 / 256.0 + 0.5 / 256.0;
            values.extend([v, tie, -tie, f32::from_bits(tie.to_bits() + 1), f32::from_bits(tie.to_bits() - 1)]);
        }
        for v in values.into_iter().filter(|v| v.abs() <= GUARD_BAND) {
            assert_eq!(snap(v), to_fixed(v), "{v}");
        }
    }

    #[test]
    fn degenerate_and_huge_triangles() {
        assert!(TriangleSetup::new([[1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]).is_none());
        let g = GUARD_BAND - 1.0;
        let t = TriangleSetup::new([[-g, -g], [g, -g], [0.0, g]]).unwrap();
        assert_eq!(t.row_span(0, 0, 100), Some((0, 100)));
        assert!(t.covers(0, 0));
    }
}
