/* The alpha test (every function on an alpha gradient, at exact and in-between references)
 * and the stencil test: every op on edge values (INCR/DECR saturating at 0 and 255, the
 * WRAP ops wrapping) with full and partial write masks, every function with a value mask,
 * sfail/zfail/zpass on a depth-tested scene, and two-sided stencil both through
 * GL_STENCIL_TEST_TWO_SIDE_EXT and through glStencilFuncSeparate/glStencilOpSeparate. */
#include "common.h"

#define W 64
#define H 64

static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
static const char *func_names[8] = {"never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always"};

static void rect(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

/* A quad whose alpha runs from 0 at x0 to 1 at x1. */
static void alpha_gradient(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glColor4f(1, 1, 1, 0);
    glVertex2f(x0, y0);
    glColor4f(1, 1, 1, 1);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glColor4f(1, 1, 1, 0);
    glVertex2f(x0, y1);
    glEnd();
}

/* Prints the stencil values of row y, columns 0..n. */
static void stencil_row(const char *key, int y, int n)
{
    GLubyte s[W];
    glReadPixels(0, y, n, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    char buf[W * 4 + 1];
    int len = 0;
    for (int i = 0; i < n; i++)
        len += snprintf(buf + len, sizeof buf - len, "%d ", s[i]);
    capi_value(key, "%s", buf);
}

static void alpha_tests(void)
{
    static const float refs[3] = {0.5f, 0.3f, 128.5f / 255.0f};
    for (int r = 0; r < 3; r++) {
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_ALPHA_TEST);
        for (int f = 0; f < 8; f++) {
            glAlphaFunc(funcs[f], refs[r]);
            alpha_gradient(0, f * 8.0f, W, f * 8.0f + 8);
        }
        glDisable(GL_ALPHA_TEST);
        char name[32];
        snprintf(name, sizeof name, "alpha_ref%d", r);
        capi_save_framebuffer(name, W, H);
        /* The alpha test with a flat color: all or nothing. */
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(GL_GREATER, refs[r]);
        glColor4f(0, 1, 0, 0.5f);
        rect(0, 0, 8, 8, 0);
        glDisable(GL_ALPHA_TEST);
        GLubyte px[4];
        glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        snprintf(name, sizeof name, "alpha_flat_ref%d", r);
        capi_value(name, "%d %d %d %d", px[0], px[1], px[2], px[3]);
    }
    /* A drawn line and point go through the alpha test too. */
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_LESS, 0.5f);
    glBegin(GL_LINES);
    glColor4f(1, 0, 0, 0);
    glVertex2f(0, 10.5f);
    glColor4f(1, 0, 0, 1);
    glVertex2f(W, 10.5f);
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    glColor4f(0, 0, 1, 0.75f);
    glVertex2f(10.5f, 30.5f);
    glColor4f(0, 0, 1, 0.25f);
    glVertex2f(20.5f, 30.5f);
    glEnd();
    glPointSize(1);
    glDisable(GL_ALPHA_TEST);
    capi_save_framebuffer("alpha_lines_points", W, H);
}

static const GLenum ops[8] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
static const char *op_names[8] = {"keep", "zero", "replace", "incr", "decr", "invert", "incr_wrap", "decr_wrap"};

/* Every op as zpass on stencil values 0, 1, 0x80, 0xfe, 0xff (pixels 0..4 of the row), with
 * write mask `mask`; the row is applied twice to see saturation and wrapping settle. */
static void stencil_ops(void)
{
    static const GLubyte start[5] = {0, 1, 0x80, 0xfe, 0xff};
    static const GLuint masks[3] = {0xff, 0x0f, 0xf0};
    glEnable(GL_STENCIL_TEST);
    for (int m = 0; m < 3; m++)
        for (int o = 0; o < 8; o++) {
            glStencilMask(0xff);
            for (int i = 0; i < 5; i++) {
                glClearStencil(start[i]);
                glEnable(GL_SCISSOR_TEST);
                glScissor(i, 0, 1, 1);
                glClear(GL_STENCIL_BUFFER_BIT);
                glDisable(GL_SCISSOR_TEST);
            }
            glStencilMask(masks[m]);
            glStencilFunc(GL_ALWAYS, 0x5a, 0xff);
            glStencilOp(GL_ZERO, GL_ZERO, ops[o]);
            char key[64];
            rect(0, 0, 5, 1, 0);
            snprintf(key, sizeof key, "op_%s_mask%02x_once", op_names[o], masks[m]);
            stencil_row(key, 0, 5);
            rect(0, 0, 5, 1, 0);
            snprintf(key, sizeof key, "op_%s_mask%02x_twice", op_names[o], masks[m]);
            stencil_row(key, 0, 5);
        }
    glStencilMask(0xff);

    /* Counting overlaps: 300 layers of INCR saturate at 255, INCR_WRAP wraps to 44. */
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    for (int k = 0; k < 300; k++) {
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
        rect(0, 0, 4, 1, 0);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        rect(4, 0, 8, 1, 0);
        glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
        rect(8, 0, 12, 1, 0);
        glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);
        rect(12, 0, 16, 1, 0);
    }
    stencil_row("count_300", 0, 16);

    /* Every function against stored 0..15 with reference 7 and value mask 0x0e; passing
     * fragments are colored, failing ones take sfail = INVERT. */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    for (int f = 0; f < 8; f++) {
        for (int i = 0; i < 16; i++) {
            glClearStencil(i);
            glEnable(GL_SCISSOR_TEST);
            glScissor(i * 4, f * 8, 4, 8);
            glClear(GL_STENCIL_BUFFER_BIT);
            glDisable(GL_SCISSOR_TEST);
        }
        glStencilFunc(funcs[f], 7, 0x0e);
        glStencilOp(GL_INVERT, GL_KEEP, GL_INCR);
        glColor3f(1, 0.5f, 0);
        rect(0, f * 8.0f, W, f * 8.0f + 8, 0);
        char key[32];
        snprintf(key, sizeof key, "func_%s", func_names[f]);
        GLubyte s[W];
        glReadPixels(0, f * 8 + 1, W, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
        char buf[16 * 4 + 1];
        int len = 0;
        for (int i = 0; i < 16; i++)
            len += snprintf(buf + len, sizeof buf - len, "%d ", s[i * 4]);
        capi_value(key, "%s", buf);
    }
    capi_save_framebuffer("stencil_funcs", W, H);
    glDisable(GL_STENCIL_TEST);
}

