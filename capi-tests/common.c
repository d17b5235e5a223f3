/* Implementation of the capi test helpers (see common.h). */
#include "common.h"
#include <stdarg.h>

static int failures;

int capi_is_tessera(void)
{
    const char *renderer = (const char *)glGetString(GL_RENDERER);
    return renderer && strncmp(renderer, "tessera", 7) == 0;
}

int capi_probe_is_tessera(void)
{
    static int answer = -1;
    if (answer < 0) {
        static unsigned char pixel[4];
        OSMesaContext probe = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
        answer = probe && OSMesaMakeCurrent(probe, pixel, GL_UNSIGNED_BYTE, 1, 1) && capi_is_tessera();
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        if (probe)
            OSMesaDestroyContext(probe);
    }
    return answer;
}

void capi_check_at(int cond, const char *file, int line, const char *fmt, ...)
{
    if (cond)
        return;
    failures++;
    printf("FAIL %s:%d: ", file, line);
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    fflush(stdout); /* keep the line if the program crashes later */
}

void capi_value(const char *key, const char *fmt, ...)
{
    printf("VALUE %s ", key);
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    fflush(stdout); /* keep the line if the program crashes later */
}

void capi_value_query(const char *stage, const char *name, GLenum pname, int count)
{
    GLboolean b[16];
    GLint i[16];
    GLfloat f[16];
    GLdouble d[16];
    char key[128], line[2048];
    int n = 0;
    if (count > 16)
        count = 16;
    glGetBooleanv(pname, b);
    glGetIntegerv(pname, i);
    glGetFloatv(pname, f);
    glGetDoublev(pname, d);
    for (int k = 0; k < count; k++)
        n += snprintf(line + n, sizeof line - n, "b=%d i=%d f=%a d=%a ", b[k], i[k], f[k], d[k]);
    line[n] = 0;
    snprintf(key, sizeof key, "%s.%s", stage, name);
    capi_value(key, "%s", line);
}

void capi_expect_error_at(GLenum expected, const char *what, const char *file, int line)
{
    GLenum got = glGetError();
    capi_check_at(got == expected, file, line, "%s: expected GL error 0x%x, got 0x%x", what, expected, got);
    capi_value(what, "error=0x%x", got);
}

void capi_save_image(const char *name, int w, int h, int channels, enum capi_type type, const void *data)
{
    const char *dir = getenv("CAPI_OUT");
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.img", dir ? dir : ".", name);
    FILE *f = fopen(path, "wb");
    if (!f) {
        capi_check(0, "cannot write %s", path);
        return;
    }
    const char *tname = type == CAPI_U8 ? "u8" : type == CAPI_U16 ? "u16" : "f32";
    fprintf(f, "TESSIMG %d %d %d %s\n", w, h, channels, tname);
    fwrite(data, (size_t)type * channels, (size_t)w * h, f);
    fclose(f);
}

void capi_save_framebuffer(const char *name, int w, int h)
{
    unsigned char *pixels = malloc((size_t)w * h * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    capi_save_image(name, w, h, 4, CAPI_U8, pixels);
    free(pixels);
}

OSMesaContext capi_make_context(GLenum format, GLenum type, int depth, int stencil, int accum,
                                int w, int h, void **buffer_out)
{
    OSMesaContext ctx = OSMesaCreateContextExt(format, depth, stencil, accum, NULL);
    if (!ctx) {
        printf("FAIL could not create a context (format 0x%x)\n", format);
        exit(2);
    }
    void *buffer = calloc((size_t)w * h, 16);
    if (!OSMesaMakeCurrent(ctx, buffer, type, w, h)) {
        printf("FAIL OSMesaMakeCurrent failed (type 0x%x)\n", type);
        exit(2);
    }
    if (buffer_out)
        *buffer_out = buffer;
    return ctx;
}

int capi_finish(void)
{
    if (failures)
        printf("%d check(s) failed\n", failures);
    return failures ? 1 : 0;
}

long capi_status_mib(const char *key)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    long kib = -1;
    size_t n = strlen(key);
    while (f && fgets(line, sizeof line, f))
        if (strncmp(line, key, n) == 0)
            kib = atol(line + n + 1);
    if (f)
        fclose(f);
    return kib < 0 ? -1 : kib / 1024;
}

/* A failed capi_check with `key`, `what` and the info log when `object`'s `status` is false
 * (shaders and programs have the same query and log signatures). */
static void check_status(GLuint object, GLenum status, void (*get)(GLuint, GLenum, GLint *),
                         void (*get_log)(GLuint, GLsizei, GLsizei *, GLchar *), const char *key, const char *what)
{
    GLint ok = 0;
    get(object, status, &ok);
    if (!ok) {
        char log[2048] = "";
        get_log(object, sizeof log, NULL, log);
        capi_check(0, "%s: %s failed:\n%s", key, what, log);
    }
}

GLuint capi_compile_shader(GLenum type, const char *key, const char *source)
{
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, NULL);
    glCompileShader(shader);
    check_status(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, key, source);
    return shader;
}

GLuint capi_program_with(const char *key, const char *vs, const char *fs)
{
    GLuint program = glCreateProgram();
    const char *sources[2] = {vs, fs};
    const GLenum types[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    for (int i = 0; i < 2; i++) {
        if (!sources[i])
            continue;
        GLuint shader = capi_compile_shader(types[i], key, sources[i]);
        glAttachShader(program, shader);
        glDeleteShader(shader);
    }
    return program;
}

void capi_link_program(const char *key, GLuint program)
{
    glLinkProgram(program);
    check_status(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, key, "link");
}

GLuint capi_program(const char *key, const char *vs, const char *fs)
{
    GLuint program = capi_program_with(key, vs, fs);
    capi_link_program(key, program);
    return program;
}

void capi_pixel_ortho(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}
