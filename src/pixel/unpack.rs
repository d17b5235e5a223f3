//! Unpacking client images (glTexImage*, glTexSubImage*): rows of client pixels in any
//! color or depth format and type → RGBA floats or depth floats, honouring the byte order.
//!
//! GL 2.1 §3.6.4: each group's components are converted to floats (unsigned normalized
//! integers `c / (2ⁿ − 1)`, signed ones `max(c / (2ⁿ⁻¹ − 1), −1)` as Mesa 22 does, floats as
//! they are), then extended to RGBA: missing R, G, B are 0, missing A is 1, and a luminance
//! value is copied to R, G and B. Where the client pixels lie (alignment, row length, skips)
//! is [`super::layout`]'s business; this module converts one row at a time.
use super::convert::{unorm_max, unorm_to_unorm};
use super::{ClientFormat, ClientType};

/// Reads the `N` bytes at the start of `bytes` as a native-endian integer, swapped first
/// when `swap` says so (GL_UNPACK_SWAP_BYTES).
#[inline]
pub(super) fn read_uint<const N: usize>(bytes: &[u8], swap: bool) -> u32 {
    let mut b = [0u8; N];
    b.copy_from_slice(&bytes[..N]);
    if swap {
        b.reverse();
    }
    match N {
        1 => b[0] as u32,
        2 => u16::from_ne_bytes([b[0], b[1]]) as u32,
        _ => u32::from_ne_bytes([b[0], b[1], b[2], b[3]]),
    }
}

/// The packed pixel of `size` bytes (1, 2 or 4) at the start of `bytes`.
#[inline]
pub(super) fn packed_word(bytes: &[u8], size: usize, swap: bool) -> u32 {
    match size {
        1 => bytes[0] as u32,
        2 => read_uint::<2>(bytes, swap),
        _ => read_uint::<4>(bytes, swap),
    }
}

/// IEEE binary16 → f32.
pub fn half_to_float(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0f32 } else { 1.0 };
    let exponent = ((h >> 10) & 0x1f) as i32;
    let mantissa = (h & 0x3ff) as f32;
    match exponent {
        0 => sign * mantissa * (2.0f32).powi(-24),
        0x1f if mantissa == 0.0 => sign * f32::INFINITY,
        0x1f => f32::NAN,
        // 2^(e − 15) from its exponent bits (e in 1 ..= 30): exact, and no powi call.
        e => sign * (1.0 + mantissa / 1024.0) * f32::from_bits(((e - 15 + 127) as u32) << 23),
    }
}

/// One component of an array type at the start of `bytes`, as a float.
#[inline]
pub(super) fn component(ty: ClientType, bytes: &[u8], swap: bool) -> f32 {
    match ty {
        ClientType::UnsignedByte => bytes[0] as f32 / 255.0,
        ClientType::Byte => (bytes[0] as i8 as f32 / 127.0).max(-1.0),
        ClientType::UnsignedShort => read_uint::<2>(bytes, swap) as f32 / 65535.0,
        ClientType::Short => (read_uint::<2>(bytes, swap) as u16 as i16 as f32 / 32767.0).max(-1.0),
        ClientType::UnsignedInt => (read_uint::<4>(bytes, swap) as f64 / 4_294_967_295.0) as f32,
        ClientType::Int => ((read_uint::<4>(bytes, swap) as i32 as f64 / 2_147_483_647.0) as f32).max(-1.0),
        ClientType::Float => f32::from_bits(read_uint::<4>(bytes, swap)),
        ClientType::HalfFloat => half_to_float(read_uint::<2>(bytes, swap) as u16),
        _ => 0.0,
    }
}

