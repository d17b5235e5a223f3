//! Build script shared by the two drop-in libraries (lib/osmesa, lib/gl).
//!
//! Cargo names a cdylib `lib<name>.so` and has no post-link step, so this script gives the
//! library Mesa's soname and leaves beside it, in the profile directory, a symlink for every
//! other name a loader looks for (`libOSMesa.so.8 -> libOSMesa.so`; `libGL.so.1`, glvnd's
//! `libOpenGL.so(.0)` and `libGLX.so(.0)` `-> libGL.so`), plus the pkg-config files
//! `pkgconfig/gl.pc` and `pkgconfig/osmesa.pc`. The links may dangle for the moment between
//! this script and the link step; after `cargo build` they resolve, and
//! `LD_LIBRARY_PATH=target/release` is the install (`tests/loader_names.rs` checks each name).
//! The library is linked with `-z nodelete`: tessera's worker threads (`src/pool`) stay
//! parked in its code between scenes, so a dlclose must leave that code mapped (it keeps the
//! library loaded, as glibc already did while thread-local destructors of it were pending).
use std::path::PathBuf;

fn main() {
    let package = std::env::var("CARGO_PKG_NAME").expect("cargo sets CARGO_PKG_NAME");
    let (stem, version) = match package.as_str() {
        "tessera-osmesa" => ("OSMesa", "8"),
        "tessera-gl" => ("GL", "1"),
        other => panic!("dropin-build.rs used by unknown package {other}"),
    };
    let soname = format!("lib{stem}.so.{version}");
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,{soname}");
    println!("cargo:rustc-cdylib-link-arg=-Wl,-z,nodelete");
    println!("cargo:rerun-if-changed=../dropin-build.rs");

    // OUT_DIR is <profile dir>/build/<package>-<hash>/out.
    let out_dir = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    let Some(profile_dir) = out_dir.ancestors().nth(3) else {
        return;
    };
    let mut links = vec![soname];
    if stem == "GL" {
        // glvnd splits libGL into libOpenGL (the GL functions) and libGLX (the window-system
        // ones), and clients look for those names first: Debian's libGLU links libOpenGL.so.0,
        // GLFW dlopens libGLX.so.0 before libGL.so.1, PyOpenGL tries libOpenGL.so and libGLX.so
        // before libGL.so.1. Without these links the system's glvnd libraries would win
        // silently under LD_LIBRARY_PATH=target/release. libGL exports both halves.
        links.extend(["libOpenGL.so.0", "libOpenGL.so", "libGLX.so.0", "libGLX.so"].map(String::from));
    }
    for name in &links {
        let link = profile_dir.join(name);
        let _ = std::fs::remove_file(&link);
        if let Err(err) = std::os::unix::fs::symlink(format!("lib{stem}.so"), &link) {
            println!("cargo:warning=could not create {}: {err}", link.display());
        }
    }
    write_pkg_config(profile_dir, stem);
}

/// `<profile dir>/pkgconfig/gl.pc` or `osmesa.pc`, for programs built against tessera:
/// `PKG_CONFIG_PATH=target/release/pkgconfig pkg-config --cflags --libs gl`.
fn write_pkg_config(profile_dir: &std::path::Path, stem: &str) {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let include = manifest.join("../../include");
    let include = include.canonicalize().unwrap_or(include);
    let (file, description) = match stem {
        "GL" => ("gl.pc", "tessera's libGL: OpenGL and GLX on a software rasterizer"),
        _ => ("osmesa.pc", "tessera's libOSMesa: off-screen OpenGL rendering into memory"),
    };
    let text = format!(
        "prefix={prefix}\nlibdir=${{prefix}}\nincludedir={include}\n\nName: {name}\nDescription: {description}\nVersion: {version}\nLibs: -L${{libdir}} -l{stem}\nCflags: -I${{includedir}}\n",
        prefix = profile_dir.display(),
        include = include.display(),
        name = file.trim_end_matches(".pc"),
        version = std::env::var("CARGO_PKG_VERSION").unwrap_or_default(),
    );
    let dir = profile_dir.join("pkgconfig");
    let written = std::fs::create_dir_all(&dir).and_then(|_| std::fs::write(dir.join(file), text));
    if let Err(err) = written {
        println!("cargo:warning=could not write {}: {err}", dir.join(file).display());
    }
}
