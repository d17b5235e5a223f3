/* A multisampled GLX window: glXChooseFBConfig with GLX_SAMPLE_BUFFERS 1 and GLX_SAMPLES 4
 * gives a 4-sample configuration; GL_SAMPLE_BUFFERS/GL_SAMPLES report it; a white rectangle
 * whose vertical edge lies at x = 10.3 resolves, in column 10, to the fraction of samples
 * left of 0.3 (one of the four at x = 0.125, 0.375, 0.625, 0.875: 64), both in glReadPixels
 * and in what the X server shows after glXSwapBuffers (XGetImage); with GL_MULTISAMPLE
 * disabled the same edge is hard (the centre 10.5 is outside: 0). Exit status 0 on success.
 *
 * Build: gcc -std=c11 -O1 -Wall tests/glx/multisample.c -lGL -lX11 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>

#define SIZE 32

static int failures;
#define CHECK(cond, what)                                                                          \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            printf("FAIL: %s (line %d)\n", what, __LINE__);                                        \
            failures++;                                                                            \
        }                                                                                          \
    } while (0)

static void draw(void)
{
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 1);
    glBegin(GL_QUADS);
    glVertex2f(2.0f, 2.0f);
    glVertex2f(10.3f, 2.0f);
    glVertex2f(10.3f, 30.0f);
    glVertex2f(2.0f, 30.0f);
    glEnd();
}

/* Red channel of columns 8..11 of row 16 in the back buffer, after a swap the front. */
static void read_row(int out[4])
{
    unsigned char px[4][4];
    glReadPixels(8, 16, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (int i = 0; i < 4; i++)
        out[i] = px[i][0];
}

int main(void)
{
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("FAIL: no display\n");
        return 1;
    }
    int screen = DefaultScreen(dpy);
    int attributes[] = {GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 4, GLX_DOUBLEBUFFER, True, None};
    int count = 0;
    GLXFBConfig *configs = glXChooseFBConfig(dpy, screen, attributes, &count);
    if (!configs || count == 0) {
        printf("FAIL: no multisampled configuration\n");
        return 1;
    }
    int sample_buffers = 0, samples = 0;
    glXGetFBConfigAttrib(dpy, configs[0], GLX_SAMPLE_BUFFERS, &sample_buffers);
    glXGetFBConfigAttrib(dpy, configs[0], GLX_SAMPLES, &samples);
    CHECK(sample_buffers == 1 && samples == 4, "the best match has 4 samples");
    XVisualInfo *vis = glXGetVisualFromFBConfig(dpy, configs[0]);
    Window root = RootWindow(dpy, screen);
    XSetWindowAttributes swa = {0};
    swa.colormap = XCreateColormap(dpy, root, vis->visual, AllocNone);
    Window win = XCreateWindow(dpy, root, 0, 0, SIZE, SIZE, 0, vis->depth, InputOutput, vis->visual,
                               CWColormap, &swa);
    XMapWindow(dpy, win);
    XSync(dpy, False);
    GLXContext ctx = glXCreateNewContext(dpy, configs[0], GLX_RGBA_TYPE, NULL, True);
    if (!ctx || !glXMakeContextCurrent(dpy, win, win, ctx)) {
        printf("FAIL: no context\n");
        return 1;
    }
    GLint gl_sample_buffers = 0, gl_samples = 0;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &gl_sample_buffers);
    glGetIntegerv(GL_SAMPLES, &gl_samples);
    CHECK(gl_sample_buffers == 1 && gl_samples == 4, "GL_SAMPLE_BUFFERS/GL_SAMPLES");
    glViewport(0, 0, SIZE, SIZE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, SIZE, 0, SIZE, -1, 1);

    int row[4];
    draw();
    read_row(row);
    printf("multisampled edge: %d %d %d %d\n", row[0], row[1], row[2], row[3]);
    CHECK(row[0] == 255 && row[1] == 255 && row[2] == 64 && row[3] == 0, "resolved edge in the back buffer");
    glXSwapBuffers(dpy, win);
    glFinish();
    XImage *image = XGetImage(dpy, win, 0, 0, SIZE, SIZE, AllPlanes, ZPixmap);
    if (image) {
        /* Row 16 from the bottom is X row SIZE - 1 - 16. */
        unsigned long shown = XGetPixel(image, 10, SIZE - 1 - 16);
        unsigned long red = (shown & image->red_mask) >> __builtin_ctzl(image->red_mask);
        printf("X server shows column 10 as red %lu\n", red);
        CHECK(red == 64, "the window shows the resolved edge");
        XDestroyImage(image);
    } else {
        CHECK(0, "XGetImage");
    }

    glDisable(GL_MULTISAMPLE);
    draw();
    read_row(row);
    CHECK(row[2] == 0 && row[1] == 255, "GL_MULTISAMPLE disabled: pixel centres decide");

    glXMakeContextCurrent(dpy, None, None, NULL);
    glXDestroyContext(dpy, ctx);
    XFree(configs);
    XFree(vis);
    XDestroyWindow(dpy, win);
    XCloseDisplay(dpy);
    if (failures == 0)
        printf("multisample: ok\n");
    return failures ? 1 : 0;
}