/// Unpacks `out.len()` pixels of a color `format`/`ty` from `row` (which starts at the first
/// pixel) to RGBA floats. The pair must have been validated (packed types with the formats
/// they accept).
pub fn unpack_color_row(format: ClientFormat, ty: ClientType, swap: bool, row: &[u8], out: &mut [[f32; 4]]) {
    let channels = format.color_channels();
    let luminance = matches!(format, ClientFormat::Luminance | ClientFormat::LuminanceAlpha);
    let pixel_bytes = ty.pixel_bytes(format);
    for (i, px) in out.iter_mut().enumerate() {
        let bytes = &row[i * pixel_bytes..];
        let mut rgba = [0.0, 0.0, 0.0, 1.0];
        match ty {
            ClientType::Packed(packed) => {
                let word = packed_word(bytes, packed.bytes(), swap);
                // Fields widen to 8 bits by replication (or narrow by rounding), as Mesa converts
                // packed data to 8-bit texels, then become floats that round back to them.
                for ((&channel, &bits), shift) in channels.iter().zip(packed.component_bits()).zip(packed.shifts()) {
                    let field = (word >> shift) & unorm_max(bits);
                    rgba[channel] = unorm_to_unorm(field, bits, 8) as f32 / 255.0;
                }
            }
            _ => {
                let size = ty.element_bytes();
                for (k, &channel) in channels.iter().enumerate() {
                    rgba[channel] = component(ty, &bytes[k * size..], swap);
                }
            }
        }
        if luminance {
            rgba[1] = rgba[0];
            rgba[2] = rgba[0];
        }
        *px = rgba;
    }
}

/// A color or stencil index of an integer or float type at the start of `bytes` (the
/// fraction of a float index is kept; the caller takes the integer part where GL does).
pub fn index_value(bytes: &[u8], ty: ClientType, swap: bool) -> f64 {
    let size = ty.element_bytes();
    let mut raw = [0u8; 4];
    raw[..size].copy_from_slice(&bytes[..size]);
    if swap {
        raw[..size].reverse();
    }
    match ty {
        ClientType::UnsignedByte => f64::from(raw[0]),
        ClientType::Byte => f64::from(raw[0] as i8),
        ClientType::UnsignedShort => f64::from(u16::from_ne_bytes([raw[0], raw[1]])),
        ClientType::Short => f64::from(i16::from_ne_bytes([raw[0], raw[1]])),
        ClientType::UnsignedInt => f64::from(u32::from_ne_bytes(raw)),
        ClientType::Int => f64::from(i32::from_ne_bytes(raw)),
        ClientType::Float => f64::from(f32::from_ne_bytes(raw)),
        ClientType::HalfFloat => f64::from(half_to_float(u16::from_ne_bytes([raw[0], raw[1]]))),
        _ => 0.0,
    }
}

/// Bit `bit` of a bitmap row's `byte` (`bit` counts within the row; GL_UNPACK_LSB_FIRST
/// numbers a byte's bits from its least significant one).
pub fn bitmap_bit(byte: u8, bit: usize, lsb_first: bool) -> bool {
    let mask = if lsb_first { 1 << (bit % 8) } else { 0x80 >> (bit % 8) };
    byte & mask != 0
}

/// Unpacks `depths.len()` GL_UNSIGNED_INT_24_8 depth/stencil pixels from `row`: depth in the
/// high 24 bits (to [0, 1]), stencil in the low 8 (into `stencils`, as far as it reaches).
/// Returns how many pixels `row` held (at most `depths.len()`).
pub fn unpack_depth_stencil_row(swap: bool, row: &[u8], depths: &mut [f32], stencils: &mut [u8]) -> usize {
    let mut count = 0;
    for (k, word) in row.chunks_exact(4).take(depths.len()).enumerate() {
        let word = read_uint::<4>(word, swap);
        depths[k] = super::convert::depth_to_float(word >> 8, 24);
        if let Some(s) = stencils.get_mut(k) {
            *s = word as u8;
        }
        count = k + 1;
    }
    count
}

