//! The component types that vertex commands and arrays take, and their conversion to the
//! floats a [`Vertex`](super::Vertex) holds.
//!
//! Two conversions exist. Positions, texture coordinates, fog coordinates and color indices
//! convert an integer to the float of the same value ([`Component::to_f32`]). Colors,
//! secondary colors and normals given as integers are normalized fixed-point values
//! ([`Component::normalized`]), converted as table 2.9 of the GL 2.1 specification says:
//! an unsigned `c` of `b` bits becomes `c / (2^b − 1)`, a signed one `(2c + 1) / (2^b − 1)`.
//! The arithmetic is Mesa 22's (`BYTE_TO_FLOAT` and friends), bit for bit: the signed types
//! multiply by the reciprocal in single precision, GLubyte divides, GLushort multiplies by the
//! single-precision reciprocal, and GLuint multiplies in double precision. All 2¹⁶ GLshort and
//! GLushort values and 400 000 GLint/GLuint values were compared with
//! `glGetFloatv(GL_CURRENT_COLOR)` on Mesa.
//!
//! Arrays use the same conversions as the immediate-mode commands, as the GL 2.1
//! specification says. (Mesa 22's llvmpipe draws signed normalized arrays with the later
//! `max(c / (2^(b−1) − 1), −1)` rule and GLubyte arrays as `c · (1/255)`; its glArrayElement
//! uses table 2.9 like tessera. The difference is at most one unit of an 8-bit channel.)
use crate::gl::enums::*;
use crate::gl::types::GLenum;

/// A GL component type: how to read one from memory and convert it to a float.
pub trait Component: Copy {
    /// The value as a float of the same magnitude (positions, texture coordinates).
    fn to_f32(self) -> f32;
    /// The value as a normalized fixed-point number (colors, normals); floats are unchanged.
    fn normalized(self) -> f32;
    /// Reads one value from native-endian bytes (zero when `bytes` is too short).
    fn from_bytes(bytes: &[u8]) -> Self;
}

/// The first `N` bytes of `bytes`, zero-filled when it is shorter.
fn leading<const N: usize>(bytes: &[u8]) -> [u8; N] {
    let mut array = [0; N];
    if let Some(prefix) = bytes.get(..N) {
        array.copy_from_slice(prefix);
    }
    array
}

impl Component for i8 {
    fn to_f32(self) -> f32 {
        self as f32
    }
    fn normalized(self) -> f32 {
        (2.0 * self as f32 + 1.0) * (1.0 / 255.0)
    }
    fn from_bytes(bytes: &[u8]) -> Self {
        i8::from_ne_bytes(leading(bytes))
    }
}

impl Component for u8 {
    fn to_f32(self) -> f32 {
        self as f32
    }
    fn normalized(self) -> f32 {
        self as f32 / 255.0
    }
    fn from_bytes(bytes: &[u8]) -> Self {
        u8::from_ne_bytes(leading(bytes))
    }
}

impl Component for i16 {
    fn to_f32(self) -> f32 {
        self as f32
    }
    fn normalized(self) -> f32 {
        (2.0 * self as f32 + 1.0) * (1.0 / 65535.0)
    }
    fn from_bytes(bytes: &[u8]) -> Self {
        i16::from_ne_bytes(leading(bytes))
    }
}

impl Component for u16 {
    fn to_f32(self) -> f32 {
        self as f32
    }
    fn normalized(self) -> f32 {
        self as f32 * (1.0 / 65535.0)
    }
    fn from_bytes(bytes: &[u8]) -> Self {
        u16::from_ne_bytes(leading(bytes))
    }
}

impl Component for i32 {
    fn to_f32(self) -> f32 {
        self as f32
    }
    fn normalized(self) -> f32 {
        // 2³² − 1 rounds to 2³² in single precision, as in Mesa's INT_TO_FLOAT.
        (2.0 * self as f32 + 1.0) * (1.0 / 4294967295.0)
    }
    fn from_bytes(bytes: &[u8]) -> Self {
        i32::from_ne_bytes(leading(bytes))
    }
}

impl Component for u32 {
    fn to_f32(self) -> f32 {
        self as f32
    }
    fn normalized(self) -> f32 {
        (self as f64 * (1.0 / 4294967295.0)) as f32
    }
    fn from_bytes(bytes: &[u8]) -> Self {
        u32::from_ne_bytes(leading(bytes))
    }
}

