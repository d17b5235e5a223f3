#!/usr/bin/env bash
# Builds the command-stream fuzz target (fuzz/, libFuzzer with sanitizer coverage, debug
# assertions and overflow checks on) and runs it:
#   bash tools/fuzz.sh [SECONDS]    default 120; CI runs the default
# First every file of fuzz/regressions/ is replayed (past findings: each must pass), then
# the target mutates the seed corpus fuzz/corpus/command_stream for SECONDS seconds. New
# corpus entries go to target/fuzz/corpus (the committed seeds stay as they are); a
# finding is written to target/fuzz/artifacts/ and the script fails: copy it into
# fuzz/regressions/ once fixed. Longer runs: `bash tools/fuzz.sh 3600`, or pass libFuzzer
# options through FUZZ_ARGS (e.g. FUZZ_ARGS=-jobs=2).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-120}"

host=$(rustc -vV | sed -n 's/^host: //p')
# The flags cargo fuzz uses for libFuzzer's coverage; --target keeps them off build scripts.
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
cargo build --release --manifest-path fuzz/Cargo.toml --target "$host" --target-dir target/fuzz --bin command_stream
binary="target/fuzz/$host/release/command_stream"
if [[ $seconds == --build-only ]]; then
    exit 0   # tools/fuzz-seeds.sh: the build (and its generated seed_shim.c) only
fi

mkdir -p target/fuzz/corpus target/fuzz/artifacts
regressions=(fuzz/regressions/*)
if [[ -e "${regressions[0]}" ]]; then
    echo "fuzz: replaying ${#regressions[@]} regression input(s)"
    "$binary" "${regressions[@]}"
fi
echo "fuzz: running command_stream for ${seconds} s"
# -rss_limit_mb: a hostile size must fail with GL_OUT_OF_MEMORY, not eat the machine.
"$binary" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 -max_len=16384 -print_final_stats=1 \
    -artifact_prefix=target/fuzz/artifacts/ ${FUZZ_ARGS:-} target/fuzz/corpus fuzz/corpus/command_stream 2>&1 |
    grep -v -E '^#[0-9]+\s+(NEW|REDUCE|pulse)|NEW_FUNC' || { status=${PIPESTATUS[0]}; exit "$status"; }
status=${PIPESTATUS[0]}
if [[ $status -ne 0 ]]; then
    echo "fuzz: FINDING (libFuzzer exit $status); the input is in target/fuzz/artifacts/" >&2
    exit "$status"
fi
echo "fuzz: no finding in ${seconds} s"
