#!/usr/bin/env bash
# Builds the fuzz targets (fuzz/, libFuzzer with sanitizer coverage, debug assertions and
# overflow checks on) and runs them:
#   bash tools/fuzz.sh [SECONDS]    default 120; CI runs 90
# command_stream (GL/OSMesa call streams) runs SECONDS seconds, then glsl_front_end (shader
# sources through compile, link and lowering) SECONDS/2 seconds.
# First the past findings are replayed (fuzz/regressions/ for command_stream,
# fuzz/glsl-regressions/ for glsl_front_end: each must pass), then each target mutates its
# seeds: fuzz/corpus/command_stream, and for glsl_front_end fuzz/corpus/glsl_front_end plus
# the shaders of piglit's GLSL 1.10/1.20 tests, extracted here from the installed piglit
# (target/fuzz/glsl-seeds; none when piglit is missing, except that CI requires it). New
# corpus entries go to target/fuzz/corpus and target/fuzz/glsl-corpus (the committed seeds
# stay as they are); a finding is written to target/fuzz/artifacts/ and the script fails:
# copy it into the regressions once fixed. Longer runs: `bash tools/fuzz.sh 3600`, or pass
# libFuzzer options through FUZZ_ARGS (e.g. FUZZ_ARGS=-jobs=2).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-120}"

host=$(rustc -vV | sed -n 's/^host: //p')
# The flags cargo fuzz uses for libFuzzer's coverage; --target keeps them off build scripts.
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
cargo build --release --manifest-path fuzz/Cargo.toml --target "$host" --target-dir target/fuzz \
    --bin command_stream --bin glsl_front_end
binary="target/fuzz/$host/release/command_stream"
glsl_binary="target/fuzz/$host/release/glsl_front_end"
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

# The GLSL front end. Seeds: piglit's shaders, one file per shader.
glsl_seconds=$((seconds / 2))
piglit_spec=/usr/lib/x86_64-linux-gnu/piglit/tests/spec
seeds=target/fuzz/glsl-seeds
rm -rf "$seeds"
mkdir -p "$seeds" target/fuzz/glsl-corpus
if [[ -d $piglit_spec/glsl-1.10 ]]; then
    python3 - "$piglit_spec" "$seeds" <<'PY'
import pathlib, sys
spec, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
n = 0
for version in ("glsl-1.10", "glsl-1.20"):
    for path in sorted((spec / version).rglob("*")):
        if path.suffix in (".vert", ".frag"):
            shaders = [path.read_text(errors="replace")]
        elif path.suffix == ".shader_test":
            shaders, current = [], None
            for line in path.read_text(errors="replace").splitlines(keepends=True):
                if line.startswith("["):
                    current = [] if line.strip() in ("[vertex shader]", "[fragment shader]") else None
                    if current is not None:
                        shaders.append(current)
                elif current is not None:
                    current.append(line)
            shaders = ["".join(s) for s in shaders]
        else:
            continue
        for text in shaders:
            if text.strip() and len(text) < 16384:
                (out / f"{n:05}").write_text(text)
                n += 1
print(f"fuzz: {n} piglit shaders as glsl_front_end seeds")
PY
elif [[ ${CI:-} == true ]]; then
    echo "fuzz: piglit is missing ($piglit_spec): CI seeds the GLSL fuzzer with its shaders" >&2
    exit 1
else
    echo "fuzz: piglit is not installed; glsl_front_end starts from fuzz/corpus/glsl_front_end only"
fi
regressions=(fuzz/glsl-regressions/*)
if [[ -e "${regressions[0]}" ]]; then
    echo "fuzz: replaying ${#regressions[@]} GLSL regression input(s)"
    "$glsl_binary" "${regressions[@]}"
fi
echo "fuzz: running glsl_front_end for ${glsl_seconds} s"
"$glsl_binary" -max_total_time="$glsl_seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 \
    -artifact_prefix=target/fuzz/artifacts/ ${FUZZ_ARGS:-} target/fuzz/glsl-corpus fuzz/corpus/glsl_front_end "$seeds" 2>&1 |
    grep -v -E '^#[0-9]+\s+(NEW|REDUCE|pulse)|NEW_FUNC' || { status=${PIPESTATUS[0]}; exit "$status"; }
status=${PIPESTATUS[0]}
if [[ $status -ne 0 ]]; then
    echo "fuzz: FINDING in glsl_front_end (libFuzzer exit $status); the input is in target/fuzz/artifacts/" >&2
    exit "$status"
fi
echo "fuzz: no finding in glsl_front_end in ${glsl_seconds} s"
