//! The images C tests save (`capi_save_image` in capi-tests/common.c), their comparison
//! and PNG renderings of a failed comparison.
//!
//! File format: a text header `TESSIMG <width> <height> <channels> <u8|u16|f32>\n`, then
//! `width × height × channels` samples in native byte order, rows bottom-up (as glReadPixels
//! returns them). Errors are measured in the sample's own units: LSBs for u8 and u16,
//! absolute value for f32; PSNR uses the peak 255, 65535 or 1.0.
use super::manifest::Thresholds;
use std::path::Path;

/// The sample type of an image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sample {
    U8,
    U16,
    F32,
}

impl Sample {
    fn bytes(self) -> usize {
        match self {
            Sample::U8 => 1,
            Sample::U16 => 2,
            Sample::F32 => 4,
        }
    }

    /// The largest value of a normalized sample, for PSNR.
    pub fn peak(self) -> f64 {
        match self {
            Sample::U8 => 255.0,
            Sample::U16 => 65535.0,
            Sample::F32 => 1.0,
        }
    }
}

/// A decoded image; samples as f64 so every type compares the same way.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub channels: usize,
    pub sample: Sample,
    pub samples: Vec<f64>,
}

impl Image {
    /// Decodes a `.img` file's bytes.
    pub fn parse(bytes: &[u8]) -> Result<Image, String> {
        let newline = bytes.iter().position(|&b| b == b'\n').ok_or("no header line")?;
        let header = std::str::from_utf8(&bytes[..newline]).map_err(|_| "header is not text")?;
        let fields: Vec<&str> = header.split(' ').collect();
        let [magic, w, h, c, t] = fields[..] else {
            return Err(format!("bad header `{header}`"));
        };
        let number = |s: &str| s.parse::<usize>().map_err(|_| format!("bad number `{s}` in header `{header}`"));
        let (width, height, channels) = (number(w)?, number(h)?, number(c)?);
        let sample = match t {
            "u8" => Sample::U8,
            "u16" => Sample::U16,
            "f32" => Sample::F32,
            _ => return Err(format!("unknown sample type `{t}`")),
        };
        if magic != "TESSIMG" || !(1..=4).contains(&channels) {
            return Err(format!("bad header `{header}`"));
        }
        let data = &bytes[newline + 1..];
        let expected = width * height * channels * sample.bytes();
        if data.len() != expected {
            return Err(format!("{} data bytes, header `{header}` needs {expected}", data.len()));
        }
        let samples = match sample {
            Sample::U8 => data.iter().map(|&b| b as f64).collect(),
            Sample::U16 => data.chunks_exact(2).map(|c| u16::from_ne_bytes([c[0], c[1]]) as f64).collect(),
            Sample::F32 => data.chunks_exact(4).map(|c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]]) as f64).collect(),
        };
        Ok(Image { width, height, channels, sample, samples })
    }

    pub fn load(path: &Path) -> Result<Image, String> {
        let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
        Image::parse(&bytes).map_err(|e| format!("{}: {e}", path.display()))
    }

    fn describe(&self) -> String {
        format!("{}x{}x{} {:?}", self.width, self.height, self.channels, self.sample)
    }
}

/// The difference of two samples; NaN equals NaN, and NaN against a number is infinitely far.
fn sample_difference(a: f64, b: f64) -> f64 {
    if a == b || (a.is_nan() && b.is_nan()) {
        0.0
    } else {
        let d = (a - b).abs();
        if d.is_nan() {
            f64::INFINITY
        } else {
            d
        }
    }
}

/// How two images of the same shape differ.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// Largest difference of any channel.
    pub max_error: f64,
    /// Pixels with any channel differing by more than the tolerance.
    pub bad_pixels: u64,
    /// Pixels with any difference at all.
    pub differing_pixels: u64,
    /// Peak signal-to-noise ratio in dB; infinite for identical images.
    pub psnr: f64,
}

impl Comparison {
    pub fn passes(&self, limits: &Thresholds) -> bool {
        self.max_error <= limits.max_error
            && self.bad_pixels <= limits.bad_pixels
            && limits.min_psnr.is_none_or(|min| self.psnr >= min)
    }
}

