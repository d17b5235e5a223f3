/* What a GLSL program's draws need and refuse, against Mesa:
 *  - two samplers of different types on one texture unit (GL 2.0 section 2.15.4,
 *    "Validation"): glValidateProgram fails, and glBegin, glDrawArrays and glDrawElements
 *    are GL_INVALID_OPERATION and draw nothing, until the units differ again (glRasterPos,
 *    which the spec names too, is not refused: Mesa does not check it)
 *    (a shadow and a plain sampler of one dimensionality do not conflict; the lookups must
 *    matter to the result, or Mesa's compiler drops them and their samplers are inactive);
 *  - generic attribute 0 as a constant: glVertexAttrib(0, ...) outside glBegin/glEnd sets
 *    its current value, and a vertex shader reading it draws from the other arrays alone
 *    (piglit gl-2.0-vertex-const-attr); inside glBegin/glEnd it is still glVertex;
 *  - glMaterial between glBegin and glEnd: gl_FrontMaterial keeps glBegin's materials for
 *    that draw, immediate and in a display list, and has the last ones after glEnd
 *    (piglit gl-2.0-shader-materials);
 *  - the integer abs, sign, min, max and clamp that Mesa compiles in GLSL 1.10 (1.30's
 *    built-ins; piglit's vs-loop-variable-iteration-limit-unroll calls min(int, int));
 *  - a sampler array indexed by a non-constant expression (a uniform, a loop counter):
 *    GLSL 1.10/1.20 allow only constant indices, Mesa compiles the others (piglit
 *    max-samplers), and so does tessera, choosing per fragment. (An index that differs
 *    between the fragments of a quad is not compared: llvmpipe does not choose per
 *    fragment, and later GLSL versions leave such an index undefined.) */
#include "common.h"

#define W 32
#define H 32

static int validate(GLuint p)
{
    GLint ok = -1;
    glValidateProgram(p);
    glGetProgramiv(p, GL_VALIDATE_STATUS, &ok);
    return ok;
}

static void clear(void)
{
    glClearColor(0.25f, 0.25f, 0.25f, 0.25f);
    glClear(GL_COLOR_BUFFER_BIT);
}

