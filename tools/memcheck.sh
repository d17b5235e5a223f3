#!/usr/bin/env bash
# Runs a representative subset of the capi tests on tessera under valgrind memcheck: no
# invalid read or write, no use of uninitialised memory, and no block lost (definitely or
# indirectly) at exit, so nothing leaks after OSMesaDestroyContext (reliability_leaks runs
# create/draw/destroy cycles with every kind of object). Valgrind rather than
# AddressSanitizer: tessera is a Rust cdylib built by stable Rust, which cannot instrument it
# (-Zsanitizer is nightly-only); LD_PRELOADing libasan into the C programs would check the C
# side and the leaks but not tessera's own memory accesses, which memcheck sees at the
# machine-code level. The subset: each test takes 5-10 s under memcheck (about 30x slower),
# so the whole capi suite would take over 10 minutes; these cover every pipeline stage,
# every vertex source, textures, pixel rectangles, selection/feedback, display lists and
# buffer objects, context creation, sharing and threads (about 2 minutes on 2 cores).
# Usage: bash tools/memcheck.sh [test ...]   (needs a release build: cargo build --release)
set -euo pipefail
cd "$(dirname "$0")/.."

tests=("$@")
if ((${#tests[@]} == 0)); then
    tests=(reliability_leaks reliability_threads draw_primitives draw_clipping vertex_arrays vertex_buffers display_lists
        texture_sampling texture_formats pixel_rects readpixels_pack fragment_ops_blend lighting_render
        feedback_mode select_mode accum osmesa_makecurrent osmesa_threads osmesa_workers osmesa_formats osmesa_free_then_destroy errors_nocontext)
fi
command -v valgrind >/dev/null || { echo "memcheck: valgrind not installed (tools/setup-debian.sh --test)" >&2; exit 1; }
[[ -e target/release/libOSMesa.so.8 ]] || { echo "memcheck: no release build (cargo build --release)" >&2; exit 1; }

out=target/memcheck
mkdir -p "$out"
failed=()
for test in "${tests[@]}"; do
    gcc -std=c11 -O1 -g -Wall -Werror -I capi-tests "capi-tests/$test.c" capi-tests/common.c \
        -lOSMesa -lm -lpthread -o "$out/$test"
    mkdir -p "$out/$test.out"
    start=$SECONDS
    # CAPI_CYCLES: reliability_leaks' cycles (valgrind reports every lost block at exit, a
    # few cycles suffice). TESSERA_THREADS=2: the rasterizer's workers run too.
    if CAPI_OUT="$out/$test.out" CAPI_CYCLES=20 TESSERA_THREADS=2 LD_LIBRARY_PATH=target/release \
        valgrind --quiet --error-exitcode=99 --leak-check=full --show-leak-kinds=definite,indirect \
        --errors-for-leak-kinds=definite,indirect --track-origins=yes \
        --suppressions=tools/memcheck.supp "$out/$test" >"$out/$test.log" 2>&1; then
        echo "memcheck: $test ok ($((SECONDS - start)) s)"
    else
        echo "memcheck: $test FAILED ($((SECONDS - start)) s): $out/$test.log"
        grep -v '^VALUE' "$out/$test.log" | head -40
        failed+=("$test")
    fi
done
if ((${#failed[@]})); then
    echo "memcheck: ${#failed[@]} failed: ${failed[*]}"
    exit 1
fi
echo "memcheck: ${#tests[@]} tests clean"
