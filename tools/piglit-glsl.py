#!/usr/bin/env python3
"""piglit's GLSL 1.10/1.20 tests on tessera and on Mesa (issue #20).

The tests: `spec@glsl-1.10@execution` and `spec@glsl-1.20@execution` (shader_runner, from
piglit's `shader` profile) and `spec@glsl-1.10@compiler` and `spec@glsl-1.20@compiler`
(glslparsertest, from the `glslparser` profile), read from the installed piglit's test lists.
Each runs under a private Xvfb with PIGLIT_PLATFORM=glx, on tessera (LD_LIBRARY_PATH=<lib>)
or on Mesa (the system's libGL, llvmpipe).

Expectations: tests/piglit/glsl-expected.txt, one line per test:

    <tessera result> <Mesa result> <test name>   # reason, required when Mesa passes and tessera does not

Usage:
    tools/piglit-glsl.py                    # every test on tessera, checked against the file
    tools/piglit-glsl.py --sample 150       # a fixed sample (every k-th test by name): CI
    tools/piglit-glsl.py --update           # every test on tessera and Mesa; rewrites the file,
                                            # keeping the reasons of lines whose results did not change
    tools/piglit-glsl.py --mesa-only        # every test on Mesa (--update reuses these results)
Checking fails when a test the file expects to pass does not, or a test is missing from the
file; a test that now passes where the file expected otherwise is reported (update the file).
Results and each test's output go to target/piglit-glsl/.
"""
import argparse
import concurrent.futures
import gzip
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

PIGLIT = pathlib.Path("/usr/lib/x86_64-linux-gnu/piglit")
GROUPS = {
    "shader.xml.gz": ("spec@glsl-1.10@execution", "spec@glsl-1.20@execution"),
    "glslparser.xml.gz": ("spec@glsl-1.10@compiler", "spec@glsl-1.20@compiler"),
}
ROOT = pathlib.Path(__file__).resolve().parent.parent
EXPECTED = ROOT / "tests/piglit/glsl-expected.txt"
OUT = ROOT / "target/piglit-glsl"
RESULT = re.compile(r'"result":\s*"([a-z]+)"')


def tests():
    """(name, argv) of every test, sorted by name."""
    found = []
    for list_file, prefixes in GROUPS.items():
        root = ET.parse(gzip.open(PIGLIT / "tests" / list_file)).getroot()
        for t in root:
            name = t.get("name")
            if not name.startswith(tuple(p + "@" for p in prefixes)):
                continue
            options = {o.get("name"): o.get("value") for o in t}
            argv = eval(options["command"], {"__builtins__": {}})  # a Python list literal
            if argv[0] == "shader_runner":
                argv = argv + ["-auto", "-fbo"]
            found.append((name, argv))
    return sorted(found)


def run_one(name, argv, env, log_dir):
    command = [str(PIGLIT / "bin" / argv[0])] + argv[1:]
    try:
        p = subprocess.run(command, cwd=PIGLIT, env=env, capture_output=True, text=True, errors="replace", timeout=60)
        output = p.stdout + p.stderr
        found = RESULT.findall(output)
        result = found[-1] if found else ("crash" if p.returncode != 0 else "fail")
    except subprocess.TimeoutExpired as e:
        output = f"timeout after 60 s\n{e.stdout or ''}{e.stderr or ''}"
        result = "timeout"
    (log_dir / (name.replace("@", "_") + ".log")).write_text(output if isinstance(output, str) else str(output))
    return result


def run_all(selected, impl, lib, jobs):
    env = dict(os.environ, PIGLIT_PLATFORM="glx")
    if impl == "tessera":
        env.update(LD_LIBRARY_PATH=str(lib), TESSERA_QUIET="1", TESSERA_THREADS="1")
    else:
        env.pop("LD_LIBRARY_PATH", None)
        env.update(GALLIUM_DRIVER="llvmpipe", LP_NUM_THREADS="1")
    log_dir = OUT / impl
    shutil.rmtree(log_dir, ignore_errors=True)
    log_dir.mkdir(parents=True)
    start = time.time()
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        results = dict(zip([n for n, _ in selected], pool.map(lambda t: run_one(t[0], t[1], env, log_dir), selected)))
    counts = {}
    for r in results.values():
        counts[r] = counts.get(r, 0) + 1
    summary = " ".join(f"{k}={v}" for k, v in sorted(counts.items()))
    print(f"piglit-glsl: {impl}: {len(selected)} tests in {time.time() - start:.0f} s: {summary}")
    (OUT / f"{impl}.txt").write_text("".join(f"{results[n]} {n}\n" for n, _ in selected))
    return results


def stored_results(impl, selected):
    """The results of an earlier run of every selected test on `impl`, if there is one."""
    path = OUT / f"{impl}.txt"
    if not path.exists():
        return None
    results = dict(reversed(line.split(None, 1)) for line in path.read_text().splitlines() if line.strip())
    results = {name.strip(): r for name, r in results.items()}
    if all(name in results for name, _ in selected):
        print(f"piglit-glsl: {impl}: reusing {path.relative_to(ROOT)}")
        return results
    return None


