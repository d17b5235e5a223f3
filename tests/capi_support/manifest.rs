//! `capi-tests/manifest.txt`: what a test may differ in between Mesa and tessera.
//!
//! The file documents its own format in its header. In short, each line is a selector
//! (`test` or `test/image`) followed by `key=value` settings:
//! `max_error`, `tolerance`, `bad_pixels`, `min_psnr` for images and `values` (a comma list
//! of VALUE keys) for a test. Without a line, everything must be exact.
use std::collections::BTreeMap;

/// The limits one image comparison must respect.
#[derive(Clone, Debug, PartialEq)]
pub struct Thresholds {
    /// Largest allowed difference of any channel of any pixel.
    pub max_error: f64,
    /// A pixel is "bad" when any channel differs by more than this.
    pub tolerance: f64,
    /// How many bad pixels are allowed.
    pub bad_pixels: u64,
    /// Lowest allowed PSNR in dB (`None`: not checked).
    pub min_psnr: Option<f64>,
}

impl Default for Thresholds {
    /// Exact: no difference at all.
    fn default() -> Self {
        Thresholds { max_error: 0.0, tolerance: 0.0, bad_pixels: 0, min_psnr: None }
    }
}

/// The settings of one manifest line; unset fields inherit.
#[derive(Clone, Debug, Default, PartialEq)]
struct Entry {
    max_error: Option<f64>,
    tolerance: Option<f64>,
    bad_pixels: Option<u64>,
    min_psnr: Option<f64>,
    values: Vec<String>,
}

/// The parsed manifest.
#[derive(Clone, Debug, Default)]
pub struct Manifest {
    entries: BTreeMap<String, Entry>,
}

impl Manifest {
    /// Reads the manifest; a missing file is an empty manifest.
    pub fn load(path: &std::path::Path) -> Result<Manifest, String> {
        match std::fs::read_to_string(path) {
            Ok(text) => Manifest::parse(&text).map_err(|e| format!("{}: {e}", path.display())),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Manifest::default()),
            Err(e) => Err(format!("{}: {e}", path.display())),
        }
    }

    /// Parses manifest text. Unknown keys, bad numbers and repeated selectors are errors,
    /// so a typo cannot silently loosen (or fail to loosen) a comparison.
    pub fn parse(text: &str) -> Result<Manifest, String> {
        let mut entries = BTreeMap::new();
        for (number, raw) in text.lines().enumerate() {
            let line = raw.split('#').next().unwrap_or("").trim();
            if line.is_empty() {
                continue;
            }
            let at = |msg: String| format!("line {}: {msg}", number + 1);
            let mut words = line.split_whitespace();
            let selector = words.next().unwrap_or_default().to_string();
            if selector.contains('=') || selector.split('/').count() > 2 || selector.split('/').any(str::is_empty) {
                return Err(at(format!("`{selector}` is not a selector (test or test/image)")));
            }
            let mut entry = Entry::default();
            for setting in words {
                let (key, value) =
                    setting.split_once('=').ok_or_else(|| at(format!("`{setting}` is not key=value")))?;
                let number = || {
                    value
                        .parse::<f64>()
                        .ok()
                        .filter(|v| !v.is_nan())
                        .ok_or_else(|| at(format!("bad number in `{setting}`")))
                };
                match key {
                    "max_error" => entry.max_error = Some(number()?),
                    "tolerance" => entry.tolerance = Some(number()?),
                    "min_psnr" => entry.min_psnr = Some(number()?),
                    "bad_pixels" => {
                        entry.bad_pixels = Some(value.parse().map_err(|_| at(format!("bad count in `{setting}`")))?)
                    }
                    "values" if !selector.contains('/') => {
                        entry.values.extend(value.split(',').filter(|k| !k.is_empty()).map(String::from))
                    }
                    "values" => return Err(at("`values=` belongs on a test line, not an image line".into())),
                    _ => return Err(at(format!("unknown setting `{key}`"))),
                }
            }
            if entries.insert(selector.clone(), entry).is_some() {
                return Err(at(format!("`{selector}` appears twice")));
            }
        }
        Ok(Manifest { entries })
    }

    /// The limits for `image` of `test`: the test's line, then the image's line, override
    /// the exact default. `tolerance` defaults to `max_error`.
    pub fn thresholds(&self, test: &str, image: &str) -> Thresholds {
        let mut merged = Entry::default();
        for selector in [test.to_string(), format!("{test}/{image}")] {
            if let Some(e) = self.entries.get(&selector) {
                merged.max_error = e.max_error.or(merged.max_error);
                merged.tolerance = e.tolerance.or(merged.tolerance);
                merged.bad_pixels = e.bad_pixels.or(merged.bad_pixels);
                merged.min_psnr = e.min_psnr.or(merged.min_psnr);
            }
        }
        let max_error = merged.max_error.unwrap_or(0.0);
        Thresholds {
            max_error,
            tolerance: merged.tolerance.unwrap_or(max_error),
            bad_pixels: merged.bad_pixels.unwrap_or(0),
            min_psnr: merged.min_psnr,
        }
    }

    /// The VALUE keys of `test` that may differ between Mesa and tessera.
    pub fn free_values(&self, test: &str) -> &[String] {
        self.entries.get(test).map_or(&[], |e| e.values.as_slice())
    }

    /// The tests the manifest names (to warn about entries for tests that do not exist).
    pub fn tests(&self) -> impl Iterator<Item = &str> {
        self.entries.keys().map(|s| s.split('/').next().unwrap_or(s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_is_exact() {
        let m = Manifest::parse("# nothing\n\n").unwrap();
        assert_eq!(m.thresholds("t", "i"), Thresholds::default());
        assert!(m.free_values("t").is_empty());
    }

    #[test]
    fn image_line_overrides_test_line_and_tolerance_follows_max_error() {
        let m = Manifest::parse(
            "lines max_error=2 values=a,b   # comment\nlines/wide tolerance=1 bad_pixels=7 min_psnr=40.5\n",
        )
        .unwrap();
        assert_eq!(
            m.thresholds("lines", "thin"),
            Thresholds { max_error: 2.0, tolerance: 2.0, bad_pixels: 0, min_psnr: None }
        );
        assert_eq!(
            m.thresholds("lines", "wide"),
            Thresholds { max_error: 2.0, tolerance: 1.0, bad_pixels: 7, min_psnr: Some(40.5) }
        );
        assert_eq!(m.free_values("lines"), ["a".to_string(), "b".to_string()]);
        assert_eq!(m.tests().collect::<Vec<_>>(), ["lines", "lines"]);
    }

    #[test]
    fn mistakes_are_errors() {
        assert!(Manifest::parse("t max_eror=1").unwrap_err().contains("unknown setting"));
        assert!(Manifest::parse("t max_error=x").unwrap_err().contains("bad number"));
        assert!(Manifest::parse("t bad_pixels=-1").unwrap_err().contains("bad count"));
        assert!(Manifest::parse("t max_error").unwrap_err().contains("key=value"));
        assert!(Manifest::parse("t/i values=k").unwrap_err().contains("test line"));
        assert!(Manifest::parse("t\nt").unwrap_err().contains("twice"));
        assert!(Manifest::parse("a/b/c").unwrap_err().contains("selector"));
        assert!(Manifest::parse("t max_error=NaN").unwrap_err().contains("bad number"));
    }
}
