/* OSMesa writes the caller's buffer only at its flush points, and OSMesaDestroyContext is
 * not one: mesa-demos' osdemo renders, calls glFinish, frees its image buffer and only then
 * destroys the context; a destroy that writes the buffer corrupts the heap. Checked at
 * 32x32 and 400x400 (osdemo's size) with an osdemo-like scene of triangles, lines and
 * points:
 *  - destroy, with or without rendering since the last glFinish, leaves a (kept) buffer
 *    untouched, and a freed one alone (tools/memcheck.sh runs this test under valgrind,
 *    which reports any write into the freed block);
 *  - OSMesaMakeCurrent(NULL, NULL) after glFinish, with nothing drawn since, writes
 *    nothing either (Mesa writes only what was drawn since the last flush);
 *  - the flush points still work: glFlush, glFinish, making another context current and
 *    releasing with MakeCurrent(NULL, NULL) write what was drawn since the last flush;
 *    glReadPixels does not; binding the same context to another buffer of the same size
 *    moves the pending image to the new buffer (written at the next flush), the old one is
 *    left alone.
 *
 * Where tessera knowingly differs from Mesa 22:
 *  - OSMesaGetColorBuffer is a flush point on tessera (the pixels are there when it
 *    returns); Mesa 22 does not write the buffer there. Checked on tessera only.
 *  - Mesa 22 crashes in OSMesaDestroyContext when vertices drawn with glBegin/glEnd were
 *    not flushed (a Mesa bug); on Mesa they are flushed with glReadPixels first, which
 *    rasterizes them without writing the caller's buffer. tessera destroys with the
 *    draws still pending.
 */
#include "common.h"

/* An osdemo-like scene: depth-tested flat-colored triangles, lines and points. `shade`
 * changes the colors so that a later frame differs from an earlier one. */
static void scene(float shade)
{
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.2f, 0.3f * shade, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glShadeModel(GL_FLAT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(-0.9f, -0.9f, 0.5f);
    glVertex3f(0.8f, -0.7f, 0.5f);
    glVertex3f(-0.2f, 0.9f, 0.5f);
    glColor3f(0, shade, 0);
    glVertex3f(-0.6f, 0.6f, 0.0f);
    glVertex3f(0.9f, 0.1f, 0.0f);
    glVertex3f(0.1f, -0.95f, 0.0f);
    glEnd();
    glBegin(GL_LINES);
    glColor3f(1, 1, shade);
    glVertex2f(-0.95f, 0.05f);
    glVertex2f(0.95f, 0.35f);
    glVertex2f(0.3f, -0.9f);
    glVertex2f(0.35f, 0.9f);
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    glColor3f(0, 0, 1);
    glVertex2f(0.5f, 0.5f);
    glVertex2f(-0.5f, -0.5f);
    glEnd();
}

/* Bytes of `buffer` that are not the 0xEE marker. */
static size_t written(const unsigned char *buffer, size_t bytes)
{
    size_t n = 0;
    for (size_t i = 0; i < bytes; i++)
        n += buffer[i] != 0xEE;
    return n;
}

/* Makes the pending draws of the current context safe to destroy on Mesa 22 (see the top). */
static void settle_for_mesa(int tessera)
{
    if (!tessera) {
        unsigned char pixel[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    }
}

/* One osdemo run: render, glFinish, then (`pending`) render again without a flush, then
 * (`release`) release the context, then free the buffer (or keep it and check it was not
 * written) and destroy the context. */
static void run(int size, int pending, int release, int keep, int tessera)
{
    char what[96];
    snprintf(what, sizeof what, "%dx%d%s%s%s", size, size, pending ? " pending" : "", release ? " released" : "",
             keep ? " kept" : " freed");
    size_t bytes = (size_t)size * size * 4;
    unsigned char *buffer = malloc(bytes);
    capi_check(buffer != NULL, "%s: malloc", what);
    if (!buffer)
        return;
    memset(buffer, 0xEE, bytes);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    capi_check(ctx && OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, size, size), "%s: bind", what);
    scene(1);
    glFinish();
    capi_check(written(buffer, bytes) == bytes, "%s: glFinish wrote %zu of %zu bytes", what, written(buffer, bytes),
               bytes);
    if (!pending && !release && keep) {
        char name[32];
        snprintf(name, sizeof name, "scene_%d", size);
        capi_save_image(name, size, size, 4, CAPI_U8, buffer);
    }
    if (pending) {
        scene(0.5f);
        settle_for_mesa(tessera);
    }
    if (keep)
        memset(buffer, 0xEE, bytes);
    if (release) {
        capi_check(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0), "%s: release", what);
        /* Released after the last flush: nothing to write. With draws pending, the
         * release writes them (checked in flush_points). */
        if (keep && !pending)
            capi_check(written(buffer, bytes) == 0, "%s: the release wrote %zu bytes", what, written(buffer, bytes));
        if (keep)
            memset(buffer, 0xEE, bytes);
    }
    if (!keep)
        free(buffer);
    OSMesaDestroyContext(ctx);
    capi_check(OSMesaGetCurrentContext() == NULL, "%s: the destroyed context is still current", what);
    if (keep) {
        capi_check(written(buffer, bytes) == 0, "%s: OSMesaDestroyContext wrote %zu bytes into the caller's buffer",
                   what, written(buffer, bytes));
        capi_value(what, "destroy_wrote=%zu", written(buffer, bytes));
        free(buffer);
    }
}

