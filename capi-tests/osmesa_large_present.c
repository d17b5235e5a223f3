/* The caller's buffer written at a flush point for an image large enough that tessera writes
 * it in bands of rows on all its threads, the first time into fresh pages (each band asks the
 * kernel for its pages at once): every row lands where OSMESA_Y_UP and OSMESA_ROW_LENGTH put
 * it, and the padding between rows is never written, on the first presentation into a fresh
 * buffer and on later ones.
 */
#include "common.h"

#define W 640
#define H 480 /* 307 200 pixels: over tessera's 256 K-pixel threshold for a banded write */
#define ROW 647

/* A picture whose every pixel differs from its neighbours and from every other row. */
static unsigned char *pattern(void)
{
    unsigned char *p = malloc((size_t)W * H * 4);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            unsigned char *q = p + ((size_t)y * W + x) * 4;
            q[0] = (unsigned char)x;
            q[1] = (unsigned char)y;
            q[2] = (unsigned char)((x >> 8) | (y >> 8) << 4);
            q[3] = (unsigned char)(x * 7 + y * 3);
        }
    return p;
}

static void render(const unsigned char *picture)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glRasterPos2i(0, 0);
    glDrawPixels(W, H, GL_RGBA, GL_UNSIGNED_BYTE, picture);
    glFinish();
}

/* The buffer against the picture (`row` pixels per memory row); padding must still be `pad`. */
static void check_buffer(const char *what, const unsigned char *buffer, const unsigned char *picture, int row,
                         int y_up, unsigned char pad)
{
    long wrong_pixels = 0, wrong_padding = 0;
    for (int mem_row = 0; mem_row < H; mem_row++) {
        int y = y_up ? mem_row : H - 1 - mem_row;
        for (int x = 0; x < row; x++) {
            const unsigned char *got = buffer + ((size_t)mem_row * row + x) * 4;
            if (x < W) {
                if (memcmp(got, picture + ((size_t)y * W + x) * 4, 4) != 0 && wrong_pixels++ == 0)
                    capi_check(0, "%s: memory row %d pixel %d is %02x%02x%02x%02x", what, mem_row, x, got[0], got[1],
                               got[2], got[3]);
            } else if ((got[0] != pad || got[1] != pad || got[2] != pad || got[3] != pad) && wrong_padding++ == 0) {
                capi_check(0, "%s: padding at memory row %d pixel %d was written", what, mem_row, x);
            }
        }
    }
    capi_value(what, "wrong_pixels=%ld wrong_padding=%ld", wrong_pixels, wrong_padding);
}

int main(void)
{
    unsigned char *picture = pattern();
    size_t size = (size_t)ROW * H * 4;
    /* Fresh pages (calloc of a large block): their first write is the banded one. */
    unsigned char *buffer = calloc(1, size);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H), "MakeCurrent");
    OSMesaPixelStore(OSMESA_ROW_LENGTH, ROW);
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    capi_pixel_ortho(W, H);
    render(picture);
    check_buffer("fresh_row_length_y_down", buffer, picture, ROW, 0, 0);

    memset(buffer, 0xEE, size);
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    render(picture);
    check_buffer("row_length_y_up", buffer, picture, ROW, 1, 0xEE);

    /* Bound again without row length: rows packed, one band after another. */
    unsigned char *packed = calloc(1, (size_t)W * H * 4);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);
    capi_check(OSMesaMakeCurrent(ctx, packed, GL_UNSIGNED_BYTE, W, H), "MakeCurrent packed");
    render(picture);
    check_buffer("fresh_packed_y_up", packed, picture, W, 1, 0);
    capi_save_image("packed", W, H, 4, CAPI_U8, packed);

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(packed);
    free(buffer);
    free(picture);
    return capi_finish();
}
