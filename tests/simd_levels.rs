//! Same bytes at every SIMD level and thread count: the capi tests and the example programs
//! rendered by tessera at `TESSERA_SIMD=sse2`, `sse41`, `avx2` (every level this CPU has),
//! each at `TESSERA_THREADS=1` and `2`, and every output compared byte for byte with the
//! run at `sse2` on one thread: the exit status, the VALUE lines (read-backs, queries) and
//! every file the program wrote (the capi tests' `.img` images, the examples' PNGs). This is
//! tessera against itself, not against Mesa (`tests/capi.rs` does that).
//!
//! Every capi test takes part except [`SLOW`] (stress tests that run for tens of seconds
//! each: six runs of them would make this test take minutes), and every example.
//! A level the CPU lacks cannot be run; the test says so on stderr (`simd: avx2 is not
//! available on this CPU: not checked`), never silently. A probe run per configuration
//! checks through `TESSERA_DEBUG=config` that the library really runs at the level asked
//! for, so a `TESSERA_SIMD` that stopped working cannot pass by comparing one level with
//! itself.
//!
//! Artifacts: `target/capi/simd/bin/` (the programs), `target/capi/simd/run/<program>/
//! <level>-<n>t/` (each run's stdout, stderr and files).

#[allow(dead_code)] // the image and manifest helpers are tests/capi.rs's
mod capi_support;

use capi_support::process::{self, Exit, Implementation};
use capi_support::say;
use capi_support::setup::{self, Setup, CC};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};
use tessera::simd::Level;

/// A program is killed after this long.
const TIMEOUT: Duration = Duration::from_secs(60);

/// Capi tests left out, and why.
const SLOW: [(&str, &str); 2] = [
    ("reliability_memory", "16384² framebuffers, 10⁶-vertex draws, 10 000 contexts: about a minute a run"),
    ("reliability_streaming", "10⁶- and 10⁷-vertex draws measured for memory: about 45 s a run"),
];

/// The thread counts every level runs at.
const THREADS: [usize; 2] = [1, 2];

/// One way of running tessera.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Config {
    level: Level,
    threads: usize,
}

impl Config {
    fn label(self) -> String {
        format!("{}-{}t", self.level.name(), self.threads)
    }

    fn configure(self, command: &mut Command, setup: &Setup) {
        Implementation::Tessera.configure(command, setup);
        command
            .env("TESSERA_SIMD", self.level.name())
            .env("TESSERA_THREADS", self.threads.to_string())
            .env("TESSERA_DEBUG", "config");
    }
}

/// A program to run: a capi test or an example.
struct Program {
    name: String,
    binary: PathBuf,
    /// Examples take their output directory as an argument; capi tests read `CAPI_OUT`.
    example: bool,
}

/// What a run produced that must not depend on the configuration.
#[derive(Debug, PartialEq)]
struct Output {
    exit: Exit,
    values: Vec<String>,
    files: BTreeMap<String, Vec<u8>>,
}

#[test]
fn every_simd_level_and_thread_count_gives_the_same_bytes() {
    let Some(setup) = setup::require("SIMD levels") else {
        return;
    };
    setup.warn_if_library_stale();
    let started = Instant::now();
    let mut levels = Vec::new();
    for &level in Level::ALL {
        if level.available() {
            levels.push(level);
        } else {
            say(&format!("simd: {level} is not available on this CPU: not checked"));
        }
    }
    let configs: Vec<Config> =
        levels.iter().flat_map(|&level| THREADS.map(|threads| Config { level, threads })).collect();
    let out = setup.out.join("simd");
    check_levels_take_effect(&setup, &out, &configs);

    let programs = compile_all(&setup, &out);
    let next = AtomicUsize::new(0);
    let problems = Mutex::new(Vec::new());
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get()).clamp(1, 4);
    std::thread::scope(|scope| {
        for _ in 0..workers {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                let Some(program) = programs.get(i) else { break };
                let found = check_program(&setup, &out, program, &configs);
                if !found.is_empty() {
                    say(&format!("simd FAIL {}:\n  {}", program.name, found.join("\n  ")));
                }
                problems.lock().unwrap().extend(found);
            });
        }
    });
    let problems = problems.into_inner().unwrap();
    say(&format!(
        "simd: {} programs ({} capi tests, {} examples) at {} in {:.0} s: {}",
        programs.len(),
        programs.iter().filter(|p| !p.example).count(),
        programs.iter().filter(|p| p.example).count(),
        configs.iter().map(|c| c.label()).collect::<Vec<_>>().join(", "),
        started.elapsed().as_secs_f64(),
        if problems.is_empty() { "identical".to_string() } else { format!("{} difference(s)", problems.len()) }
    ));
    assert!(problems.is_empty(), "outputs differ between SIMD levels or thread counts:\n{}", problems.join("\n"));
}

