//! The standard sample positions of multisampled rasterization.
//!
//! The 2×, 4× and 8× patterns of Direct3D 10 and Vulkan ("standard sample locations"), the
//! ones llvmpipe uses (it offers 4×): offsets from a pixel's lower-left corner in sixteenths
//! of a pixel, taken in GL window coordinates as llvmpipe takes them for framebuffer objects.
//! Every position is a whole number of 1/256 pixel, so a sample is tested against the edge
//! functions of the 8-subpixel-bit fixed-point vertices exactly, with the same fill rule as
//! a pixel centre (which is the single sample at (8, 8)).
use super::triangle::{to_fixed, TriangleSetup};
use crate::framebuffer::multisample::MAX_SAMPLES;

/// A sample position inside its pixel, in 1/256 pixel from the lower-left corner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SampleOffset {
    pub x: i64,
    pub y: i64,
}

const fn sixteenths<const N: usize>(p: [[i64; 2]; N]) -> [SampleOffset; N] {
    let mut out = [SampleOffset { x: 0, y: 0 }; N];
    let mut i = 0;
    while i < N {
        out[i] = SampleOffset { x: p[i][0] * 16, y: p[i][1] * 16 };
        i += 1;
    }
    out
}

const CENTRE: [SampleOffset; 1] = sixteenths([[8, 8]]);
const SAMPLES_2: [SampleOffset; 2] = sixteenths([[12, 12], [4, 4]]);
const SAMPLES_4: [SampleOffset; 4] = sixteenths([[6, 2], [14, 6], [2, 10], [10, 14]]);
const SAMPLES_8: [SampleOffset; 8] = sixteenths([[9, 5], [7, 11], [13, 9], [5, 3], [3, 13], [1, 7], [11, 15], [15, 1]]);

/// The positions of `samples` samples per pixel (1: the pixel centre; counts other than
/// 2, 4 and 8 have no pattern and get the centre).
pub fn sample_offsets(samples: usize) -> &'static [SampleOffset] {
    match samples {
        2 => &SAMPLES_2,
        4 => &SAMPLES_4,
        8 => &SAMPLES_8,
        _ => &CENTRE,
    }
}

/// A convex quadrilateral covered sample by sample: the shape of a line or point on a
/// multisampled target while GL_MULTISAMPLE is on. llvmpipe (Mesa 22) rasterizes such a line
/// as its rectangle (the segment widened by the unrounded width perpendicular to it, no
/// diamond rule, no end caps) and such a point as the square of side the unrounded size
/// centred on it, with the triangle edge rules (measured: each equals the
/// `GL_QUADS` of its corners). GL 2.1 §3.3.3 and §3.4.4 ask for the same rectangle and a
/// circle or square. The quad is set up as two triangles sharing a diagonal, so each sample
/// is tested with the triangles' own edge functions and fill rule (the shared diagonal gives
/// every sample on it to exactly one half).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SampleQuad {
    halves: [Option<TriangleSetup>; 2],
}

impl SampleQuad {
    /// The quad of `corners` in order around it, GL window coordinates (y up). `None` when
    /// both halves are degenerate (or outside the guard band).
    pub fn new(corners: [[f32; 2]; 4]) -> Option<SampleQuad> {
        let [a, b, c, d] = corners;
        let halves = [TriangleSetup::new([a, b, c]), TriangleSetup::new([a, c, d])];
        (halves[0].is_some() || halves[1].is_some()).then_some(SampleQuad { halves })
    }

