/* glReadPixels conversions, value by value: every 8-bit value, every 5/6-bit value of a
 * 5_6_5 buffer, a spread of 16-bit and float values (rounding boundaries, the values where
 * Mesa's two-step conversions differ from a direct one), every stencil value and a spread of
 * 16- and 24-bit depths, read in every type. Each pixel holds its own value (scissored
 * 1×1 clears; depth uses full clears, which Mesa rounds exactly), so one read converts them
 * all. A VALUE line per source × format × type carries an FNV-1a hash of the bytes; the bytes
 * are saved as one image per source.
 *
 * As in readpixels_matrix.c: float 1.0 → GL_UNSIGNED_INT/GL_INT overflows in Mesa 22 (0,
 * INT_MIN) where it converts through float; tessera's saturated words are mapped to Mesa's
 * before hashing. Float buffers are read with GL_CLAMP_READ_COLOR = GL_TRUE. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <stdint.h>

/* At most this many reads per source. */
#define MAX_ROWS 64

struct named {
    GLenum e;
    const char *name;
};

static const struct named array_types[] = {
    {GL_UNSIGNED_BYTE, "UNSIGNED_BYTE"}, {GL_BYTE, "BYTE"}, {GL_UNSIGNED_SHORT, "UNSIGNED_SHORT"},
    {GL_SHORT, "SHORT"},                 {GL_UNSIGNED_INT, "UNSIGNED_INT"}, {GL_INT, "INT"},
    {GL_FLOAT, "FLOAT"},                 {GL_HALF_FLOAT, "HALF_FLOAT"},
};

static const struct named packed_types[] = {
    {GL_UNSIGNED_BYTE_3_3_2, "3_3_2"},
    {GL_UNSIGNED_BYTE_2_3_3_REV, "2_3_3_REV"},
    {GL_UNSIGNED_SHORT_5_6_5, "5_6_5"},
    {GL_UNSIGNED_SHORT_5_6_5_REV, "5_6_5_REV"},
    {GL_UNSIGNED_SHORT_4_4_4_4, "4_4_4_4"},
    {GL_UNSIGNED_SHORT_4_4_4_4_REV, "4_4_4_4_REV"},
    {GL_UNSIGNED_SHORT_5_5_5_1, "5_5_5_1"},
    {GL_UNSIGNED_SHORT_1_5_5_5_REV, "1_5_5_5_REV"},
    {GL_UNSIGNED_INT_8_8_8_8, "8_8_8_8"},
    {GL_UNSIGNED_INT_8_8_8_8_REV, "8_8_8_8_REV"},
    {GL_UNSIGNED_INT_10_10_10_2, "10_10_10_2"},
    {GL_UNSIGNED_INT_2_10_10_10_REV, "2_10_10_10_REV"},
};

#define N_ARRAY (int)(sizeof array_types / sizeof array_types[0])
#define N_PACKED (int)(sizeof packed_types / sizeof packed_types[0])

/* The reads of the current source, one image row each, `row_bytes` wide. */
static unsigned char *image;
static size_t row_bytes;
static int image_rows;

static void begin_source(int w, int h)
{
    row_bytes = (size_t)w * h * 16 + 16;
    image = malloc(row_bytes * MAX_ROWS);
    image_rows = 0;
}

static uint64_t fnv1a(const unsigned char *p, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

/* Whether GL_PACK_SWAP_BYTES is on for the current reads. */
static int swapped;

static uint32_t swap32(uint32_t w)
{
    return (w >> 24) | ((w >> 8) & 0xff00) | ((w << 8) & 0xff0000) | (w << 24);
}

/* Mesa 22's overflowed 32-bit conversion of 1.0 (see the header), applied to tessera's bytes. */
static void as_mesa_overflow(unsigned char *buf, size_t n, GLenum type)
{
    for (size_t i = 0; i + 4 <= n; i += 4) {
        uint32_t w;
        memcpy(&w, buf + i, 4);
        if (swapped)
            w = swap32(w);
        if (type == GL_UNSIGNED_INT && w == 0xffffffffu)
            w = 0;
        else if (type == GL_INT && w == 0x7fffffffu)
            w = 0x80000000u;
        if (swapped)
            w = swap32(w);
        memcpy(buf + i, &w, 4);
    }
}

static size_t bytes_of(GLenum format, GLenum type, int pixels)
{
    int comps = format == GL_RGBA || format == GL_BGRA ? 4 : format == GL_RGB ? 3 : format == GL_LUMINANCE_ALPHA ? 2 : 1;
    switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE:
        return (size_t)pixels * comps;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
    case GL_HALF_FLOAT:
        return (size_t)pixels * comps * 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT:
        return (size_t)pixels * comps * 4;
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
        return (size_t)pixels;
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
    case GL_UNSIGNED_INT_24_8:
        return (size_t)pixels * 4;
    default:
        return (size_t)pixels * 2;
    }
}

