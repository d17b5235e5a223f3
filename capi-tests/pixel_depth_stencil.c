/* glDrawPixels and glCopyPixels of GL_DEPTH_STENCIL (GL_UNSIGNED_INT_24_8, as
 * EXT_packed_depth_stencil adds them), read back with glReadPixels of the same format; under
 * the scissor box, the stencil write mask, glDepthMask(GL_FALSE), depth scale/bias and index
 * offset; and glCopyPixels of a source rectangle partly outside the framebuffer (undefined in
 * GL; Mesa 22 reads those pixels as zero, and tessera does the same). */
#include "common.h"

#define W 32
#define H 32

static GLuint image[16 * 12];
static GLuint readback[W * H];

static void save_depth_stencil(const char *name)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, readback);
    capi_save_image(name, W, H, 4, CAPI_U8, readback);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    for (int i = 0; i < 16 * 12; i++)
        image[i] = ((GLuint)(i * 87517u) & 0xffffff) << 8 | (GLuint)(i * 7 + 3) % 256;
    glClearColor(0.2f, 0.3f, 0.4f, 1);
    glClearDepth(0.5);
    glClearStencil(0x5a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    /* Plain, then scissored with a stencil write mask and no depth writes, then with
     * transfer (depth scale/bias, index offset) and zoom. */
    glRasterPos2i(1, 2);
    glDrawPixels(16, 12, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    capi_expect_error(GL_NO_ERROR, "draw depth_stencil");
    save_depth_stencil("draw_plain");
    capi_save_framebuffer("draw_plain_color", W, H);

    glEnable(GL_SCISSOR_TEST);
    glScissor(4, 4, 20, 20);
    glStencilMask(0x0f);
    glDepthMask(GL_FALSE);
    glRasterPos2i(10, 12);
    glDrawPixels(16, 12, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    glDisable(GL_SCISSOR_TEST);
    glStencilMask(0xff);
    glDepthMask(GL_TRUE);
    save_depth_stencil("draw_masked");

    /* Pixel transfer applies to both parts in GL (Mesa 22 ignores it for GL_DEPTH_STENCIL):
     * checked on tessera only, at the end. */
    glPixelZoom(1.5f, -1);
    glRasterPos2i(2, 30);
    glDrawPixels(16, 12, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    glPixelZoom(1, 1);
    save_depth_stencil("draw_zoom");

    /* Copies: inside, then from a rectangle reaching past the left/bottom and the right/top
     * edges (clipped; the destination keeps its place for the pixels that remain). */
    glRasterPos2i(18, 1);
    glCopyPixels(1, 2, 12, 10, GL_DEPTH_STENCIL);
    capi_expect_error(GL_NO_ERROR, "copy depth_stencil");
    save_depth_stencil("copy_inside");
    glRasterPos2i(20, 20);
    glCopyPixels(-4, -3, 10, 8, GL_DEPTH_STENCIL);
    glRasterPos2i(2, 14);
    glCopyPixels(26, 27, 10, 9, GL_DEPTH_STENCIL);
    save_depth_stencil("copy_outside");
    /* The same for a zoomed color copy past the left and bottom edges. (Past the right and
     * top edges Mesa 22 draws nothing for color copies, zeros for depth-stencil ones;
     * tessera draws zeros for both.) */
    glRasterPos2i(4, 4);
    glPixelZoom(2, 2);
    glCopyPixels(-3, -2, 6, 5, GL_COLOR);
    glPixelZoom(1, 1);
    capi_save_framebuffer("copy_outside_color", W, H);
    if (capi_is_tessera()) {
        GLuint one = 0x80000010u, got = 0;
        glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
        glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
        glPixelTransferi(GL_INDEX_OFFSET, 9);
        glRasterPos2i(0, 0);
        glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &one);
        glPixelTransferf(GL_DEPTH_SCALE, 1);
        glPixelTransferf(GL_DEPTH_BIAS, 0);
        glPixelTransferi(GL_INDEX_OFFSET, 0);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &got);
        /* depth 0x800000/0xffffff * 0.5 + 0.25 = 0.5000000298 -> 0x800000; stencil 0x10 + 9 */
        capi_check(got == 0x80000019u, "transferred depth-stencil 0x%08x", got);
    }

    /* Errors: a depth-stencil copy needs both buffers; a wrong type for the format. */
    glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, image);
    capi_expect_error(GL_INVALID_ENUM, "depth_stencil with unsigned byte");
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 0, 0, W, H, NULL);
    glCopyPixels(0, 0, 1, 1, GL_DEPTH_STENCIL);
    capi_expect_error(GL_INVALID_OPERATION, "copy depth_stencil without stencil");
    glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    capi_expect_error(GL_INVALID_OPERATION, "draw depth_stencil without stencil");
    return capi_finish();
}
