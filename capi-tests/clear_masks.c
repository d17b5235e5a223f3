/* Masked clears: every combination of glColorMask on RGBA, BGRA, RGB, float, 16-bit and
 * 5-6-5 buffers (the mask names GL channels, whatever their order in memory), glDepthMask
 * and glStencilMask (bitwise: only the mask's bits of the stencil value change), together
 * with scissoring, checked against a model through the caller's buffer and
 * OSMesaGetDepthBuffer.
 */
#include "common.h"

#define W 32 /* 16 columns of 2 pixels: one per color mask */
#define H 4

static const float background[4] = {0.2f, 0.4f, 0.6f, 0.8f};
static const float foreground[4] = {1.0f, 0.0f, 1.0f, 0.0f};

/* Where each GL channel (r, g, b, a) sits in memory, per format (-1: absent). */
static void channel_offsets(GLenum format, int off[4])
{
    static const int rgba[4] = {0, 1, 2, 3}, bgra[4] = {2, 1, 0, 3}, rgb[4] = {0, 1, 2, -1};
    memcpy(off, format == OSMESA_BGRA ? bgra : format == OSMESA_RGB ? rgb : rgba, sizeof rgba);
}

/* Clears the background, then column pair m with color mask m (bit 0 red .. bit 3 alpha);
 * checks every pixel. The lower half of each column is scissored away. */
