/* glGetBooleanv/Integerv/Floatv/Doublev of every state value tessera keeps.
 *
 * Each query is printed in all four types (VALUE lines compared with Mesa), once with the
 * initial state, once after setting non-default values, and then the conversions' corner
 * cases: clamped and unclamped colors, out-of-range values, unsigned masks. capi_check asserts
 * the spec's initial values, the number of values each query writes, and the errors.
 *
 * Not printed, because Mesa 22's answer depends on what tessera does not have (Mesa is GL 4.5
 * compatibility on llvmpipe): GL_MAX_CLIP_PLANES (8 vs 6), GL_MAX_TEXTURE_UNITS (8 vs 4), and
 * the initial stencil masks (Mesa 0xff, tessera all ones: both "1's" per table 6.22).
 * Setters tessera does not export yet are reached through OSMesaGetProcAddress and their
 * effects only checked (not printed) when the setter exists.
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"

#define W 32
#define H 32
#define MAXN 16
#define INT_SENTINEL 0x7eadbeef
#define FLOAT_SENTINEL -12345.0f
#define BOOL_SENTINEL 0xaa

struct query {
    const char *name;
    GLenum pname;
    int count;
};
#define Q(p, n) { #p, p, n }

/* Every query of state tessera keeps, except the capabilities (listed below). */
static const struct query queries[] = {
    Q(GL_RED_BITS, 1), Q(GL_GREEN_BITS, 1), Q(GL_BLUE_BITS, 1), Q(GL_ALPHA_BITS, 1),
    Q(GL_DEPTH_BITS, 1), Q(GL_STENCIL_BITS, 1),
    Q(GL_ACCUM_RED_BITS, 1), Q(GL_ACCUM_GREEN_BITS, 1), Q(GL_ACCUM_BLUE_BITS, 1), Q(GL_ACCUM_ALPHA_BITS, 1),
    Q(GL_AUX_BUFFERS, 1), Q(GL_DOUBLEBUFFER, 1), Q(GL_STEREO, 1), Q(GL_RGBA_MODE, 1), Q(GL_INDEX_MODE, 1),
    Q(GL_SAMPLE_BUFFERS, 1), Q(GL_SAMPLES, 1),
    Q(GL_MAX_VIEWPORT_DIMS, 2), Q(GL_MAX_ATTRIB_STACK_DEPTH, 1), Q(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 1),
    Q(GL_MAX_DRAW_BUFFERS, 1), Q(GL_MAX_LIGHTS, 1), Q(GL_SUBPIXEL_BITS, 1),
    Q(GL_ATTRIB_STACK_DEPTH, 1), Q(GL_CLIENT_ATTRIB_STACK_DEPTH, 1),
    Q(GL_DRAW_BUFFER, 1), Q(GL_DRAW_BUFFER0, 1), Q(GL_DRAW_BUFFER1, 1), Q(GL_DRAW_BUFFER2, 1),
    Q(GL_DRAW_BUFFER3, 1), Q(GL_DRAW_BUFFER4, 1), Q(GL_DRAW_BUFFER5, 1), Q(GL_DRAW_BUFFER6, 1),
    Q(GL_DRAW_BUFFER7, 1), Q(GL_READ_BUFFER, 1),
    Q(GL_COLOR_CLEAR_VALUE, 4), Q(GL_INDEX_CLEAR_VALUE, 1), Q(GL_COLOR_WRITEMASK, 4), Q(GL_INDEX_WRITEMASK, 1),
    Q(GL_ALPHA_TEST_FUNC, 1), Q(GL_ALPHA_TEST_REF, 1),
    Q(GL_BLEND_SRC, 1), Q(GL_BLEND_DST, 1), Q(GL_BLEND_SRC_RGB, 1), Q(GL_BLEND_DST_RGB, 1),
    Q(GL_BLEND_SRC_ALPHA, 1), Q(GL_BLEND_DST_ALPHA, 1), Q(GL_BLEND_EQUATION_RGB, 1),
    Q(GL_BLEND_EQUATION_ALPHA, 1), Q(GL_BLEND_COLOR, 4), Q(GL_LOGIC_OP_MODE, 1),
    Q(GL_CLAMP_VERTEX_COLOR, 1), Q(GL_CLAMP_FRAGMENT_COLOR, 1), Q(GL_CLAMP_READ_COLOR, 1),
    Q(GL_DEPTH_FUNC, 1), Q(GL_DEPTH_WRITEMASK, 1), Q(GL_DEPTH_CLEAR_VALUE, 1),
    Q(GL_STENCIL_FUNC, 1), Q(GL_STENCIL_REF, 1), Q(GL_STENCIL_FAIL, 1), Q(GL_STENCIL_PASS_DEPTH_FAIL, 1),
    Q(GL_STENCIL_PASS_DEPTH_PASS, 1), Q(GL_STENCIL_BACK_FUNC, 1), Q(GL_STENCIL_BACK_REF, 1),
    Q(GL_STENCIL_BACK_FAIL, 1), Q(GL_STENCIL_BACK_PASS_DEPTH_FAIL, 1), Q(GL_STENCIL_BACK_PASS_DEPTH_PASS, 1),
    Q(GL_ACTIVE_STENCIL_FACE_EXT, 1), Q(GL_STENCIL_CLEAR_VALUE, 1), Q(GL_ACCUM_CLEAR_VALUE, 4),
    Q(GL_VIEWPORT, 4), Q(GL_DEPTH_RANGE, 2), Q(GL_SCISSOR_BOX, 4),
    Q(GL_PERSPECTIVE_CORRECTION_HINT, 1), Q(GL_POINT_SMOOTH_HINT, 1), Q(GL_LINE_SMOOTH_HINT, 1),
    Q(GL_POLYGON_SMOOTH_HINT, 1), Q(GL_FOG_HINT, 1), Q(GL_GENERATE_MIPMAP_HINT, 1),
    Q(GL_TEXTURE_COMPRESSION_HINT, 1), Q(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, 1),
    Q(GL_ACTIVE_TEXTURE, 1),
    Q(GL_PACK_SWAP_BYTES, 1), Q(GL_PACK_LSB_FIRST, 1), Q(GL_PACK_ROW_LENGTH, 1), Q(GL_PACK_IMAGE_HEIGHT, 1),
    Q(GL_PACK_SKIP_ROWS, 1), Q(GL_PACK_SKIP_PIXELS, 1), Q(GL_PACK_SKIP_IMAGES, 1), Q(GL_PACK_ALIGNMENT, 1),
    Q(GL_UNPACK_SWAP_BYTES, 1), Q(GL_UNPACK_LSB_FIRST, 1), Q(GL_UNPACK_ROW_LENGTH, 1),
    Q(GL_UNPACK_IMAGE_HEIGHT, 1), Q(GL_UNPACK_SKIP_ROWS, 1), Q(GL_UNPACK_SKIP_PIXELS, 1),
    Q(GL_UNPACK_SKIP_IMAGES, 1), Q(GL_UNPACK_ALIGNMENT, 1),
};

