/* glCopyPixels of color (with zoom, scissor and blending), depth (the copied depths then
 * read back, and used by the depth test) and stencil (read back exactly), glDrawPixels of
 * stencil indices under a write mask, and glCopyPixels' errors. */
#include "common.h"

#define W 64
#define H 48

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0, 0, 0.25f, 1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    /* A source: a smooth triangle with depth from -0.8 to 0.6 and stencil 5. */
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 5, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(2, 2, -0.8f);
    glColor3f(0, 1, 0);
    glVertex3f(18, 2, 0.6f);
    glColor3f(0, 0, 1);
    glVertex3f(2, 18, 0.0f);
    glEnd();
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);

    /* Color: plain, zoomed, scissored with blending. */
    glRasterPos2i(22, 2);
    glCopyPixels(0, 0, 20, 20, GL_COLOR);
    glPixelZoom(0.4f, 1.4f); /* no pixel centre on a zoomed pixel's edge */
    glRasterPos2i(44, 2);
    glCopyPixels(0, 0, 20, 20, GL_COLOR);
    glPixelZoom(1, 1);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 20, 30, 28);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glRasterPos2i(8, 24);
    glCopyPixels(0, 0, 30, 20, GL_COLOR);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);

    /* Depth: copied next to the source with the depth test off (GL_ALWAYS writes). */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glColorMask(0, 0, 0, 0);
    glRasterPos2i(40, 26);
    glCopyPixels(0, 0, 20, 20, GL_DEPTH);
    glColorMask(1, 1, 1, 1);
    glDepthFunc(GL_LESS);
    GLuint depth[20 * 20], source[20 * 20];
    glReadPixels(40, 26, 20, 20, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    glReadPixels(0, 0, 20, 20, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, source);
    /* Mesa 22 copies depth through a float texture (10 of these 400 change by more than one
     * 24-bit step); tessera copies exactly. The picture below compares the depth test. */
    int exact = 0;
    for (int i = 0; i < 400; i++)
        exact += depth[i] >> 8 == source[i] >> 8;
    if (capi_is_tessera())
        capi_check(exact == 400, "tessera copies depth exactly: %d", exact);
    /* A quad at z = 0 over the copy: only where the copied depth is farther. */
    glColor3f(1, 1, 0);
    glBegin(GL_QUADS);
    glVertex2i(40, 26);
    glVertex2i(60, 26);
    glVertex2i(60, 46);
    glVertex2i(40, 46);
    glEnd();
    glDisable(GL_DEPTH_TEST);

    /* Stencil: copy, then draw stencil indices under a write mask. */
    glRasterPos2i(30, 0);
    glCopyPixels(0, 0, 20, 20, GL_STENCIL);
    GLubyte stencil[20 * 20];
    glReadPixels(30, 0, 20, 20, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    capi_save_image("copied_stencil", 20, 20, 1, CAPI_U8, stencil);
    GLubyte indices[8 * 4];
    for (int i = 0; i < 32; i++)
        indices[i] = (GLubyte)(i * 9);
    glStencilMask(0x3c);
    glRasterPos2i(32, 2);
    glDrawPixels(8, 4, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, indices);
    glStencilMask(0xff);
    glReadPixels(30, 0, 20, 20, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    capi_save_image("drawn_stencil", 20, 20, 1, CAPI_U8, stencil);

    /* Errors. */
    glCopyPixels(0, 0, -1, 2, GL_COLOR);
    capi_expect_error(GL_INVALID_VALUE, "negative width");
    glCopyPixels(0, 0, 1, 1, GL_RGBA);
    capi_expect_error(GL_INVALID_ENUM, "bad type");
    capi_save_framebuffer("copy_pixels", W, H);
    return capi_finish();
}
