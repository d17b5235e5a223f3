/* Evaluators compared with Mesa: Bézier curves (glEvalMesh1 lines and points, glEvalCoord1
 * with a color map, a rational quarter circle from GL_MAP1_VERTEX_4), a bicubic patch filled
 * and lit with GL_AUTO_NORMAL, its grid lines and points, a patch with a texture-coordinate
 * map and a color map, a rational patch with AUTO_NORMAL, a patch with a normal map, meshes
 * and maps compiled into a display list; the exact vertices of a mesh in feedback mode; the
 * glGetMap values of every target (initial and set, in the three types); the grid queries;
 * GL_EVAL_BIT; the errors. */
#include "common.h"

#define W 64
#define H 64

/* A cubic's four control points in [-0.9, 0.9]². */
static const GLfloat curve[4][3] = {{-0.9f, -0.8f, 0}, {-0.4f, 0.9f, 0}, {0.3f, -0.9f, 0}, {0.9f, 0.7f, 0}};

/* A bicubic bump: 4 × 4 control points over [-0.8, 0.8]², u along x, v along y. */
static GLfloat patch[4][4][3];

static void make_patch(void)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            patch[i][j][0] = -0.8f + 0.533333f * i;
            patch[i][j][1] = -0.8f + 0.533333f * j;
            patch[i][j][2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 0.9f : (i == 0 ? -0.3f : 0.0f);
        }
}

static void reset(void)
{
    glPopAttrib();
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glClearColor(0.1f, 0.1f, 0.15f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static void curves(void)
{
    reset();
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(30, 0, 1);
    glColor3f(1, 1, 0);
    glEvalMesh1(GL_LINE, 0, 30);
    glPointSize(3);
    glColor3f(0, 1, 1);
    glMapGrid1d(6, 0, 1);
    glEvalMesh1(GL_POINT, 0, 6);
    /* A color ramp along a shifted copy, of domain [0.5, 1.5] (extrapolated below 0.5), evaluated with glEvalCoord1. */
    static const GLfloat colors[2][4] = {{1, 0, 0, 1}, {0, 0, 1, 1}};
    glMap1f(GL_MAP1_COLOR_4, 0.5f, 1.5f, 4, 2, &colors[0][0]);
    glEnable(GL_MAP1_COLOR_4);
    glPushMatrix();
    glTranslatef(0, 0.15f, 0);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= 20; i++)
        glEvalCoord1f(i / 20.0f);
    glEnd();
    glPopMatrix();
    glDisable(GL_MAP1_COLOR_4);
    /* A rational quadratic: a quarter circle of radius 0.7 around (-0.9, -0.9). */
    const double s = 0.70710678118654752;
    const GLdouble arc[3][4] = {{-0.2, -0.9, 0, 1}, {-0.2 * s, -0.2 * s, 0, s}, {-0.9, -0.2, 0, 1}};
    glMap1d(GL_MAP1_VERTEX_4, 0, 1, 4, 3, &arc[0][0]);
    glEnable(GL_MAP1_VERTEX_4);
    glColor3f(0, 1, 0);
    glMapGrid1f(16, 0, 1);
    glEvalMesh1(GL_LINE, 0, 16);
    capi_save_framebuffer("curves", W, H);
}

static void lit(void)
{
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    const GLfloat position[4] = {0.5f, 1, 2, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    const GLfloat diffuse[4] = {0.9f, 0.6f, 0.3f, 1}, specular[4] = {1, 1, 1, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    /* One-sided: a mesh with u along x and v along y is clockwise (back-facing) while its
     * AUTO_NORMAL points to +z, towards the light. */
}

static void tilted(void)
{
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(-50, 1, 0, 0);
    glRotatef(20, 0, 0, 1);
}

static void patches(void)
{
    reset();
    tilted();
    lit();
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(12, 0, 1, 12, 0, 1);
    glEvalMesh2(GL_FILL, 0, 12, 0, 12);
    capi_save_framebuffer("patch_fill_lit", W, H);

    glShadeModel(GL_FLAT);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEvalMesh2(GL_FILL, 0, 12, 0, 12);
    capi_save_framebuffer("patch_fill_flat", W, H);

    reset();
    tilted();
    glEnable(GL_MAP2_VERTEX_3);
    glColor3f(1, 1, 1);
    glMapGrid2d(8, 0, 1, 6, 0, 1);
    glEvalMesh2(GL_LINE, 0, 8, 0, 6);
    glColor3f(1, 0, 0);
    glPointSize(2);
    glEvalMesh2(GL_POINT, 2, 6, 1, 5);
    capi_save_framebuffer("patch_line_point", W, H);
}

static void textured_patch(void)
{
    reset();
    tilted();
    GLubyte texels[8][8][4];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            GLubyte on = ((x ^ y) & 1) ? 255 : 60;
            texels[y][x][0] = on, texels[y][x][1] = on, texels[y][x][2] = on, texels[y][x][3] = 255;
        }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    static const GLfloat st[2][2][2] = {{{0, 0}, {0, 2}}, {{2, 0}, {2, 2}}};
    glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 4, 2, 0, 1, 2, 2, &st[0][0][0]);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
    static const GLfloat colors[2][2][4] = {{{1, 0.2f, 0.2f, 1}, {0.2f, 1, 0.2f, 1}}, {{0.2f, 0.2f, 1, 1}, {1, 1, 0.2f, 1}}};
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 8, 2, 0, 1, 4, 2, &colors[0][0][0]);
    glEnable(GL_MAP2_COLOR_4);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(10, 0, 1, 10, 0, 1);
    glEvalMesh2(GL_FILL, 0, 10, 0, 10);
    capi_save_framebuffer("patch_textured_colored", W, H);
    glDisable(GL_TEXTURE_2D);
}

