/* sRGB textures (EXT_texture_sRGB, core in GL 2.1): every sRGB internal format is
 * specified from the same bytes, its sizes and internal format queried and its texels read
 * back with glGetTexImage (stored as given: no conversion); then drawn into a GL_FLOAT
 * buffer and read back as floats, so that the decoded values are compared bit for bit
 * (llvmpipe decodes with its own curve, not the exact sRGB one). Nearest and linear
 * magnification, trilinear minification (explicit levels), a 3D and a cube map texture,
 * a GLSL fragment shader sampling one, float client data, glTexSubImage, and a
 * GL_SRGB8_ALPHA8 texture as a framebuffer object's colour attachment (GL 2.1 has no
 * GL_FRAMEBUFFER_SRGB: writes and blending are not encoded).
 *
 * Where tessera differs: the generic compressed GL_COMPRESSED_SRGB and
 * GL_COMPRESSED_SRGB_ALPHA are stored uncompressed (Mesa picks DXT1/DXT5 sRGB): their
 * GL_TEXTURE_COMPRESSED and GL_TEXTURE_INTERNAL_FORMAT are branched on, and their texels
 * are not compared (DXT is lossy). */
#include "common.h"

#define W 32
#define H 32

static unsigned rng = 4242;
static unsigned char rnd(void)
{
    rng = rng * 1103515245u + 12345u;
    return (unsigned char)(rng >> 16);
}

static float pixels[W * H * 4];

static void save(const char *name)
{
    glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, pixels);
    capi_save_image(name, W, H, 4, CAPI_F32, pixels);
}

/* A quad over the window with texture coordinates [s0, s1] x [t0, t1] (r = r). */
static void quad(float s0, float t0, float s1, float t1, float r)
{
    glBegin(GL_QUADS);
    glTexCoord3f(s0, t0, r);
    glVertex2f(-1, -1);
    glTexCoord3f(s1, t0, r);
    glVertex2f(1, -1);
    glTexCoord3f(s1, t1, r);
    glVertex2f(1, 1);
    glTexCoord3f(s0, t1, r);
    glVertex2f(-1, 1);
    glEnd();
}

static unsigned hash(const unsigned char *p, int n)
{
    unsigned h = 2166136261u;
    for (int i = 0; i < n; i++)
        h = (h ^ p[i]) * 16777619u;
    return h;
}

static const struct {
    GLenum format;
    const char *name;
    int compressed_on_mesa;
} formats[] = {
    {GL_SRGB, "srgb", 0},
    {GL_SRGB8, "srgb8", 0},
    {GL_SRGB_ALPHA, "srgb_alpha", 0},
    {GL_SRGB8_ALPHA8, "srgb8_alpha8", 0},
    {GL_SLUMINANCE, "sluminance", 0},
    {GL_SLUMINANCE8, "sluminance8", 0},
    {GL_SLUMINANCE_ALPHA, "sluminance_alpha", 0},
    {GL_SLUMINANCE8_ALPHA8, "sluminance8_alpha8", 0},
    {GL_COMPRESSED_SRGB, "compressed_srgb", 1},
    {GL_COMPRESSED_SRGB_ALPHA, "compressed_srgb_alpha", 1},
    {GL_COMPRESSED_SLUMINANCE, "compressed_sluminance", 0},
    {GL_COMPRESSED_SLUMINANCE_ALPHA, "compressed_sluminance_alpha", 0},
};

/* Every format from the same bytes: queries, glGetTexImage and a nearest draw of all 256
 * values of each channel (a 16x16 texture, texel for pixel over a 32x32 window: 2x2). */
