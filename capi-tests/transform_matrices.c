/* Matrix arithmetic, bit for bit: chains of glTranslate/glRotate/glScale/glFrustum/glOrtho/
 * glLoadMatrix/glMultMatrix on every stack, read back with glGetFloatv and glGetDoublev and
 * printed with %a, so that tessera must reproduce Mesa's single-precision results exactly,
 * down to the sign of zeros (which depends on Mesa's choice between its full and its 3x4
 * product, made from what was multiplied into the matrix and when it was last analysed).
 *
 * Also printed: transposed queries, booleans, stack depths and their maxima, the matrix mode
 * and the active texture. Integers are checked only: GL 2.1 (6.1.2) rounds matrix elements
 * to the nearest integer, while Mesa 22 maps them like colors (0.5 -> 1073741823); tessera
 * follows the specification. The color matrix (imaging subset) is tessera's only.
 * GL_TRANSPOSE_TEXTURE_MATRIX is compared with the active unit 0 only: Mesa 22 answers it
 * from unit 0 whatever the active unit (a bug; tessera answers for the active unit, checked).
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <math.h>

#define W 8
#define H 8

/* Prints the 16 values of a matrix query as floats, doubles (both %a) and booleans, and
 * checks the integers against round-to-nearest of the floats on tessera. */
static void print_matrix(const char *key, GLenum pname)
{
    GLfloat f[16];
    GLdouble d[16];
    GLboolean b[16];
    GLint i[16];
    char line[1024];
    int n = 0;
    glGetFloatv(pname, f);
    glGetDoublev(pname, d);
    glGetBooleanv(pname, b);
    glGetIntegerv(pname, i);
    for (int k = 0; k < 16; k++)
        n += snprintf(line + n, sizeof line - n, "%a ", f[k]);
    capi_value(key, "f %s", line);
    n = 0;
    for (int k = 0; k < 16; k++)
        n += snprintf(line + n, sizeof line - n, "%a ", d[k]);
    capi_value(key, "d %s", line);
    n = 0;
    for (int k = 0; k < 16; k++)
        n += snprintf(line + n, sizeof line - n, "%d", b[k]);
    capi_value(key, "b %s", line);
    for (int k = 0; k < 16; k++) {
        capi_check(d[k] == (GLdouble)f[k], "%s[%d]: double %a is not the float %a", key, k, d[k], f[k]);
        if (capi_is_tessera()) {
            long expected = fabsf(f[k]) < 2147483647.0f ? lroundf(f[k]) : (f[k] > 0 ? 2147483647L : -2147483648L);
            capi_check(i[k] == expected, "%s[%d]: integer %d, expected %ld (rounded %a)", key, k, i[k], expected, f[k]);
        }
    }
    capi_expect_error(GL_NO_ERROR, key);
}

static void print_int(const char *key, GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    capi_value(key, "%d", v);
}

static void print_current(const char *key)
{
    GLint mode;
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    GLenum pname = mode == GL_PROJECTION ? GL_PROJECTION_MATRIX
                   : mode == GL_TEXTURE  ? GL_TEXTURE_MATRIX
                                         : GL_MODELVIEW_MATRIX;
    print_matrix(key, pname);
}

static void chains(void)
{
    /* Modelview: a chain of every command, the axis rotations and an arbitrary one. */
    glTranslatef(1.5f, -2.25f, 3.0f);
    print_current("mv_translate");
    glRotatef(33.0f, 0.3f, -0.5f, 0.8f);
    print_current("mv_rotate_arbitrary");
    glScalef(1.1f, -0.7f, 2.3f);
    print_current("mv_scale");
    glRotatef(-71.3f, 0.0f, 1.0f, 0.0f);
    glRotated(12.5, -4.0, 0.0, 0.0);
    glRotatef(200.0f, 0.0f, 0.0f, -0.001f);
    print_current("mv_rotate_axes");
    glTranslated(0.1, 0.2, 0.3);
    glScaled(1e-3, 1e-3, 1e-3);
    print_current("mv_chain");

    /* Projection: a frustum, after which rotations take Mesa's full product. */
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.1, 0.9, -0.7, 0.8, 0.5, 100.0);
    print_current("proj_frustum");
    glRotatef(10.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -5.0f);
    print_current("proj_frustum_rotated");
    glLoadIdentity();
    glOrtho(-3.0, 5.0, -2.0, 7.0, -1.0, 9.0);
    print_current("proj_ortho");
    glRotatef(45.0f, 0.0f, 0.0f, 1.0f);
    glOrtho(0.1, 0.3, 0.1, 0.7, 0.25, 1000.0);
    print_current("proj_ortho_chain");
    glLoadIdentity();
    glFrustum(-0.1, 0.1, -0.075, 0.075, 0.1, 1e6);
    glFrustum(1.0, 3.0, 2.0, 5.0, 7.0, 11.0);
    print_current("proj_frustum_twice");
    glMatrixMode(GL_MODELVIEW);
}

