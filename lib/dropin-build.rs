//! Build script shared by the two drop-in libraries (lib/osmesa, lib/gl).
//!
//! Cargo names a cdylib `lib<name>.so` and has no post-link step, so this script gives the
//! library Mesa's soname and leaves a versioned symlink (`libOSMesa.so.8 -> libOSMesa.so`)
//! beside it in the profile directory. The link may dangle for the moment between this script
//! and the link step; after `cargo build` it resolves, and `LD_LIBRARY_PATH=target/release` is
//! the install.
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
    println!("cargo:rerun-if-changed=../dropin-build.rs");

    // OUT_DIR is <profile dir>/build/<package>-<hash>/out.
    let out_dir = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    let Some(profile_dir) = out_dir.ancestors().nth(3) else {
        return;
    };
    let link = profile_dir.join(&soname);
    let _ = std::fs::remove_file(&link);
    if let Err(err) = std::os::unix::fs::symlink(format!("lib{stem}.so"), &link) {
        println!("cargo:warning=could not create {}: {err}", link.display());
    }
}
