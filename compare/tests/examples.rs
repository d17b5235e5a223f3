//! CI for the examples and for tessera-compare itself: runs the tool on every
//! `examples-c/*.c` against Mesa llvmpipe and tessera with `examples-c/manifest.txt`, checks
//! that everything passes, that the reported numbers equal an independent computation on
//! two pictures, that the HTML report's pictures all load in headless Chromium, and that the
//! tool fails when a threshold is exceeded.
//!
//! Without gcc, Mesa's libOSMesa.so.8, tessera's built library or chromium the checks that
//! need them print SKIPPED, except under `CI=true`, where that is a failure.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("workspace root").to_path_buf()
}

fn tessera_dir() -> PathBuf {
    std::env::var_os("TESSERA_LIB_DIR").map_or_else(|| repo_root().join("target/release"), PathBuf::from)
}

/// Whether the prerequisites are there; if not, panics under CI=true, else says SKIPPED.
fn prerequisites(what: &str, needs_chromium: bool) -> bool {
    let mut missing = Vec::new();
    if Command::new("gcc").arg("--version").output().is_err() {
        missing.push("gcc".to_string());
    }
    let ldconfig = Command::new("/sbin/ldconfig").arg("-p").output().map(|o| o.stdout).unwrap_or_default();
    if !String::from_utf8_lossy(&ldconfig).contains("libOSMesa.so.8") {
        missing.push("Mesa's libOSMesa.so.8 (libosmesa6-dev)".to_string());
    }
    if !tessera_dir().join("libOSMesa.so.8").is_file() {
        missing.push(format!("{}/libOSMesa.so.8 (cargo build --release)", tessera_dir().display()));
    }
    if needs_chromium && Command::new("chromium").arg("--version").output().is_err() {
        missing.push("chromium".to_string());
    }
    if missing.is_empty() {
        return true;
    }
    let message = format!("{what}: missing {}", missing.join(", "));
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("{message} (CI=true: a missing prerequisite is a failure)");
    }
    eprintln!("SKIPPED {message}");
    false
}

/// Runs tessera-compare in the repository root; returns its exit code and stderr.
fn tessera_compare(args: &[&str]) -> (i32, String) {
    let tessera = format!("tessera={}", tessera_dir().display());
    let output = Command::new(env!("CARGO_BIN_EXE_tessera-compare"))
        .current_dir(repo_root())
        .args(["--impl", "llvmpipe", "--impl", &tessera])
        .args(args)
        .output()
        .expect("tessera-compare runs");
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    eprintln!("{stderr}");
    (output.status.code().unwrap_or(-1), stderr)
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).expect("JSON written")).expect("valid JSON")
}

/// An RGBA8 picture read with the png crate directly: (width, height, rows from the top).
fn read_rgba(path: &Path) -> (usize, usize, Vec<[u8; 4]>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).expect("PNG")));
    let mut reader = decoder.read_info().expect("PNG header");
    let mut buffer = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buffer).expect("PNG data");
    assert_eq!((info.color_type, info.bit_depth), (png::ColorType::Rgba, png::BitDepth::Eight));
    let pixels = buffer[..info.buffer_size()].chunks_exact(4).map(|p| [p[0], p[1], p[2], p[3]]).collect();
    (info.width as usize, info.height as usize, pixels)
}

/// The README's definitions, computed the slow, direct way.
struct Expected {
    max_error: u8,
    bad_pixels: usize,
    psnr: f64,
    ssim: f64,
}

