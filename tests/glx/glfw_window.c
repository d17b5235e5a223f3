/* GLFW (Debian's libglfw3, X11) on tessera: what a plain GLFW program does. With default
 * window hints it opens a window, makes its context current, draws a triangle, reads it
 * back and swaps; glGetString(GL_RENDERER) must name tessera. GLFW loads its GLX through
 * dlopen ("libGLX.so.0", then "libGL.so.1") and creates the context with
 * glXCreateContextAttribsARB (GLX_ARB_create_context), so this checks what GLFW needs from
 * tessera's GLX. Then a window with GLFW_CONTEXT_VERSION 2.0 is asked for (created: tessera
 * provides 2.1), and one of 3.0: refused with GLFW_VERSION_UNAVAILABLE and a description that
 * names the GLX error (GLXBadFBConfig, not a bare number).
 * As in a GLFW program using a loader, the program does not link libGL: GLFW loads it and
 * the GL functions come from glfwGetProcAddress. Run by tools/xvfb-tests.sh with tessera
 * first on LD_LIBRARY_PATH (Debian's GLFW 3.3 dlopens "libGL.so.1"; GLFW 3.4 tries
 * "libGLX.so.0" first).
 * Mesa 22 (llvmpipe) under Xvfb differs in one check: glReadPixels of GL_FRONT after the
 * swap returns black there; tessera keeps the front buffer in its own memory and returns the
 * swapped picture, as GLX 1.4 3.3.11 says the front buffer holds after a swap.
 * Prints one line per failed check; exit status 0 when all hold.
 *
 * Build: gcc -std=c11 -O1 -Wall tests/glx/glfw_window.c -lglfw */
#define GLFW_INCLUDE_NONE
#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

/* The GL functions, from glfwGetProcAddress once a context is current */
#define GL_FUNCTIONS(X)                                                                                                \
    X(const GLubyte *, glGetString, (GLenum))                                                                          \
    X(void, glViewport, (GLint, GLint, GLsizei, GLsizei))                                                              \
    X(void, glClearColor, (GLclampf, GLclampf, GLclampf, GLclampf))                                                    \
    X(void, glClear, (GLbitfield))                                                                                     \
    X(void, glColor3f, (GLfloat, GLfloat, GLfloat))                                                                    \
    X(void, glBegin, (GLenum))                                                                                         \
    X(void, glVertex2f, (GLfloat, GLfloat))                                                                            \
    X(void, glEnd, (void))                                                                                             \
    X(void, glReadBuffer, (GLenum))                                                                                    \
    X(void, glReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, GLvoid *))                                  \
    X(GLenum, glGetError, (void))
