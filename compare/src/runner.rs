//! Finding, compiling and running the programs: a `.c` file is compiled with gcc against
//! the system's headers (`gcc -std=c11 -O2 -Wall -I <its directory> FILE -lOSMesa -lm`), an
//! executable is used as it is, a directory means every `.c` file in it (or, without any,
//! every executable). Each run gets an empty output directory as its only argument and a
//! time limit; the PNG files it leaves there are its pictures.

use crate::implementation::Implementation;
use std::fs;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::{Duration, Instant};

/// A program to run: its name (the file stem) and where it comes from.
#[derive(Clone, Debug)]
pub struct Program {
    pub name: String,
    pub path: PathBuf,
    pub is_source: bool,
}

/// The programs named on the command line, in order (a directory's sorted by name).
pub fn collect_programs(paths: &[PathBuf]) -> Result<Vec<Program>, String> {
    let mut programs = Vec::new();
    for path in paths {
        if path.is_dir() {
            let mut entries: Vec<PathBuf> = fs::read_dir(path)
                .map_err(|e| format!("{}: {e}", path.display()))?
                .filter_map(|entry| entry.ok().map(|e| e.path()))
                .filter(|p| p.is_file())
                .collect();
            entries.sort();
            let sources: Vec<PathBuf> =
                entries.iter().filter(|p| p.extension().is_some_and(|e| e == "c")).cloned().collect();
            let chosen =
                if sources.is_empty() { entries.into_iter().filter(|p| is_executable(p)).collect() } else { sources };
            programs.extend(chosen.iter().map(|p| program(p)));
        } else if path.is_file() {
            programs.push(program(path));
        } else {
            return Err(format!("{}: no such file or directory", path.display()));
        }
    }
    if programs.is_empty() {
        return Err("no programs found".to_string());
    }
    Ok(programs)
}

fn program(path: &Path) -> Program {
    Program {
        name: path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(),
        path: path.to_path_buf(),
        is_source: path.extension().is_some_and(|e| e == "c"),
    }
}

fn is_executable(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    fs::metadata(path).map(|m| m.permissions().mode() & 0o111 != 0).unwrap_or(false)
}

/// Compiles `source` into `executable` with gcc; the error is gcc's output.
pub fn compile(source: &Path, executable: &Path) -> Result<(), String> {
    let include = source.parent().unwrap_or(Path::new("."));
    let output = std::process::Command::new("gcc")
        .args(["-std=c11", "-O2", "-Wall", "-I"])
        .arg(include)
        .arg(source)
        .arg("-o")
        .arg(executable)
        .args(["-lOSMesa", "-lm"])
        .output()
        .map_err(|e| format!("cannot run gcc: {e}"))?;
    if output.status.success() {
        Ok(())
    } else {
        Err(String::from_utf8_lossy(&output.stderr).into_owned())
    }
}

/// The outcome of one run.
#[derive(Clone, Debug)]
pub struct Run {
    pub implementation: String,
    /// None when it exited 0, else what went wrong ("exit status 1", "timed out", ...).
    pub error: Option<String>,
    pub seconds: f64,
    /// What the program printed after "rendering with " (the examples print GL_RENDERER).
    pub renderer: Option<String>,
    pub stdout: String,
    pub stderr: String,
    pub output_dir: PathBuf,
}

/// Runs `executable` on `implementation` with `output_dir` (emptied first) as argv[1].
pub fn run(executable: &Path, implementation: &Implementation, output_dir: &Path, timeout: Duration) -> Run {
    let start = Instant::now();
    let mut result = Run {
        implementation: implementation.name.clone(),
        error: None,
        seconds: 0.0,
        renderer: None,
        stdout: String::new(),
        stderr: String::new(),
        output_dir: output_dir.to_path_buf(),
    };
    let _ = fs::remove_dir_all(output_dir);
    if let Err(e) = fs::create_dir_all(output_dir) {
        result.error = Some(format!("{}: {e}", output_dir.display()));
        return result;
    }
    let child = implementation
        .command(executable)
        .arg(output_dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let mut child = match child {
        Ok(child) => child,
        Err(e) => {
            result.error = Some(format!("cannot start {}: {e}", executable.display()));
            return result;
        }
    };
    // Drain the pipes on threads, so a chatty program cannot block on a full pipe.
    let mut stdout_pipe = child.stdout.take().expect("piped");
    let mut stderr_pipe = child.stderr.take().expect("piped");
    let stdout_reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stdout_pipe.read_to_string(&mut s);
        s
    });
    let stderr_reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stderr_pipe.read_to_string(&mut s);
        s
    });
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if start.elapsed() > timeout => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(_) => break None,
        }
    };
    result.seconds = start.elapsed().as_secs_f64();
    result.stdout = stdout_reader.join().unwrap_or_default();
    result.stderr = stderr_reader.join().unwrap_or_default();
    result.error = match status {
        None => Some(format!("timed out after {} s", timeout.as_secs())),
        Some(s) if s.success() => None,
        Some(s) => Some(match s.code() {
            Some(code) => format!("exit status {code}"),
            None => format!("killed by a signal ({s})"),
        }),
    };
    result.renderer =
        result.stdout.lines().find_map(|line| line.split_once("rendering with ").map(|(_, r)| r.trim().to_string()));
    result
}

/// The stems of the PNG files in `dir`, sorted.
pub fn png_names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok())
                .filter_map(|e| e.file_name().to_str().and_then(|n| n.strip_suffix(".png")).map(str::to_string))
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}
