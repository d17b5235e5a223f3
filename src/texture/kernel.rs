//! Texture lookups a 2×2 quad at a time, with the work chosen once per draw: the level of
//! detail and the level choice once per quad (as llvmpipe computes them), and for the
//! common textures (2D RGBA8 without border, wrapped by repeat, edge clamping or
//! mirroring) a path with no per-fragment dispatch on format or border and texels
//! filtered four channels at once in one 64-bit word.
//!
//! 2D depth textures without border (shadow maps) have their own path: texels decoded from
//! the depth-buffer encoding they are stored in, compared against r when comparison is on,
//! and filtered in float, with no per-fragment dispatch on format, wrap or comparison.
//! A sampler whose level cannot depend on λ (no mipmaps, one filter for magnification and
//! minification, the usual shadow map) computes no λ at all.
//!
//! A 4×4 block of these textures runs in lane loops (`super::lanes`); the quad kernels here
//! answer the blocks the lanes leave ([`Kernel::sample_quads`]: quads that filter
//! differently, a depth level lent to the framebuffer being drawn) and every other texture,
//! and are the lanes' test oracle.
//!
//! Every kernel gives the very bits of [`Sampler::sample`], the reference lookup (which
//! remains the path of every other texture): the tests here compare them on random
//! coordinates.
//!
//! Filtering in one word: an RGBA8 texel spread to four 16-bit fields (`0x00AA_00BB_00GG_00RR`)
//! lerps all its channels with two multiplications, `(a·(256 − w) + b·w + 128) >> 8`,
//! which is llvmpipe's `a + ((b − a)·w + 128) >> 8` (the `256·a` is a whole multiple of 256)
//! and never carries between fields (at most 255·256 + 128 < 2¹⁶).
use super::sampler::{fixed, floor_i32, mirror, repeat, DepthMode, Dim, Filter, Levels, Sampler, Wrap};
use super::{depth_texel, DepthStencilPixels, TexImage, Texels};
use crate::framebuffer::format::DepthEncoding;
use crate::gl::CompareFunc;

/// The lookups of one stage, chosen when the draw compiles its texturing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kernel {
    /// Any texture: [`Sampler::sample`] per fragment, with the quad's derivatives.
    Reference,
    /// A 2D RGBA8 texture, borderless, wrapped by repeat, edge clamping or mirroring: every
    /// index the wrap gives is inside the image.
    Rgba2d,
    /// A 2D depth texture, borderless, wrapped by repeat, edge clamping or mirroring.
    Depth2d,
}

impl Kernel {
    /// The kernel for `sampler`.
    pub(super) fn choose(sampler: &Sampler) -> Kernel {
        let inside = |w: Wrap| matches!(w, Wrap::Repeat | Wrap::ClampToEdge | Wrap::MirroredRepeat);
        // sRGB images filter their decoded texels in float: the reference path.
        let rgba_borderless =
            |img: &TexImage| img.border == 0 && matches!(img.texels, Texels::Rgba8(_)) && img.depth == 1 && !img.srgb;
        let depth_borderless =
            |img: &TexImage| img.border == 0 && matches!(img.texels, Texels::Depth(_)) && img.depth == 1;
        let plain_2d = sampler.dim == Dim::D2
            && sampler.faces.len() == 1
            && !sampler.faces[0].is_empty()
            && inside(sampler.wrap[0])
            && inside(sampler.wrap[1]);
        if plain_2d && sampler.faces[0].iter().all(|l| rgba_borderless(l)) {
            Kernel::Rgba2d
        } else if plain_2d && sampler.faces[0].iter().all(|l| depth_borderless(l)) {
            Kernel::Depth2d
        } else {
            Kernel::Reference
        }
    }
}

/// u8 → f32 as `x as f32 / 255.0` (a lookup from one level) and as `x as f32 * (1.0 / 255.0)`
/// (a blend of two levels): they differ in the last bit for about half the values, and
/// each path keeps the reference's.
const DIV_255: [f32; 256] = {
    let mut t = [0.0; 256];
    let mut i = 0;
    while i < 256 {
        t[i] = i as f32 / 255.0;
        i += 1;
    }
    t
};
const MUL_255: [f32; 256] = {
    let mut t = [0.0; 256];
    let mut i = 0;
    while i < 256 {
        t[i] = i as f32 * (1.0 / 255.0);
        i += 1;
    }
    t
};

/// An RGBA8 texel in four 16-bit fields, red lowest.
#[inline(always)]
fn spread(p: [u8; 4]) -> u64 {
    let x = u32::from_le_bytes(p) as u64;
    let x = (x | (x << 16)) & 0x0000_ffff_0000_ffff;
    (x | (x << 8)) & 0x00ff_00ff_00ff_00ff
}

/// The four channels of a spread texel as floats, through `table`.
#[inline(always)]
fn unspread(x: u64, table: &[f32; 256]) -> [f32; 4] {
    [
        table[(x & 0xff) as usize],
        table[((x >> 16) & 0xff) as usize],
        table[((x >> 32) & 0xff) as usize],
        table[((x >> 48) & 0xff) as usize],
    ]
}

/// llvmpipe's 8-bit lerp on every field at once, weight `w` in 1/256 (0..=255).
#[inline(always)]
fn lerp(a: u64, b: u64, w: u64) -> u64 {
    ((a * (256 - w) + b * w + 0x0080_0080_0080_0080) >> 8) & 0x00ff_00ff_00ff_00ff
}

/// The size of one level of a borderless 2D image, as its lookups need it.
#[derive(Clone, Copy)]
struct Grid {
    size: [i32; 2],
    sizef: [f32; 2],
    /// `size − 1` for sides that are powers of two (GL_REPEAT is a mask), else −1.
    mask: [i32; 2],
}

impl Grid {
    #[inline(always)]
    fn of(img: &TexImage) -> Grid {
        let size = [img.width as i32, img.height as i32];
        Grid { size, sizef: size.map(|n| n as f32), mask: size.map(|n| if n & (n - 1) == 0 { n - 1 } else { -1 }) }
    }
}

