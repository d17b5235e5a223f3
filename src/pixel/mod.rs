//! GL pixel transfer: the client-side formats and types of glReadPixels (and later
//! glDrawPixels/glTexImage), and packing rows of framebuffer values into client memory
//! with the glPixelStore layout rules.
//!
//! This room knows no GL enums: the context validates `format` and `type` and hands over a
//! [`ClientFormat`], a [`ClientType`] and the [`PackModes`] as plain values.
//! - [`layout`]: where each pixel of a client image lives (alignment, row length, skips) and
//!   which bytes a transfer touches;
//! - [`convert`]: the scalar conversions, bit-exact with Mesa 22's;
//! - [`color`]: rows of color buffer pixels → client color formats;
//! - [`depth`]: rows of depth and stencil values → depth, stencil and depth/stencil formats.
#![deny(unsafe_code)]

pub mod color;
pub mod convert;
pub mod depth;
pub mod layout;
pub mod unpack;
pub mod unpack_rect;

/// A client pixel format (the `format` of glReadPixels).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClientFormat {
    Rgba,
    Bgra,
    Rgb,
    Bgr,
    Red,
    Green,
    Blue,
    Alpha,
    Luminance,
    LuminanceAlpha,
    DepthComponent,
    StencilIndex,
    DepthStencil,
}

impl ClientFormat {
    /// Components per pixel.
    pub fn components(self) -> usize {
        use ClientFormat::*;
        match self {
            Rgba | Bgra => 4,
            Rgb | Bgr => 3,
            LuminanceAlpha => 2,
            Red | Green | Blue | Alpha | Luminance | DepthComponent | StencilIndex => 1,
            // One packed element (GL_UNSIGNED_INT_24_8).
            DepthStencil => 1,
        }
    }

    /// For color formats, the RGBA channel each component holds, in memory order. Luminance
    /// formats name channel 0, where the color packer puts the computed luminance.
    pub fn color_channels(self) -> &'static [usize] {
        use ClientFormat::*;
        match self {
            Rgba => &[0, 1, 2, 3],
            Bgra => &[2, 1, 0, 3],
            Rgb => &[0, 1, 2],
            Bgr => &[2, 1, 0],
            Red | Luminance => &[0],
            Green => &[1],
            Blue => &[2],
            Alpha => &[3],
            LuminanceAlpha => &[0, 3],
            DepthComponent | StencilIndex | DepthStencil => &[],
        }
    }

    pub fn is_color(self) -> bool {
        !matches!(self, ClientFormat::DepthComponent | ClientFormat::StencilIndex | ClientFormat::DepthStencil)
    }
}

/// A client data type (the `type` of glReadPixels).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClientType {
    UnsignedByte,
    Byte,
    UnsignedShort,
    Short,
    UnsignedInt,
    Int,
    Float,
    HalfFloat,
    Packed(PackedType),
    /// One bit per pixel (stencil indices only).
    Bitmap,
    /// GL_UNSIGNED_INT_24_8: depth in the high 24 bits, stencil in the low 8.
    UnsignedInt24_8,
    /// GL_FLOAT_32_UNSIGNED_INT_24_8_REV (ARB_depth_buffer_float): a float depth, then a
    /// 32-bit word with the stencil index in its low 8 bits (the other 24 unused).
    Float32UnsignedInt24_8Rev,
}

impl ClientType {
    /// Bytes of one component (array types) or one packed element; 0 for bitmaps.
    pub fn element_bytes(self) -> usize {
        use ClientType::*;
        match self {
            UnsignedByte | Byte => 1,
            UnsignedShort | Short | HalfFloat => 2,
            UnsignedInt | Int | Float | UnsignedInt24_8 => 4,
            Float32UnsignedInt24_8Rev => 8,
            Packed(p) => p.bytes(),
            Bitmap => 0,
        }
    }

    /// Whether values are floating point (and so may be read unclamped).
    pub fn is_float(self) -> bool {
        matches!(self, ClientType::Float | ClientType::HalfFloat)
    }

    /// Bytes per pixel of `format` in this type; 0 for bitmaps.
    pub fn pixel_bytes(self, format: ClientFormat) -> usize {
        match self {
            ClientType::Packed(_) | ClientType::UnsignedInt24_8 | ClientType::Float32UnsignedInt24_8Rev => {
                self.element_bytes()
            }
            _ => self.element_bytes() * format.components(),
        }
    }
}

/// The packed types: all components of a pixel in one 8-, 16- or 32-bit element.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PackedType {
    UnsignedByte332,
    UnsignedByte233Rev,
    UnsignedShort565,
    UnsignedShort565Rev,
    UnsignedShort4444,
    UnsignedShort4444Rev,
    UnsignedShort5551,
    UnsignedShort1555Rev,
    UnsignedInt8888,
    UnsignedInt8888Rev,
    UnsignedInt1010102,
    UnsignedInt2101010Rev,
}

