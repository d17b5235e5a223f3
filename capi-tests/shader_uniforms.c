/* GLSL program interface (GL 2.0/2.1) without drawing: linking several shaders per stage
 * and the link errors' first lines (missing or doubled main, unresolved and recursive
 * functions, globals and varyings of two types, a varying not written, the attribute,
 * uniform and varying limits); the active uniform and attribute lists (names as GL
 * reflection gives them, sizes, types, max lengths, built-in state), glGetActiveUniform /
 * glGetActiveAttrib at every buffer size and with NULL outputs; glGetUniformLocation and
 * glGetAttribLocation for well and badly formed names; glBindAttribLocation at the next
 * link; glUniform* / glUniformMatrix* round trips through glGetUniform{f,i}v for every type
 * (bools from floats and ints, transposed and non-square matrices, array elements and
 * counts, samplers); values reset by a link (1.20 initializers); uniforms compiled into a
 * display list; and every error Mesa gives.
 *
 * Entries are printed sorted by name: Mesa orders its built-in state entries by its own
 * tables, tessera lists each stage's built-ins then its own uniforms in declaration order.
 * Locations, which follow the declaration order in both, are printed as they are. */
#include "common.h"
#include <stdlib.h>
#include <string.h>

static GLuint shader(GLenum type, const char *source)
{
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, NULL);
    glCompileShader(s);
    return s;
}

/* The first line of a log, at most 60 characters. */
static const char *first_line(const char *log)
{
    static char line[64];
    size_t n = strcspn(log, "\n");
    if (n > 60)
        n = 60;
    memcpy(line, log, n);
    line[n] = 0;
    return line;
}

/* Links up to two vertex and two fragment shaders and prints the status and log's first line. */
static GLuint link(const char *key, const char *v1, const char *v2, const char *f1, const char *f2)
{
    GLuint program = glCreateProgram();
    const char *sources[4] = {v1, v2, f1, f2};
    for (int i = 0; i < 4; i++) {
        if (sources[i]) {
            GLuint s = shader(i < 2 ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER, sources[i]);
            glAttachShader(program, s);
            glDeleteShader(s);
        }
    }
    glLinkProgram(program);
    GLint linked = -1;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    char log[4096] = "";
    glGetProgramInfoLog(program, sizeof log, NULL, log);
    capi_value(key, "linked=%d log=%s", linked, first_line(log));
    capi_expect_error(GL_NO_ERROR, key);
    return program;
}

#define VS(body) "void main() { gl_Position = ftransform();" body " }"
#define FS(body) "void main() { gl_FragColor = vec4(1.0);" body " }"

