/* OSMesaColorClamp with out-of-range clear colors: a float buffer stores the clear color
 * unclamped whatever the clamp setting (ARB_color_buffer_float: fragment color clamping
 * does not apply to glClear; piglit arb_color_buffer_float-clear), also for scissored and
 * color-masked clears; fixed-point buffers (8 and 16 bits) always clamp to [0, 1].
 * Clamping of drawn fragments is tested with drawing.
 */
#include "common.h"

#define W 4
#define H 2

static const float wild[4] = {-0.5f, 1.5f, 2.0f, 0.25f};
static const float huge[4] = {1e30f, -1e30f, 0.0f, 3.0f};

static void check_float(const float *pixels, const float c[4], const char *what)
{
    for (int i = 0; i < W * H; i++)
        if (memcmp(pixels + 4 * i, c, sizeof(float) * 4) != 0) {
            capi_check(0, "%s: pixel %d is (%g, %g, %g, %g), expected (%g, %g, %g, %g)", what, i, pixels[4 * i],
                       pixels[4 * i + 1], pixels[4 * i + 2], pixels[4 * i + 3], c[0], c[1], c[2], c[3]);
            return;
        }
}

static void clear_to(const float c[4])
{
    glClearColor(c[0], c[1], c[2], c[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
}

int main(void)
{
    static float pixels[W * H * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, pixels, GL_FLOAT, W, H), "bind float");

    clear_to(wild);
    check_float(pixels, wild, "default clamp");
    capi_save_image("float_default", W, H, 4, CAPI_F32, pixels);

    OSMesaColorClamp(GL_TRUE);
    capi_check(glGetError() == GL_NO_ERROR, "OSMesaColorClamp(GL_TRUE) recorded an error");
    clear_to(huge);
    check_float(pixels, huge, "clamp on, huge values");
    clear_to(wild);
    check_float(pixels, wild, "clamp on");
    capi_save_image("float_clamp_on", W, H, 4, CAPI_F32, pixels);

    /* Scissored and masked clears take the same path as a quad in some implementations. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, W, H);
    clear_to(huge);
    check_float(pixels, huge, "clamp on, scissored");
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    clear_to(wild);
    const float masked[4] = {wild[0], wild[1], wild[2], huge[3]};
    check_float(pixels, masked, "clamp on, alpha masked");
    capi_save_image("float_clamp_on_masked", W, H, 4, CAPI_F32, pixels);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    OSMesaColorClamp(GL_FALSE);
    clear_to(huge);
    check_float(pixels, huge, "clamp off");
    capi_save_image("float_clamp_off", W, H, 4, CAPI_F32, pixels);

    /* Fixed-point buffers clamp, with the clamp on or off. */
    static unsigned char bytes[W * H * 4];
    static unsigned short shorts[W * H * 4];
    for (int on = 0; on < 2; on++) {
        OSMesaContext fixed = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
        capi_check(OSMesaMakeCurrent(fixed, bytes, GL_UNSIGNED_BYTE, W, H), "bind ubyte");
        OSMesaColorClamp(on ? GL_TRUE : GL_FALSE);
        clear_to(wild);
        capi_check(bytes[0] == 0 && bytes[1] == 255 && bytes[2] == 255 && bytes[3] == 64,
                   "ubyte clamp %d: %d %d %d %d", on, bytes[0], bytes[1], bytes[2], bytes[3]);
        capi_save_image(on ? "ubyte_clamp_on" : "ubyte_clamp_off", W, H, 4, CAPI_U8, bytes);
        capi_check(OSMesaMakeCurrent(fixed, shorts, GL_UNSIGNED_SHORT, W, H), "bind ushort");
        clear_to(huge);
        capi_check(shorts[0] == 65535 && shorts[1] == 0 && shorts[2] == 0 && shorts[3] == 65535,
                   "ushort clamp %d: %d %d %d %d", on, shorts[0], shorts[1], shorts[2], shorts[3]);
        capi_save_image(on ? "ushort_clamp_on" : "ushort_clamp_off", W, H, 4, CAPI_U16, shorts);
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        OSMesaDestroyContext(fixed);
    }

    OSMesaDestroyContext(ctx);
    return capi_finish();
}
