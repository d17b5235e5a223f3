/* OSMesaGetProcAddress: real GL and OSMesa functions (also extension aliases) are found,
 * with or without a current context, and work when called through the pointer; names
 * that are no function give NULL.
 *
 * Mesa 22 returns a dispatch stub (not NULL) for any unknown name starting with "gl", and
 * crashes on a NULL name; tessera returns NULL for both (checked on tessera only).
 */
#include "common.h"

typedef void (*clear_color_fn)(GLclampf, GLclampf, GLclampf, GLclampf);
typedef void (*enable_fn)(GLenum);
typedef void (*scissor_fn)(GLint, GLint, GLsizei, GLsizei);
typedef void (*clear_fn)(GLbitfield);
typedef void (*finish_fn)(void);
typedef GLenum (*get_error_fn)(void);
typedef const GLubyte *(*get_string_fn)(GLenum);
typedef OSMesaContext (*get_current_fn)(void);

static unsigned char pixels[4 * 4 * 4];

int main(void)
{
    int tessera = capi_probe_is_tessera();
    static const char *present[] = {"glClear",          "glClearColor",        "glScissor",
                                    "glEnable",         "glFinish",            "glGetError",
                                    "glGetString",      "glColorMaskIndexedEXT", "glClampColorARB",
                                    "glDrawBuffersARB", "OSMesaMakeCurrent",   "OSMesaGetCurrentContext",
                                    "OSMesaGetProcAddress", "OSMesaCreateContextExt"};
    for (unsigned i = 0; i < sizeof present / sizeof present[0]; i++) {
        OSMESAproc p = OSMesaGetProcAddress(present[i]);
        capi_check(p != NULL, "%s not found", present[i]);
        capi_value(present[i], "found=%d", p != NULL);
    }
    static const char *absent[] = {"notAFunction", "", "OSMesaNotAFunction", "Glclear", "clear"};
    for (unsigned i = 0; i < sizeof absent / sizeof absent[0]; i++) {
        OSMESAproc p = OSMesaGetProcAddress(absent[i]);
        capi_check(p == NULL, "`%s` found", absent[i]);
        capi_value("absent", "`%s` found=%d", absent[i], p != NULL);
    }
    if (tessera) {
        capi_check(OSMesaGetProcAddress("glNotARealFunction") == NULL, "glNotARealFunction found");
        capi_check(OSMesaGetProcAddress("glClear ") == NULL, "`glClear ` found");
        capi_check(OSMesaGetProcAddress(NULL) == NULL, "NULL name found");
    }

    /* Call through the pointers. */
    get_current_fn get_current = (get_current_fn)OSMesaGetProcAddress("OSMesaGetCurrentContext");
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 4, 4), "bind");
    capi_check(get_current() == ctx, "OSMesaGetCurrentContext through the pointer");

    clear_color_fn clear_color = (clear_color_fn)OSMesaGetProcAddress("glClearColor");
    enable_fn enable = (enable_fn)OSMesaGetProcAddress("glEnable");
    scissor_fn scissor = (scissor_fn)OSMesaGetProcAddress("glScissor");
    clear_fn clear = (clear_fn)OSMesaGetProcAddress("glClear");
    finish_fn finish = (finish_fn)OSMesaGetProcAddress("glFinish");
    get_error_fn get_error = (get_error_fn)OSMesaGetProcAddress("glGetError");
    get_string_fn get_string = (get_string_fn)OSMesaGetProcAddress("glGetString");

    clear_color(0, 0, 1, 1);
    clear(GL_COLOR_BUFFER_BIT);
    clear_color(0, 1, 0, 1);
    enable(GL_SCISSOR_TEST);
    scissor(1, 1, 2, 2);
    clear(GL_COLOR_BUFFER_BIT);
    finish();
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            int inside = x >= 1 && x < 3 && y >= 1 && y < 3;
            const unsigned char *p = pixels + (y * 4 + x) * 4;
            capi_check(p[0] == 0 && p[1] == (inside ? 255 : 0) && p[2] == (inside ? 0 : 255) && p[3] == 255,
                       "pixel (%d,%d) is %02x%02x%02x%02x", x, y, p[0], p[1], p[2], p[3]);
        }
    capi_save_image("through_pointers", 4, 4, 4, CAPI_U8, pixels);

    clear(0x8); /* an invalid bit: GL_INVALID_VALUE, read back through the pointer */
    capi_check(get_error() == GL_INVALID_VALUE, "glGetError through the pointer");
    capi_check(get_error() == GL_NO_ERROR, "error not cleared");
    const GLubyte *direct = glGetString(GL_RENDERER), *indirect = get_string(GL_RENDERER);
    capi_check(direct && indirect && strcmp((const char *)direct, (const char *)indirect) == 0,
               "glGetString through the pointer differs");

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
