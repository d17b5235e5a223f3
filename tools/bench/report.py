#!/usr/bin/env python3
"""Turns the raw output of tools/bench.sh into BENCHMARKS.md and an SVG plot of error vs time.

Reads <dir>/<implementation>/round<N>.txt (bench.c's output) and the images of the last
round, <dir>/<implementation>/<scene>.rgba; errors are measured by `bench --compare` against
tessera's exact mode on one thread. Also, when present: <dir>/sizes.txt (library sizes),
<dir>/immediate-<impl>-round<N>.txt (immediate.c's output) and <dir>/mujoco-round<N>.json
(tools/clients/mujoco_compare.py --json). Standard library only.
"""
import argparse
import datetime
import glob
import json
import math
import os
import platform
import statistics
import subprocess

SCENES = [
    ("flat_fill", "Flat fill (8 full-window layers)"),
    ("smooth_fill", "Smooth fill, varying w (8 layers)"),
    ("blend_fill", "Blended fill (8 layers)"),
    ("depth_overdraw", "Depth-tested overdraw (8 crossing layers)"),
    ("stencil_shadow", "Stencil shadow-volume passes"),
    ("small_triangles", "100k small triangles (mesh)"),
    ("thin_triangles", "2000 long thin triangles"),
    ("fog_blend", "Fog + blend (8 layers)"),
    ("lit_mesh", "Lit mesh (128×128 quads, 2 lights, specular)"),
    ("textured_fill", "Textured fill, trilinear (8 layers)"),
    ("fbo_shadow_map", "Render to texture: 2048² depth texture in an FBO (8 quads), then sampled with depth compare"),
    ("phong_shader", "Per-pixel Blinn-Phong GLSL program on the lit mesh (2 lights)"),
    ("textured_shader", "Textured fill through a GLSL program (8 layers, trilinear)"),
    ("shader_first_draw", "First draw with a new program: compile + link a 200-line shader pair, draw 64²"),
]
STAGES = ["none", "scissor", "alpha", "stencil", "depth", "blend", "logic_op", "fog", "dither"]
LIBRARY_LIMIT_MB = 5.0
GOAL_FILL = {"flat_fill", "smooth_fill", "blend_fill", "depth_overdraw", "stencil_shadow", "fog_blend"}
# Issue #20's checks: the GLSL scenes at least as fast as llvmpipe (goal 2×), and a new
# program's first draw under an absolute time.
GOAL_SHADER = {"phong_shader", "textured_shader"}
FIRST_DRAW_LIMIT_MS = 5.0


def parse(path):
    result = {"scenes": {}}
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "renderer":
                result["renderer"] = " ".join(parts[1:])
            elif parts[0] in ("context", "first_frame"):
                result[parts[0]] = float(parts[1])
            elif parts[0] == "scene":
                result["scenes"][parts[1]] = (float(parts[2]), [float(t) for t in parts[3:]])
    return result


def implementations(directory):
    # The folders holding bench.c's output (not mujoco/, the MuJoCo script's images).
    names = sorted(n for n in os.listdir(directory) if glob.glob(os.path.join(directory, n, "round*.txt")))

    def key(name):
        if name == "llvmpipe":
            return (0, name)
        if name == "softpipe":
            return (1, name)
        mode = name.split("-")[1]
        return (2 + ["fast", "conformant", "exact"].index(mode), name)

    return sorted(names, key=key)


def collect(directory, impl):
    runs = []
    folder = os.path.join(directory, impl)
    for name in sorted(os.listdir(folder)):
        if name.startswith("round") and name.endswith(".txt"):
            runs.append(parse(os.path.join(folder, name)))
    data = {"renderer": runs[-1].get("renderer", "?") if runs else "?", "scenes": {}}
    for key in ("context", "first_frame"):
        values = [r[key] for r in runs if key in r]
        data[key] = statistics.median(values) if values else float("nan")
    for run in runs:
        for scene, (pixels, times) in run["scenes"].items():
            entry = data["scenes"].setdefault(scene, {"pixels": pixels, "times": []})
            entry["times"].extend(times)
    for entry in data["scenes"].values():
        entry["median"] = statistics.median(entry["times"]) if entry["times"] else float("nan")
    return data


def compare(bench, reference, image):
    out = subprocess.run([bench, "--compare", reference, image], capture_output=True, text=True, check=True).stdout
    parts = out.split()
    values = dict(zip(parts[0::2], parts[1::2]))
    return values


