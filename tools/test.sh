#!/usr/bin/env bash
# Everything CI checks: set-up, the release build (the drop-in libraries the capi tests
# load), the tests (Rust unit tests and tests/capi.rs, which runs every capi-tests/*.c on
# Mesa and on tessera; compare/tests/examples.rs, which runs tessera-compare on examples-c/
# against Mesa and opens its HTML report in headless chromium), formatting and clippy.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/setup-debian.sh --test   # --test: also chromium, for the HTML report check
cargo build --release
cargo test --release
cargo fmt --check
cargo clippy --all-targets --release -- -D warnings
echo "test.sh: all checks passed"
