/* Rendering into framebuffer objects: eight color attachments of different formats with
 * per-buffer blend state and write masks, depth and stencil tests on a packed
 * depth/stencil renderbuffer, clears, glDrawPixels, glBitmap and glCopyPixels into the
 * object, glReadPixels of every attachment and of depth and stencil, and the window's
 * framebuffer left untouched. */
#include "common.h"

#define W 20
#define H 12

static GLuint renderbuffer(GLenum format)
{
    GLuint rb;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, format, W, H);
    return rb;
}

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);

    static const GLenum formats[8] = {GL_RGBA8, GL_RGB8, GL_RGBA16, GL_RGBA32F,
                                      GL_RGBA8, GL_RGBA16F, GL_RGBA8, GL_RGB16};
    GLuint fb, color[8];
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    for (int i = 0; i < 8; i++) {
        color[i] = renderbuffer(formats[i]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_RENDERBUFFER, color[i]);
    }
    GLuint ds = renderbuffer(GL_DEPTH24_STENCIL8);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
    capi_value("status", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    GLenum all[8];
    for (int i = 0; i < 8; i++)
        all[i] = GL_COLOR_ATTACHMENT0 + i;
    glDrawBuffers(8, all);
    capi_value_query("fbo", "draw_buffer3", GL_DRAW_BUFFER3, 1);

    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.25f, 0.5f, 0.75f, 0.5f);
    glClearDepth(0.5);
    glClearStencil(3);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    /* Per-buffer state: blending on 1, 3, 5, 7 with different functions and equations;
     * masks on 2 and 6. */
    glEnablei(GL_BLEND, 1);
    glBlendFunci(1, GL_ONE, GL_ONE);
    glEnablei(GL_BLEND, 3);
    glBlendFunci(3, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnablei(GL_BLEND, 5);
    glBlendEquationi(5, GL_FUNC_REVERSE_SUBTRACT);
    glBlendFunci(5, GL_ONE, GL_ONE);
    glEnablei(GL_BLEND, 7);
    glBlendEquationi(7, GL_MAX);
    glColorMaski(2, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glColorMaski(6, GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);

    /* Depth: the first quad at z 0 fails GL_LESS against 0.5 (window depth 0.5 → equal),
     * the second at -0.5 passes; stencil counts the passes. */
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glColor4f(1, 0.25f, 0.5f, 0.75f);
    quad(2, 2, 14, 10, -0.5f);
    glColor4f(0.5f, 1, 0, 0.25f);
    quad(6, 4, 18, 8, 0.2f);
    glColor4f(0, 0.75f, 1, 1);
    quad(8, 0, 12, 12, -0.8f);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glColorMask(1, 1, 1, 1);

    /* Pixel rectangles into the object: a bitmap and a small image (not into the float
     * buffers, whose unpacking of bytes differs from Mesa's in the last bit). */
    static const GLenum fixed_point[6] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                          GL_COLOR_ATTACHMENT4, GL_COLOR_ATTACHMENT6, GL_COLOR_ATTACHMENT7};
    glDrawBuffers(6, fixed_point);
    static const GLubyte bits[4] = {0xa0, 0x50, 0xa0, 0x50};
    glColor4f(1, 1, 0, 1);
    glRasterPos2i(1, 1);
    glBitmap(4, 4, 0, 0, 0, 0, bits);
    GLubyte image[3 * 2 * 4];
    for (int i = 0; i < 24; i++)
        image[i] = (GLubyte)(i * 10);
    glRasterPos2i(15, 9);
    glDrawPixels(3, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
    capi_expect_error(GL_NO_ERROR, "drawing into the object");

    /* Reads of every attachment, as bytes and floats. */
    for (int i = 0; i < 8; i++) {
        glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
        static GLubyte px[W * H * 4];
        static GLfloat fx[W * H * 4];
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
        char name[32];
        snprintf(name, sizeof name, "attachment%d", i);
        capi_save_image(name, W, H, 4, CAPI_U8, px);
        glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, fx);
        snprintf(name, sizeof name, "attachment%d_float", i);
        capi_save_image(name, W, H, 4, CAPI_F32, fx);
    }
    static GLuint depth[W * H];
    static GLubyte stencil[W * H];
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    capi_save_image("depth", W, H, 1, CAPI_F32, depth); /* raw bits, compared exactly */
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    capi_save_image("stencil", W, H, 1, CAPI_U8, stencil);
    static GLuint packed[W * H];
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed);
    capi_save_image("depth_stencil", W, H, 4, CAPI_U8, packed);

    /* glCopyPixels within attachment 0 (read buffer 0, draw buffer 0 only). */
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glRasterPos2i(0, 6);
    glCopyPixels(0, 0, 8, 6, GL_COLOR);
    capi_save_framebuffer("copied", W, H);

    /* The window was not drawn into. */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    capi_value_query("window", "draw_buffer", GL_DRAW_BUFFER, 1);
    capi_value_query("window", "red_bits", GL_RED_BITS, 1);
    capi_save_framebuffer("window", W, H);
    /* Binding the object again restores its draw and read buffers. */
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    capi_value_query("rebound", "draw_buffer", GL_DRAW_BUFFER, 1);
    capi_value_query("rebound", "read_buffer", GL_READ_BUFFER, 1);
    capi_value_query("rebound", "red_bits", GL_RED_BITS, 1);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(8, color);
    glDeleteRenderbuffers(1, &ds);
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
