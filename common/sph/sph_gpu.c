/* The SPH step as GL compute passes on the current context (shaders/sph/).
 * State stays in GPU buffers between steps; per step only three counters come
 * back (max speed for the CFL bound, clamps, non-finite particles). The grid
 * is rebuilt on the GPU each step by counting sort with the same origin, cell
 * size and dimensions fs_grid_build() gives the CPU path, and the cells are
 * sorted by particle index, so both paths sum neighbours in the same order. */
#include "fs_error.h"
#include "gl.h"
#include "shader.h"
#include "sph_internal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { P_COUNT, P_BSUM, P_BSCAN, P_BWRITE, P_SCATTER, P_REORDER, P_DENSITY, P_BOUNDARY, P_FORCES, P_N };
enum { B_POS, B_VEL, B_CELL, B_COUNT, B_START, B_BLOCK, B_SIDX, B_SPOS, B_SVEL, B_RHO, B_STATS, B_N };
#define SPH_BLOCK 256

typedef struct fs_sph_gpu {
    unsigned prog[P_N], buf[B_N];
    float origin[3], origin0[3], box0[3]; /* the grid follows the box (fs_sph_move_box) */
    int dim[3];
    unsigned ncells, nblocks;
} fs_sph_gpu;

static const char *const prog_files[P_N] = {
    "sph/count.comp.glsl",       "sph/block_sum.comp.glsl", "sph/block_scan.comp.glsl",
    "sph/block_write.comp.glsl", "sph/scatter.comp.glsl",   "sph/reorder.comp.glsl",
    "sph/density.comp.glsl",     "sph/boundary.comp.glsl",  "sph/forces.comp.glsl"};

void fs_sph_gpu_free(fs_sph *s)
{
    fs_sph_gpu *G = s->gpu;
    if (!G) return;
    for (int p = 0; p < P_N; p++)
        if (G->prog[p]) glDeleteProgram(G->prog[p]);
    glDeleteBuffers(B_N, G->buf);
    free(G);
    s->gpu = NULL;
}

int fs_sph_gpu_upload(fs_sph *s, size_t first, size_t count)
{
    float *v = malloc(count * 8 * sizeof *v);
    if (!v) return fs_fail(FS_ERR_RUNTIME, "sph: out of memory");
    for (size_t i = 0; i < count; i++) {
        size_t o = first + i;
        float *p = v + 4 * i, *q = v + 4 * (count + i);
        p[0] = s->x[o];
        p[1] = s->y[o];
        p[2] = s->z[o];
        p[3] = s->m[o];
        q[0] = s->vx[o];
        q[1] = s->vy[o];
        q[2] = s->vz[o];
        q[3] = 0;
    }
    glNamedBufferSubData(s->gpu->buf[B_POS], (GLintptr)(first * 16), (GLsizeiptr)(count * 16), v);
    glNamedBufferSubData(s->gpu->buf[B_VEL], (GLintptr)(first * 16), (GLsizeiptr)(count * 16), v + 4 * count);
    free(v);
    return FS_OK;
}

int fs_sph_gpu_read(fs_sph *s)
{
    size_t n = s->nf, o = s->nb;
    float *v = malloc((n ? n : 1) * 8 * sizeof *v);
    if (!v) return fs_fail(FS_ERR_RUNTIME, "sph: out of memory");
    glGetNamedBufferSubData(s->gpu->buf[B_POS], (GLintptr)(o * 16), (GLsizeiptr)(n * 16), v);
    glGetNamedBufferSubData(s->gpu->buf[B_VEL], (GLintptr)(o * 16), (GLsizeiptr)(n * 16), v + 4 * n);
    for (size_t i = 0; i < n; i++) {
        const float *p = v + 4 * i, *q = v + 4 * (n + i);
        s->x[o + i] = p[0];
        s->y[o + i] = p[1];
        s->z[o + i] = p[2];
        s->vx[o + i] = q[0];
        s->vy[o + i] = q[1];
        s->vz[o + i] = q[2];
    }
    free(v);
    s->dirty = 0;
    return FS_OK;
}

