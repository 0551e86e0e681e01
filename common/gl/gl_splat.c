/* The compute splatter (gl_splat.h): programs, per-pixel buffers, dispatches. */
#include "gl_splat.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_sprites.h"
#include "shader.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Sprites per dispatch of the walk: 65535 workgroups of 64, the least
 * GL_MAX_COMPUTE_WORK_GROUP_COUNT GL 4.3 guarantees. The list of large sprites
 * holds one piece. */
#define PIECE ((size_t)65535 * 64)
#define NONE 0xffffffffu
/* The most workgroups of the split phase: each takes every SPLIT_GROUPS-th listed
 * sprite, so a long list costs llvmpipe fewer workgroup launches while a GPU
 * still gets 262,144 invocations. */
#define SPLIT_GROUPS 4096u
/* Storage buffer bindings (shaders/common/splat_buffers.glsl); 0 holds the sprites. */
enum { B_SPRITES = 0, B_KEY, B_WIN, B_THICK, B_LIST, B_ARGS };

static int has_extension(const char *name)
{
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; i++) {
        const char *e = (const char *)glGetStringi(GL_EXTENSIONS, (GLuint)i);
        if (e && !strcmp(e, name)) return 1;
    }
    return 0;
}

int fs_gl_has_atomic_int64(void)
{
    return has_extension("GL_NV_shader_atomic_int64") && has_extension("GL_ARB_gpu_shader_int64");
}

/* One program of the splatter: stage file, the shape's and the pass's defines. */
static unsigned build(const char *file, fs_sprite_shape shape, const char *pass, int int64)
{
    static const char *const shapes[] = {"SPRITE_XYZ 1", "SPRITE_XYZW 1", "SPRITE_ELLIPSOID 1"};
    char defines[160];
    snprintf(defines, sizeof defines, "%s\n%s%s", shapes[shape], pass, int64 ? "\nSPLAT_INT64 1" : "");
    const char *stages[] = {file, NULL};
    return fs_program_build(stages, defines);
}

int fs_gl_splat_init(fs_gl_splat *s, fs_splat_path path, fs_sprite_shape shape, int large_px)
{
    memset(s, 0, sizeof *s);
    s->shape = shape;
    s->int64 = path == FS_SPLAT_COMPUTE && fs_gl_has_atomic_int64();
    s->large_px = large_px > 0 ? (unsigned)large_px : 0xffffffffu; /* 0: never split */
    GLint bits = 8;
    glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
    s->subpixel = ldexpf(1.0f, bits);
    const char *splat = "common/sprite_splat.comp.glsl", *resolve = "common/sprite_resolve.comp.glsl";
    int ok = (s->prog_depth = build(splat, shape, "PASS_DEPTH 1", s->int64)) &&
        (s->int64 || (s->prog_index = build(splat, shape, "PASS_INDEX 1", 0))) &&
        (s->prog_thick = build(splat, shape, "PASS_THICKNESS 1", 0)) &&
        (s->prog_resolve_depth = build(resolve, shape, "RESOLVE_DEPTH 1", s->int64)) &&
        (s->prog_resolve_thick = build(resolve, shape, "RESOLVE_THICKNESS 1", 0));
    if (ok) return FS_OK;
    fs_gl_splat_free(s);
    return FS_ERR_RUNTIME;
}

static void free_buffers(fs_gl_splat *s)
{
    unsigned *b[] = {&s->buf_key, &s->buf_win, &s->buf_thick, &s->buf_list, &s->buf_args};
    for (int i = 0; i < 5; i++) {
        if (*b[i]) glDeleteBuffers(1, b[i]);
        *b[i] = 0;
    }
    s->w = s->h = 0;
    s->list_cap = 0;
}

void fs_gl_splat_free(fs_gl_splat *s)
{
    unsigned p[] = {s->prog_depth, s->prog_index, s->prog_thick, s->prog_resolve_depth, s->prog_resolve_thick};
    for (int i = 0; i < 5; i++)
        if (p[i]) glDeleteProgram(p[i]);
    free_buffers(s);
    memset(s, 0, sizeof *s);
}

