/* stencil_capping: the lecture's "filling the holes of closed solids cut by a plane". Two
 * solids (a box and a prism, flat colored faces outside, dark grey inside) are cut by a
 * user clip plane, so one looks into them. Capping: while the solids are drawn every face
 * inverts the stencil (glStencilFunc(GL_ALWAYS, 0, 0x1), glStencilOp(GL_KEEP, GL_INVERT,
 * GL_INVERT)), so a pixel ends with 1 where an odd number of faces covers it: exactly where
 * the cut is open. Then one big white rectangle is drawn where the stencil is not 0.
 *   left: cut, without the cap (the insides show); right: capped with GL_INVERT. */
#include "example.h"

/* While the insides are drawn every face is dark grey. */
static int drawing_insides;

static void face_color(float r, float g, float b)
{
    if (drawing_insides)
        glColor3f(0.25f, 0.25f, 0.25f);
    else
        glColor3f(r, g, b);
}

static void box_faces(void)
{
    static const float colors[6][3] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.7f, 0.2f}, {0.2f, 0.3f, 0.9f},
                                       {0.9f, 0.8f, 0.1f}, {0.8f, 0.3f, 0.8f}, {0.2f, 0.8f, 0.8f}};
    static const float grey[6][3] = {{0.25f, 0.25f, 0.25f}, {0.25f, 0.25f, 0.25f}, {0.25f, 0.25f, 0.25f},
                                     {0.25f, 0.25f, 0.25f}, {0.25f, 0.25f, 0.25f}, {0.25f, 0.25f, 0.25f}};
    box(-1.6f, -0.8f, -0.8f, -0.1f, 0.8f, 0.8f, drawing_insides ? grey : colors);
}

/* A triangular prism along z, faces counter-clockwise from outside. */
static void prism_faces(void)
{
    const float a[2] = {0.3f, -0.8f}, b[2] = {1.7f, -0.8f}, c[2] = {1.0f, 0.9f};
    glBegin(GL_TRIANGLES);
    face_color(1.0f, 0.6f, 0.1f);
    glVertex3f(a[0], a[1], 0.8f), glVertex3f(b[0], b[1], 0.8f), glVertex3f(c[0], c[1], 0.8f);
    face_color(0.6f, 0.3f, 0.05f);
    glVertex3f(a[0], a[1], -0.8f), glVertex3f(c[0], c[1], -0.8f), glVertex3f(b[0], b[1], -0.8f);
    glEnd();
    glBegin(GL_QUADS);
    face_color(0.5f, 0.9f, 0.3f);
    glVertex3f(a[0], a[1], -0.8f), glVertex3f(b[0], b[1], -0.8f), glVertex3f(b[0], b[1], 0.8f), glVertex3f(a[0], a[1], 0.8f);
    face_color(0.3f, 0.6f, 1.0f);
    glVertex3f(b[0], b[1], -0.8f), glVertex3f(c[0], c[1], -0.8f), glVertex3f(c[0], c[1], 0.8f), glVertex3f(b[0], b[1], 0.8f);
    face_color(0.9f, 0.4f, 0.6f);
    glVertex3f(c[0], c[1], -0.8f), glVertex3f(a[0], a[1], -0.8f), glVertex3f(a[0], a[1], 0.8f), glVertex3f(c[0], c[1], 0.8f);
    glEnd();
}

/* Front faces in their colors, back faces (seen only through the cut) dark grey. */
static void solids(void)
{
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    box_faces();
    prism_faces();
    glCullFace(GL_FRONT);
    drawing_insides = 1;
    box_faces();
    prism_faces();
    drawing_insides = 0;
    glDisable(GL_CULL_FACE);
}

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "stencil_capping", argc, argv, 640, 320, 24, 8);
    glEnable(GL_DEPTH_TEST);
    for (int capped = 0; capped < 2; capped++) {
        panel(&ex, capped, 2, 1, 0.15f, 0.15f, 0.2f);
        perspective(40.0, 1.0, 1.0, 20.0);
        look_at(2.5, 2.5, 5.0, 0.0, 0.0, 0.0, 0, 1, 0);
        glRotatef(20.0f, 0, 1, 0);

        /* The cutting plane: keeps 0.4 x - y + 0.8 z + 0.2 >= 0 (cuts off the near top). */
        static const GLdouble plane[4] = {-0.4, -1.0, -0.8, 0.5};
        glClipPlane(GL_CLIP_PLANE0, plane);
        glEnable(GL_CLIP_PLANE0);

        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0, 0x1);
        glStencilOp(GL_KEEP, GL_INVERT, GL_INVERT);
        solids();
        glDisable(GL_CLIP_PLANE0);

        if (capped) {
            /* One big white rectangle over the whole panel, only where the stencil is odd. */
            glStencilFunc(GL_NOTEQUAL, 0x0, 0x1);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            glDisable(GL_DEPTH_TEST);
            ortho(1, 1);
            glColor3f(1, 1, 1);
            rect(0, 0, 1, 1);
            glEnable(GL_DEPTH_TEST);
        }
        glDisable(GL_STENCIL_TEST);
        panel_label(&ex, capped, 2, 1, capped ? "CAPPED (GL_INVERT)" : "CUT, NO CAP");
    }
    example_save(&ex, "stencil_capping");
    return example_finish(&ex);
}