/// Compares `a` with `b`; `tolerance` decides which pixels count as bad.
pub fn compare(a: &Image, b: &Image, tolerance: f64) -> Result<Comparison, String> {
    if (a.width, a.height, a.channels, a.sample) != (b.width, b.height, b.channels, b.sample) {
        return Err(format!("shapes differ: {} vs {}", a.describe(), b.describe()));
    }
    let mut max_error = 0.0f64;
    let (mut bad_pixels, mut differing_pixels) = (0u64, 0u64);
    let mut squares = 0.0f64;
    for (pa, pb) in a.samples.chunks_exact(a.channels).zip(b.samples.chunks_exact(b.channels)) {
        let worst = pa.iter().zip(pb).map(|(&x, &y)| sample_difference(x, y)).fold(0.0, f64::max);
        squares += pa.iter().zip(pb).map(|(&x, &y)| sample_difference(x, y).powi(2)).sum::<f64>();
        max_error = max_error.max(worst);
        differing_pixels += (worst > 0.0) as u64;
        bad_pixels += (worst > tolerance) as u64;
    }
    let mse = squares / a.samples.len().max(1) as f64;
    let psnr = if mse == 0.0 { f64::INFINITY } else { 10.0 * (a.sample.peak().powi(2) / mse).log10() };
    Ok(Comparison { max_error, bad_pixels, differing_pixels, psnr })
}

/// Writes `image` as a PNG (top row first): 8-bit for u8, 16-bit for u16 and for f32
/// (clamped to [0, 1]).
pub fn write_png(image: &Image, path: &Path) -> Result<(), String> {
    let color = match image.channels {
        1 => png::ColorType::Grayscale,
        2 => png::ColorType::GrayscaleAlpha,
        3 => png::ColorType::Rgb,
        _ => png::ColorType::Rgba,
    };
    let row = image.width * image.channels;
    let mut data = Vec::with_capacity(image.samples.len() * 2);
    for y in (0..image.height).rev() {
        for &s in &image.samples[y * row..(y + 1) * row] {
            match image.sample {
                Sample::U8 => data.push(s as u8),
                Sample::U16 => data.extend_from_slice(&(s as u16).to_be_bytes()),
                Sample::F32 => data.extend_from_slice(&((s.clamp(0.0, 1.0) * 65535.0).round() as u16).to_be_bytes()),
            }
        }
    }
    let depth = if image.sample == Sample::U8 { png::BitDepth::Eight } else { png::BitDepth::Sixteen };
    encode(path, image.width, image.height, color, depth, &data)
}

/// Writes a heat map of where `a` and `b` differ: equal pixels as a dim gray copy of `a`,
/// differing ones from green (a small difference, still clearly visible) to red (a
/// difference of the full range).
pub fn write_heat_map(a: &Image, b: &Image, path: &Path) -> Result<(), String> {
    if (a.width, a.height, a.channels) != (b.width, b.height, b.channels) {
        return Err("shapes differ; no heat map".into());
    }
    let peak = a.sample.peak();
    let mut data = Vec::with_capacity(a.width * a.height * 3);
    for y in (0..a.height).rev() {
        for x in 0..a.width {
            let i = (y * a.width + x) * a.channels;
            let (pa, pb) = (&a.samples[i..i + a.channels], &b.samples[i..i + b.channels]);
            let worst = pa.iter().zip(pb).map(|(&p, &q)| sample_difference(p, q)).fold(0.0, f64::max);
            if worst == 0.0 {
                let colour = &pa[..a.channels.min(3)];
                let mean = colour.iter().sum::<f64>() / colour.len() as f64;
                let gray = (mean / peak).clamp(0.0, 1.0) * 64.0;
                data.extend_from_slice(&[gray as u8; 3]);
            } else {
                // sqrt spreads small differences (a few LSB) over a visible part of the ramp.
                let t = (worst / peak).min(1.0).sqrt();
                data.extend_from_slice(&[
                    (255.0 * (2.0 * t).min(1.0)) as u8,
                    (255.0 * (2.0 * (1.0 - t)).min(1.0)) as u8,
                    0,
                ]);
            }
        }
    }
    encode(path, a.width, a.height, png::ColorType::Rgb, png::BitDepth::Eight, &data)
}

