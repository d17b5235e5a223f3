/* glReadPixels with the pack parameters: alignment, row length, skipped rows and pixels,
 * byte swapping (and the parameters that must not matter to a 2D read: LSB first for
 * non-bitmaps, image height, skipped images, all GL_UNPACK_* ones), set with glPixelStorei
 * and glPixelStoref (which rounds), through rectangles inside, across the edges of, and
 * entirely outside the window. The client buffer is prefilled with a sentinel; an FNV-1a
 * hash of all of it is a VALUE line, so the bytes written, the bytes skipped and the bytes
 * left alone must all agree with Mesa. glPixelStore's own errors are checked too. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <stdint.h>

#define W 11
#define H 7
#define SLOT 8192
#define SENTINEL 0x5a

struct mode {
    const char *name;
    int alignment, row_length, skip_rows, skip_pixels, swap_bytes;
    /* 1: set through glPixelStoref with values that round to the integer ones. */
    int through_float;
    /* 1: also set the parameters a 2D read ignores. */
    int ignored_too;
};

static const struct mode modes[] = {
    {"default", 4, 0, 0, 0, 0, 0, 0},
    {"align1", 1, 0, 0, 0, 0, 0, 0},
    {"align2", 2, 0, 0, 0, 0, 0, 0},
    {"align8", 8, 0, 0, 0, 0, 0, 0},
    {"rowlen", 4, 17, 0, 0, 0, 0, 0},
    {"skips", 4, 0, 2, 3, 0, 0, 0},
    {"swap", 4, 0, 0, 0, 1, 0, 0},
    {"everything", 8, 19, 1, 5, 1, 0, 0},
    {"float", 8, 17, 1, 3, 1, 1, 0},
    {"ignored", 2, 0, 0, 0, 0, 0, 1},
};

struct combo {
    GLenum format, type;
    const char *name;
};

static const struct combo combos[] = {
    {GL_RGBA, GL_UNSIGNED_BYTE, "RGBA/UNSIGNED_BYTE"},
    {GL_BGRA, GL_UNSIGNED_BYTE, "BGRA/UNSIGNED_BYTE"},
    {GL_RGB, GL_UNSIGNED_BYTE, "RGB/UNSIGNED_BYTE"},
    {GL_BGR, GL_UNSIGNED_BYTE, "BGR/UNSIGNED_BYTE"},
    {GL_RGB, GL_UNSIGNED_SHORT, "RGB/UNSIGNED_SHORT"},
    {GL_ALPHA, GL_SHORT, "ALPHA/SHORT"},
    {GL_LUMINANCE_ALPHA, GL_FLOAT, "LUMINANCE_ALPHA/FLOAT"},
    {GL_RGBA, GL_HALF_FLOAT, "RGBA/HALF_FLOAT"},
    {GL_GREEN, GL_UNSIGNED_BYTE, "GREEN/UNSIGNED_BYTE"},
    {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, "RGBA/4_4_4_4"},
    {GL_RGB, GL_UNSIGNED_BYTE_3_3_2, "RGB/3_3_2"},
    {GL_RGB, GL_UNSIGNED_SHORT_5_6_5, "RGB/5_6_5"},
    {GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, "BGRA/2_10_10_10_REV"},
    {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, "RGBA/8_8_8_8"},
    {GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, "DEPTH_COMPONENT/UNSIGNED_INT"},
    {GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, "DEPTH_COMPONENT/UNSIGNED_SHORT"},
    {GL_DEPTH_COMPONENT, GL_FLOAT, "DEPTH_COMPONENT/FLOAT"},
    {GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, "STENCIL_INDEX/UNSIGNED_BYTE"},
    {GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, "STENCIL_INDEX/UNSIGNED_SHORT"},
    {GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, "DEPTH_STENCIL/UNSIGNED_INT_24_8"},
};

static const struct {
    int x, y, w, h;
    const char *name;
} rects[] = {
    {-3, -2, W + 5, H + 3, "around"},
    {2, 1, 5, 4, "inside"},
    {W - 2, H - 1, 4, 3, "corner"},
    {W + 1, 0, 3, 3, "outside"},
    {-4, -4, 3, 3, "below_left"},
    {0, 0, 0, 5, "empty"},
};

struct context_kind {
    const char *name;
    GLenum format, type;
};

static const struct context_kind kinds[] = {
    {"rgba8", GL_RGBA, GL_UNSIGNED_BYTE},
    {"rgba16", GL_RGBA, GL_UNSIGNED_SHORT},
    {"rgbaf", GL_RGBA, GL_FLOAT},
    {"rgb565", OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5},
};

