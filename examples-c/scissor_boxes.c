/* scissor_boxes: the lecture's "three different scissor boxes" (glScissor(x, y, w, h), x and
 * y the lower left corner). A pinwheel of colored triangles is drawn dimmed over the whole
 * window; then, for each of three scissor boxes, the box is cleared to its own background
 * (glClear obeys the scissor too) and the same pinwheel is drawn at full brightness: only
 * the fragments inside the box survive. */
#include "example.h"

static void pinwheel(float brightness)
{
    static const float colors[6][3] = {{1, 0.2f, 0.2f}, {1, 0.8f, 0.1f}, {0.2f, 0.9f, 0.2f},
                                       {0.1f, 0.8f, 0.9f}, {0.3f, 0.3f, 1}, {0.9f, 0.3f, 0.9f}};
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 12; i++) {
        float a0 = i * 6.2831853f / 12, a1 = (i + 1) * 6.2831853f / 12;
        const float *c = colors[i % 6];
        glColor3f(c[0] * brightness, c[1] * brightness, c[2] * brightness);
        glVertex2f(160, 120);
        glVertex2f(160 + 150 * cosf(a0), 120 + 150 * sinf(a0));
        glVertex2f(160 + 100 * cosf(a1), 120 + 100 * sinf(a1));
    }
    glEnd();
}

int main(int argc, char **argv)
{
    static const int boxes[3][4] = {{20, 130, 110, 90}, {150, 20, 70, 150}, {240, 90, 70, 130}};
    static const float backgrounds[3][3] = {{0.25f, 0.1f, 0.1f}, {0.1f, 0.25f, 0.1f}, {0.1f, 0.1f, 0.3f}};
    Example ex;
    example_start(&ex, "scissor_boxes", argc, argv, 320, 240, 0, 0);
    ortho(320, 240);
    glClearColor(0.05f, 0.05f, 0.05f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    pinwheel(0.3f);

    glEnable(GL_SCISSOR_TEST);
    for (int i = 0; i < 3; i++) {
        glScissor(boxes[i][0], boxes[i][1], boxes[i][2], boxes[i][3]);
        glClearColor(backgrounds[i][0], backgrounds[i][1], backgrounds[i][2], 1);
        glClear(GL_COLOR_BUFFER_BIT);
        pinwheel(1.0f);
    }
    glDisable(GL_SCISSOR_TEST);
    example_save(&ex, "scissor_boxes");
    return example_finish(&ex);
}
