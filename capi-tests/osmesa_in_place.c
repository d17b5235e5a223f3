/* The image of an RGBA / GL_UNSIGNED_BYTE OSMesa buffer with rows bottom-up and no gaps
 * lives, on tessera, in the caller's buffer once a flush point has rendered there in place
 * (src/framebuffer/mod.rs, Drawable). What a program sees must stay Mesa 22's wherever it
 * leaves its buffer alone between flush points:
 *  - frames drawn without a clear build on the previous frame (blending reads it);
 *  - glReadPixels, glCopyPixels and glAccum read the image (it is brought home first);
 *  - OSMesaMakeCurrent with the same buffer keeps the image, and so does OSMesaPixelStore
 *    (OSMESA_Y_UP 0 then writes the same image top row first);
 *  - glReadPixels still writes nothing into the buffer, and draws without a flush point
 *    write nothing either;
 *  - the first frame drawn without a clear builds on black (the fresh image), whatever the
 *    buffer held.
 *
 * Where tessera knowingly differs from Mesa 22 (checked on tessera only): the image that
 * lives in the caller's buffer is that buffer.
 *  - A program that writes into its buffer after a flush point and then draws without a
 *    clear finds its writes under the new drawing (Mesa 22 draws over its own copy of the
 *    last image and overwrites the buffer whole; the classic OSMesa rendered into the
 *    caller's buffer, as tessera does).
 *  - Binding the same context to another buffer of the same size after such a flush point:
 *    the old buffer is never read again (the program may have freed it), so the image
 *    becomes what the new buffer holds (Mesa 22 carries its copy of the old image). After
 *    OSMesaPixelStore(OSMESA_Y_UP, 0), whose layout is not rendered into in place, the image
 *    is tessera's own again and is carried to another buffer as on Mesa (checked on both).
 */
#include "common.h"

#define W 64
#define H 48

static unsigned char a[W * H * 4], b[W * H * 4];

/* Pixel (x, y) (y from the bottom) of a bottom-up RGBA8 buffer. */
static const unsigned char *at(const unsigned char *buffer, int x, int y)
{
    return buffer + ((size_t)y * W + x) * 4;
}

static int is(const unsigned char *p, int r, int g, int bl, int al)
{
    return p[0] == r && p[1] == g && p[2] == bl && p[3] == al;
}

/* Bytes of `buffer` that are not `marker`. */
static int written(const unsigned char *buffer, unsigned char marker)
{
    int n = 0;
    for (int i = 0; i < W * H * 4; i++)
        n += buffer[i] != marker;
    return n;
}

/* A flat-colored rectangle on pixel boundaries. */
static void rect(int x0, int y0, int x1, int y1, float r, float g, float bl, float al)
{
    glColor4f(r, g, bl, al);
    glRecti(x0, y0, x1, y1);
}

