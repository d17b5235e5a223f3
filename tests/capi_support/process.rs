//! Running a test program on one implementation, with a time limit.
//!
//! The implementation is chosen by the dynamic loader: the programs are linked against the
//! system's `libOSMesa.so.8`, and `LD_LIBRARY_PATH=<tessera lib dir>` makes the loader pick
//! tessera's file of the same name instead. For the Mesa run every tessera directory is
//! removed from `LD_LIBRARY_PATH`, so a developer's shell setting cannot turn the reference
//! run into a second tessera run.
use super::setup::Setup;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// Which library a program runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Implementation {
    /// The system's Mesa.
    Mesa,
    /// tessera, with `TESSERA_THREADS` unset (the default thread count).
    Tessera,
    /// tessera with `TESSERA_THREADS=1`, for the determinism check.
    TesseraOneThread,
}

impl Implementation {
    /// The name of the run's directory and of its images in failure reports.
    pub fn label(self) -> &'static str {
        match self {
            Implementation::Mesa => "mesa",
            Implementation::Tessera => "tessera",
            Implementation::TesseraOneThread => "tessera-1thread",
        }
    }

    /// Sets the environment that selects this implementation.
    pub fn configure(self, command: &mut Command, setup: &Setup) {
        let others = foreign_library_path(&setup.tessera_lib_dir);
        // Lazy binding lets a program built against Mesa's full symbol set run on a library
        // that does not define every function yet, as long as it does not call them.
        command.env_remove("LD_BIND_NOW").env_remove("TESSERA_THREADS");
        match self {
            Implementation::Mesa => {
                if others.is_empty() {
                    command.env_remove("LD_LIBRARY_PATH");
                } else {
                    command.env("LD_LIBRARY_PATH", join_paths(&others));
                }
            }
            Implementation::Tessera | Implementation::TesseraOneThread => {
                let mut dirs = vec![setup.tessera_lib_dir.clone()];
                dirs.extend(others);
                command.env("LD_LIBRARY_PATH", join_paths(&dirs));
                if self == Implementation::TesseraOneThread {
                    command.env("TESSERA_THREADS", "1");
                }
            }
        }
    }
}

/// The entries of the current `LD_LIBRARY_PATH` that are not tessera directories (the
/// configured one, or any directory holding a `libtessera.so`).
fn foreign_library_path(tessera: &Path) -> Vec<PathBuf> {
    without_tessera(&std::env::var_os("LD_LIBRARY_PATH").unwrap_or_default(), tessera)
}

/// The entries of the search path `value` that are not tessera directories.
fn without_tessera(value: &std::ffi::OsStr, tessera: &Path) -> Vec<PathBuf> {
    let canonical = |p: &Path| p.canonicalize().unwrap_or_else(|_| p.to_path_buf());
    let tessera = canonical(tessera);
    std::env::split_paths(value)
        .filter(|p| !p.as_os_str().is_empty())
        .filter(|p| canonical(p) != tessera && !p.join("libtessera.so").exists())
        .collect()
}

fn join_paths(paths: &[PathBuf]) -> std::ffi::OsString {
    std::env::join_paths(paths).unwrap_or_default()
}

/// How a program ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Exit {
    Code(i32),
    Signal(i32),
    TimedOut,
}

impl std::fmt::Display for Exit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Exit::Code(c) => write!(f, "exit status {c}"),
            Exit::Signal(s) => write!(f, "killed by signal {s}"),
            Exit::TimedOut => write!(f, "timed out (killed)"),
        }
    }
}

/// A finished run: how it ended, its output and its duration.
#[derive(Debug)]
pub struct Finished {
    pub exit: Exit,
    pub stdout: String,
    pub stderr: String,
    pub seconds: f64,
}

/// Runs `command` in `dir` (which must exist), stdout and stderr going to `dir/stdout.txt`
/// and `dir/stderr.txt`; kills it after `timeout`.
pub fn run_with_timeout(command: &mut Command, dir: &Path, timeout: Duration) -> std::io::Result<Finished> {
    let stdout_path = dir.join("stdout.txt");
    let stderr_path = dir.join("stderr.txt");
    let start = Instant::now();
    let mut child = command
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(File::create(&stdout_path)?)
        .stderr(File::create(&stderr_path)?)
        .spawn()?;
    let exit = loop {
        if let Some(status) = child.try_wait()? {
            break exit_of(status);
        }
        if start.elapsed() > timeout {
            let _ = child.kill();
            let _ = child.wait();
            break Exit::TimedOut;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let read = |p: &Path| String::from_utf8_lossy(&std::fs::read(p).unwrap_or_default()).into_owned();
    Ok(Finished {
        exit,
        stdout: read(&stdout_path),
        stderr: read(&stderr_path),
        seconds: start.elapsed().as_secs_f64(),
    })
}

fn exit_of(status: ExitStatus) -> Exit {
    use std::os::unix::process::ExitStatusExt as _;
    match (status.code(), status.signal()) {
        (Some(code), _) => Exit::Code(code),
        (None, Some(signal)) => Exit::Signal(signal),
        (None, None) => Exit::Code(-1),
    }
}

/// Runs `command` to completion and returns (success, combined stdout+stderr), for the
/// compiler.
pub fn output_of(command: &mut Command) -> (bool, String) {
    match command.env("LC_ALL", "C").output() {
        Ok(out) => {
            let mut text = String::from_utf8_lossy(&out.stdout).into_owned();
            text.push_str(&String::from_utf8_lossy(&out.stderr));
            (out.status.success(), text)
        }
        Err(e) => (false, format!("cannot run {command:?}: {e}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(script: &str, timeout: Duration) -> Finished {
        let dir = std::env::temp_dir().join(format!("capi-process-{}-{}", std::process::id(), script.len()));
        std::fs::create_dir_all(&dir).unwrap();
        let finished = run_with_timeout(Command::new("sh").args(["-c", script]), &dir, timeout).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        finished
    }

    #[test]
    fn reports_exit_codes_signals_output_and_timeouts() {
        let done = run("echo out; echo err >&2; exit 3", Duration::from_secs(20));
        assert_eq!((done.exit, done.stdout.as_str(), done.stderr.as_str()), (Exit::Code(3), "out\n", "err\n"));
        assert_eq!(run("kill -SEGV $$", Duration::from_secs(20)).exit, Exit::Signal(11));
        let slow = run("sleep 30", Duration::from_millis(200));
        assert_eq!(slow.exit, Exit::TimedOut);
        assert!(slow.seconds < 10.0, "the timed-out program was not killed promptly");
    }

    #[test]
    fn tessera_directories_leave_the_mesa_search_path() {
        let dir = std::env::temp_dir().join(format!("capi-ldpath-{}", std::process::id()));
        let (tessera, marked, other) = (dir.join("release"), dir.join("debug"), dir.join("other"));
        for d in [&tessera, &marked, &other] {
            std::fs::create_dir_all(d).unwrap();
        }
        std::fs::write(marked.join("libtessera.so"), b"").unwrap();
        let value = std::env::join_paths([&other, &tessera, &marked, &dir.join("release/../release")]).unwrap();
        assert_eq!(without_tessera(&value, &tessera), vec![other.clone()]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
