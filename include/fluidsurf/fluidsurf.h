/* fluidsurf: the public C API (docs/DESIGN.md, "The library").
 *
 * Render the surface of a particle fluid with any of fluidsurf's methods into a
 * G-buffer you can read, run the exact reference and compute the metrics
 * between two G-buffers, from your own arrays or from particle files.
 *
 *   fluidsurf_particles *p;  fluidsurf_scene *s;  fluidsurf_image *im;
 *   fluidsurf_particles_wrap(n, x, y, z, &p);     // your arrays, not copied
 *   fluidsurf_scene_new(&s);
 *   fluidsurf_scene_set_radius(s, 0.025);
 *   if (fluidsurf_render(s, p, "raycast_pca", NULL, 0, &im))
 *       fprintf(stderr, "%s\n", fluidsurf_last_error());
 *   const float *depth = fluidsurf_image_layer(im, "depth", NULL);
 *
 * Conventions: scene units; images are row-major, rows top to bottom, with
 * interleaved components; depth is the positive eye-space distance along the
 * view axis (INFINITY where empty), normals unit view-space vectors facing the
 * camera. Every function that can fail returns FLUIDSURF_OK (0) or an error
 * code, with one line for fluidsurf_last_error() (per thread). Nothing here
 * prints or calls exit(). Renders may be called from any thread; they run one
 * at a time (each uses every core), and GL methods share one OpenGL context:
 * OSMesa, or EGL with FLUIDSURF_GL=egl in the environment; FLUIDSURF_REQUIRE_GPU=1
 * makes a GL render on a software renderer (llvmpipe) fail with
 * FLUIDSURF_ERR_RUNTIME, its message naming the renderer.
 *
 * Versioning: FLUIDSURF_API_VERSION grows with every change; a program built
 * against version V runs with any library whose fluidsurf_api_version() >= V
 * and whose soname (libfluidsurf.so.0) is the same. So a struct the caller
 * allocates never grows (a program built against an older header would pass one
 * too small): new fields come in a new struct, filled by a new function.
 * Version 2 added fluidsurf_depth_metrics and fluidsurf_metrics_compute2.
 * Version 3 added fluidsurf_mesh (fluidsurf_mesh_build and its accessors), and
 * messages that name settings as written ("raycast_pca.normals=x: ...") and list
 * the valid methods or parameters, with no command-line flags in them.
 * Version 4 added fluidsurf_compare (a study through compare's engine) and its
 * tables, and fluidsurf_image_set_solid_depth.
 * Version 5 added fluidsurf_compare_to_dir (the study's whole folder, as
 * `fluidsurf compare -o DIR` writes it).
 * Version 6 added fluidsurf_metrics_compute3 (the metrics after `fluidsurf diff`'s
 * check that two images can be compared); fluidsurf_image_read keeps the file's
 * provenance and camera; fluidsurf_image_set_provenance, fluidsurf_image_set_layer
 * and fluidsurf_image_write; fluidsurf_mesh_from_arrays, fluidsurf_mesh_write and
 * a mesh's provenance; fluidsurf_particles_estimate_radius and
 * fluidsurf_particles_stats (what `fluidsurf info` reports).
 * Version 7 added fluidsurf_particles_array_count and fluidsurf_particles_array
 * (a particle file's other point arrays, which `fluidsurf info` lists).
 * Version 8 added the command line's input and camera options:
 * fluidsurf_scene_set_source (a particle file, or a frame pattern with
 * FIRST:LAST:STEP), fluidsurf_scene_set_camera_text (--camera's text) and
 * fluidsurf_scene_save (render --save-scene); fluidsurf_scene_set_camera takes
 * up = 0 for the scene's up axis. */
#ifndef FLUIDSURF_H
#define FLUIDSURF_H
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif
#pragma GCC visibility push(default)

/* The text between the cffi markers is also the Python module's declaration
 * list (python/fluidsurf/__init__.py): plain C only, no preprocessor. */
