/* OSMesaCreateContextAttribs: attribute lists (format, depth/stencil/accum bits, profile,
 * version), the defaults of <GL/osmesa.h> (RGBA, no depth, stencil or accum buffer,
 * compatibility profile, version 1.0), refusals (unknown attribute, negative sizes, bad
 * format, bad profile, impossible version), and OSMesaCreateContext's 24/8 default.
 *
 * Deliberate differences from Mesa 22, checked per implementation:
 *  - a core profile request: Mesa 22 creates a 4.5 core context; tessera has no shaders
 *    and returns NULL.
 *  - a NULL attribute list: Mesa 22 dereferences it (a crash); tessera uses the defaults.
 *  - OSMESA_COLOR_INDEX: Mesa 22 creates the context and refuses it at MakeCurrent;
 *    tessera refuses it at creation. Both satisfy "never usable", which is what is checked.
 */
#include "common.h"

static unsigned char pixels[4 * 4 * 4];

/* Depth bytes per value of a context bound to a 4x4 RGBA8 buffer (0: none), or -1 if it
 * cannot be bound with `type`. */
static int depth_bytes(OSMesaContext ctx, GLenum type)
{
    if (!OSMesaMakeCurrent(ctx, pixels, type, 4, 4))
        return -1;
    GLint w, h, bytes = 0;
    void *p;
    if (!OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &p))
        bytes = 0;
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    return bytes;
}

/* Creates a context from `attribs`, checks it was (not) created, reports it. */
static OSMesaContext create(const char *what, const int *attribs, int expect_context)
{
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
    capi_check((ctx != NULL) == expect_context, "%s: got %s", what, ctx ? "a context" : "NULL");
    capi_value(what, "context=%d", ctx != NULL);
    return ctx;
}

static void created(const char *what, const int *attribs, GLenum format, GLenum type, int bytes)
{
    OSMesaContext ctx = create(what, attribs, 1);
    if (!ctx)
        return;
    int got = depth_bytes(ctx, type);
    capi_check(got == bytes, "%s: depth bytes %d, expected %d", what, got, bytes);
    if (OSMesaMakeCurrent(ctx, pixels, type, 4, 4)) {
        GLint f = 0;
        OSMesaGetIntegerv(OSMESA_FORMAT, &f);
        capi_check(f == (GLint)format, "%s: format 0x%x", what, f);
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    }
    OSMesaDestroyContext(ctx);
}

/* A version request gives NULL or a context of at least that version. */
static void version(int major, int minor, int must_exist)
{
    int attribs[] = {OSMESA_CONTEXT_MAJOR_VERSION, major, OSMESA_CONTEXT_MINOR_VERSION, minor, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
    capi_check(ctx != NULL || !must_exist, "version %d.%d refused", major, minor);
    if (!ctx)
        return;
    capi_check(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 4, 4), "version %d.%d: bind", major, minor);
    const char *v = (const char *)glGetString(GL_VERSION);
    int got_major = 0, got_minor = 0;
    capi_check(v && sscanf(v, "%d.%d", &got_major, &got_minor) == 2, "GL_VERSION `%s`", v ? v : "(null)");
    capi_check(got_major > major || (got_major == major && got_minor >= minor), "version %d.%d request gave %s", major,
               minor, v ? v : "(null)");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
}

