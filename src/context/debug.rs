//! `TESSERA_DEBUG`: diagnostics a user can switch on without rebuilding.
//!
//! The variable is a comma-separated list of topics, read once per process:
//! - `pipeline`: every draw prints (on stderr) the fragment stages its state compiled to, in
//!   order, and whether the state was compiled anew or found in the scene's cache.
//! - `programs`: every fixed-function vertex or fragment program the draws generate (on a
//!   miss of the share group's cache, `super::programs`) is printed on stderr in its text
//!   form, and so is each stage of every GLSL program when it is linked.
//! - `config`: the first context created prints the renderer's configuration, one line per
//!   setting: `tessera config: simd avx2 (detected; TESSERA_SIMD unset)` (the SIMD level of
//!   the hot loops, `crate::simd`), `... threads 2`, `... accuracy conformant`.

use std::sync::OnceLock;

/// Whether `TESSERA_DEBUG` names `topic`.
pub fn enabled(topic: &str) -> bool {
    static TOPICS: OnceLock<Vec<String>> = OnceLock::new();
    TOPICS
        .get_or_init(|| {
            std::env::var("TESSERA_DEBUG")
                .map(|v| v.split(',').map(|t| t.trim().to_ascii_lowercase()).collect())
                .unwrap_or_default()
        })
        .iter()
        .any(|t| t == topic)
}

/// Under `TESSERA_DEBUG=config`, prints the renderer's configuration on stderr, once per
/// process: the SIMD level the hot loops run at and why, the rasterizer thread count, the
/// accuracy mode new contexts start in.
pub fn print_config_once() {
    static PRINTED: std::sync::Once = std::sync::Once::new();
    if enabled("config") {
        PRINTED.call_once(|| {
            eprintln!("tessera config: simd {}", crate::simd::describe());
            eprintln!("tessera config: threads {}", crate::raster::thread_count());
            eprintln!("tessera config: accuracy {}", crate::setup::accuracy::Accuracy::from_env().name());
        });
    }
}

/// The name of a primitive mode (GL_POINTS … GL_POLYGON) for diagnostics.
pub fn mode_name(mode: u32) -> &'static str {
    const NAMES: [&str; 10] = [
        "GL_POINTS",
        "GL_LINES",
        "GL_LINE_LOOP",
        "GL_LINE_STRIP",
        "GL_TRIANGLES",
        "GL_TRIANGLE_STRIP",
        "GL_TRIANGLE_FAN",
        "GL_QUADS",
        "GL_QUAD_STRIP",
        "GL_POLYGON",
    ];
    NAMES.get(mode as usize).copied().unwrap_or("primitive")
}
