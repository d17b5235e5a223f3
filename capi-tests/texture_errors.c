/* Texture errors and queries against Mesa: the errors of every texture command, texture
 * object names and bindings, proxies, level parameters, texture parameters, the texture
 * environment and texgen state in the four query types, GL_TEXTURE_BIT push/pop, and
 * texturing on lines and points. */
#include "common.h"

#define W 16
#define H 16

static void expect(GLenum error, const char *what)
{
    capi_expect_error(error, what);
}

static void errors(void)
{
    unsigned char px[16 * 16 * 4] = {0};
    glTexImage2D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_ENUM, "2D image on a 3D target");
    glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_VALUE, "negative level");
    glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_VALUE, "bad internal format");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 0x1234, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_ENUM, "bad format");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, 0x1234, px);
    expect(GL_INVALID_ENUM, "bad type");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, px);
    expect(GL_INVALID_OPERATION, "packed type with the wrong format");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_VALUE, "negative width");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_VALUE, "border 2");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_OPERATION, "depth format with color data");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, px);
    expect(GL_INVALID_OPERATION, "color format with depth data");
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_VALUE, "non-square cube face");
    glTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_ENUM, "1D image on a 2D target");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_NO_ERROR, "valid image");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_VALUE, "sub-image outside");
    glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_OPERATION, "sub-image of an undefined level");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, px);
    expect(GL_INVALID_OPERATION, "depth sub-image of a color texture");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_NO_ERROR, "valid sub-image");
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 0, 0, 2, 2);
    expect(GL_INVALID_VALUE, "copy outside");
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 3);
    expect(GL_INVALID_VALUE, "copy with border 3");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, px);
    expect(GL_INVALID_OPERATION, "depth readback of a color texture");
    glGetTexImage(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(GL_INVALID_ENUM, "readback of a proxy");
    glBindTexture(0x1234, 1);
    expect(GL_INVALID_ENUM, "bind to a bad target");
    GLuint names[2];
    glGenTextures(2, names);
    glBindTexture(GL_TEXTURE_1D, names[0]);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    expect(GL_INVALID_OPERATION, "bind to another target");
    glGenTextures(-1, names);
    expect(GL_INVALID_VALUE, "negative count");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT);
    expect(GL_INVALID_ENUM, "bad min filter");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    expect(GL_INVALID_ENUM, "mipmap mag filter");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR);
    expect(GL_INVALID_ENUM, "bad wrap");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
    expect(GL_INVALID_VALUE, "negative base level");
    glTexParameteri(GL_TEXTURE_2D, 0x1234, 0);
    expect(GL_INVALID_ENUM, "bad texture parameter");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_ZERO);
    expect(GL_INVALID_ENUM, "bad compare func");
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ONE);
    expect(GL_INVALID_ENUM, "bad env mode");
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 3);
    expect(GL_INVALID_VALUE, "rgb scale 3");
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);
    expect(GL_INVALID_ENUM, "dot3 alpha");
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR);
    expect(GL_INVALID_ENUM, "color operand for alpha");
    glTexEnvi(0x1234, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    expect(GL_INVALID_ENUM, "bad env target");
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    expect(GL_INVALID_ENUM, "sphere map on R");
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
    expect(GL_INVALID_ENUM, "normal map on Q");
    glTexGeni(0x1234, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    expect(GL_INVALID_ENUM, "bad texgen coordinate");
    glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, (GLint *)px);
    expect(GL_INVALID_ENUM, "level parameter of the cube map target");
    /* No compressed format is supported (Mesa 22 supports S3TC). */
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, 4, 4, 0, 8, px);
    GLenum compressed = glGetError();
    if (capi_is_tessera())
        capi_check(compressed == GL_INVALID_ENUM, "compressed image: 0x%x", compressed);
    glBegin(GL_POINTS);
    glBindTexture(GL_TEXTURE_2D, 0);
    glEnd();
    expect(GL_INVALID_OPERATION, "bind inside begin/end");
    glDeleteTextures(2, names);
}

static const char *pnames_level[] = {"width", "height", "depth", "border", "internal", "red", "alpha", "lum", "int",
                                     "depth_size", "compressed"};
static const GLenum level_pnames[] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH, GL_TEXTURE_BORDER,
                                      GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE, GL_TEXTURE_ALPHA_SIZE,
                                      GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE, GL_TEXTURE_DEPTH_SIZE,
                                      GL_TEXTURE_COMPRESSED};

