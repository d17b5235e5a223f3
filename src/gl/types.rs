//! The C types of the GL and OSMesa ABI, as `<GL/gl.h>` and `<GL/osmesa.h>` declare them.
//!
//! cbindgen does not emit these typedefs (see cbindgen.toml): the header writes them itself,
//! guarded so that it can be included together with the system's GL headers.
#![allow(non_camel_case_types)]
use libc::{c_char, c_double, c_float, c_int, c_schar, c_short, c_uchar, c_uint, c_ushort, c_void};

pub type GLenum = c_uint;
pub type GLboolean = c_uchar;
pub type GLbitfield = c_uint;
pub type GLvoid = c_void;
pub type GLbyte = c_schar;
pub type GLshort = c_short;
pub type GLint = c_int;
pub type GLubyte = c_uchar;
pub type GLushort = c_ushort;
pub type GLuint = c_uint;
pub type GLsizei = c_int;
pub type GLfloat = c_float;
pub type GLclampf = c_float;
pub type GLdouble = c_double;
pub type GLclampd = c_double;
pub type GLchar = c_char;
pub type GLintptr = isize;
pub type GLsizeiptr = isize;

/// The opaque context type behind `OSMesaContext`; C never sees inside.
#[repr(C)]
pub struct osmesa_context {
    _opaque: [u8; 0],
}

/// `typedef struct osmesa_context *OSMesaContext;`
pub type OSMesaContext = *mut osmesa_context;

/// `typedef void (*OSMESAproc)();`: what OSMesaGetProcAddress returns.
pub type OSMESAproc = Option<unsafe extern "C" fn()>;
