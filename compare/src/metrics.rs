//! How two pictures of the same scene differ: per-pixel errors (optionally allowing a
//! 1-pixel shift), PSNR, SSIM and a difference heat map. The definitions are the ones the
//! README documents; the unit tests below check them against values computed by hand.

use crate::image::Image;

/// The differences between a reference picture and a tested one.
#[derive(Clone, Debug, PartialEq)]
pub struct Metrics {
    /// Largest pixel error (see [`pixel_error`]), 0..=255.
    pub max_error: u8,
    /// Pixels whose error is above the tolerance.
    pub bad_pixels: usize,
    /// The tolerance `bad_pixels` was counted with.
    pub tolerance: u8,
    /// Whether the errors allow a 1-pixel shift.
    pub shift: bool,
    /// PSNR in dB over R, G and B (infinite when the colors are identical).
    pub psnr: f64,
    /// Mean SSIM of the luminances, 1.0 when identical.
    pub ssim: f64,
}

/// The error of the tested pixel (x, y): its largest channel difference (R, G, B or A) to
/// the reference pixel at the same place or, with `shift`, to the best matching reference
/// pixel among the up to nine within one pixel (x and y each -1, 0 or +1).
pub fn pixel_error(reference: &Image, tested: &Image, x: usize, y: usize, shift: bool) -> u8 {
    let t = tested.pixel(x, y);
    let radius = usize::from(shift);
    let mut best = u8::MAX;
    for ry in y.saturating_sub(radius)..=(y + radius).min(reference.height - 1) {
        for rx in x.saturating_sub(radius)..=(x + radius).min(reference.width - 1) {
            let r = reference.pixel(rx, ry);
            let error = (0..4).map(|c| t[c].abs_diff(r[c])).max().unwrap_or(0);
            best = best.min(error);
        }
    }
    best
}

/// Compares `tested` with `reference` (same size, else an error message).
pub fn compare(reference: &Image, tested: &Image, tolerance: u8, shift: bool) -> Result<Metrics, String> {
    if (reference.width, reference.height) != (tested.width, tested.height) {
        return Err(format!(
            "size {}x{} differs from the reference's {}x{}",
            tested.width, tested.height, reference.width, reference.height
        ));
    }
    let mut max_error = 0;
    let mut bad_pixels = 0;
    for y in 0..tested.height {
        for x in 0..tested.width {
            let error = pixel_error(reference, tested, x, y, shift);
            max_error = max_error.max(error);
            bad_pixels += usize::from(error > tolerance);
        }
    }
    Ok(Metrics {
        max_error,
        bad_pixels,
        tolerance,
        shift,
        psnr: psnr(reference, tested),
        ssim: ssim(reference, tested),
    })
}

/// PSNR over the R, G and B channels: 10 log10(255² / MSE), MSE the mean of the squared
/// channel differences over all pixels and the three channels; infinite for MSE 0.
pub fn psnr(a: &Image, b: &Image) -> f64 {
    let mut sum = 0.0f64;
    for (pa, pb) in a.rgba.chunks_exact(4).zip(b.rgba.chunks_exact(4)) {
        for c in 0..3 {
            let d = f64::from(pa[c]) - f64::from(pb[c]);
            sum += d * d;
        }
    }
    let count = (a.rgba.len() / 4 * 3).max(1) as f64;
    let mse = sum / count;
    if mse == 0.0 {
        f64::INFINITY
    } else {
        10.0 * (255.0f64 * 255.0 / mse).log10()
    }
}

/// The luminance of a pixel: Y = 0.299 R + 0.587 G + 0.114 B (ITU-R BT.601), 0..255.
pub fn luminance(p: [u8; 4]) -> f64 {
    0.299 * f64::from(p[0]) + 0.587 * f64::from(p[1]) + 0.114 * f64::from(p[2])
}

/// Radius and standard deviation of the SSIM window: 11x11, sigma 1.5 (Wang et al. 2004).
const SSIM_RADIUS: usize = 5;
const SSIM_SIGMA: f64 = 1.5;

