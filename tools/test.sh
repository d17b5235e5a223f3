#!/usr/bin/env bash
# Everything CI checks: set-up, the release build (the drop-in libraries the capi tests
# load), the tests (Rust unit tests and tests/capi.rs, which runs every capi-tests/*.c on
# Mesa and on tessera), formatting and clippy.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/setup-debian.sh
cargo build --release
cargo test --release
# A smoke run of the benchmark (64x64, one frame per scene: seconds; writes target/bench/quick).
bash tools/bench.sh --quick
cargo fmt --check
cargo clippy --all-targets --release -- -D warnings
echo "test.sh: all checks passed"
