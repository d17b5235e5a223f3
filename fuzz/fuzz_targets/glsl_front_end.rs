//! libFuzzer target: every input is the source of a shader for tessera's GLSL front end.
//! It is compiled as a vertex shader and as a fragment shader as glCompileShader does
//! (`shader_objects::compile`); each that compiles is linked alone as glLinkProgram does
//! (`glsl::link` and `Executable::new`: lowering onto the shading IR, validation, compiling
//! for the executor, placing the varyings). Any panic, a stack overflow, a run past
//! libFuzzer's `-timeout` or its memory limit is a finding: hostile source must give an
//! error in the info log within bounded time and memory (issue #20).
//!
//! Seeds: the shaders of piglit's GLSL 1.10/1.20 tests, extracted by tools/fuzz.sh from the
//! installed piglit (not committed), and fuzz/corpus/glsl_front_end.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tessera::context::shader_objects::{compile, Executable};
use tessera::glsl::{link, Stage};

fuzz_target!(|data: &[u8]| {
    let source = String::from_utf8_lossy(data);
    for stage in [Stage::Vertex, Stage::Fragment] {
        let (checked, log) = compile(stage, &source);
        let Some(checked) = checked else {
            assert!(log.contains("error"), "a failed compile says why: {log:?}");
            continue;
        };
        if let Ok(linked) = link::link(&[checked], &[]) {
            let _ = Executable::new(linked);
        }
    }
});
