/* Generic vertex attributes (GL 2.0) without a program: the current values every
 * glVertexAttrib form sets (normalized and integer-to-float conversions included) read back
 * by glGetVertexAttrib{f,d,i}v; the array state glVertexAttribPointer and
 * glEnable/DisableVertexAttribArray record, its buffer binding, glPushClientAttrib's save and
 * glDeleteBuffers' reset; attribute 0 aliasing glVertex, in glBegin/glEnd and as an array
 * drawn by glDrawArrays and glDrawElements with fixed-function processing; and the errors
 * of out-of-range indices, sizes, types and strides, each changing nothing. Every value is
 * printed and compared with Mesa; the pictures are compared byte for byte. */
#include "common.h"

#define S 16

static void current(const char *key, GLuint index)
{
    GLfloat f[4] = {-9, -9, -9, -9};
    GLdouble d[4] = {-9, -9, -9, -9};
    GLint i[4] = {-9, -9, -9, -9};
    glGetVertexAttribfv(index, GL_CURRENT_VERTEX_ATTRIB, f);
    glGetVertexAttribdv(index, GL_CURRENT_VERTEX_ATTRIB, d);
    glGetVertexAttribiv(index, GL_CURRENT_VERTEX_ATTRIB, i);
    capi_value(key, "f=%a,%a,%a,%a d=%a,%a,%a,%a i=%d,%d,%d,%d", f[0], f[1], f[2], f[3], d[0], d[1], d[2], d[3], i[0],
               i[1], i[2], i[3]);
    GLenum error = glGetError();
    capi_value(key, "error=0x%x", error);
}

static void array_state(const char *key, GLuint index)
{
    GLint enabled = -1, size = -1, stride = -1, type = -1, normalized = -1, buffer = -1;
    glGetVertexAttribiv(index, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
    glGetVertexAttribiv(index, GL_VERTEX_ATTRIB_ARRAY_SIZE, &size);
    glGetVertexAttribiv(index, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &stride);
    glGetVertexAttribiv(index, GL_VERTEX_ATTRIB_ARRAY_TYPE, &type);
    glGetVertexAttribiv(index, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &normalized);
    glGetVertexAttribiv(index, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &buffer);
    void *pointer = (void *)1;
    glGetVertexAttribPointerv(index, GL_VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
    GLfloat fsize = -1;
    glGetVertexAttribfv(index, GL_VERTEX_ATTRIB_ARRAY_SIZE, &fsize);
    capi_value(key, "enabled=%d size=%d stride=%d type=0x%x normalized=%d buffer=%d pointer=%lu fsize=%a", enabled, size,
               stride, type, normalized, buffer, (unsigned long)(size_t)pointer, fsize);
    capi_expect_error(GL_NO_ERROR, key);
}

static void setters(void)
{
    current("current.initial", 3);
    current("current.zero", 0);
    glVertexAttrib1f(1, 0.5f);
    current("set.1f", 1);
    glVertexAttrib2s(1, -3, 7);
    current("set.2s", 1);
    glVertexAttrib3d(1, 1.25, 2.5, -3.75);
    current("set.3d", 1);
    glVertexAttrib4f(1, 1, 2, 3, 4);
    current("set.4f", 1);
    GLfloat fv[4] = {0.125f, 0.25f, 0.375f, 0.5f};
    glVertexAttrib2fv(2, fv);
    current("set.2fv", 2);
    glVertexAttrib4Nub(2, 0, 51, 128, 255);
    current("set.4Nub", 2);
    GLbyte bv[4] = {-128, -127, 0, 127};
    glVertexAttrib4Nbv(2, bv);
    current("set.4Nbv", 2);
    glVertexAttrib4bv(2, bv);
    current("set.4bv", 2);
    GLshort sv[4] = {-32768, -1, 1, 32767};
    glVertexAttrib4Nsv(3, sv);
    current("set.4Nsv", 3);
    GLushort usv[4] = {0, 1, 32768, 65535};
    glVertexAttrib4Nusv(3, usv);
    current("set.4Nusv", 3);
    glVertexAttrib4usv(3, usv);
    current("set.4usv", 3);
    GLint iv[4] = {-2147483647 - 1, -1, 1, 2147483647};
    glVertexAttrib4Niv(4, iv);
    current("set.4Niv", 4);
    glVertexAttrib4iv(4, iv);
    current("set.4iv", 4);
    GLuint uiv[4] = {0, 1, 2147483648u, 4294967295u};
    glVertexAttrib4Nuiv(4, uiv);
    current("set.4Nuiv", 4);
    glVertexAttrib4uiv(4, uiv);
    current("set.4uiv", 4);
    GLubyte ubv[4] = {0, 1, 128, 255};
    glVertexAttrib4ubv(5, ubv);
    current("set.4ubv", 5);
    GLdouble dv[4] = {1e-40, 3.5, -0.0, 1e40};
    glVertexAttrib4dv(5, dv);
    current("set.4dv", 5);
    glVertexAttrib3f(15, 9, 8, 7);
    current("set.last", 15);

    /* Errors. */
    glVertexAttrib4f(16, 1, 1, 1, 1);
    capi_expect_error(GL_INVALID_VALUE, "error.attrib_index");
    current("error.index_query", 16);
    glGetVertexAttribiv(1, GL_TEXTURE_2D, iv);
    capi_expect_error(GL_INVALID_ENUM, "error.bad_pname");
    /* glPushAttrib(GL_CURRENT_BIT) saves the current generic values. */
    glPushAttrib(GL_CURRENT_BIT);
    glVertexAttrib4f(1, -1, -2, -3, -4);
    glPopAttrib();
    current("pop.current", 1);
}

static void arrays(void)
{
    array_state("array.initial", 1);
    glVertexAttribPointer(1, 3, GL_UNSIGNED_SHORT, GL_TRUE, 12, (void *)64);
    glEnableVertexAttribArray(1);
    array_state("array.set", 1);
    GLuint buffer;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, 256, NULL, GL_STATIC_DRAW);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, 0, (void *)16);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    array_state("array.buffer", 2);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDisableVertexAttribArray(1);
    glVertexAttribPointer(1, 1, GL_BYTE, GL_FALSE, 4, (void *)8);
    array_state("array.changed", 1);
    glPopClientAttrib();
    array_state("array.popped", 1);
    glDeleteBuffers(1, &buffer);
    array_state("array.deleted_buffer", 2);

    /* Errors, each changing nothing. */
    glVertexAttribPointer(16, 4, GL_FLOAT, GL_FALSE, 0, NULL);
    capi_expect_error(GL_INVALID_VALUE, "error.pointer_index");
    glVertexAttribPointer(1, 5, GL_FLOAT, GL_FALSE, 0, NULL);
    capi_expect_error(GL_INVALID_VALUE, "error.pointer_size");
    glVertexAttribPointer(1, 0, GL_FLOAT, GL_FALSE, 0, NULL);
    capi_expect_error(GL_INVALID_VALUE, "error.pointer_size0");
    glVertexAttribPointer(1, 4, GL_TEXTURE_2D, GL_FALSE, 0, NULL);
    capi_expect_error(GL_INVALID_ENUM, "error.pointer_type");
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, -4, NULL);
    capi_expect_error(GL_INVALID_VALUE, "error.pointer_stride");
    glEnableVertexAttribArray(16);
    capi_expect_error(GL_INVALID_VALUE, "error.enable_index");
    glDisableVertexAttribArray(16);
    capi_expect_error(GL_INVALID_VALUE, "error.disable_index");
    GLint value = -5;
    glGetVertexAttribiv(16, GL_VERTEX_ATTRIB_ARRAY_SIZE, &value);
    capi_expect_error(GL_INVALID_VALUE, "error.get_index");
    void *pointer = NULL;
    glGetVertexAttribPointerv(16, GL_VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
    capi_expect_error(GL_INVALID_VALUE, "error.get_pointer_index");
    glGetVertexAttribPointerv(1, GL_VERTEX_ATTRIB_ARRAY_SIZE, &pointer);
    capi_expect_error(GL_INVALID_ENUM, "error.get_pointer_pname");
    /* Mesa 22 writes 0 through `params` of a query that fails; tessera writes nothing. */
    capi_value("error.untouched", "%d %p", value, pointer);
    if (capi_is_tessera())
        capi_check(value == -5 && pointer == NULL, "a failed query writes nothing");
    /* Mesa 22 records GL_INVALID_VALUE for the negative stride and still changes the array
     * (its stride check does not return); tessera changes nothing, as GL says. */
    array_state("array.after_errors", 1);
    if (capi_is_tessera()) {
        GLint stride = -1, size = -1;
        glGetVertexAttribiv(1, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &stride);
        glGetVertexAttribiv(1, GL_VERTEX_ATTRIB_ARRAY_SIZE, &size);
        capi_check(stride == 12 && size == 3, "refused pointers change nothing");
    }
    glDisableVertexAttribArray(1);
}