fn encode(
    path: &Path,
    w: usize,
    h: usize,
    color: png::ColorType,
    depth: png::BitDepth,
    data: &[u8],
) -> Result<(), String> {
    let file = std::fs::File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), w as u32, h as u32);
    encoder.set_color(color);
    encoder.set_depth(depth);
    let mut writer = encoder.write_header().map_err(|e| format!("{}: {e}", path.display()))?;
    writer.write_image_data(data).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(header: &str, data: &[u8]) -> Vec<u8> {
        let mut bytes = header.as_bytes().to_vec();
        bytes.extend_from_slice(data);
        bytes
    }

    #[test]
    fn parses_every_sample_type() {
        let img = Image::parse(&file("TESSIMG 2 1 1 u8\n", &[3, 250])).unwrap();
        assert_eq!(img.samples, [3.0, 250.0]);
        let mut data = Vec::new();
        data.extend_from_slice(&513u16.to_ne_bytes());
        let img = Image::parse(&file("TESSIMG 1 1 1 u16\n", &data)).unwrap();
        assert_eq!((img.sample, img.samples[0]), (Sample::U16, 513.0));
        let img = Image::parse(&file("TESSIMG 1 1 1 f32\n", &0.25f32.to_ne_bytes())).unwrap();
        assert_eq!((img.sample, img.samples[0]), (Sample::F32, 0.25));
    }

    #[test]
    fn rejects_malformed_files() {
        assert!(Image::parse(b"TESSIMG 2 1 1 u8\n\x01").unwrap_err().contains("needs 2"));
        assert!(Image::parse(b"TESSIMG 1 1 5 u8\n\x01\x01\x01\x01\x01").is_err());
        assert!(Image::parse(b"TESSIMG 1 1 1 u12\n\x01").unwrap_err().contains("unknown sample"));
        assert!(Image::parse(b"PNG 1 1 1 u8\n\x01").is_err());
        assert!(Image::parse(b"TESSIMG 1 1 1 u8").is_err());
    }

    fn rgba(samples: &[f64]) -> Image {
        Image { width: samples.len() / 4, height: 1, channels: 4, sample: Sample::U8, samples: samples.to_vec() }
    }

    #[test]
    fn compares_with_exact_numbers() {
        let a = rgba(&[10.0, 20.0, 30.0, 255.0, 0.0, 0.0, 0.0, 0.0]);
        let b = rgba(&[12.0, 20.0, 30.0, 255.0, 0.0, 0.0, 0.0, 1.0]);
        let c = compare(&a, &b, 1.0).unwrap();
        assert_eq!((c.max_error, c.bad_pixels, c.differing_pixels), (2.0, 1, 2));
        // MSE = (4 + 1) / 8; PSNR = 10 log10(255² / 0.625)
        assert!((c.psnr - 10.0 * (65025.0f64 / 0.625).log10()).abs() < 1e-9);
        let same = compare(&a, &a, 0.0).unwrap();
        assert_eq!((same.max_error, same.bad_pixels, same.psnr), (0.0, 0, f64::INFINITY));
        assert!(same.passes(&Thresholds::default()));
        assert!(!c.passes(&Thresholds::default()));
        assert!(c.passes(&Thresholds { max_error: 2.0, tolerance: 1.0, bad_pixels: 1, min_psnr: Some(50.0) }));
        assert!(!c.passes(&Thresholds { max_error: 2.0, tolerance: 1.0, bad_pixels: 0, min_psnr: None }));
        assert!(!c.passes(&Thresholds { max_error: 2.0, tolerance: 2.0, bad_pixels: 0, min_psnr: Some(60.0) }));
    }

    #[test]
    fn nan_equals_nan_and_differs_from_numbers() {
        let f = |v: f64| Image { width: 1, height: 1, channels: 1, sample: Sample::F32, samples: vec![v] };
        assert_eq!(compare(&f(f64::NAN), &f(f64::NAN), 0.0).unwrap().max_error, 0.0);
        assert_eq!(compare(&f(f64::NAN), &f(0.5), 0.0).unwrap().max_error, f64::INFINITY);
        assert_eq!(compare(&f(f64::INFINITY), &f(f64::INFINITY), 0.0).unwrap().max_error, 0.0);
    }

    #[test]
    fn shape_mismatch_is_an_error() {
        let a = rgba(&[0.0; 8]);
        let b = rgba(&[0.0; 4]);
        assert!(compare(&a, &b, 0.0).unwrap_err().contains("shapes differ"));
    }

    #[test]
    fn writes_readable_pngs() {
        let dir = std::env::temp_dir().join(format!("capi-png-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        // 1x2 image, bottom row red, top row blue: the PNG's first row must be blue.
        let img = Image {
            width: 1,
            height: 2,
            channels: 3,
            sample: Sample::U8,
            samples: vec![255.0, 0.0, 0.0, 0.0, 0.0, 255.0],
        };
        let path = dir.join("a.png");
        write_png(&img, &path).unwrap();
        let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&path).unwrap()));
        let mut reader = decoder.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        reader.next_frame(&mut buf).unwrap();
        assert_eq!(&buf[..6], &[0, 0, 255, 255, 0, 0]);
        write_heat_map(&img, &img, &dir.join("d.png")).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
