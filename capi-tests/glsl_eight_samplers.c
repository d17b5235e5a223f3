/* Eight texture image units for a fragment shader (GL 2.0 sections 2.15.3 and 3.11.2):
 * GL_MAX_TEXTURE_IMAGE_UNITS and GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS are at least 8 (tessera:
 * exactly 8; llvmpipe: 32 and 192), eight textures bound on units 0-7 are sampled by one
 * shader through a sampler array whose elements name the units in a shuffled order, the
 * texture bindings and parameters of units 4-7 are per unit (queries, glPushAttrib), the
 * active-sampler-conflict validation covers units 4-7, and a sampler set to a unit past the
 * combined count is GL_INVALID_VALUE. Tessera keeps fixed-function texturing (enables,
 * environment) to its 4 units: those calls on units 4-7 are GL_INVALID_OPERATION there
 * (Mesa 22 accepts them on all 192 of its units), checked apart from the compared values. */
#include "common.h"

#define W 64
#define H 16

/* Colour code c (0-7) as RGB bits: red 1, green 2, blue 4. */
static void code_color(int c, GLubyte *out)
{
    out[0] = (c & 1) ? 255 : 0;
    out[1] = (c & 2) ? 255 : 0;
    out[2] = (c & 4) ? 255 : 0;
    out[3] = 255;
}

/* Texel j (0-3, rows bottom-up) of texture k has colour code (k + 3j) mod 8: every texture
 * and every texel of one texture differ. */
static int texel_code(int k, int j)
{
    return (k + 3 * j) % 8;
}

static const char *VS = "void main() {\n"
                        "  gl_Position = ftransform();\n"
                        "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
                        "}\n";

static const char *FS = "uniform sampler2D tex[8];\n"
                        "uniform float w[8];\n"
                        "void main() {\n"
                        "  vec2 uv = gl_TexCoord[0].xy;\n"
                        "  gl_FragColor = w[0] * texture2D(tex[0], uv) + w[1] * texture2D(tex[1], uv)\n"
                        "      + w[2] * texture2D(tex[2], uv) + w[3] * texture2D(tex[3], uv)\n"
                        "      + w[4] * texture2D(tex[4], uv) + w[5] * texture2D(tex[5], uv)\n"
                        "      + w[6] * texture2D(tex[6], uv) + w[7] * texture2D(tex[7], uv);\n"
                        "}\n";

/* Which unit each element of tex[] names. */
static const GLint PERM[8] = {5, 2, 7, 0, 6, 3, 1, 4};

/* The weights of the mixed row: powers of two, so that each channel (a sum of four of them:
 * every colour bit is set in four of the eight textures' texels j) is a multiple of 1/128
 * other than 1/2, never halfway between two 8-bit values. */
static const GLfloat MIX[8] = {0.5f, 0.25f, 0.125f, 0.0625f, 0.03125f, 0.015625f, 0.0078125f, 0.0078125f};

static void quad(float x, float y, float side)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(x, y);
    glTexCoord2f(1, 0);
    glVertex2f(x + side, y);
    glTexCoord2f(1, 1);
    glVertex2f(x + side, y + side);
    glTexCoord2f(0, 1);
    glVertex2f(x, y + side);
    glEnd();
}

static void limits(void)
{
    static const struct {
        const char *name;
        GLenum pname;
    } L[] = {
        {"MAX_TEXTURE_IMAGE_UNITS", GL_MAX_TEXTURE_IMAGE_UNITS},
        {"MAX_COMBINED_TEXTURE_IMAGE_UNITS", GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS},
    };
    for (int i = 0; i < 2; i++) {
        GLint n = -1;
        glGetIntegerv(L[i].pname, &n);
        capi_check(n >= 8, "%s is %d, want at least 8", L[i].name, n);
        if (capi_is_tessera())
            capi_check(n == 8, "tessera's %s is %d, want 8", L[i].name, n);
    }
    GLint coords = 0, combined = 0, vertex_units = -1;
    glGetIntegerv(GL_MAX_TEXTURE_COORDS, &coords);
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &combined);
    glGetIntegerv(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS, &vertex_units);
    if (capi_is_tessera())
        capi_check(vertex_units == 0, "tessera's vertex shaders sample no textures, yet it reports %d units",
                   vertex_units);
    /* glActiveTexture reaches the larger of the two counts, minus one (GL 2.0 section 2.7). */
    GLint last = (coords > combined ? coords : combined) - 1;
    glActiveTexture(GL_TEXTURE0 + last);
    capi_expect_error(GL_NO_ERROR, "active_texture_last");
    glActiveTexture(GL_TEXTURE0 + last + 1);
    capi_expect_error(GL_INVALID_ENUM, "active_texture_past_last");
    glActiveTexture(GL_TEXTURE0);
}