static void texture_stacks(void)
{
    /* The texture stack of unit 2; unit 0's stays the identity. glScale(-1, -1, -1) leaves
     * -0 in the matrix, and the rotation's 3x4 product keeps it at element 8. */
    glActiveTexture(GL_TEXTURE2);
    glMatrixMode(GL_TEXTURE);
    glScalef(-1.0f, -1.0f, -1.0f);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    print_matrix("tex2", GL_TEXTURE_MATRIX);
    if (capi_is_tessera()) {
        GLfloat m[16], t[16];
        glGetFloatv(GL_TEXTURE_MATRIX, m);
        glGetFloatv(GL_TRANSPOSE_TEXTURE_MATRIX, t);
        for (int k = 0; k < 16; k++)
            capi_check(t[k] == m[(k % 4) * 4 + k / 4], "GL_TRANSPOSE_TEXTURE_MATRIX of unit 2 [%d]", k);
    }
    glPushMatrix();
    glPushMatrix();
    print_int("tex2_depth", GL_TEXTURE_STACK_DEPTH);
    glActiveTexture(GL_TEXTURE0);
    print_int("tex0_depth", GL_TEXTURE_STACK_DEPTH);
    print_matrix("tex0", GL_TEXTURE_MATRIX);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(7.0f, 8.0f, 9.0f);
    glRotatef(-20.0f, 1.0f, 2.0f, 2.0f);
    print_matrix("tex0_transposed", GL_TRANSPOSE_TEXTURE_MATRIX);
    glLoadIdentity();
    glActiveTexture(GL_TEXTURE2);
    glPopMatrix();
    glPopMatrix();
    print_int("tex2_depth_popped", GL_TEXTURE_STACK_DEPTH);
    print_int("active_texture", GL_ACTIVE_TEXTURE);
    glLoadIdentity();
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_MODELVIEW);
}

static void load_and_multiply(void)
{
    static const GLfloat general[16] = {0.5f, 0.25f, -1.0f, 0.125f, 2.0f, -0.75f, 0.3f, 0.0f,
                                        0.1f, 0.2f,  0.3f,  0.4f,   -1.0f, 2.0f, -3.0f, 1.5f};
    static const GLdouble doubles[16] = {0.1, 0.2, 0.3, 0.0, -0.4, 0.5, 0.6, 0.0,
                                         0.7, -0.8, 0.9, 0.0, 1.0 / 3.0, 2.0 / 3.0, 1e-9, 1.0};
    glLoadMatrixf(general);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f); /* after a load: always the full product */
    print_current("load_general_rotated");
    glMultMatrixd(doubles);
    print_current("mult_doubles");
    glLoadMatrixd(doubles);
    print_current("load_doubles");
    glLoadTransposeMatrixf(general);
    print_current("load_transpose_f");
    print_matrix("load_transpose_f_transposed", GL_TRANSPOSE_MODELVIEW_MATRIX);
    glMultTransposeMatrixd(doubles);
    print_current("mult_transpose_d");
    glLoadTransposeMatrixd(doubles);
    glMultTransposeMatrixf(general);
    glMultMatrixf(general);
    print_current("load_mult_transpose");
    print_matrix("load_mult_transpose_transposed", GL_TRANSPOSE_MODELVIEW_MATRIX);
    glLoadIdentity();
    print_current("identity");
}

/* Where Mesa's bookkeeping shows: the same arithmetic gives +0 or -0 depending on what
 * Mesa knows about the matrix at the time. */
