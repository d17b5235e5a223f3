//! Texturing: texture images as stored ([`TexImage`]), the samplers a draw compiles from
//! texture objects ([`sampler`]), the kernels that run their lookups a 2×2 quad at a time
//! (`kernel`, chosen once per draw), and the texture environments that combine texels with
//! the fragment color ([`env`]). [`Texturing::texture_quads`] textures 16 lanes given in
//! structure-of-arrays form; [`Texturing::texture_span`] runs the same quads for a span.
//!
//! Like `fragment`, this room knows no GL enums and no context: the context validates and
//! converts, then hands over images, compiled samplers and compiled environments.
//!
//! Storage is compact and chosen for sampling: every color format is kept as RGBA8 in the
//! texture-color form of its base format (GL 2.1 table 3.20: ALPHA as (0, 0, 0, A),
//! LUMINANCE as (L, L, L, 1), INTENSITY as (I, I, I, I), RGB with A = 1), quantized to the
//! bits of the format Mesa 22 chooses for the internal format (GL_RGBA4 keeps 4 bits per
//! channel, widened back to 8 by replication). Formats of more than 8 bits per color channel
//! are stored with 8.
//!
//! **Images are stored as the framebuffer stores them**, so that a texture image attached
//! to a framebuffer object is rendered where it lives (`context::framebuffer_object` moves
//! the pixel vector into a [`crate::framebuffer::Framebuffer`] and back; no texel is copied
//! or converted per scene). The layout is linear: rows bottom-up, x fastest, no padding,
//! which is what both users want. The tile workers address a framebuffer by rows (a band is
//! a range of rows, a span a run of one row), and the sampler fetches 2×2 neighbourhoods at
//! arbitrary positions, for which a linear image costs one multiply-add per texel and keeps
//! the two rows of a bilinear footprint one row stride apart; a tiled layout would need a
//! swizzle in every span loop of the tile workers, in every row copy of glReadPixels,
//! glTexSubImage and glGetTexImage, and would only pay for sampling patterns (rotated
//! minification) that the scenes we measure do not have. Color images are
//! [`Texels::Rgba8`], the pixels of an 8-bit unorm color buffer. Depth images are a
//! [`DepthStencilBuffer`] of their format (16-bit, packed 24-bit depth with an 8-bit stencil
//! index above it, 32-bit fixed point, or the f32 bit patterns of float depth with a
//! separate stencil plane): the values a depth test compares, and the sampler decodes them
//! per fetch (an integer-to-float conversion and one multiplication, see [`depth_texel`]),
//! which is cheaper than converting a whole image per scene. Depth-stencil formats
//! (GL_EXT_packed_depth_stencil) keep their stencil indices in that buffer: sampling sees
//! only the depth, as GL specifies.
#![deny(unsafe_code)]

pub mod env;
mod kernel;
pub mod sampler;

use crate::framebuffer::format::DepthEncoding;
pub use crate::framebuffer::surface::DepthStencilPixels;
pub use crate::framebuffer::{DepthStencilBuffer, DepthStencilFormat};

/// The base internal format of a texture image (GL 2.1 table 3.15).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BaseFormat {
    Alpha,
    Luminance,
    LuminanceAlpha,
    Intensity,
    Rgb,
    Rgba,
    Depth,
}

impl BaseFormat {
    /// The texture color of an RGBA group (after unpacking) in this base format: the
    /// components the format keeps, the others as table 3.20 fills them in.
    pub fn texture_color(self, c: [f32; 4]) -> [f32; 4] {
        match self {
            BaseFormat::Alpha => [0.0, 0.0, 0.0, c[3]],
            BaseFormat::Luminance => [c[0], c[0], c[0], 1.0],
            BaseFormat::LuminanceAlpha => [c[0], c[0], c[0], c[3]],
            BaseFormat::Intensity => [c[0]; 4],
            BaseFormat::Rgb => [c[0], c[1], c[2], 1.0],
            BaseFormat::Rgba | BaseFormat::Depth => c,
        }
    }
}

/// The texels of one image, row-major (x fastest, then y, then z), border included.
#[derive(Clone, Debug, PartialEq)]
pub enum Texels {
    /// The pixels of an 8-bit unorm color buffer.
    Rgba8(Vec<[u8; 4]>),
    /// Depth (and stencil indices) as a depth/stencil buffer of the image's format stores
    /// them, one buffer row per image row.
    Depth(DepthStencilBuffer),
}

/// One mipmap level of one face: its size (border included), border width and texels.
#[derive(Clone, Debug, PartialEq)]
pub struct TexImage {
    pub width: usize,
    pub height: usize,
    pub depth: usize,
    pub border: usize,
    pub base: BaseFormat,
    pub texels: Texels,
}

/// Why an image could not be made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutOfMemory;

/// Rounds `value` (clamped to [0, 1]) to `bits` bits and widens it back to 8 by bit
/// replication, as an n-bit texel reads back through an 8-bit channel.
#[inline]
pub fn quantize_to_u8(value: f32, bits: u32) -> u8 {
    let v = if value > 0.0 { value.min(1.0) } else { 0.0 };
    if bits >= 8 || bits == 0 {
        return crate::pixel::convert::float_to_unorm(v, 8) as u8;
    }
    let n = crate::pixel::convert::float_to_unorm(v, bits);
    crate::pixel::convert::unorm_to_unorm(n, bits, 8) as u8
}

/// The storage of a depth texture format: depth of `bits` bits (16, 24 or 32), `float` for
/// the f32 depth of ARB_depth_buffer_float, with a stencil index per texel when `stencil`.
/// It is also the format of the depth buffer the texture renders as.
pub fn depth_storage(bits: u32, stencil: bool, float: bool) -> DepthStencilFormat {
    match bits {
        _ if float => DepthStencilFormat::Float32 { stencil },
        16 => DepthStencilFormat::Depth16,
        32 => DepthStencilFormat::Depth32 { stencil },
        _ => DepthStencilFormat::Packed24 { depth: true, stencil },
    }
}

/// A depth value (client data, a copied depth) as a depth texel of `encoding` stores it:
/// fixed point rounds the clamped value times 2ⁿ − 1 to nearest in double precision; float
/// depth keeps the clamped value.
#[inline]
pub fn encode_depth(encoding: DepthEncoding, value: f32) -> u32 {
    match encoding {
        DepthEncoding::Unorm(bits) => {
            let v = if value > 0.0 { value.min(1.0) } else { 0.0 };
            let max = crate::pixel::convert::unorm_max(bits) as f64;
            (v as f64 * max).round() as u32
        }
        DepthEncoding::Float => crate::framebuffer::format::float_depth_bits(value),
    }
}

/// A stored depth texel as the sampler reads it: n-bit fixed point as Mesa's texture
/// fetches convert it (`crate::pixel::convert::depth_to_float`), float depth as itself.
#[inline]
pub fn depth_texel(encoding: DepthEncoding, stored: u32) -> f32 {
    match encoding {
        DepthEncoding::Unorm(bits) => crate::pixel::convert::depth_to_float(stored, bits),
        DepthEncoding::Float => f32::from_bits(stored),
    }
}