static void rational_and_normal_maps(void)
{
    /* A rational patch (weights 1 at the corners, 2 inside) lit with GL_AUTO_NORMAL. */
    reset();
    tilted();
    lit();
    GLfloat weighted[4][4][4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            GLfloat w = (i == 1 || i == 2) && (j == 1 || j == 2) ? 2.0f : 1.0f;
            for (int k = 0; k < 3; k++)
                weighted[i][j][k] = patch[i][j][k] * w;
            weighted[i][j][3] = w;
        }
    glMap2f(GL_MAP2_VERTEX_4, 0, 1, 16, 4, 0, 1, 4, 4, &weighted[0][0][0]);
    glEnable(GL_MAP2_VERTEX_4);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(10, 0, 1, 10, 0, 1);
    glEvalMesh2(GL_FILL, 0, 10, 0, 10);
    capi_save_framebuffer("patch_rational_lit", W, H);

    /* The bump again, its normals from a bilinear normal map (no AUTO_NORMAL). */
    reset();
    tilted();
    lit();
    static const GLdouble normals[2][2][3] = {{{-0.6, -0.6, 0.5}, {-0.6, 0.6, 0.5}}, {{0.6, -0.6, 0.5}, {0.6, 0.6, 0.5}}};
    glMap2d(GL_MAP2_NORMAL, 0, 1, 6, 2, 0, 1, 3, 2, &normals[0][0][0]);
    glEnable(GL_MAP2_NORMAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_MAP2_VERTEX_3);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
    glMapGrid2f(10, 0, 1, 10, 0, 1);
    glEvalMesh2(GL_FILL, 0, 10, 0, 10);
    capi_save_framebuffer("patch_normal_map", W, H);
}

