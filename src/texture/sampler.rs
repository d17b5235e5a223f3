//! Sampling a texture (GL 2.1 §3.8.8-§3.8.9): a [`Sampler`] is compiled per draw from a
//! complete texture object, its levels shared with the object (`Arc`), and answers one
//! texture lookup at a time given the coordinates and their screen-space derivatives.
//!
//! Level of detail: ρ is the largest scaled derivative, `max(|∂u/∂x|, |∂v/∂x|, |∂w/∂x|,
//! |∂u/∂y|, …)` (llvmpipe's default approximation of the spec's lengths), with derivatives
//! taken per 2×2 quad as llvmpipe does; λ = log₂ ρ + bias, clamped to [min_lod, max_lod].
//!
//! Filtering of RGBA8 images uses 8-bit fixed-point weights as llvmpipe's AoS path does: the
//! texel position is taken to 1/256 of a texel and the lerps are integer; depth images (and
//! depth comparison) filter in float, decoding each texel from the depth-buffer encoding the
//! image is stored in (`super::depth_texel`).
use super::{depth_texel, srgb_to_linear, BaseFormat, DepthStencilPixels, TexImage, Texels};
use crate::framebuffer::format::DepthEncoding::Unorm;
use crate::gl::CompareFunc;
use std::sync::Arc;

/// Dimensionality of a texture target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Dim {
    D1,
    D2,
    D3,
    Cube,
}

impl Dim {
    /// Coordinates that address the image (1, 2 or 3; cube maps are addressed by 2 per face).
    pub fn coords(self) -> usize {
        match self {
            Dim::D1 => 1,
            Dim::D2 | Dim::Cube => 2,
            Dim::D3 => 3,
        }
    }
}

/// A wrap mode (GL_TEXTURE_WRAP_S/T/R).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Wrap {
    Repeat,
    Clamp,
    ClampToEdge,
    ClampToBorder,
    MirroredRepeat,
}

/// A filter within one level.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Filter {
    Nearest,
    Linear,
}

/// What a depth texture returns: GL_DEPTH_TEXTURE_MODE.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthMode {
    Luminance,
    Intensity,
    Alpha,
}

/// A compiled texture lookup.
#[derive(Clone, Debug)]
pub struct Sampler {
    pub dim: Dim,
    /// `faces[face][k]`: level base + k of each face (one face unless a cube map).
    pub faces: Vec<Vec<Arc<TexImage>>>,
    pub wrap: [Wrap; 3],
    pub mag: Filter,
    pub min: Filter,
    /// The mipmap filter of the minification filter, `None` without mipmapping.
    pub mip: Option<Filter>,
    /// The border color in the image's texture-color form.
    pub border: [f32; 4],
    /// Texture object bias plus the unit's GL_TEXTURE_LOD_BIAS (clamped).
    pub lod_bias: f32,
    /// The bias argument of a shader's lookup (`texture2D(s, c, bias)`), added to log₂ ρ
    /// before `lod_bias`, as llvmpipe adds them (0 for every other lookup: then exact).
    pub shader_bias: f32,
    pub min_lod: f32,
    pub max_lod: f32,
    /// GL_TEXTURE_COMPARE_MODE COMPARE_R_TO_TEXTURE on a depth image.
    pub compare: Option<CompareFunc>,
    pub depth_mode: DepthMode,
    /// The base format of the base level (for the texture environment).
    pub base: BaseFormat,
}

/// The levels a lookup reads: one, with the magnification or minification filter, or two
/// blended by the fraction of λ (with the minification filter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Levels {
    One(usize, Filter),
    Two(usize, usize, f32),
}

/// The texels of one lookup and their weights along one axis.
#[derive(Clone, Copy, Debug)]
pub(super) struct Axis {
    pub(super) i0: i32,
    pub(super) i1: i32,
    /// Weight of `i1` in 1/256 (0 for nearest).
    pub(super) w: i32,
    /// The same weight as a float.
    wf: f32,
}

/// The fixed-point position of a coordinate in texels: 8 fractional bits, rounded to
/// nearest even as llvmpipe's float → int conversion does.
#[inline]
pub(super) fn fixed(u: f32) -> i32 {
    let v = u * 256.0;
    // The common case first: the clamp matters only beyond 2²².
    if v.abs() < 4_194_304.0 {
        round_even_i32(v)
    } else {
        round_even_i32(v.clamp(-1.0e9, 1.0e9))
    }
}

/// `v` rounded to the nearest integer, ties to even, for |v| ≤ 10⁹ (no libm, no SSE4.1):
/// below 2²² adding 1.5·2²³ leaves the rounded integer in the low mantissa bits (the
/// addition rounds to nearest even, and the magic number is even); from 2²² on the
/// bit-exact [`round_even`](crate::pixel::convert::round_even) does it.
#[inline(always)]
pub(super) fn round_even_i32(v: f32) -> i32 {
    const MAGIC: f32 = 12_582_912.0;
    if v.abs() < 4_194_304.0 {
        ((v + MAGIC).to_bits() as i32).wrapping_sub(MAGIC.to_bits() as i32)
    } else {
        crate::pixel::convert::round_even(v) as i32
    }
}

