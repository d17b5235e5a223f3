/* GL_ARB_clip_control, compared with Mesa:
 *  - the GL_CLIP_ORIGIN / GL_CLIP_DEPTH_MODE queries, GL_INVALID_ENUM for bad values (nothing
 *    changes), GL_INVALID_OPERATION between glBegin and glEnd, GL_TRANSFORM_BIT push/pop, and
 *    glClipControl compiled into display lists;
 *  - a perspective scene drawn under each of the four combinations (color and depth);
 *  - culling under GL_UPPER_LEFT: the facing rule is mirrored with y, so a polygon
 *    counter-clockwise in normalized device coordinates stays front-facing;
 *  - clipping at z_c = 0 under GL_ZERO_TO_ONE (half of a triangle spanning z_ndc −1..1);
 *  - glRasterPos and glBitmap under each combination, polygon offset under GL_ZERO_TO_ONE;
 *    a raster position behind z_c = 0 is invalid under GL_ZERO_TO_ONE on tessera, as the
 *    spec says, and valid on Mesa 22 (its glRasterPos ignores the depth mode when clipping);
 *  - a reversed-Z scene in a framebuffer object with a GL_DEPTH_COMPONENT32F depth buffer:
 *    glClearDepth(0), GL_GREATER, GL_ZERO_TO_ONE and an infinite-far reversed projection,
 *    cards 1 unit apart at 2000 units (and some at 1e5, 50 apart, and a backdrop at 1e6):
 *    every pixel shows the nearest card whatever the drawing order, read-back depths are
 *    n/d. The same cards with a classic projection into a 24-bit depth buffer z-fight
 *    (checked: some pixels show a farther card).
 * Both tessera and llvmpipe store GL_DEPTH_COMPONENT32F as float (ARB_depth_buffer_float,
 * capi depth_buffer_float), and the read-back depths agree exactly. */
#include "common.h"

#define W 64
#define H 64
#define FW 128
#define FH 128

static PFNGLCLIPCONTROLPROC clip_control;

static const GLenum origins[2] = {GL_LOWER_LEFT, GL_UPPER_LEFT};
static const GLenum depths[2] = {GL_NEGATIVE_ONE_TO_ONE, GL_ZERO_TO_ONE};
static const char *origin_names[2] = {"lower_left", "upper_left"};
static const char *depth_names[2] = {"neg_one_to_one", "zero_to_one"};

static void save_depth(const char *name, int w, int h)
{
    static GLfloat depth[FW * FH];
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    capi_save_image(name, w, h, 1, CAPI_F32, depth);
}

static void query(const char *stage)
{
    capi_value_query(stage, "clip_origin", GL_CLIP_ORIGIN, 1);
    capi_value_query(stage, "clip_depth_mode", GL_CLIP_DEPTH_MODE, 1);
}

static void expect_clip(GLenum origin, GLenum depth, const char *what)
{
    GLint o = 0, d = 0;
    glGetIntegerv(GL_CLIP_ORIGIN, &o);
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &d);
    capi_check((GLenum)o == origin && (GLenum)d == depth, "%s: origin 0x%x depth 0x%x", what, o, d);
}