/* Frame 1: cleared dark blue, a red rectangle lower left. */
static void frame1(void)
{
    glClearColor(0, 0, 0.5f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    rect(4, 4, 30, 20, 1, 0, 0, 1);
}

int main(void)
{
    int tessera = capi_probe_is_tessera();
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 16, NULL);
    capi_check(ctx != NULL, "context");
    /* Whatever the buffer held, the first image is black. */
    memset(a, 0x77, sizeof a);
    capi_check(OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, W, H), "bind a");
    capi_pixel_ortho(W, H);
    rect(40, 30, 60, 44, 0, 1, 0, 1);
    glFinish();
    capi_check(is(at(a, 0, 0), 0, 0, 0, 0) && is(at(a, 50, 40), 0, 255, 0, 255), "the first image is not black");
    capi_save_image("first_without_clear", W, H, 4, CAPI_U8, a);

    frame1();
    glFinish();
    capi_save_image("frame1", W, H, 4, CAPI_U8, a);

    /* Frame 2 without a clear: a half-transparent white rectangle blended over frame 1. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    rect(20, 10, 50, 40, 1, 1, 1, 0.5f);
    glDisable(GL_BLEND);
    glFinish();
    capi_save_image("frame2_blended", W, H, 4, CAPI_U8, a);

    /* glReadPixels reads the image and writes nothing into the buffer. */
    static unsigned char read[W * H * 4];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, read);
    capi_check(memcmp(read, a, sizeof a) == 0, "glReadPixels differs from the presented image");
    capi_value("read_equals_buffer", "%d", memcmp(read, a, sizeof a) == 0);
    static unsigned char before[W * H * 4];
    memcpy(before, a, sizeof a);
    rect(0, 0, 8, 8, 1, 1, 0, 1);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, read);
    capi_check(is(read, 255, 255, 0, 255), "glReadPixels after a draw");
    capi_check(memcmp(before, a, sizeof a) == 0, "a draw and glReadPixels wrote the buffer");
    capi_value("draw_and_read_wrote", "%d", memcmp(before, a, sizeof a) != 0);
    glFinish();
    capi_save_image("after_read", W, H, 4, CAPI_U8, a);

    /* A frame that starts with a clear, read before its flush point, then presented. */
    frame1();
    glFinish();
    glClearColor(0.5f, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    rect(30, 30, 40, 40, 0, 0, 1, 1);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, read);
    capi_save_image("cleared_then_read", W, H, 4, CAPI_U8, read);
    glFinish();
    capi_check(memcmp(read, a, sizeof a) == 0, "the presented frame differs from what glReadPixels read");

    /* glCopyPixels reads the image rendered in place. */
    frame1();
    glFinish();
    glRasterPos2i(34, 24);
    glCopyPixels(0, 0, 32, 24, GL_COLOR);
    glFinish();
    capi_save_image("copy_pixels", W, H, 4, CAPI_U8, a);

    /* glAccum loads the image rendered in place and returns it after a clear. */
    frame1();
    glFinish();
    glAccum(GL_LOAD, 0.5f);
    glClearColor(0, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glAccum(GL_RETURN, 2.0f);
    glFinish();
    capi_save_image("accum_return", W, H, 4, CAPI_U8, a);

    /* The same buffer bound again keeps the image: a frame without a clear builds on it. */
    frame1();
    glFinish();
    capi_check(OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, W, H), "bind a again");
    rect(10, 30, 20, 40, 0, 1, 0, 1);
    glFinish();
    capi_check(is(at(a, 5, 5), 255, 0, 0, 255) && is(at(a, 15, 35), 0, 255, 0, 255), "rebinding a lost the image");
    capi_save_image("rebind_same", W, H, 4, CAPI_U8, a);

    /* OSMESA_Y_UP 0: the same image, top row first, then bottom-up again. */
    frame1();
    glFinish();
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    rect(40, 4, 50, 10, 1, 1, 0, 1);
    glFinish();
    capi_check(is(a + ((size_t)(H - 1 - 5) * W + 5) * 4, 255, 0, 0, 255), "Y_UP 0 lost the image");
    capi_save_image("y_down", W, H, 4, CAPI_U8, a);
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    rect(50, 30, 60, 40, 1, 0, 1, 1);
    glFinish();
    capi_check(is(at(a, 5, 5), 255, 0, 0, 255) && is(at(a, 45, 5), 255, 255, 0, 255), "Y_UP 1 lost the image");
    capi_save_image("y_up_again", W, H, 4, CAPI_U8, a);

    /* Known differences, on tessera only (see the top). */
    frame1();
    glFinish();
    if (tessera) {
        /* The program writes into its buffer, then draws without a clear. */
        for (int x = 0; x < W; x++)
            memcpy(a + ((size_t)(H - 1) * W + x) * 4, "\x11\x22\x33\x44", 4);
        rect(40, 4, 50, 10, 0, 1, 0, 1);
        glFinish();
        capi_check(is(at(a, 0, H - 1), 0x11, 0x22, 0x33, 0x44), "tessera: the program's write was not kept");
        capi_check(is(at(a, 5, 5), 255, 0, 0, 255) && is(at(a, 45, 5), 0, 255, 0, 255), "tessera: frame lost");

        /* Another buffer of the same size: its contents become the image. */
        frame1();
        glFinish();
        memset(b, 0x55, sizeof b);
        capi_check(OSMesaMakeCurrent(ctx, b, GL_UNSIGNED_BYTE, W, H), "bind b");
        rect(40, 4, 50, 10, 0, 1, 0, 1);
        glFinish();
        capi_check(is(at(b, 5, 5), 0x55, 0x55, 0x55, 0x55) && is(at(b, 45, 5), 0, 255, 0, 255),
                   "tessera: another buffer's contents are not the image");
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, read);
        capi_check(is(read, 0x55, 0x55, 0x55, 0x55), "tessera: glReadPixels does not read the new buffer");
    }

    /* OSMESA_Y_UP 0 brings the image home from the bound buffer: another buffer then gets
     * it as on Mesa. */
    frame1();
    glFinish();
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    static unsigned char c[W * H * 4];
    memset(c, 0x55, sizeof c);
    capi_check(OSMesaMakeCurrent(ctx, c, GL_UNSIGNED_BYTE, W, H), "bind c with Y_UP 0");
    rect(40, 4, 50, 10, 0, 1, 0, 1);
    glFinish();
    capi_check(is(c + ((size_t)(H - 1 - 5) * W + 5) * 4, 255, 0, 0, 255), "Y_UP 0: the image was not carried");
    capi_save_image("y_down_carried", W, H, 4, CAPI_U8, c);
    OSMesaPixelStore(OSMESA_Y_UP, 1);

    /* Nothing drawn since the last flush point: releasing writes nothing. */
    frame1();
    capi_check(OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, W, H), "bind a at the end");
    glFinish();
    memset(a, 0xEE, sizeof a);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    capi_check(written(a, 0xEE) == 0, "the release wrote the buffer");
    capi_value("release_wrote", "%d", written(a, 0xEE));
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