/// ⌊u⌋ clamped to ±10⁹, for finite `u`: truncation, one less where it went up.
#[inline(always)]
pub(super) fn floor_i32(u: f32) -> i32 {
    let c = u.clamp(-1.0e9, 1.0e9);
    let t = c as i32;
    t - i32::from(t as f32 > c)
}

/// ⌊x⌋ exactly as IEEE `floor` (signed zeros, infinities and NaN included), from
/// truncation: no libm call (`floorf` is one without SSE4.1).
#[inline]
pub fn floor(x: f32) -> f32 {
    // From 2²³ on every float is an integer (and NaN and the infinities are themselves).
    if x.is_nan() || x.abs() >= 8_388_608.0 {
        return x;
    }
    let t = (x as i32 as f32).copysign(x);
    if t > x {
        t - 1.0
    } else {
        t
    }
}

/// ⌈x⌉ exactly as IEEE `ceil`: −⌊−x⌋.
#[inline]
pub fn ceil(x: f32) -> f32 {
    -floor(-x)
}

/// log₂ x from IEEE double arithmetic only (no libm, so the same bits on every CPU):
/// exponent plus 2·atanh((m − 1)/(m + 1))/ln 2 of the mantissa m ∈ [√½, √2), whose series
/// is summed to about 10⁻¹⁷, then rounded once to f32; exact at powers of two, within
/// half an ulp (plus a 10⁻¹⁶ relative) elsewhere. Zero gives −∞, negatives NaN.
pub fn log2(x: f32) -> f32 {
    if x.is_nan() || x <= 0.0 || x == f32::INFINITY {
        return if x == 0.0 {
            f32::NEG_INFINITY
        } else if x > 0.0 {
            x
        } else {
            f32::NAN
        };
    }
    let (mut bits, mut e) = (x.to_bits(), 0i32);
    if bits < 0x0080_0000 {
        // Subnormal: scale by 2³² (exactly) into the normal range.
        bits = (x * 4_294_967_296.0).to_bits();
        e = -32;
    }
    e += (bits >> 23) as i32 - 127;
    let mut m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000) as f64;
    if m > std::f64::consts::SQRT_2 {
        m *= 0.5;
        e += 1;
    }
    let s = (m - 1.0) / (m + 1.0);
    let s2 = s * s;
    // |s| ≤ 0.1716, s² ≤ 0.0295: ten terms of s·Σ s²ᵏ/(2k + 1).
    let mut p = 1.0 / 21.0;
    for k in (0..10).rev() {
        p = p * s2 + 1.0 / (2 * k + 1) as f64;
    }
    let ln = 2.0 * s * p;
    (e as f64 + ln * std::f64::consts::LOG2_E) as f32
}

/// Mirrors `s` for GL_MIRRORED_REPEAT: `s − floor(s)` on even periods, `1 − (s − floor(s))`
/// on odd ones.
#[inline]
pub(super) fn mirror(s: f32) -> f32 {
    let f = floor(s);
    let frac = s - f;
    if (f as i64).rem_euclid(2) == 0 {
        frac
    } else {
        1.0 - frac
    }
}

/// The texel indices of coordinate `s` along an axis of `size` texels (border excluded).
/// Indices may be −1 or `size` for the border; [`Sampler`] maps them.
#[inline(always)]
pub(super) fn axis(s: f32, size: i32, wrap: Wrap, filter: Filter) -> Axis {
    let sizef = size as f32;
    let s = match wrap {
        Wrap::Clamp => s.clamp(0.0, 1.0),
        Wrap::MirroredRepeat => mirror(s),
        _ => s,
    };
    match filter {
        Filter::Nearest => {
            let u = s * sizef;
            let i = if u.is_finite() { floor_i32(u) } else { 0 };
            let i = match wrap {
                Wrap::Repeat => repeat(i, size),
                Wrap::Clamp | Wrap::ClampToEdge | Wrap::MirroredRepeat => i.clamp(0, size - 1),
                Wrap::ClampToBorder => i.clamp(-1, size),
            };
            Axis { i0: i, i1: i, w: 0, wf: 0.0 }
        }
        Filter::Linear => {
            let u = if s.is_finite() { s * sizef - 0.5 } else { 0.0 };
            let f = fixed(u);
            let (i0, w) = (f >> 8, f & 0xff);
            let (i0, i1) = match wrap {
                Wrap::Repeat => (repeat(i0, size), repeat(i0 + 1, size)),
                Wrap::ClampToEdge | Wrap::MirroredRepeat => (i0.clamp(0, size - 1), (i0 + 1).clamp(0, size - 1)),
                Wrap::Clamp | Wrap::ClampToBorder => (i0.clamp(-1, size), (i0 + 1).clamp(-1, size)),
            };
            Axis { i0, i1, w, wf: w as f32 / 256.0 }
        }
    }
}

