/* Point parameters (GL 1.4): GL_POINT_DISTANCE_ATTENUATION scales each point's size by
 * 1/sqrt(a + b d + c d^2) of its eye distance, clamped to GL_POINT_SIZE_MIN/MAX; points of
 * GL_POINT polygon mode are attenuated too; (1, 0, 0) leaves glPointSize alone. Pictures
 * compared with Mesa. */
#include "common.h"

#define W 96
#define H 48

static void row_of_points(void)
{
    glBegin(GL_POINTS);
    for (int i = 0; i < 6; i++) {
        float z = -1.5f - 3.0f * i;
        glColor3f(1, 0.2f * i, 0);
        /* x spread evenly on screen: x_eye = x_ndc * -z */
        glVertex3f((-0.8f + 0.32f * i) * -z, 0.4f * -z, z);
    }
    glEnd();
}

static void triangle_in_point_mode(void)
{
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glColor3f(0, 1, 1);
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.6f * 2, -0.5f * 2, -2);
    glVertex3f(-0.1f * 12, -0.6f * 12, -12);
    glVertex3f(0.6f * 5, -0.3f * 5, -5);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 100);
    glMatrixMode(GL_MODELVIEW);
    glPointSize(12);
    glClear(GL_COLOR_BUFFER_BIT);
    row_of_points();
    triangle_in_point_mode();
    capi_save_framebuffer("unattenuated", W, H);

    const GLfloat attenuation[3] = {0.25f, 0.2f, 0.05f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
    glPointParameterf(GL_POINT_SIZE_MIN, 2);
    glPointParameterf(GL_POINT_SIZE_MAX, 20);
    capi_value_query("attenuated", "attenuation", GL_POINT_DISTANCE_ATTENUATION, 3);
    glClear(GL_COLOR_BUFFER_BIT);
    row_of_points();
    triangle_in_point_mode();
    capi_save_framebuffer("attenuated", W, H);

    /* Quadratic only, and a large point size clamped by GL_POINT_SIZE_MAX near the eye */
    const GLfloat quadratic[3] = {0, 0, 0.1f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quadratic);
    glPointSize(30);
    glClear(GL_COLOR_BUFFER_BIT);
    row_of_points();
    capi_save_framebuffer("quadratic", W, H);

    /* Back to (1, 0, 0): glPointSize clamped to the min/max only */
    const GLfloat none[3] = {1, 0, 0};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
    glPointSize(6);
    glClear(GL_COLOR_BUFFER_BIT);
    row_of_points();
    capi_save_framebuffer("reset", W, H);
    capi_expect_error(GL_NO_ERROR, "point parameters");
    return capi_finish();
}
