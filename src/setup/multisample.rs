//! The standard sample positions of multisampled rasterization.
//!
//! The 2×, 4× and 8× patterns of Direct3D 10 and Vulkan ("standard sample locations"), the
//! ones llvmpipe uses (it offers 4×): offsets from a pixel's lower-left corner in sixteenths
//! of a pixel, taken in GL window coordinates as llvmpipe takes them for framebuffer objects.
//! Every position is a whole number of 1/256 pixel, so a sample is tested against the edge
//! functions of the 8-subpixel-bit fixed-point vertices exactly, with the same fill rule as
//! a pixel centre (which is the single sample at (8, 8)).

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

/// Sample position `index` of `samples` as fractions of a pixel (GL_SAMPLE_POSITION's
/// values; the centre for an unknown index).
pub fn sample_position(samples: usize, index: usize) -> [f32; 2] {
    let o = sample_offsets(samples).get(index).copied().unwrap_or(CENTRE[0]);
    [o.x as f32 / 256.0, o.y as f32 / 256.0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::triangle::TriangleSetup;

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
}
