/* OSMesaGetDepthBuffer: the size of a depth value for each requested depth/stencil size,
 * the stored values of depth clears (16-bit, and 24-bit depth packed with the stencil
 * value in the top byte: depth | stencil << 24), rows bottom-up, and GL_FALSE without a
 * depth buffer.
 *
 * Deliberate differences from Mesa 22, checked per implementation:
 *  - depth sizes: tessera gives at least the requested depth: 16 bits for 1..16, 24 for
 *    17..24, 32 above. Mesa 22 gives no depth buffer below 16 bits (unless stencil is also
 *    requested: then 24/8), 16 bits for 16..23, and 24 bits for 32 (never 32).
 *  - Mesa 22 crashes in OSMesaGetDepthBuffer on a context that was never bound; tessera
 *    returns GL_FALSE (checked on tessera only).
 */
#include "common.h"

#define W 4
#define H 3

static unsigned char color[W * H * 4];

/* Bytes per depth value each implementation gives for a request; 0: no depth buffer. */
static int expected_bytes(int depth, int stencil, int tessera)
{
    if (depth == 0)
        return 0;
    if (tessera)
        return depth <= 16 && stencil == 0 ? 2 : 4;
    if (stencil > 0)
        return 4;
    return depth < 16 ? 0 : depth < 24 ? 2 : 4;
}

static void sizes(int tessera)
{
    static const int depths[] = {0, 1, 8, 15, 16, 17, 23, 24, 25, 31, 32, 33};
    for (int s = 0; s <= 8; s += 8)
        for (unsigned i = 0; i < sizeof depths / sizeof depths[0]; i++) {
            int d = depths[i];
            OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, d, s, 0, NULL);
            capi_check(ctx != NULL, "depth %d stencil %d: no context", d, s);
            capi_check(OSMesaMakeCurrent(ctx, color, GL_UNSIGNED_BYTE, W, H), "bind");
            GLint w = -1, h = -1, bytes = -1;
            void *pointer = (void *)&w;
            GLboolean found = OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &pointer);
            int expected = expected_bytes(d, s, tessera);
            capi_check(found == (expected != 0), "depth %d stencil %d: GetDepthBuffer returned %d", d, s, found);
            if (found) {
                capi_check(w == W && h == H && pointer != NULL, "depth %d stencil %d: %dx%d %p", d, s, w, h, pointer);
                capi_check(bytes == expected, "depth %d stencil %d: %d bytes per value, expected %d", d, s, bytes,
                           expected);
            } else {
                capi_check(w == 0 && h == 0 && bytes == 0 && pointer == NULL,
                           "depth %d stencil %d: outputs not cleared without a depth buffer", d, s);
            }
            /* The requests on which Mesa 22 and tessera agree. */
            if (expected_bytes(d, s, 0) == expected_bytes(d, s, 1) && d != 32 && d <= 24) {
                char key[40];
                snprintf(key, sizeof key, "depth%d_stencil%d", d, s);
                capi_value(key, "found=%d %dx%d bytes=%d", found, w, h, bytes);
            }
            OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
            OSMesaDestroyContext(ctx);
        }
}

static const double clear_values[] = {0.0, 0.5, 1.0, 0.25, 0.75, 1.0 / 3.0, 0.1, -1.0, 2.0};

static void values16(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, color, GL_UNSIGNED_BYTE, W, H), "bind");
    GLint w, h, bytes;
    unsigned short *depth = NULL;
    static const unsigned short expected[] = {0x0000, 0x8000, 0xffff, 0x4000, 0xbfff, 0x5555, 0x199a, 0x0000, 0xffff};
    for (int i = 0; i < 9; i++) {
        glClearDepth(clear_values[i]);
        glClear(GL_DEPTH_BUFFER_BIT);
        glFinish();
        capi_check(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, (void **)&depth) && bytes == 2, "16-bit depth buffer");
        capi_check(depth[0] == expected[i] && depth[W * H - 1] == expected[i], "16-bit clear to %g stored 0x%04x",
                   clear_values[i], depth[0]);
        capi_value("depth16", "clear %g -> 0x%04x", clear_values[i], depth[0]);
    }
    capi_save_image("depth16", W, H, 1, CAPI_U16, depth);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

static void values24(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, color, GL_UNSIGNED_BYTE, W, H), "bind");
    GLint w, h, bytes;
    unsigned int *depth = NULL;
    static const unsigned int expected[] = {0x000000, 0x800000, 0xffffff, 0x400000, 0xbfffff,
                                            0x555555, 0x19999a, 0x000000, 0xffffff};
    for (int i = 0; i < 9; i++) {
        glClearDepth(clear_values[i]);
        glClearStencil(0x5A + i);
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glFinish();
        capi_check(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, (void **)&depth) && bytes == 4, "24/8 depth buffer");
        unsigned int want = expected[i] | (unsigned)(0x5A + i) << 24;
        capi_check(depth[0] == want && depth[W * H - 1] == want, "24/8 clear to %g/0x%x stored 0x%08x, expected 0x%08x",
                   clear_values[i], 0x5A + i, depth[0], want);
        capi_value("depth24", "clear %g stencil 0x%x -> 0x%08x", clear_values[i], 0x5A + i, depth[0]);
    }

    /* Rows bottom-up: the bottom row first in memory. */
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, W, 1);
    glClearDepth(0.25);
    glClearStencil(3);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glScissor(1, 2, 2, 1);
    glClearDepth(0.75);
    glClearStencil(7);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glFinish();
    capi_check(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, (void **)&depth), "depth buffer");
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            unsigned int want = y == 0 ? 0x03400000u : (y == 2 && x >= 1 && x <= 2) ? 0x07bfffffu : 0x00ffffffu;
            capi_check(depth[y * W + x] == want, "depth/stencil at (%d,%d) is 0x%08x, expected 0x%08x", x, y,
                       depth[y * W + x], want);
        }
    capi_save_image("depth24_stencil8_rows", W, H, 4, CAPI_U8, depth);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

/* A 32-bit request: tessera stores 32-bit depth, Mesa 22 24-bit (see the file comment). */
static void values32(int tessera)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 32, 0, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, color, GL_UNSIGNED_BYTE, W, H), "bind");
    GLint w, h, bytes;
    unsigned int *depth = NULL;
    glClearDepth(0.5);
    glClear(GL_DEPTH_BUFFER_BIT);
    glFinish();
    capi_check(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, (void **)&depth) && bytes == 4, "32-bit request");
    unsigned int want = tessera ? 0x80000000u : 0x00800000u;
    capi_check(depth[0] == want, "32-bit request: clear to 0.5 stored 0x%08x, expected 0x%08x", depth[0], want);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glFinish();
    want = tessera ? 0xffffffffu : 0x00ffffffu;
    capi_check(depth[0] == want, "32-bit request: clear to 1 stored 0x%08x, expected 0x%08x", depth[0], want);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

int main(void)
{
    int tessera = capi_probe_is_tessera();
    if (tessera) {
        /* Never bound: no depth buffer (Mesa 22 crashes here). */
        OSMesaContext unbound = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
        GLint w = -1, h = -1, bytes = -1;
        void *pointer = &w;
        capi_check(!OSMesaGetDepthBuffer(unbound, &w, &h, &bytes, &pointer), "unbound context has a depth buffer");
        capi_check(w == 0 && h == 0 && bytes == 0 && pointer == NULL, "unbound context: outputs not cleared");
        OSMesaDestroyContext(unbound);
    }
    sizes(tessera);
    values16();
    values24();
    values32(tessera);
    return capi_finish();
}
