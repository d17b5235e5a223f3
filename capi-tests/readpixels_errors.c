/* glReadPixels: the errors that depend on state (negative sizes, no read buffer, missing
 * depth or stencil buffers, GL_DEPTH_STENCIL's rules, color index, inside glBegin/glEnd),
 * facts measured on Mesa 22 (exact conversions of depth and 8-bit color, luminance as
 * R + G + B), and where tessera deliberately differs from Mesa 22, checked per
 * implementation:
 *  - float 1.0 read as GL_UNSIGNED_INT/GL_INT: Mesa overflows to 0 / INT_MIN, tessera gives
 *    0xffffffff / 0x7fffffff;
 *  - GL_CLAMP_READ_COLOR = GL_FIXED_ONLY (the default) or GL_FALSE with a float buffer: the
 *    specification reads float buffers unclamped; Mesa 22 clamps whenever it reads through a
 *    blit (e.g. GL_RED/GL_FLOAT), tessera never does;
 *  - GL_STENCIL_INDEX/GL_BITMAP: Mesa 22 never returns; tessera packs the bits as the
 *    specification lays them out (checked on tessera only);
 *  - 3-component OSMesa buffers (GL_RGB): Mesa 22 renders them wrongly; tessera reads alpha as
 *    1 (checked on tessera only);
 *  - a NULL destination: tessera writes nothing (Mesa would write through it). */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <math.h>
#include <stdint.h>

#define SENTINEL 0xee

static unsigned char buf[4096];

static int untouched(void)
{
    for (size_t i = 0; i < sizeof buf; i++)
        if (buf[i] != SENTINEL)
            return 0;
    return 1;
}

/* A read that must fail with `error` and leave the client memory alone. */
static void expect_read_error(int x, int y, int w, int h, GLenum format, GLenum type, GLenum error, const char *what)
{
    memset(buf, SENTINEL, sizeof buf);
    glReadPixels(x, y, w, h, format, type, buf);
    capi_expect_error(error, what);
    if (error != GL_NO_ERROR)
        capi_check(untouched(), "%s: an invalid read wrote memory", what);
}

