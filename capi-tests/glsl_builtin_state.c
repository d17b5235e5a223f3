/* GLSL 1.20's built-in state uniforms (section 7.5) against Mesa, value for value: a rich
 * fixed-function state (a general modelview, a perspective projection, a projective and a
 * singular texture matrix, lights with spots and attenuation, two materials, texture env
 * colors, texgen planes, clip planes, point parameters, fog, a depth range) is set, and for
 * each built-in value a one-pixel rectangle is drawn by a program whose fragment shader
 * writes the value (a vec4 expression of it) to a float color buffer with every color clamp
 * off; the pixels are read back and printed bit for bit (%a). The modelview and
 * modelview-projection matrices, the normal matrix and one light are also read in the vertex
 * shader, through an unclamped gl_FrontColor. gl_NormalScale is read with lighting off and on (Mesa's value depends on
 * whether it lights in eye space), and gl_Fog.scale once more with fog start = end. Last,
 * each built-in limit constant (gl_MaxVaryingFloats, ...) is compared in the shader with
 * what glGet reports.
 *
 * Units beyond tessera's four texture units are read at their initial values only
 * (gl_TextureMatrix[5], gl_EyePlaneS[5], ...): GLSL 1.20 sizes those arrays by
 * gl_MaxTextureCoords, 8 on both. */
#include "common.h"
#include <math.h>

#define W 32
#define H 16

static int next_pixel;
static float pixels[W * H * 4];

struct entry {
    char key[96];
    int pixel;
};
static struct entry entries[W * H];
static int entry_count;

/* Draws `expr` (a vec4 expression of built-in state) into the next pixel, read in the
 * fragment shader (vertex = 0) or in the vertex shader. */
static void draw_value(const char *key, const char *expr, int vertex)
{
    char vs[1024], fs[1024];
    if (vertex) {
        snprintf(vs, sizeof vs, "void main() { gl_Position = gl_Vertex; gl_FrontColor = %s; }", expr);
        snprintf(fs, sizeof fs, "void main() { gl_FragColor = gl_Color; }");
    } else {
        snprintf(vs, sizeof vs, "void main() { gl_Position = gl_Vertex; }");
        snprintf(fs, sizeof fs, "void main() { gl_FragColor = %s; }", expr);
    }
    GLuint program = capi_program(key, vs, fs);
    glUseProgram(program);
    int p = next_pixel++;
    if (p >= W * H) {
        capi_check(0, "too many values");
        return;
    }
    int x = p % W, y = p / W;
    float x0 = -1.0f + 2.0f * x / W, x1 = -1.0f + 2.0f * (x + 1) / W;
    float y0 = -1.0f + 2.0f * y / H, y1 = -1.0f + 2.0f * (y + 1) / H;
    glRectf(x0, y0, x1, y1);
    glUseProgram(0);
    glDeleteProgram(program);
    snprintf(entries[entry_count].key, sizeof entries[entry_count].key, "%s%s", vertex ? "vs." : "fs.", key);
    entries[entry_count].pixel = p;
    entry_count++;
}

static void value(const char *key, const char *expr)
{
    draw_value(key, expr, 0);
}

static const char *const MATRICES[] = {"ModelView", "Projection", "ModelViewProjection", "Texture"};
static const char *const FORMS[] = {"", "Inverse", "Transpose", "InverseTranspose"};

/* Every matrix in the fragment shader; in the vertex shader (`vertex`) the modelview and
 * modelview-projection ones only (llvmpipe compiles each program: time). */
static void matrices(int vertex)
{
    char name[64], key[96], expr[128];
    for (int m = 0; m < 4; m++) {
        if (vertex && (m == 1 || m == 3))
            continue;
        static const int units[] = {0, 1, 2, 5};
        for (int u = 0; u < (m == 3 ? 4 : 1); u++) {
            for (int form = 0; form < 4; form++) {
                if (m == 3)
                    snprintf(name, sizeof name, "gl_TextureMatrix%s[%d]", FORMS[form], units[u]);
                else
                    snprintf(name, sizeof name, "gl_%sMatrix%s", MATRICES[m], FORMS[form]);
                for (int c = 0; c < 4; c++) {
                    snprintf(key, sizeof key, "%s[col%d]", name, c);
                    snprintf(expr, sizeof expr, "%s[%d]", name, c);
                    draw_value(key, expr, vertex);
                }
            }
        }
    }
    for (int c = 0; c < 3; c++) {
        snprintf(key, sizeof key, "gl_NormalMatrix[col%d]", c);
        snprintf(expr, sizeof expr, "vec4(gl_NormalMatrix[%d], 0.0)", c);
        draw_value(key, expr, vertex);
    }
}