impl Component for f32 {
    fn to_f32(self) -> f32 {
        self
    }
    fn normalized(self) -> f32 {
        self
    }
    fn from_bytes(bytes: &[u8]) -> Self {
        f32::from_ne_bytes(leading(bytes))
    }
}

impl Component for f64 {
    fn to_f32(self) -> f32 {
        self as f32
    }
    fn normalized(self) -> f32 {
        self as f32
    }
    fn from_bytes(bytes: &[u8]) -> Self {
        f64::from_ne_bytes(leading(bytes))
    }
}

/// The component types of vertex arrays (GL 2.1 table 2.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ComponentType {
    Byte,
    UnsignedByte,
    Short,
    UnsignedShort,
    Int,
    UnsignedInt,
    Float,
    Double,
}

impl ComponentType {
    pub fn from_gl(e: GLenum) -> Option<Self> {
        Some(match e {
            GL_BYTE => Self::Byte,
            GL_UNSIGNED_BYTE => Self::UnsignedByte,
            GL_SHORT => Self::Short,
            GL_UNSIGNED_SHORT => Self::UnsignedShort,
            GL_INT => Self::Int,
            GL_UNSIGNED_INT => Self::UnsignedInt,
            GL_FLOAT => Self::Float,
            GL_DOUBLE => Self::Double,
            _ => return None,
        })
    }

    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Byte => GL_BYTE,
            Self::UnsignedByte => GL_UNSIGNED_BYTE,
            Self::Short => GL_SHORT,
            Self::UnsignedShort => GL_UNSIGNED_SHORT,
            Self::Int => GL_INT,
            Self::UnsignedInt => GL_UNSIGNED_INT,
            Self::Float => GL_FLOAT,
            Self::Double => GL_DOUBLE,
        }
    }

    /// Bytes of one component.
    pub fn size(self) -> usize {
        match self {
            Self::Byte | Self::UnsignedByte => 1,
            Self::Short | Self::UnsignedShort => 2,
            Self::Int | Self::UnsignedInt | Self::Float => 4,
            Self::Double => 8,
        }
    }
}

/// Decodes one array element: `size` components from the element's bytes, the components
/// the array does not hold taken from (0, 0, 0, 1).
pub type Decoder = fn(bytes: &[u8], size: usize) -> [f32; 4];

fn decode<T: Component, const NORMALIZED: bool>(bytes: &[u8], size: usize) -> [f32; 4] {
    let mut values = [0.0, 0.0, 0.0, 1.0];
    let width = std::mem::size_of::<T>();
    // Component by component over the four slots, not a loop over the element's bytes: for
    // floats that loop is a copy, which LLVM may turn into a call to memcpy of a variable
    // length, several times the cost of the (at most four) loads.
    for (i, value) in values.iter_mut().enumerate() {
        if i < size {
            if let Some(chunk) = bytes.get(i * width..(i + 1) * width) {
                let component = T::from_bytes(chunk);
                *value = if NORMALIZED { component.normalized() } else { component.to_f32() };
            }
        }
    }
    values
}

