/* Client vertex arrays: the state of every array (sizes, types, strides, pointers, enables)
 * after every valid glXxxPointer call and every error case, glEnable/DisableClientState,
 * glClientActiveTexture, glInterleavedArrays with all 14 formats, glGetPointerv,
 * glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT), the values glArrayElement reads from arrays
 * of every type (through the current attributes it sets, exact hex floats), and the errors
 * and current-attribute effects of the draw calls.
 *
 * Deliberate differences from Mesa 22 (asserted per implementation, not printed):
 * - Formats are GL 2.1's: Mesa (GL 4.5) also takes GL_HALF_FLOAT, the packed 2_10_10_10
 *   types, GL_BGRA sizes and 4-component secondary colors; tessera records the GL 2.1 errors.
 * - Mesa refuses strides above GL 4.4's GL_MAX_VERTEX_ATTRIB_STRIDE (2048) with
 *   GL_INVALID_VALUE (GL 2.1 has no limit); for a negative or too large stride Mesa records
 *   the error but still changes the array (a Mesa bug); tessera changes nothing.
 * - glClientActiveTexture takes 8 coordinate sets in both; the modes are GL 2.1's.
 * - glDrawArrays with a negative first: Mesa reads before the array, tessera draws nothing
 *   (not run on Mesa).
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <limits.h>
#include <stdint.h>

static int tessera;

enum array { VERTEX, NORMAL, COLOR, SECONDARY, FOG, INDEX, EDGE, TEX, ARRAYS };
static const char *array_names[ARRAYS] = {"vertex", "normal", "color", "secondary", "fog", "index", "edge", "tex"};
static const GLenum caps[ARRAYS] = {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY,
                                    GL_FOG_COORD_ARRAY, GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY, GL_TEXTURE_COORD_ARRAY};
static const GLenum pointer_names[ARRAYS] = {
    GL_VERTEX_ARRAY_POINTER, GL_NORMAL_ARRAY_POINTER, GL_COLOR_ARRAY_POINTER, GL_SECONDARY_COLOR_ARRAY_POINTER,
    GL_FOG_COORD_ARRAY_POINTER, GL_INDEX_ARRAY_POINTER, GL_EDGE_FLAG_ARRAY_POINTER, GL_TEXTURE_COORD_ARRAY_POINTER};
/* Size, type and stride queries of each array (0: none). */
static const GLenum size_queries[ARRAYS] = {GL_VERTEX_ARRAY_SIZE, 0, GL_COLOR_ARRAY_SIZE, GL_SECONDARY_COLOR_ARRAY_SIZE,
                                            0, 0, 0, GL_TEXTURE_COORD_ARRAY_SIZE};
static const GLenum type_queries[ARRAYS] = {GL_VERTEX_ARRAY_TYPE, GL_NORMAL_ARRAY_TYPE, GL_COLOR_ARRAY_TYPE,
                                            GL_SECONDARY_COLOR_ARRAY_TYPE, GL_FOG_COORD_ARRAY_TYPE,
                                            GL_INDEX_ARRAY_TYPE, 0, GL_TEXTURE_COORD_ARRAY_TYPE};
static const GLenum stride_queries[ARRAYS] = {
    GL_VERTEX_ARRAY_STRIDE, GL_NORMAL_ARRAY_STRIDE, GL_COLOR_ARRAY_STRIDE, GL_SECONDARY_COLOR_ARRAY_STRIDE,
    GL_FOG_COORD_ARRAY_STRIDE, GL_INDEX_ARRAY_STRIDE, GL_EDGE_FLAG_ARRAY_STRIDE, GL_TEXTURE_COORD_ARRAY_STRIDE};
static const GLenum binding_queries[ARRAYS] = {
    GL_VERTEX_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY_BUFFER_BINDING, GL_COLOR_ARRAY_BUFFER_BINDING,
    GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, GL_FOG_COORD_ARRAY_BUFFER_BINDING, GL_INDEX_ARRAY_BUFFER_BINDING,
    GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING};

