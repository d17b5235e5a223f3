/* Per-call cost of immediate-mode entry points: how many nanoseconds one glColor3f, glNormal3f,
 * glTexCoord2f, glVertex3f or glBegin/glEnd pair takes, through OSMesa. Built once against the
 * system's Mesa headers and run once per implementation (LD_LIBRARY_PATH picks tessera or
 * Mesa), like bench.c; tools/bench.sh runs it and report.py puts the figures in BENCHMARKS.md.
 *
 *   immediate [calls]     (default 2000000 calls per entry point)
 *
 * Output lines (stdout):  call <name> <ns per call>
 * Each figure is the best of 7 timed loops (the machine may be loaded: the minimum is the
 * cost of the call itself). The vertex loop draws points outside the viewport in batches of
 * 64 per glBegin/glEnd, so it includes the transform and clipping of each vertex, as an
 * immediate-mode program's vertices do; the attribute calls only set current values.
 */
#define _POSIX_C_SOURCE 199309L
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e9 + t.tv_nsec;
}

/* The argument varies with i so that no implementation can skip a call as a repeat. */
static void colors(long n)
{
    for (long i = 0; i < n; i++)
        glColor3f((float)(i & 255) * (1.0f / 255.0f), 0.5f, 0.25f);
}

static void normals(long n)
{
    for (long i = 0; i < n; i++)
        glNormal3f(0.0f, (float)(i & 1), 1.0f);
}

static void texcoords(long n)
{
    for (long i = 0; i < n; i++)
        glTexCoord2f((float)(i & 255), 0.5f);
}

static void vertices(long n)
{
    for (long i = 0; i < n; i += 64) {
        glBegin(GL_POINTS);
        for (int j = 0; j < 64; j++)
            glVertex3f(4.0f + (float)j, 0.5f, 0.0f);
        glEnd();
    }
}

static void begin_end(long n)
{
    for (long i = 0; i < n; i++) {
        glBegin(GL_POINTS);
        glEnd();
    }
}

static void measure(const char *name, void (*loop)(long), long calls, long per_iteration)
{
    double best = 1e300;
    loop(calls / 10); /* warm-up */
    for (int r = 0; r < 7; r++) {
        double t0 = now_ns();
        loop(calls);
        glFinish();
        double t = (now_ns() - t0) / (double)(calls / per_iteration);
        if (t < best)
            best = t;
    }
    printf("call %s %.2f\n", name, best);
}

int main(int argc, char **argv)
{
    long calls = argc > 1 ? atol(argv[1]) : 2000000;
    static unsigned char pixels[64 * 64 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 64, 64)) {
        fprintf(stderr, "immediate: no context\n");
        return 1;
    }
    printf("renderer %s\n", (const char *)glGetString(GL_RENDERER));
    measure("glColor3f", colors, calls, 1);
    measure("glNormal3f", normals, calls, 1);
    measure("glTexCoord2f", texcoords, calls, 1);
    measure("glVertex3f", vertices, calls, 1);
    measure("glBegin/glEnd", begin_end, calls / 4, 1);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return 0;
}
