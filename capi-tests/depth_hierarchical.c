/* Depth tests whose draws fail whole regions of the buffer (tessera skips those through
 * hierarchical z, src/framebuffer/hiz.rs): within one scene, after a draw has failed a
 * region, depth is raised there by a GL_ALWAYS draw, glDrawPixels, a scissored clear or a
 * GL_GREATER draw, and a later GL_LESS draw must pass where it was raised; a draw failing
 * everywhere must still run its stencil z-fail operation and count nothing in an occlusion
 * query; a plane redrawn with GL_LEQUAL passes everywhere. Sizes cross tiles (64) and
 * regions (16) at odd places. */
#include "common.h"

#define W 200
#define H 150

/* A rectangle in pixels at window depth z (projection and modelview are identity). */
static void rect(float x0, float y0, float x1, float y1, float z, float r, float g, float b)
{
    float d = 2 * z - 1;
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex3f(2 * x0 / W - 1, 2 * y0 / H - 1, d);
    glVertex3f(2 * x1 / W - 1, 2 * y0 / H - 1, d);
    glVertex3f(2 * x1 / W - 1, 2 * y1 / H - 1, d);
    glVertex3f(2 * x0 / W - 1, 2 * y1 / H - 1, d);
    glEnd();
}

/* The whole window, depth z0 at the left edge to z1 at the right. */
static void tilted(float z0, float z1, float r, float g, float b)
{
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, 2 * z0 - 1);
    glVertex3f(1, -1, 2 * z1 - 1);
    glVertex3f(1, 1, 2 * z1 - 1);
    glVertex3f(-1, 1, 2 * z0 - 1);
    glEnd();
}

/* Clears, draws a near plane and a farther one that fails everywhere (so its regions are
 * known to be nearer than it). */
static void near_then_rejected(void)
{
    glDisable(GL_SCISSOR_TEST);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    rect(0, 0, W, H, 0.2f, 0.5f, 0.5f, 0.5f);
    rect(0, 0, W, H, 0.6f, 0, 0, 1);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);

    /* GL_ALWAYS raises depth over part of the window. */
    near_then_rejected();
    glDepthFunc(GL_ALWAYS);
    rect(0, 0, 101, 77, 0.9f, 0, 1, 0);
    glDepthFunc(GL_LESS);
    rect(0, 0, W, H, 0.5f, 1, 0, 0);
    capi_save_framebuffer("after_always", W, H);

    /* glDrawPixels of depth raises it. */
    near_then_rejected();
    {
        static GLfloat far[70][50];
        for (int y = 0; y < 70; y++)
            for (int x = 0; x < 50; x++)
                far[y][x] = 0.9f;
        glDepthFunc(GL_ALWAYS);
        glColorMask(0, 0, 0, 0);
        glRasterPos2f(2 * 37.0f / W - 1, 2 * 21.0f / H - 1);
        glDrawPixels(50, 70, GL_DEPTH_COMPONENT, GL_FLOAT, far);
        glColorMask(1, 1, 1, 1);
    }
    glDepthFunc(GL_LESS);
    rect(0, 0, W, H, 0.5f, 1, 0, 0);
    capi_save_framebuffer("after_draw_pixels", W, H);

    /* A scissored clear raises it. */
    near_then_rejected();
    glEnable(GL_SCISSOR_TEST);
    glScissor(20, 30, 70, 50);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    rect(0, 0, W, H, 0.5f, 1, 0, 0);
    capi_save_framebuffer("after_scissored_clear", W, H);

    /* GL_GREATER with depth writes raises it where the tilted plane is farther. */
    near_then_rejected();
    glDepthFunc(GL_GREATER);
    tilted(0.05f, 0.95f, 0, 1, 0);
    glDepthFunc(GL_LESS);
    rect(0, 0, W, H, 0.5f, 1, 0, 0);
    capi_save_framebuffer("after_greater", W, H);

    /* A draw failing the depth test everywhere still increments the stencil (z-fail). */
    near_then_rejected();
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_INCR, GL_KEEP);
    rect(10, 10, 190, 140, 0.7f, 0, 1, 1);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glDisable(GL_DEPTH_TEST);
    rect(0, 0, W, H, 0.1f, 1, 1, 0);
    glDisable(GL_STENCIL_TEST);
    capi_save_framebuffer("stencil_zfail", W, H);

    /* Occlusion queries: nothing passes, then the part of a tilted plane in front. */
    if (strstr((const char *)glGetString(GL_EXTENSIONS), "GL_ARB_occlusion_query")) {
        GLuint q[2];
        GLuint counts[2];
        glGenQueries(2, q);
        near_then_rejected();
        glBeginQuery(GL_SAMPLES_PASSED, q[0]);
        rect(0, 0, W, H, 0.7f, 1, 0, 1);
        glEndQuery(GL_SAMPLES_PASSED);
        glBeginQuery(GL_SAMPLES_PASSED, q[1]);
        tilted(0.0f, 0.5f, 1, 0, 1);
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &counts[0]);
        glGetQueryObjectuiv(q[1], GL_QUERY_RESULT, &counts[1]);
        capi_check(counts[0] == 0, "a draw behind everything passes no sample (%u)", counts[0]);
        capi_value("samples_passed", "%u %u", counts[0], counts[1]);
        glDeleteQueries(2, q);
        capi_save_framebuffer("queries", W, H);
    }

    /* A tilted plane, one just behind it (fails everywhere), one crossing it, then the
     * first redrawn with GL_LEQUAL (passes wherever it is still in front). */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    tilted(0.3f, 0.7f, 0.5f, 0.5f, 0.5f);
    tilted(0.31f, 0.71f, 0, 0, 1);
    tilted(0.25f, 0.75f, 1, 0, 0);
    glDepthFunc(GL_LEQUAL);
    tilted(0.3f, 0.7f, 0, 1, 0);
    capi_save_framebuffer("tilted", W, H);

    capi_check(glGetError() == GL_NO_ERROR, "no GL error");
    return capi_finish();
}
