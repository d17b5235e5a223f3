/* clear_layers: a picture made only of clears, the one drawing operation every OSMesa
 * implementation has. A 256x256 RGBA buffer gets a background, bands from scissored
 * clears, then stripes from color-masked clears that change one channel and keep the
 * others, and nested squares. Writes <dir>/clear_layers.png (default dir: out).
 *
 *   gcc -std=c11 -I examples-c examples-c/clear_layers.c -lOSMesa -o clear_layers
 *   LD_LIBRARY_PATH=target/release ./clear_layers out     # on tessera
 *   ./clear_layers out                                    # on the system's Mesa
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include "png_write.h"

#define SIZE 256

static void clear_rect(int x, int y, int w, int h, float r, float g, float b)
{
    glScissor(x, y, w, h);
    glClearColor(r, g, b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    unsigned char *pixels = calloc(SIZE * SIZE, 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    if (!pixels || !ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, SIZE, SIZE)) {
        fprintf(stderr, "clear_layers: cannot create an OSMesa context\n");
        return 1;
    }
    printf("clear_layers: rendering with %s\n", (const char *)glGetString(GL_RENDERER));

    /* Background: a dark blue. */
    glClearColor(0.05f, 0.07f, 0.20f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);

    /* Horizontal bands getting lighter towards the top. */
    for (int i = 0; i < 16; i++)
        clear_rect(0, i * 16, SIZE, 8, 0.05f + i * 0.02f, 0.10f + i * 0.03f, 0.30f + i * 0.035f);

    /* Vertical stripes that set only red (color mask): each band keeps its green and blue. */
    glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
    for (int i = 0; i < 8; i++)
        clear_rect(i * 32 + 8, 0, 12, SIZE, 0.3f + i * 0.1f, 0, 0);
    /* ... and a wide horizontal stripe that sets only green. */
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE);
    clear_rect(0, 176, SIZE, 24, 0, 0.9f, 0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* Nested squares, alternating warm colors, in the middle. */
    for (int i = 0; i < 6; i++) {
        int inset = 48 + i * 10;
        float t = i / 5.0f;
        clear_rect(inset, inset - 24, SIZE - 2 * inset, SIZE - 2 * inset, i % 2 ? 1.0f : 0.9f - 0.3f * t,
                   i % 2 ? 0.85f - 0.4f * t : 0.3f, i % 2 ? 0.2f : 0.1f + 0.5f * t);
    }

    /* A small checkerboard in the corner, one blue-only clear per dark square. */
    glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE);
    for (int y = 0; y < 6; y++)
        for (int x = 0; x < 6; x++)
            if ((x + y) % 2)
                clear_rect(200 + x * 8, 200 + y * 8, 8, 8, 0, 0, 1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glFinish();

    char path[4096];
    snprintf(path, sizeof path, "%s/clear_layers.png", dir);
    if (png_write_rgba(path, SIZE, SIZE, pixels, 1) != 0) {
        fprintf(stderr, "clear_layers: cannot write %s\n", path);
        return 1;
    }
    printf("clear_layers: wrote %s\n", path);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(pixels);
    return 0;
}