static void links(void)
{
    glDeleteProgram(link("link.no_vertex_main", "void f() {}", NULL, FS(""), NULL));
    glDeleteProgram(link("link.no_fragment_main", VS(""), NULL, "void f() {}", NULL));
    glDeleteProgram(link("link.two_mains", VS(""), VS(""), NULL, NULL));
    glDeleteProgram(link("link.unresolved", "void f(); void main() { f(); gl_Position = vec4(0.0); }", NULL, NULL, NULL));
    glDeleteProgram(link("link.resolved", "void f(); void main() { f(); gl_Position = vec4(0.0); }",
                         "void f() { gl_PointSize = 1.0; }", NULL, NULL));
    /* An unresolved prototype that nothing reachable from main calls is no error. */
    glDeleteProgram(link("link.unreachable", "void f(); void g() { f(); }" VS(""), NULL, NULL, NULL));
    glDeleteProgram(link("link.twice_defined", "void f(); void f() {}" VS("f();"), "void f() {}", NULL, NULL));
    glDeleteProgram(link("link.uniform_types", "uniform float u; void f(); void main() { f(); gl_Position = vec4(u); }",
                         "uniform vec2 u; void f() { gl_PointSize = u.x; }", NULL, NULL));
    glDeleteProgram(link("link.uniform_types_stages", "uniform float u;" VS("gl_PointSize = u;"), NULL,
                         "uniform vec2 u;" FS("gl_FragColor.xy = u;"), NULL));
    glDeleteProgram(link("link.global_types", "float g; void f(); void main() { f(); gl_Position = vec4(g); }",
                         "int g; void f() { gl_PointSize = float(g); }", NULL, NULL));
    glDeleteProgram(link("link.varying_types", "varying vec3 c;" VS("c = vec3(1.0);"), NULL,
                         "varying vec4 c;" FS("gl_FragColor = c;"), NULL));
    glDeleteProgram(link("link.varying_missing", VS(""), NULL, "varying float c;" FS("gl_FragColor = vec4(c);"), NULL));
    glDeleteProgram(link("link.varying_unwritten", "varying vec2 c;" VS(""), NULL,
                         "varying vec2 c;" FS("gl_FragColor.xy = c;"), NULL));
    glDeleteProgram(link("link.varying_unused", VS(""), NULL, "varying vec4 c;" FS(""), NULL));
    glDeleteProgram(link("link.varying_split", "varying vec4 c; void f();" VS("f();"), "varying vec4 c; void f() { c = vec4(1.0); }",
                         "varying vec4 c; vec4 g();" FS("gl_FragColor = g();"), "varying vec4 c; vec4 g() { return c; }"));
    /* Recursion across two shaders of a stage is found by the linker (within one shader
     * Mesa finds it at compile time and tessera at link time: not tested here). Mesa names
     * the functions of the cycle in an order of its own, so only the log's start is
     * compared. */
    /* Within one shader, recursion is a compile error (the cycle's functions named in an
     * order of Mesa's own: only the first words and the reason are compared). */
    GLuint alone = shader(GL_VERTEX_SHADER, "float f(float x) { return f(x); }" VS("gl_PointSize = f(1.0);"));
    GLint compiled = -1;
    glGetShaderiv(alone, GL_COMPILE_STATUS, &compiled);
    char compile_log[256] = "";
    glGetShaderInfoLog(alone, sizeof compile_log, NULL, compile_log);
    capi_value("compile.recursion", "compiled=%d log=%s", compiled, first_line(compile_log));
    glDeleteShader(alone);
    GLuint recursive = glCreateProgram();
    glAttachShader(recursive, shader(GL_VERTEX_SHADER, "void g(); void f() { g(); }" VS("f();")));
    glAttachShader(recursive, shader(GL_VERTEX_SHADER, "void f(); void g() { f(); }"));
    glLinkProgram(recursive);
    char log[256] = "";
    glGetProgramInfoLog(recursive, sizeof log, NULL, log);
    capi_value("link.recursion", "%.22s... %s", log, strstr(log, "' has static recursion.\n") ? "has static recursion" : "?");
    glDeleteProgram(recursive);
    glDeleteProgram(link("link.fragment_only", NULL, NULL, FS("gl_FragColor = gl_Color;"), NULL));
    glDeleteProgram(link("link.vertex_only", VS("gl_FrontColor = gl_Color;"), NULL, NULL, NULL));
    glDeleteProgram(link("link.nothing", NULL, NULL, NULL, NULL));
    glDeleteProgram(link("link.uncompiled", VS(""), NULL, FS("gl_FragColor = undeclared;"), NULL));
    glDeleteProgram(link("link.attributes_16",
                         "attribute vec4 a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14;"
                         "void main() { gl_Position = gl_Vertex + a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7 + a8 + a9 + a10"
                         " + a11 + a12 + a13 + a14; }",
                         NULL, NULL, NULL));
    glDeleteProgram(link("link.attributes_17",
                         "attribute vec4 a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15;"
                         "void main() { gl_Position = gl_Vertex + a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7 + a8 + a9 + a10"
                         " + a11 + a12 + a13 + a14 + a15; }",
                         NULL, NULL, NULL));
    glDeleteProgram(link("link.uniforms_4096", "uniform vec4 u[4096];" VS("gl_Position = u[int(gl_Vertex.x)];"), NULL, NULL, NULL));
    glDeleteProgram(link("link.uniforms_5000", "uniform vec4 u[5000];" VS("gl_Position = u[int(gl_Vertex.x)];"), NULL, NULL, NULL));
    /* The varying limit: vec4 varyings filling GL_MAX_VARYING_FLOATS link, one more does not
     * (Mesa's log then starts with a packing message, not tessera's wording). The limits
     * differ (Mesa 128, tessera 64; capi glsl_limits prints them), the outcomes must not. */
    GLint max_floats = 0;
    glGetIntegerv(GL_MAX_VARYING_FLOATS, &max_floats);
    for (int extra = 0; extra <= 1; extra++) {
        int n = max_floats / 4 + extra;
        char vs[256], fs[256];
        snprintf(vs, sizeof vs, "varying vec4 v[%d];" VS("for (int i = 0; i < %d; i++) v[i] = vec4(1.0);"), n, n);
        snprintf(fs, sizeof fs, "varying vec4 v[%d];" FS("for (int i = 0; i < %d; i++) gl_FragColor += v[i];"), n, n);
        GLuint program = glCreateProgram(), v = shader(GL_VERTEX_SHADER, vs), f = shader(GL_FRAGMENT_SHADER, fs);
        glAttachShader(program, v);
        glAttachShader(program, f);
        glDeleteShader(v);
        glDeleteShader(f);
        glLinkProgram(program);
        GLint linked = -1;
        glGetProgramiv(program, GL_LINK_STATUS, &linked);
        capi_value(extra ? "link.varyings_over_limit" : "link.varyings_at_limit", "linked=%d", linked);
        glDeleteProgram(program);
    }
}