/* Lights 0, 1, 2 and 7 in the fragment shader, light 0 in the vertex shader. */
static void lights(int vertex)
{
    static const int used[] = {0, 1, 2, 7};
    char key[96], expr[256];
    for (int k = 0; k < (vertex ? 1 : 4); k++) {
        int i = used[k];
        static const char *const colors[] = {"ambient", "diffuse", "specular", "position", "halfVector"};
        for (int c = 0; c < 5; c++) {
            snprintf(key, sizeof key, "gl_LightSource[%d].%s", i, colors[c]);
            snprintf(expr, sizeof expr, "gl_LightSource[%d].%s", i, colors[c]);
            draw_value(key, expr, vertex);
        }
        snprintf(key, sizeof key, "gl_LightSource[%d].spot", i);
        snprintf(expr, sizeof expr, "vec4(gl_LightSource[%d].spotDirection, gl_LightSource[%d].spotExponent)", i, i);
        draw_value(key, expr, vertex);
        snprintf(key, sizeof key, "gl_LightSource[%d].cutoff_attenuation", i);
        snprintf(expr, sizeof expr,
                 "vec4(gl_LightSource[%d].spotCutoff, gl_LightSource[%d].spotCosCutoff, "
                 "gl_LightSource[%d].constantAttenuation, gl_LightSource[%d].linearAttenuation)",
                 i, i, i, i);
        draw_value(key, expr, vertex);
        snprintf(key, sizeof key, "gl_LightSource[%d].quadraticAttenuation", i);
        snprintf(expr, sizeof expr, "vec4(gl_LightSource[%d].quadraticAttenuation)", i);
        draw_value(key, expr, vertex);
    }
}

static void everything_else(void)
{
    char key[96], expr[256];
    value("gl_DepthRange", "vec4(gl_DepthRange.near, gl_DepthRange.far, gl_DepthRange.diff, 0.0)");
    for (int i = 0; i < 6; i++) {
        snprintf(key, sizeof key, "gl_ClipPlane[%d]", i);
        value(key, key);
    }
    value("gl_Point.size", "vec4(gl_Point.size, gl_Point.sizeMin, gl_Point.sizeMax, gl_Point.fadeThresholdSize)");
    value("gl_Point.distance",
          "vec4(gl_Point.distanceConstantAttenuation, gl_Point.distanceLinearAttenuation, "
          "gl_Point.distanceQuadraticAttenuation, 0.0)");
    static const char *const faces[] = {"Front", "Back"};
    static const char *const material[] = {"emission", "ambient", "diffuse", "specular"};
    for (int f = 0; f < 2; f++) {
        for (int m = 0; m < 4; m++) {
            snprintf(key, sizeof key, "gl_%sMaterial.%s", faces[f], material[m]);
            value(key, key);
        }
        snprintf(key, sizeof key, "gl_%sMaterial.shininess", faces[f]);
        snprintf(expr, sizeof expr, "vec4(gl_%sMaterial.shininess)", faces[f]);
        value(key, expr);
        snprintf(key, sizeof key, "gl_%sLightModelProduct.sceneColor", faces[f]);
        value(key, key);
        for (int i = 0; i < 3; i++) {
            static const char *const products[] = {"ambient", "diffuse", "specular"};
            for (int p = 0; p < 3; p++) {
                snprintf(key, sizeof key, "gl_%sLightProduct[%d].%s", faces[f], i, products[p]);
                value(key, key);
            }
        }
    }
    value("gl_LightModel.ambient", "gl_LightModel.ambient");
    for (int u = 0; u < 4; u++) {
        snprintf(key, sizeof key, "gl_TextureEnvColor[%d]", u);
        value(key, key);
    }
    static const int units[] = {0, 1, 5};
    for (int k = 0; k < 3; k++) {
        for (int c = 0; c < 4; c++) {
            snprintf(key, sizeof key, "gl_EyePlane%c[%d]", "STRQ"[c], units[k]);
            value(key, key);
            snprintf(key, sizeof key, "gl_ObjectPlane%c[%d]", "STRQ"[c], units[k]);
            value(key, key);
        }
    }
    value("gl_Fog.color", "gl_Fog.color");
    value("gl_Fog.params", "vec4(gl_Fog.density, gl_Fog.start, gl_Fog.end, gl_Fog.scale)");
}

