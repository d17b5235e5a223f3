//! The GL vocabulary: enum values, C types, implementation limits, the small value types
//! every room shares (the comparison function, the name space of GL objects, exact float
//! operations without libm) and the
//! constants of the window-system
//! headers (`<GL/osmesa.h>`, `<GL/glx.h>`).
//!
//! This is the bottom room: every other room may import it, and it imports nothing of the
//! crate. cbindgen reads `enums.rs` and `osmesa.rs` for the `#define`s of `include/GL/tessera.h`.
#![deny(unsafe_code)]

pub mod compare;
pub mod enums;
pub mod float;
pub mod glx;
pub mod limits;
pub mod names;
pub mod osmesa;
#[cfg(test)]
pub mod test_rng;
pub mod types;

pub use compare::CompareFunc;