/* Every capability of glEnable: glGet returns its enable. */
static const struct query capabilities[] = {
    Q(GL_ALPHA_TEST, 1), Q(GL_AUTO_NORMAL, 1), Q(GL_BLEND, 1), Q(GL_CLIP_PLANE0, 1), Q(GL_CLIP_PLANE1, 1),
    Q(GL_CLIP_PLANE2, 1), Q(GL_CLIP_PLANE3, 1), Q(GL_CLIP_PLANE4, 1), Q(GL_CLIP_PLANE5, 1),
    Q(GL_COLOR_LOGIC_OP, 1), Q(GL_COLOR_MATERIAL, 1), Q(GL_COLOR_SUM, 1), Q(GL_CULL_FACE, 1),
    Q(GL_DEPTH_CLAMP, 1), Q(GL_DEPTH_TEST, 1), Q(GL_DITHER, 1), Q(GL_FOG, 1), Q(GL_INDEX_LOGIC_OP, 1),
    Q(GL_LIGHT0, 1), Q(GL_LIGHT1, 1), Q(GL_LIGHT2, 1), Q(GL_LIGHT3, 1), Q(GL_LIGHT4, 1), Q(GL_LIGHT5, 1),
    Q(GL_LIGHT6, 1), Q(GL_LIGHT7, 1), Q(GL_LIGHTING, 1), Q(GL_LINE_SMOOTH, 1), Q(GL_LINE_STIPPLE, 1),
    Q(GL_MAP1_COLOR_4, 1), Q(GL_MAP1_INDEX, 1), Q(GL_MAP1_NORMAL, 1), Q(GL_MAP1_TEXTURE_COORD_1, 1),
    Q(GL_MAP1_TEXTURE_COORD_2, 1), Q(GL_MAP1_TEXTURE_COORD_3, 1), Q(GL_MAP1_TEXTURE_COORD_4, 1),
    Q(GL_MAP1_VERTEX_3, 1), Q(GL_MAP1_VERTEX_4, 1), Q(GL_MAP2_COLOR_4, 1), Q(GL_MAP2_INDEX, 1),
    Q(GL_MAP2_NORMAL, 1), Q(GL_MAP2_TEXTURE_COORD_1, 1), Q(GL_MAP2_TEXTURE_COORD_2, 1),
    Q(GL_MAP2_TEXTURE_COORD_3, 1), Q(GL_MAP2_TEXTURE_COORD_4, 1), Q(GL_MAP2_VERTEX_3, 1),
    Q(GL_MAP2_VERTEX_4, 1), Q(GL_MULTISAMPLE, 1), Q(GL_NORMALIZE, 1), Q(GL_POINT_SMOOTH, 1),
    Q(GL_POINT_SPRITE, 1), Q(GL_POLYGON_OFFSET_FILL, 1), Q(GL_POLYGON_OFFSET_LINE, 1),
    Q(GL_POLYGON_OFFSET_POINT, 1), Q(GL_POLYGON_SMOOTH, 1), Q(GL_POLYGON_STIPPLE, 1), Q(GL_RESCALE_NORMAL, 1),
    Q(GL_SAMPLE_ALPHA_TO_COVERAGE, 1), Q(GL_SAMPLE_ALPHA_TO_ONE, 1), Q(GL_SAMPLE_COVERAGE, 1),
    Q(GL_SCISSOR_TEST, 1), Q(GL_STENCIL_TEST, 1), Q(GL_STENCIL_TEST_TWO_SIDE_EXT, 1), Q(GL_TEXTURE_1D, 1),
    Q(GL_TEXTURE_2D, 1), Q(GL_TEXTURE_3D, 1), Q(GL_TEXTURE_CUBE_MAP, 1), Q(GL_TEXTURE_GEN_S, 1),
    Q(GL_TEXTURE_GEN_T, 1), Q(GL_TEXTURE_GEN_R, 1), Q(GL_TEXTURE_GEN_Q, 1),
    Q(GL_VERTEX_PROGRAM_POINT_SIZE, 1), Q(GL_VERTEX_PROGRAM_TWO_SIDE, 1),
};
#define COUNT(a) (int)(sizeof(a) / sizeof((a)[0]))

