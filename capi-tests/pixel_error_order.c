/* Which error a pixel transfer with several faults reports, compared with Mesa 22 for every
 * pair of the GL 1.x formats (plus an unknown one) and types (plus an unknown one) in
 * glDrawPixels, glReadPixels, glTexImage2D, glTexSubImage2D and glGetTexImage, and for
 * glCopyTexImage's argument errors. The GL 2.1 spec names the errors but not their order;
 * tessera follows Mesa's: a type's own rules first (a packed type with a format it does
 * not take is GL_INVALID_OPERATION even when the format is unknown: piglit's draw-pixels
 * expects that), then the format. glCopyTexImage takes no legacy internal format 1-4 and
 * reports an unknown one as GL_INVALID_ENUM (its internalformat is an enum; piglit's
 * copyteximage), after the border and before the sizes.
 *
 * Left out of the comparison, where tessera knowingly differs: formats of extensions
 * tessera does not have (GL_ABGR_EXT, GL_RG, the integer formats), which Mesa takes;
 * glGetTexImage with GL_COLOR_INDEX, which Mesa 22 accepts though GL 2.1 (§6.1.4) lists no
 * index format there (tessera: GL_INVALID_ENUM, checked on tessera only); GL_STENCIL_INDEX
 * with GL_BITMAP in glDrawPixels/glReadPixels and glGetTexImage of stencil formats, on
 * which Mesa 22 loops or crashes.
 */
#include "common.h"

static unsigned char pixels[64 * 64 * 16];

static const GLenum formats[] = {GL_COLOR_INDEX, GL_STENCIL_INDEX, GL_DEPTH_COMPONENT, GL_RED, GL_GREEN,
                                 GL_BLUE, GL_ALPHA, GL_RGB, GL_BGR, GL_RGBA, GL_BGRA, GL_LUMINANCE,
                                 GL_LUMINANCE_ALPHA, GL_DEPTH_STENCIL, 0x1234};
static const GLenum types[] = {GL_BITMAP,
                               GL_BYTE,
                               GL_UNSIGNED_BYTE,
                               GL_SHORT,
                               GL_UNSIGNED_SHORT,
                               GL_INT,
                               GL_UNSIGNED_INT,
                               GL_FLOAT,
                               GL_HALF_FLOAT,
                               GL_DOUBLE,
                               GL_UNSIGNED_BYTE_3_3_2,
                               GL_UNSIGNED_BYTE_2_3_3_REV,
                               GL_UNSIGNED_SHORT_5_6_5,
                               GL_UNSIGNED_SHORT_5_6_5_REV,
                               GL_UNSIGNED_SHORT_4_4_4_4,
                               GL_UNSIGNED_SHORT_4_4_4_4_REV,
                               GL_UNSIGNED_SHORT_5_5_5_1,
                               GL_UNSIGNED_SHORT_1_5_5_5_REV,
                               GL_UNSIGNED_INT_8_8_8_8,
                               GL_UNSIGNED_INT_8_8_8_8_REV,
                               GL_UNSIGNED_INT_10_10_10_2,
                               GL_UNSIGNED_INT_2_10_10_10_REV,
                               GL_UNSIGNED_INT_24_8,
                               0x1234};

enum op { DRAW, READ, TEX_IMAGE, TEX_SUB_IMAGE, GET_TEX_IMAGE, OPS };
static const char *const op_names[] = {"draw_pixels", "read_pixels", "tex_image", "tex_sub_image", "get_tex_image"};

/* The error of one call (after clearing earlier ones); -1 when the pair is left out. */
static int run(enum op op, GLenum format, GLenum type)
{
    int stencil_bitmap = format == GL_STENCIL_INDEX && type == GL_BITMAP;
    if ((op == DRAW || op == READ) && stencil_bitmap)
        return -1;
    if (op == GET_TEX_IMAGE && (format == GL_STENCIL_INDEX || format == GL_DEPTH_STENCIL || format == GL_COLOR_INDEX))
        return -1;
    while (glGetError() != GL_NO_ERROR)
        ;
    switch (op) {
    case DRAW: glDrawPixels(2, 2, format, type, pixels); break;
    case READ: glReadPixels(0, 0, 2, 2, format, type, pixels); break;
    case TEX_IMAGE: glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, format, type, pixels); break;
    case TEX_SUB_IMAGE: glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, format, type, pixels); break;
    case GET_TEX_IMAGE: glGetTexImage(GL_TEXTURE_2D, 0, format, type, pixels); break;
    default: break;
    }
    return (int)glGetError();
}

