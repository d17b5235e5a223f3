/* The lighting state: every glLight parameter of every light (set through the f, i, fv and iv
 * forms, read back with glGetLightfv and glGetLightiv), positions and spot directions
 * transformed by the modelview matrix of their specification, glLightModel, glMaterial of
 * each face (and FRONT_AND_BACK), glColorMaterial in every mode and how the current color
 * then updates the material (outside and between glBegin/glEnd), glMaterial between glBegin
 * and glEnd, the glGet queries of the light model and color material in four types, the
 * errors (each must change nothing), and glPushAttrib/glPopAttrib of GL_LIGHTING_BIT and
 * GL_ENABLE_BIT.
 *
 * Deliberate difference from Mesa 22: glLightf, glLightModelf and glMaterialf (and their
 * integer forms) take single-valued parameters only (GL 2.1 2.14.2: GL_INVALID_ENUM for a
 * vector parameter); Mesa accepts vector parameters there, reading the missing components as
 * zeros or garbage. Checked on tessera only.
 */
#include "common.h"
#include <math.h>

#define W 8
#define H 8

static const GLenum light_pnames[] = {
    GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION, GL_SPOT_EXPONENT,
    GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION,
};
static const char *light_names[] = {
    "ambient", "diffuse", "specular", "position", "spot_direction", "spot_exponent",
    "spot_cutoff", "constant", "linear", "quadratic",
};
static const int light_counts[] = {4, 4, 4, 4, 3, 1, 1, 1, 1, 1};

static const GLenum material_pnames[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS,
                                         GL_COLOR_INDEXES};
static const char *material_names[] = {"ambient", "diffuse", "specular", "emission", "shininess", "indexes"};
static const int material_counts[] = {4, 4, 4, 4, 1, 3};

/* Prints one light's parameters as floats (%a) and integers. */
static void print_light(const char *stage, int light)
{
    for (int p = 0; p < 10; p++) {
        GLfloat f[4] = {0};
        GLint i[4] = {0};
        glGetLightfv(GL_LIGHT0 + light, light_pnames[p], f);
        glGetLightiv(GL_LIGHT0 + light, light_pnames[p], i);
        char key[96], text[256];
        int n = 0;
        for (int c = 0; c < light_counts[p]; c++)
            n += snprintf(text + n, sizeof text - n, "%a/%d ", f[c], i[c]);
        snprintf(key, sizeof key, "%s.light%d.%s", stage, light, light_names[p]);
        capi_value(key, "%s", text);
    }
}

static void print_material(const char *stage)
{
    const GLenum faces[2] = {GL_FRONT, GL_BACK};
    for (int face = 0; face < 2; face++) {
        for (int p = 0; p < 6; p++) {
            GLfloat f[4] = {0};
            GLint i[4] = {0};
            glGetMaterialfv(faces[face], material_pnames[p], f);
            glGetMaterialiv(faces[face], material_pnames[p], i);
            char key[96], text[256];
            int n = 0;
            for (int c = 0; c < material_counts[p]; c++)
                n += snprintf(text + n, sizeof text - n, "%a/%d ", f[c], i[c]);
            snprintf(key, sizeof key, "%s.%s.%s", stage, face ? "back" : "front", material_names[p]);
            capi_value(key, "%s", text);
        }
    }
}

