//! The constants of Mesa's `<GL/osmesa.h>`: pixel formats of OSMesaCreateContext*, the
//! OSMesaPixelStore/OSMesaGetIntegerv parameters and the OSMesaCreateContextAttribs keys.
//!
//! cbindgen reads this file too, so the `OSMESA_*` `#define`s of `include/GL/tessera.h` are
//! checked against the system's `<GL/osmesa.h>`.
use super::enums::{GL_COLOR_INDEX, GL_RGB, GL_RGBA};
use super::types::{GLenum, GLint};
use std::ffi::c_int;

pub const OSMESA_COLOR_INDEX: GLenum = GL_COLOR_INDEX;
pub const OSMESA_RGBA: GLenum = GL_RGBA;
pub const OSMESA_BGRA: GLenum = 0x1;
pub const OSMESA_ARGB: GLenum = 0x2;
pub const OSMESA_RGB: GLenum = GL_RGB;
pub const OSMESA_BGR: GLenum = 0x4;
pub const OSMESA_RGB_565: GLenum = 0x5;
pub const OSMESA_ROW_LENGTH: GLint = 0x10;
pub const OSMESA_Y_UP: GLint = 0x11;
pub const OSMESA_WIDTH: GLint = 0x20;
pub const OSMESA_HEIGHT: GLint = 0x21;
pub const OSMESA_FORMAT: GLint = 0x22;
pub const OSMESA_TYPE: GLint = 0x23;
pub const OSMESA_MAX_WIDTH: GLint = 0x24;
pub const OSMESA_MAX_HEIGHT: GLint = 0x25;
pub const OSMESA_DEPTH_BITS: c_int = 0x30;
pub const OSMESA_STENCIL_BITS: c_int = 0x31;
pub const OSMESA_ACCUM_BITS: c_int = 0x32;
pub const OSMESA_PROFILE: c_int = 0x33;
pub const OSMESA_CORE_PROFILE: c_int = 0x34;
pub const OSMESA_COMPAT_PROFILE: c_int = 0x35;
pub const OSMESA_CONTEXT_MAJOR_VERSION: c_int = 0x36;
pub const OSMESA_CONTEXT_MINOR_VERSION: c_int = 0x37;
