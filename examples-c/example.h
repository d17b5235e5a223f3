/* example.h: what every example shares, so each example file shows only its scene.
 *
 *   Example ex;
 *   example_start(&ex, "stencil_triangle", argc, argv, 600, 200, 24, 8);  // RGBA8 + depth + stencil
 *   panel(&ex, 0, 3, 1, 0.1f, 0.1f, 0.1f);   // viewport + scissor on panel 0 of 3x1, cleared
 *   ...draw...
 *   panel_label(&ex, 0, 3, 1, "STEP 1");        // a caption in the panel's corner
 *   example_save(&ex, "stencil_triangle");    // writes <dir>/stencil_triangle.png
 *   return example_finish(&ex);
 *
 * The output directory is argv[1] (default "out"). Images are written opaque (alpha 255), as
 * a window would show them: the examples are about the colors a person sees. No lighting and
 * no textures: colors come from glColor (flat or smooth) and fog only. No GLU either: the
 * few helpers below build the same matrices as gluPerspective and gluLookAt.
 */
#ifndef EXAMPLE_H
#define EXAMPLE_H

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "png_write.h"

typedef struct {
    const char *name; /* the example's name, for messages */
    const char *dir;  /* where the PNG files go */
    OSMesaContext ctx;
    unsigned char *rgba; /* the OSMesa color buffer, RGBA8, bottom row first */
    int width, height;
} Example;

static inline void example_die(const char *name, const char *what)
{
    fprintf(stderr, "%s: %s\n", name, what);
    exit(1);
}

/* Creates an RGBA8 OSMesa context of width x height with the given depth and stencil bits,
 * makes it current and prints which implementation renders. */
static inline void example_start(Example *ex, const char *name, int argc, char **argv, int width, int height,
                          int depth_bits, int stencil_bits)
{
    ex->name = name;
    ex->dir = argc > 1 ? argv[1] : "out";
    ex->width = width;
    ex->height = height;
    ex->rgba = calloc((size_t)width * height, 4);
    ex->ctx = OSMesaCreateContextExt(OSMESA_RGBA, depth_bits, stencil_bits, 0, NULL);
    if (!ex->rgba || !ex->ctx || !OSMesaMakeCurrent(ex->ctx, ex->rgba, GL_UNSIGNED_BYTE, width, height))
        example_die(name, "cannot create an OSMesa context");
    printf("%s: rendering with %s\n", name, (const char *)glGetString(GL_RENDERER));
}

/* Writes width x height RGBA8 pixels (bottom row first) as <dir>/<image>.png, opaque. */
static inline void example_write_png(const Example *ex, const char *image, int width, int height,
                              const unsigned char *rgba)
{
    unsigned char *opaque = malloc((size_t)width * height * 4);
    if (!opaque)
        example_die(ex->name, "out of memory");
    memcpy(opaque, rgba, (size_t)width * height * 4);
    for (size_t i = 0; i < (size_t)width * height; i++)
        opaque[i * 4 + 3] = 255;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.png", ex->dir, image);
    if (png_write_rgba(path, width, height, opaque, 1) != 0)
        example_die(ex->name, "cannot write a PNG file (does the output directory exist?)");
    printf("%s: wrote %s\n", ex->name, path);
    free(opaque);
}

/* Finishes rendering and writes the color buffer as <dir>/<image>.png. */
static inline void example_save(const Example *ex, const char *image)
{
    glFinish();
    if (glGetError() != GL_NO_ERROR)
        example_die(ex->name, "a GL call failed");
    example_write_png(ex, image, ex->width, ex->height, ex->rgba);
}

static inline int example_finish(Example *ex)
{
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ex->ctx);
    free(ex->rgba);
    return 0;
}

/* Selects panel `index` of a columns x rows grid (panel 0 at the top left, row by row):
 * viewport and scissor cover it, and it is cleared to (r, g, b) with depth 1 and stencil 0.
 * The scissor test stays enabled, so nothing drawn for this panel leaks into another. */
static inline void panel(const Example *ex, int index, int columns, int rows, float r, float g, float b)
{
    int w = ex->width / columns, h = ex->height / rows;
    int x = (index % columns) * w, y = ex->height - (index / columns + 1) * h;
    glViewport(x, y, w, h);
    glScissor(x, y, w, h);
    glEnable(GL_SCISSOR_TEST);
    glClearColor(r, g, b, 1.0f);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* Projection: x in [0, w], y in [0, h] (y up), z in [-1, 1] (depth 0.5 at z = 0, depth 0 at
 * z = 1, depth 1 at z = -1); modelview: identity. */
static inline void ortho(float w, float h)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* gluPerspective: loads the projection matrix; modelview becomes identity. */
static inline void perspective(double fovy_degrees, double aspect, double near, double far)
{
    double top = near * tan(fovy_degrees * 3.14159265358979323846 / 360.0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-top * aspect, top * aspect, -top, top, near, far);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* gluLookAt: multiplies the current matrix by the camera at `eye` looking at `center`. */
static inline void look_at(double ex, double ey, double ez, double cx, double cy, double cz, double ux, double uy,
                    double uz)
{
    double f[3] = {cx - ex, cy - ey, cz - ez};
    double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int i = 0; i < 3; i++)
        f[i] /= fl;
    double s[3] = {f[1] * uz - f[2] * uy, f[2] * ux - f[0] * uz, f[0] * uy - f[1] * ux};
    double sl = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int i = 0; i < 3; i++)
        s[i] /= sl;
    double u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
    GLdouble m[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, 0, 0, 0, 1};
    glMultMatrixd(m);
    glTranslated(-ex, -ey, -ez);
}