static void print_model(const char *stage)
{
    capi_value_query(stage, "max_lights", GL_MAX_LIGHTS, 1);
    capi_value_query(stage, "model_ambient", GL_LIGHT_MODEL_AMBIENT, 4);
    capi_value_query(stage, "local_viewer", GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    capi_value_query(stage, "two_side", GL_LIGHT_MODEL_TWO_SIDE, 1);
    capi_value_query(stage, "color_control", GL_LIGHT_MODEL_COLOR_CONTROL, 1);
    capi_value_query(stage, "cm_face", GL_COLOR_MATERIAL_FACE, 1);
    capi_value_query(stage, "cm_parameter", GL_COLOR_MATERIAL_PARAMETER, 1);
    capi_value_query(stage, "shade_model", GL_SHADE_MODEL, 1);
    capi_value_query(stage, "lighting", GL_LIGHTING, 1);
    capi_value_query(stage, "light3", GL_LIGHT3, 1);
    capi_value_query(stage, "color_material", GL_COLOR_MATERIAL, 1);
    capi_value_query(stage, "normalize", GL_NORMALIZE, 1);
    capi_value_query(stage, "rescale_normal", GL_RESCALE_NORMAL, 1);
}

static void print_all(const char *stage)
{
    for (int l = 0; l < 8; l++)
        print_light(stage, l);
    print_material(stage);
    print_model(stage);
}

/* Every parameter through every form, positions under a rotated, scaled, translated
 * modelview matrix. */
static void set_lights(void)
{
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(1.5f, -2.0f, 0.25f);
    glRotatef(30.0f, 0.3f, 1.0f, 0.2f);
    glScalef(1.0f, 2.0f, 0.5f);
    const GLfloat ambient[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    const GLint diffuse[4] = {0x7fffffff, 0x40000000, -0x40000000, 12345678};
    const GLfloat specular[4] = {0.875f, -0.5f, 0.75f, 1.0f};
    const GLfloat position[4] = {1.0f, 2.0f, 3.0f, 1.0f};
    const GLint direction_position[4] = {1, -2, 3, 0};
    const GLfloat spot[3] = {0.3f, -0.4f, -1.0f};
    const GLint ispot[3] = {-1, 2, 5};
    glLightfv(GL_LIGHT1, GL_AMBIENT, ambient);
    glLightiv(GL_LIGHT1, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT1, GL_SPECULAR, specular);
    glLightfv(GL_LIGHT1, GL_POSITION, position);
    glLightiv(GL_LIGHT2, GL_POSITION, direction_position);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot);
    glLightiv(GL_LIGHT2, GL_SPOT_DIRECTION, ispot);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 17.6f);
    glLighti(GL_LIGHT2, GL_SPOT_EXPONENT, 128);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 33.7f);
    glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 90);
    const GLfloat att = 0.6f;
    const GLint iatt = 3;
    glLightfv(GL_LIGHT1, GL_CONSTANT_ATTENUATION, &att);
    glLightiv(GL_LIGHT2, GL_CONSTANT_ATTENUATION, &iatt);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.25f);
    glLighti(GL_LIGHT2, GL_LINEAR_ATTENUATION, 2);
    glLightf(GL_LIGHT7, GL_QUADRATIC_ATTENUATION, 0.125f);
    glLightf(GL_LIGHT7, GL_SPOT_CUTOFF, 0.0f);
    glLightf(GL_LIGHT7, GL_SPOT_EXPONENT, 0.0f);
    capi_expect_error(GL_NO_ERROR, "set lights");

    const GLfloat model_ambient[4] = {0.05f, -0.25f, 0.625f, 0.5f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 5);
    glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 0.5f);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    capi_expect_error(GL_NO_ERROR, "set light model");

    const GLfloat mat_ambient[4] = {0.9f, 0.8f, 0.7f, 0.6f};
    const GLint mat_emission[4] = {0x20000000, 0, 0x7fffffff, -0x7fffffff};
    const GLfloat indexes[3] = {1.4f, 2.5f, 7.6f};
    glMaterialfv(GL_FRONT, GL_AMBIENT, mat_ambient);
    glMaterialiv(GL_BACK, GL_EMISSION, mat_emission);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12.5f);
    glMateriali(GL_BACK, GL_SHININESS, 100);
    glMaterialfv(GL_FRONT, GL_COLOR_INDEXES, indexes);
    const GLfloat both[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, both);
    const GLfloat ad[4] = {0.3f, 0.2f, 0.1f, 0.9f};
    glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, ad);
    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);
    glShadeModel(GL_FLAT);
    capi_expect_error(GL_NO_ERROR, "set materials");
}