static void display_lists(void)
{
    reset();
    tilted();
    glEnable(GL_MAP2_VERTEX_3);
    static const GLfloat flat[2][2][3] = {{{-1, -1, 0}, {-1, 1, 0}}, {{1, -1, 0}, {1, 1, 0}}};
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, &flat[0][0][0]);
    /* The list sets its own map and grid (compiled with their values), then draws. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
    glMapGrid2f(5, 0, 1, 5, 0, 1);
    glColor3f(1, 0.5f, 0);
    glEvalMesh2(GL_LINE, 0, 5, 0, 5);
    /* (The color is set outside glBegin: Mesa 22 loses a glColor compiled between glBegin and
     * a glEvalCoord/glEvalPoint of a list.) */
    glColor3f(0, 1, 0);
    glBegin(GL_POINTS);
    glEvalPoint2(1, 1);
    glEvalCoord2f(0.5f, 0.5f);
    glEnd();
    glEndList();
    capi_expect_error(GL_NO_ERROR, "compiling evaluators");
    GLint order[2] = {0, 0};
    glGetMapiv(GL_MAP2_VERTEX_3, GL_ORDER, order);
    capi_check(order[0] == 2 && order[1] == 2, "glMap2 is only compiled under GL_COMPILE: %d %d", order[0], order[1]);
    /* Another grid now: the list sets its own. */
    glMapGrid2f(2, 0, 1, 2, 0, 1);
    glPointSize(3);
    glCallList(list);
    glGetMapiv(GL_MAP2_VERTEX_3, GL_ORDER, order);
    capi_value("list.order", "%d %d", order[0], order[1]);
    GLint segments[2];
    glGetIntegerv(GL_MAP2_GRID_SEGMENTS, segments);
    capi_value("list.segments", "%d %d", segments[0], segments[1]);
    capi_save_framebuffer("display_list", W, H);
    glDeleteLists(list, 1);
}

/* The window coordinates of glEvalMesh1's points in feedback mode (dyadic control points
 * and grid: exact on every implementation). */
