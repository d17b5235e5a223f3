//! Attribute interpolation shared by triangles and lines: how color varies over a primitive
//! ([`Shading`]) and the perspective-correct extra attributes ([`Varyings`]).
//!
//! Both are generic over the plane type, because triangles and lines evaluate their planes
//! differently (triangles around their first vertex; lines over llvmpipe's y-down
//! coordinates with fused multiply-adds), while the interpolation itself is the same.

/// A linear function of pixel position.
pub trait Interpolant {
    /// The value at (x, y) in the plane's own coordinates.
    fn at(&self, x: f32, y: f32) -> f32;

    /// How much the value grows from one pixel to the next along x.
    fn step_x(&self) -> f32 {
        self.at(1.0, 0.0) - self.at(0.0, 0.0)
    }
}

/// How a primitive's color varies over it.
#[derive(Clone, Debug, PartialEq)]
pub enum Shading<P> {
    /// One color (flat shading, or all vertices equal).
    Flat([f32; 4]),
    /// Linear in window space (all w equal: orthographic projections).
    Affine([P; 4]),
    /// Planes of color/w and of 1/w.
    Perspective { color_over_w: [P; 4], inv_w: P },
    /// Linear in window space, evaluated as the row's start value plus `i` steps (the fast
    /// accuracy mode: cheaper than evaluating each plane at each pixel, and affine even when
    /// w varies).
    Stepped([P; 4]),
}

impl<P: Interpolant> Shading<P> {
    /// The colors of the `n` pixels from `(x0, y)` (x stepping by one) appended to `colors`;
    /// for flat shading nothing is appended and the one color is returned instead.
    #[inline]
    pub fn span_colors(&self, x0: f32, y: f32, n: usize, colors: &mut Vec<[f32; 4]>) -> Option<[f32; 4]> {
        match self {
            Shading::Flat(c) => return Some(*c),
            Shading::Affine(planes) => colors.extend((0..n).map(|i| planes.each_ref().map(|p| p.at(x0 + i as f32, y)))),
            Shading::Perspective { color_over_w, inv_w } => colors.extend((0..n).map(|i| {
                let x = x0 + i as f32;
                let w = 1.0 / inv_w.at(x, y);
                color_over_w.each_ref().map(|p| p.at(x, y) * w)
            })),
            Shading::Stepped(planes) => {
                let start = planes.each_ref().map(|p| p.at(x0, y));
                let step = planes.each_ref().map(|p| p.step_x());
                colors.extend((0..n).map(|i| {
                    let i = i as f32;
                    std::array::from_fn(|c| start[c] + step[c] * i)
                }))
            }
        }
        None
    }
}

/// The attributes beyond color that a draw's later stages read (secondary color, fog
/// coordinate, texture coordinates), interpolated perspective-correctly: planes of a/w and
/// the plane of 1/w. Empty (and free) when the draw needs none.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Varyings<P> {
    over_w: Vec<P>,
    inv_w: P,
}

impl<P: Interpolant> Varyings<P> {
    pub fn new(over_w: Vec<P>, inv_w: P) -> Self {
        Varyings { over_w, inv_w }
    }

    /// How many scalar attributes are interpolated.
    pub fn len(&self) -> usize {
        self.over_w.len()
    }

    pub fn is_empty(&self) -> bool {
        self.over_w.is_empty()
    }

    /// The attributes at (x, y), into `out`.
    #[inline]
    pub fn at(&self, x: f32, y: f32, out: &mut [f32]) {
        let w = 1.0 / self.inv_w.at(x, y);
        for (o, p) in out.iter_mut().zip(&self.over_w) {
            *o = p.at(x, y) * w;
        }
    }
}