static void formats_and_decoding(void)
{
    unsigned char img[16 * 16 * 4], back[16 * 16 * 4];
    for (int i = 0; i < 16 * 16; i++) {
        img[4 * i] = (unsigned char)i;
        img[4 * i + 1] = (unsigned char)(255 - i);
        img[4 * i + 2] = (unsigned char)(i * 7);
        img[4 * i + 3] = (unsigned char)(i * 13);
    }
    static const GLenum sizes[] = {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                                   GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (unsigned f = 0; f < sizeof formats / sizeof formats[0]; f++) {
        char key[96];
        glTexImage2D(GL_TEXTURE_2D, 0, formats[f].format, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
        snprintf(key, sizeof key, "%s.teximage", formats[f].name);
        capi_expect_error(GL_NO_ERROR, key);
        GLint v[6];
        for (int k = 0; k < 6; k++)
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, sizes[k], &v[k]);
        if (formats[f].compressed_on_mesa && !capi_is_tessera()) {
            /* DXT: 4 bits per colour channel reported; tessera stores 8. */
            for (int k = 0; k < 4; k++)
                v[k] = v[k] ? 8 : 0;
        }
        snprintf(key, sizeof key, "%s.sizes", formats[f].name);
        capi_value(key, "%d %d %d %d %d %d", v[0], v[1], v[2], v[3], v[4], v[5]);
        GLint compressed = -1, internal = -1;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
        if (formats[f].compressed_on_mesa) {
            capi_check(compressed == !capi_is_tessera(), "%s: compressed %d", formats[f].name, compressed);
            capi_check(capi_is_tessera() ? internal == (GLint)formats[f].format : internal != (GLint)formats[f].format,
                       "%s: internal format 0x%x", formats[f].name, internal);
            continue;
        }
        snprintf(key, sizeof key, "%s.compressed_internal", formats[f].name);
        capi_value(key, "%d 0x%x", compressed, internal);
        memset(back, 0xee, sizeof back);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
        snprintf(key, sizeof key, "%s.getteximage", formats[f].name);
        capi_value(key, "%08x %d %d %d %d", hash(back, sizeof back), back[4], back[5], back[6], back[7]);
        glEnable(GL_TEXTURE_2D);
        quad(0, 0, 1, 1, 0);
        glDisable(GL_TEXTURE_2D);
        snprintf(key, sizeof key, "%s.nearest", formats[f].name);
        save(key);
    }
    capi_expect_error(GL_NO_ERROR, "formats");
}

/* Linear magnification of a 4x4 texture, and trilinear minification through explicit
 * levels, wrapped by repeat (an sRGB texture filters its decoded texels). */
static void filtering(void)
{
    unsigned char img[64 * 64 * 4];
    for (int i = 0; i < 64 * 64 * 4; i++)
        img[i] = rnd();
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    quad(-0.3f, -0.2f, 1.4f, 1.1f, 0);
    save("linear_mag");
    for (int level = 0, n = 64; n >= 1; level++, n /= 2) {
        for (int i = 0; i < n * n * 4; i++)
            img[i] = rnd();
        glTexImage2D(GL_TEXTURE_2D, level, GL_SRGB_ALPHA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    quad(0, 0, 3.3f, 2.7f, 0);
    save("trilinear_min");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    quad(0, 0, 5.1f, 4.3f, 0);
    save("nearest_mip_min");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.5f, 0.75f, 1.0f, 0.5f);
    quad(0, 0, 2.2f, 1.9f, 0);
    glColor4f(1, 1, 1, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    save("modulate_min");
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &t);

    /* A luminance-alpha sRGB texture, linear: luminance decoded, alpha not. */
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    for (int i = 0; i < 8 * 8 * 2; i++)
        img[i] = rnd();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SLUMINANCE8_ALPHA8, 8, 8, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
    glEnable(GL_TEXTURE_2D);
    quad(-0.2f, -0.5f, 1.2f, 1.5f, 0);
    glDisable(GL_TEXTURE_2D);
    save("sluminance_alpha_linear");
    glDeleteTextures(1, &t);
    capi_expect_error(GL_NO_ERROR, "filtering");
}

/* 3D and cube map sRGB textures, linear. */
static void other_targets(void)
{
    unsigned char img[8 * 8 * 8 * 4];
    for (int i = 0; i < (int)sizeof img; i++)
        img[i] = rnd();
    GLuint t[2];
    glGenTextures(2, t);
    glBindTexture(GL_TEXTURE_3D, t[0]);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_SRGB8, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_3D);
    quad(0.1f, 0.05f, 0.9f, 1.1f, 0.37f);
    glDisable(GL_TEXTURE_3D);
    save("texture_3d");
    glBindTexture(GL_TEXTURE_CUBE_MAP, t[1]);
    for (int face = 0; face < 6; face++)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_SRGB8_ALPHA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img + face * 8 * 8 * 4);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_CUBE_MAP);
    quad(-1.0f, -0.8f, 0.9f, 1.0f, 0.7f);
    glDisable(GL_TEXTURE_CUBE_MAP);
    save("texture_cube");
    glDeleteTextures(2, t);
    capi_expect_error(GL_NO_ERROR, "other targets");
}

