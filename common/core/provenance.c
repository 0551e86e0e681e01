#include "provenance.h"
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

const char *fs_provenance_get(const fs_provenance *p, const char *name)
{
    for (int i = 0; i < p->n; i++)
        if (!strncmp(p->name[i], "fluidsurf:", 10) && !strcmp(p->name[i] + 10, name)) return p->value[i];
    return NULL;
}

void fs_provenance_init_base(fs_provenance *p, const char *renderer, const char *gl_version)
{
    char v[640];
    p->n = 0;
    fs_provenance_set(p, "version", fs_version);
    fs_provenance_set(p, "commit", fs_commit);
    fs_provenance_set(p, "dirty", fs_dirty ? "1" : "0");
    fs_provenance_set(p, "gl_renderer", renderer ? renderer : "CPU");
    fs_provenance_set(p, "gl_version", gl_version ? gl_version : "none");
    snprintf(v, sizeof v, "%d", omp_get_max_threads());
    fs_provenance_set(p, "threads", v);
}

void fs_provenance_line(const fs_provenance *p, char *buf, int size)
{
    int n = snprintf(buf, size, "#");
    for (int i = 0; i < p->n && n < size; i++)
        n += snprintf(buf + n, size - n, " %s=%s;", p->name[i] + 10, p->value[i]);
}
