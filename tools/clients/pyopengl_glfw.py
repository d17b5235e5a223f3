"""PyOpenGL in a GLFW window (the PyPI glfw package) on GLX, under an X server.

Run by tools/clients.sh with LD_LIBRARY_PATH on tessera's build directory and DISPLAY on a
private Xvfb. GLFW dlopens libGLX.so.0 and PyOpenGL loads libGL/libOpenGL: both must be
tessera. Asserts GL_RENDERER, the back buffer before the swap and the front buffer after it.
"""
import glfw
from OpenGL import GL

W, H = 96, 64
assert glfw.init(), "glfwInit failed"
glfw.window_hint(glfw.CONTEXT_VERSION_MAJOR, 1)
glfw.window_hint(glfw.CONTEXT_VERSION_MINOR, 5)
window = glfw.create_window(W, H, "tessera", None, None)
assert window, "glfwCreateWindow failed"
glfw.make_context_current(window)

renderer = GL.glGetString(GL.GL_RENDERER).decode()
print(f"pyopengl-glfw: GLFW {glfw.get_version_string().decode()}, GL_RENDERER = {renderer}")
assert renderer.startswith("tessera"), f"not tessera: {renderer}"

width, height = glfw.get_framebuffer_size(window)
assert (width, height) == (W, H), f"framebuffer {width}x{height}"
GL.glViewport(0, 0, W, H)
GL.glClearColor(0.0, 0.0, 1.0, 1.0)
GL.glClear(GL.GL_COLOR_BUFFER_BIT)
GL.glBegin(GL.GL_TRIANGLES)
GL.glColor3f(1.0, 0.0, 0.0)
GL.glVertex2f(-0.8, -0.8)
GL.glVertex2f(0.8, -0.8)
GL.glVertex2f(0.0, 0.8)
GL.glEnd()


def pixel(buffer, x, y):
    GL.glReadBuffer(buffer)
    return tuple(GL.glReadPixels(x, y, 1, 1, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE))


back = pixel(GL.GL_BACK, W // 2, H // 3), pixel(GL.GL_BACK, 1, H - 2)
glfw.swap_buffers(window)
GL.glFinish()
front = pixel(GL.GL_FRONT, W // 2, H // 3), pixel(GL.GL_FRONT, 1, H - 2)
print(f"pyopengl-glfw: back {back}, front after swap {front}")
for centre, corner in (back, front):
    assert centre == (255, 0, 0, 255), f"the triangle is missing: {centre}"
    assert corner[:3] == (0, 0, 255), f"the clear color is missing: {corner}"
glfw.destroy_window(window)
glfw.terminate()
print("pyopengl-glfw: OK")
