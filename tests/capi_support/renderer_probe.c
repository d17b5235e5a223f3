/* Prints GL_RENDERER of the OSMesa implementation the loader picked: tests/capi.rs runs it
 * on both sides first, to prove that the environment selects Mesa and tessera as intended. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>

int main(void)
{
    static unsigned char pixel[4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixel, GL_UNSIGNED_BYTE, 1, 1))
        return 1;
    const GLubyte *renderer = glGetString(GL_RENDERER);
    printf("%s\n", renderer ? (const char *)renderer : "(null)");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return 0;
}
