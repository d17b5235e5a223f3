/* The per-fragment operations' state setters and their queries: glAlphaFunc, glStencilFunc,
 * glStencilOp, glStencilMask and their Separate/ATI forms, glActiveStencilFaceEXT with
 * GL_STENCIL_TEST_TWO_SIDE_EXT, glBlendFunc/Equation/Color (plain, Separate, indexed),
 * glLogicOp and glFog in its four forms. Every query is printed in all four types (%a for
 * floats) initially, after setting values, after each error (which must change nothing) and
 * with fragment color clamping off. Last, every setter between glBegin and glEnd.
 *
 * Deliberate differences from Mesa 22 (a GL 4.5 context): tessera is GL 2.1 without
 * ARB_blend_func_extended or KHR_blend_equation_advanced, so GL_SRC_ALPHA_SATURATE as a
 * destination factor (GL 2.1 4.1.8: source only), the GL_SRC1_* factors and GL_MULTIPLY_KHR
 * are GL_INVALID_ENUM there; Mesa accepts them. Checked per implementation.
 *
 * Mesa exports neither glActiveStencilFaceEXT nor glStencilFuncSeparateATI: both are looked
 * up with OSMesaGetProcAddress.
 */
#include "common.h"

#define W 8
#define H 8

struct query {
    const char *name;
    GLenum pname;
    int count;
};
#define Q(p, n) {#p, p, n}

static const struct query queries[] = {
    Q(GL_ALPHA_TEST_FUNC, 1),
    Q(GL_ALPHA_TEST_REF, 1),
    Q(GL_DEPTH_FUNC, 1),
    Q(GL_STENCIL_FUNC, 1),
    Q(GL_STENCIL_REF, 1),
    Q(GL_STENCIL_VALUE_MASK, 1),
    Q(GL_STENCIL_FAIL, 1),
    Q(GL_STENCIL_PASS_DEPTH_FAIL, 1),
    Q(GL_STENCIL_PASS_DEPTH_PASS, 1),
    Q(GL_STENCIL_WRITEMASK, 1),
    Q(GL_STENCIL_BACK_FUNC, 1),
    Q(GL_STENCIL_BACK_REF, 1),
    Q(GL_STENCIL_BACK_VALUE_MASK, 1),
    Q(GL_STENCIL_BACK_FAIL, 1),
    Q(GL_STENCIL_BACK_PASS_DEPTH_FAIL, 1),
    Q(GL_STENCIL_BACK_PASS_DEPTH_PASS, 1),
    Q(GL_STENCIL_BACK_WRITEMASK, 1),
    Q(GL_ACTIVE_STENCIL_FACE_EXT, 1),
    Q(GL_STENCIL_TEST_TWO_SIDE_EXT, 1),
    Q(GL_BLEND_SRC, 1),
    Q(GL_BLEND_DST, 1),
    Q(GL_BLEND_SRC_RGB, 1),
    Q(GL_BLEND_DST_RGB, 1),
    Q(GL_BLEND_SRC_ALPHA, 1),
    Q(GL_BLEND_DST_ALPHA, 1),
    Q(GL_BLEND_EQUATION, 1),
    Q(GL_BLEND_EQUATION_RGB, 1),
    Q(GL_BLEND_EQUATION_ALPHA, 1),
    Q(GL_BLEND_COLOR, 4),
    Q(GL_LOGIC_OP_MODE, 1),
    Q(GL_FOG_MODE, 1),
    Q(GL_FOG_DENSITY, 1),
    Q(GL_FOG_START, 1),
    Q(GL_FOG_END, 1),
    Q(GL_FOG_INDEX, 1),
    Q(GL_FOG_COLOR, 4),
    Q(GL_FOG_COORD_SRC, 1),
    Q(GL_FOG_DISTANCE_MODE_NV, 1),
};
#define NQUERIES (int)(sizeof queries / sizeof queries[0])

static PFNGLACTIVESTENCILFACEEXTPROC active_stencil_face;
static PFNGLSTENCILFUNCSEPARATEATIPROC stencil_func_separate_ati;

