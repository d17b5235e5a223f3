//! X server fonts as glyph bitmaps, for glXUseXFont.
//!
//! Each glyph of an X font is drawn with the font into a 1-bit pixmap on the server and read
//! back with XGetImage; the result is the bitmap glBitmap takes (rows bottom-up, most
//! significant bit first, rows padded to whole bytes) with the glyph's origin and advance
//! from the font's metrics. A character the font does not have yields an empty bitmap that
//! still advances by the font's default width, so that text layout stays regular.

use super::glx::{xlib, DisplayAddr};
use std::ffi::c_char;
use x11_dl::xlib::{XCharStruct, XFontStruct, XYPixmap};

/// One glyph, ready for glBitmap.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Glyph {
    pub width: i32,
    pub height: i32,
    /// glBitmap's xorig/yorig: the origin's position inside the bitmap.
    pub x_origin: f32,
    pub y_origin: f32,
    /// The advance after the glyph.
    pub x_move: f32,
    /// `height` rows of `(width + 7) / 8` bytes, the bottom row first.
    pub bits: Vec<u8>,
}

/// The metrics of character `c` in `fs`, or `None` when the font has no such glyph.
fn metrics(fs: &XFontStruct, c: u32) -> Option<XCharStruct> {
    // Single-byte fonts (min_byte1 == max_byte1 == 0), as glXUseXFont's characters are.
    if c < fs.min_char_or_byte2 || c > fs.max_char_or_byte2 {
        return None;
    }
    if fs.per_char.is_null() {
        return Some(fs.max_bounds);
    }
    // SAFETY: per_char has one entry per character from min_char_or_byte2 to max_char_or_byte2.
    let m = unsafe { *fs.per_char.add((c - fs.min_char_or_byte2) as usize) };
    let empty = m.width == 0 && m.lbearing == 0 && m.rbearing == 0 && m.ascent == 0 && m.descent == 0;
    (!empty).then_some(m)
}

/// The glyphs `first .. first + count` of `font` on `display`, or `None` when Xlib or the
/// font is not available.
pub fn glyphs(display: DisplayAddr, font: u64, first: i32, count: i32) -> Option<Vec<Glyph>> {
    let x = xlib()?;
    let dpy = display as *mut x11_dl::xlib::Display;
    if dpy.is_null() || count < 0 {
        return None;
    }
    // SAFETY: a live Display of the application (the current GLX binding's) and a font id;
    // XQueryFont returns NULL for a bad font.
    let fs_ptr = unsafe { (x.XQueryFont)(dpy, font) };
    if fs_ptr.is_null() {
        return None;
    }
    // SAFETY: non-null, owned by us until XFreeFontInfo below.
    let fs = unsafe { &*fs_ptr };
    // max_bounds and min_bounds hold each metric's extreme separately: the widest ink is
    // from the smallest left bearing to the largest right bearing.
    let (max, min) = (fs.max_bounds, fs.min_bounds);
    let pixmap_w = ((max.rbearing as i32 - min.lbearing as i32).max(1)) as u32;
    let pixmap_h = ((max.ascent as i32 + max.descent as i32).max(1)) as u32;
    let mut out = Vec::with_capacity(count as usize);
    // SAFETY: Xlib calls on the application's display with objects created here and freed at
    // the end; XGetImage's image is read within its size and destroyed.
    unsafe {
        let root = (x.XDefaultRootWindow)(dpy);
        let pixmap = (x.XCreatePixmap)(dpy, root, pixmap_w, pixmap_h, 1);
        let gc = (x.XCreateGC)(dpy, pixmap, 0, std::ptr::null_mut());
        (x.XSetFont)(dpy, gc, font);
        for i in 0..count {
            let c = (first + i) as u32;
            let Some(m) = metrics(fs, c) else {
                out.push(Glyph { x_move: max.width as f32, ..Glyph::default() });
                continue;
            };
            let width = (m.rbearing as i32 - m.lbearing as i32).max(0);
            let height = (m.ascent as i32 + m.descent as i32).max(0);
            let mut glyph = Glyph {
                width,
                height,
                x_origin: -(m.lbearing as f32),
                y_origin: m.descent as f32,
                x_move: m.width as f32,
                bits: Vec::new(),
            };
            if width > 0 && height > 0 {
                (x.XSetForeground)(dpy, gc, 0);
                (x.XFillRectangle)(dpy, pixmap, gc, 0, 0, pixmap_w, pixmap_h);
                (x.XSetForeground)(dpy, gc, 1);
                let ch = c as u8 as c_char;
                (x.XDrawString)(dpy, pixmap, gc, -(m.lbearing as i32), m.ascent as i32, &ch, 1);
                let image = (x.XGetImage)(dpy, pixmap, 0, 0, width as u32, height as u32, 1, XYPixmap);
                if !image.is_null() {
                    let row_bytes = (width as usize).div_ceil(8);
                    glyph.bits = vec![0; row_bytes * height as usize];
                    for y in 0..height {
                        // X rows run top-down, glBitmap's bottom-up.
                        let row = (height - 1 - y) as usize * row_bytes;
                        for px in 0..width {
                            if (x.XGetPixel)(image, px, y) != 0 {
                                glyph.bits[row + px as usize / 8] |= 0x80 >> (px % 8);
                            }
                        }
                    }
                    (x.XDestroyImage)(image);
                }
            }
            out.push(glyph);
        }
        (x.XFreeGC)(dpy, gc);
        (x.XFreePixmap)(dpy, pixmap);
        (x.XFreeFontInfo)(std::ptr::null_mut(), fs_ptr, 1);
    }
    Some(out)
}
