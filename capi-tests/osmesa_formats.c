/* Every OSMesa format x type: which OSMesaMakeCurrent accepts, and the exact bytes a full
 * clear followed by a scissored clear leave in the caller's buffer after glFinish (channel
 * order, component size, native byte order, rows bottom-up), with the memory after the
 * buffer untouched.
 *
 * Deliberate differences from Mesa 22 (branched on the implementation):
 *  - OSMESA_BGR: Mesa 22 creates the context but refuses every type at MakeCurrent (gallium
 *    has no B8G8R8 format); tessera accepts it with GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and
 *    GL_FLOAT.
 *  - Mesa 22 writes OSMESA_BGRA and OSMESA_ARGB with GL_UNSIGNED_SHORT or GL_FLOAT in RGBA
 *    order (its osmesa.c marks these "XXX wrong"), and leaves OSMESA_RGB with
 *    GL_UNSIGNED_SHORT all zeros. tessera writes the documented order; the bytes of these
 *    combinations are checked on tessera only.
 *  - Mesa 22's llvmpipe corrupts a scissored clear of OSMESA_RGB with GL_UNSIGNED_BYTE (it
 *    writes 4-byte pixels into the 3-byte rows; softpipe is right), so for that combination
 *    only the full clear is compared with Mesa.
 */
#include "common.h"

#define W 8
#define H 4
#define GUARD 64

static const GLenum formats[] = {OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR, OSMESA_RGB_565};
static const char *format_names[] = {"rgba", "bgra", "argb", "rgb", "bgr", "rgb565"};
static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT, GL_UNSIGNED_SHORT_5_6_5};
static const char *type_names[] = {"ubyte", "ushort", "float", "ushort565"};

/* For each component in memory, which RGBA channel it holds. */
static int order(GLenum format, int i)
{
    static const int rgba[] = {0, 1, 2, 3}, bgra[] = {2, 1, 0, 3}, argb[] = {3, 0, 1, 2};
    switch (format) {
    case OSMESA_BGRA:
    case OSMESA_BGR:
        return bgra[i];
    case OSMESA_ARGB:
        return argb[i];
    default:
        return rgba[i];
    }
}

static int components(GLenum format)
{
    return format == OSMESA_RGB_565 ? 1 : (format == OSMESA_RGB || format == OSMESA_BGR) ? 3 : 4;
}

static int component_bytes(GLenum type)
{
    return type == GL_UNSIGNED_BYTE ? 1 : type == GL_FLOAT ? 4 : 2;
}

/* The bytes of one pixel of color c in format/type; returns the pixel size. */
static int encode(GLenum format, GLenum type, const float c[4], unsigned char *out)
{
    if (format == OSMESA_RGB_565) {
        unsigned short v = (unsigned short)(((long)(c[0] * 31.0f + 0.5f) << 11) | ((long)(c[1] * 63.0f + 0.5f) << 5) |
                                            (long)(c[2] * 31.0f + 0.5f));
        memcpy(out, &v, 2);
        return 2;
    }
    int n = components(format), size = component_bytes(type);
    for (int i = 0; i < n; i++) {
        float v = c[order(format, i)];
        if (type == GL_UNSIGNED_BYTE) {
            out[i] = (unsigned char)(v * 255.0f + 0.5f);
        } else if (type == GL_UNSIGNED_SHORT) {
            unsigned short s = (unsigned short)(v * 65535.0f + 0.5f);
            memcpy(out + 2 * i, &s, 2);
        } else {
            memcpy(out + 4 * i, &v, 4);
        }
    }
    return n * size;
}

static int accepted_by_spec(GLenum format, GLenum type)
{
    if (format == OSMESA_RGB_565)
        return type == GL_UNSIGNED_SHORT_5_6_5;
    return type != GL_UNSIGNED_SHORT_5_6_5;
}

static int mesa_writes_wrong_bytes(GLenum format, GLenum type, int scissored)
{
    return ((format == OSMESA_BGRA || format == OSMESA_ARGB) && (type == GL_UNSIGNED_SHORT || type == GL_FLOAT)) ||
           (format == OSMESA_RGB && type == GL_UNSIGNED_SHORT) ||
           (scissored && format == OSMESA_RGB && type == GL_UNSIGNED_BYTE);
}

