/* Buffer objects (GL 1.5 and the ARB names): names, bindings, glBufferData with every usage,
 * glBufferSubData/glGetBufferSubData round trips and range errors, glMapBuffer/glUnmapBuffer,
 * the parameter and pointer queries, deletion, arrays and indices taken from buffers (array
 * pointers are offsets, glArrayElement reads the buffer's bytes), and the client attribute
 * stack with buffer bindings. Every error is printed and compared with Mesa.
 *
 * Deliberate differences from Mesa 22 (asserted per implementation, not printed):
 * - Drawing from a mapped buffer is GL_INVALID_OPERATION (allowed by GL 1.5); Mesa draws.
 * - A glBufferData that runs out of memory keeps the old contents; Mesa empties the buffer.
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <stdint.h>

static int tessera;

static GLint get_int(GLenum pname)
{
    GLint v = -12345;
    glGetIntegerv(pname, &v);
    return v;
}

/* The four parameters and the map pointer of the buffer bound to `target`. */
static void show_buffer(const char *what, GLenum target, const void *mapped)
{
    const GLenum pnames[4] = {GL_BUFFER_SIZE, GL_BUFFER_USAGE, GL_BUFFER_ACCESS, GL_BUFFER_MAPPED};
    GLint v[4];
    for (int i = 0; i < 4; i++) {
        v[i] = -12345;
        glGetBufferParameteriv(target, pnames[i], &v[i]);
    }
    GLvoid *pointer = (GLvoid *)&v;
    glGetBufferPointerv(target, GL_BUFFER_MAP_POINTER, &pointer);
    capi_check(pointer == mapped, "%s: map pointer %p, expected %p", what, pointer, mapped);
    capi_value(what, "size %d usage 0x%x access 0x%x mapped %d pointer %s", v[0], v[1], v[2], v[3],
               pointer ? "set" : "null");
}

static void show_bytes(const char *what, GLenum target, GLintptr offset, GLsizeiptr size)
{
    unsigned char bytes[64];
    memset(bytes, 0xee, sizeof bytes);
    glGetBufferSubData(target, offset, size, bytes);
    char line[256];
    int len = snprintf(line, sizeof line, "error 0x%x:", glGetError());
    for (int i = 0; i < size + 1 && i < 64; i++)
        len += snprintf(line + len, sizeof line - len, " %d", bytes[i]);
    capi_value(what, "%s", line);
}

static void names_and_bindings(void)
{
    GLuint names[4] = {0};
    glGenBuffers(3, names);
    capi_value("generated", "%u %u %u", names[0], names[1], names[2]);
    glGenBuffers(-1, names + 3);
    capi_expect_error(GL_INVALID_VALUE, "glGenBuffers(-1)");
    glGenBuffers(0, names + 3);
    capi_expect_error(GL_NO_ERROR, "glGenBuffers(0)");
    capi_value("glIsBuffer generated, unbound", "%d", glIsBuffer(names[0]));
    capi_value("glIsBuffer 0 and unknown", "%d %d", glIsBuffer(0), glIsBuffer(77));
    glBindBuffer(GL_ARRAY_BUFFER, names[0]);
    capi_value("glIsBuffer bound", "%d %d", glIsBuffer(names[0]), glIsBufferARB(names[0]));
    glBindBufferARB(GL_ELEMENT_ARRAY_BUFFER, 77);
    capi_expect_error(GL_NO_ERROR, "bind unknown name");
    capi_value("bindings", "array %d element %d", get_int(GL_ARRAY_BUFFER_BINDING),
               get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING));
    capi_value("glIsBuffer bound unknown", "%d", glIsBuffer(77));
    show_buffer("fresh", GL_ARRAY_BUFFER, NULL);
    glBindBuffer(0x1234, names[1]);
    capi_expect_error(GL_INVALID_ENUM, "glBindBuffer(0x1234)");
    const GLenum pixel_targets[2] = {GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER};
    for (int i = 0; i < 2; i++) {
        glBindBuffer(pixel_targets[i], names[1]);
        GLenum error = glGetError();
        capi_check(error == GL_NO_ERROR, "bind 0x%x: 0x%x", pixel_targets[i], error);
        glBindBuffer(pixel_targets[i], 0);
        glGetError();
    }

    /* Deletion: 0 and unknown names are ignored; names continue after the largest in use. */
    GLuint doomed[4] = {0, 12345, names[0], names[1]};
    glDeleteBuffers(4, doomed);
    capi_expect_error(GL_NO_ERROR, "glDeleteBuffers");
    glDeleteBuffersARB(-1, doomed);
    capi_expect_error(GL_INVALID_VALUE, "glDeleteBuffers(-1)");
    capi_value("deleted", "%d %d array binding %d", glIsBuffer(names[0]), glIsBuffer(names[1]),
               get_int(GL_ARRAY_BUFFER_BINDING));
    GLuint more[2];
    glGenBuffersARB(2, more);
    capi_value("generated after deletion", "%u %u", more[0], more[1]);
    GLuint all[5] = {names[2], 77, more[0], more[1], 0};
    glDeleteBuffers(5, all);
    glGenBuffers(1, more);
    capi_value("generated after deleting all", "%u", more[0]);
    glDeleteBuffers(1, more);
    capi_expect_error(GL_NO_ERROR, "names");
}