def read_expected():
    expected = {}
    if EXPECTED.exists():
        for line in EXPECTED.read_text().splitlines():
            text, _, reason = line.partition("#")
            fields = text.split()
            if len(fields) == 3:
                expected[fields[2]] = (fields[0], fields[1], reason.strip())
    return expected


def write_expected(all_tests, tessera, mesa, old):
    lines = [
        "# piglit's GLSL 1.10/1.20 tests (tools/piglit-glsl.py): <tessera> <Mesa 22 llvmpipe> <test>",
        "# Written by `tools/piglit-glsl.py --update`; a reason follows every test Mesa passes and",
        "# tessera does not (kept across updates while the two results stay the same).",
        "",
    ]
    for name, _ in all_tests:
        t, m = tessera[name], mesa[name]
        reason = ""
        if name in old and old[name][:2] == (t, m):
            reason = old[name][2]
        if m == "pass" and t != "pass" and not reason:
            reason = "not yet examined"
        lines.append(f"{t:8} {m:8} {name}" + (f"  # {reason}" if reason else ""))
    EXPECTED.write_text("\n".join(lines) + "\n")


def start_xvfb(work):
    display_file = pathlib.Path(work) / "display"
    with open(display_file, "w") as fd:
        xvfb = subprocess.Popen(
            ["Xvfb", "-displayfd", str(fd.fileno()), "-noreset", "-nolisten", "tcp", "-screen", "0", "1024x768x24"],
            pass_fds=(fd.fileno(),), stderr=subprocess.DEVNULL)
    for _ in range(100):
        if display_file.read_text().strip():
            break
        time.sleep(0.1)
    else:
        sys.exit("piglit-glsl: Xvfb did not start")
    os.environ["DISPLAY"] = ":" + display_file.read_text().split()[0]
    return xvfb


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sample", type=int, help="run only this many tests, every k-th by name")
    parser.add_argument("--update", action="store_true", help="run every test on tessera and Mesa, rewrite the file")
    parser.add_argument("--mesa-only", action="store_true",
                        help="run every test on Mesa only (target/piglit-glsl/mesa.txt, which --update then reuses)")
    parser.add_argument("--lib", default=os.environ.get("TESSERA_LIB_DIR", str(ROOT / "target/release")))
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    args = parser.parse_args()
    # piglit runs each test from its own directory: a relative --lib would find the system's Mesa.
    args.lib = os.path.abspath(args.lib)
    missing = [what for what, ok in (("piglit", (PIGLIT / "bin/shader_runner").exists()),
                                     ("Xvfb", shutil.which("Xvfb")),
                                     ("tessera's libGL.so.1",
                                      args.mesa_only or (pathlib.Path(args.lib) / "libGL.so.1").exists())) if not ok]
    if missing:
        if os.environ.get("CI") == "true":
            sys.exit(f"piglit-glsl: FAILED: missing {', '.join(missing)}")
        print(f"piglit-glsl: SKIPPED (missing {', '.join(missing)}); CI=true makes this a failure")
        return
    all_tests = tests()
    selected = all_tests
    if args.sample and not (args.update or args.mesa_only):
        step = max(1, len(all_tests) // args.sample)
        selected = all_tests[::step][: args.sample]
    OUT.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as work:
        xvfb = start_xvfb(work)
        try:
            if args.mesa_only:
                run_all(selected, "mesa", args.lib, args.jobs)
                return
            tessera = run_all(selected, "tessera", args.lib, args.jobs)
            if args.update:
                mesa = stored_results("mesa", selected) or run_all(selected, "mesa", args.lib, args.jobs)
                write_expected(all_tests, tessera, mesa, read_expected())
                passed = sum(r == "pass" for r in tessera.values())
                mesa_passed = sum(r == "pass" for r in mesa.values())
                print(f"piglit-glsl: wrote {EXPECTED.relative_to(ROOT)}: tessera passes {passed}, Mesa {mesa_passed}")
                return
        finally:
            xvfb.terminate()
    expected = read_expected()
    failures, now_passing = [], []
    for name, _ in selected:
        if name not in expected:
            failures.append(f"{name}: {tessera[name]} (not in {EXPECTED.name}: run --update)")
        elif expected[name][0] == "pass" and tessera[name] != "pass":
            failures.append(f"{name}: {tessera[name]} (expected pass; log in target/piglit-glsl/tessera/)")
        elif expected[name][0] != "pass" and tessera[name] == "pass":
            now_passing.append(name)
    for name in now_passing:
        print(f"piglit-glsl: {name} now passes (expected {expected[name][0]}): update {EXPECTED.name}")
    for f in failures:
        print(f"piglit-glsl: FAIL: {f}", file=sys.stderr)
    if failures:
        sys.exit(1)
    print(f"piglit-glsl: {len(selected)} tests as expected")


if __name__ == "__main__":
    main()
