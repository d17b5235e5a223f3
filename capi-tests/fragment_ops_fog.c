/* Fog and the color sum on a perspective floor: LINEAR, EXP and EXP2 with the eye-plane
 * (absolute and signed) and radial distances and the fog coordinate source, the color sum
 * of a secondary color under fog, GL_FOG_HINT NICEST vs FASTEST, and fogged lines and
 * points. Every image is compared with Mesa. */
#include "common.h"

#define W 96
#define H 64

/* Primary + secondary stays below 1 in every compared image: where the sum saturates, Mesa 22
 * (llvmpipe and softpipe) fogs the unclamped sum, while GL 2.1 §3.10 clamps it to [0, 1]
 * first, as tessera does (checked separately by saturated_sum_is_clamped). */

/* A floor from z = -1 (near) to z = -40 (far), seen through a frustum, with a color
 * gradient, a secondary color and a fog coordinate varying across it. */
static void floor_quad(void)
{
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.2f, 0.1f);
    glSecondaryColor3f(0.0f, 0.3f, 0.1f);
    glFogCoordf(0.5f);
    glVertex3f(-6, -1, -0.5f);
    glColor3f(0.4f, 0.6f, 0.1f);
    glSecondaryColor3f(0.5f, 0.0f, 0.2f);
    glFogCoordf(1.5f);
    glVertex3f(6, -1, -0.5f);
    glColor3f(0.2f, 0.3f, 0.9f);
    glSecondaryColor3f(0.1f, 0.6f, 0.0f);
    glFogCoordf(30.0f);
    glVertex3f(6, -1, -40);
    glColor3f(0.5f, 0.5f, 0.5f);
    glSecondaryColor3f(0.4f, 0.4f, 0.4f);
    glFogCoordf(10.0f);
    glVertex3f(-6, -1, -40);
    glEnd();
}

static void setup(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.7, 0.7, 1, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* Shifted sideways so that the radial distance differs from the plane distance. */
    glTranslatef(1.5f, 0, 0);
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_FOG);
    const GLfloat color[4] = {0.6f, 0.65f, 0.8f, 1.0f};
    glFogfv(GL_FOG_COLOR, color);
}

static void draw_case(const char *name, GLenum mode, GLenum src, GLenum distance, int sum)
{
    setup();
    glFogi(GL_FOG_MODE, mode);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 30.0f);
    glFogf(GL_FOG_DENSITY, mode == GL_EXP ? 0.08f : 0.05f);
    glFogi(GL_FOG_COORD_SRC, src);
    glFogi(GL_FOG_DISTANCE_MODE_NV, distance);
    if (sum)
        glEnable(GL_COLOR_SUM);
    else
        glDisable(GL_COLOR_SUM);
    floor_quad();
    capi_save_framebuffer(name, W, H);
}

/* A saturating color sum under fog: 0.8 + 0.5 red, fog factor 0.5 towards black. GL clamps
 * the sum to 1 before fog (0.5 → 128); Mesa 22 fogs 1.3 (0.65 → 166), a Mesa bug. */
