/* A viewport smaller than the window bounds filled triangles (they are clipped to the view
 * volume), while wide points and lines may reach past it; and flat shading under both
 * provoking-vertex conventions for every polygon primitive. */
#include "common.h"

#define W 64
#define H 64

static void shapes(float x, float y)
{
    static const float c[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    static const GLenum modes[5] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP};
    for (int m = 0; m < 5; m++) {
        glBegin(modes[m]);
        for (int i = 0; i < 6; i++) {
            glColor3fv(c[(i + m) % 6]);
            float vx = x + m * 12 + (i % 2) * 9 + (i / 2) * 1.5f, vy = y + (i / 2) * 6 + (i % 2) * 2;
            if (modes[m] == GL_QUADS)
                vx = x + m * 12 + ((i == 1 || i == 2) ? 9 : 0) + (i >= 4 ? 2 : 0), vy = y + (i >= 2 && i < 4 ? 9 : 0) + (i >= 4 ? 14 : 0);
            glVertex2f(vx, vy);
        }
        glEnd();
    }
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glClear(GL_COLOR_BUFFER_BIT);
    glViewport(10, 12, 40, 30);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, 40, 0, 30, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.7f, 0.9f);
    glVertex2f(-30, -20);
    glVertex2f(90, 5);
    glVertex2f(10, 70);
    glEnd();
    glPointSize(9);
    glBegin(GL_POINTS);
    glColor3f(1, 1, 1);
    glVertex2f(1, 1);
    glVertex2f(39, 29);
    glEnd();
    glLineWidth(5);
    glBegin(GL_LINES);
    glColor3f(1, 0, 0);
    glVertex2f(0.5f, 15);
    glVertex2f(39.5f, 16);
    glEnd();
    capi_save_framebuffer("small_viewport", W, H);

    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glShadeModel(GL_FLAT);
    glClear(GL_COLOR_BUFFER_BIT);
    shapes(2, 2);
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    shapes(2, 34);
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    capi_save_framebuffer("provoking", W, H);
    capi_check(glGetError() == GL_NO_ERROR, "no GL error");
    return capi_finish();
}
