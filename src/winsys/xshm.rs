//! MIT-SHM images: presentation through memory shared with the X server, where it offers it.
//!
//! XPutImage copies every frame through the X connection; with MIT-SHM the server reads the
//! pixels from a shared segment instead. libXext.so.6 is loaded at run time like Xlib. A
//! server that cannot see our memory (another machine or IPC namespace) refuses the attach
//! with an X error, which is caught by a temporary error handler, as Mesa's Xlib driver
//! does; the presenter then falls back to XPutImage. `TESSERA_XSHM=0` turns MIT-SHM off.
use super::libx11::Xlib;
use std::ffi::{c_int, c_uint, c_ulong};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, OnceLock};
use x11_dl::xlib;
use x11_dl::xshm::{XShmSegmentInfo, Xext};

/// libXext, loaded once; `None` when missing or when `TESSERA_XSHM=0`.
fn xext() -> Option<&'static Xext> {
    static XEXT: OnceLock<Option<Xext>> = OnceLock::new();
    XEXT.get_or_init(|| {
        if std::env::var("TESSERA_XSHM").is_ok_and(|v| v == "0") {
            return None;
        }
        Xext::open().ok()
    })
    .as_ref()
}

/// Set by the temporary error handler while a segment is attached.
static ATTACH_FAILED: AtomicBool = AtomicBool::new(false);
/// The error handler is process-wide: one attach at a time.
static ATTACHING: Mutex<()> = Mutex::new(());

unsafe extern "C" fn note_attach_error(_display: *mut xlib::Display, _event: *mut xlib::XErrorEvent) -> c_int {
    ATTACH_FAILED.store(true, Ordering::SeqCst);
    0
}

/// A shared-memory ZPixmap image of one size.
pub(super) struct ShmImage {
    image: *mut xlib::XImage,
    info: Box<XShmSegmentInfo>,
    pub(super) width: usize,
    pub(super) height: usize,
}

// SAFETY: the image header and segment are owned by this value; they are only used by the
// thread holding the drawable's lock (the presenter is inside it).
unsafe impl Send for ShmImage {}

impl ShmImage {
    /// A `width` × `height` image for `visual`/`depth`, attached to the server; `None` when
    /// MIT-SHM is missing or refused.
    pub(super) fn new(
        x: &Xlib,
        display: *mut xlib::Display,
        visual: *mut xlib::Visual,
        depth: i32,
        width: usize,
        height: usize,
    ) -> Option<ShmImage> {
        let ext = xext()?;
        // SAFETY: valid display (the application's, open while its drawables are used).
        if unsafe { (ext.XShmQueryExtension)(display) } == 0 {
            return None;
        }
        // SAFETY: plain data, filled below.
        let mut info: Box<XShmSegmentInfo> = Box::new(unsafe { std::mem::zeroed() });
        // SAFETY: valid display and visual; the header is freed on every path below.
        let image = unsafe {
            (ext.XShmCreateImage)(
                display,
                visual,
                depth as c_uint,
                xlib::ZPixmap,
                std::ptr::null_mut(),
                &mut *info,
                width as c_uint,
                height as c_uint,
            )
        };
        if image.is_null() {
            return None;
        }
        // SAFETY: a valid header from XShmCreateImage.
        let size = unsafe { (*image).bytes_per_line.max(0) as usize * height };
        // SAFETY: plain System V calls; failures are checked.
        let shmid = unsafe { libc::shmget(libc::IPC_PRIVATE, size.max(1), libc::IPC_CREAT | 0o600) };
        if shmid < 0 {
            // SAFETY: the header allocated above (no data attached).
            unsafe { (x.XFree)(image.cast()) };
            return None;
        }
        // SAFETY: the segment just created.
        let address = unsafe { libc::shmat(shmid, std::ptr::null(), 0) };
        if address as isize == -1 {
            // SAFETY: the segment and header created above.
            unsafe {
                libc::shmctl(shmid, libc::IPC_RMID, std::ptr::null_mut());
                (x.XFree)(image.cast());
            }
            return None;
        }
        info.shmid = shmid;
        info.shmaddr = address.cast();
        info.readOnly = 0;
        // SAFETY: the header's data points into the attached segment of `size` bytes.
        unsafe { (*image).data = address.cast() };
        let attached = {
            let _one_at_a_time = ATTACHING.lock().unwrap_or_else(|p| p.into_inner());
            ATTACH_FAILED.store(false, Ordering::SeqCst);
            // SAFETY: valid display; the handler only records the failure; the previous
            // handler is restored before the lock is released.
            unsafe {
                (x.XSync)(display, 0);
                let previous = (x.XSetErrorHandler)(Some(note_attach_error));
                (ext.XShmAttach)(display, &mut *info);
                (x.XSync)(display, 0);
                (x.XSetErrorHandler)(previous);
            }
            !ATTACH_FAILED.load(Ordering::SeqCst)
        };
        // SAFETY: marks the segment for removal once both sides detached (never leaks).
        unsafe { libc::shmctl(shmid, libc::IPC_RMID, std::ptr::null_mut()) };
        let shm = ShmImage { image, info, width, height };
        attached.then_some(shm)
    }

    /// Bytes per row, bits per pixel and byte order of the image.
    pub(super) fn layout(&self) -> (usize, i32, i32) {
        // SAFETY: a valid header owned by self.
        unsafe {
            ((*self.image).bytes_per_line.max(0) as usize, (*self.image).bits_per_pixel, (*self.image).byte_order)
        }
    }

    /// The pixel bytes, for filling before `put`.
    pub(super) fn bytes_mut(&mut self) -> &mut [u8] {
        let (bytes_per_line, _, _) = self.layout();
        // SAFETY: the segment holds bytes_per_line × height bytes, mapped while self lives;
        // `put` waits until the server read them, so nobody else uses them now.
        unsafe { std::slice::from_raw_parts_mut(self.info.shmaddr.cast::<u8>(), bytes_per_line * self.height) }
    }

    /// Shows the image at (0, 0) of `target` and waits until the server has read it.
    pub(super) fn put(&mut self, x: &Xlib, display: *mut xlib::Display, target: c_ulong, gc: xlib::GC) {
        let Some(ext) = xext() else {
            return;
        };
        // SAFETY: valid display, drawable and GC; the image is attached to this display.
        unsafe {
            (ext.XShmPutImage)(
                display,
                target,
                gc,
                self.image,
                0,
                0,
                0,
                0,
                self.width as c_uint,
                self.height as c_uint,
                0,
            );
            (x.XSync)(display, 0);
        }
    }

    /// Detaches from the server (the display must still be open).
    pub(super) fn detach(&mut self, display: *mut xlib::Display) {
        if let Some(ext) = xext() {
            // SAFETY: valid display; the segment is attached to it.
            unsafe { (ext.XShmDetach)(display, &mut *self.info) };
        }
    }
}

impl Drop for ShmImage {
    /// Unmaps our side only: no X call, since the display may already be closed (the server
    /// drops its side when the client disconnects, and the segment is already removed).
    fn drop(&mut self) {
        // SAFETY: our mapping and the header (its data detached first so that free() does
        // not touch the segment).
        unsafe {
            libc::shmdt(self.info.shmaddr.cast());
            (*self.image).data = std::ptr::null_mut();
            libc::free(self.image.cast());
        }
    }
}
