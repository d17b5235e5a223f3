//! Selection and feedback entry points: glRenderMode, glSelectBuffer, the name stack,
//! glFeedbackBuffer and glPassThrough. The name stack commands and glPassThrough are compiled
//! into display lists; glRenderMode, glSelectBuffer and glFeedbackBuffer always execute.
use super::caller_memory;
use super::{record_or_run, with_context};
use crate::gl::types::*;

/// Copies the hit records to the caller's select buffer.
fn copy_records(address: usize, words: &[u32]) {
    // SAFETY: `address` is the buffer the caller gave glSelectBuffer, with room for its
    // `size` words; `words` holds at most that many (the context truncates to the size).
    unsafe { caller_memory::write_all(address as *mut GLuint, words.iter().copied()) }
}

#[no_mangle]
pub extern "C" fn glRenderMode(mode: GLenum) -> GLint {
    with_context(0, |ctx| {
        let result = ctx.render_mode(mode);
        if let Some((address, words)) = &result.copy {
            copy_records(*address, words);
        }
        if let Some((address, values)) = &result.feedback {
            // SAFETY: `address` is the buffer the caller gave glFeedbackBuffer, with room for
            // its `size` floats; `values` holds at most that many.
            unsafe { caller_memory::write_all(*address as *mut GLfloat, values.iter().copied()) }
        }
        result.value
    })
}

/// # Safety
/// `buffer` must have room for `size` GLuints until selection ends.
#[no_mangle]
pub unsafe extern "C" fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint) {
    with_context((), |ctx| ctx.select_buffer(size, buffer as usize))
}

#[no_mangle]
pub extern "C" fn glInitNames() {
    record_or_run(move |ctx| ctx.init_names())
}

#[no_mangle]
pub extern "C" fn glPushName(name: GLuint) {
    record_or_run(move |ctx| ctx.push_name(name))
}

#[no_mangle]
pub extern "C" fn glPopName() {
    record_or_run(move |ctx| ctx.pop_name())
}

#[no_mangle]
pub extern "C" fn glLoadName(name: GLuint) {
    record_or_run(move |ctx| ctx.load_name(name))
}

/// # Safety
/// `buffer` must have room for `size` GLfloats until feedback ends.
#[no_mangle]
pub unsafe extern "C" fn glFeedbackBuffer(size: GLsizei, type_: GLenum, buffer: *mut GLfloat) {
    with_context((), |ctx| ctx.feedback_buffer(size, type_, buffer as usize))
}

#[no_mangle]
pub extern "C" fn glPassThrough(token: GLfloat) {
    record_or_run(move |ctx| ctx.pass_through(token))
}
