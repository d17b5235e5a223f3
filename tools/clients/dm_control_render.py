"""dm_control's suite rendering a task off-screen (MUJOCO_GL=osmesa).

Run by tools/clients.sh with LD_LIBRARY_PATH on tessera's build directory. Loads the
cartpole swing-up task, renders camera 0 at 640×480 and asserts, inside dm_control's own
OSMesa context, that GL_RENDERER names tessera, and that the picture is not blank.
"""
import os

assert os.environ.get("MUJOCO_GL") == "osmesa", "run with MUJOCO_GL=osmesa"

import numpy as np
import picture
from dm_control import suite
from OpenGL import GL

env = suite.load("cartpole", "swingup", task_kwargs={"random": 0})
env.reset()
image = env.physics.render(height=480, width=640, camera_id=0)
with env.physics.contexts.gl.make_current() as ctx:
    renderer = ctx.call(lambda: GL.glGetString(GL.GL_RENDERER).decode())
print(f"dm_control: GL_RENDERER = {renderer}")
assert renderer.startswith("tessera"), f"not tessera: {renderer}"
colors = len(np.unique(image.reshape(-1, 3), axis=0))
print(f"dm_control: image {image.shape}, {colors} distinct colors, mean {image.mean():.1f}")
assert image.shape == (480, 640, 3), image.shape
picture.save("dm_control", image)
assert colors > 50, "the image is (nearly) blank"
# Freed here, not by dm_control's atexit hook, which runs after Python has shut down the
# render thread's executor and then prints tracebacks.
env.physics.free()
env.close()
print("dm_control: OK")
