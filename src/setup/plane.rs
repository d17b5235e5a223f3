//! Attribute planes: how a set-up primitive's depth, color and extra attributes vary over
//! window space, built once per primitive and evaluated per pixel by the fragment inputs
//! its job hands to the pipeline.
//!
//! [`Shading`] (color) and [`Varyings`] (the perspective-correct extra attributes) are
//! generic over the plane type, because triangles and lines evaluate their planes
//! differently (triangles around their first vertex, [`Plane`]; lines over llvmpipe's
//! y-down coordinates with fused multiply-adds, `LinePlane`), while the interpolation
//! itself is the same.
//!
//! A primitive's planes live inside its job, not in an arena of the scene: a job stays
//! self-contained, so the code that renders it (the tile workers, each job's `render`)
//! reads its planes next to its edges with no scene at hand. Up to [`INLINE_VARYINGS`]
//! planes (one texture unit's coordinates, or the fog coordinate and the secondary color)
//! are held inline, so setting up and binning such a primitive allocates nothing; a draw
//! with more puts each primitive's planes in one allocation of their own count. Holding
//! all `MAX_VARYINGS` inline made every triangle job 544 bytes, used or not, which every
//! triangle's setup, binning and rendering moved through memory (small_triangles has none).
use crate::fragment::block::{lanes, F32s, LANES};
use crate::glsl::varyings::VARYING_SLOTS;

/// The most scalar varyings a draw interpolates: the secondary color (RGB for GL_COLOR_SUM,
/// RGBA for a GLSL `gl_SecondaryColor`), the fog coordinate and the four components of
/// every varying slot (texture units' coordinates, GLSL varyings).
pub const MAX_VARYINGS: usize = 4 + 1 + 4 * VARYING_SLOTS;

/// A linear function of pixel position.
pub trait Interpolant {
    /// The value at (x, y) in the plane's own coordinates.
    fn at(&self, x: f32, y: f32) -> f32;
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
}

impl<P: Interpolant> Shading<P> {
    /// The colors of the `n` pixels from `(x0, y)` (x stepping by one) appended to `colors`;
    /// for flat shading nothing is appended and the one color is returned instead.
    #[inline]
    pub fn span_colors(&self, x0: f32, y: f32, n: usize, colors: &mut Vec<[f32; 4]>) -> Option<[f32; 4]> {
        if let Shading::Flat(c) = self {
            return Some(*c);
        }
        // One copy of the evaluation loops per SIMD level (`crate::simd`).
        crate::simd::per_level!(self.span_colors_body(x0, y, n, colors));
        None
    }

    /// The loops of [`Self::span_colors`], inlined into each level's copy: plain loops over
    /// the appended pixels (an iterator `extend` would be a call out of the copy).
    #[inline(always)]
    fn span_colors_body(&self, x0: f32, y: f32, n: usize, colors: &mut Vec<[f32; 4]>) {
        if matches!(self, Shading::Flat(_)) {
            return;
        }
        let start = colors.len();
        colors.resize(start + n, [0.0; 4]);
        let out = &mut colors[start..];
        match self {
            Shading::Flat(_) => {}
            Shading::Affine(planes) => {
                for (i, o) in out.iter_mut().enumerate() {
                    *o = planes.each_ref().map(|p| p.at(x0 + i as f32, y));
                }
            }
            Shading::Perspective { color_over_w, inv_w } => {
                for (i, o) in out.iter_mut().enumerate() {
                    let x = x0 + i as f32;
                    let w = 1.0 / inv_w.at(x, y);
                    *o = color_over_w.each_ref().map(|p| p.at(x, y) * w);
                }
            }
        }
    }
}

/// How many varying planes a primitive holds without an allocation (see the module docs).
pub const INLINE_VARYINGS: usize = 4;

/// The attributes beyond color that a draw's later stages read (secondary color, fog
/// coordinate, texture coordinates), interpolated perspective-correctly: planes of a/w and
/// the plane of 1/w (see the module docs for where they are held); or, for the fast accuracy
/// mode, affinely: planes of the attributes themselves and no 1/w. Empty when the draw
/// needs none.
#[derive(Clone, Debug, PartialEq)]
pub struct Varyings<P> {
    /// The planes (of a/w, or of a when `inv_w` is `None`).
    over_w: Planes<P>,
    inv_w: Option<P>,
}

