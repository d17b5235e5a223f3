/* stencil_diamond: the lecture's "drawing inside and outside a diamond". The stencil is
 * cleared to 0 and a diamond sets it to 1 (GL_ALWAYS, 0x1, 0x1 with GL_REPLACE; color writes
 * off, so the diamond itself is not seen). Then the scene is drawn twice:
 *   inside the stencil (GL_EQUAL, 0x1, 0x1): a "blue sphere" (a disc, bigger than the diamond, shaded from light blue
 *   in the middle to dark blue at the rim, no lighting needed);
 *   outside it (GL_NOTEQUAL, 0x1, 0x1): a "tori scene", rows of colored rings.
 * Left panel: the two scenes drawn without the stencil test, one over the other (the sphere
 * last); right panel: with the stencil, the diamond shows the sphere and the rings around it. */
#include "example.h"

static void ring(float cx, float cy, float inner, float outer, float r, float g, float b)
{
    glColor3f(r, g, b);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 32; i++) {
        float a = i * 6.2831853f / 32;
        glVertex2f(cx + inner * cosf(a), cy + inner * sinf(a));
        glVertex2f(cx + outer * cosf(a), cy + outer * sinf(a));
    }
    glEnd();
}

static void tori_scene(void)
{
    static const float colors[4][3] = {{1, 0.4f, 0.1f}, {0.2f, 0.8f, 0.2f}, {0.9f, 0.8f, 0.1f}, {0.8f, 0.2f, 0.7f}};
    for (int y = 0; y < 5; y++)
        for (int x = 0; x < 5; x++) {
            const float *c = colors[(x + y) % 4];
            ring(30 + x * 60, 30 + y * 60, 14, 26, c[0], c[1], c[2]);
        }
}

static void blue_sphere(void)
{
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(0.6f, 0.8f, 1.0f);
    glVertex2f(120, 180);
    glColor3f(0.0f, 0.05f, 0.4f);
    for (int i = 0; i <= 48; i++) {
        float a = i * 6.2831853f / 48;
        glVertex2f(150 + 140 * cosf(a), 150 + 140 * sinf(a));
    }
    glEnd();
}

static void diamond(void)
{
    glBegin(GL_QUADS);
    glVertex2f(150, 20);
    glVertex2f(280, 150);
    glVertex2f(150, 280);
    glVertex2f(20, 150);
    glEnd();
}

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "stencil_diamond", argc, argv, 600, 300, 0, 8);
    glShadeModel(GL_SMOOTH);
    for (int with_stencil = 0; with_stencil < 2; with_stencil++) {
        panel(&ex, with_stencil, 2, 1, 0.1f, 0.1f, 0.12f);
        ortho(300, 300);
        if (with_stencil) {
            glEnable(GL_STENCIL_TEST);
            glClearStencil(0x0);
            glClear(GL_STENCIL_BUFFER_BIT);
            glStencilFunc(GL_ALWAYS, 0x1, 0x1);
            glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            diamond();
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        }
        glStencilFunc(GL_EQUAL, 0x1, 0x1); /* inside the diamond */
        blue_sphere();
        glStencilFunc(GL_NOTEQUAL, 0x1, 0x1); /* outside it */
        tori_scene();
        if (!with_stencil)
            blue_sphere(); /* without the stencil the sphere just lies on top */
        glDisable(GL_STENCIL_TEST);
        panel_label(&ex, with_stencil, 2, 1, with_stencil ? "WITH STENCIL" : "WITHOUT STENCIL");
    }
    example_save(&ex, "stencil_diamond");
    return example_finish(&ex);
}
