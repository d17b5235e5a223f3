/* glClipPlane and glGetClipPlane: the plane is multiplied by the inverse of the modelview
 * matrix at specification, in single precision, and Mesa picks one of six inversion
 * algorithms from what it knows about the matrix (identity, translation and scale, 2-D and
 * 3-D rotations with uniform or general scale, general). Each plane is read back with %a, so
 * tessera must pick the same algorithm and do the same arithmetic, including Mesa's quirks:
 * the 3-D algorithms keep the bottom row of the previous inverse, and a singular matrix has
 * the identity as its inverse.
 *
 * Then GL_TRANSFORM_BIT (planes, their enables and the matrix mode come back) and the errors:
 * planes beyond the last are GL_INVALID_ENUM (GL_MAX_CLIP_PLANES is 8 on Mesa, 6 on tessera,
 * so each run checks its own limit), and everything is GL_INVALID_OPERATION between
 * glBegin/glEnd (checked when the implementation has glBegin).
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"

#define W 8
#define H 8

static const GLdouble plane[4] = {0.3, -1.7, 2.9, 0.45};

/* Specifies `plane` as clip plane 1 under the current modelview matrix and prints it. */
static void print_plane(const char *key)
{
    GLdouble eq[4] = {-1, -1, -1, -1};
    glClipPlane(GL_CLIP_PLANE1, plane);
    glGetClipPlane(GL_CLIP_PLANE1, eq);
    capi_value(key, "%a %a %a %a", eq[0], eq[1], eq[2], eq[3]);
    capi_expect_error(GL_NO_ERROR, key);
}

static void planes(void)
{
    static const GLfloat general[16] = {0.5f, 0.25f, -1.0f, 0.125f, 2.0f, -0.75f, 0.3f, 0.0f,
                                        0.1f, 0.2f,  0.3f,  0.4f,   -1.0f, 2.0f, -3.0f, 1.5f};
    static const GLfloat affine[16] = {0.5f, 0.25f, -1.0f, 0.0f, 2.0f, -0.75f, 0.3f, 0.0f,
                                       0.1f, 0.2f,  0.3f,  0.0f, -1.0f, 2.0f, -3.0f, 1.0f};
    static const GLfloat rotation[16] = {0.0f, 1.0f, 0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f,
                                         0.0f, 0.0f, 1.0f, 0.0f, 3.0f,  4.0f, 5.0f, 1.0f};
    print_plane("identity");
    glTranslatef(1.25f, -3.5f, 7.0f);
    print_plane("translation");
    glScalef(3.0f, 3.0f, 3.0f);
    print_plane("uniform_scale");
    glScalef(0.7f, 1.3f, 1.0f);
    print_plane("general_scale_2d");
    glScalef(1.0f, 1.0f, -2.5f);
    print_plane("general_scale_3d");
    glLoadIdentity();
    glRotatef(37.0f, 0.0f, 0.0f, 1.0f);
    print_plane("rotation_2d");
    glTranslatef(0.5f, 0.25f, 0.0f);
    print_plane("rotation_2d_translated");
    glRotatef(-61.0f, 1.0f, 2.0f, 3.0f);
    print_plane("rotation_3d");
    glScalef(2.0f, 2.0f, 2.0f);
    print_plane("rotation_uniform_scale");
    glScalef(1.0f, 0.5f, 3.0f);
    print_plane("rotation_general_scale");
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    print_plane("perspective");
    glLoadMatrixf(general);
    print_plane("loaded_general");
    /* A loaded affine matrix: analysed from scratch, inverted by the adjugate, which keeps
     * the bottom row of the previous (general) inverse. */
    glLoadMatrixf(affine);
    print_plane("loaded_affine_stale_row");
    glLoadIdentity();
    glLoadMatrixf(affine);
    print_plane("loaded_affine");
    glLoadMatrixf(rotation);
    print_plane("loaded_rotation");
    glLoadIdentity();
    glScalef(0.0f, 1.0f, 1.0f);
    print_plane("singular");
    glLoadIdentity();
    glScalef(1e-20f, 1e-20f, 1e-20f);
    print_plane("tiny_scale");
    glLoadIdentity();
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    glPushMatrix(); /* analysed here: the plane reuses that analysis */
    print_plane("pushed_rotation");
    glPopMatrix();
    glLoadIdentity();
    /* Doubles are converted to float before the transform. */
    static const GLdouble precise[4] = {0.1, 1.0 / 3.0, 1e-50, 123456789.123};
    GLdouble eq[4];
    glClipPlane(GL_CLIP_PLANE0 + 5, precise);
    glGetClipPlane(GL_CLIP_PLANE0 + 5, eq);
    capi_value("precise", "%a %a %a %a", eq[0], eq[1], eq[2], eq[3]);
    /* Other planes are untouched; the projection matrix plays no part. */
    glGetClipPlane(GL_CLIP_PLANE0, eq);
    capi_value("plane0", "%a %a %a %a", eq[0], eq[1], eq[2], eq[3]);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    print_plane("under_projection");
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    /* An enabled plane (Mesa also transforms it to clip space, analysing the projection). */
    glEnable(GL_CLIP_PLANE1);
    glTranslatef(1.0f, 2.0f, 3.0f);
    print_plane("enabled");
    glDisable(GL_CLIP_PLANE1);
    glLoadIdentity();
}

