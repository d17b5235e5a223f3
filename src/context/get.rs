//! glGetBooleanv/Integerv/Floatv/Doublev.
use super::Context;
use crate::api::types::*;

impl Context {
    pub fn get_booleans(&mut self, _pname: GLenum) -> Option<Vec<GLboolean>> {
        todo!()
    }
    pub fn get_integers(&mut self, _pname: GLenum) -> Option<Vec<GLint>> {
        todo!()
    }
    pub fn get_floats(&mut self, _pname: GLenum) -> Option<Vec<GLfloat>> {
        todo!()
    }
    pub fn get_doubles(&mut self, _pname: GLenum) -> Option<Vec<GLdouble>> {
        todo!()
    }
}
