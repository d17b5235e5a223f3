//! Client vertex arrays: the state glVertexPointer and friends record, which formats each
//! array accepts, glInterleavedArrays' layouts, and which bytes a draw reads.
//!
//! A draw never reads client memory itself: it computes, per array, the one byte range its
//! indices reach ([`byte_extent`]) and asks a [`ClientMemory`] for it. The API edge implements
//! [`ClientMemory`] over raw pointers, so that is the only place where caller memory is
//! touched, and it only ever covers what GL's contract says the caller provides.
use super::components::{decoder, ComponentType, Decoder};
use crate::gl::enums::*;
use crate::gl::limits::{MAX_TEXTURE_COORDS, MAX_TEXTURE_UNITS, MAX_VERTEX_ATTRIBS};
use crate::gl::types::GLenum;

/// The fixed-function vertex arrays.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArrayId {
    Vertex,
    Normal,
    Color,
    SecondaryColor,
    FogCoord,
    Index,
    EdgeFlag,
    /// The texture coordinate array of a client texture unit.
    TexCoord(usize),
}

/// Which component types and counts an array accepts (GL 2.1 table 2.4).
struct Format {
    types: &'static [ComponentType],
    sizes: std::ops::RangeInclusive<i32>,
}

impl ArrayId {
    /// Whether integer components are normalized fixed-point values (colors, normals).
    pub fn normalized(self) -> bool {
        matches!(self, Self::Normal | Self::Color | Self::SecondaryColor)
    }

    fn format(self) -> Format {
        use ComponentType::*;
        const COLOR_TYPES: &[ComponentType] =
            &[Byte, UnsignedByte, Short, UnsignedShort, Int, UnsignedInt, Float, Double];
        match self {
            Self::Vertex => Format { types: &[Short, Int, Float, Double], sizes: 2..=4 },
            Self::Normal => Format { types: &[Byte, Short, Int, Float, Double], sizes: 3..=3 },
            Self::Color => Format { types: COLOR_TYPES, sizes: 3..=4 },
            // GL 2.1 allows size 3 only (Mesa 22, at GL 4.5, also takes 4 and GL_BGRA).
            Self::SecondaryColor => Format { types: COLOR_TYPES, sizes: 3..=3 },
            Self::FogCoord => Format { types: &[Float, Double], sizes: 1..=1 },
            Self::Index => Format { types: &[UnsignedByte, Short, Int, Float, Double], sizes: 1..=1 },
            Self::EdgeFlag => Format { types: &[UnsignedByte], sizes: 1..=1 },
            Self::TexCoord(_) => Format { types: &[Short, Int, Float, Double], sizes: 1..=4 },
        }
    }

    /// Validates a glXxxPointer call in Mesa's order: negative stride (GL_INVALID_VALUE),
    /// then the type (GL_INVALID_ENUM), then the size (GL_INVALID_VALUE). Returns the type.
    pub fn check_pointer(self, size: i32, type_: GLenum, stride: i32) -> Result<ComponentType, GLenum> {
        if stride < 0 {
            return Err(GL_INVALID_VALUE);
        }
        let format = self.format();
        let component = ComponentType::from_gl(type_).filter(|c| format.types.contains(c)).ok_or(GL_INVALID_ENUM)?;
        if !format.sizes.contains(&size) {
            return Err(GL_INVALID_VALUE);
        }
        Ok(component)
    }
}

/// One array as glXxxPointer and glEnableClientState leave it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArrayState {
    pub enabled: bool,
    /// Components per element.
    pub size: i32,
    pub component: ComponentType,
    /// As specified: 0 means tightly packed.
    pub stride: i32,
    /// A client address, or an offset into `buffer` when that is not 0.
    pub pointer: usize,
    /// GL_xxx_ARRAY_BUFFER_BINDING: the buffer bound to GL_ARRAY_BUFFER at glXxxPointer time.
    pub buffer: u32,
    /// The array's buffer was deleted: `pointer` is an offset into nothing, so draws that
    /// use the array draw nothing (GL leaves this undefined; Mesa 22 reads the offset as a
    /// client address).
    pub orphaned: bool,
    /// A generic attribute array's integer components are normalized fixed-point values
    /// (glVertexAttribPointer's `normalized`; the fixed-function arrays' rule is their
    /// [`ArrayId::normalized`]).
    pub normalized: bool,
}

