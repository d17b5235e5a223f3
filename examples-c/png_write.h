/* png_write.h: a tiny PNG writer for the examples, without libpng or zlib.
 *
 * Writes 8-bit RGBA images. The pixel data goes into zlib "stored" (uncompressed) blocks,
 * which every PNG reader accepts; the file is about as big as the raw pixels. A PNG needs
 * a CRC-32 over each chunk and an Adler-32 over the zlib data: both are computed here.
 *
 *     png_write_rgba("out/picture.png", width, height, pixels, 1);
 *
 * `bottom_up` = 1 for rows in OpenGL order (first row at the bottom, as OSMesa and
 * glReadPixels deliver them), 0 for top-down rows. Returns 0 on success, -1 on error.
 */
#ifndef PNG_WRITE_H
#define PNG_WRITE_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned long png_crc32_update(unsigned long crc, const unsigned char *data, size_t n)
{
    static unsigned long table[256];
    static int ready;
    if (!ready) {
        for (unsigned long i = 0; i < 256; i++) {
            unsigned long c = i;
            for (int k = 0; k < 8; k++)
                c = c & 1 ? 0xEDB88320UL ^ (c >> 1) : c >> 1;
            table[i] = c;
        }
        ready = 1;
    }
    crc ^= 0xFFFFFFFFUL;
    for (size_t i = 0; i < n; i++)
        crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
    return crc ^ 0xFFFFFFFFUL;
}

static void png_put32(unsigned char *p, unsigned long v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* Writes one chunk: length, type, data, CRC-32 of type and data. */
static int png_chunk(FILE *f, const char type[4], const unsigned char *data, size_t n)
{
    unsigned char head[8], tail[4];
    png_put32(head, (unsigned long)n);
    memcpy(head + 4, type, 4);
    unsigned long crc = png_crc32_update(0, head + 4, 4);
    crc = png_crc32_update(crc, data, n);
    png_put32(tail, crc);
    return fwrite(head, 1, 8, f) == 8 && (n == 0 || fwrite(data, 1, n, f) == n) && fwrite(tail, 1, 4, f) == 4 ? 0
                                                                                                        : -1;
}

static int png_write_rgba(const char *path, int width, int height, const unsigned char *pixels, int bottom_up)
{
    if (width <= 0 || height <= 0)
        return -1;
    /* The filtered image: each row is a filter byte (0: none) and the row's pixels. */
    size_t row = (size_t)width * 4, raw_size = (size_t)height * (row + 1);
    unsigned char *raw = malloc(raw_size);
    /* zlib: 2 header bytes, stored blocks of at most 65535 bytes (5 bytes of header each),
     * Adler-32 of the raw data. */
    size_t blocks = (raw_size + 65534) / 65535;
    size_t zsize = 2 + raw_size + 5 * blocks + 4;
    unsigned char *z = malloc(zsize);
    if (!raw || !z) {
        free(raw);
        free(z);
        return -1;
    }
    for (int y = 0; y < height; y++) {
        int source = bottom_up ? height - 1 - y : y;
        raw[y * (row + 1)] = 0;
        memcpy(raw + y * (row + 1) + 1, pixels + (size_t)source * row, row);
    }

    unsigned char *p = z;
    *p++ = 0x78; /* deflate, 32K window */
    *p++ = 0x01; /* no preset dictionary, fastest; (0x78 << 8 | 0x01) % 31 == 0 */
    for (size_t done = 0; done < raw_size;) {
        size_t n = raw_size - done > 65535 ? 65535 : raw_size - done;
        *p++ = done + n == raw_size ? 1 : 0; /* BFINAL, BTYPE 00 (stored) */
        *p++ = (unsigned char)(n & 0xFF);
        *p++ = (unsigned char)(n >> 8);
        *p++ = (unsigned char)(~n & 0xFF);
        *p++ = (unsigned char)((~n >> 8) & 0xFF);
        memcpy(p, raw + done, n);
        p += n;
        done += n;
    }
    unsigned long a = 1, b = 0; /* Adler-32 */
    for (size_t i = 0; i < raw_size; i++) {
        a = (a + raw[i]) % 65521;
        b = (b + a) % 65521;
    }
    png_put32(p, b << 16 | a);
    p += 4;

    unsigned char ihdr[13];
    png_put32(ihdr, (unsigned long)width);
    png_put32(ihdr + 4, (unsigned long)height);
    ihdr[8] = 8;  /* bits per channel */
    ihdr[9] = 6;  /* RGBA */
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0; /* adaptive filtering (every row uses filter 0) */
    ihdr[12] = 0; /* no interlace */

    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    FILE *f = fopen(path, "wb");
    int result = -1;
    if (f) {
        result = fwrite(signature, 1, 8, f) == 8 && png_chunk(f, "IHDR", ihdr, 13) == 0 &&
                         png_chunk(f, "IDAT", z, (size_t)(p - z)) == 0 && png_chunk(f, "IEND", NULL, 0) == 0
                     ? 0
                     : -1;
        if (fclose(f) != 0)
            result = -1;
    }
    free(raw);
    free(z);
    return result;
}

#endif
