/* Smoothing (GL_LINE_SMOOTH, GL_POINT_SMOOTH, GL_POLYGON_SMOOTH): coverage multiplied into
 * the fragment alpha.
 *  - lines: widths 1-6 at many angles, smooth-shaded and flat, blended over a background,
 *    stippled, as strips and loops, depth-tested, textured (GL_REPLACE keeps the coverage:
 *    it is applied after texturing), and drawn into the alpha channel alone (no blending):
 *    compared with Mesa (its draw module's smooth lines).
 *  - points and polygons: Mesa 22 (llvmpipe and softpipe) ignores GL_POLYGON_SMOOTH and draws
 *    smooth points as aliased discs of full alpha, while GL 2.1 (sections 3.3.1, 3.4.2,
 *    3.6.6) asks for coverage in alpha: tessera follows the spec. Their pictures are compared
 *    only where both agree (see the manifest), and the coverage is checked here.
 *  - the smooth width and size ranges. */
#include "common.h"
#include <math.h>

#define W 128
#define H 128

static GLubyte pixels[W * H * 4];

static void read_all(void)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
}

static int alpha_at(int x, int y)
{
    return pixels[(y * W + x) * 4 + 3];
}

static void lines(void)
{
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    /* A star of lines of growing width around (32, 32). */
    for (int i = 0; i < 12; i++) {
        float a = (float)i * 0.5236f + 0.1f;
        glLineWidth(1.0f + (float)(i % 6));
        glBegin(GL_LINES);
        glColor4f(1, 0.3f + 0.05f * i, 0.1f, 1);
        glVertex2f(32.3f + 4 * cosf(a), 32.6f + 4 * sinf(a));
        glColor4f(0.1f, 0.5f, 1, 0.8f);
        glVertex2f(32.3f + 28 * cosf(a), 32.6f + 28 * sinf(a));
        glEnd();
    }
    /* Axis-aligned lines at fractional offsets, flat shaded. */
    glShadeModel(GL_FLAT);
    glLineWidth(1);
    for (int i = 0; i < 6; i++) {
        glBegin(GL_LINES);
        glColor4f(1, 1, 1, 1);
        glVertex2f(70.0f + 0.25f * i, 4.0f + 5.2f * i);
        glVertex2f(120.3f, 4.0f + 5.2f * i);
        glVertex2f(70.0f + 9 * i + 0.3f * i, 40);
        glVertex2f(70.0f + 9 * i + 0.3f * i, 62.7f);
        glEnd();
    }
    glShadeModel(GL_SMOOTH);
    /* A stippled strip and a loop of width 2.5. */
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x0f3f);
    glLineWidth(2.5f);
    glBegin(GL_LINE_STRIP);
    glColor3f(1, 1, 0);
    glVertex2f(4.5f, 70.2f);
    glColor3f(0, 1, 1);
    glVertex2f(60.2f, 78.9f);
    glVertex2f(20.1f, 96.3f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    glBegin(GL_LINE_LOOP);
    glColor3f(1, 0, 1);
    glVertex2f(8, 104);
    glVertex2f(56, 108.5f);
    glVertex2f(40, 124);
    glEnd();
    /* Depth-tested lines crossing a quad at two depths. */
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    glColor3f(0.2f, 0.2f, 0.5f);
    glVertex3f(72, 70, 0);
    glVertex3f(124, 70, 0);
    glVertex3f(124, 124, 0);
    glVertex3f(72, 124, 0);
    glEnd();
    glLineWidth(3.5f);
    glBegin(GL_LINES);
    glColor3f(0, 1, 0);
    glVertex3f(68.5f, 74.2f, 0.5f); /* behind the quad */
    glVertex3f(126, 110.7f, 0.5f);
    glColor3f(1, 0.4f, 0);
    glVertex3f(68.5f, 120.2f, -0.5f); /* in front */
    glVertex3f(126, 80.9f, -0.5f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    glLineWidth(1);
    glDisable(GL_BLEND);
    glDisable(GL_LINE_SMOOTH);
}

/* Coverage into the alpha channel without blending, and through GL_REPLACE texturing. */
static void alpha_only(void)
{
    glEnable(GL_LINE_SMOOTH);
    for (int i = 0; i < 8; i++) {
        glLineWidth(1.0f + 0.75f * i);
        glBegin(GL_LINES);
        glColor4f(1, 1, 1, 1);
        glVertex2f(4.0f + 15 * i, 6.3f);
        glVertex2f(14.0f + 15 * i + 0.4f * i, 120.0f - 3.1f * i);
        glEnd();
    }
    static const GLubyte texel[4] = {200, 100, 50, 255};
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glLineWidth(2);
    glBegin(GL_LINES);
    glTexCoord2f(0.5f, 0.5f);
    glVertex2f(2.2f, 124.4f);
    glVertex2f(125.1f, 112.6f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &tex);
    glLineWidth(1);
    glDisable(GL_LINE_SMOOTH);
}

static void points(void)
{
    glEnable(GL_POINT_SMOOTH);
    for (int i = 0; i < 8; i++) {
        glPointSize(1.0f + 1.5f * i);
        glBegin(GL_POINTS);
        glColor4f(1, 0.5f, 0.2f, 1);
        glVertex2f(8.0f + 15 * i + 0.3f * i, 20.0f + 0.45f * i);
        glColor4f(0.2f, 1, 0.5f, 1);
        glVertex2f(8.5f + 15 * i, 60.5f);
        glEnd();
    }
    glPointSize(1);
    glDisable(GL_POINT_SMOOTH);
}

static void polygons(void)
{
    glEnable(GL_POLYGON_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 1);
    glVertex2f(4.3f, 4.7f);
    glColor4f(0, 1, 0, 1);
    glVertex2f(60.9f, 12.2f);
    glColor4f(0, 0, 1, 1);
    glVertex2f(20.4f, 58.6f);
    glEnd();
    glBegin(GL_QUADS);
    glColor4f(1, 1, 0, 1);
    glVertex2f(70.25f, 70.25f);
    glVertex2f(120.25f, 70.25f);
    glVertex2f(120.25f, 120.75f);
    glVertex2f(70.25f, 120.75f);
    glEnd();
    glDisable(GL_POLYGON_SMOOTH);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    capi_value_query("range", "smooth_line_width", GL_SMOOTH_LINE_WIDTH_RANGE, 2);
    capi_value_query("range", "smooth_point_size", GL_SMOOTH_POINT_SIZE_RANGE, 2);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);

    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    lines();
    capi_save_framebuffer("lines", W, H);

    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    alpha_only();
    capi_save_framebuffer("alpha_only", W, H);
    read_all();
    /* The width-1 line's end at y = 6.3: its first pixels along the line carry partial
     * coverage, its middle full coverage at some pixel of each row. */
    int partial = 0;
    for (int x = 0; x < W; x++)
        for (int y = 20; y < 100; y++)
            partial += alpha_at(x, y) > 0 && alpha_at(x, y) < 255;
    capi_check(partial > 100, "smooth lines have partly covered pixels (%d)", partial);

    glClear(GL_COLOR_BUFFER_BIT);
    points();
    capi_save_framebuffer("points", W, H);
    read_all();
    if (capi_is_tessera()) {
        /* The size-11.5 point at (115.1, 23.15): full in the middle; pixel (120, 23), whose
         * centre is 5.41 px away, 6.25 - 5.41 = 0.84 covered; (121, 23) not at all. */
        capi_check(alpha_at(115, 23) == 255, "point centre alpha %d", alpha_at(115, 23));
        capi_check(alpha_at(120, 23) == 214, "point rim alpha %d", alpha_at(120, 23));
        capi_check(alpha_at(121, 23) == 0, "point outside alpha %d", alpha_at(121, 23));
    }

    glClear(GL_COLOR_BUFFER_BIT);
    polygons();
    capi_save_framebuffer("polygons", W, H);
    read_all();
    if (capi_is_tessera()) {
        /* The quad's left edge x = 70.25 covers 3/4 of column 70, its top edge y = 120.75
         * 3/4 of row 120, its bottom edge y = 70.25 3/4 of row 70 (away from the diagonal
         * that splits it into two triangles). */
        capi_check(alpha_at(70, 90) == 191, "quad left edge alpha %d (3/4)", alpha_at(70, 90));
        capi_check(alpha_at(90, 120) == 191, "quad top edge alpha %d (3/4)", alpha_at(90, 120));
        capi_check(alpha_at(100, 70) == 191, "quad bottom edge alpha %d (3/4)", alpha_at(100, 70));
        capi_check(alpha_at(100, 85) == 255, "quad interior alpha %d", alpha_at(100, 85));
    }
    capi_check(glGetError() == GL_NO_ERROR, "no GL error");
    return capi_finish();
}
