/* Texture environments against Mesa: MODULATE, DECAL, BLEND, REPLACE and ADD on every base
 * format, GL_COMBINE with every function, source (incl. another unit's texture), operand and
 * scale, two and four units chained, and the texture matrix of each unit. Every quad has a
 * smooth primary color so that PREVIOUS and PRIMARY_COLOR vary. */
#include "common.h"

#define W 32
#define H 32

static unsigned rng = 99;
static unsigned char rnd(void)
{
    rng = rng * 1103515245u + 12345u;
    return (unsigned char)(rng >> 16);
}

static void textured_quad(void)
{
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    static const float color[4][4] = {{1, 0.2f, 0.4f, 0.9f}, {0.3f, 0.9f, 0.1f, 0.6f}, {0.2f, 0.5f, 1, 0.2f},
                                      {0.8f, 0.8f, 0.7f, 1}};
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; i++) {
        glColor4fv(color[i]);
        for (int u = 0; u < 4; u++)
            glMultiTexCoord2f(GL_TEXTURE0 + u, (corner[i][0] + 1) * 0.5f, (corner[i][1] + 1) * 0.5f);
        glVertex2fv(corner[i]);
    }
    glEnd();
}

/* An 8x8 random texture on unit `unit` in `internal` format, NEAREST. */
static void random_texture(int unit, GLenum internal)
{
    unsigned char img[8 * 8 * 4];
    for (int i = 0; i < (int)sizeof img; i++)
        img[i] = rnd();
    glActiveTexture(GL_TEXTURE0 + unit);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
}

static void classic_modes(void)
{
    static const GLenum modes[] = {GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD};
    static const char *mode_names[] = {"modulate", "decal", "blend", "replace", "add"};
    static const GLenum formats[] = {GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_INTENSITY, GL_RGB, GL_RGBA};
    static const char *format_names[] = {"alpha", "luminance", "la", "intensity", "rgb", "rgba"};
    const GLfloat env_color[4] = {0.3f, 0.6f, 0.9f, 0.45f};
    for (int f = 0; f < 6; f++) {
        random_texture(0, formats[f]);
        for (int m = 0; m < 5; m++) {
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modes[m]);
            glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
            textured_quad();
            char name[64];
            snprintf(name, sizeof name, "%s_%s", mode_names[m], format_names[f]);
            capi_save_framebuffer(name, W, H);
        }
    }
    glDisable(GL_TEXTURE_2D);
}

static void combine(void)
{
    static const GLenum functions[] = {GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE,
                                       GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA};
    static const char *names[] = {"replace", "modulate", "add", "add_signed", "interpolate", "subtract", "dot3_rgb",
                                  "dot3_rgba"};
    static const GLenum sources[] = {GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS, GL_TEXTURE0, GL_TEXTURE1};
    static const GLenum rgb_operands[] = {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};
    const GLfloat env_color[4] = {0.7f, 0.25f, 0.5f, 0.35f};
    random_texture(0, GL_RGBA);
    random_texture(1, GL_RGBA);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
    char name[64];
    for (int f = 0; f < 8; f++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, functions[f]);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, functions[f < 6 ? f : 1]);
        for (int k = 0; k < 3; k++) {
            /* Arguments rotate through the sources and operands. */
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + k, sources[(f + k) % 6]);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + k, sources[(f + 2 * k + 1) % 6]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + k, rgb_operands[(f + k) % 4]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + k, k == 1 ? GL_ONE_MINUS_SRC_ALPHA : GL_SRC_ALPHA);
        }
        for (int scale = 1; scale <= 4; scale *= 2) {
            glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, scale);
            glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 6 / scale - 1 > 2 ? 4 : 1);
            textured_quad();
            snprintf(name, sizeof name, "combine_%s_%d", names[f], scale);
            capi_save_framebuffer(name, W, H);
        }
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1);
    /* Every operand of every source, with REPLACE and INTERPOLATE. */
    for (int s = 0; s < 6; s++) {
        for (int o = 0; o < 4; o++) {
            glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
            glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, sources[s]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, rgb_operands[o]);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PREVIOUS);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, sources[(s + 1) % 6]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, rgb_operands[(o + 2) % 4]);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, sources[s]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, o % 2 ? GL_ONE_MINUS_SRC_ALPHA : GL_SRC_ALPHA);
            textured_quad();
            snprintf(name, sizeof name, "operand_%d_%d", s, o);
            capi_save_framebuffer(name, W, H);
        }
    }
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glDisable(GL_TEXTURE_2D);
}

/* Four units chained, each with its own texture matrix and mode. */
static void multitexture(void)
{
    static const GLenum modes[] = {GL_MODULATE, GL_ADD, GL_DECAL, GL_BLEND};
    static const GLenum formats[] = {GL_RGB, GL_LUMINANCE, GL_RGBA, GL_INTENSITY};
    for (int u = 0; u < 4; u++) {
        random_texture(u, formats[u]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modes[u]);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glRotatef(15.0f * (float)u, 0, 0, 1);
        glScalef(1.0f + 0.37f * (float)u, 1.0f + 0.21f * (float)u, 1);
    }
    textured_quad();
    capi_save_framebuffer("four_units", W, H);
    /* Unit 2 disabled: units 0, 1 and 3 remain. */
    glActiveTexture(GL_TEXTURE2);
    glDisable(GL_TEXTURE_2D);
    textured_quad();
    capi_save_framebuffer("units_013", W, H);
    for (int u = 0; u < 4; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        glLoadIdentity();
        glDisable(GL_TEXTURE_2D);
    }
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_MODELVIEW);
}

/* Texturing precedes the color sum, fog and the alpha test: a cut-out texture under the
 * alpha test, with a secondary color and fog, in front of a depth-tested quad. */
static void with_fragment_ops(void)
{
    random_texture(0, GL_RGBA);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.4f);
    glEnable(GL_COLOR_SUM);
    glSecondaryColor3f(0.2f, 0.1f, 0.0f);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.0f);
    glFogf(GL_FOG_END, 2.0f);
    textured_quad();
    capi_save_framebuffer("alpha_test_sum_fog", W, H);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_COLOR_SUM);
    glDisable(GL_FOG);
    glDisable(GL_TEXTURE_2D);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glShadeModel(GL_SMOOTH);
    classic_modes();
    combine();
    multitexture();
    with_fragment_ops();
    return capi_finish();
}
