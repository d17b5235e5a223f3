/* The texture coordinate sets past the fixed-function units (GL 2.0 section 2.7:
 * GL_MAX_TEXTURE_COORDS is 8, as GLSL's gl_MaxTextureCoords): sets 4..7 have current values
 * (glMultiTexCoord, in display lists too), texcoord arrays (glClientActiveTexture, the
 * GL_TEXTURE_COORD_ARRAY_* queries, glInterleavedArrays, glArrayElement), texture matrix
 * stacks and texgen state (raster texture coordinates too), saved by glPushAttrib /
 * glPushClientAttrib; a GLSL vertex
 * shader reads them as gl_MultiTexCoord4..7 and gl_TextureMatrix[4..7]. The errors past
 * set 7 are compared with Mesa; tessera's fixed-function units stop at 4 (Mesa's llvmpipe
 * has 8), so texture enables and the environment there are GL_INVALID_OPERATION on tessera
 * only (checked, not compared). */
#include "common.h"

#define W 32
#define H 32

/* glOrtho(0, W, 0, H, -1, 1), column-major. */
static const GLfloat ortho[16] = {2.0f / W, 0, 0, 0, 0, 2.0f / H, 0, 0, 0, 0, -1, 0, -1, -1, 0, 1};

static void value_floats(const char *key, GLenum pname, int count)
{
    GLfloat v[16];
    glGetFloatv(pname, v);
    char text[400] = "";
    for (int i = 0; i < count; i++)
        snprintf(text + strlen(text), sizeof text - strlen(text), " %g", v[i]);
    capi_value(key, "%s", text);
}

static void limits(void)
{
    capi_value_query("limits", "max_texture_coords", GL_MAX_TEXTURE_COORDS, 1);
    if (capi_is_tessera()) {
        GLint units = 0;
        glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
        capi_check(units == 4, "tessera's fixed-function units: %d", units);
    }
    capi_expect_error(GL_NO_ERROR, "limits");
}

