#include "ref_cache.h"
#include "fs_error.h"
#include "render_key.h"
#include "stage_counts.h"
#include "timing.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* $XDG_CACHE_HOME/fluidsurf (an absolute one, as the XDG spec asks), else ~/.cache/fluidsurf. */
static int default_dir(char *buf, int size)
{
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    if (xdg && xdg[0] == '/') return snprintf(buf, size, "%s/fluidsurf", xdg) < size ? FS_OK : FS_ERR_RUNTIME;
    if (home && *home) return snprintf(buf, size, "%s/.cache/fluidsurf", home) < size ? FS_OK : FS_ERR_RUNTIME;
    return fs_fail(FS_ERR_RUNTIME, "no cache folder: neither XDG_CACHE_HOME nor HOME is set");
}

static void turn_off(fs_ref_cache *c)
{
    snprintf(c->why, sizeof c->why, "%s", fs_error_message());
    fprintf(stderr, "fluidsurf: warning: %s; continuing without the cache\n", c->why);
    c->on = 0;
}

void fs_ref_cache_open(fs_ref_cache *c, const char *dir, int use_default, int quiet)
{
    char buf[FS_GCACHE_PATH];
    memset(c, 0, sizeof *c);
    c->quiet = quiet;
    if (!dir && !use_default) {
        snprintf(c->why, sizeof c->why, "turned off");
        return;
    }
    int rc = dir ? FS_OK : default_dir(buf, sizeof buf);
    if (!rc) rc = fs_gcache_open(&c->gc, dir ? dir : buf);
    c->on = 1;
    if (rc) turn_off(c);
}

/* The entry of key into im->g (and its counts): 1 on a hit; a bad entry is
 * named on stderr; one without the counts wanted is a miss. */
static int load_entry(fs_ref_cache *c, fs_digest key, const fs_scene *s, fs_run_image *im, fs_stages *counts)
{
    fs_gbuffer g;
    char text[FS_GCACHE_COUNTS];
    fs_gcache_result res = fs_gcache_load(&c->gc, key, s->camera.width, s->camera.height, &g, text, sizeof text);
    if (res == FS_GCACHE_BAD && !c->quiet)
        fprintf(stderr, "fluidsurf: warning: bad cache entry, rendering it again: %s\n", fs_error_message());
    if (res != FS_GCACHE_HIT) return 0;
    if (c->counters && fs_stage_counts_parse(text, counts)) { /* made without counting: count now */
        fs_gbuffer_free(&g);
        return 0;
    }
    fs_gbuffer_free(&im->g);
    im->g = g;
    return 1;
}

static void store_entry(fs_ref_cache *c, fs_digest key, fs_run *run, const fs_provenance *base, int frame,
                        const fs_run_image *im, const fs_stages *counts)
{
    fs_provenance prov;
    char text[FS_GCACHE_COUNTS] = "";
    fs_run_provenance(run, base, frame, &prov);
    static int warned;
    if (counts && fs_stage_counts_format(counts, text, sizeof text)) { /* cannot happen for FS_MAX_STAGES stages */
        if (!warned++) /* stored without: later --counters runs miss and count again */
            fprintf(stderr, "fluidsurf: warning: cache entry stored without its work counts: %s\n", fs_error_message());
        text[0] = 0;
    }
    if (fs_gcache_store(&c->gc, key, &im->g, im->rgba, &prov, text)) turn_off(c);
}

/* The counting render after the timed one, on the same inputs. It adds no
 * stage to the caller's table and runs outside every timed span: callers time
 * a view as the sum of its stages (docs/DESIGN.md, "Work counters"). */
static int count_view(fs_run *run, const fs_scene *s, const fs_particles *p, const fs_grid *g, fs_stages *counts)
{
    fs_run_image cim = {0};
    int rc = fs_run_count(fs_run_method(run), s, fs_run_values(run), NULL, p, g, &s->camera, &cim, counts);
    fs_run_image_free(&cim);
    return rc;
}

/* The floor an upload of p would set (the grid's bulk, or the particles'). */
static float floor_y(const fs_scene *s, const fs_particles *p, const fs_grid *g)
{
    if (!p->n) return 0;
    return g ? fs_scene_floor(s, g) : fs_scene_floor_of(s, p);
}

int fs_ref_cache_render(fs_ref_cache *c, fs_run *run, const fs_scene *s, const fs_particles *p, const fs_grid *g,
                        const fs_provenance *base, int frame, fs_run_image *im, fs_stages *st, fs_study_made *out)
{
    fs_stages local = {0};
    if (!st) st = &local;
    memset(out, 0, sizeof *out);
    if (!c->on) {
        int rc = fs_study_render_once(run, s, p, g, im, st);
        return !rc && c->counters ? count_view(run, s, p, g, &out->counts) : rc;
    }
    double t0 = fs_now_ms();
    fs_field f = fs_scene_field(s);
    fs_digest key = fs_render_key(fs_run_method(run), fs_run_values(run), &f, &s->camera, p);
    fs_gcache_entry(&c->gc, key, out->entry, sizeof out->entry);
    if ((out->hit = load_entry(c, key, s, im, &out->counts))) {
        fs_stages_add(st, "cache", fs_now_ms() - t0);
        fs_run_set_floor(run, floor_y(s, p, g)); /* what an upload would set */
        return fs_run_shade(run, &s->camera, im, FS_APPEARANCE_SHARED, st);
    }
    double lookup = fs_now_ms() - t0;
    fs_run_set_floor(run, floor_y(s, p, g)); /* a hit before may have set another frame's */
    int rc = fs_study_render_once(run, s, p, g, im, st);
    if (!rc && c->counters) rc = count_view(run, s, p, g, &out->counts); /* between the timed spans */
    if (rc) return rc;
    double t1 = fs_now_ms(); /* cache_store: the lookup and this write, not the counting */
    store_entry(c, key, run, base, frame, im, c->counters ? &out->counts : NULL);
    if (!c->on) out->entry[0] = 0;
    fs_stages_add(st, "cache_store", lookup + fs_now_ms() - t1);
    return FS_OK;
}
