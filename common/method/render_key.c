#include "render_key.h"
#include "method_params.h"
#include "provenance.h"
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* Bump when the key's contents or the entries' layout change. */
#define KEY_FORMAT "fluidsurf-render-key-1"

void fs_render_key_build(char *buf, int size)
{
    struct stat st;
    /* the commit does not say which uncommitted edits were built: the binary does */
    int modified = fs_dirty || !strcmp(fs_commit, "unknown");
    if (modified && stat("/proc/self/exe", &st) == 0)
        snprintf(buf, size, "%s %s-dirty exe:%lld:%lld.%09ld", fs_version, fs_commit, (long long)st.st_size,
                 (long long)st.st_mtim.tv_sec, (long)st.st_mtim.tv_nsec);
    else snprintf(buf, size, "%s %s", fs_version, fs_commit);
}

static void hash_floats(fs_hash *h, const float *v, size_t n) { fs_hash_bytes(h, v, n * sizeof *v); }

static void hash_camera(fs_hash *h, const fs_camera *c)
{
    hash_floats(h, c->eye, 3);
    hash_floats(h, c->target, 3);
    hash_floats(h, c->up, 3);
    hash_floats(h, &c->fovy_deg, 1);
    fs_hash_u64(h, (uint64_t)c->width);
    fs_hash_u64(h, (uint64_t)c->height);
    hash_floats(h, &c->znear, 1);
    hash_floats(h, &c->zfar, 1);
}

static void hash_field(fs_hash *h, const fs_field *f)
{
    hash_floats(h, &f->r, 1);
    hash_floats(h, &f->volume, 1);
    fs_hash_u64(h, (uint64_t)f->kernel);
    hash_floats(h, &f->H, 1);
    hash_floats(h, &f->iso, 1);
}

static int reads_color(const fs_method *m)
{
    for (int i = 0; i < m->naovs; i++)
        if (m->aovs[i].needs_color) return 1;
    return 0;
}

static void hash_particles(fs_hash *h, const fs_method *m, const fs_particles *p)
{
    fs_hash_u64(h, (uint64_t)p->n);
    hash_floats(h, p->x, p->n);
    hash_floats(h, p->y, p->n);
    hash_floats(h, p->z, p->n);
    int color = reads_color(m) && p->color;
    fs_hash_u64(h, (uint64_t)color);
    if (color) hash_floats(h, p->color, 3 * p->n);
}

fs_digest fs_render_key(const fs_method *m, const double *values, const fs_field *f, const fs_camera *cam,
                        const fs_particles *p)
{
    fs_hash h;
    char text[1024];
    fs_hash_init(&h);
    fs_hash_str(&h, KEY_FORMAT);
    fs_render_key_build(text, sizeof text);
    fs_hash_str(&h, text);
    fs_hash_str(&h, m->name);
    fs_method_params_string(m, values, text, sizeof text);
    fs_hash_str(&h, text);
    fs_hash_u64(&h, (uint64_t)m->nparams);
    fs_hash_bytes(&h, values, (size_t)m->nparams * sizeof *values);
    hash_field(&h, f);
    hash_camera(&h, cam);
    hash_particles(&h, m, p);
    return fs_hash_digest(&h);
}
