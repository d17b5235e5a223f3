//! Bézier curves and surfaces for the evaluators (GL 2.1 section 5.1): points of a map in the
//! Bernstein basis, and the partial derivatives that GL_AUTO_NORMAL needs.
//!
//! The arithmetic is Mesa's, in single precision, so that evaluated vertices land where
//! llvmpipe puts them: points come from Horner's scheme in the Bernstein basis (the binomial
//! coefficient updated step by step with a reciprocal, the powers of `t` accumulated), a
//! surface reduced first along its lower order; points with derivatives come from de
//! Casteljau's algorithm, whose last level gives the tangent directions (unscaled: only their
//! directions matter). Parameters are already mapped to [0, 1].
//!
//! A control point always has four components; a map of `k` components leaves the others 0.

/// One control point or evaluated value (x, y, z, w or the first `k` components).
pub type Point = [f32; 4];

/// GL_MAX_EVAL_ORDER: the largest order a map may have (Mesa's value).
pub const MAX_EVAL_ORDER: usize = 30;

fn lerp_points(a: Point, b: Point, s: f32, t: f32) -> Point {
    std::array::from_fn(|k| s * a[k] + t * b[k])
}

fn difference(a: Point, b: Point) -> Point {
    std::array::from_fn(|k| b[k] - a[k])
}

/// The point at `t` of the curve of `order` control points (`point(i)`), by Horner's scheme
/// in the Bernstein basis: `Σ C(n,i) tⁱ (1−t)ⁿ⁻ⁱ Pᵢ` with `n = order − 1`.
pub fn horner_curve(order: usize, point: impl Fn(usize) -> Point, t: f32) -> Point {
    if order < 2 {
        return point(0);
    }
    let s = 1.0 - t;
    let mut coefficient = (order - 1) as f32;
    let (p0, p1) = (point(0), point(1));
    let mut out: Point = std::array::from_fn(|k| s * p0[k] + coefficient * t * p1[k]);
    let mut power = t * t;
    for i in 2..order {
        // C(n, i) = C(n, i − 1) · (n − i + 1) / i, with the reciprocal as Mesa's table has it.
        coefficient *= (order - i) as f32;
        coefficient *= 1.0 / i as f32;
        let p = point(i);
        for k in 0..4 {
            out[k] = s * out[k] + coefficient * power * p[k];
        }
        power *= t;
    }
    out
}

/// The point at (`u`, `v`) of the surface of `uorder` × `vorder` control points
/// (`point(i, j)`, i along u): the curves along the lower order first, then the curve through
/// their points.
pub fn horner_surface([uorder, vorder]: [usize; 2], point: impl Fn(usize, usize) -> Point, [u, v]: [f32; 2]) -> Point {
    let mut reduced = [[0.0; 4]; MAX_EVAL_ORDER];
    if vorder > uorder {
        for (j, r) in reduced.iter_mut().enumerate().take(vorder) {
            *r = horner_curve(uorder, |i| point(i, j), u);
        }
        horner_curve(vorder, |j| reduced[j], v)
    } else {
        for (i, r) in reduced.iter_mut().enumerate().take(uorder) {
            *r = horner_curve(vorder, |j| point(i, j), v);
        }
        horner_curve(uorder, |i| reduced[i], u)
    }
}

/// de Casteljau's algorithm on `points[..order]` down to the last two points (in place):
/// returns them (the same point twice for order 1).
fn reduce_to_two(points: &mut [Point], t: f32) -> (Point, Point) {
    let order = points.len();
    if order == 1 {
        return (points[0], points[0]);
    }
    let s = 1.0 - t;
    for level in 1..order - 1 {
        for i in 0..order - level {
            points[i] = lerp_points(points[i], points[i + 1], s, t);
        }
    }
    (points[0], points[1])
}