/* Prints every query in the four types under "<stage>.<name>". */
static void print_all(const char *stage)
{
    for (int q = 0; q < NQUERIES; q++) {
        capi_value_query(stage, queries[q].name, queries[q].pname, queries[q].count);
    }
    capi_expect_error(GL_NO_ERROR, stage);
}

/* Expects `expected` on tessera and `mesa` on Mesa 22 (a deliberate difference), then resets
 * the blend state so that both continue from the same state. */
static void expect_blend_error(GLenum expected, GLenum mesa, const char *what)
{
    GLenum error = glGetError();
    GLenum want = capi_is_tessera() ? expected : mesa;
    capi_check(error == want, "%s: error 0x%x, expected 0x%x", what, error, want);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR);
    glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
}

static void set_values(void)
{
    glAlphaFunc(GL_GEQUAL, 0.375f);
    glStencilFunc(GL_NOTEQUAL, 300, 0xf0f0f0f0u);
    glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT);
    glStencilMask(0x80000001u);
    glStencilFuncSeparate(GL_BACK, GL_LEQUAL, -5, 0x3c);
    glStencilOpSeparate(GL_BACK, GL_REPLACE, GL_ZERO, GL_DECR);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR);
    glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
    glBlendColor(0.25f, -0.5f, 1.5f, 0.1f);
    glLogicOp(GL_NAND);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_DENSITY, 0.75f);
    glFogf(GL_FOG_START, -2.5f);
    glFogf(GL_FOG_END, 2.5f);
    glFogf(GL_FOG_INDEX, 2.5f);
    static const GLfloat color[4] = {0.5f, -0.25f, 2.0f, 0.1f};
    glFogfv(GL_FOG_COLOR, color);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
    capi_expect_error(GL_NO_ERROR, "set_values");
}

/* Every legal enumerant of each setter, then its last value printed. */
static void every_enum(void)
{
    static const GLenum funcs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const GLenum ops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
    static const GLenum factors[] = {
        GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR,
        GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR,
        GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA};
    static const GLenum equations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    char key[64];
    GLint v;
    for (int k = 0; k < 8; k++) {
        glAlphaFunc(funcs[k], 0.5f);
        glStencilFunc(funcs[7 - k], k, k);
        glStencilOp(ops[k], ops[(k + 1) % 8], ops[(k + 2) % 8]);
        glGetIntegerv(GL_ALPHA_TEST_FUNC, &v);
        snprintf(key, sizeof key, "enum.alpha_func.%d", k);
        capi_value(key, "0x%x", v);
        glGetIntegerv(GL_STENCIL_BACK_FUNC, &v);
        snprintf(key, sizeof key, "enum.stencil_func.%d", k);
        capi_value(key, "0x%x", v);
        glGetIntegerv(GL_STENCIL_BACK_PASS_DEPTH_PASS, &v);
        snprintf(key, sizeof key, "enum.stencil_op.%d", k);
        capi_value(key, "0x%x", v);
    }
    for (int k = 0; k < 14; k++) {
        glBlendFunc(factors[k], factors[13 - k]);
        GLint s, d;
        glGetIntegerv(GL_BLEND_SRC_ALPHA, &s);
        glGetIntegerv(GL_BLEND_DST_RGB, &d);
        snprintf(key, sizeof key, "enum.blend_func.%d", k);
        capi_value(key, "0x%x 0x%x", s, d);
    }
    glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ZERO);
    capi_expect_error(GL_NO_ERROR, "glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ZERO)");
    for (int k = 0; k < 5; k++) {
        glBlendEquation(equations[k]);
        glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &v);
        snprintf(key, sizeof key, "enum.blend_equation.%d", k);
        capi_value(key, "0x%x", v);
    }
    for (GLenum op = GL_CLEAR; op <= GL_SET; op++) {
        glLogicOp(op);
        glGetIntegerv(GL_LOGIC_OP_MODE, &v);
        snprintf(key, sizeof key, "enum.logic_op.0x%x", op);
        capi_value(key, "0x%x", v);
    }
    static const GLenum modes[] = {GL_LINEAR, GL_EXP, GL_EXP2};
    for (int k = 0; k < 3; k++) {
        glFogf(GL_FOG_MODE, (GLfloat)modes[k]);
        glGetIntegerv(GL_FOG_MODE, &v);
        snprintf(key, sizeof key, "enum.fog_mode.%d", k);
        capi_value(key, "0x%x", v);
    }
    static const GLenum distances[] = {GL_EYE_PLANE, GL_EYE_PLANE_ABSOLUTE_NV, GL_EYE_RADIAL_NV};
    for (int k = 0; k < 3; k++) {
        GLint p = distances[k];
        glFogiv(GL_FOG_DISTANCE_MODE_NV, &p);
        glGetIntegerv(GL_FOG_DISTANCE_MODE_NV, &v);
        snprintf(key, sizeof key, "enum.fog_distance.%d", k);
        capi_value(key, "0x%x", v);
    }
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
    glGetIntegerv(GL_FOG_COORD_SRC, &v);
    capi_value("enum.fog_coord_src", "0x%x", v);
    capi_expect_error(GL_NO_ERROR, "every_enum");
}

