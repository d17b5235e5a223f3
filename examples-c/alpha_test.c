/* alpha_test: alpha test cut-outs. The alpha test compares each fragment's alpha with a
 * reference (glAlphaFunc) and drops the fragment when the comparison fails; it is how
 * "transparent pixels" are removed without sorting or blending.
 *   alpha_test_functions.png: the eight functions with reference 0.5 on a square whose
 *     alpha rises from 0 (left) to 1 (right) (smooth shading): top row GL_NEVER, GL_LESS,
 *     GL_EQUAL, GL_LEQUAL; bottom row GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS;
 *   alpha_test_cutout.png: a "leaf" whose shape exists only in its per-vertex alphas (a
 *     grid of quads, alpha high inside a five-lobed outline, low outside), over a
 *     checkerboard: left without the alpha test (the whole quad is drawn), right with
 *     glAlphaFunc(GL_GREATER, 0.5): the cut-out. */
#include "example.h"

static void checkerboard(void)
{
    glBegin(GL_QUADS);
    for (int y = 0; y < 10; y++)
        for (int x = 0; x < 10; x++) {
            float v = (x + y) & 1 ? 0.75f : 0.55f;
            glColor3f(v, v, v);
            glVertex2f(x * 24.0f, y * 24.0f), glVertex2f(x * 24.0f + 24, y * 24.0f);
            glVertex2f(x * 24.0f + 24, y * 24.0f + 24), glVertex2f(x * 24.0f, y * 24.0f + 24);
        }
    glEnd();
}

static float leaf_alpha(float x, float y)
{
    float dx = x - 120, dy = y - 120, r = sqrtf(dx * dx + dy * dy), a = atan2f(dy, dx);
    return 1.6f - r / (70.0f + 25.0f * cosf(5 * a));
}

static void leaf(void)
{
    const int n = 24;
    const float step = 200.0f / n;
    for (int j = 0; j < n; j++) {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= n; i++) {
            float x = 20 + i * step, y0 = 20 + j * step, y1 = y0 + step;
            glColor4f(0.15f, 0.6f, 0.15f, leaf_alpha(x, y1));
            glVertex2f(x, y1);
            glColor4f(0.15f, 0.6f, 0.15f, leaf_alpha(x, y0));
            glVertex2f(x, y0);
        }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    static const GLenum functions[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                        GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const char *names[8] = {"NEVER", "LESS", "EQUAL", "LEQUAL", "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS"};
    Example ex;
    example_start(&ex, "alpha_test", argc, argv, 640, 320, 0, 0);
    glShadeModel(GL_SMOOTH);
    for (int i = 0; i < 8; i++) {
        panel(&ex, i, 4, 2, 0.2f, 0.2f, 0.25f);
        ortho(160, 160);
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(functions[i], 0.5f);
        glBegin(GL_QUADS);
        glColor4f(1.0f, 0.7f, 0.1f, 0.0f);
        glVertex2f(16, 16);
        glColor4f(1.0f, 0.7f, 0.1f, 1.0f);
        glVertex2f(144, 16);
        glVertex2f(144, 144);
        glColor4f(1.0f, 0.7f, 0.1f, 0.0f);
        glVertex2f(16, 144);
        glEnd();
        glDisable(GL_ALPHA_TEST);
        panel_label(&ex, i, 4, 2, names[i]);
    }
    example_save(&ex, "alpha_test_functions");
    glDisable(GL_SCISSOR_TEST);

    Example cut;
    example_finish(&ex);
    example_start(&cut, "alpha_test", argc, argv, 480, 240, 0, 0);
    for (int with_test = 0; with_test < 2; with_test++) {
        panel(&cut, with_test, 2, 1, 0, 0, 0);
        ortho(240, 240);
        checkerboard();
        if (with_test) {
            glEnable(GL_ALPHA_TEST);
            glAlphaFunc(GL_GREATER, 0.5f);
        }
        leaf();
        glDisable(GL_ALPHA_TEST);
        panel_label(&cut, with_test, 2, 1, with_test ? "GREATER 0.5" : "NO ALPHA TEST");
    }
    example_save(&cut, "alpha_test_cutout");
    return example_finish(&cut);
}
