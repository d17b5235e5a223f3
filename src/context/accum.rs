//! glAccum and the accumulation buffer clear.
use super::Context;
use crate::api::types::GLenum;
use crate::framebuffer::{AccumBuffer, Rect};

/// Clears `rect` of the accumulation buffer to `value` (each in [-1, 1]).
pub fn clear(_accum: &mut AccumBuffer, _rect: Rect, _value: [f32; 4]) {
    todo!("accum clear")
}

impl Context {
    /// glAccum.
    pub fn accum(&mut self, _op: GLenum, _value: f32) {
        todo!("glAccum")
    }
}
