/* Minimal test harness: CHECK records a failure and goes on; main returns the
 * number of failures, so ctest shows every broken assertion of a file at once. */
#ifndef FS_TEST_H
#define FS_TEST_H
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static int fs_test_failures;

#define CHECK(cond, ...)                                                                                               \
    do {                                                                                                               \
        if (!(cond)) {                                                                                                 \
            fs_test_failures++;                                                                                        \
            fprintf(stderr, "%s:%d: CHECK(%s) failed: ", __FILE__, __LINE__, #cond);                                   \
            fprintf(stderr, __VA_ARGS__);                                                                              \
            fputc('\n', stderr);                                                                                       \
        }                                                                                                              \
    } while (0)
#define CHECK_NEAR(a, b, tol, what)                                                                                    \
    do {                                                                                                               \
        double _a = (a), _b = (b);                                                                                     \
        CHECK(fabs(_a - _b) <= (tol), "%s: %g vs %g (tol %g)", what, _a, _b, (double)(tol));                           \
    } while (0)
#define TEST_DONE()                                                                                                    \
    do {                                                                                                               \
        if (fs_test_failures) {                                                                                        \
            fprintf(stderr, "%d check(s) failed\n", fs_test_failures);                                                 \
        } else {                                                                                                       \
            printf("all checks passed\n");                                                                             \
        }                                                                                                              \
        return fs_test_failures ? 1 : 0;                                                                               \
    } while (0)

/* A refusal of the lean build (a library left out): rc is bad input, the one-line
 * message names the CMake option, and no file was left at path. */
#define CHECK_REFUSED(rc, msg, path, option)                                                                           \
    do {                                                                                                               \
        CHECK((rc) == 2 && strstr((msg), "needs a build with " option "=ON") && !strchr((msg), '\n'),                  \
              "expected a refusal naming " option ": rc %d, %s", (rc), (msg));                                         \
        CHECK(access((path), F_OK) != 0, "%s: a refused write left a file", (path));                                   \
    } while (0)

#endif
