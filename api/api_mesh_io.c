/* Meshes of the library as files: a mesh of the caller's arrays, its provenance,
 * and the writer `fluidsurf mesh` writes with (methods/mesh/mesh_export.h). Without
 * OpenVDB (the lean build) the mesh method is not built: these refuse in one line. */
#include "api_internal.h"
#include "fs_error.h"
#if FS_WITH_OPENVDB
#include "mesh/mesh_export.h"
#include "mesh/mesh_normals.h"
#endif

#include <math.h>
#include <stdlib.h>
#include <string.h>

#if !FS_WITH_OPENVDB
static int no_openvdb(void)
{
    return fs_fail(FS_ERR_INPUT, "mesh: needs a library built with FS_WITH_OPENVDB=ON (the mesh method's files)");
}
#endif

/* Finite vertices, triangles that name them: else FS_ERR_INPUT naming the first bad one. */
static int check_arrays(size_t nv, const float *v, const float *n, size_t nt, const uint32_t *t)
{
    for (size_t i = 0; i < 3 * nv; i++)
        if (!isfinite(v[i]) || (n && !isfinite(n[i])))
            return fs_fail(FS_ERR_INPUT, "mesh: vertex %zu: %s not finite", i / 3,
                           isfinite(v[i]) ? "normal" : "position");
    for (size_t i = 0; i < 3 * nt; i++)
        if (t[i] >= nv)
            return fs_fail(FS_ERR_INPUT, "mesh: triangle %zu names vertex %u of %zu", i / 3, (unsigned)t[i], nv);
    return FLUIDSURF_OK;
}

#if FS_WITH_OPENVDB
/* A copy of the arrays into mesh; normals NULL: area-weighted from the triangles. */
static int copy_arrays(size_t nv, const float *v, const float *n, size_t nt, const uint32_t *t, fs_trimesh *m)
{
    m->nv = nv, m->nt = nt; /* one more of each: malloc(0) may be NULL */
    m->pos = malloc((3 * nv + 1) * sizeof *m->pos), m->tri = malloc((3 * nt + 1) * sizeof *m->tri);
    if (n) m->nrm = malloc((3 * nv + 1) * sizeof *m->nrm);
    if (!m->pos || !m->tri || (n && !m->nrm)) return fs_fail(FS_ERR_RUNTIME, "out of memory for a mesh");
    memcpy(m->pos, v, 3 * nv * sizeof *v), memcpy(m->tri, t, 3 * nt * sizeof *t);
    if (n) memcpy(m->nrm, n, 3 * nv * sizeof *n);
    return n ? FLUIDSURF_OK : fs_mesh_normals_smoothed(m, 0);
}
#endif

int fluidsurf_mesh_from_arrays(size_t nv, const float *vertices, const float *normals, size_t nt,
                               const uint32_t *triangles, fluidsurf_mesh **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out"))) return rc;
    *out = NULL;
    if ((rc = fs_api_check(vertices, "vertices")) || (nt && (rc = fs_api_check(triangles, "triangles")))) return rc;
    if (nv > UINT32_MAX || nt > SIZE_MAX / 12)
        return fs_fail(FS_ERR_INPUT, "mesh: %zu vertices, %zu triangles: too many", nv, nt);
    if ((rc = check_arrays(nv, vertices, normals, nt, triangles))) return rc;
#if !FS_WITH_OPENVDB
    return no_openvdb();
#else
    fluidsurf_mesh *m = calloc(1, sizeof *m);
    rc = m ? copy_arrays(nv, vertices, normals, nt, triangles, &m->m) : fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (rc) {
        fluidsurf_mesh_free(m);
        return rc;
    }
    *out = m;
    return FLUIDSURF_OK;
#endif
}

int fluidsurf_mesh_set_provenance(fluidsurf_mesh *m, const char *name, const char *value)
{
    int rc = fs_api_check(m, "mesh");
    return rc ? rc : fs_api_set_provenance(&m->prov, name, value);
}

static int prov_ok(const fluidsurf_mesh *m, int i) { return m && i >= 0 && i < m->prov.n; }
int fluidsurf_mesh_provenance_count(const fluidsurf_mesh *m) { return m ? m->prov.n : 0; }
const char *fluidsurf_mesh_provenance_name(const fluidsurf_mesh *m, int i)
{
    return prov_ok(m, i) ? m->prov.name[i] : NULL;
}
const char *fluidsurf_mesh_provenance_value(const fluidsurf_mesh *m, int i)
{
    return prov_ok(m, i) ? m->prov.value[i] : NULL;
}

int fluidsurf_mesh_write(const fluidsurf_mesh *m, const char *path)
{
    int rc;
    if ((rc = fs_api_check(m, "mesh")) || (rc = fs_api_check(path, "path"))) return rc;
#if !FS_WITH_OPENVDB
    return no_openvdb();
#else
    return fs_mesh_export(&m->m, path, &m->prov);
#endif
}
