//! Packing rows of color buffer pixels into client color formats, byte for byte as Mesa 22's
//! glReadPixels (`read_rgba_pixels` → `_mesa_format_convert`) does.
//!
//! A [`ColorPlan`] is decided once per call from the buffer format, the client format/type,
//! the clamping rule and the byte order; rows then go through at most three row-wide steps,
//! none of which matches on formats per pixel:
//! 1. a *stage* that presents the buffer's values the way Mesa's conversion sees them: as
//!    they are (8-bit, 16-bit or float), clamped, or through Mesa's intermediate (8-bit for
//!    packed types of at most 8 bits per component, float for the rest, luminance as the
//!    float sum R + G + B);
//! 2. a conversion of each channel to the client type, produced as the value's bit pattern
//!    (8-bit stages through a 256-entry table built per call);
//! 3. the store: components in the client order (or fields of a packed element), native byte
//!    order or swapped.
//!
//! The common cases skip all of this: RGBA/BGRA/RGB/BGR bytes from an 8-bit buffer, and
//! reads in the buffer's own format, are row copies or swizzles.
//!
//! Where Mesa's intermediates lose precision they are reproduced on purpose, because tessera
//! must give the same bytes: 16-bit buffers read as packed types of ≤ 8-bit components round
//! twice (16 → 8 → n bits); 5/6/5 buffers read as anything but 8-bit components go through
//! float (`c · (1/31)`), so GL_UNSIGNED_INT of 5-bit 1 is 0x08421080, not 0x08421084; float
//! values packed into the packed types round half up, not to even (see [`float_to_field`]);
//! 8-bit values widen to 10 bits by replication (43 → 172, where 43/255 · 1023 = 172.5), as
//! Mesa does for GL_RGBA buffers (it rounds correctly for OSMESA_BGRA ones, which tessera's
//! buffers cannot tell apart).
use super::convert::{float_to_half, float_to_snorm, float_to_unorm, unorm_max, unorm_to_float, unorm_to_unorm};
use super::{ClientFormat, ClientType, PackedType};
use crate::framebuffer::surface::ColorRow;
use crate::framebuffer::ColorFormat;

/// How the buffer's values are presented to the conversion (Mesa's intermediate).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stage {
    /// 8-bit values as stored.
    Unorm8,
    /// 16-bit values as stored.
    Unorm16,
    /// Float values as stored (clamped, if at all, by the conversion).
    Float,
    /// 16-bit values narrowed to 8 bits first.
    Unorm16To8,
    /// 16-bit values as floats.
    Unorm16ToFloat,
    /// 5/6/5 values widened to 8 bits (alpha 255).
    Rgb565To8,
    /// 5/6/5 values as floats (alpha 1).
    Rgb565ToFloat,
    /// Channel 0 is R + G + B as floats, channel 3 alpha; clamped to [0, 1] or not.
    Luminance { clamp: bool },
}

/// A client scalar type: its size and conversions, which return the value's bit pattern in
/// the low `SIZE` bytes.
trait Scalar {
    const SIZE: usize;
    fn from_unorm(value: u32, bits: u32) -> u32;
    fn from_float(value: f32) -> u32;
}

struct U8;
struct I8;
struct U16;
struct I16;
struct U32;
struct I32;
struct F32;
struct F16;

impl Scalar for U8 {
    const SIZE: usize = 1;
    fn from_unorm(value: u32, bits: u32) -> u32 {
        unorm_to_unorm(value, bits, 8)
    }
    fn from_float(value: f32) -> u32 {
        float_to_unorm(value, 8)
    }
}

impl Scalar for I8 {
    const SIZE: usize = 1;
    fn from_unorm(value: u32, bits: u32) -> u32 {
        unorm_to_unorm(value, bits, 7)
    }
    fn from_float(value: f32) -> u32 {
        float_to_snorm(value, 8) as u32
    }
}

impl Scalar for U16 {
    const SIZE: usize = 2;
    fn from_unorm(value: u32, bits: u32) -> u32 {
        unorm_to_unorm(value, bits, 16)
    }
    fn from_float(value: f32) -> u32 {
        float_to_unorm(value, 16)
    }
}

impl Scalar for I16 {
    const SIZE: usize = 2;
    fn from_unorm(value: u32, bits: u32) -> u32 {
        unorm_to_unorm(value, bits, 15)
    }
    fn from_float(value: f32) -> u32 {
        float_to_snorm(value, 16) as u32
    }
}

impl Scalar for U32 {
    const SIZE: usize = 4;
    fn from_unorm(value: u32, bits: u32) -> u32 {
        unorm_to_unorm(value, bits, 32)
    }
    fn from_float(value: f32) -> u32 {
        float_to_unorm(value, 32)
    }
}

