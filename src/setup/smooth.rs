//! Antialiasing coverage (GL_LINE_SMOOTH, GL_POINT_SMOOTH, GL_POLYGON_SMOOTH): for each
//! pixel, the fraction of its square a smooth primitive covers (GL 2.1 §3.3.1, §3.4.2,
//! §3.5.2, §3.6.6). The rasterizer multiplies it into the fragment's alpha.
//!
//! GL leaves the exact coverage computation to the implementation; tessera defines it as
//! follows (pixel (x, y) is the square [x, x+1] × [y, y+1], its centre (x+½, y+½)):
//!
//! - **Lines** follow Mesa 22's draw module (llvmpipe and softpipe draw smooth lines this
//!   way): the line is a rectangle of its true width `w` (at least 1), and a pixel's coverage
//!   is the product of two one-dimensional box-filtered coverages at its centre: across the
//!   line, `clamp((w + 1)/2 − |s|, 0, 1)` for the centre's distance `s` from the line, and
//!   along it, `min(clamp((L + 1)/2 − |t|, 0, 1), L)` for the distance `t` from the
//!   segment's midpoint (L the length). For a line parallel to an axis this is exactly the
//!   area of the pixel square inside the rectangle (for w ≥ 1); for other directions it is
//!   the separable approximation Mesa uses.
//! - **Points** are discs of diameter `size` (at least 1): coverage
//!   `clamp(size/2 + ½ − d, 0, 1)` for the centre's distance `d` from the point, the same
//!   one-pixel ramp across the rim as lines have across their sides.
//! - **Polygons** (triangles) get the exact area of the pixel square inside the triangle,
//!   computed by clipping the triangle to the square (in f64).
//!
//! Pixels of zero coverage produce no fragment.

/// Half the width of a smooth line's coverage footprint across it: `(w + 1)/2`, widths
/// below 1 drawn as 1 (as Mesa's draw module does).
pub fn smooth_line_half_width(width: f32) -> f32 {
    if width <= 1.0 {
        1.0
    } else {
        0.5 * width + 0.5
    }
}

/// The coverage of a smooth line (see the module docs), over window coordinates of either
/// orientation (it is symmetric).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmoothLineCoverage {
    /// The segment's midpoint.
    mid: [f32; 2],
    /// Unit vector along the line (first to second endpoint).
    along: [f32; 2],
    half_width: f32,
    /// Half the length plus half a pixel.
    half_length: f32,
    length: f32,
}

impl SmoothLineCoverage {
    /// The coverage of the line from `p0` to `p1` of GL width `width`; `None` for a
    /// zero-length or non-finite line, which draws nothing.
    pub fn new(p0: [f32; 2], p1: [f32; 2], width: f32) -> Option<SmoothLineCoverage> {
        let d = [p1[0] - p0[0], p1[1] - p0[1]];
        let length = (d[0] * d[0] + d[1] * d[1]).sqrt();
        if !(length > 0.0 && length.is_finite() && width.is_finite()) {
            return None;
        }
        Some(SmoothLineCoverage {
            mid: [(p0[0] + p1[0]) * 0.5, (p0[1] + p1[1]) * 0.5],
            along: [d[0] / length, d[1] / length],
            half_width: smooth_line_half_width(width),
            half_length: 0.5 * length + 0.5,
            length,
        })
    }

    /// The unit vector from the first endpoint to the second.
    pub fn direction(&self) -> [f32; 2] {
        self.along
    }

    pub fn length(&self) -> f32 {
        self.length
    }

    /// The coverage of the pixel whose centre is `(x, y)`.
    #[inline]
    pub fn at(&self, x: f32, y: f32) -> f32 {
        let (rx, ry) = (x - self.mid[0], y - self.mid[1]);
        let t = rx * self.along[0] + ry * self.along[1];
        let s = ry * self.along[0] - rx * self.along[1];
        let across = (self.half_width - s.abs()).clamp(0.0, 1.0);
        let along = (self.half_length - t.abs()).clamp(0.0, 1.0).min(self.length);
        across * along
    }

    /// The open interval of x where a row of pixel centres at `y` may be covered, `None`
    /// if none is.
    pub fn x_range(&self, y: f32) -> Option<(f32, f32)> {
        let [ux, uy] = self.along;
        let ry = y - self.mid[1];
        let (mut lo, mut hi) = (f32::NEG_INFINITY, f32::INFINITY);
        // |k·rx + c| < h for rx = x − mid.x: along (k = ux) and across (k = −uy) the line.
        for (k, c, h) in [(ux, ry * uy, self.half_length), (-uy, ry * ux, self.half_width)] {
            if k.abs() < 1e-6 {
                if c.abs() >= h {
                    return None;
                }
                continue;
            }
            let (a, b) = ((-h - c) / k, (h - c) / k);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        }
        (lo < hi).then_some((self.mid[0] + lo, self.mid[0] + hi))
    }

