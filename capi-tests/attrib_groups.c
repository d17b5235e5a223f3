/* glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib for the state the
 * attrib_stack test leaves out: current values and the raster position, points, lines,
 * polygons, lighting (lights and materials), fog, transform (clip planes), pixel modes,
 * display lists, texture units (environment, texgen), the polygon stipple, and the client
 * pixel-store and vertex-array groups; glGetClipPlane, glGetPolygonStipple and friends read
 * what has no glGet pname. For every piece of state and every group, the
 * test pushes the group, changes the state, pops, and records whether the value came back:
 * one VALUE line per piece of state with the set of groups that restore it (compared with
 * Mesa, and checked against the GL 2.1 tables of chapter 6 for the group that owns it). */
#include "common.h"

#define W 8
#define H 8

struct item {
    const char *name;
    GLenum pname;
    int count;
    void (*change)(void);
    GLbitfield owner; /* the group of the GL 2.1 state tables */
    int client;       /* a client attribute (glPushClientAttrib) */
    GLbitfield mesa_misses; /* groups of `owner` whose pop Mesa 22 forgets */
    void (*read)(GLdouble *out); /* for state without a glGet pname */
};

static void ch_color(void) { glColor4f(0.1f, 0.2f, 0.3f, 0.4f); }
static void ch_secondary(void) { glSecondaryColor3f(0.5f, 0.25f, 0.125f); }
static void ch_normal(void) { glNormal3f(0.6f, 0.0f, 0.8f); }
static void ch_texcoord(void) { glTexCoord4f(1, 2, 3, 4); }
static void ch_fogcoord(void) { glFogCoordf(3.5f); }
static void ch_index(void) { glIndexf(7); }
static void ch_edge(void) { glEdgeFlag(GL_FALSE); }
static void ch_rasterpos(void) { glRasterPos2f(0.25f, -0.5f); }
static void ch_point_size(void) { glPointSize(3.5f); }
static void ch_point_min(void) { glPointParameterf(GL_POINT_SIZE_MIN, 2.0f); }
static void ch_point_max(void) { glPointParameterf(GL_POINT_SIZE_MAX, 9.0f); }
static void ch_point_fade(void) { glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 3.0f); }
static void ch_point_atten(void)
{
    static const GLfloat a[3] = {1, 0.5f, 0.25f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
}
static void ch_line_width(void) { glLineWidth(2.5f); }
static void ch_line_stipple(void) { glLineStipple(3, 0x1234); }
static void ch_front_face(void) { glFrontFace(GL_CW); }
static void ch_cull_mode(void) { glCullFace(GL_FRONT); }
static void ch_polygon_mode(void) { glPolygonMode(GL_BACK, GL_LINE); }
static void ch_offset(void) { glPolygonOffset(1.5f, 2.5f); }
static void ch_shade(void) { glShadeModel(GL_FLAT); }
static void ch_two_side(void) { glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE); }
static void ch_local_viewer(void) { glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE); }
static void ch_model_ambient(void)
{
    static const GLfloat a[4] = {0.5f, 0.4f, 0.3f, 0.2f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, a);
}
static void ch_color_material(void) { glColorMaterial(GL_BACK, GL_SPECULAR); }
static void ch_fog_mode(void) { glFogi(GL_FOG_MODE, GL_LINEAR); }
static void ch_fog_density(void) { glFogf(GL_FOG_DENSITY, 0.5f); }
static void ch_fog_start(void) { glFogf(GL_FOG_START, 2.0f); }
static void ch_fog_color(void)
{
    static const GLfloat c[4] = {0.5f, 0.25f, 0.125f, 1};
    glFogfv(GL_FOG_COLOR, c);
}
static void ch_fog_src(void) { glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD); }
static void ch_matrix_mode(void) { glMatrixMode(GL_TEXTURE); }
static void ch_zoom(void) { glPixelZoom(2.0f, -1.5f); }
static void ch_red_scale(void) { glPixelTransferf(GL_RED_SCALE, 0.5f); }
static void ch_depth_bias(void) { glPixelTransferf(GL_DEPTH_BIAS, 0.25f); }
static void ch_index_shift(void) { glPixelTransferi(GL_INDEX_SHIFT, 2); }
static void ch_map_color(void) { glPixelTransferi(GL_MAP_COLOR, GL_TRUE); }
static void ch_list_base(void) { glListBase(42); }
static void ch_active_texture(void) { glActiveTexture(GL_TEXTURE1); }
static void ch_stencil_func(void) { glStencilFunc(GL_LESS, 3, 0x0f); }
static void ch_stencil_op(void) { glStencilOp(GL_INCR, GL_DECR, GL_INVERT); }
static void ch_depth_func(void) { glDepthFunc(GL_GEQUAL); }
static void ch_alpha_func(void) { glAlphaFunc(GL_GREATER, 0.5f); }
static void ch_blend_func(void) { glBlendFunc(GL_SRC_ALPHA, GL_ONE); }
static void ch_blend_eq(void) { glBlendEquation(GL_FUNC_SUBTRACT); }
static void ch_blend_color(void) { glBlendColor(0.1f, 0.2f, 0.3f, 0.4f); }
static void ch_logic_op(void) { glLogicOp(GL_XOR); }
static void ch_accum(void) { glClearAccum(0.5f, 0.5f, 0.5f, 0.5f); }
static void ch_unpack_alignment(void) { glPixelStorei(GL_UNPACK_ALIGNMENT, 2); }
static void ch_pack_row_length(void) { glPixelStorei(GL_PACK_ROW_LENGTH, 7); }
static void ch_unpack_swap(void) { glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE); }
static GLfloat array_data[16];
static void ch_vertex_array(void) { glVertexPointer(3, GL_FLOAT, 16, array_data); }
static void ch_color_array(void) { glColorPointer(3, GL_FLOAT, 12, array_data); }
static void ch_client_texture(void) { glClientActiveTexture(GL_TEXTURE1); }
static void ch_vertex_array_enable(void) { glEnableClientState(GL_VERTEX_ARRAY); }

