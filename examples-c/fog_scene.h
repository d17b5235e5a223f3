/* fog_scene.h: the scene both fog examples draw: a checkered floor and rows of colored
 * posts receding from the camera, in flat colors (fog is the only thing that shades them). */
#ifndef FOG_SCENE_H
#define FOG_SCENE_H
#include "example.h"

static inline void fog_scene(void)
{
    glBegin(GL_QUADS);
    for (int z = -3; z < 30; z++)
        for (int x = -6; x < 6; x++) {
            float v = (x + z) & 1 ? 0.9f : 0.45f;
            glColor3f(v * 0.9f, v, v * 0.8f);
            glVertex3f(x * 2.0f, 0, -z * 2.0f), glVertex3f(x * 2.0f + 2, 0, -z * 2.0f);
            glVertex3f(x * 2.0f + 2, 0, -z * 2.0f - 2), glVertex3f(x * 2.0f, 0, -z * 2.0f - 2);
        }
    static const float colors[3][3] = {{0.9f, 0.1f, 0.1f}, {0.1f, 0.3f, 0.9f}, {0.95f, 0.75f, 0.1f}};
    for (int row = 0; row < 10; row++)
        for (int side = -1; side <= 1; side += 2) {
            const float *c = colors[row % 3];
            float x = side * 3.0f, z = -4.0f - row * 5.0f;
            glColor3fv(c);
            glVertex3f(x - 0.6f, 0, z), glVertex3f(x + 0.6f, 0, z);
            glVertex3f(x + 0.6f, 3.0f, z), glVertex3f(x - 0.6f, 3.0f, z);
        }
    glEnd();
}

#endif
