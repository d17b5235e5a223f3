/* gl-probe: runs a small drawing script on an OSMesa implementation and prints which
 * pixels (and depths) it wrote, to compare Mesa's rasterization with tessera's.
 *
 *   gcc -O1 tools/gl-probe.c -o /tmp/gl-probe -lOSMesa
 *   /tmp/gl-probe < script.txt                                    # Mesa
 *   LD_LIBRARY_PATH=target/release /tmp/gl-probe < script.txt     # tessera
 *
 * `replay` in src/context/draw.rs's tests runs the same commands on tessera's Context
 * directly (the probe tests there hold scripts and Mesa's answers). Window coordinates:
 * `size W H` sets glOrtho(0, W, 0, H, -1, 1). Output lines are "name: x,y ..." (lit),
 * "x,y=rrggbbaa" (dump) or "x,y=zzzzzz" (depth, 24-bit).
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int W, H;
static unsigned char *buf;
static OSMesaContext ctx;
static float clear_c[4];

static GLenum mode_of(const char *s) {
    static const struct { const char *n; GLenum e; } t[] = {
        {"points", GL_POINTS}, {"lines", GL_LINES}, {"line_strip", GL_LINE_STRIP},
        {"line_loop", GL_LINE_LOOP}, {"triangles", GL_TRIANGLES}, {"triangle_strip", GL_TRIANGLE_STRIP},
        {"triangle_fan", GL_TRIANGLE_FAN}, {"quads", GL_QUADS}, {"quad_strip", GL_QUAD_STRIP},
        {"polygon", GL_POLYGON}, {"point", GL_POINT}, {"line", GL_LINE}, {"fill", GL_FILL},
        {"front", GL_FRONT}, {"back", GL_BACK}, {"front_and_back", GL_FRONT_AND_BACK},
        {"line_stipple", GL_LINE_STIPPLE}, {"polygon_stipple", GL_POLYGON_STIPPLE},
        {"depth_test", GL_DEPTH_TEST}, {"cull_face", GL_CULL_FACE},
        {"offset_fill", GL_POLYGON_OFFSET_FILL}, {"offset_line", GL_POLYGON_OFFSET_LINE},
        {"offset_point", GL_POLYGON_OFFSET_POINT}, {"scissor", GL_SCISSOR_TEST},
        {"flat", GL_FLAT}, {"smooth", GL_SMOOTH}, {"cw", GL_CW}, {"ccw", GL_CCW},
        {"less", GL_LESS}, {"lequal", GL_LEQUAL}, {"equal", GL_EQUAL}, {"always", GL_ALWAYS},
        {"first", 0x8E4D}, {"last", 0x8E4E},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
        if (!strcmp(t[i].n, s)) return t[i].e;
    fprintf(stderr, "unknown name %s\n", s);
    exit(2);
}

int main(void) {
    char line[4096];
    while (fgets(line, sizeof line, stdin)) {
        char cmd[64], a[64], b[64];
        double x, y, z, w;
        if (sscanf(line, "%63s", cmd) != 1 || cmd[0] == '#') continue;
        if (!strcmp(cmd, "size")) {
            sscanf(line, "%*s %d %d", &W, &H);
            ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
            buf = calloc((size_t)W * H, 4);
            OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H);
            glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0, W, 0, H, -1, 1);
            glMatrixMode(GL_MODELVIEW); glLoadIdentity();
        } else if (!strcmp(cmd, "clear")) {
            sscanf(line, "%*s %f %f %f %f", &clear_c[0], &clear_c[1], &clear_c[2], &clear_c[3]);
            glClearColor(clear_c[0], clear_c[1], clear_c[2], clear_c[3]);
            glClearDepth(1.0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        } else if (!strcmp(cmd, "cleardepth")) {
            sscanf(line, "%*s %lf", &x); glClearDepth(x); glClear(GL_DEPTH_BUFFER_BIT);
        } else if (!strcmp(cmd, "ortho")) {
            double l, r, bo, t, n, f;
            sscanf(line, "%*s %lf %lf %lf %lf %lf %lf", &l, &r, &bo, &t, &n, &f);
            glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(l, r, bo, t, n, f);
            glMatrixMode(GL_MODELVIEW);
        } else if (!strcmp(cmd, "frustum")) {
            double l, r, bo, t, n, f;
            sscanf(line, "%*s %lf %lf %lf %lf %lf %lf", &l, &r, &bo, &t, &n, &f);
            glMatrixMode(GL_PROJECTION); glLoadIdentity(); glFrustum(l, r, bo, t, n, f);
            glMatrixMode(GL_MODELVIEW);
        } else if (!strcmp(cmd, "viewport")) {
            int vx, vy, vw, vh; sscanf(line, "%*s %d %d %d %d", &vx, &vy, &vw, &vh); glViewport(vx, vy, vw, vh);
        } else if (!strcmp(cmd, "scissorbox")) {
            int vx, vy, vw, vh; sscanf(line, "%*s %d %d %d %d", &vx, &vy, &vw, &vh); glScissor(vx, vy, vw, vh);
        } else if (!strcmp(cmd, "linewidth")) {
            sscanf(line, "%*s %lf", &x); glLineWidth((float)x);
        } else if (!strcmp(cmd, "pointsize")) {
            sscanf(line, "%*s %lf", &x); glPointSize((float)x);
        } else if (!strcmp(cmd, "pointminmax")) {
            sscanf(line, "%*s %lf %lf", &x, &y);
            glPointParameterf(GL_POINT_SIZE_MIN, (float)x); glPointParameterf(GL_POINT_SIZE_MAX, (float)y);
        } else if (!strcmp(cmd, "stipple")) {
            int f; unsigned p; sscanf(line, "%*s %d %x", &f, &p); glLineStipple(f, (GLushort)p);
        } else if (!strcmp(cmd, "pstipple")) {
            /* 32 hex words, row 0 first; each word's bit 31 = leftmost -> bytes MSB first */
            unsigned rows[32]; GLubyte m[128]; char *p = line + 8;
            for (int i = 0; i < 32; i++) { rows[i] = (unsigned)strtoul(p, &p, 16); }
            for (int i = 0; i < 32; i++) for (int k = 0; k < 4; k++) m[i * 4 + k] = (rows[i] >> (24 - 8 * k)) & 0xff;
            glPolygonStipple(m);
        } else if (!strcmp(cmd, "enable")) {
            sscanf(line, "%*s %63s", a); glEnable(mode_of(a));
        } else if (!strcmp(cmd, "disable")) {
            sscanf(line, "%*s %63s", a); glDisable(mode_of(a));
        } else if (!strcmp(cmd, "shade")) {
            sscanf(line, "%*s %63s", a); glShadeModel(mode_of(a));
        } else if (!strcmp(cmd, "provoking")) {
            sscanf(line, "%*s %63s", a); glProvokingVertex(mode_of(a));
        } else if (!strcmp(cmd, "polymode")) {
            sscanf(line, "%*s %63s %63s", a, b); glPolygonMode(mode_of(a), mode_of(b));
        } else if (!strcmp(cmd, "cullface")) {
            sscanf(line, "%*s %63s", a); glCullFace(mode_of(a));
        } else if (!strcmp(cmd, "frontface")) {
            sscanf(line, "%*s %63s", a); glFrontFace(mode_of(a));
        } else if (!strcmp(cmd, "depthfunc")) {
            sscanf(line, "%*s %63s", a); glDepthFunc(mode_of(a));
        } else if (!strcmp(cmd, "offset")) {
            sscanf(line, "%*s %lf %lf", &x, &y); glPolygonOffset((float)x, (float)y);
        } else if (!strcmp(cmd, "begin")) {
            sscanf(line, "%*s %63s", a); glBegin(mode_of(a));
        } else if (!strcmp(cmd, "end")) {
            glEnd();
        } else if (!strcmp(cmd, "color")) {
            sscanf(line, "%*s %lf %lf %lf %lf", &x, &y, &z, &w); glColor4f((float)x, (float)y, (float)z, (float)w);
        } else if (!strcmp(cmd, "edge")) {
            int e; sscanf(line, "%*s %d", &e); glEdgeFlag((GLboolean)e);
        } else if (!strcmp(cmd, "v")) {
            z = 0; w = 1;
            int n = sscanf(line, "%*s %lf %lf %lf %lf", &x, &y, &z, &w);
            if (n == 4) glVertex4f((float)x, (float)y, (float)z, (float)w);
            else glVertex3f((float)x, (float)y, (float)z);
        } else if (!strcmp(cmd, "lit")) {
            /* pixels differing from the clear color */
            glFinish();
            unsigned char cc[4];
            for (int k = 0; k < 4; k++) cc[k] = (unsigned char)(clear_c[k] * 255.0f + 0.5f);
            sscanf(line, "%*s %63s", a);
            printf("%s:", a);
            for (int yy = 0; yy < H; yy++) for (int xx = 0; xx < W; xx++) {
                unsigned char *p = buf + ((size_t)yy * W + xx) * 4;
                if (memcmp(p, cc, 4)) printf(" %d,%d", xx, yy);
            }
            printf("\n");
        } else if (!strcmp(cmd, "dump")) {
            glFinish();
            unsigned char cc[4];
            for (int k = 0; k < 4; k++) cc[k] = (unsigned char)(clear_c[k] * 255.0f + 0.5f);
            sscanf(line, "%*s %63s", a);
            printf("%s:", a);
            for (int yy = 0; yy < H; yy++) for (int xx = 0; xx < W; xx++) {
                unsigned char *p = buf + ((size_t)yy * W + xx) * 4;
                if (memcmp(p, cc, 4)) printf(" %d,%d=%02x%02x%02x%02x", xx, yy, p[0], p[1], p[2], p[3]);
            }
            printf("\n");
        } else if (!strcmp(cmd, "depth")) {
            glFinish();
            sscanf(line, "%*s %63s", a);
            GLuint *d = malloc((size_t)W * H * 4);
            glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d);
            printf("%s:", a);
            for (int i = 0; i < W * H; i++) if (d[i] != 0xffffffffu) printf(" %d,%d=%06x", i % W, i / W, d[i] >> 8);
            printf("\n");
            free(d);
        } else {
            fprintf(stderr, "unknown command %s\n", cmd); return 2;
        }
    }
    return 0;
}
