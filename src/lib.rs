//! tessera: a software OpenGL 1.x/2.x implementation that C programs use without recompiling.
//!
//! The folders are the GL pipeline, and data flows one way through them:
//! `api` (the extern "C" edge) → `context` (the GL state machine) → `framebuffer` (buffers and
//! pixel formats, the only code that touches raw pixel memory), with `pixel` for the GL pixel
//! transfer formats and `winsys` for the window-system bindings (OSMesa, later GLX). Lower rooms
//! know nothing of the rooms above them: `framebuffer` knows formats, not GL enums.
//!
//! See `../shared/DESIGN.md` and the README for the rules that make it fast and exact.

pub mod api;
pub mod context;
pub mod fragment;
pub mod framebuffer;
pub mod gl;
pub mod pixel;
pub mod raster;
pub mod setup;
pub mod texture;
pub mod vertex;
pub mod winsys;
