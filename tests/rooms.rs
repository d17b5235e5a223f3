//! The import rules of the source tree (../shared/DESIGN.md, "The shape"), checked over the
//! source text so that CI fails when a room reaches up.
//!
//! The rooms of `src/`, from the top (the C edge) to the bottom (the GL vocabulary):
//! `api → winsys → context → vertex → setup → raster → fragment → glsl → shader → texture →
//! pixel → framebuffer → simd → pool → gl`. A room may name (`crate::<room>`, in a `use` or a path) only itself and
//! rooms below it; in particular the engine rooms never name `api`, `context` or `winsys`.
//! Every room but the FFI edge (`api`, `winsys`: Xlib and the C ABI) denies unsafe code at its
//! root, and within the engine only the wrapper around caller-owned pixel memory
//! (`framebuffer/external.rs`) and the calls of code compiled per SIMD level
//! (`simd/dispatch.rs`) may allow it again.

use std::path::{Path, PathBuf};

/// The rooms in pipeline order, top first.
const ROOMS: [&str; 15] = [
    "api",
    "winsys",
    "context",
    "vertex",
    "setup",
    "raster",
    "fragment",
    "glsl",
    "shader",
    "texture",
    "pixel",
    "framebuffer",
    "simd",
    "pool",
    "gl",
];

/// Rooms where `unsafe` is the point: the C ABI and Xlib.
const FFI_ROOMS: [&str; 2] = ["api", "winsys"];

/// Files of an engine room that may hold `unsafe` (each block with a `// SAFETY:` line): the
/// caller's pixel memory, the calls of `target_feature` functions, and the huge-page advice
/// for large pixel buffers, and the pool's lifetime erasure of the work it hands its threads.
const UNSAFE_WRAPPERS: [&str; 4] =
    ["src/framebuffer/external.rs", "src/simd/dispatch.rs", "src/framebuffer/pages.rs", "src/pool/lifetime.rs"];

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let path = entry.expect("directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The code of a file without its comments (line comments only: the crate has no block
/// comments in code), so that a doc naming `crate::context` is not an import.
fn code_lines(path: &Path) -> Vec<(usize, String)> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines()
        .enumerate()
        .map(|(i, line)| (i + 1, line.split("//").next().unwrap_or("").to_string()))
        .filter(|(_, code)| !code.trim().is_empty())
        .collect()
}

/// Every room a line names with `crate::<room>`.
fn named_rooms(code: &str) -> Vec<&str> {
    code.match_indices("crate::")
        .filter(|(i, _)| !code[..*i].ends_with("tessera::") && !code[..*i].ends_with('_'))
        .map(|(i, m)| {
            let rest = &code[i + m.len()..];
            let end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(rest.len());
            &rest[..end]
        })
        .collect()
}

fn room_of(path: &Path) -> Option<&'static str> {
    let relative = path.strip_prefix(src()).ok()?;
    let first = relative.components().next()?.as_os_str().to_str()?;
    let name = first.strip_suffix(".rs").unwrap_or(first);
    ROOMS.iter().copied().find(|r| *r == name)
}

fn rank(room: &str) -> Option<usize> {
    ROOMS.iter().position(|r| *r == room)
}

#[test]
fn every_file_in_src_belongs_to_a_room() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let strays: Vec<_> = files
        .iter()
        .filter(|f| f.file_name().is_some_and(|n| n != "lib.rs") && room_of(f).is_none())
        .map(|f| f.display().to_string())
        .collect();
    assert!(strays.is_empty(), "files outside the rooms {ROOMS:?}: {strays:#?}");
}

#[test]
fn no_room_imports_a_room_above_it() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut violations = Vec::new();
    for file in &files {
        let Some(room) = room_of(file) else { continue };
        let own = rank(room).expect("a room has a rank");
        for (line, code) in code_lines(file) {
            for named in named_rooms(&code) {
                match rank(named) {
                    Some(r) if r < own => violations.push(format!(
                        "{}:{line}: `{room}` names `crate::{named}`, a room above it",
                        file.strip_prefix(src()).unwrap().display()
                    )),
                    Some(_) => {}
                    None => violations.push(format!(
                        "{}:{line}: `crate::{named}` is not a room of {ROOMS:?}",
                        file.strip_prefix(src()).unwrap().display()
                    )),
                }
            }
        }
    }
    assert!(violations.is_empty(), "{} import(s) break the room order:\n{}", violations.len(), violations.join("\n"));
}

#[test]
fn the_check_sees_an_upward_import() {
    // The rule must be able to fail: these lines break it.
    assert_eq!(named_rooms("use crate::context::state::Light;"), ["context"]);
    assert_eq!(named_rooms("let x = crate::api::osmesa::OSMESA_RGBA + crate::gl::limits::MAX;"), ["api", "gl"]);
    assert!(rank("context") < rank("fragment"));
    assert!(named_rooms("tessera::crate::x and my_crate::y").is_empty());
}

#[test]
fn engine_rooms_deny_unsafe_code() {
    let mut missing = Vec::new();
    for room in ROOMS.iter().filter(|r| !FFI_ROOMS.contains(r)) {
        let root = src().join(room).join("mod.rs");
        if !root.exists() {
            continue; // a room that does not exist yet (`shader`)
        }
        let text = std::fs::read_to_string(&root).unwrap();
        if !text.contains("#![deny(unsafe_code)]") {
            missing.push(root.display().to_string());
        }
    }
    assert!(missing.is_empty(), "rooms without #![deny(unsafe_code)] at their root: {missing:#?}");

    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut stray = Vec::new();
    for file in &files {
        let Some(room) = room_of(file) else { continue };
        let relative = format!("src/{}", file.strip_prefix(src()).unwrap().display());
        if FFI_ROOMS.contains(&room) || UNSAFE_WRAPPERS.contains(&relative.as_str()) {
            continue;
        }
        for (line, code) in code_lines(file) {
            let allows = code.contains("allow(unsafe_code)");
            let block = code.contains("unsafe {") || code.contains("unsafe fn") || code.contains("unsafe impl");
            if allows || block {
                stray.push(format!("{relative}:{line}: {}", code.trim()));
            }
        }
    }
    assert!(stray.is_empty(), "unsafe code outside the FFI rooms and {UNSAFE_WRAPPERS:?}:\n{}", stray.join("\n"));
}
