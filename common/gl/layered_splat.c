/* inacio2010 section IV-A: the density grid in one rendering pass (density_grid.h).
 *
 * Every particle is sent once, as a point. A geometry shader emits the
 * particle's disk on each z plane of the grid within the support H, routed to
 * that layer of an R32F 3D texture attached layered to a framebuffer
 * (gl_Layer); the fragment shader adds V W(d, H) at the grid point with the
 * depth test off and additive blending. The grid stays on the GL side; a
 * readback is there for tests and exports.
 *
 * Limits: a geometry shader invocation may emit only so many vertices and
 * components (llvmpipe: 1024 each), so each particle's layers are split over
 * instanced invocations (layout(invocations = N)) of a few layers each. When a
 * particle reaches more layers than one draw covers (fine grids: 2H/spacing
 * larger than invocations x layers), the draw is repeated with a layer offset;
 * with the defaults on llvmpipe one draw covers 256 layers.
 * Shaders: shaders/common/layered_splat.{vert,geom,frag}.glsl. */
#include "density_splat.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_target.h"
#include "shader.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LAYERS_MAX 8 /* layers per invocation: 32 vertices of 8 components */

#define INVOCATIONS_MAX 32

struct fs_layered_splat {
    /* one program per invocation count, built when first needed, so a coarse
     * grid does not pay for idle invocations */
    unsigned prog[INVOCATIONS_MAX + 1], vao, fbo;
    int layers, max_invocations; /* layers per invocation; invocations per point */
    fs_gl_chunks parts;          /* the particles of the last run */
    size_t draws;                /* points sent in the last run (particles x passes) */
};

fs_layered_splat *fs_layered_splat_create(void)
{
    fs_layered_splat *s = calloc(1, sizeof *s);
    if (!s) {
        fs_fail(FS_ERR_RUNTIME, "layered splat: out of memory");
        return NULL;
    }
    GLint maxv = 0, maxc = 0, maxi = 0;
    glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES, &maxv);
    glGetIntegerv(GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS, &maxc);
    glGetIntegerv(GL_MAX_GEOMETRY_SHADER_INVOCATIONS, &maxi);
    /* a vertex carries gl_Position (4), gl_Layer (1) and the flat vec3 (3) */
    int layers = LAYERS_MAX;
    if (layers * 4 > maxv) layers = maxv / 4;
    if (layers * 4 * 8 > maxc) layers = maxc / 32;
    if (layers < 1 || maxi < 1) {
        free(s);
        fs_fail(FS_ERR_RUNTIME, "layered splat: geometry shader limits too small (%d vertices, %d components)", maxv,
                maxc);
        return NULL;
    }
    s->layers = layers;
    s->max_invocations = maxi < INVOCATIONS_MAX ? maxi : INVOCATIONS_MAX;
    glCreateVertexArrays(1, &s->vao);
    glCreateFramebuffers(1, &s->fbo);
    return s;
}

static unsigned program(fs_layered_splat *s, int invocations)
{
    if (s->prog[invocations]) return s->prog[invocations];
    char defs[96];
    snprintf(defs, sizeof defs, "INVOCATIONS %d\nLAYERS %d", invocations, s->layers);
    const char *st[] = {"common/layered_splat.vert.glsl", "common/layered_splat.geom.glsl",
                        "common/layered_splat.frag.glsl", NULL};
    return s->prog[invocations] = fs_program_build(st, defs);
}

void fs_layered_splat_destroy(fs_layered_splat *s)
{
    if (!s) return;
    fs_gl_chunks_free(&s->parts);
    if (s->fbo) glDeleteFramebuffers(1, &s->fbo);
    if (s->vao) glDeleteVertexArrays(1, &s->vao);
    for (int i = 0; i <= INVOCATIONS_MAX; i++)
        if (s->prog[i]) glDeleteProgram(s->prog[i]);
    free(s);
}

size_t fs_layered_splat_points(const fs_layered_splat *s) { return s ? s->draws : 0; }