    /// The rectangle `[min, max]` of window coordinates outside which coverage is zero.
    pub fn extent(&self) -> ([f32; 2], [f32; 2]) {
        let [ux, uy] = self.along;
        let (l, w) = (self.half_length, self.half_width);
        let rx = (l * ux).abs() + (w * uy).abs();
        let ry = (l * uy).abs() + (w * ux).abs();
        ([self.mid[0] - rx, self.mid[1] - ry], [self.mid[0] + rx, self.mid[1] + ry])
    }
}

/// The smooth point size drawn for a requested size: at least 1.
pub fn smooth_point_size(size: f32) -> f32 {
    size.max(1.0)
}

/// The coverage of a smooth point (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmoothPointCoverage {
    pub centre: [f32; 2],
    /// Half the (clamped) size plus half a pixel: where the coverage reaches 0.
    pub reach: f32,
}

impl SmoothPointCoverage {
    pub fn new(centre: [f32; 2], size: f32) -> SmoothPointCoverage {
        SmoothPointCoverage { centre, reach: 0.5 * smooth_point_size(size) + 0.5 }
    }

    /// The coverage of the pixel whose centre is `(x, y)`.
    #[inline]
    pub fn at(&self, x: f32, y: f32) -> f32 {
        let (dx, dy) = (x - self.centre[0], y - self.centre[1]);
        (self.reach - (dx * dx + dy * dy).sqrt()).clamp(0.0, 1.0)
    }
}