const char *fs_gl_splat_stage(const fs_gl_splat *s, int thickness)
{
    if (!s->prog_depth) return thickness ? "thickness" : "splat"; /* no compute splatter: the raster's */
    if (thickness) return "thickness_compute";
    return s->int64 ? "splat_compute64" : "splat_compute";
}

static unsigned new_buffer(size_t bytes)
{
    unsigned b = 0;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, (GLsizeiptr)(bytes ? bytes : 4), NULL, GL_DYNAMIC_STORAGE_BIT);
    return b;
}

/* The per-pixel buffers for a w x h image and the list for n sprites, bound. */
static int ensure_buffers(fs_gl_splat *s, int w, int h, size_t n)
{
    size_t px = (size_t)w * h, cap = n < PIECE ? n : PIECE;
    if (s->w != w || s->h != h || s->list_cap < cap) {
        free_buffers(s);
        s->buf_key = new_buffer(px * (s->int64 ? 8 : 4));
        s->buf_win = new_buffer(s->int64 ? 4 : px * 4);
        s->buf_thick = new_buffer(px * 8);
        s->buf_list = new_buffer(16 + cap * 16); /* uvec3 entries: a std430 stride of 16 */
        s->buf_args = new_buffer(3 * 4);
        s->w = w;
        s->h = h;
        s->list_cap = cap;
        if (glGetError() != GL_NO_ERROR)
            return fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot allocate the compute splatter's buffers for %dx%d", w, h);
    }
    unsigned b[] = {s->buf_key, s->buf_win, s->buf_thick, s->buf_list, s->buf_args};
    for (int i = 0; i < 5; i++) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, B_KEY + i, b[i]);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, s->buf_args);
    const uint32_t zero[4] = {0, 0, 0, 0};
    glNamedBufferSubData(s->buf_list, 0, sizeof zero, zero); /* list empty, no overflow */
    return FS_OK;
}

static void clear_u32(unsigned buf, uint32_t v)
{
    glClearNamedBufferData(buf, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &v);
}

/* The uniforms every pass of the splatter reads (a name the program lacks is ignored). */
static void uniforms(const fs_gl_splat *s, unsigned prog, const fs_camera *cam, float radius, float weight)
{
    fs_gl_camera_uniforms(prog, cam); /* makes prog current */
    float quantum = ldexpf(1.0f, ilogbf(radius) - FS_SPLAT_QUANTUM_BITS);
    glUniform1f(glGetUniformLocation(prog, "u_radius"), radius);
    glUniform1f(glGetUniformLocation(prog, "u_weight"), weight);
    glUniform1f(glGetUniformLocation(prog, "u_quantum"), quantum);
    glUniform1f(glGetUniformLocation(prog, "u_inv_quantum"), 1.0f / quantum);
    glUniform1f(glGetUniformLocation(prog, "u_subpixel"), s->subpixel);
    glUniform1ui(glGetUniformLocation(prog, "u_large_px"), s->large_px);
    glUniform1ui(glGetUniformLocation(prog, "u_split_groups"), SPLIT_GROUPS);
}