/* The four answers of one query. */
struct answer {
    GLboolean b[MAXN + 1];
    GLint i[MAXN + 1];
    GLfloat f[MAXN + 1];
    GLdouble d[MAXN + 1];
};

/* Runs the four queries into sentinel-filled arrays; checks that exactly `count` values are
 * written and that no error is recorded. */
static void get_all(const char *label, const struct query *q, struct answer *a)
{
    memset(a->b, BOOL_SENTINEL, sizeof a->b);
    for (int k = 0; k <= MAXN; k++) {
        a->i[k] = INT_SENTINEL;
        a->f[k] = FLOAT_SENTINEL;
        a->d[k] = FLOAT_SENTINEL;
    }
    glGetBooleanv(q->pname, a->b);
    glGetIntegerv(q->pname, a->i);
    glGetFloatv(q->pname, a->f);
    glGetDoublev(q->pname, a->d);
    GLenum error = glGetError();
    capi_check(error == GL_NO_ERROR, "%s %s: error 0x%x", label, q->name, error);
    for (int k = 0; k <= MAXN; k++) {
        int written = a->i[k] != INT_SENTINEL || a->f[k] != FLOAT_SENTINEL || a->d[k] != FLOAT_SENTINEL ||
                      a->b[k] != BOOL_SENTINEL;
        capi_check(written == (k < q->count), "%s %s: value %d %s", label, q->name, k,
                   written ? "written past the count" : "not written");
    }
    for (int k = 0; k < q->count; k++)
        capi_check(a->b[k] == GL_TRUE || a->b[k] == GL_FALSE, "%s %s: boolean %d is %d", label, q->name, k, a->b[k]);
}

/* Prints the four answers as one VALUE line; integers only when `with_ints`. */
static void print_answer(const char *label, const struct query *q, const struct answer *a, int with_ints)
{
    char line[2048] = "", part[64];
    strcat(line, "b=");
    for (int k = 0; k < q->count; k++) {
        snprintf(part, sizeof part, "%s%d", k ? "," : "", a->b[k]);
        strcat(line, part);
    }
    if (with_ints) {
        strcat(line, " i=");
        for (int k = 0; k < q->count; k++) {
            snprintf(part, sizeof part, "%s%d", k ? "," : "", a->i[k]);
            strcat(line, part);
        }
    }
    strcat(line, " f=");
    for (int k = 0; k < q->count; k++) {
        snprintf(part, sizeof part, "%s%.9g", k ? "," : "", a->f[k]);
        strcat(line, part);
    }
    strcat(line, " d=");
    for (int k = 0; k < q->count; k++) {
        snprintf(part, sizeof part, "%s%.17g", k ? "," : "", a->d[k]);
        strcat(line, part);
    }
    char key[256];
    snprintf(key, sizeof key, "%s.%s", label, q->name);
    capi_value(key, "%s", line);
}

static void show(const char *label, const struct query *q)
{
    struct answer a;
    get_all(label, q, &a);
    print_answer(label, q, &a, 1);
}

/* Every query of both tables. */
static void show_everything(const char *label)
{
    for (int n = 0; n < COUNT(queries); n++)
        show(label, &queries[n]);
    for (int n = 0; n < COUNT(capabilities); n++)
        show(label, &capabilities[n]);
}

static GLint get_int(GLenum pname)
{
    GLint v[MAXN];
    v[0] = INT_SENTINEL;
    glGetIntegerv(pname, v);
    return v[0];
}

static GLdouble get_double(GLenum pname)
{
    GLdouble v[MAXN];
    v[0] = FLOAT_SENTINEL;
    glGetDoublev(pname, v);
    return v[0];
}

/* Initial values of GL 2.1 chapter 6 for a single-buffered RGBA context with depth, stencil
 * and accumulation buffers. */
