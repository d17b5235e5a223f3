/* Huge-draw memory probe: peak resident memory above the caller's own data for
 *   strip      glDrawArrays(GL_TRIANGLE_STRIP) of 10^6 vertices from a client array,
 *   immediate  the same strip between glBegin and glEnd,
 *   elements   glDrawElements(GL_TRIANGLES) of 10^7 GL_UNSIGNED_INT indices into 10^4 vertices,
 *   list       the strip's glDrawArrays compiled into a display list, then glCallList (the
 *              list, compiled before the first measure, counts as the caller's data),
 * each followed by glFinish, into a 512x512 RGBA8 OSMesa buffer. The caller's data (arrays,
 * indices, buffer) is allocated and touched first; the probe prints VmHWM (peak RSS) after
 * that and after the draw, and their difference, so what it prints is what the library
 * itself needed. It also writes a checksum of the image, to compare runs.
 * gcc -std=c11 -O2 tools/probes/huge_draws.c -lOSMesa -o /tmp/huge_draws
 * LD_LIBRARY_PATH=target/release /tmp/huge_draws strip   (or immediate, elements) */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define W 512

static long peak_kib(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    long kib = -1;
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "VmHWM: %ld", &kib) == 1)
            break;
    if (f)
        fclose(f);
    return kib;
}

/* Strip vertex i: rows of 1000 columns zig-zagging between two heights, 0.5 px apart in x. */
static void strip_vertex(long i, float *xy)
{
    long column = (i / 2) % 1000, row = (i / 2) / 1000;
    xy[0] = 4.0f + 0.5f * column;
    xy[1] = (float)((row % 250) * 2 + (i & 1) * 2) + 0.25f;
}

int main(int argc, char **argv)
{
    const char *what = argc > 1 ? argv[1] : "strip";
    static unsigned char image[W * W * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, image, GL_UNSIGNED_BYTE, W, W))
        return 1;
    glViewport(0, 0, W, W);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, W, -1, 1);
    glShadeModel(GL_SMOOTH);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    const long strip = 1000000, vertices = 10000, indices = 10000000;
    float *xy = NULL, *rgb = NULL;
    unsigned *index = NULL;
    long n = strcmp(what, "elements") == 0 ? vertices : strip;
    xy = malloc(sizeof(float) * 2 * n);
    rgb = malloc(sizeof(float) * 3 * n);
    for (long i = 0; i < n; i++) {
        if (n == strip) {
            strip_vertex(i, xy + 2 * i);
        } else {
            xy[2 * i] = 1.0f + (float)(i % 100) * 5.0f;
            xy[2 * i + 1] = 1.0f + (float)(i / 100) * 5.0f;
        }
        rgb[3 * i] = (float)(i % 251) / 250.0f;
        rgb[3 * i + 1] = (float)(i % 241) / 240.0f;
        rgb[3 * i + 2] = (float)(i % 239) / 238.0f;
    }
    if (strcmp(what, "elements") == 0) {
        index = malloc(sizeof(unsigned) * indices);
        /* Triangles between neighbours of the 100 x 100 grid, cycling over it. */
        for (long t = 0; t < indices / 3; t++) {
            long cell = t % (99 * 99), a = cell / 99 * 100 + cell % 99;
            long b = (t & 1) ? a + 101 : a + 1, c = (t & 1) ? a + 100 : a + 101;
            index[3 * t] = (unsigned)a;
            index[3 * t + 1] = (unsigned)b;
            index[3 * t + 2] = (unsigned)c;
        }
        index[indices - 1] = 0;
    }
    GLuint list = 0;
    if (strcmp(what, "list") == 0) {
        list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, xy);
        glColorPointer(3, GL_FLOAT, 0, rgb);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, (GLsizei)n);
        glEndList();
    }
    long before = peak_kib();
    if (list) {
        glCallList(list);
    } else if (strcmp(what, "immediate") == 0) {
        glBegin(GL_TRIANGLE_STRIP);
        for (long i = 0; i < n; i++) {
            glColor3fv(rgb + 3 * i);
            glVertex2fv(xy + 2 * i);
        }
        glEnd();
    } else {
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, xy);
        glColorPointer(3, GL_FLOAT, 0, rgb);
        if (index)
            glDrawElements(GL_TRIANGLES, (GLsizei)indices, GL_UNSIGNED_INT, index);
        else
            glDrawArrays(GL_TRIANGLE_STRIP, 0, (GLsizei)n);
    }
    glFinish();
    long after = peak_kib();
    unsigned long sum = 0;
    for (long i = 0; i < W * W * 4; i++)
        sum = sum * 31 + image[i];
    printf("%s: peak RSS %ld MiB with the caller's data, %ld MiB above it; image checksum %016lx; error 0x%x\n",
           what, before / 1024, (after - before) / 1024, sum, glGetError());
    OSMesaDestroyContext(ctx);
    free(xy);
    free(rgb);
    free(index);
    return 0;
}