/// The renderer probe at each configuration: `TESSERA_DEBUG=config` must report the level
/// asked for (every level run here is one the CPU has, so none may fall back).
fn check_levels_take_effect(setup: &Setup, out: &Path, configs: &[Config]) {
    let binary = out.join("bin/renderer_probe");
    std::fs::create_dir_all(binary.parent().unwrap()).unwrap();
    let source = setup.root.join("tests/capi_support/renderer_probe.c");
    let (ok, log) =
        process::output_of(Command::new(CC).arg("-std=c11").arg(&source).arg("-o").arg(&binary).arg("-lOSMesa"));
    assert!(ok, "cannot build the renderer probe:\n{log}");
    for &config in configs {
        let dir = out.join("run/renderer_probe").join(config.label());
        std::fs::create_dir_all(&dir).unwrap();
        let mut command = Command::new(&binary);
        config.configure(&mut command, setup);
        let finished = process::run_with_timeout(&mut command, &dir, TIMEOUT).expect("the renderer probe runs");
        assert_eq!(finished.exit, Exit::Code(0), "renderer probe at {}: {}", config.label(), finished.stderr);
        let expected = [
            format!("tessera config: simd {} (TESSERA_SIMD={})", config.level, config.level),
            format!("tessera config: threads {}", config.threads),
        ];
        for line in expected {
            assert!(
                finished.stderr.lines().any(|l| l == line),
                "at {} tessera did not report `{line}` (TESSERA_SIMD or TESSERA_THREADS has no effect?); stderr:\n{}",
                config.label(),
                finished.stderr
            );
        }
    }
}

/// Compiles the capi tests (but [`SLOW`]) and the examples into `out/bin`, reusing a binary
/// newer than every file of its source directory.
fn compile_all(setup: &Setup, out: &Path) -> Vec<Program> {
    let bin = out.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    let capi = setup.root.join("capi-tests");
    let examples = setup.root.join("examples-c");
    let mut jobs = Vec::new();
    for (dir, example) in [(&capi, false), (&examples, true)] {
        for name in c_programs(dir) {
            if !example && (name == "common" || SLOW.iter().any(|(s, _)| *s == name)) {
                continue;
            }
            let binary = bin.join(if example { format!("example_{name}") } else { name.clone() });
            jobs.push((
                Program { name: if example { format!("examples-c/{name}") } else { name }, binary, example },
                dir,
            ));
        }
    }
    for (name, why) in SLOW {
        say(&format!("simd: capi test {name} is left out ({why})"));
    }
    let next = AtomicUsize::new(0);
    let failures = Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..std::thread::available_parallelism().map_or(2, |n| n.get()).clamp(1, 4) {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                let Some((program, dir)) = jobs.get(i) else { break };
                if let Err(log) = compile(program, dir) {
                    failures.lock().unwrap().push(format!("{}: {log}", program.name));
                }
            });
        }
    });
    let failures = failures.into_inner().unwrap();
    assert!(failures.is_empty(), "programs do not compile:\n{}", failures.join("\n"));
    jobs.into_iter().map(|(p, _)| p).collect()
}

/// The stems of the `*.c` files of `dir`, sorted.
fn c_programs(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "c") && p.is_file())
        .filter_map(|p| p.file_stem().map(|s| s.to_string_lossy().into_owned()))
        .collect();
    names.sort();
    names
}

fn compile(program: &Program, dir: &Path) -> Result<(), String> {
    let modified = |p: &Path| p.metadata().and_then(|m| m.modified()).ok();
    let newest_source =
        std::fs::read_dir(dir).ok().into_iter().flatten().filter_map(|e| modified(&e.ok()?.path())).max();
    if let (Some(built), Some(source)) = (modified(&program.binary), newest_source) {
        if built > source {
            return Ok(());
        }
    }
    let stem = program.name.rsplit('/').next().unwrap_or(&program.name);
    let mut command = Command::new(CC);
    command.args(["-std=c11", "-O1", "-Wall", "-Werror", "-I"]).arg(dir).arg(dir.join(format!("{stem}.c")));
    if !program.example {
        command.arg(dir.join("common.c"));
    }
    command.args(["-lOSMesa", "-lm", "-lpthread", "-o"]).arg(&program.binary);
    match process::output_of(&mut command) {
        (true, _) => Ok(()),
        (false, log) => Err(log),
    }
}