/// As [`axis`], with the weight the float fraction of the texel position (llvmpipe's SoA
/// filtering: `u = s·size − ½`, `i₀ = ⌊u⌋`, weight `u − ⌊u⌋`), for linear filtering.
pub(super) fn float_axis(s: f32, size: i32, wrap: Wrap, filter: Filter) -> Axis {
    if filter == Filter::Nearest {
        return axis(s, size, wrap, filter);
    }
    let s = match wrap {
        Wrap::Clamp => s.clamp(0.0, 1.0),
        Wrap::MirroredRepeat => mirror(s),
        _ => s,
    };
    let u = if s.is_finite() { s * size as f32 - 0.5 } else { 0.0 };
    let whole = floor(u);
    let i0 = whole.clamp(-1.0e9, 1.0e9) as i32;
    let (i0, i1) = match wrap {
        Wrap::Repeat => (repeat(i0, size), repeat(i0 + 1, size)),
        Wrap::ClampToEdge | Wrap::MirroredRepeat => (i0.clamp(0, size - 1), (i0 + 1).clamp(0, size - 1)),
        Wrap::Clamp | Wrap::ClampToBorder => (i0.clamp(-1, size), (i0 + 1).clamp(-1, size)),
    };
    Axis { i0, i1, w: 0, wf: u - whole }
}

/// `a + w·(b − a)` per channel with one fused multiply-add, as llvmpipe's float lerp
/// (`lp_build_mad`, fused on machines with FMA as Mesa's reference runs; exact here on every
/// machine).
#[inline]
fn lerp_fused(a: [f32; 4], b: [f32; 4], w: f32) -> [f32; 4] {
    std::array::from_fn(|k| w.mul_add(b[k] - a[k], a[k]))
}

/// `i` modulo `size` (> 0), in [0, size): GL_REPEAT's index. Most indices are in range
/// already, and most sizes are powers of two: no division for either.
#[inline(always)]
pub(super) fn repeat(i: i32, size: i32) -> i32 {
    if (i as u32) < size as u32 {
        i
    } else if size & (size - 1) == 0 {
        i & (size - 1)
    } else {
        i.rem_euclid(size)
    }
}

