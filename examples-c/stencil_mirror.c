/* stencil_mirror: the lecture's mirror reflection with the stencil and the selective depth
 * clear. A wall mirror stands at z = -3 behind a checkered floor with a box and a pyramid.
 * The correct picture is drawn in three steps:
 *   1. the scene; then the mirror into the stencil (stencil 1 where the mirror is visible,
 *      color and depth writes off);
 *   2. the depth buffer is cleared selectively behind the mirror: color writes off,
 *      glDepthRange(1, 1), glDepthFunc(GL_ALWAYS), glStencilFunc(GL_EQUAL, 1, ~0), and the
 *      mirror drawn once more: depth 1 wherever the stencil is 1;
 *   3. the reflected scene (mirrored through the plane z = -3, so clockwise faces are front
 *      faces) only where the stencil is 1, then the glass, lightly blended.
 * Panels: the reflected scene alone; the same algorithm without the stencil (the reflection
 * spills out of the mirror and over the box in front of it); limited by the stencil. */
#include "example.h"

#define MIRROR_Z (-3.0f)

static void floor_tiles(void)
{
    glBegin(GL_QUADS);
    for (int z = 0; z < 5; z++)
        for (int x = -4; x < 4; x++) {
            if ((x + z) & 1)
                glColor3f(0.85f, 0.85f, 0.8f);
            else
                glColor3f(0.35f, 0.3f, 0.3f);
            float z0 = MIRROR_Z + z, x0 = (float)x;
            glVertex3f(x0, -1, z0 + 1), glVertex3f(x0 + 1, -1, z0 + 1), glVertex3f(x0 + 1, -1, z0), glVertex3f(x0, -1, z0);
        }
    glEnd();
}

static void pyramid(float x, float z, float size)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.3f, 0.2f);
    glVertex3f(x - size, -1, z + size), glVertex3f(x + size, -1, z + size), glVertex3f(x, size * 1.6f - 1, z);
    glColor3f(0.3f, 0.9f, 0.3f);
    glVertex3f(x + size, -1, z + size), glVertex3f(x + size, -1, z - size), glVertex3f(x, size * 1.6f - 1, z);
    glColor3f(0.3f, 0.4f, 1.0f);
    glVertex3f(x + size, -1, z - size), glVertex3f(x - size, -1, z - size), glVertex3f(x, size * 1.6f - 1, z);
    glColor3f(1.0f, 0.9f, 0.2f);
    glVertex3f(x - size, -1, z - size), glVertex3f(x - size, -1, z + size), glVertex3f(x, size * 1.6f - 1, z);
    glEnd();
}

static void scene(void)
{
    static const float colors[6][3] = {{0.7f, 0.2f, 0.7f}, {0.9f, 0.4f, 0.9f}, {0.4f, 0.1f, 0.4f},
                                       {1.0f, 0.6f, 1.0f}, {0.5f, 0.15f, 0.5f}, {0.8f, 0.3f, 0.8f}};
    floor_tiles();
    box(-0.9f, -1.0f, -1.4f, 0.1f, 0.3f, -0.4f, colors);
    pyramid(1.1f, -2.0f, 0.5f);
}

static void mirror(void) { rect_z(-1.8f, -1.0f, 1.8f, 1.4f, MIRROR_Z); }

static void reflected_scene(void)
{
    glPushMatrix();
    glTranslatef(0, 0, MIRROR_Z);
    glScalef(1, 1, -1);
    glTranslatef(0, 0, -MIRROR_Z);
    glFrontFace(GL_CW);
    scene();
    glFrontFace(GL_CCW);
    glPopMatrix();
}

static void camera(void)
{
    perspective(50.0, 4.0 / 3.0, 0.5, 30.0);
    look_at(1.0, 1.3, 3.5, 0.0, -0.2, -2.0, 0, 1, 0);
}

/* The three steps; `use_stencil` 0 leaves the stencil test out of steps 2 and 3. */
static void mirrored_picture(int use_stencil)
{
    scene();

    /* 1. The visible part of the mirror into the stencil. */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, ~0u);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    mirror();
    glDepthMask(GL_TRUE);
    if (!use_stencil)
        glDisable(GL_STENCIL_TEST);

    /* 2. Selectively clear the depth behind the mirror. */
    glDepthRange(1, 1);
    glDepthFunc(GL_ALWAYS);
    glStencilFunc(GL_EQUAL, 1, ~0u);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    mirror();
    glDepthRange(0, 1);
    glDepthFunc(GL_LESS);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* 3. The reflection, then the glass. */
    reflected_scene();
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.7f, 0.85f, 1.0f, 0.2f);
    mirror();
    glDisable(GL_BLEND);
}

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "stencil_mirror", argc, argv, 960, 240, 24, 8);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);

    panel(&ex, 0, 3, 1, 0.1f, 0.12f, 0.25f);
    camera();
    reflected_scene();

    panel(&ex, 1, 3, 1, 0.1f, 0.12f, 0.25f);
    camera();
    mirrored_picture(0);

    panel(&ex, 2, 3, 1, 0.1f, 0.12f, 0.25f);
    camera();
    mirrored_picture(1);

    panel_label(&ex, 0, 3, 1, "REFLECTED SCENE");
    panel_label(&ex, 1, 3, 1, "WITHOUT STENCIL");
    panel_label(&ex, 2, 3, 1, "LIMITED BY STENCIL");

    example_save(&ex, "stencil_mirror");
    return example_finish(&ex);
}
