//! Smooth (antialiased) lines, points and triangles: the jobs they become, and how they
//! render inside one tile. Every pixel the primitive touches gets its coverage
//! ([`crate::setup::smooth`]) walked by `raster` and multiplied into its fragment's alpha
//! by the same fragment pipeline as aliased primitives.
//!
//! A draw picks these jobs instead of the aliased ones when GL_LINE_SMOOTH,
//! GL_POINT_SMOOTH or GL_POLYGON_SMOOTH is enabled, so aliased primitives never test for
//! smoothing. Attributes are interpolated as Mesa's draw module does for its smooth lines:
//! a line is a quad reaching half a pixel beyond each end, whose ends carry the endpoints'
//! values (so they vary along the line only, over its length plus one pixel); a point has
//! one value; a triangle interpolates over its plane, evaluated at pixel centres (also at
//! centres outside it, for partly covered pixels).
use super::line::LineVertex;
use super::triangle::WindowVertex;
use crate::fragment::pipeline::{shade_covered_span, DrawState, Scratch, Span};
use crate::framebuffer::band::Band;
use crate::framebuffer::Rect;
use crate::gl::float::{ceil_to_i32, floor_f64, floor_to_i32};
use crate::raster::walk::{stipple_mask, walk_covered};
use crate::setup::plane::{Plane, PointVaryings, Shading, Varyings};
use crate::setup::smooth::{triangle_pixel_coverage, SmoothLineCoverage, SmoothPointCoverage};

/// A smooth primitive ready for rasterization.
#[derive(Clone, Debug)]
pub enum SmoothJob {
    Line(Box<SmoothLine>),
    Point(Box<SmoothPoint>),
    Triangle(Box<SmoothTriangle>),
}

impl SmoothJob {
    /// The pixels that may be covered.
    pub fn bounds(&self) -> Rect {
        match self {
            SmoothJob::Line(job) => job.bounds,
            SmoothJob::Point(job) => job.bounds,
            SmoothJob::Triangle(job) => job.bounds,
        }
    }

    /// Renders the part of the primitive inside `area` (within the band) into `band`.
    pub fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        match self {
            SmoothJob::Line(job) => job.render(state, area, band, scratch),
            SmoothJob::Point(job) => job.render(state, area, band, scratch),
            // Filled polygons are bounded by the viewport (they are clipped to a guard band).
            SmoothJob::Triangle(job) => job.render(state, area.intersect(state.fill_clip), band, scratch),
        }
    }
}

/// The GL pixel rectangle holding the window-space box `[lo, hi]` given in y-down
/// coordinates of a framebuffer `height` rows high.
fn rect_from_down(lo: [f32; 2], hi: [f32; 2], height: i32) -> Rect {
    Rect {
        x0: floor_to_i32(lo[0]),
        x1: ceil_to_i32(hi[0]),
        y0: height - ceil_to_i32(hi[1]),
        y1: height - floor_to_i32(lo[1]),
    }
}

/// The plane of a value worth `a0` at `t = 0` and `a1` at `t = 1` of a linear parameter
/// `t(dx, dy) = dx·gradient[0] + dy·gradient[1]`.
fn ramp(gradient: [f32; 2], a0: f32, a1: f32) -> Plane {
    let da = a1 - a0;
    Plane { a0, dadx: da * gradient[0], dady: da * gradient[1] }
}

/// A smooth line: its coverage and its attributes along it, over y-down coordinates.
#[derive(Clone, Debug)]
pub struct SmoothLine {
    coverage: SmoothLineCoverage,
    bounds: Rect,
    height: i32,
    /// Where the attribute planes start: half a pixel before the first endpoint.
    anchor: [f32; 2],
    z: Plane,
    shading: Shading<Plane>,
    varyings: Varyings<Plane>,
}

impl SmoothLine {
    /// Sets up the smooth line `a`–`b` of GL width `width` in a framebuffer `height` rows
    /// high; `flat` is the flat-shading color if flat shaded, `varyings` the values of the
    /// draw's varyings at `a` and `b`. `None` if it draws nothing.
    pub fn new<const N: usize>(
        a: &LineVertex<N>,
        b: &LineVertex<N>,
        width: f32,
        height: i32,
        flat: Option<[f32; 4]>,
        varyings: impl IntoIterator<Item = [f32; 2]>,
    ) -> Option<SmoothLine> {
        let coverage = SmoothLineCoverage::new([a.x, a.y_down], [b.x, b.y_down], width)?;
        let (lo, hi) = coverage.extent();
        let [ux, uy] = coverage.direction();
        // The attributes go from the first endpoint's value half a pixel before it to the
        // second's half a pixel beyond it.
        let span = coverage.length() + 1.0;
        let gradient = [ux / span, uy / span];
        let plane = |v0: f32, v1: f32| ramp(gradient, v0, v1);
        let shading = match flat {
            Some(color) => Shading::Flat(color),
            None if a.color == b.color => Shading::Flat(a.color),
            None if a.inv_w == b.inv_w => Shading::Affine(std::array::from_fn(|c| plane(a.color[c], b.color[c]))),
            None => Shading::Perspective {
                color_over_w: std::array::from_fn(|c| plane(a.color[c] * a.inv_w, b.color[c] * b.inv_w)),
                inv_w: plane(a.inv_w, b.inv_w),
            },
        };
        let over_w = varyings.into_iter().map(|v| plane(v[0] * a.inv_w, v[1] * b.inv_w));
        Some(SmoothLine {
            coverage,
            bounds: rect_from_down(lo, hi, height),
            height,
            anchor: [a.x - 0.5 * ux, a.y_down - 0.5 * uy],
            z: plane(a.z, b.z),
            shading,
            varyings: Varyings::new(over_w, plane(a.inv_w, b.inv_w)),
        })
    }

    fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.bounds);
        if area.is_empty() {
            return;
        }
        // Pixel centres in y-down coordinates: (x + ½, height − y − ½).
        let centre_down = |y: i32| (self.height - y) as f32 - 0.5;
        walk_covered(
            area,
            |y| {
                // Centres strictly inside the range, with a pixel of margin for rounding.
                let (lo, hi) = self.coverage.x_range(centre_down(y))?;
                Some((floor_to_i32(lo - 0.5) - 1, ceil_to_i32(hi - 0.5) + 2))
            },
            |x, y| self.coverage.at(x as f32 + 0.5, centre_down(y)),
            |y, x0, n, live, coverage| {
                let dx0 = x0 as f32 + 0.5 - self.anchor[0];
                let dy = centre_down(y) - self.anchor[1];
                let row_start = (y - band.y0) as usize * band.width + x0 as usize;
                // Lines are front-facing (GL 2.1 §4.1.5), as aliased lines.
                let span = Span { y, x0, n, row_start, front_facing: true };
                shade_covered_span(
                    state,
                    band,
                    scratch,
                    span,
                    live,
                    |i| self.z.at(dx0 + i as f32, dy),
                    |colors| self.shading.span_colors(dx0, dy, n, colors),
                    // A row above is one less in y-down coordinates.
                    |i, j, out| self.varyings.at(dx0 + i as f32, dy - j as f32, out),
                    coverage,
                );
            },
        );
    }
}

/// A smooth point: a disc with one depth, color and set of varyings.
#[derive(Clone, Debug)]
pub struct SmoothPoint {
    coverage: SmoothPointCoverage,
    bounds: Rect,
    height: i32,
    z: f32,
    color: [f32; 4],
    varyings: PointVaryings,
}

impl SmoothPoint {
    /// The smooth point at `v` (y-down window coordinates) of size `size` in a framebuffer
    /// `height` rows high, with `color` and the draw's `varyings`.
    pub fn new<const N: usize>(
        v: &LineVertex<N>,
        size: f32,
        height: i32,
        color: [f32; 4],
        varyings: PointVaryings,
    ) -> Option<SmoothPoint> {
        if !(v.x.is_finite() && v.y_down.is_finite()) {
            return None;
        }
        let coverage = SmoothPointCoverage::new([v.x, v.y_down], size);
        let r = coverage.reach;
        let bounds = rect_from_down([v.x - r, v.y_down - r], [v.x + r, v.y_down + r], height);
        Some(SmoothPoint { coverage, bounds, height, z: v.z, color, varyings })
    }

    fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.bounds);
        if area.is_empty() {
            return;
        }
        let centre_down = |y: i32| (self.height - y) as f32 - 0.5;
        walk_covered(
            area,
            |_| Some((area.x0, area.x1)),
            |x, y| self.coverage.at(x as f32 + 0.5, centre_down(y)),
            |y, x0, n, live, coverage| {
                let row_start = (y - band.y0) as usize * band.width + x0 as usize;
                let span = Span { y, x0, n, row_start, front_facing: true };
                shade_covered_span(
                    state,
                    band,
                    scratch,
                    span,
                    live,
                    |_| self.z,
                    |_| Some(self.color),
                    |_, _, out| out.iter_mut().zip(&self.varyings).for_each(|(o, &v)| *o = v),
                    coverage,
                );
            },
        );
    }
}

/// A smooth triangle: the exact coverage of each pixel square, attribute planes anchored
/// at its first vertex (GL window coordinates, y up).
#[derive(Clone, Debug)]
pub struct SmoothTriangle {
    vertices: [[f64; 2]; 3],
    /// The edge functions' sign inside the triangle (its winding).
    winding: f64,
    bounds: Rect,
    anchor: [f32; 2],
    z: Plane,
    shading: Shading<Plane>,
    varyings: Varyings<Plane>,
    front_facing: bool,
}