static void feedback(void)
{
    reset();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    static const GLfloat dyadic[4][3] = {{-1, -1, 0}, {-0.5f, 1, 0.5f}, {0.5f, -1, -0.5f}, {1, 1, 0}};
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &dyadic[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(4, 0, 1);
    static GLfloat buffer[256];
    glFeedbackBuffer(256, GL_3D, buffer);
    glRenderMode(GL_FEEDBACK);
    glEvalMesh1(GL_POINT, 0, 4);
    glBegin(GL_POINTS);
    glEvalPoint1(1);
    glEvalCoord1d(0.75);
    glEnd();
    int n = glRenderMode(GL_RENDER);
    capi_value("feedback.count", "%d", n);
    for (int i = 0; i + 3 < n; i += 4)
        capi_value("feedback.point", "%.0f %.4f %.4f %.4f", buffer[i], buffer[i + 1], buffer[i + 2], buffer[i + 3]);
}

/* Which maps feed which attributes, read back exactly through GL_3D_COLOR_TEXTURE feedback:
 * texture maps of 1 to 4 components (the missing components 0, 0, 1), the map of the most
 * components winning, color and normal maps (lit), a reversed domain, a rational vertex map,
 * AUTO_NORMAL over a normal map, meshes with an empty range or without a vertex map. */
static void print_feedback(const char *stage, GLfloat *buffer, int n)
{
    char key[64], tex_key[64];
    snprintf(key, sizeof key, "attributes.%s.count", stage);
    capi_value(key, "%d", n);
    snprintf(key, sizeof key, "attributes.%s", stage);
    snprintf(tex_key, sizeof tex_key, "attributes.%s.stpq", stage);
    for (int i = 0; i + 11 < n; i += 12) {
        capi_value(key, "%.0f xyz %.4f %.4f %.4f rgba %.4f %.4f %.4f %.4f", buffer[i], buffer[i + 1], buffer[i + 2],
                   buffer[i + 3], buffer[i + 4], buffer[i + 5], buffer[i + 6], buffer[i + 7]);
        capi_value(tex_key, "%.4f %.4f %.4f %.4f", buffer[i + 8], buffer[i + 9], buffer[i + 10], buffer[i + 11]);
    }
}

/* Mesa 22 breaks the rule that evaluation leaves the current values alone for the texture
 * coordinates: after a 3-component texture map, its current q is 1 (and later vertices get
 * that), and after the 1D texture maps the 2D meshes, which map no texture coordinates, get
 * (0.8, 9, 8, 1) instead of the current (9, 8, 7, 6). Those keys are free in the manifest;
 * tessera is checked against the specification here. */
static void check_current_tex(const char *what, const GLfloat *stpq)
{
    if (capi_is_tessera())
        capi_check(stpq[0] == 9 && stpq[1] == 8 && stpq[2] == 7 && stpq[3] == 6, "%s: current texture coordinates "
                   "(%g %g %g %g)", what, stpq[0], stpq[1], stpq[2], stpq[3]);
}

static void attributes(void)
{
    reset();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    static GLfloat buffer[1024];
    static const GLfloat line[2][3] = {{-0.5f, -0.5f, 0}, {0.5f, 0.25f, 0.5f}};
    static const GLfloat tex4[2][4] = {{0.25f, 0.5f, 0.75f, 1}, {1, 0.75f, 0.5f, 2}};
    static const GLfloat colors[2][4] = {{1, 0, 0, 1}, {0, 0.5f, 1, 0.5f}};
    glMap1f(GL_MAP1_VERTEX_3, 1, 0, 3, 2, &line[0][0]); /* reversed domain */
    glEnable(GL_MAP1_VERTEX_3);
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glTexCoord4f(9, 8, 7, 6);
    for (int components = 1; components <= 4; components++) {
        const GLenum target = GL_MAP1_TEXTURE_COORD_1 + components - 1;
        glMap1f(target, 0, 1, 4, 2, &tex4[0][0]);
        glEnable(target);
        glFeedbackBuffer(1024, GL_3D_COLOR_TEXTURE, buffer);
        glRenderMode(GL_FEEDBACK);
        glBegin(GL_POINTS);
        glEvalCoord1f(0.25f);
        glEnd();
        char stage[32];
        snprintf(stage, sizeof stage, "tex%d", components);
        print_feedback(stage, buffer, glRenderMode(GL_RENDER));
    }
    /* All four enabled: TEXTURE_COORD_4 wins; now a color map, and the current values stay. */
    glMap1f(GL_MAP1_COLOR_4, 0, 1, 4, 2, &colors[0][0]);
    glEnable(GL_MAP1_COLOR_4);
    glDisable(GL_MAP1_TEXTURE_COORD_4);
    glFeedbackBuffer(1024, GL_3D_COLOR_TEXTURE, buffer);
    glRenderMode(GL_FEEDBACK);
    glMapGrid1f(2, 0, 1);
    glEvalMesh1(GL_POINT, 0, 2);
    glEvalMesh1(GL_LINE, 2, 1); /* an empty range: an empty strip */
    glBegin(GL_POINTS);
    glEvalPoint1(-1);
    glVertex2f(0, 0);
    glEnd();
    print_feedback("color_tex3", buffer, glRenderMode(GL_RENDER));
    check_current_tex("glVertex after glEvalPoint", &buffer[4 * 12 + 8]);
    GLfloat current[4];
    glGetFloatv(GL_CURRENT_COLOR, current);
    capi_value("attributes.current_color", "%a %a %a %a", current[0], current[1], current[2], current[3]);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, current);
    capi_value("attributes.current_tex", "%a %a %a %a", current[0], current[1], current[2], current[3]);
    check_current_tex("GL_CURRENT_TEXTURE_COORDS", current);

    /* Lit: a normal map along a curve; then a rational vertex map. */
    glDisable(GL_MAP1_COLOR_4);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    static const GLfloat normals[3][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 1}};
    glMap1f(GL_MAP1_NORMAL, 0, 1, 3, 3, &normals[0][0]);
    glEnable(GL_MAP1_NORMAL);
    glEnable(GL_NORMALIZE);
    static const GLfloat rational[3][4] = {{-0.5f, 0, 0, 1}, {0, 0.5f, 0, 0.5f}, {0.5f, 0, 0.25f, 2}};
    glMap1f(GL_MAP1_VERTEX_4, 0, 1, 4, 3, &rational[0][0]);
    glEnable(GL_MAP1_VERTEX_4);
    glFeedbackBuffer(1024, GL_3D_COLOR_TEXTURE, buffer);
    glRenderMode(GL_FEEDBACK);
    glMapGrid1f(4, 0, 1);
    glEvalMesh1(GL_POINT, 0, 4);
    print_feedback("lit_rational", buffer, glRenderMode(GL_RENDER));
    glDisable(GL_MAP1_VERTEX_4);
    glDisable(GL_MAP1_VERTEX_3);
    glFeedbackBuffer(1024, GL_3D_COLOR_TEXTURE, buffer);
    glRenderMode(GL_FEEDBACK);
    glEvalMesh1(GL_POINT, 0, 4);
    glBegin(GL_POINTS);
    glEvalCoord1f(0.5f);
    glEnd();
    print_feedback("no_vertex_map", buffer, glRenderMode(GL_RENDER));

    /* 2D: AUTO_NORMAL takes precedence over an enabled normal map. */
    static const GLfloat square[2][2][3] = {{{-0.5f, -0.5f, 0}, {-0.5f, 0.5f, 0}}, {{0.5f, -0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}}};
    static const GLfloat down[3] = {0, 0, -1};
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, &square[0][0][0]);
    glMap2f(GL_MAP2_NORMAL, 0, 1, 3, 1, 0, 1, 3, 1, down);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_NORMAL);
    glMapGrid2f(2, 0, 1, 1, 0, 1);
    for (int automatic = 0; automatic < 2; automatic++) {
        if (automatic)
            glEnable(GL_AUTO_NORMAL);
        glFeedbackBuffer(1024, GL_3D_COLOR_TEXTURE, buffer);
        glRenderMode(GL_FEEDBACK);
        glEvalMesh2(GL_POINT, 0, 2, 0, 1);
        glEvalMesh2(GL_FILL, 0, 2, 1, 1); /* no row of cells: nothing */
        print_feedback(automatic ? "auto_normal" : "normal_map", buffer, glRenderMode(GL_RENDER));
        check_current_tex("2D mesh", &buffer[8]);
    }
    capi_expect_error(GL_NO_ERROR, "attributes");
}