static void check_defaults(void)
{
    static const struct { GLenum pname; GLint value; const char *name; } ints[] = {
        { GL_DRAW_BUFFER, GL_FRONT, "draw buffer" }, { GL_READ_BUFFER, GL_FRONT, "read buffer" },
        { GL_DRAW_BUFFER1, GL_NONE, "draw buffer 1" }, { GL_DRAW_BUFFER7, GL_NONE, "draw buffer 7" },
        { GL_ALPHA_TEST_FUNC, GL_ALWAYS, "alpha func" }, { GL_ALPHA_TEST_REF, 0, "alpha ref" },
        { GL_BLEND_SRC, GL_ONE, "blend src" }, { GL_BLEND_DST, GL_ZERO, "blend dst" },
        { GL_BLEND_SRC_ALPHA, GL_ONE, "blend src alpha" }, { GL_BLEND_DST_ALPHA, GL_ZERO, "blend dst alpha" },
        { GL_BLEND_EQUATION_RGB, GL_FUNC_ADD, "blend equation" }, { GL_BLEND_EQUATION_ALPHA, GL_FUNC_ADD, "eq a" },
        { GL_LOGIC_OP_MODE, GL_COPY, "logic op" }, { GL_DEPTH_FUNC, GL_LESS, "depth func" },
        { GL_DEPTH_WRITEMASK, 1, "depth mask" }, { GL_DEPTH_CLEAR_VALUE, 2147483647, "clear depth" },
        { GL_STENCIL_FUNC, GL_ALWAYS, "stencil func" }, { GL_STENCIL_REF, 0, "stencil ref" },
        { GL_STENCIL_FAIL, GL_KEEP, "stencil fail" }, { GL_STENCIL_PASS_DEPTH_PASS, GL_KEEP, "zpass" },
        { GL_STENCIL_BACK_FUNC, GL_ALWAYS, "back func" }, { GL_STENCIL_BACK_PASS_DEPTH_FAIL, GL_KEEP, "zfail" },
        { GL_ACTIVE_STENCIL_FACE_EXT, GL_FRONT, "active face" }, { GL_STENCIL_CLEAR_VALUE, 0, "clear stencil" },
        { GL_INDEX_WRITEMASK, -1, "index mask" }, { GL_INDEX_CLEAR_VALUE, 0, "clear index" },
        { GL_CLAMP_VERTEX_COLOR, GL_TRUE, "clamp vertex" }, { GL_CLAMP_FRAGMENT_COLOR, GL_FIXED_ONLY, "clamp frag" },
        { GL_CLAMP_READ_COLOR, GL_FIXED_ONLY, "clamp read" }, { GL_ACTIVE_TEXTURE, GL_TEXTURE0, "active texture" },
        { GL_PERSPECTIVE_CORRECTION_HINT, GL_DONT_CARE, "hint" }, { GL_GENERATE_MIPMAP_HINT, GL_DONT_CARE, "hint" },
        { GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_DONT_CARE, "hint" }, { GL_FOG_HINT, GL_DONT_CARE, "hint" },
        { GL_PACK_ALIGNMENT, 4, "pack alignment" }, { GL_UNPACK_ALIGNMENT, 4, "unpack alignment" },
        { GL_PACK_ROW_LENGTH, 0, "pack row length" }, { GL_UNPACK_SWAP_BYTES, 0, "unpack swap" },
        { GL_ATTRIB_STACK_DEPTH, 0, "stack depth" }, { GL_CLIENT_ATTRIB_STACK_DEPTH, 0, "client stack depth" },
        { GL_RED_BITS, 8, "red bits" }, { GL_ALPHA_BITS, 8, "alpha bits" }, { GL_DEPTH_BITS, 24, "depth bits" },
        { GL_STENCIL_BITS, 8, "stencil bits" }, { GL_ACCUM_RED_BITS, 16, "accum bits" },
        { GL_DOUBLEBUFFER, 0, "doublebuffer" }, { GL_RGBA_MODE, 1, "rgba mode" }, { GL_INDEX_MODE, 0, "index" },
        { GL_MAX_ATTRIB_STACK_DEPTH, 16, "max stack" }, { GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 16, "max client" },
        { GL_MAX_DRAW_BUFFERS, 8, "max draw buffers" }, { GL_MAX_LIGHTS, 8, "max lights" },
    };
    for (int n = 0; n < COUNT(ints); n++) {
        GLint v = get_int(ints[n].pname);
        capi_check(v == ints[n].value, "initial %s (0x%x) is %d, not %d", ints[n].name, ints[n].pname, v,
                   ints[n].value);
    }
    GLint v4[4];
    glGetIntegerv(GL_VIEWPORT, v4);
    capi_check(v4[0] == 0 && v4[1] == 0 && v4[2] == W && v4[3] == H, "initial viewport");
    glGetIntegerv(GL_SCISSOR_BOX, v4);
    capi_check(v4[0] == 0 && v4[1] == 0 && v4[2] == W && v4[3] == H, "initial scissor box");
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, v4);
    capi_check(v4[0] >= W && v4[1] >= H, "max viewport dims");
    GLdouble range[2];
    glGetDoublev(GL_DEPTH_RANGE, range);
    capi_check(range[0] == 0.0 && range[1] == 1.0, "initial depth range");
    GLfloat color[4];
    glGetFloatv(GL_COLOR_CLEAR_VALUE, color);
    capi_check(!color[0] && !color[1] && !color[2] && !color[3], "initial clear color");
    GLboolean mask[4];
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    capi_check(mask[0] && mask[1] && mask[2] && mask[3], "initial color mask");

    /* "1's" for an 8-bit stencil buffer: at least its 8 bits (Mesa keeps 0xff, tessera ~0). */
    const GLenum stencil_masks[] = { GL_STENCIL_VALUE_MASK, GL_STENCIL_WRITEMASK, GL_STENCIL_BACK_VALUE_MASK,
                                     GL_STENCIL_BACK_WRITEMASK };
    for (int n = 0; n < 4; n++) {
        GLdouble m = get_double(stencil_masks[n]);
        capi_check(m == 255.0 || m == 4294967295.0, "initial stencil mask 0x%x is %.17g", stencil_masks[n], m);
    }
    /* Implementation limits where tessera and llvmpipe differ: at least the spec's minimum. */
    capi_check(get_int(GL_MAX_CLIP_PLANES) >= 6, "GL_MAX_CLIP_PLANES");
    capi_check(get_int(GL_MAX_TEXTURE_UNITS) >= 2, "GL_MAX_TEXTURE_UNITS");
    capi_check(get_int(GL_SUBPIXEL_BITS) >= 4, "GL_SUBPIXEL_BITS (softpipe has 4, llvmpipe and tessera 8)");

    for (int n = 0; n < COUNT(capabilities); n++) {
        GLenum cap = capabilities[n].pname;
        int on = cap == GL_DITHER || cap == GL_MULTISAMPLE;
        capi_check(get_int(cap) == on, "initial %s", capabilities[n].name);
    }
    capi_check(glGetError() == GL_NO_ERROR, "defaults: errors");
}