/* A fragment shader sampling an sRGB texture (decoded as in fixed function). */
static void glsl(void)
{
    static const char *fs = "uniform sampler2D tex;\n"
                            "void main() { vec4 c = texture2D(tex, gl_TexCoord[0].st);\n"
                            "  gl_FragColor = vec4(c.bgr, c.a * 0.5 + 0.25); }\n";
    unsigned char img[8 * 8 * 4];
    for (int i = 0; i < (int)sizeof img; i++)
        img[i] = rnd();
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB_ALPHA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    GLuint p = capi_program("glsl", NULL, fs);
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, "tex"), 0);
    quad(-0.25f, 0.1f, 1.3f, 0.9f, 0);
    glUseProgram(0);
    save("glsl_sampled");
    glDeleteProgram(p);
    glDeleteTextures(1, &t);
    capi_expect_error(GL_NO_ERROR, "glsl");
}

/* Float and ubyte client data, glTexSubImage and glCopyTexSubImage: the stored bytes (no
 * encoding on the way in). */
static void uploads(void)
{
    float data[4 * 4 * 4];
    for (int i = 0; i < 4 * 4 * 4; i++)
        data[i] = (float)i / 63.0f;
    unsigned char back[4 * 4 * 4];
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 4, 4, 0, GL_RGBA, GL_FLOAT, data);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    capi_value("upload.float", "%08x %d %d %d %d", hash(back, sizeof back), back[4], back[5], back[6], back[7]);
    float fback[4 * 4 * 4];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, fback);
    capi_value("upload.float_back", "%a %a %a %a", fback[4], fback[5], fback[6], fback[7]);
    unsigned char sub[2 * 2 * 3] = {10, 20, 30, 40, 50, 60, 70, 80, 90, 200, 210, 220};
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, sub);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    capi_value("upload.sub", "%08x", hash(back, sizeof back));
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SLUMINANCE, 4, 4, 0, GL_RGBA, GL_FLOAT, data);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, back);
    capi_value("upload.sluminance", "%08x %d %d", hash(back, 16), back[1], back[2]);
    glDeleteTextures(1, &t);
    capi_expect_error(GL_NO_ERROR, "uploads");
}

/* A GL_SRGB8_ALPHA8 texture as a framebuffer object's colour buffer: clears, a smooth
 * triangle and blending write linear values unencoded; then the texture is sampled. */
static void framebuffer_attachment(void)
{
    GLuint t, fbo;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenFramebuffersEXT(1, &fbo);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, t, 0);
    GLenum status = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    capi_value("fbo.status", "0x%x", status);
    glViewport(0, 0, 16, 16);
    glClearColor(0.5f, 0.25f, 0.125f, 0.75f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 0.5f);
    glVertex2f(-1, -1);
    glColor4f(0, 1, 0, 1);
    glVertex2f(1, -1);
    glColor4f(0, 0, 1, 0.25f);
    glVertex2f(0, 1);
    glEnd();
    glDisable(GL_BLEND);
    glColor4f(1, 1, 1, 1);
    unsigned char px[16 * 16 * 4];
    glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_value("fbo.clear_pixel", "%d %d %d %d", px[0], px[1], px[2], px[3]);
    capi_save_image("fbo_rendered", 16, 16, 4, CAPI_U8, px);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    glDeleteFramebuffersEXT(1, &fbo);
    glViewport(0, 0, W, H);
    glEnable(GL_TEXTURE_2D);
    quad(0, 0, 1, 1, 0);
    glDisable(GL_TEXTURE_2D);
    save("fbo_sampled");
    glDeleteTextures(1, &t);
    capi_expect_error(GL_NO_ERROR, "fbo");
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_FLOAT, 0, 0, 0, W, H, NULL);
    capi_expect_error(GL_NO_ERROR, "context");
    formats_and_decoding();
    filtering();
    other_targets();
    glsl();
    uploads();
    framebuffer_attachment();
    return capi_finish();
}