/// log₂ x approximated as llvmpipe's `lp_build_fast_log2`: the exponent plus the mantissa
/// minus one (exact at powers of two, linear in between).
#[inline]
pub fn fast_log2(x: f32) -> f32 {
    if x.is_nan() || x <= 0.0 || !x.is_finite() {
        return log2(x);
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32 - 127;
    let mantissa = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    exponent as f32 + mantissa - 1.0
}

/// Integer lerp of 8-bit values with a weight in 1/256, rounded to nearest (llvmpipe's).
#[inline]
fn lerp8(a: i32, b: i32, w: i32) -> i32 {
    a + (((b - a) * w + 128) >> 8)
}

/// Cube map face selection (GL 2.1 table 3.21): the face index (+X, −X, +Y, −Y, +Z, −Z) and
/// the 2D coordinates on it.
pub fn cube_face(s: f32, t: f32, r: f32) -> (usize, f32, f32, f32) {
    let (ax, ay, az) = (s.abs(), t.abs(), r.abs());
    let (face, sc, tc, ma) = if ax >= ay && ax >= az {
        if s >= 0.0 {
            (0, -r, -t, ax)
        } else {
            (1, r, -t, ax)
        }
    } else if ay >= az {
        if t >= 0.0 {
            (2, s, r, ay)
        } else {
            (3, s, -r, ay)
        }
    } else if r >= 0.0 {
        (4, s, -t, az)
    } else {
        (5, -s, -t, az)
    };
    let inv = if ma > 0.0 { 0.5 / ma } else { 0.0 };
    (face, sc * inv + 0.5, tc * inv + 0.5, ma)
}

impl Sampler {
    /// Whether two samplers look up alike: the very same images (shared, not compared
    /// texel by texel) read with the same parameters. Draw states are reused by this test,
    /// so a parameter it left out would let a draw sample with an earlier draw's wrap modes.
    pub fn same_lookup(&self, other: &Sampler) -> bool {
        let bits = |s: &Sampler| {
            [s.lod_bias, s.shader_bias, s.min_lod, s.max_lod, s.border[0], s.border[1], s.border[2], s.border[3]]
                .map(f32::to_bits)
        };
        self.dim == other.dim
            && self.wrap == other.wrap
            && self.mag == other.mag
            && self.min == other.min
            && self.mip == other.mip
            && self.compare == other.compare
            && self.depth_mode == other.depth_mode
            && self.base == other.base
            && bits(self) == bits(other)
            && self.faces.len() == other.faces.len()
            && self
                .faces
                .iter()
                .zip(&other.faces)
                .all(|(x, y)| x.len() == y.len() && x.iter().zip(y).all(|(p, q)| Arc::ptr_eq(p, q)))
    }

    /// The texture color of coordinates `c` (s, t, r already divided by q), given their
    /// derivatives along x and y (`ddx`, `ddy`, in coordinate units per pixel).
    pub fn sample(&self, c: [f32; 3], ddx: [f32; 3], ddy: [f32; 3]) -> [f32; 4] {
        let (face, coords) = match self.dim {
            Dim::Cube => {
                let (face, s, t, _) = cube_face(c[0], c[1], c[2]);
                (face, [s, t, c[2]])
            }
            _ => (0, c),
        };
        let levels = &self.faces[face.min(self.faces.len() - 1)];
        let lambda = self.lambda(&levels[0], ddx, ddy, c);
        match self.levels(lambda, levels.len()) {
            Levels::One(d, filter) => self.filter_level(&levels[d], coords, filter),
            Levels::Two(d1, d2, frac) => {
                let a = self.filter_level_raw(&levels[d1], coords, self.min);
                let b = self.filter_level_raw(&levels[d2], coords, self.min);
                match (a, b) {
                    (Ok(a), Ok(b)) => {
                        let w = (frac * 256.0) as i32;
                        std::array::from_fn(|k| lerp8(a[k], b[k], w) as f32 * (1.0 / 255.0))
                    }
                    // sRGB levels blend as llvmpipe's float lerp does (fused).
                    (Err(a), Err(b)) if levels[d1].srgb => lerp_fused(a, b, frac),
                    (Err(a), Err(b)) => std::array::from_fn(|k| a[k] + frac * (b[k] - a[k])),
                    // Every level of a complete texture has the same format.
                    (a, _) => a.map_or_else(|f| f, |v| v.map(|x| x as f32 / 255.0)),
                }
            }
        }
    }

    /// The level or levels (of `count`) a lookup at level of detail `lambda` reads, and
    /// with which filter (§3.8.8, §3.8.9).
    #[inline]
    pub(super) fn levels(&self, lambda: f32, count: usize) -> Levels {
        // c: the magnification/minification switch-over point (§3.8.9).
        let switch = if self.mag == Filter::Linear && self.mip == Some(Filter::Nearest) && self.min == Filter::Nearest {
            0.5
        } else {
            0.0
        };
        let last = (count - 1) as f32;
        if lambda <= switch || lambda.is_nan() {
            return Levels::One(0, self.mag);
        }
        match self.mip {
            None => Levels::One(0, self.min),
            Some(Filter::Nearest) => {
                let d = if lambda <= 0.5 { 0.0 } else { (ceil(lambda + 0.5) - 1.0).min(last) };
                Levels::One(d as usize, self.min)
            }
            Some(Filter::Linear) => {
                let whole = floor(lambda);
                let d1 = whole.min(last);
                let d2 = (d1 + 1.0).min(last);
                let frac = lambda - whole;
                if d1 == d2 || frac == 0.0 {
                    Levels::One(d1 as usize, self.min)
                } else {
                    Levels::Two(d1 as usize, d2 as usize, frac)
                }
            }
        }
    }

    /// λ: log₂ of the largest scaled derivative, biased and clamped.
    pub(super) fn lambda(&self, base: &TexImage, ddx: [f32; 3], ddy: [f32; 3], c: [f32; 3]) -> f32 {
        let b2 = 2 * base.border;
        let mut size = [(base.width - b2) as f32, (base.height - b2.min(base.height - 1)) as f32, 1.0];
        let dims = self.dim.coords();
        if self.dim == Dim::D3 {
            size[2] = (base.depth - b2) as f32;
        }
        // ρ² = the larger squared length of the scaled derivative vectors along x and y.
        let scale: [f32; 3] = if self.dim == Dim::Cube {
            // Derivatives on the face: the major axis scales the others by 1/(2|ma|).
            let (_, _, _, ma) = cube_face(c[0], c[1], c[2]);
            let k = if ma > 0.0 { size[0] * 0.5 / ma } else { 0.0 };
            [k; 3]
        } else {
            std::array::from_fn(|k| if k < dims { size[k] } else { 0.0 })
        };
        let length2 = |d: [f32; 3]| (0..3).map(|k| (d[k] * scale[k]) * (d[k] * scale[k])).sum::<f32>();
        let rho2 = length2(ddx).max(length2(ddy));
        // With a mipmap blend, llvmpipe takes log₂ piecewise linearly between powers of two
        // (exponent plus mantissa − 1) of ρ², and halves it; the level choice of the other
        // filters is exact.
        let half_log2 = if self.mip == Some(Filter::Linear) { 0.5 * fast_log2(rho2) } else { 0.5 * log2(rho2) };
        // As `f32::clamp`, without its panic when GL_TEXTURE_MIN_LOD > GL_TEXTURE_MAX_LOD
        // (then the maximum wins, as in llvmpipe); NaN stays NaN.
        let mut lambda = (half_log2 + self.shader_bias) + self.lod_bias;
        if lambda < self.min_lod {
            lambda = self.min_lod;
        }
        if lambda > self.max_lod {
            lambda = self.max_lod;
        }
        lambda
    }

    /// One filtered lookup in one image.
    fn filter_level(&self, img: &TexImage, c: [f32; 3], filter: Filter) -> [f32; 4] {
        match self.filter_level_raw(img, c, filter) {
            Ok(v) => v.map(|x| x as f32 / 255.0),
            Err(f) => f,
        }
    }

    /// One filtered lookup: 8-bit values from RGBA8 images (`Ok`), floats from depth ones.
    #[inline]
    fn filter_level_raw(&self, img: &TexImage, c: [f32; 3], filter: Filter) -> Result<[i32; 4], [f32; 4]> {
        let b = img.border as i32;
        let dims = self.dim.coords();
        let size = [img.width as i32 - 2 * b, if dims >= 2 { img.height as i32 - 2 * b } else { 1 }, {
            if dims >= 3 {
                img.depth as i32 - 2 * b
            } else {
                1
            }
        }];
        let wrap = |k: usize| if self.dim == Dim::Cube { Wrap::ClampToEdge } else { self.wrap[k] };
        let ax = axis(c[0], size[0], wrap(0), filter);
        let ay = if dims >= 2 { axis(c[1], size[1], wrap(1), filter) } else { Axis { i0: 0, i1: 0, w: 0, wf: 0.0 } };
        let az = if dims >= 3 { axis(c[2], size[2], wrap(2), filter) } else { Axis { i0: 0, i1: 0, w: 0, wf: 0.0 } };
        // Index of a texel, or None for the border color.
        let at = |x: i32, y: i32, z: i32| -> Option<usize> {
            let inside = |i: i32, n: i32, k: usize| k >= dims || (i >= -b && i < n + b);
            if !(inside(x, size[0], 0) && inside(y, size[1], 1) && inside(z, size[2], 2)) {
                return None;
            }
            let by = if dims >= 2 { b } else { 0 };
            let bz = if dims >= 3 { b } else { 0 };
            Some(img.index((x + b) as usize, (y + by) as usize, (z + bz) as usize))
        };
        match (&img.texels, self.compare) {
            (Texels::Rgba8(t), _) if img.srgb => {
                // Each texel decoded to linear (alpha as unorm), then filtered in float as
                // llvmpipe's SoA path filters formats that do not fit 8-bit unorm: weights
                // the float fractions of the texel positions, not 8-bit ones.
                let float_axis =
                    |k: usize, a: Axis| if k < dims { float_axis(c[k], size[k], wrap(k), filter) } else { a };
                let (ax, ay, az) = (float_axis(0, ax), float_axis(1, ay), float_axis(2, az));
                let lookup = FloatLookup { at: &at, ax, ay, az, dims, filter };
                let decode = |p: [u8; 4]| {
                    [srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2]), p[3] as f32 * (1.0 / 255.0)]
                };
                Err(lookup.filter(self.border, |i| decode(t[i])))
            }
            (Texels::Rgba8(t), _) => {
                let border8 = self.border.map(|c| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as i32);
                // Repeat, edge clamping and mirroring keep every index inside a borderless
                // image: no border test and no Option per texel.
                let inside_only = b == 0 && (0..dims).all(|k| !matches!(wrap(k), Wrap::Clamp | Wrap::ClampToBorder));
                let (w, h) = (img.width, img.height);
                let fetch = |x: i32, y: i32, z: i32| {
                    if inside_only {
                        let p = t[(z as usize * h + y as usize) * w + x as usize];
                        [p[0] as i32, p[1] as i32, p[2] as i32, p[3] as i32]
                    } else {
                        at(x, y, z).map_or(border8, |i| t[i].map(|c| c as i32))
                    }
                };
                let row = |y, z| -> [i32; 4] {
                    let (p, q) = (fetch(ax.i0, y, z), fetch(ax.i1, y, z));
                    std::array::from_fn(|k| lerp8(p[k], q[k], ax.w))
                };
                let plane = |z| -> [i32; 4] {
                    let (p, q) = (row(ay.i0, z), row(ay.i1, z));
                    std::array::from_fn(|k| lerp8(p[k], q[k], ay.w))
                };
                let v = if filter == Filter::Nearest {
                    fetch(ax.i0, ay.i0, az.i0)
                } else if dims == 1 {
                    row(0, 0)
                } else if dims == 2 {
                    plane(0)
                } else {
                    let (p, q) = (plane(az.i0), plane(az.i1));
                    std::array::from_fn(|k| lerp8(p[k], q[k], az.w))
                };
                Ok(v)
            }
            (Texels::Depth(t), compare) => {
                // Depth texels are stored as a depth buffer stores them; the decoding is
                // chosen once per lookup, not per texel.
                let lookup = DepthLookup { at: &at, ax, ay, az, dims, filter, compare, reference: c_ref(c, self.dim) };
                let border = self.border[0];
                let d = match t.pixels() {
                    DepthStencilPixels::Depth16(px) => lookup.filter(border, |i| depth_texel(Unorm(16), px[i] as u32)),
                    DepthStencilPixels::Packed24(px) => {
                        lookup.filter(border, |i| depth_texel(Unorm(24), px[i] & 0x00ff_ffff))
                    }
                    DepthStencilPixels::Depth32(px, _) => {
                        let encoding = t.depth_encoding();
                        lookup.filter(border, |i| depth_texel(encoding, px[i]))
                    }
                    DepthStencilPixels::None => border,
                };
                Err(match self.depth_mode {
                    DepthMode::Luminance => [d, d, d, 1.0],
                    DepthMode::Intensity => [d; 4],
                    DepthMode::Alpha => [0.0, 0.0, 0.0, d],
                })
            }
        }
    }
}

