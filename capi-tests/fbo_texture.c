/* Render to texture: drawing into texture images attached to a framebuffer object (a 2D
 * level 0 and level 1, a cube map face, 3D layers through glFramebufferTexture3D and
 * glFramebufferTextureLayer, an RGB texture, a depth texture), then sampling them (with
 * mipmaps made by glGenerateMipmap) and reading them with glGetTexImage; glCopyTexSubImage2D
 * from an object's attachment. */
#include "common.h"

#define W 32
#define H 32

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex3f(x0, y0, z);
    glTexCoord2f(1, 0);
    glVertex3f(x1, y0, z);
    glTexCoord2f(1, 1);
    glVertex3f(x1, y1, z);
    glTexCoord2f(0, 1);
    glVertex3f(x0, y1, z);
    glEnd();
}

/* A scene in the unit square: a smooth triangle over a cleared background. */
static void scene(float r, float g)
{
    glClearColor(r, g, 0.5f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 1);
    glVertex3f(0.1f, 0.1f, -0.5f);
    glColor4f(0, 1, 0, 0.5f);
    glVertex3f(0.9f, 0.2f, 0.5f);
    glColor4f(0, 0, 1, 0.25f);
    glVertex3f(0.4f, 0.95f, 0);
    glEnd();
}

static void save_tex(GLenum target, int level, const char *name, int w, int h, int d)
{
    static GLubyte px[W * H * 4 * 4];
    glGetTexImage(target, level, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_save_image(name, w, h * d, 4, CAPI_U8, px);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, 1, 0, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    GLuint fb, tex[6], depth_rb;
    glGenFramebuffers(1, &fb);
    glGenTextures(6, tex);
    glGenRenderbuffers(1, &depth_rb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);

    /* 2D, level 0 with a depth renderbuffer; then level 1 alone. */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    /* The whole chain: Mesa 22 accepts a level other than the base level only in a
     * mipmap-complete texture (a later rule; ARB_framebuffer_object has none). */
    for (int level = 1; (W >> level) > 0; level++)
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, W >> level, H >> level, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, W, H);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
    capi_value("status.2d", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glViewport(0, 0, W, H);
    glEnable(GL_DEPTH_TEST);
    scene(0.2f, 0.3f);
    glDisable(GL_DEPTH_TEST);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 1);
    glViewport(0, 0, W / 2, H / 2);
    scene(0.7f, 0.1f);
    capi_expect_error(GL_NO_ERROR, "rendering into levels 0 and 1");
    save_tex(GL_TEXTURE_2D, 0, "tex2d_level0", W, H, 1);
    save_tex(GL_TEXTURE_2D, 1, "tex2d_level1", W / 2, H / 2, 1);

    /* glGenerateMipmap from the rendered level 0, then sampled in the window. */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGenerateMipmap(GL_TEXTURE_2D);
    save_tex(GL_TEXTURE_2D, 1, "mipmap_level1", W / 2, H / 2, 1);
    save_tex(GL_TEXTURE_2D, 3, "mipmap_level3", W / 8, H / 8, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glViewport(0, 0, W, H);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0, 1, 1, 0);
    quad(0.1f, 0.6f, 0.35f, 0.85f, 0); /* minified: samples the generated levels */
    glDisable(GL_TEXTURE_2D);
    capi_save_framebuffer("sampled", W, H);

    /* A cube map face, cleared and drawn into. */
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    for (int f = 0; f < 6; f++)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, tex[1], 0);
    capi_value("status.cube", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    GLint face = 0;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, &face);
    capi_value("cube.face", "0x%x", face);
    glViewport(0, 0, 8, 8);
    scene(0.9f, 0.9f);
    save_tex(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, "cube_negative_y", 8, 8, 1);
    save_tex(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, "cube_positive_y", 8, 8, 1);

    /* 3D layers 1 (FramebufferTexture3D) and 3 (FramebufferTextureLayer). */
    glBindTexture(GL_TEXTURE_3D, tex[2]);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, tex[2], 0, 1);
    capi_value("status.3d", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    scene(0.1f, 0.6f);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, tex[2], 0, 3);
    GLint layer = -1;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, &layer);
    capi_value("3d.layer", "%d", layer);
    glClearColor(1, 0.5f, 0.25f, 0.125f);
    glClear(GL_COLOR_BUFFER_BIT);
    save_tex(GL_TEXTURE_3D, 0, "tex3d", 8, 8, 4);
    glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, tex[2], 0, 4);
    capi_value("status.3d_layer_out_of_range", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));

    /* An RGB texture keeps alpha 1 under blending with destination alpha. */
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[3], 0);
    capi_value("status.rgb", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    capi_value_query("rgb", "alpha_bits", GL_ALPHA_BITS, 1);
    glClearColor(0.2f, 0.4f, 0.6f, 0.3f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
    scene(0.2f, 0.4f);
    glDisable(GL_BLEND);
    save_tex(GL_TEXTURE_2D, 0, "rgb", 8, 8, 1);

    /* A depth texture as the depth attachment, read back as floats and used as a shadow map. */
    GLuint color_rb;
    glGenRenderbuffers(1, &color_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, color_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 16, 16);
    glBindTexture(GL_TEXTURE_2D, tex[4]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex[4], 0);
    capi_value("status.depth_texture", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glViewport(0, 0, 16, 16);
    /* Overlapping quads of constant depth (the depth of sloped triangles in 16-bit buffers
     * differs from llvmpipe's in the last bits whatever the buffer, see draw_depth_cull). */
    glEnable(GL_DEPTH_TEST);
    glClearDepth(1);
    glClear(GL_DEPTH_BUFFER_BIT);
    quad(0.1f, 0.1f, 0.7f, 0.6f, 0.3f);
    quad(0.4f, 0.3f, 0.9f, 0.95f, -0.6f);
    quad(0.2f, 0.5f, 0.5f, 0.8f, 0.1f);
    glDisable(GL_DEPTH_TEST);
    static GLfloat depth[16 * 16], texels[16 * 16];
    glReadPixels(0, 0, 16, 16, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    capi_save_image("depth_read", 16, 16, 1, CAPI_F32, depth);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels);
    capi_check(memcmp(depth, texels, sizeof depth) == 0, "the depth texture holds what was read");
    capi_save_image("depth_texture", 16, 16, 1, CAPI_F32, texels);

    /* glCopyTexSubImage2D from attachment 1 of the object. */
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, color_rb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 0);
    glDrawBuffer(GL_COLOR_ATTACHMENT1);
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    capi_value("status.attachment1", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glBindTexture(GL_TEXTURE_2D, tex[5]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 3, 4, 6, 5);
    save_tex(GL_TEXTURE_2D, 0, "copied", 8, 8, 1);
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
