/* Blending: a table of every source × destination factor pair GL 2.1 allows (15 × 14:
 * GL_SRC_ALPHA_SATURATE is a source factor only) with GL_FUNC_ADD at several source
 * alphas, over a destination gradient with varying alpha; the other equations on a smaller
 * table; separate RGB/alpha functions and equations; the blend color; blending through the
 * color mask, and on lines and points. */
#include "common.h"

#define CELL 4
#define W (15 * CELL)
#define H (15 * CELL)

static const GLenum factors[15] = {
    GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE,
};

/* The destination: one flat-colored point per pixel, every channel (alpha included)
 * varying over the buffer. (Points, not a smooth-shaded quad: the test is about blending,
 * not about how interpolated colors round.) */
static void destination(void)
{
    glDisable(GL_BLEND);
    glBegin(GL_POINTS);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            glColor4f((x * 17 % 61) / 60.0f, (y * 7 % 59) / 58.0f, ((x + y) % 23) / 22.0f, ((x * 3 + y * 5) % 31) / 30.0f);
            glVertex2f(x + 0.5f, y + 0.5f);
        }
    glEnd();
}

/* A source cell: CELL × CELL points around `c` with alpha around `a`. */
static void source_cell(int col, int row, const float c[3], float a)
{
    glBegin(GL_POINTS);
    for (int j = 0; j < CELL; j++)
        for (int i = 0; i < CELL; i++) {
            float t = (i + j * CELL) / 15.0f;
            glColor4f(c[0] * (1 - t) + c[1] * t, c[1] * (1 - t) + c[2] * t, c[2] * (1 - t) + c[0] * t, a * (1 - 0.4f * t * (j & 1)));
            glVertex2f(col * CELL + i + 0.5f, row * CELL + j + 0.5f);
        }
    glEnd();
}

static void factor_table(const char *name, GLenum equation, float alpha)
{
    static const float color[3] = {0.8f, 0.3f, 0.55f};
    destination();
    glEnable(GL_BLEND);
    glBlendEquation(equation);
    for (int s = 0; s < 15; s++)
        for (int d = 0; d < 14; d++) {
            glBlendFunc(factors[s], factors[d]);
            source_cell(s, d, color, alpha);
        }
    glDisable(GL_BLEND);
    capi_expect_error(GL_NO_ERROR, name);
    capi_save_framebuffer(name, W, H);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glBlendColor(0.25f, 0.6f, 0.9f, 0.4f);

    static const float alphas[4] = {0.0f, 0.3f, 0.5f, 1.0f};
    for (int i = 0; i < 4; i++) {
        char name[32];
        snprintf(name, sizeof name, "add_alpha%d", i);
        factor_table(name, GL_FUNC_ADD, alphas[i]);
    }
    factor_table("subtract", GL_FUNC_SUBTRACT, 0.6f);
    factor_table("reverse_subtract", GL_FUNC_REVERSE_SUBTRACT, 0.6f);
    /* MIN and MAX ignore the factors: every cell of the table is the same function. */
    factor_table("min", GL_MIN, 0.6f);
    factor_table("max", GL_MAX, 0.6f);

    /* Separate RGB and alpha functions and equations. */
    destination();
    glEnable(GL_BLEND);
    static const float color[3] = {0.3f, 0.9f, 0.45f};
    for (int i = 0; i < 15; i++) {
        glBlendFuncSeparate(factors[i], factors[(i + 3) % 14], factors[(i + 7) % 15], factors[(i + 11) % 14]);
        glBlendEquationSeparate(i % 2 ? GL_FUNC_REVERSE_SUBTRACT : GL_FUNC_ADD, i % 3 ? GL_FUNC_ADD : GL_MAX);
        for (int row = 0; row < 15; row++)
            source_cell(i, row, color, row / 14.0f);
    }
    glDisable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    capi_save_framebuffer("separate", W, H);

    /* Blending with a color mask: masked channels keep the destination. */
    destination();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    source_cell(0, 0, color, 0.5f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    /* Lines and points blend too (flat color). */
    glBlendFunc(GL_ONE, GL_ONE);
    glColor4f(0.25f, 0.25f, 0.25f, 0.25f);
    glBegin(GL_LINES);
    glVertex2f(0, 20.5f);
    glVertex2f(W, 20.5f);
    glEnd();
    glPointSize(4);
    glBegin(GL_POINTS);
    glVertex2f(30, 40);
    glEnd();
    glDisable(GL_BLEND);
    capi_save_framebuffer("mask_lines_points", W, H);

    /* Exact values: 0.5 of white over black and back, a few single pixels. */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int k = 0; k < 5; k++) {
        glColor4f(1, 0.5f, 0.25f, 0.5f);
        glBegin(GL_QUADS);
        glVertex2f(0, 0);
        glVertex2f(2, 0);
        glVertex2f(2, 2);
        glVertex2f(0, 2);
        glEnd();
        GLubyte px[4];
        glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        char key[32];
        snprintf(key, sizeof key, "over_%d", k);
        capi_value(key, "%d %d %d %d", px[0], px[1], px[2], px[3]);
    }
    glDisable(GL_BLEND);
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