    /// The rectangle of the line `p1`–`p2` of width `width` (GL window coordinates). As
    /// llvmpipe, the ends and the half-width offset are snapped to 1/256 pixel separately.
    pub fn line(p1: [f32; 2], p2: [f32; 2], width: f32) -> Option<SampleQuad> {
        let (dx, dy) = (p2[0] - p1[0], p2[1] - p1[1]);
        let length = (dx * dx + dy * dy).sqrt();
        if length == 0.0 || length.is_nan() {
            return None;
        }
        let scale = width * 0.5 / length;
        let (nx, ny) = (to_fixed(-dy * scale), to_fixed(dx * scale));
        let (a, b) = (p1.map(to_fixed), p2.map(to_fixed));
        SampleQuad::from_fixed([
            [a[0] + nx, a[1] + ny],
            [a[0] - nx, a[1] - ny],
            [b[0] - nx, b[1] - ny],
            [b[0] + nx, b[1] + ny],
        ])
    }

    /// The square of side `size` centred on `centre` (GL window coordinates; the centre and
    /// the side snapped to 1/256 pixel separately, as llvmpipe).
    pub fn point(centre: [f32; 2], size: f32) -> Option<SampleQuad> {
        let h = to_fixed(size) / 2;
        let [x, y] = centre.map(to_fixed);
        SampleQuad::from_fixed([[x - h, y - h], [x + h, y - h], [x + h, y + h], [x - h, y + h]])
    }

    /// [`SampleQuad::new`] of corners already in 1/256 pixel (exact in f32 within 65536
    /// pixels of the origin, far beyond the largest framebuffer, so the triangle setup
    /// snaps them to themselves).
    fn from_fixed(corners: [[i64; 2]; 4]) -> Option<SampleQuad> {
        SampleQuad::new(corners.map(|c| c.map(|v| v as f32 / 256.0)))
    }

    /// The pixels that may hold covered samples: `(x0, y0, x1, y1)`, exclusive maxima.
    pub fn pixel_box(&self) -> (i32, i32, i32, i32) {
        self.halves
            .iter()
            .flatten()
            .map(TriangleSetup::pixel_box)
            .fold((i32::MAX, i32::MAX, i32::MIN, i32::MIN), |(a, b, c, d), (x0, y0, x1, y1)| {
                (a.min(x0), b.min(y0), c.max(x1), d.max(y1))
            })
    }

    /// As [`TriangleSetup::row_span_at`]: the pixels of row `y` whose sample at `(offset_x,
    /// offset_y)` the quad covers. The halves' spans are adjacent (the quad is convex), so
    /// their union is one span.
    #[inline]
    pub fn row_span_at(&self, y: i32, offset_x: i64, offset_y: i64, clip_x0: i32, clip_x1: i32) -> Option<(i32, i32)> {
        let span = |h: &Option<TriangleSetup>| h.as_ref()?.row_span_at(y, offset_x, offset_y, clip_x0, clip_x1);
        match (span(&self.halves[0]), span(&self.halves[1])) {
            (Some((a, b)), Some((c, d))) => Some((a.min(c), b.max(d))),
            (one, other) => one.or(other),
        }
    }
}

/// Sample position `index` of `samples` as fractions of a pixel (GL_SAMPLE_POSITION's
/// values; the centre for an unknown index).
pub fn sample_position(samples: usize, index: usize) -> [f32; 2] {
    let o = sample_offsets(samples).get(index).copied().unwrap_or(CENTRE[0]);
    [o.x as f32 / 256.0, o.y as f32 / 256.0]
}