/* The grid fs_grid_build() makes of these particles: the fluid never leaves
 * the box, so the boundary shell fixes the bounds. Returns its cell count. */
static double place_grid(const fs_sph *s, fs_sph_gpu *G)
{
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < s->nb + s->nf; i++) {
        float p[3] = {s->x[i], s->y[i], s->z[i]};
        for (int a = 0; a < 3; a++) {
            lo[a] = fminf(lo[a], p[a]);
            hi[a] = fmaxf(hi[a], p[a]);
        }
    }
    double cells = 1;
    for (int a = 0; a < 3; a++) {
        G->origin[a] = lo[a] - s->H;
        G->dim[a] = (int)(floor(((double)hi[a] - G->origin[a]) / s->H) + 2);
        cells *= G->dim[a];
    }
    memcpy(G->origin0, G->origin, sizeof G->origin);
    memcpy(G->box0, s->box_lo, sizeof G->box0);
    return cells;
}

/* run() dispatches one work group per 128 particles and per 64 cells, and the
 * particles and the cell table are one storage block each (docs/DESIGN.md, "GL limits"). */
static int check_limits(size_t n, double cells)
{
    GLint maxssbo = 0, maxgroups = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxssbo);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &maxgroups);
    if ((n + 127) / 128 > (size_t)maxgroups || ceil(cells / 64) > maxgroups)
        return fs_fail(FS_ERR_INPUT,
                       "sph: %zu particles (boundary included) or %.0f grid cells need more than "
                       "GL_MAX_COMPUTE_WORK_GROUP_COUNT[x] = %d work groups on the GPU path",
                       n, cells, maxgroups);
    if ((cells + 1) * 4 > (double)(unsigned)maxssbo)
        return fs_fail(FS_ERR_INPUT, "sph: %.0f grid cells exceed one shader storage buffer (%d bytes) on the GPU path",
                       cells, maxssbo);
    return FS_OK;
}

/* The storage buffers of n particles and the grid's cells. */
static int make_buffers(fs_sph_gpu *G, size_t n)
{
    glCreateBuffers(B_N, G->buf);
    size_t bytes[B_N] = {n * 16,
                         n * 16,
                         n * 4,
                         (size_t)G->ncells * 4,
                         ((size_t)G->ncells + 1) * 4,
                         (size_t)G->nblocks * 4,
                         n * 4,
                         n * 16,
                         n * 16,
                         n * 8,
                         16};
    for (int b = 0; b < B_N; b++) glNamedBufferData(G->buf[b], (GLsizeiptr)bytes[b], NULL, GL_DYNAMIC_DRAW);
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot allocate the SPH buffers");
}

int fs_sph_gpu_init(fs_sph *s)
{
    fs_sph_gpu *G = calloc(1, sizeof *G);
    if (!G) return fs_fail(FS_ERR_RUNTIME, "sph: out of memory");
    s->gpu = G;
    size_t n = s->nb + s->cap;
    GLint maxssbo = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxssbo);
    if ((double)n * 16 > (double)(unsigned)maxssbo)
        return fs_fail(FS_ERR_INPUT,
                       "sph: %zu particles (boundary included) exceed one shader storage buffer "
                       "(%d bytes) on the GPU path",
                       n, maxssbo);
    for (int p = 0; p < P_N; p++) {
        const char *st[] = {prog_files[p], NULL};
        if (!(G->prog[p] = fs_program_build(st, NULL))) return FS_ERR_RUNTIME;
    }
    double cells = place_grid(s, G);
    int rc = check_limits(n, cells);
    if (rc) return rc;
    G->ncells = (unsigned)cells;
    G->nblocks = (G->ncells + SPH_BLOCK - 1) / SPH_BLOCK;
    return (rc = make_buffers(G, n)) ? rc : fs_sph_gpu_upload(s, 0, s->nb + s->nf);
}

