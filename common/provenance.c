#include "provenance.h"
#include "kernels.h"
#include <omp.h>
#include <stdio.h>
#include <string.h>

void fs_provenance_set(fs_provenance *p, const char *name, const char *value)
{
    char full[48];
    snprintf(full, sizeof full, "fluidsurf:%s", name);
    int i = 0;
    while (i < p->n && strcmp(p->name[i], full)) i++;
    if (i == FS_PROV_MAX) return;
    if (i == p->n) p->n++;
    snprintf(p->name[i], sizeof p->name[i], "%s", full);
    snprintf(p->value[i], sizeof p->value[i], "%s", value);
    p->attr[i].name = p->name[i];
    p->attr[i].value = p->value[i];
}

void fs_provenance_init(fs_provenance *p, const fs_scene *s, const char *renderer, const char *gl_version)
{
    char v[640];
    p->n = 0;
    fs_provenance_set(p, "version", fs_version);
    fs_provenance_set(p, "commit", fs_commit);
    fs_provenance_set(p, "gl_renderer", renderer ? renderer : "CPU");
    fs_provenance_set(p, "gl_version", gl_version ? gl_version : "none");
    snprintf(v, sizeof v, "%d", omp_get_max_threads());
    fs_provenance_set(p, "threads", v);
    snprintf(v, sizeof v, "%016llx", s->hash);
    fs_provenance_set(p, "scene_hash", v);
    fs_provenance_set(p, "scene", s->path[0] ? s->path : "(command line)");
    fs_provenance_set(p, "source", s->synth.shape ? "synthetic" : s->source);
    snprintf(v, sizeof v, "%u", s->synth.seed);
    fs_provenance_set(p, "seed", v);
    snprintf(v, sizeof v, "%.9g", s->radius);
    fs_provenance_set(p, "r", v);
    snprintf(v, sizeof v, "kernel=%s;support=%.9gr;iso=%.9g;volume_scale=%.9g", fs_kernel_name(s->kernel), s->support_r,
             s->iso, s->volume_scale);
    fs_provenance_set(p, "field", v);
    const fs_camera *c = &s->camera;
    snprintf(v, sizeof v, "eye=%.9g,%.9g,%.9g;target=%.9g,%.9g,%.9g;up=%.9g,%.9g,%.9g;fov=%.9g;size=%dx%d", c->eye[0],
             c->eye[1], c->eye[2], c->target[0], c->target[1], c->target[2], c->up[0], c->up[1], c->up[2], c->fovy_deg,
             c->width, c->height);
    fs_provenance_set(p, "camera", v);
}

void fs_provenance_line(const fs_provenance *p, char *buf, int size)
{
    int n = snprintf(buf, size, "#");
    for (int i = 0; i < p->n && n < size; i++) n += snprintf(buf + n, size - n, " %s=%s;", p->name[i] + 10, p->value[i]);
}
