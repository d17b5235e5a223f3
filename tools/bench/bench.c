/* The benchmark program behind tools/bench.sh: renders a fixed set of scenes through OSMesa
 * and prints, per scene, the time of each repeated frame. Built once against the system's
 * Mesa headers and run once per implementation (LD_LIBRARY_PATH picks tessera or Mesa).
 *
 *   bench <out-dir> <repetitions> <size> [scene]   (only the scenes whose name starts with scene)
 *   bench --compare <reference.rgba> <image.rgba>   (no GL: prints the error of an image)
 *
 * Output lines (stdout):
 *   context <ms>          context creation + bind + first clear + glFinish
 *   first_frame <ms>      the same plus the first frame of the flat scene, from process start
 *                         of the measurement (so it includes context creation)
 *   scene <name> <pixels> <ms> <ms> ...   one time per repetition, after one warm-up frame
 * Each scene's last frame is written to <out-dir>/<name>.rgba (raw RGBA8, bottom row first).
 */
#define _POSIX_C_SOURCE 199309L
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static int W = 1024, H = 1024;
static unsigned char *pixels;

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

/* A deterministic generator so that every implementation draws the same scene. */
static unsigned rng_state = 12345u;
static float rnd(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (rng_state >> 8) / 16777216.0f;
}

/* A full-screen quad in clip space whose right half lies at w = 1 and left half at w = wl, so
 * that perspective-correct and affine interpolation differ; z from z0 (left) to z1 (right). */
static void quad(float wl, float z0, float z1, const float c[4][4])
{
    const float xs[4] = {-1, 1, 1, -1}, ys[4] = {-1, -1, 1, 1};
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; i++) {
        float w = xs[i] < 0 ? wl : 1.0f;
        float z = xs[i] < 0 ? z0 : z1;
        glColor4fv(c[i]);
        glVertex4f(xs[i] * w, ys[i] * w, z * w, w);
    }
    glEnd();
}

static void layer_colors(int layer, float alpha, float c[4][4])
{
    for (int i = 0; i < 4; i++) {
        c[i][0] = (float)((layer * 37 + i * 61) % 256) / 255.0f;
        c[i][1] = (float)((layer * 91 + i * 17 + 80) % 256) / 255.0f;
        c[i][2] = (float)((layer * 13 + i * 111 + 160) % 256) / 255.0f;
        c[i][3] = alpha;
    }
}

static void reset_state(void)
{
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_FOG);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_COLOR_LOGIC_OP);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DITHER);
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glShadeModel(GL_SMOOTH);
    glColorMask(1, 1, 1, 1);
    glDepthMask(1);
    glDepthFunc(GL_LESS);
    glStencilMask(0xff);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

#define LAYERS 8

/* Scenes: each draws one frame and returns the number of fragments it generates. */

static double scene_flat(void)
{
    glShadeModel(GL_FLAT);
    for (int l = 0; l < LAYERS; l++) {
        float c[4][4];
        layer_colors(l, 1.0f, c);
        for (int i = 0; i < 4; i++)
            memcpy(c[i], c[3], sizeof c[3]);
        quad(1.0f, 0, 0, c);
    }
    return (double)LAYERS * W * H;
}

static double scene_smooth(void)
{
    for (int l = 0; l < LAYERS; l++) {
        float c[4][4];
        layer_colors(l, 1.0f, c);
        quad(1.0f + 0.25f * l, 0, 0, c);
    }
    return (double)LAYERS * W * H;
}

static double scene_blend(void)
{
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int l = 0; l < LAYERS; l++) {
        float c[4][4];
        layer_colors(l, 0.3f + 0.05f * l, c);
        quad(1.0f + 0.25f * l, 0, 0, c);
    }
    return (double)LAYERS * W * H;
}

static double scene_depth(void)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    for (int l = 0; l < LAYERS; l++) {
        float c[4][4];
        layer_colors(l, 1.0f, c);
        /* Planes that cross each other: half of each layer passes. */
        float z0 = (l % 2) ? -0.8f + 0.1f * l : 0.8f - 0.1f * l;
        quad(1.0f + 0.25f * l, z0, -z0, c);
    }
    return (double)LAYERS * W * H;
}

