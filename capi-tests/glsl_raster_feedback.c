/* glRasterPos, feedback and selection with a GLSL vertex shader in use (GL 2.1 sections
 * 2.13, 5.2, 5.3): the raster position, colour and texture coordinates come from the
 * shader's outputs (those it does not write keep the current values, as in Mesa 22), user
 * clip planes test gl_Position, the fourth raster coordinate is 1/w_c and the raster
 * distance is left as it was (Mesa's draw-module raster position); feedback vertices and
 * selection hits come from the shader's gl_Position, colours and gl_TexCoord[0]. The raster
 * texture coordinates of sets 4-7 come from gl_TexCoord[4..7] as those of sets 0-3 do. Generic
 * attributes (current values) feed the shader. No glColor between glBegin and glEnd here:
 * Mesa's feedback of a shader that does not write gl_FrontColor reports the colour current
 * before the glBegin (its current values are updated after the primitive). */
#include "common.h"

static void raster(const char *key)
{
    GLfloat v[4];
    GLint valid;
    char k[64];
    glGetIntegerv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    snprintf(k, sizeof k, "%s.valid", key);
    capi_value(k, "%d", valid);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, v);
    snprintf(k, sizeof k, "%s.position", key);
    capi_value(k, "%a %a %a %a", v[0], v[1], v[2], v[3]);
    glGetFloatv(GL_CURRENT_RASTER_COLOR, v);
    snprintf(k, sizeof k, "%s.color", key);
    capi_value(k, "%a %a %a %a", v[0], v[1], v[2], v[3]);
    glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, v);
    snprintf(k, sizeof k, "%s.secondary", key);
    capi_value(k, "%a %a %a %a", v[0], v[1], v[2], v[3]);
    for (int unit = 0; unit < 2; unit++) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, v);
        snprintf(k, sizeof k, "%s.tex%d", key, unit);
        capi_value(k, "%a %a %a %a", v[0], v[1], v[2], v[3]);
    }
    glActiveTexture(GL_TEXTURE0);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, v);
    snprintf(k, sizeof k, "%s.distance", key);
    capi_value(k, "%a", v[0]);
    capi_expect_error(GL_NO_ERROR, key);
}

static GLuint program(const char *vs)
{
    GLuint p = capi_program_with("raster feedback", vs, NULL);
    glBindAttribLocation(p, 3, "extra");
    capi_link_program("raster feedback", p);
    return p;
}

