//! The Xlib functions tessera's GLX calls, loaded at run time from libX11.so.6.
//!
//! Loading Xlib at run time keeps libGL.so.1 free of a link-time X dependency and lets
//! OSMesa users run without X libraries. x11-dl's `Xlib::open` would do it, but it looks up
//! every one of Xlib's ~800 functions, and the code of those look-ups cost each library
//! 71 KB; the table below holds only the functions tessera calls, with x11-dl's own
//! (hand-checked) C signatures and types. Add a function here before calling it.
use std::ffi::{c_char, c_int, c_long, c_uint, c_ulong, c_void};
use x11_dl::xlib::{
    Display, Visual, XErrorEvent, XExtCodes, XFontStruct, XGCValues, XImage, XVisualInfo, XWindowAttributes, GC,
};

/// An error-string procedure of an extension (`XESetErrorString`).
pub type ErrorStringProc = unsafe extern "C" fn(*mut Display, c_int, *mut XExtCodes, *mut c_char, c_int) -> *mut c_char;
/// A close-display procedure of an extension (`XESetCloseDisplay`).
pub type CloseDisplayProc = unsafe extern "C" fn(*mut Display, *mut XExtCodes) -> c_int;
/// An X error handler (`XSetErrorHandler`).
pub type ErrorHandler = unsafe extern "C" fn(*mut Display, *mut XErrorEvent) -> c_int;

/// Declares [`Xlib`], one field per function, and its loader, which looks each one up by
/// its own name.
macro_rules! xlib_functions {
    ($($name:ident: fn($($arg:ty),*) -> $ret:ty;)*) => {
        /// The Xlib functions tessera calls, as loaded by [`Xlib::open`].
        #[allow(non_snake_case)]
        pub struct Xlib {
            $(pub $name: unsafe extern "C" fn($($arg),*) -> $ret,)*
        }

        impl Xlib {
            /// libX11.so.6 (or libX11.so) and the functions above; `None` if the library
            /// or one of the functions is missing. The library stays loaded for the
            /// life of the process.
            pub fn open() -> Option<Xlib> {
                // SAFETY: dlopen of NUL-terminated names; libX11's initialisers are safe to
                // run at any time (Xlib does nothing until a display is opened).
                let library = unsafe {
                    let first = libc::dlopen(c"libX11.so.6".as_ptr(), libc::RTLD_LAZY);
                    if first.is_null() { libc::dlopen(c"libX11.so".as_ptr(), libc::RTLD_LAZY) } else { first }
                };
                if library.is_null() {
                    return None;
                }
                Some(Xlib {
                    $($name: {
                        // SAFETY: dlsym with a NUL-terminated name in the library just
                        // opened (never closed); the symbol is the Xlib function of that
                        // name, whose C signature the field's type mirrors (x11-dl's).
                        unsafe {
                            let symbol = libc::dlsym(library, concat!(stringify!($name), "\0").as_ptr() as *const c_char);
                            if symbol.is_null() {
                                return None;
                            }
                            std::mem::transmute::<*mut c_void, unsafe extern "C" fn($($arg),*) -> $ret>(symbol)
                        }
                    },)*
                })
            }
        }
    };
}

xlib_functions! {
    XCreateGC: fn(*mut Display, c_ulong, c_ulong, *mut XGCValues) -> GC;
    XCreateImage: fn(*mut Display, *mut Visual, c_uint, c_int, c_int, *mut c_char, c_uint, c_uint, c_int, c_int) -> *mut XImage;
    XCreatePixmap: fn(*mut Display, c_ulong, c_uint, c_uint, c_uint) -> c_ulong;
    XDefaultRootWindow: fn(*mut Display) -> c_ulong;
    XDestroyImage: fn(*mut XImage) -> c_int;
    XDrawString: fn(*mut Display, c_ulong, GC, c_int, c_int, *const c_char, c_int) -> c_int;
    XESetCloseDisplay: fn(*mut Display, c_int, Option<CloseDisplayProc>) -> Option<CloseDisplayProc>;
    XESetErrorString: fn(*mut Display, c_int, Option<ErrorStringProc>) -> Option<ErrorStringProc>;
    XFillRectangle: fn(*mut Display, c_ulong, GC, c_int, c_int, c_uint, c_uint) -> c_int;
    XFlush: fn(*mut Display) -> c_int;
    XFree: fn(*mut c_void) -> c_int;
    XFreeFontInfo: fn(*mut *mut c_char, *mut XFontStruct, c_int) -> c_int;
    XFreeGC: fn(*mut Display, GC) -> c_int;
    XFreePixmap: fn(*mut Display, c_ulong) -> c_int;
    XGetGeometry: fn(*mut Display, c_ulong, *mut c_ulong, *mut c_int, *mut c_int, *mut c_uint, *mut c_uint, *mut c_uint, *mut c_uint) -> c_int;
    XGetImage: fn(*mut Display, c_ulong, c_int, c_int, c_uint, c_uint, c_ulong, c_int) -> *mut XImage;
    XGetPixel: fn(*mut XImage, c_int, c_int) -> c_ulong;
    XGetVisualInfo: fn(*mut Display, c_long, *mut XVisualInfo, *mut c_int) -> *mut XVisualInfo;
    XGetWindowAttributes: fn(*mut Display, c_ulong, *mut XWindowAttributes) -> c_int;
    XInitExtension: fn(*mut Display, *const c_char) -> *mut XExtCodes;
    XNextRequest: fn(*mut Display) -> c_ulong;
    XPutImage: fn(*mut Display, c_ulong, GC, *mut XImage, c_int, c_int, c_int, c_int, c_uint, c_uint) -> c_int;
    XQueryExtension: fn(*mut Display, *const c_char, *mut c_int, *mut c_int, *mut c_int) -> c_int;
    XQueryFont: fn(*mut Display, c_ulong) -> *mut XFontStruct;
    XRootWindow: fn(*mut Display, c_int) -> c_ulong;
    XScreenCount: fn(*mut Display) -> c_int;
    XSetErrorHandler: fn(Option<ErrorHandler>) -> Option<ErrorHandler>;
    XSetFont: fn(*mut Display, GC, c_ulong) -> c_int;
    XSetForeground: fn(*mut Display, GC, c_ulong) -> c_int;
    XSync: fn(*mut Display, c_int) -> c_int;
}