impl Scalar for I32 {
    const SIZE: usize = 4;
    fn from_unorm(value: u32, bits: u32) -> u32 {
        unorm_to_unorm(value, bits, 31)
    }
    fn from_float(value: f32) -> u32 {
        float_to_snorm(value, 32) as u32
    }
}

impl Scalar for F32 {
    const SIZE: usize = 4;
    fn from_unorm(value: u32, bits: u32) -> u32 {
        unorm_to_float(value, bits).to_bits()
    }
    fn from_float(value: f32) -> u32 {
        value.to_bits()
    }
}

impl Scalar for F16 {
    const SIZE: usize = 2;
    fn from_unorm(value: u32, bits: u32) -> u32 {
        float_to_half(unorm_to_float(value, bits)) as u32
    }
    fn from_float(value: f32) -> u32 {
        float_to_half(value) as u32
    }
}

/// Converts and stores a row of 16-bit pixels, the components named by the channel list.
type ShortEmitter = fn(&[[u16; 4]], &[usize], &mut [u8]);
/// Converts and stores a row of float pixels.
type FloatEmitter = fn(&[[f32; 4]], &[usize], &mut [u8]);

/// The conversions of one array type, as function pointers chosen once per call (each a
/// loop monomorphized for the type, the byte order and the clamping).
#[derive(Clone, Copy)]
struct ArrayConversions {
    size: usize,
    unorm: fn(u32, u32) -> u32,
    shorts: ShortEmitter,
    floats: FloatEmitter,
}

fn array_conversions_of<T: Scalar>(swap: bool, clamp: bool) -> ArrayConversions {
    let shorts: ShortEmitter = if swap { emit_shorts::<T, true> } else { emit_shorts::<T, false> };
    let floats: FloatEmitter = match (swap, clamp) {
        (false, false) => emit_floats::<T, false, false>,
        (false, true) => emit_floats::<T, false, true>,
        (true, false) => emit_floats::<T, true, false>,
        (true, true) => emit_floats::<T, true, true>,
    };
    ArrayConversions { size: T::SIZE, unorm: T::from_unorm, shorts, floats }
}

fn array_conversions(ty: ClientType, swap: bool, clamp: bool) -> Option<ArrayConversions> {
    Some(match ty {
        ClientType::UnsignedByte => array_conversions_of::<U8>(swap, clamp),
        ClientType::Byte => array_conversions_of::<I8>(swap, clamp),
        ClientType::UnsignedShort => array_conversions_of::<U16>(swap, clamp),
        ClientType::Short => array_conversions_of::<I16>(swap, clamp),
        ClientType::UnsignedInt => array_conversions_of::<U32>(swap, clamp),
        ClientType::Int => array_conversions_of::<I32>(swap, clamp),
        ClientType::Float => array_conversions_of::<F32>(swap, clamp),
        ClientType::HalfFloat => array_conversions_of::<F16>(swap, clamp),
        _ => return None,
    })
}

/// What one pixel becomes.
enum Target {
    /// One value per component, in the order of `channels`.
    Array { channels: &'static [usize], conv: ArrayConversions },
    /// All components in one `bytes`-byte element; `bits`/`shifts` are per RGBA channel
    /// (unused channels have 0 bits). `half_up`: how float values round (see [`float_to_field`]).
    Packed { bits: [u32; 4], shifts: [u32; 4], bytes: usize, half_up: bool },
}

/// A per-call shortcut that needs no conversion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shortcut {
    /// The 8-bit row's bytes as they are.
    Rgba8,
    /// The 8-bit row with red and blue exchanged.
    Bgra8,
    /// The 8-bit row's first three bytes, in this order.
    Rgb8([usize; 3]),
    /// The row's values in native byte order, as stored (16-bit RGBA, float RGBA, 5_6_5).
    Native,
}

/// Reusable row buffers of a transfer (allocated once per call, not per row).
#[derive(Default)]
pub struct ColorScratch {
    bytes: Vec<[u8; 4]>,
    floats: Vec<[f32; 4]>,
}

/// How to pack every row of one glReadPixels call.
pub struct ColorPlan {
    stage: Stage,
    target: Target,
    shortcut: Option<Shortcut>,
    swap_bytes: bool,
    /// For 8-bit stages: the converted value of every 8-bit input, per RGBA channel.
    table: Option<Box<[[u32; 256]; 4]>>,
}

