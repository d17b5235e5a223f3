#!/usr/bin/env bash
# Installs what building and testing tessera needs on Debian, when it is missing:
#   gcc               compiles the C tests and examples
#   libosmesa6-dev    Mesa's libOSMesa.so.8 (the reference implementation) and <GL/osmesa.h>
#   libgl1-mesa-dev   <GL/gl.h> and <GL/glext.h>
# and, with --test (tools/test.sh; the main job needs none of them):
#   chromium          opens tessera-compare's HTML report
#   xvfb piglit mesa-utils glew-utils freeglut3-dev x11-apps libx11-dev python3 pkg-config
#                     the GLX checks of tools/xvfb-tests.sh: a private X server, piglit's
#                     tests, glxinfo/glxgears, glewinfo, a freeglut program, xwd screenshots
#   libglfw3 libglfw3-dev
#                     tools/xvfb-tests.sh's GLFW check: tests/glx/glfw_window.c opens a GLFW
#                     window on tessera, as a plain GLFW program does
#   g++               builds libFuzzer for tools/fuzz.sh
#   valgrind          tools/memcheck.sh: capi tests under memcheck (invalid accesses, leaks)
#   python3-venv      tools/clients.sh: a virtual environment for PyOpenGL, MuJoCo, dm_control, glfw
# Runs `apt-get update` once (only if something is missing), as root or through sudo.
# The Rust toolchain is not installed here (Debian's is too old): see README.md.
set -euo pipefail

packages=(gcc libosmesa6-dev libgl1-mesa-dev)
if [[ ${1:-} == --test ]]; then
    packages+=(chromium xvfb piglit mesa-utils glew-utils freeglut3-dev x11-apps libx11-dev python3 pkg-config g++ valgrind
        libglfw3 libglfw3-dev python3-venv)
fi
missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done

if ((${#missing[@]})); then
    if [[ $(id -u) -eq 0 ]]; then
        as_root=()
    elif command -v sudo >/dev/null; then
        as_root=(sudo)
    else
        echo "setup-debian: need root or sudo to install: ${missing[*]}" >&2
        exit 1
    fi
    echo "setup-debian: installing ${missing[*]}"
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y "${missing[@]}"
else
    echo "setup-debian: ${packages[*]} already installed"
fi

if ! command -v cargo >/dev/null; then
    if [[ -x "$HOME/.cargo/bin/cargo" ]]; then
        echo "setup-debian: cargo is in ~/.cargo/bin but not on PATH: run 'source ~/.cargo/env'" >&2
    else
        echo "setup-debian: cargo not found: install Rust with rustup (https://rustup.rs), then 'source ~/.cargo/env'" >&2
    fi
    exit 1
fi
