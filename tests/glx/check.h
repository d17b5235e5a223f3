/* The check of the GLX test programs: CHECK(cond, fmt, ...) prints "FAIL line N: ..." and
 * counts a failure when cond does not hold; a program exits non-zero when `failures` > 0. */
#ifndef TESSERA_GLX_CHECK_H
#define TESSERA_GLX_CHECK_H
#include <stdio.h>

static int failures;
#define CHECK(cond, ...)                                                                                               \
    do {                                                                                                               \
        if (!(cond)) {                                                                                                 \
            printf("FAIL line %d: ", __LINE__);                                                                        \
            printf(__VA_ARGS__);                                                                                       \
            printf("\n");                                                                                              \
            failures++;                                                                                                \
        }                                                                                                              \
    } while (0)

#endif
