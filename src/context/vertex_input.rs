//! Vertex input: the commands that make vertices (glBegin/glEnd and the current attributes,
//! client arrays and the draw calls that read them, buffer objects) and hand them to the
//! geometry pipeline through [`Context::draw_vertices`].
//!
//! Every source produces [`Vertex`] records: glVertex snapshots the current attributes, an
//! array draw starts from that snapshot and overwrites what its enabled arrays hold. The
//! vertices of a glBegin/glEnd pair and of a draw call are collected in vectors that live
//! as long as the context, so steady-state drawing allocates nothing per vertex or per call.
//! Points, lines, triangles and quads are delivered in batches of [`BATCH_VERTICES`] (also
//! while glBegin/glEnd is still open). Strips, fans, loops and polygons are delivered in
//! parts of about as many vertices, each repeating the vertices the next primitives share
//! with the previous part
//! ([`continued_vertices`](crate::vertex::assembly::continued_vertices)), so a draw of any length needs bounded
//! memory and draws the same pixels as delivered whole; they are delivered whole while a
//! display list captures an array draw, in selection and feedback modes, and after
//! glMaterial between glBegin and glEnd (whose marks count vertices from glBegin). A
//! captured draw is cut into parts again when the list is called
//! ([`Context::deliver_in_parts`]): the list holds its vertices, the draw needs no more.
//!
//! Deliberate differences from Mesa 22 (which implements GL 4.5 and is lenient where GL 2.1
//! is not) are listed with the commands they concern, in the submodules.
mod arrays;
mod buffers;
mod compiled;
mod draws;
mod generic;
#[cfg(test)]
mod glsl_tests;
mod immediate;

use super::get::Value;
use super::state::Material;
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::vertex::arrays::{ArrayId, ClientArrays};
use crate::vertex::assembly::{continued_vertices, DrawPart};
use crate::vertex::generic::{GenericRows, GenericValues};
use crate::vertex::Vertex;

/// One batch of an array draw a display list captured: its mode, its vertices and, when
/// generic arrays were enabled, each vertex's generic attributes (else empty).
#[derive(Clone, Debug)]
struct CapturedBatch {
    mode: GLenum,
    vertices: Vec<Vertex>,
    generic: Vec<GenericValues>,
}
pub use generic::AttribValue;

/// GL_MAX_ELEMENTS_VERTICES / GL_MAX_ELEMENTS_INDICES: a recommendation only (any count
/// works); Mesa's value.
pub const MAX_ELEMENTS: i32 = 3000;

/// Primitives that share no vertices (points, lines, triangles, quads) are delivered in
/// batches of this many vertices (a multiple of 1, 2, 3 and 4), so a long glBegin/glEnd or a
/// large draw call needs no more memory than that and stays in cache. Strips, fans, loops
/// and polygons are delivered in parts of this many vertices (even: strips keep their
/// triangles' order) plus the ones each part repeats.
pub const BATCH_VERTICES: usize = 3072;

/// Vertices per primitive of the modes whose primitives share no vertices.
fn independent_primitive_size(mode: GLenum) -> Option<usize> {
    match mode {
        GL_POINTS => Some(1),
        GL_LINES => Some(2),
        GL_TRIANGLES => Some(3),
        GL_QUADS => Some(4),
        _ => None,
    }
}

/// The vertex-input state of a context besides the current attributes (which are
/// `state.current`) and the buffer objects (`Context::buffers`).
#[derive(Debug, Default)]
pub struct VertexInput {
    /// GL_CLIENT_VERTEX_ARRAY_BIT state.
    pub arrays: ClientArrays,
    /// The mode of the open glBegin.
    begin_mode: GLenum,
    /// The vertices since glBegin.
    vertices: Vec<Vertex>,
    /// The vertices of an array draw under construction.
    batch: Vec<Vertex>,
    /// The generic attribute rows the open glBegin/glEnd's vertices, or an array draw's,
    /// name ([`crate::vertex::generic`]).
    pub(crate) generic_rows: GenericRows,
    /// glMaterial between glBegin and glEnd: from which open vertex on each front and back
    /// material applies (empty when glMaterial was not called since glBegin).
    pub material_marks: Vec<(usize, [Material; 2])>,
    /// While an array draw is compiled into a display list: the batches it delivers.
    capture: Option<Vec<CapturedBatch>>,
    /// Whether a part of the open connected primitive has been delivered.
    parts_delivered: bool,
    /// The line stipple counter where the last delivered part of a connected primitive ended.
    pub(crate) stipple_counter: i32,
    /// Every batch handed to the geometry pipeline, for tests.
    #[cfg(test)]
    pub(crate) delivered: Vec<(GLenum, Vec<Vertex>)>,
}

