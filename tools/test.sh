#!/usr/bin/env bash
# Everything CI checks: set-up, the release build (the drop-in libraries the capi tests
# load), the tests (Rust unit tests and tests/capi.rs, which runs every capi-tests/*.c on
# Mesa and on tessera; tests/simd_levels.rs, which renders the capi tests and examples at
# every TESSERA_SIMD level the CPU has on 1 and 2 threads and compares the bytes (about a
# minute on 2 cores); compare/tests/examples.rs, which runs tessera-compare on examples-c/
# against Mesa and opens its HTML report in headless chromium), the GLX checks under Xvfb
# (tools/xvfb-tests.sh, piglit included), a sample of piglit's GLSL tests (tools/piglit-glsl.py), real Python clients (tools/clients.sh), the fuzz targets (tools/fuzz.sh), formatting and clippy.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/setup-debian.sh --test   # --test: also chromium, for the HTML report check
cargo build --release
# The engine's unit tests are built without LTO and in 16 codegen units, in a target directory
# of their own: their one large test binary took over 7 CPU minutes to link with fat LTO, and
# LTO changes no result (no fast-math, no FMA contraction). Everything that loads the shipped
# libraries (the capi comparison against Mesa, the SIMD-level byte comparison, GLX, clients,
# piglit) uses the LTO build `cargo build --release` left in target/release.
CARGO_PROFILE_RELEASE_LTO=off CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16 CARGO_TARGET_DIR=target/unit-tests \
    cargo test --release -p tessera --lib
cargo test --release -p tessera --test '*'
cargo test --release -p tessera --doc
cargo test --release --workspace --exclude tessera
# A subset of the capi tests under valgrind memcheck: invalid accesses, leaks (about 2 min).
bash tools/memcheck.sh
bash tools/xvfb-tests.sh   # GLX under a private Xvfb: glxinfo, glxgears, freeglut, two threads, piglit
# Real clients from PyPI (PyOpenGL, MuJoCo, dm_control, glfw) in a cached venv, on tessera.
bash tools/clients.sh
# piglit's GLSL 1.10/1.20 tests: a fixed sample of 150 against tests/piglit/glsl-expected.txt
# (the full sets: python3 tools/piglit-glsl.py; README, "GLSL conformance").
python3 tools/piglit-glsl.py --sample 150
# Fuzzing (fuzz/): past findings replayed, then 90 s of command streams and 45 s of GLSL
# shaders (libFuzzer).
bash tools/fuzz.sh 90
# A smoke run of the benchmark (64x64, one frame per scene: seconds; writes target/bench/quick).
bash tools/bench.sh --quick
cargo fmt --check
cargo clippy --all-targets --release -- -D warnings
echo "test.sh: all checks passed"
