/* A scene (JSON, cJSON): particle source, units, field, camera, light,
 * material, background and per-method parameters. Command-line flags and
 * the caller's settings override it. See the scenes in experiments/scenes/ and README.md for the keys. */
#ifndef FS_SCENE_H
#define FS_SCENE_H
#include "camera.h"
#include "kernels.h"
#include "obstacles.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_PATH_MAX 1024
#define FS_MAX_SETS 64

typedef enum { FS_MATERIAL_WATER = 0, FS_MATERIAL_OPAQUE } fs_material_kind;
typedef enum { FS_BACKGROUND_SKY = 0, FS_BACKGROUND_CHECKER } fs_background_kind;
typedef enum { FS_SYNTH_NONE = 0, FS_SYNTH_SLAB, FS_SYNTH_SPHERE, FS_SYNTH_BOX } fs_synth_shape;
/* Where r came from, for the provenance (r_source=...). */
typedef enum { FS_R_DEFAULT = 0, FS_R_SCENE, FS_R_FILE, FS_R_OPTION, FS_R_ESTIMATED } fs_radius_source;
/* Where the up axis came from; FS_UP_AUTO: the first frame decides (up_axis.h). */
typedef enum { FS_UP_DEFAULT = 0, FS_UP_SCENE, FS_UP_OPTION, FS_UP_AUTO } fs_up_source;

typedef struct fs_synthetic {
    fs_synth_shape shape;
    int size[3];  /* particles per axis (slab, box); size[0] = diameter in particles (sphere) */
    float jitter; /* amplitude in multiples of r (default 0.1) */
    unsigned seed;
    int moving; /* sequence: 0 re-jitter per frame, 1 also translate */
} fs_synthetic;

/* A "method.param=value" setting, parsed once: split when it is added and, once the
 * method layer has installed its resolver (fs_scene_set_resolver), resolved there too.
 * The scene sits below the method registry, so it holds the method only as an opaque
 * pointer the registry gave it. */
typedef struct fs_scene_setting {
    char text[160];     /* as written: messages name it */
    const void *method; /* the fs_method it sets; NULL: not resolved yet (no resolver) */
    int param;          /* index in that method's parameter table */
    double value;       /* parsed against that parameter */
} fs_scene_setting;
typedef int (*fs_scene_resolver)(fs_scene_setting *set);

typedef struct fs_scene {
    char path[FS_PATH_MAX];      /* the scene file itself, "" when built from flags */
    char source[FS_PATH_MAX];    /* particle file or printf pattern; "" for synthetic */
    char format[16];             /* forced particle format, "" = from the extension */
    int frame_first, frame_last; /* for a pattern source; -1 when not a sequence */
    int frame_step;              /* every frame_step-th frame of first..last (1: each) */
    fs_synthetic synth;

    float radius; /* particle radius r */
    fs_radius_source r_source;
    float spacing_r;    /* the r the first frame's spacing implies, 0 when not measured: the
                      * framing and the up guess read it, so --radius moves neither */
    float volume_scale; /* V = volume_scale (2r)^3 */
    fs_kernel kernel;
    float support_r; /* H in multiples of r */
    float iso;
    int up_axis; /* 0 x, 1 y, 2 z */
    fs_up_source up_source;

    fs_camera camera;
    int has_camera;     /* 0: frame the particles */
    int camera_up_auto; /* a placed camera without an up of its own: it follows up_axis */

    float light_dir[3]; /* towards the light, world space */
    float light_color[3];
    float ambient;

    fs_material_kind material;
    float material_color[3]; /* opaque albedo, or water's tint */
    float ior;
    float absorption[3]; /* water, per scene unit of thickness */

    fs_background_kind background;
    fs_obstacles obstacles; /* static solids, drawn opaque (obstacles.h) */

    int nsets;
    fs_scene_setting sets[FS_MAX_SETS]; /* scene first, then the caller's */
    unsigned long long hash;            /* the scene hash (hash.h) of the scene file bytes, or of the flags */
} fs_scene;

void fs_scene_defaults(fs_scene *s);
/* The method layer's resolver (the registry installs it when a method is registered):
 * from then on fs_scene_add_set resolves each setting as it stores it, and refuses an
 * unknown method or parameter or a bad value there. NULL: settings are only split. */
void fs_scene_set_resolver(fs_scene_resolver r);
/* "default", "scene", "file", "option", "estimated"; "auto" ... for up. */
const char *fs_radius_source_name(fs_radius_source r);
const char *fs_up_source_name(fs_up_source u);
/* Reads a scene file; FS_ERR_INPUT with "path: what" on malformed JSON, bad keys
 * or values. Relative particle paths are resolved against the scene's folder. */
int fs_scene_load(fs_scene *s, const char *path);
/* Appends "method.param=value", resolved when there is a resolver (FS_ERR_INPUT if the
 * list is full, the text malformed, or the resolver refuses it). */
int fs_scene_add_set(fs_scene *s, const char *set);
fs_field fs_scene_field(const fs_scene *s);
/* Places the camera c (has_camera); up_given 0: its up follows the scene's up
 * axis (camera_up_auto), as a scene file's camera without "up" does. */
void fs_scene_place_camera(fs_scene *s, const fs_camera *c, int up_given);
/* Writes s as a scene file that reproduces it: r, the up axis and the camera as
 * settled (call it after the first frame is adopted), paths absolute, numbers
 * exact; atomically (output_file.h). */
int fs_scene_save(const fs_scene *s, const char *path);
/* Completes the camera: frames the box when has_camera is 0, turns a placed
 * camera's up to the scene's up axis when camera_up_auto, sets clip planes. */
void fs_scene_finish_camera(fs_scene *s, const float bmin[3], const float bmax[3]);
struct fs_particles;
struct fs_grid;
/* Height of the checker floor: the bulk's lowest point minus r, along up (the
 * grid's bulk box, so a far stray below the fluid does not sink the floor). */
float fs_scene_floor(const fs_scene *s, const struct fs_grid *g);
/* The same floor from the particles, when no grid is at hand (builds one). */
float fs_scene_floor_of(const fs_scene *s, const struct fs_particles *p);
/* The same for a particle set: frames the 1%..99% quantile box, grown by r, of
 * the particles in the bulk box (so neither spray nor far strays shrink the fluid
 * to a corner), and clips with the bulk box (docs/DESIGN.md, "Neighbour grid").
 * With spacing_r set, the bulk's cells and the growth are of spacing_r, not r:
 * the framing then reads the particles alone, and --radius does not move it. */
void fs_scene_frame_particles(fs_scene *s, const struct fs_particles *p);

#ifdef __cplusplus
}
#endif
#endif
