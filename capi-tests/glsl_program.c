/* GLSL programs with both stages (GL 2.1 section 2.15 and 3.11): varyings between a vertex
 * and a fragment shader, packed into more slots than fixed function has texture units (a
 * float, a vec2, a vec3, a mat2, a vec4 array of 6, gl_TexCoord[1] and gl_FrontColor);
 * generic attributes from arrays (floats and normalized unsigned bytes) beside
 * glVertexPointer; ftransform() and the built-in matrices against a fixed-function draw of
 * the same triangles; a uniform struct array; a sampler reading the texture of unit 2 at
 * coordinates computed in the vertex shader; and two programs used in turn in one frame.
 * Values are exact binary fractions where possible so that the images match bit for bit. */
#include "common.h"

#define W 64
#define H 64

static GLuint program(const char *key, const char *vs, const char *fs)
{
    GLuint p = capi_program_with(key, vs, fs);
    glBindAttribLocation(p, 3, "weights");
    glBindAttribLocation(p, 5, "tint");
    capi_link_program(key, p);
    capi_expect_error(GL_NO_ERROR, key);
    return p;
}

static void clear(void)
{
    glClearColor(0.25f, 0.25f, 0.25f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* Six vertices: two triangles over most of the window. */
static const GLfloat positions[] = {-0.875f, -0.875f, 0.875f, -0.875f, 0.875f, 0.875f,
                                    -0.875f, -0.875f, 0.875f, 0.875f,  -0.875f, 0.875f};
static const GLfloat weights[] = {0, 0.25f, 0.5f, 1, 0.75f, 0.125f, 0.375f, 0.625f, 1, 0.5f, 0.25f, 0.875f};
static const GLubyte tints[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255,
                                255, 255, 0, 255, 0, 255, 255, 255, 255, 0, 255, 255};

static void arrays(void)
{
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, positions);
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, weights);
    glEnableVertexAttribArray(5);
    glVertexAttribPointer(5, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, tints);
}

static const char *many_varyings_vs =
    "attribute vec2 weights;\n"
    "attribute vec4 tint;\n"
    "varying float a;\n"
    "varying vec2 b;\n"
    "varying vec3 c;\n"
    "varying mat2 m;\n"
    "varying vec4 v[6];\n"
    "void main() {\n"
    "    gl_Position = ftransform();\n"
    "    a = weights.x;\n"
    "    b = weights.yx;\n"
    "    c = tint.rgb;\n"
    "    m = mat2(weights, weights.yx * 0.5);\n"
    "    for (int i = 0; i < 6; i++) v[i] = vec4(float(i) * 0.125, weights, tint.a * 0.5);\n"
    "    gl_TexCoord[1] = vec4(weights.yx, 0.5, 1.0);\n"
    "    gl_FrontColor = tint;\n"
    "}\n";

static const char *many_varyings_fs =
    "varying float a;\n"
    "varying vec2 b;\n"
    "varying vec3 c;\n"
    "varying mat2 m;\n"
    "varying vec4 v[6];\n"
    "uniform int pick;\n"
    "void main() {\n"
    "    vec4 s = vec4(0.0);\n"
    "    for (int i = 0; i < 6; i++) s += v[i] * 0.125;\n"
    "    if (pick == 0) gl_FragColor = vec4(a, b, 1.0);\n"
    "    else if (pick == 1) gl_FragColor = vec4(c, 1.0);\n"
    "    else if (pick == 2) gl_FragColor = vec4(m[0], m[1].y, 1.0);\n"
    "    else if (pick == 3) gl_FragColor = s;\n"
    "    else if (pick == 4) gl_FragColor = gl_TexCoord[1];\n"
    "    else gl_FragColor = gl_Color * v[5].w * 2.0;\n"
    "}\n";

static void many_varyings(void)
{
    GLuint p = program("varyings", many_varyings_vs, many_varyings_fs);
    glUseProgram(p);
    arrays();
    static const char *names[] = {"float_vec2", "vec3", "mat2", "array", "tex_coord", "color"};
    for (int pick = 0; pick < 6; pick++) {
        clear();
        glUniform1i(glGetUniformLocation(p, "pick"), pick);
        glDrawArrays(GL_TRIANGLES, 0, 6);
        capi_expect_error(GL_NO_ERROR, names[pick]);
        char name[32];
        snprintf(name, sizeof name, "varyings_%s", names[pick]);
        capi_save_framebuffer(name, W, H);
    }
    glDisableVertexAttribArray(3);
    glDisableVertexAttribArray(5);
    glUseProgram(0);
    glDeleteProgram(p);
}