unsigned fs_density_texture_create(const fs_density_grid *shape)
{
    GLint max3d = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3d);
    for (int a = 0; a < 3; a++)
        if (shape->dim[a] < 1 || shape->dim[a] > max3d) {
            fs_fail(FS_ERR_INPUT, "density texture: %dx%dx%d points exceed this context's 3D texture limit %d",
                    shape->dim[0], shape->dim[1], shape->dim[2], max3d);
            return 0;
        }
    unsigned t = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &t);
    glTextureStorage3D(t, 1, GL_R32F, shape->dim[0], shape->dim[1], shape->dim[2]);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    if (glGetError() != GL_NO_ERROR) {
        glDeleteTextures(1, &t);
        fs_fail(FS_ERR_RUNTIME, "density texture: cannot allocate %dx%dx%d R32F", shape->dim[0], shape->dim[1],
                shape->dim[2]);
        return 0;
    }
    return t;
}

int fs_density_texture_upload(unsigned tex, const fs_density_grid *g)
{
    if (!g->data) return fs_fail(FS_ERR_INPUT, "density texture: grid not initialised");
    glTextureSubImage3D(tex, 0, 0, 0, 0, g->dim[0], g->dim[1], g->dim[2], GL_RED, GL_FLOAT, g->data);
    /* A driver may defer the upload until the texture is first used, so that it lands in
     * the next stage's time (on the H200, the march after build=slice took 2-5 ms where the
     * same march after the layered build took 0.1: issue 52). One texel copied on the GL
     * makes the upload happen now, inside the build's timed stage. */
    unsigned one = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &one);
    glTextureStorage3D(one, 1, GL_R32F, 1, 1, 1);
    glCopyImageSubData(tex, GL_TEXTURE_3D, 0, 0, 0, 0, one, GL_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1);
    glDeleteTextures(1, &one);
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "density texture: upload failed");
}

int fs_density_texture_read(unsigned tex, fs_density_grid *g)
{
    if (!g->data) return fs_fail(FS_ERR_INPUT, "density texture: grid not initialised");
    size_t bytes = fs_density_grid_points(g) * sizeof(float);
    if (bytes > 0x7fffffff) return fs_fail(FS_ERR_INPUT, "density texture: %zu bytes are too many to read back", bytes);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    /* texel (i, j, k) lands at (k*dim[1] + j)*dim[0] + i: the grid's own layout */
    glGetTextureImage(tex, 0, GL_RED, GL_FLOAT, (GLsizei)bytes, g->data);
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "density texture: readback failed");
}

static int upload_particles(fs_layered_splat *s, const fs_particles *p)
{
    float *v = malloc(p->n * 4 * sizeof(float));
    if (!v) return fs_fail(FS_ERR_RUNTIME, "layered splat: out of memory for %zu particles", p->n);
    for (size_t i = 0; i < p->n; i++) {
        if (!isfinite(p->x[i]) || !isfinite(p->y[i]) || !isfinite(p->z[i])) {
            free(v);
            return fs_fail(FS_ERR_INPUT, "layered splat: particle %zu has a non-finite position", i);
        }
        v[4 * i] = p->x[i];
        v[4 * i + 1] = p->y[i];
        v[4 * i + 2] = p->z[i];
        v[4 * i + 3] = 0.0f;
    }
    int rc = fs_gl_chunks_upload(&s->parts, v, p->n, "layered splat");
    free(v);
    return rc;
}

/* The run's inputs make sense and the grid fits this context's viewport and layers. */
static int check_run(const fs_density_grid *shape, const fs_field *f, unsigned tex3d)
{
    if (!tex3d) return fs_fail(FS_ERR_INPUT, "layered splat: no 3D texture");
    if (!(f->H > 0) || !(f->volume > 0) || !isfinite(f->H) || !isfinite(f->volume))
        return fs_fail(FS_ERR_INPUT, "layered splat: support H %g and volume V %g must be positive", f->H, f->volume);
    if (!(shape->spacing > 0)) return fs_fail(FS_ERR_INPUT, "layered splat: grid spacing %g", shape->spacing);
    const int *dim = shape->dim;
    GLint maxvp[2] = {0, 0}, maxlayers = 0;
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxvp);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_LAYERS, &maxlayers);
    if (dim[0] > maxvp[0] || dim[1] > maxvp[1] || dim[2] > maxlayers)
        return fs_fail(FS_ERR_INPUT, "layered splat: %dx%dx%d points exceed this context's %dx%d viewport or %d layers",
                       dim[0], dim[1], dim[2], maxvp[0], maxvp[1], maxlayers);
    return FS_OK;
}