/// Unpacks `out.len()` GL_DEPTH_COMPONENT values of type `ty` from `row`, clamped to [0, 1].
pub fn unpack_depth_row(ty: ClientType, swap: bool, row: &[u8], out: &mut [f32]) {
    let size = ty.element_bytes();
    for (i, d) in out.iter_mut().enumerate() {
        let bytes = &row[i * size..];
        let value = match ty {
            // Mesa unpacks 32-bit unsigned depth in double precision.
            ClientType::UnsignedInt => (read_uint::<4>(bytes, swap) as f64 / 4_294_967_295.0) as f32,
            _ => component(ty, bytes, swap),
        };
        *d = value.clamp(0.0, 1.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pixel::PackedType;

    #[test]
    fn indices_bits_and_depth_stencil_words() {
        assert_eq!(index_value(&[0xff], ClientType::Byte, false), -1.0);
        assert_eq!(
            index_value(&300u16.to_be_bytes(), ClientType::UnsignedShort, cfg!(target_endian = "little")),
            300.0
        );
        assert_eq!(index_value(&2.75f32.to_ne_bytes(), ClientType::Float, false), 2.75);
        assert!(bitmap_bit(0b1000_0000, 8, false) && !bitmap_bit(0b1000_0000, 8, true));
        assert!(bitmap_bit(0b0000_0010, 1, true));
        let words: Vec<u8> = [(0xffffffu32 << 8) | 7, 0x12].iter().flat_map(|w| w.to_ne_bytes()).collect();
        let (mut depths, mut stencils) = ([0.5f32; 3], [0u8; 1]);
        assert_eq!(unpack_depth_stencil_row(false, &words, &mut depths, &mut stencils), 2);
        assert_eq!((depths, stencils), ([1.0, 0.0, 0.5], [7]));
    }

    #[test]
    fn formats_extend_to_rgba() {
        let mut out = [[0.0; 4]; 1];
        unpack_color_row(ClientFormat::Luminance, ClientType::UnsignedByte, false, &[51], &mut out);
        assert_eq!(out[0], [0.2, 0.2, 0.2, 1.0]);
        unpack_color_row(ClientFormat::Bgra, ClientType::UnsignedByte, false, &[0, 51, 255, 0], &mut out);
        assert_eq!(out[0], [1.0, 0.2, 0.0, 0.0]);
        unpack_color_row(ClientFormat::Alpha, ClientType::Byte, false, &[0x81], &mut out);
        assert_eq!(out[0], [0.0, 0.0, 0.0, -1.0]);
        let word = 0xf800u16.to_ne_bytes();
        let ty = ClientType::Packed(PackedType::UnsignedShort565);
        unpack_color_row(ClientFormat::Rgb, ty, false, &word, &mut out);
        assert_eq!(out[0], [1.0, 0.0, 0.0, 1.0]);
        // Swapped bytes: 0x00f8 read as 0xf800 → only blue's low bits.
        unpack_color_row(ClientFormat::Rgb, ty, true, &word, &mut out);
        assert_eq!(out[0], [0.0, 28.0 / 255.0, 198.0 / 255.0, 1.0]);
        let word = 0x1122_33ffu32.to_ne_bytes();
        unpack_color_row(
            ClientFormat::Rgba,
            ClientType::Packed(PackedType::UnsignedInt8888Rev),
            false,
            &word,
            &mut out,
        );
        assert_eq!(out[0], [1.0, 0.2, 34.0 / 255.0, 17.0 / 255.0]);
    }

    #[test]
    fn depth_and_half() {
        let mut d = [0.0; 2];
        unpack_depth_row(ClientType::UnsignedShort, false, &[0xff, 0xff, 0, 0], &mut d);
        assert_eq!(d, [1.0, 0.0]);
        unpack_depth_row(ClientType::Float, false, &[0, 0, 0xc0, 0x3f, 0, 0, 0, 0x3f], &mut d);
        assert_eq!(d, [1.0, 0.5]);
        assert_eq!(half_to_float(0x3c00), 1.0);
        assert_eq!(half_to_float(0xb800), -0.5);
        assert_eq!(half_to_float(0x0001), 5.960_464_5e-8);
    }
}
