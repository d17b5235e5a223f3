/* GL_DEPTH_CLAMP (ARB_depth_clamp) and GL_POLYGON_OFFSET_CLAMP (EXT_polygon_offset_clamp),
 * compared with Mesa through the depth buffer they leave:
 *  - with depth clamping, geometry beyond the near and far planes is not clipped and its
 *    fragment depths are clamped to the depth range (normal and reversed, and glDepthRange
 *    narrower than [0, 1]); without it the same geometry is clipped;
 *  - glPolygonOffsetClampEXT bounds the offset of a steep triangle from above (positive
 *    clamp) and from below (negative clamp); 0 leaves it unbounded; it applies to
 *    GL_POLYGON_OFFSET_LINE outlines too. */
#include "common.h"

#define W 32
#define H 32

static void save_depth(const char *name)
{
    static GLfloat depth[W * H];
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    capi_save_image(name, W, H, 1, CAPI_F32, depth);
}

/* A triangle crossing both the near plane (z = -3) and the far plane (z = 3), and a quad
 * wholly in front of the near plane. */
static void beyond_near_and_far(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(-0.9f, -0.9f, -3);
    glVertex3f(0.9f, -0.7f, 3);
    glVertex3f(0, 0.9f, 0.2f);
    glColor3f(0, 1, 0);
    glEnd();
    glBegin(GL_QUADS);
    glVertex3f(-1, 0.6f, -2);
    glVertex3f(-0.5f, 0.6f, -2);
    glVertex3f(-0.5f, 1, -2);
    glVertex3f(-1, 1, -2);
    glEnd();
}

static void steep_triangle(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.9f, -0.9f, -0.5f);
    glVertex3f(0.9f, -0.8f, 0.5f);
    glVertex3f(-0.2f, 0.9f, 0.1f);
    glEnd();
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    /* libOSMesa exports no extension entry points: reached as programs do. */
    PFNGLPOLYGONOFFSETCLAMPEXTPROC glPolygonOffsetClampEXT =
        (PFNGLPOLYGONOFFSETCLAMPEXTPROC)OSMesaGetProcAddress("glPolygonOffsetClampEXT");
    capi_check(glPolygonOffsetClampEXT != NULL, "glPolygonOffsetClampEXT");
    if (!glPolygonOffsetClampEXT)
        return capi_finish();
    const char *extensions = (const char *)glGetString(GL_EXTENSIONS);
    capi_check(strstr(extensions, "GL_ARB_depth_clamp") != NULL, "GL_ARB_depth_clamp listed");
    capi_check(strstr(extensions, "GL_EXT_polygon_offset_clamp") != NULL, "GL_EXT_polygon_offset_clamp listed");
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glClearDepth(0.5);

    capi_value_query("initial", "depth_clamp", GL_DEPTH_CLAMP, 1);
    beyond_near_and_far();
    save_depth("unclamped_depth");
    capi_save_framebuffer("unclamped_color", W, H);

    glEnable(GL_DEPTH_CLAMP);
    capi_value_query("enabled", "depth_clamp", GL_DEPTH_CLAMP, 1);
    capi_check(glIsEnabled(GL_DEPTH_CLAMP), "glIsEnabled(GL_DEPTH_CLAMP)");
    beyond_near_and_far();
    save_depth("clamped_depth");
    capi_save_framebuffer("clamped_color", W, H);

    glDepthRange(0.25, 0.75);
    beyond_near_and_far();
    save_depth("clamped_range");
    glDepthRange(0.8, 0.3); /* reversed: clamped to [0.3, 0.8] */
    beyond_near_and_far();
    save_depth("clamped_reversed");
    glDisable(GL_DEPTH_CLAMP);
    beyond_near_and_far();
    save_depth("unclamped_reversed");
    glDepthRange(0, 1);
    capi_expect_error(GL_NO_ERROR, "depth clamp");

    steep_triangle();
    save_depth("no_offset");
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffsetClampEXT(8, 4, 0.01f);
    capi_value_query("offset", "clamp", GL_POLYGON_OFFSET_CLAMP_EXT, 1);
    steep_triangle();
    save_depth("offset_clamp_positive");
    glPolygonOffsetClampEXT(-8, -4, -0.01f);
    steep_triangle();
    save_depth("offset_clamp_negative");
    glPolygonOffsetClampEXT(-8, -4, 0.5f); /* the offset is negative: a positive clamp does nothing */
    steep_triangle();
    save_depth("offset_clamp_other_sign");
    glPolygonOffsetClampEXT(8, 4, 0);
    steep_triangle();
    save_depth("offset_clamp_zero");
    glPolygonOffset(8, 4); /* resets the clamp to 0 */
    capi_value_query("reset", "clamp", GL_POLYGON_OFFSET_CLAMP_EXT, 1);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glPolygonOffsetClampEXT(8, 4, 0.005f);
    steep_triangle();
    save_depth("offset_clamp_line");
    capi_expect_error(GL_NO_ERROR, "offset clamp");
    return capi_finish();
}
