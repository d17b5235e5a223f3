//! Unpacking client pixels for glDrawPixels (and glBitmap's bits): one pixel's components
//! of a format/type pair to floats.
//!
//! Unsigned normalized types map [0, 2ⁿ−1] onto [0, 1]; signed types map c to
//! max(c / (2ⁿ⁻¹−1), −1), as Mesa 22 does; floats are taken as they are.
use super::{ClientFormat, ClientType};

/// Reads `n` bytes at `at` as one element, honouring GL_UNPACK_SWAP_BYTES.
fn element(bytes: &[u8], n: usize, swap: bool) -> u32 {
    let mut value = 0u32;
    for k in 0..n {
        let b = if swap { bytes[n - 1 - k] } else { bytes[k] };
        value |= (b as u32) << (8 * if cfg!(target_endian = "little") { k } else { n - 1 - k });
    }
    value
}

/// A component narrower than 8 bits widened to 8 by repeating its bits, as Mesa 22 does when
/// it stores packed pixels in an 8-bit image (5-bit 28 → 231, 6-bit 12 → 48).
fn replicate_to_8_bits(v: u32, bits: u32) -> u32 {
    let (mut result, mut filled) = (0u32, 0u32);
    while filled < 8 {
        result = (result << bits) | v;
        filled += bits;
    }
    result >> (filled - 8)
}

fn half_to_float(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exponent = (h >> 10) & 0x1f;
    let mantissa = (h & 0x3ff) as f32;
    sign * match exponent {
        0 => mantissa * (2.0f32).powi(-24),
        31 if mantissa == 0.0 => f32::INFINITY,
        31 => f32::NAN,
        e => (1.0 + mantissa / 1024.0) * (2.0f32).powi(e as i32 - 15),
    }
}

/// The components of one pixel of `format`/`ty` starting at `bytes`, in memory order (the
/// format's component order); `out` gets `format.components()` values.
pub fn unpack_components(bytes: &[u8], format: ClientFormat, ty: ClientType, swap: bool, out: &mut [f32]) {
    let count = format.components();
    if let ClientType::Packed(packed) = ty {
        let value = element(bytes, packed.bytes(), swap);
        for ((o, &bits), shift) in out.iter_mut().zip(packed.component_bits()).zip(packed.shifts()) {
            let max = (1u32 << bits) - 1;
            let v = (value >> shift) & max;
            *o = if bits < 8 { replicate_to_8_bits(v, bits) as f32 / 255.0 } else { v as f32 / max as f32 };
        }
        return;
    }
    let size = ty.element_bytes();
    for (i, o) in out.iter_mut().take(count).enumerate() {
        let e = element(&bytes[i * size..], size, swap);
        *o = match ty {
            ClientType::UnsignedByte => e as f32 / 255.0,
            ClientType::Byte => (e as u8 as i8 as f32 / 127.0).max(-1.0),
            ClientType::UnsignedShort => e as f32 / 65535.0,
            ClientType::Short => (e as u16 as i16 as f32 / 32767.0).max(-1.0),
            ClientType::UnsignedInt => (e as f64 / 4294967295.0) as f32,
            ClientType::Int => ((e as i32 as f64 / 2147483647.0) as f32).max(-1.0),
            ClientType::Float => f32::from_bits(e),
            ClientType::HalfFloat => half_to_float(e as u16),
            _ => 0.0,
        };
    }
}

/// One pixel of a color format as RGBA: missing color channels are 0, missing alpha 1;
/// luminance goes to red, green and blue.
pub fn unpack_rgba(bytes: &[u8], format: ClientFormat, ty: ClientType, swap: bool) -> [f32; 4] {
    let mut components = [0.0f32; 4];
    unpack_components(bytes, format, ty, swap, &mut components);
    let mut rgba = [0.0, 0.0, 0.0, 1.0];
    if matches!(format, ClientFormat::Luminance | ClientFormat::LuminanceAlpha) {
        rgba[..3].fill(components[0]);
        if format == ClientFormat::LuminanceAlpha {
            rgba[3] = components[1];
        }
        return rgba;
    }
    for (&channel, &value) in format.color_channels().iter().zip(&components) {
        rgba[channel] = value;
    }
    rgba
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pixel::PackedType;

    #[test]
    fn formats_and_types_unpack_to_rgba() {
        let f = ClientFormat::Rgba;
        assert_eq!(unpack_rgba(&[255, 0, 51, 255], f, ClientType::UnsignedByte, false), [1.0, 0.0, 0.2, 1.0]);
        assert_eq!(unpack_rgba(&[0x80, 127, 0, 0], f, ClientType::Byte, false), [-1.0, 1.0, 0.0, 0.0]);
        assert_eq!(
            unpack_rgba(&[255, 0, 51], ClientFormat::Bgr, ClientType::UnsignedByte, false),
            [0.2, 0.0, 1.0, 1.0]
        );
        assert_eq!(
            unpack_rgba(&[51, 102], ClientFormat::LuminanceAlpha, ClientType::UnsignedByte, false),
            [0.2, 0.2, 0.2, 0.4]
        );
        assert_eq!(unpack_rgba(&[51], ClientFormat::Alpha, ClientType::UnsignedByte, false), [0.0, 0.0, 0.0, 0.2]);
        let swapped = 0.5f32.to_be_bytes();
        let native = 0.5f32.to_ne_bytes();
        let swap = swapped != native;
        assert_eq!(unpack_rgba(&swapped, ClientFormat::Red, ClientType::Float, swap)[0], 0.5);
        // 5-6-5: red in the high bits.
        let rgb565 = (31u16 << 11 | 3 << 5 | 1).to_ne_bytes();
        let packed = ClientType::Packed(PackedType::UnsignedShort565);
        assert_eq!(unpack_rgba(&rgb565, ClientFormat::Rgb, packed, false), [1.0, 12.0 / 255.0, 8.0 / 255.0, 1.0]);
        assert_eq!(replicate_to_8_bits(28, 5), 231);
        assert_eq!(replicate_to_8_bits(12, 6), 48);
        assert_eq!(replicate_to_8_bits(2, 2), 0xaa);
        assert_eq!(replicate_to_8_bits(1, 1), 255);
        assert_eq!(replicate_to_8_bits(5, 3), 0b1011_0110);
        assert_eq!(half_to_float(0x3c00), 1.0);
        assert_eq!(half_to_float(0xc000), -2.0);
    }
}