static void level_values(const char *stage, GLenum target, int level)
{
    GLint width;
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &width);
    for (unsigned i = 0; i < sizeof level_pnames / sizeof level_pnames[0]; i++) {
        GLint iv = -7;
        GLfloat fv = -7;
        glGetTexLevelParameteriv(target, level, level_pnames[i], &iv);
        glGetTexLevelParameterfv(target, level, level_pnames[i], &fv);
        if (width == 0 && level_pnames[i] == GL_TEXTURE_INTERNAL_FORMAT) {
            /* An undefined image's internal format is 1 in GL 2.1 (table 6.17); Mesa 22
             * answers GL_RGBA, the GL 3 value. */
            if (capi_is_tessera())
                capi_check(iv == 1, "%s: undefined internal format %d", stage, iv);
            continue;
        }
        capi_value(stage, "%s %d %g", pnames_level[i], iv, fv);
    }
}

static void queries(void)
{
    GLuint names[3];
    glGenTextures(3, names);
    capi_value("names", "%u %u %u", names[0], names[1], names[2]);
    capi_value("is_texture_unbound", "%d", glIsTexture(names[0]));
    glBindTexture(GL_TEXTURE_2D, names[1]);
    capi_value("is_texture_bound", "%d", glIsTexture(names[1]));
    capi_value_query("bound", "binding_2d", GL_TEXTURE_BINDING_2D, 1);
    capi_value_query("limits", "max_size", GL_MAX_TEXTURE_SIZE, 1);
    capi_value_query("limits", "max_3d", GL_MAX_3D_TEXTURE_SIZE, 1);
    capi_value_query("limits", "max_cube", GL_MAX_CUBE_MAP_TEXTURE_SIZE, 1);
    capi_value_query("limits", "max_bias", GL_MAX_TEXTURE_LOD_BIAS, 1);
    unsigned char px[8 * 8 * 4] = {0};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8_ALPHA8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glTexImage2D(GL_TEXTURE_2D, 2, GL_RGB5, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    level_values("level0", GL_TEXTURE_2D, 0);
    level_values("level2", GL_TEXTURE_2D, 2);
    /* A bordered image reports its size with the border (GL 2.1 §3.8.1); Mesa 22 strips
     * borders at specification and reports the inner size. */
    glTexImage2D(GL_TEXTURE_2D, 3, GL_RGB5, 4, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    if (capi_is_tessera()) {
        GLint bw, bh, bb;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH, &bw);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_HEIGHT, &bh);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_BORDER, &bb);
        capi_check(bw == 4 && bh == 3 && bb == 1, "bordered level: %d x %d, border %d", bw, bh, bb);
    }
    level_values("level1_undefined", GL_TEXTURE_2D, 1);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, 64, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    level_values("proxy3d", GL_PROXY_TEXTURE_3D, 0);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 1 << 20, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    expect(GL_NO_ERROR, "a proxy beyond the maximum size is no error");
    level_values("proxy_too_large", GL_PROXY_TEXTURE_2D, 0);
    glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    level_values("proxy_cube", GL_PROXY_TEXTURE_CUBE_MAP, 0);

    /* Texture parameters, set in one type and read in two. */
    const GLfloat border[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -2.5f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3.25f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 5);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0.5f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.5f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    static const GLenum params[] = {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S,
                                    GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R, GL_TEXTURE_BORDER_COLOR,
                                    GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD, GL_TEXTURE_BASE_LEVEL,
                                    GL_TEXTURE_MAX_LEVEL, GL_TEXTURE_PRIORITY, GL_TEXTURE_RESIDENT,
                                    GL_TEXTURE_LOD_BIAS, GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC,
                                    GL_DEPTH_TEXTURE_MODE, GL_GENERATE_MIPMAP};
    for (unsigned i = 0; i < sizeof params / sizeof params[0]; i++) {
        GLint iv[4] = {-7, -7, -7, -7};
        GLfloat fv[4] = {-7, -7, -7, -7};
        glGetTexParameteriv(GL_TEXTURE_2D, params[i], iv);
        glGetTexParameterfv(GL_TEXTURE_2D, params[i], fv);
        capi_value("tex_parameter", "0x%x %d %d %d %d %g %g %g %g", params[i], iv[0], iv[1], iv[2], iv[3], fv[0],
                   fv[1], fv[2], fv[3]);
    }
    GLint color_i[4] = {0x7fffffff, 0, 0x40000000, -5};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, color_i);
    GLfloat back[4];
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, back);
    capi_value("border_from_ints", "%.4f %.4f %.4f %.4f", back[0], back[1], back[2], back[3]);

    /* Texture environment and texgen on unit 1. */
    glActiveTexture(GL_TEXTURE1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, GL_TEXTURE0);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_ALPHA);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2.0f);
    const GLfloat env[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -0.75f);
    static const GLenum env_pnames[] = {GL_TEXTURE_ENV_MODE, GL_COMBINE_RGB, GL_COMBINE_ALPHA, GL_SOURCE0_RGB,
                                        GL_SOURCE2_ALPHA, GL_OPERAND1_RGB, GL_OPERAND2_ALPHA, GL_RGB_SCALE,
                                        GL_ALPHA_SCALE, GL_TEXTURE_ENV_COLOR};
    for (unsigned i = 0; i < sizeof env_pnames / sizeof env_pnames[0]; i++) {
        GLint iv[4] = {-7, -7, -7, -7};
        GLfloat fv[4] = {-7, -7, -7, -7};
        glGetTexEnviv(GL_TEXTURE_ENV, env_pnames[i], iv);
        glGetTexEnvfv(GL_TEXTURE_ENV, env_pnames[i], fv);
        capi_value("tex_env", "0x%x %d %d %d %d %g %g %g %g", env_pnames[i], iv[0], iv[1], iv[2], iv[3], fv[0], fv[1],
                   fv[2], fv[3]);
    }
    GLfloat bias;
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &bias);
    capi_value("unit_bias", "%g", bias);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(1, 2, 3);
    glScalef(2, 2, 2);
    const GLdouble plane[4] = {1, 2, 3, 4};
    glTexGendv(GL_T, GL_EYE_PLANE, plane);
    glTexGendv(GL_T, GL_OBJECT_PLANE, plane);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glEnable(GL_TEXTURE_GEN_T);
    glLoadIdentity();
    GLdouble dv[4];
    GLfloat fv[4];
    GLint iv[4];
    glGetTexGendv(GL_T, GL_EYE_PLANE, dv);
    glGetTexGenfv(GL_T, GL_OBJECT_PLANE, fv);
    glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, iv);
    capi_value("texgen", "%g %g %g %g | %g %g %g %g | 0x%x", dv[0], dv[1], dv[2], dv[3], fv[0], fv[1], fv[2], fv[3],
               iv[0]);
    capi_value_query("unit1", "gen_t", GL_TEXTURE_GEN_T, 1);
    capi_value_query("unit1", "binding_2d", GL_TEXTURE_BINDING_2D, 1);

    /* GL_TEXTURE_BIT restores the active unit, enables, bindings, environment and texgen. */
    glPushAttrib(GL_TEXTURE_BIT);
    /* The bound object's parameters are part of the group too. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
    glBindTexture(GL_TEXTURE_2D, names[2]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    glDisable(GL_TEXTURE_GEN_T);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glActiveTexture(GL_TEXTURE2);
    glPopAttrib();
    capi_value_query("popped", "active", GL_ACTIVE_TEXTURE, 1);
    capi_value_query("popped", "binding_2d", GL_TEXTURE_BINDING_2D, 1);
    capi_value_query("popped", "gen_t", GL_TEXTURE_GEN_T, 1);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv);
    glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, iv + 1);
    capi_value("popped_env_gen", "0x%x 0x%x", iv[0], iv[1]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, iv);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, iv + 1);
    capi_value("popped_object", "0x%x 0x%x", iv[0], iv[1]);
    glDisable(GL_TEXTURE_GEN_T);
    glActiveTexture(GL_TEXTURE0);

    /* Deleting a bound texture reverts the binding to 0. */
    glBindTexture(GL_TEXTURE_2D, names[1]);
    glDeleteTextures(1, &names[1]);
    capi_value_query("deleted", "binding_2d", GL_TEXTURE_BINDING_2D, 1);
    capi_value("is_texture_deleted", "%d", glIsTexture(names[1]));
    GLboolean resident[3];
    capi_value("resident", "%d", glAreTexturesResident(1, &names[2], resident));
    expect(GL_NO_ERROR, "queries");
}

/* Texture coordinates on lines and points (interpolated along lines, one per point). */
static void lines_points(void)
{
    unsigned char img[4 * 4 * 4];
    for (int i = 0; i < 64; i++)
        img[i] = (unsigned char)(i * 37 + 11);
    glBindTexture(GL_TEXTURE_2D, 0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES);
    glTexCoord2f(0.05f, 0.1f);
    glVertex2f(1, 2.5f);
    glTexCoord2f(0.95f, 0.9f);
    glVertex2f(15, 13.5f);
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    glTexCoord2f(0.6f, 0.1f);
    glVertex2f(12.5f, 3.5f);
    glTexCoord2f(0.1f, 0.8f);
    glVertex2f(3.5f, 12.5f);
    glEnd();
    capi_save_framebuffer("lines_points", W, H);
    glDisable(GL_TEXTURE_2D);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    errors();
    queries();
    lines_points();
    return capi_finish();
}
