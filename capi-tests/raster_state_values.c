/* The rasterization state setters and their queries: glShadeModel, glProvokingVertex,
 * glFrontFace, glCullFace, glPolygonMode, glPolygonOffset(Clamp), glLineWidth, glLineStipple,
 * glPointSize and glPointParameter in all its forms. Every query is printed in all four types
 * (%a for floats) initially, after setting values (including extreme ones, which are kept
 * unclamped), and after each error, which must change nothing. Then the attribute groups that
 * hold this state (GL_POLYGON_BIT, GL_LINE_BIT, GL_POINT_BIT, GL_LIGHTING_BIT) and the
 * GL_INVALID_OPERATION of every setter between glBegin and glEnd (when glBegin exists).
 *
 * The implementation limits (GL_*_RANGE, GL_*_GRANULARITY) describe each rasterizer and are
 * checked against each implementation's own values, not compared. Mesa 22's GL_LIGHTING_BIT
 * does not restore GL_PROVOKING_VERTEX, which ARB_provoking_vertex puts in that group:
 * checked per implementation.
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"

#define W 8
#define H 8

struct query {
    const char *name;
    GLenum pname;
    int count;
};
#define Q(p, n) {#p, p, n}

static const struct query queries[] = {
    Q(GL_SHADE_MODEL, 1),        Q(GL_PROVOKING_VERTEX, 1),           Q(GL_FRONT_FACE, 1),
    Q(GL_CULL_FACE_MODE, 1),     Q(GL_POLYGON_MODE, 2),               Q(GL_POLYGON_OFFSET_FACTOR, 1),
    Q(GL_POLYGON_OFFSET_UNITS, 1), Q(GL_POLYGON_OFFSET_CLAMP, 1),     Q(GL_LINE_WIDTH, 1),
    Q(GL_LINE_STIPPLE_PATTERN, 1), Q(GL_LINE_STIPPLE_REPEAT, 1),      Q(GL_POINT_SIZE, 1),
    Q(GL_POINT_SIZE_MIN, 1),     Q(GL_POINT_SIZE_MAX, 1),             Q(GL_POINT_FADE_THRESHOLD_SIZE, 1),
    Q(GL_POINT_DISTANCE_ATTENUATION, 3), Q(GL_POINT_SPRITE_COORD_ORIGIN, 1),
};
#define NQUERIES (int)(sizeof queries / sizeof queries[0])

static PFNGLPOLYGONOFFSETCLAMPPROC polygon_offset_clamp;

/* Prints every query in the four types under "<stage>.<name>". */
static void print_all(const char *stage)
{
    for (int q = 0; q < NQUERIES; q++) {
        capi_value_query(stage, queries[q].name, queries[q].pname, queries[q].count);
    }
    capi_expect_error(GL_NO_ERROR, stage);
}