impl ArrayState {
    fn new(size: i32) -> Self {
        ArrayState {
            enabled: false,
            size,
            component: ComponentType::Float,
            stride: 0,
            pointer: 0,
            buffer: 0,
            orphaned: false,
            normalized: false,
        }
    }

    /// Records a glXxxPointer's validated format and where the elements are (`pointer` is an
    /// offset into `buffer` when that is not 0).
    pub fn specify(&mut self, size: i32, component: ComponentType, stride: i32, pointer: usize, buffer: u32) {
        self.size = size;
        self.component = component;
        self.stride = stride;
        self.pointer = pointer;
        self.buffer = buffer;
        self.orphaned = false;
    }

    /// Bytes of one element.
    pub fn element_size(&self) -> usize {
        self.size as usize * self.component.size()
    }

    /// Bytes from one element to the next.
    pub fn effective_stride(&self) -> usize {
        if self.stride == 0 {
            self.element_size()
        } else {
            self.stride as usize
        }
    }
}

/// GL_CLIENT_VERTEX_ARRAY_BIT: every array, the client active texture unit and the two
/// buffer bindings that belong to vertex array state.
#[derive(Clone, Debug, PartialEq)]
pub struct ClientArrays {
    pub vertex: ArrayState,
    pub normal: ArrayState,
    pub color: ArrayState,
    pub secondary_color: ArrayState,
    pub fog_coord: ArrayState,
    pub index: ArrayState,
    pub edge_flag: ArrayState,
    /// One per texture coordinate set; the sets past GL_MAX_TEXTURE_UNITS feed only GLSL
    /// vertex shaders, as the generic arrays do ([`ClientArrays::generic_slots`]).
    pub tex_coords: [ArrayState; MAX_TEXTURE_COORDS],
    /// glClientActiveTexture: the unit glTexCoordPointer and the texture array enable address.
    pub client_active_texture: usize,
    /// GL_ARRAY_BUFFER_BINDING.
    pub array_buffer: u32,
    /// GL_ELEMENT_ARRAY_BUFFER_BINDING.
    pub element_array_buffer: u32,
    /// The generic attribute arrays (glVertexAttribPointer). Array 0 is the vertex position
    /// when enabled ([`ClientArrays::position`]); the others wait for GLSL programs.
    pub generic: [ArrayState; MAX_VERTEX_ATTRIBS],
}

impl Default for ClientArrays {
    fn default() -> Self {
        let mut edge_flag = ArrayState::new(1);
        edge_flag.component = ComponentType::UnsignedByte;
        ClientArrays {
            vertex: ArrayState::new(4),
            normal: ArrayState::new(3),
            color: ArrayState::new(4),
            secondary_color: ArrayState::new(3),
            fog_coord: ArrayState::new(1),
            index: ArrayState::new(1),
            edge_flag,
            tex_coords: [ArrayState::new(4); MAX_TEXTURE_COORDS],
            client_active_texture: 0,
            array_buffer: 0,
            element_array_buffer: 0,
            generic: [ArrayState::new(4); MAX_VERTEX_ATTRIBS],
        }
    }
}

impl ClientArrays {
    pub fn get(&self, id: ArrayId) -> &ArrayState {
        match id {
            ArrayId::Vertex => &self.vertex,
            ArrayId::Normal => &self.normal,
            ArrayId::Color => &self.color,
            ArrayId::SecondaryColor => &self.secondary_color,
            ArrayId::FogCoord => &self.fog_coord,
            ArrayId::Index => &self.index,
            ArrayId::EdgeFlag => &self.edge_flag,
            ArrayId::TexCoord(unit) => &self.tex_coords[unit.min(MAX_TEXTURE_COORDS - 1)],
        }
    }