impl TexImage {
    /// A `width` × `height` × `depth` color image (border included) of zero texels (a
    /// depth image of 24 bits for [`BaseFormat::Depth`]; see [`TexImage::new_depth`]).
    pub fn new(
        width: usize,
        height: usize,
        depth: usize,
        border: usize,
        base: BaseFormat,
    ) -> Result<TexImage, OutOfMemory> {
        if base == BaseFormat::Depth {
            return TexImage::new_depth(width, height, depth, border, depth_storage(24, false, false));
        }
        let count = width.checked_mul(height).and_then(|n| n.checked_mul(depth)).ok_or(OutOfMemory)?;
        let mut v = Vec::new();
        v.try_reserve_exact(count).map_err(|_| OutOfMemory)?;
        v.resize(count, base_texel(base));
        Ok(TexImage { width, height, depth, border, base, texels: Texels::Rgba8(v) })
    }

    /// A `width` × `height` × `depth` depth image (border included) of `format`, depth and
    /// stencil zero.
    pub fn new_depth(
        width: usize,
        height: usize,
        depth: usize,
        border: usize,
        format: DepthStencilFormat,
    ) -> Result<TexImage, OutOfMemory> {
        let rows = height.checked_mul(depth).ok_or(OutOfMemory)?;
        let buffer = crate::framebuffer::layers::depth_stencil_buffer(format, width, rows).map_err(|_| OutOfMemory)?;
        Ok(TexImage { width, height, depth, border, base: BaseFormat::Depth, texels: Texels::Depth(buffer) })
    }

    /// Index of texel (x, y, z) (border included).
    #[inline]
    pub fn index(&self, x: usize, y: usize, z: usize) -> usize {
        (z * self.height + y) * self.width + x
    }

    /// The format of a depth image's storage (`None` for color images).
    pub fn depth_format(&self) -> Option<DepthStencilFormat> {
        match &self.texels {
            Texels::Depth(d) => Some(d.format()),
            Texels::Rgba8(_) => None,
        }
    }

    /// Whether the image keeps a stencil index per texel (a depth-stencil image).
    pub fn has_stencil(&self) -> bool {
        self.depth_format().is_some_and(|f| f.stencil_bits() > 0)
    }

    /// Depth texel `i` as the sampler reads it (0 for color images).
    #[inline]
    pub fn depth_f32(&self, i: usize) -> f32 {
        match &self.texels {
            Texels::Depth(d) => depth_texel(d.depth_encoding(), d.depth_value(i)),
            Texels::Rgba8(_) => 0.0,
        }
    }

    /// Stores `value` (clamped to [0, 1]) as depth texel `i` of a depth image, its stencil
    /// index unchanged.
    #[inline]
    pub fn set_depth_f32(&mut self, i: usize, value: f32) {
        if let Texels::Depth(d) = &mut self.texels {
            let stored = encode_depth(d.depth_encoding(), value);
            d.set_depth_value(i, stored);
        }
    }

    /// The stencil index of texel `i` (0 without stencil).
    #[inline]
    pub fn stencil(&self, i: usize) -> u8 {
        match &self.texels {
            Texels::Depth(d) => d.stencil_value(i),
            Texels::Rgba8(_) => 0,
        }
    }

    /// Sets the stencil index of texel `i` (nothing without stencil).
    #[inline]
    pub fn set_stencil(&mut self, i: usize, index: u8) {
        if let Texels::Depth(d) = &mut self.texels {
            d.set_stencil_value(i, index);
        }
    }

    /// The texel at (x, y, z) as RGBA floats (depth in R, G, B and A).
    pub fn texel_f32(&self, i: usize) -> [f32; 4] {
        match &self.texels {
            Texels::Rgba8(t) => t[i].map(|c| c as f32 / 255.0),
            Texels::Depth(_) => [self.depth_f32(i); 4],
        }
    }
}

/// The stored value of a texel no data has been given for: zero in the format's channels.
fn base_texel(base: BaseFormat) -> [u8; 4] {
    match base {
        BaseFormat::Luminance | BaseFormat::Rgb => [0, 0, 0, 255],
        _ => [0; 4],
    }
}

/// The size of mipmap level `level` of a dimension whose base size is `size` (border
/// excluded): ⌊size / 2^level⌋, at least 1.
pub fn level_size(size: usize, level: usize) -> usize {
    if level >= usize::BITS as usize {
        1
    } else {
        (size >> level).max(1)
    }
}

/// The next level of a mipmap chain (GL_GENERATE_MIPMAP): each texel the average of the
/// 2×2×2 (or fewer, for dimensions already 1) texels below it. Borders are not filtered
/// (the new level gets none).
pub fn downsample(src: &TexImage, dims: usize) -> Result<TexImage, OutOfMemory> {
    let b = src.border;
    let (w, h, d) = (src.width - 2 * b, src.height - 2 * b.min(usize::from(dims >= 2)), src.depth);
    let h = if dims >= 2 { h } else { 1 };
    let d = if dims >= 3 { d - 2 * b } else { 1 };
    let (nw, nh, nd) = ((w / 2).max(1), (h / 2).max(1), (d / 2).max(1));
    let mut out = match src.depth_format() {
        Some(format) => TexImage::new_depth(nw, nh, nd, 0, format)?,
        None => TexImage::new(nw, nh, nd, 0, src.base)?,
    };
    let (fx, fy, fz) = (if w > 1 { 2 } else { 1 }, if h > 1 { 2 } else { 1 }, if d > 1 { 2 } else { 1 });
    let by = if dims >= 2 { b } else { 0 };
    let bz = if dims >= 3 { b } else { 0 };
    // Halves as llvmpipe's mipmap blit samples them: bilinear at the centre of each 2×2
    // (×2) box, each lerp an 8-bit lerp at weight 1/2 rounded (x + ⌊(y − x + 1) / 2⌋).
    let half = |p: [f32; 4], q: [f32; 4], eight_bit: bool| -> [f32; 4] {
        if eight_bit {
            std::array::from_fn(|k| {
                let (a, b) = (byte(p[k]) as i32, byte(q[k]) as i32);
                (a + (((b - a) * 128 + 128) >> 8)) as f32 / 255.0
            })
        } else {
            std::array::from_fn(|k| (p[k] + q[k]) * 0.5)
        }
    };
    let eight_bit = matches!(src.texels, Texels::Rgba8(_));
    // An 8-bit value v as a float (v / 255, v · (1/255)) back to v: c · 255 is within a few
    // ulps of v, so adding ½ and truncating rounds it as `round` would, without the libm
    // call per channel (`roundf`, out of line: most of a mipmap chain's cost).
    fn byte(c: f32) -> u8 {
        (c * 255.0 + 0.5) as u8
    }
    for z in 0..nd {
        for y in 0..nh {
            for x in 0..nw {
                let texel = |dx: usize, dy: usize, dz: usize| {
                    src.texel_f32(src.index(
                        x * fx + dx.min(fx - 1) + b,
                        y * fy + dy.min(fy - 1) + by,
                        z * fz + dz.min(fz - 1) + bz,
                    ))
                };
                let row = |dy, dz| half(texel(0, dy, dz), texel(1, dy, dz), eight_bit);
                let plane = |dz| half(row(0, dz), row(1, dz), eight_bit);
                let v = half(plane(0), plane(1), eight_bit);
                let o = out.index(x, y, z);
                match &mut out.texels {
                    Texels::Rgba8(t) => t[o] = v.map(byte),
                    Texels::Depth(_) => out.set_depth_f32(o, v[0]),
                }
                if out.has_stencil() {
                    // Stencil indices are not averaged: each keeps its box's first index.
                    out.set_stencil(o, src.stencil(src.index(x * fx + b, y * fy + by, z * fz + bz)));
                }
            }
        }
    }
    Ok(out)
}