static const char *reflect_vertex =
    "#version 120\n"
    "struct S { float a; vec3 b[2]; mat2 m; };\n"
    "uniform S s;\n"
    "uniform S sa[2];\n"
    "uniform float arr[5];\n"
    "uniform float dyn[3];\n"
    "uniform mat3 m3;\n"
    "uniform mat2x3 m23;\n"
    "uniform mat4x2 m42;\n"
    "uniform bool bb;\n"
    "uniform bvec2 bv;\n"
    "uniform ivec3 iv;\n"
    "uniform int i1;\n"
    "uniform float unused;\n"
    "uniform vec4 init = vec4(1.0, 2.0, 3.0, 4.0);\n"
    "uniform float shared;\n"
    "attribute vec4 pos;\n"
    "attribute vec3 nrm;\n"
    "attribute mat2 am;\n"
    "attribute float unused_attribute;\n"
    "attribute vec2 tc;\n"
    "attribute mat4 bound;\n"
    "void main()\n"
    "{\n"
    "    gl_Position = gl_ModelViewProjectionMatrix * pos + vec4(nrm, 1.0) + vec4(am[0], tc) + gl_Color\n"
    "        + gl_Normal.xxxx + gl_MultiTexCoord1 + bound[3]\n"
    "        + vec4(s.a + s.b[1].x + s.m[0][0] + sa[1].b[0].y + arr[2] + dyn[int(pos.x)] + m3[0][0] + m23[1][2]\n"
    "        + m42[3][1] + float(bb) + float(bv.y) + float(iv.z) + float(i1) + shared)\n"
    "        + init + gl_LightSource[1].diffuse + gl_FrontMaterial.ambient * gl_Fog.color;\n"
    "}\n";

/* The samplers are the fragment shader's: tessera's vertex shaders have no texture image
 * units (GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS 0), so a vertex shader that samples does not link. */
