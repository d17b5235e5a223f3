/* blend_factors: the 6x6 table of source x destination blend factors from the Pyglet
 * blending article: a yellow square (1, 1, 0, alpha) blended over a grey background square
 * with every pair of six source factors (rows, bottom to top: SRC_ALPHA, ONE_MINUS_SRC_ALPHA,
 * DST_COLOR, ONE_MINUS_DST_COLOR, ZERO, ONE) and six destination factors (columns, left to
 * right: SRC_ALPHA, ONE_MINUS_SRC_ALPHA, SRC_COLOR, ONE_MINUS_SRC_COLOR, ZERO, ONE), drawn
 * at the article's four alphas 0.01, 0.30, 0.70 and 1.00 (blend_factors_a001.png, ...).
 * Same 450x450 window layout as the article: 40x40 squares at 50 + 60 * column/row. */
#include "example.h"

static void square_with_blending(float x, float y, GLenum sfactor, GLenum dfactor, float alpha)
{
    glBlendFunc(sfactor, dfactor);
    glColor4f(1.0f, 1.0f, 0.0f, alpha);
    rect(x, y, x + 40, y + 40);
}

int main(int argc, char **argv)
{
    static const GLenum sfactors[6] = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_COLOR,
                                       GL_ONE_MINUS_DST_COLOR, GL_ZERO, GL_ONE};
    static const GLenum dfactors[6] = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_COLOR,
                                       GL_ONE_MINUS_SRC_COLOR, GL_ZERO, GL_ONE};
    static const float alphas[4] = {0.01f, 0.30f, 0.70f, 1.00f};
    static const char *images[4] = {"blend_factors_a001", "blend_factors_a030", "blend_factors_a070",
                                    "blend_factors_a100"};
    static const char *captions[4] = {"ALPHA 0.01", "ALPHA 0.30", "ALPHA 0.70", "ALPHA 1.00"};
    Example ex;
    example_start(&ex, "blend_factors", argc, argv, 450, 450, 0, 0);
    ortho(450, 450);
    for (int a = 0; a < 4; a++) {
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        /* The grey background square, 10 pixels from the border, not blended. */
        glDisable(GL_BLEND);
        glColor3f(0.5f, 0.5f, 0.5f);
        rect(10, 10, 440, 440);
        glEnable(GL_BLEND);
        for (int y = 0; y < 6; y++)
            for (int x = 0; x < 6; x++)
                square_with_blending(50 + 60 * x, 50 + 60 * y, sfactors[y], dfactors[x], alphas[a]);
        label(&ex, 14, 426, 2, captions[a]);
        example_save(&ex, images[a]);
    }
    return example_finish(&ex);
}
