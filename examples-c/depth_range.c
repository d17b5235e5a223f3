/* depth_range: uses of glDepthRange from the lecture. Each panel draws a far blue wall
 * (z = -0.6), a near orange square (z = 0.6) and a green triangle at middle depth (z = 0).
 *   1. plain glDepthRange(0, 1) with GL_LESS: orange in front of green in front of blue;
 *   2. reversed range glDepthRange(1, 0) with glClearDepth(0) and GL_GREATER: the same
 *      picture (near and far swap twice);
 *   3. layers: the green triangle drawn with glDepthRange(0, 0.1) lies in front of
 *      everything else (drawn with glDepthRange(0.1, 1)), like a cockpit or a HUD;
 *   4. selective depth clear: after the wall and the square, a rectangle with color writes
 *      off, glDepthRange(1, 1) and GL_ALWAYS resets the depth to 1 in a window; the green
 *      triangle, drawn next, shows through the orange square there. */
#include "example.h"

static void wall(void)
{
    glColor3f(0.2f, 0.35f, 0.9f);
    rect_z(10, 10, 150, 150, -0.6f);
}

static void square(void)
{
    glColor3f(1.0f, 0.55f, 0.1f);
    rect_z(60, 30, 140, 110, 0.6f);
}

static void triangle(void)
{
    glColor3f(0.1f, 0.8f, 0.3f);
    glBegin(GL_TRIANGLES);
    glVertex3f(20, 20, 0), glVertex3f(120, 50, 0), glVertex3f(50, 140, 0);
    glEnd();
}

int main(int argc, char **argv)
{
    static const char *names[4] = {"0,1 LESS", "1,0 GREATER", "LAYERS", "SELECTIVE CLEAR"};
    Example ex;
    example_start(&ex, "depth_range", argc, argv, 640, 160, 24, 0);
    glEnable(GL_DEPTH_TEST);
    for (int use = 0; use < 4; use++) {
        panel(&ex, use, 4, 1, 0.15f, 0.15f, 0.15f);
        ortho(160, 160);
        glDepthFunc(GL_LESS);
        switch (use) {
        case 0:
            wall(), square(), triangle();
            break;
        case 1:
            glClearDepth(0.0);
            glClear(GL_DEPTH_BUFFER_BIT);
            glDepthRange(1, 0);
            glDepthFunc(GL_GREATER);
            wall(), square(), triangle();
            glDepthRange(0, 1);
            break;
        case 2:
            glDepthRange(0.1, 1);
            wall(), square();
            glDepthRange(0, 0.1);
            triangle();
            glDepthRange(0, 1);
            break;
        case 3:
            wall(), square();
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glDepthRange(1, 1);
            glDepthFunc(GL_ALWAYS);
            rect(40, 60, 100, 120);
            glDepthRange(0, 1);
            glDepthFunc(GL_LESS);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            triangle();
            break;
        }
        panel_label(&ex, use, 4, 1, names[use]);
    }
    example_save(&ex, "depth_range");
    return example_finish(&ex);
}
