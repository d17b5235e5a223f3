/* Sharing and concurrency: eight contexts created with one share context render eight
 * different scenes at once on eight threads, each with the shared display list, the shared
 * texture and the shared vertex buffer object; every frame must have the bytes the same
 * scene has when the contexts render one after another on one thread (and the pictures are
 * compared with Mesa's). The shared objects' names and contents are seen by every context
 * of the group (GL 2.1 appendix D), and deleting one in one context deletes it for all.
 * Making a context current while it is current on another thread fails on tessera
 * (OSMesaMakeCurrent returns GL_FALSE and the owner keeps rendering correctly); Mesa 22 does
 * not check (printed only). */
#define _POSIX_C_SOURCE 200809L /* pthread barriers under -std=c11 */
#include "common.h"
#include <math.h>
#include <pthread.h>

#define THREADS 8
#define FRAMES 12
#define W 64
#define H 64

static OSMesaContext contexts[THREADS];
static unsigned char sequential[THREADS][W * H * 4];
static GLuint list, texture, vbo;

/* Scene `i`: a clear, the shared textured quad (texture coordinates from the shared buffer
 * object, scaled per scene), then the shared list rotated and colored per scene. */
static void scene(int i)
{
    glViewport(0, 0, W, H);
    glClearColor(i / 8.0f, 0.25f, 1.0f - i / 8.0f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -1, 1);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glScalef(1.013f * (1 + i), 1.029f * (1 + i % 3), 1); /* no texel edge exactly at a pixel centre */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glVertexPointer(2, GL_FLOAT, 4 * sizeof(float), (const void *)0);
    glTexCoordPointer(2, GL_FLOAT, 4 * sizeof(float), (const void *)(2 * sizeof(float)));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glColor3f(1, 1, 1);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDisable(GL_TEXTURE_2D);
    glRotatef(i * 45.0f, 0, 0, 1);
    glColor3f((i & 1) ? 1.0f : 0.0f, (i & 2) ? 1.0f : 0.0f, (i & 4) ? 1.0f : 0.5f);
    glCallList(list);
    glFinish();
}

struct job {
    int index;
    unsigned char pixels[W * H * 4];
    int mismatches;
    GLenum error;
};

static pthread_barrier_t start;

static void *render(void *arg)
{
    struct job *job = arg;
    pthread_barrier_wait(&start);
    if (!OSMesaMakeCurrent(contexts[job->index], job->pixels, GL_UNSIGNED_BYTE, W, H)) {
        job->mismatches = FRAMES;
        return NULL;
    }
    for (int frame = 0; frame < FRAMES; frame++) {
        memset(job->pixels, 0, sizeof job->pixels);
        scene(job->index);
        job->mismatches += memcmp(job->pixels, sequential[job->index], sizeof job->pixels) != 0;
    }
    job->error = glGetError();
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    return NULL;
}

/* The owner thread of the MakeCurrent conflict: binds context 0, waits while the main
 * thread tries to bind it too, renders, and releases it. */
static pthread_barrier_t bound, tried;
static struct job owner_job;

static void *owner(void *arg)
{
    (void)arg;
    int ok = OSMesaMakeCurrent(contexts[0], owner_job.pixels, GL_UNSIGNED_BYTE, W, H);
    pthread_barrier_wait(&bound);
    pthread_barrier_wait(&tried);
    if (ok) {
        scene(0);
        owner_job.mismatches = memcmp(owner_job.pixels, sequential[0], sizeof owner_job.pixels) != 0;
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    }
    return NULL;
}

