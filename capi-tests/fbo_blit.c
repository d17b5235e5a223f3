/* glBlitFramebuffer: copies, scaled NEAREST (up and down, ratios that put no pixel centre on
 * a source pixel edge), mirrored by inverted rectangles, LINEAR, scissored, between formats
 * (RGBA8, RGBA32F, RGB8 and the window), depth and stencil, overlapping within one buffer,
 * and the errors. */
#include "common.h"

#define SW 15
#define SH 9
#define DW 32
#define DH 20

static GLuint fbo_with(GLenum color_format, GLenum ds_format, int w, int h)
{
    GLuint fb, rb[2];
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, color_format, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    if (ds_format) {
        glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, ds_format, w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
        if (ds_format == GL_DEPTH24_STENCIL8)
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    }
    capi_check(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE, "complete 0x%x", color_format);
    return fb;
}

static void save(GLuint fb, const char *name, int w, int h)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
    static GLubyte px[DW * DH * 4];
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_save_image(name, w, h, 4, CAPI_U8, px);
}

static void clear_dst(GLuint fb)
{
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClearDepth(1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, DW, DH, NULL);
    GLuint src = fbo_with(GL_RGBA8, GL_DEPTH24_STENCIL8, SW, SH);
    GLuint dst = fbo_with(GL_RGBA8, GL_DEPTH24_STENCIL8, DW, DH);
    GLuint fdst = fbo_with(GL_RGBA32F, 0, DW, DH);
    GLuint rgb = fbo_with(GL_RGB8, 0, DW, DH);
    GLuint d16 = fbo_with(GL_RGBA8, GL_DEPTH_COMPONENT16, DW, DH);

    /* The source: every pixel its own color, depth and stencil. */
    glBindFramebuffer(GL_FRAMEBUFFER, src);
    glViewport(0, 0, SW, SH);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, SW, 0, SH, -1, 1);
    static GLubyte image[SW * SH * 4];
    static GLfloat depth[SW * SH];
    static GLubyte stencil[SW * SH];
    for (int y = 0; y < SH; y++)
        for (int x = 0; x < SW; x++) {
            GLubyte *p = image + 4 * (y * SW + x);
            p[0] = (GLubyte)(x * 17);
            p[1] = (GLubyte)(y * 28);
            p[2] = (GLubyte)((x * 7 + y * 13) & 255);
            p[3] = (GLubyte)(255 - x * 3);
            depth[y * SW + x] = (x + y * SW) / (float)(SW * SH);
            stencil[y * SW + x] = (GLubyte)(x + y * 16);
        }
    glRasterPos2i(0, 0);
    glDrawPixels(SW, SH, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDrawPixels(SW, SH, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    glDisable(GL_DEPTH_TEST);
    glDrawPixels(SW, SH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    capi_expect_error(GL_NO_ERROR, "source");
    save(src, "source", SW, SH);
    static GLuint source_depth[SW * SH];
    glReadPixels(0, 0, SW, SH, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, source_depth);
    capi_save_image("source_depth", SW, SH, 4, CAPI_U8, source_depth);

    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    /* Copy, up-scaled, down-scaled, mirrored in x, in y, and both rectangles inverted. */
    clear_dst(dst);
    glBlitFramebuffer(0, 0, SW, SH, 1, 1, 1 + SW, 1 + SH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(dst, "copy", DW, DH);
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(3, 1, 11, 9, 0, 0, 32, 16, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(dst, "upscaled", DW, DH);
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(0, 0, SW, SH, 2, 3, 8, 6, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(dst, "downscaled", DW, DH);
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(0, 0, SW, SH, 30, 0, 0, 18, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(dst, "mirrored_x", DW, DH);
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(0, SH, SW, 0, 0, 0, SW, SH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(dst, "mirrored_y", DW, DH);
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(SW, SH, 0, 0, SW, SH, 0, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(dst, "both_inverted", DW, DH);

    /* LINEAR, up-scaled (compared with a tolerance: the weights' precision differs). */
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(2, 2, 10, 7, 0, 0, 32, 20, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    save(dst, "linear", DW, DH);

    /* Scissored. */
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glEnable(GL_SCISSOR_TEST);
    glScissor(4, 2, 9, 5);
    glBlitFramebuffer(0, 0, SW, SH, 0, 0, 2 * SW, 2 * SH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glDisable(GL_SCISSOR_TEST);
    save(dst, "scissored", DW, DH);

    /* Between formats: into float (read back as floats), into RGB8, float back to RGBA8,
     * and into the window. */
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fdst);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(0, 0, SW, SH, 0, 0, SW, SH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fdst);
    static GLfloat fpx[DW * DH * 4];
    glReadPixels(0, 0, DW, DH, GL_RGBA, GL_FLOAT, fpx);
    capi_save_image("to_float", DW, DH, 4, CAPI_F32, fpx);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, rgb);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(0, 0, SW, SH, 0, 0, SW, SH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(rgb, "to_rgb", DW, DH);
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fdst);
    glBlitFramebuffer(0, 0, DW, DH, 0, 0, DW, DH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(dst, "from_float", DW, DH);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(0, 0, SW, SH, 5, 5, 5 + 2 * SW, 5 + SH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(0, "to_window", DW, DH);

    /* Overlapping within one buffer (the window): the copy reads the values from before. */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glBlitFramebuffer(5, 5, 25, 14, 9, 7, 29, 16, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    save(0, "overlapping", DW, DH);

    /* Depth and stencil, scaled and mirrored, read back exactly. */
    clear_dst(dst);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBlitFramebuffer(0, 0, SW, SH, 2 * SW, 0, 0, 2 * SH, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBlitFramebuffer(0, 0, SW, SH, 0, 0, SW, SH, GL_STENCIL_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, dst);
    static GLuint dpx[DW * DH];
    static GLubyte spx[DW * DH];
    glReadPixels(0, 0, DW, DH, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, dpx);
    /* A blit copies depth values (GL 3.0 section 4.3.2); tessera does so exactly, llvmpipe
     * passes them through a float and rounds one value in a few up by one 24-bit step. */
    static GLushort d16px[DW * DH];
    int exact = 1;
    for (int y = 0; y < DH; y++)
        for (int x = 0; x < DW; x++) {
            d16px[y * DW + x] = (GLushort)(dpx[y * DW + x] >> 16);
            if (x < 2 * SW && y < 2 * SH)
                exact &= dpx[y * DW + x] == source_depth[(y / 2) * SW + (2 * SW - 1 - x) / 2];
        }
    if (capi_is_tessera())
        capi_check(exact, "depth blits copy values exactly");
    capi_save_image("depth", DW, DH, 1, CAPI_U16, d16px);
    glReadPixels(0, 0, DW, DH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, spx);
    capi_save_image("stencil", DW, DH, 1, CAPI_U8, spx);
    save(dst, "depth_stencil_color_untouched", DW, DH);
    capi_expect_error(GL_NO_ERROR, "blits");

    /* Errors. */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, dst);
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
    capi_expect_error(GL_INVALID_OPERATION, "LINEAR depth");
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 8, 8, GL_STENCIL_BUFFER_BIT, GL_LINEAR);
    capi_expect_error(GL_INVALID_OPERATION, "LINEAR stencil");
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT | 0x8000, GL_NEAREST);
    capi_expect_error(GL_INVALID_VALUE, "mask");
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_LINEAR_MIPMAP_LINEAR);
    capi_expect_error(GL_INVALID_ENUM, "filter");
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, d16);
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_INVALID_OPERATION, "depth formats differ");
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_NO_ERROR, "color between framebuffers whose depth formats differ");
    GLuint empty;
    glGenFramebuffers(1, &empty);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, empty);
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_INVALID_FRAMEBUFFER_OPERATION, "incomplete read framebuffer");
    PFNGLBLITFRAMEBUFFEREXTPROC blit_ext = (PFNGLBLITFRAMEBUFFEREXTPROC)OSMesaGetProcAddress("glBlitFramebufferEXT");
    capi_check(blit_ext != NULL, "glBlitFramebufferEXT is found");
    if (blit_ext)
        blit_ext(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_INVALID_FRAMEBUFFER_OPERATION, "EXT name");
    return capi_finish();
}