impl Context {
    /// Records, for glMaterial between glBegin and glEnd, that the current materials apply
    /// from the next vertex on.
    pub(crate) fn mark_material_change(&mut self) {
        let at = self.vertex_input.vertices.len();
        let materials = self.state.lighting.materials;
        let marks = &mut self.vertex_input.material_marks;
        match marks.last_mut() {
            Some(last) if last.0 == at => last.1 = materials,
            _ => marks.push((at, materials)),
        }
    }

    /// Hands finished vertices to the geometry pipeline.
    fn deliver(&mut self, mode: GLenum, vertices: &[Vertex]) {
        self.deliver_part(mode, vertices, DrawPart::WHOLE);
    }

    /// Hands `vertices` to the geometry pipeline as [`Context::deliver`] does, but a long
    /// strip, fan, loop or polygon in parts of [`BATCH_VERTICES`] plus the vertices each
    /// part repeats, exactly as an array draw delivers one (`draw_in_parts`), when parts may
    /// be delivered: a display list's captured draw then needs no more memory to draw than a
    /// draw from the arrays.
    fn deliver_in_parts(&mut self, mode: GLenum, vertices: &[Vertex]) {
        let count = vertices.len();
        let kept = continued_vertices(mode, BATCH_VERTICES);
        let Some(kept) = kept.filter(|_| count > BATCH_VERTICES + 2 && self.may_deliver_parts()) else {
            return self.deliver(mode, vertices);
        };
        let loop_ = mode == GL_LINE_LOOP;
        let part_mode = if loop_ { GL_LINE_STRIP } else { mode };
        let mut part_vertices = Vec::with_capacity(BATCH_VERTICES + 1);
        let mut start = 0;
        loop {
            let end = (start + BATCH_VERTICES).min(count);
            let part = DrawPart { first: start == 0, last: end == count };
            part_vertices.clear();
            if kept.first && !loop_ && !part.first {
                part_vertices.push(vertices[0]);
            }
            part_vertices.extend_from_slice(&vertices[start..end]);
            if loop_ && part.last {
                part_vertices.push(vertices[0]);
            }
            self.deliver_part(part_mode, &part_vertices, part);
            if part.last {
                return;
            }
            start = end - kept.tail;
        }
    }

    /// Hands one part of a draw to the geometry pipeline (whole draws are
    /// [`DrawPart::WHOLE`]; parts are never captured).
    fn deliver_part(&mut self, mode: GLenum, vertices: &[Vertex], part: DrawPart) {
        if let Some(capture) = &mut self.vertex_input.capture {
            // Each vertex's generic attributes by value: its row, when the draw made rows.
            let rows = &self.vertex_input.generic_rows;
            let generic = if rows.rows.is_empty() {
                Vec::new()
            } else {
                vertices.iter().map(|v| *rows.of(v, &self.state.current.generic)).collect()
            };
            return capture.push(CapturedBatch { mode, vertices: vertices.to_vec(), generic });
        }
        #[cfg(test)]
        self.vertex_input.delivered.push((mode, vertices.to_vec()));
        self.draw_part(mode, vertices, part);
    }

    /// Whether a display list is capturing an array draw now.
    fn capturing(&self) -> bool {
        self.vertex_input.capture.is_some()
    }

    /// Whether a connected primitive may be delivered in parts now (see the module docs).
    fn may_deliver_parts(&self) -> bool {
        self.vertex_input.capture.is_none() && self.rendering()
    }