/* Current values, texture matrices, texgen and array state of sets 4..7. */
static void set_and_get(void)
{
    for (int i = 4; i < 8; i++)
        glMultiTexCoord4f(GL_TEXTURE0 + i, (float)i, 0.5f * i, -1.0f * i, 2.0f);
    glMultiTexCoord2f(GL_TEXTURE2, 9, 8);
    for (int i = 0; i < 8; i++) {
        char key[64];
        glActiveTexture(GL_TEXTURE0 + i);
        snprintf(key, sizeof key, "current.%d", i);
        value_floats(key, GL_CURRENT_TEXTURE_COORDS, 4);
    }
    capi_expect_error(GL_NO_ERROR, "current");

    /* Texture matrices: set 5 translated and pushed, set 7 scaled; set 4 untouched. */
    glMatrixMode(GL_TEXTURE);
    glActiveTexture(GL_TEXTURE5);
    glTranslatef(1, 2, 3);
    glPushMatrix();
    glRotatef(90, 0, 0, 1);
    glActiveTexture(GL_TEXTURE7);
    glScalef(2, 3, 4);
    for (int i = 4; i < 8; i++) {
        char key[64];
        glActiveTexture(GL_TEXTURE0 + i);
        snprintf(key, sizeof key, "matrix.%d", i);
        value_floats(key, GL_TEXTURE_MATRIX, 16);
        if (capi_is_tessera()) {
            /* Not compared: Mesa 22 answers the identity for set 5 here. */
            GLfloat m[16], t[16];
            glGetFloatv(GL_TEXTURE_MATRIX, m);
            glGetFloatv(GL_TRANSPOSE_TEXTURE_MATRIX, t);
            for (int k = 0; k < 16; k++)
                capi_check(t[k] == m[(k % 4) * 4 + k / 4], "set %d: transposed element %d", i, k);
        }
        snprintf(key, sizeof key, "depth.%d", i);
        capi_value_query("matrix", key, GL_TEXTURE_STACK_DEPTH, 1);
    }
    glActiveTexture(GL_TEXTURE5);
    glPopMatrix();
    value_floats("matrix.5.popped", GL_TEXTURE_MATRIX, 16);
    glMatrixMode(GL_MODELVIEW);
    capi_expect_error(GL_NO_ERROR, "matrices");

    /* Texgen of set 6. */
    glActiveTexture(GL_TEXTURE6);
    static const GLfloat plane[4] = {1, 2, 3, 4};
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
    glTexGenfv(GL_T, GL_EYE_PLANE, plane);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_R);
    capi_value("texgen.6.enabled", "%d %d %d", glIsEnabled(GL_TEXTURE_GEN_S), glIsEnabled(GL_TEXTURE_GEN_T),
               glIsEnabled(GL_TEXTURE_GEN_R));
    capi_value_query("texgen.6", "gen_s", GL_TEXTURE_GEN_S, 1);
    GLint mode[3];
    GLfloat object[4], eye[4];
    glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode[0]);
    glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &mode[1]);
    glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &mode[2]);
    glGetTexGenfv(GL_S, GL_OBJECT_PLANE, object);
    glGetTexGenfv(GL_T, GL_EYE_PLANE, eye);
    capi_value("texgen.6.modes", "%x %x %x", mode[0], mode[1], mode[2]);
    capi_value("texgen.6.planes", "%g %g %g %g / %g %g %g %g", object[0], object[1], object[2], object[3], eye[0],
               eye[1], eye[2], eye[3]);
    glActiveTexture(GL_TEXTURE4);
    capi_value("texgen.4.enabled", "%d", glIsEnabled(GL_TEXTURE_GEN_S));
    glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode[0]);
    capi_value("texgen.4.mode", "%x", mode[0]);
    glActiveTexture(GL_TEXTURE6);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_R);
    glActiveTexture(GL_TEXTURE0);
    capi_expect_error(GL_NO_ERROR, "texgen");

    /* Arrays of set 6: enable and pointer per set. */
    static const GLshort array6[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    glClientActiveTexture(GL_TEXTURE6);
    glTexCoordPointer(3, GL_SHORT, 8, array6);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    capi_value_query("array.6", "client_active", GL_CLIENT_ACTIVE_TEXTURE, 1);
    capi_value_query("array.6", "enabled", GL_TEXTURE_COORD_ARRAY, 1);
    capi_value_query("array.6", "size", GL_TEXTURE_COORD_ARRAY_SIZE, 1);
    capi_value_query("array.6", "type", GL_TEXTURE_COORD_ARRAY_TYPE, 1);
    capi_value_query("array.6", "stride", GL_TEXTURE_COORD_ARRAY_STRIDE, 1);
    GLvoid *pointer = NULL;
    glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &pointer);
    capi_check(pointer == array6, "set 6's pointer");
    glClientActiveTexture(GL_TEXTURE5);
    capi_value_query("array.5", "enabled", GL_TEXTURE_COORD_ARRAY, 1);
    capi_value_query("array.5", "size", GL_TEXTURE_COORD_ARRAY_SIZE, 1);
    glClientActiveTexture(GL_TEXTURE6);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    capi_expect_error(GL_NO_ERROR, "arrays");
}

static void errors(void)
{
    /* Mesa accepts its 192 combined image units here; tessera's limit is the 8 sets. */
    glActiveTexture(GL_TEXTURE0 + 200);
    capi_expect_error(GL_INVALID_ENUM, "active_texture_200");
    if (capi_is_tessera()) {
        glActiveTexture(GL_TEXTURE8);
        capi_check(glGetError() == GL_INVALID_ENUM, "glActiveTexture(GL_TEXTURE8)");
    }
    glClientActiveTexture(GL_TEXTURE8);
    capi_expect_error(GL_INVALID_ENUM, "client_active_texture_8");
    capi_value_query("errors", "active_after", GL_ACTIVE_TEXTURE, 1);
    capi_value_query("errors", "client_active_after", GL_CLIENT_ACTIVE_TEXTURE, 1);

    /* Units 4..7 are coordinate sets only on tessera: texture enables and the environment
     * there are GL_INVALID_OPERATION (Mesa's llvmpipe has 8 fixed-function units). */
    glActiveTexture(GL_TEXTURE5);
    if (capi_is_tessera()) {
        GLint v = 0;
        glEnable(GL_TEXTURE_2D);
        capi_check(glGetError() == GL_INVALID_OPERATION, "glEnable(GL_TEXTURE_2D) on unit 5");
        capi_check(!glIsEnabled(GL_TEXTURE_2D) && glGetError() == GL_INVALID_OPERATION, "glIsEnabled on unit 5");
        glGetIntegerv(GL_TEXTURE_CUBE_MAP, &v);
        capi_check(glGetError() == GL_INVALID_OPERATION, "glGet(GL_TEXTURE_CUBE_MAP) on unit 5");
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
        capi_check(glGetError() == GL_INVALID_OPERATION, "glTexEnv on unit 5");
        glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
        capi_check(glGetError() == GL_INVALID_OPERATION, "glGetTexEnv on unit 5");
        glMultiTexCoord1f(GL_TEXTURE8, 1);
        capi_check(glGetError() == GL_INVALID_ENUM, "glMultiTexCoord(GL_TEXTURE8)");
    }
    /* GL_COORD_REPLACE is coordinate state: every set has it. */
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    GLint replace = 0;
    glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace);
    capi_value("errors.coord_replace.5", "%d", replace);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
    glActiveTexture(GL_TEXTURE0);
    capi_expect_error(GL_NO_ERROR, "errors_end");
}