/* ftransform() and gl_ModelViewProjectionMatrix * gl_Vertex place vertices where fixed
 * function does (GL's invariance rule for ftransform): three draws of one rotated,
 * perspective triangle set, red by fixed function, then green by each program with
 * GL_EQUAL depth testing: only pixels whose depth matches exactly turn green. */
static void invariance(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.1f, -0.2f, -3);
    glRotatef(30, 0.3f, 1, 0.2f);
    const char *fs = "void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }";
    const char *vs[2] = {"void main() { gl_Position = ftransform(); }",
                         "void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }"};
    const char *names[2] = {"ftransform", "mvp_matrix"};
    glEnable(GL_DEPTH_TEST);
    for (int k = 0; k < 2; k++) {
        clear();
        glDepthFunc(GL_LESS);
        glColor3f(1, 0, 0);
        glDrawArrays(GL_TRIANGLES, 0, 6);
        GLuint p = program(names[k], vs[k], fs);
        glUseProgram(p);
        glDepthFunc(GL_EQUAL);
        glDrawArrays(GL_TRIANGLES, 0, 6);
        capi_expect_error(GL_NO_ERROR, names[k]);
        capi_save_framebuffer(names[k], W, H);
        glUseProgram(0);
        glDeleteProgram(p);
    }
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static GLuint texture_on_unit_2(void)
{
    GLubyte texels[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        texels[4 * i + 0] = (GLubyte)(i * 4);
        texels[4 * i + 1] = (GLubyte)(255 - i * 4);
        texels[4 * i + 2] = (GLubyte)((i & 1) * 255);
        texels[4 * i + 3] = 255;
    }
    GLuint tex;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glActiveTexture(GL_TEXTURE0);
    return tex;
}

/* A uniform struct array chooses a scale and offset per triangle; the sampler reads unit 2
 * at coordinates the vertex shader computes; a second program draws over part of it. */
static void structs_and_samplers(void)
{
    GLuint tex = texture_on_unit_2();
    const char *vs = "struct Place { vec2 scale; vec2 offset; };\n"
                     "uniform Place places[2];\n"
                     "attribute vec2 weights;\n"
                     "varying vec2 uv;\n"
                     "void main() {\n"
                     "    Place p = places[gl_Vertex.x > 0.0 ? 1 : 0];\n"
                     "    uv = weights * p.scale + p.offset;\n"
                     "    gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);\n"
                     "}\n";
    const char *fs = "uniform sampler2D image;\n"
                     "varying vec2 uv;\n"
                     "void main() { gl_FragColor = texture2D(image, uv); }\n";
    GLuint p = program("structs", vs, fs);
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, "image"), 2);
    glUniform2f(glGetUniformLocation(p, "places[0].scale"), 1, 0.5f);
    glUniform2f(glGetUniformLocation(p, "places[0].offset"), 0, 0.25f);
    glUniform2f(glGetUniformLocation(p, "places[1].scale"), 0.5f, 1);
    glUniform2f(glGetUniformLocation(p, "places[1].offset"), 0.5f, 0);
    arrays();
    clear();
    glDrawArrays(GL_TRIANGLES, 0, 6);
    const char *vs2 = "void main() { gl_Position = vec4(gl_Vertex.xy * 0.5, 0.0, 1.0); }";
    const char *fs2 = "uniform vec4 c; void main() { gl_FragColor = c; }";
    GLuint p2 = program("second", vs2, fs2);
    glUseProgram(p2);
    glUniform4f(glGetUniformLocation(p2, "c"), 0.5f, 0.75f, 0.25f, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    capi_expect_error(GL_NO_ERROR, "structs");
    capi_save_framebuffer("structs_samplers", W, H);
    glDisableVertexAttribArray(3);
    glDisableVertexAttribArray(5);
    glUseProgram(0);
    glDeleteProgram(p);
    glDeleteProgram(p2);
    glDeleteTextures(1, &tex);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 0, 0, W, H, NULL);
    many_varyings();
    invariance();
    structs_and_samplers();
    return capi_finish();
}
