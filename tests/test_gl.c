/* OpenGL plumbing on the real OSMesa context: 4.5 core, the function table,
 * shader errors reported as file:line, and GLSL kernels equal to the C ones. */
#include "fs_error.h"
#include "fs_test.h"
#include "gl.h"
#include "test_gl_context.h"
#include "kernels.h"
#include "shader.h"
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

static void test_shader_errors(void)
{
    char dir[512];
    snprintf(dir, sizeof dir, "%s/shader_err", FS_TEST_OUT);
    mkdir(dir, 0755);
    char sub[600];
    snprintf(sub, sizeof sub, "%s/common", dir);
    mkdir(sub, 0755);
    char path[700];
    snprintf(path, sizeof path, "%s/common/inc.glsl", dir);
    write_file(path, "float ok1() { return 1.0; }\nfloat bad() { return undefined_name; }\n");
    snprintf(path, sizeof path, "%s/broken.comp.glsl", dir);
    write_file(path, "#version 450 core\n#include \"common/inc.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n");
    snprintf(path, sizeof path, "%s/broken2.comp.glsl", dir);
    write_file(path, "#version 450 core\nlayout(local_size_x = 1) in;\n\nvoid main() { int x = nope; }\n");
    setenv("FLUIDSURF_SHADER_DIR", dir, 1);
    const char *a[] = {"broken.comp.glsl", NULL};
    CHECK(fs_program_build(a, NULL) == 0, "broken shader built");
    const char *msg = fs_error_message();
    printf("include error: %s\n", msg);
    CHECK(strstr(msg, "shaders/common/inc.glsl:2:") != NULL, "error does not name the included file and line: %s", msg);
    const char *b[] = {"broken2.comp.glsl", NULL};
    CHECK(fs_program_build(b, "EXTRA 1") == 0, "broken shader built");
    msg = fs_error_message();
    printf("main error: %s\n", msg);
    CHECK(strstr(msg, "shaders/broken2.comp.glsl:4:") != NULL, "error does not name the file and line: %s", msg);
    unsetenv("FLUIDSURF_SHADER_DIR");
}

static void test_kernels_agree(void)
{
    const char *st[] = {"tests/kernel_eval.comp.glsl", NULL};
    GLuint prog = fs_program_build(st, NULL);
    CHECK(prog != 0, "kernel_eval: %s", fs_error_message());
    if (!prog) return;
    const unsigned n = 1000;
    const float H = 0.1f;
    GLuint buf;
    glCreateBuffers(1, &buf);
    glNamedBufferStorage(buf, n * 8 * sizeof(float), NULL, GL_DYNAMIC_STORAGE_BIT);
    glUseProgram(prog);
    glUniform1ui(glGetUniformLocation(prog, "u_n"), n);
    glUniform1f(glGetUniformLocation(prog, "u_H"), H);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf);
    glDispatchCompute((n + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    float *v = malloc(n * 8 * sizeof(float));
    glGetNamedBufferSubData(buf, 0, n * 8 * sizeof(float), v);
    double worst = 0;
    for (unsigned i = 0; i < n; i++) {
        float d = (float)i / (n - 1) * 1.1f * H;
        for (int k = 0; k < 4; k++) {
            double w = fs_kernel_w((fs_kernel)k, d, H), dw = fs_kernel_dw((fs_kernel)k, d, H);
            double scale_w = fs_kernel_w((fs_kernel)k, 0, H), scale_dw = fs_kernel_max_dw((fs_kernel)k, H);
            double ew = fabs(v[(i * 4 + k) * 2] - w) / scale_w, edw = fabs(v[(i * 4 + k) * 2 + 1] - dw) / scale_dw;
            if (ew > worst) worst = ew;
            if (edw > worst) worst = edw;
        }
    }
    printf("largest C/GLSL kernel difference: %.3g of the kernel's peak\n", worst);
    CHECK(worst < 1e-5, "GLSL and C kernels differ by %g of the peak", worst);
    free(v);
    glDeleteBuffers(1, &buf);
    glDeleteProgram(prog);
}

int main(void)
{
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    printf("renderer: %s, version: %s\n", ctx.renderer, ctx.version);
    CHECK(strstr(ctx.version, "4.5") == ctx.version || strstr(ctx.version, "4.6") == ctx.version, "version %s",
          ctx.version);
    test_shader_errors();
    test_kernels_agree();
    CHECK(glGetError() == GL_NO_ERROR, "GL error left");
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
