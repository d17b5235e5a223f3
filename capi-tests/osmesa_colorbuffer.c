/* OSMesaGetColorBuffer: GL_FALSE and zeroed outputs for a context that was never bound;
 * for a bound one the caller's own pointer, the bound size and the context's format, also
 * after the context was released or another one made current.
 *
 * tessera treats OSMesaGetColorBuffer as a flush point (the pixels are in the buffer when
 * it returns); Mesa 22 does not write the buffer there. That part is checked on tessera
 * only; both are checked after glFinish.
 */
#include "common.h"

static unsigned char pixels[6 * 5 * 4], other[2 * 2 * 4];

int main(void)
{
    int tessera = capi_probe_is_tessera();
    static const GLenum formats[] = {OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_RGB_565};
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE,
                                   GL_UNSIGNED_SHORT_5_6_5};
    for (int i = 0; i < 5; i++) {
        OSMesaContext ctx = OSMesaCreateContextExt(formats[i], 0, 0, 0, NULL);
        GLint w = -1, h = -1, format = -1;
        void *pointer = &w;
        GLboolean found = OSMesaGetColorBuffer(ctx, &w, &h, &format, &pointer);
        capi_check(!found && w == 0 && h == 0 && format == 0 && pointer == NULL,
                   "format 0x%x: an unbound context reports a color buffer (%d %dx%d 0x%x %p)", formats[i], found, w, h,
                   format, pointer);
        capi_value("unbound", "found=%d %dx%d format=0x%x", found, w, h, format);

        memset(pixels, 0xEE, sizeof pixels);
        capi_check(OSMesaMakeCurrent(ctx, pixels, types[i], 6, 5), "bind");
        glClearColor(1, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        found = OSMesaGetColorBuffer(ctx, &w, &h, &format, &pointer);
        capi_check(found && w == 6 && h == 5 && format == (GLint)formats[i] && pointer == pixels,
                   "format 0x%x: bound: %d %dx%d 0x%x %s pointer", formats[i], found, w, h, format,
                   pointer == pixels ? "same" : "another");
        capi_value("bound", "found=%d %dx%d format=0x%x same_pointer=%d", found, w, h, format, pointer == pixels);
        if (tessera)
            capi_check(pixels[0] != 0xEE || pixels[1] != 0xEE, "OSMesaGetColorBuffer did not flush the clear");
        glFinish();
        capi_check(pixels[0] != 0xEE || pixels[1] != 0xEE, "glFinish did not write the buffer");

        /* Released, and with another context current: still the buffer it was bound to. */
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        found = OSMesaGetColorBuffer(ctx, &w, &h, &format, &pointer);
        capi_check(found && w == 6 && h == 5 && pointer == pixels, "released: %d %dx%d", found, w, h);
        capi_value("released", "found=%d %dx%d format=0x%x same_pointer=%d", found, w, h, format, pointer == pixels);
        OSMesaContext ctx2 = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
        capi_check(OSMesaMakeCurrent(ctx2, other, GL_UNSIGNED_BYTE, 2, 2), "bind ctx2");
        found = OSMesaGetColorBuffer(ctx, &w, &h, &format, &pointer);
        capi_check(found && w == 6 && h == 5 && pointer == pixels, "another context current: %d %dx%d", found, w, h);
        found = OSMesaGetColorBuffer(ctx2, &w, &h, &format, &pointer);
        capi_check(found && w == 2 && h == 2 && format == OSMESA_RGBA && pointer == other, "ctx2: %d %dx%d", found, w,
                   h);

        /* NULL out-pointers are skipped by tessera; Mesa 22 writes through them (a crash). */
        if (tessera)
            capi_check(OSMesaGetColorBuffer(ctx2, NULL, NULL, NULL, NULL) == GL_TRUE, "NULL out-pointers refused");
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        OSMesaDestroyContext(ctx2);
        OSMesaDestroyContext(ctx);
    }
    return capi_finish();
}