static void set_values(void)
{
    glShadeModel(GL_FLAT);
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    glFrontFace(GL_CW);
    glCullFace(GL_FRONT_AND_BACK);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glPolygonOffset(2.5f, -3.5f);
    glLineWidth(2.4999998f);
    glLineStipple(3, 0xa5c3);
    glPointSize(7.5f);
    glPointParameterf(GL_POINT_SIZE_MIN, 1.5f);
    glPointParameterf(GL_POINT_SIZE_MAX, 64.25f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 0.1f);
    static const GLfloat attenuation[3] = {0.5f, -0.25f, 1e-7f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    capi_expect_error(GL_NO_ERROR, "set_values");
}

/* Values beyond every range are kept as given; the point parameter forms convert. */
static void extremes(void)
{
    glLineWidth(300.0f);
    glPointSize(1000.0f);
    glPointParameterf(GL_POINT_SIZE_MIN, 300.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 0.0f);
    glLineStipple(0, 0x1234);
    capi_expect_error(GL_NO_ERROR, "extremes");
    print_all("extremes");
    glLineStipple(-7, 0xffff);
    glGetError();
    GLint repeat;
    glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &repeat);
    capi_value("stipple_negative_factor", "%d", repeat);
    glLineStipple(1000, 0x8001);
    glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &repeat);
    capi_value("stipple_big_factor", "%d", repeat);
    glLineStipple(256, 1);
    glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &repeat);
    capi_value("stipple_256", "%d", repeat);

    /* The scalar forms of GL_POINT_DISTANCE_ATTENUATION set (param, 0, 0), as in Mesa. */
    glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 5.0f);
    capi_expect_error(GL_NO_ERROR, "attenuation_f");
    print_all("attenuation_f");
    glPointParameteri(GL_POINT_DISTANCE_ATTENUATION, 3);
    capi_expect_error(GL_NO_ERROR, "attenuation_i");
    static const GLint attenuation_i[3] = {2, -3, 16777217};
    glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, attenuation_i);
    capi_expect_error(GL_NO_ERROR, "attenuation_iv");
    print_all("attenuation_iv");
    static const GLint min_i = 3, origin_i = GL_UPPER_LEFT;
    glPointParameteriv(GL_POINT_SIZE_MIN, &min_i);
    glPointParameteriv(GL_POINT_SPRITE_COORD_ORIGIN, &origin_i);
    static const GLfloat fade = 2.75f;
    glPointParameterfvARB(GL_POINT_FADE_THRESHOLD_SIZE, &fade);
    glPointParameterfARB(GL_POINT_SIZE_MAX, 33.0f);
    glPointParameterfEXT(GL_POINT_SIZE_MIN, 0.0f);
    static const GLfloat max_f = 12.0f;
    glPointParameterfvEXT(GL_POINT_SIZE_MAX, &max_f);
    /* A float origin is truncated to the enum. */
    glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, (GLfloat)GL_LOWER_LEFT + 0.75f);
    capi_expect_error(GL_NO_ERROR, "point_forms");
    print_all("point_forms");
    glProvokingVertexEXT(GL_LAST_VERTEX_CONVENTION);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPolygonMode(GL_BACK, GL_LINE);
    capi_expect_error(GL_NO_ERROR, "modes");
    print_all("modes");
}

static void offset_clamp(void)
{
    GLfloat clamp = -1;
    if (!polygon_offset_clamp)
        return;
    polygon_offset_clamp(1.0f, 2.0f, 0.75f);
    glGetFloatv(GL_POLYGON_OFFSET_CLAMP, &clamp);
    capi_value("offset_clamp", "%a", clamp);
    polygon_offset_clamp(-1.0f, 0.5f, -3.0f);
    glGetFloatv(GL_POLYGON_OFFSET_CLAMP, &clamp);
    capi_value("offset_clamp_negative", "%a", clamp);
    glPolygonOffset(4.0f, 8.0f); /* resets the clamp to 0 */
    glGetFloatv(GL_POLYGON_OFFSET_CLAMP, &clamp);
    capi_value("offset_clamp_reset", "%a", clamp);
    PFNGLPOLYGONOFFSETCLAMPEXTPROC ext = (PFNGLPOLYGONOFFSETCLAMPEXTPROC)OSMesaGetProcAddress("glPolygonOffsetClampEXT");
    capi_check(ext != NULL, "glPolygonOffsetClampEXT exists");
    if (ext) {
        ext(1.0f, 1.0f, 0.5f);
        glGetFloatv(GL_POLYGON_OFFSET_CLAMP, &clamp);
        capi_value("offset_clamp_ext", "%a", clamp);
    }
    capi_expect_error(GL_NO_ERROR, "offset_clamp");
}

