/* glReadPixels: every format × type, from every kind of color buffer, byte for byte.
 *
 * For each context kind (8-bit RGBA/BGRA/RGB, 16-bit, float, 5_6_5; with and without depth
 * and stencil) the framebuffer is cleared to a pattern of scissored regions with chosen
 * colors, depths and stencil values, and read back through a rectangle that sticks out of
 * the window on all four sides, in every format × type pair (valid or not). The client
 * buffer is prefilled with a sentinel, so bytes outside the window must stay untouched. The
 * GL error and an FNV-1a hash of the whole buffer are VALUE lines; the buffers are saved as
 * one image per context (a row per format × type) so a failure can be looked at, and
 * READPIXELS_DUMP=kind/FORMAT/TYPE (e.g. rgba16/RGBA/FLOAT) prints one buffer on stderr.
 *
 * Known Mesa 22 bugs and differences this test steps around (tessera follows the
 * specification there; readpixels_errors.c checks both behaviours explicitly):
 *  - float 1.0 read as GL_UNSIGNED_INT gives 0 and as GL_INT gives INT_MIN (single-precision
 *    overflow) wherever Mesa converts through float (float and 5_6_5 buffers, luminance):
 *    on tessera those words are mapped to Mesa's values before hashing;
 *  - GL_STENCIL_INDEX/GL_BITMAP never returns: not called;
 *  - float buffers read unclamped (GL_CLAMP_READ_COLOR GL_FALSE, or GL_FIXED_ONLY, which
 *    Mesa wrongly applies to its float buffers) come back clamped whenever Mesa reads through
 *    a blit: float contexts read with GL_CLAMP_READ_COLOR = GL_TRUE here;
 *  - OSMesa contexts of 3-component formats (GL_RGB, OSMESA_BGR) render and read garbage in
 *    Mesa 22: not used;
 *  - Mesa reads OSMESA_BGRA 8-bit buffers as the 10-bit packed types through float (correct
 *    rounding) but GL_RGBA ones by bit replication (172 for 43, not 173); tessera's 8-bit
 *    buffers do not know their OSMesa layout and replicate: skipped for the BGRA context. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <stdint.h>

#define W 13
#define H 9
/* The read rectangle: one column left, two right, one row below, one above the window. */
#define RX (-1)
#define RY (-1)
#define RW (W + 3)
#define RH (H + 2)
#define SLOT 3072
#define SENTINEL 0xa5

struct named {
    GLenum e;
    const char *name;
};

static const struct named formats[] = {
    {GL_RGBA, "RGBA"},
    {GL_BGRA, "BGRA"},
    {GL_RGB, "RGB"},
    {GL_BGR, "BGR"},
    {GL_RED, "RED"},
    {GL_GREEN, "GREEN"},
    {GL_BLUE, "BLUE"},
    {GL_ALPHA, "ALPHA"},
    {GL_LUMINANCE, "LUMINANCE"},
    {GL_LUMINANCE_ALPHA, "LUMINANCE_ALPHA"},
    {GL_DEPTH_COMPONENT, "DEPTH_COMPONENT"},
    {GL_STENCIL_INDEX, "STENCIL_INDEX"},
    {GL_DEPTH_STENCIL, "DEPTH_STENCIL"},
    {GL_COLOR_INDEX, "COLOR_INDEX"},
    {GL_INTENSITY, "INTENSITY"},
    {GL_RGBA8, "RGBA8"},
};

static const struct named types[] = {
    {GL_UNSIGNED_BYTE, "UNSIGNED_BYTE"},
    {GL_BYTE, "BYTE"},
    {GL_UNSIGNED_SHORT, "UNSIGNED_SHORT"},
    {GL_SHORT, "SHORT"},
    {GL_UNSIGNED_INT, "UNSIGNED_INT"},
    {GL_INT, "INT"},
    {GL_FLOAT, "FLOAT"},
    {GL_HALF_FLOAT, "HALF_FLOAT"},
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
    {GL_UNSIGNED_INT_24_8, "UNSIGNED_INT_24_8"},
    {GL_BITMAP, "BITMAP"},
    {0x1234, "bogus"},
};