static double scene_stencil(void)
{
    float c[4][4];
    /* The scene: a depth-tested floor. */
    glEnable(GL_DEPTH_TEST);
    layer_colors(1, 1.0f, c);
    quad(1.5f, 0.2f, 0.6f, c);
    /* Shadow volumes: two-sided stencil, increment on back faces failing depth, decrement on
     * front faces failing depth (z-fail), no color or depth writes. */
    glColorMask(0, 0, 0, 0);
    glDepthMask(0);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glEnable(GL_CULL_FACE);
    for (int v = 0; v < 3; v++) {
        float z = -0.5f + 0.4f * v;
        glCullFace(GL_FRONT);
        glStencilOp(GL_KEEP, GL_INCR_WRAP, GL_KEEP);
        glBegin(GL_QUADS); /* back faces (clockwise) */
        glVertex3f(-0.9f + 0.3f * v, -0.9f, z);
        glVertex3f(-0.9f + 0.3f * v, 0.9f, z);
        glVertex3f(0.5f + 0.1f * v, 0.9f, z);
        glVertex3f(0.5f + 0.1f * v, -0.9f, z);
        glEnd();
        glCullFace(GL_BACK);
        glStencilOp(GL_KEEP, GL_DECR_WRAP, GL_KEEP);
        glBegin(GL_QUADS); /* front faces */
        glVertex3f(-0.7f + 0.3f * v, -0.7f, z + 0.5f);
        glVertex3f(0.7f + 0.1f * v, -0.7f, z + 0.5f);
        glVertex3f(0.7f + 0.1f * v, 0.7f, z + 0.5f);
        glVertex3f(-0.7f + 0.3f * v, 0.7f, z + 0.5f);
        glEnd();
    }
    glDisable(GL_CULL_FACE);
    /* The lit pass where the stencil is 0. */
    glColorMask(1, 1, 1, 1);
    glDepthFunc(GL_LEQUAL);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    layer_colors(5, 1.0f, c);
    quad(1.5f, 0.2f, 0.6f, c);
    return (double)W * H * (2 + 3 * (0.7 * 0.9 + 0.49 * 0.75));
}

static float *mesh_xy, *mesh_rgb;
static int mesh_vertices;

static double scene_small_triangles(void)
{
    /* 250 × 200 cells, two triangles each: 100 000 triangles over the whole window. */
    const int nx = 250, ny = 200;
    if (!mesh_xy) {
        mesh_vertices = nx * ny * 6;
        mesh_xy = malloc(sizeof(float) * 2 * mesh_vertices);
        mesh_rgb = malloc(sizeof(float) * 3 * mesh_vertices);
        int k = 0;
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                const int corner[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
                for (int v = 0; v < 6; v++, k++) {
                    int gi = i + corner[v][0], gj = j + corner[v][1];
                    mesh_xy[2 * k] = -1.0f + 2.0f * gi / nx;
                    mesh_xy[2 * k + 1] = -1.0f + 2.0f * gj / ny;
                    mesh_rgb[3 * k] = (float)((gi * 7 + gj * 3) % 256) / 255.0f;
                    mesh_rgb[3 * k + 1] = (float)((gi * 5 + gj * 11) % 256) / 255.0f;
                    mesh_rgb[3 * k + 2] = (float)((gi + gj * 13) % 256) / 255.0f;
                }
            }
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, mesh_xy);
    glColorPointer(3, GL_FLOAT, 0, mesh_rgb);
    glDrawArrays(GL_TRIANGLES, 0, mesh_vertices);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    return (double)W * H;
}

static double scene_thin_triangles(void)
{
    /* 2000 slivers across the window, each about 0.7 pixel tall. */
    const int n = 2000;
    double area = 0;
    rng_state = 777u;
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < n; i++) {
        float y0 = rnd() * 2 - 1, y1 = rnd() * 2 - 1, t = 1.4f / H;
        glColor3f(rnd(), rnd(), rnd());
        glVertex2f(-1.0f, y0);
        glColor3f(rnd(), rnd(), rnd());
        glVertex2f(1.0f, y1);
        glColor3f(rnd(), rnd(), rnd());
        glVertex2f(1.0f, y1 + t);
        area += 0.5 * W * 0.7;
    }
    glEnd();
    return area;
}