/* Sets array `a`; sizes of arrays without one are ignored. */
static void set_pointer(enum array a, GLint size, GLenum type, GLsizei stride, const void *pointer)
{
    switch (a) {
    case VERTEX: glVertexPointer(size, type, stride, pointer); break;
    case NORMAL: glNormalPointer(type, stride, pointer); break;
    case COLOR: glColorPointer(size, type, stride, pointer); break;
    case SECONDARY: glSecondaryColorPointer(size, type, stride, pointer); break;
    case FOG: glFogCoordPointer(type, stride, pointer); break;
    case INDEX: glIndexPointer(type, stride, pointer); break;
    case EDGE: glEdgeFlagPointer(stride, pointer); break;
    case TEX: glTexCoordPointer(size, type, stride, pointer); break;
    default: break;
    }
}

static GLint get_int(GLenum pname)
{
    GLint v = -12345;
    if (pname)
        glGetIntegerv(pname, &v);
    return v;
}

/* The state of array `a` as one string (pointer relative to `base`). */
static void describe(enum array a, const void *base, char *out, size_t n)
{
    GLvoid *pointer = NULL;
    glGetPointerv(pointer_names[a], &pointer);
    char where[32] = "null";
    if (pointer)
        snprintf(where, sizeof where, "%+td", (const char *)pointer - (const char *)base);
    snprintf(out, n, "enabled %d/%d size %d type 0x%x stride %d pointer %s binding %d", glIsEnabled(caps[a]),
             get_int(caps[a]), get_int(size_queries[a]), get_int(type_queries[a]), get_int(stride_queries[a]), where,
             get_int(binding_queries[a]));
}

static void show_array(const char *what, enum array a, const void *base)
{
    char state[256];
    describe(a, base, state, sizeof state);
    capi_value(what, "%s %s", array_names[a], state);
}

static void show_all(const char *what, const void *base)
{
    for (int a = 0; a < ARRAYS; a++)
        show_array(what, a, base);
    capi_value(what, "client active texture 0x%x array buffer %d element array buffer %d",
               get_int(GL_CLIENT_ACTIVE_TEXTURE), get_int(GL_ARRAY_BUFFER_BINDING),
               get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING));
}

static const GLenum all_types[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT,
                                   GL_FLOAT, GL_DOUBLE, GL_BOOL, GL_2_BYTES, GL_FIXED, 0, 0x7fffffff};
/* Types Mesa 22 takes beyond GL 2.1. */
static const GLenum later_types[] = {GL_HALF_FLOAT, GL_INT_2_10_10_10_REV, GL_UNSIGNED_INT_2_10_10_10_REV};