static uint64_t fnv1a(const unsigned char *p, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

/* A scene of a background and three scissored regions (values that every clear path of
 * Mesa stores alike; see readpixels_matrix.c). */
static void draw_scene(int rgb565)
{
    static const struct {
        int x, y, w, h;
        float c[4];
        double depth;
        int stencil;
    } r[] = {
        {0, 0, W, H, {0.25f, 0.5f, 0.75f, 1.0f}, 0.1, 0x11},
        {0, 0, 4, 3, {1.0f, 0.0f, 0.2f, 0.6f}, 0.75, 0xa5},
        {5, 2, 6, 5, {0.47f, 0.03f, 0.53f, 0.97f}, 0.25, 0xff},
        {2, 4, 3, 3, {0.8f, 0.6f, 0.0039f, 0.2f}, 0.5, 0x42},
    };
    glDisable(GL_DITHER);
    for (size_t i = 0; i < sizeof r / sizeof r[0]; i++) {
        if (i == 0)
            glDisable(GL_SCISSOR_TEST);
        else
            glEnable(GL_SCISSOR_TEST);
        glScissor(r[i].x, r[i].y, r[i].w, r[i].h);
        if (rgb565)
            glClearColor((int)(r[i].c[0] * 31 + 0.5f) / 31.0f, (int)(r[i].c[1] * 63 + 0.5f) / 63.0f,
                         (int)(r[i].c[2] * 31 + 0.5f) / 31.0f, 1.0f);
        else
            glClearColor(r[i].c[0], r[i].c[1], r[i].c[2], r[i].c[3]);
        glClearDepth(r[i].depth);
        glClearStencil(r[i].stencil);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
}

static void set_mode(const struct mode *m)
{
    if (m->through_float) {
        /* glPixelStoref rounds half away from zero (lroundf). */
        glPixelStoref(GL_PACK_ALIGNMENT, m->alignment - 0.4f);
        glPixelStoref(GL_PACK_ROW_LENGTH, m->row_length - 0.5f);
        glPixelStoref(GL_PACK_SKIP_ROWS, m->skip_rows + 0.49f);
        glPixelStoref(GL_PACK_SKIP_PIXELS, m->skip_pixels - 0.5f);
        glPixelStoref(GL_PACK_SWAP_BYTES, m->swap_bytes ? 0.5f : 0.4f);
    } else {
        glPixelStorei(GL_PACK_ALIGNMENT, m->alignment);
        glPixelStorei(GL_PACK_ROW_LENGTH, m->row_length);
        glPixelStorei(GL_PACK_SKIP_ROWS, m->skip_rows);
        glPixelStorei(GL_PACK_SKIP_PIXELS, m->skip_pixels);
        glPixelStorei(GL_PACK_SWAP_BYTES, m->swap_bytes ? 7 : 0);
    }
    int ignored = m->ignored_too;
    glPixelStorei(GL_PACK_LSB_FIRST, ignored);
    glPixelStorei(GL_PACK_IMAGE_HEIGHT, ignored ? 3 : 0);
    glPixelStorei(GL_PACK_SKIP_IMAGES, ignored ? 2 : 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, ignored ? 1 : 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, ignored ? 23 : 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, ignored ? 4 : 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, ignored ? 4 : 0);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, ignored);
    glPixelStorei(GL_UNPACK_LSB_FIRST, ignored);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, ignored ? 5 : 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, ignored ? 1 : 0);
    capi_expect_error(GL_NO_ERROR, m->name);
}

static void run_kind(const struct context_kind *kind)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(kind->format, kind->type, 24, 8, 0, W, H, &fb);
    glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE);
    draw_scene(kind->type == GL_UNSIGNED_SHORT_5_6_5);
    static unsigned char buf[SLOT];
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        set_mode(&modes[m]);
        for (size_t c = 0; c < sizeof combos / sizeof combos[0]; c++) {
            for (size_t r = 0; r < sizeof rects / sizeof rects[0]; r++) {
                memset(buf, SENTINEL, SLOT);
                glReadPixels(rects[r].x, rects[r].y, rects[r].w, rects[r].h, combos[c].format, combos[c].type, buf);
                GLenum err = glGetError();
                capi_check(buf[SLOT - 1] == SENTINEL, "%s %s %s %s wrote too far", kind->name, modes[m].name,
                           combos[c].name, rects[r].name);
                int untouched = 1;
                for (int i = 0; i < SLOT; i++)
                    untouched &= buf[i] == SENTINEL;
                if (r >= 3)
                    capi_check(untouched, "%s %s %s: nothing inside the window, yet bytes changed", kind->name,
                               modes[m].name, combos[c].name);
                capi_value("read", "%s %s %s %s err=0x%x fnv=%016llx", kind->name, modes[m].name, combos[c].name,
                           rects[r].name, err, (unsigned long long)fnv1a(buf, SLOT));
            }
        }
    }
    OSMesaDestroyContext(ctx);
    free(fb);
}

