/* glXMakeContextCurrent with a separate read drawable: glReadPixels, glCopyPixels and
 * glCopyTexImage2D read the read drawable while drawing goes to the draw drawable
 * (GLX 1.4 §3.3.7). Two pbuffers of one configuration: A is cleared red, B green; bound as
 * (draw A, read B), reads give green and copies bring green into A. Run by
 * tools/xvfb-tests.sh; prints one line per failed check, exit status 0 when all hold.
 *
 * Build: gcc -std=c11 -O1 -Wall tests/glx/read_drawable.c -lGL -lX11 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <stdio.h>

#include "check.h"

static void clear(float r, float g, float b)
{
    glClearColor(r, g, b, 1);
    glClear(GL_COLOR_BUFFER_BIT);
}

static void pixel(int x, int y, unsigned char out[4])
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
    int count = 0;
    int attribs[] = {GLX_DOUBLEBUFFER, False, GLX_RED_SIZE, 8, GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, None};
    GLXFBConfig *configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attribs, &count);
    if (!configs) {
        printf("FAIL: no single-buffered pbuffer config\n");
        return 1;
    }
    int size[] = {GLX_PBUFFER_WIDTH, 16, GLX_PBUFFER_HEIGHT, 16, None};
    GLXPbuffer a = glXCreatePbuffer(dpy, configs[0], size);
    GLXPbuffer b = glXCreatePbuffer(dpy, configs[0], size);
    GLXContext ctx = glXCreateNewContext(dpy, configs[0], GLX_RGBA_TYPE, NULL, True);
    CHECK(a && b && ctx, "pbuffers and context");

    unsigned char px[4];
    CHECK(glXMakeContextCurrent(dpy, b, b, ctx), "bind B");
    clear(0, 1, 0);
    CHECK(glXMakeContextCurrent(dpy, a, b, ctx), "bind draw A, read B");
    CHECK(glXGetCurrentDrawable() == a && glXGetCurrentReadDrawable() == b, "current draw and read drawables");
    clear(1, 0, 0);
    pixel(3, 3, px);
    CHECK(px[0] == 0 && px[1] == 255, "glReadPixels read %u,%u,%u (want B's green)", px[0], px[1], px[2]);

    /* glCopyPixels: B's lower-left 4x4 block drawn into A at (8, 8) */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 16, 0, 16, -1, 1);
    glRasterPos2i(8, 8);
    glCopyPixels(0, 0, 4, 4, GL_COLOR);

    /* glCopyTexImage2D from B, drawn into A's lower-left corner */
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(0, 0);
    glTexCoord2f(1, 0);
    glVertex2f(4, 0);
    glTexCoord2f(1, 1);
    glVertex2f(4, 4);
    glTexCoord2f(0, 1);
    glVertex2f(0, 4);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    CHECK(glGetError() == GL_NO_ERROR, "GL errors");

    /* What A holds now: read it by binding A for reading too */
    CHECK(glXMakeContextCurrent(dpy, a, a, ctx), "bind A");
    pixel(9, 9, px);
    CHECK(px[0] == 0 && px[1] == 255, "glCopyPixels brought %u,%u,%u (want B's green)", px[0], px[1], px[2]);
    pixel(1, 1, px);
    CHECK(px[0] == 0 && px[1] == 255, "the glCopyTexImage2D texture drew %u,%u,%u (want B's green)", px[0], px[1],
          px[2]);
    pixel(14, 2, px);
    CHECK(px[0] == 255 && px[1] == 0, "A's clear %u,%u,%u (want red)", px[0], px[1], px[2]);
    CHECK(glXMakeContextCurrent(dpy, b, b, ctx), "bind B");
    pixel(9, 9, px);
    CHECK(px[0] == 0 && px[1] == 255, "B changed: %u,%u,%u", px[0], px[1], px[2]);

    glXMakeContextCurrent(dpy, None, None, NULL);
    glXDestroyContext(dpy, ctx);
    glXDestroyPbuffer(dpy, a);
    glXDestroyPbuffer(dpy, b);
    XFree(configs);
    XCloseDisplay(dpy);
    printf("read_drawable: %s (%d failures)\n", failures ? "FAILED" : "ok", failures);
    return failures ? 1 : 0;
}
