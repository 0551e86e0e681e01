/* The reference cache as compare and render use it (docs/DESIGN.md, "Reference
 * cache"): the folder from --cache / --no-cache, one-line warnings, and one
 * frame's reference view loaded from the cache or rendered and stored. */
#ifndef FS_REF_CACHE_H
#define FS_REF_CACHE_H
#include "gbuffer_cache.h"
#include "run.h"
#include "study.h"

typedef struct fs_ref_cache {
    fs_gcache gc;
    int on;         /* 0: no cache (turned off, or its folder is unusable) */
    int quiet;      /* no note about a bad entry */
    int counters;   /* views come with the work counts of a counting render */
    char why[1200]; /* why it is off, for the report */
} fs_ref_cache;

/* dir: the --cache folder, or NULL for the default ($XDG_CACHE_HOME/fluidsurf,
 * else ~/.cache/fluidsurf) when use_default, else off. A folder that cannot be
 * made or written gives one warning line naming it, and the cache stays off. */
void fs_ref_cache_open(fs_ref_cache *c, const char *dir, int use_default, int quiet);

/* Frame p's view of run into im: from the cache (stage "cache", the time to
 * hash the key and load and check the entry, then "shade"), or uploaded
 * (grid g, or NULL to build one), rendered and shaded (the run's stages),
 * then stored (stage "cache_store"). base and frame give the entry's
 * provenance (fs_run_provenance). A bad entry is re-rendered and replaced.
 * With c->counters a counting render follows the timed one and its counts are
 * stored in the entry; an entry without counts is then a miss. The counting
 * render adds no stage to st and lies outside every stage's span: time the
 * view by fs_stages_total(st), never by a clock around this call. */
int fs_ref_cache_render(fs_ref_cache *c, fs_run *run, const fs_scene *s, const fs_particles *p, const fs_grid *g,
                        const fs_provenance *base, int frame, fs_run_image *im, fs_stages *st, fs_study_made *out);

#endif
