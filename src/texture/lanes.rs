//! Texture lookups of a whole 4×4 block in lane loops: the path of the common textures (2D,
//! borderless, wrapped by repeat, edge clamping or mirroring; RGBA8 or depth), compiled
//! once per SIMD level by the lookup's entry point ([`super::TextureStage::sample_lanes`]).
//!
//! The work per block: each quad's levels (λ once per 2×2 quad, as llvmpipe; none when the
//! level cannot depend on λ), then for the lanes together — every lane in its quad's levels,
//! the lanes of quads without a live lane in a live quad's levels — the texel positions and
//! weights, the texel indices, the gather (the one part done lane by lane) and the filter.
//! Nothing is decided per lane: the wrap mode, filter, format and comparison are chosen once
//! per block, outside the lane loops, so that each loop is a few vector instructions. The
//! per-level sizes come from [`Grid`]s computed once per draw.
//!
//! RGBA8 texels are filtered two channels per 32-bit word: a texel splits into red and blue
//! (`0x00BB_00RR`) and green and alpha (`0x00AA_00GG`), and one lerp
//! `(a·(256 − w) + b·w + 0x0080_0080) >> 8`, masked, is llvmpipe's 8-bit lerp
//! `a + ((b − a)·w + 128) >> 8` on both channels at once (each field stays below 2¹⁶:
//! 255·256 + 128). Depth texels are decoded from their storage format, compared with r when
//! comparison is on, and filtered in float, as the reference does.
//!
//! The results are the very bits of [`Sampler::sample`] (the reference, through the quad
//! kernels in `kernel`); a block the lanes do not take (quads that filter differently, a
//! depth level without texels) is left to the quad kernels.
// Lane loops index several arrays by lane: plain `for i in 0..LANES` loops are what
// vectorise (iterator chains over zipped arrays stay scalar or calls without LTO).
#![allow(clippy::needless_range_loop)]

use super::kernel::{quad_levels, QUAD_LANES};
use super::sampler::{fixed, floor_i32, mirror, repeat, DepthMode, Filter, Levels, Sampler, Wrap};
use super::{DepthStencilPixels, F32s, TexImage, Texels, LANES};
use crate::framebuffer::format::DepthEncoding;
use crate::gl::CompareFunc;

type I32s = [i32; LANES];
type U32s = [u32; LANES];

/// Every lane, in order.
const ALL_LANES: [usize; LANES] = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15];

/// The lanes of each quad ([`QUAD_LANES`]) as a mask.
const QUAD_BITS: [u16; 4] = [0x0033, 0x00cc, 0x3300, 0xcc00];

/// The quad of each lane ([`QUAD_LANES`] numbering).
pub(super) const QUAD_OF_LANE: [usize; LANES] = [0, 0, 1, 1, 0, 0, 1, 1, 2, 2, 3, 3, 2, 2, 3, 3];

/// The size of one level of a borderless 2D image, as its lookups need it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Grid {
    pub(super) size: [i32; 2],
    pub(super) sizef: [f32; 2],
}

impl Grid {
    pub(super) fn of(img: &TexImage) -> Grid {
        let size = [img.width as i32, img.height as i32];
        Grid { size, sizef: size.map(|n| n as f32) }
    }
}

/// How an axis wraps, as the lane loops distinguish it (the wraps `Kernel::choose` admits).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AxisWrap {
    Repeat,
    Edge,
    Mirror,
}

impl AxisWrap {
    fn of(wrap: Wrap) -> AxisWrap {
        match wrap {
            Wrap::Repeat => AxisWrap::Repeat,
            Wrap::MirroredRepeat => AxisWrap::Mirror,
            _ => AxisWrap::Edge,
        }
    }
}

/// A stage's block lookups: the sizes of its levels, computed once per draw.
#[derive(Clone, Debug)]
pub(super) struct Plan {
    /// Each level of face 0 (empty when the lanes do not take the texture).
    grids: Vec<Grid>,
    wrap: [AxisWrap; 2],
    /// Whether every level's side is a power of two, per axis (GL_REPEAT is then a mask).
    pot: [bool; 2],
    /// Whether the level cannot depend on λ (no mipmaps, one filter for magnification and
    /// minification): then no λ is computed.
    fixed_level: bool,
    depth: bool,
}

