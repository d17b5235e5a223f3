/* A refused glXCreateContextAttribsARB tells the user why on stderr: one line naming the
 * version and profile asked for and what tessera provides (winsys::notice), once per
 * process however often the program retries, and none with TESSERA_QUIET=1. This program
 * asks twice for an OpenGL 3.3 core profile context (refused: tessera provides less) with
 * its own X error handler (the refusal is also a GLXBadFBConfig X error); it checks the
 * refusals, and tools/xvfb-tests.sh checks its stderr, run with and without TESSERA_QUIET.
 * Prints one line per failed check on stdout; exit status 0 when all hold.
 *
 * Build: gcc -std=c11 -O1 -Wall tests/glx/context_notice.c -lGL -lX11 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>
#include <stdio.h>

static int errors_seen;

static int handler(Display *dpy, XErrorEvent *e)
{
    (void)dpy;
    (void)e;
    errors_seen++;
    return 0;
}

int main(void)
{
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("cannot open display\n");
        return 2;
    }
    XSetErrorHandler(handler);
    int count = 0, failures = 0;
    int attribs[] = {GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, None};
    GLXFBConfig *configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attribs, &count);
    PFNGLXCREATECONTEXTATTRIBSARBPROC create_attribs =
        (PFNGLXCREATECONTEXTATTRIBSARBPROC)glXGetProcAddressARB((const GLubyte *)"glXCreateContextAttribsARB");
    if (!configs || !create_attribs) {
        printf("FAIL: no config or no glXCreateContextAttribsARB\n");
        return 1;
    }
    int core33[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 3, GLX_CONTEXT_PROFILE_MASK_ARB,
                    GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
    for (int i = 0; i < 2; i++) {
        GLXContext ctx = create_attribs(dpy, configs[0], NULL, True, core33);
        XSync(dpy, False);
        if (ctx) {
            printf("FAIL: an OpenGL 3.3 core context was created (try %d)\n", i + 1);
            glXDestroyContext(dpy, ctx);
            failures++;
        }
    }
    if (errors_seen != 2) {
        printf("FAIL: %d X errors for two refusals\n", errors_seen);
        failures++;
    }
    XFree(configs);
    XCloseDisplay(dpy);
    printf("context_notice: %s (%d failures)\n", failures ? "FAILED" : "ok", failures);
    return failures ? 1 : 0;
}
