/* GLX share contexts share texture and buffer objects (names and contents), not only display
 * lists (GL 2.1 appendix D). Context A (glXCreateNewContext, no share context) makes a 2x2
 * texture of four colours and a vertex buffer with a textured quad covering the left half of
 * the viewport; contexts created with A (or with a context of A's group) as share context,
 * through glXCreateContext, glXCreateNewContext and glXCreateContextAttribsARB, draw with
 * them into a window and read the window back: the quad is on the left half only (the
 * vertices arrived) and shows the four texels (the texels arrived). A texel changed in one
 * context is seen by glGetTexImage in another. A context created without a share context
 * does not see the names (glIsTexture/glIsBuffer false, glIsList false). Deleting the
 * objects in one context deletes the names for the whole group (glIsTexture false in A).
 * Run by tools/xvfb-tests.sh on tessera; it passes on Mesa 22 (llvmpipe) as well.
 * Prints one line per failed check; exit status 0 when all hold.
 *
 * Build: gcc -std=c11 -O1 -Wall tests/glx/share_objects.c -lGL -lX11 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

enum { W = 32, H = 32 };

/* The texture's four texels, bottom row first: red, green / blue, white */
static const unsigned char texels[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};

/* The quad in the buffer: x, y, s, t per vertex, covering the left half (x from -1 to 0) */
static const float quad[4][4] = {{-1, -1, 0, 0}, {0, -1, 1, 0}, {0, 1, 1, 1}, {-1, 1, 0, 1}};

static GLuint tex, vbo, list;

/* Draws the shared quad with the shared texture into the current (window) drawable and
 * checks what arrived: the texels on the left half, the clear colour on the right. */
static void draw_and_check(const char *who)
{
    CHECK(glIsTexture(tex), "%s: glIsTexture(%u) false in a sharing context", who, tex);
    CHECK(glIsBuffer(vbo), "%s: glIsBuffer(%u) false in a sharing context", who, vbo);
    CHECK(glIsList(list), "%s: glIsList(%u) false in a sharing context", who, list);
    glViewport(0, 0, W, H);
    glClearColor(0.5f, 0.5f, 0.5f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, sizeof quad[0], (const void *)0);
    glTexCoordPointer(2, GL_FLOAT, sizeof quad[0], (const void *)(2 * sizeof(float)));
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDisable(GL_TEXTURE_2D);
    CHECK(glGetError() == GL_NO_ERROR, "%s: GL error while drawing", who);

    unsigned char px[H][W][4];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    /* The quad is 16x32 pixels; each texel covers an 8x16 block. Sample the block centres. */
    const int at[4][2] = {{4, 8}, {12, 8}, {4, 24}, {12, 24}};
    for (int i = 0; i < 4; i++) {
        const unsigned char *p = px[at[i][1]][at[i][0]];
        CHECK(memcmp(p, texels[i], 4) == 0, "%s: texel %d at (%d,%d) is %d,%d,%d,%d", who, i, at[i][0], at[i][1],
              p[0], p[1], p[2], p[3]);
    }
    /* The right half was not covered by the quad's vertices */
    const int clear_at[2][2] = {{20, 8}, {28, 24}};
    for (int i = 0; i < 2; i++) {
        const unsigned char *p = px[clear_at[i][1]][clear_at[i][0]];
        CHECK(p[0] >= 127 && p[0] <= 128 && p[1] >= 127 && p[1] <= 128 && p[2] >= 127 && p[2] <= 128,
              "%s: (%d,%d) should keep the clear colour, is %d,%d,%d", who, clear_at[i][0], clear_at[i][1], p[0], p[1],
              p[2]);
    }
}