/* Reads the w × h window as format/type (tightly packed), hashes it and keeps it for the
 * image. `float_path`: the source converts through float in Mesa (see the header). */
static void read_all(const char *source, int w, int h, GLenum format, const char *fname, GLenum type,
                     const char *tname, int float_path)
{
    unsigned char *buf = image + row_bytes * image_rows;
    memset(buf, 0xa5, row_bytes);
    glReadPixels(0, 0, w, h, format, type, buf);
    GLenum err = glGetError();
    capi_check(err == GL_NO_ERROR, "%s %s %s: error 0x%x", source, fname, tname, err);
    size_t n = bytes_of(format, type, w * h);
    if (capi_is_tessera() && float_path && (type == GL_UNSIGNED_INT || type == GL_INT))
        as_mesa_overflow(buf, n, type);
    capi_check(buf[n] == 0xa5, "%s %s %s wrote past the image", source, fname, tname);
    capi_value("read", "%s %s %s fnv=%016llx", source, fname, tname, (unsigned long long)fnv1a(buf, n));
    if (image_rows < MAX_ROWS - 1)
        image_rows++;
}

static void save(const char *source)
{
    char name[64];
    snprintf(name, sizeof name, "readpixels_values_%s", source);
    capi_save_image(name, (int)row_bytes, image_rows, 1, CAPI_U8, image);
    free(image);
}

/* Reads a color source in every array type as RGBA, BGRA, LUMINANCE_ALPHA and ALPHA, and in
 * every packed type. */
static void read_color_source(const char *source, int w, int h, int float_source)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    static const struct named formats[] = {
        {GL_RGBA, "RGBA"}, {GL_BGRA, "BGRA"}, {GL_LUMINANCE_ALPHA, "LUMINANCE_ALPHA"}, {GL_RED, "RED"}};
    for (int f = 0; f < 4; f++)
        for (int t = 0; t < N_ARRAY; t++)
            read_all(source, w, h, formats[f].e, formats[f].name, array_types[t].e, array_types[t].name,
                     float_source || formats[f].e == GL_LUMINANCE_ALPHA);
    for (int t = 0; t < N_PACKED; t++) {
        GLenum type = packed_types[t].e;
        int rgb = type == GL_UNSIGNED_BYTE_3_3_2 || type == GL_UNSIGNED_BYTE_2_3_3_REV ||
                  type == GL_UNSIGNED_SHORT_5_6_5 || type == GL_UNSIGNED_SHORT_5_6_5_REV;
        read_all(source, w, h, rgb ? GL_RGB : GL_RGBA, rgb ? "RGB" : "RGBA", type, packed_types[t].name, float_source);
    }
    /* Byte-swapped reads of every element size. */
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    swapped = 1;
    read_all(source, w, h, GL_RGBA, "RGBA", GL_UNSIGNED_SHORT, "UNSIGNED_SHORT/swapped", float_source);
    read_all(source, w, h, GL_RGBA, "RGBA", GL_INT, "INT/swapped", float_source);
    read_all(source, w, h, GL_RGBA, "RGBA", GL_FLOAT, "FLOAT/swapped", float_source);
    read_all(source, w, h, GL_RGBA, "RGBA", GL_UNSIGNED_SHORT_4_4_4_4_REV, "4_4_4_4_REV/swapped", float_source);
    read_all(source, w, h, GL_BGRA, "BGRA", GL_UNSIGNED_INT_2_10_10_10_REV, "2_10_10_10_REV/swapped", float_source);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    swapped = 0;
}

