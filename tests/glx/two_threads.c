/* Two GLX contexts on two windows, each current in its own thread, render independently:
 * every thread clears its window to its own color, draws its own triangle, swaps, and checks
 * with glReadPixels (front buffer after the swap) and with XGetImage (what the X server shows)
 * that it sees its own picture and never the other thread's. Exit status 0 on success.
 *
 * Then a context current in another thread cannot be made current here (BadAccess), and the
 * refusal leaves this thread's own context current and working.
 *
 * Build: gcc -std=c11 -O1 -Wall tests/glx/two_threads.c -lGL -lX11 -lpthread */
#define _POSIX_C_SOURCE 200112L
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

#define SIZE 64
#define FRAMES 40

struct job {
    Display *dpy;
    Window win;
    XVisualInfo *vis;
    float clear[3];
    float tri[3];
    int failures;
};

static int near(unsigned a, float b)
{
    int want = (int)(b * 255.0f + 0.5f);
    return abs((int)a - want) <= 1;
}

static void *render(void *arg)
{
    struct job *job = arg;
    GLXContext ctx = glXCreateContext(job->dpy, job->vis, NULL, True);
    if (!ctx || !glXMakeCurrent(job->dpy, job->win, ctx)) {
        fprintf(stderr, "no context\n");
        job->failures++;
        return NULL;
    }
    for (int frame = 0; frame < FRAMES; frame++) {
        glClearColor(job->clear[0], job->clear[1], job->clear[2], 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor3fv(job->tri);
        glBegin(GL_TRIANGLES);
        glVertex2f(-0.5f, -0.5f);
        glVertex2f(0.5f, -0.5f);
        glVertex2f(0.0f, 0.5f);
        glEnd();
        glXSwapBuffers(job->dpy, job->win);
        unsigned char px[2][4];
        glReadBuffer(GL_FRONT);
        glReadPixels(SIZE / 2, SIZE / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[0]);
        glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[1]);
        if (!near(px[0][0], job->tri[0]) || !near(px[0][1], job->tri[1]) || !near(px[0][2], job->tri[2]) ||
            !near(px[1][0], job->clear[0]) || !near(px[1][1], job->clear[1]) || !near(px[1][2], job->clear[2])) {
            fprintf(stderr, "frame %d: read %u,%u,%u / %u,%u,%u\n", frame, px[0][0], px[0][1], px[0][2], px[1][0],
                    px[1][1], px[1][2]);
            job->failures++;
        }
    }
    glXMakeCurrent(job->dpy, None, NULL);
    glXDestroyContext(job->dpy, ctx);
    return NULL;
}

static pthread_barrier_t barrier;

/* Keeps a context current in its own thread until the main thread has tried to take it. */
struct holder {
    Display *dpy;
    Window win;
    GLXContext ctx;
    int ok;
};

static void *hold(void *arg)
{
    struct holder *h = arg;
    h->ok = glXMakeCurrent(h->dpy, h->win, h->ctx);
    pthread_barrier_wait(&barrier); /* current now */
    pthread_barrier_wait(&barrier); /* main thread has tried */
    glXMakeCurrent(h->dpy, None, NULL);
    return NULL;
}

/* The X errors received (the refused glXMakeCurrent below generates BadAccess). */
static int bad_access_errors;

static int count_x_errors(Display *dpy, XErrorEvent *e)
{
    (void)dpy;
    if (e->error_code == BadAccess)
        bad_access_errors++;
    return 0;
}

