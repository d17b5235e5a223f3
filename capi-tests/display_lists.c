/* Display lists: GL_COMPILE draws nothing until glCallList, GL_COMPILE_AND_EXECUTE draws at
 * once; commands GL 2.1 section 5.4 executes immediately (pixel store, client state,
 * glGenLists, glIsList, glGet*) take effect during compilation; errors of compiled commands
 * are raised when the list runs; nesting stops at GL_MAX_LIST_NESTING; glCallLists with every
 * type and the list base; vertex arrays and the unpack modes are read at compile time;
 * lists are shared with a context created with a share context. */
#include "common.h"

#define W 48
#define H 48

static GLfloat modelview_x(void)
{
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    return m[12];
}

static void quad(float x, float y, float s)
{
    glBegin(GL_QUADS);
    glVertex2f(x, y);
    glVertex2f(x + s, y);
    glVertex2f(x + s, y + s);
    glVertex2f(x, y + s);
    glEnd();
}

static int pixel_is(int x, int y, const GLubyte *rgba)
{
    GLubyte p[4];
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return memcmp(p, rgba, 4) == 0;
}

int main(void)
{
    void *buffer1;
    OSMesaContext ctx = capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, &buffer1);
    static const GLubyte black[4] = {0, 0, 0, 0}, red[4] = {255, 0, 0, 255}, green[4] = {0, 255, 0, 255};
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT);

    capi_value_query("initial", "max_list_nesting", GL_MAX_LIST_NESTING, 1);
    capi_value_query("initial", "list_mode", GL_LIST_MODE, 1);

    /* GL_COMPILE: nothing happens until the list is called. */
    GLuint base = glGenLists(4);
    capi_value("gen_lists", "%u", base);
    capi_check(glIsList(base) && glIsList(base + 3) && !glIsList(base + 4), "glGenLists reserves names");
    glNewList(base, GL_COMPILE);
    capi_value_query("compiling", "list_index", GL_LIST_INDEX, 1);
    capi_value_query("compiling", "list_mode", GL_LIST_MODE, 1);
    glColor3f(1, 0, 0);
    quad(2, 2, 8);
    glTranslatef(5, 0, 0);
    glEndList();
    capi_check(pixel_is(4, 4, black), "GL_COMPILE draws nothing");
    capi_check(modelview_x() == 0, "GL_COMPILE changes no state");
    GLfloat color[4];
    glGetFloatv(GL_CURRENT_COLOR, color);
    capi_check(color[1] == 1, "the current color is untouched by compilation");
    glCallList(base);
    capi_check(pixel_is(4, 4, red), "glCallList draws");
    capi_value("after_call.modelview_x", "%g", modelview_x());
    glLoadIdentity();

    /* GL_COMPILE_AND_EXECUTE draws while compiling. */
    glNewList(base + 1, GL_COMPILE_AND_EXECUTE);
    capi_value_query("compile_and_execute", "list_mode", GL_LIST_MODE, 1);
    glColor3f(0, 1, 0);
    quad(12, 2, 8);
    glEndList();
    capi_check(pixel_is(14, 4, green), "GL_COMPILE_AND_EXECUTE draws at once");

    /* Immediate commands and deferred errors. */
    glNewList(base + 2, GL_COMPILE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2); /* executed now */
    glEnableClientState(GL_VERTEX_ARRAY);  /* executed now */
    GLuint inner = glGenLists(1);          /* executed now */
    glEnable(0x1234);                      /* compiled: the error comes at glCallList */
    glNewList(7777, GL_COMPILE);           /* INVALID_OPERATION now */
    capi_expect_error(GL_INVALID_OPERATION, "glNewList inside glNewList");
    glLineWidth(-1.0f); /* compiled */
    glEndList();
    capi_expect_error(GL_NO_ERROR, "compiling records no error");
    GLint alignment;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    capi_value("immediate.alignment", "%d", alignment);
    capi_check(glIsEnabled(GL_VERTEX_ARRAY), "glEnableClientState executed during compilation");
    glDisableClientState(GL_VERTEX_ARRAY);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    capi_check(inner == base + 4, "glGenLists inside glNewList: %u", inner);
    glCallList(base + 2);
    capi_expect_error(GL_INVALID_ENUM, "compiled glEnable's error at execution");
    capi_expect_error(GL_NO_ERROR, "only the first error is kept");
    glEndList();
    capi_expect_error(GL_INVALID_OPERATION, "glEndList without glNewList");
    glNewList(0, GL_COMPILE);
    capi_expect_error(GL_INVALID_VALUE, "glNewList(0)");
    glNewList(1, GL_RENDER);
    capi_expect_error(GL_INVALID_ENUM, "glNewList bad mode");

    /* Nesting: a list calling itself runs GL_MAX_LIST_NESTING times. */
    GLuint recursive = glGenLists(1);
    glNewList(recursive, GL_COMPILE);
    glTranslatef(1, 0, 0);
    glCallList(recursive);
    glEndList();
    glLoadIdentity();
    glCallList(recursive);
    capi_value("nesting.translate", "%g", modelview_x());
    /* A list calling a list that is redefined later uses the definition at execution. */
    GLuint outer = glGenLists(2);
    glNewList(outer, GL_COMPILE);
    glCallList(outer + 1);
    glCallList(outer + 1);
    glEndList();
    glNewList(outer + 1, GL_COMPILE);
    glTranslatef(3, 0, 0);
    glEndList();
    glLoadIdentity();
    glCallList(outer);
    capi_value("nested.translate", "%g", modelview_x());

    /* glCallLists with every type; list k translates by 2^k. */
    for (int k = 0; k < 12; k++) {
        glNewList(1000 + k, GL_COMPILE);
        glTranslatef((float)(1 << k), 0, 0);
        glEndList();
    }
    glListBase(1000);
    {
        GLbyte b[] = {0, 1};
        GLubyte ub[] = {2, 3};
        GLshort s[] = {4, 5};
        GLushort us[] = {6};
        GLint i[] = {7};
        GLuint ui[] = {8};
        GLfloat f[] = {9.7f};
        GLubyte two[] = {0, 10, 0, 11};
        GLubyte three[] = {0, 0, 0};
        GLubyte four[] = {0, 0, 0, 1};
        struct { GLenum type; int n; const void *data; } calls[] = {
            {GL_BYTE, 2, b}, {GL_UNSIGNED_BYTE, 2, ub}, {GL_SHORT, 2, s}, {GL_UNSIGNED_SHORT, 1, us},
            {GL_INT, 1, i}, {GL_UNSIGNED_INT, 1, ui}, {GL_FLOAT, 1, f}, {GL_2_BYTES, 2, two},
            {GL_3_BYTES, 1, three}, {GL_4_BYTES, 1, four},
        };
        for (unsigned c = 0; c < sizeof calls / sizeof calls[0]; c++) {
            char key[64];
            glLoadIdentity();
            glCallLists(calls[c].n, calls[c].type, calls[c].data);
            snprintf(key, sizeof key, "call_lists.%04x", calls[c].type);
            capi_value(key, "%g", modelview_x());
        }
        glCallLists(1, GL_DOUBLE, b);
        capi_expect_error(GL_INVALID_ENUM, "glCallLists GL_DOUBLE");
        glCallLists(-1, GL_BYTE, b);
        capi_expect_error(GL_INVALID_VALUE, "glCallLists n < 0");
        /* Compiled glCallLists: names copied now, list base applied at execution. */
        GLuint calls_list = glGenLists(1);
        GLubyte names[] = {1, 2};
        glNewList(calls_list, GL_COMPILE);
        glCallLists(2, GL_UNSIGNED_BYTE, names);
        glEndList();
        names[0] = 5;
        glListBase(1001);
        glLoadIdentity();
        glCallList(calls_list);
        capi_value("compiled_call_lists", "%g", modelview_x());
        /* GL_LIST_BIT */
        glPushAttrib(GL_LIST_BIT);
        glListBase(5);
        capi_value_query("pushed", "list_base", GL_LIST_BASE, 1);
        glPopAttrib();
        capi_value_query("popped", "list_base", GL_LIST_BASE, 1);
        glListBase(0);
    }
    glLoadIdentity();

    /* Vertex arrays are dereferenced at compile time; the other attributes are current. */
    {
        GLfloat verts[] = {24, 2, 32, 2, 32, 10, 24, 10};
        GLubyte colors[] = {0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255};
        GLuint arrays_list = glGenLists(1);
        glVertexPointer(2, GL_FLOAT, 0, verts);
        glEnableClientState(GL_VERTEX_ARRAY);
        glNewList(arrays_list, GL_COMPILE);
        glDrawArrays(GL_QUADS, 0, 4);
        glTranslatef(0, 10, 0);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors); /* executed now */
        glEnableClientState(GL_COLOR_ARRAY);
        glDrawArrays(GL_QUADS, 0, 4);
        glDisableClientState(GL_COLOR_ARRAY);
        glTranslatef(0, 10, 0);
        glBegin(GL_QUADS);
        for (int v = 0; v < 4; v++)
            glArrayElement(v);
        glEnd();
        glDrawArrays(0x7777, 0, 4);
        glEndList();
        for (int v = 0; v < 8; v++)
            verts[v] = 0;
        glDisableClientState(GL_VERTEX_ARRAY);
        glColor3f(1, 1, 0);
        glCallList(arrays_list);
        capi_expect_error(GL_INVALID_ENUM, "compiled glDrawArrays with a bad mode");
        glLoadIdentity();
    }

    /* The polygon stipple is unpacked at compile time with the unpack modes then. */
    {
        GLubyte stipple[4 * 32 * 2];
        for (unsigned b = 0; b < sizeof stipple; b++)
            stipple[b] = (GLubyte)(b * 37 + 11);
        GLuint stipple_list = glGenLists(1);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
        glNewList(stipple_list, GL_COMPILE);
        glPolygonStipple(stipple);
        glEndList();
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glCallList(stipple_list);
        GLubyte back[128];
        glGetPolygonStipple(back);
        capi_check(memcmp(back, stipple + 12, 128) == 0, "stipple unpacked with the compile-time modes");
        glEnable(GL_POLYGON_STIPPLE);
        glColor3f(1, 0, 1);
        quad(34, 2, 12);
        glDisable(GL_POLYGON_STIPPLE);
    }

    /* Deleting. */
    glDeleteLists(base + 3, 1);
    capi_check(!glIsList(base + 3) && glIsList(base + 2), "glDeleteLists removes exactly its range");
    glDeleteLists(base, -1);
    capi_expect_error(GL_INVALID_VALUE, "glDeleteLists range < 0");
    capi_save_framebuffer("lists", W, H);

    /* Sharing. */
    OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, ctx);
    OSMesaContext alone = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    static GLubyte buffer2[W * H * 4];
    capi_check(shared && alone, "contexts created");
    OSMesaMakeCurrent(shared, buffer2, GL_UNSIGNED_BYTE, W, H);
    capi_check(glIsList(base + 1), "a shared context sees the lists");
    GLuint from_shared = glGenLists(1);
    capi_value("shared.gen_lists", "%u", from_shared);
    glNewList(from_shared, GL_COMPILE);
    glTranslatef(42, 0, 0);
    glEndList();
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(base);
    capi_save_framebuffer("shared", W, H);
    OSMesaMakeCurrent(alone, buffer2, GL_UNSIGNED_BYTE, W, H);
    capi_check(!glIsList(base + 1), "an unshared context does not");
    OSMesaMakeCurrent(ctx, buffer1, GL_UNSIGNED_BYTE, W, H);
    capi_check(glIsList(from_shared), "a list made in the shared context is seen by the first");
    OSMesaDestroyContext(shared);
    OSMesaDestroyContext(alone);
    return capi_finish();
}
