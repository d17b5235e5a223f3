//! Every library name a GL client's loader looks for is in the build directory and is tessera.
//!
//! Clients do not all ask for `libGL.so.1`: GLFW dlopens `libGLX.so.0` first, PyOpenGL tries
//! `libOpenGL.so` and `libGLX.so`, Debian's libGLU links `libOpenGL.so.0`, OSMesa users ask for
//! `libOSMesa.so.8` or `libOSMesa.so`. A name missing from `target/release` is not an error
//! for the dynamic loader: it falls back to the system's glvnd or Mesa library and the program
//! silently runs on Mesa. So for each name this test checks that the file is there and leads
//! to the right library, then, in a child process started with
//! `LD_LIBRARY_PATH=<lib dir>` (the loader reads it only at start-up), dlopens the bare name
//! as a client would and proves tessera answered: the handle has tessera's own
//! `tesseraSetAccuracy`, `dladdr` of its `glGetString` names a file of the build directory,
//! `glXGetProcAddressARB` agrees, no system GL library got mapped, and an OSMesa context
//! made current through the handle clears pixels and names tessera as `GL_RENDERER`.
//!
//! The child is this test binary itself, running only [`probe_child`] (a no-op unless
//! `TESSERA_LOADER_PROBE` names the library to probe).
use std::ffi::{c_char, c_int, c_uint, c_void, CStr, CString};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Each name and the library file it must lead to.
const NAMES: [(&str, &str); 8] = [
    ("libGL.so.1", "libGL.so"),
    ("libGL.so", "libGL.so"),
    ("libOpenGL.so.0", "libGL.so"),
    ("libOpenGL.so", "libGL.so"),
    ("libGLX.so.0", "libGL.so"),
    ("libGLX.so", "libGL.so"),
    ("libOSMesa.so.8", "libOSMesa.so"),
    ("libOSMesa.so", "libOSMesa.so"),
];

/// The environment variable that turns [`probe_child`] on, naming the library to dlopen.
const PROBE_ENV: &str = "TESSERA_LOADER_PROBE";

/// The directory holding tessera's libraries (`TESSERA_LIB_DIR`, default `target/release`).
fn lib_dir() -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    match std::env::var_os("TESSERA_LIB_DIR") {
        Some(dir) => root.join(dir),
        None => match std::env::var_os("CARGO_TARGET_DIR") {
            Some(target) => root.join(target).join("release"),
            None => root.join("target/release"),
        },
    }
}

fn canonical(path: &Path) -> PathBuf {
    path.canonicalize().unwrap_or_else(|e| panic!("cannot resolve {}: {e}", path.display()))
}

#[test]
fn every_loader_name_is_tessera() {
    let dir = lib_dir();
    if !dir.join("libGL.so").exists() || !dir.join("libOSMesa.so").exists() {
        let message = format!("loader names: tessera's libraries are not in {} (cargo build --release)", dir.display());
        if std::env::var("CI").is_ok_and(|v| v.eq_ignore_ascii_case("true") || v == "1") {
            panic!("{message} (CI=true: a missing prerequisite is a failure)");
        }
        eprintln!("SKIPPED {message}");
        return;
    }
    let mut failures = Vec::new();
    for (name, target) in NAMES {
        if let Err(why) = check_name(&dir, name, target) {
            failures.push(format!("{name}: {why}"));
        } else {
            eprintln!("loader names: {name} -> {target}: tessera");
        }
    }
    assert!(failures.is_empty(), "names that do not lead to tessera:\n{}", failures.join("\n"));
}

/// Checks one name on disk, then through the dynamic loader in a child process.
fn check_name(dir: &Path, name: &str, target: &str) -> Result<(), String> {
    let path = dir.join(name);
    if std::fs::symlink_metadata(&path).is_err() {
        return Err(format!("{} does not exist", path.display()));
    }
    let expected = canonical(&dir.join(target));
    let found = path.canonicalize().map_err(|e| format!("{} does not resolve: {e}", path.display()))?;
    if found != expected {
        return Err(format!("{} leads to {}, not {}", path.display(), found.display(), expected.display()));
    }

    let output = Command::new(std::env::current_exe().expect("the test binary's path"))
        .args(["probe_child", "--exact", "--nocapture", "--test-threads=1"])
        .env(PROBE_ENV, name)
        .env("LD_LIBRARY_PATH", dir)
        .env_remove("LD_PRELOAD")
        .env("TESSERA_THREADS", "1")
        .output()
        .map_err(|e| format!("cannot start the probe: {e}"))?;
    let stdout = String::from_utf8_lossy(&output.stdout);
    let report = || format!("probe output:\n{stdout}\n{}", String::from_utf8_lossy(&output.stderr));
    if !output.status.success() || !stdout.contains("PROBE OK") {
        return Err(format!("the probe failed ({})\n{}", output.status, report()));
    }
    let line = |key: &str| {
        // (libtest prints `test probe_child ... ` before the probe's first line)
        let value = stdout.lines().find_map(|l| l.split_once(key).map(|(_, value)| value.trim()));
        value.ok_or_else(|| format!("no {key} line\n{}", report()))
    };
    // dladdr names the file the loader mapped; it must be this build's library.
    let from = canonical(Path::new(line("GLGETSTRING FROM")?));
    if from != expected {
        return Err(format!("glGetString comes from {}, not {}", from.display(), expected.display()));
    }
    let renderer = line("RENDERER")?;
    if !renderer.starts_with("tessera") {
        return Err(format!("GL_RENDERER is `{renderer}`"));
    }
    Ok(())
}

