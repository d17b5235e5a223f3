/* fog_modes: the three fog factors of the lecture side by side, f blending the incoming
 * color with the fog color (C = f * Ci + (1 - f) * Cf, light grey here), d the distance:
 *   left:   GL_LINEAR, f = (end - d) / (end - start), start 2, end 50;
 *   middle: GL_EXP,    f = exp(-density * d), density 0.05;
 *   right:  GL_EXP2,   f = exp(-(density * d)^2), density 0.04.
 * The scene: a floor and rows of red, blue and yellow posts going into the distance. */
#include "fog_scene.h"

int main(int argc, char **argv)
{
    static const GLfloat fog_color[4] = {0.75f, 0.78f, 0.82f, 1.0f};
    static const GLint modes[3] = {GL_LINEAR, GL_EXP, GL_EXP2};
    static const float densities[3] = {0.0f, 0.05f, 0.04f};
    Example ex;
    example_start(&ex, "fog_modes", argc, argv, 720, 240, 24, 0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, fog_color);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 50.0f);
    for (int i = 0; i < 3; i++) {
        panel(&ex, i, 3, 1, fog_color[0], fog_color[1], fog_color[2]);
        glFogi(GL_FOG_MODE, modes[i]);
        glFogf(GL_FOG_DENSITY, densities[i]);
        perspective(60.0, 1.0, 0.5, 100.0);
        look_at(0, 2.0, 4.0, 0, 1.0, -10, 0, 1, 0);
        fog_scene();
        panel_label(&ex, i, 3, 1, i == 0 ? "GL_LINEAR" : i == 1 ? "GL_EXP" : "GL_EXP2");
    }
    example_save(&ex, "fog_modes");
    return example_finish(&ex);
}
