//! Line setup: an aliased line of any width as a parallelogram of four fixed-point edges,
//! with the endpoint rules of Mesa 22's llvmpipe.
//!
//! GL 2.1 §3.4.1 defines width-1 lines by the diamond-exit rule: a pixel is drawn when the
//! segment leaves the diamond |x − xc| + |y − yc| < ½ around its centre, so a line draws its
//! start pixel and not its end pixel, and strips draw shared vertices once. Wide lines
//! (§3.4.2) widen x-major lines vertically and y-major lines horizontally by `round(width)`
//! pixels. llvmpipe implements both with one shape: the segment, widened across its minor
//! axis by `round(width)` pixels (a parallelogram whose short sides are vertical for x-major
//! lines, horizontal for y-major ones), with each end moved by half a pixel along the major
//! axis where the diamond test says the end pixel must (or must not) be drawn. The edges
//! then cover pixel centres with the same fill convention as triangles. We compute exactly
//! that shape, so pixels match llvmpipe's bit for bit, including its quirks (the diamond
//! tests are evaluated in floating point on the unsnapped endpoints, in llvmpipe's y-down
//! window space).
//!
//! Coordinates here are llvmpipe's window space: y grows downwards (`y_down = H − y_gl`,
//! computed from the viewport as llvmpipe does), and a pixel is sampled at its centre, i.e.
//! at the integer corner after the vertices are moved by −½. Rows are converted back to
//! GL's bottom-up rows only when spans are produced.
use super::fixed::{div_ceil, div_floor};
use crate::framebuffer::Rect;
use crate::gl::float::{floor_f32, fused_multiply_add};

/// Subpixel bits, as for triangles.
const ORDER: u32 = 8;
const ONE: i64 = 1 << ORDER;
/// Largest |window coordinate| of a line end that is set up (see [`LineSetup::new`]).
const MAX_COORDINATE: f32 = (1 << 22) as f32;

/// Snaps a coordinate to fixed point as llvmpipe does: `v · 256` rounded half away from
/// zero by adding ±½ in single precision and truncating.
#[inline]
fn snap(v: f32) -> i64 {
    round_half_away(v * ONE as f32)
}

/// llvmpipe's `util_iround`: `(int)(f ± 0.5f)`, the addition rounded to single precision.
#[inline]
pub fn round_half_away(f: f32) -> i64 {
    if f >= 0.0 {
        (f + 0.5) as i64
    } else {
        (f - 0.5) as i64
    }
}

/// `x >= 0` (so −0 counts as positive), the sign test of llvmpipe's diamond rule.
#[inline]
fn non_negative(x: f32) -> bool {
    x >= 0.0
}

/// One edge of the parallelogram: pixel (px, py) (y-down) is inside when
/// `c − dcdx·256·px + dcdy·256·py > 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct EdgePlane {
    dcdx: i64,
    dcdy: i64,
    c: i64,
}

/// How attributes vary along a line: llvmpipe's plane `a(px, py) = a0 + dadx·px + dady·py`
/// over y-down pixel coordinates, whose gradient follows only the major axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineGradient {
    /// `da/dx = (a1 − a2) · dx · inv_length2`, and the same for y (one of them is 0).
    dx: f32,
    dy: f32,
    inv_length2: f32,
    /// The first endpoint moved by −½ (where the plane takes the first endpoint's value).
    origin: [f32; 2],
}

/// A plane of one attribute over y-down pixel coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct LinePlane {
    pub a0: f32,
    pub dadx: f32,
    pub dady: f32,
}

impl LinePlane {
    /// The value at pixel (px, py) (y-down), with llvmpipe's two fused multiply-adds (the
    /// last bit decides depth-test ties), computed exactly without FMA hardware
    /// ([`fused_multiply_add`]): the same bits on every machine.
    #[inline]
    pub fn at(&self, px: f32, py: f32) -> f32 {
        fused_multiply_add(self.dady, py, fused_multiply_add(self.dadx, px, self.a0))
    }
}

impl LineGradient {
    /// The gradient of the projection onto the segment `p1`–`p2` (y-down window
    /// coordinates; not both equal): attributes vary along the line itself, as llvmpipe
    /// interpolates the rectangles of lines on a multisampled target.
    pub fn along(p1: [f32; 2], p2: [f32; 2]) -> LineGradient {
        let (dx, dy) = (p1[0] - p2[0], p1[1] - p2[1]);
        LineGradient { dx, dy, inv_length2: 1.0 / (dx * dx + dy * dy), origin: [p1[0] - 0.5, p1[1] - 0.5] }
    }