static const char *reflect_fragment =
    "uniform float fu;\n"
    "uniform float shared;\n"
    "uniform sampler2D tex;\n"
    "uniform samplerCube cube[2];\n"
    "void main()\n"
    "{\n"
    "    gl_FragColor = vec4(fu + shared + texture2D(tex, vec2(0.0)).x + textureCube(cube[1], vec3(0.0)).x)\n"
    "        * gl_FragCoord + gl_TextureEnvColor[0];\n"
    "}\n";

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Prints every active uniform (or attribute) sorted by name. */
static void entries(const char *key, GLuint program, int uniforms)
{
    GLint count = -1, longest = -1;
    glGetProgramiv(program, uniforms ? GL_ACTIVE_UNIFORMS : GL_ACTIVE_ATTRIBUTES, &count);
    glGetProgramiv(program, uniforms ? GL_ACTIVE_UNIFORM_MAX_LENGTH : GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &longest);
    capi_value(key, "count=%d max_length=%d", count, longest);
    char **lines = calloc(count > 0 ? count : 1, sizeof *lines);
    for (GLint i = 0; i < count; i++) {
        char name[128];
        GLsizei length = -1;
        GLint size = -1;
        GLenum type = 0;
        if (uniforms)
            glGetActiveUniform(program, i, sizeof name, &length, &size, &type, name);
        else
            glGetActiveAttrib(program, i, sizeof name, &length, &size, &type, name);
        lines[i] = malloc(200);
        snprintf(lines[i], 200, "%s length=%d size=%d type=0x%x location=%d", name, length, size, type,
                 uniforms ? glGetUniformLocation(program, name) : glGetAttribLocation(program, name));
    }
    qsort(lines, count, sizeof *lines, by_name);
    for (GLint i = 0; i < count; i++) {
        char k[64];
        snprintf(k, sizeof k, "%s.%d", key, i);
        capi_value(k, "%s", lines[i]);
        free(lines[i]);
    }
    free(lines);
    capi_expect_error(GL_NO_ERROR, key);
}

/* glGetActiveUniform of the uniform called `wanted`, at buffer size `size`. */
static void active_at_size(GLuint program, int uniforms, GLint index, GLsizei size, const char *key)
{
    char name[32];
    memset(name, 'X', sizeof name);
    GLsizei length = -7;
    GLint count = -7;
    GLenum type = 7;
    if (uniforms)
        glGetActiveUniform(program, index, size, &length, &count, &type, name);
    else
        glGetActiveAttrib(program, index, size, &length, &count, &type, name);
    name[31] = 0;
    capi_value(key, "length=%d size=%d type=0x%x name=%.12s", length, count, type, name);
}

static GLint find(GLuint program, int uniforms, const char *wanted)
{
    GLint count = 0;
    glGetProgramiv(program, uniforms ? GL_ACTIVE_UNIFORMS : GL_ACTIVE_ATTRIBUTES, &count);
    for (GLint i = 0; i < count; i++) {
        char name[128];
        GLint size;
        GLenum type;
        if (uniforms)
            glGetActiveUniform(program, i, sizeof name, NULL, &size, &type, name);
        else
            glGetActiveAttrib(program, i, sizeof name, NULL, &size, &type, name);
        if (!strcmp(name, wanted))
            return i;
    }
    return -1;
}