static void pointer_formats(void)
{
    static char base[64];
    char key[128], before[256], after[256];
    for (int a = 0; a < ARRAYS; a++) {
        for (unsigned t = 0; t < sizeof all_types / sizeof all_types[0]; t++) {
            for (GLint size = -1; size <= 5; size++) {
                if (a == SECONDARY && size == 4)
                    continue; /* Mesa takes it (below) */
                describe(a, base, before, sizeof before);
                set_pointer(a, size, all_types[t], 4 * (size + 1), base + t);
                GLenum error = glGetError();
                describe(a, base, after, sizeof after);
                snprintf(key, sizeof key, "%s size %d type 0x%x", array_names[a], size, all_types[t]);
                capi_value(key, "error 0x%x %s", error, after);
                if (error != GL_NO_ERROR)
                    capi_check(strcmp(before, after) == 0, "%s: failed call changed %s to %s", key, before, after);
            }
        }
        /* Negative strides, with a valid format. */
        GLint size = a == TEX || a == VERTEX ? 2 : a == COLOR || a == SECONDARY ? 3 : 1;
        GLenum type = a == EDGE ? GL_UNSIGNED_BYTE : a == INDEX ? GL_SHORT : GL_FLOAT;
        set_pointer(a, size, type, 0, base);
        describe(a, base, before, sizeof before);
        set_pointer(a, size, type, -1, base + 8);
        snprintf(key, sizeof key, "%s stride -1", array_names[a]);
        capi_expect_error(GL_INVALID_VALUE, key);
        describe(a, base, after, sizeof after);
        if (tessera)
            capi_check(strcmp(before, after) == 0, "%s: changed %s to %s", key, before, after);
        /* Large strides: no limit in GL 2.1. */
        set_pointer(a, size, type, 4096, base);
        GLenum error = glGetError();
        capi_check(error == (tessera ? GL_NO_ERROR : GL_INVALID_VALUE), "%s stride 4096: 0x%x", array_names[a], error);
        capi_check(get_int(stride_queries[a]) == 4096, "%s stride 4096 reads %d", array_names[a],
                   get_int(stride_queries[a]));
        set_pointer(a, size, type, 2048, base);
        snprintf(key, sizeof key, "%s stride 2048", array_names[a]);
        capi_expect_error(GL_NO_ERROR, key);
        show_array(key, a, base);
        /* Types and sizes beyond GL 2.1. */
        for (unsigned t = 0; a != EDGE && t < sizeof later_types / sizeof later_types[0]; t++) {
            set_pointer(a, 4, later_types[t], 0, base);
            error = glGetError();
            if (tessera)
                capi_check(error != GL_NO_ERROR, "%s type 0x%x size 4 is refused", array_names[a], later_types[t]);
        }
        if (a == COLOR || a == SECONDARY) {
            set_pointer(a, GL_BGRA, GL_UNSIGNED_BYTE, 0, base);
            error = glGetError();
            if (tessera)
                capi_check(error == GL_INVALID_VALUE, "%s size GL_BGRA: 0x%x", array_names[a], error);
        }
        if (a == SECONDARY) {
            /* GL 2.1: 3 components only. */
            set_pointer(a, 4, GL_FLOAT, 0, base);
            error = glGetError();
            capi_check(error == (tessera ? GL_INVALID_VALUE : GL_NO_ERROR), "secondary size 4: 0x%x", error);
        }
        set_pointer(a, size, type, 0, base);
    }
    capi_expect_error(GL_NO_ERROR, "pointer formats");
}

static void enables_and_units(void)
{
    static char base[16];
    for (int a = 0; a < ARRAYS; a++) {
        glEnableClientState(caps[a]);
        show_array("enabled", a, base);
        glDisableClientState(caps[a]);
        show_array("disabled", a, base);
        glEnable(caps[a]); /* Mesa takes the client arrays in glEnable too */
        show_array("glEnable", a, base);
        glDisable(caps[a]);
        show_array("glDisable", a, base);
    }
    const GLenum bad_caps[] = {GL_TEXTURE_2D, GL_LIGHTING, GL_VERTEX_ATTRIB_ARRAY_POINTER, 0};
    for (unsigned i = 0; i < sizeof bad_caps / sizeof bad_caps[0]; i++) {
        char key[64];
        glEnableClientState(bad_caps[i]);
        snprintf(key, sizeof key, "glEnableClientState(0x%x)", bad_caps[i]);
        capi_expect_error(GL_INVALID_ENUM, key);
        glDisableClientState(bad_caps[i]);
        snprintf(key, sizeof key, "glDisableClientState(0x%x)", bad_caps[i]);
        capi_expect_error(GL_INVALID_ENUM, key);
    }

    /* Texture coordinate arrays per client unit. */
    for (int unit = 0; unit < 4; unit++) {
        glClientActiveTexture(GL_TEXTURE0 + unit);
        glTexCoordPointer(unit + 1, unit % 2 ? GL_SHORT : GL_DOUBLE, 8 * unit, base + unit);
        if (unit % 2)
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    }
    glClientActiveTextureARB(GL_TEXTURE1);
    capi_expect_error(GL_NO_ERROR, "texture units");
    for (int unit = 0; unit < 4; unit++) {
        char key[64];
        glClientActiveTexture(GL_TEXTURE0 + unit);
        snprintf(key, sizeof key, "client unit %d", unit);
        show_array(key, TEX, base);
    }
    glClientActiveTexture(GL_TEXTURE0 + 8);
    capi_expect_error(GL_INVALID_ENUM, "glClientActiveTexture(GL_TEXTURE0 + 8)");
    glClientActiveTexture(GL_TEXTURE0 + 32);
    capi_expect_error(GL_INVALID_ENUM, "glClientActiveTexture(GL_TEXTURE0 + 32)");
    glClientActiveTexture(GL_TEXTURE0 - 1);
    capi_expect_error(GL_INVALID_ENUM, "glClientActiveTexture(GL_TEXTURE0 - 1)");
    glClientActiveTexture(GL_TEXTURE3);
    capi_value("client active texture", "0x%x", get_int(GL_CLIENT_ACTIVE_TEXTURE));
    glClientActiveTexture(GL_TEXTURE0);

    /* glGetPointerv names. */
    GLvoid *pointer = (GLvoid *)base;
    glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &pointer);
    capi_check(pointer == NULL, "no feedback buffer");
    glGetPointerv(GL_SELECTION_BUFFER_POINTER, &pointer);
    capi_check(pointer == NULL, "no selection buffer");
    capi_expect_error(GL_NO_ERROR, "feedback and selection pointers");
    const GLenum bad_pointer_names[] = {GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_SIZE, 0};
    for (unsigned i = 0; i < sizeof bad_pointer_names / sizeof bad_pointer_names[0]; i++) {
        char key[64];
        pointer = (GLvoid *)base;
        glGetPointerv(bad_pointer_names[i], &pointer);
        snprintf(key, sizeof key, "glGetPointerv(0x%x)", bad_pointer_names[i]);
        capi_expect_error(GL_INVALID_ENUM, key);
        capi_check(pointer == base, "%s writes nothing", key);
    }
    GLvoid *ext = NULL;
    glGetPointervEXT(GL_TEXTURE_COORD_ARRAY_POINTER, &ext);
    capi_check(ext == base, "glGetPointervEXT");
}

