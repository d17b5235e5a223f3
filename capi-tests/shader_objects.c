/* GL 2.0 shader and program objects, without drawing: creation and the one name space of
 * shaders and programs; glShaderSource's pieces and lengths read back by glGetShaderSource at
 * every buffer size; compile status and the info log's first error line; attach, detach and
 * glGetAttachedShaders; link status, glUseProgram and GL_CURRENT_PROGRAM; GL's deferred
 * deletion (a shader attached to a program, a program current in a context) and its
 * GL_DELETE_STATUS; glUseProgram compiled into a display list; objects shared with a second
 * context; glBindAttribLocation and glGetAttribLocation's errors; and the error each invalid
 * call records, with nothing changed. Every value is printed and compared with Mesa. */
#include "common.h"

static const char *vertex_source =
    "#version 110\n"
    "varying vec4 color;\n"
    "void main()\n"
    "{\n"
    "    color = gl_Color;\n"
    "    gl_Position = ftransform();\n"
    "}\n";

static const char *fragment_source =
    "varying vec4 color;\n"
    "void main()\n"
    "{\n"
    "    gl_FragColor = color;\n"
    "}\n";

/* An undeclared name on line 4. */
static const char *bad_fragment_source =
    "varying vec4 color;\n"
    "void main()\n"
    "{\n"
    "    gl_FragColor = colour;\n"
    "}\n";

static void shader_values(const char *key, GLuint shader)
{
    GLint type = -1, deleted = -1, compiled = -1, log_length = -1, source_length = -1;
    glGetShaderiv(shader, GL_SHADER_TYPE, &type);
    glGetShaderiv(shader, GL_DELETE_STATUS, &deleted);
    glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &log_length);
    glGetShaderiv(shader, GL_SHADER_SOURCE_LENGTH, &source_length);
    capi_value(key, "type=0x%x deleted=%d compiled=%d log_length=%s source_length=%d", type, deleted, compiled,
               log_length > 1 ? "some" : (log_length == 1 ? "1" : "0"), source_length);
    capi_expect_error(GL_NO_ERROR, key);
}

static void program_values(const char *key, GLuint program)
{
    GLint deleted = -1, linked = -1, attached = -1;
    glGetProgramiv(program, GL_DELETE_STATUS, &deleted);
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    glGetProgramiv(program, GL_ATTACHED_SHADERS, &attached);
    capi_value(key, "deleted=%d linked=%d attached=%d", deleted, linked, attached);
    capi_expect_error(GL_NO_ERROR, key);
}

static GLuint compiled_shader(GLenum type, const char *source)
{
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, NULL);
    glCompileShader(shader);
    return shader;
}

static void current_program(const char *key)
{
    GLint current = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    capi_value(key, "%d", current);
}

static void sources(void)
{
    GLuint shader = glCreateShader(GL_FRAGMENT_SHADER);
    shader_values("source.new", shader);
    /* Three pieces: NUL-terminated (NULL lengths entry -1), counted, and counted short. */
    const char *pieces[3] = {"void main()", " { gl_FragColor = vec4(1.0); }XXXX", "\n// end\nignored"};
    GLint lengths[3] = {-1, 30, 8};
    glShaderSource(shader, 3, pieces, lengths);
    capi_expect_error(GL_NO_ERROR, "source.set");
    shader_values("source.set", shader);
    int sizes[] = {0, 1, 2, 12, 48, 49, 50, 100};
    for (unsigned i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        char text[128];
        memset(text, '#', sizeof text);
        GLsizei length = -7;
        glGetShaderSource(shader, sizes[i], &length, text);
        text[sizeof text - 1] = 0;
        char key[32];
        snprintf(key, sizeof key, "source.get%d", sizes[i]);
        capi_value(key, "length=%d text=[%.60s] after=%d", length, sizes[i] ? text : "-",
                   sizes[i] < 100 ? text[sizes[i]] : 0);
        capi_expect_error(GL_NO_ERROR, key);
    }
    /* NULL length pointer: the text alone. */
    char text[128] = {0};
    glGetShaderSource(shader, sizeof text, NULL, text);
    capi_value("source.nolength", "[%s]", text);

    /* Errors, each changing nothing. */
    glShaderSource(shader, -1, pieces, NULL);
    capi_expect_error(GL_INVALID_VALUE, "source.negative_count");
    glGetShaderSource(shader, -1, NULL, text);
    capi_expect_error(GL_INVALID_VALUE, "source.negative_size");
    shader_values("source.unchanged", shader);
    glShaderSource(shader, 1, pieces, NULL);
    shader_values("source.replaced", shader);
    glDeleteShader(shader);
}