static GLuint reflection(void)
{
    GLuint program = glCreateProgram();
    glAttachShader(program, shader(GL_VERTEX_SHADER, reflect_vertex));
    glAttachShader(program, shader(GL_FRAGMENT_SHADER, reflect_fragment));
    glBindAttribLocation(program, 7, "bound");
    glBindAttribLocation(program, 14, "nrm");
    capi_expect_error(GL_NO_ERROR, "reflect.bind");
    glLinkProgram(program);
    GLint linked = -1;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    capi_value("reflect.linked", "%d", linked);
    entries("reflect.uniform", program, 1);
    entries("reflect.attribute", program, 0);

    /* Buffer sizes and NULL outputs. At size 0 Mesa writes a NUL anyway (one byte past a
     * buffer of 0 bytes); tessera writes nothing, as GL says (manifest: reflect.buffer.0). */
    GLint arr = find(program, 1, "arr[0]");
    for (GLsizei size = 0; size <= 7; size++) {
        char key[64];
        snprintf(key, sizeof key, "reflect.buffer.%d", size);
        active_at_size(program, 1, arr, size, key);
    }
    glGetActiveUniform(program, arr, 16, NULL, NULL, NULL, NULL);
    capi_expect_error(GL_NO_ERROR, "reflect.null_outputs");
    active_at_size(program, 0, find(program, 0, "tc"), 2, "reflect.attribute_buffer");
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    active_at_size(program, 1, count, 32, "reflect.past_end");
    capi_expect_error(GL_INVALID_VALUE, "reflect.past_end");
    active_at_size(program, 1, 0, -1, "reflect.negative_buffer");
    capi_expect_error(GL_INVALID_VALUE, "reflect.negative_buffer");
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
    active_at_size(program, 0, count, 32, "reflect.attribute_past_end");
    capi_expect_error(GL_INVALID_VALUE, "reflect.attribute_past_end");
    glGetActiveUniform(12345, 0, 32, NULL, NULL, NULL, NULL);
    capi_expect_error(GL_INVALID_VALUE, "reflect.no_program");

    /* Locations by name. */
    static const char *names[] = {"arr",    "arr[0]",  "arr[1]",     "arr[2]",   "arr[3]",     "arr[-1]",  "arr[ 1]",
                                  "arr[01]", "arr[1]x", "arr[",      "arr]",     "dyn",        "dyn[2]",   "dyn[3]",
                                  "m3",     "m3[0]",   "m3[1]",      "s",        "s.a",        "s.a[0]",   "s.b",
                                  "s.b[1]", "s.b[2]",  "s.m",        "sa",       "sa[1]",      "sa[1].a",  "sa[1].b[1]",
                                  "sa.a",   "sa[2].a", "cube",       "cube[1]",  "unused",     "init",     "shared",
                                  "fu",     "",        "gl_Fog.color", "gl_ModelViewProjectionMatrix", "nothing", NULL};
    for (int i = 0; names[i]; i++) {
        char key[64];
        snprintf(key, sizeof key, "location.%s", names[i]);
        capi_value(key, "%d", glGetUniformLocation(program, names[i]));
    }
    static const char *attributes[] = {"pos", "nrm", "am", "tc", "bound", "unused_attribute", "gl_Vertex", "gl_Color", "nothing", NULL};
    for (int i = 0; attributes[i]; i++) {
        char key[64];
        snprintf(key, sizeof key, "attribute_location.%s", attributes[i]);
        capi_value(key, "%d", glGetAttribLocation(program, attributes[i]));
    }
    capi_expect_error(GL_NO_ERROR, "locations");
    return program;
}

