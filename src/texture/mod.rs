//! Texturing: texture images as stored ([`TexImage`]), the samplers a draw compiles from
//! texture objects ([`sampler`]), the kernels that run their lookups a 2×2 quad at a time
//! (`kernel`, chosen once per draw), and the texture environments' state ([`env`]).
//! [`TextureStage::sample_lanes`] is the lookup of 16 lanes in structure-of-arrays form that
//! a fragment program's sample instruction calls (`crate::fragment::shading`); the
//! environments themselves are part of the generated fragment program.
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
mod lanes;
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
    /// Whether the color channels are sRGB-encoded (EXT_texture_sRGB formats): sampling
    /// decodes red, green and blue to linear per texel, before filtering
    /// ([`srgb_to_linear`]); alpha, storage, rendering into the image and glGetTexImage
    /// keep the stored values.
    pub srgb: bool,
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
        Ok(TexImage { width, height, depth, border, base, texels: Texels::Rgba8(v), srgb: false })
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
        Ok(TexImage {
            width,
            height,
            depth,
            border,
            base: BaseFormat::Depth,
            texels: Texels::Depth(buffer),
            srgb: false,
        })
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

/// An 8-bit sRGB-encoded channel value as llvmpipe's texture fetch decodes it to linear
/// (Mesa 22's `lp_build_srgb_to_linear`): values up to 15 on a line, `v / (12.6 · 255)`, the
/// others through the cubic `0.3012 x³ + 0.6935 x² + 0.0030 x + 0.0023` (x = v / 255, the
/// 1/255 folded into the coefficients), evaluated as llvmpipe evaluates it: even and odd
/// terms in x², each step one fused multiply-add (LLVM fuses `fmuladd` on machines with
/// FMA, as Mesa's reference runs). It differs from the exact sRGB curve by up to 0.4 of a
/// step, so the pictures match Mesa's only with llvmpipe's curve. The 256 values are
/// computed once (`f32::mul_add` is exact on every machine: the same bits everywhere).
#[inline]
pub fn srgb_to_linear(v: u8) -> f32 {
    static TABLE: std::sync::OnceLock<[f32; 256]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| std::array::from_fn(|i| srgb_curve(i as u8)))[v as usize]
}

/// One value of [`srgb_to_linear`]'s table.
fn srgb_curve(v: u8) -> f32 {
    let x = v as f32;
    if v <= 15 {
        // llvmpipe's constants are float expressions rounded once more to float.
        return x * (1.0f32 / (12.6f32 * 255.0f32));
    }
    let c0 = 0.0023f32;
    let c1 = 0.0030f32 / 255.0f32;
    let c2 = 0.6935f32 / (255.0f32 * 255.0f32);
    let c3 = 0.3012f32 / (255.0f32 * 255.0f32 * 255.0f32);
    let x2 = x * x;
    let even = c2.mul_add(x2, c0);
    let odd = c3.mul_add(x2, c1);
    odd.mul_add(x, even)
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
    out.srgb = src.srgb;
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
    /// How the sampler's lookups run, chosen from it: quad by quad (`kernel`), and the
    /// lane loops' plan for the textures they take.
    kernel: kernel::Kernel,
    plan: Option<lanes::Plan>,
    /// Whether a lookup depends on the derivatives of its coordinates: not when every λ
    /// gives the same level and filter (no mipmaps, one filter for magnification and
    /// minification), as for most shadow maps.
    derivatives: bool,
}

