//! The client array commands: glXxxPointer, glEnableClientState, glClientActiveTexture,
//! glInterleavedArrays and glGetPointerv.
//!
//! GL 2.1 leaves these client-state commands undefined between glBegin and glEnd ("an error
//! may or may not be generated"); Mesa 22 generates GL_INVALID_OPERATION, and so does tessera.
//!
//! Deliberate differences from Mesa 22:
//! - Formats are GL 2.1's (table 2.4): no GL_HALF_FLOAT, packed or GL_BGRA arrays, and a
//!   secondary color array has 3 components only.
//! - An invalid call changes nothing. Mesa 22 records GL_INVALID_VALUE for a negative stride
//!   but still sets the array (stored as a 16-bit stride), and also refuses strides above
//!   GL 4.4's GL_MAX_VERTEX_ATTRIB_STRIDE (2048), still setting the array; GL 2.1 has no such
//!   limit, so tessera takes any non-negative stride.
//! - glClientActiveTexture takes the 4 units tessera has (Mesa: 8).
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::vertex::arrays::{ArrayId, InterleavedLayout};
use crate::vertex::components::ComponentType;

impl Context {
    /// Every glXxxPointer: validates the format of `id` and records it with the
    /// GL_ARRAY_BUFFER binding (when that is not 0, `pointer` is an offset into it).
    pub fn array_pointer(&mut self, id: ArrayId, size: i32, type_: GLenum, stride: i32, pointer: usize) {
        if !self.check_outside_begin_end() {
            return;
        }
        match id.check_pointer(size, type_, stride) {
            Ok(component) => self.set_array(id, size, component, stride, pointer),
            Err(error) => self.error(error),
        }
    }

    fn set_array(&mut self, id: ArrayId, size: i32, component: ComponentType, stride: i32, pointer: usize) {
        let buffer = self.vertex_input.arrays.array_buffer;
        self.vertex_input.arrays.get_mut(id).specify(size, component, stride, pointer, buffer);
    }

    /// glVertexPointer.
    pub fn vertex_pointer(&mut self, size: i32, type_: GLenum, stride: i32, pointer: usize) {
        self.array_pointer(ArrayId::Vertex, size, type_, stride, pointer)
    }

    /// glNormalPointer.
    pub fn normal_pointer(&mut self, type_: GLenum, stride: i32, pointer: usize) {
        self.array_pointer(ArrayId::Normal, 3, type_, stride, pointer)
    }

    /// glColorPointer.
    pub fn color_pointer(&mut self, size: i32, type_: GLenum, stride: i32, pointer: usize) {
        self.array_pointer(ArrayId::Color, size, type_, stride, pointer)
    }

    /// glSecondaryColorPointer.
    pub fn secondary_color_pointer(&mut self, size: i32, type_: GLenum, stride: i32, pointer: usize) {
        self.array_pointer(ArrayId::SecondaryColor, size, type_, stride, pointer)
    }

    /// glFogCoordPointer.
    pub fn fog_coord_pointer(&mut self, type_: GLenum, stride: i32, pointer: usize) {
        self.array_pointer(ArrayId::FogCoord, 1, type_, stride, pointer)
    }

    /// glIndexPointer.
    pub fn index_pointer(&mut self, type_: GLenum, stride: i32, pointer: usize) {
        self.array_pointer(ArrayId::Index, 1, type_, stride, pointer)
    }

    /// glEdgeFlagPointer: GLboolean elements.
    pub fn edge_flag_pointer(&mut self, stride: i32, pointer: usize) {
        self.array_pointer(ArrayId::EdgeFlag, 1, GL_UNSIGNED_BYTE, stride, pointer)
    }

    /// glTexCoordPointer: the array of the client active texture unit.
    pub fn tex_coord_pointer(&mut self, size: i32, type_: GLenum, stride: i32, pointer: usize) {
        let id = self.vertex_input.arrays.active_tex_coord();
        self.array_pointer(id, size, type_, stride, pointer)
    }

    /// glEnableClientState / glDisableClientState.
    pub fn enable_client_state(&mut self, cap: GLenum, on: bool) {
        if !self.check_outside_begin_end() {
            return;
        }
        match self.client_array_enable(cap) {
            Some(enabled) => *enabled = on,
            None => self.error(GL_INVALID_ENUM),
        }
    }

