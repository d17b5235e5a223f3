/* blend_draw_order: "draw order matters" (lecture example II). A yellow triangle
 * (1, 1, 0, 0.8) on the left and a cyan one (0, 1, 1, 0.8) on the right, blended with
 * glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) over black, so foreground and
 * background mix 0.8 : 0.2. Left panel: yellow first, then cyan; the overlap is
 * 0.8 * cyan + 0.2 * (0.8, 0.8, 0) = (0.16, 0.96, 0.8). Right panel: cyan first, then
 * yellow; the overlap is (0.8, 0.96, 0.16). */
#include "example.h"

static void yellow_triangle(void)
{
    glColor4f(1.0f, 1.0f, 0.0f, 0.8f);
    glBegin(GL_TRIANGLES);
    glVertex2f(20, 30);
    glVertex2f(200, 30);
    glVertex2f(80, 230);
    glEnd();
}

static void cyan_triangle(void)
{
    glColor4f(0.0f, 1.0f, 1.0f, 0.8f);
    glBegin(GL_TRIANGLES);
    glVertex2f(60, 30);
    glVertex2f(240, 30);
    glVertex2f(180, 230);
    glEnd();
}

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "blend_draw_order", argc, argv, 520, 260, 0, 0);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    panel(&ex, 0, 2, 1, 0, 0, 0);
    ortho(260, 260);
    yellow_triangle();
    cyan_triangle();

    panel(&ex, 1, 2, 1, 0, 0, 0);
    ortho(260, 260);
    cyan_triangle();
    yellow_triangle();

    panel_label(&ex, 0, 2, 1, "YELLOW, THEN CYAN");
    panel_label(&ex, 1, 2, 1, "CYAN, THEN YELLOW");
    example_save(&ex, "blend_draw_order");
    return example_finish(&ex);
}
