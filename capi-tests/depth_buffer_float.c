/* GL_ARB_depth_buffer_float, compared with Mesa (llvmpipe stores Z32_FLOAT and
 * Z32_FLOAT_S8X24_UINT; tessera keeps the float bit patterns in its 32-bit depth plane):
 *  - GL_DEPTH_COMPONENT32F and GL_DEPTH32F_STENCIL8 renderbuffers: complete framebuffers,
 *    GL_DEPTH_BITS 32, GL_RENDERBUFFER_DEPTH_SIZE, attachment component type GL_FLOAT;
 *  - clears and drawn depths read back as GL_FLOAT exactly (0.1f, 2e-8f, 3e-8f: values a
 *    fixed-point buffer cannot hold), fragment depth clamped to [0, 1];
 *  - a reversed-Z scene (glClipControl GL_ZERO_TO_ONE, GL_GREATER, clear 0, infinite far
 *    plane): quads at 1e5 and 1e5 + 10 units resolve in a float buffer, and do not in a
 *    24-bit one (both depths round to the same 24-bit value, the farther quad wins);
 *  - stencil beside float depth (GL_DEPTH32F_STENCIL8);
 *  - polygon offset: r = 2^(e − 23) of the primitive's largest depth, so units 1 at depth
 *    0.25 moves it by 2^-25 exactly;
 *  - GL_DEPTH_COMPONENT32F textures: glTexImage2D from GL_FLOAT (clamped to [0, 1]) and
 *    GL_UNSIGNED_INT, GL_TEXTURE_DEPTH_SIZE, glGetTexImage as GL_FLOAT, rendering into
 *    the texture and reading it back, sampling with depth compare;
 *  - glBlitFramebuffer of depth between float and fixed-point buffers: GL_INVALID_OPERATION
 *    (the formats differ), between two float buffers: exact;
 *  - the pixel type GL_FLOAT_32_UNSIGNED_INT_24_8_REV: glReadPixels and glDrawPixels of
 *    GL_DEPTH_STENCIL on float and 24-bit buffers, glTexImage2D/glGetTexImage of a
 *    GL_DEPTH32F_STENCIL8 texture, and its errors with other formats. */
#include "common.h"

#define W 16
#define H 16

static PFNGLCLIPCONTROLPROC clip_control;

static GLuint make_fbo(GLenum depth_format, int texture, GLuint *color_out, GLuint *depth_out)
{
    GLuint fb, color, depth;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    int stencil = depth_format == GL_DEPTH32F_STENCIL8 || depth_format == GL_DEPTH24_STENCIL8;
    GLenum point = stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    if (texture) {
        glGenTextures(1, &depth);
        glBindTexture(GL_TEXTURE_2D, depth);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, depth_format, W, H, 0, stencil ? GL_DEPTH_STENCIL : GL_DEPTH_COMPONENT,
                     stencil ? GL_UNSIGNED_INT_24_8 : GL_FLOAT, NULL);
        glFramebufferTexture2D(GL_FRAMEBUFFER, point, GL_TEXTURE_2D, depth, 0);
    } else {
        glGenRenderbuffers(1, &depth);
        glBindRenderbuffer(GL_RENDERBUFFER, depth);
        glRenderbufferStorage(GL_RENDERBUFFER, depth_format, W, H);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, point, GL_RENDERBUFFER, depth);
    }
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    capi_check(status == GL_FRAMEBUFFER_COMPLETE, "FBO with 0x%x (%s) complete: 0x%x", depth_format,
               texture ? "texture" : "renderbuffer", status);
    capi_expect_error(GL_NO_ERROR, "make_fbo");
    glViewport(0, 0, W, H);
    *color_out = color;
    *depth_out = depth;
    return fb;
}

static void free_fbo(GLuint fb, GLuint color, GLuint depth, int texture)
{
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(1, &color);
    if (texture)
        glDeleteTextures(1, &depth);
    else
        glDeleteRenderbuffers(1, &depth);
}