/* glPushAttrib / glPushClientAttrib and display lists keep sets 4..7. */
static void attribs_and_lists(void)
{
    glActiveTexture(GL_TEXTURE7);
    glMultiTexCoord4f(GL_TEXTURE6, 6, 6, 6, 6);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glPushAttrib(GL_CURRENT_BIT | GL_TEXTURE_BIT | GL_ENABLE_BIT | GL_TRANSFORM_BIT);
    glMultiTexCoord4f(GL_TEXTURE6, -1, -1, -1, -1);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glEnable(GL_TEXTURE_GEN_Q);
    glActiveTexture(GL_TEXTURE1);
    glPopAttrib();
    capi_value_query("attrib", "active", GL_ACTIVE_TEXTURE, 1);
    capi_value_query("attrib", "gen_q", GL_TEXTURE_GEN_Q, 1);
    GLint mode = 0;
    glGetTexGeniv(GL_Q, GL_TEXTURE_GEN_MODE, &mode);
    capi_value("attrib.gen_q_mode", "%x", mode);
    glActiveTexture(GL_TEXTURE6);
    value_floats("attrib.current.6", GL_CURRENT_TEXTURE_COORDS, 4);

    static const GLfloat coords[4] = {0};
    glClientActiveTexture(GL_TEXTURE7);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glTexCoordPointer(2, GL_FLOAT, 0, coords);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE2);
    glPopClientAttrib();
    capi_value_query("client_attrib", "client_active", GL_CLIENT_ACTIVE_TEXTURE, 1);
    capi_value_query("client_attrib", "enabled.7", GL_TEXTURE_COORD_ARRAY, 1);
    capi_value_query("client_attrib", "size.7", GL_TEXTURE_COORD_ARRAY_SIZE, 1);
    glClientActiveTexture(GL_TEXTURE0);

    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glMultiTexCoord3f(GL_TEXTURE5, 0.25f, 0.5f, 0.75f);
    glEndList();
    glActiveTexture(GL_TEXTURE5);
    value_floats("list.before", GL_CURRENT_TEXTURE_COORDS, 4);
    glCallList(list);
    value_floats("list.after", GL_CURRENT_TEXTURE_COORDS, 4);
    glDeleteLists(list, 1);
    glActiveTexture(GL_TEXTURE0);
    capi_expect_error(GL_NO_ERROR, "attribs_and_lists");
}

