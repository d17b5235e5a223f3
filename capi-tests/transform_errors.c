/* The errors of the matrix commands and glActiveTexture, and that an erroneous call changes
 * nothing: bad matrix modes, stack overflow and underflow of every stack at its own depth,
 * degenerate glFrustum and glOrtho volumes (validated in single precision, as Mesa does), and
 * texture units out of range. Every command is GL_INVALID_OPERATION between glBegin and
 * glEnd (checked when the implementation has glBegin).
 *
 * Deliberate differences, checked per implementation and not printed: Mesa 22 ignores
 * glMatrixMode(GL_TEXTURE0) without an error (tessera: GL_INVALID_ENUM, as the specification
 * says), accepts GL_MATRIX0_ARB (ARB_vertex_program, which tessera lacks) and rejects
 * GL_COLOR (tessera keeps the imaging subset's color matrix stack); glActiveTexture accepts
 * Mesa's 192 combined units but tessera's 8 texture coordinate sets only.
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"

#define W 8
#define H 8

static void print_modelview(const char *key)
{
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    capi_value(key, "%a %a %a %a %a %a", m[0], m[5], m[10], m[12], m[13], m[14]);
}

static GLint get_int(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

static void matrix_modes(void)
{
    GLint mode;
    glMatrixMode(GL_PROJECTION);
    glMatrixMode(GL_MODELVIEW + 3);
    capi_expect_error(GL_INVALID_ENUM, "mode_bad");
    glMatrixMode(0);
    capi_expect_error(GL_INVALID_ENUM, "mode_zero");
    glMatrixMode(GL_TEXTURE_2D);
    capi_expect_error(GL_INVALID_ENUM, "mode_texture_2d");
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    capi_value("mode_unchanged", "0x%x", mode);

    glMatrixMode(GL_TEXTURE0);
    GLenum error = glGetError();
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    capi_check(error == (capi_is_tessera() ? GL_INVALID_ENUM : GL_NO_ERROR), "glMatrixMode(GL_TEXTURE0): 0x%x", error);
    capi_check(mode == GL_PROJECTION, "glMatrixMode(GL_TEXTURE0) changes nothing: 0x%x", mode);
    glMatrixMode(GL_MATRIX0_ARB);
    error = glGetError();
    capi_check(error == (capi_is_tessera() ? GL_INVALID_ENUM : GL_NO_ERROR), "glMatrixMode(GL_MATRIX0_ARB): 0x%x", error);
    glMatrixMode(GL_COLOR);
    error = glGetError();
    capi_check(error == (capi_is_tessera() ? GL_NO_ERROR : GL_INVALID_ENUM), "glMatrixMode(GL_COLOR): 0x%x", error);
    glMatrixMode(GL_MODELVIEW);
}

/* Pushes until the stack of `mode` overflows and pops until it underflows. */
static void overflow(const char *key, GLenum mode, GLenum depth_pname, GLenum max_pname)
{
    char what[64];
    glMatrixMode(mode);
    GLint max = get_int(max_pname);
    glPopMatrix();
    snprintf(what, sizeof what, "%s_underflow_initial", key);
    capi_expect_error(GL_STACK_UNDERFLOW, what);
    for (int i = 1; i < max; i++) {
        glTranslatef((float)i, 0.0f, 0.0f);
        glPushMatrix();
    }
    snprintf(what, sizeof what, "%s_full", key);
    capi_expect_error(GL_NO_ERROR, what);
    capi_value(what, "depth=%d", get_int(depth_pname));
    glScalef(2.0f, 2.0f, 2.0f);
    glPushMatrix();
    snprintf(what, sizeof what, "%s_overflow", key);
    capi_expect_error(GL_STACK_OVERFLOW, what);
    capi_value(what, "depth=%d", get_int(depth_pname));
    GLfloat m[16];
    int matches = 1;
    for (int i = max - 1; i >= 1; i--) {
        glPopMatrix();
        glGetFloatv(mode == GL_MODELVIEW ? GL_MODELVIEW_MATRIX
                    : mode == GL_PROJECTION ? GL_PROJECTION_MATRIX
                                            : GL_TEXTURE_MATRIX,
                    m);
        /* After popping to entry i-1 the top holds the translations 1..i. */
        matches &= m[12] == (float)(i * (i + 1) / 2) && m[0] == 1.0f;
    }
    snprintf(what, sizeof what, "%s_popped", key);
    capi_value(what, "depth=%d tops_match=%d", get_int(depth_pname), matches);
    glPopMatrix();
    snprintf(what, sizeof what, "%s_underflow", key);
    capi_expect_error(GL_STACK_UNDERFLOW, what);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
}