static void saturated_sum_is_clamped(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_FOG);
    glEnable(GL_COLOR_SUM);
    const GLfloat black[4] = {0, 0, 0, 1};
    glFogfv(GL_FOG_COLOR, black);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0);
    glFogf(GL_FOG_END, 1);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glPointSize(1);
    glBegin(GL_POINTS);
    glColor3f(0.8f, 0, 0);
    glSecondaryColor3f(0.5f, 0, 0);
    glFogCoordf(0.5f);
    glVertex2f(0.5f, 0.5f);
    glEnd();
    unsigned char px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    int expected = capi_is_tessera() ? 128 : 166;
    capi_check(abs(px[0] - expected) <= 1, "saturated color sum under fog: red %d, expected %d", px[0], expected);
    glDisable(GL_COLOR_SUM);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 16, 0, 0, W, H, NULL);
    draw_case("linear_plane_abs", GL_LINEAR, GL_FRAGMENT_DEPTH, GL_EYE_PLANE_ABSOLUTE_NV, 0);
    draw_case("exp_plane_abs", GL_EXP, GL_FRAGMENT_DEPTH, GL_EYE_PLANE_ABSOLUTE_NV, 0);
    draw_case("exp2_radial", GL_EXP2, GL_FRAGMENT_DEPTH, GL_EYE_RADIAL_NV, 0);
    draw_case("linear_radial", GL_LINEAR, GL_FRAGMENT_DEPTH, GL_EYE_RADIAL_NV, 0);
    /* Signed eye z is negative in front of the eye: LINEAR fog factors above 1, no fog. */
    draw_case("linear_plane_signed", GL_LINEAR, GL_FRAGMENT_DEPTH, GL_EYE_PLANE, 0);
    draw_case("exp_plane_signed", GL_EXP, GL_FRAGMENT_DEPTH, GL_EYE_PLANE, 0);
    draw_case("linear_coord", GL_LINEAR, GL_FOG_COORD, GL_EYE_PLANE_ABSOLUTE_NV, 0);
    draw_case("exp2_coord", GL_EXP2, GL_FOG_COORD, GL_EYE_PLANE_ABSOLUTE_NV, 0);
    draw_case("linear_plane_sum", GL_LINEAR, GL_FRAGMENT_DEPTH, GL_EYE_PLANE_ABSOLUTE_NV, 1);
    draw_case("exp_coord_sum", GL_EXP, GL_FOG_COORD, GL_EYE_PLANE_ABSOLUTE_NV, 1);

    /* The color sum without fog, saturating (clamped before fog on fixed-point buffers). */
    setup();
    glDisable(GL_FOG);
    glEnable(GL_COLOR_SUM);
    floor_quad();
    capi_save_framebuffer("sum_only", W, H);
    glDisable(GL_COLOR_SUM);

    /* GL_FOG_HINT: a large EXP-fogged triangle under NICEST and FASTEST must match Mesa. */
    unsigned char nicest[W * H * 4], fastest[W * H * 4];
    glHint(GL_FOG_HINT, GL_NICEST);
    draw_case("exp_hint_nicest", GL_EXP, GL_FRAGMENT_DEPTH, GL_EYE_RADIAL_NV, 0);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, nicest);
    glHint(GL_FOG_HINT, GL_FASTEST);
    draw_case("exp_hint_fastest", GL_EXP, GL_FRAGMENT_DEPTH, GL_EYE_RADIAL_NV, 0);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, fastest);
    capi_value("hint_images_equal", "%d", memcmp(nicest, fastest, sizeof nicest) == 0);
    glHint(GL_FOG_HINT, GL_DONT_CARE);

    /* Fog at the unfogged reference color must change the image (the test can fail). */
    setup();
    glDisable(GL_FOG);
    floor_quad();
    unsigned char plain[W * H * 4];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, plain);
    capi_check(memcmp(plain, nicest, sizeof plain) != 0, "fog changes the floor");

    /* Lines and points, fogged by eye distance and by fog coordinate, with the color sum. */
    setup();
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 1.0f);
    glFogf(GL_FOG_END, 25.0f);
    glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE_ABSOLUTE_NV);
    glEnable(GL_COLOR_SUM);
    glBegin(GL_LINES);
    for (int i = 0; i < 8; i++) {
        glColor3f(1, 0.1f * i, 0);
        glSecondaryColor3f(0, 0, 0.1f * i);
        glVertex3f(-5 + i, -0.8f, -1.5f);
        glColor3f(0, 1, 0.05f * i);
        glVertex3f(-5 + i, 0.5f, -35);
    }
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    for (int i = 0; i < 10; i++) {
        glColor3f(0.5f, 1, 0.1f * i);
        glSecondaryColor3f(0.05f * i, 0, 0);
        glVertex3f(3, 0.3f, -2.0f - 3.0f * i);
    }
    glEnd();
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glSecondaryColor3f(0, 0.1f, 0);
    glBegin(GL_LINES);
    glColor3f(0.9f, 0.8f, 0.7f);
    glFogCoordf(0);
    glVertex3f(-5, 1, -3);
    glFogCoordf(25);
    glVertex3f(5, 1, -3);
    glEnd();
    glBegin(GL_POINTS);
    for (int i = 0; i < 10; i++) {
        glFogCoordf(2.5f * i);
        glVertex3f(-4 + i, 0.0f, -4);
    }
    glEnd();
    capi_save_framebuffer("lines_points", W, H);
    saturated_sum_is_clamped();
    return capi_finish();
}
