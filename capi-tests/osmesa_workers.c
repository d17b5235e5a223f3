/* Frames large enough to be rendered by several worker threads (several rows of 64x64
 * tiles), from several application threads at once and from forked children.
 *
 * tessera's workers are shared by every context and parked between scenes (src/pool): each
 * thread's picture must still be its own and exact while the others render, and a child
 * forked after the parent rendered (the workers do not survive fork) must render the same
 * picture, then the parent again. The threaded part gives the same values on Mesa; the fork
 * part is checked on tessera only: Mesa 22's llvmpipe hangs in a child forked after the
 * parent rendered (its rasterizer threads do not survive fork, and nothing replaces them).
 */
#define _POSIX_C_SOURCE 200809L /* pthread barriers, fork under -std=c11 */
#include "common.h"
#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>

#define THREADS 3
#define FRAMES 12
#define W 320
#define H 256

/* A picture of the thread and frame: a clear, a scissored clear, and a flat axis-aligned
 * rectangle of two triangles (whole pixels, so every implementation covers the same ones);
 * the number of pixels that differ from what it must be. */
static int draw_and_check(unsigned char *pixels, int index, int frame)
{
    unsigned char bg[4] = {(unsigned char)(60 * index + 20), (unsigned char)(frame * 17), 40, 255};
    unsigned char sq[4] = {200, (unsigned char)(30 * index), (unsigned char)(255 - frame), 255};
    unsigned char fg[4] = {10, 250, (unsigned char)(20 * index + frame), 255};
    int sx = 8 * index + frame, sy = 70 + 9 * index, ss = 90; /* scissored clear: crosses tiles */
    int rx = 150 - 5 * index, ry = 20 + frame, rw = 140, rh = 200;
    capi_pixel_ortho(W, H);
    glShadeModel(GL_FLAT);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(bg[0] / 255.0f, bg[1] / 255.0f, bg[2] / 255.0f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(sx, sy, ss, ss);
    glClearColor(sq[0] / 255.0f, sq[1] / 255.0f, sq[2] / 255.0f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColor4ub(fg[0], fg[1], fg[2], fg[3]);
    glBegin(GL_TRIANGLES);
    glVertex2i(rx, ry);
    glVertex2i(rx + rw, ry);
    glVertex2i(rx + rw, ry + rh);
    glVertex2i(rx, ry);
    glVertex2i(rx + rw, ry + rh);
    glVertex2i(rx, ry + rh);
    glEnd();
    glFinish();
    int wrong = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const unsigned char *want = bg;
            if (x >= sx && x < sx + ss && y >= sy && y < sy + ss)
                want = sq;
            if (x >= rx && x < rx + rw && y >= ry && y < ry + rh)
                want = fg;
            wrong += memcmp(pixels + ((size_t)y * W + x) * 4, want, 4) != 0;
        }
    return wrong;
}

struct job {
    int index;
    OSMesaContext ctx;
    unsigned char *pixels;
    int wrong;
};

static pthread_barrier_t start;

static void *work(void *arg)
{
    struct job *job = arg;
    if (!OSMesaMakeCurrent(job->ctx, job->pixels, GL_UNSIGNED_BYTE, W, H)) {
        job->wrong = -1;
        return NULL;
    }
    pthread_barrier_wait(&start);
    for (int frame = 0; frame < FRAMES; frame++)
        job->wrong += draw_and_check(job->pixels, job->index, frame);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    return NULL;
}

/* One context, one frame on this thread; the wrong pixel count (-1: no context). */
static int one_frame(int index)
{
    unsigned char *pixels = calloc((size_t)W * H, 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    int wrong = -1;
    if (ctx && pixels && OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H))
        wrong = draw_and_check(pixels, index, 3);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    if (ctx)
        OSMesaDestroyContext(ctx);
    free(pixels);
    return wrong;
}

int main(void)
{
    /* Threads at once, each with its own context and buffer. */
    static struct job jobs[THREADS];
    pthread_t threads[THREADS];
    pthread_barrier_init(&start, NULL, THREADS);
    for (int i = 0; i < THREADS; i++) {
        jobs[i].index = i;
        jobs[i].ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
        jobs[i].pixels = calloc((size_t)W * H, 4);
        capi_check(jobs[i].ctx != NULL && jobs[i].pixels != NULL, "context %d", i);
    }
    for (int i = 0; i < THREADS; i++)
        capi_check(pthread_create(&threads[i], NULL, work, &jobs[i]) == 0, "pthread_create");
    for (int i = 0; i < THREADS; i++)
        pthread_join(threads[i], NULL);
    for (int i = 0; i < THREADS; i++) {
        char name[32];
        snprintf(name, sizeof name, "thread%d", i);
        capi_value(name, "wrong_pixels=%d", jobs[i].wrong);
        capi_save_image(name, W, H, 4, CAPI_U8, jobs[i].pixels);
        OSMesaDestroyContext(jobs[i].ctx);
        free(jobs[i].pixels);
    }
    pthread_barrier_destroy(&start);

    /* fork after rendering: the child renders (and forks again), then the parent. */
    if (capi_is_tessera()) {
        capi_check(one_frame(0) == 0, "the parent's frame before fork");
        fflush(stdout);
        for (int round = 0; round < 2; round++) {
            pid_t child = fork();
            if (child == 0) {
                int wrong = one_frame(1);
                pid_t grandchild = fork();
                if (grandchild == 0)
                    _exit(one_frame(2) == 0 ? 0 : 1);
                int status = 1;
                waitpid(grandchild, &status, 0);
                _exit(wrong == 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : 1);
            }
            int status = -1;
            capi_check(child > 0 && waitpid(child, &status, 0) == child, "fork/waitpid");
            capi_check(WIFEXITED(status) && WEXITSTATUS(status) == 0, "round %d: the child's and grandchild's frames",
                       round);
        }
        capi_check(one_frame(2) == 0, "the parent's frame after fork");
    }
    return capi_finish();
}