int main(void)
{
    unsigned char *buffer;
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, 64, 64, (void **)&buffer);
    GLuint p = program("attribute vec4 extra;\n"
                       "void main() {\n"
                       "  gl_Position = vec4(gl_Vertex.xy * 0.5, gl_Vertex.z * 0.25, 2.0) + extra;\n"
                       "  gl_FrontColor = vec4(1.5, -0.5, 0.25, 0.75) * gl_Color.a;\n"
                       "  gl_TexCoord[0] = vec4(0.125, 0.25, 0.375, 0.5) + gl_MultiTexCoord0 * 0.5;\n"
                       "}\n");
    GLuint q = program("attribute vec4 extra;\n"
                       "void main() {\n"
                       "  gl_Position = ftransform() + extra;\n"
                       "  gl_FrontSecondaryColor = vec4(0.5, 0.25, 1.0, 1.0);\n"
                       "  gl_TexCoord[1] = gl_Vertex.yxzw;\n"
                       "}\n");
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glSecondaryColor3f(0.625f, 0.75f, 0.875f);
    glMultiTexCoord4f(GL_TEXTURE1, 5, 6, 7, 8);
    glTexCoord4f(1, 2, 3, 4);
    glVertexAttrib4f(3, 0.5f, 0, 0, 0);
    glRasterPos4f(1, 1, 1, 1);
    raster("fixed");

    glUseProgram(p);
    glRasterPos4f(1, 1, 1, 1);
    raster("shader");
    glVertexAttrib4f(3, 0, 0.25f, 0, 0);
    glRasterPos3f(-0.5f, 0.5f, -1);
    raster("shader_attribute");
    glRasterPos3f(5, 0, 0);
    raster("shader_outside");
    glRasterPos3f(0.5f, 0.5f, 0);
    GLdouble plane[4] = {-1, 0, 0, 0};
    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    glRasterPos3f(0.5f, 0.5f, 0);
    raster("shader_clip_plane");
    glDisable(GL_CLIP_PLANE0);
    glRasterPos3f(-0.5f, -0.5f, 0);
    /* A bitmap at the shader's raster position, in its raster colour. */
    static const GLubyte bits[8] = {0xff, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xff};
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glBitmap(8, 8, 0, 0, 0, 0, bits);
    capi_save_framebuffer("bitmap", 64, 64);

    glUseProgram(q);
    glMatrixMode(GL_PROJECTION);
    glOrtho(-2, 2, -2, 2, -2, 2);
    glMatrixMode(GL_MODELVIEW);
    glVertexAttrib4f(3, 0, 0, 0, 0);
    glRasterPos3f(0.5f, -1, 0.5f);
    raster("ftransform");

    /* Feedback through each program. */
    GLfloat fb[256];
    for (int pass = 0; pass < 2; pass++) {
        glUseProgram(pass ? q : p);
        glFeedbackBuffer(256, GL_4D_COLOR_TEXTURE, fb);
        glRenderMode(GL_FEEDBACK);
        glBegin(GL_POINTS);
        glVertex3f(0.5f, 0.5f, 0.5f);
        glEnd();
        glBegin(GL_LINES);
        glVertex2f(0, 0);
        glVertex2f(1.5f, 0.5f);
        glEnd();
        glBegin(GL_TRIANGLES);
        glVertex3f(-1, -1, 0);
        glVertex3f(3, -1, 0);
        glVertex3f(0, 1, 0);
        glEnd();
        glRasterPos2f(0.25f, 0.25f);
        glBitmap(0, 0, 0, 0, 0, 0, NULL);
        int n = glRenderMode(GL_RENDER);
        char key[32];
        snprintf(key, sizeof key, "feedback%d.count", pass);
        capi_value(key, "%d", n);
        for (int i = 0; i < n && i < 256; i++) {
            snprintf(key, sizeof key, "feedback%d.%d", pass, i);
            capi_value(key, "%a", fb[i]);
        }
    }

    /* Selection: hits and depths from the shader's positions. */
    GLuint sel[64];
    glUseProgram(p);
    glSelectBuffer(64, sel);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(7);
    glBegin(GL_TRIANGLES);
    glVertex3f(0, 0, 2);
    glVertex3f(1, 0, -1);
    glVertex3f(0, 1, 0);
    glEnd();
    glLoadName(8);
    glBegin(GL_POINTS);
    glVertex3f(9, 9, 0);
    glEnd();
    glLoadName(9);
    glRasterPos3f(0.25f, 0.25f, 3);
    int hits = glRenderMode(GL_RENDER);
    capi_value("select.hits", "%d", hits);
    for (int i = 0, k = 0; i < hits && k < 60; i++) {
        capi_value("select.record", "%u %u %u %u", sel[k], sel[k + 1], sel[k + 2], sel[k + 3]);
        k += 3 + sel[k];
    }
    glUseProgram(0);

    /* The texture coordinate sets past the fixed-function units (4-7) under a shader: the
     * raster coordinates of a set are what the shader writes to its gl_TexCoord element (as
     * for sets 0-3), the current ones where it writes none. */
    GLuint r = program("attribute vec4 extra;\n"
                       "void main() {\n"
                       "  gl_Position = ftransform() + extra;\n"
                       "  gl_TexCoord[5] = vec4(0.5, -2.0, 0.25, 3.0) + gl_MultiTexCoord6 * 0.5 + gl_Vertex.x;\n"
                       "  gl_TexCoord[7] = gl_MultiTexCoord4.wzyx;\n"
                       "}\n");
    for (int set = 4; set < 8; set++)
        glMultiTexCoord4f(GL_TEXTURE0 + set, set, set + 0.5f, -set, 1.0f / set);
    glUseProgram(r);
    glRasterPos3f(0.25f, 0.5f, 0);
    for (int set = 4; set < 8; set++) {
        GLfloat v[4];
        char key[32];
        glActiveTexture(GL_TEXTURE0 + set);
        glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, v);
        snprintf(key, sizeof key, "sets.tex%d", set);
        capi_value(key, "%a %a %a %a", v[0], v[1], v[2], v[3]);
        if (set == 5)
            capi_check(v[0] == 3.75f && v[1] == 1.5f && v[2] == -2.5f && v[3] == 3.3333333f,
                       "raster coordinates of set 5: %g %g %g %g, want the shader's 3.75 1.5 -2.5 3.33333",
                       v[0], v[1], v[2], v[3]);
        if (set == 6)
            capi_check(v[0] == 6.0f && v[3] == 1.0f / 6, "raster coordinates of set 6 (not written): %g %g %g %g",
                       v[0], v[1], v[2], v[3]);
    }
    glActiveTexture(GL_TEXTURE0);
    glUseProgram(0);
    glDeleteProgram(p);
    glDeleteProgram(q);
    glDeleteProgram(r);
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
