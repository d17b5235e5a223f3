/* logic_ops: the sixteen logic operations (glLogicOp with GL_COLOR_LOGIC_OP), one cell each,
 * in the order of the lecture's table, row by row from the top: CLEAR, COPY, NOOP, SET /
 * COPY_INVERTED, INVERT, AND_REVERSE, OR_REVERSE / AND, OR, NAND, NOR / XOR, EQUIV,
 * AND_INVERTED, OR_INVERTED. Each cell's destination is four vertical stripes (black, white,
 * orange, blue); the source, drawn with the cell's operation, is a square whose upper half is
 * white and lower half teal. Inside the square each stripe shows f(S, D) bit by bit. */
#include "example.h"

int main(int argc, char **argv)
{
    static const GLenum ops[16] = {GL_CLEAR, GL_COPY, GL_NOOP, GL_SET,
                                   GL_COPY_INVERTED, GL_INVERT, GL_AND_REVERSE, GL_OR_REVERSE,
                                   GL_AND, GL_OR, GL_NAND, GL_NOR,
                                   GL_XOR, GL_EQUIV, GL_AND_INVERTED, GL_OR_INVERTED};
    static const unsigned char stripes[4][3] = {{0, 0, 0}, {255, 255, 255}, {255, 160, 0}, {40, 80, 220}};
    static const char *names[16] = {"CLEAR", "COPY", "NOOP", "SET", "COPY_INVERTED", "INVERT", "AND_REVERSE",
                                    "OR_REVERSE", "AND", "OR", "NAND", "NOR", "XOR", "EQUIV", "AND_INVERTED",
                                    "OR_INVERTED"};
    Example ex;
    example_start(&ex, "logic_ops", argc, argv, 480, 480, 0, 0);
    for (int i = 0; i < 16; i++) {
        panel(&ex, i, 4, 4, 0.5f, 0.5f, 0.5f);
        ortho(120, 120);
        for (int s = 0; s < 4; s++) {
            glColor3ubv(stripes[s]);
            rect(4 + s * 28, 4, 4 + (s + 1) * 28, 116);
        }
        glEnable(GL_COLOR_LOGIC_OP);
        glLogicOp(ops[i]);
        glColor3ub(255, 255, 255);
        rect(20, 60, 100, 100);
        glColor3ub(0, 160, 150);
        rect(20, 20, 100, 60);
        glDisable(GL_COLOR_LOGIC_OP);
        panel_label(&ex, i, 4, 4, names[i]);
    }
    example_save(&ex, "logic_ops");
    return example_finish(&ex);
}
