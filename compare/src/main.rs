//! The `tessera-compare` command line: see `usage()` and the README.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;
use tessera_compare::image::read_png;
use tessera_compare::implementation::Implementation;
use tessera_compare::manifest::Manifest;
use tessera_compare::metrics::compare;
use tessera_compare::report::{self, Comparison, ImageReport, ProgramReport, Report};
use tessera_compare::runner::{self, Program};

fn usage() -> &'static str {
    "usage: tessera-compare [options] PROGRAM...\n\
     \n\
     Runs each PROGRAM (a .c file, compiled with gcc against the system's GL headers; an\n\
     executable; or a directory of them) on every implementation, with an empty output\n\
     directory as its argument, and compares the PNG files each run writes with those of\n\
     the first implementation (the reference).\n\
     \n\
     options:\n\
       -i, --impl SPEC      an implementation, at least two, the first is the reference:\n\
                            llvmpipe | softpipe | tessera (= target/release) | NAME=DIR\n\
       -m, --manifest FILE  per-test thresholds (default: manifest.txt next to the first\n\
                            program, if there is one; without an entry images must be equal)\n\
       --shift              allow a 1-pixel shift for every image\n\
       --json FILE          write the results as JSON\n\
       --html DIR           write an HTML report (DIR/index.html)\n\
       --work DIR           where binaries and pictures go (default target/tessera-compare)\n\
       --timeout SECONDS    time limit of each run (default 60)\n\
     \n\
     Exit status: 0 when every image is within its thresholds, 1 when not, 2 on bad usage."
}

struct Options {
    implementations: Vec<Implementation>,
    manifest: Option<PathBuf>,
    shift: bool,
    json: Option<PathBuf>,
    html: Option<PathBuf>,
    work: PathBuf,
    timeout: Duration,
    programs: Vec<PathBuf>,
}

fn parse_args(args: &[String]) -> Result<Options, String> {
    let mut options = Options {
        implementations: Vec::new(),
        manifest: None,
        shift: false,
        json: None,
        html: None,
        work: PathBuf::from("target/tessera-compare"),
        timeout: Duration::from_secs(60),
        programs: Vec::new(),
    };
    let mut args = args.iter();
    while let Some(arg) = args.next() {
        let mut value = || args.next().cloned().ok_or_else(|| format!("{arg} needs a value"));
        match arg.as_str() {
            "-h" | "--help" => return Err(String::new()),
            "-i" | "--impl" => options.implementations.push(Implementation::parse(&value()?)?),
            "-m" | "--manifest" => options.manifest = Some(PathBuf::from(value()?)),
            "--shift" => options.shift = true,
            "--json" => options.json = Some(PathBuf::from(value()?)),
            "--html" => options.html = Some(PathBuf::from(value()?)),
            "--work" => options.work = PathBuf::from(value()?),
            "--timeout" => {
                let v = value()?;
                options.timeout = Duration::from_secs(v.parse().map_err(|_| format!("--timeout: {v}"))?);
            }
            a if a.starts_with('-') => return Err(format!("unknown option {a}")),
            a => options.programs.push(PathBuf::from(a)),
        }
    }
    if options.implementations.len() < 2 {
        return Err("give at least two implementations (--impl)".to_string());
    }
    let mut names: Vec<&str> = options.implementations.iter().map(|i| i.name.as_str()).collect();
    names.sort();
    if names.windows(2).any(|w| w[0] == w[1]) {
        return Err("two implementations have the same name (use NAME=DIR)".to_string());
    }
    if options.programs.is_empty() {
        return Err("no PROGRAM given".to_string());
    }
    Ok(options)
}

/// The default manifest: manifest.txt in the first program's directory (or the directory).
fn default_manifest(first: &Path) -> Option<PathBuf> {
    let dir = if first.is_dir() { first.to_path_buf() } else { first.parent()?.to_path_buf() };
    let candidate = dir.join("manifest.txt");
    candidate.is_file().then_some(candidate)
}

