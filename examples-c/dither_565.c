/* dither_565: the lecture's dithering slide: a 24-bit RGB888 picture shown with fewer
 * colors, truncated versus dithered. The picture is horizontal ramps (red, green, blue,
 * grey, and an orange-to-purple mix), each column its own flat 8-bit color, drawn three
 * times:
 *   dither_888.png:            into an RGBA8 buffer (the original);
 *   dither_565_truncated.png:  into an OSMESA_RGB_565 buffer with glDisable(GL_DITHER):
 *                              each channel keeps its top 5 or 6 bits, the ramps band;
 *   dither_565_dithered.png:   into RGB_565 with GL_DITHER on (the GL default): the bands
 *                              become an ordered 4x4 pattern whose average is the original.
 * Mesa 22 does not dither (its picture equals the truncated one); tessera adds the ordered
 * 4x4 Bayer threshold before truncating. dither_565_expected.png is what that pattern gives,
 * computed here from the 888 picture (RGB565 pictures are widened back to 8 bits by bit
 * replication for the PNG files). */
#include "example.h"

#define W 256
#define H 160

static void ramps(void)
{
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    for (int band = 0; band < 5; band++)
        for (int x = 0; x < W; x++) {
            int v = 48 + x / 2; /* 48 .. 175: slow ramps show the banding best */
            int r = band == 0 || band == 3 ? v : 0, g = band == 1 || band == 3 ? v : 0;
            int b = band == 2 || band == 3 ? v : 0;
            if (band == 4)
                r = 255 - x / 3, g = 40 + x / 5, b = 60 + x / 2;
            glColor3ub(r, g, b);
            glVertex2i(x, band * 32), glVertex2i(x + 1, band * 32);
            glVertex2i(x + 1, band * 32 + 32), glVertex2i(x, band * 32 + 32);
        }
    glEnd();
}

/* Renders the ramps into an RGB565 buffer and writes it widened to RGBA8. */
static void render_565(const Example *ex, int dither, const char *image)
{
    static unsigned short pixels[W * H];
    static unsigned char rgba[W * H * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB_565, 0, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_SHORT_5_6_5, W, H))
        example_die(ex->name, "cannot create an RGB565 context");
    ortho(W, H);
    if (dither)
        glEnable(GL_DITHER);
    else
        glDisable(GL_DITHER);
    ramps();
    glFinish();
    for (int i = 0; i < W * H; i++) {
        int r5 = pixels[i] >> 11, g6 = (pixels[i] >> 5) & 63, b5 = pixels[i] & 31;
        rgba[i * 4 + 0] = (unsigned char)(r5 << 3 | r5 >> 2);
        rgba[i * 4 + 1] = (unsigned char)(g6 << 2 | g6 >> 4);
        rgba[i * 4 + 2] = (unsigned char)(b5 << 3 | b5 >> 2);
        rgba[i * 4 + 3] = 255;
    }
    example_write_png(ex, image, W, H, rgba);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

/* One 8-bit channel dithered to `bits` bits with threshold m (0..15) of the 4x4 pattern,
 * widened back to 8 bits: floor((v * (2^bits - 1) * 16 + (2m + 1) * 255 / 2) / (16 * 255)). */
static unsigned char dither_channel(int v, int m, int bits)
{
    unsigned max = (1u << bits) - 1;
    unsigned q = (32u * v * max + (2u * m + 1) * 255) / (32 * 255);
    return (unsigned char)(bits == 5 ? (q << 3 | q >> 2) : (q << 2 | q >> 4));
}

int main(int argc, char **argv)
{
    static const int bayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    static unsigned char expected[W * H * 4];
    Example ex;
    example_start(&ex, "dither_565", argc, argv, W, H, 0, 0);
    ortho(W, H);
    ramps();
    example_save(&ex, "dither_888");
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const unsigned char *p = ex.rgba + (y * W + x) * 4;
            int m = bayer[y & 3][x & 3];
            unsigned char *e = expected + (y * W + x) * 4;
            e[0] = dither_channel(p[0], m, 5), e[1] = dither_channel(p[1], m, 6);
            e[2] = dither_channel(p[2], m, 5), e[3] = 255;
        }
    example_write_png(&ex, "dither_565_expected", W, H, expected);

    render_565(&ex, 0, "dither_565_truncated");
    render_565(&ex, 1, "dither_565_dithered");
    return example_finish(&ex);
}
