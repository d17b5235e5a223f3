/* Framebuffer objects: completeness of valid and invalid attachment sets, attachment and
 * renderbuffer queries, errors of the object commands, the bindings, and deletion of bound
 * objects. (Incomplete draw/read buffer states are left to the Rust tests: Mesa 22 relaxes
 * them as ARB_ES2_compatibility allows, tessera follows ARB_framebuffer_object.) */
#include "common.h"

static GLuint renderbuffer(GLenum format, int w, int h)
{
    GLuint rb;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
    return rb;
}

static void status(const char *what)
{
    GLenum s = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    capi_value(what, "0x%x", s);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, 16, 16, NULL);
    status("status.window");
    capi_value_query("init", "framebuffer_binding", GL_FRAMEBUFFER_BINDING, 1);
    capi_value_query("init", "max_color_attachments_ge_8", GL_MAX_COLOR_ATTACHMENTS, 1);

    GLuint fb;
    glGenFramebuffers(1, &fb);
    capi_value("is_framebuffer.genned", "%d", glIsFramebuffer(fb));
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    capi_value("is_framebuffer.bound", "%d", glIsFramebuffer(fb));
    capi_value_query("bound", "draw_binding", GL_DRAW_FRAMEBUFFER_BINDING, 1);
    capi_value_query("bound", "read_binding", GL_READ_FRAMEBUFFER_BINDING, 1);
    capi_value_query("bound", "draw_buffer", GL_DRAW_BUFFER, 1);
    capi_value_query("bound", "read_buffer", GL_READ_BUFFER, 1);
    status("status.empty");

    /* Valid sets. */
    GLuint color = renderbuffer(GL_RGBA8, 8, 4);
    capi_value_query("rb", "renderbuffer_binding", GL_RENDERBUFFER_BINDING, 1);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    status("status.color");
    GLuint ds = renderbuffer(GL_DEPTH24_STENCIL8, 8, 4);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
    status("status.color_depth_stencil");
    capi_value_query("fbo", "red_bits", GL_RED_BITS, 1);
    capi_value_query("fbo", "alpha_bits", GL_ALPHA_BITS, 1);
    capi_value_query("fbo", "depth_bits", GL_DEPTH_BITS, 1);
    capi_value_query("fbo", "stencil_bits", GL_STENCIL_BITS, 1);
    capi_value_query("fbo", "doublebuffer", GL_DOUBLEBUFFER, 1);

    /* Attachment queries. */
    static const struct { GLenum pname; const char *name; } params[] = {
        {GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, "type"},   {GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, "name"},
        {GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, "red"},       {GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE, "alpha"},
        {GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, "depth"},   {GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, "stencil"},
        {GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, "component"},
    };
    static const struct { GLenum point; const char *name; } points[] = {
        {GL_COLOR_ATTACHMENT0, "color0"}, {GL_DEPTH_ATTACHMENT, "depth"},
        {GL_STENCIL_ATTACHMENT, "stencil"}, {GL_DEPTH_STENCIL_ATTACHMENT, "depth_stencil"},
    };
    for (unsigned p = 0; p < sizeof points / sizeof points[0]; p++) {
        for (unsigned i = 0; i < sizeof params / sizeof params[0]; i++) {
            GLint v = -1;
            glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, points[p].point, params[i].pname, &v);
            char key[64];
            snprintf(key, sizeof key, "attachment.%s.%s", points[p].name, params[i].name);
            capi_value(key, "%d err 0x%x", v, glGetError());
        }
    }
    GLint none = -1;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &none);
    capi_value("attachment.color1.type", "%d err 0x%x", none, glGetError());

    /* Renderbuffer queries of each format. */
    static const GLenum formats[] = {GL_RGBA8, GL_RGB8, GL_RGBA16, GL_RGBA32F, GL_DEPTH_COMPONENT16,
                                     GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32F, GL_STENCIL_INDEX8,
                                     GL_DEPTH24_STENCIL8};
    static const GLenum rb_params[] = {GL_RENDERBUFFER_WIDTH, GL_RENDERBUFFER_HEIGHT,
                                       GL_RENDERBUFFER_INTERNAL_FORMAT, GL_RENDERBUFFER_RED_SIZE,
                                       GL_RENDERBUFFER_GREEN_SIZE, GL_RENDERBUFFER_BLUE_SIZE,
                                       GL_RENDERBUFFER_ALPHA_SIZE, GL_RENDERBUFFER_DEPTH_SIZE,
                                       GL_RENDERBUFFER_STENCIL_SIZE, GL_RENDERBUFFER_SAMPLES};
    GLuint probe = renderbuffer(GL_RGBA8, 1, 1);
    for (unsigned f = 0; f < sizeof formats / sizeof formats[0]; f++) {
        glRenderbufferStorage(GL_RENDERBUFFER, formats[f], 5, 3);
        for (unsigned i = 0; i < sizeof rb_params / sizeof rb_params[0]; i++) {
            GLint v = -1;
            glGetRenderbufferParameteriv(GL_RENDERBUFFER, rb_params[i], &v);
            char key[64];
            snprintf(key, sizeof key, "rb.0x%x.0x%x", formats[f], rb_params[i]);
            capi_value(key, "%d", v);
        }
    }
    capi_expect_error(GL_NO_ERROR, "renderbuffer queries");

    /* Invalid sets: a color image at the depth point, a depth image at a color point,
     * storage never allocated, zero size. */
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, color);
    status("status.color_at_depth");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ds);
    status("status.depth_at_color");
    GLuint unallocated;
    glGenRenderbuffers(1, &unallocated);
    glBindRenderbuffer(GL_RENDERBUFFER, unallocated);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, unallocated);
    status("status.unallocated");
    GLuint zero = renderbuffer(GL_RGBA8, 0, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, zero);
    status("status.zero_size");
    GLuint stencil_only = renderbuffer(GL_STENCIL_INDEX8, 8, 4);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, stencil_only);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
    status("status.stencil_at_depth");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, stencil_only);
    status("status.stencil_only");

    /* Textures: complete for RGBA8 and depth levels; a missing level is incomplete. */
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    status("status.texture");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 1);
    status("status.texture_missing_level");
    GLint level = -1;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
    capi_value("attachment.texture_level", "%d", level);

    /* Errors. */
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, tex, 0);
    capi_expect_error(GL_INVALID_OPERATION, "3D target in FramebufferTexture2D");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X, tex, 0);
    capi_expect_error(GL_INVALID_OPERATION, "cube face of a 2D texture");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 4242, 0);
    capi_expect_error(GL_INVALID_OPERATION, "no such texture");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, -1);
    capi_expect_error(GL_INVALID_VALUE, "negative level");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 4242);
    capi_expect_error(GL_INVALID_OPERATION, "no such renderbuffer");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color);
    capi_expect_error(GL_INVALID_ENUM, "renderbuffer target");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_BACK, GL_RENDERBUFFER, color);
    capi_expect_error(GL_INVALID_ENUM, "attachment GL_BACK");
    glFramebufferRenderbuffer(GL_TEXTURE_2D, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    capi_expect_error(GL_INVALID_ENUM, "framebuffer target");
    glBindFramebuffer(GL_RENDERBUFFER, 0);
    capi_expect_error(GL_INVALID_ENUM, "bind target");
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_UNSIGNED_BYTE, 4, 4);
    capi_expect_error(GL_INVALID_ENUM, "storage format");
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, -1, 4);
    capi_expect_error(GL_INVALID_VALUE, "negative width");
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1 << 20, 4);
    capi_expect_error(GL_INVALID_VALUE, "too wide");
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
    capi_expect_error(GL_INVALID_OPERATION, "no renderbuffer bound");
    glCheckFramebufferStatus(GL_TEXTURE_2D);
    capi_expect_error(GL_INVALID_ENUM, "status target");
    glDrawBuffer(GL_BACK);
    capi_expect_error(GL_INVALID_OPERATION, "GL_BACK into an object");
    glReadBuffer(GL_FRONT);
    capi_expect_error(GL_INVALID_OPERATION, "GL_FRONT from an object");
    GLenum bufs[2] = {GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, bufs);
    capi_expect_error(GL_INVALID_OPERATION, "a draw buffer twice");

    /* An incomplete framebuffer: drawing, clearing and reading are errors. */
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 3);
    glClear(GL_COLOR_BUFFER_BIT);
    capi_expect_error(GL_INVALID_FRAMEBUFFER_OPERATION, "clear of an incomplete framebuffer");
    GLubyte px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_expect_error(GL_INVALID_FRAMEBUFFER_OPERATION, "read of an incomplete framebuffer");

    /* Separate read and draw bindings. */
    GLuint fb2;
    glGenFramebuffers(1, &fb2);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb2);
    capi_value_query("split", "draw_binding", GL_DRAW_FRAMEBUFFER_BINDING, 1);
    capi_value_query("split", "read_binding", GL_READ_FRAMEBUFFER_BINDING, 1);
    capi_value("status.read_empty", "0x%x", glCheckFramebufferStatus(GL_READ_FRAMEBUFFER));

    /* Deleting bound objects unbinds them; the window's draw buffer is back. */
    glDeleteFramebuffers(1, &fb);
    capi_value_query("deleted", "draw_binding", GL_DRAW_FRAMEBUFFER_BINDING, 1);
    capi_value_query("deleted", "read_binding", GL_READ_FRAMEBUFFER_BINDING, 1);
    capi_value_query("deleted", "draw_buffer", GL_DRAW_BUFFER, 1);
    glDeleteFramebuffers(1, &fb2);
    capi_value_query("deleted2", "read_binding", GL_READ_FRAMEBUFFER_BINDING, 1);
    capi_value_query("deleted2", "read_buffer", GL_READ_BUFFER, 1);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glDeleteRenderbuffers(1, &color);
    capi_value_query("deleted", "renderbuffer_binding", GL_RENDERBUFFER_BINDING, 1);
    capi_value("is_renderbuffer.deleted", "%d", glIsRenderbuffer(color));
    glDeleteRenderbuffers(1, &ds);
    glDeleteRenderbuffers(1, &probe);
    glDeleteRenderbuffers(1, &zero);
    glDeleteRenderbuffers(1, &stencil_only);
    glDeleteRenderbuffers(1, &unallocated);
    capi_expect_error(GL_NO_ERROR, "end");
    return capi_finish();
}