impl TextureStage {
    /// The texture colors (`out[channel][lane]`, f32 bits, before the environment) of the
    /// lanes `live` of a 4×4 block, lanes row-major (lane `i` at column `i & 3`, row
    /// `i >> 2`, rows upward), from the coordinates (s, t, r, q) `coords` (f32 bits; divided
    /// by q when `projective`, 0 where q is 0): the level of detail per 2×2 quad of rows
    /// (0, 1) and (2, 3), the upper row of each (llvmpipe's) giving the x derivative and its
    /// left column the y one. Every lane of a quad with a live lane must hold its pixel's
    /// coordinates. This is the implicit-LOD lookup a fixed-function program's sample
    /// instruction needs (`shader::exec::Textures::sample` over a draw's stages). Lanes
    /// outside `live` receive unspecified values or are left alone.
    ///
    /// Compiled once per SIMD level: the lane loops of the common textures (`lanes`) run at
    /// the machine's level; other textures go quad by quad through the reference kernels.
    pub fn sample_lanes(&self, coords: &[[u32; LANES]; 4], projective: bool, live: u16, out: &mut [[u32; LANES]; 4]) {
        self.sample_lanes_with(&self.sampler, coords, projective, live, out)
    }

    /// The per-level copies of the lookup, with `sampler` for the stage's own: one set of
    /// copies for [`Self::sample_lanes`] and [`Self::sample_lanes_biased`] (a second set
    /// was about 70 KB per level in each library).
    #[inline(never)]
    fn sample_lanes_with(
        &self,
        sampler: &sampler::Sampler,
        coords: &[[u32; LANES]; 4],
        projective: bool,
        live: u16,
        out: &mut [[u32; LANES]; 4],
    ) {
        crate::simd::per_level!(self.sample_lanes_body(sampler, coords, projective, live, out))
    }

    /// [`TextureStage::sample_lanes`] with a shader's bias argument (`bias`, f32 bits per
    /// lane) added to λ: per lane, as llvmpipe takes a bias that varies (the derivatives
    /// stay per 2×2 quad). One lookup per distinct bias, each with that bias in a copy of
    /// the sampler (a rare lookup: the copy is cheaper than a bias in every lookup's path;
    /// a bias uniform over the block is one lookup).
    pub fn sample_lanes_biased(
        &self,
        coords: &[[u32; LANES]; 4],
        projective: bool,
        bias: &[u32; LANES],
        live: u16,
        out: &mut [[u32; LANES]; 4],
    ) {
        let mut sampler = self.sampler.clone();
        let mut rest = live;
        while rest != 0 {
            let value = bias[rest.trailing_zeros() as usize];
            let lanes = (0..LANES).fold(0u16, |m, l| m | (u16::from(bias[l] == value) << l)) & rest;
            rest &= !lanes;
            sampler.shader_bias = f32::from_bits(value);
            // The lane loops may write every lane: into a copy, then the lanes taken.
            let mut texels = *out;
            self.sample_lanes_with(&sampler, coords, projective, lanes, &mut texels);
            for (channel, values) in out.iter_mut().zip(&texels) {
                for l in (0..LANES).filter(|l| lanes & (1 << l) != 0) {
                    channel[l] = values[l];
                }
            }
        }
    }

