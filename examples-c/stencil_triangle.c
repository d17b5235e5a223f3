/* stencil_triangle: the lecture's "drawing limited by a triangle". Three panels, each one
 * step further:
 *   1. a red triangle is drawn and sets the stencil to 1 where it covers
 *      (glStencilFunc(GL_ALWAYS, 1, 1), glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE));
 *   2. then a green square only where the stencil is 1 (GL_EQUAL): the green part of the
 *      square is the part inside the triangle, without the square's corners;
 *   3. then a blue square, the same square, only where the stencil is not 1 (GL_NOTEQUAL):
 *      only its blue corners remain. */
#include "example.h"

static void red_triangle(void)
{
    glColor3f(1, 0, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(100, 185);
    glVertex2f(12, 20);
    glVertex2f(188, 20);
    glEnd();
}

static void square(void) { rect(45, 35, 155, 145); }

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "stencil_triangle", argc, argv, 600, 200, 0, 8);
    glEnable(GL_STENCIL_TEST);
    for (int steps = 1; steps <= 3; steps++) {
        panel(&ex, steps - 1, 3, 1, 0.9f, 0.9f, 0.9f);
        ortho(200, 200);

        glStencilFunc(GL_ALWAYS, 1, 1);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        red_triangle();

        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        if (steps >= 2) {
            glStencilFunc(GL_EQUAL, 1, 1);
            glColor3f(0, 0.8f, 0);
            square();
        }
        if (steps >= 3) {
            glStencilFunc(GL_NOTEQUAL, 1, 1);
            glColor3f(0, 0, 1);
            square();
        }
        panel_label(&ex, steps - 1, 3, 1, steps == 1 ? "1" : steps == 2 ? "2: EQUAL 1" : "3: NOTEQUAL 1");
    }
    example_save(&ex, "stencil_triangle");
    return example_finish(&ex);
}
