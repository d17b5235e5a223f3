/* GLSL fragment shaders in draws (GL 2.1 section 3.11) with fixed-function vertex
 * processing (programs without a vertex shader): small images drawn with a constant
 * colour; gl_Color smooth; uniforms of several types (vec4, mat2, int, bool, arrays); a
 * texture sampled on unit 1 through a sampler uniform (NEAREST and LINEAR, the unit's
 * enables off); discard in a checker pattern; a gl_FragCoord pattern; gl_FrontFacing with a
 * front and a back triangle; gl_FragDepth with a depth test; a loop with break and an
 * if/else; dFdx/dFdy; gl_TexCoord and the secondary colour and fog coordinate varyings;
 * glBitmap and glDrawPixels fragments (shaded too); and the alpha test after a shader.
 * Values are chosen as exact binary fractions where possible, so that the images match
 * bit for bit. */
#include "common.h"

#define W 64
#define H 64

static GLuint program(const char *key, const char *fs)
{
    GLuint p = capi_program(key, NULL, fs);
    glUseProgram(p);
    capi_expect_error(GL_NO_ERROR, key);
    return p;
}

/* A quad over the whole window, corners coloured red, green, blue, white (smooth). */
static void quad(void)
{
    glBegin(GL_QUADS);
    glColor4f(1, 0, 0, 1);
    glTexCoord2f(0, 0);
    glVertex2f(-1, -1);
    glColor4f(0, 1, 0, 1);
    glTexCoord2f(1, 0);
    glVertex2f(1, -1);
    glColor4f(0, 0, 1, 1);
    glTexCoord2f(1, 1);
    glVertex2f(1, 1);
    glColor4f(1, 1, 1, 0);
    glTexCoord2f(0, 1);
    glVertex2f(-1, 1);
    glEnd();
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
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static void constant(void)
{
    clear();
    GLuint p = program("constant", "void main() { gl_FragColor = vec4(0.5, 0.25, 0.75, 1.0); }");
    quad();
    finish("constant", p);
}

static void color(void)
{
    clear();
    GLuint p = program("color", "void main() { gl_FragColor = gl_Color.bgra; }");
    quad();
    finish("color", p);
}

static void uniforms(void)
{
    clear();
    GLuint p = program("uniforms",
                       "uniform vec4 tint; uniform mat2 m; uniform int k; uniform bool flip;\n"
                       "uniform float weights[3];\n"
                       "void main() {\n"
                       "  vec2 v = m * vec2(0.5, 0.25);\n"
                       "  float w = weights[0] + weights[1] + weights[2];\n"
                       "  vec4 c = vec4(v, float(k) / 4.0, w) * tint;\n"
                       "  gl_FragColor = flip ? c.abgr : c;\n"
                       "}\n");
    glUniform4f(glGetUniformLocation(p, "tint"), 1.0f, 0.5f, 1.0f, 1.0f);
    GLfloat m[4] = {1.0f, 0.5f, 0.0f, 1.0f};
    glUniformMatrix2fv(glGetUniformLocation(p, "m"), 1, GL_FALSE, m);
    glUniform1i(glGetUniformLocation(p, "k"), 3);
    glUniform1i(glGetUniformLocation(p, "flip"), 0);
    GLfloat weights[3] = {0.125f, 0.25f, 0.5f};
    glUniform1fv(glGetUniformLocation(p, "weights"), 3, weights);
    glViewport(0, 0, W / 2, H);
    quad();
    glUniform1i(glGetUniformLocation(p, "flip"), 1);
    glViewport(W / 2, 0, W / 2, H);
    quad();
    glViewport(0, 0, W, H);
    finish("uniforms", p);
}

/* An 8x8 RGBA texture on unit 1 (texturing disabled there: shaders ignore the enables). */
static GLuint texture(void)
{
    GLubyte texels[8 * 8 * 4];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            GLubyte *t = texels + 4 * (y * 8 + x);
            t[0] = (GLubyte)(x * 32);
            t[1] = (GLubyte)(y * 32);
            t[2] = (GLubyte)(((x + y) & 1) * 255);
            t[3] = 255;
        }
    GLuint tex;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glActiveTexture(GL_TEXTURE0);
    return tex;
}