static void volumes(void)
{
    static const double bad_frustums[][6] = {
        {0, 1, 0, 1, 0, 1},           /* near = 0 */
        {0, 1, 0, 1, -1, 1},          /* near < 0 */
        {0, 1, 0, 1, 1, 0},           /* far = 0 */
        {0, 1, 0, 1, 1, -2},          /* far < 0 */
        {0, 1, 0, 1, 2, 2},           /* near = far */
        {1, 1, 0, 1, 1, 2},           /* left = right */
        {0, 1, 3, 3, 1, 2},           /* bottom = top */
        {1, 1 + 1e-10, 0, 1, 1, 2},   /* equal as floats */
        {0, 1, 0, 1, 1e-50, 2},       /* near is 0 as a float */
        {0, 1, 0, 1, 1, 1 + 1e-12},   /* near = far as floats */
    };
    static const double bad_orthos[][6] = {
        {1, 1, 0, 1, 0, 1},
        {0, 1, 2, 2, 0, 1},
        {0, 1, 0, 1, -3, -3},
        {0, 1e-50, 0, 1, 0, 1},
    };
    char key[64];
    glTranslatef(1.0f, 2.0f, 3.0f);
    for (unsigned i = 0; i < sizeof bad_frustums / sizeof bad_frustums[0]; i++) {
        const double *v = bad_frustums[i];
        glFrustum(v[0], v[1], v[2], v[3], v[4], v[5]);
        snprintf(key, sizeof key, "frustum_%u", i);
        capi_expect_error(GL_INVALID_VALUE, key);
    }
    for (unsigned i = 0; i < sizeof bad_orthos / sizeof bad_orthos[0]; i++) {
        const double *v = bad_orthos[i];
        glOrtho(v[0], v[1], v[2], v[3], v[4], v[5]);
        snprintf(key, sizeof key, "ortho_%u", i);
        capi_expect_error(GL_INVALID_VALUE, key);
    }
    print_modelview("after_bad_volumes");
    /* Legal though odd: a reversed ortho volume, negative planes, tiny differences. */
    glOrtho(1, -1, 1, -1, 1, -1);
    capi_expect_error(GL_NO_ERROR, "ortho_reversed");
    glOrtho(-5, -4, -3, -2, -10, -9);
    capi_expect_error(GL_NO_ERROR, "ortho_negative");
    glFrustum(2, 1, 1, 0.5, 0.25, 0.125);
    capi_expect_error(GL_NO_ERROR, "frustum_far_before_near");
    glFrustum(0, 1e-40, 0, 1, 1, 2);
    capi_expect_error(GL_NO_ERROR, "frustum_denormal_width");
    print_modelview("after_odd_volumes");
    glLoadIdentity();
}

