/* glBegin/glEnd: the primitive modes, nesting errors, which commands are legal between
 * glBegin and glEnd (section 2.6.3: the vertex attribute commands, glArrayElement,
 * glEvalCoord/Point, glMaterial, glCallList(s)) and that every other command tessera has
 * records GL_INVALID_OPERATION there and changes nothing.
 *
 * Errors recorded between glBegin and glEnd are read after glEnd (glGetError is itself
 * illegal inside: it records GL_INVALID_OPERATION and returns 0).
 *
 * Deliberate differences from Mesa 22 (asserted per implementation, not printed): Mesa, at
 * GL 4.5, takes the adjacency modes (0xA-0xD) and makes GL_PATCHES GL_INVALID_OPERATION;
 * GL 2.1 has neither, so tessera records GL_INVALID_ENUM.
 */
#define GL_GLEXT_PROTOTYPES
#include "common.h"

/* Runs `call` between glBegin and glEnd, prints and checks the error read after glEnd. */
#define INSIDE(expected, call)                                                                    \
    do {                                                                                          \
        glBegin(GL_TRIANGLES);                                                                    \
        call;                                                                                     \
        glEnd();                                                                                  \
        capi_expect_error(expected, "inside " #call);                                             \
    } while (0)

static GLfloat vertices[8] = {0, 0, 1, 0, 1, 1, 0, 1};
static GLubyte indices[4] = {0, 1, 2, 3};

static void legal_commands(void)
{
    GLfloat f4[4] = {0.5f, 0.5f, 0.5f, 0.5f};
    INSIDE(GL_NO_ERROR, glVertex2f(0, 0));
    INSIDE(GL_NO_ERROR, glVertex4dv((const GLdouble[]){1, 2, 3, 4}));
    INSIDE(GL_NO_ERROR, glColor4fv(f4));
    INSIDE(GL_NO_ERROR, glColor3ub(1, 2, 3));
    INSIDE(GL_NO_ERROR, glSecondaryColor3f(0.1f, 0.2f, 0.3f));
    INSIDE(GL_NO_ERROR, glNormal3s(1, 2, 3));
    INSIDE(GL_NO_ERROR, glTexCoord2i(1, 2));
    INSIDE(GL_NO_ERROR, glMultiTexCoord3f(GL_TEXTURE1, 1, 2, 3));
    INSIDE(GL_NO_ERROR, glFogCoordd(2));
    INSIDE(GL_NO_ERROR, glEdgeFlag(GL_FALSE));
    INSIDE(GL_NO_ERROR, glIndexi(3));
    INSIDE(GL_NO_ERROR, glArrayElement(1));
    glEdgeFlag(GL_TRUE);
}

static void illegal_commands(void)
{
    GLuint name = 0;
    GLint value = 0;
    GLfloat f[4];
    GLubyte bytes[4];
    GLvoid *pointer;
    GLint firsts[1] = {0};
    GLsizei counts[1] = {3};
    const GLvoid *index_pointers[1] = {indices};

    INSIDE(GL_INVALID_OPERATION, glBegin(GL_POINTS));
    INSIDE(GL_INVALID_OPERATION, glRectf(0, 0, 1, 1));
    INSIDE(GL_INVALID_OPERATION, glRectsv((const GLshort[]){0, 0}, (const GLshort[]){1, 1}));
    INSIDE(GL_INVALID_OPERATION, glVertexPointer(3, GL_FLOAT, 0, vertices));
    INSIDE(GL_INVALID_OPERATION, glNormalPointer(GL_FLOAT, 0, vertices));
    INSIDE(GL_INVALID_OPERATION, glColorPointer(3, GL_FLOAT, 0, vertices));
    INSIDE(GL_INVALID_OPERATION, glSecondaryColorPointer(3, GL_FLOAT, 0, vertices));
    INSIDE(GL_INVALID_OPERATION, glFogCoordPointer(GL_FLOAT, 0, vertices));
    INSIDE(GL_INVALID_OPERATION, glIndexPointer(GL_FLOAT, 0, vertices));
    INSIDE(GL_INVALID_OPERATION, glEdgeFlagPointer(0, vertices));
    INSIDE(GL_INVALID_OPERATION, glTexCoordPointer(2, GL_FLOAT, 0, vertices));
    INSIDE(GL_INVALID_OPERATION, glInterleavedArrays(GL_V3F, 0, vertices));
    INSIDE(GL_INVALID_OPERATION, glEnableClientState(GL_COLOR_ARRAY));
    INSIDE(GL_INVALID_OPERATION, glDisableClientState(GL_VERTEX_ARRAY));
    INSIDE(GL_INVALID_OPERATION, glClientActiveTexture(GL_TEXTURE1));
    INSIDE(GL_INVALID_OPERATION, glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pointer));
    INSIDE(GL_INVALID_OPERATION, glDrawArrays(GL_TRIANGLES, 0, 3));
    INSIDE(GL_INVALID_OPERATION, glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, indices));
    INSIDE(GL_INVALID_OPERATION, glDrawRangeElements(GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_BYTE, indices));
    INSIDE(GL_INVALID_OPERATION, glMultiDrawArrays(GL_TRIANGLES, firsts, counts, 1));
    INSIDE(GL_INVALID_OPERATION, glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_BYTE, index_pointers, 1));
    INSIDE(GL_INVALID_OPERATION, glGenBuffers(1, &name));
    INSIDE(GL_INVALID_OPERATION, glBindBuffer(GL_ARRAY_BUFFER, 1));
    INSIDE(GL_INVALID_OPERATION, value = glIsBuffer(1));
    INSIDE(GL_INVALID_OPERATION, glBufferData(GL_ARRAY_BUFFER, 4, bytes, GL_STATIC_DRAW));
    INSIDE(GL_INVALID_OPERATION, glBufferSubData(GL_ARRAY_BUFFER, 0, 1, bytes));
    INSIDE(GL_INVALID_OPERATION, glGetBufferSubData(GL_ARRAY_BUFFER, 0, 1, bytes));
    INSIDE(GL_INVALID_OPERATION, pointer = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY));
    INSIDE(GL_INVALID_OPERATION, value = glUnmapBuffer(GL_ARRAY_BUFFER));
    INSIDE(GL_INVALID_OPERATION, glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &value));
    INSIDE(GL_INVALID_OPERATION, glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &pointer));
    INSIDE(GL_INVALID_OPERATION, glDeleteBuffers(1, &name));
    INSIDE(GL_INVALID_OPERATION, value = glIsEnabled(GL_VERTEX_ARRAY));
    INSIDE(GL_INVALID_OPERATION, glEnable(GL_VERTEX_ARRAY));
    INSIDE(GL_INVALID_OPERATION, glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT));
    INSIDE(GL_INVALID_OPERATION, glPopClientAttrib());
    INSIDE(GL_INVALID_OPERATION, glPushAttrib(GL_CURRENT_BIT));
    INSIDE(GL_INVALID_OPERATION, glGetFloatv(GL_CURRENT_COLOR, f));
    INSIDE(GL_INVALID_OPERATION, glFlush());
    INSIDE(GL_INVALID_OPERATION, glFinish());
    INSIDE(GL_INVALID_OPERATION, value = glGetError());
    capi_check(value == GL_NO_ERROR, "glGetError inside glBegin/glEnd returns 0, got 0x%x", value);
}