/* cffi:begin */
enum { FLUIDSURF_API_VERSION = 8 };
enum { FLUIDSURF_OK = 0, FLUIDSURF_ERR_RUNTIME = 1, FLUIDSURF_ERR_INPUT = 2 };

int fluidsurf_api_version(void);
/* "0.1.0 (commit abc1234)" */
const char *fluidsurf_version(void);
/* The message of this thread's last failure, one line. */
const char *fluidsurf_last_error(void);

/* ---- particles ---------------------------------------------------------- */
typedef struct fluidsurf_particles fluidsurf_particles;

/* n particles at (x[i], y[i], z[i]): the arrays are the caller's, used in
 * place (not copied), and must stay valid and unchanged while p is used. */
int fluidsurf_particles_wrap(size_t n, const float *x, const float *y, const float *z, fluidsurf_particles **out);
/* Linear RGB colours, 3 floats per particle, used in place as above (NULL: none). */
int fluidsurf_particles_set_color(fluidsurf_particles *p, const float *rgb);
/* Reads a particle file (PLY, BGEO, VTK, VTU, VDB, raw, CSV; format from the
 * extension, or format = "ply", ...). The library owns its arrays. */
int fluidsurf_particles_read(const char *path, const char *format, fluidsurf_particles **out);
size_t fluidsurf_particles_count(const fluidsurf_particles *p);
/* The radius stored in the file, 0 when it has none (or for wrapped arrays). */
double fluidsurf_particles_radius(const fluidsurf_particles *p);
/* A column: "x", "y", "z", "vx", "vy", "vz" (1 float each), "color" (3 floats
 * each), "phase" (1 int32 each); NULL when absent. ncomp may be NULL. */
const void *fluidsurf_particles_column(const fluidsurf_particles *p, const char *name, int *ncomp);
/* Since version 7: a read file's other point arrays, those `fluidsurf info` lists
 * and `convert` writes (DualSPHysics' Idp and Rhop, SPlisHSPlasH's id): how many
 * (0 for wrapped arrays), and array i (0 <= i < count): its name (owned by p),
 * components per particle and type, and its count x ncomp values, particle after
 * particle; NULL for an i out of range. name, ncomp and type may be NULL. */
enum { FLUIDSURF_ARRAY_F32 = 0, FLUIDSURF_ARRAY_F64 = 1, FLUIDSURF_ARRAY_I32 = 2, FLUIDSURF_ARRAY_U32 = 3 };
int fluidsurf_particles_array_count(const fluidsurf_particles *p);
const void *fluidsurf_particles_array(const fluidsurf_particles *p, int i, const char **name, int *ncomp, int *type);
void fluidsurf_particles_free(fluidsurf_particles *p);
/* Since version 6: the radius the spacing implies, as a render without one
 * estimates it (r = (volume per particle)^(1/3) / 2, from the 32 nearest
 * neighbours of a fixed sample of 4096 particles). FLUIDSURF_ERR_INPUT for
 * fewer than 2 particles or no spacing (all at one point). */
int fluidsurf_particles_estimate_radius(const fluidsurf_particles *p, double *radius);
/* Since version 6: what `fluidsurf info` reports. */
enum { FLUIDSURF_R_GIVEN = 0, FLUIDSURF_R_FILE = 1, FLUIDSURF_R_ESTIMATED = 2, FLUIDSURF_R_DEFAULT = 3 };
typedef struct fluidsurf_particles_info {
    size_t count;
    double bbox_min[3], bbox_max[3];
    double radius;           /* the r of the numbers below: the radius given, else the file's, else the estimate, else
                                the default */
    int radius_source;       /* FLUIDSURF_R_GIVEN, _FILE, _ESTIMATED or _DEFAULT */
    double estimated_radius; /* the r the spacing implies; 0 when there is no spacing */
    double nn_median;        /* median distance to the nearest neighbour (a fixed sample of 4096) */
    double density_median;   /* median normalised density phi at particle centres (cubic, support 4r) */
    double volume_scale;     /* the one phi was computed with: volume_scale / density_median would make it 1 */
} fluidsurf_particles_info;
/* radius: 0 for none given; volume_scale: V = volume_scale (2r)^3 (1: the default). */
int fluidsurf_particles_stats(const fluidsurf_particles *p, double radius, double volume_scale,
                              fluidsurf_particles_info *out);