    /// The plane of an attribute worth `a1` at the first endpoint and `a2` at the second.
    pub fn plane(&self, a1: f32, a2: f32) -> LinePlane {
        let da = a1 - a2;
        let dadx = da * self.dx * self.inv_length2;
        let dady = da * self.dy * self.inv_length2;
        LinePlane { a0: a1 - (dadx * self.origin[0] + dady * self.origin[1]), dadx, dady }
    }
}

/// A set-up line.
#[derive(Clone, Debug, PartialEq)]
pub struct LineSetup {
    planes: [EdgePlane; 4],
    /// The parallelogram's corners in y-down fixed point (pixel (px, py) samples at
    /// (256·px, 256·py)).
    corners: [[i64; 2]; 4],
    /// The framebuffer height: y-down row `py` is GL row `height − 1 − py`.
    height: i32,
    /// Pixels that may be covered, in GL rows (exclusive maxima).
    pub bounds: Rect,
    pub gradient: LineGradient,
}

/// `0 < v < 1`.
#[inline]
fn open_unit(v: f32) -> bool {
    v > 0.0 && v < 1.0
}

/// Fractional part of a coordinate, `f − floor(f)`.
#[inline]
fn fract(f: f32) -> f32 {
    f - floor_f32(f)
}

impl LineSetup {
    /// Sets up the line from `p1` to `p2` (y-down window coordinates, `height` the
    /// framebuffer height) of GL line width `width`. `None` for a zero-length line, which
    /// draws nothing.
    pub fn new(p1: [f32; 2], p2: [f32; 2], width: f32, height: i32) -> Option<LineSetup> {
        // Lines are clipped to the viewport, so farther coordinates can only come from a
        // viewport far outside the framebuffer (or NaN): nothing to draw, and no risk of
        // overflowing the 64-bit edge functions.
        if ![p1[0], p1[1], p2[0], p2[1]].iter().all(|c| c.abs() <= MAX_COORDINATE) {
            return None;
        }
        let dx = p1[0] - p2[0];
        let dy = p1[1] - p2[1];
        let length2 = dx * dx + dy * dy;
        if length2 == 0.0 {
            return None;
        }
        let inv_length2 = 1.0 / length2;
        // Offset of each endpoint from the centre of the pixel containing it.
        let centre_offset = |v: f32| v - floor_f32(v) - 0.5;
        let (x1d, y1d) = (centre_offset(p1[0]), centre_offset(p1[1]));
        let (mut x2d, mut y2d) = (centre_offset(p2[0]), centre_offset(p2[1]));
        // Widths count whole pixels (halves round up); at least one.
        let half_width = (round_half_away(width.max(1.0)) * ONE) / 2;
        let (mut a, mut b) = (p1, p2);
        let (mut offset_a, mut offset_b) = ([0.0f32; 2], [0.0f32; 2]);
        let gradient;
        let x_major = dx.abs() >= dy.abs();
        if x_major {
            let slope = dy / dx;
            if y2d == -0.5 && dy < 0.0 {
                y2d = 0.5;
            }
            // The diamond-exit decisions for both ends, on the unsnapped endpoints: inside
            // the end's diamond, or leaving the pixel through the diamond's far side.
            let draw_start = x1d.abs() + y1d.abs() < 0.5
                || (non_negative(x1d) != non_negative(-dx)
                    && (non_negative(-y1d) != non_negative(dy) || open_unit(fract(p1[1]) + x1d * slope)));
            let draw_end = x2d.abs() + y2d.abs() >= 0.5
                && non_negative(x2d) == non_negative(-dx)
                && (non_negative(-y2d) == non_negative(dy) || open_unit(fract(p2[1]) + x2d * slope));
            // Attributes vary along x only.
            gradient = (dx * (1.0 + slope * slope), 0.0);
            // Whether the plain parallelogram would draw each end pixel; where it would
            // not match the diamond rule, that end moves by half a pixel along the line.
            // `a` ends up the right end, `b` the left one.
            let start_drawn = non_negative(-x1d) != non_negative(dx);
            let end_drawn = non_negative(x2d) == non_negative(-dx) || x2d == 0.0;
            let half = if dx < 0.0 { -0.5 } else { 0.5 };
            if dx < 0.0 {
                std::mem::swap(&mut a, &mut b);
            }
            let (start, end) = if dx < 0.0 { (&mut offset_b, &mut offset_a) } else { (&mut offset_a, &mut offset_b) };
            if start_drawn != draw_start {
                let ox = -x1d + half;
                *start = [ox, ox * slope];
            }
            if end_drawn != draw_end {
                let ox = -x2d + half;
                *end = [ox, ox * slope];
            }
        } else {
            let slope = dx / dy;
            if x2d == -0.5 && dx < 0.0 {
                x2d = 0.5;
            }
            let draw_start = x1d.abs() + y1d.abs() < 0.5
                || (non_negative(-y1d) != non_negative(dy)
                    && (non_negative(x1d) != non_negative(-dx) || open_unit(fract(p1[0]) + y1d * slope)));
            let draw_end = x2d.abs() + y2d.abs() >= 0.5
                && non_negative(-y2d) == non_negative(dy)
                && (non_negative(x2d) == non_negative(-dx) || (0.0..1.0).contains(&(fract(p2[0]) + y2d * slope)));
            gradient = (0.0, dy * (1.0 + slope * slope));
            // `a` ends up the upper end (smaller y-down), `b` the lower one. (The y-major
            // tests differ from the x-major ones in details, as in Mesa 22.)
            let start_drawn = non_negative(y1d) == non_negative(dy);
            let end_drawn = non_negative(-y2d) == non_negative(dy) || y2d == 0.0;
            let half = if dy > 0.0 { 0.5 } else { -0.5 };
            if dy > 0.0 {
                std::mem::swap(&mut a, &mut b);
            }
            let (start, end) = if dy > 0.0 { (&mut offset_b, &mut offset_a) } else { (&mut offset_a, &mut offset_b) };
            if start_drawn != draw_start {
                let oy = -y1d + half;
                *start = [oy * slope, oy];
            }
            if end_drawn != draw_end {
                let oy = -y2d + half;
                *end = [oy * slope, oy];
            }
        }
        let fa = [snap(a[0] + offset_a[0] - 0.5), snap(a[1] + offset_a[1] - 0.5)];
        let fb = [snap(b[0] + offset_b[0] - 0.5), snap(b[1] + offset_b[1] - 0.5)];
        // The parallelogram a, b, b', a' (counter-clockwise on a y-down screen).
        let (x, y) = if x_major {
            (
                [fa[0], fb[0], fb[0], fa[0]],
                [fa[1] - half_width, fb[1] - half_width, fb[1] + half_width, fa[1] + half_width],
            )
        } else {
            (
                [fa[0] - half_width, fb[0] - half_width, fb[0] + half_width, fa[0] + half_width],
                [fa[1], fb[1], fb[1], fa[1]],
            )
        };
        let planes = std::array::from_fn(|i| {
            let j = (i + 1) % 4;
            let dcdx = y[i] - y[j];
            let dcdy = x[i] - x[j];
            // Centres exactly on an edge belong to left edges and to bottom edges.
            let owns = dcdx < 0 || (dcdx == 0 && dcdy < 0);
            EdgePlane { dcdx, dcdy, c: dcdx * x[i] - dcdy * y[i] + owns as i64 }
        });
        // Bounding box of centres in y-down pixels (inclusive), as llvmpipe rounds it.
        let min_x = (x.iter().min().unwrap() + ONE - 1) >> ORDER;
        let max_x = ((x.iter().max().unwrap() + ONE - 1) >> ORDER) - 1;
        let min_y = (y.iter().min().unwrap() + ONE) >> ORDER;
        let max_y = ((y.iter().max().unwrap() + ONE) >> ORDER) - 1;
        let to_i32 = |v: i64| v.clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
        let bounds = Rect {
            x0: to_i32(min_x),
            x1: to_i32(max_x + 1),
            y0: to_i32(height as i64 - 1 - max_y),
            y1: to_i32(height as i64 - min_y),
        };
        Some(LineSetup {
            planes,
            corners: std::array::from_fn(|i| [x[i], y[i]]),
            height,
            bounds,
            gradient: LineGradient { dx: gradient.0, dy: gradient.1, inv_length2, origin: [p1[0] - 0.5, p1[1] - 0.5] },
        })
    }

