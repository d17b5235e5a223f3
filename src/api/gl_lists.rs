//! Display list entry points: glNewList, glEndList, glCallList, glCallLists, glListBase,
//! glGenLists, glDeleteLists, glIsList.
//!
//! glCallList, glCallLists and glListBase are themselves compiled into lists; glCallLists
//! copies its names when it is issued and adds the list base when it runs. The others always
//! execute (GL 2.1 section 5.4).
use super::caller_memory;
use super::{record_or_run, with_context};
use crate::context::lists::{call_lists_type_size, decode_call_lists};
use crate::gl::enums::*;
use crate::gl::types::*;

#[no_mangle]
pub extern "C" fn glNewList(list: GLuint, mode: GLenum) {
    with_context((), |ctx| ctx.new_list(list, mode))
}

#[no_mangle]
pub extern "C" fn glEndList() {
    with_context((), |ctx| ctx.end_list())
}

#[no_mangle]
pub extern "C" fn glCallList(list: GLuint) {
    record_or_run(move |ctx| ctx.call_list(list))
}

/// # Safety
/// `lists` must point to `n` names of `type_` (it is not read when `n` or `type_` is invalid).
#[no_mangle]
pub unsafe extern "C" fn glCallLists(n: GLsizei, type_: GLenum, lists: *const GLvoid) {
    let offsets = if n < 0 {
        Err(GL_INVALID_VALUE)
    } else {
        match call_lists_type_size(type_) {
            None => Err(GL_INVALID_ENUM),
            Some(_) if n == 0 || lists.is_null() => Ok(Vec::new()),
            Some(size) => {
                // SAFETY: the caller passes `n` names of `type_`, `size` bytes each.
                let bytes = unsafe { caller_memory::bytes(lists, 0..n as usize * size) }.unwrap_or_default();
                Ok(decode_call_lists(type_, bytes))
            }
        }
    };
    record_or_run(move |ctx| ctx.call_lists(&offsets))
}

#[no_mangle]
pub extern "C" fn glListBase(base: GLuint) {
    record_or_run(move |ctx| ctx.list_base(base))
}

#[no_mangle]
pub extern "C" fn glGenLists(range: GLsizei) -> GLuint {
    with_context(0, |ctx| ctx.gen_lists(range))
}

#[no_mangle]
pub extern "C" fn glDeleteLists(list: GLuint, range: GLsizei) {
    with_context((), |ctx| ctx.delete_lists(list, range))
}

#[no_mangle]
pub extern "C" fn glIsList(list: GLuint) -> GLboolean {
    with_context(GL_FALSE, |ctx| if ctx.is_list(list) { GL_TRUE } else { GL_FALSE })
}