    pub fn get_mut(&mut self, id: ArrayId) -> &mut ArrayState {
        match id {
            ArrayId::Vertex => &mut self.vertex,
            ArrayId::Normal => &mut self.normal,
            ArrayId::Color => &mut self.color,
            ArrayId::SecondaryColor => &mut self.secondary_color,
            ArrayId::FogCoord => &mut self.fog_coord,
            ArrayId::Index => &mut self.index,
            ArrayId::EdgeFlag => &mut self.edge_flag,
            ArrayId::TexCoord(unit) => &mut self.tex_coords[unit.min(MAX_TEXTURE_COORDS - 1)],
        }
    }

    /// The texture coordinate array of the client active unit.
    pub fn active_tex_coord(&self) -> ArrayId {
        ArrayId::TexCoord(self.client_active_texture)
    }

    /// The array a glEnableClientState / glIsEnabled capability names.
    pub fn array_of_capability(&self, cap: GLenum) -> Option<ArrayId> {
        Some(match cap {
            GL_VERTEX_ARRAY => ArrayId::Vertex,
            GL_NORMAL_ARRAY => ArrayId::Normal,
            GL_COLOR_ARRAY => ArrayId::Color,
            GL_SECONDARY_COLOR_ARRAY => ArrayId::SecondaryColor,
            GL_FOG_COORD_ARRAY => ArrayId::FogCoord,
            GL_INDEX_ARRAY => ArrayId::Index,
            GL_EDGE_FLAG_ARRAY => ArrayId::EdgeFlag,
            GL_TEXTURE_COORD_ARRAY => self.active_tex_coord(),
            _ => return None,
        })
    }

    /// The array a glGetPointerv name asks for.
    pub fn array_of_pointer_name(&self, pname: GLenum) -> Option<ArrayId> {
        Some(match pname {
            GL_VERTEX_ARRAY_POINTER => ArrayId::Vertex,
            GL_NORMAL_ARRAY_POINTER => ArrayId::Normal,
            GL_COLOR_ARRAY_POINTER => ArrayId::Color,
            GL_SECONDARY_COLOR_ARRAY_POINTER => ArrayId::SecondaryColor,
            GL_FOG_COORD_ARRAY_POINTER => ArrayId::FogCoord,
            GL_INDEX_ARRAY_POINTER => ArrayId::Index,
            GL_EDGE_FLAG_ARRAY_POINTER => ArrayId::EdgeFlag,
            GL_TEXTURE_COORD_ARRAY_POINTER => self.active_tex_coord(),
            _ => return None,
        })
    }

    /// The array draws take positions from: generic attribute 0 when it is enabled, which
    /// GL 2.0 section 2.8 gives precedence over the vertex array, else the vertex array.
    pub fn position(&self) -> &ArrayState {
        if self.generic[0].enabled {
            &self.generic[0]
        } else {
            &self.vertex
        }
    }

    /// The arrays whose values go to the rows of generic attributes
    /// ([`crate::vertex::generic`]) with the slot each fills: the generic arrays past 0, then
    /// the texture coordinate arrays past GL_MAX_TEXTURE_UNITS.
    pub fn generic_slots(&self) -> impl Iterator<Item = (usize, &ArrayState)> {
        let generic = self.generic.iter().enumerate().skip(1);
        let sets = self.tex_coords.iter().enumerate().skip(MAX_TEXTURE_UNITS);
        generic.chain(sets.map(|(set, a)| (crate::vertex::generic::tex_coord_slot(set), a)))
    }

