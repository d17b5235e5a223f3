"""PyOpenGL on OSMesa (PYOPENGL_PLATFORM=osmesa): a triangle rendered off-screen.

Run by tools/clients.sh with LD_LIBRARY_PATH on tessera's build directory. Asserts that
GL_RENDERER names tessera and that the pixels are the triangle's and the clear color's.
"""
import os

assert os.environ.get("PYOPENGL_PLATFORM") == "osmesa", "run with PYOPENGL_PLATFORM=osmesa"

from OpenGL import GL, arrays, osmesa

W, H = 64, 48
context = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 16, 0, 0, None)
assert context, "OSMesaCreateContextExt failed"
buffer = arrays.GLubyteArray.zeros((H, W, 4))
assert osmesa.OSMesaMakeCurrent(context, buffer, GL.GL_UNSIGNED_BYTE, W, H), "OSMesaMakeCurrent failed"

renderer = GL.glGetString(GL.GL_RENDERER).decode()
print(f"pyopengl-osmesa: GL_RENDERER = {renderer}, GL_VERSION = {GL.glGetString(GL.GL_VERSION).decode()}")
assert renderer.startswith("tessera"), f"not tessera: {renderer}"

GL.glViewport(0, 0, W, H)
GL.glClearColor(0.0, 0.0, 1.0, 1.0)
GL.glClear(GL.GL_COLOR_BUFFER_BIT)
GL.glBegin(GL.GL_TRIANGLES)
GL.glColor3f(1.0, 0.0, 0.0)
GL.glVertex2f(-0.8, -0.8)
GL.glVertex2f(0.8, -0.8)
GL.glVertex2f(0.0, 0.8)
GL.glEnd()
GL.glFinish()

# OSMesa's rows run bottom-up (row 0 is the bottom of the picture).
centre = tuple(int(c) for c in buffer[H // 3, W // 2])
corner = tuple(int(c) for c in buffer[H - 2, 1])
read = GL.glReadPixels(W // 2, H // 3, 1, 1, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
print(f"pyopengl-osmesa: centre {centre}, corner {corner}")
assert centre == (255, 0, 0, 255), f"the triangle is not in the buffer: {centre}"
assert corner == (0, 0, 255, 255), f"the clear color is not in the buffer: {corner}"
assert bytes(read) == bytes(centre), f"glReadPixels disagrees with the buffer: {bytes(read)!r}"
red = sum(1 for y in range(H) for x in range(W) if tuple(buffer[y, x]) == (255, 0, 0, 255))
# The triangle covers half of a 0.8·W × 0.8·H rectangle: about 983 pixels at 64×48.
assert abs(red - 0.5 * 0.8 * W * 0.8 * H) < 0.02 * W * H, f"{red} red pixels"
osmesa.OSMesaDestroyContext(context)
print("pyopengl-osmesa: OK")