static void interleaved(void)
{
    static char base[256];
    const struct { const char *name; GLenum format; } formats[] = {
        {"GL_V2F", GL_V2F}, {"GL_V3F", GL_V3F}, {"GL_C4UB_V2F", GL_C4UB_V2F}, {"GL_C4UB_V3F", GL_C4UB_V3F},
        {"GL_C3F_V3F", GL_C3F_V3F}, {"GL_N3F_V3F", GL_N3F_V3F}, {"GL_C4F_N3F_V3F", GL_C4F_N3F_V3F},
        {"GL_T2F_V3F", GL_T2F_V3F}, {"GL_T4F_V4F", GL_T4F_V4F}, {"GL_T2F_C4UB_V3F", GL_T2F_C4UB_V3F},
        {"GL_T2F_C3F_V3F", GL_T2F_C3F_V3F}, {"GL_T2F_N3F_V3F", GL_T2F_N3F_V3F},
        {"GL_T2F_C4F_N3F_V3F", GL_T2F_C4F_N3F_V3F}, {"GL_T4F_C4F_N3F_V4F", GL_T4F_C4F_N3F_V4F},
    };
    for (unsigned f = 0; f < sizeof formats / sizeof formats[0]; f++) {
        for (GLsizei stride = 0; stride <= 100; stride += 100) {
            for (int a = 0; a < ARRAYS; a++) {
                set_pointer(a, a == VERTEX || a == TEX ? 2 : 3, a == EDGE ? GL_UNSIGNED_BYTE : GL_SHORT, 6, base);
                glEnableClientState(caps[a]);
            }
            glClientActiveTexture(GL_TEXTURE1);
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
            glClientActiveTexture(GL_TEXTURE0);
            glGetError();
            glInterleavedArrays(formats[f].format, stride, base + 16);
            char key[64];
            snprintf(key, sizeof key, "%s stride %d", formats[f].name, stride);
            capi_expect_error(GL_NO_ERROR, key);
            show_all(key, base);
            glClientActiveTexture(GL_TEXTURE1);
            capi_value(key, "unit 1 texture array still enabled %d", glIsEnabled(GL_TEXTURE_COORD_ARRAY));
            glClientActiveTexture(GL_TEXTURE0);
        }
    }
    /* The client active unit's array is the one set. */
    glClientActiveTexture(GL_TEXTURE2);
    glInterleavedArrays(GL_T2F_V3F, 0, base);
    show_all("GL_T2F_V3F on client unit 2", base);
    glClientActiveTexture(GL_TEXTURE0);
    show_array("unit 0 after GL_T2F_V3F on unit 2", TEX, base);
    /* Errors change nothing. */
    char before[256], after[256];
    describe(VERTEX, base, before, sizeof before);
    glInterleavedArrays(GL_V2F, -1, base);
    capi_expect_error(GL_INVALID_VALUE, "glInterleavedArrays stride -1");
    glInterleavedArrays(GL_V2F - 1, 0, base);
    capi_expect_error(GL_INVALID_ENUM, "glInterleavedArrays(GL_V2F - 1)");
    glInterleavedArrays(GL_T4F_C4F_N3F_V4F + 1, 0, base);
    capi_expect_error(GL_INVALID_ENUM, "glInterleavedArrays(GL_T4F_C4F_N3F_V4F + 1)");
    glInterleavedArrays(0x1234, -1, base);
    capi_expect_error(GL_INVALID_VALUE, "glInterleavedArrays bad format and stride");
    describe(VERTEX, base, after, sizeof after);
    capi_check(strcmp(before, after) == 0, "failed glInterleavedArrays changed %s to %s", before, after);
    /* Strides that are not multiples of anything are fine. */
    glInterleavedArrays(GL_C4UB_V2F, 3, base);
    capi_expect_error(GL_NO_ERROR, "glInterleavedArrays stride 3");
    show_all("GL_C4UB_V2F stride 3", base);
}

