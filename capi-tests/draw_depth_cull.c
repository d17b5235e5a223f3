/* Depth test with every function against a tilted plane, re-drawing with GL_EQUAL, and
 * face culling with every cull face / front face combination. */
#include "common.h"

#define W 128
#define H 64

static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

static void tilted(float x, float y, float z0, float z1, float r, float g, float b)
{
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex3f(x, y, z0);
    glVertex3f(x + 30, y, z1);
    glVertex3f(x + 30, y + 30, z1);
    glVertex3f(x, y + 30, z0);
    glEnd();
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    for (int i = 0; i < 8; i++) {
        float x = (i % 4) * 32.0f + 1, y = (i / 4) * 32.0f + 1;
        glDepthFunc(GL_LESS);
        tilted(x, y, -0.9f, 0.9f, 0.3f, 0.3f, 0.3f);
        glDepthFunc(funcs[i]);
        tilted(x, y, 0.9f, -0.9f, 1, 0.5f, 0);
        /* Redrawing the first plane with GL_EQUAL must hit exactly its visible pixels. */
        glDepthFunc(GL_EQUAL);
        tilted(x, y, -0.9f, 0.9f, 0, 0.4f, 1);
    }
    capi_save_framebuffer("depth_funcs", W, H);

    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_CULL_FACE);
    static const GLenum faces[3] = {GL_BACK, GL_FRONT, GL_FRONT_AND_BACK};
    for (int f = 0; f < 3; f++)
        for (int ff = 0; ff < 2; ff++) {
            glCullFace(faces[f]);
            glFrontFace(ff ? GL_CW : GL_CCW);
            float x = (f * 2 + ff) * 20.0f + 4;
            glBegin(GL_TRIANGLES);
            glColor3f(1, 0, 0); /* counter-clockwise */
            glVertex2f(x, 5);
            glVertex2f(x + 15, 5);
            glVertex2f(x + 7, 25);
            glColor3f(0, 1, 0); /* clockwise */
            glVertex2f(x, 35);
            glVertex2f(x + 7, 55);
            glVertex2f(x + 15, 35);
            glEnd();
        }
    glDisable(GL_CULL_FACE);
    capi_save_framebuffer("culling", W, H);

    /* Coplanar polygons z-fight; glPolygonOffset pushes the second one in front. */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.5, 0.5, 1, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(-60, 1, 0, 0);
    for (int pass = 0; pass < 3; pass++) {
        if (pass == 2) {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(-1.5f, -2.0f);
        }
        float x0 = pass == 0 ? -6 : -2, y0 = pass == 0 ? -8 : -5;
        glColor3f(pass == 0, pass == 1, pass == 2);
        glBegin(GL_QUADS);
        glVertex3f(x0, y0, -4);
        glVertex3f(x0 + 8, y0, -4);
        glVertex3f(x0 + 8, y0 + 12, -4);
        glVertex3f(x0, y0 + 12, -4);
        glEnd();
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    capi_save_framebuffer("polygon_offset", W, H);
    capi_check(glGetError() == GL_NO_ERROR, "no GL error");
    return capi_finish();
}
