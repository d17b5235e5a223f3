#!/usr/bin/env bash
# Everything CI checks: set-up, the release build (the drop-in libraries the capi tests
# load), the tests (Rust unit tests and tests/capi.rs, which runs every capi-tests/*.c on
# Mesa and on tessera), formatting and clippy.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/setup-debian.sh
cargo build --release
cargo test --release
# Command-stream fuzzing (fuzz/): past findings replayed, then 90 s of libFuzzer.
bash tools/fuzz.sh 90
cargo fmt --check
cargo clippy --all-targets --release -- -D warnings
echo "test.sh: all checks passed"
