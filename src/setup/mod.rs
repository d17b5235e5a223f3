//! Primitive setup: window-space primitives → fixed-point edge functions, exact per-row
//! coverage, attribute planes and bounding boxes, made into jobs and binned into the tiles
//! of the [`Scene`] they may touch.
//!
//! The rasterization contract (DESIGN.md): 8 subpixel bits, pixel centres at +0.5, the
//! top-left fill rule, and edge functions evaluated in 64-bit integers so no input that
//! survives clipping can overflow. Coverage is computed per row as a span solved exactly
//! from the edge equations, so a pixel is covered iff its centre is inside by exact
//! integer arithmetic, whatever the triangle's size or shape.
//!
//! - the shapes: [`triangle`] and [`line`] (edges and row solves), [`point`], [`smooth`]
//!   (antialiasing coverage), [`multisample`] (sample positions and sample-covered quads),
//!   with the rounding divisions of [`fixed`];
//! - the attributes: [`plane`] (planes, shading, varyings), chosen per [`accuracy`] mode;
//! - the [`jobs`]: a set-up primitive with its planes, and how it renders inside a tile
//!   (its coverage walked by `raster`, its spans shaded by `fragment`);
//! - the [`scene`]: draw states, jobs and bins, handed to the tile workers at a flush.
#![deny(unsafe_code)]

pub mod accuracy;
pub mod fixed;
pub mod jobs;
pub mod line;
pub mod multisample;
pub mod plane;
pub mod point;
pub mod scene;
pub mod smooth;
pub mod triangle;

pub use scene::{Primitive, Scene};