/* ---- scene: field, camera, appearance, method settings ----------------- */
typedef struct fluidsurf_scene fluidsurf_scene;

typedef struct fluidsurf_field {
    double radius;       /* particle radius r */
    double volume_scale; /* particle volume V = volume_scale (2r)^3 */
    double support;      /* kernel support H, in multiples of r */
    double iso;          /* iso value of the density field */
    char kernel[16];     /* "cubic", "poly6", "spiky", "wyvill" */
} fluidsurf_field;

typedef struct fluidsurf_camera {
    double eye[3], target[3], up[3];
    double fov_deg;    /* vertical field of view */
    int width, height; /* pixels */
} fluidsurf_camera;

/* The defaults of a scene built from a bare particle file (README.md, "Scenes");
 * its camera frames the particles at each render, as the command line does, and
 * its up axis is "auto" (chosen from the particles at render time). */
int fluidsurf_scene_new(fluidsurf_scene **out);
/* A scene file (JSON), with its particle source, field, camera and settings. */
int fluidsurf_scene_load(const char *path, fluidsurf_scene **out);
int fluidsurf_scene_copy(const fluidsurf_scene *s, fluidsurf_scene **out);
void fluidsurf_scene_free(fluidsurf_scene *s);
int fluidsurf_scene_get_field(const fluidsurf_scene *s, fluidsurf_field *f);
/* radius 0 keeps r unset: the file's, else the one the spacing implies. */
int fluidsurf_scene_set_field(fluidsurf_scene *s, const fluidsurf_field *f);
/* The up axis: "x", "y", "z", or "auto" (the particles decide at render time,
 * as `--up auto` does; the image's provenance "up" says which and why). */
int fluidsurf_scene_set_up(fluidsurf_scene *s, const char *up);
int fluidsurf_scene_set_radius(fluidsurf_scene *s, double radius);
/* The scene's camera; *placed is 0 while it is framed on the particles at render time. */
int fluidsurf_scene_get_camera(const fluidsurf_scene *s, fluidsurf_camera *c, int *placed);
/* Places the camera (no framing any more). An up of 0, 0, 0 (since version 8)
 * follows the scene's up axis, as a scene file's camera without "up" does. */
int fluidsurf_scene_set_camera(fluidsurf_scene *s, const fluidsurf_camera *c);
/* Since version 8: places the camera from the command line's --camera text,
 * "eye=X,Y,Z;target=X,Y,Z[;up=x|y|z|X,Y,Z][;fov=DEG][;size=WxH]"; keys left out
 * keep the scene's camera's values, and without up= its up follows the scene's
 * up axis. FLUIDSURF_ERR_INPUT naming the problem (nothing changed) otherwise. */
int fluidsurf_scene_set_camera_text(fluidsurf_scene *s, const char *text);
/* The image size; the camera stays framed or placed. */
int fluidsurf_scene_set_size(fluidsurf_scene *s, int width, int height);
/* A method parameter, "method.param=value", as --set on the command line; parsed and checked
 * against the method's parameters here (FLUIDSURF_ERR_INPUT, nothing stored, when it is bad). */
int fluidsurf_scene_set(fluidsurf_scene *s, const char *setting);
/* A scene with a particle source: its frames are first..last (0..0 for one file). */
int fluidsurf_scene_frames(const fluidsurf_scene *s, int *first, int *last);
int fluidsurf_scene_read_frame(const fluidsurf_scene *s, int frame, fluidsurf_particles **out);
/* Since version 8: the scene's particle source, as the command line's input: a
 * particle file (first = last = step = 0), or a frame pattern ("f_%04d.vtk" or
 * "f_{}.vtk") read at frames first, first + step, ... up to last (--frames
 * FIRST:LAST:STEP). fluidsurf_compare with frames NULL then compares those frames. */
