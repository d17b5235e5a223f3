/* Texture coordinate generation and shadow maps against Mesa: OBJECT_LINEAR and EYE_LINEAR
 * (planes given under a modelview, which transforms eye planes at specification), SPHERE_MAP,
 * NORMAL_MAP and REFLECTION_MAP (with a cube map) on a lit-free sphere of normals, with the
 * texture matrix; then a complete fixed-function shadow-mapping scene: depth rendered from
 * the light, copied into a DEPTH_COMPONENT texture with glCopyTexImage2D, projected with
 * EYE_LINEAR texgen and the texture matrix, compared with COMPARE_R_TO_TEXTURE under every
 * compare function and depth texture mode. */
#include "common.h"
#include <math.h>

#define W 64
#define H 64

static unsigned rng = 4242;
static unsigned char rnd(void)
{
    rng = rng * 1103515245u + 12345u;
    return (unsigned char)(rng >> 16);
}

static void perspective(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A tessellated sphere of radius 1 at (0, 0, -4), with normals. */
static void sphere(void)
{
    const int slices = 16, stacks = 12;
    for (int i = 0; i < stacks; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= slices; j++) {
            for (int k = 1; k >= 0; k--) {
                float phi = 3.14159265f * ((float)(i + k) / stacks - 0.5f);
                float theta = 2.0f * 3.14159265f * (float)j / slices;
                float x = cosf(phi) * cosf(theta), y = sinf(phi), z = cosf(phi) * sinf(theta);
                glNormal3f(x, y, z);
                glVertex3f(x, y, z - 4.0f);
            }
        }
        glEnd();
    }
}

static void checker_texture(void)
{
    unsigned char img[16 * 16 * 4];
    for (int i = 0; i < 16 * 16; i++) {
        int on = ((i % 16) / 2 + (i / 16) / 2) % 2;
        img[4 * i] = on ? 230 : 30;
        img[4 * i + 1] = (unsigned char)(i % 16 * 15);
        img[4 * i + 2] = (unsigned char)(i / 16 * 15);
        img[4 * i + 3] = 255;
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void texgen(void)
{
    glClearColor(0.1f, 0.1f, 0.2f, 1);
    checker_texture();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    const GLfloat splane[4] = {0.5f, 0.1f, 0.0f, 0.5f}, tplane[4] = {0.0f, 0.45f, 0.2f, 0.5f};
    static const GLenum modes[] = {GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_NORMAL_MAP, GL_REFLECTION_MAP};
    static const char *names[] = {"object_linear", "eye_linear", "sphere_map", "normal_map", "reflection_map"};
    for (int m = 0; m < 5; m++) {
        perspective();
        /* Eye planes are given under a rotated modelview: they keep that transform. */
        glRotatef(30, 0, 1, 0);
        glTexGenfv(GL_S, GL_OBJECT_PLANE, splane);
        glTexGenfv(GL_T, GL_OBJECT_PLANE, tplane);
        glTexGenfv(GL_S, GL_EYE_PLANE, splane);
        glTexGenfv(GL_T, GL_EYE_PLANE, tplane);
        glLoadIdentity();
        glTranslatef(0.2f, 0.1f, 0);
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, (GLint)modes[m]);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, (GLint)modes[m]);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
        if (m >= 3) {
            /* NORMAL_MAP and REFLECTION_MAP generate R as well: sampled from a 2D texture
             * they are scaled into range by the texture matrix. */
            glMatrixMode(GL_TEXTURE);
            glLoadIdentity();
            glTranslatef(0.5f, 0.5f, 0);
            glScalef(0.5f, 0.5f, 1);
            glMatrixMode(GL_MODELVIEW);
        }
        glClear(GL_COLOR_BUFFER_BIT);
        sphere();
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
        capi_save_framebuffer(names[m], W, H);
        GLfloat eye[4];
        glGetTexGenfv(GL_S, GL_EYE_PLANE, eye);
        capi_value("eye_plane", "%s %.5f %.5f %.5f %.5f", names[m], eye[0], eye[1], eye[2], eye[3]);
    }
    /* A cube map looked up with REFLECTION_MAP on S, T and R. */
    GLuint cube;
    glGenTextures(1, &cube);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    for (int face = 0; face < 6; face++) {
        unsigned char f[8 * 8 * 4];
        for (int i = 0; i < 64; i++) {
            f[4 * i] = (unsigned char)(face * 45 + (i % 8) * 5);
            f[4 * i + 1] = rnd();
            f[4 * i + 2] = (unsigned char)(255 - face * 40);
            f[4 * i + 3] = 255;
        }
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, f);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_CUBE_MAP);
    for (int c = 0; c < 3; c++)
        glTexGeni(GL_S + c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glEnable(GL_TEXTURE_GEN_R);
    perspective();
    glClear(GL_COLOR_BUFFER_BIT);
    sphere();
    capi_save_framebuffer("cube_reflection", W, H);
    glDisable(GL_TEXTURE_CUBE_MAP);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &cube);
}

