/* depth_functions: the eight depth functions. Every panel first draws a blue triangle at
 * depth 0.5 with GL_LESS (the depth buffer is cleared to 1.0), then a red band with the
 * panel's function; the band's left third is nearer (depth 0.2), its middle third at the
 * triangle's depth (0.5), its right third farther (0.8). Where the band passes the test it
 * is drawn (and writes its depth); where it fails the triangle or the background stays.
 * Top row: GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL; bottom row: GL_GREATER, GL_NOTEQUAL,
 * GL_GEQUAL, GL_ALWAYS. In every panel the band crosses both the triangle and the
 * background, so each function shows its result against depth 0.5 and against 1.0. */
#include "example.h"

int main(int argc, char **argv)
{
    static const GLenum functions[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                        GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const char *names[8] = {"NEVER", "LESS", "EQUAL", "LEQUAL", "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS"};
    Example ex;
    example_start(&ex, "depth_functions", argc, argv, 640, 320, 24, 0);
    glEnable(GL_DEPTH_TEST);
    for (int i = 0; i < 8; i++) {
        panel(&ex, i, 4, 2, 0.92f, 0.92f, 0.88f);
        ortho(160, 160); /* z = 0: depth 0.5; z = 0.6: depth 0.2; z = -0.6: depth 0.8 */

        glDepthFunc(GL_LESS);
        glColor3f(0.1f, 0.2f, 0.9f);
        glBegin(GL_TRIANGLES);
        glVertex3f(80, 150, 0), glVertex3f(10, 10, 0), glVertex3f(150, 10, 0);
        glEnd();

        glDepthFunc(functions[i]);
        glColor3f(0.9f, 0.1f, 0.1f);
        rect_z(5, 55, 55, 95, 0.6f);
        rect_z(55, 55, 105, 95, 0.0f);
        rect_z(105, 55, 155, 95, -0.6f);
        panel_label(&ex, i, 4, 2, names[i]);
    }
    example_save(&ex, "depth_functions");
    return example_finish(&ex);
}