/* Invalid calls: each sets its error and changes nothing (compared by printing after). */
static void errors(void)
{
    const GLfloat v[4] = {1, 2, 3, 4};
    glLightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 1.0f);
    capi_expect_error(GL_INVALID_ENUM, "light 8");
    glLightfv(GL_LIGHT0, GL_SHININESS, v);
    capi_expect_error(GL_INVALID_ENUM, "light pname");
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 128.5f);
    capi_expect_error(GL_INVALID_VALUE, "spot exponent > 128");
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, -0.5f);
    capi_expect_error(GL_INVALID_VALUE, "spot exponent < 0");
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 90.5f);
    capi_expect_error(GL_INVALID_VALUE, "spot cutoff 90.5");
    glLighti(GL_LIGHT1, GL_SPOT_CUTOFF, -1);
    capi_expect_error(GL_INVALID_VALUE, "spot cutoff -1");
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 179.0f);
    capi_expect_error(GL_INVALID_VALUE, "spot cutoff 179");
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, -0.01f);
    capi_expect_error(GL_INVALID_VALUE, "constant attenuation");
    glLighti(GL_LIGHT1, GL_LINEAR_ATTENUATION, -1);
    capi_expect_error(GL_INVALID_VALUE, "linear attenuation");
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, -2.0f);
    capi_expect_error(GL_INVALID_VALUE, "quadratic attenuation");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FRONT);
    capi_expect_error(GL_INVALID_ENUM, "color control");
    glLightModelfv(GL_SHININESS, v);
    capi_expect_error(GL_INVALID_ENUM, "light model pname");
    glMaterialf(GL_FRONT, GL_SHININESS, 128.5f);
    capi_expect_error(GL_INVALID_VALUE, "shininess > 128");
    glMaterialf(GL_BACK, GL_SHININESS, -1.0f);
    capi_expect_error(GL_INVALID_VALUE, "shininess < 0");
    glMaterialfv(GL_LEFT, GL_AMBIENT, v);
    capi_expect_error(GL_INVALID_ENUM, "material face");
    glMaterialfv(GL_FRONT, GL_POSITION, v);
    capi_expect_error(GL_INVALID_ENUM, "material pname");
    GLfloat out[4] = {-7, -7, -7, -7};
    glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, out);
    capi_expect_error(GL_INVALID_ENUM, "get material front and back");
    glGetMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, out);
    capi_expect_error(GL_INVALID_ENUM, "get material ambient and diffuse");
    glGetLightfv(GL_LIGHT0 + 8, GL_AMBIENT, out);
    capi_expect_error(GL_INVALID_ENUM, "get light 8");
    glGetLightfv(GL_LIGHT0, GL_EMISSION, out);
    capi_expect_error(GL_INVALID_ENUM, "get light pname");
    capi_check(out[0] == -7, "failed queries write nothing");
    glColorMaterial(GL_LEFT, GL_DIFFUSE);
    capi_expect_error(GL_INVALID_ENUM, "color material face");
    glColorMaterial(GL_FRONT, GL_SHININESS);
    capi_expect_error(GL_INVALID_ENUM, "color material mode");
    if (capi_is_tessera()) {
        /* GL 2.1 2.14.2: the scalar forms take single-valued parameters (Mesa accepts these). */
        glLightf(GL_LIGHT0, GL_AMBIENT, 0.5f);
        capi_check(glGetError() == GL_INVALID_ENUM, "glLightf vector parameter");
        glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.5f);
        capi_check(glGetError() == GL_INVALID_ENUM, "glLightModelf vector parameter");
        glMaterialf(GL_FRONT, GL_DIFFUSE, 0.5f);
        capi_check(glGetError() == GL_INVALID_ENUM, "glMaterialf vector parameter");
    }
    /* Between glBegin and glEnd: glLight, glLightModel, glColorMaterial and the queries are
     * illegal; glMaterial is legal. */
    glBegin(GL_POINTS);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 3.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
    glColorMaterial(GL_FRONT, GL_EMISSION);
    glGetLightfv(GL_LIGHT1, GL_AMBIENT, out);
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, out);
    glMaterialf(GL_FRONT, GL_SHININESS, 3.0f);
    glEnd();
    capi_expect_error(GL_INVALID_OPERATION, "inside begin/end");
    capi_check(glGetError() == GL_NO_ERROR, "one error only");
    glMaterialf(GL_FRONT, GL_SHININESS, 12.5f);
}