fn expected_numbers(reference: &Path, tested: &Path, tolerance: u8, shift: bool) -> Expected {
    let (w, h, a) = read_rgba(reference);
    let (w2, h2, b) = read_rgba(tested);
    assert_eq!((w, h), (w2, h2));
    let radius: i64 = if shift { 1 } else { 0 };
    let (mut max_error, mut bad_pixels, mut squares) = (0u8, 0usize, 0f64);
    for y in 0..h as i64 {
        for x in 0..w as i64 {
            let t = b[(y * w as i64 + x) as usize];
            let mut best = 255u8;
            for dy in -radius..=radius {
                for dx in -radius..=radius {
                    let (rx, ry) = (x + dx, y + dy);
                    if rx >= 0 && ry >= 0 && rx < w as i64 && ry < h as i64 {
                        let r = a[(ry * w as i64 + rx) as usize];
                        best = best.min(
                            (0..4).map(|c| (i32::from(t[c]) - i32::from(r[c])).unsigned_abs() as u8).max().unwrap(),
                        );
                    }
                }
            }
            max_error = max_error.max(best);
            bad_pixels += usize::from(best > tolerance);
            let r = a[(y * w as i64 + x) as usize];
            squares += (0..3).map(|c| (f64::from(t[c]) - f64::from(r[c])).powi(2)).sum::<f64>();
        }
    }
    let mse = squares / (w * h * 3) as f64;
    let psnr = if mse == 0.0 { f64::INFINITY } else { 10.0 * (255.0 * 255.0 / mse).log10() };
    // SSIM with direct 2D windows (11x11 gaussian, sigma 1.5, truncated and renormalised).
    let luma = |p: [u8; 4]| 0.299 * f64::from(p[0]) + 0.587 * f64::from(p[1]) + 0.114 * f64::from(p[2]);
    let (ya, yb): (Vec<f64>, Vec<f64>) = (a.iter().map(|&p| luma(p)).collect(), b.iter().map(|&p| luma(p)).collect());
    let (c1, c2) = ((0.01f64 * 255.0).powi(2), (0.03f64 * 255.0).powi(2));
    let mut total = 0.0;
    for y in 0..h as i64 {
        for x in 0..w as i64 {
            let (mut sw, mut sa, mut sb, mut saa, mut sbb, mut sab) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
            for dy in -5i64..=5 {
                for dx in -5i64..=5 {
                    let (sx, sy) = (x + dx, y + dy);
                    if sx < 0 || sy < 0 || sx >= w as i64 || sy >= h as i64 {
                        continue;
                    }
                    let weight = (-((dx * dx + dy * dy) as f64) / (2.0 * 1.5 * 1.5)).exp();
                    let (va, vb) = (ya[(sy * w as i64 + sx) as usize], yb[(sy * w as i64 + sx) as usize]);
                    sw += weight;
                    sa += weight * va;
                    sb += weight * vb;
                    saa += weight * va * va;
                    sbb += weight * vb * vb;
                    sab += weight * va * vb;
                }
            }
            let (mx, my) = (sa / sw, sb / sw);
            let (vx, vy, cov) = (saa / sw - mx * mx, sbb / sw - my * my, sab / sw - mx * my);
            total += (2.0 * mx * my + c1) * (2.0 * cov + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
        }
    }
    Expected { max_error, bad_pixels, psnr, ssim: total / (w * h) as f64 }
}

fn find<'a>(list: &'a Value, name: &str) -> &'a Value {
    list.as_array().unwrap().iter().find(|v| v["name"] == name).unwrap_or_else(|| panic!("{name} in the report"))
}

#[test]
fn examples_match_mesa_and_the_report_is_right() {
    if !prerequisites("tessera-compare examples", false) {
        return;
    }
    let work = repo_root().join("target/tessera-compare-test/examples");
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).unwrap();
    let (json_path, html_dir) = (work.join("report.json"), work.join("html"));
    let (status, stderr) = tessera_compare(&[
        "--manifest",
        "examples-c/manifest.txt",
        "--work",
        work.to_str().unwrap(),
        "--json",
        json_path.to_str().unwrap(),
        "--html",
        html_dir.to_str().unwrap(),
        "examples-c",
    ]);
    assert!(stderr.contains("[1/"), "progress lines on stderr");
    let report = read_json(&json_path);
    let failed: Vec<&Value> = report["programs"].as_array().unwrap().iter().filter(|p| p["passed"] != true).collect();
    assert!(failed.is_empty(), "examples over their thresholds: {failed:#?}");
    assert_eq!(status, 0);
    assert_eq!(report["passed"], true);

    // Every example ran on both, wrote pictures, and each picture was compared.
    let sources = std::fs::read_dir(repo_root().join("examples-c"))
        .unwrap()
        .filter(|e| e.as_ref().unwrap().path().extension().is_some_and(|x| x == "c"))
        .count();
    let programs = report["programs"].as_array().unwrap();
    assert_eq!(programs.len(), sources);
    for program in programs {
        assert_eq!(program["runs"].as_array().unwrap().len(), 2);
        let renderers: Vec<&str> =
            program["runs"].as_array().unwrap().iter().map(|r| r["renderer"].as_str().unwrap()).collect();
        assert!(renderers[0].contains("llvmpipe") && renderers[1].contains("tessera"), "{renderers:?}");
        let images = program["images"].as_array().unwrap();
        assert!(!images.is_empty(), "{} wrote pictures", program["name"]);
        for image in images {
            assert_eq!(image["comparisons"].as_array().unwrap().len(), 1, "{}", image["name"]);
        }
    }
    // The dithered picture is checked on tessera against the exact ordered-dither expectation.
    let dither = find(&find(&report["programs"], "dither_565")["images"], "dither_565_dithered");
    let check = &dither["comparisons"][0];
    assert_eq!(
        (check["tested"].as_str(), check["reference"].as_str()),
        (Some("tessera"), Some("image dither_565_expected"))
    );
    assert_eq!(check["max_error"], 0);

    // The reported numbers against an independent computation, on a picture with 1-LSB
    // differences (no shift) and one compared with the shift allowance.
    for (program, image) in [("translucent_house", "translucent_house"), ("fog_distance", "fog_distance")] {
        let entry = find(&find(&report["programs"], program)["images"], image);
        let c = &entry["comparisons"][0];
        let shift = c["thresholds"]["shift"].as_bool().unwrap();
        let tolerance = c["thresholds"]["tolerance"].as_u64().unwrap() as u8;
        let expected = expected_numbers(
            Path::new(entry["files"]["llvmpipe"].as_str().unwrap()),
            Path::new(entry["files"]["tessera"].as_str().unwrap()),
            tolerance,
            shift,
        );
        assert_eq!(c["max_error"].as_u64().unwrap(), u64::from(expected.max_error), "{image} max error");
        assert_eq!(c["bad_pixels"].as_u64().unwrap(), expected.bad_pixels as u64, "{image} bad pixels");
        assert!(expected.psnr.is_finite(), "{image} has differences to measure");
        assert!(
            (c["psnr"].as_f64().unwrap() - expected.psnr).abs() < 1e-3,
            "{image} PSNR {} vs {}",
            c["psnr"],
            expected.psnr
        );
        assert!(
            (c["ssim"].as_f64().unwrap() - expected.ssim).abs() < 2e-6,
            "{image} SSIM {} vs {}",
            c["ssim"],
            expected.ssim
        );
        assert!(expected.ssim < 1.0);
    }

    browser_check(&html_dir);
}