static double scene_fog_blend(void)
{
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.0f);
    glFogf(GL_FOG_END, 1.0f);
    const float fog_color[4] = {0.5f, 0.6f, 0.7f, 1.0f};
    glFogfv(GL_FOG_COLOR, fog_color);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int l = 0; l < LAYERS; l++) {
        float c[4][4];
        layer_colors(l, 0.5f, c);
        quad(1.0f + 0.25f * l, -0.9f + 0.1f * l, 0.1f * l, c);
    }
    return (double)LAYERS * W * H;
}

/* A lit mesh: a 128 x 128 grid of quads bent into a dome, two lights (one local with
 * attenuation), specular, depth-tested; the lighting is per vertex. */
static double scene_lit_mesh(void)
{
    enum { N = 128 };
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_NORMALIZE);
    const float dir[4] = {0.3f, 0.5f, 1.0f, 0.0f}, pos[4] = {-0.5f, 0.2f, 0.8f, 1.0f};
    const float white[4] = {1, 1, 1, 1}, warm[4] = {0.9f, 0.6f, 0.3f, 1}, spec[4] = {0.8f, 0.8f, 0.8f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT1, GL_POSITION, pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.5f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
    for (int j = 0; j < N; j++) {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= N; i++)
            for (int k = 1; k >= 0; k--) {
                float x = -1 + 2.0f * i / N, y = -1 + 2.0f * (j + k) / N;
                float z = 0.5f - 0.5f * (x * x + y * y);
                glNormal3f(x, y, 1.0f);
                glVertex3f(x, y, -z);
            }
        glEnd();
    }
    glDisable(GL_LIGHT0);
    glDisable(GL_LIGHT1);
    glDisable(GL_NORMALIZE);
    return (double)W * H;
}

/* Textured fill: 8 full-window layers of a mipmapped 256 x 256 RGBA texture, trilinear,
 * GL_MODULATE with the smooth colors, with perspective (the quads' varying w). */
static double scene_textured(void)
{
    static GLuint texture;
    if (!texture) {
        static unsigned char texels[256 * 256 * 4];
        for (int i = 0; i < 256 * 256; i++) {
            int x = i % 256, y = i / 256;
            texels[4 * i + 0] = (unsigned char)(((x / 16) ^ (y / 16)) & 1 ? 255 : 40);
            texels[4 * i + 1] = (unsigned char)x;
            texels[4 * i + 2] = (unsigned char)y;
            texels[4 * i + 3] = 255;
        }
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 256, 256, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    }
    glBindTexture(GL_TEXTURE_2D, texture);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    for (int l = 0; l < LAYERS; l++) {
        float c[4][4];
        layer_colors(l, 1.0f, c);
        const float xs[4] = {-1, 1, 1, -1}, ys[4] = {-1, -1, 1, 1}, wl = 1.0f + 0.25f * l;
        glBegin(GL_QUADS);
        for (int i = 0; i < 4; i++) {
            float w = xs[i] < 0 ? wl : 1.0f;
            glColor4fv(c[i]);
            glTexCoord2f((xs[i] + 1) * 2 + 0.1f * l, (ys[i] + 1) * 2);
            glVertex4f(xs[i] * w, ys[i] * w, 0, w);
        }
        glEnd();
    }
    return (double)LAYERS * W * H;
}

/* Render to texture, as a shadow-mapping client does each frame: depth is drawn into a
 * 2048 x 2048 GL_DEPTH_COMPONENT24 texture attached to a framebuffer object (a cleared map and
 * 8 overlapping occluder quads), then the window is filled with that texture sampled with
 * depth comparison (GL_COMPARE_R_TO_TEXTURE, linear filtering). */