int fluidsurf_scene_set_source(fluidsurf_scene *s, const char *path, int first, int last, int step);
/* Since version 8: writes the scene as a scene file (path ending .json), as
 * `render --save-scene` does: settled on p as a render of p settles it (r, the
 * up axis and the framed camera), so that loading the file and rendering p with
 * it gives the same image. Numbers exact, paths absolute; the scene needs a
 * particle source (a scene file's, or fluidsurf_scene_set_source), whose frames
 * the file names (p is not written). FLUIDSURF_ERR_INPUT without one. */
int fluidsurf_scene_save(const fluidsurf_scene *s, const fluidsurf_particles *p, const char *path);

/* ---- methods ------------------------------------------------------------ */
typedef struct fluidsurf_param {
    const char *name;
    const char *type; /* "float", "int", "bool", "enum" */
    double default_value, min, max;
    const char *choices; /* enum: "a|b|c" (the value is the index), else "" */
    const char *help;    /* one line, with units */
} fluidsurf_param;

int fluidsurf_method_count(void);
/* The i-th method's name, NULL past the end. "reference" is the exact CPU ray caster. */
const char *fluidsurf_method_name(int i);
const char *fluidsurf_method_description(const char *method);
const char *fluidsurf_method_paper(const char *method);
/* 1 when the method renders through OpenGL, 0 when on the CPU, -1 when unknown. */
int fluidsurf_method_needs_gl(const char *method);
/* Its parameters' count (-1: unknown method) and the j-th one. */
int fluidsurf_param_count(const char *method);
int fluidsurf_param_info(const char *method, int j, fluidsurf_param *out);

/* ---- rendering ---------------------------------------------------------- */
typedef struct fluidsurf_image fluidsurf_image;

/* Renders method on particles p into a new image: the G-buffer and the shared
 * shading. params: nparams "param=value" settings of this method, applied
 * after the scene's. A scene without a placed camera frames p (and, without
 * a radius, takes the file's or estimates r from the spacing, as the command
 * line does). */
int fluidsurf_render(const fluidsurf_scene *s, const fluidsurf_particles *p, const char *method,
                     const char *const *params, int nparams, fluidsurf_image **out);
/* The exact reference: fluidsurf_render with method "reference". */
int fluidsurf_reference(const fluidsurf_scene *s, const fluidsurf_particles *p, fluidsurf_image **out);
/* A G-buffer EXR written by fluidsurf (render -o OUT.exr, compare), with its
 * provenance (every "fluidsurf:NAME" attribute) and, since version 5, the camera
 * its fluidsurf:camera names (fluidsurf_image_camera). */
int fluidsurf_image_read(const char *path, fluidsurf_image **out);
/* An image of your own arrays (copied), w x h pixels: depth (1 per pixel,
 * INFINITY where empty), normal (3), coverage (1, 0 or 1); thickness (1) and
 * rgba (4, linear) may be NULL. radius: its r (0: none). For metrics against
 * your own renderer. */
int fluidsurf_image_from_arrays(int w, int h, const float *depth, const float *normal, const float *thickness,
                                const float *coverage, const float *rgba, double radius, fluidsurf_image **out);
/* Since version 4: the solids' depth at each pixel (w x h floats, 0 or INFINITY
 * where no solid is hit), copied into the layer "solid_depth", so that metrics
 * of an image made from arrays leave out what the solids hide, as compare does. */
int fluidsurf_image_set_solid_depth(fluidsurf_image *im, const float *solid_depth);
/* Since version 6: adds or replaces the provenance entry name ("fluidsurf:NAME",
 * under 48 characters; value under 640), e.g. of an image made from arrays that a
 * render had returned, so that fluidsurf_metrics_compute3 can check it. A
 * "fluidsurf:camera" must read as a camera ("eye=x,y,z;target=...;up=...;fov=f;size=WxH"). */
