/* Texture parameters changed between draws of one frame: each draw samples with the
 * parameters current when it was issued, though the draws are rendered together later
 * (piglit texwrap draws its wrap modes side by side with nothing but glTexParameter between
 * them). Wrap modes, the border colour, filters and the LOD bias change from draw to draw,
 * with fixed-function texturing and with a GLSL fragment shader; every image is compared
 * with Mesa, and a few pixels are checked against the texel they must show. */
#include "common.h"

#define W 96
#define H 32

static void setup_ortho(void)
{
    capi_pixel_ortho(W, H);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
}

/* A 16x16 quad at (x, 8) showing texture coordinates -1.25 .. 2.25. */
static void tile(float x)
{
    glBegin(GL_QUADS);
    glTexCoord2f(-1.25f, -1.25f);
    glVertex2f(x, 8);
    glTexCoord2f(2.25f, -1.25f);
    glVertex2f(x + 16, 8);
    glTexCoord2f(2.25f, 2.25f);
    glVertex2f(x + 16, 24);
    glTexCoord2f(-1.25f, 2.25f);
    glVertex2f(x, 24);
    glEnd();
}

/* A 4x4 texture: red lower-left texel, the others white and black in a checkerboard;
 * with its mipmaps generated when `mipmaps`. */
static GLuint make_texture(int mipmaps)
{
    unsigned char img[4 * 4 * 4];
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            unsigned char *p = &img[(y * 4 + x) * 4];
            int white = (x + y) & 1;
            p[0] = (x == 0 && y == 0) || white ? 255 : 0;
            p[1] = p[2] = white ? 255 : 0;
            p[3] = 255;
        }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, mipmaps ? GL_TRUE : GL_FALSE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    return tex;
}

static const GLenum wraps[] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT};

/* The five wrap modes side by side in one frame, then a border colour change. */
static void draw_wrap_row(const char *name)
{
    const GLfloat green[4] = {0, 1, 0, 1}, blue[4] = {0, 0, 1, 1};
    setup_ortho();
    for (int w = 0; w < 5; w++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[w]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[w]);
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, w == 3 ? blue : green);
        tile(2 + 18 * w);
    }
    unsigned char px[4];
    /* The lower-left corner of each tile: texel (1, 1) repeated (black), the red texel
     * clamped, the red texel clamped to the edge, the blue border, texel (2, 2) mirrored
     * (black). */
    static const unsigned char want[5][3] = {{0, 0, 0}, {255, 0, 0}, {255, 0, 0}, {0, 0, 255}, {0, 0, 0}};
    for (int w = 0; w < 5; w++) {
        glReadPixels(2 + 18 * w, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        capi_check(px[0] == want[w][0] && px[1] == want[w][1] && px[2] == want[w][2],
                   "%s: wrap mode %d corner is (%d, %d, %d)", name, w, px[0], px[1], px[2]);
    }
    capi_save_framebuffer(name, W, H);
}

static void fixed_function(void)
{
    GLuint tex = make_texture(0);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int f = 0; f < 2; f++) {
        GLenum filter = f ? GL_LINEAR : GL_NEAREST;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        if (f == 0) {
            draw_wrap_row("ff_wrap_nearest");
        } else {
            /* LINEAR: only the unchecked image (edges blend). */
            setup_ortho();
            for (int w = 0; w < 5; w++) {
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[w]);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[(w + 1) % 5]);
                tile(2 + 18 * w);
            }
            capi_save_framebuffer("ff_wrap_linear", W, H);
        }
    }
    /* Filters and the LOD bias changed between two draws of a minified, mipmapped quad. */
    glDeleteTextures(1, &tex);
    tex = make_texture(1);
    setup_ortho();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    static const GLenum mins[] = {GL_NEAREST, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR};
    for (int m = 0; m < 3; m++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mins[m]);
        for (int b = 0; b < 2; b++) {
            glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, b ? 1.0f : 0.0f);
            float x = 2 + 16 * (m * 2 + b);
            glBegin(GL_QUADS);
            glTexCoord2f(0, 0);
            glVertex2f(x, 8);
            glTexCoord2f(3, 0);
            glVertex2f(x + 14, 8);
            glTexCoord2f(3, 3);
            glVertex2f(x + 14, 22);
            glTexCoord2f(0, 3);
            glVertex2f(x, 22);
            glEnd();
        }
    }
    capi_save_framebuffer("ff_filters_bias", W, H);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &tex);
}

static void glsl(void)
{
    static const char *vs = "void main() { gl_TexCoord[0] = gl_MultiTexCoord0; gl_Position = ftransform(); }";
    static const char *fs = "uniform sampler2D t; void main() { gl_FragColor = texture2D(t, gl_TexCoord[0].xy); }";
    GLuint prog = capi_program("glsl", vs, fs);
    glUseProgram(prog);
    GLuint tex = make_texture(0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    draw_wrap_row("glsl_wrap_nearest");
    glUseProgram(0);
    glDeleteProgram(prog);
    glDeleteTextures(1, &tex);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    fixed_function();
    glsl();
    capi_expect_error(GL_NO_ERROR, "after every draw");
    return capi_finish();
}
