//! Entry points that are other names of existing ones, added so that an extension tessera
//! advertises has every entry point (GL_ATI_separate_stencil).
use super::types::*;
use super::with_context;

/// GL_ATI_separate_stencil's name of glStencilOpSeparate (same arguments and rules).
#[no_mangle]
pub extern "C" fn glStencilOpSeparateATI(face: GLenum, sfail: GLenum, dpfail: GLenum, dppass: GLenum) {
    with_context((), |ctx| ctx.stencil_op_separate(face, sfail, dpfail, dppass))
}