impl ColorPlan {
    /// The plan for reading a buffer of `source` format as `format`/`ty`. `clamp` says whether
    /// values are clamped to [0, 1] (Mesa's IMAGE_CLAMP_BIT: GL_CLAMP_READ_COLOR in effect, or
    /// a non-float type). `None` if `format`/`ty` is not a color format/type pair (the
    /// context has validated them before).
    pub fn new(
        source: ColorFormat,
        format: ClientFormat,
        ty: ClientType,
        clamp: bool,
        swap_bytes: bool,
    ) -> Option<ColorPlan> {
        let channels = format.color_channels();
        if channels.is_empty() {
            return None;
        }
        let luminance = matches!(format, ClientFormat::Luminance | ClientFormat::LuminanceAlpha);
        // Only values straight from a float buffer may still need clamping here: luminance
        // clamps itself, every other stage is within [0, 1].
        let clamp_floats = clamp && !luminance && source.is_float();
        let target = match ty {
            ClientType::Packed(packed) if packed.accepts(format) => packed_target(packed, channels),
            _ => Target::Array { channels, conv: array_conversions(ty, swap_bytes, clamp_floats)? },
        };
        let packed_bits = match &target {
            Target::Packed { bits, .. } => bits.iter().copied().max(),
            Target::Array { .. } => None,
        };
        let stage = if luminance {
            Stage::Luminance { clamp }
        } else {
            match source {
                ColorFormat::Unorm8 { .. } => Stage::Unorm8,
                ColorFormat::Unorm16 { .. } => match packed_bits {
                    None => Stage::Unorm16,
                    Some(bits) if bits <= 8 => Stage::Unorm16To8,
                    Some(_) => Stage::Unorm16ToFloat,
                },
                ColorFormat::Float32 { .. } => Stage::Float,
                ColorFormat::Rgb565 => match packed_bits {
                    None if ty == ClientType::UnsignedByte => Stage::Rgb565To8,
                    Some(bits) if bits <= 8 => Stage::Rgb565To8,
                    _ => Stage::Rgb565ToFloat,
                },
            }
        };
        let shortcut =
            if swap_bytes && ty.element_bytes() > 1 { None } else { shortcut(stage, format, ty, clamp_floats) };
        let eight_bit = matches!(stage, Stage::Unorm8 | Stage::Unorm16To8 | Stage::Rgb565To8);
        let table = (eight_bit && shortcut.is_none()).then(|| eight_bit_table(&target));
        Some(ColorPlan { stage, target, shortcut, swap_bytes, table })
    }

    /// Bytes one pixel takes in client memory.
    pub fn pixel_bytes(&self) -> usize {
        match &self.target {
            Target::Array { channels, conv } => channels.len() * conv.size,
            Target::Packed { bytes, .. } => *bytes,
        }
    }

    /// Packs one row of pixels into `out` (exactly `row.len()` pixels long).
    pub fn pack_row(&self, row: ColorRow<'_>, out: &mut [u8], scratch: &mut ColorScratch) {
        if let Some(shortcut) = self.shortcut {
            return copy_row(shortcut, row, out);
        }
        let swap = self.swap_bytes;
        match (self.stage_row(row, &mut scratch.bytes, &mut scratch.floats), &self.target, &self.table) {
            (Staged::Bytes(px), Target::Array { channels, conv }, Some(table)) => match (conv.size, swap) {
                (1, _) => emit_table::<1, false>(px, table, channels, out),
                (2, false) => emit_table::<2, false>(px, table, channels, out),
                (2, true) => emit_table::<2, true>(px, table, channels, out),
                (_, false) => emit_table::<4, false>(px, table, channels, out),
                (_, true) => emit_table::<4, true>(px, table, channels, out),
            },
            (Staged::Bytes(px), Target::Packed { shifts, bytes, .. }, Some(table)) => match (*bytes, swap) {
                (1, _) => emit_packed_table::<1, false>(px, table, shifts, out),
                (2, false) => emit_packed_table::<2, false>(px, table, shifts, out),
                (2, true) => emit_packed_table::<2, true>(px, table, shifts, out),
                (_, false) => emit_packed_table::<4, false>(px, table, shifts, out),
                (_, true) => emit_packed_table::<4, true>(px, table, shifts, out),
            },
            (Staged::Shorts(px), Target::Array { channels, conv }, _) => (conv.shorts)(px, channels, out),
            (Staged::Floats(px), Target::Array { channels, conv }, _) => (conv.floats)(px, channels, out),
            (Staged::Floats(px), Target::Packed { bits, shifts, bytes, half_up }, _) => {
                let fields = |p: &[f32; 4]| {
                    let field = |c: usize| float_to_field(p[c], bits[c], *half_up) << shifts[c];
                    field(0) | field(1) | field(2) | field(3)
                };
                match (*bytes, swap) {
                    (1, _) => emit_words::<1, false>(px, fields, out),
                    (2, false) => emit_words::<2, false>(px, fields, out),
                    (2, true) => emit_words::<2, true>(px, fields, out),
                    (_, false) => emit_words::<4, false>(px, fields, out),
                    (_, true) => emit_words::<4, true>(px, fields, out),
                }
            }
            // Other pairs are never planned.
            _ => {}
        }
    }

