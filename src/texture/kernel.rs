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
//! minification, the usual shadow map) computes no λ at all. On a 4×4 block
//! ([`Kernel::sample_block`]) depth lookups run over the 16 lanes (`depth_block`): texels
//! gathered, then decoded, compared and filtered in lane loops, each lane in its quad's
//! levels; a block whose quads filter differently (magnification in one, minification in
//! another) goes quad by quad.
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
        let rgba_borderless =
            |img: &TexImage| img.border == 0 && matches!(img.texels, Texels::Rgba8(_)) && img.depth == 1;
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
    /// [`AxisWrap::index`] of 16 lanes, each with its level's size and mask.
    #[inline(always)]
    fn index_lanes(i: &[i32; 16], size: &[i32; 16], mask: &[i32; 16]) -> [i32; 16] {
        let mut out = [0; 16];
        for k in 0..16 {
            out[k] = Self::index(i[k], size[k], mask[k]);
        }
        out
    }
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
    #[inline(always)]
    fn index_lanes(i: &[i32; 16], size: &[i32; 16], mask: &[i32; 16]) -> [i32; 16] {
        // The branch on the sizes once, not per lane: masks vectorise.
        let mut out = [0; 16];
        if mask.iter().all(|&m| m >= 0) {
            for k in 0..16 {
                out[k] = i[k] & mask[k];
            }
        } else {
            for k in 0..16 {
                out[k] = repeat(i[k], size[k]);
            }
        }
        out
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
                let levels = &sampler.faces[0];
                let which = quad_levels(sampler, ddx, ddy, c);
                let done = match &levels[0].texels {
                    Texels::Depth(buffer) => match (buffer.pixels(), buffer.depth_encoding()) {
                        (DepthStencilPixels::Depth16(_), _) => depth_quad::<Unorm16>(sampler, which, c, live, out),
                        (DepthStencilPixels::Packed24(_), _) => depth_quad::<Unorm24>(sampler, which, c, live, out),
                        (DepthStencilPixels::Depth32(..), DepthEncoding::Float) => {
                            depth_quad::<FloatDepth>(sampler, which, c, live, out)
                        }
                        (DepthStencilPixels::Depth32(..), _) => depth_quad::<Unorm32>(sampler, which, c, live, out),
                        (DepthStencilPixels::None, _) => false,
                    },
                    Texels::Rgba8(_) => false,
                };
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
fn quad_levels(sampler: &Sampler, ddx: [f32; 3], ddy: [f32; 3], c: &[[f32; 3]; 4]) -> Levels {
    if sampler.mip.is_none() && sampler.mag == sampler.min {
        Levels::One(0, sampler.mag)
    } else {
        let levels = &sampler.faces[0];
        sampler.levels(sampler.lambda(&levels[0], ddx, ddy, c[0]), levels.len())
    }
}

/// The texels of one level of a depth image in one storage format, decoded as
/// [`depth_texel`] does.
trait DepthTexels<'a>: Copy {
    /// The level's texels, if `img` holds this format.
    fn of(img: &'a TexImage) -> Option<Self>;
    /// The stored word of texel `i`, as [`DepthTexels::decode`] takes it.
    fn raw(self, i: usize) -> u32;
    /// A stored word as the sampler reads it ([`depth_texel`]): separate from the fetch
    /// so that the lane loops gather first and decode 16 lanes at once.
    fn decode(raw: u32) -> f32;
    #[inline(always)]
    fn texel(self, i: usize) -> f32 {
        Self::decode(self.raw(i))
    }
}

#[derive(Clone, Copy)]
struct Unorm16<'a>(&'a [u16]);
#[derive(Clone, Copy)]
struct Unorm24<'a>(&'a [u32]);
#[derive(Clone, Copy)]
struct Unorm32<'a>(&'a [u32]);
#[derive(Clone, Copy)]
struct FloatDepth<'a>(&'a [u32]);

/// The pixels of a depth image, if it holds any.
fn depth_pixels(img: &TexImage) -> Option<(&DepthStencilPixels, DepthEncoding)> {
    match &img.texels {
        Texels::Depth(buffer) => Some((buffer.pixels(), buffer.depth_encoding())),
        Texels::Rgba8(_) => None,
    }
}

