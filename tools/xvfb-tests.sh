#!/usr/bin/env bash
# The GLX checks, on tessera's libGL.so.1 (target/release) under a private Xvfb:
#   1. glxinfo names tessera as the renderer and lists its extensions; glewinfo (glew-utils)
#      reports GL_VERSION_1_1 ... GL_VERSION_1_5 and every advertised extension as OK;
#   2. tests/glx/two_threads.c: two windows, two contexts, two threads render independently;
#      tests/glx/glx_api.c: the GLX API (configs, context rules, drawables, resizing, stereo);
#      tests/glx/read_drawable.c: reads from a separate read drawable;
#      tests/glx/glx_errors.c: GLX errors as X protocol errors, named in Xlib's error text;
#      tests/glx/context_notice.c: a refused glXCreateContextAttribsARB prints one line
#      naming the version asked for and the one provided (none with TESSERA_QUIET=1);
#      tests/glx/share_objects.c: share contexts share textures, buffers and display lists;
#      tests/glx/multisample.c: a 4-sample window's resolved edges;
#      tests/glx/glfw_window.c: a GLFW window (Debian's libglfw3) renders on tessera;
#   3. tests/glx/glut_scene.c (freeglut): a screenshot (xwd) shows the expected picture;
#   4. glxgears runs and its window shows the gears (not blank);
#   5. piglit: every command of ../shared/piglit/fragment-ops.txt is run; each one
#      tests/piglit/expected.txt marks "pass" must pass (a skip is not a pass).
#   6. piglit's framebuffer-object tests, further GL 1.x tests and the tests of the GL 2.x
#      features tessera has: each command tests/piglit/fbo-expected.txt, gl1x-expected.txt or
#      gl2x-expected.txt marks "pass" must pass.
# Needs xvfb, piglit, mesa-utils, freeglut3-dev, libglfw3-dev, x11-apps, libx11-dev, python3 (installed by
# tools/setup-debian.sh). Without them it skips loudly, except under CI=true where it fails.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
lib=${TESSERA_LIB_DIR:-$root/target/release}
piglit_bin=/usr/lib/x86_64-linux-gnu/piglit/bin
list=../shared/piglit/fragment-ops.txt
expected=tests/piglit/expected.txt

missing=()
for tool in Xvfb glxinfo glewinfo glxgears xwd gcc python3 pkg-config; do
    command -v "$tool" >/dev/null || missing+=("$tool")
