//! The GL implementations a program runs on, as given on the command line:
//! `llvmpipe` (the system's Mesa), `softpipe` (the system's Mesa with
//! `GALLIUM_DRIVER=softpipe`), `tessera` (tessera's `target/release`), `tessera=DIR` or
//! `NAME=DIR` (the `libOSMesa.so.8` in DIR, loaded through `LD_LIBRARY_PATH`).

use std::path::{Path, PathBuf};
use std::process::Command;

/// One GL implementation and how to make a program load it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Implementation {
    /// The name used in reports and in the manifest's `only=`.
    pub name: String,
    /// The directory holding its `libOSMesa.so.8`; None for the system library.
    pub lib_dir: Option<PathBuf>,
    /// `GALLIUM_DRIVER` for the system's Mesa.
    pub gallium_driver: Option<String>,
}

impl Implementation {
    /// Parses a command-line implementation (see the module documentation).
    pub fn parse(spec: &str) -> Result<Implementation, String> {
        let system = |driver: &str| Implementation {
            name: driver.to_string(),
            lib_dir: None,
            gallium_driver: Some(driver.to_string()),
        };
        let (name, dir) = match spec.split_once('=') {
            Some((name, dir)) => (name, PathBuf::from(dir)),
            None if spec == "llvmpipe" || spec == "softpipe" => return Ok(system(spec)),
            None if spec == "tessera" => (spec, PathBuf::from("target/release")),
            None => return Err(format!("unknown implementation {spec} (llvmpipe, softpipe, tessera[=DIR], NAME=DIR)")),
        };
        if name.is_empty() {
            return Err(format!("{spec}: empty name"));
        }
        if !dir.join("libOSMesa.so.8").is_file() {
            return Err(format!("{spec}: {} has no libOSMesa.so.8", dir.display()));
        }
        let dir = dir.canonicalize().map_err(|e| format!("{}: {e}", dir.display()))?;
        Ok(Implementation { name: name.to_string(), lib_dir: Some(dir), gallium_driver: None })
    }

    /// How it was given, for the report.
    pub fn describe(&self) -> String {
        match (&self.lib_dir, &self.gallium_driver) {
            (Some(dir), _) => format!("LD_LIBRARY_PATH={}", dir.display()),
            (None, Some(driver)) => format!("system libOSMesa.so.8, GALLIUM_DRIVER={driver}"),
            (None, None) => "system libOSMesa.so.8".to_string(),
        }
    }

    /// A command running `program` on this implementation: any inherited
    /// `LD_LIBRARY_PATH` and `GALLIUM_DRIVER` are replaced.
    pub fn command(&self, program: &Path) -> Command {
        let mut command = Command::new(program);
        command.env_remove("LD_LIBRARY_PATH").env_remove("GALLIUM_DRIVER");
        if let Some(dir) = &self.lib_dir {
            command.env("LD_LIBRARY_PATH", dir);
        }
        if let Some(driver) = &self.gallium_driver {
            command.env("GALLIUM_DRIVER", driver);
        }
        command
    }
}
