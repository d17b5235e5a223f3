/* GL_EXT_packed_depth_stencil textures: GL_DEPTH_STENCIL / GL_DEPTH24_STENCIL8 images given
 * as GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 data (glTexImage2D, glTexSubImage2D, the format
 * and type errors), read back with glGetTexImage, their level parameters, sampled as depth
 * textures with depth comparison, copied from the window (glCopyTexImage2D), and rendered
 * into through a framebuffer object with the stencil test (then read back as depth and
 * stencil). */
#include "common.h"

#define W 16
#define H 16

static void quad(float z, float r)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, r);
    glVertex3f(0, 0, z);
    glTexCoord3f(1, 0, r);
    glVertex3f(1, 0, z);
    glTexCoord3f(1, 1, r);
    glVertex3f(1, 1, z);
    glTexCoord3f(0, 1, r);
    glVertex3f(0, 1, z);
    glEnd();
}

/* Saves level 0 of the bound 2D texture as GL_DEPTH_STENCIL words (4 bytes a texel). */
static void save_words(const char *name, int w, int h)
{
    static GLuint words[W * H];
    memset(words, 0xcd, sizeof words);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, words);
    capi_save_image(name, w, h, 4, CAPI_U8, words);
}

static void errors(void)
{
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    GLuint word = 0;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 1, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT, &word);
    capi_value("err.ds_uint", "0x%x", glGetError());
    /* Depth formats take depth or depth-stencil data (GL 2.1 + EXT_packed_depth_stencil). */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 1, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &word);
    capi_expect_error(GL_NO_ERROR, "depth-stencil image from depth data");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &word);
    capi_expect_error(GL_INVALID_OPERATION, "color image from depth-stencil data");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &word);
    capi_expect_error(GL_NO_ERROR, "depth image from depth-stencil data");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &word);
    capi_value("err.depth_stencil_read_of_depth", "0x%x", glGetError());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_INT_24_8, &word);
    capi_expect_error(GL_INVALID_OPERATION, "24_8 with a color format");
    GLint format = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    capi_value("err.level_untouched", "0x%x", format);
    /* A depth-stencil image, then sub-images of the wrong kinds. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, 1, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &word);
    capi_expect_error(GL_NO_ERROR, "GL_DEPTH_STENCIL internal format");
    word = 0x12345678;
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &word);
    GLuint depth = 0x80000000u;
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &depth);
    capi_expect_error(GL_NO_ERROR, "depth sub-image of a depth-stencil image");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &word);
    /* Mesa 22 (llvmpipe) loses the stencil of the texel here (and truncates the depth to
     * 0x7fffff): depth data replaces only depth, as tessera does. */
    if (capi_is_tessera())
        capi_check(word == 0x80000078, "depth sub-image keeps stencil: 0x%08x", word);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &word);
    capi_expect_error(GL_INVALID_OPERATION, "color sub-image of a depth-stencil image");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &word);
    capi_expect_error(GL_INVALID_OPERATION, "color read of a depth-stencil image");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH24_STENCIL8, 1, 1, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &word);
    capi_value("err.3d", "0x%x", glGetError());
    glDeleteTextures(1, &t);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    capi_check(ext && strstr(ext, "GL_EXT_packed_depth_stencil ") != NULL, "extension advertised");
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, 1, 0, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    errors();

    /* Upload: depth ramps across, stencil = a pattern; then a 2x2 sub-image. */
    GLuint tex[3];
    glGenTextures(3, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    static GLuint words[4 * 4];
    for (int i = 0; i < 16; i++)
        words[i] = ((GLuint)(i * 0x111111u) << 8) | (GLuint)(i * 17 + 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 4, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, words);
    capi_expect_error(GL_NO_ERROR, "depth-stencil upload");
    GLint v;
    const GLenum params[] = {GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE,
                             GL_TEXTURE_RED_SIZE, GL_TEXTURE_ALPHA_SIZE};
    for (int i = 0; i < 5; i++) {
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, params[i], &v);
        capi_value("level_param", "%d 0x%x", i, v);
    }
    GLuint sub[4] = {0xffffff01, 0x80000002, 0x00000003, 0x123456ff};
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, sub);
    capi_expect_error(GL_NO_ERROR, "depth-stencil sub-image");
    static GLuint back[4 * 4];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    capi_expect_error(GL_NO_ERROR, "depth-stencil read");
    capi_check(back[2 * 4 + 1] == 0xffffff01 && back[3 * 4 + 2] == 0x123456ff && back[5] == words[5],
               "read back what was stored");
    save_words("upload", 4, 4);
    static GLfloat depths[4 * 4];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    capi_value("read_depth_float.err", "0x%x", glGetError());
    capi_save_image("upload_depth_float", 4, 4, 1, CAPI_F32, depths);

    /* Sampling: nearest, compared with r = 0.5 (LEQUAL), as luminance, then as alpha. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0.5f);
    capi_save_framebuffer("sample_plain", W, H);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0.5f);
    capi_save_framebuffer("sample_compare_luminance", W, H);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 0.5f, 0.25f, 1);
    quad(0, 0.3f);
    capi_save_framebuffer("sample_compare_alpha", W, H);
    glDisable(GL_TEXTURE_2D);
    glColor4f(1, 1, 1, 1);

    /* glCopyTexImage2D from the window's depth and stencil. */
    glClearDepth(0.75);
    glClearStencil(0x5a);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0x21, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_TRIANGLES);
    glVertex3f(0.1f, 0.1f, 0.5f);
    glVertex3f(0.9f, 0.3f, 0.5f);
    glVertex3f(0.3f, 0.9f, 0.5f);
    glEnd();
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    static GLuint window[W * H];
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, window);
    capi_save_image("window_words", W, H, 4, CAPI_U8, window);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 0, 0, W, H, 0);
    capi_expect_error(GL_NO_ERROR, "copy of depth and stencil");
    save_words("copy", W, H);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 8, 8, 4, 4);
    capi_expect_error(GL_NO_ERROR, "sub-copy of depth and stencil");
    save_words("copy_sub", W, H);

    /* Render to texture: a DEPTH24_STENCIL8 texture at the depth and stencil points. */
    GLuint fb;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, W, H, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, NULL);
    GLuint color;
    glGenTextures(1, &color);
    glBindTexture(GL_TEXTURE_2D, color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex[2], 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, tex[2], 0);
    capi_value("fbo.status", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glGetIntegerv(GL_STENCIL_BITS, &v);
    capi_value("fbo.stencil_bits", "%d", v);
    glGetIntegerv(GL_DEPTH_BITS, &v);
    capi_value("fbo.depth_bits", "%d", v);
    glViewport(0, 0, W, H);
    glClearColor(0, 0, 0, 1);
    glClearDepth(1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    /* A triangle writes stencil 7 and its depth (constant: tessera's depth interpolation
     * of sloped triangles is not llvmpipe's, which is not what this test is about). */
    glStencilFunc(GL_ALWAYS, 7, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor4f(1, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glVertex3f(0.05f, 0.05f, 0.5f);
    glVertex3f(0.95f, 0.2f, 0.5f);
    glVertex3f(0.2f, 0.95f, 0.5f);
    glEnd();
    /* A quad drawn only where stencil is 7 and in front; it increments stencil there. */
    glStencilFunc(GL_EQUAL, 7, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glColor4f(0, 1, 0, 1);
    glBegin(GL_QUADS);
    glVertex3f(0, 0, 0.9f);
    glVertex3f(0.6f, 0, 0.9f);
    glVertex3f(0.6f, 1, 0.9f);
    glVertex3f(0, 1, 0.9f);
    glEnd();
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    capi_save_framebuffer("rtt_color", W, H);
    static GLubyte stencil[W * H];
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    capi_save_image("rtt_stencil_readpixels", W, H, 1, CAPI_U8, stencil);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    save_words("rtt_texture", W, H);
    static GLuint rtt[W * H];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, rtt);
    int eights = 0, sevens = 0;
    for (int i = 0; i < W * H; i++) {
        eights += (rtt[i] & 0xff) == 8;
        sevens += (rtt[i] & 0xff) == 7;
    }
    capi_check(eights > 10 && sevens > 10, "stencil rendered into the texture (%d, %d)", eights, sevens);

    /* The rendered texture sampled with depth comparison. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0.45f);
    capi_save_framebuffer("rtt_sampled", W, H);
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
