//! The results and their two renderings: JSON for CI and an HTML directory for people
//! (`index.html` with every implementation's picture side by side, a difference heat map
//! per comparison and the numbers; its script marks the page once every picture loaded).

use crate::image::{read_png, write_png};
use crate::implementation::Implementation;
use crate::manifest::Thresholds;
use crate::metrics::{heat_map, Metrics};
use crate::runner::Run;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

/// One image of one implementation checked against a reference picture.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// The implementation whose picture is checked.
    pub tested: String,
    /// What it is checked against: an implementation's name, or `image <name>` (same run).
    pub reference: String,
    pub reference_file: Option<PathBuf>,
    pub tested_file: Option<PathBuf>,
    pub thresholds: Thresholds,
    /// The numbers, or why there are none (a missing picture, a size mismatch).
    pub metrics: Result<Metrics, String>,
    /// Which thresholds were exceeded; empty when it passed.
    pub failures: Vec<String>,
}

/// One picture name of a program: each implementation's file and the comparisons.
#[derive(Clone, Debug)]
pub struct ImageReport {
    pub name: String,
    pub files: Vec<(String, Option<PathBuf>)>,
    pub comparisons: Vec<Comparison>,
}

/// One program: its build, its runs and its pictures.
#[derive(Clone, Debug)]
pub struct ProgramReport {
    pub name: String,
    pub path: PathBuf,
    pub compile_error: Option<String>,
    pub runs: Vec<Run>,
    pub images: Vec<ImageReport>,
}

impl ProgramReport {
    /// Everything that makes this program fail.
    pub fn failures(&self) -> Vec<String> {
        let mut failures = Vec::new();
        if let Some(e) = &self.compile_error {
            failures.push(format!("does not compile: {}", e.lines().next().unwrap_or("")));
        }
        for run in &self.runs {
            if let Some(e) = &run.error {
                failures.push(format!("{}: {e}", run.implementation));
            }
        }
        if self.compile_error.is_none() && self.images.is_empty() {
            failures.push("wrote no PNG file".to_string());
        }
        for image in &self.images {
            for c in &image.comparisons {
                for f in &c.failures {
                    failures.push(format!("{} on {} against {}: {f}", image.name, c.tested, c.reference));
                }
            }
        }
        failures
    }
}

/// The whole comparison.
#[derive(Clone, Debug)]
pub struct Report {
    pub implementations: Vec<Implementation>,
    pub programs: Vec<ProgramReport>,
}

impl Report {
    pub fn passed(&self) -> bool {
        self.programs.iter().all(|p| p.failures().is_empty())
    }
}

fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn json_option<T: std::fmt::Display>(value: Option<T>) -> String {
    value.map_or("null".to_string(), |v| v.to_string())
}

fn json_path(path: &Option<PathBuf>) -> String {
    path.as_ref().map_or("null".to_string(), |p| json_string(&p.display().to_string()))
}

fn json_list(items: &[String]) -> String {
    format!("[{}]", items.join(", "))
}

/// The report as JSON (format in the README; PSNR of identical pictures is `null`).
pub fn to_json(report: &Report) -> String {
    let implementations: Vec<String> = report
        .implementations
        .iter()
        .map(|i| format!("{{\"name\": {}, \"how\": {}}}", json_string(&i.name), json_string(&i.describe())))
        .collect();
    let programs: Vec<String> = report.programs.iter().map(program_json).collect();
    format!(
        "{{\n\"passed\": {},\n\"reference\": {},\n\"implementations\": {},\n\"programs\": [\n{}\n]\n}}\n",
        report.passed(),
        json_string(report.implementations.first().map_or("", |i| i.name.as_str())),
        json_list(&implementations),
        programs.join(",\n")
    )
}

fn program_json(program: &ProgramReport) -> String {
    let runs: Vec<String> = program
        .runs
        .iter()
        .map(|r| {
            format!(
                "{{\"implementation\": {}, \"error\": {}, \"seconds\": {:.3}, \"renderer\": {}}}",
                json_string(&r.implementation),
                json_option(r.error.as_deref().map(json_string)),
                r.seconds,
                json_option(r.renderer.as_deref().map(json_string))
            )
        })
        .collect();
    let images: Vec<String> = program.images.iter().map(image_json).collect();
    let failures: Vec<String> = program.failures().iter().map(|f| json_string(f)).collect();
    format!(
        "{{\"name\": {}, \"passed\": {}, \"failures\": {}, \"compile_error\": {}, \"runs\": {},\n \"images\": [\n  {}\n ]}}",
        json_string(&program.name),
        failures.is_empty(),
        json_list(&failures),
        json_option(program.compile_error.as_deref().map(json_string)),
        json_list(&runs),
        images.join(",\n  ")
    )
}