/* Invalid calls: each records its error and changes nothing (compared by print_all). */
static void errors(void)
{
    glAlphaFunc(GL_NEVER - 1, 0.5f);
    capi_expect_error(GL_INVALID_ENUM, "glAlphaFunc(bad func)");
    glStencilFunc(GL_ALWAYS + 1, 1, 1);
    capi_expect_error(GL_INVALID_ENUM, "glStencilFunc(bad func)");
    glStencilFuncSeparate(GL_FRONT_LEFT, GL_LESS, 1, 1);
    capi_expect_error(GL_INVALID_ENUM, "glStencilFuncSeparate(bad face)");
    glStencilFuncSeparate(GL_FRONT, GL_ONE, 1, 1);
    capi_expect_error(GL_INVALID_ENUM, "glStencilFuncSeparate(bad func)");
    stencil_func_separate_ati(GL_LESS, GL_KEEP, 1, 1);
    capi_expect_error(GL_INVALID_ENUM, "glStencilFuncSeparateATI(bad back func)");
    stencil_func_separate_ati(GL_ZERO, GL_LESS, 1, 1);
    capi_expect_error(GL_INVALID_ENUM, "glStencilFuncSeparateATI(bad front func)");
    glStencilOp(GL_KEEP, GL_ONE, GL_KEEP);
    capi_expect_error(GL_INVALID_ENUM, "glStencilOp(bad zfail)");
    glStencilOp(GL_INCR, GL_KEEP, GL_LESS);
    capi_expect_error(GL_INVALID_ENUM, "glStencilOp(bad zpass)");
    glStencilOpSeparate(GL_BACK, GL_NONE + 1, GL_KEEP, GL_KEEP);
    capi_expect_error(GL_INVALID_ENUM, "glStencilOpSeparate(bad sfail)");
    glStencilOpSeparate(GL_LEFT, GL_KEEP, GL_KEEP, GL_KEEP);
    capi_expect_error(GL_INVALID_ENUM, "glStencilOpSeparate(bad face)");
    glStencilMaskSeparate(GL_BACK_LEFT, 0);
    capi_expect_error(GL_INVALID_ENUM, "glStencilMaskSeparate(bad face)");
    active_stencil_face(GL_FRONT_AND_BACK);
    capi_expect_error(GL_INVALID_ENUM, "glActiveStencilFaceEXT(GL_FRONT_AND_BACK)");

    glBlendFunc(GL_ONE, GL_ALPHA);
    capi_expect_error(GL_INVALID_ENUM, "glBlendFunc(bad dst)");
    glBlendFunc(GL_FUNC_ADD, GL_ONE);
    capi_expect_error(GL_INVALID_ENUM, "glBlendFunc(bad src)");
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, 0x9999);
    capi_expect_error(GL_INVALID_ENUM, "glBlendFuncSeparate(bad dst alpha)");
    glBlendFuncSeparateEXT(GL_ONE, GL_ONE, GL_SRC_ALPHA_SATURATE + 1, GL_ONE);
    capi_expect_error(GL_INVALID_ENUM, "glBlendFuncSeparateEXT(bad src alpha)");
    glBlendEquation(GL_LOGIC_OP);
    capi_expect_error(GL_INVALID_ENUM, "glBlendEquation(GL_LOGIC_OP)");
    glBlendEquationSeparate(GL_FUNC_ADD, GL_ONE);
    capi_expect_error(GL_INVALID_ENUM, "glBlendEquationSeparate(bad alpha)");
    glBlendEquationEXT(GL_ZERO);
    capi_expect_error(GL_INVALID_ENUM, "glBlendEquationEXT(bad)");
    glBlendFunci(8, GL_ONE, GL_ONE);
    capi_expect_error(GL_INVALID_VALUE, "glBlendFunci(8)");
    glBlendFunciARB(8, 0x9999, GL_ONE);
    capi_expect_error(GL_INVALID_VALUE, "glBlendFunciARB(8, bad) index first");
    glBlendFuncSeparatei(0xffffffffu, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    capi_expect_error(GL_INVALID_VALUE, "glBlendFuncSeparatei(~0)");
    glBlendFuncSeparateiARB(7, GL_ONE, GL_ONE, GL_ONE, GL_FOG);
    capi_expect_error(GL_INVALID_ENUM, "glBlendFuncSeparateiARB(7, bad)");
    glBlendEquationi(8, GL_MIN);
    capi_expect_error(GL_INVALID_VALUE, "glBlendEquationi(8)");
    glBlendEquationiARB(1, GL_ONE);
    capi_expect_error(GL_INVALID_ENUM, "glBlendEquationiARB(1, bad)");
    glBlendEquationSeparatei(8, GL_MIN, 0x9999);
    capi_expect_error(GL_INVALID_VALUE, "glBlendEquationSeparatei(8, bad)");
    glBlendEquationSeparateiARB(0, GL_MIN, 0x9999);
    capi_expect_error(GL_INVALID_ENUM, "glBlendEquationSeparateiARB(0, bad)");
    glLogicOp(GL_CLEAR - 1);
    capi_expect_error(GL_INVALID_ENUM, "glLogicOp(GL_CLEAR - 1)");
    glLogicOp(GL_SET + 1);
    capi_expect_error(GL_INVALID_ENUM, "glLogicOp(GL_SET + 1)");

    glFogi(GL_FOG_MODE, GL_EYE_PLANE);
    capi_expect_error(GL_INVALID_ENUM, "glFogi(GL_FOG_MODE, bad)");
    glFogf(GL_FOG_DENSITY, -0.25f);
    capi_expect_error(GL_INVALID_VALUE, "glFogf(GL_FOG_DENSITY, -0.25)");
    GLint negative = -1;
    glFogiv(GL_FOG_DENSITY, &negative);
    capi_expect_error(GL_INVALID_VALUE, "glFogiv(GL_FOG_DENSITY, -1)");
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD_SRC);
    capi_expect_error(GL_INVALID_ENUM, "glFogi(GL_FOG_COORD_SRC, bad)");
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_LINEAR);
    capi_expect_error(GL_INVALID_ENUM, "glFogi(GL_FOG_DISTANCE_MODE_NV, bad)");
    glFogf(GL_FOG_HINT, 1.0f);
    capi_expect_error(GL_INVALID_ENUM, "glFogf(GL_FOG_HINT)");
    static const GLfloat zero[4] = {0};
    glFogfv(GL_FOG, zero);
    capi_expect_error(GL_INVALID_ENUM, "glFogfv(GL_FOG)");

    /* Deliberate differences: GL 2.1 rules on tessera, extensions on Mesa 22. */
    glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE);
    expect_blend_error(GL_INVALID_ENUM, GL_NO_ERROR, "glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE)");
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_SRC_ALPHA_SATURATE);
    expect_blend_error(GL_INVALID_ENUM, GL_NO_ERROR, "glBlendFuncSeparate(.., GL_SRC_ALPHA_SATURATE)");
    glBlendFunc(GL_SRC1_COLOR, GL_ONE);
    expect_blend_error(GL_INVALID_ENUM, GL_NO_ERROR, "glBlendFunc(GL_SRC1_COLOR, GL_ONE)");
    glBlendFunci(2, GL_ONE, GL_ONE_MINUS_SRC1_ALPHA);
    expect_blend_error(GL_INVALID_ENUM, GL_NO_ERROR, "glBlendFunci(2, GL_ONE, GL_ONE_MINUS_SRC1_ALPHA)");
    glBlendEquation(GL_MULTIPLY_KHR);
    expect_blend_error(GL_INVALID_ENUM, GL_NO_ERROR, "glBlendEquation(GL_MULTIPLY_KHR)");
}