/* Non-default values through the setters every implementation exports. */
static void set_non_defaults(void)
{
    for (int n = 0; n < COUNT(capabilities); n++) {
        GLenum cap = capabilities[n].pname;
        if (glIsEnabled(cap))
            glDisable(cap);
        else
            glEnable(cap);
    }
    glDisablei(GL_BLEND, 1);
    glClearColor(0.5f, 0.1f, -1.0f, 2.0f);
    glClearIndex(3.7f);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glIndexMask(0x3c);
    glDrawBuffer(GL_FRONT_LEFT);
    glReadBuffer(GL_LEFT);
    glClampColor(GL_CLAMP_VERTEX_COLOR, GL_FALSE);
    glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE);
    glClearDepth(0.3);
    glDepthMask(GL_FALSE);
    glClearStencil(-7);
    glStencilMaskSeparate(GL_FRONT, 0x80000001u);
    glStencilMaskSeparate(GL_BACK, 0x5a);
    glClearAccum(-0.5f, 0.25f, 2.0f, -3.0f);
    glViewport(2, 3, 5, 7);
    glDepthRange(0.25, 0.75);
    glScissor(-1, 2, 30, 40);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glHint(GL_POINT_SMOOTH_HINT, GL_FASTEST);
    glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    glHint(GL_POLYGON_SMOOTH_HINT, GL_FASTEST);
    glHint(GL_FOG_HINT, GL_NICEST);
    glHint(GL_GENERATE_MIPMAP_HINT, GL_FASTEST);
    glHint(GL_TEXTURE_COMPRESSION_HINT, GL_NICEST);
    glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_FASTEST);
    capi_expect_error(GL_NO_ERROR, "set.errors");

    /* The masks that differ only by default can be compared once set. */
    static const struct query masks[] = { Q(GL_STENCIL_WRITEMASK, 1), Q(GL_STENCIL_BACK_WRITEMASK, 1) };
    show("set", &masks[0]);
    show("set", &masks[1]);
    capi_check(get_int(GL_STENCIL_WRITEMASK) == 2147483647, "unsigned mask saturates as an integer");
    capi_check(get_double(GL_STENCIL_WRITEMASK) == 2147483649.0, "unsigned mask as a double");
    capi_check(get_int(GL_INDEX_CLEAR_VALUE) == 3, "clear index truncated");
    capi_check(get_int(GL_STENCIL_CLEAR_VALUE) == -7, "clear stencil as given");
    capi_check(get_int(GL_DRAW_BUFFER) == GL_FRONT_LEFT && get_int(GL_DRAW_BUFFER0) == GL_FRONT_LEFT, "draw buf");
    capi_check(get_int(GL_BLEND) == 1, "glGet(GL_BLEND) is draw buffer 0");
}