static void ch_clip_plane(void)
{
    static const GLdouble p[4] = {1, 2, 3, 4};
    glClipPlane(GL_CLIP_PLANE2, p);
}
static void rd_clip_plane(GLdouble *out) { glGetClipPlane(GL_CLIP_PLANE2, out); }
static void ch_light(void)
{
    static const GLfloat d[4] = {0.25f, 0.5f, 0.75f, 1};
    glLightfv(GL_LIGHT1, GL_DIFFUSE, d);
}
static void rd_light(GLdouble *out)
{
    GLfloat f[4];
    glGetLightfv(GL_LIGHT1, GL_DIFFUSE, f);
    for (int k = 0; k < 4; k++)
        out[k] = f[k];
}
static void ch_material(void)
{
    static const GLfloat e[4] = {0.1f, 0.2f, 0.3f, 1};
    glMaterialfv(GL_BACK, GL_EMISSION, e);
}
static void rd_material(GLdouble *out)
{
    GLfloat f[4];
    glGetMaterialfv(GL_BACK, GL_EMISSION, f);
    for (int k = 0; k < 4; k++)
        out[k] = f[k];
}
static void ch_env(void) { glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL); }
static void rd_env(GLdouble *out)
{
    GLint v;
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
    out[0] = v;
}
static void ch_gen(void) { glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR); }
static void rd_gen(GLdouble *out)
{
    GLint v;
    glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &v);
    out[0] = v;
}
static void ch_stipple(void)
{
    GLubyte bits[128];
    for (int k = 0; k < 128; k++)
        bits[k] = (GLubyte)(k * 29 + 1);
    glPolygonStipple(bits);
}
static void rd_stipple(GLdouble *out)
{
    GLubyte bits[128];
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetPolygonStipple(bits);
    unsigned sum = 0;
    for (int k = 0; k < 128; k++)
        sum = sum * 31 + bits[k];
    out[0] = sum;
}
static void ch_pixel_map(void)
{
    static const GLfloat m[2] = {0.25f, 0.75f};
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, m);
}
static void rd_pixel_map(GLdouble *out)
{
    GLint size;
    glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &size);
    out[0] = size;
}