/* A call's error checked against the expected one (and printed for the comparison). */
#define EXPECT(expected, call)                                                                   \
    do {                                                                                         \
        while (glGetError() != GL_NO_ERROR)                                                      \
            ;                                                                                    \
        call;                                                                                    \
        GLenum got = glGetError();                                                               \
        capi_check(got == (expected), "%s: 0x%x, expected 0x%x", #call, got, (GLenum)(expected)); \
        capi_value(#call, "0x%x", got);                                                          \
    } while (0)

/* As EXPECT, without the VALUE line (for checks of one implementation). */
#define CHECK(expected, call)                                                                    \
    do {                                                                                         \
        while (glGetError() != GL_NO_ERROR)                                                      \
            ;                                                                                    \
        call;                                                                                    \
        GLenum got = glGetError();                                                               \
        capi_check(got == (expected), "%s: 0x%x, expected 0x%x", #call, got, (GLenum)(expected)); \
    } while (0)

int main(void)
{
    static unsigned char buffer[16 * 16 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    capi_check(ctx && OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 16, 16), "bind");
    /* A texture image for glTexSubImage2D and glGetTexImage. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);

    for (int op = 0; op < OPS; op++) {
        int counts[3] = {0, 0, 0};
        for (size_t f = 0; f < sizeof formats / sizeof *formats; f++)
            for (size_t t = 0; t < sizeof types / sizeof *types; t++) {
                int error = run((enum op)op, formats[f], types[t]);
                if (error < 0)
                    continue;
                counts[error == GL_INVALID_ENUM ? 0 : error == GL_INVALID_OPERATION ? 1 : 2]++;
                capi_value(op_names[op], "format=0x%x type=0x%x error=0x%x", formats[f], types[t], error);
            }
        capi_value(op_names[op], "enum=%d operation=%d other=%d", counts[0], counts[1], counts[2]);
    }

    /* The pairs piglit's draw-pixels checks: a packed type's format rule comes first. */
    EXPECT(GL_INVALID_OPERATION, glDrawPixels(2, 2, 0x1234, GL_UNSIGNED_SHORT_4_4_4_4, pixels));
    EXPECT(GL_INVALID_OPERATION, glDrawPixels(2, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE_3_3_2, pixels));
    EXPECT(GL_INVALID_ENUM, glDrawPixels(2, 2, 0x1234, GL_UNSIGNED_BYTE, pixels));
    EXPECT(GL_INVALID_ENUM, glDrawPixels(2, 2, GL_RGBA, GL_BITMAP, pixels));
    EXPECT(GL_INVALID_OPERATION, glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, 0x1234, GL_UNSIGNED_INT_8_8_8_8,
                                              pixels));
    EXPECT(GL_INVALID_ENUM, glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_STENCIL_INDEX, GL_DOUBLE, pixels));
    EXPECT(GL_NO_ERROR, glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_COLOR_INDEX, GL_HALF_FLOAT, pixels));

    /* glGetTexImage has no index formats (GL 2.1 §6.1.4); Mesa 22 accepts GL_COLOR_INDEX. */
    if (capi_is_tessera()) {
        CHECK(GL_INVALID_ENUM, glGetTexImage(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, pixels));
        CHECK(GL_INVALID_ENUM, glGetTexImage(GL_TEXTURE_2D, 0, GL_STENCIL_INDEX, GL_FLOAT, pixels));
        CHECK(GL_INVALID_OPERATION, glGetTexImage(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, GL_UNSIGNED_SHORT_5_6_5, pixels));
        CHECK(GL_INVALID_ENUM, glGetTexImage(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, GL_BITMAP, pixels));
    }

    /* glTexImage: border and sizes, then format and type, then the internal format. */
    EXPECT(GL_INVALID_VALUE, glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 7, 0x1234, GL_UNSIGNED_BYTE, NULL));
    EXPECT(GL_INVALID_VALUE, glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, 0x1234, GL_UNSIGNED_BYTE, NULL));
    EXPECT(GL_INVALID_ENUM, glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 4, 4, 0, 0x1234, GL_UNSIGNED_BYTE, NULL));
    EXPECT(GL_INVALID_VALUE, glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    EXPECT(GL_NO_ERROR, glTexImage2D(GL_TEXTURE_2D, 0, 3, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));

    /* glCopyTexImage: target, level, border, internal format (no 1-4), sizes. */
    for (GLint internal = 1; internal <= 4; internal++) {
        EXPECT(GL_INVALID_ENUM, glCopyTexImage2D(GL_TEXTURE_2D, 0, internal, 0, 0, 4, 4, 0));
        EXPECT(GL_INVALID_ENUM, glCopyTexImage1D(GL_TEXTURE_1D, 0, internal, 0, 0, 4, 0));
    }
    EXPECT(GL_INVALID_ENUM, glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 0, 0, 4, 4, 0));
    EXPECT(GL_INVALID_VALUE, glCopyTexImage2D(GL_TEXTURE_2D, -1, 1, 0, 0, 4, 4, 0));
    EXPECT(GL_INVALID_VALUE, glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 0, 0, 4, 4, 5));
    EXPECT(GL_INVALID_ENUM, glCopyTexImage2D(GL_TEXTURE_2D, 0, 1, 0, 0, -4, 4, 0));
    EXPECT(GL_INVALID_VALUE, glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -4, 4, 0));
    EXPECT(GL_INVALID_ENUM, glCopyTexImage2D(0x1234, 0, 1, 0, 0, 4, 4, 0));
    EXPECT(GL_NO_ERROR, glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 0));

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
