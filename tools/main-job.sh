#!/usr/bin/env bash
# The main job: sets up the machine, builds tessera's drop-in libraries, then builds every
# examples-c/*.c against the system's Mesa headers and runs it on tessera
# (LD_LIBRARY_PATH=target/release). The examples write their pictures to out/.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/setup-debian.sh
cargo build --release

mkdir -p out target/examples
for source in examples-c/*.c; do
    name=$(basename "$source" .c)
    gcc -std=c11 -O2 -Wall -Werror -I examples-c "$source" -o "target/examples/$name" -lOSMesa -lm
    echo "main-job: running $name on tessera"
    LD_LIBRARY_PATH="$PWD/target/release${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "target/examples/$name" out
done

echo "main-job: pictures written to $PWD/out/:"
ls -1 out/*.png
echo "main-job: to compare them with Mesa (HTML report): target/release/tessera-compare --impl llvmpipe --impl tessera --html out/report examples-c"
