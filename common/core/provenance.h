/* Provenance of every output (docs/DESIGN.md, "Provenance"): version, commit, renderer, threads,
 * seed, scene hash, r, camera, method parameters, as name/value strings that
 * become EXR header attributes, report lines or CSV comments. */
#ifndef FS_PROVENANCE_H
#define FS_PROVENANCE_H
#ifdef __cplusplus
extern "C" {
#endif

#define FS_PROV_MAX 40

/* A string attribute (EXR header entry). */
typedef struct fs_attr {
    const char *name, *value;
} fs_attr;

/* fluidsurf's version, the commit it was built at ("unknown" outside git) and whether the
 * tree outside results/ differed from that commit (1) or not (0) (generated fs_version.c). */
extern const char fs_version[];
extern const char fs_commit[];
extern const int fs_dirty;

typedef struct fs_provenance {
    int n;
    fs_attr attr[FS_PROV_MAX];
    char name[FS_PROV_MAX][48];
    char value[FS_PROV_MAX][640];
} fs_provenance;

/* Version, commit, renderer (GL_RENDERER, or NULL: "CPU"), GL version and threads;
 * scene/scene_provenance.h adds the scene's entries. */
void fs_provenance_init_base(fs_provenance *p, const char *renderer, const char *gl_version);
/* Adds or replaces "fluidsurf:NAME". */
void fs_provenance_set(fs_provenance *p, const char *name, const char *value);
/* The value of "fluidsurf:NAME", NULL when p has none. */
const char *fs_provenance_get(const fs_provenance *p, const char *name);
/* One line "# k=v; k=v ..." for CSV headers. */
void fs_provenance_line(const fs_provenance *p, char *buf, int size);

#ifdef __cplusplus
}
#endif
#endif
