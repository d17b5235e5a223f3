/* OSMesaGetIntegerv for every query (OSMESA_WIDTH, HEIGHT, FORMAT, TYPE, ROW_LENGTH, Y_UP,
 * MAX_WIDTH, MAX_HEIGHT) with several formats, types and sizes, after rebinding, after a
 * refused bind, and without a current context.
 *
 * Mesa 22 dereferences the missing context for every query but WIDTH, HEIGHT and MAX_*
 * when no context is current (a crash), so those queries run on tessera only. For an
 * unknown query Mesa 22 prints a warning and records no GL error; tessera records
 * GL_INVALID_ENUM. Neither writes the value.
 */
#include "common.h"

static const GLint queries[] = {OSMESA_WIDTH,     OSMESA_HEIGHT,    OSMESA_FORMAT,    OSMESA_TYPE,
                                OSMESA_ROW_LENGTH, OSMESA_Y_UP,      OSMESA_MAX_WIDTH, OSMESA_MAX_HEIGHT};
static const char *names[] = {"width", "height", "format", "type", "row_length", "y_up", "max_width", "max_height"};

static GLint get(GLint pname)
{
    GLint value = -12345;
    OSMesaGetIntegerv(pname, &value);
    return value;
}

/* Prints every query as one VALUE line and checks the size, format and type. */
static void check_all(const char *what, GLint w, GLint h, GLenum format, GLenum type)
{
    char line[256] = "";
    for (int i = 0; i < 8; i++) {
        char item[40];
        snprintf(item, sizeof item, "%s%s=%d", i ? " " : "", names[i], get(queries[i]));
        strcat(line, item);
    }
    capi_value(what, "%s", line);
    capi_check(get(OSMESA_WIDTH) == w && get(OSMESA_HEIGHT) == h, "%s: size %dx%d", what, get(OSMESA_WIDTH),
               get(OSMESA_HEIGHT));
    capi_check(get(OSMESA_FORMAT) == (GLint)format, "%s: format 0x%x", what, get(OSMESA_FORMAT));
    capi_check(get(OSMESA_TYPE) == (GLint)type, "%s: type 0x%x", what, get(OSMESA_TYPE));
    capi_check(get(OSMESA_MAX_WIDTH) >= 4096 && get(OSMESA_MAX_HEIGHT) >= 4096, "%s: max size below 4096", what);
    capi_check(glGetError() == GL_NO_ERROR, "%s: a query recorded a GL error", what);
}

int main(void)
{
    int tessera = capi_probe_is_tessera();

    /* No current context. */
    capi_value("none_width", "%d", get(OSMESA_WIDTH));
    capi_value("none_height", "%d", get(OSMESA_HEIGHT));
    capi_value("none_max", "%d %d", get(OSMESA_MAX_WIDTH), get(OSMESA_MAX_HEIGHT));
    if (tessera) {
        capi_check(get(OSMESA_FORMAT) == 0 && get(OSMESA_TYPE) == 0 && get(OSMESA_ROW_LENGTH) == 0,
                   "format/type/row length without a context are not 0");
        capi_check(get(OSMESA_Y_UP) == 1, "y_up without a context is not 1");
    }

    static float buffer[64 * 64 * 4];
    struct {
        GLenum format, type;
        int w, h;
        const char *name;
    } cases[] = {
        {OSMESA_RGBA, GL_UNSIGNED_BYTE, 5, 3, "rgba_ubyte_5x3"},
        {OSMESA_BGRA, GL_UNSIGNED_BYTE, 7, 2, "bgra_ubyte_7x2"},
        {OSMESA_ARGB, GL_UNSIGNED_BYTE, 1, 1, "argb_ubyte_1x1"},
        {OSMESA_RGBA, GL_FLOAT, 64, 64, "rgba_float_64x64"},
        {OSMESA_RGB, GL_UNSIGNED_BYTE, 4, 4, "rgb_ubyte_4x4"},
        {OSMESA_RGBA, GL_UNSIGNED_SHORT, 9, 31, "rgba_ushort_9x31"},
        {OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 3, 9, "rgb565_3x9"},
    };
    for (unsigned i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        OSMesaContext ctx = OSMesaCreateContextExt(cases[i].format, 16, 0, 0, NULL);
        capi_check(OSMesaMakeCurrent(ctx, buffer, cases[i].type, cases[i].w, cases[i].h), "%s: bind", cases[i].name);
        check_all(cases[i].name, cases[i].w, cases[i].h, cases[i].format, cases[i].type);

        /* Rebinding with another size updates the size; a refused bind changes nothing. */
        capi_check(OSMesaMakeCurrent(ctx, buffer, cases[i].type, 2, 6), "%s: rebind", cases[i].name);
        check_all("rebound", 2, 6, cases[i].format, cases[i].type);
        capi_check(!OSMesaMakeCurrent(ctx, buffer, GL_INT, 30, 30), "%s: GL_INT accepted", cases[i].name);
        check_all("after_refused_bind", 2, 6, cases[i].format, cases[i].type);

        GLint value = -7;
        OSMesaGetIntegerv(0x99, &value);
        GLenum error = glGetError();
        capi_check(value == -7, "%s: an unknown query wrote %d", cases[i].name, value);
        capi_check(error == (tessera ? GL_INVALID_ENUM : GL_NO_ERROR), "%s: unknown query: error 0x%x", cases[i].name,
                   error);

        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        capi_value("released_size", "%d %d", get(OSMESA_WIDTH), get(OSMESA_HEIGHT));
        OSMesaDestroyContext(ctx);
    }
    return capi_finish();
}