#define SHADOW_SIZE 2048
static double scene_fbo_shadow_map(void)
{
    static GLuint texture, fbo;
    if (!fbo) {
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, SHADOW_SIZE, SHADOW_SIZE, 0, GL_DEPTH_COMPONENT,
                     GL_UNSIGNED_INT, NULL);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture, 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            fprintf(stderr, "bench: the shadow map framebuffer is not complete\n");
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    /* The depth pass. */
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, SHADOW_SIZE, SHADOW_SIZE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    for (int l = 0; l < LAYERS; l++) {
        float x0 = -1.0f + 0.2f * l, y0 = -0.9f + 0.15f * l, z = 0.8f - 0.2f * l;
        glBegin(GL_QUADS);
        glVertex3f(x0, y0, z);
        glVertex3f(x0 + 1.0f, y0, z - 0.3f);
        glVertex3f(x0 + 1.0f, y0 + 1.0f, z - 0.3f);
        glVertex3f(x0, y0 + 1.0f, z);
        glEnd();
    }
    glDisable(GL_DEPTH_TEST);
    /* The lit pass: the window, each pixel compared against the map. */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, W, H);
    glBindTexture(GL_TEXTURE_2D, texture);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    const float xs[4] = {-1, 1, 1, -1}, ys[4] = {-1, -1, 1, 1};
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; i++) {
        glColor4f(0.9f, 0.8f, 0.6f, 1.0f);
        glTexCoord3f((xs[i] + 1) * 0.5f, (ys[i] + 1) * 0.5f, 0.3f + 0.2f * (xs[i] + 1));
        glVertex2f(xs[i], ys[i]);
    }
    glEnd();
    glDisable(GL_TEXTURE_2D);
    return (double)LAYERS * SHADOW_SIZE * SHADOW_SIZE / 4 + (double)W * H;
}

/* The per-stage scene: the smooth scene with one fragment stage enabled (all passing). */
static const char *stage_name = "none";
static double scene_stage(void)
{
    if (!strcmp(stage_name, "scissor")) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(1, 1, W - 2, H - 2);
    } else if (!strcmp(stage_name, "alpha")) {
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(GL_GREATER, 0.1f);
    } else if (!strcmp(stage_name, "stencil")) {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 1, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    } else if (!strcmp(stage_name, "depth")) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
    } else if (!strcmp(stage_name, "blend")) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    } else if (!strcmp(stage_name, "logic_op")) {
        glEnable(GL_COLOR_LOGIC_OP);
        glLogicOp(GL_XOR);
    } else if (!strcmp(stage_name, "fog")) {
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_START, 0.0f);
        glFogf(GL_FOG_END, 2.0f);
    } else if (!strcmp(stage_name, "dither")) {
        glEnable(GL_DITHER);
    }
    for (int l = 0; l < LAYERS; l++) {
        float c[4][4];
        layer_colors(l, 0.75f, c);
        quad(1.0f + 0.25f * l, 0.5f, 0.5f, c);
    }
    return (double)LAYERS * W * H;
}

/* GLSL scenes (issue #20's performance checks). The GL 2.0 entry points are looked up with
 * OSMesaGetProcAddress, as a client of a 1.5 context would (tessera reports 2.1 only once
 * every GL 2.1 feature works; its entry points exist either way). */
static PFNGLCREATESHADERPROC pCreateShader;
static PFNGLSHADERSOURCEPROC pShaderSource;
static PFNGLCOMPILESHADERPROC pCompileShader;
static PFNGLGETSHADERIVPROC pGetShaderiv;
static PFNGLGETSHADERINFOLOGPROC pGetShaderInfoLog;
static PFNGLCREATEPROGRAMPROC pCreateProgram;
static PFNGLATTACHSHADERPROC pAttachShader;
static PFNGLLINKPROGRAMPROC pLinkProgram;
static PFNGLGETPROGRAMIVPROC pGetProgramiv;
static PFNGLGETPROGRAMINFOLOGPROC pGetProgramInfoLog;
static PFNGLUSEPROGRAMPROC pUseProgram;
static PFNGLDELETESHADERPROC pDeleteShader;
static PFNGLDELETEPROGRAMPROC pDeleteProgram;
static PFNGLGETUNIFORMLOCATIONPROC pGetUniformLocation;
static PFNGLUNIFORM1IPROC pUniform1i;