/* An axis-aligned rectangle in the xy plane at height z (counter-clockwise from below-left). */
static inline void rect_z(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

static inline void rect(float x0, float y0, float x1, float y1) { rect_z(x0, y0, x1, y1, 0.0f); }

/* A cube from (x0,y0,z0) to (x1,y1,z1), each face its own flat color from `colors` (six RGB
 * triples: -x, +x, -y, +y, -z, +z), faces counter-clockwise seen from outside. */
static inline void box(float x0, float y0, float z0, float x1, float y1, float z1, const float colors[6][3])
{
    const float v[8][3] = {{x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0},
                           {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}};
    static const int faces[6][4] = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                    {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        glColor3fv(colors[f]);
        for (int k = 0; k < 4; k++)
            glVertex3fv(v[faces[f][k]]);
    }
    glEnd();
}

/* Labels: a 3x5 pixel font (rows top to bottom, '1' = lit), drawn as axis-aligned quads
 * with integer corners, so every implementation covers exactly the same pixels. */
static const char *const label_glyphs[][2] = {
    {"A", "010101111101101"}, {"B", "110101110101110"}, {"C", "011100100100011"}, {"D", "110101101101110"},
    {"E", "111100110100111"}, {"F", "111100110100100"}, {"G", "011100101101011"}, {"H", "101101111101101"},
    {"I", "111010010010111"}, {"J", "001001001101010"}, {"K", "101101110101101"}, {"L", "100100100100111"},
    {"M", "101111111101101"}, {"N", "110101101101101"}, {"O", "010101101101010"}, {"P", "110101110100100"},
    {"Q", "010101101110011"}, {"R", "110101110101101"}, {"S", "011100010001110"}, {"T", "111010010010010"},
    {"U", "101101101101111"}, {"V", "101101101101010"}, {"W", "101101111111101"}, {"X", "101101010101101"},
    {"Y", "101101010010010"}, {"Z", "111001010100111"}, {"0", "111101101101111"}, {"1", "010110010010111"},
    {"2", "110001010100111"}, {"3", "110001010001110"}, {"4", "101101111001001"}, {"5", "111100110001110"},
    {"6", "011100111101111"}, {"7", "111001010010010"}, {"8", "111101111101111"}, {"9", "111101111001110"},
    {"_", "000000000000111"}, {"-", "000000111000000"}, {".", "000000000000010"}, {",", "000000000010100"},
    {"+", "000010111010000"}, {"(", "001010010010001"}, {")", "100010010010100"}, {"/", "001001010100100"},
    {"=", "000111000111000"}, {":", "000010000010000"}, {">", "100010001010100"}, {"<", "001010100010001"},
};

/* Writes `text` (upper case, digits, _-.,+()/=:<> and spaces) with its lower left corner at
 * window pixel (x, y), `scale` pixels per font pixel, white on a black box. GL state and
 * matrices are saved and restored, so a label can be drawn at any point. */
static inline void label(const Example *ex, int x, int y, int scale, const char *text)
{
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glDisable(GL_SCISSOR_TEST), glDisable(GL_DEPTH_TEST), glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND), glDisable(GL_COLOR_LOGIC_OP), glDisable(GL_ALPHA_TEST), glDisable(GL_FOG);
    glDisable(GL_CULL_FACE), glDisable(GL_CLIP_PLANE0), glDisable(GL_DITHER);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glShadeModel(GL_FLAT);
    glViewport(0, 0, ex->width, ex->height);
    ortho((float)ex->width, (float)ex->height);
    int n = (int)strlen(text);
    glColor3f(0, 0, 0);
    rect((float)x - scale, (float)y - scale, (float)(x + n * 4 * scale), (float)(y + 6 * scale));
    glColor3f(1, 1, 1);
    for (int i = 0; i < n; i++) {
        const char *bits = NULL;
        for (size_t g = 0; g < sizeof label_glyphs / sizeof label_glyphs[0]; g++)
            if (label_glyphs[g][0][0] == text[i])
                bits = label_glyphs[g][1];
        for (int k = 0; bits && k < 15; k++)
            if (bits[k] == '1') {
                int px = x + (i * 4 + k % 3) * scale, py = y + (4 - k / 3) * scale;
                rect((float)px, (float)py, (float)(px + scale), (float)(py + scale));
            }
    }
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
    glPopAttrib();
}

/* A label in the top left corner of panel `index` of a columns x rows grid (see panel()). */
static inline void panel_label(const Example *ex, int index, int columns, int rows, const char *text)
{
    int w = ex->width / columns, h = ex->height / rows;
    int x = (index % columns) * w, y = ex->height - (index / columns) * h;
    label(ex, x + 6, y - 16, 2, text);
}

#endif
