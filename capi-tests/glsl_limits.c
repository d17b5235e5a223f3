/* The GL 2.0/2.1 implementation limits of the programmable pipeline through all four glGet
 * forms (GL_MAX_VARYING_FLOATS, GL_MAX_VERTEX_ATTRIBS, the uniform budgets, the texture image
 * units, GL_MAX_TEXTURE_COORDS, GL_MAX_DRAW_BUFFERS, and the fixed-function limits GLSL
 * exposes as constants) and GL_CURRENT_PROGRAM before, during and after glUseProgram. Where
 * tessera's limits are knowingly smaller than llvmpipe's, the manifest frees the value. That
 * the shaders' built-in constants (gl_MaxVaryingFloats, ...) equal these is checked by
 * glsl_builtin_state, which draws. */
#include "common.h"

struct limit {
    const char *name;
    GLenum pname;
};

static const struct limit LIMITS[] = {
    {"MAX_VARYING_FLOATS", GL_MAX_VARYING_FLOATS},
    {"MAX_VERTEX_ATTRIBS", GL_MAX_VERTEX_ATTRIBS},
    {"MAX_VERTEX_UNIFORM_COMPONENTS", GL_MAX_VERTEX_UNIFORM_COMPONENTS},
    {"MAX_FRAGMENT_UNIFORM_COMPONENTS", GL_MAX_FRAGMENT_UNIFORM_COMPONENTS},
    {"MAX_VERTEX_TEXTURE_IMAGE_UNITS", GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS},
    {"MAX_COMBINED_TEXTURE_IMAGE_UNITS", GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS},
    {"MAX_TEXTURE_IMAGE_UNITS", GL_MAX_TEXTURE_IMAGE_UNITS},
    {"MAX_TEXTURE_COORDS", GL_MAX_TEXTURE_COORDS},
    {"MAX_DRAW_BUFFERS", GL_MAX_DRAW_BUFFERS},
    {"MAX_TEXTURE_UNITS", GL_MAX_TEXTURE_UNITS},
    {"MAX_LIGHTS", GL_MAX_LIGHTS},
    {"MAX_CLIP_PLANES", GL_MAX_CLIP_PLANES},
};
#define LIMIT_COUNT ((int)(sizeof LIMITS / sizeof LIMITS[0]))

static GLuint build(const char *vs, const char *fs)
{
    return capi_program("limits", vs, fs);
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 4, 4, &buffer);

    for (int i = 0; i < LIMIT_COUNT; i++) {
        capi_value_query("limit", LIMITS[i].name, LIMITS[i].pname, 1);
        GLint n = -1;
        GLfloat f = -1;
        glGetIntegerv(LIMITS[i].pname, &n);
        glGetFloatv(LIMITS[i].pname, &f);
        capi_check(f == (GLfloat)n, "%s: glGetFloatv %g, glGetIntegerv %d", LIMITS[i].name, f, n);
    }
    capi_expect_error(GL_NO_ERROR, "limits");
    capi_value_query("program", "CURRENT_PROGRAM.none", GL_CURRENT_PROGRAM, 1);

    GLuint program = build("void main() { gl_Position = gl_Vertex; }", "void main() { gl_FragColor = vec4(1.0); }");
    glUseProgram(program);
    GLint current[4] = {0};
    GLfloat current_f = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, current);
    glGetFloatv(GL_CURRENT_PROGRAM, &current_f);
    capi_check((GLuint)current[0] == program && current_f == (GLfloat)program, "GL_CURRENT_PROGRAM %d, program %u",
               current[0], program);
    capi_value("program.CURRENT_PROGRAM.bound", "%d", (GLuint)current[0] == program);
    glUseProgram(0);
    /* A deleted program stays current until it is replaced. */
    glUseProgram(program);
    glDeleteProgram(program);
    glGetIntegerv(GL_CURRENT_PROGRAM, current);
    capi_value("program.CURRENT_PROGRAM.deleted_in_use", "%d", (GLuint)current[0] == program);
    glUseProgram(0);
    capi_value_query("program", "CURRENT_PROGRAM.unbound", GL_CURRENT_PROGRAM, 1);
    capi_expect_error(GL_NO_ERROR, "programs");

    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
