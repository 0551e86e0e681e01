/* Particle file dispatcher: picks the reader/writer from the extension or a
 * forced format name, and applies the checks every format shares. */
#include "particle_io.h"
#include "output_file.h"
#include "fs_error.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

const char *fs_format_from_path(const char *path)
{
    static const struct {
        const char *ext, *format;
    } table[] = {
        {".bgeo.gz", "bgeo"}, {".bgeo", "bgeo"}, {".vtk", "vtk"}, {".vtu", "vtu"}, {".ply", "ply"},
        {".vdb", "vdb"},      {".raw", "raw"},   {".xyz", "raw"}, {".csv", "csv"},
    };
    if (!path) return NULL;
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        if (fs_path_ends_with(path, table[i].ext)) return table[i].format;
    return NULL;
}

/* Resolves the format for path: forced name wins, else the extension. */
static int pick_format(const char *path, const char *format, const char **out)
{
    if (format && *format) {
        *out = format;
        return FS_OK;
    }
    *out = fs_format_from_path(path);
    if (!*out)
        return fs_fail(FS_ERR_INPUT,
                       "%s: unknown particle file extension (known: .vtk .vtu .bgeo .bgeo.gz .ply "
                       ".vdb .raw .xyz .csv)",
                       path);
    return FS_OK;
}

/* Common checks before any reader runs, so VTK/OpenVDB never see a missing or empty file. */
static int check_input_file(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) return fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, strerror(errno));
    if (S_ISDIR(st.st_mode)) return fs_fail(FS_ERR_INPUT, "%s: is a directory, not a particle file", path);
    if (!S_ISREG(st.st_mode)) return fs_fail(FS_ERR_INPUT, "%s: not a regular file", path);
    if (st.st_size == 0) return fs_fail(FS_ERR_INPUT, "%s: empty file", path);
    FILE *f = fopen(path, "rb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, strerror(errno));
    fclose(f);
    return FS_OK;
}

/* Every read error names the file: a layer below (fs_particles_alloc) may not know it. */
static int name_file(int rc, const char *path)
{
    const char *msg = fs_error_message();
    size_t n = strlen(path);
    if (strncmp(msg, path, n) == 0 && msg[n] == ':') return rc;
    char copy[1024];
    snprintf(copy, sizeof copy, "%s", msg);
    return fs_fail(rc, "%s: %s", path, copy);
}

int fs_particles_read(fs_particles *p, const char *path, const char *format)
{
    memset(p, 0, sizeof *p);
    const char *fmt;
    struct stat st; /* a directory first: its name says nothing of a format */
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) return check_input_file(path);
    int rc = pick_format(path, format, &fmt);
    if (rc) return rc;
    static const struct {
        const char *name;
        int (*read)(fs_particles *, const char *);
    } readers[] = {
        {"vtk", fs_read_vtk}, {"vtu", fs_read_vtu}, {"bgeo", fs_read_bgeo}, {"ply", fs_read_ply},
        {"vdb", fs_read_vdb}, {"raw", fs_read_raw}, {"csv", fs_read_csv},
    };
    int (*read)(fs_particles *, const char *) = NULL;
    for (size_t i = 0; i < sizeof readers / sizeof readers[0]; i++)
        if (strcasecmp(fmt, readers[i].name) == 0) read = readers[i].read;
    if (!read)
        return fs_fail(FS_ERR_INPUT, "%s: unknown particle format '%s' (known: vtk vtu bgeo ply vdb raw csv)", path,
                       fmt);
    rc = check_input_file(path);
    if (!rc) rc = read(p, path);
    if (!rc) rc = fs_particles_validate(p, path);
    if (rc) {
        fs_particles_free(p);
        return name_file(rc, path);
    }
    fs_particles_bounds(p);
    return FS_OK;
}

int fs_particles_write(const fs_particles *p, const char *path, const char *format)
{
    const char *fmt;
    int rc = pick_format(path, format, &fmt);
    if (rc) return rc;
    static const struct {
        const char *name;
        int (*write)(const fs_particles *, const char *);
    } writers[] = {
        {"vtk", fs_write_vtk},
        {"bgeo", fs_write_bgeo},
        {"ply", fs_write_ply},
        {"vdb", fs_write_vdb},
    };
    for (size_t i = 0; i < sizeof writers / sizeof writers[0]; i++) {
        if (strcasecmp(fmt, writers[i].name) != 0) continue;
        /* Never write a file our own readers would reject. */
        rc = fs_particles_validate(p, path);
        return rc ? rc : writers[i].write(p, path);
    }
    return fs_fail(FS_ERR_INPUT, "%s: cannot write format '%s' (writers: vtk bgeo ply vdb)", path, fmt);
}

int fs_particles_writable(const char *path, const char *format)
{
    const char *fmt;
    int rc = pick_format(path, format, &fmt);
    if (rc) return rc;
    /* The stub (io_vdb_none.c) refuses without looking at the particles. */
    if (!FS_WITH_OPENVDB && strcasecmp(fmt, "vdb") == 0) return fs_write_vdb(NULL, path);
    return FS_OK;
}