/// One filtered lookup in a depth image: where its texels are and how they combine.
struct DepthLookup<'a, A: Fn(i32, i32, i32) -> Option<usize>> {
    /// The index of a texel, `None` for the border.
    at: &'a A,
    ax: Axis,
    ay: Axis,
    az: Axis,
    dims: usize,
    filter: Filter,
    compare: Option<CompareFunc>,
    reference: f32,
}

impl<A: Fn(i32, i32, i32) -> Option<usize>> DepthLookup<'_, A> {
    /// The filtered depth (or comparison result), texel `i` being `texel(i)`.
    #[inline]
    fn filter(&self, border: f32, texel: impl Fn(usize) -> f32) -> f32 {
        let (ax, ay, az) = (self.ax, self.ay, self.az);
        let fetch = |x, y, z| -> f32 {
            let d = (self.at)(x, y, z).map_or(border, &texel);
            match self.compare {
                Some(func) => {
                    if depth_passes(func, self.reference, d) {
                        1.0
                    } else {
                        0.0
                    }
                }
                None => d,
            }
        };
        let lerp = |a: f32, b: f32, w: f32| a + w * (b - a);
        let row = |y, z| lerp(fetch(ax.i0, y, z), fetch(ax.i1, y, z), ax.wf);
        let plane = |z| lerp(row(ay.i0, z), row(ay.i1, z), ay.wf);
        if self.filter == Filter::Nearest {
            fetch(ax.i0, ay.i0, az.i0)
        } else if self.dims == 1 {
            row(0, 0)
        } else if self.dims == 2 {
            plane(0)
        } else {
            lerp(plane(az.i0), plane(az.i1), az.wf)
        }
    }
}