static void errors(void)
{
    set_values();
    glShadeModel(GL_FRONT);
    capi_expect_error(GL_INVALID_ENUM, "shade_model_bad");
    glShadeModel(0);
    capi_expect_error(GL_INVALID_ENUM, "shade_model_zero");
    glProvokingVertex(GL_FLAT);
    capi_expect_error(GL_INVALID_ENUM, "provoking_bad");
    glFrontFace(GL_FRONT);
    capi_expect_error(GL_INVALID_ENUM, "front_face_bad");
    glCullFace(GL_FRONT_LEFT);
    capi_expect_error(GL_INVALID_ENUM, "cull_face_bad");
    glCullFace(GL_CCW);
    capi_expect_error(GL_INVALID_ENUM, "cull_face_ccw");
    glPolygonMode(GL_FRONT_LEFT, GL_LINE);
    capi_expect_error(GL_INVALID_ENUM, "polygon_mode_face");
    glPolygonMode(GL_FRONT, GL_FRONT);
    capi_expect_error(GL_INVALID_ENUM, "polygon_mode_mode");
    glPolygonMode(GL_BACK, GL_FILL_RECTANGLE_NV);
    capi_expect_error(GL_INVALID_ENUM, "polygon_mode_fill_rectangle");
    glLineWidth(0.0f);
    capi_expect_error(GL_INVALID_VALUE, "line_width_zero");
    glLineWidth(-1.0f);
    capi_expect_error(GL_INVALID_VALUE, "line_width_negative");
    glLineWidth(-0.0f);
    capi_expect_error(GL_INVALID_VALUE, "line_width_negative_zero");
    glPointSize(0.0f);
    capi_expect_error(GL_INVALID_VALUE, "point_size_zero");
    glPointSize(-2.0f);
    capi_expect_error(GL_INVALID_VALUE, "point_size_negative");
    glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
    capi_expect_error(GL_INVALID_VALUE, "point_min_negative");
    glPointParameterf(GL_POINT_SIZE_MAX, -0.5f);
    capi_expect_error(GL_INVALID_VALUE, "point_max_negative");
    glPointParameteri(GL_POINT_FADE_THRESHOLD_SIZE, -1);
    capi_expect_error(GL_INVALID_VALUE, "point_fade_negative");
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_RGBA);
    capi_expect_error(GL_INVALID_VALUE, "point_origin_bad");
    glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, -1.0f);
    capi_expect_error(GL_INVALID_VALUE, "point_origin_negative");
    glPointParameterf(GL_POINT_SIZE, 1.0f);
    capi_expect_error(GL_INVALID_ENUM, "point_parameter_pname");
    glPointParameteri(GL_POINT_SPRITE_R_MODE_NV, GL_ZERO);
    capi_expect_error(GL_INVALID_ENUM, "point_parameter_r_mode");
    static const GLfloat one = 1.0f;
    glPointParameterfv(0, &one);
    capi_expect_error(GL_INVALID_ENUM, "point_parameter_zero");
    print_all("after_errors");
    if (capi_is_tessera()) {
        /* NULL vectors are ignored (Mesa 22 dereferences them). */
        glPointParameterfv(GL_POINT_SIZE_MIN, NULL);
        glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, NULL);
        capi_check(glGetError() == GL_NO_ERROR, "NULL point parameters");
    }
}

static void limits(void)
{
    GLfloat aliased_line[2], smooth_line[2], line_step, aliased_point[2], smooth_point[2], point_step;
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, aliased_line);
    glGetFloatv(GL_LINE_WIDTH_RANGE, smooth_line);
    glGetFloatv(GL_LINE_WIDTH_GRANULARITY, &line_step);
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, aliased_point);
    glGetFloatv(GL_POINT_SIZE_RANGE, smooth_point);
    glGetFloatv(GL_POINT_SIZE_GRANULARITY, &point_step);
    capi_expect_error(GL_NO_ERROR, "limits");
    /* Each implementation's own rasterizer limits. */
    float step = capi_is_tessera() ? 0.125f : 0.1f;
    capi_check(aliased_line[0] == 1.0f && aliased_line[1] == 255.0f, "aliased line widths %g..%g", aliased_line[0],
               aliased_line[1]);
    capi_check(smooth_line[0] == 1.0f && smooth_line[1] == 255.0f, "smooth line widths %g..%g", smooth_line[0],
               smooth_line[1]);
    capi_check(aliased_point[0] == 1.0f && aliased_point[1] == 255.0f, "aliased point sizes %g..%g", aliased_point[0],
               aliased_point[1]);
    capi_check(smooth_point[0] == 1.0f && smooth_point[1] == 255.0f, "smooth point sizes %g..%g", smooth_point[0],
               smooth_point[1]);
    capi_check(line_step == step && point_step == step, "granularities %g %g", line_step, point_step);
}

/* Every query as doubles, for before/after comparisons that are not printed. */
static void snapshot(GLdouble out[NQUERIES][4])
{
    for (int q = 0; q < NQUERIES; q++)
        glGetDoublev(queries[q].pname, out[q]);
}

