/* depth_mask: the three depth buffer modes of the lecture. A near green square (depth 0.3)
 * is drawn first, then a far red square (depth 0.7) overlapping it.
 *   left:   depth test off: the red square, drawn last, covers the green one;
 *   middle: depth test on, depth writes on (glDepthMask(GL_TRUE)): the nearer green square
 *           stays in front;
 *   right:  depth test on, the green square drawn with depth writes off
 *           (glDepthMask(GL_FALSE)): it leaves no depth, so the far red square covers it. */
#include "example.h"

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "depth_mask", argc, argv, 600, 200, 24, 0);
    for (int mode = 0; mode < 3; mode++) {
        panel(&ex, mode, 3, 1, 0.2f, 0.2f, 0.2f);
        ortho(200, 200);
        if (mode == 0)
            glDisable(GL_DEPTH_TEST);
        else
            glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);

        glDepthMask(mode == 2 ? GL_FALSE : GL_TRUE);
        glColor3f(0.1f, 0.8f, 0.2f);
        rect_z(20, 20, 130, 130, 0.4f); /* depth 0.3 */
        glDepthMask(GL_TRUE);
        glColor3f(0.9f, 0.15f, 0.1f);
        rect_z(70, 70, 180, 180, -0.4f); /* depth 0.7 */
        panel_label(&ex, mode, 3, 1, mode == 0 ? "TEST OFF" : mode == 1 ? "TEST ON, MASK ON" : "GREEN MASK OFF");
    }
    example_save(&ex, "depth_mask");
    return example_finish(&ex);
}