static void sampling(GLuint tex)
{
    static const char *fs = "uniform sampler2D s;\n"
                            "void main() { gl_FragColor = texture2D(s, gl_TexCoord[0].st * 1.25 - 0.125); }\n";
    for (int linear = 0; linear < 2; linear++) {
        const char *name = linear ? "texture_linear" : "texture_nearest";
        clear();
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, tex);
        GLint filter = linear ? GL_LINEAR : GL_NEAREST;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        glActiveTexture(GL_TEXTURE0);
        GLuint p = program(name, fs);
        glUniform1i(glGetUniformLocation(p, "s"), 1);
        quad();
        finish(name, p);
    }
    /* A sampler on a unit without a complete texture reads (0, 0, 0, 1). */
    clear();
    GLuint p = program("texture_incomplete", "uniform sampler2D s;\n"
                                             "void main() { gl_FragColor = texture2D(s, vec2(0.5)) + vec4(0.25); }\n");
    glUniform1i(glGetUniformLocation(p, "s"), 2);
    quad();
    finish("texture_incomplete", p);
}

static void discard(void)
{
    clear();
    GLuint p = program("discard", "void main() {\n"
                                  "  vec2 c = floor(gl_FragCoord.xy / 8.0);\n"
                                  "  if (mod(c.x + c.y, 2.0) == 1.0) discard;\n"
                                  "  gl_FragColor = gl_Color;\n"
                                  "}\n");
    quad();
    finish("discard", p);
}

static void frag_coord(void)
{
    clear();
    GLuint p = program("frag_coord", "void main() {\n"
                                     "  gl_FragColor = vec4(fract(gl_FragCoord.xy / 16.0), gl_FragCoord.z, 1.0);\n"
                                     "}\n");
    glBegin(GL_TRIANGLES);
    glVertex3f(-1, -1, -0.5f);
    glVertex3f(1, -1, 0.5f);
    glVertex3f(-1, 1, 0.0f);
    glEnd();
    finish("frag_coord", p);
}

static void front_facing(void)
{
    clear();
    GLuint p = program("front_facing", "void main() {\n"
                                       "  gl_FragColor = gl_FrontFacing ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);\n"
                                       "}\n");
    glBegin(GL_TRIANGLES);
    /* Counter-clockwise: front. */
    glVertex2f(-1, -1);
    glVertex2f(0, -1);
    glVertex2f(-1, 1);
    /* Clockwise: back. */
    glVertex2f(0, -1);
    glVertex2f(0, 1);
    glVertex2f(1, -1);
    glEnd();
    finish("front_facing", p);
}

static void frag_depth(void)
{
    clear();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    /* A plain quad at depth 0.5 (window), then a shader quad at depth 0 whose fragments
     * take a depth ramp over x: only its left part (depth below 0.5) passes. */
    glColor4f(0, 0, 1, 1);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
    GLuint p = program("frag_depth", "void main() {\n"
                                     "  gl_FragDepth = gl_FragCoord.x / 64.0;\n"
                                     "  gl_FragColor = vec4(1.0, 1.0, 0.0, 1.0);\n"
                                     "}\n");
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, -1);
    glVertex3f(1, -1, -1);
    glVertex3f(1, 1, -1);
    glVertex3f(-1, 1, -1);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    finish("frag_depth", p);
    /* The depth buffer the shader wrote. */
    static GLuint depth[W * H];
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    for (int i = 0; i < W * H; i++)
        depth[i] >>= 16;
    static GLushort depth16[W * H];
    for (int i = 0; i < W * H; i++)
        depth16[i] = (GLushort)depth[i];
    capi_save_image("frag_depth_buffer", W, H, 1, CAPI_U16, depth16);
}