static void state_errors(void)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 8, 8, &fb);
    expect_read_error(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE, "negative width");
    expect_read_error(0, 0, 1, -1, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE, "negative height");
    expect_read_error(0, 0, -1, 1, 0x1234, 0x1234, GL_INVALID_VALUE, "negative width before a bad enum");
    expect_read_error(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, GL_INVALID_OPERATION, "depth without a depth buffer");
    expect_read_error(0, 0, 1, 1, GL_DEPTH_COMPONENT, 0x1234, GL_INVALID_OPERATION, "no depth buffer before a bad type");
    expect_read_error(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION, "stencil without stencil");
    expect_read_error(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, GL_INVALID_OPERATION, "depth/stencil, neither");
    expect_read_error(0, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_NO_ERROR, "empty read");
    expect_read_error(0, 0, 1, 1, GL_RGBA, 0x1234, GL_INVALID_ENUM, "bad type");
    expect_read_error(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, GL_INVALID_OPERATION, "4-component type, RGB");
    expect_read_error(0, 0, 1, 1, GL_BGR, GL_UNSIGNED_BYTE_3_3_2, GL_INVALID_OPERATION, "3-component type, BGR");
    expect_read_error(0, 0, 1, 1, GL_LUMINANCE, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION, "packed luminance");
    expect_read_error(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_24_8, GL_INVALID_OPERATION, "24_8 color");
    expect_read_error(0, 0, 1, 1, GL_ALPHA, GL_BITMAP, GL_INVALID_ENUM, "bitmap alpha");
    expect_read_error(0, 0, 1, 1, GL_INTENSITY, GL_UNSIGNED_BYTE, GL_INVALID_ENUM, "intensity");

    /* With the read buffer GL_NONE, color reads fail, after the format/type checks. */
    glReadBuffer(GL_NONE);
    capi_expect_error(GL_NO_ERROR, "glReadBuffer(GL_NONE)");
    expect_read_error(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION, "read buffer GL_NONE");
    expect_read_error(0, 0, 0, 0, GL_LUMINANCE, GL_FLOAT, GL_INVALID_OPERATION, "read buffer GL_NONE, empty read");
    expect_read_error(0, 0, 1, 1, GL_RGBA, 0x1234, GL_INVALID_ENUM, "bad type before read buffer GL_NONE");
    expect_read_error(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, GL_INVALID_OPERATION, "GL_NONE, packed mismatch");
    expect_read_error(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE, "negative size before GL_NONE");
    glReadBuffer(GL_FRONT);
    capi_expect_error(GL_NO_ERROR, "glReadBuffer(GL_FRONT)");
    OSMesaDestroyContext(ctx);
    free(fb);

    ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, 8, 8, &fb);
    glClearDepth(0.5);
    glClearStencil(0x42);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    expect_read_error(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT, GL_INVALID_ENUM, "depth/stencil, not 24_8");
    expect_read_error(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT, GL_INVALID_ENUM, "depth/stencil as float");
    expect_read_error(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, GL_INVALID_OPERATION, "depth as 24_8");
    expect_read_error(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION, "packed depth");
    expect_read_error(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_BITMAP, GL_INVALID_ENUM, "depth as bitmap");
    expect_read_error(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION, "color index");
    expect_read_error(0, 0, 1, 1, GL_COLOR_INDEX, GL_BITMAP, GL_INVALID_OPERATION, "color index bitmap");
    expect_read_error(0, 0, 1, 1, GL_COLOR_INDEX, 0x1234, GL_INVALID_ENUM, "color index, bad type");
    expect_read_error(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, GL_INVALID_ENUM, "bad format");
    expect_read_error(0, 0, 1, 1, 0x1234, GL_UNSIGNED_SHORT_4_4_4_4, GL_INVALID_OPERATION, "bad format, packed type");

    /* Depth and stencil reads do not need a color read buffer. */
    glReadBuffer(GL_NONE);
    uint32_t ds = 0;
    glReadPixels(3, 4, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
    capi_expect_error(GL_NO_ERROR, "depth/stencil with read buffer GL_NONE");
    capi_check(ds == 0x80000042u, "depth 0.5, stencil 0x42 as 24_8: 0x%08x", ds);
    capi_value("depth_stencil_24_8", "0x%08x", ds);
    glReadBuffer(GL_FRONT);

    /* Inside glBegin/glEnd (tessera has no glBegin yet: checked where it exists). */
    void (*begin)(GLenum) = (void (*)(GLenum))OSMesaGetProcAddress("glBegin");
    void (*end)(void) = (void (*)(void))OSMesaGetProcAddress("glEnd");
    if (begin && end) {
        memset(buf, SENTINEL, sizeof buf);
        begin(GL_POINTS);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        end();
        GLenum err = glGetError();
        capi_check(err == GL_INVALID_OPERATION, "glReadPixels inside glBegin/glEnd: 0x%x", err);
        capi_check(untouched(), "glReadPixels inside glBegin/glEnd wrote memory");
        /* The alignment stayed 4: a 1×2 RGB read leaves bytes 3..4 alone. */
        memset(buf, SENTINEL, sizeof buf);
        glReadPixels(0, 0, 1, 2, GL_RGB, GL_UNSIGNED_BYTE, buf);
        capi_check(buf[3] == SENTINEL && buf[4] != SENTINEL, "glPixelStorei inside glBegin/glEnd changed state");
    }
    OSMesaDestroyContext(ctx);
    free(fb);
}

