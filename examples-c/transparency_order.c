/* transparency_order: the lecture's "draw order is important, example III". An opaque box
 * (1) is drawn first with depth test and depth writes on; then two translucent planes
 * (alpha 0.5): a blue one (2) near the viewer and a red one (3) farther away, behind the
 * blue one and in front of the box. Four panels:
 *   top left:     back to front (red, then blue), depth writes off: right
 *   top right:    back to front, depth writes on: also right (the writes are only wasted)
 *   bottom left:  front to back (blue, then red), depth writes on: wrong, the red plane is
 *                 missing behind the blue one (it fails the depth test against it)
 *   bottom right: front to back, depth writes off: wrong, the farther red plane is blended
 *                 over the nearer blue one. */
#include "example.h"

static void opaque_box(void)
{
    static const float colors[6][3] = {{0.9f, 0.7f, 0.1f}, {0.7f, 0.5f, 0.05f}, {0.5f, 0.35f, 0.0f},
                                       {1.0f, 0.85f, 0.3f}, {0.6f, 0.45f, 0.05f}, {0.95f, 0.75f, 0.2f}};
    box(-1.0f, -1.0f, -9.0f, 1.0f, 1.0f, -7.0f, colors);
}

static void blue_plane(void)
{
    glColor4f(0.1f, 0.3f, 1.0f, 0.5f);
    rect_z(-2.0f, -1.4f, 1.2f, 1.2f, -3.0f);
}

static void red_plane(void)
{
    glColor4f(1.0f, 0.1f, 0.1f, 0.5f);
    rect_z(-0.6f, -1.2f, 2.4f, 1.8f, -5.0f);
}

int main(int argc, char **argv)
{
    static const char *names[4] = {"BACK TO FRONT, WRITES OFF", "BACK TO FRONT, WRITES ON",
                                   "FRONT TO BACK, WRITES ON", "FRONT TO BACK, WRITES OFF"};
    Example ex;
    example_start(&ex, "transparency_order", argc, argv, 600, 480, 24, 0);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    for (int i = 0; i < 4; i++) {
        int back_to_front = i < 2, depth_writes = i == 1 || i == 2;
        panel(&ex, i, 2, 2, 0.15f, 0.15f, 0.15f);
        perspective(45.0, 300.0 / 240.0, 1.0, 30.0);
        look_at(2.5, 1.5, 2.0, 0.0, 0.0, -6.0, 0, 1, 0);

        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        opaque_box();

        glEnable(GL_BLEND);
        glDepthMask(depth_writes ? GL_TRUE : GL_FALSE);
        if (back_to_front) {
            red_plane();
            blue_plane();
        } else {
            blue_plane();
            red_plane();
        }
        glDepthMask(GL_TRUE);
        panel_label(&ex, i, 2, 2, names[i]);
    }
    example_save(&ex, "transparency_order");
    return example_finish(&ex);
}
