/* Multisampled renderbuffers resolved by glBlitFramebuffer: sample counts and completeness,
 * triangle edges at the 4-sample positions (a fan of thin triangles at many slopes, a depth
 * intersection tested per sample), GL_SAMPLE_COVERAGE and GL_SAMPLE_ALPHA_TO_COVERAGE
 * masks, GL_MULTISAMPLE disabled (pixel centres decide for every sample), lines and points
 * of several widths covering the samples of their rectangles and squares (unrounded widths,
 * as llvmpipe), and the errors of resolving blits. The pictures are read back from the single-sample resolve target. */
#include "common.h"
#include <math.h>

#define W 48
#define H 40

static GLuint renderbuffer(GLsizei samples, GLenum format)
{
    GLuint rb;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, W, H);
    return rb;
}

static GLuint framebuffer(GLuint color, GLuint depth_stencil)
{
    GLuint fb;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    if (depth_stencil) {
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_stencil);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_stencil);
    }
    return fb;
}

/* Resolves `ms` into `resolved` and saves it as `name`. */
static void resolve(GLuint ms, GLuint resolved, const char *name)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_NO_ERROR, "resolving blit");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved);
    static GLubyte px[W * H * 4];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_save_image(name, W, H, 4, CAPI_U8, px);
    glBindFramebuffer(GL_FRAMEBUFFER, ms);
}