    /// Every array a fixed-function draw reads with its id, texture units in order (the
    /// sets past GL_MAX_TEXTURE_UNITS are in [`ClientArrays::generic_slots`]); the positions
    /// are [`ClientArrays::position`]'s.
    pub fn all(&self) -> impl Iterator<Item = (ArrayId, &ArrayState)> {
        let fixed = [
            ArrayId::Vertex,
            ArrayId::Normal,
            ArrayId::Color,
            ArrayId::SecondaryColor,
            ArrayId::FogCoord,
            ArrayId::Index,
            ArrayId::EdgeFlag,
        ];
        fixed.into_iter().chain((0..MAX_TEXTURE_UNITS).map(ArrayId::TexCoord)).map(move |id| match id {
            ArrayId::Vertex => (id, self.position()),
            _ => (id, self.get(id)),
        })
    }

    /// Every array, mutably, the generic ones included.
    pub fn all_mut(&mut self) -> impl Iterator<Item = &mut ArrayState> {
        [
            &mut self.vertex,
            &mut self.normal,
            &mut self.color,
            &mut self.secondary_color,
            &mut self.fog_coord,
            &mut self.index,
            &mut self.edge_flag,
        ]
        .into_iter()
        .chain(self.tex_coords.iter_mut())
        .chain(self.generic.iter_mut())
    }
}

/// The arrays one glInterleavedArrays format sets (GL 2.1 table 2.5), byte offsets within an
/// element and the element size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct InterleavedLayout {
    /// Texture coordinate components and offset.
    pub tex_coords: Option<(i32, usize)>,
    /// Color components, type and offset.
    pub color: Option<(i32, ComponentType, usize)>,
    /// Normal offset.
    pub normal: Option<usize>,
    /// Vertex components and offset.
    pub vertex: (i32, usize),
    /// The stride when the call gives 0.
    pub stride: usize,
}

impl InterleavedLayout {
    pub fn from_gl(format: GLenum) -> Option<Self> {
        // f = sizeof(GLfloat); c = 4 unsigned bytes padded to a multiple of f.
        const F: usize = 4;
        const C: usize = 4;
        use ComponentType::{Float, UnsignedByte};
        let layout =
            |tex_coords, color, normal, vertex, stride| InterleavedLayout { tex_coords, color, normal, vertex, stride };
        Some(match format {
            GL_V2F => layout(None, None, None, (2, 0), 2 * F),
            GL_V3F => layout(None, None, None, (3, 0), 3 * F),
            GL_C4UB_V2F => layout(None, Some((4, UnsignedByte, 0)), None, (2, C), C + 2 * F),
            GL_C4UB_V3F => layout(None, Some((4, UnsignedByte, 0)), None, (3, C), C + 3 * F),
            GL_C3F_V3F => layout(None, Some((3, Float, 0)), None, (3, 3 * F), 6 * F),
            GL_N3F_V3F => layout(None, None, Some(0), (3, 3 * F), 6 * F),
            GL_C4F_N3F_V3F => layout(None, Some((4, Float, 0)), Some(4 * F), (3, 7 * F), 10 * F),
            GL_T2F_V3F => layout(Some((2, 0)), None, None, (3, 2 * F), 5 * F),
            GL_T4F_V4F => layout(Some((4, 0)), None, None, (4, 4 * F), 8 * F),
            GL_T2F_C4UB_V3F => layout(Some((2, 0)), Some((4, UnsignedByte, 2 * F)), None, (3, C + 2 * F), C + 5 * F),
            GL_T2F_C3F_V3F => layout(Some((2, 0)), Some((3, Float, 2 * F)), None, (3, 5 * F), 8 * F),
            GL_T2F_N3F_V3F => layout(Some((2, 0)), None, Some(2 * F), (3, 5 * F), 8 * F),
            GL_T2F_C4F_N3F_V3F => layout(Some((2, 0)), Some((4, Float, 2 * F)), Some(6 * F), (3, 9 * F), 12 * F),
            GL_T4F_C4F_N3F_V4F => layout(Some((4, 0)), Some((4, Float, 4 * F)), Some(8 * F), (4, 11 * F), 15 * F),
            _ => return None,
        })
    }
}