impl SmoothTriangle {
    /// Sets up a smooth triangle; as [`super::triangle::TriangleJob::new`], plus its facing.
    /// `None` for a degenerate or non-finite triangle.
    pub fn new<const N: usize>(
        v: [WindowVertex<N>; 3],
        flat: Option<[f32; 4]>,
        depth_offset: f32,
        varyings: impl IntoIterator<Item = [f32; 3]>,
        front_facing: bool,
    ) -> Option<SmoothTriangle> {
        let p = v.map(|q| [q.x as f64, q.y as f64]);
        let d1 = [p[1][0] - p[0][0], p[1][1] - p[0][1]];
        let d2 = [p[2][0] - p[0][0], p[2][1] - p[0][1]];
        let area2 = d1[0] * d2[1] - d2[0] * d1[1];
        if !(area2.is_finite() && area2 != 0.0) {
            return None;
        }
        let plane = |values: [f32; 3]| Plane::through(d1, d2, values);
        let mut z = plane(v.map(|q| q.z));
        z.a0 += depth_offset;
        let inv_w = v.map(|q| q.inv_w);
        let shading = match flat {
            Some(color) => Shading::Flat(color),
            None if v[0].color == v[1].color && v[1].color == v[2].color => Shading::Flat(v[0].color),
            None if inv_w[0] == inv_w[1] && inv_w[1] == inv_w[2] => {
                Shading::Affine(std::array::from_fn(|c| plane(v.map(|q| q.color[c]))))
            }
            None => Shading::Perspective {
                color_over_w: std::array::from_fn(|c| plane(v.map(|q| q.color[c] * q.inv_w))),
                inv_w: plane(inv_w),
            },
        };
        let over_w = varyings.into_iter().map(|a| plane([0, 1, 2].map(|i| a[i] * inv_w[i])));
        let to_i32 = |f: f64| f.clamp(i32::MIN as f64 / 2.0, i32::MAX as f64 / 2.0) as i32;
        let (xs, ys) = (p.map(|q| q[0]), p.map(|q| q[1]));
        let min = |a: [f64; 3]| a[0].min(a[1]).min(a[2]);
        let max = |a: [f64; 3]| a[0].max(a[1]).max(a[2]);
        Some(SmoothTriangle {
            vertices: p,
            winding: area2.signum(),
            bounds: Rect {
                x0: to_i32(floor_f64(min(xs))),
                x1: to_i32(-floor_f64(-max(xs))),
                y0: to_i32(floor_f64(min(ys))),
                y1: to_i32(-floor_f64(-max(ys))),
            },
            anchor: [v[0].x, v[0].y],
            z,
            shading,
            varyings: Varyings::new(over_w, plane(inv_w)),
            front_facing,
        })
    }

    /// Whether window point `q` is inside (or on) the triangle.
    #[inline]
    fn contains(&self, q: [f64; 2]) -> bool {
        (0..3).all(|i| {
            let (a, b) = (self.vertices[i], self.vertices[(i + 1) % 3]);
            let edge = (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
            edge * self.winding >= 0.0
        })
    }

    /// The coverage of pixel (x, y): 1 when its four corners are inside, else the area
    /// clipped out of it.
    #[inline]
    fn coverage(&self, x: i32, y: i32) -> f32 {
        let (x0, y0) = (x as f64, y as f64);
        let corners = [[x0, y0], [x0 + 1.0, y0], [x0, y0 + 1.0], [x0 + 1.0, y0 + 1.0]];
        if corners.iter().all(|&c| self.contains(c)) {
            1.0
        } else {
            triangle_pixel_coverage(&self.vertices, x, y) as f32
        }
    }

    fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.bounds);
        if area.is_empty() {
            return;
        }
        walk_covered(
            area,
            |_| Some((area.x0, area.x1)),
            |x, y| self.coverage(x, y),
            |y, x0, n, mut live, coverage| {
                if let Some(pattern) = &state.polygon_stipple {
                    live &= stipple_mask(pattern, x0, y);
                    if live == 0 {
                        return;
                    }
                }
                let dx0 = x0 as f32 + 0.5 - self.anchor[0];
                let dy = y as f32 + 0.5 - self.anchor[1];
                let row_start = (y - band.y0) as usize * band.width + x0 as usize;
                let span = Span { y, x0, n, row_start, front_facing: self.front_facing };
                shade_covered_span(
                    state,
                    band,
                    scratch,
                    span,
                    live,
                    |i| self.z.at(dx0 + i as f32, dy),
                    |colors| self.shading.span_colors(dx0, dy, n, colors),
                    |i, j, out| self.varyings.at(dx0 + i as f32, dy + j as f32, out),
                    coverage,
                );
            },
        );
    }
}