/* One pixel per value: pixel i of a w-wide window gets color(i). */
static void clear_pixels(int w, int count, void (*color)(int, float[4]))
{
    glEnable(GL_SCISSOR_TEST);
    for (int i = 0; i < count; i++) {
        float c[4];
        color(i, c);
        glScissor(i % w, i / w, 1, 1);
        glClearColor(c[0], c[1], c[2], c[3]);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
}

static void color8(int i, float c[4])
{
    /* Every value in every channel, in different pixels per channel. */
    c[0] = i / 255.0f;
    c[1] = (255 - i) / 255.0f;
    c[2] = ((i * 7) & 255) / 255.0f;
    c[3] = ((i * 13 + 5) & 255) / 255.0f;
}

/* 16-bit values: edges, Mesa's double-rounding cases (0x124a: 3-bit 1 directly, 0 through
 * 8 bits; 0x0422: 5-bit; 0x0209: 6-bit), halves and a pseudo-random spread. */
static const uint16_t special16[] = {0,      1,      2,      0x7f,   0x80,   0x7fff, 0x8000, 0x8001, 0xfffe, 0xffff,
                                     0x124a, 0x124b, 0x0422, 0x0423, 0x0209, 0x020a, 0x5555, 0xaaaa, 0x0101, 0x8080,
                                     0x00ff, 0xff00, 0x3fff, 0xc000, 0x0808, 0x4924, 0x2492, 0x6db6, 0x9249, 0xdb6d};

static uint16_t value16(int i)
{
    int n = (int)(sizeof special16 / sizeof special16[0]);
    if (i < n)
        return special16[i];
    uint32_t x = (uint32_t)i * 2654435761u;
    return (uint16_t)(x >> 16);
}

static void color16(int i, float c[4])
{
    for (int k = 0; k < 4; k++)
        c[k] = value16(i * 4 + k) / 65535.0f;
}

/* Float values: boundaries of the 8-bit and 16-bit roundings, halves, tiny and huge values,
 * negatives (clamped by the read), values just below 1. (Not -0.0: Mesa's drawn clear
 * stores it as +0.0.) */
static float valuef(int i)
{
    static const float special[] = {0.0f,         1.0f,          0.5f,        0.25f,       -1.0f,      2.0f,
                                    1e-8f,        1e-40f,        0.99999994f, 0.9999f,     0.49999997f, 0.50000006f,
                                    0.5f / 255,   1.5f / 255,    127.5f / 255, 254.5f / 255, 0.5f / 65535, 32767.5f / 65535,
                                    1.0f / 3,     2.0f / 3,      0.1f,        0.2f,        0.3f,       0.7f,
                                    6.1e-5f,      6.0975e-5f,    0.00048828125f, 0.33325195f, 1.0f / 1023, 0.5f / 1023};
    int n = (int)(sizeof special / sizeof special[0]);
    if (i < n)
        return special[i];
    uint32_t x = (uint32_t)i * 2654435761u;
    return (float)(x >> 8) / (float)(1u << 24) * 1.1f - 0.05f;
}

static void colorf(int i, float c[4])
{
    for (int k = 0; k < 4; k++)
        c[k] = valuef(i * 4 + k);
}

static void color565(int i, float c[4])
{
    int r = i % 32, g = i / 32, b = (i * 5) % 32;
    c[0] = r / 31.0f;
    c[1] = g / 63.0f;
    c[2] = b / 31.0f;
    c[3] = 1.0f;
}

static void color_sources(void)
{
    void *fb;
    OSMesaContext ctx;

    ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 16, 16, &fb);
    begin_source(16, 16);
    clear_pixels(16, 256, color8);
    read_color_source("rgba8", 16, 16, 0);
    save("rgba8");
    OSMesaDestroyContext(ctx);
    free(fb);

    ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_SHORT, 0, 0, 0, 16, 16, &fb);
    begin_source(16, 16);
    clear_pixels(16, 256, color16);
    read_color_source("rgba16", 16, 16, 0);
    save("rgba16");
    OSMesaDestroyContext(ctx);
    free(fb);

    ctx = capi_make_context(GL_RGBA, GL_FLOAT, 0, 0, 0, 16, 16, &fb);
    glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE);
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    begin_source(16, 16);
    clear_pixels(16, 256, colorf);
    read_color_source("rgbaf", 16, 16, 1);
    save("rgbaf");
    OSMesaDestroyContext(ctx);
    free(fb);

    ctx = capi_make_context(OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 0, 0, 0, 32, 64, &fb);
    glDisable(GL_DITHER);
    begin_source(32, 64);
    clear_pixels(32, 32 * 64, color565);
    read_color_source("rgb565", 32, 64, 1);
    save("rgb565");
    OSMesaDestroyContext(ctx);
    free(fb);
}