/// One filtered lookup of RGBA float texels (decoded sRGB images): where its texels are and
/// how they combine, as [`DepthLookup`] combines depths.
struct FloatLookup<'a, A: Fn(i32, i32, i32) -> Option<usize>> {
    /// The index of a texel, `None` for the border.
    at: &'a A,
    ax: Axis,
    ay: Axis,
    az: Axis,
    dims: usize,
    filter: Filter,
}

impl<A: Fn(i32, i32, i32) -> Option<usize>> FloatLookup<'_, A> {
    /// The filtered color, texel `i` being `texel(i)`, the border `border`.
    #[inline]
    fn filter(&self, border: [f32; 4], texel: impl Fn(usize) -> [f32; 4]) -> [f32; 4] {
        let (ax, ay, az) = (self.ax, self.ay, self.az);
        let fetch = |x, y, z| (self.at)(x, y, z).map_or(border, &texel);
        let lerp = |a: [f32; 4], b: [f32; 4], w: f32| -> [f32; 4] { lerp_fused(a, b, w) };
        let row = |y, z| lerp(fetch(ax.i0, y, z), fetch(ax.i1, y, z), ax.wf);
        let plane = |z| lerp(row(ay.i0, z), row(ay.i1, z), ay.wf);
        if self.filter == Filter::Nearest {
            fetch(ax.i0, ay.i0, az.i0)
        } else if self.dims == 1 {
            row(0, 0)
        } else if self.dims == 2 {
            plane(0)
        } else {
            lerp(plane(az.i0), plane(az.i1), az.wf)
        }
    }
}

/// The reference value of a depth comparison: r (the third coordinate) for 1D and 2D
/// textures, clamped to [0, 1] as fixed-point depth formats require.
fn c_ref(c: [f32; 3], _dim: Dim) -> f32 {
    c[2].clamp(0.0, 1.0)
}