/* A quad over the left (`half` 0), right (1) or whole (2) viewport at NDC depth z. */
static void quad(float z, int half)
{
    float x0 = half == 1 ? 0.0f : -1.0f, x1 = half == 0 ? 0.0f : 1.0f;
    glBegin(GL_QUADS);
    glVertex3f(x0, -1, z);
    glVertex3f(x1, -1, z);
    glVertex3f(x1, 1, z);
    glVertex3f(x0, 1, z);
    glEnd();
}

static float read_depth(int x, int y)
{
    GLfloat z = -1;
    glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
    return z;
}

static void identity(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* Clears, exact depths, clamping, state queries, on one depth format. */
static void exact_depths(GLenum format, int texture, const char *name)
{
    char key[96];
    GLuint color, depth;
    GLuint fb = make_fbo(format, texture, &color, &depth);
    int is_float = format == GL_DEPTH_COMPONENT32F || format == GL_DEPTH32F_STENCIL8;
    snprintf(key, sizeof key, "%s", name);
    capi_value_query(key, "depth_bits", GL_DEPTH_BITS, 1);
    capi_value_query(key, "stencil_bits", GL_STENCIL_BITS, 1);
    GLint bits = 0, type = 0;
    glGetIntegerv(GL_DEPTH_BITS, &bits);
    capi_check(bits == (is_float ? 32 : 24), "%s: GL_DEPTH_BITS %d", name, bits);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
    capi_check(type == (is_float ? GL_FLOAT : GL_UNSIGNED_NORMALIZED), "%s: component type 0x%x", name, type);
    snprintf(key, sizeof key, "%s.component_type", name);
    capi_value(key, "0x%x", type);
    if (!texture) {
        GLint size = 0;
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &size);
        snprintf(key, sizeof key, "%s.renderbuffer_depth_size", name);
        capi_value(key, "%d", size);
    }
    capi_expect_error(GL_NO_ERROR, "queries");

    /* A whole clear and a scissored one of 0.1: float buffers hold 0.1f itself. */
    glClearDepth(0.1);
    glClear(GL_DEPTH_BUFFER_BIT);
    float z = read_depth(3, 3);
    snprintf(key, sizeof key, "%s.clear_0_1", name);
    capi_value(key, "%a", z);
    if (is_float)
        capi_check(z == 0.1f, "%s: cleared depth %a, expected 0.1f", name, z);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 4, 4);
    glClearDepth(0.7);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    snprintf(key, sizeof key, "%s.scissored_clear_0_7", name);
    capi_value(key, "%a", read_depth(1, 1));

    /* Depths a 24-bit buffer rounds together (both to 0): red at 2e-8, then green behind it
     * at 1e-8 with GL_GEQUAL (reversed Z), which must fail. */
    identity();
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glClearDepth(0);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(1, 0, 0);
    quad(2e-8f, 2);
    glDepthFunc(GL_GEQUAL);
    glColor3f(0, 1, 0);
    quad(1e-8f, 2);
    GLubyte px[4];
    glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    z = read_depth(8, 8);
    snprintf(key, sizeof key, "%s.small_depth", name);
    capi_value(key, "%a rgb %d %d %d", z, px[0], px[1], px[2]);
    if (is_float) {
        capi_check(z == 2e-8f, "%s: depth %a, expected 2e-8f exactly", name, z);
        capi_check(px[0] == 255 && px[1] == 0, "%s: the nearer quad (2e-8) stays: %d %d", name, px[0], px[1]);
    } else {
        capi_check(px[1] == 255 && px[0] == 0, "%s: 24 bits cannot separate 1e-8 and 2e-8: %d %d", name, px[0],
                   px[1]);
    }
    /* Depth beyond [0, 1] (GL_DEPTH_CLAMP keeps the fragment) stores clamped. */
    glEnable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_ALWAYS);
    quad(1.5f, 0);
    quad(-0.5f, 1);
    glDisable(GL_DEPTH_CLAMP);
    float zl = read_depth(2, 8), zr = read_depth(12, 8);
    snprintf(key, sizeof key, "%s.clamped", name);
    capi_value(key, "%a %a", zl, zr);
    capi_check(zl == 1.0f && zr == 0.0f, "%s: clamped depths %a %a", name, zl, zr);
    /* The whole plane as GL_FLOAT and as GL_UNSIGNED_INT. */
    static GLfloat plane[W * H];
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, plane);
    snprintf(key, sizeof key, "%s_depth", name);
    capi_save_image(key, W, H, 1, CAPI_F32, plane);
    GLuint u = 0;
    glReadPixels(2, 8, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &u);
    snprintf(key, sizeof key, "%s.uint_one", name);
    capi_value(key, "0x%x", u);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    capi_expect_error(GL_NO_ERROR, "exact depths");
    free_fbo(fb, color, depth, texture);
}

