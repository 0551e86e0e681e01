/* Test helper: the GL context a GL test renders in, set up one way for every such test:
 * the default kind (OSMesa, or what FLUIDSURF_GL names) at 16x16 (each render makes its
 * own targets). A failure is a failed CHECK naming the error. */
#ifndef FS_TEST_GL_CONTEXT_H
#define FS_TEST_GL_CONTEXT_H
#include "fs_error.h"
#include "fs_test.h"
#include "gl_context.h"

/* FS_OK, or the error code with the CHECK recorded: the caller ends the test
 * (TEST_DONE) or the part that needs GL. */
static inline int fs_test_gl_context(fs_gl_context *ctx)
{
    int rc = fs_gl_context_create(ctx, fs_gl_context_default_kind(), 16, 16);
    CHECK(rc == FS_OK, "context: %s", fs_error_message());
    return rc;
}

#endif
