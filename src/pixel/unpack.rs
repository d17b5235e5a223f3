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
        e => sign * (1.0 + mantissa / 1024.0) * (2.0f32).powi(e - 15),
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
