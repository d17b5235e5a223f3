//! libFuzzer target: every input is a command stream for tessera (see `tessera_fuzz::run`).
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::sync::atomic::{AtomicU64, Ordering};

/// Calls made so far in this process; reported at every power of two of inputs, so the
/// CI log shows how many GL calls the run made.
static CALLS: AtomicU64 = AtomicU64::new(0);
static INPUTS: AtomicU64 = AtomicU64::new(0);

fuzz_target!(|data: &[u8]| {
    let calls = CALLS.fetch_add(tessera_fuzz::run(data), Ordering::Relaxed);
    let inputs = INPUTS.fetch_add(1, Ordering::Relaxed) + 1;
    if inputs.is_power_of_two() && inputs >= 1024 {
        eprintln!("command_stream: {inputs} inputs, {calls} GL/OSMesa calls");
    }
});
