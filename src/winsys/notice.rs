//! One-line notices to the user on stderr: why tessera refused what a program asked for.
//!
//! A program that asks for something tessera does not provide (a context version, a pixel
//! format, a GLX configuration) usually reports only that it failed, or nothing. These
//! notices say what was asked and what tessera provides, so a user can act on the refusal.
//! Each reason is printed at most once per process (a program that retries in a loop prints
//! one line), and `TESSERA_QUIET=1` silences them all.

use std::collections::HashSet;
use std::sync::{Mutex, OnceLock};

/// Whether `TESSERA_QUIET` asks for silence (any value but empty or `0`).
pub fn quiet() -> bool {
    static QUIET: OnceLock<bool> = OnceLock::new();
    *QUIET.get_or_init(|| std::env::var("TESSERA_QUIET").is_ok_and(|v| !v.is_empty() && v != "0"))
}

/// Prints `tessera: <message>` on stderr, unless `reason` was already printed by this process
/// or `TESSERA_QUIET` is set. `reason` is a short stable key (e.g. `"osmesa-version"`);
/// `message` is built only when the line is printed.
pub fn once(reason: &str, message: impl FnOnce() -> String) {
    if quiet() {
        return;
    }
    static SEEN: OnceLock<Mutex<HashSet<String>>> = OnceLock::new();
    let seen = SEEN.get_or_init(|| Mutex::new(HashSet::new()));
    // A poisoned set still holds the reasons printed so far.
    let first_time = seen.lock().unwrap_or_else(|e| e.into_inner()).insert(reason.to_string());
    if first_time {
        eprintln!("tessera: {}", message());
    }
}