static void color_masks(GLenum format, GLenum type, const char *name)
{
    int size = type == GL_UNSIGNED_BYTE ? 1 : type == GL_FLOAT ? 4 : 2;
    int n = format == OSMESA_RGB ? 3 : 4;
    static float buffer[W * H * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(format, 0, 0, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, buffer, type, W, H), "%s: bind", name);
    glClearColor(background[0], background[1], background[2], background[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glClearColor(foreground[0], foreground[1], foreground[2], foreground[3]);
    for (int m = 0; m < 16; m++) {
        glColorMask(m & 1, (m >> 1) & 1, (m >> 2) & 1, (m >> 3) & 1);
        glScissor(2 * m, H / 2, 2, H / 2);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glFinish();
    capi_check(glGetError() == GL_NO_ERROR, "%s: GL error", name);

    int off[4];
    channel_offsets(format, off);
    int wrong = 0;
    for (int y = 0; y < H && !wrong; y++)
        for (int x = 0; x < W && !wrong; x++) {
            int m = y >= H / 2 ? x / 2 : 0;
            const unsigned char *pixel = (const unsigned char *)buffer + (y * W + x) * n * size;
            for (int c = 0; c < 4 && !wrong; c++) {
                if (off[c] < 0)
                    continue;
                float want = (m >> c) & 1 ? foreground[c] : background[c];
                double got, expect;
                if (type == GL_UNSIGNED_BYTE) {
                    got = pixel[off[c]];
                    expect = (int)(want * 255.0f + 0.5f);
                } else if (type == GL_UNSIGNED_SHORT) {
                    unsigned short s;
                    memcpy(&s, pixel + 2 * off[c], 2);
                    got = s;
                    expect = (int)(want * 65535.0f + 0.5f);
                } else {
                    float f;
                    memcpy(&f, pixel + 4 * off[c], 4);
                    got = f;
                    expect = want;
                }
                if (got != expect) {
                    wrong = 1;
                    capi_check(0, "%s: pixel (%d,%d) channel %d is %g, expected %g (mask %d)", name, x, y, c, got,
                               expect, m);
                }
            }
        }
    enum capi_type ct = type == GL_UNSIGNED_BYTE ? CAPI_U8 : type == GL_FLOAT ? CAPI_F32 : CAPI_U16;
    if (format != OSMESA_RGB || type != GL_UNSIGNED_BYTE)
        capi_save_image(name, W, H, n, ct, buffer);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

/* 5-6-5: the mask keeps whole fields of the packed value. */
static void color_masks_565(void)
{
    static unsigned short buffer[W * H];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB_565, 0, 0, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_SHORT_5_6_5, W, H), "565: bind");
    glClearColor(background[0], background[1], background[2], background[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glClearColor(foreground[0], foreground[1], foreground[2], foreground[3]);
    for (int m = 0; m < 16; m++) {
        glColorMask(m & 1, (m >> 1) & 1, (m >> 2) & 1, (m >> 3) & 1);
        glScissor(2 * m, H / 2, 2, H / 2);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glFinish();
    /* background 0.2, 0.4, 0.6 -> 6, 25, 19; foreground 1, 0, 1 -> 31, 0, 31 */
    for (int i = 0; i < W * H; i++) {
        int m = i / W >= H / 2 ? (i % W) / 2 : 0;
        unsigned r = m & 1 ? 31 : 6, g = m & 2 ? 0 : 25, b = m & 4 ? 31 : 19;
        unsigned short want = (unsigned short)(r << 11 | g << 5 | b);
        if (buffer[i] != want) {
            capi_check(0, "565: pixel (%d,%d) is 0x%04x, expected 0x%04x (mask %d)", i % W, i / W, buffer[i], want, m);
            break;
        }
    }
    capi_save_image("rgb565", W, H, 1, CAPI_U16, buffer);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

/* Depth and stencil write masks. */
static void depth_stencil_masks(void)
{
    static unsigned char color[8 * 2 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, color, GL_UNSIGNED_BYTE, 8, 2), "depth/stencil: bind");
    glClearDepth(0.5);
    glClearStencil(0xA5);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    glEnable(GL_SCISSOR_TEST);
    /* column 0: depth masked off, stencil fully masked off */
    glScissor(0, 0, 1, 2);
    glDepthMask(GL_FALSE);
    glStencilMask(0x00);
    glClearDepth(1.0);
    glClearStencil(0xFF);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    /* column 1: stencil mask 0x0F */
    glScissor(1, 0, 1, 2);
    glStencilMask(0x0F);
    glClearStencil(0x3C);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    /* column 2: stencil mask 0xF0, depth on */
    glScissor(2, 0, 1, 2);
    glDepthMask(GL_TRUE);
    glStencilMask(0xF0);
    glClearDepth(0.25);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    /* column 3: a mask wider than 8 bits, only depth cleared */
    glScissor(3, 0, 1, 2);
    glStencilMask(0xFFFFFF5A);
    glClearDepth(0.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    /* column 4: the same mask, stencil cleared */
    glScissor(4, 0, 1, 2);
    glClearStencil(0x1C3);
    glClear(GL_STENCIL_BUFFER_BIT);
    /* column 5: depth masked off, only depth cleared: nothing changes */
    glScissor(5, 0, 1, 2);
    glDepthMask(GL_FALSE);
    glClearDepth(0.75);
    glClear(GL_DEPTH_BUFFER_BIT);
    /* column 6: glColorMask does not affect depth/stencil */
    glScissor(6, 0, 1, 2);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClearStencil(0x11);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glFinish();
    capi_check(glGetError() == GL_NO_ERROR, "depth/stencil: GL error");

    static const unsigned int expected[8] = {
        0xA5800000u,              /* 0: untouched */
        0xAC800000u,              /* 1: stencil (0xA5 & 0xF0) | (0x3C & 0x0F) = 0xAC; depth still masked */
        0x35400000u,              /* 2: stencil (0x3C & 0xF0) | (0xA5 & 0x0F) = 0x35; depth 0.25 */
        0xA5000000u,              /* 3: depth 0.0 */
        0xE7800000u,              /* 4: stencil (0xA5 & ~0x5A) | (0xC3 & 0x5A) = 0xA5 & 0xA5 | 0x42 = 0xE7 */
        0xA5800000u,              /* 5: untouched */
        0x11bfffffu,              /* 6: stencil 0x11, depth 0.75 (the last depth clear value) */
        0xA5800000u,              /* 7: untouched */
    };
    GLint w, h, bytes;
    unsigned int *ds = NULL;
    capi_check(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, (void **)&ds) && bytes == 4, "depth/stencil: no buffer");
    if (ds) {
        for (int y = 0; y < 2; y++)
            for (int x = 0; x < 8; x++)
                capi_check(ds[y * 8 + x] == expected[x], "depth/stencil at (%d,%d) is 0x%08x, expected 0x%08x", x, y,
                           ds[y * 8 + x], expected[x]);
        capi_save_image("depth_stencil", 8, 2, 4, CAPI_U8, ds);
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

int main(void)
{
    color_masks(OSMESA_RGBA, GL_UNSIGNED_BYTE, "rgba_ubyte");
    color_masks(OSMESA_BGRA, GL_UNSIGNED_BYTE, "bgra_ubyte");
    color_masks(OSMESA_RGB, GL_FLOAT, "rgb_float");
    /* Mesa 22's llvmpipe corrupts scissored clears of 3-byte RGB pixels (see osmesa_formats.c). */
    if (capi_probe_is_tessera())
        color_masks(OSMESA_RGB, GL_UNSIGNED_BYTE, "rgb_ubyte");
    color_masks(OSMESA_RGBA, GL_UNSIGNED_SHORT, "rgba_ushort");
    color_masks(OSMESA_RGBA, GL_FLOAT, "rgba_float");
    color_masks_565();
    depth_stencil_masks();
    return capi_finish();
}