/// One enabled unit of a draw: its sampler (chosen once per draw), its environment and
/// where its texture coordinates are among the draw's varyings (s, t, r, q from `slot`).
#[derive(Clone, Debug)]
pub struct TextureStage {
    pub unit: usize,
    pub sampler: sampler::Sampler,
    pub env: env::TexEnv,
    pub slot: usize,
    /// How the sampler's lookups run, chosen from it.
    kernel: kernel::Kernel,
    /// Whether a lookup depends on the derivatives of its coordinates: not when every λ
    /// gives the same level and filter (no mipmaps, one filter for magnification and
    /// minification), as for most shadow maps.
    derivatives: bool,
}

impl TextureStage {
    /// The texture colors (`out[channel][lane]`, before the environment) of the lanes
    /// `live` of a 4×4 block, lanes row-major (lane `i` at column `i & 3`, row `i >> 2`,
    /// rows upward) and the coordinates `c` already divided by q: the level of detail per
    /// 2×2 quad of rows (0, 1) and (2, 3), the upper row of each (llvmpipe's) giving the x
    /// derivative and its left column the y one. Every lane of a quad with a live lane must
    /// hold its pixel's coordinates. This is the implicit-LOD lookup a program's sample
    /// instruction needs (`shader::exec::Textures::sample` over a draw's stages: divide by
    /// q when projective, then call this); lanes of other quads are left alone.
    #[inline]
    pub fn sample_block(&self, c: &[F32s; 3], live: u16, out: &mut [F32s; 4]) {
        self.kernel.sample_block(&self.sampler, c, live, out);
    }

    pub fn new(unit: usize, sampler: sampler::Sampler, env: env::TexEnv, slot: usize) -> TextureStage {
        let kernel = kernel::Kernel::choose(&sampler);
        let derivatives = sampler.mip.is_some() || sampler.mag != sampler.min;
        TextureStage { unit, sampler, env, slot, kernel, derivatives }
    }
}

/// The texturing of a draw: only the units that are enabled and complete, in unit order.
#[derive(Clone, Debug)]
pub struct Texturing {
    pub stages: Vec<TextureStage>,
    /// Framebuffer height: derivatives are taken per 2×2 quad of llvmpipe's y-down rows.
    pub fb_height: i32,
}

impl PartialEq for Texturing {
    /// Two draws texture alike only if they share the very same images.
    fn eq(&self, other: &Self) -> bool {
        self.fb_height == other.fb_height
            && self.stages.len() == other.stages.len()
            && self.stages.iter().zip(&other.stages).all(|(a, b)| {
                a.unit == b.unit
                    && a.slot == b.slot
                    && a.env == b.env
                    && a.sampler.faces.len() == b.sampler.faces.len()
                    && a.sampler
                        .faces
                        .iter()
                        .zip(&b.sampler.faces)
                        .all(|(x, y)| x.len() == y.len() && x.iter().zip(y).all(|(p, q)| std::sync::Arc::ptr_eq(p, q)))
            })
    }
}

/// Most texture units a draw can use.
pub const MAX_UNITS: usize = crate::gl::limits::MAX_TEXTURE_UNITS;

/// Fragments in a block given to [`Texturing::texture_quads`]: four 2×2 quads.
pub const LANES: usize = 16;

/// One value per lane of a block.
pub type F32s = [f32; LANES];

/// The lanes of a 4-bit mask, in order.
#[inline(always)]
fn lanes4(mask: u8) -> impl Iterator<Item = usize> {
    (0..4).filter(move |&l| mask & (1 << l) != 0)
}

/// The projected coordinates (s/q, t/q, r/q) of a stage from a fragment's varyings.
#[inline]
fn projected(v: &[f32], slot: usize) -> [f32; 3] {
    let q = v[slot + 3];
    let inv = if q != 0.0 { 1.0 / q } else { 0.0 };
    [v[slot] * inv, v[slot + 1] * inv, v[slot + 2] * inv]
}

impl Texturing {
    /// Textures the lanes `live` of one quad: `coords[k][lane]` are stage k's projected
    /// coordinates (every lane's: the derivatives need the upper row and the left column
    /// even where their fragments are not live), `colors` the primary colors, replaced by
    /// the last unit's output.
    #[inline]
    fn texture_quad(&self, coords: &[[[f32; 3]; 4]; MAX_UNITS], live: u8, colors: &mut [[f32; 4]; 4]) {
        if let [s] = self.stages.as_slice() {
            // One unit, and an environment that reads no other unit's texture: no table of
            // every unit's texels.
            if !matches!(s.env.mode, env::EnvMode::Combine(_)) {
                let mut out = [[0.0; 4]; 4];
                s.kernel.sample_quad(&s.sampler, &coords[0], live, &mut out);
                for (lane, (color, texel)) in colors.iter_mut().zip(&out).enumerate() {
                    if live & (1 << lane) != 0 {
                        *color = s.env.apply(0, *color, *color, std::slice::from_ref(texel));
                    }
                }
                return;
            }
        }
        let mut texels = [[[0.0, 0.0, 0.0, 1.0]; MAX_UNITS]; 4];
        for (k, s) in self.stages.iter().enumerate() {
            let mut out = [[0.0; 4]; 4];
            s.kernel.sample_quad(&s.sampler, &coords[k], live, &mut out);
            for (lane, t) in texels.iter_mut().enumerate() {
                t[s.unit] = out[lane];
            }
        }
        for (lane, color) in colors.iter_mut().enumerate() {
            if live & (1 << lane) == 0 {
                continue;
            }
            let primary = *color;
            let mut previous = primary;
            for s in &self.stages {
                previous = s.env.apply(s.unit, previous, primary, &texels[lane]);
            }
            *color = previous;
        }
    }

