#!/usr/bin/env bash
# The benchmark: tessera in every accuracy mode (1 thread and all cores) against Mesa's
# llvmpipe and softpipe, in one run where the implementations alternate; writes
# BENCHMARKS.md and bench-error-vs-time.svg (see the README, "Benchmark").
#
#   bash tools/bench.sh            # the full run (1024x1024; minutes)
#   bash tools/bench.sh --quick    # a smoke run (64x64, one repetition) into target/bench/quick
#
# Besides the scenes (tools/bench/bench.c) it measures the size of the shipped libraries, the
# cost of immediate-mode calls (tools/bench/immediate.c) and MuJoCo's renderer per frame
# (tools/clients/mujoco_compare.py, when the clients venv of tools/clients.sh exists), tessera
# alternating with llvmpipe in each, and the error of tessera's transcendental functions
# (examples/math_errors.rs).
#
# Knobs: BENCH_SIZE (window side), BENCH_REPS (timed frames per scene and process),
# BENCH_ROUNDS (processes per implementation, alternating), BENCH_SOFTPIPE_REPS,
# BENCH_MUJOCO_FRAMES (timed MuJoCo frames per process), BENCH_VENV (the python of a venv
# with mujoco; default target/clients-venv).
set -euo pipefail
cd "$(dirname "$0")/.."

size=${BENCH_SIZE:-1024}
reps=${BENCH_REPS:-5}
rounds=${BENCH_ROUNDS:-3}
softpipe_reps=${BENCH_SOFTPIPE_REPS:-1}
mujoco_frames=${BENCH_MUJOCO_FRAMES:-3}
immediate_calls=2000000
venv=${BENCH_VENV:-target/clients-venv}
out=target/bench/run
markdown=BENCHMARKS.md
svg=bench-error-vs-time.svg
if [[ "${1:-}" == "--quick" ]]; then
    size=64 reps=1 rounds=1 softpipe_reps=1 mujoco_frames=1 immediate_calls=200000
    out=target/bench/quick
    markdown=$out/BENCHMARKS.md
    svg=$out/bench-error-vs-time.svg
fi

cargo build --release --quiet
mkdir -p target/bench
gcc -std=c11 -O2 -Wall -Werror tools/bench/bench.c -lOSMesa -lm -o target/bench/bench
gcc -std=c11 -O2 -Wall -Werror tools/bench/immediate.c -lOSMesa -o target/bench/immediate
rm -rf "$out"
mkdir -p "$out"

cores=$(nproc)
lib=$(pwd)/target/release
# name|environment (run with `env -u LD_LIBRARY_PATH`, then these assignments)
impls=("llvmpipe|GALLIUM_DRIVER=llvmpipe" "softpipe|GALLIUM_DRIVER=softpipe")
for mode in fast conformant exact; do
    impls+=("tessera-$mode-1t|LD_LIBRARY_PATH=$lib TESSERA_THREADS=1 TESSERA_ACCURACY=$mode")
    impls+=("tessera-$mode-${cores}t|LD_LIBRARY_PATH=$lib TESSERA_THREADS=$cores TESSERA_ACCURACY=$mode")
done

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for ((round = 1; round <= rounds; round++)); do
    for impl in "${impls[@]}"; do
        name=${impl%%|*}
        assignments=${impl#*|}
        n=$reps
        [[ $name == softpipe ]] && n=$softpipe_reps
        mkdir -p "$out/$name"
        echo "bench: round $round/$rounds: $name" >&2
        # shellcheck disable=SC2086
        env -u LD_LIBRARY_PATH $assignments ./target/bench/bench "$out/$name" "$n" "$size" >"$out/$name/round$round.txt"
    done
done

# Extras live in files (and mujoco/): report.py takes the folders with round*.txt for implementations.
for name in libOSMesa.so.8 libGL.so.1; do
    echo "$name $(stat -L -c %s "$lib/$name")"
done >"$out/sizes.txt"
for ((round = 1; round <= rounds; round++)); do
    echo "bench: round $round/$rounds: immediate-mode calls" >&2
    env -u LD_LIBRARY_PATH GALLIUM_DRIVER=llvmpipe ./target/bench/immediate "$immediate_calls" >"$out/immediate-llvmpipe-round$round.txt"
    env LD_LIBRARY_PATH="$lib" TESSERA_THREADS="$cores" ./target/bench/immediate "$immediate_calls" >"$out/immediate-tessera-round$round.txt"
done
if [[ -x $venv/bin/python ]]; then
    for ((round = 1; round <= rounds; round++)); do
        echo "bench: round $round/$rounds: MuJoCo (tessera, then llvmpipe)" >&2
        # A picture that differs from Mesa's is the capi/clients tests' business, not this one's.
        "$venv/bin/python" tools/clients/mujoco_compare.py --lib "$lib" --out "$out/mujoco" --frames "$mujoco_frames" \
            --default-shadows --compare-with-mesa --json "$out/mujoco-round$round.json" >&2 || true
    done
else
    echo "bench: no $venv/bin/python (tools/clients.sh builds it): MuJoCo not measured" >&2
fi
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
echo "bench: transcendental function errors" >&2
cargo run --release --quiet --example math_errors >"$out/math-errors.md"

python3 tools/bench/report.py --dir "$out" --size "$size" --cores "$cores" --reps "$reps" --rounds "$rounds" \
    --load "$load_before" --load-after "$load_after" --markdown "$markdown" --svg "$svg"
echo "bench: wrote $markdown and $svg" >&2
