#!/usr/bin/env bash
# Regenerates the capi-derived seeds of the fuzz corpus (fuzz/corpus/command_stream/capi-*):
# every capi test runs on tessera with fuzz/build.rs's seed_shim.c preloaded, which writes
# each GL call the test makes (those the decoder can make from a prototype: state, vertices,
# matrices, textures, lists, queries, ...) as the bytes that make the command_stream decoder
# repeat it. Each test gives two seeds of at most 3 KiB cut at call boundaries: its first
# calls and calls from its middle (about 260 KiB in all). Needs a release build of tessera.
# Usage: bash tools/fuzz-seeds.sh
set -euo pipefail
cd "$(dirname "$0")/.."
host=$(rustc -vV | sed -n 's/^host: //p')
bash tools/fuzz.sh --build-only
shim_source=$(ls -t target/fuzz/"$host"/release/build/tessera-fuzz-*/out/seed_shim.c | head -1)
work=target/fuzz/seeds
rm -rf "$work"
mkdir -p "$work/bin" "$work/out"
gcc -shared -fPIC -O1 -w -I include -o "$work/seed_shim.so" "$shim_source" -ldl
rm -f fuzz/corpus/command_stream/capi-*
for source in capi-tests/*.c; do
    test=$(basename "$source" .c)
    [[ $test == common ]] && continue
    gcc -std=c11 -O1 -I capi-tests "$source" capi-tests/common.c -lOSMesa -lm -lpthread -o "$work/bin/$test"
    mkdir -p "$work/out/$test"
    CAPI_OUT="$work/out/$test" CAPI_CYCLES=3 TESSERA_FUZZ_SEED="$work/$test.stream" LD_PRELOAD="$PWD/$work/seed_shim.so" \
        LD_LIBRARY_PATH=target/release timeout 120 "$work/bin/$test" >/dev/null 2>&1 || true
    [[ -s $work/$test.stream ]] || continue
    python3 - "$work/$test.stream" "fuzz/corpus/command_stream/capi-$test" <<'PY'
import sys
stream, prefix = sys.argv[1], sys.argv[2]
data = open(stream, "rb").read()
starts = [int(line) for line in open(stream + ".calls")] + [len(data)]
LIMIT = 3072
def chunk(first):
    """Calls from index `first` on, as long as they fit in LIMIT bytes."""
    last = first
    while last + 1 < len(starts) and starts[last + 1] - starts[first] <= LIMIT:
        last += 1
    return data[starts[first]:starts[last]]
calls = len(starts) - 1
seeds = [chunk(0)]
if calls > 2 * len(seeds[0]) // 20:
    seeds.append(chunk(calls // 2))
for k, seed in enumerate(seeds):
    if seed:
        open(f"{prefix}-{k}", "wb").write(seed)
PY
done
echo "fuzz-seeds: $(ls fuzz/corpus/command_stream/capi-* | wc -l) seeds, $(cat fuzz/corpus/command_stream/capi-* | wc -c) bytes"