static int load_glsl_entry_points(void)
{
#define LOAD(p, name) (p = (void *)OSMesaGetProcAddress(name)) != NULL
    return LOAD(pCreateShader, "glCreateShader") && LOAD(pShaderSource, "glShaderSource") &&
           LOAD(pCompileShader, "glCompileShader") && LOAD(pGetShaderiv, "glGetShaderiv") &&
           LOAD(pGetShaderInfoLog, "glGetShaderInfoLog") && LOAD(pCreateProgram, "glCreateProgram") &&
           LOAD(pAttachShader, "glAttachShader") && LOAD(pLinkProgram, "glLinkProgram") &&
           LOAD(pGetProgramiv, "glGetProgramiv") && LOAD(pGetProgramInfoLog, "glGetProgramInfoLog") &&
           LOAD(pUseProgram, "glUseProgram") && LOAD(pDeleteShader, "glDeleteShader") &&
           LOAD(pDeleteProgram, "glDeleteProgram") && LOAD(pGetUniformLocation, "glGetUniformLocation") &&
           LOAD(pUniform1i, "glUniform1i");
#undef LOAD
}

/* Compiles and links a program; exits with the info log on failure (a benchmark of a
 * program that does not link would time nothing). */
static GLuint build_program(const char *vertex, const char *fragment)
{
    const char *sources[2] = {vertex, fragment};
    const GLenum kinds[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    GLuint program = pCreateProgram();
    char log[4096];
    for (int i = 0; i < 2; i++) {
        GLuint shader = pCreateShader(kinds[i]);
        GLint ok = 0;
        pShaderSource(shader, 1, &sources[i], NULL);
        pCompileShader(shader);
        pGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            pGetShaderInfoLog(shader, sizeof log, NULL, log);
            fprintf(stderr, "bench: shader does not compile:\n%s\n", log);
            exit(1);
        }
        pAttachShader(program, shader);
        pDeleteShader(shader); /* freed with the program */
    }
    GLint linked = 0;
    pLinkProgram(program);
    pGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        pGetProgramInfoLog(program, sizeof log, NULL, log);
        fprintf(stderr, "bench: program does not link:\n%s\n", log);
        exit(1);
    }
    return program;
}

/* Per-pixel Blinn-Phong: the lit mesh of scene_lit_mesh (same lights and material), lit in
 * the fragment shader from the built-in light and material state. */
static double scene_phong_shader(void)
{
    static GLuint program;
    if (!program)
        program = build_program(
            "varying vec3 normal, position;\n"
            "void main() {\n"
            "    position = vec3(gl_ModelViewMatrix * gl_Vertex);\n"
            "    normal = gl_NormalMatrix * gl_Normal;\n"
            "    gl_Position = ftransform();\n"
            "}\n",
            "varying vec3 normal, position;\n"
            "void main() {\n"
            "    vec3 n = normalize(normal);\n"
            "    vec3 eye = -normalize(position);\n"
            "    vec4 color = gl_FrontLightModelProduct.sceneColor;\n"
            "    for (int i = 0; i < 2; i++) {\n"
            "        vec4 p = gl_LightSource[i].position;\n"
            "        vec3 l = p.w == 0.0 ? normalize(p.xyz) : normalize(p.xyz - position);\n"
            "        float attenuation = p.w == 0.0 ? 1.0\n"
            "            : 1.0 / (gl_LightSource[i].constantAttenuation\n"
            "                     + gl_LightSource[i].linearAttenuation * length(p.xyz - position));\n"
            "        float diffuse = max(dot(n, l), 0.0);\n"
            "        color += attenuation * (gl_FrontLightProduct[i].ambient + gl_FrontLightProduct[i].diffuse * diffuse);\n"
            "        if (diffuse > 0.0) {\n"
            "            float h = max(dot(n, normalize(l + eye)), 0.0);\n"
            "            color += attenuation * gl_FrontLightProduct[i].specular * pow(h, gl_FrontMaterial.shininess);\n"
            "        }\n"
            "    }\n"
            "    gl_FragColor = clamp(color, 0.0, 1.0);\n"
            "}\n");
    pUseProgram(program);
    double fragments = scene_lit_mesh();
    pUseProgram(0);
    return fragments;
}