static void print_map(const char *name, GLenum target, int values)
{
    GLfloat f[64];
    GLdouble d[64];
    GLint iv[64];
    char key[96];
    for (int q = 0; q < 3; q++) {
        const GLenum query = q == 0 ? GL_COEFF : q == 1 ? GL_ORDER : GL_DOMAIN;
        const int count = q == 0 ? values : q == 1 ? (target >= GL_MAP2_COLOR_4 ? 2 : 1) : (target >= GL_MAP2_COLOR_4 ? 4 : 2);
        for (int i = 0; i < 64; i++)
            f[i] = -99, d[i] = -99, iv[i] = -99;
        glGetMapfv(target, query, f);
        glGetMapdv(target, query, d);
        glGetMapiv(target, query, iv);
        capi_check(f[count] == -99 && d[count] == -99 && iv[count] == -99, "%s %d writes %d values", name, q, count);
        for (int i = 0; i < count; i++) {
            snprintf(key, sizeof key, "map.%s.%d.%d", name, q, i);
            capi_value(key, "%a %a %d", f[i], d[i], iv[i]);
        }
    }
}

static void queries(void)
{
    reset();
    /* Initial maps: order 1, domain [0, 1], the default value of each attribute. */
    static const struct {
        const char *name;
        GLenum target;
        int components;
    } maps[] = {
        {"map1_color4", GL_MAP1_COLOR_4, 4}, {"map1_index", GL_MAP1_INDEX, 1},
        {"map1_normal", GL_MAP1_NORMAL, 3}, {"map1_tex1", GL_MAP1_TEXTURE_COORD_1, 1},
        {"map1_tex2", GL_MAP1_TEXTURE_COORD_2, 2}, {"map1_tex3", GL_MAP1_TEXTURE_COORD_3, 3},
        {"map1_tex4", GL_MAP1_TEXTURE_COORD_4, 4}, {"map1_vertex3", GL_MAP1_VERTEX_3, 3},
        {"map1_vertex4", GL_MAP1_VERTEX_4, 4}, {"map2_color4", GL_MAP2_COLOR_4, 4},
        {"map2_index", GL_MAP2_INDEX, 1}, {"map2_normal", GL_MAP2_NORMAL, 3},
        {"map2_tex1", GL_MAP2_TEXTURE_COORD_1, 1}, {"map2_tex2", GL_MAP2_TEXTURE_COORD_2, 2},
        {"map2_tex3", GL_MAP2_TEXTURE_COORD_3, 3}, {"map2_tex4", GL_MAP2_TEXTURE_COORD_4, 4},
        {"map2_vertex3", GL_MAP2_VERTEX_3, 3}, {"map2_vertex4", GL_MAP2_VERTEX_4, 4},
    };
    for (unsigned m = 0; m < sizeof maps / sizeof maps[0]; m++) {
        print_map(maps[m].name, maps[m].target, maps[m].components);
        capi_check(!glIsEnabled(maps[m].target), "%s starts disabled", maps[m].name);
    }
    capi_expect_error(GL_NO_ERROR, "initial maps");

    /* Set maps: strides larger than the point, values that round both ways as integers. */
    const GLfloat strided[3 * 5] = {1.5f, -2.5f, 0.49f, 9, 9, 3.25f, 4.75f, -0.5f, 9, 9, 100.6f, -7.4f, 2.5f, 9, 9};
    glMap1f(GL_MAP1_NORMAL, -1.5f, 2.5f, 5, 3, strided);
    print_map("set_map1_normal", GL_MAP1_NORMAL, 9);
    const GLdouble grid[2][3][2] = {{{0.1, 0.2}, {0.3, 0.4}, {0.5, 0.6}}, {{-0.1, -0.2}, {-0.3, -0.4}, {-0.5, -0.6}}};
    glMap2d(GL_MAP2_TEXTURE_COORD_1, 0.25, -3.75, 6, 2, 10, 11, 2, 3, &grid[0][0][0]);
    print_map("set_map2_tex1", GL_MAP2_TEXTURE_COORD_1, 6);
    capi_expect_error(GL_NO_ERROR, "set maps");

    /* Grids. */
    capi_value_query("grid.initial", "MAP1_GRID_DOMAIN", GL_MAP1_GRID_DOMAIN, 2);
    capi_value_query("grid.initial", "MAP1_GRID_SEGMENTS", GL_MAP1_GRID_SEGMENTS, 1);
    capi_value_query("grid.initial", "MAP2_GRID_DOMAIN", GL_MAP2_GRID_DOMAIN, 4);
    capi_value_query("grid.initial", "MAP2_GRID_SEGMENTS", GL_MAP2_GRID_SEGMENTS, 2);
    capi_value_query("grid.initial", "MAX_EVAL_ORDER", GL_MAX_EVAL_ORDER, 1);
    capi_value_query("grid.initial", "AUTO_NORMAL", GL_AUTO_NORMAL, 1);
    glMapGrid1d(7, 2.5, -1.25);
    glMapGrid2f(3, 0.5f, 1.5f, 9, -2, 2.75f);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_MAP2_INDEX);
    capi_value_query("grid.set", "MAP1_GRID_DOMAIN", GL_MAP1_GRID_DOMAIN, 2);
    capi_value_query("grid.set", "MAP1_GRID_SEGMENTS", GL_MAP1_GRID_SEGMENTS, 1);
    capi_value_query("grid.set", "MAP2_GRID_DOMAIN", GL_MAP2_GRID_DOMAIN, 4);
    capi_value_query("grid.set", "MAP2_GRID_SEGMENTS", GL_MAP2_GRID_SEGMENTS, 2);
    capi_value_query("grid.set", "AUTO_NORMAL", GL_AUTO_NORMAL, 1);
    capi_value_query("grid.set", "MAP2_INDEX", GL_MAP2_INDEX, 1);

    /* GL_EVAL_BIT: enables and grids come back; the maps are no attribute state. */
    glPushAttrib(GL_EVAL_BIT);
    glMapGrid1f(2, 0, 1);
    glMapGrid2f(4, 0, 1, 5, 0, 1);
    glDisable(GL_AUTO_NORMAL);
    glDisable(GL_MAP2_INDEX);
    glEnable(GL_MAP1_VERTEX_4);
    const GLfloat one = 42;
    glMap1f(GL_MAP1_INDEX, 0, 1, 1, 1, &one);
    glPopAttrib();
    capi_value_query("eval_bit", "MAP1_GRID_DOMAIN", GL_MAP1_GRID_DOMAIN, 2);
    capi_value_query("eval_bit", "MAP1_GRID_SEGMENTS", GL_MAP1_GRID_SEGMENTS, 1);
    capi_value_query("eval_bit", "MAP2_GRID_DOMAIN", GL_MAP2_GRID_DOMAIN, 4);
    capi_value_query("eval_bit", "MAP2_GRID_SEGMENTS", GL_MAP2_GRID_SEGMENTS, 2);
    capi_check(glIsEnabled(GL_AUTO_NORMAL) && glIsEnabled(GL_MAP2_INDEX) && !glIsEnabled(GL_MAP1_VERTEX_4),
               "GL_EVAL_BIT restores the enables");
    GLfloat index = 0;
    glGetMapfv(GL_MAP1_INDEX, GL_COEFF, &index);
    capi_check(index == 42, "maps stay after glPopAttrib: %g", index);
    capi_expect_error(GL_NO_ERROR, "grids and GL_EVAL_BIT");
}