#define NFORMATS (int)(sizeof formats / sizeof formats[0])
#define NTYPES (int)(sizeof types / sizeof types[0])

struct context_kind {
    const char *name;
    GLenum format, type;
    int depth, stencil;
    /* GL_CLAMP_READ_COLOR to set (0: leave the default GL_FIXED_ONLY). */
    GLenum clamp;
    /* Float-path buffers (float, 5_6_5), where Mesa's 32-bit conversion of 1.0 overflows. */
    int float_path;
};

static const struct context_kind kinds[] = {
    {"rgba8", GL_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, 0},
    {"bgra8_z16", OSMESA_BGRA, GL_UNSIGNED_BYTE, 16, 0, 0, 0},
    {"rgba8_s8", GL_RGBA, GL_UNSIGNED_BYTE, 0, 8, 0, 0},
    {"rgba16", GL_RGBA, GL_UNSIGNED_SHORT, 24, 8, 0, 0},
    {"rgba16_none", GL_RGBA, GL_UNSIGNED_SHORT, 0, 0, 0, 0},
    {"rgbaf", GL_RGBA, GL_FLOAT, 24, 8, GL_TRUE, 1},
    {"rgbaf_z16", GL_RGBA, GL_FLOAT, 16, 0, GL_TRUE, 1},
    {"rgb565", OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 24, 8, 0, 1},
};

/* The scene: a background and six overlapping scissored regions, each with its own color,
 * depth and stencil. Mesa 22 clears scissored regions by drawing, which rounds some values
 * differently from a full clear (depth 0.1 and 0.9, 16-bit color 0.3 and 0.7, 5_6_5 color
 * 0.2) and clamps float colors; so the background (a full clear) holds the colors outside
 * [0, 1], the regions' values are the same either way, and 5_6_5 contexts get colors that
 * 5_6_5 represents exactly. The scene is then the same on both implementations and only the
 * reads are compared. */
static const struct {
    int x, y, w, h;
    float color[4];
    double depth;
    int stencil;
} regions[] = {
    {0, 0, W, H, {2.0f, -0.5f, 0.25f, 1.5f}, 0.1, 0x00},
    {0, 0, 5, 4, {1.0f, 0.0f, 0.25f, 1.0f}, 0.75, 0x5a},
    {6, 4, 7, 5, {0.47f, 0.03f, 0.25f, 0.97f}, 0.2, 0xff},
    {3, 2, 5, 4, {0.1f, 0.2f, 0.25f, 0.5f}, 0.0, 0x81},
    {12, 8, 1, 1, {0.0039f, 0.996f, 0.6f, 0.8f}, 0.99999, 0x02},
    {1, 7, 3, 2, {0.8f, 0.6f, 0.0039f, 0.999f}, 0.5, 0x7f},
    {8, 0, 4, 3, {0.53f, 0.2f, 0.1f, 0.6f}, 0.25, 0x3c},
};

/* The nearest value an n-bit channel holds exactly. */
static float exact(float c, int bits)
{
    float max = (float)((1 << bits) - 1);
    c = c < 0.0f ? 0.0f : c > 1.0f ? 1.0f : c;
    return (float)(int)(c * max + 0.5f) / max;
}

