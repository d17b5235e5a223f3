/* Bounded memory for huge draws: a 10^6-vertex glBegin/glEnd triangle strip, line loop,
 * triangle fan and polygon (as its outline), a 10^7-index glDrawElements (triangles) and a
 * 10^6-index one (triangle strip), each drawing a picture compared with Mesa's (the other
 * connected modes, the stipple and flat shading across parts are compared with the whole
 * draw by the unit test long_primitives_in_parts_draw_the_same_pixels_as_whole). The growth of the peak resident size over each
 * draw (VmHWM, reset before the draw through /proc/self/clear_refs) is printed for the
 * notes and bounded on tessera: vertices are delivered in bounded parts and the binned
 * scene is rendered when it grows past its bound, so a draw needs the same memory
 * whatever its length. (Mesa streams too; its figures are printed, not asserted.)
 * The polygon's outline is checked analytically instead of against Mesa: Mesa 22 splits a
 * long GL_POLYGON where its vertex buffer wraps and draws the split edges as outline edges
 * (GL 2.1 section 3.5.4: only the polygon's boundary edges are drawn); tessera draws one
 * polygon, so no pixel inside the circle is lit. */
#define _DEFAULT_SOURCE
#include "common.h"
#include <math.h>

enum { W = 128, H = 128, MILLION = 1000000 };

/* Peak resident size growth bound on tessera, in MiB: the scene's budget is 64 MiB, the
 * parts of vertices and the pipeline's per-draw storage a few MiB. Before the streaming
 * work a 10^6-vertex strip grew the process by 574 MiB and the 10^7 indices by 1053 MiB. */
#define MAX_GROWTH_MIB 100


/* Resets VmHWM to the current resident size (Linux 4.0+: "5" to clear_refs). */
static void reset_peak(void)
{
    FILE *f = fopen("/proc/self/clear_refs", "w");
    capi_check(f != NULL, "cannot open /proc/self/clear_refs");
    if (f) {
        fputs("5", f);
        fclose(f);
    }
}

static int tessera;

/* Checks and prints the peak growth since `base` (MiB) of draw `name`. */
static void check_growth(const char *name, long base)
{
    long growth = capi_status_mib("VmHWM:") - base;
    printf("%s: peak resident growth %ld MiB\n", name, growth);
    if (tessera)
        capi_check(growth <= MAX_GROWTH_MIB, "%s: peak grew by %ld MiB (bound %d)", name, growth, MAX_GROWTH_MIB);
}

/* Vertex i of a long primitive: a spiral of 40 turns around the centre whose radius and
 * color change slowly, so that neighbouring strip triangles are thin but cover pixels. */
static void spiral_vertex(int i, int count, int zigzag)
{
    float t = (float)i / count;
    float angle = t * 40.0f * 6.2831853f;
    float r = 8.0f + 52.0f * t + (zigzag && (i & 1) ? 6.0f : 0.0f);
    glColor3f(t, 1.0f - t, (i & 1024) ? 1.0f : 0.25f);
    glVertex2f(W / 2 + r * cosf(angle), H / 2 + r * sinf(angle));
}

static void immediate(const char *name, GLenum mode, int zigzag)
{
    glClear(GL_COLOR_BUFFER_BIT);
    reset_peak();
    long base = capi_status_mib("VmRSS:");
    glBegin(mode);
    for (int i = 0; i < MILLION; i++)
        spiral_vertex(i, MILLION, zigzag);
    glEnd();
    glFinish();
    check_growth(name, base);
    capi_expect_error(GL_NO_ERROR, name);
    capi_save_framebuffer(name, W, H);
}

