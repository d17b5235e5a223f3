/* The GLX 1.4 API on tessera (run by tools/xvfb-tests.sh under Xvfb): queries, FBConfig
 * selection and attributes, context creation rules (GLX_ARB_create_context), windows with
 * front-buffer drawing presented at glFlush, resizing, pbuffers, pixmaps, stereo buffers,
 * glXCopyContext and glXGetProcAddress. Prints one line per failed check; exit status 0 when
 * all hold.
 *
 * Build: gcc -std=c11 -O1 -Wall tests/glx/glx_api.c -lGL -lX11 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

static int attrib(Display *dpy, GLXFBConfig c, int a)
{
    int v = -12345;
    CHECK(glXGetFBConfigAttrib(dpy, c, a, &v) == Success, "attribute 0x%x", a);
    return v;
}

static Window make_window(Display *dpy, XVisualInfo *vis, int x, int w, int h)
{
    XSetWindowAttributes swa = {0};
    swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vis->screen), vis->visual, AllocNone);
    Window win = XCreateWindow(dpy, RootWindow(dpy, vis->screen), x, 0, w, h, 0, vis->depth, InputOutput, vis->visual,
                               CWColormap, &swa);
    XMapWindow(dpy, win);
    XSync(dpy, False);
    return win;
}

static unsigned long shown(Display *dpy, Drawable d, int x, int y)
{
    XSync(dpy, False);
    XImage *img = XGetImage(dpy, d, x, y, 1, 1, AllPlanes, ZPixmap);
    if (!img)
        return 0xdeadbeef;
    unsigned long p = XGetPixel(img, 0, 0) & 0xffffff;
    XDestroyImage(img);
    return p;
}

/* The refused requests below generate X protocol errors (tests/glx/glx_errors.c checks
 * them); Xlib's default handler would end the program. */
static int ignore_x_errors(Display *dpy, XErrorEvent *e)
{
    (void)dpy;
    (void)e;
    return 0;
}

static void read_rgb(int x, int y, unsigned char out[4])
{
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
}

