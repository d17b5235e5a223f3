/* Color logic ops: all sixteen on RGBA8 (over a varied destination, with a color mask, on
 * lines and points, and replacing blending when both are enabled) and on RGB565 (dither
 * off). GL_DITHER on RGB565: Mesa 22 does not dither (its stores truncate); tessera dithers
 * with the ordered pattern of src/fragment/dither.rs, checked here pixel by pixel. */
#include "common.h"

#define W 64
#define H 32

static const GLenum logic_ops[16] = {
    GL_CLEAR, GL_AND, GL_AND_REVERSE, GL_COPY, GL_AND_INVERTED, GL_NOOP, GL_XOR, GL_OR,
    GL_NOR, GL_EQUIV, GL_INVERT, GL_OR_REVERSE, GL_COPY_INVERTED, GL_OR_INVERTED, GL_NAND, GL_SET,
};

/* The 8-bit channel values of pixel (x, y) of the destination and of the source. */
static int dst_value(int x, int y, int k) { return (x * 37 + y * 11 + k * 71) % 256; }
static int src_value(int x, int y, int k) { return (x * 13 + y * 29 + k * 97 + 5) % 256; }

static void points(int (*value)(int, int, int), int x0, int y0, int w, int h)
{
    glBegin(GL_POINTS);
    for (int y = y0; y < y0 + h; y++)
        for (int x = x0; x < x0 + w; x++) {
            glColor4ub(value(x, y, 0), value(x, y, 1), value(x, y, 2), value(x, y, 3));
            glVertex2f(x + 0.5f, y + 0.5f);
        }
    glEnd();
}

static void logic_rgba8(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    points(dst_value, 0, 0, W, H);
    glEnable(GL_COLOR_LOGIC_OP);
    /* Each op on a 4 × 16 strip of source points. */
    for (int i = 0; i < 16; i++) {
        glLogicOp(logic_ops[i]);
        points(src_value, i * 4, 0, 4, 16);
    }
    /* With blending enabled too: the logic op wins. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glLogicOp(GL_XOR);
    points(src_value, 0, 16, 16, 4);
    glDisable(GL_BLEND);
    /* Through a color mask. */
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glLogicOp(GL_INVERT);
    points(src_value, 16, 16, 16, 4);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    /* A smooth line and a flat wide point. */
    glLogicOp(GL_OR_REVERSE);
    glBegin(GL_LINES);
    glColor4f(1, 0, 0.5f, 1);
    glVertex2f(0, 24.5f);
    glColor4f(0, 1, 0.25f, 0);
    glVertex2f(W, 24.5f);
    glEnd();
    glLogicOp(GL_EQUIV);
    glPointSize(5);
    glBegin(GL_POINTS);
    glColor4ub(0x5a, 0xa5, 0x0f, 0xf0);
    glVertex2f(40, 28);
    glEnd();
    glPointSize(1);
    glDisable(GL_COLOR_LOGIC_OP);
    capi_save_framebuffer("logic_rgba8", W, H);
    /* Exact values of one pixel per op: NAND of src and dst at (i*4, 0). */
    GLubyte px[4];
    glReadPixels(14 * 4, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    int expect[4];
    for (int k = 0; k < 4; k++)
        expect[k] = ~(src_value(56, 0, k) & dst_value(56, 0, k)) & 0xff;
    capi_check(px[0] == expect[0] && px[1] == expect[1] && px[2] == expect[2] && px[3] == expect[3],
               "NAND: got %d %d %d %d, expected %d %d %d %d", px[0], px[1], px[2], px[3], expect[0], expect[1],
               expect[2], expect[3]);
    capi_value("nand", "%d %d %d %d", px[0], px[1], px[2], px[3]);
    capi_expect_error(GL_NO_ERROR, "rgba8");
}

/* The dithered RGB565 word tessera stores for 8-bit channels (r, g, b) at (x, y). */
static unsigned dithered(int x, int y, int r, int g, int b)
{
    static const int bayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    int m = bayer[y & 3][x & 3];
    unsigned r5 = (32u * r * 31 + (2u * m + 1) * 255) / (32 * 255);
    unsigned g6 = (32u * g * 63 + (2u * m + 1) * 255) / (32 * 255);
    unsigned b5 = (32u * b * 31 + (2u * m + 1) * 255) / (32 * 255);
    return r5 << 11 | g6 << 5 | b5;
}

static void rgb565(void)
{
    void *buffer;
    capi_make_context(OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 0, 0, 0, W, H, &buffer);
    const unsigned short *px = buffer;
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);

    /* Logic ops without dither: the same on both. */
    glDisable(GL_DITHER);
    points(dst_value, 0, 0, W, H);
    glEnable(GL_COLOR_LOGIC_OP);
    for (int i = 0; i < 16; i++) {
        glLogicOp(logic_ops[i]);
        points(src_value, i * 4, 0, 4, 16);
    }
    glDisable(GL_COLOR_LOGIC_OP);
    glFinish();
    capi_save_image("logic_rgb565", W, H, 1, CAPI_U16, buffer);

    /* GL_DITHER (on by default) on every 8-bit value of each channel. */
    glEnable(GL_DITHER);
    capi_value("dither_enabled", "%d", glIsEnabled(GL_DITHER));
    points(src_value, 0, 0, W, H);
    glFinish();
    int tessera = capi_is_tessera();
    int bad = 0, dithered_differs = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int r = src_value(x, y, 0), g = src_value(x, y, 1), b = src_value(x, y, 2);
            unsigned truncated = (unsigned)(r >> 3) << 11 | (unsigned)(g >> 2) << 5 | (unsigned)(b >> 3);
            unsigned want = tessera ? dithered(x, y, r, g, b) : truncated;
            dithered_differs += dithered(x, y, r, g, b) != truncated;
            if (px[y * W + x] != want && bad++ < 5)
                capi_check(0, "dither at %d,%d: got %04x, expected %04x", x, y, px[y * W + x], want);
        }
    capi_check(bad == 0, "%d pixels differ from the expected dither", bad);
    capi_check(dithered_differs > W * H / 4, "the pattern is exercised (%d)", dithered_differs);
    /* The alpha test on RGB565 compares in float (not in 8 bits as on RGBA8): alpha
     * 126/255 against GEQUAL references between 8-bit steps. */
    glDisable(GL_DITHER);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_ALPHA_TEST);
    static const float refs[4] = {126.5f / 255, 125.5f / 255, 127.5f / 255, 126.2f / 255};
    for (int i = 0; i < 4; i++) {
        glAlphaFunc(GL_GEQUAL, refs[i]);
        glColor4f(1, 1, 1, 126.0f / 255);
        glBegin(GL_POINTS);
        glVertex2f(i + 0.5f, 0.5f);
        glEnd();
    }
    glDisable(GL_ALPHA_TEST);
    glFinish();
    capi_value("alpha_rgb565", "%04x %04x %04x %04x", px[0], px[1], px[2], px[3]);
    capi_expect_error(GL_NO_ERROR, "rgb565");
}

int main(void)
{
    logic_rgba8();
    rgb565();
    return capi_finish();
}