/* Reversed Z: infinite far plane, z_ndc = n / d. A quad at 1e5 + 10 (green, drawn first)
 * and one at 1e5 (red, in front of it) must leave red; in 24 bits both depths are 17 and
 * the nearer quad fails GL_GREATER. */
static void reversed_z(GLenum format, const char *name)
{
    GLuint color, depth;
    GLuint fb = make_fbo(format, 0, &color, &depth);
    const float n = 0.1f;
    const GLfloat reversed[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1, 0, 0, n, 0};
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(reversed);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glClearDepth(0);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (int i = 0; i < 2; i++) {
        float d = i == 0 ? 1e5f + 10.0f : 1e5f;
        glColor3f(i == 1, i == 0, 0);
        glBegin(GL_QUADS);
        glVertex3f(-d, -d, -d);
        glVertex3f(d, -d, -d);
        glVertex3f(d, d, -d);
        glVertex3f(-d, d, -d);
        glEnd();
    }
    GLubyte px[4];
    glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    float z = read_depth(8, 8);
    char key[64];
    snprintf(key, sizeof key, "reversed_z_%s", name);
    capi_value(key, "%a rgb %d %d %d", z, px[0], px[1], px[2]);
    if (format == GL_DEPTH_COMPONENT32F)
        capi_check(px[0] == 255 && px[1] == 0, "float reversed Z resolves 10 units at 1e5: %d %d", px[0], px[1]);
    else
        capi_check(px[1] == 255, "24-bit reversed Z cannot: %d %d", px[0], px[1]);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    identity();
    free_fbo(fb, color, depth, 0);
}

/* Stencil beside float depth, read back alone and as GL_UNSIGNED_INT_24_8. */
static void stencil_with_float_depth(void)
{
    GLuint color, depth;
    GLuint fb = make_fbo(GL_DEPTH32F_STENCIL8, 0, &color, &depth);
    identity();
    glClearStencil(0);
    glClearDepth(0.25);
    glClear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0x5a, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glEnable(GL_DEPTH_TEST);
    quad(-0.9f, 0); /* window depth 0.05 passes GL_LESS */
    quad(0.9f, 1);  /* window depth 0.95 fails */
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    GLubyte s[2];
    glReadPixels(2, 8, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[0]);
    glReadPixels(12, 8, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[1]);
    capi_check(s[0] == 0x5a && s[1] == 0, "stencil written where depth passed: 0x%x 0x%x", s[0], s[1]);
    GLuint packed[2];
    glReadPixels(2, 8, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &packed[0]);
    glReadPixels(12, 8, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &packed[1]);
    capi_value("d32fs8.stencil", "0x%x 0x%x", s[0], s[1]);
    capi_value("d32fs8.packed", "0x%08x 0x%08x", packed[0], packed[1]);
    capi_value("d32fs8.depth", "%a %a", read_depth(2, 8), read_depth(12, 8));
    capi_expect_error(GL_NO_ERROR, "stencil with float depth");
    free_fbo(fb, color, depth, 0);
}

