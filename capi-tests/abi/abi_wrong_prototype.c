/* Must FAIL to compile (tests/capi.rs checks the message): a prototype that differs from
 * tessera.h's (glClearStencil takes a GLint) is a conflicting declaration. */
void glClearStencil(unsigned int s);
#include "tessera.h"