static void clear(void)
{
    glClearColor(0, 0, 0, 0);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
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

    /* Sample counts: 4 is offered as is; any request gets at least what it asked for. */
    GLuint color = renderbuffer(4, GL_RGBA8);
    GLint samples = -1;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
    capi_value("rb_samples_4", "%d", samples);
    GLuint ds = renderbuffer(4, GL_DEPTH24_STENCIL8);
    GLuint two = renderbuffer(2, GL_RGBA8);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
    capi_check(samples >= 2, "2 samples requested, %d given", samples);
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    capi_check(max_samples >= 4, "GL_MAX_SAMPLES %d", max_samples);

    /* All attachments must have the same number of samples. */
    GLuint single = renderbuffer(0, GL_DEPTH24_STENCIL8);
    GLuint mixed = framebuffer(color, single);
    capi_value("mixed_status", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glDeleteFramebuffers(1, &mixed);
    (void)two;

    GLuint ms = framebuffer(color, ds);
    capi_value("ms_status", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    capi_value_query("ms", "sample_buffers", GL_SAMPLE_BUFFERS, 1);
    capi_value_query("ms", "samples", GL_SAMPLES, 1);
    GLuint target_rb;
    glGenRenderbuffers(1, &target_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, target_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H);
    GLuint resolved = framebuffer(target_rb, 0);
    capi_value_query("resolved", "sample_buffers", GL_SAMPLE_BUFFERS, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, ms);

    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);

    /* A fan of thin triangles at many slopes, and two crossing planes (depth per sample). */
    clear();
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 12; i++) {
        float a = 0.13f + i * 0.125f, b = a + 0.05f;
        glColor3f(1.0f, i / 12.0f, 0.5f);
        glVertex3f(12.3f, 20.1f, 0);
        glVertex3f(12.3f + 11.0f * cosf(a), 20.1f + 18.0f * sinf(a), 0);
        glVertex3f(12.3f + 11.0f * cosf(b), 20.1f + 18.0f * sinf(b), 0);
    }
    glColor3f(0, 0.8f, 0.2f);
    glVertex3f(26.2f, 3.3f, -0.9f);
    glVertex3f(46.7f, 5.1f, 0.9f);
    glVertex3f(30.4f, 37.6f, 0.9f);
    glColor3f(0.2f, 0.3f, 1.0f);
    glVertex3f(45.9f, 2.6f, -0.9f);
    glVertex3f(44.1f, 36.8f, -0.9f);
    glVertex3f(25.3f, 21.7f, 0.9f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    resolve(ms, resolved, "edges");

    /* GL_SAMPLE_COVERAGE: half of the samples, then the other half in another color. */
    clear();
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0.5f, GL_FALSE);
    glColor3f(1, 0, 0);
    quad(2, 2, 30, 30, 0);
    glSampleCoverage(0.5f, GL_TRUE);
    glColor3f(0, 0, 1);
    quad(10, 10, 46, 38, 0);
    glDisable(GL_SAMPLE_COVERAGE);
    GLfloat value = 0;
    GLboolean invert = 0;
    glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &value);
    glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &invert);
    capi_value("coverage", "%g %d", value, invert);
    resolve(ms, resolved, "sample_coverage");

    /* GL_SAMPLE_ALPHA_TO_COVERAGE: alpha 0.3 covers 2 of 4 samples (alpha > s/4), 0.8 all
     * but one... then GL_SAMPLE_ALPHA_TO_ONE. */
    clear();
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glColor4f(1, 1, 1, 0.3f);
    quad(2, 2, 22, 38, 0);
    glColor4f(1, 1, 0, 0.8f);
    quad(24, 2, 46, 18, 0);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    glColor4f(0, 1, 1, 0.6f);
    quad(24, 20, 46, 38, 0);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    resolve(ms, resolved, "alpha_to_coverage");

    /* GL_MULTISAMPLE disabled: every sample of a pixel whose centre is covered. */
    clear();
    glDisable(GL_MULTISAMPLE);
    glColor3f(1, 1, 1);
    glBegin(GL_TRIANGLES);
    glVertex2f(3.3f, 2.2f);
    glVertex2f(44.6f, 9.1f);
    glVertex2f(17.8f, 37.4f);
    glEnd();
    glEnable(GL_MULTISAMPLE);
    resolve(ms, resolved, "multisample_disabled");

    /* Lines (several widths and slopes, smooth-shaded, one through a depth-tested plane) and
     * points (several sizes, off-centre) cover the samples of their rectangles and squares. */
    clear();
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.3f, 0.3f, 0.3f);
    quad(0, 20, W, 40, 0);
    const float widths[] = {1.0f, 1.5f, 2.5f, 4.0f, 0.5f};
    for (int i = 0; i < 5; i++) {
        glLineWidth(widths[i]);
        glBegin(GL_LINES);
        glColor3f(1, 0.2f * i, 0);
        glVertex3f(2.3f + i * 0.17f, 3.2f + i * 3.4f, -0.5f);
        glColor3f(0, 0.2f * i, 1);
        glVertex3f(22.6f, 5.7f + i * 4.1f, 0.5f);
        glColor3f(0, 1, 0.2f * i);
        glVertex3f(25.1f + i * 4.3f, 1.4f, -0.5f);
        glColor3f(1, 1, 0.2f * i);
        glVertex3f(27.4f + i * 4.1f, 18.9f - i * 0.3f, 0.5f);
        glEnd();
    }
    glLineWidth(1);
    const float sizes[] = {1.0f, 2.5f, 3.0f, 5.5f, 8.0f};
    for (int i = 0; i < 5; i++) {
        glPointSize(sizes[i]);
        glColor3f(0.2f * i, 1, 1);
        glBegin(GL_POINTS);
        glVertex3f(4.3f + i * 9.1f, 25.2f + i * 0.37f, -0.5f);
        glVertex3f(6.5f + i * 8.7f, 34.5f, 0.5f);
        glEnd();
    }
    /* GL_POINT_SMOOTH changes nothing on a multisampled target in Mesa 22 (its square). */
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor3f(1, 0.5f, 1);
    glPointSize(3.5f);
    glBegin(GL_POINTS);
    glVertex3f(12.3f, 30.2f, 0.5f);
    glEnd();
    glPointSize(6.0f);
    glBegin(GL_POINTS);
    glVertex3f(30.6f, 29.7f, 0.5f);
    glEnd();
    glDisable(GL_BLEND);
    glDisable(GL_POINT_SMOOTH);
    glPointSize(1);
    glDisable(GL_DEPTH_TEST);
    resolve(ms, resolved, "lines_points");

    /* Resolving blits: same size only, never into a multisampled framebuffer. */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W / 2, H / 2, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    capi_expect_error(GL_INVALID_OPERATION, "scaled resolve");
    /* ARB_framebuffer_object (what GL 2.1 programs get) refuses a blit into a multisampled
     * framebuffer; Mesa 22's 4.5 context follows GL 4.5, which allows it. */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ms);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (capi_is_tessera())
        capi_check(glGetError() == GL_INVALID_OPERATION, "blit into a multisampled framebuffer");
    else
        (void)glGetError();
    /* Pixels of a multisampled framebuffer object are read through a resolve only. */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms);
    GLubyte px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    capi_expect_error(GL_INVALID_OPERATION, "glReadPixels of a multisampled framebuffer");
    return capi_finish();
}
