//! GL_DITHER for RGB565 targets: an ordered 4×4 dither applied when 8-bit color channels are
//! reduced to 5 or 6 bits. 8-bit and wider targets are not dithered (a no-op).
//!
//! Mesa 22 does not dither, so this is tessera's own definition, exact against it:
//! - the matrix is the 4×4 Bayer matrix [`BAYER4`], indexed `[y & 3][x & 3]` by window
//!   coordinates (x right, y up, origin at the window's lower left pixel);
//! - a channel's 8-bit value `v` becomes `floor(v·max/255 + (M + ½)/16)` with `max` = 31 or
//!   63, computed exactly in integers as `(32·v·max + (2M + 1)·255) / (32·255)`. The result
//!   never exceeds `max`, 0 stays 0 and 255 stays `max`, and over the 16 cells of the matrix
//!   the mean is within 1/32 of the exact `v·max/255`, where the undithered store (which
//!   truncates, `v >> 3`, as llvmpipe does) is biased down by up to one step.

/// The ordered-dither thresholds: cell `M` adds `(M + ½)/16` of a step before truncation.
pub const BAYER4: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

/// Reduces the 8-bit value `v` to `bits` (5 or 6) bits with matrix cell `m` (0..16).
#[inline(always)]
pub fn dither_channel(v: u8, bits: u32, m: u8) -> u32 {
    let max = (1u32 << bits) - 1;
    (32 * v as u32 * max + (2 * m as u32 + 1) * 255) / (32 * 255)
}

/// Packs 8-bit RGB colors of a span starting at window pixel (`x0`, `y`) into dithered
/// RGB565 words in `out` (every pixel of the span; the caller writes the live ones).
pub fn dither_rgb565(x0: u32, y: u32, colors: &[[u8; 4]], out: &mut [u16]) {
    let row = &BAYER4[(y & 3) as usize];
    for (i, (o, c)) in out.iter_mut().zip(colors).enumerate().take(super::MAX_SPAN) {
        let m = row[((x0 + i as u32) & 3) as usize];
        let r = dither_channel(c[0], 5, m);
        let g = dither_channel(c[1], 6, m);
        let b = dither_channel(c[2], 5, m);
        *o = (r << 11 | g << 5 | b) as u16;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrix_is_a_permutation_of_0_to_15() {
        let mut seen = [false; 16];
        BAYER4.iter().flatten().for_each(|&m| seen[m as usize] = true);
        assert!(seen.iter().all(|&s| s));
    }

    #[test]
    fn endpoints_are_exact_and_bounded() {
        for m in 0..16 {
            assert_eq!(dither_channel(0, 5, m), 0);
            assert_eq!(dither_channel(255, 5, m), 31);
            assert_eq!(dither_channel(0, 6, m), 0);
            assert_eq!(dither_channel(255, 6, m), 63);
        }
        for v in 0..=255u8 {
            for m in 0..16 {
                assert!(dither_channel(v, 5, m) <= 31 && dither_channel(v, 6, m) <= 63);
            }
        }
    }

    #[test]
    fn mean_over_the_matrix_tracks_the_exact_value() {
        for bits in [5, 6] {
            let max = (1u32 << bits) - 1;
            for v in 0..=255u8 {
                let sum: u32 = (0..16).map(|m| dither_channel(v, bits, m)).sum();
                let exact = 16.0 * v as f64 * max as f64 / 255.0;
                assert!((sum as f64 - exact).abs() <= 0.5, "v {v} bits {bits}: {sum} vs {exact}");
            }
        }
    }

    #[test]
    fn span_pattern_is_anchored_at_the_window_origin() {
        // v = 132: 132·31/255 = 16.047 on red/blue → 17 only where (M + ½)/16 ≥ 0.953, M = 15;
        // 132·63/255 = 32.612 on green → 33 where M ≥ 6.
        let colors = [[132u8, 132, 132, 255]; 4];
        let mut out = [0u16; 4];
        dither_rgb565(0, 1, &colors, &mut out);
        // Row 1 is [12, 4, 14, 6]: green 33, 32, 33, 33; red and blue 16.
        let w = |r: u16, g: u16, b: u16| r << 11 | g << 5 | b;
        assert_eq!(out, [w(16, 33, 16), w(16, 32, 16), w(16, 33, 16), w(16, 33, 16)]);
        // Starting at x = 2 on row 3 ([15, 7, 13, 5]): cells 13, 5, 15, 7.
        dither_rgb565(2, 7, &colors, &mut out);
        assert_eq!(out, [w(16, 33, 16), w(16, 32, 16), w(17, 33, 17), w(16, 33, 16)]);
    }
}
