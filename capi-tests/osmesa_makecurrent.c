/* OSMesaMakeCurrent's rules: what it refuses (NULL buffer, sizes below 1, a type the
 * format cannot take) without touching the buffer or the current context; NULL/NULL
 * releases the current context and returns GL_TRUE; the first bind sets the scissor box
 * (and viewport) to the buffer's size while later binds keep them; each context keeps its
 * own state; destroying the current context releases it.
 *
 * The viewport cannot be observed without drawing or glGetIntegerv, which later work
 * brings; the scissor box is observed through clears into the caller's buffer.
 */
#include "common.h"

static unsigned char small[8 * 8 * 4], big[16 * 16 * 4], other[8 * 8 * 4];

/* Counts the pixels of a w x h RGBA8 buffer equal to (r, g, b, a). */
static int count(const unsigned char *buffer, int w, int h, int r, int g, int b, int a)
{
    int n = 0;
    for (int i = 0; i < w * h; i++)
        n += buffer[4 * i] == r && buffer[4 * i + 1] == g && buffer[4 * i + 2] == b && buffer[4 * i + 3] == a;
    return n;
}

/* Counts pixels equal to (r, g, b, a) inside the lower-left 8x8 of a 16x16 buffer. */
static int count_lower_left(const unsigned char *buffer, int r, int g, int b, int a)
{
    int n = 0;
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            const unsigned char *p = buffer + (y * 16 + x) * 4;
            n += p[0] == r && p[1] == g && p[2] == b && p[3] == a;
        }
    return n;
}

static void refused(OSMesaContext ctx, void *buffer, GLenum type, int w, int h, const char *what)
{
    memset(small, 0xEE, sizeof small);
    OSMesaContext before = OSMesaGetCurrentContext();
    GLboolean result = OSMesaMakeCurrent(ctx, buffer, type, w, h);
    capi_check(result == GL_FALSE, "%s: MakeCurrent returned %d", what, result);
    capi_value(what, "%d", result);
    capi_check(OSMesaGetCurrentContext() == before, "%s: the current context changed", what);
    capi_check(count(small, 8, 8, 0xEE, 0xEE, 0xEE, 0xEE) == 64, "%s: the buffer was written", what);
}

int main(void)
{
    capi_check(OSMesaGetCurrentContext() == NULL, "a context is current at start");
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    OSMesaContext ctx565 = OSMesaCreateContextExt(OSMESA_RGB_565, 0, 0, 0, NULL);
    capi_check(ctx && ctx565, "context creation failed");

    /* Refused with no context current. */
    refused(ctx, NULL, GL_UNSIGNED_BYTE, 8, 8, "null_buffer");
    refused(ctx, small, GL_UNSIGNED_BYTE, 0, 8, "zero_width");
    refused(ctx, small, GL_UNSIGNED_BYTE, 8, 0, "zero_height");
    refused(ctx, small, GL_UNSIGNED_BYTE, -1, 8, "negative_width");
    refused(ctx, small, GL_UNSIGNED_BYTE, 8, -5, "negative_height");
    refused(ctx, small, GL_UNSIGNED_SHORT_5_6_5, 8, 8, "rgba_with_565");
    refused(ctx, small, GL_INT, 8, 8, "rgba_with_int");
    refused(ctx565, small, GL_UNSIGNED_BYTE, 8, 8, "565_with_ubyte");
    refused(NULL, small, GL_UNSIGNED_BYTE, 8, 8, "null_context");
    capi_check(OSMesaGetCurrentContext() == NULL, "a refused bind made a context current");

    /* The first bind: the scissor box becomes the whole 8x8 buffer. */
    capi_check(OSMesaMakeCurrent(ctx, small, GL_UNSIGNED_BYTE, 8, 8), "first bind");
    capi_check(OSMesaGetCurrentContext() == ctx, "ctx is not current after binding");
    glEnable(GL_SCISSOR_TEST);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    capi_check(count(small, 8, 8, 0, 255, 0, 255) == 64, "the initial scissor box is not the 8x8 buffer");
    capi_save_image("first_bind", 8, 8, 4, CAPI_U8, small);

    /* A bigger buffer: the scissor box stays 8x8 (set at the first bind only). */
    capi_check(OSMesaMakeCurrent(ctx, big, GL_UNSIGNED_BYTE, 16, 16), "bind 16x16");
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    int blue = count(big, 16, 16, 0, 0, 255, 255);
    capi_check(blue == 64 && count_lower_left(big, 0, 0, 255, 255) == 64,
               "the scissor box changed at the second bind: %d blue pixels", blue);
    capi_value("blue_after_rebind", "%d", blue);
    /* Without the scissor test, clears cover the whole buffer whatever the viewport. */
    glDisable(GL_SCISSOR_TEST);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    capi_check(count(big, 16, 16, 255, 0, 0, 255) == 256, "an unscissored clear missed pixels");
    capi_save_image("rebind_16x16", 16, 16, 4, CAPI_U8, big);

    /* A refused bind keeps the current context and its buffer. */
    refused(ctx565, small, GL_UNSIGNED_BYTE, 8, 8, "refused_while_current");
    capi_check(OSMesaGetCurrentContext() == ctx, "a refused bind released ctx");
    glClearColor(1, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    capi_check(count(big, 16, 16, 255, 255, 0, 255) == 256, "after a refused bind, ctx no longer renders to its buffer");

    /* A second context has its own state (clear color still the default 0,0,0,0). */
    OSMesaContext ctx2 = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    memset(other, 0xEE, sizeof other);
    capi_check(OSMesaMakeCurrent(ctx2, other, GL_UNSIGNED_BYTE, 8, 8), "bind ctx2");
    capi_check(OSMesaGetCurrentContext() == ctx2, "ctx2 is not current");
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    capi_check(count(other, 8, 8, 0, 0, 0, 0) == 64, "ctx2 does not clear to its own default clear color");
    capi_check(count(big, 16, 16, 255, 255, 0, 255) == 256, "ctx2 rendered into ctx's buffer");
    /* Back to ctx: its clear color (yellow) survived. */
    capi_check(OSMesaMakeCurrent(ctx, big, GL_UNSIGNED_BYTE, 16, 16), "bind ctx again");
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    capi_check(count(big, 16, 16, 255, 255, 0, 255) == 256, "ctx lost its clear color");
    capi_check(count(other, 8, 8, 0, 0, 0, 0) == 64, "ctx rendered into ctx2's buffer");

    /* NULL/NULL releases; GL calls then do nothing. */
    GLboolean released = OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    capi_check(released == GL_TRUE, "MakeCurrent(NULL, NULL) returned %d", released);
    capi_check(OSMesaGetCurrentContext() == NULL, "a context is still current after MakeCurrent(NULL, NULL)");
    memset(big, 0xEE, sizeof big);
    glClearColor(0, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    capi_check(count(big, 16, 16, 0xEE, 0xEE, 0xEE, 0xEE) == 256, "a GL call without a current context rendered");
    capi_check(glGetString(GL_RENDERER) == NULL, "glGetString without a current context is not NULL");

    /* Destroying the current context releases it. */
    capi_check(OSMesaMakeCurrent(ctx2, other, GL_UNSIGNED_BYTE, 8, 8), "bind ctx2 again");
    OSMesaDestroyContext(ctx2);
    capi_check(OSMesaGetCurrentContext() == NULL, "the destroyed context is still current");

    OSMesaDestroyContext(ctx);
    OSMesaDestroyContext(ctx565);
    return capi_finish();
}
