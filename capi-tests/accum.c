/* The accumulation buffer: glClearAccum/glClear(GL_ACCUM_BUFFER_BIT) and glAccum with every
 * operation, on RGBA contexts of 8-bit, 16-bit and float channels.
 *
 * Mesa 22 computes glAccum on the CPU over a signed 16-bit accumulation buffer; tessera must
 * give the same bytes, so every scenario saves its picture (compared exactly) and prints a few
 * pixels as VALUE lines, and capi_check() asserts what the GL specification promises.
 * Triangles are not needed: the "frames" are made of scissored clears.
 *
 * Reading results: the caller's OSMesa buffer after glFinish. Mesa 22 does not mark the front
 * buffer as drawn after glAccum(GL_RETURN), so a glFinish right after it leaves the caller's
 * buffer stale there (a Mesa bug); present() therefore does an empty scissored clear first,
 * which marks the buffer on Mesa and changes nothing anywhere.
 */
#include "common.h"
#include <math.h>

#define W 32
#define H 16

static GLenum cur_type;
static const char *cur_tag;
static void *cur_buffer;

/* Clears the rectangle to a color (scissored), leaving the scissor test off. */
static void fill(int x, int y, int w, int h, float r, float g, float b, float a)
{
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, w, h);
    glClearColor(r, g, b, a);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

/* Makes the caller's buffer current (see the file comment); leaves the scissor test off. */
static void present(void)
{
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glFinish();
}

/* Channel c of pixel (x, y) as a float in the buffer's scale (1.0 = full). */
static float channel(int x, int y, int c)
{
    size_t i = ((size_t)y * W + x) * 4 + c;
    switch (cur_type) {
    case GL_UNSIGNED_BYTE: return ((unsigned char *)cur_buffer)[i] / 255.0f;
    case GL_UNSIGNED_SHORT: return ((unsigned short *)cur_buffer)[i] / 65535.0f;
    default: return ((float *)cur_buffer)[i];
    }
}

/* Prints pixel (x, y) exactly (integers, or floats in hex) as VALUE <tag>.<name>. */
static void value_px(const char *name, int x, int y)
{
    char key[128];
    snprintf(key, sizeof key, "%s.%s(%d,%d)", cur_tag, name, x, y);
    size_t i = ((size_t)y * W + x) * 4;
    switch (cur_type) {
    case GL_UNSIGNED_BYTE: {
        const unsigned char *p = (const unsigned char *)cur_buffer + i;
        capi_value(key, "%d %d %d %d", p[0], p[1], p[2], p[3]);
        break;
    }
    case GL_UNSIGNED_SHORT: {
        const unsigned short *p = (const unsigned short *)cur_buffer + i;
        capi_value(key, "%d %d %d %d", p[0], p[1], p[2], p[3]);
        break;
    }
    default: {
        const float *p = (const float *)cur_buffer + i;
        capi_value(key, "%a %a %a %a", p[0], p[1], p[2], p[3]);
        break;
    }
    }
}

/* Presents and saves the whole buffer as <tag>_<name>. */
static void save(const char *name)
{
    char key[128];
    present();
    snprintf(key, sizeof key, "%s_%s", cur_tag, name);
    enum capi_type t = cur_type == GL_UNSIGNED_BYTE ? CAPI_U8 : cur_type == GL_UNSIGNED_SHORT ? CAPI_U16 : CAPI_F32;
    capi_save_image(key, W, H, 4, t, cur_buffer);
}

/* Checks channel c of (x, y) against an expected value within tol. */
#define check_near(x, y, c, expected, tol)                                                              \
    do {                                                                                               \
        float got_ = channel((x), (y), (c));                                                           \
        capi_check(fabsf(got_ - (expected)) <= (tol), "%s (%d,%d).%d = %g, expected %g", cur_tag, (x), \
                   (y), (c), got_, (double)(expected));                                                \
    } while (0)

static void clear_accum(float r, float g, float b, float a)
{
    glClearAccum(r, g, b, a);
    glClear(GL_ACCUM_BUFFER_BIT);
}