/* Push a group, change everything, pop, print what came back. */
static void attribute_groups(void)
{
    static const GLbitfield groups[] = {GL_POLYGON_BIT, GL_LINE_BIT, GL_POINT_BIT, GL_LIGHTING_BIT, GL_ENABLE_BIT};
    static const char *names[] = {"polygon_bit", "line_bit", "point_bit", "lighting_bit", "enable_bit"};
    for (unsigned g = 0; g < sizeof groups / sizeof groups[0]; g++) {
        glPushAttrib(groups[g]);
        set_values();
        GLint provoking;
        glGetIntegerv(GL_PROVOKING_VERTEX, &provoking);
        glPopAttrib();
        GLint restored;
        glGetIntegerv(GL_PROVOKING_VERTEX, &restored);
        int tessera_restores = groups[g] == GL_LIGHTING_BIT && capi_is_tessera();
        capi_check(restored == (tessera_restores ? GL_LAST_VERTEX_CONVENTION : GL_FIRST_VERTEX_CONVENTION),
                   "%s: GL_PROVOKING_VERTEX 0x%x", names[g], restored);
        glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); /* same on both for the print */
        print_all(names[g]);
        /* Back to the initial values for the next group. */
        glShadeModel(GL_SMOOTH);
        glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
        glFrontFace(GL_CCW);
        glCullFace(GL_BACK);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glPolygonOffset(0.0f, 0.0f);
        glLineWidth(1.0f);
        glLineStipple(1, 0xffff);
        glPointSize(1.0f);
        glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
        glPointParameterf(GL_POINT_SIZE_MAX, 255.0f);
        glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 1.0f);
        static const GLfloat attenuation[3] = {1.0f, 0.0f, 0.0f};
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
        glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    }
    capi_expect_error(GL_NO_ERROR, "attribute_groups");
}

static void inside_begin_end(void)
{
    void (*begin)(GLenum) = (void (*)(GLenum))OSMesaGetProcAddress("glBegin");
    void (*end)(void) = (void (*)(void))OSMesaGetProcAddress("glEnd");
    if (!begin || !end)
        return;
    static const GLfloat three[3] = {2, 3, 4};
    static const GLint three_i[3] = {2, 3, 4};
    static GLdouble before[NQUERIES][4], after[NQUERIES][4];
    snapshot(before);
    for (int i = 0; i <= 16; i++) {
        begin(GL_TRIANGLES);
        switch (i) {
        case 0: glShadeModel(GL_FLAT); break;
        case 1: glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); break;
        case 2: glFrontFace(GL_CW); break;
        case 3: glCullFace(GL_FRONT); break;
        case 4: glPolygonMode(GL_FRONT, GL_LINE); break;
        case 5: glPolygonOffset(1, 1); break;
        case 6: glLineWidth(2); break;
        case 7: glLineStipple(2, 0xf0f0); break;
        case 8: glPointSize(3); break;
        case 9: glPointParameterf(GL_POINT_SIZE_MIN, 2); break;
        case 10: glPointParameteri(GL_POINT_SIZE_MAX, 2); break;
        case 11: glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, three); break;
        case 12: glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, three_i); break;
        case 13: glLineWidth(-1); break; /* the Begin/End error wins */
        case 14: glShadeModel(GL_FRONT); break;
        case 15:
            if (polygon_offset_clamp)
                polygon_offset_clamp(1, 1, 1);
            else
                glPointSize(2);
            break;
        case 16: glPointParameterf(0xdead, 1); break;
        }
        end();
        GLenum error = glGetError();
        capi_check(error == GL_INVALID_OPERATION, "setter %d between glBegin/glEnd: 0x%x", i, error);
    }
    snapshot(after);
    capi_check(memcmp(before, after, sizeof before) == 0, "nothing changed between glBegin/glEnd");
}

int main(void)
{
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    polygon_offset_clamp = (PFNGLPOLYGONOFFSETCLAMPPROC)OSMesaGetProcAddress("glPolygonOffsetClamp");
    capi_check(polygon_offset_clamp != NULL, "glPolygonOffsetClamp exists");
    print_all("initial");
    GLfloat max_size, aliased_point[2];
    glGetFloatv(GL_POINT_SIZE_MAX, &max_size);
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, aliased_point);
    capi_check(max_size == aliased_point[1], "initial GL_POINT_SIZE_MAX %g is the largest size", max_size);
    set_values();
    print_all("set");
    extremes();
    offset_clamp();
    errors();
    limits();
    attribute_groups();
    inside_begin_end();
    OSMesaDestroyContext(ctx);
    return capi_finish();
}