/// One level of an RGBA8 2D image, borderless, with what its lookups need.
#[derive(Clone, Copy)]
struct Level2d<'a> {
    texels: &'a [[u8; 4]],
    width: i32,
    grid: Grid,
}

impl<'a> Level2d<'a> {
    #[inline(always)]
    fn of(img: &'a TexImage) -> Level2d<'a> {
        let texels = match &img.texels {
            Texels::Rgba8(t) => t.as_slice(),
            // Kernel::choose admits RGBA8 images only.
            Texels::Depth(_) => &[],
        };
        Level2d { texels, width: img.width as i32, grid: Grid::of(img) }
    }

    #[inline(always)]
    fn fetch(&self, x: i32, y: i32) -> u64 {
        spread(self.texels[y as usize * self.width as usize + x as usize])
    }
}

/// A wrap mode along one axis, as a type: the lookups of a quad are compiled for their
/// pair of modes, with nothing left to decide per fragment. Each gives `sampler::axis`'s
/// indices.
trait AxisWrap {
    /// The coordinate as the filter sees it (GL_MIRRORED_REPEAT folds it).
    #[inline(always)]
    fn fold(s: f32) -> f32 {
        s
    }
    /// The index of an integer texel position.
    fn index(i: i32, size: i32, mask: i32) -> i32;
}

struct Repeat;
struct Edge;
struct Mirror;

impl AxisWrap for Repeat {
    #[inline(always)]
    fn index(i: i32, size: i32, mask: i32) -> i32 {
        if mask >= 0 {
            i & mask
        } else {
            repeat(i, size)
        }
    }
}

impl AxisWrap for Edge {
    #[inline(always)]
    fn index(i: i32, size: i32, _: i32) -> i32 {
        i.clamp(0, size - 1)
    }
}

impl AxisWrap for Mirror {
    #[inline(always)]
    fn fold(s: f32) -> f32 {
        mirror(s)
    }
    #[inline(always)]
    fn index(i: i32, size: i32, _: i32) -> i32 {
        i.clamp(0, size - 1)
    }
}

/// The nearest texel's index along axis `k` of the folded coordinate `s`.
#[inline(always)]
fn nearest<W: AxisWrap>(level: &Grid, k: usize, s: f32) -> i32 {
    let u = s * level.sizef[k];
    let i = if u.is_finite() { floor_i32(u) } else { 0 };
    W::index(i, level.size[k], level.mask[k])
}

/// The two texels' indices along axis `k` of the folded coordinate `s`, and the weight
/// of the second in 1/256.
#[inline(always)]
fn linear<W: AxisWrap>(level: &Grid, k: usize, s: f32) -> (i32, i32, u64) {
    let u = if s.is_finite() { s * level.sizef[k] - 0.5 } else { 0.0 };
    let f = fixed(u);
    let i0 = f >> 8;
    let (size, mask) = (level.size[k], level.mask[k]);
    (W::index(i0, size, mask), W::index(i0 + 1, size, mask), (f & 0xff) as u64)
}

/// The filtered texel of one level at the folded coordinates (s, t).
#[inline(always)]
fn filter<X: AxisWrap, Y: AxisWrap, const LINEAR: bool>(level: &Level2d, s: f32, t: f32) -> u64 {
    if LINEAR {
        let (x0, x1, wx) = linear::<X>(&level.grid, 0, s);
        let (y0, y1, wy) = linear::<Y>(&level.grid, 1, t);
        let upper = lerp(level.fetch(x0, y0), level.fetch(x1, y0), wx);
        let lower = lerp(level.fetch(x0, y1), level.fetch(x1, y1), wx);
        lerp(upper, lower, wy)
    } else {
        level.fetch(nearest::<X>(&level.grid, 0, s), nearest::<Y>(&level.grid, 1, t))
    }
}

/// The lanes of a 4-bit quad mask, in order.
#[inline(always)]
fn lanes(live: u8) -> impl Iterator<Item = usize> {
    (0..4).filter(move |&l| live & (1 << l) != 0)
}

/// The lookups of a quad in one level.
fn one_level<X: AxisWrap, Y: AxisWrap, const LINEAR: bool>(
    level: Level2d,
    c: &[[f32; 3]; 4],
    live: u8,
    out: &mut [[f32; 4]; 4],
) {
    for l in lanes(live) {
        let v = filter::<X, Y, LINEAR>(&level, X::fold(c[l][0]), Y::fold(c[l][1]));
        out[l] = unspread(v, &DIV_255);
    }
}

/// The lookups of a quad in two levels, blended by `w` (in 1/256).
fn two_levels<X: AxisWrap, Y: AxisWrap, const LINEAR: bool>(
    (a, b, w): (Level2d, Level2d, u64),
    c: &[[f32; 3]; 4],
    live: u8,
    out: &mut [[f32; 4]; 4],
) {
    for l in lanes(live) {
        let (s, t) = (X::fold(c[l][0]), Y::fold(c[l][1]));
        let v = lerp(filter::<X, Y, LINEAR>(&a, s, t), filter::<X, Y, LINEAR>(&b, s, t), w);
        out[l] = unspread(v, &MUL_255);
    }
}

/// Calls `$f::<X, Y, LINEAR $more>($args…)` with the types of the wrap modes `$wrap` and
/// the filter (`$more`: the function's further generic arguments, `, _` to infer them).
macro_rules! dispatch {
    ($f:ident [$($more:tt)*], $wrap:expr, $filter:expr, $($args:expr),*) => {{
        macro_rules! with_y {
            ($x:ty) => {
                match ($wrap[1], $filter) {
                    (Wrap::Repeat, Filter::Linear) => $f::<$x, Repeat, true $($more)*>($($args),*),
                    (Wrap::Repeat, Filter::Nearest) => $f::<$x, Repeat, false $($more)*>($($args),*),
                    (Wrap::MirroredRepeat, Filter::Linear) => $f::<$x, Mirror, true $($more)*>($($args),*),
                    (Wrap::MirroredRepeat, Filter::Nearest) => $f::<$x, Mirror, false $($more)*>($($args),*),
                    (_, Filter::Linear) => $f::<$x, Edge, true $($more)*>($($args),*),
                    (_, Filter::Nearest) => $f::<$x, Edge, false $($more)*>($($args),*),
                }
            };
        }
        match $wrap[0] {
            Wrap::Repeat => with_y!(Repeat),
            Wrap::MirroredRepeat => with_y!(Mirror),
            _ => with_y!(Edge),
        }
    }};
}

impl Kernel {
    /// The texture colors of the lanes `live` of a quad (lanes 0 to 3: upper left, upper
    /// right, lower left, lower right in llvmpipe's y-down rows) whose coordinates (s, t, r
    /// divided by q) are `c`; the derivatives are the differences along the quad's upper
    /// row and left column. Lanes outside `live` are left alone in `out`.
    #[inline]
    pub(super) fn sample_quad(self, sampler: &Sampler, c: &[[f32; 3]; 4], live: u8, out: &mut [[f32; 4]; 4]) {
        let ddx: [f32; 3] = std::array::from_fn(|j| c[1][j] - c[0][j]);
        let ddy: [f32; 3] = std::array::from_fn(|j| c[2][j] - c[0][j]);
        match self {
            Kernel::Reference => {
                for l in lanes(live) {
                    out[l] = sampler.sample(c[l], ddx, ddy);
                }
            }
            Kernel::Rgba2d => {
                let levels = &sampler.faces[0];
                let wrap = sampler.wrap;
                match quad_levels(sampler, ddx, ddy, c) {
                    Levels::One(d, filter) => {
                        dispatch!(one_level [], wrap, filter, Level2d::of(&levels[d]), c, live, out)
                    }
                    Levels::Two(d1, d2, frac) => {
                        let w = (frac * 256.0) as i32 as u64;
                        let pair = (Level2d::of(&levels[d1]), Level2d::of(&levels[d2]), w);
                        dispatch!(two_levels [], wrap, sampler.min, pair, c, live, out)
                    }
                }
            }
            Kernel::Depth2d => {
                let which = quad_levels(sampler, ddx, ddy, c);
                let done = depth_quad(sampler, which, c, live, out);
                if !done {
                    // An image without texels (attached to the framebuffer being drawn)
                    // or of another format: the reference answers.
                    Kernel::Reference.sample_quad(sampler, c, live, out);
                }
            }
        }
    }
}

/// The levels the lookups of a quad read. λ of a 2D texture depends on the derivatives
/// only: one per quad; and none at all when every λ gives the same level and filter (no
/// mipmaps, the same filter for magnification and minification).
#[inline(always)]
pub(super) fn quad_levels(sampler: &Sampler, ddx: [f32; 3], ddy: [f32; 3], c: &[[f32; 3]; 4]) -> Levels {
    if sampler.mip.is_none() && sampler.mag == sampler.min {
        Levels::One(0, sampler.mag)
    } else {
        let levels = &sampler.faces[0];
        sampler.levels(sampler.lambda(&levels[0], ddx, ddy, c[0]), levels.len())
    }
}

/// The texels of one level of a depth image, decoded as [`depth_texel`] does. One type for
/// every storage format, matched per texel (the same arm for every texel of a lookup, so a
/// predicted branch): a copy of the quad kernels per format cost the libraries 120 KB, for
/// the lookups the lane loops leave (`super::lanes` decodes 16 lanes per match).
#[derive(Clone, Copy)]
enum DepthTexels<'a> {
    Unorm16(&'a [u16]),
    /// Packed 24-bit depth (the stencil index above it).
    Unorm24(&'a [u32]),
    Unorm32(&'a [u32]),
    Float(&'a [u32]),
}

impl<'a> DepthTexels<'a> {
    /// The level's texels, if it holds depth in a format the quad kernels read.
    fn of(img: &'a TexImage) -> Option<Self> {
        let Texels::Depth(buffer) = &img.texels else { return None };
        match (buffer.pixels(), buffer.depth_encoding()) {
            (DepthStencilPixels::Depth16(px), _) => Some(DepthTexels::Unorm16(px)),
            (DepthStencilPixels::Packed24(px), _) => Some(DepthTexels::Unorm24(px)),
            (DepthStencilPixels::Depth32(px, _), DepthEncoding::Unorm(32)) => Some(DepthTexels::Unorm32(px)),
            (DepthStencilPixels::Depth32(px, _), DepthEncoding::Float) => Some(DepthTexels::Float(px)),
            _ => None,
        }
    }

    /// The number of texels stored.
    fn len(self) -> usize {
        match self {
            DepthTexels::Unorm16(px) => px.len(),
            DepthTexels::Unorm24(px) | DepthTexels::Unorm32(px) | DepthTexels::Float(px) => px.len(),
        }
    }

    /// Texel `i` as the sampler reads it ([`depth_texel`]).
    #[inline(always)]
    fn texel(self, i: usize) -> f32 {
        match self {
            DepthTexels::Unorm16(px) => depth_texel(DepthEncoding::Unorm(16), px[i] as u32),
            DepthTexels::Unorm24(px) => depth_texel(DepthEncoding::Unorm(24), px[i] & 0x00ff_ffff),
            DepthTexels::Unorm32(px) => depth_texel(DepthEncoding::Unorm(32), px[i]),
            DepthTexels::Float(px) => depth_texel(DepthEncoding::Float, px[i]),
        }
    }
}

/// A depth comparison function without a branch per texel: which of less, equal and
/// greater pass, and whether the answer is the opposite (GL_NOTEQUAL is "not equal" and
/// GL_ALWAYS "not never", which hold where an operand is NaN, as IEEE comparisons say).
#[derive(Clone, Copy, Debug)]
pub(super) struct Compare {
    less: bool,
    equal: bool,
    greater: bool,
    invert: bool,
}

impl Compare {
    pub(super) fn new(func: CompareFunc) -> Compare {
        let (less, equal, greater, invert) = match func {
            CompareFunc::Never => (false, false, false, false),
            CompareFunc::Less => (true, false, false, false),
            CompareFunc::Equal => (false, true, false, false),
            CompareFunc::LessEqual => (true, true, false, false),
            CompareFunc::Greater => (false, false, true, false),
            CompareFunc::NotEqual => (false, true, false, true),
            CompareFunc::GreaterEqual => (false, true, true, false),
            CompareFunc::Always => (false, false, false, true),
        };
        Compare { less, equal, greater, invert }
    }

    /// [`depth_passes`](super::sampler::depth_passes) of `func`.
    #[inline(always)]
    pub(super) fn passes(self, r: f32, d: f32) -> bool {
        (((r < d) & self.less) | ((r == d) & self.equal) | ((r > d) & self.greater)) != self.invert
    }
}

/// One level of a borderless 2D depth image.
#[derive(Clone, Copy)]
struct DepthLevel2d<'a> {
    texels: DepthTexels<'a>,
    width: usize,
    grid: Grid,
}

impl<'a> DepthLevel2d<'a> {
    fn of(img: &'a TexImage) -> Option<Self> {
        // Every texel index the wrap modes give must be inside the texels.
        let count = img.width * img.height;
        let texels = DepthTexels::of(img)?;
        (texels.len() >= count && count > 0).then(|| DepthLevel2d { texels, width: img.width, grid: Grid::of(img) })
    }

    /// The filtered depth, or the filtered comparison of `reference` with the texels, at
    /// the folded coordinates (s, t): `DepthLookup::filter` of the reference.
    #[inline(always)]
    fn filter<X: AxisWrap, Y: AxisWrap, const LINEAR: bool>(
        &self,
        compare: Option<Compare>,
        reference: f32,
        s: f32,
        t: f32,
    ) -> f32 {
        let fetch = |x: i32, y: i32| {
            let d = self.texels.texel(y as usize * self.width + x as usize);
            match compare {
                Some(c) => {
                    if c.passes(reference, d) {
                        1.0
                    } else {
                        0.0
                    }
                }
                None => d,
            }
        };
        if LINEAR {
            let (x0, x1, wx) = linear::<X>(&self.grid, 0, s);
            let (y0, y1, wy) = linear::<Y>(&self.grid, 1, t);
            let (wx, wy) = (wx as f32 / 256.0, wy as f32 / 256.0);
            let lerp = |a: f32, b: f32, w: f32| a + w * (b - a);
            let row = |y| lerp(fetch(x0, y), fetch(x1, y), wx);
            lerp(row(y0), row(y1), wy)
        } else {
            fetch(nearest::<X>(&self.grid, 0, s), nearest::<Y>(&self.grid, 1, t))
        }
    }
}

/// The depth lookups of a quad in one level (`second`: blended with a second level by
/// `frac`, in float as the reference blends depth): the filtered values of the live lanes.
fn depth_levels<X: AxisWrap, Y: AxisWrap, const LINEAR: bool>(
    (first, second): (DepthLevel2d, Option<(DepthLevel2d, f32)>),
    compare: Option<Compare>,
    c: &[[f32; 3]; 4],
    live: u8,
    out: &mut [f32; 4],
) {
    for l in lanes(live) {
        let (s, t) = (X::fold(c[l][0]), Y::fold(c[l][1]));
        // The reference value: r, clamped as fixed-point depth formats require.
        let reference = c[l][2].clamp(0.0, 1.0);
        let a = first.filter::<X, Y, LINEAR>(compare, reference, s, t);
        out[l] = match second {
            None => a,
            Some((level, frac)) => a + frac * (level.filter::<X, Y, LINEAR>(compare, reference, s, t) - a),
        };
    }
}

/// The depth lookups of the lanes `live` of a quad in the levels `which`, as texture
/// colors of the sampler's depth mode; false (and `out` untouched) if a level does not
/// hold depth texels the kernels read.
fn depth_quad(sampler: &Sampler, which: Levels, c: &[[f32; 3]; 4], live: u8, out: &mut [[f32; 4]; 4]) -> bool {
    let levels = &sampler.faces[0];
    let level = |d: usize| DepthLevel2d::of(&levels[d]);
    let (pair, filter) = match which {
        Levels::One(d, filter) => match level(d) {
            Some(a) => ((a, None), filter),
            None => return false,
        },
        Levels::Two(d1, d2, frac) => match (level(d1), level(d2)) {
            (Some(a), Some(b)) => ((a, Some((b, frac))), sampler.min),
            _ => return false,
        },
    };
    let mut d = [0.0; 4];
    let compare = sampler.compare.map(Compare::new);
    dispatch!(depth_levels [], sampler.wrap, filter, pair, compare, c, live, &mut d);
    // A blend of two levels blends every channel alike: the constant channels stay
    // (1 + f·0 = 1, 0 + f·0 = 0), the others are the blended depth.
    for l in lanes(live) {
        let d = d[l];
        out[l] = match sampler.depth_mode {
            DepthMode::Luminance => [d, d, d, 1.0],
            DepthMode::Intensity => [d; 4],
            DepthMode::Alpha => [0.0, 0.0, 0.0, d],
        };
    }
    true
}

use super::{F32s, LANES};

/// The lanes of the 2×2 quads of a block whose row pairs (0, 1) and (2, 3) are llvmpipe's
/// quads, in the order [`Kernel::sample_quad`] takes them: upper left, upper right, lower
/// left, lower right of llvmpipe's y-down rows (its upper row is the block's higher row).
pub(super) const QUAD_LANES: [[usize; 4]; 4] = [[4, 5, 0, 1], [6, 7, 2, 3], [12, 13, 8, 9], [14, 15, 10, 11]];

/// The live lanes of quad `q` of a block mask, as a 4-bit quad mask in [`QUAD_LANES`] order.
#[inline(always)]
pub(super) fn quad_mask(live: u16, q: usize) -> u8 {
    let l = QUAD_LANES[q];
    (0..4).fold(0u8, |m, k| m | ((((live >> l[k]) & 1) as u8) << k))
}

impl Kernel {
    /// The texture colors of the lanes `live` of a block whose quads are [`QUAD_LANES`], a
    /// quad at a time ([`Kernel::sample_quad`]): `c` the coordinates (s, t, r divided by q)
    /// of every lane (those of a quad with a live lane give its derivatives, live or not);
    /// `out[channel][lane]` receives the f32 bits of the live lanes' colors, the others are
    /// left alone. The blocks `lanes::Plan` does not take come here.
    pub(super) fn sample_quads(self, sampler: &Sampler, c: &[F32s; 3], live: u16, out: &mut [[u32; LANES]; 4]) {
        for (q, lanes) in QUAD_LANES.iter().enumerate() {
            let m = quad_mask(live, q);
            if m == 0 {
                continue;
            }
            let quad: [[f32; 3]; 4] = std::array::from_fn(|l| std::array::from_fn(|j| c[j][lanes[l]]));
            let mut colors = [[0.0; 4]; 4];
            self.sample_quad(sampler, &quad, m, &mut colors);
            for l in super::lanes4(m) {
                for (k, channel) in out.iter_mut().enumerate() {
                    channel[lanes[l]] = colors[l][k].to_bits();
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::sampler::depth_passes;
    use crate::texture::sampler::DepthMode;
    use crate::texture::BaseFormat;
    use std::sync::Arc;

    use crate::gl::test_rng::TestRng as Rng;

    /// A block's lookups as a stage runs them: through the lane loops when they take the
    /// block (then true), else quad by quad.
    fn sample_block(sampler: &Sampler, c: &[F32s; 3], live: u16, out: &mut [F32s; 4]) -> bool {
        let kernel = Kernel::choose(sampler);
        let mut words = out.map(|channel| channel.map(f32::to_bits));
        let took = kernel != Kernel::Reference
            && crate::texture::lanes::Plan::new(sampler, kernel == Kernel::Depth2d)
                .sample(sampler, c, live, &mut words);
        if !took {
            kernel.sample_quads(sampler, c, live, &mut words);
        }
        *out = words.map(|channel| channel.map(f32::from_bits));
        took
    }

    fn chain(rng: &mut Rng, w: usize, h: usize) -> Vec<Arc<TexImage>> {
        let mut levels = Vec::new();
        let (mut w, mut h) = (w, h);
        loop {
            let texels = (0..w * h).map(|_| rng.next().to_le_bytes()[..4].try_into().unwrap()).collect();
            levels.push(Arc::new(TexImage {
                width: w,
                height: h,
                depth: 1,
                border: 0,
                base: BaseFormat::Rgba,
                texels: Texels::Rgba8(texels),
                srgb: false,
            }));
            if w == 1 && h == 1 {
                return levels;
            }
            (w, h) = ((w / 2).max(1), (h / 2).max(1));
        }
    }

    #[test]
    fn lerp_in_one_word_is_llvmpipes_lerp() {
        for a in (0..256).step_by(5) {
            for b in (0..256).step_by(3) {
                for w in 0..256 {
                    let v = lerp(spread([a as u8, b as u8, 255, 0]), spread([b as u8, a as u8, 0, 255]), w);
                    let expect = |p: i32, q: i32| (p + (((q - p) * w as i32 + 128) >> 8)) as u64;
                    assert_eq!(v & 0xffff, expect(a, b));
                    assert_eq!((v >> 16) & 0xffff, expect(b, a));
                    assert_eq!((v >> 32) & 0xffff, expect(255, 0));
                    assert_eq!(v >> 48, expect(0, 255));
                }
            }
        }
    }

    /// RGBA 2D sampler number `case` of the kernel tests: every wrap pair, filter pair, a
    /// few biases and LOD clamps, over `levels` with mipmap filter `mip`.
    fn rgba_case(levels: &[std::sync::Arc<TexImage>], mip: Option<Filter>, case: usize) -> Sampler {
        let wraps = [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat];
        let filters = [Filter::Nearest, Filter::Linear];
        Sampler {
            dim: Dim::D2,
            faces: vec![levels.to_vec()],
            wrap: [wraps[case % 3], wraps[(case / 3) % 3], Wrap::Repeat],
            mag: filters[(case / 9) % 2],
            min: filters[(case / 18 + case) % 2],
            mip,
            border: [0.0; 4],
            lod_bias: [0.0, 0.5, -1.25][case % 3],
            shader_bias: 0.0,
            min_lod: -1000.0,
            max_lod: [1000.0, 2.5][case % 2],
            compare: None,
            depth_mode: DepthMode::Luminance,
            base: BaseFormat::Rgba,
        }
    }

    #[test]
    fn quad_kernels_give_the_reference_bits() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let mut checked = 0;
        for (w, h) in [(8, 8), (5, 3), (16, 1), (1, 6), (12, 20)] {
            let levels = chain(&mut rng, w, h);
            for mip in [None, Some(Filter::Nearest), Some(Filter::Linear)] {
                for case in 0..24 {
                    let sampler = rgba_case(&levels, mip, case);
                    let kernel = Kernel::choose(&sampler);
                    assert_eq!(kernel, Kernel::Rgba2d);
                    for _ in 0..40 {
                        // Coordinates around [0, 1] with quad steps from tiny to several texels.
                        let scale = [0.001, 0.05, 0.3, 2.0][(rng.next() % 4) as usize];
                        let origin = [rng.unit() * 3.0 - 1.0, rng.unit() * 3.0 - 1.0];
                        let step = [(rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale];
                        let down = [(rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale];
                        let c: [[f32; 3]; 4] = std::array::from_fn(|l| {
                            let (x, y) = ((l % 2) as f32, (l / 2) as f32);
                            let jitter = (rng.unit() - 0.5) * scale * 0.1;
                            [origin[0] + step[0] * x + down[0] * y + jitter, origin[1] + step[1] * x + down[1] * y, 0.0]
                        });
                        let mut out = [[9.0; 4]; 4];
                        kernel.sample_quad(&sampler, &c, 0b1111, &mut out);
                        let mut reference = [[9.0; 4]; 4];
                        Kernel::Reference.sample_quad(&sampler, &c, 0b1111, &mut reference);
                        assert_eq!(out.map(|l| l.map(f32::to_bits)), reference.map(|l| l.map(f32::to_bits)));
                        checked += 4;
                    }
                }
            }
        }
        assert!(checked > 10_000);
    }

    // A lane indexes coordinates, colors and masks alike.
    #[allow(clippy::needless_range_loop)]
    #[test]
    fn block_lookups_are_the_quad_lookups() {
        // Blocks whose quads choose the same levels (the lane loops) and different ones
        // (steep coordinates: quad by quad), every mask shape: each live lane gets the bits
        // of its quad's `sample_quad`, the lanes in `QUAD_LANES` order.
        let mut rng = Rng(0x1234_5678_9abc_def1);
        let mut checked = 0;
        let mut uniform = 0;
        for (w, h) in [(8, 8), (5, 3), (16, 16), (12, 20), (64, 32)] {
            let levels = chain(&mut rng, w, h);
            for mip in [None, Some(Filter::Nearest), Some(Filter::Linear)] {
                for case in 0..24 {
                    let sampler = rgba_case(&levels, mip, case);
                    let kernel = Kernel::choose(&sampler);
                    for _ in 0..20 {
                        let scale = [0.001, 0.02, 0.3, 2.0][(rng.next() % 4) as usize];
                        let origin = [rng.unit() * 3.0 - 1.0, rng.unit() * 3.0 - 1.0];
                        let step = [(rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale];
                        let up = [(rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale];
                        let curve = (rng.unit() - 0.5) * scale * 0.3;
                        let mut c = [[0.0; 16]; 3];
                        for i in 0..16 {
                            let (x, y) = ((i & 3) as f32, (i >> 2) as f32);
                            c[0][i] = origin[0] + step[0] * x + up[0] * y + curve * x * y;
                            c[1][i] = origin[1] + step[1] * x + up[1] * y - curve * y * y;
                        }
                        if rng.next().is_multiple_of(16) {
                            c[0][(rng.next() % 16) as usize] =
                                [f32::NAN, f32::INFINITY, 3.0e9][(rng.next() % 3) as usize];
                        }
                        let live = [0xffff, rng.next() as u16, 0x0001, 0x8000, 0x0660][(rng.next() % 5) as usize];
                        let mut out = [[7.0; 16]; 4];
                        sample_block(&sampler, &c, live, &mut out);
                        assert_eq!(kernel, Kernel::choose(&sampler));
                        let mut all_same = true;
                        let mut first = None;
                        for (q, lanes) in QUAD_LANES.iter().enumerate() {
                            let m = quad_mask(live, q);
                            if m == 0 {
                                continue;
                            }
                            let quad: [[f32; 3]; 4] = std::array::from_fn(|l| [c[0][lanes[l]], c[1][lanes[l]], 0.0]);
                            let mut reference = [[9.0; 4]; 4];
                            Kernel::Reference.sample_quad(&sampler, &quad, m, &mut reference);
                            let ddx = [quad[1][0] - quad[0][0], quad[1][1] - quad[0][1], 0.0];
                            let ddy = [quad[2][0] - quad[0][0], quad[2][1] - quad[0][1], 0.0];
                            let which = quad_levels(&sampler, ddx, ddy, &quad);
                            all_same &= *first.get_or_insert(which) == which;
                            for l in super::lanes(m) {
                                let lane: [f32; 4] = std::array::from_fn(|k| out[k][lanes[l]]);
                                assert_eq!(
                                    lane.map(f32::to_bits),
                                    reference[l].map(f32::to_bits),
                                    "{sampler:?} {c:?} {live:#x} lane {}",
                                    lanes[l]
                                );
                                checked += 1;
                            }
                        }
                        uniform += usize::from(all_same);
                    }
                }
            }
        }
        assert!(checked > 20_000 && uniform > 1000, "{checked} {uniform}");
    }

    /// A chain of depth levels of `format` from `w` × `h` down to 1 × 1, random depths
    /// (a few exactly 0, 1 and repeated values, where comparisons tie).
    fn depth_chain(
        rng: &mut Rng,
        w: usize,
        h: usize,
        format: crate::texture::DepthStencilFormat,
    ) -> Vec<Arc<TexImage>> {
        let mut levels = Vec::new();
        let (mut w, mut h) = (w, h);
        loop {
            let mut img = TexImage::new_depth(w, h, 1, 0, format).unwrap();
            for i in 0..w * h {
                let v = match rng.next() % 8 {
                    0 => 0.0,
                    1 => 1.0,
                    2 => 0.5,
                    _ => rng.unit(),
                };
                img.set_depth_f32(i, v);
            }
            levels.push(Arc::new(img));
            if w == 1 && h == 1 {
                return levels;
            }
            (w, h) = ((w / 2).max(1), (h / 2).max(1));
        }
    }

    #[test]
    fn depth_kernels_give_the_reference_bits() {
        use crate::texture::{depth_storage, DepthStencilFormat};
        let mut rng = Rng(0x2545_f491_4f6c_dd1d);
        let funcs = [
            None,
            Some(CompareFunc::LessEqual),
            Some(CompareFunc::GreaterEqual),
            Some(CompareFunc::Less),
            Some(CompareFunc::Greater),
            Some(CompareFunc::Equal),
            Some(CompareFunc::NotEqual),
            Some(CompareFunc::Always),
            Some(CompareFunc::Never),
        ];
        let modes = [DepthMode::Luminance, DepthMode::Intensity, DepthMode::Alpha];
        let formats = [
            depth_storage(16, false, false),
            depth_storage(24, true, false),
            depth_storage(32, false, false),
            depth_storage(32, true, true),
        ];
        assert!(matches!(formats[3], DepthStencilFormat::Float32 { .. }));
        let mut checked = 0;
        for (f, format) in formats.iter().enumerate() {
            for (w, h) in [(8, 8), (5, 3), (16, 1), (12, 20)] {
                let levels = depth_chain(&mut rng, w, h, *format);
                for mip in [None, Some(Filter::Nearest), Some(Filter::Linear)] {
                    for case in 0..36 {
                        let sampler = Sampler {
                            border: [0.25, 0.0, 0.0, 0.0],
                            compare: funcs[(case + f) % funcs.len()],
                            depth_mode: modes[(case / 4) % 3],
                            base: BaseFormat::Depth,
                            ..rgba_case(&levels, mip, case)
                        };
                        let kernel = Kernel::choose(&sampler);
                        assert_eq!(kernel, Kernel::Depth2d);
                        for _ in 0..30 {
                            let scale = [0.001, 0.05, 0.3, 2.0][(rng.next() % 4) as usize];
                            let origin = [rng.unit() * 3.0 - 1.0, rng.unit() * 3.0 - 1.0];
                            let step = [(rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale];
                            let down = [(rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale];
                            // r around [0, 1] (clamped as the reference value), sometimes a
                            // stored value exactly.
                            let r0 = [rng.unit() * 1.4 - 0.2, 0.5, 1.0, 0.0][(rng.next() % 4) as usize];
                            let c: [[f32; 3]; 4] = std::array::from_fn(|l| {
                                let (x, y) = ((l % 2) as f32, (l / 2) as f32);
                                let jitter = (rng.unit() - 0.5) * scale * 0.1;
                                let r = if rng.next() & 1 == 0 { r0 } else { r0 + (rng.unit() - 0.5) * 0.01 };
                                [
                                    origin[0] + step[0] * x + down[0] * y + jitter,
                                    origin[1] + step[1] * x + down[1] * y,
                                    r,
                                ]
                            });
                            let live = [0b1111, 0b0110, 0b1000][(rng.next() % 3) as usize];
                            let mut out = [[9.0; 4]; 4];
                            kernel.sample_quad(&sampler, &c, live, &mut out);
                            let mut reference = [[9.0; 4]; 4];
                            Kernel::Reference.sample_quad(&sampler, &c, live, &mut reference);
                            assert_eq!(
                                out.map(|l| l.map(f32::to_bits)),
                                reference.map(|l| l.map(f32::to_bits)),
                                "{format:?} {w}x{h} {sampler:?} {c:?}"
                            );
                            checked += live.count_ones();
                        }
                    }
                }
            }
        }
        assert!(checked > 20_000, "{checked}");
    }

    #[test]
    fn branchless_comparisons_are_the_compare_functions() {
        let funcs = CompareFunc::ALL;
        let values = [0.0, -0.0, 0.25, 0.5, 1.0, f32::NAN, f32::INFINITY];
        for func in funcs {
            for r in values {
                for d in values {
                    assert_eq!(Compare::new(func).passes(r, d), depth_passes(func, r, d), "{func:?} {r} {d}");
                }
            }
        }
    }

    // A lane indexes coordinates, colors and masks alike.
    #[allow(clippy::needless_range_loop)]
    #[test]
    fn depth_block_lanes_are_the_quad_lookups() {
        // Random depth blocks through `sample_block` (the lane loops) against each quad's
        // `sample_quad` (`depth_quad`): every storage format, image sizes odd and even,
        // with and without mipmaps, every comparison function and none, nearest and
        // linear (alike or not for magnification and minification, so that quads of one
        // block may filter differently), every wrap pair, each depth mode, random partial
        // masks, r sometimes exactly a stored texel (EQUAL and NOTEQUAL tie there), and
        // coordinates from nearly flat to steep (one level per block, or levels per quad).
        // Live lanes must carry the quad path's bits; the others must be left alone.
        use crate::texture::depth_storage;
        let mut rng = Rng(0x0dd5_eed5_1234_abcd);
        let funcs = [None].into_iter().chain(CompareFunc::ALL.into_iter().map(Some)).collect::<Vec<_>>();
        let modes = [DepthMode::Luminance, DepthMode::Intensity, DepthMode::Alpha];
        let formats = [
            depth_storage(16, false, false),
            depth_storage(24, true, false),
            depth_storage(24, false, false),
            depth_storage(32, false, false),
            depth_storage(32, true, true),
        ];
        let (mut checked, mut in_lanes, mut blended) = (0u32, 0u32, 0u32);
        for (f, format) in formats.iter().enumerate() {
            for (w, h) in [(8, 8), (5, 3), (7, 12), (16, 1), (1, 6), (33, 17)] {
                let levels = depth_chain(&mut rng, w, h, *format);
                for mip in [None, Some(Filter::Nearest), Some(Filter::Linear)] {
                    for case in 0..36 {
                        let sampler = Sampler {
                            compare: funcs[(case + f) % funcs.len()],
                            depth_mode: modes[(case / 4) % 3],
                            base: BaseFormat::Depth,
                            ..rgba_case(&levels, mip, case)
                        };
                        let kernel = Kernel::choose(&sampler);
                        assert_eq!(kernel, Kernel::Depth2d);
                        for _ in 0..12 {
                            let scale = [0.0005, 0.02, 0.3, 2.0][(rng.next() % 4) as usize];
                            let origin = [rng.unit() * 3.0 - 1.0, rng.unit() * 3.0 - 1.0];
                            let step = [(rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale];
                            let down = [(rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale];
                            // A stored value (of a random level and texel), or around [0, 1].
                            let level = &levels[(rng.next() % levels.len() as u64) as usize];
                            let stored = level.depth_f32((rng.next() % (level.width * level.height) as u64) as usize);
                            let r0 = [stored, stored, rng.unit() * 1.4 - 0.2, 1.0][(rng.next() % 4) as usize];
                            let mut c = [[0.0f32; 16]; 3];
                            // Steep blocks: each quad its own derivatives.
                            let per_quad = rng.next().is_multiple_of(4);
                            for i in 0..16 {
                                let (x, y) = ((i & 3) as f32, (i >> 2) as f32);
                                let k = if per_quad {
                                    1.0 + crate::texture::lanes::QUAD_OF_LANE[i] as f32 * 3.0
                                } else {
                                    1.0
                                };
                                let jitter = (rng.unit() - 0.5) * scale * 0.05;
                                c[0][i] = origin[0] + (step[0] * x + down[0] * y) * k + jitter;
                                c[1][i] = origin[1] + (step[1] * x + down[1] * y) * k;
                                c[2][i] =
                                    if rng.next().is_multiple_of(3) { r0 + (rng.unit() - 0.5) * 0.01 } else { r0 };
                            }
                            let live = match rng.next() % 4 {
                                0 => 0xffff,
                                1 => rng.next() as u16,
                                2 => (rng.next() as u16) & (rng.next() as u16),
                                _ => 1 << (rng.next() % 16),
                            };
                            let mut out = [[7.0f32; 16]; 4];
                            let took_lanes = sample_block(&sampler, &c, live, &mut out);
                            in_lanes += u32::from(took_lanes && live != 0);
                            blended += u32::from(took_lanes && mip == Some(Filter::Linear) && live != 0);
                            for (q, lanes) in QUAD_LANES.iter().enumerate() {
                                let quad: [[f32; 3]; 4] =
                                    std::array::from_fn(|l| std::array::from_fn(|j| c[j][lanes[l]]));
                                let mut expect = [[7.0f32; 4]; 4];
                                kernel.sample_quad(&sampler, &quad, quad_mask(live, q), &mut expect);
                                for l in 0..4 {
                                    let i = lanes[l];
                                    // Live lanes carry the quad path's bits; the others
                                    // are left alone by the quad path (the lanes write
                                    // unspecified values there).
                                    if live & (1 << i) == 0 && took_lanes {
                                        continue;
                                    }
                                    for k in 0..4 {
                                        let want = if live & (1 << i) != 0 { expect[l][k] } else { 7.0 };
                                        assert_eq!(
                                            out[k][i].to_bits(),
                                            want.to_bits(),
                                            "{format:?} {w}x{h} lane {i} channel {k} {sampler:?} {c:?} {live:#x}"
                                        );
                                    }
                                }
                            }
                            checked += live.count_ones();
                        }
                    }
                }
            }
        }
        assert!(checked > 50_000 && in_lanes > 5_000 && blended > 500, "{checked} {in_lanes} {blended}");
    }

    #[test]
    fn depth_images_without_texels_take_the_reference_path() {
        // A depth texture attached to the framebuffer being drawn has lent its texels to
        // it: the lookups give the border depth as the reference does.
        use crate::texture::depth_storage;
        let mut img = TexImage::new_depth(4, 4, 1, 0, depth_storage(24, false, false)).unwrap();
        if let Texels::Depth(buffer) = &mut img.texels {
            *buffer = crate::texture::DepthStencilBuffer::default();
        }
        let sampler = Sampler {
            dim: Dim::D2,
            faces: vec![vec![Arc::new(img)]],
            wrap: [Wrap::ClampToEdge; 3],
            mag: Filter::Nearest,
            min: Filter::Nearest,
            mip: None,
            border: [0.75, 0.0, 0.0, 0.0],
            lod_bias: 0.0,
            shader_bias: 0.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            compare: Some(CompareFunc::LessEqual),
            depth_mode: DepthMode::Intensity,
            base: BaseFormat::Depth,
        };
        assert_eq!(Kernel::choose(&sampler), Kernel::Depth2d);
        let c = [[0.5, 0.5, 0.5]; 4];
        let mut out = [[9.0; 4]; 4];
        Kernel::Depth2d.sample_quad(&sampler, &c, 0b0101, &mut out);
        let mut reference = [[9.0; 4]; 4];
        Kernel::Reference.sample_quad(&sampler, &c, 0b0101, &mut reference);
        assert_eq!(out, reference);
        assert_eq!(out[0], [0.75; 4]);
        assert_eq!(out[1], [9.0; 4], "lanes outside the mask are left alone");
    }

    #[test]
    fn other_textures_take_the_reference_path() {
        let mut rng = Rng(7);
        let levels = chain(&mut rng, 4, 4);
        let mut sampler = Sampler {
            dim: Dim::D2,
            faces: vec![levels],
            wrap: [Wrap::Repeat, Wrap::ClampToBorder, Wrap::Repeat],
            mag: Filter::Linear,
            min: Filter::Linear,
            mip: None,
            border: [0.0; 4],
            lod_bias: 0.0,
            shader_bias: 0.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            compare: None,
            depth_mode: DepthMode::Luminance,
            base: BaseFormat::Rgba,
        };
        assert_eq!(Kernel::choose(&sampler), Kernel::Reference);
        sampler.wrap[1] = Wrap::Clamp;
        assert_eq!(Kernel::choose(&sampler), Kernel::Reference);
        sampler.wrap[1] = Wrap::MirroredRepeat;
        assert_eq!(Kernel::choose(&sampler), Kernel::Rgba2d);
        sampler.dim = Dim::D3;
        assert_eq!(Kernel::choose(&sampler), Kernel::Reference);
    }
}
