/* Particle readers and writers. The format comes from the extension unless
 * forced: vtk, vtu, bgeo, ply, vdb, raw (float32 xyz, little endian), csv.
 * Every failure returns FS_ERR_INPUT (bad file) or FS_ERR_RUNTIME with a
 * one-line message "path: what is wrong"; p is left empty. */
#ifndef FS_PARTICLE_IO_H
#define FS_PARTICLE_IO_H
#include "frame_pattern.h"
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

/* "" or NULL format: from the extension (".bgeo.gz" counts as bgeo). */
int fs_particles_read(fs_particles *p, const char *path, const char *format);
/* Writers: vtk (legacy binary), bgeo, ply (binary), vdb. Writes to a temporary
 * file in the same folder and renames it, never leaving a partial file. */
int fs_particles_write(const fs_particles *p, const char *path, const char *format);
/* FS_OK when this build can write path's format (a build without VTK or OpenVDB
 * refuses .vtk or .vdb, as the writer would): lets a command refuse before it works. */
int fs_particles_writable(const char *path, const char *format);
const char *fs_format_from_path(const char *path);

/* Per-format entry points (one file each; the C++ ones are thin adapters). */
int fs_read_vtk(fs_particles *p, const char *path); /* legacy .vtk, our own (io_vtk_legacy.c) */
int fs_read_vtu(fs_particles *p, const char *path); /* XML .vtu, through VTK */
int fs_read_bgeo(fs_particles *p, const char *path);
int fs_read_ply(fs_particles *p, const char *path);
int fs_read_vdb(fs_particles *p, const char *path); /* OpenVDB point grids */
int fs_read_raw(fs_particles *p, const char *path);
int fs_read_csv(fs_particles *p, const char *path);
int fs_write_vtk(const fs_particles *p, const char *path);
int fs_write_bgeo(const fs_particles *p, const char *path);
int fs_write_ply(const fs_particles *p, const char *path);
int fs_write_vdb(const fs_particles *p, const char *path);

#ifdef __cplusplus
}
#endif
#endif
