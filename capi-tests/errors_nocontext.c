/* GL and OSMesa calls without a current context must not crash and do nothing: before any
 * context exists, after a failed first OSMesaMakeCurrent, after a failed bind of another
 * context, after MakeCurrent(NULL, NULL), and after the current context was destroyed.
 * Queries return neutral values (glGetError GL_NO_ERROR, glGetString NULL, glIsEnabled
 * GL_FALSE). The program then binds a context and checks that none of it leaked into it.
 *
 * Mesa 22 crashes in OSMesaPixelStore, OSMesaColorClamp and most OSMesaGetIntegerv
 * queries without a current context, and in OSMesaGetDepthBuffer on a context never
 * bound; those calls run on tessera only.
 */
#include "common.h"

static unsigned char pixels[4 * 4 * 4];

static void gl_calls(const char *when, int tessera)
{
    glClearColor(1, 0, 0, 1);
    glClearDepth(0.0);
    glClearStencil(7);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glClear(0x8);
    glEnable(GL_SCISSOR_TEST);
    glEnable(0x1234);
    glDisable(GL_DITHER);
    glScissor(0, 0, 1, 1);
    glViewport(0, 0, 1, 1);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glStencilMask(0x1);
    glHint(GL_FOG_HINT, GL_NICEST);
    glFlush();
    glFinish();
    GLenum error = glGetError();
    const GLubyte *vendor = glGetString(GL_VENDOR);
    GLboolean enabled = glIsEnabled(GL_SCISSOR_TEST);
    capi_check(error == GL_NO_ERROR && vendor == NULL && enabled == GL_FALSE,
               "%s: glGetError 0x%x, glGetString %p, glIsEnabled %d", when, error, (const void *)vendor, enabled);
    capi_value(when, "error=0x%x vendor_null=%d enabled=%d", error, vendor == NULL, enabled);
    capi_check(OSMesaGetCurrentContext() == NULL, "%s: a context is current", when);

    GLint width = -1, height = -1;
    OSMesaGetIntegerv(OSMESA_WIDTH, &width);
    OSMesaGetIntegerv(OSMESA_HEIGHT, &height);
    capi_value("size", "%s: %dx%d", when, width, height);
    if (tessera) {
        GLint format = -1;
        OSMesaGetIntegerv(OSMESA_FORMAT, &format);
        capi_check(format == 0, "%s: OSMESA_FORMAT %d", when, format);
        OSMesaPixelStore(OSMESA_Y_UP, 0);
        OSMesaPixelStore(OSMESA_ROW_LENGTH, 100);
        OSMesaColorClamp(GL_TRUE);
        OSMesaDestroyContext(NULL);
        OSMesaDestroyContext((OSMesaContext)(void *)pixels); /* not a context: ignored */
    }
}

int main(void)
{
    int tessera = capi_probe_is_tessera();
    gl_calls("before_any_context", tessera);

    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    gl_calls("created_not_bound", tessera);
    if (tessera) {
        GLint w = -1, h = -1, bytes = -1;
        void *p = &w;
        capi_check(!OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &p), "depth buffer of an unbound context");
    }

    capi_check(!OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_SHORT_5_6_5, 4, 4), "RGBA with 5_6_5 accepted");
    gl_calls("after_failed_first_bind", tessera);
    capi_check(!OSMesaMakeCurrent(ctx, NULL, GL_UNSIGNED_BYTE, 4, 4), "NULL buffer accepted");
    gl_calls("after_null_buffer", tessera);

    capi_check(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 4, 4), "bind");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    gl_calls("after_release", tessera);

    OSMesaContext doomed = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    static unsigned char doomed_pixels[4 * 4 * 4];
    capi_check(OSMesaMakeCurrent(doomed, doomed_pixels, GL_UNSIGNED_BYTE, 4, 4), "bind doomed");
    OSMesaDestroyContext(doomed);
    gl_calls("after_destroying_current", tessera);

    /* Nothing above reached ctx: its state is the default (black clear color, no scissor,
     * full color mask) and its error flag is clear. */
    memset(pixels, 0xEE, sizeof pixels);
    capi_check(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 4, 4), "bind again");
    capi_expect_error(GL_NO_ERROR, "ctx_error_flag");
    capi_check(!glIsEnabled(GL_SCISSOR_TEST), "scissor test leaked into ctx");
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glFinish();
    for (int i = 0; i < 16; i++)
        capi_check(pixels[4 * i] == 0 && pixels[4 * i + 1] == 0 && pixels[4 * i + 2] == 0 && pixels[4 * i + 3] == 0,
                   "pixel %d is %02x%02x%02x%02x", i, pixels[4 * i], pixels[4 * i + 1], pixels[4 * i + 2],
                   pixels[4 * i + 3]);
    GLint w, h, bytes;
    unsigned int *ds = NULL;
    capi_check(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, (void **)&ds) && ds && ds[0] == 0x00ffffffu,
               "depth/stencil leaked into ctx: 0x%08x", ds ? ds[0] : 0);
    capi_save_image("ctx_after", 4, 4, 4, CAPI_U8, pixels);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
