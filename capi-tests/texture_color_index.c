/* Texture images given as GL_COLOR_INDEX data (GL 1.0): each index is shifted and offset
 * (GL_INDEX_SHIFT, GL_INDEX_OFFSET), then looks up the GL_PIXEL_MAP_I_TO_R/G/B/A tables,
 * masked to their size. Unsigned byte, short, float and GL_BITMAP data (GL_UNPACK_LSB_FIRST,
 * skipped pixels), a sub-image, and the errors; the texels read back with glGetTexImage are
 * compared with Mesa. */
#include "common.h"

static void save_texture(const char *name, int w, int h)
{
    static GLubyte texels[16 * 16 * 4];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    capi_save_image(name, w, h, 4, CAPI_U8, texels);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 16, 16, NULL);
    const GLfloat r[4] = {0, 1, 0.5f, 0.25f}, g[4] = {0.75f, 0, 1, 0.5f}, b[4] = {1, 0.2f, 0, 0.6f},
                  a[4] = {1, 1, 0.5f, 0};
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, g);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, a);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    GLubyte bytes[16];
    for (int i = 0; i < 16; i++)
        bytes[i] = (GLubyte)(i * 5);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, bytes);
    capi_expect_error(GL_NO_ERROR, "unsigned byte indices");
    save_texture("ubyte", 4, 4);

    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 1);
    GLshort shorts[16];
    for (int i = 0; i < 16; i++)
        shorts[i] = (GLshort)(i - 8);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_COLOR_INDEX, GL_SHORT, shorts);
    save_texture("short_shift_offset", 4, 4);
    glPixelTransferi(GL_INDEX_SHIFT, -1);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    GLfloat floats[16];
    for (int i = 0; i < 16; i++)
        floats[i] = i * 0.75f;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_FLOAT, floats);
    save_texture("float_shift", 4, 4);
    glPixelTransferi(GL_INDEX_SHIFT, 0);

    /* Bitmaps: 8x4 bits, one byte a row (index 1 where a bit is set) */
    const GLubyte bits[8] = {0xb5, 0x3c, 0x0f, 0xf0, 0x81, 0x7e, 0xaa, 0x55};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
    capi_expect_error(GL_NO_ERROR, "bitmap indices");
    save_texture("bitmap", 8, 4);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
    save_texture("bitmap_lsb_first", 8, 4);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    /* Rows of two bytes after 3 skipped pixels: Mesa 22 reads other bits than GL 2.1
     * §3.6.4 places (its texels hold indices a bitmap cannot give), so tessera's texels
     * are checked against the bits directly. */
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 16);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    if (capi_is_tessera()) {
        GLubyte texels[8 * 4 * 4];
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        for (int y = 0; y < 4; y++)
            for (int x = 0; x < 8; x++) {
                int bit = 3 + x, set = (bits[2 * y + bit / 8] >> (7 - bit % 8)) & 1;
                capi_check(texels[4 * (8 * y + x)] == (set ? 255 : 0) && texels[4 * (8 * y + x) + 1] == (set ? 0 : 191),
                           "skipped bitmap texel %d,%d", x, y);
            }
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_COLOR_INDEX, GL_BITMAP, bits);

    /* A sub-image of indices into an RGBA image */
    const GLubyte sub[4] = {3, 2, 1, 0};
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 1, 2, 2, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, sub);
    capi_expect_error(GL_NO_ERROR, "index sub-image");
    save_texture("sub_image", 8, 4);

    /* Errors: packed types, depth textures, and reading indices back */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE_3_3_2, bytes);
    capi_expect_error(GL_INVALID_OPERATION, "packed index type");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, bytes);
    capi_expect_error(GL_INVALID_OPERATION, "indices into a depth texture");
    return capi_finish();
}
