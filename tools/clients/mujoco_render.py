"""MuJoCo's own Python bindings rendering a small model (MUJOCO_GL=osmesa, or glfw).

Run by tools/clients.sh with LD_LIBRARY_PATH on tessera's build directory. mujoco.Renderer
creates an OSMesa context through PyOpenGL (with MUJOCO_GL=glfw: a hidden GLFW window on
GLX) and renders into framebuffer objects. This asserts, inside that context, that
GL_RENDERER names tessera, that the 640×480 color image shows the model (a red box on a
checkered floor under a light) and that the depth image has the box and the floor at their
distances. It prints `HAS_ARB_clip_control yes|no` for tools/clients.sh.
"""
import os

assert os.environ.get("MUJOCO_GL") in ("osmesa", "glfw"), "run with MUJOCO_GL=osmesa (or glfw, with a display)"

import mujoco
import numpy as np
import picture
from OpenGL import GL

XML = """
<mujoco>
  <asset>
    <texture name="grid" type="2d" builtin="checker" rgb1=".2 .3 .4" rgb2=".8 .8 .8" width="64" height="64"/>
    <material name="grid" texture="grid" texrepeat="4 4"/>
  </asset>
  <worldbody>
    <light pos="0 0 3" dir="0 0 -1" diffuse="1 1 1"/>
    <geom type="plane" size="2 2 .1" material="grid"/>
    <body pos="0 0 .3">
      <freejoint/>
      <geom type="box" size=".2 .2 .2" rgba="1 0 0 1"/>
    </body>
    <camera name="view" pos="0 -1.6 1.2" xyaxes="1 0 0 0 .6 .8"/>
  </worldbody>
</mujoco>
"""

model = mujoco.MjModel.from_xml_string(XML)
data = mujoco.MjData(model)
mujoco.mj_forward(model, data)
renderer = mujoco.Renderer(model, height=480, width=640)

# mujoco.Renderer leaves its context current on this thread: ask it who renders.
renderer_string = GL.glGetString(GL.GL_RENDERER).decode()
extensions = GL.glGetString(GL.GL_EXTENSIONS).decode().split()
print(f"mujoco {mujoco.__version__}: GL_RENDERER = {renderer_string}, GL_VERSION = {GL.glGetString(GL.GL_VERSION).decode()}")
print(f"HAS_ARB_clip_control {'yes' if 'GL_ARB_clip_control' in extensions else 'no'}")
assert renderer_string.startswith("tessera"), f"not tessera: {renderer_string}"

renderer.update_scene(data, camera="view")
image = renderer.render()
assert image.shape == (480, 640, 3), image.shape
picture.save("mujoco-" + os.environ["MUJOCO_GL"], image)
colors = len(np.unique(image.reshape(-1, 3), axis=0))
red = int(np.count_nonzero((image[..., 0] > 120) & (image[..., 0] > 2 * image[..., 1].astype(int) + 20)))
print(f"mujoco: image {image.shape}, {colors} distinct colors, {red} red pixels, mean {image.mean():.1f}")
assert colors > 50, "the image is (nearly) blank"
assert red > 2000, "the red box is not in the picture"

renderer.enable_depth_rendering()
renderer.update_scene(data, camera="view")
depth = renderer.render()
# The box's top is about 1.5 from the camera, the floor's far edge about 4; beyond the floor
# (the upper part of the picture) the depth is the far plane's.
near, far = float(depth.min()), float(depth.max())
scene = float(np.mean(depth < 5.0))
print(f"mujoco: depth from {near:.3f} to {far:.3f}, {scene:.0%} of the pixels nearer than 5")
assert 1.0 < near < 2.0, "the box is not at its distance in the depth image"
assert 0.3 < scene < 0.95, "the floor is not in the depth image"
renderer.close()
print("mujoco: OK")