impl PackedType {
    /// Bytes of one element.
    pub fn bytes(self) -> usize {
        use PackedType::*;
        match self {
            UnsignedByte332 | UnsignedByte233Rev => 1,
            UnsignedShort565 | UnsignedShort565Rev | UnsignedShort4444 | UnsignedShort4444Rev | UnsignedShort5551
            | UnsignedShort1555Rev => 2,
            UnsignedInt8888 | UnsignedInt8888Rev | UnsignedInt1010102 | UnsignedInt2101010Rev => 4,
        }
    }

    /// Bits of each component, in the format's component order.
    pub fn component_bits(self) -> &'static [u32] {
        use PackedType::*;
        match self {
            UnsignedByte332 | UnsignedByte233Rev => &[3, 3, 2],
            UnsignedShort565 | UnsignedShort565Rev => &[5, 6, 5],
            UnsignedShort4444 | UnsignedShort4444Rev => &[4, 4, 4, 4],
            UnsignedShort5551 | UnsignedShort1555Rev => &[5, 5, 5, 1],
            UnsignedInt8888 | UnsignedInt8888Rev => &[8, 8, 8, 8],
            UnsignedInt1010102 | UnsignedInt2101010Rev => &[10, 10, 10, 2],
        }
    }

    /// `_REV` types put the first component in the least significant bits, the others in the
    /// most significant.
    pub fn reversed(self) -> bool {
        use PackedType::*;
        matches!(
            self,
            UnsignedByte233Rev
                | UnsignedShort565Rev
                | UnsignedShort4444Rev
                | UnsignedShort1555Rev
                | UnsignedInt8888Rev
                | UnsignedInt2101010Rev
        )
    }

    /// The bit position of each component (format order).
    pub fn shifts(self) -> Vec<u32> {
        let bits = self.component_bits();
        let total = 8 * self.bytes() as u32;
        let mut below = 0;
        bits.iter()
            .map(|&b| {
                let shift = if self.reversed() { below } else { total - below - b };
                below += b;
                shift
            })
            .collect()
    }

    /// The widest component.
    pub fn max_bits(self) -> u32 {
        self.component_bits().iter().copied().max().unwrap_or(0)
    }

    /// Whether `format` may be packed in this type (GL_RGB for the 3-component types,
    /// GL_RGBA/GL_BGRA for the 4-component ones).
    pub fn accepts(self, format: ClientFormat) -> bool {
        match self.component_bits().len() {
            3 => format == ClientFormat::Rgb,
            _ => matches!(format, ClientFormat::Rgba | ClientFormat::Bgra),
        }
    }
}

/// The glPixelStore pack modes of one transfer (already validated).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PackModes {
    pub swap_bytes: bool,
    pub lsb_first: bool,
    /// Pixels per row of the client image; 0: the width of the transfer.
    pub row_length: usize,
    pub skip_rows: usize,
    pub skip_pixels: usize,
    /// 1, 2, 4 or 8.
    pub alignment: usize,
}

impl Default for PackModes {
    fn default() -> Self {
        PackModes { swap_bytes: false, lsb_first: false, row_length: 0, skip_rows: 0, skip_pixels: 0, alignment: 4 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packed_shifts_follow_the_gl_tables() {
        assert_eq!(PackedType::UnsignedByte332.shifts(), [5, 2, 0]);
        assert_eq!(PackedType::UnsignedByte233Rev.shifts(), [0, 3, 6]);
        assert_eq!(PackedType::UnsignedShort565.shifts(), [11, 5, 0]);
        assert_eq!(PackedType::UnsignedShort565Rev.shifts(), [0, 5, 11]);
        assert_eq!(PackedType::UnsignedShort5551.shifts(), [11, 6, 1, 0]);
        assert_eq!(PackedType::UnsignedShort1555Rev.shifts(), [0, 5, 10, 15]);
        assert_eq!(PackedType::UnsignedInt1010102.shifts(), [22, 12, 2, 0]);
        assert_eq!(PackedType::UnsignedInt2101010Rev.shifts(), [0, 10, 20, 30]);
        assert_eq!(PackedType::UnsignedInt8888Rev.shifts(), [0, 8, 16, 24]);
    }

    #[test]
    fn pixel_sizes() {
        assert_eq!(ClientType::Float.pixel_bytes(ClientFormat::Rgb), 12);
        assert_eq!(ClientType::HalfFloat.pixel_bytes(ClientFormat::LuminanceAlpha), 4);
        assert_eq!(ClientType::Packed(PackedType::UnsignedShort4444).pixel_bytes(ClientFormat::Bgra), 2);
        assert_eq!(ClientType::UnsignedInt24_8.pixel_bytes(ClientFormat::DepthStencil), 4);
        assert_eq!(ClientType::Float32UnsignedInt24_8Rev.pixel_bytes(ClientFormat::DepthStencil), 8);
        assert_eq!(ClientType::Bitmap.pixel_bytes(ClientFormat::StencilIndex), 0);
    }
}
