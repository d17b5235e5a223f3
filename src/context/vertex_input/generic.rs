//! Generic vertex attributes (GL 2.0 section 2.7 and 2.8): glVertexAttrib's current values,
//! glVertexAttribPointer's arrays and their queries.
//!
//! Attribute 0 is the vertex position: glVertexAttrib*(0, …) is glVertex, and an enabled
//! array 0 takes precedence over the vertex array in draws
//! ([`ClientArrays::position`](crate::vertex::arrays::ClientArrays::position)). The other
//! attributes are recorded and queried; they reach the vertex stage with GLSL programs.
//!
//! Where Mesa 22 differs (capi-tests/vertex_attributes.c says so too): a
//! glVertexAttribPointer with a negative stride records GL_INVALID_VALUE and, in Mesa, still
//! changes the array; here it changes nothing. A glGetVertexAttrib* that records an error
//! writes nothing here, where Mesa writes 0.
use super::super::Context;
use crate::gl::enums::*;
use crate::gl::limits::MAX_VERTEX_ATTRIBS;
use crate::gl::types::GLenum;
use crate::vertex::components::ComponentType;
use crate::vertex::generic::CURRENT;

/// A glGetVertexAttrib* answer: four values for GL_CURRENT_VERTEX_ATTRIB, else one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AttribValue {
    Current([f32; 4]),
    One(i64),
}

impl AttribValue {
    /// The values as glGetVertexAttribfv/dv return them.
    pub fn floats(self) -> Vec<f64> {
        match self {
            AttribValue::Current(v) => v.iter().map(|&c| f64::from(c)).collect(),
            AttribValue::One(n) => vec![n as f64],
        }
    }

    /// The values as glGetVertexAttribiv returns them: current values truncated toward zero
    /// as Mesa does, a value outside the integers' range (or NaN) becoming i32::MIN as x86's
    /// conversion makes it.
    pub fn integers(self) -> Vec<i32> {
        let truncate = |c: f32| {
            if (-2_147_483_648.0..2_147_483_648.0).contains(&c) {
                c as i32
            } else {
                i32::MIN
            }
        };
        match self {
            AttribValue::Current(v) => v.iter().map(|&c| truncate(c)).collect(),
            AttribValue::One(n) => vec![n as i32],
        }
    }
}