#define S(p, n, fn, g) { #p, p, n, fn, g, 0, 0, NULL }
#define S_MESA_MISSES(p, n, fn, g, m) { #p, p, n, fn, g, 0, m, NULL }
#define C(p, n, fn) { #p, p, n, fn, 0, 1, 0, NULL }
#define R(name, reader, fn, g) { name, 0, 4, fn, g, 0, 0, reader }
#define R_MESA_MISSES(name, reader, fn, g, m) { name, 0, 4, fn, g, 0, m, reader }

static const struct item items[] = {
    S(GL_CURRENT_COLOR, 4, ch_color, GL_CURRENT_BIT),
    S(GL_CURRENT_SECONDARY_COLOR, 4, ch_secondary, GL_CURRENT_BIT),
    S(GL_CURRENT_NORMAL, 3, ch_normal, GL_CURRENT_BIT),
    S(GL_CURRENT_TEXTURE_COORDS, 4, ch_texcoord, GL_CURRENT_BIT),
    S(GL_CURRENT_FOG_COORD, 1, ch_fogcoord, GL_CURRENT_BIT),
    S(GL_CURRENT_INDEX, 1, ch_index, GL_CURRENT_BIT),
    S(GL_EDGE_FLAG, 1, ch_edge, GL_CURRENT_BIT),
    S(GL_CURRENT_RASTER_POSITION, 4, ch_rasterpos, GL_CURRENT_BIT),
    S(GL_POINT_SIZE, 1, ch_point_size, GL_POINT_BIT),
    S(GL_POINT_SIZE_MIN, 1, ch_point_min, GL_POINT_BIT),
    S(GL_POINT_SIZE_MAX, 1, ch_point_max, GL_POINT_BIT),
    S(GL_POINT_FADE_THRESHOLD_SIZE, 1, ch_point_fade, GL_POINT_BIT),
    S(GL_POINT_DISTANCE_ATTENUATION, 3, ch_point_atten, GL_POINT_BIT),
    S(GL_LINE_WIDTH, 1, ch_line_width, GL_LINE_BIT),
    S(GL_LINE_STIPPLE_PATTERN, 1, ch_line_stipple, GL_LINE_BIT),
    S(GL_LINE_STIPPLE_REPEAT, 1, ch_line_stipple, GL_LINE_BIT),
    S(GL_FRONT_FACE, 1, ch_front_face, GL_POLYGON_BIT),
    S(GL_CULL_FACE_MODE, 1, ch_cull_mode, GL_POLYGON_BIT),
    S(GL_POLYGON_MODE, 2, ch_polygon_mode, GL_POLYGON_BIT),
    S(GL_POLYGON_OFFSET_FACTOR, 1, ch_offset, GL_POLYGON_BIT),
    S(GL_POLYGON_OFFSET_UNITS, 1, ch_offset, GL_POLYGON_BIT),
    S(GL_SHADE_MODEL, 1, ch_shade, GL_LIGHTING_BIT),
    S(GL_LIGHT_MODEL_TWO_SIDE, 1, ch_two_side, GL_LIGHTING_BIT),
    S(GL_LIGHT_MODEL_LOCAL_VIEWER, 1, ch_local_viewer, GL_LIGHTING_BIT),
    S(GL_LIGHT_MODEL_AMBIENT, 4, ch_model_ambient, GL_LIGHTING_BIT),
    S(GL_COLOR_MATERIAL_FACE, 1, ch_color_material, GL_LIGHTING_BIT),
    S(GL_COLOR_MATERIAL_PARAMETER, 1, ch_color_material, GL_LIGHTING_BIT),
    S(GL_FOG_MODE, 1, ch_fog_mode, GL_FOG_BIT),
    S(GL_FOG_DENSITY, 1, ch_fog_density, GL_FOG_BIT),
    S(GL_FOG_START, 1, ch_fog_start, GL_FOG_BIT),
    S(GL_FOG_COLOR, 4, ch_fog_color, GL_FOG_BIT),
    /* Table 6.11 puts GL_FOG_COORD_SRC in the fog group; Mesa 22's pop does not restore it
     * (tessera follows the spec): asserted per implementation, left out of the VALUE line. */
    S_MESA_MISSES(GL_FOG_COORD_SRC, 1, ch_fog_src, GL_FOG_BIT, GL_FOG_BIT),
    S(GL_MATRIX_MODE, 1, ch_matrix_mode, GL_TRANSFORM_BIT),
    S(GL_ZOOM_X, 1, ch_zoom, GL_PIXEL_MODE_BIT),
    S(GL_ZOOM_Y, 1, ch_zoom, GL_PIXEL_MODE_BIT),
    S(GL_RED_SCALE, 1, ch_red_scale, GL_PIXEL_MODE_BIT),
    S(GL_DEPTH_BIAS, 1, ch_depth_bias, GL_PIXEL_MODE_BIT),
    S(GL_INDEX_SHIFT, 1, ch_index_shift, GL_PIXEL_MODE_BIT),
    S(GL_MAP_COLOR, 1, ch_map_color, GL_PIXEL_MODE_BIT),
    S(GL_LIST_BASE, 1, ch_list_base, GL_LIST_BIT),
    S(GL_ACTIVE_TEXTURE, 1, ch_active_texture, GL_TEXTURE_BIT),
    S(GL_STENCIL_FUNC, 1, ch_stencil_func, GL_STENCIL_BUFFER_BIT),
    S(GL_STENCIL_REF, 1, ch_stencil_func, GL_STENCIL_BUFFER_BIT),
    S(GL_STENCIL_VALUE_MASK, 1, ch_stencil_func, GL_STENCIL_BUFFER_BIT),
    S(GL_STENCIL_FAIL, 1, ch_stencil_op, GL_STENCIL_BUFFER_BIT),
    S(GL_STENCIL_PASS_DEPTH_PASS, 1, ch_stencil_op, GL_STENCIL_BUFFER_BIT),
    S(GL_DEPTH_FUNC, 1, ch_depth_func, GL_DEPTH_BUFFER_BIT),
    S(GL_ALPHA_TEST_FUNC, 1, ch_alpha_func, GL_COLOR_BUFFER_BIT),
    S(GL_ALPHA_TEST_REF, 1, ch_alpha_func, GL_COLOR_BUFFER_BIT),
    S(GL_BLEND_SRC, 1, ch_blend_func, GL_COLOR_BUFFER_BIT),
    S(GL_BLEND_DST, 1, ch_blend_func, GL_COLOR_BUFFER_BIT),
    S(GL_BLEND_EQUATION, 1, ch_blend_eq, GL_COLOR_BUFFER_BIT),
    S(GL_BLEND_COLOR, 4, ch_blend_color, GL_COLOR_BUFFER_BIT),
    S(GL_LOGIC_OP_MODE, 1, ch_logic_op, GL_COLOR_BUFFER_BIT),
    S(GL_ACCUM_CLEAR_VALUE, 4, ch_accum, GL_ACCUM_BUFFER_BIT),
    R("glGetClipPlane", rd_clip_plane, ch_clip_plane, GL_TRANSFORM_BIT),
    R("glGetLightfv", rd_light, ch_light, GL_LIGHTING_BIT),
    /* Materials are lighting state (table 6.13); Mesa 22's glGetMaterialfv reads back the
     * changed value after the pop (tessera follows the spec). */
    R_MESA_MISSES("glGetMaterialfv", rd_material, ch_material, GL_LIGHTING_BIT, GL_LIGHTING_BIT),
    R("glGetTexEnviv", rd_env, ch_env, GL_TEXTURE_BIT),
    R("glGetTexGeniv", rd_gen, ch_gen, GL_TEXTURE_BIT),
    R("glGetPolygonStipple", rd_stipple, ch_stipple, GL_POLYGON_STIPPLE_BIT),
    /* Pixel maps belong to no group (table 6.24). */
    R("glPixelMap", rd_pixel_map, ch_pixel_map, 0),
    C(GL_UNPACK_ALIGNMENT, 1, ch_unpack_alignment),
    C(GL_PACK_ROW_LENGTH, 1, ch_pack_row_length),
    C(GL_UNPACK_SWAP_BYTES, 1, ch_unpack_swap),
    C(GL_VERTEX_ARRAY_SIZE, 1, ch_vertex_array),
    C(GL_VERTEX_ARRAY_STRIDE, 1, ch_vertex_array),
    C(GL_COLOR_ARRAY_SIZE, 1, ch_color_array),
    C(GL_CLIENT_ACTIVE_TEXTURE, 1, ch_client_texture),
    C(GL_VERTEX_ARRAY, 1, ch_vertex_array_enable),
};
#define NITEMS (int)(sizeof items / sizeof items[0])

