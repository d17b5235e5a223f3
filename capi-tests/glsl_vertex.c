/* GLSL vertex shaders in draws, with fixed-function fragment processing (no fragment
 * shader): the position from a uniform matrix; gl_FrontColor from a generic attribute array
 * (float, and normalized unsigned bytes through glDrawElements), from glVertexAttrib in
 * immediate mode and in a display list; gl_TexCoord[0] feeding fixed-function texturing;
 * two-sided colour with GL_VERTEX_PROGRAM_TWO_SIDE; gl_PointSize with
 * GL_VERTEX_PROGRAM_POINT_SIZE (and glPointSize without it); generic attribute 0 aliasing
 * the position (an array and glVertexAttrib); a user clip plane testing gl_ClipVertex;
 * built-in inputs (gl_Color, gl_MultiTexCoord0, gl_Normal, gl_SecondaryColor, gl_FogCoord);
 * and a vertex shader's outputs clamped (GL_CLAMP_VERTEX_COLOR's default). */
#include "common.h"

#define W 64
#define H 64

/* glOrtho(0, W, 0, H, -1, 1), column-major. */
static const GLfloat ortho[16] = {2.0f / W, 0, 0, 0, 0, 2.0f / H, 0, 0, 0, 0, -1, 0, -1, -1, 0, 1};

/* A program of the vertex shader `source` alone, with "color" at location 1 and "size" at
 * 2 (when the shader has them), in use, its matrix uniform "mvp" set to `ortho`. */
static GLuint program(const char *source)
{
    GLuint p = capi_program_with("vertex", source, NULL);
    glBindAttribLocation(p, 1, "color");
    glBindAttribLocation(p, 2, "size");
    capi_link_program("vertex", p);
    glUseProgram(p);
    GLint mvp = glGetUniformLocation(p, "mvp");
    if (mvp >= 0)
        glUniformMatrix4fv(mvp, 1, GL_FALSE, ortho);
    return p;
}

static void grab(const char *name)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    capi_save_framebuffer(name, W, H);
    capi_expect_error(GL_NO_ERROR, name);
    glClear(GL_COLOR_BUFFER_BIT);
}

static const char *generic_color_vs = "uniform mat4 mvp;\n"
                                      "attribute vec4 color;\n"
                                      "void main() {\n"
                                      "    gl_Position = mvp * gl_Vertex;\n"
                                      "    gl_FrontColor = color;\n"
                                      "}\n";

static void generic_arrays(void)
{
    GLuint p = program(generic_color_vs);
    static const GLfloat pos[] = {4, 4, 60, 8, 30, 60, 4, 40, 20, 60, 6, 60};
    static const GLfloat colors[] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 0, 1, 1, 1, 1, 1, 0, 1, 1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0, colors);
    glEnableVertexAttribArray(1);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    grab("generic_float_array");

    /* Normalized unsigned bytes of 3 components (alpha 1), through glDrawElements. */
    static const GLubyte bytes[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 0, 128, 64, 32, 0, 0, 0};
    static const GLushort indices[] = {0, 1, 2, 2, 3, 4, 0, 2, 4};
    static const GLfloat quad[] = {4, 4, 60, 4, 60, 60, 32, 62, 4, 60};
    glVertexPointer(2, GL_FLOAT, 0, quad);
    glVertexAttribPointer(1, 3, GL_UNSIGNED_BYTE, GL_TRUE, 6, bytes);
    glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_SHORT, indices);
    grab("generic_ubyte_normalized_elements");

    /* Unnormalized shorts divided in the shader. */
    static const GLshort shorts[] = {200, 0, 0, 0, 200, 100, 50, 50, 200, 200, 200, 200, 0, 100, 0};
    glVertexAttribPointer(1, 3, GL_SHORT, GL_FALSE, 0, shorts);
    glUseProgram(0);
    glDeleteProgram(p);
    p = program("uniform mat4 mvp;\n"
                "attribute vec3 color;\n"
                "void main() {\n"
                "    gl_Position = mvp * gl_Vertex;\n"
                "    gl_FrontColor = vec4(color / 200.0, 1.0);\n"
                "}\n");
    glDrawRangeElements(GL_TRIANGLES, 0, 4, 9, GL_UNSIGNED_SHORT, indices);
    grab("generic_short_range_elements");

    glDisableVertexAttribArray(1);
    /* The current value when the array is disabled. */
    glVertexAttrib3f(1, 100.0f, 50.0f, 150.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    grab("generic_current_value");
    glDisableClientState(GL_VERTEX_ARRAY);
    glUseProgram(0);
    glDeleteProgram(p);
}

