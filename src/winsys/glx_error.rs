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
//! So that Xlib's error text (XGetErrorText, and the default error handler's message) names
//! these errors ("GLXBadContext", not "167"), the GLX extension is registered with the
//! display through `XInitExtension`, with an `XESetErrorString` procedure giving the names of
//! glxproto.h, as Mesa's libGL does through libXext; an `XESetCloseDisplay` procedure forgets
//! the display when it closes (a later display at the same address is registered anew).
//!
//! `_XError` expects the display's internal lock to be held, which Xlib's `LockDisplay`
//! macro takes through `dpy->lock_fns` (set only after `XInitThreads`). Those fields of
//! `struct _XDisplay` (Xlibint.h) are part of Xlib's stable extension ABI; their offset is
//! fixed for LP64 below; they are read only when Xlib is thread-safe (its `_XLockMutex_fn`
//! is set), and the functions found there are only called when they lie inside libX11
//! itself (checked with `dladdr`).
use super::glx::{server_extension, xlib, DisplayAddr};
use std::collections::HashSet;
use std::ffi::{c_char, c_int, c_void, CStr};
use std::sync::{Mutex, MutexGuard, OnceLock};
use x11_dl::xlib::{Display, XExtCodes};

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

/// The names of the GLX error codes 0..=13 (glxproto.h), as libGL gives them to Xlib.
const ERROR_NAMES: [&CStr; 14] = [
    c"GLXBadContext",
    c"GLXBadContextState",
    c"GLXBadDrawable",
    c"GLXBadPixmap",
    c"GLXBadContextTag",
    c"GLXBadCurrentWindow",
    c"GLXBadRenderRequest",
    c"GLXBadLargeRequest",
    c"GLXUnsupportedPrivateRequest",
    c"GLXBadFBConfig",
    c"GLXBadPbuffer",
    c"GLXBadCurrentDrawable",
    c"GLXBadWindow",
    c"GLXBadProfileARB",
];

/// The name of GLX error `code` (relative to the extension's error base), if it is one.
pub fn error_name(code: i32) -> Option<&'static CStr> {
    usize::try_from(code).ok().and_then(|i| ERROR_NAMES.get(i)).copied()
}

/// The displays whose GLX error names are registered with Xlib.
fn named_displays() -> MutexGuard<'static, HashSet<DisplayAddr>> {
    static DISPLAYS: OnceLock<Mutex<HashSet<DisplayAddr>>> = OnceLock::new();
    DISPLAYS.get_or_init(|| Mutex::new(HashSet::new())).lock().unwrap_or_else(|p| p.into_inner())
}

/// Xlib's error-string procedure for the GLX extension: writes the name of a GLX error code
/// into `buffer` (truncated to `size` bytes with the NUL); other codes are left alone.
unsafe extern "C" fn error_string(
    _display: *mut Display,
    code: c_int,
    codes: *mut XExtCodes,
    buffer: *mut c_char,
    size: c_int,
) -> *mut c_char {
    if codes.is_null() || buffer.is_null() || size <= 0 {
        return std::ptr::null_mut();
    }
    // SAFETY: Xlib passes the XExtCodes registered by XInitExtension below.
    let first_error = unsafe { (*codes).first_error };
    let Some(name) = error_name(code.wrapping_sub(first_error)) else {
        return std::ptr::null_mut();
    };
    let bytes = name.to_bytes();
    let n = bytes.len().min(size as usize - 1);
    // SAFETY: Xlib's buffer holds `size` bytes; n + 1 <= size are written.
    unsafe {
        std::ptr::copy_nonoverlapping(bytes.as_ptr().cast::<c_char>(), buffer, n);
        *buffer.add(n) = 0;
    }
    buffer
}

/// Xlib's close-display procedure for the GLX extension: the display is no longer named.
unsafe extern "C" fn close_display(display: *mut Display, _codes: *mut XExtCodes) -> c_int {
    named_displays().remove(&(display as DisplayAddr));
    0
}

/// Registers the GLX error names with Xlib for `display` (once per open display), so that
/// XGetErrorText and Xlib's default error handler name tessera's GLX errors. Does nothing
/// without Xlib or a GLX extension on the server.
pub fn register_error_names(display: DisplayAddr) {
    if display == 0 || named_displays().contains(&display) {
        return;
    }
    let Some(x) = xlib() else {
        return;
    };
    // SAFETY: the application's open Display; XInitExtension returns Xlib's own record of
    // the extension on this display (NULL when the server lacks it), valid until it closes;
    // the procedures have the signatures Xlib calls them with.
    unsafe {
        let codes = (x.XInitExtension)(display as *mut Display, c"GLX".as_ptr());
        if codes.is_null() {
            return;
        }
        let extension = (*codes).extension;
        (x.XESetErrorString)(display as *mut Display, extension, Some(error_string));
        (x.XESetCloseDisplay)(display as *mut Display, extension, Some(close_display));
    }
    named_displays().insert(display);
}

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
    register_error_names(display);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glx_error_codes_have_xlib_names() {
        assert_eq!(error_name(0), Some(c"GLXBadContext"));
        assert_eq!(error_name(9), Some(c"GLXBadFBConfig"));
        assert_eq!(error_name(13), Some(c"GLXBadProfileARB"));
        assert_eq!(error_name(14), None);
        assert_eq!(error_name(-1), None);
        let mut codes = XExtCodes { extension: 150, major_opcode: 150, first_event: 90, first_error: 160 };
        let mut buffer = [b'x' as c_char; 32];
        let mut name = |code, buffer: &mut [c_char], size| {
            // SAFETY: `codes` and a buffer of at least `size` bytes, as Xlib passes them.
            let out = unsafe { error_string(std::ptr::null_mut(), code, &mut codes, buffer.as_mut_ptr(), size) };
            // SAFETY: error_string wrote a NUL-terminated name when it returned the buffer.
            (!out.is_null()).then(|| unsafe { CStr::from_ptr(out) }.to_str().unwrap().to_string())
        };
        assert_eq!(name(160 + 2, &mut buffer, 32).as_deref(), Some("GLXBadDrawable"));
        assert_eq!(name(160 + 12, &mut buffer, 7).as_deref(), Some("GLXBad"));
        // Core codes and other extensions' codes are not GLX's: the buffer is left alone.
        buffer[0] = b'?' as c_char;
        assert_eq!(name(8, &mut buffer, 32), None);
        assert_eq!(name(160 + 14, &mut buffer, 32), None);
        assert_eq!(buffer[0], b'?' as c_char);
    }
}