/* The flush points at `size`: what writes the caller's buffer and what does not. */
static void flush_points(int size, int tessera)
{
    size_t bytes = (size_t)size * size * 4;
    unsigned char *a = malloc(bytes), *b = malloc(bytes), *other = malloc(16 * 16 * 4);
    capi_check(a && b && other, "malloc");
    if (!a || !b || !other)
        return;
    memset(a, 0xEE, bytes);
    memset(b, 0xEE, bytes);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    OSMesaContext ctx2 = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    capi_check(ctx && ctx2 && OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, size, size), "bind");

#define STEP(key, buffer, expect_written)                                                                      \
    do {                                                                                                       \
        size_t n = written(buffer, bytes);                                                                     \
        capi_check((expect_written) ? n == bytes : n == 0, "%dx%d %s: %zu of %zu bytes written", size, size, key, \
                   n, bytes);                                                                                  \
        capi_value(key, "%dx%d written=%d", size, size, n == bytes ? 1 : n == 0 ? 0 : -1);                      \
    } while (0)

    scene(1);
    STEP("draw_only", a, 0);
    unsigned char pixel[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    STEP("read_pixels", a, 0);
    if (tessera) {
        GLint w, h, format;
        void *pointer;
        capi_check(OSMesaGetColorBuffer(ctx, &w, &h, &format, &pointer) && pointer == a, "OSMesaGetColorBuffer");
        capi_check(written(a, bytes) == bytes, "OSMesaGetColorBuffer did not write the buffer");
        memset(a, 0xEE, bytes);
        scene(1);
    }
    glFinish();
    STEP("finish", a, 1);
    char name[32];
    snprintf(name, sizeof name, "finished_%d", size);
    capi_save_image(name, size, size, 4, CAPI_U8, a);

    /* Nothing drawn since: neither glFinish nor glFlush writes again. */
    memset(a, 0xEE, bytes);
    glFinish();
    glFlush();
    STEP("finish_again", a, 0);

    scene(0.5f);
    glFlush();
    STEP("flush", a, 1);

    /* Another context made current: the old one's pending image is written. */
    memset(a, 0xEE, bytes);
    scene(1);
    capi_check(OSMesaMakeCurrent(ctx2, other, GL_UNSIGNED_BYTE, 16, 16), "bind ctx2");
    STEP("other_context", a, 1);
    /* Back to ctx (nothing drawn since): nothing is written. */
    memset(a, 0xEE, bytes);
    capi_check(OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, size, size), "bind ctx again");
    STEP("rebind_after_flush", a, 0);

    /* Released with draws pending: they are written. */
    scene(0.5f);
    capi_check(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0), "release");
    STEP("release", a, 1);

    /* The same context bound to another buffer of the same size: the old buffer is left
     * alone, the pending image goes to the new one at the next flush. */
    capi_check(OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, size, size), "bind ctx to a");
    memset(a, 0xEE, bytes);
    scene(1);
    capi_check(OSMesaMakeCurrent(ctx, b, GL_UNSIGNED_BYTE, size, size), "bind ctx to b");
    STEP("rebind_old", a, 0);
    STEP("rebind_new_before_flush", b, 0);
    glFinish();
    STEP("rebind_old_after_flush", a, 0);
    STEP("rebind_new_after_flush", b, 1);
    snprintf(name, sizeof name, "rebound_%d", size);
    capi_save_image(name, size, size, 4, CAPI_U8, b);
#undef STEP

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx2);
    OSMesaDestroyContext(ctx);
    free(a);
    free(b);
    free(other);
}

int main(void)
{
    int tessera = capi_probe_is_tessera();
    static const int sizes[] = {32, 400};
    for (int i = 0; i < 2; i++) {
        int size = sizes[i];
        for (int keep = 1; keep >= 0; keep--) {
            run(size, 0, 0, keep, tessera); /* osdemo: glFinish, free, destroy */
            run(size, 1, 0, keep, tessera); /* drawn again since the glFinish */
            run(size, 0, 1, keep, tessera); /* released after the glFinish */
        }
        flush_points(size, tessera);
    }
    return capi_finish();
}
