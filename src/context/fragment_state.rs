//! Setters of the per-fragment operations' state (glDepthFunc, ...), with their validation.
use super::state::CompareFunc;
use super::Context;
use crate::api::enums::*;
use crate::api::types::GLenum;

impl Context {
    /// glDepthFunc.
    pub fn depth_func(&mut self, func: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        match CompareFunc::from_gl(func) {
            Some(f) => self.state.depth.func = f,
            None => self.error(GL_INVALID_ENUM),
        }
    }
}
