//! Selection entry points: glRenderMode, glSelectBuffer and the name stack. The name stack
//! commands are compiled into display lists; glRenderMode and glSelectBuffer always execute.
use super::types::*;
use super::{record_or_run, with_context};

/// Copies the hit records to the caller's select buffer.
fn copy_records(address: usize, words: &[u32]) {
    // SAFETY: `address` is the buffer the caller gave glSelectBuffer, with room for its
    // `size` words; `words` holds at most that many (the context truncates to the size).
    unsafe { std::ptr::copy_nonoverlapping(words.as_ptr(), address as *mut GLuint, words.len()) }
}

#[no_mangle]
pub extern "C" fn glRenderMode(mode: GLenum) -> GLint {
    with_context(0, |ctx| {
        let result = ctx.render_mode(mode);
        if let Some((address, words)) = &result.copy {
            copy_records(*address, words);
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
