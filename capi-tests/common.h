/* Shared helpers of the capi tests.
 *
 * Every capi test is a standalone C program built once against the system's Mesa headers
 * (-lOSMesa) and run twice by tests/capi.rs: on Mesa and on tessera (LD_LIBRARY_PATH).
 *  - capi_check(): an assertion that must hold on every implementation; a failure makes the
 *    program exit non-zero.
 *  - capi_value(): a value that must be identical on Mesa and on tessera; the runner compares
 *    the VALUE lines of the two runs (unless the manifest allows a difference).
 *  - capi_save_image(): an image the runner compares between the two runs with the
 *    thresholds of capi-tests/manifest.txt (default: exact).
 * Behaviour where tessera deliberately differs from Mesa 22 is branched on capi_is_tessera().
 */
#ifndef CAPI_COMMON_H
#define CAPI_COMMON_H

/* Declare the GL 1.2+ entry points too: tests call them directly, as legacy programs do. */
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Component types of saved images. */
enum capi_type { CAPI_U8 = 1, CAPI_U16 = 2, CAPI_F32 = 4 };

/* Nonzero when GL_RENDERER starts with "tessera" (needs a current context). */
int capi_is_tessera(void);

/* As capi_is_tessera(), but needs no current context: it binds a temporary 1x1 context to
 * find out (once; the answer is cached). Call it while no context of the test is current:
 * it leaves no context current. For guarding calls that crash Mesa 22 without a context. */
int capi_probe_is_tessera(void);

/* Records a failed assertion (printed as "FAIL file:line: message") when cond is false. */
#define capi_check(cond, ...) capi_check_at((cond), __FILE__, __LINE__, __VA_ARGS__)
void capi_check_at(int cond, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* Prints "VALUE <key> <formatted value>": compared between Mesa and tessera. */
void capi_value(const char *key, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Queries pname (count values, at most 16) with glGetBooleanv/Integerv/Floatv/Doublev and
 * prints all four as one VALUE line keyed "<stage>.<name>" (floats as %a, bit for bit). */
void capi_value_query(const char *stage, const char *name, GLenum pname, int count);

/* Checks glGetError() == expected (an assertion) and prints it as a VALUE. */
#define capi_expect_error(expected, what) capi_expect_error_at((expected), (what), __FILE__, __LINE__)
void capi_expect_error_at(GLenum expected, const char *what, const char *file, int line);

/* Saves an image for comparison: w x h pixels of `channels` components of `type`, rows
 * bottom-up as glReadPixels returns them, tightly packed. Written to $CAPI_OUT/<name>.img. */
void capi_save_image(const char *name, int w, int h, int channels, enum capi_type type, const void *data);

/* Reads the current read buffer (RGBA, GL_UNSIGNED_BYTE, pack alignment 1) and saves it. */
void capi_save_framebuffer(const char *name, int w, int h);

/* Creates an RGBA/UNSIGNED_BYTE context with the given depth/stencil/accum bits, binds a
 * w x h buffer (owned by the helper) and returns the context; aborts the test on failure. */
OSMesaContext capi_make_context(GLenum format, GLenum type, int depth, int stencil, int accum,
                                int w, int h, void **buffer_out);

/* Pixel coordinates for drawing: the viewport is the w x h window, the projection
 * glOrtho(0, w, 0, h, -1, 1), the modelview identity (left current). */
void capi_pixel_ortho(int w, int h);

/* GLSL helpers for tests whose shaders must compile and link (a failure is a failed
 * capi_check carrying `key` and the info log). Tests of compile or link failures query
 * the status themselves.
 *  - capi_compile_shader(): a compiled shader of `type`.
 *  - capi_program_with(): a new program with the shaders of `vs` and `fs` attached (either
 *    may be NULL) and already flagged for deletion, so the caller can bind attribute
 *    locations before capi_link_program().
 *  - capi_link_program(): links `program` and checks its status.
 *  - capi_program(): capi_program_with() then capi_link_program(). */
GLuint capi_compile_shader(GLenum type, const char *key, const char *source);
GLuint capi_program_with(const char *key, const char *vs, const char *fs);
void capi_link_program(const char *key, GLuint program);
GLuint capi_program(const char *key, const char *vs, const char *fs);

/* A line of /proc/self/status in MiB (e.g. "VmRSS:" or "VmHWM:", the peak); -1 when absent. */
long capi_status_mib(const char *key);

/* Exit status: 0 when every capi_check held. Call last in main(). */
int capi_finish(void);

#endif