static const float color_a[4] = {0.2f, 0.4f, 0.6f, 0.8f};
static const float color_b[4] = {1.0f, 0.0f, 128.0f / 255.0f, 17.0f / 255.0f};

static void run(int f, int t, int tessera)
{
    GLenum format = formats[f], type = types[t];
    char name[64];
    snprintf(name, sizeof name, "%s_%s", format_names[f], type_names[t]);

    OSMesaContext ctx = OSMesaCreateContextExt(format, 0, 0, 0, NULL);
    capi_check(ctx != NULL, "%s: OSMesaCreateContextExt failed", name);
    if (!ctx)
        return;
    size_t size = (size_t)W * H * 16 + GUARD;
    unsigned char *buffer = malloc(size);
    memset(buffer, 0xA5, size);
    GLboolean bound = OSMesaMakeCurrent(ctx, buffer, type, W, H);

    int expected_bound = accepted_by_spec(format, type);
    if (format == OSMESA_BGR) {
        /* Mesa 22 refuses BGR at MakeCurrent; tessera supports it (see the file comment). */
        capi_check(bound == (tessera ? expected_bound : 0), "%s: MakeCurrent returned %d", name, bound);
    } else {
        capi_check(bound == expected_bound, "%s: MakeCurrent returned %d", name, bound);
        capi_value(name, "bound=%d", bound);
    }

    if (bound) {
        unsigned char pa[16], pb[16];
        int bpp = encode(format, type, color_a, pa);
        encode(format, type, color_b, pb);
        enum capi_type ct = type == GL_UNSIGNED_BYTE ? CAPI_U8 : type == GL_FLOAT ? CAPI_F32 : CAPI_U16;

        /* A full clear, then a scissored one over it. */
        for (int scissored = 0; scissored < 2; scissored++) {
            if (scissored) {
                glEnable(GL_SCISSOR_TEST);
                glScissor(2, 1, 3, 2);
                glClearColor(color_b[0], color_b[1], color_b[2], color_b[3]);
            } else {
                glClearColor(color_a[0], color_a[1], color_a[2], color_a[3]);
            }
            glClear(GL_COLOR_BUFFER_BIT);
            glFinish();
            capi_check(glGetError() == GL_NO_ERROR, "%s: GL error", name);
            int mesa_wrong = mesa_writes_wrong_bytes(format, type, scissored);
            if (mesa_wrong && !tessera)
                continue;
            int wrong = 0;
            for (int y = 0; y < H && !wrong; y++)
                for (int x = 0; x < W && !wrong; x++) {
                    int inside = scissored && x >= 2 && x < 5 && y >= 1 && y < 3;
                    const unsigned char *got = buffer + ((size_t)y * W + x) * bpp;
                    if (memcmp(got, inside ? pb : pa, bpp) != 0) {
                        wrong = 1;
                        capi_check(0, "%s: pixel (%d,%d) has the wrong bytes (first byte %02x, expected %02x)%s", name,
                                   x, y, got[0], (inside ? pb : pa)[0], scissored ? " after the scissored clear" : "");
                    }
                }
            if (!mesa_wrong && format != OSMESA_BGR) {
                char image[80];
                snprintf(image, sizeof image, "%s%s", name, scissored ? "_scissored" : "_full");
                capi_save_image(image, W, H, components(format), ct, buffer);
            }
        }
        for (size_t i = (size_t)W * H * bpp; i < size; i++)
            if (buffer[i] != 0xA5) {
                capi_check(0, "%s: byte %zu after the buffer was written", name, i);
                break;
            }
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    } else {
        int touched = 0;
        for (size_t i = 0; i < size; i++)
            touched |= buffer[i] != 0xA5;
        capi_check(!touched, "%s: a refused MakeCurrent wrote into the buffer", name);
    }
    OSMesaDestroyContext(ctx);
    free(buffer);
}

int main(void)
{
    int tessera = capi_probe_is_tessera();
    for (int f = 0; f < 6; f++)
        for (int t = 0; t < 4; t++)
            run(f, t, tessera);
    return capi_finish();
}