fn image_json(image: &ImageReport) -> String {
    let files: Vec<String> =
        image.files.iter().map(|(name, path)| format!("{}: {}", json_string(name), json_path(path))).collect();
    let comparisons: Vec<String> = image.comparisons.iter().map(comparison_json).collect();
    format!(
        "{{\"name\": {}, \"files\": {{{}}}, \"comparisons\": [\n   {}]}}",
        json_string(&image.name),
        files.join(", "),
        comparisons.join(",\n   ")
    )
}

fn comparison_json(c: &Comparison) -> String {
    let t = &c.thresholds;
    let thresholds = format!(
        "{{\"max_error\": {}, \"tolerance\": {}, \"bad_pixels\": {}, \"min_psnr\": {}, \"min_ssim\": {}, \"shift\": {}}}",
        t.max_error,
        t.tolerance(),
        t.bad_pixels,
        json_option(t.min_psnr),
        json_option(t.min_ssim),
        t.shift
    );
    let numbers = match &c.metrics {
        Ok(m) => format!(
            "\"max_error\": {}, \"bad_pixels\": {}, \"psnr\": {}, \"ssim\": {:.6}, \"error\": null",
            m.max_error,
            m.bad_pixels,
            if m.psnr.is_finite() { format!("{:.4}", m.psnr) } else { "null".to_string() },
            m.ssim
        ),
        Err(e) => format!(
            "\"max_error\": null, \"bad_pixels\": null, \"psnr\": null, \"ssim\": null, \"error\": {}",
            json_string(e)
        ),
    };
    let failures: Vec<String> = c.failures.iter().map(|f| json_string(f)).collect();
    format!(
        "{{\"tested\": {}, \"reference\": {}, \"passed\": {}, \"failures\": {}, {}, \"thresholds\": {}}}",
        json_string(&c.tested),
        json_string(&c.reference),
        c.failures.is_empty(),
        json_list(&failures),
        numbers,
        thresholds
    )
}

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// Writes `dir/index.html` and the pictures it shows under `dir/img/`.
pub fn write_html(report: &Report, dir: &Path) -> Result<(), String> {
    let img_dir = dir.join("img");
    let _ = fs::remove_dir_all(&img_dir);
    fs::create_dir_all(&img_dir).map_err(|e| format!("{}: {e}", img_dir.display()))?;
    let mut html = String::new();
    let passed = report.programs.iter().filter(|p| p.failures().is_empty()).count();
    let _ = write!(
        html,
        "<!DOCTYPE html>\n<html data-images=\"pending\"><head><meta charset=\"utf-8\">\n\
         <title>tessera-compare report</title>\n<style>\n\
         body {{ font-family: sans-serif; background: #f4f4f4; margin: 1em; }}\n\
         section {{ background: white; padding: 0.5em 1em; margin-bottom: 1em; border-left: 6px solid #3a3; }}\n\
         section.fail {{ border-left-color: #c22; }}\n\
         figure {{ display: inline-block; margin: 0.3em; vertical-align: top; }}\n\
         figure img {{ max-width: 480px; image-rendering: pixelated; border: 1px solid #888; }}\n\
         table {{ border-collapse: collapse; }} td, th {{ border: 1px solid #bbb; padding: 2px 6px; }}\n\
         .bad {{ color: #c22; font-weight: bold; }}\n</style></head><body>\n\
         <h1>tessera-compare</h1>\n<p>{} of {} programs passed. Reference: <b>{}</b>. Implementations: {}.</p>\n\
         <p>Heat maps: equal pixels dim grey, differing pixels from green (1) to red (128 and more).</p>\n\
         <p id=\"image-check\">images: checking</p>\n",
        passed,
        report.programs.len(),
        html_escape(report.implementations.first().map_or("", |i| i.name.as_str())),
        report
            .implementations
            .iter()
            .map(|i| format!("<b>{}</b> ({})", html_escape(&i.name), html_escape(&i.describe())))
            .collect::<Vec<_>>()
            .join(", ")
    );
    for program in &report.programs {
        program_html(&mut html, program, &img_dir)?;
    }
    html.push_str(
        "<script>\n\
         window.addEventListener('load', function () {\n\
           var images = document.images, broken = 0;\n\
           for (var i = 0; i < images.length; i++)\n\
             if (!(images[i].complete && images[i].naturalWidth > 0)) broken++;\n\
           var check = document.getElementById('image-check');\n\
           check.textContent = broken === 0 ? 'images-loaded: all ' + images.length\n\
                                            : 'images-failed: ' + broken + ' of ' + images.length;\n\
           document.documentElement.setAttribute('data-images', broken === 0 ? 'loaded' : 'failed');\n\
         });\n</script>\n</body></html>\n",
    );
    let index = dir.join("index.html");
    fs::write(&index, html).map_err(|e| format!("{}: {e}", index.display()))
}

