/* Whether two images can be compared: the one rule of `fluidsurf diff` and of the
 * library's metrics (fluidsurf_metrics_compute3, Python's metrics()), from their
 * sizes and provenance (docs/DESIGN.md, "Metrics"). A different size or camera is
 * refused always; a different scene or r is a finding the caller warns about, or
 * refuses under strict. */
#ifndef FS_COMPARABLE_H
#define FS_COMPARABLE_H
#ifdef __cplusplus
extern "C" {
#endif

/* One image as the rule sees it: its name in messages (a file, "image"), its size,
 * the provenance values fluidsurf:camera ("eye=x,y,z;target=...;up=...;fov=f;...")
 * and fluidsurf:scene_hash ("" or NULL when it has none), and r (0: none). */
typedef struct fs_comparable {
    const char *name;
    int w, h;
    const char *camera, *scene_hash;
    float r;
} fs_comparable;

enum { FS_COMPARABLE_MAX_FINDINGS = 3, FS_COMPARABLE_FINDING_LEN = 400 };

/* The findings that do not refuse by themselves (one each at most: camera, scene, r). */
typedef struct fs_comparable_findings {
    int n;
    char text[FS_COMPARABLE_MAX_FINDINGS][FS_COMPARABLE_FINDING_LEN];
} fs_comparable_findings;

typedef struct fs_comparable_rules {
    const char *strict;  /* NULL, or the switch that refuses the findings ("--strict"), named in the refusal */
    int report_missing;  /* 1: what an image lacks is a finding (diff); 0: only what both carry is checked */
    int radius_given;    /* the caller gave r: a missing r is no finding */
    const char *r_which; /* which r the depth errors are in, said after a different r ("the first file's r") */
} fs_comparable_rules;

/* FS_ERR_INPUT (fs_fail: one line naming both images and what differs) for a
 * different size or camera, or under rules->strict for the first finding; else
 * FS_OK with the findings in found (the caller warns). Cameras agree when eye,
 * target, up and fov agree within a relative 1e-6, r within the same. */
int fs_comparable_check(const fs_comparable im[2], const fs_comparable_rules *rules, fs_comparable_findings *found);

#ifdef __cplusplus
}
#endif
#endif