static void client_attrib_stack(void)
{
    static char base[64];
    glClientActiveTexture(GL_TEXTURE2);
    glColorPointer(3, GL_UNSIGNED_SHORT, 10, base + 3);
    glEnableClientState(GL_COLOR_ARRAY);
    glTexCoordPointer(1, GL_INT, 0, base + 5);
    glPixelStorei(GL_PACK_ALIGNMENT, 2);
    show_all("before push", base);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glInterleavedArrays(GL_T4F_C4F_N3F_V4F, 0, base);
    glClientActiveTexture(GL_TEXTURE0);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPopClientAttrib();
    capi_expect_error(GL_NO_ERROR, "client push/pop");
    show_all("after pop", base);
    capi_value("pack alignment after vertex array pop", "%d", get_int(GL_PACK_ALIGNMENT));
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glDisableClientState(GL_COLOR_ARRAY);
    glPopClientAttrib();
    show_array("pixel store pop leaves arrays", COLOR, base);
    glClientActiveTexture(GL_TEXTURE0);
}

/* glArrayElement outside glBegin/glEnd sets the current attributes from element 1 of every
 * enabled array: the arrays' decoding and conversions, read back exactly. */
static void show_current(const char *what)
{
    GLfloat c[4], s[4], n[3], t[4], f, i;
    GLboolean e;
    glGetFloatv(GL_CURRENT_COLOR, c);
    glGetFloatv(GL_CURRENT_SECONDARY_COLOR, s);
    glGetFloatv(GL_CURRENT_NORMAL, n);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
    glGetFloatv(GL_CURRENT_FOG_COORD, &f);
    glGetFloatv(GL_CURRENT_INDEX, &i);
    glGetBooleanv(GL_EDGE_FLAG, &e);
    capi_value(what, "color %a %a %a %a secondary %a %a %a %a normal %a %a %a tex %a %a %a %a fog %a index %a edge %d",
               c[0], c[1], c[2], c[3], s[0], s[1], s[2], s[3], n[0], n[1], n[2], t[0], t[1], t[2], t[3], f, i, e);
    /* An empty glBegin/glEnd makes Mesa's immediate-mode storage start afresh (see
     * vertex_current.c for the Mesa bug this avoids). */
    glBegin(GL_POINTS);
    glEnd();
}