/* A frame: background plus an 8x8 square at x = 4 + 6k, colored by k. */
static void draw_frame(int k)
{
    fill(0, 0, W, H, 0.1f, 0.1f, 0.2f, 1.0f);
    fill(4 + 6 * k, 4, 8, 8, 1.0f, 0.25f * k, 0.75f, 0.5f);
}

/* Motion blur: the average of 4 frames (LOAD 1/4 then ACCUM 1/4, RETURN 1). */
static void motion_blur(void)
{
    for (int k = 0; k < 4; k++) {
        draw_frame(k);
        glAccum(k == 0 ? GL_LOAD : GL_ACCUM, 0.25f);
    }
    glAccum(GL_RETURN, 1.0f);
    capi_expect_error(GL_NO_ERROR, "blur");
    save("blur");
    /* x = 28 is covered by the last frame only; x = 10 by the first two; y = 1 by none. */
    check_near(28, 6, 0, (3 * 0.1f + 1.0f) / 4, 0.004f);
    check_near(10, 6, 0, (2 * 0.1f + 2 * 1.0f) / 4, 0.004f);
    check_near(10, 6, 1, (2 * 0.1f + 0.25f) / 4, 0.004f);
    check_near(3, 1, 2, 0.2f, 0.004f);
    check_near(3, 1, 3, 1.0f, 0.004f);
    value_px("blur", 28, 6);
    value_px("blur", 23, 6);
    value_px("blur", 10, 6);
    value_px("blur", 3, 1);
}

/* Decay trails: acc = acc * 0.5 + frame * 0.5 for 4 frames (MULT then ACCUM). */
static void decay(void)
{
    clear_accum(0, 0, 0, 0);
    for (int k = 0; k < 4; k++) {
        draw_frame(k);
        glAccum(GL_MULT, 0.5f);
        glAccum(GL_ACCUM, 0.5f);
    }
    glAccum(GL_RETURN, 1.0f);
    save("decay");
    /* Background everywhere after 4 halvings: 0.1 * (1 - 1/16). */
    check_near(0, 0, 0, 0.1f * 15 / 16, 0.004f);
    /* Covered by frames 2 and 3 only at x = 23. */
    check_near(23, 6, 0, 0.1f * 3 / 16 + 1.0f * 0.75f, 0.004f);
    value_px("decay", 0, 0);
    value_px("decay", 18, 6);
    value_px("decay", 24, 6);
}

/* Bias: LOAD a ramp, ADD 0.25 then RETURN; ADD -0.6 then RETURN (negative sums). */
static void bias(void)
{
    for (int x = 0; x < W; x++)
        fill(x, 0, 1, H, x / 31.0f, 1.0f - x / 31.0f, 0.5f, x / 62.0f);
    glAccum(GL_LOAD, 1.0f);
    glAccum(GL_ADD, 0.25f);
    glAccum(GL_RETURN, 1.0f);
    save("add");
    check_near(0, 0, 0, 0.25f, 0.004f);
    check_near(16, 0, 2, 0.75f, 0.004f);
    check_near(31, 0, 1, 0.25f, 0.004f);
    value_px("add", 0, 0);
    value_px("add", 13, 3);
    value_px("add", 31, 0);
    glAccum(GL_ADD, -0.6f);
    glAccum(GL_RETURN, 1.0f);
    save("sub");
    /* 0.25 - 0.6 < 0 clamps to 0 in fixed-point buffers and stays negative in float ones. */
    if (cur_type == GL_FLOAT)
        check_near(0, 0, 0, -0.35f, 0.004f);
    else
        check_near(0, 0, 0, 0.0f, 0.0f);
    check_near(16, 0, 0, 16 / 31.0f + 0.25f - 0.6f, 0.004f);
    value_px("sub", 0, 0);
    value_px("sub", 20, 5);
    /* Increments below one step of the 16-bit buffer vanish. */
    glAccum(GL_ADD, 1e-5f);
    glAccum(GL_RETURN, 1.0f);
    save("tiny");
}

