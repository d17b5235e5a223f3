//! GLSL in tessera: the front end (the `tessera-glsl-front` crate, re-exported here: source →
//! a checked, typed program with Mesa's info log), the lowering of checked shaders onto the
//! shading IR of [`crate::shader`], and linking.
//!
//! - [`preprocess`], [`lex`], [`parse`], [`ast`], [`check`], [`hir`], [`builtins`], [`fold`],
//!   [`diagnostics`]: the front end ([`compile_shader`] is `glCompileShader`'s entry).
//! - [`lower`]: the checked units of one stage → a shading IR program, with its uniform,
//!   input, output and sampler interface by GL names.
//! - [`link`]: the shaders of a program → one interface (Mesa's link errors), the active
//!   uniforms and attributes with their locations, and the uniform values' storage.
//! - [`varyings`]: where a program's varyings sit in the vertex record.
#![deny(unsafe_code)]

pub use glsl_front::{ast, builtins, check, diagnostics, fold, hir, lex, parse, preprocess};
pub use glsl_front::{compile_shader, parse_shader, Checked, InfoLog, Limits, Options, Parsed, Stage};

pub mod link;
pub mod lower;
pub mod varyings;

#[cfg(test)]
mod tests;

// The front end's limits (`Limits::TESSERA`, what the compiler lets shaders use) are written
// out in its crate, which cannot see tessera's; they must be the ones glGet reports.
const _: () = {
    use crate::gl::limits::{
        MAX_CLIP_PLANES, MAX_DRAW_BUFFERS, MAX_LIGHTS, MAX_TEXTURE_COORDS, MAX_TEXTURE_IMAGE_UNITS, MAX_TEXTURE_UNITS,
        MAX_VERTEX_ATTRIBS,
    };
    let limits = Limits::TESSERA;
    assert!(limits.max_lights == MAX_LIGHTS as i32);
    assert!(limits.max_clip_planes == MAX_CLIP_PLANES as i32);
    assert!(limits.max_texture_units == MAX_TEXTURE_UNITS as i32);
    assert!(limits.max_texture_coords == MAX_TEXTURE_COORDS as i32);
    assert!(limits.max_vertex_attribs == MAX_VERTEX_ATTRIBS as i32);
    assert!(limits.max_varying_floats == varyings::MAX_VARYING_FLOATS as i32);
    assert!(limits.max_combined_texture_image_units == MAX_TEXTURE_IMAGE_UNITS as i32);
    assert!(limits.max_texture_image_units == MAX_TEXTURE_IMAGE_UNITS as i32);
    assert!(limits.max_draw_buffers == MAX_DRAW_BUFFERS as i32);
};