static const struct named stencil_types[] = {
    {GL_UNSIGNED_BYTE, "UNSIGNED_BYTE"}, {GL_BYTE, "BYTE"}, {GL_UNSIGNED_SHORT, "UNSIGNED_SHORT"},
    {GL_SHORT, "SHORT"},                 {GL_UNSIGNED_INT, "UNSIGNED_INT"}, {GL_INT, "INT"},
    {GL_FLOAT, "FLOAT"},                 {GL_HALF_FLOAT, "HALF_FLOAT"},
};

static void stencil_source(void)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, 16, 16, &fb);
    glEnable(GL_SCISSOR_TEST);
    for (int i = 0; i < 256; i++) {
        glScissor(i % 16, i / 16, 1, 1);
        glClearStencil(i);
        glClear(GL_STENCIL_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    begin_source(16, 16);
    for (int swap = 0; swap < 2; swap++) {
        glPixelStorei(GL_PACK_SWAP_BYTES, swap);
        for (int t = 0; t < 8; t++) {
            char tname[64];
            snprintf(tname, sizeof tname, "%s%s", stencil_types[t].name, swap ? "/swapped" : "");
            read_all("stencil", 16, 16, GL_STENCIL_INDEX, "STENCIL_INDEX", stencil_types[t].e, tname, 0);
        }
        read_all("stencil", 16, 16, GL_DEPTH_STENCIL, "DEPTH_STENCIL", GL_UNSIGNED_INT_24_8,
                 swap ? "UNSIGNED_INT_24_8/swapped" : "UNSIGNED_INT_24_8", 0);
    }
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    save("stencil");
    OSMesaDestroyContext(ctx);
    free(fb);
}

/* Depth values: a few decimals whose full clear both implementations round alike, then
 * exact fractions j / (2^n - 1) of the buffer's precision spread over [0, 1]. */
static double depth_value(int i, int bits)
{
    double max = bits == 16 ? 65535.0 : 16777215.0;
    static const double special[] = {0.0, 1.0, 0.5, 0.25, 0.1, 0.75};
    if (i < 6)
        return special[i];
    if (i < 10)
        return (i - 5) / max;
    uint32_t x = (uint32_t)i * 2654435761u;
    return (double)(x % (uint32_t)max) / max;
}

static void depth_source(int bits)
{
    void *fb;
    char source[32];
    snprintf(source, sizeof source, "depth%d", bits);
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, bits, bits == 24 ? 8 : 0, 0, 4, 4, &fb);
    enum { VALUES = 96 };
    static const struct named depth_types[] = {
        {GL_UNSIGNED_BYTE, "UNSIGNED_BYTE"}, {GL_BYTE, "BYTE"}, {GL_UNSIGNED_SHORT, "UNSIGNED_SHORT"},
        {GL_SHORT, "SHORT"},                 {GL_UNSIGNED_INT, "UNSIGNED_INT"}, {GL_INT, "INT"},
        {GL_FLOAT, "FLOAT"},                 {GL_HALF_FLOAT, "HALF_FLOAT"},
    };
    static unsigned char out[2][9][VALUES * 4];
    memset(out, 0xa5, sizeof out);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glClearStencil(0x3c);
    for (int i = 0; i < VALUES; i++) {
        glClearDepth(depth_value(i, bits));
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        for (int swap = 0; swap < 2; swap++) {
            glPixelStorei(GL_PACK_SWAP_BYTES, swap);
            for (int t = 0; t < 8; t++) {
                size_t size = bytes_of(GL_RED, depth_types[t].e, 1);
                glReadPixels(1, 2, 1, 1, GL_DEPTH_COMPONENT, depth_types[t].e, out[swap][t] + i * size);
            }
            if (bits == 24)
                glReadPixels(1, 2, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out[swap][8] + i * 4);
        }
    }
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    capi_expect_error(GL_NO_ERROR, source);
    for (int swap = 0; swap < 2; swap++) {
        for (int t = 0; t < (bits == 24 ? 9 : 8); t++) {
            const char *tname = t == 8 ? "DEPTH_STENCIL/UNSIGNED_INT_24_8" : depth_types[t].name;
            size_t n = t == 8 ? VALUES * 4 : bytes_of(GL_RED, depth_types[t].e, VALUES);
            capi_value("read", "%s %s%s fnv=%016llx", source, tname, swap ? "/swapped" : "",
                       (unsigned long long)fnv1a(out[swap][t], n));
        }
    }
    capi_save_image(source, VALUES * 4, 18, 1, CAPI_U8, out);
    OSMesaDestroyContext(ctx);
    free(fb);
}

int main(void)
{
    color_sources();
    stencil_source();
    depth_source(16);
    depth_source(24);
    return capi_finish();
}