static void set_common(const fs_sph *s, unsigned prog)
{
    const fs_sph_gpu *G = s->gpu;
    glUseProgram(prog);
    glUniform1ui(glGetUniformLocation(prog, "u_n"), (unsigned)(s->nb + s->nf));
    glUniform1ui(glGetUniformLocation(prog, "u_nb"), (unsigned)s->nb);
    glUniform1ui(glGetUniformLocation(prog, "u_ncells"), G->ncells);
    glUniform1ui(glGetUniformLocation(prog, "u_nblocks"), G->nblocks);
    glUniform3f(glGetUniformLocation(prog, "u_origin"), G->origin[0], G->origin[1], G->origin[2]);
    glUniform1f(glGetUniformLocation(prog, "u_cell"), s->H);
    glUniform3iv(glGetUniformLocation(prog, "u_dim"), 1, G->dim);
}

static void run(const fs_sph *s, int p, unsigned items, unsigned local)
{
    set_common(s, s->gpu->prog[p]);
    glDispatchCompute((items + local - 1) / local, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

int fs_sph_gpu_step(fs_sph *s, float dt)
{
    fs_sph_gpu *G = s->gpu;
    unsigned n = (unsigned)(s->nb + s->nf);
    for (int a = 0; a < 3; a++) G->origin[a] = G->origin0[a] + (s->box_lo[a] - G->box0[a]);
    for (int b = 0; b < B_N; b++) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, (GLuint)b, G->buf[b]);
    unsigned zero = 0;
    glClearNamedBufferData(G->buf[B_COUNT], GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glClearNamedBufferData(G->buf[B_STATS], GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    run(s, P_COUNT, n, 128);
    run(s, P_BSUM, G->nblocks, 64);
    run(s, P_BSCAN, 1, 1);
    run(s, P_BWRITE, G->nblocks, 64);
    run(s, P_SCATTER, n, 128);
    run(s, P_REORDER, G->ncells, 64);
    unsigned pd = G->prog[P_DENSITY], pf = G->prog[P_FORCES];
    set_common(s, pd);
    glUniform1f(glGetUniformLocation(pd, "u_H"), s->H);
    glUniform1f(glGetUniformLocation(pd, "u_rho0"), s->prm.rho0);
    glUniform1f(glGetUniformLocation(pd, "u_B"), s->B);
    glUniform1f(glGetUniformLocation(pd, "u_k"), s->k);
    glUniform1i(glGetUniformLocation(pd, "u_tait"), s->prm.eos == FS_SPH_TAIT);
    glDispatchCompute((n + 127) / 128, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    unsigned pb = G->prog[P_BOUNDARY];
    set_common(s, pb);
    glUniform1f(glGetUniformLocation(pb, "u_H"), s->H);
    glUniform1f(glGetUniformLocation(pb, "u_g"), s->prm.gravity);
    glDispatchCompute((n + 127) / 128, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    set_common(s, pf);
    glUniform1f(glGetUniformLocation(pf, "u_H"), s->H);
    glUniform1f(glGetUniformLocation(pf, "u_mu"), s->prm.nu * s->prm.rho0);
    glUniform1f(glGetUniformLocation(pf, "u_g"), s->prm.gravity);
    glUniform1f(glGetUniformLocation(pf, "u_dt"), dt);
    glUniform1f(glGetUniformLocation(pf, "u_r02"), 4 * s->prm.r * s->prm.r);
    glUniform1f(glGetUniformLocation(pf, "u_D"), s->prm.c * s->prm.c / 40);
    glUniform3f(glGetUniformLocation(pf, "u_box_lo"), s->box_lo[0], s->box_lo[1], s->box_lo[2]);
    glUniform3f(glGetUniformLocation(pf, "u_box_hi"), s->box_hi[0], s->box_hi[1], s->box_hi[2]);
    glDispatchCompute((n + 127) / 128, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    unsigned st[4];
    glGetNamedBufferSubData(G->buf[B_STATS], 0, sizeof st, st); /* waits for the step */
    if (glGetError() != GL_NO_ERROR) return fs_fail(FS_ERR_RUNTIME, "OpenGL: an SPH compute pass failed");
    memcpy(&s->st.v_max, &st[0], sizeof(float));
    s->st.clamps += st[1];
    s->st.nonfinite = st[2];
    s->dirty = 1;
    return FS_OK;
}