/* EXT_stencil_two_side: the non-separate calls address the active face; GL_STENCIL_* report
 * it, GL_STENCIL_BACK_* the GL 2.0 back face, which the EXT back face is not. */
static void two_side(void)
{
    glStencilFunc(GL_LESS, 1, 0xf);
    glStencilOp(GL_KEEP, GL_ZERO, GL_REPLACE);
    glStencilMask(0xff);
    active_stencil_face(GL_BACK);
    print_all("two_side.back_face_active");
    glStencilFunc(GL_EQUAL, 2, 0x3);
    glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
    glStencilMask(0x5);
    print_all("two_side.back_face_set");
    glEnable(GL_STENCIL_TEST_TWO_SIDE_EXT);
    print_all("two_side.enabled");
    active_stencil_face(GL_FRONT);
    print_all("two_side.front_face_active");
    glStencilFuncSeparate(GL_BACK, GL_GREATER, 3, 0x7);
    glStencilOpSeparate(GL_FRONT_AND_BACK, GL_DECR_WRAP, GL_INCR_WRAP, GL_ZERO);
    glStencilMaskSeparate(GL_FRONT_AND_BACK, 0x11);
    active_stencil_face(GL_BACK);
    print_all("two_side.separate_calls");
    stencil_func_separate_ati(GL_NEVER, GL_ALWAYS, 4, 0x9);
    print_all("two_side.ati");
    glDisable(GL_STENCIL_TEST_TWO_SIDE_EXT);
    glStencilFunc(GL_GEQUAL, 6, 0x60);
    print_all("two_side.disabled_back_active");
    active_stencil_face(GL_FRONT);
    capi_expect_error(GL_NO_ERROR, "two_side");
}

