/* glPolygonStipple and glGetPolygonStipple: the 32x32 pattern moves through the pixel store
 * as a bitmap. It is specified under a series of unpack modes (GL_UNPACK_LSB_FIRST,
 * alignment, row length, skipped rows and pixels, with bit offsets that are not byte
 * aligned) and read back, byte by byte, under default and under unusual pack modes; every
 * byte of the client buffers is printed. GL_POLYGON_STIPPLE_BIT restores the pattern.
 *
 * Pack buffers are cleared to zero before reading: with GL_PACK_SKIP_PIXELS not a multiple
 * of 8, Mesa 22 zeroes the bits of the first and last byte of each row that lie outside the
 * pattern, while tessera leaves them alone (checked on tessera with a non-zero fill). Where
 * rows share a byte (a row length too short for the skipped pixels), Mesa's zeroing even
 * erases the end of the previous row, so those layouts are checked on tessera only.
 * glPolygonStipple(NULL) crashes Mesa 22; tessera ignores it (checked on tessera only).
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"

#define W 8
#define H 8
#define BUF 2048

static unsigned char source[BUF];

static void print_bytes(const char *key, const unsigned char *bytes, int n)
{
    char line[2 * BUF + 1];
    for (int i = 0; i < n; i++)
        snprintf(line + 2 * i, 3, "%02x", bytes[i]);
    capi_value(key, "%s", line);
}

static void reset_store(int pack)
{
    if (pack) {
        glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
        glPixelStorei(GL_PACK_SKIP_ROWS, 0);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    } else {
        glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    }
}

/* Reads the pattern back with default pack modes and prints its 128 bytes. */
static void print_pattern(const char *key)
{
    unsigned char out[128];
    memset(out, 0, sizeof out);
    glGetPolygonStipple(out);
    print_bytes(key, out, sizeof out);
    capi_expect_error(GL_NO_ERROR, key);
}

struct modes {
    const char *name;
    int lsb_first, row_length, skip_rows, skip_pixels, alignment, swap_bytes;
};

static const struct modes mode_list[] = {
    {"default", 0, 0, 0, 0, 4, 0},
    {"lsb_first", 1, 0, 0, 0, 4, 0},
    {"skip_pixels_8", 0, 0, 0, 8, 1, 0},
    {"skip_pixels_3", 0, 0, 0, 3, 1, 0},
    {"skip_pixels_13_lsb", 1, 0, 0, 13, 2, 0},
    {"row_length_41_align_8", 0, 41, 0, 0, 8, 0},
    {"row_length_9", 0, 9, 0, 0, 1, 0},
    {"skip_rows_5_align_2", 0, 0, 5, 0, 2, 0},
    {"everything", 1, 50, 3, 7, 8, 1},
};

static void unpack(void)
{
    for (unsigned m = 0; m < sizeof mode_list / sizeof mode_list[0]; m++) {
        const struct modes *md = &mode_list[m];
        glPixelStorei(GL_UNPACK_LSB_FIRST, md->lsb_first);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, md->row_length);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, md->skip_rows);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, md->skip_pixels);
        glPixelStorei(GL_UNPACK_ALIGNMENT, md->alignment);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, md->swap_bytes);
        glPolygonStipple(source);
        char key[64];
        snprintf(key, sizeof key, "unpack_%s", md->name);
        print_pattern(key);
    }
    reset_store(0);
}

/* Pack modes whose rows share no byte, printed; then those whose rows do, checked only. */
static const struct modes pack_list[] = {
    {"default", 0, 0, 0, 0, 4, 0},
    {"lsb_first", 1, 0, 0, 0, 4, 0},
    {"skip_pixels_8", 0, 0, 0, 8, 1, 0},
    {"skip_pixels_3", 0, 40, 0, 3, 1, 0},
    {"skip_pixels_13_lsb", 1, 48, 0, 13, 2, 0},
    {"row_length_41_align_8", 0, 41, 0, 0, 8, 0},
    {"skip_rows_5_align_2", 0, 0, 5, 0, 2, 0},
    {"everything", 1, 50, 3, 7, 8, 1},
    {"shared_bytes_3", 0, 0, 0, 3, 1, 0},
    {"shared_bytes_13_lsb", 1, 0, 2, 13, 2, 0},
    {"row_length_9", 0, 9, 0, 0, 1, 0},
};
#define PRINTED_PACK_MODES 8

/* The mask of the bits of `buffer` byte `i` that hold pattern pixels under `md`. */
static unsigned char pattern_bits(const struct modes *md, int stride, int i)
{
    unsigned char mask = 0;
    for (int row = 0; row < 32; row++)
        for (int col = 0; col < 32; col++) {
            int bit = md->skip_pixels + col;
            if ((md->skip_rows + row) * stride + bit / 8 == i)
                mask |= md->lsb_first ? 1 << (bit % 8) : 0x80 >> (bit % 8);
        }
    return mask;
}