static void zero_signs(void)
{
    static const GLfloat negate[16] = {-1.0f, -0.0f, -0.0f, -0.0f, -0.0f, -1.0f, -0.0f, -0.0f,
                                       -0.0f, -0.0f, -1.0f, -0.0f, 0.0f,  0.0f,  0.0f,  1.0f};
    /* A loaded matrix is "general": the rotation takes the full product. */
    glLoadMatrixf(negate);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    print_current("loaded_then_rotated");
    /* glPushMatrix analyses the matrix, which then is known to be affine: 3x4 product. */
    glLoadMatrixf(negate);
    glPushMatrix();
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    print_current("loaded_pushed_rotated");
    glPopMatrix();
    print_current("popped");
    /* glLoadIdentity keeps what was multiplied in before: after a frustum, full products. */
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 2.0);
    glLoadIdentity();
    glScalef(-1.0f, -1.0f, -1.0f);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    print_current("identity_after_frustum");
    glPushMatrix(); /* analysed from the flags: still general */
    glPopMatrix();
    glLoadIdentity();
    glScalef(-1.0f, -1.0f, -1.0f);
    glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    print_current("identity_after_frustum_pushed");
    /* A fresh stack entry after popping all: an affine chain. */
    glLoadIdentity();
    glPushMatrix();
    glLoadMatrixf(negate);
    glLoadIdentity();
    glScalef(-1.0f, -1.0f, -1.0f);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    print_current("reloaded_identity");
    glPopMatrix();
    glScalef(-1.0f, -1.0f, -1.0f);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    print_current("popped_identity");
    glMultMatrixf(negate);
    print_current("mult_negate");
    glLoadIdentity();
}

/* A draw validates state, and Mesa analyses the changed matrices then: a loaded matrix known
 * to be affine afterwards takes the 3x4 product, which keeps -0 at element 8. Checked (not
 * printed) so that it holds as soon as the implementation can draw. */
static void draw_time_analysis(void)
{
    static const GLfloat negate[16] = {-1.0f, -0.0f, -0.0f, -0.0f, -0.0f, -1.0f, -0.0f, -0.0f,
                                       -0.0f, -0.0f, -1.0f, -0.0f, 0.0f,  0.0f,  0.0f,  1.0f};
    void (*begin)(GLenum) = (void (*)(GLenum))OSMesaGetProcAddress("glBegin");
    void (*vertex)(GLfloat, GLfloat, GLfloat) = (void (*)(GLfloat, GLfloat, GLfloat))OSMesaGetProcAddress("glVertex3f");
    void (*end)(void) = (void (*)(void))OSMesaGetProcAddress("glEnd");
    if (!begin || !vertex || !end)
        return;
    GLfloat m[16];
    glLoadMatrixf(negate);
    begin(GL_POINTS);
    vertex(0.0f, 0.0f, 0.0f);
    end();
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    capi_check(m[8] == 0.0f && signbit(m[8]), "after a draw, the 3x4 product: element 8 is %a", m[8]);
    glLoadIdentity();
    capi_check(glGetError() == GL_NO_ERROR, "draw_time_analysis");
}

static void rotation_corners(void)
{
    glLoadIdentity();
    glRotatef(0.0f, 1.0f, 2.0f, 3.0f); /* no rotation at all */
    glRotatef(45.0f, 0.0f, 0.0f, 0.0f); /* zero axis: nothing */
    glRotatef(45.0f, 1e-5f, 1e-5f, 1e-5f); /* shorter than 1e-4: nothing */
    print_current("rotate_nothing");
    glRotatef(45.0f, 1e-4f, 0.0f, 1e-4f); /* just long enough */
    print_current("rotate_short_axis");
    glLoadIdentity();
    glRotatef(1e6f, 3.0f, 4.0f, 12.0f);
    print_current("rotate_big_angle");
    glLoadIdentity();
    for (int k = 0; k < 7; k++)
        glRotatef(-51.43f * (float)k, (float)(k % 3) - 1.0f, 0.5f, (float)k);
    print_current("rotate_sequence");
    glLoadIdentity();
    glRotated(90.0, 0.0, -2.0, 0.0);
    glRotated(180.0, 1.0, 0.0, 0.0);
    glRotated(270.0, 0.0, 0.0, 1.0);
    print_current("rotate_right_angles");
    glLoadIdentity();
    glScalef(0.0f, 1.0f, 1.0f);
    glTranslatef(1e30f, -1e30f, 3.0f);
    glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
    print_current("singular_huge");
    glLoadIdentity();
}