static void compiling(void)
{
    GLuint good = compiled_shader(GL_VERTEX_SHADER, vertex_source);
    shader_values("compile.good", good);
    GLuint bad = compiled_shader(GL_FRAGMENT_SHADER, bad_fragment_source);
    shader_values("compile.bad", bad);
    char log[1024] = {0};
    GLsizei length = -1;
    glGetShaderInfoLog(bad, sizeof log, &length, log);
    capi_check(length > 0 && (GLsizei)strlen(log) == length, "compile.bad: the log's length");
    /* The first line names the source string and line ("0:4(...): error: ..."). */
    int string = -1, line = -1;
    capi_check(sscanf(log, "%d:%d(", &string, &line) == 2, "compile.bad: log starts with a position: %s", log);
    capi_value("compile.bad.position", "%d:%d error=%d", string, line, strstr(log, "error") != NULL);
    /* A short buffer: bufSize - 1 characters and a NUL. */
    char two[4] = {'#', '#', '#', '#'};
    glGetShaderInfoLog(bad, 3, &length, two);
    capi_value("compile.bad.short_log", "length=%d nul=%d keep=%c", length, two[2] == 0, two[3]);
    glGetShaderInfoLog(bad, -1, &length, two);
    capi_expect_error(GL_INVALID_VALUE, "compile.log_negative_size");
    /* An empty shader does not compile (no main) on Mesa; no source at all: not compiled. */
    GLuint empty = glCreateShader(GL_VERTEX_SHADER);
    glCompileShader(empty);
    shader_values("compile.no_source", empty);
    glDeleteShader(good);
    glDeleteShader(bad);
    glDeleteShader(empty);
    capi_expect_error(GL_NO_ERROR, "compile.delete");
}