/* scene_textured through a program: the texture sampled in the fragment shader and
 * modulated by the interpolated colour, as GL_MODULATE does. */
static double scene_textured_shader(void)
{
    static GLuint program;
    if (!program) {
        program = build_program("void main() {\n"
                                "    gl_Position = ftransform();\n"
                                "    gl_TexCoord[0] = gl_MultiTexCoord0;\n"
                                "    gl_FrontColor = gl_Color;\n"
                                "}\n",
                                "uniform sampler2D image;\n"
                                "void main() {\n"
                                "    gl_FragColor = texture2D(image, gl_TexCoord[0].xy) * gl_Color;\n"
                                "}\n");
        pUseProgram(program);
        pUniform1i(pGetUniformLocation(program, "image"), 0);
    }
    pUseProgram(program);
    double fragments = scene_textured();
    glDisable(GL_TEXTURE_2D);
    pUseProgram(0);
    return fragments;
}

/* The first draw with a new program: a 200-line shader pair (lighting, texturing, fog and
 * helper functions) compiled, linked and drawn over 64 x 64 pixels. Each repetition's source
 * differs by one constant, and the constants start from the process id, so no implementation
 * can reuse an earlier compile (Mesa keeps compiled shaders in a disk cache across
 * processes: with the same sources in every run, llvmpipe's "first" draws were cache hits). */
