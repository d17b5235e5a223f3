//! Window-system bindings: how a context gets a drawable and how the drawable is shown.
//! OSMesa renders into the caller's memory; GLX into X windows, pixmaps and pbuffers.
//!
//! `unsafe` is confined to the modules that call Xlib and the MIT-SHM extension through
//! their C ABI (`glx`, `glx_error`, `libx11`, `xfont`, `xshm`); the others may not use it.
#![deny(unsafe_code)]

#[allow(unsafe_code)]
pub mod glx;
pub mod glx_config;
#[allow(unsafe_code)]
pub mod glx_error;
#[allow(unsafe_code)]
mod libx11;
pub mod notice;
pub mod osmesa;
#[allow(unsafe_code)]
pub mod xfont;
#[allow(unsafe_code)]
mod xshm;