static void set_state(void)
{
    /* Clip planes and eye planes are specified under this modelview. */
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.5f, -1.25f, 2.0f);
    glRotatef(33.0f, 0.3f, 1.0f, -0.2f);
    static const GLdouble planes[6][4] = {{1, 0, 0, 0.5},  {0, 1, 0, -0.25}, {0.3, 0.4, 0.5, 0.6},
                                          {-1, 2, -3, 4}, {0, 0, -1, 0.75},  {0.1, 0.2, 0.7, -0.9}};
    for (int i = 0; i < 6; i++)
        glClipPlane(GL_CLIP_PLANE0 + i, planes[i]);
    static const GLfloat eye[4][4] = {{1, 0.5f, 0, 0.25f}, {0, 1, 0.3f, 0}, {0.2f, 0, 1, -1}, {0, 0.1f, 0, 1}};
    static const GLfloat object[4][4] = {{0.5f, 0, 0, 1}, {0, 0.75f, 0, 0}, {0, 0, 2, 0.5f}, {1, 1, 1, 1}};
    for (int u = 0; u < 2; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        for (int c = 0; c < 4; c++) {
            GLfloat e[4], o[4];
            for (int k = 0; k < 4; k++) {
                e[k] = eye[c][k] * (u + 1);
                o[k] = object[c][k] - u;
            }
            glTexGenfv(GL_S + c, GL_EYE_PLANE, e);
            glTexGenfv(GL_S + c, GL_OBJECT_PLANE, o);
        }
    }
    /* Lights too: positions and spot directions go through the modelview. */
    static const GLfloat l0_pos[4] = {1, 2, 3, 1}, l0_dir[3] = {0.2f, -0.5f, -1};
    static const GLfloat l1_pos[4] = {-0.5f, 1, 0.25f, 0}, l2_pos[4] = {2, -1, 0.5f, 2};
    static const GLfloat l0_amb[4] = {0.1f, 0.2f, 0.3f, 0.4f}, l0_dif[4] = {0.9f, 0.8f, 0.7f, 0.6f};
    static const GLfloat l0_spec[4] = {0.5f, 0.25f, 0.125f, 1}, l1_dif[4] = {0.3f, 0.6f, 0.9f, 0.5f};
    static const GLfloat l2_amb[4] = {0.7f, 0.1f, 0.4f, 0.2f}, l2_spec[4] = {0.33f, 0.66f, 0.99f, 0.11f};
    glLightfv(GL_LIGHT0, GL_POSITION, l0_pos);
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, l0_dir);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 37.5f);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 12.0f);
    glLightfv(GL_LIGHT0, GL_AMBIENT, l0_amb);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, l0_dif);
    glLightfv(GL_LIGHT0, GL_SPECULAR, l0_spec);
    glLightfv(GL_LIGHT1, GL_POSITION, l1_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, l1_dif);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 90.0f);
    glLightfv(GL_LIGHT2, GL_POSITION, l2_pos);
    glLightfv(GL_LIGHT2, GL_AMBIENT, l2_amb);
    glLightfv(GL_LIGHT2, GL_SPECULAR, l2_spec);
    glLightf(GL_LIGHT2, GL_CONSTANT_ATTENUATION, 0.5f);
    glLightf(GL_LIGHT2, GL_LINEAR_ATTENUATION, 0.25f);
    glLightf(GL_LIGHT2, GL_QUADRATIC_ATTENUATION, 0.125f);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 0.0f);
    /* Then a non-uniform scale, so that the normal matrix and gl_NormalScale are not trivial. */
    glScalef(1.5f, 0.75f, 2.5f);

    static const GLfloat model_ambient[4] = {0.15f, 0.25f, 0.35f, 0.45f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient);
    static const GLfloat f_em[4] = {0.05f, 0.1f, 0.15f, 0.2f}, f_amb[4] = {0.3f, 0.35f, 0.4f, 0.45f};
    static const GLfloat f_dif[4] = {0.6f, 0.55f, 0.5f, 0.625f}, f_spec[4] = {0.7f, 0.8f, 0.9f, 0.3f};
    static const GLfloat b_em[4] = {0.2f, 0, 0.1f, 0.9f}, b_amb[4] = {0.9f, 0.7f, 0.5f, 0.3f};
    static const GLfloat b_dif[4] = {0.11f, 0.22f, 0.33f, 0.44f}, b_spec[4] = {0.25f, 0.5f, 0.75f, 0.875f};
    glMaterialfv(GL_FRONT, GL_EMISSION, f_em);
    glMaterialfv(GL_FRONT, GL_AMBIENT, f_amb);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, f_dif);
    glMaterialfv(GL_FRONT, GL_SPECULAR, f_spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 17.0f);
    glMaterialfv(GL_BACK, GL_EMISSION, b_em);
    glMaterialfv(GL_BACK, GL_AMBIENT, b_amb);
    glMaterialfv(GL_BACK, GL_DIFFUSE, b_dif);
    glMaterialfv(GL_BACK, GL_SPECULAR, b_spec);
    glMaterialf(GL_BACK, GL_SHININESS, 99.5f);

    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.0, 1.5, -0.75, 1.25, 0.5, 20.0);
    glMatrixMode(GL_TEXTURE);
    glActiveTexture(GL_TEXTURE0);
    static const GLfloat projective[16] = {1, 0.5f, 0, 0.25f, 0.125f, 2, 0.3f, 0, -0.5f, 0, 1.5f, 0.1f, 3, -2, 1, 1};
    glLoadMatrixf(projective);
    glActiveTexture(GL_TEXTURE1);
    glTranslatef(0.25f, 0.5f, 0);
    glScalef(2.0f, 0.0f, 1.0f); /* singular */
    glActiveTexture(GL_TEXTURE2);
    glRotatef(90.0f, 0, 0, 1);
    glMatrixMode(GL_MODELVIEW);

    for (int u = 0; u < 4; u++) {
        GLfloat c[4] = {0.1f * u, 0.2f + 0.1f * u, 0.75f - 0.125f * u, 0.9f};
        glActiveTexture(GL_TEXTURE0 + u);
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
    }
    glActiveTexture(GL_TEXTURE0);

    static const GLfloat fog[4] = {0.3f, 1.5f, -0.25f, 0.6f};
    glFogfv(GL_FOG_COLOR, fog);
    glFogf(GL_FOG_DENSITY, 0.35f);
    glFogf(GL_FOG_START, 1.5f);
    glFogf(GL_FOG_END, 7.25f);

    glPointSize(3.5f);
    glPointParameterf(GL_POINT_SIZE_MIN, 1.25f);
    glPointParameterf(GL_POINT_SIZE_MAX, 40.0f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 2.5f);
    static const GLfloat attenuation[3] = {1.0f, 0.125f, 0.0625f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);

    glDepthRange(0.1, 0.7);
}