int main(void)
{
    int tessera = capi_probe_is_tessera();
    static unsigned char base_pixels[W * H * 4];
    OSMesaContext base = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    capi_check(base != NULL && OSMesaMakeCurrent(base, base_pixels, GL_UNSIGNED_BYTE, W, H), "no base context");

    /* The shared objects, made in the share context. */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < 5; k++) {
        float a = k * 1.2566371f;
        glVertex2f(0, 0);
        glVertex2f(0.8f * cosf(a), 0.8f * sinf(a));
        glVertex2f(0.8f * cosf(a + 0.4f), 0.8f * sinf(a + 0.4f));
    }
    glEnd();
    glEndList();
    static unsigned char checker[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        int on = ((i % 8) ^ (i / 8)) & 1;
        checker[4 * i] = on ? 255 : 40;
        checker[4 * i + 1] = on ? 200 : 90;
        checker[4 * i + 2] = (i * 4) & 255;
        checker[4 * i + 3] = 255;
    }
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    static const float quad[] = {-0.9f, -0.9f, 0, 0, 0.9f, -0.9f, 1, 0, 0.9f, 0.9f, 1, 1, -0.9f, 0.9f, 0, 1};
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    capi_expect_error(GL_NO_ERROR, "shared objects");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);

    for (int i = 0; i < THREADS; i++) {
        contexts[i] = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, base);
        capi_check(contexts[i] != NULL, "context %d not created", i);
        if (!contexts[i])
            return capi_finish();
    }

    /* Every context of the group sees the objects; the references, one after another. */
    for (int i = 0; i < THREADS; i++) {
        OSMesaMakeCurrent(contexts[i], sequential[i], GL_UNSIGNED_BYTE, W, H);
        if (i == 3) {
            capi_value("context3.is_list", "%d", glIsList(list));
            capi_value("context3.is_texture", "%d", glIsTexture(texture));
            capi_value("context3.is_buffer", "%d", glIsBuffer(vbo));
            GLint size = 0;
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
            capi_value("context3.buffer_size", "%d", size);
        }
        scene(i);
        capi_expect_error(GL_NO_ERROR, "sequential scene");
        char name[32];
        snprintf(name, sizeof name, "scene%d", i);
        capi_save_image(name, W, H, 4, CAPI_U8, sequential[i]);
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);

    /* All at once. */
    static struct job jobs[THREADS];
    pthread_t threads[THREADS];
    pthread_barrier_init(&start, NULL, THREADS);
    for (int i = 0; i < THREADS; i++) {
        jobs[i].index = i;
        pthread_create(&threads[i], NULL, render, &jobs[i]);
    }
    for (int i = 0; i < THREADS; i++) {
        pthread_join(threads[i], NULL);
        capi_check(jobs[i].mismatches == 0, "thread %d: %d of %d frames differ from the sequential picture", i,
                   jobs[i].mismatches, FRAMES);
        capi_check(jobs[i].error == GL_NO_ERROR, "thread %d: error 0x%x", i, jobs[i].error);
    }
    pthread_barrier_destroy(&start);

    /* MakeCurrent of a context current on another thread. */
    pthread_barrier_init(&bound, NULL, 2);
    pthread_barrier_init(&tried, NULL, 2);
    pthread_t owner_thread;
    pthread_create(&owner_thread, NULL, owner, NULL);
    pthread_barrier_wait(&bound);
    static unsigned char stolen[W * H * 4];
    GLboolean taken = OSMesaMakeCurrent(contexts[0], stolen, GL_UNSIGNED_BYTE, W, H);
    printf("MakeCurrent of a context current on another thread: %d\n", taken);
    if (tessera)
        capi_check(taken == GL_FALSE, "MakeCurrent of a context current on another thread succeeded");
    if (taken)
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    pthread_barrier_wait(&tried);
    pthread_join(owner_thread, NULL);
    if (tessera)
        capi_check(owner_job.mismatches == 0, "the owner's rendering changed after the refused MakeCurrent");
    /* Released by its owner, the context binds here. */
    capi_check(OSMesaMakeCurrent(contexts[0], stolen, GL_UNSIGNED_BYTE, W, H), "released context not bound");

    /* Deleting a shared object in one context deletes it for the group. */
    glDeleteTextures(1, &texture);
    glDeleteBuffers(1, &vbo);
    glDeleteLists(list, 1);
    OSMesaMakeCurrent(contexts[5], stolen, GL_UNSIGNED_BYTE, W, H);
    capi_value("context5.after_delete", "list %d texture %d buffer %d", glIsList(list), glIsTexture(texture),
               glIsBuffer(vbo));
    /* New names from one context are new for the others too. */
    GLuint fresh;
    glGenTextures(1, &fresh);
    glBindTexture(GL_TEXTURE_2D, fresh);
    OSMesaMakeCurrent(contexts[6], stolen, GL_UNSIGNED_BYTE, W, H);
    capi_value("context6.fresh_is_texture", "%d", glIsTexture(fresh));
    GLuint other;
    glGenTextures(1, &other);
    capi_check(other != fresh, "two contexts of a share group got the same new texture name %u", other);
    capi_expect_error(GL_NO_ERROR, "after deletion");

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    for (int i = 0; i < THREADS; i++)
        OSMesaDestroyContext(contexts[i]);
    OSMesaDestroyContext(base);
    return capi_finish();
}
