/* multi_draw_buffers: one draw, several draw buffers, a blend state per draw buffer
 * (glDrawBuffers, glEnablei/glDisablei(GL_BLEND, i), glBlendFunci, glBlendEquationi).
 *
 * An OSMesa context has a single color buffer (GL_FRONT_LEFT; no back or aux buffers), so
 * the lecture's several color buffers cannot all be seen at once. What can be seen is that
 * the blend state belongs to the draw buffer *slot*: the same draw (a teal square with
 * alpha 0.6 over orange and blue stripes) is sent with glDrawBuffers(n, {GL_NONE, ...,
 * GL_FRONT_LEFT}) putting the front buffer in slot 0, 1, 2 or 3, and each slot has its own
 * blend state set up once before:
 *   top row:    slot 0: blending off (replace); slot 1: SRC_ALPHA, ONE_MINUS_SRC_ALPHA;
 *               slot 2: ONE, ONE (additive);
 *   bottom row: slot 3: GL_FUNC_REVERSE_SUBTRACT with ONE, ONE (destination minus source);
 *               glDrawBuffer(GL_FRONT_AND_BACK) (writes the front, the only buffer; slot 0's
 *               state); glDrawBuffer(GL_NONE): the draw writes nothing. */
#include "example.h"

static void stripes(void)
{
    glColor3f(1.0f, 0.55f, 0.1f);
    rect(10, 10, 60, 150);
    glColor3f(0.2f, 0.3f, 0.9f);
    rect(60, 10, 110, 150);
    glColor3f(0.9f, 0.9f, 0.9f);
    rect(110, 10, 150, 150);
}

static void the_draw(void)
{
    glColor4f(0.0f, 0.7f, 0.6f, 0.6f);
    rect(30, 40, 130, 120);
}

int main(int argc, char **argv)
{
    static const char *names[6] = {"SLOT 0: OFF", "SLOT 1: ALPHA", "SLOT 2: ADD", "SLOT 3: REV SUB",
                                   "FRONT_AND_BACK", "NONE"};
    Example ex;
    example_start(&ex, "multi_draw_buffers", argc, argv, 480, 320, 0, 0);

    /* The per-slot blend states, set once. */
    glDisablei(GL_BLEND, 0);
    glEnablei(GL_BLEND, 1);
    glBlendFunci(1, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnablei(GL_BLEND, 2);
    glBlendFunci(2, GL_ONE, GL_ONE);
    glEnablei(GL_BLEND, 3);
    glBlendFunci(3, GL_ONE, GL_ONE);
    glBlendEquationi(3, GL_FUNC_REVERSE_SUBTRACT);

    for (int i = 0; i < 6; i++) {
        panel(&ex, i, 3, 2, 0.1f, 0.1f, 0.1f);
        ortho(160, 160);
        GLenum slots[4] = {GL_NONE, GL_NONE, GL_NONE, GL_NONE};
        glDrawBuffer(GL_FRONT_LEFT);
        stripes();
        if (i < 4) {
            slots[i] = GL_FRONT_LEFT;
            glDrawBuffers(i + 1, slots);
        } else {
            glDrawBuffer(i == 4 ? GL_FRONT_AND_BACK : GL_NONE);
        }
        the_draw();
        panel_label(&ex, i, 3, 2, names[i]);
    }
    glDrawBuffer(GL_FRONT_LEFT);
    example_save(&ex, "multi_draw_buffers");
    return example_finish(&ex);
}
