"""PyOpenGL's GLUT binding (the system's freeglut) on GLX, under an X server.

Run by tools/clients.sh with LD_LIBRARY_PATH on tessera's build directory and DISPLAY on a
private Xvfb. Asserts GL_RENDERER and the pixels of a triangle drawn in the display callback.
"""
import sys

from OpenGL import GL, GLUT

W, H = 80, 60
result = {}


def display():
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
    result["renderer"] = GL.glGetString(GL.GL_RENDERER).decode()
    result["centre"] = tuple(GL.glReadPixels(W // 2, H // 3, 1, 1, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE))
    result["corner"] = tuple(GL.glReadPixels(1, H - 2, 1, 1, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE))
    GLUT.glutSwapBuffers()
    GLUT.glutLeaveMainLoop()


GLUT.glutInit(sys.argv)
GLUT.glutInitDisplayMode(GLUT.GLUT_RGBA | GLUT.GLUT_DOUBLE)
GLUT.glutInitWindowSize(W, H)
GLUT.glutCreateWindow(b"tessera")
GLUT.glutDisplayFunc(display)
GLUT.glutSetOption(GLUT.GLUT_ACTION_ON_WINDOW_CLOSE, GLUT.GLUT_ACTION_CONTINUE_EXECUTION)
GLUT.glutMainLoop()

print(f"pyopengl-glut: GL_RENDERER = {result.get('renderer')}, centre {result.get('centre')}, corner {result.get('corner')}")
assert result, "the display callback never ran"
assert result["renderer"].startswith("tessera"), f"not tessera: {result['renderer']}"
assert result["centre"] == (255, 0, 0, 255), f"the triangle is missing: {result['centre']}"
assert result["corner"][:3] == (0, 0, 255), f"the clear color is missing: {result['corner']}"
print("pyopengl-glut: OK")