fn check_program(program: &Program, options: &Options, manifest: &Manifest) -> ProgramReport {
    let mut result = ProgramReport {
        name: program.name.clone(),
        path: program.path.clone(),
        compile_error: None,
        runs: Vec::new(),
        images: Vec::new(),
    };
    let executable = if program.is_source {
        let bin_dir = options.work.join("bin");
        let _ = std::fs::create_dir_all(&bin_dir);
        let executable = bin_dir.join(&program.name);
        if let Err(e) = runner::compile(&program.path, &executable) {
            result.compile_error = Some(e);
            return result;
        }
        executable
    } else {
        program.path.canonicalize().unwrap_or_else(|_| program.path.clone())
    };
    for implementation in &options.implementations {
        let out = options.work.join("out").join(&implementation.name).join(&program.name);
        result.runs.push(runner::run(&executable, implementation, &out, options.timeout));
    }
    let mut names: Vec<String> = result.runs.iter().flat_map(|r| runner::png_names(&r.output_dir)).collect();
    names.sort();
    names.dedup();
    for name in names {
        let file = |run: &runner::Run, image: &str| {
            let path = run.output_dir.join(format!("{image}.png"));
            path.is_file().then_some(path)
        };
        let files: Vec<(String, Option<PathBuf>)> =
            result.runs.iter().map(|r| (r.implementation.clone(), file(r, &name))).collect();
        let thresholds = manifest.thresholds(&program.name, &name, options.shift);
        let mut comparisons = Vec::new();
        for (index, run) in result.runs.iter().enumerate() {
            if !thresholds.applies_to(&run.implementation) {
                continue;
            }
            let (reference, reference_file) = match &thresholds.against {
                Some(other) => (format!("image {other}"), file(run, other)),
                None if index == 0 => continue,
                None => (result.runs[0].implementation.clone(), files[0].1.clone()),
            };
            let tested_file = file(run, &name);
            let metrics = match (&reference_file, &tested_file) {
                (Some(r), Some(t)) => read_png(r)
                    .and_then(|r| read_png(t).and_then(|t| compare(&r, &t, thresholds.tolerance(), thresholds.shift))),
                (None, _) => Err(format!("no picture for {reference}")),
                (_, None) => Err(format!("no picture on {}", run.implementation)),
            };
            let failures = match &metrics {
                Ok(m) => thresholds.failures(m),
                Err(e) => vec![e.clone()],
            };
            comparisons.push(Comparison {
                tested: run.implementation.clone(),
                reference,
                reference_file,
                tested_file,
                thresholds: thresholds.clone(),
                metrics,
                failures,
            });
        }
        result.images.push(ImageReport { name, files, comparisons });
    }
    result
}

fn progress_line(index: usize, count: usize, program: &ProgramReport) -> String {
    let runs: Vec<String> = program
        .runs
        .iter()
        .map(|r| format!("{} {} {:.1}s", r.implementation, r.error.as_deref().unwrap_or("ok"), r.seconds))
        .collect();
    let worst = program
        .images
        .iter()
        .flat_map(|i| &i.comparisons)
        .filter_map(|c| c.metrics.as_ref().ok())
        .map(|m| m.max_error)
        .max();
    let failures = program.failures();
    format!(
        "[{}/{}] {}: {}; {} images, largest error {}: {}",
        index + 1,
        count,
        program.name,
        if runs.is_empty() { "not run".to_string() } else { runs.join(", ") },
        program.images.len(),
        worst.map_or("-".to_string(), |w| w.to_string()),
        match failures.len() {
            0 => "pass".to_string(),
            1..=2 => format!("FAIL ({})", failures.join("; ")),
            n => format!("FAIL ({}; and {} more)", failures[..2].join("; "), n - 2),
        }
    )
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let options = match parse_args(&args) {
        Ok(options) => options,
        Err(message) if message.is_empty() => {
            println!("{}", usage());
            return ExitCode::SUCCESS;
        }
        Err(message) => {
            eprintln!("tessera-compare: {message}");
            eprintln!("{}", usage());
            return ExitCode::from(2);
        }
    };
    let manifest_path = options.manifest.clone().or_else(|| default_manifest(&options.programs[0]));
    let manifest = match &manifest_path {
        Some(path) => {
            match std::fs::read_to_string(path).map_err(|e| e.to_string()).and_then(|t| Manifest::parse(&t)) {
                Ok(m) => m,
                Err(e) => {
                    eprintln!("tessera-compare: {}: {e}", path.display());
                    return ExitCode::from(2);
                }
            }
        }
        None => Manifest::default(),
    };
    let programs = match runner::collect_programs(&options.programs) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("tessera-compare: {e}");
            return ExitCode::from(2);
        }
    };
    eprintln!(
        "tessera-compare: {} programs on {} (reference {}), manifest {}",
        programs.len(),
        options.implementations.iter().map(|i| i.name.as_str()).collect::<Vec<_>>().join(", "),
        options.implementations[0].name,
        manifest_path.as_ref().map_or("none".to_string(), |p| p.display().to_string())
    );
    let mut report = Report { implementations: options.implementations.clone(), programs: Vec::new() };
    for (index, program) in programs.iter().enumerate() {
        let result = check_program(program, &options, &manifest);
        eprintln!("{}", progress_line(index, programs.len(), &result));
        report.programs.push(result);
    }
    if let Some(path) = &options.json {
        if let Err(e) = std::fs::write(path, report::to_json(&report)) {
            eprintln!("tessera-compare: {}: {e}", path.display());
            return ExitCode::from(2);
        }
        eprintln!("tessera-compare: JSON in {}", path.display());
    }
    if let Some(dir) = &options.html {
        if let Err(e) =
            std::fs::create_dir_all(dir).map_err(|e| e.to_string()).and_then(|_| report::write_html(&report, dir))
        {
            eprintln!("tessera-compare: HTML report: {e}");
            return ExitCode::from(2);
        }
        eprintln!("tessera-compare: HTML report in {}", dir.join("index.html").display());
    }
    let failed = report.programs.iter().filter(|p| !p.failures().is_empty()).count();
    eprintln!("tessera-compare: {} passed, {} failed", report.programs.len() - failed, failed);
    if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
