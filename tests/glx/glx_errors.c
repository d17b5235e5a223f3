/* GLX errors reach the application's X error handler as X protocol errors, with the codes
 * the GLX 1.4 specification (and GLX_ARB_create_context) names: the error code (GLX errors
 * offset by the GLX extension's error base), the GLX major opcode and the minor opcode of
 * the request the call stands for. Run by tools/xvfb-tests.sh, once as is and once with
 * argument "threads" (XInitThreads first: Xlib's display lock is then in use).
 * These are the specifications' rules; Mesa 22's GLX (on Xvfb) departs from some of them:
 * it makes a context current without drawables and one current in another thread, accepts
 * glXCreateWindow twice on one window, and reports GLXBadFBConfig for version 9.9; and it
 * provides OpenGL 3.3 core, which tessera (OpenGL 2.1) refuses with GLXBadFBConfig.
 * Xlib's error text names the GLX errors (XGetErrorText gives "GLXBadContext", not a bare
 * number, and Xlib's default error handler prints the name), as with Mesa's libGL.
 * Prints one line per failed check; exit status 0 when all hold.
 *
 * Build: gcc -std=c11 -O1 -Wall tests/glx/glx_errors.c -lGL -lX11 -lpthread */
#define _GNU_SOURCE
#include <GL/gl.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* GLX error codes and request minor opcodes (glxproto.h, which needs the server's headers) */
enum { GLXBadContext = 0, GLXBadDrawable = 2, GLXBadPixmap = 3, GLXBadFBConfig = 9, GLXBadPbuffer = 10, GLXBadWindow = 12,
       GLXBadProfileARB = 13 };
enum { X_GLXDestroyContext = 4, X_GLXMakeCurrent = 5, X_GLXCopyContext = 10, X_GLXDestroyPixmap = 23,
       X_GLXCreateNewContext = 24, X_GLXMakeContextCurrent = 26, X_GLXCreatePbuffer = 27, X_GLXDestroyPbuffer = 28,
       X_GLXGetDrawableAttributes = 29, X_GLXCreateWindow = 31, X_GLXDestroyWindow = 32,
       X_GLXCreateContextAttribsARB = 34 };

#include "check.h"

static int errors_seen, last_code, last_major, last_minor;

static int handler(Display *dpy, XErrorEvent *e)
{
    (void)dpy;
    errors_seen++;
    last_code = e->error_code;
    last_major = e->request_code;
    last_minor = e->minor_code;
    return 0;
}

static int glx_opcode, glx_error_base;

/* Runs nothing itself: checks that exactly one error arrived since `before` with `code`
 * (core when glx is 0, else offset by the GLX error base) for GLX request `minor`. */
static void expect(Display *dpy, int before, int glx, int code, int minor, const char *what)
{
    XSync(dpy, False);
    int want = glx ? glx_error_base + code : code;
    CHECK(errors_seen == before + 1, "%s: %d errors (want 1)", what, errors_seen - before);
    CHECK(last_code == want && last_major == glx_opcode && last_minor == minor,
          "%s: error %d major %d minor %d (want %d, %d, %d)", what, last_code, last_major, last_minor, want,
          glx_opcode, minor);
}

/* The GLX error names of glxproto.h, by code */
static const char *const glx_error_names[] = {
    "GLXBadContext",       "GLXBadContextState",  "GLXBadDrawable",      "GLXBadPixmap",
    "GLXBadContextTag",    "GLXBadCurrentWindow", "GLXBadRenderRequest", "GLXBadLargeRequest",
    "GLXUnsupportedPrivateRequest", "GLXBadFBConfig", "GLXBadPbuffer", "GLXBadCurrentDrawable",
    "GLXBadWindow",        "GLXBadProfileARB"};

/* XGetErrorText of the last error names it */
static void expect_text(Display *dpy, const char *name)
{
    char text[128] = "";
    XGetErrorText(dpy, last_code, text, sizeof text);
    CHECK(strcmp(text, name) == 0, "XGetErrorText(%d) = \"%s\" (want \"%s\")", last_code, text, name);
}

