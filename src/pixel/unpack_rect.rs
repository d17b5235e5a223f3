//! Unpacking client pixels for glDrawPixels (and glBitmap's bits): one pixel's components
//! of a format/type pair to floats.
//!
//! Unsigned normalized types map [0, 2ⁿ−1] onto [0, 1]; signed types map c to
//! max(c / (2ⁿ⁻¹−1), −1), as Mesa 22 does; floats are taken as they are.
//!
//! The element conversions are the texture unpacker's ([`super::unpack`]); packed fields keep
//! their full precision here (textures narrow them to 8 bits), fields narrower than 8 bits
//! widening to 8 as Mesa 22 stores them.
use super::convert::unorm_to_unorm;
use super::unpack::{component, packed_word};
use super::{ClientFormat, ClientType};

/// The components of one pixel of `format`/`ty` starting at `bytes`, in memory order (the
/// format's component order); `out` gets `format.components()` values.
pub fn unpack_components(bytes: &[u8], format: ClientFormat, ty: ClientType, swap: bool, out: &mut [f32]) {
    let count = format.components();
    if let ClientType::Packed(packed) = ty {
        let value = packed_word(bytes, packed.bytes(), swap);
        for ((o, &bits), shift) in out.iter_mut().zip(packed.component_bits()).zip(packed.shifts()) {
            let max = (1u32 << bits) - 1;
            let v = (value >> shift) & max;
            *o = if bits < 8 { unorm_to_unorm(v, bits, 8) as f32 / 255.0 } else { v as f32 / max as f32 };
        }
        return;
    }
    let size = ty.element_bytes();
    for (i, o) in out.iter_mut().take(count).enumerate() {
        *o = component(ty, &bytes[i * size..], swap);
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
    use crate::pixel::unpack::half_to_float;
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
        assert_eq!(unorm_to_unorm(28, 5, 8), 231);
        assert_eq!(unorm_to_unorm(12, 6, 8), 48);
        assert_eq!(unorm_to_unorm(2, 2, 8), 0xaa);
        assert_eq!(unorm_to_unorm(1, 1, 8), 255);
        assert_eq!(unorm_to_unorm(5, 3, 8), 0b1011_0110);
        assert_eq!(half_to_float(0x3c00), 1.0);
        assert_eq!(half_to_float(0xc000), -2.0);
    }
}
