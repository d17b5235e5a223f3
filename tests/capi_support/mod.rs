//! The machinery behind `tests/capi.rs`: finding the tools and the two implementations
//! ([`setup`]), running a program on one of them with a time limit ([`process`]), the
//! per-test allowances of `capi-tests/manifest.txt` ([`manifest`]) and comparing the images
//! the C tests save ([`image`]).
//!
//! Output that a person must see even when the test harness captures output (the per-test
//! lines, the SKIPPED banner) goes through [`say`], which writes to the process's stderr
//! directly instead of through `eprintln!` (which libtest captures).

pub mod image;
pub mod manifest;
pub mod process;
pub mod setup;

use std::io::Write as _;

/// Writes `text` and a newline to stderr, bypassing the test harness's output capture.
pub fn say(text: &str) {
    let mut stderr = std::io::stderr().lock();
    let _ = writeln!(stderr, "{text}");
    let _ = stderr.flush();
}