impl Plan {
    /// The plan of `sampler`, whose kernel is `Rgba2d` (`depth` false) or `Depth2d`.
    pub(super) fn new(sampler: &Sampler, depth: bool) -> Plan {
        let grids: Vec<Grid> = sampler.faces[0].iter().map(|l| Grid::of(l)).collect();
        let pot = [0, 1].map(|k| grids.iter().all(|g| g.size[k] & (g.size[k] - 1) == 0));
        Plan {
            grids,
            wrap: [AxisWrap::of(sampler.wrap[0]), AxisWrap::of(sampler.wrap[1])],
            pot,
            fixed_level: sampler.mip.is_none() && sampler.mag == sampler.min,
            depth,
        }
    }

    /// The lookups of a block (`c`: s, t, r divided by q, every lane of a quad with a live
    /// lane holding its pixel's coordinates) into `out[channel][lane]` as f32 bits, every
    /// lane written (the lanes outside `live` with unspecified values). False, with `out`
    /// untouched, when the lanes do not take the block (then the quad kernels answer).
    #[inline(always)]
    pub(super) fn sample(&self, sampler: &Sampler, c: &[F32s; 3], live: u16, out: &mut [U32s; 4]) -> bool {
        if live == 0 || self.grids.is_empty() {
            return live == 0;
        }
        // Each live quad's levels; the other quads read the first live quad's.
        let mut which = [None; 4];
        for (q, lanes) in QUAD_LANES.iter().enumerate() {
            if live & QUAD_BITS[q] == 0 {
                continue;
            }
            which[q] = Some(if self.fixed_level {
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
        // Per quad: the first level, the second (the first again when there is one) and
        // the weight of the second.
        let mut levels = QuadLevels { first: [0; 4], second: [0; 4], frac: [0.0; 4], two: 0 };
        for q in 0..4 {
            match which[q].unwrap_or(any) {
                Levels::One(d, _) => (levels.first[q], levels.second[q]) = (d, d),
                Levels::Two(d1, d2, f) => {
                    (levels.first[q], levels.second[q], levels.frac[q]) = (d1, d2, f);
                    levels.two |= QUAD_BITS[q];
                }
            }
        }
        // The coordinates as the filter sees them (mirrored repeat folds them).
        let mut st = [c[0], c[1]];
        for (k, s) in st.iter_mut().enumerate() {
            if self.wrap[k] == AxisWrap::Mirror {
                for v in s.iter_mut() {
                    *v = mirror(*v);
                }
            }
        }
        let linear = filter == Filter::Linear;
        if self.depth {
            self.depth_block(sampler, &levels, linear, &st, &c[2], out)
        } else {
            self.rgba_block(sampler, &levels, linear, &st, out)
        }
    }

    /// The per-lane sizes of the levels `d` (one per quad) along axis `k`.
    #[inline(always)]
    fn sizes(&self, d: [usize; 4], k: usize) -> (F32s, I32s) {
        let (mut sizef, mut size) = ([0.0; LANES], [0; LANES]);
        if d[1..].iter().all(|&x| x == d[0]) {
            let g = &self.grids[d[0]];
            sizef = [g.sizef[k]; LANES];
            size = [g.size[k]; LANES];
        } else {
            for l in 0..LANES {
                let g = &self.grids[d[QUAD_OF_LANE[l]]];
                (sizef[l], size[l]) = (g.sizef[k], g.size[k]);
            }
        }
        (sizef, size)
    }

    /// `i` wrapped into `[0, size)` along axis `k` (mirrored coordinates were folded: their
    /// indices clamp, as the edge's).
    #[inline(always)]
    fn wrap_lanes(&self, k: usize, i: &I32s, size: &I32s) -> I32s {
        let mut out = [0; LANES];
        match self.wrap[k] {
            AxisWrap::Repeat if self.pot[k] => {
                for l in 0..LANES {
                    out[l] = i[l] & (size[l] - 1);
                }
            }
            AxisWrap::Repeat => {
                for l in 0..LANES {
                    out[l] = repeat(i[l], size[l]);
                }
            }
            AxisWrap::Edge | AxisWrap::Mirror => {
                for l in 0..LANES {
                    out[l] = i[l].max(0).min(size[l] - 1);
                }
            }
        }
        out
    }

    /// `sampler::axis` (linear) along axis `k` of 16 lanes: the two texels' indices and the
    /// weight of the second in 1/256. The position in texels less ½ is taken to 1/256
    /// rounded to nearest even (`fixed`), by the magic number below 2²², exactly beyond.
    #[inline(always)]
    fn linear_axis(&self, k: usize, s: &F32s, sizef: &F32s, size: &I32s) -> (I32s, I32s, U32s) {
        const MAGIC: f32 = 12_582_912.0;
        let mut u = [0.0f32; LANES];
        for l in 0..LANES {
            let scaled = s[l] * sizef[l] - 0.5;
            u[l] = if s[l].is_finite() { scaled } else { 0.0 };
        }
        let mut f = [0i32; LANES];
        let mut big = [false; LANES];
        for l in 0..LANES {
            let v = u[l] * 256.0;
            f[l] = ((v + MAGIC).to_bits() as i32).wrapping_sub(MAGIC.to_bits() as i32);
            big[l] = !(v.abs() < 4_194_304.0);
        }
        if big.iter().any(|&b| b) {
            for l in 0..LANES {
                if big[l] {
                    f[l] = fixed(u[l]);
                }
            }
        }
        let (mut i0, mut i1, mut w) = ([0; LANES], [0; LANES], [0u32; LANES]);
        for l in 0..LANES {
            i0[l] = f[l] >> 8;
            i1[l] = (f[l] >> 8) + 1;
            w[l] = (f[l] & 0xff) as u32;
        }
        (self.wrap_lanes(k, &i0, size), self.wrap_lanes(k, &i1, size), w)
    }

    /// `sampler::axis` (nearest) along axis `k` of 16 lanes: ⌊s · size⌋, wrapped.
    #[inline(always)]
    fn nearest_axis(&self, k: usize, s: &F32s, sizef: &F32s, size: &I32s) -> I32s {
        let mut i = [0; LANES];
        for l in 0..LANES {
            let u = s[l] * sizef[l];
            let floor = floor_i32(u);
            i[l] = if u.is_finite() { floor } else { 0 };
        }
        self.wrap_lanes(k, &i, size)
    }

    /// The texel indices (`y · width + x`) and weights of the lookups of the lanes at `st`
    /// in the levels `d` (one per quad): one index (nearest) or four (linear: (x0, y0),
    /// (x1, y0), (x0, y1), (x1, y1)) per lane, with the weights of x1 and y1 in 1/256.
    #[inline(always)]
    fn footprint(&self, d: [usize; 4], linear: bool, st: &[F32s; 2], fp: &mut Footprint) {
        let (sizef_x, width) = self.sizes(d, 0);
        let (sizef_y, height) = self.sizes(d, 1);
        if linear {
            let (x0, x1, wx) = self.linear_axis(0, &st[0], &sizef_x, &width);
            let (y0, y1, wy) = self.linear_axis(1, &st[1], &sizef_y, &height);
            for l in 0..LANES {
                let (r0, r1) = (y0[l] * width[l], y1[l] * width[l]);
                fp.index[0][l] = r0 + x0[l];
                fp.index[1][l] = r0 + x1[l];
                fp.index[2][l] = r1 + x0[l];
                fp.index[3][l] = r1 + x1[l];
            }
            (fp.wx, fp.wy) = (wx, wy);
        } else {
            let x = self.nearest_axis(0, &st[0], &sizef_x, &width);
            let y = self.nearest_axis(1, &st[1], &sizef_y, &height);
            for l in 0..LANES {
                fp.index[0][l] = y[l] * width[l] + x[l];
            }
        }
    }

    /// The filtered texels of the lanes at `st` in the levels `d` (one per quad), as their
    /// red-and-blue and green-and-alpha halves; `None` if a level holds no RGBA8 texels.
    #[inline(always)]
    fn rgba_levels(
        &self,
        images: &[std::sync::Arc<TexImage>],
        d: [usize; 4],
        linear: bool,
        st: &[F32s; 2],
    ) -> Option<[U32s; 2]> {
        let mut fp = Footprint { index: [[0; LANES]; 4], wx: [0; LANES], wy: [0; LANES] };
        self.footprint(d, linear, st, &mut fp);
        let mut texels = [[0u32; LANES]; 4];
        let corners = if linear { 4 } else { 1 };
        if d[1..].iter().all(|&x| x == d[0]) {
            let t = rgba_texels(&images[d[0]])?;
            for (texels, index) in texels.iter_mut().zip(&fp.index).take(corners) {
                for l in 0..LANES {
                    texels[l] = u32::from_le_bytes(t[index[l] as usize]);
                }
            }
        } else {
            for (q, lanes) in QUAD_LANES.iter().enumerate() {
                let t = rgba_texels(&images[d[q]])?;
                for (texels, index) in texels.iter_mut().zip(&fp.index).take(corners) {
                    for &l in lanes {
                        texels[l] = u32::from_le_bytes(t[index[l] as usize]);
                    }
                }
            }
        }
        let mut halves = [[0u32; LANES]; 2];
        for (h, half) in halves.iter_mut().enumerate() {
            let shift = 8 * h as u32;
            if linear {
                for l in 0..LANES {
                    let p = |c: usize| (texels[c][l] >> shift) & 0x00ff_00ff;
                    let upper = lerp2(p(0), p(1), fp.wx[l]);
                    let lower = lerp2(p(2), p(3), fp.wx[l]);
                    half[l] = lerp2(upper, lower, fp.wy[l]);
                }
            } else {
                for l in 0..LANES {
                    half[l] = (texels[0][l] >> shift) & 0x00ff_00ff;
                }
            }
        }
        Some(halves)
    }

    /// The filtered depths (or filtered comparisons with `reference`) of the lanes at `st`
    /// in the levels `d` (one per quad); `None` if a level holds no texels of `format`.
    // The lookup's parts, as `depth_block` has them.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn depth_levels(
        &self,
        images: &[std::sync::Arc<TexImage>],
        format: DepthFormat,
        compare: Option<CompareFunc>,
        reference: &F32s,
        d: [usize; 4],
        linear: bool,
        st: &[F32s; 2],
    ) -> Option<F32s> {
        let mut fp = Footprint { index: [[0; LANES]; 4], wx: [0; LANES], wy: [0; LANES] };
        self.footprint(d, linear, st, &mut fp);
        let corners = if linear { 4 } else { 1 };
        let mut raw = [[0u32; LANES]; 4];
        if d[1..].iter().all(|&x| x == d[0]) {
            let (texels, f) = depth_texels(&images[d[0]])?;
            if f != format {
                return None;
            }
            for (raw, index) in raw.iter_mut().zip(&fp.index).take(corners) {
                texels.gather(index, &ALL_LANES, raw);
            }
        } else {
            for (q, lanes) in QUAD_LANES.iter().enumerate() {
                let (texels, f) = depth_texels(&images[d[q]])?;
                if f != format {
                    return None;
                }
                for (raw, index) in raw.iter_mut().zip(&fp.index).take(corners) {
                    texels.gather(index, lanes, raw);
                }
            }
        }
        let mut v = [[0.0f32; LANES]; 4];
        for (v, raw) in v.iter_mut().zip(&raw).take(corners) {
            format.decode(raw, v);
            if let Some(func) = compare {
                compare_lanes(func, reference, v);
            }
        }
        if !linear {
            return Some(v[0]);
        }
        let mut d = [0.0f32; LANES];
        for l in 0..LANES {
            let (fx, fy) = (fp.wx[l] as f32 / 256.0, fp.wy[l] as f32 / 256.0);
            let upper = v[0][l] + fx * (v[1][l] - v[0][l]);
            let lower = v[2][l] + fx * (v[3][l] - v[2][l]);
            d[l] = upper + fy * (lower - upper);
        }
        Some(d)
    }

    /// RGBA8 lookups ([`Plan::sample`]).
    #[inline(always)]
    fn rgba_block(
        &self,
        sampler: &Sampler,
        levels: &QuadLevels,
        linear: bool,
        st: &[F32s; 2],
        out: &mut [U32s; 4],
    ) -> bool {
        let images = &sampler.faces[0];
        let Some(mut v) = self.rgba_levels(images, levels.first, linear, st) else { return false };
        if levels.two != 0 {
            let Some(b) = self.rgba_levels(images, levels.second, linear, st) else { return false };
            let mut w = [0u32; LANES];
            for l in 0..LANES {
                // A quad of one level blends it with itself at weight 0: itself.
                w[l] = (levels.frac[QUAD_OF_LANE[l]] * 256.0) as i32 as u32;
            }
            for (a, b) in v.iter_mut().zip(&b) {
                for l in 0..LANES {
                    a[l] = lerp2(a[l], b[l], w[l]);
                }
            }
        }
        // u8 → f32 as the reference converts it: `/ 255` from one level, `· (1/255)` from a
        // blend of two.
        for (k, o) in out.iter_mut().enumerate() {
            let (half, shift) = (&v[k & 1], 16 * (k >> 1) as u32);
            let mut x = [0.0f32; LANES];
            for l in 0..LANES {
                x[l] = ((half[l] >> shift) & 0xff) as f32;
            }
            match levels.two {
                0 => {
                    for l in 0..LANES {
                        o[l] = (x[l] / 255.0).to_bits();
                    }
                }
                0xffff => {
                    for l in 0..LANES {
                        o[l] = (x[l] * (1.0 / 255.0)).to_bits();
                    }
                }
                two => {
                    for l in 0..LANES {
                        let blended = two & (1 << l) != 0;
                        o[l] = if blended { x[l] * (1.0 / 255.0) } else { x[l] / 255.0 }.to_bits();
                    }
                }
            }
        }
        true
    }

    /// Depth lookups ([`Plan::sample`]), `r` the reference values before clamping.
    #[inline(always)]
    fn depth_block(
        &self,
        sampler: &Sampler,
        levels: &QuadLevels,
        linear: bool,
        st: &[F32s; 2],
        r: &F32s,
        out: &mut [U32s; 4],
    ) -> bool {
        let images = &sampler.faces[0];
        let Some((_, format)) = depth_texels(&images[0]) else { return false };
        // The reference value: r, clamped as fixed-point depth formats require.
        let mut reference = [0.0f32; LANES];
        for l in 0..LANES {
            reference[l] = r[l].clamp(0.0, 1.0);
        }
        let compare = sampler.compare;
        let Some(mut d) = self.depth_levels(images, format, compare, &reference, levels.first, linear, st) else {
            return false;
        };
        if levels.two != 0 {
            let Some(b) = self.depth_levels(images, format, compare, &reference, levels.second, linear, st) else {
                return false;
            };
            for l in 0..LANES {
                // A quad of one level keeps its value (not `a + 0·(b − a)`, which differs
                // where b is not finite).
                if levels.two & (1 << l) != 0 {
                    let f = levels.frac[QUAD_OF_LANE[l]];
                    d[l] += f * (b[l] - d[l]);
                }
            }
        }
        // The texture colors of the depth mode.
        let (constant, depth_channels): (f32, [bool; 4]) = match sampler.depth_mode {
            DepthMode::Luminance => (1.0, [true, true, true, false]),
            DepthMode::Intensity => (0.0, [true; 4]),
            DepthMode::Alpha => (0.0, [false, false, false, true]),
        };
        for (channel, o) in depth_channels.iter().zip(out.iter_mut()) {
            if *channel {
                for l in 0..LANES {
                    o[l] = d[l].to_bits();
                }
            } else {
                *o = [constant.to_bits(); LANES];
            }
        }
        true
    }
}

/// The levels each quad of a block reads: the first, the second (the first again for a
/// quad of one level) and the weight of the second; `two` the lanes of quads of two levels.
struct QuadLevels {
    first: [usize; 4],
    second: [usize; 4],
    frac: [f32; 4],
    two: u16,
}

/// The texels a set of lookups reads: one or four indices per lane, and the weights of the
/// second texel along x and y (linear).
struct Footprint {
    index: [I32s; 4],
    wx: U32s,
    wy: U32s,
}

/// The comparisons of `reference` with the depths `v` by `func`, as 1 or 0 into `v`
/// ([`super::sampler::depth_passes`]): one plain loop per function.
#[inline(always)]
fn compare_lanes(func: CompareFunc, reference: &F32s, v: &mut F32s) {
    macro_rules! lanes {
        (|$r:ident, $d:ident| $passes:expr) => {
            for l in 0..LANES {
                let ($r, $d) = (reference[l], v[l]);
                v[l] = if $passes { 1.0 } else { 0.0 };
            }
        };
    }
    match func {
        CompareFunc::Never => *v = [0.0; LANES],
        CompareFunc::Less => lanes!(|r, d| r < d),
        CompareFunc::Equal => lanes!(|r, d| r == d),
        CompareFunc::LessEqual => lanes!(|r, d| r <= d),
        CompareFunc::Greater => lanes!(|r, d| r > d),
        CompareFunc::NotEqual => lanes!(|r, d| r != d),
        CompareFunc::GreaterEqual => lanes!(|r, d| r >= d),
        CompareFunc::Always => *v = [1.0; LANES],
    }
}

/// llvmpipe's 8-bit lerp on the two 8-bit fields (bits 0–7 and 16–23) of `a` and `b`,
/// weight `w` in 1/256 (0..=255).
#[inline(always)]
fn lerp2(a: u32, b: u32, w: u32) -> u32 {
    ((a * (256 - w) + b * w + 0x0080_0080) >> 8) & 0x00ff_00ff
}

/// The texels of an RGBA8 level.
#[inline(always)]
fn rgba_texels(img: &TexImage) -> Option<&[[u8; 4]]> {
    match &img.texels {
        Texels::Rgba8(t) if t.len() >= img.width * img.height => Some(t),
        _ => None,
    }
}

/// How a depth level stores its texels, as the lanes decode them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum DepthFormat {
    Unorm16,
    /// Packed 24-bit depth (the stencil index above it).
    Unorm24,
    Unorm32,
    Float,
}

impl DepthFormat {
    /// `raw` (stored words) decoded as [`super::depth_texel`] does.
    #[inline(always)]
    fn decode(self, raw: &U32s, out: &mut F32s) {
        match self {
            DepthFormat::Unorm16 => {
                for l in 0..LANES {
                    out[l] = raw[l] as f32 * (1.0 / 65535.0);
                }
            }
            DepthFormat::Unorm24 => {
                for l in 0..LANES {
                    out[l] = ((raw[l] & 0x00ff_ffff) as f64 * (1.0 / 16_777_215.0)) as f32;
                }
            }
            DepthFormat::Unorm32 => {
                for l in 0..LANES {
                    out[l] = (raw[l] as f64 * (1.0 / 4_294_967_295.0)) as f32;
                }
            }
            DepthFormat::Float => {
                for l in 0..LANES {
                    out[l] = f32::from_bits(raw[l]);
                }
            }
        }
    }
}

/// A depth level's stored words.
#[derive(Clone, Copy)]
enum DepthWords<'a> {
    U16(&'a [u16]),
    U32(&'a [u32]),
}

impl DepthWords<'_> {
    /// The words at `index` of the lanes `lanes`, into `out`.
    #[inline(always)]
    fn gather(self, index: &I32s, lanes: &[usize], out: &mut U32s) {
        match self {
            DepthWords::U16(w) => {
                for &l in lanes {
                    out[l] = w[index[l] as usize] as u32;
                }
            }
            DepthWords::U32(w) => {
                for &l in lanes {
                    out[l] = w[index[l] as usize];
                }
            }
        }
    }
}

/// The stored words of a depth level and their format, if it holds all its texels.
#[inline(always)]
fn depth_texels(img: &TexImage) -> Option<(DepthWords<'_>, DepthFormat)> {
    let Texels::Depth(buffer) = &img.texels else { return None };
    let count = img.width * img.height;
    let (words, format) = match (buffer.pixels(), buffer.depth_encoding()) {
        (DepthStencilPixels::Depth16(px), _) if px.len() >= count => (DepthWords::U16(px), DepthFormat::Unorm16),
        (DepthStencilPixels::Packed24(px), _) if px.len() >= count => (DepthWords::U32(px), DepthFormat::Unorm24),
        (DepthStencilPixels::Depth32(px, _), DepthEncoding::Float) if px.len() >= count => {
            (DepthWords::U32(px), DepthFormat::Float)
        }
        (DepthStencilPixels::Depth32(px, _), DepthEncoding::Unorm(_)) if px.len() >= count => {
            (DepthWords::U32(px), DepthFormat::Unorm32)
        }
        _ => return None,
    };
    (count > 0).then_some((words, format))
}