/* Xlib's default error handler, in a child process with its own connection, prints the GLX
 * error's name for an error tessera raises (and exits the child, as it always does). */
static void check_default_handler_text(void)
{
    int fds[2];
    if (pipe(fds) != 0)
        return;
    pid_t child = fork();
    if (child == 0) {
        dup2(fds[1], 2);
        close(fds[0]);
        Display *d = XOpenDisplay(NULL);
        if (!d)
            _exit(3);
        int eb, evb;
        glXQueryExtension(d, &eb, &evb);
        glXDestroyContext(d, (GLXContext)(void *)&eb); /* GLXBadContext, to the default handler */
        XSync(d, False);
        _exit(0); /* not reached: the default handler exits */
    }
    close(fds[1]);
    char out[4096] = "";
    size_t used = 0;
    ssize_t got;
    while (used < sizeof out - 1 && (got = read(fds[0], out + used, sizeof out - 1 - used)) > 0)
        used += (size_t)got;
    close(fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    CHECK(strstr(out, "X Error of failed request:  GLXBadContext") != NULL,
          "the default error handler printed: %s", out);
    CHECK(strstr(out, "(GLX)") != NULL, "the default error handler does not name the GLX extension: %s", out);
}

static Display *thread_dpy;
static GLXContext thread_ctx;
static GLXPbuffer thread_pb;
static pthread_mutex_t mutex = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t cond = PTHREAD_COND_INITIALIZER;
static int stage;

static void *hold_context(void *arg)
{
    (void)arg;
    glXMakeContextCurrent(thread_dpy, thread_pb, thread_pb, thread_ctx);
    pthread_mutex_lock(&mutex);
    stage = 1;
    pthread_cond_broadcast(&cond);
    while (stage != 2)
        pthread_cond_wait(&cond, &mutex);
    pthread_mutex_unlock(&mutex);
    glXMakeContextCurrent(thread_dpy, None, None, NULL);
    return NULL;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "threads") == 0)
        XInitThreads();
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("cannot open display\n");
        return 2;
    }
    int event_base;
    if (!XQueryExtension(dpy, "GLX", &glx_opcode, &event_base, &glx_error_base)) {
        printf("glx_errors: the X server has no GLX extension: nothing to check\n");
        return 1;
    }
    int error_base = -1;
    glXQueryExtension(dpy, &error_base, &event_base);
    CHECK(error_base == glx_error_base, "glXQueryExtension error base %d, server's %d", error_base, glx_error_base);
    /* Xlib names every GLX error code (the extension registered by tessera) */
    for (int i = 0; i < (int)(sizeof glx_error_names / sizeof *glx_error_names); i++) {
        char text[128] = "";
        XGetErrorText(dpy, glx_error_base + i, text, sizeof text);
        CHECK(strcmp(text, glx_error_names[i]) == 0, "XGetErrorText(GLX error %d) = \"%s\" (want \"%s\")", i,
              text, glx_error_names[i]);
    }
    char core_text[128] = "";
    XGetErrorText(dpy, BadMatch, core_text, sizeof core_text);
    CHECK(strstr(core_text, "BadMatch") != NULL, "XGetErrorText(BadMatch) = \"%s\"", core_text);
    check_default_handler_text();
    XSetErrorHandler(handler);
    int screen = DefaultScreen(dpy), count = 0;
    int attribs[] = {GLX_DOUBLEBUFFER, True, GLX_RED_SIZE, 8, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT | GLX_PBUFFER_BIT, None};
    GLXFBConfig *configs = glXChooseFBConfig(dpy, screen, attribs, &count);
    if (!configs) {
        printf("FAIL: no config\n");
        return 1;
    }
    GLXFBConfig config = configs[0];
    XFree(configs);
    int pb_attribs[] = {GLX_PBUFFER_WIDTH, 8, GLX_PBUFFER_HEIGHT, 8, None};
    GLXPbuffer pb = glXCreatePbuffer(dpy, config, pb_attribs);
    GLXContext ctx = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, NULL, True);
    CHECK(pb && ctx, "pbuffer and context");
    XSync(dpy, False);
    CHECK(errors_seen == 0, "%d errors from valid calls", errors_seen);
    GLXContext bogus = (GLXContext)(void *)&count; /* an address that is no context */

    int n = errors_seen;
    CHECK(!glXMakeContextCurrent(dpy, pb, pb, bogus), "bogus context made current");
    expect(dpy, n, 1, GLXBadContext, X_GLXMakeContextCurrent, "glXMakeContextCurrent(bogus context)");
    expect_text(dpy, "GLXBadContext");
    n = errors_seen;
    CHECK(!glXMakeCurrent(dpy, pb, NULL), "no context with a drawable");
    expect(dpy, n, 0, BadMatch, X_GLXMakeCurrent, "glXMakeCurrent(drawable, NULL)");
    n = errors_seen;
    CHECK(!glXMakeContextCurrent(dpy, None, None, ctx), "context without drawables");
    expect(dpy, n, 0, BadMatch, X_GLXMakeContextCurrent, "glXMakeContextCurrent(None, None, ctx)");
    n = errors_seen;
    glXDestroyContext(dpy, bogus);
    expect(dpy, n, 1, GLXBadContext, X_GLXDestroyContext, "glXDestroyContext(bogus)");
    n = errors_seen;
    CHECK(glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, bogus, True) == NULL, "bogus share context");
    expect(dpy, n, 1, GLXBadContext, X_GLXCreateNewContext, "glXCreateNewContext(share bogus)");
    n = errors_seen;
    CHECK(glXCreateNewContext(dpy, config, 0x1234, NULL, True) == NULL, "render type 0x1234");
    expect(dpy, n, 0, BadValue, X_GLXCreateNewContext, "glXCreateNewContext(render type 0x1234)");
    n = errors_seen;
    glXCopyContext(dpy, ctx, ctx, GL_ALL_ATTRIB_BITS);
    expect(dpy, n, 0, BadMatch, X_GLXCopyContext, "glXCopyContext(ctx, ctx)");
    n = errors_seen;
    glXDestroyPbuffer(dpy, 0x7fffff0);
    expect(dpy, n, 1, GLXBadPbuffer, X_GLXDestroyPbuffer, "glXDestroyPbuffer(bogus)");
    n = errors_seen;
    glXDestroyWindow(dpy, 0x7fffff0);
    expect(dpy, n, 1, GLXBadWindow, X_GLXDestroyWindow, "glXDestroyWindow(bogus)");
    expect_text(dpy, "GLXBadWindow");
    n = errors_seen;
    glXDestroyPixmap(dpy, 0x7fffff0);
    expect(dpy, n, 1, GLXBadPixmap, X_GLXDestroyPixmap, "glXDestroyPixmap(bogus)");
    n = errors_seen;
    CHECK(glXCreatePbuffer(dpy, (GLXFBConfig)(void *)&count, pb_attribs) == 0, "pbuffer of a bogus config");
    expect(dpy, n, 1, GLXBadFBConfig, X_GLXCreatePbuffer, "glXCreatePbuffer(bogus config)");

    /* glXCreateWindow twice on one window: BadAlloc */
    XVisualInfo *vis = glXGetVisualFromFBConfig(dpy, config);
    XSetWindowAttributes swa = {0};
    swa.colormap = XCreateColormap(dpy, RootWindow(dpy, screen), vis->visual, AllocNone);
    Window win = XCreateWindow(dpy, RootWindow(dpy, screen), 0, 0, 16, 16, 0, vis->depth, InputOutput, vis->visual,
                               CWColormap, &swa);
    XSync(dpy, False);
    n = errors_seen;
    GLXWindow glxwin = glXCreateWindow(dpy, config, win, NULL);
    CHECK(glxwin != 0, "glXCreateWindow");
    CHECK(glXCreateWindow(dpy, config, win, NULL) == 0, "second glXCreateWindow on one window");
    expect(dpy, n, 0, BadAlloc, X_GLXCreateWindow, "glXCreateWindow twice");

    /* Drawable queries and swaps of something that is no GLX drawable */
    unsigned int value = 0;
    n = errors_seen;
    glXQueryDrawable(dpy, 0x7fffff0, GLX_WIDTH, &value);
    expect(dpy, n, 1, GLXBadDrawable, X_GLXGetDrawableAttributes, "glXQueryDrawable(bogus)");

    /* GLX_ARB_create_context */
    PFNGLXCREATECONTEXTATTRIBSARBPROC create_attribs =
        (PFNGLXCREATECONTEXTATTRIBSARBPROC)glXGetProcAddressARB((const GLubyte *)"glXCreateContextAttribsARB");
    if (create_attribs) {
        int unknown[] = {0x7777, 1, None};
        n = errors_seen;
        CHECK(create_attribs(dpy, config, NULL, True, unknown) == NULL, "unknown attribute");
        expect(dpy, n, 0, BadValue, X_GLXCreateContextAttribsARB, "glXCreateContextAttribsARB(unknown attribute)");
        int v99[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 9, GLX_CONTEXT_MINOR_VERSION_ARB, 9, None};
        n = errors_seen;
        CHECK(create_attribs(dpy, config, NULL, True, v99) == NULL, "version 9.9");
        expect(dpy, n, 0, BadMatch, X_GLXCreateContextAttribsARB, "glXCreateContextAttribsARB(9.9)");
        int bad_profile[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 2,
                             GLX_CONTEXT_PROFILE_MASK_ARB, 0x40, None};
        n = errors_seen;
        CHECK(create_attribs(dpy, config, NULL, True, bad_profile) == NULL, "profile mask 0x40");
        expect(dpy, n, 1, GLXBadProfileARB, X_GLXCreateContextAttribsARB, "glXCreateContextAttribsARB(bad profile)");
        expect_text(dpy, "GLXBadProfileARB");
        int v33[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 3, GLX_CONTEXT_PROFILE_MASK_ARB,
                     GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
        n = errors_seen;
        CHECK(create_attribs(dpy, config, NULL, True, v33) == NULL, "version 3.3 core");
        expect(dpy, n, 1, GLXBadFBConfig, X_GLXCreateContextAttribsARB, "glXCreateContextAttribsARB(3.3 core)");
        expect_text(dpy, "GLXBadFBConfig");
    } else {
        CHECK(0, "no glXCreateContextAttribsARB");
    }

    /* A context current in another thread: BadAccess */
    thread_dpy = dpy;
    thread_ctx = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, NULL, True);
    thread_pb = glXCreatePbuffer(dpy, config, pb_attribs);
    XSync(dpy, False);
    pthread_t thread;
    pthread_create(&thread, NULL, hold_context, NULL);
    pthread_mutex_lock(&mutex);
    while (stage != 1)
        pthread_cond_wait(&cond, &mutex);
    pthread_mutex_unlock(&mutex);
    n = errors_seen;
    CHECK(!glXMakeContextCurrent(dpy, pb, pb, thread_ctx), "a context current in another thread");
    expect(dpy, n, 0, BadAccess, X_GLXMakeContextCurrent, "glXMakeContextCurrent(context of another thread)");
    pthread_mutex_lock(&mutex);
    stage = 2;
    pthread_cond_broadcast(&cond);
    pthread_mutex_unlock(&mutex);
    pthread_join(thread, NULL);

    /* Valid calls still report nothing */
    n = errors_seen;
    CHECK(glXMakeContextCurrent(dpy, pb, pb, ctx), "valid make current");
    glXMakeContextCurrent(dpy, None, None, NULL);
    XSync(dpy, False);
    CHECK(errors_seen == n, "valid calls reported %d errors", errors_seen - n);

    glXDestroyContext(dpy, thread_ctx);
    glXDestroyContext(dpy, ctx);
    glXDestroyPbuffer(dpy, thread_pb);
    glXDestroyPbuffer(dpy, pb);
    glXDestroyWindow(dpy, glxwin);
    XDestroyWindow(dpy, win);
    XFree(vis);
    XCloseDisplay(dpy);
    printf("glx_errors%s: %s (%d failures)\n", argc > 1 ? " (threads)" : "", failures ? "FAILED" : "ok", failures);
    return failures ? 1 : 0;
}