impl Context {
    /// The generic attribute `index` (GL_INVALID_VALUE beyond GL_MAX_VERTEX_ATTRIBS).
    fn generic_index(&mut self, index: u32) -> Option<usize> {
        let index = index as usize;
        if index >= MAX_VERTEX_ATTRIBS {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        Some(index)
    }

    /// Every glVertexAttrib form, its components already converted: attribute 0 between
    /// glBegin and glEnd is a glVertex; outside them it sets attribute 0's current value, as
    /// the others do, which a GLSL vertex shader reads when no array feeds attribute 0
    /// (Mesa's behaviour; piglit gl-2.0-vertex-const-attr).
    pub fn vertex_attrib(&mut self, index: u32, value: [f32; 4]) {
        match self.generic_index(index) {
            Some(0) if self.inside_begin_end => self.vertex_xyzw(value[0], value[1], value[2], value[3]),
            Some(index) => self.set_generic(index, value),
            None => {}
        }
    }

    /// Sets generic attribute `index`'s current value. Between glBegin and glEnd the open
    /// vertices keep the values they were made with: the first change there puts the values
    /// before it in a row (which the open vertices then name), and each change after a
    /// glVertex starts a new row for the vertices to come ([`crate::vertex::generic`]).
    pub(super) fn set_generic(&mut self, index: usize, value: [f32; 4]) {
        let current = &mut self.state.current;
        let before = current.generic;
        current.generic[index] = value;
        if !self.inside_begin_end {
            return;
        }
        let input = &mut self.vertex_input;
        if current.generic_row == CURRENT {
            let row = input.generic_rows.push(before);
            for v in input.vertices.iter_mut() {
                v.generic = row;
            }
            current.generic_row = row;
        }
        let row = current.generic_row;
        if input.vertices.last().is_some_and(|v| v.generic == row) {
            current.generic_row = input.generic_rows.push(current.generic);
        } else {
            input.generic_rows.rows[row as usize] = current.generic;
        }
    }

    /// Drops the generic attribute rows of glBegin/glEnd (at glBegin and after glEnd's
    /// delivery): vertices made afterwards read the current values until glVertexAttrib
    /// changes them inside glBegin/glEnd again.
    pub(super) fn forget_generic_rows(&mut self) {
        if self.state.current.generic_row != CURRENT || !self.vertex_input.generic_rows.rows.is_empty() {
            self.vertex_input.generic_rows.clear();
            self.state.current.generic_row = CURRENT;
        }
    }

    /// glVertexAttribPointer: validated in Mesa's order (index, stride, type, size).
    pub fn vertex_attrib_pointer(
        &mut self,
        index: u32,
        size: i32,
        type_: GLenum,
        normalized: bool,
        stride: i32,
        pointer: usize,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(index) = self.generic_index(index) else { return };
        let component = match ComponentType::from_gl(type_) {
            _ if stride < 0 => return self.error(GL_INVALID_VALUE),
            Some(component) => component,
            None => return self.error(GL_INVALID_ENUM),
        };
        if !(1..=4).contains(&size) {
            return self.error(GL_INVALID_VALUE);
        }
        let buffer = self.vertex_input.arrays.array_buffer;
        let array = &mut self.vertex_input.arrays.generic[index];
        array.specify(size, component, stride, pointer, buffer);
        array.normalized = normalized;
    }

    /// glEnableVertexAttribArray / glDisableVertexAttribArray.
    pub fn enable_vertex_attrib_array(&mut self, index: u32, on: bool) {
        if !self.check_outside_begin_end() {
            return;
        }
        if let Some(index) = self.generic_index(index) {
            self.vertex_input.arrays.generic[index].enabled = on;
        }
    }

    /// glGetVertexAttrib{f,d,i}v. Generic attribute 0 has no current value
    /// (GL_INVALID_OPERATION).
    pub fn get_vertex_attrib(&mut self, index: u32, pname: GLenum) -> Option<AttribValue> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let index = self.generic_index(index)?;
        let array = &self.vertex_input.arrays.generic[index];
        let one = |n: i64| Some(AttribValue::One(n));
        match pname {
            GL_CURRENT_VERTEX_ATTRIB if index == 0 => {
                self.error(GL_INVALID_OPERATION);
                None
            }
            GL_CURRENT_VERTEX_ATTRIB => Some(AttribValue::Current(self.state.current.generic[index])),
            GL_VERTEX_ATTRIB_ARRAY_ENABLED => one(array.enabled as i64),
            GL_VERTEX_ATTRIB_ARRAY_SIZE => one(array.size.into()),
            GL_VERTEX_ATTRIB_ARRAY_STRIDE => one(array.stride.into()),
            GL_VERTEX_ATTRIB_ARRAY_TYPE => one(array.component.to_gl().into()),
            GL_VERTEX_ATTRIB_ARRAY_NORMALIZED => one(array.normalized as i64),
            GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING => one(array.buffer.into()),
            _ => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glGetVertexAttribPointerv.
    pub fn get_vertex_attrib_pointer(&mut self, index: u32, pname: GLenum) -> Option<usize> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let index = self.generic_index(index)?;
        if pname != GL_VERTEX_ATTRIB_ARRAY_POINTER {
            self.error(GL_INVALID_ENUM);
            return None;
        }
        Some(self.vertex_input.arrays.generic[index].pointer)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_queries_truncate_and_send_the_unrepresentable_to_the_minimum() {
        let value = AttribValue::Current([-0.99, 2.5, f32::INFINITY, 2_147_483_648.0]);
        assert_eq!(value.integers(), [0, 2, i32::MIN, i32::MIN]);
        assert_eq!(
            AttribValue::Current([f32::NAN, -2_147_483_648.0, -3.75, 0.0]).integers(),
            [i32::MIN, i32::MIN, -3, 0]
        );
        assert_eq!(AttribValue::One(0x1406).floats(), [5126.0]);
    }
}