/* glPixelStore's own errors: the state stays as it was (checked through a read). */
static void pixel_store_errors(void)
{
    void *fb;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 8, 0, 4, 4, &fb);
    glClearStencil(0x77);
    glClear(GL_STENCIL_BUFFER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    static const struct {
        GLenum pname;
        float value;
        int through_float;
        GLenum error;
        const char *what;
    } cases[] = {
        {GL_PACK_ALIGNMENT, 3, 0, GL_INVALID_VALUE, "alignment 3"},
        {GL_PACK_ALIGNMENT, 16, 0, GL_INVALID_VALUE, "alignment 16"},
        {GL_PACK_ALIGNMENT, 0, 0, GL_INVALID_VALUE, "alignment 0"},
        {GL_UNPACK_ALIGNMENT, -4, 0, GL_INVALID_VALUE, "unpack alignment -4"},
        {GL_PACK_ROW_LENGTH, -1, 0, GL_INVALID_VALUE, "row length -1"},
        {GL_PACK_SKIP_ROWS, -1, 0, GL_INVALID_VALUE, "skip rows -1"},
        {GL_PACK_SKIP_PIXELS, -1, 0, GL_INVALID_VALUE, "skip pixels -1"},
        {GL_PACK_SKIP_IMAGES, -1, 0, GL_INVALID_VALUE, "skip images -1"},
        {GL_PACK_IMAGE_HEIGHT, -1, 0, GL_INVALID_VALUE, "image height -1"},
        {GL_UNPACK_ROW_LENGTH, -1, 0, GL_INVALID_VALUE, "unpack row length -1"},
        {GL_UNPACK_SKIP_IMAGES, -1, 0, GL_INVALID_VALUE, "unpack skip images -1"},
        {GL_PACK_ROW_LENGTH, -0.5f, 1, GL_INVALID_VALUE, "row length -0.5f (rounds to -1)"},
        {GL_PACK_ROW_LENGTH, 3e9f, 1, GL_INVALID_VALUE, "row length 3e9f (negative as GLint)"},
        {GL_PACK_ALIGNMENT, 2.6f, 1, GL_INVALID_VALUE, "alignment 2.6f (rounds to 3)"},
        {0x1234, 1, 0, GL_INVALID_ENUM, "bogus pname"},
        {GL_PACK_ALIGNMENT + 1, 1, 0, GL_INVALID_ENUM, "pname after GL_PACK_ALIGNMENT"},
        {GL_UNPACK_SWAP_BYTES - 1, 1, 0, GL_INVALID_ENUM, "pname before GL_UNPACK_SWAP_BYTES"},
        {GL_PACK_ROW_LENGTH, -0.4f, 1, GL_NO_ERROR, "row length -0.4f (rounds to 0)"},
        {GL_PACK_ROW_LENGTH, 0.49999997f, 1, GL_NO_ERROR, "row length 0.49999997f (rounds to 0)"},
        {GL_PACK_ROW_LENGTH, 1e20f, 1, GL_NO_ERROR, "row length 1e20f (0 as GLint)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (cases[i].through_float)
            glPixelStoref(cases[i].pname, cases[i].value);
        else
            glPixelStorei(cases[i].pname, (GLint)cases[i].value);
        capi_expect_error(cases[i].error, cases[i].what);
    }
    /* Still alignment 1 and row length 0: a 3×2 read is 6 tight bytes. */
    unsigned char b[16];
    memset(b, SENTINEL, sizeof b);
    glReadPixels(0, 0, 3, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, b);
    capi_expect_error(GL_NO_ERROR, "read after the errors");
    for (int i = 0; i < 16; i++)
        capi_check(b[i] == (i < 6 ? 0x77 : SENTINEL), "byte %d is 0x%02x", i, b[i]);
    OSMesaDestroyContext(ctx);
    free(fb);
}

int main(void)
{
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        run_kind(&kinds[k]);
    pixel_store_errors();
    return capi_finish();
}