/* Fog parameters through every entry point, including the integer color mapping and the
 * non-vector forms with GL_FOG_COLOR (Mesa passes the value as red, the rest 0). */
static void fog_forms(void)
{
    static const GLint icolor[4] = {0x7fffffff, -0x7fffffff, 0x40000000, 0};
    glFogiv(GL_FOG_COLOR, icolor);
    print_all("fog.iv_color");
    glFogi(GL_FOG_COLOR, 5);
    print_all("fog.i_color");
    glFogf(GL_FOG_COLOR, 0.25f);
    print_all("fog.f_color");
    GLint start = -7, index = 3;
    glFogiv(GL_FOG_START, &start);
    glFogiv(GL_FOG_INDEX, &index);
    glFogf(GL_FOG_END, 1e9f);
    glFogf(GL_FOG_DENSITY, 0.0f);
    glFogi(GL_FOG_MODE, GL_EXP2);
    GLfloat coord = (GLfloat)GL_FOG_COORD;
    glFogfv(GL_FOG_COORDINATE_SOURCE, &coord);
    print_all("fog.numbers");
    glFogf(GL_FOG_INDEX, -2.5f);
    glFogf(GL_FOG_START, 0.4999999f);
    print_all("fog.rounding");
    capi_expect_error(GL_NO_ERROR, "fog_forms");
}

