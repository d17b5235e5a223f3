/* GLSL fragment shaders in draws, the inputs and lookups beyond capi glsl_fragment (issue
 * #20): shadow2D and shadow1D on a depth texture with each GL_DEPTH_TEXTURE_MODE and a
 * reference beyond [0, 1] (clamped), shadow2DProj; texture2DProj in its vec3 and vec4
 * forms (q is the last component); texture2D's bias argument (uniform and varying) on a
 * mipmap whose levels have colours of their own, with the texture's GL_TEXTURE_LOD_BIAS
 * too; gl_FragCoord.w on a perspective triangle (1 over the clip w); gl_PointCoord on
 * point sprites with both GL_POINT_SPRITE_COORD_ORIGIN values; gl_FragData[0..2] into a
 * framebuffer object's three colour attachments (glDrawBuffers, the second buffer blended),
 * and gl_FragColor broadcast to all three. Fixed-function vertex
 * processing throughout (programs with a fragment shader only). */
#include "common.h"

#define W 64
#define H 64

static GLuint program(const char *key, const char *fs)
{
    GLuint p = capi_program(key, NULL, fs);
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, "s"), 0);
    capi_expect_error(GL_NO_ERROR, key);
    return p;
}

static void finish(const char *name, GLuint p)
{
    capi_expect_error(GL_NO_ERROR, name);
    capi_save_framebuffer(name, W, H);
    glUseProgram(0);
    glDeleteProgram(p);
}

static void clear(void)
{
    glClearColor(0.25f, 0.25f, 0.25f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
}

/* A quad over the whole window with texture coordinates (s, t, r, q) at its corners. */
static void quad(const float tc[4][4])
{
    static const float xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; i++) {
        glTexCoord4fv(tc[i]);
        glVertex2fv(xy[i]);
    }
    glEnd();
}

