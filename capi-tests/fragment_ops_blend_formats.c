/* Blending on the color buffers that are not 8-bit RGBA: RGB565 (5/6-bit channels, no
 * alpha: destination alpha reads as 1), 16-bit unorm RGBA and float RGBA. The float buffer
 * also blends unclamped colors (GL_CLAMP_VERTEX_COLOR and GL_CLAMP_FRAGMENT_COLOR off) and
 * is then re-blended with clamping on. Each buffer gets the full 15 x 14 factor table with
 * GL_FUNC_ADD, every other equation on a few factor pairs, and separate functions; the
 * stored pixels are compared with Mesa exactly (raw buffer memory, not a conversion). */
#include "common.h"

#define CELL 3
#define W (15 * CELL)
#define H (15 * CELL + 2 * CELL)

static const GLenum factors[15] = {
    GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE,
};

/* One flat-colored point per pixel; `scale` stretches the colors past 1 for the float
 * buffer (with vertex clamping off). */
static void destination(float scale)
{
    glDisable(GL_BLEND);
    glBegin(GL_POINTS);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            glColor4f(scale * (x * 17 % 61) / 60.0f, (y * 7 % 59) / 58.0f, scale * ((x + y) % 23) / 22.0f,
                      ((x * 3 + y * 5) % 31) / 30.0f);
            glVertex2f(x + 0.5f, y + 0.5f);
        }
    glEnd();
}

static void source_cell(int col, int row, float a, float scale)
{
    glBegin(GL_POINTS);
    for (int j = 0; j < CELL; j++)
        for (int i = 0; i < CELL; i++) {
            float t = (i + j * CELL) / 8.0f;
            glColor4f(scale * (0.8f - 0.5f * t), 0.3f + 0.6f * t, 0.55f, a * (1 - 0.3f * t));
            glVertex2f(col * CELL + i + 0.5f, row * CELL + j + 0.5f);
        }
    glEnd();
}

/* The factor table (rows 0..13), then the other equations and separate functions on the two
 * extra rows. */
static void blend_scene(float scale)
{
    destination(scale);
    glEnable(GL_BLEND);
    glBlendColor(0.25f, 0.6f, 0.9f, 0.4f);
    glBlendEquation(GL_FUNC_ADD);
    for (int s = 0; s < 15; s++)
        for (int d = 0; d < 14; d++) {
            glBlendFunc(factors[s], factors[d]);
            source_cell(s, d, 0.6f, scale);
        }
    static const GLenum equations[4] = {GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    for (int i = 0; i < 15; i++) {
        glBlendEquation(equations[i % 4]);
        glBlendFunc(factors[i], factors[(i + 5) % 14]);
        source_cell(i, 14, 0.45f, scale);
        glBlendEquationSeparate(equations[(i + 1) % 4], equations[i % 2]);
        glBlendFuncSeparate(factors[(i + 2) % 15], factors[i % 14], factors[(i + 9) % 15], factors[(i + 4) % 14]);
        source_cell(i, 15, 0.8f, scale);
    }
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glFinish();
}

static void run(const char *name, GLenum format, GLenum type, int bytes_per_pixel, int channels, enum capi_type kind)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(format, type, 0, 0, 0, W, H, &buffer);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    /* Mesa does not dither; the dither pattern has its own test (fragment_ops_logic_dither). */
    glDisable(GL_DITHER);
    blend_scene(1.0f);
    capi_expect_error(GL_NO_ERROR, name);
    (void)bytes_per_pixel;
    capi_save_image(name, W, H, channels, kind, buffer);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
}

int main(void)
{
    run("rgb565", OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 2, 1, CAPI_U16);
    run("rgba16", OSMESA_RGBA, GL_UNSIGNED_SHORT, 8, 4, CAPI_U16);
    run("rgba_float", OSMESA_RGBA, GL_FLOAT, 16, 4, CAPI_F32);

    /* The float buffer with colors past 1 and no clamping anywhere: blending works on the
     * unclamped values (GL 2.1 §4.1.8 for floating-point buffers). */
    void *buffer;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_FLOAT, 0, 0, 0, W, H, &buffer);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClampColorARB(GL_CLAMP_VERTEX_COLOR_ARB, GL_FALSE);
    glClampColorARB(GL_CLAMP_FRAGMENT_COLOR_ARB, GL_FALSE);
    capi_expect_error(GL_NO_ERROR, "clamp color off");
    blend_scene(2.5f);
    capi_save_image("float_unclamped", W, H, 4, CAPI_F32, buffer);
    /* Values past 1 survive: nothing clamped them. */
    const float *px = (const float *)buffer;
    int above = 0;
    for (int i = 0; i < W * H * 4; i++)
        above += px[i] > 1.0f;
    capi_check(above > W * H / 4, "only %d unclamped values above 1", above);
    /* Clamping on again: fragment colors are clamped, so a plain write stays within
     * [0, 1]; blending (not clamped on float buffers) may still sum past 1. */
    glClampColorARB(GL_CLAMP_VERTEX_COLOR_ARB, GL_TRUE);
    glClampColorARB(GL_CLAMP_FRAGMENT_COLOR_ARB, GL_TRUE);
    destination(2.5f);
    glFinish();
    int outside = 0;
    for (int i = 0; i < W * H * 4; i++)
        outside += px[i] < 0.0f || px[i] > 1.0f;
    capi_check(outside == 0, "%d clamped float values outside [0, 1]", outside);
    blend_scene(2.5f);
    capi_save_image("float_clamped", W, H, 4, CAPI_F32, buffer);
    capi_expect_error(GL_NO_ERROR, "end");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