static void bindings(void)
{
    const char *vs = "attribute vec4 a; attribute vec4 b; attribute mat3 m;"
                     "void main() { gl_Position = a + b + vec4(m[0], 1.0); }";
    GLuint program = glCreateProgram();
    glAttachShader(program, shader(GL_VERTEX_SHADER, vs));
    glLinkProgram(program);
    capi_value("bind.auto", "a=%d b=%d m=%d", glGetAttribLocation(program, "a"), glGetAttribLocation(program, "b"),
               glGetAttribLocation(program, "m"));
    glBindAttribLocation(program, 0, "b");
    glBindAttribLocation(program, 5, "a");
    capi_value("bind.before_relink", "a=%d b=%d", glGetAttribLocation(program, "a"), glGetAttribLocation(program, "b"));
    glLinkProgram(program);
    capi_value("bind.after_relink", "a=%d b=%d m=%d", glGetAttribLocation(program, "a"), glGetAttribLocation(program, "b"),
               glGetAttribLocation(program, "m"));
    glBindAttribLocation(program, 1, "gl_Vertex");
    capi_expect_error(GL_INVALID_OPERATION, "bind.gl_prefix");
    glBindAttribLocation(program, 16, "a");
    capi_expect_error(GL_INVALID_VALUE, "bind.index_16");
    glBindAttribLocation(12345, 0, "a");
    capi_expect_error(GL_INVALID_VALUE, "bind.no_program");
    glBindAttribLocation(program, 15, "unused_name");
    capi_expect_error(GL_NO_ERROR, "bind.unused_name");

    /* An unlinked program: locations are GL_INVALID_OPERATION. */
    GLuint unlinked = glCreateProgram();
    capi_value("unlinked.uniform", "%d", glGetUniformLocation(unlinked, "a"));
    capi_expect_error(GL_INVALID_OPERATION, "unlinked.uniform");
    capi_value("unlinked.attribute", "%d", glGetAttribLocation(unlinked, "a"));
    capi_expect_error(GL_INVALID_OPERATION, "unlinked.attribute");
    GLint count = -1;
    glGetProgramiv(unlinked, GL_ACTIVE_UNIFORMS, &count);
    capi_value("unlinked.active", "%d", count);
    capi_value("bad_name.uniform", "%d", glGetUniformLocation(12345, "a"));
    capi_expect_error(GL_INVALID_VALUE, "bad_name.uniform");
    GLuint s = glCreateShader(GL_VERTEX_SHADER);
    capi_value("shader_name.uniform", "%d", glGetUniformLocation(s, "a"));
    capi_expect_error(GL_INVALID_OPERATION, "shader_name.uniform");
    glDeleteShader(s);
    glDeleteProgram(unlinked);
    glDeleteProgram(program);
}

static void print_float(const char *key, GLuint program, GLint location, int n)
{
    GLfloat f[16];
    for (int i = 0; i < 16; i++)
        f[i] = -99.0f;
    glGetUniformfv(program, location, f);
    char text[400] = "";
    for (int i = 0; i < n; i++)
        snprintf(text + strlen(text), sizeof text - strlen(text), "%g ", f[i]);
    capi_value(key, "%s", text);
}

static void print_int(const char *key, GLuint program, GLint location, int n)
{
    GLint v[16];
    for (int i = 0; i < 16; i++)
        v[i] = -99;
    glGetUniformiv(program, location, v);
    char text[400] = "";
    for (int i = 0; i < n; i++)
        snprintf(text + strlen(text), sizeof text - strlen(text), "%d ", v[i]);
    capi_value(key, "%s", text);
}