/* sfail / zfail / zpass on a depth-tested scene: a near quad in the middle, then a far quad
 * over everything with a stencil test that fails on the left third. */
static void stencil_depth(void)
{
    glClearStencil(0);
    glClearDepth(1);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glColor3f(0, 0, 1);
    rect(16, 16, 48, 48, 0.5f); /* glOrtho's z is negated: window depth 0.25 */
    /* Left third gets stencil 1 (no depth test, no color) so the later test fails there. */
    glEnable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    rect(0, 0, 21, H, 0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    /* sfail: 1 → 2; zfail (behind the blue quad): 0 → 255; zpass: 0 → 1. */
    glStencilOp(GL_INCR, GL_DECR_WRAP, GL_INCR_WRAP);
    glColor3f(1, 1, 0);
    rect(0, 0, W, H, -0.5f); /* window depth 0.75 */
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    capi_save_framebuffer("stencil_depth_color", W, H);
    stencil_row("sdz_row_8", 8, W);
    stencil_row("sdz_row_32", 32, W);
    /* The depth buffer was written only where both tests passed. */
    GLuint depth[W];
    glReadPixels(0, 32, W, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    capi_value("sdz_depth", "%u %u %u %u %u", depth[2], depth[18], depth[30], depth[50], depth[60]);
    /* Stencil enabled without a depth test: every stencil survivor takes zpass. */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NOTEQUAL, 2, 0xff);
    glStencilOp(GL_ZERO, GL_ZERO, GL_REPLACE);
    rect(0, 0, W, H, 0.9f);
    glDisable(GL_STENCIL_TEST);
    stencil_row("sdz_nodepth_row_32", 32, W);
}

/* Front-facing (CCW) and back-facing (CW) triangles on separate halves, each with its own
 * stencil state; lines and points are front-facing. */
static void draw_two_faces(void)
{
    glBegin(GL_TRIANGLES);
    glVertex2f(0, 0); /* CCW: front */
    glVertex2f(32, 0);
    glVertex2f(0, 32);
    glVertex2f(32, 32); /* CW: back */
    glVertex2f(32, 64);
    glVertex2f(64, 32);
    glEnd();
    glBegin(GL_LINES);
    glVertex2f(0, 40.5f);
    glVertex2f(20, 40.5f);
    glEnd();
    glBegin(GL_POINTS);
    glVertex2f(40.5f, 10.5f);
    glEnd();
}

static void report_faces(const char *prefix)
{
    GLubyte s[4];
    char key[64];
    glReadPixels(4, 4, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[0]);
    glReadPixels(38, 36, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[1]);
    glReadPixels(10, 40, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[2]);
    glReadPixels(40, 10, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[3]);
    snprintf(key, sizeof key, "%s_front_back_line_point", prefix);
    capi_value(key, "%d %d %d %d", s[0], s[1], s[2], s[3]);
}

static void two_sided(void)
{
    glClearStencil(0x10);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    /* Separate state: front INCR, back DECR; back func fails on the line test below. */
    glStencilFuncSeparate(GL_FRONT, GL_ALWAYS, 0, 0xff);
    glStencilFuncSeparate(GL_BACK, GL_EQUAL, 0x10, 0xff);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR);
    draw_two_faces();
    report_faces("separate");
    draw_two_faces(); /* back now fails (0x0f != 0x10): unchanged */
    report_faces("separate_again");
    glStencilMaskSeparate(GL_BACK, 0x0f);
    glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 0xf3, 0xff);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_REPLACE);
    draw_two_faces();
    report_faces("separate_backmask");
    glStencilMask(0xff);

    /* EXT_stencil_two_side: the EXT back face is used only while two-side is enabled. */
    PFNGLACTIVESTENCILFACEEXTPROC glActiveStencilFaceEXT =
        (PFNGLACTIVESTENCILFACEEXTPROC)OSMesaGetProcAddress("glActiveStencilFaceEXT");
    capi_check(glActiveStencilFaceEXT != NULL, "glActiveStencilFaceEXT");
    if (!glActiveStencilFaceEXT)
        return;
    glClear(GL_STENCIL_BUFFER_BIT);
    glActiveStencilFaceEXT(GL_BACK);
    glStencilFunc(GL_ALWAYS, 0x33, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glActiveStencilFaceEXT(GL_FRONT);
    glStencilFunc(GL_ALWAYS, 0x44, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
    glEnable(GL_STENCIL_TEST_TWO_SIDE_EXT);
    draw_two_faces();
    report_faces("ext_two_side");
    glDisable(GL_STENCIL_TEST_TWO_SIDE_EXT);
    draw_two_faces();
    report_faces("ext_two_side_disabled");
    glDisable(GL_STENCIL_TEST);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    alpha_tests();
    stencil_ops();
    stencil_depth();
    two_sided();
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