/// The point at (`u`, `v`) of a surface and its derivative directions along u and along v
/// (each `(order − 1)` times smaller than the true partial derivative with respect to the
/// normalized parameter; zero along an order of 1).
pub fn de_casteljau_surface(
    [uorder, vorder]: [usize; 2],
    point: impl Fn(usize, usize) -> Point,
    [u, v]: [f32; 2],
) -> (Point, Point, Point) {
    let (us, vs) = (1.0 - u, 1.0 - v);
    // Along u, per column j: the point of the column's curve and its derivative direction.
    let mut column = [[0.0; 4]; MAX_EVAL_ORDER];
    let mut on_curve = [[0.0; 4]; MAX_EVAL_ORDER];
    let mut along_u = [[0.0; 4]; MAX_EVAL_ORDER];
    for j in 0..vorder {
        for (i, c) in column.iter_mut().enumerate().take(uorder) {
            *c = point(i, j);
        }
        let (a, b) = reduce_to_two(&mut column[..uorder], u);
        on_curve[j] = if uorder == 1 { a } else { lerp_points(a, b, us, u) };
        along_u[j] = if uorder == 1 { [0.0; 4] } else { difference(a, b) };
    }
    // Along v: the point and the v direction from the column points, the u direction from
    // the column derivatives.
    let (c0, c1) = reduce_to_two(&mut on_curve[..vorder], v);
    let (d0, d1) = reduce_to_two(&mut along_u[..vorder], v);
    if vorder == 1 {
        return (c0, d0, [0.0; 4]);
    }
    (lerp_points(c0, c1, vs, v), lerp_points(d0, d1, vs, v), difference(c0, c1))
}

