//! Programs: the shading IR that vertex processing and fragment shading are written in, its
//! validator and text dump, and the executor that runs a program over the 16 lanes of a
//! block. The fixed-function generators and the GLSL front end compile into it; `vertex`
//! and `fragment` run what they produce.
//!
//! - [`ir`]: the program form. Scalar registers of four types (f32, i32, u32, bool; GLSL's
//!   vectors and matrices are lowered to scalars by whoever builds the program), typed
//!   operations, and structured control flow (if/else, loops with break and continue,
//!   return, discard), which is what GLSL has and what masked execution over lanes wants.
//! - [`validate`]: checks a program before it runs (types, slots, where break, continue,
//!   discard and derivatives may appear, nesting depth), so the executor trusts it.
//! - [`dump`]: the text form of a program (`TESSERA_DEBUG=programs`).
//! - [`lower`] and [`fast`]: the executor the pipeline runs: a program pre-decoded once
//!   (constants folded, dead code dropped, uniform values scalar, fused operations) and
//!   interpreted over a file of 16-lane words, bit-identical to [`exec`] (tested on random
//!   programs); `fast`'s docs say why an interpreter, with measurements.
//! - [`flatten`]: loops of known trip counts unrolled and pure `if`s made selects before
//!   lowering, so that typical GLSL programs run as straight code.
//! - [`specialize`]: a program specialised on a draw's uniform values (selects on them
//!   made copies, what they decide computed once, dead arms dropped).
//! - [`group`]: consecutive operations of one kind (a `vec4`'s components) made one
//!   operation of the interpreter.
//! - [`cache`]: compiled programs by the key of the state that shaped them, least recently
//!   used evicted first (one cache per share group).
//! - [`exec`]: the reference: runs a validated program over 16 lanes with execution masks, statement by statement; the arithmetic
//!   is IEEE add, sub, mul, div and sqrt rounded once each (no contraction), and
//!   [`math`]'s own polynomials for exp2, log2, sin and cos, so every SIMD level and every
//!   CPU gives the same bytes.
#![deny(unsafe_code)]

pub mod build;
pub mod cache;
pub mod dump;
pub mod exec;
pub mod fast;
pub mod flatten;
pub mod group;
pub mod ir;
pub mod lower;
pub mod math;
pub mod specialize;
pub mod validate;

#[cfg(test)]
mod bench;
#[cfg(test)]
mod tests;