static void state_and_errors(void)
{
    query("initial");
    expect_clip(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE, "initial");

    clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    capi_expect_error(GL_NO_ERROR, "valid");
    query("set");
    expect_clip(GL_UPPER_LEFT, GL_ZERO_TO_ONE, "set");

    clip_control(GL_ZERO_TO_ONE, GL_ZERO_TO_ONE);
    capi_expect_error(GL_INVALID_ENUM, "bad origin");
    clip_control(GL_LOWER_LEFT, GL_LOWER_LEFT);
    capi_expect_error(GL_INVALID_ENUM, "bad depth");
    clip_control(GL_POINT_SPRITE_COORD_ORIGIN, GL_NEGATIVE_ONE_TO_ONE);
    capi_expect_error(GL_INVALID_ENUM, "bad origin, good depth");
    expect_clip(GL_UPPER_LEFT, GL_ZERO_TO_ONE, "unchanged by errors");

    glBegin(GL_TRIANGLES);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glEnd();
    capi_expect_error(GL_INVALID_OPERATION, "inside glBegin/glEnd");
    expect_clip(GL_UPPER_LEFT, GL_ZERO_TO_ONE, "unchanged inside glBegin/glEnd");

    /* Part of GL_TRANSFORM_BIT, not of GL_VIEWPORT_BIT. */
    glPushAttrib(GL_TRANSFORM_BIT);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    query("pushed");
    glPopAttrib();
    query("popped");
    expect_clip(GL_UPPER_LEFT, GL_ZERO_TO_ONE, "restored by GL_TRANSFORM_BIT");
    glPushAttrib(GL_VIEWPORT_BIT | GL_POLYGON_BIT);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glPopAttrib();
    expect_clip(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE, "not in GL_VIEWPORT_BIT");

    /* glClipControl is compiled into display lists (as in Mesa 22). */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    clip_control(GL_UPPER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glEndList();
    query("after_compile");
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glCallList(list);
    query("after_call");
    glDeleteLists(list, 1);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    capi_expect_error(GL_NO_ERROR, "state section");
}

static void perspective(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* An asymmetric scene: a smooth triangle going into the distance, a tilted quad through it
 * and a line and points, so that a flip of y or a change of the depth mapping shows. */
static void scene(void)
{
    glClearColor(0.1f, 0.1f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(-1.2f, -1.0f, -1.1f);
    glColor3f(0, 1, 0);
    glVertex3f(1.0f, -0.6f, -4.5f);
    glColor3f(0, 0, 1);
    glVertex3f(-0.3f, 1.4f, -2.5f);
    glEnd();
    glBegin(GL_QUADS);
    glColor3f(1, 1, 0);
    glVertex3f(-0.8f, -0.2f, -1.5f);
    glVertex3f(0.9f, -0.3f, -3.5f);
    glColor3f(0, 1, 1);
    glVertex3f(0.9f, 0.6f, -3.5f);
    glVertex3f(-0.8f, 0.5f, -1.5f);
    glEnd();
    glBegin(GL_LINES);
    glColor3f(1, 1, 1);
    glVertex3f(-1.0f, 0.8f, -1.2f);
    glVertex3f(0.7f, 0.9f, -4.0f);
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    glColor3f(1, 0, 1);
    glVertex3f(0.5f, -0.9f, -2.0f);
    glVertex3f(-0.6f, 0.2f, -1.05f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
}

static void four_combinations(void)
{
    perspective();
    for (int o = 0; o < 2; o++) {
        for (int d = 0; d < 2; d++) {
            char name[64];
            clip_control(origins[o], depths[d]);
            scene();
            snprintf(name, sizeof name, "scene_%s_%s", origin_names[o], depth_names[d]);
            capi_save_framebuffer(name, W, H);
            snprintf(name, sizeof name, "scene_%s_%s_depth", origin_names[o], depth_names[d]);
            save_depth(name, W, H);
        }
    }
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

static void read_rgb(int x, int y, GLubyte out[3])
{
    GLubyte p[4];
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    memcpy(out, p, 3);
}

/* A counter-clockwise (in NDC) red triangle on the left, a clockwise green one on the right,
 * both in the upper half of NDC, with back faces culled. */
static void culling(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    for (int o = 0; o < 2; o++) {
        for (int front = 0; front < 2; front++) {
            char name[64];
            clip_control(origins[o], GL_NEGATIVE_ONE_TO_ONE);
            glFrontFace(front ? GL_CW : GL_CCW);
            glClearColor(0, 0, 0, 1);
            glClear(GL_COLOR_BUFFER_BIT);
            glBegin(GL_TRIANGLES);
            glColor3f(1, 0, 0);
            glVertex2f(-0.9f, 0.1f);
            glVertex2f(-0.1f, 0.1f);
            glVertex2f(-0.5f, 0.9f);
            glColor3f(0, 1, 0);
            glVertex2f(0.1f, 0.1f);
            glVertex2f(0.5f, 0.9f);
            glVertex2f(0.9f, 0.1f);
            glEnd();
            snprintf(name, sizeof name, "cull_%s_%s", origin_names[o], front ? "cw" : "ccw");
            capi_save_framebuffer(name, W, H);
            /* NDC (±0.5, 0.4) is window y 44 under GL_LOWER_LEFT, 19 under GL_UPPER_LEFT. */
            int y = o ? 19 : 44;
            GLubyte left[3], right[3];
            read_rgb(16, y, left);
            read_rgb(48, y, right);
            int red_shown = left[0] == 255, green_shown = right[1] == 255;
            capi_check(red_shown == !front && green_shown == front,
                       "%s front %s: red %d green %d (the facing rule follows NDC winding)",
                       origin_names[o], front ? "cw" : "ccw", red_shown, green_shown);
            /* The mirrored half stays empty. */
            read_rgb(16, o ? 44 : 19, left);
            capi_check(left[0] == 0 && left[1] == 0, "%s: nothing in the mirrored half", origin_names[o]);
        }
    }
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

/* A triangle whose z_ndc runs from −1 at the left edge to 1 at the right: under
 * GL_ZERO_TO_ONE the left half (z_c < 0) is clipped away, by default nothing is. */
static void z_zero_clipping(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    for (int d = 0; d < 2; d++) {
        char name[64];
        clip_control(GL_LOWER_LEFT, depths[d]);
        glClearColor(0, 0, 0, 1);
        glClearDepth(1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glColor3f(1, 1, 1);
        glBegin(GL_TRIANGLES);
        glVertex3f(-1, -1, -1);
        glVertex3f(1, -1, 1);
        glVertex3f(1, 1, 1);
        glVertex3f(-1, -1, -1);
        glVertex3f(1, 1, 1);
        glVertex3f(-1, 1, -1);
        glEnd();
        snprintf(name, sizeof name, "zclip_%s", depth_names[d]);
        capi_save_framebuffer(name, W, H);
        snprintf(name, sizeof name, "zclip_%s_depth", depth_names[d]);
        save_depth(name, W, H);
        GLubyte left[3], right[3];
        read_rgb(10, 32, left);
        read_rgb(54, 32, right);
        capi_check(right[0] == 255, "%s: right half drawn", depth_names[d]);
        capi_check((left[0] == 255) == (d == 0), "%s: left half %s", depth_names[d], d ? "clipped" : "drawn");
        /* Pixel 32's centre is at z_ndc = 1/64: depth n + 1/64 = 1/64 under ZERO_TO_ONE,
         * 0.5 + 1/128 by default. */
        GLfloat z;
        glReadPixels(32, 32, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
        GLfloat expected = d ? 1.0f / 64 : 0.5f + 1.0f / 128;
        capi_check(z > expected - 1e-4f && z < expected + 1e-4f, "%s: depth at z_ndc 0 is %g", depth_names[d], z);
    }
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

/* z_ndc of (0, 0, −1.2) under the frustum is ≈ −0.583: valid by default, clipped under
 * GL_ZERO_TO_ONE (ARB_clip_control: the raster position is clipped as a vertex). Mesa 22
 * keeps it valid (see raster_and_offset): checked on tessera only. */
static void raster_behind_z_zero(void)
{
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glRasterPos3f(0, 0, -1.2f);
    GLint valid = -1;
    glGetIntegerv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    if (capi_is_tessera())
        capi_check(valid == 0, "raster position behind z_c = 0 is invalid under GL_ZERO_TO_ONE");
    glRasterPos3f(0, 0, -3);
    glGetIntegerv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    capi_check(valid == 1, "raster position in front of z_c = 0 is valid under GL_ZERO_TO_ONE");
    GLfloat pos[4];
    glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
    /* z_ndc = (1.5 · 3 − 2.5) / 3 = 2/3, so window z = 2/3 with the default depth range. */
    capi_check(pos[2] > 0.6666f && pos[2] < 0.6667f, "raster z under GL_ZERO_TO_ONE: %g", pos[2]);
}

/* glRasterPos goes through the clip-space conventions; glBitmap draws from there upwards in
 * window coordinates; glWindowPos is unaffected. A steep polygon with offset shows the
 * doubled depth slope of GL_ZERO_TO_ONE. */
static void raster_and_offset(void)
{
    static const GLubyte bits[8] = {0xff, 0x81, 0x81, 0xf1, 0x81, 0x81, 0x81, 0xff};
    perspective();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int o = 0; o < 2; o++) {
        for (int d = 0; d < 2; d++) {
            char key[64];
            clip_control(origins[o], depths[d]);
            glClearColor(0, 0, 0, 1);
            glClear(GL_COLOR_BUFFER_BIT);
            glColor3f(1, 1, 0);
            glRasterPos3f(-0.5f, 0.5f, -2);
            snprintf(key, sizeof key, "raster_%s_%s", origin_names[o], depth_names[d]);
            capi_value_query(key, "position", GL_CURRENT_RASTER_POSITION, 4);
            capi_value_query(key, "valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
            glBitmap(8, 8, 0, 0, 10, -3, bits);
            glBitmap(8, 8, 0, 0, 0, 0, bits);
            capi_value_query(key, "moved", GL_CURRENT_RASTER_POSITION, 4);
            /* z_ndc ≈ −0.583: inside by default, behind z_c = 0 under GL_ZERO_TO_ONE, where
             * Mesa 22 does not clip the raster position (its rastpos.c tests z_c ≥ −w_c
             * whatever the depth mode) and maps it to window z = −0.583 outside the depth
             * range; the spec clips it like any vertex (checked in raster_behind_z_zero). */
            glRasterPos3f(0, 0, -1.2f);
            if (d == 0) {
                capi_value_query(key, "near_position", GL_CURRENT_RASTER_POSITION, 4);
                capi_value_query(key, "near_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
            }
            glWindowPos3f(5, 6, 0.25f);
            capi_value_query(key, "window_pos", GL_CURRENT_RASTER_POSITION, 4);
            snprintf(key, sizeof key, "bitmap_%s_%s", origin_names[o], depth_names[d]);
            capi_save_framebuffer(key, W, H);
        }
    }
    raster_behind_z_zero();

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2, 4);
    for (int d = 0; d < 2; d++) {
        char name[64];
        clip_control(GL_UPPER_LEFT, depths[d]);
        glClearDepth(1);
        glClear(GL_DEPTH_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        glVertex3f(-1, -1, -1.5f);
        glVertex3f(1, -0.5f, -4);
        glVertex3f(0, 1, -2);
        glEnd();
        snprintf(name, sizeof name, "offset_%s_depth", depth_names[d]);
        save_depth(name, W, H);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

/* Cards facing the viewer: card i at distance dist[i] spans NDC x from left[i] to 0.9, so in
 * the strip in front of each card's left edge only farther cards lie behind it. */
#define CARDS 20
static float dist[CARDS];
static float left_edge[CARDS];

static void card_color(int i, GLubyte c[3])
{
    c[0] = (GLubyte)(40 + i * 11);
    c[1] = (GLubyte)(250 - i * 12);
    c[2] = (GLubyte)((i * 73) % 256);
}

static void setup_cards(void)
{
    /* 16 cards 1 unit apart at 2000 (nearest first), 3 at 1e5 (50 apart), a backdrop at 1e6. */
    for (int i = 0; i < 16; i++)
        dist[i] = 2000.0f + i;
    for (int i = 0; i < 3; i++)
        dist[16 + i] = 100000.0f + 50.0f * i;
    dist[19] = 1000000.0f;
    for (int i = 0; i < CARDS; i++)
        left_edge[i] = i == CARDS - 1 ? -1.0f : 0.8f - 0.09f * i;
}

static void draw_card(int i)
{
    GLubyte c[3];
    card_color(i, c);
    glColor3ubv(c);
    /* Eye x = x_ndc · d with a 90° field of view. */
    float d = dist[i];
    glBegin(GL_QUADS);
    glVertex3f(left_edge[i] * d, -0.8f * d, -d);
    glVertex3f(0.95f * d, -0.8f * d, -d);
    glVertex3f(0.95f * d, 0.8f * d, -d);
    glVertex3f(left_edge[i] * d, 0.8f * d, -d);
    glEnd();
}

/* Draws the cards in an order interleaving far-before-near and near-before-far. */
static void draw_cards(int far_to_near_only)
{
    if (far_to_near_only) {
        for (int i = CARDS - 1; i >= 0; i--)
            draw_card(i);
        return;
    }
    for (int k = 0; k < CARDS; k++)
        draw_card(k % 2 ? CARDS - 1 - k / 2 : k / 2);
}

/* The number of pixels (of the card rows) not showing the nearest card covering them. */
static int wrong_pixels(int w, int h)
{
    static GLubyte px[FW * FH * 4];
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    int wrong = 0;
    for (int y = h / 4; y < 3 * h / 4; y++) {
        for (int x = 0; x < w; x++) {
            float xn = (x + 0.5f) * 2.0f / w - 1.0f;
            if (xn >= 0.95f)
                continue;
            int nearest = -1;
            for (int i = 0; i < CARDS && nearest < 0; i++)
                if (xn >= left_edge[i])
                    nearest = i;
            /* Pixels at a card's edge may belong to either card. */
            if (nearest < 0 || (nearest < CARDS - 1 && xn - left_edge[nearest] < 2.0f / w))
                continue;
            GLubyte c[3];
            card_color(nearest, c);
            const GLubyte *p = px + 4 * (y * w + x);
            wrong += p[0] != c[0] || p[1] != c[1] || p[2] != c[2];
        }
    }
    return wrong;
}

static void reversed_z(void)
{
    setup_cards();
    GLuint fb, color, depth;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    capi_check(status == GL_FRAMEBUFFER_COMPLETE, "float depth FBO complete (0x%x)", status);
    capi_expect_error(GL_NO_ERROR, "float depth FBO");
    glViewport(0, 0, FW, FH);

    /* Infinite-far reversed projection for z_ndc in [0, 1]: z_c = n, w_c = −z_e, so
     * z_ndc = n / d, 1 at the near plane and → 0 at infinity. */
    const float n = 0.1f;
    const GLfloat reversed[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1, 0, 0, n, 0};
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(reversed);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    for (int order = 0; order < 2; order++) {
        glClearColor(0, 0, 0, 1);
        glClearDepth(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        draw_cards(order);
        int wrong = wrong_pixels(FW, FH);
        capi_check(wrong == 0, "reversed float depth, order %d: %d pixels show a farther card", order, wrong);
        if (order == 0) {
            capi_save_framebuffer("reversed_z_color", FW, FH);
            save_depth("reversed_z_depth", FW, FH);
            /* The depth of card i is n / d_i. */
            for (int i = 0; i < CARDS; i += 3) {
                int x = (int)(((left_edge[i] + 0.05f) * 0.5f + 0.5f) * FW);
                GLfloat z;
                glReadPixels(x, FH / 2, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
                float expected = n / dist[i];
                capi_check(z > expected * 0.9999f && z < expected * 1.0001f, "card %d depth %g, expected %g", i, z,
                           expected);
            }
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(1, &color);
    glDeleteRenderbuffers(1, &depth);

    /* The classic way into the 24-bit window depth buffer: near 0.1, far 1e7, GL_LESS, drawn
     * far to near. Cards 1 unit apart at 2000 share depth values and the nearer loses. */
    glViewport(0, 0, W, H);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-n, n, -n, n, n, 1e7);
    glMatrixMode(GL_MODELVIEW);
    glDepthFunc(GL_LESS);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw_cards(1);
    int wrong = wrong_pixels(W, H);
    capi_check(wrong > 0, "classic 24-bit depth z-fights: %d wrong pixels", wrong);
    glDisable(GL_DEPTH_TEST);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    const char *extensions = (const char *)glGetString(GL_EXTENSIONS);
    capi_check(strstr(extensions, "GL_ARB_clip_control") != NULL, "GL_ARB_clip_control listed");
    clip_control = (PFNGLCLIPCONTROLPROC)OSMesaGetProcAddress("glClipControl");
    capi_check(clip_control != NULL, "glClipControl");
    if (!clip_control)
        return capi_finish();
    state_and_errors();
    four_combinations();
    culling();
    z_zero_clipping();
    raster_and_offset();
    reversed_z();
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