int main(void)
{
    void *buffer;
    OSMesaContext ctx = capi_make_context(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 16, 16, &buffer);
    int tessera = capi_is_tessera();

    /* Every GL 2.1 mode, with and without vertices. */
    const GLenum modes[] = {GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP, GL_TRIANGLES,
                            GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
    for (unsigned i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        glBegin(modes[i]);
        glEnd();
        glBegin(modes[i]);
        for (int v = 0; v < 5; v++)
            glVertex2f(v, v % 2);
        glEnd();
        char key[64];
        snprintf(key, sizeof key, "mode 0x%x", modes[i]);
        capi_expect_error(GL_NO_ERROR, key);
    }

    /* Modes beyond GL 2.1. */
    const GLenum bad_modes[] = {0xF, 0x7fffffff, 0xffffffff};
    for (unsigned i = 0; i < sizeof bad_modes / sizeof bad_modes[0]; i++) {
        glBegin(bad_modes[i]);
        char key[64];
        snprintf(key, sizeof key, "glBegin(0x%x)", bad_modes[i]);
        capi_expect_error(GL_INVALID_ENUM, key);
        glEnd();
        capi_expect_error(GL_INVALID_OPERATION, "glEnd after a failed glBegin");
    }
    for (GLenum mode = 0xA; mode <= 0xE; mode++) {
        glBegin(mode);
        GLenum error = glGetError();
        if (tessera) {
            capi_check(error == GL_INVALID_ENUM, "glBegin(0x%x): 0x%x", mode, error);
        } else {
            capi_check(error == (mode == 0xE ? GL_INVALID_OPERATION : GL_NO_ERROR), "Mesa glBegin(0x%x): 0x%x", mode, error);
            if (error == GL_NO_ERROR)
                glEnd();
        }
        glGetError();
    }

    /* Nesting. */
    glEnd();
    capi_expect_error(GL_INVALID_OPERATION, "glEnd outside");
    glBegin(GL_LINES);
    glBegin(GL_POINTS);
    glVertex2f(0, 0);
    glVertex2f(1, 1);
    glEnd();
    capi_expect_error(GL_INVALID_OPERATION, "nested glBegin");
    glEnd();
    capi_expect_error(GL_INVALID_OPERATION, "second glEnd");

    /* glRect outside is a polygon; its integer and vector forms exist. */
    glRecti(1, 1, 5, 5);
    glRectd(1, 1, 5, 5);
    glRectfv((const GLfloat[]){1, 1}, (const GLfloat[]){5, 5});
    glRectiv((const GLint[]){1, 1}, (const GLint[]){5, 5});
    glRectdv((const GLdouble[]){1, 1}, (const GLdouble[]){5, 5});
    glRects(1, 1, 5, 5);
    capi_expect_error(GL_NO_ERROR, "glRect outside");

    glVertexPointer(2, GL_FLOAT, 0, vertices);
    glEnableClientState(GL_VERTEX_ARRAY);
    legal_commands();
    illegal_commands();

    /* The illegal calls changed nothing. */
    GLint value;
    GLvoid *pointer;
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pointer);
    capi_check(pointer == vertices, "vertex pointer unchanged");
    glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &value);
    capi_value("vertex array size", "%d", value);
    glGetIntegerv(GL_COLOR_ARRAY, &value);
    capi_value("color array enabled", "%d", value);
    glGetIntegerv(GL_VERTEX_ARRAY, &value);
    capi_value("vertex array enabled", "%d", value);
    glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &value);
    capi_value("client active texture", "0x%x", value);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &value);
    capi_value("array buffer binding", "%d", value);
    capi_value("buffer 1 exists", "%d", glIsBuffer(1));
    glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &value);
    capi_value("attrib stack depth", "%d", value);
    glGetIntegerv(GL_CLIENT_ATTRIB_STACK_DEPTH, &value);
    capi_value("client attrib stack depth", "%d", value);
    /* The attributes set inside are current. */
    GLfloat c[4];
    glGetFloatv(GL_CURRENT_INDEX, c);
    capi_value("current index", "%a", c[0]);
    glGetFloatv(GL_CURRENT_FOG_COORD, c);
    capi_value("current fog coordinate", "%a", c[0]);
    capi_expect_error(GL_NO_ERROR, "end");

    /* The first error inside glBegin/glEnd is the one kept. */
    glBegin(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, -1);
    glVertexPointer(1, GL_FLOAT, 0, vertices);
    glEnd();
    capi_expect_error(GL_INVALID_OPERATION, "first error kept");

    /* Mesa 22 crashes destroying a current context with unflushed draws. */
    glFinish();
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}