/* Each built-in constant the implementation limits give (GLSL 1.20 section 7.4) against
 * the glGet value, in the shader: 1 when they agree. (The values themselves are glsl_limits'
 * business.) */
static void constants(void)
{
    static const struct {
        const char *constant;
        GLenum pname;
    } limits[] = {
        {"gl_MaxVaryingFloats", GL_MAX_VARYING_FLOATS},
        {"gl_MaxVertexAttribs", GL_MAX_VERTEX_ATTRIBS},
        {"gl_MaxVertexUniformComponents", GL_MAX_VERTEX_UNIFORM_COMPONENTS},
        {"gl_MaxFragmentUniformComponents", GL_MAX_FRAGMENT_UNIFORM_COMPONENTS},
        {"gl_MaxVertexTextureImageUnits", GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS},
        {"gl_MaxCombinedTextureImageUnits", GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS},
        {"gl_MaxTextureImageUnits", GL_MAX_TEXTURE_IMAGE_UNITS},
        {"gl_MaxTextureCoords", GL_MAX_TEXTURE_COORDS},
        {"gl_MaxDrawBuffers", GL_MAX_DRAW_BUFFERS},
        {"gl_MaxTextureUnits", GL_MAX_TEXTURE_UNITS},
        {"gl_MaxLights", GL_MAX_LIGHTS},
        {"gl_MaxClipPlanes", GL_MAX_CLIP_PLANES},
    };
    for (unsigned i = 0; i < sizeof limits / sizeof limits[0]; i++) {
        GLint n = -1;
        glGetIntegerv(limits[i].pname, &n);
        char key[96], expr[256];
        snprintf(key, sizeof key, "constant.%s", limits[i].constant);
        snprintf(expr, sizeof expr, "vec4(%s == %d ? 1.0 : 0.0)", limits[i].constant, n);
        value(key, expr);
    }
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_FLOAT, 0, 0, 0, W, H, &buffer);
    glClampColor(GL_CLAMP_VERTEX_COLOR, GL_FALSE);
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
    glClearColor(-7, -7, -7, -7);
    glClear(GL_COLOR_BUFFER_BIT);
    set_state();
    capi_expect_error(GL_NO_ERROR, "state set");

    matrices(0);
    value("gl_NormalScale.unlit", "vec4(gl_NormalScale)");
    glEnable(GL_LIGHTING);
    value("gl_NormalScale.lit", "vec4(gl_NormalScale)");
    glDisable(GL_LIGHTING);
    lights(0);
    everything_else();
    matrices(1);
    lights(1);
    constants();
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 2.0f);
    value("gl_Fog.params.start_is_end", "vec4(gl_Fog.density, gl_Fog.start, gl_Fog.end, gl_Fog.scale)");
    capi_expect_error(GL_NO_ERROR, "drawn");

    glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, pixels);
    for (int i = 0; i < entry_count; i++) {
        const float *p = &pixels[entries[i].pixel * 4];
        capi_value(entries[i].key, "%a %a %a %a", p[0], p[1], p[2], p[3]);
        capi_check(p[0] != -7.0f || p[1] != -7.0f, "%s was not drawn", entries[i].key);
    }
    capi_value("count", "%d", entry_count);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