/// The decoder for elements of `component`, normalized (colors, normals) or not. Chosen once
/// per array and draw, so the per-vertex loop does not branch on the type.
pub fn decoder(component: ComponentType, normalized: bool) -> Decoder {
    use ComponentType::*;
    match (component, normalized) {
        (Byte, false) => decode::<i8, false>,
        (Byte, true) => decode::<i8, true>,
        (UnsignedByte, false) => decode::<u8, false>,
        (UnsignedByte, true) => decode::<u8, true>,
        (Short, false) => decode::<i16, false>,
        (Short, true) => decode::<i16, true>,
        (UnsignedShort, false) => decode::<u16, false>,
        (UnsignedShort, true) => decode::<u16, true>,
        (Int, false) => decode::<i32, false>,
        (Int, true) => decode::<i32, true>,
        (UnsignedInt, false) => decode::<u32, false>,
        (UnsignedInt, true) => decode::<u32, true>,
        (Float, _) => decode::<f32, false>,
        (Double, _) => decode::<f64, false>,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signed_bytes_map_to_odd_multiples_of_one_255th() {
        assert_eq!((-128i8).normalized(), -1.0);
        assert_eq!(127i8.normalized(), 1.0);
        // Values measured on Mesa 22 (glColor3b, glGetFloatv), as bit patterns.
        assert_eq!((-127i8).normalized().to_bits(), 0xbf7dfdff);
        assert_eq!(0i8.normalized().to_bits(), 0x3b808081);
        assert_eq!(1i8.normalized().to_bits(), 0x3c40c0c2);
        assert_eq!(64i8.normalized().to_bits(), 0x3f018182);
    }

    #[test]
    fn unsigned_bytes_divide_and_unsigned_shorts_multiply() {
        assert_eq!(0u8.normalized(), 0.0);
        assert_eq!(255u8.normalized(), 1.0);
        // 3/255 by division is 0x3c40c0c1; Mesa's reciprocal product would be ...c2.
        assert_eq!(3u8.normalized().to_bits(), 0x3c40c0c1);
        assert_eq!(65535u16.normalized(), 1.0);
        // 257 · (1/65535) rounds below 1/255.
        assert_eq!(257u16.normalized().to_bits(), 0x3b808080);
    }

    #[test]
    fn shorts_and_ints() {
        assert_eq!((-32768i16).normalized(), -1.0);
        assert_eq!(32767i16.normalized(), 1.0);
        assert_eq!(1i16.normalized().to_bits(), 0x384000c0);
        assert_eq!(i32::MIN.normalized(), -1.0);
        assert_eq!(i32::MAX.normalized(), 1.0);
        assert_eq!(0i32.normalized(), 2.0f32.powi(-32));
        assert_eq!(1i32.normalized(), 3.0 * 2.0f32.powi(-32));
        // Rounded to single precision before the product: 2147483583 → 1 − 2⁻²⁴.
        assert_eq!(2147483583i32.normalized().to_bits(), 0x3f7fffff);
    }

    #[test]
    fn unsigned_ints_multiply_in_double_precision() {
        assert_eq!(0u32.normalized(), 0.0);
        assert_eq!(1u32.normalized(), 2.0f32.powi(-32));
        assert_eq!(u32::MAX.normalized(), 1.0);
        // In single precision 4294967167 would round down to 2³² − 256 first.
        assert_eq!(4294967167u32.normalized(), 1.0);
        assert_eq!(4294967040u32.normalized().to_bits(), 0x3f7fffff);
        assert_eq!(2147483647u32.normalized(), 0.5);
    }

    #[test]
    fn decoders_fill_missing_components_from_0_0_0_1() {
        let bytes: Vec<u8> = [-2i16, 7].iter().flat_map(|v| v.to_ne_bytes()).collect();
        assert_eq!(decoder(ComponentType::Short, false)(&bytes, 2), [-2.0, 7.0, 0.0, 1.0]);
        let n = decoder(ComponentType::Short, true)(&bytes, 2);
        assert_eq!(n, [(-3.0f32) * (1.0 / 65535.0), 15.0 * (1.0 / 65535.0), 0.0, 1.0]);
        let doubles: Vec<u8> = [0.1f64, 2.5, -3.0].iter().flat_map(|v| v.to_ne_bytes()).collect();
        assert_eq!(decoder(ComponentType::Double, true)(&doubles, 3), [0.1f64 as f32, 2.5, -3.0, 1.0]);
        let ubytes = [255u8, 0, 51, 102];
        assert_eq!(decoder(ComponentType::UnsignedByte, true)(&ubytes, 4), [1.0, 0.0, 0.2, 0.4]);
        assert_eq!(decoder(ComponentType::UnsignedByte, false)(&ubytes, 1), [255.0, 0.0, 0.0, 1.0]);
        // A short element (out of a buffer's range) reads what is there, the rest defaults.
        assert_eq!(decoder(ComponentType::Float, false)(&1.5f32.to_ne_bytes(), 3), [1.5, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn component_types_round_trip_their_enums() {
        for e in [GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE]
        {
            assert_eq!(ComponentType::from_gl(e).map(ComponentType::to_gl), Some(e));
        }
        assert_eq!(ComponentType::from_gl(GL_HALF_FLOAT), None);
        assert_eq!(ComponentType::from_gl(GL_2_BYTES), None);
        assert_eq!(ComponentType::Double.size(), 8);
        assert_eq!(ComponentType::UnsignedShort.size(), 2);
    }
}