    /// glClientActiveTexture.
    pub fn client_active_texture(&mut self, texture: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        match super::immediate::texture_unit(texture) {
            Some(unit) => self.vertex_input.arrays.client_active_texture = unit,
            None => self.error(GL_INVALID_ENUM),
        }
    }

    /// glInterleavedArrays: sets and enables the arrays of `format` (texture coordinates of
    /// the client active unit only) and disables the others of table 2.5 and the edge flag
    /// and index arrays. Like Mesa, the secondary color and fog coordinate arrays are left
    /// alone (the pseudo-code of the GL 2.1 specification does not name them).
    pub fn interleaved_arrays(&mut self, format: GLenum, stride: i32, pointer: usize) {
        if !self.check_outside_begin_end() {
            return;
        }
        if stride < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        let Some(layout) = InterleavedLayout::from_gl(format) else {
            return self.error(GL_INVALID_ENUM);
        };
        let stride = if stride == 0 { layout.stride as i32 } else { stride };
        let at = |offset: usize| pointer.wrapping_add(offset);
        self.vertex_input.arrays.edge_flag.enabled = false;
        self.vertex_input.arrays.index.enabled = false;
        let tex = self.vertex_input.arrays.active_tex_coord();
        let parts = [
            (tex, layout.tex_coords.map(|(size, offset)| (size, ComponentType::Float, offset))),
            (ArrayId::Color, layout.color),
            (ArrayId::Normal, layout.normal.map(|offset| (3, ComponentType::Float, offset))),
            (ArrayId::Vertex, Some((layout.vertex.0, ComponentType::Float, layout.vertex.1))),
        ];
        for (id, part) in parts {
            if let Some((size, component, offset)) = part {
                self.set_array(id, size, component, stride, at(offset));
            }
            self.vertex_input.arrays.get_mut(id).enabled = part.is_some();
        }
    }

