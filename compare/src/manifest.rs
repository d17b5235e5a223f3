//! The manifest: per-program and per-image thresholds, one line each.
//!
//! ```text
//! # comment
//! <program>[/<image>] key=value ...   # comment
//! ```
//!
//! `<program>` is the C file's stem (`fog_modes`), `<image>` a PNG's stem without `.png`. A
//! program line applies to all its images; an image line overrides it key by key. Keys:
//! `max_error=N` (largest pixel error, default 0), `tolerance=T` (a pixel is bad when its
//! error is above T; default: max_error), `bad_pixels=N` (bad pixels allowed, default 0),
//! `min_psnr=DB`, `min_ssim=S` (not checked unless given), `shift=1` (errors allow a
//! 1-pixel shift), `against=<image>` (compare with that image of the same run instead of the
//! reference implementation's), `only=<impl>[,<impl>...]` (check this image only on these
//! implementations; on the others it is shown but not compared).

/// The thresholds one image is checked with.
#[derive(Clone, Debug, PartialEq)]
pub struct Thresholds {
    pub max_error: u8,
    pub tolerance: Option<u8>,
    pub bad_pixels: usize,
    pub min_psnr: Option<f64>,
    pub min_ssim: Option<f64>,
    pub shift: bool,
    pub against: Option<String>,
    pub only: Option<Vec<String>>,
}

impl Thresholds {
    /// Exact comparison; `shift` from the command line.
    pub fn exact(shift: bool) -> Thresholds {
        Thresholds {
            max_error: 0,
            tolerance: None,
            bad_pixels: 0,
            min_psnr: None,
            min_ssim: None,
            shift,
            against: None,
            only: None,
        }
    }

    pub fn tolerance(&self) -> u8 {
        self.tolerance.unwrap_or(self.max_error)
    }

    /// Whether the image is compared on implementation `name`.
    pub fn applies_to(&self, name: &str) -> bool {
        self.only.as_ref().is_none_or(|names| names.iter().any(|n| n == name))
    }

    /// The thresholds `metrics` exceeds, as readable reasons (empty: passed).
    pub fn failures(&self, metrics: &crate::metrics::Metrics) -> Vec<String> {
        let mut failures = Vec::new();
        if metrics.max_error > self.max_error {
            failures.push(format!("max error {} > {}", metrics.max_error, self.max_error));
        }
        if metrics.bad_pixels > self.bad_pixels {
            failures.push(format!(
                "{} pixels over tolerance {} > {}",
                metrics.bad_pixels,
                self.tolerance(),
                self.bad_pixels
            ));
        }
        if let Some(min) = self.min_psnr {
            if metrics.psnr < min {
                failures.push(format!("PSNR {:.2} dB < {min}", metrics.psnr));
            }
        }
        if let Some(min) = self.min_ssim {
            if metrics.ssim < min {
                failures.push(format!("SSIM {:.5} < {min}", metrics.ssim));
            }
        }
        failures
    }

    fn set(&mut self, key: &str, value: &str) -> Result<(), String> {
        let number = |v: &str| v.parse::<f64>().map_err(|_| format!("{key}: not a number: {v}"));
        let count = |v: &str| v.parse::<usize>().map_err(|_| format!("{key}: not a count: {v}"));
        let level = |v: &str| v.parse::<u8>().map_err(|_| format!("{key}: not 0..255: {v}"));
        match key {
            "max_error" => self.max_error = level(value)?,
            "tolerance" => self.tolerance = Some(level(value)?),
            "bad_pixels" => self.bad_pixels = count(value)?,
            "min_psnr" => self.min_psnr = Some(number(value)?),
            "min_ssim" => self.min_ssim = Some(number(value)?),
            "shift" => self.shift = matches!(value, "1" | "true" | "yes"),
            "against" => self.against = Some(value.to_string()),
            "only" => self.only = Some(value.split(',').map(str::to_string).collect()),
            _ => return Err(format!("unknown key {key}")),
        }
        Ok(())
    }
}

/// A parsed manifest.
#[derive(Clone, Debug, Default)]
pub struct Manifest {
    entries: Vec<(String, Vec<(String, String)>)>,
}

impl Manifest {
    /// Parses the manifest text; every key is checked.
    pub fn parse(text: &str) -> Result<Manifest, String> {
        let mut entries = Vec::new();
        for (number, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            let mut words = line.split_whitespace();
            let Some(selector) = words.next() else { continue };
            let mut pairs = Vec::new();
            for word in words {
                let (key, value) =
                    word.split_once('=').ok_or_else(|| format!("line {}: expected key=value: {word}", number + 1))?;
                Thresholds::exact(false).set(key, value).map_err(|e| format!("line {}: {e}", number + 1))?;
                pairs.push((key.to_string(), value.to_string()));
            }
            entries.push((selector.to_string(), pairs));
        }
        Ok(Manifest { entries })
    }

    /// The thresholds of `program`'s image `image`.
    pub fn thresholds(&self, program: &str, image: &str, shift: bool) -> Thresholds {
        let mut thresholds = Thresholds::exact(shift);
        let image_selector = format!("{program}/{image}");
        for selector in [program, image_selector.as_str()] {
            for (entry, pairs) in &self.entries {
                if entry == selector {
                    for (key, value) in pairs {
                        thresholds.set(key, value).expect("checked by parse");
                    }
                }
            }
        }
        thresholds
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn image_lines_override_program_lines() {
        let m = Manifest::parse(
            "# header\nfog max_error=1 shift=1   # why\nfog/b max_error=3 bad_pixels=2\n\
             dither/d against=e only=tessera,x\n",
        )
        .unwrap();
        let a = m.thresholds("fog", "a", false);
        assert_eq!((a.max_error, a.tolerance(), a.bad_pixels, a.shift), (1, 1, 0, true));
        let b = m.thresholds("fog", "b", false);
        assert_eq!((b.max_error, b.bad_pixels, b.shift), (3, 2, true));
        let d = m.thresholds("dither", "d", false);
        assert_eq!(d.against.as_deref(), Some("e"));
        assert!(d.applies_to("x") && !d.applies_to("llvmpipe"));
        assert_eq!(m.thresholds("other", "a", false), Thresholds::exact(false));
        assert!(Manifest::parse("x max_eror=1").is_err());
        assert!(Manifest::parse("x max_error=300").is_err());
        assert!(Manifest::parse("x max_error").is_err());
    }
}
