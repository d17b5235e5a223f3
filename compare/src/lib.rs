//! tessera-compare: runs C programs that render with OSMesa and write PNG files on several
//! GL implementations (tessera, Mesa llvmpipe, Mesa softpipe, any `libOSMesa.so.8`
//! directory), compares the pictures image by image and writes a JSON and an HTML report.
//!
//! The modules follow the tool's steps: [`implementation`] says how a program is run on each
//! GL, [`runner`] compiles and runs the programs, [`image`] reads and writes PNG files,
//! [`metrics`] measures the differences, [`manifest`] holds the per-test thresholds, and
//! [`report`] writes the JSON and the HTML.

pub mod image;
pub mod implementation;
pub mod manifest;
pub mod metrics;
pub mod report;
pub mod runner;