int fluidsurf_image_set_provenance(fluidsurf_image *im, const char *name, const char *value);
/* Since version 6: a layer (AOV) name of ncomp (1 or 4) floats per pixel, copied
 * (fluidsurf_image_set_solid_depth is name "solid_depth", 1); an existing one of
 * that name is written over. Not a core layer (depth, normal, ...). */
int fluidsurf_image_set_layer(fluidsurf_image *im, const char *name, int ncomp, const float *data);
/* Since version 6: the image as `fluidsurf render -o` writes it, by the extension:
 * .png (the shaded image, sRGB) or .exr (RGBA, the G-buffer, every layer, and the
 * provenance as attributes), into a temporary file renamed at the end.
 * FLUIDSURF_ERR_INPUT for another extension or an image without rgba. */
int fluidsurf_image_write(const fluidsurf_image *im, const char *path);
void fluidsurf_image_free(fluidsurf_image *im);
int fluidsurf_image_width(const fluidsurf_image *im);
int fluidsurf_image_height(const fluidsurf_image *im);
/* The radius r the image was rendered with. */
double fluidsurf_image_radius(const fluidsurf_image *im);
/* The camera it was rendered with (the framing chosen, when the scene had
 * none): pass it to fluidsurf_scene_set_camera to keep a sequence's view, or to
 * render a read EXR's view again. FLUIDSURF_ERR_INPUT for an image made from
 * arrays, or read from a file without fluidsurf:camera. */
int fluidsurf_image_camera(const fluidsurf_image *im, fluidsurf_camera *c);
/* A layer: "depth" (1), "normal" (3), "thickness" (1), "coverage" (1), "rgba"
 * (4, the linear shaded image) or an AOV by name; NULL when absent. */
const float *fluidsurf_image_layer(const fluidsurf_image *im, const char *name, int *ncomp);
int fluidsurf_image_aov_count(const fluidsurf_image *im);
const char *fluidsurf_image_aov_name(const fluidsurf_image *im, int i);
/* The render's stages ("grid", "upload", "march", "shade", ...), their wall
 * times in ms, and the renderer each ran on ("CPU" or GL_RENDERER). */
int fluidsurf_image_stage_count(const fluidsurf_image *im);
const char *fluidsurf_image_stage_name(const fluidsurf_image *im, int i);
double fluidsurf_image_stage_ms(const fluidsurf_image *im, int i);
const char *fluidsurf_image_stage_renderer(const fluidsurf_image *im, int i);
/* Provenance, "fluidsurf:NAME" entries as in the EXRs (version, commit, method, params, ...). */
int fluidsurf_image_provenance_count(const fluidsurf_image *im);
const char *fluidsurf_image_provenance_name(const fluidsurf_image *im, int i);
const char *fluidsurf_image_provenance_value(const fluidsurf_image *im, int i);

/* ---- metrics ------------------------------------------------------------ */
typedef struct fluidsurf_metrics {
    double mask_iou;        /* coverage IoU (1 when both are empty) */
    double depth_bias_r;    /* mean depth difference where both cover, in r */
    double depth_rmse_r;    /* RMS of the difference around the bias, in r */
    double depth_p95_r;     /* 95th percentile of |difference - bias|: around the mean */
    double normal_mean_deg; /* mean normal angle where both cover */
    double normal_p95_deg;
    double interior_normal_mean_deg; /* >= 3 px from either silhouette */
    double psnr_db;                  /* shaded luminance; INFINITY when equal */
    double ssim;
    size_t n_both, n_union, n_interior;
} fluidsurf_metrics;

/* A method's image against a reference's (the same size); radius: r for the
 * depth errors (<= 0: the reference image's). NAN where no pixel counts. Where
 * an image carries the layer "solid_depth" (rendered in a scene with solids, or
 * read from such an EXR; the reference's first), the pixels a solid hides are
 * left out, as fluidsurf compare leaves them out. */
