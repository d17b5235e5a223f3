//! Texture objects and images: glGenTextures/glBindTexture/glDeleteTextures, glTexImage*,
//! glTexSubImage*, glCopyTexImage*, glCopyTexSubImage*, glGetTexImage, glTexParameter*,
//! glGetTexParameter*, glGetTexLevelParameter*, proxy textures and mipmap generation.
//!
//! Each texture object keeps its levels (per cube face) as shared [`TexImage`]s: a draw's
//! compiled sampler holds the same `Arc`s, so specifying an image replaces the `Arc` and
//! never changes what an already recorded draw samples; glTexSubImage and the copies flush
//! recorded rendering first and then write in place.
//!
//! Validation follows GL 2.1 §3.8.1-§3.8.4 in Mesa 22's order of checks (target, level,
//! internal format, format/type, sizes, border, format compatibility). Deliberate
//! differences from Mesa 22: the generic compressed internal formats are stored uncompressed
//! (GL_TEXTURE_COMPRESSED false; Mesa picks S3TC for GL_COMPRESSED_RGB), formats of more than
//! 8 bits per color channel are stored with 8 (their sizes read back as 8), the generic
//! compressed sRGB formats are stored uncompressed as well, and no compressed format is supported
//! (glCompressedTexImage* is GL_INVALID_ENUM). GL_COLOR_INDEX image data (every index type,
//! GL_BITMAP included) becomes RGBA through GL_INDEX_SHIFT/OFFSET and the GL_PIXEL_MAP_I_TO_*
//! tables (GL 2.1 §3.6.5, "Color Index Lookup"); glGetTexImage cannot return indices.
use super::pixel_buffers::{ClientBytes, ClientBytesMut};
use super::Context;
use crate::framebuffer::format::DepthEncoding;
use crate::gl::enums::*;
use crate::gl::names::{NameTable, OutOfNames};
use crate::gl::types::GLenum;
use crate::pixel::layout::VolumeLayout;
use crate::pixel::unpack::{bitmap_bit, index_value, unpack_color_row, unpack_depth_row, unpack_depth_stencil_row};
use crate::pixel::{ClientFormat, ClientType, PackModes};
use crate::texture::{depth_storage, quantize_to_u8, BaseFormat, TexImage, Texels};
use std::ops::Range;
use std::sync::Arc;

/// GL_MAX_TEXTURE_SIZE, GL_MAX_3D_TEXTURE_SIZE, GL_MAX_CUBE_MAP_TEXTURE_SIZE (Mesa 22's).
pub const MAX_TEXTURE_SIZE: usize = 16384;
pub const MAX_3D_TEXTURE_SIZE: usize = 2048;
pub const MAX_CUBE_MAP_TEXTURE_SIZE: usize = 16384;
/// GL_MAX_TEXTURE_LOD_BIAS.
pub const MAX_TEXTURE_LOD_BIAS: f32 = 16.0;

/// The four texture targets, in the order of the per-unit binding arrays.
pub const TARGETS: [GLenum; 4] = [GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP];

/// Index of a bindable target in [`TARGETS`].
pub fn target_index(target: GLenum) -> Option<usize> {
    TARGETS.iter().position(|&t| t == target)
}

/// The storage and reported sizes of an internal format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FormatInfo {
    pub base: BaseFormat,
    /// Bits each stored RGBA channel is quantized to (0: not stored).
    pub bits: [u32; 4],
    /// GL_TEXTURE_RED/GREEN/BLUE/ALPHA/LUMINANCE/INTENSITY/DEPTH/STENCIL_SIZE.
    pub sizes: [i32; 8],
    /// Depth kept as floats, only clamped to [0, 1] (ARB_depth_buffer_float's
    /// GL_DEPTH_COMPONENT32F and GL_DEPTH32F_STENCIL8), instead of quantized to `bits[0]`.
    pub float_depth: bool,
    /// Red, green and blue are sRGB-encoded (EXT_texture_sRGB, GL 2.1): sampling decodes
    /// them (`crate::texture::srgb_to_linear`).
    pub srgb: bool,
}

impl FormatInfo {
    /// Whether images of the format keep stencil beside depth (GL_DEPTH_STENCIL formats).
    pub fn has_stencil(&self) -> bool {
        self.sizes[7] > 0
    }

    /// How images of a depth format are stored (and render): a depth buffer of this format.
    pub fn depth_format(&self) -> crate::framebuffer::DepthStencilFormat {
        depth_storage(self.bits[0], self.has_stencil(), self.float_depth)
    }
}

/// What an internal format is stored as; `None` for formats tessera does not accept.
pub fn format_info(internal_format: i32) -> Option<FormatInfo> {
    use BaseFormat::*;
    let f = internal_format as GLenum;
    let rgba = |base, r: u32, g: u32, b: u32, a: u32| FormatInfo {
        base,
        bits: [r, g, b, a],
        sizes: [r as i32, g as i32, b as i32, a as i32, 0, 0, 0, 0],
        float_depth: false,
        srgb: false,
    };
    let lum = |l: u32, a: u32| FormatInfo {
        base: if a > 0 { LuminanceAlpha } else { Luminance },
        bits: [l, l, l, a],
        sizes: [0, 0, 0, a as i32, l as i32, 0, 0, 0],
        float_depth: false,
        srgb: false,
    };
    let depth = |bits: u32, stencil: i32, float_depth: bool| FormatInfo {
        base: Depth,
        bits: [bits, 0, 0, 0],
        sizes: [0, 0, 0, 0, 0, 0, bits as i32, stencil],
        float_depth,
        srgb: false,
    };
    let srgb = |info: FormatInfo| FormatInfo { srgb: true, ..info };
    Some(match f {
        1 | GL_LUMINANCE | GL_LUMINANCE8 | GL_LUMINANCE12 | GL_LUMINANCE16 | GL_COMPRESSED_LUMINANCE => lum(8, 0),
        GL_LUMINANCE4 => lum(8, 0),
        2
        | GL_LUMINANCE_ALPHA
        | GL_LUMINANCE6_ALPHA2
        | GL_LUMINANCE8_ALPHA8
        | GL_LUMINANCE12_ALPHA4
        | GL_LUMINANCE12_ALPHA12
        | GL_LUMINANCE16_ALPHA16
        | GL_COMPRESSED_LUMINANCE_ALPHA => lum(8, 8),
        GL_LUMINANCE4_ALPHA4 => lum(4, 4),
        GL_ALPHA | GL_ALPHA4 | GL_ALPHA8 | GL_ALPHA12 | GL_ALPHA16 | GL_COMPRESSED_ALPHA => rgba(Alpha, 0, 0, 0, 8),
        GL_INTENSITY | GL_INTENSITY4 | GL_INTENSITY8 | GL_INTENSITY12 | GL_INTENSITY16 | GL_COMPRESSED_INTENSITY => {
            FormatInfo {
                base: Intensity,
                bits: [8; 4],
                sizes: [0, 0, 0, 0, 0, 8, 0, 0],
                float_depth: false,
                srgb: false,
            }
        }
        3 | GL_RGB | GL_RGB8 | GL_RGB10 | GL_RGB12 | GL_RGB16 | GL_COMPRESSED_RGB => rgba(Rgb, 8, 8, 8, 0),
        GL_R3_G3_B2 => rgba(Rgb, 3, 3, 2, 0),
        GL_RGB4 => rgba(Rgb, 4, 4, 4, 0),
        GL_RGB5 => rgba(Rgb, 5, 5, 5, 0),
        4 | GL_RGBA | GL_RGBA8 | GL_RGBA12 | GL_RGBA16 | GL_COMPRESSED_RGBA => rgba(Rgba, 8, 8, 8, 8),
        GL_RGBA2 | GL_RGBA4 => rgba(Rgba, 4, 4, 4, 4),
        GL_RGB5_A1 => rgba(Rgba, 5, 5, 5, 1),
        GL_RGB10_A2 => rgba(Rgba, 8, 8, 8, 2),
        GL_DEPTH_COMPONENT | GL_DEPTH_COMPONENT24 => depth(24, 0, false),
        GL_DEPTH_COMPONENT16 => depth(16, 0, false),
        GL_DEPTH_COMPONENT32 => depth(32, 0, false),
        // GL_EXT_packed_depth_stencil: 24-bit depth and 8-bit stencil (Mesa's Z24_S8).
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 => depth(24, 8, false),
        // ARB_depth_buffer_float (Mesa's Z32_FLOAT and Z32_FLOAT_S8X24_UINT).
        GL_DEPTH_COMPONENT32F => depth(32, 0, true),
        GL_DEPTH32F_STENCIL8 => depth(32, 8, true),
        // EXT_texture_sRGB (core in GL 2.1): 8 bits per channel, as Mesa 22 stores them; the
        // generic compressed ones are stored uncompressed, as the other generic compressed
        // formats are.
        GL_SRGB | GL_SRGB8 | GL_COMPRESSED_SRGB => srgb(rgba(Rgb, 8, 8, 8, 0)),
        GL_SRGB_ALPHA | GL_SRGB8_ALPHA8 | GL_COMPRESSED_SRGB_ALPHA => srgb(rgba(Rgba, 8, 8, 8, 8)),
        GL_SLUMINANCE | GL_SLUMINANCE8 | GL_COMPRESSED_SLUMINANCE => srgb(lum(8, 0)),
        GL_SLUMINANCE_ALPHA | GL_SLUMINANCE8_ALPHA8 | GL_COMPRESSED_SLUMINANCE_ALPHA => srgb(lum(8, 8)),
        _ => return None,
    })
}