/// Headless Chromium opens the HTML report: its script must find every picture loaded; with
/// one picture removed it must report it.
fn browser_check(html_dir: &Path) {
    if !prerequisites("HTML report in chromium", true) {
        return;
    }
    let html = std::fs::read_to_string(html_dir.join("index.html")).unwrap();
    let images = html.matches("<img ").count();
    assert!(images > 40, "the report shows the pictures ({images})");
    let dump = |what: &str| -> String {
        let profile = html_dir.parent().unwrap().join(format!("chromium-profile-{what}"));
        let _ = std::fs::remove_dir_all(&profile);
        let output = Command::new("chromium")
            .args(["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking"])
            .args(["--disable-component-update", "--disable-sync", "--no-first-run"])
            .arg(format!("--user-data-dir={}", profile.display()))
            .args(["--virtual-time-budget=5000", "--dump-dom"])
            .arg(format!("file://{}", html_dir.join("index.html").canonicalize().unwrap().display()))
            .output()
            .expect("chromium runs");
        String::from_utf8_lossy(&output.stdout).into_owned()
    };
    let dom = dump("all");
    assert!(dom.contains("data-images=\"loaded\""), "every picture loads");
    assert!(dom.contains(&format!("images-loaded: all {images}")), "the script counted {images} pictures");

    // The check can fail: remove one picture.
    let first = html.split("<img src=\"").nth(1).unwrap().split('"').next().unwrap();
    std::fs::remove_file(html_dir.join(first)).unwrap();
    let dom = dump("broken");
    assert!(dom.contains("data-images=\"failed\""), "a missing picture is noticed");
    assert!(dom.contains(&format!("images-failed: 1 of {images}")));
}

#[test]
fn exceeded_thresholds_fail() {
    if !prerequisites("tessera-compare strict manifest", false) {
        return;
    }
    let work = repo_root().join("target/tessera-compare-test/strict");
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).unwrap();
    // translucent_house differs by 1 LSB and may not; tessera's dithered picture is not
    // the truncated one.
    let manifest = work.join("manifest.txt");
    std::fs::write(
        &manifest,
        "translucent_house max_error=0\ndither_565/dither_565_dithered against=dither_565_truncated only=tessera\n",
    )
    .unwrap();
    let json = work.join("report.json");
    let (status, stderr) = tessera_compare(&[
        "--manifest",
        manifest.to_str().unwrap(),
        "--work",
        work.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
        "examples-c/translucent_house.c",
        "examples-c/dither_565.c",
    ]);
    assert_eq!(status, 1, "a threshold exceeded is exit status 1");
    assert!(stderr.contains("0 passed, 2 failed"));
    let report = read_json(&json);
    assert_eq!(report["passed"], false);
    let house = find(&report["programs"], "translucent_house");
    assert!(house["failures"][0].as_str().unwrap().contains("max error 1 > 0"), "{house}");
    let dither = find(&report["programs"], "dither_565");
    assert!(dither["failures"][0]
        .as_str()
        .unwrap()
        .contains("dither_565_dithered on tessera against image dither_565_truncated"));
    // Bad usage is exit status 2.
    assert_eq!(tessera_compare(&["--bogus"]).0, 2);
}