static const GLbitfield groups[] = {
    GL_CURRENT_BIT, GL_POINT_BIT, GL_LINE_BIT, GL_POLYGON_BIT, GL_POLYGON_STIPPLE_BIT,
    GL_PIXEL_MODE_BIT, GL_LIGHTING_BIT, GL_FOG_BIT, GL_DEPTH_BUFFER_BIT, GL_ACCUM_BUFFER_BIT,
    GL_STENCIL_BUFFER_BIT, GL_VIEWPORT_BIT, GL_TRANSFORM_BIT, GL_ENABLE_BIT, GL_COLOR_BUFFER_BIT,
    GL_HINT_BIT, GL_LIST_BIT, GL_TEXTURE_BIT, GL_SCISSOR_BIT,
};
static const GLbitfield client_groups[] = {GL_CLIENT_PIXEL_STORE_BIT, GL_CLIENT_VERTEX_ARRAY_BIT};

static void get(int i, GLdouble *out)
{
    for (int k = 0; k < 4; k++)
        out[k] = -999.0;
    if (items[i].read)
        items[i].read(out);
    else
        glGetDoublev(items[i].pname, out);
}

static int restored_by(int i, GLbitfield group, int client)
{
    GLdouble before[4], after[4];
    get(i, before);
    if (client)
        glPushClientAttrib(group);
    else
        glPushAttrib(group);
    items[i].change();
    if (client)
        glPopClientAttrib();
    else
        glPopAttrib();
    get(i, after);
    return memcmp(before, after, sizeof before) == 0;
}

int main(void)
{
    int tessera = capi_probe_is_tessera();
    for (int i = 0; i < NITEMS; i++) {
        GLbitfield restored = 0;
        const GLbitfield *list = items[i].client ? client_groups : groups;
        int n = items[i].client ? 2 : (int)(sizeof groups / sizeof groups[0]);
        for (int g = 0; g < n; g++) {
            /* A fresh context per measurement: each starts from the defaults. */
            OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 16, W, H, NULL);
            if (restored_by(i, list[g], items[i].client))
                restored |= list[g];
            capi_expect_error(GL_NO_ERROR, items[i].name);
            OSMesaDestroyContext(ctx);
        }
        capi_value(items[i].name, "0x%x", restored & ~items[i].mesa_misses);
        GLbitfield expected = tessera ? items[i].owner : items[i].owner & ~items[i].mesa_misses;
        if (!items[i].client)
            capi_check(restored == expected, "%s restored by 0x%x, expected 0x%x", items[i].name, restored,
                       expected);
        else
            capi_check(restored != 0, "%s restored by no client group", items[i].name);
    }
    return capi_finish();
}