/* Values measured on Mesa 22 that must hold on both. */
static void measured_facts(void)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, 4, 4, &fb);
    glClearDepth(0.1);
    glClearStencil(0xa7);
    glClearColor(128 / 255.0f, 0.2f, 0.3f, 0.1f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    uint32_t u32 = 0, ds = 0;
    uint16_t u16 = 0;
    float f = 0;
    glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &u32);
    glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &u16);
    glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
    glReadPixels(1, 1, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
    capi_check(u32 == 0x19999a19u, "depth 0x19999a as GL_UNSIGNED_INT (bit replication): 0x%08x", u32);
    capi_check(u16 == 0x199a, "depth 0x19999a as GL_UNSIGNED_SHORT (through float, rounded): 0x%04x", u16);
    capi_check(f == 0.100000031f, "depth 0x19999a as GL_FLOAT: %.9g", f);
    capi_check(ds == 0x19999aa7u, "depth/stencil as 24_8: 0x%08x", ds);
    capi_value("depth", "uint=0x%08x ushort=0x%04x float=%a ds=0x%08x", u32, u16, f, ds);

    float rgba[4];
    uint16_t us[4];
    glReadPixels(2, 2, 1, 1, GL_RGBA, GL_FLOAT, rgba);
    glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT, us);
    capi_check(rgba[0] == 0.501960814f, "8-bit 128 as GL_FLOAT: %.9g", rgba[0]);
    capi_check(us[0] == 32896, "8-bit 128 as GL_UNSIGNED_SHORT: %u", us[0]);
    capi_value("color128", "float=%a ushort=%u", rgba[0], us[0]);

    /* Luminance is R + G + B (clamped), computed in single precision from the floats. */
    float lum[2];
    glReadPixels(2, 2, 1, 1, GL_LUMINANCE_ALPHA, GL_FLOAT, lum);
    float sum = rgba[0] + rgba[1] + rgba[2];
    capi_check(lum[0] == (sum > 1.0f ? 1.0f : sum), "luminance %.9g, R+G+B %.9g", lum[0], sum);
    capi_check(lum[1] == rgba[3], "luminance alpha %.9g, alpha %.9g", lum[1], rgba[3]);
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(2, 2, 1, 1, GL_RGBA, GL_FLOAT, rgba);
    glReadPixels(2, 2, 1, 1, GL_LUMINANCE, GL_FLOAT, lum);
    capi_check(lum[0] == rgba[0] + rgba[1] + rgba[2], "luminance %.9g is not R+G+B", lum[0]);
    unsigned char lum8 = 0;
    glReadPixels(2, 2, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, &lum8);
    capi_check(lum8 == (unsigned char)lrintf(lum[0] * 255.0f), "luminance %.9g as a byte: %u", lum[0], lum8);
    capi_value("luminance", "float=%a byte=%u", lum[0], lum8);
    OSMesaDestroyContext(ctx);
    free(fb);
}