#define DECLARE(ret, name, args) static ret(*p_##name) args;
GL_FUNCTIONS(DECLARE)
#define LOAD(ret, name, args)                                                                                          \
    p_##name = (ret(*) args)glfwGetProcAddress(#name);                                                                 \
    if (!p_##name) {                                                                                                   \
        printf("FAIL: glfwGetProcAddress(\"%s\") is NULL\n", #name);                                                 \
        return 0;                                                                                                      \
    }

static int load_gl(void)
{
    GL_FUNCTIONS(LOAD)
    return 1;
}

static int last_error;
static char last_description[512];

static void on_error(int code, const char *description)
{
    last_error = code;
    snprintf(last_description, sizeof last_description, "%s", description);
    printf("glfw_window: GLFW error 0x%x: %s\n", code, description);
}

static int near(const unsigned char *p, int r, int g, int b)
{
    return abs(p[0] - r) <= 1 && abs(p[1] - g) <= 1 && abs(p[2] - b) <= 1;
}

/* Clears blue, draws a red triangle over the lower-left half and checks both halves in the
 * buffer `which` (GL_BACK before the swap, GL_FRONT after it). */
static void check_picture(int w, int h, GLenum which, const char *when)
{
    unsigned char lower_left[4], upper_right[4];
    p_glReadBuffer(which);
    p_glReadPixels(w / 4, h / 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, lower_left);
    p_glReadPixels(3 * w / 4, 3 * h / 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, upper_right);
    CHECK(near(lower_left, 255, 0, 0), "%s: the triangle's pixel is %d,%d,%d (want red)", when, lower_left[0],
          lower_left[1], lower_left[2]);
    CHECK(near(upper_right, 0, 0, 255), "%s: the cleared pixel is %d,%d,%d (want blue)", when, upper_right[0],
          upper_right[1], upper_right[2]);
}

int main(void)
{
    glfwSetErrorCallback(on_error);
    if (!glfwInit()) {
        printf("FAIL: glfwInit: %s\n", last_description);
        return 1;
    }
    /* Default hints: what a plain GLFW user gets */
    GLFWwindow *window = glfwCreateWindow(64, 48, "glfw_window", NULL, NULL);
    if (!window) {
        printf("FAIL: glfwCreateWindow with default hints: %s\n", last_description);
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    if (!load_gl()) {
        glfwTerminate();
        return 1;
    }
    const char *renderer = (const char *)p_glGetString(GL_RENDERER);
    const char *version = (const char *)p_glGetString(GL_VERSION);
    printf("glfw_window: GL_RENDERER = %s, GL_VERSION = %s\n", renderer ? renderer : "(null)",
           version ? version : "(null)");
    CHECK(renderer && strncmp(renderer, "tessera", 7) == 0, "GL_RENDERER is not tessera's: %s",
          renderer ? renderer : "(null)");
    int major = glfwGetWindowAttrib(window, GLFW_CONTEXT_VERSION_MAJOR);
    int minor = glfwGetWindowAttrib(window, GLFW_CONTEXT_VERSION_MINOR);
    int vmajor = 0, vminor = 0;
    CHECK(version && sscanf(version, "%d.%d", &vmajor, &vminor) == 2 && vmajor == major && vminor == minor,
          "GLFW's context version %d.%d is not GL_VERSION's", major, minor);

    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    CHECK(w == 64 && h == 48, "framebuffer size %dx%d (want 64x48)", w, h);
    p_glViewport(0, 0, w, h);
    p_glClearColor(0, 0, 1, 1);
    p_glClear(GL_COLOR_BUFFER_BIT);
    p_glColor3f(1, 0, 0);
    p_glBegin(GL_TRIANGLES);
    p_glVertex2f(-1, -1);
    p_glVertex2f(1, -1);
    p_glVertex2f(-1, 1);
    p_glEnd();
    check_picture(w, h, GL_BACK, "before the swap");
    glfwSwapBuffers(window);
    check_picture(w, h, GL_FRONT, "after the swap");
    glfwSwapInterval(1);
    glfwPollEvents();
    CHECK(p_glGetError() == GL_NO_ERROR, "GL error 0x%x", p_glGetError());
    glfwDestroyWindow(window);

    /* A 2.0 window: created, since tessera provides 2.1. Then 3.0, which it does not provide:
     * refused, and GLFW's description names the GLX error. */
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    window = glfwCreateWindow(64, 48, "glfw_window 2.0", NULL, NULL);
    CHECK(window != NULL, "an OpenGL 2.0 window was refused although %d.%d is provided: %s", major, minor,
          last_description);
    if (window)
        glfwDestroyWindow(window);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    last_error = 0;
    last_description[0] = 0;
    window = glfwCreateWindow(64, 48, "glfw_window 3.0", NULL, NULL);
    if (major >= 3) {
        CHECK(window != NULL, "an OpenGL 3.0 window was refused although %d.%d is provided: %s", major, minor,
              last_description);
    } else {
        CHECK(window == NULL, "an OpenGL 3.0 window was created on OpenGL %d.%d", major, minor);
        CHECK(last_error == GLFW_VERSION_UNAVAILABLE, "error 0x%x (want GLFW_VERSION_UNAVAILABLE)", last_error);
        CHECK(strstr(last_description, "GLXBadFBConfig") != NULL, "the refusal does not name the GLX error: %s",
              last_description);
        printf("glfw_window: OpenGL 3.0 refused as expected on OpenGL %d.%d\n", major, minor);
    }
    if (window)
        glfwDestroyWindow(window);
    glfwTerminate();
    printf("glfw_window: %s (%d failures)\n", failures ? "FAILED" : "ok", failures);
    return failures ? 1 : 0;
}
