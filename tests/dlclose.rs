//! A program may dlopen libOSMesa, render, dlclose it, and do it again, and then exit: with
//! tessera's worker threads parked in the library between scenes (`src/pool`), that is safe
//! only if dlclose never unmaps the library's code. The libraries are linked `-z nodelete`
//! (`lib/dropin-build.rs`); this test renders frames big enough for the workers (and the
//! parallel write into the caller's buffer) through a dlopen'ed handle three times, each
//! followed by dlclose, checks the pixels and that the code stays mapped, lets the parked
//! workers sit after the last dlclose, and exits normally. Mesa 22 unloads its library at
//! dlclose (its threads end with their context).
//!
//! The child is this test binary itself, running only [`dlclose_child`] (a no-op unless
//! `TESSERA_DLCLOSE_PROBE` names the library).
use std::ffi::{c_int, c_uint, c_void, CStr, CString};
use std::path::PathBuf;
use std::process::Command;

const PROBE_ENV: &str = "TESSERA_DLCLOSE_PROBE";

/// libOSMesa.so.8 of the build directory (`TESSERA_LIB_DIR`, default `target/release`).
fn library() -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let dir = std::env::var_os("TESSERA_LIB_DIR").map_or_else(|| root.join("target/release"), |d| root.join(d));
    dir.join("libOSMesa.so.8")
}

#[test]
fn render_dlclose_repeat_and_exit() {
    let lib = library();
    if !lib.exists() {
        eprintln!("dlclose: {} not built (cargo build --release); skipped", lib.display());
        return;
    }
    let output = Command::new(std::env::current_exe().expect("the test binary's path"))
        .args(["--exact", "dlclose_child", "--nocapture", "--test-threads=1"])
        .env(PROBE_ENV, &lib)
        .env("TESSERA_THREADS", "2")
        .output()
        .expect("the child runs");
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success() && stdout.contains("dlclose child: ok"),
        "child failed ({}):\n{stdout}\n{}",
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
}

type CreateContextExt = unsafe extern "C" fn(c_uint, c_int, c_int, c_int, *mut c_void) -> *mut c_void;
type MakeCurrent = unsafe extern "C" fn(*mut c_void, *mut c_void, c_uint, c_int, c_int) -> u8;
type DestroyContext = unsafe extern "C" fn(*mut c_void);
type ClearColor = unsafe extern "C" fn(f32, f32, f32, f32);
type Clear = unsafe extern "C" fn(c_uint);
type Finish = unsafe extern "C" fn();

const OSMESA_RGBA: c_uint = 0x1908;
const GL_UNSIGNED_BYTE: c_uint = 0x1401;
const GL_COLOR_BUFFER_BIT: c_uint = 0x4000;
const GL_DEPTH_BUFFER_BIT: c_uint = 0x0100;
const SIDE: usize = 512;

/// Whether a file named like `lib` is mapped in this process.
fn mapped(lib: &str) -> bool {
    let name = std::path::Path::new(lib).file_name().and_then(|n| n.to_str()).unwrap_or(lib);
    let stem = name.split(".so").next().unwrap_or(name);
    std::fs::read_to_string("/proc/self/maps").is_ok_and(|m| m.lines().any(|l| l.contains(&format!("{stem}.so"))))
}

#[test]
fn dlclose_child() {
    let Ok(lib) = std::env::var(PROBE_ENV) else {
        return;
    };
    let path = CString::new(lib.clone()).expect("a path without NUL");
    for round in 0..3 {
        let mut pixels = vec![0u8; SIDE * SIDE * 4];
        // SAFETY: dlopen/dlsym get NUL-terminated names; each symbol is cast to the signature
        // the OSMesa/GL headers give it; the pixel buffer outlives the binding (released with
        // OSMesaMakeCurrent(NULL) before it is dropped) and holds SIDE² RGBA pixels.
        unsafe {
            let handle = libc::dlopen(path.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL);
            assert!(!handle.is_null(), "dlopen: {:?}", CStr::from_ptr(libc::dlerror()));
            let sym = |name: &CStr| {
                let p = libc::dlsym(handle, name.as_ptr());
                assert!(!p.is_null(), "no {name:?}");
                p
            };
            let create: CreateContextExt = std::mem::transmute(sym(c"OSMesaCreateContextExt"));
            let make_current: MakeCurrent = std::mem::transmute(sym(c"OSMesaMakeCurrent"));
            let destroy: DestroyContext = std::mem::transmute(sym(c"OSMesaDestroyContext"));
            let clear_color: ClearColor = std::mem::transmute(sym(c"glClearColor"));
            let clear: Clear = std::mem::transmute(sym(c"glClear"));
            let finish: Finish = std::mem::transmute(sym(c"glFinish"));
            let ctx = create(OSMESA_RGBA, 24, 8, 0, std::ptr::null_mut());
            assert!(!ctx.is_null(), "no context");
            assert_eq!(
                make_current(ctx, pixels.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, SIDE as c_int, SIDE as c_int),
                1
            );
            clear_color(0.2, 0.4, 0.6, 1.0);
            clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            finish();
            make_current(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
            destroy(ctx);
            assert_eq!(libc::dlclose(handle), 0, "dlclose");
        }
        assert!(pixels.chunks_exact(4).all(|p| p == [51, 102, 153, 255]), "round {round}: wrong pixels");
        assert!(mapped(&lib), "round {round}: the library was unmapped while its workers are parked in it");
    }
    // The workers stay parked in the closed library; the process then exits normally.
    std::thread::sleep(std::time::Duration::from_millis(50));
    println!("dlclose child: ok");
}