/// Mean SSIM of the luminances (Wang, Bovik, Sheikh, Simoncelli 2004): at every pixel, the
/// means, variances and covariance of the two luminance pictures are taken over an 11x11
/// gaussian window (sigma 1.5) centred on the pixel; near the border the window keeps only
/// the taps inside the picture, renormalised to sum 1. Then
/// SSIM = (2 mx my + C1)(2 sxy + C2) / ((mx² + my² + C1)(sx² + sy² + C2)) with
/// C1 = (0.01 * 255)², C2 = (0.03 * 255)², and the result is the mean over all pixels.
pub fn ssim(a: &Image, b: &Image) -> f64 {
    let (w, h) = (a.width, a.height);
    if w == 0 || h == 0 {
        return 1.0;
    }
    let ya: Vec<f64> = a.rgba.chunks_exact(4).map(|p| luminance([p[0], p[1], p[2], p[3]])).collect();
    let yb: Vec<f64> = b.rgba.chunks_exact(4).map(|p| luminance([p[0], p[1], p[2], p[3]])).collect();
    let products = |f: &dyn Fn(usize) -> f64| -> Vec<f64> { (0..w * h).map(f).collect() };
    let mean_a = gaussian_blur(&ya, w, h);
    let mean_b = gaussian_blur(&yb, w, h);
    let mean_aa = gaussian_blur(&products(&|i| ya[i] * ya[i]), w, h);
    let mean_bb = gaussian_blur(&products(&|i| yb[i] * yb[i]), w, h);
    let mean_ab = gaussian_blur(&products(&|i| ya[i] * yb[i]), w, h);
    let c1 = (0.01f64 * 255.0).powi(2);
    let c2 = (0.03f64 * 255.0).powi(2);
    let mut total = 0.0;
    for i in 0..w * h {
        let (mx, my) = (mean_a[i], mean_b[i]);
        let var_x = mean_aa[i] - mx * mx;
        let var_y = mean_bb[i] - my * my;
        let cov = mean_ab[i] - mx * my;
        total += (2.0 * mx * my + c1) * (2.0 * cov + c2) / ((mx * mx + my * my + c1) * (var_x + var_y + c2));
    }
    total / (w * h) as f64
}

/// The separable gaussian window average of `values` (w x h) at every pixel, taps outside
/// the picture left out and the rest renormalised (per axis, which is the same as in 2D).
fn gaussian_blur(values: &[f64], w: usize, h: usize) -> Vec<f64> {
    let taps: Vec<f64> = (0..=2 * SSIM_RADIUS)
        .map(|i| {
            let d = i as f64 - SSIM_RADIUS as f64;
            (-d * d / (2.0 * SSIM_SIGMA * SSIM_SIGMA)).exp()
        })
        .collect();
    let blur_axis = |input: &[f64], along_x: bool| -> Vec<f64> {
        let mut out = vec![0.0; w * h];
        let len = if along_x { w } else { h };
        for y in 0..h {
            for x in 0..w {
                let pos = if along_x { x } else { y };
                let (mut sum, mut weight) = (0.0, 0.0);
                for (k, tap) in taps.iter().enumerate() {
                    let p = pos as isize + k as isize - SSIM_RADIUS as isize;
                    if p < 0 || p >= len as isize {
                        continue;
                    }
                    let (sx, sy) = if along_x { (p as usize, y) } else { (x, p as usize) };
                    sum += tap * input[sy * w + sx];
                    weight += tap;
                }
                out[y * w + x] = sum / weight;
            }
        }
        out
    };
    blur_axis(&blur_axis(values, true), false)
}

/// The heat map color of a pixel error `d` > 0: green (0, 255, 0) for 1, red (255, 0, 0)
/// for 128 and more, in between t = log2(d) / 7 mixes them: (round(255 t), round(255 (1 - t)), 0).
pub fn heat_color(d: u8) -> [u8; 4] {
    let t = (f64::from(d).log2() / 7.0).min(1.0);
    [(255.0 * t).round() as u8, (255.0 * (1.0 - t)).round() as u8, 0, 255]
}