static void transform_bit(void)
{
    static const GLdouble other[4] = {1.0, 2.0, 3.0, 4.0};
    GLdouble eq[4];
    GLint mode;
    glMatrixMode(GL_TEXTURE);
    glEnable(GL_CLIP_PLANE3);
    glPushAttrib(GL_TRANSFORM_BIT);
    glMatrixMode(GL_PROJECTION);
    glClipPlane(GL_CLIP_PLANE1, other);
    glDisable(GL_CLIP_PLANE3);
    glEnable(GL_CLIP_PLANE4);
    glPopAttrib();
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    glGetClipPlane(GL_CLIP_PLANE1, eq);
    capi_value("transform_bit", "mode=0x%x plane=%a %a %a %a enabled=%d%d", mode, eq[0], eq[1], eq[2], eq[3],
               glIsEnabled(GL_CLIP_PLANE3), glIsEnabled(GL_CLIP_PLANE4));
    /* Planes are restored in eye space, not transformed again. */
    glMatrixMode(GL_MODELVIEW);
    glPushAttrib(GL_TRANSFORM_BIT);
    glScalef(2.0f, 2.0f, 2.0f);
    glClipPlane(GL_CLIP_PLANE1, other);
    glPopAttrib();
    glGetClipPlane(GL_CLIP_PLANE1, eq);
    capi_value("transform_bit_eye_space", "%a %a %a %a", eq[0], eq[1], eq[2], eq[3]);
    /* Other groups leave planes and mode alone. */
    glPushAttrib(GL_ALL_ATTRIB_BITS & ~GL_TRANSFORM_BIT);
    glMatrixMode(GL_PROJECTION);
    glClipPlane(GL_CLIP_PLANE1, plane);
    glPopAttrib();
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    glGetClipPlane(GL_CLIP_PLANE1, eq);
    capi_value("other_bits", "mode=0x%x plane=%a %a %a %a", mode, eq[0], eq[1], eq[2], eq[3]);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    capi_expect_error(GL_NO_ERROR, "transform_bit_errors");
}

static void errors(void)
{
    GLint max = 0;
    GLdouble eq[4] = {9, 9, 9, 9};
    glGetIntegerv(GL_MAX_CLIP_PLANES, &max);
    capi_check(max == (capi_is_tessera() ? 6 : 8), "GL_MAX_CLIP_PLANES %d", max);
    glClipPlane(GL_CLIP_PLANE0 + max, plane);
    capi_expect_error(GL_INVALID_ENUM, "clip_plane_beyond_max");
    glClipPlane(GL_CLIP_PLANE0 - 1, plane);
    capi_expect_error(GL_INVALID_ENUM, "clip_plane_below");
    glClipPlane(GL_TEXTURE_2D, plane);
    capi_expect_error(GL_INVALID_ENUM, "clip_plane_other_enum");
    glGetClipPlane(GL_CLIP_PLANE0 + max, eq);
    capi_expect_error(GL_INVALID_ENUM, "get_clip_plane_beyond_max");
    capi_check(eq[0] == 9 && eq[3] == 9, "an invalid glGetClipPlane writes nothing");
    glGetClipPlane(0, eq);
    capi_expect_error(GL_INVALID_ENUM, "get_clip_plane_zero");
    glClipPlane(GL_CLIP_PLANE0 + max - 1, plane);
    capi_expect_error(GL_NO_ERROR, "clip_plane_last");
    if (capi_is_tessera()) {
        /* Mesa 22 crashes on a NULL plane; tessera ignores it. */
        glClipPlane(GL_CLIP_PLANE0, NULL);
        glGetClipPlane(GL_CLIP_PLANE0, NULL);
        capi_check(glGetError() == GL_NO_ERROR, "NULL planes are ignored");
    }

    void (*begin)(GLenum) = (void (*)(GLenum))OSMesaGetProcAddress("glBegin");
    void (*end)(void) = (void (*)(void))OSMesaGetProcAddress("glEnd");
    if (begin && end) {
        begin(GL_POINTS);
        glClipPlane(GL_CLIP_PLANE0, plane);
        end();
        capi_check(glGetError() == GL_INVALID_OPERATION, "glClipPlane between glBegin/glEnd");
        begin(GL_POINTS);
        glGetClipPlane(GL_CLIP_PLANE0, eq);
        end();
        capi_check(glGetError() == GL_INVALID_OPERATION, "glGetClipPlane between glBegin/glEnd");
    }
}

int main(void)
{
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    GLdouble eq[4] = {9, 9, 9, 9};
    glGetClipPlane(GL_CLIP_PLANE2, eq);
    capi_value("initial", "%a %a %a %a", eq[0], eq[1], eq[2], eq[3]);
    planes();
    transform_bit();
    errors();
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
