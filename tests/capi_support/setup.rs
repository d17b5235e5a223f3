//! What the capi tests need, found once: gcc, Mesa's libOSMesa.so.8 and headers (the
//! reference), tessera's drop-in library, and the directories under `target/capi/`.
//!
//! When something is missing the tests cannot say anything about tessera. Outside CI that is
//! a loud SKIPPED message (a developer without Mesa can still run `cargo test`); with
//! `CI=true` it is a failure, so a broken CI image cannot pass silently.
use super::say;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Paths shared by every capi test.
#[derive(Clone, Debug)]
pub struct Setup {
    /// The checkout (where Cargo.toml, capi-tests/ and include/ are).
    pub root: PathBuf,
    /// `<target dir>/capi`: binaries, run directories, failure images.
    pub out: PathBuf,
    /// The directory holding tessera's `libOSMesa.so.8` (`TESSERA_LIB_DIR`, default
    /// `<target dir>/release`).
    pub tessera_lib_dir: PathBuf,
    /// Mesa's `libOSMesa.so.8` as the compiler's library search finds it.
    pub mesa_library: PathBuf,
}

/// Whether we run under CI (`CI=true`, as CI services set it).
pub fn is_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v.eq_ignore_ascii_case("true") || v == "1")
}

/// The compiler the tests use.
pub const CC: &str = "gcc";

/// Finds everything, or reports what is missing: a panic under CI, a SKIPPED banner
/// otherwise (then `None`: the caller returns and the test passes vacuously).
pub fn require(what: &str) -> Option<Setup> {
    match find() {
        Ok(setup) => Some(setup),
        Err(missing) => {
            let message = format!("{what}: {missing}");
            if is_ci() {
                panic!("capi prerequisites missing under CI=true: {message}");
            }
            let bar = "!".repeat(78);
            say(&format!(
                "{bar}\n!! SKIPPED {message}\n!! (run tools/setup-debian.sh and `cargo build --release`; \
                 with CI=true this is a failure)\n{bar}"
            ));
            None
        }
    }
}

fn find() -> Result<Setup, String> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let target = match std::env::var_os("CARGO_TARGET_DIR") {
        Some(dir) => root.join(dir),
        None => root.join("target"),
    };
    let tessera_lib_dir = match std::env::var_os("TESSERA_LIB_DIR") {
        Some(dir) => root.join(dir),
        None => target.join("release"),
    };

    let version = Command::new(CC).arg("--version").output();
    if !version.is_ok_and(|o| o.status.success()) {
        return Err(format!("`{CC}` is not installed (apt-get install gcc)"));
    }
    let mesa_library = library_path("libOSMesa.so.8")
        .ok_or("Mesa's libOSMesa.so.8 is not installed (apt-get install libosmesa6-dev)")?;
    library_path("libOSMesa.so").ok_or("libOSMesa.so (for -lOSMesa) is missing (apt-get install libosmesa6-dev)")?;
    if !headers_compile() {
        return Err("Mesa's <GL/gl.h>, <GL/glext.h> or <GL/osmesa.h> is missing \
                    (apt-get install libosmesa6-dev libgl1-mesa-dev)"
            .into());
    }
    if !tessera_lib_dir.join("libOSMesa.so.8").exists() {
        return Err(format!(
            "tessera's library {} does not exist (run `cargo build --release`, or set TESSERA_LIB_DIR)",
            tessera_lib_dir.join("libOSMesa.so.8").display()
        ));
    }
    let canonical = |p: &Path| p.canonicalize().unwrap_or_else(|_| p.to_path_buf());
    if canonical(&mesa_library).parent() == Some(&canonical(&tessera_lib_dir)) {
        return Err("the compiler finds tessera's libOSMesa.so.8 instead of Mesa's (check LIBRARY_PATH)".into());
    }
    let out = target.join("capi");
    std::fs::create_dir_all(&out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    Ok(Setup { root, out, tessera_lib_dir, mesa_library })
}

/// The path of `name` in the compiler's library search path, if it is there.
fn library_path(name: &str) -> Option<PathBuf> {
    let output = Command::new(CC).arg(format!("-print-file-name={name}")).output().ok()?;
    let path = PathBuf::from(String::from_utf8_lossy(&output.stdout).trim());
    (path.is_absolute() && path.exists()).then_some(path)
}

/// Whether the system GL headers compile.
fn headers_compile() -> bool {
    use std::io::Write as _;
    let child = Command::new(CC)
        .args(["-fsyntax-only", "-x", "c", "-"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn();
    let Ok(mut child) = child else { return false };
    if let Some(mut stdin) = child.stdin.take() {
        let _ = stdin.write_all(b"#include <GL/osmesa.h>\n#include <GL/gl.h>\n#include <GL/glext.h>\n");
    }
    child.wait().is_ok_and(|s| s.success())
}

impl Setup {
    /// Warns (loudly, without failing) when tessera's library is older than the sources:
    /// `cargo test` does not rebuild the drop-in cdylib, `cargo build --release` does.
    pub fn warn_if_library_stale(&self) {
        let library = self.tessera_lib_dir.join("libOSMesa.so.8");
        let Ok(built) = library.metadata().and_then(|m| m.modified()) else {
            return;
        };
        let newest = ["src", "lib", "build.rs"].iter().filter_map(|p| newest_mtime(&self.root.join(p))).max();
        if newest.is_some_and(|n| n > built) {
            say(&format!(
                "WARNING: {} is older than the sources: run `cargo build --release` first",
                library.display()
            ));
        }
    }
}

fn newest_mtime(path: &Path) -> Option<std::time::SystemTime> {
    let meta = path.metadata().ok()?;
    if meta.is_file() {
        return meta.modified().ok();
    }
    std::fs::read_dir(path).ok()?.filter_map(|e| e.ok()).filter_map(|e| newest_mtime(&e.path())).max()
}