/* An 8x8 depth texture: depth (x + 8y) / 64 at texel (x, y). */
static GLuint depth_texture(GLenum target)
{
    GLfloat texels[64];
    for (int i = 0; i < 64; i++)
        texels[i] = (float)i / 64.0f;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(target, tex);
    if (target == GL_TEXTURE_1D)
        glTexImage1D(target, 0, GL_DEPTH_COMPONENT, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels);
    else
        glTexImage2D(target, 0, GL_DEPTH_COMPONENT, 8, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    return tex;
}

static void shadow(void)
{
    /* r from -0.25 (left) to 1.25 (right): clamped to [0, 1] before the comparison. */
    static const float tc[4][4] = {{0, 0, -0.25f, 1}, {1, 0, 1.25f, 1}, {1, 1, 1.25f, 1}, {0, 1, -0.25f, 1}};
    GLuint tex = depth_texture(GL_TEXTURE_2D);
    static const GLenum modes[3] = {GL_LUMINANCE, GL_INTENSITY, GL_ALPHA};
    static const char *names[3] = {"shadow2d_luminance", "shadow2d_intensity", "shadow2d_alpha"};
    for (int m = 0; m < 3; m++) {
        clear();
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, modes[m]);
        GLuint p = program(names[m], "uniform sampler2DShadow s;\n"
                                     "void main() { gl_FragColor = shadow2D(s, gl_TexCoord[0].stp) * 0.75 + 0.125; }\n");
        quad(tc);
        finish(names[m], p);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
    /* Projective: (s, t, r) divided by q = 2 at every corner. */
    static const float proj[4][4] = {{0, 0, 0, 2}, {2, 0, 2, 2}, {2, 2, 2, 2}, {0, 2, 0, 2}};
    clear();
    GLuint p = program("shadow2dproj", "uniform sampler2DShadow s;\n"
                                       "void main() { gl_FragColor = shadow2DProj(s, gl_TexCoord[0]); }\n");
    quad(proj);
    finish("shadow2dproj", p);
    glDeleteTextures(1, &tex);

    tex = depth_texture(GL_TEXTURE_1D);
    clear();
    p = program("shadow1d", "uniform sampler1DShadow s;\n"
                            "void main() { gl_FragColor = shadow1D(s, vec3(gl_TexCoord[0].s, 0.0, gl_TexCoord[0].t)); }\n");
    quad(tc);
    finish("shadow1d", p);
    glDeleteTextures(1, &tex);
    glBindTexture(GL_TEXTURE_1D, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

/* An 8x8 RGBA texture of four coloured quadrants with a white diagonal. */
static GLuint rgba_texture(void)
{
    GLubyte texels[8 * 8 * 4];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            GLubyte *t = texels + 4 * (y * 8 + x);
            t[0] = (GLubyte)(x < 4 ? 255 : 0);
            t[1] = (GLubyte)(y < 4 ? 255 : 0);
            t[2] = (GLubyte)(x == y ? 255 : 64);
            t[3] = 255;
        }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return tex;
}

static void projective(void)
{
    GLuint tex = rgba_texture();
    /* q varies across the quad: 1 at the left, 2 at the right. */
    static const float tc[4][4] = {{0, 0, 1, 1}, {2, 0, 2, 2}, {2, 2, 2, 2}, {0, 1, 1, 1}};
    clear();
    GLuint p = program("texture2dproj_vec3", "uniform sampler2D s;\n"
                                             "void main() { gl_FragColor = texture2DProj(s, gl_TexCoord[0].stp); }\n");
    quad(tc);
    finish("texture2dproj_vec3", p);
    /* The vec4 form divides by the w component (here 2 q), not by the third (p). */
    clear();
    p = program("texture2dproj_vec4", "uniform sampler2D s;\n"
                                      "void main() { gl_FragColor = texture2DProj(s, vec4(gl_TexCoord[0].st, 0.5, 2.0 * gl_TexCoord[0].q) * 2.0); }\n");
    quad(tc);
    finish("texture2dproj_vec4", p);
    glDeleteTextures(1, &tex);
}

/* A 32x32 mipmap whose six levels are red, green, blue, yellow, cyan, magenta. */
static GLuint mipmap(void)
{
    static const GLubyte colors[6][4] = {
        {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}, {0, 255, 255, 255}, {255, 0, 255, 255},
    };
    static GLubyte texels[32 * 32 * 4];
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    for (int level = 0, size = 32; size >= 1; level++, size /= 2) {
        for (int i = 0; i < size * size; i++)
            memcpy(texels + 4 * i, colors[level], 4);
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return tex;
}

static void bias(void)
{
    GLuint tex = mipmap();
    /* One texel of level 0 per 2 pixels: level 0 without a bias. */
    static const float tc[4][4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {1, 1, 0, 1}, {0, 1, 0, 1}};
    clear();
    GLuint p = program("bias_uniform", "uniform sampler2D s;\n"
                                       "void main() { gl_FragColor = texture2D(s, gl_TexCoord[0].st, 2.0); }\n");
    quad(tc);
    finish("bias_uniform", p);
    /* A bias growing left to right (per 8 columns), and one varying per quad. */
    clear();
    p = program("bias_varying", "uniform sampler2D s;\n"
                                "void main() { gl_FragColor = texture2D(s, gl_TexCoord[0].st, floor(gl_FragCoord.x / 8.0) - 1.0); }\n");
    quad(tc);
    finish("bias_varying", p);
    clear();
    p = program("bias_per_pixel", "uniform sampler2D s;\n"
                                  "void main() { gl_FragColor = texture2D(s, gl_TexCoord[0].st, mod(gl_FragCoord.x + gl_FragCoord.y, 4.0)); }\n");
    quad(tc);
    finish("bias_per_pixel", p);
    /* The texture's own bias adds to the shader's. */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.5f);
    clear();
    p = program("bias_with_texture_bias", "uniform sampler2D s;\n"
                                          "void main() { gl_FragColor = texture2D(s, gl_TexCoord[0].st, -0.5 + gl_TexCoord[0].s); }\n");
    quad(tc);
    finish("bias_with_texture_bias", p);
    glDeleteTextures(1, &tex);
}

static void frag_coord_w(void)
{
    clear();
    GLuint p = program("frag_coord_w", "void main() { gl_FragColor = vec4(gl_FragCoord.w, fract(4.0 * gl_FragCoord.w), 1.0 / gl_FragCoord.w / 4.0, 1.0); }\n");
    /* Clip w 1, 2 and 4 at the corners (x, y, z scaled by w: the same window positions). */
    static const float v[4][3] = {{-1, -1, 1}, {1, -1, 2}, {1, 1, 4}, {-1, 1, 2}};
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; i++)
        glVertex4f(v[i][0] * v[i][2], v[i][1] * v[i][2], 0, v[i][2]);
    glEnd();
    finish("frag_coord_w", p);
}

static void point_coord(void)
{
    glEnable(GL_POINT_SPRITE);
    glPointSize(16);
    static const char *names[2] = {"point_coord_upper_left", "point_coord_lower_left"};
    static const GLenum origins[2] = {GL_UPPER_LEFT, GL_LOWER_LEFT};
    for (int o = 0; o < 2; o++) {
        glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, origins[o]);
        clear();
        GLuint p = program(names[o], "#version 120\nvoid main() { gl_FragColor = vec4(gl_PointCoord, 0.5, 1.0); }\n");
        glBegin(GL_POINTS);
        glVertex2f(-0.5f, -0.5f);
        glVertex2f(0.5f, 0.25f);
        glVertex2f(-0.25f, 0.5f);
        glEnd();
        finish(names[o], p);
    }
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    glDisable(GL_POINT_SPRITE);
    glPointSize(1);
}