static void data_and_sub_data(void)
{
    GLuint name;
    glGenBuffers(1, &name);
    /* Without a buffer bound. */
    unsigned char bytes[32];
    glBufferData(GL_ARRAY_BUFFER, 4, NULL, GL_STATIC_DRAW);
    capi_expect_error(GL_INVALID_OPERATION, "glBufferData unbound");
    glBufferData(GL_ARRAY_BUFFER, -1, NULL, 0x1234);
    capi_expect_error(GL_INVALID_OPERATION, "glBufferData unbound, bad size and usage");
    glBufferSubData(GL_ARRAY_BUFFER, -1, 0, bytes);
    capi_expect_error(GL_INVALID_OPERATION, "glBufferSubData unbound");
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, 1, bytes);
    capi_expect_error(GL_INVALID_OPERATION, "glGetBufferSubData unbound");
    glBufferData(0x1234, -1, NULL, 0x1234);
    capi_expect_error(GL_INVALID_ENUM, "glBufferData bad target");
    GLint v = -7;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, 0x1234, &v);
    capi_expect_error(GL_INVALID_OPERATION, "glGetBufferParameteriv unbound, bad pname");
    capi_check(v == -7, "a failed query writes nothing");
    GLvoid *pointer;
    glGetBufferPointerv(GL_ARRAY_BUFFER, 0x1234, &pointer);
    capi_expect_error(GL_INVALID_ENUM, "glGetBufferPointerv unbound, bad pname");
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &pointer);
    capi_expect_error(GL_INVALID_OPERATION, "glGetBufferPointerv unbound");

    glBindBuffer(GL_ARRAY_BUFFER, name);
    glBufferData(GL_ARRAY_BUFFER, -1, NULL, 0x1234);
    capi_expect_error(GL_INVALID_VALUE, "glBufferData size -1, bad usage");
    glBufferData(GL_ARRAY_BUFFER, 8, NULL, 0x1234);
    capi_expect_error(GL_INVALID_ENUM, "glBufferData bad usage");
    const GLenum usages[9] = {GL_STREAM_DRAW, GL_STREAM_READ, GL_STREAM_COPY, GL_STATIC_DRAW, GL_STATIC_READ,
                              GL_STATIC_COPY, GL_DYNAMIC_DRAW, GL_DYNAMIC_READ, GL_DYNAMIC_COPY};
    for (int i = 0; i < 9; i++) {
        char key[64];
        glBufferData(GL_ARRAY_BUFFER, i, NULL, usages[i]);
        snprintf(key, sizeof key, "usage 0x%x", usages[i]);
        capi_expect_error(GL_NO_ERROR, key);
        show_buffer(key, GL_ARRAY_BUFFER, NULL);
    }

    unsigned char data[16];
    for (int i = 0; i < 16; i++)
        data[i] = (unsigned char)(i * 3 + 1);
    glBufferDataARB(GL_ARRAY_BUFFER, 16, data, GL_DYNAMIC_DRAW);
    show_buffer("16 bytes", GL_ARRAY_BUFFER, NULL);
    show_bytes("all 16", GL_ARRAY_BUFFER, 0, 16);
    show_bytes("4 at 4", GL_ARRAY_BUFFER, 4, 4);
    show_bytes("0 at 16", GL_ARRAY_BUFFER, 16, 0);
    const struct { GLintptr offset; GLsizeiptr size; } ranges[] = {{-1, 1}, {0, -1}, {9, 8}, {8, 8}, {17, 0}, {16, 1}};
    for (unsigned i = 0; i < sizeof ranges / sizeof ranges[0]; i++) {
        char key[64];
        glBufferSubData(GL_ARRAY_BUFFER, ranges[i].offset, ranges[i].size, "abcdefgh");
        snprintf(key, sizeof key, "glBufferSubData %td %td", ranges[i].offset, ranges[i].size);
        capi_expect_error(ranges[i].offset == 8 ? GL_NO_ERROR : GL_INVALID_VALUE, key);
        snprintf(key, sizeof key, "glGetBufferSubData %td %td", ranges[i].offset, ranges[i].size);
        show_bytes(key, GL_ARRAY_BUFFER, ranges[i].offset, ranges[i].size);
    }
    glBufferSubDataARB(GL_ARRAY_BUFFER, 2, 3, "xyz");
    glBufferSubData(GL_ARRAY_BUFFER, 0, 0, NULL);
    capi_expect_error(GL_NO_ERROR, "sub data");
    glGetBufferSubDataARB(GL_ARRAY_BUFFER, 0, 16, bytes);
    capi_check(memcmp(bytes, "\x01\x04xyz\x10\x13\x16" "abcdefgh", 16) == 0, "round trip");
    show_bytes("after sub data", GL_ARRAY_BUFFER, 0, 16);
    /* NULL data leaves zeros in tessera (the contents are undefined in GL). */
    glBufferData(GL_ARRAY_BUFFER, 4, NULL, GL_STATIC_DRAW);
    if (tessera) {
        memset(bytes, 0xee, 4);
        glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, bytes);
        capi_check(!memcmp(bytes, "\0\0\0\0", 4), "zero-filled");
    }

    /* Out of memory. */
    glBufferData(GL_ARRAY_BUFFER, 8, data, GL_STATIC_DRAW);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)1 << 62, NULL, GL_STREAM_DRAW);
    capi_expect_error(GL_OUT_OF_MEMORY, "glBufferData 2^62 bytes");
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    capi_check(v == (tessera ? 8 : 0), "size after running out of memory: %d", v);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, 0x1234, &v);
    capi_expect_error(GL_INVALID_ENUM, "glGetBufferParameteriv bad pname");
    glGetBufferParameteriv(0x1234, GL_BUFFER_SIZE, &v);
    capi_expect_error(GL_INVALID_ENUM, "glGetBufferParameteriv bad target");
    glGetBufferPointerv(0x1234, GL_BUFFER_MAP_POINTER, &pointer);
    capi_expect_error(GL_INVALID_ENUM, "glGetBufferPointerv bad target");
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDeleteBuffers(1, &name);
}

