/* Scissored clears of every buffer (color, depth, stencil, alone and together), with
 * scissor boxes inside, overlapping the edges, far outside and empty, checked after every
 * step against a model through the caller's buffer and OSMesaGetDepthBuffer
 * (depth | stencil << 24, rows bottom-up).
 */
#include "common.h"

#define W 32
#define H 24

static unsigned char pixels[W * H * 4];
static unsigned char model_color[W * H * 4];
static unsigned int model_ds[W * H];
static OSMesaContext ctx;

struct clear {
    const char *name;
    int scissor;    /* scissor test on */
    int x, y, w, h; /* scissor box */
    GLbitfield mask;
    float color[4];
    double depth;
    int stencil;
};

static unsigned int depth24(double d)
{
    return (unsigned int)(d * 16777215.0 + 0.5);
}

static void apply(const struct clear *c)
{
    /* GL */
    if (c->scissor) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(c->x, c->y, c->w, c->h);
    } else {
        glDisable(GL_SCISSOR_TEST);
    }
    glClearColor(c->color[0], c->color[1], c->color[2], c->color[3]);
    glClearDepth(c->depth);
    glClearStencil(c->stencil);
    glClear(c->mask);
    glFinish();
    capi_check(glGetError() == GL_NO_ERROR, "%s: GL error", c->name);

    /* The model */
    int x0 = 0, y0 = 0, x1 = W, y1 = H;
    if (c->scissor) {
        x0 = c->x > 0 ? c->x : 0;
        y0 = c->y > 0 ? c->y : 0;
        x1 = c->x + c->w < W ? c->x + c->w : W;
        y1 = c->y + c->h < H ? c->y + c->h : H;
    }
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            int i = y * W + x;
            if (c->mask & GL_COLOR_BUFFER_BIT)
                for (int k = 0; k < 4; k++)
                    model_color[4 * i + k] = (unsigned char)(c->color[k] * 255.0f + 0.5f);
            if (c->mask & GL_DEPTH_BUFFER_BIT)
                model_ds[i] = (model_ds[i] & 0xff000000u) | depth24(c->depth);
            if (c->mask & GL_STENCIL_BUFFER_BIT)
                model_ds[i] = (model_ds[i] & 0x00ffffffu) | (unsigned)(c->stencil & 0xff) << 24;
        }

    /* Compare */
    for (int i = 0; i < W * H; i++)
        if (memcmp(pixels + 4 * i, model_color + 4 * i, 4) != 0) {
            capi_check(0, "%s: color at (%d,%d) is %02x%02x%02x%02x, expected %02x%02x%02x%02x", c->name, i % W, i / W,
                       pixels[4 * i], pixels[4 * i + 1], pixels[4 * i + 2], pixels[4 * i + 3], model_color[4 * i],
                       model_color[4 * i + 1], model_color[4 * i + 2], model_color[4 * i + 3]);
            break;
        }
    GLint w, h, bytes;
    unsigned int *ds = NULL;
    capi_check(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, (void **)&ds) && w == W && h == H && bytes == 4,
               "%s: no 24/8 depth buffer", c->name);
    if (ds) {
        for (int i = 0; i < W * H; i++)
            if (ds[i] != model_ds[i]) {
                capi_check(0, "%s: depth/stencil at (%d,%d) is 0x%08x, expected 0x%08x", c->name, i % W, i / W, ds[i],
                           model_ds[i]);
                break;
            }
    }
}

int main(void)
{
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H), "bind");
    static const struct clear steps[] = {
        {"everything", 0, 0, 0, 0, 0, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
         {0.0f, 0.0f, 0.0f, 1.0f}, 1.0, 0},
        {"color_inside", 1, 4, 3, 10, 6, GL_COLOR_BUFFER_BIT, {1.0f, 0.0f, 0.0f, 1.0f}, 0.0, 0},
        {"depth_lower_left_edge", 1, -5, -5, 10, 8, GL_DEPTH_BUFFER_BIT, {0, 0, 0, 0}, 0.5, 0},
        {"stencil_upper_right_edge", 1, 25, 18, 100, 100, GL_STENCIL_BUFFER_BIT, {0, 0, 0, 0}, 0.0, 0x33},
        {"empty_box", 1, 10, 10, 0, 5, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
         {1.0f, 1.0f, 1.0f, 1.0f}, 0.0, 0x77},
        {"outside_box", 1, 40, 30, 5, 5, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
         {1.0f, 1.0f, 1.0f, 1.0f}, 0.0, 0x77},
        {"negative_outside_box", 1, -20, -20, 10, 10, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, {1.0f, 1.0f, 1.0f, 1.0f},
         0.0, 0},
        {"all_three_inside", 1, 12, 12, 3, 3, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
         {0.0f, 1.0f, 0.0f, 0.5f}, 0.25, 0x44},
        {"single_pixel", 1, 31, 0, 1, 1, GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, {0.0f, 0.0f, 1.0f, 1.0f}, 0.0,
         0x1ff},
        {"color_depth_covering", 1, 0, 0, W, H, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT,
         {0.2f, 0.4f, 0.6f, 0.8f}, 0.75, 0},
        {"stencil_column", 1, 7, 0, 2, H, GL_STENCIL_BUFFER_BIT, {0, 0, 0, 0}, 0.0, 0x81},
        {"color_row", 1, 0, 20, W, 2, GL_COLOR_BUFFER_BIT, {1.0f, 1.0f, 0.0f, 1.0f}, 0.0, 0},
    };
    for (unsigned i = 0; i < sizeof steps / sizeof steps[0]; i++)
        apply(&steps[i]);
    capi_save_image("color", W, H, 4, CAPI_U8, pixels);
    GLint w, h, bytes;
    void *ds;
    if (OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &ds))
        capi_save_image("depth_stencil", W, H, 4, CAPI_U8, ds);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
