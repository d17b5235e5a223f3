/* Per-vertex lighting results compared bit for bit with Mesa (llvmpipe): on a float color buffer with
 * every color clamp off, a grid of flat-shaded quads (each showing its provoking vertex's lit
 * color unchanged) with pseudo-random normals and depths, under directional lights with an
 * infinite viewer, a local light with attenuation and a spotlight under a local viewer,
 * lights brighter than 1 and negative, two-sided lighting (half of the quads wound
 * clockwise), GL_NORMALIZE and GL_RESCALE_NORMAL under scaled modelviews, and
 * GL_COLOR_MATERIAL; last with GL_CLAMP_VERTEX_COLOR on. (GL_FIXED_ONLY is not compared:
 * Mesa 22 treats OSMesa float buffers as fixed-point there, see get.rs.) */
#include "common.h"

#define W 32
#define H 32
#define N 16 /* quads per side, 2×2 pixels each */

static unsigned seed;
static float rnd(void)
{
    seed = seed * 1664525u + 1013904223u;
    return (float)(seed >> 8) / (float)(1 << 24);
}

static void grid(int colored)
{
    seed = 12345;
    glBegin(GL_QUADS);
    for (int j = 0; j < N; j++) {
        for (int i = 0; i < N; i++) {
            float x0 = -1 + 2.0f * i / N, x1 = -1 + 2.0f * (i + 1) / N;
            float y0 = -1 + 2.0f * j / N, y1 = -1 + 2.0f * (j + 1) / N;
            float z = -rnd() * 0.8f;
            /* The provoking (last) vertex carries the normal that matters. */
            glNormal3f(rnd() * 2 - 1, rnd() * 2 - 1, rnd() * 1.5f - 0.3f);
            if (colored)
                glColor4f(rnd(), rnd(), rnd(), rnd());
            if ((i + j) & 1) { /* clockwise: back-facing */
                glVertex3f(x0, y0, z);
                glVertex3f(x0, y1, z);
                glVertex3f(x1, y1, z);
                glVertex3f(x1, y0, z);
            } else {
                glVertex3f(x0, y0, z);
                glVertex3f(x1, y0, z);
                glVertex3f(x1, y1, z);
                glVertex3f(x0, y1, z);
            }
        }
    }
    glEnd();
}

static void begin_case(void)
{
    glPopAttrib();
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glClampColor(GL_CLAMP_VERTEX_COLOR, GL_FALSE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -4);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_FLAT);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    const GLfloat spec[4] = {0.6f, 0.5f, 0.4f, 1}, diffuse[4] = {0.9f, 0.8f, 0.7f, 0.6f};
    const GLfloat emission[4] = {0.01f, 0.02f, 0.03f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_EMISSION, emission);
    glMaterialf(GL_FRONT, GL_SHININESS, 13.0f);
    glMaterialf(GL_BACK, GL_SHININESS, 50.0f);
}

static void save(const char *name)
{
    static GLfloat pixels[W * H * 4];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, pixels);
    capi_save_image(name, W, H, 4, CAPI_F32, pixels);
}

static void directional(void)
{
    begin_case();
    const GLfloat bright[4] = {2.5f, 1.25f, 0.5f, 1}, negative[4] = {-0.75f, 0.0f, -0.25f, 1};
    const GLfloat pos0[4] = {0.2f, 0.5f, 1, 0}, pos1[4] = {-0.6f, 0.2f, 0.7f, 0};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, bright);
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, negative);
    glLightfv(GL_LIGHT1, GL_SPECULAR, bright);
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glEnable(GL_LIGHT1);
    grid(0);
    save("directional");
}

static void local(int two_side)
{
    begin_case();
    const GLfloat pos0[4] = {0.3f, 0.4f, 1.5f, 1}, pos1[4] = {-0.5f, -0.2f, -2.0f, 1};
    const GLfloat dir1[3] = {0.3f, 0.1f, -1}, amb[4] = {0.1f, 0.05f, 0.02f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.7f);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.2f);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.05f);
    glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
    glLoadIdentity();
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, dir1);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 60.0f);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 3.0f);
    const GLfloat white[4] = {1, 1, 1, 1};
    glLightfv(GL_LIGHT1, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT1, GL_SPECULAR, white);
    glEnable(GL_LIGHT1);
    glTranslatef(0, 0, -4);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two_side);
    grid(0);
    save(two_side ? "local_two_side" : "local");
}

static void scaled(GLenum mode, const char *name)
{
    begin_case();
    glEnable(mode);
    glScalef(0.5f, mode == GL_NORMALIZE ? 0.8f : 0.5f, 0.5f);
    glScalef(2, 2, 2);
    glRotatef(20, 1, 1, 0);
    glScalef(0.5f, 0.5f, 0.5f);
    grid(0);
    save(name);
}

static void color_material(void)
{
    begin_case();
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    const GLfloat amb[4] = {0.3f, 0.2f, 0.1f, 1};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    grid(1);
    save("color_material");
}

static void clamped(void)
{
    begin_case();
    glClampColor(GL_CLAMP_VERTEX_COLOR, GL_TRUE);
    const GLfloat bright[4] = {2.5f, 1.25f, 0.5f, 1};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, bright);
    grid(0);
    save("clamped");
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_FLOAT, 0, 0, 0, W, H, &buffer);
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    directional();
    local(0);
    local(1);
    scaled(GL_NORMALIZE, "normalize");
    scaled(GL_RESCALE_NORMAL, "rescale");
    color_material();
    clamped();
    GLfloat p[4];
    glReadPixels(W / 2, H / 2, 1, 1, GL_RGBA, GL_FLOAT, p);
    capi_check(p[0] <= 1.0f, "clamped per vertex: %g", p[0]);
    capi_expect_error(GL_NO_ERROR, "float lighting");
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
