//! Point setup: which pixels an aliased point covers (GL 2.1 §3.4.1, "basic point
//! rasterization"), in llvmpipe's fixed-point arithmetic.
//!
//! A point of integer size `n` covers an `n × n` square of pixels: for odd `n` centred on
//! the pixel that contains the point, for even `n` on the pixel corner nearest to it. The
//! size is rounded to an integer first (at 1/256 precision, halves rounding down) and is at
//! least 1. llvmpipe decides this in its y-down window space with the bottom-left fill
//! convention, which shifts the point's y by one subpixel before truncating: a point
//! exactly on a pixel border in y belongs to the pixel above it in GL terms (measured on
//! Mesa 22: a size-1 point at y = 2.0 lights row 2, not row 1).
use super::line::round_half_away;
use crate::framebuffer::Rect;

const ORDER: u32 = 8;
const ONE: i64 = 1 << ORDER;

/// Snaps a coordinate to fixed point as llvmpipe does (see the line setup).
#[inline]
fn snap(v: f32) -> i64 {
    round_half_away(v * ONE as f32)
}

/// The integer side of a point of size `size` (after clamping), in pixels.
pub fn point_side(size: f32) -> i64 {
    (((snap(size) + ONE / 2 - 1) & !(ONE - 1)) >> ORDER).max(1)
}

/// The pixels covered by a point at `(x, y_down)` (y-down window coordinates of a
/// framebuffer `height` rows high) of size `size`, as a GL rectangle (exclusive maxima).
pub fn point_rect(x: f32, y_down: f32, size: f32, height: i32) -> Rect {
    let side = point_side(size);
    let fx = snap(x);
    let fy = snap(y_down) - 1;
    let start = |f: i64| {
        if side & 1 == 1 {
            (f >> ORDER) - (side - 1) / 2
        } else {
            ((f + ONE / 2) >> ORDER) - side / 2
        }
    };
    let (x0, y0) = (start(fx), start(fy));
    let to_i32 = |v: i64| v.clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
    // y-down rows y0 ..= y0 + side − 1 are GL rows height − y0 − side ..= height − 1 − y0.
    Rect {
        x0: to_i32(x0),
        x1: to_i32(x0 + side),
        y0: to_i32(height as i64 - y0 - side),
        y1: to_i32(height as i64 - y0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_round_to_whole_pixels_halves_down() {
        assert_eq!([0.1, 1.0, 1.5, 1.51, 2.5, 2.51, 254.9].map(point_side), [1, 1, 1, 2, 2, 3, 255]);
    }

    #[test]
    fn odd_points_centre_on_their_pixel_even_points_on_the_nearest_corner() {
        // GL coordinates (x, y) in an 16-row framebuffer: y_down = 16 − y.
        let rect = |x: f32, y: f32, s: f32| point_rect(x, 16.0 - y, s, 16);
        assert_eq!(rect(4.5, 4.5, 1.0), Rect { x0: 4, x1: 5, y0: 4, y1: 5 });
        assert_eq!(rect(4.5, 4.5, 5.0), Rect { x0: 2, x1: 7, y0: 2, y1: 7 });
        assert_eq!(rect(4.2, 4.7, 2.0), Rect { x0: 3, x1: 5, y0: 4, y1: 6 });
        // On a pixel border in y, the point belongs to the row above.
        assert_eq!(rect(4.5, 2.0, 1.0), Rect { x0: 4, x1: 5, y0: 2, y1: 3 });
    }
}
