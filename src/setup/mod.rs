//! Primitive setup: window-space primitives → fixed-point edge functions, exact per-row
//! coverage spans and attribute planes, ready for binning into tiles.
//!
//! The rasterization contract (DESIGN.md): 8 subpixel bits, pixel centres at +0.5, the
//! top-left fill rule, and edge functions evaluated in 64-bit integers so no input that
//! survives clipping can overflow. Coverage is computed per row as a span solved exactly
//! from the three edge equations, so a pixel is covered iff its centre is inside by exact
//! integer arithmetic, whatever the triangle's size or shape.

pub mod line;
pub mod multisample;
pub mod point;
pub mod smooth;
pub mod triangle;
