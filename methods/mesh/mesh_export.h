/* Mesh files: binary little-endian PLY and Wavefront OBJ (mesh_export.c), VTK
 * legacy .vtk and XML .vtp through VTK's writers (mesh_vtk.cpp, only with
 * FS_WITH_VTK). Every writer writes a temporary file and renames it over the
 * target only when all of it was written (output_file.h). */
#ifndef FS_MESH_EXPORT_H
#define FS_MESH_EXPORT_H
#include "provenance.h"
#include "trimesh.h"
#ifdef __cplusplus
extern "C" {
#endif

/* The extensions fs_mesh_export writes, for messages. */
#define FS_MESH_EXPORTS ".ply, .obj, .vtk, .vtp"
/* 1 when path's extension is one of them. */
int fs_mesh_export_known(const char *path);
/* Writes m (positions, normals, triangles; velocity and colour when m has them,
 * except to .obj) to path by its extension, with the provenance prov (may be
 * NULL) as EXRs carry it: PLY comments and OBJ comment lines
 * "fluidsurf:NAME=VALUE", VTK field data (one string array per entry, named
 * fluidsurf:NAME). FS_ERR_INPUT for an unknown extension or a folder that
 * cannot be written. */
int fs_mesh_export(const fs_trimesh *m, const char *path, const fs_provenance *prov);
/* .vtk (xml 0) or .vtp (xml 1) through VTK, to the temporary path tmp
 * (messages name path). */
int fs_mesh_write_vtk(const fs_trimesh *m, const char *path, const char *tmp, int xml, const fs_provenance *prov);

#ifdef __cplusplus
}
#endif
#endif
