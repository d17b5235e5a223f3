//! tessera's own entry points (not in any system header): the accuracy mode of the current
//! context (see `setup::accuracy` and the README's "Accuracy modes"). The mode codes are
//! literals so that cbindgen writes them into `GL/tessera.h`.
use super::with_context;
use crate::gl::enums::*;
use crate::gl::types::*;
use crate::setup::accuracy::Accuracy;

/// Perspective-correct f32 interpolation; the default, compared with Mesa by the tests.
pub const TESSERA_ACCURACY_CONFORMANT: GLint = 0;
/// Affine interpolation, no dithering.
pub const TESSERA_ACCURACY_FAST: GLint = 1;
/// Attributes from f64 barycentric coordinates at every pixel (the reference).
pub const TESSERA_ACCURACY_EXACT: GLint = 2;

/// Sets the current context's accuracy mode for the draws that follow. An unknown mode is
/// GL_INVALID_ENUM, and a call between glBegin and glEnd GL_INVALID_OPERATION; both change
/// nothing.
#[no_mangle]
pub extern "C" fn tesseraSetAccuracy(mode: GLint) {
    with_context((), |ctx| {
        if !ctx.check_outside_begin_end() {
            return;
        }
        match Accuracy::from_code(mode) {
            Some(accuracy) => ctx.accuracy = accuracy,
            None => ctx.error(GL_INVALID_ENUM),
        }
    })
}

/// The current context's accuracy mode (`TESSERA_ACCURACY_*`); -1 without a current context.
#[no_mangle]
pub extern "C" fn tesseraGetAccuracy() -> GLint {
    with_context(-1, |ctx| ctx.accuracy as GLint)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_constants_are_the_mode_codes() {
        assert_eq!(Accuracy::from_code(TESSERA_ACCURACY_CONFORMANT), Some(Accuracy::Conformant));
        assert_eq!(Accuracy::from_code(TESSERA_ACCURACY_FAST), Some(Accuracy::Fast));
        assert_eq!(Accuracy::from_code(TESSERA_ACCURACY_EXACT), Some(Accuracy::Exact));
    }
}