static void texture_units(void)
{
    GLint max_units = get_int(GL_MAX_TEXTURE_UNITS);
    capi_check(max_units == (capi_is_tessera() ? 4 : 8), "GL_MAX_TEXTURE_UNITS %d", max_units);
    glActiveTexture(GL_TEXTURE0 + 3);
    capi_expect_error(GL_NO_ERROR, "active_texture_3");
    glActiveTexture(GL_TEXTURE0 - 1);
    capi_expect_error(GL_INVALID_ENUM, "active_texture_below");
    glActiveTexture(GL_TEXTURE0 + 200);
    capi_expect_error(GL_INVALID_ENUM, "active_texture_200");
    glActiveTexture(0);
    capi_expect_error(GL_INVALID_ENUM, "active_texture_zero");
    capi_value("active_texture", "0x%x", get_int(GL_ACTIVE_TEXTURE));
    /* Units past the fixed-function ones select texture coordinate sets (8 on both). */
    glActiveTexture(GL_TEXTURE0 + max_units);
    capi_expect_error(GL_NO_ERROR, "active_texture_max_units");
    glActiveTexture(GL_TEXTURE0 + 8);
    GLenum error = glGetError();
    capi_check(error == (capi_is_tessera() ? GL_INVALID_ENUM : GL_NO_ERROR), "unit 8: 0x%x", error);
    glActiveTextureARB(GL_TEXTURE1);
    capi_value("active_texture_arb", "0x%x", get_int(GL_ACTIVE_TEXTURE));
    glActiveTexture(GL_TEXTURE0);
    capi_expect_error(GL_NO_ERROR, "texture_units");
}

/* Every command between glBegin and glEnd: GL_INVALID_OPERATION and no change. */
static void inside_begin_end(void)
{
    void (*begin)(GLenum) = (void (*)(GLenum))OSMesaGetProcAddress("glBegin");
    void (*end)(void) = (void (*)(void))OSMesaGetProcAddress("glEnd");
    if (!begin || !end)
        return;
    static const GLfloat m[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 1, 1, 1};
    static const GLdouble md[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 1, 1, 1};
    GLfloat before[16], after[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, before);
    for (int i = 0;; i++) {
        begin(GL_POINTS);
        switch (i) {
        case 0: glMatrixMode(GL_PROJECTION); break;
        case 1: glPushMatrix(); break;
        case 2: glPopMatrix(); break;
        case 3: glLoadIdentity(); break;
        case 4: glLoadMatrixf(m); break;
        case 5: glLoadMatrixd(md); break;
        case 6: glMultMatrixf(m); break;
        case 7: glMultMatrixd(md); break;
        case 8: glLoadTransposeMatrixf(m); break;
        case 9: glMultTransposeMatrixd(md); break;
        case 10: glRotatef(30, 1, 0, 0); break;
        case 11: glRotated(30, 1, 0, 0); break;
        case 12: glScalef(2, 2, 2); break;
        case 13: glTranslated(1, 2, 3); break;
        case 14: glFrustum(-1, 1, -1, 1, 1, 2); break;
        case 15: glOrtho(-1, 1, -1, 1, 1, 2); break;
        case 16: glActiveTexture(GL_TEXTURE1); break;
        case 17: glFrustum(0, 0, 0, 0, 0, 0); break; /* invalid too: the Begin/End error wins */
        default: break;
        }
        end();
        if (i > 17)
            break;
        GLenum error = glGetError();
        capi_check(error == GL_INVALID_OPERATION, "command %d between glBegin/glEnd: 0x%x", i, error);
    }
    glGetFloatv(GL_MODELVIEW_MATRIX, after);
    capi_check(memcmp(before, after, sizeof before) == 0, "nothing changed between glBegin/glEnd");
    capi_check(get_int(GL_MATRIX_MODE) == GL_MODELVIEW && get_int(GL_MODELVIEW_STACK_DEPTH) == 1 &&
                   get_int(GL_ACTIVE_TEXTURE) == GL_TEXTURE0,
               "mode, depth and unit unchanged");
}

int main(void)
{
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    matrix_modes();
    overflow("modelview", GL_MODELVIEW, GL_MODELVIEW_STACK_DEPTH, GL_MAX_MODELVIEW_STACK_DEPTH);
    overflow("projection", GL_PROJECTION, GL_PROJECTION_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH);
    overflow("texture0", GL_TEXTURE, GL_TEXTURE_STACK_DEPTH, GL_MAX_TEXTURE_STACK_DEPTH);
    glActiveTexture(GL_TEXTURE3);
    overflow("texture3", GL_TEXTURE, GL_TEXTURE_STACK_DEPTH, GL_MAX_TEXTURE_STACK_DEPTH);
    glActiveTexture(GL_TEXTURE0);
    volumes();
    texture_units();
    inside_begin_end();
    capi_expect_error(GL_NO_ERROR, "end");
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