def extras(directory):
    """Library sizes, immediate-mode ns per call (median over rounds) and MuJoCo ms per frame."""
    sizes = {}
    path = os.path.join(directory, "sizes.txt")
    if os.path.exists(path):
        with open(path) as f:
            sizes = {name: int(size) for name, size in (line.split() for line in f if line.strip())}
    calls = {}
    for path in sorted(glob.glob(os.path.join(directory, "immediate-*-round*.txt"))):
        impl = os.path.basename(path)[len("immediate-") :].rsplit("-round", 1)[0]
        with open(path) as f:
            for line in f:
                parts = line.split()
                if len(parts) == 3 and parts[0] == "call":
                    calls.setdefault(parts[1], {}).setdefault(impl, []).append(float(parts[2]))
    calls = {name: {impl: statistics.median(v) for impl, v in by_impl.items()} for name, by_impl in calls.items()}
    mujoco = {}
    for path in sorted(glob.glob(os.path.join(directory, "mujoco-round*.json"))):
        with open(path) as f:
            run = json.load(f)
        for impl in ("tessera", "mesa"):
            if isinstance(run.get(impl), dict):
                mujoco.setdefault(impl, []).append(run[impl]["per_frame_ms"])
        mujoco["frames"] = run.get("frames")
        mujoco["difference"] = run.get("difference")
    for impl in ("tessera", "mesa"):
        if impl in mujoco:
            mujoco[impl] = statistics.median(mujoco[impl])
    return sizes, calls, mujoco


def fmt_ms(ms):
    return f"{ms:.2f}" if ms >= 0.1 else f"{ms:.3f}"