static void mapping(void)
{
    GLuint name;
    glGenBuffers(1, &name);
    glBindBuffer(GL_ARRAY_BUFFER, name);
    GLvoid *p = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    capi_expect_error(GL_INVALID_OPERATION, "map an empty buffer");
    capi_check(p == NULL, "failed map is NULL");
    glBufferData(GL_ARRAY_BUFFER, 8, "ABCDEFGH", GL_STATIC_DRAW);
    p = glMapBuffer(0x1234, GL_READ_ONLY);
    capi_expect_error(GL_INVALID_ENUM, "glMapBuffer bad target");
    p = glMapBuffer(GL_ARRAY_BUFFER, 0x1234);
    capi_expect_error(GL_INVALID_ENUM, "glMapBuffer bad access");
    capi_check(p == NULL, "failed map is NULL");
    glUnmapBuffer(0x1234);
    capi_expect_error(GL_INVALID_ENUM, "glUnmapBuffer bad target");
    GLboolean unmapped = glUnmapBuffer(GL_ARRAY_BUFFER);
    capi_expect_error(GL_INVALID_OPERATION, "glUnmapBuffer not mapped");
    capi_check(!unmapped, "glUnmapBuffer of an unmapped buffer is GL_FALSE");

    const GLenum accesses[3] = {GL_READ_ONLY, GL_WRITE_ONLY, GL_READ_WRITE};
    for (int i = 0; i < 3; i++) {
        char key[64];
        p = i == 1 ? glMapBufferARB(GL_ARRAY_BUFFER, accesses[i]) : glMapBuffer(GL_ARRAY_BUFFER, accesses[i]);
        snprintf(key, sizeof key, "mapped 0x%x", accesses[i]);
        capi_expect_error(GL_NO_ERROR, key);
        capi_check(p != NULL, "%s: pointer", key);
        show_buffer(key, GL_ARRAY_BUFFER, p);
        if (i == 0)
            capi_check(p && memcmp(p, "ABCDEFGH", 8) == 0, "mapped contents");
        if (i == 2 && p)
            memcpy(p, "map!", 4);
        GLvoid *again = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
        capi_expect_error(GL_INVALID_OPERATION, "map twice");
        capi_check(again == NULL, "second map is NULL");
        unsigned char bytes[4];
        glBufferSubData(GL_ARRAY_BUFFER, 0, 1, "z");
        capi_expect_error(GL_INVALID_OPERATION, "glBufferSubData while mapped");
        glGetBufferSubData(GL_ARRAY_BUFFER, 0, 1, bytes);
        capi_expect_error(GL_INVALID_OPERATION, "glGetBufferSubData while mapped");
        glBufferSubData(GL_ARRAY_BUFFER, 0, 9, "z");
        capi_expect_error(GL_INVALID_VALUE, "glBufferSubData while mapped, out of range");
        glGetBufferSubData(GL_ARRAY_BUFFER, -1, 1, bytes);
        capi_expect_error(GL_INVALID_VALUE, "glGetBufferSubData while mapped, out of range");
        unmapped = i == 1 ? glUnmapBufferARB(GL_ARRAY_BUFFER) : glUnmapBuffer(GL_ARRAY_BUFFER);
        capi_expect_error(GL_NO_ERROR, "glUnmapBuffer");
        capi_check(unmapped == GL_TRUE, "glUnmapBuffer is GL_TRUE");
        snprintf(key, sizeof key, "unmapped 0x%x", accesses[i]);
        show_buffer(key, GL_ARRAY_BUFFER, NULL);
    }
    show_bytes("written through the map", GL_ARRAY_BUFFER, 0, 8);

    /* glBufferData unmaps. */
    p = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    glBufferData(GL_ARRAY_BUFFER, 4, "wxyz", GL_STREAM_COPY);
    capi_expect_error(GL_NO_ERROR, "glBufferData while mapped");
    show_buffer("glBufferData while mapped", GL_ARRAY_BUFFER, NULL);
    glBufferData(GL_ARRAY_BUFFER, 0, NULL, GL_STREAM_COPY);
    p = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    capi_expect_error(GL_INVALID_OPERATION, "map a buffer emptied by glBufferData");

    /* Deleting a mapped buffer unmaps it. */
    glBufferData(GL_ARRAY_BUFFER, 4, "wxyz", GL_STREAM_COPY);
    p = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
    glDeleteBuffers(1, &name);
    capi_expect_error(GL_NO_ERROR, "delete mapped");
    glBindBuffer(GL_ARRAY_BUFFER, name);
    show_buffer("name of a deleted mapped buffer, bound again", GL_ARRAY_BUFFER, NULL);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDeleteBuffers(1, &name);
}