static void draw_scene(int rgb565)
{
    glDisable(GL_DITHER);
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    for (size_t i = 0; i < sizeof regions / sizeof regions[0]; i++) {
        /* The background is a full clear. */
        if (i == 0)
            glDisable(GL_SCISSOR_TEST);
        else
            glEnable(GL_SCISSOR_TEST);
        const float *c = regions[i].color;
        glScissor(regions[i].x, regions[i].y, regions[i].w, regions[i].h);
        if (rgb565 && i > 0)
            glClearColor(exact(c[0], 5), exact(c[1], 6), exact(c[2], 5), c[3]);
        else
            glClearColor(c[0], c[1], c[2], c[3]);
        glClearDepth(regions[i].depth);
        glClearStencil(regions[i].stencil);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
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

/* Whether Mesa converts through float (where its 32-bit conversion of 1.0 overflows):
 * luminance always, every color format from float and 5_6_5 buffers. */
static int float_path(const struct context_kind *kind, GLenum f)
{
    if (f == GL_LUMINANCE || f == GL_LUMINANCE_ALPHA)
        return 1;
    return kind->float_path && f != GL_DEPTH_COMPONENT && f != GL_STENCIL_INDEX && f != GL_DEPTH_STENCIL;
}

/* Maps tessera's saturated 32-bit conversions of 1.0 to Mesa 22's overflowed ones. */
static void as_mesa_overflow(unsigned char *buf, GLenum type)
{
    for (size_t i = 0; i + 4 <= SLOT; i += 4) {
        uint32_t w;
        memcpy(&w, buf + i, 4);
        if (type == GL_UNSIGNED_INT && w == 0xffffffffu)
            w = 0;
        else if (type == GL_INT && w == 0x7fffffffu)
            w = 0x80000000u;
        memcpy(buf + i, &w, 4);
    }
}

/* Prints the buffer on stderr, a row of the client image per line, if READPIXELS_DUMP names it. */
static void dump(const char *kind, const char *format, const char *type, const unsigned char *buf)
{
    const char *want = getenv("READPIXELS_DUMP");
    char key[128];
    snprintf(key, sizeof key, "%s/%s/%s", kind, format, type);
    if (!want || strcmp(want, key) != 0)
        return;
    size_t end = SLOT;
    while (end > 0 && buf[end - 1] == SENTINEL)
        end--;
    for (size_t i = 0; i < end; i++)
        fprintf(stderr, "%02x%s", buf[i], (i + 1) % 64 == 0 ? "\n" : " ");
    fprintf(stderr, "\n");
}

static void run_kind(const struct context_kind *kind)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(kind->format, kind->type, kind->depth, kind->stencil, 0, W, H, &fb);
    int tessera = capi_is_tessera();
    if (kind->clamp)
        glClampColor(GL_CLAMP_READ_COLOR, kind->clamp);
    draw_scene(kind->type == GL_UNSIGNED_SHORT_5_6_5);
    capi_expect_error(GL_NO_ERROR, kind->name);

    unsigned char *image = malloc((size_t)SLOT * NFORMATS * NTYPES);
    int rows = 0;
    for (int f = 0; f < NFORMATS; f++) {
        for (int t = 0; t < NTYPES; t++) {
            GLenum format = formats[f].e, type = types[t].e;
            /* Mesa 22 hangs here (see the header); readpixels_errors.c checks tessera. */
            if (format == GL_STENCIL_INDEX && type == GL_BITMAP && kind->stencil)
                continue;
            /* Layout-dependent in Mesa (see the header). */
            if (kind->format == OSMESA_BGRA &&
                (type == GL_UNSIGNED_INT_10_10_10_2 || type == GL_UNSIGNED_INT_2_10_10_10_REV))
                continue;
            unsigned char *buf = image + (size_t)rows * SLOT;
            memset(buf, SENTINEL, SLOT);
            glReadPixels(RX, RY, RW, RH, format, type, buf);
            GLenum err = glGetError();
            if (err != GL_NO_ERROR) {
                capi_value("err", "%s %s %s 0x%x", kind->name, formats[f].name, types[t].name, err);
                continue;
            }
            if (tessera && float_path(kind, format) && (type == GL_UNSIGNED_INT || type == GL_INT))
                as_mesa_overflow(buf, type);
            /* Bytes outside the window (column 0 of the first full row) keep the sentinel. */
            int untouched = 1;
            for (size_t i = 0; i < 4; i++)
                untouched &= buf[i] == SENTINEL;
            capi_check(untouched, "%s %s %s wrote outside the window", kind->name, formats[f].name,
                       types[t].name);
            dump(kind->name, formats[f].name, types[t].name, buf);
            capi_value("read", "%s %s %s fnv=%016llx", kind->name, formats[f].name, types[t].name,
                       (unsigned long long)fnv1a(buf, SLOT));
            rows++;
        }
    }
    char name[64];
    snprintf(name, sizeof name, "readpixels_matrix_%s", kind->name);
    capi_save_image(name, SLOT, rows, 1, CAPI_U8, image);
    free(image);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(fb);
}

int main(void)
{
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        run_kind(&kinds[k]);
    return capi_finish();
}
