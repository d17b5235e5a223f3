/* Several contexts rendering at once on several threads: each thread binds its own
 * context (created by the main thread) to its own buffer and repeatedly renders a
 * thread-specific picture of scissored clears, checking its color buffer, its depth and
 * stencil values and its error flag after every frame. Contexts share nothing, so no
 * thread may ever see another's colors, errors or current context.
 */
#define _POSIX_C_SOURCE 200809L /* pthread barriers under -std=c11 */
#include "common.h"
#include <pthread.h>

#define THREADS 4
#define FRAMES 40
#define W 64
#define H 48

struct job {
    int index;
    OSMesaContext ctx;
    unsigned char pixels[W * H * 4];
    int failures;
    char first_failure[200];
};

static pthread_barrier_t start;

static void fail(struct job *job, const char *what, int frame)
{
    if (job->failures++ == 0)
        snprintf(job->first_failure, sizeof job->first_failure, "thread %d frame %d: %s", job->index, frame, what);
}

/* The thread's colors: background and square, distinct per thread and per frame parity. */
static void colors(int index, int frame, unsigned char bg[4], unsigned char fg[4])
{
    bg[0] = (unsigned char)(40 * index + 10);
    bg[1] = (unsigned char)(frame & 1 ? 200 : 100);
    bg[2] = 0;
    bg[3] = 255;
    fg[0] = 255;
    fg[1] = (unsigned char)(50 * index);
    fg[2] = (unsigned char)(frame & 1 ? 255 : 128);
    fg[3] = 255;
}

static void *work(void *arg)
{
    struct job *job = arg;
    if (!OSMesaMakeCurrent(job->ctx, job->pixels, GL_UNSIGNED_BYTE, W, H)) {
        fail(job, "MakeCurrent failed", -1);
        return NULL;
    }
    pthread_barrier_wait(&start);
    for (int frame = 0; frame < FRAMES; frame++) {
        unsigned char bg[4], fg[4];
        colors(job->index, frame, bg, fg);
        int x0 = 4 * job->index + (frame % 5), y0 = 3 + job->index, size = 10 + job->index;
        glDisable(GL_SCISSOR_TEST);
        glClearColor(bg[0] / 255.0f, bg[1] / 255.0f, bg[2] / 255.0f, bg[3] / 255.0f);
        glClearDepth(0.25 * job->index);
        glClearStencil(job->index + 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glEnable(GL_SCISSOR_TEST);
        glScissor(x0, y0, size, size);
        glClearColor(fg[0] / 255.0f, fg[1] / 255.0f, fg[2] / 255.0f, fg[3] / 255.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (job->index & 1)
            glClear(0x8); /* GL_INVALID_VALUE on odd threads only */
        glFinish();

        if (OSMesaGetCurrentContext() != job->ctx)
            fail(job, "another context is current", frame);
        GLenum error = glGetError();
        if (error != ((job->index & 1) ? GL_INVALID_VALUE : GL_NO_ERROR))
            fail(job, "wrong GL error", frame);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int inside = x >= x0 && x < x0 + size && y >= y0 && y < y0 + size;
                if (memcmp(job->pixels + (y * W + x) * 4, inside ? fg : bg, 4) != 0) {
                    fail(job, "wrong color", frame);
                    y = H;
                    break;
                }
            }
        GLint w, h, bytes;
        unsigned int *depth;
        if (!OSMesaGetDepthBuffer(job->ctx, &w, &h, &bytes, (void **)&depth) || bytes != 4) {
            fail(job, "no 24/8 depth buffer", frame);
        } else {
            static const unsigned int depth24[] = {0x000000, 0x400000, 0x800000, 0xbfffff}; /* 0.25 * index */
            unsigned int want = (unsigned)(job->index + 1) << 24 | depth24[job->index];
            if (depth[0] != want || depth[W * H - 1] != want)
                fail(job, "wrong depth/stencil value", frame);
        }
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    return NULL;
}

int main(void)
{
    static struct job jobs[THREADS];
    pthread_t threads[THREADS];
    pthread_barrier_init(&start, NULL, THREADS);
    for (int i = 0; i < THREADS; i++) {
        jobs[i].index = i;
        jobs[i].ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
        capi_check(jobs[i].ctx != NULL, "context %d", i);
    }
    for (int i = 0; i < THREADS; i++)
        capi_check(pthread_create(&threads[i], NULL, work, &jobs[i]) == 0, "pthread_create");
    for (int i = 0; i < THREADS; i++)
        pthread_join(threads[i], NULL);
    capi_check(OSMesaGetCurrentContext() == NULL, "a worker's context is current on the main thread");
    for (int i = 0; i < THREADS; i++) {
        capi_check(jobs[i].failures == 0, "%d failure(s), first: %s", jobs[i].failures, jobs[i].first_failure);
        char name[32];
        snprintf(name, sizeof name, "thread%d", i);
        capi_save_image(name, W, H, 4, CAPI_U8, jobs[i].pixels);
        capi_value(name, "failures=%d", jobs[i].failures);
        OSMesaDestroyContext(jobs[i].ctx);
    }
    pthread_barrier_destroy(&start);
    return capi_finish();
}