int fluidsurf_metrics_compute(const fluidsurf_image *method, const fluidsurf_image *reference, double radius,
                              fluidsurf_metrics *out);

/* Since version 2: the depth difference e (method - reference, in r, where both
 * cover) itself rather than around its mean, which a few far outliers pull. */
typedef struct fluidsurf_depth_metrics {
    double depth_median_r;  /* median of e (signed) */
    double depth_abs_p50_r; /* 50th, 95th, 99th percentiles of |e| (nearest rank) */
    double depth_abs_p95_r;
    double depth_abs_p99_r;
    double depth_over_1r_frac; /* share of the pixels both cover with |e| > 1 */
} fluidsurf_depth_metrics;

/* fluidsurf_metrics_compute, plus the depth metrics above into depth (NULL: none). */
int fluidsurf_metrics_compute2(const fluidsurf_image *method, const fluidsurf_image *reference, double radius,
                               fluidsurf_metrics *out, fluidsurf_depth_metrics *depth);
/* Since version 6: fluidsurf_metrics_compute2 after the check `fluidsurf diff`
 * makes, with its wording: images of different sizes, or of different cameras
 * (provenance fluidsurf:camera), are refused (FLUIDSURF_ERR_INPUT); a different
 * scene (fluidsurf:scene_hash) or r is a warning, one line each into warnings
 * (size bytes, lines separated by '\n', "" when none; NULL: not wanted), or with
 * FLUIDSURF_METRICS_STRICT a refusal, as `diff --strict`. Only what both images
 * carry is checked: images made from arrays without provenance pass. */
enum { FLUIDSURF_METRICS_STRICT = 1 };
int fluidsurf_metrics_compute3(const fluidsurf_image *method, const fluidsurf_image *reference, double radius,
                               int flags, fluidsurf_metrics *out, fluidsurf_depth_metrics *depth, char *warnings,
                               size_t size);
/* ---- meshes (since version 3) ------------------------------------------ */
typedef struct fluidsurf_mesh fluidsurf_mesh;

/* The surface of particles p as a triangle mesh, without rendering (as
 * `fluidsurf mesh` makes it): the mesh method's marching cubes of the scene's
 * field (methods/mesh/README.md). params: nparams "param=value" settings of the
 * method "mesh" (cube, smooth, smooth_iters, field, ...), applied after the
 * scene's. r as fluidsurf_render settles it. FLUIDSURF_ERR_INPUT in a library
 * built without OpenVDB (FS_WITH_OPENVDB=OFF, the lean build). */
int fluidsurf_mesh_build(const fluidsurf_scene *s, const fluidsurf_particles *p, const char *const *params, int nparams,
                         fluidsurf_mesh **out);
size_t fluidsurf_mesh_vertex_count(const fluidsurf_mesh *m);
size_t fluidsurf_mesh_triangle_count(const fluidsurf_mesh *m);
/* 3 floats per vertex, scene units. */
const float *fluidsurf_mesh_vertices(const fluidsurf_mesh *m);
/* 3 floats per vertex: the unit outward normal -grad phi / |grad phi| (with
 * smooth=weighted splashsurf's smoothed face normals); where that has no length,
 * its faces' or its largest face's normal (methods/mesh/README.md, step 5). */
const float *fluidsurf_mesh_normals(const fluidsurf_mesh *m);
/* 3 vertex indices per triangle, counter-clockwise seen from outside. */
const uint32_t *fluidsurf_mesh_triangles(const fluidsurf_mesh *m);
/* The radius r it was built with. */
double fluidsurf_mesh_radius(const fluidsurf_mesh *m);
void fluidsurf_mesh_free(fluidsurf_mesh *m);
/* Since version 6: a mesh of the caller's arrays (copied): nv vertices (3 floats
 * each), their unit normals (NULL: the area-weighted mean of the adjacent
 * triangles' normals), nt triangles (3 vertex indices each). */
int fluidsurf_mesh_from_arrays(size_t nv, const float *vertices, const float *normals, size_t nt,
                               const uint32_t *triangles, fluidsurf_mesh **out);