int main(void)
{
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("cannot open display\n");
        return 2;
    }
    int screen = DefaultScreen(dpy), count = 0;
    int attribs[] = {GLX_DOUBLEBUFFER, True, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8,
                     GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT | GLX_PBUFFER_BIT, None};
    GLXFBConfig *configs = glXChooseFBConfig(dpy, screen, attribs, &count);
    if (!configs) {
        printf("FAIL: no config\n");
        return 1;
    }
    GLXFBConfig config = configs[0];
    XFree(configs);
    XVisualInfo *vis = glXGetVisualFromFBConfig(dpy, config);
    XSetWindowAttributes swa = {0};
    swa.colormap = XCreateColormap(dpy, RootWindow(dpy, screen), vis->visual, AllocNone);
    Window win = XCreateWindow(dpy, RootWindow(dpy, screen), 0, 0, W, H, 0, vis->depth, InputOutput, vis->visual,
                               CWColormap, &swa);
    XMapWindow(dpy, win);
    int pb_attribs[] = {GLX_PBUFFER_WIDTH, 8, GLX_PBUFFER_HEIGHT, 8, None};
    GLXPbuffer pb = glXCreatePbuffer(dpy, config, pb_attribs);
    XSync(dpy, False);

    PFNGLXCREATECONTEXTATTRIBSARBPROC create_attribs =
        (PFNGLXCREATECONTEXTATTRIBSARBPROC)glXGetProcAddressARB((const GLubyte *)"glXCreateContextAttribsARB");
    GLXContext a = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, NULL, True);
    GLXContext b = glXCreateContext(dpy, vis, a, True);
    GLXContext c = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, a, True);
    int version[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 3, None};
    GLXContext d = create_attribs ? create_attribs(dpy, config, a, True, version) : NULL;
    GLXContext e = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, b, True); /* shares through B */
    GLXContext alone = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, NULL, True);
    if (!a || !b || !c || !d || !e || !alone || !pb) {
        printf("FAIL: contexts %p %p %p %p %p %p, pbuffer %lu\n", (void *)a, (void *)b, (void *)c, (void *)d,
               (void *)e, (void *)alone, (unsigned long)pb);
        return 1;
    }

    /* A makes the objects (on a pbuffer: no drawing of its own) */
    CHECK(glXMakeContextCurrent(dpy, pb, pb, a), "make A current");
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glEndList();
    glFinish();
    CHECK(glGetError() == GL_NO_ERROR, "A: GL error while making the objects");

    /* Each sharing context draws with them into the window */
    const struct {
        GLXContext ctx;
        const char *who;
    } sharing[] = {{b, "glXCreateContext(share A)"},
                   {c, "glXCreateNewContext(share A)"},
                   {d, "glXCreateContextAttribsARB(1.3, share A)"},
                   {e, "glXCreateNewContext(share B)"}};
    for (size_t i = 0; i < sizeof sharing / sizeof *sharing; i++) {
        CHECK(glXMakeCurrent(dpy, win, sharing[i].ctx), "make %s current", sharing[i].who);
        draw_and_check(sharing[i].who);
        glXSwapBuffers(dpy, win);
    }

    /* Contents are shared: a texel and a vertex changed in E are seen in A */
    CHECK(glXMakeCurrent(dpy, win, e), "make E current");
    const unsigned char yellow[4] = {255, 255, 0, 255};
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, yellow);
    glBindTexture(GL_TEXTURE_2D, 0);
    const float moved = 0.5f;
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof(float), sizeof moved, &moved);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glFinish();
    CHECK(glXMakeContextCurrent(dpy, pb, pb, a), "make A current again");
    unsigned char got[4][4];
    glBindTexture(GL_TEXTURE_2D, tex);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
    glBindTexture(GL_TEXTURE_2D, 0);
    CHECK(memcmp(got[3], yellow, 4) == 0 && memcmp(got[0], texels[0], 4) == 0,
          "A does not see E's glTexSubImage2D: %d,%d,%d,%d", got[3][0], got[3][1], got[3][2], got[3][3]);
    float first[4] = {0};
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, sizeof first, first);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    CHECK(first[0] == -1 && first[1] == moved, "A does not see E's glBufferSubData: %g %g", first[0], first[1]);

    /* A context of its own share group sees none of the names */
    CHECK(glXMakeCurrent(dpy, win, alone), "make the unshared context current");
    CHECK(!glIsTexture(tex), "glIsTexture(%u) true in a context that does not share", tex);
    CHECK(!glIsBuffer(vbo), "glIsBuffer(%u) true in a context that does not share", vbo);
    CHECK(!glIsList(list), "glIsList(%u) true in a context that does not share", list);

    /* Deleting in C deletes the names for the group: A and E no longer see them */
    CHECK(glXMakeCurrent(dpy, win, c), "make C current");
    glDeleteTextures(1, &tex);
    glDeleteBuffers(1, &vbo);
    glDeleteLists(list, 1);
    glFinish();
    const GLXContext others[2] = {a, e};
    for (int i = 0; i < 2; i++) {
        CHECK(glXMakeContextCurrent(dpy, pb, pb, others[i]), "make %c current", "AE"[i]);
        CHECK(!glIsTexture(tex), "%c: texture %u still exists after C deleted it", "AE"[i], tex);
        CHECK(!glIsBuffer(vbo), "%c: buffer %u still exists after C deleted it", "AE"[i], vbo);
        CHECK(!glIsList(list), "%c: list %u still exists after C deleted it", "AE"[i], list);
    }

    glXMakeContextCurrent(dpy, None, None, NULL);
    GLXContext all[] = {a, b, c, d, e, alone};
    for (size_t i = 0; i < sizeof all / sizeof *all; i++)
        glXDestroyContext(dpy, all[i]);
    glXDestroyPbuffer(dpy, pb);
    XDestroyWindow(dpy, win);
    XFree(vis);
    XCloseDisplay(dpy);
    printf("share_objects: %s (%d failures)\n", failures ? "FAILED" : "ok", failures);
    return failures ? 1 : 0;
}
