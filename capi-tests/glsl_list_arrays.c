/* Array draws compiled into display lists with generic attribute arrays enabled (GL 2.1
 * section 5.4: client arrays are dereferenced when the command is compiled): glDrawArrays
 * and glDrawElements with glVertexAttribPointer arrays inside glNewList. The arrays are
 * then overwritten and disabled and the current generic values changed before the list
 * runs: the list draws the compiled values; attributes without an enabled array take the
 * current values at execution. The list runs under GL_COMPILE and GL_COMPILE_AND_EXECUTE,
 * with the program it was compiled under and with another one, and in feedback mode. */
#include "common.h"

#define W 64
#define H 64

static GLuint program(const char *vs, const char *fs)
{
    GLuint p = capi_program_with("list arrays", vs, fs);
    glBindAttribLocation(p, 1, "weight");
    glBindAttribLocation(p, 5, "tint");
    capi_link_program("list arrays", p);
    return p;
}

static const char *vs = "attribute vec2 weight;\n"
                        "attribute vec4 tint;\n"
                        "varying vec4 c;\n"
                        "void main() {\n"
                        "  gl_Position = gl_Vertex + vec4(weight * 0.25, 0.0, 0.0);\n"
                        "  c = tint;\n"
                        "}\n";
static const char *fs = "varying vec4 c;\nvoid main() { gl_FragColor = c; }\n";
static const char *vs2 = "attribute vec2 weight;\n"
                         "attribute vec4 tint;\n"
                         "varying vec4 c;\n"
                         "void main() {\n"
                         "  gl_Position = gl_Vertex - vec4(weight.yx * 0.25, 0.0, 0.0);\n"
                         "  c = tint.bgra;\n"
                         "}\n";

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    GLuint p = program(vs, fs), p2 = program(vs2, fs);
    static GLfloat position[] = {-0.75f, -0.75f, 0.5f, -0.75f, -0.75f, 0.5f, 0.0f, 0.25f, 0.75f, 0.0f, 0.25f, 0.75f};
    static GLfloat weight[] = {0, 0, 1, 0, 0, 1, 0.5f, 0.5f, -1, 0, 0, -1};
    static GLubyte tint[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255,
                             255, 255, 0, 255, 0, 255, 255, 255, 255, 0, 255, 255};
    static GLushort indices[] = {3, 4, 5};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, position);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 0, weight);
    glVertexAttribPointer(5, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, tint);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(5);
    glUseProgram(p);

    GLuint list = glGenLists(3);
    glNewList(list, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, indices);
    glEndList();
    /* Only the weights from an array: the tint is the current value at execution. */
    glDisableVertexAttribArray(5);
    glNewList(list + 1, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 3, 3);
    glEndList();
    glEnableVertexAttribArray(5);
    /* Compiled and executed. */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glNewList(list + 2, GL_COMPILE_AND_EXECUTE);
    glDrawArrays(GL_TRIANGLE_STRIP, 1, 5);
    glEndList();
    capi_save_framebuffer("compile_and_execute", W, H);
    capi_expect_error(GL_NO_ERROR, "compile");

    /* The arrays change and go away; the lists keep what they read. */
    for (unsigned i = 0; i < sizeof weight / sizeof weight[0]; i++)
        weight[i] = 0;
    memset(tint, 0x40, sizeof tint);
    glDisableVertexAttribArray(1);
    glDisableVertexAttribArray(5);
    glVertexAttrib4f(5, 0.25f, 0.5f, 0.75f, 1.0f);
    glVertexAttrib2f(1, 0.125f, 0.125f);

    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(list);
    capi_save_framebuffer("list", W, H);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(list + 1);
    capi_save_framebuffer("list_current_tint", W, H);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(list + 2);
    capi_save_framebuffer("list_strip", W, H);
    glUseProgram(p2);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(list);
    capi_save_framebuffer("list_other_program", W, H);

    /* Feedback: the compiled weights move the vertices. */
    GLfloat fb[128];
    glFeedbackBuffer(128, GL_2D, fb);
    glRenderMode(GL_FEEDBACK);
    glCallList(list);
    int n = glRenderMode(GL_RENDER);
    capi_value("feedback.count", "%d", n);
    for (int i = 0; i < n && i < 128; i++)
        capi_value("feedback.value", "%a", fb[i]);

    glUseProgram(0);
    glDeleteLists(list, 3);
    glDeleteProgram(p);
    glDeleteProgram(p2);
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
