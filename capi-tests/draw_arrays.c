/* The same mesh drawn from every vertex source must give the same picture: immediate
 * mode, client arrays (glDrawArrays, glDrawElements with every index type,
 * glDrawRangeElements, glMultiDrawElements, glArrayElement, glInterleavedArrays) and
 * vertex buffer objects (for vertices and for indices). */
#include "common.h"
#include <math.h>

#define W 64
#define H 64
#define N 10 /* grid of N x N quads */

static GLfloat pos[(N + 1) * (N + 1)][3];
static GLubyte col[(N + 1) * (N + 1)][4];
static GLuint idx32[N * N * 6];
static GLushort idx16[N * N * 6];
static GLubyte idx8[N * N * 6];
static unsigned char reference[W * H * 4], pixels[W * H * 4];

static void build(void)
{
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            int k = j * (N + 1) + i;
            pos[k][0] = 2.1f + i * 6.0f + 1.3f * sinf(j * 0.7f);
            pos[k][1] = 1.7f + j * 6.0f + 1.1f * cosf(i * 0.9f);
            pos[k][2] = 0;
            col[k][0] = (GLubyte)(i * 25);
            col[k][1] = (GLubyte)(j * 25);
            col[k][2] = (GLubyte)((i * j) % 256);
            col[k][3] = 255;
        }
    int n = 0;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int a = j * (N + 1) + i, b = a + 1, c = a + N + 2, d = a + N + 1;
            int tri[6] = {a, b, c, a, c, d};
            for (int t = 0; t < 6; t++, n++)
                idx32[n] = idx16[n] = idx8[n] = (GLubyte)tri[t], idx32[n] = tri[t], idx16[n] = (GLushort)tri[t];
        }
}

static void grab(const char *name, int compare)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, compare ? pixels : reference);
    if (compare)
        capi_check(memcmp(pixels, reference, sizeof pixels) == 0, "%s differs from immediate mode", name);
    else
        capi_save_image(name, W, H, 4, CAPI_U8, reference);
    glClear(GL_COLOR_BUFFER_BIT);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    build();
    glClear(GL_COLOR_BUFFER_BIT);

    glBegin(GL_TRIANGLES);
    for (int n = 0; n < N * N * 6; n++) {
        glColor4ubv(col[idx32[n]]);
        glVertex3fv(pos[idx32[n]]);
    }
    glEnd();
    grab("mesh", 0);

    glVertexPointer(3, GL_FLOAT, 0, pos);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawElements(GL_TRIANGLES, N * N * 6, GL_UNSIGNED_INT, idx32);
    grab("elements_uint", 1);
    glDrawElements(GL_TRIANGLES, N * N * 6, GL_UNSIGNED_SHORT, idx16);
    grab("elements_ushort", 1);
    glDrawElements(GL_TRIANGLES, N * N * 6, GL_UNSIGNED_BYTE, idx8);
    grab("elements_ubyte", 1);
    glDrawRangeElements(GL_TRIANGLES, 0, (N + 1) * (N + 1) - 1, N * N * 6, GL_UNSIGNED_INT, idx32);
    grab("range_elements", 1);
    GLsizei counts[2] = {N * N * 3, N * N * 3};
    const GLvoid *starts[2] = {idx32, idx32 + N * N * 3};
    glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_INT, starts, 2);
    grab("multi_draw_elements", 1);
    glBegin(GL_TRIANGLES);
    for (int n = 0; n < N * N * 6; n++)
        glArrayElement(idx32[n]);
    glEnd();
    grab("array_element", 1);

    /* Expanded, non-indexed copy for glDrawArrays and glInterleavedArrays (GL_C4UB_V3F). */
    static struct { GLubyte c[4]; GLfloat v[3]; } interleaved[N * N * 6];
    static GLfloat flat_pos[N * N * 6][3];
    static GLubyte flat_col[N * N * 6][4];
    for (int n = 0; n < N * N * 6; n++) {
        memcpy(interleaved[n].c, col[idx32[n]], 4);
        memcpy(interleaved[n].v, pos[idx32[n]], 12);
        memcpy(flat_pos[n], pos[idx32[n]], 12);
        memcpy(flat_col[n], col[idx32[n]], 4);
    }
    glVertexPointer(3, GL_FLOAT, 0, flat_pos);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, flat_col);
    glDrawArrays(GL_TRIANGLES, 0, N * N * 6);
    grab("draw_arrays", 1);
    glInterleavedArrays(GL_C4UB_V3F, 0, interleaved);
    glDrawArrays(GL_TRIANGLES, 0, N * N * 6);
    grab("interleaved", 1);

    /* Buffer objects for the vertices and the indices. */
    GLuint buffers[3];
    glGenBuffers(3, buffers);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof pos, pos, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, 0, (const GLvoid *)0);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ARRAY_BUFFER, sizeof col, col, GL_STATIC_DRAW);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, (const GLvoid *)0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx16, idx16, GL_STATIC_DRAW);
    glDrawElements(GL_TRIANGLES, N * N * 6, GL_UNSIGNED_SHORT, (const GLvoid *)0);
    grab("vbo_elements", 1);
    glDeleteBuffers(3, buffers);
    capi_check(glGetError() == GL_NO_ERROR, "no GL error");
    return capi_finish();
}