static void array_element_values(void)
{
    /* Element 0 is padding, element 1 the values, each element 4 components wide. */
    static const GLbyte b[8] = {0, 0, 0, 0, -128, 127, 1, -37};
    static const GLubyte ub[8] = {0, 0, 0, 0, 255, 0, 3, 200};
    static const GLshort s[8] = {0, 0, 0, 0, -32768, 32767, 1, -12345};
    static const GLushort us[8] = {0, 0, 0, 0, 65535, 0, 257, 12345};
    static const GLint i[8] = {0, 0, 0, 0, INT_MIN, INT_MAX, 1, 2147483583};
    static const GLuint ui[8] = {0, 0, 0, 0, 4294967295u, 0, 4294967167u, 4294967040u};
    static const GLfloat f[8] = {0, 0, 0, 0, 0.1f, -2.5f, 3e10f, 0.75f};
    static const GLdouble d[8] = {0, 0, 0, 0, 0.1, -2.5, 1.0 / 3.0, 1e-40};
    const struct { const char *name; GLenum type; const void *data; } sources[] = {
        {"byte", GL_BYTE, b}, {"ubyte", GL_UNSIGNED_BYTE, ub}, {"short", GL_SHORT, s},
        {"ushort", GL_UNSIGNED_SHORT, us}, {"int", GL_INT, i}, {"uint", GL_UNSIGNED_INT, ui},
        {"float", GL_FLOAT, f}, {"double", GL_DOUBLE, d},
    };
    const int sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
    for (int a = 0; a < ARRAYS; a++)
        glDisableClientState(caps[a]);
    for (unsigned k = 0; k < sizeof sources / sizeof sources[0]; k++) {
        for (int a = 0; a < ARRAYS; a++) {
            if (a == VERTEX || a == EDGE)
                continue; /* the edge flag array holds GLbooleans whatever the source (below) */
            for (GLint size = 1; size <= (a == SECONDARY ? 3 : 4); size++) {
                glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
                glSecondaryColor3f(0.5f, 0.5f, 0.5f);
                glNormal3f(0.5f, 0.5f, 0.5f);
                glTexCoord4f(0.5f, 0.5f, 0.5f, 0.5f);
                glFogCoordf(0.5f);
                glIndexf(0.5f);
                glEdgeFlag(GL_TRUE);
                glBegin(GL_POINTS);
                glEnd();
                set_pointer(a, size, sources[k].type, 4 * sizes[k], sources[k].data);
                if (glGetError() != GL_NO_ERROR)
                    continue;
                glEnableClientState(caps[a]);
                glArrayElement(1);
                glDisableClientState(caps[a]);
                char key[96];
                snprintf(key, sizeof key, "glArrayElement %s size %d %s", array_names[a], size, sources[k].name);
                show_current(key);
                if (a == NORMAL || a == FOG || a == INDEX)
                    break;
            }
        }
    }
    /* Edge flags: GL_FALSE and GL_TRUE elements (tessera also takes any nonzero GLboolean as
     * TRUE; Mesa only exactly 1, as for glEdgeFlag). */
    static const GLboolean flags[4] = {1, 0, 1, 7};
    glEdgeFlagPointer(0, flags);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glArrayElement(1);
    show_current("glArrayElement edge flag 0");
    glArrayElement(2);
    show_current("glArrayElement edge flag 1");
    glEdgeFlag(GL_FALSE);
    glArrayElement(3);
    GLboolean edge;
    glGetBooleanv(GL_EDGE_FLAG, &edge);
    capi_check(edge == (tessera ? GL_TRUE : GL_FALSE), "edge flag element 7 reads %d", edge);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    glEdgeFlag(GL_TRUE);

    /* Stride and an odd offset: element 2 of a 7-byte-stride array of 3 ubytes. */
    static const GLubyte packed[21] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 9, 99, 199, 0, 0, 0, 0};
    glColorPointer(3, GL_UNSIGNED_BYTE, 7, packed);
    glEnableClientState(GL_COLOR_ARRAY);
    glArrayElement(2);
    show_current("glArrayElement stride 7");
    /* glArrayElement between glBegin and glEnd emits vertices; the values stay current. */
    static const GLfloat positions[6] = {1, 2, 3, 4, 5, 6};
    glVertexPointer(2, GL_FLOAT, 0, positions);
    glEnableClientState(GL_VERTEX_ARRAY);
    glBegin(GL_LINES);
    glArrayElement(0);
    glArrayElement(1);
    glEnd();
    capi_expect_error(GL_NO_ERROR, "glArrayElement inside");
    show_current("after glArrayElement inside");
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    /* A negative element is ignored (Mesa reads before the array; only on tessera). */
    if (tessera) {
        glEnableClientState(GL_COLOR_ARRAY);
        glColor4f(0.25f, 0.25f, 0.25f, 0.25f);
        glArrayElement(-1);
        GLfloat c[4];
        glGetFloatv(GL_CURRENT_COLOR, c);
        capi_check(c[0] == 0.25f, "glArrayElement(-1) changes nothing");
        glDisableClientState(GL_COLOR_ARRAY);
    }
    capi_expect_error(GL_NO_ERROR, "array element values");
}

