/* A program built with tessera's own headers (gcc -I include, so <GL/gl.h> is
 * include/GL/gl.h) and linked with -L target/release -l:libOSMesa.so.8: it must build
 * without the system headers and run on tessera. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef TESSERA_GL_H
#error "expected tessera's headers (include/GL), got the system's"
#endif

int main(void)
{
    static unsigned char pixels[4 * 3 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 4, 3)) {
        printf("FAIL cannot create and bind a context\n");
        return 1;
    }
    const char *renderer = (const char *)glGetString(GL_RENDERER);
    if (!renderer || strncmp(renderer, "tessera", 7) != 0) {
        printf("FAIL GL_RENDERER is %s, not tessera\n", renderer ? renderer : "(null)");
        return 1;
    }
    glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    const unsigned char green[4] = {0, 255, 0, 255};
    for (int i = 0; i < 4 * 3; i++) {
        if (memcmp(pixels + 4 * i, green, 4) != 0) {
            printf("FAIL pixel %d is %02x%02x%02x%02x\n", i, pixels[4 * i], pixels[4 * i + 1], pixels[4 * i + 2],
                   pixels[4 * i + 3]);
            return 1;
        }
    }
    if (glGetError() != GL_NO_ERROR) {
        printf("FAIL unexpected GL error\n");
        return 1;
    }
    /* tessera's own extension: the accuracy mode (TESSERA_ACCURACY unset: conformant). */
    const char *env_mode = getenv("TESSERA_ACCURACY");
    if (!env_mode && tesseraGetAccuracy() != TESSERA_ACCURACY_CONFORMANT) {
        printf("FAIL default accuracy is %d\n", tesseraGetAccuracy());
        return 1;
    }
    tesseraSetAccuracy(TESSERA_ACCURACY_EXACT);
    tesseraSetAccuracy(42);
    if (tesseraGetAccuracy() != TESSERA_ACCURACY_EXACT || glGetError() != GL_INVALID_ENUM) {
        printf("FAIL tesseraSetAccuracy: mode %d\n", tesseraGetAccuracy());
        return 1;
    }
    tesseraSetAccuracy(TESSERA_ACCURACY_FAST);
    if (tesseraGetAccuracy() != TESSERA_ACCURACY_FAST || glGetError() != GL_NO_ERROR) {
        printf("FAIL tesseraSetAccuracy(TESSERA_ACCURACY_FAST)\n");
        return 1;
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    printf("ok: %s\n", renderer);
    return 0;
}