static void errors(void)
{
    GLuint shader = glCreateShader(GL_VERTEX_SHADER);
    GLuint program = glCreateProgram();
    capi_value("errors.names", "shader=%d program=%d distinct=%d", shader != 0, program != 0, shader != program);
    capi_check(glIsShader(shader) && !glIsShader(program) && glIsProgram(program) && !glIsProgram(shader),
               "glIsShader/glIsProgram tell the kinds apart");
    capi_value("errors.is", "%d %d %d %d %d", glIsShader(0), glIsProgram(0), glIsShader(program + shader + 100),
               glIsShader(shader), glIsProgram(program));
    capi_expect_error(GL_NO_ERROR, "errors.is");

    GLuint none = glCreateShader(GL_TEXTURE_2D);
    capi_value("errors.create_bad_type", "%u", none);
    capi_expect_error(GL_INVALID_ENUM, "errors.create_bad_type");

    GLint value = -5;
    glGetShaderiv(program, GL_SHADER_TYPE, &value);
    capi_expect_error(GL_INVALID_OPERATION, "errors.shaderiv_on_program");
    glGetShaderiv(12345, GL_SHADER_TYPE, &value);
    capi_expect_error(GL_INVALID_VALUE, "errors.shaderiv_unknown");
    glGetShaderiv(shader, GL_LINK_STATUS, &value);
    capi_expect_error(GL_INVALID_ENUM, "errors.shaderiv_bad_pname");
    glGetProgramiv(shader, GL_LINK_STATUS, &value);
    capi_expect_error(GL_INVALID_OPERATION, "errors.programiv_on_shader");
    glGetProgramiv(12345, GL_LINK_STATUS, &value);
    capi_expect_error(GL_INVALID_VALUE, "errors.programiv_unknown");
    glGetProgramiv(program, GL_SHADER_TYPE, &value);
    capi_expect_error(GL_INVALID_ENUM, "errors.programiv_bad_pname");
    capi_value("errors.value_untouched", "%d", value);

    const char *text = "void main() {}";
    glShaderSource(program, 1, &text, NULL);
    capi_expect_error(GL_INVALID_OPERATION, "errors.source_on_program");
    glCompileShader(program);
    capi_expect_error(GL_INVALID_OPERATION, "errors.compile_program");
    glCompileShader(12345);
    capi_expect_error(GL_INVALID_VALUE, "errors.compile_unknown");
    glLinkProgram(shader);
    capi_expect_error(GL_INVALID_OPERATION, "errors.link_shader");
    glLinkProgram(12345);
    capi_expect_error(GL_INVALID_VALUE, "errors.link_unknown");
    glUseProgram(shader);
    capi_expect_error(GL_INVALID_OPERATION, "errors.use_shader");
    glUseProgram(12345);
    capi_expect_error(GL_INVALID_VALUE, "errors.use_unknown");
    glUseProgram(program);
    capi_expect_error(GL_INVALID_OPERATION, "errors.use_unlinked");
    current_program("errors.current_unchanged");

    glAttachShader(shader, shader);
    capi_expect_error(GL_INVALID_OPERATION, "errors.attach_to_shader");
    glAttachShader(program, program);
    capi_expect_error(GL_INVALID_OPERATION, "errors.attach_program");
    glAttachShader(program, 12345);
    capi_expect_error(GL_INVALID_VALUE, "errors.attach_unknown");
    glAttachShader(12345, shader);
    capi_expect_error(GL_INVALID_VALUE, "errors.attach_to_unknown");
    glAttachShader(program, shader);
    capi_expect_error(GL_NO_ERROR, "errors.attach");
    glAttachShader(program, shader);
    capi_expect_error(GL_INVALID_OPERATION, "errors.attach_twice");
    GLuint other = glCreateShader(GL_FRAGMENT_SHADER);
    glDetachShader(program, other);
    capi_expect_error(GL_INVALID_OPERATION, "errors.detach_not_attached");
    program_values("errors.program_after", program);

    GLuint list[4] = {0, 0, 0, 0};
    GLsizei count = -1;
    glGetAttachedShaders(program, -1, &count, list);
    capi_expect_error(GL_INVALID_VALUE, "errors.attached_negative");
    glAttachShader(program, other);
    glGetAttachedShaders(program, 1, &count, list);
    capi_value("errors.attached_one", "count=%d first_is_ours=%d second=%u", count,
               list[0] == shader || list[0] == other, list[1]);
    glGetAttachedShaders(program, 4, &count, list);
    capi_value("errors.attached_all", "count=%d both=%d", count,
               (list[0] == shader && list[1] == other) || (list[0] == other && list[1] == shader));
    capi_expect_error(GL_NO_ERROR, "errors.attached");

    glBindAttribLocation(program, 100000, "position");
    capi_expect_error(GL_INVALID_VALUE, "errors.bind_attrib_index");
    glBindAttribLocation(program, 1, "gl_Vertex");
    capi_expect_error(GL_INVALID_OPERATION, "errors.bind_attrib_gl_prefix");
    glBindAttribLocation(shader, 1, "position");
    capi_expect_error(GL_INVALID_OPERATION, "errors.bind_attrib_shader");
    GLint location = glGetAttribLocation(program, "position");
    capi_value("errors.attrib_location_unlinked", "%d", location);
    capi_expect_error(GL_INVALID_OPERATION, "errors.attrib_location_unlinked");
    location = glGetUniformLocation(program, "u");
    capi_value("errors.uniform_location_unlinked", "%d", location);
    capi_expect_error(GL_INVALID_OPERATION, "errors.uniform_location_unlinked");

    glDeleteShader(program);
    capi_expect_error(GL_INVALID_OPERATION, "errors.delete_program_as_shader");
    glDeleteProgram(shader);
    capi_expect_error(GL_INVALID_OPERATION, "errors.delete_shader_as_program");
    glDeleteShader(12345);
    capi_expect_error(GL_INVALID_VALUE, "errors.delete_unknown");
    glDeleteShader(0);
    glDeleteProgram(0);
    capi_expect_error(GL_NO_ERROR, "errors.delete_zero");
    glDeleteProgram(program);
    glDeleteShader(shader);
    glDeleteShader(other);
    capi_value("errors.all_gone", "%d %d %d", glIsProgram(program), glIsShader(shader), glIsShader(other));
    capi_expect_error(GL_NO_ERROR, "errors.deleted");
}