/* The raster texture coordinates of sets 4..7: texgen and the texture matrices apply. */
static void raster(void)
{
    static const GLfloat plane[4] = {2, 0, 0, 0.5f};
    glMatrixMode(GL_TEXTURE);
    glActiveTexture(GL_TEXTURE6);
    glTranslatef(0.5f, 0, 0);
    glMatrixMode(GL_MODELVIEW);
    glMultiTexCoord4f(GL_TEXTURE6, 1, 2, 3, 1);
    glMultiTexCoord4f(GL_TEXTURE5, 7, 7, 7, 1);
    glActiveTexture(GL_TEXTURE5);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
    glEnable(GL_TEXTURE_GEN_S);
    glRasterPos2f(0.25f, 0.5f);
    for (int i = 4; i < 8; i++) {
        char key[64];
        glActiveTexture(GL_TEXTURE0 + i);
        snprintf(key, sizeof key, "raster.%d", i);
        value_floats(key, GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    }
    glWindowPos2f(1, 1);
    glActiveTexture(GL_TEXTURE6);
    value_floats("window_pos.6", GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glActiveTexture(GL_TEXTURE5);
    glDisable(GL_TEXTURE_GEN_S);
    glActiveTexture(GL_TEXTURE0);
    capi_expect_error(GL_NO_ERROR, "raster");
}

static GLuint vertex_program(const char *source)
{
    GLuint p = capi_program("sets", source, NULL);
    glUseProgram(p);
    glUniformMatrix4fv(glGetUniformLocation(p, "mvp"), 1, GL_FALSE, ortho);
    return p;
}

static void grab(const char *name)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    capi_save_framebuffer(name, W, H);
    capi_expect_error(GL_NO_ERROR, name);
    glClear(GL_COLOR_BUFFER_BIT);
}

/* A vertex shader colouring with gl_TextureMatrix[5] * gl_MultiTexCoord6 (and with
 * gl_MultiTexCoord7 and gl_TextureMatrix[4] in the immediate-mode draw). */
static void shader_draws(void)
{
    GLuint p = vertex_program("uniform mat4 mvp;\n"
                              "void main() {\n"
                              "    gl_Position = mvp * gl_Vertex;\n"
                              "    gl_FrontColor = gl_TextureMatrix[5] * gl_MultiTexCoord6\n"
                              "        + gl_TextureMatrix[4] * gl_MultiTexCoord7;\n"
                              "}\n");
    /* Set 5's matrix halves and shifts: (s, t, r, q) -> (s/2, t/2 + 0.25, r, q). */
    glMatrixMode(GL_TEXTURE);
    glActiveTexture(GL_TEXTURE5);
    glLoadIdentity();
    glTranslatef(0, 0.25f, 0);
    glScalef(0.5f, 0.5f, 1);
    glActiveTexture(GL_TEXTURE4);
    glLoadIdentity();
    glScalef(0.5f, 1, 1);
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_MODELVIEW);
    glMultiTexCoord4f(GL_TEXTURE7, 0, 0, 0, 0);

    static const GLfloat pos[] = {2, 2, 30, 4, 16, 30, 2, 30, 30, 30, 4, 16};
    static const GLfloat set6[] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1, 0.5f, 0, 1, 1, 1, 1, 0, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glClientActiveTexture(GL_TEXTURE6);
    glTexCoordPointer(4, GL_FLOAT, 0, set6);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    grab("array_set6_matrix5");

    /* The same draw through glArrayElement and compiled into a display list. */
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 6; i++)
        glArrayElement(i);
    glEnd();
    grab("array_element_set6");
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glEndList();
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glCallList(list);
    glDeleteLists(list, 1);
    grab("list_set6");

    /* Without the array the current value of set 6 goes to every vertex. */
    glMultiTexCoord4f(GL_TEXTURE6, 0.5f, 1, 0.25f, 1);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    grab("current_set6");
    glMultiTexCoord4f(GL_TEXTURE6, 0, 0, 0, 0);

    /* Immediate mode: gl_MultiTexCoord7 per vertex (through matrix 4). */
    glDisableClientState(GL_VERTEX_ARRAY);
    glBegin(GL_TRIANGLES);
    glMultiTexCoord4f(GL_TEXTURE7, 1, 0, 0, 1);
    glVertex2f(2, 2);
    glMultiTexCoord4f(GL_TEXTURE7, 0, 1, 0, 1);
    glVertex2f(30, 2);
    glMultiTexCoord4f(GL_TEXTURE7, 0, 0, 1, 1);
    glVertex2f(16, 30);
    glEnd();
    grab("immediate_set7_matrix4");

    /* glInterleavedArrays fills the client active set's array. */
    static const GLfloat t2f_v3f[] = {1, 0, 2, 2, 0, 0, 1, 30, 2, 0, 1, 1, 16, 30, 0};
    glMultiTexCoord4f(GL_TEXTURE7, 0, 0, 0, 0);
    glClientActiveTexture(GL_TEXTURE6);
    glInterleavedArrays(GL_T2F_V3F, 0, t2f_v3f);
    capi_value_query("interleaved", "enabled.6", GL_TEXTURE_COORD_ARRAY, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    grab("interleaved_set6");
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    glUseProgram(0);
    glDeleteProgram(p);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, W, H, NULL);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    limits();
    set_and_get();
    errors();
    attribs_and_lists();
    raster();
    shader_draws();
    return capi_finish();
}
