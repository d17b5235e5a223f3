#!/usr/bin/env bash
# The benchmark: tessera in every accuracy mode (1 thread and all cores) against Mesa's
# llvmpipe and softpipe, in one run where the implementations alternate; writes
# BENCHMARKS.md and bench-error-vs-time.svg (see the README, "Benchmark").
#
#   bash tools/bench.sh            # the full run (1024x1024; minutes)
#   bash tools/bench.sh --quick    # a smoke run (64x64, one repetition) into target/bench/quick
#
# Knobs: BENCH_SIZE (window side), BENCH_REPS (timed frames per scene and process),
# BENCH_ROUNDS (processes per implementation, alternating), BENCH_SOFTPIPE_REPS.
set -euo pipefail
cd "$(dirname "$0")/.."

size=${BENCH_SIZE:-1024}
reps=${BENCH_REPS:-5}
rounds=${BENCH_ROUNDS:-3}
softpipe_reps=${BENCH_SOFTPIPE_REPS:-1}
out=target/bench/run
markdown=BENCHMARKS.md
svg=bench-error-vs-time.svg
if [[ "${1:-}" == "--quick" ]]; then
    size=64 reps=1 rounds=1 softpipe_reps=1
    out=target/bench/quick
    markdown=$out/BENCHMARKS.md
    svg=$out/bench-error-vs-time.svg
fi

cargo build --release --quiet
mkdir -p target/bench
gcc -std=c11 -O2 -Wall -Werror tools/bench/bench.c -lOSMesa -lm -o target/bench/bench
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
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

python3 tools/bench/report.py --dir "$out" --size "$size" --cores "$cores" --reps "$reps" --rounds "$rounds" \
    --load "$load_before" --load-after "$load_after" --markdown "$markdown" --svg "$svg"
echo "bench: wrote $markdown and $svg" >&2