/* Float buffers: 32-bit conversions of 1.0 and unclamped reads. */
static void float_buffer_differences(void)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_FLOAT, 0, 0, 0, 4, 4, &fb);
    int tessera = capi_is_tessera();
    glClearColor(1.0f, 0.5f, 2.0f, -0.5f);
    glClear(GL_COLOR_BUFFER_BIT);

    uint32_t u[4];
    int32_t i[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT, u);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_INT, i);
    capi_value("uint_half", "0x%08x", u[1]);
    capi_value("int_half", "0x%08x", (uint32_t)i[1]);
    capi_check(u[1] == 0x80000000u && i[1] == 0x40000000, "0.5 as 32-bit: 0x%08x 0x%08x", u[1], (uint32_t)i[1]);
    capi_check(u[3] == 0 && i[3] == 0, "-0.5 clamps to 0");
    if (tessera) {
        capi_check(u[0] == 0xffffffffu && u[2] == 0xffffffffu, "1.0 as GL_UNSIGNED_INT: 0x%08x 0x%08x", u[0], u[2]);
        capi_check(i[0] == 0x7fffffff && i[2] == 0x7fffffff, "1.0 as GL_INT: 0x%08x 0x%08x", (uint32_t)i[0],
                   (uint32_t)i[2]);
    } else {
        /* Mesa 22's single-precision overflow (a bug). */
        capi_check(u[0] == 0 && u[2] == 0, "Mesa: 1.0 as GL_UNSIGNED_INT overflowed to 0");
        capi_check(i[0] == INT32_MIN && i[2] == INT32_MIN, "Mesa: 1.0 as GL_INT overflowed to INT_MIN");
    }

    /* Unclamped reads. */
    float rgba[4], red = 0;
    glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE);
    glReadPixels(0, 0, 1, 1, GL_RED, GL_FLOAT, &red);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, rgba);
    capi_check(red == 1.0f && rgba[2] == 1.0f && rgba[3] == 0.0f, "GL_TRUE clamps: %g %g %g", red, rgba[2], rgba[3]);
    capi_value("clamped", "%g %g %g %g", rgba[0], rgba[1], rgba[2], rgba[3]);
    for (int mode = 0; mode < 2; mode++) {
        glClampColor(GL_CLAMP_READ_COLOR, mode == 0 ? GL_FIXED_ONLY : GL_FALSE);
        glReadPixels(0, 0, 1, 1, GL_RED, GL_FLOAT, &red);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, rgba);
        if (tessera)
            capi_check(red == 1.0f && rgba[2] == 2.0f && rgba[3] == -0.5f, "%s reads float buffers unclamped: %g %g",
                       mode == 0 ? "GL_FIXED_ONLY" : "GL_FALSE", rgba[2], rgba[3]);
        /* Non-float types still clamp. */
        unsigned char ub[4];
        signed char b[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ub);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BYTE, b);
        capi_check(ub[2] == 255 && ub[3] == 0 && b[2] == 127 && b[3] == 0, "byte types clamp: %u %u %d %d", ub[2],
                   ub[3], b[2], b[3]);
        capi_value("unclamped_mode_bytes", "%d: %u %u %u %u / %d %d %d %d", mode, ub[0], ub[1], ub[2], ub[3], b[0], b[1],
                   b[2], b[3]);
    }
    capi_expect_error(GL_NO_ERROR, "float reads");
    OSMesaDestroyContext(ctx);
    free(fb);
}

/* glGetError as a check only (for the sections that run on one implementation). */
static void check_no_error(const char *what)
{
    GLenum err = glGetError();
    capi_check(err == GL_NO_ERROR, "%s: error 0x%x", what, err);
}