    /// The glGet values of the current attributes and the vertex array state; `None` for
    /// other pnames.
    pub(crate) fn vertex_input_values(&self, pname: GLenum) -> Option<Vec<Value>> {
        use Value::*;
        let current = &self.state.current;
        let arrays = &self.vertex_input.arrays;
        let array = |id| arrays.get(id);
        let size = |id| vec![Int(array(id).size)];
        let type_ = |id| vec![Enum(array(id).component.to_gl())];
        let stride = |id| vec![Int(array(id).stride)];
        let binding = |id: ArrayId| vec![Int(array(id).buffer as i32)];
        let tex = arrays.active_tex_coord();
        Some(match pname {
            GL_CURRENT_COLOR => current.color.map(NormFloat).to_vec(),
            GL_CURRENT_SECONDARY_COLOR => current.secondary_color.map(NormFloat).to_vec(),
            GL_CURRENT_NORMAL => current.normal.map(NormFloat).to_vec(),
            GL_CURRENT_TEXTURE_COORDS => {
                let coords = self.current_tex_coords(self.state.texture.active_unit);
                coords.map(Float).to_vec()
            }
            GL_CURRENT_FOG_COORD => vec![Float(current.fog_coord)],
            GL_CURRENT_INDEX => vec![Float(current.index)],
            GL_EDGE_FLAG => vec![Bool(current.edge_flag)],

            GL_VERTEX_ARRAY
            | GL_NORMAL_ARRAY
            | GL_COLOR_ARRAY
            | GL_SECONDARY_COLOR_ARRAY
            | GL_FOG_COORD_ARRAY
            | GL_INDEX_ARRAY
            | GL_EDGE_FLAG_ARRAY
            | GL_TEXTURE_COORD_ARRAY => {
                vec![Bool(arrays.array_of_capability(pname).is_some_and(|id| array(id).enabled))]
            }
            GL_VERTEX_ARRAY_SIZE => size(ArrayId::Vertex),
            GL_VERTEX_ARRAY_TYPE => type_(ArrayId::Vertex),
            GL_VERTEX_ARRAY_STRIDE => stride(ArrayId::Vertex),
            GL_NORMAL_ARRAY_TYPE => type_(ArrayId::Normal),
            GL_NORMAL_ARRAY_STRIDE => stride(ArrayId::Normal),
            GL_COLOR_ARRAY_SIZE => size(ArrayId::Color),
            GL_COLOR_ARRAY_TYPE => type_(ArrayId::Color),
            GL_COLOR_ARRAY_STRIDE => stride(ArrayId::Color),
            GL_SECONDARY_COLOR_ARRAY_SIZE => size(ArrayId::SecondaryColor),
            GL_SECONDARY_COLOR_ARRAY_TYPE => type_(ArrayId::SecondaryColor),
            GL_SECONDARY_COLOR_ARRAY_STRIDE => stride(ArrayId::SecondaryColor),
            GL_FOG_COORD_ARRAY_TYPE => type_(ArrayId::FogCoord),
            GL_FOG_COORD_ARRAY_STRIDE => stride(ArrayId::FogCoord),
            GL_INDEX_ARRAY_TYPE => type_(ArrayId::Index),
            GL_INDEX_ARRAY_STRIDE => stride(ArrayId::Index),
            GL_EDGE_FLAG_ARRAY_STRIDE => stride(ArrayId::EdgeFlag),
            GL_TEXTURE_COORD_ARRAY_SIZE => size(tex),
            GL_TEXTURE_COORD_ARRAY_TYPE => type_(tex),
            GL_TEXTURE_COORD_ARRAY_STRIDE => stride(tex),
            GL_CLIENT_ACTIVE_TEXTURE => vec![Enum(GL_TEXTURE0 + arrays.client_active_texture as GLenum)],

            GL_ARRAY_BUFFER_BINDING => vec![Int(arrays.array_buffer as i32)],
            GL_ELEMENT_ARRAY_BUFFER_BINDING => vec![Int(arrays.element_array_buffer as i32)],
            GL_PIXEL_PACK_BUFFER_BINDING => vec![Int(self.pixel_store.pack_buffer as i32)],
            GL_PIXEL_UNPACK_BUFFER_BINDING => vec![Int(self.pixel_store.unpack_buffer as i32)],
            GL_VERTEX_ARRAY_BUFFER_BINDING => binding(ArrayId::Vertex),
            GL_NORMAL_ARRAY_BUFFER_BINDING => binding(ArrayId::Normal),
            GL_COLOR_ARRAY_BUFFER_BINDING => binding(ArrayId::Color),
            GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING => binding(ArrayId::SecondaryColor),
            GL_FOG_COORD_ARRAY_BUFFER_BINDING => binding(ArrayId::FogCoord),
            GL_INDEX_ARRAY_BUFFER_BINDING => binding(ArrayId::Index),
            GL_EDGE_FLAG_ARRAY_BUFFER_BINDING => binding(ArrayId::EdgeFlag),
            GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING => binding(tex),

            GL_MAX_ELEMENTS_VERTICES | GL_MAX_ELEMENTS_INDICES => vec![Int(MAX_ELEMENTS)],
            _ => return None,
        })
    }