    /// Textures the fragments `live` of a block of [`LANES`] lanes in structure-of-arrays
    /// form: lane `4·q + 2·r + c` is column c (0 left) of row r (0 the upper in llvmpipe's
    /// y-down rows) of quad q. `varyings[v][lane]` holds varying v of the draw (stage k's
    /// s, t, r, q at its slot); every lane of a quad with a live lane must hold its
    /// pixel's varyings (helper lanes give the derivatives). `colors[channel][lane]` holds
    /// the primary colors and receives the last unit's output for the live lanes.
    pub fn texture_quads(&self, varyings: &[[f32; LANES]], live: u16, colors: &mut [[f32; LANES]; 4]) {
        for q in 0..LANES / 4 {
            let quad_live = ((live >> (4 * q)) & 0xf) as u8;
            if quad_live == 0 {
                continue;
            }
            let mut coords = [[[0.0; 3]; 4]; MAX_UNITS];
            for (k, s) in self.stages.iter().enumerate() {
                for (lane, c) in coords[k].iter_mut().enumerate() {
                    let v = [0, 1, 2, 3].map(|j| varyings[s.slot + j][4 * q + lane]);
                    *c = projected(&v, 0);
                }
            }
            let mut quad = [[0.0; 4]; 4];
            for (lane, c) in quad.iter_mut().enumerate() {
                *c = std::array::from_fn(|ch| colors[ch][4 * q + lane]);
            }
            self.texture_quad(&coords, quad_live, &mut quad);
            for (lane, c) in quad.iter().enumerate() {
                if quad_live & (1 << lane) != 0 {
                    for ch in 0..4 {
                        colors[ch][4 * q + lane] = c[ch];
                    }
                }
            }
        }
    }

    /// Textures the fragments `live` of a 4×4 block at window row `y` (and some column x), its lanes
    /// row-major (lane `i` is pixel `(x + (i & 3), y + (i >> 2))`, rows upward):
    /// `colors[channel][lane]` holds the primary colors and receives the last unit's output
    /// in the live lanes. `varying_lanes(y0, first, out)` gives varyings `first ..
    /// first + out.len()` of the 16 lanes of the block at `(x, y0)` (`y0` is `y`, or `y − 1`
    /// and `y + 3`, see below), each lane the value its pixel's own evaluation gives.
    ///
    /// The same bits as [`Texturing::texture_span`] on the block's rows: the level of
    /// detail is per 2×2 quad of llvmpipe's y-down rows, whose row pairs are the block's
    /// (0, 1) and (2, 3) when `fb_height − y` is even; otherwise they straddle the block's
    /// edges, and the lookups that need derivatives run on the blocks one row below and
    /// three rows above, whose row pairs are those quads (a lookup that needs none takes
    /// the block as it is). Every lane of a quad with a live lane is evaluated: no
    /// neighbour is evaluated twice, as the span path does per row.
    pub fn texture_block(
        &self,
        y: i32,
        live: u16,
        colors: &mut [F32s; 4],
        varying_lanes: impl Fn(i32, usize, &mut [F32s]),
    ) {
        if self.stages.is_empty() || live == 0 {
            return;
        }
        crate::simd::per_level!({
            let aligned = (self.fb_height - y) & 1 == 0 || !self.stages.iter().any(|s| s.derivatives);
            if aligned {
                self.texture_aligned(y, live, colors, &varying_lanes);
                return;
            }
            // Rows 0..3 of the block are rows 1..4 of the block below, row 3 is row 0 of
            // the block above.
            let below = live << 4;
            if below != 0 {
                let mut shifted = [[0.0; LANES]; 4];
                for (s, c) in shifted.iter_mut().zip(colors.iter()) {
                    s[4..].copy_from_slice(&c[..12]);
                }
                self.texture_aligned(y - 1, below, &mut shifted, &varying_lanes);
                for (s, c) in shifted.iter().zip(colors.iter_mut()) {
                    c[..12].copy_from_slice(&s[4..]);
                }
            }
            let above = live >> 12;
            if above != 0 {
                let mut shifted = [[0.0; LANES]; 4];
                for (s, c) in shifted.iter_mut().zip(colors.iter()) {
                    s[..4].copy_from_slice(&c[12..]);
                }
                self.texture_aligned(y + 3, above, &mut shifted, &varying_lanes);
                for (s, c) in shifted.iter().zip(colors.iter_mut()) {
                    c[12..].copy_from_slice(&s[..4]);
                }
            }
        })
    }

    /// [`Texturing::texture_block`] on a block whose row pairs are llvmpipe's quads (or
    /// whose lookups need no derivatives), at window row `y`.
    #[inline(always)]
    fn texture_aligned(
        &self,
        y: i32,
        live: u16,
        colors: &mut [F32s; 4],
        varying_lanes: &impl Fn(i32, usize, &mut [F32s]),
    ) {
        // Each stage's projected coordinates over the lanes, and its texture colors.
        let mut texels = [[[0.0f32; LANES]; 4]; MAX_UNITS];
        for (s, t) in self.stages.iter().zip(texels.iter_mut()) {
            let mut v = [[0.0; LANES]; 4];
            varying_lanes(y, s.slot, &mut v);
            let mut c = [[0.0; LANES]; 3];
            for i in 0..LANES {
                let q = v[3][i];
                let inv = if q != 0.0 { 1.0 / q } else { 0.0 };
                for j in 0..3 {
                    c[j][i] = v[j][i] * inv;
                }
            }
            s.sample_block(&c, live, t);
        }
        if self.stages.iter().all(|s| s.env.has_lanes()) {
            for (s, t) in self.stages.iter().zip(&texels) {
                s.env.apply_lanes(colors, t, live);
            }
            return;
        }
        // GL_COMBINE reads every unit's texture and the primary color: per fragment.
        for i in (0..LANES).filter(|i| live & (1 << i) != 0) {
            let mut unit_texels = [[0.0, 0.0, 0.0, 1.0]; MAX_UNITS];
            for (s, t) in self.stages.iter().zip(&texels) {
                unit_texels[s.unit] = std::array::from_fn(|k| t[k][i]);
            }
            let primary: [f32; 4] = std::array::from_fn(|k| colors[k][i]);
            let mut previous = primary;
            for s in &self.stages {
                previous = s.env.apply(s.unit, previous, primary, &unit_texels);
            }
            for (k, c) in colors.iter_mut().enumerate() {
                c[i] = previous[k];
            }
        }
    }