static void values(GLuint program)
{
    glUseProgram(program);
#define L(name) glGetUniformLocation(program, name)
    /* Values after the link: zeros and the initializer. */
    print_float("initial.init", program, L("init"), 4);
    print_float("initial.m3", program, L("m3"), 9);
    print_int("initial.tex", program, L("tex"), 1);

    glUniform1f(L("s.a"), 1.5f);
    print_float("set.float", program, L("s.a"), 1);
    print_int("set.float_as_int", program, L("s.a"), 1);
    glUniform1f(L("s.a"), 2.5f);
    print_int("set.float_2.5_as_int", program, L("s.a"), 1);
    glUniform1f(L("s.a"), -2.7f);
    print_int("set.float_-2.7_as_int", program, L("s.a"), 1);
    glUniform3f(L("s.b[1]"), 1, 2, 3);
    print_float("set.vec3_element", program, L("s.b[1]"), 3);
    GLfloat vec3s[9] = {4, 5, 6, 7, 8, 9, 10, 11, 12};
    glUniform3fv(L("sa[1].b"), 2, vec3s);
    print_float("set.vec3v.0", program, L("sa[1].b[0]"), 3);
    print_float("set.vec3v.1", program, L("sa[1].b[1]"), 3);
    /* Past the array's end: the extra elements are dropped. */
    glUniform3fv(L("sa[0].b[1]"), 3, vec3s);
    capi_expect_error(GL_NO_ERROR, "set.past_end");
    print_float("set.past_end.1", program, L("sa[0].b[1]"), 3);
    print_float("set.past_end.next", program, L("sa[0].m"), 4);
    GLfloat floats[5] = {0.5f, 1.5f, 2.5f, 3.5f, 4.5f};
    glUniform1fv(L("arr"), 5, floats);
    print_float("set.arr.0", program, L("arr[0]"), 1);
    print_float("set.arr.2", program, L("arr[2]"), 1);
    glUniform1fv(L("arr[1]"), 1, floats + 4);
    print_float("set.arr.1", program, L("arr[1]"), 1);

    glUniform1i(L("i1"), -7);
    print_int("set.int", program, L("i1"), 1);
    print_float("set.int_as_float", program, L("i1"), 1);
    glUniform3i(L("iv"), 1, -2, 3);
    print_int("set.ivec3", program, L("iv"), 3);
    GLint ints[3] = {7, 8, 9};
    glUniform3iv(L("iv"), 1, ints);
    print_int("set.ivec3v", program, L("iv"), 3);

    glUniform1f(L("bb"), 0.25f);
    print_int("set.bool_from_float", program, L("bb"), 1);
    print_float("set.bool_from_float_f", program, L("bb"), 1);
    glUniform1i(L("bb"), 0);
    print_int("set.bool_from_int_0", program, L("bb"), 1);
    glUniform1i(L("bb"), -5);
    print_int("set.bool_from_int", program, L("bb"), 1);
    glUniform2f(L("bv"), 0.0f, -3.0f);
    print_int("set.bvec2_from_float", program, L("bv"), 2);
    glUniform2i(L("bv"), 9, 0);
    print_int("set.bvec2_from_int", program, L("bv"), 2);
    capi_expect_error(GL_NO_ERROR, "set.scalars");

    GLfloat m[16];
    for (int i = 0; i < 16; i++)
        m[i] = (GLfloat)(i + 1);
    glUniformMatrix3fv(L("m3"), 1, GL_FALSE, m);
    print_float("set.mat3", program, L("m3"), 9);
    glUniformMatrix3fv(L("m3"), 1, GL_TRUE, m);
    print_float("set.mat3_transposed", program, L("m3"), 9);
    glUniformMatrix2x3fv(L("m23"), 1, GL_FALSE, m);
    print_float("set.mat2x3", program, L("m23"), 6);
    glUniformMatrix2x3fv(L("m23"), 1, GL_TRUE, m);
    print_float("set.mat2x3_transposed", program, L("m23"), 6);
    glUniformMatrix4x2fv(L("m42"), 1, GL_TRUE, m);
    print_float("set.mat4x2_transposed", program, L("m42"), 8);
    glUniformMatrix2fv(L("s.m"), 1, GL_TRUE, m);
    print_float("set.mat2_transposed", program, L("s.m"), 4);
    print_int("set.mat2_as_int", program, L("s.m"), 4);
    capi_expect_error(GL_NO_ERROR, "set.matrices");

    glUniform1i(L("tex"), 3);
    print_int("set.sampler", program, L("tex"), 1);
    GLint units[2] = {1, 2};
    glUniform1iv(L("cube"), 2, units);
    print_int("set.sampler_array.1", program, L("cube[1]"), 1);
    print_float("set.sampler_as_float", program, L("cube[1]"), 1);
    capi_expect_error(GL_NO_ERROR, "set.samplers");

    /* Errors: nothing changes. */
    glUniform1f(L("tex"), 1.0f);
    capi_expect_error(GL_INVALID_OPERATION, "error.sampler_float");
    glUniform2i(L("tex"), 1, 1);
    capi_expect_error(GL_INVALID_OPERATION, "error.sampler_ivec2");
    glUniform1i(L("tex"), 1000);
    capi_expect_error(GL_INVALID_VALUE, "error.sampler_unit");
    glUniform1i(L("tex"), -1);
    capi_expect_error(GL_INVALID_VALUE, "error.sampler_negative");
    print_int("error.sampler_kept", program, L("tex"), 1);
    glUniform1i(L("s.a"), 1);
    capi_expect_error(GL_INVALID_OPERATION, "error.int_on_float");
    glUniform1f(L("i1"), 1.0f);
    capi_expect_error(GL_INVALID_OPERATION, "error.float_on_int");
    glUniform2f(L("s.a"), 1.0f, 2.0f);
    capi_expect_error(GL_INVALID_OPERATION, "error.vec2_on_float");
    glUniform4f(L("s.m"), 1, 2, 3, 4);
    capi_expect_error(GL_INVALID_OPERATION, "error.vec4_on_mat2");
    glUniformMatrix2fv(L("init"), 1, GL_FALSE, m);
    capi_expect_error(GL_INVALID_OPERATION, "error.mat2_on_vec4");
    glUniformMatrix3x2fv(L("m23"), 1, GL_FALSE, m);
    capi_expect_error(GL_INVALID_OPERATION, "error.mat3x2_on_mat2x3");
    glUniform1fv(L("s.a"), 2, floats);
    capi_expect_error(GL_INVALID_OPERATION, "error.count_on_non_array");
    glUniform1fv(L("arr"), -1, floats);
    capi_expect_error(GL_INVALID_VALUE, "error.negative_count");
    glUniform1f(1000, 1.0f);
    capi_expect_error(GL_INVALID_OPERATION, "error.bad_location");
    glUniform1f(-2, 1.0f);
    capi_expect_error(GL_INVALID_OPERATION, "error.location_-2");
    glUniform1f(-1, 1.0f);
    capi_expect_error(GL_NO_ERROR, "error.location_-1");
    print_float("error.float_kept", program, L("s.a"), 1);
    print_float("error.get_location_-1", program, -1, 1);
    capi_expect_error(GL_INVALID_OPERATION, "error.get_location_-1");
    print_float("error.get_location_1000", program, 1000, 1);
    capi_expect_error(GL_INVALID_OPERATION, "error.get_location_1000");
    print_float("error.get_no_program", 12345, 0, 1);
    capi_expect_error(GL_INVALID_VALUE, "error.get_no_program");

    /* Uniforms compiled into a display list. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glUniform1f(L("s.a"), 42.0f);
    glUniform2fv(L("arr"), 1, floats); /* wrong size: its error comes when the list runs */
    glEndList();
    capi_expect_error(GL_NO_ERROR, "list.compiled");
    print_float("list.before_call", program, L("s.a"), 1);
    glCallList(list);
    capi_expect_error(GL_INVALID_OPERATION, "list.called");
    print_float("list.after_call", program, L("s.a"), 1);
    glDeleteLists(list, 1);

    /* A relink resets the values (the initializer again). */
    glUniform4f(L("init"), 9, 9, 9, 9);
    glLinkProgram(program);
    print_float("relink.init", program, L("init"), 4);
    print_float("relink.float", program, L("s.a"), 1);

    /* No current program. */
    glUseProgram(0);
    glUniform1f(0, 1.0f);
    capi_expect_error(GL_INVALID_OPERATION, "error.no_current_program");
    glUniform1f(-1, 1.0f);
    capi_expect_error(GL_INVALID_OPERATION, "error.no_current_program_-1");
#undef L
}

/* A location of another program: valid there, past the end of this one. */
static void other_program(GLuint big)
{
    GLuint small = link("other.small", "uniform float x;" VS("gl_PointSize = x;"), NULL, NULL, NULL);
    glUseProgram(small);
    glUniform1f(glGetUniformLocation(big, "fu"), 1.0f);
    capi_expect_error(GL_INVALID_OPERATION, "other.location");
    glUniform1f(glGetUniformLocation(small, "x"), 3.0f);
    print_float("other.value", small, glGetUniformLocation(small, "x"), 1);
    glUseProgram(0);
    glDeleteProgram(small);
}

int main(void)
{
    void *buffer = NULL;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 16, 0, 0, 16, 16, &buffer);
    links();
    GLuint program = reflection();
    bindings();
    values(program);
    other_program(program);
    glDeleteProgram(program);
    capi_expect_error(GL_NO_ERROR, "end");
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
