#!/usr/bin/env python3
"""MuJoCo on tessera: renders a scene with shadows and reflections through MuJoCo's OSMesa
backend and checks that MuJoCo finds what it asks for.

MuJoCo reads depth with reversed Z (mjDEPTH_ZEROFAR) and needs GL_ARB_clip_control for it;
without the extension its first depth rendering prints "ARB_clip_control unavailable while
mjDEPTH_ZEROFAR requested, depth accuracy will be limited". This script renders color and
depth, fails when that warning appears (with --strict: any MuJoCo warning, such as
"ARB_depth_buffer_float unavailable", which MuJoCo checks next), saves the color image as PNG and
prints the GL renderer and the time per color frame.

    python3 -m venv /tmp/mjvenv && /tmp/mjvenv/bin/pip install mujoco PyOpenGL numpy   # pillow too for PNGs
    /tmp/mjvenv/bin/python tools/clients/mujoco_compare.py [--lib target/release] [--out DIR]
        [--frames N] [--compare-with-mesa] [--default-shadows] [--json FILE]

--lib is put first on LD_LIBRARY_PATH of the rendering process (MUJOCO_GL=osmesa,
PYOPENGL_PLATFORM=osmesa); --compare-with-mesa renders the same frames again on the system's
Mesa (no LD_LIBRARY_PATH) and reports the difference of the two images (fails above
--max-mean-error, in 8-bit steps averaged over all channels). Exit status 0: no warning, and
the images agree when compared. --default-shadows renders with MuJoCo's default shadow map
(4096², instead of the 2048² of the checking scene): the benchmark's scene (tools/bench.sh).
--json writes each implementation's time per frame and the image difference to FILE.
"""
import argparse
import json
import os
import subprocess
import sys
import time

WIDTH, HEIGHT = 640, 480
WARNING = "ARB_clip_control unavailable"

# A reflective checkered floor, a light casting shadows, and bodies at several distances.
MODEL = """
<mujoco>
  <visual>
    <quality shadowsize="2048"/>
    <global offwidth="640" offheight="480"/>
  </visual>
  <asset>
    <texture name="grid" type="2d" builtin="checker" rgb1=".2 .3 .4" rgb2=".8 .8 .8"
             width="256" height="256"/>
    <material name="floor" texture="grid" texrepeat="8 8" reflectance="0.4"/>
    <material name="red" rgba=".8 .2 .2 1" specular="0.5" shininess="0.6"/>
    <material name="green" rgba=".2 .7 .3 1" reflectance="0.2"/>
  </asset>
  <worldbody>
    <light name="sun" pos="1 -1 4" dir="-0.2 0.2 -1" castshadow="true" diffuse=".8 .8 .8"/>
    <light name="fill" pos="-2 2 3" dir="0.4 -0.4 -1" castshadow="true" diffuse=".3 .3 .3"/>
    <geom name="floor" type="plane" size="6 6 0.1" material="floor"/>
    <body name="box" pos="0 0 0.5">
      <freejoint/>
      <geom type="box" size=".3 .3 .3" material="red" euler="0 0 30"/>
    </body>
    <body name="ball" pos="0.9 0.5 0.4">
      <geom type="sphere" size=".35" material="green"/>
    </body>
    <body name="capsule" pos="-0.8 0.6 0.3">
      <geom type="capsule" size=".12 .4" rgba=".3 .4 .9 1" euler="0 90 20"/>
    </body>
    <body name="far" pos="3 4 0.6">
      <geom type="cylinder" size=".4 .6" rgba=".9 .8 .2 1"/>
    </body>
  </worldbody>
</mujoco>
"""


def render(out, frames, default_shadows):
    """The child process: renders `frames` frames, saves the last as PNG, prints JSON."""
    import mujoco
    import numpy as np

    xml = MODEL.replace('<quality shadowsize="2048"/>', "") if default_shadows else MODEL
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    renderer = mujoco.Renderer(model, HEIGHT, WIDTH)
    camera = mujoco.MjvCamera()
    camera.lookat[:] = [0.3, 0.6, 0.4]
    camera.distance, camera.azimuth, camera.elevation = 4.5, 120.0, -25.0
    from OpenGL import GL

    renderer.update_scene(data, camera)
    image = renderer.render()  # the first frame compiles and uploads; not timed
    start = time.perf_counter()
    for _ in range(frames):
        renderer.update_scene(data, camera)
        image = renderer.render()
    per_frame = (time.perf_counter() - start) / max(frames, 1)
    # The pixels for the comparison; a PNG for people when Pillow is there (the clients venv
    # of tools/clients.sh has none).
    np.save(out[: -len(".png")] + "_color.npy", image)
    try:
        from PIL import Image

        Image.fromarray(image).save(out)
    except ImportError:
        pass
    # The depth rendering is where MuJoCo checks for reversed-Z support.
    renderer.enable_depth_rendering()
    renderer.update_scene(data, camera)
    depth = renderer.render()
    np.save(out[: -len(".png")] + "_depth.npy", depth)
    renderer_name = GL.glGetString(GL.GL_RENDERER)
    print(
        json.dumps(
            {
                "renderer": renderer_name.decode() if renderer_name else None,
                "per_frame_ms": per_frame * 1000.0,
                "png": out,
                "mean": float(np.asarray(image).mean()),
            }
        ),
        flush=True,
    )