    /// The row as the conversion sees it.
    fn stage_row<'a>(
        &self,
        row: ColorRow<'a>,
        bytes: &'a mut Vec<[u8; 4]>,
        floats: &'a mut Vec<[f32; 4]>,
    ) -> Staged<'a> {
        match (self.stage, row) {
            (Stage::Unorm8, ColorRow::Unorm8(px)) => Staged::Bytes(px),
            (Stage::Unorm16, ColorRow::Unorm16(px)) => Staged::Shorts(px),
            (Stage::Float, ColorRow::Float32(px)) => Staged::Floats(px),
            (Stage::Unorm16To8, ColorRow::Unorm16(px)) => {
                refill(bytes, px.iter().map(|p| p.map(|c| unorm_to_unorm(c as u32, 16, 8) as u8)));
                Staged::Bytes(bytes)
            }
            (Stage::Unorm16ToFloat, ColorRow::Unorm16(px)) => {
                refill(floats, px.iter().map(|p| p.map(|c| unorm_to_float(c as u32, 16))));
                Staged::Floats(floats)
            }
            (Stage::Rgb565To8, ColorRow::Rgb565(px)) => {
                refill(
                    bytes,
                    px.iter().map(|&p| {
                        let [r, g, b] = split565(p);
                        [
                            unorm_to_unorm(r, 5, 8) as u8,
                            unorm_to_unorm(g, 6, 8) as u8,
                            unorm_to_unorm(b, 5, 8) as u8,
                            255,
                        ]
                    }),
                );
                Staged::Bytes(bytes)
            }
            (Stage::Rgb565ToFloat, ColorRow::Rgb565(px)) => {
                refill(floats, px.iter().map(|&p| float565(p)));
                Staged::Floats(floats)
            }
            (Stage::Luminance { clamp }, row) => {
                luminance_row(row, clamp, floats);
                Staged::Floats(floats)
            }
            // The plan was made for another buffer format: nothing sensible to write.
            _ => Staged::Floats(&[]),
        }
    }
}