/// Runs `program` at every configuration and compares each output with the first's.
fn check_program(setup: &Setup, out: &Path, program: &Program, configs: &[Config]) -> Vec<String> {
    let mut problems = Vec::new();
    let mut reference: Option<(Config, Output)> = None;
    for &config in configs {
        let dir = out.join("run").join(program.name.replace('/', "_")).join(config.label());
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let mut command = Command::new(&program.binary);
        if program.example {
            command.arg(&dir);
        } else {
            command.env("CAPI_OUT", &dir);
        }
        config.configure(&mut command, setup);
        let finished = match process::run_with_timeout(&mut command, &dir, TIMEOUT) {
            Ok(finished) => finished,
            Err(e) => {
                problems.push(format!("{} at {}: cannot run: {e}", program.name, config.label()));
                continue;
            }
        };
        let values = finished.stdout.lines().filter(|l| l.starts_with("VALUE ")).map(str::to_string).collect();
        let output = Output { exit: finished.exit, values, files: files_in(&dir) };
        match &reference {
            None => reference = Some((config, output)),
            Some((first, expected)) => {
                for difference in differences(expected, &output) {
                    problems.push(format!(
                        "{}: {} differs from {}: {difference} ({})",
                        program.name,
                        config.label(),
                        first.label(),
                        dir.display()
                    ));
                }
            }
        }
    }
    problems
}

/// Every file a run wrote, by name, but the harness's own stdout and stderr.
fn files_in(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file())
        .filter_map(|p| Some((p.file_name()?.to_string_lossy().into_owned(), p)))
        .filter(|(name, _)| name != "stdout.txt" && name != "stderr.txt")
        .map(|(name, p)| (name, std::fs::read(&p).unwrap_or_default()))
        .collect()
}

/// How `b` differs from `a`, one line per difference.
fn differences(a: &Output, b: &Output) -> Vec<String> {
    let mut found = Vec::new();
    if a.exit != b.exit {
        found.push(format!("{} instead of {}", b.exit, a.exit));
    }
    if a.values != b.values {
        let first =
            a.values.iter().zip(&b.values).position(|(x, y)| x != y).unwrap_or(a.values.len().min(b.values.len()));
        let show = |v: &[String]| v.get(first).cloned().unwrap_or_else(|| "(no more VALUE lines)".into());
        found.push(format!("VALUE line #{first}: `{}` instead of `{}`", show(&b.values), show(&a.values)));
    }
    for name in a.files.keys().chain(b.files.keys().filter(|k| !a.files.contains_key(*k))) {
        match (a.files.get(name), b.files.get(name)) {
            (Some(x), Some(y)) if x != y => {
                let at = x.iter().zip(y).position(|(p, q)| p != q).unwrap_or(x.len().min(y.len()));
                found.push(format!(
                    "file {name}: first different byte at offset {at} ({} vs {} bytes)",
                    y.len(),
                    x.len()
                ));
            }
            (Some(_), None) => found.push(format!("file {name} was not written")),
            (None, Some(_)) => found.push(format!("file {name} was written only here")),
            _ => {}
        }
    }
    found
}

#[test]
fn a_changed_byte_exit_or_value_is_a_difference() {
    let output = || Output {
        exit: Exit::Code(0),
        values: vec!["VALUE a 1".into(), "VALUE b 2".into()],
        files: BTreeMap::from([("x.img".to_string(), vec![0u8, 1, 2, 3]), ("y.png".to_string(), vec![9u8; 8])]),
    };
    assert!(differences(&output(), &output()).is_empty());
    let mut byte = output();
    byte.files.get_mut("x.img").unwrap()[2] ^= 1;
    assert_eq!(differences(&output(), &byte), ["file x.img: first different byte at offset 2 (4 vs 4 bytes)"]);
    let mut value = output();
    value.values[1] = "VALUE b 3".into();
    assert_eq!(differences(&output(), &value).len(), 1);
    let mut exit = output();
    exit.exit = Exit::Code(1);
    assert_eq!(differences(&output(), &exit).len(), 1);
    let mut missing = output();
    missing.files.remove("y.png");
    assert_eq!(differences(&output(), &missing), ["file y.png was not written"]);
}
