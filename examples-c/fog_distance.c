/* fog_distance: which distance fog uses (GL_NV_fog_distance). The lecture's "range fog"
 * versus "non-range fog": with a wide field of view (100 degrees) the same linear fog
 * (start 2, end 30) looks different at the edges of the picture.
 *   left:  GL_EYE_PLANE_ABSOLUTE_NV (the default): d = |z| in eye space, the distance to
 *          the eye plane: a wall facing the camera is fogged evenly;
 *   right: GL_EYE_RADIAL_NV: d = the true distance to the eye: the same wall gets foggier
 *          towards its sides, as it does in real fog when one turns the head.
 * The scene: the floor and posts of fog_modes, plus a wall of colored tiles at z = -14
 * facing the camera. */
#include "fog_scene.h"

static void wall(void)
{
    glBegin(GL_QUADS);
    for (int y = 0; y < 4; y++)
        for (int x = -10; x < 10; x++) {
            glColor3f((x & 1) ? 0.9f : 0.2f, (y & 1) ? 0.8f : 0.3f, ((x + y) & 1) ? 0.9f : 0.3f);
            glVertex3f(x * 2.0f, y * 2.0f, -14), glVertex3f(x * 2.0f + 2, y * 2.0f, -14);
            glVertex3f(x * 2.0f + 2, y * 2.0f + 2, -14), glVertex3f(x * 2.0f, y * 2.0f + 2, -14);
        }
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLfloat fog_color[4] = {0.75f, 0.78f, 0.82f, 1.0f};
    static const GLint distance_modes[2] = {GL_EYE_PLANE_ABSOLUTE_NV, GL_EYE_RADIAL_NV};
    Example ex;
    example_start(&ex, "fog_distance", argc, argv, 640, 320, 24, 0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, fog_color);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 30.0f);
    for (int i = 0; i < 2; i++) {
        panel(&ex, i, 2, 1, fog_color[0], fog_color[1], fog_color[2]);
        glFogi(GL_FOG_DISTANCE_MODE_NV, distance_modes[i]);
        perspective(100.0, 1.0, 0.5, 100.0);
        look_at(0, 2.0, 0.0, 0, 2.0, -10, 0, 1, 0);
        fog_scene();
        wall();
        panel_label(&ex, i, 2, 1, i == 0 ? "EYE PLANE" : "RADIAL");
    }
    example_save(&ex, "fog_distance");
    return example_finish(&ex);
}