/* The scene: a floor and a box above it. */
static void scene(void)
{
    glBegin(GL_QUADS);
    glColor3f(0.8f, 0.8f, 0.7f);
    glVertex3f(-3, -1, -1);
    glVertex3f(3, -1, -1);
    glVertex3f(3, -1, -8);
    glVertex3f(-3, -1, -8);
    glColor3f(0.9f, 0.3f, 0.2f);
    /* Box top and front. */
    glVertex3f(-0.5f, 0.2f, -3.5f);
    glVertex3f(0.7f, 0.2f, -3.5f);
    glVertex3f(0.7f, 0.2f, -4.7f);
    glVertex3f(-0.5f, 0.2f, -4.7f);
    glVertex3f(-0.5f, -1, -3.5f);
    glVertex3f(0.7f, -1, -3.5f);
    glVertex3f(0.7f, 0.2f, -3.5f);
    glVertex3f(-0.5f, 0.2f, -3.5f);
    glEnd();
}

static void light_view(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 12);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* The light above and to the left, looking down at the box. */
    glRotatef(50, 1, 0, 0);
    glRotatef(-20, 0, 1, 0);
    glTranslatef(1.5f, -4.5f, 1.0f);
}

static void shadow_map(void)
{
    /* 1. Depth from the light, copied into a depth texture. */
    glViewport(0, 0, W, H);
    light_view();
    GLfloat light_projection[16], light_modelview[16];
    glGetFloatv(GL_PROJECTION_MATRIX, light_projection);
    glGetFloatv(GL_MODELVIEW_MATRIX, light_modelview);
    glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    scene();
    glDisable(GL_POLYGON_OFFSET_FILL);
    GLuint shadow;
    glGenTextures(1, &shadow);
    glBindTexture(GL_TEXTURE_2D, shadow);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 0, 0, W, H, 0);
    capi_expect_error(GL_NO_ERROR, "copy depth");
    float depth[W * H];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    capi_save_image("light_depth", W, H, 1, CAPI_F32, depth);

    /* 2. The camera view, texgen EYE_LINEAR with identity planes under the camera's
     * modelview, the texture matrix: bias · light projection · light modelview · camera⁻¹. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(10, 1, 0, 0);
    glTranslatef(0, -0.5f, 0.5f);
    GLfloat camera[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, camera);
    /* The inverse of the camera (a rotation about x and a translation). */
    glPushMatrix();
    glLoadIdentity();
    glTranslatef(0, 0.5f, -0.5f);
    glRotatef(-10, 1, 0, 0);
    GLfloat camera_inverse[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, camera_inverse);
    glPopMatrix();
    static const GLfloat planes[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    glPushMatrix();
    glLoadIdentity();
    for (int c = 0; c < 4; c++) {
        glTexGeni(GL_S + c, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        glTexGenfv(GL_S + c, GL_EYE_PLANE, planes[c]);
        glEnable(GL_TEXTURE_GEN_S + c);
    }
    glPopMatrix();
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.5f);
    glScalef(0.5f, 0.5f, 0.5f);
    glMultMatrixf(light_projection);
    glMultMatrixf(light_modelview);
    glMultMatrixf(camera_inverse);
    glMatrixMode(GL_MODELVIEW);
    (void)camera;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    static const GLenum funcs[] = {GL_LEQUAL, GL_GEQUAL, GL_LESS, GL_GREATER, GL_ALWAYS, GL_NEVER};
    static const GLenum modes[] = {GL_LUMINANCE, GL_INTENSITY, GL_ALPHA};
    char name[64];
    for (int filter = 0; filter < 2; filter++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter ? GL_LINEAR : GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter ? GL_LINEAR : GL_NEAREST);
        for (int f = 0; f < 6; f++) {
            for (int m = 0; m < 3; m++) {
                if (filter && m > 0)
                    continue;
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, funcs[f]);
                glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, modes[m]);
                glClearColor(0.2f, 0.3f, 0.5f, 0.5f);
                glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
                scene();
                snprintf(name, sizeof name, "shadow_%s_f%d_m%d", filter ? "linear" : "nearest", f, m);
                capi_save_framebuffer(name, W, H);
            }
        }
    }
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    for (int c = 0; c < 4; c++)
        glDisable(GL_TEXTURE_GEN_S + c);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_DEPTH_TEST);
    glDeleteTextures(1, &shadow);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 0, 0, W, H, NULL);
    texgen();
    shadow_map();
    return capi_finish();
}