/* Every setter between glBegin and glEnd: GL_INVALID_OPERATION, nothing changes. */
static void inside_begin_end(void)
{
    static const GLfloat f4[4] = {0.5f, 0.5f, 0.5f, 0.5f};
    static const GLint i4[4] = {1, 1, 1, 1};
    for (int k = 0; k < 24; k++) {
        glBegin(GL_POINTS);
        switch (k) {
        case 0: glAlphaFunc(GL_LESS, 0.5f); break;
        case 1: glStencilFunc(GL_LESS, 1, 1); break;
        case 2: glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO); break;
        case 3: glStencilFuncSeparate(GL_FRONT, GL_LESS, 1, 1); break;
        case 4: glStencilOpSeparate(GL_BACK, GL_ZERO, GL_ZERO, GL_ZERO); break;
        case 5: stencil_func_separate_ati(GL_LESS, GL_LESS, 1, 1); break;
        case 6: active_stencil_face(GL_BACK); break;
        case 7: glStencilMask(0); break;
        case 8: glBlendFunc(GL_ZERO, GL_ZERO); break;
        case 9: glBlendFuncSeparate(GL_ZERO, GL_ZERO, GL_ZERO, GL_ZERO); break;
        case 10: glBlendEquation(GL_MIN); break;
        case 11: glBlendEquationSeparate(GL_MIN, GL_MIN); break;
        case 12: glBlendColor(1, 1, 1, 1); break;
        case 13: glBlendFunci(0, GL_ZERO, GL_ZERO); break;
        case 14: glBlendFuncSeparatei(0, GL_ZERO, GL_ZERO, GL_ZERO, GL_ZERO); break;
        case 15: glBlendEquationi(0, GL_MIN); break;
        case 16: glBlendEquationSeparatei(0, GL_MIN, GL_MIN); break;
        case 17: glLogicOp(GL_XOR); break;
        case 18: glFogf(GL_FOG_START, 9); break;
        case 19: glFogi(GL_FOG_MODE, GL_EXP); break;
        case 20: glFogfv(GL_FOG_COLOR, f4); break;
        case 21: glFogiv(GL_FOG_COLOR, i4); break;
        case 22: glDepthFunc(GL_NEVER); break;
        case 23: glBlendFunci(9, GL_ZERO, GL_ZERO); break;
        }
        glEnd();
        char what[64];
        snprintf(what, sizeof what, "inside_begin_end.%d", k);
        capi_expect_error(GL_INVALID_OPERATION, what);
    }
    print_all("inside_begin_end");
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, &buffer);
    active_stencil_face = (PFNGLACTIVESTENCILFACEEXTPROC)OSMesaGetProcAddress("glActiveStencilFaceEXT");
    stencil_func_separate_ati = (PFNGLSTENCILFUNCSEPARATEATIPROC)OSMesaGetProcAddress("glStencilFuncSeparateATI");
    capi_check(active_stencil_face && stencil_func_separate_ati, "extension entry points");
    if (!active_stencil_face || !stencil_func_separate_ati)
        return capi_finish();

    /* The initial stencil masks are "1's": 0xff on Mesa 22, ~0 on tessera (see get_state.c).
     * Make them ~0 on all three faces (front, back, EXT back) before comparing. */
    active_stencil_face(GL_BACK);
    glStencilFunc(GL_ALWAYS, 0, ~0u);
    glStencilMask(~0u);
    active_stencil_face(GL_FRONT);
    glStencilFunc(GL_ALWAYS, 0, ~0u);
    glStencilMask(~0u);
    print_all("initial");
    set_values();
    print_all("set");
    errors();
    print_all("after_errors");
    /* Unclamped colors within [-1, 1]: beyond it Mesa 22's integer conversion wraps and
     * tessera's saturates (see src/context/get.rs). */
    glBlendColor(0.25f, -0.5f, 1.0f, -0.1f);
    static const GLfloat fog_color[4] = {-1.0f, 0.75f, -0.25f, 0.5f};
    glFogfv(GL_FOG_COLOR, fog_color);
    glAlphaFunc(GL_GEQUAL, -0.375f);
    print_all("clamped");
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    print_all("unclamped");
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FIXED_ONLY);
    two_side();
    fog_forms();
    every_enum();
    print_all("every_enum");
    inside_begin_end();

    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