impl<'a> DepthTexels<'a> for Unorm16<'a> {
    fn of(img: &'a TexImage) -> Option<Self> {
        match depth_pixels(img)? {
            (DepthStencilPixels::Depth16(px), _) => Some(Unorm16(px)),
            _ => None,
        }
    }
    #[inline(always)]
    fn raw(self, i: usize) -> u32 {
        self.0[i] as u32
    }
    #[inline(always)]
    fn decode(raw: u32) -> f32 {
        depth_texel(DepthEncoding::Unorm(16), raw)
    }
}

impl<'a> DepthTexels<'a> for Unorm24<'a> {
    fn of(img: &'a TexImage) -> Option<Self> {
        match depth_pixels(img)? {
            (DepthStencilPixels::Packed24(px), _) => Some(Unorm24(px)),
            _ => None,
        }
    }
    #[inline(always)]
    fn raw(self, i: usize) -> u32 {
        self.0[i] & 0x00ff_ffff
    }
    #[inline(always)]
    fn decode(raw: u32) -> f32 {
        depth_texel(DepthEncoding::Unorm(24), raw)
    }
}

impl<'a> DepthTexels<'a> for Unorm32<'a> {
    fn of(img: &'a TexImage) -> Option<Self> {
        match depth_pixels(img)? {
            (DepthStencilPixels::Depth32(px, _), DepthEncoding::Unorm(32)) => Some(Unorm32(px)),
            _ => None,
        }
    }
    #[inline(always)]
    fn raw(self, i: usize) -> u32 {
        self.0[i]
    }
    #[inline(always)]
    fn decode(raw: u32) -> f32 {
        depth_texel(DepthEncoding::Unorm(32), raw)
    }
}

impl<'a> DepthTexels<'a> for FloatDepth<'a> {
    fn of(img: &'a TexImage) -> Option<Self> {
        match depth_pixels(img)? {
            (DepthStencilPixels::Depth32(px, _), DepthEncoding::Float) => Some(FloatDepth(px)),
            _ => None,
        }
    }
    #[inline(always)]
    fn raw(self, i: usize) -> u32 {
        self.0[i]
    }
    #[inline(always)]
    fn decode(raw: u32) -> f32 {
        depth_texel(DepthEncoding::Float, raw)
    }
}

/// A depth comparison function without a branch per texel: which of less, equal and
/// greater pass, and whether the answer is the opposite (GL_NOTEQUAL is "not equal" and
/// GL_ALWAYS "not never", which hold where an operand is NaN, as IEEE comparisons say).
#[derive(Clone, Copy, Debug)]
struct Compare {
    less: bool,
    equal: bool,
    greater: bool,
    invert: bool,
}