/* The current color tracks the material while GL_COLOR_MATERIAL is enabled. */
static void color_material(void)
{
    const GLenum modes[5] = {GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE};
    const GLenum faces[3] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
    char stage[64];
    for (int f = 0; f < 3; f++) {
        for (int m = 0; m < 5; m++) {
            glPushAttrib(GL_LIGHTING_BIT | GL_CURRENT_BIT);
            glColor4f(0.1f * m, 0.2f, 0.05f * f, 0.5f);
            glColorMaterial(faces[f], modes[m]);
            /* Not enabled yet: nothing tracked. Enabling copies the current color. */
            glEnable(GL_COLOR_MATERIAL);
            snprintf(stage, sizeof stage, "cm%d_%d.enabled", f, m);
            print_material(stage);
            glColor4f(0.7f, 0.6f, 0.5f, 0.4f);
            snprintf(stage, sizeof stage, "cm%d_%d.color", f, m);
            print_material(stage);
            /* glColor between glBegin and glEnd: the material follows by glEnd. */
            glBegin(GL_POINTS);
            glColor4f(0.3f, 0.9f, 0.1f, 0.2f);
            glVertex2f(100, 100);
            glColor4f(0.25f, 0.125f, 1.0f, 0.75f);
            glEnd();
            snprintf(stage, sizeof stage, "cm%d_%d.begin_end", f, m);
            print_material(stage);
            glDisable(GL_COLOR_MATERIAL);
            glColor4f(0.0f, 0.0f, 0.0f, 0.0f);
            snprintf(stage, sizeof stage, "cm%d_%d.disabled", f, m);
            print_material(stage);
            glPopAttrib();
        }
    }
    capi_expect_error(GL_NO_ERROR, "color material");
}

/* glMaterial between glBegin and glEnd: the material after glEnd is the last one given. */
static void material_in_begin_end(void)
{
    const GLfloat red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1};
    glBegin(GL_TRIANGLES);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glVertex2f(100, 100);
    glMaterialfv(GL_BACK, GL_EMISSION, green);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 64.0f);
    glVertex2f(101, 100);
    glVertex2f(100, 101);
    glEnd();
    capi_expect_error(GL_NO_ERROR, "material in begin/end");
    print_material("begin_end_material");
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 16, 0, 0, W, H, &buffer);
    print_all("initial");
    /* GL_LIGHTING_BIT restores everything but GL_NORMALIZE (GL_ENABLE_BIT and
     * GL_TRANSFORM_BIT). Pushes are not nested: Mesa 22 forgets changes made under a nested
     * push when the inner group pops, and restores nothing at the outer pop. */
    glPushAttrib(GL_LIGHTING_BIT);
    set_lights();
    print_all("set");
    errors();
    print_all("after_errors");
    glPopAttrib();
    print_all("pop_lighting");
    /* GL_ENABLE_BIT restores the enables only. */
    glPushAttrib(GL_ENABLE_BIT);
    glEnable(GL_LIGHTING);
    glEnable(GL_COLOR_MATERIAL);
    glDisable(GL_NORMALIZE);
    glEnable(GL_RESCALE_NORMAL);
    print_all("enables");
    glPopAttrib();
    print_all("pop_enable");
    color_material();
    print_all("after_color_material");
    material_in_begin_end();
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
