/* Must FAIL to compile (tests/capi.rs checks the message): a constant defined with a value
 * other than tessera.h's is reported by tessera.h's guard. GL_DEPTH_TEST is 0x0B71. */
#define GL_DEPTH_TEST 0x0B72
#include "tessera.h"