static void immediate(void)
{
    GLuint p = program(generic_color_vs);
    glVertexAttrib4f(1, 0.2f, 0.4f, 0.6f, 1.0f);
    glBegin(GL_TRIANGLES);
    glVertex2f(4, 4); /* made before any glVertexAttrib inside glBegin/glEnd */
    glVertexAttrib4f(1, 1, 0, 0, 1);
    glVertex2f(60, 4);
    glVertexAttrib4f(1, 0, 1, 0, 1);
    glVertexAttrib1f(1, 0.5f); /* (0.5, 0, 0, 1): the last call before glVertex wins */
    glVertex2f(32, 60);
    glVertexAttrib4f(1, 0, 0, 1, 1);
    glVertex2f(2, 62);
    glVertex2f(20, 40);
    glVertexAttrib4f(1, 1, 1, 0, 1);
    glVertexAttrib2f(0, 8, 60); /* attribute 0 provokes a vertex */
    glEnd();
    grab("immediate_vertex_attrib");

    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLE_STRIP);
    glVertexAttrib4f(1, 1, 0, 1, 1);
    glVertex2f(6, 6);
    glVertexAttrib4f(1, 0, 1, 1, 1);
    glVertex2f(58, 10);
    glVertexAttrib4f(1, 1, 1, 1, 1);
    glVertexAttrib2f(0, 10, 50);
    glVertexAttrib4f(1, 0.25f, 0.5f, 0.75f, 1);
    glVertexAttrib4f(0, 50, 58, 0, 1);
    glEnd();
    glEndList();
    glVertexAttrib4f(1, 0, 0, 0, 1);
    glCallList(list);
    grab("display_list_vertex_attrib");
    glDeleteLists(list, 1);
    glUseProgram(0);
    glDeleteProgram(p);
}

/* Generic attribute 0 aliases the position: an array of it, read as gl_Vertex and as a
 * user attribute bound to location 0. */
static void attribute_zero(void)
{
    GLuint p = program(generic_color_vs);
    static const GLfloat pos[] = {10, 2, 62, 30, 2, 50};
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos);
    glEnableVertexAttribArray(0);
    glVertexAttrib4f(1, 0.9f, 0.6f, 0.3f, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glUseProgram(0);
    glDeleteProgram(p);

    p = capi_program_with("attribute zero aliasing",
                          "uniform mat4 mvp;\n"
                          "attribute vec2 where;\n"
                          "void main() {\n"
                          "    gl_Position = mvp * vec4(where.yx, 0.0, 1.0);\n"
                          "    gl_FrontColor = vec4(0.0, 0.5, 1.0, 1.0);\n"
                          "}\n",
                          NULL);
    glBindAttribLocation(p, 0, "where");
    capi_link_program("attribute zero aliasing", p);
    glUseProgram(p);
    glUniformMatrix4fv(glGetUniformLocation(p, "mvp"), 1, GL_FALSE, ortho);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisableVertexAttribArray(0);
    grab("attribute_zero_aliasing");
    glUseProgram(0);
    glDeleteProgram(p);
}

static void texturing(void)
{
    GLubyte texels[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        int on = ((i % 8) ^ (i / 8)) & 1;
        texels[4 * i + 0] = on ? 255 : 20;
        texels[4 * i + 1] = on ? 200 : 80;
        texels[4 * i + 2] = (GLubyte)(i * 4);
        texels[4 * i + 3] = 255;
    }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    GLuint p = program("uniform mat4 mvp;\n"
                       "uniform vec2 scale;\n"
                       "void main() {\n"
                       "    gl_Position = mvp * gl_Vertex;\n"
                       "    gl_TexCoord[0] = vec4(gl_MultiTexCoord0.xy * scale, 0.0, 1.0);\n"
                       "    gl_FrontColor = gl_Color;\n"
                       "}\n");
    /* 14 x 10 texels over 56 x 56 pixels: no texel edge on a pixel centre. */
    glUniform2f(glGetUniformLocation(p, "scale"), 1.75f, 1.25f);
    glBegin(GL_QUADS);
    glColor3f(1, 1, 1);
    glTexCoord2f(0, 0);
    glVertex2f(4, 4);
    glTexCoord2f(1, 0);
    glVertex2f(60, 4);
    glColor3f(1, 0.5f, 1);
    glTexCoord2f(1, 1);
    glVertex2f(60, 60);
    glTexCoord2f(0, 1);
    glVertex2f(4, 60);
    glEnd();
    grab("tex_coord_fixed_function_texturing");
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &tex);
    glUseProgram(0);
    glDeleteProgram(p);
}