/* Saves colour attachment `i` of the bound framebuffer object. */
static void save_attachment(const char *name, int i)
{
    static GLubyte px[W * H * 4];
    glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_save_image(name, W, H, 4, CAPI_U8, px);
}

static void frag_data(void)
{
    GLuint fb, tex[3];
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glGenTextures(3, tex);
    for (int i = 0; i < 3; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, tex[i], 0);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    capi_value("frag_data_status", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    /* Buffer 0 is attachment 2, buffer 1 attachment 0, buffer 2 attachment 1. */
    static const GLenum buffers[3] = {GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(3, buffers);
    glClearColor(0.25f, 0.25f, 0.25f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnablei(GL_BLEND, 1);
    glBlendFunci(1, GL_ONE, GL_ONE);
    GLuint p = program("frag_data", "void main() {\n"
                                    "    gl_FragData[0] = vec4(gl_TexCoord[0].st, 0.0, 1.0);\n"
                                    "    gl_FragData[1] = vec4(0.0, 0.5, gl_TexCoord[0].s, 1.0);\n"
                                    "    if (gl_TexCoord[0].t > 0.5) discard;\n"
                                    "    gl_FragData[2] = vec4(1.0 - gl_TexCoord[0].t, 0.25, 0.75, 1.0);\n"
                                    "}\n");
    static const float tc[4][4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {1, 1, 0, 1}, {0, 1, 0, 1}};
    quad(tc);
    /* A triangle and a point too (the other primitives' paths). */
    glBegin(GL_TRIANGLES);
    glTexCoord2f(0.25f, 0.125f);
    glVertex2f(-0.75f, -0.75f);
    glTexCoord2f(0.75f, 0.25f);
    glVertex2f(0.0f, -0.5f);
    glTexCoord2f(0.5f, 0.375f);
    glVertex2f(-0.5f, 0.0f);
    glEnd();
    glPointSize(5);
    glBegin(GL_POINTS);
    glTexCoord2f(0.875f, 0.125f);
    glVertex2f(0.5f, -0.5f);
    glEnd();
    glPointSize(1);
    capi_expect_error(GL_NO_ERROR, "frag_data");
    save_attachment("frag_data_attachment0", 0);
    save_attachment("frag_data_attachment1", 1);
    save_attachment("frag_data_attachment2", 2);
    glUseProgram(0);
    glDeleteProgram(p);

    /* gl_FragColor reaches every draw buffer. */
    glClear(GL_COLOR_BUFFER_BIT);
    p = program("frag_color_broadcast", "void main() { gl_FragColor = vec4(gl_TexCoord[0].st, 0.5, 1.0); }\n");
    quad(tc);
    capi_expect_error(GL_NO_ERROR, "frag_color_broadcast");
    save_attachment("frag_color_attachment0", 0);
    save_attachment("frag_color_attachment1", 1);
    save_attachment("frag_color_attachment2", 2);
    glUseProgram(0);
    glDeleteProgram(p);
    glDisablei(GL_BLEND, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteTextures(3, tex);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 0, 0, W, H, NULL);
    shadow();
    projective();
    bias();
    frag_coord_w();
    point_coord();
    frag_data();
    return capi_finish();
}