static void draws(void)
{
    static const GLfloat positions[16] = {0, 0, 4, 0, 4, 4, 0, 4, 8, 8, 12, 8, 12, 12, 8, 12};
    static const GLubyte colors[32] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9,
                                       1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    static const GLubyte ub_indices[6] = {0, 1, 2, 0, 2, 3};
    static const GLushort us_indices[6] = {4, 5, 6, 4, 6, 7};
    static const GLuint ui_indices[6] = {7, 6, 5, 7, 5, 4};
    glVertexPointer(2, GL_FLOAT, 0, positions);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glColor4f(0.5f, 0.25f, 0.125f, 1.0f);

    glDrawArrays(GL_QUADS, 0, 8);
    glDrawArraysEXT(GL_TRIANGLE_FAN, 4, 4);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, ub_indices);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, us_indices);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, ui_indices);
    glDrawRangeElements(GL_TRIANGLES, 0, 3, 6, GL_UNSIGNED_BYTE, ub_indices);
    glDrawRangeElementsEXT(GL_POINTS, 4, 7, 6, GL_UNSIGNED_SHORT, us_indices);
    const GLint firsts[3] = {0, 4, 2};
    const GLsizei counts[3] = {4, 0, 3};
    glMultiDrawArrays(GL_LINE_LOOP, firsts, counts, 3);
    glMultiDrawArraysEXT(GL_POINTS, firsts, counts, 3);
    const GLvoid *index_pointers[3] = {ub_indices, ub_indices + 3, ub_indices};
    const GLsizei index_counts[3] = {3, 3, 0};
    glMultiDrawElements(GL_TRIANGLES, index_counts, GL_UNSIGNED_BYTE, index_pointers, 3);
    glMultiDrawElementsEXT(GL_LINES, index_counts, GL_UNSIGNED_BYTE, index_pointers, 2);
    glDrawArrays(GL_POINTS, 0, 0);
    glDrawElements(GL_POINTS, 0, GL_UNSIGNED_INT, NULL);
    capi_expect_error(GL_NO_ERROR, "draws");
    /* Draws leave the current attributes as they were. */
    show_current("after draws");
    /* Without the vertex array nothing is drawn, and nothing is an error. */
    glDisableClientState(GL_VERTEX_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, ub_indices);
    capi_expect_error(GL_NO_ERROR, "draws without the vertex array");
    glEnableClientState(GL_VERTEX_ARRAY);
    if (tessera) {
        glDrawArrays(GL_TRIANGLES, -3, 3);
        capi_check(glGetError() == GL_NO_ERROR, "negative first draws nothing");
    }

    /* Errors, in Mesa's order. */
    const GLint bad_firsts[2] = {0, 0};
    const GLsizei bad_counts[2] = {3, -1};
    const GLvoid *bad_pointers[2] = {ub_indices, ub_indices};
    glDrawArrays(GL_TRIANGLES, 0, -1);
    capi_expect_error(GL_INVALID_VALUE, "glDrawArrays count -1");
    glDrawArrays(0xF, 0, -1);
    capi_expect_error(GL_INVALID_VALUE, "glDrawArrays bad mode count -1");
    glDrawArrays(0xF, 0, 3);
    capi_expect_error(GL_INVALID_ENUM, "glDrawArrays bad mode");
    glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_BYTE, ub_indices);
    capi_expect_error(GL_INVALID_VALUE, "glDrawElements count -1");
    glDrawElements(0xF, -1, GL_FLOAT, ub_indices);
    capi_expect_error(GL_INVALID_VALUE, "glDrawElements count -1 bad mode and type");
    glDrawElements(0xF, 3, GL_UNSIGNED_BYTE, ub_indices);
    capi_expect_error(GL_INVALID_ENUM, "glDrawElements bad mode");
    const GLenum bad_index_types[] = {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, 0};
    for (unsigned k = 0; k < sizeof bad_index_types / sizeof bad_index_types[0]; k++) {
        char key[64];
        glDrawElements(GL_TRIANGLES, 3, bad_index_types[k], ub_indices);
        snprintf(key, sizeof key, "glDrawElements type 0x%x", bad_index_types[k]);
        capi_expect_error(GL_INVALID_ENUM, key);
        glDrawElements(GL_TRIANGLES, 0, bad_index_types[k], ub_indices);
        snprintf(key, sizeof key, "glDrawElements count 0 type 0x%x", bad_index_types[k]);
        capi_expect_error(GL_INVALID_ENUM, key);
    }
    glDrawRangeElements(0xF, 2, 1, -1, GL_FLOAT, ub_indices);
    capi_expect_error(GL_INVALID_VALUE, "glDrawRangeElements end < start first");
    glDrawRangeElements(0xF, 1, 2, -1, GL_FLOAT, ub_indices);
    capi_expect_error(GL_INVALID_VALUE, "glDrawRangeElements count -1");
    glDrawRangeElements(0xF, 1, 2, 3, GL_FLOAT, ub_indices);
    capi_expect_error(GL_INVALID_ENUM, "glDrawRangeElements bad mode");
    glDrawRangeElements(GL_POINTS, 1, 2, 3, GL_FLOAT, ub_indices);
    capi_expect_error(GL_INVALID_ENUM, "glDrawRangeElements bad type");
    glDrawRangeElements(GL_POINTS, 5, 5, 3, GL_UNSIGNED_BYTE, ub_indices);
    capi_expect_error(GL_NO_ERROR, "glDrawRangeElements start == end");
    glMultiDrawArrays(0xF, bad_firsts, bad_counts, -1);
    capi_expect_error(GL_INVALID_VALUE, "glMultiDrawArrays drawcount -1");
    glMultiDrawArrays(0xF, bad_firsts, bad_counts, 2);
    capi_expect_error(GL_INVALID_ENUM, "glMultiDrawArrays bad mode");
    glMultiDrawArrays(GL_POINTS, bad_firsts, bad_counts, 2);
    capi_expect_error(GL_INVALID_VALUE, "glMultiDrawArrays count -1");
    glMultiDrawArrays(GL_POINTS, bad_firsts, bad_counts, 0);
    capi_expect_error(GL_NO_ERROR, "glMultiDrawArrays drawcount 0");
    glMultiDrawElements(0xF, bad_counts, GL_FLOAT, bad_pointers, -1);
    capi_expect_error(GL_INVALID_VALUE, "glMultiDrawElements drawcount -1");
    glMultiDrawElements(0xF, bad_counts, GL_FLOAT, bad_pointers, 2);
    capi_expect_error(GL_INVALID_ENUM, "glMultiDrawElements bad mode");
    glMultiDrawElements(GL_POINTS, bad_counts, GL_FLOAT, bad_pointers, 2);
    capi_expect_error(GL_INVALID_ENUM, "glMultiDrawElements bad type");
    glMultiDrawElements(GL_POINTS, bad_counts, GL_UNSIGNED_BYTE, bad_pointers, 2);
    capi_expect_error(GL_INVALID_VALUE, "glMultiDrawElements count -1");
    for (GLenum mode = 0xA; mode <= 0xE; mode++) {
        glDrawArrays(mode, 0, 4);
        GLenum error = glGetError();
        if (tessera)
            capi_check(error == GL_INVALID_ENUM, "glDrawArrays mode 0x%x: 0x%x", mode, error);
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 16, 16, &buffer);
    tessera = capi_is_tessera();

    show_all("initial", NULL);
    capi_value("max elements", "%d %d", get_int(GL_MAX_ELEMENTS_VERTICES), get_int(GL_MAX_ELEMENTS_INDICES));
    pointer_formats();
    enables_and_units();
    interleaved();
    client_attrib_stack();
    array_element_values();
    draws();
    capi_expect_error(GL_NO_ERROR, "end");

    /* Mesa 22 crashes destroying a current context with unflushed draws. */
    glFinish();
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
