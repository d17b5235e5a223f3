/* Draws three quads with different fragment states (plain, depth-tested, alpha-tested and
 * blended) and the first one again, for the TESSERA_DEBUG=pipeline test in tests/capi.rs. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdlib.h>

static void quad(void)
{
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
}

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    void *buffer = calloc(16 * 16, 4);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 16, 16))
        return 2;
    quad();
    glEnable(GL_DEPTH_TEST);
    quad();
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    quad();
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    quad();
    glFinish();
    OSMesaDestroyContext(ctx);
    free(buffer);
    return glGetError() == GL_NO_ERROR ? 0 : 1;
}
