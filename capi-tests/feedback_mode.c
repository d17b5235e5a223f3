/* Feedback: a transcript of points, lines (strips and independent segments, clipped),
 * triangles (a clipped one, a culled one, a collinear one with and without culling, a quad
 * and a polygon), glPassThrough, glBitmap,
 * glDrawPixels and glCopyPixels tokens, in every feedback type, compared value by value with
 * Mesa; the return value on overflow; the errors. */
#include "common.h"

#define W 64
#define H 48

static void scene(void)
{
    glColor4f(1, 0.5f, 0.25f, 1);
    glTexCoord4f(0.5f, 0.25f, 2, 1);
    glBegin(GL_POINTS);
    glVertex3f(10, 10, 0.5f);
    glVertex3f(100, 10, 0); /* outside */
    glEnd();
    glPassThrough(42.5f);
    glBegin(GL_LINE_STRIP);
    glColor3f(0, 1, 0);
    glVertex2f(5, 5);
    glVertex2f(20, 30);
    glColor3f(0, 0, 1);
    glVertex2f(80, 30); /* clipped at x = 64 */
    glEnd();
    glBegin(GL_LINES);
    glVertex2f(1, 1);
    glVertex2f(2, 3);
    glVertex2f(4, 4);
    glVertex2f(6, 2);
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(10, 20, -0.5f);
    glVertex3f(30, 20, 0.5f);
    glVertex3f(20, 40, 0);
    glColor3f(1, 1, 0);
    glVertex2f(50, 10);
    glVertex2f(70, 10); /* clipped */
    glVertex2f(55, 30);
    glEnd();
    glEnable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES); /* clockwise: culled */
    glVertex2f(10, 10);
    glVertex2f(20, 40);
    glVertex2f(30, 10);
    glEnd();
    glBegin(GL_TRIANGLES); /* collinear: zero area, removed while culling */
    glVertex2f(1, 2);
    glVertex2f(3, 4);
    glVertex2f(5, 6);
    glEnd();
    glDisable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES); /* collinear: zero area, reported without culling */
    glVertex3f(1, 2, 0.25f);
    glVertex3f(3, 4, 0.5f);
    glVertex3f(5, 6, 0.75f);
    glEnd();
    glBegin(GL_QUADS);
    glVertex2f(2, 40);
    glVertex2f(8, 40);
    glVertex2f(8, 46);
    glVertex2f(2, 46);
    glEnd();
    glBegin(GL_POLYGON);
    glVertex2f(40, 35);
    glVertex2f(46, 36);
    glVertex2f(48, 42);
    glVertex2f(43, 46);
    glVertex2f(39, 41);
    glEnd();
    static const GLubyte bits[2] = {0xff, 0xff};
    glRasterPos3f(12.5f, 7.25f, 0.25f);
    glBitmap(8, 2, 0, 0, 3, 1, bits);
    glDrawPixels(1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, bits);
    glCopyPixels(0, 0, 2, 2, GL_COLOR);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    static GLfloat buffer[2048];
    const GLenum types[] = {GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE};
    for (int t = 0; t < 5; t++) {
        memset(buffer, 0, sizeof buffer);
        glFeedbackBuffer(2048, types[t], buffer);
        void *pointer = NULL;
        glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &pointer);
        capi_check(pointer == buffer, "GL_FEEDBACK_BUFFER_POINTER");
        glRenderMode(GL_FEEDBACK);
        scene();
        GLint n = glRenderMode(GL_RENDER);
        char key[32];
        snprintf(key, sizeof key, "type%d.count", t);
        capi_value(key, "%d", n);
        for (int i = 0; i < n; i++) {
            snprintf(key, sizeof key, "type%d.%d", t, i);
            capi_value(key, "%a", buffer[i]);
        }
    }
    /* Overflow. */
    glFeedbackBuffer(7, GL_3D, buffer);
    glRenderMode(GL_FEEDBACK);
    scene();
    capi_value("overflow", "%d", glRenderMode(GL_RENDER));
    /* Errors. */
    glFeedbackBuffer(4, GL_RGBA, buffer);
    capi_expect_error(GL_INVALID_ENUM, "bad type");
    glFeedbackBuffer(-1, GL_2D, buffer);
    capi_expect_error(GL_INVALID_VALUE, "negative size");
    glRenderMode(GL_FEEDBACK);
    glFeedbackBuffer(4, GL_2D, buffer);
    capi_expect_error(GL_INVALID_OPERATION, "in feedback mode");
    glRenderMode(GL_RENDER);
    capi_value_query("render", "feedback_size", GL_FEEDBACK_BUFFER_SIZE, 1);
    return capi_finish();
}
