/* Texture sampling against Mesa: every wrap mode with NEAREST and LINEAR on magnified and
 * minified quads, border texels and the border color, the six minification filters with
 * mipmap LOD selection on a receding plane (LOD bias, min/max LOD, base/max level,
 * GL_GENERATE_MIPMAP and glGenerateMipmap), non-power-of-two sizes, and 1D, 3D and cube map
 * textures. Every image is compared with Mesa. */
#include "common.h"

#define W 64
#define H 64

static unsigned rng = 12345;
static unsigned char rnd(void)
{
    rng = rng * 1103515245u + 12345u;
    return (unsigned char)(rng >> 16);
}

/* A w x h RGBA image of random texels. */
static unsigned char *random_image(int w, int h, int d)
{
    unsigned char *p = malloc((size_t)w * h * d * 4);
    for (int i = 0; i < w * h * d * 4; i++)
        p[i] = rnd();
    return p;
}

static void setup_ortho(void)
{
    capi_pixel_ortho(W, H);
    glClearColor(0.2f, 0.1f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
}

/* A screen-aligned quad from (x0, y0) to (x1, y1) with texture coordinates s0..s1, t0..t1. */
static void quad(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(s0, t0);
    glVertex2f(x0, y0);
    glTexCoord2f(s1, t0);
    glVertex2f(x1, y0);
    glTexCoord2f(s1, t1);
    glVertex2f(x1, y1);
    glTexCoord2f(s0, t1);
    glVertex2f(x0, y1);
    glEnd();
}

static const GLenum wraps[] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT};
static const char *wrap_names[] = {"repeat", "clamp", "edge", "border", "mirror"};

static void wrap_modes(void)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    unsigned char *img = random_image(4, 4, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    const GLfloat border[4] = {0.9f, 0.8f, 0.1f, 1.0f};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int f = 0; f < 2; f++) {
        GLenum filter = f ? GL_LINEAR : GL_NEAREST;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        for (int w = 0; w < 5; w++) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[w]);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[(w + 2) % 5]);
            setup_ortho();
            /* Magnified, then minified (a 64x64 texture-space area on 20x20 pixels). */
            quad(2, 2, 42, 42, -1.3f, -0.7f, 2.2f, 1.9f);
            quad(44, 2, 62, 20, -7.03f, -5.01f, 9.07f, 11.02f);
            quad(44, 24, 62, 62, 0.013f, 0.011f, 1.021f, 1.017f);
            char name[64];
            snprintf(name, sizeof name, "wrap_%s_%s", wrap_names[w], f ? "linear" : "nearest");
            capi_save_framebuffer(name, W, H);
        }
    }
    free(img);
    glDeleteTextures(1, &tex);
    glDisable(GL_TEXTURE_2D);
}

/* A texture with a 1-texel border of its own. GL_CLAMP and GL_CLAMP_TO_BORDER sample the
 * border texels (GL 2.1 §3.8.8); Mesa 22's gallium drivers strip texture borders at
 * specification and use the border color instead, so those two are checked on tessera only:
 * far outside the image, the lookup returns the border texel. Repeat, mirrored repeat and
 * clamp to edge never reach the border and are compared with Mesa. */
static void image_border(void)
{
    unsigned char *img = random_image(6, 6, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int w = 0; w < 5; w++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[w]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[w]);
        setup_ortho();
        quad(4, 4, 60, 60, -0.4f, -0.4f, 1.4f, 1.4f);
        if (wraps[w] == GL_CLAMP || wraps[w] == GL_CLAMP_TO_BORDER) {
            if (capi_is_tessera()) {
                unsigned char px[4];
                glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
                /* Texel (0, 0) of the image given is the border's bottom-left corner: alone far
                 * outside with CLAMP_TO_BORDER, blended half and half with its neighbours
                 * (8-bit lerps rounded) at the clamped corner with CLAMP. */
                for (int c = 0; c < 3; c++) {
                    int expect = img[c];
                    if (wraps[w] == GL_CLAMP) {
                        int a = img[c], b = img[4 + c], d = img[24 + c], e = img[28 + c];
                        int lo = a + (((b - a) * 128 + 128) >> 8), hi = d + (((e - d) * 128 + 128) >> 8);
                        expect = lo + (((hi - lo) * 128 + 128) >> 8);
                    }
                    capi_check(px[c] == expect, "%s: border texel channel %d: %d, expected %d", wrap_names[w], c,
                               px[c], expect);
                }
            }
            continue;
        }
        char name[64];
        snprintf(name, sizeof name, "image_border_%s", wrap_names[w]);
        capi_save_framebuffer(name, W, H);
    }
    free(img);
    glDisable(GL_TEXTURE_2D);
}

/* Levels of solid, distinct colors so the chosen level shows. */
static void solid_levels(int size)
{
    static const unsigned char colors[8][4] = {
        {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255},
        {0, 255, 255, 255}, {255, 0, 255, 255}, {255, 255, 255, 255}, {40, 40, 40, 255},
    };
    unsigned char *img = malloc((size_t)size * size * 4);
    for (int level = 0; size >> level; level++) {
        int s = size >> level;
        for (int i = 0; i < s * s; i++)
            memcpy(img + 4 * i, colors[level], 4);
        /* A darker checker so that the filter within the level shows too. */
        for (int i = 0; i < s * s; i++)
            if (((i % s) + (i / s)) % 2)
                img[4 * i + 3] = img[4 * i] = img[4 * i] / 2;
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    }
    free(img);
}