static int check_busy_context(Display *dpy, XVisualInfo *vis, Window a, Window b)
{
    XErrorHandler previous = XSetErrorHandler(count_x_errors);
    int failures = 0;
    GLXContext busy = glXCreateContext(dpy, vis, NULL, True), mine = glXCreateContext(dpy, vis, NULL, True);
    struct holder h = {dpy, a, busy, 0};
    pthread_t t;
    pthread_barrier_init(&barrier, NULL, 2);
    pthread_create(&t, NULL, hold, &h);
    pthread_barrier_wait(&barrier);
    if (!glXMakeCurrent(dpy, b, mine))
        failures++;
    if (glXMakeCurrent(dpy, b, busy)) {
        fprintf(stderr, "a context current in another thread was made current here\n");
        failures++;
    }
    XSync(dpy, False);
    if (bad_access_errors != 1) {
        fprintf(stderr, "the refusal generated %d BadAccess errors (want 1)\n", bad_access_errors);
        failures++;
    }
    XSetErrorHandler(previous);
    if (glXGetCurrentContext() != mine) {
        fprintf(stderr, "the refused glXMakeCurrent changed the current context\n");
        failures++;
    }
    unsigned char px[4] = {0};
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    if (px[0] != 255 || px[1] != 0) {
        fprintf(stderr, "own context no longer renders after the refusal: %u,%u\n", px[0], px[1]);
        failures++;
    }
    pthread_barrier_wait(&barrier);
    pthread_join(t, NULL);
    if (!h.ok)
        failures++;
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, busy);
    glXDestroyContext(dpy, mine);
    return failures;
}

int main(void)
{
    if (!XInitThreads())
        return 2;
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy) {
        fprintf(stderr, "cannot open display\n");
        return 2;
    }
    int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, None};
    XVisualInfo *vis = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
    if (!vis) {
        fprintf(stderr, "no visual\n");
        return 1;
    }
    const char *renderer = NULL;
    struct job jobs[2] = {
        {dpy, 0, vis, {0.0f, 0.0f, 1.0f}, {1.0f, 1.0f, 0.0f}, 0},
        {dpy, 0, vis, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 1.0f}, 0},
    };
    for (int i = 0; i < 2; i++) {
        XSetWindowAttributes swa = {0};
        swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vis->screen), vis->visual, AllocNone);
        jobs[i].win = XCreateWindow(dpy, RootWindow(dpy, vis->screen), 10 + i * 100, 10, SIZE, SIZE, 0, vis->depth,
                                    InputOutput, vis->visual, CWColormap, &swa);
        XMapWindow(dpy, jobs[i].win);
    }
    XSync(dpy, False);
    pthread_t threads[2];
    for (int i = 0; i < 2; i++)
        pthread_create(&threads[i], NULL, render, &jobs[i]);
    for (int i = 0; i < 2; i++)
        pthread_join(threads[i], NULL);
    XSync(dpy, False);
    int failures = jobs[0].failures + jobs[1].failures;
    /* What the X server shows: each window's centre and corner. */
    for (int i = 0; i < 2; i++) {
        XImage *img = XGetImage(dpy, jobs[i].win, 0, 0, SIZE, SIZE, AllPlanes, ZPixmap);
        if (!img) {
            failures++;
            continue;
        }
        unsigned long centre = XGetPixel(img, SIZE / 2, SIZE / 2), corner = XGetPixel(img, 1, SIZE - 2);
        unsigned long want_centre = (jobs[i].tri[0] ? 0xff0000 : 0) | (jobs[i].tri[1] ? 0xff00 : 0) | (jobs[i].tri[2] ? 0xff : 0);
        unsigned long want_corner = (jobs[i].clear[0] ? 0xff0000 : 0) | (jobs[i].clear[1] ? 0xff00 : 0) | (jobs[i].clear[2] ? 0xff : 0);
        if ((centre & 0xffffff) != want_centre || (corner & 0xffffff) != want_corner) {
            fprintf(stderr, "window %d shows %06lx / %06lx, want %06lx / %06lx\n", i, centre, corner, want_centre, want_corner);
            failures++;
        }
        XDestroyImage(img);
    }
    failures += check_busy_context(dpy, vis, jobs[0].win, jobs[1].win);
    GLXContext probe = glXCreateContext(dpy, vis, NULL, True);
    if (probe && glXMakeCurrent(dpy, jobs[0].win, probe))
        renderer = (const char *)glGetString(GL_RENDERER);
    printf("renderer: %s\n", renderer ? renderer : "(none)");
    glXMakeCurrent(dpy, None, NULL);
    printf("two_threads: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
