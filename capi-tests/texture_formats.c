/* Texture images in every GL 1.5 internal format and every client format and type: each is
 * uploaded (under several glPixelStore unpack layouts), read back with glGetTexImage and
 * drawn, and the bytes and pictures compared with Mesa. Formats of more than 8 bits per
 * channel are read back as 8-bit values (tessera stores them with 8 bits). */
#include "common.h"

#define W 16
#define H 16

static unsigned rng = 777;
static unsigned char rnd(void)
{
    rng = rng * 1103515245u + 12345u;
    return (unsigned char)(rng >> 16);
}

/* Draws the bound 2D texture over the whole framebuffer with GL_REPLACE, texel for pixel. */
static void draw_texture(void)
{
    glClearColor(0.5f, 0.25f, 0.75f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(-1, -1);
    glTexCoord2f(1, 0);
    glVertex2f(1, -1);
    glTexCoord2f(1, 1);
    glVertex2f(1, 1);
    glTexCoord2f(0, 1);
    glVertex2f(-1, 1);
    glEnd();
    glDisable(GL_TEXTURE_2D);
}

static const struct {
    GLenum format;
    const char *name;
} internal_formats[] = {
    {1, "1"}, {2, "2"}, {3, "3"}, {4, "4"},
    {GL_ALPHA, "alpha"}, {GL_ALPHA4, "alpha4"}, {GL_ALPHA8, "alpha8"}, {GL_ALPHA12, "alpha12"},
    {GL_ALPHA16, "alpha16"}, {GL_LUMINANCE, "luminance"}, {GL_LUMINANCE4, "luminance4"},
    {GL_LUMINANCE8, "luminance8"}, {GL_LUMINANCE12, "luminance12"}, {GL_LUMINANCE16, "luminance16"},
    {GL_LUMINANCE_ALPHA, "luminance_alpha"}, {GL_LUMINANCE4_ALPHA4, "l4a4"}, {GL_LUMINANCE6_ALPHA2, "l6a2"},
    {GL_LUMINANCE8_ALPHA8, "l8a8"}, {GL_LUMINANCE12_ALPHA4, "l12a4"}, {GL_LUMINANCE12_ALPHA12, "l12a12"},
    {GL_LUMINANCE16_ALPHA16, "l16a16"}, {GL_INTENSITY, "intensity"}, {GL_INTENSITY4, "intensity4"},
    {GL_INTENSITY8, "intensity8"}, {GL_INTENSITY12, "intensity12"}, {GL_INTENSITY16, "intensity16"},
    {GL_RGB, "rgb"}, {GL_R3_G3_B2, "r3g3b2"}, {GL_RGB4, "rgb4"}, {GL_RGB5, "rgb5"}, {GL_RGB8, "rgb8"},
    {GL_RGB10, "rgb10"}, {GL_RGB12, "rgb12"}, {GL_RGB16, "rgb16"}, {GL_RGBA, "rgba"}, {GL_RGBA2, "rgba2"},
    {GL_RGBA4, "rgba4"}, {GL_RGB5_A1, "rgb5a1"}, {GL_RGBA8, "rgba8"}, {GL_RGB10_A2, "rgb10a2"},
    {GL_RGBA12, "rgba12"}, {GL_RGBA16, "rgba16"},
};

/* Every internal format from the same RGBA bytes: read back as RGBA bytes and drawn. */
static void internal_format_images(void)
{
    unsigned char img[W * H * 4], back[W * H * 4];
    for (int i = 0; i < W * H * 4; i++)
        img[i] = rnd();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (unsigned f = 0; f < sizeof internal_formats / sizeof internal_formats[0]; f++) {
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal_formats[f].format, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
        capi_expect_error(GL_NO_ERROR, internal_formats[f].name);
        GLint internal;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
        capi_value(internal_formats[f].name, "internal 0x%x", internal);
        char name[64];
        /* Formats stored with more than 8 bits in Mesa read back the same as 8-bit bytes. */
        memset(back, 0, sizeof back);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
        snprintf(name, sizeof name, "get_%s", internal_formats[f].name);
        capi_save_image(name, W, H, 4, CAPI_U8, back);
        draw_texture();
        snprintf(name, sizeof name, "draw_%s", internal_formats[f].name);
        capi_save_framebuffer(name, W, H);
    }
}

static const struct {
    GLenum format, type;
    int bytes; /* per pixel */
    const char *name;
} client[] = {
    {GL_RGBA, GL_UNSIGNED_BYTE, 4, "rgba_ubyte"}, {GL_BGRA, GL_UNSIGNED_BYTE, 4, "bgra_ubyte"},
    {GL_RGB, GL_UNSIGNED_BYTE, 3, "rgb_ubyte"}, {GL_BGR, GL_UNSIGNED_BYTE, 3, "bgr_ubyte"},
    {GL_RED, GL_UNSIGNED_BYTE, 1, "red_ubyte"}, {GL_GREEN, GL_UNSIGNED_BYTE, 1, "green_ubyte"},
    {GL_BLUE, GL_UNSIGNED_BYTE, 1, "blue_ubyte"}, {GL_ALPHA, GL_UNSIGNED_BYTE, 1, "alpha_ubyte"},
    {GL_LUMINANCE, GL_UNSIGNED_BYTE, 1, "lum_ubyte"}, {GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, 2, "la_ubyte"},
    {GL_RGBA, GL_BYTE, 4, "rgba_byte"}, {GL_RGBA, GL_UNSIGNED_SHORT, 8, "rgba_ushort"},
    {GL_RGBA, GL_SHORT, 8, "rgba_short"}, {GL_RGBA, GL_UNSIGNED_INT, 16, "rgba_uint"},
    {GL_RGBA, GL_INT, 16, "rgba_int"}, {GL_RGBA, GL_FLOAT, 16, "rgba_float"},
    {GL_RGB, GL_UNSIGNED_BYTE_3_3_2, 1, "332"}, {GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, 1, "233rev"},
    {GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 2, "565"}, {GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, 2, "565rev"},
    {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 2, "4444"}, {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, "4444rev"},
    {GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 2, "5551"}, {GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, "1555rev"},
    {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, 4, "8888"}, {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, 4, "8888rev"},
    {GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, 4, "1010102"}, {GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, 4, "2101010rev"},
};

/* Random client data in each format/type (floats in [0, 1]), uploaded to RGBA8 under an
 * unpack layout, then read back as RGBA bytes and in the same format/type. */
static void client_formats(void)
{
    static unsigned char data[4096], back[4096];
    const int w = 5, h = 3;
    for (unsigned c = 0; c < sizeof client / sizeof client[0]; c++) {
        for (unsigned i = 0; i < sizeof data; i++)
            data[i] = rnd();
        if (client[c].type == GL_FLOAT)
            for (unsigned i = 0; i < sizeof data / 4; i++)
                ((float *)data)[i] = (float)(rnd() % 101) / 100.0f;
        for (int layout = 0; layout < 3; layout++) {
            glPixelStorei(GL_UNPACK_ALIGNMENT, layout == 1 ? 8 : 1);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, layout == 2 ? 9 : 0);
            glPixelStorei(GL_UNPACK_SKIP_ROWS, layout == 2 ? 2 : 0);
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, layout == 2 ? 3 : 0);
            glPixelStorei(GL_UNPACK_SWAP_BYTES, layout == 1);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, client[c].format, client[c].type, data);
            capi_expect_error(GL_NO_ERROR, client[c].name);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            memset(back, 0, sizeof back);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
            char name[64];
            snprintf(name, sizeof name, "up_%s_%d", client[c].name, layout);
            capi_save_image(name, w, h, 4, CAPI_U8, back);
        }
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        /* Readback in the client format itself, from an RGBA8 texture of known bytes. */
        unsigned char rgba[5 * 3 * 4];
        for (unsigned i = 0; i < sizeof rgba; i++)
            rgba[i] = rnd();
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        memset(back, 0, sizeof back);
        glGetTexImage(GL_TEXTURE_2D, 0, client[c].format, client[c].type, back);
        char name[64];
        snprintf(name, sizeof name, "get_as_%s", client[c].name);
        capi_save_image(name, w * h * client[c].bytes, 1, 1, CAPI_U8, back);
    }
}

