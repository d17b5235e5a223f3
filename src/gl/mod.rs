//! The GL vocabulary: enum values, C types, implementation limits and the small value types
//! every room shares (the comparison function).
//!
//! This is the bottom room: every other room may import it, and it imports nothing of the
//! crate. cbindgen reads `enums.rs` for the `#define`s of `include/GL/tessera.h`.

pub mod compare;
pub mod enums;
pub mod limits;
pub mod types;

pub use compare::CompareFunc;
