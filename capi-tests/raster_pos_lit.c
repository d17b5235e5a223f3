/* The raster position's color and texture coordinates go through the per-vertex stage
 * (GL 2.1 section 2.13): lit colors under GL_LIGHTING, texture coordinates through texgen
 * and the texture matrix (with and without a texture enabled, on units 0 and 1); feedback
 * vertices are lit too (and, as in Mesa 22, get texgen only on units with a texture
 * enabled). Values compared with Mesa. */
#include "common.h"

#define W 16
#define H 16

static void raster_values(const char *stage)
{
    capi_value_query(stage, "color", GL_CURRENT_RASTER_COLOR, 4);
    capi_value_query(stage, "secondary", GL_CURRENT_RASTER_SECONDARY_COLOR, 4);
    capi_value_query(stage, "position", GL_CURRENT_RASTER_POSITION, 4);
    capi_value_query(stage, "distance", GL_CURRENT_RASTER_DISTANCE, 1);
    glActiveTexture(GL_TEXTURE0);
    capi_value_query(stage, "tex0", GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    glActiveTexture(GL_TEXTURE1);
    capi_value_query(stage, "tex1", GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    glActiveTexture(GL_TEXTURE0);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.1f, -0.2f, -3);
    glRotatef(30, 0.3f, 1, 0.2f);

    glColor4f(0.3f, 0.6f, 0.9f, 0.5f);
    glSecondaryColor3f(0.2f, 0.1f, 0.05f);
    glNormal3f(0.2f, 0.5f, 1);
    glMultiTexCoord4f(GL_TEXTURE0, 0.25f, 0.5f, 0.75f, 1);
    glMultiTexCoord4f(GL_TEXTURE1, -1, 2, 0.5f, 2);
    glRasterPos3f(0.2f, 0.3f, 0.1f);
    raster_values("plain");

    /* Lighting: one positional light and a material. (Mesa 22 lights the raster position
     * with code of its own, which differs from its draws' per-vertex lighting in some
     * cases, e.g. under GL_NORMALIZE or GL_SEPARATE_SPECULAR_COLOR with an unnormalized
     * normal; tessera uses its draws' code, bit-exact with Mesa's draws. Compared here where
     * the two agree.) */
    GLfloat light_pos[4] = {1, 2, 3, 1}, diffuse[4] = {0.9f, 0.8f, 0.7f, 1}, spec[4] = {1, 1, 1, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
    GLfloat mat_spec[4] = {0.5f, 0.5f, 0.5f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, mat_spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glRasterPos3f(0.2f, 0.3f, 0.1f);
    raster_values("lit");
    glDisable(GL_LIGHTING);

    /* Texgen and texture matrices, without a texture enabled, then with one. */
    GLfloat plane_s[4] = {1, 0.5f, 0, 0.25f}, plane_t[4] = {0, 1, 2, 0};
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, plane_s);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_T, GL_EYE_PLANE, plane_t);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glMatrixMode(GL_TEXTURE);
    glScalef(2, 3, 1);
    glTranslatef(0.5f, 0, 0.25f);
    glActiveTexture(GL_TEXTURE1);
    glRotatef(45, 0, 0, 1);
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_MODELVIEW);
    glRasterPos3f(0.2f, 0.3f, 0.1f);
    raster_values("texgen");
    glEnable(GL_TEXTURE_2D);
    glRasterPos3f(0.2f, 0.3f, 0.1f);
    raster_values("texgen_enabled");
    glDisable(GL_TEXTURE_2D);

    /* Feedback of a lit, texgen'd point. */
    glEnable(GL_LIGHTING);
    GLfloat buffer[64];
    glFeedbackBuffer(64, GL_3D_COLOR_TEXTURE, buffer);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex3f(0.2f, 0.3f, 0.1f);
    glEnd();
    int n = glRenderMode(GL_RENDER);
    capi_value("feedback.count", "%d", n);
    for (int i = 0; i < n && i < 64; i++)
        capi_value("feedback.value", "%d %a", i, buffer[i]);
    capi_expect_error(GL_NO_ERROR, "no error");
    return capi_finish();
}