static void linking_and_deletion(void)
{
    GLuint vertex = compiled_shader(GL_VERTEX_SHADER, vertex_source);
    GLuint fragment = compiled_shader(GL_FRAGMENT_SHADER, fragment_source);
    GLuint bad = compiled_shader(GL_FRAGMENT_SHADER, bad_fragment_source);
    GLuint program = glCreateProgram();
    program_values("link.new", program);
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    program_values("link.good", program);
    glUseProgram(program);
    capi_expect_error(GL_NO_ERROR, "link.use");
    current_program("link.current");

    /* A failed link keeps the program current and its last good executable in use. */
    GLuint failing = glCreateProgram();
    glAttachShader(failing, vertex);
    glAttachShader(failing, bad);
    glLinkProgram(failing);
    program_values("link.bad", failing);
    GLint log_length = 0;
    glGetProgramiv(failing, GL_INFO_LOG_LENGTH, &log_length);
    capi_value("link.bad.log", "%d", log_length > 1);
    glUseProgram(failing);
    capi_expect_error(GL_INVALID_OPERATION, "link.use_failed");
    current_program("link.still_current");

    /* Deleting an attached shader flags it; it lives until detached. */
    glDeleteShader(fragment);
    capi_value("delete.flagged_shader", "is=%d", glIsShader(fragment));
    shader_values("delete.flagged_shader_values", fragment);
    glDetachShader(program, fragment);
    capi_value("delete.detached_shader", "is=%d", glIsShader(fragment));
    GLint value = -3;
    glGetShaderiv(fragment, GL_DELETE_STATUS, &value);
    capi_expect_error(GL_INVALID_VALUE, "delete.detached_shader_gone");
    program_values("delete.program_after_detach", program);

    /* Deleting the current program flags it; it lives until no longer current. The shaders
     * it holds that were flagged go with it. */
    glDeleteShader(vertex);
    glDeleteProgram(program);
    capi_value("delete.current_program", "is=%d shader_is=%d", glIsProgram(program), glIsShader(vertex));
    program_values("delete.current_program_values", program);
    current_program("delete.current_still");
    glUseProgram(0);
    capi_expect_error(GL_NO_ERROR, "delete.use_zero");
    current_program("delete.current_none");
    capi_value("delete.program_gone", "program=%d vertex=%d (still attached to the failed program)",
               glIsProgram(program), glIsShader(vertex));
    glDeleteProgram(failing);
    capi_value("delete.failed_gone", "program=%d vertex=%d bad=%d", glIsProgram(failing), glIsShader(vertex),
               glIsShader(bad));
    glDeleteShader(bad);
    capi_value("delete.bad_gone", "%d", glIsShader(bad));
    capi_expect_error(GL_NO_ERROR, "delete.end");

    /* A program with no shaders. */
    GLuint empty = glCreateProgram();
    glLinkProgram(empty);
    program_values("link.empty", empty);
    glValidateProgram(empty);
    GLint validated = -1;
    glGetProgramiv(empty, GL_VALIDATE_STATUS, &validated);
    capi_expect_error(GL_NO_ERROR, "link.empty");
    glDeleteProgram(empty);
}

static void lists_and_sharing(void)
{
    GLuint program = glCreateProgram();
    GLuint vertex = compiled_shader(GL_VERTEX_SHADER, vertex_source);
    GLuint fragment = compiled_shader(GL_FRAGMENT_SHADER, fragment_source);
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    /* glUseProgram is compiled; glCreateShader inside a list runs at once. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glUseProgram(program);
    GLuint inside = glCreateShader(GL_VERTEX_SHADER);
    glEndList();
    capi_value("list.created_inside", "%d", glIsShader(inside));
    current_program("list.compiled_only");
    glCallList(list);
    current_program("list.called");
    glUseProgram(0);
    glDeleteLists(list, 1);
    glDeleteShader(inside);

    /* A second context sharing the first's objects sees the program, linked. */
    OSMesaContext first = OSMesaGetCurrentContext();
    OSMesaContext second = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, first);
    capi_check(second != NULL, "shared context");
    static unsigned char pixels[4 * 4 * 4];
    OSMesaMakeCurrent(second, pixels, GL_UNSIGNED_BYTE, 4, 4);
    capi_value("share.seen", "program=%d vertex=%d", glIsProgram(program), glIsShader(vertex));
    program_values("share.values", program);
    glUseProgram(program);
    current_program("share.current");
    capi_expect_error(GL_NO_ERROR, "share.use");
    OSMesaDestroyContext(second);
}

int main(void)
{
    void *buffer = NULL;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 16, 0, 0, 16, 16, &buffer);
    current_program("start");
    sources();
    compiling();
    errors();
    linking_and_deletion();
    lists_and_sharing();
    capi_expect_error(GL_NO_ERROR, "end");
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
