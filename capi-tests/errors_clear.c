/* GL error semantics around clears: glClear with bits outside COLOR|DEPTH|STENCIL|ACCUM
 * records GL_INVALID_VALUE and clears nothing (not even the valid buffers named with it);
 * glClear(0) is valid and does nothing; the error flag is sticky (the first error is kept
 * until glGetError reads it, later ones are dropped); invalid glScissor/glViewport change
 * nothing; each context has its own error flag; without a current context glGetError
 * returns GL_NO_ERROR.
 */
#include "common.h"

#define W 8
#define H 4

static unsigned char pixels[W * H * 4];
static OSMesaContext ctx;

/* Every pixel's color and depth/stencil equal the given values. */
static void check_buffers(const char *what, const unsigned char rgba[4], unsigned int ds)
{
    glFinish();
    for (int i = 0; i < W * H; i++)
        if (memcmp(pixels + 4 * i, rgba, 4) != 0) {
            capi_check(0, "%s: pixel %d is %02x%02x%02x%02x", what, i, pixels[4 * i], pixels[4 * i + 1],
                       pixels[4 * i + 2], pixels[4 * i + 3]);
            break;
        }
    GLint w, h, bytes;
    unsigned int *depth = NULL;
    capi_check(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, (void **)&depth) && bytes == 4, "%s: depth buffer", what);
    for (int i = 0; depth && i < W * H; i++)
        if (depth[i] != ds) {
            capi_check(0, "%s: depth/stencil %d is 0x%08x, expected 0x%08x", what, i, depth[i], ds);
            break;
        }
}

int main(void)
{
    capi_expect_error(GL_NO_ERROR, "no_context");
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
    capi_check(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H), "bind");
    capi_expect_error(GL_NO_ERROR, "fresh_context");

    static const unsigned char blue[4] = {0, 0, 255, 255};
    glClearColor(0, 0, 1, 1);
    glClearDepth(0.5);
    glClearStencil(0x12);
    /* (Clearing the accumulation buffer is tested with glAccum, which can read it.) */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    capi_expect_error(GL_NO_ERROR, "clear_all_three");
    check_buffers("initial", blue, 0x12800000u);

    /* Bad bits: GL_INVALID_VALUE and nothing cleared. */
    glClearColor(1, 0, 0, 1);
    glClearDepth(1.0);
    glClearStencil(0x34);
    static const GLbitfield bad[] = {0x8,
                                     0x1, /* GL_CURRENT_BIT */
                                     0x80000000u,
                                     GL_COLOR_BUFFER_BIT | 0x8,
                                     GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | 0x10000,
                                     0xFFFFFFFFu};
    for (unsigned i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        glClear(bad[i]);
        char key[32];
        snprintf(key, sizeof key, "clear_0x%x", bad[i]);
        capi_expect_error(GL_INVALID_VALUE, key);
        check_buffers(key, blue, 0x12800000u);
    }

    glClear(0);
    capi_expect_error(GL_NO_ERROR, "clear_nothing");
    check_buffers("clear(0)", blue, 0x12800000u);

    /* Sticky: the first error stays, the second is dropped. */
    glEnable(0x1234);
    glClear(0x8);
    glScissor(0, 0, -1, 1);
    capi_expect_error(GL_INVALID_ENUM, "sticky_first");
    capi_expect_error(GL_NO_ERROR, "sticky_then_clear");
    capi_expect_error(GL_NO_ERROR, "sticky_still_clear");

    /* Invalid scissor and viewport sizes change nothing. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 2, 2);
    glScissor(0, 0, -1, 4);
    capi_expect_error(GL_INVALID_VALUE, "scissor_negative_width");
    glScissor(0, 0, 4, -1);
    capi_expect_error(GL_INVALID_VALUE, "scissor_negative_height");
    glViewport(0, 0, -1, -1);
    capi_expect_error(GL_INVALID_VALUE, "viewport_negative");
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    int green = 0;
    for (int i = 0; i < W * H; i++)
        green += pixels[4 * i + 1] == 255;
    capi_check(green == 4, "the scissor box changed: %d pixels cleared, expected 4", green);
    capi_value("scissored_pixels", "%d", green);
    capi_save_image("after_errors", W, H, 4, CAPI_U8, pixels);
    glDisable(GL_SCISSOR_TEST);

    /* Each context has its own error flag. */
    glClear(0x8);
    OSMesaContext other = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    static unsigned char other_pixels[4 * 4];
    capi_check(OSMesaMakeCurrent(other, other_pixels, GL_UNSIGNED_BYTE, 2, 2), "bind other");
    capi_expect_error(GL_NO_ERROR, "other_context");
    glEnable(0x5678);
    capi_check(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H), "bind ctx again");
    capi_expect_error(GL_INVALID_VALUE, "first_context_kept_its_error");
    capi_check(OSMesaMakeCurrent(other, other_pixels, GL_UNSIGNED_BYTE, 2, 2), "bind other again");
    capi_expect_error(GL_INVALID_ENUM, "other_context_kept_its_error");

    /* Without a current context: no error to report. */
    glEnable(0x5678);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    glClear(0x8);
    capi_expect_error(GL_NO_ERROR, "released");
    capi_check(OSMesaMakeCurrent(other, other_pixels, GL_UNSIGNED_BYTE, 2, 2), "bind other a third time");
    capi_expect_error(GL_INVALID_ENUM, "error_survives_release");

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(other);
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