    // Lanes index the coordinate arrays alike.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    fn sample_lanes_body(
        &self,
        sampler: &sampler::Sampler,
        coords: &[[u32; LANES]; 4],
        projective: bool,
        live: u16,
        out: &mut [[u32; LANES]; 4],
    ) {
        let mut c = [[0f32; LANES]; 3];
        if projective {
            let mut inv = [0f32; LANES];
            for i in 0..LANES {
                // Divided in every lane, then chosen: a division under a condition stays
                // scalar.
                let q = f32::from_bits(coords[3][i]);
                let reciprocal = 1.0 / q;
                inv[i] = if q != 0.0 { reciprocal } else { 0.0 };
            }
            for j in 0..3 {
                for i in 0..LANES {
                    c[j][i] = f32::from_bits(coords[j][i]) * inv[i];
                }
            }
        } else {
            for j in 0..3 {
                for i in 0..LANES {
                    c[j][i] = f32::from_bits(coords[j][i]);
                }
            }
        }
        if let Some(plan) = &self.plan {
            if plan.sample(sampler, &c, live, out) {
                return;
            }
        }
        self.kernel.sample_quads(sampler, &c, live, out);
    }

    /// [`TextureStage::sample_lanes`] of coordinates already divided by q, as f32 colors
    /// (the tests' form).
    #[cfg(test)]
    pub fn sample_block(&self, c: &[F32s; 3], live: u16, out: &mut [F32s; 4]) {
        let coords = [0, 1, 2, 3].map(|j| if j < 3 { c[j].map(f32::to_bits) } else { [1f32.to_bits(); LANES] });
        let mut words = out.map(|channel| channel.map(f32::to_bits));
        self.sample_lanes(&coords, false, live, &mut words);
        *out = words.map(|channel| channel.map(f32::from_bits));
    }

    /// Whether a lookup depends on the derivatives of its coordinates (then its level of
    /// detail is per 2×2 quad, and the quads must be llvmpipe's).
    #[inline]
    pub fn needs_derivatives(&self) -> bool {
        self.derivatives
    }

    pub fn new(unit: usize, sampler: sampler::Sampler, env: env::TexEnv, slot: usize) -> TextureStage {
        let kernel = kernel::Kernel::choose(&sampler);
        let plan = match kernel {
            kernel::Kernel::Rgba2d => Some(lanes::Plan::new(&sampler, false)),
            kernel::Kernel::Depth2d => Some(lanes::Plan::new(&sampler, true)),
            kernel::Kernel::Reference => None,
        };
        let derivatives = sampler.mip.is_some() || sampler.mag != sampler.min;
        TextureStage { unit, sampler, env, slot, kernel, plan, derivatives }
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
    /// Two draws texture alike only if they share the very same images, read alike.
    fn eq(&self, other: &Self) -> bool {
        self.fb_height == other.fb_height
            && self.stages.len() == other.stages.len()
            && self.stages.iter().zip(&other.stages).all(|(a, b)| {
                a.unit == b.unit && a.slot == b.slot && a.env == b.env && a.sampler.same_lookup(&b.sampler)
            })
    }
}

/// Most texture units a draw can use.
pub const MAX_UNITS: usize = crate::gl::limits::MAX_TEXTURE_UNITS;

/// Fragments in a block given to [`TextureStage::sample_lanes`]: four 2×2 quads.
pub const LANES: usize = 16;

/// One value per lane of a block.
pub type F32s = [f32; LANES];

