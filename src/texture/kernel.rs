//! Texture lookups a 2×2 quad at a time, with the work chosen once per draw: the level of
//! detail and the level choice once per quad (as llvmpipe computes them), and for the
//! common textures (2D RGBA8 without border, wrapped by repeat, edge clamping or
//! mirroring) a path with no per-fragment dispatch on format or border and texels
//! filtered four channels at once in one 64-bit word.
//!
//! Every kernel gives the very bits of [`Sampler::sample`], the reference lookup (which
//! remains the path of every other texture): the tests here compare them on random
//! coordinates.
//!
//! Filtering in one word: an RGBA8 texel spread to four 16-bit fields (`0x00AA_00BB_00GG_00RR`)
//! lerps all its channels with two multiplications, `(a·(256 − w) + b·w + 128) >> 8`,
//! which is llvmpipe's `a + ((b − a)·w + 128) >> 8` (the `256·a` is a whole multiple of 256)
//! and never carries between fields (at most 255·256 + 128 < 2¹⁶).
use super::sampler::{fixed, floor_i32, mirror, repeat, Dim, Filter, Levels, Sampler, Wrap};
use super::{TexImage, Texels};

/// The lookups of one stage, chosen when the draw compiles its texturing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kernel {
    /// Any texture: [`Sampler::sample`] per fragment, with the quad's derivatives.
    Reference,
    /// A 2D RGBA8 texture, borderless, wrapped by repeat, edge clamping or mirroring: every
    /// index the wrap gives is inside the image.
    Rgba2d,
}

impl Kernel {
    /// The kernel for `sampler`.
    pub(super) fn choose(sampler: &Sampler) -> Kernel {
        let inside = |w: Wrap| matches!(w, Wrap::Repeat | Wrap::ClampToEdge | Wrap::MirroredRepeat);
        let rgba_borderless =
            |img: &TexImage| img.border == 0 && matches!(img.texels, Texels::Rgba8(_)) && img.depth == 1;
        if sampler.dim == Dim::D2
            && sampler.faces.len() == 1
            && !sampler.faces[0].is_empty()
            && sampler.faces[0].iter().all(|l| rgba_borderless(l))
            && inside(sampler.wrap[0])
            && inside(sampler.wrap[1])
        {
            Kernel::Rgba2d
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

/// One level of an RGBA8 2D image, borderless, with what its lookups need.
#[derive(Clone, Copy)]
struct Level2d<'a> {
    texels: &'a [[u8; 4]],
    width: i32,
    size: [i32; 2],
    sizef: [f32; 2],
    /// `size − 1` for sides that are powers of two (GL_REPEAT is a mask), else −1.
    mask: [i32; 2],
}

impl<'a> Level2d<'a> {
    #[inline(always)]
    fn of(img: &'a TexImage) -> Level2d<'a> {
        let texels = match &img.texels {
            Texels::Rgba8(t) => t.as_slice(),
            // Kernel::choose admits RGBA8 images only.
            Texels::Depth(_) => &[],
        };
        let size = [img.width as i32, img.height as i32];
        Level2d {
            texels,
            width: size[0],
            size,
            sizef: size.map(|n| n as f32),
            mask: size.map(|n| if n & (n - 1) == 0 { n - 1 } else { -1 }),
        }
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
fn nearest<W: AxisWrap>(level: &Level2d, k: usize, s: f32) -> i32 {
    let u = s * level.sizef[k];
    let i = if u.is_finite() { floor_i32(u) } else { 0 };
    W::index(i, level.size[k], level.mask[k])
}

/// The two texels' indices along axis `k` of the folded coordinate `s`, and the weight
/// of the second in 1/256.
#[inline(always)]
fn linear<W: AxisWrap>(level: &Level2d, k: usize, s: f32) -> (i32, i32, u64) {
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
        let (x0, x1, wx) = linear::<X>(level, 0, s);
        let (y0, y1, wy) = linear::<Y>(level, 1, t);
        let upper = lerp(level.fetch(x0, y0), level.fetch(x1, y0), wx);
        let lower = lerp(level.fetch(x0, y1), level.fetch(x1, y1), wx);
        lerp(upper, lower, wy)
    } else {
        level.fetch(nearest::<X>(level, 0, s), nearest::<Y>(level, 1, t))
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

/// Calls `$f::<X, Y, LINEAR>($args…)` with the types of the wrap modes `$wrap` and the filter.
macro_rules! dispatch {
    ($f:ident, $wrap:expr, $filter:expr, $($args:expr),*) => {{
        macro_rules! with_y {
            ($x:ty) => {
                match ($wrap[1], $filter) {
                    (Wrap::Repeat, Filter::Linear) => $f::<$x, Repeat, true>($($args),*),
                    (Wrap::Repeat, Filter::Nearest) => $f::<$x, Repeat, false>($($args),*),
                    (Wrap::MirroredRepeat, Filter::Linear) => $f::<$x, Mirror, true>($($args),*),
                    (Wrap::MirroredRepeat, Filter::Nearest) => $f::<$x, Mirror, false>($($args),*),
                    (_, Filter::Linear) => $f::<$x, Edge, true>($($args),*),
                    (_, Filter::Nearest) => $f::<$x, Edge, false>($($args),*),
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
                // λ of a 2D texture depends on the derivatives only: one per quad.
                let lambda = sampler.lambda(&levels[0], ddx, ddy, c[0]);
                let wrap = sampler.wrap;
                match sampler.levels(lambda, levels.len()) {
                    Levels::One(d, filter) => {
                        dispatch!(one_level, wrap, filter, Level2d::of(&levels[d]), c, live, out)
                    }
                    Levels::Two(d1, d2, frac) => {
                        let w = (frac * 256.0) as i32 as u64;
                        let pair = (Level2d::of(&levels[d1]), Level2d::of(&levels[d2]), w);
                        dispatch!(two_levels, wrap, sampler.min, pair, c, live, out)
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::sampler::DepthMode;
    use crate::texture::BaseFormat;
    use std::sync::Arc;

    /// A small deterministic generator (xorshift).
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn unit(&mut self) -> f32 {
            (self.next() >> 40) as f32 / (1u64 << 24) as f32
        }
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

    #[test]
    fn quad_kernels_give_the_reference_bits() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let wraps = [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat];
        let filters = [Filter::Nearest, Filter::Linear];
        let mut checked = 0;
        for (w, h) in [(8, 8), (5, 3), (16, 1), (1, 6), (12, 20)] {
            let levels = chain(&mut rng, w, h);
            for mip in [None, Some(Filter::Nearest), Some(Filter::Linear)] {
                for case in 0..24 {
                    let sampler = Sampler {
                        dim: Dim::D2,
                        faces: vec![levels.clone()],
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
                    };
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
