/* translucent_house: the Pyglet article's translucent house (an open box of four walls and a
 * four-triangle roof, every face alpha 0.5, blended with SRC_ALPHA, ONE_MINUS_SRC_ALPHA over
 * a dark blue background), seen from (4, 6, 18) towards (0, 2, 0) with a 70 degree field of
 * view, as in the article's screenshots:
 *   top left:     the house, depth test off (every face blends in drawing order)
 *   top right:    the house, depth test on (faces behind a nearer face drawn earlier vanish)
 *   bottom left:  the article's second example, depth test off: the house, then two
 *                 translucent planes (pink on the left, light blue on the right, alpha 0.7)
 *   bottom right: the same with the depth test on; the planes are drawn with depth writes
 *                 off (glDepthMask(GL_FALSE)), so they never hide what is drawn after them. */
#include "example.h"

static void walls(void)
{
    glBegin(GL_QUADS);
    glColor4f(0.0f, 0.0f, 1.0f, 0.5f); /* blue floor */
    glVertex3f(-5, -5, -5), glVertex3f(-5, -5, 5), glVertex3f(5, -5, 5), glVertex3f(5, -5, -5);
    glColor4f(0.0f, 1.0f, 0.0f, 0.5f); /* green ceiling */
    glVertex3f(-5, 5, -5), glVertex3f(-5, 5, 5), glVertex3f(5, 5, 5), glVertex3f(5, 5, -5);
    glColor4f(1.0f, 0.0f, 0.0f, 0.5f); /* red left wall */
    glVertex3f(-5, -5, -5), glVertex3f(-5, -5, 5), glVertex3f(-5, 5, 5), glVertex3f(-5, 5, -5);
    glColor4f(1.0f, 1.0f, 0.0f, 0.5f); /* yellow right wall */
    glVertex3f(5, -5, -5), glVertex3f(5, -5, 5), glVertex3f(5, 5, 5), glVertex3f(5, 5, -5);
    glEnd();
}

static void roof(void)
{
    glBegin(GL_TRIANGLES);
    glColor4f(0.0f, 1.0f, 1.0f, 0.5f);
    glVertex3f(-5, 5, -5), glVertex3f(5, 5, -5), glVertex3f(0, 11, 0);
    glColor4f(1.0f, 0.0f, 1.0f, 0.5f);
    glVertex3f(5, 5, -5), glVertex3f(5, 5, 5), glVertex3f(0, 11, 0);
    glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
    glVertex3f(5, 5, 5), glVertex3f(-5, 5, 5), glVertex3f(0, 11, 0);
    glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
    glVertex3f(-5, 5, 5), glVertex3f(-5, 5, -5), glVertex3f(0, 11, 0);
    glEnd();
}

/* The two translucent planes in front of the house, drawn read-only for the depth buffer. */
static void planes(void)
{
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -50.0f);
    glDepthMask(GL_FALSE);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.5f, 0.5f, 0.7f);
    glVertex3f(-14, -8, 35), glVertex3f(0, -8, 35), glVertex3f(0, 8, 35), glVertex3f(-14, 8, 35);
    glColor4f(0.5f, 0.5f, 1.0f, 0.7f);
    glVertex3f(0, -8, 25), glVertex3f(14, -8, 25), glVertex3f(14, 8, 25), glVertex3f(0, 8, 25);
    glEnd();
    glDepthMask(GL_TRUE);
}

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "translucent_house", argc, argv, 600, 600, 24, 0);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthFunc(GL_LESS);
    for (int i = 0; i < 4; i++) {
        int depth_test = i % 2, with_planes = i / 2;
        panel(&ex, i, 2, 2, 0.0f, 0.0f, 0.3f);
        if (depth_test)
            glEnable(GL_DEPTH_TEST);
        else
            glDisable(GL_DEPTH_TEST);
        perspective(70.0, 1.0, 0.1, 90.0);
        look_at(4, 6, 18, 0, 2, 0, 0, 1, 0);
        walls();
        roof();
        if (with_planes)
            planes();
        panel_label(&ex, i, 2, 2, depth_test ? "DEPTH TEST ON" : "DEPTH TEST OFF");
    }
    example_save(&ex, "translucent_house");
    return example_finish(&ex);
}