/* Depth formats: upload as float and unsigned int, read back as float, drawn as luminance. */
static void depth_formats(void)
{
    static const GLenum formats[] = {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24,
                                     GL_DEPTH_COMPONENT32};
    float depth[W * H], back[W * H];
    for (int i = 0; i < W * H; i++)
        depth[i] = (float)i / (W * H - 1);
    for (int f = 0; f < 4; f++) {
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)formats[f], W, H, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
        capi_expect_error(GL_NO_ERROR, "depth upload");
        GLint bits;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &bits);
        capi_value("depth_bits", "%d: %d", f, bits);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
        char name[64];
        snprintf(name, sizeof name, "depth_%d", f);
        capi_save_image(name, W, H, 1, CAPI_F32, back);
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, f % 2 ? GL_INTENSITY : GL_LUMINANCE);
        draw_texture();
        snprintf(name, sizeof name, "depth_draw_%d", f);
        capi_save_framebuffer(name, W, H);
    }
    unsigned short d16[W * H];
    for (int i = 0; i < W * H; i++)
        d16[i] = (unsigned short)(i * 257);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, W, H, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, d16);
    unsigned short b16[W * H];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, b16);
    capi_check(memcmp(d16, b16, sizeof d16) == 0, "16-bit depth round trip");
}