/* Conversions of colors: clamped per CLAMP_FRAGMENT_COLOR, normalized to integers. */
static void check_color_conversions(void)
{
    static const struct query clear = Q(GL_COLOR_CLEAR_VALUE, 4);
    static const struct query accum = Q(GL_ACCUM_CLEAR_VALUE, 4);
    static const struct query depth = Q(GL_DEPTH_CLEAR_VALUE, 1);
    static const struct query index = Q(GL_INDEX_CLEAR_VALUE, 1);
    struct answer a;

    glClearColor(0.5f, 0.1f, -1.0f, 2.0f);
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FIXED_ONLY);
    get_all("fixed_only", &clear, &a);
    print_answer("fixed_only", &clear, &a, 1);
    capi_check(a.i[0] == 1073741823 && a.i[1] == 214748367 && a.i[2] == 0 && a.i[3] == 2147483647,
               "clamped clear color as integers: %d %d %d %d", a.i[0], a.i[1], a.i[2], a.i[3]);

    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_TRUE);
    show("clamp_true", &clear);

    /* Unclamped: the integers of values outside [-1, 1] are not printed (Mesa's C cast of an
     * out-of-range double gives -2^31; tessera saturates). */
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    get_all("clamp_false", &clear, &a);
    print_answer("clamp_false", &clear, &a, 0);
    capi_check(a.f[2] == -1.0f && a.f[3] == 2.0f, "unclamped clear color");
    capi_check(a.i[0] == 1073741823 && a.i[2] == -2147483647, "in-range unclamped integers %d %d", a.i[0], a.i[2]);
    if (capi_is_tessera())
        capi_check(a.i[3] == 2147483647, "tessera saturates 2.0 to %d", a.i[3]);
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FIXED_ONLY);

    glClearAccum(-0.5f, 0.25f, 2.0f, -3.0f);
    get_all("accum", &accum, &a);
    print_answer("accum", &accum, &a, 1);
    capi_check(a.i[0] == -1073741823 && a.i[1] == 536870911 && a.i[2] == 2147483647 && a.i[3] == -2147483647,
               "accum clear as integers");

    glClearDepth(0.3);
    get_all("depth", &depth, &a);
    print_answer("depth", &depth, &a, 1);
    capi_check(a.i[0] == 644245094 && a.d[0] == 0.3, "clear depth 0.3: %d %.17g", a.i[0], a.d[0]);
    glClearDepth(-2.0);
    capi_check(get_double(GL_DEPTH_CLEAR_VALUE) == 0.0, "clear depth clamps");

    glClearIndex(5e9f);
    show("clear_index_wraps", &index);
    capi_check(get_int(GL_INDEX_CLEAR_VALUE) == 705032704, "clear index as Mesa's GLuint");
    capi_check(glGetError() == GL_NO_ERROR, "color conversions: errors");
}

/* A float color buffer: FIXED_ONLY does not clamp there (GL 3.0 4.1.x). Mesa 22 still
 * clamps the queried value for OSMesa's float buffer (its window-system framebuffer is
 * never marked as float) although it clears unclamped; tessera reports what it clears with. */
static void check_float_buffer(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_FLOAT, 0, 0, 0, 4, 4, &buffer);
    static const struct query red_bits = Q(GL_RED_BITS, 1);
    show("float_buffer", &red_bits);
    glClearColor(0.5f, 0.1f, -1.0f, 2.0f);
    GLfloat c[4];
    glGetFloatv(GL_COLOR_CLEAR_VALUE, c);
    if (capi_is_tessera())
        capi_check(c[2] == -1.0f && c[3] == 2.0f, "float buffer: FIXED_ONLY leaves the clear color");
    else
        capi_check(c[2] == 0.0f && c[3] == 1.0f, "Mesa 22 clamps the queried clear color");
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_TRUE);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, c);
    capi_check(c[2] == 0.0f && c[3] == 1.0f, "float buffer with clamping on");
    capi_check(glGetError() == GL_NO_ERROR, "float buffer: errors");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
}