static void polygon_offset(void)
{
    GLuint color, depth;
    GLuint fb = make_fbo(GL_DEPTH_COMPONENT32F, 0, &color, &depth);
    identity();
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_POLYGON_OFFSET_FILL);
    const float depths[3] = {0.25f, 0.7f, 1e-5f};
    const float units[3] = {1.0f, -4.0f, 16.0f};
    for (int i = 0; i < 3; i++) {
        glPolygonOffset(0, units[i]);
        quad(depths[i], 2);
        float z = read_depth(8, 8);
        char key[64];
        snprintf(key, sizeof key, "offset.%d", i);
        capi_value(key, "%a", z);
        /* r = 2^(e − 23): 0.25 = 2^-2 → 2^-25; 0.7 (e = −1) → 2^-24; 1e-5 (e = −17) → 2^-40. */
        const float r[3] = {0x1p-25f, 0x1p-24f, 0x1p-40f};
        float expected = depths[i] + units[i] * r[i];
        capi_check(z == expected, "offset %d: %a, expected %a", i, z, expected);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    capi_expect_error(GL_NO_ERROR, "polygon offset");
    free_fbo(fb, color, depth, 0);
}

static void textures(void)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    const GLfloat data[8] = {0.0f, 3e-8f, 0.1f, 0.5f, 1.0f, 1.5f, -0.25f, 0.999999f};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 4, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, data);
    capi_expect_error(GL_NO_ERROR, "glTexImage2D DEPTH_COMPONENT32F from GL_FLOAT");
    GLint size = 0, internal = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &size);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    capi_value("tex.depth_size", "%d internal 0x%x", size, internal);
    capi_check(size == 32, "GL_TEXTURE_DEPTH_SIZE %d", size);
    GLfloat back[8];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
    for (int i = 0; i < 8; i++) {
        char key[32];
        snprintf(key, sizeof key, "tex.float.%d", i);
        capi_value(key, "%a", back[i]);
    }
    capi_check(back[1] == 3e-8f && back[2] == 0.1f && back[7] == 0.999999f, "texels kept exactly: %a %a %a",
               back[1], back[2], back[7]);
    GLushort us[8];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, us);
    capi_value("tex.ushort", "%u %u %u %u %u %u %u %u", us[0], us[1], us[2], us[3], us[4], us[5], us[6], us[7]);
    /* From GL_UNSIGNED_INT: 0x80000000 / (2^32 − 1). */
    const GLuint ui[2] = {0x80000000u, 0xffffffffu};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 2, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, ui);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
    capi_value("tex.from_uint", "%a %a", back[0], back[1]);

    /* Sampling with depth compare: r = 0.3 against the texels with GL_LEQUAL (r <= texel),
     * as luminance: 0.29999998 (the float below 0.3f) fails, 0.3f passes. */
    const GLfloat row[4] = {0.1f, 0.29999998f, 0.3f, 0.9f};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 4, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, row);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glEnable(GL_TEXTURE_2D);
    glColor3f(1, 1, 1);
    identity();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glTexCoord4f(0, 0, 0.3f, 1);
    glVertex2f(-1, -1);
    glTexCoord4f(1, 0, 0.3f, 1);
    glVertex2f(1, -1);
    glTexCoord4f(1, 1, 0.3f, 1);
    glVertex2f(1, 1);
    glTexCoord4f(0, 1, 0.3f, 1);
    glVertex2f(-1, 1);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    GLubyte px[W * 4];
    glReadPixels(0, 8, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    /* Texel k covers x in [4k, 4k + 4): pass (white) where 0.3 <= texel. */
    capi_value("tex.compare", "%d %d %d %d", px[0 * 16 + 2 * 4], px[1 * 16 + 2 * 4], px[2 * 16 + 2 * 4],
               px[3 * 16 + 2 * 4]);
    capi_check(px[8] == 0 && px[16 + 8] == 0 && px[32 + 8] == 255 && px[48 + 8] == 255,
               "compare against exact float texels: %d %d %d %d", px[8], px[24], px[40], px[56]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glDeleteTextures(1, &tex);
    capi_expect_error(GL_NO_ERROR, "textures");

    /* Render into a GL_DEPTH32F_STENCIL8 texture and read its texels. */
    GLuint color, depth;
    GLuint fb = make_fbo(GL_DEPTH32F_STENCIL8, 1, &color, &depth);
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glClearDepth(1);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    quad(3e-8f, 0);
    glDisable(GL_DEPTH_TEST);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, depth);
    static GLfloat texels[W * H];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels);
    capi_value("rtt.texels", "%a %a", texels[8 * W + 2], texels[8 * W + 12]);
    capi_check(texels[8 * W + 2] == 3e-8f && texels[8 * W + 12] == 1.0f, "rendered texels %a %a",
               texels[8 * W + 2], texels[8 * W + 12]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &size);
    GLint stencil_size = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &stencil_size);
    capi_value("rtt.sizes", "%d %d", size, stencil_size);
    capi_expect_error(GL_NO_ERROR, "render to texture");
    free_fbo(fb, color, depth, 1);
}