/// The index types of glDrawElements.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IndexType {
    UnsignedByte,
    UnsignedShort,
    UnsignedInt,
}

impl IndexType {
    pub fn from_gl(e: GLenum) -> Option<Self> {
        Some(match e {
            GL_UNSIGNED_BYTE => Self::UnsignedByte,
            GL_UNSIGNED_SHORT => Self::UnsignedShort,
            GL_UNSIGNED_INT => Self::UnsignedInt,
            _ => return None,
        })
    }

    /// Bytes of one index.
    pub fn size(self) -> usize {
        match self {
            Self::UnsignedByte => 1,
            Self::UnsignedShort => 2,
            Self::UnsignedInt => 4,
        }
    }

    /// The indices packed in `bytes` (native endian), in order.
    pub fn decode(self, bytes: &[u8]) -> impl Iterator<Item = u32> + '_ {
        bytes.chunks_exact(self.size()).map(move |chunk| match *chunk {
            [b] => b as u32,
            [b0, b1] => u16::from_ne_bytes([b0, b1]) as u32,
            [b0, b1, b2, b3] => u32::from_ne_bytes([b0, b1, b2, b3]),
            _ => 0,
        })
    }
}

/// The smallest and largest index in `indices`, `None` when there are none.
pub fn index_range(indices: impl IntoIterator<Item = u32>) -> Option<(u32, u32)> {
    indices.into_iter().fold(None, |range, i| match range {
        None => Some((i, i)),
        Some((lo, hi)) => Some((lo.min(i), hi.max(i))),
    })
}

/// The bytes an array's elements `first..=last` occupy: (offset from the array's pointer,
/// length). `None` when the range does not fit the address space.
pub fn byte_extent(first: u32, last: u32, stride: usize, element_size: usize) -> Option<(usize, usize)> {
    let offset = (first as usize).checked_mul(stride)?;
    let span = ((last - first.min(last)) as usize).checked_mul(stride)?.checked_add(element_size)?;
    offset.checked_add(span)?;
    Some((offset, span))
}

/// Caller-owned memory a draw reads (client arrays, client index arrays).
pub trait ClientMemory {
    /// The `len` bytes at `address`, or `None` when they cannot be read (a null address).
    fn bytes(&self, address: usize, len: usize) -> Option<&[u8]>;
}

/// One enabled array prepared for a draw: its bytes from element `first` on.
#[derive(Clone, Copy)]
pub struct BoundArray<'a> {
    bytes: &'a [u8],
    first: u32,
    stride: usize,
    element_size: usize,
    size: usize,
    decode: Decoder,
    /// GL_FLOAT components (read in place by [`BoundArray::fill_floats`]).
    float: bool,
}

impl<'a> BoundArray<'a> {
    /// `bytes` start at element `first` of `array` (as [`byte_extent`] computed them).
    pub fn new(id: ArrayId, array: &ArrayState, bytes: &'a [u8], first: u32) -> Self {
        BoundArray {
            bytes,
            first,
            stride: array.effective_stride(),
            element_size: array.element_size(),
            size: array.size as usize,
            decode: decoder(array.component, id.normalized() || array.normalized),
            float: array.component == ComponentType::Float,
        }
    }

