//! The one-line refusal notices of OSMesa context creation and binding (src/winsys/notice.rs):
//! each names what was asked and what tessera provides, appears once per process per
//! reason however often the refusal repeats, and not at all under `TESSERA_QUIET=1`.
//!
//! A notice is printed once per process, so the refusals run in a child process (this test
//! binary again, running only `refusals_child`), whose stderr the tests read.
use std::ffi::c_int;
use std::process::Command;
use tessera::api::osmesa::*;
use tessera::gl::enums::*;
use tessera::gl::osmesa::*;

const CHILD: &str = "TESSERA_NOTICES_CHILD";

/// Makes every refusal twice (does nothing unless run as the child).
#[test]
fn refusals_child() {
    if std::env::var_os(CHILD).is_none() {
        return;
    }
    // pyrender's request: OpenGL 3.3 core profile; then 3.0 compatibility (same reason).
    let core_33 =
        [OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0];
    let compat_30 = [OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 0, 0 as c_int];
    for attribs in [&core_33[..], &compat_30[..]] {
        // SAFETY: a zero-terminated attribute list.
        let ctx = unsafe { OSMesaCreateContextAttribs(attribs.as_ptr(), std::ptr::null_mut()) };
        assert!(ctx.is_null());
    }
    for _ in 0..2 {
        assert!(OSMesaCreateContextExt(OSMESA_COLOR_INDEX, 16, 0, 0, std::ptr::null_mut()).is_null());
        assert!(OSMesaCreateContext(0x1234, std::ptr::null_mut()).is_null());
        assert!(OSMesaCreateContextExt(OSMESA_RGBA, -1, 0, 0, std::ptr::null_mut()).is_null());
    }
    let ctx = OSMesaCreateContextExt(OSMESA_RGB_565, 16, 0, 0, std::ptr::null_mut());
    assert!(!ctx.is_null());
    let mut buffer = vec![0u32; 16 * 16];
    for ty in [GL_UNSIGNED_BYTE, GL_FLOAT] {
        // SAFETY: the buffer holds 16 × 16 pixels of any type OSMesa accepts.
        let bound = unsafe { OSMesaMakeCurrent(ctx, buffer.as_mut_ptr().cast(), ty, 16, 16) };
        assert_eq!(bound, GL_FALSE);
    }
    OSMesaDestroyContext(ctx);
}

/// The child's stderr lines, with `TESSERA_QUIET` set to `quiet` (or unset).
fn child_stderr(quiet: Option<&str>) -> Vec<String> {
    let mut command = Command::new(std::env::current_exe().unwrap());
    command.args(["--exact", "refusals_child", "--test-threads=1", "--nocapture"]).env(CHILD, "1");
    match quiet {
        Some(v) => command.env("TESSERA_QUIET", v),
        None => command.env_remove("TESSERA_QUIET"),
    };
    let output = command.output().unwrap();
    assert!(output.status.success(), "child failed: {}", String::from_utf8_lossy(&output.stdout));
    String::from_utf8_lossy(&output.stderr).lines().filter(|l| l.starts_with("tessera:")).map(String::from).collect()
}

#[test]
fn each_refusal_reason_is_named_once() {
    let lines = child_stderr(None);
    let expected = [
        "tessera: OSMesaCreateContextAttribs asked for OpenGL 3.3 core profile; \
         tessera provides OpenGL 2.1 (compatibility)",
        "tessera: OSMesaCreateContextExt asked for pixel format OSMESA_COLOR_INDEX; \
         tessera provides OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR and OSMESA_RGB_565",
        "tessera: OSMesaCreateContextExt asked for -1 depth, 0 stencil and 0 accumulation bits; \
         tessera provides any size from 0 (depth up to 32 bits, stencil 8, accumulation 16 per channel)",
        "tessera: OSMesaMakeCurrent asked for type GL_UNSIGNED_BYTE with format OSMESA_RGB_565; \
         tessera provides GL_UNSIGNED_SHORT_5_6_5 with OSMESA_RGB_565",
    ];
    assert_eq!(lines, expected, "the notices, in order, one per reason");
}

#[test]
fn tessera_quiet_silences_every_notice() {
    assert_eq!(child_stderr(Some("1")), Vec::<String>::new());
    // `0` and empty mean not quiet.
    assert_eq!(child_stderr(Some("0")).len(), 4);
}
