/* Selection: a picking scene (a pick matrix around a point, named objects at several depths,
 * nested names, culled and clipped objects, a raster position) in GL_SELECT mode; every hit
 * record word is compared with Mesa. Also the name stack's errors, glRenderMode's return
 * values (hit count, -1 on overflow), GL_RENDER_MODE/GL_NAME_STACK_DEPTH, and that
 * selection draws and clears nothing. */
#include "common.h"

#define W 64
#define H 64

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

static void scene(void)
{
    glInitNames();
    glPushName(1);
    quad(10, 10, 50, 50, 0.25f); /* covers the pick point */
    glLoadName(2);
    quad(30, 30, 60, 60, -0.5f); /* covers it too, farther */
    glLoadName(3);
    quad(0, 0, 5, 5, 0.0f); /* away from the pick point */
    glLoadName(4);
    glPushName(40);
    glBegin(GL_TRIANGLES); /* a sloped triangle through the point */
    glVertex3f(20, 20, -0.9f);
    glVertex3f(60, 25, 0.9f);
    glVertex3f(25, 60, 0.3f);
    glEnd();
    glPopName();
    glLoadName(5);
    glEnable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES); /* clockwise: culled */
    glVertex3f(20, 20, 0);
    glVertex3f(25, 60, 0);
    glVertex3f(60, 25, 0);
    glEnd();
    glDisable(GL_CULL_FACE);
    glLoadName(6);
    glBegin(GL_LINES);
    glVertex3f(0, 0, 0.5f);
    glVertex3f(64, 64, -0.5f);
    glEnd();
    glLoadName(7);
    glBegin(GL_POINTS);
    glVertex3f(32, 32, 0.75f);
    glVertex3f(2, 2, 0);
    glEnd();
    glLoadName(8);
    glRasterPos3f(33, 31, 0.1f);
    glLoadName(9);
    glPopName();
    glPushName(10);
    glPushName(11);
    quad(31, 31, 33, 33, -0.25f);
    glPopName();
    glPopName();
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glClearColor(0.2f, 0.2f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT);

    GLuint buffer[256];
    memset(buffer, 0xff, sizeof buffer);
    glSelectBuffer(256, buffer);
    void *pointer = NULL;
    glGetPointerv(GL_SELECTION_BUFFER_POINTER, &pointer);
    capi_check(pointer == buffer, "GL_SELECTION_BUFFER_POINTER");
    capi_check(glRenderMode(GL_SELECT) == 0, "leaving GL_RENDER returns 0");
    capi_value_query("select", "render_mode", GL_RENDER_MODE, 1);
    /* A pick matrix: a 4x4 pixel region around (32, 32) fills the view volume. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glTranslatef(0, 0, 0);
    glScalef(W / 4.0f, H / 4.0f, 1.0f);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT); /* draws nothing in selection mode */
    scene();
    capi_value_query("select", "name_stack_depth", GL_NAME_STACK_DEPTH, 1);
    GLint hits = glRenderMode(GL_RENDER);
    capi_value("hits", "%d", hits);
    int word = 0;
    for (int h = 0; h < hits && word < 256; h++) {
        char key[32];
        GLuint n = buffer[word];
        snprintf(key, sizeof key, "hit%d", h);
        capi_value(key, "names=%u zmin=%u zmax=%u", n, buffer[word + 1], buffer[word + 2]);
        for (GLuint k = 0; k < n; k++) {
            snprintf(key, sizeof key, "hit%d.name%u", h, k);
            capi_value(key, "%u", buffer[word + 3 + k]);
        }
        word += 3 + (int)n;
    }
    capi_value("words", "%d", word);
    capi_value("after_last_record", "%x", buffer[word]);
    capi_save_framebuffer("untouched", W, H);

    /* Overflow: -1, and the buffer holds what fitted. */
    GLuint small[5];
    memset(small, 0xff, sizeof small);
    glSelectBuffer(5, small);
    glRenderMode(GL_SELECT);
    glPushName(1);
    glPushName(2);
    quad(0, 0, 64, 64, 0);
    glPopName();
    quad(0, 0, 64, 64, 0);
    capi_value("overflow", "%d", glRenderMode(GL_RENDER));
    capi_value("overflow_words", "%u %u %u %u %u", small[0], small[1], small[2], small[3], small[4]);

    /* Errors. */
    glRenderMode(GL_SELECT);
    glSelectBuffer(5, small);
    capi_expect_error(GL_INVALID_OPERATION, "glSelectBuffer in selection mode");
    glPopName();
    capi_expect_error(GL_STACK_UNDERFLOW, "glPopName on an empty stack");
    glLoadName(3);
    capi_expect_error(GL_INVALID_OPERATION, "glLoadName on an empty stack");
    for (int i = 0; i < 64; i++)
        glPushName((GLuint)i);
    capi_expect_error(GL_NO_ERROR, "64 names fit");
    glPushName(64);
    capi_expect_error(GL_STACK_OVERFLOW, "the 65th overflows");
    glRenderMode(GL_RENDER);
    capi_value_query("render", "name_stack_depth", GL_NAME_STACK_DEPTH, 1);
    glPushName(1); /* ignored outside selection mode */
    capi_expect_error(GL_NO_ERROR, "name stack ignored in GL_RENDER");
    glRenderMode(0x1234);
    capi_expect_error(GL_INVALID_ENUM, "glRenderMode bad mode");
    glSelectBuffer(-1, small);
    capi_expect_error(GL_INVALID_VALUE, "glSelectBuffer negative size");
    return capi_finish();
}