/* Additive blending into every layer of the texture, with the grid's and the field's uniforms. */
static void begin_splat(const fs_layered_splat *s, unsigned prog, const fs_density_grid *shape, const fs_field *f)
{
    glBindFramebuffer(GL_FRAMEBUFFER, s->fbo);
    glViewport(0, 0, shape->dim[0], shape->dim[1]);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glUseProgram(prog);
    glBindVertexArray(s->vao);
    glUniform3f(glGetUniformLocation(prog, "u_origin"), shape->origin[0], shape->origin[1], shape->origin[2]);
    glUniform1f(glGetUniformLocation(prog, "u_spacing"), shape->spacing);
    glUniform3iv(glGetUniformLocation(prog, "u_dim"), 1, shape->dim);
    glUniform1f(glGetUniformLocation(prog, "u_H"), f->H);
    glUniform1f(glGetUniformLocation(prog, "u_V"), f->volume);
    glUniform1i(glGetUniformLocation(prog, "u_kernel"), (int)f->kernel);
}

/* Every particle drawn once per pass of per_draw layers. */
static void draw_passes(fs_layered_splat *s, unsigned prog, size_t n, int passes, int per_draw)
{
    const int u_layer0 = glGetUniformLocation(prog, "u_layer0");
    for (int pass = 0; pass < passes; pass++) {
        glUniform1i(u_layer0, pass * per_draw);
        for (int b = 0; b < s->parts.n; b++) {
            size_t chunk = s->parts.chunk, lo = (size_t)b * chunk, hi = lo + chunk < n ? lo + chunk : n;
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, s->parts.bufs[b]);
            glDrawArrays(GL_POINTS, 0, (GLsizei)(hi - lo));
            s->draws += hi - lo;
        }
    }
}

int fs_layered_splat_run(fs_layered_splat *s, const fs_density_grid *shape, const fs_particles *p, const fs_field *f,
                         unsigned tex3d)
{
    int rc = check_run(shape, f, tex3d);
    if (rc) return rc;
    s->draws = 0;
    const float zero = 0.0f;
    glClearTexImage(tex3d, 0, GL_RED, GL_FLOAT, &zero);
    if (p->n == 0) return FS_OK;
    if ((rc = upload_particles(s, p))) return rc;
    const int *dim = shape->dim;
    glNamedFramebufferTexture(s->fbo, GL_COLOR_ATTACHMENT0, tex3d, 0); /* layered: the whole 3D texture */
    if (glCheckNamedFramebufferStatus(s->fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return fs_fail(FS_ERR_RUNTIME, "layered splat: layered R32F framebuffer of %dx%dx%d is incomplete", dim[0],
                       dim[1], dim[2]);
    /* layers one particle can reach; one draw covers invocations x layers of them */
    int reach = (int)floor(2.0 * f->H / shape->spacing) + 2;
    int inv = (reach + s->layers - 1) / s->layers;
    if (inv > s->max_invocations) inv = s->max_invocations;
    int per_draw = inv * s->layers, passes = (reach + per_draw - 1) / per_draw;
    unsigned prog = program(s, inv);
    if (!prog) return FS_ERR_RUNTIME;
    begin_splat(s, prog, shape, f);
    draw_passes(s, prog, p->n, passes, per_draw);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (glGetError() != GL_NO_ERROR) return fs_fail(FS_ERR_RUNTIME, "layered splat: OpenGL error while splatting");
    return FS_OK;
}