static void control_flow(void)
{
    clear();
    GLuint p = program("control_flow", "void main() {\n"
                                       "  int n = int(gl_FragCoord.x) / 8;\n"
                                       "  float sum = 0.0;\n"
                                       "  for (int i = 0; i < 16; i++) {\n"
                                       "    if (i >= n) break;\n"
                                       "    sum += 0.125;\n"
                                       "  }\n"
                                       "  vec4 c;\n"
                                       "  if (gl_FragCoord.y < 32.0) c = vec4(sum, 0.0, 0.0, 1.0);\n"
                                       "  else c = vec4(0.0, sum, 0.5, 1.0);\n"
                                       "  gl_FragColor = c;\n"
                                       "}\n");
    quad();
    finish("control_flow", p);
}

static void derivatives(void)
{
    clear();
    GLuint p = program("derivatives", "void main() {\n"
                                      "  vec2 t = gl_TexCoord[0].st * 64.0;\n"
                                      "  float q = t.x * t.x / 64.0;\n"
                                      "  gl_FragColor = vec4(dFdx(t.x) / 2.0, dFdy(t.y) / 2.0, dFdx(q) / 8.0, 1.0);\n"
                                      "}\n");
    quad();
    finish("derivatives", p);
}

static void varyings(void)
{
    clear();
    GLuint p = program("varyings", "void main() {\n"
                                   "  gl_FragColor = vec4(gl_SecondaryColor.rg, gl_TexCoord[2].x, gl_FogFragCoord);\n"
                                   "}\n");
    /* The fog coordinates as given (fog itself stays off: the shader reads them). */
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glBegin(GL_TRIANGLES);
    glSecondaryColor3f(1, 0, 0);
    glMultiTexCoord2f(GL_TEXTURE2, 0, 0);
    glFogCoordf(0.25f);
    glVertex2f(-1, -1);
    glSecondaryColor3f(0, 1, 0);
    glMultiTexCoord2f(GL_TEXTURE2, 1, 0);
    glFogCoordf(0.5f);
    glVertex2f(1, -1);
    glSecondaryColor3f(0, 0, 1);
    glMultiTexCoord2f(GL_TEXTURE2, 0.5f, 0);
    glFogCoordf(1.0f);
    glVertex2f(-1, 1);
    glEnd();
    glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    finish("varyings", p);
}

static void pixels(void)
{
    clear();
    GLuint p = program("pixels", "void main() { gl_FragColor = vec4(gl_Color.r, 0.5, fract(gl_FragCoord.x / 8.0), 1.0); }");
    glColor4f(0.75f, 0, 0, 1);
    glRasterPos2f(-0.5f, -0.5f);
    static GLubyte bits[16 * 2];
    for (int i = 0; i < 32; i++)
        bits[i] = (GLubyte)(i & 1 ? 0xf0 : 0x3c);
    glBitmap(16, 16, 0, 0, 0, 0, bits);
    static GLubyte image[8 * 8 * 4];
    for (int i = 0; i < 8 * 8 * 4; i++)
        image[i] = (GLubyte)(i * 4);
    glRasterPos2f(0.25f, 0.25f);
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, image);
    finish("pixels", p);
}

static void alpha_test(void)
{
    clear();
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    GLuint p = program("alpha_test", "void main() { gl_FragColor = vec4(gl_Color.rgb, gl_FragCoord.x / 64.0); }");
    quad();
    glDisable(GL_ALPHA_TEST);
    finish("alpha_test", p);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 0, 0, W, H, NULL);
    GLuint tex = texture();
    constant();
    color();
    uniforms();
    sampling(tex);
    discard();
    frag_coord();
    front_facing();
    frag_depth();
    control_flow();
    derivatives();
    varyings();
    pixels();
    alpha_test();
    return capi_finish();
}
