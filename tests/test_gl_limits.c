/* The GL limits check (common/gl/gl_limits.h, docs/DESIGN.md "GL limits"): the
 * pure check refuses each limit one below its need with the one line the CLI
 * prints, and a limit the driver does not report; the real context (OSMesa, or
 * EGL in the lean build) meets every need. Prints the driver's values beside the
 * needs, the numbers docs/DESIGN.md records. `test_gl_limits --table` prints the table
 * alone (name, need), for tests/gl_limits_needs.py. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "gl_limits.h"
#include <stdlib.h>
#include <string.h>

#define MAXN 128

static void test_table(const fs_gl_limit *t, int n)
{
    CHECK(n > 0 && n <= MAXN, "%d limits", n);
    for (int i = 0; i < n; i++) {
        CHECK(!strncmp(t[i].name, "GL_MAX_", 7) && t[i].need > 0 && t[i].what && *t[i].what, "entry %d", i);
        for (int j = 0; j < i; j++) CHECK(strcmp(t[i].name, t[j].name), "%s listed twice", t[i].name);
    }
}

/* Every limit one below its need, and not reported (-1): refused with exactly the line. */
static void test_refusals(const fs_gl_limit *t, int n)
{
    long long have[MAXN] = {0};
    if (n > MAXN) return;
    for (int i = 0; i < n; i++) have[i] = t[i].need;
    CHECK(fs_gl_limits_check(have, "Test GL 1.0") == FS_OK, "the needs themselves refused: %s", fs_error_message());
    for (int i = 0; i < n; i++) {
        char want[512];
        have[i] = t[i].need - 1;
        int rc = fs_gl_limits_check(have, "Test GL 1.0");
        snprintf(want, sizeof want, "OpenGL: %s is %lld on Test GL 1.0; fluidsurf needs %lld (%s)", t[i].name,
                 t[i].need - 1, t[i].need, t[i].what);
        CHECK(rc == FS_ERR_RUNTIME && !strcmp(fs_error_message(), want), "%s one below: rc %d, '%s'", t[i].name, rc,
              fs_error_message());
        have[i] = -1;
        rc = fs_gl_limits_check(have, "Test GL 1.0");
        CHECK(rc == FS_ERR_RUNTIME && strstr(fs_error_message(), " is not reported on Test GL 1.0; fluidsurf needs "),
              "%s unreported: rc %d, '%s'", t[i].name, rc, fs_error_message());
        have[i] = t[i].need;
    }
    printf("%d limits: each refused one below its need, and when not reported\n", n);
}

/* The context of this build meets every need; its values, for docs/DESIGN.md. */
static void test_context(const fs_gl_limit *t, int n)
{
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) return;
    long long have[MAXN] = {0};
    if (n > MAXN) return;
    fs_gl_limits_query(have);
    printf("%s (%s):\n", ctx.renderer, ctx.version);
    for (int i = 0; i < n; i++) {
        printf("  %-42s %12lld  needs %lld\n", t[i].name, have[i], t[i].need);
        CHECK(have[i] >= t[i].need, "%s is %lld on %s, below the need %lld", t[i].name, have[i], ctx.renderer,
              t[i].need);
    }
    CHECK(fs_gl_limits_check_current(ctx.renderer) == FS_OK, "%s", fs_error_message());
    fs_gl_context_destroy(&ctx);
}

int main(int argc, char **argv)
{
    int n = 0;
    const fs_gl_limit *t = fs_gl_limits(&n);
    if (argc > 1 && !strcmp(argv[1], "--table")) {
        for (int i = 0; i < n; i++) printf("%s\t%lld\n", t[i].name, t[i].need);
        return 0;
    }
    test_table(t, n);
    test_refusals(t, n);
    test_context(t, n);
    TEST_DONE();
}