static void blits(void)
{
    GLuint c1, d1, c2, d2, c3, d3;
    GLuint f32 = make_fbo(GL_DEPTH_COMPONENT32F, 0, &c1, &d1);
    glClearDepth(0.1);
    glClear(GL_DEPTH_BUFFER_BIT);
    GLuint f24 = make_fbo(GL_DEPTH_COMPONENT24, 0, &c2, &d2);
    GLuint other = make_fbo(GL_DEPTH_COMPONENT32F, 0, &c3, &d3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, f32);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f24);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_INVALID_OPERATION, "depth blit float -> 24-bit");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, f24);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f32);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_INVALID_OPERATION, "depth blit 24-bit -> float");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, f32);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, other);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_NO_ERROR, "depth blit float -> float");
    glBindFramebuffer(GL_FRAMEBUFFER, other);
    float z = read_depth(5, 5);
    capi_value("blit.float", "%a", z);
    capi_check(z == 0.1f, "blitted float depth %a", z);
    glClearDepth(1);
    free_fbo(other, c3, d3, 0);
    free_fbo(f24, c2, d2, 0);
    free_fbo(f32, c1, d1, 0);
}

static void rev_type(void)
{
    GLuint color, depth;
    GLuint fb = make_fbo(GL_DEPTH32F_STENCIL8, 0, &color, &depth);
    /* glDrawPixels of two pixels: depth 3e-8 / 1.5 (clamped), stencil 0x33 / 0x1ff (0xff). */
    const GLuint in[4] = {0, 0x33, 0, 0x1ff};
    GLfloat d0 = 3e-8f, d1 = 1.5f;
    GLuint words[4];
    memcpy(&words[0], &d0, 4);
    memcpy(&words[2], &d1, 4);
    words[1] = in[1];
    words[3] = in[3];
    glClearDepth(0.5);
    glClearStencil(0);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glWindowPos2i(3, 4);
    glDrawPixels(2, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, words);
    capi_expect_error(GL_NO_ERROR, "glDrawPixels GL_FLOAT_32_UNSIGNED_INT_24_8_REV");
    GLuint out[6] = {0xdeadbeef, 0xdeadbeef, 0xdeadbeef, 0xdeadbeef, 0xdeadbeef, 0xdeadbeef};
    glReadPixels(2, 4, 3, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
    capi_expect_error(GL_NO_ERROR, "glReadPixels GL_FLOAT_32_UNSIGNED_INT_24_8_REV");
    capi_value("rev.read_float", "%08x %08x %08x %08x %08x %08x", out[0], out[1], out[2], out[3], out[4], out[5]);
    float got;
    memcpy(&got, &out[2], 4);
    capi_check(got == 3e-8f && (out[3] & 0xff) == 0x33, "REV round trip: %a 0x%x", got, out[3]);
    GLuint packed[3];
    glReadPixels(2, 4, 3, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed);
    capi_value("rev.read_24_8", "%08x %08x %08x", packed[0], packed[1], packed[2]);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    glReadPixels(3, 4, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    /* GL_PACK_SWAP_BYTES swaps each 4-byte word, the depth and the stencil word. Mesa 22
     * swaps the depth word and leaves the stencil word of this one-pixel read unswapped
     * (0x00000033); tessera swaps both as the spec says (0x33000000). */
    capi_value("rev.read_swapped", "%08x", out[0]);
    if (capi_is_tessera())
        capi_check(out[1] == 0x33000000u, "swapped stencil word 0x%08x", out[1]);
    /* Errors: the type needs GL_DEPTH_STENCIL. */
    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
    capi_expect_error(GL_INVALID_OPERATION, "glReadPixels DEPTH_COMPONENT with the REV type");
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
    capi_expect_error(GL_INVALID_OPERATION, "glReadPixels RGBA with the REV type");
    glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT, out);
    capi_expect_error(GL_INVALID_ENUM, "glReadPixels DEPTH_STENCIL as GL_FLOAT");
    free_fbo(fb, color, depth, 0);

    /* From a 24-bit depth-stencil buffer. */
    fb = make_fbo(GL_DEPTH24_STENCIL8, 0, &color, &depth);
    glClearDepth(0.1);
    glClearStencil(0x81);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
    capi_value("rev.read_d24s8", "%08x %08x", out[0], out[1]);
    glWindowPos2i(0, 0);
    glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, words);
    glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed);
    capi_value("rev.draw_d24s8", "%08x", packed[0]);
    glClearDepth(1);
    glClearStencil(0);
    capi_expect_error(GL_NO_ERROR, "REV on 24-bit");
    free_fbo(fb, color, depth, 0);

    /* Texture data. */
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 2, 1, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV,
                 words);
    capi_expect_error(GL_NO_ERROR, "glTexImage2D DEPTH32F_STENCIL8 from the REV type");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
    capi_value("rev.teximage", "%08x %08x %08x %08x", out[0], out[1], out[2], out[3]);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed);
    capi_value("rev.teximage_24_8", "%08x %08x", packed[0], packed[1]);
    const GLuint d24s8[2] = {0x80000012u, 0xffffff34u};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 2, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, d24s8);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out);
    capi_value("rev.teximage_from_24_8", "%08x %08x %08x %08x", out[0], out[1], out[2], out[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 2, 1, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT_32_UNSIGNED_INT_24_8_REV, words);
    capi_expect_error(GL_INVALID_OPERATION, "glTexImage2D DEPTH_COMPONENT with the REV type");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, words);
    capi_expect_error(GL_INVALID_OPERATION, "glTexImage2D RGBA with the REV type");
    glDeleteTextures(1, &tex);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    const char *extensions = (const char *)glGetString(GL_EXTENSIONS);
    capi_check(strstr(extensions, "GL_ARB_depth_buffer_float") != NULL, "GL_ARB_depth_buffer_float listed");
    clip_control = (PFNGLCLIPCONTROLPROC)OSMesaGetProcAddress("glClipControl");
    capi_check(clip_control != NULL, "glClipControl");
    if (!clip_control)
        return capi_finish();
    exact_depths(GL_DEPTH_COMPONENT32F, 0, "rb_d32f");
    exact_depths(GL_DEPTH32F_STENCIL8, 0, "rb_d32fs8");
    exact_depths(GL_DEPTH_COMPONENT32F, 1, "tex_d32f");
    exact_depths(GL_DEPTH32F_STENCIL8, 1, "tex_d32fs8");
    exact_depths(GL_DEPTH_COMPONENT24, 0, "rb_d24");
    reversed_z(GL_DEPTH_COMPONENT32F, "float");
    reversed_z(GL_DEPTH_COMPONENT24, "fixed24");
    stencil_with_float_depth();
    polygon_offset();
    textures();
    blits();
    rev_type();
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