    /// Stores elements `first`, `first + 1`, … of a GL_FLOAT array into `out` (one each,
    /// missing components (0, 0, 0, 1)) when all of them lie wholly within the bytes, and
    /// says whether it did. Then the values are exactly [`BoundArray::fetch`]'s, read in
    /// place: no decoder call and no bounds arithmetic per element (the common case of a
    /// float array draw, where the decoder call was most of the fetch).
    // Inlined into each caller's per-array loop: left to the inliner (without LTO), whether
    // the store closure is inlined into the loop changed with unrelated edits elsewhere.
    #[inline(always)]
    pub fn fill_floats<T>(&self, first: u32, out: &mut [T], store: impl Fn(&mut T, [f32; 4])) -> bool {
        if !self.float || out.is_empty() || self.element_size != 4 * self.size {
            return false;
        }
        let start = (first.wrapping_sub(self.first) as usize).checked_mul(self.stride);
        let end = start
            .and_then(|s| (out.len() - 1).checked_mul(self.stride).and_then(|d| s.checked_add(d)))
            .and_then(|last| last.checked_add(self.element_size));
        let (Some(start), Some(end)) = (start, end) else { return false };
        if end > self.bytes.len() {
            return false;
        }
        match self.size {
            1 => self.store_floats::<1, T>(start, out, store),
            2 => self.store_floats::<2, T>(start, out, store),
            3 => self.store_floats::<3, T>(start, out, store),
            _ => self.store_floats::<4, T>(start, out, store),
        }
        true
    }

    /// [`BoundArray::fill_floats`]' loop for `N` components, `out[k]` from the bytes at
    /// `start + k · stride` (checked to lie within the bytes).
    #[inline(always)]
    fn store_floats<const N: usize, T>(&self, start: usize, out: &mut [T], store: impl Fn(&mut T, [f32; 4])) {
        for (k, o) in out.iter_mut().enumerate() {
            let at = start + k * self.stride;
            let Some(element) = self.bytes.get(at..at + 4 * N) else { return };
            let mut value = [0.0, 0.0, 0.0, 1.0];
            for (v, c) in value.iter_mut().zip(element.chunks_exact(4)) {
                *v = f32::from_ne_bytes([c[0], c[1], c[2], c[3]]);
            }
            store(o, value);
        }
    }