static void pack(void)
{
    static unsigned char out[BUF];
    glPolygonStipple(source);
    for (unsigned m = 0; m < sizeof pack_list / sizeof pack_list[0]; m++) {
        const struct modes *md = &pack_list[m];
        glPixelStorei(GL_PACK_LSB_FIRST, md->lsb_first);
        glPixelStorei(GL_PACK_ROW_LENGTH, md->row_length);
        glPixelStorei(GL_PACK_SKIP_ROWS, md->skip_rows);
        glPixelStorei(GL_PACK_SKIP_PIXELS, md->skip_pixels);
        glPixelStorei(GL_PACK_ALIGNMENT, md->alignment);
        glPixelStorei(GL_PACK_SWAP_BYTES, md->swap_bytes);
        memset(out, 0, sizeof out);
        glGetPolygonStipple(out);
        char key[64];
        snprintf(key, sizeof key, "pack_%s", md->name);
        /* Everything the largest layout can touch: 35 rows of up to 8 bytes. */
        int row_bytes = ((md->row_length ? md->row_length : 32) + 7) / 8;
        int stride = (row_bytes + md->alignment - 1) / md->alignment * md->alignment;
        int size = stride * (32 + md->skip_rows) + 8;
        if (m < PRINTED_PACK_MODES)
            print_bytes(key, out, size);
        else
            capi_check(glGetError() == GL_NO_ERROR, "%s", key);
        capi_expect_error(GL_NO_ERROR, key);

        /* The bytes a bit-by-bit pack of the pattern (read back with default modes) into a
         * zeroed buffer gives, rows in order. */
        unsigned char reference[128];
        static unsigned char expected[BUF];
        glPixelStorei(GL_PACK_LSB_FIRST, 0);
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
        glPixelStorei(GL_PACK_SKIP_ROWS, 0);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glGetPolygonStipple(reference);
        memset(expected, 0, sizeof expected);
        for (int row = 0; row < 32; row++)
            for (int col = 0; col < 32; col++) {
                int bit = md->skip_pixels + col;
                int byte = (md->skip_rows + row) * stride + bit / 8;
                unsigned char mask = md->lsb_first ? 1 << (bit % 8) : 0x80 >> (bit % 8);
                if ((reference[row * 4 + col / 8] >> (7 - col % 8)) & 1)
                    expected[byte] |= mask;
                else
                    expected[byte] &= ~mask;
            }
        /* Mesa's zeroing of shared bytes loses the ends of rows: tessera only. */
        if (m < PRINTED_PACK_MODES || capi_is_tessera())
            capi_check(memcmp(out, expected, size) == 0, "%s: the bytes of a bit-by-bit pack", md->name);

        if (capi_is_tessera()) {
            /* Only the pattern's bits are written. */
            static unsigned char filled[BUF];
            memset(filled, 0xa5, sizeof filled);
            glPixelStorei(GL_PACK_LSB_FIRST, md->lsb_first);
            glPixelStorei(GL_PACK_ROW_LENGTH, md->row_length);
            glPixelStorei(GL_PACK_SKIP_ROWS, md->skip_rows);
            glPixelStorei(GL_PACK_SKIP_PIXELS, md->skip_pixels);
            glPixelStorei(GL_PACK_ALIGNMENT, md->alignment);
            glGetPolygonStipple(filled);
            int ok = 1;
            for (int i = 0; i < size; i++) {
                unsigned char mask = pattern_bits(md, stride, i);
                ok &= (filled[i] & mask) == (out[i] & mask) && (filled[i] & ~mask & 0xff) == (0xa5 & ~mask);
            }
            capi_check(ok, "%s: bits outside the pattern are kept", md->name);
        }
    }
    reset_store(1);
}

static void attribs_and_errors(void)
{
    static const unsigned char stripes[128] = {0x0f, 0xf0, 0x33, 0xcc};
    glPolygonStipple(source);
    glPushAttrib(GL_POLYGON_STIPPLE_BIT);
    glPolygonStipple(stripes);
    print_pattern("pushed_then_changed");
    glPopAttrib();
    print_pattern("popped");
    glPushAttrib(GL_ALL_ATTRIB_BITS & ~GL_POLYGON_STIPPLE_BIT);
    glPolygonStipple(stripes);
    glPopAttrib();
    print_pattern("other_bits_keep_it");
    glPolygonStipple(source);

    glGetPolygonStipple(NULL);
    capi_expect_error(GL_NO_ERROR, "get_null");
    if (capi_is_tessera()) {
        glPolygonStipple(NULL);
        capi_check(glGetError() == GL_NO_ERROR, "glPolygonStipple(NULL) is ignored");
    }
    void (*begin)(GLenum) = (void (*)(GLenum))OSMesaGetProcAddress("glBegin");
    void (*end)(void) = (void (*)(void))OSMesaGetProcAddress("glEnd");
    if (begin && end) {
        unsigned char out[128];
        memset(out, 0x5a, sizeof out);
        begin(GL_TRIANGLES);
        glPolygonStipple(stripes);
        end();
        capi_check(glGetError() == GL_INVALID_OPERATION, "glPolygonStipple between glBegin/glEnd");
        begin(GL_TRIANGLES);
        glGetPolygonStipple(out);
        end();
        capi_check(glGetError() == GL_INVALID_OPERATION, "glGetPolygonStipple between glBegin/glEnd");
        capi_check(out[0] == 0x5a && out[127] == 0x5a, "nothing written between glBegin/glEnd");
    }
    print_pattern("final");
}

int main(void)
{
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    for (int i = 0; i < BUF; i++)
        source[i] = (unsigned char)(i * 37 + 11 + (i >> 7));
    print_pattern("initial");
    unpack();
    pack();
    attribs_and_errors();
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
