/* The ABI check (compiled by tests/capi.rs with gcc -std=c11 -Wall -Wextra -Werror -c).
 *
 * Mesa's headers first, with every extension prototype visible, then tessera's generated
 * header. Each #define of tessera.h is wrapped as
 *     #if !defined(NAME) ... #elif (NAME) != (value) #error ... #endif
 * so a constant whose value differs from the system headers stops the compilation, and a
 * prototype that differs from Mesa's is a "conflicting types" error. tessera.h is found
 * through -iquote include/GL, so <GL/...> still means the system headers here.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "tessera.h"

/* Including it twice must be harmless too. */
#include "tessera.h"