    /// The enable flag of the client array a capability names (glEnable(GL_VERTEX_ARRAY)
    /// works as glEnableClientState, as in Mesa).
    pub(crate) fn client_array_enable(&mut self, cap: GLenum) -> Option<&mut bool> {
        let id = self.vertex_input.arrays.array_of_capability(cap)?;
        Some(&mut self.vertex_input.arrays.get_mut(id).enabled)
    }

    /// glPopClientAttrib of GL_CLIENT_VERTEX_ARRAY_BIT. The two buffer bindings are restored
    /// as glBindBuffer would bind them, so a buffer deleted since the push comes back as a new,
    /// empty buffer of the same name (as in Mesa). Arrays whose buffer was deleted since keep
    /// its name and draw nothing.
    pub(crate) fn restore_client_arrays(&mut self, saved: ClientArrays) {
        let mut buffers = self.buffers.lock();
        buffers.create_on_bind(saved.array_buffer);
        buffers.create_on_bind(saved.element_array_buffer);
        drop(buffers);
        self.vertex_input.arrays = saved;
    }
}

#[cfg(test)]
pub(crate) mod test_support {
    use super::*;
    use crate::context::ContextConfig;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};
    use crate::vertex::arrays::ClientMemory;

    pub fn context() -> Context {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, depth_stencil, 0);
        Context::new(ContextConfig { visual })
    }

    /// Client memory made of regions at fake addresses.
    #[derive(Default)]
    pub struct FakeMemory {
        regions: Vec<(usize, Vec<u8>)>,
        /// Every (address, length) a draw asked for.
        pub reads: std::cell::RefCell<Vec<(usize, usize)>>,
    }

    impl FakeMemory {
        /// Adds `bytes` at `address`; returns the address.
        pub fn add(&mut self, address: usize, bytes: Vec<u8>) -> usize {
            self.regions.push((address, bytes));
            address
        }
    }

    impl ClientMemory for FakeMemory {
        fn bytes(&self, address: usize, len: usize) -> Option<&[u8]> {
            self.reads.borrow_mut().push((address, len));
            let (start, bytes) = self.regions.iter().find(|(start, bytes)| {
                address >= *start && address.checked_add(len).is_some_and(|end| end <= start + bytes.len())
            })?;
            bytes.get(address - start..address - start + len)
        }
    }

    pub fn floats(values: &[f32]) -> Vec<u8> {
        values.iter().flat_map(|v| v.to_ne_bytes()).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::test_support::*;
    use super::*;

    #[test]
    fn current_attribute_queries_and_their_integer_forms() {
        let mut ctx = context();
        assert_eq!(ctx.get_floats(GL_CURRENT_COLOR), Some(vec![1.0; 4]));
        assert_eq!(ctx.get_floats(GL_CURRENT_SECONDARY_COLOR), Some(vec![0.0, 0.0, 0.0, 1.0]));
        assert_eq!(ctx.get_integers(GL_CURRENT_NORMAL), Some(vec![0, 0, i32::MAX]));
        assert_eq!(ctx.get_integers(GL_CURRENT_TEXTURE_COORDS), Some(vec![0, 0, 0, 1]));
        assert_eq!(ctx.get_booleans(GL_EDGE_FLAG), Some(vec![GL_TRUE]));
        assert_eq!(ctx.get_floats(GL_CURRENT_INDEX), Some(vec![1.0]));
        // Values measured on Mesa 22: colors and normals are normalized, texture coordinates,
        // fog coordinates and the index round to nearest.
        ctx.set_color([0.5, 0.25, -0.5, 0.1]);
        assert_eq!(ctx.get_integers(GL_CURRENT_COLOR), Some(vec![1073741823, 536870911, -1073741823, 214748367]));
        ctx.set_normal([-0.5, 0.3, 1.0]);
        assert_eq!(ctx.get_integers(GL_CURRENT_NORMAL), Some(vec![-1073741823, 644245119, 2147483647]));
        ctx.set_tex_coords(0, [2.5, -0.5, 1.5, -2.5]);
        assert_eq!(ctx.get_integers(GL_CURRENT_TEXTURE_COORDS), Some(vec![3, -1, 2, -3]));
        ctx.set_fog_coord(-0.5);
        ctx.set_index(-3.5);
        assert_eq!(ctx.get_integers(GL_CURRENT_FOG_COORD), Some(vec![-1]));
        assert_eq!(ctx.get_integers(GL_CURRENT_INDEX), Some(vec![-4]));
        ctx.set_edge_flag(false);
        assert_eq!(ctx.get_floats(GL_EDGE_FLAG), Some(vec![0.0]));
        // GL_CURRENT_TEXTURE_COORDS follows the server active texture unit.
        ctx.multi_tex_coord(GL_TEXTURE2, [9.0, 8.0, 0.0, 1.0]);
        ctx.state.texture.active_unit = 2;
        assert_eq!(ctx.get_floats(GL_CURRENT_TEXTURE_COORDS), Some(vec![9.0, 8.0, 0.0, 1.0]));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn array_state_queries_follow_the_client_active_unit() {
        let mut ctx = context();
        assert_eq!(ctx.get_integers(GL_VERTEX_ARRAY_SIZE), Some(vec![4]));
        assert_eq!(ctx.get_integers(GL_SECONDARY_COLOR_ARRAY_SIZE), Some(vec![3]));
        assert_eq!(ctx.get_integers(GL_INDEX_ARRAY_TYPE), Some(vec![GL_FLOAT as i32]));
        assert_eq!(ctx.get_integers(GL_CLIENT_ACTIVE_TEXTURE), Some(vec![GL_TEXTURE0 as i32]));
        assert_eq!(ctx.get_integers(GL_MAX_ELEMENTS_INDICES), Some(vec![3000]));
        ctx.client_active_texture(GL_TEXTURE1);
        ctx.tex_coord_pointer(3, GL_SHORT, 6, 99);
        ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY, true);
        assert_eq!(ctx.get_integers(GL_TEXTURE_COORD_ARRAY_SIZE), Some(vec![3]));
        assert_eq!(ctx.get_integers(GL_TEXTURE_COORD_ARRAY_STRIDE), Some(vec![6]));
        assert_eq!(ctx.get_booleans(GL_TEXTURE_COORD_ARRAY), Some(vec![GL_TRUE]));
        ctx.client_active_texture(GL_TEXTURE0);
        assert_eq!(ctx.get_integers(GL_TEXTURE_COORD_ARRAY_SIZE), Some(vec![4]));
        assert_eq!(ctx.get_booleans(GL_TEXTURE_COORD_ARRAY), Some(vec![GL_FALSE]));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn client_vertex_array_bit_saves_arrays_and_bindings() {
        let mut ctx = context();
        ctx.bind_buffer(GL_ARRAY_BUFFER, 7);
        ctx.color_pointer(3, GL_BYTE, 5, 12);
        ctx.enable_client_state(GL_COLOR_ARRAY, true);
        ctx.client_active_texture(GL_TEXTURE2);
        let saved = ctx.vertex_input.arrays.clone();
        ctx.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        ctx.bind_buffer(GL_ARRAY_BUFFER, 8);
        ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 8);
        ctx.interleaved_arrays(GL_T4F_C4F_N3F_V4F, 0, 0);
        ctx.client_active_texture(GL_TEXTURE0);
        ctx.pixel_store.pack.alignment = 8;
        ctx.pop_client_attrib();
        assert_eq!(ctx.vertex_input.arrays, saved);
        assert_eq!(ctx.pixel_store.pack.alignment, 8, "only the vertex array group was pushed");
        // The pixel store bit leaves the arrays alone.
        ctx.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT);
        ctx.enable_client_state(GL_COLOR_ARRAY, false);
        ctx.pop_client_attrib();
        assert!(!ctx.vertex_input.arrays.color.enabled);
        // A bound buffer deleted while pushed comes back as an empty buffer of that name.
        ctx.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        ctx.delete_buffers(1, &[7]);
        assert!(!ctx.is_buffer(7));
        ctx.pop_client_attrib();
        assert_eq!(ctx.get_integers(GL_ARRAY_BUFFER_BINDING), Some(vec![7]));
        assert!(ctx.is_buffer(7));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn current_bit_saves_the_current_attributes() {
        let mut ctx = context();
        ctx.set_color([0.5; 4]);
        ctx.set_edge_flag(false);
        let saved = ctx.state.current.clone();
        ctx.push_attrib(GL_CURRENT_BIT);
        ctx.set_color([0.25; 4]);
        ctx.set_edge_flag(true);
        ctx.multi_tex_coord(GL_TEXTURE1, [3.0; 4]);
        ctx.set_index(4.0);
        ctx.pop_attrib();
        assert_eq!(ctx.state.current, saved);
        ctx.push_attrib(GL_ALL_ATTRIB_BITS & !GL_CURRENT_BIT);
        ctx.set_color([0.75; 4]);
        ctx.pop_attrib();
        assert_eq!(ctx.state.current.color, [0.75; 4]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }
}
