/* blend_three_quads: the lecture's "blending example I": red, green and blue quads, each with
 * alpha 0.33, blended with glBlendFunc(GL_SRC_ALPHA, GL_ONE) over black. Where two overlap the
 * sum is yellow (red + green), cyan (green + blue) or magenta (red + blue), each channel
 * 0.33; where all three overlap it is grey (0.33, 0.33, 0.33). The destination alpha is
 * not used. */
#include "example.h"

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "blend_three_quads", argc, argv, 300, 300, 0, 0);
    ortho(300, 300);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);

    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glColor4f(1, 0, 0, 0.33f); /* drawRedQuad */
    rect(30, 110, 190, 270);
    glColor4f(0, 1, 0, 0.33f); /* drawGreenQuad */
    rect(110, 110, 270, 270);
    glColor4f(0, 0, 1, 0.33f); /* drawBlueQuad */
    rect(70, 30, 230, 190);

    example_save(&ex, "blend_three_quads");
    return example_finish(&ex);
}