    /// Element `index`, missing components (0, 0, 0, 1). Bytes beyond the data (a buffer
    /// object smaller than the draw needs) read as zero.
    pub fn fetch(&self, index: u32) -> [f32; 4] {
        let start = (index.wrapping_sub(self.first) as usize).wrapping_mul(self.stride);
        let end = start.saturating_add(self.element_size).min(self.bytes.len());
        (self.decode)(self.bytes.get(start..end).unwrap_or(&[]), self.size)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pointer_validation_follows_mesas_order() {
        assert_eq!(ArrayId::Vertex.check_pointer(3, GL_FLOAT, 0), Ok(ComponentType::Float));
        assert_eq!(ArrayId::Vertex.check_pointer(1, GL_FLOAT, 0), Err(GL_INVALID_VALUE));
        assert_eq!(ArrayId::Vertex.check_pointer(3, GL_BYTE, 0), Err(GL_INVALID_ENUM));
        // Type before size, stride before both.
        assert_eq!(ArrayId::Vertex.check_pointer(5, GL_UNSIGNED_BYTE, 0), Err(GL_INVALID_ENUM));
        assert_eq!(ArrayId::Color.check_pointer(5, GL_BOOL, -1), Err(GL_INVALID_VALUE));
        assert_eq!(ArrayId::Color.check_pointer(3, GL_UNSIGNED_INT, 100000), Ok(ComponentType::UnsignedInt));
        assert_eq!(ArrayId::Color.check_pointer(GL_BGRA as i32, GL_UNSIGNED_BYTE, 0), Err(GL_INVALID_VALUE));
        assert_eq!(ArrayId::SecondaryColor.check_pointer(4, GL_FLOAT, 0), Err(GL_INVALID_VALUE));
        assert_eq!(ArrayId::Normal.check_pointer(3, GL_UNSIGNED_BYTE, 0), Err(GL_INVALID_ENUM));
        assert_eq!(ArrayId::Normal.check_pointer(3, GL_BYTE, 0), Ok(ComponentType::Byte));
        assert_eq!(ArrayId::FogCoord.check_pointer(1, GL_INT, 0), Err(GL_INVALID_ENUM));
        assert_eq!(ArrayId::Index.check_pointer(1, GL_UNSIGNED_BYTE, 0), Ok(ComponentType::UnsignedByte));
        assert_eq!(ArrayId::Index.check_pointer(1, GL_BYTE, 0), Err(GL_INVALID_ENUM));
        assert_eq!(ArrayId::TexCoord(2).check_pointer(1, GL_SHORT, 0), Ok(ComponentType::Short));
        assert_eq!(ArrayId::TexCoord(0).check_pointer(0, GL_SHORT, 0), Err(GL_INVALID_VALUE));
        assert_eq!(ArrayId::TexCoord(0).check_pointer(2, GL_HALF_FLOAT, 0), Err(GL_INVALID_ENUM));
    }

    #[test]
    fn interleaved_layouts_match_table_2_5() {
        // (format, tex size/offset, color size/offset, normal offset, vertex size/offset, stride),
        // as Mesa 22 reports them through glGet and glGetPointerv.
        let l = InterleavedLayout::from_gl;
        let v = |f| {
            let x: InterleavedLayout = l(f).unwrap();
            (x.tex_coords, x.color.map(|(s, _, o)| (s, o)), x.normal, x.vertex, x.stride)
        };
        assert_eq!(v(GL_V2F), (None, None, None, (2, 0), 8));
        assert_eq!(v(GL_V3F), (None, None, None, (3, 0), 12));
        assert_eq!(v(GL_C4UB_V2F), (None, Some((4, 0)), None, (2, 4), 12));
        assert_eq!(v(GL_C4UB_V3F), (None, Some((4, 0)), None, (3, 4), 16));
        assert_eq!(v(GL_C3F_V3F), (None, Some((3, 0)), None, (3, 12), 24));
        assert_eq!(v(GL_N3F_V3F), (None, None, Some(0), (3, 12), 24));
        assert_eq!(v(GL_C4F_N3F_V3F), (None, Some((4, 0)), Some(16), (3, 28), 40));
        assert_eq!(v(GL_T2F_V3F), (Some((2, 0)), None, None, (3, 8), 20));
        assert_eq!(v(GL_T4F_V4F), (Some((4, 0)), None, None, (4, 16), 32));
        assert_eq!(v(GL_T2F_C4UB_V3F), (Some((2, 0)), Some((4, 8)), None, (3, 12), 24));
        assert_eq!(v(GL_T2F_C3F_V3F), (Some((2, 0)), Some((3, 8)), None, (3, 20), 32));
        assert_eq!(v(GL_T2F_N3F_V3F), (Some((2, 0)), None, Some(8), (3, 20), 32));
        assert_eq!(v(GL_T2F_C4F_N3F_V3F), (Some((2, 0)), Some((4, 8)), Some(24), (3, 36), 48));
        assert_eq!(v(GL_T4F_C4F_N3F_V4F), (Some((4, 0)), Some((4, 16)), Some(32), (4, 44), 60));
        assert_eq!(l(GL_C4UB_V2F).unwrap().color.unwrap().1, ComponentType::UnsignedByte);
        assert_eq!(l(GL_C4F_N3F_V3F).unwrap().color.unwrap().1, ComponentType::Float);
        assert_eq!(l(GL_V2F - 1), None);
        assert_eq!(l(GL_T4F_C4F_N3F_V4F + 1), None);
    }

    #[test]
    fn index_ranges_of_every_index_type() {
        let bytes = [5u8, 0, 200, 7];
        assert_eq!(index_range(IndexType::UnsignedByte.decode(&bytes)), Some((0, 200)));
        let shorts: Vec<u8> = [300u16, 65535, 2].iter().flat_map(|v| v.to_ne_bytes()).collect();
        assert_eq!(IndexType::UnsignedShort.decode(&shorts).collect::<Vec<_>>(), [300, 65535, 2]);
        assert_eq!(index_range(IndexType::UnsignedShort.decode(&shorts)), Some((2, 65535)));
        let ints: Vec<u8> = [70000u32, u32::MAX, 69999].iter().flat_map(|v| v.to_ne_bytes()).collect();
        assert_eq!(index_range(IndexType::UnsignedInt.decode(&ints)), Some((69999, u32::MAX)));
        assert_eq!(index_range(IndexType::UnsignedInt.decode(&[])), None);
        // A trailing partial index is not an index.
        assert_eq!(IndexType::UnsignedInt.decode(&ints[..7]).count(), 1);
        assert_eq!(IndexType::from_gl(GL_UNSIGNED_SHORT), Some(IndexType::UnsignedShort));
        assert_eq!(IndexType::from_gl(GL_SHORT), None);
    }

    #[test]
    fn byte_extents_cover_exactly_the_elements_read() {
        // Elements 3..=5 of a 12-byte-stride array of 8-byte elements.
        assert_eq!(byte_extent(3, 5, 12, 8), Some((36, 32)));
        assert_eq!(byte_extent(0, 0, 16, 4), Some((0, 4)));
        assert_eq!(byte_extent(u32::MAX, u32::MAX, 1 << 20, 4), Some(((u32::MAX as usize) << 20, 4)));
        assert_eq!(byte_extent(u32::MAX, u32::MAX, 1 << 40, 4), None);
        assert_eq!(byte_extent(0, u32::MAX, usize::MAX / 2, 4), None);
    }

    #[test]
    fn bound_arrays_fetch_relative_to_their_first_element() {
        let mut array = ArrayState::new(2);
        array.component = ComponentType::Short;
        array.stride = 6;
        // Elements 10 and 11: (1, 2) and (3, 4), with two bytes of padding between.
        let bytes: Vec<u8> = [1i16, 2, 0, 3, 4].iter().flat_map(|v| v.to_ne_bytes()).collect();
        let bound = BoundArray::new(ArrayId::TexCoord(1), &array, &bytes, 10);
        assert_eq!(bound.fetch(10), [1.0, 2.0, 0.0, 1.0]);
        assert_eq!(bound.fetch(11), [3.0, 4.0, 0.0, 1.0]);
        // Beyond the data: zeros (then the defaults), never a panic.
        assert_eq!(bound.fetch(12), [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(bound.fetch(3), [0.0, 0.0, 0.0, 1.0]);
        let colors = BoundArray::new(ArrayId::Color, &array, &bytes, 10);
        assert_eq!(colors.fetch(10), [3.0 * (1.0 / 65535.0), 5.0 * (1.0 / 65535.0), 0.0, 1.0]);
    }

    #[test]
    fn capabilities_and_pointer_names_follow_the_client_active_unit() {
        let mut arrays = ClientArrays { client_active_texture: 2, ..Default::default() };
        assert_eq!(arrays.array_of_capability(GL_TEXTURE_COORD_ARRAY), Some(ArrayId::TexCoord(2)));
        assert_eq!(arrays.array_of_pointer_name(GL_TEXTURE_COORD_ARRAY_POINTER), Some(ArrayId::TexCoord(2)));
        assert_eq!(arrays.array_of_capability(GL_FOG_COORD_ARRAY), Some(ArrayId::FogCoord));
        assert_eq!(arrays.array_of_capability(GL_TEXTURE_2D), None);
        assert_eq!(arrays.array_of_pointer_name(GL_VERTEX_ARRAY), None);
        assert_eq!(arrays.all().count(), 7 + MAX_TEXTURE_UNITS);
        assert_eq!(arrays.all_mut().count(), 7 + MAX_TEXTURE_COORDS + MAX_VERTEX_ATTRIBS);
        // Generic arrays past 0, then the sets past the fixed-function units.
        let slots: Vec<usize> = arrays.generic_slots().map(|(slot, _)| slot).collect();
        assert_eq!(slots, (1..crate::vertex::generic::SLOTS).collect::<Vec<_>>());
        assert_eq!(arrays.edge_flag.element_size(), 1);
        assert_eq!(arrays.vertex.effective_stride(), 16);
    }
}