    /// The y-down pixel row of GL row `y`.
    #[inline]
    pub fn row_down(&self, y: i32) -> i32 {
        self.height - 1 - y
    }

    /// Pixel columns `[x0, x1)` that may hold covered pixels in GL rows `[y0, y1)`: the
    /// parallelogram's extent across that slab, with a pixel of margin.
    pub fn columns(&self, y0: i32, y1: i32) -> Option<(i32, i32)> {
        // Sample rows of the slab in y-down fixed point.
        let lo = (self.row_down(y1 - 1) as i64) * ONE;
        let hi = (self.row_down(y0) as i64) * ONE;
        let (mut min_x, mut max_x) = (i64::MAX, i64::MIN);
        let mut take = |x: i64| {
            min_x = min_x.min(x);
            max_x = max_x.max(x);
        };
        for i in 0..4 {
            let [px, py] = self.corners[i];
            let [qx, qy] = self.corners[(i + 1) % 4];
            if (lo..=hi).contains(&py) {
                take(px);
            }
            for bound in [lo, hi] {
                if (py < bound) != (qy < bound) {
                    // The edge crosses the slab's side: x there, rounded both ways.
                    let n = (bound - py) * (qx - px);
                    let d = qy - py;
                    take(px + div_floor(n, d));
                    take(px + div_ceil(n, d));
                }
            }
        }
        (min_x <= max_x).then(|| {
            let to_i32 = |v: i64| v.clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
            (to_i32(div_floor(min_x, ONE) - 1), to_i32(div_ceil(max_x, ONE) + 2))
        })
    }

