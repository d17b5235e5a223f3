/* Lines and points compared with Mesa: widths 1-5, stipple patterns and factors, strips
 * and loops (the stipple continues along a strip), points of sizes 1-7 at fractional
 * positions, polygon modes GL_LINE and GL_POINT for front and back faces, edge flags, and
 * polygon offset for lines. */
#include "common.h"

#define W 128
#define H 128

static void lines(void)
{
    for (int i = 0; i < 5; i++) {
        glLineWidth(1.0f + i);
        glBegin(GL_LINES);
        glColor3f(1, 0.2f * i, 0);
        glVertex2f(4.3f + i * 24, 4.6f);
        glVertex2f(20.7f + i * 24, 30.2f);
        glColor3f(0, 1, 0.2f * i);
        glVertex2f(3.5f + i * 24, 40.5f);
        glColor3f(0, 0, 1);
        glVertex2f(23.5f + i * 24, 44.5f);
        glEnd();
    }
    glLineWidth(1);
    glEnable(GL_LINE_STIPPLE);
    static const GLushort patterns[4] = {0x0f0f, 0xaaaa, 0x00ff, 0x1c47};
    for (int i = 0; i < 4; i++) {
        glLineStipple(i + 1, patterns[i]);
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 1, 0);
        glVertex2f(2.5f, 52.5f + i * 6);
        glVertex2f(60.5f, 54.5f + i * 6);
        glVertex2f(125.5f, 50.5f + i * 7);
        glEnd();
    }
    glDisable(GL_LINE_STIPPLE);
    glBegin(GL_LINE_LOOP);
    glColor3f(0, 1, 1);
    glVertex2f(70, 80);
    glVertex2f(120, 84);
    glColor3f(1, 0, 1);
    glVertex2f(110, 124);
    glVertex2f(75, 110);
    glEnd();
}

static void points(void)
{
    for (int i = 0; i < 7; i++) {
        glPointSize(1.0f + i);
        glBegin(GL_POINTS);
        glColor3f(1, 1, 1);
        glVertex2f(6.0f + i * 9, 80.0f);
        glColor3f(1, 0.5f, 0);
        glVertex2f(6.5f + i * 9, 92.5f);
        glColor3f(0.3f, 0.6f, 1);
        glVertex2f(6.3f + i * 9, 104.8f);
        glEnd();
    }
    glPointSize(1);
}

static void polygon_modes(void)
{
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glPointSize(2);
    glBegin(GL_QUADS); /* front (CCW) */
    glColor3f(1, 0, 0);
    glVertex2f(10.5f, 10.5f);
    glVertex2f(50.5f, 12.5f);
    glVertex2f(48.5f, 50.5f);
    glVertex2f(12.5f, 46.5f);
    glEnd();
    glBegin(GL_TRIANGLES); /* back (CW) */
    glColor3f(0, 1, 0);
    glVertex2f(70, 10);
    glVertex2f(90, 50);
    glVertex2f(110, 12);
    glEnd();
    glBegin(GL_POLYGON); /* front, with one edge flagged off */
    glColor3f(1, 1, 0);
    glVertex2f(20, 70);
    glEdgeFlag(GL_FALSE);
    glVertex2f(60, 72);
    glEdgeFlag(GL_TRUE);
    glVertex2f(64, 110);
    glVertex2f(30, 120);
    glVertex2f(14, 96);
    glEnd();
    glPointSize(1);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    /* Polygon offset for lines drawn over a filled triangle. */
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.2f, 0.6f);
    glVertex3f(72, 70, 0.3f);
    glVertex3f(124, 76, -0.5f);
    glVertex3f(96, 124, 0.1f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(-1, -2);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 1);
    glVertex3f(72, 70, 0.3f);
    glVertex3f(124, 76, -0.5f);
    glVertex3f(96, 124, 0.1f);
    glEnd();
    glDisable(GL_POLYGON_OFFSET_LINE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_DEPTH_TEST);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT);
    lines();
    points();
    capi_save_framebuffer("lines_points", W, H);
    glShadeModel(GL_FLAT);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    polygon_modes();
    capi_save_framebuffer("polygon_modes", W, H);
    /* Polygon stipple on a filled quad. */
    GLubyte stipple[128];
    for (int i = 0; i < 128; i++)
        stipple[i] = (GLubyte)(i * 37 + (i >> 3));
    glPolygonStipple(stipple);
    glEnable(GL_POLYGON_STIPPLE);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glColor3f(1, 0.5f, 0.2f);
    glVertex2f(5, 5);
    glVertex2f(120, 9);
    glVertex2f(118, 122);
    glVertex2f(9, 117);
    glEnd();
    glDisable(GL_POLYGON_STIPPLE);
    capi_save_framebuffer("polygon_stipple", W, H);
    capi_check(glGetError() == GL_NO_ERROR, "no GL error");
    return capi_finish();
}