/// Whether the comparison `r func d` holds (GL_TEXTURE_COMPARE_FUNC).
#[inline]
pub fn depth_passes(func: CompareFunc, r: f32, d: f32) -> bool {
    match func {
        CompareFunc::Never => false,
        CompareFunc::Less => r < d,
        CompareFunc::Equal => r == d,
        CompareFunc::LessEqual => r <= d,
        CompareFunc::Greater => r > d,
        CompareFunc::NotEqual => r != d,
        CompareFunc::GreaterEqual => r >= d,
        CompareFunc::Always => true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(w: usize, h: usize, texels: Vec<[u8; 4]>) -> Arc<TexImage> {
        Arc::new(TexImage {
            width: w,
            height: h,
            depth: 1,
            border: 0,
            base: BaseFormat::Rgba,
            texels: Texels::Rgba8(texels),
            srgb: false,
        })
    }

    fn sampler(levels: Vec<Arc<TexImage>>, wrap: Wrap, filter: Filter) -> Sampler {
        Sampler {
            dim: Dim::D2,
            faces: vec![levels],
            wrap: [wrap; 3],
            mag: filter,
            min: filter,
            mip: None,
            border: [0.0, 0.0, 1.0, 1.0],
            lod_bias: 0.0,
            shader_bias: 0.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            compare: None,
            depth_mode: DepthMode::Luminance,
            base: BaseFormat::Rgba,
        }
    }

    const ZERO: [f32; 3] = [0.0; 3];

    #[test]
    fn wrap_modes_address_the_right_texels() {
        let img = image(2, 1, vec![[255, 0, 0, 255], [0, 255, 0, 255]]);
        let red = [1.0, 0.0, 0.0, 1.0];
        let green = [0.0, 1.0, 0.0, 1.0];
        let blue = [0.0, 0.0, 1.0, 1.0];
        let s = |wrap, x: f32| sampler(vec![img.clone()], wrap, Filter::Nearest).sample([x, 0.5, 0.0], ZERO, ZERO);
        assert_eq!(s(Wrap::Repeat, 1.25), red);
        assert_eq!(s(Wrap::Repeat, -0.25), green);
        assert_eq!(s(Wrap::ClampToEdge, 7.0), green);
        assert_eq!(s(Wrap::ClampToBorder, 1.2), blue);
        assert_eq!(s(Wrap::ClampToBorder, -0.01), blue);
        assert_eq!(s(Wrap::MirroredRepeat, 1.25), green);
        assert_eq!(s(Wrap::MirroredRepeat, 1.75), red);
        assert_eq!(s(Wrap::Clamp, 1.5), green);
    }

    #[test]
    fn linear_filtering_uses_8_bit_weights() {
        let img = image(2, 1, vec![[0, 0, 0, 0], [255, 255, 255, 255]]);
        let lin = |wrap, x: f32| sampler(vec![img.clone()], wrap, Filter::Linear).sample([x, 0.5, 0.0], ZERO, ZERO);
        // Between the two texel centres: a quarter of the way (255 · 64 / 256 rounded).
        assert_eq!(lin(Wrap::ClampToEdge, 0.375)[0], 64.0 / 255.0);
        assert_eq!(lin(Wrap::ClampToEdge, 0.5)[0], 128.0 / 255.0);
        // A weight of 1/512 texel rounds to 1/256 (half to even: 0.5 → 0, 1.5 → 2).
        assert_eq!(lin(Wrap::ClampToEdge, 0.25 + 1.5 / 512.0)[0], 2.0 / 255.0);
        assert_eq!(lin(Wrap::ClampToEdge, 0.25 + 0.5 / 512.0)[0], 0.0);
        // GL_CLAMP at the edge mixes in the border color half and half.
        assert_eq!(lin(Wrap::Clamp, 1.0), [128.0 / 255.0, 128.0 / 255.0, 1.0, 1.0]);
        // Repeat wraps the second texel to the first.
        assert_eq!(lin(Wrap::Repeat, 1.0)[0], 128.0 / 255.0);
    }

    #[test]
    fn mipmap_levels_follow_lambda() {
        let l0 = image(4, 4, vec![[255, 0, 0, 255]; 16]);
        let l1 = image(2, 2, vec![[0, 255, 0, 255]; 4]);
        let l2 = image(1, 1, vec![[0, 0, 255, 255]]);
        let mut s = sampler(vec![l0, l1, l2], Wrap::Repeat, Filter::Nearest);
        s.mip = Some(Filter::Nearest);
        let d = |rho: f32| [rho / 4.0, 0.0, 0.0];
        assert_eq!(s.sample([0.5; 3], d(1.0), ZERO), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(s.sample([0.5; 3], d(2.0), ZERO), [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(s.sample([0.5; 3], d(64.0), ZERO), [0.0, 0.0, 1.0, 1.0]);
        s.mip = Some(Filter::Linear);
        // ρ² = 2, λ = 0.5: halfway between red and green.
        let half = s.sample([0.5; 3], [0.25, 0.25, 0.0], ZERO);
        assert_eq!(half, [128.0 / 255.0, 128.0 / 255.0, 0.0, 1.0]);
        // ρ = 1.5: llvmpipe's λ is 0.5 · fast_log2(2.25) = 0.5625 (exact: 0.585), weight 144.
        let blend = s.sample([0.5; 3], [0.375, 0.0, 0.0], ZERO);
        assert_eq!(blend[1], (((255 * 144 + 128) >> 8) as f32) / 255.0);
        assert_eq!(fast_log2(2.25), 1.125);
    }

    #[test]
    fn depth_comparison_and_modes() {
        let mut img = TexImage::new_depth(2, 1, 1, 0, super::super::depth_storage(32, false, true)).unwrap();
        img.set_depth_f32(0, 0.25);
        img.set_depth_f32(1, 0.75);
        let img = Arc::new(img);
        let mut s = sampler(vec![img], Wrap::ClampToEdge, Filter::Linear);
        s.base = BaseFormat::Depth;
        s.compare = Some(CompareFunc::LessEqual);
        // r = 0.5: passes against 0.75 only; halfway between the texels gives 0.5.
        assert_eq!(s.sample([0.5, 0.5, 0.5], ZERO, ZERO), [0.5, 0.5, 0.5, 1.0]);
        s.depth_mode = DepthMode::Alpha;
        assert_eq!(s.sample([0.75, 0.5, 0.5], ZERO, ZERO), [0.0, 0.0, 0.0, 1.0]);
        s.compare = None;
        s.depth_mode = DepthMode::Intensity;
        assert_eq!(s.sample([0.25, 0.5, 0.0], ZERO, ZERO), [0.25; 4]);
    }

    #[test]
    fn floor_ceil_and_log2_without_libm() {
        let mut x = 0x1234_5678u32;
        let mut values = vec![0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.5, -2.5, 8_388_607.5, -8_388_607.5, 1.0e20, -1.0e20];
        values.extend([f32::INFINITY, f32::NEG_INFINITY, f32::MIN_POSITIVE, -f32::MIN_POSITIVE, 1.0e-40]);
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            values.push(f32::from_bits(x));
        }
        let mut off_by_an_ulp = 0;
        for &v in &values {
            if v.is_nan() {
                assert!(floor(v).is_nan() && ceil(v).is_nan() && log2(v).is_nan());
                continue;
            }
            assert_eq!(floor(v).to_bits(), v.floor().to_bits(), "floor {v}");
            assert_eq!(ceil(v).to_bits(), v.ceil().to_bits(), "ceil {v}");
            let (mine, libm) = (log2(v), v.log2());
            if libm.is_nan() {
                assert!(mine.is_nan());
            } else if mine != libm {
                // Within an ulp of the C library's (which is not correctly rounded either).
                assert_eq!((mine.to_bits() as i64 - libm.to_bits() as i64).abs(), 1, "log2 {v}");
                off_by_an_ulp += 1;
            }
        }
        assert!(off_by_an_ulp < values.len() / 1000, "{off_by_an_ulp}");
        for e in -149..128 {
            let power =
                if e >= -126 { f32::from_bits(((e + 127) as u32) << 23) } else { f32::from_bits(1 << (e + 149)) };
            assert_eq!(log2(power), e as f32);
        }
        assert_eq!(log2(0.0), f32::NEG_INFINITY);
    }

    #[test]
    fn min_lod_above_max_lod_takes_the_maximum() {
        let l0 = image(4, 4, vec![[255, 0, 0, 255]; 16]);
        let l1 = image(2, 2, vec![[0, 255, 0, 255]; 4]);
        let l2 = image(1, 1, vec![[0, 0, 255, 255]]);
        let mut s = sampler(vec![l0, l1, l2], Wrap::Repeat, Filter::Nearest);
        s.mip = Some(Filter::Nearest);
        (s.min_lod, s.max_lod) = (2.0, 1.0);
        assert_eq!(s.sample([0.5; 3], ZERO, ZERO), [0.0, 1.0, 0.0, 1.0]);
    }

    #[test]
    fn cube_faces_follow_the_major_axis() {
        assert_eq!(cube_face(1.0, 0.0, 0.0).0, 0);
        assert_eq!(cube_face(-1.0, 0.2, 0.1).0, 1);
        assert_eq!(cube_face(0.1, 1.0, 0.2).0, 2);
        assert_eq!(cube_face(0.1, -1.0, 0.2).0, 3);
        assert_eq!(cube_face(0.1, 0.2, 1.0).0, 4);
        assert_eq!(cube_face(0.1, 0.2, -1.0).0, 5);
        let (_, s, t, _) = cube_face(1.0, -0.5, 0.5);
        assert_eq!((s, t), (0.25, 0.75));
    }
}
