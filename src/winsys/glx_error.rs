//! GLX errors as X protocol errors: where the GLX 1.4 specification says a call "generates"
//! an error (BadMatch, BadValue, GLXBadContext, GLXBadDrawable, ...), the application's X
//! error handler (XSetErrorHandler) receives it, as from Mesa's GLX.
//!
//! tessera renders without GLX protocol, so no server produces these errors. As Mesa's
//! direct-rendering GLX does, a wire-format error is made here and handed to Xlib's
//! `_XError` (exported by libX11 for extension libraries), which queues it like one read
//! from the server and calls the handler: its major opcode is the server's GLX extension's
//! (`XQueryExtension("GLX")`), GLX-specific codes are offset by the extension's error base,
//! the minor opcode names the GLX request the call stands for, and the serial is the last
//! request's. Without a GLX extension on the server (its codes unknown) nothing is reported
//! and the calls' return values alone tell the failure.
//!
//! `_XError` expects the display's internal lock to be held, which Xlib's `LockDisplay`
//! macro takes through `dpy->lock_fns` (set only after `XInitThreads`). Those fields of
//! `struct _XDisplay` (Xlibint.h) are part of Xlib's stable extension ABI; their offset is
//! fixed for LP64 below; they are read only when Xlib is thread-safe (its `_XLockMutex_fn`
//! is set), and the functions found there are only called when they lie inside libX11
//! itself (checked with `dladdr`).
use super::glx::{server_extension, xlib, DisplayAddr};
use std::ffi::{c_int, c_void, CStr};
use std::sync::OnceLock;

/// An error GLX generates: a core X error code or a GLX extension error (offset by the
/// extension's error base).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlxError {
    Core(u8),
    Glx(u8),
}

pub const BAD_VALUE: GlxError = GlxError::Core(2);
pub const BAD_MATCH: GlxError = GlxError::Core(8);
pub const BAD_ACCESS: GlxError = GlxError::Core(10);
pub const BAD_ALLOC: GlxError = GlxError::Core(11);
pub const GLX_BAD_CONTEXT: GlxError = GlxError::Glx(0);
pub const GLX_BAD_DRAWABLE: GlxError = GlxError::Glx(2);
pub const GLX_BAD_PIXMAP: GlxError = GlxError::Glx(3);
pub const GLX_BAD_FBCONFIG: GlxError = GlxError::Glx(9);
pub const GLX_BAD_PBUFFER: GlxError = GlxError::Glx(10);
pub const GLX_BAD_WINDOW: GlxError = GlxError::Glx(12);

/// The GLX requests (minor opcodes, glxproto.h) the calls stand for.
pub mod request {
    pub const CREATE_CONTEXT: u8 = 3;
    pub const DESTROY_CONTEXT: u8 = 4;
    pub const MAKE_CURRENT: u8 = 5;
    pub const COPY_CONTEXT: u8 = 10;
    pub const SWAP_BUFFERS: u8 = 11;
    pub const CREATE_GLX_PIXMAP: u8 = 13;
    pub const DESTROY_GLX_PIXMAP: u8 = 15;
    pub const VENDOR_PRIVATE: u8 = 16;
    pub const CREATE_PIXMAP: u8 = 22;
    pub const DESTROY_PIXMAP: u8 = 23;
    pub const CREATE_NEW_CONTEXT: u8 = 24;
    pub const QUERY_CONTEXT: u8 = 25;
    pub const MAKE_CONTEXT_CURRENT: u8 = 26;
    pub const CREATE_PBUFFER: u8 = 27;
    pub const DESTROY_PBUFFER: u8 = 28;
    pub const GET_DRAWABLE_ATTRIBUTES: u8 = 29;
    pub const CHANGE_DRAWABLE_ATTRIBUTES: u8 = 30;
    pub const CREATE_WINDOW: u8 = 31;
    pub const DESTROY_WINDOW: u8 = 32;
    pub const CREATE_CONTEXT_ATTRIBS_ARB: u8 = 34;
}

/// An X error as the server sends it (xError of Xproto.h: 32 bytes).
#[repr(C)]
struct WireError {
    kind: u8,
    code: u8,
    sequence: u16,
    resource: u32,
    minor: u16,
    major: u8,
    pad: [u8; 21],
}

type XErrorFn = unsafe extern "C" fn(*mut c_void, *mut WireError) -> c_int;
type LockFn = unsafe extern "C" fn(*mut c_void);

/// Offset of `lock_fns` (struct _XLockPtrs *: lock_display, unlock_display) in Xlib's
/// `struct _XDisplay` on LP64 (offsetof in Xlibint.h of libX11 1.8).
const LOCK_FNS_OFFSET: usize = 2408;

