/* Stamping and reloading the work items of compare --resume (resume.h). */
#include "resume.h"
#include "hash.h"
#include "image_io.h"
#include "render_output.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void item_key(const fs_provenance *prov, char hex[FS_DIGEST_HEX])
{
    fs_hash h;
    fs_hash_init(&h);
    for (int i = 0; i < prov->n; i++) {
        fs_hash_str(&h, prov->attr[i].name);
        fs_hash_str(&h, prov->attr[i].value);
    }
    fs_digest_hex(fs_hash_digest(&h), hex);
}

int fs_runs_format(const fs_stages *runs, int nruns, char *buf, int size)
{
    int at = 0;
    buf[0] = 0;
    for (int k = 0; k < nruns; k++)
        for (int s = 0; s < runs[k].n; s++) {
            at += snprintf(buf + at, at < size ? size - at : 0, "%s%s=%.17g/%.17g",
                           s       ? ","
                               : k ? ";"
                                   : "",
                           runs[k].name[s], runs[k].ms[s], runs[k].gpu_ms[s]);
            if (at >= size) return 0;
        }
    return 1;
}

void fs_resume_stamp(fs_provenance *prov, const fs_study_entry *e, int f)
{
    char key[FS_DIGEST_HEX], ms[40], runs[640];
    item_key(prov, key);
    snprintf(ms, sizeof ms, "%.17g", e->frame_ms[f]);
    fs_provenance_set(prov, "item", key);
    fs_provenance_set(prov, "frame_ms", ms);
    if (f == 0 && fs_runs_format(e->runs, e->nruns, runs, sizeof runs)) fs_provenance_set(prov, "runs", runs);
}

/* A stage name as the one static string the tables compare by pointer or text. */
static const char *intern(const char *name)
{
    static char pool[64][32];
    static int n;
    for (int i = 0; i < n; i++)
        if (!strcmp(pool[i], name)) return pool[i];
    if (n == 64 || strlen(name) >= sizeof pool[0]) return NULL;
    return strcpy(pool[n++], name);
}

int fs_runs_parse(const char *s, fs_stages *runs, int max)
{
    int nruns = 0;
    fs_stages st = {0};
    while (*s && nruns < max) {
        char name[32];
        double ms, gpu;
        int used;
        if (sscanf(s, "%31[^=]=%lf/%lf%n", name, &ms, &gpu, &used) != 3 || st.n == FS_MAX_STAGES) return 0;
        if (!(st.name[st.n] = intern(name))) return 0;
        st.ms[st.n] = ms, st.gpu_ms[st.n] = gpu, st.n++;
        s += used;
        if (*s == ',') s++;
        else if (*s == ';' || !*s) {
            runs[nruns++] = st;
            memset(&st, 0, sizeof st);
            if (*s) s++;
        } else return 0;
    }
    return *s ? 0 : nruns;
}

int fs_resume_load(fs_study_entry *e, int f, int repeat, const fs_provenance *prov, const char *exr, fs_run_image *v)
{
    char want[FS_DIGEST_HEX], have[FS_DIGEST_HEX], ms[64], runs[640];
    item_key(prov, want);
    if (fs_read_image_attr(exr, "fluidsurf:item", have, sizeof have) != 1 || strcmp(want, have)) return 0;
    if (fs_read_image_attr(exr, "fluidsurf:frame_ms", ms, sizeof ms) != 1) return 0;
    fs_stages got[FS_STUDY_MAX_RUNS];
    int n = 0; /* an item timed with another --repeat is rendered again: e->runs holds `repeat` */
    if (f == 0 &&
        (fs_read_image_attr(exr, "fluidsurf:runs", runs, sizeof runs) != 1 ||
         (n = fs_runs_parse(runs, got, FS_STUDY_MAX_RUNS)) != repeat))
        return 0;
    float r;
    memset(v, 0, sizeof *v);
    if (fs_read_render(exr, &v->g, &v->rgba, &r)) {
        fs_run_image_free(v);
        return 0;
    }
    e->frame_ms[f] = strtod(ms, NULL);
    if (f == 0) memcpy(e->runs, got, (size_t)(e->nruns = n) * sizeof *got);
    return 1;
}