/// The difference heat map: where the pixels are equal (error 0, no shift allowance) a dim
/// grey copy of the reference (grey level 32 + Y/4, Y its luminance rounded down), elsewhere
/// [`heat_color`] of the error. Both pictures must have the same size.
pub fn heat_map(reference: &Image, tested: &Image) -> Image {
    let mut out = Image::filled(reference.width, reference.height, [0, 0, 0, 255]);
    for y in 0..reference.height {
        for x in 0..reference.width {
            let d = pixel_error(reference, tested, x, y, false);
            let color = if d == 0 {
                let grey = 32 + (luminance(reference.pixel(x, y)) as u8) / 4;
                [grey, grey, grey, 255]
            } else {
                heat_color(d)
            };
            out.set_pixel(x, y, color);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey(width: usize, height: usize, values: &[u8]) -> Image {
        Image { width, height, rgba: values.iter().flat_map(|&v| [v, v, v, 255]).collect() }
    }

    #[test]
    fn psnr_of_known_differences() {
        let a = grey(2, 2, &[0, 0, 0, 0]);
        assert_eq!(psnr(&a, &a), f64::INFINITY);
        // One channel of one pixel off by 10: MSE = 100 / 12.
        let mut b = a.clone();
        b.rgba[0] = 10;
        let expected = 10.0 * (65025.0f64 / (100.0 / 12.0)).log10(); // 38.9226 dB
        assert!((psnr(&a, &b) - expected).abs() < 1e-12);
        assert!((psnr(&a, &b) - 38.922616).abs() < 1e-5);
        // Every channel off by 255: 0 dB. Alpha is not part of PSNR.
        let white = grey(2, 2, &[255, 255, 255, 255]);
        assert!(psnr(&a, &white).abs() < 1e-12);
        let mut alpha = a.clone();
        alpha.rgba[3] = 0;
        assert_eq!(psnr(&a, &alpha), f64::INFINITY);
    }

    #[test]
    fn ssim_of_known_pictures() {
        // Identical pictures: 1.
        let a = grey(7, 5, &(0..35).map(|i| (i * 7 % 256) as u8).collect::<Vec<_>>());
        assert!((ssim(&a, &a) - 1.0).abs() < 1e-12);
        // Two flat pictures: variances 0, so SSIM = (2 x y + C1) / (x² + y² + C1) everywhere.
        // x = 100, y = 110 (grey levels are their own luminance): 22006.5025 / 22106.5025.
        let (x, y) = (grey(6, 6, &[100; 36]), grey(6, 6, &[110; 36]));
        let c1 = 6.5025;
        let expected = (2.0 * 100.0 * 110.0 + c1) / (100.0f64 * 100.0 + 110.0 * 110.0 + c1);
        assert!((ssim(&x, &y) - expected).abs() < 1e-9);
        assert!((ssim(&x, &y) - 0.9954764).abs() < 1e-6);
        // A 2x1 picture [0, 255] against its negative [255, 0]. At each pixel the window holds
        // the pixel with weight 1 and the other with w = exp(-1 / 4.5), normalised to
        // p = 1 / (1 + w) and q = w / (1 + w): means 255 q and 255 p, both variances 255² pq,
        // covariance -255² pq, so SSIM = (2 s pq + C1)(C2 - 2 s pq) / ((s (p² + q²) + C1)(2 s pq + C2))
        // with s = 255², at both pixels.
        let (p, q) = (grey(2, 1, &[0, 255]), grey(2, 1, &[255, 0]));
        let w = (-1.0f64 / 4.5).exp();
        let (pw, qw, s, c2) = (1.0 / (1.0 + w), w / (1.0 + w), 65025.0f64, 58.5225);
        let expected = (2.0 * s * pw * qw + c1) * (c2 - 2.0 * s * pw * qw)
            / ((s * (pw * pw + qw * qw) + c1) * (2.0 * s * pw * qw + c2));
        assert!((ssim(&p, &q) - expected).abs() < 1e-9);
        assert!((ssim(&p, &q) - (-0.9722615)).abs() < 1e-6);
    }

    #[test]
    fn ssim_matches_a_direct_window_sum() {
        // 13x12 pseudo-random picture against a noisy copy: the separable blur must equal
        // the direct 2D truncated, renormalised gaussian window. Reference value computed
        // independently (Python, direct 2D windows): 0.469835534.
        let values: Vec<u8> = (0..156u32).map(|i| ((i * 73 + 19) % 251) as u8).collect();
        let noisy: Vec<u8> = values.iter().enumerate().map(|(i, &v)| v.wrapping_add((i % 7) as u8 * 9)).collect();
        let (a, b) = (grey(13, 12, &values), grey(13, 12, &noisy));
        let got = ssim(&a, &b);
        assert!((got - SSIM_13X12).abs() < 1e-6, "ssim {got}");
    }

    /// See `ssim_matches_a_direct_window_sum`.
    const SSIM_13X12: f64 = 0.469835534;

    #[test]
    fn shift_allowance() {
        // A vertical white line at x = 2 in the reference, at x = 3 in the tested picture.
        let mut reference = grey(6, 4, &[0; 24]);
        let mut tested = reference.clone();
        for y in 0..4 {
            reference.set_pixel(2, y, [255, 255, 255, 255]);
            tested.set_pixel(3, y, [255, 255, 255, 255]);
        }
        let exact = compare(&reference, &tested, 0, false).unwrap();
        assert_eq!((exact.max_error, exact.bad_pixels), (255, 8));
        let shifted = compare(&reference, &tested, 0, true).unwrap();
        assert_eq!((shifted.max_error, shifted.bad_pixels), (0, 0));
        // Two pixels away is not within the allowance: only the line's own pixels differ
        // (the black pixel at x = 2 finds black at x = 1).
        let mut far = grey(6, 4, &[0; 24]);
        for y in 0..4 {
            far.set_pixel(4, y, [255, 255, 255, 255]);
        }
        let shifted = compare(&reference, &far, 0, true).unwrap();
        assert_eq!((shifted.max_error, shifted.bad_pixels), (255, 4));
        // Tolerance: one channel off by 3 counts as bad with tolerance 2, not with 3.
        let mut near = reference.clone();
        near.rgba[1] = 3;
        assert_eq!(compare(&reference, &near, 2, false).unwrap().bad_pixels, 1);
        assert_eq!(compare(&reference, &near, 3, false).unwrap().bad_pixels, 0);
        assert!(compare(&reference, &grey(5, 4, &[0; 20]), 0, false).is_err());
    }

    #[test]
    fn heat_map_colors() {
        assert_eq!(heat_color(1), [0, 255, 0, 255]);
        assert_eq!(heat_color(128), [255, 0, 0, 255]);
        assert_eq!(heat_color(255), [255, 0, 0, 255]);
        // d = 8: t = 3/7, (109.29, 145.71) rounded.
        assert_eq!(heat_color(8), [109, 146, 0, 255]);
        // Equal pixels: 32 + floor(Y)/4; white: Y = 255 -> 32 + 63 = 95; mid grey 100 -> 57.
        let reference = grey(3, 1, &[255, 100, 0]);
        let mut tested = reference.clone();
        tested.set_pixel(2, 0, [0, 0, 2, 255]);
        let map = heat_map(&reference, &tested);
        assert_eq!(map.pixel(0, 0), [95, 95, 95, 255]);
        assert_eq!(map.pixel(1, 0), [57, 57, 57, 255]);
        assert_eq!(map.pixel(2, 0), heat_color(2));
        assert_eq!(heat_color(2), [36, 219, 0, 255]);
    }
}