static int center_red(void)
{
    unsigned char px[4];
    glReadPixels(W / 2, H / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    return px[0];
}

static void sampler_conflicts(void)
{
    static const char *fs = "uniform sampler2D a; uniform sampler3D b; uniform sampler2DShadow c;\n"
                            "void main() { gl_FragColor = vec4(0.5, 0.0, 0.0, 0.5)\n"
                            "    + 0.001 * (texture2D(a, vec2(0.5)) + texture3D(b, vec3(0.5))\n"
                            "               + shadow2D(c, vec3(0.5))); }\n";
    GLuint p = capi_program_with("samplers", NULL, fs);
    capi_link_program("samplers", p);
    glUseProgram(p);
    GLint a = glGetUniformLocation(p, "a"), b = glGetUniformLocation(p, "b"), c = glGetUniformLocation(p, "c");
    static const struct {
        const char *name;
        int a, b, c;
    } cases[] = {
        {"all_distinct", 0, 1, 2},
        {"2d_3d_shared", 1, 1, 2},
        {"2d_shadow_shared", 3, 1, 3},
        {"3d_shadow_shared", 0, 2, 2},
        {"all_on_0", 0, 0, 0},
    };
    static const GLfloat quad[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    static const GLubyte indices[4] = {0, 1, 2, 3};
    glVertexPointer(2, GL_FLOAT, 0, quad);
    glEnableClientState(GL_VERTEX_ARRAY);
    char key[96];
    for (unsigned i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        glUniform1i(a, cases[i].a);
        glUniform1i(b, cases[i].b);
        glUniform1i(c, cases[i].c);
        capi_expect_error(GL_NO_ERROR, "uniforms set");
        snprintf(key, sizeof key, "conflict.%s.validate", cases[i].name);
        capi_value(key, "%d", validate(p));

        clear();
        glBegin(GL_QUADS);
        snprintf(key, sizeof key, "conflict.%s.begin_error", cases[i].name);
        capi_value(key, "0x%x", glGetError());
        for (int v = 0; v < 4; v++)
            glVertex2fv(quad[v]);
        glEnd();
        snprintf(key, sizeof key, "conflict.%s.end_error", cases[i].name);
        capi_value(key, "0x%x", glGetError());
        snprintf(key, sizeof key, "conflict.%s.begin_drew", cases[i].name);
        capi_value(key, "%d", center_red());

        clear();
        glDrawArrays(GL_QUADS, 0, 4);
        snprintf(key, sizeof key, "conflict.%s.draw_arrays_error", cases[i].name);
        capi_value(key, "0x%x", glGetError());
        snprintf(key, sizeof key, "conflict.%s.draw_arrays_drew", cases[i].name);
        capi_value(key, "%d", center_red());

        clear();
        glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, indices);
        snprintf(key, sizeof key, "conflict.%s.draw_elements_error", cases[i].name);
        capi_value(key, "0x%x", glGetError());
        snprintf(key, sizeof key, "conflict.%s.draw_elements_drew", cases[i].name);
        capi_value(key, "%d", center_red());

        /* (The info log is not compared: Mesa keeps a failed validation's log after a
         * later one succeeds.) */
        glRasterPos2f(0.5f, 0.5f);
        snprintf(key, sizeof key, "conflict.%s.raster_pos_error", cases[i].name);
        capi_value(key, "0x%x", glGetError());
    }
    /* The rule must be able to fail: the first case is valid, the second is not. */
    glUniform1i(a, 1);
    glUniform1i(b, 1);
    capi_check(!validate(p), "a 2D and a 3D sampler on one unit do not validate");
    glDrawArrays(GL_QUADS, 0, 4);
    capi_expect_error(GL_INVALID_OPERATION, "glDrawArrays with conflicting samplers");
    glUniform1i(b, 2);
    capi_check(validate(p), "distinct units validate");
    glDrawArrays(GL_QUADS, 0, 4);
    capi_expect_error(GL_NO_ERROR, "glDrawArrays with distinct units");
    glDisableClientState(GL_VERTEX_ARRAY);
    glUseProgram(0);
    glDeleteProgram(p);
}

static void constant_attribute_0(void)
{
    static const char *vs = "attribute vec2 vertex; attribute vec4 attr; varying vec4 color;\n"
                            "void main() { gl_Position = vec4(vertex, 0.0, 1.0); color = attr; }\n";
    static const char *fs = "varying vec4 color; void main() { gl_FragColor = color; }\n";
    static const GLfloat quad[4][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    GLuint p = capi_program_with("attr0", vs, fs);
    glBindAttribLocation(p, 0, "attr");
    glBindAttribLocation(p, 1, "vertex");
    capi_link_program("attr0", p);
    glUseProgram(p);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 0, quad);
    glEnableVertexAttribArray(1);
    static const GLfloat colors[4][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    clear();
    /* One quadrant per glVertexAttrib{1,2,3,4}fv(0): the missing components are 0, 0, 1. */
    for (int q = 0; q < 4; q++) {
        glViewport((q & 1) * W / 2, (q >> 1) * H / 2, W / 2, H / 2);
        switch (q) {
        case 0: glVertexAttrib1fv(0, colors[q]); break;
        case 1: glVertexAttrib2fv(0, colors[q]); break;
        case 2: glVertexAttrib3fv(0, colors[q]); break;
        default: glVertexAttrib4fv(0, colors[q]); break;
        }
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    glViewport(0, 0, W, H);
    capi_expect_error(GL_NO_ERROR, "draws with a constant attribute 0");
    unsigned char px[4];
    glReadPixels(W / 4, H / 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_check(px[0] == 255 && px[1] == 0 && px[2] == 0, "attribute 0 = (1, 0, 0, 1) draws red: (%d, %d, %d)", px[0],
               px[1], px[2]);
    capi_save_framebuffer("constant_attribute_0", W, H);

    /* Element draws and glDrawRangeElements alike; with no array enabled at all every
     * vertex is the same point (nothing covers a pixel). */
    static const GLushort strip[4] = {0, 1, 2, 3};
    clear();
    glVertexAttrib4f(0, 0.0f, 0.5f, 1.0f, 1.0f);
    glDrawElements(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_SHORT, strip);
    capi_save_framebuffer("constant_attribute_0_elements", W, H);
    glDisableVertexAttribArray(1);
    clear();
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    capi_expect_error(GL_NO_ERROR, "a draw with no array");
    capi_save_framebuffer("constant_attribute_0_no_arrays", W, H);

    /* Inside glBegin/glEnd, attribute 0 is the vertex. */
    clear();
    glBegin(GL_TRIANGLE_STRIP);
    for (int v = 0; v < 4; v++) {
        glVertexAttrib2fv(1, quad[v]);
        glVertexAttrib4f(0, 1.0f, 1.0f, 0.0f, 1.0f);
    }
    glEnd();
    capi_expect_error(GL_NO_ERROR, "glBegin/glEnd with attribute 0");
    capi_save_framebuffer("attribute_0_in_begin_end", W, H);

    /* Without a shader, only the vertex array or array 0 draws. */
    glUseProgram(0);
    glEnableVertexAttribArray(1);
    clear();
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    capi_value("fixed_function.array_1_only_drew", "%d", center_red() != 64);
    glDisableVertexAttribArray(1);
    glDeleteProgram(p);
}

static void materials_in_begin_end(void)
{
    static const char *vs = "attribute vec4 generic1;\n"
                            "void main() { gl_FrontColor = gl_FrontMaterial.ambient + gl_FrontMaterial.diffuse\n"
                            "    + gl_FrontLightProduct[0].ambient + generic1; gl_Position = ftransform(); }\n";
    static const char *fs = "void main() { gl_FragColor = gl_Color; }\n";
    static const float red[] = {1, 0, 0, 1}, ambient[] = {0, 0.3f, 0.5f, 1}, diffuse[] = {0, 0.2f, 0.3f, 1};
    static const float generic1[] = {0.2f, 0.1f, -0.4f, 0};
    static const float pos[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    GLuint p = capi_program_with("materials", vs, fs);
    capi_link_program("materials", p);
    glUseProgram(p);
    GLint g1 = glGetAttribLocation(p, "generic1");
    /* The list first: after it Mesa 22 still has the materials of before its glBegin (its
     * list playback does not make the list's last glMaterial current), where tessera has
     * the last one, as GL 2.1 section 5.4 (a list's commands execute as if called) says;
     * so that value is checked on tessera only, and the immediate case comes last. */
    for (int list = 1; list >= 0; list--) {
        clear();
        if (list)
            glNewList(1, GL_COMPILE);
        glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
        glBegin(GL_TRIANGLE_FAN);
        for (int i = 0; i < 4; i++) {
            glMaterialfv(GL_FRONT, GL_AMBIENT, red);
            glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
            glVertexAttrib4fv(g1, generic1);
            glVertex2fv(pos[i]);
        }
        glEnd();
        if (list) {
            glEndList();
            glCallList(1);
            glDeleteLists(1, 1);
        }
        unsigned char px[4];
        glReadPixels(W / 2, H / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        /* ambient + diffuse + 0.2 ambient (light 0's ambient is black) + generic1. */
        capi_check(px[0] == 51 && px[1] >= 152 && px[1] <= 154 && px[2] == 102,
                   "%s: gl_FrontMaterial keeps glBegin's materials: (%d, %d, %d)", list ? "list" : "immediate", px[0],
                   px[1], px[2]);
        capi_save_framebuffer(list ? "materials_list" : "materials_immediate", W, H);
        GLfloat after[4];
        glGetMaterialfv(GL_FRONT, GL_AMBIENT, after);
        if (!list)
            capi_value("materials.immediate.ambient_after", "%g %g %g %g", after[0], after[1], after[2], after[3]);
        else if (capi_is_tessera())
            capi_check(after[0] == 1 && after[1] == 0 && after[2] == 0, "the list's last glMaterial is current");
    }
    /* After glEnd the last materials hold: a draw without glMaterial reads them. */
    clear();
    glBegin(GL_TRIANGLE_FAN);
    for (int i = 0; i < 4; i++)
        glVertex2fv(pos[i]);
    glEnd();
    capi_save_framebuffer("materials_after_end", W, H);
    glUseProgram(0);
    glDeleteProgram(p);
}

static void integer_builtins_110(void)
{
    static const char *fs = "uniform int u;\n"
                            "void main() { ivec2 v = max(ivec2(u, -u), 1);\n"
                            "  gl_FragColor = vec4(float(sign(u)) * 0.5 + 0.5, float(abs(u)) / 8.0,\n"
                            "                      float(clamp(u, -2, 2) + 2) / 4.0, float(min(v.x, v.y)) / 8.0); }\n";
    GLuint p = capi_program_with("integer_builtins", NULL, fs);
    capi_link_program("integer_builtins", p);
    glUseProgram(p);
    GLint u = glGetUniformLocation(p, "u");
    static const int values[] = {-5, 0, 3, 7};
    char key[64];
    for (unsigned i = 0; i < sizeof values / sizeof values[0]; i++) {
        glUniform1i(u, values[i]);
        clear();
        glRectf(-1, -1, 1, 1);
        unsigned char px[4];
        glReadPixels(W / 2, H / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        snprintf(key, sizeof key, "integer_builtins.u=%d", values[i]);
        capi_value(key, "%d %d %d %d", px[0], px[1], px[2], px[3]);
    }
    capi_expect_error(GL_NO_ERROR, "integer built-ins");
    glUseProgram(0);
    glDeleteProgram(p);
}

static void dynamic_sampler_indices(void)
{
    static const char *fs = "uniform sampler2D t[3]; uniform int i;\n"
                            "void main() {\n"
                            "  vec4 loop = vec4(0.0);\n"
                            "  for (int k = 0; k < 3; k++) if (k == i) loop = texture2D(t[k], vec2(0.5));\n"
                            "  gl_FragColor = 0.5 * texture2D(t[i], vec2(0.5)) + 0.5 * loop; }\n";
    GLuint p = capi_program_with("dynamic_samplers", NULL, fs);
    capi_link_program("dynamic_samplers", p);
    glUseProgram(p);
    static const GLubyte texels[3][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
    GLuint tex[3];
    glGenTextures(3, tex);
    char name[8];
    for (int k = 0; k < 3; k++) {
        glActiveTexture(GL_TEXTURE0 + k);
        glBindTexture(GL_TEXTURE_2D, tex[k]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels[k]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        /* Units in another order than the elements. */
        snprintf(name, sizeof name, "t[%d]", k);
        glUniform1i(glGetUniformLocation(p, name), 2 - k);
    }
    glActiveTexture(GL_TEXTURE0);
    GLint i = glGetUniformLocation(p, "i");
    for (int k = 0; k < 3; k++) {
        glUniform1i(i, k);
        clear();
        glRectf(-1, -1, 1, 1);
        unsigned char px[4];
        glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        /* Element k reads unit 2 - k, which holds texel 2 - k. */
        int want = 2 - k;
        capi_check(px[want] >= 190 || (want == 2 && px[2] >= 190), "t[%d] reads unit %d: (%d, %d, %d)", k, want, px[0],
                   px[1], px[2]);
        snprintf(name, sizeof name, "i=%d", k);
        capi_save_framebuffer(k == 0 ? "dynamic_samplers_0" : k == 1 ? "dynamic_samplers_1" : "dynamic_samplers_2", W,
                              H);
    }
    capi_expect_error(GL_NO_ERROR, "dynamic sampler indices");
    glUseProgram(0);
    glDeleteProgram(p);
    glDeleteTextures(3, tex);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    sampler_conflicts();
    constant_attribute_0();
    materials_in_begin_end();
    integer_builtins_110();
    dynamic_sampler_indices();
    capi_expect_error(GL_NO_ERROR, "at the end");
    return capi_finish();
}
