/* Clear-value conversions, whole-buffer and partial (scissored), for every buffer kind.
 *
 * llvmpipe converts a whole-buffer clear by packing the value, and draws a partial clear as
 * a quad, whose color and depth stores convert differently (16-bit ties, 5/6-bit through
 * 8-bit, depth through the viewport in single precision). Tessera matches both paths bit for
 * bit; this sweeps 2041 values through each buffer kind and prints every result. */
#include "common.h"

static void sweep(const char *label, GLenum format, GLenum type, int depth, int stencil, int partial)
{
    OSMesaContext ctx = OSMesaCreateContextExt(format, depth, stencil, 0, NULL);
    static float buffer[8 * 8 * 4];
    capi_check(ctx && OSMesaMakeCurrent(ctx, buffer, type, 8, 8), "%s: context", label);
    if (partial) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, 4, 4);
    }
    for (int i = -20; i <= 2020; i++) {
        float v = i == -20 ? -0.0f : i / 2000.0f;
        glClearColor(v, 1.0f - v, v * 0.5f, v);
        glClearDepth(v);
        glClearStencil(i);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glFinish();
        GLint w, h, bytes_per_value;
        void *depth_buffer;
        unsigned d = 0;
        if (OSMesaGetDepthBuffer(ctx, &w, &h, &bytes_per_value, &depth_buffer))
            d = bytes_per_value == 2 ? ((unsigned short *)depth_buffer)[0] : ((unsigned *)depth_buffer)[0];
        const unsigned char *b = (const unsigned char *)buffer;
        char key[64];
        snprintf(key, sizeof key, "%s.%s.%d", label, partial ? "partial" : "whole", i);
        capi_value(key, "%02x%02x%02x%02x%02x%02x%02x%02x%02x%02x%02x%02x%02x%02x%02x%02x d=%x", b[0], b[1], b[2],
                   b[3], b[4], b[5], b[6], b[7], b[8], b[9], b[10], b[11], b[12], b[13], b[14], b[15], d);
    }
    capi_check(glGetError() == GL_NO_ERROR, "%s: no error", label);
    OSMesaDestroyContext(ctx);
}

int main(void)
{
    for (int partial = 0; partial < 2; partial++) {
        sweep("rgba8-d24s8", OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, partial);
        sweep("rgb565-d16", OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 16, 0, partial);
        sweep("rgbaf-d24", OSMESA_RGBA, GL_FLOAT, 24, 0, partial);
        sweep("rgba16-d16", OSMESA_RGBA, GL_UNSIGNED_SHORT, 16, 0, partial);
    }
    return capi_finish();
}