int main(void)
{
    tessera = capi_probe_is_tessera();
    void *buffer;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, &buffer);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0, 0, 0, 1);

    glShadeModel(GL_FLAT);
    immediate("triangle_strip", GL_TRIANGLE_STRIP, 1);
    glShadeModel(GL_SMOOTH);
    immediate("line_loop", GL_LINE_LOOP, 0);
    immediate("triangle_fan", GL_TRIANGLE_FAN, 0);
    /* A polygon of 10^6 vertices on a circle (convex), drawn as its outline. */
    for (int outline = 1; outline < 2; outline++) {
        glPolygonMode(GL_FRONT_AND_BACK, outline ? GL_LINE : GL_FILL);
        glClear(GL_COLOR_BUFFER_BIT);
        reset_peak();
        long base = capi_status_mib("VmRSS:");
        glBegin(GL_POLYGON);
        for (int i = 0; i < MILLION; i++) {
            float angle = (float)i / MILLION * 6.2831853f;
            glColor3f((float)i / MILLION, 0.5f, 1.0f - (float)i / MILLION);
            glVertex2f(W / 2 + 50.5f * cosf(angle), H / 2 + 50.5f * sinf(angle));
        }
        glEnd();
        glFinish();
        const char *name = outline ? "polygon_outline" : "polygon";
        check_growth(name, base);
        capi_expect_error(GL_NO_ERROR, name);
        if (!outline) {
            capi_save_framebuffer(name, W, H);
            continue;
        }
        static GLubyte pixels[W * H * 4];
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        int inside = 0, boundary = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                float dx = x + 0.5f - W / 2, dy = y + 0.5f - H / 2, r = sqrtf(dx * dx + dy * dy);
                int lit = pixels[4 * (y * W + x)] | pixels[4 * (y * W + x) + 2];
                inside += lit && r < 48.0f;
                boundary += lit && r > 49.0f && r < 52.0f;
            }
        printf("polygon outline: %d pixels lit inside, %d on the circle\n", inside, boundary);
        capi_check(boundary > 250, "polygon outline: only %d pixels on the circle", boundary);
        if (tessera)
            capi_check(inside == 0, "polygon outline: %d pixels inside the polygon are lit", inside);
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

    /* Array draws: a grid of 64 x 64 vertices, 10^7 indices of small triangles cycling over
     * the grid's cells (depth test off: later triangles paint over earlier ones), and a
     * 10^6-index triangle strip through the same grid. */
    enum { G = 64, INDICES = 10000000 };
    static float grid[G * G * 2], colors[G * G * 3];
    for (int y = 0; y < G; y++)
        for (int x = 0; x < G; x++) {
            int i = y * G + x;
            grid[2 * i] = x * 2.0f + 0.3f;
            grid[2 * i + 1] = y * 2.0f + 0.6f;
            colors[3 * i] = x / (float)G;
            colors[3 * i + 1] = y / (float)G;
            colors[3 * i + 2] = ((x ^ y) & 1) ? 1.0f : 0.0f;
        }
    unsigned *indices = malloc(sizeof(unsigned) * INDICES);
    capi_check(indices != NULL, "no memory for the indices");
    if (!indices)
        return capi_finish();
    for (int t = 0; t < INDICES / 3; t++) {
        int cell = (int)(((unsigned)t * 2654435761u) % ((G - 1) * (G - 1)));
        int x = cell % (G - 1), y = cell / (G - 1);
        unsigned a = y * G + x;
        indices[3 * t] = a;
        indices[3 * t + 1] = (t & 1) ? a + G + 1 : a + 1;
        indices[3 * t + 2] = a + G;
    }
    indices[INDICES - 1] = 0;
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, grid);
    glColorPointer(3, GL_FLOAT, 0, colors);
    glClear(GL_COLOR_BUFFER_BIT);
    reset_peak();
    long base = capi_status_mib("VmRSS:");
    glDrawElements(GL_TRIANGLES, INDICES, GL_UNSIGNED_INT, indices);
    glFinish();
    check_growth("elements_triangles", base);
    capi_expect_error(GL_NO_ERROR, "10^7-index glDrawElements");
    capi_save_framebuffer("elements_triangles", W, H);

    /* The strip zigzags along the grid rows, row after row, again and again. */
    for (int i = 0; i < MILLION; i++) {
        int k = i % (2 * G * (G - 1));
        int row = k / (2 * G), col = (k % (2 * G)) / 2;
        indices[i] = (unsigned)((row + (k & 1)) * G + col);
    }
    glShadeModel(GL_FLAT);
    glClear(GL_COLOR_BUFFER_BIT);
    reset_peak();
    base = capi_status_mib("VmRSS:");
    glDrawElements(GL_TRIANGLE_STRIP, MILLION, GL_UNSIGNED_INT, indices);
    glFinish();
    check_growth("elements_strip", base);
    capi_expect_error(GL_NO_ERROR, "10^6-index strip");
    capi_save_framebuffer("elements_strip", W, H);
    free(indices);

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