/* One phase of the splat program over sprites [base, base + count) of the bound buffer. */
static void phase(unsigned prog, int ph, size_t base, size_t count)
{
    glUniform1i(glGetUniformLocation(prog, "u_phase"), ph);
    glUniform1ui(glGetUniformLocation(prog, "u_base"), (unsigned)base);
    glUniform1ui(glGetUniformLocation(prog, "u_count"), (unsigned)count);
    if (ph == 0) glDispatchCompute((unsigned)((count + 63) / 64), 1, 1);
    else if (ph == 2) glDispatchCompute(1, 1, 1);
    else glDispatchComputeIndirect(0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

/* The splat program prog (uniforms set) over every sprite: per buffer and
 * piece, the walk, the list's dispatch, the workgroup phase. */
static void splat_all(unsigned prog, const fs_sprite_bufs *sp)
{
    for (int b = 0; b < sp->nbufs; b++) {
        size_t first = (size_t)b * sp->chunk, cnt = sp->n - first < sp->chunk ? sp->n - first : sp->chunk;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, B_SPRITES, sp->bufs[b]);
        glUniform1ui(glGetUniformLocation(prog, "u_first"), (unsigned)first);
        for (size_t o = 0; o < cnt; o += PIECE) {
            size_t m = cnt - o < PIECE ? cnt - o : PIECE;
            phase(prog, 0, o, m);
            phase(prog, 2, o, m);
            phase(prog, 1, o, m);
        }
    }
}

/* The resolve program prog (uniforms set) over every pixel, once per sprite
 * buffer for the depth (each pixel takes its winner from the buffer holding it). */
static void resolve_all(unsigned prog, const fs_camera *cam, const fs_sprite_bufs *sp, int per_buffer)
{
    int passes = per_buffer ? sp->nbufs : 1;
    for (int b = 0; b < passes; b++) {
        size_t first = (size_t)b * sp->chunk, cnt = sp->n - first < sp->chunk ? sp->n - first : sp->chunk;
        if (per_buffer) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, B_SPRITES, sp->bufs[b]);
        glUniform1ui(glGetUniformLocation(prog, "u_first"), (unsigned)first);
        glUniform1ui(glGetUniformLocation(prog, "u_count"), (unsigned)cnt);
        glDispatchCompute((unsigned)(cam->width + 7) / 8, (unsigned)(cam->height + 7) / 8, 1);
    }
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

static int check_count(const fs_sprite_bufs *sp)
{
    if (sp->n < NONE) return FS_OK; /* an index must differ from NONE */
    return fs_fail(FS_ERR_INPUT, "the compute splatter takes fewer than %u sprites, not %zu", NONE, sp->n);
}

int fs_gl_splat_depth(fs_gl_splat *s, const fs_gl_target *t, const fs_camera *cam, const fs_sprite_bufs *sp,
                      float radius)
{
    int rc = check_count(sp);
    if (!rc) rc = ensure_buffers(s, cam->width, cam->height, sp->n);
    if (rc) return rc;
    clear_u32(s->buf_key, NONE); /* depth bits above 1.0: nothing splatted */
    clear_u32(s->buf_win, NONE);
    uniforms(s, s->prog_depth, cam, radius, 1.0f);
    splat_all(s->prog_depth, sp);
    if (!s->int64) {
        uniforms(s, s->prog_index, cam, radius, 1.0f);
        splat_all(s->prog_index, sp);
    }
    uniforms(s, s->prog_resolve_depth, cam, radius, 1.0f);
    glBindImageTexture(0, t->tex[FS_TARGET_DEPTH], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(1, t->tex[FS_TARGET_NORMAL], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    resolve_all(s->prog_resolve_depth, cam, sp, 1);
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "OpenGL error in the compute depth splat");
}

int fs_gl_splat_thickness(fs_gl_splat *s, const fs_gl_target *t, const fs_camera *cam, const fs_sprite_bufs *sp,
                          float radius, float weight)
{
    int rc = check_count(sp);
    if (!rc) rc = ensure_buffers(s, cam->width, cam->height, sp->n);
    if (rc) return rc;
    clear_u32(s->buf_thick, 0);
    uniforms(s, s->prog_thick, cam, radius, weight);
    splat_all(s->prog_thick, sp);
    uniforms(s, s->prog_resolve_thick, cam, radius, weight);
    glBindImageTexture(2, t->tex[FS_TARGET_THICKNESS], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    resolve_all(s->prog_resolve_thick, cam, sp, 0);
    uint32_t head[4] = {0};
    glGetNamedBufferSubData(s->buf_list, 0, sizeof head, head);
    if (head[2]) return fs_fail(FS_ERR_RUNTIME, "the compute splatter's thickness sum overflowed 2^64 units");
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "OpenGL error in the compute thickness splat");
}