/// A texture object's sampling parameters (glTexParameter).
#[derive(Clone, Debug, PartialEq)]
pub struct TexParams {
    pub min_filter: GLenum,
    pub mag_filter: GLenum,
    pub wrap: [GLenum; 3],
    pub border_color: [f32; 4],
    pub priority: f32,
    pub min_lod: f32,
    pub max_lod: f32,
    pub base_level: i32,
    pub max_level: i32,
    pub lod_bias: f32,
    pub compare_mode: GLenum,
    pub compare_func: GLenum,
    pub depth_mode: GLenum,
    pub generate_mipmap: bool,
}

impl Default for TexParams {
    fn default() -> Self {
        TexParams {
            min_filter: GL_NEAREST_MIPMAP_LINEAR,
            mag_filter: GL_LINEAR,
            wrap: [GL_REPEAT; 3],
            border_color: [0.0; 4],
            priority: 1.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            lod_bias: 0.0,
            compare_mode: GL_NONE,
            compare_func: GL_LEQUAL,
            depth_mode: GL_LUMINANCE,
            generate_mipmap: false,
        }
    }
}

/// One specified mipmap level.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    /// The texels (`None` for proxy levels, which have no storage).
    pub image: Option<Arc<TexImage>>,
    pub internal_format: i32,
    pub info: FormatInfo,
    /// Size without the border.
    pub width: usize,
    pub height: usize,
    pub depth: usize,
    pub border: usize,
}

/// A texture object.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct TextureObject {
    /// The target it was first bound to (0: never bound).
    pub target: GLenum,
    pub params: TexParams,
    /// Levels of each face (only face 0 unless a cube map).
    pub faces: [Vec<Option<Level>>; 6],
}

impl TextureObject {
    fn with_target(target: GLenum) -> Self {
        TextureObject { target, ..Default::default() }
    }

    pub fn level(&self, face: usize, level: usize) -> Option<&Level> {
        self.faces.get(face)?.get(level)?.as_ref()
    }
}

/// Every texture object of a context, the default objects (name 0) and the proxies.
#[derive(Clone, Debug, Default)]
pub struct TextureTable {
    /// The named objects (name 0 is the default object of each target, below).
    names: NameTable<TextureObject>,
    defaults: [TextureObject; 4],
    proxies: [TextureObject; 4],
}

impl TextureTable {
    pub fn new() -> Self {
        let mut t = TextureTable::default();
        for (i, &target) in TARGETS.iter().enumerate() {
            t.defaults[i] = TextureObject::with_target(target);
            t.proxies[i] = TextureObject::with_target(target);
        }
        t
    }

    pub fn get(&self, name: u32, target_idx: usize) -> Option<&TextureObject> {
        if name == 0 {
            Some(&self.defaults[target_idx])
        } else {
            self.names.get(name)
        }
    }

    pub fn get_mut(&mut self, name: u32, target_idx: usize) -> Option<&mut TextureObject> {
        if name == 0 {
            Some(&mut self.defaults[target_idx])
        } else {
            self.names.get_mut(name)
        }
    }

    /// The object named `name` (not 0) once it has been bound (framebuffer attachments).
    pub fn object(&self, name: u32) -> Option<&TextureObject> {
        self.names.get(name)
    }

    pub fn object_mut(&mut self, name: u32) -> Option<&mut TextureObject> {
        self.names.get_mut(name)
    }
}

/// A validated image command: its target, internal format and client format/type.
type CheckedImage = (ImageTarget, FormatInfo, Option<(ClientFormat, ClientType)>);

/// Which object an image command addresses: a bound object's face, or a proxy.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct ImageTarget {
    /// Index into [`TARGETS`].
    target: usize,
    face: usize,
    proxy: bool,
}

