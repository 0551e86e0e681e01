/* The scene's part of every output's provenance (scene_provenance.h). */
#include "scene_provenance.h"
#include "camera_text.h"
#include <stdio.h>

void fs_provenance_init(fs_provenance *p, const fs_scene *s, const char *renderer, const char *gl_version)
{
    char v[640];
    fs_provenance_init_base(p, renderer, gl_version);
    snprintf(v, sizeof v, "%016llx", s->hash);
    if (s->hash) fs_provenance_set(p, "scene_hash", v); /* 0: the library's scene, no file or flags to hash */
    fs_provenance_set(p, "scene", s->path[0] ? s->path : "(command line)");
    fs_provenance_set(p, "source", s->synth.shape ? "synthetic" : s->source);
    snprintf(v, sizeof v, "%u", s->synth.seed);
    fs_provenance_set(p, "seed", v);
    snprintf(v, sizeof v, "%.9g", s->radius);
    fs_provenance_set(p, "r", v);
    fs_provenance_set(p, "r_source", fs_radius_source_name(s->r_source));
    snprintf(v, sizeof v, "%c;%s", 'x' + s->up_axis, fs_up_source_name(s->up_source));
    fs_provenance_set(p, "up", v);
    snprintf(v, sizeof v, "kernel=%s;support=%.9gr;iso=%.9g;volume_scale=%.9g", fs_kernel_name(s->kernel), s->support_r,
             s->iso, s->volume_scale);
    fs_provenance_set(p, "field", v);
    fs_camera_format(&s->camera, v, sizeof v);
    fs_provenance_set(p, "camera", v);
}
