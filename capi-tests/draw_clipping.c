/* Geometry that must be clipped: triangles crossing the near plane and the eye plane
 * (w = 0, w < 0), a floor to the horizon, huge coordinates, sliver triangles and user clip
 * planes. Coverage and colors are compared with Mesa (manifest tolerances for
 * interpolation only). */
#include "common.h"

#define W 96
#define H 96

static void frustum(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void floor_and_walls(void)
{
    /* A floor from behind the eye (z = +5) to far away (z = -90). */
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0);
    glVertex3f(-4, -1, 5);
    glColor3f(0, 1, 0);
    glVertex3f(4, -1, 5);
    glColor3f(0, 0, 1);
    glVertex3f(4, -1, -90);
    glColor3f(1, 1, 1);
    glVertex3f(-4, -1, -90);
    glEnd();
    /* A triangle with one vertex exactly in the eye plane (w = 0) and one behind. */
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 0);
    glVertex3f(-0.5f, 0.2f, -3);
    glColor3f(0, 1, 1);
    glVertex3f(0.9f, 0.4f, 0);
    glColor3f(1, 0, 1);
    glVertex3f(0.1f, 0.9f, 2);
    glEnd();
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glEnable(GL_DEPTH_TEST);
    frustum();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    floor_and_walls();
    capi_save_framebuffer("near_and_eye_plane", W, H);

    /* Huge coordinates: a triangle 1e6 units across, seen through an orthographic window. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.6f, 1.0f);
    glVertex2f(-1e6f, -1e6f);
    glVertex2f(1e6f, -3e5f);
    glVertex2f(40.3f, 50.7f);
    glColor3f(1.0f, 0.5f, 0.0f);
    glVertex2f(1e7f, 1e7f);
    glVertex2f(-1e7f, 1e7f);
    glVertex2f(60.2f, 70.9f);
    glEnd();
    /* Slivers: long thin triangles less than a pixel wide. */
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 12; i++) {
        glColor3f(1, 1, (float)i / 12);
        glVertex2f(2.0f, 5.0f + i * 7.3f);
        glVertex2f(94.0f, 5.3f + i * 7.3f + i * 0.05f);
        glVertex2f(94.0f, 5.3f + i * 7.3f + 0.2f + i * 0.06f);
    }
    glEnd();
    capi_save_framebuffer("huge_and_slivers", W, H);

    /* User clip planes (eye space, set with an identity modelview). */
    glShadeModel(GL_SMOOTH);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const GLdouble plane0[4] = {1, 0.3, 0, -30};
    const GLdouble plane1[4] = {-0.2, -1, 0, 80};
    glClipPlane(GL_CLIP_PLANE0, plane0);
    glClipPlane(GL_CLIP_PLANE1, plane1);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE1);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex2f(48, 48);
    for (int i = 0; i <= 24; i++) {
        float a = i * 6.2831853f / 24;
        glColor3f(i % 2, (i / 2) % 2, 1);
        glVertex2f(48 + 44 * __builtin_cosf(a), 48 + 44 * __builtin_sinf(a));
    }
    glEnd();
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_CLIP_PLANE1);
    capi_save_framebuffer("user_clip_planes", W, H);
    capi_check(glGetError() == GL_NO_ERROR, "no GL error");
    return capi_finish();
}