/// The first `len` are the planes; the rest stay default.
#[derive(Clone, Debug, PartialEq)]
enum Planes<P> {
    Inline { planes: [P; INLINE_VARYINGS], len: u8 },
    Heap { planes: Box<[P]> },
}

impl<P: Default + Copy> Default for Varyings<P> {
    fn default() -> Self {
        Varyings { over_w: Planes::Inline { planes: [P::default(); INLINE_VARYINGS], len: 0 }, inv_w: None }
    }
}

impl<P: Interpolant + Copy + Default> Varyings<P> {
    /// The planes `over_w` (at most [`MAX_VARYINGS`]; a draw never has more, and any beyond
    /// are dropped) with the plane of 1/w.
    #[inline]
    pub fn new(over_w: impl IntoIterator<Item = P>, inv_w: P) -> Self {
        Self::with_inv_w(over_w, Some(inv_w))
    }

    /// The planes `linear` of the attributes themselves, interpolated affinely in window
    /// space (the fast accuracy mode: no divide per fragment).
    #[inline]
    pub fn affine(linear: impl IntoIterator<Item = P>) -> Self {
        Self::with_inv_w(linear, None)
    }

    #[inline]
    fn with_inv_w(planes_in: impl IntoIterator<Item = P>, inv_w: Option<P>) -> Self {
        let mut planes_in = planes_in.into_iter();
        let mut planes = [P::default(); INLINE_VARYINGS];
        let mut len = 0;
        for (slot, p) in planes.iter_mut().zip(&mut planes_in) {
            *slot = p;
            len += 1;
        }
        let over_w = match planes_in.next() {
            None => Planes::Inline { planes, len },
            Some(next) => {
                let mut all = Vec::with_capacity(2 * INLINE_VARYINGS);
                all.extend_from_slice(&planes);
                all.extend(std::iter::once(next).chain(planes_in).take(MAX_VARYINGS - INLINE_VARYINGS));
                Planes::Heap { planes: all.into_boxed_slice() }
            }
        };
        Varyings { over_w, inv_w }
    }
}

impl<P: Interpolant> Varyings<P> {
    /// How many scalar attributes are interpolated.
    pub fn len(&self) -> usize {
        self.planes().len()
    }

    /// Whether the planes are in an allocation of their own (more than
    /// [`INLINE_VARYINGS`]).
    #[inline(always)]
    pub fn on_heap(&self) -> bool {
        matches!(self.over_w, Planes::Heap { .. })
    }

    pub fn is_empty(&self) -> bool {
        self.planes().is_empty()
    }

    /// The planes of a/w.
    #[inline]
    pub fn planes(&self) -> &[P] {
        match &self.over_w {
            Planes::Inline { planes, len } => &planes[..*len as usize],
            Planes::Heap { planes } => planes,
        }
    }

    /// The attributes at (x, y), into `out`.
    #[inline]
    pub fn at(&self, x: f32, y: f32, out: &mut [f32]) {
        match &self.inv_w {
            Some(inv_w) => {
                let w = 1.0 / inv_w.at(x, y);
                for (o, p) in out.iter_mut().zip(self.planes()) {
                    *o = p.at(x, y) * w;
                }
            }
            None => {
                for (o, p) in out.iter_mut().zip(self.planes()) {
                    *o = p.at(x, y);
                }
            }
        }
    }

    /// Attributes `first .. first + out.len()` at the 16 points `(x[i], y[i])` of a block,
    /// into `out` (one lane array per attribute; attributes the primitive lacks are 0):
    /// lane for lane the arithmetic of [`Self::at`], so the same bits.
    #[inline(always)]
    pub fn lanes_at(&self, x: &F32s, y: &F32s, first: usize, out: &mut [F32s]) {
        let Some(inv_w) = &self.inv_w else {
            // Affine (the fast accuracy mode): the planes themselves.
            for (k, o) in out.iter_mut().enumerate() {
                *o = match self.planes().get(first + k) {
                    Some(p) => lanes(|i| p.at(x[i], y[i])),
                    None => [0.0; LANES],
                };
            }
            return;
        };
        let q: F32s = lanes(|i| inv_w.at(x[i], y[i]));
        let w: F32s = lanes(|i| 1.0 / q[i]);
        for (k, o) in out.iter_mut().enumerate() {
            *o = match self.planes().get(first + k) {
                Some(p) => lanes(|i| p.at(x[i], y[i]) * w[i]),
                None => [0.0; LANES],
            };
        }
    }
}

