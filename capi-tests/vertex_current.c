/* The current vertex attributes: every glColor, glSecondaryColor, glNormal, glTexCoord,
 * glMultiTexCoord, glFogCoord, glEdgeFlag and glIndex variant (scalar and vector, core and
 * EXT/ARB names), read back with glGetFloatv as exact hex floats (VALUE lines compared with
 * Mesa bit for bit), then the four glGet types of each attribute, glPushAttrib(GL_CURRENT_BIT),
 * and the initial values.
 *
 * The integer arguments are the corners of each type (its minimum, maximum, zero, one) and
 * values whose conversion rounds, so a conversion that is off by one unit in the last place
 * shows. Texture coordinates and positions convert integers by value, colors and normals as
 * normalized fixed point (GL 2.1 table 2.9, Mesa's arithmetic).
 *
 * Mesa 22 bug (asserted on tessera only): its immediate-mode attribute storage keeps stale
 * components when an attribute goes from fewer components to more and back without a flush
 * (vbo_exec_fixup_vertex does not record the larger size when the storage is already large
 * enough): after glColor4f, glColor3f, glColor4f(..., a), a glColor3f leaves alpha a instead
 * of 1, and likewise glTexCoord1f/2f/3f keep stale t, r, q. (glColor3b and the other non-float
 * forms go through glColor4f with alpha 1 and are not affected.) The printed calls are
 * separated by an empty glBegin/glEnd, which makes Mesa start afresh, so the bug stays out of
 * the VALUE lines; the sequences that show it are at the end.
 *
 * Deliberate differences from Mesa 22 (asserted per implementation, not printed): Mesa takes
 * glMultiTexCoord with any target (it writes unit target & 7), tessera only its 8 sets
 * (GL_INVALID_ENUM otherwise); glEdgeFlag(7) is TRUE in tessera (any nonzero GLboolean) and
 * FALSE in Mesa (only exactly 1); glGetIntegerv of a color beyond [-1, 1] saturates in tessera
 * and overflows to INT_MIN in Mesa.
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <limits.h>

/* An empty glBegin/glEnd: Mesa flushes its immediate-mode attribute storage there (see the
 * Mesa bug above); nothing happens in tessera. */
static void fresh(void)
{
    glBegin(GL_POINTS);
    glEnd();
}

/* glActiveTexture, looked up so the test runs where it is not exported yet; the texture
 * coordinates of units other than 0 are only checked (not printed) through it. */
static PFNGLACTIVETEXTUREPROC active_texture;

/* Checks the current texture coordinates of `unit` against `expected`. */
static void check_unit(const char *what, int unit, const GLfloat expected[4])
{
    if (!active_texture)
        return;
    GLfloat t[4];
    active_texture(GL_TEXTURE0 + unit);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
    active_texture(GL_TEXTURE0);
    capi_check(memcmp(t, expected, sizeof t) == 0, "%s: unit %d holds %a %a %a %a, expected %a %a %a %a", what, unit,
               t[0], t[1], t[2], t[3], expected[0], expected[1], expected[2], expected[3]);
    fresh();
}

static void show(const char *what)
{
    GLfloat c[4], s[4], n[3], t[4], f, i;
    GLboolean e;
    glGetFloatv(GL_CURRENT_COLOR, c);
    glGetFloatv(GL_CURRENT_SECONDARY_COLOR, s);
    glGetFloatv(GL_CURRENT_NORMAL, n);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
    glGetFloatv(GL_CURRENT_FOG_COORD, &f);
    glGetFloatv(GL_CURRENT_INDEX, &i);
    glGetBooleanv(GL_EDGE_FLAG, &e);
    capi_value(what, "color %a %a %a %a secondary %a %a %a %a normal %a %a %a tex %a %a %a %a fog %a index %a edge %d",
               c[0], c[1], c[2], c[3], s[0], s[1], s[2], s[3], n[0], n[1], n[2], t[0], t[1], t[2], t[3], f, i, e);
    capi_check(glGetError() == GL_NO_ERROR, "%s: no error", what);
    fresh();
}

