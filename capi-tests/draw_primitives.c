/* Every primitive mode, smooth and flat shaded, with both provoking-vertex conventions'
 * default (last vertex), drawn with glBegin/glEnd into a 128x96 window.
 *
 * Coverage must match Mesa exactly (same fill rule, 8 subpixel bits); smooth colors may
 * differ by the rounding of interpolation (manifest). */
#include "common.h"
#include <math.h>

#define W 128
#define H 96

static const GLenum modes[10] = {GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES,
                                 GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};

/* Draws mode m in cell (cx, cy) of a 4 x 3 grid of 32 x 32 cells. */
static void draw_mode(int m, float cx, float cy)
{
    static const float colors[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    glBegin(modes[m]);
    for (int i = 0; i < 6; i++) {
        float a = (float)i / 6.0f * 6.2831853f + 0.3f * m;
        float r = (i % 2) ? 13.0f : 9.5f;
        /* Strips and quad strips need a zig-zag order to be non-degenerate. */
        if (modes[m] == GL_TRIANGLE_STRIP || modes[m] == GL_QUAD_STRIP) {
            float x = cx + 3.3f + (i / 2) * 12.1f - 12.0f, y = cy + ((i % 2) ? 12.7f : -11.3f);
            glColor3fv(colors[i]);
            glVertex2f(x, y);
            continue;
        }
        glColor3fv(colors[i]);
        glVertex2f(cx + 16.0f + r * cosf(a) - 16.0f + 16.0f, cy + r * sinf(a));
    }
    glEnd();
}

static void scene(const char *name, GLenum shade)
{
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(shade);
    for (int m = 0; m < 10; m++)
        draw_mode(m, (m % 4) * 32.0f + 0.37f, (m / 4) * 32.0f + 16.0f + 0.21f);
    capi_check(glGetError() == GL_NO_ERROR, "%s: no GL error", name);
    capi_save_framebuffer(name, W, H);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    scene("smooth", GL_SMOOTH);
    scene("flat", GL_FLAT);
    /* Integer and half-integer vertex positions exercise the fill rule on pixel centres. */
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 8; i++) {
        float x = 4.0f + 15.0f * i, off = (i % 2) ? 0.5f : 0.0f;
        glColor3f(1, (float)i / 8, 0);
        glVertex2f(x + off, 4 + off);
        glVertex2f(x + 12 + off, 4 + off);
        glVertex2f(x + 6 + off, 20 + off);
        glColor3f(0, (float)i / 8, 1);
        glVertex2f(x + off, 30 + off);
        glVertex2f(x + 12 + off, 30 + off);
        glVertex2f(x + 12 + off, 42 + off);
        glVertex2f(x + off, 30 + off);
        glVertex2f(x + 12 + off, 42 + off);
        glVertex2f(x + off, 42 + off);
    }
    glEnd();
    capi_save_framebuffer("fill_rule", W, H);
    return capi_finish();
}