/// The lanes of a 4-bit mask, in order.
#[inline(always)]
fn lanes4(mask: u8) -> impl Iterator<Item = usize> {
    (0..4).filter(move |&l| mask & (1 << l) != 0)
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
    fn srgb_decoding_is_llvmpipes_curve() {
        // Bits read back from Mesa 22.3.6's llvmpipe (a 256×1 GL_SRGB8_ALPHA8 texture
        // drawn with GL_REPLACE into an OSMesa GL_FLOAT buffer): the line below 16, the
        // cubic above, and not the exact sRGB curve (0.000303527 for 1).
        let bits = |v: u8| srgb_to_linear(v).to_bits();
        assert_eq!(srgb_to_linear(0), 0.0);
        assert_eq!(srgb_to_linear(1), f32::from_bits(0x39a3_2d56));
        assert_eq!([bits(16), bits(100), bits(200), bits(254)], [0x3bad_702a, 0x3e03_5f2a, 0x3f13_9a9a, 0x3f7d_b425]);
        assert_eq!(srgb_to_linear(255), 1.0);
        // All 256: the sum of their bit patterns (mod 2³²) is that of Mesa's values.
        let sum = (0..=255u8).fold(0u32, |s, v| s.wrapping_add(bits(v)));
        assert_eq!(sum, 3_359_847_906);
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
            shader_bias: 0.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            compare: None,
            depth_mode: DepthMode::Luminance,
            base: BaseFormat::Rgba,
        }
    }

    use crate::gl::test_rng::TestRng as Rng;

    // A lane indexes coordinates, colors and masks alike.
    #[allow(clippy::needless_range_loop)]
    #[test]
    fn stage_block_lookups_are_the_quads_lookups() {
        // The lookup a program's sample instruction calls (row-major lanes) against the
        // quad kernel, quad by quad: the same colors lane for lane.
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
            // The same lanes quad by quad, in the quad kernel's order (upper left, upper
            // right, lower left, lower right of llvmpipe's y-down rows: the block's higher
            // row first).
            let stage = &texturing.stages[0];
            for lanes in &[[4, 5, 0, 1], [6, 7, 2, 3], [12, 13, 8, 9], [14, 15, 10, 11]] {
                let m = (0..4).fold(0u8, |m, k| m | ((((live >> lanes[k]) & 1) as u8) << k));
                if m == 0 {
                    continue;
                }
                let quad: [[f32; 3]; 4] = std::array::from_fn(|l| std::array::from_fn(|j| c[j][lanes[l]]));
                let mut colors = [[0.0; 4]; 4];
                stage.kernel.sample_quad(&stage.sampler, &quad, m, &mut colors);
                for l in lanes4(m) {
                    for k in 0..4 {
                        assert_eq!(out[k][lanes[l]].to_bits(), colors[l][k].to_bits(), "lane {} channel {k}", lanes[l]);
                    }
                }
            }
            for i in (0..LANES).filter(|i| live & (1 << i) != 0) {
                differ += usize::from(out[0][i] != out[0][0]);
            }
        }
        assert!(differ > 500, "{differ}");
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

    // A lane indexes coordinates, colors and biases alike.
    #[allow(clippy::needless_range_loop)]
    #[test]
    fn a_lookups_bias_adds_to_each_lanes_level_of_detail() {
        // A mipmap of one colour per level, minified 2× (λ = 1 without a bias): each lane's
        // bias picks its own level (per lane, as llvmpipe's varying bias), and a bias equal
        // in every lane reads as a texture bias of that value does.
        use std::sync::Arc;
        let mut levels = Vec::new();
        for (d, n) in [16usize, 8, 4, 2, 1].into_iter().enumerate() {
            let mut img = TexImage::new(n, n, 1, 0, BaseFormat::Rgba).unwrap();
            img.texels = Texels::Rgba8(vec![[d as u8 * 50, 0, 0, 255]; n * n]);
            levels.push(Arc::new(img));
        }
        let mut sampler = trilinear_rgba(levels);
        sampler.mip = Some(sampler::Filter::Nearest);
        sampler.min = sampler::Filter::Nearest;
        let env = env::TexEnv { mode: env::EnvMode::Replace, base: BaseFormat::Rgba, color: [0.0; 4] };
        let stage = TextureStage::new(0, sampler.clone(), env, 0);
        let coords: [[u32; LANES]; 4] = std::array::from_fn(|j| {
            std::array::from_fn(|i| {
                let (x, y) = ((i & 3) as f32, (i >> 2) as f32);
                [x * 2.0 / 16.0, y * 2.0 / 16.0, 0.0, 1.0][j].to_bits()
            })
        });
        // Per lane: λ = 1 + bias, levels 1, 2, 3 and 0 (magnified) across each row; and
        // one bias over the middle rows.
        let per_lane: [u32; LANES] = std::array::from_fn(|i| [0.0f32, 1.0, 2.0, -1.0][i % 4].to_bits());
        let cases =
            [(per_lane, 0xffffu16), ([0.5f32.to_bits(); LANES], 0x0ff0), ([(-2.0f32).to_bits(); LANES], 0x0ff0)];
        let mut levels_seen = std::collections::BTreeSet::new();
        for (bias, live) in cases {
            let mut biased = [[0u32; LANES]; 4];
            stage.sample_lanes_biased(&coords, false, &bias, live, &mut biased);
            for i in (0..LANES).filter(|i| live & (1 << i) != 0) {
                let mut with_texture_bias = sampler.clone();
                with_texture_bias.lod_bias = f32::from_bits(bias[i]);
                let mut expected = [[0u32; LANES]; 4];
                TextureStage::new(0, with_texture_bias, env, 0).sample_lanes(&coords, false, live, &mut expected);
                assert_eq!(biased.map(|c| c[i]), expected.map(|c| c[i]), "bias {} lane {i}", f32::from_bits(bias[i]));
                levels_seen.insert(biased[0][i]);
            }
        }
        assert_eq!(levels_seen.len(), 4, "levels 0 to 3 read");
    }
}