/* A floor receding from the viewer. */
static void receding_plane(void)
{
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 60);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.2f, 0.1f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glTexCoord2f(0.013f, 0.021f);
    glVertex3f(-4, -1, -1.2f);
    glTexCoord2f(6.029f, 0.021f);
    glVertex3f(4, -1, -1.2f);
    glTexCoord2f(6.029f, 40.017f);
    glVertex3f(4, -1, -50);
    glTexCoord2f(0.013f, 40.017f);
    glVertex3f(-4, -1, -50);
    glEnd();
}

static void mipmaps(void)
{
    static const GLenum mins[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                  GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
    static const char *names[] = {"nearest", "linear", "nn", "ln", "nl", "ll"};
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    solid_levels(32);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    char name[64];
    for (int m = 0; m < 6; m++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mins[m]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, m % 2 ? GL_LINEAR : GL_NEAREST);
        receding_plane();
        snprintf(name, sizeof name, "mip_%s", names[m]);
        capi_save_framebuffer(name, W, H);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    /* Biases: the texture's, the unit's, and min/max LOD, base/max level. */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.0f);
    receding_plane();
    capi_save_framebuffer("mip_bias_texture", W, H);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.0f);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.0f);
    receding_plane();
    capi_save_framebuffer("mip_bias_unit", W, H);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1.0f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 2.0f);
    receding_plane();
    capi_save_framebuffer("mip_min_max_lod", W, H);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000.0f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1000.0f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
    receding_plane();
    capi_save_framebuffer("mip_base_max_level", W, H);
    /* An incomplete texture (a level missing) disables texturing on the unit. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
    glTexImage2D(GL_TEXTURE_2D, 3, GL_RGBA, 3, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glColor3f(0.3f, 0.9f, 0.5f);
    receding_plane();
    capi_save_framebuffer("mip_incomplete", W, H);
    glColor3f(1, 1, 1);

    /* Generated mipmaps: GL_GENERATE_MIPMAP and glGenerateMipmap. */
    unsigned char *img = random_image(16, 16, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    receding_plane();
    capi_save_framebuffer("mip_generate", W, H);
    unsigned char level2[4 * 4 * 4];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 2, GL_RGBA, GL_UNSIGNED_BYTE, level2);
    capi_save_image("mip_generate_level2", 4, 4, 4, CAPI_U8, level2);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
    free(img);
    img = random_image(8, 8, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glGenerateMipmap(GL_TEXTURE_2D);
    receding_plane();
    capi_save_framebuffer("mip_generate_call", W, H);
    free(img);
    glDeleteTextures(1, &tex);
    glDisable(GL_TEXTURE_2D);
}

static void npot_1d_3d_cube(void)
{
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    /* Non-power-of-two 2D. */
    unsigned char *img = random_image(5, 3, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    setup_ortho();
    quad(2, 2, 62, 62, -0.5f, -0.5f, 1.5f, 1.5f);
    capi_save_framebuffer("npot", W, H);
    glDisable(GL_TEXTURE_2D);
    free(img);

    /* 1D. */
    img = random_image(8, 1, 1);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_1D);
    setup_ortho();
    quad(2, 2, 62, 62, -0.25f, 0, 1.25f, 1);
    capi_save_framebuffer("tex1d", W, H);
    glDisable(GL_TEXTURE_1D);
    free(img);

    /* 3D, a slanted slice. */
    img = random_image(4, 4, 4);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_3D);
    setup_ortho();
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, 0);
    glVertex2f(2, 2);
    glTexCoord3f(1, 0, 0.3f);
    glVertex2f(62, 2);
    glTexCoord3f(1, 1, 1);
    glVertex2f(62, 62);
    glTexCoord3f(0, 1, 0.6f);
    glVertex2f(2, 62);
    glEnd();
    capi_save_framebuffer("tex3d", W, H);
    glDisable(GL_TEXTURE_3D);
    free(img);

    /* Cube map: each face a solid color with a gradient, looked up with direction vectors. */
    GLuint cube;
    glGenTextures(1, &cube);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    for (int face = 0; face < 6; face++) {
        unsigned char f[4 * 4 * 4];
        for (int i = 0; i < 16; i++) {
            f[4 * i] = (unsigned char)(face * 40);
            f[4 * i + 1] = (unsigned char)(i * 16);
            f[4 * i + 2] = (unsigned char)(255 - face * 40);
            f[4 * i + 3] = 255;
        }
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, f);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_CUBE_MAP);
    setup_ortho();
    for (int i = 0; i < 6; i++) {
        float dir[6][3] = {{1, 0.3f, -0.2f}, {-1, 0.3f, 0.2f}, {0.2f, 1, 0.3f},
                           {0.2f, -1, -0.3f}, {0.3f, -0.2f, 1}, {-0.3f, 0.2f, -1}};
        float x = (float)(i % 3) * 21 + 1, y = (float)(i / 3) * 31 + 1;
        glBegin(GL_QUADS);
        glTexCoord3f(dir[i][0] * 1.0f, dir[i][1] - 0.37f, dir[i][2] - 0.39f);
        glVertex2f(x, y);
        glTexCoord3f(dir[i][0] * 1.0f, dir[i][1] + 0.41f, dir[i][2] - 0.39f);
        glVertex2f(x + 20, y);
        glTexCoord3f(dir[i][0] * 1.0f, dir[i][1] + 0.41f, dir[i][2] + 0.43f);
        glVertex2f(x + 20, y + 30);
        glTexCoord3f(dir[i][0] * 1.0f, dir[i][1] - 0.37f, dir[i][2] + 0.43f);
        glVertex2f(x, y + 30);
        glEnd();
    }
    capi_save_framebuffer("cube", W, H);
    glDisable(GL_TEXTURE_CUBE_MAP);
    glDeleteTextures(1, &cube);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    wrap_modes();
    image_border();
    mipmaps();
    npot_1d_3d_cube();
    return capi_finish();
}
