/* clip_behind_camera: the lecture's "removing the parts of primitives behind the camera".
 * A triangle on the ground has two vertices in front of the camera and one behind it
 * (red and green in front, blue behind; smooth colors).
 *   left:   side view (orthographic, along the x axis): the camera (white dot) looking
 *           to the left, its view frustum in grey, the triangle seen edge-on as a line;
 *   middle: wrong: the vertices projected and divided by w first, then the triangle drawn
 *           between the projections: the vertex behind the camera (w < 0) flips over to
 *           the top of the picture, and the triangle covers the wrong part of the screen;
 *   right:  right: GL clips the triangle in clip space (before the division by w) against
 *           the near plane, so only the part in front of the camera is drawn, reaching
 *           down from the projection of the front edge to the bottom of the picture. */
#include "example.h"

static const float vertices[3][3] = {{-2.0f, -1.0f, -6.0f}, {2.0f, -1.0f, -6.0f}, {0.3f, -1.6f, 2.0f}};
static const float colors[3][3] = {{1.0f, 0.2f, 0.2f}, {0.2f, 0.9f, 0.2f}, {0.2f, 0.3f, 1.0f}};

#define NEAR 0.5
#define FAR 20.0
#define FOVY 60.0

static void side_view(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-9, 5, -5, 5, -10, 10); /* the camera looks to the left */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(-90, 0, 1, 0); /* look along -x: eye z becomes screen x */
    glScalef(1, 1, -1);
    double t = tan(FOVY * 3.14159265358979323846 / 360.0);
    glColor3f(0.5f, 0.5f, 0.5f);
    glBegin(GL_LINES);
    glVertex3f(0, 0, 0), glVertex3f(0, (float)(10 * t), -10);
    glVertex3f(0, 0, 0), glVertex3f(0, (float)(-10 * t), -10);
    glVertex3f(0, (float)(NEAR * t), -NEAR), glVertex3f(0, (float)(-NEAR * t), -NEAR);
    glEnd();
    glPointSize(7);
    glColor3f(1, 1, 1);
    glBegin(GL_POINTS);
    glVertex3f(0, 0, 0);
    glEnd();
    glLineWidth(3);
    glBegin(GL_LINES);
    glColor3fv(colors[0]), glVertex3fv(vertices[0]);
    glColor3fv(colors[2]), glVertex3fv(vertices[2]);
    glEnd();
    glLineWidth(1);
}

static void triangle(void)
{
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; i++) {
        glColor3fv(colors[i]);
        glVertex3fv(vertices[i]);
    }
    glEnd();
}

/* The mistake: divide by w on the CPU, then draw the projections in 2D. */
static void wrong_projection(double aspect)
{
    double f = 1.0 / tan(FOVY * 3.14159265358979323846 / 360.0);
    ortho(2, 2);
    glTranslatef(1, 1, 0); /* NDC [-1, 1] to [0, 2] */
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; i++) {
        double w = -vertices[i][2];
        glColor3fv(colors[i]);
        glVertex2d(f / aspect * vertices[i][0] / w, f * vertices[i][1] / w);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    Example ex;
    example_start(&ex, "clip_behind_camera", argc, argv, 720, 240, 0, 0);
    glShadeModel(GL_SMOOTH);

    panel(&ex, 0, 3, 1, 0.1f, 0.1f, 0.15f);
    side_view();

    panel(&ex, 1, 3, 1, 0.1f, 0.1f, 0.15f);
    wrong_projection(1.0);

    panel(&ex, 2, 3, 1, 0.1f, 0.1f, 0.15f);
    perspective(FOVY, 1.0, NEAR, FAR);
    triangle();

    panel_label(&ex, 0, 3, 1, "SIDE VIEW");
    panel_label(&ex, 1, 3, 1, "WRONG: DIVIDE FIRST");
    panel_label(&ex, 2, 3, 1, "RIGHT: CLIPPED");

    example_save(&ex, "clip_behind_camera");
    return example_finish(&ex);
}