/* Unknown pnames: GL_INVALID_ENUM and nothing written, for each of the four calls. */
static void check_errors(void)
{
    const GLenum bad[] = { 0, GL_RGBA, 0xdead, GL_DRAW_BUFFER8, GL_DRAW_BUFFER15, GL_TEXTURE_2D + 1 };
    for (int n = 0; n < COUNT(bad); n++) {
        struct answer a;
        memset(a.b, BOOL_SENTINEL, sizeof a.b);
        a.i[0] = INT_SENTINEL;
        a.f[0] = a.d[0] = FLOAT_SENTINEL;
        char key[64];
        glGetBooleanv(bad[n], a.b);
        snprintf(key, sizeof key, "bad_pname.0x%x.boolean", bad[n]);
        capi_expect_error(GL_INVALID_ENUM, key);
        glGetIntegerv(bad[n], a.i);
        snprintf(key, sizeof key, "bad_pname.0x%x.integer", bad[n]);
        capi_expect_error(GL_INVALID_ENUM, key);
        glGetFloatv(bad[n], a.f);
        snprintf(key, sizeof key, "bad_pname.0x%x.float", bad[n]);
        capi_expect_error(GL_INVALID_ENUM, key);
        glGetDoublev(bad[n], a.d);
        snprintf(key, sizeof key, "bad_pname.0x%x.double", bad[n]);
        capi_expect_error(GL_INVALID_ENUM, key);
        capi_check(a.b[0] == BOOL_SENTINEL && a.i[0] == INT_SENTINEL && a.f[0] == FLOAT_SENTINEL &&
                       a.d[0] == FLOAT_SENTINEL,
                   "bad pname 0x%x wrote a value", bad[n]);
    }
    /* The error is sticky: a second bad query keeps the first error, a good one adds none. */
    GLint v;
    glGetIntegerv(0xdead, &v);
    glGetIntegerv(GL_DEPTH_FUNC, &v);
    capi_expect_error(GL_INVALID_ENUM, "bad_pname.sticky");
    capi_expect_error(GL_NO_ERROR, "bad_pname.cleared");

    /* GL 3.0 queries do not exist in a GL 2.1 implementation (Mesa is 4.5). */
    if (capi_is_tessera()) {
        const GLenum gl3[] = { GL_MAJOR_VERSION, GL_MINOR_VERSION, GL_NUM_EXTENSIONS, GL_CONTEXT_FLAGS };
        for (int n = 0; n < COUNT(gl3); n++) {
            glGetIntegerv(gl3[n], &v);
            capi_check(glGetError() == GL_INVALID_ENUM, "GL 3 pname 0x%x accepted", gl3[n]);
        }
    }
}

/* Setters tessera may not export yet: their effect on queries is checked when they exist. */
typedef void (*fn_e_i)(GLenum, GLint);
typedef void (*fn_e_f)(GLenum, GLfloat);
typedef void (*fn_e)(GLenum);
typedef void (*fn_e_e)(GLenum, GLenum);
typedef void (*fn_eeee)(GLenum, GLenum, GLenum, GLenum);
typedef void (*fn_e_e_i_u)(GLenum, GLenum, GLint, GLuint);
typedef void (*fn_ffff)(GLfloat, GLfloat, GLfloat, GLfloat);

#define PROC(type, name) ((type)OSMesaGetProcAddress(name))