/* LOAD + RETURN with values that scale past 1, below 0 and overflow the buffer. */
static void scaling(void)
{
    for (int x = 0; x < W; x++)
        fill(x, 0, 1, H, x / 31.0f, 0.75f, 0.3f, 1.0f - x / 31.0f);
    glAccum(GL_LOAD, 1.0f);
    glAccum(GL_RETURN, 2.0f);
    save("return2");
    check_near(31, 0, 0, cur_type == GL_FLOAT ? 2.0f : 1.0f, 0.004f);
    check_near(4, 0, 0, 8 / 31.0f, 0.004f);
    check_near(4, 0, 1, cur_type == GL_FLOAT ? 1.5f : 1.0f, 0.004f);
    value_px("return2", 4, 0);
    value_px("return2", 31, 0);
    glAccum(GL_RETURN, 0.5f);
    save("return_half");
    check_near(31, 0, 0, 0.5f, 0.004f);
    value_px("return_half", 17, 2);
    glAccum(GL_RETURN, -1.0f);
    save("return_neg");
    value_px("return_neg", 17, 2);
    /* The buffer holds [-1, 1]: LOAD 2 of 0.75 overflows (Mesa wraps around). */
    fill(0, 0, W, H, 0.75f, 0.25f, 0.5f, 1.0f);
    glAccum(GL_LOAD, 2.0f);
    glAccum(GL_RETURN, 1.0f);
    save("overflow");
    value_px("overflow", 0, 0);
    /* MULT by a large value, and LOAD with value 0. */
    fill(0, 0, W, H, 0.001f, 0.01f, 0.02f, 0.03f);
    glAccum(GL_LOAD, 1.0f);
    glAccum(GL_MULT, 40.0f);
    glAccum(GL_RETURN, 1.0f);
    save("mult40");
    value_px("mult40", 0, 0);
    glAccum(GL_LOAD, 0.0f);
    glAccum(GL_RETURN, 1.0f);
    save("load0");
    check_near(5, 5, 0, 0.0f, 0.0f);
    check_near(5, 5, 3, 0.0f, 0.0f);
}

/* LOAD truncates color * value * 32767 after reading the color as Mesa does, c * (1/(2^n-1))
 * in float: one step of the accumulation buffer, amplified here by ADD and RETURN 32767/255
 * (one step becomes one 8-bit level, or 257 16-bit levels). */
static void precision(void)
{
    fill(0, 0, W, H, 254 / 255.0f, 254 / 255.0f, 254 / 255.0f, 254 / 255.0f);
    glAccum(GL_LOAD, 33151 / 32767.0f); /* 254 (8-bit): -32515 with Mesa's reciprocal, -32516 by division */
    glAccum(GL_ADD, 32615 / 32767.0f);
    glAccum(GL_RETURN, 32767 / 255.0f);
    save("precision_load");
    value_px("precision_load", 0, 0);
    fill(0, 0, W, H, 257 / 65535.0f, 257 / 65535.0f, 257 / 65535.0f, 257 / 65535.0f);
    glAccum(GL_LOAD, 510 / 32767.0f); /* 257 (16-bit): 1 with Mesa's reciprocal, 2 by division */
    glAccum(GL_RETURN, 32767 / 255.0f);
    save("precision_load2");
    value_px("precision_load2", 0, 0);
    /* GL_ACCUM with a tiny value adds nothing once truncated. */
    glAccum(GL_ACCUM, 1e-6f);
    glAccum(GL_RETURN, 32767 / 255.0f);
    value_px("precision_accum_tiny", 0, 0);
}