/// The area of the pixel square `[x, x+1] × [y, y+1]` inside the triangle `v` (any
/// winding), exactly up to f64 rounding.
pub fn triangle_pixel_coverage(v: &[[f64; 2]; 3], x: i32, y: i32) -> f64 {
    let (x0, y0) = (x as f64, y as f64);
    let (x1, y1) = (x0 + 1.0, y0 + 1.0);
    // Sutherland–Hodgman against the square's four sides, in fixed-size buffers (a triangle
    // clipped by four half-planes has at most 7 vertices).
    let mut poly = [[0.0f64; 2]; 8];
    let mut next = [[0.0f64; 2]; 8];
    poly[..3].copy_from_slice(v);
    let mut n = 3;
    // Each side: inside when `sign · (p[axis] − bound) ≥ 0`.
    for (axis, bound, sign) in [(0, x0, 1.0), (0, x1, -1.0), (1, y0, 1.0), (1, y1, -1.0)] {
        let mut m = 0;
        for i in 0..n {
            let (p, q) = (poly[i], poly[(i + 1) % n]);
            let (dp, dq) = (sign * (p[axis] - bound), sign * (q[axis] - bound));
            if dp >= 0.0 {
                next[m] = p;
                m += 1;
            }
            if (dp >= 0.0) != (dq >= 0.0) {
                let t = dp / (dp - dq);
                let mut r = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
                r[axis] = bound;
                next[m] = r;
                m += 1;
            }
        }
        n = m;
        if n < 3 {
            return 0.0;
        }
        poly[..n].copy_from_slice(&next[..n]);
    }
    let twice: f64 = (0..n)
        .map(|i| {
            let (p, q) = (poly[i], poly[(i + 1) % n]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum();
    (twice * 0.5).abs().min(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_horizontal_line_of_width_one_covers_rows_by_distance() {
        // From (2.5, 10.25) to (12.5, 10.25): row 10 (centre 10.5) is 0.25 away, row 9
        // (9.5) 0.75 away; along the line, pixels 3..=11 are fully inside, the end pixels 2
        // and 12 half.
        let line = SmoothLineCoverage::new([2.5, 10.25], [12.5, 10.25], 1.0).unwrap();
        assert_eq!(line.at(5.5, 10.5), 0.75);
        assert_eq!(line.at(5.5, 9.5), 0.25);
        assert_eq!(line.at(5.5, 11.5), 0.0);
        assert_eq!(line.at(3.5, 10.5), 0.75);
        assert_eq!(line.at(2.5, 10.5), 0.75 * 0.5);
        assert_eq!(line.at(12.5, 10.5), 0.75 * 0.5);
        assert_eq!(line.at(1.5, 10.5), 0.0);
        assert_eq!(line.at(13.5, 10.5), 0.0);
        // At a half-pixel offset the line is centred on a row: full there, nothing beside.
        let centred = SmoothLineCoverage::new([2.0, 10.5], [12.0, 10.5], 1.0).unwrap();
        assert_eq!((centred.at(5.5, 10.5), centred.at(5.5, 9.5), centred.at(5.5, 11.5)), (1.0, 0.0, 0.0));
    }

    #[test]
    fn axis_aligned_line_coverage_is_the_area_inside_the_rectangle() {
        // Width 3 from (1, 8.2) to (11, 8.2): the rectangle y ∈ [6.7, 9.7], x ∈ [1, 11].
        let line = SmoothLineCoverage::new([1.0, 8.2], [11.0, 8.2], 3.0).unwrap();
        let rect = ([1.0f64, 6.7], [11.0f64, 9.7]);
        for y in 4..12 {
            for x in -1..14 {
                let overlap = |lo: f64, hi: f64, p: f64| (hi.min(p + 1.0) - lo.max(p)).max(0.0);
                let area = overlap(rect.0[0], rect.1[0], x as f64) * overlap(rect.0[1], rect.1[1], y as f64);
                let got = line.at(x as f32 + 0.5, y as f32 + 0.5) as f64;
                assert!((got - area).abs() < 1e-6, "({x}, {y}): {got} vs {area}");
            }
        }
    }

    #[test]
    fn short_lines_cover_at_most_their_length() {
        let line = SmoothLineCoverage::new([4.5, 4.5], [4.75, 4.5], 1.0).unwrap();
        assert_eq!(line.at(4.5, 4.5), 0.25);
        assert!(SmoothLineCoverage::new([1.0, 1.0], [1.0, 1.0], 1.0).is_none());
        assert!(SmoothLineCoverage::new([f32::NAN, 1.0], [3.0, 1.0], 1.0).is_none());
    }

    #[test]
    fn line_extent_holds_every_covered_pixel() {
        let line = SmoothLineCoverage::new([3.2, 1.7], [17.9, 11.3], 2.6).unwrap();
        let (lo, hi) = line.extent();
        for y in -5..30 {
            for x in -5..30 {
                let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
                if line.at(cx, cy) > 0.0 {
                    assert!(cx > lo[0] && cx < hi[0] && cy > lo[1] && cy < hi[1], "({x}, {y})");
                }
            }
        }
    }

    #[test]
    fn x_range_holds_every_covered_pixel_of_its_row() {
        for (p0, p1, w) in
            [([3.2, 1.7], [17.9, 11.3], 2.6), ([2.0, 5.5], [20.0, 5.5], 1.0), ([7.3, 1.0], [7.3, 19.0], 4.0)]
        {
            let line = SmoothLineCoverage::new(p0, p1, w).unwrap();
            for y in -5..30 {
                let cy = y as f32 + 0.5;
                let range = line.x_range(cy);
                for x in -5..30 {
                    let cx = x as f32 + 0.5;
                    if line.at(cx, cy) > 0.0 {
                        let (lo, hi) = range.expect("a covered row without a range");
                        assert!(cx > lo - 1e-3 && cx < hi + 1e-3, "({x}, {y}) outside {lo}..{hi}");
                    }
                }
            }
        }
    }

    #[test]
    fn points_ramp_over_one_pixel_at_the_rim() {
        let point = SmoothPointCoverage::new([8.5, 8.5], 4.0);
        assert_eq!(point.at(8.5, 8.5), 1.0);
        assert_eq!(point.at(10.5, 8.5), 0.5);
        assert_eq!(point.at(11.5, 8.5), 0.0);
        assert_eq!(point.at(9.5, 8.5), 1.0);
        // Sizes below 1 are drawn as 1.
        assert_eq!(SmoothPointCoverage::new([0.0, 0.0], 0.25), SmoothPointCoverage::new([0.0, 0.0], 1.0));
    }

    #[test]
    fn triangle_coverage_is_the_exact_area() {
        let tri = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
        assert_eq!(triangle_pixel_coverage(&tri, 0, 0), 1.0);
        // The hypotenuse x + y = 4 cuts pixel (1, 2) along its diagonal.
        assert_eq!(triangle_pixel_coverage(&tri, 1, 2), 0.5);
        assert_eq!(triangle_pixel_coverage(&tri, 3, 0), 0.5);
        assert_eq!(triangle_pixel_coverage(&tri, 2, 2), 0.0);
        assert_eq!(triangle_pixel_coverage(&tri, -1, 0), 0.0);
        // Clockwise winding gives the same area; a triangle inside one pixel gives its own.
        let cw = [[0.0, 0.0], [0.0, 4.0], [4.0, 0.0]];
        assert_eq!(triangle_pixel_coverage(&cw, 1, 2), 0.5);
        let small = [[5.25, 5.25], [5.75, 5.25], [5.25, 5.75]];
        assert_eq!(triangle_pixel_coverage(&small, 5, 5), 0.125);
        // The pixels of a triangle sum to its area.
        let t = [[1.3, 0.7], [9.8, 2.1], [4.4, 7.9]];
        let area = ((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1])) / 2.0;
        let sum: f64 =
            (0..10).flat_map(|y| (0..11).map(move |x| (x, y))).map(|(x, y)| triangle_pixel_coverage(&t, x, y)).sum();
        assert!((sum - area).abs() < 1e-9, "{sum} vs {area}");
    }
}