/// Xlib's `_XError`, found in the already loaded libX11.
fn x_error_fn() -> Option<XErrorFn> {
    static FUNCTION: OnceLock<Option<XErrorFn>> = OnceLock::new();
    *FUNCTION.get_or_init(|| {
        // SAFETY: dlopen/dlsym with NUL-terminated names; RTLD_NOLOAD only finds the
        // libX11 the application (or x11-dl) already loaded. The symbol is _XError, whose
        // C signature XErrorFn mirrors.
        unsafe {
            let library = libc::dlopen(c"libX11.so.6".as_ptr(), libc::RTLD_LAZY | libc::RTLD_NOLOAD);
            if library.is_null() {
                return None;
            }
            let symbol = libc::dlsym(library, c"_XError".as_ptr());
            (!symbol.is_null()).then(|| std::mem::transmute::<*mut c_void, XErrorFn>(symbol))
        }
    })
}

/// Whether `address` lies in libX11's code (the check that the lock functions were read
/// from the right place).
fn in_libx11(address: *const c_void) -> bool {
    // SAFETY: Dl_info is plain data (pointers and integers); all-zero is a valid value.
    let mut info: libc::Dl_info = unsafe { std::mem::zeroed() };
    // SAFETY: dladdr only inspects the address; `info` is a local out-parameter.
    if unsafe { libc::dladdr(address, &mut info) } == 0 || info.dli_fname.is_null() {
        return false;
    }
    // SAFETY: dladdr gave a NUL-terminated file name.
    let name = unsafe { CStr::from_ptr(info.dli_fname) };
    name.to_bytes().windows(9).any(|w| w == b"libX11.so")
}

/// Whether Xlib was made thread-safe (XInitThreads): its `_XLockMutex_fn` is set then.
fn xlib_threaded() -> bool {
    // SAFETY: as in x_error_fn; `_XLockMutex_fn` is a function-pointer variable of libX11,
    // read once as an address.
    unsafe {
        let library = libc::dlopen(c"libX11.so.6".as_ptr(), libc::RTLD_LAZY | libc::RTLD_NOLOAD);
        if library.is_null() {
            return false;
        }
        let variable = libc::dlsym(library, c"_XLockMutex_fn".as_ptr()) as *const usize;
        !variable.is_null() && variable.read() != 0
    }
}

/// The display's internal lock functions; `Ok(None)` when Xlib is not thread-safe (no
/// locking needed), `Err` when they cannot be trusted.
fn lock_functions(display: DisplayAddr) -> Result<Option<(LockFn, LockFn)>, ()> {
    if !xlib_threaded() {
        return Ok(None);
    }
    if cfg!(not(target_pointer_width = "64")) {
        return Err(());
    }
    // SAFETY: `display` is the application's Display*, a struct _XDisplay larger than
    // LOCK_FNS_OFFSET + 8 bytes; the field is a pointer, read unaligned to be safe.
    let lock_fns =
        unsafe { ((display as *const u8).add(LOCK_FNS_OFFSET) as *const *const [usize; 2]).read_unaligned() };
    if lock_fns.is_null() {
        return Err(());
    }
    // SAFETY: `lock_fns` is Xlib's struct _XLockPtrs of this display (allocated by
    // XInitThreads' display setup): two function pointers.
    let [lock, unlock] = unsafe { lock_fns.read_unaligned() };
    if lock == 0 || unlock == 0 || !in_libx11(lock as *const c_void) || !in_libx11(unlock as *const c_void) {
        return Err(());
    }
    // SAFETY: both are functions of libX11 (checked) taking the Display*.
    unsafe { Ok(Some((std::mem::transmute::<usize, LockFn>(lock), std::mem::transmute::<usize, LockFn>(unlock)))) }
}

/// Reports `error` about `resource` for the GLX request `minor` to the application's X error
/// handler on `display`. Does nothing without a display, Xlib, or a GLX extension.
pub fn report(display: DisplayAddr, error: GlxError, resource: u64, minor: u8) {
    if display == 0 {
        return;
    }
    let (Some(x), Some(x_error)) = (xlib(), x_error_fn()) else {
        return;
    };
    let Some((major, _, error_base)) = server_extension(display, c"GLX") else {
        return;
    };
    let Ok(locks) = lock_functions(display) else {
        return;
    };
    let code = match error {
        GlxError::Core(c) => c,
        GlxError::Glx(c) => (error_base + c as i32) as u8,
    };
    let dpy = display as *mut c_void;
    // SAFETY: the application's display; XNextRequest takes the display lock itself.
    let last_request = unsafe { (x.XNextRequest)(display as *mut _) }.wrapping_sub(1);
    let mut wire = WireError {
        kind: 0, // X_Error
        code,
        sequence: last_request as u16,
        resource: resource as u32,
        minor: minor as u16,
        major: major as u8,
        pad: [0; 21],
    };
    // SAFETY: as Xlib's own LockDisplay/_XError/UnlockDisplay sequence: the lock functions
    // were checked to be libX11's, `wire` is a complete xError, and _XError releases the
    // lock around the call of the application's handler.
    unsafe {
        if let Some((lock, _)) = locks {
            lock(dpy);
        }
        x_error(dpy, &mut wire);
        if let Some((_, unlock)) = locks {
            unlock(dpy);
        }
    }
}