static void two_sided(void)
{
    GLuint p = program("uniform mat4 mvp;\n"
                       "void main() {\n"
                       "    gl_Position = mvp * gl_Vertex;\n"
                       "    gl_FrontColor = vec4(1.0, 0.25, 0.0, 1.0);\n"
                       "    gl_BackColor = vec4(0.0, 0.5, 1.0, 1.0);\n"
                       "    gl_FrontSecondaryColor = vec4(0.0);\n"
                       "    gl_BackSecondaryColor = vec4(0.0);\n"
                       "}\n");
    for (int on = 0; on < 2; on++) {
        if (on)
            glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
        glBegin(GL_TRIANGLES);
        /* Counter-clockwise (front) on the left, clockwise (back) on the right. */
        glVertex2f(2, 2);
        glVertex2f(30, 2);
        glVertex2f(16, 60);
        glVertex2f(34, 2);
        glVertex2f(48, 60);
        glVertex2f(62, 2);
        glEnd();
        grab(on ? "two_side_on" : "two_side_off");
    }
    glDisable(GL_VERTEX_PROGRAM_TWO_SIDE);
    glUseProgram(0);
    glDeleteProgram(p);
}

static void point_sizes(void)
{
    GLuint p = program("uniform mat4 mvp;\n"
                       "attribute float size;\n"
                       "void main() {\n"
                       "    gl_Position = mvp * gl_Vertex;\n"
                       "    gl_FrontColor = vec4(1.0, size / 10.0, 0.0, 1.0);\n"
                       "    gl_PointSize = size;\n"
                       "}\n");
    glPointSize(3.0f);
    for (int on = 0; on < 2; on++) {
        if (on)
            glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
        glBegin(GL_POINTS);
        for (int i = 0; i < 6; i++) {
            glVertexAttrib1f(2, (GLfloat)(i * 2 + 1));
            glVertex2f(6.5f + i * 10.0f, 12.5f + i * 8.0f);
        }
        glEnd();
        grab(on ? "point_size_program" : "point_size_fixed");
    }
    glDisable(GL_VERTEX_PROGRAM_POINT_SIZE);
    glPointSize(1.0f);
    glUseProgram(0);
    glDeleteProgram(p);
}

static void clip_vertex(void)
{
    GLuint p = program("uniform mat4 mvp;\n"
                       "void main() {\n"
                       "    gl_Position = mvp * gl_Vertex;\n"
                       "    gl_ClipVertex = gl_Vertex;\n"
                       "    gl_FrontColor = vec4(0.5, 1.0, 0.25, 1.0);\n"
                       "}\n");
    /* x + y <= 64, in the clip vertex's coordinates (the identity modelview's eye space). */
    static const GLdouble plane[4] = {-1, -1, 0, 64};
    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    glBegin(GL_QUADS);
    glVertex2f(4, 4);
    glVertex2f(60, 4);
    glVertex2f(60, 60);
    glVertex2f(4, 60);
    glEnd();
    glDisable(GL_CLIP_PLANE0);
    grab("clip_vertex_plane");
    glUseProgram(0);
    glDeleteProgram(p);
}

static void builtin_inputs(void)
{
    GLuint p = program("uniform mat4 mvp;\n"
                       "uniform float bias;\n"
                       "void main() {\n"
                       "    gl_Position = mvp * gl_Vertex;\n"
                       "    gl_FrontColor = vec4(gl_Color.rgb * 0.5 + gl_SecondaryColor.rgb * 0.5,\n"
                       "                         gl_FogCoord + bias);\n"
                       "    gl_FrontColor.r += gl_Normal.z * 0.25 + gl_MultiTexCoord1.x;\n"
                       "    gl_FrontColor.g += gl_MultiTexCoord5.w * 0.125;\n"
                       "}\n");
    glUniform1f(glGetUniformLocation(p, "bias"), 0.5f);
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.4f, 0.6f);
    glSecondaryColor3f(0.4f, 0.2f, 0.0f);
    glNormal3f(0, 0, 1);
    glFogCoordf(0.25f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.125f, 0);
    glVertex2f(4, 4);
    glColor3f(1.0f, 0.0f, 0.6f);
    glNormal3f(0, 0, 2);
    glVertex2f(60, 4);
    glSecondaryColor3f(1.0f, 1.0f, 1.0f);
    glFogCoordf(0.5f);
    glVertex2f(32, 60);
    glEnd();
    grab("builtin_inputs_and_clamp");
    glUseProgram(0);
    glDeleteProgram(p);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    generic_arrays();
    immediate();
    attribute_zero();
    texturing();
    two_sided();
    point_sizes();
    clip_vertex();
    builtin_inputs();
    return capi_finish();
}
