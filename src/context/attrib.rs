//! glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib.
use super::Context;

/// One glPushAttrib entry.
pub struct SavedAttribs {}

/// One glPushClientAttrib entry.
pub struct SavedClientAttribs {}

impl Context {
    pub fn push_attrib(&mut self, _mask: u32) {
        todo!()
    }
    pub fn pop_attrib(&mut self) {
        todo!()
    }
    pub fn push_client_attrib(&mut self, _mask: u32) {
        todo!()
    }
    pub fn pop_client_attrib(&mut self) {
        todo!()
    }
}