/* Negative accumulation values from glClearAccum, brought back by RETURN -1. */
static void negative(void)
{
    clear_accum(-0.5f, 0.25f, -1.0f, 1.0f);
    glAccum(GL_RETURN, -1.0f);
    save("neg_return");
    check_near(1, 1, 0, 0.5f, 0.004f);
    check_near(1, 1, 1, cur_type == GL_FLOAT ? -0.25f : 0.0f, 0.004f);
    check_near(1, 1, 2, 1.0f, 0.004f);
    value_px("neg_return", 1, 1);
    /* glClearAccum clamps to [-1, 1]. */
    clear_accum(-3.0f, 2.0f, 0.123f, -0.001f);
    glAccum(GL_RETURN, 0.75f);
    save("clamped_clear");
    value_px("clamped_clear", 2, 2);
    glAccum(GL_RETURN, -0.75f);
    value_px("clamped_clear_neg", 2, 2);
}

/* Scissor confines every operation; the color mask confines RETURN but not the accum clear. */
static void scissor_and_mask(void)
{
    clear_accum(0.2f, 0.4f, 0.6f, 0.8f);
    fill(0, 0, W, H, 0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(8, 4, 10, 6);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    clear_accum(1.0f, 1.0f, 1.0f, 1.0f); /* inside the box, whatever the color mask */
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glAccum(GL_ADD, -0.1f);
    glAccum(GL_MULT, 0.5f);
    glScissor(4, 2, 20, 10);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glAccum(GL_RETURN, 1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    save("scissor_mask");
    check_near(0, 0, 0, 0.0f, 0.0f);   /* outside the RETURN box */
    check_near(5, 3, 0, 0.2f, 0.004f); /* RETURN box, outside the clear box */
    check_near(5, 3, 1, 0.0f, 0.0f);   /* masked */
    check_near(10, 5, 0, 0.45f, 0.004f);
    check_near(10, 5, 2, 0.45f, 0.004f);
    check_near(10, 5, 3, 0.0f, 0.0f); /* masked */
    value_px("scissor_mask", 5, 3);
    value_px("scissor_mask", 10, 5);
    value_px("scissor_mask", 17, 9);
    value_px("scissor_mask", 18, 10);
    /* LOAD is scissored too. */
    fill(0, 0, W, H, 0.9f, 0.8f, 0.69f, 0.6f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(-4, -4, 12, 10);
    glAccum(GL_LOAD, 1.0f);
    glScissor(0, 0, 0, 0);
    glAccum(GL_RETURN, 1.0f); /* an empty box changes nothing */
    glDisable(GL_SCISSOR_TEST);
    fill(0, 0, W, H, 0.0f, 0.0f, 0.0f, 0.0f);
    glAccum(GL_RETURN, 1.0f);
    save("scissor_load");
    check_near(7, 5, 0, 0.9f, 0.004f);
    check_near(8, 5, 0, 0.45f, 0.004f);
    check_near(7, 6, 2, 0.6f, 0.004f);
    capi_expect_error(GL_NO_ERROR, "scissor");
}

/* GL_NONE as read buffer makes LOAD/ACCUM no-ops; as draw buffer, RETURN a no-op. */
static void none_buffers(void)
{
    clear_accum(0.5f, 0.5f, 0.5f, 0.5f);
    fill(0, 0, W, H, 1.0f, 1.0f, 1.0f, 1.0f);
    glReadBuffer(GL_NONE);
    glAccum(GL_LOAD, 1.0f);
    glAccum(GL_ACCUM, 1.0f);
    glReadBuffer(GL_FRONT);
    glAccum(GL_RETURN, 1.0f);
    save("read_none");
    check_near(3, 3, 0, 0.5f, 0.004f);
    value_px("read_none", 3, 3);
    fill(0, 0, W, H, 1.0f, 1.0f, 1.0f, 1.0f);
    glDrawBuffer(GL_NONE);
    glAccum(GL_RETURN, 0.1f);
    clear_accum(-0.5f, 0.75f, 0.0f, 0.25f); /* the accum clear does not need a draw buffer */
    glDrawBuffer(GL_FRONT);
    capi_expect_error(GL_NO_ERROR, "none_buffers");
    present();
    check_near(3, 3, 0, 1.0f, 0.0f);
    glAccum(GL_RETURN, 1.0f);
    save("none_buffers");
    check_near(3, 3, 0, cur_type == GL_FLOAT ? -0.5f : 0.0f, 0.004f);
    check_near(3, 3, 1, 0.75f, 0.004f);
    value_px("none_buffers", 3, 3);
}

static void errors(void)
{
    glAccum(GL_ADD + 1, 1.0f);
    capi_expect_error(GL_INVALID_ENUM, "bad_op");
    glAccum(0, 1.0f);
    capi_expect_error(GL_INVALID_ENUM, "op_zero");
    /* glBegin may be missing from a partial implementation: look it up. */
    void (*begin)(GLenum) = (void (*)(GLenum))OSMesaGetProcAddress("glBegin");
    void (*end)(void) = (void (*)(void))OSMesaGetProcAddress("glEnd");
    if (begin && end) {
        clear_accum(1, 1, 1, 1);
        fill(0, 0, W, H, 0, 0, 0, 0);
        begin(GL_POINTS);
        glAccum(GL_RETURN, 1.0f);
        end();
        capi_check(glGetError() == GL_INVALID_OPERATION, "glAccum inside glBegin/glEnd");
        present();
        capi_check(channel(0, 0, 0) == 0.0f, "glAccum inside glBegin/glEnd changed the buffer");
    }
}

static void run(GLenum type, const char *tag)
{
    cur_type = type;
    cur_tag = tag;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, type, 24, 8, 16, W, H, &cur_buffer);
    motion_blur();
    decay();
    bias();
    scaling();
    precision();
    negative();
    scissor_and_mask();
    none_buffers();
    errors();
    capi_expect_error(GL_NO_ERROR, tag);
    OSMesaDestroyContext(ctx);
    free(cur_buffer);
}

/* A context without accumulation buffer: glAccum is GL_INVALID_OPERATION (after the enum
 * check); clearing GL_ACCUM_BUFFER_BIT is not an error. */
static void no_accum_buffer(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, &buffer);
    glAccum(GL_RETURN, 1.0f);
    capi_expect_error(GL_INVALID_OPERATION, "no_accum.return");
    glAccum(GL_ADD, 0.0f);
    capi_expect_error(GL_INVALID_OPERATION, "no_accum.add0");
    glAccum(GL_ADD + 1, 1.0f);
    capi_expect_error(GL_INVALID_ENUM, "no_accum.bad_op");
    glClear(GL_ACCUM_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    capi_expect_error(GL_NO_ERROR, "no_accum.clear");
    OSMesaDestroyContext(ctx);
    free(buffer);
}

/* RGB 5/6/5: LOAD reads c * (1/31) and c * (1/63); RETURN rounds half up to 5/6 bits. */
static void rgb565(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 24, 8, 16, W, H, &buffer);
    for (int x = 0; x < W; x++)
        fill(x, 0, 1, H, x / 31.0f, (x * 2 + 1) / 63.0f, 1.0f - x / 31.0f, 1.0f);
    glAccum(GL_LOAD, 1.0f);
    const float values[] = {0.5f, 1.5f, 0.25f, 63 / 64.0f};
    for (int i = 0; i < 4; i++) {
        char name[32];
        glAccum(GL_RETURN, values[i]);
        present();
        snprintf(name, sizeof name, "rgb565_return%d", i);
        capi_save_image(name, W, H, 1, CAPI_U16, buffer);
        const unsigned short *px = buffer;
        capi_value(name, "%04x %04x %04x %04x", px[1], px[7], px[16], px[30]);
    }
    capi_expect_error(GL_NO_ERROR, "rgb565");
    OSMesaDestroyContext(ctx);
    free(buffer);
}

int main(void)
{
    run(GL_UNSIGNED_BYTE, "u8");
    run(GL_UNSIGNED_SHORT, "u16");
    run(GL_FLOAT, "f32");
    rgb565();
    no_accum_buffer();
    return capi_finish();
}
