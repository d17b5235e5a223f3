/* Point sprites (GL 2.0 §3.3, ARB_point_sprite): with GL_POINT_SPRITE on, a point is the
 * square of its unrounded size (at least one pixel) whatever GL_POINT_SMOOTH says, and the
 * texture coordinates of every unit with GL_COORD_REPLACE vary over it, s from 0 at the left
 * to 1 at the right, t from 0 at the top (GL_UPPER_LEFT, the default) or at the bottom
 * (GL_POINT_SPRITE_COORD_ORIGIN GL_LOWER_LEFT), r = 0 and q = 1; units without it keep the
 * vertex's coordinates. Each case is an image compared with Mesa: sizes that are powers of
 * two and not, points on and off pixel centres, both origins, two units of which one
 * replaces, GL_POINT_SMOOTH on, a perspective projection, and sprites off again. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"

enum { W = 64, H = 64 };

static void checker_texture(GLuint name, int unit, int cells)
{
    enum { N = 16 };
    GLubyte texels[N * N * 4];
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            GLubyte *t = texels + 4 * (y * N + x);
            int on = ((x * cells / N) + (y * cells / N)) & 1;
            t[0] = (GLubyte)(x * 16), t[1] = (GLubyte)(y * 16), t[2] = on ? 255 : 0, t[3] = 255;
        }
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, N, N, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glEnable(GL_TEXTURE_2D);
}

/* Points of several sizes at and between pixel centres. */
static void draw_points(const char *name)
{
    glClearColor(0.2f, 0.2f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    const float sizes[6] = {16, 8, 11, 5.5f, 2.25f, 1};
    for (int i = 0; i < 6; i++) {
        glPointSize(sizes[i]);
        glBegin(GL_POINTS);
        glMultiTexCoord4f(GL_TEXTURE0, 0.3f, 0.6f, 0, 1);
        glMultiTexCoord4f(GL_TEXTURE1, 0.25f, 0.75f, 0, 1);
        glVertex2f(12.0f + 20 * (i % 3), 14.0f + 20 * (i / 3));
        glVertex2f(12.5f + 20 * (i % 3) + 0.25f, 22.5f + 20 * (i / 3) + 0.375f);
        glEnd();
    }
    capi_save_framebuffer(name, W, H);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    GLuint textures[2];
    glGenTextures(2, textures);
    checker_texture(textures[0], 0, 4);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    checker_texture(textures[1], 1, 2);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);

    draw_points("no_sprites");
    glEnable(GL_POINT_SPRITE);
    capi_value("sprite enabled", "%d", glIsEnabled(GL_POINT_SPRITE));
    draw_points("sprites_without_replace");
    glActiveTexture(GL_TEXTURE0);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    draw_points("sprites_unit0_replaces");
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    draw_points("sprites_lower_left");
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    glActiveTexture(GL_TEXTURE1);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    draw_points("sprites_both_replace");
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    draw_points("sprites_smooth_ignored");
    glDisable(GL_BLEND);
    glDisable(GL_POINT_SMOOTH);

    /* Perspective: the sprites' w is not 1. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT);
    glPointSize(12);
    glBegin(GL_POINTS);
    for (int i = 0; i < 4; i++)
        glVertex3f(-0.9f + 0.6f * i, 0.3f * i - 0.5f, -1.5f - 0.9f * i);
    glEnd();
    capi_save_framebuffer("sprites_perspective", W, H);
    glLoadIdentity();

    glDisable(GL_POINT_SPRITE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    draw_points("sprites_off_again");
    return capi_finish();
}