// The few OSMesa/GL signatures the probe calls through dlsym.
type CreateContextExt = unsafe extern "C" fn(c_uint, c_int, c_int, c_int, *mut c_void) -> *mut c_void;
type MakeCurrent = unsafe extern "C" fn(*mut c_void, *mut c_void, c_uint, c_int, c_int) -> u8;
type DestroyContext = unsafe extern "C" fn(*mut c_void);
type GetString = unsafe extern "C" fn(c_uint) -> *const u8;
type ClearColor = unsafe extern "C" fn(f32, f32, f32, f32);
type Clear = unsafe extern "C" fn(c_uint);
type Finish = unsafe extern "C" fn();
type GetProcAddress = unsafe extern "C" fn(*const u8) -> *mut c_void;

const OSMESA_RGBA: c_uint = 0x1908;
const GL_UNSIGNED_BYTE: c_uint = 0x1401;
const GL_RENDERER: c_uint = 0x1F01;
const GL_COLOR_BUFFER_BIT: c_uint = 0x4000;

/// The child's side: dlopens `$TESSERA_LOADER_PROBE` by its bare name and reports on stdout
/// where its functions come from; panics (a failed child) where tessera did not answer.
#[test]
fn probe_child() {
    let Some(name) = std::env::var_os(PROBE_ENV) else {
        return;
    };
    let name = CString::new(name.into_encoded_bytes()).expect("a library name");
    // SAFETY: dlopen/dlsym/dladdr get NUL-terminated names and a valid Dl_info out-pointer; the
    // symbols are called through the signatures tessera's headers (and Mesa's) declare, with a
    // pixel buffer that outlives the context's use of it (the context is destroyed first).
    unsafe {
        let handle = libc::dlopen(name.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL);
        if handle.is_null() {
            panic!("dlopen({name:?}) failed: {:?}", CStr::from_ptr(libc::dlerror()));
        }
        let symbol = |s: &CStr| {
            let p = libc::dlsym(handle, s.as_ptr());
            assert!(!p.is_null(), "{s:?} is not in {name:?}: not tessera's library");
            p
        };
        symbol(c"tesseraSetAccuracy");
        let get_string = symbol(c"glGetString");
        let mut info: libc::Dl_info = std::mem::zeroed();
        assert!(libc::dladdr(get_string, &mut info) != 0, "dladdr(glGetString) failed");
        println!("GLGETSTRING FROM {}", CStr::from_ptr(info.dli_fname).to_string_lossy());

        let get_proc: GetProcAddress = std::mem::transmute(symbol(c"glXGetProcAddressARB"));
        assert_eq!(get_proc(c"glGetString".as_ptr().cast()), get_string, "glXGetProcAddressARB disagrees with dlsym");

        let create: CreateContextExt = std::mem::transmute(symbol(c"OSMesaCreateContextExt"));
        let make_current: MakeCurrent = std::mem::transmute(symbol(c"OSMesaMakeCurrent"));
        let destroy: DestroyContext = std::mem::transmute(symbol(c"OSMesaDestroyContext"));
        let get_string: GetString = std::mem::transmute(get_string);
        let clear_color: ClearColor = std::mem::transmute(symbol(c"glClearColor"));
        let clear: Clear = std::mem::transmute(symbol(c"glClear"));
        let finish: Finish = std::mem::transmute(symbol(c"glFinish"));

        let context = create(OSMESA_RGBA, 16, 0, 0, std::ptr::null_mut());
        assert!(!context.is_null(), "OSMesaCreateContextExt failed");
        let mut pixels = vec![0u8; 8 * 8 * 4];
        assert_eq!(make_current(context, pixels.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 8, 8), 1);
        let renderer = get_string(GL_RENDERER);
        assert!(!renderer.is_null(), "glGetString(GL_RENDERER) is NULL");
        println!("RENDERER {}", CStr::from_ptr(renderer.cast::<c_char>()).to_string_lossy());
        clear_color(0.0, 1.0, 0.0, 1.0);
        clear(GL_COLOR_BUFFER_BIT);
        finish();
        destroy(context);
        assert!(pixels.chunks(4).all(|p| p == [0, 255, 0, 255]), "the clear did not reach the buffer");
    }
    // Nothing else answered: no system GL library was mapped beside tessera's.
    let maps = std::fs::read_to_string("/proc/self/maps").expect("/proc/self/maps");
    let system: Vec<&str> = maps
        .lines()
        .filter_map(|l| l.split_whitespace().nth(5))
        .filter(|p| {
            let file = p.rsplit('/').next().unwrap_or("");
            ["libGL.so", "libGLX", "libOpenGL", "libGLdispatch", "libOSMesa"].iter().any(|n| file.starts_with(n))
                && !Path::new(p).starts_with(lib_dir_of_probe())
        })
        .collect();
    assert!(system.is_empty(), "system GL libraries were loaded too: {system:?}");
    println!("PROBE OK");
}

/// The probe's library directory: the first entry of its LD_LIBRARY_PATH, canonical.
fn lib_dir_of_probe() -> PathBuf {
    let path = std::env::var_os("LD_LIBRARY_PATH").expect("the probe runs with LD_LIBRARY_PATH");
    let first = std::env::split_paths(&path).next().expect("a directory");
    canonical(&first)
}