/// A staged row.
enum Staged<'a> {
    Bytes(&'a [[u8; 4]]),
    Shorts(&'a [[u16; 4]]),
    Floats(&'a [[f32; 4]]),
}

/// Replaces the contents of `buffer` (keeping its allocation).
fn refill<T>(buffer: &mut Vec<T>, items: impl Iterator<Item = T>) {
    buffer.clear();
    buffer.extend(items);
}

/// A float → packed field of `bits` bits (0: unused). Mesa packs float values into the packed
/// types (other than 8_8_8_8) with gallium's format packers, which round half up
/// (`(int)(x · max + 0.5)` in single precision) where its other conversions round half to even:
/// 0.3 is 4.5 of 4 bits and packs as 5, 0.5 packs as 1 in a 1-bit field.
#[inline]
fn float_to_field(value: f32, bits: u32, half_up: bool) -> u32 {
    if bits == 0 {
        0
    } else if half_up {
        // NaN passes the clamp and `as` makes it 0, as the C conversion leaves it.
        (clamp01(value) * unorm_max(bits) as f32 + 0.5) as u32
    } else {
        float_to_unorm(value, bits)
    }
}

/// Mesa's IMAGE_CLAMP_BIT clamp (`CLAMP`): NaN passes through.
#[inline]
fn clamp01(value: f32) -> f32 {
    value.clamp(0.0, 1.0)
}

#[inline]
fn split565(pixel: u16) -> [u32; 3] {
    let p = pixel as u32;
    [p >> 11, (p >> 5) & 63, p & 31]
}

/// A 5/6/5 pixel as Mesa's float unpacker gives it.
#[inline]
fn float565(pixel: u16) -> [f32; 4] {
    let [r, g, b] = split565(pixel);
    [unorm_to_float(r, 5), unorm_to_float(g, 6), unorm_to_float(b, 5), 1.0]
}

/// Luminance rows: Mesa reads L = R + G + B (in this order, in single precision) from the
/// pixels as floats, clamped to [0, 1] with the channels when `clamp` (glGetTexImage uses
/// L = R; glReadPixels does not).
fn luminance_row(row: ColorRow<'_>, clamp: bool, out: &mut Vec<[f32; 4]>) {
    let lum = |p: [f32; 4]| {
        let p = if clamp { p.map(clamp01) } else { p };
        let sum = p[0] + p[1] + p[2];
        [if clamp { clamp01(sum) } else { sum }, 0.0, 0.0, p[3]]
    };
    match row {
        ColorRow::Unorm8(px) => refill(out, px.iter().map(|p| lum(p.map(|c| unorm_to_float(c as u32, 8))))),
        ColorRow::Unorm16(px) => refill(out, px.iter().map(|p| lum(p.map(|c| unorm_to_float(c as u32, 16))))),
        ColorRow::Float32(px) => refill(out, px.iter().map(|&p| lum(p))),
        ColorRow::Rgb565(px) => refill(out, px.iter().map(|&p| lum(float565(p)))),
    }
}

/// The packed target of `packed` for a format whose components hold `channels`.
fn packed_target(packed: PackedType, channels: &[usize]) -> Target {
    let mut bits = [0; 4];
    let mut shifts = [0; 4];
    for ((&channel, &b), s) in channels.iter().zip(packed.component_bits()).zip(packed.shifts()) {
        bits[channel] = b;
        shifts[channel] = s;
    }
    let half_up = !matches!(packed, PackedType::UnsignedInt8888 | PackedType::UnsignedInt8888Rev);
    Target::Packed { bits, shifts, bytes: packed.bytes(), half_up }
}

/// For 8-bit stages: every 8-bit input converted, per channel (packed: the field value).
fn eight_bit_table(target: &Target) -> Box<[[u32; 256]; 4]> {
    let mut table = Box::new([[0u32; 256]; 4]);
    for (channel, entries) in table.iter_mut().enumerate() {
        for (v, entry) in entries.iter_mut().enumerate() {
            *entry = match target {
                Target::Array { conv, .. } => (conv.unorm)(v as u32, 8),
                Target::Packed { bits, .. } if bits[channel] > 0 => unorm_to_unorm(v as u32, 8, bits[channel]),
                Target::Packed { .. } => 0,
            };
        }
    }
    table
}

/// The shortcut for reads that need no conversion, if any.
fn shortcut(stage: Stage, format: ClientFormat, ty: ClientType, clamp_floats: bool) -> Option<Shortcut> {
    use ClientFormat::*;
    match (stage, format, ty) {
        (Stage::Unorm8, Rgba, ClientType::UnsignedByte) => Some(Shortcut::Rgba8),
        (Stage::Unorm8, Bgra, ClientType::UnsignedByte) => Some(Shortcut::Bgra8),
        (Stage::Unorm8, Rgb, ClientType::UnsignedByte) => Some(Shortcut::Rgb8([0, 1, 2])),
        (Stage::Unorm8, Bgr, ClientType::UnsignedByte) => Some(Shortcut::Rgb8([2, 1, 0])),
        (Stage::Unorm16, Rgba, ClientType::UnsignedShort) => Some(Shortcut::Native),
        (Stage::Float, Rgba, ClientType::Float) if !clamp_floats => Some(Shortcut::Native),
        (Stage::Rgb565To8, Rgb, ClientType::Packed(PackedType::UnsignedShort565)) => Some(Shortcut::Native),
        _ => None,
    }
}

/// Performs a shortcut.
fn copy_row(shortcut: Shortcut, row: ColorRow<'_>, out: &mut [u8]) {
    match (shortcut, row) {
        (Shortcut::Rgba8, ColorRow::Unorm8(px)) => out.copy_from_slice(px.as_flattened()),
        (Shortcut::Bgra8, ColorRow::Unorm8(px)) => {
            for (o, p) in out.chunks_exact_mut(4).zip(px) {
                // Exchange bytes 0 and 2 of the pixel as one word.
                let v = u32::from_le_bytes(*p);
                let swapped = (v & 0xff00_ff00) | ((v & 0xff) << 16) | ((v >> 16) & 0xff);
                o.copy_from_slice(&swapped.to_le_bytes());
            }
        }
        (Shortcut::Rgb8(order), ColorRow::Unorm8(px)) => {
            for (o, p) in out.chunks_exact_mut(3).zip(px) {
                o.copy_from_slice(&[p[order[0]], p[order[1]], p[order[2]]]);
            }
        }
        (Shortcut::Native, ColorRow::Unorm16(px)) => {
            for (o, v) in out.chunks_exact_mut(2).zip(px.as_flattened()) {
                o.copy_from_slice(&v.to_ne_bytes());
            }
        }
        (Shortcut::Native, ColorRow::Float32(px)) => {
            for (o, v) in out.chunks_exact_mut(4).zip(px.as_flattened()) {
                o.copy_from_slice(&v.to_ne_bytes());
            }
        }
        (Shortcut::Native, ColorRow::Rgb565(px)) => {
            for (o, v) in out.chunks_exact_mut(2).zip(px) {
                o.copy_from_slice(&v.to_ne_bytes());
            }
        }
        _ => {}
    }
}

/// Writes the low `SIZE` bytes of `value` in native byte order, or reversed.
#[inline(always)]
fn put<const SIZE: usize, const SWAP: bool>(out: &mut [u8], value: u32) {
    let bytes = value.to_ne_bytes();
    let low = if cfg!(target_endian = "little") { &bytes[..SIZE] } else { &bytes[4 - SIZE..] };
    for (i, o) in out[..SIZE].iter_mut().enumerate() {
        *o = if SWAP { low[SIZE - 1 - i] } else { low[i] };
    }
}

/// `put` for a scalar type's size (the match folds away once `T` is known).
#[inline(always)]
fn put_scalar<T: Scalar, const SWAP: bool>(out: &mut [u8], value: u32) {
    match T::SIZE {
        1 => put::<1, SWAP>(out, value),
        2 => put::<2, SWAP>(out, value),
        _ => put::<4, SWAP>(out, value),
    }
}

fn emit_shorts<T: Scalar, const SWAP: bool>(src: &[[u16; 4]], channels: &[usize], out: &mut [u8]) {
    for (o, p) in out.chunks_exact_mut(channels.len() * T::SIZE).zip(src) {
        for (slot, &c) in o.chunks_exact_mut(T::SIZE).zip(channels) {
            put_scalar::<T, SWAP>(slot, T::from_unorm(p[c] as u32, 16));
        }
    }
}

fn emit_floats<T: Scalar, const SWAP: bool, const CLAMP: bool>(src: &[[f32; 4]], channels: &[usize], out: &mut [u8]) {
    for (o, p) in out.chunks_exact_mut(channels.len() * T::SIZE).zip(src) {
        for (slot, &c) in o.chunks_exact_mut(T::SIZE).zip(channels) {
            let v = if CLAMP { clamp01(p[c]) } else { p[c] };
            put_scalar::<T, SWAP>(slot, T::from_float(v));
        }
    }
}

fn emit_table<const SIZE: usize, const SWAP: bool>(
    src: &[[u8; 4]],
    table: &[[u32; 256]; 4],
    channels: &[usize],
    out: &mut [u8],
) {
    for (o, p) in out.chunks_exact_mut(channels.len() * SIZE).zip(src) {
        for (slot, &c) in o.chunks_exact_mut(SIZE).zip(channels) {
            put::<SIZE, SWAP>(slot, table[c][p[c] as usize]);
        }
    }
}

fn emit_packed_table<const SIZE: usize, const SWAP: bool>(
    src: &[[u8; 4]],
    table: &[[u32; 256]; 4],
    shifts: &[u32; 4],
    out: &mut [u8],
) {
    for (o, p) in out.chunks_exact_mut(SIZE).zip(src) {
        // Unused channels' table entries are 0, so their (zero) shift adds nothing.
        let word = (table[0][p[0] as usize] << shifts[0])
            | (table[1][p[1] as usize] << shifts[1])
            | (table[2][p[2] as usize] << shifts[2])
            | (table[3][p[3] as usize] << shifts[3]);
        put::<SIZE, SWAP>(o, word);
    }
}

fn emit_words<const SIZE: usize, const SWAP: bool>(src: &[[f32; 4]], word: impl Fn(&[f32; 4]) -> u32, out: &mut [u8]) {
    for (o, p) in out.chunks_exact_mut(SIZE).zip(src) {
        put::<SIZE, SWAP>(o, word(p));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(
        source: ColorFormat,
        row: ColorRow,
        format: ClientFormat,
        ty: ClientType,
        clamp: bool,
        swap: bool,
    ) -> Vec<u8> {
        let plan = ColorPlan::new(source, format, ty, clamp, swap).unwrap();
        let mut out = vec![0xcd; plan.pixel_bytes() * row.len()];
        plan.pack_row(row, &mut out, &mut ColorScratch::default());
        out
    }

    const RGBA8: ColorFormat = ColorFormat::Unorm8 { alpha: true };
    const RGBA16: ColorFormat = ColorFormat::Unorm16 { alpha: true };
    const RGBAF: ColorFormat = ColorFormat::Float32 { alpha: true };

    fn words32(bytes: &[u8]) -> Vec<u32> {
        bytes.chunks_exact(4).map(|c| u32::from_ne_bytes(c.try_into().unwrap())).collect()
    }

    fn words16(bytes: &[u8]) -> Vec<u16> {
        bytes.chunks_exact(2).map(|c| u16::from_ne_bytes(c.try_into().unwrap())).collect()
    }

    #[test]
    fn eight_bit_shortcuts_copy_and_swizzle() {
        let px = [[1, 2, 3, 4], [5, 6, 7, 8]];
        let row = ColorRow::Unorm8(&px);
        use ClientFormat::*;
        assert_eq!(read(RGBA8, row, Rgba, ClientType::UnsignedByte, false, false), [1, 2, 3, 4, 5, 6, 7, 8]);
        assert_eq!(read(RGBA8, row, Bgra, ClientType::UnsignedByte, false, true), [3, 2, 1, 4, 7, 6, 5, 8]);
        assert_eq!(read(RGBA8, row, Bgr, ClientType::UnsignedByte, false, false), [3, 2, 1, 7, 6, 5]);
        assert_eq!(read(RGBA8, row, Alpha, ClientType::UnsignedByte, false, false), [4, 8]);
        assert_eq!(read(RGBA8, row, Green, ClientType::Byte, false, false), [1, 3]);
    }

    #[test]
    fn eight_bit_reads_match_mesa_measurements() {
        // glClearColor(1, 0.5, 0, 0.2) of an RGBA8 buffer read on Mesa 22.
        let px = [[255, 128, 0, 51]];
        let row = ColorRow::Unorm8(&px);
        use ClientFormat::Rgba;
        let uint = read(RGBA8, row, Rgba, ClientType::UnsignedInt, false, false);
        assert_eq!(words32(&uint), [0xffff_ffff, 0x8080_8080, 0, 0x3333_3333]);
        let int = read(RGBA8, row, Rgba, ClientType::Int, false, false);
        assert_eq!(words32(&int), [0x7fff_ffff, 0x4040_4040, 0, 0x1999_9999]);
        let short = read(RGBA8, row, Rgba, ClientType::Short, false, false);
        assert_eq!(words16(&short), [0x7fff, 0x4040, 0, 0x1999]);
        assert_eq!(read(RGBA8, row, Rgba, ClientType::Byte, false, false), [0x7f, 0x40, 0, 0x19]);
        let float = read(RGBA8, row, Rgba, ClientType::Float, false, false);
        assert_eq!(words32(&float), [0x3f80_0000, 0x3f00_8081, 0, 0x3e4c_ccce]);
        let ushort = read(RGBA8, row, Rgba, ClientType::UnsignedShort, false, true);
        assert_eq!(words16(&ushort), [0xffff, 0x8080, 0, 0x3333]);
        // Luminance is R + G + B, clamped (fixed-point buffer) or not.
        let lum = read(RGBA8, row, ClientFormat::Luminance, ClientType::Float, false, false);
        assert_eq!(words32(&lum), [0x3fc0_4040]);
        let lum = read(RGBA8, row, ClientFormat::LuminanceAlpha, ClientType::UnsignedByte, true, false);
        assert_eq!(lum, [255, 51]);
    }

    #[test]
    fn packed_types_place_fields() {
        let px = [[135, 120, 8, 247]];
        let row = ColorRow::Unorm8(&px);
        use ClientFormat::*;
        use PackedType::*;
        let p = |format, ty| read(RGBA8, row, format, ClientType::Packed(ty), false, false);
        // Measured on Mesa 22 (glClearColor(0.53, 0.47, 0.03, 0.97), RGBA8).
        assert_eq!(words32(&p(Rgba, UnsignedInt1010102)), [0x879e_1083]);
        assert_eq!(words32(&p(Rgba, UnsignedInt2101010Rev)), [0xc207_861e]);
        assert_eq!(words32(&p(Rgba, UnsignedInt8888)), [0x8778_08f7]);
        assert_eq!(words32(&p(Rgba, UnsignedInt8888Rev)), [0xf708_7887]);
        assert_eq!(words16(&p(Rgba, UnsignedShort4444)), [0x870f]);
        assert_eq!(words16(&p(Rgba, UnsignedShort4444Rev)), [0xf078]);
        assert_eq!(words16(&p(Rgba, UnsignedShort5551)), [0x83c3]);
        assert_eq!(words16(&p(Rgba, UnsignedShort1555Rev)), [0x85f0]);
        assert_eq!(p(Rgb, UnsignedByte332), [0x8c]);
        assert_eq!(p(Rgb, UnsignedByte233Rev), [0x1c]);
        assert_eq!(words16(&p(Rgb, UnsignedShort565)), [0x83c1]);
        assert_eq!(words16(&p(Rgb, UnsignedShort565Rev)), [0x0bd0]);
        assert_eq!(words32(&p(Bgra, UnsignedInt1010102)), [0x081e_187b]);
        // Swapped bytes of a 16-bit element.
        let swapped = read(RGBA8, row, Rgba, ClientType::Packed(UnsignedShort4444), false, true);
        assert_eq!(swapped, 0x870f_u16.to_be_bytes());
    }

    #[test]
    fn sixteen_bit_buffers_round_twice_for_small_packed_fields() {
        // Mesa narrows 16-bit values to 8 bits before packing fields of at most 8 bits:
        // 0x124a is 3-bit 1 directly (1.0003) but 8-bit 18 → 3-bit 0 (0.494); 0x0422 is 5-bit
        // 1 directly (0.5005) but 8-bit 4 → 5-bit 0 (0.486).
        let px = [[0x124a, 0x0000, 0x0422, 0xffff]];
        let row = ColorRow::Unorm16(&px);
        let out = read(RGBA16, row, ClientFormat::Rgb, ClientType::Packed(PackedType::UnsignedByte332), false, false);
        assert_eq!(out, [0x00]);
        let px = [[0x0000, 0x0000, 0x0422, 0xffff]];
        let row = ColorRow::Unorm16(&px);
        let out =
            read(RGBA16, row, ClientFormat::Bgra, ClientType::Packed(PackedType::UnsignedShort5551), false, false);
        assert_eq!(words16(&out), [0x0001]);
        // Fields wider than 8 bits go through float instead: 0x5555 → 2 bits: 1.
        let px = [[0, 0, 0, 0x5555]];
        let row = ColorRow::Unorm16(&px);
        let out =
            read(RGBA16, row, ClientFormat::Rgba, ClientType::Packed(PackedType::UnsignedInt1010102), false, false);
        assert_eq!(words32(&out), [1]);
    }

    #[test]
    fn floats_pack_half_up_except_into_8888() {
        use PackedType::*;
        // 0.3 · 15 and 0.7 · 15 are 4.5 and 10.5 in single precision; measured on Mesa 22.
        let px = [[0.3, 0.7, 0.5, 2.5 / 255.0]];
        let row = ColorRow::Float32(&px);
        let p = |ty| read(RGBAF, row, ClientFormat::Rgba, ClientType::Packed(ty), true, false);
        assert_eq!(words16(&p(UnsignedShort4444)), [0x5b80]);
        assert_eq!(words16(&p(UnsignedShort5551)), [(9 << 11) | (22 << 6) | (16 << 1)]);
        // 8_8_8_8 rounds to even: 76.5 → 76, 178.5 → 178, 2.5 → 2.
        assert_eq!(words32(&p(UnsignedInt8888)), [0x4cb2_8002]);
        // 16-bit 19763 is 308.5 of 10 bits through float: 309.
        let px = [[19763, 0, 0, 0]];
        let out = read(
            RGBA16,
            ColorRow::Unorm16(&px),
            ClientFormat::Rgba,
            ClientType::Packed(UnsignedInt1010102),
            false,
            false,
        );
        assert_eq!(words32(&out), [309 << 22]);
    }

    #[test]
    fn rgb565_goes_through_float_except_for_bytes() {
        // r = 1, g = 1, b = 3 (glClearColor(1/31, 1/63, 3/31)); measured on Mesa 22.
        let px = [0x0823u16];
        let row = ColorRow::Rgb565(&px);
        use ClientFormat::*;
        let source = ColorFormat::Rgb565;
        assert_eq!(read(source, row, Rgba, ClientType::UnsignedByte, false, false), [0x08, 0x04, 0x18, 0xff]);
        let ushort = read(source, row, Rgba, ClientType::UnsignedShort, false, false);
        assert_eq!(words16(&ushort), [0x0842, 0x0410, 0x18c6, 0xffff]);
        let uint = read(source, row, Rgba, ClientType::UnsignedInt, false, false);
        // Mesa 22 gives 0 for the alpha (1.0 overflows); tessera saturates.
        assert_eq!(words32(&uint), [0x0842_1080, 0x0410_4108, 0x18c6_3180, 0xffff_ffff]);
        let int = read(source, row, Rgba, ClientType::Int, false, false);
        assert_eq!(words32(&int), [0x0421_0840, 0x0208_2084, 0x0c63_18c0, 0x7fff_ffff]);
        let float = read(source, row, Rgba, ClientType::Float, false, false);
        assert_eq!(words32(&float), [0x3d04_2108, 0x3c82_0821, 0x3dc6_318c, 0x3f80_0000]);
        assert_eq!(read(source, row, Rgb, ClientType::Packed(PackedType::UnsignedShort565), false, true), [0x08, 0x23]);
    }

    #[test]
    fn float_buffers_clamp_only_when_asked() {
        let px = [[1.0, 0.5, 2.0, -0.5]];
        let row = ColorRow::Float32(&px);
        use ClientFormat::*;
        let raw = read(RGBAF, row, Rgba, ClientType::Float, false, false);
        assert_eq!(words32(&raw), [1.0f32, 0.5, 2.0, -0.5].map(f32::to_bits));
        let clamped = read(RGBAF, row, Rgba, ClientType::Float, true, false);
        assert_eq!(words32(&clamped), [1.0f32, 0.5, 1.0, 0.0].map(f32::to_bits));
        assert_eq!(read(RGBAF, row, Rgba, ClientType::Byte, true, false), [0x7f, 0x40, 0x7f, 0]);
        assert_eq!(read(RGBAF, row, Rgba, ClientType::HalfFloat, true, false), [0, 0x3c, 0, 0x38, 0, 0x3c, 0, 0]);
        let lum = read(RGBAF, row, Luminance, ClientType::Float, false, false);
        assert_eq!(words32(&lum), [3.5f32.to_bits()]);
        let lum = read(RGBAF, row, Luminance, ClientType::Float, true, false);
        assert_eq!(words32(&lum), [1.0f32.to_bits()]);
    }
}