done
[[ -x $piglit_bin/depthfunc ]] || missing+=("piglit")
[[ -f /usr/include/GL/glut.h ]] || missing+=("freeglut3-dev")
[[ -f /usr/include/GLFW/glfw3.h ]] || missing+=("libglfw3-dev")
[[ -f $list ]] || missing+=("$list")
[[ -e $lib/libGL.so.1 ]] || missing+=("$lib/libGL.so.1 (cargo build --release)")
if ((${#missing[@]})); then
    if [[ ${CI:-} == true ]]; then
        echo "xvfb-tests: FAILED: missing ${missing[*]}" >&2
        exit 1
    fi
    echo "xvfb-tests: SKIPPED (missing ${missing[*]}); CI=true makes this a failure" >&2
    exit 0
fi

work=$(mktemp -d)
xvfb_pid=
cleanup() {
    [[ -n $xvfb_pid ]] && kill "$xvfb_pid" 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT

# A private server on a free display number (-displayfd lets Xvfb pick and tell it).
Xvfb -displayfd 3 -noreset -nolisten tcp -screen 0 1024x768x24 3>"$work/display" 2>"$work/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 100); do
    [[ -s $work/display ]] && break
    sleep 0.1
done
[[ -s $work/display ]] || { echo "xvfb-tests: Xvfb did not start" >&2; cat "$work/xvfb.log" >&2; exit 1; }
export DISPLAY=:$(head -1 "$work/display")
export PIGLIT_PLATFORM=glx
echo "xvfb-tests: Xvfb on $DISPLAY"
on_tessera=(env "LD_LIBRARY_PATH=$lib")
# The GLX API tests provoke refusals on purpose: without their one-line notices on stderr
# (tests/glx/context_notice.c checks those).
quiet_on_tessera=(env "LD_LIBRARY_PATH=$lib" TESSERA_QUIET=1)
failures=0
fail() {
    echo "xvfb-tests: FAIL: $*" >&2
    failures=$((failures + 1))
}

# 1. glxinfo
if "${on_tessera[@]}" glxinfo >"$work/glxinfo.txt" 2>&1; then
    grep -q "OpenGL renderer string: tessera" "$work/glxinfo.txt" || fail "glxinfo does not name tessera"
    grep -q "GL_EXT_blend_minmax" "$work/glxinfo.txt" || fail "glxinfo lists no tessera extensions"
    grep -E "OpenGL (renderer|version) string" "$work/glxinfo.txt"
else
    fail "glxinfo exited with an error"
    tail -5 "$work/glxinfo.txt" >&2
fi

# 1b. glewinfo: GLEW's own check of every entry point of each core version and extension
if "${on_tessera[@]}" glewinfo >"$work/glewinfo.txt" 2>&1; then
    for v in 1_1 1_2 1_3 1_4 1_5; do
        grep -qE "^GL_VERSION_$v: +OK *$" "$work/glewinfo.txt" || fail "glewinfo: GL_VERSION_$v is not OK"
    done
    for ext in $(grep -oE '\bGL_[A-Za-z0-9_]+' "$work/glxinfo.txt" | sort -u); do
        if grep -qE "^$ext: " "$work/glewinfo.txt"; then
            grep -qE "^$ext: +OK *$" "$work/glewinfo.txt" || fail "glewinfo: $ext is advertised but not OK"
        fi
    done
    echo "glewinfo: GL_VERSION_1_1 ... 1_5 OK, $(grep -cE '^GL_[A-Za-z0-9_]+: +OK *$' "$work/glewinfo.txt") entries OK"
else
    fail "glewinfo exited with an error"
fi

# 2. two contexts, two windows, two threads
# (built with tessera's gl.pc: its headers and its libGL.so)
gl_flags=$(PKG_CONFIG_PATH=$lib/pkgconfig pkg-config --cflags --libs gl) || fail "no $lib/pkgconfig/gl.pc"
gcc -std=c11 -O1 -Wall -Werror tests/glx/two_threads.c $gl_flags -lX11 -lpthread -o "$work/two_threads"
"${quiet_on_tessera[@]}" timeout 60 "$work/two_threads" || fail "tests/glx/two_threads.c"

# The GLX API: configs, context rules, windows, resizing, pbuffers, pixmaps, stereo
gcc -std=c11 -O1 -Wall -Werror tests/glx/glx_api.c $gl_flags -lX11 -o "$work/glx_api"
"${quiet_on_tessera[@]}" timeout 60 "$work/glx_api" || fail "tests/glx/glx_api.c"
# A separate read drawable; GLX errors reach the X error handler (Xlib threaded or not)
gcc -std=c11 -O1 -Wall -Werror tests/glx/read_drawable.c $gl_flags -lX11 -o "$work/read_drawable"
"${on_tessera[@]}" timeout 60 "$work/read_drawable" || fail "tests/glx/read_drawable.c"
gcc -std=c11 -O1 -Wall -Werror tests/glx/glx_errors.c $gl_flags -lX11 -lpthread -o "$work/glx_errors"
"${quiet_on_tessera[@]}" timeout 60 "$work/glx_errors" || fail "tests/glx/glx_errors.c"
"${quiet_on_tessera[@]}" timeout 60 "$work/glx_errors" threads || fail "tests/glx/glx_errors.c threads"
# A refused glXCreateContextAttribsARB (3.3 core, asked twice): exactly one line on stderr
# naming what was asked and the version glxinfo reports; TESSERA_QUIET=1: no line.
gcc -std=c11 -O1 -Wall -Werror tests/glx/context_notice.c $gl_flags -lX11 -o "$work/context_notice"
provided=$(sed -n 's/^OpenGL version string: \([0-9]*\.[0-9]*\) tessera.*/\1/p' "$work/glxinfo.txt")
if env -u TESSERA_QUIET "${on_tessera[@]}" timeout 60 "$work/context_notice" 2>"$work/notice.err"; then
    want="tessera: glXCreateContextAttribsARB asked for OpenGL 3.3 core profile; tessera provides OpenGL ${provided:-?} (compatibility)"
    [[ $(wc -l <"$work/notice.err") == 1 && $(cat "$work/notice.err") == "$want" ]] ||
        fail "context_notice: stderr is not the one notice line \"$want\": $(cat "$work/notice.err")"
else
    fail "tests/glx/context_notice.c"
fi
"${on_tessera[@]}" TESSERA_QUIET=1 timeout 60 "$work/context_notice" 2>"$work/notice.err" >/dev/null ||
    fail "tests/glx/context_notice.c with TESSERA_QUIET=1"
[[ ! -s $work/notice.err ]] || fail "context_notice printed with TESSERA_QUIET=1: $(cat "$work/notice.err")"
# Share contexts share texture objects, buffer objects and display lists
gcc -std=c11 -O1 -Wall -Werror tests/glx/share_objects.c $gl_flags -lX11 -o "$work/share_objects"
"${on_tessera[@]}" timeout 60 "$work/share_objects" || fail "tests/glx/share_objects.c"
# The same two programs presenting with XPutImage instead of MIT-SHM
"${quiet_on_tessera[@]}" TESSERA_XSHM=0 timeout 60 "$work/two_threads" || fail "two_threads.c with TESSERA_XSHM=0"
"${quiet_on_tessera[@]}" TESSERA_XSHM=0 timeout 60 "$work/glx_api" || fail "glx_api.c with TESSERA_XSHM=0"
# A multisampled (4-sample) window: resolved edges in glReadPixels and on the screen
gcc -std=c11 -O1 -Wall -Werror tests/glx/multisample.c $gl_flags -lX11 -o "$work/multisample"
"${quiet_on_tessera[@]}" timeout 60 "$work/multisample" || fail "tests/glx/multisample.c"

# GLFW (Debian's libglfw3): a window with default hints renders on tessera, and an OpenGL 2.0
# request is answered as tessera's version allows. Linked with libglfw only: GLFW dlopens
# the GL library (Debian's 3.3: libGL.so.1; GLFW 3.4: libGLX.so.0 first, which
# target/release must then provide), so the renderer string tells that tessera answered.
gcc -std=c11 -O1 -Wall -Werror tests/glx/glfw_window.c -lglfw -o "$work/glfw_window"
if "${quiet_on_tessera[@]}" timeout 60 "$work/glfw_window" >"$work/glfw.out" 2>&1; then
    grep -q "GL_RENDERER = tessera" "$work/glfw.out" || fail "GLFW's context is not tessera's"
    grep "^glfw_window:" "$work/glfw.out"
else
    fail "tests/glx/glfw_window.c"
    cat "$work/glfw.out" >&2
fi

# The install layout: Debian's libGLU reaches tessera through libOpenGL.so.0.
glu=$(ldconfig -p 2>/dev/null | awk '/libGLU.so.1 / {print $NF}' | head -1 || true)
if [[ -n $glu ]]; then
    # (ldd's output captured first: `grep -q` ending the pipe early fails it under pipefail)
    glu_libs=$("${on_tessera[@]}" ldd "$glu" || true)
    grep -q "libOpenGL.so.0 => $lib/libOpenGL.so.0" <<<"$glu_libs" ||
        fail "libGLU does not load tessera's libOpenGL.so.0"
fi
[[ -e $lib/libOSMesa.so && -e $lib/pkgconfig/osmesa.pc ]] || fail "libOSMesa.so or osmesa.pc missing"

# Programs linked with immediate binding (Debian builds glxgears and libglut with -z now)
# cannot even start while a GL function they import is missing from tessera. For the
# functions tessera does not export yet (display lists, lighting, glBitmap: other issues),
# a preloaded library of no-op stubs returning 0 is built, with only those names, so it
# never hides a real tessera entry point; the list is printed.
stub_missing() {
    local name=$1
    shift
    local missing=()
    nm -D --defined-only "$lib/libGL.so.1" | awk '{print $3}' >"$work/tessera-symbols.txt"
    for symbol in $(nm -D --undefined-only "$@" | awk '{print $2}' | sed 's/@.*//' | grep '^gl[A-Z]' | sort -u); do
        grep -qx "$symbol" "$work/tessera-symbols.txt" || missing+=("$symbol")
    done
    : >"$work/$name-stubs.c"
    for symbol in "${missing[@]}"; do echo "long $symbol(void) { return 0; }" >>"$work/$name-stubs.c"; done
    gcc -shared -fPIC "$work/$name-stubs.c" -o "$work/lib$name-stubs.so"
    echo "xvfb-tests: $name: GL functions not in tessera yet, stubbed: ${missing[*]:-none}"
}

# Runs a windowed program in the background until it printed `marker` (or 20 s passed),
# takes a screenshot of the window named `name` into $work/<name>.xwd, then stops it.
screenshot_program() {
    local name=$1 marker=$2
    shift 2
    "${on_tessera[@]}" "$@" >"$work/$name.out" 2>&1 &
    local pid=$!
    for _ in $(seq 200); do
        grep -q "$marker" "$work/$name.out" 2>/dev/null && break
        kill -0 $pid 2>/dev/null || break
        sleep 0.1
    done
    sleep 0.5
    local ok=0
    xwd -silent -name "$name" -out "$work/$name.xwd" || ok=1
    if ! kill -0 $pid 2>/dev/null; then
        echo "xvfb-tests: $name exited early:" >&2
        cat "$work/$name.out" >&2
        ok=1
    fi
    kill $pid 2>/dev/null || true
    wait $pid 2>/dev/null || true
    return $ok
}

# 3. freeglut: the picture at known places (see tests/glx/glut_scene.c; window 300x300)
gcc -std=c11 -O1 -Wall -Werror tests/glx/glut_scene.c -lglut -lGL -o "$work/glut_scene"
stub_missing glut "$work/glut_scene" "$(ldd "$work/glut_scene" | awk '/libglut/ {print $3}')"
if screenshot_program "tessera glut_scene" "frame shown" env LD_PRELOAD="$work/libglut-stubs.so" "$work/glut_scene"; then
    cp "$work/tessera glut_scene.xwd" "$work/glut_scene.xwd"
    python3 tools/xwd_check.py "$work/glut_scene.xwd" not-blank \
        pixel 75 30 0 0 153 1 \
        pixel 225 75 0 255 0 1 \
        pixel 270 225 128 128 77 2 \
        pixel 75 250 180 140 60 100 || fail "glut_scene's window does not show its picture"
else
    fail "glut_scene did not run"
fi

# 4. glxgears: lit gears compiled into display lists; the window must show them.
stub_missing glxgears "$(command -v glxgears)"
if screenshot_program glxgears "GL_RENDERER" env LD_PRELOAD="$work/libglxgears-stubs.so" glxgears -info; then
    grep -q "GL_RENDERER *= tessera" "$work/glxgears.out" || fail "glxgears does not run on tessera"
    python3 tools/xwd_check.py "$work/glxgears.xwd" not-blank || fail "glxgears' window is blank"
    cp "$work/glxgears.xwd" target/glxgears.xwd 2>/dev/null || true
else
    fail "glxgears did not run"
fi

# 5. piglit
declare -A want
while read -r status command; do
    [[ -z $status || $status == \#* ]] && continue
    command=${command%%#*}
    command=$(echo $command)
    want[$command]=$status
done <"$expected"
declare -A count=()
unexpected_passes=()
while IFS= read -r line; do
    [[ -z $line || $line == \#* ]] && continue
    command=$(echo ${line%%#*})
    output=$(cd "$piglit_bin" && "${on_tessera[@]}" timeout 120 ./$command 2>&1) || true
    result=$(grep -o '"result": *"[a-z]*"' <<<"$output" | tail -1 | sed 's/.*"\([a-z]*\)"$/\1/' || true)
    result=${result:-crash}
    count[$result]=$((${count[$result]:-0} + 1))
    case ${want[$command]:-} in
    pass) [[ $result == pass ]] || fail "piglit $command: $result (expected pass)" ;;
    excluded)
        [[ $result == pass ]] && unexpected_passes+=("$command")
        [[ $result == pass ]] || echo "xvfb-tests: piglit $command: $result (excluded)"
        ;;
    *) fail "piglit $command is not in $expected" ;;
    esac
done <"$list"
summary=""
for r in "${!count[@]}"; do summary+="$r=${count[$r]} "; done
echo "xvfb-tests: piglit summary: $summary(expected to pass: $(grep -c '^pass' "$expected"))"
for c in "${unexpected_passes[@]}"; do
    echo "xvfb-tests: piglit $c now passes: mark it 'pass' in $expected"
done

# 6. piglit's framebuffer-object tests, further GL 1.x tests and the GL 2.x
#    feature tests: every command of tests/piglit/fbo-expected.txt, gl1x-expected.txt and gl2x-expected.txt
#    (the GL 2.x file takes about 15 s on tessera, so CI runs all of it).
for expectations in tests/piglit/fbo-expected.txt tests/piglit/gl1x-expected.txt tests/piglit/gl2x-expected.txt; do
    passed=0
    while read -r status command; do
        [[ -z $status || $status == \#* ]] && continue
        command=$(echo ${command%%#*})
        output=$(cd "$piglit_bin" && "${on_tessera[@]}" timeout 120 ./$command 2>&1) || true
        result=$(grep -o '"result": *"[a-z]*"' <<<"$output" | tail -1 | sed 's/.*"\([a-z]*\)"$/\1/' || true)
        result=${result:-crash}
        case $status in
        pass)
            [[ $result == pass ]] && passed=$((passed + 1))
            [[ $result == pass ]] || fail "piglit $command: $result (expected pass)"
            ;;
        *) [[ $result == pass ]] && echo "xvfb-tests: piglit $command now passes: mark it 'pass' in $expectations" ;;
        esac
    done <"$expectations"
    echo "xvfb-tests: piglit $(basename "$expectations" -expected.txt) tests: $passed passed (expected: $(grep -c '^pass' "$expectations"))"
done

if ((failures)); then
    echo "xvfb-tests: $failures check(s) FAILED" >&2
    exit 1
fi
echo "xvfb-tests: all GLX checks passed"
