/* fluidsurf_mesh_build: the mesh method's surface of one particle set as a
 * triangle mesh the caller reads, without rendering, as `fluidsurf mesh` builds
 * it (cli/commands/cmd_mesh.c): the scene's field sampled near the particles and meshed
 * by OpenVDB's volumeToMesh (methods/mesh/mesh_build.h). Without OpenVDB (the
 * lean build) the method does not exist and the function refuses in one line. */
#include "api_internal.h"
#include "fs_error.h"
#if FS_WITH_OPENVDB
#include "mesh/mesh.h"
#endif

#include <stdlib.h>

#if FS_WITH_OPENVDB
/* Grid and mesh of p on the scene's field, one build at a time (fs_api_lock), and its provenance. */
static int build(const fs_scene *sc, const fs_particles *p, const double *values, fluidsurf_mesh *out)
{
    fs_field f = fs_scene_field(sc);
    fs_mesh_opts opts;
    fs_grid g = {0};
    int rc = fs_mesh_opts_from_values(values, &f, &opts);
    if (rc) return rc;
    fs_api_lock(1);
    rc = fs_grid_build(&g, p, f.H);
    if (!rc) rc = fs_mesh_build(p, &g, &f, &opts, &out->m, NULL);
    fs_api_lock(0);
    fs_grid_free(&g);
    out->radius = f.r;
    fs_mesh_provenance(&out->prov, sc, values, 0);
    return rc;
}
#endif

int fluidsurf_mesh_build(const fluidsurf_scene *s, const fluidsurf_particles *fp, const char *const *params,
                         int nparams, fluidsurf_mesh **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out"))) return rc;
    *out = NULL;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(fp, "particles"))) return rc;
    fs_api_init();
#if !FS_WITH_OPENVDB
    (void)params, (void)nparams;
    return fs_fail(FS_ERR_INPUT,
                   "mesh: needs a library built with FS_WITH_OPENVDB=ON (its marching cubes are OpenVDB's)");
#else
    const fs_method *m = fs_method_find("mesh");
    if (!m) return fs_fail(FS_ERR_RUNTIME, "mesh: the method is not registered");
    fs_scene *sc = malloc(sizeof *sc);
    fluidsurf_mesh *mesh = calloc(1, sizeof *mesh);
    fs_particles p;
    double values[FS_MAX_PARAMS];
    rc = sc && mesh ? FLUIDSURF_OK : fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!rc) rc = fs_api_prepare(s, fp, m, params, nparams, sc, &p, values);
    if (!rc) rc = build(sc, &p, values, mesh);
    free(sc);
    if (rc) {
        fluidsurf_mesh_free(mesh);
        return rc;
    }
    *out = mesh;
    return FLUIDSURF_OK;
#endif
}

size_t fluidsurf_mesh_vertex_count(const fluidsurf_mesh *m) { return m ? m->m.nv : 0; }
size_t fluidsurf_mesh_triangle_count(const fluidsurf_mesh *m) { return m ? m->m.nt : 0; }
const float *fluidsurf_mesh_vertices(const fluidsurf_mesh *m) { return m ? m->m.pos : NULL; }
const float *fluidsurf_mesh_normals(const fluidsurf_mesh *m) { return m ? m->m.nrm : NULL; }
const uint32_t *fluidsurf_mesh_triangles(const fluidsurf_mesh *m) { return m ? m->m.tri : NULL; }
double fluidsurf_mesh_radius(const fluidsurf_mesh *m) { return m ? m->radius : 0; }

void fluidsurf_mesh_free(fluidsurf_mesh *m)
{
#if FS_WITH_OPENVDB
    if (m) fs_trimesh_free(&m->m);
#endif
    free(m);
}