int main(void)
{
    int tessera = capi_probe_is_tessera();

    static const int empty[] = {0};
    created("empty_list", empty, OSMESA_RGBA, GL_UNSIGNED_BYTE, 0);
    if (tessera) {
        OSMesaContext ctx = OSMesaCreateContextAttribs(NULL, NULL);
        capi_check(ctx && depth_bytes(ctx, GL_UNSIGNED_BYTE) == 0, "NULL list: not a default context");
        if (ctx)
            OSMesaDestroyContext(ctx);
    }
    static const int bgra16[] = {OSMESA_FORMAT, OSMESA_BGRA, OSMESA_DEPTH_BITS, 16, OSMESA_STENCIL_BITS, 0, 0};
    created("bgra_depth16", bgra16, OSMESA_BGRA, GL_UNSIGNED_BYTE, 2);
    static const int d24s8[] = {OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8, 0};
    created("depth24_stencil8", d24s8, OSMESA_RGBA, GL_UNSIGNED_BYTE, 4);
    static const int stencil_only[] = {OSMESA_STENCIL_BITS, 8, 0};
    created("stencil_only", stencil_only, OSMESA_RGBA, GL_UNSIGNED_BYTE, 0);
    static const int accum[] = {OSMESA_ACCUM_BITS, 16, OSMESA_DEPTH_BITS, 24, 0};
    created("accum16", accum, OSMESA_RGBA, GL_UNSIGNED_BYTE, 4);
    static const int rgb565[] = {OSMESA_FORMAT, OSMESA_RGB_565, 0};
    created("rgb565", rgb565, OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 0);
    static const int rgb_float[] = {OSMESA_FORMAT, OSMESA_RGB, OSMESA_DEPTH_BITS, 24, 0};
    created("rgb_float", rgb_float, OSMESA_RGB, GL_FLOAT, 4);
    static const int compat[] = {OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
    created("compat_profile", compat, OSMESA_RGBA, GL_UNSIGNED_BYTE, 0);
    static const int later_wins[] = {OSMESA_DEPTH_BITS, 24, OSMESA_DEPTH_BITS, 0, 0};
    created("repeated_attribute", later_wins, OSMESA_RGBA, GL_UNSIGNED_BYTE, 0);

    static const int unknown[] = {0x99, 1, 0};
    create("unknown_attribute", unknown, 0);
    static const int unknown_later[] = {OSMESA_DEPTH_BITS, 16, 0x1234, 0, 0};
    create("unknown_after_valid", unknown_later, 0);
    static const int negative_depth[] = {OSMESA_DEPTH_BITS, -1, 0};
    create("negative_depth", negative_depth, 0);
    static const int negative_stencil[] = {OSMESA_STENCIL_BITS, -8, 0};
    create("negative_stencil", negative_stencil, 0);
    static const int negative_accum[] = {OSMESA_ACCUM_BITS, -16, 0};
    create("negative_accum", negative_accum, 0);
    static const int bad_format[] = {OSMESA_FORMAT, 0x1234, 0};
    create("bad_format", bad_format, 0);
    static const int bad_profile[] = {OSMESA_PROFILE, 0x1234, 0};
    create("bad_profile", bad_profile, 0);
    static const int version9[] = {OSMESA_CONTEXT_MAJOR_VERSION, 9, 0};
    create("version_9", version9, 0);

    static const int core[] = {OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                               OSMESA_CONTEXT_MINOR_VERSION, 2, 0};
    OSMesaContext core_ctx = OSMesaCreateContextAttribs(core, NULL);
    capi_check((core_ctx == NULL) == tessera, "core profile: %s", core_ctx ? "a context" : "NULL");
    if (core_ctx)
        OSMesaDestroyContext(core_ctx);

    static const int color_index[] = {OSMESA_FORMAT, OSMESA_COLOR_INDEX, 0};
    OSMesaContext ci = OSMesaCreateContextAttribs(color_index, NULL);
    capi_check(!ci || depth_bytes(ci, GL_UNSIGNED_BYTE) == -1, "a color index context can be bound");
    if (ci)
        OSMesaDestroyContext(ci);

    version(1, 0, 1);
    version(1, 1, 0);
    version(1, 5, 0);
    version(2, 0, 0);
    version(2, 1, 0);
    version(3, 0, 0);

    /* OSMesaCreateContext: 24-bit depth and 8-bit stencil. */
    OSMesaContext plain = OSMesaCreateContext(OSMESA_RGBA, NULL);
    capi_check(plain && depth_bytes(plain, GL_UNSIGNED_BYTE) == 4, "OSMesaCreateContext has no 24/8 depth buffer");
    capi_value("create_context_depth_bytes", "%d", plain ? depth_bytes(plain, GL_UNSIGNED_BYTE) : -1);

    /* A share list that is a context. */
    OSMesaContext shared = OSMesaCreateContextAttribs(empty, plain);
    capi_check(shared != NULL, "sharing with a context failed");
    capi_value("shared", "context=%d", shared != NULL);
    if (shared)
        OSMesaDestroyContext(shared);
    if (plain)
        OSMesaDestroyContext(plain);
    return capi_finish();
}