/// The varyings of a point, one value each over the whole point, inline (the first as many
/// as the draw has; the rest are zero and never read: the fragment stages ask for the
/// draw's count).
pub type PointVaryings = [f32; MAX_VARYINGS];

/// The values of `values` (at most [`MAX_VARYINGS`]) as [`PointVaryings`].
#[inline]
pub fn point_varyings(values: impl IntoIterator<Item = f32>) -> PointVaryings {
    let mut out = [0.0; MAX_VARYINGS];
    out.iter_mut().zip(values).for_each(|(o, v)| *o = v);
    out
}

/// `a(x, y) = a0 + dadx·(x − x0) + dady·(y − y0)` around the anchor `(x0, y0)`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Plane {
    pub a0: f32,
    pub dadx: f32,
    pub dady: f32,
}

impl Plane {
    /// The plane through three values at three points (in pixels, relative to the anchor at
    /// the first point).
    pub fn through(d1: [f64; 2], d2: [f64; 2], values: [f32; 3]) -> Plane {
        let det = d1[0] * d2[1] - d2[0] * d1[1];
        let (v0, v1, v2) = (values[0] as f64, values[1] as f64, values[2] as f64);
        let (dv1, dv2) = (v1 - v0, v2 - v0);
        Plane {
            a0: values[0],
            dadx: ((dv1 * d2[1] - dv2 * d1[1]) / det) as f32,
            dady: ((d1[0] * dv2 - d2[0] * dv1) / det) as f32,
        }
    }

    /// [`Plane::through`] for `N` sets of values at once: the same operations on the same
    /// operands (so the same bits), written as loops over the planes that the compiler
    /// vectorises, the divisions included (a triangle's setup divides twice per plane).
    #[inline(always)]
    pub fn through_all<const N: usize>(d1: [f64; 2], d2: [f64; 2], values: [[f32; 3]; N]) -> [Plane; N] {
        let det = d1[0] * d2[1] - d2[0] * d1[1];
        let dv1: [f64; N] = values.map(|v| v[1] as f64 - v[0] as f64);
        let dv2: [f64; N] = values.map(|v| v[2] as f64 - v[0] as f64);
        let dadx: [f64; N] = std::array::from_fn(|k| (dv1[k] * d2[1] - dv2[k] * d1[1]) / det);
        let dady: [f64; N] = std::array::from_fn(|k| (d1[0] * dv2[k] - d2[0] * dv1[k]) / det);
        std::array::from_fn(|k| Plane { a0: values[k][0], dadx: dadx[k] as f32, dady: dady[k] as f32 })
    }

    #[inline]
    pub fn at(&self, dx: f32, dy: f32) -> f32 {
        self.a0 + self.dadx * dx + self.dady * dy
    }
}

impl Interpolant for Plane {
    #[inline]
    fn at(&self, dx: f32, dy: f32) -> f32 {
        Plane::at(self, dx, dy)
    }
}

impl Interpolant for super::line::LinePlane {
    #[inline]
    fn at(&self, px: f32, py: f32) -> f32 {
        super::line::LinePlane::at(self, px, py)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn varyings_inline_or_on_the_heap_hold_every_plane_in_order() {
        // Every count up to MAX_VARYINGS (inline up to INLINE_VARYINGS, then one allocation),
        // and more than MAX_VARYINGS (the rest dropped): the planes come back in order and
        // evaluate to their own values.
        for n in 0..=MAX_VARYINGS + 2 {
            let planes = (0..n).map(|k| Plane { a0: k as f32, dadx: 0.5, dady: -0.25 });
            let v = Varyings::new(planes.clone(), Plane { a0: 2.0, dadx: 0.0, dady: 0.0 });
            let kept = n.min(MAX_VARYINGS);
            assert_eq!(v.len(), kept);
            assert_eq!(v.planes(), &planes.take(kept).collect::<Vec<_>>()[..]);
            let mut out = vec![f32::NAN; kept];
            v.at(2.0, 4.0, &mut out);
            // (k + 0.5·2 − 0.25·4) / 2 = k / 2.
            assert_eq!(out, (0..kept).map(|k| k as f32 / 2.0).collect::<Vec<_>>(), "{n} planes");
        }
        assert!(Varyings::<Plane>::default().is_empty());
    }
}