/* Array pointers with a buffer bound are offsets into it. */
static void arrays_in_buffers(void)
{
    GLuint names[3];
    glGenBuffers(3, names);
    /* Element i: position (i, 10 i) as floats, then color (i, 2i, 3i, 255) as ubytes. */
    unsigned char data[4 + 8 * 12];
    memset(data, 0xff, 4);
    for (int i = 0; i < 8; i++) {
        GLfloat position[2] = {(GLfloat)i, 10.0f * i};
        memcpy(data + 4 + 12 * i, position, 8);
        unsigned char color[4] = {(unsigned char)i, (unsigned char)(2 * i), (unsigned char)(3 * i), 255};
        memcpy(data + 4 + 12 * i + 8, color, 4);
    }
    glBindBuffer(GL_ARRAY_BUFFER, names[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
    glVertexPointer(2, GL_FLOAT, 12, (const GLvoid *)(uintptr_t)4);
    glColorPointer(4, GL_UNSIGNED_BYTE, 12, (const GLvoid *)(uintptr_t)12);
    glBindBuffer(GL_ARRAY_BUFFER, names[1]);
    glNormalPointer(GL_FLOAT, 0, (const GLvoid *)(uintptr_t)0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    GLvoid *pointer;
    glGetPointerv(GL_COLOR_ARRAY_POINTER, &pointer);
    capi_value("color pointer is an offset", "%td", (const char *)pointer - (const char *)0);
    capi_value("array bindings", "vertex %d color %d normal %d texture %d array %d",
               get_int(GL_VERTEX_ARRAY_BUFFER_BINDING), get_int(GL_COLOR_ARRAY_BUFFER_BINDING),
               get_int(GL_NORMAL_ARRAY_BUFFER_BINDING), get_int(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING),
               get_int(GL_ARRAY_BUFFER_BINDING));

    /* glArrayElement reads the buffer. */
    glEnableClientState(GL_COLOR_ARRAY);
    glArrayElement(5);
    GLfloat c[4];
    glGetFloatv(GL_CURRENT_COLOR, c);
    capi_value("color from buffer element 5", "%a %a %a %a", c[0], c[1], c[2], c[3]);

    /* Draws with indices in a buffer. */
    const GLushort indices[6] = {0, 1, 2, 7, 6, 5};
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, names[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, (const GLvoid *)(uintptr_t)6);
    glDrawRangeElements(GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_SHORT, (const GLvoid *)0);
    glDrawArrays(GL_TRIANGLE_STRIP, 2, 4);
    const GLsizei counts[2] = {3, 3};
    const GLvoid *offsets[2] = {(const GLvoid *)0, (const GLvoid *)(uintptr_t)6};
    glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_SHORT, offsets, 2);
    capi_expect_error(GL_NO_ERROR, "draws from buffers");
    glGetFloatv(GL_CURRENT_COLOR, c);
    capi_value("current color after draws from buffers", "%a %a %a %a", c[0], c[1], c[2], c[3]);

    /* Drawing from a mapped buffer. */
    glBindBuffer(GL_ARRAY_BUFFER, names[0]);
    GLvoid *p = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    capi_check(p != NULL, "mapped");
    glDrawArrays(GL_TRIANGLES, 0, 3);
    GLenum error = glGetError();
    capi_check(error == (tessera ? GL_INVALID_OPERATION : GL_NO_ERROR), "draw from a mapped buffer: 0x%x", error);
    glUnmapBuffer(GL_ARRAY_BUFFER);
    p = glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_ONLY);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, (const GLvoid *)0);
    error = glGetError();
    capi_check(error == (tessera ? GL_INVALID_OPERATION : GL_NO_ERROR), "draw with mapped indices: 0x%x", error);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    capi_expect_error(GL_NO_ERROR, "glDrawArrays does not read the mapped element buffer");
    glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER);

    /* The client attribute stack holds the bindings. */
    glBindBuffer(GL_ARRAY_BUFFER, names[1]);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glBindBuffer(GL_ARRAY_BUFFER, names[0]);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glColorPointer(3, GL_FLOAT, 0, (const GLvoid *)(uintptr_t)8);
    glPopClientAttrib();
    capi_value("after pop", "array %d element %d color %d color size %d", get_int(GL_ARRAY_BUFFER_BINDING),
               get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING), get_int(GL_COLOR_ARRAY_BUFFER_BINDING),
               get_int(GL_COLOR_ARRAY_SIZE));
    /* A bound buffer deleted while pushed is bound again by name (a new, empty buffer). */
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDeleteBuffers(1, &names[1]);
    capi_value("deleted while pushed", "%d binding %d normal %d", glIsBuffer(names[1]),
               get_int(GL_ARRAY_BUFFER_BINDING), get_int(GL_NORMAL_ARRAY_BUFFER_BINDING));
    glPopClientAttrib();
    capi_value("after pop of a deleted binding", "%d binding %d", glIsBuffer(names[1]),
               get_int(GL_ARRAY_BUFFER_BINDING));
    show_buffer("the recreated buffer", GL_ARRAY_BUFFER, NULL);

    /* Deleting a buffer resets every binding to it; the pointers stay offsets. */
    glBindBuffer(GL_ARRAY_BUFFER, names[0]);
    glClientActiveTexture(GL_TEXTURE1);
    glTexCoordPointer(2, GL_FLOAT, 12, (const GLvoid *)(uintptr_t)4);
    glClientActiveTexture(GL_TEXTURE0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, names[0]);
    glDeleteBuffers(1, &names[0]);
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pointer);
    glClientActiveTexture(GL_TEXTURE1);
    capi_value("after deleting the array buffer", "array %d element %d vertex %d color %d texture1 %d pointer %td",
               get_int(GL_ARRAY_BUFFER_BINDING), get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING),
               get_int(GL_VERTEX_ARRAY_BUFFER_BINDING), get_int(GL_COLOR_ARRAY_BUFFER_BINDING),
               get_int(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING), (const char *)pointer - (const char *)0);
    glClientActiveTexture(GL_TEXTURE0);
    /* Drawing from arrays whose buffer is gone is undefined (Mesa reads the offset as a client
     * address); tessera draws nothing. */
    if (tessera) {
        glDrawArrays(GL_TRIANGLES, 0, 3);
        capi_check(glGetError() == GL_NO_ERROR, "draw from deleted buffers is no error");
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glDeleteBuffers(3, names);
    capi_expect_error(GL_NO_ERROR, "arrays in buffers");
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 16, 16, &buffer);
    tessera = capi_is_tessera();

    names_and_bindings();
    data_and_sub_data();
    mapping();
    arrays_in_buffers();
    capi_expect_error(GL_NO_ERROR, "end");

    /* Mesa 22 crashes destroying a current context with unflushed draws. */
    glFinish();
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