static void check_optional_setters(void)
{
    fn_e_i pixel_store = PROC(fn_e_i, "glPixelStorei");
    if (pixel_store) {
        const GLenum names[] = { GL_PACK_ROW_LENGTH, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
                                 GL_PACK_SKIP_IMAGES, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT,
                                 GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_IMAGES };
        for (int n = 0; n < COUNT(names); n++)
            pixel_store(names[n], 10 + n);
        for (int n = 0; n < COUNT(names); n++)
            capi_check(get_int(names[n]) == 10 + n, "pixel store 0x%x", names[n]);
        pixel_store(GL_PACK_ALIGNMENT, 8);
        pixel_store(GL_UNPACK_ALIGNMENT, 2);
        pixel_store(GL_PACK_SWAP_BYTES, 1);
        pixel_store(GL_UNPACK_LSB_FIRST, 1);
        capi_check(get_int(GL_PACK_ALIGNMENT) == 8 && get_int(GL_UNPACK_ALIGNMENT) == 2, "alignments");
        capi_check(get_int(GL_PACK_SWAP_BYTES) == 1 && get_int(GL_UNPACK_LSB_FIRST) == 1, "pixel store flags");
        capi_check(get_int(GL_PACK_LSB_FIRST) == 0 && get_int(GL_UNPACK_SWAP_BYTES) == 0, "pixel store flags");
    } else {
        printf("NOTE glPixelStorei not exported\n");
    }

    fn_e_f alpha_func = PROC(fn_e_f, "glAlphaFunc");
    if (alpha_func) {
        alpha_func(GL_GREATER, 0.25f);
        capi_check(get_int(GL_ALPHA_TEST_FUNC) == GL_GREATER, "alpha func");
        capi_check(get_int(GL_ALPHA_TEST_REF) == 536870911, "alpha ref 0.25 as an integer");
        alpha_func(GL_LESS, 2.0f);
        capi_check(get_double(GL_ALPHA_TEST_REF) == 1.0, "alpha ref clamped");
    } else {
        printf("NOTE glAlphaFunc not exported\n");
    }

    fn_e_e_i_u stencil_func = PROC(fn_e_e_i_u, "glStencilFuncSeparate");
    fn_eeee stencil_op = PROC(fn_eeee, "glStencilOpSeparate");
    if (stencil_func && stencil_op) {
        stencil_func(GL_FRONT, GL_LESS, 300, 0x0f);
        stencil_func(GL_BACK, GL_GEQUAL, -3, 0xffffffffu);
        stencil_op(GL_FRONT, GL_INCR, GL_DECR, GL_INVERT);
        stencil_op(GL_BACK, GL_ZERO, GL_REPLACE, GL_INCR_WRAP);
        capi_check(get_int(GL_STENCIL_FUNC) == GL_LESS && get_int(GL_STENCIL_BACK_FUNC) == GL_GEQUAL, "funcs");
        capi_check(get_int(GL_STENCIL_REF) == 255 && get_int(GL_STENCIL_BACK_REF) == 0, "refs clamp to bits");
        capi_check(get_int(GL_STENCIL_VALUE_MASK) == 15, "value mask");
        capi_check(get_int(GL_STENCIL_BACK_VALUE_MASK) == 2147483647, "value mask saturates");
        capi_check(get_int(GL_STENCIL_FAIL) == GL_INCR && get_int(GL_STENCIL_PASS_DEPTH_FAIL) == GL_DECR &&
                       get_int(GL_STENCIL_PASS_DEPTH_PASS) == GL_INVERT,
                   "front ops");
        capi_check(get_int(GL_STENCIL_BACK_FAIL) == GL_ZERO && get_int(GL_STENCIL_BACK_PASS_DEPTH_FAIL) == GL_REPLACE &&
                       get_int(GL_STENCIL_BACK_PASS_DEPTH_PASS) == GL_INCR_WRAP,
                   "back ops");
    } else {
        printf("NOTE glStencilFuncSeparate/glStencilOpSeparate not exported\n");
    }

    fn_eeee blend_func = PROC(fn_eeee, "glBlendFuncSeparate");
    fn_e_e blend_equation = PROC(fn_e_e, "glBlendEquationSeparate");
    fn_ffff blend_color = PROC(fn_ffff, "glBlendColor");
    if (blend_func && blend_equation && blend_color) {
        blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_COLOR, GL_CONSTANT_ALPHA);
        blend_equation(GL_FUNC_SUBTRACT, GL_MAX);
        blend_color(0.5f, -1.0f, 2.0f, 0.25f);
        capi_check(get_int(GL_BLEND_SRC) == GL_SRC_ALPHA && get_int(GL_BLEND_SRC_RGB) == GL_SRC_ALPHA, "src");
        capi_check(get_int(GL_BLEND_DST) == GL_ONE_MINUS_SRC_ALPHA, "dst");
        capi_check(get_int(GL_BLEND_SRC_ALPHA) == GL_DST_COLOR && get_int(GL_BLEND_DST_ALPHA) == GL_CONSTANT_ALPHA,
                   "alpha factors");
        capi_check(get_int(GL_BLEND_EQUATION_RGB) == GL_FUNC_SUBTRACT && get_int(GL_BLEND_EQUATION_ALPHA) == GL_MAX,
                   "equations");
        GLint c[4];
        glGetIntegerv(GL_BLEND_COLOR, c);
        capi_check(c[0] == 1073741823 && c[1] == 0 && c[2] == 2147483647 && c[3] == 536870911, "blend color");
    } else {
        printf("NOTE glBlendFuncSeparate/glBlendEquationSeparate/glBlendColor not exported\n");
    }

    fn_e logic_op = PROC(fn_e, "glLogicOp"), depth_func = PROC(fn_e, "glDepthFunc");
    if (logic_op && depth_func) {
        logic_op(GL_XOR);
        depth_func(GL_GEQUAL);
        capi_check(get_int(GL_LOGIC_OP_MODE) == GL_XOR && get_int(GL_DEPTH_FUNC) == GL_GEQUAL, "logic op, depth");
    } else {
        printf("NOTE glLogicOp/glDepthFunc not exported\n");
    }

    fn_e active_texture = PROC(fn_e, "glActiveTexture");
    if (active_texture) {
        active_texture(GL_TEXTURE1);
        capi_check(get_int(GL_ACTIVE_TEXTURE) == GL_TEXTURE1, "active texture");
        /* Unit 0 has every enable on (set_non_defaults); unit 1 only GL_TEXTURE_3D. */
        glEnable(GL_TEXTURE_3D);
        capi_check(get_int(GL_TEXTURE_2D) == 0 && get_int(GL_TEXTURE_3D) == 1, "unit 1 enables");
        active_texture(GL_TEXTURE0);
        glDisable(GL_TEXTURE_3D);
        capi_check(get_int(GL_TEXTURE_2D) == 1 && get_int(GL_TEXTURE_3D) == 0, "unit 0 enables");
        active_texture(GL_TEXTURE1);
        capi_check(get_int(GL_TEXTURE_3D) == 1, "unit 1 enables kept");
        active_texture(GL_TEXTURE0);
    } else {
        printf("NOTE glActiveTexture not exported\n");
    }

    fn_e active_face = PROC(fn_e, "glActiveStencilFaceEXT");
    if (active_face) {
        active_face(GL_BACK);
        capi_check(get_int(GL_ACTIVE_STENCIL_FACE_EXT) == GL_BACK, "active stencil face");
        active_face(GL_FRONT);
    } else {
        printf("NOTE glActiveStencilFaceEXT not exported\n");
    }
    capi_check(glGetError() == GL_NO_ERROR, "optional setters: errors");
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 24, 8, 16, W, H, &buffer);
    check_defaults();
    show_everything("default");
    set_non_defaults();
    show_everything("set");
    check_color_conversions();
    check_errors();
    check_optional_setters();
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
    check_float_buffer();
    return capi_finish();
}