/* Calls fn(args) and fnv(array of args), showing the state after each. */
#define CALL3N(fn, fnv, T, a, b, c)                                                               \
    do {                                                                                          \
        T v_[3] = {a, b, c};                                                                      \
        fn(a, b, c);                                                                              \
        show(#fn);                                                                                \
        glColor4f(0.125f, 0.125f, 0.125f, 0.125f);                                                \
        glSecondaryColor3f(0.125f, 0.125f, 0.125f);                                               \
        glNormal3f(0.125f, 0.125f, 0.125f);                                                       \
        fnv(v_);                                                                                  \
        show(#fnv);                                                                               \
    } while (0)
#define CALL3(fn, T, a, b, c) CALL3N(fn, fn##v, T, a, b, c)
#define CALL4(fn, T, a, b, c, d)                                                                  \
    do {                                                                                          \
        T v_[4] = {a, b, c, d};                                                                   \
        fn(a, b, c, d);                                                                           \
        show(#fn);                                                                                \
        glColor4f(0.125f, 0.125f, 0.125f, 0.125f);                                                \
        fn##v(v_);                                                                                \
        show(#fn "v");                                                                            \
    } while (0)

/* Each color variant with three argument sets: corners, mid values, small values. */
#define COLORS(sfx, T, lo, hi, mid1, mid2, small)                                                 \
    do {                                                                                          \
        CALL3(glColor3##sfx, T, lo, hi, mid1);                                                    \
        CALL3(glColor3##sfx, T, mid2, small, 0);                                                  \
        CALL4(glColor4##sfx, T, hi, lo, mid2, small);                                             \
        CALL4(glColor4##sfx, T, 0, 1, mid1, mid2);                                                \
        CALL3(glSecondaryColor3##sfx, T, lo, mid1, hi);                                           \
        CALL3N(glSecondaryColor3##sfx##EXT, glSecondaryColor3##sfx##vEXT, T, small, mid2, 1);                                    \
    } while (0)

static void colors(void)
{
    COLORS(b, GLbyte, -128, 127, 64, -37, 1);
    COLORS(ub, GLubyte, 0, 255, 128, 3, 6);
    COLORS(s, GLshort, -32768, 32767, 16384, -12345, 1);
    COLORS(us, GLushort, 0, 65535, 32768, 257, 12345);
    COLORS(i, GLint, INT_MIN, INT_MAX, 1073741824, -123456789, 2147483583);
    COLORS(ui, GLuint, 0, 4294967295u, 2147483648u, 4294967167u, 4294967040u);
    COLORS(f, GLfloat, -1.0f, 1.0f, 0.1f, 0.3f, 1e-30f);
    COLORS(d, GLdouble, -1.0, 1.0, 0.1, 1.0 / 3.0, 1e-50);
    /* Beyond [0, 1]: the current color is not clamped. */
    CALL4(glColor4f, GLfloat, 2.0f, -1.5f, 1e30f, -0.0f);
    CALL3(glSecondaryColor3d, GLdouble, 2.5, -7.0, 1e300);
    /* The vector forms of the EXT names. */
    CALL3N(glSecondaryColor3bEXT, glSecondaryColor3bvEXT, GLbyte, 1, 2, 3);
    CALL3N(glSecondaryColor3ubEXT, glSecondaryColor3ubvEXT, GLubyte, 1, 2, 3);
    CALL3N(glSecondaryColor3sEXT, glSecondaryColor3svEXT, GLshort, 1, 2, 3);
    CALL3N(glSecondaryColor3usEXT, glSecondaryColor3usvEXT, GLushort, 1, 2, 3);
    CALL3N(glSecondaryColor3iEXT, glSecondaryColor3ivEXT, GLint, 1, 2, 3);
    CALL3N(glSecondaryColor3uiEXT, glSecondaryColor3uivEXT, GLuint, 1, 2, 3);
    CALL3N(glSecondaryColor3fEXT, glSecondaryColor3fvEXT, GLfloat, 1, 2, 3);
    CALL3N(glSecondaryColor3dEXT, glSecondaryColor3dvEXT, GLdouble, 1, 2, 3);
}

static void normals(void)
{
    CALL3(glNormal3b, GLbyte, -128, 127, 1);
    CALL3(glNormal3b, GLbyte, 0, -1, 100);
    CALL3(glNormal3s, GLshort, -32768, 32767, 1);
    CALL3(glNormal3s, GLshort, 0, -1, 30000);
    CALL3(glNormal3i, GLint, INT_MIN, INT_MAX, 1);
    CALL3(glNormal3i, GLint, 0, -1, 987654321);
    CALL3(glNormal3f, GLfloat, 0.6f, -0.8f, 3.0f);
    CALL3(glNormal3d, GLdouble, 0.1, 1e-40, -1e40);
}

/* glTexCoordN (unit 0, printed) and glMultiTexCoordN (units 0, 2 and 3: printed for unit
 * 0, checked against the values converted by value for the others). */
#define TEXN(n, sfx, T, ...)                                                                      \
    do {                                                                                          \
        T v_[4] = {__VA_ARGS__};                                                                  \
        GLfloat e_[4] = {0, 0, 0, 1};                                                             \
        for (int k_ = 0; k_ < n; k_++)                                                            \
            e_[k_] = (GLfloat)v_[k_];                                                             \
        glTexCoord##n##sfx##v(v_);                                                                \
        show("glTexCoord" #n #sfx "v");                                                           \
        glTexCoord4f(9, 9, 9, 9);                                                                 \
        glMultiTexCoord##n##sfx##v(GL_TEXTURE0, v_);                                              \
        show("glMultiTexCoord" #n #sfx "v unit 0");                                               \
        glMultiTexCoord##n##sfx##v(GL_TEXTURE2, v_);                                              \
        check_unit("glMultiTexCoord" #n #sfx "v", 2, e_);                                         \
        glMultiTexCoord##n##sfx##vARB(GL_TEXTURE3, v_);                                           \
        check_unit("glMultiTexCoord" #n #sfx "vARB", 3, e_);                                      \
    } while (0)

static void tex_coords(void)
{
    TEXN(1, s, GLshort, -32768, 0, 0, 0);
    TEXN(2, s, GLshort, 32767, -5, 0, 0);
    TEXN(3, s, GLshort, 1, 2, 3, 0);
    TEXN(4, s, GLshort, -1, -2, -3, -4);
    TEXN(1, i, GLint, INT_MIN, 0, 0, 0);
    TEXN(2, i, GLint, INT_MAX, 16777217, 0, 0);
    TEXN(3, i, GLint, 1, 2, 3, 0);
    TEXN(4, i, GLint, -1, -2, -3, 123456789);
    TEXN(1, f, GLfloat, 0.5f, 0, 0, 0);
    TEXN(2, f, GLfloat, 2.5f, -0.5f, 0, 0);
    TEXN(3, f, GLfloat, 1.5f, -2.5f, 1e-30f, 0);
    TEXN(4, f, GLfloat, 0.1f, 0.2f, 0.3f, 0.4f);
    TEXN(1, d, GLdouble, 0.1, 0, 0, 0);
    TEXN(2, d, GLdouble, 1e300, -1e-300, 0, 0);
    TEXN(3, d, GLdouble, 1.0 / 3.0, 2.0 / 3.0, 5.5, 0);
    TEXN(4, d, GLdouble, -0.5, 0.5, 1.5, -1.5);
    /* The scalar forms, each once. */
    glTexCoord1s(3); show("glTexCoord1s");
    glTexCoord2s(3, 4); show("glTexCoord2s");
    glTexCoord3s(3, 4, 5); show("glTexCoord3s");
    glTexCoord4s(3, 4, 5, 6); show("glTexCoord4s");
    glTexCoord1i(-3); show("glTexCoord1i");
    glTexCoord2i(-3, 7); show("glTexCoord2i");
    glTexCoord3i(-3, 7, 9); show("glTexCoord3i");
    glTexCoord4i(-3, 7, 9, 11); show("glTexCoord4i");
    glTexCoord1f(0.25f); show("glTexCoord1f");
    glTexCoord2f(0.25f, 0.75f); show("glTexCoord2f");
    glTexCoord3f(0.25f, 0.75f, 1.25f); show("glTexCoord3f");
    glTexCoord4f(0.25f, 0.75f, 1.25f, 2.0f); show("glTexCoord4f");
    glTexCoord1d(0.1); show("glTexCoord1d");
    glTexCoord2d(0.1, 0.2); show("glTexCoord2d");
    glTexCoord3d(0.1, 0.2, 0.3); show("glTexCoord3d");
    glTexCoord4d(0.1, 0.2, 0.3, 0.4); show("glTexCoord4d");
    /* The scalar glMultiTexCoord forms, on unit 0 (printed) and unit 1 (checked). */
#define MTC(call, ...)                                                                            \
    do {                                                                                          \
        GLfloat e_[4] = {__VA_ARGS__};                                                            \
        GLenum target = GL_TEXTURE0;                                                              \
        call;                                                                                     \
        show(#call);                                                                              \
        target = GL_TEXTURE1;                                                                     \
        call;                                                                                     \
        check_unit(#call, 1, e_);                                                                 \
    } while (0)
    MTC(glMultiTexCoord1s(target, 8), 8, 0, 0, 1);
    MTC(glMultiTexCoord2sARB(target, 8, 9), 8, 9, 0, 1);
    MTC(glMultiTexCoord3s(target, 8, 9, 10), 8, 9, 10, 1);
    MTC(glMultiTexCoord4sARB(target, 8, 9, 10, 11), 8, 9, 10, 11);
    MTC(glMultiTexCoord1i(target, -8), -8, 0, 0, 1);
    MTC(glMultiTexCoord2i(target, -8, 9), -8, 9, 0, 1);
    MTC(glMultiTexCoord3iARB(target, -8, 9, 10), -8, 9, 10, 1);
    MTC(glMultiTexCoord4i(target, -8, 9, 10, 11), -8, 9, 10, 11);
    MTC(glMultiTexCoord1f(target, 0.5f), 0.5f, 0, 0, 1);
    MTC(glMultiTexCoord2f(target, 0.5f, 1.5f), 0.5f, 1.5f, 0, 1);
    MTC(glMultiTexCoord3f(target, 0.5f, 1.5f, 2.5f), 0.5f, 1.5f, 2.5f, 1);
    MTC(glMultiTexCoord4fARB(target, 0.5f, 1.5f, 2.5f, 3.5f), 0.5f, 1.5f, 2.5f, 3.5f);
    MTC(glMultiTexCoord1dARB(target, 0.7), (GLfloat)0.7, 0, 0, 1);
    MTC(glMultiTexCoord2d(target, 0.7, 0.8), (GLfloat)0.7, (GLfloat)0.8, 0, 1);
    MTC(glMultiTexCoord3d(target, 0.7, 0.8, 0.9), (GLfloat)0.7, (GLfloat)0.8, (GLfloat)0.9, 1);
    MTC(glMultiTexCoord4d(target, 0.7, 0.8, 0.9, 1.1), (GLfloat)0.7, (GLfloat)0.8, (GLfloat)0.9, (GLfloat)1.1);
    /* glTexCoord is unit 0 whatever the active unit. */
    if (active_texture) {
        const GLfloat unit1[4] = {(GLfloat)0.7, (GLfloat)0.8, (GLfloat)0.9, (GLfloat)1.1};
        active_texture(GL_TEXTURE1);
        glTexCoord2f(42.0f, 43.0f);
        active_texture(GL_TEXTURE0);
        check_unit("glTexCoord2f with unit 1 active", 1, unit1);
    } else {
        glTexCoord2f(42.0f, 43.0f);
    }
    show("unit 0 after glTexCoord2f");
}

static void fog_index_edge(void)
{
    GLfloat f = 2.5f;
    GLdouble d = -0.1;
    glFogCoordf(0.5f); show("glFogCoordf");
    glFogCoordfv(&f); show("glFogCoordfv");
    glFogCoordd(0.1); show("glFogCoordd");
    glFogCoorddv(&d); show("glFogCoorddv");
    glFogCoordfEXT(-3.5f); show("glFogCoordfEXT");
    glFogCoordfvEXT(&f); show("glFogCoordfvEXT");
    glFogCoorddEXT(1e40); show("glFogCoorddEXT");
    glFogCoorddvEXT(&d); show("glFogCoorddvEXT");

    GLshort s = -300;
    GLint i = 100000;
    GLfloat fi = 2.5f;
    GLdouble di = -3.5;
    GLubyte ub = 200;
    glIndexs(7); show("glIndexs");
    glIndexsv(&s); show("glIndexsv");
    glIndexi(-7); show("glIndexi");
    glIndexiv(&i); show("glIndexiv");
    glIndexf(0.75f); show("glIndexf");
    glIndexfv(&fi); show("glIndexfv");
    glIndexd(0.1); show("glIndexd");
    glIndexdv(&di); show("glIndexdv");
    glIndexub(255); show("glIndexub");
    glIndexubv(&ub); show("glIndexubv");

    GLboolean no = GL_FALSE, yes = GL_TRUE;
    glEdgeFlag(GL_FALSE); show("glEdgeFlag false");
    glEdgeFlagv(&yes); show("glEdgeFlagv true");
    glEdgeFlagv(&no); show("glEdgeFlagv false");
    glEdgeFlag(GL_TRUE); show("glEdgeFlag true");
}

/* The four glGet types of every attribute, with values inside [-1, 1] for the normalized
 * ones (beyond, Mesa's integer conversion overflows). */
static void get_types(void)
{
    glColor4f(0.5f, -0.25f, 0.1f, 1.0f);
    glSecondaryColor3f(-1.0f, 0.3f, 0.0f);
    glNormal3f(-0.5f, 0.3f, 1.0f);
    glTexCoord4f(2.5f, -0.5f, 1.5f, -2.5f);
    glFogCoordf(-0.5f);
    glIndexf(-3.5f);
    glEdgeFlag(GL_FALSE);
    const struct { const char *name; GLenum pname; int n; } q[] = {
        {"GL_CURRENT_COLOR", GL_CURRENT_COLOR, 4},
        {"GL_CURRENT_SECONDARY_COLOR", GL_CURRENT_SECONDARY_COLOR, 4},
        {"GL_CURRENT_NORMAL", GL_CURRENT_NORMAL, 3},
        {"GL_CURRENT_TEXTURE_COORDS", GL_CURRENT_TEXTURE_COORDS, 4},
        {"GL_CURRENT_FOG_COORD", GL_CURRENT_FOG_COORD, 1},
        {"GL_CURRENT_INDEX", GL_CURRENT_INDEX, 1},
        {"GL_EDGE_FLAG", GL_EDGE_FLAG, 1},
    };
    for (unsigned k = 0; k < sizeof q / sizeof q[0]; k++) {
        GLint iv[4] = {0};
        GLdouble dv[4] = {0};
        GLboolean bv[4] = {0};
        glGetIntegerv(q[k].pname, iv);
        glGetDoublev(q[k].pname, dv);
        glGetBooleanv(q[k].pname, bv);
        char line[512];
        int len = 0;
        for (int j = 0; j < q[k].n; j++)
            len += snprintf(line + len, sizeof line - len, " %d/%.17g/%d", iv[j], dv[j], bv[j]);
        capi_value(q[k].name, "%s", line);
    }
    capi_expect_error(GL_NO_ERROR, "get_types");
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 8, 8, &buffer);
    int tessera = capi_is_tessera();

    active_texture = (PFNGLACTIVETEXTUREPROC)OSMesaGetProcAddress("glActiveTexture");
    capi_check(tessera || active_texture, "Mesa has glActiveTexture");

    show("initial");
    GLfloat c[4];
    glGetFloatv(GL_CURRENT_COLOR, c);
    capi_check(c[0] == 1 && c[1] == 1 && c[2] == 1 && c[3] == 1, "initial color is white");
    const GLfloat initial_tex[4] = {0, 0, 0, 1};
    check_unit("initial", 3, initial_tex);

    colors();
    normals();
    tex_coords();
    fog_index_edge();
    get_types();

    /* glPushAttrib(GL_CURRENT_BIT) saves and restores every current attribute. */
    glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
    glSecondaryColor3f(0.5f, 0.6f, 0.7f);
    glNormal3f(0, 1, 0);
    glMultiTexCoord4f(GL_TEXTURE1, 1, 2, 3, 4);
    glFogCoordf(9);
    glIndexf(5);
    glEdgeFlag(GL_FALSE);
    show("before push");
    glPushAttrib(GL_CURRENT_BIT);
    glColor3ub(1, 2, 3);
    glSecondaryColor3ub(4, 5, 6);
    glNormal3b(7, 8, 9);
    glMultiTexCoord1i(GL_TEXTURE1, 10);
    glFogCoordd(11);
    glIndexi(12);
    glEdgeFlag(GL_TRUE);
    show("changed");
    glPopAttrib();
    show("after pop");
    const GLfloat pushed_tex[4] = {1, 2, 3, 4};
    check_unit("after pop", 1, pushed_tex);
    glPushAttrib(GL_ALL_ATTRIB_BITS & ~GL_CURRENT_BIT);
    glColor3f(0.25f, 0.5f, 0.75f);
    glPopAttrib();
    show("current bit not pushed");
    capi_expect_error(GL_NO_ERROR, "push/pop current");

    /* Attribute commands between glBegin and glEnd set the current values there. */
    glBegin(GL_POINTS);
    glColor3f(0.5f, 0.25f, 0.125f);
    glNormal3s(100, 200, 300);
    glTexCoord2i(5, 6);
    glFogCoordf(3);
    glIndexi(4);
    glEdgeFlag(GL_FALSE);
    glSecondaryColor3us(1000, 2000, 3000);
    glEnd();
    capi_expect_error(GL_NO_ERROR, "attributes inside glBegin/glEnd");
    show("set inside glBegin/glEnd");

    /* glMultiTexCoord of a coordinate set past the fixed-function units (both have 8 sets),
     * and of one past GL_MAX_TEXTURE_COORDS: tessera's GL_INVALID_ENUM; Mesa does not check
     * the target (it writes set `target & 7`, so that call is tessera's alone). */
    glMultiTexCoord2f(GL_TEXTURE4, 1, 2);
    capi_expect_error(GL_NO_ERROR, "glMultiTexCoord(GL_TEXTURE4)");
    show("after glMultiTexCoord(GL_TEXTURE4)");
    if (tessera) {
        glMultiTexCoord2f(GL_TEXTURE8, 1, 2);
        GLenum error = glGetError();
        capi_check(error == GL_INVALID_ENUM, "glMultiTexCoord(GL_TEXTURE8): 0x%x", error);
    }

    /* glEdgeFlag with a GLboolean that is neither 0 nor 1. */
    glEdgeFlag(7);
    GLboolean edge;
    glGetBooleanv(GL_EDGE_FLAG, &edge);
    capi_check(edge == (tessera ? GL_TRUE : GL_FALSE), "glEdgeFlag(7) reads %d", edge);
    glEdgeFlag(GL_TRUE);

    /* The sequences that show Mesa's stale components: fewer, more, fewer components. */
    fresh();
    glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
    glColor3f(0.5f, 0.5f, 0.5f);
    glColor4f(0.25f, 0.25f, 0.25f, 0.25f);
    glColor3f(0.75f, 0.75f, 0.75f);
    glGetFloatv(GL_CURRENT_COLOR, c);
    capi_check(c[3] == (tessera ? 1.0f : 0.25f), "glColor3f after glColor4f, glColor3f, glColor4f: alpha %a", c[3]);
    fresh();
    glTexCoord4f(9, 9, 9, 9);
    glTexCoord1f(1);
    glTexCoord4f(2, 3, 4, 5);
    glTexCoord2f(6, 7);
    GLfloat t[4];
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
    if (tessera)
        capi_check(t[2] == 0 && t[3] == 1, "glTexCoord2f after glTexCoord1f, glTexCoord4f: %a %a", t[2], t[3]);
    else
        capi_check(t[2] == 4 && t[3] == 5, "Mesa's stale r, q: %a %a", t[2], t[3]);
    fresh();

    /* Beyond [-1, 1], integer queries of normalized values: tessera saturates. */
    glColor4f(2.0f, -2.0f, 0, 0);
    GLint iv[4];
    glGetIntegerv(GL_CURRENT_COLOR, iv);
    if (tessera)
        capi_check(iv[0] == INT_MAX && iv[1] == INT_MIN, "saturated: %d %d", iv[0], iv[1]);
    capi_expect_error(GL_NO_ERROR, "end");

    /* Mesa 22 crashes destroying a current context with unflushed draws. */
    glFinish();
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