def run_child(lib, out, frames, default_shadows=False):
    """Renders in a child process (MuJoCo's warnings go to the C streams) and returns its
    result and everything it printed."""
    env = dict(os.environ, MUJOCO_GL="osmesa", PYOPENGL_PLATFORM="osmesa")
    env.pop("LD_LIBRARY_PATH", None)
    if lib:
        env["LD_LIBRARY_PATH"] = os.path.abspath(lib)
    child = subprocess.run(
        [sys.executable, __file__, "--child", out, "--frames", str(frames)]
        + (["--default-shadows"] if default_shadows else []),
        env=env,
        capture_output=True,
        text=True,
        cwd=os.path.dirname(os.path.abspath(out)) or ".",
    )
    output = child.stdout + child.stderr
    result = None
    for line in child.stdout.splitlines():
        if line.startswith("{"):
            result = json.loads(line)
    return child.returncode, result, output


def image_difference(a, b):
    """Color difference in 8-bit steps, and the depth maps' (linear distances) relative one."""
    import numpy as np

    x = np.load(a[: -len(".png")] + "_color.npy").astype(np.int32)
    y = np.load(b[: -len(".png")] + "_color.npy").astype(np.int32)
    d = np.abs(x - y)
    za = np.load(a[: -len(".png")] + "_depth.npy")
    zb = np.load(b[: -len(".png")] + "_depth.npy")
    rel = np.abs(za - zb) / np.maximum(np.abs(zb), 1e-6)
    return {
        "mean_error": float(d.mean()),
        "max_error": int(d.max()),
        "pixels_over_8": int((d.max(axis=2) > 8).sum()),
        "pixels": int(d.shape[0] * d.shape[1]),
        "depth_median_relative_error": float(np.median(rel)),
        "depth_p99_relative_error": float(np.percentile(rel, 99)),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--child", help=argparse.SUPPRESS)
    parser.add_argument("--lib", default="target/release", help="tessera's library directory")
    parser.add_argument("--out", default="target/clients", help="where the PNGs go")
    parser.add_argument("--frames", type=int, default=10, help="timed frames")
    parser.add_argument("--compare-with-mesa", action="store_true")
    parser.add_argument("--max-mean-error", type=float, default=2.0)
    parser.add_argument("--strict", action="store_true", help="fail on any MuJoCo warning")
    parser.add_argument("--default-shadows", action="store_true", help="MuJoCo's default 4096² shadow map")
    parser.add_argument("--json", help="write the times per frame and the difference here")
    args = parser.parse_args()
    if args.child:
        render(args.child, args.frames, args.default_shadows)
        return 0

    os.makedirs(args.out, exist_ok=True)
    failed = False
    runs = [("tessera", args.lib)] + ([("mesa", None)] if args.compare_with_mesa else [])
    results = {}
    for name, lib in runs:
        png = os.path.abspath(os.path.join(args.out, f"mujoco_{name}.png"))
        code, result, output = run_child(lib, png, args.frames, args.default_shadows)
        warnings = [l for l in output.splitlines() if "WARNING" in l or WARNING in l]
        print(f"{name}: exit {code}, renderer {result and result['renderer']!r}, "
              f"{result and round(result['per_frame_ms'], 1)} ms/frame, {png}")
        for w in warnings:
            print(f"{name}: MuJoCo warning: {w}")
        if code != 0 or result is None:
            print(output)
            failed = True
            continue
        if name == "tessera":
            if not (result["renderer"] or "").startswith("tessera"):
                print("tessera: the renderer is not tessera (is --lib right?)")
                failed = True
            if any(WARNING in w for w in warnings) or (args.strict and warnings):
                failed = True
        results[name] = result
    diff = None
    if "tessera" in results and "mesa" in results:
        diff = image_difference(results["tessera"]["png"], results["mesa"]["png"])
        print(f"tessera vs mesa: {json.dumps(diff)}")
        if diff["mean_error"] > args.max_mean_error:
            failed = True
    if args.json:
        summary = {name: {"per_frame_ms": r["per_frame_ms"], "renderer": r["renderer"]} for name, r in results.items()}
        summary.update(frames=args.frames, width=WIDTH, height=HEIGHT, difference=diff, failed=failed)
        with open(args.json, "w") as f:
            json.dump(summary, f, indent=1)
    print("FAIL" if failed else "ok")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