/// The unit normal of a surface from its derivative directions at `point` (GL_AUTO_NORMAL):
/// `∂p/∂u × ∂p/∂v`, for a homogeneous map (`homogeneous`: MAP2_VERTEX_4) the derivatives of
/// (x/w, y/w, z/w) scaled by w². A zero cross product stays zero.
pub fn surface_normal(point: Point, du: Point, dv: Point, homogeneous: bool) -> [f32; 3] {
    let tangent = |d: Point| -> [f32; 3] {
        if homogeneous {
            std::array::from_fn(|k| d[k] * point[3] - d[3] * point[k])
        } else {
            [d[0], d[1], d[2]]
        }
    };
    let (a, b) = (tangent(du), tangent(dv));
    let n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let length_squared = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if length_squared == 0.0 {
        return n;
    }
    let scale = 1.0 / length_squared.sqrt();
    n.map(|c| c * scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f32, y: f32, z: f32) -> Point {
        [x, y, z, 0.0]
    }

    #[test]
    fn curves_interpolate_their_end_points_and_follow_bernstein() {
        // A quadratic: (0,0), (1,2), (2,0) → at t = 0.5: 0.25·P0 + 0.5·P1 + 0.25·P2 = (1, 1).
        let points = [p(0.0, 0.0, 0.0), p(1.0, 2.0, 0.0), p(2.0, 0.0, 0.0)];
        assert_eq!(horner_curve(3, |i| points[i], 0.5), p(1.0, 1.0, 0.0));
        assert_eq!(horner_curve(3, |i| points[i], 0.0), points[0]);
        assert_eq!(horner_curve(3, |i| points[i], 1.0), points[2]);
        // A cubic at t = 0.25: weights 27/64, 27/64, 9/64, 1/64 (all exact in binary).
        let cubic = [p(64.0, 0.0, 0.0), p(0.0, 64.0, 0.0), p(0.0, 0.0, 64.0), p(64.0, 64.0, 64.0)];
        assert_eq!(horner_curve(4, |i| cubic[i], 0.25), p(28.0, 28.0, 10.0));
        // Order 1 is a constant, order 2 a line; outside [0, 1] the polynomial extrapolates.
        assert_eq!(horner_curve(1, |_| p(3.0, 4.0, 5.0), 0.7), p(3.0, 4.0, 5.0));
        assert_eq!(horner_curve(2, |i| p(i as f32 * 4.0, 0.0, 0.0), 1.5), p(6.0, 0.0, 0.0));
        // Degree 29: the coefficients C(29, i) reach 77558760; the curve of constant points is
        // that constant (the weights sum to 1) to within rounding.
        let x = horner_curve(MAX_EVAL_ORDER, |_| p(1.0, 0.0, 0.0), 0.3)[0];
        assert!((x - 1.0).abs() < 1e-5, "{x}");
    }

    #[test]
    fn surfaces_are_curves_of_curves_in_either_order() {
        // The bilinear patch z = u·v over the unit square, and a biquadratic with a bump.
        let bilinear = |i: usize, j: usize| p(i as f32, j as f32, (i * j) as f32);
        assert_eq!(horner_surface([2, 2], bilinear, [0.25, 0.5]), p(0.25, 0.5, 0.125));
        let bump = |i: usize, j: usize| p(i as f32, j as f32, if i == 1 && j == 1 { 16.0 } else { 0.0 });
        // z(0.5, 0.5) = 16 · (2·0.5·0.5)² = 4.
        assert_eq!(horner_surface([3, 3], bump, [0.5, 0.5]), p(1.0, 1.0, 4.0));
        // Different orders reduce along the lower one first; both give the tensor product.
        let wide = |i: usize, j: usize| p(i as f32, j as f32 * 0.5, 0.0);
        assert_eq!(horner_surface([2, 3], wide, [0.5, 0.5]), p(0.5, 0.5, 0.0));
        assert_eq!(horner_surface([3, 2], |i, j| wide(j, i), [0.5, 0.5]), p(0.5, 0.5, 0.0));
        assert_eq!(horner_surface([1, 1], |_, _| p(7.0, 8.0, 9.0), [0.3, 0.6]), p(7.0, 8.0, 9.0));
    }

    #[test]
    fn de_casteljau_gives_the_point_and_the_tangent_directions() {
        let bump = |i: usize, j: usize| p(i as f32, j as f32, if i == 1 && j == 1 { 16.0 } else { 0.0 });
        let (point, du, dv) = de_casteljau_surface([3, 3], bump, [0.5, 0.5]);
        assert_eq!(point, p(1.0, 1.0, 4.0));
        // At the top of the symmetric bump both tangents are horizontal: ∂p/∂u = 2·(1, 0, 0).
        assert_eq!((du, dv), (p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)));
        assert_eq!(surface_normal(point, du, dv, false), [0.0, 0.0, 1.0]);
        // On its flank at u = 0.25, v = 0.5: z = 16·2u(1−u)·2v(1−v) = 3, ∂z/∂u = 16·(2−4u)·0.5
        // = 8 and ∂x/∂u = 2: the direction (2, 0, 8) halved (order 3).
        let (point, du, _) = de_casteljau_surface([3, 3], bump, [0.25, 0.5]);
        assert_eq!(point, p(0.5, 1.0, 3.0));
        assert_eq!(du, p(1.0, 0.0, 4.0));
        // A plane tilted by z = x: normal (−1, 0, 1)/√2, whatever the orders.
        let plane = |i: usize, j: usize| p(i as f32, j as f32, i as f32);
        let (point, du, dv) = de_casteljau_surface([2, 4], plane, [0.3, 0.7]);
        let n = surface_normal(point, du, dv, false);
        let h = std::f32::consts::FRAC_1_SQRT_2;
        assert!((n[0] + h).abs() < 1e-6 && n[1].abs() < 1e-6 && (n[2] - h).abs() < 1e-6, "{n:?}");
        // The point agrees with Horner's to within rounding.
        let horner = horner_surface([2, 4], plane, [0.3, 0.7]);
        assert!((0..3).all(|k| (horner[k] - point[k]).abs() < 1e-6));
        // An order of 1 has no derivative along it: the normal is zero.
        let (_, du, dv) = de_casteljau_surface([1, 3], plane, [0.5, 0.5]);
        assert_eq!(du, [0.0; 4]);
        assert_eq!(surface_normal(p(0.0, 0.0, 0.0), du, dv, false), [0.0, 0.0, 0.0]);
    }

    #[test]
    fn homogeneous_normals_use_the_projected_derivatives() {
        // A plane z = 0 given with w = 2 everywhere: the same normal as with w = 1.
        let flat = |i: usize, j: usize| [2.0 * i as f32, 2.0 * j as f32, 0.0, 2.0];
        let (point, du, dv) = de_casteljau_surface([2, 2], flat, [0.5, 0.5]);
        assert_eq!(point, [1.0, 1.0, 0.0, 2.0]);
        assert_eq!(surface_normal(point, du, dv, true), [0.0, 0.0, 1.0]);
        // Treated as non-homogeneous, w does not enter either (it is not a spatial component).
        assert_eq!(surface_normal(point, du, dv, false), [0.0, 0.0, 1.0]);
        // Where w varies: p = (u, v, 0, 1 + u) projects to (u/w, v/w, 0); the tangents scaled by
        // w² are (1, −0.5, 0) and (0, 1.5, 0), whose cross product points along +z.
        let varying = |i: usize, j: usize| [i as f32, j as f32, 0.0, 1.0 + i as f32];
        let (point, du, dv) = de_casteljau_surface([2, 2], varying, [0.5, 0.5]);
        assert_eq!(point, [0.5, 0.5, 0.0, 1.5]);
        assert_eq!(surface_normal(point, du, dv, true), [0.0, 0.0, 1.0]);
    }
}