/* Attribute 0 is the vertex position: glVertexAttrib*(0, ...) provokes a vertex. */
static void aliasing(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, S, 0, S, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertexAttrib2f(0, 1, 1);
    glVertexAttrib3f(0, 7, 1, 0);
    glVertexAttrib4f(0, 1, 7, 0, 1);
    glEnd();
    capi_expect_error(GL_NO_ERROR, "alias.immediate");
    /* An array on attribute 0 (shorts, normalized off) beside a conventional color array. */
    static const GLshort positions[] = {8, 8, 15, 8, 15, 15, 8, 15};
    static const GLubyte colors[] = {0, 255, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 0, 0, 255, 255};
    glVertexAttribPointer(0, 2, GL_SHORT, GL_FALSE, 0, positions);
    glEnableVertexAttribArray(0);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_QUADS, 0, 4);
    capi_expect_error(GL_NO_ERROR, "alias.draw_arrays");
    /* The generic array takes precedence over an enabled conventional vertex array. */
    static const GLfloat elsewhere[] = {0, 8, 6, 8, 6, 15, 0, 15};
    static const GLubyte indices[] = {0, 1, 2, 0, 2, 3};
    glVertexPointer(2, GL_FLOAT, 0, elsewhere);
    glEnableClientState(GL_VERTEX_ARRAY);
    static const GLshort moved[] = {1, 9, 6, 9, 6, 14, 1, 14};
    glVertexAttribPointer(0, 2, GL_SHORT, GL_FALSE, 0, moved);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, indices);
    capi_expect_error(GL_NO_ERROR, "alias.draw_elements");
    glDisableVertexAttribArray(0);
    glDisableClientState(GL_COLOR_ARRAY);
    /* With the generic array disabled, the conventional array draws again. */
    glColor3f(1, 1, 0);
    static const GLfloat corner[] = {10, 1, 14, 1, 14, 5};
    glVertexPointer(2, GL_FLOAT, 0, corner);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisableClientState(GL_VERTEX_ARRAY);
    capi_save_framebuffer("alias", S, S);
    void *pointer = NULL;
    glGetVertexAttribPointerv(0, GL_VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
    capi_value("alias.array0_pointer", "%d", pointer == (void *)moved);
}

int main(void)
{
    void *buffer = NULL;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 16, 0, 0, S, S, &buffer);
    GLint max = 0;
    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &max);
    capi_value("max_vertex_attribs", "%d", max);
    setters();
    arrays();
    aliasing();
    capi_expect_error(GL_NO_ERROR, "end");
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
