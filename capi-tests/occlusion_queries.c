/* Occlusion queries: the count of GL_SAMPLES_PASSED is the exact number of fragments that
 * pass the depth and stencil tests (checked against the pixel count of axis-aligned
 * rectangles, and compared with Mesa for triangles, lines, points, glBitmap and a
 * display list); the query entry points' errors and state. */
#include "common.h"

#define W 128
#define H 96

static GLuint result(GLuint q)
{
    GLuint available = 0, value = 0;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &available);
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &value);
    capi_check(available == 1 || !capi_is_tessera(), "available after asking for it");
    return value;
}

static void rect(int x0, int y0, int x1, int y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f((float)x0, (float)y0, z);
    glVertex3f((float)x1, (float)y0, z);
    glVertex3f((float)x1, (float)y1, z);
    glVertex3f((float)x0, (float)y1, z);
    glEnd();
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    GLuint q[4];
    glGenQueries(4, q);
    capi_value("gen", "%u %u %u %u", q[0], q[1], q[2], q[3]);
    GLint bits = 0;
    glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &bits);
    capi_check(bits >= 32, "counter bits %d", bits);

    /* A 100x50 rectangle: 5000 fragments, across several tiles. */
    glEnable(GL_DEPTH_TEST);
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    GLint current = 0;
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
    capi_check(current == (GLint)q[0], "GL_CURRENT_QUERY");
    rect(10, 20, 110, 70, 0.0f);
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint n = result(q[0]);
    capi_value("visible_rect", "%u", n);
    capi_check(n == 5000, "exact count %u", n);

    /* Behind it (object z = -0.5 is window z 0.75): 20x50 minus the 10x30 overlap. */
    glBeginQuery(GL_SAMPLES_PASSED, q[1]);
    rect(100, 40, 120, 90, -0.5f);
    rect(0, 0, 10, 10, -0.5f); /* in front of the cleared depth: 100 more */
    glEndQuery(GL_SAMPLES_PASSED);
    n = result(q[1]);
    capi_value("partly_hidden", "%u", n);
    capi_check(n == 20 * 50 - 10 * 30 + 100, "exact count %u", n);

    /* Stencil, scissor, triangles, lines, points and a bitmap. */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 64, H);
    glDepthFunc(GL_ALWAYS);
    glBeginQuery(GL_SAMPLES_PASSED, q[2]);
    rect(30, 30, 90, 60, 0.0f); /* 34x30 inside the scissor */
    rect(40, 35, 80, 50, 0.0f); /* stencil now 1 there: none */
    glBegin(GL_TRIANGLES);
    glVertex2f(1.5f, 75.2f);
    glVertex2f(40.3f, 80.1f);
    glVertex2f(12.7f, 95.0f);
    glEnd();
    glBegin(GL_LINES);
    glVertex2f(0.5f, 72.5f);
    glVertex2f(63.5f, 90.5f);
    glEnd();
    glPointSize(5);
    glBegin(GL_POINTS);
    glVertex2f(50.5f, 10.5f);
    glEnd();
    GLubyte bitmap[8] = {0xff, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xff};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2i(20, 5);
    glBitmap(8, 8, 0, 0, 0, 0, bitmap);
    glEndQuery(GL_SAMPLES_PASSED);
    n = result(q[2]);
    capi_value("mixed", "%u", n);

    /* From a display list. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBeginQuery(GL_SAMPLES_PASSED, q[3]);
    rect(0, 0, 4, 4, 0.0f);
    glEndQuery(GL_SAMPLES_PASSED);
    glEndList();
    glDisable(GL_STENCIL_TEST);
    glCallList(list);
    n = result(q[3]);
    capi_value("from_list", "%u", n);
    capi_check(n == 16, "16 fragments %u", n);
    glDisable(GL_SCISSOR_TEST);

    /* Errors. */
    glBeginQuery(GL_SAMPLES_PASSED, 0);
    capi_expect_error(GL_INVALID_OPERATION, "glBeginQuery(0)");
    glBeginQuery(GL_TIME_ELAPSED + 0x1000, q[0]);
    capi_expect_error(GL_INVALID_ENUM, "glBeginQuery bad target");
    glEndQuery(GL_SAMPLES_PASSED);
    capi_expect_error(GL_INVALID_OPERATION, "glEndQuery without a query");
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glBeginQuery(GL_SAMPLES_PASSED, q[1]);
    capi_expect_error(GL_INVALID_OPERATION, "nested glBeginQuery");
    GLuint value;
    glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &value);
    capi_expect_error(GL_INVALID_OPERATION, "result of the active query");
    glEndQuery(GL_SAMPLES_PASSED);
    glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &value);
    capi_value("empty_query", "%u", value);
    glGetQueryObjectuiv(9999, GL_QUERY_RESULT, &value);
    capi_expect_error(GL_INVALID_OPERATION, "result of no query");
    glGenQueries(-1, q);
    capi_expect_error(GL_INVALID_VALUE, "glGenQueries(-1)");
    capi_check(glIsQuery(q[1]), "glIsQuery");
    glDeleteQueries(1, &q[1]);
    capi_check(!glIsQuery(q[1]), "deleted");
    capi_expect_error(GL_NO_ERROR, "no error");
    capi_save_framebuffer("occlusion", W, H);
    return capi_finish();
}
