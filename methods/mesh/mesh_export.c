/* PLY and OBJ writers and the export dispatch (mesh_export.h). */
#include "mesh_export.h"
#include "fs_error.h"
#include "output_file.h"
#include "provenance.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>

int fs_mesh_export_known(const char *path)
{
    return fs_path_ends_with(path, ".ply") || fs_path_ends_with(path, ".obj") || fs_path_ends_with(path, ".vtk") ||
        fs_path_ends_with(path, ".vtp");
}

/* Each provenance entry as one line "PREFIXfluidsurf:NAME=VALUE"; a line break
 * in a value becomes a space, so every entry stays one line. */
static int write_provenance(FILE *f, const char *prefix, const fs_provenance *prov)
{
    for (int i = 0; prov && i < prov->n; i++) {
        char v[sizeof prov->value[0]];
        snprintf(v, sizeof v, "%s", prov->value[i]);
        for (char *c = v; *c; c++)
            if (*c == '\n' || *c == '\r') *c = ' ';
        if (fprintf(f, "%s%s=%s\n", prefix, prov->name[i], v) < 0) return -1;
    }
    return 0;
}

/* Binary little-endian PLY: vertex x y z nx ny nz (float), then vx vy vz and
 * red green blue (float, linear, as fluidsurf's particle PLYs) when the mesh
 * has them, face uchar count + uint indices, as MeshLab, Blender and ParaView
 * read it. */
static int write_ply(FILE *f, const fs_trimesh *m, const fs_provenance *prov)
{
    fprintf(f, "ply\nformat binary_little_endian 1.0\ncomment fluidsurf mesh %s\n", fs_version);
    if (write_provenance(f, "comment ", prov)) return -1;
    fprintf(f, "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n", m->nv);
    fprintf(f, "property float nx\nproperty float ny\nproperty float nz\n");
    if (m->vel) fprintf(f, "property float vx\nproperty float vy\nproperty float vz\n");
    if (m->col) fprintf(f, "property float red\nproperty float green\nproperty float blue\n");
    fprintf(f, "element face %zu\nproperty list uchar uint vertex_indices\nend_header\n", m->nt);
    for (size_t v = 0; v < m->nv; v++) {
        float rec[12];
        size_t k = 6;
        memcpy(rec, m->pos + 3 * v, 3 * sizeof *rec);
        memcpy(rec + 3, m->nrm + 3 * v, 3 * sizeof *rec);
        if (m->vel) memcpy(rec + k, m->vel + 3 * v, 3 * sizeof *rec), k += 3;
        if (m->col) memcpy(rec + k, m->col + 3 * v, 3 * sizeof *rec), k += 3;
        if (fwrite(rec, sizeof *rec, k, f) != k) return -1;
    }
    for (size_t t = 0; t < m->nt; t++) {
        unsigned char rec[13];
        rec[0] = 3;
        memcpy(rec + 1, m->tri + 3 * t, 12);
        if (fwrite(rec, sizeof rec, 1, f) != 1) return -1;
    }
    return 0;
}

/* OBJ: v, vn with the same index, f v//vn (1-based); no vertex attributes (OBJ has none). */
static int write_obj(FILE *f, const fs_trimesh *m, const fs_provenance *prov)
{
    fprintf(f, "# fluidsurf mesh %s\n", fs_version);
    if (write_provenance(f, "# ", prov)) return -1;
    for (size_t v = 0; v < m->nv; v++) {
        const float *p = m->pos + 3 * v;
        if (fprintf(f, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]) < 0) return -1;
    }
    for (size_t v = 0; v < m->nv; v++) {
        const float *n = m->nrm + 3 * v;
        if (fprintf(f, "vn %.6g %.6g %.6g\n", n[0], n[1], n[2]) < 0) return -1;
    }
    for (size_t t = 0; t < m->nt; t++) {
        const uint32_t *c = m->tri + 3 * t;
        if (fprintf(f, "f %u//%u %u//%u %u//%u\n", c[0] + 1, c[0] + 1, c[1] + 1, c[1] + 1, c[2] + 1, c[2] + 1) < 0)
            return -1;
    }
    return 0;
}

/* Writes through stdio into tmp; every write, the flush and the close checked. */
static int write_stdio(const fs_trimesh *m, const char *path, const char *tmp, int ply, const fs_provenance *prov)
{
    FILE *f = fopen(tmp, "wb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot write: %s", path, strerror(errno));
    int bad = ply ? write_ply(f, m, prov) : write_obj(f, m, prov);
    bad |= fflush(f) != 0;
    bad |= ferror(f) != 0;
    bad |= fclose(f) != 0;
    return bad ? fs_fail(FS_ERR_RUNTIME, "%s: write failed: %s", path, strerror(errno ? errno : EIO)) : FS_OK;
}

int fs_mesh_export(const fs_trimesh *m, const char *path, const fs_provenance *prov)
{
    if (!fs_mesh_export_known(path))
        return fs_fail(FS_ERR_INPUT, "%s: unknown mesh format (the mesh exports %s)", path, FS_MESH_EXPORTS);
    if (!m->nrm) return fs_fail(FS_ERR_RUNTIME, "%s: the mesh has no normals", path);
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    if (fs_path_ends_with(path, ".vtk") || fs_path_ends_with(path, ".vtp"))
        rc = fs_mesh_write_vtk(m, path, tmp, fs_path_ends_with(path, ".vtp"), prov);
    else rc = write_stdio(m, path, tmp, fs_path_ends_with(path, ".ply"), prov);
    int rc2 = fs_output_end(path, tmp, rc == FS_OK);
    return rc ? rc : rc2;
}
