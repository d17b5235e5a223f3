//! `TESSERA_DEBUG`: diagnostics a user can switch on without rebuilding.
//!
//! The variable is a comma-separated list of topics, read once per process:
//! - `pipeline`: every draw prints (on stderr) the fragment stages its state compiled to, in
//!   order, and whether the state was compiled anew or found in the scene's cache.

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
