//! The GLSL front end: GLSL 1.10 and 1.20 shader source → a checked, typed program
//! ([`hir`]) for one stage, with an info log worded as Mesa's. [`compile_shader`] is the entry
//! point for `glCompileShader`; tessera's `glsl` module lowers the result onto its shading IR
//! and links programs.
//!
//! It is a crate of its own only so that it can be compiled for size (the workspace's
//! Cargo.toml says why): compiling runs once per shader, never per pixel or vertex.
//!
//! - [`preprocess`]: directives, conditionals and macro expansion over tokens.
//! - [`lex`]: source → preprocessing tokens → GLSL tokens of the shader's version.
//! - [`parse`]: recursive descent over the grammar of chapter 9 into [`ast`].
//! - [`check`]: semantic analysis into [`hir`], with the built-ins of [`builtins`] and the
//!   constant folding of [`fold`].
//! - [`diagnostics`]: positions and the info log (`0:12(5): error: ...`).
//!
//! As in Mesa, preprocessor errors end the compile before parsing, and the first syntax
//! error ends the parse; semantic errors are all reported. Nothing here is tied to a GL
//! context.
#![deny(unsafe_code)]

pub mod ast;
pub mod builtins;
pub mod check;
pub mod diagnostics;
pub mod fold;
pub mod hir;
pub mod lex;
pub mod parse;
pub mod preprocess;

#[cfg(test)]
mod check_tests;

pub use builtins::Limits;
pub use diagnostics::InfoLog;
pub use hir::{Checked, Stage};
pub use preprocess::Options;

/// A parsed shader and what the preprocessor recorded about it.
#[derive(Clone, Debug)]
pub struct Parsed {
    pub unit: ast::TranslationUnit,
    pub extensions: Vec<preprocess::Extension>,
    pub invariant_all: bool,
}

/// Preprocesses and parses one shader source. `None` when the log holds an error.
pub fn parse_shader(source: &str, options: &Options, log: &mut InfoLog) -> Option<Parsed> {
    let pre = preprocess::preprocess(source, options, log);
    if log.has_errors() {
        return None;
    }
    let tokens = lex::classify(&pre.tokens, pre.version, pre.end, log);
    // The preprocessor's tokens are not needed past here: freed before the tree is built,
    // they do not add to the compile's peak memory (a token each, 10⁶ of them in a
    // 10⁵-line shader).
    let preprocess::Preprocessed { version, tokens: preprocessed, extensions, invariant_all, .. } = pre;
    drop(preprocessed);
    let unit = parse::parse(&tokens, version, log).ok()?;
    Some(Parsed { unit, extensions, invariant_all })
}

/// Compiles one shader source for `stage`: preprocessing, parsing and semantic analysis.
/// `None` when the log holds an error; warnings may be in the log either way.
pub fn compile_shader(source: &str, stage: Stage, options: &Options, log: &mut InfoLog) -> Option<Checked> {
    let parsed = parse_shader(source, options, log)?;
    check::check(&parsed, stage, &Limits::default(), log)
}