def svg_plot(path, results, impls, reference):
    """Small multiples: per scene, each implementation at (time per frame, max channel error)."""
    colors = {"llvmpipe": "#d62728", "softpipe": "#ff7f0e", "fast": "#2ca02c", "conformant": "#1f77b4", "exact": "#9467bd"}
    cols, panel_w, panel_h, margin = 4, 300, 220, 50
    rows = math.ceil(len(SCENES) / cols)
    width, height = cols * panel_w, rows * panel_h + 70
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" font-size="10">',
        f'<rect width="{width}" height="{height}" fill="white"/>',
        f'<text x="10" y="16" font-size="13">Error against tessera exact ({reference}) vs median time per frame; '
        "x: ms (log), y: max channel error in LSB (log(1+e))</text>",
    ]
    legend_x = 10
    for label, color in colors.items():
        out.append(f'<circle cx="{legend_x + 5}" cy="30" r="4" fill="{color}"/>')
        out.append(f'<text x="{legend_x + 12}" y="33">{label}{" (tessera; open: 1 thread)" if label == "exact" else ""}</text>')
        legend_x += 90 if label != "exact" else 220
    for index, (scene, title) in enumerate(SCENES):
        px, py = (index % cols) * panel_w, (index // cols) * panel_h + 45
        points = []
        for impl in impls:
            entry = results[impl]["scenes"].get(scene)
            if not entry or not math.isfinite(entry["median"]) or entry.get("max_error") in (None, "-"):
                continue
            points.append((impl, entry["median"], int(entry["max_error"])))
        if not points:
            continue
        tmin = min(p[1] for p in points) / 1.5
        tmax = max(p[1] for p in points) * 1.5
        emax = max(math.log1p(max(p[2] for p in points)), math.log1p(4))
        x0, y0, x1, y1 = px + margin, py + panel_h - 40, px + panel_w - 15, py + 25
        out.append(f'<text x="{px + margin}" y="{py + 15}" font-size="11">{title}</text>')
        out.append(f'<rect x="{x0}" y="{y1}" width="{x1 - x0}" height="{y0 - y1}" fill="none" stroke="#999"/>')

        def sx(t):
            return x0 + (math.log(t) - math.log(tmin)) / (math.log(tmax) - math.log(tmin)) * (x1 - x0)

        def sy(e):
            return y0 - math.log1p(e) / emax * (y0 - y1)

        for t in (0.1, 1, 10, 100, 1000, 10000):
            if tmin <= t <= tmax:
                out.append(f'<line x1="{sx(t):.1f}" y1="{y0}" x2="{sx(t):.1f}" y2="{y0 + 4}" stroke="#999"/>')
                out.append(f'<text x="{sx(t):.1f}" y="{y0 + 14}" text-anchor="middle">{t:g} ms</text>')
        for e in (0, 1, 4, 16, 64, 255):
            if math.log1p(e) <= emax:
                out.append(f'<text x="{x0 - 4}" y="{sy(e) + 3:.1f}" text-anchor="end">{e}</text>')
        for impl, t, e in points:
            family = impl if impl in ("llvmpipe", "softpipe") else impl.split("-")[1]
            color = colors[family]
            one_thread = impl.endswith("-1t")
            fill = "white" if one_thread else color
            out.append(
                f"<g><title>{impl}: {t:.2f} ms, max error {e}</title>"
                f'<circle cx="{sx(t):.1f}" cy="{sy(e):.1f}" r="4" fill="{fill}" stroke="{color}" stroke-width="1.5"/></g>'
            )
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    parser = argparse.ArgumentParser()
    for name in ("dir", "size", "cores", "reps", "rounds", "load", "load-after", "markdown", "svg"):
        parser.add_argument(f"--{name}", required=True)
    args = parser.parse_args()
    bench = os.path.join(os.path.dirname(os.path.abspath(args.dir)), "bench")
    if not os.path.exists(bench):
        bench = "target/bench/bench"
    impls = implementations(args.dir)
    results = {impl: collect(args.dir, impl) for impl in impls}
    sizes, calls, mujoco = extras(args.dir)
    reference = "tessera-exact-1t"
    default = f"tessera-conformant-{args.cores}t"
    for impl in impls:
        for scene, entry in results[impl]["scenes"].items():
            errors = compare(
                bench,
                os.path.join(args.dir, reference, scene + ".rgba"),
                os.path.join(args.dir, impl, scene + ".rgba"),
            )
            entry.update(errors)

    loads = [float(x) for x in args.load.split() + args.load_after.split()]
    loaded = max(loads) > 0.5
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    md = []
    md.append("# Benchmarks")
    md.append("")
    md.append("Generated by `bash tools/bench.sh` (tools/bench/bench.c, tools/bench/report.py); do not edit.")
    md.append("")
    md.append(
        f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, {cpu}, {args.cores} cores, "
        f"{platform.system()} {platform.release()}. Window {args.size}×{args.size} RGBA8 with 24-bit depth and "
        f"8-bit stencil. Each implementation ran {args.rounds} processes, alternating with the others "
        f"(llvmpipe, softpipe, then tessera in every mode), each timing {args.reps} frames per scene after a "
        "warm-up frame (softpipe fewer); times are medians of all timed frames: clear, draw, glFinish."
    )
    md.append("")
    if loaded:
        md.append(
            f"**Measured on a loaded machine** (load average {args.load} before, {args.load_after} after, "
            f"on {args.cores} cores): other work shared the cores, so absolute times are pessimistic and noisy; "
            "regenerate on a quiet machine for reference numbers."
        )
    else:
        md.append(f"Load average {args.load} before, {args.load_after} after, on {args.cores} cores.")
    md.append("")
    md.append(
        "Implementations: `llvmpipe` and `softpipe` are Mesa's OSMesa (" + results.get("llvmpipe", {}).get("renderer", "?")
        + "; llvmpipe on all cores); `tessera-<mode>-<n>t` is tessera with `TESSERA_ACCURACY=<mode>` and "
        "`TESSERA_THREADS=<n>`. Errors are against `tessera-exact-1t` (the exact mode's picture): largest channel "
        "difference, pixels where some channel differs by more than 1, PSNR over RGBA in dB (inf: identical)."
    )
    md.append("")
    md.append(f"Plot of error against time per scene: [{os.path.basename(args.svg)}]({os.path.basename(args.svg)}).")
    md.append("")

    md.append("## Goals (default mode on all cores against llvmpipe)")
    md.append("")
    md.append("| Scene | tessera conformant | llvmpipe | Throughput ratio | Goal | Met |")
    md.append("|---|---:|---:|---:|---:|:---:|")
    if "llvmpipe" in results and default in results:
        for scene, title in SCENES:
            a = results[default]["scenes"].get(scene)
            b = results["llvmpipe"]["scenes"].get(scene)
            if not a or not b:
                continue
            ratio = b["median"] / a["median"]
            if scene == "shader_first_draw":
                met = "yes" if a["median"] < FIRST_DRAW_LIMIT_MS else "no"
                md.append(
                    f"| {title} | {fmt_ms(a['median'])} ms | {fmt_ms(b['median'])} ms | {ratio:.2f}× | "
                    f"< {FIRST_DRAW_LIMIT_MS:g} ms | {met} |"
                )
                continue
            goal = 3.0 if scene in GOAL_FILL else 1.5 if scene == "small_triangles" else 1.0 if scene in GOAL_SHADER else None
            met = "" if goal is None else ("yes" if ratio >= goal else "no")
            md.append(
                f"| {title} | {fmt_ms(a['median'])} ms | {fmt_ms(b['median'])} ms | {ratio:.2f}× | "
                f"{'' if goal is None else f'{goal:g}×'} | {met} |"
            )
        ctx = results[default]["first_frame"]
        md.append(
            f"| Context + first frame | {fmt_ms(ctx)} ms | {fmt_ms(results['llvmpipe']['first_frame'])} ms | "
            f"{results['llvmpipe']['first_frame'] / ctx:.2f}× | < 1 ms | {'yes' if ctx < 1 else 'no'} |"
        )
    if "tessera" in mujoco and "mesa" in mujoco:
        ratio = mujoco["mesa"] / mujoco["tessera"]
        md.append(
            f"| MuJoCo renderer frame (640×480, default shadows, reflections) | {fmt_ms(mujoco['tessera'])} ms | "
            f"{fmt_ms(mujoco['mesa'])} ms | {ratio:.2f}× | 1× | {'yes' if ratio >= 1 else 'no'} |"
        )
    for name, ns in calls.items():
        if "tessera" in ns and "llvmpipe" in ns:
            cost = ns["tessera"] / ns["llvmpipe"]
            md.append(
                f"| `{name}` call | {ns['tessera']:.1f} ns | {ns['llvmpipe']:.1f} ns | {1 / cost:.2f}× | 0.5× | "
                f"{'yes' if cost <= 2 else 'no'} |"
            )
    for name, size in sizes.items():
        mb = size / 1e6
        md.append(f"| `{name}` size | {mb:.2f} MB | | | ≤ {LIBRARY_LIMIT_MB:g} MB | {'yes' if mb <= LIBRARY_LIMIT_MB else 'no'} |")
    md.append("")

    md.append("## Shipped libraries")
    md.append("")
    md.append(
        "Size on disk of the drop-in libraries of `cargo build --release` (the release profile: fat LTO, one "
        "codegen unit, no debug information, no symbol table; `cargo build --profile profiling` keeps both for perf and callgrind)."
    )
    md.append("")
    md.append("| Library | Bytes | MB | Limit |")
    md.append("|---|---:|---:|---:|")
    for name, size in sizes.items():
        md.append(f"| `{name}` | {size} | {size / 1e6:.2f} | {LIBRARY_LIMIT_MB:g} MB |")
    if not sizes:
        md.append("| (not measured) | | | |")
    md.append("")

    md.append("## Immediate-mode calls")
    md.append("")
    md.append(
        "tools/bench/immediate.c: nanoseconds per call through OSMesa, best of 7 loops of many calls in each "
        "process, median over the processes (tessera alternating with llvmpipe). The attribute calls only set "
        "the current value; `glVertex3f` draws points outside the viewport 64 per glBegin/glEnd, so it includes "
        "each vertex's transform and clipping; `glBegin/glEnd` is an empty pair. Goal: tessera within 2× of Mesa."
    )
    md.append("")
    md.append("| Call | tessera ns | llvmpipe ns | tessera ÷ llvmpipe |")
    md.append("|---|---:|---:|---:|")
    for name, ns in calls.items():
        t, m = ns.get("tessera", float("nan")), ns.get("llvmpipe", float("nan"))
        md.append(f"| `{name}` | {t:.1f} | {m:.1f} | {t / m:.2f}× |")
    if not calls:
        md.append("| (not measured) | | | |")
    md.append("")

    md.append("## MuJoCo renderer")
    md.append("")
    if "tessera" in mujoco and "mesa" in mujoco:
        diff = mujoco.get("difference") or {}
        md.append(
            "tools/clients/mujoco_compare.py `--default-shadows`: MuJoCo's `Renderer` (MUJOCO_GL=osmesa) at 640×480, "
            "a reflective floor, two lights casting shadows with MuJoCo's default 4096² shadow map; time per color "
            f"frame over {mujoco.get('frames')} frames after a first one, median over the rounds, tessera (all cores) "
            "then llvmpipe in each round."
        )
        md.append("")
        md.append("| tessera ms/frame | llvmpipe ms/frame | llvmpipe ÷ tessera | mean / max color difference |")
        md.append("|---:|---:|---:|---:|")
        md.append(
            f"| {fmt_ms(mujoco['tessera'])} | {fmt_ms(mujoco['mesa'])} | {mujoco['mesa'] / mujoco['tessera']:.2f}× | "
            f"{diff.get('mean_error', float('nan')):.2f} / {diff.get('max_error', '-')} |"
        )
    else:
        md.append("Not measured: no MuJoCo venv (tools/clients.sh builds target/clients-venv), or a run failed.")
    md.append("")

    md.append("## Context creation and first frame")
    md.append("")
    md.append(
        "Context: `OSMesaCreateContextExt` + `OSMesaMakeCurrent` + a clear of color, depth and stencil + `glFinish`, "
        "the first context of the process. First frame: the same plus the flat-fill scene and `glFinish`. Medians "
        "over the processes."
    )
    md.append("")
    md.append("| Implementation | Context + first clear (ms) | Context + first frame (ms) |")
    md.append("|---|---:|---:|")
    for impl in impls:
        md.append(f"| {impl} | {fmt_ms(results[impl]['context'])} | {fmt_ms(results[impl]['first_frame'])} |")
    md.append("")

    math_table = os.path.join(args.dir, "math-errors.md")
    if os.path.exists(math_table):
        md.append("## Transcendental functions")
        md.append("")
        md.append(
            "Largest error of tessera's own exp2, log2, pow, sin, cos and eˣ against double precision over dense "
            "samples of their inputs (`examples/math_errors.rs`, the sweeps of `src/shader/math/errors.rs`, which "
            "the tests assert against the bounds). The same functions, with the same bits, run in every accuracy "
            "mode and at every SIMD level: they use IEEE operations and fused multiply-adds computed exactly in double precision (round to odd), never by libm or an FMA instruction."
        )
        md.append("")
        with open(math_table) as f:
            md.extend(line.rstrip("\n") for line in f)
        md.append("")

    md.append("## Scenes")
    md.append("")
    md.append(
        "Mpixel/s counts the fragments a frame generates (layers × window for the full-window scenes, the "
        "covered area otherwise) over the median frame time. \"vs llvmpipe\" is llvmpipe's time over this "
        "row's (above 1: faster than llvmpipe)."
    )
    for scene, title in SCENES:
        md.append("")
        md.append(f"### {title} (`{scene}`)")
        md.append("")
        md.append("| Implementation | ms/frame | Mpixel/s | vs llvmpipe | Max error | Pixels > 1 LSB | PSNR (dB) |")
        md.append("|---|---:|---:|---:|---:|---:|---:|")
        base = results.get("llvmpipe", {}).get("scenes", {}).get(scene)
        for impl in impls:
            entry = results[impl]["scenes"].get(scene)
            if not entry:
                continue
            ms = entry["median"]
            mpix = entry["pixels"] / ms / 1000.0
            speed = f"{base['median'] / ms:.2f}×" if base else "-"
            md.append(
                f"| {impl} | {fmt_ms(ms)} | {mpix:.0f} | {speed} | {entry.get('max_error', '-')} | "
                f"{entry.get('over_1lsb', '-')} | {entry.get('psnr', '-')} |"
            )
    md.append("")

    md.append("## Per-stage cost")
    md.append("")
    md.append(
        "The smooth-fill scene (8 full-window layers, w varying) with one fragment stage enabled at a time, set up "
        "so that every fragment passes (scissor box one pixel inside the window, alpha > 0.1 on alpha 0.75, stencil "
        "ALWAYS/REPLACE, depth LEQUAL, blend SRC_ALPHA/ONE_MINUS_SRC_ALPHA, logic op XOR, linear fog, dither on "
        "RGBA8). \"Added\" is the stage's cost: the frame time minus the same implementation's time with no "
        "stage (`none`); \"cost\" is their ratio; the last column is llvmpipe's time over tessera's (above 1: "
        "tessera faster)."
    )
    md.append("")
    tess1 = "tessera-conformant-1t"
    header = (
        f"| Stage | llvmpipe ms | llvmpipe added ms | llvmpipe cost | {default} ms | added ms | cost | "
        f"{tess1} ms | added ms | cost | tessera ({args.cores}t) vs llvmpipe |"
    )
    md.append(header)
    md.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")

    def stage_ms(impl, stage):
        entry = results.get(impl, {}).get("scenes", {}).get(f"stage_{stage}")
        return entry["median"] if entry else float("nan")

    for stage in STAGES:
        row = [stage]
        for impl in ("llvmpipe", default, tess1):
            ms = stage_ms(impl, stage)
            none = stage_ms(impl, "none")
            row += [fmt_ms(ms), f"{ms - none:+.2f}", f"{ms / none:.2f}×"]
        row.append(f"{stage_ms('llvmpipe', stage) / stage_ms(default, stage):.2f}×")
        md.append("| " + " | ".join(row) + " |")
    md.append("")
    with open(args.markdown, "w") as f:
        f.write("\n".join(md))
    svg_plot(args.svg, results, impls, reference)


if __name__ == "__main__":
    main()