/// Sample positions relative to the pixel centre, in pixels (GL's y up): where a job
/// evaluates its depth plane for each sample.
pub fn sample_shifts(offsets: &[SampleOffset]) -> [[f32; 2]; MAX_SAMPLES] {
    std::array::from_fn(|s| offsets.get(s).map_or([0.0; 2], |o| [o.x as f32 / 256.0 - 0.5, o.y as f32 / 256.0 - 0.5]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Samples of `pixels` pixels (a row starting at x = 0, row 0) that the triangle covers.
    fn covered_samples(t: &TriangleSetup, samples: usize, pixels: i32) -> usize {
        sample_offsets(samples)
            .iter()
            .map(|o| t.row_span_at(0, o.x, o.y, 0, pixels).map_or(0, |(a, b)| (b - a) as usize))
            .sum()
    }

    #[test]
    fn patterns_are_the_standard_ones() {
        assert_eq!(sample_position(4, 0), [0.375, 0.125]);
        assert_eq!(sample_position(4, 3), [0.625, 0.875]);
        assert_eq!(sample_position(2, 1), [0.25, 0.25]);
        assert_eq!(sample_position(8, 7), [0.9375, 0.0625]);
        assert_eq!(sample_position(1, 0), [0.5, 0.5]);
        // Every pattern has one sample per column and per row of its grid (no two samples
        // share an x or a y), which is what makes the edge coverage below exact.
        for n in [2, 4, 8] {
            let offsets = sample_offsets(n);
            for (i, a) in offsets.iter().enumerate() {
                for b in &offsets[i + 1..] {
                    assert!(a.x != b.x && a.y != b.y, "{n}: {a:?} {b:?}");
                }
            }
        }
    }

    #[test]
    fn a_vertical_edge_covers_the_analytic_fraction_of_samples() {
        // A tall rectangle's left edge at x = k/16 inside pixel 0 covers, in that pixel,
        // exactly the samples right of the edge (and those on it: a left edge owns them).
        for n in [2usize, 4, 8] {
            for k in 0..=16 {
                let e = k as f32 / 16.0;
                let a = TriangleSetup::new([[e, -1.0], [4.0, -1.0], [4.0, 2.0]]).unwrap();
                let b = TriangleSetup::new([[e, -1.0], [4.0, 2.0], [e, 2.0]]).unwrap();
                let expected = sample_offsets(n).iter().filter(|o| o.x >= k * 16).count();
                let in_pixel = |t: &TriangleSetup| {
                    sample_offsets(n).iter().filter(|o| t.row_span_at(0, o.x, o.y, 0, 1).is_some()).count()
                };
                assert_eq!(in_pixel(&a) + in_pixel(&b), expected, "{n} samples, edge at {k}/16");
                // The other three pixels are fully covered.
                assert_eq!(covered_samples(&a, n, 4) + covered_samples(&b, n, 4), expected + 3 * n);
            }
        }
    }

    #[test]
    fn a_diagonal_edge_covers_the_samples_below_it() {
        // The triangle (0,0), (1,0), (1,1) of one pixel: the samples with y ≤ x. The 2×
        // pattern's samples lie on the diagonal, which is the triangle's left edge (it runs
        // downwards), so they are covered; the mirrored triangle, whose diagonal is a right
        // edge, covers exactly the samples with y > x.
        for n in [2usize, 4, 8] {
            let t = TriangleSetup::new([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]).unwrap();
            let expected = sample_offsets(n).iter().filter(|o| o.y <= o.x).count();
            assert_eq!(covered_samples(&t, n, 1), expected, "{n} samples");
            let mirrored = TriangleSetup::new([[0.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).unwrap();
            assert_eq!(covered_samples(&mirrored, n, 1), n - expected, "{n} samples");
        }
        // Half a pixel: exactly half of every pattern's samples.
        for n in [2usize, 4, 8] {
            let t = TriangleSetup::new([[0.0, -8.0], [0.5, -8.0], [0.5, 8.0]]).unwrap();
            let u = TriangleSetup::new([[0.0, -8.0], [0.5, 8.0], [0.0, 8.0]]).unwrap();
            assert_eq!(covered_samples(&t, n, 1) + covered_samples(&u, n, 1), n / 2, "{n} samples");
        }
    }

    /// Covered samples of the pixels `[x0, x1) × [y0, y1)`.
    fn quad_samples(q: &SampleQuad, samples: usize, x0: i32, x1: i32, y0: i32, y1: i32) -> usize {
        let offsets = sample_offsets(samples);
        (y0..y1)
            .flat_map(|y| offsets.iter().map(move |o| (y, o)))
            .map(|(y, o)| q.row_span_at(y, o.x, o.y, x0, x1).map_or(0, |(a, b)| (b - a) as usize))
            .sum()
    }

    /// The samples of pixel grid `[-8, 24)²` inside the open box (exact fractions of a pixel
    /// as multiples of 1/256), counted from the sample positions alone.
    fn analytic(samples: usize, x0: i64, x1: i64, y0: i64, y1: i64) -> usize {
        let mut count = 0;
        for py in -8i64..24 {
            for px in -8i64..24 {
                for o in sample_offsets(samples) {
                    let (sx, sy) = (px * 256 + o.x, py * 256 + o.y);
                    count += usize::from(sx > x0 && sx < x1 && sy > y0 && sy < y1);
                }
            }
        }
        count
    }

    #[test]
    fn axis_aligned_lines_and_points_cover_their_rectangle_samples() {
        // Edges at odd multiples of 1/256 pixel never pass through a sample (samples sit on
        // sixteenths), so the count is the plain inside test.
        for n in [2usize, 4, 8] {
            for (i, width) in [1.0f32, 1.5, 2.0, 3.25, 0.5].into_iter().enumerate() {
                let odd = |whole: f32, k: usize| whole + (2 * k + 1) as f32 / 256.0;
                let (x0, x1, y) = (odd(2.0, 18 * i + 1), odd(13.0, 46), odd(7.0, 17 * i));
                let fixed = |v: f32| (v * 256.0) as i64;
                let h = width / 2.0;
                let expected = analytic(n, fixed(x0), fixed(x1), fixed(y - h), fixed(y + h));
                let horizontal = SampleQuad::line([x0, y], [x1, y], width).unwrap();
                assert_eq!(quad_samples(&horizontal, n, -8, 24, -8, 24), expected, "{n} samples, width {width}");
                // The same line drawn backwards, and its transpose.
                let backwards = SampleQuad::line([x1, y], [x0, y], width).unwrap();
                assert_eq!(quad_samples(&backwards, n, -8, 24, -8, 24), expected);
                let vertical = SampleQuad::line([y, x0], [y, x1], width).unwrap();
                let expected_vertical = analytic(n, fixed(y - h), fixed(y + h), fixed(x0), fixed(x1));
                assert_eq!(quad_samples(&vertical, n, -8, 24, -8, 24), expected_vertical);
                // A point of size `width · 4` centred at (x0 + 3, y): its square.
                let size = width * 4.0;
                let (cx, s) = (x0 + 3.0, size / 2.0);
                let point = SampleQuad::point([cx, y], size).unwrap();
                let expected_point = analytic(n, fixed(cx - s), fixed(cx + s), fixed(y - s), fixed(y + s));
                assert_eq!(quad_samples(&point, n, -8, 24, -8, 24), expected_point, "{n} samples, size {size}");
            }
        }
        // Known values: a width-1 horizontal line through a row's middle covers half of
        // the samples of each pixel it spans (8 whole pixels here), a 2×2 point aligned on
        // pixels every sample of 4 pixels.
        let line = SampleQuad::line([2.0, 4.5], [10.0, 4.5], 1.0).unwrap();
        assert_eq!(quad_samples(&line, 4, 0, 16, 0, 16), 8 * 4);
        let line = SampleQuad::line([2.0, 4.0], [10.0, 4.0], 1.0).unwrap();
        assert_eq!(quad_samples(&line, 4, 0, 16, 3, 4), 8 * 2);
        assert_eq!(quad_samples(&line, 4, 0, 16, 4, 5), 8 * 2);
        let point = SampleQuad::point([5.0, 5.0], 2.0).unwrap();
        assert_eq!(quad_samples(&point, 8, 0, 16, 0, 16), 4 * 8);
        assert_eq!(point.pixel_box(), (4, 4, 7, 7));
        assert!(SampleQuad::line([1.0, 1.0], [1.0, 1.0], 2.0).is_none());
    }
}