/* Stencil as GL_BITMAP (tessera only: Mesa 22 loops forever). */
static void stencil_bitmaps(void)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 8, 0, 16, 2, &fb);
    if (!capi_is_tessera()) {
        OSMesaDestroyContext(ctx);
        free(fb);
        return;
    }
    /* Row 0: stencil i for x = i (bit 0 alternates; 2 has bit 0 clear), row 1: all 0xff. */
    glEnable(GL_SCISSOR_TEST);
    for (int x = 0; x < 16; x++) {
        glScissor(x, 0, 1, 1);
        glClearStencil(x);
        glClear(GL_STENCIL_BUFFER_BIT);
    }
    glScissor(0, 1, 16, 1);
    glClearStencil(0xff);
    glClear(GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);

    /* MSB first: bit 0 of x at bit 7 - x%8 of byte x/8. Odd x have bit 0 set. */
    memset(buf, SENTINEL, sizeof buf);
    glReadPixels(0, 0, 16, 2, GL_STENCIL_INDEX, GL_BITMAP, buf);
    check_no_error("stencil bitmap");
    capi_check(buf[0] == 0x55 && buf[1] == 0x55, "row 0 MSB first: %02x %02x", buf[0], buf[1]);
    capi_check(buf[2] == SENTINEL && buf[3] == SENTINEL, "alignment padding written: %02x %02x", buf[2], buf[3]);
    capi_check(buf[4] == 0xff && buf[5] == 0xff, "row 1: %02x %02x", buf[4], buf[5]);

    /* LSB first, alignment 1, 5 pixels from x = 3 (values 3..7: 1,0,1,0,1), skip 2 pixels:
     * bits 2..6 of byte 0; bits 0, 1 and 7 keep the sentinel's. */
    glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
    memset(buf, 0x00, sizeof buf);
    glReadPixels(3, 0, 5, 1, GL_STENCIL_INDEX, GL_BITMAP, buf);
    capi_check(buf[0] == ((1 << 2) | (1 << 4) | (1 << 6)), "LSB first with skip: %02x", buf[0]);
    memset(buf, 0xff, sizeof buf);
    glReadPixels(3, 0, 5, 1, GL_STENCIL_INDEX, GL_BITMAP, buf);
    capi_check(buf[0] == (0xff & ~((1 << 3) | (1 << 5))), "LSB first keeps other bits: %02x", buf[0]);

    /* Clipped on the left: the image keeps its layout (rows of 16 pixels, 2 bytes), pixel
     * x = -3 is bit 2 of byte 0 (skip 2), so x = 0..4 are bits 5..9. */
    glPixelStorei(GL_PACK_ROW_LENGTH, 16);
    memset(buf, 0x00, sizeof buf);
    glReadPixels(-3, 0, 8, 2, GL_STENCIL_INDEX, GL_BITMAP, buf);
    capi_check(buf[0] == (1 << 6), "clipped row 0: %02x (x = 0..2 at bits 5..7: 0, 1, 0)", buf[0]);
    capi_check(buf[1] == 0x01, "clipped row 0 byte 1: %02x (x = 3, 4 at bits 0, 1: 1, 0)", buf[1]);
    capi_check(buf[2] == 0xe0 && buf[3] == 0x03, "clipped row 1: %02x %02x", buf[2], buf[3]);
    capi_check(buf[4] == 0x00, "past the image: %02x", buf[4]);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    check_no_error("stencil bitmaps");
    OSMesaDestroyContext(ctx);
    free(fb);
}

/* 3-component buffers read alpha as 1 (tessera only: Mesa 22's are broken). */
static void rgb_buffers(void)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT};
    for (int t = 0; t < 3; t++) {
        void *fb;
        OSMesaContext ctx = capi_make_context(GL_RGB, types[t], 0, 0, 0, 4, 4, &fb);
        if (capi_is_tessera()) {
            glClearColor(0.2f, 0.4f, 0.6f, 0.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            unsigned char ub[4];
            float f[4];
            uint32_t u[4];
            glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ub);
            glReadPixels(1, 1, 1, 1, GL_RGBA, GL_FLOAT, f);
            glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_INT, u);
            capi_check(ub[0] == 51 && ub[1] == 102 && ub[2] == 153 && ub[3] == 255, "RGB buffer as bytes: %u %u %u %u",
                       ub[0], ub[1], ub[2], ub[3]);
            capi_check(f[3] == 1.0f && u[3] == 0xffffffffu, "RGB buffer alpha: %g 0x%08x", f[3], u[3]);
            check_no_error("RGB buffer reads");
        }
        OSMesaDestroyContext(ctx);
        free(fb);
    }
}

/* A NULL destination (no pixel buffer object exists) writes nothing and is not an error on
 * tessera; Mesa 22 would write through it (checked on tessera only). */
static void null_destination(void)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, 4, 4, &fb);
    if (capi_is_tessera()) {
        glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        glReadPixels(0, 0, 4, 4, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, NULL);
        check_no_error("NULL destination");
    }
    OSMesaDestroyContext(ctx);
    free(fb);
}

int main(void)
{
    state_errors();
    measured_facts();
    float_buffer_differences();
    stencil_bitmaps();
    rgb_buffers();
    null_destination();
    return capi_finish();
}