impl Compare {
    fn new(func: CompareFunc) -> Compare {
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
    fn passes(self, r: f32, d: f32) -> bool {
        (((r < d) & self.less) | ((r == d) & self.equal) | ((r > d) & self.greater)) != self.invert
    }
}

/// One level of a borderless 2D depth image.
#[derive(Clone, Copy)]
struct DepthLevel2d<T> {
    texels: T,
    width: usize,
    grid: Grid,
}

impl<'a, T: DepthTexels<'a>> DepthLevel2d<T> {
    fn of(img: &'a TexImage) -> Option<Self> {
        // Every texel index the wrap modes give must be inside the texels.
        let count = img.width * img.height;
        let texels = T::of(img)?;
        let long_enough = match depth_pixels(img)? {
            (DepthStencilPixels::Depth16(px), _) => px.len() >= count,
            (DepthStencilPixels::Packed24(px), _) | (DepthStencilPixels::Depth32(px, _), _) => px.len() >= count,
            (DepthStencilPixels::None, _) => false,
        };
        (long_enough && count > 0).then(|| DepthLevel2d { texels, width: img.width, grid: Grid::of(img) })
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
fn depth_levels<'a, X: AxisWrap, Y: AxisWrap, const LINEAR: bool, T: DepthTexels<'a>>(
    (first, second): (DepthLevel2d<T>, Option<(DepthLevel2d<T>, f32)>),
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
/// hold texels of format `T`.
fn depth_quad<'a, T: DepthTexels<'a>>(
    sampler: &'a Sampler,
    which: Levels,
    c: &[[f32; 3]; 4],
    live: u8,
    out: &mut [[f32; 4]; 4],
) -> bool {
    let levels = &sampler.faces[0];
    let level = |d: usize| DepthLevel2d::<T>::of(&levels[d]);
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
    dispatch!(depth_levels [, _], sampler.wrap, filter, pair, compare, c, live, &mut d);
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

use super::F32s;

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
    /// The texture colors of the lanes `live` of a block whose quads are [`QUAD_LANES`]:
    /// `c` the coordinates (s, t, r divided by q) of every lane (those of a quad with a live
    /// lane give its derivatives, live or not); `out[channel][lane]` receives the colors of
    /// the live lanes (the others are left alone or zero). Per quad the very bits of
    /// [`Kernel::sample_quad`].
    pub(super) fn sample_block(self, sampler: &Sampler, c: &[F32s; 3], live: u16, out: &mut [F32s; 4]) {
        match self {
            Kernel::Rgba2d => {
                let wrap = sampler.wrap;
                let mut values = [[0i32; 16]; 4];
                let mut two = 0u16;
                dispatch_wrap!(rgba_block, wrap, sampler, c, live, &mut values, &mut two);
                // u8 → f32 as the reference converts it: `/ 255` from one level, `· (1/255)`
                // from a blend of two (see DIV_255).
                for (channel, v) in out.iter_mut().zip(&values) {
                    for (i, o) in channel.iter_mut().enumerate() {
                        let x = v[i] as f32;
                        *o = if two & (1 << i) != 0 { x * (1.0 / 255.0) } else { x / 255.0 };
                    }
                }
            }
            Kernel::Depth2d if depth_block(sampler, c, live, out) => {}
            _ => {
                // Other kernels (and depth blocks the lane loops leave): a quad at a time.
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
                            channel[lanes[l]] = colors[l][k];
                        }
                    }
                }
            }
        }
    }
}

/// Calls `$f::<X, Y>($args…)` with the types of the wrap modes `$wrap`.
macro_rules! dispatch_wrap {
    ($f:ident, $wrap:expr, $($args:expr),*) => {{
        macro_rules! with_y {
            ($x:ty) => {
                match $wrap[1] {
                    Wrap::Repeat => $f::<$x, Repeat>($($args),*),
                    Wrap::MirroredRepeat => $f::<$x, Mirror>($($args),*),
                    _ => $f::<$x, Edge>($($args),*),
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
use dispatch_wrap;

/// The RGBA8 lookups of a block's live lanes as 8-bit channel values (`values[channel][lane]`),
/// per quad in the levels its derivatives choose; `two` receives the lanes blended from two
/// levels. When every live quad reads the same levels with linear filtering (a surface
/// that is not too steep), all 16 lanes are filtered together in lane loops
/// ([`linear_lanes`]); otherwise quad by quad, lane by lane.
#[inline(always)]
fn rgba_block<X: AxisWrap, Y: AxisWrap>(
    sampler: &Sampler,
    c: &[F32s; 3],
    live: u16,
    values: &mut [[i32; 16]; 4],
    two: &mut u16,
) {
    let levels = &sampler.faces[0];
    // Plain loops here: LLVM leaves `array::from_fn` and `map` as calls of a closure.
    let (mut s, mut t) = ([0.0; 16], [0.0; 16]);
    for i in 0..16 {
        s[i] = X::fold(c[0][i]);
        t[i] = Y::fold(c[1][i]);
    }
    let mut which = [None; 4];
    for (q, lanes) in QUAD_LANES.iter().enumerate() {
        if quad_mask(live, q) != 0 {
            let (l0, l1, l2) = (lanes[0], lanes[1], lanes[2]);
            let ddx = [c[0][l1] - c[0][l0], c[1][l1] - c[1][l0], c[2][l1] - c[2][l0]];
            let ddy = [c[0][l2] - c[0][l0], c[1][l2] - c[1][l0], c[2][l2] - c[2][l0]];
            let c0 = [c[0][lanes[0]], c[1][lanes[0]], c[2][lanes[0]]];
            which[q] = Some(quad_levels(sampler, ddx, ddy, &[c0; 4]));
        }
    }
    // Linear filtering in every live quad: the lane loops, each lane in its quad's levels
    // (one level as a blend of that level with itself at weight 0, which is its value).
    let linear = |l: &Option<Levels>| match l {
        None => true,
        Some(Levels::One(_, mode)) => *mode == Filter::Linear,
        Some(Levels::Two(..)) => sampler.min == Filter::Linear,
    };
    if let (Some(any), true) = (which.iter().flatten().next().copied(), which.iter().all(linear)) {
        let mut first = [0usize; 4];
        let mut second = [0usize; 4];
        let mut weight = [0i32; 4];
        for q in 0..4 {
            // Quads without a live lane read a live quad's levels (any index is inside them).
            match which[q].unwrap_or(any) {
                Levels::One(d, _) => (first[q], second[q]) = (d, d),
                Levels::Two(d1, d2, frac) => {
                    (first[q], second[q], weight[q]) = (d1, d2, (frac * 256.0) as i32);
                    *two |= QUAD_LANES[q].iter().fold(0u16, |m, &i| m | (1 << i));
                }
            }
        }
        let mut b = [[0i32; 16]; 4];
        let of = |d: [usize; 4]| {
            let l = |q: usize| Level2d::of(&levels[d[q]]);
            [l(0), l(1), l(2), l(3)]
        };
        linear_lanes::<X, Y>(&of(first), &s, &t, values);
        if *two != 0 {
            linear_lanes::<X, Y>(&of(second), &s, &t, &mut b);
            let mut w = [0i32; 16];
            for i in 0..16 {
                w[i] = weight[QUAD_OF_LANE[i]];
            }
            for (a, b) in values.iter_mut().zip(&b) {
                for i in 0..16 {
                    a[i] = lerp8(a[i], b[i], w[i]);
                }
            }
        }
        return;
    }
    let mut words = [0u64; 16];
    for (q, lanes) in QUAD_LANES.iter().enumerate() {
        let m = quad_mask(live, q);
        let Some(levels_q) = which[q] else { continue };
        match levels_q {
            Levels::One(d, mode) => {
                let level = Level2d::of(&levels[d]);
                for l in super::lanes4(m) {
                    let i = lanes[l];
                    words[i] = match mode {
                        Filter::Linear => filter::<X, Y, true>(&level, s[i], t[i]),
                        Filter::Nearest => filter::<X, Y, false>(&level, s[i], t[i]),
                    };
                }
            }
            Levels::Two(d1, d2, frac) => {
                let w = (frac * 256.0) as i32 as u64;
                let (a, b) = (Level2d::of(&levels[d1]), Level2d::of(&levels[d2]));
                for l in super::lanes4(m) {
                    let i = lanes[l];
                    words[i] = match sampler.min {
                        Filter::Linear => {
                            lerp(filter::<X, Y, true>(&a, s[i], t[i]), filter::<X, Y, true>(&b, s[i], t[i]), w)
                        }
                        Filter::Nearest => {
                            lerp(filter::<X, Y, false>(&a, s[i], t[i]), filter::<X, Y, false>(&b, s[i], t[i]), w)
                        }
                    };
                    *two |= 1 << i;
                }
            }
        }
    }
    for (k, v) in values.iter_mut().enumerate() {
        for i in 0..16 {
            v[i] = ((words[i] >> (16 * k)) & 0xff) as i32;
        }
    }
}

/// llvmpipe's 8-bit lerp, weight `w` in 1/256 (what [`lerp`] does on every field).
#[inline(always)]
fn lerp8(a: i32, b: i32, w: i32) -> i32 {
    a + (((b - a) * w + 128) >> 8)
}

/// The quad of each lane of a block ([`QUAD_LANES`]).
const QUAD_OF_LANE: [usize; 16] = [0, 0, 1, 1, 0, 0, 1, 1, 2, 2, 3, 3, 2, 2, 3, 3];

/// [`linear`] over 16 lanes, in lane loops, each lane in the level of its quad (`grids`):
/// the two texels' indices along axis `k` of the folded coordinates `s` and the weight of
/// the second in 1/256. [`fixed`]'s rounding by the magic number in every lane, and its
/// exact path for the lanes beyond 2²².
#[inline(always)]
fn linear_axis_lanes<W: AxisWrap>(grids: &[Grid; 4], k: usize, s: &F32s) -> ([i32; 16], [i32; 16], [i32; 16]) {
    const MAGIC: f32 = 12_582_912.0;
    let (mut sizef, mut size, mut mask) = ([0.0; 16], [0i32; 16], [0i32; 16]);
    for i in 0..16 {
        let g = &grids[QUAD_OF_LANE[i]];
        (sizef[i], size[i], mask[i]) = (g.sizef[k], g.size[k], g.mask[k]);
    }
    let mut f = [0i32; 16];
    let mut big = 0u32;
    for i in 0..16 {
        let u = if s[i].is_finite() { s[i] * sizef[i] - 0.5 } else { 0.0 };
        let v = u * 256.0;
        f[i] = ((v + MAGIC).to_bits() as i32).wrapping_sub(MAGIC.to_bits() as i32);
        big |= u32::from((v.abs() >= 4_194_304.0) | v.is_nan()) << i;
    }
    while big != 0 {
        let i = big.trailing_zeros() as usize;
        f[i] = fixed(if s[i].is_finite() { s[i] * sizef[i] - 0.5 } else { 0.0 });
        big &= big - 1;
    }
    let mut i0 = [0i32; 16];
    let mut i1 = [0i32; 16];
    let mut w = [0i32; 16];
    for i in 0..16 {
        i0[i] = f[i] >> 8;
        i1[i] = i0[i] + 1;
        w[i] = f[i] & 0xff;
    }
    (W::index_lanes(&i0, &size, &mask), W::index_lanes(&i1, &size, &mask), w)
}

/// The bilinear lookups of 16 lanes at the folded coordinates (s, t), each lane in the
/// level of its quad: the channel values of [`filter`] (linear), lerped channel by channel
/// in lane loops.
#[inline(always)]
fn linear_lanes<X: AxisWrap, Y: AxisWrap>(levels: &[Level2d; 4], s: &F32s, t: &F32s, out: &mut [[i32; 16]; 4]) {
    let grids = [levels[0].grid, levels[1].grid, levels[2].grid, levels[3].grid];
    let (x0, x1, wx) = linear_axis_lanes::<X>(&grids, 0, s);
    let (y0, y1, wy) = linear_axis_lanes::<Y>(&grids, 1, t);
    let mut texels = [[0u32; 16]; 4];
    for (level, lanes) in levels.iter().zip(&QUAD_LANES) {
        let width = level.width as usize;
        for &i in lanes {
            let (r0, r1) = (y0[i] as usize * width, y1[i] as usize * width);
            texels[0][i] = u32::from_le_bytes(level.texels[r0 + x0[i] as usize]);
            texels[1][i] = u32::from_le_bytes(level.texels[r0 + x1[i] as usize]);
            texels[2][i] = u32::from_le_bytes(level.texels[r1 + x0[i] as usize]);
            texels[3][i] = u32::from_le_bytes(level.texels[r1 + x1[i] as usize]);
        }
    }
    for (k, o) in out.iter_mut().enumerate() {
        let shift = 8 * k as u32;
        for i in 0..16 {
            let ch = |p: u32| ((p >> shift) & 0xff) as i32;
            let upper = lerp8(ch(texels[0][i]), ch(texels[1][i]), wx[i]);
            let lower = lerp8(ch(texels[2][i]), ch(texels[3][i]), wx[i]);
            o[i] = lerp8(upper, lower, wy[i]);
        }
    }
}

/// The depth lookups of a block's live lanes in lane loops (2D depth images, every
/// format, comparison or not): the very bits of [`depth_quad`] quad by quad. Each quad's
/// levels are chosen as [`Kernel::sample_quad`] chooses them (none per quad when the level
/// cannot depend on λ, as for most shadow maps); when every live quad filters alike
/// (nearest or linear), all 16 lanes are looked up together, each in its quad's levels,
/// texels gathered, then decoded, compared and filtered over the lanes. False, with `out`
/// untouched, when the quads filter differently or a level holds no texels of the first
/// level's format: the quad path answers then.
fn depth_block(sampler: &Sampler, c: &[F32s; 3], live: u16, out: &mut [F32s; 4]) -> bool {
    match &sampler.faces[0][0].texels {
        Texels::Depth(buffer) => match (buffer.pixels(), buffer.depth_encoding()) {
            (DepthStencilPixels::Depth16(_), _) => depth_block_in::<Unorm16>(sampler, c, live, out),
            (DepthStencilPixels::Packed24(_), _) => depth_block_in::<Unorm24>(sampler, c, live, out),
            (DepthStencilPixels::Depth32(..), DepthEncoding::Float) => {
                depth_block_in::<FloatDepth>(sampler, c, live, out)
            }
            (DepthStencilPixels::Depth32(..), _) => depth_block_in::<Unorm32>(sampler, c, live, out),
            (DepthStencilPixels::None, _) => false,
        },
        Texels::Rgba8(_) => false,
    }
}

/// [`depth_block`] for texels of format `T`.
#[inline(always)]
fn depth_block_in<'a, T: DepthTexels<'a>>(sampler: &'a Sampler, c: &[F32s; 3], live: u16, out: &mut [F32s; 4]) -> bool {
    let levels = &sampler.faces[0];
    // The levels of each quad with a live lane.
    let mut which = [None; 4];
    let fixed_level = sampler.mip.is_none() && sampler.mag == sampler.min;
    for (q, lanes) in QUAD_LANES.iter().enumerate() {
        if quad_mask(live, q) == 0 {
            continue;
        }
        which[q] = Some(if fixed_level {
            Levels::One(0, sampler.mag)
        } else {
            let (l0, l1, l2) = (lanes[0], lanes[1], lanes[2]);
            let ddx = [c[0][l1] - c[0][l0], c[1][l1] - c[1][l0], c[2][l1] - c[2][l0]];
            let ddy = [c[0][l2] - c[0][l0], c[1][l2] - c[1][l0], c[2][l2] - c[2][l0]];
            let c0 = [c[0][l0], c[1][l0], c[2][l0]];
            quad_levels(sampler, ddx, ddy, &[c0; 4])
        });
    }
    let filter_of = |l: Levels| match l {
        Levels::One(_, mode) => mode,
        Levels::Two(..) => sampler.min,
    };
    let Some(any) = which.iter().flatten().next().copied() else { return true };
    let filter = filter_of(any);
    if which.iter().flatten().any(|&l| filter_of(l) != filter) {
        return false;
    }
    // Per quad: the first level, the second (the first again when there is one) and the
    // weight of the second. Quads without a live lane read a live quad's levels.
    let (mut first, mut second, mut frac) = ([0usize; 4], [0usize; 4], [0.0f32; 4]);
    let mut two = 0u16;
    for q in 0..4 {
        match which[q].unwrap_or(any) {
            Levels::One(d, _) => (first[q], second[q]) = (d, d),
            Levels::Two(d1, d2, f) => {
                (first[q], second[q], frac[q]) = (d1, d2, f);
                two |= QUAD_LANES[q].iter().fold(0u16, |m, &i| m | (1 << i));
            }
        }
    }
    // Each quad's level, looked up once when every quad reads the same (the usual case).
    let of = |d: [usize; 4]| -> Option<[DepthLevel2d<T>; 4]> {
        let level = DepthLevel2d::<T>::of(&levels[d[0]])?;
        if d[1..].iter().all(|&x| x == d[0]) {
            return Some([level; 4]);
        }
        Some([
            level,
            DepthLevel2d::<T>::of(&levels[d[1]])?,
            DepthLevel2d::<T>::of(&levels[d[2]])?,
            DepthLevel2d::<T>::of(&levels[d[3]])?,
        ])
    };
    // Only textures that wrap alike on both axes (shadow maps do) take the lanes: one copy
    // of the lane loops per wrap, filter and format instead of one per pair of wraps
    // (which made this function over half a megabyte); the quad path answers the others.
    if wrap_class(sampler.wrap[0]) != wrap_class(sampler.wrap[1]) {
        return false;
    }
    let Some(a_levels) = of(first) else { return false };
    let b_levels = if two != 0 {
        match of(second) {
            Some(b) => Some(b),
            None => return false,
        }
    } else {
        None
    };
    // Plain loops: LLVM leaves `array::from_fn` and `map` as calls of a closure.
    let mut reference = [0.0f32; 16];
    for i in 0..16 {
        // The reference value: r, clamped as fixed-point depth formats require.
        reference[i] = c[2][i].clamp(0.0, 1.0);
    }
    let compare = sampler.compare.map(Compare::new);
    let mut d = [0.0f32; 16];
    let lanes = depth_lanes_of::<T>(sampler.wrap, filter);
    lanes(&a_levels, compare, &reference, c, &mut d);
    if let Some(b_levels) = b_levels {
        let mut b = [0.0f32; 16];
        lanes(&b_levels, compare, &reference, c, &mut b);
        let mut f = [0.0f32; 16];
        for i in 0..16 {
            f[i] = frac[QUAD_OF_LANE[i]];
        }
        for i in 0..16 {
            // A quad of one level keeps its value (not `a + 0·(b − a)`, which differs
            // where b is not finite).
            if two & (1 << i) != 0 {
                d[i] = d[i] + f[i] * (b[i] - d[i]);
            }
        }
    }
    // The texture colors of the depth mode, in the live lanes.
    let (constant, depth_channels): (f32, [bool; 4]) = match sampler.depth_mode {
        DepthMode::Luminance => (1.0, [true, true, true, false]),
        DepthMode::Intensity => (0.0, [true; 4]),
        DepthMode::Alpha => (0.0, [false, false, false, true]),
    };
    for (channel, o) in depth_channels.iter().zip(out.iter_mut()) {
        for i in 0..16 {
            if live & (1 << i) != 0 {
                o[i] = if *channel { d[i] } else { constant };
            }
        }
    }
    true
}

/// Which lane-loop type a wrap mode takes (as `dispatch!` chooses): repeat, mirrored
/// repeat, or a clamp.
fn wrap_class(wrap: Wrap) -> u8 {
    match wrap {
        Wrap::Repeat => 0,
        Wrap::MirroredRepeat => 1,
        _ => 2,
    }
}

/// The lane loops of a depth lookup for texels of format `T`.
type DepthLanes<'a, T> = fn(&[DepthLevel2d<T>; 4], Option<Compare>, &F32s, &[F32s; 3], &mut F32s);

/// [`depth_lanes`] for a texture that wraps by `wrap` on both axes (`wrap[0]`'s class
/// decides; [`depth_block_in`] checked that `wrap[1]`'s is the same) with `filter`.
fn depth_lanes_of<'a, T: DepthTexels<'a>>(wrap: [Wrap; 3], filter: Filter) -> DepthLanes<'a, T> {
    match (wrap_class(wrap[0]), filter) {
        (0, Filter::Linear) => depth_lanes::<Repeat, Repeat, true, T>,
        (0, Filter::Nearest) => depth_lanes::<Repeat, Repeat, false, T>,
        (1, Filter::Linear) => depth_lanes::<Mirror, Mirror, true, T>,
        (1, Filter::Nearest) => depth_lanes::<Mirror, Mirror, false, T>,
        (_, Filter::Linear) => depth_lanes::<Edge, Edge, true, T>,
        (_, Filter::Nearest) => depth_lanes::<Edge, Edge, false, T>,
    }
}

/// The filtered depth (or filtered comparison of `reference` with the texels) of 16 lanes
/// at the coordinates `c`, each lane in the level of its quad: [`DepthLevel2d::filter`]
/// lane by lane, in lane loops.
fn depth_lanes<'a, X: AxisWrap, Y: AxisWrap, const LINEAR: bool, T: DepthTexels<'a>>(
    levels: &[DepthLevel2d<T>; 4],
    compare: Option<Compare>,
    reference: &F32s,
    c: &[F32s; 3],
    out: &mut F32s,
) {
    let (mut s, mut t) = ([0.0; 16], [0.0; 16]);
    for i in 0..16 {
        s[i] = X::fold(c[0][i]);
        t[i] = Y::fold(c[1][i]);
    }
    let grids = [levels[0].grid, levels[1].grid, levels[2].grid, levels[3].grid];
    // The texels' stored words (four per lane when linear), gathered quad by quad.
    let mut raw = [[0u32; 16]; 4];
    let (mut wx, mut wy) = ([0i32; 16], [0i32; 16]);
    if LINEAR {
        let (x0, x1, wx_) = linear_axis_lanes::<X>(&grids, 0, &s);
        let (y0, y1, wy_) = linear_axis_lanes::<Y>(&grids, 1, &t);
        (wx, wy) = (wx_, wy_);
        for (level, lanes) in levels.iter().zip(&QUAD_LANES) {
            let width = level.width;
            for &i in lanes {
                let (r0, r1) = (y0[i] as usize * width, y1[i] as usize * width);
                raw[0][i] = level.texels.raw(r0 + x0[i] as usize);
                raw[1][i] = level.texels.raw(r0 + x1[i] as usize);
                raw[2][i] = level.texels.raw(r1 + x0[i] as usize);
                raw[3][i] = level.texels.raw(r1 + x1[i] as usize);
            }
        }
    } else {
        for (level, lanes) in levels.iter().zip(&QUAD_LANES) {
            for &i in lanes {
                let x = nearest::<X>(&level.grid, 0, s[i]);
                let y = nearest::<Y>(&level.grid, 1, t[i]);
                raw[0][i] = level.texels.raw(y as usize * level.width + x as usize);
            }
        }
    }
    // Decoded, and compared with the reference when comparison is on.
    let texels = if LINEAR { 4 } else { 1 };
    let mut v = [[0.0f32; 16]; 4];
    for (v, raw) in v.iter_mut().zip(&raw).take(texels) {
        for i in 0..16 {
            v[i] = T::decode(raw[i]);
        }
        if let Some(cmp) = compare {
            for i in 0..16 {
                v[i] = if cmp.passes(reference[i], v[i]) { 1.0 } else { 0.0 };
            }
        }
    }
    if LINEAR {
        for i in 0..16 {
            let (fx, fy) = (wx[i] as f32 / 256.0, wy[i] as f32 / 256.0);
            let upper = v[0][i] + fx * (v[1][i] - v[0][i]);
            let lower = v[2][i] + fx * (v[3][i] - v[2][i]);
            out[i] = upper + fy * (lower - upper);
        }
    } else {
        *out = v[0];
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
                        kernel.sample_block(&sampler, &c, live, &mut out);
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
                                let k = if per_quad { 1.0 + QUAD_OF_LANE[i] as f32 * 3.0 } else { 1.0 };
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
                            kernel.sample_block(&sampler, &c, live, &mut out);
                            let mut lanes_out = [[7.0f32; 16]; 4];
                            let took_lanes = depth_block(&sampler, &c, live, &mut lanes_out);
                            in_lanes += u32::from(took_lanes && live != 0);
                            blended += u32::from(took_lanes && mip == Some(Filter::Linear) && live != 0);
                            for (q, lanes) in QUAD_LANES.iter().enumerate() {
                                let quad: [[f32; 3]; 4] =
                                    std::array::from_fn(|l| std::array::from_fn(|j| c[j][lanes[l]]));
                                let mut expect = [[7.0f32; 4]; 4];
                                kernel.sample_quad(&sampler, &quad, quad_mask(live, q), &mut expect);
                                for l in 0..4 {
                                    let i = lanes[l];
                                    for k in 0..4 {
                                        let want = if live & (1 << i) != 0 { expect[l][k] } else { 7.0 };
                                        assert_eq!(
                                            out[k][i].to_bits(),
                                            want.to_bits(),
                                            "{format:?} {w}x{h} lane {i} channel {k} {sampler:?} {c:?} {live:#x}"
                                        );
                                        if took_lanes {
                                            assert_eq!(lanes_out[k][i].to_bits(), want.to_bits());
                                        }
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