static double scene_shader_first_draw(void)
{
    static int generation = -1;
    if (generation < 0)
        generation = (int)(getpid() % 100000) * 1000;
    static char vertex[8192], fragment[16384];
    int n = snprintf(vertex, sizeof vertex,
                     "// first-draw benchmark, generation %d\n"
                     "varying vec3 normal, position;\n"
                     "varying vec2 uv;\n"
                     "varying float fog;\n"
                     "uniform float time;\n"
                     "const float wobble = %d.0 / 1000.0;\n"
                     "vec4 displaced(vec4 v) {\n"
                     "    float s = sin(v.x * 3.0 + time) * wobble;\n"
                     "    float c = cos(v.y * 2.0 - time) * wobble;\n"
                     "    return vec4(v.xyz + vec3(s, c, s * c), v.w);\n"
                     "}\n"
                     "float fog_factor(vec3 eye) {\n"
                     "    float d = length(eye);\n"
                     "    return clamp((gl_Fog.end - d) * gl_Fog.scale, 0.0, 1.0);\n"
                     "}\n"
                     "void main() {\n"
                     "    vec4 v = displaced(gl_Vertex);\n"
                     "    position = vec3(gl_ModelViewMatrix * v);\n"
                     "    normal = normalize(gl_NormalMatrix * gl_Normal);\n"
                     "    uv = gl_MultiTexCoord0.xy * 2.0;\n"
                     "    fog = fog_factor(position);\n"
                     "    gl_FrontColor = gl_Color;\n"
                     "    gl_Position = gl_ModelViewProjectionMatrix * v;\n"
                     "}\n",
                     generation, generation % 7);
    int m = snprintf(fragment, sizeof fragment,
                     "// first-draw benchmark, generation %d\n"
                     "varying vec3 normal, position;\n"
                     "varying vec2 uv;\n"
                     "varying float fog;\n"
                     "uniform sampler2D albedo;\n"
                     "uniform sampler2D detail;\n"
                     "uniform float exposure;\n"
                     "const int LIGHTS = 2;\n"
                     "const float seed = %d.0;\n"
                     "struct Surface {\n"
                     "    vec3 normal;\n"
                     "    vec3 view;\n"
                     "    vec4 base;\n"
                     "    float roughness;\n"
                     "};\n",
                     generation, generation);
    /* Helper functions: each a few lines of the arithmetic real shaders do. */
    for (int f = 0; f < 12; f++)
        m += snprintf(fragment + m, sizeof fragment - m,
                      "float hash%d(vec2 p) {\n"
                      "    p = fract(p * vec2(%d.13, %d.71) + seed);\n"
                      "    p += dot(p, p.yx + 19.19);\n"
                      "    return fract((p.x + p.y) * p.x);\n"
                      "}\n"
                      "vec3 tone%d(vec3 c) {\n"
                      "    vec3 x = max(vec3(0.0), c * exposure - 0.004 * float(%d));\n"
                      "    return (x * (6.2 * x + 0.5)) / (x * (6.2 * x + 1.7) + 0.06);\n"
                      "}\n",
                      f, f + 3, f + 5, f, f);
    m += snprintf(fragment + m, sizeof fragment - m,
                  "float specular(Surface s, vec3 l) {\n"
                  "    vec3 h = normalize(l + s.view);\n"
                  "    float shininess = mix(8.0, 64.0, 1.0 - s.roughness);\n"
                  "    return pow(max(dot(s.normal, h), 0.0), shininess);\n"
                  "}\n"
                  "vec3 light(Surface s, int i) {\n"
                  "    vec4 p = gl_LightSource[i].position;\n"
                  "    vec3 l = p.w == 0.0 ? normalize(p.xyz) : normalize(p.xyz - s.view);\n"
                  "    float d = max(dot(s.normal, l), 0.0);\n"
                  "    vec3 c = gl_LightSource[i].diffuse.rgb * d * s.base.rgb;\n"
                  "    if (d > 0.0)\n"
                  "        c += gl_LightSource[i].specular.rgb * specular(s, l);\n"
                  "    return c;\n"
                  "}\n"
                  "void main() {\n"
                  "    Surface s;\n"
                  "    s.normal = normalize(normal);\n"
                  "    s.view = -normalize(position);\n"
                  "    s.base = texture2D(albedo, uv) * gl_Color;\n"
                  "    s.roughness = texture2D(detail, uv * 4.0).r;\n"
                  "    vec3 color = gl_LightModel.ambient.rgb * s.base.rgb;\n"
                  "    for (int i = 0; i < LIGHTS; i++)\n"
                  "        color += light(s, i);\n"
                  "    float grain = 0.0;\n");
    for (int f = 0; f < 12; f++)
        m += snprintf(fragment + m, sizeof fragment - m, "    grain += hash%d(gl_FragCoord.xy) * %d.0;\n", f, f + 1);
    m += snprintf(fragment + m, sizeof fragment - m,
                  "    color += (grain / 78.0 - 0.5) / 64.0;\n"
                  "    if (exposure > 1.5)\n"
                  "        color = tone%d(color);\n"
                  "    else\n"
                  "        color = tone%d(color);\n"
                  "    gl_FragColor = vec4(mix(gl_Fog.color.rgb, color, fog), s.base.a);\n"
                  "}\n",
                  generation % 12, (generation + 5) % 12);
    (void)n;
    generation++;
    GLuint program = build_program(vertex, fragment);
    pUseProgram(program);
    glBegin(GL_QUADS);
    const float h = 64.0f / (float)W;
    glColor3f(0.9f, 0.8f, 0.7f);
    glNormal3f(0, 0, 1);
    glTexCoord2f(0, 0);
    glVertex2f(-h, -h);
    glTexCoord2f(1, 0);
    glVertex2f(h, -h);
    glTexCoord2f(1, 1);
    glVertex2f(h, h);
    glTexCoord2f(0, 1);
    glVertex2f(-h, h);
    glEnd();
    pUseProgram(0);
    pDeleteProgram(program);
    return 64.0 * 64.0;
}

static void save(const char *dir, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.rgba", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, "bench: cannot write %s\n", path);
        exit(1);
    }
    fwrite(pixels, 4, (size_t)W * H, f);
    fclose(f);
}

static const char *only;

static void run(const char *dir, const char *name, double (*scene)(void), int reps)
{
    if (only && strncmp(name, only, strlen(only)) != 0)
        return;
    double fragments = 0;
    printf("scene %s", name);
    for (int r = -1; r < reps; r++) {
        double t0 = now_ms();
        /* The masks a scene left must not mask the next clear. */
        reset_state();
        glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
        glClearDepth(1.0);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        fragments = scene();
        glFinish();
        double t1 = now_ms();
        if (r == -1)
            printf(" %.0f", fragments);
        else
            printf(" %.4f", t1 - t0);
    }
    printf("\n");
    fflush(stdout);
    if (glGetError() != GL_NO_ERROR)
        fprintf(stderr, "bench: GL error in scene %s\n", name);
    save(dir, name);
}