    /// The covered pixels of GL row `y` as a half-open range within `[clip_x0, clip_x1)`.
    pub fn row_span(&self, y: i32, clip_x0: i32, clip_x1: i32) -> Option<(i32, i32)> {
        let py = self.row_down(y) as i64 * ONE;
        let mut lo = clip_x0.max(self.bounds.x0) as i64;
        let mut hi = clip_x1.min(self.bounds.x1) as i64;
        for p in &self.planes {
            // Inside: k − 256·dcdx·px > 0 with k = c + dcdy·256·py.
            let k = p.c + p.dcdy * py;
            let step = p.dcdx * ONE;
            if step > 0 {
                hi = hi.min(div_ceil(k, step));
            } else if step < 0 {
                lo = lo.max(div_floor(k, step) + 1);
            } else if k <= 0 {
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

    /// The pixels of a line in a `size`-row framebuffer, GL coordinates in and out.
    fn pixels(p1: [f32; 2], p2: [f32; 2], width: f32, size: i32) -> Vec<(i32, i32)> {
        let down = |p: [f32; 2]| [p[0], size as f32 - p[1]];
        let Some(line) = LineSetup::new(down(p1), down(p2), width, size) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for y in 0..size {
            if let Some((a, b)) = line.row_span(y, 0, size) {
                out.extend((a..b).map(|x| (x, y)));
            }
        }
        out
    }

    #[test]
    fn horizontal_lines_draw_the_start_and_not_the_end() {
        assert_eq!(pixels([1.5, 2.5], [4.5, 2.5], 1.0, 8), vec![(1, 2), (2, 2), (3, 2)]);
        assert_eq!(pixels([4.5, 2.5], [1.5, 2.5], 1.0, 8), vec![(2, 2), (3, 2), (4, 2)]);
        // On a pixel border the line belongs to the row below (Mesa 22: y = 2 lights row 1).
        assert_eq!(pixels([1.0, 2.0], [4.0, 2.0], 1.0, 8), vec![(1, 1), (2, 1), (3, 1)]);
    }

    #[test]
    fn wide_lines_cover_whole_columns_and_rows() {
        // Width 3, x-major: three rows per column; y-major: three columns per row.
        let x_major = pixels([1.5, 4.5], [5.5, 4.5], 3.0, 8);
        assert_eq!(x_major, (3..6).flat_map(|y| (1..5).map(move |x| (x, y))).collect::<Vec<_>>());
        let y_major = pixels([4.5, 1.5], [4.5, 4.5], 3.0, 8);
        assert_eq!(y_major, (1..4).flat_map(|y| (3..6).map(move |x| (x, y))).collect::<Vec<_>>());
    }

    #[test]
    fn degenerate_and_far_lines_draw_nothing() {
        assert!(LineSetup::new([3.0, 3.0], [3.0, 3.0], 1.0, 8).is_none());
        assert!(LineSetup::new([f32::NAN, 3.0], [5.0, 3.0], 1.0, 8).is_none());
        assert!(LineSetup::new([-1e9, 3.0], [5.0, 3.0], 1.0, 8).is_none());
    }

    #[test]
    fn columns_contain_every_covered_pixel() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            ((seed >> 11) as f64 / (1u64 << 53) as f64) as f32 * 200.0 - 20.0
        };
        for _ in 0..300 {
            let (p1, p2, width) = ([next(), next()], [next(), next()], 1.0 + (next() + 20.0) / 40.0);
            let Some(line) = LineSetup::new(p1, p2, width, 160) else { continue };
            for band in (0..160).step_by(16) {
                let columns = line.columns(band, band + 16);
                for y in band..band + 16 {
                    if let Some((a, b)) = line.row_span(y, -100, 300) {
                        let (c0, c1) = columns.expect("a covered row in a band with no columns");
                        assert!(c0 <= a && b <= c1, "row {y}: span {a}..{b} outside {c0}..{c1}");
                    }
                }
            }
        }
    }
}