fn program_html(html: &mut String, program: &ProgramReport, img_dir: &Path) -> Result<(), String> {
    let failures = program.failures();
    let _ = writeln!(
        html,
        "<section class=\"{}\" id=\"{}\"><h2>{} — {}</h2>",
        if failures.is_empty() { "pass" } else { "fail" },
        html_escape(&program.name),
        html_escape(&program.name),
        if failures.is_empty() { "passed" } else { "FAILED" }
    );
    for f in &failures {
        let _ = writeln!(html, "<p class=\"bad\">{}</p>", html_escape(f));
    }
    let runs: Vec<String> = program
        .runs
        .iter()
        .map(|r| {
            format!(
                "{}: {} in {:.2} s{}",
                html_escape(&r.implementation),
                r.error.as_deref().map_or("ok".to_string(), html_escape),
                r.seconds,
                r.renderer.as_deref().map_or(String::new(), |s| format!(" ({})", html_escape(s)))
            )
        })
        .collect();
    let _ = writeln!(html, "<p>Runs: {}</p>", runs.join("; "));
    let program_dir = img_dir.join(&program.name);
    fs::create_dir_all(&program_dir).map_err(|e| format!("{}: {e}", program_dir.display()))?;
    for image in &program.images {
        let _ = writeln!(html, "<h3>{}</h3><div>", html_escape(&image.name));
        for (implementation, file) in &image.files {
            let Some(file) = file else {
                let _ = writeln!(
                    html,
                    "<figure><figcaption>{}: no picture</figcaption></figure>",
                    html_escape(implementation)
                );
                continue;
            };
            let name = format!("{}.{}.png", image.name, implementation);
            fs::copy(file, program_dir.join(&name)).map_err(|e| format!("{}: {e}", file.display()))?;
            let _ = writeln!(
                html,
                "<figure><img src=\"img/{}/{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>",
                html_escape(&program.name),
                html_escape(&name),
                html_escape(&name),
                html_escape(implementation)
            );
        }
        for c in &image.comparisons {
            let (Some(reference), Some(tested), Ok(_)) = (&c.reference_file, &c.tested_file, &c.metrics) else {
                continue;
            };
            let map = heat_map(&read_png(reference)?, &read_png(tested)?);
            let name = format!("{}.{}-vs-{}.diff.png", image.name, c.tested, c.reference.replace(' ', "_"));
            write_png(&program_dir.join(&name), &map)?;
            let _ = writeln!(
                html,
                "<figure><img src=\"img/{}/{}\" alt=\"{}\"><figcaption>difference: {} against {}</figcaption></figure>",
                html_escape(&program.name),
                html_escape(&name),
                html_escape(&name),
                html_escape(&c.tested),
                html_escape(&c.reference)
            );
        }
        html.push_str(
            "</div><table><tr><th>tested</th><th>against</th><th>max error</th><th>bad pixels (tolerance)</th>\
             <th>PSNR dB</th><th>SSIM</th><th>1-px shift</th><th>thresholds</th><th>result</th></tr>\n",
        );
        for c in &image.comparisons {
            let t = &c.thresholds;
            let limits = format!(
                "max_error={} tolerance={} bad_pixels={}{}{}",
                t.max_error,
                t.tolerance(),
                t.bad_pixels,
                t.min_psnr.map_or(String::new(), |v| format!(" min_psnr={v}")),
                t.min_ssim.map_or(String::new(), |v| format!(" min_ssim={v}"))
            );
            let numbers = match &c.metrics {
                Ok(m) => format!(
                    "<td>{}</td><td>{} ({})</td><td>{}</td><td>{:.5}</td><td>{}</td>",
                    m.max_error,
                    m.bad_pixels,
                    m.tolerance,
                    if m.psnr.is_finite() { format!("{:.2}", m.psnr) } else { "∞".to_string() },
                    m.ssim,
                    if m.shift { "yes" } else { "no" }
                ),
                Err(e) => format!("<td colspan=\"5\" class=\"bad\">{}</td>", html_escape(e)),
            };
            let result = if c.failures.is_empty() {
                "pass".to_string()
            } else {
                format!("<span class=\"bad\">{}</span>", html_escape(&c.failures.join("; ")))
            };
            let _ = writeln!(
                html,
                "<tr><td>{}</td><td>{}</td>{}<td>{}</td><td>{}</td></tr>",
                html_escape(&c.tested),
                html_escape(&c.reference),
                numbers,
                html_escape(&limits),
                result
            );
        }
        html.push_str("</table>\n");
    }
    html.push_str("</section>\n");
    Ok(())
}