static void errors(void)
{
    reset();
    const GLfloat points[64] = {0};
    GLfloat f[16] = {0};
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, points);
    capi_expect_error(GL_NO_ERROR, "valid glMap1f");
    glMap1f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, points);
    capi_expect_error(GL_INVALID_ENUM, "glMap1f with a 2D target");
    glMap1f(GL_TEXTURE_2D, 0, 1, 3, 2, points);
    capi_expect_error(GL_INVALID_ENUM, "glMap1f with a bad target");
    glMap1f(GL_MAP1_VERTEX_3, 1, 1, 3, 2, points);
    capi_expect_error(GL_INVALID_VALUE, "glMap1f u1 == u2");
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 2, 2, points);
    capi_expect_error(GL_INVALID_VALUE, "glMap1f stride < 3");
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, points);
    capi_expect_error(GL_INVALID_VALUE, "glMap1f order 0");
    GLint max_order = 0;
    glGetIntegerv(GL_MAX_EVAL_ORDER, &max_order);
    glMap1f(GL_MAP1_INDEX, 0, 1, 1, max_order + 1, points);
    capi_expect_error(GL_INVALID_VALUE, "glMap1f order above GL_MAX_EVAL_ORDER");
    glMap1f(GL_MAP1_INDEX, 0, 1, 1, max_order, points);
    capi_expect_error(GL_NO_ERROR, "glMap1f order GL_MAX_EVAL_ORDER");
    glMap2f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, points);
    capi_expect_error(GL_INVALID_ENUM, "glMap2f with a 1D target");
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 1, 1, 6, 2, points);
    capi_expect_error(GL_INVALID_VALUE, "glMap2f v1 == v2");
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 0, points);
    capi_expect_error(GL_INVALID_VALUE, "glMap2f vorder 0");
    glMap2d(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 3, 2, (const GLdouble *)points);
    capi_expect_error(GL_INVALID_VALUE, "glMap2d vstride < 4");
    glActiveTexture(GL_TEXTURE1);
    glMap1f(GL_MAP1_TEXTURE_COORD_2, 0, 1, 2, 2, points);
    capi_expect_error(GL_INVALID_OPERATION, "glMap1f with active texture unit 1");
    glActiveTexture(GL_TEXTURE0);
    glGetMapfv(GL_MAP1_VERTEX_3, GL_ORDER, f);
    capi_check(f[0] == 4, "the rejected maps changed nothing: order %g", f[0]);
    glGetMapfv(GL_MAP1_GRID_DOMAIN, GL_COEFF, f);
    capi_expect_error(GL_INVALID_ENUM, "glGetMapfv with a bad target");
    glGetMapiv(GL_MAP1_VERTEX_3, GL_MAP1_GRID_DOMAIN, (GLint *)f);
    capi_expect_error(GL_INVALID_ENUM, "glGetMapiv with a bad query");
    glMapGrid1f(0, 0, 1);
    capi_expect_error(GL_INVALID_VALUE, "glMapGrid1f 0 segments");
    glMapGrid2d(1, 0, 1, -1, 0, 1);
    capi_expect_error(GL_INVALID_VALUE, "glMapGrid2d -1 segments");
    glEvalMesh1(GL_FILL, 0, 1);
    capi_expect_error(GL_INVALID_ENUM, "glEvalMesh1 GL_FILL");
    glEvalMesh2(GL_TRIANGLES, 0, 1, 0, 1);
    capi_expect_error(GL_INVALID_ENUM, "glEvalMesh2 bad mode");
    /* Between glBegin and glEnd: glMap, glMapGrid, glEvalMesh and glGetMap are illegal;
     * glEvalCoord and glEvalPoint are legal. */
    glEnable(GL_MAP1_VERTEX_3);
    glBegin(GL_POINTS);
    glEvalCoord1f(0.5f);
    glEvalPoint1(0);
    glEvalCoord2fv((const GLfloat[]){0.5f, 0.5f});
    glEvalPoint2(0, 0);
    glEvalCoord1dv((const GLdouble[]){0.25});
    glEvalCoord2dv((const GLdouble[]){0.25, 0.75});
    glEnd();
    capi_expect_error(GL_NO_ERROR, "glEvalCoord and glEvalPoint inside glBegin/glEnd");
    const struct {
        const char *name;
        int which;
    } illegal[] = {{"glMap1f", 0}, {"glMap2f", 1}, {"glMapGrid1f", 2}, {"glMapGrid2f", 3},
                   {"glEvalMesh1", 4}, {"glEvalMesh2", 5}, {"glGetMapfv", 6}};
    for (unsigned k = 0; k < sizeof illegal / sizeof illegal[0]; k++) {
        glBegin(GL_POINTS);
        switch (illegal[k].which) {
        case 0: glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, points); break;
        case 1: glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, points); break;
        case 2: glMapGrid1f(3, 0, 1); break;
        case 3: glMapGrid2f(3, 0, 1, 3, 0, 1); break;
        case 4: glEvalMesh1(GL_POINT, 0, 1); break;
        case 5: glEvalMesh2(GL_POINT, 0, 1, 0, 1); break;
        default: glGetMapfv(GL_MAP1_VERTEX_3, GL_ORDER, f); break;
        }
        glEnd();
        capi_expect_error(GL_INVALID_OPERATION, illegal[k].name);
    }
    glGetMapfv(GL_MAP1_VERTEX_3, GL_ORDER, f);
    capi_check(f[0] == 4, "glMap1f inside glBegin/glEnd changed nothing: order %g", f[0]);
    capi_value_query("errors", "MAP1_GRID_SEGMENTS", GL_MAP1_GRID_SEGMENTS, 1);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    make_patch();
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    queries(); /* first: the maps are still the initial ones */
    errors();
    curves();
    patches();
    textured_patch();
    rational_and_normal_maps();
    display_lists();
    feedback();
    attributes();
    return capi_finish();
}