/// The image target of glTexImage{dims}D / glCopyTexImage / glTexSubImage (proxies allowed
/// where `proxy_ok`).
fn image_target(dims: usize, target: GLenum, proxy_ok: bool) -> Option<ImageTarget> {
    let t = |target, face, proxy| Some(ImageTarget { target, face, proxy });
    match (dims, target) {
        (1, GL_TEXTURE_1D) => t(0, 0, false),
        (1, GL_PROXY_TEXTURE_1D) if proxy_ok => t(0, 0, true),
        (2, GL_TEXTURE_2D) => t(1, 0, false),
        (2, GL_PROXY_TEXTURE_2D) if proxy_ok => t(1, 0, true),
        (2, GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) => {
            t(3, (target - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize, false)
        }
        (2, GL_PROXY_TEXTURE_CUBE_MAP) if proxy_ok => t(3, 0, true),
        (3, GL_TEXTURE_3D) => t(2, 0, false),
        (3, GL_PROXY_TEXTURE_3D) if proxy_ok => t(2, 0, true),
        _ => None,
    }
}

/// The largest size of a target's images.
fn max_size(target: usize) -> usize {
    match target {
        2 => MAX_3D_TEXTURE_SIZE,
        3 => MAX_CUBE_MAP_TEXTURE_SIZE,
        _ => MAX_TEXTURE_SIZE,
    }
}

/// log₂ of the largest size: the largest valid level.
fn max_level(target: usize) -> i32 {
    max_size(target).trailing_zeros() as i32
}

/// Client formats a texture image may be given in: the color, depth and (for depth-stencil
/// formats, GL_EXT_packed_depth_stencil) depth-stencil formats of pixel transfers (not
/// stencil or color index).
fn texture_client_format(format: GLenum) -> Option<ClientFormat> {
    match super::read_pixels::read_format(format)? {
        super::read_pixels::ReadFormat::Client(ClientFormat::StencilIndex) => None,
        super::read_pixels::ReadFormat::Client(f) => Some(f),
        super::read_pixels::ReadFormat::ColorIndex => None,
    }
}

/// Checks a client format/type pair for texture image data (glTexImage, glTexSubImage):
/// the pairs of [`check_texture_format_type`], and GL_COLOR_INDEX data, which is returned
/// as [`ClientFormat::StencilIndex`] (the one-index layout; no texture format takes
/// stencil data, so that format means color indices here).
pub(super) fn check_texture_upload_format_type(
    format: GLenum,
    ty: GLenum,
) -> Result<(ClientFormat, ClientType), GLenum> {
    if format != GL_COLOR_INDEX {
        return check_texture_format_type(format, ty);
    }
    // Every array type and GL_BITMAP (GL_HALF_FLOAT too, with ARB_half_float_pixel, as in Mesa).
    match super::read_pixels::client_type(ty) {
        None => Err(GL_INVALID_ENUM),
        Some(ClientType::Packed(_) | ClientType::UnsignedInt24_8 | ClientType::Float32UnsignedInt24_8Rev) => {
            Err(GL_INVALID_OPERATION)
        }
        Some(t) => Ok((ClientFormat::StencilIndex, t)),
    }
}

/// GL_COLOR_INDEX image data to RGBA (GL 2.1 §3.6.5): the index is shifted by
/// GL_INDEX_SHIFT and offset by GL_INDEX_OFFSET, then looks up the GL_PIXEL_MAP_I_TO_R/G/B/A
/// tables (whose sizes are powers of two) masked to their size.
pub(super) struct IndexToRgba {
    shift: i32,
    offset: i32,
    maps: [Vec<f32>; 4],
}

impl IndexToRgba {
    pub(super) fn new(mode: &super::state::PixelModeState) -> IndexToRgba {
        IndexToRgba {
            shift: mode.transfer.index_shift,
            offset: mode.transfer.index_offset,
            maps: std::array::from_fn(|k| mode.maps[2 + k].clone()),
        }
    }

    /// The color of index `value` (a float index keeps its fraction until the lookup,
    /// which takes the integer part).
    fn color(&self, value: f64) -> [f32; 4] {
        let shifted = value * 2f64.powi(self.shift) + self.offset as f64;
        let index = if shifted.is_finite() { shifted.trunc() as i64 } else { 0 };
        std::array::from_fn(|k| {
            let map = &self.maps[k];
            map[(index & (map.len() as i64 - 1)) as usize]
        })
    }

    /// Unpacks one row of `width` indices of type `ty` starting at `row` (for bitmaps the
    /// row's first byte holds the bit `first_bit`) into colors.
    fn unpack_row(
        &self,
        ty: ClientType,
        swap: bool,
        lsb_first: bool,
        first_bit: usize,
        row: &[u8],
        out: &mut [[f32; 4]],
    ) {
        let size = ty.element_bytes();
        for (i, px) in out.iter_mut().enumerate() {
            let value = if ty == ClientType::Bitmap {
                let bit = first_bit % 8 + i;
                let byte = row.get(bit / 8).copied().unwrap_or(0);
                f64::from(u8::from(bitmap_bit(byte, bit, lsb_first)))
            } else {
                let Some(bytes) = row.get(i * size..(i + 1) * size) else { break };
                index_value(bytes, ty, swap)
            };
            *px = self.color(value);
        }
    }
}

/// Checks a client format/type pair for texture data; the error when invalid. The rules
/// go in Mesa's order (`_mesa_error_check_format_and_type`, then whether the format can
/// hold texture data): a type's own rules first (GL_BITMAP only with index formats; a
/// packed type only with its formats, GL_INVALID_OPERATION even for an unknown format),
/// then the format's validity. The GL 2.1 spec names the errors but not their order.
pub(super) fn check_texture_format_type(format: GLenum, ty: GLenum) -> Result<(ClientFormat, ClientType), GLenum> {
    use super::read_pixels::{read_format, unknown_format_error, ReadFormat};
    if format == GL_DEPTH_STENCIL && ty != GL_UNSIGNED_INT_24_8 && ty != GL_FLOAT_32_UNSIGNED_INT_24_8_REV {
        // GL_DEPTH_STENCIL data has the two packed types (Mesa: GL_INVALID_ENUM otherwise).
        return Err(GL_INVALID_ENUM);
    }
    let client_type = super::read_pixels::client_type(ty).ok_or(GL_INVALID_ENUM)?;
    let known = read_format(format);
    match (client_type, known) {
        (ClientType::Bitmap, Some(ReadFormat::ColorIndex | ReadFormat::Client(ClientFormat::StencilIndex))) => {}
        (ClientType::Bitmap, _) => return Err(GL_INVALID_ENUM),
        (ClientType::Packed(p), Some(ReadFormat::Client(f))) if p.accepts(f) => {}
        (ClientType::Packed(_), _) => return Err(GL_INVALID_OPERATION),
        (
            ClientType::UnsignedInt24_8 | ClientType::Float32UnsignedInt24_8Rev,
            Some(ReadFormat::Client(ClientFormat::DepthStencil)),
        ) => {}
        (ClientType::UnsignedInt24_8 | ClientType::Float32UnsignedInt24_8Rev, _) => return Err(GL_INVALID_OPERATION),
        _ => {}
    }
    let Some(f) = texture_client_format(format) else {
        return Err(match known {
            // Formats that exist but cannot hold texture data.
            Some(_) => GL_INVALID_OPERATION,
            None => unknown_format_error(ty),
        });
    };
    match client_type {
        ClientType::Bitmap => Err(GL_INVALID_ENUM),
        ClientType::Packed(_) if f == ClientFormat::DepthComponent => Err(GL_INVALID_OPERATION),
        t => Ok((f, t)),
    }
}

/// The client layout of a 1D/2D/3D image transfer of `width` × `height` pixels under the
/// pixel store `modes` (the image height and skipped images count for volumes only).
pub(super) fn client_image(
    format: ClientFormat,
    ty: ClientType,
    modes: &super::state::PixelStoreModes,
    width: usize,
    height: usize,
    dims: usize,
) -> Option<VolumeLayout> {
    let (image_height, skip_images) =
        if dims == 3 { (modes.image_height.max(0) as usize, modes.skip_images.max(0) as usize) } else { (0, 0) };
    VolumeLayout::new(format, ty, &PackModes::from(modes), [width, height], image_height, skip_images)
}

/// The sizes and placement of an image command, already converted from GL integers.
#[derive(Clone, Copy, Debug)]
pub struct ImageArgs {
    pub target: GLenum,
    pub level: i32,
    pub internal_format: i32,
    pub width: i32,
    pub height: i32,
    pub depth: i32,
    pub border: i32,
}

/// A sub-image region: offsets and sizes.
#[derive(Clone, Copy, Debug)]
pub struct Region {
    pub x: i32,
    pub y: i32,
    pub z: i32,
    pub width: i32,
    pub height: i32,
    pub depth: i32,
}

impl Context {
    /// The name bound to target index `t` on the active unit.
    pub fn bound_texture(&self, t: usize) -> u32 {
        self.state.texture.unit_state[self.state.texture.active_unit].bindings[t]
    }

    /// glGenTextures.
    pub fn gen_textures(&mut self, n: i32) -> Option<Vec<u32>> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if n < 0 {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        let names = self.textures.lock().names.generate(n as usize);
        match names {
            Ok(names) => Some(names),
            Err(OutOfNames) => {
                self.error(GL_OUT_OF_MEMORY);
                None
            }
        }
    }

    /// glDeleteTextures: bindings of deleted objects revert to the default objects.
    pub fn delete_textures(&mut self, n: i32, names: &[u32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if n < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        for &name in names {
            if name == 0 {
                continue;
            }
            let removed = self.textures.lock().names.delete(name).is_some();
            if removed {
                self.detach_texture(name);
                for unit in &mut self.state.texture.unit_state {
                    for b in &mut unit.bindings {
                        if *b == name {
                            *b = 0;
                        }
                    }
                }
            }
        }
    }

    /// glIsTexture: true for names of objects that have been bound.
    pub fn is_texture(&mut self, name: u32) -> bool {
        self.check_outside_begin_end() && name != 0 && self.textures.lock().names.is_object(name)
    }

    /// glBindTexture.
    pub fn bind_texture(&mut self, target: GLenum, name: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(t) = target_index(target) else {
            return self.error(GL_INVALID_ENUM);
        };
        if name != 0 {
            let other_target = {
                let mut t = self.textures.lock();
                t.names
                    .get_or_create(name, || TextureObject::with_target(target))
                    .is_some_and(|obj| obj.target != target)
            };
            if other_target {
                return self.error(GL_INVALID_OPERATION);
            }
        }
        let unit = self.state.texture.active_unit;
        self.state.texture.unit_state[unit].bindings[t] = name;
    }

    /// glPrioritizeTextures: priorities are clamped to [0, 1]; name 0 and unknown names are
    /// skipped.
    pub fn prioritize_textures(&mut self, n: i32, names: &[u32], priorities: &[f32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if n < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        for (&name, &p) in names.iter().zip(priorities) {
            if name == 0 {
                continue;
            }
            if let Some(obj) = self.textures.lock().names.get_mut(name) {
                obj.params.priority = p.clamp(0.0, 1.0);
            }
        }
    }

    /// glAreTexturesResident: every texture is resident (GL_TRUE, `residences` untouched);
    /// a name that is not a texture is GL_INVALID_VALUE.
    pub fn are_textures_resident(&mut self, n: i32, names: &[u32]) -> bool {
        if !self.check_outside_begin_end() {
            return false;
        }
        if n < 0 {
            self.error(GL_INVALID_VALUE);
            return false;
        }
        let unknown = {
            let t = self.textures.lock();
            names.iter().any(|&name| name == 0 || !t.names.is_object(name))
        };
        if unknown {
            self.error(GL_INVALID_VALUE);
            return false;
        }
        true
    }

    /// Runs `f` on the object an image command with `it` works on (the texture table is
    /// locked meanwhile: `f` must not lock it again).
    fn with_image_object<R>(&self, it: ImageTarget, f: impl FnOnce(&mut TextureObject) -> R) -> R {
        let name = self.bound_texture(it.target);
        let mut guard = self.textures.lock();
        let t = &mut *guard;
        let obj = if it.proxy {
            &mut t.proxies[it.target]
        } else if name == 0 {
            &mut t.defaults[it.target]
        } else {
            let target = TARGETS[it.target];
            // A name is bound only once it is an object, so this creates nothing in practice.
            match t.names.get_or_create(name, || TextureObject::with_target(target)) {
                Some(obj) => obj,
                None => &mut t.defaults[it.target],
            }
        };
        f(obj)
    }

    /// Validates glTexImage{dims}D / glCopyTexImage{dims}D arguments; returns the target,
    /// the format info and the sizes without border. `client` is the format/type (None for
    /// copies, whose source format comes from the internal format).
    fn check_tex_image(
        &mut self,
        dims: usize,
        a: &ImageArgs,
        client: Option<(GLenum, GLenum)>,
        proxy_ok: bool,
    ) -> Option<CheckedImage> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let Some(it) = image_target(dims, a.target, proxy_ok) else {
            self.error(GL_INVALID_ENUM);
            return None;
        };
        if a.level < 0 || a.level > max_level(it.target) {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        // Mesa's order (the GL 2.1 spec names the errors, not their order): the border, the
        // sizes, the client format and type, the internal format.
        if a.border != 0 && a.border != 1 {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        let b2 = 2 * a.border;
        let limit = (max_size(it.target) >> a.level) as i32 + b2;
        let dims_ok = |s: i32, used: bool| !used || (s >= b2 && s <= limit);
        let sizes_ok = a.width >= 0
            && a.height >= 0
            && a.depth >= 0
            && dims_ok(a.width, true)
            && dims_ok(a.height, dims >= 2)
            && dims_ok(a.depth, dims >= 3)
            && !(it.target == 3 && a.width != a.height);
        // glCopyTexImage's internalformat is an enum without the legacy 1-4 (GL 2.1
        // §3.8.2): anything else is GL_INVALID_ENUM (§2.5), checked before the sizes as in
        // Mesa; glTexImage's is an integer, GL_INVALID_VALUE when unknown (§3.8.1), checked
        // after the client format and type.
        let copy = client.is_none();
        let info = match format_info(a.internal_format) {
            Some(_) if copy && (1..=4).contains(&a.internal_format) => None,
            info => info,
        };
        if copy && info.is_none() {
            self.error(GL_INVALID_ENUM);
            return None;
        }
        // Proxies report a size they cannot have as zero state (below), not as an error.
        let proxy_size = it.proxy && a.width >= 0 && a.height >= 0 && a.depth >= 0;
        if !sizes_ok && !proxy_size {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        let pair = match client {
            Some((format, ty)) => match check_texture_upload_format_type(format, ty) {
                Ok(p) => Some(p),
                Err(e) => {
                    self.error(e);
                    return None;
                }
            },
            None => None,
        };
        let Some(info) = info else {
            self.error(GL_INVALID_VALUE);
            return None;
        };
        if !sizes_ok {
            self.clear_proxy_level(it, a.level as usize);
            return None;
        }
        if let Some((f, _)) = pair {
            if !data_fits(f, &info) {
                self.error(GL_INVALID_OPERATION);
                return None;
            }
        }
        if info.base == BaseFormat::Depth && (it.target == 2 || it.target == 3) {
            // Mesa 22 reports depth-stencil images of 3D textures as GL_INVALID_OPERATION.
            let error = if it.target == 2 && !info.has_stencil() { GL_INVALID_VALUE } else { GL_INVALID_OPERATION };
            self.error(error);
            return None;
        }
        Some((it, info, pair))
    }

    fn clear_proxy_level(&mut self, it: ImageTarget, level: usize) {
        let mut t = self.textures.lock();
        for face in t.proxies[it.target].faces.iter_mut() {
            if let Some(l) = face.get_mut(level) {
                *l = None;
            }
        }
    }

    /// Stores `level` of `face` on the object of `it`.
    fn set_level(&mut self, it: ImageTarget, level: usize, new: Level) {
        let faces = if it.proxy && it.target == 3 { 0..6 } else { it.face..it.face + 1 };
        self.with_image_object(it, |obj| {
            for face in faces {
                let levels = &mut obj.faces[face];
                if levels.len() <= level {
                    levels.resize(level + 1, None);
                }
                levels[level] = Some(new.clone());
            }
        });
    }

    /// The bytes of a `size` (width, height, depth) client image of `format`/`ty` under the
    /// current unpack state: what an image command reads. `None` when the arguments are
    /// invalid (the command reports that when it runs). Display lists copy these bytes.
    pub fn client_image_span(&self, dims: usize, format: GLenum, ty: GLenum, size: [i32; 3]) -> Option<Range<usize>> {
        let (cf, ct) = check_texture_upload_format_type(format, ty).ok()?;
        if size.iter().any(|&s| s < 0) {
            return None;
        }
        let [w, h, d] = size.map(|s| s.max(1) as usize);
        let client = client_image(cf, ct, &self.pixel_store.unpack, size[0] as usize, h, dims)?;
        client.span(w.min(size[0] as usize), h, d)
    }

    /// glTexImage1D/2D/3D. `data` gives the client bytes of the image's span (relative to
    /// the pointer); `None` (a NULL pointer) leaves the texels zero.
    pub fn tex_image<'a>(
        &mut self,
        dims: usize,
        a: ImageArgs,
        format: GLenum,
        ty: GLenum,
        data: impl FnOnce(Range<usize>) -> ClientBytes<'a>,
    ) {
        let Some((it, info, pair)) = self.check_tex_image(dims, &a, Some((format, ty)), true) else {
            return;
        };
        self.flush_into_textures();
        let (cf, ct) = pair.expect("format and type checked");
        let b = a.border as usize;
        let (w, h, d) = (a.width as usize, a.height.max(1) as usize, a.depth.max(1) as usize);
        let (iw, ih, id) = (w, if dims >= 2 { h } else { 1 }, if dims >= 3 { d } else { 1 });
        let size = |s: usize, used: bool| if used { s - 2 * b } else { 1 };
        let level = Level {
            image: None,
            internal_format: a.internal_format,
            info,
            width: size(iw, true),
            height: size(ih, dims >= 2),
            depth: size(id, dims >= 3),
            border: b,
        };
        if it.proxy {
            self.set_level(it, a.level as usize, level);
            return;
        }
        let Ok(mut image) = new_image(iw, ih, id, b, &info) else {
            return self.error(GL_OUT_OF_MEMORY);
        };
        let Some(client) = client_image(cf, ct, &self.pixel_store.unpack, iw, ih, dims) else {
            return self.error(GL_INVALID_VALUE);
        };
        let Some(span) = client.span(iw, ih, id) else {
            return self.error(GL_INVALID_VALUE);
        };
        let bytes = if span.is_empty() { Ok(None) } else { data(span.clone()) };
        let bytes = match bytes {
            Ok(bytes) => bytes,
            Err(error) => return self.error(error),
        };
        if let Some(bytes) = bytes {
            let unpack = Unpack {
                swap: self.pixel_store.unpack.swap_bytes,
                lsb_first: self.pixel_store.unpack.lsb_first,
                indices: IndexToRgba::new(&self.state.pixel_mode),
            };
            let region = Region { x: 0, y: 0, z: 0, width: iw as i32, height: ih as i32, depth: id as i32 };
            store_client(&mut image, &info, &client, span.start, bytes, cf, ct, &unpack, region);
        }
        self.set_level(it, a.level as usize, Level { image: Some(Arc::new(image)), ..level });
        self.after_image_change(it, a.level as usize);
    }

    /// GL_GENERATE_MIPMAP: regenerates the levels below the base level when `level` is it.
    fn after_image_change(&mut self, it: ImageTarget, level: usize) {
        let dims = if it.target == 2 {
            3
        } else if it.target == 0 {
            1
        } else {
            2
        };
        let failed = self.with_image_object(it, |obj| {
            obj.params.generate_mipmap
                && level as i32 == obj.params.base_level
                && generate_mipmaps(obj, it.face, dims).is_err()
        });
        if failed {
            self.error(GL_OUT_OF_MEMORY);
        }
    }

    /// Validates a sub-image (or copy) region of the level `level` of target `it`; returns the level's
    /// format info and its border.
    fn check_sub_image(&mut self, dims: usize, target: GLenum, level: i32, r: &Region) -> Option<(ImageTarget, Level)> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let Some(it) = image_target(dims, target, false) else {
            self.error(GL_INVALID_ENUM);
            return None;
        };
        if level < 0 || level > max_level(it.target) {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        let Some(lv) = self.with_image_object(it, |obj| obj.level(it.face, level as usize).cloned()) else {
            self.error(GL_INVALID_OPERATION);
            return None;
        };
        if r.width < 0 || r.height < 0 || r.depth < 0 {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        let b = lv.border as i64;
        let fits = |o: i32, s: i32, size: usize, used: bool| {
            !used || ((o as i64) >= -b && (o as i64) + (s as i64) <= size as i64 + b)
        };
        if !(fits(r.x, r.width, lv.width, true)
            && fits(r.y, r.height, lv.height, dims >= 2)
            && fits(r.z, r.depth, lv.depth, dims >= 3))
        {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        Some((it, lv))
    }

    /// glTexSubImage1D/2D/3D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image<'a>(
        &mut self,
        dims: usize,
        target: GLenum,
        level: i32,
        r: Region,
        format: GLenum,
        ty: GLenum,
        data: impl FnOnce(Range<usize>) -> ClientBytes<'a>,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        self.flush_into_textures();
        if image_target(dims, target, false).is_none() {
            return self.error(GL_INVALID_ENUM);
        }
        let (cf, ct) = match check_texture_upload_format_type(format, ty) {
            Ok(p) => p,
            Err(e) => return self.error(e),
        };
        let Some((it, lv)) = self.check_sub_image(dims, target, level, &r) else {
            return;
        };
        if !data_fits(cf, &lv.info) {
            return self.error(GL_INVALID_OPERATION);
        }
        let r =
            Region { height: if dims >= 2 { r.height } else { 1 }, depth: if dims >= 3 { r.depth } else { 1 }, ..r };
        let (w, h, d) = (r.width as usize, r.height as usize, r.depth as usize);
        let Some(client) = client_image(cf, ct, &self.pixel_store.unpack, w, h, dims) else {
            return self.error(GL_INVALID_VALUE);
        };
        let Some(span) = client.span(w, h, d) else {
            return self.error(GL_INVALID_VALUE);
        };
        if span.is_empty() {
            return;
        }
        let bytes = match data(span.clone()) {
            Ok(Some(bytes)) => bytes,
            Ok(None) => return,
            Err(error) => return self.error(error),
        };
        self.flush_rendering();
        let unpack = Unpack {
            swap: self.pixel_store.unpack.swap_bytes,
            lsb_first: self.pixel_store.unpack.lsb_first,
            indices: IndexToRgba::new(&self.state.pixel_mode),
        };
        let b = lv.border as i32;
        let region =
            Region { x: r.x + b, y: if dims >= 2 { r.y + b } else { 0 }, z: if dims >= 3 { r.z + b } else { 0 }, ..r };
        self.with_level_image(it, level as usize, |image| {
            store_client(image, &lv.info, &client, span.start, bytes, cf, ct, &unpack, region)
        });
        self.after_image_change(it, level as usize);
    }

    /// Runs `f` on the texels of a level (cloned first if a recorded draw still shares them).
    fn with_level_image(&mut self, it: ImageTarget, level: usize, f: impl FnOnce(&mut TexImage)) {
        self.with_image_object(it, |obj| {
            if let Some(Some(lv)) = obj.faces[it.face].get_mut(level) {
                if let Some(image) = lv.image.as_mut() {
                    f(Arc::make_mut(image));
                }
            }
        });
    }

    /// glCopyTexImage1D/2D: the image comes from the read buffer (color formats) or the depth
    /// buffer (depth formats); pixels outside the framebuffer are zero.
    pub fn copy_tex_image(&mut self, dims: usize, a: ImageArgs, x: i32, y: i32) {
        let Some((it, info, _)) = self.check_tex_image(dims, &a, None, false) else {
            return;
        };
        if !self.check_framebuffer_complete(false) || !self.check_read_single_sampled() {
            return;
        }
        let depth_bits = self.read_config().depth_stencil.depth_bits();
        let stencil_bits = self.read_config().depth_stencil.stencil_bits();
        if info.base == BaseFormat::Depth && (depth_bits == 0 || (info.has_stencil() && stencil_bits == 0)) {
            return self.error(GL_INVALID_OPERATION);
        }
        if info.base != BaseFormat::Depth && self.current_read_slot().is_none() {
            return self.error(GL_INVALID_OPERATION);
        }
        let b = a.border as usize;
        let (w, h) = (a.width as usize, if dims >= 2 { a.height as usize } else { 1 });
        let Ok(mut image) = new_image(w, h, 1, b, &info) else {
            return self.error(GL_OUT_OF_MEMORY);
        };
        self.flush_rendering();
        let region = Region { x: 0, y: 0, z: 0, width: w as i32, height: h as i32, depth: 1 };
        self.copy_framebuffer(&mut image, &info, region, x, y);
        let level = Level {
            image: Some(Arc::new(image)),
            internal_format: a.internal_format,
            info,
            width: w - 2 * b,
            height: if dims >= 2 { h - 2 * b } else { 1 },
            depth: 1,
            border: b,
        };
        self.set_level(it, a.level as usize, level);
        self.after_image_change(it, a.level as usize);
    }

    /// glCopyTexSubImage1D/2D/3D.
    pub fn copy_tex_sub_image(&mut self, dims: usize, target: GLenum, level: i32, r: Region, x: i32, y: i32) {
        let Some((it, lv)) = self.check_sub_image(dims, target, level, &Region { depth: 1, ..r }) else {
            return;
        };
        if !self.check_framebuffer_complete(false) || !self.check_read_single_sampled() {
            return;
        }
        let depth_bits = self.read_config().depth_stencil.depth_bits();
        let stencil_bits = self.read_config().depth_stencil.stencil_bits();
        if (lv.info.base == BaseFormat::Depth && (depth_bits == 0 || (lv.info.has_stencil() && stencil_bits == 0)))
            || (lv.info.base != BaseFormat::Depth && self.current_read_slot().is_none())
        {
            return self.error(GL_INVALID_OPERATION);
        }
        self.flush_rendering();
        let b = lv.border as i32;
        let region = Region {
            x: r.x + b,
            y: if dims >= 2 { r.y + b } else { 0 },
            z: if dims >= 3 { r.z + b } else { 0 },
            width: r.width,
            height: if dims >= 2 { r.height } else { 1 },
            depth: 1,
        };
        let image = self.with_image_object(it, |obj| obj.level(it.face, level as usize).and_then(|l| l.image.clone()));
        let mut image = match image {
            Some(i) => i,
            None => return,
        };
        self.copy_framebuffer(Arc::make_mut(&mut image), &lv.info, region, x, y);
        self.with_image_object(it, |obj| {
            if let Some(Some(l)) = obj.faces[it.face].get_mut(level as usize) {
                l.image = Some(image);
            }
        });
        self.after_image_change(it, level as usize);
    }

    /// Copies the framebuffer rectangle at (x, y) into `region` of `image`.
    fn copy_framebuffer(&mut self, image: &mut TexImage, info: &FormatInfo, region: Region, x: i32, y: i32) {
        let slot = self.current_read_slot();
        let _ = self.with_read_framebuffer(|fb| {
            let (fw, fh) = (fb.width() as i32, fb.height() as i32);
            let mut colors = Vec::new();
            let mut depths = Vec::new();
            let mut stencils = Vec::new();
            for row in 0..region.height {
                let sy = y + row;
                if sy < 0 || sy >= fh {
                    continue;
                }
                let (x0, x1) = (x.max(0), (x + region.width).min(fw));
                if x0 >= x1 {
                    continue;
                }
                let tx = (region.x + x0 - x) as usize;
                let ty = (region.y + row) as usize;
                let start = image.index(tx, ty, region.z as usize);
                if info.base == BaseFormat::Depth {
                    depths.clear();
                    fb.depth_stencil().read_depth_row(sy, x0, x1, &mut depths);
                    let encoding = fb.depth_stencil().depth_encoding();
                    for (k, &d) in depths.iter().enumerate() {
                        image.set_depth_f32(start + k, encoding.decode(d));
                    }
                    if info.has_stencil() {
                        stencils.clear();
                        fb.depth_stencil().read_stencil_row(sy, x0, x1, &mut stencils);
                        for (k, &s) in stencils.iter().enumerate() {
                            image.set_stencil(start + k, s);
                        }
                    }
                } else if let Some(buffer) = slot.and_then(|s| fb.color(s)) {
                    colors.clear();
                    buffer.read_row_f32(sy, x0, x1, &mut colors);
                    if let Texels::Rgba8(t) = &mut image.texels {
                        for (k, c) in colors.iter().enumerate() {
                            t[start + k] = texel8(info, *c);
                        }
                    }
                }
            }
        });
    }

    /// glGenerateMipmap (GL_ARB_framebuffer_object / EXT_framebuffer_object): the levels
    /// below the base level of the bound object of `target`, from the base level.
    pub fn generate_mipmap(&mut self, target: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(t) = target_index(target) else {
            return self.error(GL_INVALID_ENUM);
        };
        self.flush_rendering();
        let it = ImageTarget { target: t, face: 0, proxy: false };
        let dims = if t == 2 {
            3
        } else if t == 0 {
            1
        } else {
            2
        };
        let faces = if t == 3 { 6 } else { 1 };
        let failed =
            self.with_image_object(it, |obj| (0..faces).any(|face| generate_mipmaps(obj, face, dims).is_err()));
        if failed {
            self.error(GL_OUT_OF_MEMORY);
        }
    }

    /// glTexParameter{if}[v]: `values` as floats, `ints` the same values as the integers of
    /// the integer forms (for the border color's normalization).
    pub fn tex_parameter(&mut self, target: GLenum, pname: GLenum, values: &[f32], int_form: bool) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(t) = target_index(target) else {
            return self.error(GL_INVALID_ENUM);
        };
        let v = values.first().copied().unwrap_or(0.0);
        let e = v as i32 as GLenum;
        let name = self.bound_texture(t);
        let textures = self.textures.clone();
        let mut table = textures.lock();
        let Some(obj) = table.get_mut(name, t) else {
            return;
        };
        let p = &mut obj.params;
        let result: Result<(), GLenum> = match pname {
            GL_TEXTURE_MIN_FILTER => match e {
                GL_NEAREST
                | GL_LINEAR
                | GL_NEAREST_MIPMAP_NEAREST
                | GL_LINEAR_MIPMAP_NEAREST
                | GL_NEAREST_MIPMAP_LINEAR
                | GL_LINEAR_MIPMAP_LINEAR => {
                    p.min_filter = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            GL_TEXTURE_MAG_FILTER => match e {
                GL_NEAREST | GL_LINEAR => {
                    p.mag_filter = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R => match e {
                GL_REPEAT | GL_CLAMP | GL_CLAMP_TO_EDGE | GL_CLAMP_TO_BORDER | GL_MIRRORED_REPEAT => {
                    let i = match pname {
                        GL_TEXTURE_WRAP_S => 0,
                        GL_TEXTURE_WRAP_T => 1,
                        _ => 2,
                    };
                    p.wrap[i] = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            GL_TEXTURE_BORDER_COLOR => {
                if values.len() < 4 {
                    Err(GL_INVALID_ENUM)
                } else {
                    let c: [f32; 4] = std::array::from_fn(|i| values[i]);
                    // The integer forms give normalized integers; colors are clamped (GL 2.1).
                    p.border_color = c.map(|x| {
                        let f = if int_form { (x as f64 / 2147483647.0) as f32 } else { x };
                        f.clamp(0.0, 1.0)
                    });
                    Ok(())
                }
            }
            GL_TEXTURE_PRIORITY => {
                p.priority = v.clamp(0.0, 1.0);
                Ok(())
            }
            GL_TEXTURE_MIN_LOD => {
                p.min_lod = v;
                Ok(())
            }
            GL_TEXTURE_MAX_LOD => {
                p.max_lod = v;
                Ok(())
            }
            GL_TEXTURE_BASE_LEVEL | GL_TEXTURE_MAX_LEVEL => {
                let i = v as i32;
                if i < 0 {
                    Err(GL_INVALID_VALUE)
                } else {
                    if pname == GL_TEXTURE_BASE_LEVEL {
                        p.base_level = i;
                    } else {
                        p.max_level = i;
                    }
                    Ok(())
                }
            }
            GL_TEXTURE_LOD_BIAS => {
                p.lod_bias = v;
                Ok(())
            }
            GL_TEXTURE_COMPARE_MODE => match e {
                GL_NONE | GL_COMPARE_R_TO_TEXTURE => {
                    p.compare_mode = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            GL_TEXTURE_COMPARE_FUNC => match e {
                GL_NEVER | GL_LESS | GL_EQUAL | GL_LEQUAL | GL_GREATER | GL_NOTEQUAL | GL_GEQUAL | GL_ALWAYS => {
                    p.compare_func = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            GL_DEPTH_TEXTURE_MODE => match e {
                GL_LUMINANCE | GL_INTENSITY | GL_ALPHA => {
                    p.depth_mode = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            GL_GENERATE_MIPMAP => {
                p.generate_mipmap = v != 0.0;
                Ok(())
            }
            _ => Err(GL_INVALID_ENUM),
        };
        if let Err(e) = result {
            self.error(e);
        }
    }

    /// glGetTexParameter{if}v: the values as floats and whether each is an enum/integer
    /// (integer queries of the border color are normalized, of the LODs rounded).
    pub fn get_tex_parameter(&mut self, target: GLenum, pname: GLenum) -> Option<(Vec<f32>, bool)> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let Some(t) = target_index(target) else {
            self.error(GL_INVALID_ENUM);
            return None;
        };
        let name = self.bound_texture(t);
        let p = self.textures.lock().get(name, t)?.params.clone();
        let e = |x: GLenum| (vec![x as f32], false);
        Some(match pname {
            GL_TEXTURE_MIN_FILTER => e(p.min_filter),
            GL_TEXTURE_MAG_FILTER => e(p.mag_filter),
            GL_TEXTURE_WRAP_S => e(p.wrap[0]),
            GL_TEXTURE_WRAP_T => e(p.wrap[1]),
            GL_TEXTURE_WRAP_R => e(p.wrap[2]),
            GL_TEXTURE_BORDER_COLOR => (p.border_color.to_vec(), true),
            GL_TEXTURE_PRIORITY => (vec![p.priority], true),
            GL_TEXTURE_RESIDENT => e(GL_TRUE as GLenum),
            GL_TEXTURE_MIN_LOD => (vec![p.min_lod], false),
            GL_TEXTURE_MAX_LOD => (vec![p.max_lod], false),
            GL_TEXTURE_BASE_LEVEL => e(p.base_level as GLenum),
            GL_TEXTURE_MAX_LEVEL => e(p.max_level as GLenum),
            GL_TEXTURE_LOD_BIAS => (vec![p.lod_bias], false),
            GL_TEXTURE_COMPARE_MODE => e(p.compare_mode),
            GL_TEXTURE_COMPARE_FUNC => e(p.compare_func),
            GL_DEPTH_TEXTURE_MODE => e(p.depth_mode),
            GL_GENERATE_MIPMAP => e(p.generate_mipmap as GLenum),
            _ => {
                self.error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    /// glGetTexLevelParameter{if}v.
    pub fn get_tex_level_parameter(&mut self, target: GLenum, level: i32, pname: GLenum) -> Option<i32> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let dims = match target {
            GL_TEXTURE_1D | GL_PROXY_TEXTURE_1D => 1,
            GL_TEXTURE_3D | GL_PROXY_TEXTURE_3D => 3,
            _ => 2,
        };
        let Some(it) = image_target(dims, target, true) else {
            self.error(GL_INVALID_ENUM);
            return None;
        };
        if level < 0 || level > max_level(it.target) {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        let lv = self.with_image_object(it, |obj| obj.level(it.face, level as usize).cloned());
        let size = |k: usize| lv.as_ref().map_or(0, |l| l.info.sizes[k]);
        Some(match pname {
            GL_TEXTURE_WIDTH => lv.as_ref().map_or(0, |l| (l.width + 2 * l.border) as i32),
            GL_TEXTURE_HEIGHT => {
                lv.as_ref().map_or(0, |l| (l.height + if dims >= 2 { 2 * l.border } else { 0 }) as i32)
            }
            GL_TEXTURE_DEPTH => lv.as_ref().map_or(0, |l| (l.depth + if dims >= 3 { 2 * l.border } else { 0 }) as i32),
            GL_TEXTURE_BORDER => lv.as_ref().map_or(0, |l| l.border as i32),
            GL_TEXTURE_INTERNAL_FORMAT => lv.as_ref().map_or(1, |l| reported_internal_format(l.internal_format)),
            GL_TEXTURE_RED_SIZE => size(0),
            GL_TEXTURE_GREEN_SIZE => size(1),
            GL_TEXTURE_BLUE_SIZE => size(2),
            GL_TEXTURE_ALPHA_SIZE => size(3),
            GL_TEXTURE_LUMINANCE_SIZE => size(4),
            GL_TEXTURE_INTENSITY_SIZE => size(5),
            GL_TEXTURE_DEPTH_SIZE => size(6),
            GL_TEXTURE_STENCIL_SIZE => size(7),
            GL_TEXTURE_COMPRESSED => 0,
            GL_TEXTURE_COMPRESSED_IMAGE_SIZE => {
                self.error(GL_INVALID_OPERATION);
                return None;
            }
            _ => {
                self.error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    /// glGetTexImage: the level's texels in `format`/`ty` under the pack parameters.
    /// `dest` turns the byte span into client memory (`None`: NULL, nothing written).
    pub fn get_tex_image<'a>(
        &mut self,
        target: GLenum,
        level: i32,
        format: GLenum,
        ty: GLenum,
        dest: impl FnOnce(Range<usize>) -> ClientBytesMut<'a>,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        self.flush_into_textures();
        let dims = match target {
            GL_TEXTURE_1D => 1,
            GL_TEXTURE_3D => 3,
            _ => 2,
        };
        let Some(it) = image_target(dims, target, false) else {
            return self.error(GL_INVALID_ENUM);
        };
        if level < 0 || level > max_level(it.target) {
            return self.error(GL_INVALID_VALUE);
        }
        let (cf, ct) = match check_texture_format_type(format, ty) {
            Ok(p) => p,
            // GL 2.1 §6.1.4 lists no index format for glGetTexImage: GL_INVALID_ENUM (§2.5),
            // after the type's rules. (Mesa 22 accepts GL_COLOR_INDEX.)
            Err(GL_INVALID_OPERATION) if matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX) => {
                return self.error(
                    if matches!(
                        super::read_pixels::client_type(ty),
                        Some(ClientType::Packed(_) | ClientType::UnsignedInt24_8)
                    ) {
                        GL_INVALID_OPERATION
                    } else {
                        GL_INVALID_ENUM
                    },
                )
            }
            Err(e) => return self.error(e),
        };
        let Some(lv) = self.with_image_object(it, |obj| obj.level(it.face, level as usize).cloned()) else {
            return;
        };
        // Depth and stencil can be read only from an image that has both.
        let readable = match cf {
            ClientFormat::DepthStencil => lv.info.has_stencil(),
            _ => data_fits(cf, &lv.info),
        };
        if !readable {
            return self.error(GL_INVALID_OPERATION);
        }
        let Some(image) = lv.image else { return };
        self.flush_rendering();
        let (w, h, d) = (image.width, image.height, image.depth);
        let Some(client) = client_image(cf, ct, &self.pixel_store.pack, w, h, dims) else {
            return self.error(GL_INVALID_VALUE);
        };
        let Some(span) = client.span(w, h, d) else {
            return self.error(GL_INVALID_VALUE);
        };
        if span.is_empty() {
            return;
        }
        let out = match dest(span.clone()) {
            Ok(Some(out)) => out,
            Ok(None) => return,
            Err(error) => return self.error(error),
        };
        let swap = self.pixel_store.pack.swap_bytes;
        for z in 0..d {
            for y in 0..h {
                let Some(offset) = client.row_offset(y, z) else { continue };
                let row = &mut out[offset - span.start..offset - span.start + w * client.pixel_bytes()];
                let start = image.index(0, y, z);
                if cf == ClientFormat::DepthStencil {
                    let Texels::Depth(t) = &image.texels else { continue };
                    let stencil: Vec<u8> = (start..start + w).map(|i| t.stencil_value(i)).collect();
                    let stencil = &stencil[..];
                    if lv.info.float_depth || ct == ClientType::Float32UnsignedInt24_8Rev {
                        // The texels as float depth values (a float's bit pattern is its
                        // DepthEncoding::Float value).
                        let bits: Vec<u32> = (start..start + w).map(|i| image.depth_f32(i).to_bits()).collect();
                        if ct == ClientType::Float32UnsignedInt24_8Rev {
                            crate::pixel::depth::pack_depth_stencil_float_row(
                                &bits,
                                DepthEncoding::Float,
                                stencil,
                                swap,
                                row,
                            );
                        } else {
                            crate::pixel::depth::pack_depth_stencil_row(
                                &bits,
                                DepthEncoding::Float,
                                stencil,
                                swap,
                                row,
                            );
                        }
                    } else {
                        // A depth-stencil format with fixed-point depth keeps 24 bits.
                        let fixed: Vec<u32> = (start..start + w).map(|i| t.depth_value(i)).collect();
                        crate::pixel::depth::pack_depth_stencil_row(
                            &fixed,
                            DepthEncoding::Unorm(24),
                            stencil,
                            swap,
                            row,
                        );
                    }
                } else {
                    pack_texels_row(&image, start, w, cf, ct, swap, row);
                }
            }
        }
    }
}

/// A zero image of a format (depth formats in their depth-buffer storage, with stencil for
/// depth-stencil formats).
fn new_image(
    w: usize,
    h: usize,
    d: usize,
    border: usize,
    info: &FormatInfo,
) -> Result<TexImage, crate::texture::OutOfMemory> {
    if info.base == BaseFormat::Depth {
        TexImage::new_depth(w, h, d, border, info.depth_format())
    } else {
        let mut image = TexImage::new(w, h, d, border, info.base)?;
        image.srgb = info.srgb;
        Ok(image)
    }
}

/// GL_TEXTURE_INTERNAL_FORMAT of a level specified with `internal_format`. A generic
/// compressed format stored uncompressed is "replaced by the corresponding base internal
/// format" (GL 1.3 §3.8.1, as Mesa 22 reports it) — for the sRGB ones, which Mesa 22 stores
/// uncompressed too when no compressed sRGB format of that base exists (luminance, luminance
/// alpha). tessera keeps reporting the other generic compressed formats as given (GL_RGB and
/// GL_RGBA sRGB included), where Mesa reports the S3TC format it chose.
fn reported_internal_format(internal_format: i32) -> i32 {
    match internal_format as GLenum {
        GL_COMPRESSED_SLUMINANCE => GL_LUMINANCE as i32,
        GL_COMPRESSED_SLUMINANCE_ALPHA => GL_LUMINANCE_ALPHA as i32,
        _ => internal_format,
    }
}

/// Whether client data of format `f` may specify images of a format: depth or depth-stencil
/// data for depth and depth-stencil formats (GL_EXT_packed_depth_stencil; depth data leaves
/// the stencil of a depth-stencil image alone, depth-stencil data gives a depth image only
/// its depth), color data for color formats.
fn data_fits(f: ClientFormat, info: &FormatInfo) -> bool {
    let depth_data = matches!(f, ClientFormat::DepthComponent | ClientFormat::DepthStencil);
    depth_data == (info.base == BaseFormat::Depth)
}

/// The stored 8-bit texel of an RGBA color in a format.
#[inline]
fn texel8(info: &FormatInfo, c: [f32; 4]) -> [u8; 4] {
    let t = info.base.texture_color(c);
    std::array::from_fn(|k| quantize_to_u8(t[k], info.bits[k]))
}

/// The unpack state an image upload needs besides the layout.
struct Unpack {
    swap: bool,
    lsb_first: bool,
    indices: IndexToRgba,
}

/// Converts client pixels of `region` (texel coordinates, border included) into `image`;
/// `cf` is [`ClientFormat::StencilIndex`] for color-index data.
#[allow(clippy::too_many_arguments)]
fn store_client(
    image: &mut TexImage,
    info: &FormatInfo,
    client: &VolumeLayout,
    span_start: usize,
    bytes: &[u8],
    cf: ClientFormat,
    ct: ClientType,
    unpack: &Unpack,
    r: Region,
) {
    let swap = unpack.swap;
    let w = r.width as usize;
    let mut colors = vec![[0f32; 4]; w];
    let mut depths = vec![0f32; w];
    let mut stencils = Vec::new();
    for z in 0..r.depth as usize {
        for y in 0..r.height as usize {
            let Some(offset) = client.row_offset(y, z) else { continue };
            let Some(row) = bytes.get(offset - span_start..) else { continue };
            let start = image.index(r.x as usize, r.y as usize + y, r.z as usize + z);
            match &mut image.texels {
                Texels::Rgba8(t) => {
                    if cf == ClientFormat::StencilIndex {
                        let first_bit = client.first_bit();
                        unpack.indices.unpack_row(ct, swap, unpack.lsb_first, first_bit, row, &mut colors);
                    } else {
                        unpack_color_row(cf, ct, swap, row, &mut colors);
                    }
                    for (k, c) in colors.iter().enumerate() {
                        t[start + k] = texel8(info, *c);
                    }
                }
                Texels::Depth(_) if cf == ClientFormat::DepthStencil && ct == ClientType::Float32UnsignedInt24_8Rev => {
                    for (k, pixel) in row.chunks_exact(8).take(w).enumerate() {
                        let (depth, index) = crate::pixel::depth::unpack_depth_stencil_float(pixel, swap);
                        image.set_depth_f32(start + k, depth);
                        image.set_stencil(start + k, index);
                    }
                }
                Texels::Depth(_) if cf == ClientFormat::DepthStencil => {
                    // Depth-stencil data gives a depth-only image its depth alone.
                    stencils.resize(w, 0);
                    let n = unpack_depth_stencil_row(swap, row, &mut depths, &mut stencils);
                    for k in 0..n {
                        image.set_depth_f32(start + k, depths[k]);
                        image.set_stencil(start + k, stencils[k]);
                    }
                }
                Texels::Depth(_) => {
                    unpack_depth_row(ct, swap, row, &mut depths);
                    for (k, &d) in depths.iter().enumerate() {
                        image.set_depth_f32(start + k, d);
                    }
                }
            }
        }
    }
}

/// Regenerates every level below the base level of `face` from it, down to 1×1.
fn generate_mipmaps(obj: &mut TextureObject, face: usize, dims: usize) -> Result<(), crate::texture::OutOfMemory> {
    let base = obj.params.base_level.max(0) as usize;
    let Some(base_level) = obj.level(face, base).cloned() else {
        return Ok(());
    };
    let Some(mut image) = base_level.image.clone() else {
        return Ok(());
    };
    let mut level = base;
    let mut current = base_level;
    while current.width > 1 || current.height > 1 || current.depth > 1 {
        let next = Arc::new(crate::texture::downsample(&image, dims)?);
        level += 1;
        let new = Level {
            image: Some(next.clone()),
            width: next.width,
            height: next.height,
            depth: next.depth,
            border: 0,
            ..current.clone()
        };
        let levels = &mut obj.faces[face];
        if levels.len() <= level {
            levels.resize(level + 1, None);
        }
        levels[level] = Some(new.clone());
        image = next;
        current = new;
    }
    Ok(())
}

/// Packs `count` texels of `image` from index `start` as `format`/`ty` (glGetTexImage).
/// The texels are first given the components GL 2.1 §6.1.4 returns for their base format
/// (luminance and intensity as (L, 0, 0, 1), alpha as (0, 0, 0, A)), and luminance is read
/// back from R. 8-bit texels convert to other integer sizes by Mesa's bit replication
/// (`unorm_to_unorm`) and to float as `u · (1/255)`; depth converts from float.
fn pack_texels_row(
    image: &TexImage,
    start: usize,
    count: usize,
    format: ClientFormat,
    ty: ClientType,
    swap: bool,
    out: &mut [u8],
) {
    use crate::pixel::convert::{float_to_half, float_to_snorm, float_to_unorm, unorm_to_float, unorm_to_unorm};
    let put = |out: &mut [u8], bytes: &[u8]| {
        let n = bytes.len();
        out[..n].copy_from_slice(bytes);
        if swap {
            out[..n].reverse();
        }
    };
    let channels: &[usize] = match format {
        ClientFormat::Luminance | ClientFormat::DepthComponent => &[0],
        ClientFormat::LuminanceAlpha => &[0, 3],
        f => f.color_channels(),
    };
    let pixel_bytes = ty.pixel_bytes(format);
    // A texel as 8-bit values (color) or a float (depth), in the returned components.
    let texel = |i: usize| -> Result<[u8; 4], f32> {
        match &image.texels {
            Texels::Rgba8(t) => {
                let c = t[start + i];
                Ok(match image.base {
                    BaseFormat::Luminance | BaseFormat::Intensity => [c[0], 0, 0, 255],
                    BaseFormat::LuminanceAlpha => [c[0], 0, 0, c[3]],
                    _ => c,
                })
            }
            Texels::Depth(_) => Err(image.depth_f32(start + i)),
        }
    };
    for i in 0..count {
        let t = texel(i);
        let o = &mut out[i * pixel_bytes..(i + 1) * pixel_bytes];
        match ty {
            ClientType::Packed(p) => {
                let mut word = 0u32;
                for ((&ch, &bits), shift) in channels.iter().zip(p.component_bits()).zip(p.shifts()) {
                    let field = match t {
                        Ok(c) => unorm_to_unorm(c[ch] as u32, 8, bits),
                        Err(d) => float_to_unorm(d, bits),
                    };
                    word |= field << shift;
                }
                match p.bytes() {
                    1 => o[0] = word as u8,
                    2 => put(o, &(word as u16).to_ne_bytes()),
                    _ => put(o, &word.to_ne_bytes()),
                }
            }
            _ => {
                let size = ty.element_bytes();
                for (k, &ch) in channels.iter().enumerate() {
                    let slot = &mut o[k * size..(k + 1) * size];
                    match t {
                        Ok(c) => {
                            let v = c[ch] as u32;
                            match ty {
                                ClientType::UnsignedByte => slot[0] = v as u8,
                                ClientType::Byte => slot[0] = unorm_to_unorm(v, 8, 7) as u8,
                                ClientType::UnsignedShort => {
                                    put(slot, &(unorm_to_unorm(v, 8, 16) as u16).to_ne_bytes())
                                }
                                ClientType::Short => put(slot, &(unorm_to_unorm(v, 8, 15) as u16).to_ne_bytes()),
                                ClientType::UnsignedInt => put(slot, &unorm_to_unorm(v, 8, 32).to_ne_bytes()),
                                ClientType::Int => put(slot, &unorm_to_unorm(v, 8, 31).to_ne_bytes()),
                                ClientType::Float => put(slot, &unorm_to_float(v, 8).to_ne_bytes()),
                                ClientType::HalfFloat => put(slot, &float_to_half(unorm_to_float(v, 8)).to_ne_bytes()),
                                _ => {}
                            }
                        }
                        Err(d) => match ty {
                            ClientType::UnsignedByte => slot[0] = float_to_unorm(d, 8) as u8,
                            ClientType::Byte => slot[0] = float_to_snorm(d, 8) as i8 as u8,
                            ClientType::UnsignedShort => put(slot, &(float_to_unorm(d, 16) as u16).to_ne_bytes()),
                            ClientType::Short => put(slot, &(float_to_snorm(d, 16) as i16).to_ne_bytes()),
                            ClientType::UnsignedInt => put(slot, &float_to_unorm(d, 32).to_ne_bytes()),
                            ClientType::Int => put(slot, &float_to_snorm(d, 32).to_ne_bytes()),
                            ClientType::Float => put(slot, &d.to_ne_bytes()),
                            ClientType::HalfFloat => put(slot, &float_to_half(d).to_ne_bytes()),
                            _ => {}
                        },
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_stencil_formats_are_depth_images_with_stencil() {
        for f in [GL_DEPTH_STENCIL, GL_DEPTH24_STENCIL8] {
            let info = format_info(f as i32).unwrap();
            assert_eq!((info.base, info.bits[0], info.sizes[6], info.sizes[7]), (BaseFormat::Depth, 24, 24, 8));
            assert!(info.has_stencil());
            assert!(data_fits(ClientFormat::DepthStencil, &info) && data_fits(ClientFormat::DepthComponent, &info));
            assert!(!data_fits(ClientFormat::Rgba, &info));
            assert!(new_image(2, 2, 1, 0, &info).unwrap().has_stencil());
        }
        let depth = format_info(GL_DEPTH_COMPONENT24 as i32).unwrap();
        assert!(!depth.has_stencil() && data_fits(ClientFormat::DepthStencil, &depth));
        assert!(!new_image(2, 2, 1, 0, &depth).unwrap().has_stencil());
        let color = format_info(GL_RGBA8 as i32).unwrap();
        assert!(!data_fits(ClientFormat::DepthStencil, &color) && !data_fits(ClientFormat::DepthComponent, &color));
    }

    #[test]
    fn depth_stencil_data_needs_the_packed_type() {
        assert_eq!(
            check_texture_format_type(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8),
            Ok((ClientFormat::DepthStencil, ClientType::UnsignedInt24_8))
        );
        assert_eq!(check_texture_format_type(GL_DEPTH_STENCIL, GL_UNSIGNED_INT), Err(GL_INVALID_ENUM));
        assert_eq!(check_texture_format_type(GL_RGBA, GL_UNSIGNED_INT_24_8), Err(GL_INVALID_OPERATION));
        assert_eq!(check_texture_format_type(GL_STENCIL_INDEX, GL_UNSIGNED_BYTE), Err(GL_INVALID_OPERATION));
    }
}