    /// glGetPointerv: the pointer (or buffer offset) of an array; the feedback and selection
    /// buffer pointers are null (those modes do not exist yet). `None`: an error was recorded.
    pub fn get_pointer(&mut self, pname: GLenum) -> Option<usize> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if matches!(pname, GL_FEEDBACK_BUFFER_POINTER | GL_SELECTION_BUFFER_POINTER) {
            return Some(self.selection.buffer_pointer(pname));
        }
        match self.vertex_input.arrays.array_of_pointer_name(pname) {
            Some(id) => Some(self.vertex_input.arrays.get(id).pointer),
            None => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_support::*;
    use super::*;
    use crate::gl::limits::{MAX_TEXTURE_COORDS, MAX_TEXTURE_UNITS};

    #[test]
    fn pointers_record_format_and_buffer_binding() {
        let mut ctx = context();
        ctx.color_pointer(3, GL_UNSIGNED_SHORT, 8, 0x1000);
        let color = ctx.vertex_input.arrays.color;
        assert_eq!(
            (color.size, color.component, color.stride, color.pointer, color.buffer),
            (3, ComponentType::UnsignedShort, 8, 0x1000, 0)
        );
        ctx.bind_buffer(GL_ARRAY_BUFFER, 5);
        ctx.vertex_pointer(2, GL_DOUBLE, 0, 16);
        ctx.edge_flag_pointer(3, 7);
        assert_eq!(ctx.vertex_input.arrays.vertex.buffer, 5);
        assert_eq!(ctx.vertex_input.arrays.edge_flag.stride, 3);
        assert_eq!(ctx.vertex_input.arrays.edge_flag.buffer, 5);
        assert_eq!(ctx.get_integers(GL_VERTEX_ARRAY_BUFFER_BINDING), Some(vec![5]));
        assert_eq!(ctx.get_integers(GL_COLOR_ARRAY_BUFFER_BINDING), Some(vec![0]));
        assert_eq!(ctx.get_pointer(GL_VERTEX_ARRAY_POINTER), Some(16));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn invalid_pointers_change_nothing() {
        let mut ctx = context();
        let before = ctx.vertex_input.arrays.clone();
        ctx.vertex_pointer(3, GL_FLOAT, -1, 5);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.normal_pointer(GL_UNSIGNED_INT, 0, 5);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.secondary_color_pointer(4, GL_FLOAT, 0, 5);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.fog_coord_pointer(GL_SHORT, 0, 5);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.index_pointer(GL_UNSIGNED_SHORT, 0, 5);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.tex_coord_pointer(5, GL_FLOAT, 0, 5);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.edge_flag_pointer(-4, 5);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.inside_begin_end = true;
        ctx.color_pointer(4, GL_FLOAT, 0, 5);
        ctx.enable_client_state(GL_COLOR_ARRAY, true);
        ctx.client_active_texture(GL_TEXTURE1);
        ctx.interleaved_arrays(GL_V2F, 0, 5);
        assert_eq!(ctx.get_pointer(GL_COLOR_ARRAY_POINTER), None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.inside_begin_end = false;
        assert_eq!(ctx.vertex_input.arrays, before);
    }

    #[test]
    fn client_state_enables_and_active_unit() {
        let mut ctx = context();
        ctx.enable_client_state(GL_FOG_COORD_ARRAY, true);
        ctx.enable_client_state(GL_TEXTURE_2D, true);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert!(ctx.vertex_input.arrays.fog_coord.enabled);
        ctx.client_active_texture(GL_TEXTURE0 + MAX_TEXTURE_COORDS as GLenum);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        // The sets past the fixed-function units have arrays too.
        ctx.client_active_texture(GL_TEXTURE0 + MAX_TEXTURE_UNITS as GLenum + 1);
        ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY, true);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert!(ctx.vertex_input.arrays.tex_coords[MAX_TEXTURE_UNITS + 1].enabled);
        ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY, false);
        ctx.client_active_texture(GL_TEXTURE3);
        ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY, true);
        assert!(ctx.vertex_input.arrays.tex_coords[3].enabled);
        assert!(!ctx.vertex_input.arrays.tex_coords[0].enabled);
        // glEnable and glIsEnabled address the client arrays too, as in Mesa.
        ctx.set_capability(GL_EDGE_FLAG_ARRAY, true);
        assert!(ctx.vertex_input.arrays.edge_flag.enabled);
        assert_eq!(ctx.is_enabled(GL_TEXTURE_COORD_ARRAY), GL_TRUE);
        ctx.set_capability(GL_TEXTURE_COORD_ARRAY, false);
        assert!(!ctx.vertex_input.arrays.tex_coords[3].enabled);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn interleaved_arrays_set_enable_and_disable() {
        let mut ctx = context();
        for cap in [GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY, GL_FOG_COORD_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY] {
            ctx.enable_client_state(cap, true);
        }
        ctx.client_active_texture(GL_TEXTURE1);
        ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY, true);
        ctx.interleaved_arrays(GL_T2F_C4UB_V3F, 0, 0x1000);
        let a = &ctx.vertex_input.arrays;
        assert!(a.vertex.enabled && a.color.enabled && a.tex_coords[1].enabled);
        assert!(!a.normal.enabled && !a.index.enabled && !a.edge_flag.enabled);
        // Untouched: the fog coordinate array and the other unit's texture array.
        assert!(a.fog_coord.enabled && a.tex_coords[0].enabled);
        assert_eq!((a.tex_coords[1].size, a.tex_coords[1].pointer, a.tex_coords[1].stride), (2, 0x1000, 24));
        assert_eq!((a.color.size, a.color.component, a.color.pointer), (4, ComponentType::UnsignedByte, 0x1008));
        assert_eq!((a.vertex.size, a.vertex.pointer, a.vertex.stride), (3, 0x100c, 24));
        ctx.interleaved_arrays(GL_N3F_V3F, 100, 0);
        let a = &ctx.vertex_input.arrays;
        assert!(!a.color.enabled && !a.tex_coords[1].enabled && a.normal.enabled);
        assert_eq!((a.normal.stride, a.normal.pointer, a.vertex.pointer), (100, 0, 12));
        let before = ctx.vertex_input.arrays.clone();
        ctx.interleaved_arrays(GL_V2F, -1, 0);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.interleaved_arrays(GL_T4F_C4F_N3F_V4F + 1, 0, 0);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.vertex_input.arrays, before);
    }

    #[test]
    fn get_pointer_names() {
        let mut ctx = context();
        ctx.fog_coord_pointer(GL_DOUBLE, 0, 0x77);
        assert_eq!(ctx.get_pointer(GL_FOG_COORD_ARRAY_POINTER), Some(0x77));
        assert_eq!(ctx.get_pointer(GL_FEEDBACK_BUFFER_POINTER), Some(0));
        assert_eq!(ctx.get_pointer(GL_VERTEX_ARRAY), None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
    }
}
