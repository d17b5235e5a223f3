/* glDrawPixels of GL_COLOR_INDEX in RGBA mode: indices of several types (and a bitmap)
 * converted through GL_PIXEL_MAP_I_TO_[RGBA] (each index masked to its table's size).
 * GL_MAP_COLOR is on: its I_TO_I lookup is only for indices that stay indices (GL 2.1
 * section 3.6.5), never for these RGBA groups, and the RGBA-to-RGBA lookups (default tables of
 * one zero entry) apply to RGBA groups only, not to these. GL_INDEX_SHIFT/GL_INDEX_OFFSET are
 * applied by tessera as the specification says, but Mesa 22 ignores them for this format, so
 * they are not compared here. */
#include "common.h"

#define W 32
#define H 32

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    GLfloat r[16], g[16], b[8], a[4], ii[16];
    for (int i = 0; i < 16; i++) {
        r[i] = i / 15.0f;
        g[i] = (15 - i) / 15.0f;
        ii[i] = (float)((i * 5) % 16);
    }
    for (int i = 0; i < 8; i++)
        b[i] = (i % 3) / 2.0f;
    for (int i = 0; i < 4; i++)
        a[i] = 1.0f - i * 0.25f;
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 16, r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 16, g);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 8, b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, a);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 16, ii);
    glClearColor(0.1f, 0.2f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    GLubyte ub[8 * 6];
    GLshort ss[8 * 6];
    GLfloat ff[8 * 6];
    for (int i = 0; i < 48; i++) {
        ub[i] = (GLubyte)(i * 7);
        ss[i] = (GLshort)(i * 3 - 20);
        ff[i] = i * 0.75f;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glRasterPos2i(1, 1);
    glDrawPixels(8, 6, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(11, 1);
    glDrawPixels(8, 6, GL_COLOR_INDEX, GL_SHORT, ss);
    glRasterPos2i(21, 1);
    glDrawPixels(8, 6, GL_COLOR_INDEX, GL_FLOAT, ff);
    static const GLubyte bits[6] = {0xa5, 0x3c, 0xff, 0x00, 0x81, 0x7e};
    glRasterPos2i(4, 20);
    glPixelZoom(2, 1);
    glDrawPixels(8, 6, GL_COLOR_INDEX, GL_BITMAP, bits);
    glPixelZoom(1, 1);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    capi_expect_error(GL_NO_ERROR, "color index draws");
    capi_save_framebuffer("color_index", W, H);
    return capi_finish();
}