/* Sub-images, 3D images with image height and skip images, and 1D. */
static void sub_images(void)
{
    unsigned char img[8 * 8 * 4], sub[64 * 4], back[8 * 8 * 4];
    for (int i = 0; i < (int)sizeof img; i++)
        img[i] = rnd();
    for (int i = 0; i < (int)sizeof sub; i++)
        sub[i] = rnd();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 5);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 3, 4, GL_BGRA, GL_UNSIGNED_BYTE, sub);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 6, 0, 2, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, sub);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    capi_save_image("sub2d", 8, 8, 4, CAPI_U8, back);

    unsigned char vol[4 * 4 * 6 * 4];
    for (int i = 0; i < (int)sizeof vol; i++)
        vol[i] = rnd();
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 5);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 2, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, sub);
    unsigned char vback[4 * 4 * 3 * 4];
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, vback);
    capi_save_image("tex3d", 4, 12, 4, CAPI_U8, vback);

    glTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE_ALPHA, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexSubImage1D(GL_TEXTURE_1D, 0, 3, 2, GL_ALPHA, GL_UNSIGNED_BYTE, sub);
    unsigned char back1[8 * 2];
    glGetTexImage(GL_TEXTURE_1D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, back1);
    capi_save_image("tex1d_la", 8, 1, 2, CAPI_U8, back1);
    capi_expect_error(GL_NO_ERROR, "sub images");
}

/* glCopyTexImage2D / glCopyTexSubImage2D from a drawn framebuffer, partly outside it. */
static void copies(void)
{
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 1);
    glVertex2f(-1, -1);
    glColor4f(0, 1, 0, 0.5f);
    glVertex2f(1, -1);
    glColor4f(0, 0, 1, 0);
    glVertex2f(0, 1);
    glEnd();
    glColor4f(1, 1, 1, 1);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 3, 8, 8, 0);
    unsigned char back[8 * 8 * 4];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    capi_save_image("copy", 8, 8, 4, CAPI_U8, back);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 10, 10, 4, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    capi_save_image("copy_sub", 8, 8, 4, CAPI_U8, back);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 0, 0, 16, 16, 0);
    unsigned char lum[16 * 16];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    capi_save_image("copy_luminance", 16, 16, 1, CAPI_U8, lum);
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 3, 5, 8, 0);
    unsigned char row[8 * 4];
    glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, row);
    capi_save_image("copy1d", 8, 1, 4, CAPI_U8, row);
    capi_expect_error(GL_NO_ERROR, "copies");
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 0, 0, W, H, NULL);
    internal_format_images();
    client_formats();
    depth_formats();
    sub_images();
    copies();
    return capi_finish();
}