static void stacks(void)
{
    print_int("mv_depth", GL_MODELVIEW_STACK_DEPTH);
    print_int("proj_depth", GL_PROJECTION_STACK_DEPTH);
    print_int("tex_depth", GL_TEXTURE_STACK_DEPTH);
    print_int("max_mv_depth", GL_MAX_MODELVIEW_STACK_DEPTH);
    print_int("max_proj_depth", GL_MAX_PROJECTION_STACK_DEPTH);
    print_int("max_tex_depth", GL_MAX_TEXTURE_STACK_DEPTH);
    glTranslatef(1.0f, 2.0f, 3.0f);
    glPushMatrix();
    glScalef(2.0f, 2.0f, 2.0f);
    glPushMatrix();
    print_int("mv_depth_pushed", GL_MODELVIEW_STACK_DEPTH);
    print_current("pushed_top");
    glPopMatrix();
    glPopMatrix();
    print_current("popped_twice");
    print_int("mv_depth_popped", GL_MODELVIEW_STACK_DEPTH);
    glLoadIdentity();
    glMatrixMode(GL_PROJECTION);
    print_int("mode_projection", GL_MATRIX_MODE);
    glPushMatrix();
    print_int("proj_depth_pushed", GL_PROJECTION_STACK_DEPTH);
    print_int("mv_depth_unchanged", GL_MODELVIEW_STACK_DEPTH);
    glPopMatrix();
    glMatrixMode(GL_TEXTURE);
    print_int("mode_texture", GL_MATRIX_MODE);
    glMatrixMode(GL_MODELVIEW);
    print_int("mode_modelview", GL_MATRIX_MODE);
    capi_expect_error(GL_NO_ERROR, "stacks");
}

/* The imaging subset's color matrix: tessera has it, Mesa 22 does not. */
static void color_matrix(void)
{
    if (!capi_is_tessera())
        return;
    GLint depth = 0, max = 0;
    GLfloat m[16], t[16];
    glMatrixMode(GL_COLOR);
    capi_check(glGetError() == GL_NO_ERROR, "glMatrixMode(GL_COLOR)");
    glScalef(0.5f, 0.25f, 2.0f);
    glTranslatef(1.0f, 1.0f, 1.0f);
    glPushMatrix();
    glGetIntegerv(GL_COLOR_MATRIX_STACK_DEPTH, &depth);
    glGetIntegerv(GL_MAX_COLOR_MATRIX_STACK_DEPTH, &max);
    glGetFloatv(GL_COLOR_MATRIX, m);
    glGetFloatv(GL_TRANSPOSE_COLOR_MATRIX, t);
    capi_check(depth == 2 && max == 10, "color matrix depth %d of %d", depth, max);
    capi_check(m[0] == 0.5f && m[5] == 0.25f && m[10] == 2.0f && m[12] == 0.5f && m[13] == 0.25f && m[14] == 2.0f,
               "color matrix");
    capi_check(t[3] == 0.5f && t[7] == 0.25f && t[11] == 2.0f, "transposed color matrix");
    glPopMatrix();
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    capi_check(glGetError() == GL_NO_ERROR, "color matrix errors");
}

int main(void)
{
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    print_matrix("initial_modelview", GL_MODELVIEW_MATRIX);
    print_matrix("initial_projection", GL_PROJECTION_MATRIX);
    print_matrix("initial_texture", GL_TEXTURE_MATRIX);
    print_int("initial_mode", GL_MATRIX_MODE);
    chains();
    print_matrix("chain_transposed", GL_TRANSPOSE_MODELVIEW_MATRIX);
    print_matrix("projection_transposed", GL_TRANSPOSE_PROJECTION_MATRIX);
    glLoadIdentity();
    texture_stacks();
    load_and_multiply();
    zero_signs();
    draw_time_analysis();
    rotation_corners();
    stacks();
    color_matrix();
    capi_expect_error(GL_NO_ERROR, "end");
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