/* The per-unit state of units 4-7: bindings, parameters, the texture attribute group. */
static void unit_state(const GLuint *textures)
{
    char key[64];
    for (int unit = 4; unit < 8; unit++) {
        glActiveTexture(GL_TEXTURE0 + unit);
        GLint bound = -1;
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
        capi_check(bound == (GLint)textures[unit], "unit %d: GL_TEXTURE_BINDING_2D %d, want %u", unit, bound,
                   textures[unit]);
        snprintf(key, sizeof key, "unit%d.binding_is_own", unit);
        capi_value(key, "%d", bound == (GLint)textures[unit]);
        GLint filter = 0;
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
        snprintf(key, sizeof key, "unit%d.min_filter", unit);
        capi_value(key, "0x%x", filter);
        GLint width = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
        snprintf(key, sizeof key, "unit%d.width", unit);
        capi_value(key, "%d", width);
    }
    capi_expect_error(GL_NO_ERROR, "unit_state");

    /* GL_TEXTURE_BIT keeps every unit's bindings. */
    glActiveTexture(GL_TEXTURE6);
    glPushAttrib(GL_TEXTURE_BIT);
    glBindTexture(GL_TEXTURE_2D, textures[1]);
    GLint bound = -1;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    capi_value("attrib.rebound_is_texture1", "%d", bound == (GLint)textures[1]);
    glActiveTexture(GL_TEXTURE2);
    glPopAttrib();
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    capi_value("attrib.active_unit", "%d", active - GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    capi_check(bound == (GLint)textures[6], "unit 6 after glPopAttrib: binding %d, want %u", bound, textures[6]);
    capi_value("attrib.restored", "%d", bound == (GLint)textures[6]);
    capi_expect_error(GL_NO_ERROR, "attrib");

    /* Fixed-function texturing stops at tessera's 4 units. */
    if (capi_is_tessera()) {
        glActiveTexture(GL_TEXTURE5);
        glEnable(GL_TEXTURE_2D);
        capi_check(glGetError() == GL_INVALID_OPERATION, "glEnable(GL_TEXTURE_2D) on unit 5");
        glIsEnabled(GL_TEXTURE_2D);
        capi_check(glGetError() == GL_INVALID_OPERATION, "glIsEnabled(GL_TEXTURE_2D) on unit 5");
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
        capi_check(glGetError() == GL_INVALID_OPERATION, "glTexEnv on unit 5");
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        capi_check(glGetError() == GL_NO_ERROR, "glTexParameter on unit 5");
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    }
    glActiveTexture(GL_TEXTURE0);
}

/* The active-sampler-conflict validation on units 4-7 (GL 2.0 section 2.15.4). */
static void conflicts(void)
{
    GLuint p = capi_program("conflict", VS,
                            "uniform sampler2D a;\n"
                            "uniform sampler1D b;\n"
                            "void main() {\n"
                            "  gl_FragColor = texture2D(a, gl_TexCoord[0].xy) + texture1D(b, gl_TexCoord[0].x);\n"
                            "}\n");
    glUseProgram(p);
    GLint a = glGetUniformLocation(p, "a"), b = glGetUniformLocation(p, "b");
    GLint status = -1;
    glUniform1i(a, 6);
    glUniform1i(b, 6);
    glValidateProgram(p);
    glGetProgramiv(p, GL_VALIDATE_STATUS, &status);
    capi_check(status == GL_FALSE, "two sampler types on unit 6 validate");
    capi_value("conflict.same_unit6.validate", "%d", status);
    quad(0, 0, 1);
    capi_expect_error(GL_INVALID_OPERATION, "conflict.same_unit6.draw");
    glUniform1i(b, 7);
    glValidateProgram(p);
    glGetProgramiv(p, GL_VALIDATE_STATUS, &status);
    capi_check(status == GL_TRUE, "units 6 and 7 do not validate");
    capi_value("conflict.units6_7.validate", "%d", status);
    glUniform1i(a, 4);
    glUniform1i(b, 4);
    glValidateProgram(p);
    glGetProgramiv(p, GL_VALIDATE_STATUS, &status);
    capi_value("conflict.same_unit4.validate", "%d", status);
    glUniform1i(b, 0);
    capi_expect_error(GL_NO_ERROR, "conflict.units");

    /* A unit past the combined count is GL_INVALID_VALUE and changes nothing. */
    GLint combined = 0, unit = -1;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &combined);
    glUniform1i(a, 7);
    glUniform1i(a, combined);
    capi_expect_error(GL_INVALID_VALUE, "conflict.past_combined");
    glGetUniformiv(p, a, &unit);
    capi_value("conflict.past_combined.kept", "%d", unit);
    glUseProgram(0);
    glDeleteProgram(p);
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, &buffer);
    capi_pixel_ortho(W, H);
    limits();

    GLuint textures[8];
    glGenTextures(8, textures);
    for (int k = 0; k < 8; k++) {
        GLubyte texels[16];
        for (int j = 0; j < 4; j++)
            code_color(texel_code(k, j), texels + 4 * j);
        glActiveTexture(GL_TEXTURE0 + k);
        glBindTexture(GL_TEXTURE_2D, textures[k]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glActiveTexture(GL_TEXTURE0);
    capi_expect_error(GL_NO_ERROR, "textures");
    unit_state(textures);

    GLuint p = capi_program("eight", VS, FS);
    glUseProgram(p);
    glUniform1iv(glGetUniformLocation(p, "tex"), 8, PERM);
    GLint weights = glGetUniformLocation(p, "w");
    GLint set[8] = {0};
    glGetUniformiv(p, glGetUniformLocation(p, "tex[5]"), &set[5]);
    capi_value("uniform.tex5", "%d", set[5]);
    glValidateProgram(p);
    GLint status = 0;
    glGetProgramiv(p, GL_VALIDATE_STATUS, &status);
    capi_value("eight.validate", "%d", status);

    glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    /* Bottom row: column i shows tex[i] alone, the texture of unit PERM[i]. */
    for (int i = 0; i < 8; i++) {
        GLfloat w[8] = {0};
        w[i] = 1;
        glUniform1fv(weights, 8, w);
        quad(8.0f * i, 0, 8);
    }
    /* Top row: all eight at once, tex[i] weighing MIX[i]. */
    glUniform1fv(weights, 8, MIX);
    for (int i = 0; i < 8; i++)
        quad(8.0f * i, 8, 8);
    capi_expect_error(GL_NO_ERROR, "draw");

    GLubyte pixels[W * H * 4];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    int wrong = 0;
    for (int i = 0; i < 8; i++) {
        for (int j = 0; j < 4; j++) {
            int x = 8 * i + 2 + 4 * (j & 1), y = 2 + 4 * (j >> 1);
            GLubyte want[4];
            code_color(texel_code(PERM[i], j), want);
            const GLubyte *got = pixels + 4 * (y * W + x);
            if (memcmp(got, want, 4) != 0 && wrong++ < 8)
                capi_check(0, "column %d texel %d at (%d, %d): %d %d %d %d, want %d %d %d %d (unit %d)", i, j, x, y,
                           got[0], got[1], got[2], got[3], want[0], want[1], want[2], want[3], PERM[i]);
            /* The mix: texel j of every tex[k], weighed. */
            double sum[3] = {0, 0, 0};
            for (int k = 0; k < 8; k++) {
                GLubyte c[4];
                code_color(texel_code(PERM[k], j), c);
                for (int ch = 0; ch < 3; ch++)
                    sum[ch] += c[ch] ? MIX[k] : 0;
            }
            const GLubyte *mix = pixels + 4 * ((y + 8) * W + x);
            for (int ch = 0; ch < 3; ch++) {
                int expect = (int)(sum[ch] * 255 + 0.5);
                int d = mix[ch] - expect;
                if ((d > 1 || d < -1) && wrong++ < 8)
                    capi_check(0, "mix column %d texel %d channel %d: %d, want %d", i, j, ch, mix[ch], expect);
            }
        }
    }
    capi_value("draw.wrong_pixels", "%d", wrong);
    capi_save_image("eight_units", W, H, 4, CAPI_U8, pixels);
    glUseProgram(0);
    glDeleteProgram(p);

    conflicts();
    glDeleteTextures(8, textures);
    capi_expect_error(GL_NO_ERROR, "end");
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