static unsigned char *read_all(const char *path, long *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    *size = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *data = malloc(*size > 0 ? *size : 1);
    if (fread(data, 1, *size, f) != (size_t)*size) {
        free(data);
        data = NULL;
    }
    fclose(f);
    return data;
}

/* Prints "max_error <m> over_1lsb <pixels> psnr <dB>" of an RGBA8 image against a reference
 * (every channel; PSNR "inf" when identical). */
static int compare(const char *reference, const char *image)
{
    long na, nb;
    unsigned char *a = read_all(reference, &na), *b = read_all(image, &nb);
    if (!a || !b || na != nb) {
        printf("max_error - over_1lsb - psnr -\n");
        return 0;
    }
    int max_error = 0;
    long over = 0;
    double squares = 0;
    for (long p = 0; p < na / 4; p++) {
        int worst = 0;
        for (int c = 0; c < 4; c++) {
            int d = abs((int)a[4 * p + c] - (int)b[4 * p + c]);
            squares += (double)d * d;
            if (d > worst)
                worst = d;
        }
        if (worst > max_error)
            max_error = worst;
        if (worst > 1)
            over++;
    }
    if (squares == 0)
        printf("max_error 0 over_1lsb 0 psnr inf\n");
    else
        printf("max_error %d over_1lsb %ld psnr %.2f\n", max_error, over,
               10.0 * log10(255.0 * 255.0 / (squares / (double)na)));
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 4 && !strcmp(argv[1], "--compare"))
        return compare(argv[2], argv[3]);
    if (argc < 4) {
        fprintf(stderr, "usage: bench <out-dir> <repetitions> <size>\n");
        return 2;
    }
    const char *dir = argv[1];
    int reps = atoi(argv[2]);
    W = H = atoi(argv[3]);
    only = argc > 4 ? argv[4] : NULL;
    pixels = calloc((size_t)W * H, 4);

    double t0 = now_ms();
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H)) {
        fprintf(stderr, "bench: no context\n");
        return 1;
    }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glFinish();
    double t1 = now_ms();
    reset_state();
    scene_flat();
    glFinish();
    double t2 = now_ms();
    printf("renderer %s\n", (const char *)glGetString(GL_RENDERER));
    printf("context %.4f\nfirst_frame %.4f\n", t1 - t0, t2 - t0);

    run(dir, "flat_fill", scene_flat, reps);
    run(dir, "smooth_fill", scene_smooth, reps);
    run(dir, "blend_fill", scene_blend, reps);
    run(dir, "depth_overdraw", scene_depth, reps);
    run(dir, "stencil_shadow", scene_stencil, reps);
    run(dir, "small_triangles", scene_small_triangles, reps);
    run(dir, "thin_triangles", scene_thin_triangles, reps);
    run(dir, "fog_blend", scene_fog_blend, reps);
    run(dir, "lit_mesh", scene_lit_mesh, reps);
    run(dir, "textured_fill", scene_textured, reps);
    run(dir, "fbo_shadow_map", scene_fbo_shadow_map, reps);
    if (load_glsl_entry_points()) {
        run(dir, "phong_shader", scene_phong_shader, reps);
        run(dir, "textured_shader", scene_textured_shader, reps);
        run(dir, "shader_first_draw", scene_shader_first_draw, reps);
    } else {
        fprintf(stderr, "bench: no GL 2.0 entry points: GLSL scenes skipped\n");
    }
    const char *stages[] = {"none", "scissor", "alpha", "stencil", "depth", "blend", "logic_op", "fog", "dither"};
    for (unsigned s = 0; s < sizeof stages / sizeof *stages; s++) {
        char name[64];
        stage_name = stages[s];
        snprintf(name, sizeof name, "stage_%s", stage_name);
        run(dir, name, scene_stage, reps);
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return 0;
}
