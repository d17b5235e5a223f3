/* Hostile sizes and memory: the largest framebuffer the API allows (16384 x 16384) works
 * or fails cleanly; a 10^6-vertex glBegin/glEnd and a 10^7-index glDrawElements draw what
 * they should (memory printed; bounded in reliability_streaming.c); 10 000
 * create/draw/destroy cycles do not grow the process.
 * Memory figures (peak and current resident size from /proc/self/status) are printed for
 * the notes; the bounds are asserted on tessera only (Mesa's are its own). */
#define _DEFAULT_SOURCE
#include "common.h"


static void frame(void)
{
    glClearColor(0.1f, 0.2f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(-1, -1, 0);
    glColor3f(0, 1, 0);
    glVertex3f(1, -1, 0);
    glColor3f(0, 0, 1);
    glVertex3f(0, 1, 0);
    glEnd();
    glFinish();
}

int main(void)
{
    int tessera = capi_probe_is_tessera();

    /* The largest buffer: 16384 x 16384 RGBA8 (1 GiB). */
    OSMesaContext big = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    unsigned char *pixels = malloc((size_t)16384 * 16384 * 4);
    if (big && pixels && OSMesaMakeCurrent(big, pixels, GL_UNSIGNED_BYTE, 16384, 16384)) {
        GLenum error = glGetError();
        capi_check(error == GL_NO_ERROR || error == GL_OUT_OF_MEMORY, "largest buffer: error 0x%x", error);
        if (error == GL_NO_ERROR) {
            frame();
            /* The centre is inside the triangle. */
            const unsigned char *centre = pixels + ((size_t)8192 * 16384 + 8192) * 4;
            capi_check(centre[0] + centre[1] + centre[2] > 200, "largest buffer: triangle missing");
            const unsigned char *corner = pixels + (size_t)16383 * 16384 * 4; /* top left: cleared */
            capi_check(corner[0] == 26 && corner[3] == 255, "largest buffer: clear missing (%d)", corner[0]);
        }
        printf("largest buffer: peak %ld MiB\n", capi_status_mib("VmHWM:"));
    } else {
        /* Failing cleanly is allowed; no error recorded by a refused MakeCurrent. */
        printf("largest buffer refused\n");
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    if (big)
        OSMesaDestroyContext(big);
    free(pixels);

    /* A 10^6-vertex glBegin/glEnd: a strip of tiny triangles sweeping the buffer. */
    enum { W = 256, H = 256 };
    void *buffer;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, &buffer);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT);
    long before = capi_status_mib("VmRSS:");
    glColor3f(1, 1, 1);
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 1000000; i++) {
        float t = i / 1000000.0f;
        glVertex2f(t * W, (i & 1) ? H * 0.75f : H * 0.25f);
    }
    glEnd();
    glFinish();
    long strip = capi_status_mib("VmHWM:");
    GLubyte px[4];
    glReadPixels(W / 2, H / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_check(px[0] == 255 && px[1] == 255, "10^6-vertex strip not drawn");
    capi_expect_error(GL_NO_ERROR, "10^6-vertex strip");

    /* A 10^7-index glDrawElements of points (40 MB of indices, the caller's). */
    static float vertices[W * 2];
    for (int i = 0; i < W; i++) {
        vertices[2 * i] = i + 0.5f;
        vertices[2 * i + 1] = 10.5f;
    }
    unsigned *indices = malloc(sizeof(unsigned) * 10000000);
    for (int i = 0; i < 10000000; i++)
        indices[i] = (unsigned)(i % W);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, vertices);
    glDrawElements(GL_POINTS, 10000000, GL_UNSIGNED_INT, indices);
    glFinish();
    long elements = capi_status_mib("VmHWM:");
    glDisableClientState(GL_VERTEX_ARRAY);
    free(indices);
    int lit = 0;
    static GLubyte row[W * 4];
    glReadPixels(0, 10, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
    for (int i = 0; i < W; i++)
        lit += row[4 * i] == 255;
    capi_check(lit == W, "10^7-index draw: %d of %d points", lit, W);
    capi_expect_error(GL_NO_ERROR, "10^7-index draw");
    printf("memory: before %ld MiB, peak after the strip %ld MiB, after the 10^7 indices %ld MiB\n", before, strip,
           elements);
    /* Peak growth of long draws is bounded and asserted in reliability_streaming.c (the
     * peak here includes the 16384^2 buffer above). */
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);

    /* 10 000 create/draw/destroy cycles on tessera (1 000 on Mesa, which takes 8 ms a
     * context): resident size after a tenth of them and at the end. */
    int cycles = tessera ? 10000 : 1000;
    long at1000 = 0;
    for (int cycle = 1; cycle <= cycles; cycle++) {
        static unsigned char small[64 * 64 * 4];
        OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
        if (!c || !OSMesaMakeCurrent(c, small, GL_UNSIGNED_BYTE, 64, 64)) {
            capi_check(0, "cycle %d: no context", cycle);
            break;
        }
        frame();
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        OSMesaDestroyContext(c);
        if (cycle == cycles / 10)
            at1000 = capi_status_mib("VmRSS:");
    }
    long at10000 = capi_status_mib("VmRSS:");
    printf("cycles: resident %ld MiB after %d, %ld MiB after %d\n", at1000, cycles / 10, at10000, cycles);
    if (tessera)
        capi_check(at10000 - at1000 <= 2, "10 000 cycles grew the process by %ld MiB", at10000 - at1000);
    return capi_finish();
}