/* Since version 6: provenance, "fluidsurf:NAME" entries (a built mesh's: version,
 * commit, r, field, method, params, ...), as an image's. */
int fluidsurf_mesh_set_provenance(fluidsurf_mesh *m, const char *name, const char *value);
int fluidsurf_mesh_provenance_count(const fluidsurf_mesh *m);
const char *fluidsurf_mesh_provenance_name(const fluidsurf_mesh *m, int i);
const char *fluidsurf_mesh_provenance_value(const fluidsurf_mesh *m, int i);
/* Since version 6: the mesh as `fluidsurf mesh` writes it, by the extension: .ply,
 * .obj, .vtk or .vtp (.vtk and .vtp need FS_WITH_VTK), with its provenance in the
 * header (PLY comments, OBJ comments, VTK field data). */
int fluidsurf_mesh_write(const fluidsurf_mesh *m, const char *path);
/* ---- studies (since version 4) ---------------------------------------- */
typedef struct fluidsurf_study fluidsurf_study;
enum { FLUIDSURF_STUDY_COUNTERS = 1 };

/* Every method variant against every reference on every frame, through the
 * engine of `fluidsurf compare` (common/study): the same metrics (in the scene,
 * solids left out), the same timing protocol (one upload, a warm-up, `repeat`
 * timed renders, their median; 0: 3), the same tables.
 * frames: nframes particle sets (a sequence, framed and r settled on the
 * first), or NULL for the scene's own particle source (a scene file's frames).
 * methods: a comma list, NULL for every registered method but the reference
 * (the ground truth is a method of the study only when named). sets: nsets
 * "method.param=value" settings; a comma list of values sweeps the parameter
 * ("spheres.radius_scale=0.8,1.2"), as --set. references: nreferences of
 * "reference", "reference:param=value,...", "analytic" (0: "reference").
 * flags: FLUIDSURF_STUDY_COUNTERS adds a counting render per item. Writes no
 * file. */
int fluidsurf_compare(const fluidsurf_scene *s, const fluidsurf_particles *const *frames, int nframes,
                      const char *methods, const char *const *sets, int nsets, const char *const *references,
                      int nreferences, int repeat, int flags, fluidsurf_study **out);
/* A table as the CSV text compare writes into NAME.csv: "metrics", "timings",
 * "temporal" (a sequence) or "counters" (with FLUIDSURF_STUDY_COUNTERS); its
 * first line is the provenance ("# fluidsurf:..."). NULL when the study has no
 * such table. Owned by the study. */
const char *fluidsurf_study_table(const fluidsurf_study *st, const char *name);
void fluidsurf_study_free(fluidsurf_study *st);
/* ---- study folders (since version 5) ---------------------------------- */
enum { FLUIDSURF_STUDY_FORCE = 2, FLUIDSURF_STUDY_RESUME = 4 };
/* fluidsurf_compare, with the study's folder written into dir (made if
 * missing) as `fluidsurf compare -o DIR --no-cache` writes it: each view's PNG
 * and EXR, the heatmaps, panel.png, the tables, report.md and report.html,
 * listed in dir/fluidsurf-outputs.txt; the same files byte for byte but for the
 * times and the command line report.md records. flags as fluidsurf_compare's,
 * and FLUIDSURF_STUDY_FORCE (an earlier run's files in dir are removed first;
 * without it such a dir is refused) or FLUIDSURF_STUDY_RESUME (the items an
 * earlier run of the same study finished there are loaded, not rendered).
 * On an error dir holds no half-written file. */
int fluidsurf_compare_to_dir(const fluidsurf_scene *s, const fluidsurf_particles *const *frames, int nframes,
                             const char *methods, const char *const *sets, int nsets, const char *const *references,
                             int nreferences, int repeat, int flags, const char *dir, fluidsurf_study **out);
/* cffi:end */

#pragma GCC visibility pop
#ifdef __cplusplus
}
#endif
#endif
