//! Window-system bindings: how a context gets a drawable and how the drawable is shown.
//! OSMesa renders into the caller's memory; GLX into X windows, pixmaps and pbuffers.

pub mod glx;
pub mod glx_config;
pub mod glx_error;
pub mod notice;
pub mod osmesa;
pub mod xfont;
mod xshm;
