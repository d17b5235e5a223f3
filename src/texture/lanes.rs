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

use super::kernel::QUAD_LANES;
use super::sampler::{fast_log2, fixed, floor_i32, log2, mirror, repeat, DepthMode, Filter, Levels, Sampler, Wrap};
use super::{DepthStencilPixels, F32s, TexImage, Texels, LANES};
use crate::framebuffer::format::DepthEncoding;
use crate::gl::CompareFunc;

type I32s = [i32; LANES];
type U32s = [u32; LANES];
type U16s = [u16; LANES];

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
        let lambdas = if self.fixed_level { None } else { Some(self.lambdas(sampler, c)) };
        let mut which = [None; 4];
        for q in 0..4 {
            if live & QUAD_BITS[q] != 0 {
                which[q] = Some(match lambdas {
                    None => Levels::One(0, sampler.mag),
                    Some(lambda) => sampler.levels(lambda[q], self.grids.len()),
                });
            }
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
        for k in 0..2 {
            if self.wrap[k] == AxisWrap::Mirror {
                for l in 0..LANES {
                    st[k][l] = mirror(st[k][l]);
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

    /// λ of each quad: [`Sampler::lambda`] of a borderless 2D texture, whose derivatives
    /// are the differences along the quad's upper row and left column (ρ² the larger
    /// squared length of the scaled derivative vectors, r's scaled by 0).
    #[inline(always)]
    fn lambdas(&self, sampler: &Sampler, c: &[F32s; 3]) -> [f32; 4] {
        let size = self.grids[0].sizef;
        let mut rho2 = [0.0f32; 4];
        for q in 0..4 {
            let [l0, l1, l2, _] = QUAD_LANES[q];
            let length2 = |a: usize| {
                let (x, y, z) =
                    ((c[0][a] - c[0][l0]) * size[0], (c[1][a] - c[1][l0]) * size[1], (c[2][a] - c[2][l0]) * 0.0);
                x * x + y * y + z * z
            };
            rho2[q] = length2(l1).max(length2(l2));
        }
        let mut lambda = [0.0f32; 4];
        for q in 0..4 {
            // With a mipmap blend, llvmpipe's piecewise linear log₂; the others exact.
            let half = if sampler.mip == Some(Filter::Linear) { 0.5 * fast_log2(rho2[q]) } else { 0.5 * log2(rho2[q]) };
            // Clamped as `Sampler::lambda` clamps (the maximum wins; NaN stays NaN).
            let mut l = (half + sampler.shader_bias) + sampler.lod_bias;
            if l < sampler.min_lod {
                l = sampler.min_lod;
            }
            if l > sampler.max_lod {
                l = sampler.max_lod;
            }
            lambda[q] = l;
        }
        lambda
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
    // `!(x < limit)` is true for NaN as well, in one vector compare.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    fn linear_axis(&self, k: usize, s: &F32s, sizef: &F32s, size: &I32s) -> (I32s, I32s, I32s) {
        const MAGIC: f32 = 12_582_912.0;
        let mut u = [0.0f32; LANES];
        for l in 0..LANES {
            let scaled = s[l] * sizef[l] - 0.5;
            u[l] = if s[l].is_finite() { scaled } else { 0.0 };
        }
        let mut f = [0i32; LANES];
        // Whether any lane is beyond the magic number's range, as one reduction (an array
        // of flags compared with all-false was packed to bytes and stored lane by lane);
        // the rare lanes beyond are found again in the branch.
        let mut big = false;
        for l in 0..LANES {
            let v = u[l] * 256.0;
            f[l] = ((v + MAGIC).to_bits() as i32).wrapping_sub(MAGIC.to_bits() as i32);
            big |= !(v.abs() < 4_194_304.0);
        }
        if big {
            for l in 0..LANES {
                if !((u[l] * 256.0).abs() < 4_194_304.0) {
                    f[l] = fixed(u[l]);
                }
            }
        }
        let (mut i0, mut i1, mut w) = ([0; LANES], [0; LANES], [0; LANES]);
        for l in 0..LANES {
            i0[l] = f[l] >> 8;
            i1[l] = (f[l] >> 8) + 1;
            w[l] = f[l] & 0xff;
        }
        (self.wrap_lanes(k, &i0, size), self.wrap_lanes(k, &i1, size), w)
    }

    /// `sampler::axis` (nearest) along axis `k` of 16 lanes: ⌊s · size⌋, wrapped. Below 2²²
    /// the integer nearest u (by the magic number) less one where it is above u;
    /// `floor_i32` beyond (a float-to-integer cast is scalar code per lane).
    #[inline(always)]
    // `!(x < limit)` is true for NaN as well, in one vector compare.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    fn nearest_axis(&self, k: usize, s: &F32s, sizef: &F32s, size: &I32s) -> I32s {
        const MAGIC: f32 = 12_582_912.0;
        let mut u = [0.0f32; LANES];
        let mut i = [0; LANES];
        // One reduction for the lanes beyond the magic number's range (see `linear_axis`).
        let mut big = false;
        for l in 0..LANES {
            u[l] = s[l] * sizef[l];
            let r = ((u[l] + MAGIC).to_bits() as i32).wrapping_sub(MAGIC.to_bits() as i32);
            i[l] = r - i32::from(r as f32 > u[l]);
            big |= !(u[l].abs() < 4_194_304.0);
        }
        if big {
            for l in 0..LANES {
                if !(u[l].abs() < 4_194_304.0) {
                    i[l] = if u[l].is_finite() { floor_i32(u[l]) } else { 0 };
                }
            }
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

    /// The filtered texels of the lanes at `st` in the levels `d` (one per quad), channel
    /// by channel; `None` if a level holds no RGBA8 texels.
    #[inline(always)]
    fn rgba_levels(
        &self,
        images: &[std::sync::Arc<TexImage>],
        d: [usize; 4],
        linear: bool,
        st: &[F32s; 2],
    ) -> Option<[U16s; 4]> {
        let mut fp = Footprint { index: [[0; LANES]; 4], wx: [0; LANES], wy: [0; LANES] };
        self.footprint(d, linear, st, &mut fp);
        let mut texels = [[0u32; LANES]; 4];
        let corners = if linear { 4 } else { 1 };
        if d[1..].iter().all(|&x| x == d[0]) {
            let t = rgba_texels(&images[d[0]])?;
            for c in 0..corners {
                for l in 0..LANES {
                    texels[c][l] = u32::from_le_bytes(t[fp.index[c][l] as usize]);
                }
            }
        } else {
            for q in 0..4 {
                let t = rgba_texels(&images[d[q]])?;
                for c in 0..corners {
                    for l in QUAD_LANES[q] {
                        texels[c][l] = u32::from_le_bytes(t[fp.index[c][l] as usize]);
                    }
                }
            }
        }
        // Channel by channel in 16-bit lanes (a 16-lane channel is one AVX2 register, and
        // SSE2 multiplies 16-bit lanes, not 32-bit ones).
        let (mut wx, mut wy) = ([0u16; LANES], [0u16; LANES]);
        for l in 0..LANES {
            (wx[l], wy[l]) = (fp.wx[l] as u16, fp.wy[l] as u16);
        }
        // The channels of each corner's texels (constant shifts, so that the loop
        // vectorises), then the lerps channel by channel.
        let mut p = [[[0u16; LANES]; 4]; 4];
        for c in 0..corners {
            for l in 0..LANES {
                let t = texels[c][l];
                p[0][c][l] = (t & 0xff) as u16;
                p[1][c][l] = ((t >> 8) & 0xff) as u16;
                p[2][c][l] = ((t >> 16) & 0xff) as u16;
                p[3][c][l] = (t >> 24) as u16;
            }
        }
        let mut channels = [[0u16; LANES]; 4];
        for k in 0..4 {
            if linear {
                for l in 0..LANES {
                    let upper = lerp8(p[k][0][l], p[k][1][l], wx[l]);
                    let lower = lerp8(p[k][2][l], p[k][3][l], wx[l]);
                    channels[k][l] = lerp8(upper, lower, wy[l]);
                }
            } else {
                channels[k] = p[k][0];
            }
        }
        Some(channels)
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
            for c in 0..corners {
                texels.gather_all(&fp.index[c], &mut raw[c]);
            }
        } else {
            for q in 0..4 {
                let (texels, f) = depth_texels(&images[d[q]])?;
                if f != format {
                    return None;
                }
                for c in 0..corners {
                    texels.gather(&fp.index[c], &QUAD_LANES[q], &mut raw[c]);
                }
            }
        }
        let mut v = [[0.0f32; LANES]; 4];
        for c in 0..corners {
            format.decode(&raw[c], &mut v[c]);
            if let Some(func) = compare {
                compare_lanes(func, reference, &mut v[c]);
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
            // A quad of one level blends it with itself at weight 0: itself.
            let quad_w = levels.frac.map(|f| (f * 256.0) as i32 as u16);
            let mut w = [0u16; LANES];
            for l in 0..LANES {
                w[l] = quad_w[QUAD_OF_LANE[l]];
            }
            for k in 0..4 {
                for l in 0..LANES {
                    v[k][l] = lerp8(v[k][l], b[k][l], w[l]);
                }
            }
        }
        // u8 → f32 as the reference converts it: `/ 255` from one level, `· (1/255)` from a
        // blend of two.
        for k in 0..4 {
            let mut x = [0.0f32; LANES];
            for l in 0..LANES {
                x[l] = v[k][l] as i32 as f32;
            }
            let o = &mut out[k];
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
        for k in 0..4 {
            if depth_channels[k] {
                for l in 0..LANES {
                    out[k][l] = d[l].to_bits();
                }
            } else {
                out[k] = [constant.to_bits(); LANES];
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
    wx: I32s,
    wy: I32s,
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

/// llvmpipe's 8-bit lerp `a + ((b − a)·w + 128) >> 8`, weight `w` in 1/256 (0..=255), as
/// `(a·(256 − w) + b·w + 128) >> 8` (the `256·a` is a whole multiple of 256) in 16 bits:
/// at most 255·256 + 128.
#[inline(always)]
fn lerp8(a: u16, b: u16, w: u16) -> u16 {
    (a * (256 - w) + b * w + 128) >> 8
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
                    out[l] = raw[l] as i32 as f32 * (1.0 / 65535.0);
                }
            }
            DepthFormat::Unorm24 => {
                // The single-precision quotient: the double-precision product rounded to
                // single precision, for every 24-bit value (the test below checks them
                // all), in a quarter of the instructions.
                for l in 0..LANES {
                    out[l] = (raw[l] & 0x00ff_ffff) as i32 as f32 / 16_777_215.0;
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
    /// The words at `index` of every lane, into `out`: [`Self::gather`] in a plain lane
    /// loop (through the list of lanes, each lane's index was loaded from it and its
    /// place in `out` checked).
    #[inline(always)]
    fn gather_all(self, index: &I32s, out: &mut U32s) {
        match self {
            DepthWords::U16(w) => {
                for l in 0..LANES {
                    out[l] = w[index[l] as usize] as u32;
                }
            }
            DepthWords::U32(w) => {
                for l in 0..LANES {
                    out[l] = w[index[l] as usize];
                }
            }
        }
    }

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

#[cfg(test)]
mod tests {
    use crate::framebuffer::format::DepthEncoding;

    #[test]
    fn single_precision_quotients_are_the_24_bit_depth_texels() {
        // `DepthFormat::Unorm24`'s decoding against `depth_texel`'s (Mesa's double-precision
        // product), for every 24-bit value.
        for v in 0..1u32 << 24 {
            let lanes = v as f32 / 16_777_215.0;
            assert_eq!(lanes.to_bits(), super::super::depth_texel(DepthEncoding::Unorm(24), v).to_bits(), "{v}");
        }
    }
}