    /// Textures the fragments of `live` of the span at window row `y`, columns `x0..`:
    /// `colors` holds the primary colors and receives the last unit's output.
    /// `varyings_at(dx, dy, out)` evaluates the draw's varyings at the pixel `dx` columns
    /// right of the span's first and `dy` rows above it (the quad neighbours of a pixel
    /// give the derivatives).
    pub fn texture_span(
        &self,
        colors: &mut [[f32; 4]],
        live: u64,
        x0: i32,
        y: i32,
        scratch: &mut Vec<f32>,
        varyings_at: impl Fn(i32, i32, &mut [f32]),
    ) {
        // No complete unit: the colors pass unchanged.
        let Some(n) = self.stages.iter().map(|s| s.slot + 4).max() else { return };
        scratch.resize(4 * n, 0.0);
        let mut lane_varyings = scratch.chunks_exact_mut(n);
        let mut lane = || lane_varyings.next().unwrap_or_default();
        let v = [lane(), lane(), lane(), lane()];
        let live = live & if colors.len() >= 64 { u64::MAX } else { (1 << colors.len()) - 1 };
        if !self.stages.iter().any(|s| s.derivatives) {
            // No lookup depends on derivatives: a fragment's texture color depends on its
            // own coordinates only (evaluated at its pixel, dy = 0, as below), so any four
            // fragments of the span can go through the quad kernels together, and no
            // neighbour is evaluated.
            let mut first = 0;
            while live >> first != 0 {
                let group = ((live >> first) & 0xf) as u8;
                if group != 0 {
                    let mut coords = [[[0.0; 3]; 4]; MAX_UNITS];
                    let mut quad = [[0.0; 4]; 4];
                    for l in lanes4(group) {
                        let i = first + l;
                        varyings_at(i as i32, 0, v[l]);
                        for (k, s) in self.stages.iter().enumerate() {
                            coords[k][l] = projected(v[l], s.slot);
                        }
                        quad[l] = colors[i];
                    }
                    self.texture_quad(&coords, group, &mut quad);
                    for l in lanes4(group) {
                        colors[first + l] = quad[l];
                    }
                }
                first += 4;
                if first >= 64 {
                    break;
                }
            }
            return;
        }
        // Quad rows in llvmpipe's y-down numbering: the quad's upper row, and the one below;
        // the span is one of them (`row`), its fragments the lanes 2·row and 2·row + 1.
        let y_down = self.fb_height - 1 - y;
        let upper = self.fb_height - 1 - (y_down & !1) - y;
        let row = usize::from(upper != 0);
        let in_span = |i: i32| (0..64).contains(&i) && live & (1 << i) != 0;
        let mut rest = live;
        while rest != 0 {
            let i = rest.trailing_zeros() as i32;
            // The span index of the quad's left column (−1 when the span starts on its right).
            let left = ((x0 + i) & !1) - x0;
            let mut quad_live = 0u8;
            for c in 0..2 {
                if in_span(left + c) {
                    quad_live |= 1 << (2 * row + c as usize);
                    rest &= !(1 << (left + c));
                }
            }
            // The upper row and the left column give the derivatives; the lower right
            // pixel is evaluated only as a fragment of the span. A fragment's own lane is
            // evaluated at the very arguments of its pixel (dy = 0), so it is the same.
            varyings_at(left, upper, v[0]);
            varyings_at(left + 1, upper, v[1]);
            varyings_at(left, upper - 1, v[2]);
            if quad_live & 8 != 0 {
                varyings_at(left + 1, upper - 1, v[3]);
            }
            let mut coords = [[[0.0; 3]; 4]; MAX_UNITS];
            for (k, s) in self.stages.iter().enumerate() {
                for (l, c) in coords[k].iter_mut().enumerate() {
                    if l < 3 || quad_live & 8 != 0 {
                        *c = projected(v[l], s.slot);
                    }
                }
            }
            let mut quad = [[0.0; 4]; 4];
            for c in 0..2 {
                if quad_live & (1 << (2 * row + c)) != 0 {
                    quad[2 * row + c] = colors[(left + c as i32) as usize];
                }
            }
            self.texture_quad(&coords, quad_live, &mut quad);
            for c in 0..2 {
                if quad_live & (1 << (2 * row + c)) != 0 {
                    colors[(left + c as i32) as usize] = quad[2 * row + c];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantization_replicates_low_bits() {
        assert_eq!(quantize_to_u8(1.0, 4), 255);
        assert_eq!(quantize_to_u8(0.5, 4), 0x88);
        assert_eq!(quantize_to_u8(0.5, 1), 0); // ties to even
        assert_eq!(quantize_to_u8(0.75, 1), 255);
        assert_eq!(quantize_to_u8(0.2, 8), 51);
        assert_eq!(quantize_to_u8(-1.0, 8), 0);
    }

    #[test]
    fn depth_texels_keep_the_depth_buffer_encoding() {
        // Fixed point rounds to nearest (0.5 · 65535 = 32767.5 → 32768) and reads back as
        // Mesa's fetch converts it; float depth keeps the clamped value, −0 as +0.
        assert_eq!(encode_depth(DepthEncoding::Unorm(16), 0.5), 32768);
        assert_eq!(depth_texel(DepthEncoding::Unorm(16), 32768), 32768.0 * (1.0 / 65535.0f32));
        assert_eq!(encode_depth(DepthEncoding::Unorm(24), 2.0), 0xff_ffff);
        assert_eq!(encode_depth(DepthEncoding::Unorm(24), f32::NAN), 0);
        assert_eq!(depth_texel(DepthEncoding::Unorm(24), 0xff_ffff), 1.0);
        assert_eq!(encode_depth(DepthEncoding::Float, -0.0), 0);
        assert_eq!(depth_texel(DepthEncoding::Float, encode_depth(DepthEncoding::Float, 0.3)), 0.3);
        // A depth-stencil image: depth and stencil share a packed word, and setting one
        // keeps the other.
        let format = depth_storage(24, true, false);
        assert_eq!(format, DepthStencilFormat::Packed24 { depth: true, stencil: true });
        let mut image = TexImage::new_depth(2, 1, 1, 0, format).unwrap();
        image.set_stencil(1, 0xa5);
        image.set_depth_f32(1, 1.0);
        image.set_depth_f32(0, 0.25);
        let Texels::Depth(buffer) = &image.texels else { unreachable!() };
        let DepthStencilPixels::Packed24(words) = buffer.pixels() else { unreachable!() };
        assert_eq!(words, &vec![0x40_0000, 0xa5ff_ffff]);
        assert_eq!((image.stencil(1), image.depth_f32(1)), (0xa5, 1.0));
        let float = TexImage::new_depth(1, 1, 1, 0, depth_storage(32, true, true)).unwrap();
        assert_eq!(float.depth_format(), Some(DepthStencilFormat::Float32 { stencil: true }));
        assert!(
            float.has_stencil()
                && !TexImage::new_depth(1, 1, 1, 0, depth_storage(16, false, false)).unwrap().has_stencil()
        );
    }

    /// A trilinear RGBA 2D sampler over `levels`, repeating in s and mirrored in t.
    fn trilinear_rgba(levels: Vec<std::sync::Arc<TexImage>>) -> sampler::Sampler {
        use sampler::{DepthMode, Dim, Filter, Wrap};
        sampler::Sampler {
            dim: Dim::D2,
            faces: vec![levels],
            wrap: [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::Repeat],
            mag: Filter::Linear,
            min: Filter::Linear,
            mip: Some(Filter::Linear),
            border: [0.0; 4],
            lod_bias: 0.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            compare: None,
            depth_mode: DepthMode::Luminance,
            base: BaseFormat::Rgba,
        }
    }

    #[test]
    fn quads_and_spans_texture_alike() {
        use std::sync::Arc;
        let mut seed = 0x2545_f491u32;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        let levels: Vec<_> = [8usize, 4, 2, 1]
            .iter()
            .map(|&n| {
                let mut img = TexImage::new(n, n, 1, 0, BaseFormat::Rgba).unwrap();
                img.texels = Texels::Rgba8((0..n * n).map(|_| next().to_le_bytes()).collect());
                Arc::new(img)
            })
            .collect();
        let sampler = trilinear_rgba(levels);
        let env = env::TexEnv { mode: env::EnvMode::Modulate, base: BaseFormat::Rgba, color: [0.0; 4] };
        let (w, h) = (9, 7);
        let texturing = Texturing { stages: vec![TextureStage::new(0, sampler, env, 1)], fb_height: h };
        // Varyings: one unused, then s, t, r, q with perspective.
        let at = |x: i32, y: i32, out: &mut [f32]| {
            let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
            let q = 1.0 + 0.05 * x - 0.02 * y;
            out[..5].copy_from_slice(&[9.0, (0.13 * x + 0.04 * y) / q, (0.02 * x - 0.3 * y) / q, 0.0, q]);
        };
        let primary = |x: i32, y: i32| [x as f32 / 9.0, y as f32 / 7.0, 0.5, 1.0];
        // Spans: one per row from column 1, every other pixel but two live.
        let mut image = vec![[[0.0; 4]; 9]; 7];
        let mut scratch = Vec::new();
        for y in 0..h {
            let mut colors: Vec<_> = (1..w).map(|x| primary(x, y)).collect();
            texturing
                .texture_span(&mut colors, 0xff & !0b100100, 1, y, &mut scratch, |dx, dy, out| at(1 + dx, y + dy, out));
            for (x, c) in colors.iter().enumerate() {
                image[y as usize][x + 1] = *c;
            }
        }
        // The same pixels as quads: the upper rows of the y-down pairs.
        let mut compared = 0;
        for upper in (1..h).rev().filter(|y| (h - 1 - y) % 2 == 0) {
            for x0 in (0..w - 1).step_by(2) {
                let mut varyings = vec![[0.0; LANES]; 5];
                let mut colors = [[0.0; LANES]; 4];
                let mut live = 0u16;
                for lane in 0..4 {
                    let (x, y) = (x0 + (lane % 2) as i32, upper - (lane / 2) as i32);
                    let mut v = [0.0; 5];
                    at(x, y, &mut v);
                    for (k, value) in v.iter().enumerate() {
                        varyings[k][lane] = *value;
                    }
                    let p = primary(x, y);
                    for ch in 0..4 {
                        colors[ch][lane] = p[ch];
                    }
                    if (1..w).contains(&x) && ![2, 5].contains(&(x - 1)) {
                        live |= 1 << lane;
                    }
                }
                texturing.texture_quads(&varyings, live, &mut colors);
                for lane in (0..4).filter(|l| live & (1 << l) != 0) {
                    let (x, y) = (x0 + (lane % 2) as i32, upper - (lane / 2) as i32);
                    let quad: [f32; 4] = std::array::from_fn(|ch| colors[ch][lane]);
                    assert_eq!(quad, image[y as usize][x as usize], "pixel ({x}, {y})");
                    assert_ne!(quad, primary(x, y));
                    compared += 1;
                }
            }
        }
        assert_eq!(compared, 30);
        // No complete unit: the colors pass unchanged.
        let none = Texturing { stages: Vec::new(), fb_height: h };
        let mut colors = vec![[0.25; 4]; 3];
        none.texture_span(&mut colors, 0b111, 0, 0, &mut scratch, |_, _, _| unreachable!());
        assert_eq!(colors, vec![[0.25; 4]; 3]);
    }

    use crate::gl::test_rng::TestRng as Rng;

    /// Random draws of one to three units (every kernel: RGBA8 2D, depth with comparison,
    /// a bordered or clamped 2D image and a cube map through the reference; every classic
    /// environment and GL_COMBINE), on framebuffers of odd and even heights: each block
    /// textured over its lanes gives the bits of the span path on its rows, whatever the
    /// mask. A wrong lane order, a quad of the wrong rows or derivatives taken the wrong
    /// way round change levels of detail (the coordinates vary anisotropically, with
    /// perspective) and so colors.
    // A lane indexes coordinates, colors and masks alike.
    #[allow(clippy::needless_range_loop)]
    #[test]
    fn blocks_texture_as_spans_do() {
        use sampler::{DepthMode, Dim, Filter, Sampler, Wrap};
        use std::sync::Arc;
        let mut rng = Rng(0x5851_f42d_4c95_7f2d);
        let rgba_chain = |rng: &mut Rng, w: usize, h: usize, border: usize| -> Vec<Arc<TexImage>> {
            let (mut w, mut h) = (w, h);
            let mut levels = Vec::new();
            loop {
                let (bw, bh) = (w + 2 * border, h + 2 * border);
                let mut img = TexImage::new(bw, bh, 1, border, BaseFormat::Rgba).unwrap();
                img.texels = Texels::Rgba8((0..bw * bh).map(|_| (rng.next() as u32).to_le_bytes()).collect());
                levels.push(Arc::new(img));
                if w == 1 && h == 1 {
                    return levels;
                }
                (w, h) = ((w / 2).max(1), (h / 2).max(1));
            }
        };
        let mut depth = TexImage::new_depth(16, 16, 1, 0, depth_storage(24, true, false)).unwrap();
        for i in 0..256 {
            depth.set_depth_f32(i, rng.unit());
        }
        let depth = Arc::new(depth);
        let wraps = [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat, Wrap::ClampToBorder, Wrap::Clamp];
        let filters = [Filter::Nearest, Filter::Linear];
        let mips = [None, Some(Filter::Nearest), Some(Filter::Linear)];
        let modes = [
            env::EnvMode::Modulate,
            env::EnvMode::Replace,
            env::EnvMode::Decal,
            env::EnvMode::Blend,
            env::EnvMode::Add,
            env::EnvMode::Combine(env::Combine {
                rgb: env::CombineFn::Interpolate,
                alpha: env::CombineFn::Modulate,
                src_rgb: [env::Source::Texture, env::Source::Previous, env::Source::PrimaryColor],
                op_rgb: [env::Operand { alpha: false, invert: false }; 3],
                src_alpha: [env::Source::Texture, env::Source::TextureUnit(0), env::Source::Constant],
                op_alpha: [env::Operand { alpha: true, invert: true }; 3],
                scale_rgb: 2.0,
                scale_alpha: 1.0,
            }),
        ];
        let bases =
            [BaseFormat::Rgba, BaseFormat::Rgb, BaseFormat::Intensity, BaseFormat::Alpha, BaseFormat::LuminanceAlpha];
        let mut compared = 0;
        let mut differ = 0;
        for draw in 0..60 {
            let units = 1 + (rng.next() % 3) as usize;
            let mut stages = Vec::new();
            for unit in 0..units {
                let kind = rng.next() % 5;
                let mip = mips[(rng.next() % 3) as usize];
                let (dim, faces, compare, wrap) = match kind {
                    // RGBA8 2D: the specialised kernel.
                    0 | 1 => (
                        Dim::D2,
                        {
                            let (w, h) = (8 << (rng.next() % 3), 4 << (rng.next() % 3));
                            vec![rgba_chain(&mut rng, w, h, 0)]
                        },
                        None,
                        [wraps[(rng.next() % 3) as usize], wraps[(rng.next() % 3) as usize], Wrap::Repeat],
                    ),
                    // Depth with comparison (the shadow-map kernel).
                    2 => (
                        Dim::D2,
                        vec![vec![depth.clone()]],
                        Some(crate::gl::CompareFunc::LessEqual),
                        [wraps[(rng.next() % 3) as usize], Wrap::ClampToEdge, Wrap::Repeat],
                    ),
                    // A bordered image, clamped to its border: the reference.
                    3 => (
                        Dim::D2,
                        vec![rgba_chain(&mut rng, 8, 8, 1)],
                        None,
                        [wraps[3 + (rng.next() % 2) as usize], Wrap::ClampToBorder, Wrap::Repeat],
                    ),
                    // A cube map: the reference.
                    _ => (
                        Dim::Cube,
                        (0..6).map(|_| rgba_chain(&mut rng, 4, 4, 0)).collect(),
                        None,
                        [Wrap::ClampToEdge; 3],
                    ),
                };
                let mip = if kind == 2 { None } else { mip };
                let sampler = Sampler {
                    dim,
                    faces,
                    wrap,
                    mag: filters[(rng.next() % 2) as usize],
                    min: filters[(rng.next() % 2) as usize],
                    mip,
                    border: [0.25, 0.5, 0.75, 1.0],
                    lod_bias: [0.0, 0.5, -1.0][(rng.next() % 3) as usize],
                    min_lod: -1000.0,
                    max_lod: 1000.0,
                    compare,
                    depth_mode: DepthMode::Intensity,
                    base: BaseFormat::Rgba,
                };
                let mode = modes[(rng.next() % modes.len() as u64) as usize];
                let base = bases[(rng.next() % bases.len() as u64) as usize];
                let env = env::TexEnv { mode, base, color: [0.2, 0.4, 0.6, 0.8] };
                stages.push(TextureStage::new(unit, sampler, env, 5 + 4 * unit));
            }
            let fb_height = [7, 8, 9, 10, 13][draw % 5];
            let texturing = Texturing { stages, fb_height };
            // Varyings: five others, then s, t, r, q per unit, planes with perspective.
            let n = 5 + 4 * units;
            let planes: Vec<[f32; 3]> = (0..n)
                .map(|_| {
                    let scale = [0.02, 0.2, 1.0][(rng.next() % 3) as usize];
                    [rng.unit() * 2.0 - 0.5, (rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale]
                })
                .collect();
            // w changing fast from row to row: the derivatives of a quad's two rows differ.
            let (qx, qy) = ((rng.unit() - 0.5) * 0.1, 0.05 + 0.4 * rng.unit());
            let at = |x: i32, y: i32, out: &mut [f32]| {
                let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
                let w = 1.0 + qx * x + qy * y;
                // s/q = plane/w: not affine in the window.
                for (o, p) in out.iter_mut().zip(&planes) {
                    *o = p[0] + p[1] * x + p[2] * y;
                }
                for u in 0..units {
                    if let Some(q) = out.get_mut(5 + 4 * u + 3) {
                        *q = w;
                    }
                }
            };
            for (bx, by) in [(0, 0), (4, 4), (8, 0), (4, 8)] {
                let live = [0xffff, rng.next() as u16, 1 << (rng.next() % 16), 0x8421][(rng.next() % 4) as usize];
                let primary = |x: i32, y: i32| [x as f32 / 12.0, y as f32 / 12.0, 0.5, 0.75];
                let mut colors = [[0.0; LANES]; 4];
                for i in 0..LANES {
                    let p = primary(bx + (i & 3) as i32, by + (i >> 2) as i32);
                    for k in 0..4 {
                        colors[k][i] = p[k];
                    }
                }
                let before = colors;
                texturing.texture_block(by, live, &mut colors, |y0, first, out| {
                    for i in 0..LANES {
                        let mut v = vec![0.0; n];
                        at(bx + (i & 3) as i32, y0 + (i >> 2) as i32, &mut v);
                        for (k, o) in out.iter_mut().enumerate() {
                            o[i] = v.get(first + k).copied().unwrap_or(0.0);
                        }
                    }
                });
                let mut scratch = Vec::new();
                for r in 0..4 {
                    let y = by + r as i32;
                    let mut row: Vec<[f32; 4]> = (0..4).map(|c| primary(bx + c, y)).collect();
                    let row_live = (live >> (4 * r)) as u64 & 0xf;
                    texturing
                        .texture_span(&mut row, row_live, bx, y, &mut scratch, |dx, dy, out| at(bx + dx, y + dy, out));
                    for (c, pixel) in row.iter().enumerate() {
                        let i = 4 * r + c;
                        let lane: [f32; 4] = std::array::from_fn(|k| colors[k][i]);
                        if live & (1 << i) != 0 {
                            assert_eq!(
                                lane.map(f32::to_bits),
                                pixel.map(f32::to_bits),
                                "draw {draw} block ({bx}, {by}) lane {i} height {fb_height}"
                            );
                            compared += 1;
                            differ += usize::from(lane != std::array::from_fn(|k| before[k][i]));
                        } else {
                            assert_eq!(lane, std::array::from_fn(|k| before[k][i]), "a lane outside the mask");
                        }
                    }
                }
            }
        }
        assert!(compared > 1000 && differ > compared / 2, "{compared} {differ}");
    }

    // A lane indexes coordinates, colors and masks alike.
    #[allow(clippy::needless_range_loop)]
    #[test]
    fn stage_block_lookups_are_the_quads_lookups() {
        // The lookup a program's sample instruction calls (row-major lanes) against
        // `texture_quads` (quad-major lanes) with GL_REPLACE on RGBA, which passes the
        // texture color through: the same colors lane for lane.
        use std::sync::Arc;
        let mut rng = Rng(0x0dd_f00d);
        let mut levels = Vec::new();
        for n in [16usize, 8, 4, 2, 1] {
            let mut img = TexImage::new(n, n, 1, 0, BaseFormat::Rgba).unwrap();
            img.texels = Texels::Rgba8((0..n * n).map(|_| (rng.next() as u32).to_le_bytes()).collect());
            levels.push(Arc::new(img));
        }
        let sampler = trilinear_rgba(levels);
        let env = env::TexEnv { mode: env::EnvMode::Replace, base: BaseFormat::Rgba, color: [0.0; 4] };
        let texturing = Texturing { stages: vec![TextureStage::new(0, sampler, env, 0)], fb_height: 64 };
        let mut differ = 0;
        for _ in 0..200 {
            let (a, b, d) = (rng.unit() * 4.0, rng.unit() - 0.5, rng.unit() * 0.3);
            let live = rng.next() as u16 | 1;
            // Row-major coordinates, with perspective-like curvature per row.
            let mut c = [[0.0; LANES]; 3];
            for i in 0..LANES {
                let (x, y) = ((i & 3) as f32, (i >> 2) as f32);
                let w = 1.0 + d * y;
                c[0][i] = (a + b * x) / w;
                c[1][i] = (b + 0.4 * y + d * x) / w;
            }
            let mut out = [[0.0; LANES]; 4];
            texturing.stages[0].sample_block(&c, live, &mut out);
            // The same lanes quad-major: lane 4q + 2r + c, r = 0 the quad's higher row.
            let quad_major = |i: usize| {
                let (col, row) = (i & 3, i >> 2);
                4 * ((row >> 1) * 2 + (col >> 1)) + 2 * (1 - (row & 1)) + (col & 1)
            };
            let mut varyings = vec![[0.0; LANES]; 4];
            let mut colors = [[0.5; LANES]; 4];
            let mut quad_live = 0u16;
            for i in 0..LANES {
                let j = quad_major(i);
                varyings[0][j] = c[0][i];
                varyings[1][j] = c[1][i];
                varyings[3][j] = 1.0;
                quad_live |= ((live >> i) & 1) << j;
            }
            texturing.texture_quads(&varyings, quad_live, &mut colors);
            for i in (0..LANES).filter(|i| live & (1 << i) != 0) {
                let j = quad_major(i);
                for k in 0..4 {
                    assert_eq!(out[k][i].to_bits(), colors[k][j].to_bits(), "lane {i} channel {k}");
                }
                differ += usize::from(out[0][i] != out[0][0]);
            }
        }
        assert!(differ > 500, "{differ}");
    }

    #[test]
    fn lookups_without_derivatives_evaluate_only_the_live_fragments() {
        use sampler::{DepthMode, Dim, Filter, Sampler, Wrap};
        use std::cell::Cell;
        use std::sync::Arc;
        // A depth texture with comparison and no mipmaps (a shadow map) on unit 1 and an
        // unmipmapped RGBA texture on unit 0: no λ, so no neighbour is evaluated.
        let mut depth = TexImage::new_depth(8, 8, 1, 0, depth_storage(24, true, false)).unwrap();
        for i in 0..64 {
            depth.set_depth_f32(i, (i % 7) as f32 / 6.0);
        }
        let mut rgba = TexImage::new(4, 4, 1, 0, BaseFormat::Rgba).unwrap();
        rgba.texels = Texels::Rgba8((0..16u8).map(|i| [i * 16, 255 - i * 9, i * 3, 200]).collect());
        let sampler = |image: TexImage, filter: Filter, compare| Sampler {
            dim: Dim::D2,
            faces: vec![vec![Arc::new(image)]],
            wrap: [Wrap::ClampToEdge, Wrap::Repeat, Wrap::Repeat],
            mag: filter,
            min: filter,
            mip: None,
            border: [0.0; 4],
            lod_bias: 0.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            compare,
            depth_mode: DepthMode::Intensity,
            base: BaseFormat::Rgba,
        };
        let modulate = env::TexEnv { mode: env::EnvMode::Modulate, base: BaseFormat::Rgba, color: [0.0; 4] };
        let stages = vec![
            TextureStage::new(0, sampler(rgba, Filter::Linear, None), modulate, 0),
            TextureStage::new(
                1,
                sampler(depth, Filter::Nearest, Some(crate::gl::CompareFunc::GreaterEqual)),
                modulate,
                4,
            ),
        ];
        assert!(stages.iter().all(|s| !s.derivatives));
        let h = 6;
        let texturing = Texturing { stages, fb_height: h };
        let at = |x: i32, y: i32, out: &mut [f32]| {
            let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
            let q = 1.0 + 0.05 * x;
            out[..8].copy_from_slice(&[0.11 * x / q, 0.07 * y / q, 0.0, 1.0 / q, 0.1 * x, 0.13 * y, 0.08 * x, 1.0]);
        };
        let neighbours = Cell::new(0);
        let mut scratch = Vec::new();
        for y in 0..h {
            let live = 0b1101_1011u64;
            let mut colors = vec![[0.5, 0.75, 1.0, 1.0]; 8];
            texturing.texture_span(&mut colors, live, 3, y, &mut scratch, |dx, dy, out| {
                neighbours.set(neighbours.get() + usize::from(dy != 0 || live & (1 << dx) == 0));
                at(3 + dx, y + dy, out)
            });
            for (i, color) in colors.iter().enumerate() {
                if live & (1 << i) == 0 {
                    assert_eq!(*color, [0.5, 0.75, 1.0, 1.0], "a fragment outside the span's mask");
                    continue;
                }
                // Each fragment as the reference samples it, from its own coordinates.
                let mut v = [0.0; 8];
                at(3 + i as i32, y, &mut v);
                let mut expect = [0.5, 0.75, 1.0, 1.0];
                for s in &texturing.stages {
                    let texel = s.sampler.sample(projected(&v, s.slot), [0.0; 3], [0.0; 3]);
                    let mut texels = [[0.0; 4]; MAX_UNITS];
                    texels[s.unit] = texel;
                    expect = s.env.apply(s.unit, expect, [0.5, 0.75, 1.0, 1.0], &texels);
                }
                assert_eq!(*color, expect, "pixel ({}, {y})", 3 + i);
            }
        }
        assert_eq!(neighbours.get(), 0, "no coordinates but the live fragments' are evaluated");
    }

    #[test]
    fn downsampling_averages_boxes() {
        let mut img = TexImage::new(2, 2, 1, 0, BaseFormat::Rgba).unwrap();
        img.texels = Texels::Rgba8(vec![[0, 0, 0, 0], [255, 0, 0, 0], [0, 255, 0, 0], [255, 255, 4, 0]]);
        let next = downsample(&img, 2).unwrap();
        assert_eq!((next.width, next.height), (1, 1));
        assert_eq!(next.texels, Texels::Rgba8(vec![[128, 128, 1, 0]]));
        assert_eq!(level_size(5, 1), 2);
        // A depth-stencil image keeps its stencil indices; each box keeps its first index,
        // and the averaged depth is stored in the image's format.
        let format = depth_storage(24, true, false);
        let mut ds = TexImage::new_depth(2, 2, 1, 0, format).unwrap();
        for (i, (d, s)) in [(0.0, 7), (0.5, 1), (0.5, 2), (1.0, 3)].into_iter().enumerate() {
            ds.set_depth_f32(i, d);
            ds.set_stencil(i, s);
        }
        let next = downsample(&ds, 2).unwrap();
        assert_eq!(next.depth_format(), Some(format));
        assert_eq!((next.depth_f32(0), next.stencil(0)), (depth_texel(DepthEncoding::Unorm(24), 0x80_0000), 7));
        assert_eq!(level_size(5, 9), 1);
    }
}