int main(void)
{
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("cannot open display\n");
        return 2;
    }
    int screen = DefaultScreen(dpy);
    XSetErrorHandler(ignore_x_errors);

    /* Queries */
    int error_base, event_base, major = 0, minor = 0;
    CHECK(glXQueryExtension(dpy, &error_base, &event_base), "glXQueryExtension");
    CHECK(glXQueryVersion(dpy, &major, &minor) && major == 1 && minor == 4, "version %d.%d", major, minor);
    const char *ext = glXQueryExtensionsString(dpy, screen);
    CHECK(ext && strstr(ext, "GLX_ARB_create_context"), "extensions %s", ext ? ext : "(null)");
    CHECK(glXGetClientString(dpy, GLX_VENDOR) && glXQueryServerString(dpy, screen, GLX_VERSION), "strings");

    /* FBConfigs: every combination asked for exists and reports what was asked */
    int count = 0;
    GLXFBConfig *all = glXGetFBConfigs(dpy, screen, &count);
    CHECK(all && count >= 40, "glXGetFBConfigs: %d", count);
    XFree(all);
    const int depths[] = {0, 16, 24}, stencils[] = {0, 8}, accums[] = {0, 16};
    for (int db = 0; db < 2; db++)
        for (int d = 0; d < 3; d++)
            for (int s = 0; s < 2; s++)
                for (int a = 0; a < 2; a++) {
                    int want[] = {GLX_DOUBLEBUFFER, db, GLX_DEPTH_SIZE, depths[d], GLX_STENCIL_SIZE, stencils[s],
                                  GLX_ACCUM_RED_SIZE, accums[a], GLX_RED_SIZE, 8, GLX_RENDER_TYPE, GLX_RGBA_BIT,
                                  GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT | GLX_PBUFFER_BIT, None};
                    GLXFBConfig *c = glXChooseFBConfig(dpy, screen, want, &count);
                    CHECK(c && count > 0, "no config db=%d depth=%d stencil=%d accum=%d", db, depths[d], stencils[s],
                          accums[a]);
                    if (!c)
                        continue;
                    CHECK(attrib(dpy, c[0], GLX_DOUBLEBUFFER) == db, "double");
                    CHECK(attrib(dpy, c[0], GLX_DEPTH_SIZE) >= depths[d], "depth");
                    CHECK(attrib(dpy, c[0], GLX_STENCIL_SIZE) == stencils[s], "stencil: smallest first");
                    CHECK(attrib(dpy, c[0], GLX_ACCUM_RED_SIZE) >= accums[a], "accum");
                    CHECK(attrib(dpy, c[0], GLX_X_VISUAL_TYPE) == GLX_TRUE_COLOR, "TrueColor first");
                    XFree(c);
                }
    int impossible[] = {GLX_SAMPLES, 16, None};
    CHECK(glXChooseFBConfig(dpy, screen, impossible, &count) == NULL && count == 0, "16-sample config offered");

    int rgba_db[] = {GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 24, GLX_STENCIL_SIZE, 8, GLX_ALPHA_SIZE, 8, None};
    GLXFBConfig *configs = glXChooseFBConfig(dpy, screen, rgba_db, &count);
    if (!configs) {
        printf("FAIL: no double-buffered RGBA config\n");
        return 1;
    }
    GLXFBConfig config = configs[0];
    XFree(configs);
    XVisualInfo *vis = glXGetVisualFromFBConfig(dpy, config);
    CHECK(vis && (int)vis->visualid == attrib(dpy, config, GLX_VISUAL_ID), "visual of the config");

    /* Context creation rules */
    PFNGLXCREATECONTEXTATTRIBSARBPROC create_attribs =
        (PFNGLXCREATECONTEXTATTRIBSARBPROC)glXGetProcAddressARB((const GLubyte *)"glXCreateContextAttribsARB");
    CHECK(create_attribs != NULL, "glXGetProcAddressARB(glXCreateContextAttribsARB)");
    if (create_attribs) {
        /* Every compatibility version up to 2.1 is created; 3.0 and later are refused. */
        static const int accepted[][2] = {{1, 0}, {1, 1}, {1, 5}, {2, 0}, {2, 1}};
        for (unsigned i = 0; i < sizeof accepted / sizeof accepted[0]; i++) {
            int version[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, accepted[i][0], GLX_CONTEXT_MINOR_VERSION_ARB,
                             accepted[i][1], None};
            GLXContext c = create_attribs(dpy, config, NULL, True, version);
            CHECK(c != NULL, "%d.%d compatibility context refused", accepted[i][0], accepted[i][1]);
            if (c)
                glXDestroyContext(dpy, c);
        }
        int v30[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 0, None};
        int core[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 2,
                      GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
        int fwd[] = {GLX_CONTEXT_FLAGS_ARB, GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB, None};
        CHECK(create_attribs(dpy, config, NULL, True, v30) == NULL, "3.0 context created (version is 2.1)");
        CHECK(create_attribs(dpy, config, NULL, True, core) == NULL, "3.2 core context created");
        CHECK(create_attribs(dpy, config, NULL, True, fwd) == NULL, "forward-compatible 1.0 context created");
    }
    CHECK(glXCreateNewContext(dpy, config, GLX_COLOR_INDEX_TYPE, NULL, True) == NULL, "color-index context");

    /* A window: viewport at the window size, front-buffer drawing shown at glFlush */
    Window win = make_window(dpy, vis, 0, 80, 60);
    GLXWindow glxwin = glXCreateWindow(dpy, config, win, NULL);
    GLXContext ctx = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, NULL, True);
    CHECK(ctx && glXIsDirect(dpy, ctx), "context");
    CHECK(glXMakeContextCurrent(dpy, glxwin, glxwin, ctx), "glXMakeContextCurrent");
    CHECK(glXGetCurrentContext() == ctx && glXGetCurrentDrawable() == glxwin && glXGetCurrentReadDrawable() == glxwin &&
              glXGetCurrentDisplay() == dpy,
          "current queries");
    int vp[4], sc[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    glGetIntegerv(GL_SCISSOR_BOX, sc);
    CHECK(vp[2] == 80 && vp[3] == 60 && sc[2] == 80 && sc[3] == 60, "viewport %dx%d scissor %dx%d", vp[2], vp[3],
          sc[2], sc[3]);
    GLint db = 0, drawbuf = 0;
    glGetIntegerv(GL_DOUBLEBUFFER, &db);
    glGetIntegerv(GL_DRAW_BUFFER, &drawbuf);
    CHECK(db == 1 && drawbuf == GL_BACK, "double buffered, drawing to GL_BACK");
    unsigned int w = 0, h = 0;
    glXQueryDrawable(dpy, glxwin, GLX_WIDTH, &w);
    glXQueryDrawable(dpy, glxwin, GLX_HEIGHT, &h);
    CHECK(w == 80 && h == 60, "glXQueryDrawable %ux%u", w, h);

    glDrawBuffer(GL_FRONT);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFlush();
    CHECK(shown(dpy, win, 10, 10) == 0xff0000, "front-buffer clear shown at glFlush: %06lx", shown(dpy, win, 10, 10));
    unsigned char px[4];
    glReadBuffer(GL_FRONT);
    read_rgb(5, 5, px);
    CHECK(px[0] == 255 && px[1] == 0 && px[3] == 255, "front read %u,%u,%u,%u", px[0], px[1], px[2], px[3]);

    /* Back buffer, swap: the front gets the back's picture */
    glDrawBuffer(GL_BACK);
    glClearColor(0, 0, 1, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK(shown(dpy, win, 10, 10) == 0xff0000, "back-buffer drawing shown before the swap");
    glXSwapBuffers(dpy, glxwin);
    CHECK(shown(dpy, win, 10, 10) == 0x0000ff, "swap not shown: %06lx", shown(dpy, win, 10, 10));
    read_rgb(5, 5, px);
    CHECK(px[2] == 255 && px[3] == 128, "front after swap %u,%u,%u,%u (alpha kept)", px[0], px[1], px[2], px[3]);

    /* Resizing: the buffers follow at the next swap */
    XResizeWindow(dpy, win, 120, 90);
    XSync(dpy, False);
    glXSwapBuffers(dpy, glxwin);
    glXQueryDrawable(dpy, glxwin, GLX_WIDTH, &w);
    glXQueryDrawable(dpy, glxwin, GLX_HEIGHT, &h);
    CHECK(w == 120 && h == 90, "after resize %ux%u", w, h);
    glViewport(0, 0, 120, 90);
    glScissor(0, 0, 120, 90);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy, glxwin);
    CHECK(shown(dpy, win, 110, 85) == 0x00ff00, "resized window: %06lx", shown(dpy, win, 110, 85));

    /* glXCopyContext: GL_COLOR_BUFFER_BIT carries the clear color */
    GLXContext other = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, NULL, True);
    glXCopyContext(dpy, ctx, other, GL_COLOR_BUFFER_BIT);

    /* A pbuffer */
    int pb_attribs[] = {GLX_PBUFFER_WIDTH, 32, GLX_PBUFFER_HEIGHT, 16, None};
    GLXPbuffer pb = glXCreatePbuffer(dpy, config, pb_attribs);
    CHECK(pb != 0, "pbuffer");
    CHECK(glXMakeContextCurrent(dpy, pb, pb, other), "current on the pbuffer");
    GLfloat clear[4];
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    CHECK(clear[1] == 1.0f && clear[0] == 0.0f, "glXCopyContext: clear color %g,%g", clear[0], clear[1]);
    glGetIntegerv(GL_VIEWPORT, vp);
    CHECK(vp[2] == 32 && vp[3] == 16, "pbuffer viewport %dx%d", vp[2], vp[3]);
    glClearColor(0.5f, 0.25f, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadBuffer(GL_BACK);
    read_rgb(31, 15, px);
    CHECK(px[0] == 128 && px[1] == 64 && px[2] == 255, "pbuffer read %u,%u,%u", px[0], px[1], px[2]);
    glXQueryDrawable(dpy, pb, GLX_WIDTH, &w);
    CHECK(w == 32, "pbuffer width %u", w);
    glXMakeContextCurrent(dpy, None, None, NULL);
    CHECK(glXGetCurrentContext() == NULL && glXGetCurrentDrawable() == None, "released");
    glXDestroyPbuffer(dpy, pb);

    /* A pixmap, single buffered */
    int single[] = {GLX_DOUBLEBUFFER, False, GLX_DRAWABLE_TYPE, GLX_PIXMAP_BIT, None};
    GLXFBConfig *sc_configs = glXChooseFBConfig(dpy, screen, single, &count);
    if (sc_configs) {
        XVisualInfo *svis = glXGetVisualFromFBConfig(dpy, sc_configs[0]);
        Pixmap pixmap = XCreatePixmap(dpy, RootWindow(dpy, screen), 16, 16, svis->depth);
        GLXPixmap glxpix = glXCreatePixmap(dpy, sc_configs[0], pixmap, NULL);
        GLXContext pctx = glXCreateNewContext(dpy, sc_configs[0], GLX_RGBA_TYPE, NULL, True);
        CHECK(glxpix && pctx && glXMakeCurrent(dpy, glxpix, pctx), "current on a pixmap");
        glClearColor(1, 1, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        CHECK(shown(dpy, pixmap, 3, 3) == 0xffff00, "pixmap shows %06lx", shown(dpy, pixmap, 3, 3));
        glXMakeCurrent(dpy, None, NULL);
        glXDestroyContext(dpy, pctx);
        glXDestroyPixmap(dpy, glxpix);
        XFreePixmap(dpy, pixmap);
        XFree(svis);
        XFree(sc_configs);
    } else {
        CHECK(0, "no single-buffered pixmap config");
    }

    /* Stereo: four color buffers, the left one shown */
    int stereo[] = {GLX_STEREO, True, GLX_DOUBLEBUFFER, True, None};
    GLXFBConfig *st = glXChooseFBConfig(dpy, screen, stereo, &count);
    CHECK(st != NULL, "stereo config");
    if (st) {
        XVisualInfo *svis = glXGetVisualFromFBConfig(dpy, st[0]);
        Window swin = make_window(dpy, svis, 200, 20, 20);
        GLXContext sctx = glXCreateNewContext(dpy, st[0], GLX_RGBA_TYPE, NULL, True);
        CHECK(glXMakeCurrent(dpy, swin, sctx), "stereo current");
        GLboolean is_stereo = 0;
        glGetBooleanv(GL_STEREO, &is_stereo);
        CHECK(is_stereo, "GL_STEREO");
        glDrawBuffer(GL_BACK_RIGHT);
        glClearColor(1, 0, 1, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawBuffer(GL_BACK_LEFT);
        glClearColor(0, 1, 1, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        CHECK(glGetError() == GL_NO_ERROR, "stereo draw buffers");
        glXSwapBuffers(dpy, swin);
        glReadBuffer(GL_FRONT_RIGHT);
        read_rgb(2, 2, px);
        CHECK(px[0] == 255 && px[1] == 0 && px[2] == 255, "front right %u,%u,%u", px[0], px[1], px[2]);
        CHECK(shown(dpy, swin, 2, 2) == 0x00ffff, "stereo window shows %06lx", shown(dpy, swin, 2, 2));
        glXMakeCurrent(dpy, None, NULL);
        glXDestroyContext(dpy, sctx);
        XFree(svis);
        XFree(st);
    }

    /* glXSelectEvent's mask reads back (tessera never clobbers a buffer, so no event comes). */
    unsigned long selected = 1234;
    glXSelectEvent(dpy, glxwin, GLX_PBUFFER_CLOBBER_MASK);
    glXGetSelectedEvent(dpy, glxwin, &selected);
    CHECK(selected == GLX_PBUFFER_CLOBBER_MASK, "glXGetSelectedEvent gave %lu", selected);

    /* glXUseXFont: the server's "fixed" font as display lists drawing glBitmap glyphs, which
     * advance the raster position; a context created sharing ctx sees the lists. */
    CHECK(glXMakeContextCurrent(dpy, glxwin, glxwin, ctx), "current again for glXUseXFont");
    Font font = XLoadFont(dpy, "fixed");
    GLuint base = glGenLists(128);
    glXUseXFont(font, 0, 128, base);
    CHECK(glIsList(base + 'H') && glIsList(base + 'I'), "glXUseXFont made no lists");
    glDisable(GL_SCISSOR_TEST);
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_BACK);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 80, 0, 60, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1, 1, 1);
    glRasterPos2i(4, 20);
    GLint start[4], raster[4];
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, start);
    glListBase(base);
    glCallLists(2, GL_UNSIGNED_BYTE, "HI");
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, raster);
    /* "fixed" is a 6-pixel-wide font: two glyphs advance by 12. */
    CHECK(raster[0] - start[0] == 12 && raster[1] == start[1], "glyphs advanced the raster position by (%d, %d)",
          raster[0] - start[0], raster[1] - start[1]);
    static unsigned char text[80 * 60 * 4];
    glReadPixels(0, 0, 80, 60, GL_RGBA, GL_UNSIGNED_BYTE, text);
    int lit = 0;
    for (int i = 0; i < 80 * 60; i++)
        lit += text[4 * i] == 255;
    CHECK(lit >= 15, "the glyphs drew %d pixels", lit);
    GLXContext sharing = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, ctx, True);
    CHECK(sharing && glXMakeContextCurrent(dpy, glxwin, glxwin, sharing) && glIsList(base + 'H'),
          "a context sharing ctx does not see its display lists");
    glXMakeContextCurrent(dpy, glxwin, glxwin, ctx);
    if (sharing)
        glXDestroyContext(dpy, sharing);
    XUnloadFont(dpy, font);

    /* glXGetProcAddress reaches every exported function, GLX included */
    const char *names[] = {"glClear", "glBlendEquationSeparate", "glStencilOpSeparate", "glDrawBuffers",
                           "glXSwapIntervalMESA", "glXChooseFBConfig", "glBlendFuncSeparateEXT"};
    for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
        CHECK(glXGetProcAddress((const GLubyte *)names[i]) != NULL, "glXGetProcAddress(%s)", names[i]);
    CHECK(glXGetProcAddress((const GLubyte *)"glNoSuchThing") == NULL, "unknown name resolved");

    glXDestroyContext(dpy, other);
    glXDestroyContext(dpy, ctx);
    glXDestroyWindow(dpy, glxwin);
    XFree(vis);
    XCloseDisplay(dpy);
    printf("glx_api: %s (%d failures)\n", failures ? "FAILED" : "ok", failures);
    return failures ? 1 : 0;
}
