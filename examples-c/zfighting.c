/* zfighting: z-fighting and its fixes from the lecture. A grey floor (y = 0) is seen in
 * perspective; a red "decal" quad, rotated by 30 degrees, lies just above it (y = 0.002),
 * drawn second with GL_LESS. In exact arithmetic the decal is always in front, but the
 * depth buffer cannot tell the two surfaces apart far from the camera: they fight, and
 * noisy stripes show which one won each pixel.
 *   zfighting.png, 16-bit depth buffer:
 *     left:  near plane 0.05: most of the precision is spent next to the camera: fighting;
 *     right: near plane 1.0 (the first fix: push the near plane away): less fighting;
 *   zfighting_offset.png, the same two views with the decal drawn with
 *     glPolygonOffset(-1, -1) (GL_POLYGON_OFFSET_FILL): pulled towards the viewer by an
 *     amount that follows the slope and the depth resolution, it wins everywhere. */
#include "example.h"

static void floor_and_decal(int offset)
{
    glColor3f(0.6f, 0.6f, 0.6f);
    glBegin(GL_QUADS);
    glVertex3f(-8, 0, 4), glVertex3f(8, 0, 4), glVertex3f(8, 0, -30), glVertex3f(-8, 0, -30);
    glEnd();

    if (offset) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(-1.0f, -1.0f);
    }
    glPushMatrix();
    glTranslatef(0, 0.002f, -8);
    glRotatef(30, 0, 1, 0);
    glColor3f(0.9f, 0.1f, 0.1f);
    glBegin(GL_QUADS);
    glVertex3f(-4, 0, 4), glVertex3f(4, 0, 4), glVertex3f(4, 0, -4), glVertex3f(-4, 0, -4);
    glEnd();
    glPopMatrix();
    glDisable(GL_POLYGON_OFFSET_FILL);
}

int main(int argc, char **argv)
{
    static const char *names[4] = {"NEAR 0.05", "NEAR 1.0", "NEAR 0.05 + OFFSET", "NEAR 1.0 + OFFSET"};
    Example ex;
    example_start(&ex, "zfighting", argc, argv, 640, 320, 16, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    for (int offset = 0; offset < 2; offset++) {
        for (int i = 0; i < 2; i++) {
            panel(&ex, i, 2, 1, 0.1f, 0.1f, 0.2f);
            perspective(50.0, 1.0, i == 0 ? 0.05 : 1.0, 60.0);
            look_at(0, 2, 6, 0, 0, -6, 0, 1, 0);
            floor_and_decal(offset);
            panel_label(&ex, i, 2, 1, names[offset * 2 + i]);
        }
        example_save(&ex, offset ? "zfighting_offset" : "zfighting");
    }
    return example_finish(&ex);
}
